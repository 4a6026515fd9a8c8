//! Mass properties of a rigid body (mass, centre of mass, inertia about the centre of mass),
//! their composition, and the angular momentum, kinetic energy and holding torque of a body
//! turning with angular velocity ω (the unit's 2.43–2.64).

use crate::error::{check_finite, check_positive, Error, Result};
use crate::inertia::tensor::{self, Principal, TopKind};
use crate::{Mat3, Vec3};

/// Tolerance of the rotation check of [`MassProperties::rotated`]: `|RᵀR − 1|` entrywise and
/// `|det R − 1|` (a rotation matrix that went through text or single precision passes).
pub const ROTATION_TOL: f64 = 1e-9;

/// The mass properties of a rigid body.
///
/// - `mass` (kg) is finite and `> 0`;
/// - `center_of_mass` (m) is in the body's reference axes;
/// - `inertia` (kg·m²) is the inertia tensor **about the centre of mass**, expressed in the same
///   axes, with the unit's sign convention (products negated, `I_xy = −Σ m x y`, 2.46–2.50) so
///   that `L = I·ω` (2.63). It is symmetric and satisfies the triangle inequality
///   (checked by [`tensor::check_inertia`] on construction).
///
/// The fields are private so that every value of this type is a valid body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MassProperties {
    mass: f64,
    center_of_mass: Vec3,
    inertia: Mat3,
}

impl MassProperties {
    /// A body of mass `mass` (kg) with centre of mass `center_of_mass` (m) and inertia tensor
    /// `inertia` (kg·m², about the centre of mass). Errors name `mass`, `center_of_mass` or
    /// `inertia` (see [`tensor::check_inertia`]).
    pub fn new(mass: f64, center_of_mass: Vec3, inertia: Mat3) -> Result<Self> {
        check_positive("mass", mass)?;
        check_finite("center_of_mass", center_of_mass.as_slice())?;
        let inertia = tensor::check_inertia("inertia", &inertia)?;
        Ok(Self {
            mass,
            center_of_mass,
            inertia,
        })
    }

    /// Builds without checks, for values that are valid by construction inside the crate
    /// (formulas of solids, exact integrals); the inertia is symmetrised.
    pub(crate) fn from_parts(mass: f64, center_of_mass: Vec3, inertia: Mat3) -> Self {
        let inertia = (inertia + inertia.transpose()) * 0.5;
        Self {
            mass,
            center_of_mass,
            inertia,
        }
    }

    /// A body whose inertia about the point `point` (m) is `inertia_about_point` (kg·m²): the
    /// parallel-axis theorem run backwards, `I_cm = I_P − m (|d|² 1 − d dᵀ)`, `d = com − P`.
    /// The physical checks of the result allow for the round-off of that subtraction
    /// (relative to `|I_P|`, see [`tensor::check_inertia_scaled`]).
    pub fn from_inertia_about(
        mass: f64,
        center_of_mass: Vec3,
        inertia_about_point: Mat3,
        point: Vec3,
    ) -> Result<Self> {
        check_positive("mass", mass)?;
        check_finite("center_of_mass", center_of_mass.as_slice())?;
        check_finite("point", point.as_slice())?;
        check_finite("inertia", inertia_about_point.as_slice())
            .map_err(|e| Error::inertia("inertia", e.message))?;
        let cm = tensor::shift_to_com(&inertia_about_point, mass, &center_of_mass, &point);
        // Round-off of the cancellation is relative to the tensor about the point.
        let inertia = tensor::check_inertia_scaled("inertia", &cm, inertia_about_point.amax())?;
        Ok(Self {
            mass,
            center_of_mass,
            inertia,
        })
    }

    /// Point masses `masses[a]` (kg, each `> 0`) at `positions[a]` (m): the discrete sums of the
    /// unit's 2.46–2.50, taken about the centre of mass `Σ m r / Σ m`.
    ///
    /// One point mass is allowed (its inertia about its centre of mass is zero); errors name
    /// `masses` (empty, non-finite or `≤ 0`, with the index) or `positions` (non-finite, or a
    /// count different from `masses`).
    pub fn from_point_masses(masses: &[f64], positions: &[[f64; 3]]) -> Result<Self> {
        if masses.is_empty() {
            return Err(Error::invalid(
                "masses",
                "must hold at least one mass, got none",
            ));
        }
        if positions.len() != masses.len() {
            return Err(Error::invalid(
                "positions",
                format!(
                    "must hold one position per mass: {} positions for {} masses",
                    positions.len(),
                    masses.len()
                ),
            ));
        }
        if let Some(i) = masses.iter().position(|m| !(m.is_finite() && *m > 0.0)) {
            return Err(Error::invalid(
                "masses",
                format!("must be finite and > 0, got {} at index {i}", masses[i]),
            ));
        }
        check_finite("positions", positions.as_flattened())?;
        let mass: f64 = masses.iter().sum();
        let first: Vec3 = masses
            .iter()
            .zip(positions)
            .map(|(m, r)| Vec3::from(*r) * *m)
            .sum();
        let com = first / mass;
        // Second pass about the centre of mass: no cancellation of large parallel-axis terms.
        let inertia = masses
            .iter()
            .zip(positions)
            .map(|(m, r)| tensor::point_inertia(*m, &(Vec3::from(*r) - com)))
            .sum();
        Ok(Self::from_parts(mass, com, inertia))
    }

    /// The mass (kg).
    pub fn mass(&self) -> f64 {
        self.mass
    }

    /// The centre of mass (m).
    pub fn center_of_mass(&self) -> Vec3 {
        self.center_of_mass
    }

    /// The inertia tensor about the centre of mass (kg·m²), products negated (2.46–2.50).
    pub fn inertia(&self) -> Mat3 {
        self.inertia
    }

    /// The inertia tensor about the point `point` (m), in the same axes (kg·m²): the
    /// parallel-axis theorem `I_P = I_cm + m (|d|² 1 − d dᵀ)`, `d = com − P`.
    pub fn inertia_about(&self, point: &Vec3) -> Result<Mat3> {
        check_finite("point", point.as_slice())?;
        Ok(tensor::shift_from_com(
            &self.inertia,
            self.mass,
            &self.center_of_mass,
            point,
        ))
    }

    /// The inertia about `about` (m), or about the centre of mass when `None`.
    fn inertia_at(&self, about: Option<&Vec3>) -> Result<Mat3> {
        match about {
            None => Ok(self.inertia),
            Some(p) => {
                check_finite("about", p.as_slice())?;
                Ok(tensor::shift_from_com(
                    &self.inertia,
                    self.mass,
                    &self.center_of_mass,
                    p,
                ))
            }
        }
    }

    /// Principal moments (kg·m², ascending) and principal axes (columns of a proper rotation);
    /// moments equal within `rtol` of the largest get clean axes (see [`tensor::principal`]).
    pub fn principal(&self, rtol: f64) -> Principal {
        tensor::principal(&self.inertia, rtol)
    }

    /// The kind of top (see [`tensor::classify`]), moments equal within `rtol` of the largest.
    pub fn kind(&self, rtol: f64) -> Result<TopKind> {
        tensor::classify(self.principal(rtol).moments, rtol)
    }

    /// The same body moved by `offset` (m): the centre of mass moves, the inertia about it does
    /// not change.
    pub fn translated(&self, offset: &Vec3) -> Result<Self> {
        check_finite("offset", offset.as_slice())?;
        Ok(Self {
            center_of_mass: self.center_of_mass + offset,
            ..*self
        })
    }

    /// The same body rotated actively by the rotation matrix `rotation` about the origin of its
    /// axes: `com ↦ R com`, `I ↦ R I Rᵀ`. `rotation` must be orthonormal with `det = +1` within
    /// [`ROTATION_TOL`], else an [`Error::rotation`] naming `rotation`.
    pub fn rotated(&self, rotation: &Mat3) -> Result<Self> {
        check_rotation("rotation", rotation)?;
        Ok(Self::from_parts(
            self.mass,
            rotation * self.center_of_mass,
            tensor::rotate(rotation, &self.inertia),
        ))
    }

    /// The body made of all of `bodies` rigidly joined: the masses add, the centre of mass is
    /// the mass-weighted mean, and each inertia is shifted to the common centre of mass by the
    /// parallel-axis theorem before summing. Errors name `bodies` when it is empty.
    pub fn combine(bodies: &[MassProperties]) -> Result<Self> {
        if bodies.is_empty() {
            return Err(Error::invalid(
                "bodies",
                "must hold at least one body, got none",
            ));
        }
        let mass: f64 = bodies.iter().map(|b| b.mass).sum();
        let com: Vec3 = bodies
            .iter()
            .map(|b| b.center_of_mass * b.mass)
            .sum::<Vec3>()
            / mass;
        let inertia: Mat3 = bodies
            .iter()
            .map(|b| tensor::shift_from_com(&b.inertia, b.mass, &b.center_of_mass, &com))
            .sum();
        Ok(Self::from_parts(mass, com, inertia))
    }

    /// Angular momentum `L = I·ω` (kg·m²/s; 2.51 with the errata's summation index, 2.63) of the
    /// body turning with angular velocity `omega` (rad/s): about its centre of mass when `about`
    /// is `None` (the spin angular momentum), else about the fixed point `about` (m) around
    /// which the body turns (`L_P = I_P·ω`, equal to Σ m r × (ω × r) with r from P, 2.44).
    pub fn angular_momentum(&self, omega: &Vec3, about: Option<&Vec3>) -> Result<Vec3> {
        check_finite("omega", omega.as_slice())?;
        Ok(self.inertia_at(about)? * omega)
    }

    /// Kinetic energy of rotation `T = ½ ω·I·ω = ½ ω·L` (J; 2.53, 2.64): about the centre of mass
    /// when `about` is `None`, else the whole kinetic energy of the body turning about the fixed
    /// point `about` (m) with angular velocity `omega` (rad/s).
    pub fn kinetic_energy(&self, omega: &Vec3, about: Option<&Vec3>) -> Result<f64> {
        let l = self.angular_momentum(omega, about)?;
        Ok(0.5 * omega.dot(&l))
    }

    /// The torque `N = ω × L` (N·m) that keeps the body turning at the constant angular velocity
    /// `omega` (rad/s), about `about` (m; `None`: the centre of mass): L is carried round by the
    /// rotation, `dL/dt = ω × L = N` (2.58–2.59). Zero exactly when ω is along a principal axis.
    pub fn holding_torque(&self, omega: &Vec3, about: Option<&Vec3>) -> Result<Vec3> {
        let l = self.angular_momentum(omega, about)?;
        Ok(omega.cross(&l))
    }

    /// The angle (rad, in `[0, π/2]` for a physical body) between the angular momentum `L` and
    /// the angular velocity `omega` (rad/s), about `about` (m; `None`: the centre of mass):
    /// zero when ω is along a principal axis (2.57: in general L is not parallel to ω).
    /// Errors name `omega` when ω = 0 or when L = 0 (ω along the axis of a zero moment), where
    /// the angle is undefined.
    pub fn momentum_angle(&self, omega: &Vec3, about: Option<&Vec3>) -> Result<f64> {
        let l = self.angular_momentum(omega, about)?;
        if omega.norm() == 0.0 {
            return Err(Error::invalid(
                "omega",
                "must be non-zero for the angle between L and ω",
            ));
        }
        if l.norm() == 0.0 {
            return Err(Error::invalid(
                "omega",
                "gives zero angular momentum (ω along an axis of zero moment): the angle \
                 between L and ω is undefined",
            ));
        }
        Ok(omega.cross(&l).norm().atan2(omega.dot(&l)))
    }
}

/// Checks that `r` is a proper rotation matrix within [`ROTATION_TOL`].
fn check_rotation(argument: &str, r: &Mat3) -> Result<()> {
    if let Err(e) = check_finite(argument, r.as_slice()) {
        return Err(Error::rotation(argument, e.message));
    }
    let err = (r.transpose() * r - Mat3::identity()).amax();
    if err > ROTATION_TOL {
        return Err(Error::rotation(
            argument,
            format!(
                "must be orthonormal (RᵀR = 1), off by {err:.3e} (tolerance {ROTATION_TOL:.0e})"
            ),
        ));
    }
    let det = r.determinant();
    if (det - 1.0).abs() > ROTATION_TOL {
        return Err(Error::rotation(
            argument,
            format!("must have det = +1 (a proper rotation, not a reflection), got {det}"),
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dumbbell_momentum_is_not_along_omega() {
        // 2.58–2.59: two unit masses at ±(1, 0, 1) turning about z.
        let b =
            MassProperties::from_point_masses(&[1.0, 1.0], &[[1.0, 0.0, 1.0], [-1.0, 0.0, -1.0]])
                .unwrap();
        let w = Vec3::new(0.0, 0.0, 2.0);
        let l = b.angular_momentum(&w, None).unwrap();
        // Direct sum Σ m r × (ω × r).
        let direct: Vec3 = [Vec3::new(1.0, 0.0, 1.0), Vec3::new(-1.0, 0.0, -1.0)]
            .iter()
            .map(|r| r.cross(&w.cross(r)))
            .sum();
        assert!((l - direct).amax() < 1e-15);
        assert!(l.dot(&Vec3::new(1.0, 0.0, 1.0)).abs() < 1e-15, "L ⟂ rod");
        let angle = b.momentum_angle(&w, None).unwrap();
        assert!((angle - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
        let n = b.holding_torque(&w, None).unwrap();
        assert!((n - w.cross(&l)).amax() == 0.0 && n.norm() > 1.0);
        assert!((b.kinetic_energy(&w, None).unwrap() - 0.5 * w.dot(&l)).abs() < 1e-15);
    }

    #[test]
    fn refusals_name_arguments() {
        let e = MassProperties::from_point_masses(&[1.0, -2.0], &[[0.0; 3], [1.0; 3]]).unwrap_err();
        assert!(
            e.to_string().starts_with("masses:") && e.message.contains("index 1"),
            "{e}"
        );
        let e = MassProperties::from_point_masses(&[1.0], &[[0.0; 3], [1.0; 3]]).unwrap_err();
        assert!(e.to_string().starts_with("positions:"), "{e}");
        let e = MassProperties::new(0.0, Vec3::zeros(), Mat3::identity()).unwrap_err();
        assert!(e.to_string().starts_with("mass:"), "{e}");
        let b = MassProperties::new(1.0, Vec3::zeros(), Mat3::identity()).unwrap();
        let e = b.rotated(&(Mat3::identity() * -1.0)).unwrap_err();
        assert_eq!(e.kind, crate::ErrorKind::InvalidRotation);
        assert!(e.message.contains("det"), "{e}");
        assert!(b.momentum_angle(&Vec3::zeros(), None).is_err());
        assert!(MassProperties::combine(&[]).is_err());
    }
}
