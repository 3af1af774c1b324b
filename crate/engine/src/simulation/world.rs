//! The world: one robot on one terrain, advanced by [`World::step`].
//!
//! # Solver
//! Sequential impulses with soft constraints, like the reference (dyn4j, Box2D-style):
//! the 8 Hz / 0.3 springs are soft distance joints, i.e. implicit-Euler spring-dampers
//! solved inside the velocity iterations. We keep this scheme rather than XPBD or
//! explicit springs because at dt = 1/60 the springs' stiffness (omega dt ~ 0.84 for
//! one spring, higher for the voxel's collective modes) makes the integrator's own
//! damping part of the reference's behaviour: the same scheme reproduces the same
//! response (area ratios settle in a few steps with little ringing), where an
//! explicit or substepped integrator would ring at the true 8 Hz. Welded squares are
//! merged into rigid pieces (exact for rigid welds, and fewer bodies and rows).
//!
//! One step is a list of phases: find the self-contacts (corner squares of different
//! voxels that are not welded together), gravity and damping, prepare and warm start
//! every row, 10 velocity iterations (springs, ropes, ground contacts,
//! self-contacts), integrate positions, up to 10 position iterations (ground contacts,
//! ropes, self-contacts), detect the ground contacts of the new pose.

use super::assembly::{assemble, Assembly};
use super::body::{Pieces, Squares};
use super::broad_phase::BroadPhase;
use super::collide::{detect, Contact};
use super::constants::{
    ACTUATION_KICK_MARGIN, CONTACT_MARGIN, DAMPING, DT, GRAVITY, LINEAR_SLOP, MAX_ROTATION,
    MAX_TRANSLATION, POSITION_ITERATIONS, VELOCITY_ITERATIONS,
};
use super::contact::ContactSolver;
use super::ground::Ground;
use super::ropes::Ropes;
use super::self_collide::{detect_self, PairContact};
use super::self_contact::SelfContactSolver;
use super::springs::Springs;

/// A robot on a terrain.
#[derive(Debug, Clone)]
pub struct World {
    pub(crate) pieces: Pieces,
    pub(crate) squares: Squares,
    pub(super) springs: Springs,
    ropes: Ropes,
    pub(super) ground: Ground,
    contacts: Vec<Contact>,
    solver: ContactSolver,
    broad: BroadPhase,
    self_contacts: Vec<PairContact>,
    self_solver: SelfContactSolver,
    hints: Vec<usize>,
    touching: Vec<bool>,
    steps: u64,
    /// Whether the actuation was set since the last step.
    actuated: bool,
}

impl World {
    /// Builds and places a robot whose voxels sit at grid `cells` (in voxel index
    /// order, y up) on the polyline (xs, ys).
    pub fn new(cells: &[(usize, usize)], xs: &[f64], ys: &[f64]) -> World {
        World::with_start_offset(cells, xs, ys, 0.0)
    }

    /// As [`World::new`], with the robot's start shifted right by `offset` metres
    /// before it is lowered onto the ground (SPEC 12's ensembles shift by k x 1e-5 m).
    pub(crate) fn with_start_offset(
        cells: &[(usize, usize)],
        xs: &[f64],
        ys: &[f64],
        offset: f64,
    ) -> World {
        let ground = Ground::new(xs, ys);
        let Assembly {
            pieces,
            squares,
            springs,
            ropes,
        } = assemble(cells, &ground, offset);
        let hints = vec![ground.segments() / 2; squares.len()];
        let broad = BroadPhase::new(&squares, pieces.len());
        let springs = Springs::new(&springs, &pieces);
        let mut world = World {
            pieces,
            springs,
            ropes: Ropes::new(ropes),
            ground,
            contacts: Vec::new(),
            solver: ContactSolver::default(),
            broad,
            self_contacts: Vec::new(),
            self_solver: SelfContactSolver::default(),
            hints,
            touching: vec![false; cells.len()],
            squares,
            steps: 0,
            actuated: false,
        };
        world.detect_contacts();
        world
    }

    /// Sets the actuation of every voxel (u in [-1, 1], +1 contracts), held until the
    /// next call. Values outside the range are clipped; NaN counts as 0.
    pub fn set_actuation(&mut self, actuation: &[f64]) {
        self.springs.set_actuation(actuation);
        self.actuated = true;
    }

    /// Advances the world by one step of [`DT`] seconds. The phases are methods so that
    /// [`super::lockstep`] runs the same ones with the springs of several robots in lanes.
    pub fn step(&mut self) {
        self.begin_step();
        self.springs.prepare(&mut self.pieces);
        self.prepare_others();
        for _ in 0..VELOCITY_ITERATIONS {
            self.springs.solve_velocity(&mut self.pieces.vel);
            self.solve_others();
        }
        self.end_step();
    }

    /// Before the springs: self-contacts, gravity and damping.
    #[inline]
    pub(super) fn begin_step(&mut self) {
        self.detect_self_contacts();
        self.apply_gravity_and_damping();
    }

    /// After the springs' preparation: every other row's, with its warm start.
    #[inline]
    pub(super) fn prepare_others(&mut self) {
        self.ropes.prepare(&mut self.pieces);
        self.solver.prepare(&self.contacts, &mut self.pieces);
        self.self_solver
            .prepare(&self.self_contacts, &mut self.pieces);
    }

    /// After each spring sweep: one sweep over ropes, ground contacts and self-contacts.
    #[inline]
    pub(super) fn solve_others(&mut self) {
        self.ropes.solve_velocity(&mut self.pieces.vel);
        self.solver.solve_velocity(&mut self.pieces);
        self.self_solver.solve_velocity(&mut self.pieces);
    }

    /// After the velocity iterations: positions, their corrections, the new contacts.
    #[inline]
    pub(super) fn end_step(&mut self) {
        self.integrate_positions();
        for _ in 0..POSITION_ITERATIONS {
            let contacts_ok = ContactSolver::solve_position(&self.contacts, &mut self.pieces);
            let ropes_ok = self.ropes.solve_position(&mut self.pieces);
            // Self-contacts last: a rope's full correction must not leave squares of
            // different voxels pushed into each other.
            let self_ok = SelfContactSolver::solve_position(&self.self_contacts, &mut self.pieces);
            if contacts_ok && self_ok && ropes_ok {
                break;
            }
        }
        self.detect_contacts();
        self.steps += 1;
    }

    fn apply_gravity_and_damping(&mut self) {
        let keep = (1.0 - DT * DAMPING).clamp(0.0, 1.0);
        for v in &mut self.pieces.vel {
            v.vy += GRAVITY * DT;
            v.vx *= keep;
            v.vy *= keep;
            v.w *= keep;
        }
    }

    fn integrate_positions(&mut self) {
        let p = &mut self.pieces;
        for i in 0..p.len() {
            let v = &mut p.vel[i];
            let (mut dx, mut dy) = (v.vx * DT, v.vy * DT);
            let d2 = dx * dx + dy * dy;
            if d2 > MAX_TRANSLATION * MAX_TRANSLATION {
                let scale = MAX_TRANSLATION / d2.sqrt();
                (dx, dy) = (dx * scale, dy * scale);
                (v.vx, v.vy) = (dx / DT, dy / DT);
            }
            let da = (v.w * DT).clamp(-MAX_ROTATION, MAX_ROTATION);
            v.w = da / DT;
            p.x[i] += dx;
            p.y[i] += dy;
            let angle = p.angle[i] + da;
            p.set_angle(i, angle);
        }
    }

    pub(super) fn detect_contacts(&mut self) {
        detect(
            &self.pieces,
            &self.squares,
            &self.ground,
            &mut self.hints,
            &mut self.contacts,
        );
        self.touching.iter_mut().for_each(|t| *t = false);
        for c in self.contacts.iter().filter(|c| c.separation < LINEAR_SLOP) {
            self.touching[c.square / 4] = true;
        }
    }

    /// Finds the contacts between squares of different voxels for this step. Right
    /// after an actuation change the springs' new rest lengths can accelerate a limb
    /// within the step beyond what its speed predicts, so the speculative margin is
    /// widened for that step.
    fn detect_self_contacts(&mut self) {
        let margin = match self.actuated {
            true => CONTACT_MARGIN + ACTUATION_KICK_MARGIN,
            false => CONTACT_MARGIN,
        };
        self.actuated = false;
        detect_self(
            &self.pieces,
            &self.squares,
            &mut self.broad,
            margin,
            &mut self.self_contacts,
        );
    }

    /// Changes the robot-ground friction coefficient (default 1.414, SPEC 3); for
    /// experiments and tests.
    pub fn set_friction(&mut self, friction: f64) {
        self.solver.friction = friction;
    }

    /// Steps taken so far.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// Simulated time (s): steps x dt.
    pub(crate) fn time(&self) -> f64 {
        self.steps as f64 * DT
    }

    /// Number of voxels.
    pub fn voxel_count(&self) -> usize {
        self.touching.len()
    }

    /// Whether any corner square of voxel `v` touches the ground now (a contact closer
    /// than the slop: resting contacts sit within a hair of zero separation).
    pub(crate) fn touching(&self, v: usize) -> bool {
        self.touching[v]
    }

    /// The ground the robot walks on.
    pub fn ground(&self) -> &Ground {
        &self.ground
    }

    /// The rigid pieces (read-only).
    pub fn pieces(&self) -> &Pieces {
        &self.pieces
    }

    /// Number of contact points this step.
    pub fn contact_count(&self) -> usize {
        self.contacts.len()
    }

    /// Number of contact points between corner squares of different voxels this step.
    pub fn self_contact_count(&self) -> usize {
        self.self_contacts.len()
    }

    /// The contacts between corner squares of different voxels this step.
    pub fn self_contacts(&self) -> &[PairContact] {
        &self.self_contacts
    }

    /// Potential energy stored in the springs at the last step (J).
    pub fn spring_energy(&self) -> f64 {
        self.springs.potential_energy()
    }

    /// True if every piece's position and velocity is finite.
    pub fn is_finite(&self) -> bool {
        let p = &self.pieces;
        (0..p.len()).all(|i| {
            let v = p.vel[i];
            (p.x[i] + p.y[i] + p.angle[i] + v.vx + v.vy + v.w).is_finite()
        })
    }
}
