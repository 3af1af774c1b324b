//! VSR Playground core: voxel-based soft robots whose every voxel runs the same
//! controller, evolved by a genetic algorithm.
//!
//! Layers point one way: `simulation` <- `controllers` <- `genetics` <- `experiment`
//! <- (`wasm` for the page, `bin/vsr` for the command line). The core has no clock,
//! no I/O and no ambient randomness: every random draw comes from an explicit seed.

pub mod controllers;
pub mod error;
pub mod experiment;
pub mod genetics;
pub mod random;
pub mod simulation;
pub mod statistics;

#[cfg(target_arch = "wasm32")]
pub mod wasm;

pub use error::{Error, Result};
