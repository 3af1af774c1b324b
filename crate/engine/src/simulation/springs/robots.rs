//! Robots in lanes: the springs of [`LANES`] robots of the same body solved at once, lane
//! k being robot k (issue 30, section 1).
//!
//! Each robot's own solver ([`super::Springs`]) packs up to [`LANES`] groups of springs
//! that share no piece into a batch. Here every one of those groups becomes a batch of its
//! own whose lanes are the robots: the same rows, the same square offsets and masses in
//! every lane (the body is the same), each lane reading its own robot's poses, velocities,
//! targets and impulses. Groups in a batch share no piece, so solving them one after the
//! other in lane order does exactly what the robot's own solver does; the arithmetic of a
//! group is the very same code (`prepare`, `group`, `sweep`, through [`Source`]). Every
//! lane therefore computes exactly the numbers of its robot alone, bit for bit, and every
//! vector operation is full: no padding lanes, and the velocities are read and written as
//! whole vectors instead of gathered per lane.
//!
//! "The same body" means the same springs between the same pieces; the constants of a
//! body (its squares' offsets from the pieces' centres of mass, inverse masses and
//! inertias) still differ between robots in their last bits, because each robot was
//! built where its terrain put it, so they are per lane too, copied when a robot takes a
//! lane (`attach`). The robots' own state stays where it lives ([`super::Springs`] and the
//! pieces): the caller copies it in and out around the spring phases (`load`, `store`), so
//! the rest of the step (ropes, contacts, integration) runs per robot, unchanged.

// Lane loops index several parallel arrays by lane on purpose.
#![allow(clippy::needless_range_loop)]

use super::batch::{Batch, Batches, RowDef};
use super::lanes::{Lane3, Source, Velocities, L, LANES, PAD};
use super::{law, Springs};
use crate::simulation::body::Pieces;
use crate::simulation::constants::CORNER_MASS;

/// Per piece, one value per robot: poses and velocities.
#[derive(Debug, Clone, Default)]
struct Fleet {
    x: Vec<L>,
    y: Vec<L>,
    cos: Vec<L>,
    sin: Vec<L>,
    vx: Vec<L>,
    vy: Vec<L>,
    w: Vec<L>,
}

impl Velocities for Fleet {
    /// Every lane of a robots batch names the same piece.
    #[inline(always)]
    fn gather(&self, ids: &[u32; LANES]) -> Lane3 {
        let p = ids[0] as usize;
        Lane3 {
            x: self.vx[p],
            y: self.vy[p],
            w: self.w[p],
        }
    }

    #[inline(always)]
    fn scatter(&mut self, lane: &Lane3, ids: &[u32; LANES]) {
        let p = ids[0] as usize;
        self.vx[p] = lane.x;
        self.vy[p] = lane.y;
        self.w[p] = lane.w;
    }
}

impl Source for Fleet {
    #[inline(always)]
    fn pose(&self, ids: &[u32; LANES]) -> [L; 4] {
        let p = ids[0] as usize;
        [self.x[p], self.y[p], self.cos[p], self.sin[p]]
    }
}

/// The springs of [`LANES`] robots of one body, one robot per lane.
#[derive(Debug, Clone)]
pub struct RobotLanes {
    batches: Batches,
    /// Row e here is row `map[e].0`, lane `map[e].1` of each robot's own packing.
    map: Vec<(u32, u8)>,
    /// Batch g here is batch `groups[g].0`, lane `groups[g].1` of each robot's own packing.
    groups: Vec<(u32, u8)>,
    /// The padding slots (row, lane) of each robot's own packing.
    padding: Vec<(u32, u8)>,
    fleet: Fleet,
}

/// The energy terms a robot's own preparation leaves in a padding lane: 1 / m_ref of two
/// bare corner squares with no lever arm (the padding's anchors are its pieces' centres,
/// so its length, stretch and lever arms are zero), and a zero stretch.
const PADDING_ENERGY: (f64, f64) = (2.0 / CORNER_MASS, 0.0);

impl RobotLanes {
    /// The lanes for robots whose springs are laid out like `template`'s.
    pub fn new(template: &Springs) -> Self {
        let own = &template.batches;
        let mut out = Batches::default();
        let mut map = Vec::new();
        let mut groups = Vec::new();
        let mut padding = Vec::new();
        let mut n_coupling = 0;
        for (b, batch) in own.batches.iter().enumerate() {
            for k in (0..LANES).filter(|&k| batch.a[k] == PAD) {
                let rows = batch.start..batch.start + batch.rows;
                padding.extend(rows.map(|r| (r, k as u8)));
            }
            for k in (0..LANES).filter(|&k| batch.a[k] != PAD) {
                let splat = |x: &L| [x[k]; LANES]; // every lane set by `attach`
                let n = batch.rows as usize;
                groups.push((b as u32, k as u8));
                out.batches.push(Batch {
                    a: [batch.a[k]; LANES],
                    b: [batch.b[k]; LANES],
                    squares: batch.squares.each_ref().map(splat),
                    inv: batch.inv.each_ref().map(splat),
                    live: splat(&batch.live),
                    start: out.defs.len() as u32,
                    coupling: n_coupling as u32,
                    rows: batch.rows,
                });
                n_coupling += n * (n - 1) / 2;
                for r in batch.start as usize..batch.start as usize + n {
                    let d = &own.defs[r];
                    out.defs.push(RowDef {
                        qax: splat(&d.qax),
                        qay: splat(&d.qay),
                        qbx: splat(&d.qbx),
                        qby: splat(&d.qby),
                        target: [0.0; LANES],
                    });
                    map.push((r as u32, k as u8));
                }
            }
        }
        let n = out.defs.len();
        out.rows = vec![Default::default(); n];
        out.coupling = vec![[0.0; LANES]; n_coupling];
        out.impulse = vec![[0.0; LANES]; n];
        out.energy = vec![([0.0; LANES], [0.0; LANES]); n];
        let mut lanes = RobotLanes {
            batches: out,
            map,
            groups,
            padding,
            fleet: Fleet::default(),
        };
        for k in 0..LANES {
            lanes.attach(k, template);
        }
        lanes
    }

    /// Gives lane `k` to a robot with these springs: copies its body's constants (square
    /// offsets, inverse masses and inertias, anchor offsets). Its springs must be laid out
    /// like the template's (the same body).
    pub fn attach(&mut self, k: usize, springs: &Springs) {
        let own = &springs.batches;
        let slots = own.defs.len() * LANES;
        assert_eq!(slots, self.map.len() + self.padding.len(), "same body");
        for (g, &(b, lane)) in self.groups.iter().enumerate() {
            let (src, lane) = (&own.batches[b as usize], lane as usize);
            let dst = &mut self.batches.batches[g];
            assert!(
                src.a[lane] == dst.a[k] && src.b[lane] == dst.b[k],
                "same body"
            );
            for i in 0..4 {
                dst.squares[i][k] = src.squares[i][lane];
                dst.inv[i][k] = src.inv[i][lane];
            }
            dst.live[k] = src.live[lane];
        }
        for (e, &(r, lane)) in self.map.iter().enumerate() {
            let (src, lane) = (&own.defs[r as usize], lane as usize);
            let dst = &mut self.batches.defs[e];
            dst.qax[k] = src.qax[lane];
            dst.qay[k] = src.qay[lane];
            dst.qbx[k] = src.qbx[lane];
            dst.qby[k] = src.qby[lane];
        }
    }

    /// Copies robot `k`'s spring state (targets, warm-start impulses), poses and
    /// velocities into lane `k`, before [`RobotLanes::prepare`].
    pub fn load(&mut self, k: usize, springs: &Springs, pieces: &Pieces) {
        let own = &springs.batches;
        for (e, &(r, lane)) in self.map.iter().enumerate() {
            let (r, lane) = (r as usize, lane as usize);
            self.batches.defs[e].target[k] = own.defs[r].target[lane];
            self.batches.impulse[e][k] = own.impulse[r][lane];
        }
        let f = &mut self.fleet;
        let n = pieces.len();
        for v in [&mut f.x, &mut f.y, &mut f.cos, &mut f.sin] {
            v.resize(n, [0.0; LANES]);
        }
        for p in 0..n {
            f.x[p][k] = pieces.x[p];
            f.y[p][k] = pieces.y[p];
            f.cos[p][k] = pieces.cos[p];
            f.sin[p][k] = pieces.sin[p];
        }
        self.load_velocities(k, pieces);
    }

    /// Copies robot `k`'s velocities into lane `k` (before a sweep).
    pub fn load_velocities(&mut self, k: usize, pieces: &Pieces) {
        let f = &mut self.fleet;
        let n = pieces.len();
        for v in [&mut f.vx, &mut f.vy, &mut f.w] {
            v.resize(n, [0.0; LANES]);
        }
        for (p, v) in pieces.vel.iter().enumerate() {
            f.vx[p][k] = v.vx;
            f.vy[p][k] = v.vy;
            f.w[p][k] = v.w;
        }
    }

    /// Writes lane `k`'s velocities back to robot `k` (after the preparation or a sweep).
    pub fn store_velocities(&self, k: usize, pieces: &mut Pieces) {
        let f = &self.fleet;
        for (p, v) in pieces.vel.iter_mut().enumerate() {
            v.vx = f.vx[p][k];
            v.vy = f.vy[p][k];
            v.w = f.w[p][k];
        }
    }

    /// Writes lane `k`'s impulses and energy terms back to robot `k`'s springs (after
    /// the last sweep of a step).
    pub fn store(&self, k: usize, springs: &mut Springs) {
        let own = &mut springs.batches;
        for (e, &(r, lane)) in self.map.iter().enumerate() {
            let (r, lane) = (r as usize, lane as usize);
            own.impulse[r][lane] = self.batches.impulse[e][k];
            let (inv_ref, stretch) = &self.batches.energy[e];
            own.energy[r].0[lane] = inv_ref[k];
            own.energy[r].1[lane] = stretch[k];
        }
        for &(r, lane) in &self.padding {
            let (r, lane) = (r as usize, lane as usize);
            (own.energy[r].0[lane], own.energy[r].1[lane]) = PADDING_ENERGY;
        }
    }

    /// Prepares every row of every lane and applies the warm-start impulses (what
    /// [`Springs::prepare`] does for one robot).
    pub fn prepare(&mut self) {
        self.batches.prepare(&mut self.fleet, law());
    }

    /// One sequential-impulse sweep over every spring of every lane (what
    /// [`Springs::solve_velocity`] does for one robot).
    pub fn solve_velocity(&mut self) {
        self.batches.solve(&mut self.fleet);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::simulation::assembly::assemble;
    use crate::simulation::ground::Ground;
    use crate::simulation::Shape;

    fn vel_bits(p: &Pieces) -> Vec<[u64; 3]> {
        p.vel
            .iter()
            .map(|v| [v.vx.to_bits(), v.vy.to_bits(), v.w.to_bits()])
            .collect()
    }

    #[test]
    fn prepare_and_sweep_match_one_robot() {
        let shape = Shape::parse("biped-4x3").unwrap();
        let ground = Ground::new(&[0.0, 10.0, 1990.0, 2000.0], &[100.0, 5.0, 5.0, 100.0]);
        let asm = assemble(shape.voxels(), &ground, 0.0);
        let mut pieces = asm.pieces.clone();
        for (i, v) in pieces.vel.iter_mut().enumerate() {
            v.vx = 0.1 * i as f64;
            v.vy = -0.05 * i as f64;
            v.w = 0.01 * i as f64;
        }
        let mut springs = Springs::new(&asm.springs, &pieces);
        let mut lanes = RobotLanes::new(&springs);
        for k in 0..LANES {
            lanes.load(k, &springs, &pieces);
        }
        springs.prepare(&mut pieces);
        lanes.prepare();
        let mut mine = pieces.clone();
        lanes.store_velocities(1, &mut mine);
        assert_eq!(vel_bits(&pieces), vel_bits(&mine), "after prepare");
        springs.solve_velocity(&mut pieces.vel);
        lanes.solve_velocity();
        lanes.store_velocities(2, &mut mine);
        assert_eq!(vel_bits(&pieces), vel_bits(&mine), "after a sweep");
    }
}
