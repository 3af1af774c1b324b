//! `vsr simulate --ensemble K`: the gait's velocity over K starts shifted by k x 1e-5 m
//! (SPEC 12), each velocity with their mean and sample sd, as text or JSON.

use std::time::Instant;

use vsr::experiment::{gait_ensemble, simulated_seconds, PhaseGait, ENSEMBLE_SHIFT};
use vsr::simulation::{Shape, Terrain};
use vsr::{Error, Result};

/// What one ensemble runs.
pub struct Setup<'a> {
    /// The robot.
    pub shape: &'a Shape,
    /// The terrain and its name.
    pub terrain: (&'a Terrain, &'a str),
    /// The gait.
    pub gait: PhaseGait,
    /// Simulated seconds of each run.
    pub seconds: f64,
    /// Offset of the first start (m).
    pub base: f64,
}

/// The number of runs from `--ensemble K`: at least 1.
pub fn runs(k: i64) -> Result<usize> {
    match usize::try_from(k) {
        Ok(n) if n >= 1 => Ok(n),
        _ => Err(Error::Input(format!(
            "--ensemble K needs K >= 1 runs, got {k}"
        ))),
    }
}

/// Runs the ensemble and prints it.
pub fn run(setup: &Setup, runs: usize, json: bool) -> Result<()> {
    let start = Instant::now();
    let (terrain, name) = setup.terrain;
    let e = gait_ensemble(
        setup.shape,
        terrain,
        setup.gait,
        setup.seconds,
        runs,
        setup.base,
    )?;
    let wall = start.elapsed().as_secs_f64();
    if json {
        let body = serde_json::json!({
            "shape": setup.shape.to_rows(),
            "terrain": name,
            "gait": { "frequency": setup.gait.frequency, "phase": setup.gait.phase },
            // The simulated time of each run, as a single run reports it (steps x dt).
            "seconds": simulated_seconds(setup.seconds),
            "start_offset": setup.base,
            "runs": runs,
            "offsets": e.offsets,
            "velocities": e.velocities,
            "mean": e.mean,
            "sd": e.sd,
            "wall_seconds": wall,
        });
        say!("{body}");
        return Ok(());
    }
    say!(
        "{} on {name} with gait {},{}: {runs} starts shifted by {ENSEMBLE_SHIFT} m from {} m",
        setup.shape.to_rows(),
        setup.gait.frequency,
        setup.gait.phase,
        setup.base
    );
    for (offset, v) in e.offsets.iter().zip(&e.velocities) {
        say!("  start offset {offset:.5} m: velocity {v:.4} m/s");
    }
    let sd = e.sd.map_or("-".to_string(), |s| format!("{s:.4}"));
    say!("mean {:.4} m/s, sd {sd} m/s ({wall:.2} s)", e.mean);
    Ok(())
}
