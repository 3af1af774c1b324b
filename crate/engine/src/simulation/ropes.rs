//! Rope constraints: the centres of adjacent corner squares of a voxel never come
//! closer than 1.2 m, so the squares cannot overlap (SPEC 2). A rope is a one-sided
//! hard distance constraint, active only while it is at its limit: a clamped impulse in
//! the velocity solver and a Baumgarte-limited push in the position solver. Ropes are
//! almost never at their limit, so [`Ropes::prepare`] first compares the squared
//! distance with a slightly widened limit and builds the full row only near it.

use super::body::{Pieces, Velocity};
use super::constants::{LINEAR_SLOP, MAX_LINEAR_CORRECTION, ROPE_MIN_LENGTH};
use super::joint::JointRow;

/// Squared distances above this are surely longer than the rope limit, whatever the
/// rounding of the square root: the full row is built only below it.
const SURELY_SLACK2: f64 = ROPE_MIN_LENGTH * ROPE_MIN_LENGTH * (1.0 + 1e-9);

/// One rope between the centres of two corner squares.
#[derive(Debug, Clone, Copy)]
pub(crate) struct RopeDef {
    /// Piece and offset of the first square centre from its centre of mass.
    pub(crate) a: (usize, f64, f64),
    /// Piece and offset of the second square centre.
    pub(crate) b: (usize, f64, f64),
}

/// Every rope of a robot, with the active rows of the current step.
#[derive(Debug, Clone, Default)]
pub(crate) struct Ropes {
    defs: Vec<RopeDef>,
    active: Vec<(usize, JointRow)>,
    impulse: Vec<f64>,
}

impl Ropes {
    /// Builds the rope set.
    pub(crate) fn new(defs: Vec<RopeDef>) -> Self {
        let n = defs.len();
        Ropes {
            defs,
            active: Vec::with_capacity(n),
            impulse: vec![0.0; n],
        }
    }

    fn row(&self, pieces: &Pieces, i: usize) -> JointRow {
        let d = &self.defs[i];
        let ra = pieces.rotate(d.a.0, d.a.1, d.a.2);
        let rb = pieces.rotate(d.b.0, d.b.1, d.b.2);
        JointRow::new(pieces, d.a.0, d.b.0, ra, rb)
    }

    /// True if rope i is certainly longer than its limit (no square root needed).
    #[inline]
    fn surely_slack(&self, pieces: &Pieces, i: usize) -> bool {
        let d = &self.defs[i];
        let (ax, ay) = pieces.to_world(d.a.0, d.a.1, d.a.2);
        let (bx, by) = pieces.to_world(d.b.0, d.b.1, d.b.2);
        let (dx, dy) = (bx - ax, by - ay);
        dx * dx + dy * dy > SURELY_SLACK2
    }

    /// Finds the ropes at their limit and applies their warm-start impulses.
    pub(crate) fn prepare(&mut self, pieces: &mut Pieces) {
        self.active.clear();
        for i in 0..self.defs.len() {
            if self.surely_slack(pieces, i) {
                self.impulse[i] = 0.0;
                continue;
            }
            let row = self.row(pieces, i);
            if row.length <= ROPE_MIN_LENGTH {
                row.apply(&mut pieces.vel, self.impulse[i]);
                self.active.push((i, row));
            } else {
                self.impulse[i] = 0.0;
            }
        }
    }

    /// One sweep over the active ropes: the anchors may separate, never approach.
    #[inline]
    pub(crate) fn solve_velocity(&mut self, vel: &mut [Velocity]) {
        for (i, row) in &self.active {
            let lambda = -row.velocity(vel) / row.inv_mass;
            let old = self.impulse[*i];
            let new = (old + lambda).max(0.0);
            self.impulse[*i] = new;
            row.apply(vel, new - old);
        }
    }

    /// One position sweep; returns true when no rope is shorter than its limit by more
    /// than the slop.
    pub(crate) fn solve_position(&self, pieces: &mut Pieces) -> bool {
        let mut ok = true;
        for (i, _) in &self.active {
            let row = self.row(pieces, *i);
            let error = row.length - ROPE_MIN_LENGTH;
            if error >= -LINEAR_SLOP {
                continue;
            }
            ok = false;
            let c = (error + LINEAR_SLOP).clamp(-MAX_LINEAR_CORRECTION, 0.0);
            let impulse = -c / row.inv_mass;
            let d = &self.defs[*i];
            let (px, py) = (row.nx * impulse, row.ny * impulse);
            let ra = pieces.rotate(d.a.0, d.a.1, d.a.2);
            let rb = pieces.rotate(d.b.0, d.b.1, d.b.2);
            pieces.push_position(d.a.0, -px, -py, ra.0, ra.1);
            pieces.push_position(d.b.0, px, py, rb.0, rb.1);
        }
        ok
    }
}
