//! The arguments every entry point shares, parsed by the engine's own parsers so that a bad
//! one fails with the message the command line gives.

use numpy::PyReadonlyArray2;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyList, PyString, PyTuple};
use vsr::controllers::ControllerKind;
use vsr::experiment::config::check_seconds;
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
    length: &Bound<'_, PyAny>,
) -> PyResult<(Shape, ControllerKind, Terrain, f64)> {
    let (shape, kind) = robot(shape, controller)?;
    Ok((shape, kind, terrain(terrain_name)?, seconds(length)?))
}

/// A terrain by name (flat, hilly-1-10-3, ...).
pub fn terrain(name: &str) -> PyResult<Terrain> {
    Terrain::parse(name).map_err(to_py)
}

/// The episode length when none is given (s): the paper's.
pub const DEFAULT_SECONDS: f64 = 30.0;

/// An episode length as Python gives it (`seconds`): a number (else a `ValueError` naming
/// `seconds`), then checked as the command line checks it (the same message).
pub fn seconds(value: &Bound<'_, PyAny>) -> PyResult<f64> {
    let seconds = number(value, "seconds")?;
    check_seconds(seconds).map_err(to_py)?;
    Ok(seconds)
}

/// A real-number argument named `name`: a Python int or float (or anything with
/// `__float__`, numpy's scalars included), not a bool or a string; anything else, and an int
/// too large for a float, a `ValueError` that names it, not the `TypeError` or
/// `OverflowError` of a plain conversion. The range is the caller's to check.
pub fn number(value: &Bound<'_, PyAny>, name: &str) -> PyResult<f64> {
    let refused = || input(format!("{name} must be a number, got {}", describe(value)));
    if value.is_instance_of::<PyBool>() || value.is_instance_of::<PyString>() {
        return Err(refused());
    }
    value.extract::<f64>().map_err(|_| refused())
}

/// An optional [`number`] (None when not given).
pub fn optional_number(value: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Option<f64>> {
    value
        .filter(|v| !v.is_none())
        .map(|v| number(v, name))
        .transpose()
}

/// A whole-number argument (a seed, a count, a number of threads) named `name`: an integer
/// in [0, 2^64 - 1], anything else (-1, 2.5, "3", True, 2^64) a `ValueError` that names it,
/// not the `OverflowError` or `TypeError` of a plain conversion.
pub fn whole(value: &Bound<'_, PyAny>, name: &str) -> PyResult<u64> {
    integer(value).ok_or_else(|| {
        input(format!(
            "{name} must be an integer in [0, 2^64 - 1], got {}",
            describe(value)
        ))
    })
}

/// `value` as a u64 when it is a Python integer (or one of numpy's) in range; a bool is not
/// taken for 0 or 1.
fn integer(value: &Bound<'_, PyAny>) -> Option<u64> {
    if value.is_instance_of::<PyBool>() {
        return None;
    }
    value.extract::<u64>().ok()
}

/// A pair of whole numbers named `name`, e.g. `voxels` (min, max): a tuple or list of two
/// integers in [0, 2^64 - 1], anything else a `ValueError` that names it and its parts.
pub fn pair(value: &Bound<'_, PyAny>, name: &str, parts: &str) -> PyResult<(usize, usize)> {
    let refused = || {
        input(format!(
            "{name} must be two integers {parts}, each in [0, 2^64 - 1], got {}",
            describe(value)
        ))
    };
    if !(value.is_instance_of::<PyTuple>() || value.is_instance_of::<PyList>()) {
        return Err(refused());
    }
    let items: Vec<Bound<'_, PyAny>> = value.try_iter()?.collect::<PyResult<_>>()?;
    match items.as_slice() {
        [a, b] => {
            let one = |v: &Bound<'_, PyAny>| integer(v).and_then(|n| usize::try_from(n).ok());
            Ok((one(a).ok_or_else(refused)?, one(b).ok_or_else(refused)?))
        }
        _ => Err(refused()),
    }
}

/// An optional [`pair`] (None when not given).
pub fn optional_pair(
    value: Option<&Bound<'_, PyAny>>,
    name: &str,
    parts: &str,
) -> PyResult<Option<(usize, usize)>> {
    value
        .filter(|v| !v.is_none())
        .map(|v| pair(v, name, parts))
        .transpose()
}

/// [`whole`] as a `usize` (a count of threads, of bodies).
pub fn whole_usize(value: &Bound<'_, PyAny>, name: &str) -> PyResult<usize> {
    let n = whole(value, name)?;
    usize::try_from(n).map_err(|_| input(format!("{name} is too large: {n}")))
}

/// A number of threads: None (every core) or an integer of at least 1, anything else a
/// `ValueError` that says so (-1 and 0 alike).
pub fn optional_threads(value: Option<&Bound<'_, PyAny>>) -> PyResult<Option<usize>> {
    let Some(v) = value.filter(|v| !v.is_none()) else {
        return Ok(None);
    };
    match integer(v).and_then(|n| usize::try_from(n).ok()) {
        Some(n) if n >= 1 => Ok(Some(n)),
        _ => Err(input(format!(
            "threads must be an integer of at least 1, or None for every core; got {}",
            describe(v)
        ))),
    }
}

/// An optional [`whole_usize`] (None when not given).
pub fn optional_usize(value: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Option<usize>> {
    value
        .filter(|v| !v.is_none())
        .map(|v| whole_usize(v, name))
        .transpose()
}

/// A short description of a Python value for a message: its repr, cut at 40 characters.
pub fn describe(value: &Bound<'_, PyAny>) -> String {
    let text = value
        .repr()
        .map_or_else(|_| "?".to_string(), |r| r.to_string());
    match text.char_indices().nth(40) {
        Some((cut, _)) => format!("{}...", &text[..cut]),
        None => text,
    }
}

/// The rows of a C-contiguous float32 matrix, in place (the Python half hands them so).
pub fn rows<'a>(genomes: &'a PyReadonlyArray2<'_, f32>) -> PyResult<&'a [f32]> {
    genomes
        .as_slice()
        .map_err(|_| input("genomes must be a C-contiguous float32 array".into()))
}
