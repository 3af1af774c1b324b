//! Validation: re-assess an evolved individual on 10 fixed terrains and report each
//! velocity, their median and their mean. Two sets ([`ValidationSet`]):
//! - `paper`: `hilly-1-10-0` .. `hilly-1-10-9`, the paper's re-assessment terrains. They are
//!   also in the training pool (training draws `hilly-1-10-0..9999`), so they are not unseen;
//!   kept to compare with the paper.
//! - `unseen`: `hilly-1-10-10000` .. `hilly-1-10-10009`, which no training run can draw.
//!
//! The sensor noise of terrain `hilly-1-10-K` is seeded by `evaluation_seed(0, 0, K,
//! Validation)`, the same for every individual and every run, so validations are comparable
//! across runs (the paper set keeps the seeds it always had).

use super::evaluate::evaluate;
use super::run::Best;
use super::seeds::{evaluation_seed, Purpose, TERRAIN_SEEDS};
use crate::error::{Error, Result};
use crate::quantiles::median;
use crate::simulation::Terrain;
use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// Number of validation terrains in a set.
pub const VALIDATION_TERRAINS: u32 = 10;

/// A set of 10 validation terrains; see the module doc.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ValidationSet {
    /// `hilly-1-10-0..9`: the paper's terrains (also in the training pool).
    Paper,
    /// `hilly-1-10-10000..10009`: outside the training pool.
    Unseen,
}

impl ValidationSet {
    /// Both sets, paper first.
    pub const ALL: [ValidationSet; 2] = [ValidationSet::Paper, ValidationSet::Unseen];

    /// The name accepted by `FromStr`.
    pub fn name(self) -> &'static str {
        match self {
            ValidationSet::Paper => "paper",
            ValidationSet::Unseen => "unseen",
        }
    }

    /// The set's first terrain, where the frozen-attention ablation of a run on this set runs.
    pub fn first_terrain(self) -> String {
        validation_terrain(self.terrain_seed(0))
    }

    /// The set's episodes in order: each terrain's name and its sensor-noise seed. An
    /// episode of that genome on that terrain with that noise seed (`vsr evaluate
    /// --noise-seed`, `vsr.evaluate(noise_seed=...)`) is the validation's, bit for bit.
    pub fn episodes(self) -> Vec<(String, u64)> {
        (0..VALIDATION_TERRAINS)
            .map(|i| {
                let k = self.terrain_seed(i);
                (validation_terrain(k), validation_noise_seed(k))
            })
            .collect()
    }

    /// The terrain seed of the set's terrain `i` (0..10).
    pub(crate) fn terrain_seed(self, i: u32) -> u32 {
        match self {
            ValidationSet::Paper => i,
            ValidationSet::Unseen => TERRAIN_SEEDS as u32 + i,
        }
    }
}

impl fmt::Display for ValidationSet {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for ValidationSet {
    type Err = Error;

    fn from_str(s: &str) -> Result<Self> {
        Self::ALL
            .into_iter()
            .find(|v| v.name() == s.trim())
            .ok_or_else(|| {
                Error::Input(format!(
                    "unknown validation set '{s}', expected paper (hilly-1-10-0..9, the \
                     paper's) or unseen (hilly-1-10-10000..10009)"
                ))
            })
    }
}

/// The name of validation terrain `i` (`hilly-1-10-i`; the unseen set's are i >= 10000).
pub(crate) fn validation_terrain(i: u32) -> String {
    format!("hilly-1-10-{i}")
}

/// The sensor-noise seed of validation terrain `hilly-1-10-K` (also used by the ablation).
pub(crate) fn validation_noise_seed(k: u32) -> u64 {
    evaluation_seed(0, 0, k, Purpose::Validation)
}

/// The sensor-noise seed of an episode on `terrain` outside evolution: that of validation
/// terrain K for `hilly-1-10-K`, that of terrain 0 for any other terrain.
pub(crate) fn noise_seed_for(terrain: &str) -> u64 {
    let k = terrain
        .strip_prefix("hilly-1-10-")
        .and_then(|k| k.parse().ok());
    validation_noise_seed(k.unwrap_or(0))
}

/// One validation episode.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TerrainVelocity {
    /// The terrain.
    pub terrain: String,
    /// The episode's velocity (m/s).
    pub velocity: f64,
}

/// The validation of one individual.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Validation {
    /// Which terrains (absent in files written before there were two sets: paper).
    #[serde(default = "paper_set")]
    pub(crate) set: ValidationSet,
    /// One entry per terrain, in terrain order.
    pub terrains: Vec<TerrainVelocity>,
    /// Median of the velocities (mean of the middle two).
    pub median: f64,
    /// Mean of the velocities (the paper's re-assessment figure).
    #[serde(default)]
    pub mean: f64,
}

fn paper_set() -> ValidationSet {
    ValidationSet::Paper
}

/// Validates `best` on the paper's set with episodes of `seconds`; see [`validate_on`].
pub fn validate(best: &Best, seconds: f64) -> Result<Validation> {
    validate_on(best, ValidationSet::Paper, seconds)
}

/// Validates `best` on `set` with episodes of `seconds`; an episode that becomes unstable is
/// an error naming its terrain.
pub fn validate_on(best: &Best, set: ValidationSet, seconds: f64) -> Result<Validation> {
    let terrains = episodes_on(best, set, seconds)?
        .into_iter()
        .map(|(terrain, velocity)| {
            let velocity = velocity
                .map_err(|e| Error::Unstable(format!("{e} (validation terrain {terrain})")))?;
            Ok(TerrainVelocity { terrain, velocity })
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(Validation::of(set, terrains))
}

/// Every episode of `best` on `set`, in terrain order: the terrain's name and the episode's
/// velocity, or the error that stopped it (an unstable episode). A genome that does not fit
/// is an error before any episode.
pub(crate) fn episodes_on(
    best: &Best,
    set: ValidationSet,
    seconds: f64,
) -> Result<Vec<(String, Result<f64>)>> {
    best.validate("the genome")?;
    let mut out = Vec::new();
    for (name, noise) in set.episodes() {
        let terrain = Terrain::parse(&name)?;
        let velocity = evaluate(
            &best.shape,
            terrain,
            best.controller,
            &best.genome,
            Some(noise),
            seconds,
        )
        .map(|o| o.velocity);
        out.push((name, velocity));
    }
    Ok(out)
}

impl Validation {
    /// The validation of these episodes on `set`: their median and mean.
    pub(crate) fn of(set: ValidationSet, terrains: Vec<TerrainVelocity>) -> Validation {
        let velocities: Vec<f64> = terrains.iter().map(|t| t.velocity).collect();
        Validation {
            set,
            median: median(&velocities),
            mean: velocities.iter().sum::<f64>() / velocities.len() as f64,
            terrains,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn validation_terrains_are_the_papers_unseen_ones() {
        assert_eq!(validation_terrain(0), "hilly-1-10-0");
        assert_eq!(validation_terrain(9), "hilly-1-10-9");
        assert_ne!(validation_noise_seed(0), validation_noise_seed(1));
    }

    #[test]
    fn the_unseen_set_lies_outside_the_training_pool() {
        let seeds: Vec<u32> = (0..10)
            .map(|i| ValidationSet::Unseen.terrain_seed(i))
            .collect();
        assert_eq!(seeds.first(), Some(&10_000));
        assert_eq!(seeds.last(), Some(&10_009));
        assert!(seeds.iter().all(|&k| u64::from(k) >= TERRAIN_SEEDS));
        assert_eq!(ValidationSet::Paper.terrain_seed(9), 9);
        assert_eq!(
            "unseen".parse::<ValidationSet>().unwrap(),
            ValidationSet::Unseen
        );
        assert!("test".parse::<ValidationSet>().is_err());
    }
}
