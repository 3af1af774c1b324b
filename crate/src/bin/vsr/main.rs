//! `vsr`: the command-line face of VSR Playground. Each subcommand lives in its own
//! file; all of them are thin shells over the library. Bad arguments exit with code 2
//! and a message on stderr.

#[cfg(not(target_arch = "wasm32"))]
mod ablate;
#[cfg(not(target_arch = "wasm32"))]
mod atomic;
#[cfg(not(target_arch = "wasm32"))]
mod bench;
#[cfg(not(target_arch = "wasm32"))]
mod bench_evolution;
#[cfg(not(target_arch = "wasm32"))]
mod campaign;
#[cfg(not(target_arch = "wasm32"))]
mod campaign_export;
#[cfg(not(target_arch = "wasm32"))]
mod campaign_run;
#[cfg(not(target_arch = "wasm32"))]
mod checkpoint;
#[cfg(not(target_arch = "wasm32"))]
mod cli;
#[cfg(not(target_arch = "wasm32"))]
mod ensemble;
#[cfg(not(target_arch = "wasm32"))]
mod evaluate;
#[cfg(not(target_arch = "wasm32"))]
mod evolve;
#[cfg(not(target_arch = "wasm32"))]
mod finetune;
#[cfg(not(target_arch = "wasm32"))]
mod params;
#[cfg(not(target_arch = "wasm32"))]
mod report;
#[cfg(not(target_arch = "wasm32"))]
mod runfile;
#[cfg(not(target_arch = "wasm32"))]
mod simulate;
#[cfg(not(target_arch = "wasm32"))]
mod svg;
#[cfg(not(target_arch = "wasm32"))]
mod terrain;
#[cfg(not(target_arch = "wasm32"))]
mod trajectory;
#[cfg(not(target_arch = "wasm32"))]
mod validate;

#[cfg(not(target_arch = "wasm32"))]
fn main() {
    std::process::exit(cli::run());
}

/// The CLI is native only; the wasm build of the package uses the library.
#[cfg(target_arch = "wasm32")]
fn main() {}
