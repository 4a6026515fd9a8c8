//! Issue 26: course and speed changes in `Gyrocompass::simulate_track` — the settled heading
//! moves to the new speed error, and a Schuler-tuned compass goes there without a swing (no
//! ballistic error), against a compass that is not tuned (the negative control), and the
//! linearised solution (`Gyrocompass::linear_solution`) against the full simulation.

use poinsot::dynamics::{Gyrocompass, Ship, SimulateOptions, Track, Turn};
use poinsot::earth::Earth;

/// The compasses' pendulosity m g l (N·m) and rotor-and-case moments (kg·m²).
const PENDULOSITY: f64 = 1.2;
const INERTIA: [f64; 3] = [0.5, 1.0, 1.0];

/// The Schuler-tuned compass at `latitude_deg` (degrees) with damping ratio `damping`.
fn tuned(latitude_deg: f64, damping: f64) -> Gyrocompass {
    Gyrocompass::schuler_tuned(
        latitude_deg.to_radians(),
        PENDULOSITY,
        damping,
        INERTIA,
        Earth::default(),
    )
    .unwrap()
}

fn opts(samples: usize) -> SimulateOptions {
    SimulateOptions {
        samples,
        rtol: 1e-9,
        atol: 1e-12,
        ..Default::default()
    }
}

const TURN_AT: f64 = 600.0;
const TURN_TAKES: f64 = 120.0;
const SPEED: f64 = 10.0;

/// The reversal north → south at 10 m/s in two minutes, from `t = 600 s`.
fn reversal() -> Track {
    Track::new(
        Ship::new(SPEED, 0.0).unwrap(),
        vec![Turn {
            time: TURN_AT,
            duration: Some(TURN_TAKES),
            speed: SPEED,
            course: std::f64::consts::PI,
        }],
    )
    .unwrap()
}

/// The largest |heading − settled heading| (rad) after the turn, over `span` s, where the
/// settled heading is −δ of the new course at the ship's latitude then; and |Δδ|.
fn swing_after_reversal(c: &Gyrocompass, span: f64) -> (f64, f64) {
    let d0 = c.speed_error(SPEED, 0.0).unwrap();
    let (_, tilt) = c.settle().unwrap();
    let end = TURN_AT + TURN_TAKES;
    let n = ((end + span) / 10.0) as usize + 1;
    let run = c
        .simulate_track(end + span, -d0, tilt, &reversal(), &opts(n))
        .unwrap();
    let mut worst: f64 = 0.0;
    for k in 0..run.t.len() {
        if run.t[k] < end {
            // Before the turn, the compass sits on the old speed error.
            if run.t[k] < TURN_AT {
                assert!((run.heading[k] + d0).abs() < 0.01f64.to_radians());
            }
            continue;
        }
        let here = Gyrocompass {
            latitude: run.latitude[k],
            ..*c
        };
        let settled = -here.speed_error(SPEED, std::f64::consts::PI).unwrap();
        worst = worst.max((run.heading[k] - settled).abs());
    }
    let d1 = c.speed_error(SPEED, std::f64::consts::PI).unwrap();
    (worst, (d1 - d0).abs())
}

#[test]
fn schuler_tuned_compass_has_no_ballistic_error() {
    let c = tuned(30.0, 0.0);
    let p = c.period().unwrap();
    let (swing, jump) = swing_after_reversal(&c, p);
    eprintln!(
        "tuned: swing {} deg of a jump {} deg",
        swing.to_degrees(),
        jump.to_degrees()
    );
    assert!(jump > 2.5f64.to_radians(), "{}", jump.to_degrees());
    assert!(
        swing < 0.01 * jump,
        "{} of {}",
        swing.to_degrees(),
        jump.to_degrees()
    );
}

#[test]
fn a_compass_not_schuler_tuned_swings_after_a_turn() {
    // Twice Schuler's rotor: the ballistic deflection P Δv/(g H) is half the change of the
    // speed error, so the compass swings about its new heading by about half the jump.
    let schuler = tuned(30.0, 0.0);
    let c = Gyrocompass::new(
        schuler.latitude,
        2.0 * schuler.angular_momentum,
        PENDULOSITY,
        0.0,
        INERTIA,
        Earth::default(),
    )
    .unwrap();
    let p = c.period().unwrap();
    let (swing, jump) = swing_after_reversal(&c, 0.6 * p);
    eprintln!(
        "detuned: swing {} deg of a jump {} deg",
        swing.to_degrees(),
        jump.to_degrees()
    );
    assert!(
        (swing / jump - 0.5).abs() < 0.05,
        "{} of {}",
        swing.to_degrees(),
        jump.to_degrees()
    );
}

#[test]
fn tracks_refused_by_name() {
    let ship = Ship::new(5.0, 0.0).unwrap();
    let turn = |time: f64, duration: Option<f64>, speed: f64, course: f64| Turn {
        time,
        duration,
        speed,
        course,
    };
    for bad in [
        vec![turn(-1.0, None, 5.0, 0.0)],
        vec![turn(f64::NAN, None, 5.0, 0.0)],
        vec![turn(10.0, Some(0.0), 5.0, 0.0)],
        vec![turn(10.0, Some(f64::INFINITY), 5.0, 0.0)],
        vec![turn(10.0, None, -5.0, 0.0)],
        vec![turn(10.0, None, 5.0, f64::NAN)],
        vec![
            turn(100.0, Some(60.0), 5.0, 1.0),
            turn(120.0, None, 5.0, 0.0),
        ],
    ] {
        let err = Track::new(ship, bad.clone()).unwrap_err();
        assert_eq!(err.argument, "turns", "{bad:?}: {}", err.message);
    }
    let err = Track::new(
        ship,
        vec![
            turn(100.0, Some(60.0), 5.0, 1.0),
            turn(120.0, None, 5.0, 0.0),
        ],
    )
    .unwrap_err();
    assert!(err.message.contains("turn 1"), "{}", err.message);
    // Back to back is allowed; the default duration is the core's.
    let track = Track::new(
        ship,
        vec![
            turn(100.0, Some(60.0), 5.0, 1.0),
            turn(160.0, None, 5.0, 0.0),
        ],
    )
    .unwrap();
    let (v, a) = track.velocity(160.0 + 0.5 * poinsot::dynamics::COMPASS_TURN_DURATION);
    let want = [0.5 * 5.0 * 1f64.sin(), 0.5 * 5.0 * (1f64.cos() + 1.0)];
    assert!(
        (v[0] - want[0]).abs() < 1e-12 && (v[1] - want[1]).abs() < 1e-12,
        "{v:?}"
    );
    assert!(a[0] < 0.0);
    assert_eq!(
        Track::new(
            Ship {
                speed: -1.0,
                course: 0.0
            },
            vec![]
        )
        .unwrap_err()
        .argument,
        "speed"
    );
}

#[test]
fn linear_solution_follows_the_full_simulation() {
    // A damped compass started 0.5 degrees off its settled heading, at its settled tilt: the
    // closed-form linear solution and the full gyrostat agree to 2 % of the offset over a
    // period, and the heading stays inside the linear envelope.
    let c = tuned(40.0, 0.3);
    let p = c.period().unwrap();
    let (err, tilt) = c.settle().unwrap();
    let off = 0.5f64.to_radians();
    let run = c.simulate(p, -err + off, tilt, None, &opts(201)).unwrap();
    let lin = c.linear_solution(&run.t, -err + off, tilt, None).unwrap();
    assert!((lin.settled_heading + err).abs() < 1e-15);
    for k in 0..run.t.len() {
        let d = (run.heading[k] - lin.heading[k]).abs();
        assert!(d < 0.02 * off, "t = {}: {} deg", run.t[k], d.to_degrees());
        assert!((run.heading[k] - lin.settled_heading).abs() <= lin.envelope[k] + 0.02 * off);
    }
    assert!((lin.envelope[0] - off / (1.0 - 0.09f64).sqrt()).abs() < 1e-12);
    let still = Earth::new(0.0, 6.371e6, 9.80665).unwrap();
    let c = Gyrocompass::new(0.5, 2.0, PENDULOSITY, 0.0, INERTIA, still).unwrap();
    assert_eq!(
        c.linear_solution(&[0.0], 0.0, 0.0, None)
            .unwrap_err()
            .argument,
        "rotation_rate"
    );
}

#[test]
fn a_fixed_axis_heading_turns_at_the_closed_form_rate() {
    // Foucault's free gyroscope (pivot at the centre of mass) at 49 degrees, its axis along body
    // axis 1 aimed 40 degrees east of north and 20 degrees up: the heading's rate seen from the
    // ground, by central differences of the carried run, against Ω (sin λ − cos λ tan θ cos α).
    use poinsot::dynamics::{
        fixed_axis_heading_rate, simulate_carried, BodyInertia, Carrier, Load, Method, Torque,
    };
    use poinsot::rotation::quaternion_to_matrix;
    use poinsot::Vec3;
    let earth = Earth::default();
    let lat = 49f64.to_radians();
    let place = Carrier::earth(earth, lat).unwrap();
    let (a0, t0) = (40f64.to_radians(), 20f64.to_radians());
    // Body → ENU: axis 1 to (sin α cos θ, cos α cos θ, sin θ); turn by −θ about y, then by
    // π/2 − α about up.
    let half = |x: f64| (0.5 * x).sin_cos();
    let (sz, cz) = half(std::f64::consts::FRAC_PI_2 - a0);
    let (sy, cy) = half(-t0);
    let q0 = [cz * cy, -sz * sy, cz * sy, sz * cy];
    let body = BodyInertia::from_moments([1.5, 1.0, 1.0]).unwrap();
    let opts = SimulateOptions {
        method: Method::Exact,
        samples: 7,
        ..Default::default()
    };
    // Inertial ω along the axis: relative ω = 50 e₁ less the ground's.
    let r0 = quaternion_to_matrix(&q0, true).unwrap();
    let w = Vec3::new(50.0, 0.0, 0.0)
        - r0.transpose() * earth.rotation_rate * Vec3::new(0.0, lat.cos(), lat.sin());
    let run = simulate_carried(
        &body,
        w,
        Some(q0),
        6.0 * 3600.0,
        &place,
        Load::default(),
        &mut Torque::None,
        &opts,
    )
    .unwrap();
    let heading = |q: &[f64; 4]| {
        let s = quaternion_to_matrix(q, true).unwrap() * Vec3::x();
        (s.x.atan2(s.y), s.z.atan2(s.x.hypot(s.y)))
    };
    let h = 1.0;
    for k in 1..run.inertial.t.len() - 1 {
        // Sample k's axis, turned ±1 s by the ground (Rodrigues): the central difference is
        // good to h² α‴/6, about 1e-9 Ω here (α‴ ~ Ω³, tan θ amplifying it).
        let (a, th) = heading(&run.relative_attitude[k]);
        let s = Vec3::new(a.sin() * th.cos(), a.cos() * th.cos(), th.sin());
        let k_axis = Vec3::new(0.0, lat.cos(), lat.sin());
        let back = |dt: f64| {
            let ang = -earth.rotation_rate * dt;
            s * ang.cos()
                + k_axis.cross(&s) * ang.sin()
                + k_axis * k_axis.dot(&s) * (1.0 - ang.cos())
        };
        let (p, m) = (back(h), back(-h));
        let fd = (p.x.atan2(p.y) - m.x.atan2(m.y)) / (2.0 * h);
        let rate = fixed_axis_heading_rate(&earth, lat, a, th).unwrap();
        assert!(
            (fd - rate).abs() < 1e-7 * earth.rotation_rate,
            "{fd} vs {rate}"
        );
    }
    // At the start the axis is where it was put; aimed at the celestial pole it stays put.
    let (a, th) = heading(&run.relative_attitude[0]);
    assert!((a - a0).abs() < 1e-12 && (th - t0).abs() < 1e-12);
    assert!(
        fixed_axis_heading_rate(&earth, lat, 0.0, lat)
            .unwrap()
            .abs()
            < 1e-20
    );
    let flat = fixed_axis_heading_rate(&earth, lat, 1.0, 0.0).unwrap();
    assert!((flat - earth.rotation_rate * lat.sin()).abs() < 1e-20);
    let vertical = fixed_axis_heading_rate(&earth, lat, 0.0, std::f64::consts::FRAC_PI_2);
    assert_eq!(vertical.unwrap_err().argument, "tilt");
}
