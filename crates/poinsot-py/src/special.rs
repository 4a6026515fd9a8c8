//! Bindings of `poinsot::special` (conversion only).
use numpy::{PyArray2, PyReadonlyArray1};
use poinsot::special::{self, Jacobi};
use poinsot_py_macros::export;
use pyo3::prelude::*;

use crate::control::map_each;
use crate::errors::IntoPy;
use crate::frames::{rows_out, vec_in};

/// sn, cn, dn, am of u (N,) for parameter m → (N, 4).
#[export]
fn special_jacobi<'py>(
    py: Python<'py>,
    u: PyReadonlyArray1<'py, f64>,
    m: f64,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let u = vec_in(&u);
    let j = Jacobi::new(m).py()?;
    let rows = map_each(py, &u, |&x| {
        j.eval_checked(x).map(|v| [v.sn, v.cn, v.dn, v.am])
    })?;
    Ok(rows_out(py, &rows))
}

/// Legendre's elliptic integral `kind` ("K", "E", "PI", "F", "EINC", "PIINC") at (phi, n, m).
#[export]
fn special_elliptic(kind: &str, phi: f64, n: f64, m: f64) -> PyResult<f64> {
    special::elliptic(kind, phi, n, m).py()
}

/// Registers this file's functions on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    add_functions!(m; special_jacobi, special_elliptic);
    Ok(())
}
