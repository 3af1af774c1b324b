//! `codesign`: a body search around a brain, as `vsr codesign` runs it (the same settings
//! rules, `CodesignConfig::with_module`, and the same bits for any number of threads), with
//! the GIL released but for a moment between iterations: each iteration's line goes to the
//! `vsr` logger and Ctrl-C is looked at. Gives the co-design run file's text, which `vsr
//! evaluate --genome` and the page read.

use pyo3::prelude::*;
use rayon::prelude::*;
use std::sync::Mutex;
use std::time::Instant;
use vsr::controllers::ControllerKind;
use vsr::experiment::codesign::source_in_file;
use vsr::experiment::{BrainMode, Codesign, CodesignConfig, Job, Timing, TrainingTerrain};

use crate::args::{
    optional_number, optional_pair, optional_threads, optional_usize, whole, DEFAULT_SECONDS,
};
use crate::batch::{info, Pool};
use crate::errors::to_py;

/// The co-design run file (JSON text) of a body search; `module` is a pretrained module's run
/// file text (for `frozen` and `finetune`; of a co-design run file, its best body or archive
/// entry `entry`).
#[pyfunction]
#[pyo3(signature = (brain, evals, seed, module=None, controller="attention", start=None,
    seconds=None, terrain="hilly-1-10", grid=None, voxels=None, batch=None, threads=None,
    entry=None))]
#[allow(clippy::too_many_arguments)]
pub fn codesign(
    py: Python<'_>,
    brain: &str,
    evals: Bound<'_, PyAny>,
    seed: Bound<'_, PyAny>,
    module: Option<&str>,
    controller: &str,
    start: Option<&str>,
    seconds: Option<Bound<'_, PyAny>>,
    terrain: &str,
    grid: Option<Bound<'_, PyAny>>,
    voxels: Option<Bound<'_, PyAny>>,
    batch: Option<Bound<'_, PyAny>>,
    threads: Option<Bound<'_, PyAny>>,
    entry: Option<Bound<'_, PyAny>>,
) -> PyResult<String> {
    let (evals, seed) = (whole(&evals, "evals")?, whole(&seed, "seed")?);
    let batch = optional_usize(batch.as_ref(), "batch")?;
    let threads = optional_threads(threads.as_ref())?;
    let entry = optional_usize(entry.as_ref(), "entry")?;
    let seconds = optional_number(seconds.as_ref(), "seconds")?.unwrap_or(DEFAULT_SECONDS);
    let grid = optional_pair(grid.as_ref(), "grid", "(width, height)")?;
    let voxels = optional_pair(voxels.as_ref(), "voxels", "(min, max)")?;
    let brain: BrainMode = brain.parse().map_err(to_py)?;
    let controller: ControllerKind = controller.parse().map_err(to_py)?;
    let module = match (module, entry) {
        (Some(text), _) => Some(source_in_file(text, entry).map_err(to_py)?),
        (None, Some(_)) => {
            return Err(pyo3::exceptions::PyValueError::new_err(
                "entry names a body of the module's file: give module too",
            ))
        }
        (None, None) => None,
    };
    let mut config = CodesignConfig::with_module(brain, module, controller, start, evals, seed)
        .map_err(to_py)?;
    config.seconds = seconds;
    config.terrain = TrainingTerrain::parse(terrain).map_err(to_py)?;
    if let Some(g) = grid {
        (config.grid_width, config.grid_height) = g;
    }
    if let Some(v) = voxels {
        (config.min_voxels, config.max_voxels) = v;
    }
    if let Some(b) = batch {
        config.batch = b;
    }
    config.validate().map_err(to_py)?;
    let mut search = Codesign::new(config).map_err(to_py)?;
    let pool = Pool::new(threads)?;
    let threads = pool.threads();
    let started = Instant::now();
    let clock = || started.elapsed().as_secs_f64();
    // Between iterations, with the GIL: the iteration's line to the `vsr` logger and a look at
    // Ctrl-C; a Python error (KeyboardInterrupt) stops the search and is raised as it is.
    let stopped: Mutex<Option<PyErr>> = Mutex::new(None);
    let run = py.detach(|| {
        let evaluate = |jobs: &[Job]| pool.install(|| jobs.par_iter().map(Job::fitness).collect());
        let after = |s: &Codesign| {
            let looked = Python::attach(|py| {
                if let Some(record) = s.history().last() {
                    info(py, &record.summary())?;
                }
                py.check_signals()
            });
            looked.map_err(|e| {
                *stopped.lock().unwrap_or_else(|p| p.into_inner()) = Some(e);
                vsr::Error::Input("stopped from Python".into())
            })
        };
        search.run(evaluate, after, clock)?;
        search.run_file(Some(Timing {
            threads,
            wall_seconds: clock(),
        }))
    });
    if let Some(e) = stopped.into_inner().unwrap_or_else(|p| p.into_inner()) {
        return Err(e);
    }
    Ok(run.map_err(to_py)?.to_json())
}
