//! Bindings of `poinsot::rotation`: Euler angles (any of the 24 conventions), Euler's theorem,
//! Chasles' screw and the Euler-angle kinematics (the unit's 2.98–2.99).

use crate::args::{flag, matrix, number, text, vector, Flag, Number, Numbers, Text};
use crate::convert::{mat_out, renamed, vec_out, Out};
use crate::fields;
use poinsot::rotation::{self as rot, EulerSequence, Frame};
use wasm_bindgen::prelude::wasm_bindgen;

/// The sequence `seq` (a string), intrinsic or extrinsic (a boolean).
fn sequence(seq: &Text, intrinsic: &Flag) -> Out<EulerSequence> {
    Ok(EulerSequence::new(
        &text("seq", seq)?,
        flag("intrinsic", intrinsic)?,
    )?)
}

/// Euler angles of a rotation matrix, with the gimbal-lock flag.
#[wasm_bindgen]
#[derive(Debug, Clone, PartialEq)]
pub struct EulerAngles {
    angles: Vec<f64>,
    gimbal_lock: bool,
}

#[wasm_bindgen]
impl EulerAngles {
    /// The three angles (rad); at gimbal lock the third is set to zero (the core's convention).
    #[wasm_bindgen(getter)]
    pub fn angles(&self) -> Vec<f64> {
        self.angles.clone()
    }
    /// Whether the middle angle sits at its singular value (only the sum or difference of the
    /// outer two is then determined).
    #[wasm_bindgen(getter, js_name = gimbalLock)]
    pub fn gimbal_lock(&self) -> bool {
        self.gimbal_lock
    }
}

/// Functions of arrays of numbers and of an Euler sequence: `in_sequence! { " doc" jsName
/// rust_name(arg: kind, ...) -> Output = |sequence| body; ... }` is, for each entry, a
/// `#[wasm_bindgen] pub fn rust_name(arg, ..., seq, intrinsic) -> Out<Output>` that converts
/// each array with `args::kind` (`triple`, `vector`, `matrix`), then `seq` (a string) and
/// `intrinsic` (a boolean) to the [`EulerSequence`] `sequence`, and returns `body`. Doc lines are
/// string literals (see `crate::calls!`).
macro_rules! in_sequence {
    ($($($doc:literal)* $js:ident $name:ident($($arg:ident: $kind:ident),+) -> $out:ty = |$seq:ident| $body:expr;)*) => {
        $(
            $(#[doc = $doc])*
            #[wasm_bindgen(js_name = $js)]
            pub fn $name(
                $(#[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] $arg: Numbers,)+
                #[wasm_bindgen(unchecked_param_type = "string")] seq: Text,
                #[wasm_bindgen(unchecked_param_type = "boolean")] intrinsic: Flag,
            ) -> Out<$out> {
                $(let $arg = crate::args::$kind(stringify!($arg), &$arg)?;)+
                let $seq = sequence(&seq, &intrinsic)?;
                $body
            }
        )*
    };
}

in_sequence! {
    " The rotation matrix (9 numbers, row-major) of Euler `angles` (rad, 3 numbers) in the"
    " sequence `seq` (three lowercase axis letters, e.g. `\"zxz\"`, the unit's φ, θ, ψ), intrinsic or"
    " extrinsic (`intrinsic`, a boolean): intrinsic `R = R_a(α) R_b(β) R_c(γ)`, extrinsic"
    " `R = R_c(γ) R_b(β) R_a(α)`."
    eulerToMatrix euler_to_matrix(angles: triple) -> Vec<f64> = |seq| {
        Ok(mat_out(&rot::euler_to_matrix(angles, seq)?))
    };
    " The Euler angles of the rotation matrix `r` (9 numbers, row-major; must be a proper rotation)"
    " in the sequence `seq`, intrinsic or extrinsic."
    matrixToEuler matrix_to_euler(r: matrix) -> EulerAngles = |seq| {
        let e = rot::matrix_to_euler(&r, seq).map_err(renamed("R", "r"))?;
        Ok(EulerAngles {
            angles: e.angles.to_vec(),
            gimbal_lock: e.gimbal_lock,
        })
    };
    " The body-frame angular velocity (rad/s, 3 numbers) for Euler `angles` (rad) and their time"
    " derivatives `rates` (rad/s) in sequence `seq` (the unit's 2.99 for intrinsic zxz)."
    bodyAngularVelocity body_angular_velocity(angles: triple, rates: triple) -> Vec<f64> = |seq| {
        Ok(vec_out(&rot::body_angular_velocity(angles, rates, seq)?))
    };
    " The Euler-angle rates (rad/s) that produce the body angular velocity `omega_body` (rad/s) at"
    " `angles` (rad); throws a `GimbalLockError` at the singular angles of the sequence."
    eulerRates euler_rates(angles: triple, omega_body: vector) -> Vec<f64> = |seq| {
        Ok(rot::euler_rates(angles, &omega_body, seq, Frame::Body)?.to_vec())
    };
}

/// Euler's theorem: `[ax, ay, az, angle]`, the unit axis and the angle (rad, in [0, π]) of the
/// rotation matrix `r` (9 numbers, row-major).
#[wasm_bindgen(js_name = rotationAxis)]
pub fn rotation_axis(
    #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] r: Numbers,
) -> Out<Vec<f64>> {
    let (axis, angle) = rot::rotation_axis(&matrix("r", &r)?).map_err(renamed("R", "r"))?;
    Ok(vec![axis.x, axis.y, axis.z, angle])
}

/// Chasles' screw of a displacement `x ↦ R x + t`.
#[wasm_bindgen]
#[derive(Debug, Clone, PartialEq)]
pub struct Screw {
    inner: rot::Screw,
}

fields!(Screw {
    " Unit direction of the screw axis."
    axis axis -> vector(axis);
    " The point of the axis nearest the origin (m)."
    point point -> vector(point);
    " Rotation angle about the axis (rad, in [0, π])."
    angle angle -> number(angle);
    " Signed translation along the axis (m)."
    slide slide -> number(slide);
    " `slide / angle` (m/rad); `Infinity` for a pure translation (never NaN)."
    pitch pitch -> number(pitch);
});

#[wasm_bindgen]
impl Screw {
    /// The pose reached at fraction `s` of the screw motion (rotation by `s·angle` about the
    /// axis while sliding `s·slide` along it; core `Screw::displacement_at`, Python
    /// `Screw.displacement_at`): 12 numbers, `R(s)` row-major then `t(s)` (m). `s = 0` is the
    /// identity, `s = 1` the displacement the screw was built from.
    #[wasm_bindgen(js_name = displacementAt)]
    pub fn displacement_at(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] s: Number,
    ) -> Out<Vec<f64>> {
        let (r, t) = self.inner.displacement_at(number("s", &s)?)?;
        let mut out = mat_out(&r);
        out.extend(vec_out(&t));
        Ok(out)
    }
}

/// Chasles' theorem for the displacement `x ↦ R x + t` (`r` 9 numbers row-major, `t` 3 numbers, m).
#[wasm_bindgen(js_name = screwAxis)]
pub fn screw_axis(
    #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] r: Numbers,
    #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] t: Numbers,
) -> Out<Screw> {
    let s = rot::screw_axis(&matrix("r", &r)?, &vector("t", &t)?).map_err(renamed("R", "r"))?;
    Ok(Screw { inner: s })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convert::refused;

    #[test]
    fn zxz_matches_the_product_of_elementary_rotations() {
        let (phi, theta, psi) = (0.3, 0.7, -1.1);
        let r = euler_to_matrix(vec![phi, theta, psi], "zxz".into(), true).unwrap();
        let expect = rot::rot_z(phi) * rot::rot_x(theta) * rot::rot_z(psi);
        assert_eq!(r, mat_out(&expect));
        let back = matrix_to_euler(r.clone(), "zxz".into(), true).unwrap();
        assert!(!back.gimbal_lock());
        for (a, b) in back.angles().iter().zip([phi, theta, psi]) {
            assert!((a - b).abs() < 1e-14, "{a} vs {b}");
        }
    }

    #[test]
    fn gimbal_lock_is_reported_and_rates_throw() {
        let r = euler_to_matrix(vec![0.4, 0.0, 0.2], "zxz".into(), true).unwrap();
        assert!(matrix_to_euler(r, "zxz".into(), true)
            .unwrap()
            .gimbal_lock());
        let e =
            euler_rates(vec![0.4, 0.0, 0.2], vec![0.0, 0.0, 1.0], "zxz".into(), true).unwrap_err();
        assert_eq!(e.name, "GimbalLockError");
    }

    #[test]
    fn bad_input_is_an_error_not_nan() {
        refused(
            euler_to_matrix(vec![f64::NAN, 0.0, 0.0], "zxz".into(), true),
            "angles",
        );
        assert!(euler_to_matrix(vec![0.0; 3], "zqz".into(), true).is_err());
        assert_eq!(
            rotation_axis(vec![2.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0])
                .unwrap_err()
                .name,
            "InvalidRotationError"
        );
    }

    #[test]
    fn displacement_at_ends_and_errors() {
        let r = euler_to_matrix(vec![0.4, 1.1, -0.7], "zxz".into(), true).unwrap();
        let t = [0.8, -1.5, 2.0];
        let s = screw_axis(r.clone(), t.to_vec()).unwrap();
        let d0 = s.displacement_at(0.0).unwrap();
        assert_eq!(&d0[..9], &mat_out(&poinsot::Mat3::identity())[..]);
        assert_eq!(&d0[9..], vec![0.0; 3]);
        let d1 = s.displacement_at(1.0).unwrap();
        assert_eq!(d1.len(), 12);
        for (a, b) in d1.iter().zip(r.iter().chain(&t)) {
            assert!((a - b).abs() < 1e-14, "{a} vs {b}");
        }
        let e = s.displacement_at(f64::NAN).unwrap_err();
        assert_eq!(e.name, "PoinsotError");
        assert!(e.message.starts_with("s: "), "{}", e.message);
    }

    #[test]
    fn pure_translation_has_infinite_pitch() {
        let id = mat_out(&poinsot::Mat3::identity());
        let s = screw_axis(id, vec![0.0, 0.0, 2.0]).unwrap();
        assert!(s.pitch().is_infinite());
        assert!((s.slide() - 2.0).abs() < 1e-15);
    }

    /// Results beyond the doubles are refused by the core, naming the argument (this binding
    /// guarded them itself before).
    #[test]
    fn overflowing_results_name_the_argument() {
        let starts = |r: Out<Vec<f64>>, prefix: &str| {
            let e = r.unwrap_err();
            assert_eq!(e.name, "PoinsotError");
            assert!(e.message.starts_with(prefix), "{}", e.message);
        };
        let z = || "zxz".to_string();
        starts(
            body_angular_velocity(vec![0.1, 0.2, 0.3], vec![1e308; 3], z(), true),
            "rates: the angular velocity overflows",
        );
        starts(
            euler_rates(vec![0.1, 1e-3, 0.3], vec![1e308, 1e308, 0.0], z(), true),
            "omega_body: the Euler-angle rates overflow",
        );
        let id = mat_out(&poinsot::Mat3::identity());
        let e = screw_axis(id, vec![1e308; 3]).unwrap_err();
        assert!(e.message.starts_with("t: "), "{}", e.message);
        let r = euler_to_matrix(vec![0.1, 0.2, 0.3], z(), true).unwrap();
        starts(
            screw_axis(r, vec![1.0, 2.0, 3.0])
                .unwrap()
                .displacement_at(1e308),
            "s: ",
        );
    }
}
