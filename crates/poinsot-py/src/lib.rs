//! Python bindings of the poinsot core: conversion of arrays and mapping of errors, no physics.
//!
//! The files mirror the core's modules: `rotation.rs` binds `poinsot::rotation`,
//! `inertia.rs` binds `poinsot::inertia`. The compiled module is private (`poinsot._core`);
//! the typed public API lives in `python/poinsot`.
#![forbid(unsafe_code)]

mod analytic;
mod convert;
mod dynamics;
mod earth;
mod errors;
mod frames;
mod heavy_top;
mod inertia;
mod rotation;
mod special;

use pyo3::prelude::*;

/// The compiled core of poinsot (private: use the `poinsot` package).
#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    errors::register(m)?;
    rotation::register(m)?;
    inertia::register(m)?;
    frames::register(m)?;
    earth::register(m)?;
    special::register(m)?;
    analytic::register(m)?;
    dynamics::register(m)?;
    heavy_top::register(m)?;
    Ok(())
}
