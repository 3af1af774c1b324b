//! The engine of VSR Playground: voxel-based soft robots whose every voxel runs the same
//! controller, evolved by a genetic algorithm.
//!
//! Layers point one way: `simulation` <- `controllers` <- `genetics` <- `experiment`. Other
//! crates of the workspace sit on top: `vsr-wasm` (crate/wasm) for the page, `vsr-study`
//! (crate/study: campaigns, reports, statistics) and the `vsr` command line (crate/cli), and
//! the Python package (python/). The engine has no clock, no I/O and no ambient randomness:
//! every random draw comes from an explicit seed, so its numbers are the same bits native and
//! wasm.
//!
//! What is `pub` here is what those crates and the tests use; everything else is
//! `pub(crate)`.

pub mod controllers;
pub(crate) mod error;
pub mod experiment;
pub mod genetics;
pub mod quantiles;
pub mod random;
pub mod simulation;

pub use error::{Error, Result};
