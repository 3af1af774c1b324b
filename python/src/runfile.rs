//! Run files, the format `vsr evolve` writes and `vsr evaluate` and the page read
//! (`vsr::experiment::run`): checked and printed by the engine, so Python reads and writes
//! exactly what the command line does. File access stays in the Python half.

use pyo3::prelude::*;
use vsr::experiment::{Best, EvolutionConfig, RunFile, TrainingTerrain};

use crate::args::{optional_number, robot, seconds as check_seconds, whole};
use crate::errors::to_py;

/// The run file `text` checked as `vsr evaluate` checks it, printed as `vsr` prints it.
#[pyfunction]
pub fn check_run(text: &str) -> PyResult<String> {
    Ok(RunFile::from_json(text).map_err(to_py)?.to_json())
}

/// A run file for a genome evolved outside the engine (e.g. by CMA-ES): the paper's
/// configuration for `shape` and `controller` with `seed` and a budget of `evaluations`
/// (at least one GA population), episodes of `seconds` on `terrain` (the paper's 30 s and
/// hilly-1-10 when None), no generation records, `genome` as the best with `fitness`.
#[pyfunction]
#[pyo3(signature = (genome, shape, controller, fitness, seed, evaluations, seconds, terrain))]
#[allow(clippy::too_many_arguments)]
pub fn new_run(
    genome: Vec<f32>,
    shape: &str,
    controller: &str,
    fitness: Option<Bound<'_, PyAny>>,
    seed: Bound<'_, PyAny>,
    evaluations: Bound<'_, PyAny>,
    seconds: Option<Bound<'_, PyAny>>,
    terrain: Option<&str>,
) -> PyResult<String> {
    let (shape, kind) = robot(shape, controller)?;
    let (seed, evaluations) = (whole(&seed, "seed")?, whole(&evaluations, "evaluations")?);
    let fitness = optional_number(fitness.as_ref(), "fitness")?;
    let seconds = seconds.as_ref().map(check_seconds).transpose()?;
    let mut config = EvolutionConfig::paper(shape.clone(), kind, evaluations, seed);
    config.ga.budget_evals = evaluations.max(config.ga.population as u64);
    if let Some(seconds) = seconds {
        config.seconds = seconds;
    }
    if let Some(terrain) = terrain {
        config.terrain = TrainingTerrain::parse(terrain).map_err(to_py)?;
    }
    let best = Best::new(kind, shape, genome, fitness.unwrap_or(f64::NAN));
    let run = RunFile::new(config, vec![], best, None);
    run.validate().map_err(to_py)?;
    Ok(run.to_json())
}
