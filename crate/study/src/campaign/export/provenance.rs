//! What every record of the pretrained manifest (a module, a body) says of the run it was
//! taken from: where it came from and the figures a replay must reproduce.

use super::SetFigures;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use vsr::experiment::{Validation, ValidationSet};

/// What every record of the manifest (a module, a body) says of the run it was taken from:
/// where it came from and the figures a replay must reproduce.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Provenance {
    /// Run seed.
    pub seed: u64,
    /// The run's evaluation budget (`--evals`).
    pub budget: u64,
    /// Evaluations the run made.
    pub evaluations: u64,
    /// The exported best's training fitness (m/s).
    pub training_best: f64,
    /// Its validation figures, by set.
    pub validation: BTreeMap<ValidationSet, SetFigures>,
    /// Runs of its category it was chosen from (finished and validated on both sets).
    pub chosen_from: usize,
    /// The command that made the run file (from the campaign's plan).
    pub command: String,
    /// The campaign file the run belongs to.
    pub campaign: String,
    /// The code that exported it (and replays it: tests/pretrained.rs).
    pub code_version: String,
    /// The run's wall time, if it recorded it (s).
    #[serde(default)]
    pub wall_seconds: Option<f64>,
}

/// Who exported a record: the command that made its run, the campaign, the code version.
#[derive(Debug, Clone, Copy)]
pub struct Origin<'a> {
    /// The command that made the run file.
    pub command: &'a str,
    /// The campaign file.
    pub campaign: &'a str,
    /// The exporting code's version.
    pub code_version: &'a str,
}

/// What a run says of itself for its provenance.
#[derive(Debug, Clone, Copy)]
pub struct RunFigures {
    /// Run seed.
    pub seed: u64,
    /// Evaluation budget.
    pub budget: u64,
    /// Evaluations made.
    pub evaluations: u64,
    /// The exported best's training fitness (m/s).
    pub training_best: f64,
    /// Wall time, if recorded (s).
    pub wall_seconds: Option<f64>,
}

impl Provenance {
    /// The provenance of a run's best (`run`), validated as `validation`, chosen from
    /// `chosen_from` runs, exported by `origin`.
    pub fn new(
        run: RunFigures,
        validation: &BTreeMap<ValidationSet, Validation>,
        chosen_from: usize,
        origin: Origin,
    ) -> Self {
        Provenance {
            seed: run.seed,
            budget: run.budget,
            evaluations: run.evaluations,
            training_best: run.training_best,
            validation: validation
                .iter()
                .map(|(set, v)| (*set, SetFigures::from(v)))
                .collect(),
            chosen_from,
            command: origin.command.to_string(),
            campaign: origin.campaign.to_string(),
            code_version: origin.code_version.to_string(),
            wall_seconds: run.wall_seconds,
        }
    }
}
