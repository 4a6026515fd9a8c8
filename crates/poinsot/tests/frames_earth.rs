//! Tests of the rotating Earth (`poinsot::earth`, the unit's eqs. 2.29–2.42): the unit's
//! worked numbers, hemisphere signs, limits, and exact integrations against closed forms.

use poinsot::earth::{
    fit_precession_rate, Earth, FallModel, Gravity, SIDEREAL_RATE, SOLAR_DAY_RATE,
};
use poinsot::frames::{simulate_particle, MovingFrame, ParticleState, SteadyMotion};
use poinsot::integrate::{Crossing, Options};
use poinsot::{ErrorKind, Vec3};
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

fn deg(x: f64) -> f64 {
    x.to_radians()
}

/// Relative closeness.
fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

#[test]
fn convention_sidereal_default_and_enu_omega() {
    let e = Earth::default();
    assert_eq!(e.rotation_rate, 7.2921150e-5);
    // The nominal IERS value; 2π/86164.0905 s differs from it by 1.2e-7.
    assert!(rel(SIDEREAL_RATE, 2.0 * PI / 86164.0905) < 2e-7);
    // ENU: ω = ω (0, cos λ, sin λ): along north at the equator, up at the north pole.
    let w = e.omega_enu(deg(30.0)).unwrap();
    assert!((w - SIDEREAL_RATE * Vec3::new(0.0, deg(30.0).cos(), 0.5)).norm() < 1e-20);
    assert!((e.omega_enu(FRAC_PI_2).unwrap() - SIDEREAL_RATE * Vec3::z()).norm() < 1e-20);
    assert!(rel(SOLAR_DAY_RATE, 7.2722e-5) < 1e-4);
}

/// The unit's numbers with its solar-day rate, and the errata's sidereal ones.
#[test]
fn the_units_worked_numbers() {
    let solar = Earth::new(SOLAR_DAY_RATE, 6.4e6, 9.81).unwrap();
    assert_eq!(format!("{:.2e}", solar.rotation_rate), "7.27e-5");
    let c = solar.centrifugal_acceleration(0.0).unwrap().norm();
    assert_eq!(format!("{c:.1e}"), "3.4e-2");
    assert!(rel(c, 3.38e-2) < 2e-3);
    assert!(rel(2.0 * solar.rotation_rate, 1.45e-4) < 4e-3);
    let x = solar.eastward_deflection(100.0, FRAC_PI_4).unwrap();
    assert_eq!(format!("{x:.2e}"), "1.55e-2");
    assert!(rel(x, 1.548e-2) < 1e-3);
    let sidereal = Earth::new(SIDEREAL_RATE, 6.4e6, 9.80665).unwrap();
    assert!(
        rel(
            sidereal.centrifugal_acceleration(0.0).unwrap().norm(),
            3.40e-2
        ) < 2e-3
    );
    assert!(rel(2.0 * sidereal.rotation_rate, 1.458e-4) < 1e-3);
    assert!(
        rel(
            Earth::default()
                .eastward_deflection(100.0, FRAC_PI_4)
                .unwrap(),
            1.552e-2
        ) < 1e-3
    );
}

#[test]
fn effective_gravity_limits_and_plumb_line() {
    let e = Earth::default();
    let w2r = SIDEREAL_RATE.powi(2) * e.radius;
    let pole = e.effective_gravity(FRAC_PI_2).unwrap();
    assert!((pole.magnitude - e.g).abs() < 1e-12 && pole.deviation.abs() < 1e-15);
    let eq = e.effective_gravity(0.0).unwrap();
    assert!((eq.magnitude - (e.g - w2r)).abs() < 1e-12 && eq.deviation.abs() < 1e-15);
    // Largest deviation near 45°, about 0.1°, towards the equator in both hemispheres.
    let n = e.effective_gravity(FRAC_PI_4).unwrap();
    let s = e.effective_gravity(-FRAC_PI_4).unwrap();
    assert!(n.deviation > 0.0 && s.deviation < 0.0 && rel(n.deviation, -s.deviation) < 1e-12);
    assert!(
        (n.deviation.to_degrees() - 0.0995).abs() < 2e-3,
        "{}",
        n.deviation.to_degrees()
    );
    assert!(n.vector.y < 0.0 && s.vector.y > 0.0);
}

/// Horizontal motion is deflected to the right in the north, left in the south, not at all
/// at the equator (the unit's discussion of Fig. 2.5–2.7).
#[test]
fn coriolis_hemisphere_signs() {
    let e = Earth::default();
    let v = Vec3::new(0.0, 10.0, 0.0); // northward
    let n = e.coriolis_acceleration(deg(45.0), &v).unwrap();
    let s = e.coriolis_acceleration(deg(-45.0), &v).unwrap();
    let q = e.coriolis_acceleration(0.0, &v).unwrap();
    assert!(
        n.x > 0.0,
        "north: to the right of a northward motion is east"
    );
    assert!(s.x < 0.0, "south: to the left");
    assert!(q.norm() < 1e-20, "equator: nothing for horizontal motion");
    // 2ω v at the pole (the unit's 1.5e-4 v_r).
    assert!(
        rel(
            e.coriolis_acceleration(FRAC_PI_2, &v).unwrap().norm(),
            2.0 * SIDEREAL_RATE * 10.0
        ) < 1e-12
    );
}

/// The exact drop approaches the unit's first-order 2.42 as h → 0, and its southward
/// deflection approaches the second-order closed form.
#[test]
fn drop_exact_tends_to_first_order() {
    let e = Earth::default();
    let model = FallModel::default();
    let mut prev = f64::INFINITY;
    for &h in &[1e4, 1e3, 1e2, 1e1] {
        let fall = e.drop(h, FRAC_PI_4, &model).unwrap();
        let first = e.eastward_deflection(h, FRAC_PI_4).unwrap();
        let r = rel(fall.east, first);
        assert!(
            r < prev,
            "h = {h}: relative difference {r:e} must shrink with h"
        );
        prev = r;
        let south = e.southward_deflection(h, FRAC_PI_4).unwrap();
        assert!(
            rel(-fall.north, south) < 1e-3,
            "h = {h}: south {} vs {south}",
            -fall.north
        );
        // The time of fall changes at second order, by about (ω T)².
        let t0 = e.fall_time(h).unwrap();
        assert!(
            rel(fall.time, t0) < (SIDEREAL_RATE * t0).powi(2),
            "h = {h}: {} vs {t0}",
            fall.time
        );
    }
    assert!(prev < 1e-7);
    let fall = e.drop(100.0, FRAC_PI_4, &model).unwrap();
    assert!(rel(fall.east, 1.552e-2) < 1e-3);
}

/// Landing points: east in both hemispheres, equatorward, none at the poles.
#[test]
fn drop_hemispheres_equator_and_poles() {
    let e = Earth::default();
    let m = FallModel::default();
    let n = e.drop(200.0, deg(40.0), &m).unwrap();
    let s = e.drop(200.0, deg(-40.0), &m).unwrap();
    assert!(n.east > 0.0 && s.east > 0.0 && rel(n.east, s.east) < 1e-9);
    assert!(n.north < 0.0 && s.north > 0.0, "towards the equator");
    let q = e.drop(200.0, 0.0, &m).unwrap();
    assert!(q.east > n.east && q.north.abs() < 1e-12);
    let p = e.drop(200.0, FRAC_PI_2, &m).unwrap();
    assert!(p.east.abs() < 1e-12 && p.north.abs() < 1e-12);
    // Without rotation it falls straight down.
    let still = e
        .drop(
            200.0,
            deg(40.0),
            &FallModel {
                rotation: false,
                ..m
            },
        )
        .unwrap();
    assert!(still.east.abs() < 1e-14 && still.north.abs() < 1e-14);
    // Weaker gravity aloft: a slower, longer fall and more eastward drift.
    let sq = e
        .drop(
            1e4,
            deg(40.0),
            &FallModel {
                gravity: Gravity::InverseSquare,
                ..m
            },
        )
        .unwrap();
    let un = e.drop(1e4, deg(40.0), &m).unwrap();
    assert!(sq.time > un.time && sq.east > un.east);
}

/// The drop of `Earth::drop` is the general moving-frame integrator's particle in a frame
/// rotating with ω (ENU) whose origin feels the centripetal acceleration of the surface.
#[test]
fn drop_agrees_with_the_general_moving_frame_integrator() {
    let e = Earth::default();
    let lat = deg(50.0);
    let w = e.omega_enu(lat).unwrap();
    let rho0 = Vec3::new(0.0, 0.0, e.radius);
    // True gravity is −gẑ + ω×(ω×ρ₀) so that the effective gravity at the origin is −gẑ.
    let g_true = Vec3::new(0.0, 0.0, -e.g) + w.cross(&w.cross(&rho0));
    let frame = MovingFrame::new(
        Vec3::zeros(),
        Vec3::zeros(),
        w.cross(&w.cross(&rho0)),
        w,
        Vec3::zeros(),
    )
    .unwrap();
    // In ENU components the frame's state is constant (it rotates with the Earth).
    let motion = move |_t: f64| frame;
    let opts = Options::with_tolerances(1e-12, 1e-12);
    let sol = simulate_particle(
        &motion,
        2.0,
        Vec3::new(0.0, 0.0, 300.0),
        Vec3::zeros(),
        0.0,
        100.0,
        |_t, _r, _v| 2.0 * g_true,
        &opts,
        Some((|_t: f64, y: &ParticleState| y[2], Crossing::Falling)),
    )
    .unwrap();
    let ev = sol.event.unwrap();
    let fall = e.drop(300.0, lat, &FallModel::default()).unwrap();
    assert!(rel(ev.t, fall.time) < 1e-11);
    assert!(rel(ev.y[0], fall.east) < 1e-9 && rel(ev.y[1], fall.north) < 1e-7);
    let _ = SteadyMotion::new(frame).unwrap();
}

#[test]
fn projectile_range_and_drift() {
    let e = Earth::default();
    let (v, el) = (300.0, FRAC_PI_4);
    let still = FallModel {
        rotation: false,
        ..FallModel::default()
    };
    let flat = e.projectile(v, el, 0.3, deg(45.0), 0.0, &still).unwrap();
    assert!(rel(flat.range, v * v * (2.0 * el).sin() / e.g) < 1e-10);
    assert!(flat.drift.abs() < 1e-9 && rel(flat.time, 2.0 * v * el.sin() / e.g) < 1e-10);
    // Rotation: drift to the right in the north, to the left in the south, for any azimuth.
    for az in [0.0, 1.0, 2.5, 4.0] {
        let n = e
            .projectile(v, el, az, deg(45.0), 0.0, &FallModel::default())
            .unwrap();
        let s = e
            .projectile(v, el, az, deg(-45.0), 0.0, &FallModel::default())
            .unwrap();
        assert!(
            n.drift > 0.0 && s.drift < 0.0,
            "azimuth {az}: {} {}",
            n.drift,
            s.drift
        );
    }
    // First-order drift of a lofted shot (vertical-Coriolis part): ω sinλ v³ sin²α cosα... sanity: O(ωT·range).
    let n = e
        .projectile(v, el, 0.0, deg(45.0), 0.0, &FallModel::default())
        .unwrap();
    assert!(n.drift < 1e-3 * n.range * 10.0);
}

#[test]
fn foucault_plane_turns_at_omega_sin_latitude() {
    // A fast-turning planet keeps the run short; amplitude 1 % of the length.
    let e = Earth::new(1e-3, 6.371e6, 9.81).unwrap();
    let opts = Options {
        dense: false,
        ..Options::with_tolerances(1e-11, 1e-12)
    };
    for lat in [deg(50.0), deg(-50.0), FRAC_PI_2] {
        let s0 = e.foucault_release(lat, 10.0, 0.1, 0.0).unwrap();
        let run = e
            .foucault(lat, 10.0, s0, 0.0, 600.0, &[0.0, 600.0], &opts)
            .unwrap();
        let rate = fit_precession_rate(&run.turn_times, &run.turn_angles).unwrap();
        let expect = e.foucault_rate(lat).unwrap();
        assert!(
            rel(rate, expect) < 2e-3,
            "latitude {lat}: {rate} vs {expect}"
        );
        // |r| stays the length of the string.
        let r = run.final_state;
        assert!(((r[0] * r[0] + r[1] * r[1] + r[2] * r[2]).sqrt() - 10.0).abs() < 1e-8);
    }
    // Clockwise (negative) in the north.
    assert!(e.foucault_rate(deg(50.0)).unwrap() < 0.0);
    // At the equator the plane does not turn.
    let s0 = e.foucault_release(0.0, 10.0, 0.1, 0.3).unwrap();
    let run = e.foucault(0.0, 10.0, s0, 0.0, 600.0, &[], &opts).unwrap();
    let rate = fit_precession_rate(&run.turn_times, &run.turn_angles).unwrap();
    assert!(rate.abs() < 1e-3 * e.rotation_rate, "{rate}");
}

#[test]
fn inertial_oscillations_and_the_low() {
    let e = Earth::default();
    let opts = Options::with_tolerances(1e-12, 1e-12);
    for lat in [deg(45.0), deg(-30.0)] {
        let f = e.coriolis_parameter(lat).unwrap();
        let period = e.inertial_period(lat).unwrap();
        let run = e
            .inertial_oscillation(
                lat,
                [10.0, 0.0],
                period,
                &[0.0, period / 2.0, period],
                &opts,
            )
            .unwrap();
        assert!(rel(run.turning_rate, -f) < 1e-9);
        // Back at the start after one inertial period; half-way the diameter 2v/|f| away.
        let end = run.states[2];
        assert!(end[0].hypot(end[1]) < 1e-6 * 10.0 / f.abs());
        let mid = run.states[1];
        assert!(rel(mid[0].hypot(mid[1]), 20.0 / f.abs()) < 1e-9);
    }
    let eq = e
        .inertial_oscillation(0.0, [10.0, 5.0], 1e5, &[1e5], &opts)
        .unwrap();
    assert!(eq.turning_rate.abs() < 1e-15 && (eq.states[0][0] - 1e6).abs() < 1e-3);
    // Flow into a low: counterclockwise in the north, clockwise in the south.
    let starts = [[5e5, 0.0], [0.0, 5e5], [-5e5, 0.0], [0.0, -5e5]];
    let n = e
        .flow_into_low(deg(45.0), &starts, 2e-9, 1e-5, 2e5, &[2e5], &opts)
        .unwrap();
    let s = e
        .flow_into_low(deg(-45.0), &starts, 2e-9, 1e-5, 2e5, &[2e5], &opts)
        .unwrap();
    assert!(n.circulation > 0.0 && s.circulation < 0.0);
    assert!(rel(n.circulation, -s.circulation) < 1e-9);
}

#[test]
fn bad_input_names_the_argument() {
    let e = Earth::default();
    for lat in [deg(90.5), -2.0, f64::NAN, f64::INFINITY] {
        let err = e.omega_enu(lat).unwrap_err();
        assert_eq!(
            (err.kind, err.argument.as_str()),
            (ErrorKind::InvalidArgument, "latitude")
        );
    }
    assert!(e.omega_enu(FRAC_PI_2).is_ok() && e.omega_enu(-FRAC_PI_2).is_ok());
    assert_eq!(
        e.eastward_deflection(-1.0, 0.3).unwrap_err().argument,
        "height"
    );
    assert_eq!(
        e.drop(-1.0, 0.3, &FallModel::default())
            .unwrap_err()
            .argument,
        "height"
    );
    assert_eq!(
        e.drop(f64::NAN, 0.3, &FallModel::default())
            .unwrap_err()
            .argument,
        "height"
    );
    let bad = FallModel {
        options: Options::with_tolerances(0.0, 1e-9),
        ..FallModel::default()
    };
    assert_eq!(e.drop(10.0, 0.3, &bad).unwrap_err().argument, "rtol");
    assert_eq!(
        Earth::new(-1.0, 1.0, 1.0).unwrap_err().argument,
        "rotation_rate"
    );
    assert_eq!(Earth::new(1.0, 0.0, 1.0).unwrap_err().argument, "radius");
    assert_eq!(
        e.projectile(0.0, 0.5, 0.0, 0.0, 0.0, &FallModel::default())
            .unwrap_err()
            .argument,
        "speed"
    );
    assert_eq!(
        e.projectile(10.0, -0.5, 0.0, 0.0, 0.0, &FallModel::default())
            .unwrap_err()
            .argument,
        "elevation"
    );
    assert_eq!(
        e.foucault_release(0.3, 1.0, 2.0, 0.0).unwrap_err().argument,
        "amplitude"
    );
}

/// Jacobi's integral of the Foucault run: conserved to the integrator's tolerance, also on a
/// fast-spinning planet where the centrifugal term matters; the plain energy ½v² + g z, which
/// leaves the centrifugal potential out, drifts far more there (the negative control).
#[test]
fn foucault_conserves_jacobis_integral() {
    // rtol 1e-10 over 120 s of a 10 m pendulum: the drift stays below 1e-8 of g L.
    const DRIFT: f64 = 1e-8;
    let e = Earth::new(1000.0 * SIDEREAL_RATE, poinsot::earth::MEAN_RADIUS, 9.80665).unwrap();
    let (lat, len) = (deg(40.0), 10.0);
    let s0 = e.foucault_release(lat, len, 1.0, 0.3).unwrap();
    let times: Vec<f64> = (0..=120).map(|i| i as f64).collect();
    let run = e
        .foucault(
            lat,
            len,
            s0,
            0.0,
            120.0,
            &times,
            &Options::with_tolerances(1e-10, 1e-12),
        )
        .unwrap();
    let j0 = e.jacobi_integral(lat, &s0).unwrap();
    let scale = e.g * len;
    let mut worst: f64 = 0.0;
    let mut plain_worst: f64 = 0.0;
    let plain = |s: &ParticleState| 0.5 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]) + e.g * s[2];
    for s in &run.states {
        worst = worst.max((e.jacobi_integral(lat, s).unwrap() - j0).abs() / scale);
        plain_worst = plain_worst.max((plain(s) - plain(&s0)).abs() / scale);
    }
    assert!(worst < DRIFT, "Jacobi drift {worst:e}");
    assert!(
        plain_worst > 1e3 * DRIFT,
        "the plain energy should not be conserved: {plain_worst:e}"
    );
    // Its value: released from rest, J = g z − ½ |ω × r|².
    let w = e.omega_enu(lat).unwrap();
    let r = Vec3::new(s0[0], s0[1], s0[2]);
    assert!((j0 - (e.g * s0[2] - 0.5 * w.cross(&r).norm_squared())).abs() < 1e-12 * scale);
    assert_eq!(
        e.jacobi_integral(2.0, &s0).unwrap_err().argument,
        "latitude"
    );
    assert_eq!(
        e.jacobi_integral(lat, &[f64::NAN; 6]).unwrap_err().argument,
        "state"
    );
}

/// The low's energy budget: energy + work against friction is constant; without friction the
/// energy itself is; continuing a run from a sample reproduces the run.
#[test]
fn low_energy_budget_and_continuation() {
    // rtol 1e-12: the budget closes to 1e-9 of the initial potential energy.
    const BUDGET: f64 = 1e-9;
    let e = Earth::default();
    let opts = Options::with_tolerances(1e-12, 1e-6);
    let starts = [[5e5, 0.0], [0.0, 5e5], [-3e5, -1e5]];
    let times: Vec<f64> = (0..=48).map(|i| i as f64 * 3600.0).collect();
    let k = 2e-9;
    for gamma in [0.0, 1e-5, 5e-5] {
        let run = e
            .flow_into_low(deg(45.0), &starts, k, gamma, 48.0 * 3600.0, &times, &opts)
            .unwrap();
        for (p, start) in starts.iter().enumerate() {
            let e0 = run.energy[p][0];
            assert!((e0 - 0.5 * k * (start[0].powi(2) + start[1].powi(2))).abs() < 1e-12 * e0);
            for i in 0..times.len() {
                let budget = run.energy[p][i] + run.dissipated[p][i] - e0;
                assert!(
                    budget.abs() < BUDGET * e0,
                    "gamma {gamma} parcel {p} sample {i}: {budget:e}"
                );
            }
            let lost = run.dissipated[p][times.len() - 1];
            if gamma == 0.0 {
                assert_eq!(lost, 0.0);
            } else {
                // Friction takes a real share of the energy (the control: the budget is not trivial).
                assert!(lost > 0.1 * e0, "gamma {gamma}: lost {lost:e} of {e0:e}");
            }
        }
        // Continue from sample 10 to the end: the same states at the later samples.
        let from: Vec<[f64; 4]> = run.parcels.iter().map(|p| p[10]).collect();
        let rest = e
            .flow_into_low_from(
                deg(45.0),
                &from,
                times[10],
                k,
                gamma,
                times[48],
                &times[10..],
                &opts,
            )
            .unwrap();
        for p in 0..starts.len() {
            for (i, s) in rest.parcels[p].iter().enumerate() {
                let want = run.parcels[p][10 + i];
                let err = ((s[0] - want[0]).hypot(s[1] - want[1])) / 5e5;
                assert!(err < 1e-8, "continuation parcel {p} sample {i}: {err:e}");
                let d = rest.dissipated[p][i] + run.dissipated[p][10] - run.dissipated[p][10 + i];
                assert!(d.abs() < BUDGET * run.energy[p][0]);
            }
        }
    }
    let bad = e
        .flow_into_low_from(0.5, &[[1.0, 0.0, 0.0, 0.0]], 10.0, k, 0.0, 5.0, &[], &opts)
        .unwrap_err();
    assert_eq!(bad.argument, "t_end");
    let bad = e
        .flow_into_low_from(0.5, &[], 0.0, k, 0.0, 5.0, &[], &opts)
        .unwrap_err();
    assert_eq!(bad.argument, "states");
    let bad = e
        .flow_into_low_from(
            0.5,
            &[[1.0, f64::NAN, 0.0, 0.0]],
            0.0,
            k,
            0.0,
            5.0,
            &[],
            &opts,
        )
        .unwrap_err();
    assert_eq!(bad.argument, "states");
}
