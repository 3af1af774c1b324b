//! The spring solver's data, four independent chains at a time.
//!
//! Sequential impulses are latency-bound: each row reads the velocities the previous
//! row wrote. Springs joining the same two corner squares form a *group* (the 4
//! springs of a side, or one diagonal); groups that share no piece commute, so we pack
//! up to four such groups of equal length into a *batch* (see [`super::packing`]) and
//! prepare and solve its rows lane by lane: four dependency chains in flight instead
//! of one, with identical arithmetic per row.
//!
//! Layout, all struct-of-arrays over the 4 lanes (`[f64; LANES]`, so the compiler packs
//! them into SIMD registers):
//! - per batch ([`Batch`]): the lanes' pieces, their corner squares' centre offsets
//!   (piece frame) and inverse masses;
//! - per row, static ([`RowDef`]): each anchor's offset from its square's centre and
//!   the target length set by the actuation;
//! - per row, per step ([`Row4`]): what the velocity sweep needs;
//! - per batch, per step: the coupling between its rows, `coupling[batch.coupling..]`.
//!
//! `rows[batch.start + j]` is row j of every lane of a batch. A missing lane points at
//! the padding piece (index = number of real pieces, whose velocity slot exists but is
//! never integrated) with zero inverse masses and a zero `live` flag, so it never
//! changes anything.

// Lane loops index several parallel arrays by lane on purpose.
#![allow(clippy::needless_range_loop)]

use super::body::Velocity;

/// Lanes per batch.
pub const LANES: usize = 4;
/// One value per lane.
pub type L = [f64; LANES];

/// Row j of the four lanes of a batch, prepared for one step.
#[derive(Debug, Clone, Copy, Default)]
pub struct Row4 {
    pub nx: L,
    pub ny: L,
    pub rna: L,
    pub rnb: L,
    /// Row j of A = T diag(-inv_k) J (see [`super::lane_solve`]), over u = (vb - va, wa, wb).
    pub a: [L; 4],
    pub inv_k: L,
    pub bias: L,
    pub gamma: L,
}

/// Static part of row j of a batch: anchor offsets from their square centres (piece
/// frame) and the target length.
#[derive(Debug, Clone, Copy, Default)]
pub struct RowDef {
    pub qax: L,
    pub qay: L,
    pub qbx: L,
    pub qby: L,
    pub target: L,
}

/// Up to four groups of springs that share no piece.
#[derive(Debug, Clone, Copy)]
pub struct Batch {
    pub a: [u32; LANES],
    pub b: [u32; LANES],
    /// Square centre offsets from the pieces' centres of mass, piece frame: a x, a y,
    /// b x, b y.
    pub squares: [L; 4],
    /// Inverse masses and inertias: a mass, a inertia, b mass, b inertia.
    pub inv: [L; 4],
    /// 1 for a lane that carries springs, 0 for padding.
    pub live: L,
    /// First row and first coupling entry (rows (rows - 1) / 2 of them).
    pub start: u32,
    pub coupling: u32,
    pub rows: u32,
}

/// Springs packed into batches, with each spring's (row, lane) slot.
#[derive(Debug, Clone, Default)]
pub struct Lanes {
    pub batches: Vec<Batch>,
    pub defs: Vec<RowDef>,
    pub rows: Vec<Row4>,
    /// Per batch, the Gauss-Seidel transfer T between its rows (see
    /// [`super::lane_solve`]): entry (j, i), i < j, in row-major order.
    pub coupling: Vec<L>,
    pub impulse: Vec<L>,
    /// Stiffness (N/m) and stretch (m) of the last prepared step, per row.
    pub energy: Vec<(L, L)>,
    /// Slot of spring i: (row index, lane).
    pub slot: Vec<(u32, u8)>,
}

impl Lanes {
    /// Sets spring i's target length.
    #[inline]
    pub fn set_target(&mut self, i: usize, target: f64) {
        let (r, k) = self.slot[i];
        self.defs[r as usize].target[k as usize] = target;
    }

    /// Potential energy of the last prepared step: sum of k x^2 / 2.
    pub fn potential_energy(&self) -> f64 {
        let mut sum = 0.0;
        for (k, x) in &self.energy {
            for j in 0..LANES {
                sum += 0.5 * k[j] * x[j] * x[j];
            }
        }
        sum
    }
}

/// Velocities of the four lanes' pieces on one side, struct-of-arrays.
pub struct Lane3 {
    pub x: L,
    pub y: L,
    pub w: L,
}

impl Lane3 {
    #[inline]
    pub fn gather(vel: &[Velocity], pieces: &[u32; LANES]) -> Self {
        let v = pieces.map(|p| vel[p as usize]);
        Lane3 {
            x: v.map(|v| v.vx),
            y: v.map(|v| v.vy),
            w: v.map(|v| v.w),
        }
    }

    #[inline]
    pub fn scatter(&self, vel: &mut [Velocity], pieces: &[u32; LANES]) {
        for k in 0..LANES {
            vel[pieces[k] as usize] = Velocity {
                vx: self.x[k],
                vy: self.y[k],
                w: self.w[k],
            };
        }
    }
}
