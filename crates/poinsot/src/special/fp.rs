//! Exact scaling by powers of two, for computing at unit scale what is asked at any scale of the
//! double range (the elliptic integrals are homogeneous; the free body's motion is invariant
//! under ω → sω, t → t/s and I → sI).

/// The exponent `e` of a finite nonzero `x` with `2^e ≤ |x| < 2^(e+1)`, subnormals included
/// (`e` from −1074 to 1023); `0` for zero and non-finite `x` (which scaling leaves as they are).
pub(crate) fn exponent(x: f64) -> i32 {
    if x == 0.0 || !x.is_finite() {
        return 0;
    }
    let bits = x.abs().to_bits();
    let biased = (bits >> 52) as i32;
    if biased == 0 {
        // Subnormal: the leading bit of the 52-bit fraction sets the exponent.
        let lead = 63 - (bits.leading_zeros() as i32);
        lead - 1074
    } else {
        biased - 1023
    }
}

/// `2^k` for `−1022 ≤ k ≤ 1023` (a normal double, exact).
fn pow2_normal(k: i32) -> f64 {
    debug_assert!((-1022..=1023).contains(&k));
    f64::from_bits(((k + 1023) as u64) << 52)
}

/// `x · 2^k` for any `k`, with a single rounding (only when the result is subnormal): the
/// scaling is split so that no intermediate overflows or underflows early. Overflows to ±∞ and
/// underflows to ±0 as the exact product would.
pub(crate) fn ldexp(x: f64, k: i32) -> f64 {
    if x == 0.0 || !x.is_finite() || k == 0 {
        return x;
    }
    // x = y · 2^e with y in [1, 2) (exact), then y · 2^(e + k).
    let e = exponent(x);
    let y = if e >= -1022 {
        x * pow2_normal(-e.min(1022))
    } else {
        // Subnormal x: two exact steps up.
        x * pow2_normal(1022) * pow2_normal(-e - 1022)
    };
    // For e = 1023 the first step could only divide by 2^1022: y is then in [2, 4).
    let y = if e == 1023 { y * 0.5 } else { y };
    let k = e.saturating_add(k);
    if k > 1023 {
        return x.signum() * f64::INFINITY;
    }
    if k >= -1022 {
        return y * pow2_normal(k);
    }
    if k < -1022 - 54 {
        return x.signum() * 0.0;
    }
    // y · 2^(k + 1022) is normal and exact; the last factor 2^-1022 rounds once.
    y * pow2_normal(k + 1022) * pow2_normal(-1022)
}

/// `10^e10` and a mantissa for showing a value that a double cannot hold, given as
/// `mantissa · 2^k` (finite mantissa): "≈ 3.2e-340".
pub(crate) fn describe(mantissa: f64, k: i32) -> String {
    if mantissa == 0.0 {
        return "0".to_string();
    }
    let log10 = mantissa.abs().log10() + f64::from(k) * std::f64::consts::LOG10_2;
    let e = log10.floor();
    let m = 10f64.powf(log10 - e);
    let sign = if mantissa < 0.0 { "-" } else { "" };
    format!("{sign}{m:.2}e{e}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exponents_and_exact_scaling() {
        assert_eq!(exponent(1.0), 0);
        assert_eq!(exponent(1.5), 0);
        assert_eq!(exponent(0.75), -1);
        assert_eq!(exponent(f64::MAX), 1023);
        assert_eq!(exponent(f64::MIN_POSITIVE), -1022);
        assert_eq!(exponent(5e-324), -1074);
        assert_eq!(exponent(3.0 * 5e-324), -1073);
        assert_eq!(ldexp(1.0, -1074), 5e-324);
        assert_eq!(ldexp(5e-324, 1074), 1.0);
        assert_eq!(ldexp(3.0, 1023), 3.0 * 2f64.powi(1023) / 2.0 * 2.0);
        assert!(ldexp(1.0, 1024).is_infinite());
        assert_eq!(ldexp(1.0, -1075), 0.0);
        assert_eq!(ldexp(1.5, -1074), 1e-323); // 1.5 · 2^-1074 rounds to even: 2 · 2^-1074.
        assert_eq!(ldexp(f64::MAX, -2046), ldexp(ldexp(f64::MAX, -1023), -1023));
        for &x in &[1e-300, 3.7e-320, 1.0, 2.5e300, f64::MAX, 5e-324] {
            let k = exponent(x);
            let y = ldexp(x, -k);
            assert!((1.0..2.0).contains(&y), "{x} {k} {y}");
            assert_eq!(ldexp(y, k), x);
        }
        assert_eq!(describe(1.0, -1130), "6.86e-341");
        assert_eq!(describe(-3.0, 1100), "-4.07e331");
    }
}
