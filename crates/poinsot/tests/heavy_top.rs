//! The heavy symmetric top: constants of motion, effective potential, turning points, motion
//! classes, steady precession and the errata of the unit's 2.117 and 2.120.

mod common;
use common::top;

use poinsot::analytic::{
    constants_of_state, lagrangian, min_spin, sleeping_threshold, steady_precession, EulerState,
    HeavyTop, MotionClass, VerticalPass,
};
use poinsot::ErrorKind;
use proptest::prelude::*;

/// Round-off of quantities built from O(1) data by a few dozen operations.
const ROUND_OFF: f64 = 1e-13;

/// The errata example of `seed-errata.md`: the exact fast rate of 2.116 is 24.2176 and the
/// corrected 2.120, p_ψ/(I₁ cos θ₀), gives 24.2326; the unit's printed p_ψ/(2 I₁ cos θ₀) is off
/// by a factor 2. A regression to the printed formula fails the first assertion.
#[test]
fn test_erratum_2_120_fast_precession_has_no_factor_half() {
    let s = steady_precession(1.0, 0.5, 0.3, 0.6, 40.0).unwrap();
    assert!(
        (s.fast - 24.2176).abs() < 5e-5,
        "exact fast root {}",
        s.fast
    );
    assert!(
        (s.fast_approx - 24.2326).abs() < 5e-5,
        "p_psi/(I1 cos th0) = {}",
        s.fast_approx
    );
    assert!((s.fast_approx - s.fast).abs() / s.fast < 1e-3);
    // The misprint is a factor 2 away from the truth.
    assert!((s.fast_approx_as_printed / s.fast - 0.5).abs() < 1e-3);
    // The slow root and 2.121 agree to the same order (m g l I₁ cos θ₀ / p_ψ² ≈ 6e-4).
    assert!((s.slow - s.slow_approx.unwrap()).abs() / s.slow < 1e-3);
}

/// 2.117 with the erratum fixed: the discriminant is 1 − 4 m g l I₁ cos θ₀ / p_ψ² (the unit
/// prints p_φ²). Pinned three ways: (1) the rates exist exactly down to the minimum spin 2.119,
/// which is derived from p_ψ; (2) a top started at either rate does not nutate; (3) the
/// misprinted discriminant, with the steady top's own p_φ, gives rates at which it does nutate.
#[test]
fn test_erratum_2_117_discriminant_has_p_psi_squared() {
    let (i1, i3, mgl, th0) = (1.0, 0.5, 1.0, 0.8);
    let wmin = min_spin(i1, i3, mgl, th0).unwrap();
    assert!(steady_precession(i1, i3, mgl, th0, wmin * (1.0 + 1e-9)).is_ok());
    let err = steady_precession(i1, i3, mgl, th0, wmin * (1.0 - 1e-9)).unwrap_err();
    assert!(
        err.argument == "omega3" && err.message.contains("2.119"),
        "{err}"
    );

    let w3 = 6.0;
    let s = steady_precession(i1, i3, mgl, th0, w3).unwrap();
    let (sn, c) = th0.sin_cos();
    let p_psi = i3 * w3;
    for rate in [s.slow, s.fast] {
        let t = top(i1, i3, mgl, th0, 0.0, rate, w3 - rate * c);
        assert_eq!(
            t.motion_class(),
            MotionClass::SteadyPrecession,
            "rate {rate}"
        );
        let (t1, t2) = t.turning_points();
        assert!(
            t2 - t1 < 1e-12,
            "nutation {} at the exact rate {rate}",
            t2 - t1
        );
        // b = p_φ − p_ψ cos θ₀ solves 2.116.
        let b = t.p_phi() - p_psi * c;
        let res = b * b * c - b * p_psi * sn.powi(2) + mgl * i1 * sn.powi(4);
        assert!(
            res.abs() < ROUND_OFF * (b * p_psi).abs(),
            "2.116 residual {res}"
        );
        // The printed 2.117 (p_φ² under the root) misses the root.
        let p_phi = t.p_phi();
        let disc = 1.0 - 4.0 * mgl * i1 * c / (p_phi * p_phi);
        let sign = if rate == s.slow { -1.0 } else { 1.0 };
        let b_misprint = p_psi * sn * sn / (2.0 * c) * (1.0 + sign * disc.sqrt());
        let rate_misprint = b_misprint / (i1 * sn * sn);
        let t_bad = top(i1, i3, mgl, th0, 0.0, rate_misprint, w3 - rate_misprint * c);
        let (b1, b2) = t_bad.turning_points();
        assert!(
            b2 - b1 > 1e-3,
            "the misprinted 2.117 gives {rate_misprint}, nutation {}",
            b2 - b1
        );
    }
}

/// 2.120 (corrected) and 2.121 approach the exact roots as 1/ω₃²: doubling the spin divides
/// their relative errors by ≈ 4.
#[test]
fn fast_top_approximations_converge_quadratically() {
    let (i1, i3, mgl, th0) = (1.0, 0.5, 0.3, 0.6);
    let rel = |w3: f64| {
        let s = steady_precession(i1, i3, mgl, th0, w3).unwrap();
        (
            (s.slow_approx.unwrap() - s.slow).abs() / s.slow,
            (s.fast_approx - s.fast).abs() / s.fast,
        )
    };
    let (s1, f1) = rel(40.0);
    let (s2, f2) = rel(80.0);
    assert!(
        (s1 / s2 - 4.0).abs() < 0.05 && (f1 / f2 - 4.0).abs() < 0.05,
        "{s1} {s2} {f1} {f2}"
    );
}

#[test]
fn minimum_spin_2_119_and_sleeping_threshold() {
    let (i1, i3, mgl) = (1.3, 0.7, 0.9);
    let th0: f64 = 0.4;
    let expect = 2.0 / i3 * (mgl * i1 * th0.cos()).sqrt();
    assert!((min_spin(i1, i3, mgl, th0).unwrap() - expect).abs() < ROUND_OFF * expect);
    assert_eq!(min_spin(i1, i3, mgl, 2.0).unwrap(), 0.0);
    let thr = sleeping_threshold(i1, i3, mgl).unwrap();
    assert!((thr - min_spin(i1, i3, mgl, 0.0).unwrap()).abs() < ROUND_OFF * thr);
    // ω₃² > 4 m g l I₁ / I₃² decides.
    let up = top(i1, i3, mgl, 0.0, 0.0, 0.0, thr * 1.001);
    let down = top(i1, i3, mgl, 0.0, 0.0, 0.0, thr * 0.999);
    assert_eq!(up.motion_class(), MotionClass::Sleeping);
    assert_eq!(down.motion_class(), MotionClass::Sleeping);
    assert!(up.is_sleeping_stable() && !down.is_sleeping_stable());
    assert!(up.nutation_period().is_some() && down.nutation_period().is_none());
}

/// 2.113 against central differences of 2.110, on both sides of the equator and with loops
/// (p_φ of either sign).
#[test]
fn derivative_2_113_matches_finite_differences_of_2_110() {
    for (th0, phd) in [(0.8, 0.0), (0.8, -0.5), (2.4, 0.7), (0.05, 3.0)] {
        let t = top(1.0, 0.5, 1.0, th0, 0.2, phd, 6.0);
        for k in 1..40 {
            let th = std::f64::consts::PI * k as f64 / 40.0;
            let h = 1e-5;
            let fd = (t.effective_potential(th + h).unwrap()
                - t.effective_potential(th - h).unwrap())
                / (2.0 * h);
            let d = t.effective_potential_derivative(th).unwrap();
            assert!(
                (fd - d).abs() < 1e-7 * (1.0 + d.abs()),
                "theta {th}: 2.113 {d} vs fd {fd}"
            );
        }
    }
}

/// The constants 2.103–2.109 from the initial state, against their definitions written out.
#[test]
fn constants_of_motion_from_the_state() {
    let (i1, i3, mgl) = (1.2, 0.6, 0.8);
    let st = EulerState {
        phi: 0.3,
        theta: 1.1,
        psi: -0.2,
        phi_dot: 0.7,
        theta_dot: -0.4,
        psi_dot: 5.0,
    };
    let t = HeavyTop::new(i1, i3, mgl, st).unwrap();
    let (s, c) = st.theta.sin_cos();
    let w3 = st.psi_dot + st.phi_dot * c;
    let p_psi = i3 * w3;
    let p_phi = i1 * st.phi_dot * s * s + i3 * w3 * c;
    let e =
        0.5 * i1 * (st.theta_dot.powi(2) + (st.phi_dot * s).powi(2)) + 0.5 * i3 * w3 * w3 + mgl * c;
    let close = |a: f64, b: f64| (a - b).abs() <= ROUND_OFF * (1.0 + b.abs());
    assert!(close(t.p_psi(), p_psi) && close(t.p_phi(), p_phi) && close(t.energy(), e));
    assert!(close(t.omega3(), w3));
    let ep = e - p_psi * p_psi / (2.0 * i3);
    assert!(close(t.reduced_energy(), ep));
    // E' = ½ I₁ θ̇² + V(θ) (2.109).
    assert!(close(
        ep,
        0.5 * i1 * st.theta_dot.powi(2) + t.effective_potential(st.theta).unwrap()
    ));
    // L = T − V (2.102).
    let l = lagrangian(i1, i3, mgl, &st).unwrap();
    assert!(close(l, e - 2.0 * mgl * c));
}

/// At the turning points E' = V(θ) (2.109 with θ̇ = 0); released at rest (θ̇₀ = 0) the start is
/// a turning point exactly; the motion never leaves [θ₁, θ₂].
#[test]
fn turning_points_are_where_the_effective_potential_meets_e_prime() {
    for (th0, thd, phd, psd) in [
        (0.8, 0.0, 0.0, 6.0),
        (0.8, 0.3, 0.6, 6.0),
        (2.5, 0.5, 0.3, 2.0),
        (0.01, 0.001, 0.2, 10.0),
    ] {
        let t = top(1.0, 0.5, 1.0, th0, thd, phd, psd);
        let (t1, t2) = t.turning_points();
        assert!(t1 < t2);
        let ep = t.reduced_energy();
        for th in [t1, t2] {
            let v = t.effective_potential(th).unwrap();
            assert!(
                (v - ep).abs() < 1e-12 * ep.abs().max(1.0),
                "V({th}) = {v}, E' = {ep}"
            );
        }
        if thd == 0.0 {
            assert!(t1 == th0 || t2 == th0);
        }
        let period = t.nutation_period().unwrap();
        for k in 0..200 {
            let th = t.euler_angles(period * k as f64 / 97.0).unwrap()[1];
            assert!(th >= t1 - 1e-14 && th <= t2 + 1e-14);
        }
    }
}

/// The path classes of Goldstein Fig. 5.9 and the poles.
#[test]
fn motion_classes() {
    let cls = |th, thd, phd, psd| top(1.0, 0.5, 1.0, th, thd, phd, psd).motion_class();
    assert_eq!(cls(0.8, 0.0, 0.0, 6.0), MotionClass::Cusps);
    assert_eq!(cls(0.8, 0.0, -0.5, 6.0), MotionClass::Loops);
    assert_eq!(cls(0.8, 0.0, 0.5, 6.0), MotionClass::Waves);
    assert_eq!(cls(0.0, 0.0, 0.0, 6.0), MotionClass::Sleeping);
    assert_eq!(
        cls(std::f64::consts::PI, 0.0, 0.0, 6.0),
        MotionClass::Hanging
    );
    // A spherical pendulum released at rest swings through the bottom.
    assert_eq!(cls(0.8, 0.0, 0.0, 0.0), MotionClass::ThroughVertical);
    assert_eq!(MotionClass::Cusps.name(), "cusps");
}

/// φ̇ from the exact solution against the sign test that defines the classes: one sign on
/// waves, both signs on loops, zero at θ₁ for cusps.
#[test]
fn classes_match_the_sign_of_phi_dot_along_the_motion() {
    for (phd, class) in [
        (0.5, MotionClass::Waves),
        (-0.5, MotionClass::Loops),
        (0.0, MotionClass::Cusps),
    ] {
        let t = top(1.0, 0.5, 1.0, 0.8, 0.0, phd, 6.0);
        assert_eq!(t.motion_class(), class);
        let period = t.nutation_period().unwrap();
        let rates: Vec<f64> = (0..400)
            .map(|k| t.euler_rates(period * k as f64 / 400.0).unwrap()[0])
            .collect();
        let (lo, hi) = rates
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &r| {
                (a.min(r), b.max(r))
            });
        match class {
            MotionClass::Waves => assert!(lo > 0.0),
            MotionClass::Loops => assert!(lo < 0.0 && hi > 0.0),
            _ => assert!(rates[0].abs() < 1e-15 && lo >= -1e-15),
        }
    }
}

/// p_φ (= L_Z), p_ψ and E recomputed from the exact angles and rates at many times equal their
/// initial values; the rates equal central differences of the angles.
#[test]
fn constants_are_conserved_along_the_exact_solution() {
    let (i1, i3, mgl) = (1.0, 0.5, 1.0);
    for (th0, thd, phd, psd) in [
        (0.8, 0.3, 0.6, 6.0),
        (0.8, 0.0, -0.5, 6.0),
        (2.5, 0.5, 0.3, 2.0),
        (0.01, 0.001, 0.2, 10.0),
    ] {
        let t = top(i1, i3, mgl, th0, thd, phd, psd);
        for k in 0..50 {
            let time = 0.173 * k as f64;
            let [ph, th, ps] = t.euler_angles(time).unwrap();
            let [phd, thd, psd] = t.euler_rates(time).unwrap();
            let st = EulerState {
                phi: ph,
                theta: th,
                psi: ps,
                phi_dot: phd,
                theta_dot: thd,
                psi_dot: psd,
            };
            let c = HeavyTop::new(i1, i3, mgl, st).unwrap();
            let tol = 1e-12 * (1.0 + t.p_psi().abs() + t.p_phi().abs());
            assert!(
                (c.p_phi() - t.p_phi()).abs() < tol,
                "p_phi at {time}: {} vs {}",
                c.p_phi(),
                t.p_phi()
            );
            assert!((c.p_psi() - t.p_psi()).abs() < tol);
            assert!((c.energy() - t.energy()).abs() < 1e-12 * (1.0 + t.energy().abs()));
            // Rates against central differences of the angles (h³ error of the difference).
            let h = 1e-5;
            let (a, b) = (
                t.euler_angles(time - h).unwrap(),
                t.euler_angles(time + h).unwrap(),
            );
            for i in 0..3 {
                let fd = (b[i] - a[i]) / (2.0 * h);
                assert!(
                    (fd - [phd, thd, psd][i]).abs() < 1e-6 * (1.0 + fd.abs()),
                    "{i} at {time}"
                );
            }
        }
    }
}

/// θ is periodic with the nutation period, φ and ψ advance by their mean rates times it.
#[test]
fn nutation_period_and_mean_rates() {
    let t = top(1.0, 0.5, 1.0, 0.8, 0.3, 0.6, 6.0);
    let p = t.nutation_period().unwrap();
    for k in 0..10 {
        let t0 = 0.37 * k as f64;
        let (a, b) = (t.euler_angles(t0).unwrap(), t.euler_angles(t0 + p).unwrap());
        assert!((a[1] - b[1]).abs() < 1e-13);
        assert!((b[0] - a[0] - t.mean_precession_rate() * p).abs() < 1e-12);
        assert!((b[2] - a[2] - t.mean_spin_rate() * p).abs() < 1e-12);
    }
}

/// The precession period is the time of one turn about the vertical: for steady precession φ
/// advances by exactly 2π in it; for a nutating top φ advances by 2π·k over k precession
/// periods to within one nutation's wobble of φ about its mean line (|φ − ⟨φ̇⟩t − φ₀| stays
/// below the spread of φ over a nutation period). A sleeping top does not turn: no period.
/// Negative control: 2π/|φ̇₀| (the start rate, not the mean) misses the turn of a nutating top.
#[test]
fn precession_period_is_one_turn_about_the_vertical() {
    use std::f64::consts::TAU;
    let steady = steady_precession(1.0, 0.5, 1.0, 0.8, 12.0).unwrap().slow;
    let s = HeavyTop::with_spin(1.0, 0.5, 1.0, 0.0, 0.8, 0.0, steady, 0.0, 12.0).unwrap();
    let p = s.precession_period().unwrap();
    assert!((p - TAU / steady).abs() < 1e-9 * p);
    assert!((s.euler_angles(p).unwrap()[0] - TAU).abs() < 1e-9);

    let t = top(1.0, 0.5, 1.0, 0.8, 0.3, 0.6, 6.0);
    let (n, q) = (t.nutation_period().unwrap(), t.precession_period().unwrap());
    assert!((q - TAU / t.mean_precession_rate().abs()).abs() < 1e-12 * q);
    // After a whole number of nutation periods nearest to k precession periods, φ has turned
    // by k·2π plus at most the mean rate times half a nutation period.
    for k in 1..4 {
        let m = (k as f64 * q / n).round();
        let turned = t.euler_angles(m * n).unwrap()[0] - t.euler_angles(0.0).unwrap()[0];
        let slack = t.mean_precession_rate().abs() * n / 2.0 + 1e-9;
        assert!(
            (turned.abs() - k as f64 * TAU).abs() <= slack,
            "k = {k}: {turned}"
        );
    }
    // Negative control: the start rate φ̇₀ = 0.3 rad/s is not the mean.
    assert!((TAU / 0.3 - q).abs() > 0.1 * q);

    let sleeping = top(1.0, 0.5, 1.0, 0.0, 0.0, 0.0, 10.0);
    assert_eq!(sleeping.precession_period(), None);
}

#[test]
fn from_constants_reproduces_the_top_with_those_constants() {
    let a = top(1.0, 0.5, 1.0, 0.8, 0.3, 0.6, 6.0);
    let b = HeavyTop::from_constants(1.0, 0.5, 1.0, a.p_phi(), a.p_psi(), a.energy()).unwrap();
    let (a1, a2) = a.turning_points();
    let (b1, b2) = b.turning_points();
    assert!((a1 - b1).abs() < 1e-12 && (a2 - b2).abs() < 1e-12);
    assert_eq!(a.motion_class(), b.motion_class());
    assert!((a.nutation_period().unwrap() - b.nutation_period().unwrap()).abs() < 1e-12);
    // b starts at θ₁: θ_b(t) = θ_a(t + t₁) where a reaches θ₁ at t₁.
    assert!((b.euler_angles(0.0).unwrap()[1] - b1).abs() < 1e-15);
    assert!((b.mean_precession_rate() - a.mean_precession_rate()).abs() < 1e-12);
    // Below the minimum of V: refused, naming the energy.
    let e = HeavyTop::from_constants(1.0, 0.5, 1.0, a.p_phi(), a.p_psi(), a.energy() - 10.0)
        .unwrap_err();
    assert_eq!(e.argument, "energy");
}

/// Bad input: the error names the argument and the condition.
#[test]
fn bad_input_is_refused_naming_the_argument() {
    let st = EulerState {
        theta: 0.5,
        psi_dot: 3.0,
        ..Default::default()
    };
    let cases: Vec<(&str, poinsot::Result<HeavyTop>)> = vec![
        ("I1", HeavyTop::new(0.0, 0.5, 1.0, st)),
        ("I1", HeavyTop::new(-1.0, 0.5, 1.0, st)),
        ("I1", HeavyTop::new(f64::NAN, 0.5, 1.0, st)),
        ("I3", HeavyTop::new(1.0, 0.0, 1.0, st)),
        ("I3", HeavyTop::new(1.0, -0.5, 1.0, st)),
        ("I3", HeavyTop::new(1.0, f64::INFINITY, 1.0, st)),
        ("I3", HeavyTop::new(1.0, 2.5, 1.0, st)),
        ("mgl", HeavyTop::new(1.0, 0.5, -1.0, st)),
        ("mgl", HeavyTop::new(1.0, 0.5, f64::NAN, st)),
        (
            "theta",
            HeavyTop::new(1.0, 0.5, 1.0, EulerState { theta: -0.1, ..st }),
        ),
        (
            "theta",
            HeavyTop::new(1.0, 0.5, 1.0, EulerState { theta: 3.2, ..st }),
        ),
        (
            "theta",
            HeavyTop::new(
                1.0,
                0.5,
                1.0,
                EulerState {
                    theta: f64::NAN,
                    ..st
                },
            ),
        ),
        (
            "theta_dot",
            HeavyTop::new(
                1.0,
                0.5,
                1.0,
                EulerState {
                    theta_dot: f64::INFINITY,
                    ..st
                },
            ),
        ),
        (
            "phi_dot",
            HeavyTop::new(
                1.0,
                0.5,
                1.0,
                EulerState {
                    phi_dot: f64::NAN,
                    ..st
                },
            ),
        ),
        (
            "psi_dot",
            HeavyTop::new(
                1.0,
                0.5,
                1.0,
                EulerState {
                    psi_dot: f64::NAN,
                    ..st
                },
            ),
        ),
        (
            "p_phi",
            HeavyTop::from_constants(1.0, 0.5, 1.0, f64::NAN, 1.0, 1.0),
        ),
        (
            "energy",
            HeavyTop::from_constants(1.0, 0.5, 1.0, 1.0, 1.0, f64::INFINITY),
        ),
    ];
    for (arg, r) in cases {
        let e = r.unwrap_err();
        assert_eq!(e.argument, arg, "{e}");
        assert!(e.to_string().starts_with(&format!("{arg}:")), "{e}");
    }
    assert_eq!(
        HeavyTop::new(1.0, 2.5, 1.0, st).unwrap_err().kind,
        ErrorKind::InvalidInertia
    );
    let t = top(1.0, 0.5, 1.0, 0.5, 0.0, 0.0, 3.0);
    assert_eq!(t.effective_potential(4.0).unwrap_err().argument, "theta");
    assert_eq!(
        steady_precession(1.0, 0.5, 1.0, 0.5, f64::NAN)
            .unwrap_err()
            .argument,
        "omega3"
    );
    assert_eq!(
        steady_precession(1.0, 0.5, 1.0, -1.0, 3.0)
            .unwrap_err()
            .argument,
        "theta0"
    );
    let mut out = vec![0.0; 6];
    assert_eq!(
        t.euler_angles_into(&[0.0, f64::NAN], &mut out)
            .unwrap_err()
            .argument,
        "times"
    );
}

/// Starting at a pole with θ̇ < 0 is the same motion as θ̇ > 0 with the line of nodes reversed.
#[test]
fn negative_theta_dot_at_the_pole_is_reflected() {
    let a = HeavyTop::new(
        1.0,
        0.5,
        1.0,
        EulerState {
            theta: 0.0,
            theta_dot: -0.5,
            psi_dot: 6.0,
            ..Default::default()
        },
    )
    .unwrap();
    let s = a.initial_state();
    assert!(s.theta_dot > 0.0 && (s.phi - std::f64::consts::PI).abs() < 1e-15);
    let [_, th, _] = a.euler_angles(0.3).unwrap();
    assert!(th > 0.0);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]
    /// Random tops: θ stays in [θ₁, θ₂]; E' = ½I₁θ̇² + V(θ) along the motion; the state at a later
    /// time, taken as a new start, continues the same motion.
    #[test]
    fn random_tops_keep_their_invariants(
        i3 in 0.1f64..2.0, mgl in 0.0f64..3.0, th0 in 0.05f64..3.09,
        thd in -2.0f64..2.0, phd in -3.0f64..3.0, w3 in -20.0f64..20.0, t in 0.0f64..20.0,
    ) {
        let i1 = 1.0;
        let c = th0.cos();
        let st = EulerState { theta: th0, theta_dot: thd, phi_dot: phd, psi_dot: w3 - phd * c, ..Default::default() };
        let a = HeavyTop::new(i1, i3, mgl, st).unwrap();
        let (t1, t2) = a.turning_points();
        let [ph, th, ps] = a.euler_angles(t).unwrap();
        let [phd_t, thd_t, psd_t] = a.euler_rates(t).unwrap();
        prop_assert!(th >= t1 - 1e-12 && th <= t2 + 1e-12);
        let ep = 0.5 * i1 * thd_t * thd_t + a.effective_potential(th).unwrap();
        let scale = 1.0 + a.reduced_energy().abs() + a.p_phi().powi(2) + a.p_psi().powi(2);
        prop_assert!((ep - a.reduced_energy()).abs() < 1e-10 * scale, "{} vs {}", ep, a.reduced_energy());
        let b = HeavyTop::new(i1, i3, mgl, EulerState { phi: ph, theta: th, psi: ps, phi_dot: phd_t, theta_dot: thd_t, psi_dot: psd_t }).unwrap();
        let (x, y) = (a.euler_angles(t + 0.7).unwrap(), b.euler_angles(0.7).unwrap());
        prop_assert!((x[1] - y[1]).abs() < 1e-9, "theta {} vs {}", x[1], y[1]);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]
    /// The Fourier fast path (closed-form coefficients from Jacobi's theta expansions) equals the
    /// incomplete integrals (sn and Carlson's R_J at each time) on random tops, to round-off:
    /// 1e-12 absolute for |angle| ≤ 1, relative above.
    #[test]
    fn fourier_path_equals_the_incomplete_integrals(
        i3 in 0.1f64..2.0, mgl in 0.0f64..3.0, th0 in 0.01f64..3.13,
        thd in -3.0f64..3.0, phd in -4.0f64..4.0, w3 in -25.0f64..25.0,
    ) {
        let c = th0.cos();
        let st = EulerState { theta: th0, theta_dot: thd, phi_dot: phd, psi_dot: w3 - phd * c, phi: 0.4, psi: -1.3 };
        let top = HeavyTop::new(1.0, i3, mgl, st).unwrap();
        let times: Vec<f64> = (0..64).map(|k| 0.61 * k as f64 - 3.0).collect();
        let mut batch = vec![0.0; 3 * times.len()];
        top.euler_angles_into(&times, &mut batch).unwrap();
        for (k, &t) in times.iter().enumerate() {
            let a = top.euler_angles(t).unwrap();
            let b = top.euler_angles_carlson(t).unwrap();
            for i in 0..3 {
                let scale = b[i].abs().max(1.0);
                prop_assert!((a[i] - b[i]).abs() < 1e-12 * scale, "t {} comp {}: {} vs {} ({} terms)", t, i, a[i], b[i], top.fourier_terms());
                prop_assert!((batch[3 * k + i] - b[i]).abs() < 1e-12 * scale, "batch t {} comp {}", t, i);
            }
        }
    }
}

/// `constants_of_state` at the initial state is bit-identical to the top's constants; at the
/// exact state at time t it equals them to round-off (the drift of the solution); the energy agrees
/// with an independent form, ½ Σ Iᵢωᵢ² + m g l cos θ from the body angular velocity of the z-x-z
/// Euler rates; a state perturbed by 1e-5 in θ̇ is detected (negative control).
#[test]
fn constants_of_state_equal_the_constants_along_the_motion() {
    let (i1, i3, mgl) = (1.3, 0.7, 2.0);
    for (th0, thd, phd, psd) in [
        (0.6, 0.0, 0.0, 9.0),  // cusps
        (0.6, 0.0, 1.5, 9.0),  // waves
        (0.6, 0.0, -1.0, 9.0), // loops
        (2.4, 0.4, 0.3, 1.0),  // below the horizontal
    ] {
        let st0 = EulerState {
            phi: 0.3,
            theta: th0,
            psi: -0.2,
            phi_dot: phd,
            theta_dot: thd,
            psi_dot: psd,
        };
        let t = HeavyTop::new(i1, i3, mgl, st0).unwrap();
        let c0 = constants_of_state(i1, i3, mgl, &st0).unwrap();
        assert_eq!(
            (c0.p_phi, c0.p_psi, c0.energy),
            (t.p_phi(), t.p_psi(), t.energy())
        );
        let scale_e = t.energy().abs() + 0.5 * i3 * t.omega3().powi(2) + mgl;
        let scale_p = t.p_phi().abs() + t.p_psi().abs();
        for k in 0..40 {
            let time = 0.137 * k as f64;
            let [ph, th, ps] = t.euler_angles(time).unwrap();
            let [phd, thd, psd] = t.euler_rates(time).unwrap();
            let st = EulerState {
                phi: ph,
                theta: th,
                psi: ps,
                phi_dot: phd,
                theta_dot: thd,
                psi_dot: psd,
            };
            let c = constants_of_state(i1, i3, mgl, &st).unwrap();
            assert!(
                (c.energy - t.energy()).abs() <= 1e-12 * scale_e,
                "E at {time}"
            );
            assert!(
                (c.p_phi - t.p_phi()).abs() <= 1e-12 * scale_p,
                "p_phi at {time}"
            );
            assert!(
                (c.p_psi - t.p_psi()).abs() <= 1e-12 * scale_p,
                "p_psi at {time}"
            );
            // Independent: body ω of the z-x-z rates, T = ½ Σ Iᵢ ωᵢ².
            let (sth, cth) = th.sin_cos();
            let (sps, cps) = ps.sin_cos();
            let w1 = phd * sth * sps + thd * cps;
            let w2 = phd * sth * cps - thd * sps;
            let w3 = phd * cth + psd;
            let e = 0.5 * (i1 * (w1 * w1 + w2 * w2) + i3 * w3 * w3) + mgl * cth;
            assert!(
                (c.energy - e).abs() <= 1e-12 * scale_e,
                "E vs body omega at {time}"
            );
            // Negative control: θ̇ off by 1e-5 rad/s shows in E (ΔE ≈ I₁ θ̇ · 1e-5, far above
            // the tolerance wherever |θ̇| > 0.05).
            if thd.abs() > 0.05 {
                let bad = EulerState {
                    theta_dot: thd + 1e-5,
                    ..st
                };
                let cb = constants_of_state(i1, i3, mgl, &bad).unwrap();
                assert!((cb.energy - t.energy()).abs() > 10.0 * 1e-12 * scale_e);
            }
        }
    }
    let st = EulerState {
        theta: 4.0,
        ..Default::default()
    };
    let e = constants_of_state(1.0, 0.5, 1.0, &st).unwrap_err();
    assert!(e.to_string().starts_with("theta"), "{e}");
    let st = EulerState {
        theta: 1.0,
        psi_dot: f64::NAN,
        ..Default::default()
    };
    assert!(constants_of_state(1.0, 0.5, 1.0, &st)
        .unwrap_err()
        .to_string()
        .starts_with("psi_dot"));
    assert!(constants_of_state(1.0, 3.0, 1.0, &st)
        .unwrap_err()
        .to_string()
        .starts_with("I3"));
}

/// `with_spin` sets ψ̇ = ω₃ − φ̇ cos θ (2.99): the top's ω₃ is the given spin (to round-off) and
/// its initial ψ̇ satisfies 2.99 against an independent evaluation; errors name the argument.
#[test]
fn with_spin_gives_the_requested_omega3() {
    for (th, phd, w3) in [
        (0.7, -0.4, 9.0),
        (0.0, 0.5, 6.0),
        (2.0, 1.5, -3.0),
        (1.2, 0.0, 0.0),
    ] {
        let t = HeavyTop::with_spin(1.0, 0.5, 1.0, 0.1, th, 0.2, phd, 0.3, w3).unwrap();
        assert!(
            (t.omega3() - w3).abs() <= 1e-14 * (1.0 + w3.abs() + phd.abs()),
            "{th} {phd} {w3}"
        );
        let s = t.initial_state();
        assert_eq!(
            (s.phi, s.theta, s.psi, s.phi_dot, s.theta_dot),
            (0.1, th, 0.2, phd, 0.3)
        );
        assert!((s.psi_dot + s.phi_dot * th.cos() - w3).abs() <= 1e-14 * (1.0 + w3.abs()));
    }
    let e = HeavyTop::with_spin(1.0, 0.5, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, f64::INFINITY).unwrap_err();
    assert!(e.to_string().starts_with("omega3"), "{e}");
    let e = HeavyTop::with_spin(1.0, 0.5, 1.0, 0.0, -1.0, 0.0, 0.0, 0.0, 1.0).unwrap_err();
    assert!(e.to_string().starts_with("theta"), "{e}");
}

/// The spin ω₃ = p_ψ/I₃ is a number the top returns: where it overflows although p_ψ and E do
/// not (a subnormal I₃), the constructors refuse, naming the rate or the constant it comes from
/// — the rule that every number returned is finite is the core's, not the front ends'.
#[test]
fn a_spin_beyond_the_doubles_is_refused_naming_its_cause() {
    let fast = EulerState {
        phi_dot: 1e308,
        psi_dot: 1e308,
        ..Default::default()
    };
    let e = HeavyTop::new(1.0, 1e-310, 0.0, fast).unwrap_err();
    assert!(
        e.to_string().starts_with("phi_dot: the top's spin omega3"),
        "{e}"
    );
    let e = HeavyTop::from_constants(1.0, 5e-324, 0.0, 0.0, 1e-15, 1e300).unwrap_err();
    assert!(
        e.to_string().starts_with("p_psi: the top's spin omega3"),
        "{e}"
    );
    // Just inside the range: accepted, and the spin is the finite p_psi / I3.
    let top = HeavyTop::from_constants(1.0, 1e-300, 0.0, 0.0, 1e-15, 1e300).unwrap();
    assert_eq!(top.omega3(), 1e-15 / 1e-300);
}

/// The corrected 2.120, p_ψ/(I₁ cos θ₀), can overflow where the exact fast rate q/(I₁ cos θ₀)
/// and the printed p_ψ/(2 I₁ cos θ₀) do not (q ≈ 0.75 p_ψ here): refused naming `theta0`, as
/// every other rate out of range, instead of returning an infinite `fast_approx`.
#[test]
fn steady_precession_refuses_an_infinite_fast_approximation() {
    let theta0 = 1e-10f64.acos();
    let e = steady_precession(1e-300, 1e-300, 6.56e305, theta0, 1.87e298).unwrap_err();
    assert!(
        e.to_string()
            .starts_with("theta0: the fast precession rate"),
        "{e}"
    );
    let s = steady_precession(1e-300, 1e-300, 6.56e305, theta0, 1.7e298).unwrap();
    for r in [
        s.slow,
        s.fast,
        s.fast_approx,
        s.fast_approx_as_printed,
        s.min_spin,
    ] {
        assert!(r.is_finite(), "{s:?}");
    }
}

/// Which pole a top of the class "through vertical" passes through, against its θ bounds and
/// the closed forms of the planar pendulum (no spin, a = b = 0: the cubic is
/// (1 − u²)(α − βu), roots ±1 and α/β): released at rest at θ₀ it swings between θ₀ and the
/// bottom, θ₂ = π; thrown over the top (α/β > 1) it passes both poles. A top started upright
/// with a nod (θ = 0, θ̇ ≠ 0) comes back through the upright, θ₁ = 0. Every other class has
/// none.
#[test]
fn vertical_pass_names_the_pole_of_the_turning_points() {
    let pi = std::f64::consts::PI;
    let down = top(1.0, 0.5, 1.0, 0.8, 0.0, 0.0, 0.0);
    assert_eq!(down.motion_class(), MotionClass::ThroughVertical);
    assert_eq!(down.turning_points(), (0.8, pi));
    assert_eq!(down.vertical_pass(), Some(VerticalPass::StraightDown));
    // ½ I₁ θ̇² + m g l cos θ₀ > m g l: over the top.
    let round = top(1.0, 0.5, 1.0, 0.8, 5.0, 0.0, 0.0);
    assert_eq!(round.turning_points(), (0.0, pi));
    assert_eq!(round.vertical_pass(), Some(VerticalPass::Both));
    let up = top(1.0, 0.5, 1.0, 0.0, 1e-9, 0.0, 8.0);
    assert_eq!(up.motion_class(), MotionClass::ThroughVertical);
    let (t1, t2) = up.turning_points();
    assert!(t1 == 0.0 && t2 > 0.0 && t2 < pi / 2.0, "{t1} {t2}");
    assert_eq!(up.vertical_pass(), Some(VerticalPass::Upright));
    assert_eq!(VerticalPass::StraightDown.name(), "straight down");
    // Negative controls: a nutating, a sleeping and a hanging top pass through no pole.
    for t in [
        top(1.0, 0.5, 1.0, 0.8, 0.0, 0.0, 6.0),
        top(1.0, 0.5, 1.0, 0.0, 0.0, 0.0, 6.0),
        top(1.0, 0.5, 1.0, pi, 0.0, 0.0, 6.0),
    ] {
        assert_ne!(t.motion_class(), MotionClass::ThroughVertical);
        assert_eq!(t.vertical_pass(), None, "{:?}", t.motion_class());
    }
}
