//! An `[[any_body]]` group's brains for any body for `pretrained/`: one per group and
//! controller (`GROUP-CONTROLLER.json`), each with its provenance and its figures on every
//! body set it was walked on, which a replay must reproduce ([`replay`]).
//!
//! Choice (docs/ANALYSIS-PLAN.md, "One brain for every body": "the best attention-any module
//! (by its training-set median, never by held-out data)"), once every planned run of the
//! condition is finished and validated on every set (so that a module, once exported, is
//! final): the run whose best has the highest median over its **training set** of each body's
//! mean speed on the group's first terrain set (`unseen`); ties: the first seed. No held-out
//! set is used to choose, so the held-out figures stay honest.

use super::{Entry, Origin, Provenance, RunFigures};
use crate::campaign::any_body::{set_stem, AnyBodyGroup};
use crate::campaign::results::{AnyBodyData, AnyBodySpec, Results};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::Path;
use vsr::controllers::ControllerKind;
use vsr::experiment::body_set::{validate_bodies, BodiesValidation};
use vsr::experiment::{Best, BodySet, ValidationSet};
use vsr::quantiles::median;

/// How a brain for any body is chosen, in words (the manifest's record says it).
pub const CHOSEN_BY: &str = "of the condition's runs, the one whose best has the highest \
    median over its training set (each body's mean speed on the unseen terrains); held-out \
    sets are not used to choose";

/// One body set's figures of a brain for any body.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BodySetFigures {
    /// The set's name (its file's stem, e.g. `heldout-random`).
    pub name: String,
    /// Its file, as the campaign names it (relative to where the campaign ran).
    pub file: String,
    /// Held out (never trained on) or the training set.
    pub heldout: bool,
    /// The terrains.
    pub set: ValidationSet,
    /// Episode seconds.
    pub seconds: f64,
    /// Median over the bodies of each body's mean speed (m/s).
    pub median: f64,
    /// Share of the bodies above 1 m/s.
    pub walking_share: f64,
    /// Each body's mean speed over the terrains, in the set's order (m/s).
    pub means: Vec<f64>,
    /// The typical run beside the chosen one: the median over the condition's runs (those
    /// it was chosen from) of each run's `median` on this set (m/s). Absent in a manifest
    /// written before it was recorded.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub median_of_runs: Option<f64>,
}

/// What the manifest says of a brain for any body beyond a module's provenance.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct AnyBodyRecord {
    /// The campaign's `[[any_body]]` group.
    pub group: String,
    /// The training body-set file, as the campaign names it.
    pub training_set: String,
    /// Bodies walked by each evaluation in training.
    pub per_evaluation: usize,
    /// How it was chosen ([`CHOSEN_BY`]).
    pub chosen_by: String,
    /// Its figures on every body set of the group (held-out sets first, then the training
    /// set), each terrain set.
    pub sets: Vec<BodySetFigures>,
}

/// A chosen run.
#[derive(Debug, Clone)]
pub struct AnyBodyChoice {
    /// The chosen run.
    pub spec: AnyBodySpec,
    /// Its outputs.
    pub data: AnyBodyData,
    /// Finished, validated runs of its condition it was chosen from.
    pub candidates: usize,
    /// Each of those runs' median on every (body set, terrain set) it was walked on.
    pub run_medians: Vec<BTreeMap<(String, ValidationSet), f64>>,
}

/// A condition's choice: (group, controller), the chosen run (`None` until every planned
/// run is finished and validated on every set), and (planned, finished and validated).
#[derive(Debug, Clone)]
pub struct AnyBodyChosen {
    /// (group, controller).
    pub key: (String, ControllerKind),
    /// The chosen run.
    pub choice: Option<AnyBodyChoice>,
    /// Planned runs, and those finished and validated on every set.
    pub runs: (usize, usize),
}

/// A brain for any body's file name in the pretrained folder.
pub fn any_body_file(group: &str, controller: ControllerKind) -> String {
    format!("{group}-{controller}.json")
}

/// Whether `data` is finished and validated on every body set and terrain set of `g`.
pub fn complete(g: &AnyBodyGroup, data: &AnyBodyData) -> bool {
    data.run.is_some()
        && g.validated_on().iter().all(|b| {
            g.sets
                .iter()
                .all(|&s| data.validation.contains_key(&(set_stem(b), s)))
        })
}

/// The training-set median of `data` on `g`'s first terrain set: the score of the choice
/// (NaN, a run that fell apart, never wins).
pub fn training_median(g: &AnyBodyGroup, data: &AnyBodyData) -> Option<f64> {
    let set = *g.sets.first()?;
    let m = data.validation.get(&(set_stem(&g.bodies), set))?.median;
    Some(if m.is_nan() { f64::NEG_INFINITY } else { m })
}

/// Every (group, controller) of `results` whose controller is in `controllers`, in campaign
/// order, with its choice.
pub fn choose_any_body(results: &Results, controllers: &[ControllerKind]) -> Vec<AnyBodyChosen> {
    let mut out: Vec<AnyBodyChosen> = Vec::new();
    for g in &results.campaign.any_body {
        for &controller in g.controllers.iter().filter(|c| controllers.contains(c)) {
            let mine = results
                .any_body
                .iter()
                .filter(|(s, _)| s.group == g.name && s.controller == controller);
            let mut chosen = AnyBodyChosen {
                key: (g.name.clone(), controller),
                choice: None,
                runs: (0, 0),
            };
            let mut run_medians = Vec::new();
            for (spec, data) in mine {
                chosen.runs.0 += 1;
                if !complete(g, data) {
                    continue;
                }
                chosen.runs.1 += 1;
                let medians = data.validation.iter().map(|(k, v)| (k.clone(), v.median));
                let medians: BTreeMap<_, _> = medians.collect();
                let score = training_median(g, data).unwrap_or(f64::NEG_INFINITY);
                let slot = &mut chosen.choice;
                let candidates = slot.as_ref().map_or(0, |c| c.candidates) + 1;
                let better = slot.as_ref().map_or(true, |c| {
                    score > training_median(g, &c.data).unwrap_or(f64::NEG_INFINITY)
                });
                run_medians.push(medians);
                if better {
                    *slot = Some(AnyBodyChoice {
                        spec: spec.clone(),
                        data: data.clone(),
                        candidates,
                        run_medians: Vec::new(),
                    });
                } else if let Some(c) = slot.as_mut() {
                    c.candidates = candidates;
                }
            }
            if let Some(c) = chosen.choice.as_mut() {
                c.run_medians = run_medians;
            }
            if chosen.runs.1 < chosen.runs.0 {
                chosen.choice = None;
            }
            out.push(chosen);
        }
    }
    out
}

/// The manifest entry of `choice` in group `g`, exported by `origin`; `None` if its run
/// file is absent.
pub fn any_body_entry(choice: &AnyBodyChoice, g: &AnyBodyGroup, origin: Origin) -> Option<Entry> {
    let run = choice.data.run.as_ref()?;
    let figures = RunFigures {
        seed: choice.spec.seed,
        budget: choice.spec.evals,
        evaluations: run.generations.last().map_or(0, |g| g.evaluations),
        training_best: run.best.fitness,
        wall_seconds: run.timing.as_ref().map(|t| t.wall_seconds),
    };
    let mut sets = Vec::new();
    for (i, bodies) in g.validated_on().into_iter().enumerate() {
        for &set in &g.sets {
            let key = (set_stem(bodies), set);
            let v = choice.data.validation.get(&key)?;
            let of_runs: Vec<f64> = choice
                .run_medians
                .iter()
                .filter_map(|m| m.get(&key).copied())
                .collect();
            sets.push(BodySetFigures {
                name: set_stem(bodies),
                file: bodies.to_string(),
                heldout: i < g.heldout.len(),
                set,
                seconds: v.seconds,
                median: v.median,
                walking_share: v.walking_share,
                means: v.per_body.iter().map(|b| b.validation.mean).collect(),
                median_of_runs: (!of_runs.is_empty()).then(|| median(&of_runs)),
            });
        }
    }
    let training = run.config.bodies.as_ref().map(|b| b.set.bodies.len());
    Some(Entry {
        file: any_body_file(&g.name, choice.spec.controller),
        shape: set_stem(&g.bodies),
        rows: run.best.shape.to_rows(),
        controller: choice.spec.controller,
        finetuned_from: None,
        bodies: training,
        any_body: Some(AnyBodyRecord {
            group: g.name.clone(),
            training_set: g.bodies.clone(),
            per_evaluation: g.per_evaluation,
            chosen_by: CHOSEN_BY.to_string(),
            sets,
        }),
        provenance: Provenance::new(figures, &BTreeMap::new(), choice.candidates, origin),
    })
}

/// Walks `best` again on every body set `record` lists (their files relative to `root`) and
/// says where a figure differs from the record (bit for bit), or `Ok`. The sets run on
/// threads of their own; the result does not depend on them.
pub fn replay(record: &AnyBodyRecord, best: &Best, root: &Path) -> Result<(), String> {
    let results: Vec<Result<(), String>> = std::thread::scope(|scope| {
        let handles: Vec<_> = record
            .sets
            .iter()
            .map(|s| scope.spawn(move || replay_set(s, best, root)))
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().unwrap_or_else(|_| Err("a replay panicked".into())))
            .collect()
    });
    results.into_iter().collect()
}

fn replay_set(s: &BodySetFigures, best: &Best, root: &Path) -> Result<(), String> {
    let bodies = BodySet::read(&root.join(&s.file)).map_err(|e| e.to_string())?;
    let v: BodiesValidation =
        validate_bodies(best, &bodies, s.set, s.seconds).map_err(|e| e.to_string())?;
    let means: Vec<f64> = v.per_body.iter().map(|b| b.validation.mean).collect();
    if (means != s.means) || v.median != s.median || v.walking_share != s.walking_share {
        return Err(format!(
            "{} on the {} terrains: replayed median {} and share {}, recorded {} and {}",
            s.name, s.set, v.median, v.walking_share, s.median, s.walking_share
        ));
    }
    Ok(())
}

/// A Markdown table of the manifest's brains for any body (for the folder's README).
pub fn any_body_table(modules: &[Entry]) -> String {
    let mut md = String::new();
    for m in modules {
        let Some(a) = &m.any_body else { continue };
        if md.is_empty() {
            md += "| file | brain | trained on | seed | evaluations | training best | median \
                   per body set (m/s) | chosen from |\n|---|---|---|---|---|---|---|---|\n";
        }
        let medians: Vec<String> = a
            .sets
            .iter()
            .map(|s| format!("{} {:.2}", s.name, s.median))
            .collect();
        md += &format!(
            "| {} | {} | {} ({}, {} per evaluation) | {} | {} | {:.2} | {} | {} runs |\n",
            m.file,
            m.controller,
            m.shape,
            match m.bodies.unwrap_or(0) {
                1 => "1 body".to_string(),
                n => format!("{n} bodies"),
            },
            a.per_evaluation,
            m.provenance.seed,
            m.provenance.evaluations,
            m.provenance.training_best,
            medians.join("; "),
            m.provenance.chosen_from
        );
    }
    md
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_file_names_group_and_controller() {
        let name = super::any_body_file(
            "any-train32",
            vsr::controllers::ControllerKind::AttentionAny,
        );
        assert_eq!(name, "any-train32-attention-any.json");
    }
}
