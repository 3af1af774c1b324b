//! `simulate`: one episode of a genome, as `vsr evaluate` runs it, reported as its JSON is
//! (velocity, distance, steps, seconds) and, on request, recorded after every step: the time
//! (s), the robot's centre (m) and every voxel's four outer corners (m; SW, SE, NE, NW).

use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use vsr::experiment::evaluate::controller_for;
use vsr::experiment::{steps_for, Episode, Policy};

use crate::args::{setup, whole};
use crate::errors::to_py;

/// What is recorded after every step: time, centre, corners (flat, in step order).
#[derive(Default)]
struct Recording {
    time: Vec<f64>,
    centre: Vec<f64>,
    corners: Vec<f32>,
}

impl Recording {
    fn push(&mut self, episode: &Episode, scratch: &mut [f32]) {
        self.time.push(episode.time());
        self.centre.extend([episode.centre_x(), episode.centre_y()]);
        episode.write_voxel_corners(scratch);
        self.corners.extend_from_slice(scratch);
    }
}

/// One episode of `genome` (a few hundred genes at most: copied) driving `controller` on `shape` over `terrain`; a dict with
/// `velocity`, `distance`, `steps`, `seconds` and, when `trajectory`, `time` (T,),
/// `centre` (T, 2) and `corners` (T, voxels, 4, 2).
#[pyfunction]
#[pyo3(signature = (genome, shape, controller, terrain, seconds, noise_seed, trajectory))]
#[allow(clippy::too_many_arguments)]
pub fn simulate<'py>(
    py: Python<'py>,
    genome: Vec<f32>,
    shape: &str,
    controller: &str,
    terrain: &str,
    seconds: Bound<'py, PyAny>,
    noise_seed: Bound<'py, PyAny>,
    trajectory: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let (shape, kind, terrain, seconds) = setup(shape, controller, terrain, &seconds)?;
    let noise_seed = whole(&noise_seed, "noise_seed")?;
    let brain = controller_for(kind, &shape, &genome).map_err(to_py)?;
    let n = shape.voxel_count();
    let (outcome, recording) = py
        .detach(|| {
            let policy = Policy::Brain(brain);
            let mut episode = Episode::with_policy(&shape, terrain, policy, Some(noise_seed));
            let mut recording = Recording::default();
            if trajectory {
                let mut scratch = vec![0.0f32; 8 * n];
                for _ in 0..steps_for(seconds) {
                    episode.step(1)?;
                    recording.push(&episode, &mut scratch);
                }
            }
            episode.run(seconds).map(|o| (o, recording))
        })
        .map_err(to_py)?;
    let out = PyDict::new(py);
    out.set_item("velocity", outcome.velocity)?;
    out.set_item("distance", outcome.distance)?;
    out.set_item("steps", outcome.steps)?;
    out.set_item("seconds", outcome.seconds)?;
    if trajectory {
        let steps = recording.time.len();
        out.set_item("time", PyArray1::from_vec(py, recording.time))?;
        let centre = PyArray1::from_vec(py, recording.centre).reshape([steps, 2])?;
        out.set_item("centre", centre)?;
        let corners = PyArray1::from_vec(py, recording.corners).reshape([steps, n, 4, 2])?;
        out.set_item("corners", corners)?;
    }
    Ok(out)
}
