//! Stopping long computations, and reporting their progress.
//!
//! Every long loop of the core (integration steps, samples of a trajectory, triangles of a
//! mesh, bodies of a batch) calls [`tick`] once per unit of work, and [`report`] when it knows
//! how far it has come. Both cost a few nanoseconds. Every [`TICKS_PER_POLL`] ticks the
//! [`Monitor`] installed on the calling thread by [`watched`] is asked whether to go on; when it
//! returns an error the loop stops and the call returns that error — by convention of kind
//! [`crate::ErrorKind::Interrupted`].
//!
//! The core knows no clocks and no signals: a front end supplies the monitor. The Python
//! bindings install one that, at most every [`POLL_PERIOD_MS`] of wall-clock time, checks for
//! Ctrl-C and calls the user's progress callback; a callback that raises stops the run. Without
//! a monitor, ticks cost one thread-local counter increment.
//!
//! Parallel work (rayon) runs on other threads, which have no monitor: [`parallel`] runs it on a
//! helper thread while the calling thread keeps polling its monitor, and tells the workers to
//! stop through a shared [`Cancel`] flag.

use std::cell::{Cell, RefCell};
use std::rc::Rc;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::Arc;

use crate::error::{Error, ErrorKind, Result};

/// How often, in ticks, the monitor is polled (a power of two).
pub const TICKS_PER_POLL: u32 = 1024;

/// The wall-clock interval (ms) at which a front end's monitor should look for an interrupt:
/// 20 ms, so that Ctrl-C stops any run within a tenth of a second.
pub const POLL_PERIOD_MS: u64 = 20;

/// Watches a long computation: asked every [`TICKS_PER_POLL`] ticks whether to go on.
pub trait Monitor {
    /// `progress` is the fraction of the work done, in [0, 1], as last reported by the
    /// computation (0 before the first report). An error stops the computation, which returns
    /// it.
    fn poll(&mut self, progress: f64) -> Result<()>;
}

type Shared = Rc<RefCell<dyn Monitor>>;

thread_local! {
    static MONITOR: RefCell<Option<Shared>> = const { RefCell::new(None) };
    static TICKS: Cell<u32> = const { Cell::new(0) };
    static PROGRESS: Cell<f64> = const { Cell::new(0.0) };
}

/// Restores the previous monitor and progress when [`watched`] ends (also on unwinding).
struct Restore(Option<Shared>, f64);

impl Drop for Restore {
    fn drop(&mut self) {
        let previous = self.0.take();
        MONITOR.with(|m| *m.borrow_mut() = previous);
        PROGRESS.with(|p| p.set(self.1));
    }
}

/// Runs `work` with `monitor` watching it on this thread, and returns the result with the
/// monitor (to read back what it recorded). Calls nest: the previous monitor is restored after.
pub fn watched<M: Monitor + 'static, R>(monitor: M, work: impl FnOnce() -> R) -> (R, M) {
    let cell = Rc::new(RefCell::new(monitor));
    let shared: Shared = cell.clone();
    let previous = MONITOR.with(|m| m.borrow_mut().replace(shared));
    let restore = Restore(previous, PROGRESS.with(|p| p.replace(0.0)));
    let result = work();
    drop(restore);
    match Rc::try_unwrap(cell) {
        Ok(cell) => (result, cell.into_inner()),
        // Unreachable: `restore` dropped the only other reference.
        Err(_) => unreachable!("the monitor is still installed"),
    }
}

/// Whether a monitor watches this thread.
pub fn is_watched() -> bool {
    MONITOR.with(|m| m.borrow().is_some())
}

fn poll() -> Result<()> {
    let Some(monitor) = MONITOR.with(|m| m.borrow().clone()) else {
        return Ok(());
    };
    let progress = PROGRESS.with(Cell::get);
    // A monitor that calls back into the core (a progress callback computing something) is
    // not polled again from inside itself.
    let Ok(mut monitor) = monitor.try_borrow_mut() else {
        return Ok(());
    };
    monitor.poll(progress)
}

/// One unit of work done: polls the monitor every [`TICKS_PER_POLL`] ticks.
#[inline]
pub fn tick() -> Result<()> {
    let n = TICKS.with(|t| {
        let n = t.get().wrapping_add(1);
        t.set(n);
        n
    });
    if n.is_multiple_of(TICKS_PER_POLL) {
        poll()
    } else {
        Ok(())
    }
}

/// `k` units of work done at once (polls at most once).
#[inline]
pub fn tick_by(k: u32) -> Result<()> {
    let (before, after) = TICKS.with(|t| {
        let before = t.get();
        let after = before.wrapping_add(k);
        t.set(after);
        (before, after)
    });
    if before / TICKS_PER_POLL != after / TICKS_PER_POLL || k >= TICKS_PER_POLL {
        poll()
    } else {
        Ok(())
    }
}

/// Records the fraction of the work done (clamped to [0, 1]) and ticks.
#[inline]
pub fn report(fraction: f64) -> Result<()> {
    PROGRESS.with(|p| p.set(fraction.clamp(0.0, 1.0)));
    tick()
}

/// The error a monitor returns to stop a run (the front end keeps its own, richer error).
pub fn interrupted() -> Error {
    Error::new(
        ErrorKind::Interrupted,
        "interrupt",
        "the computation was stopped before it finished",
    )
}

/// A stop flag and a progress counter shared by the threads of a parallel computation.
#[derive(Debug, Default)]
pub struct Cancel {
    stop: AtomicBool,
    done: AtomicU64,
    total: u64,
}

impl Monitor for Arc<Cancel> {
    /// Stops once the shared flag is set: install it with [`watched`] on a worker thread so
    /// that the worker's loops obey the flag.
    fn poll(&mut self, _progress: f64) -> Result<()> {
        self.check()
    }
}

impl Cancel {
    /// A flag for a computation of `total` units of work (for the progress fraction).
    pub fn new(total: u64) -> Self {
        Self {
            stop: AtomicBool::new(false),
            done: AtomicU64::new(0),
            total,
        }
    }

    /// Asks the workers to stop.
    pub fn cancel(&self) {
        self.stop.store(true, Ordering::Relaxed);
    }

    /// An [`interrupted`] error once [`Cancel::cancel`] was called.
    #[inline]
    pub fn check(&self) -> Result<()> {
        if self.stop.load(Ordering::Relaxed) {
            Err(interrupted())
        } else {
            Ok(())
        }
    }

    /// Counts `k` more units of work done.
    #[inline]
    pub fn advance(&self, k: u64) {
        self.done.fetch_add(k, Ordering::Relaxed);
    }

    /// The fraction of the work done, in [0, 1].
    pub fn progress(&self) -> f64 {
        if self.total == 0 {
            0.0
        } else {
            (self.done.load(Ordering::Relaxed) as f64 / self.total as f64).min(1.0)
        }
    }
}

/// Marks a parallel computation done and wakes the thread waiting for it, when dropped (at the
/// end of the work, or while a panic unwinds it).
#[cfg(not(target_arch = "wasm32"))]
struct Done<'a>(&'a AtomicBool, std::thread::Thread);

#[cfg(not(target_arch = "wasm32"))]
impl Drop for Done<'_> {
    fn drop(&mut self) {
        self.0.store(true, Ordering::Release);
        self.1.unpark();
    }
}

/// Runs `work` (which may fan out with rayon; it should call [`Cancel::check`] and
/// [`Cancel::advance`] regularly) so that this thread's monitor keeps being polled: on a helper
/// thread while this one polls every [`POLL_PERIOD_MS`], when a monitor watches this thread;
/// directly otherwise (and always on targets without threads).
pub fn parallel<R: Send>(
    total: u64,
    work: impl FnOnce(&Arc<Cancel>) -> Result<R> + Send,
) -> Result<R> {
    let cancel = Arc::new(Cancel::new(total));
    #[cfg(not(target_arch = "wasm32"))]
    if is_watched() {
        // Set (and the caller woken) when the work ends, also by a panic: waiting for
        // `is_finished` instead left the caller parked for another poll period whenever the
        // thread had not quite exited when it woke (5–10 ms lost by a short call).
        let done = AtomicBool::new(false);
        return std::thread::scope(|scope| {
            let caller = std::thread::current();
            let shared = &cancel;
            let done_ref = &done;
            let worker = scope.spawn(move || {
                let _done = Done(done_ref, caller);
                work(shared)
            });
            let mut stopped: Option<Error> = None;
            while !done.load(Ordering::Acquire) {
                std::thread::park_timeout(std::time::Duration::from_millis(POLL_PERIOD_MS));
                if stopped.is_none() {
                    PROGRESS.with(|p| p.set(cancel.progress()));
                    if let Err(e) = poll() {
                        cancel.cancel();
                        stopped = Some(e);
                    }
                }
            }
            let result = match worker.join() {
                Ok(r) => r,
                Err(payload) => std::panic::resume_unwind(payload),
            };
            match stopped {
                Some(e) => Err(e),
                None => result,
            }
        });
    }
    work(&cancel)
}

/// Items per chunk of the array loops ([`try_map`], [`try_map_n`], [`fill_chunks`]): the
/// monitor (or, in parallel, the stop flag) is asked between two chunks, so that Ctrl-C stops
/// an evaluation over a user's array within a poll period whatever its length.
pub const CHUNK: usize = 1024;

/// Parallel loops of fewer chunks than this run without the watching thread of [`parallel`]
/// (starting it costs more than such a loop takes).
const WATCHED_CHUNKS: usize = 16;

/// `f(i)` for `i` in `0..n`, in order, on this thread, the monitor polled every [`CHUNK`]
/// items; the first error stops the loop.
pub fn try_map_n<R>(n: usize, mut f: impl FnMut(usize) -> Result<R>) -> Result<Vec<R>> {
    let mut out = Vec::with_capacity(n);
    let mut start = 0;
    while start < n {
        let end = (start + CHUNK).min(n);
        tick_by(CHUNK as u32)?;
        for i in start..end {
            out.push(f(i)?);
        }
        start = end;
    }
    Ok(out)
}

/// `f` of each of `items`, in order, on this thread, the monitor polled every [`CHUNK`] items:
/// the loop of an evaluation over an array. The first error stops the loop.
pub fn try_map<T, R>(items: &[T], mut f: impl FnMut(&T) -> Result<R>) -> Result<Vec<R>> {
    try_map_n(items.len(), |i| f(&items[i]))
}

/// Fills `out` chunk by chunk: `f(start, chunk)` for consecutive chunks of `chunk` elements
/// (the last one shorter), `start` the index in `out` of the chunk's first element. With
/// `parallel` the chunks run on rayon's threads under [`parallel`] (each one first checks the
/// stop flag, so Ctrl-C stops the loop within a chunk's time); otherwise in order on this
/// thread, the monitor polled before each chunk. Returns the error of a failing chunk: the
/// first on this thread, any one in parallel (a caller that must name the first failing
/// element looks for it again, unless the error is [`ErrorKind::Interrupted`]).
pub fn fill_chunks<T: Send>(
    out: &mut [T],
    chunk: usize,
    parallel: bool,
    f: impl Fn(usize, &mut [T]) -> Result<()> + Sync + Send,
) -> Result<()> {
    use rayon::prelude::*;
    let chunk = chunk.max(1);
    if !parallel {
        let ticks = u32::try_from(chunk).unwrap_or(u32::MAX);
        for (c, ys) in out.chunks_mut(chunk).enumerate() {
            tick_by(ticks)?;
            f(c * chunk, ys)?;
        }
        return Ok(());
    }
    let chunks = out.len().div_ceil(chunk);
    if chunks < WATCHED_CHUNKS {
        return out
            .par_chunks_mut(chunk)
            .enumerate()
            .try_for_each(|(c, ys)| f(c * chunk, ys));
    }
    self::parallel(out.len() as u64, |cancel| {
        out.par_chunks_mut(chunk)
            .enumerate()
            .try_for_each(|(c, ys)| {
                cancel.check()?;
                f(c * chunk, ys)?;
                cancel.advance(ys.len() as u64);
                Ok(())
            })
    })
}

/// `f(range)` for consecutive ranges of `chunk` indices covering `0..n`, as [`fill_chunks`]
/// (in parallel or on this thread, stoppable between two ranges): a loop that writes nothing
/// or writes into several buffers.
pub fn for_ranges(
    n: usize,
    chunk: usize,
    parallel: bool,
    f: impl Fn(std::ops::Range<usize>) -> Result<()> + Sync + Send,
) -> Result<()> {
    // Zero-sized elements: the vector allocates nothing.
    let mut units = vec![(); n];
    fill_chunks(&mut units, chunk, parallel, |start, c| {
        f(start..start + c.len())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Stops after `limit` polls and counts them.
    struct StopAfter {
        polls: usize,
        limit: usize,
        last_progress: f64,
    }

    impl Monitor for StopAfter {
        fn poll(&mut self, progress: f64) -> Result<()> {
            self.polls += 1;
            self.last_progress = progress;
            if self.polls >= self.limit {
                Err(interrupted())
            } else {
                Ok(())
            }
        }
    }

    fn count_to(n: u64) -> Result<u64> {
        let mut i = 0;
        while i < n {
            i += 1;
            report(i as f64 / n as f64)?;
        }
        Ok(i)
    }

    #[test]
    fn a_monitor_stops_a_loop_and_sees_its_progress() {
        let monitor = StopAfter {
            polls: 0,
            limit: 3,
            last_progress: 0.0,
        };
        let (result, m) = watched(monitor, || count_to(1_000_000));
        let err = result.unwrap_err();
        assert_eq!(err.kind, ErrorKind::Interrupted);
        assert_eq!(m.polls, 3);
        assert!(
            m.last_progress > 0.0 && m.last_progress < 0.01,
            "{}",
            m.last_progress
        );
        // Negative control: without a monitor the same loop runs to the end.
        assert_eq!(count_to(100_000).unwrap(), 100_000);
        assert!(!is_watched());
    }

    #[test]
    fn monitors_nest() {
        let outer = StopAfter {
            polls: 0,
            limit: usize::MAX,
            last_progress: 0.0,
        };
        let (r, outer) = watched(outer, || {
            let inner = StopAfter {
                polls: 0,
                limit: usize::MAX,
                last_progress: 0.0,
            };
            let (r, inner) = watched(inner, || count_to(10_000));
            assert!(inner.polls >= 9);
            r.and_then(|_| count_to(10_000))
        });
        assert!(r.is_ok());
        assert!(outer.polls >= 9 && outer.polls <= 11, "{}", outer.polls);
    }

    #[test]
    fn parallel_work_is_stopped_through_the_flag() {
        let monitor = StopAfter {
            polls: 0,
            limit: 2,
            last_progress: 0.0,
        };
        let (result, m) = watched(monitor, || {
            parallel(1000, |cancel| {
                loop {
                    cancel.check()?;
                    cancel.advance(1);
                    std::thread::sleep(std::time::Duration::from_millis(1));
                }
                #[allow(unreachable_code)]
                Ok(())
            })
        });
        assert_eq!(result.unwrap_err().kind, ErrorKind::Interrupted);
        assert_eq!(m.polls, 2);
        assert!(m.last_progress > 0.0);
        // Without a monitor, the work runs on this thread to the end.
        assert_eq!(
            parallel(10, |c| {
                c.advance(10);
                Ok(c.progress())
            })
            .unwrap(),
            1.0
        );
    }
}
