//! `param_count` and `evaluate`: many genomes of one robot on one terrain, each row the
//! episode `vsr evaluate` runs, scored as evolution scores it (`vsr::experiment::evaluate::
//! fitness`: the velocity, NaN if the simulation exploded; sensor noise seeded by
//! `noise_seed`), spread over a rayon pool with the GIL released. The velocities come
//! back in row order whatever the number of threads: every episode is independent.

use numpy::{PyArray1, PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::prelude::*;
use rayon::prelude::*;
use vsr::experiment::evaluate::fitness;

use crate::args::{optional_threads, robot, rows, setup, whole};
use crate::errors::{input, to_py};

/// Genome length of `controller` on `shape`.
#[pyfunction]
pub fn param_count(shape: &str, controller: &str) -> PyResult<usize> {
    let (shape, kind) = robot(shape, controller)?;
    Ok(kind.param_count(shape.voxel_count()))
}

/// Episodes per thread between two looks at Python's signals (Ctrl-C): about a second of
/// 30-s episodes.
const CHUNK_PER_THREAD: usize = 32;

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
    seconds: f64,
    threads: Option<Bound<'py, PyAny>>,
    noise_seed: Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let (shape, kind, terrain, seconds) = setup(shape, controller, terrain, seconds)?;
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
    let pool = pool(threads)?;
    // In chunks, with Python's signals looked at between them: Ctrl-C stops a large batch
    // within a chunk (KeyboardInterrupt), not at its end. Every episode is independent, so the
    // chunks change no velocity.
    let workers = pool
        .as_ref()
        .map_or_else(rayon::current_num_threads, |p| p.current_num_threads());
    let chunk = (CHUNK_PER_THREAD * workers).max(1);
    let mut velocities = Vec::with_capacity(count);
    for start in (0..count).step_by(chunk) {
        let end = (start + chunk).min(count);
        let part = py.detach(|| {
            let run = || {
                (start..end)
                    .into_par_iter()
                    .map(|i| fitness(&shape, terrain.clone(), kind, row(i), noise, seconds))
                    .collect::<Vec<f64>>()
            };
            match &pool {
                Some(pool) => pool.install(run),
                None => run(),
            }
        });
        velocities.extend(part);
        py.check_signals()?;
    }
    Ok(PyArray1::from_vec(py, velocities))
}

/// A pool of `threads` threads, or `None` for rayon's pool of all cores.
pub(crate) fn pool(threads: Option<usize>) -> PyResult<Option<rayon::ThreadPool>> {
    match threads {
        None => Ok(None),
        Some(0) => Err(input("threads must be at least 1".into())),
        Some(t) => rayon::ThreadPoolBuilder::new()
            .num_threads(t)
            .build()
            .map(Some)
            .map_err(|e| input(format!("cannot start {t} threads: {e}"))),
    }
}
