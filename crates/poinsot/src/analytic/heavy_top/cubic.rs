//! The cubic of the heavy top and its turning points, computed without cancellation.
//!
//! With u = cos θ, the energy integral (the unit's 2.109 with 2.110) reads
//! `u̇² = f(u) = (1 − u²)(α − βu) − (b − au)²` (Goldstein §5.7, eq. 5.62), where, per unit of
//! I₁, `a = p_ψ/I₁`, `b = p_φ/I₁`, `α = 2E'/I₁`, `β = 2mgl/I₁`. The turning points θ₁ ≤ θ₂ are
//! the roots u₂ ≥ u₁ of f in [−1, 1]; the third root u₃ ≥ 1.
//!
//! Near the poles u = ±1 the naive form loses every digit of 1 ∓ u. So the cubic is kept in
//! three variables, each exact where it is small:
//!
//! * about the upper pole, `w = 1 − u = 2 sin²(θ/2)`:
//!   `f = w(2 − w)(γ + βw) − (d + aw)²` with `d = b − a = (p_φ − p_ψ)/I₁`, `γ = α − β`;
//! * about the lower pole, `v = 1 + u = 2 cos²(θ/2)`:
//!   `f = v(2 − v)(δ − βv) − (e − av)²` with `e = b + a`, `δ = α + β`;
//! * about the initial angle θ₀, `s = w − w₀`: `f = F₀ + F₁s + F₂s² − βs³`, with
//!   `F₀ = sin²θ₀ θ̇₀²` exactly, so that a top released at a turning point (θ̇₀ = 0) has that
//!   turning point exactly and a small nutation keeps its relative accuracy.
//!
//! `d`, `e`, `γ`, `δ` and the `F`'s are formed from the initial state directly
//! (e.g. `d = φ̇₀ sin²θ₀ − a w₀`), never by subtracting nearly equal momenta.

/// The reduced constants of the motion, per unit of I₁ (units 1/s and 1/s²).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Reduced {
    /// a = p_ψ / I₁.
    pub a: f64,
    /// b = p_φ / I₁.
    pub b: f64,
    /// d = b − a = (p_φ − p_ψ)/I₁.
    pub d: f64,
    /// e = b + a = (p_φ + p_ψ)/I₁.
    pub e: f64,
    /// β = 2 m g l / I₁.
    pub beta: f64,
    /// γ = α − β = 2(E' − mgl)/I₁.
    pub gamma: f64,
    /// δ = α + β = 2(E' + mgl)/I₁.
    pub delta: f64,
}

/// The Taylor coefficients of f about the initial angle, in s = w − w₀ (f = F₀ + F₁s + F₂s² − βs³).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Local {
    /// w₀ = 1 − cos θ₀.
    pub w0: f64,
    /// v₀ = 1 + cos θ₀.
    pub v0: f64,
    /// F₀ = f(w₀) = sin²θ₀ θ̇₀² ≥ 0.
    pub f0: f64,
    /// F₁ = df/dw at w₀.
    pub f1: f64,
    /// F₂ = ½ d²f/dw² at w₀.
    pub f2: f64,
}

/// The turning points in the two pole variables: `w_lo = 1 − u₂` (θ₁, the upper turning point),
/// `w_hi = 1 − u₁` (θ₂), `v_lo = 1 + u₁ = 2 − w_hi`, `v_hi = 1 + u₂ = 2 − w_lo`. Both variables
/// of each turning point are kept, each formed without cancellation (as an offset from the start
/// w₀ + s, v₀ − s, or in the variable where it is small with the other as its complement ≥ 1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Turning {
    /// 1 − cos θ₁.
    pub w_lo: f64,
    /// 1 − cos θ₂.
    pub w_hi: f64,
    /// 1 + cos θ₂.
    pub v_lo: f64,
    /// 1 + cos θ₁.
    pub v_hi: f64,
}

impl Turning {
    /// Both turning points at one angle given by its two pole variables.
    pub fn coincident(w: f64, v: f64) -> Self {
        Self {
            w_lo: w,
            w_hi: w,
            v_lo: v,
            v_hi: v,
        }
    }
    /// From both pole distances of each turning point: upper (w_lo, v_hi), lower (w_hi, v_lo).
    pub fn new(upper: (f64, f64), lower: (f64, f64)) -> Self {
        Self {
            w_lo: upper.0,
            v_hi: upper.1,
            w_hi: lower.0,
            v_lo: lower.1,
        }
    }
    /// Whether the motion lies nearer the lower (hanging) pole than the upper: w₁ + w₂ > 2, i.e.
    /// v₁ + v₂ < 2. There the v's are the small, exact pole distances and the w's ≈ 2 have lost
    /// theirs (1 − cos θ rounds to 2 within ~1.5e-8 rad of θ = π).
    pub fn nearer_lower_pole(&self) -> bool {
        self.w_lo + self.w_hi > 2.0
    }
    /// The nutation's extent w₂ − w₁ = v₂ − v₁ = u₂ − u₁ (≥ 0), as the difference of the pole
    /// distances about the nearer pole, each exact where small: w₂ − w₁ near the upright (as
    /// before), v₂ − v₁ near the hanging pole, where w₂ − w₁ would be a difference of two numbers
    /// that both round to ~2 (0 for a nutation between π − 1e-8 and π − 7.6e-9). Zero for steady
    /// motion.
    pub fn spread(&self) -> f64 {
        if self.nearer_lower_pole() {
            self.v_hi - self.v_lo
        } else {
            self.w_hi - self.w_lo
        }
    }
    /// θ₁ (upper) and θ₂ (lower), in [0, π].
    pub fn thetas(&self) -> (f64, f64) {
        (
            theta_from_wv(self.w_lo, self.v_hi),
            theta_from_wv(self.w_hi, self.v_lo),
        )
    }
    /// The distances π − θ₁ ≥ π − θ₂ from the hanging pole, to full relative precision however
    /// small (from v = 1 + cos θ: `tan((π − θ)/2) = √(v/w)`); π − θ of the double θ would round
    /// them to an ulp of π (4.4e-16).
    pub fn hanging_distances(&self) -> (f64, f64) {
        (
            theta_from_wv(self.v_hi, self.w_lo),
            theta_from_wv(self.v_lo, self.w_hi),
        )
    }
}

/// w = 1 − cos θ and v = 1 + cos θ without cancellation: `2 sin²(θ/2)`, `2 cos²(θ/2)`. θ = π
/// (the double nearest π, the bottom as the API spells it) is the hanging pole itself, v = 0, as
/// θ = 0 is the upright one (else v = 7.5e-33: a top "at π" would nutate 1.2e-16 rad from it).
pub(crate) fn w_v(theta: f64) -> (f64, f64) {
    if theta == std::f64::consts::PI {
        return (2.0, 0.0);
    }
    let (sh, ch) = (0.5 * theta).sin_cos();
    (2.0 * sh * sh, 2.0 * ch * ch)
}

/// sin θ and cos θ, with θ = π the hanging pole itself (sin θ = 0, as [`w_v`] has v = 0 there).
pub(crate) fn sin_cos(theta: f64) -> (f64, f64) {
    if theta == std::f64::consts::PI {
        return (0.0, -1.0);
    }
    theta.sin_cos()
}

/// θ from w = 1 − cos θ and v = 1 + cos θ: `tan(θ/2) = √(w/v)`, accurate at both poles.
pub(crate) fn theta_from_wv(w: f64, v: f64) -> f64 {
    2.0 * w.max(0.0).sqrt().atan2(v.max(0.0).sqrt())
}

impl Reduced {
    /// f and df/dw at w (the upper-pole variable).
    pub fn f_w(&self, w: f64) -> (f64, f64) {
        let Self {
            a, d, beta, gamma, ..
        } = *self;
        let g = gamma + beta * w;
        let r = d + a * w;
        let q = w * (2.0 - w);
        (q * g - r * r, 2.0 * (1.0 - w) * g + beta * q - 2.0 * a * r)
    }

    /// f and df/dv at v (the lower-pole variable).
    pub fn f_v(&self, v: f64) -> (f64, f64) {
        let Self {
            a, e, beta, delta, ..
        } = *self;
        let g = delta - beta * v;
        let r = e - a * v;
        let q = v * (2.0 - v);
        (q * g - r * r, 2.0 * (1.0 - v) * g - beta * q + 2.0 * a * r)
    }

    /// The coefficients of f(w) = −βw³ + C₂w² + C₁w + C₀: (C₂, C₁, C₀).
    pub fn w_coefficients(&self) -> (f64, f64, f64) {
        let Self {
            a, d, beta, gamma, ..
        } = *self;
        (
            2.0 * beta - gamma - a * a,
            2.0 * gamma - 2.0 * a * d,
            -d * d,
        )
    }

    /// The scale of the terms of f at w: the round-off of an evaluation is a few ε times this.
    pub fn f_scale(&self, w: f64) -> f64 {
        let Self {
            a, d, beta, gamma, ..
        } = *self;
        let q = w * (2.0 - w);
        q * (gamma.abs() + beta * w.abs()) + (d.abs() + (a * w).abs()).powi(2)
    }

    /// P = β(u₃ − u₁), the factor with f(u) = (u − u₁)(u₂ − u)(P − β(u − u₁)), and the
    /// complementary parameter's numerator `β(u₃ − u₂)`.
    ///
    /// Near the upper pole with the turning points well apart (w₁ ≤ w₂/2: a top falling from near
    /// upright, or nutating far below it) both are sums of non-negative terms,
    /// `P = βw₂ + β(u₃ − 1)` and `β(u₃ − u₂) = βw₁ + β(u₃ − 1)`, with β(u₃ − 1) from the product
    /// of the roots ([`Reduced::beta_u3_minus_one`]): nothing cancels, so a top released at
    /// θ₀ = 1e-12 keeps m's complement 1 − m ≈ θ₀²/4 to full relative precision. Otherwise from
    /// the sum of the roots (Vieta), written about the pole the motion is nearer to.
    pub fn p_and_complement(&self, t: &Turning) -> (f64, f64) {
        if let Some(nbw3) = self.beta_u3_minus_one_by_product(t) {
            return (self.beta * t.w_hi + nbw3, self.beta * t.w_lo + nbw3);
        }
        let Self {
            a,
            beta,
            gamma,
            delta,
            ..
        } = *self;
        // β w₃ = C₂ − β(w_lo + w_hi); P = β(w_hi − w₃), β(u₃ − u₂) = β(w_lo − w₃). Written about
        // the pole the motion is nearer to, so that the small pole distances keep their digits.
        if t.w_lo + t.w_hi <= 2.0 {
            let base = gamma + a * a - 2.0 * beta;
            (
                base + beta * (2.0 * t.w_hi + t.w_lo),
                base + beta * (2.0 * t.w_lo + t.w_hi),
            )
        } else {
            // γ = δ − 2β and w = 2 − v: P = δ + a² + β(w_lo − 2 v_lo) with w_lo = 2 − v_hi.
            let base = delta + a * a;
            (
                base + beta * (t.w_lo - 2.0 * t.v_lo),
                base + beta * (t.w_hi - 2.0 * t.v_hi),
            )
        }
    }

    /// β(u₃ − 1) = −β w₃ ≥ 0 (zero at the sleeping-top threshold and for a top without spin or
    /// p_φ), where the roots are well apart: from their product, `β w₃ w₁ w₂ = −d²`, i.e.
    /// `β(u₃ − 1) = (d/w₁)(d/w₂)`, or, where the axis passes through the upper pole (w₁ = 0,
    /// d = 0), from the quadratic left by f/w, `β w₃ w₂ = −2γ`. Both keep full relative precision
    /// however small w₁ is; the sum of the roots would leave an absolute error of ε·(a² + 2β).
    /// `None` where the roots are not well apart (w₁ > w₂/2, where their sum is accurate).
    fn beta_u3_minus_one_by_product(&self, t: &Turning) -> Option<f64> {
        if !(t.w_hi > 0.0 && t.w_lo <= 0.5 * t.w_hi) {
            return None;
        }
        Some(if t.w_lo == 0.0 {
            (2.0 * self.gamma / t.w_hi).max(0.0)
        } else {
            (self.d / t.w_lo) * (self.d / t.w_hi)
        })
    }
}

impl Reduced {
    /// β(u₃ − 1) = −β w₃ ≥ 0 (zero at the sleeping-top threshold), from the product of the roots
    /// where they are well apart (see [`Reduced::p_and_complement`]), else from their sum.
    pub fn beta_u3_minus_one(&self, t: &Turning) -> f64 {
        if let Some(nbw3) = self.beta_u3_minus_one_by_product(t) {
            return nbw3;
        }
        let Self {
            a,
            beta,
            gamma,
            delta,
            ..
        } = *self;
        if t.w_lo + t.w_hi <= 2.0 {
            gamma + a * a - 2.0 * beta + beta * (t.w_lo + t.w_hi)
        } else {
            delta + a * a - beta * (t.v_lo + t.v_hi)
        }
    }
}

impl Local {
    /// f and df/ds at s = w − w₀.
    pub fn f_s(&self, beta: f64, s: f64) -> (f64, f64) {
        let Self { f0, f1, f2, .. } = *self;
        (
            f0 + s * (f1 + s * (f2 - beta * s)),
            f1 + s * (2.0 * f2 - 3.0 * beta * s),
        )
    }
}

/// The iteration limit of [`bracketed_root`]: enough for plain bisection over the whole double
/// range. A bracket of width 2 closing on a root of 1e-120 (a turning point near the upright
/// pole) takes ~400 halvings where Newton's steps leave the bracket, and 1100 reach the smallest
/// subnormal; a limit of 400 stopped such roots short, 1e-10 off at θ ≈ 1e-54 and 10 % off at
/// θ ≈ 1e-60. Typical roots take under 50.
const ROOT_ITERATIONS: usize = 2200;

/// A root of `g` between `neg` (where g ≤ 0) and `pos` (where g ≥ 0), in either order, by
/// Newton's method safeguarded by bisection. The signs at the ends are taken as given (they
/// are known from the physics even where round-off would blur them). Returns a point of the
/// bracket within a few ulp of the root.
pub(crate) fn bracketed_root(g: impl Fn(f64) -> (f64, f64), mut neg: f64, mut pos: f64) -> f64 {
    if neg == pos {
        return neg;
    }
    let mut x = 0.5 * (neg + pos);
    for _ in 0..ROOT_ITERATIONS {
        let (f, df) = g(x);
        if f == 0.0 {
            return x;
        }
        if f < 0.0 {
            neg = x;
        } else {
            pos = x;
        }
        let (lo, hi) = if neg < pos { (neg, pos) } else { (pos, neg) };
        if hi - lo <= 2.0 * f64::EPSILON * lo.abs().max(hi.abs()) || hi - lo <= f64::MIN_POSITIVE {
            return x;
        }
        let newton = x - f / df;
        let next = if df != 0.0 && newton.is_finite() && newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if next == x {
            return x;
        }
        // A Newton step that barely moves is the end (the root is found to round-off) unless
        // the bracket is still wide, where a stalled Newton step means a flat f: bisect then.
        if (next - x).abs() <= 2.0 * f64::EPSILON * x.abs() {
            return next;
        }
        x = next;
    }
    x
}

/// The roots of `c0 + c1 s + c2 s²` (real, possibly none): the stable quadratic formula.
pub(crate) fn quadratic_roots(c2: f64, c1: f64, c0: f64) -> Vec<f64> {
    if c2 == 0.0 {
        if c1 == 0.0 {
            return vec![];
        }
        return vec![-c0 / c1];
    }
    let disc = c1 * c1 - 4.0 * c2 * c0;
    if disc < 0.0 {
        return vec![];
    }
    let q = -0.5 * (c1 + c1.signum() * disc.sqrt());
    if q == 0.0 {
        return vec![0.0, 0.0];
    }
    vec![q / c2, c0 / q]
}

/// The turning points of a top whose initial state is known (`local` about w₀).
pub(crate) fn turning_points_from_state(r: &Reduced, l: &Local) -> Turning {
    let beta = r.beta;
    let fs = |s: f64| l.f_s(beta, s);
    // Both at w₀ (steady motion, or resting at a pole).
    if l.f0 == 0.0 && l.f1 == 0.0 {
        return Turning::coincident(l.w0, l.v0);
    }
    // The other root of f(w₀ + s) = s (F₁ + F₂ s − β s²) when w₀ itself is a root (θ̇₀ = 0):
    // the root of the quadratic nearest 0 on the side where f > 0 (the sign of F₁).
    let other_root_at_rest = || -> f64 {
        let side = l.f1.signum();
        let limit = if side > 0.0 { l.v0 } else { l.w0 };
        quadratic_roots(-beta, l.f2, l.f1)
            .into_iter()
            .filter(|s| s * side > 0.0)
            .fold(
                limit * side,
                |best, s| if s.abs() < best.abs() { s } else { best },
            )
    };
    // Upper turning point: w_lo ∈ [0, w₀] (f(0) = −d² ≤ 0), as (w, v) each without cancellation:
    // w₀ + s and v₀ − s with s ≤ 0, or from the top pole's own variable when nearer to it.
    let upper = if l.w0 == 0.0 {
        (0.0, l.v0)
    } else if l.f0 == 0.0 && l.f1 > 0.0 {
        (l.w0, l.v0)
    } else {
        let s = if l.f0 == 0.0 {
            other_root_at_rest()
        } else {
            bracketed_root(fs, -l.w0, 0.0)
        };
        let w = l.w0 + s;
        if w.max(0.0) < -s {
            let w = polish_near_pole(|w| r.f_w(w), w, -s, r.d, l.w0);
            (w, 2.0 - w)
        } else {
            (w, l.v0 - s)
        }
    };
    // Lower turning point: v_lo ∈ [0, v₀] (f at v = 0 is −e² ≤ 0): w₀ + s and v₀ − s with s ≥ 0.
    let lower = if l.v0 == 0.0 {
        (l.w0, 0.0)
    } else if l.f0 == 0.0 && l.f1 < 0.0 {
        (l.w0, l.v0)
    } else {
        let s = if l.f0 == 0.0 {
            other_root_at_rest()
        } else {
            bracketed_root(fs, l.v0, 0.0)
        };
        let v = l.v0 - s;
        if v.max(0.0) < s {
            let v = polish_near_pole(|v| r.f_v(v), v, s, r.e, l.v0);
            (2.0 - v, v)
        } else {
            (l.w0 + s, v)
        }
    };
    Turning::new(upper, lower)
}

/// Re-solves a root at pole distance `p` (first found at distance `dist` from the start, whose
/// pole distance is `p0`) in the pole's own variable when it lies nearer to the pole than to
/// the start, where that variable carries more digits.
fn polish_near_pole(g: impl Fn(f64) -> (f64, f64), p: f64, dist: f64, k: f64, p0: f64) -> f64 {
    let p = p.clamp(0.0, p0);
    if p >= dist.abs() {
        return p;
    }
    root_near_pole(g, k, (2.0 * p).min(p0))
}

/// The root of f in [0, hi] in a pole variable, given f(hi) ≥ 0 and f(0) = −k² ≤ 0. `k` is the
/// pole's momentum combination (d or e): when it is zero the pole itself may be the turning
/// point (the axis passes through the vertical).
fn root_near_pole(g: impl Fn(f64) -> (f64, f64), k: f64, hi: f64) -> f64 {
    if k != 0.0 {
        return bracketed_root(g, 0.0, hi);
    }
    // f = p·h(p) with h(0) = f'(0): the pole is the turning point when h(0) ≥ 0.
    let (_, h0) = g(0.0);
    if h0 >= 0.0 {
        return 0.0;
    }
    let h = |x: f64| {
        let (f, df) = g(x);
        if x == 0.0 {
            (df, 0.0)
        } else {
            (f / x, (df - f / x) / x)
        }
    };
    bracketed_root(h, 0.0, hi)
}

/// The turning points of a top given by its constants only: the roots on either side of the
/// maximum of f. `None` if f < 0 everywhere on [−1, 1] (the energy is below the minimum of
/// the effective potential); `Some((turning, steady))` otherwise.
pub(crate) fn turning_points_from_constants(r: &Reduced) -> Option<Turning> {
    let (c2, c1, _) = r.w_coefficients();
    // The maximum of f on [0, 2]: the larger root of f'(w) = −3βw² + 2C₂w + C₁, or, below the
    // equator, the smaller root of f'(v) = 3βv² − 2(2β + δ + a²)v + 2(δ + ae) (same point, in v).
    let w_star = quadratic_roots(-3.0 * r.beta, 2.0 * c2, c1)
        .into_iter()
        .fold(f64::NEG_INFINITY, f64::max);
    let w_star = if w_star.is_finite() {
        w_star.clamp(0.0, 2.0)
    } else {
        1.0
    };
    let v_star = if w_star <= 1.0 {
        2.0 - w_star
    } else {
        let v = quadratic_roots(
            3.0 * r.beta,
            -2.0 * (2.0 * r.beta + r.delta + r.a * r.a),
            2.0 * (r.delta + r.a * r.e),
        )
        .into_iter()
        .filter(|v| v.is_finite())
        .fold(f64::INFINITY, f64::min);
        if v.is_finite() {
            v.clamp(0.0, 1.0)
        } else {
            2.0 - w_star
        }
    };
    let (f_star, _) = if w_star <= 1.0 {
        r.f_w(w_star)
    } else {
        r.f_v(v_star)
    };
    let tol = 64.0 * f64::EPSILON * r.f_scale(w_star);
    if f_star < -tol {
        return None;
    }
    if f_star <= tol {
        return Some(if w_star <= 1.0 {
            Turning::coincident(w_star, v_star)
        } else {
            Turning::coincident(2.0 - v_star, v_star)
        });
    }
    // Each root in the variable where it is ≤ 1, the other variable as its complement (≥ 1).
    let in_w = |w: f64| (w, 2.0 - w);
    let in_v = |v: f64| (2.0 - v, v);
    // Upper root in [0, w*]; where d = 0 (p_φ = p_ψ) the pole itself may be it, whatever w*.
    let upper = if w_star <= 1.0 || r.f_w(1.0).0 >= 0.0 {
        in_w(root_near_pole(|w| r.f_w(w), r.d, w_star.min(1.0)))
    } else {
        in_v(bracketed_root(|v| r.f_v(v), 1.0, v_star))
    };
    // Lower root in [w*, 2]; where e = 0 (p_φ = −p_ψ) the lower pole may be it.
    let lower = if v_star <= 1.0 || r.f_v(1.0).0 >= 0.0 {
        in_v(root_near_pole(|v| r.f_v(v), r.e, v_star.min(1.0)))
    } else {
        in_w(bracketed_root(|w| r.f_w(w), 1.0, w_star))
    };
    Some(Turning::new(upper, lower))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bracketed_root_finds_a_tiny_root_to_relative_precision() {
        // (x − 1e-20)(x + 1): a root far below the bracket's width.
        let g = |x: f64| ((x - 1e-20) * (x + 1.0), 2.0 * x + 1.0 - 1e-20);
        let r = bracketed_root(g, 0.0, 0.5);
        assert!((r / 1e-20 - 1.0).abs() < 1e-14, "{r:e}");
    }

    #[test]
    fn quadratic_roots_are_stable() {
        let r = quadratic_roots(1.0, -1e8, 1.0);
        let small = r.iter().cloned().fold(f64::INFINITY, f64::min);
        assert!((small / 1e-8 - 1.0).abs() < 1e-15, "{small:e}");
    }
}
