//! Many bodies at once: the same integration for arrays of moments and initial states, in
//! parallel with rayon.
//!
//! The fixed-step methods (RK4, the splittings) run on SIMD lanes ([`super::lanes`]): bodies
//! in groups of lanes in structure-of-arrays form, blocks of groups spread over the cores. The
//! exact flow and DOP853 (adaptive, a different step sequence per body) run body by body.

use rayon::prelude::*;

use super::equations::{angular_acceleration_principal, quaternion_rate};
use super::lanes::{
    free_steps_lanes, kicked_steps_lanes, rk4_lanes, SplitLanes, StateLanes, TorqueLanes,
};
use super::simulate::{default_step_of, Method, SimulateOptions};
use super::torque::{Torque, TorqueContext, TorqueModel};
use std::sync::Arc;

use crate::analytic::FreeRigidBody;
use crate::control::{self, Cancel};
use crate::error::{Error, Result};
use crate::integrate::{composition_coefficients, dop853, Options};
use crate::limits::check_steps;
use crate::rotation::{normalized, quaternion_to_mat3_unchecked, Quaternion};
use crate::rows::{check_every_row, check_row, check_row_counts, in_body, IDENTITY};
use crate::simd::{self, F64s, Simd, WithSimd, MAX_LANES};
use crate::Vec3;

/// The final states of a batch: ω (body, rad/s) and attitude (`[w, x, y, z]`) per body.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct BatchResult {
    /// Final body angular velocities.
    pub omega: Vec<[f64; 3]>,
    /// Final attitudes (unit quaternions, body → space).
    pub attitude: Vec<Quaternion>,
    /// Steps per body (fixed-step methods), 0 for the exact flow.
    pub steps: usize,
}

/// Integrates `moments.len()` bodies (principal moments, body axes principal) from `omega0`
/// and `attitude0` (identity if `None`) over `duration` under the same `torque` (evaluated with
/// each body's own inertia), with `opts.method`, the fixed step `opts.dt` (`None`: each body's
/// [`super::default_step`]) and DOP853's `opts.rtol`/`opts.atol` (`opts.samples` is not used: only
/// the final states are returned), in parallel.
///
/// RK4 and the splittings run on SIMD lanes, a group of bodies per vector instruction (8
/// with AVX2), the groups in parallel (`dynamics/lanes.rs`): RK4 gives the numbers of
/// [`super::simulate()`] for each body bit for bit, the splittings the same to a relative 1e-16
/// per step (their rotations' sines and cosines are vectorized). The exact flow and DOP853 run
/// body by body. Every built-in [`Torque`] runs on the lanes; a torque given as a function (a
/// [`TorqueModel`] of a front end, a Python callable) is not taken here: integrate such bodies
/// one by one with [`super::simulate()`].
///
/// Every body may take at most `opts.max_steps` steps (checked for every body before the first
/// step of any for the fixed-step methods; DOP853 stops there). The run can be stopped through
/// [`crate::control`] (a monitor on the calling thread), also while the workers run; progress
/// is the fraction of the bodies done.
///
/// Errors name `moments`, `omega0` or `attitude0` with the row at fault, `duration`, `dt`,
/// `max_steps` or `method`, and the first body (lowest index) at fault: its start (`omega0`,
/// `torque` overflowing) or its steps (`max_steps`); a diverging body stops everything with
/// [`crate::ErrorKind::Diverged`] naming its row.
pub fn simulate_batch(
    moments: &[[f64; 3]],
    omega0: &[[f64; 3]],
    attitude0: Option<&[Quaternion]>,
    duration: f64,
    torque: &Torque,
    opts: &SimulateOptions,
) -> Result<BatchResult> {
    let SimulateOptions {
        method,
        dt,
        max_steps,
        rtol,
        atol,
        ..
    } = *opts;
    let n = moments.len();
    check_row_counts(n, omega0.len(), attitude0.map(<[Quaternion]>::len))?;
    if !(duration.is_finite() && duration > 0.0) {
        return Err(Error::invalid(
            "duration",
            format!("must be finite and > 0, got {duration}"),
        ));
    }
    if let Some(h) = dt {
        if !(h.is_finite() && h > 0.0) {
            return Err(Error::invalid(
                "dt",
                format!("must be finite and > 0, got {}", crate::error::num(h)),
            ));
        }
        if method.is_fixed_step() {
            check_steps(
                (duration / h).ceil(),
                max_steps,
                &format!(
                    "take a larger dt (now {} s) or a shorter duration",
                    crate::error::num(h)
                ),
            )?;
        }
    }
    if max_steps == 0 {
        return Err(Error::invalid("max_steps", "must be >= 1, got 0"));
    }
    torque.validate()?;
    let method = match method {
        Method::Auto if torque.is_zero() => Method::Exact,
        Method::Auto => Method::Dop853,
        Method::Exact if !torque.is_zero() => {
            return Err(Error::invalid(
                "method",
                "'exact' solves the torque-free body only",
            ));
        }
        Method::Splitting(k) => {
            composition_coefficients(usize::from(k))
                .map_err(|e| Error::invalid("method", e.message))?;
            method
        }
        m => m,
    };
    // Validate every row first (in parallel), naming the first row at fault; then the unit
    // attitudes.
    check_every_row(moments, omega0, attitude0)?;
    let q0: Option<Vec<Quaternion>> = attitude0.map(|_| {
        (0..n)
            .into_par_iter()
            .with_min_len(BLOCK)
            .map(|i| check_row(moments, omega0, attitude0, i).unwrap_or(IDENTITY))
            .collect()
    });
    let q0 = Attitudes(q0.as_deref());
    if let Method::Rk4 | Method::Splitting(_) = method {
        return lanes_batch(moments, omega0, q0, duration, torque, method, dt, max_steps);
    }
    let results: Vec<Result<([f64; 3], Quaternion, usize)>> =
        control::parallel(n as u64, |cancel| {
            Ok((0..n)
                .into_par_iter()
                .with_min_len(256)
                .map(|i| {
                    cancel.check()?;
                    // The worker's own loops (DOP853) poll the shared flag too.
                    let (result, _) = control::watched(Arc::clone(cancel), || {
                        one_body(
                            &moments[i],
                            &omega0[i],
                            &q0.get(i),
                            duration,
                            *torque,
                            method,
                            max_steps,
                            (rtol, atol),
                        )
                    });
                    cancel.advance(1);
                    result.map_err(|e| in_body(i, e))
                })
                .collect())
        })?;
    let mut out = BatchResult {
        omega: Vec::with_capacity(n),
        attitude: Vec::with_capacity(n),
        steps: 0,
    };
    for r in results {
        let (w, q, steps) = r?;
        out.omega.push(w);
        out.attitude.push(q);
        out.steps = out.steps.max(steps);
    }
    Ok(out)
}

/// The bodies' unit attitudes at the start, or the identity for all.
#[derive(Debug, Clone, Copy)]
struct Attitudes<'a>(Option<&'a [Quaternion]>);

impl Attitudes<'_> {
    #[inline(always)]
    fn get(&self, i: usize) -> Quaternion {
        match self.0 {
            Some(q) => q[i],
            None => IDENTITY,
        }
    }
}

/// The torque on a body (principal moments `moments`) at time t, ω and attitude q (not
/// necessarily of unit norm), in principal components, as every path of the batch evaluates it.
fn torque_at(torque: Torque, moments: &[f64; 3], t: f64, w: &Vec3, q: &Quaternion) -> Vec3 {
    let mut model = torque;
    if model.is_zero() {
        return Vec3::zeros();
    }
    let r = if model.depends_on_attitude() {
        quaternion_to_mat3_unchecked(&normalized(q))
    } else {
        crate::Mat3::identity()
    };
    model.torque(&TorqueContext {
        t,
        omega: w,
        attitude: &r,
        inertia: &crate::Mat3::from_diagonal(&Vec3::from(*moments)),
    })
}

/// The start of one body of a fixed-step run: checks that L, T and the torque at the start are
/// finite, and returns the step (s) and the number of steps (the default step if `dt` is
/// `None`; `Δ/ceil(Δ/dt)` otherwise), checked against `max_steps`.
fn fixed_steps(
    moments: &[f64; 3],
    omega0: &[f64; 3],
    q0: &Quaternion,
    duration: f64,
    torque: Torque,
    dt: Option<f64>,
    max_steps: usize,
) -> Result<(f64, usize)> {
    let w0 = Vec3::from(*omega0);
    // The start must be representable: L = I ω and the torque (an overflow is blamed on the
    // argument it comes from, not on the integrator).
    let l0 = Vec3::new(moments[0] * w0.x, moments[1] * w0.y, moments[2] * w0.z);
    if !(l0.iter().all(|x| x.is_finite()) && (0.5 * w0.dot(&l0)).is_finite()) {
        return Err(Error::invalid(
            "omega0",
            "the initial angular momentum or energy overflows",
        ));
    }
    let n0 = torque_at(torque, moments, 0.0, &w0, q0);
    if !n0.iter().all(|x| x.is_finite()) {
        return Err(Error::invalid(
            "torque",
            "the torque at the start overflows",
        ));
    }
    let h = match dt {
        Some(h) => h,
        None => {
            let (lo, hi) = moments
                .iter()
                .fold((f64::INFINITY, 0.0f64), |(lo, hi), &m| {
                    (lo.min(m), hi.max(m))
                });
            default_step_of(hi, lo, w0.norm(), n0.norm(), torque.orbit_rate()).unwrap_or(duration)
        }
    };
    let k = (duration / h).ceil().max(1.0);
    check_steps(k, max_steps, "take a larger dt or a shorter duration")?;
    Ok((duration / k, k as usize))
}

/// Bodies per rayon task: a multiple of every group size (`F64s::<S>::LANES`: 2 to 16).
const BLOCK: usize = 128;

/// The fixed-step methods on SIMD lanes: every body's start and steps checked first (the
/// lowest failing index reported), then blocks of [`BLOCK`] bodies integrated in parallel,
/// each in groups of lanes.
#[allow(clippy::too_many_arguments)]
fn lanes_batch(
    moments: &[[f64; 3]],
    omega0: &[[f64; 3]],
    q0: Attitudes<'_>,
    duration: f64,
    torque: &Torque,
    method: Method,
    dt: Option<f64>,
    max_steps: usize,
) -> Result<BatchResult> {
    let n = moments.len();
    let torque = *torque;
    let gammas: &[f64] = match method {
        Method::Splitting(order) => composition_coefficients(usize::from(order))?,
        _ => &[],
    };
    // Each body's step and number of steps, before any work.
    let mut step = vec![0.0; n];
    let mut count = vec![0.0; n];
    // The first body refused (the lowest index: the same error whatever the threads).
    let first_bad = step
        .par_chunks_mut(BLOCK)
        .zip(count.par_chunks_mut(BLOCK))
        .enumerate()
        .filter_map(|(c, (hs, ks))| {
            for (j, (h, k)) in hs.iter_mut().zip(ks.iter_mut()).enumerate() {
                let i = c * BLOCK + j;
                match fixed_steps(
                    &moments[i],
                    &omega0[i],
                    &q0.get(i),
                    duration,
                    torque,
                    dt,
                    max_steps,
                ) {
                    Ok((hi, ki)) => (*h, *k) = (hi, ki as f64),
                    Err(e) => return Some((i, e)),
                }
            }
            None
        })
        .min_by_key(|(i, _)| *i);
    if let Some((i, e)) = first_bad {
        return Err(in_body(i, e));
    }
    let steps = count.iter().fold(0.0f64, |a, &b| a.max(b)) as usize;
    let mut omega = vec![[0.0; 3]; n];
    let mut attitude = vec![[0.0; 4]; n];
    let diverged = control::parallel(n as u64, |cancel| {
        omega
            .par_chunks_mut(BLOCK)
            .zip(attitude.par_chunks_mut(BLOCK))
            .enumerate()
            .map(|(c, (w_out, q_out))| {
                cancel.check()?;
                let len = w_out.len();
                let bad = simd::dispatch(Block {
                    start: c * BLOCK,
                    moments,
                    omega0,
                    q0,
                    step: &step,
                    count: &count,
                    method,
                    gammas,
                    torque,
                    cancel,
                    w_out,
                    q_out,
                })?;
                cancel.advance(len as u64);
                Ok(bad)
            })
            .try_reduce(|| None, |a, b| Ok(a.into_iter().chain(b).min()))
    })?;
    if let Some(i) = diverged {
        return Err(in_body(
            i,
            Error::diverged("duration", "the state stopped being finite before the end"),
        ));
    }
    Ok(BatchResult {
        omega,
        attitude,
        steps,
    })
}

/// Lanes of column `k` of `rows[first..first + len]`; the lanes past `len` repeat the first
/// row.
#[inline(always)]
fn column<S: Simd, const K: usize>(
    s: S,
    rows: &[[f64; K]],
    first: usize,
    len: usize,
    k: usize,
) -> F64s<S> {
    let mut buf = [0.0; MAX_LANES];
    for (l, b) in buf.iter_mut().enumerate().take(F64s::<S>::LANES) {
        *b = rows[first + if l < len { l } else { 0 }][k];
    }
    F64s::load(s, &buf)
}

/// Lanes of `values[first..first + len]`, then zeros.
#[inline(always)]
fn values<S: Simd>(s: S, values: &[f64], first: usize, len: usize) -> F64s<S> {
    let mut buf = [0.0; MAX_LANES];
    buf[..len].copy_from_slice(&values[first..first + len]);
    F64s::load(s, &buf)
}

/// A block of bodies of a fixed-step batch, from body `start`, integrated into `w_out` and
/// `q_out` (whose length is the block's) in groups of lanes.
struct Block<'a> {
    start: usize,
    moments: &'a [[f64; 3]],
    omega0: &'a [[f64; 3]],
    q0: Attitudes<'a>,
    step: &'a [f64],
    count: &'a [f64],
    method: Method,
    gammas: &'a [f64],
    torque: Torque,
    cancel: &'a Cancel,
    w_out: &'a mut [[f64; 3]],
    q_out: &'a mut [Quaternion],
}

impl WithSimd for Block<'_> {
    /// The first body whose final state is not finite.
    type Output = Result<Option<usize>>;

    #[inline(always)]
    fn with_simd<S: Simd>(mut self, s: S) -> Self::Output {
        let lanes = F64s::<S>::LANES;
        let (w_all, q_all) = (
            std::mem::take(&mut self.w_out),
            std::mem::take(&mut self.q_out),
        );
        let mut bad = None;
        for (g, (w_out, q_out)) in w_all
            .chunks_mut(lanes)
            .zip(q_all.chunks_mut(lanes))
            .enumerate()
        {
            let found = self.group(s, self.start + g * lanes, w_out, q_out)?;
            bad = bad.or(found);
        }
        Ok(bad)
    }
}

impl Block<'_> {
    /// Integrates the group of bodies `first..first + w_out.len()` into `w_out`, `q_out`;
    /// returns the first of them whose final state is not finite.
    #[inline(always)]
    fn group<S: Simd>(
        &self,
        s: S,
        first: usize,
        w_out: &mut [[f64; 3]],
        q_out: &mut [Quaternion],
    ) -> Result<Option<usize>> {
        let len = w_out.len();
        let m = [0, 1, 2].map(|k| column(s, self.moments, first, len, k));
        let w = [0, 1, 2].map(|k| column(s, self.omega0, first, len, k));
        let q = match self.q0.0 {
            Some(rows) => [0, 1, 2, 3].map(|k| column(s, rows, first, len, k)),
            None => IDENTITY.map(|c| F64s::splat(s, c)),
        };
        // The lanes past the group's end take no steps (and are not written out).
        let h = values(s, self.step, first, len);
        let count = values(s, self.count, first, len);
        let free = self.torque.is_zero();
        let torque = TorqueLanes::new(self.torque, m);
        let (w, q) = if self.method == Method::Rk4 {
            let mut y: StateLanes<S> = [w[0], w[1], w[2], q[0], q[1], q[2], q[3]];
            rk4_lanes(&m, &mut y, h, count, &torque, self.cancel)?;
            ([y[0], y[1], y[2]], [y[3], y[4], y[5], y[6]])
        } else {
            let mut state = SplitLanes {
                l: [m[0] * w[0], m[1] * w[1], m[2] * w[2]],
                q,
                t: F64s::splat(s, 0.0),
            };
            if free {
                free_steps_lanes(&mut state, &m, self.gammas, h, count, self.cancel)?;
            } else {
                kicked_steps_lanes(&mut state, &m, self.gammas, h, count, &torque, self.cancel)?;
            }
            let l = state.l;
            ([l[0] / m[0], l[1] / m[1], l[2] / m[2]], state.q)
        };
        let mut bad = None;
        for l in 0..len {
            w_out[l] = std::array::from_fn(|k| w[k].lanes()[l]);
            q_out[l] = std::array::from_fn(|k| q[k].lanes()[l]);
            let finite = w_out[l].iter().chain(&q_out[l]).all(|v| v.is_finite());
            if !finite && bad.is_none() {
                bad = Some(first + l);
            }
        }
        Ok(bad)
    }
}

/// One body by the exact flow or DOP853 (the fixed-step methods run on lanes).
#[allow(clippy::too_many_arguments)]
fn one_body(
    moments: &[f64; 3],
    omega0: &[f64; 3],
    q0: &Quaternion,
    duration: f64,
    torque: Torque,
    method: Method,
    max_steps: usize,
    (rtol, atol): (f64, f64),
) -> Result<([f64; 3], Quaternion, usize)> {
    let w0 = Vec3::from(*omega0);
    // The start must be representable: L = I ω and the torque (an overflow is blamed on the
    // argument it comes from, not on the integrator).
    // The exact flow rescales internally and needs neither.
    let l0 = Vec3::new(moments[0] * w0.x, moments[1] * w0.y, moments[2] * w0.z);
    if method != Method::Exact
        && !(l0.iter().all(|x| x.is_finite()) && (0.5 * w0.dot(&l0)).is_finite())
    {
        return Err(Error::invalid(
            "omega0",
            "the initial angular momentum or energy overflows",
        ));
    }
    if !torque_at(torque, moments, 0.0, &w0, q0)
        .iter()
        .all(|x| x.is_finite())
    {
        return Err(Error::invalid(
            "torque",
            "the torque at the start overflows",
        ));
    }
    match method {
        Method::Exact => {
            if w0.iter().all(|&c| c == 0.0) {
                return Ok((*omega0, *q0, 0));
            }
            let (w, q) = FreeRigidBody::new(*moments, w0, Some(*q0))?
                .state(duration)
                .map_err(|e| e.renamed("t", "duration"))?;
            Ok(([w.x, w.y, w.z], q, 0))
        }
        _ => {
            let y0 = [w0.x, w0.y, w0.z, q0[0], q0[1], q0[2], q0[3]];
            let rhs = |t: f64, y: &[f64; 7], dy: &mut [f64; 7]| {
                let w = Vec3::new(y[0], y[1], y[2]);
                let q = [y[3], y[4], y[5], y[6]];
                let n = torque_at(torque, moments, t, &w, &q);
                let a = angular_acceleration_principal(moments, &w, &n);
                let qd = quaternion_rate(&q, &w);
                *dy = [a.x, a.y, a.z, qd[0], qd[1], qd[2], qd[3]];
            };
            let opts = Options {
                dense: false,
                max_steps,
                ..Options::with_tolerances(rtol, atol)
            };
            // A step that fails (its size below round-off) names the run's `duration`.
            let sol =
                dop853(rhs, 0.0, y0, duration, &opts).map_err(|e| e.renamed("t", "duration"))?;
            let y = sol.y_final();
            let q = normalized(&[y[3], y[4], y[5], y[6]]);
            Ok(([y[0], y[1], y[2]], q, sol.stats.accepted))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Integrates bodies with pulp's scalar code (`scalar`) or the CPU's own instruction set
    /// (through `dispatch`).
    fn run(
        moments: &[[f64; 3]],
        omega0: &[[f64; 3]],
        method: Method,
        torque: Torque,
        scalar: bool,
    ) -> (Vec<[f64; 3]>, Vec<Quaternion>) {
        let n = moments.len();
        let mut step = vec![0.0; n];
        let mut count = vec![0.0; n];
        for i in 0..n {
            let (h, k) = fixed_steps(
                &moments[i],
                &omega0[i],
                &IDENTITY,
                0.7,
                torque,
                None,
                1 << 30,
            )
            .unwrap();
            (step[i], count[i]) = (h, k as f64);
        }
        let gammas = match method {
            Method::Splitting(order) => composition_coefficients(usize::from(order)).unwrap(),
            _ => &[],
        };
        let cancel = Cancel::new(n as u64);
        let mut w = vec![[0.0; 3]; n];
        let mut q = vec![[0.0; 4]; n];
        let block = Block {
            start: 0,
            moments,
            omega0,
            q0: Attitudes(None),
            step: &step,
            count: &count,
            method,
            gammas,
            torque,
            cancel: &cancel,
            w_out: &mut w,
            q_out: &mut q,
        };
        let bad = if scalar {
            block.with_simd(pulp::Scalar)
        } else {
            simd::dispatch(block)
        };
        assert_eq!(bad.unwrap(), None);
        (w, q)
    }

    /// The same bits with pulp's scalar code as with this CPU's vector instructions (AVX2 on
    /// x86-64-v3): no fused multiply-add, the same operations in every lane.
    #[test]
    fn the_instruction_set_does_not_change_a_bit() {
        let moments: Vec<[f64; 3]> = (0..37).map(|i| [1.0, 1.3 + 0.02 * i as f64, 2.0]).collect();
        let omega: Vec<[f64; 3]> = (0..37)
            .map(|i| [0.3 + 0.01 * i as f64, -1.1, 0.8 + 0.05 * (i % 5) as f64])
            .collect();
        for method in [Method::Rk4, Method::Splitting(4)] {
            for torque in [Torque::None, Torque::GravityGradient { mean_motion: 0.9 }] {
                let wide = run(&moments, &omega, method, torque, false);
                let scalar = run(&moments, &omega, method, torque, true);
                assert_eq!(wide, scalar, "{method:?} {torque:?}");
            }
        }
    }
}
