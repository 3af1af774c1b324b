//! The arguments every entry point shares, parsed by the engine's own parsers so that a bad
//! one fails with the message the command line gives.

use numpy::PyReadonlyArray2;
use pyo3::prelude::*;
use vsr::controllers::ControllerKind;
use vsr::experiment::config::MAX_SECONDS;
use vsr::simulation::{Shape, Terrain};

use crate::errors::{input, to_py};

/// A robot: its shape (a preset or rows, top first) and its controller family.
pub fn robot(shape: &str, controller: &str) -> PyResult<(Shape, ControllerKind)> {
    let shape = Shape::parse(shape).map_err(to_py)?;
    let kind = controller.parse::<ControllerKind>().map_err(to_py)?;
    Ok((shape, kind))
}

/// What an episode needs from its arguments: the robot, the terrain, the length (s).
pub fn setup(
    shape: &str,
    controller: &str,
    terrain_name: &str,
    length: f64,
) -> PyResult<(Shape, ControllerKind, Terrain, f64)> {
    let (shape, kind) = robot(shape, controller)?;
    Ok((shape, kind, terrain(terrain_name)?, seconds(length)?))
}

/// A terrain by name (flat, hilly-1-10-3, ...).
pub fn terrain(name: &str) -> PyResult<Terrain> {
    Terrain::parse(name).map_err(to_py)
}

/// An episode length, in the range the command line accepts.
pub fn seconds(seconds: f64) -> PyResult<f64> {
    if seconds > 0.0 && seconds <= MAX_SECONDS {
        return Ok(seconds);
    }
    Err(input(format!(
        "seconds must be in (0, {MAX_SECONDS}], got {seconds}"
    )))
}

/// The rows of a C-contiguous float32 matrix, in place (the Python half hands them so).
pub fn rows<'a>(genomes: &'a PyReadonlyArray2<'_, f32>) -> PyResult<&'a [f32]> {
    genomes
        .as_slice()
        .map_err(|_| input("genomes must be a C-contiguous float32 array".into()))
}
