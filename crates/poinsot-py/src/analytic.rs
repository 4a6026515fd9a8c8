//! Bindings of `poinsot::analytic` (the torque-free solutions; conversion only).
use numpy::{PyArray1, PyArray2, PyReadonlyArray1};
use poinsot::analytic::{axis_stability as core_axis_stability, FreeRigidBody, FreeSymmetricTop};
use poinsot::Vec3;
use pyo3::prelude::*;

use crate::convert::{vec3, vec3_out};
use crate::errors::{invalid, IntoPy};
use crate::frames::{rows_out, vec_in};

/// A (4,) quaternion argument, optional.
pub(crate) fn opt_quat(
    argument: &str,
    a: &Option<PyReadonlyArray1<'_, f64>>,
) -> PyResult<Option<[f64; 4]>> {
    match a {
        None => Ok(None),
        Some(a) => {
            let v = vec_in(a);
            if v.len() != 4 {
                return Err(invalid(
                    argument,
                    format!("must have shape (4,) ([w, x, y, z]), got ({},)", v.len()),
                ));
            }
            Ok(Some([v[0], v[1], v[2], v[3]]))
        }
    }
}

fn a3(v: &Vec3) -> [f64; 3] {
    [v.x, v.y, v.z]
}

fn times_in(t: &PyReadonlyArray1<'_, f64>) -> PyResult<Vec<f64>> {
    let t = vec_in(t);
    poinsot::error::check_finite("t", &t).py()?;
    Ok(t)
}

/// The closed-form free symmetric top (private; use `poinsot.FreeSymmetricTop`).
#[pyclass(module = "poinsot._core", name = "SymmetricTopSolution", frozen)]
pub struct PySymmetricTop {
    inner: FreeSymmetricTop,
}

#[pymethods]
impl PySymmetricTop {
    #[new]
    #[pyo3(signature = (i1, i3, omega0, attitude0=None))]
    fn new(
        i1: f64,
        i3: f64,
        omega0: PyReadonlyArray1<'_, f64>,
        attitude0: Option<PyReadonlyArray1<'_, f64>>,
    ) -> PyResult<Self> {
        let w = Vec3::from(vec3("omega0", &omega0)?);
        let q = opt_quat("attitude0", &attitude0)?;
        Ok(Self {
            inner: FreeSymmetricTop::new(i1, i3, w, q).py()?,
        })
    }
    #[getter]
    fn precession_rate(&self) -> f64 {
        self.inner.precession_rate()
    }
    #[getter]
    fn amplitude(&self) -> f64 {
        self.inner.amplitude()
    }
    #[getter]
    fn phase(&self) -> f64 {
        self.inner.phase()
    }
    #[getter]
    fn omega3(&self) -> f64 {
        self.inner.omega3()
    }
    #[getter]
    fn omega_magnitude(&self) -> f64 {
        self.inner.omega_magnitude()
    }
    #[getter]
    fn energy(&self) -> PyResult<f64> {
        self.inner.energy().py()
    }
    #[getter]
    fn angular_momentum_magnitude(&self) -> PyResult<f64> {
        self.inner.angular_momentum_magnitude().py()
    }
    #[getter]
    fn angular_momentum<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray1<f64>>> {
        Ok(vec3_out(py, a3(&self.inner.angular_momentum().py()?)))
    }
    #[getter]
    fn body_cone_angle(&self) -> f64 {
        self.inner.body_cone_angle()
    }
    #[getter]
    fn space_cone_angle(&self) -> f64 {
        self.inner.space_cone_angle()
    }
    #[getter]
    fn nutation_angle(&self) -> f64 {
        self.inner.nutation_angle()
    }
    #[getter]
    fn space_precession_rate(&self) -> f64 {
        self.inner.space_precession_rate()
    }
    #[getter]
    fn shape(&self) -> &'static str {
        self.inner.shape().as_str()
    }
    /// ω at times t (N,) → (N, 3).
    fn omega<'py>(
        &self,
        py: Python<'py>,
        t: PyReadonlyArray1<'py, f64>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let rows = times_in(&t)?
            .iter()
            .map(|&t| self.inner.omega(t).map(|w| a3(&w)))
            .collect::<poinsot::Result<Vec<[f64; 3]>>>()
            .py()?;
        Ok(rows_out(py, &rows))
    }
    /// Attitudes at times t (N,) → (N, 4) [w, x, y, z].
    fn attitude<'py>(
        &self,
        py: Python<'py>,
        t: PyReadonlyArray1<'py, f64>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let rows = times_in(&t)?
            .iter()
            .map(|&t| self.inner.attitude(t))
            .collect::<poinsot::Result<Vec<[f64; 4]>>>()
            .py()?;
        Ok(rows_out(py, &rows))
    }
    /// The symmetry axis in space at times t (N,) → (N, 3).
    fn symmetry_axis<'py>(
        &self,
        py: Python<'py>,
        t: PyReadonlyArray1<'py, f64>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let rows = times_in(&t)?
            .iter()
            .map(|&t| self.inner.symmetry_axis(t).map(|v| a3(&v)))
            .collect::<poinsot::Result<Vec<[f64; 3]>>>()
            .py()?;
        Ok(rows_out(py, &rows))
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

#[pymethods]
impl PyFreeBody {
    #[new]
    #[pyo3(signature = (moments, omega0, attitude0=None))]
    fn new(
        moments: PyReadonlyArray1<'_, f64>,
        omega0: PyReadonlyArray1<'_, f64>,
        attitude0: Option<PyReadonlyArray1<'_, f64>>,
    ) -> PyResult<Self> {
        let m = vec3("moments", &moments)?;
        let w = Vec3::from(vec3("omega0", &omega0)?);
        let q = opt_quat("attitude0", &attitude0)?;
        Ok(Self {
            inner: FreeRigidBody::new(m, w, q).py()?,
        })
    }
    #[getter]
    fn energy(&self) -> PyResult<f64> {
        self.inner.energy().py()
    }
    #[getter]
    fn angular_momentum<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray1<f64>>> {
        Ok(vec3_out(py, a3(&self.inner.angular_momentum().py()?)))
    }
    #[getter]
    fn regime(&self) -> &'static str {
        self.inner.regime().as_str()
    }
    #[getter]
    fn parameter(&self) -> f64 {
        self.inner.parameter()
    }
    #[getter]
    fn frequency(&self) -> PyResult<f64> {
        self.inner.frequency().py()
    }
    #[getter]
    fn period(&self) -> PyResult<f64> {
        self.inner.period().py()
    }
    #[getter]
    fn flip_interval(&self) -> PyResult<f64> {
        self.inner.flip_interval().py()
    }
    #[getter]
    fn pole_axis(&self) -> Option<usize> {
        self.inner.pole_axis()
    }
    #[getter]
    fn invariable_plane_distance(&self) -> f64 {
        self.inner.invariable_plane_distance()
    }
    /// (ω (N, 3) body, attitude (N, 4) [w, x, y, z], signs continuous) at times t (N,).
    #[allow(clippy::type_complexity)]
    fn state<'py>(
        &self,
        py: Python<'py>,
        t: PyReadonlyArray1<'py, f64>,
    ) -> PyResult<(Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<f64>>)> {
        let times = times_in(&t)?;
        let (w, q) = if times.len() > 4096 {
            py.detach(|| self.inner.sample(&times))
        } else {
            self.inner.sample(&times)
        }
        .py()?;
        Ok((rows_out(py, &w), rows_out(py, &q)))
    }
    /// ω in space components at times t (N,) → (N, 3) (the herpolhode).
    fn omega_space<'py>(
        &self,
        py: Python<'py>,
        t: PyReadonlyArray1<'py, f64>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let rows = times_in(&t)?
            .iter()
            .map(|&t| self.inner.omega_space(t).map(|v| a3(&v)))
            .collect::<poinsot::Result<Vec<[f64; 3]>>>()
            .py()?;
        Ok(rows_out(py, &rows))
    }
    /// L(t) = I·ω(t) in body components at times t (N,) → (N, 3).
    fn angular_momentum_body<'py>(
        &self,
        py: Python<'py>,
        t: PyReadonlyArray1<'py, f64>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let rows = times_in(&t)?
            .iter()
            .map(|&t| self.inner.angular_momentum_body(t).map(|v| a3(&v)))
            .collect::<poinsot::Result<Vec<[f64; 3]>>>()
            .py()?;
        Ok(rows_out(py, &rows))
    }
    /// `samples` points of the polhode (N, 3).
    fn polhode<'py>(&self, py: Python<'py>, samples: usize) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let rows: Vec<[f64; 3]> = self.inner.polhode(samples).py()?.iter().map(a3).collect();
        Ok(rows_out(py, &rows))
    }
    /// The invariable plane's unit normal L̂ (3,).
    #[getter]
    fn invariable_plane_normal<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        vec3_out(py, a3(&self.inner.invariable_plane_normal()))
    }
    /// Poinsot's contact point at times t (N,) → (N, 3), space (`body` false) or body components.
    fn contact_point<'py>(
        &self,
        py: Python<'py>,
        t: PyReadonlyArray1<'py, f64>,
        body: bool,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let rows = times_in(&t)?
            .iter()
            .map(|&t| {
                if body {
                    self.inner.contact_point_body(t)
                } else {
                    self.inner.contact_point(t)
                }
                .map(|v| a3(&v))
            })
            .collect::<poinsot::Result<Vec<[f64; 3]>>>()
            .py()?;
        Ok(rows_out(py, &rows))
    }
    /// `samples` points of the polhode on the inertia ellipsoid (N, 3).
    fn contact_polhode<'py>(
        &self,
        py: Python<'py>,
        samples: usize,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let rows: Vec<[f64; 3]> = self
            .inner
            .contact_polhode(samples)
            .py()?
            .iter()
            .map(a3)
            .collect();
        Ok(rows_out(py, &rows))
    }
}

/// The stability of steady rotation about each principal axis: [(kind, rate)] × 3.
#[pyfunction]
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

/// Registers this file's classes and functions on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PySymmetricTop>()?;
    m.add_class::<PyFreeBody>()?;
    m.add_function(wrap_pyfunction!(axis_stability, m)?)?;
    Ok(())
}
