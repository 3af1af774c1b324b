//! [`Evolution`]: a JS handle on one `experiment::Evolution` (ask/tell), owned by the page's
//! GA coordinator worker, and [`evaluate_job`], the one evaluation an evaluation worker runs.
//!
//! `ask()` returns the pending generation's jobs as plain objects (everything but the genomes: the
//! noise seed as a decimal string, since a JS number cannot hold every 64-bit seed) and
//! `genomes()` their genomes as one flat `Float32Array` (job i at `i * genomeLength`), so
//! genes cross the boundary as f32 bits, never through decimal text. The coordinator hands
//! each job to any worker and calls `tell` with the fitness values in job order: the result
//! never depends on which worker evaluated what.

use serde::Deserialize;
use wasm_bindgen::prelude::{wasm_bindgen, JsError, JsValue};

use super::page::{seed_from, to_js};
use vsr::controllers::ControllerKind;
use vsr::experiment::{
    codesign::source_in_file, Evolution as CoreEvolution, EvolutionConfig, Job, Timing,
    TrainingTerrain,
};
use vsr::simulation::Shape;

/// A run's settings as the page sends them: what `vsr evolve` / `vsr finetune` take as
/// options (`--shape --controller --seed --seconds --terrain --population --evals`).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Settings {
    shape: String,
    #[serde(default)]
    controller: Option<String>,
    seed: f64,
    seconds: f64,
    terrain: String,
    population: usize,
    budget: u64,
}

impl Settings {
    fn read(value: JsValue) -> Result<Settings, JsError> {
        serde_wasm_bindgen::from_value(value)
            .map_err(|e| JsError::new(&format!("bad run settings: {e}")))
    }

    /// The options every run applies on top of its paper configuration, as the CLI does.
    fn apply(&self, mut config: EvolutionConfig) -> Result<EvolutionConfig, JsError> {
        config.seconds = self.seconds;
        config.terrain = TrainingTerrain::parse(&self.terrain)?;
        config.ga.population = self.population;
        Ok(config)
    }
}

/// An evolutionary run in progress, driven by the page's coordinator.
#[wasm_bindgen]
pub struct Evolution {
    inner: CoreEvolution,
    pending: Vec<Job>,
}

#[wasm_bindgen]
impl Evolution {
    /// Starts a run from scratch, as `vsr evolve` does, from `{shape, controller, seed,
    /// seconds, terrain, population, budget}`. Invalid settings throw an `Error`.
    #[wasm_bindgen(constructor)]
    pub fn new(settings: JsValue) -> Result<Evolution, JsError> {
        let s = Settings::read(settings)?;
        let controller: ControllerKind = s.controller.as_deref().unwrap_or("").parse()?;
        let shape = Shape::parse(&s.shape)?;
        let config = EvolutionConfig::paper(shape, controller, s.budget, seed_from(s.seed)?);
        Evolution::start(s.apply(config)?)
    }

    /// Starts a fine-tuning run, as `vsr finetune --from RUN [--entry I]` does: the best
    /// individual of the run file `run_file` (of a co-design run file, its best body or
    /// archive entry `entry`) lends its 32 attention genes, frozen, to the body
    /// `settings.shape` (the controller is the source's).
    pub fn finetune(
        run_file: &str,
        settings: JsValue,
        entry: Option<usize>,
    ) -> Result<Evolution, JsError> {
        let s = Settings::read(settings)?;
        let source = source_in_file(run_file, entry)?;
        let shape = Shape::parse(&s.shape)?;
        let config = EvolutionConfig::finetune(source, shape, s.budget, seed_from(s.seed)?);
        Evolution::start(s.apply(config)?)
    }

    fn start(config: EvolutionConfig) -> Result<Evolution, JsError> {
        Ok(Evolution {
            inner: CoreEvolution::new(config)?,
            pending: Vec::new(),
        })
    }

    /// The pending generation's jobs, an array of `{generation, index, shape, controller,
    /// terrain, noiseSeed (decimal string), seconds}`; empty once the budget is spent.
    /// Asking again before `tell` returns the same jobs.
    pub fn ask(&mut self) -> Result<JsValue, JsError> {
        self.pending = self.inner.next_batch();
        to_js(&self.pending)
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
    /// with the wall seconds since the start, and returns the generation's record
    /// (`generation`, `evaluations`, `best`, `q3`, `median`, `q1`, `worst`, `wall_seconds`;
    /// non-finite values as null). A wrong count, or no pending batch, throws and changes nothing.
    pub fn tell(&mut self, fitness: &[f64], wall_seconds: f64) -> Result<JsValue, JsError> {
        if self.pending.is_empty() {
            return Err(JsError::new(
                "tell called with no jobs pending: call ask first",
            ));
        }
        let record = self.inner.tell(fitness, wall_seconds)?;
        self.pending.clear();
        to_js(&record)
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

/// Evaluates one job, as `ask()` described it, with its `genome`: the genome drives the
/// job's shape with its controller on its terrain for its seconds, with sensor noise seeded
/// by its `noiseSeed`. Returns the fitness (velocity, m/s), NaN when the episode exploded;
/// bad input throws an `Error`.
#[wasm_bindgen(js_name = evaluateJob)]
pub fn evaluate_job(job: JsValue, genome: &[f32]) -> Result<f64, JsError> {
    let mut job: Job =
        serde_wasm_bindgen::from_value(job).map_err(|e| JsError::new(&format!("bad job: {e}")))?;
    job.genome = genome.to_vec();
    Ok(job.fitness()?)
}
