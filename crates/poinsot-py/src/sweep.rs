//! Bindings of `poinsot::sweep` (conversion and error mapping only).
//!
//! A sweep travels as its dimensions, a list of `(name, length, offset)`, and its keywords, a
//! list of `(keyword, values, dimension index or None)` with `values` a C-contiguous float64
//! array holding the keyword's entries row-major (3 numbers an entry for a vector). Each
//! function checks every point (`check_only=True`: only that) or computes them, returning a
//! dict of flat arrays, one entry a point in row-major order (`(N, 3)` / `(N, 4)` for vectors);
//! categories (motion class, regime, stability) as `uint8` codes into `sweep_categories()`.
use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray1};
use poinsot::dynamics::{Method, SimulateOptions, TorqueKind};
use poinsot::sweep::{self as core, Column, Dim, Grid};
use poinsot_py_macros::export;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::control::run;
use crate::convert::{parse, rows_out, slice, vector};
use crate::earth::{PyEarth, PyFallModel};
use crate::errors::IntoPy;

/// The dimensions as they come from Python: `(name, length, offset)`.
type Dims = Vec<(String, usize, usize)>;
/// The keywords as they come from Python: `(keyword, values, dimension)`.
type Columns<'py> = Vec<(String, PyReadonlyArray1<'py, f64>, Option<usize>)>;

/// The core's grid over the Python arrays (borrowed: no copy).
fn grid<'a>(dims: &'a Dims, columns: &'a Columns<'_>) -> PyResult<Grid<'a>> {
    let dims = dims
        .iter()
        .map(|(name, len, offset)| Dim {
            name,
            len: *len,
            offset: *offset,
        })
        .collect();
    let columns = columns
        .iter()
        .map(|(keyword, values, dim)| {
            Ok(Column {
                keyword,
                values: slice(keyword, values, "must be a C-contiguous float64 array")?,
                dim: *dim,
            })
        })
        .collect::<PyResult<_>>()?;
    Grid::new(dims, columns).py()
}

/// A new (N,) float64 array of `f` over the points.
fn floats<'py, T>(
    py: Python<'py>,
    points: &[T],
    f: impl Fn(&T) -> f64,
) -> Bound<'py, PyArray1<f64>> {
    PyArray1::from_vec(py, points.iter().map(f).collect())
}

/// A new (N,) uint8 array of `f` over the points.
fn codes<'py, T>(py: Python<'py>, points: &[T], f: impl Fn(&T) -> u8) -> Bound<'py, PyArray1<u8>> {
    PyArray1::from_vec(py, points.iter().map(f).collect())
}

/// Checks that `bytes_each` bytes a point of the sweep of `dims` fit in the memory budget (the
/// results of a sweep gathered from its chunks); the error names the longest dimension.
#[export]
fn sweep_check_memory(dims: Dims, bytes_each: usize) -> PyResult<()> {
    let columns: Columns<'_> = Vec::new();
    grid(&dims, &columns)?.check_memory(bytes_each).py()
}

/// The names of the categories' codes, from the core's tables: `{"motion_class": [...],
/// "regime": [...], "stability": [...]}` (a code is an index into its list).
#[export]
fn sweep_categories(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    let d = PyDict::new(py);
    let motion: Vec<&str> = core::MOTION_CLASSES.iter().map(|c| c.name()).collect();
    let regimes: Vec<&str> = core::FREE_REGIMES.iter().map(|r| r.as_str()).collect();
    let stabilities: Vec<&str> = core::STABILITIES.iter().map(|s| s.as_str()).collect();
    d.set_item("motion_class", motion)?;
    d.set_item("regime", regimes)?;
    d.set_item("stability", stabilities)?;
    Ok(d)
}

/// The heavy top at every point: `{"motion_class" (uint8 codes), "turning_points" (N, 2),
/// "nutation_period", "mean_precession_rate", "mean_spin_rate", "omega3", "p_phi", "p_psi",
/// "energy", "reduced_energy", "is_sleeping_stable" (bool)}`; None with `check_only`.
#[export]
#[pyo3(signature = (dims, columns, check_only, progress=None))]
fn sweep_heavy_top<'py>(
    py: Python<'py>,
    dims: Dims,
    columns: Columns<'py>,
    check_only: bool,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<Option<Bound<'py, PyDict>>> {
    let g = grid(&dims, &columns)?;
    if check_only {
        run(py, None, || core::check_heavy_top(&g))?;
        return Ok(None);
    }
    let out = run(py, progress.as_ref(), || core::heavy_top(&g))?;
    let d = PyDict::new(py);
    d.set_item(
        "motion_class",
        codes(py, &out, |p| core::motion_class_code(p.motion_class)),
    )?;
    let turning: Vec<[f64; 2]> = out
        .iter()
        .map(|p| [p.turning_points.0, p.turning_points.1])
        .collect();
    d.set_item("turning_points", rows_out(py, &turning))?;
    d.set_item("nutation_period", floats(py, &out, |p| p.nutation_period))?;
    d.set_item(
        "mean_precession_rate",
        floats(py, &out, |p| p.mean_precession_rate),
    )?;
    d.set_item("mean_spin_rate", floats(py, &out, |p| p.mean_spin_rate))?;
    d.set_item("omega3", floats(py, &out, |p| p.omega3))?;
    d.set_item("p_phi", floats(py, &out, |p| p.p_phi))?;
    d.set_item("p_psi", floats(py, &out, |p| p.p_psi))?;
    d.set_item("energy", floats(py, &out, |p| p.energy))?;
    d.set_item("reduced_energy", floats(py, &out, |p| p.reduced_energy))?;
    let sleeping: Vec<bool> = out.iter().map(|p| p.is_sleeping_stable).collect();
    d.set_item("is_sleeping_stable", PyArray1::from_vec(py, sleeping))?;
    Ok(Some(d))
}

/// The free body at every point: `{"omega0" (N, 3), "regime" (codes), "period",
/// "flip_interval", "parameter", "frequency", "pole_axis" (int8, -1 for none), "energy",
/// "angular_momentum" (N, 3), "axis_stability" (N, 3 codes), "axis_rate" (N, 3)}`; None with
/// `check_only`.
#[export]
#[pyo3(signature = (dims, columns, check_only, progress=None))]
fn sweep_free_body<'py>(
    py: Python<'py>,
    dims: Dims,
    columns: Columns<'py>,
    check_only: bool,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<Option<Bound<'py, PyDict>>> {
    let g = grid(&dims, &columns)?;
    if check_only {
        run(py, None, || core::check_free_body(&g))?;
        return Ok(None);
    }
    let out = run(py, progress.as_ref(), || core::free_body(&g))?;
    let d = PyDict::new(py);
    let omega0: Vec<[f64; 3]> = out.iter().map(|p| p.omega0).collect();
    d.set_item("omega0", rows_out(py, &omega0))?;
    d.set_item("regime", codes(py, &out, |p| core::regime_code(p.regime)))?;
    d.set_item("period", floats(py, &out, |p| p.period))?;
    d.set_item("flip_interval", floats(py, &out, |p| p.flip_interval))?;
    d.set_item("parameter", floats(py, &out, |p| p.parameter))?;
    d.set_item("frequency", floats(py, &out, |p| p.frequency))?;
    let pole: Vec<i8> = out
        .iter()
        .map(|p| p.pole_axis.map_or(-1, |k| k as i8))
        .collect();
    d.set_item("pole_axis", PyArray1::from_vec(py, pole))?;
    d.set_item("energy", floats(py, &out, |p| p.energy))?;
    let l: Vec<[f64; 3]> = out.iter().map(|p| p.angular_momentum).collect();
    d.set_item("angular_momentum", rows_out(py, &l))?;
    let kinds: Vec<u8> = out
        .iter()
        .flat_map(|p| p.axis_stability.map(|a| core::stability_code(a.stability)))
        .collect();
    d.set_item(
        "axis_stability",
        PyArray1::from_vec(py, kinds).reshape([out.len(), 3])?,
    )?;
    let rates: Vec<[f64; 3]> = out
        .iter()
        .map(|p| p.axis_stability.map(|a| a.rate))
        .collect();
    d.set_item("axis_rate", rows_out(py, &rates))?;
    Ok(Some(d))
}

/// Ensembles under a torque (`simulate_batch`'s settings: duration, torque as kind, (3,)
/// vector and scalar, method, dt, max_steps): `{"omega" (N, 3), "attitude" (N, 4)}`; None with
/// `check_only`.
#[export]
#[pyo3(signature = (dims, columns, duration, torque_kind, torque_vector, torque_scalar, method, dt, max_steps, check_only, progress=None))]
#[allow(clippy::too_many_arguments)]
fn sweep_simulate<'py>(
    py: Python<'py>,
    dims: Dims,
    columns: Columns<'py>,
    duration: f64,
    torque_kind: &str,
    torque_vector: PyReadonlyArray1<'py, f64>,
    torque_scalar: f64,
    method: &str,
    dt: Option<f64>,
    max_steps: usize,
    check_only: bool,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<Option<Bound<'py, PyDict>>> {
    let g = grid(&dims, &columns)?;
    let torque = parse::<TorqueKind>(torque_kind)?
        .torque(vector("torque", &torque_vector)?, torque_scalar)
        .py()?;
    let opts = SimulateOptions {
        method: Method::parse(method).py()?,
        dt,
        max_steps,
        ..SimulateOptions::default()
    };
    if check_only {
        run(py, None, || {
            core::check_simulate(&g, duration, &torque, &opts)
        })?;
        return Ok(None);
    }
    let out = run(py, progress.as_ref(), || {
        core::simulate(&g, duration, &torque, &opts)
    })?;
    let d = PyDict::new(py);
    let omega: Vec<[f64; 3]> = out.iter().map(|p| p.omega).collect();
    let attitude: Vec<[f64; 4]> = out.iter().map(|p| p.attitude).collect();
    d.set_item("omega", rows_out(py, &omega))?;
    d.set_item("attitude", rows_out(py, &attitude))?;
    Ok(Some(d))
}

/// Drops on the Earth (`EarthCore`) under the fall model (`FallModel`): `{"time", "east",
/// "north", "first_order_east", "second_order_south"}`; None with `check_only`.
#[export]
#[pyo3(signature = (dims, columns, earth, model, check_only, progress=None))]
fn sweep_drop<'py>(
    py: Python<'py>,
    dims: Dims,
    columns: Columns<'py>,
    earth: PyRef<'py, PyEarth>,
    model: PyRef<'py, PyFallModel>,
    check_only: bool,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<Option<Bound<'py, PyDict>>> {
    let grid = grid(&dims, &columns)?;
    let (e, m) = (earth.inner, model.inner);
    if check_only {
        run(py, None, || core::check_drop(&grid, &m))?;
        return Ok(None);
    }
    let out = run(py, progress.as_ref(), || core::drop(&e, &grid, &m))?;
    let d = PyDict::new(py);
    d.set_item("time", floats(py, &out, |p| p.time))?;
    d.set_item("east", floats(py, &out, |p| p.east))?;
    d.set_item("north", floats(py, &out, |p| p.north))?;
    d.set_item("first_order_east", floats(py, &out, |p| p.first_order_east))?;
    d.set_item(
        "second_order_south",
        floats(py, &out, |p| p.second_order_south),
    )?;
    Ok(Some(d))
}

/// Projectiles on the Earth, as [`sweep_drop`]: `{"time", "east", "north", "range",
/// "downrange", "drift"}`; None with `check_only`.
#[export]
#[pyo3(signature = (dims, columns, earth, model, check_only, progress=None))]
fn sweep_projectile<'py>(
    py: Python<'py>,
    dims: Dims,
    columns: Columns<'py>,
    earth: PyRef<'py, PyEarth>,
    model: PyRef<'py, PyFallModel>,
    check_only: bool,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<Option<Bound<'py, PyDict>>> {
    let grid = grid(&dims, &columns)?;
    let (e, m) = (earth.inner, model.inner);
    if check_only {
        run(py, None, || core::check_projectile(&grid, &m))?;
        return Ok(None);
    }
    let out = run(py, progress.as_ref(), || core::projectile(&e, &grid, &m))?;
    let d = PyDict::new(py);
    d.set_item("time", floats(py, &out, |p| p.time))?;
    d.set_item("east", floats(py, &out, |p| p.east))?;
    d.set_item("north", floats(py, &out, |p| p.north))?;
    d.set_item("range", floats(py, &out, |p| p.range))?;
    d.set_item("downrange", floats(py, &out, |p| p.downrange))?;
    d.set_item("drift", floats(py, &out, |p| p.drift))?;
    Ok(Some(d))
}

/// Registers this file's functions on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add(
        "SWEEP_HEAVY_TOP_KEYWORDS",
        core::HEAVY_TOP_KEYWORDS.to_vec(),
    )?;
    m.add(
        "SWEEP_FREE_BODY_KEYWORDS",
        core::FREE_BODY_KEYWORDS.to_vec(),
    )?;
    m.add("SWEEP_SIMULATE_KEYWORDS", core::SIMULATE_KEYWORDS.to_vec())?;
    m.add("SWEEP_DROP_KEYWORDS", core::DROP_KEYWORDS.to_vec())?;
    m.add(
        "SWEEP_PROJECTILE_KEYWORDS",
        core::PROJECTILE_KEYWORDS.to_vec(),
    )?;
    m.add_function(wrap_pyfunction!(sweep_categories, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_check_memory, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_heavy_top, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_free_body, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_simulate, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_drop, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_projectile, m)?)?;
    Ok(())
}
