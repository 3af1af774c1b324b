//! The one place that composes genome -> controller -> world -> fitness: episodes, evaluation
//! seeds, evolutionary runs and their run files, fine-tuning (and the page's transplant),
//! validation, the ablation, and the playground's defaults.

pub(crate) mod ablation;
pub mod body_set;
pub(crate) mod checkpoint;
pub mod codesign;
pub mod config;
pub(crate) mod ensemble;
pub(crate) mod episode;
pub mod evaluate;
pub mod evolution;
pub(crate) mod finetune;
pub(crate) mod freeze;
pub(crate) mod gait;
mod ground;
mod json;
pub mod playground;
pub(crate) mod policy;
pub mod run;
pub mod seeds;
mod together;
pub(crate) mod trajectory;
pub mod validation;

pub use ablation::{ablate, unfrozen_velocity, AblationPoint, ABLATION_TERRAIN};
pub use body_set::BodySet;
pub use checkpoint::Checkpoint;
pub use codesign::{
    best_and_seconds_in_file, best_in_file, BrainMode, Codesign, CodesignConfig, CodesignRun,
};
pub use config::{EvolutionConfig, SourceRun, TrainingBodies, TrainingTerrain};
pub use ensemble::{check_start_offset, gait_ensemble, Ensemble, ENSEMBLE_SHIFT};
pub use episode::{simulated_seconds, steps_for, topology, Episode, GaitEpisode, Outcome, Policy};
pub use evolution::{planned_evaluations, Evolution, Job};
pub use finetune::{source_of, transplant};
pub use freeze::freezable_policy;
pub use gait::PhaseGait;
pub use run::{Best, GenerationRecord, RunFile, Timing};
pub use together::fitness_together;
pub use trajectory::Frame;
pub use validation::{validate, validate_on, Validation, ValidationSet};
