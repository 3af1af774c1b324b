//! The samples the report compares: the runs of one label (a controller, fine-tuned or from
//! scratch) on one shape and budget, gathered from the results, and their measures.

use crate::campaign::file::{EvolveGroup, FinetuneGroup};
use crate::campaign::{Results, RunData, RunSpec};
use vsr::experiment::ValidationSet;

/// A labelled sample of runs.
#[derive(Clone)]
pub(super) struct Sample {
    pub(super) label: String,
    pub(super) runs: Vec<RunData>,
}

/// The samples of an evolve group on one shape and budget: one per controller, with the runs
/// whose file exists.
pub(super) fn samples_of(
    results: &Results,
    g: &EvolveGroup,
    shape: &str,
    evals: u64,
) -> Vec<Sample> {
    let seeds = g.seeds.as_ref().unwrap_or(&results.campaign.seeds);
    g.controllers
        .iter()
        .map(|&c| Sample {
            label: c.to_string(),
            runs: results.seeds_of(&RunSpec::scratch(shape, c, evals, 0), seeds),
        })
        .collect()
}

/// The measures of a sample: `best`, then the validation mean of each set.
pub(super) fn measures(s: &Sample, sets: &[ValidationSet]) -> Vec<(String, Vec<f64>)> {
    let mut m = vec![(
        "best".to_string(),
        s.runs.iter().filter_map(RunData::final_best).collect(),
    )];
    for &set in sets {
        let values = s.runs.iter().filter_map(|d| d.validation_mean(set));
        m.push((format!("{set} mean"), values.collect()));
    }
    m
}

/// The label of a transfer in tables ("SOURCE -> TARGET").
pub(super) fn transfer(pair: &[String; 2]) -> String {
    format!("{} -> {}", pair[0], pair[1])
}

/// The samples of a transfer: fine-tuned, then from scratch on the target (when planned).
pub(super) fn finetune_samples(
    results: &Results,
    g: &FinetuneGroup,
    pair: &[String; 2],
) -> Vec<Sample> {
    let seeds = g.seeds.as_ref().unwrap_or(&results.campaign.seeds);
    let [from, to] = pair;
    let source = RunSpec::scratch(from, g.controller, g.source_evals, 0);
    let tuned = RunSpec::finetuned(source, to, g.evals);
    let mut samples = vec![Sample {
        label: format!("fine-tuned from {from} ({} + {})", g.source_evals, g.evals),
        runs: results.seeds_of(&tuned, seeds),
    }];
    if let Some(evals) = g.scratch_evals {
        samples.push(Sample {
            label: format!("from scratch ({evals})"),
            runs: results.seeds_of(&RunSpec::scratch(to, g.controller, evals, 0), seeds),
        });
    }
    samples
}
