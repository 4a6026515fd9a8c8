//! Bindings of `poinsot::earth` (conversion only): the core's types as Python classes, as in
//! the WebAssembly binding. `EarthCore` holds a checked `poinsot::earth::Earth` (the public
//! `poinsot.Earth`, python/poinsot/earth.py, holds one), `FallModel` the core's fall model; the
//! runs return `FallCore`, `FlightCore`, `FoucaultRunCore`, `InertialRunCore` and `LowFlowCore`,
//! whose attributes are the core's results (numpy arrays for the samples). The core checks every
//! argument and names it as the caller knows it, so no error is renamed here. The physical
//! constants are the core's ([`register`] adds them to the module; the runs' defaults are in
//! `_core.DEFAULTS`, defaults.rs).
use numpy::ndarray::{Array2, Array3};
use numpy::{IntoPyArray, PyArray1, PyArray2, PyArray3, PyReadonlyArray1, PyReadonlyArray2};
use poinsot::earth::{self as ea, Earth, FallModel, Gravity, LowSetup};
use poinsot::frames::ParticleState;
use poinsot::integrate::sample_times;
use poinsot::limits::check_count;
use poinsot::Vec3;
use poinsot_py_macros::export;
use pyo3::prelude::*;
use pyo3::types::PyType;

use crate::control::{map_each, run};
use crate::convert::{
    array_in, options, parse, rows_in, rows_view, vec_in, Rows, RunSettings, Values,
};
use crate::errors::{invalid, IntoPy};

/// Bytes per sample of a trajectory in the local frame: t and the state (6).
const SAMPLE_BYTES: usize = poinsot::frames::PARTICLE_BYTES_PER_SAMPLE;

/// The rotating Earth (private; use `poinsot.Earth`): the core's `Earth`, checked when made.
#[pyclass(module = "poinsot._core", name = "EarthCore", frozen)]
pub struct PyEarth {
    pub(crate) inner: Earth,
}

/// The model of a near-surface motion (the core's `FallModel`): gravity "uniform" or
/// "inverse-square", the rotation's terms, and the integrator's tolerances.
#[pyclass(module = "poinsot._core", name = "FallModel", frozen)]
pub struct PyFallModel {
    pub(crate) inner: FallModel,
}

/// `#[getter]`s of a result class for fields of the core value it holds:
/// `getters!(Class.held: Type { field, … } …)`.
macro_rules! getters {
    ($class:ident.$held:ident: $($ty:ty { $($field:ident),+ $(,)? })+) => {
        #[export]
        impl $class {
            $($(#[getter]
            fn $field(&self) -> $ty {
                self.$held.$field
            })+)+
        }
    };
}

/// A run of the core that ends at a landing (`Fall`, `Flight`: `time` (s) and `solution`), held
/// with its samples: `landing_run!(doc Class("PythonName", CoreType) { getter, … })` is the
/// class, the `#[getter]`s of the core run's listed fields and `Class::sampled`.
macro_rules! landing_run {
    ($(#[$doc:meta])* $class:ident($name:literal, $run:ty) { $($field:ident),+ }) => {
        $(#[$doc])*
        #[pyclass(module = "poinsot._core", name = $name, frozen)]
        pub struct $class {
            run: $run,
            #[pyo3(get)]
            t: Py<PyArray1<f64>>,
            #[pyo3(get)]
            position: Py<PyArray2<f64>>,
            #[pyo3(get)]
            velocity: Py<PyArray2<f64>>,
        }

        getters!($class.run: f64 { $($field),+ });

        impl $class {
            /// The run `make` makes (without the GIL), sampled at `samples` even times from
            /// release to landing.
            fn sampled(
                py: Python<'_>,
                samples: usize,
                make: impl FnOnce() -> poinsot::Result<$run> + Send,
            ) -> PyResult<Self> {
                let (made, t, states) = run(py, None, || {
                    let made = make()?;
                    let t = grid(made.time, samples)?;
                    let states = made.solution.sample(&t)?;
                    Ok((made, t, states))
                })?;
                let (position, velocity) = split(py, &states)?;
                let t = values(py, t);
                Ok(Self { run: made, t, position, velocity })
            }
        }
    };
}

landing_run!(
    /// A body dropped from rest (the core's `Fall`, held), sampled: landing time (s), point (m,
    /// ENU), the closed forms 2.42 and second order (m), and the samples t (N,), position and
    /// velocity (N, 3).
    PyFall("FallCore", ea::Fall) { time, east, north, first_order_east, second_order_south }
);

landing_run!(
    /// A projectile's flight (the core's `Flight`, held), sampled as [`PyFall`].
    PyFlight("FlightCore", ea::Flight) { time, east, north, range, downrange, drift }
);

/// A Foucault run (the core's `FoucaultSwing`): samples, turning points, the measurement of the
/// swing plane and whether the unit's −ω sin λ describes it (`FoucaultSwing::unit_rate`).
#[pyclass(module = "poinsot._core", name = "FoucaultRunCore", frozen, get_all)]
pub struct PyFoucaultRun {
    t: Py<PyArray1<f64>>,
    position: Py<PyArray2<f64>>,
    velocity: Py<PyArray2<f64>>,
    turn_times: Py<PyArray1<f64>>,
    turn_angles: Py<PyArray1<f64>>,
    precession_rate: Option<f64>,
    full_turn_period: Option<f64>,
    expected_rate: f64,
    expected_full_turn_period: f64,
    sense: &'static str,
    regime: &'static str,
    regime_note: String,
    theory_rate: Option<f64>,
    unit_rate_holds: bool,
    unit_rate_note: String,
    spin_ratio: f64,
    amplitude_ratio: f64,
    spin_departure: Option<f64>,
    amplitude_departure: Option<f64>,
}

/// An inertial oscillation (the core's `InertialSwing`): t (N,), position and velocity (N, 2),
/// the measured turning rate (rad/s), the period (s) and the sense.
#[pyclass(module = "poinsot._core", name = "InertialRunCore", frozen, get_all)]
pub struct PyInertialRun {
    t: Py<PyArray1<f64>>,
    position: Py<PyArray2<f64>>,
    velocity: Py<PyArray2<f64>>,
    turning_rate: f64,
    measured_period: f64,
    period: f64,
    sense: &'static str,
}

/// The flow into a low (the core's `LowFlow`): t (N,), position and velocity (P, N, 2), the
/// circulation (m²/s) and its sense, energy and dissipated work (P, N) (J/kg).
#[pyclass(module = "poinsot._core", name = "LowFlowCore", frozen, get_all)]
pub struct PyLowFlow {
    t: Py<PyArray1<f64>>,
    position: Py<PyArray3<f64>>,
    velocity: Py<PyArray3<f64>>,
    circulation: f64,
    sense: &'static str,
    energy: Py<PyArray2<f64>>,
    dissipated: Py<PyArray2<f64>>,
}

/// A new (N,) array, held by a result.
fn values(py: Python<'_>, v: Vec<f64>) -> Py<PyArray1<f64>> {
    PyArray1::from_vec(py, v).unbind()
}

/// The `K` columns from `from` of each state as a new (N, K) array, held by a result.
fn columns<const S: usize, const K: usize>(
    py: Python<'_>,
    states: &[[f64; S]],
    from: usize,
) -> PyResult<Py<PyArray2<f64>>> {
    let rows: Vec<[f64; K]> = states
        .iter()
        .map(|s| std::array::from_fn(|k| s[from + k]))
        .collect();
    Ok(Rows(rows).into_pyobject(py)?.unbind())
}

/// Sampled states `[x, y, z, vx, vy, vz]` as (position, velocity), each (N, 3).
type Split = (Py<PyArray2<f64>>, Py<PyArray2<f64>>);

fn split(py: Python<'_>, states: &[ParticleState]) -> PyResult<Split> {
    Ok((
        columns::<6, 3>(py, states, 0)?,
        columns::<6, 3>(py, states, 3)?,
    ))
}

/// Rows of equal length (P rows of N) as a new (P, N) array.
fn table(py: Python<'_>, rows: Vec<Vec<f64>>) -> Py<PyArray2<f64>> {
    let n = rows.first().map_or(0, Vec::len);
    Array2::from_shape_fn((rows.len(), n), |(p, i)| rows[p][i])
        .into_pyarray(py)
        .unbind()
}

/// The `k`-th and `k + 1`-th components of every parcel's states, (P, N, 2).
fn tracks(py: Python<'_>, parcels: &[Vec<[f64; 4]>], k: usize) -> Py<PyArray3<f64>> {
    let n = parcels.first().map_or(0, Vec::len);
    Array3::from_shape_fn((parcels.len(), n, 2), |(p, i, c)| parcels[p][i][k + c])
        .into_pyarray(py)
        .unbind()
}

/// The Python name of a gravity model (its `FromStr` in the core reads it back).
fn gravity_name(gravity: Gravity) -> &'static str {
    match gravity {
        Gravity::Uniform => "uniform",
        Gravity::InverseSquare => "inverse-square",
    }
}

/// `samples` even times over a trajectory of `duration` (s), checked (naming `samples`).
fn grid(duration: f64, samples: usize) -> poinsot::Result<Vec<f64>> {
    check_count("samples", samples, 2, SAMPLE_BYTES)?;
    sample_times(0.0, duration, samples, SAMPLE_BYTES)
}

/// A per-latitude quantity over an array of latitudes (rad).
fn per_latitude<R: Send>(
    py: Python<'_>,
    latitude: &PyReadonlyArray1<'_, f64>,
    f: impl Fn(f64) -> poinsot::Result<R> + Send,
) -> PyResult<Vec<R>> {
    map_each(py, &vec_in(latitude), move |&l| f(l))
}

/// Pairs of (N,) heights (m) and latitudes (rad).
fn per_height<'py>(
    py: Python<'py>,
    height: &PyReadonlyArray1<'py, f64>,
    latitude: &PyReadonlyArray1<'py, f64>,
    f: impl Fn(f64, f64) -> poinsot::Result<f64> + Send,
) -> PyResult<Values> {
    let (hs, ls) = (vec_in(height), vec_in(latitude));
    if hs.len() != ls.len() {
        return Err(invalid("height", "must have one value per latitude"));
    }
    let pairs: Vec<(f64, f64)> = hs.into_iter().zip(ls).collect();
    Ok(Values(map_each(py, &pairs, move |&(h, l)| f(h, l))?))
}

core_export! {
    impl PyFallModel;
    getters {}
    fields {
        rotation -> bool;
        centrifugal -> bool;
        rtol in options -> f64;
        atol in options -> f64;
        max_steps in options -> usize;
    }

    #[new]
    fn new(
        gravity: &str,
        rotation: bool,
        centrifugal: bool,
        rtol: f64,
        atol: f64,
        max_steps: usize,
    ) -> PyResult<Self> {
        Ok(Self {
            inner: FallModel {
                gravity: parse(gravity)?,
                rotation,
                centrifugal,
                options: options(rtol, atol, max_steps, true),
            },
        })
    }

    /// The model made again from its arguments (pickling, for the workers of a sweep).
    #[allow(clippy::type_complexity)]
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> (
        Bound<'py, PyType>,
        (&'static str, bool, bool, f64, f64, usize),
    ) {
        let m = slf.get().inner;
        let o = m.options;
        let args = (
            gravity_name(m.gravity),
            m.rotation,
            m.centrifugal,
            o.rtol,
            o.atol,
            o.max_steps,
        );
        (slf.get_type(), args)
    }

    #[getter]
    fn gravity(&self) -> &'static str {
        gravity_name(self.inner.gravity)
    }
}

/// `core_export! { impl PyEarth; new { … } … }`: the Earth made from its fields (`new { … }`, as
/// in `core_export!`), the methods written out after the lists, and one method per quantity of
/// the core's `Earth` named after it, at (N,) latitudes (`per_latitude { … }`, through
/// [`per_latitude`]) or at (N,) heights and latitudes (`per_height { … }`, through
/// [`per_height`]). pyo3 takes one `#[pymethods]` block per class, so the generated methods go
/// into that block.
macro_rules! earth_export {
    (
        new { $($new:tt)* }
        per_latitude { $($(#[$ldoc:meta])* $lat:ident;)* }
        per_height { $($(#[$hdoc:meta])* $height:ident;)* }
        $($methods:tt)*
    ) => {
        core_export! {
            impl PyEarth;
            new { $($new)* }
            $($(#[$ldoc])*
            fn $lat(&self, py: Python<'_>, latitude: PyReadonlyArray1<'_, f64>) -> PyResult<Values> {
                per_latitude(py, &latitude, |l| self.inner.$lat(l)).map(Values)
            })*
            $($(#[$hdoc])*
            fn $height<'py>(
                &self,
                py: Python<'py>,
                height: PyReadonlyArray1<'py, f64>,
                latitude: PyReadonlyArray1<'py, f64>,
            ) -> PyResult<Values> {
                per_height(py, &height, &latitude, move |h, l| self.inner.$height(h, l))
            })*
            $($methods)*
        }
    };
}

earth_export! {
    new {
        /// The Earth of rate (rad/s, ≥ 0), radius (m, > 0) and gravity (m/s², > 0); errors name
        /// them.
        (rotation_rate: f64, radius: f64, g: f64) = Earth::new;
    }
    per_latitude {
        /// f = 2 ω sin λ (1/s) at (N,) latitudes.
        coriolis_parameter;
        /// −ω sin λ (rad/s) at (N,) latitudes.
        foucault_rate;
        /// π/(ω |sin λ|) (s; inf where ω sin λ = 0) at (N,) latitudes.
        inertial_period;
        /// ω² R cos λ (m/s²) at (N,) latitudes, in closed form.
        centrifugal_magnitude;
        /// The plumb line's deviation (rad) at (N,) latitudes, in closed form.
        plumb_line_deviation_closed;
    }
    per_height {
        /// The first-order eastward deflection 2.42 (m) for (N,) heights and latitudes.
        eastward_deflection;
        /// The second-order southward deflection (m) for (N,) heights and latitudes.
        southward_deflection;
    }


    /// ω in ENU components, (N, 3), at (N,) latitudes.
    fn omega_enu(&self, py: Python<'_>, latitude: PyReadonlyArray1<'_, f64>) -> PyResult<Rows<3>> {
        Ok(Rows(per_latitude(py, &latitude, |l| {
            self.inner.omega_enu(l).map(|w| [w.x, w.y, w.z])
        })?))
    }

    /// (vector (N, 3), magnitude (N,), deviation (N,), centrifugal (N, 3)) at (N,) latitudes.
    fn effective_gravity(
        &self,
        py: Python<'_>,
        latitude: PyReadonlyArray1<'_, f64>,
    ) -> PyResult<(Rows<3>, Values, Values, Rows<3>)> {
        // Split into columns with the GIL still released (the split held it ~0.2 s for 3·10⁶).
        let lats = vec_in(&latitude);
        let earth = &self.inner;
        run(py, None, || {
            let each = poinsot::control::try_map(&lats, |&l| {
                Ok((earth.effective_gravity(l)?, earth.centrifugal_acceleration(l)?))
            })?;
            Ok((
                each.iter().map(|(g, _)| g.vector).collect(),
                each.iter().map(|(g, _)| g.magnitude).collect(),
                each.iter().map(|(g, _)| g.deviation).collect(),
                each.iter().map(|(_, c)| *c).collect(),
            ))
        })
    }

    /// −2 ω × v (N, 3) for (N,) latitudes and (N, 3) ENU velocities.
    fn coriolis_acceleration(
        &self,
        py: Python<'_>,
        latitude: PyReadonlyArray1<'_, f64>,
        velocity_enu: PyReadonlyArray2<'_, f64>,
    ) -> PyResult<Rows<3>> {
        let lats = vec_in(&latitude);
        let vels = rows_in::<3>("velocity_enu", &velocity_enu)?;
        if lats.len() != vels.len() {
            return Err(invalid("velocity_enu", "must have one row per latitude"));
        }
        let pairs: Vec<(f64, [f64; 3])> = lats.into_iter().zip(vels).collect();
        let rows = map_each(py, &pairs, |(l, v)| {
            self.inner
                .coriolis_acceleration(*l, &Vec3::new(v[0], v[1], v[2]))
        })?;
        Ok(rows.into_iter().collect())
    }

    /// The time of fall (s) from `height` (m) without rotation, √(2h/g) (2.41).
    fn fall_time(&self, height: f64) -> PyResult<f64> {
        self.inner.fall_time(height).py()
    }

    /// Jacobi's integral (N,) of (N, 3) ENU positions (m) and velocities (m/s) at `latitude`.
    fn jacobi_integral(
        &self,
        py: Python<'_>,
        latitude: f64,
        position: PyReadonlyArray2<'_, f64>,
        velocity: PyReadonlyArray2<'_, f64>,
    ) -> PyResult<Values> {
        let r = rows_view::<3>("position", &position)?;
        let v = rows_view::<3>("velocity", &velocity)?;
        if r.len() != v.len() {
            return Err(invalid("velocity", "must have one row per position"));
        }
        Ok(Values(run(py, None, || {
            poinsot::control::try_map_n(r.len(), |i| {
                let (p, w) = (r[i], v[i]);
                self.inner
                    .jacobi_integral(latitude, &[p[0], p[1], p[2], w[0], w[1], w[2]])
            })
        })?))
    }

    /// The exact drop (`Earth::drop`), sampled at `samples` even times from release to landing.
    fn drop(
        &self,
        py: Python<'_>,
        height: f64,
        latitude: f64,
        model: PyRef<'_, PyFallModel>,
        samples: usize,
    ) -> PyResult<PyFall> {
        let m = model.inner;
        PyFall::sampled(py, samples, || self.inner.drop(height, latitude, &m))
    }

    /// A projectile's flight (`Earth::projectile`), sampled as [`PyEarth::drop`].
    #[allow(clippy::too_many_arguments)]
    fn projectile(
        &self,
        py: Python<'_>,
        speed: f64,
        elevation: f64,
        azimuth: f64,
        latitude: f64,
        height: f64,
        model: PyRef<'_, PyFallModel>,
        samples: usize,
    ) -> PyResult<PyFlight> {
        let m = model.inner;
        PyFlight::sampled(py, samples, || {
            self.inner
                .projectile(speed, elevation, azimuth, latitude, height, &m)
        })
    }

    /// A Foucault run as the core makes it (`Earth::foucault_swing`; in stretches reporting to
    /// `progress(fraction)` when given: `Earth::foucault_swing_in`), measured.
    #[pyo3(signature = (latitude, length, amplitude, azimuth, duration, settings, progress=None))]
    #[allow(clippy::too_many_arguments)]
    fn foucault_swing(
        &self,
        py: Python<'_>,
        latitude: f64,
        length: f64,
        amplitude: f64,
        azimuth: f64,
        duration: f64,
        settings: RunSettings,
        progress: Option<Bound<'_, PyAny>>,
    ) -> PyResult<PyFoucaultRun> {
        let (samples, tol) = (settings.0, settings.tolerances());
        // With a `progress(fraction)` callable: the core's run in stretches, reporting after each.
        let stretches = match progress {
            Some(_) => ea::foucault_stretches(duration),
            None => 1,
        };
        let (swing, check) = run(py, progress.as_ref(), || {
            let swing = self.inner.foucault_swing_in(
                latitude, length, amplitude, azimuth, duration, samples, &tol, stretches,
            )?;
            let check = swing.unit_rate()?;
            Ok((swing, check))
        })?;
        let (r, m) = (swing.run, swing.measurement);
        let (position, velocity) = split(py, &r.states)?;
        Ok(PyFoucaultRun {
            t: values(py, r.t),
            position,
            velocity,
            turn_times: values(py, r.turn_times),
            turn_angles: values(py, r.turn_angles),
            precession_rate: m.precession_rate,
            full_turn_period: m.full_turn_period,
            expected_rate: m.expected_rate,
            expected_full_turn_period: m.expected_full_turn_period,
            sense: m.sense_name(),
            regime: m.regime.name(),
            regime_note: m.note,
            theory_rate: m.theory_rate,
            unit_rate_holds: check.holds,
            unit_rate_note: check.note,
            spin_ratio: check.spin_ratio,
            amplitude_ratio: check.amplitude_ratio,
            spin_departure: check.spin_departure,
            amplitude_departure: check.amplitude_departure,
        })
    }

    /// An inertial oscillation as the core makes it (`Earth::inertial_swing`; `duration` None:
    /// the core's default).
    #[pyo3(signature = (latitude, velocity, duration, settings))]
    fn inertial_swing(
        &self,
        py: Python<'_>,
        latitude: f64,
        velocity: PyReadonlyArray1<'_, f64>,
        duration: Option<f64>,
        settings: RunSettings,
    ) -> PyResult<PyInertialRun> {
        let v = array_in::<2>("velocity", &velocity)?;
        let (samples, tol) = (settings.0, settings.tolerances());
        let swing = run(py, None, || {
            self.inner
                .inertial_swing(latitude, v, duration, samples, &tol)
        })?;
        Ok(PyInertialRun {
            position: columns::<4, 2>(py, &swing.run.states, 0)?,
            velocity: columns::<4, 2>(py, &swing.run.states, 2)?,
            t: values(py, swing.run.t),
            turning_rate: swing.run.turning_rate,
            measured_period: swing.run.measured_period,
            period: swing.period,
            sense: swing.sense.name(),
        })
    }

    /// Parcels on a ring of `radius` (m) flowing into a low as the core sets them up
    /// (`Earth::low_flow`).
    #[allow(clippy::too_many_arguments)]
    fn low_flow(
        &self,
        py: Python<'_>,
        latitude: f64,
        radius: f64,
        parcels: usize,
        pull: f64,
        friction: f64,
        duration: f64,
        settings: RunSettings,
    ) -> PyResult<PyLowFlow> {
        let setup = LowSetup {
            radius,
            parcels,
            pull,
            friction,
        };
        let (samples, tol) = (settings.0, settings.tolerances());
        let flow = run(py, None, || {
            self.inner
                .low_flow(latitude, &setup, duration, samples, &tol)
        })?;
        let r = flow.run;
        Ok(PyLowFlow {
            position: tracks(py, &r.parcels, 0),
            velocity: tracks(py, &r.parcels, 2),
            t: values(py, r.t),
            circulation: r.circulation,
            sense: flow.sense.name(),
            energy: table(py, r.energy),
            dissipated: table(py, r.dissipated),
        })
    }
}

/// `samples` evenly spaced times from `t0` to `t_end`, the core's grid (`sample_times`: the
/// count checked, ≥ 2 and within the memory budget, naming `samples`).
#[export]
#[pyo3(name = "sample_times")]
fn py_sample_times(t0: f64, t_end: f64, samples: usize) -> PyResult<Values> {
    Ok(Values(
        sample_times(t0, t_end, samples, ea::FOUCAULT_BYTES_PER_SAMPLE).py()?,
    ))
}

/// Registers this file's classes and functions on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyEarth>()?;
    m.add_class::<PyFallModel>()?;
    m.add_class::<PyFall>()?;
    m.add_class::<PyFlight>()?;
    m.add_class::<PyFoucaultRun>()?;
    m.add_class::<PyInertialRun>()?;
    m.add_class::<PyLowFlow>()?;
    add_functions!(m; py_sample_times);
    // The physical constants (the defaults of `poinsot.Earth`).
    m.add("SIDEREAL_RATE", ea::SIDEREAL_RATE)?;
    m.add("SOLAR_DAY_RATE", ea::SOLAR_DAY_RATE)?;
    m.add("MEAN_RADIUS", ea::MEAN_RADIUS)?;
    m.add("STANDARD_GRAVITY", ea::STANDARD_GRAVITY)?;
    Ok(())
}
