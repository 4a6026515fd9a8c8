//! Small quaternion helpers shared by the closed-form solutions (scalar-first `[w, x, y, z]`,
//! active, body → space).

use crate::rotation::Quaternion;
use crate::Vec3;

/// The quaternion of the rotation by `angle` about the unit vector `axis`.
#[inline]
pub(crate) fn axis_angle_q(axis: &Vec3, angle: f64) -> Quaternion {
    let (s, c) = (0.5 * angle).sin_cos();
    [c, s * axis.x, s * axis.y, s * axis.z]
}

/// The quaternion of the rotation by `angle` about coordinate axis `k` (0, 1, 2).
#[inline]
pub(crate) fn coordinate_q(k: usize, angle: f64) -> Quaternion {
    let (s, c) = (0.5 * angle).sin_cos();
    let mut q = [c, 0.0, 0.0, 0.0];
    q[k + 1] = s;
    q
}

/// The conjugate (the inverse of a unit quaternion).
#[inline]
pub(crate) fn conj(q: &Quaternion) -> Quaternion {
    [q[0], -q[1], -q[2], -q[3]]
}

/// `R(q) v` for a unit quaternion.
#[inline]
pub(crate) fn rotate(q: &Quaternion, v: &Vec3) -> Vec3 {
    let u = Vec3::new(q[1], q[2], q[3]);
    let t = u.cross(v) + q[0] * v;
    v + 2.0 * u.cross(&t)
}

/// `q / |q|`.
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

/// The Hamilton product `p ⊗ q`: `R(p ⊗ q) = R(p) R(q)`.
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

/// The unit quaternion of a rotation matrix given row-major (assumed a rotation), by
/// Shepperd's method: built from the largest of `1 + tr R` and `1 + 2R_ii − tr R`.
#[inline]
pub(crate) fn matrix_to_quaternion_unchecked(m: &[f64; 9]) -> Quaternion {
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

/// The rotation matrix of a unit quaternion.
#[inline]
pub(crate) fn quaternion_matrix(q: &Quaternion) -> crate::Mat3 {
    let [w, x, y, z] = *q;
    crate::Mat3::new(
        1.0 - 2.0 * (y * y + z * z),
        2.0 * (x * y - w * z),
        2.0 * (x * z + w * y),
        2.0 * (x * y + w * z),
        1.0 - 2.0 * (x * x + z * z),
        2.0 * (y * z - w * x),
        2.0 * (x * z - w * y),
        2.0 * (y * z + w * x),
        1.0 - 2.0 * (x * x + y * y),
    )
}
