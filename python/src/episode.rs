//! `vsr.Episode`: an episode stepped from Python, gymnasium-style, for a controller that
//! lives in Python. The engine's episode with an external policy (SPEC 8's clock): `reset`
//! takes the first step and observes; each `step(action)` holds the action (one actuation
//! per voxel, in [-1, 1]) for the next 20 steps, as the engine holds a controller's output,
//! and observes again. Observations are the sensor readings a controller is fed, shape
//! (voxels, 4): area, vx, vy, touch, each within `observation_bounds`. The reward is the
//! centre's x advance during the step, so the rewards add up to the distance of `vsr
//! evaluate`; the episode is truncated after `seconds` (1801 steps, 90 actions for 30 s),
//! never terminated. An action is a 1-D array of one finite number per voxel; values outside
//! [-1, 1] act as -1 or 1 (the engine clamps, as it does a controller's output).

use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray1};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use vsr::experiment::{steps_for, Policy};
use vsr::simulation::constants::ACTUATION_HOLD_STEPS;
use vsr::simulation::sensors::READING_BOUNDS;
use vsr::simulation::{Shape, Terrain};

use crate::args::{
    describe, seconds as check_seconds, terrain as parse_terrain, whole, DEFAULT_SECONDS,
};
use crate::errors::{input, to_py};

type Engine = vsr::experiment::Episode;

/// A robot of `shape` on `terrain` driven from Python; sensor noise seeded by `noise_seed`.
#[pyclass(unsendable, module = "vsr")]
pub struct Episode {
    shape: Shape,
    terrain: Terrain,
    noise_seed: u64,
    steps: u64,
    engine: Option<Engine>,
    last_x: f64,
}

#[pymethods]
impl Episode {
    #[new]
    #[pyo3(signature = (shape, terrain, seconds=None, noise_seed=None))]
    #[pyo3(text_signature = "(shape, terrain, seconds=30.0, noise_seed=0)")]
    fn new(
        shape: &str,
        terrain: &str,
        seconds: Option<Bound<'_, PyAny>>,
        noise_seed: Option<Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let shape = Shape::parse(shape).map_err(to_py)?;
        let seconds = match seconds {
            Some(seconds) => check_seconds(&seconds)?,
            None => DEFAULT_SECONDS,
        };
        let noise_seed = match noise_seed {
            Some(seed) => whole(&seed, "noise_seed")?,
            None => 0,
        };
        Ok(Episode {
            shape,
            terrain: parse_terrain(terrain)?,
            noise_seed,
            steps: steps_for(seconds),
            engine: None,
            last_x: 0.0,
        })
    }

    /// Starts afresh (`seed`, when given, replaces the noise seed) and takes the first step;
    /// returns (observation, info).
    #[pyo3(signature = (seed=None))]
    fn reset<'py>(
        &mut self,
        py: Python<'py>,
        seed: Option<Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        if let Some(seed) = seed {
            self.noise_seed = whole(&seed, "seed")?;
        }
        let terrain = self.terrain.clone();
        let noise = Some(self.noise_seed);
        let mut engine = Engine::with_policy(&self.shape, terrain, Policy::External, noise);
        engine.step(1).map_err(to_py)?;
        self.last_x = engine.centre_x();
        self.engine = Some(engine);
        let observation = self.observe(py)?;
        Ok((observation, self.info(py)?).into_pyobject(py)?.into_any())
    }

    /// Holds `action` for the next 20 steps; returns (observation, reward, terminated,
    /// truncated, info).
    fn step<'py>(
        &mut self,
        py: Python<'py>,
        action: Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let action = actuations(&action, self.shape.voxel_count())?;
        let total = self.steps;
        let engine = self.running()?;
        let left = total - engine.world().steps();
        engine.set_actuation(&action).map_err(to_py)?;
        engine
            .step(left.min(ACTUATION_HOLD_STEPS as u64) as usize)
            .map_err(to_py)?;
        let x = engine.centre_x();
        let truncated = engine.world().steps() >= total;
        let reward = x - std::mem::replace(&mut self.last_x, x);
        let observation = self.observe(py)?;
        let info = self.info(py)?;
        Ok((observation, reward, false, truncated, info)
            .into_pyobject(py)?
            .into_any())
    }

    /// Number of voxels (the observation has one row per voxel).
    #[getter]
    fn voxel_count(&self) -> usize {
        self.shape.voxel_count()
    }

    /// Each voxel's cell in the shape's grid, shape (voxels, 2): column x from the left,
    /// row y from the bottom, in voxel index order (the observation's rows).
    #[getter]
    fn grid<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let cells: Vec<i64> = (self.shape.voxels().iter())
            .flat_map(|&(x, y)| [x as i64, y as i64])
            .collect();
        let array = PyArray1::from_vec(py, cells).reshape([self.shape.voxel_count(), 2])?;
        Ok(array.into_any())
    }

    /// (low, high): every reading of an observation lies in this range (the readings are
    /// normalized to [0, 1], and the sensor noise, sd 0.01, never exceeds 0.121).
    #[classattr]
    fn observation_bounds() -> (f32, f32) {
        (READING_BOUNDS[0], READING_BOUNDS[1])
    }

    /// The velocity so far (m/s), as `vsr evaluate` computes it at the end.
    #[getter]
    fn velocity(&self) -> PyResult<f64> {
        Ok(self.started()?.outcome().velocity)
    }

    /// Simulated seconds so far.
    #[getter]
    fn time(&self) -> PyResult<f64> {
        Ok(self.started()?.time())
    }

    /// Every voxel's four outer corners now, shape (voxels, 4, 2), SW, SE, NE, NW (m).
    fn corners<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let engine = self.started()?;
        let mut out = vec![0.0f32; 8 * engine.voxel_count()];
        engine.write_voxel_corners(&mut out);
        let array = PyArray1::from_vec(py, out).reshape([engine.voxel_count(), 4, 2])?;
        Ok(array.into_any())
    }
}

impl Episode {
    fn started(&self) -> PyResult<&Engine> {
        self.engine
            .as_ref()
            .ok_or_else(|| input("the episode has not started: call reset() first".into()))
    }

    fn running(&mut self) -> PyResult<&mut Engine> {
        let total = self.steps;
        match &mut self.engine {
            None => Err(input(
                "the episode has not started: call reset() first".into(),
            )),
            Some(e) if e.world().steps() >= total => Err(input(
                "the episode is over (truncated): call reset() to start another".into(),
            )),
            Some(e) => Ok(e),
        }
    }

    fn observe<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let engine = self.started()?;
        let readings = PyArray1::from_slice(py, engine.observation());
        Ok(readings.reshape([engine.voxel_count(), 4])?.into_any())
    }

    fn info<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let engine = self.started()?;
        let info = PyDict::new(py);
        info.set_item("time", engine.time())?;
        info.set_item("x", engine.centre_x())?;
        info.set_item("velocity", engine.outcome().velocity)?;
        Ok(info)
    }
}

/// An action as one actuation per voxel: anything numpy reads as a 1-D array of `voxels`
/// numbers (the engine then checks the count and that each is finite).
fn actuations(action: &Bound<'_, PyAny>, voxels: usize) -> PyResult<Vec<f64>> {
    let expected =
        format!("the action must be a 1-D array of {voxels} actuations in [-1, 1], one per voxel");
    let numpy = action.py().import("numpy")?;
    let array = numpy
        .call_method1("asarray", (action, "float64"))
        .map_err(|_| input(format!("{expected}, got {}", describe(action))))?;
    let dims: usize = array.getattr("ndim")?.extract()?;
    if dims != 1 {
        let shape = array.getattr("shape")?.str()?;
        return Err(input(format!("{expected}, got an array of shape {shape}")));
    }
    let array: PyReadonlyArray1<'_, f64> = array.extract()?;
    Ok(array.as_array().to_vec())
}
