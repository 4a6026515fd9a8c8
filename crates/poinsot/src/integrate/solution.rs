//! The result of an integration: the accepted steps, their dense output and the event.

use super::dop853_coefficients::INTERPOLATOR_POWER;
use super::options::Stats;
use super::state::OdeState;
use crate::error::{Error, Result};

/// The dense output of one DOP853 step: a polynomial of degree 7 in `(t − t_old)/h` that
/// interpolates the solution over the step with the accuracy of the step itself
/// (Hairer, Nørsett & Wanner, §II.6).
#[derive(Debug, Clone, PartialEq)]
pub struct DenseStep {
    /// Start of the step.
    pub t_old: f64,
    /// Signed step size.
    pub h: f64,
    y_old: Vec<f64>,
    /// `INTERPOLATOR_POWER` rows of `n` coefficients, row-major.
    coeffs: Vec<f64>,
}

impl DenseStep {
    pub(crate) fn new(t_old: f64, h: f64, y_old: Vec<f64>, coeffs: Vec<f64>) -> Self {
        debug_assert_eq!(coeffs.len(), INTERPOLATOR_POWER * y_old.len());
        Self {
            t_old,
            h,
            y_old,
            coeffs,
        }
    }

    /// Writes the interpolated state at `t` into `out` (`out.len()` = state length).
    /// Exact at the two ends of the step up to round-off; meant for `t` inside the step.
    pub fn eval_into(&self, t: f64, out: &mut [f64]) {
        let n = self.y_old.len();
        let x = (t - self.t_old) / self.h;
        // Horner-like evaluation in the alternating factors x and (1 − x), as in DOP853's
        // CONTD8 (the rows are taken from the highest power down).
        for (i, o) in out.iter_mut().enumerate().take(n) {
            let mut acc = 0.0;
            for (j, row) in (0..INTERPOLATOR_POWER).rev().enumerate() {
                acc += self.coeffs[row * n + i];
                acc *= if j % 2 == 0 { x } else { 1.0 - x };
            }
            *o = acc + self.y_old[i];
        }
    }
}

/// The time and state at which a terminal event function crossed zero.
#[derive(Debug, Clone, PartialEq)]
pub struct EventHit<S> {
    /// Time of the crossing (found on the dense output to ~4 ulp of t).
    pub t: f64,
    /// State at `t`, computed by a full Runge–Kutta step from the start of the step that
    /// contains the crossing (so with the integrator's full order).
    pub y: S,
}

/// The solution of an initial-value problem.
///
/// `t` and `y` hold the start, every accepted step and the end (the event, if one
/// stopped the integration); with dense output ([`super::Options::dense`]) the solution can
/// be evaluated at any time between them with [`Solution::at`] and [`Solution::sample`].
#[derive(Debug, Clone)]
pub struct Solution<S> {
    /// Times of the accepted steps, from `t0` to the final time (monotone).
    pub t: Vec<f64>,
    /// States at `t`.
    pub y: Vec<S>,
    /// Work counters.
    pub stats: Stats,
    /// The terminal event, if one stopped the integration (then `t` ends at its time).
    pub event: Option<EventHit<S>>,
    pub(crate) dense: Vec<DenseStep>,
}

impl<S: OdeState> Solution<S> {
    pub(crate) fn new(t0: f64, y0: S) -> Self {
        Self {
            t: vec![t0],
            y: vec![y0],
            stats: Stats::default(),
            event: None,
            dense: Vec::new(),
        }
    }

    /// The final time reached.
    pub fn t_final(&self) -> f64 {
        *self
            .t
            .last()
            .expect("a solution holds at least its initial point")
    }

    /// The state at the final time.
    pub fn y_final(&self) -> &S {
        self.y
            .last()
            .expect("a solution holds at least its initial point")
    }

    /// Whether the dense output was kept (so that [`Solution::at`] works).
    pub fn has_dense_output(&self) -> bool {
        self.t.len() == 1 || self.dense.len() + 1 == self.t.len()
    }

    /// The state at time `t`, which must lie between the first and the final time.
    pub fn at(&self, t: f64) -> Result<S> {
        let mut out = self.y[0].clone();
        self.eval_into(t, out.as_mut_slice())?;
        Ok(out)
    }

    /// The states at each of `times` (each between the first and the final time).
    pub fn sample(&self, times: &[f64]) -> Result<Vec<S>> {
        times.iter().map(|&t| self.at(t)).collect()
    }

    fn eval_into(&self, t: f64, out: &mut [f64]) -> Result<()> {
        let t0 = self.t[0];
        let t1 = self.t_final();
        let (lo, hi) = if t1 >= t0 { (t0, t1) } else { (t1, t0) };
        if !(t >= lo && t <= hi) {
            return Err(Error::invalid(
                "t",
                format!("must lie in [{lo}, {hi}], the solved interval, got {t}"),
            ));
        }
        if t == t1 {
            out.copy_from_slice(self.y_final().as_slice());
            return Ok(());
        }
        if !self.has_dense_output() {
            return Err(Error::invalid(
                "t",
                "this solution kept no dense output (solve with Options::dense = true)",
            ));
        }
        // Step i covers [t[i], t[i+1]]; find it by bisection on the monotone times.
        let forward = t1 >= t0;
        let i = self
            .t
            .partition_point(|&ti| if forward { ti <= t } else { ti >= t });
        let i = i.saturating_sub(1).min(self.dense.len() - 1);
        self.dense[i].eval_into(t, out);
        Ok(())
    }
}
