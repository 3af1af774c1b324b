//! Genetics: a genetic algorithm driven by ask/tell. It knows genomes (`Vec<f32>`) and fitness
//! values (`f64`, higher is better), never a controller or the world; the caller evaluates.
//!
//! - [`operators`]: tournament selection, Gaussian mutation, extended geometric crossover,
//!   all with an explicit RNG and an optional frozen prefix of genes they never touch;
//! - `ga`: the paper's mu + lambda GA with overlapping generations and parent
//!   re-evaluation ([`Ga`], [`GaConfig`], [`Candidate`], [`GenerationStats`]).

mod config;
pub(crate) mod ga;
pub mod operators;
mod stats;

pub(crate) use config::check_init_range;
pub use config::{check_budget, GaConfig};
pub use ga::{Candidate, Ga, GaState};
pub use stats::GenerationStats;
