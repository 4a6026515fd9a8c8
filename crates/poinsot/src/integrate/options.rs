//! Tolerances and limits of the adaptive integrator, and its counters.

use crate::error::{Error, Result};

/// The smallest relative tolerance accepted: 100 ε, below which round-off dominates the
/// local error estimate (the same floor as Hairer's DOP853 and scipy).
pub const MIN_RTOL: f64 = 100.0 * f64::EPSILON;

/// Options of the adaptive integrator [`crate::integrate::dop853`].
///
/// The local error of each step is kept below `atol + rtol·|y|` componentwise (in the RMS
/// norm of Hairer's DOP853).
///
/// ```
/// use poinsot::integrate::{dop853, Options};
/// // Tight tolerances, no dense output (only the end point is wanted), at most 10⁴ steps.
/// let opts = Options { dense: false, max_steps: 10_000, ..Options::with_tolerances(1e-12, 1e-14) };
/// opts.validate()?;
/// // The harmonic oscillator x'' = −x over one period comes back to its start.
/// let f = |_t: f64, y: &[f64; 2], dy: &mut [f64; 2]| *dy = [y[1], -y[0]];
/// let sol = dop853(f, 0.0, [1.0, 0.0], 2.0 * std::f64::consts::PI, &opts)?;
/// assert!((sol.y_final()[0] - 1.0).abs() < 1e-10);
/// // A tolerance below round-off is refused, naming the field.
/// assert_eq!(Options::with_tolerances(1e-20, 1e-14).validate().unwrap_err().argument, "rtol");
/// # Ok::<(), poinsot::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Relative tolerance, in `[MIN_RTOL, 1)` (default 1e-10).
    pub rtol: f64,
    /// Absolute tolerance, `> 0`, in the units of the state (default 1e-12).
    pub atol: f64,
    /// Maximum number of attempted steps (accepted and rejected) before giving up
    /// (default 1 000 000).
    pub max_steps: usize,
    /// Size of the first step; `None` chooses it automatically (Hairer's algorithm).
    pub first_step: Option<f64>,
    /// Largest step size allowed (default infinite).
    pub max_step: f64,
    /// Keep the dense output of every step so that the solution can be evaluated anywhere
    /// ([`crate::integrate::Solution::at`]); costs three more evaluations per step
    /// (default true).
    pub dense: bool,
}

/// The tolerances and step limit of one kind of run: the defaults of its `rtol`, `atol` and
/// `max_steps` arguments.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerances {
    /// Relative tolerance of the adaptive integration.
    pub rtol: f64,
    /// Absolute tolerance (in the units of the state: m and m/s).
    pub atol: f64,
    /// Step limit: a run needing more is refused before it starts.
    pub max_steps: usize,
}

impl Tolerances {
    /// The integrator's options with these tolerances (`dense`: keep the dense output).
    pub fn options(self, dense: bool) -> Options {
        Options {
            rtol: self.rtol,
            atol: self.atol,
            max_steps: self.max_steps,
            dense,
            ..Options::default()
        }
    }
}

impl Default for Options {
    fn default() -> Self {
        Self {
            rtol: 1e-10,
            atol: 1e-12,
            max_steps: 1_000_000,
            first_step: None,
            max_step: f64::INFINITY,
            dense: true,
        }
    }
}

impl Options {
    /// Default options with the given tolerances.
    pub fn with_tolerances(rtol: f64, atol: f64) -> Self {
        Self {
            rtol,
            atol,
            ..Self::default()
        }
    }

    /// Checks every field; the error names the field at fault.
    pub fn validate(&self) -> Result<()> {
        if !(self.rtol.is_finite() && self.rtol > 0.0) {
            return Err(Error::invalid(
                "rtol",
                format!(
                    "must be finite and > 0, got {}",
                    crate::error::num(self.rtol)
                ),
            ));
        }
        if self.rtol < MIN_RTOL {
            return Err(Error::invalid(
                "rtol",
                format!(
                    "must be >= {MIN_RTOL:e} (100 machine epsilons), got {:e}",
                    self.rtol
                ),
            ));
        }
        if self.rtol >= 1.0 {
            return Err(Error::invalid(
                "rtol",
                format!("must be < 1, got {}", crate::error::num(self.rtol)),
            ));
        }
        if !(self.atol.is_finite() && self.atol > 0.0) {
            return Err(Error::invalid(
                "atol",
                format!(
                    "must be finite and > 0, got {}",
                    crate::error::num(self.atol)
                ),
            ));
        }
        if self.max_steps == 0 {
            return Err(Error::invalid("max_steps", "must be >= 1, got 0"));
        }
        if let Some(h) = self.first_step {
            if !(h.is_finite() && h > 0.0) {
                return Err(Error::invalid(
                    "first_step",
                    format!("must be finite and > 0, got {}", crate::error::num(h)),
                ));
            }
        }
        if self.max_step.is_nan() || self.max_step <= 0.0 {
            return Err(Error::invalid(
                "max_step",
                format!("must be > 0, got {}", crate::error::num(self.max_step)),
            ));
        }
        Ok(())
    }
}

/// Which sign changes of an event function stop the integration.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Crossing {
    /// Any sign change.
    #[default]
    Any,
    /// From negative to positive only.
    Rising,
    /// From positive to negative only.
    Falling,
}

impl Crossing {
    /// Whether going from `g0` to `g1` is a crossing of this kind.
    pub(crate) fn detects(self, g0: f64, g1: f64) -> bool {
        let rising = g0 < 0.0 && g1 >= 0.0;
        let falling = g0 > 0.0 && g1 <= 0.0;
        match self {
            Crossing::Any => rising || falling,
            Crossing::Rising => rising,
            Crossing::Falling => falling,
        }
    }
}

/// Work done by an integration.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Stats {
    /// Accepted steps.
    pub accepted: usize,
    /// Rejected steps (error estimate above tolerance).
    pub rejected: usize,
    /// Evaluations of the right-hand side.
    pub evaluations: usize,
}
