//! Body sets from Python (`vsr::experiment::body_set`): `read_bodies` reads a body-set file as
//! `vsr evolve --bodies` and `vsr validate --bodies` read it (the same messages for an empty
//! or damaged file); `validate_bodies` is `vsr validate --bodies`, bit for bit: a brain for
//! any body walked on every body of a set, each on the validation set's ten terrains with
//! their noise seeds, the bodies spread over a pool with the GIL released (any number of
//! threads gives the same figures), Ctrl-C seen and progress logged between chunks.

use std::path::PathBuf;

use numpy::PyArray1;
use pyo3::exceptions::PyFileNotFoundError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString};
use vsr::controllers::ControllerKind;
use vsr::experiment::body_set::validation::best_on;
use vsr::experiment::body_set::{validate_body, BodiesValidation, MAX_BODIES};
use vsr::experiment::{Best, BodySet, ValidationSet};
use vsr::simulation::Shape;

use crate::args::{describe, optional_threads, seconds as check_seconds};
use crate::batch::{Pool, CHUNK_PER_THREAD};
use crate::errors::{input, to_py};

/// Episodes of one body's validation (its set's terrains).
const TERRAINS_PER_BODY: usize = 10;

/// The bodies (rows, top first) of the body-set file at `path`.
#[pyfunction]
pub fn read_bodies(path: PathBuf) -> PyResult<Vec<String>> {
    let set = read(&path)?;
    Ok(set.bodies.iter().map(Shape::to_rows).collect())
}

/// `vsr validate --bodies` of `genome`: `bodies` is a body-set file's path (str or
/// os.PathLike) or a list of bodies (presets or rows); `shape`, when given, is the genome's own
/// body (a run file's), which a controller tied to its body may walk only.
#[pyfunction]
#[pyo3(signature = (genome, shape, controller, bodies, set, seconds, threads))]
#[allow(clippy::too_many_arguments)]
pub fn validate_bodies<'py>(
    py: Python<'py>,
    genome: Vec<f32>,
    shape: Option<&str>,
    controller: &str,
    bodies: Bound<'py, PyAny>,
    set: &str,
    seconds: Bound<'py, PyAny>,
    threads: Option<Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let kind: ControllerKind = controller.parse().map_err(to_py)?;
    let set = set.parse::<ValidationSet>().map_err(to_py)?;
    let seconds = check_seconds(&seconds)?;
    let threads = optional_threads(threads.as_ref())?;
    let bodies = body_set(&bodies)?;
    let own = match shape {
        Some(rows) => Shape::parse(rows).map_err(to_py)?,
        None if kind.is_body_independent() => bodies.bodies[0].clone(),
        None => {
            return Err(input(format!(
                "this {kind} genome has genes for each voxel of one body, so it cannot walk a \
                 body set; only a brain for any body (attention-any, mlp-any, mlp-comm-any) can \
                 be measured on a body set (or give shape=, the genome's own body, and a set of \
                 that body only)"
            )))
        }
    };
    kind.check_genome("the genome", own.voxel_count(), &genome)
        .map_err(to_py)?;
    let best = Best::new(kind, own, genome, f64::NAN);
    // Every body is checked before any episode runs (a brain tied to its body: in words).
    for body in &bodies.bodies {
        best_on(&best, body).map_err(to_py)?;
    }
    let per_thread = (CHUNK_PER_THREAD / TERRAINS_PER_BODY).max(1);
    let per_body = Pool::new(threads)?
        .map(py, bodies.bodies.len(), per_thread, "bodies", |i| {
            validate_body(&best, &bodies.bodies[i], set, seconds)
        })?
        .into_iter()
        .collect::<vsr::Result<Vec<_>>>()
        .map_err(to_py)?;
    let validation = BodiesValidation::new(&bodies, set, seconds, per_body);
    dict(py, &validation)
}

/// The body set `bodies` stands for: a file (str or os.PathLike) or a list of bodies.
fn body_set(bodies: &Bound<'_, PyAny>) -> PyResult<BodySet> {
    if bodies.is_instance_of::<PyString>() || bodies.hasattr("__fspath__")? {
        let path: PathBuf = bodies.extract()?;
        let text = path.to_string_lossy();
        if !path.exists() && Shape::parse(&text).is_ok() {
            return Err(input(format!(
                "bodies is a body-set file's path or a list of bodies: '{text}' is a body, not \
                 a file; give a list, bodies=['{text}']"
            )));
        }
        return read(&path);
    }
    let refused = || {
        input(format!(
            "bodies must be a body-set file's path or a list of bodies (presets or rows such \
             as '1111-1111-1001'), got {}",
            describe(bodies)
        ))
    };
    let items: Vec<Bound<'_, PyAny>> = match bodies.try_iter() {
        Ok(items) => items.collect::<PyResult<_>>()?,
        Err(_) => return Err(refused()),
    };
    if items.is_empty() {
        return Err(input(
            "bodies is an empty list: give at least one body (a preset or rows such as \
             '1111-1111-1001')"
                .into(),
        ));
    }
    if items.len() > MAX_BODIES {
        return Err(input(format!(
            "bodies has {} bodies, more than {MAX_BODIES}",
            items.len()
        )));
    }
    let shapes = items
        .iter()
        .enumerate()
        .map(|(i, item)| {
            let rows = item.cast::<PyString>().map_err(|_| {
                input(format!(
                    "body {i} of the list must be a string (a preset or rows such as \
                     '1111-1111-1001'), got {}",
                    describe(item)
                ))
            })?;
            Shape::parse(&rows.to_cow()?)
                .map_err(|e| input(format!("body {i} of the list is not a body: {e}")))
        })
        .collect::<PyResult<Vec<Shape>>>()?;
    Ok(BodySet {
        name: format!("a list of {} bodies", shapes.len()),
        bodies: shapes,
    })
}

/// The body-set file at `path` (`BodySet::read`: its messages); a missing file is a
/// `FileNotFoundError`, another file error an `OSError`, a damaged or empty set a `ValueError`.
fn read(path: &std::path::Path) -> PyResult<BodySet> {
    BodySet::read(path).map_err(|e| match e {
        vsr::Error::Io(message) if !path.exists() => PyFileNotFoundError::new_err(message),
        e => to_py(e),
    })
}

/// The validation as a dict (see `vsr.validate`).
fn dict<'py>(py: Python<'py>, v: &BodiesValidation) -> PyResult<Bound<'py, PyDict>> {
    let (names, seeds): (Vec<String>, Vec<u64>) = v.set.episodes().into_iter().unzip();
    let per_body = PyList::empty(py);
    for b in &v.per_body {
        let one = PyDict::new(py);
        one.set_item("body", b.body.to_rows())?;
        let velocities: Vec<f64> = b.validation.terrains.iter().map(|t| t.velocity).collect();
        one.set_item("velocities", PyArray1::from_vec(py, velocities))?;
        one.set_item("median", b.validation.median)?;
        one.set_item("mean", b.validation.mean)?;
        per_body.append(one)?;
    }
    let means: Vec<f64> = v.per_body.iter().map(|b| b.validation.mean).collect();
    let out = PyDict::new(py);
    out.set_item("name", &v.bodies)?;
    out.set_item("set", v.set.name())?;
    out.set_item("terrains", names)?;
    out.set_item("noise_seeds", seeds)?;
    out.set_item("seconds", v.seconds)?;
    out.set_item("per_body", per_body)?;
    out.set_item("means", PyArray1::from_vec(py, means))?;
    out.set_item("median", v.median)?;
    out.set_item("walking_share", v.walking_share)?;
    Ok(out)
}
