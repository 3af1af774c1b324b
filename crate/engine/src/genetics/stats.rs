//! Summary statistics of a surviving population's fitness, reported after each `tell`.

use crate::quantiles::quantile;
use serde::{Deserialize, Serialize};

/// Fitness summary of the population that survived one generation. Quartiles use linear
/// interpolation between order statistics (numpy's default). NaN fitness counts as -inf;
/// non-finite values serialize to JSON as `null`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct GenerationStats {
    /// The generation just told (0 for the initial population).
    pub generation: u32,
    /// Evaluations done so far, this generation included.
    pub evaluations: u64,
    /// Highest fitness.
    pub best: f64,
    /// Upper quartile.
    pub(crate) q3: f64,
    /// Median.
    pub(crate) median: f64,
    /// Lower quartile.
    pub(crate) q1: f64,
    /// Lowest fitness.
    pub worst: f64,
}

impl GenerationStats {
    /// Summarises `fitness` (any order; NaN already mapped to -inf by the caller).
    pub(crate) fn of(generation: u32, evaluations: u64, fitness: &[f64]) -> Self {
        let mut sorted = fitness.to_vec();
        sorted.sort_by(|a, b| a.total_cmp(b));
        Self {
            generation,
            evaluations,
            best: quantile(&sorted, 1.0),
            q3: quantile(&sorted, 0.75),
            median: quantile(&sorted, 0.5),
            q1: quantile(&sorted, 0.25),
            worst: quantile(&sorted, 0.0),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quartiles_interpolate_like_numpy() {
        let s = GenerationStats::of(3, 700, &[4.0, 1.0, 3.0, 2.0, 5.0]);
        assert_eq!(
            (s.worst, s.q1, s.median, s.q3, s.best),
            (1.0, 2.0, 3.0, 4.0, 5.0)
        );
        let s = GenerationStats::of(0, 4, &[1.0, 2.0, 3.0, 4.0]);
        assert_eq!((s.q1, s.median, s.q3), (1.75, 2.5, 3.25));
        let s = GenerationStats::of(0, 3, &[f64::NEG_INFINITY, 1.0, 2.0]);
        assert_eq!((s.q1, s.median), (f64::NEG_INFINITY, 1.0));
    }
}
