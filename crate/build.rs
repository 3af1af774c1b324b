//! Embeds the version of the code being built as `VSR_VERSION`: the crate version and the git
//! commit (`-dirty` with uncommitted changes), e.g. `0.1.0 (git 5436b58c1a2b)`; outside a git
//! checkout just the crate version. `vsr --version` prints it and `vsr campaign export`
//! records it, so provenance names the code that ran, not whatever checkout the command
//! happens to be run in.

use std::process::Command;

fn main() {
    // Rerun on any change of the sources or of git's idea of the tree.
    println!("cargo:rerun-if-changed=crate/src");
    println!("cargo:rerun-if-changed=.git/HEAD");
    println!("cargo:rerun-if-changed=.git/index");
    let described = Command::new("git")
        .args(["describe", "--always", "--dirty", "--abbrev=12"])
        // Do not refresh the index (that would touch .git/index and rerun this script).
        .env("GIT_OPTIONAL_LOCKS", "0")
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string());
    let crate_version = std::env::var("CARGO_PKG_VERSION").unwrap_or_default();
    let version = match described.filter(|c| !c.is_empty()) {
        Some(commit) => format!("{crate_version} (git {commit})"),
        None => crate_version,
    };
    println!("cargo:rustc-env=VSR_VERSION={version}");
}
