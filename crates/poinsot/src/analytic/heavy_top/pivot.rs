//! A heavy top made of a real body: a symmetric [`MassProperties`] pivoted on its symmetry axis.
//!
//! The body's axis 3 (its reference z axis) must be its symmetry axis: a principal axis through
//! the centre of mass (I_xz = I_yz = 0) about which the transverse moments are equal
//! (I_xx = I_yy, I_xy = 0). The pivot lies on that axis at `pivot_distance` = l below the centre
//! of mass, so the centre of mass is at +l on axis 3 as [`HeavyTop`] requires, and
//!
//! - I₁ = I_xx + m l² (about a transverse axis through the pivot: the parallel-axis theorem,
//!   the unit's 2.59 / `MassProperties::inertia_about`),
//! - I₃ = I_zz (the symmetry axis passes through the pivot: unchanged),
//! - m g l (N·m), the torque of the weight per unit sin θ.

use super::{EulerState, HeavyTop};
use crate::error::{check_non_negative, check_result, Error, Result};
use crate::inertia::{MassProperties, DEFAULT_KIND_RTOL};

/// The relative tolerance of the symmetry check of [`heavy_top_parameters`]: the transverse
/// moments I_xx, I_yy and the products I_xy, I_xz, I_yz of the body (about its centre of mass,
/// in its axes) may differ from a symmetric top's by this fraction of the largest principal
/// moment (the tolerance under which `RigidBody.kind` calls two moments equal).
pub const PIVOT_SYMMETRY_RTOL: f64 = DEFAULT_KIND_RTOL;

/// The heavy top's parameters `[I1, I3, mgl]` (kg·m², kg·m², N·m) of the symmetric `body`
/// pivoted on its axis 3 at `pivot_distance` (m, ≥ 0) below its centre of mass, under gravity
/// `g` (m/s², ≥ 0): I₁ = I_xx + m l² (parallel axes), I₃ = I_zz, m g l.
///
/// Errors: `pivot_distance` or `g` negative or not finite; `body` when its axis 3 is not a
/// principal axis (I_xz or I_yz beyond [`PIVOT_SYMMETRY_RTOL`] of the largest moment) or its
/// transverse moments differ (I_xx ≠ I_yy or I_xy ≠ 0 beyond it), the message giving the
/// entries; `pivot_distance` when I₁ or m g l overflow.
///
/// ```
/// use poinsot::analytic::heavy_top_parameters;
/// use poinsot::inertia::thin_disk;
/// // A 0.2 kg disk of radius 5 cm, its centre 10 cm from the pivot.
/// let disk = thin_disk(0.2, 0.05)?;
/// let [i1, i3, mgl] = heavy_top_parameters(&disk, 0.1, 9.80665)?;
/// assert!((i1 - (0.2 * 0.05f64.powi(2) / 4.0 + 0.2 * 0.1f64.powi(2))).abs() < 1e-18);
/// assert!((i3 - 0.2 * 0.05f64.powi(2) / 2.0).abs() < 1e-18);
/// assert!((mgl - 0.2 * 9.80665 * 0.1).abs() < 1e-15);
/// # Ok::<(), poinsot::Error>(())
/// ```
pub fn heavy_top_parameters(
    body: &MassProperties,
    pivot_distance: f64,
    g: f64,
) -> Result<[f64; 3]> {
    check_non_negative("pivot_distance", pivot_distance)?;
    check_non_negative("g", g)?;
    let i = body.inertia();
    let largest = body.principal(PIVOT_SYMMETRY_RTOL).moments[2];
    let tol = PIVOT_SYMMETRY_RTOL * largest;
    let (ixx, iyy, izz) = (i[(0, 0)], i[(1, 1)], i[(2, 2)]);
    let (ixy, ixz, iyz) = (i[(0, 1)], i[(0, 2)], i[(1, 2)]);
    if ixz.abs() > tol || iyz.abs() > tol {
        return Err(Error::invalid(
            "body",
            format!(
                "its axis 3 (z) must be a principal axis (the symmetry axis through the pivot), \
                 got I_xz = {ixz:e}, I_yz = {iyz:e} kg·m² (largest moment {largest:e}); rotate \
                 the body so that its symmetry axis is z"
            ),
        ));
    }
    if (ixx - iyy).abs() > tol || ixy.abs() > tol {
        return Err(Error::invalid(
            "body",
            format!(
                "must be symmetric about its axis 3 (z) for a heavy symmetric top (I1 = I2), got \
                 I_xx = {ixx:e}, I_yy = {iyy:e}, I_xy = {ixy:e} kg·m² (equal within {:e} of the \
                 largest moment required)",
                PIVOT_SYMMETRY_RTOL
            ),
        ));
    }
    let m = body.mass();
    // The mean of the two (equal) transverse moments, plus m l² (parallel axes).
    let i1 = 0.5 * (ixx + iyy) + m * pivot_distance * pivot_distance;
    let mgl = m * g * pivot_distance;
    check_result("pivot_distance", "I1 about the pivot, m g l", &[i1, mgl])?;
    Ok([i1, izz, mgl])
}

impl HeavyTop {
    /// The top made of the symmetric `body` pivoted on its axis 3 at `pivot_distance` (m) below
    /// its centre of mass under gravity `g` (m/s²) ([`heavy_top_parameters`]), started at time
    /// 0 from `state` (rad, rad/s) as [`HeavyTop::new`]. Errors as both.
    pub fn from_body(
        body: &MassProperties,
        pivot_distance: f64,
        g: f64,
        state: EulerState,
    ) -> Result<Self> {
        let [i1, i3, mgl] = heavy_top_parameters(body, pivot_distance, g)?;
        Self::new(i1, i3, mgl, state)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analytic::steady_precession;
    use crate::inertia::{cuboid, solid_cone, solid_cylinder, thin_disk};
    use crate::ErrorKind;

    /// The lead's example by hand: a 0.2 kg disk of radius 5 cm, 10 cm from its pivot, spun at
    /// 1500 rpm, tilted 30°. I₁ = m r²/4 + m d² = 2.125e-3 kg·m², I₃ = m r²/2 = 2.5e-4 kg·m²,
    /// m g l = 0.196133 N·m; its steady precession rates are the roots of 2.116,
    /// I₁ cos θ φ̇² − p_ψ φ̇ + m g l = 0, by the quadratic formula.
    #[test]
    fn the_disk_on_a_pivot_matches_the_hand_computation() {
        let (m, r, d, g) = (0.2, 0.05, 0.1, 9.80665);
        let disk = thin_disk(m, r).unwrap();
        let [i1, i3, mgl] = heavy_top_parameters(&disk, d, g).unwrap();
        assert!((i1 - 2.125e-3).abs() < 1e-17, "{i1}");
        assert!((i3 - 2.5e-4).abs() < 1e-18, "{i3}");
        assert!((mgl - 0.196133).abs() < 1e-15, "{mgl}");
        let omega3 = 1500.0 * 2.0 * std::f64::consts::PI / 60.0;
        let theta = 30f64.to_radians();
        let p = i3 * omega3;
        let a = i1 * theta.cos();
        let disc = (p * p - 4.0 * a * mgl).sqrt();
        let (slow, fast) = ((p - disc) / (2.0 * a), (p + disc) / (2.0 * a));
        let s = steady_precession(i1, i3, mgl, theta, omega3).unwrap();
        assert!((s.slow - slow).abs() < 1e-12 * slow, "{} {slow}", s.slow);
        assert!((s.fast - fast).abs() < 1e-12 * fast, "{} {fast}", s.fast);
        // 1500 rpm is only 3.3 % above the least spin 2.119, (2/I₃)√(m g l I₁ cos θ) = 152.0
        // rad/s: the slow rate, 7.975 rad/s, is far from the fast-top m g l / p_ψ = 4.99 rad/s.
        let least = 2.0 / i3 * (mgl * i1 * theta.cos()).sqrt();
        assert!((s.min_spin - least).abs() < 1e-13 * least);
        assert!((omega3 / least - 1.0335).abs() < 1e-4, "{}", omega3 / least);
        assert!((slow - 7.975).abs() < 1e-3, "{slow}");
        // The top from the body is the top of these parameters, bit for bit.
        let state = EulerState::with_rates(theta, 0.0, 0.0, omega3);
        let top = HeavyTop::from_body(&disk, d, g, state).unwrap();
        let same = HeavyTop::new(i1, i3, mgl, state).unwrap();
        assert_eq!((top.i1(), top.i3(), top.mgl()), (i1, i3, mgl));
        assert_eq!(
            top.euler_angles(0.3).unwrap(),
            same.euler_angles(0.3).unwrap()
        );
    }

    /// I₁ about the pivot is the body's own parallel-axis shift (`inertia_about` a point on the
    /// axis l below the centre of mass), and I₃ its moment about z, for any symmetric solid —
    /// also one whose centre of mass is not at the origin (the cone: apex at the origin).
    #[test]
    fn parameters_are_the_parallel_axis_shift_of_the_body() {
        for body in [
            solid_cylinder(1.5, 0.3, 2.0).unwrap(),
            solid_cone(2.0, 0.5, 1.2).unwrap(),
            cuboid(3.0, [0.4, 0.4, 1.0]).unwrap(),
        ] {
            let l = 0.7;
            let pivot = body.center_of_mass() - crate::Vec3::new(0.0, 0.0, l);
            let about = body.inertia_about(&pivot).unwrap();
            let [i1, i3, mgl] = heavy_top_parameters(&body, l, 9.81).unwrap();
            assert!((i1 - about[(0, 0)]).abs() < 1e-14 * i1);
            assert!((i1 - about[(1, 1)]).abs() < 1e-14 * i1);
            assert!((i3 - about[(2, 2)]).abs() < 1e-14 * i3);
            assert!((mgl - body.mass() * 9.81 * l).abs() < 1e-14 * mgl);
        }
    }

    /// Negative controls: an asymmetric box (I_xx ≠ I_yy) and a disk tipped off its axis
    /// (I_xz ≠ 0) are refused naming `body`; a negative distance names `pivot_distance`.
    #[test]
    fn an_asymmetric_body_or_a_tilted_axis_is_refused_naming_body() {
        let b = cuboid(1.0, [0.1, 0.2, 0.3]).unwrap();
        let e = heavy_top_parameters(&b, 0.1, 9.81).unwrap_err();
        assert_eq!(
            (e.argument.as_str(), e.kind),
            ("body", ErrorKind::InvalidArgument)
        );
        assert!(e.to_string().contains("symmetric"), "{e}");
        let tipped = thin_disk(1.0, 1.0)
            .unwrap()
            .rotated(&crate::rotation::axis_angle_to_matrix(&crate::Vec3::x(), 0.3).unwrap())
            .unwrap();
        let e = heavy_top_parameters(&tipped, 0.1, 9.81).unwrap_err();
        assert_eq!(e.argument, "body");
        assert!(e.to_string().contains("principal axis"), "{e}");
        // A disk turned about its own axis stays symmetric: accepted.
        let turned = thin_disk(1.0, 1.0)
            .unwrap()
            .rotated(&crate::rotation::axis_angle_to_matrix(&crate::Vec3::z(), 0.3).unwrap())
            .unwrap();
        assert!(heavy_top_parameters(&turned, 0.1, 9.81).is_ok());
        let e = heavy_top_parameters(&thin_disk(1.0, 1.0).unwrap(), -0.1, 9.81).unwrap_err();
        assert_eq!(e.argument, "pivot_distance");
        let e = heavy_top_parameters(&thin_disk(1.0, 1.0).unwrap(), 0.1, f64::NAN).unwrap_err();
        assert_eq!(e.argument, "g");
    }
}
