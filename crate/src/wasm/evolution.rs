//! [`Evolution`]: a JS handle on one `experiment::Evolution` (ask/tell), owned by the page's
//! GA coordinator worker, and [`evaluate_job`], the one evaluation an evaluation worker runs.
//!
//! `ask()` returns the pending generation's jobs as JSON (everything but the genomes: the
//! noise seed as a decimal string, since a JS number cannot hold every 64-bit seed) and
//! `genomes()` their genomes as one flat `Float32Array` (job i at `i * genomeLength`), so
//! genes cross the boundary as f32 bits, never through decimal text. The coordinator hands
//! each job to any worker and calls `tell` with the fitness values in job order: the result
//! never depends on which worker evaluated what.

use serde::Serialize;
use wasm_bindgen::prelude::{wasm_bindgen, JsError};

use crate::controllers::ControllerKind;
use crate::experiment::{Evolution as CoreEvolution, EvolutionConfig, Job, Timing};
use crate::simulation::{Shape, Terrain};

/// What `ask()` reports per job (the genome travels separately, see the module doc).
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct JobInfo<'a> {
    generation: u32,
    index: u32,
    shape: String,
    controller: String,
    terrain: &'a str,
    noise_seed: String,
    seconds: f64,
}

/// An evolutionary run in progress, driven by the page's coordinator.
#[wasm_bindgen]
pub struct Evolution {
    inner: CoreEvolution,
    pending: Vec<Job>,
}

#[wasm_bindgen]
impl Evolution {
    /// Starts a run from its configuration, as JSON in the run file's `config` layout
    /// (`shape`, `controller`, `seed`, `seconds`, `terrain`, `ga`: missing GA fields take
    /// the paper's values). A malformed or invalid configuration throws an `Error`.
    #[wasm_bindgen(constructor)]
    pub fn new(config: &str) -> Result<Evolution, JsError> {
        let config: EvolutionConfig = serde_json::from_str(config)
            .map_err(|e| JsError::new(&format!("bad evolution settings: {e}")))?;
        let inner = CoreEvolution::new(config)?;
        Ok(Evolution {
            inner,
            pending: Vec::new(),
        })
    }

    /// The pending generation's jobs as a JSON array of `{generation, index, shape,
    /// controller, terrain, noiseSeed (decimal string), seconds}`; `[]` once the budget is
    /// spent. Asking again before `tell` returns the same jobs.
    pub fn ask(&mut self) -> Result<String, JsError> {
        self.pending = self.inner.next_batch();
        let infos: Vec<JobInfo> = self.pending.iter().map(job_info).collect();
        serde_json::to_string(&infos).map_err(|e| JsError::new(&e.to_string()))
    }

    /// The pending jobs' genomes, flat: job i at `i * genomeLength`.
    pub fn genomes(&self) -> Vec<f32> {
        self.pending
            .iter()
            .flat_map(|j| j.genome.iter().copied())
            .collect()
    }

    /// Genes per genome.
    #[wasm_bindgen(getter, js_name = genomeLength)]
    pub fn genome_length(&self) -> usize {
        self.inner.config().genome_len()
    }

    /// Reports the pending jobs' fitness values in job order (NaN for an exploded episode)
    /// with the wall seconds since the start, and returns the generation's record as JSON
    /// (`generation`, `evaluations`, `best`, `q3`, `median`, `q1`, `worst`, `wall_seconds`;
    /// non-finite values as null). A wrong count, or no pending batch, throws and changes nothing.
    pub fn tell(&mut self, fitness: &[f64], wall_seconds: f64) -> Result<String, JsError> {
        if self.pending.is_empty() {
            return Err(JsError::new(
                "tell called with no jobs pending: call ask first",
            ));
        }
        let record = self.inner.tell(fitness, wall_seconds)?;
        self.pending.clear();
        serde_json::to_string(&record).map_err(|e| JsError::new(&e.to_string()))
    }

    /// Evaluations told so far.
    #[wasm_bindgen(getter)]
    pub fn evaluations(&self) -> f64 {
        self.inner.evaluations() as f64
    }

    /// Evaluations the whole run takes (the initial population plus whole generations).
    #[wasm_bindgen(getter, js_name = plannedEvaluations)]
    pub fn planned_evaluations(&self) -> f64 {
        self.inner.planned_evaluations() as f64
    }

    /// True once the budget is spent.
    #[wasm_bindgen(getter, js_name = isDone)]
    pub fn is_done(&self) -> bool {
        self.inner.is_done()
    }

    /// The current best's fitness (its latest evaluation, m/s); -Infinity before generation 0
    /// is told.
    #[wasm_bindgen(getter, js_name = bestFitness)]
    pub fn best_fitness(&self) -> f64 {
        self.inner.best().map_or(f64::NEG_INFINITY, |b| b.fitness)
    }

    /// The run so far as a run file (JSON text, the format `vsr evolve` writes), with how it
    /// ran: `workers` evaluation workers and `wall_seconds` of wall time. Throws before
    /// generation 0 is told.
    #[wasm_bindgen(js_name = runFile)]
    pub fn run_file(&self, workers: usize, wall_seconds: f64) -> Result<String, JsError> {
        let timing = Timing {
            threads: workers,
            wall_seconds,
        };
        Ok(self.inner.run_file(Some(timing))?.to_json())
    }
}

fn job_info(job: &Job) -> JobInfo<'_> {
    JobInfo {
        generation: job.generation,
        index: job.index,
        shape: job.shape.to_rows(),
        controller: job.controller.to_string(),
        terrain: &job.terrain,
        noise_seed: job.noise_seed.to_string(),
        seconds: job.seconds,
    }
}

/// Evaluates one job: `genome` drives `shape` (rows or preset) with a `controller`
/// (`attention`, `mlp`, ...) on `terrain` (a full name such as `hilly-1-10-4821`) for
/// `seconds`, with sensor noise seeded by `noise_seed` (a decimal string). Returns the
/// fitness (velocity, m/s), NaN when the episode exploded; bad input throws an `Error`.
#[wasm_bindgen(js_name = evaluateJob)]
pub fn evaluate_job(
    genome: &[f32],
    shape: &str,
    controller: &str,
    terrain: &str,
    noise_seed: &str,
    seconds: f64,
) -> Result<f64, JsError> {
    let shape = Shape::parse(shape)?;
    let controller: ControllerKind = controller.parse()?;
    let noise_seed: u64 = noise_seed.trim().parse().map_err(|_| {
        JsError::new(&format!(
            "noise seed {noise_seed:?} is not an unsigned 64-bit integer"
        ))
    })?;
    Terrain::parse(terrain)?;
    let expected = controller.param_count(shape.voxel_count());
    if genome.len() != expected {
        return Err(JsError::new(&format!(
            "a {controller} controller for {} has {expected} genes, the job has {}",
            shape.to_rows(),
            genome.len()
        )));
    }
    if !(seconds > 0.0 && seconds.is_finite()) {
        return Err(JsError::new(&format!(
            "episode seconds must be positive, got {seconds}"
        )));
    }
    let job = Job {
        generation: 0,
        index: 0,
        genome: genome.to_vec(),
        shape,
        controller,
        terrain: terrain.to_string(),
        noise_seed,
        seconds,
    };
    Ok(job.fitness())
}
