//! What the page asks the core without simulating (through its core worker, www/core-worker.js):
//! the defaults it shows, the check of a drawing (verdict, pieces, parameter counts), and the
//! two genome operations of the playground: transplanting a module onto a drawn body
//! (SPEC 10, the rule of `vsr finetune`) and following a walking robot's edits.

use serde::Serialize;
use wasm_bindgen::prelude::{wasm_bindgen, JsError, JsValue};

use vsr::controllers::{remap_genome, ControllerKind};
use vsr::experiment::playground::{self, PAGE_CONTROLLERS};
use vsr::experiment::seeds::{evaluation_seed, Purpose};
use vsr::experiment::{self, PhaseGait, TrainingTerrain};
use vsr::simulation::{Shape, Terrain};

/// The page's defaults, from the core (`experiment::playground`): `{grid: {width, height},
/// presets: [{name, rows}], controllers, quick and paper: {population, seconds, budget},
/// trainingTerrain, viewTerrain, gait: {frequency, phase}, maxSeed, attentionGenes,
/// viewNoiseSeed (the viewer's sensor noise seed, a decimal string, for measuring a brain as
/// the viewer walks it), physics: {timeStep, areaContracted, areaExpanded, cornerSide}}`.
#[wasm_bindgen]
pub fn defaults() -> Result<JsValue, JsError> {
    to_js(&playground::defaults()?)
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct ShapeCheck {
    ok: bool,
    message: String,
    voxels: usize,
    pieces: Vec<Vec<[usize; 2]>>,
    params: Vec<(String, usize)>,
}

/// Checks a drawing written as rows (top first): `{ok, message ('' when ok), voxels,
/// pieces: [[[x, y], ...], ...] (cells from the bottom-left, one list per 4-connected
/// piece), params: [[controller, genes], ...]}`. Never throws.
#[wasm_bindgen(js_name = checkShape)]
pub fn check_shape(rows: &str) -> Result<JsValue, JsError> {
    let pieces: Vec<Vec<[usize; 2]>> = Shape::pieces(rows)
        .unwrap_or_default()
        .into_iter()
        .map(|p| p.into_iter().map(|(x, y)| [x, y]).collect())
        .collect();
    let voxels = pieces.iter().map(Vec::len).sum();
    let verdict = if rows.trim().is_empty() {
        Err("draw at least one voxel".to_string())
    } else {
        Shape::parse(rows).map(|_| ()).map_err(|e| e.to_string())
    };
    let check = ShapeCheck {
        ok: verdict.is_ok(),
        message: verdict.err().unwrap_or_default(),
        voxels,
        pieces,
        params: PAGE_CONTROLLERS
            .iter()
            .map(|k| (k.name().to_string(), k.param_count(voxels)))
            .collect(),
    };
    to_js(&check)
}

/// SPEC 10's transplant (`experiment::transplant`, how `vsr finetune --seed SEED` starts):
/// the best individual of the run `run_file` put on the body `rows`.
#[wasm_bindgen]
pub fn transplant(run_file: &str, rows: &str, seed: f64) -> Result<Vec<f32>, JsError> {
    Ok(experiment::transplant(
        experiment::codesign::source_in_file(run_file, None)?,
        Shape::parse(rows)?,
        seed_from(seed)?,
    )?)
}

/// A walking robot's genome after an edit of its body from `from_rows` to `to_rows`, by grid
/// position (`controllers::remap_genome`): shared genes and the genes of surviving voxels
/// are kept; the genes of new voxels come from the stream of (run seed `seed`, edit number
/// `edit`). Cell (x, y) of the new rows is cell (x + shift_x, y + shift_y) of the old ones.
#[wasm_bindgen(js_name = remapGenome)]
#[allow(clippy::too_many_arguments)]
pub fn remap(
    controller: &str,
    genome: &[f32],
    from_rows: &str,
    to_rows: &str,
    shift_x: i32,
    shift_y: i32,
    seed: f64,
    edit: u32,
) -> Result<Vec<f32>, JsError> {
    let kind: ControllerKind = controller.parse()?;
    let from = Shape::parse(from_rows)?;
    let to = Shape::parse(to_rows)?;
    let stream = evaluation_seed(seed_from(seed)?, edit, 0, Purpose::Remap);
    let shift = (i64::from(shift_x), i64::from(shift_y));
    Ok(remap_genome(kind, genome, &from, &to, shift, stream)?)
}

/// Checks that `genome` fits a `controller` on `rows` (the core's one genome check).
#[wasm_bindgen(js_name = checkGenome)]
pub fn check_genome(controller: &str, rows: &str, genome: &[f32]) -> Result<(), JsError> {
    let kind: ControllerKind = controller.parse()?;
    let shape = Shape::parse(rows)?;
    Ok(kind.check_genome("the genome", shape.voxel_count(), genome)?)
}

/// A seed from a JS number: a whole number in 0 ..= 2^53 - 1.
pub(super) fn seed_from(seed: f64) -> Result<u64, JsError> {
    let max = vsr::experiment::config::MAX_SEED as f64;
    if seed.fract() == 0.0 && (0.0..=max).contains(&seed) {
        Ok(seed as u64)
    } else {
        Err(JsError::new(&format!(
            "the seed must be a whole number from 0 to 2^53 - 1, not {seed}"
        )))
    }
}

/// A Rust value as a plain JS value (objects, arrays, numbers).
pub(super) fn to_js<T: Serialize>(value: &T) -> Result<JsValue, JsError> {
    serde_wasm_bindgen::to_value(value).map_err(|e| JsError::new(&e.to_string()))
}

/// A fresh run seed from the platform's randomness (`getrandom`: the browser's
/// `crypto.getRandomValues`), in 0 ..= 2^53 - 1 so that a JS number holds it exactly.
#[wasm_bindgen(js_name = freshSeed)]
pub fn fresh_seed() -> Result<f64, JsError> {
    let mut bytes = [0u8; 8];
    getrandom::getrandom(&mut bytes)
        .map_err(|e| JsError::new(&format!("no randomness available: {e}")))?;
    Ok((u64::from_le_bytes(bytes) & vsr::experiment::config::MAX_SEED) as f64)
}

/// `''` when `name` is a terrain the viewer can show (`flat`, `hilly-1-10-0`, ...), else
/// why not, in words.
#[wasm_bindgen(js_name = checkTerrain)]
pub fn check_terrain(name: &str) -> String {
    Terrain::parse(name).map_or_else(|e| e.to_string(), |_| String::new())
}

/// `''` when `text` is a phase gait `F,PHI` (frequency in Hz, phase per column in rad, as
/// `vsr --gait` reads it), else why not, in words.
#[wasm_bindgen(js_name = checkGait)]
pub fn check_gait(text: &str) -> String {
    PhaseGait::parse(text).map_or_else(|e| e.to_string(), |_| String::new())
}

/// `''` when `name` is a training terrain (a family such as `hilly-1-10`, or a terrain
/// name), else why not, in words.
#[wasm_bindgen(js_name = checkTrainingTerrain)]
pub fn check_training_terrain(name: &str) -> String {
    TrainingTerrain::parse(name).map_or_else(|e| e.to_string(), |_| String::new())
}
