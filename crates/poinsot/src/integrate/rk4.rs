//! The classic fixed-step 4th-order Runge–Kutta method.
// Index loops mirror the Butcher-tableau formulas they implement.
#![allow(clippy::needless_range_loop)]

use super::options::Stats;
use super::solution::Solution;
use super::state::{OdeState, OdeSystem};
use crate::error::{check_finite, Error, Result};

/// One classic RK4 step of size `h` from `(t, y)`: returns y(t + h) with a local error O(h⁵).
pub fn rk4_step<S: OdeState, F: OdeSystem<S>>(system: &mut F, t: f64, y: &S, h: f64) -> S {
    let n = y.as_slice().len();
    let mut k1 = y.clone();
    let mut k2 = y.clone();
    let mut k3 = y.clone();
    let mut k4 = y.clone();
    let mut tmp = y.clone();
    let ys = y.as_slice();
    system.rhs(t, y, &mut k1);
    for i in 0..n {
        tmp.as_mut_slice()[i] = ys[i] + 0.5 * h * k1.as_slice()[i];
    }
    system.rhs(t + 0.5 * h, &tmp, &mut k2);
    for i in 0..n {
        tmp.as_mut_slice()[i] = ys[i] + 0.5 * h * k2.as_slice()[i];
    }
    system.rhs(t + 0.5 * h, &tmp, &mut k3);
    for i in 0..n {
        tmp.as_mut_slice()[i] = ys[i] + h * k3.as_slice()[i];
    }
    system.rhs(t + h, &tmp, &mut k4);
    let mut out = y.clone();
    for i in 0..n {
        let (a, b, c, d) = (k1.as_slice()[i], k2.as_slice()[i], k3.as_slice()[i], k4.as_slice()[i]);
        out.as_mut_slice()[i] = ys[i] + h / 6.0 * (a + 2.0 * b + 2.0 * c + d);
    }
    out
}

/// Integrates from `(t0, y0)` to `t_end` with `steps` equal RK4 steps (global error O(h⁴)).
///
/// The solution holds every step (no dense output). Errors name `t0`, `t_end`, `y0` or
/// `steps`; a state that stops being finite is reported as `Diverged` naming `t`.
pub fn rk4<S: OdeState, F: OdeSystem<S>>(mut system: F, t0: f64, y0: S, t_end: f64, steps: usize) -> Result<Solution<S>> {
    check_finite("t0", &[t0])?;
    check_finite("t_end", &[t_end])?;
    check_finite("y0", y0.as_slice())?;
    if steps == 0 {
        return Err(Error::invalid("steps", "must be >= 1, got 0"));
    }
    let h = (t_end - t0) / steps as f64;
    let mut sol = Solution::new(t0, y0.clone());
    let mut y = y0;
    for i in 0..steps {
        let t = t0 + h * i as f64;
        y = rk4_step(&mut system, t, &y, h);
        if y.as_slice().iter().any(|v| !v.is_finite()) {
            return Err(Error::diverged("t", format!("the state stopped being finite at t = {}", t + h)));
        }
        let t_next = if i + 1 == steps { t_end } else { t0 + h * (i + 1) as f64 };
        sol.t.push(t_next);
        sol.y.push(y.clone());
    }
    sol.stats = Stats { accepted: steps, rejected: 0, evaluations: 4 * steps };
    Ok(sol)
}
