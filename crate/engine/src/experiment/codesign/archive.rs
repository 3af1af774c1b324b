//! The quality-diversity archive (MAP-Elites): one elite per pair of body descriptors a
//! person reads at a glance, the body's size (voxel count, in bins) and its number of feet
//! (the pieces of its bottom row: a box has 1, the biped 2, the comb 4). Size and feet are
//! what one sees first in a drawing and what most changes a gait, so the gallery reads as
//! "small or large, hopping or walking on two, three, four feet". Each elite is re-measured
//! on a fresh terrain every iteration (as the paper's GA re-measures its parents), and its
//! fitness is the mean of its measurements, so one lucky terrain does not keep a body.

use super::config::CodesignConfig;
use super::design::Design;
use serde::{Deserialize, Serialize};

/// An archive cell: (size bin, feet bin), both from 0.
pub type Cell = [usize; 2];

/// The best design found for one cell.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Elite {
    /// Its archive cell.
    pub cell: Cell,
    /// The design.
    pub design: Design,
    /// Mean of its measurements (m/s); -infinity (null in JSON) if one exploded.
    #[serde(with = "crate::experiment::json::finite_or_null")]
    pub fitness: f64,
    /// How many measurements the mean is over.
    pub measurements: u32,
    /// The iteration in which it entered the archive.
    pub found: u32,
}

/// The archive: elites in cell order.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Archive {
    elites: Vec<Elite>,
}

/// The cell of a design under `config`'s bins.
pub fn cell_of(config: &CodesignConfig, design: &Design) -> Cell {
    let n = design.body.voxel_count();
    let size = n.saturating_sub(config.min_voxels) / config.size_bin;
    let feet = design.body.feet().clamp(1, config.max_feet) - 1;
    [size.min(config.size_bins() - 1), feet]
}

impl Archive {
    /// The elites in cell order.
    pub fn elites(&self) -> &[Elite] {
        &self.elites
    }

    /// An archive from stored elites, put in cell order.
    pub(crate) fn from_elites(mut elites: Vec<Elite>) -> Archive {
        elites.sort_by_key(|e| e.cell);
        Archive { elites }
    }

    /// Number of filled cells.
    pub fn filled(&self) -> usize {
        self.elites.len()
    }

    /// The elite with the highest fitness (the first in cell order on a tie).
    pub fn best(&self) -> Option<&Elite> {
        self.elites
            .iter()
            .fold(None, |best: Option<&Elite>, e| match best {
                Some(b) if b.fitness >= e.fitness => Some(b),
                _ => Some(e),
            })
    }

    /// The QD-score: the sum over filled cells of the elite's fitness where positive.
    pub fn qd_score(&self) -> f64 {
        self.elites.iter().map(|e| e.fitness.max(0.0)).sum()
    }

    /// Adds one measurement to elite `i`'s mean (NaN, an exploded episode, makes it -inf).
    pub(crate) fn remeasure(&mut self, i: usize, fitness: f64) {
        let e = &mut self.elites[i];
        let f = if fitness.is_nan() {
            f64::NEG_INFINITY
        } else {
            fitness
        };
        let m = f64::from(e.measurements);
        e.fitness = if e.fitness.is_finite() && f.is_finite() {
            (e.fitness * m + f) / (m + 1.0)
        } else {
            f64::NEG_INFINITY
        };
        e.measurements += 1;
    }

    /// Offers a child measured once: it takes its cell when the cell is empty or its fitness
    /// is strictly higher than the elite's. A child that exploded (NaN) is never kept.
    /// Returns whether it was kept.
    pub(crate) fn offer(
        &mut self,
        cell: Cell,
        design: Design,
        fitness: f64,
        iteration: u32,
    ) -> bool {
        if fitness.is_nan() {
            return false;
        }
        let elite = Elite {
            cell,
            design,
            fitness,
            measurements: 1,
            found: iteration,
        };
        match self.elites.binary_search_by_key(&cell, |e| e.cell) {
            Ok(i) if fitness > self.elites[i].fitness => self.elites[i] = elite,
            Ok(_) => return false,
            Err(i) => self.elites.insert(i, elite),
        }
        true
    }
}
