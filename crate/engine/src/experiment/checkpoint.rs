//! Checkpoints: an evolutionary run stopped between two generations, kept so that it can go on
//! later exactly as if it had never stopped (the same run file, bit for bit, apart from the
//! wall times). `vsr evolve` and `vsr finetune` write one next to their output while they run
//! and delete it when the run file is written (or keep the final one, so that a run with a
//! larger budget continues it); a campaign interrupted mid-run resumes there.
//!
//! Top level: `format` ("vsr-checkpoint"), `version` (1), `config` (the run's
//! [`EvolutionConfig`]), `generations` (the records so far) and `ga` ([`GaState`]: survivors,
//! their fitness and the GA's position in its random stream, as bit patterns). Every evaluation
//! seed derives from (run seed, generation, index), so nothing else is needed to continue.

use super::config::EvolutionConfig;
use super::evolution::Evolution;
use super::run::GenerationRecord;
use crate::error::{Error, Result};
use crate::genetics::GaState;
use serde::{Deserialize, Serialize};

/// The value of the `format` field.
pub(crate) const CHECKPOINT_FORMAT: &str = "vsr-checkpoint";
/// The checkpoint version this code writes and reads.
pub(crate) const CHECKPOINT_VERSION: u32 = 1;

/// A run stopped between two generations; see the module doc.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Checkpoint {
    /// Always [`CHECKPOINT_FORMAT`].
    pub(crate) format: String,
    /// Always [`CHECKPOINT_VERSION`].
    pub(crate) version: u32,
    /// The code that wrote it (`vsr --version`), when the writer knows: a run continued by
    /// other code is bit-identical to an uninterrupted one only if nothing that shapes a run
    /// changed between the two.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub code: Option<String>,
    /// The run's configuration.
    pub(crate) config: EvolutionConfig,
    /// Per-generation records so far, generation 0 first.
    pub(crate) generations: Vec<GenerationRecord>,
    /// The GA's exact state.
    pub ga: GaState,
}

impl Checkpoint {
    /// One line of JSON, ending with a newline.
    pub fn to_json(&self) -> Result<String> {
        let mut text = serde_json::to_string(self)
            .map_err(|e| Error::Input(format!("cannot encode the checkpoint: {e}")))?;
        text.push('\n');
        Ok(text)
    }

    /// Parses a checkpoint, checking its format, version and configuration.
    pub fn from_json(text: &str) -> Result<Checkpoint> {
        let value: serde_json::Value = serde_json::from_str(text)
            .map_err(|e| Error::Input(format!("the checkpoint is not valid JSON: {e}")))?;
        let format = value.get("format").and_then(|f| f.as_str());
        if format != Some(CHECKPOINT_FORMAT) {
            return Err(Error::Input(format!(
                "this is not a vsr checkpoint: its \"format\" is not \"{CHECKPOINT_FORMAT}\""
            )));
        }
        let version = value.get("version").and_then(|v| v.as_u64());
        if version != Some(u64::from(CHECKPOINT_VERSION)) {
            return Err(Error::Input(format!(
                "checkpoint version {version:?} is not supported: this vsr reads version \
                 {CHECKPOINT_VERSION}"
            )));
        }
        let checkpoint: Checkpoint = serde_json::from_value(value)
            .map_err(|e| Error::Input(format!("the checkpoint is malformed: {e}")))?;
        checkpoint.config.validate()?;
        let last = checkpoint.generations.last().map(|g| g.evaluations);
        if checkpoint.generations.len() != checkpoint.ga.generation as usize
            || last != Some(checkpoint.ga.evaluations)
        {
            return Err(Error::Input(format!(
                "the checkpoint is inconsistent: {} generation records for generation {}, \
                 the last at {last:?} evaluations for {}",
                checkpoint.generations.len(),
                checkpoint.ga.generation,
                checkpoint.ga.evaluations
            )));
        }
        Ok(checkpoint)
    }
}

impl Evolution {
    /// The checkpoint of the run so far, written by `code`; `None` before generation 0 is
    /// told or while a batch is pending.
    pub fn checkpoint(&self, code: Option<&str>) -> Option<Checkpoint> {
        Some(Checkpoint {
            format: CHECKPOINT_FORMAT.to_string(),
            version: CHECKPOINT_VERSION,
            code: code.map(str::to_string),
            config: self.config().clone(),
            generations: self.history().to_vec(),
            ga: self.ga_state()?,
        })
    }

    /// Continues the run `config` from `checkpoint`: a checkpoint of the same run, or of a run
    /// that differs only in its budget and whose state this run passes through on its way
    /// (a run's draws never depend on its budget, so a 20,000-evaluation run's final state is
    /// the 30,000-evaluation run's state after the same generation, bit for bit). Fails, with
    /// a message saying how they differ, otherwise.
    pub fn resume(config: EvolutionConfig, checkpoint: Checkpoint) -> Result<Evolution> {
        let mut same_budget = checkpoint.config.clone();
        same_budget.ga.budget_evals = config.ga.budget_evals;
        if same_budget != config {
            return Err(Error::Input(format!(
                "the checkpoint belongs to another run ({}); this run is {}",
                describe(&checkpoint.config),
                describe(&config)
            )));
        }
        // The run reaches the state if it was not done before its last generation.
        let generations = &checkpoint.generations;
        let before_last = generations.len().checked_sub(2).map(|i| &generations[i]);
        if let Some(g) = before_last.filter(|g| g.evaluations >= config.ga.budget_evals) {
            return Err(Error::Input(format!(
                "the checkpoint is past this run's budget: this run of {} evaluations ends \
                 after generation {} ({} evaluations), the checkpoint is at generation {}",
                config.ga.budget_evals, g.generation, g.evaluations, checkpoint.ga.generation
            )));
        }
        Evolution::from_parts(config, &checkpoint.ga, checkpoint.generations)
    }
}

/// A configuration in a few words, for messages.
fn describe(c: &EvolutionConfig) -> String {
    format!(
        "{} on {}, terrain {}, seed {}, {} evaluations, population {}, {} s episodes{}",
        c.controller,
        c.shape.to_rows(),
        String::from(c.terrain.clone()),
        c.seed,
        c.ga.budget_evals,
        c.ga.population,
        c.seconds,
        if c.source.is_some() {
            ", fine-tuning"
        } else {
            ""
        }
    )
}
