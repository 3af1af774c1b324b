//! The run-file side of the [`Episode`] handle: an episode driven by the best individual
//! of a run file (`experiment::evaluate::replay`), and each voxel's attention matrix.
//! The step and frame getters are the phase-gait episode's (`episode.rs`), unchanged.

use js_sys::{Float32Array, Object, Reflect};
use wasm_bindgen::prelude::{wasm_bindgen, JsError, JsValue};

use super::episode::GAIT_NAME;
use super::Episode;
use vsr::controllers::ControllerKind;
use vsr::experiment::evaluate::replay;
use vsr::experiment::{best_in_file, Episode as CoreEpisode, Policy};
use vsr::experiment::{check_start_offset, freezable_policy, PhaseGait};
use vsr::simulation::constants::PLACEMENT_LEFT_X;
use vsr::simulation::{Shape, Terrain};

/// The start offset that puts the robot's left edge at `left` (m): 0 (the start line) for
/// NaN or for a place off the ground between the walls.
fn placement_offset(shape: &Shape, terrain: &Terrain, left: f64) -> f64 {
    let offset = left - PLACEMENT_LEFT_X;
    if check_start_offset(shape, terrain, offset).is_ok() {
        offset
    } else {
        0.0
    }
}

/// Seed of the sensor noise in episodes built from run files (as `vsr evaluate` defaults).
pub const NOISE_SEED: u64 = vsr::experiment::playground::VIEW_NOISE_SEED;

#[wasm_bindgen]
impl Episode {
    /// Builds the episode of the run file `text` (its JSON): the file's best individual
    /// drives its own shape on `terrain`, with sensor noise seed 0. `shape` is `""` for the
    /// file's shape, or must name that same shape. A malformed file, another version, an
    /// unknown terrain or another shape throws an `Error` whose message says what is wrong.
    #[wasm_bindgen(js_name = fromRunFile)]
    pub fn from_run_file(text: &str, terrain: &str, shape: &str) -> Result<Episode, JsError> {
        let best = best_in_file(text, None)?;
        let terrain = Terrain::parse(terrain)?;
        let wanted = match shape.trim() {
            "" => None,
            s => Some(Shape::parse(s)?),
        };
        let inner = replay(&best, wanted.as_ref(), terrain, Some(NOISE_SEED))?;
        let controller = best.controller.to_string();
        Ok(Episode::wrap(inner, best.shape, controller))
    }

    /// Builds the episode of a genome on a drawn body: a `controller` (`attention`, `mlp`,
    /// `mlp-comm`) with parameters `genome` drives the body `rows` on `terrain`, with sensor
    /// noise seed 0, its left edge placed at `left` metres (NaN: the start line; a place
    /// off the ground between the walls also falls back to the start line). An attention
    /// brain can be frozen (`freezeAttention`). A genome that does not fit the body throws
    /// an `Error` saying so.
    #[wasm_bindgen(js_name = fromGenome)]
    pub fn from_genome(
        rows: &str,
        terrain: &str,
        controller: &str,
        genome: &[f32],
        left: f64,
    ) -> Result<Episode, JsError> {
        let kind: ControllerKind = controller.parse()?;
        let shape = Shape::parse(rows)?;
        let brain = freezable_policy(kind, &shape, genome)?;
        let terrain = Terrain::parse(terrain)?;
        let offset = placement_offset(&shape, &terrain, left);
        let inner =
            CoreEpisode::with_start_offset(&shape, terrain, brain, Some(NOISE_SEED), offset);
        Ok(Episode::wrap(inner, shape, kind.to_string()))
    }

    /// The phase-gait episode of `new`, its left edge placed at `left` metres (NaN: the start
    /// line, as `new`; off the ground: the start line too).
    #[wasm_bindgen(js_name = gaitAt)]
    pub fn gait_at(
        rows: &str,
        terrain: &str,
        frequency: f64,
        phase: f64,
        left: f64,
    ) -> Result<Episode, JsError> {
        let shape = Shape::parse(rows)?;
        let terrain = Terrain::parse(terrain)?;
        let offset = placement_offset(&shape, &terrain, left);
        let gait = Policy::Gait(PhaseGait::new(frequency, phase)?);
        let inner = CoreEpisode::with_start_offset(&shape, terrain, gait, None, offset);
        Ok(Episode::wrap(inner, shape, GAIT_NAME.to_string()))
    }

    /// The left edge of the robot now: the smallest x of its voxels' outer corners (m).
    #[wasm_bindgen(js_name = leftEdge)]
    pub fn left_edge(&self) -> f64 {
        let corners = self.corners();
        let xs = corners.iter().step_by(2).map(|&x| f64::from(x));
        xs.fold(f64::INFINITY, f64::min)
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

#[wasm_bindgen]
impl Episode {
    /// The whole current frame as one object, so the worker crosses the boundary once per
    /// frame: `{time, voxels, centreX, centreY, distance, episodeSpeed, corners, areas,
    /// bodies, attention}`, the buffers as `Float32Array`s with the layouts of the
    /// getters above (attention empty when the controller has none); distance and
    /// episodeSpeed as the getters of `measure.rs` say.
    pub fn frame(&self) -> Result<Object, JsError> {
        let frame = Object::new();
        let set = |key: &str, value: JsValue| {
            Reflect::set(&frame, &JsValue::from_str(key), &value)
                .map(|_| ())
                .map_err(|_| JsError::new("could not build a frame object"))
        };
        set("time", self.time().into())?;
        set("voxels", (self.voxel_count() as f64).into())?;
        set("centreX", self.centre_x().into())?;
        set("centreY", self.centre_y().into())?;
        set("distance", self.distance().into())?;
        set("episodeSpeed", self.episode_speed().into())?;
        set("corners", Float32Array::from(&self.corners()[..]).into())?;
        set("areas", Float32Array::from(&self.area_ratios()[..]).into())?;
        set(
            "bodies",
            Float32Array::from(&self.corner_bodies()[..]).into(),
        )?;
        set(
            "attention",
            Float32Array::from(&self.attention()[..]).into(),
        )?;
        Ok(frame)
    }
}
