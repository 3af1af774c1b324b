//! Embeds the git commit the code is built from (`VSR_GIT`, with `-dirty` for uncommitted
//! changes), so the provenance `vsr campaign export` writes names the code that ran, not
//! whatever checkout the command happens to be run in. Outside a git checkout nothing is
//! embedded.

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
    if let Some(commit) = described.filter(|c| !c.is_empty()) {
        println!("cargo:rustc-env=VSR_GIT={commit}");
    }
}
