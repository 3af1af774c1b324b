//! A body-search campaign's best bodies with their brains for `pretrained/bodies/`: one per
//! group and condition, each with its provenance (the run file and its archive entry, the
//! command that made it, the campaign, the code version) and the figures a replay must
//! reproduce.
//!
//! Choice, once every planned run of the condition is finished and validated on both sets
//! (so that a body, once exported, is final): the run whose best body has the highest median
//! velocity on the `paper` set (ties: the first seed), as for the modules. The `unseen` set
//! is not used to choose, so its figure stays an unbiased estimate of how the chosen body
//! walks on terrains it has never met.
//!
//! The file written is the run file with its archive cut to that one entry (the best): a
//! co-design run file still, so `vsr evaluate --genome`, `vsr validate` and Python replay it;
//! the whole archive stays in the run file the entry names.

use super::{Origin, Provenance, RunFigures};
use crate::campaign::results::{CodesignData, CodesignSpec, Results};
use serde::{Deserialize, Serialize};
use vsr::controllers::ControllerKind;
use vsr::experiment::{CodesignRun, ValidationSet};

/// One body of the manifest's `bodies`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BodyEntry {
    /// Its file in the pretrained folder (`bodies/GROUP-CONDITION.json`).
    pub file: String,
    /// The campaign's body-search group.
    pub group: String,
    /// The condition (`frozen`, `finetune`, `scratch-CONTROLLER`).
    pub condition: String,
    /// The body in rows notation.
    pub rows: String,
    /// Its voxels.
    pub voxels: usize,
    /// Its feet.
    pub feet: usize,
    /// The brain's controller family.
    pub controller: ControllerKind,
    /// The pretrained module the search started from (`frozen`, `finetune`), as the
    /// campaign names it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub module: Option<String>,
    /// The run file it was taken from.
    pub run_file: String,
    /// Its entry in that file's archive (`vsr validate --entry`).
    pub entry: usize,
    /// Where it came from, and the figures a replay must reproduce.
    #[serde(flatten)]
    pub provenance: Provenance,
}

/// A chosen body: its run and what it was chosen from.
#[derive(Debug, Clone)]
pub struct BodyChoice {
    /// The chosen run.
    pub spec: CodesignSpec,
    /// Its outputs (a finished run file, both validations).
    pub data: CodesignData,
    /// Finished, validated runs of its condition.
    pub candidates: usize,
}

/// A body's file name in the pretrained folder.
pub fn body_file(group: &str, condition: &str) -> String {
    format!("bodies/{group}-{condition}.json")
}

/// A condition's choice: its (group, condition), its chosen run (`None` until every planned
/// run is finished and validated on both sets) and how many of its planned runs are.
#[derive(Debug, Clone)]
pub struct Chosen {
    /// (group, condition).
    pub key: (String, String),
    /// The chosen run.
    pub choice: Option<BodyChoice>,
    /// Planned runs, and those finished and validated on both sets.
    pub runs: (usize, usize),
}

/// Every (group, condition) of `results` in campaign order with its choice.
pub fn choose_bodies(results: &Results) -> Vec<Chosen> {
    let mut out: Vec<Chosen> = Vec::new();
    for (spec, data) in &results.codesign {
        let key = (spec.group.clone(), spec.condition.clone());
        let at = match out.iter().position(|c| c.key == key) {
            Some(at) => at,
            None => {
                out.push(Chosen {
                    key,
                    choice: None,
                    runs: (0, 0),
                });
                out.len() - 1
            }
        };
        out[at].runs.0 += 1;
        if !data.complete() {
            continue;
        }
        out[at].runs.1 += 1;
        let score = |d: &CodesignData| {
            let m = d.validation[&ValidationSet::Paper].median;
            if m.is_nan() {
                f64::NEG_INFINITY
            } else {
                m
            }
        };
        let slot = &mut out[at].choice;
        let candidates = slot.as_ref().map_or(0, |c| c.candidates) + 1;
        if slot.as_ref().map_or(true, |c| score(data) > score(&c.data)) {
            *slot = Some(BodyChoice {
                spec: spec.clone(),
                data: data.clone(),
                candidates,
            });
        } else if let Some(c) = slot.as_mut() {
            c.candidates = candidates;
        }
    }
    for c in &mut out {
        if c.runs.1 < c.runs.0 {
            c.choice = None;
        }
    }
    out
}

/// The index of a run's best in its archive: the entry whose body and genome are the best's.
pub fn best_entry(run: &CodesignRun) -> Option<usize> {
    run.archive
        .iter()
        .position(|e| e.shape == run.best.shape && e.genome == run.best.genome)
}

/// The run file to write for `run`: its archive cut to the best entry.
pub fn trimmed(run: &CodesignRun) -> Option<CodesignRun> {
    let i = best_entry(run)?;
    let mut cut = run.clone();
    cut.archive = vec![run.archive[i].clone()];
    Some(cut)
}

/// The manifest entry of `choice`: its run file `run_file`, with the group's `module`,
/// exported by `origin`; `None` if the run file is absent or its best is not in its archive.
pub fn body_entry(
    choice: &BodyChoice,
    (run_file, module): (&str, Option<&str>),
    origin: Origin,
) -> Option<BodyEntry> {
    let run = choice.data.run.as_ref()?;
    let entry = best_entry(run)?;
    let e = &run.archive[entry];
    let figures = RunFigures {
        seed: choice.spec.seed,
        budget: run.config.budget_evals,
        evaluations: run.evaluations,
        training_best: e.fitness,
        wall_seconds: run.timing.as_ref().map(|t| t.wall_seconds),
    };
    Some(BodyEntry {
        file: body_file(&choice.spec.group, &choice.spec.condition),
        group: choice.spec.group.clone(),
        condition: choice.spec.condition.clone(),
        rows: e.shape.to_rows(),
        voxels: e.voxels,
        feet: e.feet,
        controller: run.config.controller,
        module: module.map(str::to_string),
        run_file: run_file.to_string(),
        entry,
        provenance: Provenance::new(figures, &choice.data.validation, choice.candidates, origin),
    })
}

/// A Markdown table of `bodies` (for the folder's README).
pub fn bodies_table(bodies: &[BodyEntry]) -> String {
    let mut md = String::from(
        "| file | brain | body | voxels, feet | seed | training best | paper median | unseen \
         mean | from (run file, entry) | chosen from |\n|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for b in bodies {
        let figure = |set, mean: bool| {
            b.provenance
                .validation
                .get(&set)
                .map_or(f64::NAN, |f| if mean { f.mean } else { f.median })
        };
        md += &format!(
            "| {} | {} ({}) | `{}` | {}, {} | {} | {:.2} | {:.2} | {:.2} | `{}`, entry {} | {} runs |\n",
            b.file,
            b.condition,
            b.controller,
            b.rows,
            b.voxels,
            b.feet,
            b.provenance.seed,
            b.provenance.training_best,
            figure(ValidationSet::Paper, false),
            figure(ValidationSet::Unseen, true),
            b.run_file,
            b.entry,
            b.provenance.chosen_from
        );
    }
    md
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_body_file_names_group_and_condition() {
        assert_eq!(super::body_file("rq3", "frozen"), "bodies/rq3-frozen.json");
    }
}
