//! The run-file side of the [`Episode`] handle: an episode driven by the best individual
//! of a run file (`experiment::evaluate::replay`), and each voxel's attention matrix.
//! The step and frame getters are the phase-gait episode's (`episode.rs`), unchanged.

use wasm_bindgen::prelude::{wasm_bindgen, JsError};

use super::Episode;
use crate::experiment::evaluate::replay;
use crate::experiment::RunFile;
use crate::simulation::{Shape, Terrain};

/// Seed of the sensor noise in episodes built from run files (as `vsr evaluate` defaults).
pub const NOISE_SEED: u64 = 0;

#[wasm_bindgen]
impl Episode {
    /// Builds the episode of the run file `text` (its JSON): the file's best individual
    /// drives its own shape on `terrain`, with sensor noise seed 0. `shape` is `""` for the
    /// file's shape, or must name that same shape. A malformed file, another version, an
    /// unknown terrain or another shape throws an `Error` whose message says what is wrong.
    #[wasm_bindgen(js_name = fromRunFile)]
    pub fn from_run_file(text: &str, terrain: &str, shape: &str) -> Result<Episode, JsError> {
        let run = RunFile::from_json(text)?;
        let terrain = Terrain::parse(terrain)?;
        let wanted = match shape.trim() {
            "" => None,
            s => Some(Shape::parse(s)?),
        };
        let inner = replay(&run.best, wanted.as_ref(), terrain, Some(NOISE_SEED))?;
        Ok(Episode {
            inner,
            shape: run.best.shape,
            controller: run.best.controller.to_string(),
        })
    }

    /// Each voxel's current attention matrix, length 16n: for voxel i at `16i`, 4 rows of
    /// 4 (row-major), rows and columns in sensor order area, vx, vy, touch, values in
    /// -1 .. 1. Empty when the controller has no attention (phase gait, MLP, MLP-Comm).
    pub fn attention(&self) -> Vec<f32> {
        self.inner
            .attention()
            .map_or_else(Vec::new, <[f32]>::to_vec)
    }
}
