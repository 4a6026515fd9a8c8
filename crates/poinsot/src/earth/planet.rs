//! The Earth's parameters and the local quantities of the unit (eqs. 2.29–2.33, 2.42).

use std::f64::consts::{FRAC_PI_2, PI, SQRT_2};

use crate::error::{
    check_finite, check_non_negative, check_positive, finite_result, num, Error, Result,
};
use crate::special::fp::{exponent, ldexp};
use crate::Vec3;

/// The Earth's sidereal rotation rate, 2π / 86164.0905 s (rad/s): the true rate, the default.
pub const SIDEREAL_RATE: f64 = 7.2921150e-5;
/// The unit's rate, 2π / (24 · 3600) s (rad/s): one turn per solar day (see the errata).
pub const SOLAR_DAY_RATE: f64 = 2.0 * PI / 86400.0;
/// The Earth's mean radius (m).
pub const MEAN_RADIUS: f64 = 6.371e6;
/// Standard gravity (m/s²).
pub const STANDARD_GRAVITY: f64 = 9.80665;

/// The rotating Earth: a sphere of `radius` turning at `rotation_rate` about its axis, with
/// gravity `g` at its surface.
///
/// `g` plays the unit's roles: the attraction in the effective gravity (eq. 2.31), and the
/// local (plumb-line) gravity of the near-surface motions (eqs. 2.32–2.42), whose local
/// vertical z is the plumb line, so that the centrifugal acceleration at the origin is
/// already contained in it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Earth {
    /// ω (rad/s), ≥ 0.
    pub rotation_rate: f64,
    /// R (m), > 0.
    pub radius: f64,
    /// g (m/s²), > 0.
    pub g: f64,
}

impl Default for Earth {
    /// The sidereal rate, the mean radius and standard gravity.
    fn default() -> Self {
        Self {
            rotation_rate: SIDEREAL_RATE,
            radius: MEAN_RADIUS,
            g: STANDARD_GRAVITY,
        }
    }
}

/// Checks that `latitude` (rad) is finite and in [−π/2, π/2]; the message also shows degrees.
pub fn check_latitude(latitude: f64) -> Result<()> {
    if latitude.is_finite() && latitude.abs() <= FRAC_PI_2 {
        Ok(())
    } else {
        Err(Error::invalid(
            "latitude",
            format!("must be finite and in [-pi/2, pi/2] rad ([-90, 90] degrees), got {} rad ({} degrees)", num(latitude), num(latitude.to_degrees())),
        ))
    }
}

/// The effective gravity at the surface (eq. 2.31) in ENU components.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EffectiveGravity {
    /// g_e = g − ω × (ω × r) (m/s², ENU), with g = −g ẑ radial and r = R ẑ.
    pub vector: Vec3,
    /// |g_e| (m/s²).
    pub magnitude: f64,
    /// Angle between the plumb line and the radial direction (rad): positive when the plumb
    /// line's lower end points south of the radial direction (north of the equator), i.e.
    /// the plumb line leans towards the equator in both hemispheres.
    pub deviation: f64,
}

impl Earth {
    /// An Earth with the given rate (rad/s, ≥ 0), radius (m, > 0) and gravity (m/s², > 0).
    pub fn new(rotation_rate: f64, radius: f64, g: f64) -> Result<Self> {
        check_non_negative("rotation_rate", rotation_rate)?;
        check_positive("radius", radius)?;
        check_positive("g", g)?;
        Ok(Self {
            rotation_rate,
            radius,
            g,
        })
    }

    /// The unit's Earth: one turn per solar day (ω = 2π/86400 s), mean radius, standard gravity.
    pub fn solar_day() -> Self {
        Self {
            rotation_rate: SOLAR_DAY_RATE,
            ..Self::default()
        }
    }

    /// ω in ENU components at `latitude` (rad): ω (0, cos λ, sin λ) (eq. 2.33).
    pub fn omega_enu(&self, latitude: f64) -> Result<Vec3> {
        check_latitude(latitude)?;
        Ok(self.omega_enu_unchecked(latitude))
    }

    #[inline]
    pub(crate) fn omega_enu_unchecked(&self, latitude: f64) -> Vec3 {
        self.rotation_rate * Vec3::new(0.0, latitude.cos(), latitude.sin())
    }

    /// The centrifugal acceleration −ω × (ω × r) at the surface (m/s², ENU), r = R ẑ:
    /// ω² R cos λ (0, −sin λ, cos λ), of magnitude ω² R cos λ (ω² R at the equator).
    ///
    /// Computed on mantissas with the powers of two applied last, so that ω² does not
    /// overflow on the way to a representable ω² R cos λ; a component that is not
    /// representable is refused, naming `rotation_rate`.
    pub fn centrifugal_acceleration(&self, latitude: f64) -> Result<Vec3> {
        check_latitude(latitude)?;
        let c = self.centrifugal_unchecked(latitude);
        if c.iter().all(|x| x.is_finite()) {
            Ok(c)
        } else {
            Err(self.overflow("the centrifugal acceleration ω² R cos λ", latitude))
        }
    }

    /// The magnitude of the centrifugal acceleration, ω² R cos λ (m/s²), in closed form (the
    /// length of [`Self::centrifugal_acceleration`] by a second route): ω² R at the equator, 0
    /// at the poles. Refused, naming `rotation_rate`, where it overflows.
    pub fn centrifugal_magnitude(&self, latitude: f64) -> Result<f64> {
        check_latitude(latitude)?;
        let a = self.rotation_rate * self.rotation_rate * self.radius * latitude.cos().abs();
        if a.is_finite() {
            Ok(a)
        } else {
            Err(self.overflow("the centrifugal acceleration ω² R cos λ", latitude))
        }
    }

    /// The deviation of the plumb line from the radius (rad) in closed form, a second route
    /// beside [`Self::effective_gravity`]'s vector: with q = ω² R / g,
    ///
    /// tan δ = q sin λ cos λ / (1 − q cos² λ)
    ///
    /// (the centrifugal acceleration's northward part over what is left of gravity along the
    /// radius; δ ≈ (q/2) sin 2λ to first order in q, 0.1° at 45° on the Earth). Refused, naming
    /// `rotation_rate`, where q overflows.
    pub fn plumb_line_deviation_closed(&self, latitude: f64) -> Result<f64> {
        check_latitude(latitude)?;
        let q = self.rotation_rate * self.rotation_rate * self.radius / self.g;
        if !q.is_finite() {
            return Err(self.overflow("the ratio ω² R / g", latitude));
        }
        let (s, c) = latitude.sin_cos();
        Ok((q * s * c).atan2(1.0 - q * c * c))
    }

    /// ω² R cos λ (0, −sin λ, cos λ) on mantissas (±inf where a component overflows).
    fn centrifugal_unchecked(&self, latitude: f64) -> Vec3 {
        if self.rotation_rate == 0.0 {
            return Vec3::zeros();
        }
        let (s, c) = latitude.sin_cos();
        let (ew, er) = (exponent(self.rotation_rate), exponent(self.radius));
        let mw = ldexp(self.rotation_rate, -ew);
        let mr = ldexp(self.radius, -er);
        // m in [1, 8): ω² R = m · 2^k exactly in the exponent.
        let m = mw * mw * mr;
        let k = 2 * ew + er;
        Vec3::new(0.0, -ldexp(m * c * s, k), ldexp(m * c * c, k))
    }

    /// The error for a quantity of this Earth that overflows at `latitude`: it names
    /// `rotation_rate`, the argument that makes it large.
    fn overflow(&self, what: &str, latitude: f64) -> Error {
        Error::invalid(
            "rotation_rate",
            format!(
                "{what} is not representable as a finite number for rotation_rate = {} rad/s \
                 and radius = {} m at latitude {} rad (it overflows)",
                num(self.rotation_rate),
                num(self.radius),
                num(latitude)
            ),
        )
    }

    /// The effective gravity g − ω × (ω × r) at the surface (eqs. 2.30–2.31), with its
    /// magnitude and the deviation of the plumb line.
    ///
    /// All three are finite or the call is refused, naming `rotation_rate`: the vector, its
    /// magnitude (a scaled hypotenuse, finite whenever the vector's length is representable)
    /// and the deviation (never computed from infinities).
    pub fn effective_gravity(&self, latitude: f64) -> Result<EffectiveGravity> {
        let c = self.centrifugal_acceleration(latitude)?;
        let vector = Vec3::new(0.0, 0.0, -self.g) + c;
        // |g_e| = hypot(g_y, g_z): finite whenever the length is (the norm of the sum of
        // squares overflows at 1e154).
        let magnitude = vector.y.hypot(vector.z);
        if !magnitude.is_finite() {
            return Err(self.overflow("the magnitude of the effective gravity", latitude));
        }
        let deviation = (-vector.y).atan2(-vector.z);
        Ok(EffectiveGravity {
            vector,
            magnitude,
            deviation,
        })
    }

    /// The Coriolis acceleration −2 ω × v (m/s², ENU) of a particle moving with
    /// `velocity_enu` (m/s, ENU) relative to the Earth at `latitude` (eq. 2.30). Errors name
    /// `velocity_enu` and `latitude`.
    pub fn coriolis_acceleration(&self, latitude: f64, velocity_enu: &Vec3) -> Result<Vec3> {
        check_finite("velocity_enu", velocity_enu.as_slice())?;
        let w = self.omega_enu(latitude)?;
        let a = -2.0 * w.cross(velocity_enu);
        if a.iter().all(|x| x.is_finite()) {
            Ok(a)
        } else {
            Err(Error::invalid(
                "velocity_enu",
                format!(
                    "the Coriolis acceleration −2 ω × v is not representable as a finite number \
                     for this velocity and rotation_rate = {} rad/s (it overflows)",
                    num(self.rotation_rate)
                ),
            ))
        }
    }

    /// The Coriolis parameter f = 2 ω sin λ (1/s): horizontal motion turns at −f (clockwise
    /// seen from above when f > 0, in the north). Its largest value, at the poles, is the
    /// unit's 2ω.
    pub fn coriolis_parameter(&self, latitude: f64) -> Result<f64> {
        check_latitude(latitude)?;
        let f = 2.0 * self.rotation_rate * latitude.sin();
        if f.is_finite() {
            Ok(f)
        } else {
            Err(self.overflow("the Coriolis parameter 2 ω sin λ", latitude))
        }
    }

    /// The unit's first-order eastward deflection (eq. 2.42) of a body dropped from rest
    /// from `height` (m, ≥ 0) at `latitude` (rad): x = ⅓ ω cos λ √(8 h³ / g) (m, east).
    pub fn eastward_deflection(&self, height: f64, latitude: f64) -> Result<f64> {
        check_non_negative("height", height)?;
        check_latitude(latitude)?;
        // √(8h³/g) = 2√2 · h · √(h/g), without overflowing h³ on the way.
        let x = self.rotation_rate
            * latitude.cos()
            * (2.0 * SQRT_2 * height * (height / self.g).sqrt())
            / 3.0;
        finite_result("height", "the eastward deflection", x)
    }

    /// The second-order southward deflection (m; equatorward: positive south in the north,
    /// negative in the south) of a body dropped from `height` at `latitude`, in the model of
    /// [`Earth::drop`] with uniform gravity: y = −¾ ω² sin 2λ h² / g (north component), of
    /// which ⅓ comes from the Coriolis force and 5/12 from the change of the centrifugal
    /// force with height. Returned as the southward distance ¾ ω² sin 2λ h² / g.
    pub fn southward_deflection(&self, height: f64, latitude: f64) -> Result<f64> {
        check_non_negative("height", height)?;
        check_latitude(latitude)?;
        let w = self.rotation_rate;
        let wh = w * height;
        finite_result(
            "height",
            "the southward deflection",
            0.75 * (2.0 * latitude).sin() * wh * (wh / self.g),
        )
    }

    /// The time of fall from `height` (m) without rotation, √(2h/g) (eq. 2.41); refused,
    /// naming `height`, where it is beyond the largest double (h/g overflows for a tiny g).
    pub fn fall_time(&self, height: f64) -> Result<f64> {
        check_non_negative("height", height)?;
        // √(2h/g) = √2 · √(h/g): no overflow of 2h on the way.
        finite_result(
            "height",
            "the time of fall",
            SQRT_2 * (height / self.g).sqrt(),
        )
    }

    /// The rate at which a Foucault pendulum's swing plane turns (rad/s), counterclockwise
    /// seen from above positive: −ω sin λ (clockwise in the north).
    pub fn foucault_rate(&self, latitude: f64) -> Result<f64> {
        check_latitude(latitude)?;
        Ok(-self.rotation_rate * latitude.sin())
    }

    /// The period of inertial oscillations, 2π/|f| = π/(ω |sin λ|) (s); infinite where f = 0
    /// (at the equator, or on a planet that does not turn: there is no inertial oscillation).
    ///
    /// Where f ≠ 0 but the period is beyond the largest double (|sin λ| below ~1e-300), the
    /// call is refused naming `latitude`: an infinity would claim there is no oscillation.
    pub fn inertial_period(&self, latitude: f64) -> Result<f64> {
        check_latitude(latitude)?;
        let w_sin = self.rotation_rate * latitude.sin().abs();
        if w_sin == 0.0 {
            return Ok(f64::INFINITY);
        }
        let period = PI / w_sin;
        if period.is_finite() {
            Ok(period)
        } else {
            Err(Error::invalid(
                "latitude",
                format!(
                    "the inertial period π/(ω |sin λ|) at latitude {} rad with rotation_rate = {} \
                     rad/s is beyond the largest double (it overflows); it is infinite only \
                     where ω sin λ = 0",
                    num(latitude),
                    num(self.rotation_rate)
                ),
            ))
        }
    }
}
