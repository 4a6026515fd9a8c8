//! Bindings of `poinsot::sweep` (conversion and error mapping only).
//!
//! A sweep travels as its dimensions, a list of `(name, length, offset)`, and its keywords, a
//! list of `(keyword, values, dimension index or None)` with `values` a C-contiguous float64
//! array holding the keyword's entries row-major (3 numbers an entry for a vector). Each
//! function checks every point (`check_only=True`: only that) or computes them, returning a
//! dict of flat arrays, one entry a point in row-major order (`(N, 3)` / `(N, 4)` for vectors);
//! categories (motion class, regime, stability) as `uint8` codes into `sweep_categories()`.
use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray1};
use poinsot::sweep::{self as core, Column, Dim, Grid};
use poinsot_py_macros::export;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::control::run;
use crate::convert::{rows_out, slice};
use crate::dynamics::{batch_settings, BatchSettings};
use crate::earth::{PyEarth, PyFallModel};
use crate::errors::IntoPy;

/// The dimensions as they come from Python: `(name, length, offset, argument)` (see
/// [`Dim::argument`]: the user's argument that errors about the dimension name).
type Dims = Vec<(String, usize, usize, String)>;
/// The keywords as they come from Python: `(keyword, values, dimension)`.
type Columns<'py> = Vec<(String, PyReadonlyArray1<'py, f64>, Option<usize>)>;
/// A sweep's results: None with `check_only`.
type Out<'py> = Option<Bound<'py, PyDict>>;

/// The core's grid over the Python arrays (borrowed: no copy).
fn grid<'a>(dims: &'a Dims, columns: &'a Columns<'_>) -> PyResult<Grid<'a>> {
    let dims = dims
        .iter()
        .map(|(name, len, offset, argument)| Dim {
            name,
            len: *len,
            offset: *offset,
            argument,
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

/// A sweep from Python: its `check` alone (`check_only`: None), or its points from `compute`
/// (the GIL released, reporting to `progress`) written into a new dict by `fill`.
fn sweep<'py, T: Send>(
    py: Python<'py>,
    check_only: bool,
    progress: Option<Bound<'py, PyAny>>,
    check: impl FnOnce() -> poinsot::Result<()> + Send,
    compute: impl FnOnce() -> poinsot::Result<Vec<T>> + Send,
    fill: impl FnOnce(&Bound<'py, PyDict>, &[T]) -> PyResult<()>,
) -> PyResult<Out<'py>> {
    if check_only {
        run(py, None, check)?;
        return Ok(None);
    }
    let out = run(py, progress.as_ref(), compute)?;
    let d = PyDict::new(py);
    fill(&d, &out)?;
    Ok(Some(d))
}

/// Sets `d[name]` to the (N,) float64 array of the `f64` field `name` of each point, for each
/// name given.
macro_rules! set_floats {
    ($d:expr, $points:expr; $($field:ident),+ $(,)?) => {{
        let py = $d.py();
        $($d.set_item(
            stringify!($field),
            PyArray1::from_vec(py, $points.iter().map(|p| p.$field).collect()),
        )?;)+
    }};
}

/// Sets `d[name]` to a new (N, …) array of `f` over the points: rows (`[f64; K]`) or a column
/// of scalars (`f64`, `u8`, `i8`, `bool`).
fn set<T, E: numpy::Element>(
    d: &Bound<'_, PyDict>,
    name: &str,
    points: &[T],
    f: impl Fn(&T) -> E,
) -> PyResult<()> {
    d.set_item(
        name,
        PyArray1::from_vec(d.py(), points.iter().map(f).collect()),
    )
}

/// Sets `d[name]` to the (N, K) array of `f` over the points.
fn set_rows<T, const K: usize>(
    d: &Bound<'_, PyDict>,
    name: &str,
    points: &[T],
    f: impl Fn(&T) -> [f64; K],
) -> PyResult<()> {
    let rows: Vec<[f64; K]> = points.iter().map(f).collect();
    d.set_item(name, rows_out(d.py(), &rows))
}

/// Checks that `bytes_each` bytes a point of the sweep of `dims` fit in the memory budget (the
/// results of a sweep gathered from its chunks); the error names the longest dimension's
/// argument.
#[export]
fn sweep_check_memory(dims: Dims, bytes_each: usize) -> PyResult<()> {
    grid(&dims, &Vec::new())?.check_memory(bytes_each).py()
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

/// Exports `$name`, the sweep of a model of the grid alone: `core::$check` with `check_only`
/// (None), else `core::$run` at every point, its results written into the dict by `$fill`.
macro_rules! grid_sweep {
    ($(#[$doc:meta])* $name:ident = $check:ident, $run:ident, $fill:ident) => {
        $(#[$doc])*
        #[export]
        #[pyo3(signature = (dims, columns, check_only, progress=None))]
        fn $name<'py>(
            py: Python<'py>,
            dims: Dims,
            columns: Columns<'py>,
            check_only: bool,
            progress: Option<Bound<'py, PyAny>>,
        ) -> PyResult<Out<'py>> {
            let g = grid(&dims, &columns)?;
            let (check, compute) = (|| core::$check(&g), || core::$run(&g));
            sweep(py, check_only, progress, check, compute, $fill)
        }
    };
}

grid_sweep!(
    /// The heavy top at every point: `{"motion_class" (uint8 codes), "turning_points" (N, 2),
    /// "nutation_period", "mean_precession_rate", "mean_spin_rate", "omega3", "p_phi", "p_psi",
    /// "energy", "reduced_energy", "is_sleeping_stable" (bool)}`; None with `check_only`.
    sweep_heavy_top = check_heavy_top, heavy_top, heavy_top_columns
);

/// The heavy top's results into the sweep's dict.
fn heavy_top_columns(d: &Bound<'_, PyDict>, out: &[core::HeavyTopPoint]) -> PyResult<()> {
    set(d, "motion_class", out, |p| {
        core::motion_class_code(p.motion_class)
    })?;
    set_rows(d, "turning_points", out, |p| {
        [p.turning_points.0, p.turning_points.1]
    })?;
    set_floats!(d, out; nutation_period, mean_precession_rate, mean_spin_rate, omega3,
        p_phi, p_psi, energy, reduced_energy);
    set(d, "is_sleeping_stable", out, |p| p.is_sleeping_stable)
}

grid_sweep!(
    /// The free body at every point: `{"omega0" (N, 3), "regime" (codes), "period",
    /// "flip_interval", "parameter", "frequency", "pole_axis" (int8, -1 for none), "energy",
    /// "angular_momentum" (N, 3), "axis_stability" (N, 3 codes), "axis_rate" (N, 3)}`; None
    /// with `check_only`.
    sweep_free_body = check_free_body, free_body, free_body_columns
);

/// The free body's results into the sweep's dict.
fn free_body_columns(d: &Bound<'_, PyDict>, out: &[core::FreeBodyPoint]) -> PyResult<()> {
    set_rows(d, "omega0", out, |p| p.omega0)?;
    set(d, "regime", out, |p| core::regime_code(p.regime))?;
    set_floats!(d, out; period, flip_interval, parameter, frequency);
    set(d, "pole_axis", out, |p| p.pole_axis.map_or(-1, |k| k as i8))?;
    set_floats!(d, out; energy);
    set_rows(d, "angular_momentum", out, |p| p.angular_momentum)?;
    let kinds: Vec<u8> = out
        .iter()
        .flat_map(|p| p.axis_stability.map(|a| core::stability_code(a.stability)))
        .collect();
    let kinds = PyArray1::from_vec(d.py(), kinds).reshape([out.len(), 3])?;
    d.set_item("axis_stability", kinds)?;
    set_rows(d, "axis_rate", out, |p| p.axis_stability.map(|a| a.rate))
}

/// Ensembles under a torque (`simulate_batch`'s [`BatchSettings`]): `{"omega" (N, 3),
/// "attitude" (N, 4)}`; None with `check_only`.
#[export]
#[pyo3(signature = (dims, columns, settings, check_only, progress=None))]
fn sweep_simulate<'py>(
    py: Python<'py>,
    dims: Dims,
    columns: Columns<'py>,
    settings: BatchSettings<'py>,
    check_only: bool,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<Out<'py>> {
    let g = grid(&dims, &columns)?;
    let (duration, torque, opts) = batch_settings(&settings)?;
    let check = || core::check_simulate(&g, duration, &torque, &opts);
    let compute = || core::simulate(&g, duration, &torque, &opts);
    sweep(py, check_only, progress, check, compute, |d, out| {
        set_rows(d, "omega", out, |p| p.omega)?;
        set_rows(d, "attitude", out, |p| p.attitude)
    })
}

/// Exports `$name`, a sweep on the Earth (`EarthCore`) under the fall model (`FallModel`):
/// `core::$check` alone with `check_only` (None), else `core::$run` at every point, its
/// `f64` results `$field`s as (N,) arrays.
macro_rules! earth_sweep {
    ($(#[$doc:meta])* $name:ident = $check:ident, $run:ident: $($field:ident),+) => {
        $(#[$doc])*
        #[export]
        #[pyo3(signature = (dims, columns, earth, model, check_only, progress=None))]
        fn $name<'py>(
            py: Python<'py>,
            dims: Dims,
            columns: Columns<'py>,
            earth: PyRef<'py, PyEarth>,
            model: PyRef<'py, PyFallModel>,
            check_only: bool,
            progress: Option<Bound<'py, PyAny>>,
        ) -> PyResult<Out<'py>> {
            let g = grid(&dims, &columns)?;
            let (e, m) = (earth.inner, model.inner);
            let (check, compute) = (|| core::$check(&g, &m), || core::$run(&e, &g, &m));
            sweep(py, check_only, progress, check, compute, |d, out| {
                set_floats!(d, out; $($field),+);
                Ok(())
            })
        }
    };
}

earth_sweep!(
    /// Drops on the Earth: `{"time", "east", "north", "first_order_east",
    /// "second_order_south"}`; None with `check_only`.
    sweep_drop = check_drop, drop: time, east, north, first_order_east, second_order_south
);
earth_sweep!(
    /// Projectiles on the Earth: `{"time", "east", "north", "range", "downrange", "drift"}`;
    /// None with `check_only`.
    sweep_projectile = check_projectile, projectile: time, east, north, range, downrange, drift
);

/// Registers this file's functions on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    for (name, keywords) in [
        ("SWEEP_HEAVY_TOP_KEYWORDS", &core::HEAVY_TOP_KEYWORDS[..]),
        ("SWEEP_FREE_BODY_KEYWORDS", &core::FREE_BODY_KEYWORDS[..]),
        ("SWEEP_SIMULATE_KEYWORDS", &core::SIMULATE_KEYWORDS[..]),
        ("SWEEP_DROP_KEYWORDS", &core::DROP_KEYWORDS[..]),
        ("SWEEP_PROJECTILE_KEYWORDS", &core::PROJECTILE_KEYWORDS[..]),
    ] {
        m.add(name, keywords.to_vec())?;
    }
    add_functions!(m; sweep_categories, sweep_check_memory, sweep_heavy_top, sweep_free_body,
        sweep_simulate, sweep_drop, sweep_projectile);
    Ok(())
}
