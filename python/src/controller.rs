//! `vsr.Controller`: one of the engine's controllers with a genome, asked from Python with
//! the readings an [`Episode`](crate::episode::Episode) observes: bring the engine's own
//! brain to an episode stepped from Python, or check one's own against it.

use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray2};
use pyo3::prelude::*;
use vsr::controllers::{check_io, ControllerKind};
use vsr::experiment::evaluate::controller_for;

use crate::args::robot;
use crate::errors::{input, to_py};

/// A controller of `controller` for `shape` with parameters `genome` (one per gene).
#[pyclass(unsendable, module = "vsr")]
pub struct Controller {
    inner: Box<dyn vsr::controllers::Controller>,
    kind: ControllerKind,
    voxels: usize,
}

#[pymethods]
impl Controller {
    #[new]
    fn new(shape: &str, controller: &str, genome: Vec<f32>) -> PyResult<Self> {
        let (shape, kind) = robot(shape, controller)?;
        let inner = controller_for(kind, &shape, &genome).map_err(to_py)?;
        let voxels = shape.voxel_count();
        Ok(Controller {
            inner,
            kind,
            voxels,
        })
    }

    /// One actuation per voxel (float32, in [-1, 1]) from readings of shape (voxels, 4).
    fn control<'py>(
        &mut self,
        py: Python<'py>,
        observation: PyReadonlyArray2<'py, f32>,
    ) -> PyResult<Bound<'py, PyArray1<f32>>> {
        let readings = observation
            .as_slice()
            .map_err(|_| input("the observation must be a C-contiguous float32 array".into()))?;
        let mut out = vec![0.0f32; self.voxels];
        check_io(self.voxels, readings, &out).map_err(to_py)?;
        self.inner.control(readings, &mut out);
        Ok(PyArray1::from_vec(py, out))
    }

    /// Clears the state kept between calls, as at the start of an episode.
    fn reset(&mut self) {
        self.inner.reset();
    }

    /// True for controllers with state (MLP-Comm, slow attention): the engine asks them after
    /// every step, so an episode stepped every 20 steps does not reproduce them.
    #[getter]
    fn needs_every_step(&self) -> bool {
        self.inner.needs_every_step()
    }

    /// The controller family's name.
    #[getter]
    fn kind(&self) -> &'static str {
        self.kind.name()
    }

    /// The genome (float32).
    #[getter]
    fn genome<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f32>> {
        PyArray1::from_vec(py, self.inner.params())
    }

    /// Each voxel's attention matrix, shape (voxels, 4, 4), or None without attention.
    fn attention<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        let Some(matrices) = self.inner.attention() else {
            return Ok(None);
        };
        let array = PyArray1::from_slice(py, matrices).reshape([self.voxels, 4, 4])?;
        Ok(Some(array.into_any()))
    }
}
