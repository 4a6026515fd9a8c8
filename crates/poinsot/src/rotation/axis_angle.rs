//! Euler's theorem: every rotation (a displacement with one point fixed) is a rotation by one
//! angle about one axis through the fixed point (the unit's section "Euler's Theorem").
//!
//! [`rotation_axis`] finds the axis and angle of a matrix, [`axis_angle_to_matrix`] builds the
//! matrix back (Rodrigues' formula).

use crate::error::{check_finite, Error, Result};
use crate::rotation::matrix::{rotation_to_convert, row_major};
use crate::rotation::quaternion::matrix_to_quaternion_unchecked;
use crate::{Mat3, Vec3};

/// The conventional axis returned for the identity (angle 0), whose axis is undefined: `+z`.
pub const IDENTITY_AXIS: [f64; 3] = [0.0, 0.0, 1.0];

/// Euler's theorem: the unit axis `n` and angle `θ ∈ [0, π]` (rad) with `R = R_n(θ)`.
///
/// Accurate to round-off for every angle: the angle is `2 atan2(|q_v|, q_w)` of the quaternion
/// built with Shepperd's method, so neither `acos((tr R − 1)/2)` (which loses half the digits
/// for small angles) nor the skew part alone (which vanishes at `π`) is used. At `θ = π` both
/// `n` and `−n` are valid; the sign follows the quaternion's canonical sign (first non-zero
/// component positive). The identity gives angle 0 and the conventional axis
/// [`IDENTITY_AXIS`] (`+z`).
///
/// `r` is checked with [`crate::rotation::ROTATION_MATRIX_TOL`]; errors name `"R"`. A matrix off
/// orthonormal by more than [`crate::rotation::NEAREST_ROTATION_DEFECT`] gives the axis and
/// angle of the nearest rotation.
pub fn rotation_axis(r: &Mat3) -> Result<(Vec3, f64)> {
    let (n, angle) = rotation_axis_unchecked(&rotation_to_convert("R", &row_major(r))?);
    Ok((Vec3::from(n), angle))
}

/// Axis and angle of a row-major rotation matrix (assumed valid).
#[inline]
pub(crate) fn rotation_axis_unchecked(m: &[f64; 9]) -> ([f64; 3], f64) {
    let q = matrix_to_quaternion_unchecked(m);
    // hypot: no underflow of the squares for angles below 1e-154.
    let s = q[1].hypot(q[2]).hypot(q[3]);
    if s == 0.0 {
        return (IDENTITY_AXIS, 0.0);
    }
    ([q[1] / s, q[2] / s, q[3] / s], 2.0 * s.atan2(q[0]))
}

/// Rodrigues' formula: the rotation by `angle` (rad, any value, right-hand rule) about `axis`
/// (any non-zero length; normalised here):
/// `R = I + sin θ K + (1 − cos θ) K²` with `K` the cross-product matrix of the unit axis, and
/// `1 − cos θ` computed as `2 sin²(θ/2)` for accuracy at small angles.
///
/// Errors: non-finite input ([`Error::invalid`] naming `"axis"` or `"angle"`), zero axis
/// ([`Error::invalid`] naming `"axis"`).
pub fn axis_angle_to_matrix(axis: &Vec3, angle: f64) -> Result<Mat3> {
    check_finite("axis", axis.as_slice())?;
    check_finite("angle", &[angle])?;
    let n = axis.norm();
    if n == 0.0 {
        return Err(Error::invalid(
            "axis",
            "must be a non-zero vector (a rotation axis has a direction), got [0, 0, 0]",
        ));
    }
    Ok(rodrigues(&(axis / n), angle))
}

/// Rodrigues' formula for a unit axis.
#[inline]
pub(crate) fn rodrigues(n: &Vec3, angle: f64) -> Mat3 {
    let s = angle.sin();
    let h = (0.5 * angle).sin();
    let one_minus_c = 2.0 * h * h;
    let k = Mat3::new(0.0, -n.z, n.y, n.z, 0.0, -n.x, -n.y, n.x, 0.0);
    Mat3::identity() + k * s + k * k * one_minus_c
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rotation::{rot_x, rot_y};
    use crate::ErrorKind;

    #[test]
    fn tiny_angles_keep_relative_accuracy() {
        for theta in [1e-8, 1e-12, 1e-300] {
            let (n, a) = rotation_axis(&rot_y(theta)).unwrap();
            assert!((a - theta).abs() <= 1e-15 * theta, "{a} vs {theta}");
            assert!((n - Vec3::y()).norm() < 1e-15);
        }
    }

    #[test]
    fn identity_and_half_turns() {
        assert_eq!(rotation_axis(&Mat3::identity()).unwrap(), (Vec3::z(), 0.0));
        let (n, a) = rotation_axis(&rot_x(std::f64::consts::PI)).unwrap();
        assert!((a - std::f64::consts::PI).abs() < 1e-15 && (n - Vec3::x()).norm() < 1e-15);
        let near = std::f64::consts::PI - 1e-9;
        let (n, a) = rotation_axis(&rot_x(-near)).unwrap();
        assert!(
            (a - near).abs() < 4e-16 && (n + Vec3::x()).norm() < 1e-15,
            "{a} {n}"
        );
    }

    #[test]
    fn rodrigues_round_trip_and_zero_axis() {
        let axis = Vec3::new(1.0, -2.0, 0.5);
        let r = axis_angle_to_matrix(&axis, 2.5).unwrap();
        let (n, a) = rotation_axis(&r).unwrap();
        assert!((n - axis.normalize()).norm() < 1e-15 && (a - 2.5).abs() < 1e-15);
        let e = axis_angle_to_matrix(&Vec3::zeros(), 1.0).unwrap_err();
        assert_eq!(e.kind, ErrorKind::InvalidArgument);
        assert!(e.to_string().starts_with("axis: "), "{e}");
    }
}
