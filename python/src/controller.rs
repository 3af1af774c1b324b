//! `vsr.Controller`: one of the engine's controllers with a genome, asked from Python with
//! the readings an [`Episode`](crate::episode::Episode) observes: bring the engine's own
//! brain to an episode stepped from Python, or check one's own against it.

use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2};
use pyo3::prelude::*;
use vsr::controllers::{ControllerKind, SENSORS_PER_VOXEL};
use vsr::experiment::evaluate::controller_for;

use crate::args::{describe, robot};
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
    fn new(shape: &str, controller: &str, genome: &Bound<'_, PyAny>) -> PyResult<Self> {
        let (shape, kind) = robot(shape, controller)?;
        // Genes as `vsr.evaluate` takes them (vsr._genes: float32, rounded once, refused
        // out of float32's range), read in place.
        let genes = genome
            .py()
            .import("vsr")?
            .call_method1("_genes", (genome, 1, "the genome"))?;
        let genes: PyReadonlyArray1<'_, f32> = genes.extract()?;
        let inner = controller_for(kind, &shape, genes.as_slice()?).map_err(to_py)?;
        let voxels = shape.voxel_count();
        Ok(Controller {
            inner,
            kind,
            voxels,
        })
    }

    /// One actuation per voxel (float32, in [-1, 1]) from readings of shape (voxels, 4):
    /// any array-like of finite numbers (rounded to float32 once, as genes are).
    fn control<'py>(
        &mut self,
        py: Python<'py>,
        observation: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray1<f32>>> {
        let readings = observation_of(observation, self.voxels)?;
        let readings = readings.as_slice()?;
        if let Some(i) = readings.iter().position(|r| !r.is_finite()) {
            return Err(input(format!(
                "reading {} of voxel {} in the observation is {}, readings must be finite \
                 numbers",
                i % SENSORS_PER_VOXEL,
                i / SENSORS_PER_VOXEL,
                readings[i]
            )));
        }
        let mut out = vec![0.0f32; self.voxels];
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

/// `observation` as a C-contiguous float32 array of shape (voxels, 4), copied only when it is
/// not one already; anything else is a `ValueError` that says what is expected.
fn observation_of<'py>(
    observation: &Bound<'py, PyAny>,
    voxels: usize,
) -> PyResult<PyReadonlyArray2<'py, f32>> {
    let expected = format!(
        "the observation must be an array of shape ({voxels}, {SENSORS_PER_VOXEL}): \
         {SENSORS_PER_VOXEL} readings (area, vx, vy, touch) per voxel"
    );
    let numpy = observation.py().import("numpy")?;
    let array = numpy
        .call_method1("ascontiguousarray", (observation, "float32"))
        .map_err(|_| input(format!("{expected}, got {}", describe(observation))))?;
    let shape = array.getattr("shape")?;
    if shape.extract::<Vec<usize>>()? != [voxels, SENSORS_PER_VOXEL] {
        return Err(input(format!("{expected}, got shape {}", shape.str()?)));
    }
    array.extract()
}
