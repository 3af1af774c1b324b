//! Reading and writing run files. Writing is atomic (see `atomic`): an interrupted command
//! never leaves a half-written run file.

use std::fs;
use std::path::{Path, PathBuf};

use vsr::experiment::config::check_seconds;
use vsr::experiment::RunFile;
use vsr::{Error, Result};

pub use crate::atomic::check_writable;

/// The module in a run file or a co-design run file (its best body with its brain, or archive
/// entry `entry`), to fine-tune or to search bodies around, naming the file in every error.
pub fn load_source(path: &Path, entry: Option<usize>) -> Result<vsr::experiment::SourceRun> {
    let text = fs::read_to_string(path)
        .map_err(|e| Error::Io(format!("cannot read run file {}: {e}", path.display())))?;
    vsr::experiment::codesign::source_in_file(&text, entry).map_err(|e| in_file(path, e))
}

/// The individual a command walks (`vsr evaluate`, `vsr validate`, `vsr ablate`): `--genome`
/// and `--entry`.
#[derive(clap::Args, Debug)]
pub struct Individual {
    /// The run file whose best individual is walked (or a co-design run file: its best body
    /// with its brain).
    #[arg(long)]
    pub genome: PathBuf,
    /// A co-design run file's archive entry (0 first, in the file's order) instead of its best.
    #[arg(long)]
    pub entry: Option<usize>,
}

impl Individual {
    /// Its body and brain, and the episode length (s) to walk it for: `seconds` when given,
    /// else its run's own (`config.seconds` of the file), checked; errors name the file.
    pub fn load(&self, seconds: Option<f64>) -> Result<(vsr::experiment::Best, f64)> {
        seconds.map(check_seconds).transpose()?;
        let text = fs::read_to_string(&self.genome).map_err(|e| {
            Error::Io(format!(
                "cannot read run file {}: {e}",
                self.genome.display()
            ))
        })?;
        let (best, own) = vsr::experiment::best_and_seconds_in_file(&text, self.entry)
            .map_err(|e| in_file(&self.genome, e))?;
        Ok((best, seconds.unwrap_or(own)))
    }
}

/// `e` with the file named first (and said once: "invalid input" is not repeated).
fn in_file(path: &Path, e: Error) -> Error {
    match e {
        Error::Input(m) => Error::Input(format!("{}: {m}", path.display())),
        other => Error::Input(format!("{}: {other}", path.display())),
    }
}

/// Writes `run` to `path` atomically.
pub fn save(path: &Path, run: &RunFile) -> Result<()> {
    crate::atomic::write(path, run.to_json().as_bytes(), "run file")
}
