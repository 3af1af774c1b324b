//! The series the report's line figures are drawn from, one per run: best fitness, the
//! frozen-attention ablation and its unfrozen reference, slow attention's alpha and eta.

use crate::campaign::RunData;
use vsr::experiment::ValidationSet;

/// Best fitness against evaluations of each run, x shifted by `offset` evaluations.
pub fn best_series(runs: &[RunData], offset: f64) -> Vec<Vec<(f64, f64)>> {
    runs.iter()
        .filter_map(|d| d.run.as_ref())
        .map(|r| {
            let points = r.generations.iter();
            points
                .map(|g| (offset + g.evaluations as f64, g.best))
                .collect()
        })
        .collect()
}

/// Velocity against freeze second of each run's ablation on `set`.
pub fn ablation_series(runs: &[RunData], set: ValidationSet) -> Vec<Vec<(f64, f64)>> {
    runs.iter()
        .filter_map(|d| d.ablation.get(&set))
        .map(|a| {
            let points = a.iter();
            points
                .map(|p| (f64::from(p.freeze_second), p.velocity))
                .collect()
        })
        .collect()
}

/// The unfrozen reference of each run with an ablation on `set`, as a flat series over the
/// same freeze seconds.
pub fn unfrozen_series(runs: &[RunData], set: ValidationSet) -> Vec<Vec<(f64, f64)>> {
    runs.iter()
        .filter_map(|d| Some((d.ablation.get(&set)?, d.unfrozen(set)?)))
        .map(|(a, v)| a.iter().map(|p| (f64::from(p.freeze_second), v)).collect())
        .collect()
}

/// alpha (`eta` false) or eta (`eta` true) of each generation's best, against evaluations,
/// for runs that recorded them.
pub fn rate_series(runs: &[RunData], eta: bool) -> Vec<Vec<(f64, f64)>> {
    runs.iter()
        .filter_map(|d| d.run.as_ref())
        .map(|r| {
            let rate = |g: &vsr::experiment::GenerationRecord| if eta { g.eta } else { g.alpha };
            let points = r.generations.iter();
            points
                .filter_map(|g| rate(g).map(|v| (g.evaluations as f64, f64::from(v))))
                .collect::<Vec<_>>()
        })
        .filter(|s| !s.is_empty())
        .collect()
}
