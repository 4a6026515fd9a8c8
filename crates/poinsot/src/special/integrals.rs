//! Legendre's elliptic integrals, complete and incomplete, as thin checked wrappers of the
//! `ellip` crate (Carlson's symmetric forms, after Boost and Cephes; DLMF §19.2, 19.25).
//!
//! Same parameter convention as the Jacobi functions: `m = k²` (mpmath, scipy); the
//! characteristic `n` of the third kind enters as `1 − n sin²θ` in the denominator
//! (mpmath's `ellippi(n, φ, m)`, DLMF's `Π(φ, n, k)` with `n = α²`).
//!
//! Errors name the argument at fault (`phi`, `n` or `m`); the integrals are never returned as
//! NaN.

use crate::error::{check_finite, Error, Result};

/// Maps an error string of `ellip` to the argument it concerns.
fn mapped(result: std::result::Result<f64, &'static str>, default_argument: &str) -> Result<f64> {
    match result {
        Ok(v) if !v.is_nan() => Ok(v),
        Ok(v) => Err(Error::invalid(
            default_argument,
            format!("the integral is undefined here (got {v})"),
        )),
        Err(msg) => {
            let argument = if msg.contains("n sin") || msg.contains(" n ") {
                "n"
            } else if msg.contains("m sin")
                || msg.contains(" m ")
                || msg.contains("m must")
                || msg.contains("m <")
            {
                "m"
            } else {
                default_argument
            };
            Err(Error::invalid(argument, msg.to_string()))
        }
    }
}

fn check_m(m: f64) -> Result<()> {
    check_finite("m", &[m])?;
    if m > 1.0 {
        return Err(Error::invalid("m", format!("must be <= 1, got {m}")));
    }
    Ok(())
}

/// K(m) = F(π/2 | m), the complete integral of the first kind, for `m < 1` (infinite at m = 1).
pub fn ellipk(m: f64) -> Result<f64> {
    check_m(m)?;
    if m == 1.0 {
        return Ok(f64::INFINITY);
    }
    mapped(ellip::ellipk(m), "m")
}

/// E(m) = E(π/2 | m), the complete integral of the second kind, for `m ≤ 1`.
pub fn ellipe(m: f64) -> Result<f64> {
    check_m(m)?;
    mapped(ellip::ellipe(m), "m")
}

/// Π(n | m) = Π(n; π/2 | m), the complete integral of the third kind, for `m < 1`, `n ≠ 1`
/// (the Cauchy principal value for `n > 1`).
pub fn ellippi(n: f64, m: f64) -> Result<f64> {
    check_finite("n", &[n])?;
    check_m(m)?;
    if n == 1.0 {
        return Err(Error::invalid(
            "n",
            "must not equal 1 (the complete integral diverges)",
        ));
    }
    mapped(ellip::ellippi(n, m), "n")
}

/// F(φ | m) = ∫₀^φ dθ / (1 − m sin²θ)^½, the incomplete integral of the first kind; any real
/// φ for `m < 1`, `|φ| < π/2` for `m = 1`.
pub fn ellipf(phi: f64, m: f64) -> Result<f64> {
    check_finite("phi", &[phi])?;
    check_m(m)?;
    if m == 1.0 {
        if phi.abs() >= std::f64::consts::FRAC_PI_2 {
            return Err(Error::invalid(
                "phi",
                format!("must satisfy |phi| < π/2 for m = 1, got {phi}"),
            ));
        }
        // F(φ | 1) = gd⁻¹(φ) = atanh(sin φ).
        return Ok(phi.sin().atanh());
    }
    mapped(ellip::ellipf(phi, m), "phi")
}

/// E(φ | m) = ∫₀^φ (1 − m sin²θ)^½ dθ, the incomplete integral of the second kind.
pub fn ellipeinc(phi: f64, m: f64) -> Result<f64> {
    check_finite("phi", &[phi])?;
    check_m(m)?;
    mapped(ellip::ellipeinc(phi, m), "phi")
}

/// Π(n; φ | m) = ∫₀^φ dθ / ((1 − n sin²θ)(1 − m sin²θ)^½), the incomplete integral of the
/// third kind (mpmath's `ellippi(n, phi, m)`); `n sin²φ ≠ 1`.
pub fn ellippiinc(phi: f64, n: f64, m: f64) -> Result<f64> {
    check_finite("phi", &[phi])?;
    check_finite("n", &[n])?;
    check_m(m)?;
    mapped(ellip::ellippiinc(phi, n, m), "phi")
}

/// F(φ | m) from the **complementary** parameter `mc = 1 − m` (`0 < mc ≤ 1`), any real φ:
/// `F = sin φ · R_F(cos²φ, cos²φ + m_c sin²φ, 1)` on `|φ| ≤ π/2` (DLMF 19.25.5, with
/// `1 − m sin²φ` written without cancellation) and `F(φ + jπ) = F(φ) + 2jK`. Use it near
/// `m = 1`, where `mc` carries digits that `1 − m` has lost. Errors name `phi` or `mc`.
pub fn ellipf_complement(phi: f64, mc: f64) -> Result<f64> {
    ellippiinc_complement(phi, 0.0, mc)
}

/// Π(n; φ | m) from the complementary parameter `mc = 1 − m` (`0 < mc ≤ 1`), for `n < 1` and
/// any real φ: `Π = s R_F(c², Δ², 1) + (n/3) s³ R_J(c², Δ², 1, 1 − n s²)` with `s = sin φ`,
/// `c = cos φ`, `Δ² = c² + m_c s²` on `|φ| ≤ π/2` (DLMF 19.25.14) and
/// `Π(n; φ + jπ) = Π(n; φ) + 2jΠ(n)`. Errors name `phi`, `n` or `mc`.
pub fn ellippiinc_complement(phi: f64, n: f64, mc: f64) -> Result<f64> {
    check_finite("phi", &[phi])?;
    check_finite("n", &[n])?;
    if !(mc.is_finite() && mc > 0.0 && mc <= 1.0) {
        return Err(Error::invalid("mc", format!("the complementary parameter must be in (0, 1], got {mc}")));
    }
    if n >= 1.0 {
        return Err(Error::invalid("n", format!("must be < 1, got {n}")));
    }
    let j = (phi / std::f64::consts::PI).round();
    let r = phi - j * std::f64::consts::PI;
    let (s, c) = r.sin_cos();
    let c2 = c * c;
    let d2 = c2 + mc * s * s;
    let mut value = s * mapped(ellip::elliprf(c2, d2, 1.0), "phi")?;
    let mut complete = 0.0;
    if j != 0.0 {
        complete = mapped(ellip::elliprf(0.0, mc, 1.0), "mc")?;
    }
    if n != 0.0 {
        value += n / 3.0 * s * s * s * mapped(ellip::elliprj(c2, d2, 1.0, 1.0 - n * s * s), "n")?;
        if j != 0.0 {
            complete += n / 3.0 * mapped(ellip::elliprj(0.0, mc, 1.0, 1.0 - n), "n")?;
        }
    }
    Ok(value + 2.0 * j * complete)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn limits_and_errors() {
        assert!((ellipk(0.0).unwrap() - std::f64::consts::FRAC_PI_2).abs() < 1e-16);
        assert!(ellipk(1.0).unwrap().is_infinite());
        assert_eq!(ellipk(1.5).unwrap_err().argument, "m");
        assert_eq!(ellippi(1.0, 0.5).unwrap_err().argument, "n");
        assert_eq!(ellipf(f64::NAN, 0.5).unwrap_err().argument, "phi");
        assert_eq!(ellipf(2.0, 1.0).unwrap_err().argument, "phi");
        // Π(0; φ | m) = F(φ | m).
        let (f, p) = (
            ellipf(1.2, 0.3).unwrap(),
            ellippiinc(1.2, 0.0, 0.3).unwrap(),
        );
        assert!((f - p).abs() < 1e-15);
    }
}
