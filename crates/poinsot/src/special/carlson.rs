//! Carlson's symmetric elliptic integrals R_C, R_F, R_D and R_J of real arguments, by the
//! duplication theorem (Carlson 1995, "Numerical computation of real or complex elliptic
//! integrals", Numer. Algorithms 10; DLMF §19.36(i)), over the whole double range: the crate's
//! one implementation of them (Legendre's integrals in [`super::integrals`], the free body's
//! attitude, its SIMD lanes' nome and the heavy top's motion and Fourier series all call these).
//!
//! Two things differ from the usual implementations (Boost, the `ellip` crate), which fail or
//! lose accuracy at the edges of the double range:
//! * the integrals are homogeneous (R_F of degree −½, R_D and R_J of degree −3/2), so the
//!   arguments are first scaled by a power of 4 (exact, and exact under the square root) that
//!   centres their exponents on 0: arguments up to 600 decades apart then neither overflow nor
//!   underflow in the duplication's products (scaling the largest to 1 made the terms 1/d of
//!   R_J overflow for Π(0.3 | −1e308));
//! * the duplication runs until the spread of the arguments about their mean (which shrinks
//!   by exactly 4 per step) is below a tolerance of the mean, with no fixed cap on the count:
//!   as the mean itself falls towards the result's R^−2, two arguments 10⁻³⁰⁰ below the third
//!   take about 13 steps, where `ellip` stops after 11 and returns an unconverged value.
//!
//! Preconditions (checked by the callers, which name the user's argument): all arguments
//! finite, x, y, z ≥ 0 with at most one of them zero, p ≠ 0 (p < 0: Cauchy principal value).

use super::fp::{exponent, ldexp};
use crate::simd::ATAN_TAYLOR;

/// Relative spread below which the R_F series is summed: its first neglected terms are of
/// degree 8 in the spread, 0.003⁸ ≈ 7e-21 (below ε/4 = 5.5e-17 with a wide margin).
const TOL_F: f64 = 0.003;
/// The same for R_D and R_J, whose series are truncated after degree 5: 0.0015⁶ ≈ 1.1e-17,
/// below ε/4 (Carlson 1995 takes (ε/4)^(1/6) ≈ 0.0016).
const TOL_DJ: f64 = 0.0015;
/// A guard only. Each duplication divides the spread of the arguments about their mean by
/// exactly 4, while the mean falls towards R^−2 (R^−2/3 for R_D, R_J): the steps needed grow as
/// log₄ of the initial spread over that limit, about 13 for R_F(0, 1e-300, 1) and under 40
/// for anything in the double range.
const MAX_STEPS: usize = 1100;
/// Below this weight 4^−m the duplication of R_J rescales its arguments (see [`rj_scaled`]).
const RESCALE_BELOW: f64 = 3.054936363499605e-151; // 2^-500

/// The power of 4 by which to divide the arguments: `h` with the arguments' exponents centred
/// on 0 (their largest and smallest nonzero ones, `e_max` and `e_min`, become ≈ ±(e_max −
/// e_min)/2), so that neither the square roots' products nor the terms 1/d of the duplication
/// overflow or underflow for arguments up to 600 decades apart; kept within [−1000, 1000]
/// after scaling. 0 (no scaling) when all arguments lie within 10^±90.
#[inline]
fn quarter_scale(args: &[f64]) -> i32 {
    let max = args.iter().fold(0.0f64, |a, &b| a.max(b.abs()));
    let min = args
        .iter()
        .filter(|v| **v != 0.0)
        .fold(f64::INFINITY, |a, &b| a.min(b.abs()));
    if max == 0.0 || ((1e-90..=1e90).contains(&max) && (1e-90..=1e90).contains(&min)) {
        return 0;
    }
    let (e_max, e_min) = (exponent(max), exponent(min));
    let h = (e_max + e_min).div_euclid(4);
    // Largest scaled exponent e_max − 2h at most 1000.
    h.max((e_max - 1000).div_euclid(2) + 1)
}

/// R_C(1, 1 + e) for e > −1: `atan(√e)/√e`, `atanh(√−e)/√−e`, or its Maclaurin series
/// `1 − e/3 + e²/5 − …` (atan x / x in e = x², [`ATAN_TAYLOR`]) for |e| < 0.01 (10 terms: the
/// first neglected, e¹⁰/21, is < 5e-22).
#[inline]
fn rc1p(e: f64) -> f64 {
    if e.abs() < 0.01 {
        ATAN_TAYLOR[..10]
            .iter()
            .rev()
            .fold(0.0, |acc, &c| acc * e + c)
    } else if e > 0.0 {
        let r = e.sqrt();
        r.atan() / r
    } else {
        let r = (-e).sqrt();
        r.atanh() / r
    }
}

/// ρ = (r₁ + r₂ + r₃ + r₁r₂r₃)/(1 + r₁r₂ + r₂r₃ + r₃r₁) for rᵢ ≥ 0, without overflow: numerator
/// and denominator divided by r_max · max(1, r_mid).
#[inline]
fn carlson_rho(a: f64, b: f64, c: f64) -> f64 {
    let mut r = [a, b, c];
    r.sort_by(f64::total_cmp);
    let [r1, r2, r3] = r;
    if r3 == 0.0 {
        return 0.0;
    }
    let scale = r3 * r2.max(1.0);
    let m2 = r2.max(1.0);
    let num = (r1 + r2 + r3) / scale + r1 * (r2 / m2);
    let den = 1.0 / scale + r1 * (r2 / scale) + (r1 + r2) / m2;
    num / den
}

/// R_C(1, 1 + e) for e = (1 − ρ)/(1 + ρ), ρ ≥ 0, with 1 + e = 2/(1 + ρ) exact to a few ulp
/// where e → −1 (ρ → ∞): there R_C = atanh(√−e)/√−e = ln((1 + √−e)/√(1 + e))/√−e.
#[inline]
fn rc1p_rho(rho: f64) -> f64 {
    let e = (1.0 - rho) / (1.0 + rho);
    if e >= -0.5 {
        return rc1p(e);
    }
    let s = (-e).sqrt();
    let one_plus_e = 2.0 / (1.0 + rho);
    ((1.0 + s) / one_plus_e.sqrt()).ln() / s
}

/// R_C(x, y) = ½∫₀^∞ (t + x)^−½ (t + y)^−1 dt for x ≥ 0, y ≠ 0 (the Cauchy principal value for
/// y < 0, DLMF 19.2.20).
pub(crate) fn rc(x: f64, y: f64) -> f64 {
    if y < 0.0 {
        // DLMF 19.2.20: R_C(x, y) = (x/(x − y))^½ R_C(x − y, −y).
        return (x / (x - y)).sqrt() * rc(x - y, -y);
    }
    let h = quarter_scale(&[x, y]);
    let (x, y) = (ldexp(x, -2 * h), ldexp(y, -2 * h));
    let value = if x == 0.0 {
        std::f64::consts::FRAC_PI_2 / y.sqrt()
    } else {
        let e = y / x - 1.0;
        if e.abs() < 1e-3 {
            // R_C(x, y) = x^−½ R_C(1, y/x), by its series near y = x.
            rc1p(e) / x.sqrt()
        } else if y > x {
            // DLMF 19.2.18; √((y − x)/x) may overflow for x ≪ y: atan(∞) = π/2.
            ((y - x) / x).sqrt().atan() / (y - x).sqrt()
        } else {
            // DLMF 19.2.19, atanh s = ln((1 + s)/√(1 − s²)) with 1 − s² = y/x taken as it
            // is: atanh of s = √(1 − y/x) rounded to 1 would be infinite for y ≪ x.
            let s = ((x - y) / x).sqrt();
            ((1.0 + s) / (y / x).sqrt()).ln() / (x - y).sqrt()
        }
    };
    ldexp(value, -h)
}

/// R_F(x, y, z) = ½∫₀^∞ ((t + x)(t + y)(t + z))^−½ dt (DLMF 19.16.1).
pub(crate) fn rf(x: f64, y: f64, z: f64) -> f64 {
    let h = quarter_scale(&[x, y, z]);
    let (mut x, mut y, mut z) = if h == 0 {
        (x, y, z)
    } else {
        (ldexp(x, -2 * h), ldexp(y, -2 * h), ldexp(z, -2 * h))
    };
    let mut a = (x + y + z) / 3.0;
    // The spread about the mean shrinks by exactly 4 per duplication: track it, and stop when
    // it falls below TOL_F of the (falling) mean.
    let mut q = (a - x).abs().max((a - y).abs()).max((a - z).abs()) / TOL_F;
    for _ in 0..MAX_STEPS {
        if q <= a {
            break;
        }
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lambda = sx * (sy + sz) + sy * sz;
        x = 0.25 * (x + lambda);
        y = 0.25 * (y + lambda);
        z = 0.25 * (z + lambda);
        a = 0.25 * (a + lambda);
        q *= 0.25;
    }
    // Carlson (1995) eq. (2.2)-(2.3), with X = 1 − x/A etc.
    let dx = (a - x) / a;
    let dy = (a - y) / a;
    let dz = -dx - dy;
    let e2 = dx * dy - dz * dz;
    let e3 = dx * dy * dz;
    let series = 1.0
        + e3 * (1.0 / 14.0 + 3.0 * e3 / 104.0)
        + e2 * (-0.1 + e2 / 24.0 - 3.0 * e3 / 44.0 - 5.0 * e2 * e2 / 208.0 + e2 * e3 / 16.0);
    ldexp(series / a.sqrt(), -h)
}

/// R_D(x, y, z) = R_J(x, y, z, z) = (3/2)∫₀^∞ ((t + x)(t + y))^−½ (t + z)^−3/2 dt, z > 0
/// (DLMF 19.16.5).
pub(crate) fn rd(x: f64, y: f64, z: f64) -> f64 {
    let h = quarter_scale(&[x, y, z]);
    let (mut x, mut y, mut z) = if h == 0 {
        (x, y, z)
    } else {
        (ldexp(x, -2 * h), ldexp(y, -2 * h), ldexp(z, -2 * h))
    };
    let mut a = (x + y + 3.0 * z) / 5.0;
    let mut sum = 0.0;
    let mut fac = 1.0;
    let mut q = (a - x).abs().max((a - y).abs()).max((a - z).abs()) / TOL_DJ;
    for _ in 0..MAX_STEPS {
        if q <= a {
            break;
        }
        q *= 0.25;
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lambda = sx * (sy + sz) + sy * sz;
        sum += fac / (sz * (z + lambda));
        fac *= 0.25;
        x = 0.25 * (x + lambda);
        y = 0.25 * (y + lambda);
        z = 0.25 * (z + lambda);
        a = 0.25 * (a + lambda);
    }
    // Carlson (1995) eq. (2.29).
    let dx = (a - x) / a;
    let dy = (a - y) / a;
    let dz = -(dx + dy) / 3.0;
    let xy = dx * dy;
    let z2 = dz * dz;
    let e2 = xy - 6.0 * z2;
    let e3 = (3.0 * xy - 8.0 * z2) * dz;
    let e4 = 3.0 * (xy - z2) * z2;
    let e5 = xy * z2 * dz;
    let series = 1.0 - 3.0 * e2 / 14.0 + e3 / 6.0 + 9.0 * e2 * e2 / 88.0
        - 3.0 * e4 / 22.0
        - 9.0 * e2 * e3 / 52.0
        + 3.0 * e5 / 26.0;
    ldexp(fac * series / (a * a.sqrt()) + 3.0 * sum, -3 * h)
}

/// R_J(x, y, z, p) = (3/2)∫₀^∞ ((t + x)(t + y)(t + z))^−½ (t + p)^−1 dt (DLMF 19.16.2); for
/// p < 0 the Cauchy principal value (DLMF 19.20.14).
pub(crate) fn rj(x: f64, y: f64, z: f64, p: f64) -> f64 {
    if p < 0.0 {
        return rj_principal_value(x, y, z, -p);
    }
    rj_scaled(x, y, z, p, 0)
}

/// w R_J(x, y, z, p), the power of two of w applied last (for p > 0; a principal value
/// otherwise): finite wherever the product is, even where R_J alone is not a normal double.
pub(crate) fn times_rj(w: f64, x: f64, y: f64, z: f64, p: f64) -> f64 {
    if w == 0.0 || !w.is_finite() {
        return w * rj(x, y, z, p);
    }
    if p < 0.0 {
        return w * rj(x, y, z, p);
    }
    let e = exponent(w);
    ldexp(w, -e) * rj_scaled(x, y, z, p, e)
}

/// 2^k R_J(x, y, z, p) for p > 0, the power of two applied last: for a product w R_J whose
/// factors leave the double range on their own (w = 2^k × its mantissa). NaN where the
/// duplication cannot be carried out in double precision (arguments so far apart that the
/// product of their square roots overflows, or no convergence within `MAX_STEPS`): callers turn
/// it into an error naming their argument, never a number.
pub(crate) fn rj_scaled(x: f64, y: f64, z: f64, p: f64, k: i32) -> f64 {
    let h = quarter_scale(&[x, y, z, p]);
    let (mut x, mut y, mut z, mut p) = if h == 0 {
        (x, y, z, p)
    } else {
        (
            ldexp(x, -2 * h),
            ldexp(y, -2 * h),
            ldexp(z, -2 * h),
            ldexp(p, -2 * h),
        )
    };
    let mut a = (x + y + z + 2.0 * p) / 5.0;
    let mut sum = 0.0;
    let mut fac = 1.0;
    let mut q = (a - x)
        .abs()
        .max((a - y).abs())
        .max((a - z).abs())
        .max((a - p).abs())
        / TOL_DJ;
    let mut converged = false;
    for _ in 0..MAX_STEPS {
        if q <= a {
            converged = true;
            break;
        }
        q *= 0.25;
        let (sx, sy, sz, sp) = (x.sqrt(), y.sqrt(), z.sqrt(), p.sqrt());
        let lambda = sx * (sy + sz) + sy * sz;
        let (ax, ay, az) = (sp + sx, sp + sy, sp + sz);
        let d = ax * ay * az;
        if !d.is_finite() {
            return f64::NAN;
        }
        // e = δ_m / d_m² = Π(√p − √xᵢ)/Π(√p + √xᵢ), taken as it is where e ≥ −½ (R_C(1, 1 + e)
        // needs e to a few ulp absolute there); below, 1 + e would lose its digits as e → −1
        // (arguments hundreds of decades apart, where the product rounds to −1): there e =
        // (1 − ρ)/(1 + ρ) with ρ = √α/√β of Carlson's older form, a ratio of sums of positive
        // terms in rᵢ = √(xᵢ/p), so that 1 + e = 2/(1 + ρ) keeps them.
        let e = (sp - sx) * (sp - sy) * (sp - sz) / d;
        let rc = if e >= -0.5 {
            rc1p(e)
        } else {
            rc1p_rho(carlson_rho(sx / sp, sy / sp, sz / sp))
        };
        sum += fac * rc / d;
        fac *= 0.25;
        x = 0.25 * (x + lambda);
        y = 0.25 * (y + lambda);
        z = 0.25 * (z + lambda);
        p = 0.25 * (p + lambda);
        a = 0.25 * (a + lambda);
        if fac < RESCALE_BELOW {
            // Hundreds of steps (arguments ~10^600 apart): 4^−m would underflow. R_J is
            // homogeneous of degree −3/2, so the arguments × 4^K and fac × 8^K leave every
            // later term fac/d and the remainder fac R_J(x, y, z, p) unchanged (exact powers
            // of two), with the arguments kept below 2^600 (d below 2^903).
            let top = x.max(y).max(z).max(p).max(a);
            let kk = ((600 - exponent(top)) / 2).min(250);
            if kk > 0 {
                x = ldexp(x, 2 * kk);
                y = ldexp(y, 2 * kk);
                z = ldexp(z, 2 * kk);
                p = ldexp(p, 2 * kk);
                a = ldexp(a, 2 * kk);
                q = ldexp(q, 2 * kk);
                fac = ldexp(fac, 3 * kk);
            }
            if fac == 0.0 {
                return f64::NAN;
            }
        }
    }
    // Carlson (1995) eq. (2.19).
    let dx = (a - x) / a;
    let dy = (a - y) / a;
    let dz = (a - z) / a;
    let dp = -(dx + dy + dz) / 2.0;
    let xyz = dx * dy * dz;
    let p2 = dp * dp;
    let e2 = dx * dy + dx * dz + dy * dz - 3.0 * p2;
    let e3 = xyz + 2.0 * e2 * dp + 4.0 * p2 * dp;
    let e4 = (2.0 * xyz + e2 * dp + 3.0 * p2 * dp) * dp;
    let e5 = xyz * p2;
    let series = 1.0 - 3.0 * e2 / 14.0 + e3 / 6.0 + 9.0 * e2 * e2 / 88.0
        - 3.0 * e4 / 22.0
        - 9.0 * e2 * e3 / 52.0
        + 3.0 * e5 / 26.0;
    if !converged {
        return f64::NAN;
    }
    ldexp(fac * series / (a * a.sqrt()) + 6.0 * sum, k - 3 * h)
}

/// The principal value R_J(x, y, z, −q), q > 0 (DLMF 19.20.14 with x ≤ y ≤ z):
/// `(z + q) R_J(x, y, z, −q) = (p − z) R_J(x, y, z, p) − 3R_F(x, y, z)
///  + 3 (xyz/(xy + pq))^½ R_C(xy + pq, pq)`, `p = (z(x + y + q) − xy)/(z + q) > 0`.
fn rj_principal_value(x: f64, y: f64, z: f64, q: f64) -> f64 {
    let mut v = [x, y, z];
    v.sort_by(f64::total_cmp);
    let [x, y, z] = v;
    let h = quarter_scale(&[x, y, z, q]);
    let (x, y, z, q) = (
        ldexp(x, -2 * h),
        ldexp(y, -2 * h),
        ldexp(z, -2 * h),
        ldexp(q, -2 * h),
    );
    // z(x + y + q) − xy = z(x + q) + y(z − x): no cancellation.
    let p = (z * (x + q) + y * (z - x)) / (z + q);
    let xy = x * y;
    let pq = p * q;
    let mut value = (p - z) * rj(x, y, z, p) - 3.0 * rf(x, y, z);
    if xy != 0.0 {
        value += 3.0 * (xy * z / (xy + pq)).sqrt() * rc(xy + pq, pq);
    }
    ldexp(value / (z + q), -3 * h)
}

/// Below this, `c²` and `d²` in [`rf_cd`], [`rj_cd`], [`rd_cd`] are small enough for the
/// leading asymptotic forms: their relative error is O(c² ln c) < 1e-22 (Carlson & Gustafson
/// 1994), and the squares, which may underflow, are never formed.
const ASYMPTOTIC_CD: f64 = 1e-12;

/// ln(4/(c + d)) without overflow of the quotient (c + d may be subnormal).
#[inline]
fn log_four_over(sum: f64) -> f64 {
    std::f64::consts::LN_2 * 2.0 - sum.ln()
}

/// R_F(c², d², 1) for c, d ≥ 0, not both zero, from c and d themselves (their squares may
/// underflow): `ln(4/(c + d))` when both are below 1e-12 (DLMF 19.27.3 with z = 1).
pub(crate) fn rf_cd(c: f64, d: f64) -> f64 {
    if c.max(d) < ASYMPTOTIC_CD {
        log_four_over(c + d)
    } else {
        rf(c * c, d * d, 1.0)
    }
}

/// R_J(c², d², 1, p) for c, d ≥ 0, not both zero, and p > 0: for c, d below 1e-12,
/// `(3/p)[ln(4/(c + d)) − R_C(1, p)]` (from `R_J = (3/p)R_F − (3/2p)∫ t dt/((t + p)…)`, whose
/// last integral tends to `2R_C(1, p)`).
pub(crate) fn rj_cd(c: f64, d: f64, p: f64) -> f64 {
    if c.max(d) < ASYMPTOTIC_CD {
        3.0 / p * (log_four_over(c + d) - rc(1.0, p))
    } else {
        rj(c * c, d * d, 1.0, p)
    }
}

/// R_D(c², 1, d²) for 0 ≤ c ≤ d, d > 0: for d below 1e-12, `3/(d(d + c))`, the integral with
/// (t + 1)^−½ replaced by 1 (relative error O(d² ln d)).
pub(crate) fn rd_cd(c: f64, d: f64) -> f64 {
    if d < ASYMPTOTIC_CD {
        3.0 / (d * (d + c))
    } else {
        rd(c * c, 1.0, d * d)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn closed_forms_and_homogeneity() {
        let pi = std::f64::consts::PI;
        // R_F(0, 1, 1) = π/2, R_D(0, 1, 1) = 3π/4, R_C(0, 1) = π/2, R_J(x, x, x, x) = x^(−3/2).
        assert!((rf(0.0, 1.0, 1.0) - pi / 2.0).abs() < 4e-16);
        assert!((rd(0.0, 1.0, 1.0) - 3.0 * pi / 4.0).abs() < 8e-16);
        assert!((rc(0.0, 1.0) - pi / 2.0).abs() < 4e-16);
        assert!((rj(2.0, 2.0, 2.0, 2.0) - 2f64.powf(-1.5)).abs() < 4e-16);
        // R_C(x, y) elementary (DLMF 19.2.18-19).
        assert!((rc(1.0, 2.0) - 1f64.atan()).abs() < 4e-16);
        assert!((rc(2.0, 1.0) - 2f64.sqrt().acosh()).abs() < 4e-16);
        // Homogeneity across the whole range (R_D and R_J of degree −3/2 only as far as their
        // values stay representable).
        for &(x, y, z, p) in &[
            (0.3, 0.7, 1.1, 0.5),
            (0.0, 2.0, 3.0, 0.1),
            (1e-7, 1.0, 0.5, 9.0),
        ] {
            for &s in &[
                2f64.powi(-1000),
                2f64.powi(-600),
                2f64.powi(600),
                2f64.powi(1000),
            ] {
                let f = rf(s * x, s * y, s * z) * s.sqrt();
                assert!((f / rf(x, y, z) - 1.0).abs() < 1e-15, "{s}");
            }
            for &s in &[
                2f64.powi(-600),
                2f64.powi(-300),
                2f64.powi(300),
                2f64.powi(600),
            ] {
                let d = rd(s * x, s * y, s * z) * s * s.sqrt();
                assert!((d / rd(x, y, z) - 1.0).abs() < 1e-15, "{s}");
                let j = rj(s * x, s * y, s * z, s * p) * s * s.sqrt();
                assert!((j / rj(x, y, z, p) - 1.0).abs() < 1e-15, "{s}");
            }
        }
    }

    #[test]
    fn widely_spread_arguments_converge() {
        // Subnormal k' (4/k' overflows): K ≈ ln 4 − ln k'.
        assert!((rf_cd(0.0, 5e-324) - (4f64.ln() - 5e-324f64.ln())).abs() < 1e-13);
        // R_F(0, m₁, 1) = K ≈ ln(4/√m₁) + O(m₁ ln m₁) (DLMF 19.12.1): the duplication itself,
        // far below the asymptotic switch, agrees with the asymptotic form.
        for &mc in &[1e-30, 1e-100, 1e-300] {
            let k = rf(0.0, mc, 1.0);
            let want = (4.0 / mc.sqrt()).ln();
            assert!((k / want - 1.0).abs() < 1e-15, "{mc}: {k} {want}");
            assert!((rf_cd(0.0, mc.sqrt()) / k - 1.0).abs() < 1e-15);
            // R_J and R_D against their leading forms at the same points.
            let j = rj(0.0, mc, 1.0, 3.0);
            assert!((rj_cd(0.0, mc.sqrt(), 3.0) / j - 1.0).abs() < 1e-14, "{mc}");
            let d = rd(mc, 1.0, 4.0 * mc);
            assert!(
                (rd_cd(mc.sqrt(), 2.0 * mc.sqrt()) / d - 1.0).abs() < 1e-14,
                "{mc}"
            );
        }
    }
}
