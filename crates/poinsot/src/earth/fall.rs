//! Falling bodies and projectiles integrated exactly in the rotating Earth's local frame
//! (eqs. 2.30, 2.32–2.42).

use super::planet::{check_latitude, Earth};
use crate::error::{check_finite, check_non_negative, check_positive, num, Error, Result};
use crate::frames::ParticleState;
use crate::integrate::{dop853_until, Crossing, Options, Solution};
use crate::Vec3;

/// How gravity varies near the surface.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Gravity {
    /// A uniform field −g ẑ; the ground is the plane z = 0 (the unit's model).
    #[default]
    Uniform,
    /// The field of a spherical Earth of radius R centred at −R ẑ, −g R² ρ/|ρ|³ with
    /// ρ = r + R ẑ (g decreases with height); the ground is the sphere |ρ| = R.
    InverseSquare,
}

impl std::str::FromStr for Gravity {
    type Err = Error;
    /// `"uniform"` or `"inverse-square"`; the error names `gravity`.
    fn from_str(name: &str) -> Result<Self> {
        match name {
            "uniform" => Ok(Gravity::Uniform),
            "inverse-square" => Ok(Gravity::InverseSquare),
            _ => Err(Error::invalid(
                "gravity",
                format!("must be 'uniform' or 'inverse-square', got {name:?}"),
            )),
        }
    }
}

/// The model of a near-surface motion in the rotating local frame:
///
/// r̈ = g(r) − 2 ω × ṙ − ω × (ω × r),
///
/// with ẑ the plumb line at the origin (the centrifugal acceleration there is part of g).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FallModel {
    /// Uniform or inverse-square gravity.
    pub gravity: Gravity,
    /// Include the Earth's rotation (Coriolis force and centrifugal variation); false gives
    /// the motion on a non-rotating Earth, for comparison.
    pub rotation: bool,
    /// Include the change of the centrifugal force away from the origin, −ω × (ω × r)
    /// (second order in ω; needs `rotation`).
    pub centrifugal: bool,
    /// Integrator settings (default rtol = atol = 1e-12).
    pub options: Options,
}

impl Default for FallModel {
    fn default() -> Self {
        Self {
            gravity: Gravity::Uniform,
            rotation: true,
            centrifugal: true,
            options: Options::with_tolerances(1e-12, 1e-12),
        }
    }
}

/// A body dropped from rest: where and when it lands.
#[derive(Debug, Clone)]
pub struct Fall {
    /// Time of fall (s).
    pub time: f64,
    /// Eastward displacement at landing (m).
    pub east: f64,
    /// Northward displacement at landing (m; negative = south).
    pub north: f64,
    /// The unit's first-order eastward deflection (eq. 2.42) from the same height and latitude
    /// ([`Earth::eastward_deflection`], m), to compare with `east`.
    pub first_order_east: f64,
    /// The second-order equatorward deflection ([`Earth::southward_deflection`], m; uniform
    /// gravity), to compare with −`north`.
    pub second_order_south: f64,
    /// The trajectory `[x, y, z, vx, vy, vz]` (ENU) from release to landing, with dense output.
    pub solution: Solution<ParticleState>,
}

impl Fall {
    /// The state `[x, y, z, vx, vy, vz]` (ENU, m and m/s) at time `t` (s, in [0, time]) from
    /// the dense output (the model's `options.dense`); errors name `t`.
    pub fn state_at(&self, t: f64) -> Result<ParticleState> {
        check_finite("t", &[t])?;
        let s = self.solution.at(t)?;
        check_finite("t", &s).map(|_| s)
    }
}

/// A projectile's flight: where and when it lands.
#[derive(Debug, Clone)]
pub struct Flight {
    /// Time of flight (s).
    pub time: f64,
    /// Eastward displacement at landing (m).
    pub east: f64,
    /// Northward displacement at landing (m).
    pub north: f64,
    /// Horizontal distance from the launch point to the landing point (m).
    pub range: f64,
    /// Landing displacement along the launch azimuth (m).
    pub downrange: f64,
    /// Landing displacement perpendicular to the launch azimuth, positive to the right
    /// (seen from above, facing the launch direction) (m).
    pub drift: f64,
    /// The trajectory `[x, y, z, vx, vy, vz]` (ENU), with dense output.
    pub solution: Solution<ParticleState>,
}

impl Earth {
    /// The acceleration (m/s², ENU) of a free particle at `r` with velocity `v` in the local
    /// frame whose angular velocity is `w` (ENU), under `model`.
    #[inline]
    pub(crate) fn local_acceleration(
        &self,
        w: &Vec3,
        r: &Vec3,
        v: &Vec3,
        model: &FallModel,
    ) -> Vec3 {
        let mut a = match model.gravity {
            Gravity::Uniform => Vec3::new(0.0, 0.0, -self.g),
            Gravity::InverseSquare => {
                let rho = Vec3::new(r.x, r.y, r.z + self.radius);
                let d = rho.norm();
                -self.g * self.radius * self.radius / (d * d * d) * rho
            }
        };
        if model.rotation {
            a -= 2.0 * w.cross(v);
            if model.centrifugal {
                a -= w.cross(&w.cross(r));
            }
        }
        a
    }

    /// The height above the ground of a point of the local frame (m) under `model`.
    #[inline]
    fn height_above_ground(&self, r: &[f64], model: &FallModel) -> f64 {
        match model.gravity {
            Gravity::Uniform => r[2],
            Gravity::InverseSquare => {
                let rho = Vec3::new(r[0], r[1], r[2] + self.radius);
                rho.norm() - self.radius
            }
        }
    }

    /// Integrates a particle in the local frame at `latitude` from `(position, velocity)`
    /// until it reaches the ground (or `t_end`).
    fn fly(
        &self,
        latitude: f64,
        position: Vec3,
        velocity: Vec3,
        t_end: f64,
        model: &FallModel,
    ) -> Result<Solution<ParticleState>> {
        let w = self.omega_enu(latitude)?;
        let y0 = [
            position.x, position.y, position.z, velocity.x, velocity.y, velocity.z,
        ];
        let rhs = |_t: f64, y: &ParticleState, dy: &mut ParticleState| {
            let r = Vec3::new(y[0], y[1], y[2]);
            let v = Vec3::new(y[3], y[4], y[5]);
            let a = self.local_acceleration(&w, &r, &v, model);
            *dy = [y[3], y[4], y[5], a.x, a.y, a.z];
        };
        dop853_until(
            rhs,
            0.0,
            y0,
            t_end,
            &model.options,
            |_t, y: &ParticleState| self.height_above_ground(y, model),
            Crossing::Falling,
        )
    }

    /// Checks the arguments of [`Earth::drop`] before any work: `height` (finite, > 0) and
    /// `latitude` (in [−π/2, π/2]); the error names the argument.
    pub fn check_drop(height: f64, latitude: f64) -> Result<()> {
        check_positive("height", height)?;
        check_latitude(latitude)
    }

    /// Checks the arguments of [`Earth::projectile`] before any work: `speed` (finite, > 0),
    /// `elevation` (in [−π/2, π/2], > 0 from the ground), `azimuth` (finite), `height` (finite,
    /// ≥ 0) and `latitude` (in [−π/2, π/2]); the error names the argument.
    pub fn check_projectile(
        speed: f64,
        elevation: f64,
        azimuth: f64,
        latitude: f64,
        height: f64,
    ) -> Result<()> {
        check_positive("speed", speed)?;
        check_finite("elevation", &[elevation])?;
        check_finite("azimuth", &[azimuth])?;
        check_non_negative("height", height)?;
        check_latitude(latitude)?;
        if elevation.abs() > std::f64::consts::FRAC_PI_2 {
            return Err(Error::invalid(
                "elevation",
                format!("must be in [-pi/2, pi/2] rad, got {}", num(elevation)),
            ));
        }
        if height == 0.0 && elevation <= 0.0 {
            return Err(Error::invalid(
                "elevation",
                format!(
                    "must be > 0 for a launch from the ground, got {}",
                    num(elevation)
                ),
            ));
        }
        Ok(())
    }

    /// A body dropped from rest at `height` (m, > 0) above the ground at `latitude` (rad),
    /// integrated exactly (to the model's tolerance) in the rotating frame until it lands.
    ///
    /// To first order in ω the landing point is the unit's eq. 2.42 east
    /// ([`Earth::eastward_deflection`]); at second order it is also displaced towards the
    /// equator ([`Earth::southward_deflection`] for uniform gravity): both come with the fall.
    ///
    /// Errors name `height` (also for an integration that fails: the height sets its time
    /// and scale), `latitude`, and the model's `rtol`, `atol` and `max_steps`.
    pub fn drop(&self, height: f64, latitude: f64, model: &FallModel) -> Result<Fall> {
        Self::check_drop(height, latitude)?;
        let t0 = self.fall_time(height)?;
        let t_end = 4.0 * t0 + 1.0;
        // The integrator's end, start and time all come from the height.
        let sol = self
            .fly(
                latitude,
                Vec3::new(0.0, 0.0, height),
                Vec3::zeros(),
                t_end,
                model,
            )
            .map_err(|e| {
                e.renamed("t", "height")
                    .renamed("y0", "height")
                    .renamed("t_end", "height")
            })?;
        let hit = sol.event.as_ref().ok_or_else(|| {
            Error::diverged(
                "height",
                format!("the body did not land within t = {} s", num(t_end)),
            )
        })?;
        let (time, east, north) = (hit.t, hit.y[0], hit.y[1]);
        check_finite("height", &[time, east, north])?;
        Ok(Fall {
            time,
            east,
            north,
            first_order_east: self.eastward_deflection(height, latitude)?,
            second_order_south: self.southward_deflection(height, latitude)?,
            solution: sol,
        })
    }

    /// A projectile launched from `height` (m, ≥ 0) at `speed` (m/s, > 0), `elevation`
    /// (rad above the horizontal, in [−π/2, π/2]; > 0 from the ground) and `azimuth` (rad,
    /// clockwise from north: 0 north, π/2 east) at `latitude` (rad), flown until it lands.
    #[allow(clippy::too_many_arguments)]
    pub fn projectile(
        &self,
        speed: f64,
        elevation: f64,
        azimuth: f64,
        latitude: f64,
        height: f64,
        model: &FallModel,
    ) -> Result<Flight> {
        Self::check_projectile(speed, elevation, azimuth, latitude, height)?;
        let (sa, ca) = azimuth.sin_cos();
        let (se, ce) = elevation.sin_cos();
        let v0 = speed * Vec3::new(ce * sa, ce * ca, se);
        // A generous bound on the time of flight: 4 × the non-rotating one, plus a second.
        let vz = v0.z;
        // t = (v_z + √(v_z² + 2gh))/g, written so that nothing overflows before the end.
        let root = vz.hypot(std::f64::consts::SQRT_2 * self.g.sqrt() * height.sqrt());
        let t_flat = vz / self.g + root / self.g;
        let t_end = crate::error::finite_result("speed", "the time of flight", 4.0 * t_flat + 1.0)?;
        let mut model = *model;
        if height == 0.0 {
            // A launch from the ground starts on the event surface (height 0): the landing
            // is the next time the height falls to 0, which the integrator sees only if a
            // step ends while the body is still above the ground. A toss much shorter than
            // the first step (0.15 m/s lasts 0.015 s) would otherwise be stepped over whole
            // and reported as never coming down; steps of at most an eighth of the flat
            // flight time end above the ground (z(t) > 0 for 0 < t < t_flat).
            let peak = 0.5 * vz * (vz / self.g);
            if peak < f64::MIN_POSITIVE {
                return Err(Error::invalid(
                    "elevation",
                    format!(
                        "the toss is too low to integrate: its height v² sin² e / 2g = {} m \
                         is below the smallest normal double (speed {} m/s, elevation {} rad)",
                        num(peak),
                        num(speed),
                        num(elevation)
                    ),
                ));
            }
            model.options.max_step = model.options.max_step.min(t_flat / 8.0);
        }
        // The integrator's time and start come from the speed (the time of flight).
        let sol = self
            .fly(latitude, Vec3::new(0.0, 0.0, height), v0, t_end, &model)
            .map_err(|e| e.renamed("t", "speed").renamed("y0", "speed"))?;
        let hit = sol.event.as_ref().ok_or_else(|| {
            Error::invalid(
                "speed",
                format!(
                    "the projectile does not come down within {} s (is {} m/s an orbital speed?)",
                    num(t_end),
                    num(speed)
                ),
            )
        })?;
        let (east, north) = (hit.y[0], hit.y[1]);
        let (range, downrange, drift) = (
            east.hypot(north),
            east * sa + north * ca,
            east * ca - north * sa,
        );
        check_finite("speed", &[hit.t, east, north, range, downrange, drift])?;
        Ok(Flight {
            time: hit.t,
            east,
            north,
            range,
            downrange,
            drift,
            solution: sol,
        })
    }
}
