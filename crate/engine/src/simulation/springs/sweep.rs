//! The spring velocity sweep: every lane's group solved as one Gauss-Seidel sweep in
//! closed form, lambda = A u + T c (see [`super`]), with explicit 4-wide SIMD
//! (`wide::f64x4`: SSE2 pairs natively, simd128 pairs in wasm) in the same operation
//! order as the lane-by-lane formulas, so results stay bit-identical.

// Lane loops index several parallel arrays by lane on purpose.
#![allow(clippy::needless_range_loop)]

use super::batch::{Batches, Row, MAX_ROWS};
use super::lanes::{Lane3, Velocities, L};
use wide::f64x4;

/// Applies per-row impulses `lambda` to the lanes' velocities: -J^T on a, +J^T on b.
#[inline(always)]
pub(super) fn apply(rows: &[Row], lambda: &[L], inv: &[L; 4], a: &mut Lane3, b: &mut Lane3) {
    let v = |x: &L| f64x4::from(*x);
    let z = f64x4::ZERO;
    let (mut px, mut py, mut ta, mut tb) = (z, z, z, z);
    for (row, l) in rows.iter().zip(lambda) {
        let l = v(l);
        px += v(&row.nx) * l;
        py += v(&row.ny) * l;
        ta += v(&row.rna) * l;
        tb += v(&row.rnb) * l;
    }
    let [ima, iia, imb, iib] = inv.map(f64x4::from);
    a.x = (v(&a.x) - ima * px).to_array();
    a.y = (v(&a.y) - ima * py).to_array();
    a.w = (v(&a.w) - iia * ta).to_array();
    b.x = (v(&b.x) + imb * px).to_array();
    b.y = (v(&b.y) + imb * py).to_array();
    b.w = (v(&b.w) + iib * tb).to_array();
}

/// One sweep over a batch of `R` rows.
#[inline(always)]
fn solve_batch<const R: usize>(
    (rows, acc, t): (&[Row], &mut [L], &[L]),
    inv: &[L; 4],
    a: &mut Lane3,
    b: &mut Lane3,
) {
    let rows: &[Row; R] = rows[..R].try_into().expect("R rows");
    let acc: &mut [L; R] = (&mut acc[..R]).try_into().expect("R rows");
    let t = &t[..R * (R - 1) / 2];
    let v = |x: &L| f64x4::from(*x);
    let c: [f64x4; R] = std::array::from_fn(|j| {
        let r = &rows[j];
        v(&r.neg_inv_k) * (v(&r.bias) + v(&r.gamma) * v(&acc[j]))
    });
    let mut lambda = c;
    let mut idx = 0;
    for j in 1..R {
        for i in 0..j {
            lambda[j] += v(&t[idx]) * c[i];
            idx += 1;
        }
    }
    let (ux, uy) = (v(&b.x) - v(&a.x), v(&b.y) - v(&a.y));
    let (wa, wb) = (v(&a.w), v(&b.w));
    let lambda: [L; R] = std::array::from_fn(|j| {
        let r = &rows[j].a;
        let au = (v(&r[0]) * ux + v(&r[1]) * uy) + (v(&r[2]) * wa + v(&r[3]) * wb);
        let l = lambda[j] + au;
        acc[j] = (v(&acc[j]) + l).to_array();
        l.to_array()
    });
    apply(rows, &lambda, inv, a, b);
}

impl Batches {
    /// One sequential-impulse sweep over every batch.
    pub(super) fn solve<V: Velocities + ?Sized>(&mut self, vel: &mut V) {
        for batch in &self.batches {
            let mut a = vel.gather(&batch.a);
            let mut b = vel.gather(&batch.b);
            let (start, m) = (batch.start as usize, batch.coupling as usize);
            let data = (
                &self.rows[start..],
                &mut self.impulse[start..],
                &self.coupling[m..],
            );
            let (inv, a_, b_) = (&batch.inv, &mut a, &mut b);
            match batch.rows {
                1 => solve_batch::<1>(data, inv, a_, b_),
                2 => solve_batch::<2>(data, inv, a_, b_),
                3 => solve_batch::<3>(data, inv, a_, b_),
                _ => solve_batch::<MAX_ROWS>(data, inv, a_, b_),
            }
            vel.scatter(&a, &batch.a);
            vel.scatter(&b, &batch.b);
        }
    }
}
