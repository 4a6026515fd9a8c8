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

use crate::special::ellip_carlson::{rd, rf};
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
    pub w_lo: f64,
    pub w_hi: f64,
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
        let dw = s.w_hi - s.w_lo;
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
    /// eight times at once so that the sum over the terms runs across the lanes (and
    /// vectorizes).
    pub(crate) fn angles_into(&self, ts: &[f64], out: &mut [f64]) {
        const L: usize = 8;
        let mut t_chunks = ts.chunks_exact(L);
        let mut o_chunks = out.chunks_exact_mut(3 * L);
        for (tc, oc) in (&mut t_chunks).zip(&mut o_chunks) {
            let (mut c1, mut s1) = ([0.0; L], [0.0; L]);
            for i in 0..L {
                (s1[i], c1[i]) = sin_cos_reduced(reduce_angle(self.x0 + self.nu * tc[i]));
            }
            let (mut ck, mut sk) = (c1, s1);
            let (mut sw, mut sp, mut ss) = ([0.0; L], [0.0; L], [0.0; L]);
            for k in 0..self.a.len() {
                let (a, bp, bs) = (self.a[k], self.b_phi[k], self.b_psi[k]);
                for i in 0..L {
                    sw[i] += a * ck[i];
                    sp[i] += bp * sk[i];
                    ss[i] += bs * sk[i];
                    let c_next = ck[i] * c1[i] - sk[i] * s1[i];
                    sk[i] = sk[i] * c1[i] + ck[i] * s1[i];
                    ck[i] = c_next;
                }
            }
            for i in 0..L {
                let w = (self.w_mean + sw[i]).max(0.0);
                let v = (self.v_mean - sw[i]).max(0.0);
                oc[3 * i] = self.phi_base + self.phi_rate * tc[i] + sp[i];
                oc[3 * i + 1] = theta_from_wv_fast(w, v);
                oc[3 * i + 2] = self.psi_base + self.psi_rate * tc[i] + ss[i];
            }
        }
        for (&t, o) in t_chunks
            .remainder()
            .iter()
            .zip(o_chunks.into_remainder().chunks_exact_mut(3))
        {
            o.copy_from_slice(&self.angles(t));
        }
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
/// terms are below 1e-19). Straight-line code, so that the eight lanes of
/// [`Fourier::angles_into`] vectorize.
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
    const S: [f64; 9] = [
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
    const C: [f64; 10] = [
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
    let mut ps = S[8];
    for &c in S[..8].iter().rev() {
        ps = ps * z + c;
    }
    let mut pc = C[9];
    for &c in C[..9].iter().rev() {
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
    let (k, tk) = if t <= 0.198_912_367_379_658 {
        (0.0, 0.0)
    } else if t <= 0.668_178_637_919_298_9 {
        (FRAC_PI_8, T1)
    } else {
        (FRAC_PI_4, 1.0)
    };
    let x = (t - tk) / (t * tk + 1.0);
    let z = x * x;
    const A: [f64; 11] = [
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
    let mut p = A[10];
    for &c in A[..10].iter().rev() {
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
    use super::*;

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
