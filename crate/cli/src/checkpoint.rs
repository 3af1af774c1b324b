//! The checkpoint file of a running `vsr evolve` / `vsr finetune`: `OUT.checkpoint` next to the
//! run file `OUT`, written atomically between generations at most every `--checkpoint-every`
//! seconds, read at the start (the run continues from it, bit for bit) and deleted once the
//! run file is written, or kept with the final state (`--keep-checkpoint`) so that a run with
//! a larger budget can start from it (`--continue`). See `vsr::experiment::checkpoint`.

use std::fs;
use std::path::{Path, PathBuf};
use std::time::Instant;

use vsr::experiment::{Checkpoint, Evolution, EvolutionConfig};
use vsr::{Error, Result};

/// The code writing and reading checkpoints, as `vsr --version` prints it.
const CODE: &str = env!("VSR_VERSION");

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

    /// The run `config` from its checkpoint if there is one; else from `earlier` (the final
    /// checkpoint of a run with a smaller budget, `--continue`) if that exists; else from the
    /// start. A checkpoint of another run, or a damaged one, is an error naming the file
    /// (nothing is deleted: the user decides).
    pub fn start(&self, config: EvolutionConfig, earlier: Option<&Path>) -> Result<Evolution> {
        if let Some(evolution) =
            resume_from(&self.path, &config, "delete it to start the run afresh")?
        {
            return Ok(evolution);
        }
        let Some(earlier) = earlier else {
            return Evolution::new(config);
        };
        // Another run's file, maybe: never advise deleting it.
        let advice = "leave out --continue to start this run afresh (the file is left as it is)";
        match resume_from(earlier, &config, advice)? {
            Some(evolution) => Ok(evolution),
            None => {
                eprintln!(
                    "vsr: note: {} does not exist: the run starts from generation 0",
                    earlier.display()
                );
                Evolution::new(config)
            }
        }
    }

    /// Writes the checkpoint if `every_seconds` have passed since the last one. A checkpoint
    /// that cannot be written is a warning, not the end of the run: the run file is what
    /// counts, the checkpoint only saves time.
    pub fn after_generation(&mut self, evolution: &Evolution) {
        let due = self.every_seconds > 0.0
            && self.last.elapsed().as_secs_f64() >= self.every_seconds
            && !evolution.is_done();
        let Some(checkpoint) = evolution.checkpoint(Some(CODE)).filter(|_| due) else {
            return;
        };
        let written = checkpoint
            .to_json()
            .and_then(|text| crate::atomic::write(&self.path, text.as_bytes(), "checkpoint"));
        if let Err(e) = written {
            eprintln!("vsr: warning: {e}; the run goes on without it");
        }
        self.last = Instant::now();
    }

    /// Once the run file is written: keeps the final checkpoint (`keep`: a run with a larger
    /// budget can continue this one) or deletes it.
    pub fn finish(&self, evolution: &Evolution, keep: bool) -> Result<()> {
        if keep {
            let written = evolution
                .checkpoint(Some(CODE))
                .ok_or_else(|| Error::Input("the run has no generation to keep".into()))
                .and_then(|c| c.to_json())
                .and_then(|text| crate::atomic::write(&self.path, text.as_bytes(), "checkpoint"));
            if let Err(e) = written {
                eprintln!("vsr: warning: {e}; a longer run will start from generation 0");
            }
            return Ok(());
        }
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

/// The run `config` continued from the checkpoint at `path`; `None` if there is no such file; a
/// file that cannot continue this run is an error that ends with `advice`.
fn resume_from(path: &Path, config: &EvolutionConfig, advice: &str) -> Result<Option<Evolution>> {
    let text = match fs::read_to_string(path) {
        Ok(text) => text,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => {
            return Err(Error::Io(format!(
                "cannot read checkpoint {}: {e}",
                path.display()
            )))
        }
    };
    let resumed = Checkpoint::from_json(&text).and_then(|c| {
        let at = (c.ga.generation, c.ga.evaluations, c.code.clone());
        Evolution::resume(config.clone(), c).map(|e| (e, at))
    });
    let (evolution, (generation, evaluations, code)) = resumed
        .map_err(|e| Error::Input(format!("{}: {}; {advice}", path.display(), e.message())))?;
    eprintln!(
        "resuming from {} (generation {generation}, {evaluations} evaluations done)",
        path.display()
    );
    if code.as_deref() != Some(CODE) {
        eprintln!(
            "vsr: note: the checkpoint was written by vsr {}, this is vsr {CODE}: the run is \
             the uninterrupted run bit for bit only if nothing that shapes a run (simulator, \
             controllers, GA) changed in between",
            code.as_deref().unwrap_or("(unknown version)")
        );
    }
    Ok(Some(evolution))
}
