//! The one place that composes genome -> controller -> world -> fitness.

pub mod episode;
pub mod evaluate;
pub mod gait;
pub mod seeds;

pub use episode::{steps_for, topology, Episode, GaitEpisode, Outcome, Policy};
pub use gait::PhaseGait;
