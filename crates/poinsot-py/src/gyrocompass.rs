//! Bindings of `poinsot::dynamics::{simulate_carried, Gyrocompass}` (conversion and error
//! mapping only). `GyrocompassCore` holds a checked core value; the public, documented class is
//! `poinsot.Gyrocompass` (python/poinsot/gyrocompass.py). The carrying frame travels as a kind
//! ("frame" or "earth"), the packed frame (24,) (as the frames binding takes it), the pivot and
//! gravity (3,), and the Earth (`EarthCore`) and latitude.
use numpy::PyReadonlyArray1;
use poinsot::dynamics::{
    simulate_carried, Carrier, CompassRun, Gyrocompass, Load, Ship, Track, Turn,
};
use poinsot::earth::Earth;
use poinsot::Vec3;
use poinsot_py_macros::export;
use pyo3::prelude::*;
use pyo3::types::PyType;

use crate::control::run;
use crate::convert::{rows_into, vec_in, vector, RunSettings, Values};
use crate::dynamics::{initial_state, PyTrajectory, Start, TorqueSpec};
use crate::earth::PyEarth;
use crate::errors::{invalid, IntoPy};
use crate::frames::frame_arg;

/// A pendulous gyrocompass (private; use `poinsot.Gyrocompass`): the core's `Gyrocompass`,
/// checked when made.
#[pyclass(module = "poinsot._core", name = "GyrocompassCore", frozen)]
pub struct PyGyrocompass {
    inner: Gyrocompass,
}

/// The constructor's arguments: latitude, H, P, ζ, inertia and the Earth.
type Args = (f64, f64, f64, f64, [f64; 3], PyEarth);

/// A compass run's (t, heading, tilt, latitude) arrays (s, rad).
type CompassArrays = (Values, Values, Values, Values);

/// The core's compass run `work` (the GIL released, Ctrl-C polled, `progress(fraction)` called
/// when given) as its arrays.
fn compass_run(
    py: Python<'_>,
    progress: Option<Bound<'_, PyAny>>,
    work: impl FnOnce() -> poinsot::Result<CompassRun> + Send,
) -> PyResult<CompassArrays> {
    let out = run(py, progress.as_ref(), work)?;
    Ok((
        Values(out.t),
        Values(out.heading),
        Values(out.tilt),
        Values(out.latitude),
    ))
}

/// The constructor's arguments of a compass, in order.
fn args(c: &Gyrocompass) -> Args {
    (
        c.latitude,
        c.angular_momentum,
        c.pendulosity,
        c.damping,
        c.inertia,
        PyEarth { inner: c.earth },
    )
}

core_export! {
    impl PyGyrocompass;
    getters {
        /// ω_n (rad/s).
        natural_frequency -> f64;
        /// D (N·m/rad).
        damping_coefficient -> f64;
        /// k (N·m·s).
        viscous_coefficient -> f64;
        /// Ω R cos λ (m/s).
        ground_speed -> f64;
    }
    fallible {
        /// 2π √(H/(P Ω cos λ)) (s).
        period -> f64;
        /// (latitude error, tilt) of the settled compass (rad).
        settle -> (f64, f64);
    }

    /// latitude (rad), H (kg·m²/s; None: the core's Schuler-tuned H,
    /// `Gyrocompass::schuler_tuned`), P = m g l (N·m), damping ratio ζ, inertia (3,) (kg·m²) and
    /// the Earth (checked when made); errors name them.
    #[new]
    fn new(
        latitude: f64,
        angular_momentum: Option<f64>,
        pendulosity: f64,
        damping: f64,
        inertia: [f64; 3],
        earth: PyRef<'_, PyEarth>,
    ) -> PyResult<Self> {
        let (p, d, e) = (pendulosity, damping, earth.inner);
        let c = match angular_momentum {
            Some(h) => Gyrocompass::new(latitude, h, p, d, inertia, e),
            None => Gyrocompass::schuler_tuned(latitude, p, d, inertia, e),
        };
        Ok(Self { inner: c.py()? })
    }

    /// 2π √(R/g) (s) of the Earth.
    #[staticmethod]
    fn schuler_period(earth: PyRef<'_, PyEarth>) -> f64 {
        Gyrocompass::schuler_period(&earth.inner)
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> (Bound<'py, PyType>, Args) {
        (slf.get_type(), args(&slf.get().inner))
    }

    /// The constructor's arguments, in order.
    #[getter]
    fn args(&self) -> Args {
        args(&self.inner)
    }

    /// δ (rad) for speed (m/s) and course (rad).
    fn speed_error(&self, speed: f64, course: f64) -> PyResult<f64> {
        self.inner.speed_error(speed, course).py()
    }

    /// V cos C / (Ω R cos λ) (rad).
    fn speed_error_small_angle(&self, speed: f64, course: f64) -> PyResult<f64> {
        self.inner.speed_error_small_angle(speed, course).py()
    }

    /// (t, heading, tilt, latitude) arrays (s, rad) of the full model's run on a track: the
    /// start's speed (m/s) and course (rad), then the turns (time s, duration s or None, speed
    /// m/s, course rad; none: a steady track, the core's `Gyrocompass::simulate`).
    #[pyo3(signature = (duration, heading0, tilt0, speed, course, turns, method, settings, progress))]
    #[allow(clippy::too_many_arguments)]
    fn simulate<'py>(
        &self,
        py: Python<'py>,
        duration: f64,
        heading0: f64,
        tilt0: f64,
        speed: f64,
        course: f64,
        turns: Vec<(f64, Option<f64>, f64, f64)>,
        method: &str,
        settings: RunSettings,
        progress: Option<Bound<'py, PyAny>>,
    ) -> PyResult<CompassArrays> {
        let opts = settings.simulate(method)?;
        let turns = turns
            .into_iter()
            .map(|(time, duration, speed, course)| Turn {
                time,
                duration,
                speed,
                course,
            })
            .collect();
        let track = Track::new(Ship::new(speed, course).py()?, turns).py()?;
        let c = self.inner;
        compass_run(py, progress, || {
            c.simulate_track(duration, heading0, tilt0, &track, &opts)
        })
    }

    /// (heading, tilt, envelope) arrays (rad) of the linear solution at the times t (s), and
    /// the settled (heading, tilt) (rad).
    fn linear_solution(
        &self,
        t: PyReadonlyArray1<'_, f64>,
        heading0: f64,
        tilt0: f64,
        speed: f64,
        course: f64,
    ) -> PyResult<LinearArrays> {
        let ship = Ship::new(speed, course).py()?;
        let out = self
            .inner
            .linear_solution(&vec_in(&t), heading0, tilt0, Some(ship))
            .py()?;
        Ok((
            Values(out.heading),
            Values(out.tilt),
            Values(out.envelope),
            (out.settled_heading, out.settled_tilt),
        ))
    }
}

/// The linear solution's heading, tilt and envelope (rad) and the settled (heading, tilt).
type LinearArrays = (Values, Values, Values, (f64, f64));

/// A carried body's run: the inertial trajectory, and the relative attitude (N, 4), the frame's
/// attitude (N, 4) and the relative ω (N, 3).
type CarriedOut<'py> = (
    PyTrajectory,
    Bound<'py, numpy::PyArray2<f64>>,
    Bound<'py, numpy::PyArray2<f64>>,
    Bound<'py, numpy::PyArray2<f64>>,
);

/// Simulates a body carried by a moving frame (see `poinsot.simulate(..., carried_by=...)`).
#[export]
#[pyo3(signature = (start, duration, kind, frame, pivot, gravity, earth, latitude, mass_moment, torque, method, settings, progress))]
#[allow(clippy::too_many_arguments)]
fn dynamics_simulate_carried<'py>(
    py: Python<'py>,
    start: Start<'py>,
    duration: f64,
    kind: &str,
    frame: PyReadonlyArray1<'py, f64>,
    pivot: PyReadonlyArray1<'py, f64>,
    gravity: PyReadonlyArray1<'py, f64>,
    earth: Option<PyRef<'py, PyEarth>>,
    latitude: f64,
    mass_moment: PyReadonlyArray1<'py, f64>,
    torque: TorqueSpec<'py>,
    method: &str,
    settings: RunSettings,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<CarriedOut<'py>> {
    let (body, w0, q0) = initial_state(&start)?;
    let carrier = match kind {
        "frame" => Carrier::frame(
            frame_arg(&frame)?,
            vector("pivot", &pivot)?,
            vector("gravity", &gravity)?,
        )
        .py()?,
        "earth" => place(earth.as_deref(), latitude)?,
        other => {
            return Err(invalid(
                "carried_by",
                format!("must be 'frame' or 'earth', got {other:?}"),
            ))
        }
    };
    let load = Load {
        mass_moment: vector("body", &mass_moment)?,
        rotor: Vec3::zeros(),
    };
    let mut torque = crate::dynamics::torque(&torque)?;
    let opts = settings.simulate(method)?;
    let out = run(py, progress.as_ref(), || {
        simulate_carried(&body, w0, q0, duration, &carrier, load, &mut torque, &opts)
    })?;
    Ok((
        PyTrajectory::new(py, out.inertial)?,
        rows_into(py, out.relative_attitude)?,
        rows_into(py, out.frame_attitude)?,
        rows_into(py, out.relative_omega)?,
    ))
}

/// The place at `latitude` (rad) on `earth` (None: the core's default Earth) as the core makes
/// it (`Carrier::earth`; the errors name `latitude`).
fn place(earth: Option<&PyEarth>, latitude: f64) -> PyResult<Carrier> {
    let e = earth.map_or_else(Earth::default, |e| e.inner);
    Carrier::earth(e, latitude).py()
}

/// Checks a place on the Earth as the core makes one (`Carrier::earth`; the errors name
/// `latitude`): `poinsot.Place` calls it when made.
#[export]
fn dynamics_check_place(earth: PyRef<'_, PyEarth>, latitude: f64) -> PyResult<()> {
    place(Some(&earth), latitude).map(drop)
}

/// Registers this file's class and function on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyGyrocompass>()?;
    add_functions!(m; dynamics_simulate_carried, dynamics_check_place);
    Ok(())
}
