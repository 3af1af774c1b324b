//! `evaluate_bodies`: many robots, each with its own body and genome (a researcher's own body
//! search), or one genome for every body (a brain for any body: `attention-any`, `mlp-any`,
//! `mlp-comm-any`), on one terrain, each exactly the episode `vsr evaluate --genome` runs for
//! that body and genome; on a pool with the GIL released, Ctrl-C seen and progress logged
//! between chunks (`batch`), results in input order.

use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::prelude::*;
use vsr::controllers::ControllerKind;
use vsr::experiment::evaluate::fitness;
use vsr::simulation::Shape;

use crate::args::{optional_threads, seconds as check_seconds, terrain, whole};
use crate::batch::Pool;
use crate::errors::{input, to_py};

/// Velocities (m/s) of `genomes[i]` driving `controller` on `shapes[i]` (with `shared`,
/// `genomes[0]` on every shape); NaN where the episode exploded. A length mismatch, a bad
/// shape or a non-finite gene names its robot.
#[pyfunction]
#[pyo3(signature = (shapes, genomes, controller, terrain_name, seconds, threads, noise_seed, shared))]
#[allow(clippy::too_many_arguments)]
pub fn evaluate_bodies<'py>(
    py: Python<'py>,
    shapes: Vec<String>,
    genomes: Vec<PyReadonlyArray1<'py, f32>>,
    controller: &str,
    terrain_name: &str,
    seconds: Bound<'py, PyAny>,
    threads: Option<Bound<'py, PyAny>>,
    noise_seed: Bound<'py, PyAny>,
    shared: bool,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let threads = optional_threads(threads.as_ref())?;
    let noise_seed = whole(&noise_seed, "noise_seed")?;
    if shared && genomes.len() != 1 {
        return Err(input(format!(
            "one genome for every body, but {} genomes were given",
            genomes.len()
        )));
    }
    if !shared && shapes.len() != genomes.len() {
        return Err(input(format!(
            "{} shapes but {} genomes: give one shape per genome (or one genome for every \
             body, with a controller for any body)",
            shapes.len(),
            genomes.len()
        )));
    }
    let kind: ControllerKind = controller.parse().map_err(to_py)?;
    let (ground, seconds) = (terrain(terrain_name)?, check_seconds(&seconds)?);
    let bodies = shapes
        .iter()
        .enumerate()
        .map(|(i, rows)| Shape::parse(rows).map_err(|e| input(format!("robot {i}: {e}"))))
        .collect::<PyResult<Vec<Shape>>>()?;
    let genes = genomes
        .iter()
        .enumerate()
        .map(|(i, genome)| {
            genome.as_slice().map(<[f32]>::to_vec).map_err(|_| {
                input(format!(
                    "robot {i}: the genome must be a contiguous float32 array"
                ))
            })
        })
        .collect::<PyResult<Vec<Vec<f32>>>>()?;
    if shared {
        check_shared(kind, &bodies, &genes[0])?;
    } else {
        for (i, (shape, genome)) in bodies.iter().zip(&genes).enumerate() {
            kind.check_genome(&format!("robot {i}'s genome"), shape.voxel_count(), genome)
                .map_err(to_py)?;
        }
    }
    let genome_of = |i: usize| if shared { &genes[0] } else { &genes[i] };
    let ground = std::sync::Arc::new(ground);
    let velocities = Pool::new(threads)?.episodes(py, bodies.len(), |i| {
        fitness(
            &bodies[i],
            ground.clone(),
            kind,
            genome_of(i),
            Some(noise_seed),
            seconds,
        )
    })?;
    Ok(PyArray1::from_vec(py, velocities))
}

/// One genome for every body: any number of bodies with a controller for any body, bodies of
/// one size only for a controller whose genome length follows the body (a `ValueError` that
/// says so, naming two robots of different sizes); then the genome's own check.
fn check_shared(kind: ControllerKind, bodies: &[Shape], genome: &[f32]) -> PyResult<()> {
    let Some(first) = bodies.first() else {
        return Ok(());
    };
    let n = first.voxel_count();
    if !kind.is_body_independent() {
        if let Some(j) = bodies.iter().position(|b| b.voxel_count() != n) {
            return Err(input(format!(
                "one genome for every body needs a controller for any body (attention-any, \
                 mlp-any, mlp-comm-any): the {kind} controller's genome length depends on the \
                 body's size, and robot 0 has {n} voxels but robot {j} has {}; give one genome \
                 per body",
                bodies[j].voxel_count()
            )));
        }
    }
    kind.check_genome("the genome", n, genome).map_err(to_py)
}
