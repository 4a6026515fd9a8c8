//! Rotation matrices: validation, elementary rotations about the coordinate axes, composition
//! and application to vectors.
//!
//! Rotations are active: `R` turns a vector `v` into `R v`; a body's attitude `R` maps its
//! body-frame components to space-frame components (`x_space = R x_body`).

use crate::error::{check_finite, Error, Result};
use crate::{Mat3, Vec3};

/// Tolerance on `max |RᵀR − I|` and `|det R − 1|` with which every function that *takes* a
/// rotation matrix accepts it (`1e-6`: forgiving of matrices stored in single precision or
/// composed many times, strict enough to reject a scaled, sheared or reflected matrix). The
/// explicit validator [`check_rotation_matrix`] takes its own tolerance.
pub const ROTATION_MATRIX_TOL: f64 = 1e-6;

/// Orthonormality defect `max |RᵀR − I|` up to which a function that *converts* a rotation
/// matrix (to a quaternion, Euler angles, an axis and angle, a screw) uses the matrix's own
/// entries; above it (and within [`ROTATION_MATRIX_TOL`]) it converts the nearest rotation
/// instead (the orthogonal factor of the polar decomposition, `nearest_rotation`, what
/// scipy's `Rotation.from_matrix` takes). `16 ε ≈ 3.6e-15`: a matrix built in double precision
/// from angles or a unit quaternion is off by up to about 12 ε and is converted as it is, bit
/// for bit as before; one printed to 7 decimals (off by about 1e-7) is projected, which moves
/// its quaternion by about the defect (for the example in `docs/rotation.md`, from 3.2e-8 to
/// 3.6e-9 off the quaternion of the rotation before rounding).
pub const NEAREST_ROTATION_DEFECT: f64 = 16.0 * f64::EPSILON;

/// Most iterations of [`nearest_rotation`]: from the largest accepted defect, 1e-6, the error
/// goes 1e-6 → 4e-13 → round-off, so two suffice; the rest is margin.
const NEAREST_ROTATION_ITERATIONS: usize = 4;

/// The active rotation by `angle` (rad) about the x axis:
/// `[[1, 0, 0], [0, cos, −sin], [0, sin, cos]]`.
pub fn rot_x(angle: f64) -> Mat3 {
    let (s, c) = angle.sin_cos();
    Mat3::new(1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c)
}

/// The active rotation by `angle` (rad) about the y axis:
/// `[[cos, 0, sin], [0, 1, 0], [−sin, 0, cos]]`.
pub fn rot_y(angle: f64) -> Mat3 {
    let (s, c) = angle.sin_cos();
    Mat3::new(c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c)
}

/// The active rotation by `angle` (rad) about the z axis:
/// `[[cos, −sin, 0], [sin, cos, 0], [0, 0, 1]]` (turns `e_x` towards `e_y`).
pub fn rot_z(angle: f64) -> Mat3 {
    let (s, c) = angle.sin_cos();
    Mat3::new(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0)
}

/// The active rotation by `angle` (rad) about coordinate axis `axis` (0 = x, 1 = y, 2 = z).
///
/// # Panics
/// Never for `axis < 3`; an `axis >= 3` is a programming error and panics.
pub fn elementary_rotation(axis: usize, angle: f64) -> Mat3 {
    match axis {
        0 => rot_x(angle),
        1 => rot_y(angle),
        2 => rot_z(angle),
        _ => panic!("coordinate axis index must be 0, 1 or 2, got {axis}"),
    }
}

/// The composition `R_1 R_2 ⋯ R_n` of `rotations` (the last one acts first on a vector);
/// the identity for an empty slice. Each factor is checked with [`ROTATION_MATRIX_TOL`].
pub fn compose(rotations: &[Mat3]) -> Result<Mat3> {
    let mut out = Mat3::identity();
    for (i, r) in rotations.iter().enumerate() {
        check_rotation_matrix_named(&format!("rotations[{i}]"), r, ROTATION_MATRIX_TOL)?;
        out *= r;
    }
    Ok(out)
}

/// Applies the rotation `r` to every vector of `v`: `R v_k` (space components of body-fixed
/// vectors, for an attitude `R`). `r` is checked with [`ROTATION_MATRIX_TOL`]; `v` must be finite.
pub fn rotate_vectors(r: &Mat3, v: &[Vec3]) -> Result<Vec<Vec3>> {
    check_rotation_matrix(r, ROTATION_MATRIX_TOL)?;
    v.iter()
        .map(|x| {
            check_finite("v", x.as_slice())?;
            Ok(r * x)
        })
        .collect()
}

/// Checks that `r` is a proper rotation within `tol`: finite, orthonormal
/// (`max |RᵀR − I| <= tol`) and `|det R − 1| <= tol`. The error names the argument `"R"`.
pub fn check_rotation_matrix(r: &Mat3, tol: f64) -> Result<()> {
    check_rotation_matrix_named("R", r, tol)
}

/// [`check_rotation_matrix`] for an argument named `argument`.
///
/// Errors: [`Error::invalid`] for a non-finite entry or a bad `tol`; [`Error::rotation`] saying
/// which condition fails and by how much (orthonormality defect, or a determinant that is not
/// +1, e.g. −1 for a reflection).
pub fn check_rotation_matrix_named(argument: &str, r: &Mat3, tol: f64) -> Result<()> {
    if !(tol.is_finite() && tol >= 0.0) {
        return Err(Error::invalid(
            "tol",
            format!("must be finite and >= 0, got {tol}"),
        ));
    }
    let m = row_major(r);
    check_finite(argument, &m)?;
    let (defect, det) = rotation_defects(&m);
    rotation_verdict(argument, defect, det, tol)
}

/// `(max |RᵀR − I|, det R)` of a row-major matrix (used by the single and batch checks).
pub(crate) fn rotation_defects(m: &[f64; 9]) -> (f64, f64) {
    // Gram matrix of the columns, upper triangle (RᵀR is symmetric).
    let col = |j: usize| [m[j], m[3 + j], m[6 + j]];
    let (c0, c1, c2) = (col(0), col(1), col(2));
    let dot = |a: &[f64; 3], b: &[f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let defect = (dot(&c0, &c0) - 1.0)
        .abs()
        .max((dot(&c1, &c1) - 1.0).abs())
        .max((dot(&c2, &c2) - 1.0).abs())
        .max(dot(&c0, &c1).abs())
        .max(dot(&c0, &c2).abs())
        .max(dot(&c1, &c2).abs());
    let det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6])
        + m[2] * (m[3] * m[7] - m[4] * m[6]);
    (defect, det)
}

/// The error (if any) for a matrix with orthonormality defect `defect` and determinant `det`.
/// NaN defects (non-finite input) are reported as non-orthonormal.
pub(crate) fn rotation_verdict(argument: &str, defect: f64, det: f64, tol: f64) -> Result<()> {
    if defect.is_nan() || defect > tol {
        let extra = if det < 0.0 {
            " (and det < 0: it also reflects)"
        } else {
            ""
        };
        return Err(Error::rotation(
            argument,
            format!(
                "not a rotation matrix: not orthonormal, max |RᵀR − I| = {defect:.3e} exceeds \
                 tol = {tol:.1e}{extra}"
            ),
        ));
    }
    if det.is_nan() || (det - 1.0).abs() > tol {
        let what = if det < 0.0 {
            "a reflection (improper), not a proper rotation"
        } else {
            "not +1"
        };
        return Err(Error::rotation(
            argument,
            format!(
                "not a rotation matrix: det R = {det:.6} is {what}; |det R − 1| = {:.3e} exceeds \
                 tol = {tol:.1e}",
                (det - 1.0).abs()
            ),
        ));
    }
    Ok(())
}

/// Checks the row-major matrix `m` named `argument` with [`ROTATION_MATRIX_TOL`] (errors as
/// [`check_rotation_matrix_named`]) and returns the rotation a conversion should use: `m`
/// itself when its defect is at most [`NEAREST_ROTATION_DEFECT`] (the common, exact case: one
/// comparison more than the check), else [`nearest_rotation`] of `m`.
#[inline]
pub(crate) fn rotation_to_convert(argument: &str, m: &[f64; 9]) -> Result<[f64; 9]> {
    if !m.iter().all(|v| v.is_finite()) {
        check_finite(argument, m)?;
    }
    let (defect, det) = rotation_defects(m);
    rotation_verdict(argument, defect, det, ROTATION_MATRIX_TOL)?;
    Ok(if defect <= NEAREST_ROTATION_DEFECT {
        *m
    } else {
        nearest_rotation(m)
    })
}

/// The rotation nearest to the row-major matrix `m` in the Frobenius norm (and every other
/// unitarily invariant norm): the orthogonal factor `U` of the polar decomposition `m = U H`
/// (`U = V Wᵀ` of the SVD `m = V Σ Wᵀ`; a rotation since `det m > 0`). Computed by the
/// Newton–Schulz (Björck–Bowie) iteration `X ← X (3I − XᵀX) / 2`, which converges
/// quadratically to `U` for `‖XᵀX − I‖ < 1`, until `max |XᵀX − I| <= NEAREST_ROTATION_DEFECT`.
/// For `m` within [`ROTATION_MATRIX_TOL`] of orthonormal (the caller's check) two iterations
/// reach round-off.
pub(crate) fn nearest_rotation(m: &[f64; 9]) -> [f64; 9] {
    let mut x = *m;
    for _ in 0..NEAREST_ROTATION_ITERATIONS {
        // G = XᵀX (symmetric), then H = (3I − G) / 2 and X ← X H.
        let g = |i: usize, j: usize| x[i] * x[j] + x[3 + i] * x[3 + j] + x[6 + i] * x[6 + j];
        let (g00, g11, g22) = (g(0, 0), g(1, 1), g(2, 2));
        let (g01, g02, g12) = (g(0, 1), g(0, 2), g(1, 2));
        let defect = (g00 - 1.0)
            .abs()
            .max((g11 - 1.0).abs())
            .max((g22 - 1.0).abs())
            .max(g01.abs())
            .max(g02.abs())
            .max(g12.abs());
        if defect <= NEAREST_ROTATION_DEFECT {
            break;
        }
        let h = [
            [1.5 - 0.5 * g00, -0.5 * g01, -0.5 * g02],
            [-0.5 * g01, 1.5 - 0.5 * g11, -0.5 * g12],
            [-0.5 * g02, -0.5 * g12, 1.5 - 0.5 * g22],
        ];
        let mut y = [0.0; 9];
        for r in 0..3 {
            for c in 0..3 {
                y[3 * r + c] = x[3 * r] * h[0][c] + x[3 * r + 1] * h[1][c] + x[3 * r + 2] * h[2][c];
            }
        }
        x = y;
    }
    x
}

/// Row-major copy of a nalgebra (column-major) matrix.
pub(crate) fn row_major(r: &Mat3) -> [f64; 9] {
    [
        r[(0, 0)],
        r[(0, 1)],
        r[(0, 2)],
        r[(1, 0)],
        r[(1, 1)],
        r[(1, 2)],
        r[(2, 0)],
        r[(2, 1)],
        r[(2, 2)],
    ]
}

/// A nalgebra matrix from row-major entries.
pub(crate) fn from_row_major(m: &[f64; 9]) -> Mat3 {
    Mat3::new(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ErrorKind;

    #[test]
    fn elementary_rotations_are_active_and_right_handed() {
        // R_z(90°) turns e_x into e_y, R_x(90°) turns e_y into e_z, R_y(90°) turns e_z into e_x.
        let q = std::f64::consts::FRAC_PI_2;
        assert!((rot_z(q) * Vec3::x() - Vec3::y()).norm() < 1e-15);
        assert!((rot_x(q) * Vec3::y() - Vec3::z()).norm() < 1e-15);
        assert!((rot_y(q) * Vec3::z() - Vec3::x()).norm() < 1e-15);
        for a in 0..3 {
            assert_eq!(elementary_rotation(a, 0.3), [rot_x, rot_y, rot_z][a](0.3));
        }
    }

    #[test]
    fn check_names_the_failure() {
        let mut r = rot_z(0.4);
        assert!(check_rotation_matrix(&r, 1e-12).is_ok());
        r[(0, 0)] *= 2.0;
        let e = check_rotation_matrix(&r, 1e-9).unwrap_err();
        assert_eq!(e.kind, ErrorKind::InvalidRotation);
        assert!(
            e.to_string().starts_with("R: ") && e.message.contains("orthonormal"),
            "{e}"
        );
        let refl = Mat3::from_diagonal(&Vec3::new(1.0, 1.0, -1.0));
        let e = check_rotation_matrix_named("attitude", &refl, 1e-9).unwrap_err();
        assert!(
            e.to_string().starts_with("attitude: ") && e.message.contains("reflection"),
            "{e}"
        );
        let mut nan = Mat3::identity();
        nan[(1, 2)] = f64::NAN;
        assert_eq!(
            check_rotation_matrix(&nan, 1e-9).unwrap_err().kind,
            ErrorKind::InvalidArgument
        );
        assert!(compose(&[rot_x(0.1), refl])
            .unwrap_err()
            .to_string()
            .starts_with("rotations[1]"));
    }

    #[test]
    fn compose_applies_the_last_factor_first() {
        let v = Vec3::new(0.3, -1.2, 2.0);
        let r = compose(&[rot_x(0.7), rot_z(-0.4)]).unwrap();
        assert!((r * v - rot_x(0.7) * (rot_z(-0.4) * v)).norm() < 1e-15);
        let out = rotate_vectors(&r, &[v, Vec3::x()]).unwrap();
        assert!((out[0] - r * v).norm() == 0.0);
    }
}
