//! The exact motion of the heavy top as Fourier series with closed-form coefficients: the fast
//! path of [`super::HeavyTop::euler_angles`].
//!
//! In the phase `x = πτ/K` (period 2π = one nutation period) every periodic part of the motion
//! has a Fourier series whose coefficients are known in closed form from Jacobi's theta-function
//! expansions (Whittaker & Watson §22.6, §22.74; DLMF 22.11):
//!
//! * `sn²τ = D/K − (2π²/(mK²)) Σ k qᵏ/(1 − q²ᵏ) cos kx`, q = exp(−πK'/K) the nome, D = (K − E)/m;
//! * for `n = m sn²a`, `∫₀^τ dτ'/(1 − n sn²τ') = (Π(n|m)/K) τ − (sn a/(cn a dn a)) Σ (2/k) qᵏ/(1 − q²ᵏ)
//!   sin(kπa/K) sin kx` (from Jacobi's Π(u, a) = u Z(a) + ½ ln Θ(u − a)/Θ(u + a)).
//!
//! For the circular case m < n < 1 the parameter is a = K + i b, for −∞ < n < 0 it is a = i b; with
//! `β = K' − b` (the distance of the integrand's pole from the real axis, in the units of τ),
//! `ρ = exp(−πβ/K)`, the coefficient of sin kx is
//! `(±1)ᵏ c (ρᵏ − (q²/ρ)ᵏ) / (k (1 − q²ᵏ))`, with `c = √(n/((n − m)(1 − n)))`, sign (−1)ᵏ
//! (circular), and `c = √(−n/((m − n)(1 − n)))`, sign +1 (n < 0); `β = F(arcsin √((1 − n)/(1 − m)) | 1 − m)`
//! (circular) or `F(arcsin √(1/(1 − n)) | 1 − m)` (n < 0), all through Carlson's R_F.
//!
//! The series converge geometrically (ratios q and ρ); they are summed to round-off, so this is
//! the exact solution, evaluated with one sin/cos and a rotation recurrence per time. Where a
//! ratio is too close to 1 (the axis passing very near a pole, or m → 1) more than
//! [`MAX_TERMS`] terms would be needed, and the solution is evaluated by Carlson's R_J instead.

use crate::simd::{
    rotate_by_quadrant, sin_cos_kernel, F64s, Simd, WithSimd, ATAN_TAYLOR, COS_TAYLOR, SIN_TAYLOR,
};
use crate::special::carlson::{rd, rf};
use std::f64::consts::PI;

/// The most Fourier terms the fast path uses; beyond, the incomplete integrals are evaluated.
pub(crate) const MAX_TERMS: usize = 64;
/// Terms below this fraction of the series' scale are dropped (below half an ulp).
pub(crate) const TRUNCATION: f64 = 1e-17;

/// One third-kind integral's Fourier data: `c`, the sign pattern, ρ (see the module docs).
#[derive(Debug, Clone, Copy)]
pub(crate) struct ThirdSeries {
    c: f64,
    alternating: bool,
    rho: f64,
}

impl ThirdSeries {
    /// Circular case m < n < 1, from n, 1 − n, n − m and 1 − m (each accurate).
    pub(crate) fn circular(
        n: f64,
        one_minus_n: f64,
        n_minus_m: f64,
        mc: f64,
        k: f64,
    ) -> Option<Self> {
        if !(n_minus_m > 0.0 && one_minus_n > 0.0 && mc > 0.0) {
            return None;
        }
        let c = (n / (n_minus_m * one_minus_n)).sqrt();
        // β = F(φ | 1 − m), sin²φ = (1 − n)/(1 − m), cos²φ = (n − m)/(1 − m), 1 − (1 − m) sin²φ = n.
        let beta = (one_minus_n / mc).sqrt() * rf(n_minus_m / mc, n, 1.0);
        Some(Self {
            c,
            alternating: true,
            rho: (-PI * beta / k).exp(),
        })
    }

    /// Hyperbolic case n < 0, from −n, 1 − n, m − n and m, 1 − m.
    pub(crate) fn hyperbolic(
        minus_n: f64,
        one_minus_n: f64,
        m: f64,
        mc: f64,
        k: f64,
    ) -> Option<Self> {
        if !(minus_n > 0.0 && mc > 0.0) {
            return None;
        }
        let c = (minus_n / ((m + minus_n) * one_minus_n)).sqrt();
        // β = F(φ | 1 − m), sin²φ = 1/(1 − n), cos²φ = −n/(1 − n), 1 − (1 − m) sin²φ = (m − n)/(1 − n).
        let s2 = 1.0 / one_minus_n;
        let beta = s2.sqrt() * rf(minus_n * s2, (m + minus_n) * s2, 1.0);
        Some(Self {
            c,
            alternating: false,
            rho: (-PI * beta / k).exp(),
        })
    }

    /// The coefficient of sin kx (k ≥ 1) given q.
    pub(crate) fn coefficient(&self, kk: usize, q: f64) -> f64 {
        let kf = kk as f64;
        let q2k = q.powi(2 * kk as i32);
        let r = self.rho.powi(kk as i32) - (q * q / self.rho).powi(kk as i32);
        let sign = if self.alternating && kk % 2 == 1 {
            -1.0
        } else {
            1.0
        };
        sign * self.c * r / (kf * (1.0 - q2k))
    }
}

/// The input of the series: the solution's constants, as [`super::motion`] has them.
pub(crate) struct SeriesInput {
    pub k: f64,
    pub k_prime: f64,
    pub m: f64,
    pub mc: f64,
    pub kappa: f64,
    pub tau0: f64,
    pub w_hi: f64,
    /// w₂ − w₁ = v₂ − v₁, about the nearer pole (`Turning::spread`).
    pub spread: f64,
    pub v_lo: f64,
    pub v_hi: f64,
    /// Series of ∫dτ/w with its factor (φ gets `half_d · factor`), if present.
    pub w_series: Option<(ThirdSeries, f64)>,
    /// Series of ∫dτ/v with its factor and whether it is in σ = τ − K (shift by π in x).
    pub v_series: Option<(ThirdSeries, f64, bool)>,
    pub half_d: f64,
    pub half_e: f64,
    pub phi0: f64,
    pub psi0: f64,
    pub phi_rate: f64,
    pub psi_rate: f64,
}

/// The Fourier form of a nutating top's motion.
#[derive(Debug, Clone)]
pub(crate) struct Fourier {
    x0: f64,
    nu: f64,
    w_mean: f64,
    v_mean: f64,
    /// w = w̄ + Σ A_k cos kx, v = v̄ − Σ A_k cos kx.
    a: Vec<f64>,
    /// φ = φ_base + ⟨φ̇⟩t + Σ B_k sin kx (and ψ likewise).
    b_phi: Vec<f64>,
    b_psi: Vec<f64>,
    phi_base: f64,
    psi_base: f64,
    phi_rate: f64,
    psi_rate: f64,
}

/// The nome q = exp(−πK'/K) and q/m (finite as m → 0, where q ≈ m/16).
pub(crate) fn nome(m: f64, k: f64, k_prime: f64) -> (f64, f64) {
    if m < 1e-4 {
        // q = m/16 + 8(m/16)² + 84(m/16)³ + 992(m/16)⁴ + … (DLMF 19.5.5); the next term is < 1e-23.
        let e = m / 16.0;
        let q_over_m = (1.0 + e * (8.0 + e * (84.0 + e * 992.0))) / 16.0;
        (m * q_over_m, q_over_m)
    } else {
        let q = (-PI * k_prime / k).exp();
        (q, q / m)
    }
}

impl Fourier {
    /// The series, or `None` when they would need more than [`MAX_TERMS`] terms.
    pub(crate) fn new(s: &SeriesInput) -> Option<Self> {
        let (q, q_over_m) = nome(s.m, s.k, s.k_prime);
        if q.is_nan() || q >= 0.5 {
            return None;
        }
        // ⟨sn²⟩ = D/K with D = (K − E)/m = R_D(0, 1 − m, 1)/3.
        let d = rd(0.0, s.mc, 1.0);
        if d.is_nan() {
            return None;
        }
        let d = d / 3.0;
        let mean_sn2 = d / s.k;
        // The amplitude w₂ − w₁ = v₂ − v₁ from the pole distances that are exact here (near the
        // hanging pole w₂ − w₁ of the w's ≈ 2 is lost: the θ of the series would not move).
        let dw = s.spread;
        let dv = s.v_hi - s.v_lo;
        let w_mean = s.w_hi - dw * mean_sn2;
        let v_mean = s.v_lo + dv * mean_sn2;
        let amp = dw * 2.0 * PI * PI / (s.k * s.k) * q_over_m;
        let (mut a, mut b_phi, mut b_psi) = (Vec::new(), Vec::new(), Vec::new());
        let mut scale_phi: f64 = 1.0;
        let mut scale_psi: f64 = 1.0;
        for kk in 1..=MAX_TERMS + 1 {
            if kk > MAX_TERMS {
                return None;
            }
            let kf = kk as f64;
            let qk1 = q.powi(kk as i32 - 1);
            let ak = amp * kf * qk1 / (1.0 - q.powi(2 * kk as i32));
            let wk = s
                .w_series
                .map_or(0.0, |(ser, f)| f * ser.coefficient(kk, q));
            let vk = s.v_series.map_or(0.0, |(ser, f, shifted)| {
                let sign = if shifted && kk % 2 == 1 { -1.0 } else { 1.0 };
                sign * f * ser.coefficient(kk, q)
            });
            let bp = (s.half_d * wk + s.half_e * vk) / s.kappa;
            let bs = (-s.half_d * wk + s.half_e * vk) / s.kappa;
            scale_phi = scale_phi.max(bp.abs());
            scale_psi = scale_psi.max(bs.abs());
            a.push(ak);
            b_phi.push(bp);
            b_psi.push(bs);
            if ak.abs() <= TRUNCATION * dw
                && bp.abs() <= TRUNCATION * scale_phi
                && bs.abs() <= TRUNCATION * scale_psi
            {
                break;
            }
        }
        let x0 = PI * s.tau0 / s.k;
        let mut me = Self {
            x0,
            nu: PI * s.kappa / s.k,
            w_mean,
            v_mean,
            a,
            b_phi,
            b_psi,
            phi_base: 0.0,
            psi_base: 0.0,
            phi_rate: s.phi_rate,
            psi_rate: s.psi_rate,
        };
        let (_, _, sp, ss) = me.sums(reduce_angle(x0));
        me.phi_base = s.phi0 - sp;
        me.psi_base = s.psi0 - ss;
        Some(me)
    }

    /// Σ A_k cos kr, (unused), Σ Bφ_k sin kr, Σ Bψ_k sin kr at a reduced phase r.
    #[inline]
    fn sums(&self, r: f64) -> (f64, f64, f64, f64) {
        let (s1, c1) = sin_cos_reduced(r);
        let (mut ck, mut sk) = (c1, s1);
        let (mut sw, mut sp, mut ss) = (0.0, 0.0, 0.0);
        for i in 0..self.a.len() {
            sw += self.a[i] * ck;
            sp += self.b_phi[i] * sk;
            ss += self.b_psi[i] * sk;
            // (cos, sin) of (k + 1) r by one rotation.
            let c_next = ck * c1 - sk * s1;
            sk = sk * c1 + ck * s1;
            ck = c_next;
        }
        (sw, 0.0, sp, ss)
    }

    /// (φ, θ, ψ) at time t.
    #[inline]
    pub(crate) fn angles(&self, t: f64) -> [f64; 3] {
        let x = self.x0 + self.nu * t;
        let (sw, _, sp, ss) = self.sums(reduce_angle(x));
        let w = self.w_mean + sw;
        let v = self.v_mean - sw;
        let theta = theta_from_wv_fast(w.max(0.0), v.max(0.0));
        [
            self.phi_base + self.phi_rate * t + sp,
            theta,
            self.psi_base + self.psi_rate * t + ss,
        ]
    }

    /// [`Fourier::angles`] at many times into `out` (flat, 3 per time): the same arithmetic,
    /// bit for bit, on SIMD lanes (a group of times per vector instruction, the widest the CPU
    /// has: [`crate::simd`]), so that the sum over the terms runs across the lanes.
    pub(crate) fn angles_into(&self, ts: &[f64], out: &mut [f64]) {
        crate::simd::dispatch(AnglesLanes {
            series: self,
            ts,
            out,
        });
    }

    /// Carries the series from a time unit 1/σ to seconds (see `Nutation::rescale_time`).
    pub(crate) fn rescale_time(&mut self, sigma: f64) {
        self.nu *= sigma;
        self.phi_rate *= sigma;
        self.psi_rate *= sigma;
    }

    /// The number of terms used.
    pub(crate) fn terms(&self) -> usize {
        self.a.len()
    }
}

/// [`Fourier::angles`] on lanes, bit for bit: every operation of [`reduce_angle`],
/// [`sin_cos_reduced`] and [`theta_from_wv_fast`] lane by lane (`f64::round` as
/// [`F64s::round_away`], the branches as selections).
struct AnglesLanes<'a> {
    series: &'a Fourier,
    ts: &'a [f64],
    out: &'a mut [f64],
}

impl WithSimd for AnglesLanes<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: Simd>(self, s: S) {
        let lanes = F64s::<S>::LANES;
        let f = self.series;
        let mut t_chunks = self.ts.chunks_exact(lanes);
        let mut o_chunks = self.out.chunks_exact_mut(3 * lanes);
        for (tc, oc) in (&mut t_chunks).zip(&mut o_chunks) {
            let t = F64s::load(s, tc);
            let x = f.x0 + f.nu * t;
            let (s1, c1) = sin_cos_reduced_lanes(reduce_angle_lanes(x));
            let (mut ck, mut sk) = (c1, s1);
            let zero = F64s::splat(s, 0.0);
            let (mut sw, mut sp, mut ss) = (zero, zero, zero);
            for ((&a, &bp), &bs) in f.a.iter().zip(&f.b_phi).zip(&f.b_psi) {
                sw += a * ck;
                sp += bp * sk;
                ss += bs * sk;
                let c_next = ck * c1 - sk * s1;
                sk = sk * c1 + ck * s1;
                ck = c_next;
            }
            let w = f.w_mean + sw;
            let v = f.v_mean - sw;
            let w = F64s::select(w.lt(zero), zero, w);
            let v = F64s::select(v.lt(zero), zero, v);
            let phi = f.phi_base + f.phi_rate * t + sp;
            let theta = theta_from_wv_lanes(w, v);
            let psi = f.psi_base + f.psi_rate * t + ss;
            for i in 0..lanes {
                oc[3 * i] = phi.lanes()[i];
                oc[3 * i + 1] = theta.lanes()[i];
                oc[3 * i + 2] = psi.lanes()[i];
            }
        }
        for (&t, o) in t_chunks
            .remainder()
            .iter()
            .zip(o_chunks.into_remainder().chunks_exact_mut(3))
        {
            o.copy_from_slice(&f.angles(t));
        }
    }
}

/// [`reduce_angle`] on lanes.
#[inline(always)]
fn reduce_angle_lanes<S: Simd>(x: F64s<S>) -> F64s<S> {
    const TWO_PI_HI: f64 = std::f64::consts::TAU;
    const TWO_PI_LO: f64 = 2.449_293_598_294_706_4e-16;
    let j = (x / TWO_PI_HI).round_away();
    let reduced = (x - j * TWO_PI_HI) - j * TWO_PI_LO;
    F64s::select(j.eq(x.splat_like(0.0)), x, reduced)
}

/// [`sin_cos_reduced`] on lanes.
#[inline(always)]
fn sin_cos_reduced_lanes<S: Simd>(r: F64s<S>) -> (F64s<S>, F64s<S>) {
    const PIO2_HI: f64 = std::f64::consts::FRAC_PI_2;
    const PIO2_LO: f64 = 6.123_233_995_736_766e-17;
    let q = (r * std::f64::consts::FRAC_2_PI).round_away();
    let y = (r - q * PIO2_HI) - q * PIO2_LO;
    let (sy, cy) = sin_cos_kernel(y);
    // The quadrant q mod 4 (q ∈ {−2, …, 2}), as `(q as i64) & 3`.
    rotate_by_quadrant(q, sy, cy)
}

/// [`theta_from_wv_fast`] on lanes.
#[inline(always)]
fn theta_from_wv_lanes<S: Simd>(w: F64s<S>, v: F64s<S>) -> F64s<S> {
    use std::f64::consts::{FRAC_PI_4, FRAC_PI_8, PI};
    let (a, b) = (w.sqrt(), v.sqrt());
    let swap = b.lt(a);
    let t = F64s::select(swap, b, a) / F64s::select(swap, a, b);
    const T1: f64 = std::f64::consts::SQRT_2 - 1.0;
    let first = t.le(t.splat_like(THETA_FIRST));
    let second = t.le(t.splat_like(THETA_SECOND));
    let k = F64s::select(
        first,
        t.splat_like(0.0),
        F64s::select(second, t.splat_like(FRAC_PI_8), t.splat_like(FRAC_PI_4)),
    );
    let tk = F64s::select(
        first,
        t.splat_like(0.0),
        F64s::select(second, t.splat_like(T1), t.splat_like(1.0)),
    );
    let x = (t - tk) / (t * tk + 1.0);
    let z = x * x;
    let mut p = t.splat_like(ATAN_TAYLOR[10]);
    for &c in ATAN_TAYLOR[..10].iter().rev() {
        p = p * z + c;
    }
    let half = x * p + k;
    F64s::select(swap, PI - 2.0 * half, 2.0 * half)
}

/// x − 2πj in [−π, π] (2π split in two parts so that the reduction adds one rounding).
#[inline]
fn reduce_angle(x: f64) -> f64 {
    const TWO_PI_HI: f64 = std::f64::consts::TAU;
    const TWO_PI_LO: f64 = 2.449_293_598_294_706_4e-16;
    let j = (x / TWO_PI_HI).round();
    if j == 0.0 {
        return x;
    }
    (x - j * TWO_PI_HI) - j * TWO_PI_LO
}

/// sin and cos of r ∈ [−π, π] (after [`reduce_angle`]) within 2 ulp: quadrant reduction by π/2
/// (in two parts) and the Taylor series of sin and cos on [−π/4, π/4] to x¹⁷ and x¹⁸ (the next
/// terms are below 1e-19). Straight-line code, mirrored lane by lane by
/// [`Fourier::angles_into`] (`sin_cos_reduced_lanes`).
#[inline(always)]
fn sin_cos_reduced(r: f64) -> (f64, f64) {
    const PIO2_HI: f64 = std::f64::consts::FRAC_PI_2;
    const PIO2_LO: f64 = 6.123_233_995_736_766e-17;
    let q = (r * std::f64::consts::FRAC_2_PI).round();
    // (Plain products, not mul_add: the baseline x86-64 target has no FMA instruction and
    // mul_add would call a software fma.) The error of y is a few ulp of r.
    let y = (r - q * PIO2_HI) - q * PIO2_LO;
    let z = y * y;
    // sin y = y (1 − z/3! + z²/5! − …), cos y = 1 − z/2! + z²/4! − … (Horner in z).
    let mut ps = SIN_TAYLOR[8];
    for &c in SIN_TAYLOR[..8].iter().rev() {
        ps = ps * z + c;
    }
    let mut pc = COS_TAYLOR[9];
    for &c in COS_TAYLOR[..9].iter().rev() {
        pc = pc * z + c;
    }
    let (sy, cy) = (y * ps, pc);
    // r = y + qπ/2 with q ∈ {−2, …, 2}: rotate by the quadrant.
    let qi = (q as i64) & 3;
    let (s, c) = if qi & 1 == 1 { (cy, sy) } else { (sy, cy) };
    let s = if qi >= 2 { -s } else { s };
    let c = if qi == 1 || qi == 2 { -c } else { c };
    (s, c)
}

/// Where [`theta_from_wv_fast`] switches from atan t to π/8 + atan(…) (tan(π/16)), and from
/// that to π/4 + atan(…) (tan(3π/16)).
const THETA_FIRST: f64 = 0.198_912_367_379_658;
const THETA_SECOND: f64 = 0.668_178_637_919_298_9;

/// θ = 2 atan(√(w/v)) ∈ [0, π] for w, v ≥ 0 (not both 0), within a few ulp: the ratio t of the
/// smaller to the larger root lies in [0, 1]; `atan t = kπ/8 + atan((t − tan kπ/8)/(1 + t tan kπ/8))`
/// with the nearest k ∈ {0, 1, 2} leaves |x| ≤ tan(π/16), where the Taylor series to x²¹ is
/// exact to 2e-17 relative.
#[inline(always)]
fn theta_from_wv_fast(w: f64, v: f64) -> f64 {
    use std::f64::consts::{FRAC_PI_4, FRAC_PI_8, PI};
    let (a, b) = (w.sqrt(), v.sqrt());
    let swap = a > b;
    let t = if swap { b / a } else { a / b };
    // tan(π/8) = √2 − 1 (the subtraction is exact).
    const T1: f64 = std::f64::consts::SQRT_2 - 1.0;
    let (k, tk) = if t <= THETA_FIRST {
        (0.0, 0.0)
    } else if t <= THETA_SECOND {
        (FRAC_PI_8, T1)
    } else {
        (FRAC_PI_4, 1.0)
    };
    let x = (t - tk) / (t * tk + 1.0);
    let z = x * x;
    let mut p = ATAN_TAYLOR[10];
    for &c in ATAN_TAYLOR[..10].iter().rev() {
        p = p * z + c;
    }
    let half = x * p + k;
    if swap {
        PI - 2.0 * half
    } else {
        2.0 * half
    }
}

#[cfg(test)]
mod tests {
    use super::super::{EulerState, HeavyTop, Motion};
    use super::*;

    /// The series of a few nutating tops (waves, loops, near the upper pole, a fast top, next to
    /// the hanging pole).
    fn series() -> Vec<Fourier> {
        let states = [
            (0.5, 1.0, 0.8, 0.3, 0.6, 6.0),
            (0.5, 2.0, 1.2, -0.7, -1.5, 2.0),
            (1.5, 0.3, 0.05, 0.2, 0.1, 30.0),
            (0.8, 1.0, 2.5, 1.0, 0.4, -9.0),
            // Next to the hanging pole (the amplitude from v = 1 + cos θ: issue 21).
            (0.5, 1.0, PI - 1e-8, 0.0, 0.3, 1.3),
        ];
        let all: Vec<Fourier> = states
            .iter()
            .filter_map(|&(i3, mgl, theta, theta_dot, phi_dot, psi_dot)| {
                let st = EulerState {
                    theta,
                    theta_dot,
                    phi_dot,
                    psi_dot,
                    phi: 0.3,
                    psi: -1.1,
                };
                let top = HeavyTop::new(1.0, i3, mgl, st).unwrap();
                let Motion::Nutating(n) = &top.motion else {
                    panic!("not nutating")
                };
                n.fourier().cloned()
            })
            .collect();
        assert!(all.len() >= 3);
        all
    }

    struct Check<'a>(&'a Fourier, &'a [f64]);
    impl WithSimd for Check<'_> {
        type Output = Vec<f64>;
        #[inline(always)]
        fn with_simd<S: Simd>(self, s: S) -> Vec<f64> {
            let mut out = vec![0.0; 3 * self.1.len()];
            AnglesLanes {
                series: self.0,
                ts: self.1,
                out: &mut out,
            }
            .with_simd(s);
            out
        }
    }

    /// The lanes give `Fourier::angles` bit for bit, with this CPU's instructions and with
    /// scalar code, at times of both signs, large and small, and a count that fills no group.
    #[test]
    fn lanes_equal_the_scalar_path_bit_for_bit() {
        let times: Vec<f64> = (0..1001)
            .map(|k| {
                let x = k as f64 * 0.7548776662466927;
                (x.fract() - 0.5) * 10f64.powi(k % 7 - 2)
            })
            .collect();
        for f in series() {
            let want: Vec<f64> = times.iter().flat_map(|&t| f.angles(t)).collect();
            assert_eq!(crate::simd::dispatch(Check(&f, &times)), want);
            assert_eq!(Check(&f, &times).with_simd(pulp::Scalar), want);
        }
    }

    /// The vectorizable kernels against the standard library: sin and cos to 2 ulp of 1, θ to 4
    /// ulp relative (tiny angles included).
    #[test]
    fn kernels_match_the_standard_library() {
        let ulp = f64::EPSILON;
        let mut worst: f64 = 0.0;
        for k in 0..200_001 {
            let r = -PI + 2.0 * PI * k as f64 / 200_000.0;
            let (s, c) = sin_cos_reduced(r);
            worst = worst.max((s - r.sin()).abs()).max((c - r.cos()).abs());
        }
        assert!(worst < 2.0 * ulp, "sin/cos: {worst:e}");
        let mut worst: f64 = 0.0;
        for k in 1..200_001 {
            let w = 2.0 * k as f64 / 200_000.0;
            let v = 2.0 - w;
            let got = theta_from_wv_fast(w, v);
            let want = 2.0 * w.sqrt().atan2(v.sqrt());
            worst = worst.max((got - want).abs() / want);
        }
        for w in [1e-300, 1e-200, 1e-30, 1e-12] {
            let got = theta_from_wv_fast(w, 2.0 - w);
            let want = 2.0 * w.sqrt().atan2((2.0 - w).sqrt());
            worst = worst.max((got - want).abs() / want);
        }
        assert!(worst < 4.0 * ulp, "theta: {worst:e}");
        assert_eq!(theta_from_wv_fast(0.0, 2.0), 0.0);
        assert_eq!(theta_from_wv_fast(2.0, 0.0), PI);
    }
}
