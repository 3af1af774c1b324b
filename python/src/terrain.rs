//! `terrain_for`: the terrain of one episode drawn from a training terrain, by the engine's
//! rule (`vsr::experiment::TrainingTerrain`, what `vsr evolve --terrain` takes): a family
//! (`hilly-1-10`, `steppy-1-10`) gives its terrain with seed `draw` mod 10000, the training
//! pool; a complete name (`flat`, `hilly-1-10-3`) is itself whatever the draw.

use pyo3::prelude::*;
use vsr::experiment::TrainingTerrain;

use crate::args::whole;
use crate::errors::to_py;

/// The terrain name of draw `draw` from `terrain` (a family or a name).
#[pyfunction]
pub fn terrain_for(terrain: &str, draw: Bound<'_, PyAny>) -> PyResult<String> {
    let draw = whole(&draw, "draw")?;
    let training = TrainingTerrain::parse(terrain).map_err(to_py)?;
    Ok(training.name_for(draw))
}
