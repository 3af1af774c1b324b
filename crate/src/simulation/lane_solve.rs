//! The spring velocity sweep: each lane's group solved as one Gauss-Seidel sweep in
//! closed form.
//!
//! The rows j of a group all join the same two pieces, with Jacobians J_j = (-n_j,
//! -r_a x n_j, n_j, r_b x n_j). Projecting row i changes the velocities by M^-1 J_i^T
//! lambda_i, so it changes row j's relative velocity by K_ji lambda_i with
//! K_ji = J_j M^-1 J_i^T. The sequential sweep over the group is therefore
//!
//! ```text
//! base_j   = -inv_k_j (J_j v + bias_j + gamma_j acc_j)   (all j, from the group's v)
//! lambda_j = base_j + sum_{i<j} m_ji lambda_i,  m_ji = -inv_k_j K_ji
//! v       += M^-1 sum_j J_j^T lambda_j
//! ```
//!
//! i.e. lambda = T base with T = (I - m)^-1 (unit lower triangular). J_j v depends on
//! v only through u = (vb - va, wa, wb), so with A = T diag(-inv_k) J (4 numbers per
//! row) and c_j = -inv_k_j (bias_j + gamma_j acc_j), lambda = A u + T c: the same
//! Gauss-Seidel sweep as projecting one row at a time (same order, same impulses, up
//! to rounding), but a short dependency chain from the velocities to the impulses,
//! since T c depends only on the previous sweeps. T and A are built once per step by
//! [`group_matrices`]; the velocity update uses per-lane inverse masses.

//!
//! The sweep and [`apply`] use explicit 4-wide SIMD (`wide::f64x4`: SSE2 pairs natively,
//! simd128 pairs in wasm), loading the `[f64; LANES]` fields as vectors, in the same
//! operation order as the lane-by-lane formulas, so results stay bit-identical.

// Lane loops index several parallel arrays by lane on purpose.
#![allow(clippy::needless_range_loop)]

use super::body::Velocity;
use super::lanes::{Lane3, Lanes, Row4, L, LANES};
use wide::f64x4;

/// The coupling m_ji (i < j, row-major) of a group's rows.
#[inline]
fn coupling(rows: &[Row4], inv: &[L; 4]) -> [L; 6] {
    let [ima, iia, imb, iib] = inv;
    let mut m = [[0.0; LANES]; 6];
    let mut idx = 0;
    for j in 1..rows.len() {
        let rj = &rows[j];
        for ri in &rows[..j] {
            for k in 0..LANES {
                let nn = rj.nx[k] * ri.nx[k] + rj.ny[k] * ri.ny[k];
                let kji = (ima[k] + imb[k]) * nn
                    + iia[k] * rj.rna[k] * ri.rna[k]
                    + iib[k] * rj.rnb[k] * ri.rnb[k];
                m[idx][k] = -rj.inv_k[k] * kji;
            }
            idx += 1;
        }
    }
    m
}

/// Builds T (i < j entries, row-major, into `t`) and every row's A from the
/// prepared rows of a group (at most 4 rows).
pub fn group_matrices(rows: &mut [Row4], inv: &[L; 4], t: &mut [L]) {
    let m = coupling(rows, inv);
    let at = |j: usize, i: usize| j * (j - 1) / 2 + i;
    for j in 1..rows.len() {
        for i in 0..j {
            let mut sum = m[at(j, i)];
            for q in i + 1..j {
                for k in 0..LANES {
                    sum[k] += m[at(j, q)][k] * t[at(q, i)][k];
                }
            }
            t[at(j, i)] = sum;
        }
    }
    for j in 0..rows.len() {
        let mut a = [[0.0; LANES]; 4];
        for i in 0..=j {
            let r = &rows[i];
            for k in 0..LANES {
                let w = if i == j {
                    -r.inv_k[k]
                } else {
                    -r.inv_k[k] * t[at(j, i)][k]
                };
                let ji = [r.nx[k], r.ny[k], -r.rna[k], r.rnb[k]];
                for (dst, v) in a.iter_mut().zip(ji) {
                    dst[k] += w * v;
                }
            }
        }
        rows[j].a = a;
    }
}

/// Applies per-row impulses `lambda` to the lanes' velocities: -J^T on a, +J^T on b.
#[inline(always)]
pub fn apply(rows: &[Row4], lambda: &[L], inv: &[L; 4], a: &mut Lane3, b: &mut Lane3) {
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
    (rows, acc, t): (&[Row4], &mut [L], &[L]),
    inv: &[L; 4],
    a: &mut Lane3,
    b: &mut Lane3,
) {
    let rows: &[Row4; R] = rows[..R].try_into().expect("R rows");
    let acc: &mut [L; R] = (&mut acc[..R]).try_into().expect("R rows");
    let t = &t[..R * (R - 1) / 2];
    let v = |x: &L| f64x4::from(*x);
    let c: [f64x4; R] = std::array::from_fn(|j| {
        let r = &rows[j];
        -v(&r.inv_k) * (v(&r.bias) + v(&r.gamma) * v(&acc[j]))
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

impl Lanes {
    /// One sequential-impulse sweep over every batch.
    pub fn solve(&mut self, vel: &mut [Velocity]) {
        for batch in &self.batches {
            let mut a = Lane3::gather(vel, &batch.a);
            let mut b = Lane3::gather(vel, &batch.b);
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
                _ => solve_batch::<4>(data, inv, a_, b_),
            }
            a.scatter(vel, &batch.a);
            b.scatter(vel, &batch.b);
        }
    }
}
