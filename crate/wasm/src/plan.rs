//! What a run's settings mean, from the core's rule ([`planned_evaluations`]), for the page
//! to say before a run starts: how many evaluations and generations a budget becomes.

use serde::Serialize;
use wasm_bindgen::prelude::{wasm_bindgen, JsError, JsValue};

use super::page::to_js;
use vsr::experiment::evolution::{planned_evaluations, planned_generations};

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct RunPlan {
    planned: u64,
    generations: u64,
    per_generation: u64,
}

/// The plan of a run of `population` and `budget` evaluations: `{planned (evaluations it
/// takes), generations (after generation 0), perGeneration (evaluations in each of them)}`.
/// A population or budget that is not a whole number of at least 1 throws an `Error`.
#[wasm_bindgen(js_name = runPlan)]
pub fn run_plan(population: f64, budget: f64) -> Result<JsValue, JsError> {
    let whole = |v: f64, what: &str| {
        if v >= 1.0 && v.fract() == 0.0 && v <= 1e15 {
            Ok(v as u64)
        } else {
            Err(JsError::new(&format!(
                "the {what} must be a whole number of at least 1, not {v}"
            )))
        }
    };
    let (population, budget) = (whole(population, "population")?, whole(budget, "budget")?);
    to_js(&RunPlan {
        planned: planned_evaluations(population, budget),
        generations: planned_generations(population, budget),
        per_generation: 2 * population,
    })
}
