//! Ensembles of nearly identical starts (SPEC 12). The dynamics are chaotic: one run
//! of a gait means little, the distribution of its velocity over starts shifted by a
//! few hundredths of a millimetre means a lot. The reference study shifted the start by
//! k x 1e-5 m, k = 0..16; [`gait_ensemble`] does the same with K starts.

use super::episode::{Episode, Policy};
use super::gait::PhaseGait;
use crate::error::{Error, Result};
use crate::simulation::constants::{PLACEMENT_LEFT_X, VOXEL_SIDE};
use crate::simulation::{Shape, Terrain};

/// Shift between consecutive starts of an ensemble (m), as in the reference study.
pub const ENSEMBLE_SHIFT: f64 = 1e-5;

/// The velocities of one gait over shifted starts.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Ensemble {
    /// Start offset of each run (m): base + k x 1e-5.
    pub offsets: Vec<f64>,
    /// Fitness velocity of each run (m/s), same order.
    pub velocities: Vec<f64>,
    /// Mean velocity (m/s).
    pub mean: f64,
    /// Sample standard deviation (n - 1) of the velocities; None for a single run.
    pub sd: Option<f64>,
}

impl Ensemble {
    /// Summarises velocities measured at `offsets`.
    pub(crate) fn new(offsets: Vec<f64>, velocities: Vec<f64>) -> Ensemble {
        let n = velocities.len() as f64;
        let mean = velocities.iter().sum::<f64>() / n;
        let sd = (velocities.len() > 1).then(|| {
            let ss: f64 = velocities.iter().map(|v| (v - mean) * (v - mean)).sum();
            (ss / (n - 1.0)).sqrt()
        });
        Ensemble {
            offsets,
            velocities,
            mean,
            sd,
        }
    }
}

/// Checks that a robot of `shape` started `offset` metres right of the reference
/// placement (left edge at `PLACEMENT_LEFT_X`, 11 m) stands on the terrain between its walls.
pub fn check_start_offset(shape: &Shape, terrain: &Terrain, offset: f64) -> Result<()> {
    if !offset.is_finite() {
        return Err(Error::Input(format!(
            "start offset must be a finite number of metres, got {offset}"
        )));
    }
    let xs = terrain.xs();
    let (low, high) = (xs[1], xs[xs.len() - 2]);
    let left = PLACEMENT_LEFT_X + offset;
    let right = left + VOXEL_SIDE * shape.width() as f64;
    if left >= low && right <= high {
        return Ok(());
    }
    Err(Error::Input(format!(
        "start offset {offset} m puts the robot at x = {left} .. {right} m, outside the \
         ground between the walls ({low} .. {high} m): use an offset from {} to {}",
        low - PLACEMENT_LEFT_X,
        high - PLACEMENT_LEFT_X - VOXEL_SIDE * shape.width() as f64
    )))
}

/// Runs `runs` episodes of `gait` for `seconds`, the k-th started `base + k x 1e-5` m
/// right of the reference placement.
pub fn gait_ensemble(
    shape: &Shape,
    terrain: &Terrain,
    gait: PhaseGait,
    seconds: f64,
    runs: usize,
    base: f64,
) -> Result<Ensemble> {
    if runs == 0 {
        return Err(Error::Input("an ensemble needs at least one run".into()));
    }
    let offsets: Vec<f64> = (0..runs)
        .map(|k| base + k as f64 * ENSEMBLE_SHIFT)
        .collect();
    let mut velocities = Vec::with_capacity(runs);
    for &offset in &offsets {
        check_start_offset(shape, terrain, offset)?;
        let policy = Policy::Gait(gait);
        let mut e = Episode::with_start_offset(shape, terrain.clone(), policy, None, offset);
        velocities.push(e.run(seconds)?.velocity);
    }
    Ok(Ensemble::new(offsets, velocities))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mean_and_sample_sd() {
        let e = Ensemble::new(vec![0.0; 4], vec![1.0, 2.0, 3.0, 4.0]);
        assert_eq!(e.mean, 2.5);
        assert!((e.sd.unwrap() - (5.0f64 / 3.0).sqrt()).abs() < 1e-15);
        assert_eq!(Ensemble::new(vec![0.0], vec![0.7]).sd, None);
    }

    #[test]
    fn offsets_must_keep_the_robot_between_the_walls() {
        let shape = Shape::parse("biped-4x3").unwrap();
        let flat = Terrain::parse("flat").unwrap();
        assert!(check_start_offset(&shape, &flat, 0.0).is_ok());
        assert!(check_start_offset(&shape, &flat, -1.0).is_ok());
        assert!(check_start_offset(&shape, &flat, 1966.0).is_ok());
        for bad in [-1.5, 1967.5] {
            let e = check_start_offset(&shape, &flat, bad).unwrap_err();
            assert!(e.to_string().contains("between the walls"), "{e}");
        }
        for bad in [f64::NAN, f64::INFINITY] {
            let e = check_start_offset(&shape, &flat, bad).unwrap_err();
            assert!(e.to_string().contains("finite"), "{e}");
        }
    }
}
