//! The campaign file's groups of runs: grids from scratch (with their planned
//! non-inferiority test), fine-tuning pairs and fidelity references. Parsed by `file`.

use serde::Deserialize;
use vsr::controllers::ControllerKind;
use vsr::experiment::ValidationSet;

/// A grid of runs from scratch: shapes x controllers x evals x seeds.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EvolveGroup {
    /// The group's name (titles of its figures and tables).
    pub name: String,
    /// Shapes: presets or rows.
    pub shapes: Vec<String>,
    /// Controller families.
    pub controllers: Vec<ControllerKind>,
    /// Evaluation budgets.
    pub evals: Vec<u64>,
    /// Seeds (default: the campaign's).
    #[serde(default)]
    pub seeds: Option<Vec<u64>>,
    /// Ablate every best individual that has attention.
    #[serde(default)]
    pub ablate: bool,
    /// Shorter budgets to read the same runs at (reported beside the group, not run): a run
    /// from scratch with the same shape, controller and seed and a shorter budget is the
    /// longer run's start, so its files say where the longer run stood then.
    #[serde(default)]
    pub earlier: Vec<u64>,
    /// A planned non-inferiority test between two of the group's controllers (reported, not
    /// run: it adds no job).
    #[serde(default)]
    pub noninferiority: Option<NonInferiority>,
}

/// A non-inferiority test (docs/ANALYSIS-PLAN.md, family 8): on every shape and budget of
/// the group, is `treatment` not worse than `control` by `margin` m/s or more? One family of
/// tests (Holm over the shapes) per validation set in `sets`, the first the primary.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NonInferiority {
    /// The largest loss (m/s) that still counts as "not worse".
    pub margin: f64,
    /// The controller the claim is about.
    pub treatment: ControllerKind,
    /// The controller it is compared with.
    pub control: ControllerKind,
    /// The measures: each set's validation mean, the first primary (default: unseen, then
    /// paper).
    #[serde(default = "unseen_then_paper")]
    pub sets: Vec<ValidationSet>,
    /// Seeds known before the test was planned (runs of the same grid that exist): shown
    /// beside the test, never pooled with the group's seeds.
    #[serde(default)]
    pub known_seeds: Vec<u64>,
}

fn unseen_then_paper() -> Vec<ValidationSet> {
    vec![ValidationSet::Unseen, ValidationSet::Paper]
}

/// Fine-tuning: for every pair and seed, a source run on the pair's first shape, its best
/// fine-tuned on the second, and a from-scratch run on the second for comparison.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FinetuneGroup {
    /// The group's name.
    pub name: String,
    /// `[source shape, target shape]` pairs.
    pub pairs: Vec<[String; 2]>,
    /// Controller of the source runs (attention or slow-attention).
    pub controller: ControllerKind,
    /// Budget of each source run.
    pub source_evals: u64,
    /// Budget of each fine-tuning run.
    pub evals: u64,
    /// Budget of the from-scratch comparison runs on the target shapes (none when absent).
    #[serde(default)]
    pub scratch_evals: Option<u64>,
    /// Seeds (default: the campaign's).
    #[serde(default)]
    pub seeds: Option<Vec<u64>>,
}

/// A reference file of gait ensembles (`study::fidelity`) to measure this simulator against.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FidelityGroup {
    /// The reference file, relative to the campaign file (after [`Campaign::relative_to`],
    /// to the working folder).
    pub reference: String,
}
