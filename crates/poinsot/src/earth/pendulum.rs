//! The Foucault pendulum, integrated in the rotating local frame.

use super::pendulum_measurement::{check_turning_points, PlaneFit};
use super::planet::{check_latitude, Earth};
use crate::error::{check_finite, check_positive, Error, Result};
use crate::frames::ParticleState;
use crate::integrate::{dop853_scan, Crossing, Options, Stats};
use crate::Vec3;

/// A run of the Foucault pendulum.
#[derive(Debug, Clone)]
pub struct FoucaultRun {
    /// Sample times (s).
    pub t: Vec<f64>,
    /// The bob's state `[x, y, z, vx, vy, vz]` (ENU, origin at the point of suspension) at `t`.
    pub states: Vec<ParticleState>,
    /// Times of the turning points of the swing: the largest distances of the bob from its
    /// rest position ([`super::FoucaultTheory::rest`]), located by the integrator's events (s).
    pub turn_times: Vec<f64>,
    /// Direction of the bob from its rest position at each turning point, in the plane of
    /// small swings, counterclockwise from east seen from above (rad, in (−π, π]).
    pub turn_angles: Vec<f64>,
    /// The state at the end of the run.
    pub final_state: ParticleState,
    /// Work counters.
    pub stats: Stats,
}

/// The slope (rad/s) of the swing-plane angle through the turning points, by least squares
/// after unwrapping the angles modulo π (a swing plane has no head or tail). Errors name
/// `turn_times` if fewer than 3 turning points are given, the arrays differ in length or the
/// times do not increase, and `turn_angles` if an angle is not finite. Whether the slope is a
/// rate of turn at all is [`Earth::foucault_measurement`]'s to say.
pub fn fit_precession_rate(turn_times: &[f64], turn_angles: &[f64]) -> Result<f64> {
    check_turning_points(turn_times, turn_angles)?;
    if turn_times.len() < 3 {
        return Err(Error::invalid(
            "turn_times",
            format!(
                "need at least 3 turning points to fit a rate, got {} (run longer)",
                turn_times.len()
            ),
        ));
    }
    let mut fit = PlaneFit::new(0.0);
    for (&t, &a) in turn_times.iter().zip(turn_angles) {
        fit.push(t, a);
    }
    debug_assert_eq!(fit.len(), turn_times.len());
    Ok(fit.slope().unwrap_or(0.0))
}

impl Earth {
    /// The energy per unit mass in the rotating local frame (J/kg), Jacobi's integral, of a
    /// particle in `state` `[x, y, z, vx, vy, vz]` (ENU, m and m/s) at `latitude` (rad):
    ///
    /// J = ½ |ṙ|² + g z − ½ |ω × r|²,
    ///
    /// the kinetic energy relative to the Earth plus the potentials of uniform gravity and of
    /// the centrifugal force −ω × (ω × r) (eq. 2.30; ẑ is the plumb line at the origin, whose
    /// centrifugal part is in g). The Coriolis force −2 ω × ṙ is perpendicular to ṙ and does no
    /// work, and neither does a pendulum's string, so J is constant along [`Earth::foucault`]
    /// and along the uniform-gravity [`Earth::drop`]: its drift measures the integration error.
    pub fn jacobi_integral(&self, latitude: f64, state: &ParticleState) -> Result<f64> {
        check_latitude(latitude)?;
        check_finite("state", state)?;
        let w = self.omega_enu_unchecked(latitude);
        let r = Vec3::new(state[0], state[1], state[2]);
        let v = Vec3::new(state[3], state[4], state[5]);
        // Each term finite, or the error names the half of the state it comes from.
        let kinetic = crate::error::finite_result(
            "velocity",
            "the kinetic energy ½|v|²",
            0.5 * v.norm_squared(),
        )?;
        let potential = crate::error::finite_result(
            "position",
            "the potential g z − ½|ω × r|²",
            self.g * r.z - 0.5 * w.cross(&r).norm_squared(),
        )?;
        crate::error::finite_result("velocity", "Jacobi's integral", kinetic + potential)
    }

    /// The state of a Foucault pendulum of `length` (m) at `latitude` (rad) released from
    /// rest in the rotating frame, its bob moved by `amplitude` (m, < length) from its rest
    /// position ([`Earth::foucault_theory`]) towards `azimuth` (rad, clockwise from north) along
    /// the sphere of the string: at distance `amplitude` from the string's line at rest. Origin
    /// at the point of suspension. (The rest position hangs off the plumb line of the
    /// suspension by the tilt φ ≈ (ω²L/2g) sin 2λ: 1e-8 rad on the Earth, 0.02 rad for a 80 m
    /// pendulum on a planet turning in 86 s.)
    pub fn foucault_release(
        &self,
        latitude: f64,
        length: f64,
        amplitude: f64,
        azimuth: f64,
    ) -> Result<ParticleState> {
        let theory = self.foucault_theory(latitude, length)?;
        check_positive("amplitude", amplitude)?;
        check_finite("azimuth", &[azimuth])?;
        if amplitude >= length {
            return Err(Error::invalid(
                "amplitude",
                format!("must be < length ({length} m), got {amplitude}"),
            ));
        }
        let (s, c) = azimuth.sin_cos();
        let along = (length - amplitude).sqrt() * (length + amplitude).sqrt();
        let r = along / length * theory.rest + amplitude * (s * theory.east + c * theory.north);
        Ok([r.x, r.y, r.z, 0.0, 0.0, 0.0])
    }

    /// Integrates a Foucault pendulum — a spherical pendulum of `length` (m) — in the
    /// rotating frame at `latitude` from `state0` at `t0` to `t_end`:
    ///
    /// r̈ = −g ẑ − 2 ω × ṙ − ω × (ω × r) + λ r,
    ///
    /// the string tension λ r keeping |r| = length (with Baumgarte stabilisation at the
    /// pendulum's own frequency √(g/L)). Returns the states at `times` and every turning
    /// point of the swing — the largest distances from the rest position of
    /// [`Earth::foucault_theory`], about which the bob swings (on a fast planet it hangs
    /// visibly off the plumb line of the suspension; distances from that line would mix the
    /// offset into the swing). [`Earth::foucault_measurement`] fits them and says whether the
    /// plane turns steadily: at ≈ [`Earth::foucault_rate`] = −ω sin λ on a slowly turning
    /// planet, clockwise seen from above in the north.
    #[allow(clippy::too_many_arguments)]
    pub fn foucault(
        &self,
        latitude: f64,
        length: f64,
        state0: ParticleState,
        t0: f64,
        t_end: f64,
        times: &[f64],
        options: &Options,
    ) -> Result<FoucaultRun> {
        let theory = self.foucault_theory(latitude, length)?;
        check_finite("state0", &state0)?;
        let r0 = Vec3::new(state0[0], state0[1], state0[2]);
        if ((r0.norm() - length) / length).abs() > 1e-6 {
            return Err(Error::invalid(
                "state0",
                format!(
                    "the bob must be at distance length = {length} m from the suspension, got {}",
                    r0.norm()
                ),
            ));
        }
        let w = self.omega_enu_unchecked(latitude);
        let g = self.g;
        let beta = (g / length).sqrt();
        // DOP853 takes several steps per swing: one per swing is a lower bound on the steps the
        // request needs, checked before the first (a century-long run is refused at once).
        crate::limits::check_steps(
            (t_end - t0).abs() * (beta + w.norm()) / std::f64::consts::TAU,
            options.max_steps,
            "shorten the run",
        )?;
        let rhs = |_t: f64, y: &ParticleState, dy: &mut ParticleState| {
            let r = Vec3::new(y[0], y[1], y[2]);
            let v = Vec3::new(y[3], y[4], y[5]);
            let free = Vec3::new(0.0, 0.0, -g) - 2.0 * w.cross(&v) - w.cross(&w.cross(&r));
            let r2 = r.norm_squared();
            // C = (|r|² − L²)/2, Ċ = r·v, and C̈ + 2βĊ + β²C = 0 fixes the tension.
            let c = 0.5 * (r2 - length * length);
            let lambda =
                -(v.norm_squared() + r.dot(&free) + 2.0 * beta * r.dot(&v) + beta * beta * c) / r2;
            let a = free + lambda * r;
            *dy = [v.x, v.y, v.z, a.x, a.y, a.z];
        };
        // Turning points: d|r − rest|²/dt = 2 (r − rest)·v goes from + to −.
        let rest = theory.rest;
        let event = |_t: f64, y: &ParticleState| {
            (y[0] - rest.x) * y[3] + (y[1] - rest.y) * y[4] + (y[2] - rest.z) * y[5]
        };
        let scan = dop853_scan(
            rhs,
            t0,
            state0,
            t_end,
            times,
            options,
            event,
            Crossing::Falling,
        )?;
        let turn_times = scan.crossings.iter().map(|h| h.t).collect();
        let turn_angles = scan
            .crossings
            .iter()
            .map(|h| theory.swing_angle(&Vec3::new(h.y[0], h.y[1], h.y[2])))
            .collect();
        Ok(FoucaultRun {
            t: scan.t,
            states: scan.y,
            turn_times,
            turn_angles,
            final_state: scan.y_final,
            stats: scan.stats,
        })
    }
}
