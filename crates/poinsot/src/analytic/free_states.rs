//! The exact torque-free motion of many bodies at many times at once: [`free_body_states`].

use rayon::prelude::*;

use super::free_rigid_body::{FreeRigidBody, PiSeries};
use crate::control::{self, Cancel};
use crate::error::{Error, ErrorKind, Result};
use crate::limits::check_memory;
use crate::rotation::{same_hemisphere, Quaternion};
use crate::rows::{check_every_row, check_row, check_row_counts, in_body, in_row};
use crate::Vec3;

/// The times of [`free_body_states`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StateTimes<'a> {
    /// The same M times (s) for every body.
    Shared(&'a [f64]),
    /// Each body its own M times (s): row-major (N, M), N·M values.
    PerBody(&'a [f64]),
}

/// The states of N bodies at M times each, row-major (N, M): entry `i·M + k` is body i at its
/// time k.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FreeBodyStates {
    /// ω in body components (rad/s).
    pub omega: Vec<[f64; 3]>,
    /// The attitudes `[w, x, y, z]` (body → space), their signs made continuous along each
    /// body's times (q and −q are the same attitude), as [`FreeRigidBody::sample`] gives them.
    pub attitude: Vec<Quaternion>,
    /// N, the number of bodies.
    pub bodies: usize,
    /// M, the number of times per body.
    pub times: usize,
}

/// Bytes of output per state: ω (3) and the attitude (4).
const BYTES_PER_STATE: usize = 7 * std::mem::size_of::<f64>();

/// Times per parallel task (and between two looks at the stop flag); a body with more times
/// has them split over several tasks.
const TIMES_PER_TASK: usize = 4096;

/// A body's Π series pays for itself (its coefficients cost about as much as this many states
/// by the scalar path) from this many times on.
const SERIES_FROM: usize = 8;

/// The exact states of N torque-free bodies — principal moments `moments` (kg·m², any order),
/// body angular velocities `omega0` (rad/s) and attitudes `attitude0` (`[w, x, y, z]` unit
/// quaternions, body → space; the identity if `None`) at t = 0 — at the times `times`: the
/// values of [`FreeRigidBody::sample`] for each body at its times, in parallel over bodies
/// and times, the elliptic motions (ω circling an extreme axis) on SIMD lanes, a group of
/// times per vector instruction: ω bit for bit as [`FreeRigidBody::state`], the attitude
/// within 1e-13 + 8ε per radian the body has turned of it (the state's own error model: its
/// integral of the third kind summed as a Fourier series, the lanes' sines and cosines), its
/// sign made continuous from one time to the next. Bodies nearly symmetric about their pole
/// (n < −16), near the separatrix, steady or symmetric take the scalar path. A body at rest
/// (ω₀ = 0) keeps its attitude.
///
/// Before any state is computed: the rows (each named with its index), the times (finite)
/// and the output's size against the memory budget ([`crate::limits`]). A body's own limits
/// (its motion's range, [`FreeRigidBody::max_time`]) are reported naming the first body at
/// fault. The run polls [`crate::control`] and reports progress (the fraction of the states
/// done).
///
/// Errors name `moments`, `omega0`, `attitude0` (wrong row count, or a row at fault: "row i:
/// …"), `t` (not finite, the wrong count, beyond a body's time limit: "body i: …").
///
/// ```
/// use poinsot::analytic::{free_body_states, FreeRigidBody, StateTimes};
/// use poinsot::Vec3;
/// let moments = [[1.0, 2.0, 3.0], [2.0, 2.5, 1.0]];
/// let omega0 = [[1.0, 0.1, 1.0], [0.3, -2.0, 0.2]];
/// let times = [0.0, 0.5, 10.0];
/// let s = free_body_states(&moments, &omega0, None, StateTimes::Shared(&times))?;
/// assert_eq!((s.bodies, s.times, s.omega.len()), (2, 3, 6));
/// // Body 1 at its time 2: the single body's ω at t = 10 s.
/// let one = FreeRigidBody::new(moments[1], Vec3::from(omega0[1]), None)?;
/// let (w, _) = one.state(10.0)?;
/// assert_eq!(s.omega[3 + 2], [w.x, w.y, w.z]);
/// # Ok::<(), poinsot::Error>(())
/// ```
pub fn free_body_states(
    moments: &[[f64; 3]],
    omega0: &[[f64; 3]],
    attitude0: Option<&[Quaternion]>,
    times: StateTimes<'_>,
) -> Result<FreeBodyStates> {
    let n = moments.len();
    check_row_counts(n, omega0.len(), attitude0.map(<[Quaternion]>::len))?;
    let (all_times, m, shared) = match times {
        StateTimes::Shared(t) => (t, t.len(), true),
        StateTimes::PerBody(t) => {
            if n == 0 && !t.is_empty() || n > 0 && t.len() % n != 0 {
                return Err(Error::invalid(
                    "t",
                    format!(
                        "per-body times must have N × M values for N = {n} bodies, got {}",
                        t.len()
                    ),
                ));
            }
            (t, t.len().checked_div(n).unwrap_or(0), false)
        }
    };
    check_memory("t", n as f64 * m as f64, BYTES_PER_STATE)?;
    if let Some(k) = all_times.iter().position(|t| !t.is_finite()) {
        return Err(Error::invalid(
            "t",
            format!("must be finite, got {} at index {k}", all_times[k]),
        ));
    }
    // Every row, in parallel; the first at fault is reported.
    check_every_row(moments, omega0, attitude0)?;
    let mut out = FreeBodyStates {
        omega: vec![[0.0; 3]; n * m],
        attitude: vec![[0.0; 4]; n * m],
        bodies: n,
        times: m,
    };
    if n * m == 0 {
        return Ok(out);
    }
    let times_of = |i: usize| -> &[f64] {
        if shared {
            all_times
        } else {
            &all_times[i * m..(i + 1) * m]
        }
    };
    let body_of = |i: usize| -> Result<Option<FreeRigidBody>> {
        let w0 = Vec3::from(omega0[i]);
        if w0.iter().all(|&c| c == 0.0) {
            return Ok(None);
        }
        let q0 = check_row(moments, omega0, attitude0, i)?;
        FreeRigidBody::new(moments[i], w0, Some(q0))
            .map(Some)
            .map_err(|e| in_row(i, e))
    };
    // One body's states at `ts` (its times from `from`) into `w`, `q`.
    let states = |i: usize,
                  body: &Option<FreeRigidBody>,
                  series: Option<&PiSeries>,
                  ts: &[f64],
                  w: &mut [[f64; 3]],
                  q: &mut [Quaternion],
                  cancel: &Cancel|
     -> Result<()> {
        cancel.check()?;
        match body {
            Some(b) => b.states_into(ts, w, q, series).map_err(|e| in_body(i, e))?,
            None => {
                let rest = check_row(moments, omega0, attitude0, i)?;
                w.fill(omega0[i]);
                q.fill(rest);
            }
        }
        cancel.advance(ts.len() as u64);
        Ok(())
    };
    let result = control::parallel((n * m) as u64, |cancel| {
        out.omega
            .par_chunks_mut(m)
            .zip(out.attitude.par_chunks_mut(m))
            .enumerate()
            .with_min_len((TIMES_PER_TASK / m).max(1))
            .map(|(i, (w, q))| -> std::result::Result<(), (usize, Error)> {
                // Before the body's constructor (its elliptic integrals): `map` and `reduce`
                // do not short-circuit, so after Ctrl-C every remaining body still passes
                // here (it took seconds for 10⁶ bodies when only `states` checked).
                cancel.check().map_err(|e| (i, e))?;
                let body = body_of(i).map_err(|e| (i, e))?;
                let series = if m >= SERIES_FROM {
                    body.as_ref().and_then(FreeRigidBody::pi_series)
                } else {
                    None
                };
                let ts = times_of(i);
                if m <= TIMES_PER_TASK {
                    states(i, &body, series.as_ref(), ts, w, q, cancel).map_err(|e| (i, e))?;
                } else {
                    // Many times: the body's times in parallel too.
                    w.par_chunks_mut(TIMES_PER_TASK)
                        .zip(q.par_chunks_mut(TIMES_PER_TASK))
                        .zip(ts.par_chunks(TIMES_PER_TASK))
                        .try_for_each(|((w, q), ts)| {
                            states(i, &body, series.as_ref(), ts, w, q, cancel)
                        })
                        .map_err(|e| (i, e))?;
                }
                for k in 1..m {
                    q[k] = same_hemisphere(q[k], &q[k - 1]);
                }
                Ok(())
            })
            .reduce(|| Ok(()), first_error)
            .map_err(|(_, e)| e)
    });
    result?;
    Ok(out)
}

/// The error to report of two: an interruption, else the one of the lower body.
fn first_error(
    a: std::result::Result<(), (usize, Error)>,
    b: std::result::Result<(), (usize, Error)>,
) -> std::result::Result<(), (usize, Error)> {
    match (a, b) {
        (Err(x), Err(y)) => {
            let interrupted = |e: &(usize, Error)| e.1.kind == ErrorKind::Interrupted;
            Err(if interrupted(&x) || (!interrupted(&y) && x.0 <= y.0) {
                x
            } else {
                y
            })
        }
        (Err(x), _) | (_, Err(x)) => Err(x),
        _ => Ok(()),
    }
}
