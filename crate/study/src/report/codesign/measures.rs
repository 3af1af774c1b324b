//! The measures of a body search (docs/ANALYSIS-PLAN.md, families 9 and 10), per run and per
//! condition: the final best body's mean velocity on a validation set (the best is the
//! archive's elite with the highest mean training fitness), the archive's QD-score (the sum
//! of the elites' positive mean training speeds) and coverage (filled cells) at the end, the
//! best's training fitness, and the best and the QD-score against evaluations.

use crate::campaign::results::{CodesignData, CodesignSpec};
use crate::campaign::{CodesignGroup, Results};
use vsr::experiment::{CodesignRun, ValidationSet};

/// A measure of a finished body search.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Measure {
    /// The best body's mean velocity on a validation set (m/s).
    Velocity(ValidationSet),
    /// The archive's QD-score at the end (m/s summed over the filled cells).
    QdScore,
    /// Filled archive cells at the end.
    Coverage,
    /// The best's mean training fitness (m/s).
    Best,
}

impl Measure {
    /// Its name in tables.
    pub(crate) fn name(self) -> String {
        match self {
            Measure::Velocity(set) => format!("{set} mean"),
            Measure::QdScore => "QD-score".into(),
            Measure::Coverage => "coverage".into(),
            Measure::Best => "best (training)".into(),
        }
    }

    /// Its value for one run, if the run and what the measure needs exist.
    pub(crate) fn of(self, d: &CodesignData) -> Option<f64> {
        let run = d.run.as_ref()?;
        match self {
            Measure::Velocity(set) => d.validation_mean(set),
            Measure::QdScore => Some(qd_score(run)),
            Measure::Coverage => Some(run.archive.len() as f64),
            Measure::Best => run.history.last().map(|h| h.best),
        }
    }
}

/// The QD-score of a run's final archive: the sum of its elites' positive mean fitness.
pub(crate) fn qd_score(run: &CodesignRun) -> f64 {
    run.archive.iter().map(|e| e.fitness.max(0.0)).sum()
}

/// The archive's cells: voxel-count bins times feet bins (36 with the defaults).
pub(crate) fn cells(run: &CodesignRun) -> usize {
    let c = &run.config;
    ((c.max_voxels - c.min_voxels) / c.size_bin + 1) * c.max_feet
}

/// One condition of a group: its planned seeds and the runs of those that finished.
#[derive(Clone)]
pub(crate) struct Condition<'a> {
    /// Its name (`frozen`, `finetune`, `scratch-CONTROLLER`).
    pub(crate) name: String,
    /// Seeds planned.
    pub(crate) planned: usize,
    /// Every planned run, finished or not, in seed order.
    pub(crate) all: Vec<(&'a CodesignSpec, &'a CodesignData)>,
}

impl<'a> Condition<'a> {
    /// The finished runs (run file present), in seed order.
    pub(crate) fn finished(
        &self,
    ) -> impl Iterator<Item = (&'a CodesignSpec, &'a CodesignData)> + '_ {
        self.all.iter().copied().filter(|(_, d)| d.run.is_some())
    }

    /// The values of `m` over the runs that have it, in seed order.
    pub(crate) fn values(&self, m: Measure) -> Vec<f64> {
        self.all.iter().filter_map(|(_, d)| m.of(d)).collect()
    }
}

/// The conditions of group `g`, in the campaign's order.
pub(crate) fn conditions<'a>(results: &'a Results, g: &CodesignGroup) -> Vec<Condition<'a>> {
    g.conditions
        .iter()
        .map(|c| {
            let all: Vec<_> = results
                .codesign
                .iter()
                .filter(|(s, _)| s.group == g.name && &s.condition == c)
                .map(|(s, d)| (s, d))
                .collect();
            Condition {
                name: c.clone(),
                planned: all.len(),
                all,
            }
        })
        .collect()
}

/// A record's value against evaluations: the best (`qd` false) or the QD-score (`qd` true).
/// Each run's history read every `step` evaluations (the value of the last iteration done by
/// then), from the first x every run has reached to the last x every run has reached, so that
/// point i of every series is the same number of evaluations.
pub(crate) fn series(runs: &[&CodesignRun], step: u64, qd: bool) -> Vec<Vec<(f64, f64)>> {
    let first = runs
        .iter()
        .filter_map(|r| r.history.first().map(|h| h.evaluations))
        .max();
    let last = runs
        .iter()
        .filter_map(|r| r.history.last().map(|h| h.evaluations))
        .min();
    let (Some(first), Some(last)) = (first, last) else {
        return Vec::new();
    };
    let step = step.max(1);
    let start = first.div_ceil(step) * step;
    let xs: Vec<u64> = (start..=last).step_by(step as usize).collect();
    runs.iter()
        .map(|r| {
            xs.iter()
                .filter_map(|&x| {
                    let done = r.history.iter().take_while(|h| h.evaluations <= x).last()?;
                    let y = if qd { done.qd_score } else { done.best };
                    Some((x as f64, y))
                })
                .collect()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_of_the_measures() {
        assert_eq!(
            Measure::Velocity(ValidationSet::Unseen).name(),
            "unseen mean"
        );
        assert_eq!(Measure::QdScore.name(), "QD-score");
    }
}
