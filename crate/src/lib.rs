//! VSR Playground core: voxel-based soft robots whose every voxel runs the same
//! controller, evolved by a genetic algorithm.
//!
//! Layers point one way: `simulation` <- `controllers` <- `genetics` <- `experiment`
//! <- (`wasm` for the page, `bin/vsr` for the command line). These are the engine, what the
//! wasm build compiles. `study` (campaigns, reports, statistics) sits on `experiment` for the
//! command line only and is not compiled for wasm. The core has no clock, no I/O and no
//! ambient randomness: every random draw comes from an explicit seed.
//!
//! What is `pub` here is what the command line, the page, the Python package (`python/`) and
//! the tests use; everything else is `pub(crate)`.

pub mod controllers;
pub(crate) mod error;
pub mod experiment;
pub mod genetics;
mod quantiles;
pub mod random;
pub mod simulation;

/// The study tooling (campaigns, reports, statistics): native only, never in the wasm build.
#[cfg(not(target_arch = "wasm32"))]
pub mod study;

#[cfg(target_arch = "wasm32")]
pub mod wasm;

pub use error::{Error, Result};
