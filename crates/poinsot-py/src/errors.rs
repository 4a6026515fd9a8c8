//! The one place where core errors become Python exceptions.
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
//!     └── IntegrationError
//! ```
use poinsot::{Error, ErrorKind};
use pyo3::create_exception;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

create_exception!(poinsot, PoinsotError, PyValueError, "Bad input or an impossible request to poinsot (also a ValueError). The message names the argument and the violated condition.");
create_exception!(poinsot, InvalidInertiaError, PoinsotError, "An inertia tensor that no body can have (asymmetric, negative moment, triangle inequality violated).");
create_exception!(
    poinsot,
    InvalidRotationError,
    PoinsotError,
    "A matrix that is not a proper rotation (not orthonormal within tolerance, or det != +1)."
);
create_exception!(
    poinsot,
    InvalidMeshError,
    PoinsotError,
    "A triangle mesh that does not bound a solid (open, non-manifold, inside-out or degenerate)."
);
create_exception!(
    poinsot,
    GimbalLockError,
    PoinsotError,
    "Euler-angle rates requested at the singular angles of their sequence (gimbal lock)."
);
create_exception!(
    poinsot,
    IntegrationError,
    PoinsotError,
    "A numerical integration diverged or could not reach its tolerance."
);

/// Converts a core error to the matching Python exception.
pub fn to_py(e: Error) -> PyErr {
    let msg = e.to_string();
    match e.kind {
        ErrorKind::InvalidArgument => PoinsotError::new_err(msg),
        ErrorKind::InvalidInertia => InvalidInertiaError::new_err(msg),
        ErrorKind::InvalidRotation => InvalidRotationError::new_err(msg),
        ErrorKind::InvalidMesh => InvalidMeshError::new_err(msg),
        ErrorKind::GimbalLock => GimbalLockError::new_err(msg),
        ErrorKind::Diverged => IntegrationError::new_err(msg),
        // A monitor stopped the run without keeping a Python exception (not expected: the
        // Python monitor keeps the KeyboardInterrupt or the callback's exception).
        ErrorKind::Interrupted => pyo3::exceptions::PyKeyboardInterrupt::new_err(msg),
    }
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

/// Registers the exception types on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("PoinsotError", py.get_type::<PoinsotError>())?;
    m.add("InvalidInertiaError", py.get_type::<InvalidInertiaError>())?;
    m.add(
        "InvalidRotationError",
        py.get_type::<InvalidRotationError>(),
    )?;
    m.add("InvalidMeshError", py.get_type::<InvalidMeshError>())?;
    m.add("GimbalLockError", py.get_type::<GimbalLockError>())?;
    m.add("IntegrationError", py.get_type::<IntegrationError>())?;
    Ok(())
}
