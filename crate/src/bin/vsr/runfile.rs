//! Reading and writing run files. Writing is atomic: the JSON goes to a temporary file in
//! the destination's directory, is flushed to disk, then renamed over the destination, so an
//! interrupted command never leaves a half-written run file.

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};

use vsr::experiment::RunFile;
use vsr::{Error, Result};

/// Reads and validates a run file, naming the file in every error.
pub fn load(path: &Path) -> Result<RunFile> {
    let text = fs::read_to_string(path)
        .map_err(|e| Error::Io(format!("cannot read run file {}: {e}", path.display())))?;
    RunFile::from_json(&text).map_err(|e| Error::Input(format!("{}: {e}", path.display())))
}

/// The directory `path` will be written in; an error if it does not exist, so that a long
/// run fails before it starts rather than at the end.
pub fn check_writable(path: &Path) -> Result<PathBuf> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    if !dir.is_dir() {
        return Err(Error::Io(format!(
            "cannot write {}: directory {} does not exist",
            path.display(),
            dir.display()
        )));
    }
    if path.is_dir() {
        return Err(Error::Io(format!(
            "cannot write {}: it is a directory",
            path.display()
        )));
    }
    Ok(dir)
}

/// Writes `run` to `path` atomically (see the module doc).
pub fn save(path: &Path, run: &RunFile) -> Result<()> {
    let dir = check_writable(path)?;
    let name = path
        .file_name()
        .map_or("run".into(), |n| n.to_string_lossy());
    let temp = dir.join(format!(".{name}.{}.tmp", std::process::id()));
    let written =
        write_synced(&temp, run.to_json().as_bytes()).and_then(|()| fs::rename(&temp, path));
    written.map_err(|e| {
        let _ = fs::remove_file(&temp);
        Error::Io(format!("cannot write run file {}: {e}", path.display()))
    })
}

fn write_synced(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let mut file = fs::File::create(path)?;
    file.write_all(bytes)?;
    file.sync_all()
}
