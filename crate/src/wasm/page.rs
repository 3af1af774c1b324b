//! What the page's main thread asks the core without simulating: the defaults it shows, the
//! check of a drawing (verdict, pieces, parameter counts), a module's description, and the
//! two genome operations of the playground: transplanting a module onto a drawn body
//! (SPEC 10, the rule of `vsr finetune`) and following a walking robot's edits.

use serde::Serialize;
use wasm_bindgen::prelude::{wasm_bindgen, JsError, JsValue};

use crate::controllers::{remap_genome, ControllerKind, ATTENTION_PARAMS};
use crate::experiment::config::{PAPER_SECONDS, PAPER_TERRAIN};
use crate::experiment::finetune::initial_population;
use crate::experiment::seeds::{evaluation_seed, Purpose};
use crate::experiment::{source_of, EvolutionConfig, RunFile, TrainingTerrain};
use crate::genetics::GaConfig;
use crate::simulation::{Shape, Terrain};

/// The drawing grid of the page's editor (cells).
const GRID: Grid = Grid {
    width: 20,
    height: 10,
};
/// Presets the editor offers, by name (each parses with [`Shape::parse`]).
const PRESETS: [&str; 5] = [
    "biped-4x3",
    "comb-7x2",
    "biped-6x4",
    "comb-14x2",
    "worm-6x1",
];
/// Controllers the page evolves.
const CONTROLLERS: [ControllerKind; 3] = [
    ControllerKind::Attention,
    ControllerKind::Mlp,
    ControllerKind::MlpComm,
];
/// The page's quick run: progress within a minute or two on two cores.
const QUICK: RunPreset = RunPreset {
    population: 20,
    seconds: 10.0,
    budget: 2000,
};
/// The terrain the robot walks on in the viewer.
const VIEW_TERRAIN: &str = "hilly-1-10-0";
/// The phase gait that drives a body with no controller yet: the reference biped's best
/// forward gait on flat ground (shared/reference/gaits-biped-flat.json).
const GAIT: Gait = Gait {
    frequency: 0.5,
    phase: 1.5,
};

#[derive(Serialize, Clone, Copy)]
struct Grid {
    width: usize,
    height: usize,
}

#[derive(Serialize, Clone, Copy)]
struct RunPreset {
    population: usize,
    seconds: f64,
    budget: u64,
}

#[derive(Serialize, Clone, Copy)]
struct Gait {
    frequency: f64,
    phase: f64,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Preset {
    name: &'static str,
    rows: String,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Defaults {
    grid: Grid,
    presets: Vec<Preset>,
    controllers: Vec<&'static str>,
    quick: RunPreset,
    paper: RunPreset,
    training_terrain: &'static str,
    view_terrain: &'static str,
    gait: Gait,
    max_seed: f64,
    attention_genes: usize,
    view_noise_seed: String,
}

/// The page's defaults, from the core: `{grid: {width, height}, presets: [{name, rows}],
/// controllers, quick and paper: {population, seconds, budget}, trainingTerrain, viewTerrain,
/// gait: {frequency, phase}, maxSeed, attentionGenes, viewNoiseSeed (the viewer's sensor
/// noise seed, a decimal string, for measuring a brain as the viewer walks it)}`.
#[wasm_bindgen]
pub fn defaults() -> Result<JsValue, JsError> {
    let ga = GaConfig::default();
    let presets = PRESETS
        .iter()
        .map(|&name| {
            Ok(Preset {
                name,
                rows: Shape::parse(name)?.to_rows(),
            })
        })
        .collect::<crate::Result<Vec<_>>>()?;
    let defaults = Defaults {
        grid: GRID,
        presets,
        controllers: CONTROLLERS.iter().map(|k| k.name()).collect(),
        quick: QUICK,
        paper: RunPreset {
            population: ga.population,
            seconds: PAPER_SECONDS,
            budget: ga.budget_evals,
        },
        training_terrain: PAPER_TERRAIN,
        view_terrain: VIEW_TERRAIN,
        gait: GAIT,
        max_seed: crate::experiment::config::MAX_SEED as f64,
        attention_genes: ATTENTION_PARAMS,
        view_noise_seed: super::controlled::NOISE_SEED.to_string(),
    };
    to_js(&defaults)
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
        params: CONTROLLERS
            .iter()
            .map(|k| (k.name().to_string(), k.param_count(voxels)))
            .collect(),
    };
    to_js(&check)
}

/// SPEC 10's transplant, as `vsr finetune --seed SEED` starts it: the best individual of the
/// attention run `run_file` put on the body `rows`; its 32 attention genes kept, the
/// downstream genes re-drawn for the new body (unchanged when the body is its own). An MLP
/// or MLP-Comm module has no body-independent part and is refused on another body.
#[wasm_bindgen]
pub fn transplant(run_file: &str, rows: &str, seed: f64) -> Result<Vec<f32>, JsError> {
    let run = RunFile::from_json(run_file)?;
    let shape = Shape::parse(rows)?;
    let source = source_of(&run);
    if source.controller != ControllerKind::Attention
        && source.controller != ControllerKind::SlowAttention
    {
        if source.shape == shape {
            return Ok(source.genome);
        }
        return Err(JsError::new(&format!(
            "only attention modules transfer to another body: this {} controller's genes \
             belong to the voxels of its own body ({}); open it with its own body, or evolve \
             one for yours",
            source.controller,
            source.shape.to_rows()
        )));
    }
    let config = EvolutionConfig::finetune(
        source.clone(),
        shape,
        GaConfig::default().budget_evals,
        seed_from(seed)?,
    );
    config.validate()?;
    Ok(initial_population(&config, &source).swap_remove(0))
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
    let max = crate::experiment::config::MAX_SEED as f64;
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
    Ok((u64::from_le_bytes(bytes) & crate::experiment::config::MAX_SEED) as f64)
}

/// `''` when `name` is a terrain the viewer can show (`flat`, `hilly-1-10-0`, ...), else
/// why not, in words.
#[wasm_bindgen(js_name = checkTerrain)]
pub fn check_terrain(name: &str) -> String {
    Terrain::parse(name).map_or_else(|e| e.to_string(), |_| String::new())
}

/// `''` when `name` is a training terrain (a family such as `hilly-1-10`, or a terrain
/// name), else why not, in words.
#[wasm_bindgen(js_name = checkTrainingTerrain)]
pub fn check_training_terrain(name: &str) -> String {
    TrainingTerrain::parse(name).map_or_else(|e| e.to_string(), |_| String::new())
}
