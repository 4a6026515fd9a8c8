//! Jacobi elliptic functions `sn`, `cn`, `dn` and the amplitude `am` of real argument.
//!
//! **Parameter convention:** everything here takes the *parameter* `m = k²` (as mpmath,
//! scipy and DLMF §22.1 do), not the modulus `k`, with `0 ≤ m ≤ 1`. The complementary
//! parameter is `m₁ = 1 − m`; near `m = 1` pass it yourself ([`Jacobi::with_complement`]) when
//! you know it more accurately than `1 − m` (e.g. from a physical formula).
//!
//! Method (accurate to a few ulp, relative, uniformly in `0 ≤ m ≤ 1`):
//! 1. argument reduction `u = 2K·j + r`, `|r| ≤ K`, with the quarter period `K(m)` computed by
//!    the arithmetic–geometric mean in double-double arithmetic, so the reduction adds no error
//!    beyond the representation of `u` for `|u|` up to 2⁵⁰K ([`Jacobi::max_argument`]; beyond
//!    it consecutive doubles are more than K/8 apart and the checked functions refuse `u`)
//!    (`sn(u + 2K) = −sn u`,
//!    `cn(u + 2K) = −cn u`, `dn(u + 2K) = dn u`, `am(u + 2K) = am u + π`; DLMF 22.4.3);
//! 2. parity (`sn`, `am` odd; `cn`, `dn` even) to `0 ≤ x ≤ K`, then the quarter-period shift
//!    `sn(K − v) = cd v`, `cn(K − v) = m₁^½ sd v`, `dn(K − v) = m₁^½ nd v` to evaluate only
//!    on `0 ≤ v ≤ K/2`, where `cn` and `dn` stay ≥ `(m₁/(1+m₁^½))^½`;
//! 3. on `[0, K/2]`: the Maclaurin series (DLMF 22.10) at `v/2ⁿ ≤ 1/128` for `sn`, `1 − cn` and
//!    `1 − dn`, then `n` duplications (DLMF 22.8.4–6), first on the complements
//!    `1 − cn(2u) = 2 sn² dn² / (1 − m sn⁴)`, `1 − dn(2u) = 2 m sn² cn² / (1 − m sn⁴)` (no
//!    cancellation while `cn` is near 1, Fukushima's device), then on `sn`, `cn` and the ratio
//!    `dn/cn = (1 + m₁ sc²)^½`, written without cancellation:
//!    `cn(2u) = cn² (1 − m₁ sc⁴)/D`, `sn(2u) = 2 sn (dn/cn)/D`, `D = 1 + sn² + m₁ sn² sc²`;
//! 4. `m = 0` (`sin`, `cos`, 1) and `m = 1` (`tanh`, `sech`, `sech`, `gd`) exactly.
//!
//! The error is then a few ulp times the condition number of the function at `u` (which is
//! large only near the zeros of `sn` and `cn` at large `|u|`): pinned against 40-digit
//! mpmath values in `tests/special.rs` (`jacobi_functions_match_mpmath`).

use super::dd::{Dd, PI};
use crate::error::{Error, Result};
use crate::simd::{F64s, Simd};

/// Below this argument the Maclaurin series (to u⁷ for `sn`, u⁸ for `1 − cn`, `1 − dn`) are
/// exact to round-off: the first neglected term is < 0.03 u⁸ ≈ 2e-19 relative.
const SERIES_MAX: f64 = 1.0 / 128.0;
/// The duplication switches from the complements `1 − cn`, `1 − dn` to `cn`, `dn` once
/// `1 − cn` exceeds this (then `cn = 1 − (1 − cn)` loses less than a factor 3 in relative error).
const COMPLEMENT_MAX: f64 = 0.25;
/// [`Jacobi::max_argument`] in units of 2K: 2⁴⁹ half-periods.
const MAX_REDUCTION: f64 = 562_949_953_421_312.0;

/// The values of the three Jacobi functions and the amplitude at one argument.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JacobiValues {
    /// sn(u | m) = sin(am u).
    pub sn: f64,
    /// cn(u | m) = cos(am u).
    pub cn: f64,
    /// dn(u | m) = (1 − m sn²)^½ = d(am u)/du.
    pub dn: f64,
    /// am(u | m), the amplitude φ with u = F(φ | m) (continuous, odd, am(u + 2K) = am(u) + π).
    pub am: f64,
}

/// The Jacobi elliptic functions for one parameter `m`, with the quarter period `K(m)` and the
/// complementary parameter precomputed (use it to evaluate many arguments with the same `m`).
///
/// ```
/// use poinsot::special::Jacobi;
/// let j = Jacobi::new(0.5).unwrap();
/// let v = j.eval(0.7);
/// assert!((v.sn * v.sn + v.cn * v.cn - 1.0).abs() < 1e-15);
/// assert!((v.dn * v.dn + 0.5 * v.sn * v.sn - 1.0).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jacobi {
    m: f64,
    /// 1 − m.
    mc: f64,
    /// (1 − m)^½.
    kc: f64,
    /// 2K(m) in double-double (infinite for m = 1).
    two_k: Dd,
}

impl Jacobi {
    /// The functions of parameter `m` (`0 ≤ m ≤ 1`); the error names `m` otherwise.
    pub fn new(m: f64) -> Result<Self> {
        check_parameter(m)?;
        // 1 − m exactly, as a double-double (exact as a double for m ≥ 1/2).
        let mc = Dd::diff(1.0, m);
        Ok(Self::build(m, mc))
    }

    /// The functions of parameter `m` with its complement `mc = 1 − m` given separately: use it
    /// near `m = 1`, where `mc` may be known to more relative digits than `1 − m` carries. The
    /// two must agree to a few ulp (`|m + mc − 1| ≤ 4 ε`); errors name `m` or `mc`.
    pub fn with_complement(m: f64, mc: f64) -> Result<Self> {
        check_parameter(m)?;
        if !(mc.is_finite() && (0.0..=1.0).contains(&mc)) {
            return Err(Error::invalid(
                "mc",
                format!("must be finite and in [0, 1], got {mc}"),
            ));
        }
        if (m + mc - 1.0).abs() > 4.0 * f64::EPSILON {
            return Err(Error::invalid(
                "mc",
                format!("must equal 1 − m = {}, got {mc}", 1.0 - m),
            ));
        }
        if mc == 0.0 {
            return Ok(Self::build(1.0, Dd::from(0.0)));
        }
        Ok(Self::build(m, Dd::from(mc)))
    }

    /// The functions of parameter `m = 1 − kc²` given the **complementary modulus**
    /// `kc = (1 − m)^½` (`0 ≤ kc ≤ 1`): for m so close to 1 that `1 − m` is not representable
    /// as a normal double (kc < 1.5e-154, where `mc = kc²` underflows) but K(m) ≈ ln(4/kc) and
    /// the functions are perfectly well defined. `kc = 0` is m = 1. The error names `kc`.
    pub fn with_complementary_modulus(kc: f64) -> Result<Self> {
        if !(kc.is_finite() && (0.0..=1.0).contains(&kc)) {
            return Err(Error::invalid(
                "kc",
                format!("the complementary modulus must be finite and in [0, 1], got {kc}"),
            ));
        }
        if kc == 0.0 {
            return Ok(Self::build(1.0, Dd::from(0.0)));
        }
        // mc = kc² exactly as a double-double (its low part may underflow: harmless, the
        // duplication below uses mc only where it is negligible next to 1 for such kc).
        let mc = Dd::from(kc).mul(Dd::from(kc));
        let m = Dd::from(1.0).add(mc.scale(-1.0));
        Ok(Self::build_with_kc(m.hi + m.lo, mc, Dd::from(kc)))
    }

    fn build(m: f64, mc: Dd) -> Self {
        let kc = mc.sqrt();
        Self::build_with_kc(m, mc, kc)
    }

    fn build_with_kc(m: f64, mc: Dd, kc: Dd) -> Self {
        let mcv = mc.hi + mc.lo;
        let kcv = kc.hi + kc.lo;
        let two_k = if kcv <= 0.0 {
            Dd {
                hi: f64::INFINITY,
                lo: 0.0,
            }
        } else {
            // K = π / (2 agm(1, k')) (DLMF 19.8.5), in double-double.
            PI.div(agm_dd(Dd::from(1.0), kc))
        };
        Self {
            m,
            mc: mcv,
            kc: kcv,
            two_k,
        }
    }

    /// The parameter m.
    pub fn m(&self) -> f64 {
        self.m
    }

    /// The complementary parameter 1 − m (0 when it underflows: see
    /// [`Jacobi::complementary_modulus`]).
    pub fn complement(&self) -> f64 {
        self.mc
    }

    /// The complementary modulus k' = (1 − m)^½ (nonzero whenever m < 1, even where
    /// 1 − m underflows).
    pub fn complementary_modulus(&self) -> f64 {
        self.kc
    }

    /// The largest |u| at which the functions are computed to their stated accuracy,
    /// `2⁵⁰ K(m)` (infinite for m = 0 and m = 1, which have exact forms). Up to it the
    /// reduction `u − 2Kj` is exact to the last bit of the reduced argument (2K is carried to
    /// ~32 digits); beyond it consecutive doubles are more than K/8 apart, so u no longer
    /// determines its position within the period 4K(m) and the values would be arbitrary.
    pub fn max_argument(&self) -> f64 {
        if self.m == 0.0 || self.kc == 0.0 {
            f64::INFINITY
        } else {
            MAX_REDUCTION * self.two_k.hi
        }
    }

    /// [`Jacobi::eval`] after checking `u`: finite and `|u| ≤` [`Jacobi::max_argument`]. The
    /// error names `u`.
    pub fn eval_checked(&self, u: f64) -> Result<JacobiValues> {
        crate::error::check_finite("u", &[u])?;
        let limit = self.max_argument();
        if u.abs() > limit {
            return Err(Error::invalid(
                "u",
                format!(
                    "|u| = {:e} is beyond {limit:.3e} = 2⁵⁰ K(m) for m = {}: there consecutive \
                     doubles are more than K(m)/8 apart, so u no longer fixes its place within \
                     the period 4K(m) = {:.6} and sn, cn, dn would be arbitrary",
                    u.abs(),
                    self.m,
                    2.0 * self.two_k.hi
                ),
            ));
        }
        Ok(self.eval(u))
    }

    /// The quarter period K(m) (infinite for m = 1).
    pub fn quarter_period(&self) -> f64 {
        0.5 * self.two_k.hi
    }

    /// Splits `u = 2K·j + r` with `|r| ≤ K` and `j` an integer (returned as `f64`); for
    /// m = 1 (no period), `j = 0`, `r = u`. Exact up to one rounding of `r` for `|u| < 2⁵⁰ K`.
    pub fn reduce(&self, u: f64) -> (f64, f64) {
        if !self.two_k.hi.is_finite() {
            return (0.0, u);
        }
        let j = (u / self.two_k.hi).round();
        if j == 0.0 {
            return (0.0, u);
        }
        // u − j·2K with 2K = hi + lo: the fused product-sum is exact up to its final rounding.
        let r = (-j).mul_add(self.two_k.hi, u) - j * self.two_k.lo;
        (j, r)
    }

    /// sn, cn, dn and am at `u` (any finite real). Accurate to a few ulp up to
    /// [`Jacobi::max_argument`]; beyond it only relative to the conditioning (the exact values
    /// at an argument within a few ulp of u, which is no longer meaningful): prefer
    /// [`Jacobi::eval_checked`] for arguments from outside.
    pub fn eval(&self, u: f64) -> JacobiValues {
        if self.m == 0.0 {
            let (s, c) = u.sin_cos();
            return JacobiValues {
                sn: s,
                cn: c,
                dn: 1.0,
                am: u,
            };
        }
        if self.kc == 0.0 {
            let sech = 1.0 / u.cosh();
            return JacobiValues {
                sn: u.tanh(),
                cn: sech,
                dn: sech,
                am: u.sinh().atan(),
            };
        }
        let (j, r) = self.reduce(u);
        let v = self.eval_reduced(r);
        let odd = j.rem_euclid(2.0) == 1.0;
        let sign = if odd { -1.0 } else { 1.0 };
        JacobiValues {
            sn: sign * v.sn,
            cn: sign * v.cn,
            dn: v.dn,
            am: v.am + j * std::f64::consts::PI,
        }
    }

    /// sn, cn, dn and am at a reduced argument `|r| ≤ K` (see [`Jacobi::reduce`]); `am` is then
    /// in `[−π/2, π/2]`. Arguments outside are accepted but lose the quarter-period shift.
    pub fn eval_reduced(&self, r: f64) -> JacobiValues {
        if self.m == 0.0 || self.kc == 0.0 {
            return self.eval(r);
        }
        let x = r.abs();
        let k_hi = 0.5 * self.two_k.hi;
        let k_lo = 0.5 * self.two_k.lo;
        let (sn, cn, dn) = if x <= 0.5 * k_hi {
            let (s, c, d, _) = duplicate(x, self.m, self.mc);
            (s, c, d)
        } else {
            // x = K − v with 0 ≤ v < K/2 (the subtraction is exact by Sterbenz's lemma).
            let v = ((k_hi - x) + k_lo).max(0.0);
            let (s, _, d, cd) = duplicate(v, self.m, self.mc);
            (cd, self.kc * s / d, self.kc / d)
        };
        let am = sn.atan2(cn);
        let sign = if r < 0.0 { -1.0 } else { 1.0 };
        JacobiValues {
            sn: sign * sn,
            cn,
            dn,
            am: sign * am,
        }
    }

    /// (sn u, cn u, dn u).
    pub fn sncndn(&self, u: f64) -> (f64, f64, f64) {
        let v = self.eval(u);
        (v.sn, v.cn, v.dn)
    }

    /// am(u | m), the amplitude.
    pub fn am(&self, u: f64) -> f64 {
        self.eval(u).am
    }
}

impl Jacobi {
    /// Whether [`Jacobi::reduce_lanes`] and [`Jacobi::eval_reduced_lanes`] apply: 0 < m < 1 with
    /// a finite period (the limits m = 0 and m = 1 have their own closed forms).
    pub(crate) fn has_lanes(&self) -> bool {
        self.m > 0.0 && self.kc > 0.0 && self.two_k.hi.is_finite()
    }

    /// [`Jacobi::reduce`] of every lane (for [`Jacobi::has_lanes`], |u| < 2⁵⁰ K): `(j, r)` with
    /// `u = 2K·j + r`, bit for bit as the scalar function.
    #[inline(always)]
    pub(crate) fn reduce_lanes<S: Simd>(&self, u: F64s<S>) -> (F64s<S>, F64s<S>) {
        let j = (u / self.two_k.hi).round_away();
        let zero = j.eq(u.splat_like(0.0));
        let r = (-j).mul_add(u.splat_like(self.two_k.hi), u) - j * self.two_k.lo;
        (
            F64s::select(zero, u.splat_like(0.0), j),
            F64s::select(zero, u, r),
        )
    }

    /// sn, cn and dn of every lane of reduced arguments |r| ≤ K (for [`Jacobi::has_lanes`]):
    /// [`Jacobi::eval_reduced`] without the amplitude, bit for bit.
    #[inline(always)]
    pub(crate) fn eval_reduced_lanes<S: Simd>(&self, r: F64s<S>) -> (F64s<S>, F64s<S>, F64s<S>) {
        let x = r.abs();
        let k_hi = 0.5 * self.two_k.hi;
        let k_lo = 0.5 * self.two_k.lo;
        let near = x.le(x.splat_like(0.5 * k_hi));
        // x = K − v with 0 ≤ v < K/2 where x > K/2.
        let v = (k_hi - x) + k_lo;
        let v = F64s::select(v.lt(x.splat_like(0.0)), x.splat_like(0.0), v);
        let (s, c, d, cd) = duplicate_lanes(F64s::select(near, x, v), self.m, self.mc);
        let sn = F64s::select(near, s, cd);
        let cn = F64s::select(near, c, self.kc * s / d);
        let dn = F64s::select(near, d, self.kc / d);
        let sn = F64s::select(r.lt(r.splat_like(0.0)), -sn, sn);
        (sn, cn, dn)
    }
}

/// [`duplicate`] on lanes, each lane with its own number of halvings and its own switch from
/// the complements to `cn` and ρ, bit for bit.
#[inline(always)]
fn duplicate_lanes<S: Simd>(x: F64s<S>, m: f64, mc: f64) -> (F64s<S>, F64s<S>, F64s<S>, F64s<S>) {
    let one = x.splat_like(1.0);
    let series_max = x.splat_like(SERIES_MAX);
    let complement_max = x.splat_like(COMPLEMENT_MAX);
    let mut u = x;
    let mut n = x.splat_like(0.0);
    loop {
        let big = series_max.lt(u);
        if !big.any() {
            break;
        }
        u = F64s::select(big, u * 0.5, u);
        n = F64s::select(big, n + 1.0, n);
    }
    let u2 = u * u;
    let m2 = m * m;
    let m3 = m2 * m;
    let mut s = u
        * (1.0
            - u2 * ((1.0 + m) / 6.0
                - u2 * ((1.0 + 14.0 * m + m2) / 120.0
                    - u2 * (1.0 + 135.0 * m + 135.0 * m2 + m3) / 5040.0)));
    let mut c = 0.5
        * u2
        * (1.0
            - u2 * ((1.0 + 4.0 * m) / 12.0
                - u2 * ((1.0 + 44.0 * m + 16.0 * m2) / 360.0
                    - u2 * (1.0 + 408.0 * m + 912.0 * m2 + 64.0 * m3) / 20160.0)));
    let mut d = 0.5
        * m
        * u2
        * (1.0
            - u2 * ((4.0 + m) / 12.0
                - u2 * ((16.0 + 44.0 * m + m2) / 360.0
                    - u2 * (64.0 + 912.0 * m + 408.0 * m2 + m3) / 20160.0)));
    // Phase 1 (the complements) while cn is near 1, then phase 2 (sn, cn, ρ): a lane enters
    // phase 2 at the first of its duplications where c > 1/4.
    let mut cn = one - c;
    let mut in2 = x.lt(x.splat_like(0.0));
    let steps = n.max_lane() as usize;
    for i in 0..steps {
        let active = x.splat_like(i as f64).lt(n);
        let small = c.le(complement_max);
        let enter = active.and(in2.not()).and(small.not());
        cn = F64s::select(enter, one - c, cn);
        in2 = in2.or(enter);
        let p1 = active.and(in2.not());
        let p2 = active.and(in2);
        // Phase 1.
        let s2 = s * s;
        let cn1 = one - c;
        let dn1 = one - d;
        let den = 1.0 - m * s2 * s2;
        let s_1 = 2.0 * s * cn1 * dn1 / den;
        let c_1 = 2.0 * s2 * dn1 * dn1 / den;
        let d_1 = 2.0 * m * s2 * cn1 * cn1 / den;
        // Phase 2.
        let t = s / cn;
        let t2 = t * t;
        let rho = (1.0 + mc * t2).sqrt();
        let den2 = 1.0 + s2 + mc * s2 * t2;
        let s_2 = 2.0 * s * rho / den2;
        let cn_2 = cn * cn * (1.0 - mc * t2 * t2) / den2;
        s = F64s::select(p1, s_1, F64s::select(p2, s_2, s));
        c = F64s::select(p1, c_1, c);
        d = F64s::select(p1, d_1, d);
        cn = F64s::select(p2, cn_2, cn);
    }
    // Lanes that ended in phase 1 with cn near 1; the others (in phase 2, or with c > 1/4 after
    // their last duplication) finish from cn and ρ.
    let phase1 = in2.not().and(c.le(complement_max));
    let cn = F64s::select(in2, cn, one - c);
    let t = s / cn;
    let rho = (1.0 + mc * t * t).sqrt();
    let (cn1, dn1) = (one - c, one - d);
    (
        s,
        F64s::select(phase1, cn1, cn),
        F64s::select(phase1, dn1, cn * rho),
        F64s::select(phase1, cn1 / dn1, 1.0 / rho),
    )
}

/// The arithmetic–geometric mean of `a` and `b` (both > 0) in double-double.
fn agm_dd(mut a: Dd, mut b: Dd) -> Dd {
    for _ in 0..64 {
        let d = a.add(b.scale(-1.0));
        if d.hi.abs() <= 1e-33 * a.hi {
            break;
        }
        let a_next = a.add(b).scale(0.5);
        b = a.mul(b).sqrt();
        a = a_next;
    }
    a
}

/// sn, cn, dn and cd = cn/dn at `0 ≤ x ≤ K/2` by the Maclaurin series at x/2ⁿ and n
/// duplications.
///
/// Once `cn` has left 1, the duplication carries `sn`, `cn` and the ratio `ρ = dn/cn =
/// (1 + m₁ sc²)^½` rather than `dn` itself, so that the errors of `cn` and `dn` stay correlated
/// and `sn(2u) = 2 sn ρ / (1 + sn² + m₁ sn² sc²)` and `cd = 1/ρ` keep their full relative
/// accuracy even for m → 1 (where `cn` and `dn` are both small and nearly equal).
fn duplicate(x: f64, m: f64, mc: f64) -> (f64, f64, f64, f64) {
    let mut u = x;
    let mut n = 0u32;
    while u > SERIES_MAX {
        u *= 0.5;
        n += 1;
    }
    let u2 = u * u;
    // DLMF 22.10.4–6 (A&S 16.22): sn, and 1 − cn, 1 − dn factored by u²/2 and m u²/2.
    let m2 = m * m;
    let m3 = m2 * m;
    let mut s = u
        * (1.0
            - u2 * ((1.0 + m) / 6.0
                - u2 * ((1.0 + 14.0 * m + m2) / 120.0
                    - u2 * (1.0 + 135.0 * m + 135.0 * m2 + m3) / 5040.0)));
    let mut c = 0.5
        * u2
        * (1.0
            - u2 * ((1.0 + 4.0 * m) / 12.0
                - u2 * ((1.0 + 44.0 * m + 16.0 * m2) / 360.0
                    - u2 * (1.0 + 408.0 * m + 912.0 * m2 + 64.0 * m3) / 20160.0)));
    let mut d = 0.5
        * m
        * u2
        * (1.0
            - u2 * ((4.0 + m) / 12.0
                - u2 * ((16.0 + 44.0 * m + m2) / 360.0
                    - u2 * (64.0 + 912.0 * m + 408.0 * m2 + m3) / 20160.0)));
    let mut i = 0;
    // Phase 1: the complements c = 1 − cn, d = 1 − dn, while cn is near 1.
    while i < n && c <= COMPLEMENT_MAX {
        let s2 = s * s;
        let cn = 1.0 - c;
        let dn = 1.0 - d;
        let den = 1.0 - m * s2 * s2;
        let s_new = 2.0 * s * cn * dn / den;
        c = 2.0 * s2 * dn * dn / den;
        d = 2.0 * m * s2 * cn * cn / den;
        s = s_new;
        i += 1;
    }
    if i == n && c <= COMPLEMENT_MAX {
        let (cn, dn) = (1.0 - c, 1.0 - d);
        return (s, cn, dn, cn / dn);
    }
    // Phase 2: sn, cn and ρ = dn/cn.
    let mut cn = 1.0 - c;
    let ratio = |s: f64, cn: f64| {
        let t = s / cn;
        (1.0 + mc * t * t).sqrt()
    };
    while i < n {
        let s2 = s * s;
        let t = s / cn;
        let t2 = t * t;
        let rho = (1.0 + mc * t2).sqrt();
        // D / cn² with D = 1 − m sn⁴ = cn²(1 + sn²) + m₁ sn⁴.
        let den = 1.0 + s2 + mc * s2 * t2;
        s = 2.0 * s * rho / den;
        cn = cn * cn * (1.0 - mc * t2 * t2) / den;
        i += 1;
    }
    let rho = ratio(s, cn);
    (s, cn, cn * rho, 1.0 / rho)
}

fn check_parameter(m: f64) -> Result<()> {
    if m.is_finite() && (0.0..=1.0).contains(&m) {
        Ok(())
    } else {
        Err(Error::invalid(
            "m",
            format!("the parameter m = k² must be finite and in [0, 1], got {m}"),
        ))
    }
}

/// sn(u | m) for `0 ≤ m ≤ 1` (parameter m = k²); the error names `u` or `m`.
pub fn sn(u: f64, m: f64) -> Result<f64> {
    Ok(jacobi_all(u, m)?.sn)
}

/// cn(u | m) for `0 ≤ m ≤ 1` (parameter m = k²); the error names `u` or `m`.
pub fn cn(u: f64, m: f64) -> Result<f64> {
    Ok(jacobi_all(u, m)?.cn)
}

/// dn(u | m) for `0 ≤ m ≤ 1` (parameter m = k²); the error names `u` or `m`.
pub fn dn(u: f64, m: f64) -> Result<f64> {
    Ok(jacobi_all(u, m)?.dn)
}

/// am(u | m), the Jacobi amplitude (the inverse of F(φ | m) in φ), for `0 ≤ m ≤ 1`.
pub fn am(u: f64, m: f64) -> Result<f64> {
    Ok(jacobi_all(u, m)?.am)
}

/// (sn, cn, dn)(u | m) for `0 ≤ m ≤ 1` at once (parameter m = k²).
pub fn sncndn(u: f64, m: f64) -> Result<(f64, f64, f64)> {
    let v = jacobi_all(u, m)?;
    Ok((v.sn, v.cn, v.dn))
}

/// sn, cn, dn and am at `u` for parameter `m` (builds a [`Jacobi`]: prefer that for many `u`).
/// Errors name `m` (not in [0, 1]) or `u` (not finite, or beyond [`Jacobi::max_argument`]).
pub fn jacobi_all(u: f64, m: f64) -> Result<JacobiValues> {
    crate::error::check_finite("u", &[u])?;
    Jacobi::new(m)?.eval_checked(u)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::simd::{dispatch, WithSimd, MAX_LANES};

    /// The lanes against the scalar functions, bit for bit, on instruction set `s`.
    fn lanes_on<S: Simd>(s: S) {
        let lanes = F64s::<S>::LANES;
        for j in [
            Jacobi::new(1e-300).unwrap(),
            Jacobi::new(1e-9).unwrap(),
            Jacobi::new(0.3).unwrap(),
            Jacobi::new(0.5).unwrap(),
            Jacobi::new(0.97).unwrap(),
            Jacobi::with_complement(1.0 - 1e-12, 1e-12).unwrap(),
            Jacobi::with_complementary_modulus(1e-100).unwrap(),
        ] {
            assert!(j.has_lanes());
            let k = j.quarter_period();
            let mut us: Vec<f64> = (0..2000)
                .map(|i| -9.0 * k + 18.0 * k * i as f64 / 1999.0)
                .collect();
            us.extend([
                0.0,
                -0.0,
                1e-300,
                k,
                -k,
                0.5 * k,
                2.0 * k,
                1e-5,
                k * (1.0 - 1e-15),
                7.3e4,
            ]);
            for chunk in us.chunks(lanes) {
                let mut buf = [0.0; MAX_LANES];
                buf[..chunk.len()].copy_from_slice(chunk);
                let (jj, r) = j.reduce_lanes(F64s::load(s, &buf));
                let (sn, cn, dn) = j.eval_reduced_lanes(r);
                for (i, &u) in chunk.iter().enumerate() {
                    let (j0, r0) = j.reduce(u);
                    assert_eq!(
                        (jj.lanes()[i], r.lanes()[i]),
                        (j0, r0),
                        "m = {} u = {u}",
                        j.m()
                    );
                    let v = j.eval_reduced(r0);
                    let got = (sn.lanes()[i], cn.lanes()[i], dn.lanes()[i]);
                    assert_eq!(got, (v.sn, v.cn, v.dn), "m = {} u = {u}", j.m());
                }
            }
        }
    }

    struct Lanes;
    impl WithSimd for Lanes {
        type Output = ();
        #[inline(always)]
        fn with_simd<S: Simd>(self, s: S) {
            lanes_on(s)
        }
    }

    /// sn, cn, dn on lanes equal the scalar functions bit for bit (each lane its own number of
    /// duplications and its own switch from the complements), on this CPU's instructions and
    /// in scalar code.
    #[test]
    fn lanes_equal_the_scalar_functions() {
        dispatch(Lanes);
        lanes_on(pulp::Scalar);
    }

    #[test]
    fn identities_hold_over_the_whole_parameter_range() {
        for &m in &[
            1e-300,
            1e-12,
            0.1,
            0.5,
            0.9,
            1.0 - 1e-6,
            1.0 - 1e-12,
            1.0 - 2f64.powi(-52),
        ] {
            let j = Jacobi::new(m).unwrap();
            for &u in &[0.0, 1e-9, 0.3, 1.0, 2.5, 7.0, -13.0, 100.0, -1.0e4] {
                let v = j.eval(u);
                assert!(
                    (v.sn * v.sn + v.cn * v.cn - 1.0).abs() < 4e-15,
                    "m={m} u={u} {v:?}"
                );
                assert!(
                    (v.dn * v.dn + m * v.sn * v.sn - 1.0).abs() < 4e-15,
                    "m={m} u={u} {v:?}"
                );
                assert!(
                    (v.am.sin() - v.sn).abs() < 1e-14 * (1.0 + v.am.abs()),
                    "m={m} u={u} {v:?}"
                );
            }
        }
    }

    #[test]
    fn quarter_period_values() {
        // sn(K) = 1, cn(K) = 0, dn(K) = k', am(K) = π/2 (DLMF 22.5.1).
        let j = Jacobi::new(0.7).unwrap();
        let v = j.eval(j.quarter_period());
        assert!((v.sn - 1.0).abs() < 1e-15);
        assert!(v.cn.abs() < 1e-15);
        assert!((v.dn - 0.3f64.sqrt()).abs() < 1e-15);
        assert!((v.am - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
    }

    #[test]
    fn bad_parameters_are_named() {
        assert_eq!(Jacobi::new(1.5).unwrap_err().argument, "m");
        assert_eq!(Jacobi::new(f64::NAN).unwrap_err().argument, "m");
        assert_eq!(Jacobi::new(-0.1).unwrap_err().argument, "m");
        assert_eq!(sn(f64::INFINITY, 0.5).unwrap_err().argument, "u");
        assert_eq!(
            Jacobi::with_complement(0.5, 0.6).unwrap_err().argument,
            "mc"
        );
    }
}
