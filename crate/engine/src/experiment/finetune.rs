//! Fine-tuning (SPEC 10): transfer the 32-gene attention block of an evolved individual to
//! another morphology and evolve only the downstream genes.
//!
//! The initial population is the source individual (its downstream genes re-drawn if the new
//! genome has another length or the controller differs) followed by `population - 1` genomes
//! that copy the attention block and draw every other gene uniformly in
//! [init_low, init_high] (the GA fills those: [`crate::genetics::Ga::with_initial`]). The GA
//! freezes the first 32 genes (`frozen_prefix`), so every individual keeps the block
//! bit-identical. A re-drawn source downstream comes from the stream seeded by
//! `evaluation_seed(run seed, 0, 1, Genetics)`, apart from the GA's own (index 0).

use super::config::{EvolutionConfig, SourceRun};
use super::run::{Best, RunFile};
use super::seeds::{evaluation_seed, Purpose};
use crate::controllers::ATTENTION_PARAMS;
use crate::error::{Error, Result};
use crate::genetics::GaConfig;
use crate::random::rng_from;
use crate::simulation::Shape;
use rand::Rng;

/// SPEC 10's transplant, as `vsr finetune --from RUN --shape SHAPE --seed SEED` starts it:
/// the best individual of `run` put on `shape`, the first genome of that fine-tuning run
/// (`initial_population`): its 32 attention genes kept, the downstream genes re-drawn for
/// the new body (unchanged on its own body). An MLP or MLP-Comm module has no
/// body-independent part: it keeps its own body and is refused on another. A brain for any
/// body (attention-any, ...) crosses whole: one genome drives every body.
pub fn transplant(source: SourceRun, shape: Shape, seed: u64) -> Result<Vec<f32>> {
    if source.controller.is_body_independent() {
        source.controller.check_genome(
            "the module's genome",
            shape.voxel_count(),
            &source.genome,
        )?;
        return Ok(source.genome);
    }
    if !source.controller.has_attention() {
        if source.shape == shape {
            return Ok(source.genome);
        }
        return Err(Error::Input(format!(
            "only attention modules transfer to another body: this {} controller's genes \
             belong to the voxels of its own body ({}); open it with its own body, or evolve \
             one for yours",
            source.controller,
            source.shape.to_rows()
        )));
    }
    let budget = GaConfig::default().budget_evals;
    let config = EvolutionConfig::finetune(source.clone(), shape, budget, seed);
    config.validate()?;
    Ok(initial_population(&config, &source).swap_remove(0))
}

/// The first member(s) of a fine-tuning run's population: the source individual, adapted
/// to the new genome length (see the module doc). The configuration is already validated.
pub(crate) fn initial_population(config: &EvolutionConfig, source: &SourceRun) -> Vec<Vec<f32>> {
    // A brain for any body has one layout for every body: it starts whole.
    let same_layout = source.controller == config.controller
        && (source.shape == config.shape || config.controller.is_body_independent());
    if same_layout {
        return vec![source.genome.clone()];
    }
    let (low, high) = (config.ga.init_low, config.ga.init_high);
    let mut rng = rng_from(evaluation_seed(config.seed, 0, 1, Purpose::Genetics));
    let mut genome = source.genome[..ATTENTION_PARAMS].to_vec();
    while genome.len() < config.genome_len() {
        genome.push(low + (high - low) * rng.gen::<f32>());
    }
    vec![genome]
}

/// The identity of a source run for [`EvolutionConfig::finetune`]: its best individual and
/// the settings that produced it.
pub fn source_of(run: &RunFile) -> SourceRun {
    source_from(
        run.best.clone(),
        run.config.seed,
        run.config.ga.budget_evals,
    )
}

/// `best` as a source, with the seed and budget of the run (or search) that found it.
pub(crate) fn source_from(best: Best, seed: u64, budget_evals: u64) -> SourceRun {
    let Best {
        controller,
        shape,
        genome,
        fitness,
        ..
    } = best;
    SourceRun {
        shape,
        controller,
        seed,
        budget_evals,
        fitness,
        genome,
    }
}
