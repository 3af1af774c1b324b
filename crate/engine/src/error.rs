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

impl Error {
    /// The message without its kind ("the campaign file is not valid", not "invalid input:
    /// the campaign file is not valid").
    pub fn message(&self) -> &str {
        match self {
            Error::Shape(m) | Error::Terrain(m) | Error::Input(m) | Error::Unstable(m) => m,
            Error::Io(m) => m,
        }
    }

    /// The same error about `what` (a file, an item): `what: message`, its kind kept, so a
    /// message that names its file says its kind once ("invalid input: a.toml: ...").
    pub fn about(self, what: impl std::fmt::Display) -> Error {
        match self {
            Error::Shape(m) => Error::Shape(format!("{what}: {m}")),
            Error::Terrain(m) => Error::Terrain(format!("{what}: {m}")),
            Error::Input(m) => Error::Input(format!("{what}: {m}")),
            Error::Unstable(m) => Error::Unstable(format!("{what}: {m}")),
            Error::Io(m) => Error::Io(format!("{what}: {m}")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_error_about_a_file_says_its_kind_once() {
        let e = Error::Input("the campaign file is not valid".into()).about("typo.toml");
        assert_eq!(
            e.to_string(),
            "invalid input: typo.toml: the campaign file is not valid"
        );
        let shape = Error::Shape("'blob' is not a shape".into()).about("a.toml");
        assert_eq!(
            shape.to_string(),
            "invalid shape: a.toml: 'blob' is not a shape"
        );
    }
}
