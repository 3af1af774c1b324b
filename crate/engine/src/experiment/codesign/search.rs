//! The body search, ask/tell like [`crate::experiment::Evolution`]: each iteration asks for
//! one batch of [`Job`]s, indices `[0, k)` re-measuring the archive's `k` elites in cell order
//! and indices `[k, k + batch)` new children, each made from a parent drawn uniformly among
//! the elites by the stream `evaluation_seed(seed, iteration, index, Variation)`. Iteration 0
//! measures the start design (index 0) and `batch - 1` variations of it. Every job's terrain
//! and sensor noise derive from (seed, iteration, index) as in evolution, so the result never
//! depends on threads or workers, native or wasm, or where a run was resumed.

use super::archive::{cell_of, Archive};
use super::config::CodesignConfig;
use super::design::Design;
use super::file::{CodesignRecord, CodesignRun};
use crate::error::{Error, Result};
use crate::experiment::ground::run_ground;
use crate::experiment::run::{Best, Timing};
use crate::experiment::seeds::{evaluation_seed, Purpose};
use crate::experiment::Job;
use crate::random::rng_from;
use crate::simulation::Terrain;
use rand::Rng;
use std::sync::Arc;

/// A body search in progress; see the module doc.
#[derive(Debug, Clone)]
pub struct Codesign {
    config: CodesignConfig,
    archive: Archive,
    iteration: u32,
    evaluations: u64,
    history: Vec<CodesignRecord>,
    /// The pending batch: how many elites it re-measures, and the children after them.
    pending: Option<(usize, Vec<Design>)>,
    ground: Option<Arc<Terrain>>,
}

impl Codesign {
    /// A new search; fails on an invalid configuration (the message names the fix).
    pub fn new(config: CodesignConfig) -> Result<Codesign> {
        config.validate()?;
        Ok(Codesign {
            ground: run_ground(&config.terrain)?,
            config,
            archive: Archive::default(),
            iteration: 0,
            evaluations: 0,
            history: Vec::new(),
            pending: None,
        })
    }

    /// A search continued from its run file (a checkpoint or a finished run), bit for bit.
    pub fn resume(run: CodesignRun) -> Result<Codesign> {
        let archive = run.archive_state()?;
        let (iteration, evaluations) = (run.iteration, run.evaluations);
        let mut search = Codesign::new(run.config)?;
        search.archive = archive;
        (search.iteration, search.evaluations, search.history) =
            (iteration, evaluations, run.history);
        Ok(search)
    }

    /// The configuration.
    pub fn config(&self) -> &CodesignConfig {
        &self.config
    }

    /// The archive so far.
    pub fn archive(&self) -> &Archive {
        &self.archive
    }

    /// One record per iteration told.
    pub fn history(&self) -> &[CodesignRecord] {
        &self.history
    }

    /// Evaluations told so far.
    pub fn evaluations(&self) -> u64 {
        self.evaluations
    }

    /// Iterations told so far (the iteration of the next or pending batch).
    pub fn iteration(&self) -> u32 {
        self.iteration
    }

    /// True once iteration 0 is told and the evaluations reach the budget.
    pub fn is_done(&self) -> bool {
        self.pending.is_none() && self.iteration > 0 && self.evaluations >= self.config.budget_evals
    }

    /// The evaluations the next batch will take (elites re-measured plus children); 0 when
    /// done.
    pub fn next_batch_size(&self) -> u64 {
        if self.is_done() {
            return 0;
        }
        (self.archive.filled() + self.config.batch) as u64
    }

    fn variation_rng(&self, index: usize) -> crate::random::ProjectRng {
        let seed = evaluation_seed(
            self.config.seed,
            self.iteration,
            index as u32,
            Purpose::Variation,
        );
        rng_from(seed)
    }

    /// The jobs of the pending iteration (the same until told); empty once the budget is
    /// spent.
    pub fn next_batch(&mut self) -> Result<Vec<Job>> {
        if self.is_done() {
            return Ok(Vec::new());
        }
        if self.pending.is_none() {
            self.pending = Some(self.make_batch()?);
        }
        let Some((k, children)) = &self.pending else {
            return Ok(Vec::new());
        };
        let elites = self.archive.elites()[..*k].iter().map(|e| &e.design);
        elites
            .chain(children)
            .enumerate()
            .map(|(i, design)| self.job(i as u32, design))
            .collect()
    }

    fn make_batch(&self) -> Result<(usize, Vec<Design>)> {
        let batch = self.config.batch;
        if self.iteration == 0 {
            let seed = evaluation_seed(self.config.seed, 0, 0, Purpose::Genetics);
            let start = Design::start(&self.config, &mut rng_from(seed))?;
            let mut children = vec![start.clone()];
            for i in 1..batch {
                children.push(start.vary(&self.config, &mut self.variation_rng(i)));
            }
            return Ok((0, children));
        }
        let elites = self.archive.elites();
        let k = elites.len();
        if k == 0 {
            return Err(Error::Input(
                "every body of the first iteration exploded: the archive is empty, so the \
                 search cannot go on (try another seed or start body)"
                    .into(),
            ));
        }
        let children = (0..batch)
            .map(|j| {
                let mut rng = self.variation_rng(k + j);
                let parent = rng.gen_range(0..k as u32) as usize;
                elites[parent].design.vary(&self.config, &mut rng)
            })
            .collect();
        Ok((k, children))
    }

    fn job(&self, index: u32, design: &Design) -> Result<Job> {
        let (seed, it) = (self.config.seed, self.iteration);
        let terrain_seed = evaluation_seed(seed, it, index, Purpose::Terrain);
        Ok(Job {
            generation: it,
            index,
            genome: design.controller_genome(self.config.controller),
            shape: design.shape()?,
            more_bodies: Vec::new(),
            controller: self.config.controller,
            terrain: self.config.terrain.name_for(terrain_seed),
            noise_seed: evaluation_seed(seed, it, index, Purpose::SensorNoise),
            seconds: self.config.seconds,
            ground: self.ground.clone(),
        })
    }

    /// Reports the pending batch's fitness values in index order, with the caller's wall
    /// seconds since the start. Fails, changing nothing, if nothing is pending or the count
    /// is wrong.
    pub fn tell(&mut self, fitness: &[f64], wall_seconds: f64) -> Result<CodesignRecord> {
        let Some((k, children)) = &self.pending else {
            return Err(Error::Input(
                "tell called with no batch pending: call next_batch first".into(),
            ));
        };
        if fitness.len() != k + children.len() {
            return Err(Error::Input(format!(
                "expected {} fitness values for iteration {}, got {}",
                k + children.len(),
                self.iteration,
                fitness.len()
            )));
        }
        let Some((k, children)) = self.pending.take() else {
            return Err(Error::Input("no batch pending".into()));
        };
        for (i, &f) in fitness[..k].iter().enumerate() {
            self.archive.remeasure(i, f);
        }
        let mut kept = 0;
        for (design, &f) in children.into_iter().zip(&fitness[k..]) {
            let cell = cell_of(&self.config, &design);
            kept += usize::from(self.archive.offer(cell, design, f, self.iteration));
        }
        self.evaluations += fitness.len() as u64;
        let record = CodesignRecord {
            iteration: self.iteration,
            evaluations: self.evaluations,
            best: self.archive.best().map_or(f64::NEG_INFINITY, |e| e.fitness),
            filled: self.archive.filled(),
            qd_score: self.archive.qd_score(),
            kept,
            wall_seconds,
        };
        self.history.push(record);
        self.iteration += 1;
        Ok(record)
    }

    /// Runs to the end of the budget, as [`crate::experiment::Evolution::run`].
    pub fn run(
        &mut self,
        mut evaluate_batch: impl FnMut(&[Job]) -> Result<Vec<f64>>,
        mut on_iteration: impl FnMut(&Codesign) -> Result<()>,
        mut clock: impl FnMut() -> f64,
    ) -> Result<()> {
        loop {
            let jobs = self.next_batch()?;
            if jobs.is_empty() {
                return Ok(());
            }
            let fitness = evaluate_batch(&jobs)?;
            self.tell(&fitness, clock())?;
            on_iteration(self)?;
        }
    }

    /// The best body with its brain; `None` before iteration 0 is told.
    pub fn best(&self) -> Option<Best> {
        let elite = self.archive.best()?;
        let shape = elite.design.shape().ok()?;
        let genome = elite.design.controller_genome(self.config.controller);
        Some(Best::new(
            self.config.controller,
            shape,
            genome,
            elite.fitness,
        ))
    }

    /// The co-design run file of the search so far (a checkpoint until it is done).
    pub fn run_file(&self, timing: Option<Timing>) -> Result<CodesignRun> {
        CodesignRun::new(
            self.config.clone(),
            self.iteration,
            self.evaluations,
            self.history.clone(),
            &self.archive,
            timing,
        )
    }
}
