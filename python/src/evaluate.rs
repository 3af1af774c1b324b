//! `param_count` and `evaluate`: many genomes of one robot on one terrain, each row the
//! episode `vsr evaluate` runs, scored as evolution scores it (`vsr::experiment::evaluate::
//! fitness`: the velocity, NaN if the simulation exploded; sensor noise seeded by
//! `noise_seed`), on a pool with the GIL released, Ctrl-C seen and progress logged between
//! chunks (`batch`). The velocities come back in row order whatever the number of threads.

use numpy::{PyArray1, PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::prelude::*;
use vsr::experiment::evaluate::fitness;

use crate::args::{optional_threads, robot, rows, setup, whole};
use crate::batch::Pool;
use crate::errors::to_py;

/// Genome length of `controller` on `shape`.
#[pyfunction]
pub fn param_count(shape: &str, controller: &str) -> PyResult<usize> {
    let (shape, kind) = robot(shape, controller)?;
    Ok(kind.param_count(shape.voxel_count()))
}

/// Velocities (m/s) of each row of `genomes`; NaN where the episode became unstable (the
/// command line reports an error there instead).
#[pyfunction]
#[pyo3(signature = (genomes, shape, controller, terrain, seconds, threads, noise_seed))]
#[allow(clippy::too_many_arguments)]
pub fn evaluate<'py>(
    py: Python<'py>,
    genomes: PyReadonlyArray2<'py, f32>,
    shape: &str,
    controller: &str,
    terrain: &str,
    seconds: Bound<'py, PyAny>,
    threads: Option<Bound<'py, PyAny>>,
    noise_seed: Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let (shape, kind, terrain, seconds) = setup(shape, controller, terrain, &seconds)?;
    let threads = optional_threads(threads.as_ref())?;
    let noise = Some(whole(&noise_seed, "noise_seed")?);
    let (count, length) = (genomes.shape()[0], genomes.shape()[1]);
    let data = rows(&genomes)?;
    let row = |i: usize| &data[i * length..(i + 1) * length];
    for i in 0..count {
        let what = format!("genome {i}");
        kind.check_genome(&what, shape.voxel_count(), row(i))
            .map_err(to_py)?;
    }
    let velocities = Pool::new(threads)?.episodes(py, count, |i| {
        fitness(&shape, terrain.clone(), kind, row(i), noise, seconds)
    })?;
    Ok(PyArray1::from_vec(py, velocities))
}
