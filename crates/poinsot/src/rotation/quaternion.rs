//! Unit quaternions, **scalar-first** `[w, x, y, z]`: the rotation by angle `θ` about unit axis
//! `n` is `q = [cos(θ/2), sin(θ/2) n_x, sin(θ/2) n_y, sin(θ/2) n_z]`, and `q` and `−q` are the
//! same rotation. The Hamilton product composes like matrices: `R(p ⊗ q) = R(p) R(q)`.

use crate::error::{check_finite, Error, Result};
use crate::rotation::matrix::{from_row_major, rotation_to_convert, row_major};
use crate::{Mat3, Vec3};

/// A quaternion, scalar first: `[w, x, y, z]`.
///
/// ```
/// use poinsot::rotation::{matrix_to_quaternion, quaternion_multiply, quaternion_to_matrix, rot_z};
/// use std::f64::consts::FRAC_PI_4;
/// // 90° about z: q = [cos 45°, 0, 0, sin 45°].
/// let q = matrix_to_quaternion(&rot_z(2.0 * FRAC_PI_4))?;
/// assert!((q[0] - FRAC_PI_4.cos()).abs() < 1e-15 && (q[3] - FRAC_PI_4.sin()).abs() < 1e-15);
/// // The Hamilton product composes like matrices: R(q ⊗ q) = R(q) R(q), 180° about z.
/// let qq = quaternion_multiply(&q, &q)?;
/// assert!((quaternion_to_matrix(&qq, false)? - rot_z(4.0 * FRAC_PI_4)).amax() < 1e-15);
/// # Ok::<(), poinsot::Error>(())
/// ```
pub type Quaternion = [f64; 4];

/// Largest `|‖q‖ − 1|` accepted for a unit quaternion when the caller did not ask for
/// normalisation (`1e-6`, as [`crate::rotation::ROTATION_MATRIX_TOL`] for matrices).
pub const QUATERNION_UNIT_TOL: f64 = 1e-6;

/// Checks quaternion `q` (`[w, x, y, z]`) named `argument` and returns it as a unit quaternion.
///
/// With `normalize`, any finite non-zero `q` is divided by its norm; without, `|‖q‖ − 1|` must
/// be at most [`QUATERNION_UNIT_TOL`] (and `q` is still divided by its norm, a round-off-level
/// correction). Errors: non-finite ([`Error::invalid`]), zero or non-unit
/// ([`Error::rotation`]), naming `argument`.
pub fn check_quaternion(argument: &str, q: &Quaternion, normalize: bool) -> Result<Quaternion> {
    check_finite(argument, q)?;
    let n = norm4(q);
    if n == 0.0 {
        return Err(Error::rotation(
            argument,
            "the zero quaternion represents no rotation (norm 0); quaternions are [w, x, y, z]",
        ));
    }
    if !normalize && (n - 1.0).abs() > QUATERNION_UNIT_TOL {
        return Err(Error::rotation(
            argument,
            format!(
                "must be a unit quaternion [w, x, y, z]: norm = {n:.9}, |norm − 1| = {:.3e} \
                 exceeds {QUATERNION_UNIT_TOL:.0e} (pass normalize=true to normalise)",
                (n - 1.0).abs()
            ),
        ));
    }
    Ok(q.map(|c| c / n))
}

/// `q / ‖q‖` for a finite non-zero quaternion (errors as [`check_quaternion`], naming `"q"`).
pub fn quaternion_normalize(q: &Quaternion) -> Result<Quaternion> {
    check_quaternion("q", q, true)
}

fn norm4(q: &Quaternion) -> f64 {
    // Scaled to avoid overflow and underflow of the squares.
    let m = q.iter().fold(0.0f64, |m, c| m.max(c.abs()));
    if m == 0.0 || !m.is_finite() {
        return m;
    }
    m * q.iter().map(|c| (c / m) * (c / m)).sum::<f64>().sqrt()
}

/// The unit quaternion `[w, x, y, z]` of rotation matrix `r`, canonical `w >= 0` (at `w = 0`,
/// a half turn, the first non-zero of `x, y, z` is made positive).
///
/// Robust for every angle (Shepperd's method, as refined by Markley 2008): the quaternion is
/// built from the largest of `1 + tr R` and `1 + 2 R_ii − tr R`, then normalised. `r` is
/// checked with [`crate::rotation::ROTATION_MATRIX_TOL`]; errors name `"R"`. A matrix off
/// orthonormal by more than [`crate::rotation::NEAREST_ROTATION_DEFECT`] (e.g. printed to 7
/// decimals) gives the quaternion of the nearest rotation, as scipy's `Rotation.from_matrix`
/// does, not that of its raw entries.
pub fn matrix_to_quaternion(r: &Mat3) -> Result<Quaternion> {
    Ok(matrix_to_quaternion_unchecked(&rotation_to_convert(
        "R",
        &row_major(r),
    )?))
}

/// Shepperd/Markley on a row-major matrix (assumed a rotation).
#[inline]
pub(crate) fn matrix_to_quaternion_unchecked(m: &[f64; 9]) -> Quaternion {
    let (r00, r01, r02, r10, r11, r12, r20, r21, r22) =
        (m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8]);
    let tr = r00 + r11 + r22;
    // Each candidate is 4 × (one component) × q; pick the one with the largest leading term.
    let q = if tr >= r00 && tr >= r11 && tr >= r22 {
        [1.0 + tr, r21 - r12, r02 - r20, r10 - r01]
    } else if r00 >= r11 && r00 >= r22 {
        [r21 - r12, 1.0 + r00 - r11 - r22, r01 + r10, r02 + r20]
    } else if r11 >= r22 {
        [r02 - r20, r01 + r10, 1.0 - r00 + r11 - r22, r12 + r21]
    } else {
        [r10 - r01, r02 + r20, r12 + r21, 1.0 - r00 - r11 + r22]
    };
    let n = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt();
    let mut q = q.map(|c| c / n);
    // Canonical sign: w > 0, or at w = 0 the first non-zero vector component positive.
    let lead = if q[0] != 0.0 {
        q[0]
    } else {
        q[1..].iter().copied().find(|c| *c != 0.0).unwrap_or(1.0)
    };
    if lead < 0.0 {
        q = q.map(|c| -c);
    }
    q.map(|c| c + 0.0)
}

/// The rotation matrix of quaternion `q = [w, x, y, z]`.
///
/// With `normalize = false` the quaternion must be a unit quaternion within
/// [`QUATERNION_UNIT_TOL`]; with `normalize = true` any finite non-zero quaternion is
/// normalised first. Errors as [`check_quaternion`], naming `"q"`.
pub fn quaternion_to_matrix(q: &Quaternion, normalize: bool) -> Result<Mat3> {
    let q = check_quaternion("q", q, normalize)?;
    Ok(from_row_major(&quaternion_to_matrix_unchecked(&q)))
}

/// Matrix of a unit quaternion, row-major.
#[inline]
pub(crate) fn quaternion_to_matrix_unchecked(q: &Quaternion) -> [f64; 9] {
    let [w, x, y, z] = *q;
    let (xx, yy, zz) = (x * x, y * y, z * z);
    let (xy, xz, yz) = (x * y, x * z, y * z);
    let (wx, wy, wz) = (w * x, w * y, w * z);
    [
        1.0 - 2.0 * (yy + zz),
        2.0 * (xy - wz),
        2.0 * (xz + wy),
        2.0 * (xy + wz),
        1.0 - 2.0 * (xx + zz),
        2.0 * (yz - wx),
        2.0 * (xz - wy),
        2.0 * (yz + wx),
        1.0 - 2.0 * (xx + yy),
    ]
}

/// The Hamilton product `p ⊗ q` (scalar-first). For unit quaternions it is the rotation
/// "first `q`, then `p`": `R(p ⊗ q) = R(p) R(q)`. Any finite quaternions are accepted (the
/// product is algebra; no normalisation); errors name `"p"` or `"q"` for non-finite input.
pub fn quaternion_multiply(p: &Quaternion, q: &Quaternion) -> Result<Quaternion> {
    check_finite("p", p)?;
    check_finite("q", q)?;
    Ok(hamilton(p, q))
}

/// The Hamilton product `p ⊗ q` without checks: `R(p ⊗ q) = R(p) R(q)`.
#[inline]
pub(crate) fn hamilton(p: &Quaternion, q: &Quaternion) -> Quaternion {
    let [pw, px, py, pz] = *p;
    let [qw, qx, qy, qz] = *q;
    [
        pw * qw - px * qx - py * qy - pz * qz,
        pw * qx + px * qw + py * qz - pz * qy,
        pw * qy - px * qz + py * qw + pz * qx,
        pw * qz + px * qy - py * qx + pz * qw,
    ]
}

/// Rotates vector `v` by unit quaternion `q` (`[w, x, y, z]`): `q ⊗ (0, v) ⊗ q*`, i.e.
/// `R(q) v`. `q` is checked as in [`quaternion_to_matrix`] without normalisation.
pub fn quaternion_rotate(q: &Quaternion, v: &Vec3) -> Result<Vec3> {
    let q = check_quaternion("q", q, false)?;
    check_finite("v", v.as_slice())?;
    Ok(quaternion_rotate_unchecked(&q, v))
}

/// `R(q) v` for a unit quaternion `q` (not checked): `v + 2 u × (u × v + w v)`,
/// `u = (x, y, z)`, the expanded sandwich product `q ⊗ (0, v) ⊗ q*`.
#[inline]
pub(crate) fn quaternion_rotate_unchecked(q: &Quaternion, v: &Vec3) -> Vec3 {
    let u = Vec3::new(q[1], q[2], q[3]);
    let t = u.cross(v) + q[0] * v;
    v + 2.0 * u.cross(&t)
}

/// The conjugate `[w, −x, −y, −z]` (the inverse of a unit quaternion).
#[inline]
pub(crate) fn conj(q: &Quaternion) -> Quaternion {
    [q[0], -q[1], -q[2], -q[3]]
}

/// `q / |q|` with the plain Euclidean norm (no scaling, no checks): the cheap renormalisation
/// of a quaternion known to be near unit length (integrators, sampled attitudes). Use
/// [`check_quaternion`] or [`quaternion_normalize`] for input.
#[inline]
pub(crate) fn normalized(q: &Quaternion) -> Quaternion {
    let n = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt();
    [q[0] / n, q[1] / n, q[2] / n, q[3] / n]
}

/// `q` or `−q`, whichever is nearer to `reference` (continuity of sampled attitudes).
#[inline]
pub(crate) fn same_hemisphere(q: Quaternion, reference: &Quaternion) -> Quaternion {
    let dot = q[0] * reference[0] + q[1] * reference[1] + q[2] * reference[2] + q[3] * reference[3];
    if dot < 0.0 {
        [-q[0], -q[1], -q[2], -q[3]]
    } else {
        q
    }
}

/// The quaternion of the rotation by `angle` about the unit vector `axis` (not checked).
#[inline]
pub(crate) fn axis_angle_quaternion(axis: &Vec3, angle: f64) -> Quaternion {
    let (s, c) = (0.5 * angle).sin_cos();
    [c, s * axis.x, s * axis.y, s * axis.z]
}

/// The quaternion of the rotation by `angle` about coordinate axis `k` (0, 1, 2).
#[inline]
pub(crate) fn coordinate_quaternion(k: usize, angle: f64) -> Quaternion {
    let (s, c) = (0.5 * angle).sin_cos();
    let mut q = [c, 0.0, 0.0, 0.0];
    q[k + 1] = s;
    q
}

/// The unit quaternion of a rotation matrix given row-major (assumed a rotation), by
/// Shepperd's method — built from the largest of `1 + tr R` and `1 + 2R_ii − tr R` — and
/// normalised by [`normalized`], with the sign as it falls (unlike
/// [`matrix_to_quaternion_unchecked`], no canonical `w ≥ 0`): the attitudes of the dynamics and
/// the closed-form solutions, whose numbers are pinned to this arithmetic.
#[inline]
pub(crate) fn matrix_to_quaternion_any_sign(m: &[f64; 9]) -> Quaternion {
    let (r00, r01, r02, r10, r11, r12, r20, r21, r22) =
        (m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8]);
    let tr = r00 + r11 + r22;
    let q = if tr >= r00 && tr >= r11 && tr >= r22 {
        [1.0 + tr, r21 - r12, r02 - r20, r10 - r01]
    } else if r00 >= r11 && r00 >= r22 {
        [r21 - r12, 1.0 + 2.0 * r00 - tr, r01 + r10, r02 + r20]
    } else if r11 >= r22 {
        [r02 - r20, r01 + r10, 1.0 + 2.0 * r11 - tr, r12 + r21]
    } else {
        [r10 - r01, r02 + r20, r12 + r21, 1.0 + 2.0 * r22 - tr]
    };
    normalized(&q)
}

/// The rotation matrix of a unit quaternion (not checked), as a matrix.
#[inline]
pub(crate) fn quaternion_to_mat3_unchecked(q: &Quaternion) -> Mat3 {
    from_row_major(&quaternion_to_matrix_unchecked(q))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rotation::{rot_x, rot_z};
    use crate::ErrorKind;

    #[test]
    fn scalar_first_order_and_active_sense() {
        // 90° about +z: q = [cos 45°, 0, 0, sin 45°], and it turns e_x into e_y.
        let h = std::f64::consts::FRAC_1_SQRT_2;
        let q = matrix_to_quaternion(&rot_z(std::f64::consts::FRAC_PI_2)).unwrap();
        for (a, b) in q.iter().zip([h, 0.0, 0.0, h]) {
            assert!((a - b).abs() < 1e-15, "{q:?}");
        }
        let v = quaternion_rotate(&q, &Vec3::x()).unwrap();
        assert!((v - Vec3::y()).norm() < 1e-15);
    }

    #[test]
    fn product_composes_like_matrices() {
        let p = matrix_to_quaternion(&rot_x(0.4)).unwrap();
        let q = matrix_to_quaternion(&rot_z(-1.3)).unwrap();
        let r = quaternion_to_matrix(&hamilton(&p, &q), false).unwrap();
        assert!((r - rot_x(0.4) * rot_z(-1.3)).norm() < 1e-15);
    }

    #[test]
    fn half_turn_sign_is_canonical() {
        let q = matrix_to_quaternion(&rot_x(std::f64::consts::PI)).unwrap();
        assert!(q[0].abs() < 1e-16 && (q[1] - 1.0).abs() < 1e-15, "{q:?}");
    }

    #[test]
    fn bad_quaternions_are_named() {
        let e = quaternion_to_matrix(&[0.0; 4], true).unwrap_err();
        assert_eq!(e.kind, ErrorKind::InvalidRotation);
        assert!(
            e.to_string().starts_with("q: ") && e.message.contains("zero"),
            "{e}"
        );
        let e = quaternion_to_matrix(&[1.0, 0.1, 0.0, 0.0], false).unwrap_err();
        assert!(e.message.contains("unit"), "{e}");
        assert!(quaternion_to_matrix(&[2.0, 0.0, 0.0, 0.0], true).is_ok());
        let e = quaternion_multiply(&[1.0, 0.0, f64::INFINITY, 0.0], &[1.0, 0.0, 0.0, 0.0]);
        assert!(e.unwrap_err().to_string().starts_with("p: "));
    }
}
