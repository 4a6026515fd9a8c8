//! Bindings of `poinsot::earth::RigidEarth` (conversion and error mapping only): the Earth as a
//! rigid symmetric top. `RigidEarthCore` holds a checked core value; the public, documented
//! class is `poinsot.RigidEarth` (python/poinsot/rigid_earth.py), which holds one. The core
//! names every argument as the caller knows it, so no error is renamed here.
use poinsot::earth::{self as ea, RigidEarth};
use pyo3::prelude::*;
use pyo3::types::PyType;

use crate::errors::IntoPy;

/// The Earth as a rigid symmetric top (private; use `poinsot.RigidEarth`): the core's
/// `RigidEarth`, checked when made.
#[pyclass(module = "poinsot._core", name = "RigidEarthCore", frozen)]
pub struct PyRigidEarth {
    inner: RigidEarth,
}

core_export! {
    impl PyRigidEarth;
    getters {
        /// The unit's Ω of 2.83 for the Earth, −H/(1 − H) ω (rad/s).
        euler_rate -> f64;
        /// The luni-solar precession rate (rad/s, negative: retrograde).
        precession_rate -> f64;
        /// (Sun, Moon) parts of the precession rate (rad/s).
        precession_parts -> (f64, f64);
    }
    fallible {
        /// Euler's free-nutation period (s).
        euler_period -> f64;
        /// 2π/|precession rate| (s).
        precession_period -> f64;
        /// (Δψ₀, Δε₀) of the principal nutation (rad, IAU convention).
        nutation_amplitudes -> (f64, f64);
        /// The same (Δψ₀, Δε₀) in closed form from the Moon's precession part (rad).
        nutation_amplitudes_by_precession -> (f64, f64);
    }

    /// The rigid Earth of dynamical flattening H ∈ (0, 1), rate ω > 0 (rad/s) and obliquity
    /// ε ∈ [0, π/2) (rad); errors name them.
    #[new]
    fn new(dynamical_flattening: f64, rotation_rate: f64, obliquity: f64) -> PyResult<Self> {
        Ok(Self {
            inner: RigidEarth::new(dynamical_flattening, rotation_rate, obliquity).py()?,
        })
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> (Bound<'py, PyType>, (f64, f64, f64)) {
        let e = slf.get().inner;
        (
            slf.get_type(),
            (e.dynamical_flattening, e.rotation_rate, e.obliquity),
        )
    }

    /// H = (C − A)/C.
    #[getter]
    fn dynamical_flattening(&self) -> f64 {
        self.inner.dynamical_flattening
    }

    /// ω (rad/s).
    #[getter]
    fn rotation_rate(&self) -> f64 {
        self.inner.rotation_rate
    }

    /// ε (rad).
    #[getter]
    fn obliquity(&self) -> f64 {
        self.inner.obliquity
    }

    /// The Chandler period T_E ks/(ks − k2) (s) for Love numbers 0 < k2 < ks.
    fn chandler_period(&self, k2: f64, ks: f64) -> PyResult<f64> {
        self.inner.chandler_period(k2, ks).py()
    }
}

/// Registers this file's class and the constants of the rigid Earth on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyRigidEarth>()?;
    m.add("DYNAMICAL_FLATTENING", ea::DYNAMICAL_FLATTENING)?;
    m.add("OBLIQUITY_J2000", ea::OBLIQUITY_J2000)?;
    m.add("IAU2006_PRECESSION_RATE", ea::IAU2006_PRECESSION_RATE)?;
    m.add(
        "IAU2000A_PRINCIPAL_NUTATION",
        ea::IAU2000A_PRINCIPAL_NUTATION,
    )?;
    Ok(())
}
