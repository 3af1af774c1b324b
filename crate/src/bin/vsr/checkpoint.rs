//! The checkpoint file of a running `vsr evolve` / `vsr finetune`: `OUT.checkpoint` next to the
//! run file `OUT`, written atomically between generations at most every `--checkpoint-every`
//! seconds, read at the start (the run continues from it, bit for bit) and deleted once the
//! run file is written. See `vsr::experiment::checkpoint`.

use std::fs;
use std::path::{Path, PathBuf};
use std::time::Instant;

use vsr::experiment::{Checkpoint, Evolution, EvolutionConfig};
use vsr::{Error, Result};

/// Writes a run's checkpoints and cleans up after it.
pub struct Checkpointer {
    path: PathBuf,
    every_seconds: f64,
    last: Instant,
}

impl Checkpointer {
    /// The checkpointer of the run file `out`; `every_seconds` 0 never writes one.
    pub fn new(out: &Path, every_seconds: f64) -> Result<Checkpointer> {
        if !(every_seconds >= 0.0 && every_seconds.is_finite()) {
            return Err(Error::Input(format!(
                "--checkpoint-every must be a number of seconds >= 0, got {every_seconds}"
            )));
        }
        let mut name = out.as_os_str().to_owned();
        name.push(".checkpoint");
        Ok(Checkpointer {
            path: PathBuf::from(name),
            every_seconds,
            last: Instant::now(),
        })
    }

    /// The run `config` from its checkpoint if there is one, else from the start. A
    /// checkpoint of another run, or a damaged one, is an error naming the file (nothing is
    /// deleted: the user decides).
    pub fn start(&self, config: EvolutionConfig) -> Result<Evolution> {
        let text = match fs::read_to_string(&self.path) {
            Ok(text) => text,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Evolution::new(config),
            Err(e) => {
                return Err(Error::Io(format!(
                    "cannot read checkpoint {}: {e}",
                    self.path.display()
                )))
            }
        };
        let resumed = Checkpoint::from_json(&text).and_then(|c| {
            let at = (c.ga.generation, c.ga.evaluations);
            Evolution::resume(config, c).map(|e| (e, at))
        });
        let (evolution, (generation, evaluations)) = resumed.map_err(|e| {
            Error::Input(format!(
                "{}: {e}; delete it to start the run afresh",
                self.path.display()
            ))
        })?;
        eprintln!(
            "resuming from {} (generation {generation}, {evaluations} evaluations done)",
            self.path.display()
        );
        Ok(evolution)
    }

    /// Writes the checkpoint if `every_seconds` have passed since the last one.
    pub fn after_generation(&mut self, evolution: &Evolution) -> Result<()> {
        let due = self.every_seconds > 0.0
            && self.last.elapsed().as_secs_f64() >= self.every_seconds
            && !evolution.is_done();
        if let (true, Some(checkpoint)) = (due, evolution.checkpoint()) {
            crate::atomic::write(&self.path, checkpoint.to_json().as_bytes(), "checkpoint")?;
            self.last = Instant::now();
        }
        Ok(())
    }

    /// Deletes the checkpoint once the run file is written.
    pub fn finish(&self) -> Result<()> {
        match fs::remove_file(&self.path) {
            Ok(()) => Ok(()),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(()),
            Err(e) => Err(Error::Io(format!(
                "cannot delete checkpoint {}: {e}",
                self.path.display()
            ))),
        }
    }
}
