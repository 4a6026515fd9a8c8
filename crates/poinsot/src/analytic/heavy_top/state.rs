//! The leaf of the heavy top: the state type, the limits of the solution, and the time unit in
//! which a top's motion is computed. The other parts of `heavy_top` use these; this uses only
//! the reduced constants of [`super::cubic`].

use super::cubic::Reduced;

/// A nutation θ₂ − θ₁ at or below this (rad) is reported as steady precession (it is below the
/// round-off of turning points computed from double-precision data near a double root). The
/// motion itself is still evaluated exactly with the computed turning points.
pub const STEADY_NUTATION_TOLERANCE: f64 = 1e-10;

/// The closest approach (rad) to a vertical that the solution resolves, other than passing
/// exactly through it: the axis' distance from the pole is carried as 1 − cos θ = 2 sin²(θ/2)
/// ≈ θ²/2, and the terms of the cubic near the pole (2.109–2.110 with u = cos θ; e.g.
/// sin²θ₀ θ̇₀²) are products of two such distances, ~θ⁴ in the top's time unit, which leave
/// the normal range of double precision below θ ≈ 1e-77. A start `theta` in (0, 1e-60), or a
/// motion whose turning point comes that close to a pole it does not pass through, is refused
/// (the margin, 1e-60 in θ⁴, leaves room for rates 1e-30 of the fastest); θ = 0 itself is exact.
pub const MIN_POLE_DISTANCE: f64 = 1e-60;

/// The largest phase (rad) at which the motion is evaluated: `|t|` times the fastest of the
/// motion's rates (the nutation's 2π/period, ⟨φ̇⟩, ⟨ψ̇⟩). Each rate is known to a few ulp, so the
/// phase it accumulates by time t carries a rounding error of about ε × rate × |t|; at this
/// phase that error reaches 1e-6 rad, and beyond it the nutation phase is lost (at ~1e16 rad not
/// a digit is left), so [`super::HeavyTop::euler_angles`] refuses `t` there. ≈ 4.5e9 rad, i.e. about
/// 7e8 nutation periods.
pub const MAX_PHASE: f64 = 1e-6 / f64::EPSILON;

/// φ̇ at a turning point is taken as zero (a cusp) when `|b − a cos θᵢ|` is at most this times
/// the size of its terms (the round-off of the momenta, with margin).
pub const CUSP_TOLERANCE: f64 = 1e-10;

/// Euler angles (the unit's z-x-z: φ about Z, θ about the line of nodes, ψ about axis 3) and
/// their rates at one instant (rad, rad/s).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EulerState {
    /// Precession angle φ (rad).
    pub phi: f64,
    /// Nutation angle θ (rad), in [0, π].
    pub theta: f64,
    /// Spin angle ψ (rad).
    pub psi: f64,
    /// φ̇ (rad/s).
    pub phi_dot: f64,
    /// θ̇ (rad/s).
    pub theta_dot: f64,
    /// ψ̇ (rad/s).
    pub psi_dot: f64,
}

impl EulerState {
    /// The state of the Euler angles `phi`, `theta`, `psi` (rad) and their rates `phi_dot`,
    /// `theta_dot`, `psi_dot` (rad/s), in the order of the fields (and of the front ends'
    /// `HeavyTop.from_state`).
    pub fn new(phi: f64, theta: f64, psi: f64, phi_dot: f64, theta_dot: f64, psi_dot: f64) -> Self {
        Self {
            phi,
            theta,
            psi,
            phi_dot,
            theta_dot,
            psi_dot,
        }
    }

    /// The state at the nutation angle `theta` (rad) with the rates `theta_dot`, `phi_dot`,
    /// `psi_dot` (rad/s) and φ = ψ = 0: all the Lagrangian 2.102 and the constants 2.103–2.105
    /// of a state depend on.
    pub fn with_rates(theta: f64, theta_dot: f64, phi_dot: f64, psi_dot: f64) -> Self {
        Self {
            theta,
            theta_dot,
            phi_dot,
            psi_dot,
            ..Self::default()
        }
    }
}

/// The time unit in which a top's motion is computed: 1/σ with σ = 2ᵏ the power of two nearest
/// its fastest rate (|θ̇|, |φ̇|, |ψ̇|, √(2mgl/I₁); for a top given by its constants, |p_ψ|/I₁,
/// |p_φ|/I₁ and the square roots of the energies per I₁). In that unit every rate is at most ~1,
/// so the squares and products of the cubic (2.109–2.110) stay inside double precision for rates
/// anywhere from 1e-300 to 1e300 rad/s; scaling by a power of two is exact, so a top with rates
/// near 1 rad/s gives bit for bit the numbers it gave before.
#[derive(Debug, Clone, Copy)]
pub(super) struct TimeScale {
    /// σ (1/s).
    pub(super) sigma: f64,
    /// 1/σ (s).
    inv: f64,
}

impl TimeScale {
    /// The scale of these rates (1/s; non-finite entries count as the largest double).
    pub(super) fn of(rates: &[f64]) -> Self {
        let largest = rates
            .iter()
            .map(|r| if r.is_nan() { 0.0 } else { r.abs() })
            .fold(0.0, f64::max)
            .min(f64::MAX);
        // 2ᵏ with |k| ≤ 1000 (σ and 1/σ both normal); 1 for a top with no rate at all.
        let k = if largest > 0.0 {
            largest.log2().round().clamp(-1000.0, 1000.0) as i32
        } else {
            0
        };
        Self {
            sigma: 2f64.powi(k),
            inv: 2f64.powi(-k),
        }
    }
    /// A rate (1/s) in the unit σ.
    pub(super) fn in_unit(&self, rate: f64) -> f64 {
        rate * self.inv
    }
    /// A quantity ∝ one rate back to SI (it overflows only where the SI value does).
    pub(super) fn rate_to_si(&self, x: f64) -> f64 {
        x * self.sigma
    }
    /// A quantity ∝ a rate squared back to SI.
    pub(super) fn rate2_to_si(&self, x: f64) -> f64 {
        x * self.sigma * self.sigma
    }
    /// A moment of inertia `i` (kg·m²) times a quantity `x` ∝ σ^`power` (a rate, `power` = 1,
    /// or a rate squared, 2), in SI. The product i·x is formed first where it is a normal
    /// double; where it would be subnormal (a tiny moment: I = 2⁻¹⁰¹⁸ kg·m² with x ~ 0.1) x is
    /// carried to SI first, so that no digit is lost to underflow (it overflows only where the SI
    /// value does).
    pub(super) fn moment_to_si(&self, i: f64, x: f64, power: i32) -> f64 {
        let to_si = |y: f64| {
            if power == 1 {
                self.rate_to_si(y)
            } else {
                self.rate2_to_si(y)
            }
        };
        let p = i * x;
        if x == 0.0 || p.abs() >= f64::MIN_POSITIVE {
            to_si(p)
        } else {
            to_si(x) * i
        }
    }
    /// β = 2 m g l / I₁ in the unit σ² (formed in SI where that is a finite normal double, as
    /// before; otherwise m g l is carried to the unit first, which neither overflows nor, for a
    /// huge I₁ = 2¹⁰¹⁸ kg·m², loses digits to a subnormal quotient).
    pub(super) fn beta(&self, mgl: f64, i1: f64) -> f64 {
        let beta = 2.0 * mgl / i1;
        if beta.is_finite() && (mgl == 0.0 || beta >= f64::MIN_POSITIVE) {
            beta * self.inv * self.inv
        } else {
            2.0 * (mgl * self.inv * self.inv / i1)
        }
    }
    /// Reduced constants given in SI, in the unit σ.
    pub(super) fn reduced_to_unit(&self, r: &Reduced) -> Reduced {
        let (s1, s2) = (self.inv, self.inv * self.inv);
        Reduced {
            a: r.a * s1,
            b: r.b * s1,
            d: r.d * s1,
            e: r.e * s1,
            beta: r.beta * s2,
            gamma: r.gamma * s2,
            delta: r.delta * s2,
        }
    }
}
