//! Helpers of the `vsr` command-line tests (each test file that needs them includes this
//! module): run the binary, read its output, a scratch copy of campaigns/smoke.toml.
#![allow(dead_code)]

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs `vsr` with `args`.
pub fn vsr(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_vsr"))
        .args(args)
        .output()
        .expect("vsr runs")
}

/// Its stdout and stderr as one text.
pub fn text(out: &Output) -> String {
    String::from_utf8_lossy(&out.stdout).into_owned() + &String::from_utf8_lossy(&out.stderr)
}

/// A fresh scratch directory holding a copy of campaigns/smoke.toml.
pub fn smoke(name: &str) -> (PathBuf, String) {
    let dir = std::env::temp_dir().join(format!("vsr-campaign-{name}-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    let source = Path::new(env!("CARGO_MANIFEST_DIR")).join("campaigns/smoke.toml");
    let file = dir.join("smoke.toml");
    fs::copy(source, &file).unwrap();
    (dir, file.to_str().unwrap().to_string())
}

/// The entries of `dir`, sorted.
pub fn files_in(dir: &Path) -> Vec<PathBuf> {
    let mut all = Vec::new();
    for entry in fs::read_dir(dir).into_iter().flatten().flatten() {
        all.push(entry.path());
    }
    all.sort();
    all
}
