//! Tests of moving-frame kinematics and of particles integrated in moving frames
//! (`poinsot::frames`, the unit's eqs. 2.1–2.28).

use poinsot::frames::{
    simulate_particle, simulate_particle_fixed, FrameMotion, MovingFrame, ParticleState,
    SteadyMotion,
};
use poinsot::integrate::{Crossing, Options};
use poinsot::{ErrorKind, Mat3, Vec3};
use proptest::prelude::*;

/// Round-off allowance for one transformation of O(1) quantities.
const ROUND_OFF: f64 = 1e-12;
/// The bar: moving-frame integration versus fixed-frame integration + transformation.
const FRAME_AGREEMENT: f64 = 1e-10;

fn rot(axis: Vec3, angle: f64) -> Mat3 {
    *nalgebra::Rotation3::from_axis_angle(&nalgebra::Unit::new_normalize(axis), angle).matrix()
}

fn vec3() -> impl Strategy<Value = Vec3> {
    (-2.0..2.0f64, -2.0..2.0f64, -2.0..2.0f64).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

fn frame() -> impl Strategy<Value = MovingFrame> {
    (vec3(), vec3(), vec3(), vec3(), vec3(), vec3(), 0.0..3.0f64).prop_map(
        |(o, v, a, w, wd, ax, ang)| {
            MovingFrame::new(o, v, a, w, wd)
                .unwrap()
                .with_attitude(rot(ax + Vec3::new(0.0, 0.0, 1e-3), ang))
                .unwrap()
        },
    )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    /// to_moving inverts to_fixed, and the named terms sum to the total in both directions.
    #[test]
    fn to_fixed_and_to_moving_are_inverse(f in frame(), r in vec3(), v in vec3(), a in vec3()) {
        let fixed = f.to_fixed(&r, &v, &a).unwrap();
        prop_assert!((fixed.terms.total() - fixed.acceleration).norm() < ROUND_OFF);
        let back = f.to_moving(&fixed.position, &fixed.velocity, &fixed.acceleration).unwrap();
        prop_assert!((back.position - r).norm() < 1e-11);
        prop_assert!((back.velocity - v).norm() < 1e-11);
        prop_assert!((back.acceleration - a).norm() < 1e-10);
        prop_assert!((back.terms.total() - back.acceleration).norm() < ROUND_OFF);
    }

    /// The fictitious forces are −m times the frame terms of eq. 2.21 (moving components).
    #[test]
    fn fictitious_forces_match_the_frame_terms(f in frame(), r in vec3(), v in vec3(), m in 0.1..10.0f64) {
        let ff = f.fictitious_forces(m, &r, &v).unwrap();
        let t = f.to_fixed(&r, &v, &Vec3::zeros()).unwrap().terms;
        let at = f.attitude.transpose();
        prop_assert!((ff.translational + m * (at * t.origin)).norm() < 1e-10);
        prop_assert!((ff.coriolis + m * (at * t.coriolis)).norm() < 1e-10);
        prop_assert!((ff.centrifugal + m * (at * t.centripetal)).norm() < 1e-10);
        prop_assert!((ff.euler + m * (at * t.euler)).norm() < 1e-10);
    }
}

/// Eq. 2.2–2.3 (with the errata's dots): for ω = 0 velocities and accelerations add.
#[test]
fn pure_translation_is_galilean() {
    let f = MovingFrame::new(
        Vec3::new(1.0, 2.0, 3.0),
        Vec3::new(0.5, 0.0, -1.0),
        Vec3::new(0.0, 0.1, 0.0),
        Vec3::zeros(),
        Vec3::zeros(),
    )
    .unwrap();
    let (r, v, a) = (
        Vec3::new(1.0, 0.0, 0.0),
        Vec3::new(0.0, 2.0, 0.0),
        Vec3::new(0.0, 0.0, 3.0),
    );
    let out = f.to_fixed(&r, &v, &a).unwrap();
    assert_eq!(out.position, f.origin + r);
    assert_eq!(out.velocity, f.velocity + v);
    assert_eq!(out.acceleration, f.acceleration + a);
    assert_eq!(out.terms.coriolis, Vec3::zeros());
    // A uniformly moving frame (R̈ = 0) has no fictitious force: Galilean invariance.
    let g = MovingFrame::new(
        Vec3::zeros(),
        Vec3::new(3.0, 0.0, 0.0),
        Vec3::zeros(),
        Vec3::zeros(),
        Vec3::zeros(),
    )
    .unwrap();
    assert_eq!(
        g.fictitious_forces(2.0, &r, &v).unwrap().total(),
        Vec3::zeros()
    );
}

/// A point at rest on a turntable moves on a circle: v' = ω × r, a' = −ω² r (centripetal, 2.24).
#[test]
fn point_at_rest_on_a_turntable() {
    let w = 2.0;
    let f = MovingFrame::rotating(Vec3::new(0.0, 0.0, w)).unwrap();
    let r = Vec3::new(3.0, 0.0, 1.0);
    let out = f.to_fixed(&r, &Vec3::zeros(), &Vec3::zeros()).unwrap();
    assert!((out.velocity - Vec3::new(0.0, w * 3.0, 0.0)).norm() < ROUND_OFF);
    assert!((out.acceleration - Vec3::new(-w * w * 3.0, 0.0, 0.0)).norm() < ROUND_OFF);
    // Its magnitude is ω² r sin θ = v²/(r sin θ) (eq. 2.24).
    let rho = 3.0;
    assert!((out.terms.centripetal.norm() - (w * rho).powi(2) / rho).abs() < ROUND_OFF);
}

#[test]
fn bad_frames_are_refused() {
    let e = MovingFrame::new(
        Vec3::new(f64::NAN, 0.0, 0.0),
        Vec3::zeros(),
        Vec3::zeros(),
        Vec3::zeros(),
        Vec3::zeros(),
    )
    .unwrap_err();
    assert_eq!(e.argument, "origin");
    let e = MovingFrame::default()
        .with_attitude(Mat3::from_diagonal(&Vec3::new(1.0, 1.0, -1.0)))
        .unwrap_err();
    assert_eq!(
        (e.kind, e.argument.as_str()),
        (ErrorKind::InvalidRotation, "attitude")
    );
    let e = MovingFrame::default()
        .fictitious_forces(0.0, &Vec3::zeros(), &Vec3::zeros())
        .unwrap_err();
    assert_eq!(e.argument, "mass");
    let tilted = MovingFrame::new(
        Vec3::zeros(),
        Vec3::zeros(),
        Vec3::zeros(),
        Vec3::z(),
        Vec3::x(),
    )
    .unwrap();
    assert_eq!(
        SteadyMotion::new(tilted).unwrap_err().argument,
        "angular_acceleration"
    );
}

/// Checks a moving-frame integration against a fixed-frame one: the force is a spring towards
/// a fixed point plus a uniform field, both given in the fixed frame.
fn check_against_fixed_frame<M: FrameMotion>(motion: &M, t_end: f64) -> f64 {
    let (m, k) = (1.7, 3.0);
    let anchor = Vec3::new(0.3, -0.2, 0.5);
    let field = Vec3::new(0.0, 0.5, -9.8);
    let fixed_force = move |r: &Vec3| -k * (r - anchor) + m * field;
    let opts = Options::with_tolerances(1e-13, 1e-13);
    let (r0, v0) = (Vec3::new(1.0, 0.5, -0.3), Vec3::new(-0.2, 0.4, 1.0));
    let moving = simulate_particle(
        motion,
        m,
        r0,
        v0,
        0.0,
        t_end,
        |t, r, _v| {
            let f = motion.at(t);
            f.attitude.transpose() * fixed_force(&(f.origin + f.attitude * r))
        },
        &opts,
        None::<(fn(f64, &ParticleState) -> f64, Crossing)>,
    )
    .unwrap();
    let f0 = motion.at(0.0);
    let start = f0.to_fixed(&r0, &v0, &Vec3::zeros()).unwrap();
    let fixed = simulate_particle_fixed(
        m,
        start.position,
        start.velocity,
        0.0,
        t_end,
        |_t, r, _v| fixed_force(r),
        &opts,
    )
    .unwrap();
    let mut worst: f64 = 0.0;
    for i in 0..=50 {
        let t = t_end * i as f64 / 50.0;
        let ym = moving.at(t).unwrap();
        let yf = fixed.at(t).unwrap();
        let out = motion
            .at(t)
            .to_fixed(
                &Vec3::new(ym[0], ym[1], ym[2]),
                &Vec3::new(ym[3], ym[4], ym[5]),
                &Vec3::zeros(),
            )
            .unwrap();
        let scale = Vec3::new(yf[0], yf[1], yf[2]).norm().max(1.0);
        worst = worst.max((out.position - Vec3::new(yf[0], yf[1], yf[2])).norm() / scale);
        let vscale = Vec3::new(yf[3], yf[4], yf[5]).norm().max(1.0);
        worst = worst.max((out.velocity - Vec3::new(yf[3], yf[4], yf[5])).norm() / vscale);
    }
    worst
}

/// The moving-frame equation (origin accelerating, axes spinning up) against the fixed frame.
#[test]
fn steady_frame_integration_matches_fixed_frame() {
    let w = Vec3::new(0.3, -0.4, 1.2);
    let f = MovingFrame::new(
        Vec3::new(1.0, -1.0, 0.5),
        Vec3::new(0.3, 0.2, -0.1),
        Vec3::new(-0.5, 0.25, 0.1),
        w,
        0.35 * w,
    )
    .unwrap()
    .with_attitude(rot(Vec3::new(1.0, 2.0, 3.0), 0.7))
    .unwrap();
    let motion = SteadyMotion::new(f).unwrap();
    let worst = check_against_fixed_frame(&motion, 4.0);
    assert!(worst < FRAME_AGREEMENT, "relative disagreement {worst:e}");
}

/// A frame given by functions of time, tumbling about two axes: A(t) = R_z(φ(t)) R_x(θ(t)),
/// ω = φ̇ ẑ + θ̇ R_z(φ) x̂ and ω̇ its derivative; the origin on a circle.
#[test]
fn tumbling_frame_given_by_functions_of_time_matches_fixed_frame() {
    let motion = |t: f64| {
        let (phi, dphi, ddphi) = (0.8 * t + 0.3 * t.sin(), 0.8 + 0.3 * t.cos(), -0.3 * t.sin());
        let (th, dth, ddth) = (
            0.5 * (1.3 * t).sin(),
            0.65 * (1.3 * t).cos(),
            -0.845 * (1.3 * t).sin(),
        );
        let rz = rot(Vec3::z(), phi);
        let attitude = rz * rot(Vec3::x(), th);
        let nodes = rz * Vec3::x();
        let w = dphi * Vec3::z() + dth * nodes;
        let wd = ddphi * Vec3::z() + ddth * nodes + dth * dphi * Vec3::z().cross(&nodes);
        let (s, c) = (2.0 * t).sin_cos();
        MovingFrame {
            origin: Vec3::new(c, s, 0.1 * t),
            velocity: Vec3::new(-2.0 * s, 2.0 * c, 0.1),
            acceleration: Vec3::new(-4.0 * c, -4.0 * s, 0.0),
            angular_velocity: w,
            angular_acceleration: wd,
            attitude,
        }
    };
    let worst = check_against_fixed_frame(&motion, 3.0);
    assert!(worst < FRAME_AGREEMENT, "relative disagreement {worst:e}");
}

/// Negative control: dropping the Coriolis term from the moving-frame equations must break
/// the agreement by far more than the tolerance (so the test above can fail).
#[test]
fn negative_control_without_coriolis_disagrees() {
    let w = Vec3::new(0.0, 0.0, 1.0);
    let f = MovingFrame::rotating(w).unwrap();
    let motion = SteadyMotion::new(f).unwrap();
    let opts = Options::with_tolerances(1e-12, 1e-12);
    let (r0, v0) = (Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0));
    // Free particle, moving-frame equation without Coriolis: add back +2m ω×v to cancel it.
    let wrong = simulate_particle(
        &motion,
        1.0,
        r0,
        v0,
        0.0,
        2.0,
        |_t, _r, v| 2.0 * w.cross(v),
        &opts,
        None::<(fn(f64, &ParticleState) -> f64, Crossing)>,
    )
    .unwrap();
    let right = simulate_particle(
        &motion,
        1.0,
        r0,
        v0,
        0.0,
        2.0,
        |_t, _r, _v| Vec3::zeros(),
        &opts,
        None::<(fn(f64, &ParticleState) -> f64, Crossing)>,
    )
    .unwrap();
    let start = f.to_fixed(&r0, &v0, &Vec3::zeros()).unwrap();
    let truth = motion
        .at(2.0)
        .to_moving(
            &(start.position + 2.0 * start.velocity),
            &start.velocity,
            &Vec3::zeros(),
        )
        .unwrap();
    let (yw, yr) = (wrong.y_final(), right.y_final());
    assert!((Vec3::new(yr[0], yr[1], yr[2]) - truth.position).norm() < 1e-10);
    assert!((Vec3::new(yw[0], yw[1], yw[2]) - truth.position).norm() > 0.1);
}
