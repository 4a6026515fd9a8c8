//! Long runs from Python: Ctrl-C and progress callbacks through the core's
//! [`poinsot::control`] monitor, and the GIL released while the core works.
//!
//! The monitor looks at the wall clock on each poll of the core (every
//! [`poinsot::control::TICKS_PER_POLL`] units of work); at most every
//! [`poinsot::control::POLL_PERIOD_MS`] it takes the GIL, runs Python's signal handlers
//! (Ctrl-C raises `KeyboardInterrupt` there) and calls the user's progress callback. Either
//! exception stops the run and is raised as it is.
use std::time::{Duration, Instant};

use poinsot::control::{interrupted, watched, Monitor, POLL_PERIOD_MS};
use pyo3::prelude::*;

use crate::errors::IntoPy;

/// The Python monitor: signals and an optional `progress(fraction)` callable.
pub struct PyMonitor {
    last_poll: Instant,
    progress: Option<Py<PyAny>>,
    last_fraction: f64,
    error: Option<PyErr>,
}

impl PyMonitor {
    fn new(progress: Option<&Bound<'_, PyAny>>) -> Self {
        Self {
            last_poll: Instant::now(),
            progress: progress.map(|p| p.clone().unbind()),
            last_fraction: 0.0,
            error: None,
        }
    }

    fn call_progress(&mut self, py: Python<'_>, fraction: f64) -> PyResult<()> {
        if let Some(cb) = &self.progress {
            if fraction > self.last_fraction {
                self.last_fraction = fraction;
                cb.call1(py, (fraction,))?;
            }
        }
        Ok(())
    }

    /// The run's result, or the Python exception that stopped it; on success the progress
    /// callback hears 1.0 last.
    fn finish<T>(mut self, py: Python<'_>, result: poinsot::Result<T>) -> PyResult<T> {
        if let Some(e) = self.error.take() {
            return Err(e);
        }
        let value = result.py()?;
        self.call_progress(py, 1.0)?;
        Ok(value)
    }
}

impl Monitor for PyMonitor {
    fn poll(&mut self, fraction: f64) -> poinsot::Result<()> {
        if self.last_poll.elapsed() < Duration::from_millis(POLL_PERIOD_MS) {
            return Ok(());
        }
        self.last_poll = Instant::now();
        let outcome = Python::attach(|py| {
            py.check_signals()?;
            self.call_progress(py, fraction)
        });
        outcome.map_err(|e| {
            self.error = Some(e);
            interrupted()
        })
    }
}

/// Runs `work` with the GIL released, stoppable by Ctrl-C, reporting to `progress`.
/// `work` must not call Python (use [`run_attached`] for Python callbacks).
pub fn run<T: Send>(
    py: Python<'_>,
    progress: Option<&Bound<'_, PyAny>>,
    work: impl FnOnce() -> poinsot::Result<T> + Send,
) -> PyResult<T> {
    let monitor = PyMonitor::new(progress);
    let (result, monitor) = py.detach(|| watched(monitor, work));
    monitor.finish(py, result)
}

/// `f` of each of `items` (a user's array), in order, with the GIL released and stoppable by
/// Ctrl-C (the core's [`poinsot::control::try_map`], polled every chunk of items): [`run`]
/// for the bindings that evaluate a core function at each element.
pub fn map_each<T: Sync, R: Send>(
    py: Python<'_>,
    items: &[T],
    f: impl Fn(&T) -> poinsot::Result<R> + Send,
) -> PyResult<Vec<R>> {
    run(py, None, || poinsot::control::try_map(items, f))
}

/// Like [`run`], but keeps the GIL: for work that calls Python (torque callbacks).
pub fn run_attached<T>(
    py: Python<'_>,
    progress: Option<&Bound<'_, PyAny>>,
    work: impl FnOnce() -> poinsot::Result<T>,
) -> PyResult<T> {
    let monitor = PyMonitor::new(progress);
    let (result, monitor) = watched(monitor, work);
    monitor.finish(py, result)
}
