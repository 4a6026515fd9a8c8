//! Quaternion algebra on lanes ([`crate::simd::F64s`]) for the batch kernels: the operations
//! of `quaternion.rs`, each lane computed with exactly the scalar function's arithmetic (same
//! operations, same order), so that a lane's result equals the scalar result bit for bit.

use crate::simd::{F64s, Simd};

/// Quaternions `[w, x, y, z]` on lanes: component k of lane i is `q[k].lanes()[i]`.
pub(crate) type QuatLanes<S> = [F64s<S>; 4];

/// The Hamilton product `p ⊗ q` on lanes (as `hamilton`).
#[inline(always)]
pub(crate) fn hamilton_lanes<S: Simd>(p: &QuatLanes<S>, q: &QuatLanes<S>) -> QuatLanes<S> {
    let [pw, px, py, pz] = *p;
    let [qw, qx, qy, qz] = *q;
    [
        pw * qw - px * qx - py * qy - pz * qz,
        pw * qx + px * qw + py * qz - pz * qy,
        pw * qy - px * qz + py * qw + pz * qx,
        pw * qz + px * qy - py * qx + pz * qw,
    ]
}

/// The unit quaternion of rotation matrices given row-major (as
/// `matrix_to_quaternion_any_sign`: Shepperd's choice among four forms, lane by lane, then
/// normalised).
#[inline(always)]
pub(crate) fn matrix_to_quaternion_lanes<S: Simd>(m: &[F64s<S>; 9]) -> QuatLanes<S> {
    let [r00, r01, r02, r10, r11, r12, r20, r21, r22] = *m;
    let one = r00.splat_like(1.0);
    let tr = r00 + r11 + r22;
    let by_trace = r00.le(tr).and(r11.le(tr)).and(r22.le(tr));
    let by_x = by_trace.not().and(r11.le(r00)).and(r22.le(r00));
    let by_y = by_trace.not().and(by_x.not()).and(r22.le(r11));
    let t = [one + tr, r21 - r12, r02 - r20, r10 - r01];
    let x = [r21 - r12, one + 2.0 * r00 - tr, r01 + r10, r02 + r20];
    let y = [r02 - r20, r01 + r10, one + 2.0 * r11 - tr, r12 + r21];
    let z = [r10 - r01, r02 + r20, r12 + r21, one + 2.0 * r22 - tr];
    let mut q = z;
    for k in 0..4 {
        q[k] = F64s::select(
            by_trace,
            t[k],
            F64s::select(by_x, x[k], F64s::select(by_y, y[k], z[k])),
        );
    }
    normalized_lanes(&q)
}

/// `q / |q|` on lanes (as `normalized`).
#[inline(always)]
pub(crate) fn normalized_lanes<S: Simd>(q: &QuatLanes<S>) -> QuatLanes<S> {
    let n = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt();
    [q[0] / n, q[1] / n, q[2] / n, q[3] / n]
}

/// The rotation matrix of unit quaternions, row-major (as `quaternion_to_matrix_unchecked`).
#[inline(always)]
pub(crate) fn quaternion_to_matrix_lanes<S: Simd>(q: &QuatLanes<S>) -> [F64s<S>; 9] {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rotation::quaternion::{
        hamilton, matrix_to_quaternion_any_sign, normalized, quaternion_to_matrix_unchecked,
    };
    use crate::simd::{dispatch, WithSimd};

    fn check<S: Simd>(s: S) {
        let lanes = F64s::<S>::LANES;
        let q: QuatLanes<S> =
            std::array::from_fn(|k| F64s::from_fn(s, |i| ((5 * i + 2 * k) as f64 * 0.91).cos()));
        let p: QuatLanes<S> =
            std::array::from_fn(|k| F64s::from_fn(s, |i| ((3 * i + k) as f64 * 0.37).sin()));
        let h = hamilton_lanes(&p, &q);
        let n = normalized_lanes(&q);
        let m = quaternion_to_matrix_lanes(&n);
        let back = matrix_to_quaternion_lanes(&m);
        // Matrices that pick each of Shepperd's four forms: rotations by ~π about x, y, z.
        let half_turns: [F64s<S>; 9] = std::array::from_fn(|k| {
            F64s::from_fn(s, |i| {
                let axis = i % 4;
                let r = match axis {
                    0 => crate::rotation::rot_x(3.0),
                    1 => crate::rotation::rot_y(3.0),
                    2 => crate::rotation::rot_z(3.0),
                    _ => crate::rotation::rot_z(0.2),
                };
                r[(k / 3, k % 3)]
            })
        });
        let forms = matrix_to_quaternion_lanes(&half_turns);
        for i in 0..lanes {
            let lane = |v: &QuatLanes<S>| std::array::from_fn(|k| v[k].lanes()[i]);
            assert_eq!(lane(&h), hamilton(&lane(&p), &lane(&q)));
            assert_eq!(lane(&n), normalized(&lane(&q)));
            let row = |v: &[F64s<S>; 9]| std::array::from_fn::<f64, 9, _>(|k| v[k].lanes()[i]);
            assert_eq!(lane(&back), matrix_to_quaternion_any_sign(&row(&m)));
            assert_eq!(
                lane(&forms),
                matrix_to_quaternion_any_sign(&row(&half_turns))
            );
            let want = quaternion_to_matrix_unchecked(&lane(&n));
            assert_eq!(std::array::from_fn::<f64, 9, _>(|k| m[k].lanes()[i]), want);
        }
    }

    struct Check;
    impl WithSimd for Check {
        type Output = ();
        #[inline(always)]
        fn with_simd<S: Simd>(self, s: S) {
            check(s)
        }
    }

    /// Each lane equals the scalar function bit for bit, on this CPU's instruction set and in
    /// scalar code.
    #[test]
    fn lanes_equal_the_scalar_functions() {
        dispatch(Check);
        check(pulp::Scalar);
    }
}
