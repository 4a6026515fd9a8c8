//! Array conversions shared by the binding files: numpy ↔ fixed-size Rust arrays, with
//! shape errors that name the argument.
use numpy::{PyArray1, PyArray2, PyReadonlyArray1, PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::prelude::*;

use crate::errors::invalid;

/// A length-3 float array → `[f64; 3]`.
pub fn vec3(argument: &str, a: &PyReadonlyArray1<'_, f64>) -> PyResult<[f64; 3]> {
    let s = a
        .as_slice()
        .map_err(|_| invalid(argument, "must be a contiguous array"))?;
    if s.len() != 3 {
        return Err(invalid(
            argument,
            format!("must have shape (3,), got ({},)", s.len()),
        ));
    }
    Ok([s[0], s[1], s[2]])
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
    Ok([
        [v[[0, 0]], v[[0, 1]], v[[0, 2]]],
        [v[[1, 0]], v[[1, 1]], v[[1, 2]]],
        [v[[2, 0]], v[[2, 1]], v[[2, 2]]],
    ])
}

/// An (N, 3) float array → a vector of `[f64; 3]` rows.
pub fn rows3(argument: &str, a: &PyReadonlyArray2<'_, f64>) -> PyResult<Vec<[f64; 3]>> {
    let shape = a.shape();
    if shape.len() != 2 || shape[1] != 3 {
        return Err(invalid(
            argument,
            format!("must have shape (N, 3), got {shape:?}"),
        ));
    }
    Ok(a.as_array()
        .rows()
        .into_iter()
        .map(|r| [r[0], r[1], r[2]])
        .collect())
}

/// `[f64; 3]` → a new numpy array of shape (3,).
pub fn vec3_out<'py>(py: Python<'py>, v: [f64; 3]) -> Bound<'py, PyArray1<f64>> {
    PyArray1::from_slice(py, &v)
}

/// Row-major 3×3 → a new numpy array of shape (3, 3).
pub fn mat3_out<'py>(py: Python<'py>, m: [[f64; 3]; 3]) -> Bound<'py, PyArray2<f64>> {
    use numpy::IntoPyArray;
    numpy::ndarray::Array2::from_shape_fn((3, 3), |(i, j)| m[i][j]).into_pyarray(py)
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

/// A new zero-filled float64 array of shape `dims` (an output buffer for a batch kernel).
pub fn zeros<'py>(py: Python<'py>, dims: &[usize]) -> Bound<'py, numpy::PyArrayDyn<f64>> {
    numpy::PyArrayDyn::<f64>::zeros(py, numpy::IxDyn(dims), false)
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

/// A flat row-major vector of `3·N` values → a new numpy array of shape (N, 3).
pub fn rows3_out(py: Python<'_>, flat: Vec<f64>) -> PyResult<Bound<'_, PyArray2<f64>>> {
    use numpy::PyArrayMethods;
    let n = flat.len() / 3;
    PyArray1::from_vec(py, flat).reshape([n, 3])
}

/// A flat row-major vector of `9·N` values → a new numpy array of shape (N, 3, 3).
pub fn mats3_out(py: Python<'_>, flat: Vec<f64>) -> PyResult<Bound<'_, numpy::PyArray3<f64>>> {
    use numpy::PyArrayMethods;
    let n = flat.len() / 9;
    PyArray1::from_vec(py, flat).reshape([n, 3, 3])
}
