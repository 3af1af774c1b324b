//! [`Codesign`]: a JS handle on one body search (`experiment::codesign`), owned by the page's
//! body-search coordinator worker, which hands its jobs to the same evaluation workers as an
//! evolution ([`super::evaluate_job`]). Bodies differ from job to job, so each job's genome
//! is fetched alone (`genome(i)`), as f32 bits. `vsr codesign` with the same settings gives
//! the same archive, bit for bit.

use serde::{Deserialize, Serialize};
use wasm_bindgen::prelude::{wasm_bindgen, JsError, JsValue};

use super::page::{seed_from, to_js};
use vsr::controllers::ControllerKind;
use vsr::experiment::codesign::{
    source_in_file, BrainMode, Codesign as CoreCodesign, CodesignConfig,
};
use vsr::experiment::{Job, Timing, TrainingTerrain};

/// A body search's settings as the page sends them: what `vsr codesign` takes as options.
#[derive(Deserialize)]
#[serde(deny_unknown_fields, rename_all = "camelCase")]
struct Settings {
    brain: String,
    #[serde(default)]
    controller: Option<String>,
    /// The start body's rows; default the module's own body, or a 3 x 3 box.
    #[serde(default)]
    start: Option<String>,
    seed: f64,
    seconds: f64,
    terrain: String,
    budget: u64,
    #[serde(default)]
    batch: Option<usize>,
    #[serde(default)]
    grid: Option<[usize; 2]>,
    #[serde(default)]
    voxels: Option<[usize; 2]>,
}

/// One archive entry as the gallery draws it (the genome stays in the core until asked for).
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct GalleryEntry {
    cell: [usize; 2],
    voxels: usize,
    feet: usize,
    shape: String,
    fitness: Option<f64>,
    measurements: u32,
    found: u32,
}

/// The archive's shape, for the gallery.
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Layout {
    columns: usize,
    rows: usize,
    min_voxels: usize,
    max_voxels: usize,
    size_bin: usize,
    max_feet: usize,
}

/// A body search in progress, driven by the page's coordinator.
#[wasm_bindgen]
pub struct Codesign {
    inner: CoreCodesign,
    pending: Vec<Job>,
}

#[wasm_bindgen]
impl Codesign {
    /// Starts a search as `vsr codesign` does from `{brain: 'frozen'|'finetune'|'scratch',
    /// controller?, start? (rows), seed, seconds, terrain, budget, batch?, grid?: [w, h],
    /// voxels?: [min, max]}` and, for `frozen` and `finetune`, the module's run file text
    /// (`module`, else null). Bad settings, or a module that cannot drive other bodies, throw
    /// an `Error` whose message says why.
    #[wasm_bindgen(constructor)]
    pub fn new(settings: JsValue, module: Option<String>) -> Result<Codesign, JsError> {
        let s: Settings = serde_wasm_bindgen::from_value(settings)
            .map_err(|e| JsError::new(&format!("bad body-search settings: {e}")))?;
        let brain: BrainMode = s.brain.parse()?;
        let module = match module {
            Some(text) => Some(source_in_file(&text, None)?),
            None => None,
        };
        let controller = s
            .controller
            .as_deref()
            .unwrap_or("attention")
            .parse::<ControllerKind>()?;
        let mut config = CodesignConfig::with_module(
            brain,
            module,
            controller,
            s.start.as_deref(),
            s.budget,
            seed_from(s.seed)?,
        )?;
        config.seconds = s.seconds;
        config.terrain = TrainingTerrain::parse(&s.terrain)?;
        if let Some(batch) = s.batch {
            config.batch = batch;
        }
        if let Some([w, h]) = s.grid {
            (config.grid_width, config.grid_height) = (w, h);
        }
        if let Some([min, max]) = s.voxels {
            (config.min_voxels, config.max_voxels) = (min, max);
        }
        Ok(Codesign {
            inner: CoreCodesign::new(config)?,
            pending: Vec::new(),
        })
    }

    /// The pending iteration's jobs, as `Evolution.ask` gives them (each with its own
    /// `shape`); empty once the budget is spent. Asking again before `tell` gives the same.
    pub fn ask(&mut self) -> Result<JsValue, JsError> {
        self.pending = self.inner.next_batch()?;
        to_js(&self.pending)
    }

    /// Pending job `i`'s genome (its length fits its body); empty when there is no job `i`.
    pub fn genome(&self, i: usize) -> Vec<f32> {
        self.pending
            .get(i)
            .map(|j| j.genome.clone())
            .unwrap_or_default()
    }

    /// Reports the pending jobs' fitness values in job order (NaN: exploded) with the wall
    /// seconds since the start; returns the iteration's record (`iteration`, `evaluations`,
    /// `best`, `filled`, `qd_score`, `kept`, `wall_seconds`). A wrong count throws.
    pub fn tell(&mut self, fitness: &[f64], wall_seconds: f64) -> Result<JsValue, JsError> {
        let record = self.inner.tell(fitness, wall_seconds)?;
        self.pending.clear();
        to_js(&record)
    }

    /// The archive for the gallery, in cell order: `[{cell: [size bin, feet bin], voxels,
    /// feet, shape (rows), fitness (m/s, null if exploded), measurements, found (iteration)}]`.
    pub fn gallery(&self) -> Result<JsValue, JsError> {
        let entries: Vec<GalleryEntry> = self
            .inner
            .archive()
            .elites()
            .iter()
            .map(|e| GalleryEntry {
                cell: e.cell,
                voxels: e.design.body.voxel_count(),
                feet: e.design.body.feet(),
                shape: e.design.shape().map(|s| s.to_rows()).unwrap_or_default(),
                fitness: e.fitness.is_finite().then_some(e.fitness),
                measurements: e.measurements,
                found: e.found,
            })
            .collect();
        to_js(&entries)
    }

    /// The archive's shape: `{columns (size bins), rows (feet bins), minVoxels, maxVoxels,
    /// sizeBin, maxFeet}` (a plain object).
    pub fn layout(&self) -> Result<JsValue, JsError> {
        let c = self.inner.config();
        to_js(&Layout {
            columns: c.size_bins(),
            rows: c.max_feet,
            min_voxels: c.min_voxels,
            max_voxels: c.max_voxels,
            size_bin: c.size_bin,
            max_feet: c.max_feet,
        })
    }

    /// Entry `i` (cell order) as a plain run file's `best`: `{controller, shape, genome,
    /// fitness}`, to load into the editor.
    pub fn entry(&self, i: usize) -> Result<JsValue, JsError> {
        let run = self.inner.run_file(None)?;
        to_js(&run.entry_best(i)?)
    }

    /// Evaluations told so far.
    #[wasm_bindgen(getter)]
    pub fn evaluations(&self) -> f64 {
        self.inner.evaluations() as f64
    }

    /// The evaluation budget (the last iteration may pass it).
    #[wasm_bindgen(getter)]
    pub fn budget(&self) -> f64 {
        self.inner.config().budget_evals as f64
    }

    /// True once the budget is spent.
    #[wasm_bindgen(getter, js_name = isDone)]
    pub fn is_done(&self) -> bool {
        self.inner.is_done()
    }

    /// The search so far as a co-design run file (the format `vsr codesign` writes).
    #[wasm_bindgen(js_name = runFile)]
    pub fn run_file(&self, workers: usize, wall_seconds: f64) -> Result<String, JsError> {
        let timing = Timing {
            threads: workers,
            wall_seconds,
        };
        Ok(self.inner.run_file(Some(timing))?.to_json())
    }
}
