//! Intervals and power by resampling, each from a fixed seed so that a report is the same
//! every time it is written.
//!
//! - [`a12_interval`]: the percentile bootstrap interval of Vargha-Delaney's A12 (each
//!   sample resampled with replacement within itself).
//! - [`detectable_a12`]: the smallest effect the exact two-sided Mann-Whitney test at
//!   alpha detects with the given power for samples of n1 and n2, under a normal location
//!   shift (Monte Carlo), stated as A12 = Phi(delta / sqrt 2) and as delta in standard
//!   deviations.

use super::mann_whitney::mann_whitney;
use super::order_ci::Interval;
use rand::Rng;
use serde::Serialize;
use vsr::quantiles::quantile;
use vsr::random::{rng_from, standard_normal};

/// Bootstrap resamples of [`a12_interval`].
pub const BOOTSTRAP_RESAMPLES: usize = 10_000;
/// Monte Carlo samples per shift of [`detectable_a12`].
pub const POWER_SAMPLES: usize = 2_000;
/// The seed of every resampling here.
const SEED: u64 = 2022;

/// A12 = P(X > Y) + P(X = Y) / 2 of two samples, by counting pairs.
fn a12(x: &[f64], y: &[f64]) -> f64 {
    let wins: f64 = x
        .iter()
        .flat_map(|a| {
            y.iter()
                .map(move |b| (a > b) as u8 as f64 + 0.5 * (a == b) as u8 as f64)
        })
        .sum();
    wins / (x.len() * y.len()) as f64
}

/// The percentile bootstrap 1 - `alpha` interval of A12 of `x` against `y`; None when a
/// sample is empty.
pub fn a12_interval(x: &[f64], y: &[f64], alpha: f64) -> Option<Interval> {
    if x.is_empty() || y.is_empty() {
        return None;
    }
    let mut rng = rng_from(SEED);
    let mut draw =
        |s: &[f64]| -> Vec<f64> { (0..s.len()).map(|_| s[rng.gen_range(0..s.len())]).collect() };
    let mut values: Vec<f64> = (0..BOOTSTRAP_RESAMPLES)
        .map(|_| {
            let (bx, by) = (draw(x), draw(y));
            a12(&bx, &by)
        })
        .collect();
    values.sort_by(f64::total_cmp);
    Some(Interval {
        low: quantile(&values, alpha / 2.0),
        high: quantile(&values, 1.0 - alpha / 2.0),
        coverage: 1.0 - alpha,
    })
}

/// The smallest detectable effect of a test; see the module doc.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Detectable {
    /// As A12 (above 0.5).
    pub a12: f64,
    /// As a shift in standard deviations of normal samples.
    pub delta: f64,
    /// The smallest p-value the sample sizes allow.
    pub smallest_p: f64,
}

/// The smallest normal shift whose power reaches `power` for samples of `n1` and `n2` at
/// two-sided `alpha` (bisection over delta in 0..10, to 0.01).
pub fn detectable_a12(n1: usize, n2: usize, alpha: f64, power: f64) -> Detectable {
    let low: Vec<f64> = (0..n1).map(|i| i as f64).collect();
    let high: Vec<f64> = (0..n2).map(|i| (n1 + i) as f64).collect();
    let smallest_p = mann_whitney(&high, &low).p;
    let power_at = |delta: f64| -> f64 {
        let mut rng = rng_from(SEED);
        let hits = (0..POWER_SAMPLES)
            .filter(|_| {
                let x: Vec<f64> = (0..n1).map(|_| standard_normal(&mut rng) + delta).collect();
                let y: Vec<f64> = (0..n2).map(|_| standard_normal(&mut rng)).collect();
                mann_whitney(&x, &y).p < alpha
            })
            .count();
        hits as f64 / POWER_SAMPLES as f64
    };
    let (mut lo, mut hi) = (0.0f64, 10.0f64);
    while hi - lo > 0.01 {
        let mid = 0.5 * (lo + hi);
        if power_at(mid) >= power {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Detectable {
        a12: super::normal::cdf(hi / std::f64::consts::SQRT_2),
        delta: hi,
        smallest_p,
    }
}
