//! The Lie–Poisson splitting of the rigid body (Reich 1994; McLachlan 1993; Touma & Wisdom
//! 1994; Dullweber, Leimkuhler & McLachlan 1997).
//!
//! The free body's Hamiltonian in principal axes, `H = L₁²/2I₁ + L₂²/2I₂ + L₃²/2I₃`, splits
//! into three terms whose flows are exact rotations: under `Lᵢ²/2Iᵢ` the body spins about
//! principal axis i at the constant rate `Lᵢ/Iᵢ`, so over a step h the attitude turns by
//! `θ = h Lᵢ/Iᵢ` about eᵢ (`R ← R Rot(eᵢ, θ)`) and L's body components turn by −θ about eᵢ.
//! The symmetric Strang step `R₁(h/2) R₂(h/2) R₃(h) R₂(h/2) R₁(h/2)` is second order; a torque
//! that depends only on the attitude and time (gravity, the gravity gradient, constant torques)
//! adds the exact kick `L ← L + h N` at fixed attitude around it:
//! `K(h/2) ∘ Free(h) ∘ K(h/2)`. Composed to orders 4 and 6
//! ([`crate::integrate::compose`]), every stage is a rotation or a kick, so |L| (without
//! torque) and |q| stay exact to round-off, the map is symplectic on T*SO(3) (Poisson on the
//! Lie–Poisson reduced space) and the energy error stays bounded without drift.

use crate::integrate::SymmetricStep;
use crate::rotation::{hamilton, normalized, Quaternion};
use crate::Vec3;

/// The state of the splitting: body angular momentum in principal axes, attitude, time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SplitState {
    /// L in principal body axes (kg·m²/s).
    pub l: Vec3,
    /// Attitude of the principal frame, `[w, x, y, z]`, principal → space.
    pub q: Quaternion,
    /// Time (s).
    pub t: f64,
}

/// Rotation of the body about principal axis `k` under `L_k²/2I_k` for a time `h`.
///
/// L's components turn as `l ← l − (v l ∓ s l')` with the versine `v = 1 − cos θ = 2 sin²(θ/2)`
/// and `s = sin θ`, never through `cos θ` itself: `cos θ = 1 − v` of a small step angle rounds
/// to the doubles near 1, an error of up to 2⁻⁵⁴ that scales |L| by `1 + 2δc`. When a rotation
/// angle hardly changes from step to step — a spin close to a principal axis, where `L_k` is
/// nearly constant — that rounding repeats with the same sign every step and |L| drifts
/// linearly (2.8e-11 per 10⁶ steps of order 6 for I = (1, 2, 3), ω₀ = (1, 0, 0.01), nine
/// stages of constant angles). Carried as `v` the norm's error is `4 sin²(θ/2)` times smaller
/// (the relative rounding of `v` and `s`), and the only rounding left at unit scale is that of
/// the new components, which is not correlated from step to step: |L| then wanders like √n
/// (`bench/splitting_long_runs.py`, docs/dynamics.md "Long runs").
#[inline(always)]
pub(crate) fn spin(state: &mut SplitState, moments: &[f64; 3], k: usize, h: f64) {
    let theta = h * state.l[k] / moments[k];
    let (sh, ch) = (0.5 * theta).sin_cos();
    let (s, v) = (2.0 * sh * ch, 2.0 * sh * sh);
    let (i, j) = ((k + 1) % 3, (k + 2) % 3);
    let (li, lj) = (state.l[i], state.l[j]);
    // L turns by −θ about e_k in body components: (c li + s lj, c lj − s li) with c = 1 − v.
    state.l[i] = li - (v * li - s * lj);
    state.l[j] = lj - (v * lj + s * li);
    // q ← q ⊗ (cos θ/2, sin θ/2 e_k).
    let q = state.q;
    let mut r = [ch, 0.0, 0.0, 0.0];
    r[k + 1] = sh;
    state.q = hamilton(&q, &r);
}

/// The free Strang step of the splitting, `R₁(h/2) R₂(h/2) R₃(h) R₂(h/2) R₁(h/2)`, with the
/// outer half-steps of consecutive stages merged by [`free_steps`].
pub struct FreeStrang<'a> {
    /// State being advanced.
    pub state: &'a mut SplitState,
    /// Principal moments (kg·m²).
    pub moments: [f64; 3],
}

impl SymmetricStep for FreeStrang<'_> {
    #[inline]
    fn step(&mut self, h: f64) {
        let m = self.moments;
        spin(self.state, &m, 0, 0.5 * h);
        spin(self.state, &m, 1, 0.5 * h);
        spin(self.state, &m, 2, h);
        spin(self.state, &m, 1, 0.5 * h);
        spin(self.state, &m, 0, 0.5 * h);
        self.state.t += h;
    }
}

/// `n` steps of size `h` of the free splitting composed with coefficients `gammas`, merging
/// the consecutive outer half-steps about axis 1 (so a stage costs four rotations); the
/// quaternion is renormalised once per step (a round-off-level correction).
#[inline]
pub fn free_steps(state: &mut SplitState, moments: &[f64; 3], gammas: &[f64], h: f64, n: usize) {
    if n == 0 {
        return;
    }
    let first = gammas[0];
    spin(state, moments, 0, 0.5 * first * h);
    for step in 0..n {
        for (s, &g) in gammas.iter().enumerate() {
            let gh = g * h;
            spin(state, moments, 1, 0.5 * gh);
            spin(state, moments, 2, gh);
            spin(state, moments, 1, 0.5 * gh);
            let next = if s + 1 < gammas.len() {
                gammas[s + 1]
            } else if step + 1 < n {
                first
            } else {
                0.0
            };
            spin(state, moments, 0, 0.5 * (g + next) * h);
        }
        state.t += h;
        state.q = normalized(&state.q);
    }
}

/// One step `h` of the splitting with kicks `K(h/2) ∘ Free(h) ∘ K(h/2)` composed with
/// `gammas`; `kick(state, dt)` must add `dt · N` to `state.l` at fixed attitude and time.
#[inline]
pub fn kicked_step<F: FnMut(&mut SplitState, f64)>(
    state: &mut SplitState,
    moments: &[f64; 3],
    gammas: &[f64],
    h: f64,
    kick: &mut F,
) {
    for &g in gammas {
        let gh = g * h;
        kick(state, 0.5 * gh);
        let mut free = FreeStrang {
            state: &mut *state,
            moments: *moments,
        };
        free.step(gh);
        kick(state, 0.5 * gh);
    }
    state.q = normalized(&state.q);
}
