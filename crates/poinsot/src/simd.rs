//! Lanes for the batch kernels: [`F64s`], a few vector registers of doubles operated on
//! together, and [`dispatch`], which runs a kernel with the widest vector instructions the CPU
//! has.
//!
//! The batch kernels (many bodies, many times) are written once, generic over pulp's
//! [`Simd`] instruction set `S`, in plain arithmetic on `F64s<S>`: every operator is one vector
//! instruction per register (no reliance on the compiler's auto-vectorizer). [`dispatch`] picks
//! `S` at run time — AVX2 + FMA (x86-64-v3: 4 doubles per register) when the CPU has it, plain
//! scalar code otherwise (and on other targets, where pulp supplies NEON or scalar code) — so
//! the wheels, built for baseline x86-64, still use the wide instructions. pulp keeps the
//! `unsafe` intrinsics in itself (this crate is `#![forbid(unsafe_code)]`). Everything a kernel
//! calls must be `#[inline(always)]`: code that is not inlined into the dispatched function is
//! compiled for the baseline instruction set.
//!
//! An `F64s` holds [`WIDTH`] registers: two independent chains of operations per instruction
//! stream, so that one group's long dependency chain (an RK4 step is ~100 cycles of latency)
//! does not leave the floating-point units idle.
//!
//! Each lane performs exactly the operations of the scalar code it mirrors, in the same order,
//! with no fused multiply-add (`F64s::mul_add` only where the scalar code it mirrors fuses,
//! `f64::mul_add`): a body's result does not depend on its lane, on the batch it is in, on the number of threads or on the instruction set.

use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

pub(crate) use pulp::{Simd, WithSimd};

/// Vector registers per [`F64s`].
pub(crate) const WIDTH: usize = 2;

/// The most lanes an [`F64s`] can have (8 doubles per register of AVX-512, times [`WIDTH`]):
/// the size of the buffers that gather and scatter lanes.
pub(crate) const MAX_LANES: usize = 16;

/// [`WIDTH`] vector registers of doubles, `F64s::<S>::LANES` lanes, operated on lane by lane.
#[derive(Debug, Clone, Copy)]
pub(crate) struct F64s<S: Simd> {
    s: S,
    v: [S::f64s; WIDTH],
}

/// A mask of lanes (the result of comparing two [`F64s`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Mask<S: Simd> {
    s: S,
    v: [S::m64s; WIDTH],
}

/// Runs `kernel` with the widest vector instructions this CPU has (see the module docs).
#[inline(always)]
pub(crate) fn dispatch<K: WithSimd>(kernel: K) -> K::Output {
    pulp::Arch::new().dispatch(kernel)
}

/// `[e(0), e(1)]`: the [`WIDTH`] registers, written out (no closure: a closure the compiler
/// does not inline would be compiled for the baseline instruction set, and every intrinsic in
/// it would become a call).
macro_rules! each {
    (|$k:ident| $e:expr) => {{
        let r0 = {
            let $k = 0;
            $e
        };
        let r1 = {
            let $k = 1;
            $e
        };
        [r0, r1]
    }};
}

macro_rules! lanewise {
    ($trait:ident, $method:ident, $simd:ident, $assign:ident, $assign_method:ident) => {
        impl<S: Simd> $trait for F64s<S> {
            type Output = F64s<S>;
            #[inline(always)]
            fn $method(self, rhs: F64s<S>) -> F64s<S> {
                let s = self.s;
                F64s {
                    s,
                    v: each!(|k| s.$simd(self.v[k], rhs.v[k])),
                }
            }
        }
        impl<S: Simd> $trait<f64> for F64s<S> {
            type Output = F64s<S>;
            #[inline(always)]
            fn $method(self, rhs: f64) -> F64s<S> {
                self.$method(F64s::splat(self.s, rhs))
            }
        }
        impl<S: Simd> $trait<F64s<S>> for f64 {
            type Output = F64s<S>;
            #[inline(always)]
            fn $method(self, rhs: F64s<S>) -> F64s<S> {
                F64s::splat(rhs.s, self).$method(rhs)
            }
        }
        impl<S: Simd> $assign for F64s<S> {
            #[inline(always)]
            fn $assign_method(&mut self, rhs: F64s<S>) {
                *self = self.$method(rhs);
            }
        }
    };
}

lanewise!(Add, add, add_f64s, AddAssign, add_assign);
lanewise!(Sub, sub, sub_f64s, SubAssign, sub_assign);
lanewise!(Mul, mul, mul_f64s, MulAssign, mul_assign);
lanewise!(Div, div, div_f64s, DivAssign, div_assign);

impl<S: Simd> Neg for F64s<S> {
    type Output = F64s<S>;
    #[inline(always)]
    fn neg(self) -> F64s<S> {
        let s = self.s;
        F64s {
            s,
            v: each!(|k| s.neg_f64s(self.v[k])),
        }
    }
}

impl<S: Simd> F64s<S> {
    /// The number of lanes.
    pub(crate) const LANES: usize = S::F64_LANES * WIDTH;

    /// Every lane `x`.
    #[inline(always)]
    pub(crate) fn splat(s: S, x: f64) -> Self {
        F64s {
            s,
            v: [s.splat_f64s(x); WIDTH],
        }
    }

    /// The lanes from the first [`Self::LANES`] values of `x` (unaligned loads).
    #[inline(always)]
    pub(crate) fn load(s: S, x: &[f64]) -> Self {
        let n = S::F64_LANES;
        let reg = |k: usize| -> S::f64s {
            pulp::bytemuck::pod_read_unaligned(pulp::bytemuck::cast_slice(&x[k * n..(k + 1) * n]))
        };
        F64s {
            s,
            v: [reg(0), reg(1)],
        }
    }

    /// Lane `i` is `f(i)`, for `i < LANES`.
    #[cfg(test)]
    #[inline(always)]
    pub(crate) fn from_fn(s: S, mut f: impl FnMut(usize) -> f64) -> Self {
        let mut buf = [0.0; MAX_LANES];
        for (i, b) in buf.iter_mut().enumerate().take(Self::LANES) {
            *b = f(i);
        }
        Self::load(s, &buf)
    }

    /// The lanes as a slice.
    #[inline(always)]
    pub(crate) fn lanes(&self) -> &[f64] {
        pulp::bytemuck::cast_slice(&self.v)
    }

    /// The lanes as a mutable slice (for work done lane by lane).
    #[inline(always)]
    pub(crate) fn lanes_mut(&mut self) -> &mut [f64] {
        pulp::bytemuck::cast_slice_mut(&mut self.v)
    }

    /// Every lane `x` (the instruction set of `self`).
    #[inline(always)]
    pub(crate) fn splat_like(&self, x: f64) -> Self {
        Self::splat(self.s, x)
    }

    /// The square root of every lane (IEEE, correctly rounded like `f64::sqrt`).
    #[inline(always)]
    pub(crate) fn sqrt(self) -> Self {
        let s = self.s;
        F64s {
            s,
            v: each!(|k| s.sqrt_f64s(self.v[k])),
        }
    }

    /// |x| of every lane.
    #[inline(always)]
    pub(crate) fn abs(self) -> Self {
        let s = self.s;
        F64s {
            s,
            v: each!(|k| s.abs_f64s(self.v[k])),
        }
    }

    /// Every lane rounded to the nearest integer, ties to even, for |x| < 2⁵¹ (by adding and
    /// subtracting 1.5·2⁵²).
    #[inline(always)]
    pub(crate) fn round_small(self) -> Self {
        const MAGIC: f64 = 6_755_399_441_055_744.0;
        (self + MAGIC) - MAGIC
    }

    /// `self · b + c` with one rounding (a fused multiply-add, as `f64::mul_add`): for the
    /// kernels that mirror scalar code which fuses. Never used to speed up a plain `a * b + c`,
    /// whose two roundings the lanes keep.
    #[inline(always)]
    pub(crate) fn mul_add(self, b: Self, c: Self) -> Self {
        let s = self.s;
        F64s {
            s,
            v: each!(|k| s.mul_add_f64s(self.v[k], b.v[k], c.v[k])),
        }
    }

    /// Every lane rounded to the nearest integer, ties away from zero (as `f64::round`), for
    /// |x| < 2⁵¹.
    #[inline(always)]
    pub(crate) fn round_away(self) -> Self {
        let even = self.round_small();
        let tie = (self - even).abs().eq(self.splat_like(0.5));
        let half = F64s::select(
            self.lt(self.splat_like(0.0)),
            self.splat_like(-0.5),
            self.splat_like(0.5),
        );
        F64s::select(tie, self + half, even)
    }

    /// The lanes holding an odd integer (for integer-valued lanes below 2⁵¹: as
    /// `x.rem_euclid(2.0) == 1.0`).
    #[inline(always)]
    pub(crate) fn is_odd(self) -> Mask<S> {
        let half = (self * 0.5).round_small();
        let floor = F64s::select(self.lt(half * 2.0), half - 1.0, half);
        (self - floor * 2.0).eq(self.splat_like(1.0))
    }

    /// Lane by lane: `a` where `mask`, else `b`.
    #[inline(always)]
    pub(crate) fn select(mask: Mask<S>, a: Self, b: Self) -> Self {
        let s = a.s;
        F64s {
            s,
            v: each!(|k| s.select_f64s(mask.v[k], a.v[k], b.v[k])),
        }
    }

    /// The lanes where `self < other`.
    #[inline(always)]
    pub(crate) fn lt(self, other: Self) -> Mask<S> {
        let s = self.s;
        Mask {
            s,
            v: each!(|k| s.less_than_f64s(self.v[k], other.v[k])),
        }
    }

    /// The lanes where `self <= other`.
    #[inline(always)]
    pub(crate) fn le(self, other: Self) -> Mask<S> {
        let s = self.s;
        Mask {
            s,
            v: each!(|k| s.less_than_or_equal_f64s(self.v[k], other.v[k])),
        }
    }

    /// The lanes where `self == other`.
    #[inline(always)]
    pub(crate) fn eq(self, other: Self) -> Mask<S> {
        let s = self.s;
        Mask {
            s,
            v: each!(|k| s.equal_f64s(self.v[k], other.v[k])),
        }
    }

    /// The smallest lane (NaN lanes ignored).
    #[inline(always)]
    pub(crate) fn min_lane(&self) -> f64 {
        self.lanes().iter().fold(f64::INFINITY, |a, &b| a.min(b))
    }

    /// The largest lane (NaN lanes ignored).
    #[inline(always)]
    pub(crate) fn max_lane(&self) -> f64 {
        self.lanes()
            .iter()
            .fold(f64::NEG_INFINITY, |a, &b| a.max(b))
    }
}

impl<S: Simd> Mask<S> {
    /// Lane-wise and.
    #[inline(always)]
    pub(crate) fn and(self, other: Self) -> Self {
        let s = self.s;
        Mask {
            s,
            v: each!(|k| s.and_m64s(self.v[k], other.v[k])),
        }
    }

    /// Lane-wise or.
    #[inline(always)]
    pub(crate) fn or(self, other: Self) -> Self {
        let s = self.s;
        Mask {
            s,
            v: each!(|k| s.or_m64s(self.v[k], other.v[k])),
        }
    }

    /// Lane-wise not.
    #[inline(always)]
    pub(crate) fn not(self) -> Self {
        let s = self.s;
        Mask {
            s,
            v: each!(|k| s.not_m64s(self.v[k])),
        }
    }

    /// The mask as lanes of 1.0 (set) and 0.0.
    #[inline(always)]
    fn ones(&self) -> F64s<S> {
        let s = self.s;
        F64s::select(*self, F64s::splat(s, 1.0), F64s::splat(s, 0.0))
    }

    /// Whether lane `i` is set.
    #[inline(always)]
    pub(crate) fn get(&self, i: usize) -> bool {
        self.ones().lanes()[i] != 0.0
    }

    /// Whether any lane is set.
    #[inline(always)]
    pub(crate) fn any(&self) -> bool {
        self.ones().lanes().iter().any(|&b| b != 0.0)
    }
}

/// Arguments beyond this |x| are handed to the standard library's `sin_cos` by [`sin_cos`]:
/// below it the quadrant count n = round(x·2/π) < 2²⁰ keeps n·(π/2)'s three parts exact.
const SIN_COS_VECTOR_MAX: f64 = 524_288.0; // 2^19

/// sin x and cos x of every lane, within 2 ulp of the correctly rounded values (`f64::sin_cos`
/// is within 1): the quadrant reduction x = n π/2 + y with π/2 in three parts of 33 bits
/// (Cody & Waite; exact products for n < 2²⁰), then the Taylor series of sin and cos on
/// |y| ≤ π/4 to y¹⁷ and y¹⁸ (the next terms are below 1e-19). Lanes with |x| > 2¹⁹ (never a
/// step's rotation angle in practice) are computed by the standard library.
#[inline(always)]
pub(crate) fn sin_cos<S: Simd>(x: F64s<S>) -> (F64s<S>, F64s<S>) {
    // π/2 = P1 + P2 + P3, P1 and P2 with 33 significant bits (fdlibm's pio2_1, pio2_2), P3
    // the rest rounded (pio2_2t).
    const P1: f64 = 1.570_796_326_734_125_6;
    const P2: f64 = 6.077_100_506_303_966e-11;
    const P3: f64 = 2.022_266_248_795_950_6e-21;
    let n = (x * std::f64::consts::FRAC_2_PI).round_small();
    let y = ((x - n * P1) - n * P2) - n * P3;
    let (sy, cy) = sin_cos_kernel(y);
    let (mut s, mut c) = rotate_by_quadrant(n, sy, cy);
    let big = x.abs().le(x.splat_like(SIN_COS_VECTOR_MAX)).not();
    if big.any() {
        for i in 0..F64s::<S>::LANES {
            if big.get(i) {
                (s.lanes_mut()[i], c.lanes_mut()[i]) = x.lanes()[i].sin_cos();
            }
        }
    }
    (s, c)
}

/// (sin, cos) of y + n π/2 from sin y and cos y, n a whole number (in doubles, exact for
/// |n| < 2⁵¹): the quadrant n mod 4 ∈ {0, 1, 2, 3} swaps and negates them.
#[inline(always)]
pub(crate) fn rotate_by_quadrant<S: Simd>(
    n: F64s<S>,
    sy: F64s<S>,
    cy: F64s<S>,
) -> (F64s<S>, F64s<S>) {
    let quarter = (n * 0.25).round_small();
    let quarter = F64s::select(n.lt(quarter * 4.0), quarter - 1.0, quarter);
    let quadrant = n - quarter * 4.0;
    let one = n.splat_like(1.0);
    let two = n.splat_like(2.0);
    let three = n.splat_like(3.0);
    let odd = quadrant.eq(one).or(quadrant.eq(three));
    let (s, c) = (F64s::select(odd, cy, sy), F64s::select(odd, sy, cy));
    let flip_s = two.le(quadrant);
    let flip_c = quadrant.eq(one).or(quadrant.eq(two));
    (F64s::select(flip_s, -s, s), F64s::select(flip_c, -c, c))
}

/// The Taylor coefficients of sin y / y in z = y² (to y¹⁷), for [`sin_cos_kernel`] and the
/// scalar code it mirrors.
pub(crate) const SIN_TAYLOR: [f64; 9] = [
    1.0,
    -1.0 / 6.0,
    1.0 / 120.0,
    -1.0 / 5_040.0,
    1.0 / 362_880.0,
    -1.0 / 39_916_800.0,
    1.0 / 6_227_020_800.0,
    -1.0 / 1_307_674_368_000.0,
    1.0 / 355_687_428_096_000.0,
];

/// The Taylor coefficients of cos y in z = y² (to y¹⁸).
pub(crate) const COS_TAYLOR: [f64; 10] = [
    1.0,
    -0.5,
    1.0 / 24.0,
    -1.0 / 720.0,
    1.0 / 40_320.0,
    -1.0 / 3_628_800.0,
    1.0 / 479_001_600.0,
    -1.0 / 87_178_291_200.0,
    1.0 / 20_922_789_888_000.0,
    -1.0 / 6_402_373_705_728_000.0,
];

/// The Taylor coefficients of atan x / x in z = x² (to x²¹): the heavy top's θ = 2 atan(√(w/v))
/// (scalar and on lanes, `heavy_top::fourier`) and, as the series of R_C(1, 1 + z) =
/// atan(√z)/√z, Carlson's R_C next to its pole (`special::carlson`, its first ten).
pub(crate) const ATAN_TAYLOR: [f64; 11] = [
    1.0,
    -1.0 / 3.0,
    1.0 / 5.0,
    -1.0 / 7.0,
    1.0 / 9.0,
    -1.0 / 11.0,
    1.0 / 13.0,
    -1.0 / 15.0,
    1.0 / 17.0,
    -1.0 / 19.0,
    1.0 / 21.0,
];

/// sin y and cos y for |y| ≤ π/4 (a hair beyond is harmless): Taylor series in z = y², Horner.
#[inline(always)]
pub(crate) fn sin_cos_kernel<S: Simd>(y: F64s<S>) -> (F64s<S>, F64s<S>) {
    let z = y * y;
    let mut ps = y.splat_like(SIN_TAYLOR[8]);
    for &c in SIN_TAYLOR[..8].iter().rev() {
        ps = ps * z + c;
    }
    let mut pc = y.splat_like(COS_TAYLOR[9]);
    for &c in COS_TAYLOR[..9].iter().rev() {
        pc = pc * z + c;
    }
    (y * ps, pc)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The checks of a test on one instruction set.
    fn sin_cos_on<S: Simd>(s: S) {
        let lanes = F64s::<S>::LANES;
        let mut worst: f64 = 0.0;
        let mut check = |xs: &[f64]| {
            let (sn, cs) = sin_cos(F64s::load(s, xs));
            for (i, x) in xs.iter().enumerate().take(lanes) {
                let (ws, wc) = x.sin_cos();
                worst = worst
                    .max((sn.lanes()[i] - ws).abs())
                    .max((cs.lanes()[i] - wc).abs());
            }
        };
        let total = 400_000;
        let mut buf = [0.0; MAX_LANES];
        for k in 0..total / lanes {
            for (i, b) in buf.iter_mut().enumerate().take(lanes) {
                *b = -40.0 + 80.0 * (k * lanes + i) as f64 / total as f64;
            }
            check(&buf);
        }
        for j in -50..50 {
            let mut x = j as f64 * std::f64::consts::FRAC_PI_2;
            for b in buf.iter_mut().take(lanes) {
                *b = x;
                x = x.next_up();
            }
            check(&buf);
        }
        let special = [
            1e-300,
            -1e-20,
            3e-9,
            0.0,
            -0.0,
            5e5,
            6e5,
            1e300,
            -7e5,
            std::f64::consts::FRAC_PI_4,
            2.5,
            -3.9,
            100.0,
            1e4,
            -2e5,
            0.1,
        ];
        for chunk in special.chunks(lanes) {
            buf[..chunk.len()].copy_from_slice(chunk);
            check(&buf);
        }
        assert!(worst <= 2.0 * f64::EPSILON, "sin/cos: {worst:e}");
        // A negative control: the kernel alone, without the reduction, is wrong beyond π/4.
        let (sn, _) = sin_cos_kernel(F64s::splat(s, 10.0));
        assert!((sn.lanes()[0] - 10f64.sin()).abs() > 1e-3);
    }

    struct SinCos;
    impl WithSimd for SinCos {
        type Output = ();
        #[inline(always)]
        fn with_simd<S: Simd>(self, s: S) {
            sin_cos_on(s)
        }
    }

    /// The lane sin/cos against the standard library: 2 ulp of 1 (absolute) on a dense grid of
    /// [−40, 40], next to multiples of π/2, and the hand-off beyond 2¹⁹; with the instruction
    /// set of this CPU and with scalar code.
    #[test]
    fn sin_cos_matches_the_standard_library() {
        dispatch(SinCos);
        sin_cos_on(pulp::Scalar);
    }

    struct Arithmetic;
    impl WithSimd for Arithmetic {
        type Output = ();
        #[inline(always)]
        fn with_simd<S: Simd>(self, s: S) {
            let a = F64s::from_fn(s, |i| i as f64 + 1.0);
            let b = F64s::splat(s, 2.0);
            assert_eq!((a * b + 1.0).lanes()[1], 5.0);
            assert_eq!((1.0 - a / b).lanes()[1], 0.0);
            let m = F64s::select(a.lt(b), a, b);
            assert_eq!(&m.lanes()[..2], &[1.0, 2.0]);
            assert!(a.lt(b).get(0) && !a.lt(b).get(1) && a.lt(b).any());
            assert!(!a.lt(a).any());
            assert_eq!((a * a).sqrt().lanes()[1], 2.0);
            assert_eq!(a.min_lane(), 1.0);
            assert_eq!(a.max_lane(), F64s::<S>::LANES as f64);
            assert_eq!(F64s::splat(s, 2.5).round_small().lanes()[0], 2.0);
            for x in [2.5, -2.5, 3.5, 0.49999999999999994, -7.0, 1e15 + 0.5] {
                assert_eq!(F64s::splat(s, x).round_away().lanes()[0], x.round(), "{x}");
            }
            for j in [-3.0, -2.0, -1.0, 0.0, 1.0, 4.0, 7.0, 1e12 + 1.0] {
                let odd = F64s::splat(s, j).is_odd().get(0);
                assert_eq!(odd, f64::rem_euclid(j, 2.0) == 1.0, "{j}");
            }
            let fused = F64s::splat(s, 0.1).mul_add(F64s::splat(s, 10.0), F64s::splat(s, -1.0));
            assert_eq!(fused.lanes()[0], 0.1f64.mul_add(10.0, -1.0));
            assert!(F64s::<S>::LANES >= WIDTH);
        }
    }

    #[test]
    fn lanes_compute_lane_by_lane() {
        dispatch(Arithmetic);
        Arithmetic.with_simd(pulp::Scalar);
    }
}
