//! The WebAssembly boundary: the only module that uses `wasm_bindgen`.
//!
//! Thin handles over core types, one file per wrapped type, mirroring the core's tree:
//! [`Codesign`] wraps `experiment::codesign::Codesign` for the page's body search (`codesign.rs`);
//! [`Episode`] wraps `experiment::Episode` (built from a phase gait in `episode.rs`, from
//! a run file in `controlled.rs`, measured as the fitness measures in `measure.rs`); [`Evolution`] wraps `experiment::Evolution` for the page's
//! GA coordinator and [`evaluate_job`] is one evaluation of its workers (`evolution.rs`);
//! freezing a walking robot's attention and its speed so far are in `live.rs`; [`evaluate`]
//! runs one whole episode as `vsr evaluate` does, for users of the web package (`evaluate.rs`).
//! Bulk per-frame data leaves linear memory as flat `Float32Array`s whose layouts are documented on the getters that fill them
//! and, for the page, once in `www/protocol.js`. Core errors become JS `Error`s (never
//! traps) so a worker can report bad input and keep its previous state.
#![deny(clippy::unwrap_used)]

mod bench;
mod codesign;
mod controlled;
mod episode;
mod evaluate;
mod evolution;
mod live;
mod measure;
mod module;
mod page;
mod plan;

pub use bench::bench_episode;
pub use codesign::Codesign;
pub use episode::Episode;
pub use evaluate::evaluate;
pub use evolution::{evaluate_job, Evolution};
pub use live::attention_terms;
pub use module::{describe_run, run_genome};
pub use page::{
    check_gait, check_genome, check_shape, check_terrain, check_training_terrain, defaults,
    fresh_seed, remap, transplant,
};
pub use plan::run_plan;

use wasm_bindgen::prelude::wasm_bindgen;

/// Installs the panic hook so that a Rust panic (a bug, never bad input) is printed to
/// the console with its message before the trap. Call once after instantiating the module.
#[wasm_bindgen]
pub fn start() {
    console_error_panic_hook::set_once();
}
