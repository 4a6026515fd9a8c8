//! `simulate`: the motion of a rigid body under a torque, sampled at evenly spaced times, by
//! the exact flow, the Lie–Poisson splitting (orders 2, 4, 6), RK4 or DOP853 — one interface.

use super::equations::{angular_acceleration_principal, power, quaternion_rate, RigidRhs};
use super::model::BodyInertia;
use super::splitting::{free_steps, kicked_step, SplitState};
use super::torque::{TorqueContext, TorqueModel};
use crate::analytic::FreeRigidBody;
use crate::control;
use crate::error::{check_finite, Error, Result};
use crate::integrate::{composition_coefficients, Dop853, Options};
use crate::limits::{check_count, check_steps, DEFAULT_MAX_STEPS};
use crate::rotation::{
    check_quaternion, conj, hamilton, normalized, quaternion_to_mat3_unchecked, same_hemisphere,
    Quaternion,
};
use crate::{Mat3, Vec3};

/// An integration method.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Method {
    /// The exact flow for a torque-free body, DOP853 otherwise.
    #[default]
    Auto,
    /// The exact torque-free solution ([`FreeRigidBody`]); torque-free bodies only.
    Exact,
    /// Classic fixed-step RK4 on (ω, q), q renormalised after each step.
    Rk4,
    /// Adaptive DOP853 (rtol, atol) on (ω, q), q renormalised at the samples.
    Dop853,
    /// The Lie–Poisson splitting composed to order 2, 4 or 6 (exact rotations and kicks);
    /// torques that depend on the attitude and time only.
    Splitting(u8),
}

impl Method {
    /// Parses "auto", "exact", "rk4", "dop853", "splitting" (order 2), "splitting2",
    /// "splitting4", "splitting6"; the error names `method` and lists the choices.
    pub fn parse(name: &str) -> Result<Self> {
        Ok(match name.to_ascii_lowercase().as_str() {
            "auto" => Method::Auto,
            "exact" => Method::Exact,
            "rk4" => Method::Rk4,
            "dop853" => Method::Dop853,
            "splitting" | "splitting2" | "lie-poisson" => Method::Splitting(2),
            "splitting4" => Method::Splitting(4),
            "splitting6" => Method::Splitting(6),
            other => {
                return Err(Error::invalid(
                    "method",
                    format!(
                    "must be one of 'auto', 'exact', 'rk4', 'dop853', 'splitting2', 'splitting4', \
                         'splitting6', got {other:?}"
                ),
                ))
            }
        })
    }

    /// The canonical name ("exact", "rk4", "dop853", "splitting4", ...).
    pub fn name(&self) -> String {
        match self {
            Method::Auto => "auto".into(),
            Method::Exact => "exact".into(),
            Method::Rk4 => "rk4".into(),
            Method::Dop853 => "dop853".into(),
            Method::Splitting(k) => format!("splitting{k}"),
        }
    }

    /// Whether the method takes fixed steps `dt`.
    pub fn is_fixed_step(&self) -> bool {
        matches!(self, Method::Rk4 | Method::Splitting(_))
    }
}

/// Options of [`simulate`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimulateOptions {
    /// The method (default [`Method::Auto`]).
    pub method: Method,
    /// Step of the fixed-step methods (s); `None` picks [`default_step`]. The step actually
    /// taken is `Δ / ceil(Δ/dt) ≤ dt`, Δ the sample interval, so the samples fall on steps
    /// and all steps are equal.
    pub dt: Option<f64>,
    /// Number of evenly spaced output times, both ends included (≥ 2; default 1001). The
    /// memory used grows with `samples`, never with the number of steps.
    pub samples: usize,
    /// DOP853 relative tolerance (default 1e-10).
    pub rtol: f64,
    /// DOP853 absolute tolerance (default 1e-12).
    pub atol: f64,
    /// Step limit of every method but the exact flow (default
    /// [`DEFAULT_MAX_STEPS`] = 10⁸): the fixed-step methods refuse, before the first step, a
    /// request that needs more; DOP853 stops when it reaches it.
    pub max_steps: usize,
}

impl Default for SimulateOptions {
    fn default() -> Self {
        Self {
            method: Method::Auto,
            dt: None,
            samples: 1001,
            rtol: 1e-10,
            atol: 1e-12,
            max_steps: DEFAULT_MAX_STEPS,
        }
    }
}

/// Bytes of output per sample of a [`Trajectory`]: t, ω (3), q (4), L (3), T, V, power.
pub const TRAJECTORY_BYTES_PER_SAMPLE: usize = 14 * std::mem::size_of::<f64>();

/// Steps of the splittings between two polls of [`crate::control`] (and between progress
/// reports), about a millisecond of work.
const STEPS_PER_CHUNK: usize = 4096;

/// A sampled trajectory, in the body axes the user gave.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Trajectory {
    /// Sample times (s), evenly spaced from 0 to the duration.
    pub t: Vec<f64>,
    /// ω in body components (rad/s).
    pub omega: Vec<[f64; 3]>,
    /// Attitude quaternions `[w, x, y, z]` (body → space), made continuous in sign.
    pub attitude: Vec<[f64; 4]>,
    /// Angular momentum in space components (kg·m²/s).
    pub angular_momentum: Vec<[f64; 3]>,
    /// Kinetic energy T = ½ ω·I·ω (J).
    pub energy: Vec<f64>,
    /// Potential energy of a conservative torque (gravity: m g l cos θ), else 0 (J).
    pub potential: Vec<f64>,
    /// The power of the torque ω·N = dT/dt (2.76) (W).
    pub power: Vec<f64>,
    /// The method used (never `Auto`).
    pub method: Method,
    /// The fixed step taken (s), for fixed-step methods.
    pub step: Option<f64>,
    /// Steps taken (accepted steps for DOP853).
    pub steps: usize,
    /// Evaluations of the torque model.
    pub torque_evaluations: usize,
}

/// The default step of the fixed-step methods: 1/1000 of a turn at the fastest rate of the
/// problem, `2π / (1000 ρ)` with `ρ = |ω₀| I_max/I_min + (|N₀|/I_min)^½ + n_orbit` (an upper
/// bound of the body's rates at the start). `None` when the body is at rest without torque.
pub fn default_step(
    inertia: &BodyInertia,
    omega0: &Vec3,
    torque_magnitude: f64,
    extra_rate: f64,
) -> Option<f64> {
    default_step_of(
        inertia.max_moment(),
        inertia.min_moment(),
        omega0.norm(),
        torque_magnitude,
        extra_rate,
    )
}

/// [`default_step`] from the largest and smallest principal moments and |ω₀|.
#[inline]
pub(crate) fn default_step_of(
    max_moment: f64,
    min_moment: f64,
    omega_norm: f64,
    torque_magnitude: f64,
    extra_rate: f64,
) -> Option<f64> {
    let rate =
        omega_norm * max_moment / min_moment + (torque_magnitude / min_moment).sqrt() + extra_rate;
    (rate > 0.0 && rate.is_finite()).then(|| 2.0 * std::f64::consts::PI / (1000.0 * rate))
}

/// Converts between the body axes B and the principal frame P.
struct Frames<'a> {
    inertia: &'a BodyInertia,
}

impl Frames<'_> {
    #[inline]
    fn omega_b(&self, w_p: &Vec3) -> Vec3 {
        if self.inertia.principal {
            *w_p
        } else {
            self.inertia.axes * w_p
        }
    }
    #[inline]
    fn omega_p(&self, w_b: &Vec3) -> Vec3 {
        if self.inertia.principal {
            *w_b
        } else {
            self.inertia.axes.transpose() * w_b
        }
    }
    #[inline]
    fn q_b(&self, q_p: &Quaternion) -> Quaternion {
        if self.inertia.principal {
            *q_p
        } else {
            hamilton(q_p, &conj(&self.inertia.axes_q))
        }
    }
    #[inline]
    fn q_p(&self, q_b: &Quaternion) -> Quaternion {
        if self.inertia.principal {
            *q_b
        } else {
            hamilton(q_b, &self.inertia.axes_q)
        }
    }
    /// The torque in principal components at (t, ω_P, q_P), from the model in B.
    #[inline]
    fn torque_p<T: TorqueModel + ?Sized>(
        &self,
        torque: &mut T,
        t: f64,
        w_p: &Vec3,
        q_p: &Quaternion,
    ) -> Vec3 {
        let w_b = self.omega_b(w_p);
        let attitude = if torque.depends_on_attitude() {
            quaternion_to_mat3_unchecked(&normalized(&self.q_b(q_p)))
        } else {
            Mat3::identity()
        };
        let n_b = torque.torque(&TorqueContext {
            t,
            omega: &w_b,
            attitude: &attitude,
            inertia: &self.inertia.tensor,
        });
        self.omega_p(&n_b)
    }
}

/// Checks the common arguments; returns the unit attitude.
fn check_start(omega0: &Vec3, attitude0: Option<Quaternion>, duration: f64) -> Result<Quaternion> {
    check_finite("omega0", omega0.as_slice())?;
    if !(duration.is_finite() && duration > 0.0) {
        return Err(Error::invalid(
            "duration",
            format!("must be finite and > 0, got {duration}"),
        ));
    }
    match attitude0 {
        Some(q) => check_quaternion("attitude0", &q, false),
        None => Ok([1.0, 0.0, 0.0, 0.0]),
    }
}

/// Resolves `Auto` and checks that the method suits the torque.
fn resolve<T: TorqueModel + ?Sized>(method: Method, torque: &T) -> Result<Method> {
    match method {
        Method::Auto => Ok(if torque.is_zero() { Method::Exact } else { Method::Dop853 }),
        Method::Exact if !torque.is_zero() => Err(Error::invalid(
            "method",
            "'exact' solves the torque-free body only; use 'dop853', 'rk4' or a splitting with a torque",
        )),
        Method::Splitting(k) if torque.depends_on_omega() => Err(Error::invalid(
            "method",
            format!(
                "'splitting{k}' needs a torque that depends on the attitude and time only (none, body, space, \
                 gravity, gravity gradient); a callback may depend on ω: use 'dop853' or 'rk4'"
            ),
        )),
        Method::Splitting(k) => composition_coefficients(usize::from(k)).map(|_| method).map_err(|_| {
            Error::invalid("method", format!("the splitting has order 2, 4 or 6, got {k}"))
        }),
        m => Ok(m),
    }
}

/// Simulates the rigid body of inertia `inertia` from body angular velocity `omega0` (rad/s)
/// and attitude `attitude0` (`[w, x, y, z]`, body → space; identity if `None`) for `duration`
/// seconds under `torque`, sampling `opts.samples` evenly spaced times (both ends included).
///
/// Progress is reported to [`crate::control`] (which can also stop the run). Before any work,
/// `samples` is checked against the memory budget ([`crate::limits`]) and the steps a
/// fixed-step method needs against `opts.max_steps`. Errors name the argument at fault
/// (`omega0`, `attitude0`, `duration`, `dt`, `samples`, `max_steps`, `method`, `rtol`, ...); a
/// diverging integration — any output that stops being finite, energy included — stops with
/// [`crate::ErrorKind::Diverged`] naming `t` and saying when.
///
/// ```
/// use poinsot::dynamics::{simulate, BodyInertia, Method, SimulateOptions, Torque};
/// use poinsot::Vec3;
/// // A free body integrated by the 4th-order Lie–Poisson splitting for 100 s.
/// let body = BodyInertia::from_moments([1.0, 2.0, 3.0])?;
/// let opts = SimulateOptions { method: Method::Splitting(4), dt: Some(1e-2), samples: 11, ..Default::default() };
/// let run = simulate(&body, Vec3::new(1.0, 0.1, 1.0), None, 100.0, &mut Torque::None, &opts)?;
/// assert_eq!(run.t.len(), 11);
/// // The splitting keeps |L| to round-off and the energy error bounded (O(dt⁴)), at any step.
/// let norm = |l: &[f64; 3]| (l[0] * l[0] + l[1] * l[1] + l[2] * l[2]).sqrt();
/// let l0 = norm(&run.angular_momentum[0]);
/// assert!(run.angular_momentum.iter().all(|l| (norm(l) - l0).abs() < 1e-13 * l0));
/// assert!(run.energy.iter().all(|e| (e - run.energy[0]).abs() < 1e-8));
/// // A heavy top (inertia about its pivot) tilted 0.3 rad, under gravity, by adaptive DOP853:
/// // T + V is conserved to the tolerance.
/// let top = BodyInertia::from_moments([1.0, 1.0, 0.5])?;
/// let tilt = [0.15f64.cos(), 0.15f64.sin(), 0.0, 0.0]; // [w, x, y, z], body → space
/// let opts = SimulateOptions { method: Method::Dop853, samples: 3, ..Default::default() };
/// let mut gravity = Torque::Gravity { mgl: 1.0 };
/// let run = simulate(&top, Vec3::new(0.0, 0.0, 20.0), Some(tilt), 5.0, &mut gravity, &opts)?;
/// let total = |k: usize| run.energy[k] + run.potential[k];
/// assert!((total(2) - total(0)).abs() < 1e-8 * total(0));
/// // A start that is not a unit quaternion is refused, naming the argument.
/// let err = simulate(&top, Vec3::zeros(), Some([0.9, 0.1, 0.0, 0.0]), 5.0, &mut gravity, &opts);
/// assert_eq!(err.unwrap_err().argument, "attitude0");
/// # Ok::<(), poinsot::Error>(())
/// ```
#[allow(clippy::needless_range_loop)]
pub fn simulate<T: TorqueModel + ?Sized>(
    inertia: &BodyInertia,
    omega0: Vec3,
    attitude0: Option<Quaternion>,
    duration: f64,
    torque: &mut T,
    opts: &SimulateOptions,
) -> Result<Trajectory> {
    let q0 = check_start(&omega0, attitude0, duration)?;
    check_count("samples", opts.samples, 2, TRAJECTORY_BYTES_PER_SAMPLE)?;
    if let Some(dt) = opts.dt {
        if !(dt.is_finite() && dt > 0.0) {
            return Err(Error::invalid(
                "dt",
                format!("must be finite and > 0, got {}", crate::error::num(dt)),
            ));
        }
    }
    let method = resolve(opts.method, torque)?;
    let frames = Frames { inertia };
    let n = opts.samples;
    let times = crate::integrate::even_times(0.0, duration, n);
    let mut out = Trajectory {
        method,
        ..Trajectory::default()
    };
    let mut evaluations = 0usize;

    // The sampler: converts a principal-frame state to the outputs.
    let record = |out: &mut Trajectory,
                  t: f64,
                  w_p: &Vec3,
                  q_p: &Quaternion,
                  torque: &mut T,
                  evaluations: &mut usize| {
        let w_b = frames.omega_b(w_p);
        let q_b = normalized(&frames.q_b(q_p));
        let q_b = match out.attitude.last() {
            Some(prev) => same_hemisphere(q_b, prev),
            None => q_b,
        };
        let l_b = inertia.tensor * w_b;
        let attitude = quaternion_to_mat3_unchecked(&q_b);
        let ctx = TorqueContext {
            t,
            omega: &w_b,
            attitude: &attitude,
            inertia: &inertia.tensor,
        };
        let (n_b, v) = if torque.is_zero() {
            (Vec3::zeros(), 0.0)
        } else {
            (torque.torque(&ctx), torque.potential(&ctx))
        };
        *evaluations += usize::from(!torque.is_zero());
        let l_s = attitude * l_b;
        let energy = 0.5 * w_b.dot(&l_b);
        let p = power(&w_b, &n_b);
        // Every returned number is finite: an overflow anywhere (ω, L, T, V, power) is the
        // run diverging, reported with its time.
        let finite = w_b.iter().chain(l_s.iter()).all(|x| x.is_finite())
            && q_b.iter().all(|x| x.is_finite())
            && energy.is_finite()
            && v.is_finite()
            && p.is_finite();
        if !finite {
            return Err(diverged(t));
        }
        out.t.push(t);
        out.omega.push([w_b.x, w_b.y, w_b.z]);
        out.attitude.push(q_b);
        out.angular_momentum.push([l_s.x, l_s.y, l_s.z]);
        out.energy.push(energy);
        out.potential.push(v);
        out.power.push(p);
        Ok(())
    };
    for v in [
        &mut out.t as &mut Vec<f64>,
        &mut out.energy,
        &mut out.potential,
        &mut out.power,
    ] {
        v.reserve_exact(n);
    }
    out.omega.reserve_exact(n);
    out.attitude.reserve_exact(n);
    out.angular_momentum.reserve_exact(n);

    let w0_p = frames.omega_p(&omega0);
    let q0_p = frames.q_p(&q0);
    let moments = inertia.moments;
    record(&mut out, 0.0, &w0_p, &q0_p, torque, &mut evaluations).map_err(|_| {
        // Which input overflows: ω₀ (through L or T), or else the torque (its power ω·N).
        let l0 = inertia.tensor * omega0;
        if l0.iter().all(|x| x.is_finite()) && (0.5 * omega0.dot(&l0)).is_finite() {
            overflow_at_start("torque", "the torque's power ω·N or potential")
        } else {
            overflow_at_start("omega0", "the initial angular momentum or energy")
        }
    })?;

    match method {
        Method::Exact => {
            if omega0.iter().all(|&c| c == 0.0) {
                for &t in &times[1..] {
                    record(&mut out, t, &w0_p, &q0_p, torque, &mut evaluations)?;
                    control::report(t / duration)?;
                }
            } else {
                let body = FreeRigidBody::new(moments, w0_p, Some(normalized(&q0_p)))?;
                for (i, &t) in times.iter().enumerate().skip(1) {
                    // The exact flow refuses times past its phase limit: the caller's `duration`.
                    let (w, q) = body.state(t).map_err(|e| e.renamed("t", "duration"))?;
                    record(&mut out, t, &w, &q, torque, &mut evaluations)?;
                    control::report(i as f64 / (n - 1) as f64)?;
                }
            }
        }
        Method::Rk4 | Method::Splitting(_) => {
            let n0 = frames.torque_p(torque, 0.0, &w0_p, &q0_p).norm();
            let orbit = match_orbit_rate(torque);
            let dt = match opts
                .dt
                .or_else(|| default_step(inertia, &omega0, n0, orbit))
            {
                Some(dt) => dt,
                None => duration / (n - 1) as f64,
            };
            let interval = duration / (n - 1) as f64;
            let sub = (interval / dt).ceil().max(1.0);
            check_steps(
                sub * (n - 1) as f64,
                opts.max_steps,
                &format!(
                    "take a larger dt (now {} s) or a shorter duration",
                    crate::error::num(dt)
                ),
            )?;
            let sub = sub as usize;
            let h = interval / sub as f64;
            out.step = Some(h);
            if method == Method::Rk4 {
                let mut y = [w0_p.x, w0_p.y, w0_p.z, q0_p[0], q0_p[1], q0_p[2], q0_p[3]];
                let zero = torque.is_zero();
                let rigid = RigidRhs::new(&moments);
                // Progress within the run, and a check that the state stays finite (a NaN from a
                // torque callback, an overflow) at every step, not only at the samples.
                let at =
                    |i: usize, k: usize| ((i - 1) as f64 + k as f64 / sub as f64) / (n - 1) as f64;
                let finite = |y: &[f64; 7]| y.iter().sum::<f64>().is_finite();
                for i in 1..n {
                    let t_start = times[i - 1];
                    if zero {
                        let mut none = |_t: f64, _w: &Vec3, _q: &Quaternion| Vec3::zeros();
                        for k in 0..sub {
                            control::report(at(i, k))?;
                            y = rigid.rk4_step(t_start + h * k as f64, &y, h, &mut none);
                            if !finite(&y) {
                                return Err(diverged(t_start + h * (k + 1) as f64));
                            }
                        }
                    } else {
                        let torque = &mut *torque;
                        let evals = &mut evaluations;
                        let mut model = |t: f64, w: &Vec3, q: &Quaternion| {
                            *evals += 1;
                            frames.torque_p(torque, t, w, q)
                        };
                        for k in 0..sub {
                            control::report(at(i, k))?;
                            y = rigid.rk4_step(t_start + h * k as f64, &y, h, &mut model);
                            if !finite(&y) {
                                return Err(diverged(t_start + h * (k + 1) as f64));
                            }
                        }
                    }
                    if !y.iter().all(|v| v.is_finite()) {
                        return Err(diverged(times[i]));
                    }
                    out.steps += sub;
                    let (w, q) = (Vec3::new(y[0], y[1], y[2]), [y[3], y[4], y[5], y[6]]);
                    record(&mut out, times[i], &w, &q, torque, &mut evaluations)?;
                    control::report(i as f64 / (n - 1) as f64)?;
                }
            } else {
                let Method::Splitting(order) = method else {
                    unreachable!()
                };
                let gammas = composition_coefficients(usize::from(order))?;
                let mut state = SplitState {
                    l: Vec3::new(
                        moments[0] * w0_p.x,
                        moments[1] * w0_p.y,
                        moments[2] * w0_p.z,
                    ),
                    q: q0_p,
                    t: 0.0,
                };
                let zero = torque.is_zero();
                let at =
                    |i: usize, k: usize| ((i - 1) as f64 + k as f64 / sub as f64) / (n - 1) as f64;
                for i in 1..n {
                    if zero {
                        let mut left = sub;
                        while left > 0 {
                            let k = left.min(STEPS_PER_CHUNK);
                            free_steps(&mut state, &moments, gammas, h, k);
                            left -= k;
                            control::report(at(i, sub - left))?;
                            control::tick_by(k as u32)?;
                        }
                    } else {
                        let mut kick = |s: &mut SplitState, dt: f64| {
                            let w = Vec3::new(
                                s.l.x / moments[0],
                                s.l.y / moments[1],
                                s.l.z / moments[2],
                            );
                            let nt = frames.torque_p(torque, s.t, &w, &s.q);
                            evaluations += 1;
                            s.l += dt * nt;
                        };
                        for k in 0..sub {
                            control::report(at(i, k))?;
                            kicked_step(&mut state, &moments, gammas, h, &mut kick);
                            if !(state.l.sum().is_finite()
                                && state.q.iter().sum::<f64>().is_finite())
                            {
                                return Err(diverged(times[i - 1] + h * (k + 1) as f64));
                            }
                        }
                    }
                    state.t = times[i];
                    let w = Vec3::new(
                        state.l.x / moments[0],
                        state.l.y / moments[1],
                        state.l.z / moments[2],
                    );
                    if !(w.iter().all(|v| v.is_finite()) && state.q.iter().all(|v| v.is_finite())) {
                        return Err(diverged(times[i]));
                    }
                    out.steps += sub;
                    record(&mut out, times[i], &w, &state.q, torque, &mut evaluations)?;
                    control::report(i as f64 / (n - 1) as f64)?;
                }
            }
        }
        Method::Dop853 => {
            // A lower bound on the steps DOP853 needs, checked before the first: at least one
            // step per turn at the fastest rate of the problem (it takes several).
            let n0 = frames.torque_p(torque, 0.0, &w0_p, &q0_p).norm();
            if let Some(h) = default_step(inertia, &omega0, n0, torque.orbit_rate()) {
                check_steps(
                    duration / (1000.0 * h),
                    opts.max_steps,
                    "shorten the duration",
                )?;
            }
            let options = Options {
                rtol: opts.rtol,
                atol: opts.atol,
                max_steps: opts.max_steps,
                dense: true,
                ..Options::default()
            };
            let zero = torque.is_zero();
            let mut evals = 0usize;
            let torque_ref = &mut *torque;
            let evals_ref = &mut evals;
            let system = |t: f64, y: &[f64; 7], dy: &mut [f64; 7]| {
                let w = Vec3::new(y[0], y[1], y[2]);
                let q = [y[3], y[4], y[5], y[6]];
                let nt = if zero {
                    Vec3::zeros()
                } else {
                    *evals_ref += 1;
                    frames.torque_p(torque_ref, t, &w, &q)
                };
                let a = angular_acceleration_principal(&moments, &w, &nt);
                let qd = quaternion_rate(&q, &w);
                *dy = [a.x, a.y, a.z, qd[0], qd[1], qd[2], qd[3]];
            };
            let y0 = [w0_p.x, w0_p.y, w0_p.z, q0_p[0], q0_p[1], q0_p[2], q0_p[3]];
            let mut stepper = Dop853::new(system, 0.0, y0, duration, &options)?;
            let mut next = 1;
            let mut pending: Vec<(f64, [f64; 7])> = Vec::new();
            let mut y = y0;
            while !stepper.is_finished() {
                // A step that fails (its size below round-off) names the run's `duration`.
                stepper.step().map_err(|e| e.renamed("t", "duration"))?;
                control::report(stepper.t() / duration)?;
                if next < n && times[next] <= stepper.t() {
                    let dense = stepper.dense_step();
                    while next < n && times[next] <= stepper.t() {
                        if times[next] == stepper.t() {
                            y = *stepper.y();
                        } else {
                            dense.eval_into(times[next], &mut y);
                        }
                        pending.push((times[next], y));
                        next += 1;
                    }
                    control::report((next - 1) as f64 / (n - 1) as f64)?;
                }
            }
            out.steps = stepper.stats().accepted;
            evaluations += evals;
            for (t, y) in pending {
                let (w, q) = (Vec3::new(y[0], y[1], y[2]), [y[3], y[4], y[5], y[6]]);
                record(&mut out, t, &w, &q, torque, &mut evaluations)?;
            }
        }
        Method::Auto => unreachable!("resolved above"),
    }
    out.torque_evaluations = evaluations;
    Ok(out)
}

/// A run whose state stopped being finite at `t`: the error names the run's `duration` (the time
/// it failed in the message).
fn diverged(t: f64) -> Error {
    Error::diverged("duration", format!("the state stopped being finite at t = {t} s: the motion diverged (reduce dt, or check the torque)"))
}

fn overflow_at_start(argument: &str, what: &str) -> Error {
    Error::invalid(
        argument,
        format!("{what} at the start is not representable as a finite number (overflow): scale the problem (units) down"),
    )
}

/// The orbital rate of a gravity-gradient torque (for the default step), else 0.
fn match_orbit_rate<T: TorqueModel + ?Sized>(torque: &T) -> f64 {
    torque.orbit_rate()
}
