//! The torque-free rigid body over a grid of moments and initial angular velocities (the
//! unit's 2.67–2.97 solved exactly): regime, period, flip interval, the Jacobi parameter, the
//! conserved T and L, and the stability of steady rotation about each principal axis.

use super::grid::{Grid, Param};
use crate::analytic::{
    axis_stability, check_moments, check_omega, check_omega_range, AxisStability, FreeRegime,
    FreeRigidBody, Stability,
};
use crate::error::{check_finite, check_positive, Error, Result};
use crate::Vec3;

/// The keywords of [`free_body`]: `moments` (the principal moments, 3 numbers), and the
/// initial angular velocity either as `omega0` (body components, 3 numbers) or by its size and
/// direction, `omega_magnitude` (rad/s), `omega_polar` (rad, the angle from body axis 3) and
/// `omega_azimuth` (rad, from body axis 1 towards axis 2):
/// ω₀ = |ω₀| (sin θ cos φ, sin θ sin φ, cos θ).
pub const FREE_BODY_KEYWORDS: [&str; 5] = [
    "moments",
    "omega0",
    "omega_magnitude",
    "omega_polar",
    "omega_azimuth",
];

/// Every [`FreeRegime`], in the order of their codes in a sweep.
pub const FREE_REGIMES: [FreeRegime; 5] = [
    FreeRegime::Steady,
    FreeRegime::Symmetric,
    FreeRegime::AboutMaxAxis,
    FreeRegime::AboutMinAxis,
    FreeRegime::Separatrix,
];

/// Every [`Stability`], in the order of their codes in a sweep.
pub const STABILITIES: [Stability; 3] =
    [Stability::Stable, Stability::Unstable, Stability::Neutral];

/// A regime's code in a sweep: its index in [`FREE_REGIMES`].
pub fn regime_code(regime: FreeRegime) -> u8 {
    match regime {
        FreeRegime::Steady => 0,
        FreeRegime::Symmetric => 1,
        FreeRegime::AboutMaxAxis => 2,
        FreeRegime::AboutMinAxis => 3,
        FreeRegime::Separatrix => 4,
    }
}

/// A stability's code in a sweep: its index in [`STABILITIES`].
pub fn stability_code(stability: Stability) -> u8 {
    match stability {
        Stability::Stable => 0,
        Stability::Unstable => 1,
        Stability::Neutral => 2,
    }
}

/// What a sweep of the free body gives at one point: the quantities of [`FreeRigidBody`] (with
/// the identity as initial attitude) and [`axis_stability`] at the spin |ω₀|.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FreeBodyPoint {
    /// ω₀ in body components (rad/s): as given, or from its size and direction.
    pub omega0: [f64; 3],
    /// Which motion it is.
    pub regime: FreeRegime,
    /// The period of ω(t) in the body (s), infinite when ω is constant or on the separatrix.
    pub period: f64,
    /// Half the period: the time between reversals of ω along the intermediate axis (s).
    pub flip_interval: f64,
    /// The Jacobi parameter m = k².
    pub parameter: f64,
    /// λ, the rate of the Jacobi argument (rad/s).
    pub frequency: f64,
    /// The principal axis (index into `moments`) ω circles, `None` when steady or on the
    /// separatrix.
    pub pole_axis: Option<usize>,
    /// T = ½ ω·I·ω (J).
    pub energy: f64,
    /// L = I ω₀ (kg·m²/s; space components = body components at t = 0).
    pub angular_momentum: [f64; 3],
    /// The stability of steady rotation at |ω₀| about each principal axis (the rate in 1/s).
    pub axis_stability: [AxisStability; 3],
}

/// How ω₀ is given.
enum Omega<'a> {
    Components(Param<'a>),
    Spherical {
        magnitude: Param<'a>,
        polar: Param<'a>,
        azimuth: Param<'a>,
    },
}

struct Inputs<'a> {
    moments: Param<'a>,
    omega: Omega<'a>,
}

impl<'a> Inputs<'a> {
    fn of(grid: &Grid<'a>) -> Result<Self> {
        grid.check_keywords("free_body", &FREE_BODY_KEYWORDS)?;
        let spherical = ["omega_magnitude", "omega_polar", "omega_azimuth"];
        let omega = if grid.has("omega0") {
            if let Some(k) = spherical.iter().find(|k| grid.has(k)) {
                return Err(Error::invalid(
                    *k,
                    "give omega0, or its size and direction (omega_magnitude, omega_polar, omega_azimuth), not both",
                ));
            }
            Omega::Components(grid.required("omega0", 3)?)
        } else if spherical.iter().any(|k| grid.has(k)) {
            Omega::Spherical {
                magnitude: grid.required("omega_magnitude", 1)?,
                polar: grid.required("omega_polar", 1)?,
                azimuth: grid.required("omega_azimuth", 1)?,
            }
        } else {
            return Err(Error::invalid(
                "omega0",
                "must be given, or its size and direction (omega_magnitude, omega_polar, omega_azimuth)",
            ));
        };
        Ok(Self {
            moments: grid.required("moments", 3)?,
            omega,
        })
    }

    /// The moments and ω₀ at `p`, checked as [`FreeRigidBody::new`] checks them.
    fn start(&self, p: usize) -> Result<([f64; 3], [f64; 3])> {
        let moments = self.moments.vec3(p);
        check_moments(&moments)?;
        let w = match &self.omega {
            Omega::Components(w) => {
                let w = w.vec3(p);
                check_omega("omega0", &Vec3::from(w))?;
                check_omega_range("omega0", &w)?;
                w
            }
            Omega::Spherical {
                magnitude,
                polar,
                azimuth,
            } => {
                let (size, theta, phi) = (magnitude.scalar(p), polar.scalar(p), azimuth.scalar(p));
                check_positive("omega_magnitude", size)?;
                if !(theta.is_finite() && (0.0..=std::f64::consts::PI).contains(&theta)) {
                    return Err(Error::invalid(
                        "omega_polar",
                        format!("must be finite and in [0, pi] (the angle from body axis 3), got {theta}"),
                    ));
                }
                check_finite("omega_azimuth", &[phi])?;
                let (st, ct) = theta.sin_cos();
                let (sp, cp) = phi.sin_cos();
                let w = [size * st * cp, size * st * sp, size * ct];
                check_omega_range("omega0", &w)
                    .map_err(|e| e.renamed("omega0", "omega_magnitude"))?;
                w
            }
        };
        Ok((moments, w))
    }

    /// |ω₀| at `p` (rad/s), without overflow on the way.
    fn spin(&self, p: usize, w: &[f64; 3]) -> f64 {
        match &self.omega {
            Omega::Spherical { magnitude, .. } => magnitude.scalar(p),
            Omega::Components(_) => {
                let big = w.iter().fold(0.0f64, |a, v| a.max(v.abs()));
                big * w.iter().map(|v| (v / big) * (v / big)).sum::<f64>().sqrt()
            }
        }
    }

    fn argument(&self) -> &'static str {
        match self.omega {
            Omega::Components(_) => "omega0",
            Omega::Spherical { .. } => "omega_magnitude",
        }
    }
}

/// Checks every point of a sweep of the free body as [`FreeRigidBody::new`] checks its
/// arguments (and `omega_magnitude` > 0, `omega_polar` in [0, π], `omega_azimuth` finite),
/// without solving any motion. Errors name the keyword and the first point at fault, a keyword
/// not in [`FREE_BODY_KEYWORDS`], `moments` or ω₀ missing, or ω₀ given both ways.
pub fn check_free_body(grid: &Grid<'_>) -> Result<()> {
    let inputs = Inputs::of(grid)?;
    grid.validate(|p| inputs.start(p).map(|_| ()))
}

/// The torque-free body at every point of `grid` ([`FreeRigidBody::new`] with the identity
/// attitude), in row-major order, computed in parallel after [`check_free_body`] and the memory
/// budget passed; stoppable through [`crate::control`]. A point whose period, energy or
/// momentum leaves the double range stops the sweep with that error (naming `omega0` or
/// `omega_magnitude`), located.
pub fn free_body(grid: &Grid<'_>) -> Result<Vec<FreeBodyPoint>> {
    let inputs = Inputs::of(grid)?;
    grid.check_memory(std::mem::size_of::<FreeBodyPoint>())?;
    grid.validate(|p| inputs.start(p).map(|_| ()))?;
    let argument = inputs.argument();
    grid.compute(|p| {
        let (moments, w) = inputs.start(p)?;
        let point = || -> Result<FreeBodyPoint> {
            let body = FreeRigidBody::new(moments, Vec3::from(w), None)?;
            let l = body.angular_momentum()?;
            Ok(FreeBodyPoint {
                omega0: w,
                regime: body.regime(),
                period: body.period()?,
                flip_interval: body.flip_interval()?,
                parameter: body.parameter(),
                frequency: body.frequency()?,
                pole_axis: body.pole_axis(),
                energy: body.energy()?,
                angular_momentum: [l.x, l.y, l.z],
                axis_stability: axis_stability(moments, inputs.spin(p, &w))
                    .map_err(|e| e.renamed("spin", "omega0"))?,
            })
        };
        point().map_err(|e| e.renamed("omega0", argument))
    })
}
