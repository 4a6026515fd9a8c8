//! A particle integrated in a moving frame with every fictitious force (eqs. 2.5, 2.26–2.30),
//! and the same particle integrated in the fixed frame for comparison.

use super::motion::FrameMotion;
use crate::error::{check_finite, check_positive, Error, Result};
use crate::integrate::{dop853_scan, dop853_until, Crossing, Options, Scan, Solution};
use crate::Vec3;

/// A particle's state `[x, y, z, vx, vy, vz]` (m, m/s).
pub type ParticleState = [f64; 6];

/// Splits a state into position and velocity.
#[inline]
pub(crate) fn split(y: &ParticleState) -> (Vec3, Vec3) {
    (Vec3::new(y[0], y[1], y[2]), Vec3::new(y[3], y[4], y[5]))
}

/// −R̈ − 2ω×ṙ − ω×(ω×r) − ω̇×r in moving components (the fictitious forces per unit mass).
#[inline]
fn fictitious_acceleration<M: FrameMotion + ?Sized>(frame: &M, t: f64, r: &Vec3, v: &Vec3) -> Vec3 {
    let (acc, w, wd) = frame.moving_components(t);
    -acc - 2.0 * w.cross(v) - w.cross(&w.cross(r)) - wd.cross(r)
}

/// Checks the start of a run in a moving frame: `1/mass` finite, and each fictitious term
/// finite at `(t0, position, velocity)`, so that an overflow is blamed on the argument that
/// causes it (`mass`, `frame`, `velocity` for Coriolis, `position` for the centrifugal and
/// Euler terms) instead of on the integrator.
fn check_start<M: FrameMotion + ?Sized>(
    frame: &M,
    mass: f64,
    t0: f64,
    r: &Vec3,
    v: &Vec3,
) -> Result<()> {
    check_positive("mass", mass)?;
    check_finite("position", r.as_slice())?;
    check_finite("velocity", v.as_slice())?;
    let finite = |x: Vec3| x.iter().all(|c| c.is_finite());
    if !(1.0 / mass).is_finite() {
        return Err(Error::invalid(
            "mass",
            format!("1/mass overflows for mass = {}", crate::error::num(mass)),
        ));
    }
    let (acc, w, wd) = frame.moving_components(t0);
    if !(finite(acc) && finite(w) && finite(wd)) {
        return Err(Error::invalid(
            "frame",
            "the frame's acceleration or angular velocity is not finite at the start",
        ));
    }
    if !finite(2.0 * w.cross(v)) {
        return Err(Error::invalid(
            "velocity",
            "the Coriolis acceleration 2 ω × v overflows at the start",
        ));
    }
    if !finite(w.cross(&w.cross(r)) + wd.cross(r)) {
        return Err(Error::invalid(
            "position",
            "the centrifugal or Euler acceleration overflows at this position",
        ));
    }
    Ok(())
}

/// The particle's run as the front ends offer it (`poinsot.simulate_particle` in Python,
/// `simulateParticle` in the browser lab): like [`simulate_particle`] from t = 0 to `duration`
/// (s, finite, ≥ 0), but returns only the states at the times `t_eval` (monotone, inside
/// `[0, duration]`) without keeping the steps — the fast path when few outputs are wanted.
///
/// Errors name the caller's arguments: `mass`, `position`, `velocity`, `frame` (its state not
/// finite at the start), `duration` (not finite or negative; also an integration that fails
/// before the end, the time it failed in the message), `t_eval`, `force` (a force not finite
/// at the start), `rtol`, `atol`, `max_steps`.
#[allow(clippy::too_many_arguments)]
pub fn simulate_particle_at<M, F>(
    frame: &M,
    mass: f64,
    position: Vec3,
    velocity: Vec3,
    duration: f64,
    t_eval: &[f64],
    mut force: F,
    opts: &Options,
) -> Result<Scan<ParticleState>>
where
    M: FrameMotion + ?Sized,
    F: FnMut(f64, &Vec3, &Vec3) -> Vec3,
{
    check_start(frame, mass, 0.0, &position, &velocity)?;
    crate::error::check_non_negative("duration", duration)?;
    let y0 = [
        position.x, position.y, position.z, velocity.x, velocity.y, velocity.z,
    ];
    let inv_mass = 1.0 / mass;
    let rhs = |t: f64, y: &ParticleState, dy: &mut ParticleState| {
        let (r, v) = split(y);
        let a = force(t, &r, &v) * inv_mass + fictitious_acceleration(frame, t, &r, &v);
        *dy = [v.x, v.y, v.z, a.x, a.y, a.z];
    };
    dop853_scan(
        rhs,
        0.0,
        y0,
        duration,
        t_eval,
        opts,
        |_t: f64, _y: &ParticleState| 1.0,
        Crossing::Any,
    )
    .map_err(callers_names)
}

/// The integrator's names (`times`, `t_end`, `t` of a failing step, `y0` of a right-hand side
/// not finite at the start) as the arguments of [`simulate_particle_at`] that they come from.
fn callers_names(mut e: Error) -> Error {
    e.argument = match e.argument.as_str() {
        "times" => "t_eval",
        "t_end" | "t" => "duration",
        "y0" => "force",
        _ => return e,
    }
    .into();
    e
}

/// Integrates a particle of `mass` (kg) relative to the moving `frame` from `t0` to `t_end`:
///
/// m (d²r/dt²)_rot = F − m R̈ − 2 m ω × ṙ − m ω × (ω × r) − m ω̇ × r,
///
/// all in moving components (ω, ω̇ and R̈ taken from `frame.at(t)` and turned into moving
/// components with its attitude). `force(t, r, ṙ)` is the true force in moving components
/// (N). `position` and `velocity` are the initial r and (dr/dt)_rot. Adaptive DOP853 with
/// `opts`. The optional terminal `event(t, state)` stops the integration at its first
/// crossing of kind `crossing`.
///
/// Errors name `mass`, `position`, `velocity`, `t0`, `t_end` or an option; a failing
/// integration names `t`.
#[allow(clippy::too_many_arguments)]
pub fn simulate_particle<M, F, G>(
    frame: &M,
    mass: f64,
    position: Vec3,
    velocity: Vec3,
    t0: f64,
    t_end: f64,
    mut force: F,
    opts: &Options,
    event: Option<(G, Crossing)>,
) -> Result<Solution<ParticleState>>
where
    M: FrameMotion + ?Sized,
    F: FnMut(f64, &Vec3, &Vec3) -> Vec3,
    G: FnMut(f64, &ParticleState) -> f64,
{
    check_start(frame, mass, t0, &position, &velocity)?;
    let y0 = [
        position.x, position.y, position.z, velocity.x, velocity.y, velocity.z,
    ];
    let rhs = |t: f64, y: &ParticleState, dy: &mut ParticleState| {
        let (r, v) = split(y);
        let a = force(t, &r, &v) / mass + fictitious_acceleration(frame, t, &r, &v);
        *dy = [v.x, v.y, v.z, a.x, a.y, a.z];
    };
    match event {
        Some((g, crossing)) => dop853_until(rhs, t0, y0, t_end, opts, g, crossing),
        None => dop853_until(
            rhs,
            t0,
            y0,
            t_end,
            opts,
            |_t: f64, _y: &ParticleState| 1.0,
            Crossing::Any,
        ),
    }
}

/// Integrates a particle of `mass` in the fixed (inertial) frame: m r̈' = F'(t, r', ṙ')
/// (eq. 2.4), with the force in fixed components. The reference against which
/// [`simulate_particle`] is checked.
pub fn simulate_particle_fixed<F>(
    mass: f64,
    position: Vec3,
    velocity: Vec3,
    t0: f64,
    t_end: f64,
    mut force: F,
    opts: &Options,
) -> Result<Solution<ParticleState>>
where
    F: FnMut(f64, &Vec3, &Vec3) -> Vec3,
{
    check_positive("mass", mass)?;
    check_finite("position", position.as_slice())?;
    check_finite("velocity", velocity.as_slice())?;
    let y0 = [
        position.x, position.y, position.z, velocity.x, velocity.y, velocity.z,
    ];
    let rhs = |t: f64, y: &ParticleState, dy: &mut ParticleState| {
        let (r, v) = split(y);
        let a = force(t, &r, &v) / mass;
        *dy = [v.x, v.y, v.z, a.x, a.y, a.z];
    };
    crate::integrate::dop853(rhs, t0, y0, t_end, opts)
}
