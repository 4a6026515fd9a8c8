//! The Earth's parameters and the local quantities of the unit (eqs. 2.29–2.33, 2.42).

use std::f64::consts::{FRAC_PI_2, PI};

use crate::error::{check_finite, check_non_negative, check_positive, Error, Result};
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
        Self { rotation_rate: SIDEREAL_RATE, radius: MEAN_RADIUS, g: STANDARD_GRAVITY }
    }
}

/// Checks that `latitude` (rad) is finite and in [−π/2, π/2]; the message also shows degrees.
pub fn check_latitude(latitude: f64) -> Result<()> {
    if latitude.is_finite() && latitude.abs() <= FRAC_PI_2 {
        Ok(())
    } else {
        Err(Error::invalid(
            "latitude",
            format!("must be finite and in [-pi/2, pi/2] rad ([-90, 90] degrees), got {latitude} rad ({} degrees)", latitude.to_degrees()),
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
        Ok(Self { rotation_rate, radius, g })
    }

    /// The unit's Earth: one turn per solar day (ω = 2π/86400 s), mean radius, standard gravity.
    pub fn solar_day() -> Self {
        Self { rotation_rate: SOLAR_DAY_RATE, ..Self::default() }
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
    pub fn centrifugal_acceleration(&self, latitude: f64) -> Result<Vec3> {
        let w = self.omega_enu(latitude)?;
        let r = Vec3::new(0.0, 0.0, self.radius);
        Ok(-w.cross(&w.cross(&r)))
    }

    /// The effective gravity g − ω × (ω × r) at the surface (eqs. 2.30–2.31), with its
    /// magnitude and the deviation of the plumb line.
    pub fn effective_gravity(&self, latitude: f64) -> Result<EffectiveGravity> {
        let c = self.centrifugal_acceleration(latitude)?;
        let vector = Vec3::new(0.0, 0.0, -self.g) + c;
        let deviation = (-vector.y).atan2(-vector.z);
        Ok(EffectiveGravity { vector, magnitude: vector.norm(), deviation })
    }

    /// The Coriolis acceleration −2 ω × v (m/s², ENU) of a particle moving with `velocity`
    /// (m/s, ENU) relative to the Earth at `latitude` (eq. 2.30).
    pub fn coriolis_acceleration(&self, latitude: f64, velocity: &Vec3) -> Result<Vec3> {
        check_finite("velocity", velocity.as_slice())?;
        let w = self.omega_enu(latitude)?;
        Ok(-2.0 * w.cross(velocity))
    }

    /// The Coriolis parameter f = 2 ω sin λ (1/s): horizontal motion turns at −f (clockwise
    /// seen from above when f > 0, in the north). Its largest value, at the poles, is the
    /// unit's 2ω.
    pub fn coriolis_parameter(&self, latitude: f64) -> Result<f64> {
        check_latitude(latitude)?;
        Ok(2.0 * self.rotation_rate * latitude.sin())
    }

    /// The unit's first-order eastward deflection (eq. 2.42) of a body dropped from rest
    /// from `height` (m, ≥ 0) at `latitude` (rad): x = ⅓ ω cos λ √(8 h³ / g) (m, east).
    pub fn eastward_deflection(&self, height: f64, latitude: f64) -> Result<f64> {
        check_non_negative("height", height)?;
        check_latitude(latitude)?;
        Ok(self.rotation_rate * latitude.cos() * (8.0 * height.powi(3) / self.g).sqrt() / 3.0)
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
        Ok(0.75 * w * w * (2.0 * latitude).sin() * height * height / self.g)
    }

    /// The time of fall from `height` (m) without rotation, √(2h/g) (eq. 2.41).
    pub fn fall_time(&self, height: f64) -> Result<f64> {
        check_non_negative("height", height)?;
        Ok((2.0 * height / self.g).sqrt())
    }

    /// The rate at which a Foucault pendulum's swing plane turns (rad/s), counterclockwise
    /// seen from above positive: −ω sin λ (clockwise in the north).
    pub fn foucault_rate(&self, latitude: f64) -> Result<f64> {
        check_latitude(latitude)?;
        Ok(-self.rotation_rate * latitude.sin())
    }

    /// The period of inertial oscillations, 2π/|f| = π/(ω |sin λ|) (s); infinite at the equator.
    pub fn inertial_period(&self, latitude: f64) -> Result<f64> {
        let f = self.coriolis_parameter(latitude)?;
        Ok(if f == 0.0 { f64::INFINITY } else { 2.0 * PI / f.abs() })
    }
}
