//! The lane width and what is gathered per lane: [`LANES`] independent groups of
//! springs are solved side by side, one value per lane in an [`L`].
//!
//! Padding: an empty lane's pieces are [`PAD`], which is no piece. Gathering its
//! velocity gives zero and scattering drops it; its rows have zero inverse masses
//! and a zero `live` flag, so it never changes anything (see [`super::batch::Batch`]).
//!
//! Where the lanes' poses and velocities come from is a [`Source`]: one robot's pieces
//! (lane k reads piece `ids[k]`, the usual solver) or [`super::robots`] (lane k is robot
//! k, every lane reads the same piece of its own robot). The solver's arithmetic is the
//! same code for both.

// Lane loops index several parallel arrays by lane on purpose.
#![allow(clippy::needless_range_loop)]

use crate::simulation::body::{Pieces, Velocity};

/// Lanes per batch: groups of springs solved at once (the SIMD width of the solver).
pub const LANES: usize = 4;

/// One value per lane.
pub(super) type L = [f64; LANES];

/// Piece index of a padding lane: no piece.
pub(super) const PAD: u32 = u32::MAX;

/// Velocities of the lanes' pieces, as the sweep reads and writes them.
pub(super) trait Velocities {
    /// The velocities of the lanes' pieces `ids`.
    fn gather(&self, ids: &[u32; LANES]) -> Lane3;
    /// Writes the velocities of the lanes' pieces `ids` back.
    fn scatter(&mut self, lane: &Lane3, ids: &[u32; LANES]);
}

/// Poses and velocities of the lanes' pieces, as the preparation reads them.
pub(super) trait Source: Velocities {
    /// Position and rotation of the lanes' pieces `ids`: x, y, cos, sin.
    fn pose(&self, ids: &[u32; LANES]) -> [L; 4];
}

impl Velocities for [Velocity] {
    #[inline(always)]
    fn gather(&self, ids: &[u32; LANES]) -> Lane3 {
        Lane3::gather(self, ids)
    }

    #[inline(always)]
    fn scatter(&mut self, lane: &Lane3, ids: &[u32; LANES]) {
        lane.scatter(self, ids);
    }
}

impl Velocities for Pieces {
    #[inline(always)]
    fn gather(&self, ids: &[u32; LANES]) -> Lane3 {
        Lane3::gather(&self.vel, ids)
    }

    #[inline(always)]
    fn scatter(&mut self, lane: &Lane3, ids: &[u32; LANES]) {
        lane.scatter(&mut self.vel, ids);
    }
}

impl Source for Pieces {
    /// A padding lane ([`PAD`]) reads the last piece's pose: any finite pose would do,
    /// its rows have no effect.
    #[inline(always)]
    fn pose(&self, ids: &[u32; LANES]) -> [L; 4] {
        let last = self.len() - 1;
        let p = ids.map(|id| (id as usize).min(last));
        let get = |values: &[f64]| p.map(|p| values[p]);
        [get(&self.x), get(&self.y), get(&self.cos), get(&self.sin)]
    }
}

/// Velocities of the lanes' pieces on one side of a batch, struct-of-arrays.
pub(super) struct Lane3 {
    pub(super) x: L,
    pub(super) y: L,
    pub(super) w: L,
}

impl Lane3 {
    /// The velocities of `pieces` (zero for [`PAD`]).
    #[inline]
    pub(super) fn gather(vel: &[Velocity], pieces: &[u32; LANES]) -> Self {
        let v = pieces.map(|p| vel.get(p as usize).copied().unwrap_or_default());
        Lane3 {
            x: v.map(|v| v.vx),
            y: v.map(|v| v.vy),
            w: v.map(|v| v.w),
        }
    }

    /// Writes the velocities back to `pieces` (nothing for [`PAD`]).
    #[inline]
    pub(super) fn scatter(&self, vel: &mut [Velocity], pieces: &[u32; LANES]) {
        for k in 0..LANES {
            if let Some(v) = vel.get_mut(pieces[k] as usize) {
                *v = Velocity {
                    vx: self.x[k],
                    vy: self.y[k],
                    w: self.w[k],
                };
            }
        }
    }
}
