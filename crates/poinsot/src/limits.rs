//! Limits on the work one call may ask for: a memory budget for user-sized outputs and a step
//! limit for integrations, both checked **before** any work starts.
//!
//! A request for `samples = 10¹²` would need 8 TB; one for 10¹⁴ steps would run for years. The
//! core refuses both up front, with an error that names the argument, says how much the request
//! needs and how to raise the limit — instead of aborting the process on a failed allocation or
//! running forever.
//!
//! * **Memory budget** ([`memory_budget`], [`set_memory_budget`]): the largest output, in bytes,
//!   one call may allocate — the arrays it returns (time samples, trajectories, polhodes). The
//!   default is [`DEFAULT_MEMORY_BUDGET`]: 4 GiB natively, 1 GiB in WebAssembly (whose address
//!   space is 4 GiB). It bounds what a call returns; the front ends' conversions may hold a
//!   second copy for a moment.
//! * **Step limit**: every integrating call takes a `max_steps` (default
//!   [`DEFAULT_MAX_STEPS`] = 10⁸, about a minute of the slowest method), checked with
//!   [`check_steps`] against the steps the request needs before the first one is taken.

use std::sync::atomic::{AtomicU64, Ordering};

use crate::error::{Error, Result};

/// The default memory budget (bytes): 4 GiB natively, 1 GiB on `wasm32` targets.
pub const DEFAULT_MEMORY_BUDGET: u64 = if cfg!(target_arch = "wasm32") {
    1 << 30
} else {
    4 << 30
};

/// The default step limit of the integrating calls: 10⁸ steps.
pub const DEFAULT_MAX_STEPS: usize = 100_000_000;

/// The smallest budget [`set_memory_budget`] accepts (1 MiB): every documented default run fits.
pub const MIN_MEMORY_BUDGET: u64 = 1 << 20;

static MEMORY_BUDGET: AtomicU64 = AtomicU64::new(DEFAULT_MEMORY_BUDGET);

/// The current memory budget (bytes) of one call's outputs.
pub fn memory_budget() -> u64 {
    MEMORY_BUDGET.load(Ordering::Relaxed)
}

/// Sets the memory budget (bytes, ≥ [`MIN_MEMORY_BUDGET`]) for every later call in this process;
/// returns the previous budget. The error names `bytes`.
pub fn set_memory_budget(bytes: u64) -> Result<u64> {
    if bytes < MIN_MEMORY_BUDGET {
        return Err(Error::invalid(
            "bytes",
            format!("the memory budget must be >= {MIN_MEMORY_BUDGET} (1 MiB), got {bytes}"),
        ));
    }
    Ok(MEMORY_BUDGET.swap(bytes, Ordering::Relaxed))
}

/// A byte count for people: "8.0 TB", "1.5 GB", "12 kB" (SI prefixes).
pub fn human_bytes(bytes: f64) -> String {
    const UNITS: [&str; 7] = ["bytes", "kB", "MB", "GB", "TB", "PB", "EB"];
    let mut value = bytes;
    let mut unit = 0;
    while value >= 1000.0 && unit + 1 < UNITS.len() {
        value /= 1000.0;
        unit += 1;
    }
    if unit == 0 {
        format!("{value:.0} bytes")
    } else {
        format!("{value:.1} {}", UNITS[unit])
    }
}

/// A whole number for a message: all digits below 10¹⁶, exponent form above.
fn whole(x: f64) -> String {
    if x.abs() < 1e16 {
        format!("{x:.0}")
    } else {
        format!("{x:e}")
    }
}

/// Checks that `count` items of `bytes_each` bytes fit in the memory budget; the error names
/// `argument` (the user's count, e.g. `samples`) and says how many bytes the request needs.
///
/// `count` is a float so that products of counts (samples × parcels) cannot overflow on the way.
pub fn check_memory(argument: &str, count: f64, bytes_each: usize) -> Result<()> {
    check_bytes(argument, &whole(count), count * bytes_each as f64)
}

/// Checks that a request of `needed` bytes fits in the memory budget; the error names
/// `argument`, says `what` was asked for (`"1000000000"`, `"8 parcels × 10000000 samples"`) and
/// how many bytes it would need.
pub fn check_bytes(argument: &str, what: &str, needed: f64) -> Result<()> {
    let budget = memory_budget();
    if needed.is_finite() && needed <= budget as f64 {
        return Ok(());
    }
    Err(Error::invalid(
        argument,
        format!(
            "{what} would need {} bytes ({}) of output, more than the memory budget of {budget} bytes \
             ({}); ask for fewer, or raise the budget with set_memory_budget",
            whole(needed),
            human_bytes(needed),
            human_bytes(budget as f64)
        ),
    ))
}

/// Checks a count given by the user: at least `minimum`, and `count` items of `bytes_each` bytes
/// within the memory budget. The error names `argument`.
pub fn check_count(argument: &str, count: usize, minimum: usize, bytes_each: usize) -> Result<()> {
    if count < minimum {
        return Err(Error::invalid(
            argument,
            format!("must be >= {minimum}, got {count}"),
        ));
    }
    check_memory(argument, count as f64, bytes_each)
}

/// Checks that an integration needing `steps` steps (a float: it may be astronomically large)
/// stays within `max_steps`; the error names `max_steps`, says how many steps the request
/// needs and how to ask for fewer.
pub fn check_steps(steps: f64, max_steps: usize, how_to_reduce: &str) -> Result<()> {
    if max_steps == 0 {
        return Err(Error::invalid("max_steps", "must be >= 1, got 0"));
    }
    if steps.is_finite() && steps <= max_steps as f64 {
        return Ok(());
    }
    Err(Error::invalid(
        "max_steps",
        format!(
            "the request needs {steps:.4e} steps, more than max_steps = {max_steps}; raise max_steps to allow it, \
             or {how_to_reduce}"
        ),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn memory_errors_say_how_much_and_name_the_argument() {
        let e = check_memory("samples", 1e12, 112).unwrap_err();
        assert!(e.to_string().starts_with("samples:"), "{e}");
        assert!(
            e.message.contains("112000000000000 bytes (112.0 TB)"),
            "{e}"
        );
        assert!(check_memory("samples", 1001.0, 112).is_ok());
        assert!(check_memory("samples", f64::INFINITY, 8).is_err());
        assert!(check_count("samples", 1, 2, 8)
            .unwrap_err()
            .message
            .contains(">= 2"));
    }

    #[test]
    fn step_errors_say_how_many_steps() {
        let e = check_steps(1e14, DEFAULT_MAX_STEPS, "take a larger dt").unwrap_err();
        assert_eq!(e.argument, "max_steps");
        assert!(e.message.contains("1.0000e14 steps"), "{e}");
        assert!(e.message.contains("larger dt"), "{e}");
        assert!(check_steps(1e8, DEFAULT_MAX_STEPS, "").is_ok());
        assert!(check_steps(f64::NAN, DEFAULT_MAX_STEPS, "").is_err());
    }

    #[test]
    fn human_bytes_reads() {
        assert_eq!(human_bytes(8e12), "8.0 TB");
        assert_eq!(human_bytes(512.0), "512 bytes");
    }
}
