//! The two-sided Wilcoxon signed-rank test of paired samples, by the normal approximation.
//!
//! Differences d = x - y; zero differences are dropped (scipy's `zero_method="wilcox"`); the
//! absolute differences are ranked (ties share their mean rank); W+ is the rank sum of the
//! positive differences. With n non-zero differences, z = (W+ - n (n + 1) / 4) / sigma,
//! sigma^2 = n (n + 1) (2n + 1) / 24 - sum(t^3 - t) / 48, and p = 2 (1 - Phi(|z|)), no
//! continuity correction (scipy's `wilcoxon(x, y, method="approx")`). Meant for the large
//! paired samples of the study (a set of terrains against another over every run).

use super::normal::cdf;
use serde::Serialize;

/// The outcome of one signed-rank test.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SignedRank {
    /// Pairs with a non-zero difference.
    pub n: usize,
    /// Rank sum of the positive differences.
    pub w_plus: f64,
    /// The normal deviate.
    pub z: f64,
    /// Two-sided p-value (NaN without a non-zero difference).
    pub p: f64,
}

/// The signed-rank test of `x` against `y`, paired by index (pairs with a NaN dropped).
pub fn wilcoxon_signed_rank(x: &[f64], y: &[f64]) -> SignedRank {
    let mut d: Vec<f64> = x
        .iter()
        .zip(y)
        .map(|(a, b)| a - b)
        .filter(|v| !v.is_nan() && *v != 0.0)
        .collect();
    d.sort_by(|a, b| a.abs().total_cmp(&b.abs()));
    let n = d.len();
    let (mut w_plus, mut tie_term, mut start) = (0.0, 0.0, 0);
    while start < n {
        let end = start
            + d[start..]
                .iter()
                .take_while(|v| v.abs() == d[start].abs())
                .count();
        let rank = (start + 1 + end) as f64 / 2.0;
        w_plus += rank * d[start..end].iter().filter(|v| **v > 0.0).count() as f64;
        let t = (end - start) as f64;
        tie_term += t * t * t - t;
        start = end;
    }
    let nf = n as f64;
    let variance = nf * (nf + 1.0) * (2.0 * nf + 1.0) / 24.0 - tie_term / 48.0;
    let z = (w_plus - nf * (nf + 1.0) / 4.0) / variance.sqrt();
    let p = if n == 0 {
        f64::NAN
    } else {
        (2.0 * (1.0 - cdf(z.abs()))).min(1.0)
    };
    SignedRank { n, w_plus, z, p }
}
