//! Quaternion algebra on lanes ([`crate::simd::F64s`]) for the batch kernels: the operations
//! of `quaternion.rs`, each lane computed with exactly the scalar function's arithmetic (same
//! operations, same order), so that a lane's result equals the scalar result bit for bit.

use crate::simd::{F64s, Simd};

/// Quaternions `[w, x, y, z]` on lanes: component k of lane i is `q[k].lanes()[i]`.
pub(crate) type QuatLanes<S> = [F64s<S>; 4];

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
    use crate::rotation::quaternion::{normalized, quaternion_to_matrix_unchecked};
    use crate::simd::{dispatch, WithSimd};

    fn check<S: Simd>(s: S) {
        let lanes = F64s::<S>::LANES;
        let q: QuatLanes<S> =
            std::array::from_fn(|k| F64s::from_fn(s, |i| ((5 * i + 2 * k) as f64 * 0.91).cos()));
        let n = normalized_lanes(&q);
        let m = quaternion_to_matrix_lanes(&n);
        for i in 0..lanes {
            let lane = |v: &QuatLanes<S>| std::array::from_fn(|k| v[k].lanes()[i]);
            assert_eq!(lane(&n), normalized(&lane(&q)));
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
