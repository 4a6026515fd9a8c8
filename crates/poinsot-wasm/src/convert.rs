//! Conversion between JavaScript's flat arrays and the core's types, and the error mapping.
//!
//! Layouts: a vector is 3 numbers; a matrix is 9 numbers **row-major** (`[R00, R01, R02, R10,
//! ...]`, as the core's batch kernels); a quaternion is 4 numbers scalar-first `[w, x, y, z]`.

use poinsot::{Error, ErrorKind, Mat3, Vec3};
use wasm_bindgen::prelude::wasm_bindgen;
use wasm_bindgen::JsValue;

/// An error on its way to JavaScript: the exception class name and the core's message.
#[derive(Debug, Clone, PartialEq)]
pub struct Failure {
    /// The JavaScript `Error.name`: the Python exception class of the same kind (the core's
    /// table, [`ErrorKind::class_name`]), or `"TypeError"`
    /// for an argument of the wrong JavaScript type (thrown as a real `TypeError`).
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

    /// A wrong JavaScript type (a string where a number is expected, ...): a `TypeError` whose
    /// message names `argument`, as Python raises `TypeError` for a wrong type.
    pub fn type_error(argument: &str, condition: &str) -> Self {
        Failure {
            name: "TypeError",
            message: format!("{argument}: {condition}"),
        }
    }
}

/// The core's table of exception classes: `[kind, class name]` for every kind
/// (`[["InvalidArgument", "PoinsotError"], ..., ["Diverged", "IntegrationError"], ...]`), the
/// `name` of the error each kind throws — the same table as `poinsot._core.error_classes()`.
#[wasm_bindgen(js_name = errorClasses, unchecked_return_type = "[string, string][]")]
pub fn error_classes() -> js_sys::Array {
    ErrorKind::ALL
        .iter()
        .map(|k| js_sys::Array::of2(&k.name().into(), &k.class_name().into()))
        .collect()
}

impl From<Error> for Failure {
    fn from(e: Error) -> Self {
        Failure {
            name: e.kind.class_name(),
            message: e.to_string(),
        }
    }
}

/// Maps a core error about `from` (the core's and the Python API's name of an argument, `"R"`) to
/// the same error about `to` (the binding's lower-case name of it, `r`): JavaScript's names are
/// lower case where Python keeps the unit's capital.
pub fn renamed(from: &'static str, to: &'static str) -> impl Fn(Error) -> Failure {
    move |e| Failure::from(e.renamed(from, to))
}

/// Attributes a core error to the call's `arguments` (`"i1, i3, mgl, p_phi, p_psi, energy"`)
/// unless it already names one of them: the core names the internal quantity where a
/// computation broke down (`m`, the Jacobi parameter; `theta`, a root of the cubic), which is not
/// an argument of the JavaScript call; the message keeps that name after the arguments.
pub fn attributed(arguments: &'static str) -> impl Fn(Error) -> Failure {
    move |mut e: Error| {
        if !arguments
            .split(", ")
            .any(|a| a.eq_ignore_ascii_case(&e.argument))
        {
            e.message = format!("{}: {}", e.argument, e.message);
            e.argument = arguments.into();
        }
        Failure::from(e)
    }
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.name, self.message)
    }
}

impl From<Failure> for JsValue {
    fn from(f: Failure) -> JsValue {
        if f.name == "TypeError" {
            return js_sys::TypeError::new(&f.message).into();
        }
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

/// The 4 components of the quaternion `q`, `[w, x, y, z]`.
pub fn quat_out(q: &[f64; 4]) -> Vec<f64> {
    q.to_vec()
}

/// The 9 components of `m`, row-major.
pub fn mat_out(m: &Mat3) -> Vec<f64> {
    (0..3)
        .flat_map(|i| (0..3).map(move |j| m[(i, j)]))
        .collect()
}

/// Getters that return the core's number of the same name unchanged: `getters!(Type { " doc"
/// jsName rust_name; ... })` is one `#[wasm_bindgen] impl Type` block of
/// `#[wasm_bindgen(getter, js_name = jsName)] pub fn rust_name(&self) -> f64 {
/// self.inner.rust_name() }`, each with its doc lines (string literals, not `///`: wasm-bindgen
/// writes a doc comment passed through `macro_rules!` into the TypeScript declarations as
/// `r" ..."`). The core promises these numbers finite. `getters!(Type? { ... })` is the same for
/// the core's fallible numbers: `pub fn rust_name(&self) -> Out<f64> { Ok(self.inner.rust_name()?) }`.
macro_rules! getters {
    ($ty:ident? { $($($doc:literal)* $js:ident $name:ident;)* }) => {
        #[wasm_bindgen::prelude::wasm_bindgen]
        impl $ty {
            $(
                $(#[doc = $doc])*
                #[wasm_bindgen(getter, js_name = $js)]
                pub fn $name(&self) -> crate::convert::Out<f64> {
                    Ok(self.inner.$name()?)
                }
            )*
        }
    };
    ($ty:ident { $($($doc:literal)* $js:ident $name:ident;)* }) => {
        #[wasm_bindgen::prelude::wasm_bindgen]
        impl $ty {
            $(
                $(#[doc = $doc])*
                #[wasm_bindgen(getter, js_name = $js)]
                pub fn $name(&self) -> f64 {
                    self.inner.$name()
                }
            )*
        }
    };
}
pub(crate) use getters;

/// Methods of one time `t` (s, a JavaScript number, finite) that return the core's vector or
/// quaternion at `t` as numbers: `at_time!(Type { " doc"
/// jsName rust_name -> conversion; ... })` is one `#[wasm_bindgen] impl Type` block of
/// `pub fn rust_name(&self, t) -> Out<Vec<f64>>`, `conversion(&self.inner.rust_name(t)?)`.
macro_rules! at_time {
    ($ty:ident { $($($doc:literal)* $js:ident $name:ident -> $out:path;)* }) => {
        #[wasm_bindgen::prelude::wasm_bindgen]
        impl $ty {
            $(
                $(#[doc = $doc])*
                #[wasm_bindgen(js_name = $js)]
                pub fn $name(
                    &self,
                    #[wasm_bindgen(unchecked_param_type = "number")] t: crate::args::Number,
                ) -> Out<Vec<f64>> {
                    Ok($out(&self.inner.$name(crate::free::time(&t)?)?))
                }
            )*
        }
    };
}
pub(crate) use at_time;

/// Test helper: the failure of `result`, which must be an error whose message starts with
/// `prefix` (the argument it names and the start of the condition).
#[cfg(test)]
#[track_caller]
pub(crate) fn refused<T: std::fmt::Debug>(result: Out<T>, prefix: &str) -> Failure {
    let e = result.unwrap_err();
    assert!(e.message.starts_with(prefix), "{e}");
    e
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
        let e = refused(
            vec3("omega0", &[1.0, 2.0]),
            "omega0: must hold 3 numbers, got 2",
        );
        assert_eq!(e.name, "PoinsotError");
        refused(mat3("R", &[0.0; 8]), "R: must hold 9");
        refused(quat("attitude0", &[1.0; 3]), "attitude0: must hold 4");
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
        // One table with the Python binding: a diverged run is an IntegrationError in both.
        assert_eq!(
            Failure::from(Error::diverged("t", "x")).name,
            "IntegrationError"
        );
    }
}
