//! Atomic file writing for every file `vsr` produces (run files, validations, ablations,
//! campaign tables and figures): the bytes go to a temporary file in the destination's
//! directory, are flushed to disk, then renamed over the destination, so an interrupted
//! command never leaves a half-written file, and a file that exists is complete.

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};

use vsr::{Error, Result};

/// The directory `path` will be written in, created with its parents if missing (every job
/// makes the folders it writes in, so a campaign runs from a bare folder); an error if it
/// cannot be made, so that a long run fails before it starts rather than at the end.
pub fn check_writable(path: &Path) -> Result<PathBuf> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    fs::create_dir_all(&dir).map_err(|e| {
        Error::Io(format!(
            "cannot write {}: cannot create directory {}: {e}",
            path.display(),
            dir.display()
        ))
    })?;
    if path.is_dir() {
        return Err(Error::Io(format!(
            "cannot write {}: it is a directory",
            path.display()
        )));
    }
    Ok(dir)
}

/// Writes `bytes` to `path` atomically (see the module doc); `what` names the file in errors.
pub fn write(path: &Path, bytes: &[u8], what: &str) -> Result<()> {
    let dir = check_writable(path)?;
    let name = path
        .file_name()
        .map_or("out".into(), |n| n.to_string_lossy());
    let temp = dir.join(format!(".{name}.{}.tmp", std::process::id()));
    let written = write_synced(&temp, bytes).and_then(|()| fs::rename(&temp, path));
    written.map_err(|e| {
        let _ = fs::remove_file(&temp);
        Error::Io(format!("cannot write {what} {}: {e}", path.display()))
    })
}

/// Writes `value` as one line of JSON to `path`, atomically.
pub fn write_json<T: serde::Serialize>(path: &Path, value: &T, what: &str) -> Result<()> {
    let mut text = serde_json::to_string(value)
        .map_err(|e| Error::Io(format!("cannot encode {what} as JSON: {e}")))?;
    text.push('\n');
    write(path, text.as_bytes(), what)
}

fn write_synced(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let mut file = fs::File::create(path)?;
    file.write_all(bytes)?;
    file.sync_all()
}
