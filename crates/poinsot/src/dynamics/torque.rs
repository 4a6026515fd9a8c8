//! Torques on a rigid body: none, constant in the body, constant in space, gravity about a
//! fixed pivot, the gravity-gradient torque of a circular orbit, and user models.

use crate::error::{check_finite, Error, Result};
use crate::{Mat3, Vec3};

/// What a torque model may depend on, at one instant (all in the body axes B the user gave).
#[derive(Debug, Clone, Copy)]
pub struct TorqueContext<'a> {
    /// Time (s).
    pub t: f64,
    /// Angular velocity, body components (rad/s).
    pub omega: &'a Vec3,
    /// Attitude: the rotation matrix R taking body components to space components.
    pub attitude: &'a Mat3,
    /// The inertia tensor in body axes (kg·m²).
    pub inertia: &'a Mat3,
}

/// A torque model: the torque on the body, in body components (N·m), at a given state.
pub trait TorqueModel {
    /// The torque N in body components (N·m).
    fn torque(&mut self, ctx: &TorqueContext<'_>) -> Vec3;
    /// Whether the torque may depend on ω (then the Lie–Poisson splitting cannot be used).
    fn depends_on_omega(&self) -> bool {
        true
    }
    /// Whether the torque depends on the attitude (if not, the integrators skip computing R).
    fn depends_on_attitude(&self) -> bool {
        true
    }
    /// Whether the torque is identically zero (torque-free: the exact flow applies).
    fn is_zero(&self) -> bool {
        false
    }
    /// The potential energy V (J) whose gradient gives the torque, for conservative models
    /// (gravity); 0 otherwise.
    fn potential(&self, _ctx: &TorqueContext<'_>) -> f64 {
        0.0
    }
    /// A rate (rad/s) the default step must resolve besides the body's own (an orbit's mean
    /// motion); 0 by default.
    fn orbit_rate(&self) -> f64 {
        0.0
    }
}

/// The built-in torque models.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Torque {
    /// No torque: the free rigid body.
    #[default]
    None,
    /// A constant torque in body components (N·m), like a thruster fixed to the body.
    Body(Vec3),
    /// A constant torque in space components (N·m): `N_body = Rᵀ N_space`.
    Space(Vec3),
    /// Gravity on a body turning about a fixed pivot at the origin, its centre of mass at
    /// distance l along body axis 3 and gravity −g along the space Z axis (the unit's heavy-top
    /// convention): `N = (l e₃) × (−m g Z)` in body components, `N_body = m g l (Rᵀ Z) × e₃`,
    /// with potential `V = m g l (R e₃)·Z = m g l cos θ`. `mgl` is m·g·l (J); the inertia must
    /// be taken about the pivot.
    Gravity {
        /// m g l (J).
        mgl: f64,
    },
    /// The gravity-gradient torque on a satellite whose centre of mass follows a circular
    /// orbit of mean motion n = (μ/r³)^½ in the space XY plane, at r̂(t) = (cos nt, sin nt, 0):
    /// `N_body = 3 n² r̂_b × (I·r̂_b)` with `r̂_b = Rᵀ r̂` (Hughes, *Spacecraft Attitude
    /// Dynamics*, §8.2). The attitude is relative to the inertial frame.
    GravityGradient {
        /// Orbital mean motion n (rad/s).
        mean_motion: f64,
    },
}

/// The kind of a torque, by the name the front ends use: a built-in [`Torque`] or a user's
/// function (a [`TorqueModel`] of the binding: a Python callable).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TorqueKind {
    /// [`Torque::None`].
    None,
    /// [`Torque::Body`].
    Body,
    /// [`Torque::Space`].
    Space,
    /// [`Torque::Gravity`].
    Gravity,
    /// [`Torque::GravityGradient`].
    GravityGradient,
    /// A user's function of time and state, the binding's own [`TorqueModel`].
    Callback,
}

impl std::str::FromStr for TorqueKind {
    type Err = Error;
    /// `"none"`, `"body"`, `"space"`, `"gravity"`, `"gravity_gradient"` or `"callback"`; the
    /// error names `torque`.
    fn from_str(name: &str) -> Result<Self> {
        Ok(match name {
            "none" => TorqueKind::None,
            "body" => TorqueKind::Body,
            "space" => TorqueKind::Space,
            "gravity" => TorqueKind::Gravity,
            "gravity_gradient" => TorqueKind::GravityGradient,
            "callback" => TorqueKind::Callback,
            _ => {
                return Err(Error::invalid(
                    "torque",
                    format!(
                        "must be none, body, space, gravity, gravity_gradient or callback, got \
                         {name:?}"
                    ),
                ))
            }
        })
    }
}

impl TorqueKind {
    /// The built-in torque of this kind with the constant `vector` (N·m; body and space) or
    /// `scalar` (m g l, J; the mean motion, rad/s), checked ([`Torque::validate`]); a callback
    /// is not built in: its error names `torque` and asks for the function.
    pub fn torque(self, vector: Vec3, scalar: f64) -> Result<Torque> {
        let t = match self {
            TorqueKind::None => Torque::None,
            TorqueKind::Body => Torque::Body(vector),
            TorqueKind::Space => Torque::Space(vector),
            TorqueKind::Gravity => Torque::Gravity { mgl: scalar },
            TorqueKind::GravityGradient => Torque::GravityGradient {
                mean_motion: scalar,
            },
            TorqueKind::Callback => {
                return Err(Error::invalid(
                    "torque",
                    "a callback torque needs a callable",
                ))
            }
        };
        t.validate()?;
        Ok(t)
    }
}

impl Torque {
    /// Checks the parameters; errors name `torque`, `mgl` or `mean_motion`.
    pub fn validate(&self) -> Result<()> {
        match self {
            Torque::None => Ok(()),
            Torque::Body(v) | Torque::Space(v) => check_finite("torque", v.as_slice()),
            Torque::Gravity { mgl } => check_finite("mgl", &[*mgl]),
            Torque::GravityGradient { mean_motion } => {
                if mean_motion.is_finite() && *mean_motion >= 0.0 {
                    Ok(())
                } else {
                    Err(Error::invalid(
                        "mean_motion",
                        format!("must be finite and >= 0, got {mean_motion}"),
                    ))
                }
            }
        }
    }
}

impl TorqueModel for Torque {
    #[inline]
    fn torque(&mut self, ctx: &TorqueContext<'_>) -> Vec3 {
        match *self {
            Torque::None => Vec3::zeros(),
            Torque::Body(n) => n,
            Torque::Space(n) => ctx.attitude.transpose() * n,
            Torque::Gravity { mgl } => {
                // (Rᵀ Z) × e₃ = (Z_b.y, −Z_b.x, 0), Z_b the third row of R.
                let r = ctx.attitude;
                mgl * Vec3::new(r[(2, 1)], -r[(2, 0)], 0.0)
            }
            Torque::GravityGradient { mean_motion } => {
                let (s, c) = (mean_motion * ctx.t).sin_cos();
                let rb = ctx.attitude.transpose() * Vec3::new(c, s, 0.0);
                3.0 * mean_motion * mean_motion * rb.cross(&(ctx.inertia * rb))
            }
        }
    }
    fn depends_on_omega(&self) -> bool {
        false
    }
    fn depends_on_attitude(&self) -> bool {
        matches!(
            self,
            Torque::Space(_) | Torque::Gravity { .. } | Torque::GravityGradient { .. }
        )
    }
    fn is_zero(&self) -> bool {
        matches!(self, Torque::None)
    }
    fn potential(&self, ctx: &TorqueContext<'_>) -> f64 {
        match *self {
            Torque::Gravity { mgl } => mgl * ctx.attitude[(2, 2)],
            _ => 0.0,
        }
    }
    fn orbit_rate(&self) -> f64 {
        match *self {
            Torque::GravityGradient { mean_motion } => mean_motion,
            _ => 0.0,
        }
    }
}
