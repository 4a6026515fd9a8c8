//! The exact heavy-top solution against the top integrated numerically as a rigid body under
//! gravity (Euler's equations with the gravity torque, attitude as a rotation matrix, the
//! crate's DOP853), and the sleeping-top threshold by simulation on both sides of it.
//!
//! The rigid body knows nothing of Euler angles, p_φ or the cubic: it is the independent model.
//! Body frame = principal axes at the pivot, I = diag(I₁, I₁, I₃); the centre of mass at l ê₃;
//! the torque of gravity (−mg Ẑ) in body axes is `τ = −m g l ê₃ × (Rᵀ Ẑ)`; the attitude is a
//! unit quaternion q = [w, x, y, z] (body → space) with q̇ = ½ q ⊗ (0, ω_body).

use poinsot::analytic::{sleeping_threshold, EulerState, HeavyTop};
use poinsot::integrate::{dop853, Options};
use poinsot::rotation::{
    euler_to_matrix, matrix_to_quaternion, quaternion_to_matrix, EulerSequence,
};
use poinsot::Mat3;

/// DOP853 at rtol = atol = 1e-13 over ~20 s: global error ≲ 1e-10; the bound leaves margin.
const RIGID_BODY_TOL: f64 = 1e-8;

fn zxz() -> EulerSequence {
    EulerSequence::new("zxz", true).unwrap()
}

/// ω in body axes from the Euler angles and rates (2.99).
fn body_omega(s: &EulerState) -> [f64; 3] {
    let (st, ct) = s.theta.sin_cos();
    let (sp, cp) = s.psi.sin_cos();
    [
        s.theta_dot * cp + s.phi_dot * st * sp,
        -s.theta_dot * sp + s.phi_dot * st * cp,
        s.psi_dot + s.phi_dot * ct,
    ]
}

/// The state [q (w, x, y, z), ω_body] of the rigid body at the Euler state `s`.
fn rigid_state(s: &EulerState) -> [f64; 7] {
    let r = euler_to_matrix([s.phi, s.theta, s.psi], zxz()).unwrap();
    let q = matrix_to_quaternion(&r).unwrap();
    let w = body_omega(s);
    [q[0], q[1], q[2], q[3], w[0], w[1], w[2]]
}

/// Integrates the rigid top; returns (R, ω_body) at each of `times`.
fn integrate_rigid(
    i1: f64,
    i3: f64,
    mgl: f64,
    s: &EulerState,
    times: &[f64],
) -> Vec<(Mat3, [f64; 3])> {
    let rhs = move |_t: f64, y: &[f64; 7], dy: &mut [f64; 7]| {
        let (qw, qx, qy, qz) = (y[0], y[1], y[2], y[3]);
        let (w1, w2, w3) = (y[4], y[5], y[6]);
        // q̇ = ½ q ⊗ (0, ω).
        dy[0] = 0.5 * (-qx * w1 - qy * w2 - qz * w3);
        dy[1] = 0.5 * (qw * w1 + qy * w3 - qz * w2);
        dy[2] = 0.5 * (qw * w2 + qz * w1 - qx * w3);
        dy[3] = 0.5 * (qw * w3 + qx * w2 - qy * w1);
        // Rᵀ Ẑ is the third row of R(q): (2(xz − wy), 2(yz + wx), 1 − 2(x² + y²)), over |q|².
        let n2 = qw * qw + qx * qx + qy * qy + qz * qz;
        let r31 = 2.0 * (qx * qz - qw * qy) / n2;
        let r32 = 2.0 * (qy * qz + qw * qx) / n2;
        // τ = −mgl ê₃ × (R₃₁, R₃₂, R₃₃) = mgl (R₃₂, −R₃₁, 0); Euler's equations, I = diag(I₁, I₁, I₃).
        let (tau1, tau2) = (mgl * r32, -mgl * r31);
        dy[4] = (tau1 - (i3 - i1) * w2 * w3) / i1;
        dy[5] = (tau2 - (i1 - i3) * w3 * w1) / i1;
        dy[6] = 0.0;
    };
    let t_end = times.iter().cloned().fold(0.0, f64::max);
    let sol = dop853(
        rhs,
        0.0,
        rigid_state(s),
        t_end,
        &Options::with_tolerances(1e-13, 1e-13),
    )
    .unwrap();
    times
        .iter()
        .map(|&t| {
            let y = sol.at(t).unwrap();
            (
                quaternion_to_matrix(&[y[0], y[1], y[2], y[3]], true).unwrap(),
                [y[4], y[5], y[6]],
            )
        })
        .collect()
}

/// The exact attitude (Euler angles → R, z-x-z) against the rigid body, for waves, loops,
/// cusps, a top below the horizontal, a near-sleeping top and a pendulum swinging through the
/// bottom (where φ and ψ jump by π: the attitude must not).
#[test]
fn exact_solution_matches_the_rigid_body_integration() {
    let cases = [
        (
            1.0,
            0.5,
            1.0,
            EulerState {
                theta: 0.8,
                psi_dot: 6.0,
                phi_dot: 0.5,
                ..Default::default()
            },
        ),
        (
            1.0,
            0.5,
            1.0,
            EulerState {
                theta: 0.8,
                psi_dot: 6.0,
                phi_dot: -0.5,
                phi: 0.4,
                psi: 1.0,
                ..Default::default()
            },
        ),
        (
            1.0,
            0.5,
            1.0,
            EulerState {
                theta: 0.8,
                psi_dot: 6.0,
                ..Default::default()
            },
        ),
        (
            1.3,
            0.9,
            0.7,
            EulerState {
                theta: 2.5,
                theta_dot: 0.5,
                phi_dot: 0.3,
                psi_dot: 2.0,
                ..Default::default()
            },
        ),
        (
            1.0,
            0.5,
            1.0,
            EulerState {
                theta: 0.01,
                theta_dot: 0.001,
                phi_dot: 0.2,
                psi_dot: 10.0,
                ..Default::default()
            },
        ),
        (
            1.0,
            0.5,
            1.0,
            EulerState {
                theta: 0.8,
                ..Default::default()
            },
        ),
        (
            1.0,
            0.5,
            0.0,
            EulerState {
                theta: 0.8,
                theta_dot: 0.2,
                phi_dot: 1.0,
                psi_dot: 3.0,
                ..Default::default()
            },
        ),
    ];
    let times: Vec<f64> = (1..=40).map(|k| 0.5 * k as f64).collect();
    for (i1, i3, mgl, s) in cases {
        let top = HeavyTop::new(i1, i3, mgl, s).unwrap();
        let rigid = integrate_rigid(i1, i3, mgl, &s, &times);
        for (t, (r, _)) in times.iter().zip(&rigid) {
            let exact = euler_to_matrix(top.euler_angles(*t).unwrap(), zxz()).unwrap();
            let err = (exact - r).abs().max();
            assert!(
                err < RIGID_BODY_TOL,
                "{s:?} ({:?}) at t = {t}: |ΔR| = {err:e}",
                top.motion_class()
            );
        }
        // Along the rigid body, L_Z = Ẑ · R (I ω) stays p_φ and L₃ = I₃ω₃ stays p_ψ.
        for (t, (r, w)) in times.iter().zip(&rigid) {
            let l_body = poinsot::Vec3::new(i1 * w[0], i1 * w[1], i3 * w[2]);
            let (lz, l3) = ((r * l_body).z, l_body.z);
            let tol = 1e-9 * (1.0 + top.p_phi().abs() + top.p_psi().abs());
            assert!(
                (lz - top.p_phi()).abs() < tol && (l3 - top.p_psi()).abs() < tol,
                "t = {t}: L_Z {lz} vs p_phi {}, L_3 {l3} vs p_psi {}",
                top.p_phi(),
                top.p_psi()
            );
        }
    }
}

/// The sleeping top is stable iff ω₃² > 4 m g l I₁ / I₃². Tipped by 1e-4 rad and left alone,
/// the rigid body stays within a few times the tilt for 100 s at 1.05× the threshold spin, and
/// falls a thousand times further at 0.95× — and the exact turning point θ₂ says the same.
#[test]
fn sleeping_top_threshold_by_simulation() {
    let (i1, i3, mgl) = (1.0, 0.5, 1.0);
    let thr = sleeping_threshold(i1, i3, mgl).unwrap();
    let tilt = 1e-4;
    let times: Vec<f64> = (1..=1000).map(|k| 0.1 * k as f64).collect();
    for (factor, stable) in [(1.05, true), (0.95, false)] {
        let s = EulerState {
            theta: tilt,
            psi_dot: factor * thr,
            ..Default::default()
        };
        let rigid = integrate_rigid(i1, i3, mgl, &s, &times);
        let max_theta = rigid
            .iter()
            .map(|(r, _)| r[(2, 2)].clamp(-1.0, 1.0).acos())
            .fold(0.0, f64::max);
        let top = HeavyTop::new(i1, i3, mgl, s).unwrap();
        let (_, theta2) = top.turning_points();
        if stable {
            assert!(
                max_theta < 10.0 * tilt,
                "{factor}x threshold: max theta {max_theta}"
            );
            assert!(theta2 < 10.0 * tilt && (theta2 - max_theta).abs() < 1e-3 * theta2);
        } else {
            // It falls to θ₂ = arccos(1 − (2 − a²/β)) ≈ 0.635 rad (a = p_ψ/I₁, β = 2mgl/I₁) and
            // comes back: the homoclinic excursion of the unstable sleeping top.
            assert!(
                max_theta > 1000.0 * tilt,
                "{factor}x threshold: max theta {max_theta}"
            );
            assert!(
                (theta2 - max_theta).abs() < 1e-2 * theta2,
                "theta2 {theta2} vs {max_theta}"
            );
        }
    }
}
