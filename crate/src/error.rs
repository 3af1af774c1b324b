//! One error type for the whole core. Messages are written for a person:
//! they say what was wrong and, where it helps, what would be accepted.

/// Every failure the core can report. Bad user input never panics.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// A morphology string or preset that cannot be built.
    #[error("invalid shape: {0}")]
    Shape(String),
    /// A terrain name that cannot be parsed.
    #[error("invalid terrain: {0}")]
    Terrain(String),
    /// Any other malformed argument (gait, controller, genome, run file...).
    #[error("invalid input: {0}")]
    Input(String),
    /// The simulation produced a non-finite or exploding state.
    #[error("simulation became unstable: {0}")]
    Unstable(String),
    /// Reading or writing a file failed.
    #[error("{0}")]
    Io(String),
}

/// Result with the crate's [`Error`].
pub type Result<T> = std::result::Result<T, Error>;
