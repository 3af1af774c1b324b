//! `vsr campaign merge`: one CSV row per run file found, with its configuration, its
//! validations and its best fitness per generation.
//!
//! Columns: `run, kind, shape, controller, evals, seed, source, evaluations, best, alpha, eta,
//! wall_seconds`, then per validation set `SET_median, SET_mean, SET_0 .. SET_9`, then
//! `best_g0 .. best_gN` (N the longest run's last generation; empty cells where a run is
//! shorter or a file is missing). Numbers are written in full (Rust's shortest round-trip form).
//!
//! A campaign with `[[any_body]]` groups adds, before the generations, per body set its runs
//! are walked on (held-out sets, then training sets) and terrain set `BODYSET.SET_median` (the
//! median over the set's bodies of each body's mean speed) and `BODYSET.SET_walking_share`
//! (the share of its bodies above 1 m/s), and a row per finished any-body run (`kind`
//! `any-body`, `shape` its training set) and per random brain of the floor with a validation
//! found (`kind` `random-brain`, `run` `floor-CONTROLLER-sSEED`). Other campaigns' tables are
//! unchanged.

use super::any_body::{floor_stem, set_stem};
use super::results::{Results, RunData};
use std::collections::BTreeMap;
use vsr::experiment::body_set::BodiesValidation;
use vsr::experiment::validation::VALIDATION_TERRAINS;
use vsr::experiment::ValidationSet;

/// The CSV text (header and one line per existing run file, in plan order).
pub fn csv(results: &Results) -> String {
    let sets = &results.campaign.validate;
    let generations = results
        .data
        .iter()
        .map(|(_, d)| d)
        .filter_map(|d| d.run.as_ref().map(|r| r.generations.len()))
        .chain(
            results
                .any_body
                .iter()
                .filter_map(|(_, d)| d.run.as_ref().map(|r| r.generations.len())),
        )
        .max()
        .unwrap_or(0);
    let body_sets = body_sets(results);
    let mut header: Vec<String> = [
        "run",
        "kind",
        "shape",
        "controller",
        "evals",
        "seed",
        "source",
        "evaluations",
        "best",
        "alpha",
        "eta",
        "wall_seconds",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    for set in sets {
        header.push(format!("{set}_median"));
        header.push(format!("{set}_mean"));
        header.extend((0..VALIDATION_TERRAINS).map(|i| format!("{set}_{i}")));
    }
    for (stem, set) in &body_sets {
        header.push(format!("{stem}.{set}_median"));
        header.push(format!("{stem}.{set}_walking_share"));
    }
    header.extend((0..generations).map(|g| format!("best_g{g}")));
    let mut text = header.join(",") + "\n";
    for (spec, data) in &results.data {
        let Some(run) = &data.run else { continue };
        let last = run.generations.last();
        let mut row = vec![
            spec.stem(),
            if spec.source.is_some() {
                "finetune"
            } else {
                "scratch"
            }
            .to_string(),
            spec.shape.clone(),
            spec.controller.to_string(),
            spec.evals.to_string(),
            spec.seed.to_string(),
            spec.source.as_ref().map_or(String::new(), |s| s.stem()),
            last.map_or(String::new(), |g| g.evaluations.to_string()),
            number(data.final_best()),
            number(run.best.alpha.map(f64::from)),
            number(run.best.eta.map(f64::from)),
            number(run.timing.map(|t| t.wall_seconds)),
        ];
        for &set in sets {
            row.extend(validation_cells(data, set));
        }
        let bests = run.generations.iter().map(|g| number(Some(g.best)));
        row.extend(
            bests
                .chain(std::iter::repeat(String::new()))
                .take(generations),
        );
        text += &(row.join(",") + "\n");
    }
    let standard = 2 + VALIDATION_TERRAINS as usize;
    for (spec, data) in &results.any_body {
        let Some(run) = &data.run else { continue };
        let group = results
            .campaign
            .any_body
            .iter()
            .find(|g| g.name == spec.group);
        let mut row = vec![
            spec.stem(),
            "any-body".to_string(),
            group.map_or(String::new(), |g| set_stem(&g.bodies)),
            spec.controller.to_string(),
            spec.evals.to_string(),
            spec.seed.to_string(),
            String::new(),
            number(run.generations.last().map(|g| g.evaluations as f64)),
            number(run.generations.last().map(|g| g.best)),
            String::new(),
            String::new(),
            number(run.timing.map(|t| t.wall_seconds)),
        ];
        row.extend(std::iter::repeat(String::new()).take(standard * sets.len()));
        row.extend(body_set_cells(&data.validation, &body_sets));
        let bests = run.generations.iter().map(|g| number(Some(g.best)));
        row.extend(
            bests
                .chain(std::iter::repeat(String::new()))
                .take(generations),
        );
        text += &(row.join(",") + "\n");
    }
    for ((controller, seed), found) in &results.floor {
        if found.is_empty() {
            continue;
        }
        let mut row = vec![
            floor_stem(*controller, *seed),
            "random-brain".to_string(),
            String::new(),
            controller.to_string(),
            String::new(),
            seed.to_string(),
        ];
        row.extend(std::iter::repeat(String::new()).take(6 + standard * sets.len()));
        row.extend(body_set_cells(found, &body_sets));
        row.extend(std::iter::repeat(String::new()).take(generations));
        text += &(row.join(",") + "\n");
    }
    text
}

/// Every (body-set stem, terrain set) the any-body groups' runs are walked on: held-out sets
/// first, then training sets, each once, in campaign order.
fn body_sets(results: &Results) -> Vec<(String, ValidationSet)> {
    let groups = &results.campaign.any_body;
    let heldout = groups
        .iter()
        .flat_map(|g| g.heldout.iter().map(move |h| (g, h)));
    let training = groups.iter().map(|g| (g, &g.bodies));
    let mut out: Vec<(String, ValidationSet)> = Vec::new();
    for (g, bodies) in heldout.chain(training) {
        for &set in &g.sets {
            let key = (set_stem(bodies), set);
            if !out.contains(&key) {
                out.push(key);
            }
        }
    }
    out
}

/// The median and walking share of each of `sets` in `found`, or empty cells.
fn body_set_cells(
    found: &BTreeMap<(String, ValidationSet), BodiesValidation>,
    sets: &[(String, ValidationSet)],
) -> Vec<String> {
    sets.iter()
        .flat_map(|key| match found.get(key) {
            Some(v) => [number(Some(v.median)), number(Some(v.walking_share))],
            None => [String::new(), String::new()],
        })
        .collect()
}

/// Median, mean and the 10 velocities of `set`, or 12 empty cells.
fn validation_cells(data: &RunData, set: ValidationSet) -> Vec<String> {
    let count = 2 + VALIDATION_TERRAINS as usize;
    match data.validation.get(&set) {
        None => vec![String::new(); count],
        Some(v) => [number(Some(v.median)), number(Some(v.mean))]
            .into_iter()
            .chain(v.terrains.iter().map(|t| number(Some(t.velocity))))
            .chain(std::iter::repeat(String::new()))
            .take(count)
            .collect(),
    }
}

/// A finite number in full, anything else as an empty cell.
fn number(v: Option<f64>) -> String {
    match v {
        Some(x) if x.is_finite() => x.to_string(),
        _ => String::new(),
    }
}
