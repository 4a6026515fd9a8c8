//! The one place where core errors and panics become Python exceptions.
//!
//! The exception tree is rooted at `poinsot.PoinsotError`, which is also a `ValueError`:
//!
//! ```text
//! ValueError
//! └── PoinsotError
//!     ├── InvalidInertiaError
//!     ├── InvalidRotationError
//!     ├── InvalidMeshError
//!     ├── GimbalLockError
//!     ├── IntegrationError
//!     └── InternalError      a panic (a bug), caught by [`guard`]
//! ```
//!
//! Every export goes through [`guard`] (the `#[export]` attribute of `poinsot-py-macros` wraps
//! each `#[pyfunction]` and each method of a `#[pymethods]` block in it), so no panic reaches
//! Python as pyo3's `PanicException`.
use std::any::Any;
use std::panic::{catch_unwind, AssertUnwindSafe};

use poinsot::{Error, ErrorKind};
use poinsot_py_macros::export;
use pyo3::create_exception;
use pyo3::exceptions::{PyKeyboardInterrupt, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyType;

/// The exception classes, `Name: Base = "docstring";` each (pyo3's `create_exception!`).
macro_rules! exceptions {
    ($($name:ident: $base:ty = $doc:literal;)+) => {
        $(create_exception!(poinsot, $name, $base, $doc);)+
    };
}

exceptions! {
    PoinsotError: PyValueError = "Bad input or an impossible request to poinsot (also a ValueError). The message names the argument and the violated condition.";
    InvalidInertiaError: PoinsotError = "An inertia tensor that no body can have (asymmetric, negative moment, triangle inequality violated).";
    InvalidRotationError: PoinsotError = "A matrix that is not a proper rotation (not orthonormal within tolerance, or det != +1).";
    InvalidMeshError: PoinsotError = "A triangle mesh that does not bound a solid (open, non-manifold, inside-out or degenerate).";
    GimbalLockError: PoinsotError = "Euler-angle rates requested at the singular angles of their sequence (gimbal lock).";
    IntegrationError: PoinsotError = "A numerical integration diverged or could not reach its tolerance.";
    InternalError: PoinsotError = "A bug in poinsot: the compiled core panicked (it validates its input first, so this should never happen). Raised instead of ``pyo3_runtime.PanicException``, which would escape ``except Exception``; the message asks for a report.";
}

/// The exception class named `name` (one of the core's [`ErrorKind::class_name`]s): the types
/// created above, or Python's `KeyboardInterrupt` (a monitor stopped the run without keeping a
/// Python exception — not expected: the Python monitor keeps the KeyboardInterrupt or the
/// callback's exception).
fn class<'py>(py: Python<'py>, name: &str) -> Bound<'py, PyType> {
    match name {
        "InvalidInertiaError" => py.get_type::<InvalidInertiaError>(),
        "InvalidRotationError" => py.get_type::<InvalidRotationError>(),
        "InvalidMeshError" => py.get_type::<InvalidMeshError>(),
        "GimbalLockError" => py.get_type::<GimbalLockError>(),
        "IntegrationError" => py.get_type::<IntegrationError>(),
        "KeyboardInterrupt" => py.get_type::<PyKeyboardInterrupt>(),
        _ => py.get_type::<PoinsotError>(),
    }
}

/// Converts a core error to the Python exception of its kind's class (the core's table,
/// [`ErrorKind::class_name`]).
pub fn to_py(e: Error) -> PyErr {
    let msg = e.to_string();
    Python::attach(|py| PyErr::from_type(class(py, e.kind.class_name()), msg))
}

/// The core's table of exception classes: `[(kind, class name)]` for every kind (the same
/// table the WebAssembly binding's `errorClasses()` returns).
#[export]
fn error_classes() -> Vec<(&'static str, &'static str)> {
    ErrorKind::ALL
        .iter()
        .map(|k| (k.name(), k.class_name()))
        .collect()
}

/// `Result<T, poinsot::Error>` → `PyResult<T>`.
pub trait IntoPy<T> {
    /// Maps the error with [`to_py`].
    fn py(self) -> PyResult<T>;
}

impl<T> IntoPy<T> for poinsot::Result<T> {
    fn py(self) -> PyResult<T> {
        self.map_err(to_py)
    }
}

/// A `PoinsotError` naming `argument` (for conversion errors found in the bindings, e.g. shapes).
pub fn invalid(argument: &str, message: impl Into<String>) -> PyErr {
    to_py(Error::invalid(argument, message))
}

/// Runs `f`, the body of the export `class.name` (`class` empty for a module function, `name`
/// empty for a constructor), turning a panic anywhere below it — in the binding, in the core,
/// on a thread of the core's pool (rayon hands the panic back to the caller) — into
/// [`InternalError`]: the one panic guard of the binding, through which every export goes
/// (`#[export]`). Free when nothing panics (`catch_unwind` costs nothing on the normal path).
#[inline(always)]
pub fn guard<T>(
    class: &'static str,
    name: &'static str,
    f: impl FnOnce() -> PyResult<T>,
) -> PyResult<T> {
    catch_unwind(AssertUnwindSafe(f)).unwrap_or_else(|payload| Err(panicked(class, name, payload)))
}

/// The [`InternalError`] of a panic: `"class.name: internal error in poinsot's core (message);
/// this is a bug, please report it with the call that caused it"`.
#[cold]
fn panicked(class: &str, name: &str, payload: Box<dyn Any + Send>) -> PyErr {
    let what = payload
        .downcast_ref::<String>()
        .map(String::as_str)
        .or_else(|| payload.downcast_ref::<&str>().copied())
        .unwrap_or("a panic without a message");
    let sep = if class.is_empty() || name.is_empty() {
        ""
    } else {
        "."
    };
    InternalError::new_err(format!(
        "{class}{sep}{name}: internal error in poinsot's core ({what}); this is a bug, please \
         report it with the call that caused it"
    ))
}

/// Registers the exception types on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    for kind in ErrorKind::ALL {
        let name = kind.class_name();
        if name != "KeyboardInterrupt" {
            m.add(name, class(py, name))?;
        }
    }
    m.add("InternalError", py.get_type::<InternalError>())?;
    add_functions!(m; error_classes);
    Ok(())
}
