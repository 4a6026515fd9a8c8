//! Many states of one free body at once: the elliptic motion on SIMD lanes, a group of times
//! per vector instruction.
//!
//! Each lane computes what [`FreeRigidBody::state`] computes, in the same order: ω by the same
//! reduction and duplication of the Jacobi functions (bit for bit:
//! `Jacobi::eval_reduced_lanes`), the attitude by the same Euler angles and quaternion
//! products. Two parts differ by round-off only: the integral of the third kind Π(n; am r | m)
//! of the precession angle is summed as its Fourier series ([`PiSeries`], the form the heavy
//! top's fast path uses) instead of Carlson's R_J, and the sines and cosines are the lanes'
//! ([`crate::simd::sin_cos`], within 2 ulp).

use std::f64::consts::PI;

use super::{Elliptic, FreeRigidBody, CANCELLATION};
use crate::analytic::heavy_top::fourier::{nome, ThirdSeries, MAX_TERMS, TRUNCATION};
use crate::rotation::{
    hamilton_lanes, matrix_to_quaternion_lanes, normalized_lanes, QuatLanes, Quaternion,
};
use crate::simd::{sin_cos, F64s, Simd, WithSimd, MAX_LANES};
use crate::special::carlson::rf;

/// Π(n; am r | m) for |r| ≤ K (n < 0: the free body's characteristic) as its Fourier series
/// `(Π(n|m)/K) r + Σ b_k sin(kπr/K)` (see `heavy_top::fourier`, whose hyperbolic case this
/// is), summed to round-off.
#[derive(Debug, Clone)]
pub(crate) struct PiSeries {
    /// Π(n|m)/K.
    slope: f64,
    /// π/K.
    x_per_r: f64,
    /// b₁, b₂, …
    b: Vec<f64>,
}

impl PiSeries {
    /// The series of an elliptic motion, or `None` where it would need more than
    /// [`MAX_TERMS`] terms (m near 1: next to the separatrix), where n < −[`CANCELLATION`] (a
    /// body nearly symmetric about its pole, for which the scalar path sums Π in a form with
    /// positive terms only: the series, whose ratio ρ then nears 1, would lose the digits that
    /// form keeps), or where the lanes do not apply.
    pub(super) fn new(e: &Elliptic) -> Option<Self> {
        if e.separatrix || !e.jacobi.has_lanes() || e.n < -CANCELLATION {
            return None;
        }
        let (m, mc, k) = (
            e.jacobi.m(),
            e.jacobi.complement(),
            e.jacobi.quarter_period(),
        );
        if !(mc > 0.0 && e.n < 0.0) {
            return None;
        }
        let k_prime = if m >= 1e-4 {
            rf(0.0, m, 1.0)
        } else {
            f64::INFINITY
        };
        let (q, _) = nome(m, k, k_prime);
        if q.is_nan() || q >= 0.5 {
            return None;
        }
        let series = ThirdSeries::hyperbolic(-e.n, 1.0 - e.n, m, mc, k)?;
        let mut b = Vec::new();
        let mut scale = e.pi_complete.abs();
        for kk in 1..=MAX_TERMS {
            let c = series.coefficient(kk, q);
            if !c.is_finite() {
                return None;
            }
            scale = scale.max(c.abs());
            b.push(c);
            if c.abs() <= TRUNCATION * scale {
                return Some(Self {
                    slope: e.pi_complete / k,
                    x_per_r: PI / k,
                    b,
                });
            }
        }
        None
    }

    /// Π(n; am r | m) at reduced arguments |r| ≤ K.
    #[inline(always)]
    fn eval<S: Simd>(&self, r: F64s<S>) -> F64s<S> {
        let (s1, c1) = sin_cos(r * self.x_per_r);
        let (mut ck, mut sk) = (c1, s1);
        let mut sum = r.splat_like(0.0);
        for &b in &self.b {
            sum += sk * b;
            // (cos, sin) of (k + 1)x by one rotation.
            let c_next = ck * c1 - sk * s1;
            sk = sk * c1 + ck * s1;
            ck = c_next;
        }
        self.slope * r + sum
    }

    /// Π(n; am r | m) at one reduced argument (for the tests).
    #[cfg(test)]
    pub(crate) fn eval_one(&self, r: f64) -> f64 {
        self.eval(F64s::splat(pulp::Scalar, r)).lanes()[0]
    }
}

/// The states of an elliptic motion at `times` (checked) into `omega`, `attitude`.
pub(super) struct EllipticStates<'a> {
    pub(super) body: &'a FreeRigidBody,
    pub(super) e: &'a Elliptic,
    pub(super) series: &'a PiSeries,
    pub(super) times: &'a [f64],
    pub(super) omega: &'a mut [[f64; 3]],
    pub(super) attitude: &'a mut [Quaternion],
}

impl WithSimd for EllipticStates<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: Simd>(self, s: S) {
        let lanes = F64s::<S>::LANES;
        let e = self.e;
        let s_w = self.body.scale.s_w;
        // ω in the user's axes: component i is ±(sorted component `from[i]`).
        let mut from = [(0usize, 1.0f64); 3];
        for (i, f) in from.iter_mut().enumerate() {
            for j in 0..3 {
                let v = e.to_sorted[(j, i)];
                if v != 0.0 {
                    *f = (j, v);
                }
            }
        }
        let splat4 = |q: &Quaternion| q.map(|c| F64s::splat(s, c));
        let q_pre = splat4(&e.q_pre);
        let q_post = splat4(&e.q_post);
        let zero = F64s::splat(s, 0.0);
        let one = F64s::splat(s, 1.0);
        for ((ts, w_out), q_out) in self
            .times
            .chunks(lanes)
            .zip(self.omega.chunks_mut(lanes))
            .zip(self.attitude.chunks_mut(lanes))
        {
            let len = ts.len();
            let mut buf = [ts[0]; MAX_LANES];
            buf[..len].copy_from_slice(ts);
            let th = F64s::load(s, &buf) * s_w;
            // ω in sorted components (`Elliptic::omega_sorted`).
            let tau = F64s::splat(s, e.lambda).mul_add(th, F64s::splat(s, e.tau0));
            let (j, r) = e.jacobi.reduce_lanes(tau);
            let (sn, cn, dn) = e.jacobi.eval_reduced_lanes(r);
            let flip = F64s::select(j.is_odd(), -one, one);
            let mut w = [zero; 3];
            w[e.other] = e.amp_cn * flip * cn;
            w[1] = e.amp_sn * flip * sn;
            w[e.pole] = e.amp_dn * dn;
            // The precession angle (`Elliptic::pi_of`, `Elliptic::state`).
            let pi = 2.0 * j * e.pi_complete + self.series.eval(r);
            let phi = F64s::splat(s, e.rate_p).mul_add(th, e.kappa * (pi - e.pi0));
            // L̂ in the working frame (`Elliptic::l_hat_w`) and its Euler angles (`euler_tilt`).
            let l = [e.sorted[0] * w[0], e.sorted[1] * w[1], e.sorted[2] * w[2]];
            let lw = [l[e.w_axes[0]], l[e.w_axes[1]], l[e.w_axes[2]]];
            let norm = (lw[0] * lw[0] + lw[1] * lw[1] + lw[2] * lw[2]).sqrt();
            let l = [lw[0] / norm, lw[1] / norm, lw[2] / norm];
            let c = euler_tilt_lanes(&l);
            // q = q_pre ⊗ R_z(φ) ⊗ C ⊗ q_post, normalised.
            let (sh, ch) = sin_cos(0.5 * phi);
            let q = hamilton_lanes(
                &hamilton_lanes(&q_pre, &[ch, zero, zero, sh]),
                &hamilton_lanes(&c, &q_post),
            );
            let q = normalized_lanes(&q);
            for l in 0..len {
                w_out[l] = from.map(|(j, sign)| sign * w[j].lanes()[l] * s_w);
                q_out[l] = [
                    q[0].lanes()[l],
                    q[1].lanes()[l],
                    q[2].lanes()[l],
                    q[3].lanes()[l],
                ];
            }
        }
    }
}

/// Below this the squares in √(x² + y²) could lose digits: [`euler_tilt_lanes`] takes the
/// standard library's `hypot` for such lanes.
const HYPOT_FAST_MIN: f64 = 1e-150;

/// `euler_tilt` on lanes: the rotation C with third row `l` (unit vectors).
#[inline(always)]
fn euler_tilt_lanes<S: Simd>(l: &[F64s<S>; 3]) -> QuatLanes<S> {
    let [lx, ly, lz] = *l;
    let mut rho = (lx * lx + ly * ly).sqrt();
    let small = lx
        .abs()
        .lt(lx.splat_like(HYPOT_FAST_MIN))
        .and(ly.abs().lt(lx.splat_like(HYPOT_FAST_MIN)));
    if small.any() {
        for i in 0..F64s::<S>::LANES {
            if small.get(i) {
                rho.lanes_mut()[i] = lx.lanes()[i].hypot(ly.lanes()[i]);
            }
        }
    }
    let (a, b) = (ly / rho, lx / rho);
    let zero = lx.splat_like(0.0);
    matrix_to_quaternion_lanes(&[a, -b, zero, lz * b, lz * a, -rho, lx, ly, lz])
}

#[cfg(test)]
mod tests {
    use super::super::{Motion, Reduced};
    use super::*;
    use crate::Vec3;

    /// Π(n; am r | m) by the Fourier series against Carlson's form (`Elliptic::pi_of`) on
    /// |r| ≤ K, for motions about either extreme axis, small and large m, and |n| from small to
    /// the series' limit; a series cut to half its terms is seen (negative control).
    #[test]
    fn the_series_of_pi_equals_carlsons_form() {
        let cases = [
            ([1.0, 2.0, 3.0], [1.0, 0.1, 1.0]),
            ([1.0, 2.0, 3.0], [1.0, 0.3, 0.1]),
            ([1.0, 1.1, 1.9], [0.01, 0.2, 1.0]),
            ([0.3, 1.7, 1.9], [1.0, -0.5, 0.4]),
            ([2.0, 2.5, 1.0], [0.3, -2.0, 0.2]),
            ([1.0, 1.5, 2.0], [1.0, 1.0, 1.0]),
        ];
        for (moments, w) in cases {
            let body = FreeRigidBody::new(moments, Vec3::from(w), None).unwrap();
            let Motion::Elliptic(e) = &body.motion else {
                panic!("{moments:?} {w:?} is not elliptic")
            };
            let series = PiSeries::new(e).expect("the series converges");
            let k = e.jacobi.quarter_period();
            let mut worst: f64 = 0.0;
            let mut worst_cut: f64 = 0.0;
            let mut cut = series.clone();
            cut.b.truncate(series.b.len() / 2);
            for i in 0..=400 {
                let r = -k + 2.0 * k * i as f64 / 400.0;
                let v = e.jacobi.eval_reduced(r);
                let red = Reduced {
                    j: 0.0,
                    sn: v.sn,
                    cn: v.cn,
                    dn: v.dn,
                };
                let want = e.pi_of(r, red);
                let scale = e.pi_complete.abs().max(1.0);
                worst = worst.max((series.eval_one(r) - want).abs() / scale);
                worst_cut = worst_cut.max((cut.eval_one(r) - want).abs() / scale);
            }
            assert!(worst <= 4e-15, "{moments:?} {w:?}: {worst:e}");
            assert!(worst_cut > 1e-13, "{moments:?} {w:?}: {worst_cut:e}");
        }
    }
}
