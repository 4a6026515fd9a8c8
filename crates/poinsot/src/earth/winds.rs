//! Horizontal motion under the Coriolis force: inertial oscillations and the flow into a
//! low-pressure centre (the unit's Fig. 2.7).

use super::planet::Earth;
use crate::error::{check_finite, check_non_negative, Error, Result};
use crate::integrate::{dop853_scan, Crossing, Options};

/// An inertial oscillation: a parcel moving horizontally with no force but the Coriolis force.
#[derive(Debug, Clone)]
pub struct InertialRun {
    /// Sample times (s).
    pub t: Vec<f64>,
    /// `[east, north, v_east, v_north]` (m, m/s) at `t`.
    pub states: Vec<[f64; 4]>,
    /// The rate at which the velocity turns (rad/s, counterclockwise seen from above
    /// positive), measured as the integrated turning angle divided by the duration; the
    /// theory says −f = −2 ω sin λ.
    pub turning_rate: f64,
    /// The period measured from the run, 2π/|turning_rate| (s; infinite where the velocity
    /// does not turn): the theory says π/(ω |sin λ|).
    pub measured_period: f64,
}

/// Parcels flowing into a low-pressure centre.
#[derive(Debug, Clone)]
pub struct LowRun {
    /// Sample times (s).
    pub t: Vec<f64>,
    /// For each parcel, `[east, north, v_east, v_north]` at `t` (centre of the low at 0).
    pub parcels: Vec<Vec<[f64; 4]>>,
    /// For each parcel, its energy per unit mass ½ |v|² + ½ k |r|² (J/kg: kinetic plus the
    /// pressure potential; the Coriolis force does no work) at `t`.
    pub energy: Vec<Vec<f64>>,
    /// For each parcel, the work done against friction per unit mass since the start,
    /// ∫ γ |v|² dt (J/kg), at `t`, integrated with the motion: `energy + dissipated` is
    /// constant (the energy budget; its drift measures the integration error).
    pub dissipated: Vec<Vec<f64>>,
    /// The specific angular momentum about the centre, x v_y − y v_x (m²/s), averaged over
    /// the parcels and the run: positive means counterclockwise circulation seen from above.
    pub circulation: f64,
}

/// Every returned number is finite: a run whose samples leave the range of doubles is refused,
/// naming `t_end` (the run is too long, or its scale too large, to be represented).
fn check_outputs<'a>(mut values: impl Iterator<Item = &'a f64>) -> Result<()> {
    if values.all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(Error::invalid(
            "t_end",
            "the motion leaves the range of doubles (overflow) before t_end: shorten the run or rescale it",
        ))
    }
}

impl Earth {
    /// Horizontal motion on a frictionless level surface at `latitude`: only the horizontal
    /// part of the Coriolis force acts (eq. 2.30; the vertical part is held by the ground),
    /// ẍ = f ẏ, ÿ = −f ẋ with f = 2 ω sin λ. Starting at the origin with horizontal
    /// `velocity` `[v_east, v_north]`, integrated to `t_end` and sampled at `times`.
    /// The parcel turns clockwise (right) in the north, counterclockwise in the south, not at
    /// all at the equator; it circles in the inertial period π/(ω |sin λ|).
    pub fn inertial_oscillation(
        &self,
        latitude: f64,
        velocity: [f64; 2],
        t_end: f64,
        times: &[f64],
        options: &Options,
    ) -> Result<InertialRun> {
        let f = self.coriolis_parameter(latitude)?;
        check_finite("velocity", &velocity)?;
        if velocity[0] == 0.0 && velocity[1] == 0.0 {
            return Err(Error::invalid(
                "velocity",
                "must be non-zero (a parcel at rest stays at rest)",
            ));
        }
        check_non_negative("t_end", t_end)?;
        // At least one step per inertial turn (DOP853 takes several): refuse at once a run
        // that needs more than max_steps.
        crate::limits::check_steps(
            t_end * f.abs() / std::f64::consts::TAU,
            options.max_steps,
            "shorten the run",
        )?;
        // State: x, y, vx, vy and the turning angle of the velocity θ, θ̇ = (vx ay − vy ax)/|v|².
        let rhs = |_t: f64, y: &[f64; 5], dy: &mut [f64; 5]| {
            let (vx, vy) = (y[2], y[3]);
            let (ax, ay) = (f * vy, -f * vx);
            *dy = [vx, vy, ax, ay, (vx * ay - vy * ax) / (vx * vx + vy * vy)];
        };
        let y0 = [0.0, 0.0, velocity[0], velocity[1], 0.0];
        let scan = dop853_scan(
            rhs,
            0.0,
            y0,
            t_end,
            times,
            options,
            |_t, _y: &[f64; 5]| 1.0,
            Crossing::Any,
        )?;
        let turning_rate = if t_end > 0.0 {
            scan.y_final[4] / t_end
        } else {
            0.0
        };
        check_outputs(scan.y.iter().flatten().chain([&turning_rate]))?;
        let measured_period = if turning_rate == 0.0 {
            f64::INFINITY
        } else {
            std::f64::consts::TAU / turning_rate.abs()
        };
        let states = scan.y.iter().map(|s| [s[0], s[1], s[2], s[3]]).collect();
        Ok(InertialRun {
            t: scan.t,
            states,
            turning_rate,
            measured_period,
        })
    }

    /// Parcels starting at rest at `starts` (`[east, north]`, m) around a low-pressure centre
    /// at the origin, pulled in by the pressure gradient −k r (`strength` k in 1/s², a
    /// paraboloidal low), slowed by friction −γ v (`friction` γ in 1/s) and turned by the
    /// horizontal Coriolis force −f ẑ × v, integrated to `t_end` and sampled at `times`.
    /// The sense of the circulation is measured from the run ([`LowRun::circulation`]):
    /// counterclockwise in the north, clockwise in the south (Fig. 2.7).
    #[allow(clippy::too_many_arguments)]
    pub fn flow_into_low(
        &self,
        latitude: f64,
        starts: &[[f64; 2]],
        strength: f64,
        friction: f64,
        t_end: f64,
        times: &[f64],
        options: &Options,
    ) -> Result<LowRun> {
        if starts.is_empty() {
            return Err(Error::invalid("starts", "must hold at least one parcel"));
        }
        for s in starts {
            check_finite("starts", s)?;
        }
        let states: Vec<[f64; 4]> = starts.iter().map(|s| [s[0], s[1], 0.0, 0.0]).collect();
        self.flow_into_low_from(
            latitude, &states, 0.0, strength, friction, t_end, times, options,
        )
    }

    /// [`Earth::flow_into_low`] from any states: parcels in `states` (`[east, north, v_east,
    /// v_north]`, m and m/s) at time `t0` (s), integrated to `t_end` (≥ `t0`) and sampled at
    /// `times` (in [`t0`, `t_end`], increasing). The circulation is averaged over
    /// [`t0`, `t_end`] and the dissipated work counted from `t0`. Continuing a run from one of
    /// its samples gives the state at any later time (the browser lab evaluates its
    /// animation so).
    #[allow(clippy::too_many_arguments)]
    pub fn flow_into_low_from(
        &self,
        latitude: f64,
        states: &[[f64; 4]],
        t0: f64,
        strength: f64,
        friction: f64,
        t_end: f64,
        times: &[f64],
        options: &Options,
    ) -> Result<LowRun> {
        let f = self.coriolis_parameter(latitude)?;
        crate::error::check_positive("strength", strength)?;
        check_non_negative("friction", friction)?;
        check_finite("t0", &[t0])?;
        check_finite("t_end", &[t_end])?;
        if t_end < t0 {
            return Err(Error::invalid(
                "t_end",
                format!("must be >= t0 = {t0}, got {t_end}"),
            ));
        }
        if states.is_empty() {
            return Err(Error::invalid("states", "must hold at least one parcel"));
        }
        for s in states {
            check_finite("states", s)?;
        }
        let (k, gamma) = (strength, friction);
        // At least one step per turn at the fastest rate, per parcel: a lower bound on the steps.
        crate::limits::check_steps(
            (t_end - t0) * (k.sqrt() + f.abs() + gamma) / std::f64::consts::TAU,
            options.max_steps,
            "shorten the run",
        )?;
        // k |r|² as (k x) x: no overflow of x² for a large ring with a weak pull.
        let energy_of = |y: &[f64]| {
            0.5 * (y[2] * y[2] + y[3] * y[3]) + 0.5 * ((k * y[0]) * y[0] + (k * y[1]) * y[1])
        };
        let span = t_end - t0;
        let mut parcels = Vec::with_capacity(states.len());
        let mut energy = Vec::with_capacity(states.len());
        let mut dissipated = Vec::with_capacity(states.len());
        let mut circulation = 0.0;
        for s in states {
            // State: x, y, vx, vy, ∫ (x vy − y vx) dt and ∫ γ |v|² dt.
            let rhs = |_t: f64, y: &[f64; 6], dy: &mut [f64; 6]| {
                let (x, yy, vx, vy) = (y[0], y[1], y[2], y[3]);
                *dy = [
                    vx,
                    vy,
                    -k * x - gamma * vx + f * vy,
                    -k * yy - gamma * vy - f * vx,
                    x * vy - yy * vx,
                    gamma * (vx * vx + vy * vy),
                ];
            };
            let y0 = [s[0], s[1], s[2], s[3], 0.0, 0.0];
            let scan = dop853_scan(
                rhs,
                t0,
                y0,
                t_end,
                times,
                options,
                |_t, _y: &[f64; 6]| 1.0,
                Crossing::Any,
            )?;
            if span > 0.0 {
                circulation += scan.y_final[4] / span;
            }
            parcels.push(scan.y.iter().map(|y| [y[0], y[1], y[2], y[3]]).collect());
            let e: Vec<f64> = scan.y.iter().map(|y| energy_of(y)).collect();
            check_outputs(scan.y.iter().flatten().chain(e.iter()))?;
            energy.push(e);
            dissipated.push(scan.y.iter().map(|y| y[5]).collect());
        }
        circulation /= states.len() as f64;
        check_outputs([&circulation].into_iter())?;
        Ok(LowRun {
            t: times.to_vec(),
            parcels,
            energy,
            dissipated,
            circulation,
        })
    }
}
