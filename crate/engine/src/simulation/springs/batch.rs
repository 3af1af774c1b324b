//! The packed spring data, struct-of-arrays over the lanes (`[f64; LANES]`, which the
//! solver loads as SIMD vectors):
//! - per batch ([`Batch`]): the lanes' pieces, their corner squares' centre offsets
//!   (piece frame) and inverse masses;
//! - per row, static ([`RowDef`]): each anchor's offset from its square's centre and
//!   the target length set by the actuation;
//! - per row, per step ([`Row`]): what the velocity sweep needs;
//! - per batch, per step: the coupling T between its rows, `coupling[batch.coupling..]`.
//!
//! `rows[batch.start + j]` is row j of every lane of a batch (j < `batch.rows` <=
//! [`MAX_ROWS`]); spring i sits at `slot[i]` = (row, lane).

use super::lanes::{L, LANES};

/// Rows per group at most: the four springs between two corner squares of a side.
pub(crate) const MAX_ROWS: usize = 4;

/// Entries of T below the diagonal for a group of [`MAX_ROWS`] rows.
pub(super) const MAX_COUPLING: usize = MAX_ROWS * (MAX_ROWS - 1) / 2;

/// Row j of the lanes of a batch, prepared for one step.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Row {
    pub(super) nx: L,
    pub(super) ny: L,
    pub(super) rna: L,
    pub(super) rnb: L,
    /// Row j of A = T diag(-inv_k) J (see [`super`]), over u = (vb - va, wa, wb).
    pub(super) a: [L; 4],
    /// -inv_k, as the sweep uses it (0 - inv_k: computed once per step, not per sweep).
    pub(super) neg_inv_k: L,
    pub(super) bias: L,
    pub(super) gamma: L,
}

/// Static part of row j of a batch: anchor offsets from their square centres (piece
/// frame) and the target length.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct RowDef {
    pub(super) qax: L,
    pub(super) qay: L,
    pub(super) qbx: L,
    pub(super) qby: L,
    pub(super) target: L,
}

/// Up to [`LANES`] groups of springs that share no piece.
#[derive(Debug, Clone, Copy)]
pub(super) struct Batch {
    /// The lanes' pieces on side a and side b ([`super::lanes::PAD`] for padding).
    pub(super) a: [u32; LANES],
    pub(super) b: [u32; LANES],
    /// Square centre offsets from the pieces' centres of mass, piece frame: a x, a y,
    /// b x, b y.
    pub(super) squares: [L; 4],
    /// Inverse masses and inertias: a mass, a inertia, b mass, b inertia.
    pub(super) inv: [L; 4],
    /// 1 for a lane that carries springs, 0 for padding.
    pub(super) live: L,
    /// First row and first coupling entry (rows (rows - 1) / 2 of them).
    pub(super) start: u32,
    pub(super) coupling: u32,
    /// Rows of every lane's group (1..=[`MAX_ROWS`]).
    pub(super) rows: u32,
}

/// Springs packed into batches, with each spring's (row, lane) slot.
#[derive(Debug, Clone, Default)]
pub(super) struct Batches {
    pub(super) batches: Vec<Batch>,
    pub(super) defs: Vec<RowDef>,
    pub(super) rows: Vec<Row>,
    /// Per batch, the Gauss-Seidel transfer T between its rows (see [`super`]):
    /// entry (j, i), i < j, in row-major order.
    pub(super) coupling: Vec<L>,
    /// Accumulated impulse per row (warm start).
    pub(super) impulse: Vec<L>,
    /// Per row, for the potential energy of the last prepared step: 1 / m_ref (1/kg,
    /// the stiffness is k = m_ref omega^2, divided out only when the energy is asked
    /// for) and the stretch (m, zero in padding lanes).
    pub(super) energy: Vec<(L, L)>,
    /// Slot of spring i: (row index, lane).
    pub(super) slot: Vec<(u32, u8)>,
}

impl Batches {
    /// Sets spring i's target length.
    #[inline]
    pub(super) fn set_target(&mut self, i: usize, target: f64) {
        let (r, k) = self.slot[i];
        self.defs[r as usize].target[k as usize] = target;
    }

    /// Potential energy of the last prepared step: sum of k x^2 / 2, with
    /// k = m_ref `omega2`.
    pub(super) fn potential_energy(&self, omega2: f64) -> f64 {
        let mut sum = 0.0;
        for (inv_ref, x) in &self.energy {
            for (inv_ref, x) in inv_ref.iter().zip(x) {
                let k = omega2 / inv_ref;
                sum += 0.5 * k * x * x;
            }
        }
        sum
    }
}
