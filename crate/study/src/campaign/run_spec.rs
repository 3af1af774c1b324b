//! The identity of one evolutionary run of a campaign, and where its outputs go (the
//! folder layout is `plan`'s module doc).

use std::path::{Path, PathBuf};
use vsr::controllers::ControllerKind;
use vsr::experiment::ValidationSet;

/// The identity of one evolutionary run of a campaign.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct RunSpec {
    /// The shape as the campaign names it.
    pub shape: String,
    /// Controller family.
    pub controller: ControllerKind,
    /// Evaluation budget.
    pub evals: u64,
    /// Run seed.
    pub seed: u64,
    /// For fine-tuning: the run whose best lends its attention block.
    pub source: Option<Box<RunSpec>>,
}

impl RunSpec {
    /// A run from scratch.
    pub fn scratch(shape: &str, controller: ControllerKind, evals: u64, seed: u64) -> Self {
        RunSpec {
            shape: shape.to_string(),
            controller,
            evals,
            seed,
            source: None,
        }
    }

    /// A fine-tuning of `source`'s best on `shape`, with the source's controller and seed.
    pub fn finetuned(source: RunSpec, shape: &str, evals: u64) -> Self {
        RunSpec {
            source: Some(Box::new(source.clone())),
            ..RunSpec::scratch(shape, source.controller, evals, source.seed)
        }
    }

    /// The file stem of its outputs; see the module doc.
    pub fn stem(&self) -> String {
        let tail = format!("{}-s{}", self.evals, self.seed);
        match &self.source {
            None => format!("{}-{}-{tail}", self.shape, self.controller),
            Some(s) => format!(
                "{}-{}-{}-to-{}-{tail}",
                s.shape, s.controller, s.evals, self.shape
            ),
        }
    }

    /// Its run file under `out`.
    pub fn run_path(&self, out: &Path) -> PathBuf {
        out.join("runs").join(format!("{}.json", self.stem()))
    }

    /// Its validation file on `set` under `out`.
    pub fn validation_path(&self, out: &Path, set: ValidationSet) -> PathBuf {
        out.join("validation")
            .join(format!("{}.{set}.json", self.stem()))
    }

    /// Its ablation file on `set`'s first terrain under `out` (`STEM.json` on the paper
    /// set, as before there were two; `STEM.SET.json` on another).
    pub fn ablation_path(&self, out: &Path, set: ValidationSet) -> PathBuf {
        let name = match set {
            ValidationSet::Paper => format!("{}.json", self.stem()),
            other => format!("{}.{other}.json", self.stem()),
        };
        out.join("ablation").join(name)
    }

    /// True for controllers whose attention can be frozen.
    pub fn has_attention(&self) -> bool {
        matches!(
            self.controller,
            ControllerKind::Attention | ControllerKind::SlowAttention
        )
    }
}
