//! The one conversion layer of the Python binding: numpy arrays in (checked, with shape errors
//! that name the argument) and out, the core's enums parsed from their Python names, and the
//! integrator options. Every binding file converts through here.
//!
//! Arguments come in through functions that take the argument's name, because a shape error must
//! be a `PoinsotError` naming it (pyo3's own extraction knows no argument name): [`vector`],
//! [`triple`] (a user's 3-vector of any form), [`array_in`], [`matrix`], [`rows_in`], [`times`], [`opt_quat`], [`parse`].
//! Results go out through newtypes that convert themselves to numpy arrays, so that a getter is
//! one line: [`Vector`] (3,), [`Numbers`] (K,), [`Matrix`] (3, 3), [`Rows`] (N, K), [`Values`]
//! (N,).
use std::str::FromStr;

use numpy::ndarray::Array2;
use numpy::{
    IntoPyArray, PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2,
    PyUntypedArray, PyUntypedArrayMethods,
};
use poinsot::dynamics::{Method, SimulateOptions};
use poinsot::integrate::{Options, Tolerances};
use poinsot::{Mat3, Vec3};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{IntoPyDict, PyFloat, PyInt, PyList, PyTuple};

use crate::errors::{invalid, IntoPy};

// ---------------------------------------------------------------------------------------------
// In: numpy arrays → Rust values, naming the argument on a shape error.

/// A 1-D float array → a vector.
pub fn vec_in(a: &PyReadonlyArray1<'_, f64>) -> Vec<f64> {
    a.as_array().iter().copied().collect()
}

/// A length-K float array → `[f64; K]`.
pub fn array_in<const K: usize>(
    argument: &str,
    a: &PyReadonlyArray1<'_, f64>,
) -> PyResult<[f64; K]> {
    let v = vec_in(a);
    if v.len() != K {
        return Err(invalid(
            argument,
            format!("must have shape ({K},), got ({},)", v.len()),
        ));
    }
    Ok(std::array::from_fn(|i| v[i]))
}

/// A length-3 float array → `[f64; 3]` (contiguous).
pub fn vec3(argument: &str, a: &PyReadonlyArray1<'_, f64>) -> PyResult<[f64; 3]> {
    let s = slice(argument, a, "must be a contiguous array")?;
    match s {
        [x, y, z] => Ok([*x, *y, *z]),
        _ => Err(invalid(
            argument,
            format!("must have shape (3,), got ({},)", s.len()),
        )),
    }
}

/// A length-3 float array → a core vector.
pub fn vector(argument: &str, a: &PyReadonlyArray1<'_, f64>) -> PyResult<Vec3> {
    vec3(argument, a).map(Vec3::from)
}

/// A user's 3-vector → `[f64; 3]`: the one conversion of the small calls' vector arguments
/// (the free bodies' `moments` and `omega0`), read here once.
///
/// A list or tuple (exactly) of three Python floats (exactly) or of ints within ±2⁵³, or a
/// float64 ndarray (exactly, native byte order) of shape (3,), is read directly — the numbers
/// the general conversion gives, exactly. Anything else (other sequences and dtypes, numpy
/// scalars, subclasses) and, with `finite`, a non-finite entry go through the package's general
/// conversion, `poinsot._validate.as_float_array`, and a shape check: the errors of every
/// other array argument (`ArgumentTypeError` for text, `"omega0: must be finite, got nan"`,
/// `"moments: must have shape (3,), got (2,)"`), each naming `argument`.
pub fn triple(argument: &str, a: &Bound<'_, PyAny>, finite: bool) -> PyResult<[f64; 3]> {
    match read3(a) {
        Some(v) if !finite || v.iter().all(|x| x.is_finite()) => Ok(v),
        _ => general3(argument, a, finite),
    }
}

/// The three numbers of a plain list, tuple or float64 array (see [`triple`]), else `None`.
fn read3(a: &Bound<'_, PyAny>) -> Option<[f64; 3]> {
    if let Ok(l) = a.cast_exact::<PyList>() {
        if l.len() != 3 {
            return None;
        }
        let f = |i| number(&l.get_item(i).ok()?);
        Some([f(0)?, f(1)?, f(2)?])
    } else if let Ok(t) = a.cast_exact::<PyTuple>() {
        if t.len() != 3 {
            return None;
        }
        let f = |i| number(&t.get_item(i).ok()?);
        Some([f(0)?, f(1)?, f(2)?])
    } else if a.get_type().is(a.py().get_type::<PyUntypedArray>()) {
        let arr = a.cast::<PyArray1<f64>>().ok()?.try_readonly().ok()?;
        let v = arr.as_array();
        (v.len() == 3).then(|| [v[0], v[1], v[2]])
    } else {
        None
    }
}

/// The value of an exact Python float, or of an exact int within ±2⁵³ (exactly a double; not a
/// bool), else `None`.
fn number(item: &Bound<'_, PyAny>) -> Option<f64> {
    if let Ok(f) = item.cast_exact::<PyFloat>() {
        return Some(f.value());
    }
    const EXACT: i64 = 1 << 53;
    let i: i64 = item.cast_exact::<PyInt>().ok()?.extract().ok()?;
    (-EXACT..=EXACT).contains(&i).then_some(i as f64)
}

/// [`triple`] of anything else: `poinsot._validate.as_float_array(a, argument, finite=finite)`
/// (the package's general conversion, looked up once) and a shape check.
#[cold]
fn general3(argument: &str, a: &Bound<'_, PyAny>, finite: bool) -> PyResult<[f64; 3]> {
    static CONVERT: PyOnceLock<Py<PyAny>> = PyOnceLock::new();
    let py = a.py();
    let convert = CONVERT.get_or_try_init(py, || {
        py.import("poinsot._validate")?
            .getattr("as_float_array")
            .map(Bound::unbind)
    })?;
    let kwargs = [("finite", finite)].into_py_dict(py)?;
    let arr = convert.bind(py).call((a, argument), Some(&kwargs))?;
    if let Ok(v) = arr.cast::<PyArray1<f64>>() {
        if let Ok(v) = v.try_readonly() {
            if let [x, y, z] = v.as_array().to_vec()[..] {
                return Ok([x, y, z]);
            }
        }
    }
    let shape = arr.getattr("shape")?.repr()?;
    Err(invalid(
        argument,
        format!("must have shape (3,), got {shape}"),
    ))
}

/// An optional length-3 float array → an optional core vector.
pub fn opt_vector(argument: &str, a: &Option<PyReadonlyArray1<'_, f64>>) -> PyResult<Option<Vec3>> {
    a.as_ref().map(|a| vector(argument, a)).transpose()
}

/// An optional (4,) quaternion `[w, x, y, z]`.
pub fn opt_quat(
    argument: &str,
    a: &Option<PyReadonlyArray1<'_, f64>>,
) -> PyResult<Option<[f64; 4]>> {
    let Some(a) = a else { return Ok(None) };
    let v = vec_in(a);
    match v[..] {
        [w, x, y, z] => Ok(Some([w, x, y, z])),
        _ => Err(invalid(
            argument,
            format!("must have shape (4,) ([w, x, y, z]), got ({},)", v.len()),
        )),
    }
}

/// A contiguous (N,) float64 array as a slice; `otherwise` is the message if it is not
/// contiguous.
pub fn slice<'a>(
    argument: &str,
    a: &'a PyReadonlyArray1<'_, f64>,
    otherwise: &str,
) -> PyResult<&'a [f64]> {
    a.as_slice().map_err(|_| invalid(argument, otherwise))
}

/// Times `t` (N,), each finite (the error names `t`).
pub fn times(t: &PyReadonlyArray1<'_, f64>) -> PyResult<Vec<f64>> {
    let t = vec_in(t);
    poinsot::error::check_finite("t", &t).py()?;
    Ok(t)
}

/// A (3, 3) float array → row-major `[[f64; 3]; 3]`.
pub fn mat3(argument: &str, a: &PyReadonlyArray2<'_, f64>) -> PyResult<[[f64; 3]; 3]> {
    let shape = a.shape();
    if shape != [3, 3] {
        return Err(invalid(
            argument,
            format!("must have shape (3, 3), got {shape:?}"),
        ));
    }
    let v = a.as_array();
    Ok(std::array::from_fn(|i| std::array::from_fn(|j| v[[i, j]])))
}

/// A (3, 3) float array → a core matrix.
pub fn matrix(argument: &str, a: &PyReadonlyArray2<'_, f64>) -> PyResult<Mat3> {
    mat3(argument, a).map(|m| Mat3::from_fn(|i, j| m[i][j]))
}

/// An (N, K) float array → rows of K floats, naming `argument` on a shape error.
pub fn rows_in<const K: usize>(
    argument: &str,
    a: &PyReadonlyArray2<'_, f64>,
) -> PyResult<Vec<[f64; K]>> {
    let shape = a.shape();
    if shape.len() != 2 || shape[1] != K {
        return Err(invalid(
            argument,
            format!("must have shape (N, {K}), got {shape:?}"),
        ));
    }
    if let Ok(flat) = a.as_slice() {
        // C-contiguous (the public API passes such arrays): row by row from the flat data.
        return Ok(flat
            .chunks_exact(K)
            .map(|r| std::array::from_fn(|i| r[i]))
            .collect());
    }
    Ok(a.as_array()
        .rows()
        .into_iter()
        .map(|r| std::array::from_fn(|i| r[i]))
        .collect())
}

/// An (N, K) float array → its rows as `[f64; K]`: borrowed from the array without a copy when
/// it is C-contiguous (the public API passes such arrays), copied otherwise; the error names
/// `argument`.
pub fn rows_view<'a, const K: usize>(
    argument: &str,
    a: &'a PyReadonlyArray2<'_, f64>,
) -> PyResult<std::borrow::Cow<'a, [[f64; K]]>>
where
    [f64; K]: bytemuck::Pod,
{
    let shape = a.shape();
    if shape.len() != 2 || shape[1] != K {
        return Err(invalid(
            argument,
            format!("must have shape (N, {K}), got {shape:?}"),
        ));
    }
    match a.as_slice() {
        Ok(flat) => bytemuck::try_cast_slice(flat)
            .map(std::borrow::Cow::Borrowed)
            .or_else(|_| rows_in::<K>(argument, a).map(std::borrow::Cow::Owned)),
        Err(_) => rows_in::<K>(argument, a).map(std::borrow::Cow::Owned),
    }
}

/// Rows of K floats, owned → a new (N, K) numpy array that takes the memory (no copy).
pub fn rows_into<const K: usize>(
    py: Python<'_>,
    rows: Vec<[f64; K]>,
) -> PyResult<Bound<'_, PyArray2<f64>>> {
    let n = rows.len();
    Ok(Array2::from_shape_vec((n, K), rows.into_flattened())
        .map_err(|e| invalid("rows", e.to_string()))?
        .into_pyarray(py))
}

/// An (N, 3) C-contiguous array of any element type → its flat row-major slice of `3·N` values.
pub fn rows3_slice<'a, T: numpy::Element>(
    argument: &str,
    a: &'a PyReadonlyArray2<'_, T>,
) -> PyResult<&'a [T]> {
    let shape = a.shape();
    if shape.len() != 2 || shape[1] != 3 {
        return Err(invalid(
            argument,
            format!("must have shape (N, 3), got {shape:?}"),
        ));
    }
    a.as_slice()
        .map_err(|_| invalid(argument, "must be a C-contiguous array"))
}

/// A C-contiguous float array of shape `(N, *tail)` → its flat data and `N` (for the batch
/// kernels of the core). The error names `argument` and the expected shape.
pub fn records<'a>(
    argument: &str,
    a: &'a numpy::PyReadonlyArrayDyn<'_, f64>,
    tail: &[usize],
) -> PyResult<(&'a [f64], usize)> {
    let shape = a.shape();
    if shape.len() != tail.len() + 1 || shape[1..] != *tail {
        let want: Vec<String> = tail.iter().map(|d| d.to_string()).collect();
        return Err(invalid(
            argument,
            format!("must have shape (N, {}), got {shape:?}", want.join(", ")),
        ));
    }
    let data = a
        .as_slice()
        .map_err(|_| invalid(argument, "must be a C-contiguous array"))?;
    Ok((data, shape[0]))
}

/// A core enum from its Python name (`"body"`, `"inverse-square"`, `"gravity_gradient"`), by
/// its [`FromStr`] in the core, whose error names the argument.
pub fn parse<T: FromStr<Err = poinsot::Error>>(name: &str) -> PyResult<T> {
    name.parse().py()
}

/// A run's settings, one argument as Python's `_validate.run_settings` makes them: (samples,
/// rtol, atol, max_steps), each already checked by it and again by the core's run.
#[derive(FromPyObject, Clone, Copy)]
pub struct RunSettings(pub usize, pub f64, pub f64, pub usize);

impl RunSettings {
    /// The integrator's tolerances (rtol, atol, max_steps).
    pub fn tolerances(&self) -> Tolerances {
        Tolerances {
            rtol: self.1,
            atol: self.2,
            max_steps: self.3,
        }
    }

    /// A rigid body's run options: the method named `method` (the step `dt` the method's
    /// default), the samples and the tolerances.
    pub fn simulate(&self, method: &str) -> PyResult<SimulateOptions> {
        Ok(SimulateOptions {
            method: Method::parse(method).py()?,
            dt: None,
            samples: self.0,
            rtol: self.1,
            atol: self.2,
            max_steps: self.3,
        })
    }
}

/// Integrator options from the Python keywords.
pub fn options(rtol: f64, atol: f64, max_steps: usize, dense: bool) -> Options {
    Options {
        rtol,
        atol,
        max_steps,
        dense,
        ..Options::default()
    }
}

// ---------------------------------------------------------------------------------------------
// Between the core's nalgebra types and plain arrays.

/// `[f64; 3]` → a core vector.
pub fn v3(r: &[f64; 3]) -> Vec3 {
    Vec3::new(r[0], r[1], r[2])
}

/// A core vector → `[f64; 3]`.
pub fn a3(v: &Vec3) -> [f64; 3] {
    [v.x, v.y, v.z]
}

/// A core matrix → row-major `[[f64; 3]; 3]`.
pub fn from_mat(m: &Mat3) -> [[f64; 3]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|j| m[(i, j)]))
}

// ---------------------------------------------------------------------------------------------
// Out: Rust values → new numpy arrays.

/// `[f64; 3]` → a new numpy array of shape (3,).
pub fn vec3_out<'py>(py: Python<'py>, v: [f64; 3]) -> Bound<'py, PyArray1<f64>> {
    PyArray1::from_slice(py, &v)
}

/// Row-major 3×3 → a new numpy array of shape (3, 3).
pub fn mat3_out<'py>(py: Python<'py>, m: [[f64; 3]; 3]) -> Bound<'py, PyArray2<f64>> {
    Array2::from_shape_fn((3, 3), |(i, j)| m[i][j]).into_pyarray(py)
}

/// Rows of K floats → a new (N, K) numpy array.
pub fn rows_out<'py, const K: usize>(
    py: Python<'py>,
    rows: &[[f64; K]],
) -> Bound<'py, PyArray2<f64>> {
    match Array2::from_shape_vec((rows.len(), K), rows.as_flattened().to_vec()) {
        Ok(a) => a.into_pyarray(py),
        Err(_) => Array2::from_shape_fn((rows.len(), K), |(i, j)| rows[i][j]).into_pyarray(py),
    }
}

/// A flat row-major vector of `9·N` values → a new numpy array of shape (N, 3, 3).
pub fn mats3_out(py: Python<'_>, flat: Vec<f64>) -> PyResult<Bound<'_, numpy::PyArray3<f64>>> {
    let n = flat.len() / 9;
    PyArray1::from_vec(py, flat).reshape([n, 3, 3])
}

/// A new zero-filled float64 array of shape `dims` (an output buffer for a batch kernel).
pub fn zeros<'py>(py: Python<'py>, dims: &[usize]) -> Bound<'py, numpy::PyArrayDyn<f64>> {
    numpy::PyArrayDyn::<f64>::zeros(py, numpy::IxDyn(dims), false)
}

/// A vector result: a new numpy array of shape (3,).
pub struct Vector(pub Vec3);

/// K numbers (a quaternion, a small state): a new numpy array of shape (K,).
pub struct Numbers<const K: usize>(pub [f64; K]);

/// A matrix result: a new numpy array of shape (3, 3).
pub struct Matrix(pub Mat3);

/// Rows of K floats: a new numpy array of shape (N, K).
pub struct Rows<const K: usize>(pub Vec<[f64; K]>);

/// Numbers: a new numpy array of shape (N,).
pub struct Values(pub Vec<f64>);

impl From<Vec3> for Vector {
    fn from(v: Vec3) -> Self {
        Vector(v)
    }
}

impl From<[f64; 3]> for Vector {
    fn from(v: [f64; 3]) -> Self {
        Vector(v3(&v))
    }
}

impl From<Mat3> for Matrix {
    fn from(m: Mat3) -> Self {
        Matrix(m)
    }
}

impl FromIterator<Vec3> for Rows<3> {
    fn from_iter<I: IntoIterator<Item = Vec3>>(iter: I) -> Self {
        Rows(iter.into_iter().map(|v| a3(&v)).collect())
    }
}

impl<const K: usize> FromIterator<[f64; K]> for Rows<K> {
    fn from_iter<I: IntoIterator<Item = [f64; K]>>(iter: I) -> Self {
        Rows(iter.into_iter().collect())
    }
}

impl FromIterator<f64> for Values {
    fn from_iter<I: IntoIterator<Item = f64>>(iter: I) -> Self {
        Values(iter.into_iter().collect())
    }
}

/// `IntoPyObject` for the result types made without failing: `impl[generics] Type => Target,
/// |value, py| array;`.
macro_rules! into_array {
    ($(impl[$($generics:tt)*] $ty:ty => $target:ty, |$v:ident, $py:ident| $make:expr;)+) => {
        $(impl<'py, $($generics)*> IntoPyObject<'py> for $ty {
            type Target = $target;
            type Output = Bound<'py, $target>;
            type Error = std::convert::Infallible;
            fn into_pyobject(self, $py: Python<'py>) -> Result<Self::Output, Self::Error> {
                let $v = self;
                Ok($make)
            }
        })+
    };
}

into_array! {
    impl[] Vector => PyArray1<f64>, |v, py| vec3_out(py, a3(&v.0));
    impl[const K: usize] Numbers<K> => PyArray1<f64>, |v, py| PyArray1::from_slice(py, &v.0);
    impl[] Matrix => PyArray2<f64>, |v, py| mat3_out(py, from_mat(&v.0));
    impl[] Values => PyArray1<f64>, |v, py| PyArray1::from_vec(py, v.0);
}

impl<'py, const K: usize> IntoPyObject<'py> for Rows<K> {
    type Target = PyArray2<f64>;
    type Output = Bound<'py, PyArray2<f64>>;
    type Error = PyErr;
    fn into_pyobject(self, py: Python<'py>) -> Result<Self::Output, Self::Error> {
        // The rows moved into numpy, not copied (a copy of 10⁸ rows held the GIL ~0.5 s).
        let n = self.0.len();
        PyArray1::from_vec(py, self.0.into_flattened()).reshape([n, K])
    }
}

/// A new dict of a core value's fields, each under its own name, then of named values:
/// `fields_dict!(py, s; slow, fast; min = m)` is `{"slow": s.slow, "fast": s.fast, "min": m}`.
macro_rules! fields_dict {
    ($py:expr, $value:expr; $($field:ident),* $(; $($key:ident = $extra:expr),* $(,)?)?) => {{
        let d = ::pyo3::types::PyDict::new($py);
        $(::pyo3::types::PyDictMethods::set_item(&d, stringify!($field), $value.$field)?;)*
        $($(::pyo3::types::PyDictMethods::set_item(&d, stringify!($key), $extra)?;)*)?
        d
    }};
}
pub(crate) use fields_dict;
