//! `vsr campaign merge`: one CSV row per run file found, with its configuration, its
//! validations and its best fitness per generation.
//!
//! Columns: `run, kind, shape, controller, evals, seed, source, evaluations, best, alpha, eta,
//! wall_seconds`, then per validation set `SET_median, SET_mean, SET_0 .. SET_9`, then
//! `best_g0 .. best_gN` (N the longest run's last generation; empty cells where a run is
//! shorter or a file is missing). Numbers are written in full (Rust's shortest round-trip form).

use super::results::{Results, RunData};
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
        .max()
        .unwrap_or(0);
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
    text
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
