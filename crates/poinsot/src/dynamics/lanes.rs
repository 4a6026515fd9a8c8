//! The rigid body on SIMD lanes: RK4 and the Lie–Poisson splitting for a group of
//! `F64s::<S>::LANES` bodies at once, in structure-of-arrays form (component k of body i is
//! `y[k].lanes()[i]`), under no torque or a built-in [`Torque`]. Each lane performs the
//! arithmetic of the scalar step it mirrors (`RigidRhs::rk4_step`, `splitting::spin`,
//! [`free_steps`](super::free_steps), [`kicked_step`](super::kicked_step)) in the same order,
//! so RK4 gives the scalar path's numbers bit for bit; the splitting differs only by the sine
//! and cosine of its rotation angles ([`crate::simd::sin_cos`], within 2 ulp of the standard
//! library's), a relative 1e-16 per step.
//!
//! Bodies may take different numbers of steps of different sizes (each its own default step):
//! a lane stops once its steps are done (its state is then kept as it is while the others go
//! on).

use super::torque::Torque;
use crate::control::Cancel;
use crate::error::Result;
use crate::rotation::{normalized_lanes, quaternion_to_matrix_lanes, QuatLanes};
use crate::simd::{sin_cos, F64s, Mask, Simd};

/// The state (ω₁, ω₂, ω₃, q_w, q_x, q_y, q_z) of a group of bodies.
pub(crate) type StateLanes<S> = [F64s<S>; 7];

/// Steps between two looks at the stop flag.
const STEPS_PER_POLL: usize = 64;

/// A built-in torque evaluated on lanes, in principal body components (N·m), as the scalar
/// batch evaluates it (the attitude from the normalised quaternion).
#[derive(Debug, Clone, Copy)]
pub(crate) struct TorqueLanes<S: Simd> {
    torque: Torque,
    /// The principal moments of the lanes' bodies (the gravity-gradient torque needs them).
    moments: [F64s<S>; 3],
}

impl<S: Simd> TorqueLanes<S> {
    #[inline(always)]
    pub(crate) fn new(torque: Torque, moments: [F64s<S>; 3]) -> Self {
        Self { torque, moments }
    }

    /// N at time `t` and attitude `q` (not necessarily of unit norm).
    #[inline(always)]
    pub(crate) fn at(&self, t: F64s<S>, q: &QuatLanes<S>) -> [F64s<S>; 3] {
        let zero = t.splat_like(0.0);
        match self.torque {
            Torque::None => [zero; 3],
            Torque::Body(n) => [t.splat_like(n.x), t.splat_like(n.y), t.splat_like(n.z)],
            Torque::Space(n) => {
                let r = quaternion_to_matrix_lanes(&normalized_lanes(q));
                // Rᵀ n (as nalgebra's product: a sum over the columns of Rᵀ in order).
                [
                    r[0] * n.x + r[3] * n.y + r[6] * n.z,
                    r[1] * n.x + r[4] * n.y + r[7] * n.z,
                    r[2] * n.x + r[5] * n.y + r[8] * n.z,
                ]
            }
            Torque::Gravity { mgl } => {
                let r = quaternion_to_matrix_lanes(&normalized_lanes(q));
                [mgl * r[7], mgl * -r[6], mgl * zero]
            }
            Torque::GravityGradient { mean_motion } => {
                let r = quaternion_to_matrix_lanes(&normalized_lanes(q));
                let (mut s, mut c) = (zero, zero);
                // The standard library's sin and cos of n t (the orbit's position), as the
                // scalar path takes them.
                for i in 0..F64s::<S>::LANES {
                    (s.lanes_mut()[i], c.lanes_mut()[i]) = (mean_motion * t.lanes()[i]).sin_cos();
                }
                let rb = [
                    r[0] * c + r[3] * s + r[6] * 0.0,
                    r[1] * c + r[4] * s + r[7] * 0.0,
                    r[2] * c + r[5] * s + r[8] * 0.0,
                ];
                let m = &self.moments;
                let ib = [m[0] * rb[0], m[1] * rb[1], m[2] * rb[2]];
                let k = 3.0 * mean_motion * mean_motion;
                [
                    k * (rb[1] * ib[2] - rb[2] * ib[1]),
                    k * (rb[2] * ib[0] - rb[0] * ib[2]),
                    k * (rb[0] * ib[1] - rb[1] * ib[0]),
                ]
            }
        }
    }
}

/// Euler's equations with the divisions done once, on lanes (as `RigidRhs`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct RigidLanes<S: Simd> {
    k: [F64s<S>; 3],
    inv: [F64s<S>; 3],
}

impl<S: Simd> RigidLanes<S> {
    #[inline(always)]
    pub(crate) fn new(moments: &[F64s<S>; 3]) -> Self {
        let [i1, i2, i3] = *moments;
        Self {
            k: [(i2 - i3) / i1, (i3 - i1) / i2, (i1 - i2) / i3],
            inv: [1.0 / i1, 1.0 / i2, 1.0 / i3],
        }
    }

    #[inline(always)]
    fn eval(&self, y: &StateLanes<S>, n: &[F64s<S>; 3]) -> StateLanes<S> {
        let (w1, w2, w3) = (y[0], y[1], y[2]);
        let (qw, qx, qy, qz) = (y[3], y[4], y[5], y[6]);
        [
            self.k[0] * w2 * w3 + n[0] * self.inv[0],
            self.k[1] * w3 * w1 + n[1] * self.inv[1],
            self.k[2] * w1 * w2 + n[2] * self.inv[2],
            -0.5 * (qx * w1 + qy * w2 + qz * w3),
            0.5 * (qw * w1 + qy * w3 - qz * w2),
            0.5 * (qw * w2 + qz * w1 - qx * w3),
            0.5 * (qw * w3 + qx * w2 - qy * w1),
        ]
    }

    /// One classic RK4 step of size `h` from `(t, y)`, the quaternion renormalised after it by
    /// one Newton step (as `RigidRhs::rk4_step`).
    #[inline(always)]
    fn rk4_step(
        &self,
        t: F64s<S>,
        y: &StateLanes<S>,
        h: F64s<S>,
        torque: &TorqueLanes<S>,
    ) -> StateLanes<S> {
        #[inline(always)]
        fn axpy<S: Simd>(y: &StateLanes<S>, a: F64s<S>, k: &StateLanes<S>) -> StateLanes<S> {
            let mut out = *y;
            for i in 0..7 {
                out[i] = y[i] + a * k[i];
            }
            out
        }
        #[inline(always)]
        fn quat<S: Simd>(y: &StateLanes<S>) -> QuatLanes<S> {
            [y[3], y[4], y[5], y[6]]
        }
        let half = 0.5 * h;
        let k1 = self.eval(y, &torque.at(t, &quat(y)));
        let y2 = axpy(y, half, &k1);
        let k2 = self.eval(&y2, &torque.at(t + half, &quat(&y2)));
        let y3 = axpy(y, half, &k2);
        let k3 = self.eval(&y3, &torque.at(t + half, &quat(&y3)));
        let y4 = axpy(y, h, &k3);
        let k4 = self.eval(&y4, &torque.at(t + h, &quat(&y4)));
        let h6 = h * (1.0 / 6.0);
        let mut out = *y;
        for i in 0..7 {
            out[i] = y[i] + h6 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
        }
        let n2 = out[3] * out[3] + out[4] * out[4] + out[5] * out[5] + out[6] * out[6];
        let f = 1.5 - 0.5 * n2;
        for v in &mut out[3..] {
            *v *= f;
        }
        out
    }
}

/// The lanes still stepping at step `s` of `steps` each.
#[inline(always)]
fn active<S: Simd>(s: usize, steps: &F64s<S>) -> Mask<S> {
    steps.splat_like(s as f64).lt(*steps)
}

/// RK4 steps of size `h` (lane i takes `steps.lanes()[i]` of them) from `y` under `torque`,
/// polling `cancel`.
#[inline(always)]
pub(crate) fn rk4_lanes<S: Simd>(
    moments: &[F64s<S>; 3],
    y: &mut StateLanes<S>,
    h: F64s<S>,
    steps: F64s<S>,
    torque: &TorqueLanes<S>,
    cancel: &Cancel,
) -> Result<()> {
    let rigid = RigidLanes::new(moments);
    // The steps every lane takes, then those of the lanes that take more.
    let all = steps.min_lane() as usize;
    let most = steps.max_lane() as usize;
    for s in 0..all {
        if s % STEPS_PER_POLL == 0 {
            cancel.check()?;
        }
        *y = rigid.rk4_step(h * s as f64, y, h, torque);
    }
    for s in all..most {
        if s % STEPS_PER_POLL == 0 {
            cancel.check()?;
        }
        let next = rigid.rk4_step(h * s as f64, y, h, torque);
        let on = active(s, &steps);
        for (v, n) in y.iter_mut().zip(next) {
            *v = F64s::select(on, n, *v);
        }
    }
    Ok(())
}

/// The splitting's state on lanes: L in principal axes, the attitude, the time.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SplitLanes<S: Simd> {
    pub(crate) l: [F64s<S>; 3],
    pub(crate) q: QuatLanes<S>,
    pub(crate) t: F64s<S>,
}

impl<S: Simd> SplitLanes<S> {
    /// `a` in the lanes of `on`, `b` elsewhere.
    #[inline(always)]
    fn select(on: Mask<S>, a: &Self, b: &Self) -> Self {
        let mut out = *b;
        for k in 0..3 {
            out.l[k] = F64s::select(on, a.l[k], b.l[k]);
        }
        for k in 0..4 {
            out.q[k] = F64s::select(on, a.q[k], b.q[k]);
        }
        out.t = F64s::select(on, a.t, b.t);
        out
    }
}

/// The rotation about principal axis `K` under `L_K²/2I_K` for a time `h` (as
/// `splitting::spin`; the product with the axis quaternion written without its zero terms).
#[inline(always)]
fn spin<const K: usize, S: Simd>(state: &mut SplitLanes<S>, moments: &[F64s<S>; 3], h: F64s<S>) {
    let theta = h * state.l[K] / moments[K];
    let (sh, ch) = sin_cos(0.5 * theta);
    let (s, v) = (2.0 * sh * ch, 2.0 * sh * sh);
    let (i, j) = ((K + 1) % 3, (K + 2) % 3);
    let (li, lj) = (state.l[i], state.l[j]);
    state.l[i] = li - (v * li - s * lj);
    state.l[j] = lj - (v * lj + s * li);
    // q ⊗ (ch, sh e_K).
    let [pw, px, py, pz] = state.q;
    state.q = match K {
        0 => [
            pw * ch - px * sh,
            pw * sh + px * ch,
            py * ch + pz * sh,
            -py * sh + pz * ch,
        ],
        1 => [
            pw * ch - py * sh,
            px * ch - pz * sh,
            pw * sh + py * ch,
            px * sh + pz * ch,
        ],
        _ => [
            pw * ch - pz * sh,
            px * ch + py * sh,
            -px * sh + py * ch,
            pw * sh + pz * ch,
        ],
    };
}

/// Steps of size `h` of the free splitting composed with `gammas` (as
/// [`free_steps`](super::free_steps), the outer half-steps about axis 1 of consecutive stages
/// merged), lane i taking `steps.lanes()[i]` of them; polls `cancel`.
#[inline(always)]
pub(crate) fn free_steps_lanes<S: Simd>(
    state: &mut SplitLanes<S>,
    moments: &[F64s<S>; 3],
    gammas: &[f64],
    h: F64s<S>,
    steps: F64s<S>,
    cancel: &Cancel,
) -> Result<()> {
    let most = steps.max_lane() as usize;
    if most == 0 {
        return Ok(());
    }
    let first = gammas[0];
    let mut next = *state;
    spin::<0, S>(&mut next, moments, 0.5 * first * h);
    *state = SplitLanes::select(active(0, &steps), &next, state);
    for step in 0..most {
        if step % STEPS_PER_POLL == 0 {
            cancel.check()?;
        }
        let on = active(step, &steps);
        // The last stage of a lane's last step closes with a half-step (no next stage).
        let more = active(step + 1, &steps);
        let mut next = *state;
        for (s, &g) in gammas.iter().enumerate() {
            let gh = g * h;
            spin::<1, S>(&mut next, moments, 0.5 * gh);
            spin::<2, S>(&mut next, moments, gh);
            spin::<1, S>(&mut next, moments, 0.5 * gh);
            let after = if s + 1 < gammas.len() {
                h.splat_like(gammas[s + 1])
            } else {
                F64s::select(more, h.splat_like(first), h.splat_like(0.0))
            };
            spin::<0, S>(&mut next, moments, 0.5 * (g + after) * h);
        }
        next.t += h;
        next.q = normalized_lanes(&next.q);
        *state = SplitLanes::select(on, &next, state);
    }
    Ok(())
}

/// Steps of size `h` of the splitting with kicks `K(h/2) ∘ Free(h) ∘ K(h/2)` composed with
/// `gammas` (as [`kicked_step`](super::kicked_step)), lane i taking `steps.lanes()[i]` of them.
#[inline(always)]
pub(crate) fn kicked_steps_lanes<S: Simd>(
    state: &mut SplitLanes<S>,
    moments: &[F64s<S>; 3],
    gammas: &[f64],
    h: F64s<S>,
    steps: F64s<S>,
    torque: &TorqueLanes<S>,
    cancel: &Cancel,
) -> Result<()> {
    #[inline(always)]
    fn kick<S: Simd>(s: &mut SplitLanes<S>, dt: F64s<S>, torque: &TorqueLanes<S>) {
        let n = torque.at(s.t, &s.q);
        for (l, n) in s.l.iter_mut().zip(n) {
            *l += dt * n;
        }
    }
    let most = steps.max_lane() as usize;
    for step in 0..most {
        if step % STEPS_PER_POLL == 0 {
            cancel.check()?;
        }
        let mut next = *state;
        for &g in gammas {
            let gh = g * h;
            kick(&mut next, 0.5 * gh, torque);
            let half = 0.5 * gh;
            spin::<0, S>(&mut next, moments, half);
            spin::<1, S>(&mut next, moments, half);
            spin::<2, S>(&mut next, moments, gh);
            spin::<1, S>(&mut next, moments, half);
            spin::<0, S>(&mut next, moments, half);
            next.t += gh;
            kick(&mut next, 0.5 * gh, torque);
        }
        next.q = normalized_lanes(&next.q);
        *state = SplitLanes::select(active(step, &steps), &next, state);
    }
    Ok(())
}
