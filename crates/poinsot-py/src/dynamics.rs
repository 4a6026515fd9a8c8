//! Bindings of `poinsot::dynamics` (conversion and error mapping only).
//!
//! A torque travels as a kind ("none", "body", "space", "gravity", "gravity_gradient",
//! "callback"), a (3,) vector (body/space), a scalar (m g l, or the mean motion) and, for
//! "callback", a Python callable `f(t, omega (3,), attitude (4,) [w, x, y, z]) -> (3,)` giving
//! the torque in body components.
use std::borrow::Cow;
use std::cell::RefCell;

use numpy::ndarray::{Ix1, Ix2};
use numpy::{PyArray1, PyArray2, PyReadonlyArray, PyReadonlyArray1, PyReadonlyArray2};
use poinsot::dynamics::{
    self as dyn_core, BodyInertia, Method, SimulateOptions, Torque, TorqueContext, TorqueKind,
    TorqueModel, Trajectory,
};
use poinsot::Vec3;
use poinsot_py_macros::export;
use pyo3::prelude::*;

use crate::control::{run, run_attached};
use crate::convert::{matrix, opt_quat, parse, rows_into, rows_view, vector, RunSettings};
use crate::errors::{invalid, IntoPy};

/// A torque model calling Python; the first Python error is kept and NaN returned (which stops
/// the integration).
struct PyTorque<'a, 'py> {
    py: Python<'py>,
    func: &'a Bound<'py, PyAny>,
    error: &'a RefCell<Option<PyErr>>,
}

impl TorqueModel for PyTorque<'_, '_> {
    fn torque(&mut self, ctx: &TorqueContext<'_>) -> Vec3 {
        if self.error.borrow().is_some() {
            return Vec3::repeat(f64::NAN);
        }
        let w = PyArray1::from_slice(self.py, ctx.omega.as_slice());
        let q = poinsot::rotation::matrix_to_quaternion(ctx.attitude).unwrap_or([f64::NAN; 4]);
        let q = PyArray1::from_slice(self.py, &q);
        let got = self.func.call1((ctx.t, w, q)).and_then(|o| {
            let v: Vec<f64> = o.extract()?;
            if v.len() != 3 {
                return Err(invalid(
                    "torque",
                    format!(
                        "the callback must return 3 numbers (body components), got {}",
                        v.len()
                    ),
                ));
            }
            let state_finite = ctx.omega.iter().all(|x| x.is_finite()) && ctx.t.is_finite();
            if state_finite && v.iter().any(|x| x.is_nan()) {
                return Err(crate::errors::to_py(poinsot::Error::diverged(
                    "torque",
                    format!(
                        "the callback returned {v:?} at t = {} s for omega = {:?}: a torque must be finite",
                        ctx.t,
                        ctx.omega.as_slice()
                    ),
                )));
            }
            Ok(Vec3::new(v[0], v[1], v[2]))
        });
        match got {
            Ok(v) => v,
            Err(e) => {
                self.error.borrow_mut().get_or_insert(e);
                Vec3::repeat(f64::NAN)
            }
        }
    }
}

/// One body's sampled trajectory (the core's `dynamics::Trajectory`; see `poinsot.Trajectory`):
/// t (N,) (s), omega (N, 3) (rad/s, body), attitude (N, 4) ([w, x, y, z]), angular_momentum
/// (N, 3) (kg·m²/s, space), energy, potential (J) and power (W) (N,), the method's name, the
/// fixed step (s, None for "exact" and "dop853") and the work counters.
#[pyclass(module = "poinsot._core", name = "TrajectoryCore", frozen, get_all)]
pub struct PyTrajectory {
    t: Py<PyArray1<f64>>,
    omega: Py<PyArray2<f64>>,
    attitude: Py<PyArray2<f64>>,
    angular_momentum: Py<PyArray2<f64>>,
    energy: Py<PyArray1<f64>>,
    potential: Py<PyArray1<f64>>,
    power: Py<PyArray1<f64>>,
    method: String,
    step: Option<f64>,
    steps: usize,
    torque_evaluations: usize,
}

impl PyTrajectory {
    pub(crate) fn new(py: Python<'_>, tr: Trajectory) -> PyResult<Self> {
        Ok(Self {
            t: PyArray1::from_vec(py, tr.t).unbind(),
            omega: rows_into(py, tr.omega)?.unbind(),
            attitude: rows_into(py, tr.attitude)?.unbind(),
            angular_momentum: rows_into(py, tr.angular_momentum)?.unbind(),
            energy: PyArray1::from_vec(py, tr.energy).unbind(),
            potential: PyArray1::from_vec(py, tr.potential).unbind(),
            power: PyArray1::from_vec(py, tr.power).unbind(),
            method: tr.method.name(),
            step: tr.step,
            steps: tr.steps,
            torque_evaluations: tr.torque_evaluations,
        })
    }
}

/// A torque as Python's `dynamics._torque_spec` (or a torque's `_spec`) makes it, one tuple:
/// the kind's name ("none", "body", "space", "gravity", "gravity_gradient", "callback"), the
/// (3,) vector (N·m; body and space) and the scalar (m g l, J; or the mean motion, rad/s).
pub(crate) type TorqueSpec<'py> = (String, PyReadonlyArray1<'py, f64>, f64);

/// The core's torque of a built-in kind (a "callback" is refused: it needs a callable), the
/// errors naming `torque` (or the scalar's name).
pub(crate) fn torque(spec: &TorqueSpec<'_>) -> PyResult<Torque> {
    let (kind, torque_vector, scalar) = spec;
    parse::<TorqueKind>(kind)?
        .torque(vector("torque", torque_vector)?, *scalar)
        .py()
}

/// The settings of a batch of bodies (`simulate_batch`, `sweep.simulate`) as Python's
/// `dynamics._batch_settings` makes them, one tuple: the duration (s), the [`TorqueSpec`], the
/// method, the step (s, None: each body's default) and the step limit.
pub(crate) type BatchSettings<'py> = (f64, TorqueSpec<'py>, String, Option<f64>, usize);

/// A batch's [`BatchSettings`] as the core's duration (s), torque and options.
pub(crate) fn batch_settings(
    settings: &BatchSettings<'_>,
) -> PyResult<(f64, Torque, SimulateOptions)> {
    let (duration, spec, method, dt, max_steps) = settings;
    let torque = torque(spec)?;
    let opts = SimulateOptions {
        method: Method::parse(method).py()?,
        dt: *dt,
        max_steps: *max_steps,
        ..SimulateOptions::default()
    };
    Ok((*duration, torque, opts))
}

/// Bodies and how they start, one argument (a tuple) extracted once: the inertia (kg·m²), ω₀
/// (rad/s) and the attitude or None — of one run ([`Start`]: a (3, 3) tensor, (3,), (4,)) or
/// of a batch ([`Bodies`]: principal moments (N, 3), (N, 3), (N, 4)).
pub(crate) type Initial<'py, D> = (
    PyReadonlyArray2<'py, f64>,
    PyReadonlyArray<'py, f64, D>,
    Option<PyReadonlyArray<'py, f64, D>>,
);

/// One run's start (`simulate`, `simulate_carried`).
pub(crate) type Start<'py> = Initial<'py, Ix1>;

/// A batch of bodies (`simulate_batch`, `free_body_states`).
pub(crate) type Bodies<'py> = Initial<'py, Ix2>;

/// A run's start as the core's body, ω₀ and attitude, each error naming its argument (`body`,
/// `omega0`, `attitude0`).
pub(crate) fn initial_state(s: &Start<'_>) -> PyResult<(BodyInertia, Vec3, Option<[f64; 4]>)> {
    Ok((
        BodyInertia::from_tensor(&matrix("body", &s.0)?).py()?,
        vector("omega0", &s.1)?,
        opt_quat("attitude0", &s.2)?,
    ))
}

/// The rows of a batch of bodies, borrowed where the arrays allow: moments (N, 3), ω₀ (N, 3)
/// and the attitudes (N, 4) or None.
pub(crate) type BodyRows<'a> = (
    Cow<'a, [[f64; 3]]>,
    Cow<'a, [[f64; 3]]>,
    Option<Cow<'a, [[f64; 4]]>>,
);

/// A batch's rows, each shape error naming its argument (`moments`, `omega0`, `attitude0`).
pub(crate) fn body_rows<'a>(b: &'a Bodies<'_>) -> PyResult<BodyRows<'a>> {
    let m = rows_view::<3>("moments", &b.0)?;
    let w = rows_view::<3>("omega0", &b.1)?;
    let q = match &b.2 {
        Some(a) => Some(rows_view::<4>("attitude0", a)?),
        None => None,
    };
    Ok((m, w, q))
}

/// Simulates one body (see `poinsot.simulate`).
#[export]
#[pyo3(signature = (start, duration, torque, torque_fn, method, dt, settings, progress))]
#[allow(clippy::too_many_arguments)]
fn dynamics_simulate<'py>(
    py: Python<'py>,
    start: Start<'py>,
    duration: f64,
    torque: TorqueSpec<'py>,
    torque_fn: Option<Bound<'py, PyAny>>,
    method: &str,
    dt: Option<f64>,
    settings: RunSettings,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<PyTrajectory> {
    let (body, w0, q0) = initial_state(&start)?;
    let opts = SimulateOptions {
        dt,
        ..settings.simulate(method)?
    };
    let error: RefCell<Option<PyErr>> = RefCell::new(None);
    let callback = parse::<TorqueKind>(&torque.0)? == TorqueKind::Callback;
    let tr = if let (true, Some(func)) = (callback, &torque_fn) {
        let mut model = PyTorque {
            py,
            func,
            error: &error,
        };
        let result = run_attached(py, progress.as_ref(), || {
            dyn_core::simulate(&body, w0, q0, duration, &mut model, &opts)
        });
        // The callback's own exception explains a run it stopped.
        if let Some(e) = error.into_inner() {
            return Err(e);
        }
        result?
    } else {
        let mut torque = self::torque(&torque)?;
        run(py, progress.as_ref(), || {
            dyn_core::simulate(&body, w0, q0, duration, &mut torque, &opts)
        })?
    };
    PyTrajectory::new(py, tr)
}

/// The final states of a batch: ω (N, 3), attitudes (N, 4) and the steps taken per body.
type Finals<'py> = (Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<f64>>, usize);

/// Simulates many bodies in parallel (see `poinsot.simulate_batch`): the [`Bodies`] and the
/// [`BatchSettings`] → [`Finals`].
#[export]
#[pyo3(signature = (bodies, settings, progress))]
fn dynamics_simulate_batch<'py>(
    py: Python<'py>,
    bodies: Bodies<'py>,
    settings: BatchSettings<'py>,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<Finals<'py>> {
    let (m, w, q) = body_rows(&bodies)?;
    let (duration, torque, opts) = batch_settings(&settings)?;
    let out = run(py, progress.as_ref(), || {
        dyn_core::simulate_batch(&m, &w, q.as_deref(), duration, &torque, &opts)
    })?;
    Ok((
        rows_into(py, out.omega)?,
        rows_into(py, out.attitude)?,
        out.steps,
    ))
}

/// Registers this file's functions on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyTrajectory>()?;
    add_functions!(m; dynamics_simulate, dynamics_simulate_batch);
    Ok(())
}
