//! The adaptive Dormand–Prince 8(5,3) integrator (DOP853) with dense output and events.
//!
//! Step-size control, error norm and initial step follow Hairer's DOP853 as implemented in
//! `scipy.integrate.solve_ivp(method="DOP853")`: the local error is measured by the 5th- and
//! 3rd-order embedded estimates combined as `|h|·‖e5‖² / sqrt(n (‖e5‖² + 0.01 ‖e3‖²))`
//! in the RMS norm scaled by `atol + rtol·max(|y|, |y_new|)`, and the step is scaled by
//! `0.9 · err^(−1/8)` within [0.2, 10].
// Index loops mirror the Butcher-tableau formulas they implement.
#![allow(clippy::needless_range_loop)]

use super::dop853_coefficients::{A, C, D, E3_SHIFT, E5, INTERPOLATOR_POWER, N_STAGES, N_STAGES_EXTENDED};
use super::options::{Crossing, Options, Stats};
use super::solution::{DenseStep, EventHit, Solution};
use super::state::{OdeState, OdeSystem};
use crate::error::{Error, Result};

const SAFETY: f64 = 0.9;
const MIN_FACTOR: f64 = 0.2;
const MAX_FACTOR: f64 = 10.0;
/// Order of the error estimator (the error of a step scales as h^8).
const ERROR_ESTIMATOR_ORDER: i32 = 7;

/// A DOP853 integrator advancing one accepted step at a time.
///
/// Use [`dop853`] or [`dop853_until`] for a whole solution; use the stepper directly to
/// report progress or to stop on a condition of your own.
pub struct Dop853<S: OdeState, F: OdeSystem<S>> {
    system: F,
    opts: Options,
    t: f64,
    y: S,
    t_end: f64,
    direction: f64,
    h_abs: f64,
    step_rejected_last: bool,
    t_old: f64,
    y_old: S,
    h_prev: f64,
    /// Stages k_0..k_15 (k_12 = f(t_new, y_new), k_13..k_15 the dense-output stages).
    k: [S; N_STAGES_EXTENDED],
    tmp: S,
    y_new: S,
    dense_ready: bool,
    /// k[12] holds f at the new point; it becomes k[0] when the next step starts (FSAL).
    fsal_pending: bool,
    stats: Stats,
}

impl<S: OdeState, F: OdeSystem<S>> Dop853<S, F> {
    /// Prepares the integration of `dy/dt = system(t, y)` from `(t0, y0)` towards `t_end`
    /// (which may lie before `t0`). Errors name `t0`, `t_end`, `y0` or an option.
    pub fn new(mut system: F, t0: f64, y0: S, t_end: f64, opts: &Options) -> Result<Self> {
        opts.validate()?;
        crate::error::check_finite("t0", &[t0])?;
        crate::error::check_finite("t_end", &[t_end])?;
        crate::error::check_finite("y0", y0.as_slice())?;
        let direction = if t_end >= t0 { 1.0 } else { -1.0 };
        let mut f0 = y0.clone();
        system.rhs(t0, &y0, &mut f0);
        if f0.as_slice().iter().any(|v| !v.is_finite()) {
            return Err(Error::diverged("t", format!("the right-hand side is not finite at t = {t0} (the initial point)")));
        }
        let mut k: [S; N_STAGES_EXTENDED] = std::array::from_fn(|_| y0.clone());
        k[0] = f0;
        let mut me = Self {
            system,
            opts: *opts,
            t: t0,
            y: y0.clone(),
            t_end,
            direction,
            h_abs: 0.0,
            step_rejected_last: false,
            t_old: t0,
            y_old: y0.clone(),
            h_prev: 0.0,
            k,
            tmp: y0.clone(),
            y_new: y0,
            dense_ready: false,
            fsal_pending: false,
            stats: Stats { evaluations: 1, ..Stats::default() },
        };
        me.h_abs = match opts.first_step {
            Some(h) => h.min((t_end - t0).abs()),
            None => me.initial_step(),
        };
        Ok(me)
    }

    /// The current time (the end of the last accepted step).
    pub fn t(&self) -> f64 {
        self.t
    }
    /// The current state.
    pub fn y(&self) -> &S {
        &self.y
    }
    /// The start of the last accepted step.
    pub fn t_old(&self) -> f64 {
        self.t_old
    }
    /// Work done so far.
    pub fn stats(&self) -> Stats {
        self.stats
    }
    /// Whether `t_end` has been reached.
    pub fn is_finished(&self) -> bool {
        self.t == self.t_end
    }

    /// Hairer's starting step (Solving ODEs I, §II.4).
    fn initial_step(&mut self) -> f64 {
        let interval = (self.t_end - self.t).abs();
        if interval == 0.0 {
            return 0.0;
        }
        let n = self.y.as_slice().len();
        if n == 0 {
            return interval;
        }
        let (rtol, atol) = (self.opts.rtol, self.opts.atol);
        let y0 = self.y.as_slice();
        let f0 = self.k[0].as_slice();
        let (mut s0, mut s1) = (0.0, 0.0);
        for i in 0..n {
            let scale = atol + y0[i].abs() * rtol;
            s0 += (y0[i] / scale).powi(2);
            s1 += (f0[i] / scale).powi(2);
        }
        let (d0, d1) = ((s0 / n as f64).sqrt(), (s1 / n as f64).sqrt());
        let mut h0 = if d0 < 1e-5 || d1 < 1e-5 { 1e-6 } else { 0.01 * d0 / d1 };
        h0 = h0.min(interval);
        {
            let y1 = self.tmp.as_mut_slice();
            for i in 0..n {
                y1[i] = y0[i] + h0 * self.direction * f0[i];
            }
        }
        let mut f1 = self.y.clone();
        self.system.rhs(self.t + h0 * self.direction, &self.tmp, &mut f1);
        self.stats.evaluations += 1;
        let mut s2 = 0.0;
        for i in 0..n {
            let scale = atol + y0[i].abs() * rtol;
            s2 += ((f1.as_slice()[i] - f0[i]) / scale).powi(2);
        }
        let d2 = (s2 / n as f64).sqrt() / h0;
        let h1 = if d1 <= 1e-15 && d2 <= 1e-15 || !d2.is_finite() {
            (h0 * 1e-3).max(1e-6)
        } else {
            (0.01 / d1.max(d2)).powf(1.0 / f64::from(ERROR_ESTIMATOR_ORDER + 1))
        };
        (100.0 * h0).min(h1).min(interval).min(self.opts.max_step)
    }

    /// One Runge–Kutta step of size `h` from `(t, y)` with `k[0] = f(t, y)` given; writes
    /// the 8th-order solution into `y_new` and `f(t + h, y_new)` into `k[12]`.
    fn rk_step(system: &mut F, t: f64, y: &S, h: f64, k: &mut [S], tmp: &mut S, y_new: &mut S) {
        let n = y.as_slice().len();
        for s in 1..=N_STAGES {
            {
                let (done, _) = k.split_at(s);
                let out = if s < N_STAGES { tmp.as_mut_slice() } else { y_new.as_mut_slice() };
                let out = &mut out[..n];
                out.copy_from_slice(y.as_slice());
                // out = y + h Σ_j a_sj k_j, column by column (skipping the tableau's zeros) so
                // that the inner loop runs over the state and vectorises.
                for (j, kj) in done.iter().enumerate() {
                    let a = A[s][j];
                    if a != 0.0 {
                        let ha = h * a;
                        for (o, kv) in out.iter_mut().zip(&kj.as_slice()[..n]) {
                            *o += ha * kv;
                        }
                    }
                }
            }
            let (_, tail) = k.split_at_mut(s);
            if s < N_STAGES {
                system.rhs(t + C[s] * h, tmp, &mut tail[0]);
            } else {
                system.rhs(t + h, y_new, &mut tail[0]);
            }
        }
    }

    /// The error norm of the step just taken (< 1: accept).
    fn error_norm(&self, h: f64) -> f64 {
        let n = self.y.as_slice().len();
        let (rtol, atol) = (self.opts.rtol, self.opts.atol);
        // e5 = Σ_j E5_j k_j and e3 = Σ_j E3_j k_j with E3 = b − shifts (b_12 = 0 for the FSAL stage).
        let mut e5 = self.tmp.clone();
        let mut e3 = self.tmp.clone();
        let (e5s, e3s) = (e5.as_mut_slice(), e3.as_mut_slice());
        e5s.fill(0.0);
        e3s.fill(0.0);
        for j in 0..=N_STAGES {
            let kj = &self.k[j].as_slice()[..n];
            let c5 = E5[j];
            let mut c3 = if j < N_STAGES { A[N_STAGES][j] } else { 0.0 };
            for &(js, v) in &E3_SHIFT {
                if js == j {
                    c3 -= v;
                }
            }
            for i in 0..n {
                e5s[i] += c5 * kj[i];
                e3s[i] += c3 * kj[i];
            }
        }
        let (mut e5n, mut e3n) = (0.0, 0.0);
        let (y, yn) = (self.y.as_slice(), self.y_new.as_slice());
        for i in 0..n {
            let scale = atol + y[i].abs().max(yn[i].abs()) * rtol;
            e5n += (e5s[i] / scale).powi(2);
            e3n += (e3s[i] / scale).powi(2);
        }
        if e5n == 0.0 && e3n == 0.0 {
            return 0.0;
        }
        let denom = e5n + 0.01 * e3n;
        h.abs() * e5n / (denom * n as f64).sqrt()
    }

    /// Advances by one accepted step (several attempts if the error is too large).
    ///
    /// Errors: [`crate::ErrorKind::Diverged`] naming `t` (with the time) if the step size
    /// underflows or the right-hand side stops being finite, or naming `max_steps`.
    pub fn step(&mut self) -> Result<()> {
        if self.is_finished() {
            return Ok(());
        }
        if self.fsal_pending {
            let (head, tail) = self.k.split_at_mut(N_STAGES);
            head[0].as_mut_slice().copy_from_slice(tail[0].as_slice());
            self.fsal_pending = false;
        }
        let t = self.t;
        let min_step = 10.0 * (next_toward(t, self.direction) - t).abs();
        let mut h_abs = self.h_abs.min(self.opts.max_step).max(min_step);
        let mut rejected_now = false;
        let mut nonfinite = false;
        loop {
            if self.stats.accepted + self.stats.rejected >= self.opts.max_steps {
                return Err(Error::diverged(
                    "max_steps",
                    format!("reached {} steps at t = {t} before t_end = {}: raise max_steps or loosen rtol/atol", self.opts.max_steps, self.t_end),
                ));
            }
            if h_abs < min_step {
                let why = if nonfinite { "the right-hand side is not finite" } else { "the error cannot be controlled" };
                return Err(Error::diverged(
                    "t",
                    format!("integration failed at t = {t}: the step size fell below {min_step:e} ({why}; the solution may blow up there)"),
                ));
            }
            let mut h = h_abs * self.direction;
            let mut t_new = t + h;
            if self.direction * (t_new - self.t_end) > 0.0 {
                t_new = self.t_end;
            }
            h = t_new - t;
            h_abs = h.abs();
            Self::rk_step(&mut self.system, t, &self.y, h, &mut self.k[..], &mut self.tmp, &mut self.y_new);
            self.stats.evaluations += N_STAGES;
            let finite = self.y_new.as_slice().iter().all(|v| v.is_finite())
                && self.k[..=N_STAGES].iter().all(|kj| kj.as_slice().iter().all(|v| v.is_finite()));
            let err = if finite { self.error_norm(h) } else { f64::INFINITY };
            if !(err.is_finite()) {
                nonfinite = !finite;
                self.stats.rejected += 1;
                h_abs *= MIN_FACTOR;
                rejected_now = true;
                continue;
            }
            if err < 1.0 {
                let mut factor = if err == 0.0 {
                    MAX_FACTOR
                } else {
                    MAX_FACTOR.min(SAFETY * inv_eighth_root(err))
                };
                if rejected_now {
                    factor = factor.min(1.0);
                }
                self.h_abs = h_abs * factor;
                self.step_rejected_last = rejected_now;
                // Accept: shift the state, keep k (k[0] = f_old, k[12] = f_new) for dense output.
                std::mem::swap(&mut self.y_old, &mut self.y);
                std::mem::swap(&mut self.y, &mut self.y_new);
                self.t_old = t;
                self.t = t_new;
                self.h_prev = h;
                self.dense_ready = false;
                self.fsal_pending = true;
                self.stats.accepted += 1;
                return Ok(());
            }
            self.stats.rejected += 1;
            h_abs *= MIN_FACTOR.max(SAFETY * inv_eighth_root(err));
            rejected_now = true;
        }
    }

    /// The dense output of the last accepted step (three more evaluations, once per step).
    /// Call it before the next [`Dop853::step`].
    pub fn dense_step(&mut self) -> DenseStep {
        let n = self.y.as_slice().len();
        let h = self.h_prev;
        if !self.dense_ready {
            for s in (N_STAGES + 1)..N_STAGES_EXTENDED {
                {
                    let ys = self.y_old.as_slice();
                    let out = self.tmp.as_mut_slice();
                    for i in 0..n {
                        let mut acc = 0.0;
                        for j in 0..s {
                            acc += A[s][j] * self.k[j].as_slice()[i];
                        }
                        out[i] = ys[i] + h * acc;
                    }
                }
                let (_, tail) = self.k.split_at_mut(s);
                self.system.rhs(self.t_old + C[s] * h, &self.tmp, &mut tail[0]);
                self.stats.evaluations += 1;
            }
            self.dense_ready = true;
        }
        let mut coeffs = vec![0.0; INTERPOLATOR_POWER * n];
        let (yo, yn) = (self.y_old.as_slice(), self.y.as_slice());
        let (f_old, f_new) = (self.k[0].as_slice(), self.k[N_STAGES].as_slice());
        for i in 0..n {
            let dy = yn[i] - yo[i];
            coeffs[i] = dy;
            coeffs[n + i] = h * f_old[i] - dy;
            coeffs[2 * n + i] = 2.0 * dy - h * (f_new[i] + f_old[i]);
            for (r, drow) in D.iter().enumerate() {
                let mut acc = 0.0;
                for (j, kj) in self.k.iter().enumerate() {
                    acc += drow[j] * kj.as_slice()[i];
                }
                coeffs[(3 + r) * n + i] = h * acc;
            }
        }
        DenseStep::new(self.t_old, h, yo.to_vec(), coeffs)
    }

    /// The state at `t` inside the last accepted step, by one full Runge–Kutta step from
    /// its start (8th order, unlike the 7th-order interpolant).
    fn state_by_step(&mut self, t: f64) -> S {
        let h = t - self.t_old;
        let mut k = self.k.clone();
        let mut tmp = self.tmp.clone();
        let mut out = self.y_old.clone();
        if h != 0.0 {
            Self::rk_step(&mut self.system, self.t_old, &self.y_old, h, &mut k[..], &mut tmp, &mut out);
            self.stats.evaluations += N_STAGES;
        }
        out
    }
}

/// err^(−1/8) (the step-size exponent −1/(order + 1) for the 7th-order estimator) by three
/// square roots, cheaper than `powf`.
#[inline]
fn inv_eighth_root(err: f64) -> f64 {
    const _: () = assert!(ERROR_ESTIMATOR_ORDER == 7);
    1.0 / err.sqrt().sqrt().sqrt()
}

/// The next float after `t` in `direction` (±1).
fn next_toward(t: f64, direction: f64) -> f64 {
    if t.is_nan() {
        return t;
    }
    let bits = t.to_bits();
    let up = direction > 0.0;
    if t == 0.0 {
        let tiny = f64::from_bits(1);
        return if up { tiny } else { -tiny };
    }
    let away_from_zero = (t > 0.0) == up;
    f64::from_bits(if away_from_zero { bits + 1 } else { bits - 1 })
}

/// Integrates `dy/dt = system(t, y)` from `(t0, y0)` to `t_end` with DOP853.
///
/// Returns every accepted step and (with `opts.dense`) their dense output. Errors name the
/// argument at fault (`t0`, `t_end`, `y0`, `rtol`, `atol`, `max_steps`, ...) or, for a
/// failing integration, `t` with the time where it failed (kind `Diverged`).
///
/// ```
/// use poinsot::integrate::{dop853, Options};
/// // y' = −y, y(0) = 1 → y(1) = 1/e
/// let sol = dop853(|_t: f64, y: &[f64; 1], dy: &mut [f64; 1]| dy[0] = -y[0], 0.0, [1.0], 1.0,
///                  &Options::with_tolerances(1e-12, 1e-14)).unwrap();
/// assert!((sol.y_final()[0] - (-1.0f64).exp()).abs() < 1e-12);
/// ```
pub fn dop853<S, F>(system: F, t0: f64, y0: S, t_end: f64, opts: &Options) -> Result<Solution<S>>
where
    S: OdeState,
    F: OdeSystem<S>,
{
    dop853_until(system, t0, y0, t_end, opts, |_t: f64, _y: &S| 1.0, Crossing::Any)
}

/// Like [`dop853`], but stops at the first zero crossing of `event(t, y)` of the kind
/// `crossing` (a terminal event), reported in [`Solution::event`].
///
/// The crossing time is found on the dense output by the Illinois method to a few ulp; the
/// state there is then recomputed by a full step from the start of the step. A start exactly
/// on zero (`event(t0, y0) == 0`) is not a crossing.
pub fn dop853_until<S, F, G>(
    system: F,
    t0: f64,
    y0: S,
    t_end: f64,
    opts: &Options,
    mut event: G,
    crossing: Crossing,
) -> Result<Solution<S>>
where
    S: OdeState,
    F: OdeSystem<S>,
    G: FnMut(f64, &S) -> f64,
{
    let mut stepper = Dop853::new(system, t0, y0.clone(), t_end, opts)?;
    let mut sol = Solution::new(t0, y0.clone());
    let mut g_old = event(t0, &y0);
    while !stepper.is_finished() {
        stepper.step()?;
        let g_new = event(stepper.t, &stepper.y);
        let hit = crossing.detects(g_old, g_new) && g_old != 0.0;
        if opts.dense || hit {
            let dense = stepper.dense_step();
            if hit {
                let t_hit = find_root(&dense, &mut event, stepper.t_old, g_old, stepper.t, g_new, &stepper.y);
                let y_hit = if t_hit == stepper.t { stepper.y.clone() } else { stepper.state_by_step(t_hit) };
                sol.t.push(t_hit);
                sol.y.push(y_hit.clone());
                if opts.dense {
                    sol.dense.push(dense);
                }
                sol.event = Some(EventHit { t: t_hit, y: y_hit });
                sol.stats = stepper.stats();
                return Ok(sol);
            }
            sol.dense.push(dense);
        }
        sol.t.push(stepper.t);
        sol.y.push(stepper.y.clone());
        g_old = g_new;
    }
    sol.stats = stepper.stats();
    Ok(sol)
}

/// The zero of `event(t, interpolant(t))` in the step `[a, b]` (Illinois method).
fn find_root<S: OdeState, G: FnMut(f64, &S) -> f64>(
    dense: &DenseStep,
    event: &mut G,
    a: f64,
    ga: f64,
    b: f64,
    gb: f64,
    like: &S,
) -> f64 {
    if gb == 0.0 {
        return b;
    }
    let mut y = like.clone();
    let (mut a, mut ga, mut b, mut gb) = (a, ga, b, gb);
    for _ in 0..200 {
        let c = b - gb * (b - a) / (gb - ga);
        let c = if c.is_finite() && (c - a) * (c - b) <= 0.0 { c } else { 0.5 * (a + b) };
        dense.eval_into(c, y.as_mut_slice());
        let gc = event(c, &y);
        if gc == 0.0 {
            return c;
        }
        if (gc < 0.0) != (gb < 0.0) {
            a = b;
            ga = gb;
        } else {
            ga *= 0.5;
        }
        b = c;
        gb = gc;
        if (b - a).abs() <= 4.0 * f64::EPSILON * a.abs().max(b.abs()) {
            break;
        }
    }
    b
}

/// The output of [`dop853_scan`]: the solution at requested times and every crossing of an
/// event function, without keeping the steps (memory grows with the output only).
#[derive(Debug, Clone)]
pub struct Scan<S> {
    /// The requested times.
    pub t: Vec<f64>,
    /// The states at `t` (from the dense output; the end point exactly).
    pub y: Vec<S>,
    /// Every crossing of the event function of the requested kind, in order; the states are
    /// from the dense output.
    pub crossings: Vec<EventHit<S>>,
    /// The state at `t_end`.
    pub y_final: S,
    /// Work counters.
    pub stats: Stats,
}

/// Integrates from `(t0, y0)` to `t_end`, returning the state at each of `times` (monotone,
/// inside the interval) and every zero crossing of `event` of kind `crossing`
/// (non-terminal), found on the dense output. Errors name `times` if they are not monotone
/// or leave the interval, and otherwise as [`dop853`].
#[allow(clippy::too_many_arguments)]
pub fn dop853_scan<S, F, G>(
    system: F,
    t0: f64,
    y0: S,
    t_end: f64,
    times: &[f64],
    opts: &Options,
    mut event: G,
    crossing: Crossing,
) -> Result<Scan<S>>
where
    S: OdeState,
    F: OdeSystem<S>,
    G: FnMut(f64, &S) -> f64,
{
    let mut stepper = Dop853::new(system, t0, y0.clone(), t_end, opts)?;
    let dir = stepper.direction;
    crate::error::check_finite("times", times)?;
    for (i, &t) in times.iter().enumerate() {
        if dir * (t - t0) < 0.0 || dir * (t - t_end) > 0.0 {
            return Err(Error::invalid("times", format!("must lie between t0 = {t0} and t_end = {t_end}, got {t} at index {i}")));
        }
        if i > 0 && dir * (t - times[i - 1]) < 0.0 {
            return Err(Error::invalid("times", format!("must be monotone in the direction of integration (index {i})")));
        }
    }
    let mut out = Vec::with_capacity(times.len());
    let mut next = 0;
    while next < times.len() && times[next] == t0 {
        out.push(y0.clone());
        next += 1;
    }
    let mut crossings = Vec::new();
    let mut g_old = event(t0, &y0);
    let mut y = y0.clone();
    while !stepper.is_finished() {
        stepper.step()?;
        let g_new = event(stepper.t, &stepper.y);
        let hit = crossing.detects(g_old, g_new) && g_old != 0.0;
        let wants_sample = next < times.len() && dir * (times[next] - stepper.t) <= 0.0;
        if hit || wants_sample {
            // The dense output costs three evaluations: only when a point inside the step is wanted.
            let mut dense: Option<DenseStep> = None;
            if hit {
                let d = dense.get_or_insert_with(|| stepper.dense_step());
                let t_hit = find_root(d, &mut event, stepper.t_old, g_old, stepper.t, g_new, &stepper.y);
                d.eval_into(t_hit, y.as_mut_slice());
                crossings.push(EventHit { t: t_hit, y: y.clone() });
            }
            while next < times.len() && dir * (times[next] - stepper.t) <= 0.0 {
                if times[next] == stepper.t {
                    out.push(stepper.y.clone());
                } else {
                    let d = dense.get_or_insert_with(|| stepper.dense_step());
                    d.eval_into(times[next], y.as_mut_slice());
                    out.push(y.clone());
                }
                next += 1;
            }
        }
        g_old = g_new;
    }
    Ok(Scan { t: times.to_vec(), y: out, crossings, y_final: stepper.y.clone(), stats: stepper.stats() })
}
