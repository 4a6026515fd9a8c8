//! Exact scaling by powers of two, so that products of extreme magnitudes (`m r²` with
//! `r = 1e200`, `ω·I·ω`, `m |d|²`) neither overflow nor underflow in an intermediate step when
//! the result itself is representable.
//!
//! Multiplying by `2^k` is exact in binary floating point as long as the result is a normal
//! number, so computing on mantissas in `[1, 2)` and applying the exponents at the end gives
//! the same bits as the naive formula wherever the naive formula does not leave the range, and
//! the correctly rounded result where it would.

use crate::error::{Error, Result};
use crate::{Mat3, Vec3};

/// The crate's one exact scaling by powers of two (`special::fp`: `ldexp` rounds once, only in
/// the subnormal range; `exponent` is `0` for zero and non-finite numbers).
pub(crate) use crate::special::fp::{exponent, ldexp};

/// `(x · 2^-e, e)` with `e = exponent(x)`: a mantissa in `[1, 2)` (or zero) and its exponent.
pub(crate) fn split(x: f64) -> (f64, i32) {
    let e = exponent(x);
    (ldexp(x, -e), e)
}

/// The exponent of the largest magnitude among `values` (`0` if all are zero).
pub(crate) fn exponent_of_max(values: &[f64]) -> i32 {
    exponent(values.iter().fold(0.0f64, |m, x| m.max(x.abs())))
}

/// `v · 2^k` for each component.
pub(crate) fn ldexp_vec(v: &Vec3, k: i32) -> Vec3 {
    v.map(|x| ldexp(x, k))
}

/// `m · 2^k` for each entry.
pub(crate) fn ldexp_mat(m: &Mat3, k: i32) -> Mat3 {
    m.map(|x| ldexp(x, k))
}

/// An order of magnitude for messages: `value · 2^k` written as `1.234e+567`, also far outside
/// the range of doubles.
pub(crate) fn magnitude(value: f64, k: i32) -> String {
    if value == 0.0 || !value.is_finite() {
        return format!("{value}");
    }
    let log10 = value.abs().log10() + f64::from(k) * std::f64::consts::LOG10_2;
    let e = log10.floor();
    let sign = if value < 0.0 { "-" } else { "" };
    format!(
        "{sign}{:.3}e{}{}",
        10f64.powf(log10 - e),
        if e < 0.0 { "-" } else { "+" },
        e.abs()
    )
}

/// Checks that a result `value · 2^k` (computed on scaled numbers) does not overflow; names
/// `argument` otherwise. Results below the normal range are left to IEEE gradual underflow
/// (a subnormal or zero, the correctly rounded value).
pub(crate) fn check_overflow(
    argument: &str,
    what: &str,
    value: f64,
    k: i32,
    hint: &str,
) -> Result<()> {
    if ldexp(value.abs(), k).is_finite() {
        return Ok(());
    }
    Err(Error::invalid(
        argument,
        format!(
            "{what} would be about {}, beyond the largest finite double (1.8e+308): no finite \
             answer exists; {hint}",
            magnitude(value, k)
        ),
    ))
}

/// Checks the largest triangle margin `I3 + (I2 − I1)` (at most twice the largest moment) of a
/// body's principal moments `moments · 2^k` (computed on scaled numbers) as [`check_range`]: a
/// body reports its margins, so one whose margins would overflow is refused where it is made,
/// naming `argument`, rather than one whose getters return infinity.
pub(crate) fn check_margins(argument: &str, moments: [f64; 3], k: i32, hint: &str) -> Result<()> {
    check_range(
        argument,
        "the largest triangle margin I3 + I2 - I1 (kg·m²)",
        crate::inertia::tensor::largest_margin(moments),
        k,
        hint,
    )
}

/// Checks a result `value · 2^k` (the largest magnitude of a quantity, computed on scaled
/// numbers) against the range of normal doubles and names `argument` when it leaves it:
/// beyond `f64::MAX` no finite answer exists; below `f64::MIN_POSITIVE` (but not zero) it
/// would be a subnormal with lost precision. `what` names the quantity and its unit, e.g.
/// `"the moments of inertia (kg·m²)"`; `hint` says what the user can do.
pub(crate) fn check_range(
    argument: &str,
    what: &str,
    value: f64,
    k: i32,
    hint: &str,
) -> Result<()> {
    if value == 0.0 {
        return Ok(());
    }
    let out = ldexp(value.abs(), k);
    if !out.is_finite() {
        return Err(Error::invalid(
            argument,
            format!(
                "{what} would be about {}, beyond the largest finite double (1.8e+308): no finite \
                 answer exists; {hint}",
                magnitude(value, k)
            ),
        ));
    }
    if out < f64::MIN_POSITIVE {
        return Err(Error::invalid(
            argument,
            format!(
                "{what} would be about {}, below the smallest normal double (2.2e-308), where it \
                 cannot be represented to full precision; {hint}",
                magnitude(value, k)
            ),
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ldexp_and_split_are_exact() {
        assert_eq!(ldexp(1.5, 1023), 1.5 * 2f64.powi(1023));
        assert_eq!(ldexp(1.0, 1024), f64::INFINITY);
        assert_eq!(ldexp(1.0, -1074), f64::from_bits(1));
        assert_eq!(ldexp(1.0, -1076), 0.0);
        // One rounding: 1.75·2^-1074 rounds to 2·2^-1074 (ties to even is not needed here).
        assert_eq!(ldexp(1.75, -1074), f64::from_bits(2));
        assert_eq!(ldexp(f64::from_bits(1), 2000), 2f64.powi(926));
        for x in [1.0, 3.0, 1e-310, 5e-324, 1e308, -2.5e-200] {
            let (m, e) = split(x);
            assert!((1.0..2.0).contains(&m.abs()), "{x}: {m}");
            assert_eq!(ldexp(m, e), x);
        }
        assert_eq!(exponent(0.75), -1);
        assert_eq!(exponent(f64::from_bits(1)), -1074);
        assert_eq!(magnitude(4.0, 2044), "8.079e+615");
        assert_eq!(magnitude(-1.0, -1100), "-7.362e-332");
    }
}
