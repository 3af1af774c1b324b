//! A checkpoint of the GA: its exact state between two generations, and the GA rebuilt from it.

use super::{Ga, Scored};
use crate::genetics::GaConfig;
use crate::{Error, Result};
use serde::{Deserialize, Serialize};

/// The GA between two generations, exactly: enough to continue a run bit for bit (a
/// checkpoint). Genes and fitness values are kept as their bit patterns, so no text round
/// trip can change them (an exploded evaluation's -infinity included).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct GaState {
    /// Generations told so far.
    pub generation: u32,
    /// Evaluations told so far.
    pub evaluations: u64,
    /// Survivors, best first: each gene's `f32::to_bits`.
    pub(crate) genomes: Vec<Vec<u32>>,
    /// The survivors' latest fitness: `f64::to_bits`.
    pub(crate) fitness: Vec<u64>,
    /// Words of the GA's ChaCha8 stream consumed so far.
    pub(crate) rng_word_pos: u64,
}

impl Ga {
    /// The state between generations (see [`GaState`]); `None` before generation 0 is told
    /// or while a batch is pending.
    pub(crate) fn state(&self) -> Option<GaState> {
        if self.pending.is_some() || self.generation == 0 {
            return None;
        }
        Some(GaState {
            generation: self.generation,
            evaluations: self.evaluations,
            genomes: self
                .population
                .iter()
                .map(|s| s.genome.iter().map(|g| g.to_bits()).collect())
                .collect(),
            fitness: self
                .population
                .iter()
                .map(|s| s.fitness.to_bits())
                .collect(),
            rng_word_pos: u64::try_from(self.rng.get_word_pos()).unwrap_or(u64::MAX),
        })
    }

    /// The GA of `config` and `seed` continued from `state`: asking and telling from here on
    /// gives exactly what the uninterrupted GA would. Fails on a state that does not fit the
    /// configuration (population size, genome length, non-finite genes).
    pub(crate) fn from_state(
        config: GaConfig,
        genome_len: usize,
        seed: u64,
        state: &GaState,
    ) -> Result<Ga> {
        config.validate(genome_len)?;
        let bad = |m: String| {
            Err(Error::Input(format!(
                "the checkpoint does not fit the run: {m}"
            )))
        };
        if state.generation == 0 {
            return bad("it is taken before generation 0 was evaluated".into());
        }
        if state.genomes.len() != config.population || state.fitness.len() != config.population {
            return bad(format!(
                "{} genomes and {} fitness values for a population of {}",
                state.genomes.len(),
                state.fitness.len(),
                config.population
            ));
        }
        let mut population = Vec::with_capacity(config.population);
        for (i, (bits, &fitness)) in state.genomes.iter().zip(&state.fitness).enumerate() {
            let genome: Vec<f32> = bits.iter().map(|&b| f32::from_bits(b)).collect();
            if genome.len() != genome_len || genome.iter().any(|g| !g.is_finite()) {
                return bad(format!(
                    "survivor {i} has {} genes (expected {genome_len}) or a non-finite gene",
                    genome.len()
                ));
            }
            let fitness = f64::from_bits(fitness);
            if fitness.is_nan() {
                return bad(format!("survivor {i} has a NaN fitness"));
            }
            population.push(Scored { genome, fitness });
        }
        let mut ga = Self::empty(config, seed);
        ga.rng.set_word_pos(u128::from(state.rng_word_pos));
        ga.population = population;
        ga.generation = state.generation;
        ga.evaluations = state.evaluations;
        Ok(ga)
    }
}
