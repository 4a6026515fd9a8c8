//! Tests of the ODE integrators (`poinsot::integrate`) against closed-form solutions.

use nalgebra::SVector;
use poinsot::integrate::{dop853, dop853_scan, dop853_until, Crossing, Options};
use poinsot::ErrorKind;

/// Harmonic oscillator y'' = −y as a first-order system.
fn oscillator(_t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
    dy[0] = y[1];
    dy[1] = -y[0];
}

/// DOP853 is 8th order: at rtol = 1e-12 the global error over a few periods stays within a
/// small multiple of the tolerance (the bound below allows a factor 100 of error growth).
const DOP853_GLOBAL_FACTOR: f64 = 100.0;

#[test]
fn dop853_oscillator_meets_tolerance_and_scales_with_it() {
    let t_end = 20.0;
    let mut prev = f64::INFINITY;
    for &rtol in &[1e-6, 1e-9, 1e-12] {
        let opts = Options::with_tolerances(rtol, rtol);
        let sol = dop853(oscillator, 0.0, [1.0, 0.0], t_end, &opts).unwrap();
        let y = sol.y_final();
        let err = (y[0] - t_end.cos()).abs().max((y[1] + t_end.sin()).abs());
        assert!(
            err < DOP853_GLOBAL_FACTOR * rtol,
            "rtol {rtol}: error {err}"
        );
        assert!(err < prev, "error must fall with the tolerance");
        prev = err;
    }
}

#[test]
fn dop853_dense_output_is_accurate_between_steps() {
    let opts = Options::with_tolerances(1e-12, 1e-12);
    let sol = dop853(oscillator, 0.0, [1.0, 0.0], 10.0, &opts).unwrap();
    assert!(sol.t.len() > 5, "non-trivial: several steps");
    for i in 0..=1000 {
        let t = 10.0 * i as f64 / 1000.0;
        let y = sol.at(t).unwrap();
        assert!(
            (y[0] - t.cos()).abs() < 1e-10,
            "t = {t}: {}",
            y[0] - t.cos()
        );
    }
    assert!(sol.at(10.5).is_err(), "outside the interval must fail");
}

#[test]
fn dop853_backward_and_other_state_types() {
    let opts = Options::with_tolerances(1e-12, 1e-14);
    // Backwards: y' = y from y(1) = e to t = 0.
    let sol = dop853(
        |_t: f64, y: &Vec<f64>, dy: &mut Vec<f64>| dy[0] = y[0],
        1.0,
        vec![1f64.exp()],
        0.0,
        &opts,
    )
    .unwrap();
    assert!((sol.y_final()[0] - 1.0).abs() < 1e-11);
    assert!((sol.at(0.5).unwrap()[0] - 0.5f64.exp()).abs() < 1e-11);
    // nalgebra SVector state.
    let sol = dop853(
        |_t: f64, y: &SVector<f64, 2>, dy: &mut SVector<f64, 2>| {
            dy[0] = y[1];
            dy[1] = -y[0];
        },
        0.0,
        SVector::<f64, 2>::new(0.0, 1.0),
        3.0,
        &opts,
    )
    .unwrap();
    assert!((sol.y_final()[0] - 3f64.sin()).abs() < 1e-11);
}

#[test]
fn dop853_terminal_event_finds_the_crossing() {
    // cos t first crosses zero (falling) at π/2.
    let opts = Options::with_tolerances(1e-12, 1e-12);
    let sol = dop853_until(
        oscillator,
        0.0,
        [1.0, 0.0],
        10.0,
        &opts,
        |_t, y: &[f64; 2]| y[0],
        Crossing::Falling,
    )
    .unwrap();
    let ev = sol.event.as_ref().expect("the event must fire");
    assert!(
        (ev.t - std::f64::consts::FRAC_PI_2).abs() < 1e-12,
        "{}",
        ev.t
    );
    assert!(ev.y[0].abs() < 1e-12 && (ev.y[1] + 1.0).abs() < 1e-12);
    assert_eq!(sol.t_final(), ev.t);
    // Rising only: the first rising crossing of cos t is 3π/2.
    let sol = dop853_until(
        oscillator,
        0.0,
        [1.0, 0.0],
        10.0,
        &opts,
        |_t, y: &[f64; 2]| y[0],
        Crossing::Rising,
    )
    .unwrap();
    assert!((sol.event.unwrap().t - 1.5 * std::f64::consts::PI).abs() < 1e-11);
}

#[test]
fn dop853_scan_samples_and_collects_crossings() {
    let opts = Options {
        dense: false,
        ..Options::with_tolerances(1e-12, 1e-12)
    };
    let times: Vec<f64> = (0..=50).map(|i| i as f64 * 0.4).collect();
    let scan = dop853_scan(
        oscillator,
        0.0,
        [1.0, 0.0],
        20.0,
        &times,
        &opts,
        |_t, y: &[f64; 2]| y[0],
        Crossing::Any,
    )
    .unwrap();
    assert_eq!(scan.y.len(), times.len());
    for (t, y) in times.iter().zip(&scan.y) {
        assert!((y[0] - t.cos()).abs() < 1e-10);
    }
    // Zeros of cos t in (0, 20): π/2 + kπ, k = 0..5 → 6 crossings.
    assert_eq!(scan.crossings.len(), 6);
    for (k, c) in scan.crossings.iter().enumerate() {
        assert!((c.t - (0.5 + k as f64) * std::f64::consts::PI).abs() < 1e-10);
    }
    let bad = dop853_scan(
        oscillator,
        0.0,
        [1.0, 0.0],
        1.0,
        &[0.5, 0.2],
        &opts,
        |_t, _y: &[f64; 2]| 1.0,
        Crossing::Any,
    );
    assert_eq!(bad.unwrap_err().argument, "times");
}

#[test]
fn dop853_reports_where_it_diverged() {
    // y' = y², y(0) = 1 blows up at t = 1.
    let opts = Options::with_tolerances(1e-10, 1e-10);
    let err = dop853(
        |_t: f64, y: &[f64; 1], dy: &mut [f64; 1]| dy[0] = y[0] * y[0],
        0.0,
        [1.0],
        2.0,
        &opts,
    )
    .unwrap_err();
    assert_eq!(err.kind, ErrorKind::Diverged);
    assert_eq!(err.argument, "t");
    assert!(
        err.message.contains("t = 0.99") || err.message.contains("t = 1"),
        "{err}"
    );
    // Too few steps allowed: names max_steps.
    let opts = Options {
        max_steps: 3,
        ..Options::with_tolerances(1e-12, 1e-12)
    };
    let err = dop853(oscillator, 0.0, [1.0, 0.0], 100.0, &opts).unwrap_err();
    assert_eq!(
        (err.kind, err.argument.as_str()),
        (ErrorKind::Diverged, "max_steps")
    );
}

#[test]
fn dop853_refuses_bad_options() {
    for (rtol, atol, name) in [
        (0.0, 1e-9, "rtol"),
        (-1e-9, 1e-9, "rtol"),
        (f64::NAN, 1e-9, "rtol"),
        (1e-18, 1e-9, "rtol"),
        (1e-9, 0.0, "atol"),
        (1e-9, -1.0, "atol"),
        (1e-9, f64::INFINITY, "atol"),
    ] {
        let err = dop853(
            oscillator,
            0.0,
            [1.0, 0.0],
            1.0,
            &Options::with_tolerances(rtol, atol),
        )
        .unwrap_err();
        assert_eq!(err.kind, ErrorKind::InvalidArgument);
        assert_eq!(err.argument, name, "{err}");
    }
    let err = dop853(oscillator, 0.0, [f64::NAN, 0.0], 1.0, &Options::default()).unwrap_err();
    assert_eq!(err.argument, "y0");
    let err = dop853(
        oscillator,
        0.0,
        [1.0, 0.0],
        f64::INFINITY,
        &Options::default(),
    )
    .unwrap_err();
    assert_eq!(err.argument, "t_end");
}

#[test]
fn dop853_counts_its_work() {
    let opts = Options {
        dense: false,
        ..Options::with_tolerances(1e-10, 1e-10)
    };
    let sol = dop853(oscillator, 0.0, [1.0, 0.0], 10.0, &opts).unwrap();
    let s = sol.stats;
    // 1 initial evaluation + 1 for the starting step + 12 per attempted step (FSAL).
    assert_eq!(s.evaluations, 2 + 12 * (s.accepted + s.rejected));
    assert_eq!(sol.t.len(), s.accepted + 1);
}

#[test]
fn dop853_blames_the_start_by_name() {
    // A derivative that overflows at the initial point: the initial state is at fault (issue 10).
    let err = dop853(
        |_t: f64, y: &[f64; 1], dy: &mut [f64; 1]| dy[0] = y[0] * y[0],
        0.0,
        [1e200],
        1.0,
        &Options::default(),
    )
    .unwrap_err();
    assert_eq!(
        (err.kind, err.argument.as_str()),
        (ErrorKind::InvalidArgument, "y0"),
        "{err}"
    );
    // Negative control: a real blow-up after some accepted steps names t, and says when.
    let err = dop853(
        |_t: f64, y: &[f64; 1], dy: &mut [f64; 1]| dy[0] = y[0] * y[0],
        0.0,
        [1.0],
        2.0,
        &Options::default(),
    )
    .unwrap_err();
    assert_eq!(
        (err.kind, err.argument.as_str()),
        (ErrorKind::Diverged, "t")
    );
    assert!(err.message.contains("tolerances"), "{err}");
}
