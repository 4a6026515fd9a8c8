//! Mass properties of a rigid body (mass, centre of mass, inertia about the centre of mass),
//! their composition, and the angular momentum, kinetic energy and holding torque of a body
//! turning with angular velocity ω (the unit's 2.43–2.64).
//!
//! **Range.** Every returned number is finite, or the call is an error naming the argument
//! that leads out of the range of doubles. Sums and products of extreme magnitudes (`m |d|²`
//! with `|d| = 1e200`, `ω·I·ω`) are computed on mantissas scaled by exact powers of two, so a
//! result that is representable is exact (the unit-scale bits times the power of two) even when
//! a naive intermediate would overflow or underflow. Bodies whose largest moment would fall
//! below the smallest normal double (`2.2e-308`) are refused (their tensor would have lost
//! its precision); angular momenta, energies and torques that small are returned as IEEE
//! subnormals (the correctly rounded value).

use crate::control;
use crate::error::{check_finite, check_positive, Error, Result};
use crate::inertia::scaling::{
    check_margins, check_overflow, check_range, exponent_of_max, ldexp, ldexp_mat, ldexp_vec, split,
};
use crate::inertia::tensor::{self, Principal, TopKind};
use crate::{Mat3, Vec3};

/// What to do when a result leaves the range of doubles.
const HINT: &str = "express the body in other units (e.g. g and mm, or t and km)";

/// What to do when ω makes a result overflow.
const HINT_OMEGA: &str = "no body turning this fast has a finite value here";

/// Tolerance of the rotation check of [`MassProperties::rotated`]: `|RᵀR − 1|` entrywise and
/// `|det R − 1|` (a rotation matrix that went through text or single precision passes).
pub const BODY_ROTATION_TOL: f64 = 1e-9;

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
///
/// ```
/// use poinsot::inertia::{cuboid, solid_sphere, MassProperties, TopKind, DEFAULT_KIND_RTOL};
/// use poinsot::Vec3;
/// // A 2 kg box with sides 1, 2, 3 m: I_xx = m (b² + c²) / 12 = 13/6 kg·m² about its centre.
/// let block = cuboid(2.0, [1.0, 2.0, 3.0])?;
/// assert!((block.inertia()[(0, 0)] - 13.0 / 6.0).abs() < 1e-15);
/// assert_eq!(block.kind(DEFAULT_KIND_RTOL)?, TopKind::AsymmetricTop);
/// // Parallel axes: about a corner, I_P = I + m (|d|² 1 − d dᵀ).
/// let corner = Vec3::new(0.5, 1.0, 1.5);
/// assert!((block.inertia_about(&corner)?[(0, 1)] - (-2.0 * 0.5 * 1.0)).abs() < 1e-15);
/// // Turning at 2 rad/s about z through the centre: T = ½ I_zz ω² = ½ (10/12) 4 J.
/// let t = block.kinetic_energy(&Vec3::new(0.0, 0.0, 2.0), None)?;
/// assert!((t - 5.0 / 3.0).abs() < 1e-15);
/// // A 1 kg ball stuck on top: the two combined.
/// let ball = solid_sphere(1.0, 0.1)?.translated(&Vec3::new(0.0, 0.0, 1.6))?;
/// let both = MassProperties::combine(&[block, ball])?;
/// assert_eq!(both.mass(), 3.0);
/// assert!((both.center_of_mass().z - 1.6 / 3.0).abs() < 1e-15);
/// # Ok::<(), poinsot::Error>(())
/// ```
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
        let inertia = tensor::symmetrised(&inertia);
        Self {
            mass,
            center_of_mass,
            inertia,
        }
    }

    /// A body whose inertia about the point `about` (m) is `inertia_about_point` (kg·m²): the
    /// parallel-axis theorem run backwards, `I_cm = I_P − m (|d|² 1 − d dᵀ)`, `d = com − P`.
    /// The physical checks of the result allow for the round-off of that subtraction
    /// (relative to `|I_P|`, see [`tensor::check_inertia_scaled`]). Errors about the point
    /// name `about`, the keyword of the front ends (`RigidBody.from_inertia(..., about=P)`).
    pub fn from_inertia_about(
        mass: f64,
        center_of_mass: Vec3,
        inertia_about_point: Mat3,
        about: Vec3,
    ) -> Result<Self> {
        check_positive("mass", mass)?;
        check_finite("center_of_mass", center_of_mass.as_slice())?;
        check_finite("about", about.as_slice())?;
        check_finite("inertia", inertia_about_point.as_slice())
            .map_err(|e| Error::inertia("inertia", e.message))?;
        let cm = tensor::shift_to_com(&inertia_about_point, mass, &center_of_mass, &about);
        if !cm.iter().all(|x| x.is_finite()) {
            return Err(Error::invalid(
                "about",
                "is so far from the centre of mass that the parallel-axis term m (|d|² 1 − d dᵀ) \
                 exceeds the largest finite double (1.8e+308 kg·m²)",
            ));
        }
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
        // On mantissas: masses scaled by 2^-em, positions by 2^-er (exact), so that neither
        // m r nor |d|² leaves the range when the results do not.
        let em = exponent_of_max(masses);
        let er = exponent_of_max(positions.as_flattened());
        // Each pass over the masses polls for Ctrl-C every chunk of them.
        let ms: Vec<f64> = control::try_map(masses, |m| Ok(ldexp(*m, -em)))?;
        let rs: Vec<Vec3> = control::try_map(positions, |r| Ok(ldexp_vec(&Vec3::from(*r), -er)))?;
        let n = ms.len();
        let mass: f64 = polled_sum(n, 0.0, |i| ms[i])?;
        check_range("masses", "the total mass (kg)", mass, em, HINT)?;
        let first: Vec3 = polled_sum(n, Vec3::zeros(), |i| rs[i] * ms[i])?;
        let com = first / mass;
        // Second pass about the centre of mass: no cancellation of large parallel-axis terms.
        let inertia: Mat3 = polled_sum(n, Mat3::zeros(), |i| {
            let d = rs[i] - com;
            (Mat3::identity() * d.norm_squared() - d * d.transpose()) * ms[i]
        })?;
        let k = em + 2 * er;
        let blame = if (2 * er).abs() >= em.abs() {
            "positions"
        } else {
            "masses"
        };
        check_range(
            blame,
            "the largest moment of inertia (kg·m²)",
            inertia.amax(),
            k,
            HINT,
        )?;
        check_margins(blame, tensor::moments_of(&inertia), k, HINT)?;
        Ok(Self::from_parts(
            ldexp(mass, em),
            ldexp_vec(&com, er),
            ldexp_mat(&inertia, k),
        ))
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
    /// parallel-axis theorem `I_P = I_cm + m (|d|² 1 − d dᵀ)`, `d = com − P`. An error names
    /// `point` when the result would exceed the range of doubles.
    pub fn inertia_about(&self, point: &Vec3) -> Result<Mat3> {
        self.shifted("point", point)
    }

    /// The inertia about `point`, or an error naming `argument` (non-finite point, or a
    /// result beyond the range of doubles).
    fn shifted(&self, argument: &str, point: &Vec3) -> Result<Mat3> {
        check_finite(argument, point.as_slice())?;
        let d = self.center_of_mass - point;
        let i = tensor::shift_from_com(&self.inertia, self.mass, &self.center_of_mass, point);
        if d.iter().all(|x| x.is_finite()) && i.iter().all(|x| x.is_finite()) {
            return Ok(i);
        }
        // The magnitude m |d|² on mantissas, for the message.
        let (m, em) = split(self.mass);
        let ed = exponent_of_max(&[self.center_of_mass.amax(), point.amax()]);
        let ds = ldexp_vec(&self.center_of_mass, -ed) - ldexp_vec(point, -ed);
        let value = m * ds.norm_squared();
        check_overflow(
            argument,
            "the inertia about this point (kg·m²)",
            value,
            em + 2 * ed,
            "the point is too far from the centre of mass for this mass",
        )?;
        Err(Error::invalid(
            argument,
            "the inertia about this point exceeds the largest finite double (1.8e+308)",
        ))
    }

    /// The inertia about `about` (m), or about the centre of mass when `None`.
    fn inertia_at(&self, about: Option<&Vec3>) -> Result<Mat3> {
        match about {
            None => Ok(self.inertia),
            Some(p) => self.shifted("about", p),
        }
    }

    /// `(I·2^-eI, ω·2^-eω, eI, eω)`: the tensor about `about` and ω on mantissas.
    fn scaled_omega(&self, omega: &Vec3, about: Option<&Vec3>) -> Result<(Mat3, Vec3, i32, i32)> {
        check_finite("omega", omega.as_slice())?;
        let i = self.inertia_at(about)?;
        let ei = exponent_of_max(i.as_slice());
        let ew = exponent_of_max(omega.as_slice());
        Ok((ldexp_mat(&i, -ei), ldexp_vec(omega, -ew), ei, ew))
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
    /// not change. An error names `offset` when the new centre of mass would not be finite.
    pub fn translated(&self, offset: &Vec3) -> Result<Self> {
        check_finite("offset", offset.as_slice())?;
        let com = self.center_of_mass + offset;
        if !com.iter().all(|x| x.is_finite()) {
            return Err(Error::invalid(
                "offset",
                format!(
                    "moves the centre of mass from {:?} to beyond the largest finite double \
                     (1.8e+308 m)",
                    self.center_of_mass.as_slice()
                ),
            ));
        }
        Ok(Self {
            center_of_mass: com,
            ..*self
        })
    }

    /// The same body rotated actively by the rotation matrix `rotation` about the origin of its
    /// axes: `com ↦ R com`, `I ↦ R I Rᵀ`. `rotation` must be orthonormal with `det = +1` within
    /// [`BODY_ROTATION_TOL`], else an [`Error::rotation`] naming `rotation`; an [`Error::invalid`]
    /// naming `rotation` when a rotated entry would exceed the range of doubles (a centre of
    /// mass or a tensor at the very top of the range).
    pub fn rotated(&self, rotation: &Mat3) -> Result<Self> {
        check_rotation("rotation", rotation)?;
        let ec = exponent_of_max(self.center_of_mass.as_slice());
        let com = ldexp_vec(&(rotation * ldexp_vec(&self.center_of_mass, -ec)), ec);
        let inertia = tensor::rotate(rotation, &self.inertia);
        if !(com.iter().all(|x| x.is_finite()) && inertia.iter().all(|x| x.is_finite())) {
            return Err(Error::invalid(
                "rotation",
                "turns the body so that an entry of its centre of mass or inertia tensor \
                 exceeds the largest finite double (1.8e+308)",
            ));
        }
        Ok(Self::from_parts(self.mass, com, inertia))
    }

    /// The body made of all of `bodies` rigidly joined: the masses add, the centre of mass is
    /// the mass-weighted mean, and each inertia is shifted to the common centre of mass by the
    /// parallel-axis theorem before summing. Errors name `bodies` when it is empty, or when the
    /// total mass or the combined inertia would leave the range of doubles (beyond `f64::MAX`,
    /// or a largest moment below the smallest normal double).
    pub fn combine(bodies: &[MassProperties]) -> Result<Self> {
        if bodies.is_empty() {
            return Err(Error::invalid(
                "bodies",
                "must hold at least one body, got none",
            ));
        }
        // Masses and centres of mass on mantissas (exact powers of two).
        let masses: Vec<f64> = bodies.iter().map(|b| b.mass).collect();
        let em = exponent_of_max(&masses);
        let ec = exponent_of_max(
            &bodies
                .iter()
                .map(|b| b.center_of_mass.amax())
                .collect::<Vec<_>>(),
        );
        let mass: f64 = masses.iter().map(|m| ldexp(*m, -em)).sum();
        check_range("bodies", "the total mass (kg)", mass, em, HINT)?;
        let com = ldexp_vec(
            &(bodies
                .iter()
                .map(|b| ldexp_vec(&b.center_of_mass, -ec) * ldexp(b.mass, -em))
                .sum::<Vec3>()
                / mass),
            ec,
        );
        let inertia: Mat3 = bodies
            .iter()
            .map(|b| tensor::shift_from_com(&b.inertia, b.mass, &b.center_of_mass, &com))
            .sum();
        if !inertia.iter().all(|x| x.is_finite()) {
            return Err(Error::invalid(
                "bodies",
                "the combined inertia tensor would exceed the largest finite double \
                 (1.8e+308 kg·m²): the bodies are too heavy or too far apart; express them in \
                 other units",
            ));
        }
        let largest = inertia.amax();
        if largest > 0.0 && largest < f64::MIN_POSITIVE {
            return Err(Error::invalid(
                "bodies",
                format!(
                    "the combined inertia tensor would be about {largest:.3e} kg·m², below the \
                     smallest normal double (2.2e-308), where it cannot be represented to full \
                     precision; {HINT}"
                ),
            ));
        }
        Ok(Self::from_parts(ldexp(mass, em), com, inertia))
    }

    /// Angular momentum `L = I·ω` (kg·m²/s; 2.51 with the errata's summation index, 2.63) of the
    /// body turning with angular velocity `omega` (rad/s): about its centre of mass when `about`
    /// is `None` (the spin angular momentum), else about the fixed point `about` (m) around
    /// which the body turns (`L_P = I_P·ω`, equal to Σ m r × (ω × r) with r from P, 2.44).
    pub fn angular_momentum(&self, omega: &Vec3, about: Option<&Vec3>) -> Result<Vec3> {
        let (i, w, ei, ew) = self.scaled_omega(omega, about)?;
        let l = i * w;
        check_overflow(
            "omega",
            "the angular momentum (kg·m²/s)",
            l.amax(),
            ei + ew,
            HINT_OMEGA,
        )?;
        Ok(ldexp_vec(&l, ei + ew))
    }

    /// Kinetic energy of rotation `T = ½ ω·I·ω = ½ ω·L` (J; 2.53, 2.64): about the centre of mass
    /// when `about` is `None`, else the whole kinetic energy of the body turning about the fixed
    /// point `about` (m) with angular velocity `omega` (rad/s).
    pub fn kinetic_energy(&self, omega: &Vec3, about: Option<&Vec3>) -> Result<f64> {
        let (i, w, ei, ew) = self.scaled_omega(omega, about)?;
        let t = 0.5 * w.dot(&(i * w));
        check_overflow(
            "omega",
            "the kinetic energy (J)",
            t,
            ei + 2 * ew,
            HINT_OMEGA,
        )?;
        Ok(ldexp(t, ei + 2 * ew))
    }

    /// The torque `N = ω × L` (N·m) that keeps the body turning at the constant angular velocity
    /// `omega` (rad/s), about `about` (m; `None`: the centre of mass): L is carried round by the
    /// rotation, `dL/dt = ω × L = N` (2.58–2.59). Zero exactly when ω is along a principal axis.
    pub fn holding_torque(&self, omega: &Vec3, about: Option<&Vec3>) -> Result<Vec3> {
        let (i, w, ei, ew) = self.scaled_omega(omega, about)?;
        let n = w.cross(&(i * w));
        check_overflow(
            "omega",
            "the holding torque (N·m)",
            n.amax(),
            ei + 2 * ew,
            HINT_OMEGA,
        )?;
        Ok(ldexp_vec(&n, ei + 2 * ew))
    }

    /// The angle (rad, in `[0, π/2]` for a physical body) between the angular momentum `L` and
    /// the angular velocity `omega` (rad/s), about `about` (m; `None`: the centre of mass):
    /// zero when ω is along a principal axis (2.57: in general L is not parallel to ω).
    /// Errors name `omega` when ω = 0 or when L = 0 (ω along the axis of a zero moment), where
    /// the angle is undefined. Computed on mantissas, so it is defined however small or large
    /// L is.
    pub fn momentum_angle(&self, omega: &Vec3, about: Option<&Vec3>) -> Result<f64> {
        let (i, w, _, _) = self.scaled_omega(omega, about)?;
        let l = i * w;
        if w.norm() == 0.0 {
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
        Ok(w.cross(&l).norm().atan2(w.dot(&l)))
    }
}

/// Checks that `r` is a proper rotation matrix within [`BODY_ROTATION_TOL`].
fn check_rotation(argument: &str, r: &Mat3) -> Result<()> {
    if let Err(e) = check_finite(argument, r.as_slice()) {
        return Err(Error::rotation(argument, e.message));
    }
    let err = (r.transpose() * r - Mat3::identity()).amax();
    if err > BODY_ROTATION_TOL {
        return Err(Error::rotation(
            argument,
            format!(
                "must be orthonormal (RᵀR = 1), off by {err:.3e} (tolerance {BODY_ROTATION_TOL:.0e})"
            ),
        ));
    }
    let det = r.determinant();
    if (det - 1.0).abs() > BODY_ROTATION_TOL {
        return Err(Error::rotation(
            argument,
            format!("must have det = +1 (a proper rotation, not a reflection), got {det}"),
        ));
    }
    Ok(())
}

/// `f(0) + f(1) + … + f(n − 1)` added in order from `zero` (the numbers of `Iterator::sum`),
/// polling for Ctrl-C every [`control::CHUNK`] terms.
fn polled_sum<S: std::ops::AddAssign>(n: usize, zero: S, f: impl Fn(usize) -> S) -> Result<S> {
    let mut acc = zero;
    let mut start = 0;
    while start < n {
        let end = (start + control::CHUNK).min(n);
        control::tick_by(control::CHUNK as u32)?;
        for i in start..end {
            acc += f(i);
        }
        start = end;
    }
    Ok(acc)
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
