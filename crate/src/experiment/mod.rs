//! The one place that composes genome -> controller -> world -> fitness.

pub mod episode;
pub mod gait;
pub mod seeds;

pub use episode::{steps_for, GaitEpisode, Outcome};
pub use gait::PhaseGait;
