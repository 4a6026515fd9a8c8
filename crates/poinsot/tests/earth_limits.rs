//! Issue 21, items 2, 12 and 13: overflow refused (never returned as a number), the short toss
//! that was refused as "orbital", and the names and numbers of messages.

use poinsot::analytic::{EulerState, HeavyTop};
use poinsot::earth::{Earth, FallModel};
use poinsot::error::Error;
use poinsot::frames::{MovingFrame, SteadyMotion};
use poinsot::inertia::MassProperties;
use poinsot::{Mat3, Vec3};

/// The longest run of decimal digits in `s`.
fn longest_digit_run(s: &str) -> usize {
    s.split(|c: char| !c.is_ascii_digit())
        .map(str::len)
        .max()
        .unwrap_or(0)
}

fn earth(rate: f64) -> Earth {
    Earth::new(rate, 6.371e6, 9.80665).unwrap()
}

#[test]
fn centrifugal_and_effective_gravity_overflow_is_refused_naming_rotation_rate() {
    // ω² R cos λ sin λ = 1e302 · 6.371e6 · 0.42 ≈ 2.7e308: beyond the largest double.
    let e = earth(1e151);
    for err in [
        e.centrifugal_acceleration(0.5).unwrap_err(),
        e.effective_gravity(0.5).unwrap_err(),
    ] {
        assert_eq!(err.argument, "rotation_rate", "{err}");
        assert!(err.message.contains("overflows"), "{err}");
    }
    // Negative control: the same planet at the pole has no centrifugal acceleration... only
    // round-off of cos(π/2) = 6e-17, ω² R cos λ ≈ 4e296: finite, returned.
    assert!(e
        .centrifugal_acceleration(std::f64::consts::FRAC_PI_2)
        .is_ok());
}

#[test]
fn effective_gravity_at_1e150_is_finite_and_its_magnitude_matches_the_vector() {
    // ω = 1e150: ω² = 1e300 does not overflow, but |g_e|² = 3e613 does (the old norm gave inf).
    let (w, lat) = (1e150, 0.5f64);
    let e = earth(w);
    let eg = e.effective_gravity(lat).unwrap();
    // Closed form at unit scale: g_e = (0, −ω²R cos λ sin λ, ω²R cos² λ − g), ω² = 1e300.
    let (s, c) = lat.sin_cos();
    let a = 6.371e6 * c; // ω² R cos λ / 1e300
    let (y, z) = (-a * s, a * c); // g = 9.8 is below the last bit of 1e306
    assert!(
        (eg.vector.y / 1e300 - y).abs() <= 1e-15 * y.abs(),
        "{:?}",
        eg.vector
    );
    assert!(
        (eg.vector.z / 1e300 - z).abs() <= 1e-15 * z.abs(),
        "{:?}",
        eg.vector
    );
    assert!(eg.magnitude.is_finite());
    assert!(
        (eg.magnitude / 1e300 - a).abs() <= 1e-15 * a,
        "{}",
        eg.magnitude
    );
    // g_e ≈ ω² R cos λ (0, −sin λ, cos λ) (g is negligible) points up and south: its angle
    // from the downward radial direction −ẑ is π − λ, computed from finite components.
    let want = std::f64::consts::PI - lat;
    assert!((eg.deviation - want).abs() <= 1e-15, "{}", eg.deviation);
    // The ordinary Earth is unchanged: |g_e| = √((ω²R c s)² + (g − ω²R c²)²).
    let ord = Earth::default().effective_gravity(lat).unwrap();
    let w2r = 7.2921150e-5f64.powi(2) * 6.371e6;
    let want = (w2r * c * s).hypot(9.80665 - w2r * c * c);
    assert!((ord.magnitude - want).abs() <= 1e-15 * want);
}

#[test]
fn inertial_period_overflow_is_refused_and_the_equator_is_the_documented_infinity() {
    let e = Earth::default();
    // π/(ω sin λ) at λ = 1e-305 is 4e309: not a double. The old code returned inf.
    let err = e.inertial_period(1e-305).unwrap_err();
    assert_eq!(err.argument, "latitude", "{err}");
    assert!(longest_digit_run(&err.to_string()) <= 17, "{err}");
    // The documented infinities: the equator, and a planet that does not turn.
    assert_eq!(e.inertial_period(0.0).unwrap(), f64::INFINITY);
    assert_eq!(earth(0.0).inertial_period(0.7).unwrap(), f64::INFINITY);
    // Close to the equator but representable: the closed form π/(ω sin λ).
    let p = e.inertial_period(1e-300).unwrap();
    let want = std::f64::consts::PI / (7.2921150e-5 * 1e-300);
    assert!((p - want).abs() <= 2e-16 * want, "{p} vs {want}");
}

#[test]
fn coriolis_overflow_is_refused() {
    // 2 ω sin λ = 2e308 overflows; ω = 1e308 itself is a valid rate.
    let e = earth(1e308);
    assert_eq!(
        e.coriolis_parameter(1.0).unwrap_err().argument,
        "rotation_rate"
    );
    assert!(earth(8e307).coriolis_parameter(1.0).unwrap().is_finite());
    let err = e
        .coriolis_acceleration(0.5, &Vec3::new(1e10, 0.0, 0.0))
        .unwrap_err();
    assert_eq!(err.argument, "velocity_enu", "{err}");
}

/// The landing point (east, north) of a toss from the ground on a flat, uniformly pulling,
/// rotating Earth, to first order in ω: r = v t − ½ g t² ẑ − ω × v t² + ⅓ g t³ ω × ẑ, landing
/// at T = T₀ + δT with T₀ = 2 v_z / g and δT = z₁(T₀) / v_z.
fn first_order_landing(w: Vec3, v: Vec3, g: f64) -> (f64, f64) {
    let t0 = 2.0 * v.z / g;
    let r1 = -w.cross(&v) * t0 * t0 + w.cross(&Vec3::z()) * (g * t0.powi(3) / 3.0);
    let dt = r1.z / v.z;
    (v.x * t0 + r1.x + v.x * dt, v.y * t0 + r1.y + v.y * dt)
}

#[test]
fn a_short_toss_lands_where_the_closed_form_says() {
    // 0.15 m/s at 0.5 rad lasts 0.0147 s; it was refused as "is 0.15 m/s an orbital speed?".
    let (speed, elev, az, lat) = (0.15f64, 0.5f64, 0.3f64, 0.5f64);
    let flat = FallModel {
        rotation: false,
        ..FallModel::default()
    };
    let g = 9.80665;
    for (speed, elev) in [(speed, elev), (100.0, 1e-6)] {
        let f = Earth::default()
            .projectile(speed, elev, az, lat, 0.0, &flat)
            .unwrap();
        // Without rotation: T = 2 v sin e / g, range = v² sin 2e / g, exactly a parabola.
        let t = 2.0 * speed * elev.sin() / g;
        let range = speed * speed * (2.0 * elev).sin() / g;
        assert!((f.time - t).abs() <= 1e-10 * t, "{} vs {t}", f.time);
        assert!(
            (f.range - range).abs() <= 1e-10 * range,
            "{} vs {range}",
            f.range
        );
        assert!(f.drift.abs() <= 1e-12 * range);
    }
    // With rotation (a planet turning at 0.01 rad/s so that the Coriolis deflection, 3e-7 m,
    // stands well above the tolerance): against the first-order closed form.
    let e = Earth::new(0.01, 6.371e6, g).unwrap();
    let model = FallModel {
        centrifugal: false,
        ..FallModel::default()
    };
    let f = e.projectile(speed, elev, az, lat, 0.0, &model).unwrap();
    let v = speed * Vec3::new(elev.cos() * az.sin(), elev.cos() * az.cos(), elev.sin());
    let w = e.omega_enu(lat).unwrap();
    let (east, north) = first_order_landing(w, v, g);
    let (east0, north0) = (v.x * 2.0 * v.z / g, v.y * 2.0 * v.z / g);
    let deflection = (east - east0).hypot(north - north0);
    assert!(deflection > 1e-7, "{deflection}");
    let miss = (f.east - east).hypot(f.north - north);
    assert!(
        miss <= 1e-3 * deflection,
        "miss {miss} of a deflection {deflection}"
    );
}

#[test]
fn a_toss_too_low_for_doubles_is_refused_naming_elevation_not_called_orbital() {
    let err = Earth::default()
        .projectile(1.0, 1e-200, 0.0, 0.5, 0.0, &FallModel::default())
        .unwrap_err();
    assert_eq!(err.argument, "elevation", "{err}");
    assert!(!err.message.contains("orbital"), "{err}");
    assert!(longest_digit_run(&err.to_string()) <= 17, "{err}");
}

#[test]
fn a_steady_frame_carried_out_of_range_by_t_names_t() {
    let frame = MovingFrame {
        acceleration: Vec3::new(0.0, 0.0, 1.0),
        ..MovingFrame::default()
    };
    let motion = SteadyMotion::new(frame).unwrap();
    let err = motion.state_at(1e200).unwrap_err();
    assert_eq!(err.argument, "t", "{err}");
    assert_eq!(motion.state_at(f64::NAN).unwrap_err().argument, "t");
    // Negative control: ½ R̈ t² at t = 1e100 is 5e199, finite.
    let f = motion.state_at(1e100).unwrap();
    assert_eq!(f.origin.z, 0.5 * 1e200);
}

#[test]
fn inertia_given_about_a_far_point_names_about() {
    let err = MassProperties::from_inertia_about(
        1.0,
        Vec3::zeros(),
        Mat3::identity(),
        Vec3::new(1e155, 0.0, 0.0),
    )
    .unwrap_err();
    assert_eq!(err.argument, "about", "{err}");
    let err = MassProperties::from_inertia_about(
        1.0,
        Vec3::zeros(),
        Mat3::identity(),
        Vec3::new(f64::NAN, 0.0, 0.0),
    )
    .unwrap_err();
    assert_eq!(err.argument, "about", "{err}");
}

#[test]
fn messages_print_extreme_numbers_in_exponent_form() {
    let state = EulerState {
        phi: 0.0,
        theta: 0.5,
        psi: 0.0,
        phi_dot: 0.0,
        theta_dot: 0.0,
        psi_dot: 0.0,
    };
    // HeavyTop(1e-308, .5, 1, .5): "I3: must be <= 2*I1 = 0.000…0002" (310 characters) before.
    let mut messages: Vec<Error> = vec![
        HeavyTop::new(1e-308, 0.5, 1.0, state).unwrap_err(),
        HeavyTop::new(1.0, 1e308, 1.0, state).unwrap_err(),
        Earth::default().inertial_period(1e-305).unwrap_err(),
        Earth::default()
            .projectile(1.0, 2.0, 0.0, 0.5, 0.0, &FallModel::default())
            .unwrap_err(),
    ];
    messages.push(earth(1e151).effective_gravity(0.5).unwrap_err());
    for err in &messages {
        let text = err.to_string();
        assert!(longest_digit_run(&text) <= 17, "{text}");
    }
    let top = messages[0].to_string();
    assert!(top.contains("2e-308"), "{top}");
}

/// Issue 22, item 1: the Earth's runs name the caller's own arguments (the front ends rename
/// nothing), and return finite numbers or an error.
mod the_caller_s_names {
    use poinsot::earth::{
        Earth, FallModel, LowSetup, FOUCAULT_TOLERANCES, INERTIAL_TOLERANCES, LOW_TOLERANCES,
    };

    /// Every error of a call names one of `allowed` (the call's arguments and the Earth's).
    fn names(err: poinsot::Error, allowed: &[&str]) {
        let ok = allowed.contains(&err.argument.as_str())
            || ["rotation_rate", "radius", "g"].contains(&err.argument.as_str());
        assert!(ok, "{err} names none of {allowed:?}");
    }

    #[test]
    fn a_drop_whose_integration_fails_names_the_height() {
        // The integrator's end, start and time were `t_end`, `y0` and `t`.
        let err = Earth::default()
            .drop(1e308, 0.5, &FallModel::default())
            .unwrap_err();
        assert_eq!(err.argument, "height", "{err}");
    }

    #[test]
    fn a_fall_brings_its_closed_forms_and_a_finite_state_at_any_time() {
        let e = Earth::default();
        let fall = e.drop(100.0, 0.7, &FallModel::default()).unwrap();
        assert_eq!(
            fall.first_order_east,
            e.eastward_deflection(100.0, 0.7).unwrap()
        );
        assert_eq!(
            fall.second_order_south,
            e.southward_deflection(100.0, 0.7).unwrap()
        );
        let land = fall.state_at(fall.time).unwrap();
        assert_eq!((land[0], land[1]), (fall.east, fall.north));
        assert_eq!(fall.state_at(-1.0).unwrap_err().argument, "t");
        assert_eq!(fall.state_at(f64::NAN).unwrap_err().argument, "t");
    }

    #[test]
    fn a_fall_time_beyond_doubles_is_refused_naming_the_height() {
        let e = Earth::new(7e-5, 6.4e6, 1e-300).unwrap();
        assert_eq!(e.fall_time(1e300).unwrap_err().argument, "height");
        assert!(e.fall_time(1.0).unwrap().is_finite());
    }

    #[test]
    fn a_release_beyond_doubles_names_the_amplitude() {
        // |r0| of a 1e300 m string overflows: the release was named `state0` before.
        let err = Earth::default()
            .foucault_swing(0.8, 1e300, 1.0, 0.0, 60.0, 11, &FOUCAULT_TOLERANCES)
            .unwrap_err();
        assert_eq!(err.argument, "amplitude", "{err}");
    }

    #[test]
    fn the_runs_name_only_their_arguments() {
        let e = Earth::default();
        let f = |lat, len, amp, az, dur, n| {
            e.foucault_swing(lat, len, amp, az, dur, n, &FOUCAULT_TOLERANCES)
        };
        let foucault = [
            "latitude",
            "length",
            "amplitude",
            "azimuth",
            "duration",
            "samples",
            "max_steps",
        ];
        for args in [
            (0.8, 1e300, 1.0, 0.0, 60.0, 11),
            (0.8, 1e-300, 1e-301, 0.0, 60.0, 11),
            (0.8, 10.0, 1.0, 0.0, 1e300, 11),
            (0.8, 10.0, 1.0, 1e300, 60.0, 11),
        ] {
            let (lat, len, amp, az, dur, n) = args;
            if let Err(err) = f(lat, len, amp, az, dur, n) {
                names(err, &foucault);
            }
        }
        let inertial = ["latitude", "velocity", "duration", "samples", "max_steps"];
        for (v, d) in [
            ([1e308, 1e308], 1e5),
            ([1.0, 0.0], 1e300),
            ([1e-320, 0.0], 1e5),
        ] {
            if let Err(err) = e.inertial_swing(0.8, v, Some(d), 11, &INERTIAL_TOLERANCES) {
                names(err, &inertial);
            }
        }
        let low = [
            "latitude",
            "radius",
            "parcels",
            "pull",
            "friction",
            "duration",
            "samples",
            "max_steps",
        ];
        for (r, pull, d) in [
            (1e300, 1e300, 1e5),
            (5e5, 1e-3, 1e300),
            (1e-300, 1e-300, 1e5),
        ] {
            let setup = LowSetup {
                radius: r,
                pull,
                ..LowSetup::default()
            };
            if let Err(err) = e.low_flow(0.8, &setup, d, 11, &LOW_TOLERANCES) {
                names(err, &low);
            }
        }
    }
}
