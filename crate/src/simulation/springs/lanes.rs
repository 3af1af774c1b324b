//! The lane width and what is gathered per lane: [`LANES`] independent groups of
//! springs are solved side by side, one value per lane in an [`L`].
//!
//! Padding: an empty lane's pieces are [`PAD`], which is no piece. Gathering its
//! velocity gives zero and scattering drops it; its rows have zero inverse masses
//! and a zero `live` flag, so it never changes anything (see [`super::batch::Batch`]).

// Lane loops index several parallel arrays by lane on purpose.
#![allow(clippy::needless_range_loop)]

use crate::simulation::body::Velocity;

/// Lanes per batch: groups of springs solved at once (the SIMD width of the solver).
pub(crate) const LANES: usize = 4;

/// One value per lane.
pub(super) type L = [f64; LANES];

/// Piece index of a padding lane: no piece.
pub(super) const PAD: u32 = u32::MAX;

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
