//! The exact torque-free solutions against 40-digit mpmath references and against DOP853.
//!
//! References: `python/tests/reference/gen_free_body.py` (kept with its output
//! `free_body.csv`): ω(t) from mpmath's Jacobi functions (checked against Euler's equations),
//! the attitude from a tanh-sinh quadrature of φ̇ (no Π), and the whole state checked against
//! mpmath's Taylor ODE solver.

use poinsot::analytic::{FreeRegime, FreeRigidBody, FreeSymmetricTop};
use poinsot::integrate::{dop853, Options};
use poinsot::Vec3;

const FREE_CSV: &str = include_str!("../../../python/tests/reference/free_body.csv");

/// The accuracy: 1e-12 relative (to |ω|, and to the unit quaternion) at t = 1000 for
/// I = (1, 2, 3), ω₀ = (1, 0.1, 1). For the other cases the attitude's tolerance scales with the
/// largest angle the body can have turned, (|L|/I_min) t, over 1000 rad (|L|/I_min bounds the
/// precession rate φ̇): an attitude is a phase, and a double-precision rate (λ, |L|/I) carries
/// a relative error of a few ε into it.
const EXACT_RTOL: f64 = 1e-12;

fn q_dist(a: &[f64; 4], b: &[f64; 4]) -> f64 {
    let plus: f64 = (0..4).map(|k| (a[k] - b[k]).powi(2)).sum::<f64>().sqrt();
    let minus: f64 = (0..4).map(|k| (a[k] + b[k]).powi(2)).sum::<f64>().sqrt();
    plus.min(minus)
}

#[test]
fn exact_solution_matches_mpmath_to_1e_12() {
    let mut worst = (0.0f64, 0.0f64);
    let mut n = 0;
    for line in FREE_CSV
        .lines()
        .filter(|l| !l.starts_with('#') && !l.is_empty())
    {
        let (case, rest) = line.split_once(',').unwrap();
        let v: Vec<f64> = rest.split(',').map(|s| s.parse().unwrap()).collect();
        let body = FreeRigidBody::new(
            [v[0], v[1], v[2]],
            Vec3::new(v[3], v[4], v[5]),
            Some([v[6], v[7], v[8], v[9]]),
        )
        .unwrap();
        let t = v[10];
        let (w, q) = body.state(t).unwrap();
        let want_w = Vec3::new(v[11], v[12], v[13]);
        let want_q = [v[14], v[15], v[16], v[17]];
        let ew = (w - want_w).norm() / want_w.norm();
        let eq = q_dist(&q, &want_q);
        worst = (worst.0.max(ew), worst.1.max(eq));
        eprintln!(
            "{case} t={t}: |Δω|/|ω| = {ew:.2e}, |Δq| = {eq:.2e} ({:?})",
            body.regime()
        );
        let i_min = v[0].min(v[1]).min(v[2]);
        let l = (0..3)
            .map(|k| (v[k] * v[3 + k]).powi(2))
            .sum::<f64>()
            .sqrt();
        let q_tol = if case == "headline" {
            EXACT_RTOL
        } else {
            EXACT_RTOL * (l / i_min * t / 1000.0).max(1.0)
        };
        assert!(
            ew <= EXACT_RTOL && eq <= q_tol,
            "{case} at t = {t}: ω error {ew:e}, q error {eq:e}"
        );
        n += 1;
    }
    assert!(n >= 15);
    eprintln!("worst: ω {:.2e}, q {:.2e}", worst.0, worst.1);
}

/// ω̇ and q̇ of the free body in the user's principal axes, for DOP853.
fn free_rhs(moments: [f64; 3]) -> impl FnMut(f64, &[f64; 7], &mut [f64; 7]) {
    move |_t, y, dy| {
        let [i1, i2, i3] = moments;
        let (w1, w2, w3) = (y[0], y[1], y[2]);
        dy[0] = (i2 - i3) * w2 * w3 / i1;
        dy[1] = (i3 - i1) * w3 * w1 / i2;
        dy[2] = (i1 - i2) * w1 * w2 / i3;
        let (qw, qx, qy, qz) = (y[3], y[4], y[5], y[6]);
        dy[3] = -0.5 * (qx * w1 + qy * w2 + qz * w3);
        dy[4] = 0.5 * (qw * w1 + qy * w3 - qz * w2);
        dy[5] = 0.5 * (qw * w2 + qz * w1 - qx * w3);
        dy[6] = 0.5 * (qw * w3 + qx * w2 - qy * w1);
    }
}

#[test]
fn exact_solution_matches_dop853_over_random_states() {
    // A fixed-seed LCG: random moments, ω and attitude, including near-separatrix states.
    let mut seed = 0x2545F4914F6CDD1Du64;
    let mut rnd = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let opts = Options {
        dense: false,
        ..Options::with_tolerances(1e-13, 1e-15)
    };
    for case in 0..60 {
        let a = 0.5 + rnd();
        let b = a + 0.05 + rnd();
        let c = (b + 0.05 + rnd()).min(a + b);
        let mut moments = [a, b, c];
        moments.rotate_left(case % 3);
        let mut w = Vec3::new(rnd() - 0.5, rnd() - 0.5, rnd() - 0.5) * 4.0;
        if case % 4 == 0 {
            // Near the separatrix: mostly about the intermediate axis.
            let mid = (0..3).find(|&k| moments[k] == b).unwrap();
            w *= 1e-3;
            w[mid] = 2.0;
        }
        let q0 = {
            let q = [rnd() - 0.5, rnd() - 0.5, rnd() - 0.5, rnd() - 0.5];
            let n = q.iter().map(|c| c * c).sum::<f64>().sqrt();
            q.map(|c| c / n)
        };
        let body = FreeRigidBody::new(moments, w, Some(q0)).unwrap();
        let t_end = 20.0;
        let y0 = [w.x, w.y, w.z, q0[0], q0[1], q0[2], q0[3]];
        let sol = dop853(free_rhs(moments), 0.0, y0, t_end, &opts).unwrap();
        let y = sol.y_final();
        let (we, qe) = body.state(t_end).unwrap();
        let ew = (we - Vec3::new(y[0], y[1], y[2])).norm() / w.norm();
        let eq = q_dist(&qe, &[y[3], y[4], y[5], y[6]]);
        assert!(
            ew < 1e-9 && eq < 1e-9,
            "case {case} {moments:?} {w:?} ({:?}, m = {}): ω {ew:e}, q {eq:e}",
            body.regime(),
            body.parameter()
        );
    }
}

#[test]
fn special_motions_match_dop853() {
    let opts = Options {
        dense: false,
        ..Options::with_tolerances(1e-13, 1e-15)
    };
    let cases: [([f64; 3], Vec3); 9] = [
        // Within 1e-150 and 1e-9 of the unstable axis: m = 1 − 1e-299 and 1 − 1e-18, the
        // amplitude within round-off of π/2 (found by hypothesis).
        ([1.0, 2.0, 3.0], Vec3::new(0.0, 1.0, 4.799788254443611e-150)),
        ([1.0, 2.0, 3.0], Vec3::new(1e-9, 1.0, 0.0)),
        ([1.0, 2.0, 3.0], Vec3::new(3e-9, 1.0, -1e-9)),
        ([2.0, 2.0, 3.0], Vec3::new(0.3, -1.0, 2.0)), // oblate symmetric
        ([1.0, 2.0, 2.0], Vec3::new(0.3, -1.0, 2.0)), // prolate, symmetry axis 1
        ([2.0, 1.0, 2.0], Vec3::new(0.3, -1.0, 2.0)), // symmetry axis 2
        ([1.5, 1.5, 1.5], Vec3::new(0.3, -1.0, 2.0)), // spherical
        ([1.0, 2.0, 3.0], Vec3::new(0.0, 1.3, 0.0)),  // steady about the intermediate axis
        ([1.0, 2.0, 3.0], Vec3::new(0.6, 0.0, 0.3)),  // ω₂ = 0: a polhode crossing
    ];
    for (moments, w) in cases {
        let q0 = [0.5, 0.5, 0.5, 0.5];
        let body = FreeRigidBody::new(moments, w, Some(q0)).unwrap();
        let y0 = [w.x, w.y, w.z, q0[0], q0[1], q0[2], q0[3]];
        let sol = dop853(free_rhs(moments), 0.0, y0, 15.0, &opts).unwrap();
        let y = sol.y_final();
        let (we, qe) = body.state(15.0).unwrap();
        let ew = (we - Vec3::new(y[0], y[1], y[2])).norm() / w.norm();
        let eq = q_dist(&qe, &[y[3], y[4], y[5], y[6]]);
        assert!(
            ew < 1e-10 && eq < 1e-10,
            "{moments:?} {w:?} ({:?}): ω {ew:e}, q {eq:e}",
            body.regime()
        );
    }
}

#[test]
fn separatrix_motion_is_exact() {
    // L² = 2TI₂ exactly for I = (1, 2, 3) with I₁(I₁ − I₂)ω₁² + I₃(I₃ − I₂)ω₃² = 0:
    // ω₁² = 3 ω₃² (ω₃ = 0.25 and ω₁² = 0.1875 are exact in binary).
    let w = Vec3::new(0.1875f64.sqrt(), 0.2, 0.25);
    let w = Vec3::new(w.x, w.y, (w.x * w.x / 3.0).sqrt());
    let body = FreeRigidBody::new([1.0, 2.0, 3.0], w, None).unwrap();
    if body.regime() == FreeRegime::Separatrix {
        assert!(body.period().unwrap().is_infinite());
    }
    let opts = Options {
        dense: false,
        ..Options::with_tolerances(1e-13, 1e-15)
    };
    let y0 = [w.x, w.y, w.z, 1.0, 0.0, 0.0, 0.0];
    let sol = dop853(free_rhs([1.0, 2.0, 3.0]), 0.0, y0, 10.0, &opts).unwrap();
    let y = sol.y_final();
    let (we, qe) = body.state(10.0).unwrap();
    assert!(
        (we - Vec3::new(y[0], y[1], y[2])).norm() < 1e-9,
        "{:?} {we:?} {y:?}",
        body.regime()
    );
    assert!(q_dist(&qe, &[y[3], y[4], y[5], y[6]]) < 1e-9);
}

#[test]
fn symmetric_top_closed_forms() {
    let top = FreeSymmetricTop::new(2.0, 1.0, Vec3::new(0.3, 0.4, 2.0), None).unwrap();
    // Ω = (I₁ − I₃) ω₃ / I₁ (2.83).
    assert!((top.precession_rate() - 1.0).abs() < 1e-15);
    assert!((top.amplitude() - 0.5).abs() < 1e-15);
    let body = FreeRigidBody::new([2.0, 2.0, 1.0], Vec3::new(0.3, 0.4, 2.0), None).unwrap();
    for &t in &[0.0, 0.7, 13.0, 400.0] {
        assert!((top.omega(t).unwrap() - body.omega(t).unwrap()).norm() < 1e-14);
        assert!(q_dist(&top.attitude(t).unwrap(), &body.attitude(t).unwrap()) < 1e-13);
    }
}
