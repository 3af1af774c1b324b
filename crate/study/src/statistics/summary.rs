//! The summary of a small sample: median, quartiles, extremes, mean and standard deviation
//! (its quantiles are the engine's `vsr::quantiles`, as the GA's generation statistics).

use serde::Serialize;
use vsr::quantiles::{median, quantile};

/// The summary of one sample; every field is NaN for an empty sample.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Summary {
    /// Sample size.
    pub n: usize,
    /// Smallest value.
    pub min: f64,
    /// Lower quartile.
    pub q1: f64,
    /// Median.
    pub median: f64,
    /// Upper quartile.
    pub q3: f64,
    /// Largest value.
    pub max: f64,
    /// Arithmetic mean.
    pub mean: f64,
    /// Sample standard deviation (n - 1 in the denominator; 0 for one value).
    pub sd: f64,
}

impl Summary {
    /// Summarises `values` (any order; NaN values are dropped).
    pub fn of(values: &[f64]) -> Summary {
        let mut sorted: Vec<f64> = values.iter().copied().filter(|v| !v.is_nan()).collect();
        sorted.sort_by(f64::total_cmp);
        let n = sorted.len();
        let mean = sorted.iter().sum::<f64>() / n as f64;
        let squares: f64 = sorted.iter().map(|v| (v - mean) * (v - mean)).sum();
        let sd = match n {
            0 => f64::NAN,
            1 => 0.0,
            _ => (squares / (n - 1) as f64).sqrt(),
        };
        Summary {
            n,
            min: quantile(&sorted, 0.0),
            q1: quantile(&sorted, 0.25),
            median: median(&sorted),
            q3: quantile(&sorted, 0.75),
            max: quantile(&sorted, 1.0),
            mean,
            sd,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn summary_of_a_known_sample() {
        let s = Summary::of(&[4.0, 1.0, 3.0, 2.0, 5.0]);
        assert_eq!((s.n, s.min, s.q1, s.median), (5, 1.0, 2.0, 3.0));
        assert_eq!((s.q3, s.max, s.mean), (4.0, 5.0, 3.0));
        assert!((s.sd - 2.5f64.sqrt()).abs() < 1e-12);
    }

    #[test]
    fn empty_and_nan_samples() {
        let s = Summary::of(&[f64::NAN]);
        assert_eq!(s.n, 0);
        assert!(s.median.is_nan() && s.sd.is_nan());
        assert_eq!(Summary::of(&[2.0]).sd, 0.0);
    }
}
