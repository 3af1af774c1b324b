//! [`evaluate`]: one whole episode of a genome, as `vsr evaluate` runs it, for JS users of
//! the web package (docs/embed.md): the same composition point
//! (`experiment::evaluate::evaluate`), so the velocity is bit-identical to the CLI's.

use serde::Serialize;
use wasm_bindgen::prelude::{wasm_bindgen, JsError, JsValue};

use super::page::{seed_from, to_js};
use vsr::controllers::ControllerKind;
use vsr::experiment::config::MAX_SECONDS;
use vsr::experiment::evaluate::evaluate as run_episode;
use vsr::simulation::{Shape, Terrain};

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Evaluation {
    shape: String,
    controller: String,
    terrain: String,
    noise_seed: f64,
    velocity: f64,
    distance: f64,
    steps: f64,
    seconds: f64,
}

/// Runs one episode of `seconds` in which a `controller` (`attention`, `mlp`, `mlp-comm`)
/// with parameters `genome` drives the body `shape` (a preset or rows) on `terrain`, with
/// sensor noise seed `noiseSeed` (`vsr evaluate`'s default is 0), and returns what
/// `vsr evaluate` prints: `{shape, controller, terrain, noiseSeed, velocity (m/s, the
/// fitness), distance (m), steps, seconds}`. Bad input (a genome that does not fit, NaN
/// genes, a disconnected shape, an unknown terrain, seconds outside (0, 3600]) or an
/// episode that explodes throws an `Error` saying what is wrong.
#[wasm_bindgen]
pub fn evaluate(
    shape: &str,
    controller: &str,
    terrain: &str,
    genome: &[f32],
    seconds: f64,
    noise_seed: f64,
) -> Result<JsValue, JsError> {
    let kind: ControllerKind = controller.parse()?;
    let body = Shape::parse(shape)?;
    let ground = Terrain::parse(terrain)?;
    let noise = seed_from(noise_seed)?;
    if !(seconds > 0.0 && seconds <= MAX_SECONDS) {
        return Err(JsError::new(&format!(
            "episode seconds must be in (0, {MAX_SECONDS}], got {seconds}"
        )));
    }
    let outcome = run_episode(&body, ground, kind, genome, Some(noise), seconds)?;
    to_js(&Evaluation {
        shape: body.to_rows(),
        controller: kind.to_string(),
        terrain: terrain.to_string(),
        noise_seed,
        velocity: outcome.velocity,
        distance: outcome.distance,
        steps: outcome.steps as f64,
        seconds: outcome.seconds,
    })
}
