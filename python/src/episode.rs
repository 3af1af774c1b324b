//! `vsr.Episode`: an episode stepped from Python, gymnasium-style, for a controller that
//! lives in Python. The engine's episode with an external policy (SPEC 8's clock): `reset`
//! takes the first step and observes; each `step(action)` holds the action (one actuation
//! per voxel, in [-1, 1]) for the next 20 steps, as the engine holds a controller's output,
//! and observes again. Observations are the sensor readings a controller is fed, shape
//! (voxels, 4): area, vx, vy, touch. The reward is the centre's x advance during the step,
//! so the rewards add up to the distance of `vsr evaluate`; the episode is truncated after
//! `seconds` (1801 steps, 90 actions for 30 s), never terminated.

use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use vsr::experiment::{steps_for, Policy};
use vsr::simulation::constants::ACTUATION_HOLD_STEPS;
use vsr::simulation::{Shape, Terrain};

use crate::args::{seconds as check_seconds, terrain as parse_terrain};
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
    #[pyo3(signature = (shape, terrain, seconds=30.0, noise_seed=0))]
    fn new(shape: &str, terrain: &str, seconds: f64, noise_seed: u64) -> PyResult<Self> {
        let shape = Shape::parse(shape).map_err(to_py)?;
        Ok(Episode {
            shape,
            terrain: parse_terrain(terrain)?,
            noise_seed,
            steps: steps_for(check_seconds(seconds)?),
            engine: None,
            last_x: 0.0,
        })
    }

    /// Starts afresh (`seed`, when given, replaces the noise seed) and takes the first step;
    /// returns (observation, info).
    #[pyo3(signature = (seed=None))]
    fn reset<'py>(&mut self, py: Python<'py>, seed: Option<u64>) -> PyResult<Bound<'py, PyAny>> {
        self.noise_seed = seed.unwrap_or(self.noise_seed);
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
    fn step<'py>(&mut self, py: Python<'py>, action: Vec<f64>) -> PyResult<Bound<'py, PyAny>> {
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
