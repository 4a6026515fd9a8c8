//! The scale of a torque-free motion, carried by powers of two so that the motion itself is
//! solved at unit scale.
//!
//! Euler's equations without torque are invariant under ω → sω, t → t/s (they are quadratic in
//! ω) and under I → σI: `ω(t; sω₀, σI) = s ω̂(st; ω₀, I)` and the attitude is `q̂(st)`. With
//! `s = 2^−e_w` and `σ = 2^−e_i` the scaled state (largest |ω̂_i| and largest Î in [1, 2)) is
//! exact, every quadratic form of ω̂ is free of overflow and underflow, and the time scaling
//! `t̂ = 2^e_w t` is exact: the accuracy at unit scale holds over the whole double range, and
//! `ω(t; 2^k ω₀) = 2^k ω(2^k t; ω₀)` holds bit for bit.
//!
//! Two limits remain, both of the answer rather than of the method:
//! * a conserved quantity (T ∝ σs², |L| ∝ σs, the period ∝ 1/s) outside the normal double range
//!   cannot be returned to full precision: its getter refuses, saying by how much;
//! * the phase. A double t is known to half an ulp, and the rates are carried in double
//!   precision: the phase of ω(t) and of the attitude is uncertain by a few ε times the angle
//!   the body has turned. Beyond [`PHASE_LIMIT`] radians that uncertainty exceeds ~1e-3 rad and
//!   the call refuses, naming `t` and the largest |t| of the motion.

use crate::error::{check_finite, Error, Result};
use crate::special::fp::{describe, exponent, ldexp};

/// The largest angle (rad) through which a free motion is followed: 2⁴² ≈ 4.4e12 rad. One ulp of
/// a phase of this size is 2⁻¹⁰ ≈ 1e-3 rad, and the rates, carried in double precision (a few ε
/// relative each), move the computed phase by a few such ulps: at the limit the state is good to
/// ~1e-3 (measured: `free_body.rs::phase_error_at_the_time_limit`). Past it every further factor
/// of 10 in t costs one more digit, until at ~10¹⁶ rad nothing is left.
pub const PHASE_LIMIT: f64 = 4_398_046_511_104.0;

/// The powers of two that carry the scale of a free motion (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Scale {
    /// ω = 2^e_w ω̂; t̂ = 2^e_w t.
    pub e_w: i32,
    /// I = 2^e_i Î.
    pub e_i: i32,
    /// 2^e_w, a normal double.
    pub s_w: f64,
    /// The largest |t| (s) at which the motion has turned through at most [`PHASE_LIMIT`].
    pub t_max: f64,
}

impl Scale {
    /// The scale of moments `moments` (finite, > 0) and ω₀ (finite, nonzero, checked
    /// normal by [`check_omega_range`]); `t_max` is set later from the motion's rates.
    pub fn new(moments: &[f64; 3], omega0: &[f64; 3]) -> Self {
        let e_i = exponent(moments.iter().fold(0.0f64, |a, &b| a.max(b)));
        let e_w = exponent(omega0.iter().fold(0.0f64, |a, v| a.max(v.abs())));
        Self {
            e_w,
            e_i,
            s_w: ldexp(1.0, e_w),
            t_max: f64::INFINITY,
        }
    }

    /// The moments at unit scale (exact).
    pub fn moments_hat(&self, moments: &[f64; 3]) -> [f64; 3] {
        moments.map(|v| ldexp(v, -self.e_i))
    }

    /// ω₀ at unit scale (exact).
    pub fn omega_hat(&self, omega0: &[f64; 3]) -> [f64; 3] {
        omega0.map(|v| ldexp(v, -self.e_w))
    }

    /// Sets `t_max` from the largest rate of the unit-scale motion (rad per unit of t̂).
    pub fn with_rate(mut self, rate_hat: f64) -> Self {
        self.t_max = if rate_hat > 0.0 {
            ldexp(PHASE_LIMIT / rate_hat, -self.e_w)
        } else {
            f64::INFINITY
        };
        self
    }

    /// t̂ = 2^e_w t after checking t: finite and |t| ≤ `t_max` (the error names `t`).
    #[inline]
    pub fn time(&self, t: f64) -> Result<f64> {
        if !t.is_finite() || t.abs() > self.t_max {
            check_finite("t", &[t])?;
            return Err(Error::invalid(
                "t",
                format!(
                    "the time {t:.6e} s lies beyond ±{:.6e} s, in which this motion turns \
                     through 2^42 ≈ 4.4e12 rad: past that the phase of ω(t) and of the attitude, \
                     carried in double precision, is uncertain by more than ~1e-3 rad (and by \
                     ~10^16 rad it is lost entirely: one ulp of t then moves the body by more \
                     than a radian)",
                    self.t_max
                ),
            ));
        }
        Ok(t * self.s_w)
    }

    /// A unit-scale vector times 2^e_w (rad/s).
    #[inline]
    pub fn omega(&self, w: &crate::Vec3) -> crate::Vec3 {
        w * self.s_w
    }
}

/// Checks that ω₀ (named `argument`) has a normal magnitude: its largest component at least
/// the smallest normal double. Below, its components and ω(t) would carry fewer than 53 bits
/// and its time scale 1/|ω| would exceed 4.5e307 s.
pub(crate) fn check_omega_range(argument: &str, omega: &[f64; 3]) -> Result<()> {
    let max = omega.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    if max < f64::MIN_POSITIVE {
        return Err(Error::invalid(
            argument,
            format!(
                "its largest component {max:e} rad/s is below the smallest normal double \
                 (2.2e-308): such a rotation would be computed with fewer than 53 bits, and it \
                 turns by one radian only in more than 4.5e307 s (use units in which ω is larger)"
            ),
        ));
    }
    Ok(())
}

/// `mantissa · 2^k` if it is zero or a normal double; otherwise an error naming `argument` that
/// says what (`what`, in `units`) would have been returned.
pub(crate) fn representable(
    argument: &str,
    what: &str,
    units: &str,
    mantissa: f64,
    k: i32,
) -> Result<f64> {
    let v = ldexp(mantissa, k);
    if mantissa == 0.0 || mantissa.is_infinite() || (v.is_finite() && v.abs() >= f64::MIN_POSITIVE)
    {
        return Ok(v);
    }
    let side = if v.is_finite() {
        "below the smallest normal double (2.2e-308): it would lose digits or round to 0"
    } else {
        "above the largest double (1.8e308)"
    };
    Err(Error::invalid(
        argument,
        format!(
            "{what} ≈ {} {units} is {side}; the motion itself is computed, but this number \
             cannot be returned (use units in which it is representable)",
            describe(mantissa, k)
        ),
    ))
}
