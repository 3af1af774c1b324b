//! Physical and numerical constants of the reference model (SPEC sections 1-3), in SI
//! units. Every number the simulator uses lives here, named, with its unit.

/// Time step (s).
pub const DT: f64 = 1.0 / 60.0;
/// Gravity along y (m/s^2).
pub const GRAVITY: f64 = -9.8;
/// Linear and angular damping (1/s): v *= 1 - DT * DAMPING every step.
pub const DAMPING: f64 = 0.1;

/// Side of a voxel at rest (m).
pub const VOXEL_SIDE: f64 = 3.0;
/// Rest area of a voxel (m^2).
pub(crate) const VOXEL_AREA: f64 = VOXEL_SIDE * VOXEL_SIDE;
/// Side of a rigid corner square (m): side ratio 0.4.
pub const CORNER_SIDE: f64 = 1.2;
/// Distance from a voxel centre to a corner square centre along each axis (m).
pub(crate) const CORNER_OFFSET: f64 = (VOXEL_SIDE - CORNER_SIDE) / 2.0;
/// Mass of one corner square (kg); a voxel weighs four of them.
pub const CORNER_MASS: f64 = 0.36;
/// Moment of inertia of one corner square about its centre (kg m^2): m (w^2 + h^2) / 12.
pub const CORNER_INERTIA: f64 = CORNER_MASS * (2.0 * CORNER_SIDE * CORNER_SIDE) / 12.0;

/// Spring frequency of every soft distance joint (Hz).
pub(crate) const SPRING_FREQUENCY: f64 = 8.0;
/// Spring damping ratio of every soft distance joint.
pub(crate) const SPRING_DAMPING_RATIO: f64 = 0.3;
/// Largest relative change of a voxel's area under actuation: 0.775 ..= 1.225.
pub(crate) const AREA_RATIO_MAX_DELTA: f64 = 0.225;
/// Smallest distance between the centres of adjacent corner squares of a voxel (m).
pub(crate) const ROPE_MIN_LENGTH: f64 = CORNER_SIDE;

/// Coulomb friction between a corner square and the ground: sqrt(0.2 * 10).
pub(crate) const FRICTION: f64 = std::f64::consts::SQRT_2;
/// Coulomb friction between corner squares of different voxels (self-collision):
/// corner-body friction 10, mixed as sqrt(10 * 10).
pub(crate) const SELF_FRICTION: f64 = 10.0;
/// Restitution between a corner square and the ground, and between two corner
/// squares (the larger of the two bodies' 0.1).
pub(crate) const RESTITUTION: f64 = 0.1;
/// Approach speed (m/s) below which restitution is ignored (dyn4j default).
pub(crate) const RESTITUTION_VELOCITY: f64 = 1.0;

/// Sequential-impulse velocity iterations per step.
pub(crate) const VELOCITY_ITERATIONS: usize = 10;
/// Largest number of position-correction iterations per step.
pub(crate) const POSITION_ITERATIONS: usize = 10;
/// Penetration allowed without correction (m) (dyn4j linear tolerance).
pub const LINEAR_SLOP: f64 = 0.005;
/// Contacts are kept while a corner is closer to the ground than this (m), as
/// speculative contacts that may close the gap in one step but not bounce off it;
/// without the margin a loaded corner chatters on and off the ground.
pub(crate) const CONTACT_MARGIN: f64 = 2.0 * LINEAR_SLOP;
/// In the step after an actuation change, squares of different voxels are
/// (speculative) contacts up to this much farther apart (m): the springs' new rest
/// lengths can close a gap of up to 20 cm within that step beyond what the speeds
/// before it predict (measured: without it comb-7x2's feet sink up to 20 cm into each
/// other in that step).
pub(crate) const ACTUATION_KICK_MARGIN: f64 = 0.2;
/// Fraction of the penetration corrected per position iteration.
pub(crate) const BAUMGARTE: f64 = 0.2;
/// Largest position correction per iteration (m).
pub(crate) const MAX_LINEAR_CORRECTION: f64 = 0.2;
/// Largest translation of a body in one step (m), a guard against explosions.
pub(crate) const MAX_TRANSLATION: f64 = 2.0;
/// Largest rotation of a body in one step (rad).
pub(crate) const MAX_ROTATION: f64 = 0.5 * std::f64::consts::PI;

/// Horizontal position of the robot's left edge at placement (m).
pub const PLACEMENT_LEFT_X: f64 = 11.0;
/// Gap between the lowest voxel bottom and the ground under it at placement (m).
pub(crate) const PLACEMENT_GAP: f64 = 1.0;

/// Steps an actuation value is held before the controller is asked again.
pub const ACTUATION_HOLD_STEPS: usize = 20;
