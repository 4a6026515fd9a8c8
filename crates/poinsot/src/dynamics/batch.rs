//! Many bodies at once: the same integration for arrays of moments and initial states,
//! in parallel with rayon (one body per task, bodies in chunks).

use rayon::prelude::*;

use super::equations::{angular_acceleration_principal, quaternion_rate, RigidRhs};
use super::model::BodyInertia;
use super::simulate::{default_step, Method, SimulateOptions};
use super::splitting::{free_steps, kicked_step, SplitState};
use super::torque::{Torque, TorqueContext, TorqueModel};
use std::sync::Arc;

use crate::analytic::{check_moments, FreeRigidBody};
use crate::control;
use crate::error::{Error, Result};
use crate::integrate::{composition_coefficients, dop853, Options};
use crate::limits::check_steps;
use crate::rotation::{check_quaternion, normalized, quaternion_to_mat3_unchecked, Quaternion};
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
/// [`default_step`]) and DOP853's `opts.rtol`/`opts.atol` (`opts.samples` is not used: only
/// the final states are returned), in parallel.
///
/// Every body may take at most `opts.max_steps` steps (checked before the first step for the
/// fixed-step methods; DOP853 stops there). The run can be stopped through
/// [`crate::control`] (a monitor on the calling thread), also while the workers run.
///
/// Errors name `moments`, `omega0` or `attitude0` with the row at fault, `duration`, `dt`,
/// `max_steps` or `method`; a diverging body stops everything with
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
    if omega0.len() != n {
        return Err(Error::invalid(
            "omega0",
            format!(
                "must have as many rows as moments ({n}), got {}",
                omega0.len()
            ),
        ));
    }
    if let Some(a) = attitude0 {
        if a.len() != n {
            return Err(Error::invalid(
                "attitude0",
                format!("must have as many rows as moments ({n}), got {}", a.len()),
            ));
        }
    }
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
    // Validate every row first (cheap), naming the row.
    let mut q0 = Vec::with_capacity(n);
    for i in 0..n {
        check_moments(&moments[i])
            .map_err(|e| Error::new(e.kind, "moments", format!("row {i}: {}", e.message)))?;
        if !omega0[i].iter().all(|v| v.is_finite()) {
            return Err(Error::invalid(
                "omega0",
                format!("must be finite, got {:?} at row {i}", omega0[i]),
            ));
        }
        q0.push(match attitude0 {
            Some(a) => check_quaternion("attitude0", &a[i], false)
                .map_err(|e| Error::new(e.kind, "attitude0", format!("row {i}: {}", e.message)))?,
            None => [1.0, 0.0, 0.0, 0.0],
        });
    }
    let q0 = &q0;
    let results: Vec<Result<([f64; 3], Quaternion, usize)>> =
        control::parallel(n as u64, |cancel| {
            Ok((0..n)
                .into_par_iter()
                .with_min_len(256)
                .map(|i| {
                    cancel.check()?;
                    // The worker's own loops (DOP853, RK4) poll the shared flag too.
                    let (result, _) = control::watched(Arc::clone(cancel), || {
                        one_body(
                            &moments[i],
                            &omega0[i],
                            &q0[i],
                            duration,
                            *torque,
                            method,
                            dt,
                            max_steps,
                            (rtol, atol),
                        )
                    });
                    cancel.advance(1);
                    result.map_err(|e| {
                        Error::new(e.kind, e.argument, format!("body {i}: {}", e.message))
                    })
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

#[allow(clippy::too_many_arguments)]
fn one_body(
    moments: &[f64; 3],
    omega0: &[f64; 3],
    q0: &Quaternion,
    duration: f64,
    torque: Torque,
    method: Method,
    dt: Option<f64>,
    max_steps: usize,
    (rtol, atol): (f64, f64),
) -> Result<([f64; 3], Quaternion, usize)> {
    let w0 = Vec3::from(*omega0);
    let inertia_t = crate::Mat3::from_diagonal(&Vec3::from(*moments));
    let torque_at = move |t: f64, w: &Vec3, q: &Quaternion| -> Vec3 {
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
            inertia: &inertia_t,
        })
    };
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
    if !torque_at(0.0, &w0, q0).iter().all(|x| x.is_finite()) {
        return Err(Error::invalid(
            "torque",
            "the torque at the start overflows",
        ));
    }
    let steps_for = |torque_norm: f64| -> Result<(usize, f64)> {
        let inertia = BodyInertia::from_moments(*moments)?;
        let h = dt
            .or_else(|| default_step(&inertia, &w0, torque_norm, torque.orbit_rate()))
            .unwrap_or(duration);
        let k = (duration / h).ceil().max(1.0);
        check_steps(k, max_steps, "take a larger dt or a shorter duration")?;
        let k = k as usize;
        Ok((k, duration / k as f64))
    };
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
        Method::Rk4 => {
            let (k, h) = steps_for(torque_at(0.0, &w0, q0).norm())?;
            let mut y = [w0.x, w0.y, w0.z, q0[0], q0[1], q0[2], q0[3]];
            let rigid = RigidRhs::new(moments);
            if torque.is_zero() {
                let mut none = |_t: f64, _w: &Vec3, _q: &Quaternion| Vec3::zeros();
                for s in 0..k {
                    control::tick()?;
                    y = rigid.rk4_step(h * s as f64, &y, h, &mut none);
                }
            } else {
                let mut model = |t: f64, w: &Vec3, q: &Quaternion| torque_at(t, w, q);
                for s in 0..k {
                    control::tick()?;
                    y = rigid.rk4_step(h * s as f64, &y, h, &mut model);
                }
            }
            if !y.iter().all(|v| v.is_finite()) {
                return Err(Error::diverged(
                    "t",
                    "the state stopped being finite before the end",
                ));
            }
            Ok(([y[0], y[1], y[2]], [y[3], y[4], y[5], y[6]], k))
        }
        Method::Splitting(order) => {
            let gammas = composition_coefficients(usize::from(order))?;
            let (k, h) = steps_for(torque_at(0.0, &w0, q0).norm())?;
            let mut state = SplitState {
                l: Vec3::new(moments[0] * w0.x, moments[1] * w0.y, moments[2] * w0.z),
                q: *q0,
                t: 0.0,
            };
            if torque.is_zero() {
                let mut left = k;
                while left > 0 {
                    let chunk = left.min(4096);
                    free_steps(&mut state, moments, gammas, h, chunk);
                    left -= chunk;
                    control::tick_by(chunk as u32)?;
                }
            } else {
                let mut kick = |s: &mut SplitState, dt: f64| {
                    let w = Vec3::new(s.l.x / moments[0], s.l.y / moments[1], s.l.z / moments[2]);
                    s.l += dt * torque_at(s.t, &w, &s.q);
                };
                for _ in 0..k {
                    control::tick()?;
                    kicked_step(&mut state, moments, gammas, h, &mut kick);
                }
            }
            let w = [
                state.l.x / moments[0],
                state.l.y / moments[1],
                state.l.z / moments[2],
            ];
            if !(w.iter().all(|v| v.is_finite()) && state.q.iter().all(|v| v.is_finite())) {
                return Err(Error::diverged(
                    "t",
                    "the state stopped being finite before the end",
                ));
            }
            Ok((w, state.q, k))
        }
        Method::Dop853 | Method::Auto => {
            let y0 = [w0.x, w0.y, w0.z, q0[0], q0[1], q0[2], q0[3]];
            let rhs = |t: f64, y: &[f64; 7], dy: &mut [f64; 7]| {
                let w = Vec3::new(y[0], y[1], y[2]);
                let q = [y[3], y[4], y[5], y[6]];
                let a = angular_acceleration_principal(moments, &w, &torque_at(t, &w, &q));
                let qd = quaternion_rate(&q, &w);
                *dy = [a.x, a.y, a.z, qd[0], qd[1], qd[2], qd[3]];
            };
            let opts = Options {
                dense: false,
                max_steps,
                ..Options::with_tolerances(rtol, atol)
            };
            let sol = dop853(rhs, 0.0, y0, duration, &opts)?;
            let y = sol.y_final();
            let q = normalized(&[y[3], y[4], y[5], y[6]]);
            Ok(([y[0], y[1], y[2]], q, sol.stats.accepted))
        }
    }
}
