//! The Foucault pendulum on any planet (issue 10, item 3): the rest position, the exact small-
//! swing theory against independent integrations, the measured rate against that theory, and
//! the regimes where the plane does not turn steadily — never a rate of the wrong sense.

use poinsot::earth::{
    fit_precession_rate, Earth, FoucaultMeasurement, FoucaultRegime, FoucaultRun, Sense,
    UnitRateCheck, FOUCAULT_TOLERANCES, MEAN_RADIUS, SIDEREAL_RATE, STANDARD_GRAVITY,
    UNIT_RATE_TOLERANCE,
};
use poinsot::frames::ParticleState;
use poinsot::integrate::{dop853_scan, Crossing, Options};
use poinsot::Vec3;
use proptest::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI};

fn deg(x: f64) -> f64 {
    x.to_radians()
}

fn planet(rate: f64) -> Earth {
    Earth::new(rate, MEAN_RADIUS, STANDARD_GRAVITY).unwrap()
}

/// The Python API's and the lab's tolerances.
fn options() -> Options {
    Options {
        dense: false,
        ..Options::with_tolerances(1e-10, 1e-12)
    }
}

/// Release from rest, swing for `duration` and measure, as `Earth.foucault` does.
fn swing(
    e: &Earth,
    lat: f64,
    len: f64,
    amp: f64,
    az: f64,
    duration: f64,
) -> (FoucaultRun, FoucaultMeasurement) {
    let s0 = e.foucault_release(lat, len, amp, az).unwrap();
    let run = e
        .foucault(lat, len, s0, 0.0, duration, &[duration], &options())
        .unwrap();
    let m = e
        .foucault_measurement(
            lat,
            len,
            &s0,
            0.0,
            duration,
            &run.turn_times,
            &run.turn_angles,
        )
        .unwrap();
    (run, m)
}

/// How far the measured rate may be from the small-swing theory's fit over the same run: the
/// amplitude's own (Airy) precession, (3/8)(A/L)² of the rate, twice for the terms of higher
/// order in Ω/√(g/L), plus the integration's error on the angles (rtol 1e-10: ~1e-9 rad over a
/// turn of ≥ 1e-3 rad, 1e-6 relative).
fn amplitude_tolerance(amp: f64, len: f64) -> f64 {
    2.0 * 0.375 * (amp / len).powi(2) + 1e-6
}

/// The rest position: gravity plus the centrifugal force −ω × (ω × r) at the bob lie along
/// the string; the small-spin tilt is (ω²L/2g) sin 2λ; a bob released at rest stays there
/// (the nonlinear integration); north and south are mirror images.
#[test]
fn rest_position_balances_gravity_and_the_centrifugal_force() {
    for (rate, len) in [(SIDEREAL_RATE, 67.0), (0.0729, 80.0), (0.2, 10.0)] {
        let e = planet(rate);
        for lat in [deg(54.0), deg(-54.0), deg(10.0), deg(89.0)] {
            let th = e.foucault_theory(lat, len).unwrap();
            let w = e.omega_enu(lat).unwrap();
            let force = Vec3::new(0.0, 0.0, -e.g) - w.cross(&w.cross(&th.rest));
            // Along the string to round-off of g.
            assert!(
                force.cross(&th.rest).norm() / (e.g * len) < 1e-15,
                "{rate} {lat}: {:e}",
                force.cross(&th.rest).norm()
            );
            assert!((th.rest.norm() - len).abs() < 1e-13 * len);
            // The centrifugal force pushes the bob (below the suspension, nearer the axis)
            // away from the axis: poleward of the suspension's plumb line.
            assert_eq!(th.tilt.signum(), lat.signum());
            let mirror = e.foucault_theory(-lat, len).unwrap();
            assert_eq!(mirror.tilt, -th.tilt);
            assert_eq!(mirror.stiffness, th.stiffness);
            assert_eq!(mirror.vertical_spin, -th.vertical_spin);
            // Released exactly at rest (no amplitude), the bob stays there.
            let s0 = [th.rest.x, th.rest.y, th.rest.z, 0.0, 0.0, 0.0];
            let run = e
                .foucault(
                    lat,
                    len,
                    s0,
                    0.0,
                    100.0,
                    &[100.0],
                    &Options::with_tolerances(1e-12, 1e-14),
                )
                .unwrap();
            let r = Vec3::new(run.states[0][0], run.states[0][1], run.states[0][2]);
            assert!(
                (r - th.rest).norm() < 1e-9 * len,
                "{rate} {lat}: moved {:e}",
                (r - th.rest).norm()
            );
        }
    }
    // Small spin: φ = (ω²L/2g) sin 2λ to first order (relative error O(ω²L/g) = 4e-8 here).
    let e = planet(SIDEREAL_RATE);
    let th = e.foucault_theory(deg(45.0), 67.0).unwrap();
    let first = SIDEREAL_RATE.powi(2) * 67.0 / (2.0 * e.g);
    assert!(
        ((th.tilt - first) / first).abs() < 1e-6,
        "{} vs {first}",
        th.tilt
    );
    // On the plumb line at the equator, the poles, and without spin.
    assert_eq!(e.foucault_theory(0.0, 67.0).unwrap().tilt, 0.0);
    assert_eq!(e.foucault_theory(FRAC_PI_2, 67.0).unwrap().tilt, 0.0);
    assert_eq!(
        planet(0.0).foucault_theory(deg(30.0), 67.0).unwrap().tilt,
        0.0
    );
}

/// At the pole the swing is the inertial frame's fixed swing seen from the turning planet:
/// Δ = −ω exactly and ν± = √(g/L) ± ω, for any spin below √(g/L); Δ → −ω sin λ for a slow spin.
#[test]
fn small_swing_theory_at_the_pole_and_for_a_slow_spin() {
    for rate in [SIDEREAL_RATE, 0.0729, 0.5] {
        let e = planet(rate);
        let w0 = (e.g / 10.0).sqrt();
        for (lat, sign) in [(FRAC_PI_2, 1.0), (-FRAC_PI_2, -1.0)] {
            let m = e.foucault_theory(lat, 10.0).unwrap().modes.unwrap();
            assert!(
                ((m.precession_rate + sign * rate) / rate).abs() < 1e-14,
                "{rate}: {}",
                m.precession_rate
            );
            assert!((m.frequencies[0] - (w0 - rate)).abs() < 1e-14 * w0);
            assert!((m.frequencies[1] - (w0 + rate)).abs() < 1e-14 * w0);
            assert_eq!(m.splitting, 0.0);
        }
    }
    // The Earth: −ω sin λ to (ω/√(g/L))² ~ 1e-8 relative at mid latitudes.
    let e = Earth::default();
    for lat in [deg(48.85), deg(-33.9), deg(10.0), deg(80.0)] {
        let m = e.foucault_theory(lat, 67.0).unwrap().modes.unwrap();
        let want = e.foucault_rate(lat).unwrap();
        assert!(
            ((m.precession_rate - want) / want).abs() < 1e-7,
            "{lat}: {} vs {want}",
            m.precession_rate
        );
    }
    // No spin: one frequency √(g/L), no turn.
    let m = planet(0.0)
        .foucault_theory(deg(30.0), 10.0)
        .unwrap()
        .modes
        .unwrap();
    assert_eq!(m.precession_rate, 0.0);
    assert!((m.frequencies[0] - (STANDARD_GRAVITY / 10.0).sqrt()).abs() < 1e-15);
}

/// The closed-form small swing against an independent integration (DOP853 at 1e-13) of the
/// linearised equations q̈_e = 2w q̇_n − k_e q_e, q̈_n = −2w q̇_e − k_n q_n with the theory's
/// stiffnesses and spin — the modes, their frequencies and the initial-value solve — and the
/// linearisation itself against the nonlinear pendulum at a tiny amplitude, where they differ
/// by O(A/L) of the swing.
#[test]
fn closed_form_swing_matches_integrations() {
    for (rate, len, lat) in [
        (0.0729, 80.0, deg(54.0)),
        (0.0729, 10.0, deg(-20.0)),
        (0.2, 10.0, deg(3.0)),
        (1e-3, 67.0, 0.0),
        (0.3, 10.0, deg(90.0)),
    ] {
        let e = planet(rate);
        let th = e.foucault_theory(lat, len).unwrap();
        let modes = th.modes.unwrap();
        let (q0, v0) = ([0.3e-3 * len, -0.7e-3 * len], [1e-4, 2e-4]);
        let sw = modes.swing(q0, v0, 0.0).unwrap();
        let [ke, kn] = th.stiffness;
        let w = th.vertical_spin;
        let rhs = |_t: f64, y: &[f64; 4], dy: &mut [f64; 4]| {
            *dy = [
                y[2],
                y[3],
                2.0 * w * y[3] - ke * y[0],
                -2.0 * w * y[2] - kn * y[1],
            ];
        };
        let period = 2.0 * PI / modes.swing_frequency;
        let times: Vec<f64> = (1..=40).map(|i| i as f64 * 0.25 * period).collect();
        let t_end = times[times.len() - 1];
        let scan = dop853_scan(
            rhs,
            0.0,
            [q0[0], q0[1], v0[0], v0[1]],
            t_end,
            &times,
            &Options::with_tolerances(1e-13, 1e-16),
            |_t, _y: &[f64; 4]| 1.0,
            Crossing::Any,
        )
        .unwrap();
        let scale = q0[0].hypot(q0[1]);
        for (t, y) in scan.t.iter().zip(&scan.y) {
            let (q, v) = (sw.displacement(*t), sw.velocity(*t));
            let dq = (q[0] - y[0]).hypot(q[1] - y[1]);
            let dv = (v[0] - y[2]).hypot(v[1] - y[3]);
            assert!(
                dq < 1e-10 * scale && dv < 1e-10 * scale * modes.frequencies[1],
                "{rate} {lat} t={t}: {dq:e} {dv:e}"
            );
        }
        // From rest the release is itself a turning point, not counted; the next ones follow
        // half a swing apart (to the wobble).
        let rest_swing = modes.swing(q0, [0.0, 0.0], 0.0).unwrap();
        let mut times_found = Vec::new();
        rest_swing.turning_points(0.0, t_end, usize::MAX, |t, _| times_found.push(t));
        let half = PI / modes.swing_frequency;
        assert!(
            (times_found[0] / half - 1.0).abs() < 0.1,
            "{rate} {lat}: first turning point at {}",
            times_found[0]
        );
        assert!(
            times_found.len() as f64 >= t_end / half - 1.5,
            "{rate} {lat}: {} turning points",
            times_found.len()
        );
        // The nonlinear pendulum released from rest at A = 1e-4 L: the same swing to O(A/L).
        let amp = 1e-4 * len;
        let s0 = e.foucault_release(lat, len, amp, 0.4).unwrap();
        let run = e
            .foucault(
                lat,
                len,
                s0,
                0.0,
                t_end,
                &times,
                &Options::with_tolerances(1e-12, 1e-15),
            )
            .unwrap();
        let lin = modes
            .swing(
                th.displacement_of(&Vec3::new(s0[0], s0[1], s0[2])),
                [0.0, 0.0],
                0.0,
            )
            .unwrap();
        for (t, s) in run.t.iter().zip(&run.states) {
            let q = th.displacement_of(&Vec3::new(s[0], s[1], s[2]));
            let ql = lin.displacement(*t);
            let d = (q[0] - ql[0]).hypot(q[1] - ql[1]);
            assert!(
                d < 1e-3 * amp,
                "{rate} {lat} t={t}: nonlinear vs linear {:e} of the amplitude",
                d / amp
            );
        }
    }
}

/// The case: `Earth(rotation_rate=0.0729).foucault(54, length=80, duration=60,
/// degrees=True)` reported +0.0063 rad/s, counterclockwise, from turning points at 8.9, 26.7,
/// 35.8, 53.6 s: the turning points were the largest distances from the suspension's plumb
/// line, but the bob hangs 1.7 m north of it there and swings about that rest position. Now
/// the turning points are regular, half a swing apart, and the rate is the small-swing
/// theory's for the same run (−0.05789 rad/s; its mean Δ = −0.05809, −ω sin λ = −0.05898),
/// clockwise; the south mirrors it.
#[test]
fn fast_planet_turns_clockwise_in_the_north() {
    let e = planet(0.0729);
    let (len, amp) = (80.0, 1.0);
    let (run, m) = swing(&e, deg(54.0), len, amp, 0.0, 60.0);
    let th = e.foucault_theory(deg(54.0), len).unwrap();
    let modes = th.modes.unwrap();
    // Half a swing between turning points, within the wobble of the mode's beat (1 %).
    let half = PI / modes.swing_frequency;
    for pair in run.turn_times.windows(2) {
        assert!(
            ((pair[1] - pair[0]) / half - 1.0).abs() < 1e-2,
            "turning points {:?}, half swing {half}",
            run.turn_times
        );
    }
    assert!(run.turn_times.len() >= 6);
    let rate = fit_precession_rate(&run.turn_times, &run.turn_angles).unwrap();
    assert_eq!(m.regime, FoucaultRegime::Precessing, "{}", m.note);
    assert_eq!(m.precession_rate, Some(rate));
    assert_eq!(m.sense, Some(Sense::Clockwise));
    let fit = m.theory_fit_rate.unwrap();
    assert!(
        ((rate - fit) / fit).abs() < amplitude_tolerance(amp, len),
        "{rate} vs {fit}"
    );
    // Within 1 % of the mean rate (the wobble over a 60 s run) and 2 % of −ω sin λ.
    assert!(((rate - modes.precession_rate) / modes.precession_rate).abs() < 1e-2);
    assert!(((rate - m.expected_rate) / m.expected_rate).abs() < 2e-2);
    // The south: the mirror image (azimuth mirrored north-south too).
    let (_, south) = swing(&e, deg(-54.0), len, amp, PI, 60.0);
    assert_eq!(south.sense, Some(Sense::Counterclockwise));
    assert!((south.precession_rate.unwrap() + rate).abs() < 1e-9 * rate.abs());
}

/// Negative control: the turning points of the old measurement — the largest distances from
/// the suspension's plumb line — give the wrong sense on the fast planet, as the issue saw.
#[test]
fn turning_points_about_the_plumb_line_give_the_wrong_sense() {
    let e = planet(0.0729);
    let (lat, len) = (deg(54.0), 80.0);
    let s0 = e.foucault_release(lat, len, 1.0, 0.0).unwrap();
    let w = e.omega_enu(lat).unwrap();
    let (g, beta) = (e.g, (e.g / len).sqrt());
    let rhs = |_t: f64, y: &ParticleState, dy: &mut ParticleState| {
        let (r, v) = (Vec3::new(y[0], y[1], y[2]), Vec3::new(y[3], y[4], y[5]));
        let free = Vec3::new(0.0, 0.0, -g) - 2.0 * w.cross(&v) - w.cross(&w.cross(&r));
        let c = 0.5 * (r.norm_squared() - len * len);
        let lambda = -(v.norm_squared() + r.dot(&free) + 2.0 * beta * r.dot(&v) + beta * beta * c)
            / r.norm_squared();
        let a = free + lambda * r;
        *dy = [v.x, v.y, v.z, a.x, a.y, a.z];
    };
    let scan = dop853_scan(
        rhs,
        0.0,
        s0,
        60.0,
        &[],
        &options(),
        |_t, y: &ParticleState| y[0] * y[3] + y[1] * y[4],
        Crossing::Falling,
    )
    .unwrap();
    let times: Vec<f64> = scan.crossings.iter().map(|h| h.t).collect();
    let angles: Vec<f64> = scan
        .crossings
        .iter()
        .map(|h| h.y[1].atan2(h.y[0]))
        .collect();
    let wrong = fit_precession_rate(&times, &angles).unwrap();
    assert!(
        wrong > 0.0,
        "the plumb-line measurement should get the sense wrong here: {wrong}"
    );
}

/// The measured rate against the small-swing theory on slow and fast planets, both
/// hemispheres and the poles, short and long runs: where the run is precessing, within the
/// amplitude's correction of the theory's fit over the same run, of the theory's sense, and
/// near its mean rate.
#[test]
fn measured_rate_matches_the_small_swing_theory() {
    let cases = [
        // (spin, length, latitude °, amplitude, duration)
        (SIDEREAL_RATE, 67.0, 48.85, 1.0, 3600.0),
        (SIDEREAL_RATE, 67.0, -33.9, 1.0, 600.0),
        (SIDEREAL_RATE, 10.0, 90.0, 0.1, 1800.0),
        (1e-3, 10.0, 45.0, 0.1, 600.0),
        (1e-3, 10.0, -90.0, 0.1, 200.0),
        (0.0729, 80.0, 54.0, 1.0, 600.0),
        (0.0729, 10.0, -70.0, 1.0, 120.0),
        (0.0729, 10.0, 20.0, 0.1, 120.0),
        (0.2, 10.0, 60.0, 0.1, 300.0),
        (0.2, 10.0, -89.0, 0.1, 300.0),
    ];
    for (rate, len, lat_deg, amp, duration) in cases {
        let e = planet(rate);
        let lat = deg(lat_deg);
        let (_, m) = swing(&e, lat, len, amp, 0.7, duration);
        assert_eq!(
            m.regime,
            FoucaultRegime::Precessing,
            "{rate} {lat_deg}: {}",
            m.note
        );
        let r = m.precession_rate.unwrap();
        let fit = m.theory_fit_rate.unwrap();
        let delta = m.theory_rate.unwrap();
        assert!(
            ((r - fit) / fit).abs() < amplitude_tolerance(amp, len),
            "{rate} {lat_deg}: {r} vs theory {fit}"
        );
        assert_eq!(r.signum(), -lat.signum());
        assert_eq!(
            m.sense,
            Some(if lat > 0.0 {
                Sense::Clockwise
            } else {
                Sense::Counterclockwise
            })
        );
        // The run's fit is within the steadiness tolerance of the mean rate.
        assert!(
            ((fit - delta) / delta).abs() < 0.1,
            "{rate} {lat_deg}: {fit} vs {delta}"
        );
        assert!(r.is_finite());
    }
}

/// Where the plane does not turn steadily the result says so and gives no rate; where it does
/// not turn at all, a rate ≈ 0 and no sense. Each with its figures in the note.
#[test]
fn regimes_without_a_foucault_rate() {
    // The Earth's equator: still (the negative control of the sense).
    let e = Earth::default();
    let (_, m) = swing(&e, 0.0, 67.0, 1.0, 0.3, 3600.0);
    assert_eq!(
        (m.regime, m.sense),
        (FoucaultRegime::Still, Some(Sense::None)),
        "{}",
        m.note
    );
    assert!(m.precession_rate.unwrap().abs() < 1e-3 * SIDEREAL_RATE);
    // A planet that does not spin.
    let (_, m) = swing(&planet(0.0), deg(45.0), 10.0, 1.0, 0.3, 60.0);
    assert_eq!(m.regime, FoucaultRegime::Still, "{}", m.note);
    // The equator of a fast planet: east–west and north–south swings differ in frequency and
    // the plane rocks; a plain fit would report a turn (+0.0035 rad/s here) that is none.
    let e = planet(0.0729);
    let (run, m) = swing(&e, 0.0, 80.0, 1.0, 0.78, 600.0);
    assert_eq!(m.regime, FoucaultRegime::Unsteady, "{}", m.note);
    assert_eq!(
        (m.precession_rate, m.sense, m.sense_name()),
        (None, None, "undefined")
    );
    assert!(
        fit_precession_rate(&run.turn_times, &run.turn_angles)
            .unwrap()
            .abs()
            > 1e-3
    );
    // Two degrees from it, the rocking still beats the turn.
    let (_, m) = swing(&e, deg(2.0), 80.0, 1.0, 0.7, 100.0);
    assert_eq!(m.regime, FoucaultRegime::Unsteady, "{}", m.note);
    // A run shorter than two swings, and one where the turn is within the wobble.
    let (_, m) = swing(&e, deg(54.0), 80.0, 1.0, 0.0, 15.0);
    assert_eq!(m.regime, FoucaultRegime::TooShort, "{}", m.note);
    assert!(m.note.contains("two swings"));
    // Spin against √(g/L) = 0.99 rad/s: a half-swing-per-turn loop, then no rest at all.
    let (_, m) = swing(&planet(0.5), deg(45.0), 10.0, 1.0, 0.0, 60.0);
    assert_eq!(m.regime, FoucaultRegime::NotASwing, "{}", m.note);
    let fast = planet(1.2);
    assert!(fast
        .foucault_theory(FRAC_PI_2, 10.0)
        .unwrap()
        .modes
        .is_none());
    let s0 = fast.foucault_release(FRAC_PI_2, 10.0, 1.0, 0.0).unwrap();
    let run = fast
        .foucault(FRAC_PI_2, 10.0, s0, 0.0, 20.0, &[20.0], &options())
        .unwrap();
    let m = fast
        .foucault_measurement(
            FRAC_PI_2,
            10.0,
            &s0,
            0.0,
            20.0,
            &run.turn_times,
            &run.turn_angles,
        )
        .unwrap();
    assert_eq!(
        (m.regime, m.theory_rate),
        (FoucaultRegime::NoRest, None),
        "{}",
        m.note
    );
    // A swing nine tenths of the length wide: its own precession is not the Foucault rate.
    let (_, m) = swing(&e, deg(20.0), 80.0, 72.0, 0.3, 600.0);
    assert_eq!(m.regime, FoucaultRegime::WideSwing, "{}", m.note);
    assert_eq!(m.precession_rate, None);
    assert!(m.note.contains("0.900"), "{}", m.note);
}

/// A run whose turn is not larger than the plane's wobble (3° on the fast planet: wobble 0.42,
/// Δ = −5.2e-3 rad/s) is too short, and says how long would do; the longer run measures it.
/// Two degrees from the equator the wobble exceeds one half and no run length helps.
#[test]
fn too_short_runs_say_how_long_to_run() {
    let e = planet(0.0729);
    let (_, m) = swing(&e, deg(3.0), 80.0, 1.0, 0.7, 120.0);
    assert_eq!(m.regime, FoucaultRegime::TooShort, "{}", m.note);
    assert!(m.note.contains("run for at least"), "{}", m.note);
    let (_, m) = swing(&e, deg(3.0), 80.0, 1.0, 0.7, 1000.0);
    assert_eq!(m.regime, FoucaultRegime::Precessing, "{}", m.note);
    let (_, m) = swing(&e, deg(2.0), 80.0, 1.0, 0.7, 1000.0);
    assert_eq!(m.regime, FoucaultRegime::Unsteady, "{}", m.note);
}

#[test]
fn bad_input_names_the_argument() {
    let e = planet(0.0729);
    let s0 = e.foucault_release(0.5, 10.0, 1.0, 0.0).unwrap();
    let name = |r: poinsot::Result<FoucaultMeasurement>| r.unwrap_err().argument;
    assert_eq!(
        name(e.foucault_measurement(0.5, 10.0, &s0, 0.0, 10.0, &[1.0, 2.0], &[0.0])),
        "turn_times"
    );
    assert_eq!(
        name(e.foucault_measurement(0.5, 10.0, &s0, 0.0, 10.0, &[2.0, 1.0], &[0.0, 0.0])),
        "turn_times"
    );
    assert_eq!(
        name(e.foucault_measurement(0.5, 10.0, &s0, 0.0, 10.0, &[1.0, 2.0], &[0.0, f64::NAN])),
        "turn_angles"
    );
    assert_eq!(
        name(e.foucault_measurement(0.5, 10.0, &s0, 0.0, -1.0, &[], &[])),
        "t_end"
    );
    assert_eq!(
        name(e.foucault_measurement(2.0, 10.0, &s0, 0.0, 10.0, &[], &[])),
        "latitude"
    );
    assert_eq!(
        name(e.foucault_measurement(0.5, 0.0, &s0, 0.0, 10.0, &[], &[])),
        "length"
    );
    assert_eq!(
        e.foucault_release(0.5, 10.0, 10.0, 0.0)
            .unwrap_err()
            .argument,
        "amplitude"
    );
    assert_eq!(
        e.foucault_theory(0.5, f64::INFINITY).unwrap_err().argument,
        "length"
    );
    assert_eq!(
        planet(1e200)
            .foucault_theory(0.5, 10.0)
            .unwrap_err()
            .argument,
        "rotation_rate"
    );
    assert_eq!(
        fit_precession_rate(&[1.0, 1.0, 2.0], &[0.0; 3])
            .unwrap_err()
            .argument,
        "turn_times"
    );
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    /// Any planet with a spin from 1e-6 to 1.6 √(g/L) (the Earth's is 2e-4 for 67 m; beyond
    /// ~0.25 there is no swing, beyond 1 no rest), any latitude, amplitude up to 0.9 L, azimuth
    /// and run from 1 to 40 swings: every number is finite, and a rate comes only with the
    /// sense of the theory's mean rate Δ, i.e. clockwise in the north, counterclockwise in the
    /// south; a still plane has no sense and turns by less than the still angle over the run.
    /// (Run with PROPTEST_CASES=3000: passed.)
    #[test]
    fn never_the_wrong_sense(
        log_spin in -6.0f64..0.2,
        lat in -FRAC_PI_2..FRAC_PI_2,
        len in 1.0f64..100.0,
        amp_frac in 1e-3f64..0.9,
        az in 0.0f64..(2.0 * PI),
        swings in 1.0f64..40.0,
    ) {
        let w0 = (STANDARD_GRAVITY / len).sqrt();
        let e = planet(10f64.powf(log_spin) * w0);
        let duration = swings * 2.0 * PI / w0;
        let (_, m) = swing(&e, lat, len, amp_frac * len, az, duration);
        prop_assert!(m.expected_rate.is_finite());
        prop_assert!(m.theory_rate.is_none_or(f64::is_finite));
        match (m.regime, m.precession_rate, m.sense) {
            (FoucaultRegime::Precessing, Some(r), Some(s)) => {
                let delta = m.theory_rate.unwrap();
                prop_assert!(r.is_finite() && r.signum() == delta.signum() && r.signum() == -lat.signum(), "{r} {delta} {}", m.note);
                prop_assert_eq!(s, if r > 0.0 { Sense::Counterclockwise } else { Sense::Clockwise });
            }
            (FoucaultRegime::Still, Some(r), Some(Sense::None)) => {
                prop_assert!(r.is_finite() && r.abs() * duration <= 2.0 * poinsot::earth::STILL_ANGLE, "{r} {}", m.note);
            }
            (regime, None, None) => prop_assert!(regime != FoucaultRegime::Precessing && regime != FoucaultRegime::Still),
            other => prop_assert!(false, "inconsistent measurement {other:?}: {}", m.note),
        }
    }
}

/// The browser lab's run (120 s, 2401 samples) on its planet spinning `spin` times the Earth's
/// sidereal rate: whether the unit's rate −ω sin λ describes it.
fn lab_unit_rate(
    spin: f64,
    lat: f64,
    len: f64,
    amp: f64,
    duration: f64,
) -> (UnitRateCheck, FoucaultMeasurement) {
    let e = planet(spin * SIDEREAL_RATE);
    let run = e
        .foucault_swing(
            deg(lat),
            len,
            amp,
            0.0,
            duration,
            2401,
            &FOUCAULT_TOLERANCES,
        )
        .unwrap();
    (run.unit_rate().unwrap(), run.measurement)
}

/// Issue 12: the lab says when −ω sin λ stops holding. It holds for the lab's default run; it
/// stops when the spin is not small against √(g/L) (a long pendulum) or the swing is wide, and
/// the note says which; the departures are the measurement's own numbers (Δ against −ω sin λ,
/// the measured rate against the small-swing theory's fit); at the pole the spin's departure is
/// 0 whatever the spin (Δ = −ω exactly, the closed form); the amplitude's grows as (A/L)², of
/// the size of the swing's own precession (3/8)(A/L)².
#[test]
fn unit_rate_applies_only_to_a_slow_spin_and_a_small_swing() {
    // The lab's default: λ = 49°, L = 10 m, A = 1 m, 1000 times the Earth's spin.
    let (ok, m) = lab_unit_rate(1000.0, 49.0, 10.0, 1.0, 120.0);
    assert_eq!(m.regime, FoucaultRegime::Precessing, "{}", m.note);
    assert!(ok.holds, "{}", ok.note);
    let (delta, e) = (m.theory_rate.unwrap(), m.expected_rate);
    assert_eq!(
        ok.spin_departure,
        Some((delta - e).abs() / delta.abs().max(e.abs()))
    );
    let (r, fit) = (m.precession_rate.unwrap(), m.theory_fit_rate.unwrap());
    assert_eq!(ok.amplitude_departure, Some((r - fit).abs() / fit.abs()));
    assert!(
        (ok.spin_ratio - 1000.0 * SIDEREAL_RATE / (STANDARD_GRAVITY / 10.0).sqrt()).abs() < 1e-15
    );
    assert!(
        (ok.amplitude_ratio - 0.1).abs() < 1e-6,
        "{}",
        ok.amplitude_ratio
    );
    assert!(
        ok.note.starts_with("-omega sin(lambda) applies"),
        "{}",
        ok.note
    );

    // A long pendulum: ω/√(g/L) = 0.21, the small-swing rate is off −ω sin λ by over 1 %.
    let (long, m) = lab_unit_rate(1000.0, 49.0, 80.0, 1.0, 120.0);
    assert_eq!(m.regime, FoucaultRegime::Precessing, "{}", m.note);
    assert!(!long.holds);
    assert!(long.spin_departure.unwrap() > UNIT_RATE_TOLERANCE);
    assert!(long.amplitude_departure.unwrap() <= UNIT_RATE_TOLERANCE);
    assert!(
        long.note
            .contains("the spin is not small against the pendulum")
            && !long.note.contains("wide"),
        "{}",
        long.note
    );

    // A wide swing, A/L = 0.3: the measured rate leaves the small-swing theory's.
    let (wide, m) = lab_unit_rate(1000.0, 49.0, 10.0, 3.0, 120.0);
    assert_eq!(m.regime, FoucaultRegime::Precessing, "{}", m.note);
    assert!(!wide.holds);
    assert!(wide.spin_departure.unwrap() <= UNIT_RATE_TOLERANCE);
    let a = wide.amplitude_departure.unwrap();
    assert!(a > UNIT_RATE_TOLERANCE, "{a}");
    // Of the size of the swing's own precession: within a factor 2 of (3/8)(A/L)².
    let airy = 0.375 * 0.3_f64.powi(2);
    assert!(a > 0.5 * airy && a < 2.0 * airy, "{a} vs {airy}");
    assert!(
        wide.note.contains("the swing is wide") && !wide.note.contains("spin is not small"),
        "{}",
        wide.note
    );
    // Growing as (A/L)²: doubling A/L from 0.1 to 0.2 multiplies it by about 4 (the spin's
    // own part, common to both, aside).
    let (a1, _) = lab_unit_rate(1000.0, 49.0, 10.0, 1.0, 120.0);
    let (a2, _) = lab_unit_rate(1000.0, 49.0, 10.0, 2.0, 120.0);
    let growth = a2.amplitude_departure.unwrap() / a1.amplitude_departure.unwrap();
    assert!(growth > 2.5 && growth < 6.0, "{growth}");

    // The pole: Δ = −ω exactly, so the spin's departure vanishes for a fast spin too.
    let (pole, m) = lab_unit_rate(1000.0, 90.0, 80.0, 1.0, 120.0);
    assert!(
        pole.spin_departure.unwrap() < 1e-12,
        "{:?} ({})",
        pole.spin_departure,
        m.note
    );
    assert!(pole.holds, "{}", pole.note);

    // Negative control: a run that gives no steady turn is not said to follow −ω sin λ.
    let (short, m) = lab_unit_rate(1000.0, 49.0, 10.0, 1.0, 5.0);
    assert_ne!(m.regime, FoucaultRegime::Precessing);
    assert!(!short.holds && short.amplitude_departure.is_none());
    assert!(
        short
            .note
            .starts_with("-omega sin(lambda) cannot be compared"),
        "{}",
        short.note
    );
}

/// The measurement carries the simulated plane's time for one full turn beside its rate
/// (what the CLI's sentence quotes): 2π/|rate|, against the unit's closed form 2π/(Ω sin λ)
/// over a long run on the Earth; infinite where the plane is still, absent where the run gives
/// no rate; the unit's own period 2π/|Ω sin λ| beside −ω sin λ (infinite at the equator).
#[test]
fn full_turn_period_beside_the_rate() {
    let e = Earth::default();
    let lat = deg(48.85);
    let (_, m) = swing(&e, lat, 67.0, 1.0, 0.0, 7200.0);
    assert_eq!(m.regime, FoucaultRegime::Precessing, "{}", m.note);
    let closed = 2.0 * PI / (SIDEREAL_RATE * lat.sin());
    let period = m.full_turn_period.unwrap();
    assert_eq!(period, 2.0 * PI / m.precession_rate.unwrap().abs());
    // About 31.8 h; the run's rate is within the amplitude's and the wobble's 1e-3 of the unit's.
    assert!((period / closed - 1.0).abs() < 1e-3, "{period} vs {closed}");
    assert!((m.expected_full_turn_period / closed - 1.0).abs() < 1e-14);
    // Negative control: the period is not that of the half turn a swing plane repeats after.
    assert!((period / (0.5 * closed) - 1.0).abs() > 0.5);
    // Still at the equator: no turn, an infinite period; the unit's is infinite too.
    let (_, m) = swing(&e, 0.0, 67.0, 1.0, 0.3, 3600.0);
    assert_eq!(m.regime, FoucaultRegime::Still, "{}", m.note);
    assert_eq!(m.full_turn_period, Some(f64::INFINITY));
    assert_eq!(m.expected_full_turn_period, f64::INFINITY);
    // A run too short to measure: no rate, no period; the unit's is finite.
    let (_, m) = swing(&e, lat, 67.0, 1.0, 0.0, 10.0);
    assert_eq!(m.regime, FoucaultRegime::TooShort, "{}", m.note);
    assert_eq!((m.precession_rate, m.full_turn_period), (None, None));
    assert!((m.expected_full_turn_period / closed - 1.0).abs() < 1e-14);
}
