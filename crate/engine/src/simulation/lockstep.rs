//! Robots of the same body stepped together, their springs in SIMD lanes (issue 30,
//! section 1): [`Lockstep::step`] advances [`LANES`] worlds by one step each, exactly as
//! [`World::step`] advances each alone, bit for bit.
//!
//! The springs, most of a step's time (the preparation and the 10 velocity sweeps), run
//! through [`RobotLanes`], one robot per lane; everything else (self-contacts, gravity,
//! ropes, ground contacts, integration, position corrections, contact detection) runs per
//! world, between the spring phases and in the same order as in [`World::step`]. Each
//! robot's velocities are copied into its lane before a spring phase and back after it.

use super::springs::RobotLanes;
use super::World;
use crate::simulation::constants::VELOCITY_ITERATIONS;

/// Robots stepped together, one per lane.
pub const LANES: usize = super::springs::LANES;

/// The spring lanes for worlds of one body.
#[derive(Debug, Clone)]
pub struct Lockstep {
    lanes: RobotLanes,
}

impl Lockstep {
    /// Lanes for `worlds`, [`LANES`] worlds built from the same body (same shape; the
    /// terrain, the pose and the actuation may differ), world k in lane k.
    pub fn new(worlds: &[&World]) -> Self {
        assert_eq!(worlds.len(), LANES, "one world per lane");
        let mut lanes = RobotLanes::new(&worlds[0].springs);
        for (k, w) in worlds.iter().enumerate() {
            lanes.attach(k, &w.springs);
        }
        Lockstep { lanes }
    }

    /// Gives lane `k` to another world of the same body.
    pub fn attach(&mut self, k: usize, world: &World) {
        self.lanes.attach(k, &world.springs);
    }

    /// One step of every world: `worlds` holds the [`LANES`] worlds attached, in lane
    /// order.
    pub fn step(&mut self, worlds: &mut [&mut World]) {
        assert_eq!(worlds.len(), LANES, "one world per lane");
        let lanes = &mut self.lanes;
        for (k, w) in worlds.iter_mut().enumerate() {
            w.begin_step();
            lanes.load(k, &w.springs, &w.pieces);
        }
        lanes.prepare();
        for (k, w) in worlds.iter_mut().enumerate() {
            lanes.store_velocities(k, &mut w.pieces);
            w.prepare_others();
        }
        for _ in 0..VELOCITY_ITERATIONS {
            for (k, w) in worlds.iter().enumerate() {
                lanes.load_velocities(k, &w.pieces);
            }
            lanes.solve_velocity();
            for (k, w) in worlds.iter_mut().enumerate() {
                lanes.store_velocities(k, &mut w.pieces);
                w.solve_others();
            }
        }
        for (k, w) in worlds.iter_mut().enumerate() {
            lanes.store(k, &mut w.springs);
            w.end_step();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::simulation::{Shape, Terrain};

    /// Every number of the state, as bits.
    fn bits(w: &World) -> Vec<u64> {
        let p = w.pieces();
        let mut out = Vec::new();
        for i in 0..p.len() {
            let v = p.vel[i];
            for x in [p.x[i], p.y[i], p.angle[i], v.vx, v.vy, v.w] {
                out.push(x.to_bits());
            }
        }
        out.push(w.spring_energy().to_bits());
        out
    }

    fn world(shape: &Shape, terrain: &str) -> World {
        let t = Terrain::parse(terrain).expect("terrain");
        World::new(shape.voxels(), t.xs(), t.ys())
    }

    /// Four robots on four terrains with four gaits, 300 steps: lockstep and alone agree
    /// on every bit at every step.
    #[test]
    fn lockstep_is_bit_identical_to_alone() {
        for name in ["biped-4x3", "comb-7x2", "10-10-11"] {
            let shape = Shape::parse(name).expect("shape");
            let terrains = ["hilly-1-10-0", "hilly-1-10-1", "flat", "hilly-1-10-7"];
            let mut alone: Vec<World> = terrains.iter().map(|t| world(&shape, t)).collect();
            let mut together = alone.clone();
            let mut lock = Lockstep::new(&together.iter().collect::<Vec<_>>());
            let n = shape.voxel_count();
            for step in 0..300u32 {
                if step % 20 == 0 {
                    for (k, (a, b)) in alone.iter_mut().zip(&mut together).enumerate() {
                        let u: Vec<f64> = (0..n)
                            .map(|v| (step as f64 * 0.05 + v as f64 + k as f64).sin())
                            .collect();
                        a.set_actuation(&u);
                        b.set_actuation(&u);
                    }
                }
                alone.iter_mut().for_each(World::step);
                let mut refs: Vec<&mut World> = together.iter_mut().collect();
                lock.step(&mut refs);
                for (k, (a, b)) in alone.iter().zip(&together).enumerate() {
                    let (x, y) = (bits(a), bits(b));
                    let first = x.iter().zip(&y).position(|(p, q)| p != q);
                    assert_eq!(x, y, "{name}, step {step}, robot {k}, first {first:?}");
                }
            }
        }
    }
}
