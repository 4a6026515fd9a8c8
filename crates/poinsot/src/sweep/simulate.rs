//! Ensembles of rigid bodies under a torque: the final ω and attitude of every point of a grid
//! of moments and initial states, integrated by [`crate::dynamics::simulate_batch`] (the unit's
//! 2.71 with the attitude quaternion).

use super::grid::{Grid, Param};
use crate::dynamics::{simulate_batch, SimulateOptions, Torque};
use crate::error::{check_finite, Error, Result};
use crate::inertia::check_moments;
use crate::rotation::{check_quaternion, Quaternion};

/// The keywords of [`simulate`] that may vary from point to point: `moments` (principal
/// moments, 3 numbers), `omega0` (body angular velocity, 3 numbers) and `attitude0` (unit
/// quaternion `[w, x, y, z]`, 4 numbers; the identity if not given). The duration, torque and
/// integrator settings are those of [`simulate_batch`], one for the whole sweep.
pub const SIMULATE_KEYWORDS: [&str; 3] = ["moments", "omega0", "attitude0"];

/// What a sweep of [`simulate_batch`] gives at one point: the state at the end.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimulatePoint {
    /// The final ω in body components (rad/s).
    pub omega: [f64; 3],
    /// The final attitude, a unit quaternion `[w, x, y, z]` (body → space).
    pub attitude: Quaternion,
}

const IDENTITY: [f64; 4] = [1.0, 0.0, 0.0, 0.0];

struct Inputs<'a> {
    moments: Param<'a>,
    omega0: Param<'a>,
    attitude0: Param<'a>,
}

impl<'a> Inputs<'a> {
    fn of(grid: &Grid<'a>) -> Result<Self> {
        grid.check_keywords("simulate", &SIMULATE_KEYWORDS)?;
        Ok(Self {
            moments: grid.required("moments", 3)?,
            omega0: grid.required("omega0", 3)?,
            attitude0: grid.or_default("attitude0", &IDENTITY)?,
        })
    }

    /// The point's body and start, checked as [`simulate_batch`] checks a row.
    fn check(&self, p: usize) -> Result<()> {
        check_moments(&self.moments.vec3(p))?;
        check_finite("omega0", &self.omega0.vec3(p))?;
        check_quaternion("attitude0", &self.attitude0.vec4(p), false)?;
        Ok(())
    }
}

/// Checks a sweep of [`simulate_batch`]: its settings (`duration`, `dt`, `max_steps`,
/// `method`, `torque`, as [`simulate_batch`] checks them) and every point's moments and start,
/// without integrating anything. Errors name the keyword and the first point at fault.
pub fn check_simulate(
    grid: &Grid<'_>,
    duration: f64,
    torque: &Torque,
    opts: &SimulateOptions,
) -> Result<()> {
    let inputs = Inputs::of(grid)?;
    // The batch of no body checks the settings that do not depend on a body.
    simulate_batch(&[], &[], None, duration, torque, opts)?;
    grid.validate(|p| inputs.check(p))
}

/// Integrates every point of `grid` (its moments, ω₀ and attitude₀) over `duration` under
/// `torque` with `opts` in one [`simulate_batch`] (in parallel, stoppable through
/// [`crate::control`]) after [`check_simulate`] and the memory budget (the batch's inputs and
/// outputs, 17 numbers a point) passed. An error of one body (a step limit, a divergence) is
/// located at its point of the sweep.
pub fn simulate(
    grid: &Grid<'_>,
    duration: f64,
    torque: &Torque,
    opts: &SimulateOptions,
) -> Result<Vec<SimulatePoint>> {
    let inputs = Inputs::of(grid)?;
    grid.check_memory(17 * std::mem::size_of::<f64>())?;
    check_simulate(grid, duration, torque, opts)?;
    let n = grid.len();
    let moments: Vec<[f64; 3]> = (0..n).map(|p| inputs.moments.vec3(p)).collect();
    let omega0: Vec<[f64; 3]> = (0..n).map(|p| inputs.omega0.vec3(p)).collect();
    let attitude0: Vec<Quaternion> = (0..n).map(|p| inputs.attitude0.vec4(p)).collect();
    let out = simulate_batch(&moments, &omega0, Some(&attitude0), duration, torque, opts)
        .map_err(|e| locate_body(grid, e.renamed("t", "duration")))?;
    Ok(out
        .omega
        .into_iter()
        .zip(out.attitude)
        .map(|(omega, attitude)| SimulatePoint { omega, attitude })
        .collect())
}

/// An error of [`simulate_batch`] about one body (its message begins `"body 12: "` or
/// `"row 12: "`) located at that point of the sweep instead; other errors unchanged.
fn locate_body(grid: &Grid<'_>, e: Error) -> Error {
    for word in ["body ", "row "] {
        if let Some(rest) = e.message.strip_prefix(word) {
            if let Some((index, message)) = rest.split_once(": ") {
                if let Ok(i) = index.parse::<usize>() {
                    if i < grid.len() {
                        let located = Error::new(e.kind, e.argument.clone(), message);
                        return grid.at_point(located, i);
                    }
                }
            }
        }
    }
    e
}
