//! Kinematics of Euler angles: the angular velocity from the angles and their rates (the unit's
//! eqs. 2.98–2.99, generalised to all 24 conventions) and the inverse, the rates from ω.
//!
//! For an intrinsic sequence `(a, b, c)` with angles `(α, β, γ)`, `R = R_a(α) R_b(β) R_c(γ)`,
//! each rate turns the body about the current position of its axis:
//!
//! ```text
//! ω_space = α̇ e_a + β̇ R_a(α) e_b + γ̇ R_a(α) R_b(β) e_c
//! ω_body  = Rᵀ ω_space = α̇ R_c(γ)ᵀ R_b(β)ᵀ e_a + β̇ R_c(γ)ᵀ e_b + γ̇ e_c
//! ```
//!
//! (`skew(ω_space) = Ṙ Rᵀ`, `skew(ω_body) = Rᵀ Ṙ`). An extrinsic sequence `(a, b, c)` with
//! `(α, β, γ)` is the intrinsic `(c, b, a)` with `(γ, β, α)`, rates likewise. For the unit's
//! intrinsic `zxz` (φ, θ, ψ) the body components are the unit's eq. 2.99 (with its erratum
//! `ω₃ = ω_ζ`):
//!
//! ```text
//! ω₁ = φ̇ sin θ sin ψ + θ̇ cos ψ
//! ω₂ = φ̇ sin θ cos ψ − θ̇ sin ψ
//! ω₃ = φ̇ cos θ + ψ̇
//! ```
//!
//! The map `rates ↦ ω` has determinant `−sin β` (proper Euler) or `±cos β` (Tait–Bryan): the
//! rates are undefined at gimbal lock, where [`euler_rates`] returns [`Error::gimbal_lock`].

use crate::error::{check_finite, Error, Result};
use crate::rotation::euler::{EulerSequence, SequenceKind};
use crate::rotation::matrix::elementary_rotation;
use crate::{Mat3, Vec3};

/// [`euler_rates`] refuses angles whose middle angle has `|sin β|` (proper Euler) or `|cos β|`
/// (Tait–Bryan) at most this (`1e-12`): there the rates would exceed `10¹²·|ω|` and the exact
/// singularity is within round-off of the given angle (`sin(π)` is `1.2e-16` in floating point).
pub const RATES_LOCK_TOL: f64 = 1e-12;

/// The frame in which angular-velocity components are expressed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Frame {
    /// Body axes (1, 2, 3 of the unit): `ω_body = Rᵀ ω_space`.
    Body,
    /// Space (fixed) axes (X, Y, Z of the unit).
    Space,
}

impl std::str::FromStr for Frame {
    type Err = Error;
    /// `"body"` or `"space"`; the error names `frame`.
    fn from_str(name: &str) -> Result<Self> {
        match name {
            "body" => Ok(Frame::Body),
            "space" => Ok(Frame::Space),
            _ => Err(Error::invalid(
                "frame",
                format!("must be 'body' or 'space', got {name:?}"),
            )),
        }
    }
}

/// Columns of the map from rates (intrinsic order) to ω, for intrinsic axes `[a, b, c]`.
fn intrinsic_columns(axes: [usize; 3], angles: [f64; 3], frame: Frame) -> [Vec3; 3] {
    let [a, b, c] = axes;
    let [al, be, ga] = angles;
    let e = |k: usize| Vec3::ith(k, 1.0);
    match frame {
        Frame::Space => {
            let ra = elementary_rotation(a, al);
            let rab = ra * elementary_rotation(b, be);
            [e(a), ra.column(b).into_owned(), rab.column(c).into_owned()]
        }
        Frame::Body => {
            let rct = elementary_rotation(c, -ga);
            let rcbt = rct * elementary_rotation(b, -be);
            [
                rcbt.column(a).into_owned(),
                rct.column(b).into_owned(),
                e(c),
            ]
        }
    }
}

/// The matrix `J(angles)` with `ω = J · rates` (ω in `frame`, rad/s; rates in the order of the
/// sequence's name, rad/s). Errors: non-finite angles (naming `"angles"`).
pub fn angular_velocity_matrix(angles: [f64; 3], seq: EulerSequence, frame: Frame) -> Result<Mat3> {
    check_finite("angles", &angles)?;
    let cols = intrinsic_columns(seq.intrinsic_axes(), seq.in_intrinsic_order(angles), frame);
    let cols = seq.in_intrinsic_order(cols);
    Ok(Mat3::from_columns(&cols))
}

/// The angular velocity (rad/s) in `frame` of a body whose Euler angles `angles` (rad) in
/// convention `seq` change at `rates` (rad/s, same order as the angles): eqs. 2.98–2.99
/// generalised (see the module documentation). Errors: non-finite input (naming `"angles"` or
/// `"rates"`), or an angular velocity beyond the doubles (naming `"rates"`).
pub fn angular_velocity(
    angles: [f64; 3],
    rates: [f64; 3],
    seq: EulerSequence,
    frame: Frame,
) -> Result<Vec3> {
    check_finite("angles", &angles)?;
    check_finite("rates", &rates)?;
    angular_velocity_checked_input(angles, rates, seq, frame)
}

/// [`angular_velocity`] after the finiteness checks: refuses an angular velocity beyond the
/// doubles (naming `"rates"`).
#[inline]
pub(crate) fn angular_velocity_checked_input(
    angles: [f64; 3],
    rates: [f64; 3],
    seq: EulerSequence,
    frame: Frame,
) -> Result<Vec3> {
    let w = angular_velocity_unchecked(angles, rates, seq, frame);
    if !w.iter().all(|c| c.is_finite()) {
        return Err(Error::invalid(
            "rates",
            "the angular velocity overflows for these rates",
        ));
    }
    Ok(w)
}

#[inline]
pub(crate) fn angular_velocity_unchecked(
    angles: [f64; 3],
    rates: [f64; 3],
    seq: EulerSequence,
    frame: Frame,
) -> Vec3 {
    let cols = intrinsic_columns(seq.intrinsic_axes(), seq.in_intrinsic_order(angles), frame);
    let r = seq.in_intrinsic_order(rates);
    cols[0] * r[0] + cols[1] * r[1] + cols[2] * r[2]
}

/// Body-frame angular velocity (rad/s): for the unit's intrinsic `zxz` this is eq. 2.99.
pub fn body_angular_velocity(
    angles: [f64; 3],
    rates: [f64; 3],
    seq: EulerSequence,
) -> Result<Vec3> {
    angular_velocity(angles, rates, seq, Frame::Body)
}

/// Space-frame angular velocity (rad/s), `R ω_body`.
pub fn space_angular_velocity(
    angles: [f64; 3],
    rates: [f64; 3],
    seq: EulerSequence,
) -> Result<Vec3> {
    angular_velocity(angles, rates, seq, Frame::Space)
}

/// The Euler-angle rates (rad/s, in the order of the sequence's name) that produce angular
/// velocity `omega` (rad/s, components in `frame`) at `angles` (rad): the inverse of
/// [`angular_velocity`].
///
/// Errors: non-finite input, or rates beyond the doubles (naming `"angles"` or
/// `"omega_body"`); [`Error::gimbal_lock`] naming
/// `"angles"` where `|sin β|` (proper Euler) or `|cos β|` (Tait–Bryan) is at most
/// [`RATES_LOCK_TOL`].
pub fn euler_rates(
    angles: [f64; 3],
    omega: &Vec3,
    seq: EulerSequence,
    frame: Frame,
) -> Result<[f64; 3]> {
    check_finite("angles", &angles)?;
    check_finite("omega_body", omega.as_slice())?;
    euler_rates_checked_input(angles, omega, seq, frame)
}

/// [`euler_rates`] after the finiteness checks (the gimbal-lock check and the check of the
/// rates are here).
#[inline]
pub(crate) fn euler_rates_checked_input(
    angles: [f64; 3],
    omega: &Vec3,
    seq: EulerSequence,
    frame: Frame,
) -> Result<[f64; 3]> {
    let axes = seq.intrinsic_axes();
    let ang = seq.in_intrinsic_order(angles);
    let beta = ang[1];
    let (s, c) = beta.sin_cos();
    // det J = −sin β (proper) or ε cos β (Tait–Bryan, ε = parity of the intrinsic axes), for
    // both frames (J_body = Rᵀ J_space); computed from β directly, not as a triple product.
    let (det, measure, name) = match seq.kind() {
        SequenceKind::ProperEuler => (-s, s, "sin"),
        SequenceKind::TaitBryan => {
            let eps = if (axes[1] + 3 - axes[0]) % 3 == 1 {
                1.0
            } else {
                -1.0
            };
            (eps * c, c, "cos")
        }
    };
    if measure.abs() <= RATES_LOCK_TOL {
        let (family, sing) = match seq.kind() {
            SequenceKind::ProperEuler => ("proper Euler", "sin β = 0, i.e. β = 0 or π"),
            SequenceKind::TaitBryan => ("Tait–Bryan", "cos β = 0, i.e. β = ±π/2"),
        };
        return Err(Error::gimbal_lock(
            "angles",
            format!(
                "Euler-angle rates are undefined at gimbal lock: the middle angle angles[1] = β = \
                 {beta} rad has |{name} β| = {:.1e} <= {RATES_LOCK_TOL:.0e} ({family} sequence \
                 {seq}: singular where {sing})",
                measure.abs()
            ),
        ));
    }
    let [c1, c2, c3] = intrinsic_columns(axes, ang, frame);
    let rates = [
        c2.cross(&c3).dot(omega) / det,
        c3.cross(&c1).dot(omega) / det,
        c1.cross(&c2).dot(omega) / det,
    ];
    if !rates.iter().all(|c| c.is_finite()) {
        return Err(Error::invalid(
            "omega_body",
            "the Euler-angle rates overflow for this angular velocity",
        ));
    }
    Ok(seq.in_intrinsic_order(rates))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ErrorKind;

    #[test]
    fn unit_eq_2_99_body_components() {
        let (phi, theta, psi) = (0.4, 1.2, -0.9);
        let (dphi, dtheta, dpsi) = (1.5, -0.7, 3.0);
        let w = body_angular_velocity([phi, theta, psi], [dphi, dtheta, dpsi], EulerSequence::UNIT)
            .unwrap();
        let expected = Vec3::new(
            dphi * theta.sin() * psi.sin() + dtheta * psi.cos(),
            dphi * theta.sin() * psi.cos() - dtheta * psi.sin(),
            dphi * theta.cos() + dpsi,
        );
        assert!((w - expected).norm() < 1e-15, "{w} vs {expected}");
        let back = euler_rates([phi, theta, psi], &w, EulerSequence::UNIT, Frame::Body).unwrap();
        for (a, b) in back.iter().zip([dphi, dtheta, dpsi]) {
            assert!((a - b).abs() < 1e-14);
        }
    }

    #[test]
    fn gimbal_lock_is_an_error_naming_the_angle() {
        let e = euler_rates(
            [0.3, std::f64::consts::PI, 0.1],
            &Vec3::x(),
            EulerSequence::UNIT,
            Frame::Body,
        )
        .unwrap_err();
        assert_eq!(e.kind, ErrorKind::GimbalLock);
        assert!(
            e.to_string().starts_with("angles: ") && e.message.contains("angles[1]"),
            "{e}"
        );
        let xyz = EulerSequence::new("xyz", false).unwrap();
        let e = euler_rates(
            [0.3, -std::f64::consts::FRAC_PI_2, 0.1],
            &Vec3::x(),
            xyz,
            Frame::Space,
        );
        assert_eq!(e.unwrap_err().kind, ErrorKind::GimbalLock);
    }

    /// Finite or refused in the scalar functions too (the batch kernels checked this, the
    /// browser's binding guarded it): rates or an angular velocity beyond the doubles name the
    /// argument.
    #[test]
    fn results_beyond_the_doubles_name_the_argument() {
        let e =
            body_angular_velocity([0.1, 0.2, 0.3], [1e308; 3], EulerSequence::UNIT).unwrap_err();
        assert_eq!(e.argument, "rates");
        assert!(e.message.contains("overflows"), "{e}");
        let e = euler_rates(
            [0.1, 1e-7, 0.3],
            &Vec3::new(1e308, 1e308, 0.0),
            EulerSequence::UNIT,
            Frame::Body,
        )
        .unwrap_err();
        assert_eq!(e.argument, "omega_body", "{e}");
        // Negative control: large but representable.
        assert!(body_angular_velocity([0.1, 0.2, 0.3], [1e300; 3], EulerSequence::UNIT).is_ok());
    }
}
