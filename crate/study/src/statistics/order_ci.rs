//! Distribution-free confidence intervals from order statistics.
//!
//! For the median of n values: the interval [x(k), x(n - k + 1)] covers the population
//! median with probability 1 - 2 P(B <= k - 1), B ~ Binomial(n, 1/2) (the sign test's
//! interval); k is the largest with that coverage at least 1 - alpha. Used for the median of
//! per-run slopes (the plateau) and of paired differences.

use serde::Serialize;

/// A confidence interval and its exact coverage.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Interval {
    /// Lower end.
    pub low: f64,
    /// Upper end.
    pub high: f64,
    /// The interval's exact coverage (at least the nominal level, unless the samples are
    /// too small for it, then the largest available: the whole range).
    pub coverage: f64,
}

/// The number k of order statistics to cut from each end, given the null distribution
/// `counts` of a statistic symmetric on 0 ..= counts.len() - 1 (counts, not probabilities):
/// the largest k >= 1 with 2 P(S <= k - 1) <= alpha (k = 1 when none is), and the coverage
/// 1 - 2 P(S <= k - 1).
pub(crate) fn cut_from_counts(counts: &[f64], alpha: f64) -> (usize, f64) {
    let total: f64 = counts.iter().sum();
    let cdf = |v: usize| counts[..=v].iter().sum::<f64>() / total;
    let last = (0..counts.len())
        .take_while(|&v| 2.0 * cdf(v) <= alpha)
        .last();
    let k = last.map_or(1, |v| v + 1);
    (k, 1.0 - 2.0 * cdf(k - 1))
}

/// The distribution-free 1 - `alpha` interval of the median of `values` (NaN dropped);
/// None when there is no value.
pub fn median_interval(values: &[f64], alpha: f64) -> Option<Interval> {
    let mut v: Vec<f64> = values.iter().copied().filter(|x| !x.is_nan()).collect();
    if v.is_empty() {
        return None;
    }
    v.sort_by(f64::total_cmp);
    let n = v.len();
    // Binomial(n, 1/2) counts: C(n, j).
    let mut counts = vec![1.0f64; n + 1];
    for j in 1..=n {
        counts[j] = counts[j - 1] * (n + 1 - j) as f64 / j as f64;
    }
    let (k, coverage) = cut_from_counts(&counts, alpha);
    let k = k.min(n.div_ceil(2));
    Some(Interval {
        low: v[k - 1],
        high: v[n - k],
        coverage,
    })
}
