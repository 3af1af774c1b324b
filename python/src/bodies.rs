//! `evaluate_bodies`: many robots, each with its own body and genome (a researcher's own body
//! search), on one terrain, each exactly the episode `vsr evaluate --genome` runs for that
//! body and genome; on a pool with the GIL released, Ctrl-C seen and progress logged between
//! chunks (`batch`), results in input order.

use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::prelude::*;
use vsr::experiment::evaluate::fitness;
use vsr::simulation::Shape;

use crate::args::{optional_threads, seconds as check_seconds, terrain, whole};
use crate::batch::Pool;
use crate::errors::{input, to_py};

/// Velocities (m/s) of `genomes[i]` driving `controller` on `shapes[i]`; NaN where the episode
/// exploded. A length mismatch, a bad shape or a non-finite gene names its robot.
#[pyfunction]
#[pyo3(signature = (shapes, genomes, controller, terrain_name, seconds, threads, noise_seed))]
#[allow(clippy::too_many_arguments)]
pub fn evaluate_bodies<'py>(
    py: Python<'py>,
    shapes: Vec<String>,
    genomes: Vec<PyReadonlyArray1<'py, f32>>,
    controller: &str,
    terrain_name: &str,
    seconds: f64,
    threads: Option<Bound<'py, PyAny>>,
    noise_seed: Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let threads = optional_threads(threads.as_ref())?;
    let noise_seed = whole(&noise_seed, "noise_seed")?;
    if shapes.len() != genomes.len() {
        return Err(input(format!(
            "{} shapes but {} genomes: give one shape per genome",
            shapes.len(),
            genomes.len()
        )));
    }
    let kind: vsr::controllers::ControllerKind = controller.parse().map_err(to_py)?;
    let (ground, seconds) = (terrain(terrain_name)?, check_seconds(seconds)?);
    let mut robots: Vec<(Shape, Vec<f32>)> = Vec::with_capacity(shapes.len());
    for (i, (rows, genome)) in shapes.iter().zip(&genomes).enumerate() {
        let shape = Shape::parse(rows).map_err(|e| input(format!("robot {i}: {e}")))?;
        let genes = genome
            .as_slice()
            .map_err(|_| {
                input(format!(
                    "robot {i}: the genome must be a contiguous float32 array"
                ))
            })?
            .to_vec();
        kind.check_genome(&format!("robot {i}'s genome"), shape.voxel_count(), &genes)
            .map_err(to_py)?;
        robots.push((shape, genes));
    }
    let ground = std::sync::Arc::new(ground);
    let velocities = Pool::new(threads)?.episodes(py, robots.len(), |i| {
        let (shape, genes) = &robots[i];
        fitness(
            shape,
            ground.clone(),
            kind,
            genes,
            Some(noise_seed),
            seconds,
        )
    })?;
    Ok(PyArray1::from_vec(py, velocities))
}
