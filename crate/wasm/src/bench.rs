//! [`bench_episode`]: runs a whole episode inside wasm so a benchmark times the
//! simulator, not one JS-to-wasm call per step.

use wasm_bindgen::prelude::{wasm_bindgen, JsError};

use vsr::experiment::GaitEpisode;

/// Builds `shape` on `terrain` with the phase gait (`frequency`, `phase`), runs `steps`
/// steps and returns the displacement of the robot's centre along x (m), so the work
/// cannot be optimised away and a caller can sanity-check it. Construction is included.
#[wasm_bindgen(js_name = benchEpisode)]
pub fn bench_episode(
    shape: &str,
    terrain: &str,
    frequency: f64,
    phase: f64,
    steps: usize,
) -> Result<f64, JsError> {
    let mut episode = GaitEpisode::new(shape, terrain, frequency, phase)?;
    let start = episode.centre_x();
    episode.step(steps)?;
    Ok(episode.centre_x() - start)
}
