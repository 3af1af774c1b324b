//! Validation: re-assess an evolved individual on the 10 fixed unseen terrains
//! `hilly-1-10-0` .. `hilly-1-10-9` and report each velocity and their median.
//!
//! The sensor noise of terrain `i` is seeded by `evaluation_seed(0, 0, i, Validation)`, the
//! same for every individual and every run, so validations are comparable across runs.

use super::evaluate::evaluate;
use super::run::Best;
use super::seeds::{evaluation_seed, Purpose};
use crate::error::{Error, Result};
use crate::simulation::Terrain;
use serde::Serialize;

/// Number of validation terrains.
pub const VALIDATION_TERRAINS: u32 = 10;

/// The name of validation terrain `i`.
pub fn validation_terrain(i: u32) -> String {
    format!("hilly-1-10-{i}")
}

/// The sensor-noise seed of validation terrain `i` (also used by the ablation).
pub fn validation_noise_seed(i: u32) -> u64 {
    evaluation_seed(0, 0, i, Purpose::Validation)
}

/// One validation episode.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TerrainVelocity {
    /// The terrain.
    pub terrain: String,
    /// The episode's velocity (m/s).
    pub velocity: f64,
}

/// The validation of one individual.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Validation {
    /// One entry per terrain, in terrain order.
    pub terrains: Vec<TerrainVelocity>,
    /// Median of the velocities (mean of the middle two).
    pub median: f64,
}

/// Validates `best` with episodes of `seconds`; an episode that becomes unstable is an error
/// naming its terrain.
pub fn validate(best: &Best, seconds: f64) -> Result<Validation> {
    best.validate("the genome")?;
    let mut terrains = Vec::new();
    for i in 0..VALIDATION_TERRAINS {
        let name = validation_terrain(i);
        let terrain = Terrain::parse(&name)?;
        let noise = Some(validation_noise_seed(i));
        let outcome = evaluate(
            &best.shape,
            terrain,
            best.controller,
            &best.genome,
            noise,
            seconds,
        )
        .map_err(|e| Error::Unstable(format!("{e} (validation terrain {name})")))?;
        terrains.push(TerrainVelocity {
            terrain: name,
            velocity: outcome.velocity,
        });
    }
    let velocities: Vec<f64> = terrains.iter().map(|t| t.velocity).collect();
    Ok(Validation {
        median: median(&velocities),
        terrains,
    })
}

/// Median of finite values (mean of the middle two for an even count); NaN when empty.
pub fn median(values: &[f64]) -> f64 {
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    let n = sorted.len();
    match n {
        0 => f64::NAN,
        _ if n % 2 == 1 => sorted[n / 2],
        _ => 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn median_of_odd_and_even_counts() {
        assert_eq!(median(&[3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&[4.0, 1.0, 3.0, 2.0]), 2.5);
        assert!(median(&[]).is_nan());
    }

    #[test]
    fn validation_terrains_are_the_papers_unseen_ones() {
        assert_eq!(validation_terrain(0), "hilly-1-10-0");
        assert_eq!(validation_terrain(9), "hilly-1-10-9");
        assert_ne!(validation_noise_seed(0), validation_noise_seed(1));
    }
}
