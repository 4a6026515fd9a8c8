//! The inertia tensor as a matrix: validation, the parallel-axis shift, re-expression in
//! rotated axes, principal axes and the classification of tops.
//!
//! Sign convention (the unit's 2.46–2.50): the moments are `I_xx = Σ m (y² + z²)` and the
//! products of inertia are **negated**, `I_xy = −Σ m x y`, so that the tensor maps the angular
//! velocity to the angular momentum, `L = I·ω` (2.63), and `T = ½ ω·I·ω` (2.64).
//! Written out for point masses `m_a` at `r_a = (x_a, y_a, z_a)`:
//!
//! ```text
//!     ⎡ Σm(y²+z²)   −Σm x y    −Σm x z  ⎤
//! I = ⎢  −Σm y x   Σm(z²+x²)   −Σm y z  ⎥  =  Σ m (|r|² 1 − r rᵀ)
//!     ⎣  −Σm z x    −Σm z y   Σm(x²+y²) ⎦
//! ```

use nalgebra::SymmetricEigen;

use crate::error::{check_finite, Error, Result};
use crate::inertia::scaling::{exponent, exponent_of_max, ldexp, ldexp_mat, split};
use crate::{Mat3, Vec3};

/// Relative tolerance of the symmetry check of an inertia tensor: `|I_ij − I_ji|` may be at
/// most this times the largest entry (round-off of a tensor assembled from data).
pub const SYMMETRY_RTOL: f64 = 1e-9;

/// Relative tolerance of the physical checks (principal moments ≥ 0 and the triangle
/// inequality `I_a + I_b ≥ I_c`), in units of the largest principal moment: 16 ε, the
/// round-off of a symmetric 3×3 eigen-decomposition, so that bodies on the boundary (thin
/// rods, plates, rings: `I_a + I_b = I_c` exactly) pass after rotations and shifts.
pub const PHYSICAL_RTOL: f64 = 16.0 * f64::EPSILON;

/// Default relative tolerance of [`classify`] (and of the clean-up of degenerate principal
/// axes), in units of the largest principal moment.
pub const DEFAULT_KIND_RTOL: f64 = 1e-9;

/// The parallel-axis term `m (|d|² 1 − d dᵀ)`: the inertia of a point mass `m` at offset `d`
/// (2.46–2.50 for one particle). `I_P = I_cm + m (|d|² 1 − d dᵀ)` with `d = com − P`.
///
/// Computed on mantissas (`m` and `d` scaled by powers of two, the exponent applied last), so
/// that `|d|²` does not overflow for `|d| = 1e200` when `m |d|²` is representable; entries
/// beyond the range of doubles are `±inf` (callers check).
pub fn point_inertia(mass: f64, d: &Vec3) -> Mat3 {
    let (m, em) = split(mass);
    let ed = exponent_of_max(d.as_slice());
    let d = d.map(|x| ldexp(x, -ed));
    let t = (Mat3::identity() * d.norm_squared() - d * d.transpose()) * m;
    ldexp_mat(&t, em + 2 * ed)
}

/// The inertia about the point `point` (kg·m²) of a body of mass `mass` (kg) whose inertia about
/// its centre of mass `com` (m) is `inertia_cm`: the parallel-axis theorem
/// `I_P = I_cm + m (|d|² 1 − d dᵀ)`, `d = com − P`.
pub fn shift_from_com(inertia_cm: &Mat3, mass: f64, com: &Vec3, point: &Vec3) -> Mat3 {
    inertia_cm + point_inertia(mass, &(com - point))
}

/// The inverse of [`shift_from_com`]: the inertia about the centre of mass `com` of a body of mass
/// `mass` whose inertia about `point` is `inertia_p`, `I_cm = I_P − m (|d|² 1 − d dᵀ)`.
pub fn shift_to_com(inertia_p: &Mat3, mass: f64, com: &Vec3, point: &Vec3) -> Mat3 {
    inertia_p - point_inertia(mass, &(com - point))
}

/// `(I + Iᵀ)/2`, halving first so that entries near `f64::MAX` do not overflow.
pub(crate) fn symmetrised(inertia: &Mat3) -> Mat3 {
    inertia * 0.5 + inertia.transpose() * 0.5
}

/// The same tensor expressed in rotated axes: `R I Rᵀ` (the inertia of the body rotated actively
/// by `R`, in the original axes). Computed on the tensor scaled by a power of two, so that the
/// sums of products do not overflow for entries near `f64::MAX`.
pub fn rotate(rotation: &Mat3, inertia: &Mat3) -> Mat3 {
    let e = exponent_of_max(inertia.as_slice());
    let t = ldexp_mat(inertia, -e);
    ldexp_mat(&(rotation * t * rotation.transpose()), e)
}

/// Checks that `inertia` (kg·m²) can be the inertia tensor of a body about its centre of mass and
/// returns it exactly symmetrised.
///
/// Conditions, each reported as an [`Error::inertia`] naming `argument` with the violated
/// condition and by how much: finite entries; symmetric within [`SYMMETRY_RTOL`] of the largest
/// entry; principal moments `≥ 0`; the triangle inequalities `I_a + I_b ≥ I_c` for every
/// ordering, both within [`PHYSICAL_RTOL`] of the largest principal moment (so thin rods,
/// plates and rings, which sit on the boundary, pass). The zero tensor (a point mass) is valid.
pub fn check_inertia(argument: &str, inertia: &Mat3) -> Result<Mat3> {
    check_inertia_scaled(argument, inertia, 0.0)
}

/// [`check_inertia`] with the physical tolerance taken relative to
/// `max(largest principal moment, scale)`: for a tensor obtained by cancellation from larger
/// ones (the parallel-axis shift back to the centre of mass), whose round-off is relative to
/// `scale` (kg·m²), the magnitude before the cancellation.
pub fn check_inertia_scaled(argument: &str, inertia: &Mat3, scale: f64) -> Result<Mat3> {
    if let Err(e) = check_finite(argument, inertia.as_slice()) {
        return Err(Error::inertia(argument, e.message));
    }
    let entries = inertia.amax();
    for (i, j) in [(0, 1), (0, 2), (1, 2)] {
        let diff = (inertia[(i, j)] - inertia[(j, i)]).abs();
        if diff > SYMMETRY_RTOL * entries {
            return Err(Error::inertia(
                argument,
                format!(
                    "must be symmetric: I[{i}][{j}] = {} but I[{j}][{i}] = {} (difference {:.3e}, \
                     tolerance {:.1e} relative to the largest entry)",
                    inertia[(i, j)],
                    inertia[(j, i)],
                    diff,
                    SYMMETRY_RTOL
                ),
            ));
        }
    }
    let sym = symmetrised(inertia);
    // The eigenvalues of the tensor scaled by a power of two (exact), so that the solver's
    // squares neither overflow (entries near 1e308) nor underflow (near 1e-308).
    let e = exponent(entries.max(f64::MIN_POSITIVE));
    let moments = sorted_eigenvalues(&ldexp_mat(&sym, -e)).map(|x| ldexp(x, e));
    // The triangle margins the body reports are finite too.
    if !(moments.iter().all(|m| m.is_finite()) && largest_margin(moments).is_finite()) {
        return Err(Error::inertia(
            argument,
            "its principal moments are beyond the largest double (they overflow): rescale the units",
        ));
    }
    let largest = moments[2].abs().max(moments[0].abs());
    let tol = PHYSICAL_RTOL * largest.max(scale);
    if moments[0] < -tol {
        return Err(Error::inertia(
            argument,
            format!(
                "principal moments must be >= 0, got {} (principal moments {:?}); an inertia \
                 tensor is Σ m (|r|² 1 − r rᵀ), which is positive semi-definite",
                moments[0], moments
            ),
        ));
    }
    // Ascending: the only inequality that can fail is I1 + I2 >= I3.
    let excess = moments[2] - (moments[0] + moments[1]);
    if excess > tol {
        return Err(Error::inertia(
            argument,
            format!(
                "principal moments {:?} violate the triangle inequality I1 + I2 >= I3: \
                 {} + {} < {} by {:.6e} ({:.3e} of the largest moment); no distribution of \
                 mass has these moments",
                moments,
                moments[0],
                moments[1],
                moments[2],
                excess,
                excess / largest.max(f64::MIN_POSITIVE)
            ),
        ));
    }
    Ok(sym)
}

/// The eigenvalues of a symmetric matrix, ascending.
fn sorted_eigenvalues(sym: &Mat3) -> [f64; 3] {
    let e = sym.symmetric_eigenvalues();
    let mut m = [e[0], e[1], e[2]];
    m.sort_by(f64::total_cmp);
    m
}

/// Principal moments and principal axes of an inertia tensor.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Principal {
    /// Principal moments `[I1, I2, I3]` (kg·m²), **ascending**.
    pub moments: [f64; 3],
    /// Principal axes as the columns of a proper rotation matrix (`det = +1`): column `k` is the
    /// axis of `moments[k]`, so `inertia = axes · diag(moments) · axesᵀ`.
    pub axes: Mat3,
}

impl Principal {
    /// The margins of the triangle inequalities (kg·m²), `[I2 + I3 − I1, I3 + I1 − I2,
    /// I1 + I2 − I3]` in the order of the (ascending) moments: each is `2 ∫ x_k² dm`, twice the
    /// second moment of the mass along principal axis `k` (from 2.61–2.62), so none is negative
    /// for a body, and a margin of zero means the mass lies in the plane ⟂ that axis (the
    /// perpendicular-axis theorem of a lamina: a thin disk or ring has `I1 + I2 − I3 = 0`). The
    /// last margin is the smallest.
    /// Finite for every body the core makes (it refuses one whose largest margin overflows,
    /// checked where it is made); near the top of the range the sums are reordered so that no
    /// intermediate `I2 + I3` overflows where the margin does not.
    pub fn triangle_margins(&self) -> [f64; 3] {
        let [a, b, c] = self.moments;
        let m = [b + c - a, c + a - b, a + b - c];
        if m.iter().all(|x| x.is_finite()) {
            return m;
        }
        [c + (b - a), c - (b - a), a - (c - b)]
    }
}

/// The largest triangle margin `I3 + (I2 − I1)` of the principal moments `moments` (any
/// order; at most twice the largest): where it overflows, a body of these moments cannot report
/// its margins, and the core refuses it.
pub(crate) fn largest_margin(moments: [f64; 3]) -> f64 {
    let mut m = moments;
    m.sort_by(f64::total_cmp);
    m[2] + (m[1] - m[0])
}

/// The principal moments of the symmetric tensor `inertia`, ascending.
pub(crate) fn moments_of(inertia: &Mat3) -> [f64; 3] {
    sorted_eigenvalues(&symmetrised(inertia))
}

/// Principal moments (ascending) and principal axes (columns of a proper rotation) of the
/// symmetric tensor `inertia` (the unit's 2.65–2.66: in these axes the products vanish).
///
/// Moments that agree within `rtol` of the largest one are treated as equal, and their axes are
/// then chosen cleanly instead of as round-off dictates: a spherical top gets the identity; for a
/// symmetric top the distinct axis `u` is the computed eigenvector (sign: its largest component
/// positive) and the degenerate pair is spanned by the projection onto the plane ⟂ `u` of the
/// first coordinate axis least aligned with `u`, and `u ×` that. Non-degenerate axes get the
/// sign that makes their largest component positive; the last column is the cross product of
/// the first two, so `det = +1` always.
pub fn principal(inertia: &Mat3, rtol: f64) -> Principal {
    let sym = symmetrised(inertia);
    // Decompose the tensor scaled by a power of two (exact), as in [`check_inertia_scaled`].
    let e = exponent_of_max(sym.as_slice());
    let eig = SymmetricEigen::new(ldexp_mat(&sym, -e));
    let mut order = [0usize, 1, 2];
    order.sort_by(|&a, &b| eig.eigenvalues[a].total_cmp(&eig.eigenvalues[b]));
    let moments = [
        ldexp(eig.eigenvalues[order[0]], e),
        ldexp(eig.eigenvalues[order[1]], e),
        ldexp(eig.eigenvalues[order[2]], e),
    ];
    let vec = |k: usize| -> Vec3 { eig.eigenvectors.column(order[k]).into_owned() };
    let tol = rtol.max(0.0) * moments[0].abs().max(moments[2].abs());
    let eq01 = moments[1] - moments[0] <= tol;
    let eq12 = moments[2] - moments[1] <= tol;
    let axes = if eq01 && eq12 {
        Mat3::identity()
    } else if eq01 {
        // Pair (0, 1), distinct axis 2: columns (a, u × a, u) is right-handed.
        let u = canonical_sign(vec(2).normalize());
        let a = plane_axis(&u);
        Mat3::from_columns(&[a, u.cross(&a), u])
    } else if eq12 {
        // Distinct axis 0, pair (1, 2): columns (u, a, u × a).
        let u = canonical_sign(vec(0).normalize());
        let a = plane_axis(&u);
        Mat3::from_columns(&[u, a, u.cross(&a)])
    } else {
        let c0 = canonical_sign(vec(0).normalize());
        // Re-orthogonalise the second axis against the first (round-off), then complete.
        let v1 = vec(1);
        let c1 = canonical_sign((v1 - c0 * c0.dot(&v1)).normalize());
        Mat3::from_columns(&[c0, c1, c0.cross(&c1)])
    };
    Principal { moments, axes }
}

/// `v` or `−v`, whichever has its largest-magnitude component positive (first such on ties).
fn canonical_sign(v: Vec3) -> Vec3 {
    let k = v.iamax();
    if v[k] < 0.0 {
        -v
    } else {
        v
    }
}

/// A unit vector ⟂ `u`: the projection of the first coordinate axis whose projection is longest.
fn plane_axis(u: &Vec3) -> Vec3 {
    let mut best = Vec3::zeros();
    let mut best_norm = -1.0;
    for k in 0..3 {
        let mut e = Vec3::zeros();
        e[k] = 1.0;
        let p = e - u * u[k];
        let n = p.norm();
        // Prefer the lower index unless a later one is clearly longer.
        if n > best_norm * (1.0 + 1e-12) {
            best = p / n;
            best_norm = n;
        }
    }
    best
}

/// The kind of top, from the principal moments (the unit's classification after 2.66).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TopKind {
    /// All three principal moments equal: `I1 = I2 = I3` (sphere, cube).
    SphericalTop,
    /// Exactly two principal moments equal (cylinder, cone, disk).
    SymmetricTop,
    /// All three principal moments different.
    AsymmetricTop,
    /// Two equal moments and the third zero, `(0, I, I)` ascending: a thin rod, a diatomic
    /// molecule, any set of collinear point masses. Also the zero tensor of a single point mass,
    /// for which the unit's definition `I1 = I2, I3 = 0` holds literally (see [`classify`]).
    Rotor,
}

impl TopKind {
    /// The name used by the front ends: `"spherical top"`, `"symmetric top"`,
    /// `"asymmetric top"` or `"rotor"`.
    pub fn as_str(self) -> &'static str {
        match self {
            TopKind::SphericalTop => "spherical top",
            TopKind::SymmetricTop => "symmetric top",
            TopKind::AsymmetricTop => "asymmetric top",
            TopKind::Rotor => "rotor",
        }
    }
}

impl std::fmt::Display for TopKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

/// Classifies principal moments `moments` (kg·m², any order) as a kind of top.
///
/// Two moments are "equal" when they differ by at most `rtol` times the largest moment, and a
/// moment is "zero" when it is at most `rtol` times the largest. The rotor test comes first:
/// sorted ascending `(0, I, I)` is a rotor. The zero tensor of a single point mass (all moments
/// zero) is also reported as a `Rotor`: the unit's definition (`I1 = I2` and `I3 = 0`) holds,
/// and like a rotor the body has an axis about which it cannot hold angular momentum (for a
/// point mass, every axis through it). It is deliberately not called a spherical top, whose
/// meaning (a ball that spins alike about every axis) it does not have.
///
/// Errors: non-finite moments, moments that no body can have (a negative moment, or
/// `I1 + I2 < I3` beyond [`PHYSICAL_RTOL`]), or a negative or non-finite `rtol`, named
/// `moments` or `rtol`.
pub fn classify(moments: [f64; 3], rtol: f64) -> Result<TopKind> {
    check_finite("moments", &moments)?;
    if !(rtol.is_finite() && rtol >= 0.0) {
        return Err(Error::invalid(
            "rtol",
            format!("must be finite and >= 0, got {rtol}"),
        ));
    }
    let mut m = moments;
    m.sort_by(f64::total_cmp);
    let largest = m[2].abs().max(m[0].abs());
    let tol = rtol * largest;
    if m[0] < -tol.max(PHYSICAL_RTOL * largest) {
        return Err(Error::inertia(
            "moments",
            format!("principal moments must be >= 0, got {moments:?}"),
        ));
    }
    let excess = m[2] - (m[0] + m[1]);
    if excess > PHYSICAL_RTOL * largest {
        return Err(Error::inertia(
            "moments",
            format!(
                "principal moments {moments:?} violate the triangle inequality I1 + I2 >= I3 \
                 by {excess:.6e}"
            ),
        ));
    }
    let eq01 = m[1] - m[0] <= tol;
    let eq12 = m[2] - m[1] <= tol;
    let zero0 = m[0].abs() <= tol;
    Ok(if zero0 && eq12 {
        TopKind::Rotor
    } else if eq01 && eq12 {
        TopKind::SphericalTop
    } else if eq01 || eq12 {
        TopKind::SymmetricTop
    } else {
        TopKind::AsymmetricTop
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rot_x(a: f64) -> Mat3 {
        let (s, c) = a.sin_cos();
        Mat3::new(1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c)
    }
    fn rot_z(a: f64) -> Mat3 {
        let (s, c) = a.sin_cos();
        Mat3::new(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0)
    }

    #[test]
    fn point_inertia_negates_products() {
        // One kilogram at (1, 2, 3): I_xx = y² + z² = 13, I_xy = −x y = −2 (2.46, 2.49).
        let i = point_inertia(1.0, &Vec3::new(1.0, 2.0, 3.0));
        assert_eq!(
            i,
            Mat3::new(13.0, -2.0, -3.0, -2.0, 10.0, -6.0, -3.0, -6.0, 5.0)
        );
    }

    #[test]
    fn check_accepts_boundary_bodies_rotated() {
        // A thin rod (0, 1, 1) and a plate (1, 2, 3) sit on the triangle boundary.
        for d in [[0.0, 1.0, 1.0], [1.0, 2.0, 3.0], [0.0, 0.0, 0.0]] {
            let i = Mat3::from_diagonal(&Vec3::from(d));
            for k in 0..50 {
                let r = rot_z(0.37 * k as f64) * rot_x(1.1 * k as f64);
                check_inertia("inertia", &rotate(&r, &i)).unwrap();
            }
        }
    }

    #[test]
    fn check_refuses_with_reasons() {
        let e =
            check_inertia("inertia", &Mat3::from_diagonal(&Vec3::new(1.0, 1.0, 3.0))).unwrap_err();
        assert_eq!(e.kind, crate::ErrorKind::InvalidInertia);
        assert!(e.message.contains("triangle inequality"), "{e}");
        assert!(e.message.contains("by 1.0"), "{e}");
        let e =
            check_inertia("inertia", &Mat3::from_diagonal(&Vec3::new(-1.0, 1.0, 1.0))).unwrap_err();
        assert!(e.message.contains(">= 0"), "{e}");
        let mut a = Mat3::identity();
        a[(0, 1)] = 0.1;
        let e = check_inertia("inertia", &a).unwrap_err();
        assert!(e.message.contains("symmetric"), "{e}");
        a[(0, 1)] = f64::NAN;
        let e = check_inertia("inertia", &a).unwrap_err();
        assert!(
            e.message.contains("finite") && e.to_string().starts_with("inertia:"),
            "{e}"
        );
    }

    #[test]
    fn principal_axes_are_proper_and_diagonalise() {
        let base = Mat3::from_diagonal(&Vec3::new(3.0, 1.0, 2.0));
        let p = principal(&base, DEFAULT_KIND_RTOL);
        assert_eq!(p.moments, [1.0, 2.0, 3.0]);
        assert!((p.axes.determinant() - 1.0).abs() < 1e-15);
        // Diagonal input with distinct moments: a signed permutation, (e_y, e_z, e_x).
        assert_eq!(
            p.axes,
            Mat3::new(0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0)
        );
        for d in [
            [1.0, 1.0, 1.0],
            [1.0, 1.0, 2.0],
            [1.0, 2.0, 2.0],
            [0.5, 1.0, 1.5],
        ] {
            for k in 0..20 {
                let r = rot_z(0.7 * k as f64) * rot_x(0.3 * k as f64 + 0.1);
                let i = rotate(&r, &Mat3::from_diagonal(&Vec3::from(d)));
                let p = principal(&i, DEFAULT_KIND_RTOL);
                assert!((p.axes.determinant() - 1.0).abs() < 1e-12);
                let back = p.axes.transpose() * i * p.axes;
                let diag = Mat3::from_diagonal(&Vec3::from(p.moments));
                assert!((back - diag).amax() < 1e-12, "{back} vs {diag}");
            }
        }
        // Spherical: identity; symmetric about z: the pair is (x, y).
        assert_eq!(principal(&Mat3::identity(), 1e-9).axes, Mat3::identity());
        let p = principal(&Mat3::from_diagonal(&Vec3::new(1.0, 1.0, 2.0)), 1e-9);
        assert_eq!(p.axes, Mat3::identity());
    }

    #[test]
    fn kinds() {
        assert_eq!(
            classify([1.0, 1.0, 1.0], 1e-9).unwrap(),
            TopKind::SphericalTop
        );
        assert_eq!(
            classify([2.0, 1.0, 1.0], 1e-9).unwrap(),
            TopKind::SymmetricTop
        );
        assert_eq!(
            classify([1.0, 2.0, 3.0], 1e-9).unwrap(),
            TopKind::AsymmetricTop
        );
        assert_eq!(classify([1.0, 1.0, 0.0], 1e-9).unwrap(), TopKind::Rotor);
        assert_eq!(classify([0.0, 0.0, 0.0], 1e-9).unwrap(), TopKind::Rotor);
        assert_eq!(
            classify([1.0, 1.0 + 1e-12, 1.0], 1e-9).unwrap(),
            TopKind::SphericalTop
        );
        assert_eq!(
            classify([1.0, 1.0 + 1e-12, 1.0], 0.0).unwrap(),
            TopKind::SymmetricTop
        );
        assert!(classify([1.0, f64::NAN, 1.0], 1e-9).is_err());
        assert!(classify([1.0, 1.0, 1.0], -1.0).is_err());
        assert!(classify([0.0, 0.0, 1.0], 1e-9)
            .unwrap_err()
            .message
            .contains("triangle"));
    }

    #[test]
    fn triangle_margins_are_twice_the_second_moments() {
        // Cuboid m = 12, sides (1, 2, 3): I = (13, 10, 5), ascending (5, 10, 13) about z, y, x;
        // I_j + I_k − I_i = 2 · m a_i² / 12 = 2 a_i²: (2·9, 2·4, 2·1) in that order.
        let cub = crate::inertia::cuboid(12.0, [1.0, 2.0, 3.0]).unwrap();
        let m = cub.principal(DEFAULT_KIND_RTOL).triangle_margins();
        assert_eq!(m, [18.0, 8.0, 2.0]);
        // A lamina: the thin disk sits on the boundary (perpendicular-axis theorem).
        let disk = crate::inertia::thin_disk(2.0, 0.5).unwrap();
        let m = disk.principal(DEFAULT_KIND_RTOL).triangle_margins();
        assert!(m[2].abs() < 1e-16 && m[0] > 0.0 && m[1] > 0.0, "{m:?}");
    }
}
