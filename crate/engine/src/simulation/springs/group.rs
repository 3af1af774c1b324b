//! Per step, per group: the Gauss-Seidel transfer T and the rows of
//! A = T diag(-inv_k) J that turn one sweep over a group into lambda = A u + T c
//! (derivation in [`super`]).

// Lane loops index several parallel arrays by lane on purpose.
#![allow(clippy::needless_range_loop)]

use super::batch::{Row, MAX_COUPLING};
use super::lanes::{L, LANES};

/// The coupling m_ji (i < j, row-major) of a group's rows.
#[inline]
fn coupling(rows: &[Row], inv: &[L; 4]) -> [L; MAX_COUPLING] {
    let [ima, iia, imb, iib] = inv;
    let mut m = [[0.0; LANES]; MAX_COUPLING];
    let mut idx = 0;
    for j in 1..rows.len() {
        let rj = &rows[j];
        for ri in &rows[..j] {
            for k in 0..LANES {
                let nn = rj.nx[k] * ri.nx[k] + rj.ny[k] * ri.ny[k];
                let kji = (ima[k] + imb[k]) * nn
                    + iia[k] * rj.rna[k] * ri.rna[k]
                    + iib[k] * rj.rnb[k] * ri.rnb[k];
                m[idx][k] = rj.neg_inv_k[k] * kji;
            }
            idx += 1;
        }
    }
    m
}

/// Builds T (i < j entries, row-major, into `t`) and every row's A from the
/// prepared rows of a group (at most [`super::MAX_ROWS`] rows).
pub(super) fn group_matrices(rows: &mut [Row], inv: &[L; 4], t: &mut [L]) {
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
                    r.neg_inv_k[k]
                } else {
                    r.neg_inv_k[k] * t[at(j, i)][k]
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
