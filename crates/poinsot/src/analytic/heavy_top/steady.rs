//! Steady precession of the heavy top: the exact slow and fast rates (the unit's 2.114–2.117,
//! both roots), the fast-top approximations 2.120–2.121, the minimum spin 2.119 and the
//! sleeping-top threshold.
//!
//! A top at a fixed nutation angle θ₀ with spin ω₃ precesses steadily at φ̇ when
//! `b = p_φ − p_ψ cos θ₀ = I₁ φ̇ sin²θ₀` solves 2.116,
//! `b² cos θ₀ − b p_ψ sin²θ₀ + m g l I₁ sin⁴θ₀ = 0`, i.e. (dividing by I₁ sin⁴θ₀)
//! `I₁ cos θ₀ φ̇² − p_ψ φ̇ + m g l = 0` with p_ψ = I₃ω₃ (2.103).
//!
//! Errata (see `docs/heavy_top.md`): the unit's 2.117 has p_φ² under the square root where
//! p_ψ² belongs (2.118 then uses p_ψ, correctly), and its 2.120 has a spurious factor ½: the
//! fast rate of a fast top is `φ̇_fast ≈ p_ψ/(I₁ cos θ₀) = I₃ω₃/(I₁ cos θ₀)`.

use super::validate::{check_theta, check_top};
use crate::error::{Error, Result};

/// The two steady-precession rates at one nutation angle and spin, exact and approximate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyPrecession {
    /// The exact slow rate φ̇_slow (rad/s): the root of 2.116 of smaller magnitude.
    pub slow: f64,
    /// The exact fast rate φ̇_fast (rad/s), the other root; infinite at θ₀ = π/2, where 2.116
    /// degenerates to a linear equation and only the slow rate exists.
    pub fast: f64,
    /// The unit's 2.121, `m g l / p_ψ` (rad/s): the slow rate of a fast top; `None` where it does
    /// not exist (no spin, p_ψ = 0: a conical pendulum, whose exact rates are still `slow` and
    /// `fast`) or exceeds the largest double.
    pub slow_approx: Option<f64>,
    /// The unit's 2.120 corrected, `p_ψ / (I₁ cos θ₀)` (rad/s): the fast rate of a fast top.
    pub fast_approx: f64,
    /// 2.120 as the unit prints it, `p_ψ / (2 I₁ cos θ₀)` (rad/s) — a misprint, kept to show
    /// that it is off by a factor 2 (`fast_approx` is the correct approximation).
    pub fast_approx_as_printed: f64,
    /// The minimum spin 2.119 at this angle (rad/s): steady precession needs |ω₃| ≥ this.
    pub min_spin: f64,
}

/// The minimum spin for steady precession at θ₀ (the unit's 2.119):
/// `ω₃,min = (2/I₃) √(m g l I₁ cos θ₀)` for θ₀ < π/2, and 0 for θ₀ ≥ π/2 (below the horizontal
/// any spin will do, 2.118). At θ₀ = 0 it is the sleeping-top threshold
/// [`sleeping_threshold`]. Errors name `I1`, `I3`, `mgl`, `theta0`, and `I3` where the spin is
/// beyond the range of double precision (I₃ tiny next to √(m g l I₁)).
pub fn min_spin(i1: f64, i3: f64, mgl: f64, theta0: f64) -> Result<f64> {
    check_top(i1, i3, mgl)?;
    check_theta("theta0", theta0)?;
    let c = theta0.cos();
    if c > 0.0 {
        spin_bound(mgl, i1 * c, i3)
    } else {
        Ok(0.0)
    }
}

/// The sleeping-top threshold: a top spinning upright (θ = 0) is stable iff
/// `ω₃² > 4 m g l I₁ / I₃²`, i.e. |ω₃| > `2 √(m g l I₁) / I₃` (rad/s), which this returns.
/// Errors name `I1`, `I3`, `mgl`, and `I3` where the threshold is beyond double precision.
pub fn sleeping_threshold(i1: f64, i3: f64, mgl: f64) -> Result<f64> {
    check_top(i1, i3, mgl)?;
    spin_bound(mgl, i1, i3)
}

/// `2 √(mgl · x) / I₃` (2.119 with x = I₁ cos θ₀): as a single square root where the product is
/// a normal double (bit for bit as before), else as √mgl · √x, which neither overflows nor
/// underflows; an error naming `I3` where the spin itself is not representable.
fn spin_bound(mgl: f64, x: f64, i3: f64) -> Result<f64> {
    let prod = mgl * x;
    let root = if prod.is_normal() || prod == 0.0 && (mgl == 0.0 || x == 0.0) {
        prod.sqrt()
    } else {
        mgl.sqrt() * x.sqrt()
    };
    let spin = 2.0 * root / i3;
    if spin.is_finite() {
        Ok(spin)
    } else {
        Err(Error::invalid(
            "I3",
            format!(
                "the spin 2 sqrt(mgl I1 cos theta0)/I3 (2.119) = 2 x {root:e} / {i3:e} exceeds the largest \
                 double"
            ),
        ))
    }
}

/// The steady-precession rates of a top held at nutation angle θ₀ spinning at ω₃ (2.114–2.121).
///
/// Both roots of `I₁ cos θ₀ φ̇² − p_ψ φ̇ + m g l = 0` (2.116 divided by I₁ sin⁴θ₀), computed by
/// the stable quadratic formula (no cancellation in the slow root of a fast top):
/// with `q = ½(p_ψ + sgn(p_ψ) √(p_ψ² − 4 m g l I₁ cos θ₀))`, `φ̇_fast = q / (I₁ cos θ₀)` and
/// `φ̇_slow = m g l / q`. At θ₀ = 0 (or π) they are the limits of steady precession at small
/// angles. Errors: `omega3` when |ω₃| is below the minimum spin 2.119 (no real root; the
/// message gives the minimum), and the argument checks of [`check_top`] and `theta0`.
pub fn steady_precession(
    i1: f64,
    i3: f64,
    mgl: f64,
    theta0: f64,
    omega3: f64,
) -> Result<SteadyPrecession> {
    check_top(i1, i3, mgl)?;
    check_theta("theta0", theta0)?;
    crate::error::check_finite("omega3", &[omega3])?;
    let c = theta0.cos();
    let p_psi = i3 * omega3;
    let min = min_spin(i1, i3, mgl, theta0)?;
    // The discriminant of 2.117 with p_ψ² (erratum: the unit prints p_φ²), and its square root.
    let disc = p_psi * p_psi - 4.0 * mgl * i1 * c;
    let (negative, root) = if disc.is_finite() && (disc.is_normal() || disc == 0.0) {
        (disc < 0.0, disc.abs().sqrt())
    } else {
        // p_ψ² or 4 m g l I₁ cos θ₀ out of range: |p_ψ| √(1 − 4 (m g l/p_ψ)(I₁ cos θ₀/p_ψ)), or
        // with the roles exchanged when p_ψ is the small one.
        let (big, small) = (p_psi.abs(), (4.0 * mgl).sqrt() * (i1 * c).abs().sqrt());
        if big >= small {
            let ratio = 1.0 - 4.0 * (mgl / big) * (i1 * c / big);
            (ratio < 0.0, big * ratio.abs().sqrt())
        } else {
            // p_ψ² − 4 m g l I₁ c with c < 0 (below the horizontal) is positive; with c > 0 the
            // spin is below the minimum.
            let ratio = (big / small) * (big / small) - c.signum();
            (ratio < 0.0, small * ratio.abs().sqrt())
        }
    };
    if negative {
        return Err(Error::invalid(
            "omega3",
            format!(
                "|omega3| = {} is below the minimum spin 2.119 for steady precession at theta0 = {theta0}: \
                 omega3_min = 2*sqrt(mgl*I1*cos(theta0))/I3 = {min}",
                omega3.abs()
            ),
        ));
    }
    let sign = if p_psi < 0.0 { -1.0 } else { 1.0 };
    let q = 0.5 * (p_psi + sign * root);
    let (slow, fast) = if c == 0.0 {
        // Horizontal axis: 2.116 is linear, −p_ψ φ̇ + m g l = 0.
        if p_psi != 0.0 {
            (mgl / p_psi, f64::INFINITY.copysign(p_psi))
        } else if mgl == 0.0 {
            (0.0, f64::INFINITY)
        } else {
            return Err(Error::invalid(
                "omega3",
                "a horizontal top (theta0 = pi/2) without spin (omega3 = 0) under gravity (mgl > 0) \
                 cannot precess steadily",
            ));
        }
    } else if q == 0.0 {
        // p_ψ = 0 and m g l = 0: a free top without spin; φ̇ = 0 (double root).
        (0.0, 0.0)
    } else {
        (mgl / q, q / (i1 * c))
    };
    let out = SteadyPrecession {
        slow,
        fast,
        slow_approx: Some(mgl / p_psi).filter(|x| x.is_finite()),
        fast_approx: p_psi / (i1 * c),
        fast_approx_as_printed: p_psi / (2.0 * i1 * c),
        min_spin: min,
    };
    // Every rate finite, or an error that says which is out of range.
    if !out.slow.is_finite() {
        return Err(Error::invalid(
            "omega3",
            format!(
                "the slow rate of 2.116, m g l/q = {slow:e}, exceeds the largest double for omega3 = \
                 {omega3:e} (p_psi = {p_psi:e})"
            ),
        ));
    }
    // fast_approx = 2 × fast_approx_as_printed: both finite when it is.
    if !(out.fast.is_finite() && out.fast_approx.is_finite()) {
        return Err(Error::invalid(
            "theta0",
            format!(
                "the fast precession rate ~ p_psi/(I1 cos theta0) (2.116, 2.120) exceeds the largest \
                 double at theta0 = {theta0} (cos theta0 = {c:e}): near the horizontal only the slow rate, \
                 {slow:e} rad/s, exists"
            ),
        ));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roots_solve_the_quadratic() {
        let s = steady_precession(1.0, 0.5, 0.3, 0.6, 40.0).unwrap();
        for r in [s.slow, s.fast] {
            let res = 0.6f64.cos() * r * r - 20.0 * r + 0.3;
            assert!(res.abs() < 1e-12 * 20.0 * r.abs(), "{r} {res}");
        }
        assert!(s.slow.abs() < s.fast.abs());
    }
}
