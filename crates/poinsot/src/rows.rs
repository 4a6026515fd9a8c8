//! The rows of a batch of free bodies (moments, initial ω and attitude, one body a row): their
//! counts and every row checked, errors naming the argument and the row. Shared by the batch
//! integration ([`crate::dynamics::simulate_batch`]) and the exact states of many bodies
//! ([`crate::analytic::free_body_states`]), below both.

use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::inertia::check_moments;
use crate::rotation::{check_quaternion, Quaternion};

/// The identity attitude.
pub(crate) const IDENTITY: Quaternion = [1.0, 0.0, 0.0, 0.0];

/// Rows one rayon task checks at least (the batch integration's block of bodies).
const ROWS_PER_TASK: usize = 128;

/// A batch's rows agree: as many `omega0` rows (and `attitude0` rows, when given) as `moments`
/// rows (`n`); else an error naming the argument that differs.
pub(crate) fn check_row_counts(n: usize, omega0: usize, attitude0: Option<usize>) -> Result<()> {
    let differs = |argument: &str, got: usize| {
        Error::invalid(
            argument,
            format!("must have as many rows as moments ({n}), got {got}"),
        )
    };
    if omega0 != n {
        return Err(differs("omega0", omega0));
    }
    match attitude0 {
        Some(a) if a != n => Err(differs("attitude0", a)),
        _ => Ok(()),
    }
}

/// Row `i` of a batch: the moments of a body ([`check_moments`]), a finite ω₀ and an attitude
/// quaternion (the identity when none is given), returned unit; errors name the argument and
/// the row.
pub(crate) fn check_row(
    moments: &[[f64; 3]],
    omega0: &[[f64; 3]],
    attitude0: Option<&[Quaternion]>,
    i: usize,
) -> Result<Quaternion> {
    check_moments(&moments[i]).map_err(|e| in_row(i, e))?;
    if !omega0[i].iter().all(|v| v.is_finite()) {
        return Err(Error::invalid(
            "omega0",
            format!("must be finite, got {:?} at row {i}", omega0[i]),
        ));
    }
    match attitude0 {
        Some(a) => check_quaternion("attitude0", &a[i], false).map_err(|e| in_row(i, e)),
        None => Ok(IDENTITY),
    }
}

/// Every row of a batch ([`check_row`]), in parallel: the error of the first row at fault
/// (the lowest index, whatever the threads).
pub(crate) fn check_every_row(
    moments: &[[f64; 3]],
    omega0: &[[f64; 3]],
    attitude0: Option<&[Quaternion]>,
) -> Result<()> {
    (0..moments.len())
        .into_par_iter()
        .with_min_len(ROWS_PER_TASK)
        .find_map_first(|i| check_row(moments, omega0, attitude0, i).err())
        .map_or(Ok(()), Err)
}

/// `e` with "body {i}: " before its message.
pub(crate) fn in_body(i: usize, e: Error) -> Error {
    Error::new(e.kind, e.argument, format!("body {i}: {}", e.message))
}

/// `e` with "row {i}: " before its message.
pub(crate) fn in_row(i: usize, e: Error) -> Error {
    Error::new(e.kind, e.argument, format!("row {i}: {}", e.message))
}
