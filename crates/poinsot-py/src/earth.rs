//! Bindings of `poinsot::earth` (conversion and error mapping only). Every function takes
//! the Earth as (rotation_rate, radius, g) and checks it in the core. The physical constants and
//! the runs' defaults are the core's ([`register`] adds them to the module).
use numpy::{PyArray1, PyArray2, PyReadonlyArray1, PyReadonlyArray2};
use poinsot::earth::{self as ea, fit_precession_rate, Earth, FallModel, Gravity, LowSetup};
use poinsot::integrate::{sample_times, Tolerances};
use poinsot::Vec3;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::control::{map_each, run};
use crate::convert::rows_view;
use crate::errors::{invalid, IntoPy};
use crate::frames::{array_in, options, rows_in, rows_out, solution_dict, vec_in};
use poinsot::limits::check_count;

/// Bytes per sample of a trajectory in the local frame: t and the state (6).
const SAMPLE_BYTES: usize = poinsot::frames::PARTICLE_BYTES_PER_SAMPLE;

/// The core's Earth, checked (also for the sweeps).
pub(crate) fn earth(rotation_rate: f64, radius: f64, g: f64) -> PyResult<Earth> {
    Earth::new(rotation_rate, radius, g).py()
}

fn gravity(name: &str) -> PyResult<Gravity> {
    crate::convert::parse(name)
}

/// A per-latitude scalar quantity over an array of latitudes.
fn per_latitude<'py>(
    py: Python<'py>,
    latitude: &PyReadonlyArray1<'py, f64>,
    f: impl Fn(f64) -> poinsot::Result<f64> + Send,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let out = map_each(py, &vec_in(latitude), move |&l| f(l))?;
    Ok(PyArray1::from_vec(py, out))
}

/// ω in ENU components, (N, 3), at (N,) latitudes (rad).
#[pyfunction]
fn earth_omega_enu<'py>(
    py: Python<'py>,
    rotation_rate: f64,
    radius: f64,
    g: f64,
    latitude: PyReadonlyArray1<'py, f64>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let e = earth(rotation_rate, radius, g)?;
    let rows = map_each(py, &vec_in(&latitude), |&l| {
        e.omega_enu(l).map(|w| [w.x, w.y, w.z])
    })?;
    Ok(rows_out(py, &rows))
}

/// (vector (N, 3), magnitude (N,), deviation (N,), centrifugal (N, 3)) at (N,) latitudes.
#[pyfunction]
#[allow(clippy::type_complexity)]
fn earth_effective_gravity<'py>(
    py: Python<'py>,
    rotation_rate: f64,
    radius: f64,
    g: f64,
    latitude: PyReadonlyArray1<'py, f64>,
) -> PyResult<(
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray2<f64>>,
)> {
    let e = earth(rotation_rate, radius, g)?;
    let each = map_each(py, &vec_in(&latitude), |&l| {
        Ok((e.effective_gravity(l)?, e.centrifugal_acceleration(l)?))
    })?;
    let n = each.len();
    let (mut vecs, mut mags, mut devs, mut cents) = (
        Vec::with_capacity(n),
        Vec::with_capacity(n),
        Vec::with_capacity(n),
        Vec::with_capacity(n),
    );
    for (eg, c) in each {
        vecs.push([eg.vector.x, eg.vector.y, eg.vector.z]);
        mags.push(eg.magnitude);
        devs.push(eg.deviation);
        cents.push([c.x, c.y, c.z]);
    }
    Ok((
        rows_out(py, &vecs),
        PyArray1::from_vec(py, mags),
        PyArray1::from_vec(py, devs),
        rows_out(py, &cents),
    ))
}

/// −2 ω × v (N, 3) for (N,) latitudes and (N, 3) ENU velocities.
#[pyfunction]
fn earth_coriolis_acceleration<'py>(
    py: Python<'py>,
    rotation_rate: f64,
    radius: f64,
    g: f64,
    latitude: PyReadonlyArray1<'py, f64>,
    velocity: PyReadonlyArray2<'py, f64>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let e = earth(rotation_rate, radius, g)?;
    let lats = vec_in(&latitude);
    let vels = rows_in::<3>("velocity_enu", &velocity)?;
    if lats.len() != vels.len() {
        return Err(invalid("velocity_enu", "must have one row per latitude"));
    }
    let pairs: Vec<(f64, [f64; 3])> = lats.into_iter().zip(vels).collect();
    let rows = map_each(py, &pairs, |(l, v)| {
        let a = e
            .coriolis_acceleration(*l, &Vec3::new(v[0], v[1], v[2]))
            .map_err(|mut err| {
                if err.argument == "velocity" {
                    err.argument = "velocity_enu".into();
                }
                err
            })?;
        Ok([a.x, a.y, a.z])
    })?;
    Ok(rows_out(py, &rows))
}

/// A scalar per latitude: "coriolis_parameter", "foucault_rate" or "inertial_period".
#[pyfunction]
fn earth_latitude_scalar<'py>(
    py: Python<'py>,
    rotation_rate: f64,
    radius: f64,
    g: f64,
    quantity: &str,
    latitude: PyReadonlyArray1<'py, f64>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let e = earth(rotation_rate, radius, g)?;
    match quantity {
        "coriolis_parameter" => per_latitude(py, &latitude, |l| e.coriolis_parameter(l)),
        "foucault_rate" => per_latitude(py, &latitude, |l| e.foucault_rate(l)),
        "inertial_period" => per_latitude(py, &latitude, |l| e.inertial_period(l)),
        _ => Err(invalid(
            "quantity",
            format!("unknown quantity {quantity:?}"),
        )),
    }
}

/// The time of fall (s) from `height` (m) without rotation, √(2h/g) (2.41).
#[pyfunction]
fn earth_fall_time(rotation_rate: f64, radius: f64, g: f64, height: f64) -> PyResult<f64> {
    earth(rotation_rate, radius, g)?.fall_time(height).py()
}

/// First-order east (2.42) or second-order south deflection (m) for (N,) heights and latitudes.
#[pyfunction]
fn earth_deflection<'py>(
    py: Python<'py>,
    rotation_rate: f64,
    radius: f64,
    g: f64,
    direction: &str,
    height: PyReadonlyArray1<'py, f64>,
    latitude: PyReadonlyArray1<'py, f64>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let e = earth(rotation_rate, radius, g)?;
    let (hs, ls) = (vec_in(&height), vec_in(&latitude));
    if hs.len() != ls.len() {
        return Err(invalid("height", "must have one value per latitude"));
    }
    let east = direction == "east";
    let pairs: Vec<(f64, f64)> = hs.into_iter().zip(ls).collect();
    let out = map_each(py, &pairs, |&(h, l)| {
        if east {
            e.eastward_deflection(h, l)
        } else {
            e.southward_deflection(h, l)
        }
    })?;
    Ok(PyArray1::from_vec(py, out))
}

/// The fall model of a drop or a projectile from the Python keywords (also for the sweeps).
pub(crate) fn model(
    gravity_name: &str,
    rotation: bool,
    centrifugal: bool,
    rtol: f64,
    atol: f64,
    max_steps: usize,
) -> PyResult<FallModel> {
    Ok(FallModel {
        gravity: gravity(gravity_name)?,
        rotation,
        centrifugal,
        options: options(rtol, atol, max_steps, true),
    })
}

/// The exact drop: {"time", "east", "north", "t", "states", ...}.
#[pyfunction]
#[pyo3(signature = (rotation_rate, radius, g, height, latitude, gravity, rotation, centrifugal, rtol, atol, max_steps, samples))]
#[allow(clippy::too_many_arguments)]
fn earth_drop<'py>(
    py: Python<'py>,
    rotation_rate: f64,
    radius: f64,
    g: f64,
    height: f64,
    latitude: f64,
    gravity: &str,
    rotation: bool,
    centrifugal: bool,
    rtol: f64,
    atol: f64,
    max_steps: usize,
    samples: usize,
) -> PyResult<Bound<'py, PyDict>> {
    let e = earth(rotation_rate, radius, g)?;
    let m = model(gravity, rotation, centrifugal, rtol, atol, max_steps)?;
    check_count("samples", samples, 2, SAMPLE_BYTES).py()?;
    let fall = run(py, None, || e.drop(height, latitude, &m))?;
    let d = solution_dict(
        py,
        &fall.solution,
        &sample_times(0.0, fall.time, samples, SAMPLE_BYTES).py()?,
    )?;
    d.set_item("time", fall.time)?;
    d.set_item("east", fall.east)?;
    d.set_item("north", fall.north)?;
    Ok(d)
}

/// A projectile's flight: {"time", "east", "north", "range", "downrange", "drift", "t", "states", ...}.
#[pyfunction]
#[pyo3(signature = (rotation_rate, radius, g, speed, elevation, azimuth, latitude, height, gravity, rotation, centrifugal, rtol, atol, max_steps, samples))]
#[allow(clippy::too_many_arguments)]
fn earth_projectile<'py>(
    py: Python<'py>,
    rotation_rate: f64,
    radius: f64,
    g: f64,
    speed: f64,
    elevation: f64,
    azimuth: f64,
    latitude: f64,
    height: f64,
    gravity: &str,
    rotation: bool,
    centrifugal: bool,
    rtol: f64,
    atol: f64,
    max_steps: usize,
    samples: usize,
) -> PyResult<Bound<'py, PyDict>> {
    let e = earth(rotation_rate, radius, g)?;
    let m = model(gravity, rotation, centrifugal, rtol, atol, max_steps)?;
    check_count("samples", samples, 2, SAMPLE_BYTES).py()?;
    let fl = run(py, None, || {
        e.projectile(speed, elevation, azimuth, latitude, height, &m)
    })?;
    let d = solution_dict(
        py,
        &fl.solution,
        &sample_times(0.0, fl.time, samples, SAMPLE_BYTES).py()?,
    )?;
    for (k, v) in [
        ("time", fl.time),
        ("east", fl.east),
        ("north", fl.north),
        ("range", fl.range),
        ("downrange", fl.downrange),
        ("drift", fl.drift),
    ] {
        d.set_item(k, v)?;
    }
    Ok(d)
}

/// Jacobi's integral (N,) of (N, 3) ENU positions (m) and velocities (m/s) at `latitude` (rad).
#[pyfunction]
fn earth_jacobi_integral<'py>(
    py: Python<'py>,
    rotation_rate: f64,
    radius: f64,
    g: f64,
    latitude: f64,
    position: PyReadonlyArray2<'py, f64>,
    velocity: PyReadonlyArray2<'py, f64>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let e = earth(rotation_rate, radius, g)?;
    let r = rows_view::<3>("position", &position)?;
    let v = rows_view::<3>("velocity", &velocity)?;
    if r.len() != v.len() {
        return Err(invalid("velocity", "must have one row per position"));
    }
    let out = run(py, None, || {
        poinsot::control::try_map_n(r.len(), |i| {
            let (p, w) = (r[i], v[i]);
            e.jacobi_integral(latitude, &[p[0], p[1], p[2], w[0], w[1], w[2]])
        })
    })?;
    Ok(PyArray1::from_vec(py, out))
}

/// Least-squares rate (rad/s) of the swing-plane angle through the turning points.
#[pyfunction]
fn earth_fit_precession_rate(
    turn_times: PyReadonlyArray1<'_, f64>,
    turn_angles: PyReadonlyArray1<'_, f64>,
) -> PyResult<f64> {
    fit_precession_rate(&vec_in(&turn_times), &vec_in(&turn_angles)).py()
}

/// The tolerances of a run from the Python keywords.
fn tolerances(rtol: f64, atol: f64, max_steps: usize) -> Tolerances {
    Tolerances {
        rtol,
        atol,
        max_steps,
    }
}

/// A Foucault run as the core makes it (`Earth::foucault_swing`, in stretches reporting to
/// `progress(fraction)` when given: `Earth::foucault_swing_in`): {"t", "states", "turn_times",
/// "turn_angles", "state0", "evaluations", and the measurement's "regime", "note",
/// "precession_rate", "sense", "theory_rate", "expected_rate", "theory_fit_rate",
/// "turning_points"; and whether the unit's −ω sin λ describes it (`FoucaultSwing::unit_rate`):
/// "unit_rate_holds", "unit_rate_note", "spin_ratio", "amplitude_ratio", "spin_departure",
/// "amplitude_departure"}.
#[pyfunction]
#[pyo3(signature = (rotation_rate, radius, g, latitude, length, amplitude, azimuth, duration, samples, rtol, atol, max_steps, progress=None))]
#[allow(clippy::too_many_arguments)]
fn earth_foucault_swing<'py>(
    py: Python<'py>,
    rotation_rate: f64,
    radius: f64,
    g: f64,
    latitude: f64,
    length: f64,
    amplitude: f64,
    azimuth: f64,
    duration: f64,
    samples: usize,
    rtol: f64,
    atol: f64,
    max_steps: usize,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let e = earth(rotation_rate, radius, g)?;
    let tol = tolerances(rtol, atol, max_steps);
    // With a `progress(fraction)` callable: the core's run in stretches, reporting after each.
    let stretches = match progress {
        Some(_) => ea::foucault_stretches(duration),
        None => 1,
    };
    let swing = run(py, progress.as_ref(), || {
        e.foucault_swing_in(
            latitude, length, amplitude, azimuth, duration, samples, &tol, stretches,
        )
    })?;
    let check = swing.unit_rate().py()?;
    let (r, m) = (swing.run, swing.measurement);
    let d = PyDict::new(py);
    d.set_item("t", PyArray1::from_vec(py, r.t))?;
    d.set_item("states", rows_out(py, &r.states))?;
    d.set_item("turn_times", PyArray1::from_vec(py, r.turn_times))?;
    d.set_item("turn_angles", PyArray1::from_vec(py, r.turn_angles))?;
    d.set_item("state0", PyArray1::from_vec(py, swing.state0.to_vec()))?;
    d.set_item("evaluations", r.stats.evaluations)?;
    d.set_item("regime", m.regime.name())?;
    d.set_item("note", &m.note)?;
    d.set_item("precession_rate", m.precession_rate)?;
    d.set_item("sense", m.sense_name())?;
    d.set_item("theory_rate", m.theory_rate)?;
    d.set_item("expected_rate", m.expected_rate)?;
    d.set_item("theory_fit_rate", m.theory_fit_rate)?;
    d.set_item("turning_points", m.turning_points)?;
    d.set_item("unit_rate_holds", check.holds)?;
    d.set_item("unit_rate_note", &check.note)?;
    d.set_item("spin_ratio", check.spin_ratio)?;
    d.set_item("amplitude_ratio", check.amplitude_ratio)?;
    d.set_item("spin_departure", check.spin_departure)?;
    d.set_item("amplitude_departure", check.amplitude_departure)?;
    Ok(d)
}

/// An inertial oscillation as the core makes it (`Earth::inertial_swing`; `duration` None: the
/// core's default): {"t", "states" (N, 4), "turning_rate", "period", "sense"}.
#[pyfunction]
#[pyo3(signature = (rotation_rate, radius, g, latitude, velocity, duration, samples, rtol, atol, max_steps))]
#[allow(clippy::too_many_arguments)]
fn earth_inertial_swing<'py>(
    py: Python<'py>,
    rotation_rate: f64,
    radius: f64,
    g: f64,
    latitude: f64,
    velocity: PyReadonlyArray1<'py, f64>,
    duration: Option<f64>,
    samples: usize,
    rtol: f64,
    atol: f64,
    max_steps: usize,
) -> PyResult<Bound<'py, PyDict>> {
    let e = earth(rotation_rate, radius, g)?;
    let v = array_in::<2>("velocity", &velocity)?;
    let tol = tolerances(rtol, atol, max_steps);
    let swing = run(py, None, || {
        e.inertial_swing(latitude, v, duration, samples, &tol)
    })?;
    let d = PyDict::new(py);
    d.set_item("t", PyArray1::from_vec(py, swing.run.t))?;
    d.set_item("states", rows_out(py, &swing.run.states))?;
    d.set_item("turning_rate", swing.run.turning_rate)?;
    d.set_item("period", swing.period)?;
    d.set_item("sense", swing.sense.name())?;
    Ok(d)
}

/// Parcels on a ring flowing into a low as the core sets them up (`Earth::low_flow`):
/// {"t", "parcels" (P arrays (N, 4)), "circulation", "sense", "energy", "dissipated"}.
/// `ring_radius` is the ring's radius (the Python argument `radius`).
#[pyfunction]
#[pyo3(signature = (rotation_rate, radius, g, latitude, ring_radius, parcels, pull, friction, duration, samples, rtol, atol, max_steps))]
#[allow(clippy::too_many_arguments)]
fn earth_low_flow<'py>(
    py: Python<'py>,
    rotation_rate: f64,
    radius: f64,
    g: f64,
    latitude: f64,
    ring_radius: f64,
    parcels: usize,
    pull: f64,
    friction: f64,
    duration: f64,
    samples: usize,
    rtol: f64,
    atol: f64,
    max_steps: usize,
) -> PyResult<Bound<'py, PyDict>> {
    let e = earth(rotation_rate, radius, g)?;
    let setup = LowSetup {
        radius: ring_radius,
        parcels,
        pull,
        friction,
    };
    let tol = tolerances(rtol, atol, max_steps);
    let flow = run(py, None, || {
        e.low_flow(latitude, &setup, duration, samples, &tol)
    })?;
    let d = PyDict::new(py);
    d.set_item("t", PyArray1::from_vec(py, flow.run.t))?;
    let parcels: Vec<Bound<'py, PyArray2<f64>>> =
        flow.run.parcels.iter().map(|p| rows_out(py, p)).collect();
    d.set_item("parcels", parcels)?;
    d.set_item("circulation", flow.run.circulation)?;
    d.set_item("sense", flow.sense.name())?;
    let rows = |v: Vec<Vec<f64>>| -> Vec<Bound<'py, PyArray1<f64>>> {
        v.into_iter().map(|r| PyArray1::from_vec(py, r)).collect()
    };
    d.set_item("energy", rows(flow.run.energy))?;
    d.set_item("dissipated", rows(flow.run.dissipated))?;
    Ok(d)
}

/// `samples` evenly spaced times from `t0` to `t_end`, the core's grid (`sample_times`: the
/// count checked, ≥ 2 and within the memory budget, naming `samples`).
#[pyfunction]
#[pyo3(name = "sample_times")]
fn py_sample_times<'py>(
    py: Python<'py>,
    t0: f64,
    t_end: f64,
    samples: usize,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    Ok(PyArray1::from_vec(
        py,
        sample_times(t0, t_end, samples, ea::FOUCAULT_BYTES_PER_SAMPLE).py()?,
    ))
}

/// A tolerances dict {"rtol", "atol", "max_steps"}.
fn tolerances_dict<'py>(py: Python<'py>, t: &Tolerances) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("rtol", t.rtol)?;
    d.set_item("atol", t.atol)?;
    d.set_item("max_steps", t.max_steps)?;
    Ok(d)
}

/// The defaults of the Earth's runs, the core's: {"drop", "foucault", "inertial", "low"}, each a
/// dict of the Python keywords' defaults (tolerances, samples, and the run's own arguments).
#[pyfunction]
fn earth_defaults(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    let drop = tolerances_dict(py, &ea::DROP_TOLERANCES)?;
    drop.set_item("samples", ea::DROP_SAMPLES)?;
    let foucault = tolerances_dict(py, &ea::FOUCAULT_TOLERANCES)?;
    foucault.set_item("length", ea::FOUCAULT_LENGTH)?;
    foucault.set_item("amplitude", ea::FOUCAULT_AMPLITUDE)?;
    foucault.set_item("azimuth", ea::FOUCAULT_AZIMUTH)?;
    foucault.set_item("duration", ea::FOUCAULT_DURATION)?;
    foucault.set_item("samples", ea::FOUCAULT_SAMPLES)?;
    let inertial = tolerances_dict(py, &ea::INERTIAL_TOLERANCES)?;
    inertial.set_item("velocity", ea::INERTIAL_VELOCITY.to_vec())?;
    inertial.set_item("samples", ea::INERTIAL_SAMPLES)?;
    let low = tolerances_dict(py, &ea::LOW_TOLERANCES)?;
    let setup = LowSetup::default();
    low.set_item("radius", setup.radius)?;
    low.set_item("parcels", setup.parcels)?;
    low.set_item("pull", setup.pull)?;
    low.set_item("friction", setup.friction)?;
    low.set_item("duration", ea::LOW_DURATION)?;
    low.set_item("samples", ea::LOW_SAMPLES)?;
    let d = PyDict::new(py);
    d.set_item("drop", drop)?;
    d.set_item("foucault", foucault)?;
    d.set_item("inertial", inertial)?;
    d.set_item("low", low)?;
    Ok(d)
}

/// Registers this file's functions on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(earth_omega_enu, m)?)?;
    m.add_function(wrap_pyfunction!(earth_effective_gravity, m)?)?;
    m.add_function(wrap_pyfunction!(earth_coriolis_acceleration, m)?)?;
    m.add_function(wrap_pyfunction!(earth_latitude_scalar, m)?)?;
    m.add_function(wrap_pyfunction!(earth_deflection, m)?)?;
    m.add_function(wrap_pyfunction!(earth_fall_time, m)?)?;
    m.add_function(wrap_pyfunction!(earth_drop, m)?)?;
    m.add_function(wrap_pyfunction!(earth_projectile, m)?)?;
    m.add_function(wrap_pyfunction!(earth_fit_precession_rate, m)?)?;
    m.add_function(wrap_pyfunction!(earth_jacobi_integral, m)?)?;
    m.add_function(wrap_pyfunction!(earth_foucault_swing, m)?)?;
    m.add_function(wrap_pyfunction!(earth_inertial_swing, m)?)?;
    m.add_function(wrap_pyfunction!(earth_low_flow, m)?)?;
    m.add_function(wrap_pyfunction!(py_sample_times, m)?)?;
    m.add_function(wrap_pyfunction!(earth_defaults, m)?)?;
    // The physical constants (the defaults of `poinsot.Earth`).
    m.add("SIDEREAL_RATE", ea::SIDEREAL_RATE)?;
    m.add("SOLAR_DAY_RATE", ea::SOLAR_DAY_RATE)?;
    m.add("MEAN_RADIUS", ea::MEAN_RADIUS)?;
    m.add("STANDARD_GRAVITY", ea::STANDARD_GRAVITY)?;
    Ok(())
}
