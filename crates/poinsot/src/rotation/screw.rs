//! Chasles' theorem: every rigid displacement `x ↦ R x + t` is a screw motion — a rotation by
//! an angle about an axis plus a translation (the slide) along that same axis (the unit's
//! remark after Euler's theorem).

use crate::error::{check_finite, num, Result};
use crate::rotation::axis_angle::{rodrigues, rotation_axis_unchecked, IDENTITY_AXIS};
use crate::rotation::matrix::{rotation_to_convert, row_major};
use crate::{Mat3, Vec3};

/// Angles (rad) at or below this are treated as no rotation in [`screw_axis`]: `4 ε ≈ 8.9e-16`,
/// the round-off of a rotation matrix, below which the axis direction is noise (the displacement
/// is then a pure translation, reproduced to round-off).
pub const TRANSLATION_ANGLE_TOL: f64 = 4.0 * f64::EPSILON;

/// Relative tolerance of a `pitch` given to [`Screw::new`] against `slide / angle` (a pitch
/// printed to 10 significant digits agrees; a different pitch does not).
pub const SCREW_PITCH_RTOL: f64 = 1e-9;

/// Relative size of `point · axis` (to `|point| + |slide|`, the scale of the displacement's
/// round-off) below which [`Screw::new`] takes `point` as already the point of the axis nearest
/// the origin: `16 ε ≈ 3.6e-15`, above the round-off of a [`screw_axis`] result (whose
/// `t⊥ = t − slide · axis` carries `ε |slide|`), so that one is kept bit for bit.
pub const POINT_ALONG_TOL: f64 = 16.0 * f64::EPSILON;

/// The screw of a rigid displacement `x ↦ R x + t` (Chasles' theorem).
///
/// The displacement equals: rotate by `angle` about the line through `point` with direction
/// `axis`, then translate by `slide` along `axis` (the two commute), i.e.
/// `R x + t = point + R (x − point) + slide · axis` for every `x`.
///
/// ```
/// use poinsot::rotation::{rot_z, screw_axis};
/// use poinsot::Vec3;
/// // A quarter turn about z, then a shift (1, 1, 0.5): a screw about the vertical line through
/// // (0, 1, 0), sliding 0.5 m along it.
/// let screw = screw_axis(&rot_z(std::f64::consts::FRAC_PI_2), &Vec3::new(1.0, 1.0, 0.5))?;
/// assert!((screw.axis - Vec3::z()).norm() < 1e-15);
/// assert!((screw.point - Vec3::new(0.0, 1.0, 0.0)).norm() < 1e-15);
/// assert!((screw.slide - 0.5).abs() < 1e-15);
/// # Ok::<(), poinsot::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Screw {
    /// Unit direction of the screw axis (Euler's axis of `R`; for a pure translation `t/|t|`;
    /// for the identity displacement the conventional `+z`).
    pub axis: Vec3,
    /// The point of the screw axis nearest the origin (m; `point · axis = 0`).
    pub point: Vec3,
    /// Rotation angle about `axis`, rad, in `[0, π]`.
    pub angle: f64,
    /// Signed translation along `axis` (m): `axis · t`.
    pub slide: f64,
    /// `slide / angle` (m/rad): `+∞` for a pure translation, 0 for a pure rotation and for the
    /// identity displacement (treated as the trivial rotation, never NaN).
    pub pitch: f64,
}

impl Screw {
    /// A screw from its parts, checked: the rotation by `angle` (rad, in `[0, π]`) about the
    /// line through `point` (m, finite: any point of the line, kept as the line's point nearest
    /// the origin, `point − (axis · point) axis`, unless `|axis · point|` is within
    /// [`POINT_ALONG_TOL`] of `|point| + |slide|`) along `axis` (finite, non-zero;
    /// normalised unless its length is 1 to within `4 ε`, as a [`screw_axis`] result's is), with
    /// the slide `slide` (m, finite) along it. The pitch is derived, `slide / angle` (m/rad;
    /// `±∞` for a pure translation, `angle = 0` with `slide ≠ 0`, and 0 for the identity); a
    /// `pitch` given must agree with it to [`SCREW_PITCH_RTOL`] (infinite: exactly).
    ///
    /// Errors name the part: `"axis"` (not finite, or zero), `"point"`, `"slide"` (not
    /// finite), `"angle"` (not finite or outside `[0, π]`: a screw turning the other way has
    /// the opposite axis), `"pitch"` (not `slide / angle`).
    pub fn new(
        axis: Vec3,
        point: Vec3,
        angle: f64,
        slide: f64,
        pitch: Option<f64>,
    ) -> Result<Self> {
        check_finite("axis", axis.as_slice())?;
        check_finite("point", point.as_slice())?;
        check_finite("angle", &[angle])?;
        check_finite("slide", &[slide])?;
        let len = axis.norm();
        if !(len > 0.0 && len.is_finite()) {
            return Err(crate::Error::invalid(
                "axis",
                format!("must be a non-zero vector, got length {}", num(len)),
            ));
        }
        let axis = if (len - 1.0).abs() <= 4.0 * f64::EPSILON {
            axis
        } else {
            axis / len
        };
        // The point kept is the point of the line nearest the origin (`point · axis = 0`, the
        // public contract of `Screw::point`): any other point of the line is moved along the
        // axis to it; one already perpendicular to round-off (a `screw_axis` result) is kept.
        let along = axis.dot(&point);
        let point = if along.abs() <= POINT_ALONG_TOL * (point.norm() + slide.abs()) {
            point
        } else {
            point - along * axis
        };
        if !(0.0..=std::f64::consts::PI).contains(&angle) {
            return Err(crate::Error::invalid(
                "angle",
                format!(
                    "must be in [0, pi] rad (a screw turning the other way has the opposite \
                     axis), got {}",
                    num(angle)
                ),
            ));
        }
        let derived = if angle == 0.0 {
            if slide == 0.0 {
                0.0
            } else {
                f64::INFINITY.copysign(slide)
            }
        } else {
            slide / angle
        };
        if let Some(given) = pitch {
            let agrees = if derived.is_finite() {
                (given - derived).abs() <= SCREW_PITCH_RTOL * derived.abs()
            } else {
                given == derived
            };
            if !agrees {
                return Err(crate::Error::invalid(
                    "pitch",
                    format!(
                        "must be slide / angle = {} m/rad (or left out: it is derived), got {}",
                        num(derived),
                        num(given)
                    ),
                ));
            }
        }
        Ok(Self {
            axis,
            point,
            angle,
            slide,
            pitch: derived,
        })
    }

    /// The displacement `(R, t)` of this screw: `R = R_axis(angle)` (Rodrigues) and
    /// `t = point − R point + slide · axis`.
    pub fn displacement(&self) -> (Mat3, Vec3) {
        let r = rodrigues(&self.axis, self.angle);
        (r, self.point - r * self.point + self.slide * self.axis)
    }

    /// The displacement `(R(s), t(s))` reached at fraction `s` of the screw motion: the rotation
    /// by `s · angle` about the screw axis (through `point`, along `axis`) together with the
    /// slide `s · slide` along it, `R(s) = R_axis(s · angle)` (Rodrigues) and
    /// `t(s) = point − R(s) point + s · slide · axis`.
    ///
    /// This is the motion of Chasles' theorem made continuous: every point turns about the
    /// axis at a constant rate while sliding along it, so `s = 0` is the identity, `s = 1` is
    /// [`Screw::displacement`], and the poses compose, `D(s₁ + s₂) = D(s₁) ∘ D(s₂)` (one
    /// screw, one axis). Any real `s` is accepted (`s < 0` runs the motion backwards, `s > 1`
    /// continues it). Errors: non-finite `s` (naming `"s"`).
    pub fn displacement_at(&self, s: f64) -> Result<(Mat3, Vec3)> {
        check_finite("s", &[s])?;
        let phi = s * self.angle;
        let r = rodrigues(&self.axis, phi);
        // (I − R(φ)) p without the cancellation of p − R p, which loses |p|·ε when the axis lies
        // far away (|p| ~ |t| / θ for a small angle): with p⊥ = p − (n·p) n,
        // (I − R) p = 2 sin²(φ/2) p⊥ − sin φ (n × p).
        let n = self.axis;
        let p_perp = self.point - n.dot(&self.point) * n;
        let half = (0.5 * phi).sin();
        let moved = 2.0 * half * half * p_perp - phi.sin() * n.cross(&self.point);
        let t = moved + (s * self.slide) * n;
        if !t.iter().all(|c| c.is_finite()) {
            return Err(crate::Error::invalid(
                "s",
                "the translation overflows at this fraction of the screw motion",
            ));
        }
        Ok((r, t))
    }

    /// Applies the screw motion to point `x`: `point + R (x − point) + slide · axis`, i.e.
    /// `R x + t` of the displacement it was built from. Errors: non-finite `x` (naming `"x"`).
    pub fn apply(&self, x: &Vec3) -> Result<Vec3> {
        check_finite("x", x.as_slice())?;
        let r = rodrigues(&self.axis, self.angle);
        Ok(self.point + r * (x - self.point) + self.slide * self.axis)
    }
}

/// Chasles' theorem: the screw of the displacement `x ↦ R x + t`.
///
/// With Euler's axis `n` and angle `θ` of `R` ([`crate::rotation::rotation_axis`]), the slide is
/// `d = n · t`. The axis passes through the point `p` with `R p + t = p + d n`; on the plane
/// perpendicular to `n`, `(I − R)` is invertible for `θ ≠ 0`, and the solution perpendicular to
/// `n` (the point nearest the origin) is `p = ½ (t⊥ + cot(θ/2) n × t⊥)` with `t⊥ = t − d n`.
///
/// Limits: for `θ <= TRANSLATION_ANGLE_TOL` the displacement is a pure translation — axis
/// `t/|t|`, point 0, angle 0, slide `|t|`, pitch `+∞`; the identity displacement (`t = 0`
/// too) gives axis `+z`, point 0, angle 0, slide 0, pitch 0. A pure rotation (`n · t = 0`) has
/// pitch 0.
///
/// An `R` off orthonormal by more than [`crate::rotation::NEAREST_ROTATION_DEFECT`] is replaced by
/// the nearest rotation (as in [`crate::rotation::rotation_axis`]).
///
/// Errors: `R` not a rotation within [`crate::rotation::ROTATION_MATRIX_TOL`] (naming `"R"`),
/// non-finite `t` (naming `"t"`).
pub fn screw_axis(r: &Mat3, t: &Vec3) -> Result<Screw> {
    let m = rotation_to_convert("R", &row_major(r))?;
    check_finite("t", t.as_slice())?;
    let (n, angle) = rotation_axis_unchecked(&m);
    let n = Vec3::from(n);
    if angle <= TRANSLATION_ANGLE_TOL {
        let len = t.norm();
        if !len.is_finite() {
            return Err(crate::Error::invalid(
                "t",
                "the screw's slide |t| overflows for this translation",
            ));
        }
        return Ok(if len == 0.0 {
            Screw {
                axis: Vec3::from(IDENTITY_AXIS),
                point: Vec3::zeros(),
                angle: 0.0,
                slide: 0.0,
                pitch: 0.0,
            }
        } else {
            Screw {
                axis: t / len,
                point: Vec3::zeros(),
                angle: 0.0,
                slide: len,
                pitch: f64::INFINITY,
            }
        });
    }
    let slide = n.dot(t);
    let t_perp = t - slide * n;
    let half = 0.5 * angle;
    let cot = half.cos() / half.sin();
    let point = 0.5 * (t_perp + cot * n.cross(&t_perp));
    if !(point.iter().all(|c| c.is_finite()) && slide.is_finite()) {
        return Err(crate::Error::invalid(
            "t",
            "the screw's point or slide overflows for this translation",
        ));
    }
    Ok(Screw {
        axis: n,
        point,
        angle,
        slide,
        pitch: slide / angle,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rotation::{rot_x, rot_z};
    use crate::ErrorKind;

    #[test]
    fn screw_reconstructs_a_displacement() {
        let r = rot_z(0.7) * rot_x(-1.9);
        let t = Vec3::new(0.3, -2.0, 1.1);
        let s = screw_axis(&r, &t).unwrap();
        // The axis point is fixed up to the slide: R p + t = p + d n.
        assert!((r * s.point + t - s.point - s.slide * s.axis).norm() < 1e-14);
        assert!(s.point.dot(&s.axis).abs() < 1e-15);
        let (r2, t2) = s.displacement();
        assert!((r2 - r).norm() < 1e-14 && (t2 - t).norm() < 1e-14);
        let x = Vec3::new(-0.4, 0.9, 2.2);
        assert!((s.apply(&x).unwrap() - (r * x + t)).norm() < 1e-14);
    }

    #[test]
    fn displacement_at_is_accurate_for_a_far_axis() {
        // A tiny rotation with a perpendicular translation: the axis lies |t|/θ = 1e10 m away,
        // where p − R p would cancel away ~|p|·ε ≈ 1e-6 (found by hypothesis in
        // python/tests/test_rotation_screw.py at 2.5e-11). The poses must stay at round-off of |t|.
        let r = rot_x(1e-10);
        let t = Vec3::new(0.0, 0.0, 1.0);
        let s = screw_axis(&r, &t).unwrap();
        assert!(s.point.norm() > 1e9);
        let (r1, t1) = s.displacement_at(1.0).unwrap();
        assert!((r1 - r).amax() < 1e-15 && (t1 - t).amax() < 1e-15, "{t1}");
        let (rh, th) = s.displacement_at(0.5).unwrap();
        assert!((rh * th + th - t).amax() < 1e-15, "{}", rh * th + th - t);
        // To first order in θ the half-way pose translates by half of t.
        assert!((th - 0.5 * t).amax() < 1e-9);
    }

    #[test]
    fn displacement_at_runs_from_identity_to_the_displacement_along_the_screw() {
        let r = rot_z(2.3) * rot_x(0.8);
        let t = Vec3::new(1.5, -0.2, 0.7);
        let s = screw_axis(&r, &t).unwrap();
        let (r0, t0) = s.displacement_at(0.0).unwrap();
        assert!((r0 - Mat3::identity()).amax() == 0.0 && t0.amax() == 0.0);
        let (r1, t1) = s.displacement_at(1.0).unwrap();
        assert!((r1 - r).amax() < 1e-14 && (t1 - t).amax() < 1e-14);
        // Half-way twice is the whole way (one screw composes with itself).
        let (rh, th) = s.displacement_at(0.5).unwrap();
        assert!((rh * rh - r).amax() < 1e-14);
        assert!((rh * th + th - t).amax() < 1e-14);
        // Every intermediate pose has the same screw axis, a fraction of the angle and slide.
        for k in 1..10 {
            let f = f64::from(k) / 10.0;
            let (rf, tf) = s.displacement_at(f).unwrap();
            let sf = screw_axis(&rf, &tf).unwrap();
            assert!((sf.axis - s.axis).amax() < 1e-13, "{f}");
            assert!((sf.point - s.point).amax() < 1e-13, "{f}");
            assert!((sf.angle - f * s.angle).abs() < 1e-14, "{f}");
            assert!((sf.slide - f * s.slide).abs() < 1e-14, "{f}");
            // A point on the axis only slides.
            let p = s.point + 0.3 * s.axis;
            assert!((rf * p + tf - p - f * s.slide * s.axis).amax() < 1e-14);
        }
        // A pure translation moves in a straight line.
        let s = screw_axis(&Mat3::identity(), &Vec3::new(0.0, 3.0, 4.0)).unwrap();
        let (rq, tq) = s.displacement_at(0.25).unwrap();
        assert_eq!(rq, Mat3::identity());
        assert!((tq - Vec3::new(0.0, 0.75, 1.0)).amax() < 1e-15);
        let e = s.displacement_at(f64::NAN).unwrap_err();
        assert!(e.to_string().starts_with("s: "), "{e}");
    }

    #[test]
    fn limits_translation_rotation_identity() {
        let s = screw_axis(&Mat3::identity(), &Vec3::new(0.0, 3.0, 4.0)).unwrap();
        assert_eq!((s.angle, s.slide, s.pitch), (0.0, 5.0, f64::INFINITY));
        assert!((s.axis - Vec3::new(0.0, 0.6, 0.8)).norm() < 1e-16);
        let s = screw_axis(&rot_z(1.0), &Vec3::new(1.0, 0.0, 0.0)).unwrap();
        assert_eq!(s.pitch, 0.0);
        let s = screw_axis(&Mat3::identity(), &Vec3::zeros()).unwrap();
        assert_eq!(
            (s.axis, s.angle, s.slide, s.pitch),
            (Vec3::z(), 0.0, 0.0, 0.0)
        );
        let e = screw_axis(&Mat3::identity(), &Vec3::new(f64::NAN, 0.0, 0.0)).unwrap_err();
        assert_eq!(e.kind, ErrorKind::InvalidArgument);
        assert!(e.to_string().starts_with("t: "));
    }
}
