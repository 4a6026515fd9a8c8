//! Bindings of `poinsot::inertia` (conversion and error mapping only).
use pyo3::prelude::*;

/// Registers this file's functions and classes on the module.
pub fn register(_m: &Bound<'_, PyModule>) -> PyResult<()> {
    Ok(())
}
