//! The Hodges-Lehmann shift between two samples and its exact confidence interval.
//!
//! The estimate is the median of the n1 n2 pairwise differences x_i - y_j. Its
//! distribution-free interval (Bauer 1972; Hollander and Wolfe, section 4.3) takes the k-th
//! smallest and k-th largest differences, where k is the largest with
//! 2 P(U <= k - 1) <= alpha under the Mann-Whitney null distribution: the set of shifts d for
//! which the test of x - d against y is not rejected. Exact for samples of up to
//! [`EXACT_MAX`] values; larger samples use the normal approximation of U for k.

use super::mann_whitney::{exact_null_counts, EXACT_MAX};
use super::order_ci::{cut_from_counts, Interval};
use serde::Serialize;
use vsr::quantiles::median;

/// The shift estimate of x against y with its interval.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Shift {
    /// Median of the pairwise differences x - y.
    pub estimate: f64,
    /// The 1 - alpha interval (exact coverage given).
    pub interval: Interval,
}

/// The Hodges-Lehmann shift of `x` against `y` at level 1 - `alpha` (NaN dropped); None when
/// a sample is empty.
pub fn hodges_lehmann(x: &[f64], y: &[f64], alpha: f64) -> Option<Shift> {
    let clean = |s: &[f64]| -> Vec<f64> { s.iter().copied().filter(|v| !v.is_nan()).collect() };
    let (x, y) = (clean(x), clean(y));
    let (n1, n2) = (x.len(), y.len());
    if n1 == 0 || n2 == 0 {
        return None;
    }
    let mut d: Vec<f64> = x
        .iter()
        .flat_map(|a| y.iter().map(move |b| a - b))
        .collect();
    d.sort_by(f64::total_cmp);
    let m = d.len();
    let (k, coverage) = if n1 <= EXACT_MAX && n2 <= EXACT_MAX {
        cut_from_counts(&exact_null_counts(n1, n2), alpha)
    } else {
        normal_cut(n1, n2, alpha)
    };
    let k = k.min(m.div_ceil(2));
    Some(Shift {
        estimate: median(&d),
        interval: Interval {
            low: d[k - 1],
            high: d[m - k],
            coverage,
        },
    })
}

/// k from the normal approximation of U (no continuity correction): the largest k with
/// k - 1 <= n1 n2 / 2 - z sigma, and its approximate coverage 1 - alpha.
fn normal_cut(n1: usize, n2: usize, alpha: f64) -> (usize, f64) {
    let (a, b) = (n1 as f64, n2 as f64);
    let sigma = (a * b * (a + b + 1.0) / 12.0).sqrt();
    let z = super::normal::quantile(1.0 - alpha / 2.0);
    let k = (a * b / 2.0 - z * sigma).floor().max(0.0) as usize + 1;
    (k, 1.0 - alpha)
}
