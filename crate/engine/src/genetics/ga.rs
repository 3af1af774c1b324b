//! The paper's genetic algorithm (SPEC 9): mu + lambda with overlapping generations, driven
//! by ask/tell so that a worker can evaluate in slices and in any order or parallelism.
//!
//! Batches: generation 0 asks for the `population` initial genomes (indices 0..population).
//! Every later generation asks for `2 x population` evaluations: indices `[0, population)` are
//! the current parents, best first, to be RE-EVALUATED (a parent's fitness is its latest single
//! evaluation), and indices `[population, 2 population)` are the new offspring. After `tell`,
//! parents and offspring are merged and the best `population` survive (stable: on equal fitness
//! the earlier index wins). Every evaluation counts toward the budget, which is checked before
//! each generation: the default 30000 gives generation 0 plus 150 generations, 30100 evaluations.
//!
//! All randomness comes from one `ChaCha8Rng` seeded from the run seed and consumed only in
//! `new`/`with_initial` (initial genomes) and `ask` (offspring), never by evaluation order.

use super::operators::{crossover, fitness_key, mutate, tournament};
use super::{GaConfig, GenerationStats};
use crate::{Error, Result};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

mod state;
pub use state::GaState;

/// One genome to evaluate: `index` is its position in its generation's batch (see module doc).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Candidate {
    /// Generation of the batch (0 = initial population).
    pub generation: u32,
    /// Position in the batch: parents first, then offspring.
    pub index: u32,
    /// The genome.
    pub genome: Vec<f32>,
}

/// A genome with its latest fitness.
#[derive(Debug, Clone)]
struct Scored {
    genome: Vec<f32>,
    fitness: f64,
}

/// The ask/tell GA; see the module doc for the batch layout and the budget rule.
#[derive(Debug, Clone)]
pub struct Ga {
    config: GaConfig,
    rng: ChaCha8Rng,
    /// Survivors, best first (empty until generation 0 is told).
    population: Vec<Scored>,
    /// Genomes asked and not yet told.
    pending: Option<Vec<Vec<f32>>>,
    generation: u32,
    evaluations: u64,
}

impl Ga {
    /// A GA whose initial genomes are drawn uniformly in [init_low, init_high].
    pub fn new(config: GaConfig, genome_len: usize, seed: u64) -> Result<Ga> {
        config.validate(genome_len)?;
        let mut ga = Self::empty(config, seed);
        let initial = (0..ga.config.population)
            .map(|_| ga.random_genome(genome_len, &[]))
            .collect();
        ga.pending = Some(initial);
        Ok(ga)
    }

    /// A GA whose generation 0 starts with `initial` (1 to `population` genomes of one length).
    /// The rest of the population copies the frozen prefix of `initial[0]` and draws the other
    /// genes uniformly, which is SPEC 10's fine-tuning start.
    pub fn with_initial(config: GaConfig, initial: Vec<Vec<f32>>, seed: u64) -> Result<Ga> {
        let len = initial.first().map_or(0, Vec::len);
        config.validate(len)?;
        if initial.len() > config.population {
            return Err(Error::Input(format!(
                "{} initial genomes for a population of {}",
                initial.len(),
                config.population
            )));
        }
        if let Some(i) = initial.iter().position(|g| g.len() != len) {
            return Err(Error::Input(format!(
                "initial genome {i} has length {}, genome 0 has {len}",
                initial[i].len()
            )));
        }
        if let Some(i) = initial
            .iter()
            .position(|g| g.iter().any(|v| !v.is_finite()))
        {
            return Err(Error::Input(format!(
                "initial genome {i} has a non-finite gene"
            )));
        }
        let mut ga = Self::empty(config, seed);
        let prefix = initial[0][..ga.config.frozen_prefix].to_vec();
        let mut batch = initial;
        while batch.len() < ga.config.population {
            batch.push(ga.random_genome(len, &prefix));
        }
        ga.pending = Some(batch);
        Ok(ga)
    }

    fn empty(config: GaConfig, seed: u64) -> Ga {
        Ga {
            config,
            rng: ChaCha8Rng::seed_from_u64(seed),
            population: Vec::new(),
            pending: None,
            generation: 0,
            evaluations: 0,
        }
    }

    /// `prefix` followed by genes drawn uniformly in [init_low, init_high] up to `len`.
    fn random_genome(&mut self, len: usize, prefix: &[f32]) -> Vec<f32> {
        let (low, high) = (self.config.init_low, self.config.init_high);
        let mut genome = prefix.to_vec();
        while genome.len() < len {
            genome.push(low + (high - low) * self.rng.gen::<f32>());
        }
        genome
    }

    /// The batch to evaluate next; asking again before `tell` returns the same batch. Empty
    /// once the budget is spent.
    pub fn ask(&mut self) -> Vec<Candidate> {
        if self.pending.is_none() && !self.is_done() {
            let batch = self.next_batch();
            self.pending = Some(batch);
        }
        let generation = self.generation;
        let batch = self.pending.iter().flatten();
        (0u32..)
            .zip(batch)
            .map(|(index, genome)| Candidate {
                generation,
                index,
                genome: genome.clone(),
            })
            .collect()
    }

    /// Parents (to re-evaluate) followed by `population` offspring.
    fn next_batch(&mut self) -> Vec<Vec<f32>> {
        let fitness: Vec<f64> = self.population.iter().map(|s| s.fitness).collect();
        let mut batch: Vec<Vec<f32>> = self.population.iter().map(|s| s.genome.clone()).collect();
        for _ in 0..self.config.population {
            let child = self.offspring(&fitness);
            batch.push(child);
        }
        batch
    }

    /// One offspring: crossover of two tournament winners, or mutation of one.
    fn offspring(&mut self, fitness: &[f64]) -> Vec<f32> {
        let c = &self.config;
        let use_crossover = self.rng.gen::<f64>() < c.p_crossover;
        let p1 = tournament(fitness, c.tournament, &mut self.rng).unwrap_or(0);
        let parent1 = &self.population[p1].genome;
        if use_crossover {
            let p2 = tournament(fitness, c.tournament, &mut self.rng).unwrap_or(0);
            let parent2 = &self.population[p2].genome;
            crossover(
                parent1,
                parent2,
                c.sigma_crossover,
                c.frozen_prefix,
                &mut self.rng,
            )
        } else {
            mutate(parent1, c.sigma_mutation, c.frozen_prefix, &mut self.rng)
        }
    }

    /// Reports the fitness of every candidate of the pending batch, in index order. NaN counts
    /// as -inf. Fails (changing nothing) if nothing is pending or the length is wrong.
    pub fn tell(&mut self, fitness: &[f64]) -> Result<GenerationStats> {
        let Some(batch) = self.pending.as_ref() else {
            return Err(Error::Input(
                "tell called with no batch pending: call ask first".into(),
            ));
        };
        if fitness.len() != batch.len() {
            return Err(Error::Input(format!(
                "expected {} fitness values for generation {}, got {}",
                batch.len(),
                self.generation,
                fitness.len()
            )));
        }
        let batch = self.pending.take().unwrap_or_default();
        let mut merged: Vec<Scored> = batch
            .into_iter()
            .zip(fitness)
            .map(|(genome, &f)| Scored {
                genome,
                fitness: fitness_key(f),
            })
            .collect();
        merged.sort_by(|a, b| b.fitness.total_cmp(&a.fitness));
        merged.truncate(self.config.population);
        self.population = merged;
        self.evaluations += fitness.len() as u64;
        let survivors: Vec<f64> = self.population.iter().map(|s| s.fitness).collect();
        let stats = GenerationStats::of(self.generation, self.evaluations, &survivors);
        self.generation += 1;
        Ok(stats)
    }

    /// True once generation 0 is told and the evaluations reach the budget.
    pub fn is_done(&self) -> bool {
        self.pending.is_none()
            && self.generation > 0
            && self.evaluations >= self.config.budget_evals
    }

    /// The best survivor and its latest fitness; `(&[], -inf)` before generation 0 is told.
    pub fn best(&self) -> (&[f32], f64) {
        self.population
            .first()
            .map_or((&[][..], f64::NEG_INFINITY), |s| (&s.genome[..], s.fitness))
    }

    /// Survivors, best first, with their latest fitness.
    pub fn survivors(&self) -> impl Iterator<Item = (&[f32], f64)> + '_ {
        self.population.iter().map(|s| (&s.genome[..], s.fitness))
    }

    /// Evaluations told so far.
    pub fn evaluations(&self) -> u64 {
        self.evaluations
    }

    /// Generations told so far, which is also the generation of the next (or pending) batch.
    pub fn generation(&self) -> u32 {
        self.generation
    }
}
