//! Bindings of `poinsot::analytic` (the torque-free solutions; conversion only).
use numpy::{PyArray1, PyArray3, PyArrayMethods, PyReadonlyArray1};
use poinsot::analytic::{
    axis_stability as core_axis_stability, free_body_states as core_free_body_states,
    FreeRigidBody, FreeSymmetricTop, StateTimes,
};
use poinsot_py_macros::export;
use pyo3::prelude::*;

use crate::control::{map_each, run};
use crate::convert::{opt_quat, slice, times, triple, vec3, Numbers, Rows, Vector};
use crate::dynamics::{body_rows, Bodies};
use crate::errors::IntoPy;

/// `f` at each of the times `t` (N,), each finite → (N, K) rows (without the GIL, stoppable by
/// Ctrl-C).
fn at_times<T: Send, const K: usize>(
    py: Python<'_>,
    t: &PyReadonlyArray1<'_, f64>,
    f: impl Fn(f64) -> poinsot::Result<T> + Send,
) -> PyResult<Rows<K>>
where
    Rows<K>: FromIterator<T>,
{
    Ok(map_each(py, &times(t)?, move |&t| f(t))?
        .into_iter()
        .collect())
}

/// The closed-form free symmetric top (private; use `poinsot.FreeSymmetricTop`).
#[pyclass(module = "poinsot._core", name = "SymmetricTopSolution", frozen)]
pub struct PySymmetricTop {
    inner: FreeSymmetricTop,
}

core_export! {
    impl PySymmetricTop;
    getters {
        precession_rate -> f64;
        amplitude -> f64;
        phase -> f64;
        omega3 -> f64;
        omega_magnitude -> f64;
        body_cone_angle -> f64;
        space_cone_angle -> f64;
        nutation_angle -> f64;
        space_precession_rate -> f64;
        /// The largest |t| (s) at which ω(t) and the attitude are computed (phase 2⁴² rad).
        max_time -> f64;
        /// ω at t = 0 as given (body, rad/s, (3,)).
        omega0.into() -> Vector;
        shape.as_str() -> &'static str;
    }
    fallible {
        energy -> f64;
        angular_momentum_magnitude -> f64;
        angular_momentum.map(Vector) -> Vector;
        /// 2π/|Ω| (s), the body-frame precession period.
        precession_period -> f64;
    }

    #[new]
    #[pyo3(signature = (i1, i3, omega0, attitude0=None))]
    fn new(
        i1: f64,
        i3: f64,
        omega0: &Bound<'_, PyAny>,
        attitude0: Option<PyReadonlyArray1<'_, f64>>,
    ) -> PyResult<Self> {
        let w = triple("omega0", omega0, true)?.into();
        let q = opt_quat("attitude0", &attitude0)?;
        Ok(Self {
            inner: FreeSymmetricTop::new(i1, i3, w, q).py()?,
        })
    }
    /// ω at times t (N,) → (N, 3).
    fn omega(&self, py: Python<'_>, t: PyReadonlyArray1<'_, f64>) -> PyResult<Rows<3>> {
        at_times(py, &t, |t| self.inner.omega(t))
    }
    /// Attitudes at times t (N,) → (N, 4) [w, x, y, z].
    fn attitude(&self, py: Python<'_>, t: PyReadonlyArray1<'_, f64>) -> PyResult<Rows<4>> {
        at_times(py, &t, |t| self.inner.attitude(t))
    }
    /// The symmetry axis in space at times t (N,) → (N, 3).
    fn symmetry_axis(&self, py: Python<'_>, t: PyReadonlyArray1<'_, f64>) -> PyResult<Rows<3>> {
        at_times(py, &t, |t| self.inner.symmetry_axis(t))
    }
    /// ω at one time t → (3,).
    fn omega_at(&self, t: f64) -> PyResult<Vector> {
        self.inner.omega(t).map(Vector).py()
    }
    /// The attitude at one time t → (4,) [w, x, y, z].
    fn attitude_at(&self, t: f64) -> PyResult<Numbers<4>> {
        self.inner.attitude(t).map(Numbers).py()
    }
    /// The symmetry axis in space at one time t → (3,).
    fn symmetry_axis_at(&self, t: f64) -> PyResult<Vector> {
        self.inner.symmetry_axis(t).map(Vector).py()
    }
    /// ω₃² from T and |L| (2.95).
    #[staticmethod]
    fn omega3_squared_from(i1: f64, i3: f64, energy: f64, l: f64) -> PyResult<f64> {
        FreeSymmetricTop::omega3_squared_from(i1, i3, energy, l).py()
    }
    /// A² from T and |L| (2.96).
    #[staticmethod]
    fn amplitude_squared_from(i1: f64, i3: f64, energy: f64, l: f64) -> PyResult<f64> {
        FreeSymmetricTop::amplitude_squared_from(i1, i3, energy, l).py()
    }
}

/// The exact free rigid body (private; use `poinsot.FreeRigidBody`).
#[pyclass(module = "poinsot._core", name = "FreeBodySolution", frozen)]
pub struct PyFreeBody {
    inner: FreeRigidBody,
}

core_export! {
    impl PyFreeBody;
    getters {
        parameter -> f64;
        pole_axis -> Option<usize>;
        /// |ω| of a steady rotation (rad/s), None where ω moves in the body.
        steady_rate -> Option<f64>;
        /// The intermediate axis (index) a body started nearest it flips about, or None.
        flips_about -> Option<usize>;
        invariable_plane_distance -> f64;
        /// The largest |t| (s) at which the state is computed (phase 2⁴² rad; `inf` when the
        /// body never turns that far within the double range).
        max_time -> f64;
        /// The principal moments as given (kg·m², (3,)).
        moments.into() -> Vector;
        /// ω at t = 0 as given (body, rad/s, (3,)).
        omega0.into() -> Vector;
        regime.as_str() -> &'static str;
        /// The invariable plane's unit normal L̂ (3,).
        invariable_plane_normal.into() -> Vector;
    }
    fallible {
        energy -> f64;
        angular_momentum.map(Vector) -> Vector;
        /// |L| (kg·m²/s).
        angular_momentum_magnitude -> f64;
        frequency -> f64;
        period -> f64;
        flip_interval -> f64;
    }

    #[new]
    #[pyo3(signature = (moments, omega0, attitude0=None))]
    fn new(
        moments: &Bound<'_, PyAny>,
        omega0: &Bound<'_, PyAny>,
        attitude0: Option<PyReadonlyArray1<'_, f64>>,
    ) -> PyResult<Self> {
        let m = triple("moments", moments, false)?;
        let w = triple("omega0", omega0, true)?.into();
        let q = opt_quat("attitude0", &attitude0)?;
        Ok(Self {
            inner: FreeRigidBody::new(m, w, q).py()?,
        })
    }
    /// (ω (N, 3) body, attitude (N, 4) [w, x, y, z], signs continuous) at times t (N,).
    fn state(&self, py: Python<'_>, t: PyReadonlyArray1<'_, f64>) -> PyResult<(Rows<3>, Rows<4>)> {
        let times = times(&t)?;
        let (w, q) = run(py, None, || self.inner.sample(&times))?;
        Ok((Rows(w), Rows(q)))
    }
    /// (ω (3,) body, attitude (4,) [w, x, y, z]) at one time t: `state` of [t] without the
    /// arrays of times (the same numbers).
    fn state_at(&self, t: f64) -> PyResult<(Vector, Numbers<4>)> {
        let (w, q) = self.inner.state(t).py()?;
        Ok((Vector(w), Numbers(q)))
    }
    /// ω in space components at times t (N,) → (N, 3) (the herpolhode).
    fn omega_space(&self, py: Python<'_>, t: PyReadonlyArray1<'_, f64>) -> PyResult<Rows<3>> {
        at_times(py, &t, |t| self.inner.omega_space(t))
    }
    /// L(t) = I·ω(t) in body components at times t (N,) → (N, 3).
    fn angular_momentum_body(
        &self,
        py: Python<'_>,
        t: PyReadonlyArray1<'_, f64>,
    ) -> PyResult<Rows<3>> {
        at_times(py, &t, |t| self.inner.angular_momentum_body(t))
    }
    /// `samples` points of the polhode (N, 3).
    fn polhode(&self, py: Python<'_>, samples: usize) -> PyResult<Rows<3>> {
        Ok(run(py, None, || self.inner.polhode(samples))?
            .into_iter()
            .collect())
    }
    /// Poinsot's contact point at times t (N,) → (N, 3), space (`body` false) or body components.
    fn contact_point(
        &self,
        py: Python<'_>,
        t: PyReadonlyArray1<'_, f64>,
        body: bool,
    ) -> PyResult<Rows<3>> {
        at_times(py, &t, |t| {
            if body {
                self.inner.contact_point_body(t)
            } else {
                self.inner.contact_point(t)
            }
        })
    }
    /// `samples` points of the polhode on the inertia ellipsoid (N, 3).
    fn contact_polhode(&self, py: Python<'_>, samples: usize) -> PyResult<Rows<3>> {
        Ok(run(py, None, || self.inner.contact_polhode(samples))?
            .into_iter()
            .collect())
    }
    /// The stability of steady rotation about each axis at this body's |ω₀|: [(kind, rate)] × 3.
    fn axis_stability(&self) -> PyResult<Vec<(&'static str, f64)>> {
        Ok(self
            .inner
            .axis_stability()
            .py()?
            .iter()
            .map(|a| (a.stability.as_str(), a.rate))
            .collect())
    }
}

/// The stability of steady rotation about each principal axis: [(kind, rate)] × 3.
#[export]
fn axis_stability(
    moments: PyReadonlyArray1<'_, f64>,
    spin: f64,
) -> PyResult<Vec<(&'static str, f64)>> {
    let m = vec3("moments", &moments)?;
    Ok(core_axis_stability(m, spin)
        .py()?
        .iter()
        .map(|a| (a.stability.as_str(), a.rate))
        .collect())
}

/// The exact states of N free bodies at M times each (see `poinsot.free_body_states`): the
/// [`Bodies`] (principal moments (N, 3), ω₀ (N, 3), attitudes (N, 4) or None) and the times
/// `t` flat: M values for every body, or (`per_body`) N·M values row-major → (ω (N, M, 3),
/// attitude (N, M, 4)).
#[export]
#[pyo3(signature = (bodies, t, per_body, progress))]
#[allow(clippy::type_complexity)]
fn free_body_states<'py>(
    py: Python<'py>,
    bodies: Bodies<'py>,
    t: PyReadonlyArray1<'py, f64>,
    per_body: bool,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<(Bound<'py, PyArray3<f64>>, Bound<'py, PyArray3<f64>>)> {
    let (m, w, q) = body_rows(&bodies)?;
    let ts = slice("t", &t, "must be a C-contiguous float64 array")?;
    let times = if per_body {
        StateTimes::PerBody(ts)
    } else {
        StateTimes::Shared(ts)
    };
    let out = run(py, progress.as_ref(), || {
        core_free_body_states(&m, &w, q.as_deref(), times)
    })?;
    let (n, k) = (out.bodies, out.times);
    let omega = PyArray1::from_vec(py, out.omega.into_flattened()).reshape([n, k, 3])?;
    let attitude = PyArray1::from_vec(py, out.attitude.into_flattened()).reshape([n, k, 4])?;
    Ok((omega, attitude))
}

/// Registers this file's classes and functions on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PySymmetricTop>()?;
    m.add_class::<PyFreeBody>()?;
    m.add_function(wrap_pyfunction!(axis_stability, m)?)?;
    m.add_function(wrap_pyfunction!(free_body_states, m)?)?;
    Ok(())
}
