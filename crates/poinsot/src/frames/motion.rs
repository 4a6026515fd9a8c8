//! Time-dependent moving frames: the state of the frame as a function of time.

use super::kinematics::MovingFrame;
use crate::error::{Error, Result};
use crate::{Mat3, Vec3};

/// The motion of a moving frame: its state (origin, velocity, acceleration, ω, ω̇, attitude)
/// at any time `t`, in fixed-frame components.
///
/// Implementations must be consistent (Ṙ the derivative of R, and the attitude A obeying
/// `Ȧ = [ω]× A`) for the moving-frame and fixed-frame descriptions to agree. Implemented for
/// [`SteadyMotion`] and for any closure `Fn(f64) -> MovingFrame`.
pub trait FrameMotion {
    /// The frame's state at time `t`.
    fn at(&self, t: f64) -> MovingFrame;

    /// What the moving-frame equation of a particle needs at time `t`, in moving components:
    /// (R̈, ω, ω̇). The default takes them from [`FrameMotion::at`]; implementations may
    /// override it with a cheaper equivalent.
    fn moving_components(&self, t: f64) -> (Vec3, Vec3, Vec3) {
        let f = self.at(t);
        let at = f.attitude.transpose();
        (
            at * f.acceleration,
            at * f.angular_velocity,
            at * f.angular_acceleration,
        )
    }
}

impl<F: Fn(f64) -> MovingFrame> FrameMotion for F {
    fn at(&self, t: f64) -> MovingFrame {
        self(t)
    }
}

/// A frame whose origin moves with constant acceleration and whose axes turn about a fixed
/// axis with constant angular acceleration, starting at `t = 0` from a given [`MovingFrame`]
/// state:
///
/// R(t) = R₀ + Ṙ₀ t + ½ R̈ t²,  ω(t) = ω₀ + ω̇ t,  A(t) = Rot(n̂, |ω₀| t + ½ (n̂·ω̇) t²) A₀,
///
/// with n̂ the fixed axis (ω̇ must be parallel to ω₀ so that the axis stays fixed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyMotion {
    initial: MovingFrame,
    axis: Vec3,
    rate: f64,
    rate_dot: f64,
    /// A₀ᵀω₀ and A₀ᵀω̇: ω and ω̇ in moving components (constant directions).
    w_moving: Vec3,
    wd_moving: Vec3,
    /// Whether the origin accelerates (R̈ ≠ 0).
    accelerating: bool,
}

/// Relative tolerance on |ω₀ × ω̇| / (|ω₀| |ω̇|) for the two to count as parallel.
const PARALLEL_TOLERANCE: f64 = 1e-12;

impl SteadyMotion {
    /// The steady motion starting from `initial` at `t = 0`. Errors name
    /// `angular_acceleration` if it is not parallel to the angular velocity.
    pub fn new(initial: MovingFrame) -> Result<Self> {
        let w = initial.angular_velocity;
        let wd = initial.angular_acceleration;
        let (nw, nwd) = (w.norm(), wd.norm());
        if nw > 0.0 && nwd > 0.0 && w.cross(&wd).norm() > PARALLEL_TOLERANCE * nw * nwd {
            return Err(Error::invalid(
                "angular_acceleration",
                "must be parallel to angular_velocity for a steady frame (fixed rotation axis); give the frame as a function of time instead",
            ));
        }
        let axis = if nw > 0.0 {
            w / nw
        } else if nwd > 0.0 {
            wd / nwd
        } else {
            Vec3::z()
        };
        let a0t = initial.attitude.transpose();
        Ok(Self {
            initial,
            axis,
            rate: axis.dot(&w),
            rate_dot: axis.dot(&wd),
            w_moving: a0t * w,
            wd_moving: a0t * wd,
            accelerating: initial.acceleration != Vec3::zeros(),
        })
    }

    /// The state at `t = 0`.
    pub fn initial(&self) -> &MovingFrame {
        &self.initial
    }

    /// The state at time `t` (s), checked: `t` must be finite, and every number of the state
    /// (origin, velocity, ω, attitude) finite; otherwise the error names `t` (the frame
    /// was valid at t = 0: only the time carried it out of the range of doubles, e.g. the
    /// origin ½ R̈ t² at t = 1e200).
    pub fn state_at(&self, t: f64) -> Result<MovingFrame> {
        crate::error::check_finite("t", &[t])?;
        let f = FrameMotion::at(self, t);
        let parts = [
            f.origin.as_slice(),
            f.velocity.as_slice(),
            f.acceleration.as_slice(),
            f.angular_velocity.as_slice(),
            f.angular_acceleration.as_slice(),
            f.attitude.as_slice(),
        ];
        for (name, values) in [
            "origin",
            "velocity",
            "acceleration",
            "angular velocity",
            "angular acceleration",
            "attitude",
        ]
        .iter()
        .zip(parts)
        {
            if !values.iter().all(|x| x.is_finite()) {
                return Err(Error::invalid(
                    "t",
                    format!(
                        "the frame's {name} at t = {} s is not representable as finite numbers \
                         (it overflows)",
                        crate::error::num(t)
                    ),
                ));
            }
        }
        Ok(f)
    }
}

/// The rotation by `angle` about the unit `axis` (Rodrigues' formula), active.
pub(crate) fn axis_angle(axis: &Vec3, angle: f64) -> Mat3 {
    let k = axis.cross_matrix();
    Mat3::identity() + angle.sin() * k + (1.0 - angle.cos()) * (k * k)
}

impl FrameMotion for SteadyMotion {
    /// ω and ω̇ lie along the fixed axis, which the rotation leaves alone, so their moving
    /// components are A₀ᵀω(t) and A₀ᵀω̇; only R̈ needs the attitude at `t`.
    #[inline]
    fn moving_components(&self, t: f64) -> (Vec3, Vec3, Vec3) {
        let f = &self.initial;
        let w = self.w_moving + self.wd_moving * t;
        let wd = self.wd_moving;
        let acc = if !self.accelerating {
            Vec3::zeros()
        } else {
            let angle = self.rate * t + 0.5 * self.rate_dot * t * t;
            (axis_angle(&self.axis, angle) * f.attitude).transpose() * f.acceleration
        };
        (acc, w, wd)
    }

    fn at(&self, t: f64) -> MovingFrame {
        let f = &self.initial;
        let angle = self.rate * t + 0.5 * self.rate_dot * t * t;
        MovingFrame {
            origin: f.origin + f.velocity * t + 0.5 * f.acceleration * t * t,
            velocity: f.velocity + f.acceleration * t,
            acceleration: f.acceleration,
            angular_velocity: f.angular_velocity + f.angular_acceleration * t,
            angular_acceleration: f.angular_acceleration,
            attitude: axis_angle(&self.axis, angle) * f.attitude,
        }
    }
}
