//! Engine errors as Python exceptions, with the engine's message (the one `vsr` prints after
//! "vsr: "): bad input (shape, terrain, controller, genome, argument) is a `ValueError`, a
//! file that cannot be read or written an `OSError`, an episode whose simulation became
//! non-finite a `vsr.UnstableError` (a `RuntimeError`).

use pyo3::create_exception;
use pyo3::exceptions::{PyOSError, PyRuntimeError, PyValueError};
use pyo3::PyErr;

create_exception!(
    vsr,
    UnstableError,
    PyRuntimeError,
    "The simulation of an episode became non-finite."
);

/// The Python exception for an engine error.
pub fn to_py(e: vsr::Error) -> PyErr {
    let message = e.to_string();
    match e {
        vsr::Error::Unstable(_) => UnstableError::new_err(message),
        vsr::Error::Io(_) => PyOSError::new_err(message),
        vsr::Error::Shape(_) | vsr::Error::Terrain(_) | vsr::Error::Input(_) => {
            PyValueError::new_err(message)
        }
    }
}

/// A `ValueError` worded as the engine words bad input.
pub fn input(message: String) -> PyErr {
    to_py(vsr::Error::Input(message))
}
