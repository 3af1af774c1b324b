//! `--trajectory FILE` of `vsr simulate` and `vsr evaluate`: one JSON line per step
//! (the frame layout is documented in `vsr::experiment::trajectory`). The file is
//! created before the run starts, so an unwritable path fails at once.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use vsr::experiment::{Episode, Frame};
use vsr::{Error, Result};

/// A trajectory file being written.
pub struct Writer {
    out: BufWriter<File>,
    path: PathBuf,
}

impl Writer {
    /// Creates (or truncates) the file.
    pub fn create(path: &Path) -> Result<Writer> {
        let file = File::create(path)
            .map_err(|e| Error::Io(format!("cannot write --trajectory {}: {e}", path.display())))?;
        Ok(Writer {
            out: BufWriter::new(file),
            path: path.to_path_buf(),
        })
    }

    /// Appends the episode's current state as one line.
    pub fn write(&mut self, episode: &Episode) -> Result<()> {
        serde_json::to_writer(&mut self.out, &Frame::of(episode))
            .map_err(|e| self.failed(e.to_string()))?;
        self.out
            .write_all(b"\n")
            .map_err(|e| self.failed(e.to_string()))
    }

    /// Flushes the file.
    pub fn finish(mut self) -> Result<()> {
        self.out.flush().map_err(|e| self.failed(e.to_string()))
    }

    fn failed(&self, reason: String) -> Error {
        Error::Io(format!(
            "cannot write --trajectory {}: {reason}",
            self.path.display()
        ))
    }
}

/// Steps `episode` `steps` times, writing a frame after each step to `writer` if any.
pub fn run(episode: &mut Episode, steps: u64, writer: Option<Writer>) -> Result<()> {
    let Some(mut writer) = writer else {
        return Ok(());
    };
    for _ in 0..steps {
        episode.step(1)?;
        writer.write(episode)?;
    }
    writer.finish()
}
