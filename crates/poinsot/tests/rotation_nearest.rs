//! Conversions of near-rotations and of small Euler angles (issue 21, item 3).
//!
//! - A matrix off orthonormal by more than `NEAREST_ROTATION_DEFECT` (within the accepted
//!   `ROTATION_MATRIX_TOL`) is converted as its nearest rotation. Reference: `X = Q (I + S)`
//!   with `Q` a rotation and `S` small and symmetric has the polar decomposition `Q · (I + S)`,
//!   so its nearest rotation is `Q` itself (closed form). Negative control: Shepperd's formula
//!   on the raw entries of `X` (the conversion before the fix) is off by about `|S|`.
//! - An exact rotation (built in double precision) is converted from its own entries, bit for
//!   bit as the raw formula.
//! - Small first or third Euler angles (1e-3 … 1e-12) come out to relative accuracy in all 24
//!   conventions (before the fix the third was `(α + γ) − α`: relative error up to 1e-4 at
//!   1e-12). The mpmath reference at 50 digits is `python/tests/test_rotation_precision.py`.

use std::f64::consts::PI;

use poinsot::rotation::*;
use poinsot::Mat3;

/// Round-off of a conversion of the nearest rotation: a few ε.
const NEAREST_TOL: f64 = 2e-15;

/// Shepperd's quaternion of the raw entries (as the core computes it for an exact rotation):
/// the largest of `1 + tr R`, `1 + 2R_ii − tr R`, normalised, `w ≥ 0`.
fn raw_quaternion(r: &Mat3) -> Quaternion {
    let (r00, r01, r02) = (r[(0, 0)], r[(0, 1)], r[(0, 2)]);
    let (r10, r11, r12) = (r[(1, 0)], r[(1, 1)], r[(1, 2)]);
    let (r20, r21, r22) = (r[(2, 0)], r[(2, 1)], r[(2, 2)]);
    let tr = r00 + r11 + r22;
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

fn qdist(a: &Quaternion, b: &Quaternion) -> f64 {
    let d = |s: f64| (0..4).fold(0.0f64, |m, i| m.max((a[i] - s * b[i]).abs()));
    d(1.0).min(d(-1.0))
}

fn angle_diff(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(2.0 * PI);
    d.min(2.0 * PI - d)
}

fn row_major(m: &Mat3) -> [f64; 9] {
    [0, 1, 2]
        .map(|i| [0, 1, 2].map(|j| m[(i, j)]))
        .concat()
        .try_into()
        .unwrap()
}

/// A deterministic sequence in [−1, 1) (no RNG crate needed).
fn lcg(state: &mut u64) -> f64 {
    *state = state
        .wrapping_mul(6_364_136_223_846_793_005)
        .wrapping_add(1_442_695_040_888_963_407);
    ((*state >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
}

/// `(Q, X = Q (I + S))` with `|S_ij| <= size`, `S` symmetric, `Q` a generic rotation.
fn near_rotation(state: &mut u64, size: f64) -> (Mat3, Mat3) {
    let angles = [
        PI * lcg(state),
        0.2 + 2.7 * lcg(state).abs(),
        PI * lcg(state),
    ];
    let q = euler_to_matrix(angles, EulerSequence::UNIT).unwrap();
    let mut s = Mat3::zeros();
    for i in 0..3 {
        for j in i..3 {
            let v = size * lcg(state);
            s[(i, j)] = v;
            s[(j, i)] = v;
        }
    }
    (q, q * (Mat3::identity() + s))
}

#[test]
fn a_near_rotation_converts_as_its_nearest_rotation() {
    let mut state = 21;
    for size in [3e-7, 5e-8, 1e-10, 1e-13] {
        for _ in 0..200 {
            let (q_mat, x) = near_rotation(&mut state, size);
            check_rotation_matrix(&x, ROTATION_MATRIX_TOL).unwrap();
            let reference = matrix_to_quaternion(&q_mat).unwrap();
            let got = matrix_to_quaternion(&x).unwrap();
            assert!(
                qdist(&got, &reference) < NEAREST_TOL,
                "size {size}: {got:?} vs nearest {reference:?}"
            );
            // Negative control: the raw entries' quaternion is off by about |S|.
            if size >= 1e-10 {
                assert!(qdist(&raw_quaternion(&x), &reference) > 1e-3 * size);
            }
            // Euler angles (all 24 conventions), axis and angle, screw: those of Q.
            for seq in EulerSequence::all() {
                let (a, b) = (
                    matrix_to_euler(&x, seq).unwrap(),
                    matrix_to_euler(&q_mat, seq).unwrap(),
                );
                for k in 0..3 {
                    assert!(
                        angle_diff(a.angles[k], b.angles[k]) < 1e-13,
                        "{seq} size {size}: {:?} vs {:?}",
                        a.angles,
                        b.angles
                    );
                }
            }
            let ((n1, t1), (n2, t2)) = (rotation_axis(&x).unwrap(), rotation_axis(&q_mat).unwrap());
            assert!((n1 - n2).amax() < 1e-14 && (t1 - t2).abs() < NEAREST_TOL);
            let t = poinsot::Vec3::new(0.3, -1.0, 2.0);
            let (s1, s2) = (screw_axis(&x, &t).unwrap(), screw_axis(&q_mat, &t).unwrap());
            assert!((s1.axis - s2.axis).amax() < 1e-14 && (s1.point - s2.point).amax() < 1e-13);
        }
    }
}

#[test]
fn batch_conversions_project_as_the_single_ones() {
    let mut state = 7;
    let (mut mats, mut singles_q, mut singles_axis) = (vec![], vec![], vec![]);
    for _ in 0..64 {
        let (_, x) = near_rotation(&mut state, 1e-7);
        mats.extend(row_major(&x));
        singles_q.extend(matrix_to_quaternion(&x).unwrap());
        let (n, t) = rotation_axis(&x).unwrap();
        singles_axis.extend([n.x, n.y, n.z, t]);
    }
    let mut q = vec![0.0; 4 * 64];
    matrix_to_quaternion_batch(&mats, &mut q).unwrap();
    assert_eq!(q, singles_q);
    let mut ax = vec![0.0; 4 * 64];
    rotation_axis_batch(&mats, &mut ax).unwrap();
    assert_eq!(ax, singles_axis);
    let seq = EulerSequence::new("zyz", false).unwrap();
    let (mut e, mut locked) = (vec![0.0; 3 * 64], vec![false; 64]);
    matrix_to_euler_batch(seq, &mats, &mut e, &mut locked).unwrap();
    for k in 0..64 {
        let x: [f64; 9] = mats[9 * k..9 * k + 9].try_into().unwrap();
        let single = matrix_to_euler(&Mat3::from_row_slice(&x), seq).unwrap();
        assert_eq!(&e[3 * k..3 * k + 3], &single.angles);
    }
}

/// The common path is unchanged: a rotation built in double precision (off orthonormal by a
/// few ε) is converted from its own entries, bit for bit.
#[test]
fn an_exact_rotation_is_converted_from_its_own_entries() {
    let mut state = 3;
    for _ in 0..2000 {
        let angles = [
            PI * lcg(&mut state),
            PI * lcg(&mut state),
            PI * lcg(&mut state),
        ];
        let r = euler_to_matrix(angles, EulerSequence::new("xyz", true).unwrap()).unwrap();
        assert_eq!(matrix_to_quaternion(&r).unwrap(), raw_quaternion(&r));
        let q = [
            lcg(&mut state),
            lcg(&mut state),
            lcg(&mut state),
            lcg(&mut state),
        ];
        let r = quaternion_to_matrix(&q, true).unwrap();
        assert_eq!(matrix_to_quaternion(&r).unwrap(), raw_quaternion(&r));
    }
}

/// Small first or third angles keep their relative accuracy, in all 24 conventions, with the
/// other two angles generic (away from gimbal lock).
#[test]
fn small_first_and_third_euler_angles_have_relative_accuracy() {
    let mut state = 1234;
    let mut worst = 0.0f64;
    for seq in EulerSequence::all() {
        let proper = seq.kind() == SequenceKind::ProperEuler;
        for p in 3..=12 {
            for pos in [0, 2] {
                for sign in [1.0, -1.0] {
                    let small = sign * 10f64.powi(-p) * (1.0 + 0.5 * lcg(&mut state));
                    let beta = if proper {
                        0.3 + 2.5 * lcg(&mut state).abs()
                    } else {
                        1.3 * lcg(&mut state)
                    };
                    let mut angles = [3.0 * lcg(&mut state), beta, 3.0 * lcg(&mut state)];
                    angles[pos] = small;
                    let r = euler_to_matrix(angles, seq).unwrap();
                    let got = matrix_to_euler(&r, seq).unwrap().angles;
                    let rel = (got[pos] - small).abs() / small.abs();
                    worst = worst.max(rel);
                    assert!(
                        rel <= 4.0 * f64::EPSILON,
                        "{seq} {angles:?} -> {got:?}: {rel:e}"
                    );
                    // The others are still accurate, and the triple rebuilds R.
                    for k in 0..3 {
                        assert!(angle_diff(got[k], angles[k]) < 1e-14, "{seq} {angles:?}");
                    }
                    let back = euler_to_matrix(got, seq).unwrap();
                    assert!((back - r).amax() < 1e-15, "{seq} {angles:?}");
                }
            }
        }
    }
    eprintln!("worst relative error of a small angle: {worst:e}");
}
