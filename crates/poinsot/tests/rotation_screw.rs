//! `Screw::new`: a screw built from its parts is checked, names the part at fault, derives its
//! pitch, and moves points as the closed form of a screw motion does (issue 21, item 9: the
//! public Python `Screw` was never validated).

use std::f64::consts::PI;

use poinsot::rotation::*;
use poinsot::{ErrorKind, Vec3};

/// The screw motion about the z axis shifted to pass through (a, b, ·), written out: turn by
/// `angle` about that vertical line, then rise by `slide` (an independent closed form).
fn vertical_screw(a: f64, b: f64, angle: f64, slide: f64, x: Vec3) -> Vec3 {
    let (s, c) = angle.sin_cos();
    let (dx, dy) = (x.x - a, x.y - b);
    Vec3::new(a + c * dx - s * dy, b + s * dx + c * dy, x.z + slide)
}

#[test]
fn a_screw_from_parts_moves_points_as_the_closed_form() {
    let x = Vec3::new(1.0, 2.0, 3.0);
    // A non-unit axis is normalised; the point may be any point of the line.
    let s = Screw::new(
        Vec3::new(0.0, 0.0, 2.0),
        Vec3::new(0.5, -1.0, 7.0),
        0.5,
        0.1,
        None,
    )
    .unwrap();
    assert_eq!(s.axis, Vec3::z());
    assert_eq!(s.pitch, 0.1 / 0.5);
    let want = vertical_screw(0.5, -1.0, 0.5, 0.1, x);
    assert!(
        (s.apply(&x).unwrap() - want).amax() < 1e-15,
        "{}",
        s.apply(&x).unwrap() - want
    );
    let (r, t) = s.displacement();
    assert!((r * x + t - want).amax() < 1e-14);
    // the pitch given agrees: accepted, and the stored one is the derived one
    let given = Screw::new(Vec3::z(), Vec3::zeros(), 0.5, 0.1, Some(0.2)).unwrap();
    assert_eq!(given.pitch, 0.1 / 0.5);
}

#[test]
fn a_screw_axis_result_rebuilt_from_its_parts_is_the_same_screw() {
    for (r, t) in [
        (rot_z(0.7) * rot_x(-1.9), Vec3::new(0.3, -2.0, 1.1)),
        (rot_x(PI), Vec3::new(0.0, 1.0, 2.0)),
        (rot_z(0.0), Vec3::new(0.0, 3.0, 4.0)), // a pure translation: pitch inf
        (rot_z(0.0), Vec3::zeros()),            // the identity: pitch 0
        (rot_z(1.2), Vec3::zeros()),            // a pure rotation: pitch 0
    ] {
        let s = screw_axis(&r, &t).unwrap();
        let again = Screw::new(s.axis, s.point, s.angle, s.slide, Some(s.pitch)).unwrap();
        assert_eq!(again, s, "bit for bit");
        assert_eq!(
            Screw::new(s.axis, s.point, s.angle, s.slide, None).unwrap(),
            s
        );
    }
}

#[test]
fn each_bad_part_is_named() {
    let (n, p) = (Vec3::z(), Vec3::zeros());
    let cases = [
        (
            Screw::new(Vec3::new(0.0, f64::NAN, 1.0), p, 0.5, 0.1, None),
            "axis",
        ),
        (Screw::new(Vec3::zeros(), p, 0.5, 0.1, None), "axis"),
        (
            Screw::new(Vec3::new(1e-320, 0.0, 0.0), p, 0.5, 0.1, None),
            "axis",
        ),
        (
            Screw::new(n, Vec3::new(f64::INFINITY, 0.0, 0.0), 0.5, 0.1, None),
            "point",
        ),
        (Screw::new(n, p, f64::NAN, 0.1, None), "angle"),
        (Screw::new(n, p, -0.5, 0.1, None), "angle"),
        (Screw::new(n, p, 3.5, 0.1, None), "angle"),
        (Screw::new(n, p, 0.5, f64::INFINITY, None), "slide"),
        (Screw::new(n, p, 0.5, 0.1, Some(0.3)), "pitch"),
        (
            Screw::new(n, p, 0.5, 0.1, Some(0.2 * (1.0 + 1e-6))),
            "pitch",
        ),
        (Screw::new(n, p, 0.5, 0.1, Some(f64::NAN)), "pitch"),
        (Screw::new(n, p, 0.0, 1.0, Some(1e300)), "pitch"), // a pure translation: inf
        (Screw::new(n, p, 0.0, 0.0, Some(f64::INFINITY)), "pitch"), // the identity: 0
    ];
    for (k, (res, name)) in cases.into_iter().enumerate() {
        let err = res.unwrap_err();
        assert_eq!(err.kind, ErrorKind::InvalidArgument, "{k}");
        assert_eq!(err.argument, name, "{k}: {err}");
        assert!(err.to_string().starts_with(&format!("{name}: ")), "{err}");
    }
    // negative controls: the limits themselves are accepted
    assert!(Screw::new(n, p, PI, 0.1, None).is_ok());
    assert!(Screw::new(n, p, 0.0, 0.0, Some(0.0)).is_ok());
    assert_eq!(
        Screw::new(n, p, 0.0, -2.0, None).unwrap().pitch,
        f64::NEG_INFINITY
    );
    assert!(Screw::new(n, p, 0.5, 0.1, Some(0.2 * (1.0 + 1e-12))).is_ok());
}

/// The public contract of `Screw::point`: the point of the axis nearest the origin. A point
/// given elsewhere on the line is moved to it (the motion is the same line's); the reference is
/// the minimiser of |p + λ n|² written out, λ = −(p · n)/(n · n), with the unnormalised axis.
#[test]
fn a_point_elsewhere_on_the_line_is_moved_to_the_nearest_the_origin() {
    let s = Screw::new(Vec3::z(), Vec3::new(0.5, -1.0, 7.0), 0.5, 0.1, None).unwrap();
    assert_eq!(s.point, Vec3::new(0.5, -1.0, 0.0));
    let (n, p) = (Vec3::new(1.0, -2.0, 2.0), Vec3::new(3.0, 0.25, -4.0));
    let s = Screw::new(n, p, 1.1, -0.3, None).unwrap();
    let lambda = -p.dot(&n) / n.dot(&n);
    let want = p + lambda * n;
    assert!(
        (s.point - want).amax() < 4.0 * f64::EPSILON * p.amax(),
        "{}",
        s.point - want
    );
    assert!(s.point.dot(&s.axis).abs() < 4.0 * f64::EPSILON * p.norm());
    // the same motion as the point given: every x moves to the same place
    let x = Vec3::new(-0.7, 1.3, 2.9);
    let r = rodrigues_reference(&(n / n.norm()), 1.1);
    let moved = p + r * (x - p) - 0.3 * n / n.norm();
    assert!((s.apply(&x).unwrap() - moved).amax() < 1e-14);
    // negative control: a point already nearest the origin is kept as given, bit for bit
    let q = Vec3::new(0.0, 2.0, 3.0);
    assert_eq!(Screw::new(Vec3::x(), q, 0.5, 0.1, None).unwrap().point, q);
}

/// R = cos a I + sin a [n]× + (1 − cos a) n nᵀ, written out (not the crate's rodrigues).
fn rodrigues_reference(n: &Vec3, a: f64) -> poinsot::Mat3 {
    let (s, c) = a.sin_cos();
    let k = poinsot::Mat3::new(0.0, -n.z, n.y, n.z, 0.0, -n.x, -n.y, n.x, 0.0);
    c * poinsot::Mat3::identity() + s * k + (1.0 - c) * n * n.transpose()
}

/// Every `screw_axis` result has its point perpendicular to its axis within
/// `POINT_ALONG_TOL` of `|point| + |slide|` (so `Screw::new` keeps it bit for bit): random rotations at every angle,
/// the small and near-π ones included, and translations across 12 decades.
#[test]
fn screw_axis_points_are_within_the_tolerance_kept_as_given() {
    let mut seed = 0x2545_f491_4f6c_dd1d_u64;
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut worst = 0.0_f64;
    for k in 0..20_000 {
        let axis = Vec3::new(next() - 0.5, next() - 0.5, next() - 0.5);
        let angle = match k % 4 {
            0 => PI * next(),
            1 => 10f64.powf(-12.0 * next()),
            2 => PI - 10f64.powf(-12.0 * next()),
            _ => PI * (1.0 - 1e-3 * next()),
        };
        let scale = 10f64.powf(12.0 * next() - 6.0);
        let mut t = scale * Vec3::new(next() - 0.5, next() - 0.5, next() - 0.5);
        if k % 3 == 0 {
            // mostly along the axis: a long slide and a point near the origin
            t += 10f64.powf(8.0 * next()) * scale * axis;
        }
        let r = axis_angle_to_matrix(&(axis / axis.norm()), angle).unwrap();
        let s = screw_axis(&r, &t).unwrap();
        let scale = (s.point.norm() + s.slide.abs()).max(f64::MIN_POSITIVE);
        let rel = s.point.dot(&s.axis).abs() / scale;
        worst = worst.max(rel);
        let again = Screw::new(s.axis, s.point, s.angle, s.slide, Some(s.pitch)).unwrap();
        assert_eq!(again, s, "{k}");
    }
    assert!(worst <= POINT_ALONG_TOL, "{worst:e}");
    println!("worst |p·n|/(|p| + |d|) = {worst:e} (tolerance {POINT_ALONG_TOL:e})");
}
