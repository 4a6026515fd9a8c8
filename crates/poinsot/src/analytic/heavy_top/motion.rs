//! The exact motion of a nutating heavy top: θ(t) by Jacobi's sn, φ(t) and ψ(t) by elliptic
//! integrals of the third kind (Carlson's R_J).
//!
//! With u = cos θ, u̇² = f(u) = β(u − u₁)(u − u₂)(u − u₃), u₁ ≤ u ≤ u₂ ≤ 1 ≤ u₃, the solution is
//! (Goldstein §5.7; Whittaker, *Analytical Dynamics* §71)
//!
//! `u(t) = u₁ + (u₂ − u₁) sn²(τ | m)`, `τ = κ t + τ₀`, `κ = ½√(β(u₃ − u₁))`, `m = (u₂ − u₁)/(u₃ − u₁)`,
//!
//! written without cancellation at the poles as `w = 1 − u = w₂ cn²τ + w₁ sn²τ` and
//! `v = 1 + u = v₁ cn²τ + v₂ sn²τ` (wᵢ, vᵢ the turning points' pole distances, each computed
//! where it is small), and `θ = 2 atan(√(w/v))`. The nutation period is 2K(m)/κ.
//!
//! By partial fractions 2.106 and 2.99 become
//! `φ̇ = (d/2)/w + (e/2)/v` and `ψ̇ = p_ψ/I₃ − p_ψ/I₁ − (d/2)/w + (e/2)/v`, with `d = (p_φ − p_ψ)/I₁`,
//! `e = (p_φ + p_ψ)/I₁`. Both integrals are of the third kind, each measured from the turning
//! point where its denominator is largest, so that the characteristic lies in [m, 1] (or in
//! [−1, 0]) and never cancels:
//!
//! * `∫dτ/w = (1/w₂) Π(n; am τ | m)` with `n = (w₂ − w₁)/w₂` and `1 − n sn² = w/w₂`;
//! * near the lower pole (v₁ < v₂/2), with σ = τ − K: `1/v = dn²σ / (v₂(1 − N sn²σ))`,
//!   `N = m + (1 − m)(v₂ − v₁)/v₂`, so `∫dτ/v = [m σ + (1 − m)((v₂ − v₁)/v₂) Π(N; am σ | m)] / (v₂ N)`;
//!   otherwise `∫dτ/v = (1/v₁) Π(n'; am τ | m)` with `n' = −(v₂ − v₁)/v₁ ∈ [−1, 0]`.
//!
//! `Π(n; am r | m) = r + (n/3) sn³r R_J(cn²r, dn²r, 1, 1 − n sn²r)` for |r| ≤ K (DLMF 19.25.14)
//! with `1 − n sn²` passed in its exact form, and `Π(n; am(r + 2jK)) = Π(n; am r) + 2jΠ(n|m)`,
//! `Π(n|m) = K + (n/3) R_J(0, 1 − m, 1, 1 − n)`. Where the axis passes exactly through a pole
//! (w₁ = 0, so d = 0) the term is absent and φ jumps by π there (ψ by ∓π): the Euler angles
//! keep θ in [0, π].

use super::cubic::{w_v, Reduced, Turning};
use super::fourier::{Fourier, SeriesInput, ThirdSeries};
use super::state::EulerState;
use crate::error::{Error, Result};
use crate::special::carlson::{rf, rj};
use crate::special::{Jacobi, JacobiValues};
use std::f64::consts::PI;

/// `∫₀^r dx/(1 − n sn²x)` for |r| ≤ K, given sn, cn, dn at r and `p = 1 − n sn²r` exactly.
#[inline]
fn third_reduced(r: f64, j: &JacobiValues, n: f64, p: f64) -> f64 {
    if n == 0.0 || j.sn == 0.0 {
        return r;
    }
    r + n / 3.0 * j.sn * j.sn * j.sn * rj(j.cn * j.cn, j.dn * j.dn, 1.0, p)
}

/// One elliptic integral of the third kind with its complete value.
#[derive(Debug, Clone, Copy)]
struct Third {
    /// The characteristic n.
    n: f64,
    /// Π(n | m), the integral over a quarter period.
    complete: f64,
}

impl Third {
    fn new(n: f64, one_minus_n: f64, k: f64, mc: f64) -> Self {
        let complete = if n == 0.0 {
            k
        } else if mc > 0.0 {
            k + n / 3.0 * rj(0.0, mc, 1.0, one_minus_n)
        } else {
            f64::INFINITY
        };
        Self { n, complete }
    }
}

/// How ∫dτ/v is formed (see the module docs).
#[derive(Debug, Clone, Copy)]
enum VForm {
    /// From the lower turning point (τ = 0): (1/v₁) Π(n'; am τ), n' ∈ [−1, 0].
    FromLower { third: Third, ratio: f64 },
    /// From the upper turning point (σ = τ − K): [mσ + c Π(N; am σ)] / (v₂ N).
    FromUpper {
        third: Third,
        coef_lin: f64,
        coef_pi: f64,
        ratio: f64,
    },
}

/// The precomputed exact solution of a nutating top (θ₁ < θ₂).
#[derive(Debug, Clone)]
pub(crate) struct Nutation {
    jac: Jacobi,
    /// K(m).
    k: f64,
    m: f64,
    /// √(1 − m).
    kc: f64,
    /// dτ/dt.
    kappa: f64,
    /// τ at t = 0.
    tau0: f64,
    /// Where the start lies nearer the turning point θ₁ (τ ≡ K) than θ₂: `Some(j₀)`, the phase
    /// then being carried as τ = K(1 + 2j₀) + δ with δ = δ₀ + κt, so that its offset from θ₁ keeps
    /// its digits (τ itself would round it to ε·K: a top kicked from θ₀ = 1e-12 to θ₂ = 1e-6 would
    /// start 1e-9 off θ₀).
    anchor: Option<f64>,
    /// δ₀ (see `anchor`).
    delta0: f64,
    t: Turning,
    /// d/2 and e/2 (1/s): φ̇ = (d/2)/w + (e/2)/v.
    half_d: f64,
    half_e: f64,
    /// p_ψ/I₃ − p_ψ/I₁ (rad/s).
    c_psi: f64,
    /// ∫dτ/w as (1/w₂)Π(n; am τ): `None` when d = 0 (no such term).
    w_third: Option<Third>,
    v_form: Option<VForm>,
    /// π·sgn d where the axis passes through the upper pole (w₁ = 0), else 0.
    jump_w: f64,
    /// π·sgn e where it passes through the lower pole (v₁ = 0), else 0.
    jump_v: f64,
    phi0: f64,
    psi0: f64,
    /// The integrals and jump counts at τ₀, subtracted so that φ(0) = φ₀, ψ(0) = ψ₀.
    at0: Integrals,
    /// The same motion as Fourier series (the fast path), where they converge fast enough.
    fourier: Option<Fourier>,
}

/// One phase τ of the motion, reduced: τ = 2Kj + r with |r| ≤ K, and the Jacobi functions at r
/// to full relative precision, also next to τ ≡ K where r cannot carry its offset from K.
#[derive(Debug, Clone, Copy)]
struct Phase {
    /// τ − K (unreduced).
    sigma: f64,
    j: f64,
    r: f64,
    jv: JacobiValues,
    /// The passages through τ ≡ K (w = 0) and τ ≡ 0 (v = 0), mod 2K, counted up to τ.
    nw: f64,
    nv: f64,
}

/// ∫dτ/w, ∫dτ/v and the pole passages, at one τ.
#[derive(Debug, Clone, Copy, Default)]
struct Integrals {
    iw: f64,
    iv: f64,
    nw: f64,
    nv: f64,
}

/// sn²τ₀ and cn²τ₀ next to a turning point. There the smaller is a difference of nearly equal
/// w's (w₀ − w₁ or w₂ − w₀), known only to ε w/(w₂ − w₁) absolutely, and θ̇₀ ∝ sn cn would
/// come back with the error ε w/(w₂ − w₁)/(sn cn)² relatively; `g` = sn² cn² dn² from θ̇₀
/// itself (no cancellation) gives the smaller one to a few ε relatively: s(1 − s)(1 − m s) = g
/// for sn² = s, c(1 − c)(1 − m + m c) = g for cn² = c (each solved by a few steps of a
/// contraction, the second as the quadratic m c² + (1 − m) c = g/(1 − c)). Away from a turning
/// point (the smaller above 1/4), or where `g` is not a usable number, the w's are kept.
fn near_turning_point(s2: f64, c2: f64, m: f64, mc: f64, g: f64) -> (f64, f64) {
    if !(g.is_finite() && g >= 0.0) || s2.min(c2) > 0.25 {
        return (s2, c2);
    }
    // A value outside [0, 1/2] (θ̇₀ and the cubic's roots not of one motion to round-off)
    // keeps the w's.
    let usable = |x: f64| (0.0..=0.5).contains(&x);
    if s2 <= c2 {
        let mut s = s2;
        for _ in 0..4 {
            s = g / ((1.0 - s) * (1.0 - m * s));
            if !usable(s) {
                return (s2, c2);
            }
        }
        (s, 1.0 - s)
    } else {
        let mut c = c2;
        for _ in 0..4 {
            let h = g / (1.0 - c);
            c = 2.0 * h / (mc + (mc * mc + 4.0 * m * h).sqrt());
            if !usable(c) {
                return (s2, c2);
            }
        }
        (1.0 - c, c)
    }
}

impl Nutation {
    pub(crate) fn new(
        i1: f64,
        i3: f64,
        r: &Reduced,
        t: &Turning,
        start: &EulerState,
        from_state: bool,
        sigma: f64,
    ) -> Result<Self> {
        let (p, pc) = r.p_and_complement(t);
        if p.is_nan() || p <= 0.0 {
            return Err(Error::invalid(
                "theta",
                format!("the cubic of this motion is degenerate (beta (u3 - u1) = {p}); no nutating solution"),
            ));
        }
        // m = β(w₂ − w₁)/P and 1 − m = β(u₃ − u₂)/P, each from its own accurate form, made
        // consistent by taking the larger as the complement of the smaller.
        // (w₂ − w₁ about the nearer pole: `Turning::spread`.)
        let m_raw = r.beta * t.spread() / p;
        let (m, mc) = if m_raw <= 0.5 {
            (m_raw, 1.0 - m_raw)
        } else {
            let mc = (pc / p).clamp(0.0, 0.5);
            (1.0 - mc, mc)
        };
        let jac = Jacobi::with_complement(m, mc)?;
        let k = jac.quarter_period();
        let kappa = 0.5 * p.sqrt();
        // τ₀ from w(τ₀) = w₀: sn²τ₀ = (w₂ − w₀)/(w₂ − w₁), cn²τ₀ = (w₀ − w₁)/(w₂ − w₁).
        let mut anchor_delta: Option<f64> = None;
        let tau0 = if from_state {
            let (w0, v0) = w_v(start.theta);
            let (s2, c2) = if w0 <= 1.0 {
                ((t.w_hi - w0).max(0.0), (w0 - t.w_lo).max(0.0))
            } else {
                ((v0 - t.v_lo).max(0.0), (t.v_hi - v0).max(0.0))
            };
            let tot = s2 + c2;
            let (s2, c2) = if tot > 0.0 {
                (s2 / tot, c2 / tot)
            } else {
                (0.0, 1.0)
            };
            let (s2, c2) = near_turning_point(s2, c2, m, mc, {
                // sn² cn² dn² from θ̇₀ (`rates_at`: θ̇ = −2κ (w₂ − w₁) dn cn sn/√(w v)), θ̇₀ in
                // the time unit 1/σ in which κ is.
                let q = (start.theta_dot / sigma) * (w0 * v0).sqrt() / (2.0 * kappa * t.spread());
                q * q
            });
            // Nearer θ₁ (cn² < sn²): the offset v₀ = K − |τ₀| itself, from sn²v₀ = c²/(1 − m + m c²)
            // (cn(K − v) = k' sd v): v₀ = F(arcsin √x | m) = √x R_F(1 − x, 1 − m x, 1) with
            // 1 − x = (1 − m) s²/D, 1 − m x = (1 − m)/D, D = 1 − m + m c²: no cancellation.
            let near_upper = k.is_finite() && c2 < s2;
            let tau = if c2 == 0.0 {
                k
            } else if near_upper {
                let d = mc + m * c2;
                let v0 = (c2 / d).sqrt() * rf(mc * s2 / d, mc / d, 1.0);
                anchor_delta = Some(v0);
                k - v0
            } else {
                s2.sqrt() * rf(c2, mc + m * c2, 1.0)
            };
            if c2 == 0.0 && k.is_finite() {
                anchor_delta = Some(0.0);
            }
            // On 0 < τ < K, w decreases: θ̇ < 0.
            if start.theta_dot > 0.0 {
                -tau
            } else {
                tau
            }
        } else {
            anchor_delta = k.is_finite().then_some(0.0);
            k
        };
        // τ₀ = ±(K − v₀): anchored at K (j₀ = 0, δ₀ = −v₀) or at −K (j₀ = −1, δ₀ = v₀).
        let (anchor, delta0) = match anchor_delta {
            None => (None, 0.0),
            Some(v0) if tau0 < 0.0 => (Some(-1.0), v0),
            Some(v0) => (Some(0.0), -v0),
        };
        let w_third = (r.d != 0.0 && t.w_lo > 0.0)
            .then(|| Third::new(t.spread() / t.w_hi, t.w_lo / t.w_hi, k, mc));
        let v_form = (r.e != 0.0 && t.v_lo > 0.0).then(|| {
            let dv = t.v_hi - t.v_lo;
            if t.v_lo >= 0.5 * t.v_hi || mc == 0.0 {
                let n = -dv / t.v_lo;
                VForm::FromLower {
                    third: Third::new(n, t.v_hi / t.v_lo, k, mc),
                    ratio: t.v_hi / t.v_lo,
                }
            } else {
                // N = m + (1 − m)(v₂ − v₁)/v₂, 1 − N = (1 − m) v₁/v₂.
                let n = m + mc * dv / t.v_hi;
                let denom = m * t.v_hi + mc * dv;
                VForm::FromUpper {
                    third: Third::new(n, mc * t.v_lo / t.v_hi, k, mc),
                    coef_lin: m / denom,
                    coef_pi: mc * dv / (t.v_hi * denom),
                    ratio: t.v_lo / t.v_hi,
                }
            }
        });
        let sgn = |x: f64| if x < 0.0 { -PI } else { PI };
        let mut me = Self {
            jac,
            k,
            m,
            kc: mc.sqrt(),
            kappa,
            tau0,
            anchor,
            delta0,
            t: *t,
            half_d: 0.5 * r.d,
            half_e: 0.5 * r.e,
            c_psi: r.a * (i1 / i3) - r.a,
            w_third,
            v_form,
            jump_w: if t.w_lo == 0.0 { sgn(r.d) } else { 0.0 },
            jump_v: if t.v_lo == 0.0 { sgn(r.e) } else { 0.0 },
            phi0: start.phi,
            psi0: start.psi,
            at0: Integrals::default(),
            fourier: None,
        };
        me.at0 = me.integrals(&me.phase(0.0));
        me.fourier = me.fourier_series(r, t, p);
        Ok(me)
    }

    /// The Fourier form of this motion (see [`super::fourier`]), if it converges within
    /// its term limit and the axis does not pass through a pole.
    fn fourier_series(&self, r: &Reduced, t: &Turning, p: f64) -> Option<Fourier> {
        if self.jump_w != 0.0 || self.jump_v != 0.0 || !self.k.is_finite() {
            return None;
        }
        let mc = self.kc * self.kc;
        let k_prime = if self.m >= 1e-4 {
            rf(0.0, self.m, 1.0)
        } else {
            f64::INFINITY
        };
        let dw = t.spread();
        let w_series = match self.w_third {
            None => None,
            Some(th) => {
                let n_minus_m = dw * r.beta_u3_minus_one(t) / (t.w_hi * p);
                Some((
                    ThirdSeries::circular(th.n, t.w_lo / t.w_hi, n_minus_m, mc, self.k)?,
                    1.0 / t.w_hi,
                ))
            }
        };
        let dv = t.v_hi - t.v_lo;
        let v_series = match self.v_form {
            None => None,
            // v constant to double precision (a nutation near the upper pole): ∫dτ/v = τ/v₁ is
            // all in the mean rate.
            Some(VForm::FromLower { .. }) if dv == 0.0 => None,
            Some(VForm::FromLower { .. }) => Some((
                ThirdSeries::hyperbolic(dv / t.v_lo, t.v_hi / t.v_lo, self.m, mc, self.k)?,
                1.0 / t.v_lo,
                false,
            )),
            Some(VForm::FromUpper { third, coef_pi, .. }) => Some((
                ThirdSeries::circular(third.n, mc * t.v_lo / t.v_hi, mc * dv / t.v_hi, mc, self.k)?,
                coef_pi,
                true,
            )),
        };
        let (phi_rate, psi_rate) = self.mean_rates();
        Fourier::new(&SeriesInput {
            k: self.k,
            k_prime,
            m: self.m,
            mc,
            kappa: self.kappa,
            tau0: self.tau0,
            w_hi: t.w_hi,
            spread: t.spread(),
            v_lo: t.v_lo,
            v_hi: t.v_hi,
            w_series,
            v_series,
            half_d: self.half_d,
            half_e: self.half_e,
            phi0: self.phi0,
            psi0: self.psi0,
            phi_rate,
            psi_rate,
        })
    }

    /// The Fourier form of the motion, if it has one (for the tests of its lanes).
    #[cfg(test)]
    pub(crate) fn fourier(&self) -> Option<&Fourier> {
        self.fourier.as_ref()
    }

    /// The number of Fourier terms of the fast path (0 when the motion is evaluated by R_J).
    pub(crate) fn fourier_terms(&self) -> usize {
        self.fourier.as_ref().map_or(0, Fourier::terms)
    }

    /// The period of θ, 2K/κ (s); `None` for m = 1 (an asymptotic motion).
    pub(crate) fn period(&self) -> Option<f64> {
        let p = 2.0 * self.k / self.kappa;
        p.is_finite().then_some(p)
    }

    /// Carries the solution, built in a time unit 1/σ, to seconds: every rate times σ (exact for
    /// σ a power of two; the dimensionless constants are unchanged).
    pub(crate) fn rescale_time(&mut self, sigma: f64) {
        self.kappa *= sigma;
        self.half_d *= sigma;
        self.half_e *= sigma;
        self.c_psi *= sigma;
        if let Some(f) = self.fourier.as_mut() {
            f.rescale_time(sigma);
        }
    }

    /// The rate (rad/s) of the motion's phase: the nutation phase πτ/K = 2π t/period, or for
    /// an asymptotic motion (m = 1, no period) τ itself.
    pub(crate) fn phase_rate(&self) -> f64 {
        if self.k.is_finite() {
            PI * self.kappa / self.k
        } else {
            self.kappa
        }
    }

    /// ⟨φ̇⟩ and ⟨ψ̇⟩ over a period (rad/s).
    pub(crate) fn mean_rates(&self) -> (f64, f64) {
        if !self.k.is_finite() {
            // Asymptotic motion: the rates at the end of time (the pole it approaches).
            let rates = self.rates_at(&self.phase_of_tau(1e300_f64.min(f64::MAX)));
            return (rates[0], rates[2]);
        }
        let two_k = 2.0 * self.k;
        // Increments of ∫dτ/w, ∫dτ/v over one period 2K in τ, and one passage per pole.
        let iw = self
            .w_third
            .map_or(0.0, |th| 2.0 * th.complete / self.t.w_hi);
        let iv = match self.v_form {
            None => 0.0,
            Some(VForm::FromLower { third, .. }) => 2.0 * third.complete / self.t.v_lo,
            Some(VForm::FromUpper {
                third,
                coef_lin,
                coef_pi,
                ..
            }) => coef_lin * two_k + coef_pi * 2.0 * third.complete,
        };
        let period = two_k / self.kappa;
        let dphi = (self.half_d * iw + self.half_e * iv) / self.kappa + self.jump_w + self.jump_v;
        let dpsi = (-self.half_d * iw + self.half_e * iv) / self.kappa - self.jump_w + self.jump_v;
        (dphi / period, self.c_psi + dpsi / period)
    }

    /// The phase at time t (s).
    fn phase(&self, time: f64) -> Phase {
        let Some(j0) = self.anchor else {
            return self.phase_of_tau(self.tau0 + self.kappa * time);
        };
        // τ = K(1 + 2j₀) + δ, δ = 2K j_δ + x with |x| ≤ K: the functions at K + x from those at x
        // (DLMF 22.4.3: sn(x ± K) = ±cd x, cn(x ± K) = ∓k' sd x, dn(x ± K) = k' nd x).
        let delta = self.delta0 + self.kappa * time;
        let (jd, x) = self.jac.reduce(delta);
        let v = self.jac.eval_reduced(x);
        let q = 1.0 / v.dn;
        let (j, r, sign) = if x <= 0.0 {
            (jd + j0, self.k + x, 1.0)
        } else {
            (jd + j0 + 1.0, x - self.k, -1.0)
        };
        let jv = JacobiValues {
            sn: sign * v.cn * q,
            cn: -sign * self.kc * v.sn * q,
            dn: self.kc * q,
            am: 0.0,
        };
        Phase {
            sigma: 2.0 * j0 * self.k + delta,
            j,
            r,
            jv,
            // Past τ ≡ K once x ≥ 0 (r = K + x would round x away).
            nw: jd + j0 - 1.0 + if x >= 0.0 { 1.0 } else { 0.0 },
            nv: j - 1.0 + if r >= 0.0 { 1.0 } else { 0.0 },
        }
    }

    /// The phase at τ given directly (no anchor).
    fn phase_of_tau(&self, tau: f64) -> Phase {
        let (j, r) = self.jac.reduce(tau);
        Phase {
            sigma: tau - self.k,
            j,
            r,
            jv: self.jac.eval_reduced(r),
            nw: j - 1.0 + if r >= self.k { 1.0 } else { 0.0 },
            nv: j - 1.0 + if r >= 0.0 { 1.0 } else { 0.0 },
        }
    }

    /// The integrals ∫dτ/w, ∫dτ/v and the pole-passage counts at a phase.
    fn integrals(&self, ph: &Phase) -> Integrals {
        let Phase { j, r, jv, .. } = *ph;
        let (s2, c2) = (jv.sn * jv.sn, jv.cn * jv.cn);
        let mut out = Integrals::default();
        if let Some(th) = self.w_third {
            // 1 − n sn² = w/w₂ = cn² + (w₁/w₂) sn².
            let one_minus_n = self.t.w_lo / self.t.w_hi;
            let p = c2 + one_minus_n * s2;
            out.iw = if self.k.is_finite() {
                (2.0 * j * th.complete + third_reduced(r, &jv, th.n, p)) / self.t.w_hi
            } else {
                // m = 1, 0 ≤ n < 1: ∫₀^τ dx/(1 − n tanh²x) = (τ − √n atanh(√n tanh τ))/(1 − n),
                // atanh x = ½ ln((1 + x)²/(1 − x²)) with 1 − n tanh² = (1 − n) + n sech² exact.
                let sq = th.n.sqrt();
                let at = 0.5 * ((1.0 + sq * jv.sn).powi(2) / (one_minus_n + th.n * c2)).ln();
                (r - sq * at) / (one_minus_n * self.t.w_hi)
            };
        }
        match self.v_form {
            None => {}
            Some(VForm::FromLower { third, .. }) if !self.k.is_finite() => {
                // m = 1 (the asymptotic motion towards the upright pole): sn = tanh, and with
                // n' = −k², ∫₀^τ dx/(1 + k² tanh²x) = (τ + k atan(k tanh τ))/(1 + k²), which stays
                // finite where cn² = sech²τ underflows and R_J would see two zero arguments.
                let kk = (-third.n).sqrt();
                out.iv = (r + kk * (kk * jv.sn).atan()) / ((1.0 - third.n) * self.t.v_lo);
            }
            Some(VForm::FromLower { third, ratio }) => {
                // 1 − n' sn² = v/v₁ = cn² + (v₂/v₁) sn².
                let p = c2 + ratio * s2;
                out.iv =
                    (2.0 * j * third.complete + third_reduced(r, &jv, third.n, p)) / self.t.v_lo;
            }
            Some(VForm::FromUpper {
                third,
                coef_lin,
                coef_pi,
                ratio,
            }) => {
                // σ = τ − K reduced to [−K, K] with the quarter-period shifts of sn, cn, dn.
                let (js, rs, sv) = if r >= 0.0 {
                    (
                        j,
                        r - self.k,
                        JacobiValues {
                            sn: -jv.cn / jv.dn,
                            cn: self.kc * jv.sn / jv.dn,
                            dn: self.kc / jv.dn,
                            am: 0.0,
                        },
                    )
                } else {
                    (
                        j - 1.0,
                        r + self.k,
                        JacobiValues {
                            sn: jv.cn / jv.dn,
                            cn: -self.kc * jv.sn / jv.dn,
                            dn: self.kc / jv.dn,
                            am: 0.0,
                        },
                    )
                };
                // 1 − N sn²σ = (1 − m)(sn²r + (v₁/v₂) cn²r)/dn²r, with 1 − m = kc² (1.0 − m
                // would be 0 where m rounds to 1: a top falling from near upright).
                let p = self.kc * self.kc * (s2 + ratio * c2) / (jv.dn * jv.dn);
                out.iv = coef_lin * ph.sigma
                    + coef_pi * (2.0 * js * third.complete + third_reduced(rs, &sv, third.n, p));
            }
        }
        // Passages through w = 0 at τ ≡ K and through v = 0 at τ ≡ 0 (mod 2K), counted up to τ.
        if self.jump_w != 0.0 {
            out.nw = ph.nw;
        }
        if self.jump_v != 0.0 {
            out.nv = ph.nv;
        }
        out
    }

    /// θ from the Jacobi values at τ.
    #[inline]
    fn w_v(&self, jv: &JacobiValues) -> (f64, f64) {
        let (s2, c2) = (jv.sn * jv.sn, jv.cn * jv.cn);
        (
            self.t.w_hi * c2 + self.t.w_lo * s2,
            self.t.v_lo * c2 + self.t.v_hi * s2,
        )
    }

    /// (φ, θ, ψ) at time t: by the Fourier series where they exist, else by R_J.
    #[inline]
    pub(crate) fn angles(&self, time: f64) -> [f64; 3] {
        match &self.fourier {
            Some(f) => f.angles(time),
            None => self.angles_carlson(time),
        }
    }

    /// [`Nutation::angles`] at many times into `out` (flat, 3 per time).
    pub(crate) fn angles_into(&self, ts: &[f64], out: &mut [f64]) {
        match &self.fourier {
            Some(f) => f.angles_into(ts, out),
            None => {
                for (&t, o) in ts.iter().zip(out.chunks_exact_mut(3)) {
                    o.copy_from_slice(&self.angles_carlson(t));
                }
            }
        }
    }

    /// (φ, θ, ψ) at time t by the incomplete integrals (Jacobi's sn and Carlson's R_J).
    pub(crate) fn angles_carlson(&self, time: f64) -> [f64; 3] {
        let ph = self.phase(time);
        let (jv, i) = (ph.jv, self.integrals(&ph));
        let (w, v) = self.w_v(&jv);
        let dw = (i.iw - self.at0.iw) / self.kappa;
        let dv = (i.iv - self.at0.iv) / self.kappa;
        let jw = self.jump_w * (i.nw - self.at0.nw);
        let jvv = self.jump_v * (i.nv - self.at0.nv);
        let phi = self.phi0 + self.half_d * dw + self.half_e * dv + jw + jvv;
        let psi = self.psi0 + self.c_psi * time - self.half_d * dw + self.half_e * dv - jw + jvv;
        [phi, self.theta(&jv, w, v), psi]
    }

    /// θ = 2 atan(√w/√v). Through a pole (w₁ = 0, resp. v₁ = 0) √w = √w₂ |cn| (resp.
    /// √v = √v₂ |sn|), not the root of w₂ cn², which underflows ~1e-154 from the pole: a top
    /// rising to the upright along the separatrix keeps θ to full relative precision as it
    /// approaches it (θ ~ 1e-287 rad after 1000 s).
    #[inline]
    fn theta(&self, jv: &JacobiValues, w: f64, v: f64) -> f64 {
        let rw = if self.t.w_lo == 0.0 {
            self.t.w_hi.sqrt() * jv.cn.abs()
        } else {
            w.max(0.0).sqrt()
        };
        let rv = if self.t.v_lo == 0.0 {
            self.t.v_hi.sqrt() * jv.sn.abs()
        } else {
            v.max(0.0).sqrt()
        };
        2.0 * rw.atan2(rv)
    }

    /// (φ̇, θ̇, ψ̇) at time t.
    pub(crate) fn rates(&self, time: f64) -> [f64; 3] {
        self.rates_at(&self.phase(time))
    }

    fn rates_at(&self, ph: &Phase) -> [f64; 3] {
        let jv = ph.jv;
        let (w, v) = self.w_v(&jv);
        let fw = if self.half_d != 0.0 && w > 0.0 {
            self.half_d / w
        } else {
            0.0
        };
        let fv = if self.half_e != 0.0 && v > 0.0 {
            self.half_e / v
        } else {
            0.0
        };
        // θ̇ = ẇ/sin θ, ẇ = 2κ(w₁ − w₂) sn cn dn, sin θ = √(w v); at a pole passage the ratios
        // cn/√w, sn/√v are taken in their limits. (w₂ − w₁ about the nearer pole: near the
        // hanging pole the w's both round to ~2.)
        let a = if self.t.w_lo == 0.0 {
            jv.cn.signum() / self.t.w_hi.sqrt()
        } else {
            jv.cn / w.sqrt()
        };
        let b = if self.t.v_lo == 0.0 {
            jv.sn.signum() / self.t.v_hi.sqrt()
        } else {
            jv.sn / v.sqrt()
        };
        let theta_dot = -2.0 * self.kappa * self.t.spread() * jv.dn * a * b;
        [fw + fv, theta_dot, self.c_psi - fw + fv]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::special::integrals::pi_complete_split;

    /// Π(n | m) of the nutation's third-kind integrals next to the separatrix (1 − m down to
    /// 1e-300: R_J(0, 1 − m, 1, 1 − n) has two arguments hundreds of decades below the others)
    /// against Legendre's Π of `special` (there by the asymptotic form for n in (0, 1), by the
    /// positive-term form for n < 0): the one R_J of `special::carlson` at its widest spread.
    #[test]
    fn complete_third_kind_integrals_next_to_the_separatrix() {
        for &mc in &[1e-30, 1e-100, 1e-300] {
            let m = 1.0 - mc;
            let k = Jacobi::with_complement(m, mc).unwrap().quarter_period();
            for &n in &[0.3, -2.0] {
                let got = Third::new(n, 1.0 - n, k, mc).complete;
                let want = pi_complete_split(n, m, mc).unwrap();
                assert!(
                    (got / want - 1.0).abs() < 1e-14,
                    "m₁ = {mc:e}, n = {n}: {got} against {want}"
                );
            }
        }
    }
}
