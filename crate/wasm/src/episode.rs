//! [`Episode`]: a JS handle on one `experiment::Episode`, stepped by the page's worker in
//! slices: its phase-gait constructor, the step and the frame getters. The run-file
//! constructor and the attention getter are in `controlled.rs`, the episode's measured
//! speed in `measure.rs`; both kinds of episode are this one handle, so the worker steps
//! and draws them with the same code.

use wasm_bindgen::prelude::{wasm_bindgen, JsError};

use vsr::experiment::{Episode as CoreEpisode, Outcome, PhaseGait};
use vsr::simulation::carry::voxel_map;
use vsr::simulation::{Shape, Terrain};

/// Name reported by [`Episode::controller`] for the phase gait.
pub(super) const GAIT_NAME: &str = "phase gait";

/// One robot on one terrain, driven by the phase gait u(t) = sin(2 pi f t + phi x) or by a
/// run file's controller.
#[wasm_bindgen]
pub struct Episode {
    pub(super) inner: CoreEpisode,
    pub(super) shape: Shape,
    pub(super) controller: String,
    /// The step at which the episode's length ends (see `measure.rs`), if one was set.
    pub(super) end: Option<u64>,
    /// The outcome (the fitness's measure) taken at that step, once it was reached.
    pub(super) at_end: Option<Outcome>,
}

impl Episode {
    /// The handle on a freshly built core episode, with no episode length set.
    pub(super) fn wrap(inner: CoreEpisode, shape: Shape, controller: String) -> Episode {
        Episode {
            inner,
            shape,
            controller,
            end: None,
            at_end: None,
        }
    }
}

#[wasm_bindgen]
impl Episode {
    /// Builds the robot `shape` (a preset such as `biped-4x3` or rows such as
    /// `1111-1111-1001`) on `terrain` (such as `hilly-1-10-0`) with gait frequency
    /// `frequency` (Hz) and phase `phase` (rad per column). Bad input throws an `Error`
    /// whose message says what is wrong.
    #[wasm_bindgen(constructor)]
    pub fn new(shape: &str, terrain: &str, frequency: f64, phase: f64) -> Result<Episode, JsError> {
        let shape = Shape::parse(shape)?;
        let gait = PhaseGait::new(frequency, phase)?;
        let inner = CoreEpisode::from_parts(&shape, Terrain::parse(terrain)?, gait);
        Ok(Episode::wrap(inner, shape, GAIT_NAME.to_string()))
    }

    /// What drives the voxels: `phase gait` or a controller family (`attention`, `mlp`, ...).
    #[wasm_bindgen(getter)]
    pub fn controller(&self) -> String {
        self.controller.clone()
    }

    /// The robot's shape as rows of `0`/`1`, top row first (`1111-1111-1001`).
    #[wasm_bindgen(getter)]
    pub fn shape(&self) -> String {
        self.shape.to_rows()
    }

    /// Grid cells, length 2n: for voxel i at `2i`, its column (from the left) and row (from
    /// the bottom), so a drawing can lay per-voxel data out like the robot.
    #[wasm_bindgen(js_name = voxelCells)]
    pub fn voxel_cells(&self) -> Vec<u32> {
        let cells = self.shape.voxels().iter();
        cells
            .flat_map(|&(x, y)| [x, y].map(|v| u32::try_from(v).unwrap_or(u32::MAX)))
            .collect()
    }

    /// An edit of the walking robot `old`: this freshly built robot takes `old`'s posture
    /// and motion, its cell (x, y) being `old`'s cell (x - dx, y - dy) (the edit's shift of
    /// the bounding box; cells count from the bottom left). Voxels that were not in `old`
    /// move with their neighbours.
    #[wasm_bindgen(js_name = carryPose)]
    pub fn carry_pose(&mut self, old: &Episode, dx: i32, dy: i32) {
        let shift = (i64::from(dx), i64::from(dy));
        let map = voxel_map(old.shape.voxels(), self.shape.voxels(), shift);
        self.inner.carry_pose_from(&old.inner, &map);
    }

    /// Advances the simulation by `steps` steps of 1/60 s, stopping on the way at the end of
    /// the episode's length (if set) to take its outcome. Throws if it became unstable.
    pub fn step(&mut self, steps: usize) -> Result<(), JsError> {
        let done = self.inner.world().steps();
        let to_end = self.end.filter(|&e| e > done).map(|e| e - done);
        match to_end.and_then(|n| usize::try_from(n).ok()) {
            Some(n) if n <= steps => {
                self.inner.step(n)?;
                self.at_end = Some(self.inner.outcome());
                self.inner.step(steps - n)?;
            }
            _ => self.inner.step(steps)?,
        }
        Ok(())
    }

    /// Simulated time in seconds.
    #[wasm_bindgen(getter)]
    pub fn time(&self) -> f64 {
        self.inner.time()
    }

    /// Number of voxels n; frame buffers have lengths 8n, n and 12n (attention: 16n or 0).
    #[wasm_bindgen(getter, js_name = voxelCount)]
    pub fn voxel_count(&self) -> usize {
        self.inner.voxel_count()
    }

    /// Mean x of the voxel centres (m).
    #[wasm_bindgen(getter, js_name = centreX)]
    pub fn centre_x(&self) -> f64 {
        self.inner.centre_x()
    }

    /// Mean y of the voxel centres (m, y up).
    #[wasm_bindgen(getter, js_name = centreY)]
    pub fn centre_y(&self) -> f64 {
        self.inner.centre_y()
    }

    /// Voxel outlines, length 8n: for voxel i at `8i`, its outer corner points
    /// x, y in the order SW, SE, NE, NW (m).
    pub fn corners(&self) -> Vec<f32> {
        let mut out = vec![0.0; 8 * self.inner.voxel_count()];
        self.inner.write_voxel_corners(&mut out);
        out
    }

    /// Area ratios, length n: area / rest area, 0.775 contracted .. 1.225 expanded.
    #[wasm_bindgen(js_name = areaRatios)]
    pub fn area_ratios(&self) -> Vec<f32> {
        let mut out = vec![0.0; self.inner.voxel_count()];
        self.inner.write_area_ratios(&mut out);
        out
    }

    /// Rigid corner squares (1.2 m wide), length 12n: for voxel i at `12i`, four
    /// triples centre x, centre y, angle (rad) in the order SW, SE, NE, NW.
    #[wasm_bindgen(js_name = cornerBodies)]
    pub fn corner_bodies(&self) -> Vec<f32> {
        let mut out = vec![0.0; 12 * self.inner.voxel_count()];
        self.inner.write_corner_bodies(&mut out);
        out
    }

    /// Terrain polyline x coordinates (m), walls included; pairs with [`Self::terrain_ys`].
    #[wasm_bindgen(js_name = terrainXs)]
    pub fn terrain_xs(&self) -> Vec<f64> {
        self.inner.terrain().xs().to_vec()
    }

    /// Terrain polyline y coordinates (m, y up), walls included.
    #[wasm_bindgen(js_name = terrainYs)]
    pub fn terrain_ys(&self) -> Vec<f64> {
        self.inner.terrain().ys().to_vec()
    }
}
