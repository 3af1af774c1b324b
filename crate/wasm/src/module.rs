//! What the page asks the core about a module (a run file): its description and its best
//! genome on its own body.

use serde::Serialize;
use wasm_bindgen::prelude::{wasm_bindgen, JsError, JsValue};

use super::page::to_js;
use vsr::experiment::codesign::is_codesign;
use vsr::experiment::evolution::planned_evaluations;
use vsr::experiment::{best_in_file, CodesignRun, RunFile};

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct ModuleInfo {
    shape: String,
    controller: String,
    seed: u64,
    budget: u64,
    evaluations: u64,
    fitness: f64,
    genes: usize,
    finetuned_from: Option<String>,
    seconds: f64,
    terrain: String,
    found_by_search: bool,
    /// One genome for every body (`attention-any`, `mlp-any`, `mlp-comm-any`).
    any_body: bool,
    /// The body set it was trained on (its file name), or null: trained on `shape` alone.
    body_set: Option<String>,
    /// How many bodies it was trained on (1 when on `shape` alone).
    bodies: usize,
}

/// Reads a run file (its JSON) and describes its best individual: `{shape (rows),
/// controller, seed, budget, evaluations (what that budget took: whole generations),
/// fitness, genes, finetunedFrom (source rows or null), seconds
/// (its training episodes' length), terrain (its training terrain: a family such as
/// hilly-1-10, or a name), foundBySearch (a co-design run file: its best body, found by a
/// body search), anyBody (one genome drives every body), bodySet (the body-set file it was
/// trained on, or null) and bodies (how many bodies it was trained on: 1, or the set's)}`.
/// For a brain trained on many bodies, `shape` is its set's first body. A malformed file
/// throws an `Error` that says what is wrong.
#[wasm_bindgen(js_name = describeRun)]
pub fn describe_run(run_file: &str) -> Result<JsValue, JsError> {
    if is_codesign(run_file) {
        return to_js(&describe_codesign(&CodesignRun::from_json(run_file)?));
    }
    let run = RunFile::from_json(run_file)?;
    to_js(&ModuleInfo {
        shape: run.best.shape.to_rows(),
        controller: run.best.controller.to_string(),
        seed: run.config.seed,
        budget: run.config.ga.budget_evals,
        evaluations: planned_evaluations(
            run.config.ga.population as u64,
            run.config.ga.budget_evals,
        ),
        fitness: run.best.fitness,
        genes: run.best.genome.len(),
        finetuned_from: run.config.source.as_ref().map(|s| s.shape.to_rows()),
        seconds: run.config.seconds,
        terrain: run.config.terrain.clone().into(),
        found_by_search: false,
        any_body: run.best.controller.is_body_independent(),
        body_set: run.config.bodies.as_ref().map(|b| b.set.name.clone()),
        bodies: run.config.bodies.as_ref().map_or(1, |b| b.set.bodies.len()),
    })
}

/// A body search's best body with its brain, described as a module (the page's list says
/// which search found it).
fn describe_codesign(run: &CodesignRun) -> ModuleInfo {
    ModuleInfo {
        shape: run.best.shape.to_rows(),
        controller: run.best.controller.to_string(),
        seed: run.config.seed,
        budget: run.config.budget_evals,
        evaluations: run.evaluations,
        fitness: run.best.fitness,
        genes: run.best.genome.len(),
        finetuned_from: None,
        seconds: run.config.seconds,
        terrain: run.config.terrain.clone().into(),
        found_by_search: true,
        any_body: run.best.controller.is_body_independent(),
        body_set: None,
        bodies: 1,
    }
}

/// The best genome of `run_file` itself (its own body; a co-design run file's best body).
#[wasm_bindgen(js_name = runGenome)]
pub fn run_genome(run_file: &str) -> Result<Vec<f32>, JsError> {
    Ok(best_in_file(run_file, None)?.genome)
}
