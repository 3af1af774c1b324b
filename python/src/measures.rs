//! The study's measures of one genome, as the command line takes them: `validate` is
//! `vsr validate` (`vsr::experiment::validate_on`: ten terrains, each with the sensor-noise
//! seed of its set, not `noise_seed=0`), `ablate` is `vsr ablate` with its unfrozen line
//! (`vsr::experiment::ablate`). Both run with the GIL released; their figures are the
//! command line's, bit for bit.

use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use vsr::experiment::config::MAX_SECONDS;
use vsr::experiment::ValidationSet;
use vsr::experiment::{ablate as engine_ablate, unfrozen_velocity, validate_on, Best};

use crate::args::{robot, seconds as check_seconds, whole};
use crate::errors::{input, to_py};

/// `vsr validate` of `genome`: a dict with `set`, `terrains` (names), `noise_seeds`,
/// `velocities` (float64 array), `median` and `mean`.
#[pyfunction]
#[pyo3(signature = (genome, shape, controller, set, seconds))]
pub fn validate<'py>(
    py: Python<'py>,
    genome: Vec<f32>,
    shape: &str,
    controller: &str,
    set: &str,
    seconds: Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let best = best(genome, shape, controller)?;
    let set = set.parse::<ValidationSet>().map_err(to_py)?;
    let seconds = check_seconds(&seconds)?;
    let validation = py
        .detach(|| validate_on(&best, set, seconds))
        .map_err(to_py)?;
    let (names, seeds): (Vec<String>, Vec<u64>) = set.episodes().into_iter().unzip();
    let velocities: Vec<f64> = validation.terrains.iter().map(|t| t.velocity).collect();
    let out = PyDict::new(py);
    out.set_item("set", set.name())?;
    out.set_item("terrains", names)?;
    out.set_item("noise_seeds", seeds)?;
    out.set_item("velocities", PyArray1::from_vec(py, velocities))?;
    out.set_item("median", validation.median)?;
    out.set_item("mean", validation.mean)?;
    Ok(out)
}

/// `vsr ablate` of `genome` (attention or slow-attention): a dict with `terrain`,
/// `unfrozen` (m/s), `freeze_seconds` (0..=last_second) and `velocities` (float64 array,
/// the walk with the attention frozen at each of those seconds).
#[pyfunction]
#[pyo3(signature = (genome, shape, controller, terrain, last_second, seconds))]
pub fn ablate<'py>(
    py: Python<'py>,
    genome: Vec<f32>,
    shape: &str,
    controller: &str,
    terrain: &str,
    last_second: Bound<'py, PyAny>,
    seconds: Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let best = best(genome, shape, controller)?;
    let seconds = check_seconds(&seconds)?;
    let asked = whole(&last_second, "last_second")?;
    let last_second = u32::try_from(asked)
        .ok()
        .filter(|&s| f64::from(s) <= MAX_SECONDS)
        .ok_or_else(|| {
            input(format!(
                "last_second must be at most {MAX_SECONDS}, got {asked}"
            ))
        })?;
    let (unfrozen, points) = py
        .detach(|| {
            let points = engine_ablate(&best, terrain, last_second, seconds)?;
            Ok((unfrozen_velocity(&best, terrain, seconds)?, points))
        })
        .map_err(to_py)?;
    let freeze: Vec<u32> = points.iter().map(|p| p.freeze_second).collect();
    let velocities: Vec<f64> = points.iter().map(|p| p.velocity).collect();
    let out = PyDict::new(py);
    out.set_item("terrain", terrain)?;
    out.set_item("unfrozen", unfrozen)?;
    out.set_item("freeze_seconds", PyArray1::from_vec(py, freeze))?;
    out.set_item("velocities", PyArray1::from_vec(py, velocities))?;
    Ok(out)
}

/// The genome as a run file's best individual (fitness unknown); the engine checks it.
fn best(genome: Vec<f32>, shape: &str, controller: &str) -> PyResult<Best> {
    let (shape, kind) = robot(shape, controller)?;
    Ok(Best::new(kind, shape, genome, f64::NAN))
}
