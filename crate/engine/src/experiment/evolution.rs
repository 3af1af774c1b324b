//! An evolutionary run: the GA of `genetics` driven on locomotion episodes, ask/tell style.
//!
//! [`Evolution::next_batch`] turns the GA's candidates into [`Job`]s; each job carries
//! everything needed to evaluate it alone (genome, shape, controller, terrain name, noise seed,
//! episode length), so the caller may spread a batch over threads (the CLI, with rayon) or
//! workers (the page) and hand the fitness values back in index order to [`Evolution::tell`].
//! Candidate `index` of generation `g` is evaluated on the terrain derived from
//! `evaluation_seed(run seed, g, index, Terrain)` and with sensor noise seeded by
//! `evaluation_seed(run seed, g, index, SensorNoise)`; the GA's own stream is seeded by
//! `evaluation_seed(run seed, 0, 0, Genetics)`. Hence the result never depends on the number
//! of threads or workers. A fixed training terrain is built once, when the run starts, and
//! every job shares it (see `ground`). The core has no clock: wall times come from the caller.

use super::config::{check_seconds, EvolutionConfig};
use super::evaluate::fitness;
use super::finetune::initial_population;
use super::ground::{ground, run_ground};
use super::run::{Best, GenerationRecord, RunFile, Timing};
use super::seeds::{evaluation_seed, Purpose};
use crate::controllers::ControllerKind;
use crate::error::{Error, Result};
use crate::genetics::{Candidate, Ga, GaState};
use crate::random::rng_from;
use crate::simulation::{Shape, Terrain};
use rand::Rng;
use serde::{Deserialize, Serialize};
use std::sync::Arc;

/// The seed of a run's GA stream.
fn ga_seed(config: &EvolutionConfig) -> u64 {
    evaluation_seed(config.seed, 0, 0, Purpose::Genetics)
}

/// One evaluation to perform, self-contained. Serialized (for the page's workers) as
/// `{generation, index, shape (rows), controller, terrain, noiseSeed (decimal string: a JS
/// number cannot hold every 64-bit seed), seconds}`, without the genome, which travels
/// separately as f32 bits.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Job {
    /// Generation of the batch.
    pub generation: u32,
    /// Index in the batch (parents first, then offspring).
    pub index: u32,
    /// The genome to evaluate.
    #[serde(skip)]
    pub genome: Vec<f32>,
    /// The robot's shape (with `more_bodies`, the first body walked).
    pub(crate) shape: Shape,
    /// When the run trains on many bodies: the other bodies this evaluation walks; the
    /// fitness is the mean over every body. Empty otherwise (and then not serialized).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub(crate) more_bodies: Vec<Shape>,
    /// The controller family.
    pub(crate) controller: ControllerKind,
    /// The terrain name, e.g. `hilly-1-10-4821`.
    pub(crate) terrain: String,
    /// Seed of the sensor-noise stream.
    #[serde(with = "super::json::decimal")]
    pub(crate) noise_seed: u64,
    /// Simulated seconds.
    pub(crate) seconds: f64,
    /// The run's ground when every job shares it (a fixed terrain), built once per run.
    #[serde(skip)]
    pub(super) ground: Option<Arc<Terrain>>,
}

impl Job {
    /// The fitness of this job: the episode's velocity, NaN (the worst) if it exploded. A
    /// terrain that does not parse, a genome that does not fit or a bad episode length is an
    /// error, never a fitness.
    pub fn fitness(&self) -> Result<f64> {
        let terrain = match &self.ground {
            Some(shared) if shared.name() == self.terrain.trim() => Arc::clone(shared),
            _ => ground(&self.terrain)?,
        };
        check_seconds(self.seconds)?;
        let n_voxels = self.shape.voxel_count();
        self.controller
            .check_genome("the job's genome", n_voxels, &self.genome)?;
        let bodies = std::iter::once(&self.shape).chain(&self.more_bodies);
        let speeds = bodies.map(|shape| {
            fitness(
                shape,
                Arc::clone(&terrain),
                self.controller,
                &self.genome,
                Some(self.noise_seed),
                self.seconds,
            )
        });
        // The mean over the bodies (NaN, the worst, if any exploded).
        let sum: f64 = speeds.sum();
        Ok(sum / (1 + self.more_bodies.len()) as f64)
    }
}

/// An evolutionary run in progress; see the module doc.
#[derive(Debug, Clone)]
pub struct Evolution {
    config: EvolutionConfig,
    ga: Ga,
    history: Vec<GenerationRecord>,
    ground: Option<Arc<Terrain>>,
}

impl Evolution {
    /// Starts a run: from scratch, or as a fine-tuning run when `config.source` is set
    /// (SPEC 10, see `initial_population`). Fails on an invalid configuration.
    pub fn new(config: EvolutionConfig) -> Result<Evolution> {
        config.validate()?;
        let ga_seed = ga_seed(&config);
        let ga = match &config.source {
            None => Ga::new(config.ga.clone(), config.genome_len(), ga_seed)?,
            Some(source) => {
                let initial = initial_population(&config, source);
                Ga::with_initial(config.ga.clone(), initial, ga_seed)?
            }
        };
        Ok(Evolution {
            ground: run_ground(&config.terrain)?,
            config,
            ga,
            history: Vec::new(),
        })
    }

    /// A run from scratch whose genomes have `genome_len` genes instead of the controller's own
    /// count: only for a measurement that evaluates its jobs itself (`body_set::measure`, the
    /// local inputs measured with a longer, masked genome).
    #[cfg(test)]
    pub(crate) fn with_genome_len(config: EvolutionConfig, genome_len: usize) -> Result<Evolution> {
        let ga = Ga::new(config.ga.clone(), genome_len, ga_seed(&config))?;
        Ok(Evolution {
            ground: run_ground(&config.terrain)?,
            config,
            ga,
            history: Vec::new(),
        })
    }

    /// A run continued from a GA state and the records of the generations before it (see
    /// `checkpoint`). The configuration is the one the state was taken from.
    pub(super) fn from_parts(
        config: EvolutionConfig,
        state: &GaState,
        history: Vec<GenerationRecord>,
    ) -> Result<Evolution> {
        config.validate()?;
        let ga = Ga::from_state(
            config.ga.clone(),
            config.genome_len(),
            ga_seed(&config),
            state,
        )?;
        Ok(Evolution {
            ground: run_ground(&config.terrain)?,
            config,
            ga,
            history,
        })
    }

    /// The GA's exact state between generations (see `checkpoint`).
    pub(super) fn ga_state(&self) -> Option<GaState> {
        self.ga.state()
    }

    /// The jobs of the pending generation (the same until told); empty once the budget is spent.
    pub fn next_batch(&mut self) -> Vec<Job> {
        self.ga.ask().into_iter().map(|c| self.job(c)).collect()
    }

    fn job(&self, c: Candidate) -> Job {
        let (seed, g, i) = (self.config.seed, c.generation, c.index);
        let terrain_seed = evaluation_seed(seed, g, i, Purpose::Terrain);
        let (shape, more_bodies) = match &self.config.bodies {
            None => (self.config.shape.clone(), Vec::new()),
            Some(bodies) => {
                let seed = evaluation_seed(seed, g, i, Purpose::Bodies);
                let mut drawn = draw_bodies(&bodies.set.bodies, bodies.per_evaluation, seed);
                let first = drawn.remove(0);
                (first, drawn)
            }
        };
        Job {
            generation: g,
            index: i,
            genome: c.genome,
            shape,
            more_bodies,
            controller: self.config.controller,
            terrain: self.config.terrain.name_for(terrain_seed),
            noise_seed: evaluation_seed(seed, g, i, Purpose::SensorNoise),
            seconds: self.config.seconds,
            ground: self.ground.clone(),
        }
    }

    /// Reports the pending batch's fitness values in index order, with the caller's wall
    /// seconds since the start of the run. Fails, changing nothing, on a wrong count.
    pub fn tell(&mut self, fitness: &[f64], wall_seconds: f64) -> Result<GenerationRecord> {
        let stats = self.ga.tell(fitness)?;
        let mut record = GenerationRecord::new(&stats, wall_seconds);
        if let Some(best) = self.best() {
            (record.alpha, record.eta) = (best.alpha, best.eta);
        }
        self.history.push(record);
        Ok(record)
    }

    /// Runs to the end of the budget: `evaluate_batch` returns one fitness per job, in order
    /// (or the error of a job that cannot be evaluated, which stops the run);
    /// `on_generation` sees the run after each generation (its record is the last of
    /// `history()`; a caller may checkpoint it there) and may stop the run with an error;
    /// `clock` gives the wall seconds since the start (return 0.0 where there is no clock).
    pub fn run(
        &mut self,
        mut evaluate_batch: impl FnMut(&[Job]) -> Result<Vec<f64>>,
        mut on_generation: impl FnMut(&Evolution) -> Result<()>,
        mut clock: impl FnMut() -> f64,
    ) -> Result<()> {
        loop {
            let jobs = self.next_batch();
            if jobs.is_empty() {
                return Ok(());
            }
            let fitness = evaluate_batch(&jobs)?;
            self.tell(&fitness, clock())?;
            on_generation(self)?;
        }
    }

    /// True once the budget is spent.
    pub fn is_done(&self) -> bool {
        self.ga.is_done()
    }

    /// Evaluations told so far.
    pub fn evaluations(&self) -> u64 {
        self.ga.evaluations()
    }

    /// Evaluations the whole run will take (`planned_evaluations`).
    pub fn planned_evaluations(&self) -> u64 {
        planned_evaluations(
            self.config.ga.population as u64,
            self.config.ga.budget_evals,
        )
    }

    /// The configuration.
    pub fn config(&self) -> &EvolutionConfig {
        &self.config
    }

    /// Records of the generations told so far.
    pub fn history(&self) -> &[GenerationRecord] {
        &self.history
    }

    /// The current best individual; `None` before generation 0 is told.
    pub fn best(&self) -> Option<Best> {
        let (genome, fitness) = self.ga.best();
        if genome.is_empty() {
            return None;
        }
        let (kind, shape) = (self.config.controller, self.config.shape.clone());
        Some(Best::new(kind, shape, genome.to_vec(), fitness))
    }

    /// The run file of the run so far; fails before generation 0 is told.
    pub fn run_file(&self, timing: Option<Timing>) -> Result<RunFile> {
        let best = self.best().ok_or_else(|| {
            Error::Input("no generation has been evaluated yet: there is no best".into())
        })?;
        Ok(RunFile::new(
            self.config.clone(),
            self.history.clone(),
            best,
            timing,
        ))
    }
}

/// `k` distinct bodies of `set` (k >= 1, at most its length), drawn by a partial Fisher-Yates
/// shuffle seeded by `seed`, in the order drawn.
fn draw_bodies(set: &[Shape], k: usize, seed: u64) -> Vec<Shape> {
    let mut order: Vec<usize> = (0..set.len()).collect();
    let mut rng = rng_from(seed);
    let k = k.clamp(1, set.len().max(1));
    for j in 0..k {
        let pick = rng.gen_range(j..order.len());
        order.swap(j, pick);
    }
    order[..k].iter().map(|&i| set[i].clone()).collect()
}

/// Generations after generation 0 that a run of `population` and `budget` evaluations takes:
/// each evaluates two populations (the parents again, on fresh terrains, and as many
/// children), and the last one is completed even when it passes the budget.
pub fn planned_generations(population: u64, budget: u64) -> u64 {
    budget
        .saturating_sub(population)
        .div_ceil(2 * population.max(1))
}

/// Evaluations a run of `population` and `budget` evaluations takes: generation 0 (the
/// first population) plus two populations per later generation (30100 for the paper's
/// 30000 with 100, 2020 for 2000 with 20).
pub fn planned_evaluations(population: u64, budget: u64) -> u64 {
    population + 2 * population * planned_generations(population, budget)
}
