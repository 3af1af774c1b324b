//! The native half of the `vsr` Python package (`vsr._vsr`): a thin pyo3 layer over the
//! engine, the way `crate/wasm/src` is for the page. Arrays cross as numpy arrays, read in
//! place where their dtype and layout allow (the Python half, `python/vsr/`, makes them so);
//! long computations run with the GIL released; every engine error becomes a Python
//! exception carrying the engine's message (see `errors`).

mod args;
mod batch;
mod bodies;
mod body_set;
mod codesign;
mod controller;
mod episode;
mod errors;
mod evaluate;
mod measures;
mod runfile;
mod simulate;
mod terrain;

use pyo3::prelude::*;

#[pymodule]
fn _vsr(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(evaluate::param_count, m)?)?;
    m.add_function(wrap_pyfunction!(evaluate::evaluate, m)?)?;
    m.add_function(wrap_pyfunction!(bodies::evaluate_bodies, m)?)?;
    m.add_function(wrap_pyfunction!(codesign::codesign, m)?)?;
    m.add_function(wrap_pyfunction!(simulate::simulate, m)?)?;
    m.add_function(wrap_pyfunction!(measures::validate, m)?)?;
    m.add_function(wrap_pyfunction!(measures::ablate, m)?)?;
    m.add_function(wrap_pyfunction!(body_set::read_bodies, m)?)?;
    m.add_function(wrap_pyfunction!(body_set::validate_bodies, m)?)?;
    m.add_function(wrap_pyfunction!(terrain::terrain_for, m)?)?;
    m.add_function(wrap_pyfunction!(runfile::check_run, m)?)?;
    m.add_function(wrap_pyfunction!(runfile::new_run, m)?)?;
    m.add_class::<episode::Episode>()?;
    m.add_class::<controller::Controller>()?;
    m.add("UnstableError", m.py().get_type::<errors::UnstableError>())?;
    m.add("ENGINE_VERSION", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
