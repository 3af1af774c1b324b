//! A campaign's best modules for `pretrained/`: one per shape, controller and fine-tuning
//! source, each with its provenance (the command that made it, the campaign, the code
//! version) and the figures a replay must reproduce.
//!
//! Choice: among the finished runs of a category (every seed and budget), the one whose
//! best has the highest median velocity on the `paper` validation set (ties: the first in
//! plan order). The `unseen` set is not used to choose, so its figure stays an unbiased
//! estimate of how the chosen module walks on terrains it has never met. A body-search
//! campaign's best bodies with their brains go beside them (`bodies`); an `[[any_body]]`
//! group's brains for any body are chosen by their training-set median (`any_body`).

pub mod any_body;
pub mod bodies;
mod provenance;

pub use provenance::{Origin, Provenance, RunFigures};

use super::plan::RunSpec;
use super::results::{Results, RunData};
use serde::{Deserialize, Serialize};
use vsr::controllers::ControllerKind;
use vsr::experiment::{Validation, ValidationSet};

/// The manifest's format name.
pub const FORMAT: &str = "vsr-pretrained";

/// The manifest's format version (2: both validation sets, provenance of a campaign).
pub const VERSION: u32 = 2;

/// One validation set's figures of a module.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SetFigures {
    /// Velocity on each terrain of the set, in terrain order (m/s).
    pub velocities: Vec<f64>,
    /// Their median.
    pub median: f64,
    /// Their mean (the paper's re-assessment figure).
    pub mean: f64,
}

impl From<&Validation> for SetFigures {
    fn from(v: &Validation) -> Self {
        SetFigures {
            velocities: v.terrains.iter().map(|t| t.velocity).collect(),
            median: v.median,
            mean: v.mean,
        }
    }
}

/// One module of the manifest.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Entry {
    /// Its run file in the pretrained folder.
    pub file: String,
    /// The shape's name in the campaign (e.g. `biped-4x3`).
    pub shape: String,
    /// The shape's rows (the run file's).
    pub rows: String,
    /// Controller family.
    pub controller: ControllerKind,
    /// For a fine-tuned module: the shape its attention module was evolved on.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub finetuned_from: Option<String>,
    /// For a brain for any body: how many bodies it was trained on (`shape` then names the
    /// training set, `rows` its first body).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bodies: Option<usize>,
    /// For a brain for any body: its group, training set and figures on every body set
    /// (its `validation` is empty: it has no one body).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub any_body: Option<any_body::AnyBodyRecord>,
    /// Where it came from, and the figures a replay must reproduce.
    #[serde(flatten)]
    pub provenance: Provenance,
}

/// The pretrained folder's `manifest.json`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Manifest {
    /// [`FORMAT`].
    pub format: String,
    /// [`VERSION`].
    pub version: u32,
    /// How the modules were chosen (the module doc's rule, in words).
    pub selection: String,
    /// The modules, in plan order of their categories.
    pub modules: Vec<Entry>,
    /// The best bodies of body searches with their brains (`bodies/`), in campaign order.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub bodies: Vec<bodies::BodyEntry>,
}

/// A category of modules: shape, controller, fine-tuning source.
pub type Category = (String, ControllerKind, Option<String>);

/// The category of run `spec`.
pub fn category(spec: &RunSpec) -> Category {
    let source = spec.source.as_ref().map(|s| s.shape.clone());
    (spec.shape.clone(), spec.controller, source)
}

/// A category's file name: `SHAPE-CONTROLLER.json`, or `SOURCE-CONTROLLER-to-SHAPE.json`
/// when fine-tuned (no seed or budget: the name stays when a better run is chosen later).
pub fn file_name((shape, controller, source): &Category) -> String {
    match source {
        None => format!("{shape}-{controller}.json"),
        Some(from) => format!("{from}-{controller}-to-{shape}.json"),
    }
}

/// A chosen module: its run and what it was chosen from.
#[derive(Debug, Clone)]
pub struct Choice {
    /// The chosen run.
    pub spec: RunSpec,
    /// Its outputs (run file and both validations present).
    pub data: RunData,
    /// Finished, validated runs of its category.
    pub candidates: usize,
}

/// Every category of `controllers` in `results` (plan order): its chosen run, or `None`
/// while no run of it is finished and validated on both sets.
pub fn choose(
    results: &Results,
    controllers: &[ControllerKind],
) -> Vec<(Category, Option<Choice>)> {
    let mut out: Vec<(Category, Option<Choice>)> = Vec::new();
    for (spec, data) in &results.data {
        if !controllers.contains(&spec.controller) {
            continue;
        }
        let cat = category(spec);
        let at = match out.iter().position(|(c, _)| *c == cat) {
            Some(at) => at,
            None => {
                out.push((cat, None));
                out.len() - 1
            }
        };
        if !data.complete() {
            continue;
        }
        // A NaN median (a run that fell apart) never wins.
        let score = |d: &RunData| {
            let m = d.validation[&ValidationSet::Paper].median;
            if m.is_nan() {
                f64::NEG_INFINITY
            } else {
                m
            }
        };
        let slot = &mut out[at].1;
        let candidates = slot.as_ref().map_or(0, |c| c.candidates) + 1;
        let better = slot.as_ref().map_or(true, |c| score(data) > score(&c.data));
        if better {
            *slot = Some(Choice {
                spec: spec.clone(),
                data: data.clone(),
                candidates,
            });
        } else if let Some(c) = slot.as_mut() {
            c.candidates = candidates;
        }
    }
    out
}

/// The manifest entry of `choice`, exported by `origin`; `None` if its run file is absent.
pub fn entry(choice: &Choice, origin: Origin) -> Option<Entry> {
    let run = choice.data.run.as_ref()?;
    let figures = RunFigures {
        seed: choice.spec.seed,
        budget: choice.spec.evals,
        evaluations: run.generations.last().map_or(0, |g| g.evaluations),
        training_best: run.best.fitness,
        wall_seconds: run.timing.as_ref().map(|t| t.wall_seconds),
    };
    Some(Entry {
        file: file_name(&category(&choice.spec)),
        shape: choice.spec.shape.clone(),
        rows: run.best.shape.to_rows(),
        controller: choice.spec.controller,
        finetuned_from: choice.spec.source.as_ref().map(|s| s.shape.clone()),
        bodies: None,
        any_body: None,
        provenance: Provenance::new(figures, &choice.data.validation, choice.candidates, origin),
    })
}

impl Manifest {
    /// A manifest of `modules`.
    pub fn new(modules: Vec<Entry>) -> Self {
        Manifest {
            format: FORMAT.to_string(),
            version: VERSION,
            selection: "per shape, controller and fine-tuning source: the finished run whose \
                        best has the highest median velocity on the paper validation set; the \
                        unseen set is not used to choose"
                .to_string(),
            modules,
            bodies: Vec::new(),
        }
    }

    /// A Markdown table of the modules (for the folder's README).
    pub fn table(&self) -> String {
        let mut md = String::from(
            "| file | shape | controller | seed | evaluations | training best | paper median | \
             unseen median | chosen from (validated runs) |\n|---|---|---|---|---|---|---|---|---|\n",
        );
        for m in self.modules.iter().filter(|m| m.any_body.is_none()) {
            let median = |set| {
                m.provenance
                    .validation
                    .get(&set)
                    .map_or(f64::NAN, |f| f.median)
            };
            let controller = match &m.finetuned_from {
                None => m.controller.to_string(),
                Some(from) => format!("{} fine-tuned from {from}", m.controller),
            };
            md += &format!(
                "| {} | {} | {} | {} | {} | {:.2} | {:.2} | {:.2} | {} |\n",
                m.file,
                m.shape,
                controller,
                m.provenance.seed,
                m.provenance.evaluations,
                m.provenance.training_best,
                median(ValidationSet::Paper),
                median(ValidationSet::Unseen),
                match m.provenance.chosen_from {
                    1 => "1 run".to_string(),
                    n => format!("{n} runs"),
                }
            );
        }
        md
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn file_names_name_the_category_not_the_seed() {
        let scratch = ("biped-4x3".to_string(), ControllerKind::Mlp, None);
        assert_eq!(file_name(&scratch), "biped-4x3-mlp.json");
        let tuned = (
            "comb-14x2".to_string(),
            ControllerKind::Attention,
            Some("comb-7x2".to_string()),
        );
        assert_eq!(file_name(&tuned), "comb-7x2-attention-to-comb-14x2.json");
    }
}
