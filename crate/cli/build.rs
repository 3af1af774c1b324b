//! Embeds the version of the code being built as `VSR_VERSION`: the crate version and the git
//! commit (`-dirty` with uncommitted changes to `crate/`, `Cargo.toml` or `Cargo.lock`), e.g. `0.1.0 (git 5436b58c1a2b)`; outside a git
//! checkout of this package just the crate version, or whatever the `VSR_VERSION` environment
//! variable says (for builds from a source archive). `vsr --version` prints it, `vsr campaign
//! export` and checkpoints record it, so provenance names the code that ran, not whatever
//! checkout the command happens to be run in.
//!
//! Only files that exist are watched (cargo reruns a build script on every build while a
//! watched path is missing), found through git itself so that worktrees and packed refs work.

use std::path::{Path, PathBuf};
use std::process::Command;

fn main() {
    for watched in ["crate", "Cargo.toml", "Cargo.lock"] {
        println!("cargo:rerun-if-changed={watched}");
    }
    println!("cargo:rerun-if-env-changed=VSR_VERSION");
    let crate_version = std::env::var("CARGO_PKG_VERSION").unwrap_or_default();
    let version = match std::env::var("VSR_VERSION") {
        Ok(given) if !given.trim().is_empty() => given,
        _ => match commit() {
            Some(commit) => format!("{crate_version} (git {commit})"),
            None => crate_version,
        },
    };
    println!("cargo:rustc-env=VSR_VERSION={version}");
}

/// `git describe` of this package's checkout, watching the files it depends on; `None` when
/// the package is not the top level of a git checkout (an archive, perhaps inside another
/// repository, says nothing about its own commit).
fn commit() -> Option<String> {
    let manifest = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").ok()?);
    let top = git(&manifest, &["rev-parse", "--show-toplevel"])?;
    if Path::new(&top).canonicalize().ok()? != manifest.canonicalize().ok()? {
        return None;
    }
    let head_ref = git(&manifest, &["symbolic-ref", "-q", "HEAD"]);
    let watched = ["HEAD", "index", "packed-refs"].map(String::from);
    for name in watched.iter().chain(head_ref.iter()) {
        if let Some(path) = git(&manifest, &["rev-parse", "--git-path", name]) {
            let path = manifest.join(path);
            if path.exists() {
                println!("cargo:rerun-if-changed={}", path.display());
            }
        }
    }
    let commit = git(&manifest, &["describe", "--always", "--abbrev=12"])?;
    // Dirty: uncommitted changes to what the binary is built from (not to study data, say).
    let built_from = ["crate", "Cargo.toml", "Cargo.lock"];
    let status = [&["status", "--porcelain", "--"][..], &built_from[..]].concat();
    Some(match git(&manifest, &status) {
        Some(_) => format!("{commit}-dirty"),
        None => commit,
    })
}

/// The trimmed output of a successful git command run in `dir`.
fn git(dir: &Path, args: &[&str]) -> Option<String> {
    Command::new("git")
        .current_dir(dir)
        .args(args)
        // Do not refresh the index (that would touch it and rerun this script).
        .env("GIT_OPTIONAL_LOCKS", "0")
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
        .filter(|s| !s.is_empty())
}
