//! The inertia of a body for the equations of motion: principal moments, or a full tensor
//! with its principal frame.

use crate::error::{Error, Result};
use crate::inertia::{check_inertia, check_moments, principal};
use crate::rotation::{matrix_to_quaternion_any_sign, row_major, Quaternion};
use crate::{Mat3, Vec3};

/// A body's inertia about its fixed point (or centre of mass), for Euler's equations.
///
/// The integrators work in the **principal frame** P, where Euler's equations take the unit's
/// form 2.72; a body given by a full tensor `I_B` in its own body axes B is carried there by
/// `I_B = A diag(I₁, I₂, I₃) Aᵀ` (`A` the principal axes as columns, a proper rotation):
/// `ω_P = Aᵀ ω_B`, `R_P = R_B A`. Results are returned in B.
///
/// ```
/// use poinsot::dynamics::BodyInertia;
/// use poinsot::{Mat3, Vec3};
/// // A body given by a full tensor in its own axes (products of inertia negated).
/// let tensor = Mat3::new(2.0, -0.5, 0.0, -0.5, 2.0, 0.0, 0.0, 0.0, 3.0);
/// let body = BodyInertia::from_tensor(&tensor)?;
/// assert!((body.min_moment() - 1.5).abs() < 1e-15 && (body.max_moment() - 3.0).abs() < 1e-15);
/// let w = Vec3::new(1.0, 0.0, 0.0);
/// assert_eq!(body.angular_momentum(&w), Vec3::new(2.0, -0.5, 0.0)); // L = I·ω
/// assert_eq!(body.kinetic_energy(&w), 1.0); // T = ½ ω·I·ω
/// // Moments that break the triangle inequality are refused.
/// assert_eq!(BodyInertia::from_moments([1.0, 1.0, 3.0]).unwrap_err().argument, "moments");
/// # Ok::<(), poinsot::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyInertia {
    /// The tensor in body axes B (kg·m²).
    pub tensor: Mat3,
    /// The principal moments (kg·m²), in the order of the columns of `axes`.
    pub moments: [f64; 3],
    /// The principal axes as the columns of a proper rotation A (identity for a body given by
    /// its principal moments).
    pub axes: Mat3,
    /// The quaternion of `axes`.
    pub(crate) axes_q: Quaternion,
    /// Whether B is already the principal frame (`axes` is the identity).
    pub principal: bool,
}

impl BodyInertia {
    /// A body whose axes are principal, with moments `moments` (kg·m², > 0, obeying the
    /// triangle inequality, any order); errors name `moments`.
    pub fn from_moments(moments: [f64; 3]) -> Result<Self> {
        check_moments(&moments)?;
        Ok(Self {
            tensor: Mat3::from_diagonal(&Vec3::from(moments)),
            moments,
            axes: Mat3::identity(),
            axes_q: [1.0, 0.0, 0.0, 0.0],
            principal: true,
        })
    }

    /// A body with inertia tensor `tensor` (kg·m²) in its body axes (checked as
    /// [`check_inertia`], and positive definite); errors name `body`, the argument of the runs
    /// ([`super::simulate()`], Python's `simulate(body, ...)`) whose inertia it is.
    pub fn from_tensor(tensor: &Mat3) -> Result<Self> {
        let t = check_inertia("body", tensor)?;
        let diagonal = t[(0, 1)] == 0.0 && t[(0, 2)] == 0.0 && t[(1, 2)] == 0.0;
        if diagonal {
            return Self::from_moments([t[(0, 0)], t[(1, 1)], t[(2, 2)]])
                .map_err(|e| Error::inertia("body", e.message));
        }
        let p = principal(&t, 0.0);
        check_moments(&p.moments).map_err(|e| Error::inertia("body", e.message))?;
        Ok(Self {
            tensor: t,
            moments: p.moments,
            axes: p.axes,
            axes_q: matrix_to_quaternion_any_sign(&row_major(&p.axes)),
            principal: false,
        })
    }

    /// L = I·ω (2.63) in body axes (kg·m²/s) for ω in body axes (rad/s).
    pub fn angular_momentum(&self, omega: &Vec3) -> Vec3 {
        self.tensor * omega
    }

    /// T = ½ ω·I·ω (2.64) (J).
    pub fn kinetic_energy(&self, omega: &Vec3) -> f64 {
        0.5 * omega.dot(&(self.tensor * omega))
    }

    /// The smallest principal moment (kg·m²).
    pub fn min_moment(&self) -> f64 {
        self.moments.iter().copied().fold(f64::INFINITY, f64::min)
    }

    /// The largest principal moment (kg·m²).
    pub fn max_moment(&self) -> f64 {
        self.moments.iter().copied().fold(0.0, f64::max)
    }
}
