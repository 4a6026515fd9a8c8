//! Conversion between JavaScript's flat arrays and the core's types, and the error mapping.
//!
//! Layouts: a vector is 3 numbers; a matrix is 9 numbers **row-major** (`[R00, R01, R02, R10,
//! ...]`, as the core's batch kernels); a quaternion is 4 numbers scalar-first `[w, x, y, z]`.

use poinsot::{Error, ErrorKind, Mat3, Vec3};
use wasm_bindgen::JsValue;

/// An error on its way to JavaScript: the exception class name and the core's message.
#[derive(Debug, Clone, PartialEq)]
pub struct Failure {
    /// The JavaScript `Error.name`: the Python exception class of the same kind.
    pub name: &'static str,
    /// The core's message, `"argument: condition"`.
    pub message: String,
}

/// The result type of every fallible export.
pub type Out<T> = std::result::Result<T, Failure>;

impl Failure {
    /// An invalid-argument failure naming `argument` and the violated `condition`.
    pub fn invalid(argument: &str, condition: &str) -> Self {
        Failure::from(Error::invalid(argument, condition))
    }
}

/// The Python exception class name of a core error kind (the browser shows the same names).
pub fn class_name(kind: ErrorKind) -> &'static str {
    match kind {
        ErrorKind::InvalidArgument | ErrorKind::Diverged | ErrorKind::Interrupted => "PoinsotError",
        ErrorKind::InvalidInertia => "InvalidInertiaError",
        ErrorKind::InvalidRotation => "InvalidRotationError",
        ErrorKind::InvalidMesh => "InvalidMeshError",
        ErrorKind::GimbalLock => "GimbalLockError",
    }
}

impl From<Error> for Failure {
    fn from(e: Error) -> Self {
        Failure {
            name: class_name(e.kind),
            message: e.to_string(),
        }
    }
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.name, self.message)
    }
}

impl From<Failure> for JsValue {
    fn from(f: Failure) -> JsValue {
        let e = js_sys::Error::new(&f.message);
        e.set_name(f.name);
        e.into()
    }
}

/// The 3-vector in `values`, or an error naming `argument` if it does not hold exactly 3 numbers.
/// Finiteness is left to the core, which names the argument itself.
pub fn vec3(argument: &str, values: &[f64]) -> Out<Vec3> {
    match values {
        [x, y, z] => Ok(Vec3::new(*x, *y, *z)),
        _ => Err(Failure::invalid(
            argument,
            &format!("must hold 3 numbers, got {}", values.len()),
        )),
    }
}

/// The three numbers in `values` as an array (angles, moments, sides, semi-axes).
pub fn array3(argument: &str, values: &[f64]) -> Out<[f64; 3]> {
    vec3(argument, values).map(|v| [v.x, v.y, v.z])
}

/// The row-major 3×3 matrix in `values` (9 numbers).
pub fn mat3(argument: &str, values: &[f64]) -> Out<Mat3> {
    if values.len() != 9 {
        return Err(Failure::invalid(
            argument,
            &format!(
                "must hold 9 numbers (a row-major 3×3 matrix), got {}",
                values.len()
            ),
        ));
    }
    Ok(Mat3::from_row_slice(values))
}

/// The scalar-first quaternion `[w, x, y, z]` in `values` (4 numbers).
pub fn quat(argument: &str, values: &[f64]) -> Out<[f64; 4]> {
    match values {
        [w, x, y, z] => Ok([*w, *x, *y, *z]),
        _ => Err(Failure::invalid(
            argument,
            &format!("must hold 4 numbers [w, x, y, z], got {}", values.len()),
        )),
    }
}

/// The 3 components of `v` as a vector for JavaScript (a `Float64Array`).
pub fn vec_out(v: &Vec3) -> Vec<f64> {
    vec![v.x, v.y, v.z]
}

/// The 9 components of `m`, row-major.
pub fn mat_out(m: &Mat3) -> Vec<f64> {
    (0..3)
        .flat_map(|i| (0..3).map(move |j| m[(i, j)]))
        .collect()
}

/// `values` unchanged if every one is finite; otherwise an error naming `quantity`. The core
/// promises finite results for valid input, so this guard only stops a NaN reaching the page.
pub fn finite(quantity: &str, values: Vec<f64>) -> Out<Vec<f64>> {
    if values.iter().all(|v| v.is_finite()) {
        Ok(values)
    } else {
        Err(Failure {
            name: "PoinsotError",
            message: format!("{quantity}: the result is not finite"),
        })
    }
}

/// `value` if finite, otherwise an error naming `quantity` (see [`finite`]).
pub fn finite1(quantity: &str, value: f64) -> Out<f64> {
    finite(quantity, vec![value]).map(|v| v[0])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matrices_are_row_major_both_ways() {
        let values: Vec<f64> = (0..9).map(f64::from).collect();
        let m = mat3("R", &values).unwrap();
        assert_eq!(m[(0, 1)], 1.0);
        assert_eq!(m[(1, 0)], 3.0);
        assert_eq!(mat_out(&m), values);
    }

    #[test]
    fn wrong_lengths_name_the_argument() {
        let e = vec3("omega0", &[1.0, 2.0]).unwrap_err();
        assert_eq!(e.name, "PoinsotError");
        assert!(
            e.message.starts_with("omega0: must hold 3 numbers, got 2"),
            "{}",
            e.message
        );
        assert!(mat3("R", &[0.0; 8])
            .unwrap_err()
            .message
            .starts_with("R: must hold 9"));
        assert!(quat("attitude0", &[1.0; 3])
            .unwrap_err()
            .message
            .starts_with("attitude0: must hold 4"));
    }

    #[test]
    fn core_errors_keep_their_message_and_kind() {
        let f = Failure::from(Error::inertia("inertia", "must be symmetric"));
        assert_eq!(f.name, "InvalidInertiaError");
        assert_eq!(f.message, "inertia: must be symmetric");
        assert_eq!(
            Failure::from(Error::gimbal_lock("angles", "x")).name,
            "GimbalLockError"
        );
    }

    #[test]
    fn non_finite_results_never_pass() {
        assert!(finite("omega", vec![1.0, f64::NAN]).is_err());
        assert!(finite1("energy", f64::INFINITY).is_err());
        assert_eq!(finite1("energy", 2.0).unwrap(), 2.0);
    }
}
