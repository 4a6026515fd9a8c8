//! The validation of the heavy top, in one place: the top's parameters, a state, the constants
//! of the motion, the turning points near a pole, and the rule that every number returned is
//! finite or an error naming the argument that caused it.

use super::cubic::Turning;
use super::state::{EulerState, MIN_POLE_DISTANCE};
use crate::error::{check_finite, check_non_negative, check_positive, Error, Result};

/// Checks the top's parameters: I₁ > 0, I₃ > 0, I₃ ≤ 2 I₁ (the triangle inequality of the
/// principal moments about the pivot), m g l ≥ 0, all finite. Errors name `I1`, `I3`, `mgl`.
pub fn check_top(i1: f64, i3: f64, mgl: f64) -> Result<()> {
    check_positive("I1", i1)?;
    check_positive("I3", i3)?;
    check_non_negative("mgl", mgl)?;
    if i3 > 2.0 * i1 * (1.0 + 4.0 * f64::EPSILON) {
        return Err(Error::inertia(
            "I3",
            format!(
                "must be <= 2*I1 = {} (the triangle inequality I3 <= I1 + I2 of the principal moments \
                 about the pivot), got {i3}",
                2.0 * i1
            ),
        ));
    }
    Ok(())
}

/// Checks a nutation angle: finite and in [0, π]. The error names `argument`.
pub fn check_theta(argument: &str, theta: f64) -> Result<()> {
    if !(theta.is_finite() && (0.0..=std::f64::consts::PI).contains(&theta)) {
        return Err(Error::invalid(
            argument,
            format!("must be finite and in [0, pi], got {theta}"),
        ));
    }
    Ok(())
}

/// Checks a top (as [`check_top`]) and a state of it: `theta` (as [`check_theta`]) and the rates
/// `phi_dot`, `theta_dot`, `psi_dot` (finite). For a `start` (the initial state of
/// [`super::HeavyTop::new`]) also θ not in (0, [`MIN_POLE_DISTANCE`]) and the angles `phi`,
/// `psi` (finite). Errors name the argument; the first failing check in that order.
pub(crate) fn check_state(
    i1: f64,
    i3: f64,
    mgl: f64,
    state: &EulerState,
    start: bool,
) -> Result<()> {
    check_top(i1, i3, mgl)?;
    check_theta("theta", state.theta)?;
    if start {
        if state.theta > 0.0 && state.theta < MIN_POLE_DISTANCE {
            return Err(Error::invalid(
                "theta",
                format!(
                    "0 < theta = {:e} < {MIN_POLE_DISTANCE:e} rad: closer to the vertical than the solution \
                     resolves (1 - cos theta ~ theta^2/2 leaves double precision); use theta = 0 for a top \
                     started exactly upright",
                    state.theta
                ),
            ));
        }
        check_finite("phi", &[state.phi])?;
        check_finite("psi", &[state.psi])?;
    }
    check_finite("phi_dot", &[state.phi_dot])?;
    check_finite("theta_dot", &[state.theta_dot])?;
    check_finite("psi_dot", &[state.psi_dot])?;
    Ok(())
}

/// Checks the arguments of [`super::HeavyTop::with_spin`] that it does not pass on unchanged:
/// `theta` (as [`check_theta`]), `phi_dot` and `omega3` (finite).
pub(crate) fn check_spin(theta: f64, phi_dot: f64, omega3: f64) -> Result<()> {
    check_theta("theta", theta)?;
    check_finite("phi_dot", &[phi_dot])?;
    check_finite("omega3", &[omega3])?;
    Ok(())
}

/// Checks a top (as [`check_top`]) and its constants of the motion `p_phi`, `p_psi`, `energy`
/// (finite), naming the argument.
pub(super) fn check_constants(
    i1: f64,
    i3: f64,
    mgl: f64,
    p_phi: f64,
    p_psi: f64,
    energy: f64,
) -> Result<()> {
    check_top(i1, i3, mgl)?;
    check_finite("p_phi", &[p_phi])?;
    check_finite("p_psi", &[p_psi])?;
    check_finite("energy", &[energy])?;
    Ok(())
}

/// Refuses (naming `argument`) a motion whose turning point comes closer to a pole than
/// [`MIN_POLE_DISTANCE`] without passing through it.
///
/// A turning point that close to a pole *and* closer than ε of the other one (θ₁ < ε θ₂: a
/// spin of 1e-295 rad/s swinging through the bottom) is a passage through the pole as far as
/// double precision goes: the distance is set to 0, and the axis passes through it with φ and ψ
/// turning by π in the sense of p_φ ∓ p_ψ (what the passage at θ₁ does, up to θ₁/θ₂). Only a
/// motion that stays within ~θ₁/ε of the pole is refused.
///
/// A top started from a state (`start` = its (w₀, v₀) = (1 − cos θ₀, 1 + cos θ₀)) must also
/// start farther than θ₁/ε from the pole: its time is anchored at θ₀, and the passage at θ₁
/// reaches the pole later than the passage through it by a fraction ~(θ₁/θ₀)²/2 of the time from
/// θ₀ (θ₀ = 3.2e-59 with θ₁ = 1e-60 would put every later θ(t) off by 5e-4 of itself); closer
/// starts are refused. A top given by its constants starts at θ₁ itself, the passage's instant.
pub(super) fn resolve_pole_passage(
    argument: &str,
    t: Turning,
    start: Option<(f64, f64)>,
) -> Result<Turning> {
    // 1 − cos θ at θ = MIN_POLE_DISTANCE (and 1 + cos θ at π − MIN_POLE_DISTANCE).
    let min = 0.5 * MIN_POLE_DISTANCE * MIN_POLE_DISTANCE;
    let close = |x: f64| x > 0.0 && x < min;
    // θ₁ < ε θ₂ ⇔ w₁ < ε² w₂ (near the pole w ≈ θ²/2).
    let eps2 = f64::EPSILON * f64::EPSILON;
    let (w0, v0) = start.unwrap_or((f64::INFINITY, f64::INFINITY));
    let mut out = t;
    if close(t.w_lo) && t.w_lo < eps2 * t.w_hi && t.w_lo < eps2 * w0 {
        out.w_lo = 0.0;
        out.v_hi = 2.0;
    }
    if close(t.v_lo) && t.v_lo < eps2 * t.v_hi && t.v_lo < eps2 * v0 {
        out.v_lo = 0.0;
        out.w_hi = 2.0;
    }
    let (theta1, theta2) = out.thetas();
    if close(out.w_lo) || close(out.v_lo) {
        let (which, at) = if close(out.w_lo) {
            ("upright", theta1)
        } else {
            ("hanging", std::f64::consts::PI - theta2)
        };
        return Err(Error::invalid(
            argument,
            format!(
                "this motion stays within {:e} rad of the {which} vertical and comes within {at:e} rad \
                 of it without passing through: closer than the solution resolves \
                 ({MIN_POLE_DISTANCE:e} rad: 1 - cos theta ~ theta^2/2 leaves double precision)",
                if which == "upright" { theta2 } else { std::f64::consts::PI - theta1 }
            ),
        ));
    }
    Ok(out)
}

/// The values at time `t` if they are finite, else an error naming `t`: the last line of
/// defence of the rule that every number returned is finite (the constructors refuse the
/// motions whose solution cannot be represented, so this is not expected to fire).
pub(super) fn finite_at_t<const N: usize>(t: f64, values: [f64; N]) -> Result<[f64; N]> {
    if values.iter().all(|v| v.is_finite()) {
        return Ok(values);
    }
    Err(Error::invalid(
        "t",
        format!("the solution at t = {t:e} s is not finite: its scales exceed double precision"),
    ))
}

/// `value` if finite, else an error naming `theta` that says why (see
/// [`HeavyTop::effective_potential`]).
pub(super) fn finite_at_theta(what: &str, theta: f64, value: f64) -> Result<f64> {
    if value.is_finite() {
        return Ok(value);
    }
    let why = if theta == 0.0 || theta == std::f64::consts::PI {
        "it is infinite at this pole, which the axis never reaches (p_phi != p_psi at theta = 0, \
         p_phi != -p_psi at theta = pi)"
    } else {
        "it exceeds the largest double this close to a pole the axis never reaches"
    };
    Err(Error::invalid(
        "theta",
        format!("{what} at theta = {theta:e}: {why}"),
    ))
}

/// The name of the largest of a state's rates (the usual cause of a constant of the motion that
/// overflows).
pub(super) fn largest_rate(st: &EulerState) -> &'static str {
    let mut best = ("theta_dot", st.theta_dot.abs());
    for (name, x) in [("phi_dot", st.phi_dot.abs()), ("psi_dot", st.psi_dot.abs())] {
        if x > best.1 {
            best = (name, x);
        }
    }
    best.0
}

/// Refuses, naming the argument given with it, the first quantity that is not finite: a
/// constant of the motion beyond the range of double precision.
pub(super) fn check_representable(values: &[(&str, f64, &str)]) -> Result<()> {
    match values.iter().find(|(_, v, _)| !v.is_finite()) {
        None => Ok(()),
        Some((what, value, argument)) => Err(Error::invalid(
            *argument,
            format!(
                "the top's {what} = {value} is beyond the range of double precision (about 1.8e308): \
                 no motion with these numbers can be represented"
            ),
        )),
    }
}
