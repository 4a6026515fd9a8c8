//! Property tests of `poinsot::rotation` against independent references: quaternion products
//! (for Euler matrices), Rodrigues' formula (for Euler's theorem), the displacement itself (for
//! Chasles' screw), and finite differences of `R(t)` (for the Euler-angle kinematics).
//!
//! Tolerances are named constants with their origin. proptest runs with a fixed seed.

use std::f64::consts::{FRAC_PI_2, PI};

use poinsot::rotation::*;
use poinsot::{ErrorKind, Mat3, Vec3};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};

/// Round-off of a product of three elementary rotations and of the extraction: a few ε.
const MATRIX_TOL: f64 = 1e-14;
/// At gimbal lock the third angle is set to 0: the rebuilt matrix is within 2·EULER_LOCK_TOL
/// plus round-off.
const LOCK_TOL: f64 = 2.0 * EULER_LOCK_TOL + MATRIX_TOL;
/// Central differences with step `H`: truncation `H²/6·|R'''|` ≈ 1e-11 for rates ≲ 3 rad/s,
/// round-off `ε/H` ≈ 1e-10.
const H: f64 = 1e-5;
const FD_TOL: f64 = 1e-8;

fn config() -> Config {
    Config {
        cases: 512,
        rng_seed: RngSeed::Fixed(2_98_99),
        ..Config::default()
    }
}

fn max_abs(m: &Mat3) -> f64 {
    m.iter().fold(0.0, |a, v| a.max(v.abs()))
}

fn skew(w: &Vec3) -> Mat3 {
    Mat3::new(0.0, -w.z, w.y, w.z, 0.0, -w.x, -w.y, w.x, 0.0)
}

/// Quaternion of the elementary rotation by `angle` about coordinate axis `axis`.
fn axis_quaternion(axis: usize, angle: f64) -> Quaternion {
    let mut q = [(0.5 * angle).cos(), 0.0, 0.0, 0.0];
    q[1 + axis] = (0.5 * angle).sin();
    q
}

/// Independent reference for the Euler matrix: the product of the three elementary rotations
/// written as quaternions, in the order the convention defines (intrinsic `q_a q_b q_c`,
/// extrinsic `q_c q_b q_a`), then converted once.
fn reference_matrix(angles: [f64; 3], seq: &EulerSequence) -> Mat3 {
    let ax = seq.axes().map(|a| a.index());
    let q = [0, 1, 2].map(|k| axis_quaternion(ax[k], angles[k]));
    let prod = if seq.is_intrinsic() {
        quaternion_multiply(&quaternion_multiply(&q[0], &q[1]).unwrap(), &q[2]).unwrap()
    } else {
        quaternion_multiply(&quaternion_multiply(&q[2], &q[1]).unwrap(), &q[0]).unwrap()
    };
    quaternion_to_matrix(&prod, false).unwrap()
}

/// The middle angle at which `seq` locks: 0 and π (proper) or ±π/2 (Tait–Bryan).
fn lock_angles(seq: &EulerSequence) -> [f64; 2] {
    match seq.kind() {
        SequenceKind::ProperEuler => [0.0, PI],
        SequenceKind::TaitBryan => [FRAC_PI_2, -FRAC_PI_2],
    }
}

/// Angles in the canonical ranges of `seq` from three numbers in [0, 1].
fn canonical(seq: &EulerSequence, u: [f64; 3]) -> [f64; 3] {
    let beta = match seq.kind() {
        SequenceKind::ProperEuler => u[1] * PI,
        SequenceKind::TaitBryan => (u[1] - 0.5) * PI,
    };
    [(2.0 * u[0] - 1.0) * PI, beta, (2.0 * u[2] - 1.0) * PI]
}

fn angle_diff(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(2.0 * PI);
    d.min(2.0 * PI - d)
}

fn unit() -> impl Strategy<Value = f64> {
    0.0f64..=1.0
}

fn any_rotation() -> impl Strategy<Value = Mat3> {
    (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0, -4.0f64..4.0)
        .prop_filter_map("non-zero axis", |(x, y, z, a)| {
            axis_angle_to_matrix(&Vec3::new(x, y, z), a).ok()
        })
}

proptest! {
    #![proptest_config(config())]

    /// euler_to_matrix equals the quaternion product of the elementary rotations, for all 24
    /// conventions; matrix_to_euler returns angles in range that rebuild the matrix, and the
    /// input angles themselves away from gimbal lock.
    #[test]
    fn euler_round_trips_all_conventions(u in (unit(), unit(), unit()), k in 0usize..24) {
        let seq = EulerSequence::all()[k];
        let angles = canonical(&seq, [u.0, u.1, u.2]);
        let r = euler_to_matrix(angles, seq).unwrap();
        prop_assert!(max_abs(&(r - reference_matrix(angles, &seq))) < MATRIX_TOL, "{seq}");
        let e = matrix_to_euler(&r, seq).unwrap();
        let [a, b, c] = e.angles;
        prop_assert!(a > -PI && a <= PI && c > -PI && c <= PI, "{:?}", e.angles);
        match seq.kind() {
            SequenceKind::ProperEuler => prop_assert!((0.0..=PI).contains(&b)),
            SequenceKind::TaitBryan => prop_assert!((-FRAC_PI_2..=FRAC_PI_2).contains(&b)),
        }
        let back = euler_to_matrix(e.angles, seq).unwrap();
        prop_assert!(max_abs(&(back - r)) < MATRIX_TOL, "{seq} {angles:?} -> {:?}", e.angles);
        let far = match seq.kind() {
            SequenceKind::ProperEuler => angles[1].sin().abs() > 1e-3,
            SequenceKind::TaitBryan => angles[1].cos().abs() > 1e-3,
        };
        if far {
            for (x, y) in e.angles.iter().zip(angles) {
                // Conditioning 1/|sin β| ≤ 1e3 times round-off.
                prop_assert!(angle_diff(*x, y) < 1e-12, "{seq} {angles:?} -> {:?}", e.angles);
            }
        }
    }

    /// Near (not at: 1e-13 to 1e-4 away, above EULER_LOCK_TOL) gimbal lock the split between
    /// first and third angle is ill-conditioned,
    /// but the extracted triple still rebuilds the matrix to round-off.
    #[test]
    fn euler_round_trips_near_gimbal_lock(
        u in (unit(), unit()), k in 0usize..24, which in 0usize..2, p in 4i32..=13, sign in prop::bool::ANY,
    ) {
        let seq = EulerSequence::all()[k];
        let delta = 10f64.powi(-p) * if sign { 1.0 } else { -1.0 };
        let beta = lock_angles(&seq)[which] + delta;
        let angles = [(2.0 * u.0 - 1.0) * PI, beta, (2.0 * u.1 - 1.0) * PI];
        let r = euler_to_matrix(angles, seq).unwrap();
        let e = matrix_to_euler(&r, seq).unwrap();
        let back = euler_to_matrix(e.angles, seq).unwrap();
        prop_assert!(max_abs(&(back - r)) < MATRIX_TOL, "{seq} {angles:?} -> {:?}", e.angles);
    }

    /// At gimbal lock the flag is set, the third angle is 0 and the triple rebuilds R.
    #[test]
    fn euler_at_gimbal_lock(u in (unit(), unit()), k in 0usize..24, which in 0usize..2) {
        let seq = EulerSequence::all()[k];
        let angles = [(2.0 * u.0 - 1.0) * PI, lock_angles(&seq)[which], (2.0 * u.1 - 1.0) * PI];
        let r = euler_to_matrix(angles, seq).unwrap();
        let e = matrix_to_euler(&r, seq).unwrap();
        prop_assert!(e.gimbal_lock, "{seq} {angles:?}");
        prop_assert_eq!(e.angles[2], 0.0);
        let back = euler_to_matrix(e.angles, seq).unwrap();
        prop_assert!(max_abs(&(back - r)) < LOCK_TOL, "{seq} {angles:?} -> {:?}", e.angles);
    }

    /// Extrinsic (a, b, c) with (α, β, γ) is intrinsic (c, b, a) with (γ, β, α).
    #[test]
    fn extrinsic_is_reversed_intrinsic(u in (unit(), unit(), unit()), k in 0usize..12) {
        let name = EulerSequence::NAMES[k];
        let rev: String = name.chars().rev().collect();
        let ext = EulerSequence::new(name, false).unwrap();
        let int = EulerSequence::new(&rev, true).unwrap();
        let a = canonical(&ext, [u.0, u.1, u.2]);
        let r1 = euler_to_matrix(a, ext).unwrap();
        let r2 = euler_to_matrix([a[2], a[1], a[0]], int).unwrap();
        prop_assert!(max_abs(&(r1 - r2)) == 0.0);
    }

    /// Quaternion ↔ matrix: consistent with Rodrigues, `q` and `−q` alike, w ≥ 0 canonical.
    #[test]
    fn quaternion_matrix_consistency(
        w in -1.0f64..1.0, x in -1.0f64..1.0, y in -1.0f64..1.0, z in -1.0f64..1.0,
    ) {
        let q = [w, x, y, z];
        prop_assume!(q.iter().map(|c| c * c).sum::<f64>() > 1e-6);
        let q = quaternion_normalize(&q).unwrap();
        let r = quaternion_to_matrix(&q, false).unwrap();
        check_rotation_matrix(&r, 1e-14).unwrap();
        let v = Vec3::new(q[1], q[2], q[3]);
        let angle = 2.0 * v.norm().atan2(q[0]);
        if v.norm() > 1e-8 {
            let rod = axis_angle_to_matrix(&v, angle).unwrap();
            prop_assert!(max_abs(&(rod - r)) < MATRIX_TOL);
        }
        let back = matrix_to_quaternion(&r).unwrap();
        let s = if q[0] < 0.0 { -1.0 } else { 1.0 };
        prop_assert!(back[0] >= 0.0);
        for i in 0..4 {
            prop_assert!((back[i] - s * q[i]).abs() < 1e-14, "{q:?} -> {back:?}");
        }
        let u = Vec3::new(0.3, -1.1, 2.0);
        prop_assert!((quaternion_rotate(&q, &u).unwrap() - r * u).norm() < 1e-14);
    }

    /// Euler's theorem: the axis is a unit fixed vector (R n = n), the angle is in [0, π], and
    /// Rodrigues' formula rebuilds R.
    #[test]
    fn rotation_axis_reconstructs(r in any_rotation()) {
        let (n, angle) = rotation_axis(&r).unwrap();
        prop_assert!((0.0..=PI).contains(&angle));
        prop_assert!((n.norm() - 1.0).abs() < 1e-15);
        prop_assert!((r * n - n).norm() < 1e-14);
        prop_assert!(max_abs(&(axis_angle_to_matrix(&n, angle).unwrap() - r)) < MATRIX_TOL);
    }

    /// Chasles' theorem: the screw reproduces the displacement; the point is on the axis and
    /// perpendicular to it; R p + t = p + slide·axis.
    #[test]
    fn screw_reconstructs_the_displacement(
        r in any_rotation(), t in (-5.0f64..5.0, -5.0f64..5.0, -5.0f64..5.0),
        x in (-3.0f64..3.0, -3.0f64..3.0, -3.0f64..3.0),
    ) {
        let t = Vec3::new(t.0, t.1, t.2);
        let x = Vec3::new(x.0, x.1, x.2);
        let s = screw_axis(&r, &t).unwrap();
        prop_assume!(s.angle > 1e-3); // |point| ~ |t|/angle: keep the round-off bounded
        let scale = 1.0 + s.point.norm();
        prop_assert!((r * s.point + t - s.point - s.slide * s.axis).norm() < 1e-13 * scale);
        prop_assert!(s.point.dot(&s.axis).abs() < 1e-13 * scale);
        prop_assert!((s.apply(&x).unwrap() - (r * x + t)).norm() < 1e-13 * scale);
        prop_assert!((s.slide - s.axis.dot(&t)).abs() < 1e-14 * scale);
        prop_assert!((s.pitch - s.slide / s.angle).abs() <= 1e-15 * s.pitch.abs());
    }

    /// Kinematics vs finite differences of R(t) for all 24 conventions:
    /// skew(ω_space) = Ṙ Rᵀ and skew(ω_body) = Rᵀ Ṙ; euler_rates inverts both.
    #[test]
    fn kinematics_match_finite_differences(
        u in (unit(), unit(), unit()), rates in (-3.0f64..3.0, -3.0f64..3.0, -3.0f64..3.0),
        k in 0usize..24,
    ) {
        let seq = EulerSequence::all()[k];
        let mut a = canonical(&seq, [u.0, u.1, u.2]);
        // Keep away from the lock (the rates' inverse is ill-conditioned there).
        a[1] = match seq.kind() {
            SequenceKind::ProperEuler => a[1].clamp(0.05, PI - 0.05),
            SequenceKind::TaitBryan => a[1].clamp(-FRAC_PI_2 + 0.05, FRAC_PI_2 - 0.05),
        };
        let d = [rates.0, rates.1, rates.2];
        let at = |h: f64| euler_to_matrix([a[0] + h * d[0], a[1] + h * d[1], a[2] + h * d[2]], seq).unwrap();
        let r = at(0.0);
        let rdot = (at(H) - at(-H)) / (2.0 * H);
        let ws = space_angular_velocity(a, d, seq).unwrap();
        let wb = body_angular_velocity(a, d, seq).unwrap();
        prop_assert!(max_abs(&(skew(&ws) - rdot * r.transpose())) < FD_TOL, "{seq}");
        prop_assert!(max_abs(&(skew(&wb) - r.transpose() * rdot)) < FD_TOL, "{seq}");
        prop_assert!((r * wb - ws).norm() < 1e-13);
        for (frame, w) in [(Frame::Body, wb), (Frame::Space, ws)] {
            let back = euler_rates(a, &w, seq, frame).unwrap();
            for i in 0..3 {
                // Conditioning 1/|sin β| ≤ 20.
                prop_assert!((back[i] - d[i]).abs() < 1e-12, "{seq} {frame:?}");
            }
        }
    }
}

/// The unit's eq. 2.99 (intrinsic zxz, body frame), pinned by its hard-coded formula, with the
/// erratum ω₃ = ω_ζ = ψ̇ + φ̇ cos θ.
#[test]
fn unit_eq_2_99_pinned() {
    for &(phi, theta, psi, dphi, dtheta, dpsi) in &[
        (0.1, 0.7, 2.9, 1.0, 0.0, 0.0),
        (-2.0, 2.5, -0.3, 0.3, -1.7, 4.0),
        (3.0, 1.0, 1.0, -5.0, 2.0, 0.5),
    ] {
        let w = body_angular_velocity([phi, theta, psi], [dphi, dtheta, dpsi], EulerSequence::UNIT)
            .unwrap();
        let (st, ct, sp, cp) = (
            f64::sin(theta),
            f64::cos(theta),
            f64::sin(psi),
            f64::cos(psi),
        );
        let expected = Vec3::new(
            dphi * st * sp + dtheta * cp,
            dphi * st * cp - dtheta * sp,
            dphi * ct + dpsi,
        );
        assert!((w - expected).norm() < 1e-14, "{w} vs {expected}");
        // 2.98: components along the line of nodes ξ, η and ζ (= body 3).
        let r_xi = rot_z(phi) * rot_x(theta);
        let w_space =
            space_angular_velocity([phi, theta, psi], [dphi, dtheta, dpsi], EulerSequence::UNIT)
                .unwrap();
        let w_xi = r_xi.transpose() * w_space;
        let expected_298 = Vec3::new(dtheta, dphi * st, dpsi + dphi * ct);
        assert!(
            (w_xi - expected_298).norm() < 1e-14,
            "{w_xi} vs {expected_298}"
        );
    }
}

#[test]
fn rates_raise_gimbal_lock_at_every_singularity() {
    for seq in EulerSequence::all() {
        for beta in lock_angles(&seq) {
            for frame in [Frame::Body, Frame::Space] {
                let e = euler_rates([0.4, beta, -1.0], &Vec3::new(0.1, 0.2, 0.3), seq, frame)
                    .unwrap_err();
                assert_eq!(e.kind, ErrorKind::GimbalLock, "{seq}");
                assert!(e.to_string().starts_with("angles: "), "{e}");
                assert!(e.message.contains("angles[1]"), "{e}");
            }
            // 1e-6 away: defined (rates ~ 1e6 |ω|).
            assert!(euler_rates([0.4, beta + 1e-6, -1.0], &Vec3::x(), seq, Frame::Body).is_ok());
        }
    }
}

#[test]
fn tiny_and_half_turn_angles_against_closed_forms() {
    let axis = Vec3::new(2.0, -1.0, 2.0) / 3.0;
    for theta in [1e-8, 1e-12, 1e-16] {
        let (n, a) = rotation_axis(&axis_angle_to_matrix(&axis, theta).unwrap()).unwrap();
        assert!(
            (a - theta).abs() <= 4.0 * f64::EPSILON * theta,
            "{a} vs {theta}"
        );
        assert!((n - axis).norm() < 1e-14);
    }
    for delta in [0.0, 1e-9, 1e-6] {
        let theta = PI - delta;
        let (n, a) = rotation_axis(&axis_angle_to_matrix(&axis, theta).unwrap()).unwrap();
        assert!((a - theta).abs() < 1e-15, "{a} vs {theta}");
        assert!(
            (n - axis).norm() < 1e-14 || (n + axis).norm() < 1e-14 && delta == 0.0,
            "{n}"
        );
    }
}

#[test]
fn bad_input_names_the_argument() {
    let seq = EulerSequence::UNIT;
    let e = euler_to_matrix([0.0, f64::NAN, 0.0], seq).unwrap_err();
    assert!(e.to_string().starts_with("angles: ") && e.message.contains("finite"));
    let mut r = rot_z(0.3);
    r[(2, 2)] = -1.0;
    for e in [
        matrix_to_euler(&r, seq).unwrap_err(),
        matrix_to_quaternion(&r).unwrap_err(),
        rotation_axis(&r).unwrap_err(),
        screw_axis(&r, &Vec3::zeros()).unwrap_err(),
    ] {
        assert_eq!(e.kind, ErrorKind::InvalidRotation);
        assert!(e.to_string().starts_with("R: "), "{e}");
    }
    let e = axis_angle_to_matrix(&Vec3::zeros(), 1.0).unwrap_err();
    assert!(e.to_string().starts_with("axis: ") && e.message.contains("non-zero"));
    let e = quaternion_to_matrix(&[0.0; 4], false).unwrap_err();
    assert!(e.to_string().starts_with("q: "));
    let e = euler_rates(
        [0.1, 0.2, 0.3],
        &Vec3::new(f64::INFINITY, 0.0, 0.0),
        seq,
        Frame::Body,
    )
    .unwrap_err();
    assert!(e.to_string().starts_with("omega_body: "));
}

#[test]
fn batch_kernels_match_single_calls() {
    let seq = EulerSequence::new("zyx", true).unwrap();
    let n = 10_000;
    let angles: Vec<f64> = (0..3 * n)
        .map(|i| ((i as f64) * 0.7548776662).sin() * 1.5)
        .collect();
    let mut mats = vec![0.0; 9 * n];
    euler_to_matrix_batch(seq, &angles, &mut mats).unwrap();
    let mut quats = vec![0.0; 4 * n];
    matrix_to_quaternion_batch(&mats, &mut quats).unwrap();
    let mut mats2 = vec![0.0; 9 * n];
    quaternion_to_matrix_batch(&quats, false, &mut mats2).unwrap();
    let worst = mats
        .iter()
        .zip(&mats2)
        .fold(0.0f64, |a, (x, y)| a.max((x - y).abs()));
    assert!(worst < MATRIX_TOL, "{worst}");
    let mut axes = vec![0.0; 4 * n];
    rotation_axis_batch(&mats, &mut axes).unwrap();
    let k = 1234;
    let r = euler_to_matrix([angles[3 * k], angles[3 * k + 1], angles[3 * k + 2]], seq).unwrap();
    let (ax, an) = rotation_axis(&r).unwrap();
    assert_eq!(&axes[4 * k..4 * k + 4], &[ax.x, ax.y, ax.z, an]);
    let mut w = vec![0.0; 3 * n];
    angular_velocity_batch(seq, Frame::Body, &angles, &angles, &mut w).unwrap();
    let mut back = vec![0.0; 3 * n];
    euler_rates_batch(seq, Frame::Body, &angles, &w, &mut back).unwrap();
    let worst = angles
        .iter()
        .zip(&back)
        .fold(0.0f64, |a, (x, y)| a.max((x - y).abs()));
    assert!(worst < 1e-9, "{worst}");
}
