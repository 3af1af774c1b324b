//! GA settings (SPEC 9 defaults) and their validation.

use crate::{Error, Result};
use serde::{Deserialize, Serialize};

/// GA settings; `Default` is the paper's. Missing fields in JSON take the default.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct GaConfig {
    /// Survivors per generation, and offspring per generation (mu = lambda = 100).
    pub population: usize,
    /// Tournament size (drawn with replacement).
    pub tournament: usize,
    /// Probability that an offspring comes from crossover (else from mutation).
    pub p_crossover: f64,
    /// Standard deviation of Gaussian mutation, per gene.
    pub sigma_mutation: f32,
    /// Standard deviation of the noise added after crossover, per gene.
    pub sigma_crossover: f32,
    /// Lower bound of the uniform initialisation.
    pub init_low: f32,
    /// Upper bound of the uniform initialisation.
    pub init_high: f32,
    /// Evaluation budget, checked before each generation after the first.
    pub budget_evals: u64,
    /// Genes `[0, frozen_prefix)` are never changed by the operators (fine-tuning).
    pub frozen_prefix: usize,
}

impl Default for GaConfig {
    fn default() -> Self {
        Self {
            population: 100,
            tournament: 5,
            p_crossover: 0.8,
            sigma_mutation: 0.35,
            sigma_crossover: 0.1,
            init_low: -1.0,
            init_high: 1.0,
            budget_evals: 30_000,
            frozen_prefix: 0,
        }
    }
}

/// The one check of a uniform initialisation range: finite ends, low <= high.
pub(crate) fn check_init_range(low: f32, high: f32) -> Result<()> {
    if low.is_finite() && high.is_finite() && low <= high {
        return Ok(());
    }
    Err(Error::Input(format!("bad init range [{low}, {high}]")))
}

/// The one check of an evaluation budget against the population (mu = lambda): at least one
/// population, so that generation 0 is whole. Every evolution's configuration (`vsr evolve`,
/// `vsr finetune`, a run file or checkpoint read) and every campaign file come through here.
pub fn check_budget(budget_evals: u64, population: usize) -> Result<()> {
    if population == 0 {
        return Err(Error::Input("the population must be at least 1".into()));
    }
    if budget_evals < population as u64 {
        return Err(Error::Input(format!(
            "an evaluation budget of {budget_evals} is less than one population of \
             {population}: the budget must cover at least the initial population"
        )));
    }
    Ok(())
}

impl GaConfig {
    /// Checks the settings against a genome length; messages say what is accepted.
    pub(crate) fn validate(&self, genome_len: usize) -> Result<()> {
        let bad = |m: String| Err(Error::Input(m));
        if self.population == 0 || self.tournament == 0 {
            return bad("population and tournament size must be at least 1".into());
        }
        if !(0.0..=1.0).contains(&self.p_crossover) {
            return bad(format!(
                "p_crossover must be in [0, 1], got {}",
                self.p_crossover
            ));
        }
        let sigmas = [self.sigma_mutation, self.sigma_crossover];
        if sigmas.iter().any(|s| !s.is_finite() || *s < 0.0) {
            return bad(format!("sigmas must be finite and >= 0, got {sigmas:?}"));
        }
        check_init_range(self.init_low, self.init_high)?;
        if genome_len == 0 || self.frozen_prefix > genome_len {
            return bad(format!(
                "genome length {genome_len} must be at least 1 and at least the frozen prefix {}",
                self.frozen_prefix
            ));
        }
        Ok(())
    }
}
