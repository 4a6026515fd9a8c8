//! Legendre's elliptic integrals, complete and incomplete, over the whole double range of their
//! arguments, from Carlson's symmetric forms ([`super::carlson`]; DLMF §19.25).
//!
//! Same parameter convention as the Jacobi functions: `m = k²` (mpmath, scipy), any `m ≤ 1`
//! (negative m included); the characteristic `n` of the third kind enters as `1 − n sin²θ` in
//! the denominator (mpmath's `ellippi(n, φ, m)`, DLMF's `Π(φ, n, k)` with `n = α²`); for
//! `n > 1` the Cauchy principal value (the real part of mpmath's complex value).
//!
//! Method, with `s = sin φ`, `c = cos φ`, `Δ² = c² + m₁s²` on `|φ| ≤ π/2` (`m₁ = 1 − m`, so
//! Δ² carries no cancellation near m = 1) and `X(φ + jπ) = X(φ) + 2jX_complete`:
//! * `F = s R_F(c², Δ², 1)` (19.25.5);
//! * `E = m₁F + (m m₁/3) s³ R_D(c², 1, Δ²) + m s c/Δ` for `0 < m ≤ 1`, all terms positive (from
//!   19.25.10), and `E = s R_F − (m/3) s³ R_D(c², Δ², 1)` for `m ≤ 0` (19.25.9), also positive;
//! * `Π = s R_F + (n/3) s³ R_J(c², Δ², 1, 1 − ns²)` (19.25.14) for `0 ≤ n` below the pole; for
//!   `n < 0` with `|n| s² > 1`, where those two terms would cancel, the form with positive
//!   terms that DLMF 19.21.12 gives with `q = c² + m₁s²/(1 − n)`:
//!   `Π = [s R_F + (−n) s c R_C(Δ², (1 − ns²) q)]/(1 − n) + (−n) m₁ s³ R_J(c², Δ², 1, q)/(3(1 − n)²)`;
//!   for `n s² > 1` (n > 1) the principal value
//!   `Π = |s| R_C(c²Δ², (1 − ns²)(1 − ms²/n)) − (m/(3n)) s³ R_J(c², Δ², 1, 1 − ms²/n)` (from
//!   DLMF 19.7.8 and 19.25.14);
//! * complete: `K = R_F(0, m₁, 1)`, `E = (m₁/3)(R_D(0, m₁, 1) + R_D(0, 1, m₁))` (19.25.1),
//!   `Π = K/(1 − n) + (−n)m₁ R_J(0, m₁, 1, m₁/(1 − n))/(3(1 − n)²)` for n < 0 (19.21.12),
//!   `Π = R_F + (n/3) R_J(0, m₁, 1, 1 − n)` for 0 ≤ n < 1 (19.25.2) and
//!   `Π = −(m/(3n)) R_J(0, m₁, 1, 1 − m/n)` for n > 1 (19.6.5 with 19.25.2).
//!
//! For `|φ| > 2⁵²π` (where a double φ no longer resolves its position within a period) the
//! incomplete integrals are `(2φ/π) X_complete`, exact to ≤ 1 part in 2⁵² of the value.
//!
//! Errors name the argument at fault (`phi`, `n`, `m` or `mc`) and say why: a divergent
//! integral (`K(1)`, `Π(1 | m)`, `F(φ | 1)` past π/2, `n sin²φ = 1`), or a value beyond the
//! largest double. No value is ever returned as NaN or ±∞.

use super::carlson::{rc, rd, rd_cd, rf, rf_cd, rj_cd, times_rj};
use crate::error::{check_finite, Error, Result};
use std::f64::consts::PI;

/// The low part of π in double-double (π = PI + PI_LO to 2⁻¹⁰⁷).
const PI_LO: f64 = 1.224_646_799_147_353_2e-16;
/// Beyond |φ| = 2⁵²π the incomplete integrals are taken as (2φ/π)·X_complete: the neglected
/// part, X(r) − (2r/π)X_complete with |r| ≤ π/2, is at most |X_complete|, a fraction ≤ 2⁻⁵²
/// of the value.
const PHI_LINEAR: f64 = 4_503_599_627_370_496.0 * PI;

/// The parameter with its complement, each as accurate as the caller knows it.
#[derive(Debug, Clone, Copy)]
struct Param {
    m: f64,
    mc: f64,
}

fn param(m: f64) -> Result<Param> {
    check_finite("m", &[m])?;
    if m > 1.0 {
        return Err(Error::invalid(
            "m",
            format!(
                "the parameter m = k² must be <= 1, got {m} (the integrals are complex above 1)"
            ),
        ));
    }
    // 1 − m: exact for m ≥ 1/2 (Sterbenz), one rounding below.
    Ok(Param { m, mc: 1.0 - m })
}

fn param_complement(mc: f64) -> Result<Param> {
    if !(mc.is_finite() && mc > 0.0 && mc <= 1.0) {
        return Err(Error::invalid(
            "mc",
            format!("the complementary parameter must be in (0, 1], got {mc}"),
        ));
    }
    Ok(Param { m: 1.0 - mc, mc })
}

fn finite_result(argument: &str, what: &str, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else if value.is_nan() {
        Err(unevaluable(argument, what))
    } else {
        Err(Error::invalid(
            argument,
            format!("{what} exceeds the largest double (1.8e308) here"),
        ))
    }
}

/// Carlson's duplication could not be carried out in double precision: arguments hundreds of
/// decades apart (see `carlson::rj_scaled`). Refused rather than returned inaccurate.
fn unevaluable(argument: &str, what: &str) -> Error {
    Error::invalid(
        argument,
        format!(
            "{what} cannot be evaluated in double precision for arguments this many decades \
             apart (Carlson's duplication would overflow or underflow); bring n and m closer \
             to 1 in magnitude"
        ),
    )
}

/// The argument to blame for an integral that cannot be evaluated: the more extreme of n and m.
fn extreme(n: f64, m: f64) -> &'static str {
    if n.abs() > m.abs() {
        "n"
    } else {
        "m"
    }
}

fn k_complete(p: Param) -> Result<f64> {
    if p.mc == 0.0 {
        return Err(Error::invalid(
            "m",
            "K(m) diverges at m = 1 (as ln(4/√(1 − m))); there is no finite value",
        ));
    }
    Ok(rf(0.0, p.mc, 1.0))
}

fn e_complete(p: Param) -> f64 {
    if p.mc == 0.0 {
        return 1.0;
    }
    p.mc / 3.0 * (rd(0.0, p.mc, 1.0) + rd(0.0, 1.0, p.mc))
}

/// (1 − n) with n's own rounding only where it matters: exact for n in [½, 2] (Sterbenz).
#[inline]
fn one_minus(n: f64) -> f64 {
    1.0 - n
}

fn pi_complete(n: f64, p: Param) -> Result<f64> {
    if n == 1.0 {
        return Err(Error::invalid(
            "n",
            "Π(n | m) diverges at n = 1 (the integrand has a double pole at θ = π/2)",
        ));
    }
    if p.mc == 0.0 {
        return Err(Error::invalid(
            "m",
            "Π(n | m) diverges at m = 1 (logarithmically, like K(m))",
        ));
    }
    if n > 1.0 {
        // DLMF 19.6.5 with 19.25.2: the principal value −(m/(3n)) R_J(0, m₁, 1, 1 − m/n).
        let w = p.m / n;
        // 1 − m/n as (n − m)/n: one rounding in n − m (exact near n = m), where 1 − w would
        // carry the rounding of w relative to a difference of 2⁻³⁹ next to n = m = 1.
        return Ok(times_rj(-w / 3.0, 0.0, p.mc, 1.0, (n - p.m) / n));
    }
    let k = rf(0.0, p.mc, 1.0);
    if n == 0.0 {
        return Ok(k);
    }
    if n > 0.0 {
        return Ok(k + times_rj(n / 3.0, 0.0, p.mc, 1.0, one_minus(n)));
    }
    // n < 0 (DLMF 19.21.12 with x = 0): K/(1 − n) + (−n/(1 − n))·(q/3) R_J(0, m₁, 1, q),
    // q = m₁/(1 − n); as q → 0, (q/3) R_J(0, m₁, 1, q) → √q R_C(q, m₁) = R_C(1, 1 − n)
    // (relative error O(√(q/m₁)) + O(m₁ ln m₁), < 1e-17 wherever q < 1e-300).
    let nc = one_minus(n);
    let weight = -n / nc;
    let q = p.mc / nc;
    let term = if q < 1e-300 {
        rc(1.0, nc)
    } else {
        times_rj(q / 3.0, 0.0, p.mc, 1.0, q)
    };
    Ok(k / nc + weight * term)
}

/// K(m) = F(π/2 | m), the complete integral of the first kind, for `m < 1` (any negative m).
/// Errors: `m` not finite, above 1, or equal to 1 (K diverges there).
pub fn ellipk(m: f64) -> Result<f64> {
    k_complete(param(m)?)
}

/// E(m) = E(π/2 | m), the complete integral of the second kind, for `m ≤ 1` (E(1) = 1).
pub fn ellipe(m: f64) -> Result<f64> {
    Ok(e_complete(param(m)?))
}

/// Π(n | m) = Π(n; π/2 | m), the complete integral of the third kind, for `m < 1`, `n ≠ 1`
/// (the Cauchy principal value for `n > 1`). Errors name `n` (not finite, or 1) or `m`.
pub fn ellippi(n: f64, m: f64) -> Result<f64> {
    check_finite("n", &[n])?;
    let p = param(m)?;
    finite_result(extreme(n, m), "Π(n | m)", pi_complete(n, p)?)
}

/// Which Legendre integral.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Kind {
    F,
    E,
    Pi(f64),
}

/// The integral of `kind` over `[0, r]`, `|r| ≤ π/2` (cos r ≥ 0), from its sine and cosine.
fn reduced(kind: Kind, s_signed: f64, c: f64, p: Param) -> Result<f64> {
    let sign = if s_signed < 0.0 { -1.0 } else { 1.0 };
    let s = s_signed.abs();
    if s == 0.0 {
        return Ok(0.0 * sign);
    }
    let s2 = s * s;
    // Δ = (c² + m₁ s²)^½ for m ≥ 0 (no cancellation near m = 1), (1 − m s²)^½ for m < 0.
    let delta = if p.m >= 0.0 {
        (c * c + p.mc * s2).sqrt()
    } else {
        (1.0 - p.m * s2).sqrt()
    };
    let f = s * rf_cd(c, delta);
    let value = match kind {
        Kind::F => f,
        Kind::E => {
            if p.mc == 0.0 || (s < 1e-100 && p.m.abs() <= 1.0) {
                // E(1) = sin φ; for tiny φ, E = s (1 + O(m s²)): the weighted sum below would
                // round each half of a subnormal s away.
                s
            } else if p.m > 0.0 {
                p.mc * f + p.m * p.mc / 3.0 * s * s2 * rd_cd(c, delta) + p.m * s * (c / delta)
            } else {
                f - p.m / 3.0 * s * s2 * rd(c * c, delta * delta, 1.0)
            }
        }
        Kind::Pi(n) => pi_reduced(n, s, c, delta, f, p)?,
    };
    Ok(sign * value)
}

/// Π(n; r | m) for 0 < s = sin r, c = cos r ≥ 0, given Δ and F(r | m).
fn pi_reduced(n: f64, s: f64, c: f64, delta: f64, f: f64, p: Param) -> Result<f64> {
    if n == 0.0 {
        return Ok(f);
    }
    let s2 = s * s;
    let ns2 = n * s2;
    if ns2 == 1.0 {
        return Err(Error::invalid(
            "n",
            format!(
                "n sin²φ = 1 exactly (n = {n}): the integrand has a pole at the end of the \
                 interval and the integral diverges"
            ),
        ));
    }
    if n > 0.0 && ns2 < 1.0 {
        // 1 − n s² = c² + (1 − n) s² without cancellation where n s² ≥ ½ (then n ≥ ½).
        let pp = if ns2 < 0.5 {
            1.0 - ns2
        } else if n <= 1.0 {
            c * c + one_minus(n) * s2
        } else {
            1.0 - ns2
        };
        return Ok(f + n / 3.0 * s * s2 * rj_cd(c, delta, pp));
    }
    if n > 0.0 {
        // Past the pole (n s² > 1, so n > 1): the principal value.
        let w = p.m / n;
        let pw = 1.0 - w * s2;
        let b = (1.0 - ns2) * pw;
        let a = c * c * delta * delta;
        let pole = if a == 0.0 { 0.0 } else { s * rc(a, b) };
        return Ok(pole - w / 3.0 * s * s2 * rj_cd(c, delta, pw));
    }
    // n < 0.
    let pp = 1.0 - ns2;
    if -ns2 <= 1.0 {
        return Ok(f + n / 3.0 * s * s2 * rj_cd(c, delta, pp));
    }
    let nc = one_minus(n);
    let weight = -n / nc;
    let q = c * c + p.mc * s2 / nc;
    let mut value = f / nc;
    if c > 0.0 {
        value += weight * s * c * rc(delta * delta, pp * q);
    }
    value += weight * (p.mc * s2 / nc) / 3.0 * s * rj_cd(c, delta, q);
    Ok(value)
}

/// Π(n | m) from m and its complement m₁ (for callers that know m₁ better than 1 − m): the
/// same forms as [`ellippi`] (positive terms only for n < 0).
pub(crate) fn pi_complete_split(n: f64, m: f64, mc: f64) -> Result<f64> {
    pi_complete(n, Param { m, mc })
}

/// Π(n; r | m) on |r| ≤ π/2 from s = |sin r|, c = cos r ≥ 0 and Δ = (1 − m s²)^½ (a dn), with
/// the complement m₁: the forms of [`ellippiinc`] (positive terms only for n < 0).
pub(crate) fn pi_reduced_split(n: f64, s: f64, c: f64, delta: f64, m: f64, mc: f64) -> Result<f64> {
    if s == 0.0 {
        return Ok(0.0);
    }
    let f = s * rf_cd(c, delta);
    pi_reduced(n, s, c, delta, f, Param { m, mc })
}

/// The complete value that one period π of φ adds, twice: X(φ + π) = X(φ) + 2 X_complete.
fn complete(kind: Kind, p: Param) -> Result<f64> {
    match kind {
        Kind::F => k_complete(p),
        Kind::E => Ok(e_complete(p)),
        Kind::Pi(n) => pi_complete(n, p),
    }
}

/// The incomplete integral of `kind` at any finite φ: φ = jπ + r with cos r ≥ 0.
fn incomplete(kind: Kind, phi: f64, p: Param) -> Result<f64> {
    check_finite("phi", &[phi])?;
    let name = match kind {
        Kind::F => "F(φ | m)",
        Kind::E => "E(φ | m)",
        Kind::Pi(_) => "Π(n; φ | m)",
    };
    let blame = match kind {
        Kind::Pi(n) => extreme(n, p.m),
        _ => "m",
    };
    let settled = |v: f64| {
        if v.is_nan() {
            Err(unevaluable(blame, name))
        } else {
            Ok(v)
        }
    };
    if matches!(kind, Kind::F | Kind::E)
        && (p.m == 0.0 || (p.m.abs() < 1e-16 && phi.abs() > PHI_LINEAR))
    {
        // F(φ | 0) = E(φ | 0) = φ exactly; for |m| < 1e-16 the factor K/(π/2) = 1 + m/4 + …
        // (E: 1 − m/4) rounds to 1, and φ up to the largest double stays representable.
        return Ok(phi);
    }
    if phi.abs() > PHI_LINEAR {
        let whole = complete(kind, p).map_err(|e| diverges_past_half_pi(kind, phi, e))?;
        return finite_result(
            "phi",
            name,
            phi * (settled(whole)? / std::f64::consts::FRAC_PI_2),
        );
    }
    let mut j = (phi / PI).round();
    let mut r = (-j).mul_add(PI, phi) - j * PI_LO;
    let (mut s, mut c) = r.sin_cos();
    if c < 0.0 {
        // φ/π rounded to the wrong side of a half-integer: one more period.
        j += if r > 0.0 { 1.0 } else { -1.0 };
        r = (-j).mul_add(PI, phi) - j * PI_LO;
        (s, c) = r.sin_cos();
    }
    let part = settled(reduced(kind, s, c.max(0.0), p)?)?;
    if j == 0.0 {
        return finite_result("phi", name, part);
    }
    let whole = complete(kind, p).map_err(|e| diverges_past_half_pi(kind, phi, e))?;
    finite_result("phi", name, 2.0 * j * settled(whole)? + part)
}

/// A complete integral that diverges makes the incomplete one diverge once |φ| passes π/2:
/// say so naming `phi`.
fn diverges_past_half_pi(kind: Kind, phi: f64, e: Error) -> Error {
    let what = match kind {
        Kind::F => "F(φ | 1)",
        Kind::E => "E(φ | m)",
        Kind::Pi(_) => "Π(n; φ | m)",
    };
    Error::invalid(
        "phi",
        format!(
            "{what} diverges once |phi| reaches π/2 here ({}); got phi = {phi}",
            e.message
        ),
    )
}

/// F(φ | m) = ∫₀^φ dθ / (1 − m sin²θ)^½, the incomplete integral of the first kind: any finite
/// φ for `m < 1`, `|φ| ≤ π/2` (as doubles, all below the true π/2) for `m = 1`.
pub fn ellipf(phi: f64, m: f64) -> Result<f64> {
    let p = param(m)?;
    incomplete(Kind::F, phi, p)
}

/// E(φ | m) = ∫₀^φ (1 − m sin²θ)^½ dθ, the incomplete integral of the second kind, any finite
/// φ and `m ≤ 1`.
pub fn ellipeinc(phi: f64, m: f64) -> Result<f64> {
    let p = param(m)?;
    incomplete(Kind::E, phi, p)
}

/// Π(n; φ | m) = ∫₀^φ dθ / ((1 − n sin²θ)(1 − m sin²θ)^½), the incomplete integral of the
/// third kind (mpmath's `ellippi(n, phi, m)`; the principal value past a pole, n > 1);
/// `n sin²φ ≠ 1`.
pub fn ellippiinc(phi: f64, n: f64, m: f64) -> Result<f64> {
    check_finite("n", &[n])?;
    let p = param(m)?;
    incomplete(Kind::Pi(n), phi, p)
}

/// F(φ | m) from the **complementary** parameter `mc = 1 − m` (`0 < mc ≤ 1`), any real φ. Use
/// it near `m = 1`, where `mc` carries digits that `1 − m` has lost. Errors name `phi` or `mc`.
pub fn ellipf_complement(phi: f64, mc: f64) -> Result<f64> {
    let p = param_complement(mc)?;
    incomplete(Kind::F, phi, p)
}

/// Π(n; φ | m) from the complementary parameter `mc = 1 − m` (`0 < mc ≤ 1`), for `n < 1` and
/// any real φ. Errors name `phi`, `n` or `mc`.
pub fn ellippiinc_complement(phi: f64, n: f64, mc: f64) -> Result<f64> {
    check_finite("n", &[n])?;
    let p = param_complement(mc)?;
    if n >= 1.0 {
        return Err(Error::invalid("n", format!("must be < 1, got {n}")));
    }
    incomplete(Kind::Pi(n), phi, p)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    #[test]
    fn limits_and_errors() {
        assert!((ellipk(0.0).unwrap() - FRAC_PI_2).abs() < 4e-16);
        assert_eq!(ellipk(1.0).unwrap_err().argument, "m");
        assert_eq!(ellipk(1.5).unwrap_err().argument, "m");
        assert_eq!(ellippi(1.0, 0.5).unwrap_err().argument, "n");
        assert_eq!(ellipf(f64::NAN, 0.5).unwrap_err().argument, "phi");
        assert_eq!(ellipf(2.0, 1.0).unwrap_err().argument, "phi");
        assert!(ellipf(FRAC_PI_2, 1.0).unwrap().is_finite());
        assert_eq!(ellipe(1.0).unwrap(), 1.0);
        // Π(0; φ | m) = F(φ | m).
        let (f, p) = (
            ellipf(1.2, 0.3).unwrap(),
            ellippiinc(1.2, 0.0, 0.3).unwrap(),
        );
        assert!((f - p).abs() < 1e-15);
    }
}
