//! Bindings of `poinsot::analytic`'s heavy symmetric top (conversion and error mapping only).
//!
//! `HeavyTopCore` wraps `poinsot::analytic::HeavyTop`; the public, documented class is
//! `poinsot.HeavyTop` (python/poinsot/top.py), which holds one of these.
use numpy::{PyArray2, PyArrayMethods, PyReadonlyArray1};
use poinsot::analytic::{self, EulerState, HeavyTop, VerticalPass};
use poinsot_py_macros::export;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::control::{map_each, run};
use crate::convert::{self, fields_dict, Rows, Values};
use crate::errors::{invalid, IntoPy};

/// A heavy symmetric top with its exact motion (private; use `poinsot.HeavyTop`).
#[pyclass(module = "poinsot._core", name = "HeavyTopCore", frozen)]
pub struct PyHeavyTop {
    inner: HeavyTop,
}

/// A contiguous (N,) float64 array as a slice.
fn slice<'a>(argument: &str, a: &'a PyReadonlyArray1<'_, f64>) -> PyResult<&'a [f64]> {
    convert::slice(argument, a, "must be a C-contiguous float64 array")
}

/// Evaluates `f` over `times` into a new (N, 3) array, without the GIL, stoppable by Ctrl-C.
fn batch<'py>(
    py: Python<'py>,
    times: &PyReadonlyArray1<'py, f64>,
    f: impl Fn(&[f64], &mut [f64]) -> poinsot::Result<()> + Send + Sync,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let ts = slice("t", times)?;
    let n = ts.len();
    // numpy's own allocation: large results get transparent huge pages (numpy's madvise),
    // far fewer page faults than a fresh Vec of the same size.
    let arr = PyArray2::<f64>::zeros(py, (n, 3), false);
    {
        let mut rw = arr.readwrite();
        let out = rw.as_slice_mut().map_err(|e| invalid("t", e.to_string()))?;
        run(py, None, || f(ts, out).map_err(|e| e.renamed("times", "t")))?;
    }
    Ok(arr)
}

/// Angles θ (rad, (N,)).
type Angles<'py> = PyReadonlyArray1<'py, f64>;

/// `f` at each of the angles `theta`, without the GIL, stoppable by Ctrl-C.
fn each_theta(
    py: Python<'_>,
    theta: &Angles<'_>,
    f: impl Fn(f64) -> poinsot::Result<f64> + Sync,
) -> PyResult<Values> {
    Ok(map_each(py, slice("theta", theta)?, |&th| f(th))?
        .into_iter()
        .collect())
}

/// Evaluates `f` (a batch kernel) at the one time `t`, with the GIL held (releasing it costs
/// more than one evaluation); errors name `t` as in [`batch`].
fn one(t: f64, f: impl Fn(&[f64], &mut [f64]) -> poinsot::Result<()>) -> PyResult<(f64, f64, f64)> {
    let mut out = [0.0; 3];
    f(&[t], &mut out)
        .map_err(|e| e.renamed("times", "t"))
        .py()?;
    Ok((out[0], out[1], out[2]))
}

/// The top's parameters (I₁, I₃ kg·m², m g l J), one argument as Python's `top._parameters`
/// makes them.
type Top = (f64, f64, f64);

/// The top made by the core (`make`), its error mapped.
fn made(make: poinsot::Result<HeavyTop>) -> PyResult<PyHeavyTop> {
    Ok(PyHeavyTop { inner: make.py()? })
}

/// `core_export!` of `PyHeavyTop` with the core's functions of θ at (N,) angles (`per_theta {
/// name; … }`, through [`each_theta`]) and its batch kernels at (N,) times (`per_time { name =>
/// kernel; … }`, through [`batch`]).
macro_rules! heavy_top_export {
    (
        per_theta { $($(#[$tdoc:meta])* $per_theta:ident;)* }
        per_time { $($(#[$bdoc:meta])* $per_time:ident => $kernel:ident;)* }
        $($rest:tt)*
    ) => {
        core_export! {
            impl PyHeavyTop;
            $($rest)*
            $($(#[$tdoc])*
            fn $per_theta(&self, py: Python<'_>, theta: Angles<'_>) -> PyResult<Values> {
                each_theta(py, &theta, |th| self.inner.$per_theta(th))
            })*
            $($(#[$bdoc])*
            fn $per_time<'py>(
                &self,
                py: Python<'py>,
                t: PyReadonlyArray1<'py, f64>,
            ) -> PyResult<Bound<'py, PyArray2<f64>>> {
                batch(py, &t, |ts, out| self.inner.$kernel(ts, out))
            })*
        }
    };
}

heavy_top_export! {
    per_theta {
        /// V(θ) (J) at (N,) angles θ (rad).
        effective_potential;
        /// dV/dθ (N·m) at (N,) angles θ (rad).
        effective_potential_derivative;
    }
    per_time {
        /// (N, 3) Euler angles [φ, θ, ψ] (rad) at (N,) times (s).
        euler_angles => euler_angles_into;
        /// (N, 3) Euler-angle rates [φ̇, θ̇, ψ̇] (rad/s) at (N,) times (s).
        euler_rates => euler_rates_into;
    }

    getters {
        p_phi -> f64;
        p_psi -> f64;
        omega3 -> f64;
        energy -> f64;
        reduced_energy -> f64;
        /// (θ₁, θ₂), rad.
        turning_points -> (f64, f64);
        /// (u₁, u₂, u₃): the roots of the cubic in u = cos θ (u₃ = inf for m g l = 0).
        cubic_roots -> (f64, f64, f64);
        is_sleeping_stable -> bool;
        /// The nutation period (s), None when θ never returns.
        nutation_period -> Option<f64>;
        mean_precession_rate -> f64;
        /// The precession period 2π/|⟨φ̇⟩| (s), None when the axis does not turn on average.
        precession_period -> Option<f64>;
        mean_spin_rate -> f64;
        fourier_terms -> usize;
        motion_class.name() -> &'static str;
    }

    /// The top started at t = 0 from the Euler angles and rates (φ, θ, ψ, φ̇, θ̇, ψ̇) (rad,
    /// rad/s).
    #[staticmethod]
    fn from_state(top: Top, state: [f64; 6]) -> PyResult<Self> {
        let ((i1, i3, mgl), [phi, theta, psi, phi_dot, theta_dot, psi_dot]) = (top, state);
        let state = EulerState::new(phi, theta, psi, phi_dot, theta_dot, psi_dot);
        made(HeavyTop::new(i1, i3, mgl, state))
    }

    /// The top started from (φ, θ, ψ, φ̇, θ̇, ω₃): the spin ω₃ instead of ψ̇ (2.99).
    #[staticmethod]
    fn from_spin(top: Top, state: [f64; 6]) -> PyResult<Self> {
        let ((i1, i3, mgl), [phi, theta, psi, phi_dot, theta_dot, omega3]) = (top, state);
        made(HeavyTop::with_spin(i1, i3, mgl, phi, theta, psi, phi_dot, theta_dot, omega3))
    }

    /// The top given by (p_φ, p_ψ) (kg·m²/s) and E (J); t = 0 at the upper turning point.
    #[staticmethod]
    fn from_constants(top: Top, constants: (f64, f64, f64)) -> PyResult<Self> {
        let ((i1, i3, mgl), (p_phi, p_psi, energy)) = (top, constants);
        made(HeavyTop::from_constants(i1, i3, mgl, p_phi, p_psi, energy))
    }

    /// The pole a top of class "through vertical" passes through: "upright", "straight
    /// down" or "both"; None for every other class.
    #[getter]
    fn vertical_pass(&self) -> Option<&'static str> {
        self.inner.vertical_pass().map(VerticalPass::name)
    }
    /// (I₁, I₃, m g l).
    #[getter]
    fn parameters(&self) -> (f64, f64, f64) {
        (self.inner.i1(), self.inner.i3(), self.inner.mgl())
    }
    /// (φ, θ, ψ, φ̇, θ̇, ψ̇) at t = 0.
    #[getter]
    fn initial_state(&self) -> (f64, f64, f64, f64, f64, f64) {
        let s = self.inner.initial_state();
        (s.phi, s.theta, s.psi, s.phi_dot, s.theta_dot, s.psi_dot)
    }

    /// (φ, θ, ψ) (rad) at one time t (s): `euler_angles` of [t] without the arrays (the same
    /// numbers, by the same batch kernel).
    fn euler_angles_at(&self, t: f64) -> PyResult<(f64, f64, f64)> {
        one(t, |ts, out| self.inner.euler_angles_into(ts, out))
    }

    /// (φ̇, θ̇, ψ̇) (rad/s) at one time t (s): `euler_rates` of [t] without the arrays.
    fn euler_rates_at(&self, t: f64) -> PyResult<(f64, f64, f64)> {
        one(t, |ts, out| self.inner.euler_rates_into(ts, out))
    }

    /// (N, 3) Euler angles by the incomplete elliptic integrals (sn, R_J) at every time.
    fn euler_angles_carlson(
        &self,
        py: Python<'_>,
        t: PyReadonlyArray1<'_, f64>,
    ) -> PyResult<Rows<3>> {
        let ts = slice("t", &t)?;
        poinsot::error::check_finite("t", ts).py()?;
        let rows = map_each(py, ts, |&x| self.inner.euler_angles_carlson(x))?;
        Ok(rows.into_iter().collect())
    }
}

/// The steady-precession rates at θ₀ and ω₃ as a dict: slow, fast, slow_approx (2.121),
/// fast_approx (2.120 corrected), fast_approx_as_printed (2.120 as printed), min_spin (2.119).
#[export]
fn heavy_top_steady_precession<'py>(
    py: Python<'py>,
    top: Top,
    theta0: f64,
    omega3: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let (i1, i3, mgl) = top;
    let s = analytic::steady_precession(i1, i3, mgl, theta0, omega3).py()?;
    Ok(fields_dict!(py, s; slow, fast, slow_approx, fast_approx, fast_approx_as_printed, min_spin))
}

/// The minimum spin 2.119 (rad/s) at θ₀.
#[export]
fn heavy_top_min_spin(top: Top, theta0: f64) -> PyResult<f64> {
    let (i1, i3, mgl) = top;
    analytic::min_spin(i1, i3, mgl, theta0).py()
}

/// The sleeping-top threshold 2√(m g l I₁)/I₃ (rad/s).
#[export]
fn heavy_top_sleeping_threshold(top: Top) -> PyResult<f64> {
    let (i1, i3, mgl) = top;
    analytic::sleeping_threshold(i1, i3, mgl).py()
}

/// Exports functions of the [`Top`] at one state (θ rad; θ̇, φ̇, ψ̇ rad/s): `of_state!(doc
/// name -> T = compute; …)` is `name(top, (theta, theta_dot, phi_dot, psi_dot)) -> T`,
/// `compute(i1, i3, mgl, &state)`.
macro_rules! of_state {
    ($($(#[$doc:meta])* $name:ident -> $out:ty = $compute:expr;)*) => {
        $($(#[$doc])*
        #[export]
        fn $name(top: Top, state: [f64; 4]) -> PyResult<$out> {
            let ((i1, i3, mgl), [theta, theta_dot, phi_dot, psi_dot]) = (top, state);
            let s = EulerState::with_rates(theta, theta_dot, phi_dot, psi_dot);
            let compute: fn(f64, f64, f64, &EulerState) -> poinsot::Result<$out> = $compute;
            compute(i1, i3, mgl, &s).py()
        })*
    };
}

of_state! {
    /// The Lagrangian 2.102 (J) at one state.
    heavy_top_lagrangian -> f64 = analytic::lagrangian;
    /// (p_φ, p_ψ, E) of one state (2.103–2.105), for the drift of a solution.
    heavy_top_constants_of_state -> (f64, f64, f64) = |i1, i3, mgl, s| {
        let c = analytic::constants_of_state(i1, i3, mgl, s)?;
        Ok((c.p_phi, c.p_psi, c.energy))
    };
}

/// Registers the heavy-top class and functions.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyHeavyTop>()?;
    add_functions!(m; heavy_top_steady_precession, heavy_top_min_spin,
        heavy_top_sleeping_threshold, heavy_top_lagrangian, heavy_top_constants_of_state);
    Ok(())
}
