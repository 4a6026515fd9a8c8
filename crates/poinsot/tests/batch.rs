//! `simulate_batch` on SIMD lanes against the scalar single-body path (`simulate`, body by
//! body), the exact flow, and itself (a body's result whatever its place in the batch, the
//! batch's size or the number of threads); its errors, limits and cancellation.

mod common;
use common::{sample_bodies, Bodies};
use poinsot::analytic::FreeRigidBody;
use poinsot::control::{self, Monitor};
use poinsot::dynamics::{
    simulate, simulate_batch, BatchResult, BodyInertia, Method, SimulateOptions, Torque,
};
use poinsot::{ErrorKind, Result, Vec3};
use proptest::prelude::*;

/// The largest relative difference between two final states: ω relative to |ω|, q absolute
/// (both signs of q are the same attitude).
fn state_diff(w: &[f64; 3], q: &[f64; 4], w_ref: &[f64; 3], q_ref: &[f64; 4]) -> f64 {
    let norm = w_ref.iter().map(|x| x * x).sum::<f64>().sqrt().max(1e-300);
    let dw = (0..3).map(|k| (w[k] - w_ref[k]).abs()).fold(0.0, f64::max) / norm;
    let plus = (0..4).map(|k| (q[k] - q_ref[k]).abs()).fold(0.0, f64::max);
    let minus = (0..4).map(|k| (q[k] + q_ref[k]).abs()).fold(0.0, f64::max);
    dw.max(plus.min(minus))
}

/// The batch against `simulate` run body by body with the same method and step: the largest
/// state difference over the bodies.
fn against_single_runs(
    moments: &[[f64; 3]],
    omega: &[[f64; 3]],
    attitude: &[[f64; 4]],
    duration: f64,
    torque: Torque,
    opts: &SimulateOptions,
) -> f64 {
    let batch = simulate_batch(moments, omega, Some(attitude), duration, &torque, opts).unwrap();
    let mut worst: f64 = 0.0;
    for i in 0..moments.len() {
        let body = BodyInertia::from_moments(moments[i]).unwrap();
        let single = SimulateOptions {
            samples: 2,
            ..*opts
        };
        let mut t = torque;
        let tr = simulate(
            &body,
            Vec3::from(omega[i]),
            Some(attitude[i]),
            duration,
            &mut t,
            &single,
        )
        .unwrap();
        let (w, q) = (tr.omega[1], tr.attitude[1]);
        worst = worst.max(state_diff(&batch.omega[i], &batch.attitude[i], &w, &q));
    }
    worst
}

/// Moments obeying the triangle inequality, ω₀ of size ~1–3 rad/s, unit attitudes.
fn bodies() -> impl Strategy<Value = Bodies> {
    (1usize..30).prop_flat_map(|n| {
        (
            prop::collection::vec(
                // I₃ between |I₁ − I₂| and I₁ + I₂: the triangle inequalities hold.
                (0.5f64..2.0, 0.5f64..2.0, 0.05f64..0.95).prop_map(|(a, b, t)| {
                    let lo = (a - b).abs();
                    [a, b, lo + t * (a + b - lo)]
                }),
                n,
            ),
            prop::collection::vec(
                (-3.0f64..3.0, -3.0f64..3.0, -3.0f64..3.0).prop_map(|(x, y, z)| [x, y, z + 0.1]),
                n,
            ),
            prop::collection::vec(
                (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0, 0.1f64..1.0).prop_map(|(x, y, z, w)| {
                    let n = (w * w + x * x + y * y + z * z).sqrt();
                    [w / n, x / n, y / n, z / n]
                }),
                n,
            ),
        )
    })
}

fn torques() -> impl Strategy<Value = Torque> {
    prop_oneof![
        Just(Torque::None),
        (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0)
            .prop_map(|(x, y, z)| Torque::Body(Vec3::new(x, y, z))),
        (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0)
            .prop_map(|(x, y, z)| Torque::Space(Vec3::new(x, y, z))),
        (0.0f64..2.0).prop_map(|mgl| Torque::Gravity { mgl }),
        (0.0f64..2.0).prop_map(|mean_motion| Torque::GravityGradient { mean_motion }),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// 20 RK4 steps on the lanes give the scalar path's numbers (to round-off; in fact bit for
    /// bit), for every built-in torque, with a common step or each body's own default step
    /// (different step counts in one group of lanes), batches that fill no whole group.
    #[test]
    fn rk4_lanes_equal_the_scalar_path((m, w, q) in bodies(), torque in torques(), common in any::<bool>()) {
        let opts = SimulateOptions {
            method: Method::Rk4,
            dt: common.then_some(1e-3),
            ..SimulateOptions::default()
        };
        let d = against_single_runs(&m, &w, &q, 0.02, torque, &opts);
        prop_assert!(d <= 1e-13, "{d:e}");
    }

    /// The splittings of order 2, 4 and 6 on the lanes against the scalar path (their
    /// rotations' sines and cosines differ by ≤ 2 ulp): 20 steps, and with each body's default
    /// step.
    #[test]
    fn splitting_lanes_agree_with_the_scalar_path((m, w, q) in bodies(), torque in torques(), order in prop::sample::select(vec![2u8, 4, 6]), common in any::<bool>()) {
        let opts = SimulateOptions {
            method: Method::Splitting(order),
            dt: common.then_some(1e-3),
            ..SimulateOptions::default()
        };
        let d = against_single_runs(&m, &w, &q, 0.02, torque, &opts);
        prop_assert!(d <= 1e-13, "{d:e}");
    }
}

#[test]
fn rk4_lanes_are_bit_for_bit_the_scalar_path() {
    // ω bit for bit; the attitude too once normalised as `simulate` returns it (q / |q|).
    let (m, w, q) = sample_bodies(37);
    for torque in [
        Torque::None,
        Torque::Gravity { mgl: 0.7 },
        Torque::Body(Vec3::new(0.1, -0.2, 0.3)),
    ] {
        let opts = SimulateOptions {
            method: Method::Rk4,
            dt: Some(1e-3),
            ..SimulateOptions::default()
        };
        let batch = simulate_batch(&m, &w, Some(&q), 0.05, &torque, &opts).unwrap();
        for i in 0..37 {
            let body = BodyInertia::from_moments(m[i]).unwrap();
            let single = SimulateOptions { samples: 2, ..opts };
            let mut t = torque;
            let tr = simulate(&body, Vec3::from(w[i]), Some(q[i]), 0.05, &mut t, &single).unwrap();
            let a = batch.attitude[i];
            let n = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2] + a[3] * a[3]).sqrt();
            let a = [a[0] / n, a[1] / n, a[2] / n, a[3] / n];
            assert_eq!(batch.omega[i], tr.omega[1], "{torque:?} body {i}");
            assert!(
                a == tr.attitude[1] || a.map(|c| -c) == tr.attitude[1],
                "{torque:?} body {i}"
            );
        }
    }
}

#[test]
fn the_comparison_sees_a_wrong_kernel_negative_control() {
    // The comparison above can fail: a kernel that took the space-fixed torque as body-fixed
    // (the attitude ignored), or ran the order-2 splitting for order 4, differs from the
    // reference by far more than 1e-13 after the same 20 steps.
    let (m, w, q) = sample_bodies(13);
    let opts = |method| SimulateOptions {
        method,
        dt: Some(1e-3),
        ..SimulateOptions::default()
    };
    let diff = |a: &BatchResult, b: &BatchResult| {
        (0..13)
            .map(|i| state_diff(&a.omega[i], &a.attitude[i], &b.omega[i], &b.attitude[i]))
            .fold(0.0, f64::max)
    };
    let n = Vec3::new(0.3, -0.2, 0.5);
    let space = simulate_batch(
        &m,
        &w,
        Some(&q),
        0.02,
        &Torque::Space(n),
        &opts(Method::Rk4),
    )
    .unwrap();
    let body =
        simulate_batch(&m, &w, Some(&q), 0.02, &Torque::Body(n), &opts(Method::Rk4)).unwrap();
    assert!(diff(&space, &body) > 1e-6, "{:e}", diff(&space, &body));
    let run = |order| {
        simulate_batch(
            &m,
            &w,
            Some(&q),
            0.02,
            &Torque::None,
            &opts(Method::Splitting(order)),
        )
        .unwrap()
    };
    let (s2, s4) = (run(2), run(4));
    assert!(diff(&s2, &s4) > 1e-10, "{:e}", diff(&s2, &s4));
}

#[test]
fn torque_free_lanes_agree_with_the_exact_flow() {
    // 2000 steps of 1e-3 s: RK4 and the order-4 and 6 splittings within their truncation
    // error of the exact state, order 2 within its own.
    let (m, w, q) = sample_bodies(21);
    for (method, tol) in [
        (Method::Rk4, 1e-10),
        (Method::Splitting(2), 1e-5),
        (Method::Splitting(4), 1e-10),
        (Method::Splitting(6), 1e-11),
    ] {
        let opts = SimulateOptions {
            method,
            dt: Some(1e-3),
            ..SimulateOptions::default()
        };
        let b = simulate_batch(&m, &w, Some(&q), 2.0, &Torque::None, &opts).unwrap();
        assert_eq!(b.steps, 2000);
        for i in 0..21 {
            let (we, qe) = FreeRigidBody::new(m[i], Vec3::from(w[i]), Some(q[i]))
                .unwrap()
                .state(2.0)
                .unwrap();
            let d = state_diff(&b.omega[i], &b.attitude[i], &[we.x, we.y, we.z], &qe);
            assert!(d < tol, "{method:?} body {i}: {d:e}");
        }
    }
}

#[test]
fn a_body_does_not_depend_on_its_lane_its_batch_or_the_threads() {
    // Reversed order, a batch of one, one thread or two: the same bits.
    let (m, w, q) = sample_bodies(29);
    let run = |m: &[[f64; 3]], w: &[[f64; 3]], q: &[[f64; 4]], method| -> BatchResult {
        let opts = SimulateOptions {
            method,
            dt: None,
            ..SimulateOptions::default()
        };
        simulate_batch(m, w, Some(q), 0.3, &Torque::Gravity { mgl: 0.5 }, &opts).unwrap()
    };
    for method in [Method::Rk4, Method::Splitting(4)] {
        let all = run(&m, &w, &q, method);
        let rev = |v: &[[f64; 3]]| v.iter().rev().copied().collect::<Vec<_>>();
        let qr: Vec<[f64; 4]> = q.iter().rev().copied().collect();
        let back = run(&rev(&m), &rev(&w), &qr, method);
        for i in 0..29 {
            assert_eq!(all.omega[i], back.omega[28 - i]);
            assert_eq!(all.attitude[i], back.attitude[28 - i]);
        }
        let one = run(&m[17..18], &w[17..18], &q[17..18], method);
        assert_eq!(
            (one.omega[0], one.attitude[0]),
            (all.omega[17], all.attitude[17])
        );
        for threads in [1, 2] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let again = pool.install(|| run(&m, &w, &q, method));
            assert_eq!(again, all, "{threads} threads");
        }
    }
}

#[test]
fn errors_name_the_first_body_at_fault() {
    let (m, mut w, q) = sample_bodies(40);
    let opts = SimulateOptions {
        method: Method::Rk4,
        dt: None,
        ..SimulateOptions::default()
    };
    // L overflows for bodies 31 and 9: body 9 is reported, naming omega0.
    w[31] = [1e308, 0.0, 0.0];
    w[9] = [0.0, 1e308, 1e308];
    let e = simulate_batch(&m, &w, Some(&q), 1.0, &Torque::None, &opts).unwrap_err();
    assert_eq!(e.argument, "omega0", "{e}");
    assert!(e.message.starts_with("body 9: "), "{e}");
    // Each body's own default step, checked against max_steps before any step: a fast body
    // needs too many.
    let (m, mut w, q) = sample_bodies(40);
    w[23] = [0.0, 0.0, 1e6];
    let limited = SimulateOptions {
        max_steps: 100_000,
        ..opts
    };
    let e = simulate_batch(&m, &w, Some(&q), 1.0, &Torque::None, &limited).unwrap_err();
    assert_eq!(e.argument, "max_steps", "{e}");
    assert!(e.message.starts_with("body 23: "), "{e}");
    // A body whose state overflows during the run: Diverged, naming it.
    let mut w = sample_bodies(40).1;
    w[5] = [1e150, 2e150, 1e150];
    let coarse = SimulateOptions {
        dt: Some(0.1),
        ..opts
    };
    let e = simulate_batch(&m, &w, Some(&q), 10.0, &Torque::None, &coarse).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Diverged, "{e}");
    assert!(e.message.starts_with("body 5: "), "{e}");
}

/// Stops at the first poll.
struct StopNow;

impl Monitor for StopNow {
    fn poll(&mut self, _progress: f64) -> Result<()> {
        Err(control::interrupted())
    }
}

#[test]
fn a_monitor_stops_the_lanes() {
    // 10⁴ bodies × 10⁵ steps would take seconds: the monitor stops it at its first poll.
    let (m, w, q) = sample_bodies(10_000);
    let opts = SimulateOptions {
        method: Method::Rk4,
        dt: Some(1e-5),
        ..SimulateOptions::default()
    };
    let (result, _) = control::watched(StopNow, || {
        simulate_batch(&m, &w, Some(&q), 1.0, &Torque::None, &opts)
    });
    assert_eq!(result.unwrap_err().kind, ErrorKind::Interrupted);
}
