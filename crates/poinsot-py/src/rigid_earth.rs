//! Bindings of `poinsot::earth::RigidEarth` (conversion and error mapping only): the Earth as a
//! rigid symmetric top. `RigidEarthCore` holds a checked core value; the public, documented
//! class is `poinsot.RigidEarth` (python/poinsot/rigid_earth.py), which holds one. The core
//! names every argument as the caller knows it, so no error is renamed here.
use numpy::PyReadonlyArray1;
use poinsot::earth::{self as ea, RigidEarth};
use poinsot_py_macros::export;
use pyo3::prelude::*;

use crate::control::run;
use crate::convert::{vec_in, Values};
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
    new {
        /// The rigid Earth of dynamical flattening H = (C − A)/C ∈ (0, 1), rate ω > 0 (rad/s)
        /// and obliquity ε ∈ [0, π/2) (rad); errors name them.
        (dynamical_flattening: f64, rotation_rate: f64, obliquity: f64) = RigidEarth::new;
    }

    /// The Chandler period T_E ks/(ks − k2) (s) for Love numbers 0 < k2 < ks.
    fn chandler_period(&self, k2: f64, ks: f64) -> PyResult<f64> {
        self.inner.chandler_period(k2, ks).py()
    }

    /// The spin axis integrated for `duration` (s) under the Sun's and the Moon's torques
    /// along their orbits (`RigidEarth::simulate`; the GIL released, Ctrl-C polled): (t (s),
    /// longitude (rad), obliquity (rad), moon_node (rad), node_rate (rad/s)).
    fn simulate<'py>(
        &self,
        py: Python<'py>,
        duration: f64,
        samples: usize,
        moon_node: f64,
        mean_pole: bool,
        max_steps: usize,
    ) -> PyResult<(Values, Values, Values, f64, f64)> {
        let earth = self.inner;
        let options = ea::SimulateOptions {
            samples,
            moon_node,
            mean_pole,
            max_steps,
        };
        let r = run(py, None, move || earth.simulate(duration, &options))?;
        Ok((
            Values(r.t),
            Values(r.longitude),
            Values(r.obliquity),
            r.moon_node,
            r.node_rate,
        ))
    }

    /// The averaged pole at the times `t` (s) (`RigidEarth::averaged_pole`): the precession
    /// angle ψ (rad, westward), the obliquity ε (rad) and the Moon's node Ω (rad), each of
    /// `t`'s length; the principal nutation multiplied by `nutation_scale`.
    fn averaged_pole(
        &self,
        t: PyReadonlyArray1<'_, f64>,
        moon_node: f64,
        nutation_scale: f64,
    ) -> PyResult<(Values, Values, Values)> {
        let p = self
            .inner
            .averaged_pole(&vec_in(&t), moon_node, nutation_scale)
            .py()?;
        Ok((
            Values(p.psi),
            Values(p.obliquity),
            Values(p.moon_node),
        ))
    }
}

/// The mean precession rate and the principal nutation fitted to a simulated pole
/// (`poinsot::earth::fit_pole`): (precession_rate (rad/s), mean_obliquity (rad),
/// obliquity_rate (rad/s), nutation_longitude (rad), nutation_obliquity (rad)).
#[export]
fn fit_pole(
    t: PyReadonlyArray1<'_, f64>,
    longitude: PyReadonlyArray1<'_, f64>,
    obliquity: PyReadonlyArray1<'_, f64>,
    moon_node: f64,
    node_rate: f64,
) -> PyResult<(f64, f64, f64, f64, f64)> {
    let f = ea::fit_pole(
        &vec_in(&t),
        &vec_in(&longitude),
        &vec_in(&obliquity),
        moon_node,
        node_rate,
    )
    .py()?;
    Ok((
        f.precession_rate,
        f.mean_obliquity,
        f.obliquity_rate,
        f.nutation_longitude,
        f.nutation_obliquity,
    ))
}

/// Registers this file's class and the constants of the rigid Earth on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyRigidEarth>()?;
    m.add_function(wrap_pyfunction!(fit_pole, m)?)?;
    m.add("DYNAMICAL_FLATTENING", ea::DYNAMICAL_FLATTENING)?;
    m.add("OBLIQUITY_J2000", ea::OBLIQUITY_J2000)?;
    m.add("IAU2006_PRECESSION_RATE", ea::IAU2006_PRECESSION_RATE)?;
    m.add(
        "IAU2000A_PRINCIPAL_NUTATION",
        ea::IAU2000A_PRINCIPAL_NUTATION,
    )?;
    Ok(())
}
