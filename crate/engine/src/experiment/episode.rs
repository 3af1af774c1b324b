//! A locomotion episode (SPEC 8): a robot on a terrain driven by a policy whose output
//! is latched every 20 steps (k_act = 20), with the reference's clock: at loop
//! iteration k (from 0) the world steps first, then the time is (k + 1) dt and the
//! policy is asked when k % 20 == 0; its output drives the following steps. Fitness is the centre's x displacement from after the first step to
//! after the last, over the elapsed time.

use super::gait::PhaseGait;
pub use super::policy::Policy;
use crate::controllers::Topology;
use crate::error::{Error, Result};
use crate::simulation::constants::{ACTUATION_HOLD_STEPS, DT};
use crate::simulation::sensors::Sensors;
use crate::simulation::{Shape, Terrain, World};
use std::sync::Arc;

/// The neighbour table of a shape, for controllers.
pub fn topology(shape: &Shape) -> Topology {
    let rows = (0..shape.voxel_count())
        .map(|i| shape.neighbours(i))
        .collect();
    Topology::new(rows).unwrap_or_else(|_| Topology::isolated(shape.voxel_count()))
}

/// Number of steps the reference loop takes for `seconds` of simulated time: it adds
/// dt to t in floating point while t < seconds (1801 steps for 30 s).
pub fn steps_for(seconds: f64) -> u64 {
    let (mut t, mut n) = (0.0, 0u64);
    while t < seconds {
        t += DT;
        n += 1;
    }
    n
}

/// The simulated time (s) of an episode asked to last `seconds`: [`steps_for`] x dt, as [`Outcome`] says.
pub fn simulated_seconds(seconds: f64) -> f64 {
    steps_for(seconds) as f64 * DT
}

/// The result of an episode.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Outcome {
    /// Fitness: x displacement of the centre after step 1 -> after the last step,
    /// divided by the time between them (m/s).
    pub velocity: f64,
    /// That displacement (m).
    pub distance: f64,
    /// Steps taken.
    pub steps: u64,
    /// Simulated seconds: steps x dt (see [`simulated_seconds`]).
    pub seconds: f64,
}

/// A robot on a terrain driven by a policy, stepped on demand.
#[derive(Debug)]
pub struct Episode {
    pub(super) world: World,
    terrain: Arc<Terrain>,
    policy: Policy,
    sensors: Sensors,
    columns: Vec<usize>,
    actuation: Vec<f64>,
    output: Vec<f32>,
    first_x: Option<f64>,
}

/// The page's first episode type: an [`Episode`] under a phase gait.
pub type GaitEpisode = Episode;

impl Episode {
    /// Builds the episode from a shape ("biped-4x3", "1111-1111-1001"), a terrain name
    /// and a gait u = sin(2 pi f t + phi x).
    pub fn new(shape: &str, terrain: &str, frequency: f64, phase: f64) -> Result<Episode> {
        let shape = Shape::parse(shape)?;
        let terrain = Terrain::parse(terrain)?;
        let gait = PhaseGait::new(frequency, phase)?;
        Ok(Episode::from_parts(&shape, terrain, gait))
    }

    /// Builds a phase-gait episode from parsed parts.
    pub fn from_parts(shape: &Shape, terrain: impl Into<Arc<Terrain>>, gait: PhaseGait) -> Episode {
        Episode::with_policy(shape, terrain, Policy::Gait(gait), None)
    }

    /// Builds an episode driven by `policy` on `terrain` (its own, or one shared read-only
    /// with other episodes); `noise_seed` seeds the sensor noise (None: noiseless sensors).
    pub fn with_policy(
        shape: &Shape,
        terrain: impl Into<Arc<Terrain>>,
        policy: Policy,
        noise_seed: Option<u64>,
    ) -> Episode {
        Episode::with_start_offset(shape, terrain, policy, noise_seed, 0.0)
    }

    /// As [`Episode::with_policy`], with the robot's start shifted right by `offset`
    /// metres before it is lowered onto the terrain.
    pub fn with_start_offset(
        shape: &Shape,
        terrain: impl Into<Arc<Terrain>>,
        mut policy: Policy,
        noise_seed: Option<u64>,
        offset: f64,
    ) -> Episode {
        let terrain = terrain.into();
        let world = World::with_start_offset(shape.voxels(), terrain.xs(), terrain.ys(), offset);
        let columns: Vec<usize> = shape.voxels().iter().map(|c| c.0).collect();
        if let Policy::Brain(c) = &mut policy {
            c.reset();
        }
        let n = columns.len();
        Episode {
            actuation: vec![0.0; n],
            output: vec![0.0; n],
            sensors: Sensors::new(n, noise_seed),
            world,
            terrain,
            policy,
            columns,
            first_x: None,
        }
    }

    /// Puts this freshly built episode's robot in the posture and motion of `old`'s robot;
    /// `map[v]` is the old index of voxel `v` (an edit of a walking robot, see
    /// [`crate::simulation::carry`]). The clock, the policy and the sensors start afresh.
    pub fn carry_pose_from(&mut self, old: &Episode, map: &[Option<usize>]) {
        self.world.carry_pose(&old.world, map);
    }

    /// Asks the policy after step k (1-based); its output is latched when `latch`.
    fn act(&mut self, k: u64, latch: bool) {
        match &mut self.policy {
            Policy::Gait(g) if latch => {
                g.actuate(k as f64 * DT, &self.columns, &mut self.actuation);
            }
            Policy::Gait(_) => return,
            // Read where a controller would be asked; the caller sets the actuation.
            Policy::External => {
                self.sensors.sense(&self.world);
                if latch {
                    self.sensors.read(&self.world);
                }
                return;
            }
            Policy::Brain(c) => {
                self.sensors.sense(&self.world);
                if !(latch || c.needs_every_step()) {
                    return;
                }
                c.control(self.sensors.read(&self.world), &mut self.output);
                if !latch {
                    return;
                }
                for (a, &o) in self.actuation.iter_mut().zip(&self.output) {
                    *a = f64::from(o);
                }
            }
        }
        self.world.set_actuation(&self.actuation);
    }

    /// Advances `steps` steps; an error if the simulation became non-finite.
    pub fn step(&mut self, steps: usize) -> Result<()> {
        for _ in 0..steps {
            self.world.step();
            self.after_step();
        }
        self.check()
    }

    /// What follows each world step: the policy, and the start of the distance.
    pub(super) fn after_step(&mut self) {
        let k = self.world.steps();
        self.act(k, (k - 1) % ACTUATION_HOLD_STEPS as u64 == 0);
        if self.first_x.is_none() {
            self.first_x = Some(self.world.centre().0);
        }
    }

    /// An error if the simulation became non-finite.
    pub(super) fn check(&self) -> Result<()> {
        if self.world.is_finite() {
            Ok(())
        } else {
            Err(Error::Unstable(format!(
                "non-finite state after {} steps",
                self.world.steps()
            )))
        }
    }

    /// Runs to `seconds` of simulated time (reference step count) and reports.
    pub fn run(&mut self, seconds: f64) -> Result<Outcome> {
        let target = steps_for(seconds);
        let remaining = target.saturating_sub(self.world.steps());
        self.step(remaining as usize)?;
        Ok(self.outcome())
    }

    /// The fitness so far.
    pub fn outcome(&self) -> Outcome {
        let steps = self.world.steps();
        let distance = self.first_x.map_or(0.0, |x0| self.world.centre().0 - x0);
        let elapsed = steps.saturating_sub(1) as f64 * DT;
        Outcome {
            velocity: if elapsed > 0.0 {
                distance / elapsed
            } else {
                0.0
            },
            distance,
            steps,
            seconds: steps as f64 * DT,
        }
    }

    /// The actuation currently held for every voxel.
    pub fn actuation(&self) -> &[f64] {
        &self.actuation
    }

    /// Holds `actuation` (one value per voxel, in [-1, 1], as a controller's output is held)
    /// from now on: how an [`Policy::External`] policy acts between control points. A gait or
    /// a brain replaces it at its next control point. Fails, changing nothing, on a wrong
    /// length or a non-finite value.
    pub fn set_actuation(&mut self, actuation: &[f64]) -> Result<()> {
        let n = self.voxel_count();
        if actuation.len() != n {
            return Err(Error::Input(format!(
                "expected {n} actuations (one per voxel), got {}",
                actuation.len()
            )));
        }
        if let Some(i) = actuation.iter().position(|a| !a.is_finite()) {
            return Err(Error::Input(format!(
                "actuation {i} is {}, actuations must be finite numbers in [-1, 1]",
                actuation[i]
            )));
        }
        self.actuation.copy_from_slice(actuation);
        self.world.set_actuation(&self.actuation);
        Ok(())
    }

    /// The sensor readings of the last control point, what a controller is fed: 4 per voxel
    /// (area, vx, vy, touch) in voxel index order, zeros before the first step.
    pub fn observation(&self) -> &[f32] {
        self.sensors.readings()
    }

    /// The policy driving the voxels.
    pub(crate) fn policy(&self) -> &Policy {
        &self.policy
    }

    /// Mutable access to the policy (e.g. to freeze attention mid-episode).
    pub(crate) fn policy_mut(&mut self) -> &mut Policy {
        &mut self.policy
    }

    /// Each voxel's current attention matrix (16 floats per voxel), if the policy
    /// has attention.
    pub fn attention(&self) -> Option<&[f32]> {
        match &self.policy {
            Policy::Brain(c) => c.attention(),
            Policy::Gait(_) | Policy::External => None,
        }
    }

    /// The world (read-only).
    pub fn world(&self) -> &World {
        &self.world
    }

    /// The terrain.
    pub fn terrain(&self) -> &Terrain {
        &self.terrain
    }

    /// Simulated seconds so far.
    pub fn time(&self) -> f64 {
        self.world.time()
    }

    /// Number of voxels.
    pub fn voxel_count(&self) -> usize {
        self.world.voxel_count()
    }

    /// Robot centre x (m).
    pub fn centre_x(&self) -> f64 {
        self.world.centre().0
    }

    /// Robot centre y (m).
    pub fn centre_y(&self) -> f64 {
        self.world.centre().1
    }
}
