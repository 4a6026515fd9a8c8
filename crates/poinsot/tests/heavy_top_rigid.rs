//! The exact heavy-top solution against the top integrated numerically as a rigid body under
//! gravity (Euler's equations with the gravity torque, attitude as a rotation matrix, the
//! crate's DOP853), and the sleeping-top threshold by simulation on both sides of it.
//!
//! The rigid body knows nothing of Euler angles, p_φ or the cubic: it is the independent model.
//! Body frame = principal axes at the pivot, I = diag(I₁, I₁, I₃); the centre of mass at l ê₃;
//! the torque of gravity (−mg Ẑ) in body axes is `τ = −m g l ê₃ × (Rᵀ Ẑ)`; Ṙ = R [ω]×.

use poinsot::analytic::{sleeping_threshold, EulerState, HeavyTop};
use poinsot::integrate::{dop853, Options};
use poinsot::rotation::{euler_to_matrix, EulerSequence};
use poinsot::Mat3;

/// DOP853 at rtol = atol = 1e-13 over ~20 s: global error ≲ 1e-10; the bound leaves margin.
const RIGID_BODY_TOL: f64 = 1e-8;

fn zxz() -> EulerSequence {
    EulerSequence::new("zxz", true).unwrap()
}

/// The state [R (row-major), ω_body] of the rigid body at the Euler state `s` (2.99 for ω).
fn rigid_state(s: &EulerState) -> [f64; 12] {
    let r = euler_to_matrix([s.phi, s.theta, s.psi], zxz()).unwrap();
    let (st, ct) = s.theta.sin_cos();
    let (sp, cp) = s.psi.sin_cos();
    let w = [
        s.theta_dot * cp + s.phi_dot * st * sp,
        -s.theta_dot * sp + s.phi_dot * st * cp,
        s.psi_dot + s.phi_dot * ct,
    ];
    let mut y = [0.0; 12];
    for i in 0..3 {
        for j in 0..3 {
            y[3 * i + j] = r[(i, j)];
        }
    }
    y[9..].copy_from_slice(&w);
    y
}

/// Integrates the rigid top; returns R at each of `times`.
fn integrate_rigid(i1: f64, i3: f64, mgl: f64, s: &EulerState, times: &[f64]) -> Vec<Mat3> {
    let rhs = move |_t: f64, y: &[f64; 12], dy: &mut [f64; 12]| {
        let (w1, w2, w3) = (y[9], y[10], y[11]);
        // Ṙ = R [ω]×, row by row: (r × ... ) written out.
        for i in 0..3 {
            let (a, b, c) = (y[3 * i], y[3 * i + 1], y[3 * i + 2]);
            dy[3 * i] = b * w3 - c * w2;
            dy[3 * i + 1] = c * w1 - a * w3;
            dy[3 * i + 2] = a * w2 - b * w1;
        }
        // Rᵀ Ẑ is the third row of R; τ = −mgl ê₃ × (R₃₁, R₃₂, R₃₃) = mgl (R₃₂, −R₃₁, 0).
        let (tau1, tau2) = (mgl * y[7], -mgl * y[6]);
        // Euler's equations for I = diag(I₁, I₁, I₃).
        dy[9] = (tau1 - (i3 - i1) * w2 * w3) / i1;
        dy[10] = (tau2 - (i1 - i3) * w3 * w1) / i1;
        dy[11] = 0.0;
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
            Mat3::from_row_slice(&y[..9])
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
        for (t, r) in times.iter().zip(&rigid) {
            let exact = euler_to_matrix(top.euler_angles(*t), zxz()).unwrap();
            let err = (exact - r).abs().max();
            assert!(
                err < RIGID_BODY_TOL,
                "{s:?} ({:?}) at t = {t}: |ΔR| = {err:e}",
                top.motion_class()
            );
        }
        // L_Z = p_φ and L₃ = p_ψ along the rigid body (the space-frame angular momentum's Z
        // component is R·(I ω) · Ẑ).
        let sol_l = |r: &Mat3, t: f64| {
            let [phd, thd, psd] = top.euler_rates(t);
            let [_, th, ps] = top.euler_angles(t);
            let s2 = EulerState {
                theta: th,
                psi: ps,
                phi_dot: phd,
                theta_dot: thd,
                psi_dot: psd,
                ..Default::default()
            };
            let w = rigid_state(&s2);
            let l_body = poinsot::Vec3::new(i1 * w[9], i1 * w[10], i3 * w[11]);
            ((r * l_body).z, l_body.z)
        };
        for (t, r) in times.iter().zip(&rigid) {
            let (lz, l3) = sol_l(r, *t);
            let tol = 1e-7 * (1.0 + top.p_phi().abs() + top.p_psi().abs());
            assert!(
                (lz - top.p_phi()).abs() < tol && (l3 - top.p_psi()).abs() < tol,
                "t = {t}: L_Z {lz} p_phi {}",
                top.p_phi()
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
            .map(|r| r[(2, 2)].clamp(-1.0, 1.0).acos())
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
