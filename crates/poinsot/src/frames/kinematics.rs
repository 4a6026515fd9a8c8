//! A moving frame at one instant, and the transformation of a particle's position, velocity
//! and acceleration between it and the fixed frame (eqs. 2.1–2.5, 2.14–2.28).

use crate::error::{check_finite, check_positive, Error, Result};
use crate::{Mat3, Vec3};

/// The state of a moving frame at one instant, relative to the fixed (inertial) frame.
///
/// Vectors are in fixed-frame components. `attitude` holds the moving axes (î, ĵ, k̂) as
/// columns in fixed-frame components, so that a vector with moving components `v` has fixed
/// components `attitude · v`; the identity (the default) means the axes are momentarily
/// aligned with the fixed axes, as in the unit. The particle's own (relative) quantities are
/// always in moving-frame components.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MovingFrame {
    /// Position R of the moving origin O (m).
    pub origin: Vec3,
    /// Velocity Ṙ of the moving origin (m/s).
    pub velocity: Vec3,
    /// Acceleration R̈ of the moving origin (m/s²).
    pub acceleration: Vec3,
    /// Angular velocity ω of the moving axes (rad/s).
    pub angular_velocity: Vec3,
    /// Angular acceleration ω̇ of the moving axes (rad/s²), the same seen from either frame (2.16).
    pub angular_acceleration: Vec3,
    /// Moving axes as columns, in fixed components (a proper rotation).
    pub attitude: Mat3,
}

impl Default for MovingFrame {
    fn default() -> Self {
        Self {
            origin: Vec3::zeros(),
            velocity: Vec3::zeros(),
            acceleration: Vec3::zeros(),
            angular_velocity: Vec3::zeros(),
            angular_acceleration: Vec3::zeros(),
            attitude: Mat3::identity(),
        }
    }
}

/// The fixed-frame view of a particle given in the moving frame (eqs. 2.20–2.23).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FixedMotion {
    /// r' = R + r (m, fixed components).
    pub position: Vec3,
    /// ṙ' = Ṙ + ṙ + ω × r (m/s, fixed components), eq. 2.20.
    pub velocity: Vec3,
    /// r̈' (m/s², fixed components), eq. 2.21: the sum of `terms`.
    pub acceleration: Vec3,
    /// The named terms of r̈'.
    pub terms: AccelerationTerms,
}

/// The terms of the fixed-frame acceleration (eq. 2.21 / 2.23), in fixed components.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AccelerationTerms {
    /// (d²r/dt²)_rot: the acceleration seen in the moving frame.
    pub relative: Vec3,
    /// R̈: the acceleration of the moving origin.
    pub origin: Vec3,
    /// 2 ω × (dr/dt)_rot: the Coriolis acceleration.
    pub coriolis: Vec3,
    /// ω × (ω × r): the centripetal acceleration (towards the axis, eq. 2.24).
    pub centripetal: Vec3,
    /// ω̇ × r: the Euler (azimuthal) acceleration.
    pub euler: Vec3,
}

/// Names the first of `(vector, argument)` that is not finite: every returned number is finite,
/// or the error names the input the overflowing term comes from.
fn check_vectors(items: &[(&Vec3, &str, &str)]) -> Result<()> {
    match items
        .iter()
        .find(|(v, _, _)| !v.iter().all(|c| c.is_finite()))
    {
        None => Ok(()),
        Some((_, argument, what)) => Err(crate::Error::invalid(
            *argument,
            format!("{what} overflows (is not representable as a finite number) for this value"),
        )),
    }
}

/// A particle's `position`, `velocity` and `acceleration` must be finite (the error names the
/// first that is not).
fn check_state(position: &Vec3, velocity: &Vec3, acceleration: &Vec3) -> Result<()> {
    check_finite("position", position.as_slice())?;
    check_finite("velocity", velocity.as_slice())?;
    check_finite("acceleration", acceleration.as_slice())
}

impl FixedMotion {
    /// Checks that every vector is finite; the error names the argument of
    /// [`MovingFrame::to_fixed`] whose term overflowed.
    pub fn check(&self) -> Result<()> {
        let t = &self.terms;
        check_vectors(&[
            (&self.position, "position", "the position r' = R + r"),
            (
                &t.centripetal,
                "position",
                "the centripetal acceleration ω × (ω × r)",
            ),
            (&t.euler, "position", "the Euler acceleration ω̇ × r"),
            (&t.coriolis, "velocity", "the Coriolis acceleration 2 ω × ṙ"),
            (
                &self.velocity,
                "velocity",
                "the velocity ṙ' = Ṙ + ṙ + ω × r",
            ),
            (&t.relative, "acceleration", "the relative acceleration"),
            (&self.acceleration, "acceleration", "the acceleration r̈'"),
        ])
    }
}

impl RelativeMotion {
    /// Checks that every vector is finite; the error names the argument of
    /// [`MovingFrame::to_moving`] whose term overflowed.
    pub fn check(&self) -> Result<()> {
        let t = &self.terms;
        check_vectors(&[
            (&self.position, "position", "the position r = r' − R"),
            (
                &t.centrifugal,
                "position",
                "the centrifugal acceleration −ω × (ω × r)",
            ),
            (&t.euler, "position", "the Euler acceleration −ω̇ × r"),
            (
                &self.velocity,
                "velocity",
                "the relative velocity ṙ' − Ṙ − ω × r",
            ),
            (
                &t.coriolis,
                "velocity",
                "the Coriolis acceleration −2 ω × ṙ",
            ),
            (&t.inertial, "acceleration", "the inertial acceleration"),
            (
                &self.acceleration,
                "acceleration",
                "the relative acceleration",
            ),
        ])
    }
}

impl AccelerationTerms {
    /// The sum of the terms, r̈'.
    pub fn total(&self) -> Vec3 {
        self.relative + self.origin + self.coriolis + self.centripetal + self.euler
    }
}

/// The moving-frame view of a particle given in the fixed frame (inverse of [`FixedMotion`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RelativeMotion {
    /// r = r' − R (m, moving components).
    pub position: Vec3,
    /// (dr/dt)_rot = ṙ' − Ṙ − ω × r (m/s, moving components).
    pub velocity: Vec3,
    /// (d²r/dt²)_rot (m/s², moving components): the sum of `terms`.
    pub acceleration: Vec3,
    /// The named terms of (d²r/dt²)_rot.
    pub terms: FictitiousTerms,
}

/// The terms of the moving-frame acceleration, (d²r/dt²)_rot = r̈' − R̈ − 2ω×ṙ − ω×(ω×r) − ω̇×r
/// (eqs. 2.5, 2.26, 2.30), in moving components: the true acceleration and the fictitious
/// accelerations (the fictitious forces per unit mass).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FictitiousTerms {
    /// r̈': the acceleration in the fixed frame (true force / mass).
    pub inertial: Vec3,
    /// −R̈: from the acceleration of the moving origin.
    pub translational: Vec3,
    /// −2 ω × (dr/dt)_rot.
    pub coriolis: Vec3,
    /// −ω × (ω × r), pointing away from the axis.
    pub centrifugal: Vec3,
    /// −ω̇ × r.
    pub euler: Vec3,
}

impl FictitiousTerms {
    /// The sum of the terms, (d²r/dt²)_rot.
    pub fn total(&self) -> Vec3 {
        self.inertial + self.translational + self.coriolis + self.centrifugal + self.euler
    }
}

/// The fictitious forces on a mass at rest or moving in the moving frame (eqs. 2.5, 2.26–2.28),
/// in moving components (N).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FictitiousForces {
    /// −m R̈ (eq. 2.5).
    pub translational: Vec3,
    /// −2 m ω × (dr/dt)_rot (eq. 2.26; 2.30 with its erratum).
    pub coriolis: Vec3,
    /// −m ω × (ω × r).
    pub centrifugal: Vec3,
    /// −m ω̇ × r.
    pub euler: Vec3,
}

impl FictitiousForces {
    /// The sum of the fictitious forces.
    pub fn total(&self) -> Vec3 {
        self.translational + self.coriolis + self.centrifugal + self.euler
    }
}

/// Tolerance on ‖AᵀA − 1‖ and |det A − 1| for an attitude to count as a rotation.
const ROTATION_TOLERANCE: f64 = 1e-9;

impl MovingFrame {
    /// A frame with the given state and axes aligned with the fixed axes. Errors name the
    /// first non-finite argument.
    pub fn new(
        origin: Vec3,
        velocity: Vec3,
        acceleration: Vec3,
        angular_velocity: Vec3,
        angular_acceleration: Vec3,
    ) -> Result<Self> {
        check_finite("origin", origin.as_slice())?;
        check_finite("velocity", velocity.as_slice())?;
        check_finite("acceleration", acceleration.as_slice())?;
        check_finite("angular_velocity", angular_velocity.as_slice())?;
        check_finite("angular_acceleration", angular_acceleration.as_slice())?;
        Ok(Self {
            origin,
            velocity,
            acceleration,
            angular_velocity,
            angular_acceleration,
            attitude: Mat3::identity(),
        })
    }

    /// A frame rotating at constant `omega` about the fixed origin (the unit's rotating
    /// system, eqs. 2.6–2.18).
    pub fn rotating(omega: Vec3) -> Result<Self> {
        Self::new(
            Vec3::zeros(),
            Vec3::zeros(),
            Vec3::zeros(),
            omega,
            Vec3::zeros(),
        )
    }

    /// The same frame with its axes turned to `attitude` (columns: the moving axes in fixed
    /// components). Errors (kind `InvalidRotation`, naming `attitude`) unless it is a proper
    /// rotation within 1e-9.
    pub fn with_attitude(mut self, attitude: Mat3) -> Result<Self> {
        check_finite("attitude", attitude.as_slice())?;
        let orth = (attitude.transpose() * attitude - Mat3::identity())
            .abs()
            .max();
        let det = attitude.determinant();
        if orth > ROTATION_TOLERANCE || (det - 1.0).abs() > ROTATION_TOLERANCE {
            return Err(Error::rotation(
                "attitude",
                format!("must be a proper rotation (|AᵀA − 1| = {orth:.3e}, det = {det:.12}; tolerance {ROTATION_TOLERANCE:e})"),
            ));
        }
        self.attitude = attitude;
        Ok(self)
    }

    /// ω in moving-frame components.
    pub fn angular_velocity_moving(&self) -> Vec3 {
        self.attitude.transpose() * self.angular_velocity
    }

    /// ω̇ in moving-frame components.
    pub fn angular_acceleration_moving(&self) -> Vec3 {
        self.attitude.transpose() * self.angular_acceleration
    }

    /// The fixed-frame position, velocity and acceleration of a particle whose position,
    /// velocity and acceleration relative to the moving frame (moving components) are
    /// `position`, `velocity`, `acceleration` (eqs. 2.19–2.23; 2.1–2.3 when ω = 0).
    ///
    /// r' = R + r;  ṙ' = Ṙ + ṙ + ω×r;  r̈' = R̈ + r̈ + 2ω×ṙ + ω×(ω×r) + ω̇×r.
    ///
    /// Errors name `position`, `velocity` or `acceleration`: not finite, or a term they give
    /// beyond the doubles ([`FixedMotion::check`]).
    pub fn to_fixed(
        &self,
        position: &Vec3,
        velocity: &Vec3,
        acceleration: &Vec3,
    ) -> Result<FixedMotion> {
        let m = self.fixed_motion_unchecked(position, velocity, acceleration);
        if m.check().is_err() {
            // A non-finite argument makes some output non-finite: name it before the overflow.
            check_state(position, velocity, acceleration)?;
            m.check()?;
        }
        Ok(m)
    }

    /// [`MovingFrame::to_fixed`] without the checks.
    fn fixed_motion_unchecked(
        &self,
        position: &Vec3,
        velocity: &Vec3,
        acceleration: &Vec3,
    ) -> FixedMotion {
        let a = &self.attitude;
        let (r, v, acc) = (a * position, a * velocity, a * acceleration);
        let w = &self.angular_velocity;
        let wxr = w.cross(&r);
        let terms = AccelerationTerms {
            relative: acc,
            origin: self.acceleration,
            coriolis: 2.0 * w.cross(&v),
            centripetal: w.cross(&wxr),
            euler: self.angular_acceleration.cross(&r),
        };
        FixedMotion {
            position: self.origin + r,
            velocity: self.velocity + v + wxr,
            acceleration: terms.total(),
            terms,
        }
    }

    /// The moving-frame position, velocity and acceleration (moving components) of a particle
    /// whose fixed-frame ones are given: the inverse of [`MovingFrame::to_fixed`]. Errors name
    /// `position`, `velocity` or `acceleration` ([`RelativeMotion::check`]).
    pub fn to_moving(
        &self,
        position: &Vec3,
        velocity: &Vec3,
        acceleration: &Vec3,
    ) -> Result<RelativeMotion> {
        let m = self.relative_motion_unchecked(position, velocity, acceleration);
        if m.check().is_err() {
            // A non-finite argument makes some output non-finite: name it before the overflow.
            check_state(position, velocity, acceleration)?;
            m.check()?;
        }
        Ok(m)
    }

    /// [`MovingFrame::to_moving`] without the checks.
    fn relative_motion_unchecked(
        &self,
        position: &Vec3,
        velocity: &Vec3,
        acceleration: &Vec3,
    ) -> RelativeMotion {
        let at = self.attitude.transpose();
        let w = &self.angular_velocity;
        let r = position - self.origin;
        let wxr = w.cross(&r);
        let v = velocity - self.velocity - wxr;
        let terms = FictitiousTerms {
            inertial: at * acceleration,
            translational: -(at * self.acceleration),
            coriolis: -(at * (2.0 * w.cross(&v))),
            centrifugal: -(at * w.cross(&wxr)),
            euler: -(at * self.angular_acceleration.cross(&r)),
        };
        RelativeMotion {
            position: at * r,
            velocity: at * v,
            acceleration: terms.total(),
            terms,
        }
    }

    /// The fictitious forces (moving components, N) on a particle of `mass` (kg) at
    /// `position` moving with `velocity` relative to the frame (moving components).
    /// Errors name `mass` (must be > 0), `position` or `velocity` (must be finite).
    pub fn fictitious_forces(
        &self,
        mass: f64,
        position: &Vec3,
        velocity: &Vec3,
    ) -> Result<FictitiousForces> {
        check_positive("mass", mass)?;
        check_finite("position", position.as_slice())?;
        check_finite("velocity", velocity.as_slice())?;
        let f = self.fictitious_forces_unchecked(mass, position, velocity);
        check_vectors(&[
            (&f.translational, "mass", "the translational force −m R̈"),
            (
                &f.centrifugal,
                "position",
                "the centrifugal force −m ω × (ω × r)",
            ),
            (&f.euler, "position", "the Euler force −m ω̇ × r"),
            (&f.coriolis, "velocity", "the Coriolis force −2 m ω × ṙ"),
        ])?;
        Ok(f)
    }

    /// [`MovingFrame::fictitious_forces`] without the argument checks (the hot path of the
    /// particle integrator).
    #[inline]
    pub fn fictitious_forces_unchecked(
        &self,
        mass: f64,
        position: &Vec3,
        velocity: &Vec3,
    ) -> FictitiousForces {
        let at = self.attitude.transpose();
        let w = at * self.angular_velocity;
        let wd = at * self.angular_acceleration;
        FictitiousForces {
            translational: -mass * (at * self.acceleration),
            coriolis: -2.0 * mass * w.cross(velocity),
            centrifugal: -mass * w.cross(&w.cross(position)),
            euler: -mass * wd.cross(position),
        }
    }
}
