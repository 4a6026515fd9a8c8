//! The named closed forms that stand beside the core's other routes (the experiment
//! catalogue's "closed form" column and the CLI's summaries take them from here): each equals
//! the route it checks to round-off, and refuses what it cannot return, naming the argument.

use poinsot::analytic::{axis_stability, FreeRigidBody, FreeSymmetricTop};
use poinsot::earth::{Earth, RigidEarth};
use poinsot::integrate::Options;
use poinsot::Vec3;

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

#[test]
fn centrifugal_magnitude_and_plumb_line_in_closed_form() {
    let e = Earth::default();
    for lat in [0.0_f64, 0.3, 0.8, 1.2, -0.9, std::f64::consts::FRAC_PI_2] {
        let c = e.centrifugal_acceleration(lat).unwrap();
        let m = e.centrifugal_magnitude(lat).unwrap();
        assert!((m - c.norm()).abs() <= 1e-15 * (e.rotation_rate.powi(2) * e.radius));
        let dev = e.effective_gravity(lat).unwrap().deviation;
        let closed = e.plumb_line_deviation_closed(lat).unwrap();
        assert!((closed - dev).abs() <= 1e-15, "{lat}: {closed} vs {dev}");
    }
    // The plumb line leans about 0.1° near 45° on the unit's Earth (q/2 sin 2λ to first order).
    let q = e.rotation_rate.powi(2) * e.radius / e.g;
    assert!(rel(e.plumb_line_deviation_closed(0.8).unwrap(), q / 2.0) < 1e-2);
    let fast = Earth::new(1e160, 6.4e6, 9.8).unwrap();
    let err = fast.centrifugal_magnitude(0.3).unwrap_err();
    assert_eq!(err.argument, "rotation_rate");
    let err = fast.plumb_line_deviation_closed(0.3).unwrap_err();
    assert_eq!(err.argument, "rotation_rate");
}

#[test]
fn inertial_run_measures_its_period() {
    let e = Earth::default();
    let theory = e.inertial_period(0.9).unwrap();
    let run = e
        .inertial_oscillation(0.9, [0.1, 0.0], 2.0 * theory, &[0.0], &Options::default())
        .unwrap();
    assert!(rel(run.measured_period, theory) < 1e-8);
    let equator = e
        .inertial_oscillation(0.0, [0.1, 0.0], 1e5, &[0.0], &Options::default())
        .unwrap();
    assert_eq!(equator.measured_period, f64::INFINITY);
}

#[test]
fn symmetric_top_period_and_free_body_magnitudes() {
    let w = Vec3::new(1e-6 * 7.29e-5, 0.0, 7.29e-5);
    let top = FreeSymmetricTop::new(1.0 - 3.27e-3, 1.0, w, None).unwrap();
    let body = FreeRigidBody::new([1.0 - 3.27e-3, 1.0 - 3.27e-3, 1.0], w, None).unwrap();
    assert!(rel(top.precession_period().unwrap(), body.period().unwrap()) < 1e-12);
    let sphere = FreeSymmetricTop::new(1.0, 1.0, w, None).unwrap();
    let err = sphere.precession_period().unwrap_err();
    assert_eq!(err.argument, "omega0");
    // ω₃ tiny beside the transverse spin: the scaled Ω is below 2π/f64::MAX, and the period
    // 2π/|Ω| = 2π (ω₃ = 1, I₁ = 1, I₃ = 2) is returned, not an overflow to inf.
    let skew = FreeSymmetricTop::new(1.0, 2.0, Vec3::new(1e308, 0.0, 1.0), None).unwrap();
    assert!(rel(skew.precession_period().unwrap(), std::f64::consts::TAU) < 1e-15);
    let tiny = FreeSymmetricTop::new(1.0, 2.0, Vec3::new(1e-300, 0.0, 1e-300), None).unwrap();
    assert!(
        rel(
            tiny.precession_period().unwrap(),
            std::f64::consts::TAU * 1e300
        ) < 1e-15
    );

    let b = FreeRigidBody::new([1.0, 2.0, 3.0], Vec3::new(0.3, 2.0, -0.5), None).unwrap();
    let l = b.angular_momentum().unwrap();
    assert!(rel(b.angular_momentum_magnitude().unwrap(), l.norm()) < 1e-15);
    let spin = Vec3::new(0.3, 2.0, -0.5).norm();
    let direct = axis_stability([1.0, 2.0, 3.0], spin).unwrap();
    let own = b.axis_stability().unwrap();
    for (a, o) in direct.iter().zip(&own) {
        assert_eq!(a.stability, o.stability);
        assert!(rel(o.rate, a.rate) < 1e-15);
    }
    // |ω₀| and |L| without overflow on the way (their squares would overflow).
    let big = FreeRigidBody::new([1.0, 2.0, 3.0], Vec3::new(1e200, 1e200, 0.0), None).unwrap();
    assert!(big.axis_stability().unwrap()[0].rate.is_finite());
}

#[test]
fn nutation_by_precession_is_the_direct_closed_form() {
    let e = RigidEarth::default();
    let (a, b) = e.nutation_amplitudes().unwrap();
    let (c, d) = e.nutation_amplitudes_by_precession().unwrap();
    assert!(rel(c, a) < 1e-13 && rel(d, b) < 1e-13);
}
