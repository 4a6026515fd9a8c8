//! A body carried by a moving frame (Foucault's gyroscope, a top on a turntable) and the
//! gyrocompass, against closed forms written here.

use std::f64::consts::{FRAC_PI_2, PI};

use poinsot::dynamics::{
    simulate, simulate_carried, BodyInertia, Carrier, Carrying, Gyrocompass, Load, Method, Ship,
    SimulateOptions, Torque,
};
use poinsot::earth::Earth;
use poinsot::frames::MovingFrame;
use poinsot::rotation::quaternion_to_matrix;
use poinsot::{Mat3, Vec3};
use proptest::prelude::*;

const DAY: f64 = 86164.0905;

/// Body → frame rotation taking body axis 3 to the unit vector `s` (ENU).
fn aim(s: Vec3) -> [f64; 4] {
    let z = Vec3::z();
    let axis = z.cross(&s);
    let n = axis.norm();
    if n < 1e-15 {
        return [1.0, 0.0, 0.0, 0.0];
    }
    let angle = n.atan2(z.dot(&s));
    let (sh, ch) = (0.5 * angle).sin_cos();
    let a = axis / n * sh;
    [ch, a.x, a.y, a.z]
}

fn axis3(q: &[f64; 4]) -> Vec3 {
    quaternion_to_matrix(q, true).unwrap() * Vec3::z()
}

/// A free gyroscope (pivot at its centre of mass) spinning about body axis 3, aimed along `s`,
/// its inertial ω exactly along the axis; runs for `duration` s at `lat` (rad).
fn foucault(
    lat: f64,
    s: Vec3,
    duration: f64,
    samples: usize,
) -> poinsot::dynamics::CarriedTrajectory {
    let place = Carrier::earth(Earth::default(), lat).unwrap();
    let body = BodyInertia::from_moments([1.0, 1.0, 1.5]).unwrap();
    let q0 = aim(s);
    let r0 = quaternion_to_matrix(&q0, true).unwrap();
    // Relative ω such that the inertial ω is 50 rad/s along the axis.
    let w_rel = Vec3::new(0.0, 0.0, 50.0) - r0.transpose() * place.angular_velocity(0.0);
    let opts = SimulateOptions {
        samples,
        ..Default::default()
    };
    simulate_carried(
        &body,
        w_rel,
        Some(q0),
        duration,
        &place,
        Load::default(),
        &mut Torque::None,
        &opts,
    )
    .unwrap()
}

#[test]
fn free_gyroscope_keeps_its_inertial_axis_over_a_day() {
    let lat = 49f64.to_radians();
    let s0 = Vec3::new(0.0, 1.0, 0.0);
    let run = foucault(lat, s0, DAY, 25);
    for q in &run.inertial.attitude {
        assert!((axis3(q) - s0).norm() < 1e-12, "{:?}", axis3(q) - s0);
    }
    // Seen from the ground, the axis is the inertial one turned back by the Earth: written
    // out here by Rodrigues' formula about k = (0, cos λ, sin λ).
    let k = Vec3::new(0.0, lat.cos(), lat.sin());
    let omega = Earth::default().rotation_rate;
    for (t, q) in run.inertial.t.iter().zip(&run.relative_attitude) {
        let a = -omega * t;
        let want = s0 * a.cos() + k.cross(&s0) * a.sin() + k * k.dot(&s0) * (1.0 - a.cos());
        assert!((axis3(q) - want).norm() < 1e-10);
    }
}

#[test]
fn horizontal_axis_drifts_clockwise_at_omega_sin_latitude() {
    for lat_deg in [49.0, -30.0] {
        let lat = f64::to_radians(lat_deg);
        let run = foucault(lat, Vec3::new(0.0, 1.0, 0.0), 60.0, 2);
        let s = axis3(run.relative_attitude.last().unwrap());
        let azimuth = s.x.atan2(s.y); // clockwise from north
        let rate = azimuth / 60.0;
        let want = Earth::default().rotation_rate * lat.sin();
        // The mean rate over 60 s differs from the initial one at second order in Ω t (4e-3).
        assert!((rate / want - 1.0).abs() < 1e-5, "{rate} {want}");
    }
}

#[test]
fn axis_at_the_celestial_pole_stays_put() {
    let lat = 40f64.to_radians();
    let pole = Vec3::new(0.0, lat.cos(), lat.sin());
    let run = foucault(lat, pole, DAY / 3.0, 7);
    for q in &run.relative_attitude {
        assert!((axis3(q) - pole).norm() < 1e-12);
    }
}

#[test]
fn top_on_a_turntable_matches_the_fixed_pivot_top_when_the_pivot_is_on_the_axis() {
    // The pivot on the turntable's axis feels no acceleration: the carried top is the heavy top
    // of `Torque::Gravity` seen from the turning frame.
    let w = Vec3::new(0.0, 0.0, 0.7);
    let frame = MovingFrame {
        angular_velocity: w,
        ..MovingFrame::default()
    };
    let table = Carrier::frame(frame, Vec3::zeros(), Vec3::new(0.0, 0.0, -9.81)).unwrap();
    let body = BodyInertia::from_moments([1.0, 1.0, 0.5]).unwrap();
    let mgl = 2.0;
    let tilt = [0.15f64.cos(), 0.15f64.sin(), 0.0, 0.0];
    let opts = SimulateOptions {
        method: Method::Dop853,
        samples: 5,
        ..Default::default()
    };
    let w_rel = Vec3::new(0.0, 0.0, 20.0);
    let load = Load {
        mass_moment: Vec3::new(0.0, 0.0, mgl / 9.81),
        rotor: Vec3::zeros(),
    };
    let carried = simulate_carried(
        &body,
        w_rel,
        Some(tilt),
        3.0,
        &table,
        load,
        &mut Torque::None,
        &opts,
    )
    .unwrap();
    let r0 = quaternion_to_matrix(&tilt, true).unwrap();
    let plain = simulate(
        &body,
        w_rel + r0.transpose() * w,
        Some(tilt),
        3.0,
        &mut Torque::Gravity { mgl },
        &opts,
    )
    .unwrap();
    for (a, b) in carried.inertial.attitude.iter().zip(&plain.attitude) {
        let d: f64 = a.iter().zip(b).map(|(x, y)| (x - y).abs()).sum();
        assert!(d < 1e-8, "{d}");
    }
    // And the relative attitude is the inertial one turned back by the table.
    for (k, t) in carried.inertial.t.iter().enumerate() {
        let back = poinsot::rotation::rot_z(-0.7 * t);
        let want = back * quaternion_to_matrix(&plain.attitude[k], true).unwrap();
        let got = quaternion_to_matrix(&carried.relative_attitude[k], true).unwrap();
        assert!((got - want).norm() < 1e-8);
    }
}

#[test]
fn off_axis_pivot_feels_the_centripetal_force() {
    // A body at rest on a turntable, its centre of mass above an off-axis pivot: the
    // specific force at the pivot is g + ω² r outward (2.5–2.7).
    let w = 2.0;
    let frame = MovingFrame {
        angular_velocity: Vec3::new(0.0, 0.0, w),
        ..MovingFrame::default()
    };
    let table =
        Carrier::frame(frame, Vec3::new(0.5, 0.0, 0.0), Vec3::new(0.0, 0.0, -9.81)).unwrap();
    let f = table.specific_force(0.0);
    assert!((f - Vec3::new(w * w * 0.5, 0.0, -9.81)).norm() < 1e-14);
    let t = 0.3;
    let f = table.specific_force(t);
    let want =
        Vec3::new((w * t).cos(), (w * t).sin(), 0.0) * w * w * 0.5 + Vec3::new(0.0, 0.0, -9.81);
    assert!((f - want).norm() < 1e-13);
}

fn compass(lat_deg: f64, damping: f64, earth: Earth) -> Gyrocompass {
    // Light case (nutation H/I ≈ 40 rad/s) so that the runs stay fast; H, P are realistic.
    Gyrocompass::schuler_tuned(lat_deg.to_radians(), 1.2, damping, [0.5, 1.0, 1.0], earth).unwrap()
}

fn opts(samples: usize) -> SimulateOptions {
    SimulateOptions {
        samples,
        rtol: 1e-9,
        atol: 1e-12,
        ..Default::default()
    }
}

#[test]
fn simulated_period_matches_the_linear_period() {
    let c = compass(50.0, 0.0, Earth::default());
    let p = c.period().unwrap();
    let (_, tilt) = c.settle().unwrap();
    let run = c
        .simulate(2.2 * p, 0.5f64.to_radians(), tilt, None, &opts(2201))
        .unwrap();
    // Upward zero crossings of the heading.
    let mut ups = vec![];
    for k in 1..run.t.len() {
        let (a, b) = (run.heading[k - 1], run.heading[k]);
        if a < 0.0 && b >= 0.0 {
            ups.push(run.t[k - 1] + (run.t[k] - run.t[k - 1]) * (-a) / (b - a));
        }
    }
    assert!(ups.len() >= 2, "{ups:?}");
    let measured = ups[1] - ups[0];
    assert!((measured / p - 1.0).abs() < 0.01, "{measured} vs {p}");
    assert!((p / 60.0 - 84.4).abs() < 0.05);
}

#[test]
fn damped_compass_settles_at_the_latitude_error() {
    let c = compass(40.0, 0.5, Earth::default());
    let (err, tilt) = c.settle().unwrap();
    let p = c.period().unwrap();
    let run = c
        .simulate(4.0 * p, -err + 0.3f64.to_radians(), tilt, None, &opts(101))
        .unwrap();
    let settled = *run.heading.last().unwrap();
    assert!(
        (settled + err).abs() < 0.01f64.to_radians(),
        "{} vs {}",
        settled.to_degrees(),
        -err.to_degrees()
    );
    assert!(err < 0.0, "reads low in the north");
}

#[test]
fn speed_error_matches_the_undamped_simulation_mean() {
    // The band where the full simulation meets the formula to 0.01°: up to about 45° at
    // 10 m/s. The element hangs along the apparent vertical, tilted by the Coriolis
    // acceleration's horizontal part 2 Ω sin λ V / g, about which the vertical rotation Ω sin λ
    // has a horizontal part the formula leaves out: Δδ ≈ 2 Ω V_N sin λ tan λ / g, 0.0023° at
    // 30°, 0.0057° at 45°, 0.012° at 60°, 0.044° at 80° (10 m/s on 020°). Measured (mean over
    // a period): +0.0059° at 30°, +0.0087° at 45°, +0.0143° at 60°, +0.046° at 80°, the
    // estimate on a residual of 0.002–0.004° (docs/gyrocompass.md, "The steaming error in the
    // full simulation").
    let c = compass(30.0, 0.0, Earth::default());
    let (v, course) = (10.0, 20f64.to_radians());
    let delta = c.speed_error(v, course).unwrap();
    let (_, tilt) = c.settle().unwrap();
    let p = c.period().unwrap();
    let n = 2001;
    let run = c
        .simulate(
            p,
            -delta + 0.05f64.to_radians(),
            tilt,
            Some(Ship::new(v, course).unwrap()),
            &opts(n),
        )
        .unwrap();
    // Mean over one period (trapezoid) of the heading = the settled heading.
    let h = &run.heading;
    let mean = (h.iter().sum::<f64>() - 0.5 * (h[0] + h[n - 1])) / (n - 1) as f64;
    let mid = Gyrocompass {
        latitude: run.latitude[n / 2],
        ..c
    };
    let want = -mid.speed_error(v, course).unwrap();
    assert!(
        (mean - want).abs() < 0.01f64.to_radians(),
        "{} vs {}",
        mean.to_degrees(),
        want.to_degrees()
    );
}

#[test]
fn negative_control_no_earth_rotation_no_north_seeking() {
    let still = Earth::new(0.0, 6.371e6, 9.80665).unwrap();
    let c = Gyrocompass::new(50f64.to_radians(), 2.0, 1.2, 0.0, [0.5, 1.0, 1.0], still).unwrap();
    let run = c.simulate(3000.0, 0.3, 0.0, None, &opts(11)).unwrap();
    for h in &run.heading {
        assert!((h - 0.3).abs() < 1e-9, "{h}");
    }
    assert_eq!(c.period().unwrap_err().argument, "rotation_rate");
    // With the Earth turning, the same start swings by a visible amount within 3000 s.
    let turning = compass(50.0, 0.0, Earth::default());
    let run = turning.simulate(3000.0, 0.3, 0.0, None, &opts(11)).unwrap();
    assert!((run.heading.last().unwrap() - 0.3).abs() > 0.1);
}

#[test]
fn refusals_name_the_argument() {
    let e = Earth::default();
    assert_eq!(
        Gyrocompass::new(FRAC_PI_2, 1.0, 1.0, 0.0, [1.0; 3], e)
            .unwrap_err()
            .argument,
        "latitude"
    );
    assert_eq!(
        Gyrocompass::new(-FRAC_PI_2, 1.0, 1.0, 0.0, [1.0; 3], e)
            .unwrap_err()
            .argument,
        "latitude"
    );
    assert_eq!(
        Gyrocompass::new(0.5, 0.0, 1.0, 0.0, [1.0; 3], e)
            .unwrap_err()
            .argument,
        "angular_momentum"
    );
    assert_eq!(
        Gyrocompass::new(0.5, 1.0, 0.0, 0.0, [1.0; 3], e)
            .unwrap_err()
            .argument,
        "pendulosity"
    );
    assert_eq!(
        Gyrocompass::new(0.5, 1.0, 1.0, 1.0, [1.0; 3], e)
            .unwrap_err()
            .argument,
        "damping"
    );
    let c = compass(60.0, 0.0, e);
    let ground = c.ground_speed();
    assert_eq!(
        c.speed_error(ground, -FRAC_PI_2).unwrap_err().argument,
        "speed"
    );
    assert!(c.speed_error(ground * 0.99, -FRAC_PI_2).is_ok());
    assert_eq!(
        c.simulate(1.0, f64::NAN, 0.0, None, &opts(2))
            .unwrap_err()
            .argument,
        "heading0"
    );
    assert_eq!(
        c.simulate(-1.0, 0.0, 0.0, None, &opts(2))
            .unwrap_err()
            .argument,
        "duration"
    );
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, ..ProptestConfig::default() })]

    /// The speed error is the angle of the local frame's horizontal rotation: tan δ = −w_E/w_N
    /// with w = Ω (0, cos λ, ·) + (−V_N/R, V_E/R, ·), and it tends to the small-angle form.
    #[test]
    fn speed_error_is_the_angle_of_the_horizontal_rotation(
        lat in -80.0f64..80.0, v in 0.0f64..30.0, course in -PI..PI,
    ) {
        let c = compass(lat, 0.0, Earth::default());
        let e = c.earth;
        let (vn, ve) = (v * course.cos(), v * course.sin());
        let w = Vec3::new(-vn / e.radius, e.rotation_rate * lat.to_radians().cos() + ve / e.radius, 0.0);
        let delta = c.speed_error(v, course).unwrap();
        prop_assert!((delta - (-w.x).atan2(w.y)).abs() < 1e-12);
        let small = c.speed_error_small_angle(v, course).unwrap();
        // |atan x − y| with x = y G/(G + V sin C): the two part at first order in V/G.
        let g = c.ground_speed();
        prop_assert!((delta - small).abs() <= small.abs() * (2.0 * v / (g - v)) + small.abs().powi(3) + 1e-15);
    }

    /// A carried place's frame turns consistently: Ȧ ≈ [ω]× A by central differences.
    #[test]
    fn earth_frame_turns_at_its_angular_velocity(lat in -1.5f64..1.5, t in 0.0f64..1e5) {
        let place = Carrier::earth(Earth::default(), lat).unwrap();
        let h = 1.0;
        let d: Mat3 = (place.attitude(t + h) - place.attitude(t - h)) / (2.0 * h);
        let want = place.angular_velocity(t).cross_matrix() * place.attitude(t);
        prop_assert!((d - want).norm() < 1e-12);
    }
}

#[test]
fn free_gyroscope_axis_drifts_at_the_fixed_axis_heading_rate() {
    // A horizontal axis at 49° N aimed east (cos α = 0: the tilt it takes changes the rate
    // only at second order, ~0.3 % in half an hour): its heading (clockwise from north) grows
    // at Ω sin λ (fixed_axis_heading_rate) as seen from the ground.
    let (lat, heading0, hour) = (49f64.to_radians(), FRAC_PI_2, 1800.0);
    let q = poinsot::dynamics::free_gyroscope(Earth::default(), lat, heading0, 0.0, 100.0, hour, 3)
        .unwrap();
    assert_eq!(q.len(), 3);
    let axis = |q: &[f64; 4]| quaternion_to_matrix(q, true).unwrap() * Vec3::x();
    let heading = |q: &[f64; 4]| axis(q).x.atan2(axis(q).y);
    assert!((heading(&q[0]) - heading0).abs() < 1e-12);
    let rate =
        poinsot::dynamics::fixed_axis_heading_rate(&Earth::default(), lat, heading0, 0.0).unwrap();
    let drift = heading(&q[2]) - heading0;
    assert!(
        ((drift - rate * hour) / (rate * hour)).abs() < 1e-2,
        "{drift} vs {}",
        rate * hour
    );
    // Refusals name the argument.
    let e = |r: poinsot::Result<Vec<[f64; 4]>>| r.unwrap_err().argument;
    let run = |lat: f64, h: f64, spin: f64| {
        poinsot::dynamics::free_gyroscope(Earth::default(), lat, h, 0.0, spin, hour, 3)
    };
    assert_eq!(e(run(2.0, 0.0, 100.0)), "latitude");
    assert_eq!(e(run(lat, f64::NAN, 100.0)), "heading0");
    assert_eq!(e(run(lat, 0.0, f64::INFINITY)), "spin");
}
