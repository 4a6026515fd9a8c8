//! What a Foucault run says about its swing plane: the fitted rate of turn, and whether the
//! motion is a steadily turning swing at all (the regime), judged against the exact linear
//! theory of [`super::FoucaultTheory`] for the same run.

use std::f64::consts::PI;

use super::planet::Earth;
use crate::error::{check_finite, Error, Result};
use crate::frames::ParticleState;
use crate::Vec3;

/// Fewest turning points for a rate: two swings (a line through 3 points has 1 degree of
/// freedom to spare; 4 make the fit's scatter visible).
pub const MIN_TURNING_POINTS: usize = 4;
/// The most the plane may turn per swing, as a fraction of a full turn, for it to be a swing:
/// |Δ| · (2π/σ) ≤ 2π/4, i.e. |Δ| ≤ σ/4. Unwrapping the turning points' angles modulo π needs
/// less than a quarter turn per half swing (|Δ| < σ/2); a factor 2 is kept for the wobble and
/// the amplitude's own precession. Beyond it the bob runs round a fat loop.
pub const MAX_TURN_PER_SWING: f64 = 0.25;
/// Below this turn of the plane over the run (rad) it does not turn measurably: a milliradian
/// (0.06°), below what the eye or the browser lab's drawing resolves, far above the
/// integration's noise on the angles (~1e-9 rad at the default rtol 1e-10), and above the
/// rocking that the swing's own nonlinearity and the centrifugal force's anisotropy cause at the
/// equator (≤ 6e-4 rad over the lab's 120 s at 1000 times the Earth's spin, amplitude L/10).
pub const STILL_ANGLE: f64 = 1e-3;
/// The linear theory's own fitted rate over the run must be within this fraction of its mean
/// rate Δ for the run to show a steady turn: the wobble then moves a fitted rate by at most
/// 10 %, so never its sign.
pub const STEADY_TOLERANCE: f64 = 0.1;
/// The measured rate may depart from the linear theory's (for the same run) by this fraction:
/// the amplitude's own (Airy) precession, −(3/8)(A/L)² of the rate at small amplitude (0.4 % at
/// A/L = 0.1), and more at large amplitude. Beyond it the swing is too wide for the Foucault
/// rate; within it the sense is the theory's.
pub const AMPLITUDE_TOLERANCE: f64 = 0.5;
/// The measured angles may scatter about their fitted line by this fraction of the run's turn.
pub const SCATTER_TOLERANCE: f64 = 0.25;
/// The most wobble (rad, [`super::LinearSwing::wobble`]: the radii of the swing's two minor
/// circles over its two major ones) of a steadily turning swing: its direction then stays
/// within arctan ½ ≈ 27° of a steady turn, and the centrifugal splitting of the frequencies is at
/// most 4/3 of twice the spin's vertical part (W = tan(½ arctan χ), χ = splitting / 2|w|).
/// Above it the plane rocks ([`FoucaultRegime::Unsteady`]); below it a run too short to average
/// the wobble out is [`FoucaultRegime::TooShort`].
pub const MAX_WOBBLE: f64 = 0.5;

/// Whether a Foucault run shows a swing plane turning steadily, and if not why.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FoucaultRegime {
    /// The plane turns steadily: the fitted rate is the Foucault precession (with the small
    /// correction of the amplitude).
    Precessing,
    /// The plane does not turn measurably (by less than [`STILL_ANGLE`] over the run): at the
    /// equator, or on a planet that does not spin. The rate is ≈ 0, no sense.
    Still,
    /// Too few swings, or a turn over the run not larger than the plane's wobble: run longer.
    TooShort,
    /// The plane rocks instead of turning: the centrifugal force's anisotropy beats the
    /// spin's vertical part (near the equator, or a planet spinning fast against the pendulum).
    Unsteady,
    /// The swing is so wide that its own (nonlinear) precession competes with the Foucault
    /// precession: the measured rate is not the Foucault rate.
    WideSwing,
    /// The spin is so fast against the pendulum that the plane would turn by more than a
    /// quarter turn per swing: the bob runs round a loop, there is no swing plane.
    NotASwing,
    /// The spin is so fast that the bob has no stable rest position to swing about.
    NoRest,
}

impl FoucaultRegime {
    /// The name the front ends show: "precessing", "still", "too_short", "unsteady",
    /// "wide_swing", "not_a_swing", "no_rest".
    pub fn name(self) -> &'static str {
        match self {
            Self::Precessing => "precessing",
            Self::Still => "still",
            Self::TooShort => "too_short",
            Self::Unsteady => "unsteady",
            Self::WideSwing => "wide_swing",
            Self::NotASwing => "not_a_swing",
            Self::NoRest => "no_rest",
        }
    }
}

/// The sense in which a swing plane, a parcel or a flow turns, seen from above. [`Sense::of`]
/// classifies a measured rate or circulation: no sense within [`super::SENSE_THRESHOLD`]
/// (1e-9) of its scale, round-off.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Sense {
    /// A negative rate: clockwise seen from above (the north).
    Clockwise,
    /// A positive rate: counterclockwise seen from above (the south).
    Counterclockwise,
    /// No measurable turn.
    None,
}

impl Sense {
    /// "clockwise", "counterclockwise" or "none".
    pub fn name(self) -> &'static str {
        match self {
            Self::Clockwise => "clockwise",
            Self::Counterclockwise => "counterclockwise",
            Self::None => "none",
        }
    }
}

/// The measurement of a Foucault run ([`Earth::foucault_measurement`]).
#[derive(Debug, Clone, PartialEq)]
pub struct FoucaultMeasurement {
    /// Whether the run shows a steadily turning swing plane, and if not why.
    pub regime: FoucaultRegime,
    /// The swing plane's rate of turn fitted through the turning points (rad/s,
    /// counterclockwise seen from above positive), where the regime defines one
    /// ([`FoucaultRegime::Precessing`], and ≈ 0 for [`FoucaultRegime::Still`]).
    pub precession_rate: Option<f64>,
    /// The simulated swing plane's time for one full turn, 2π/|rate| (s): where the regime
    /// defines a rate, beside it ([`FoucaultRegime::Precessing`]), and infinite where the plane
    /// does not turn measurably ([`FoucaultRegime::Still`], or a fitted rate of exactly 0);
    /// `None` otherwise.
    pub full_turn_period: Option<f64>,
    /// The sense of the turn, where the regime defines one: from the fitted rate when
    /// precessing (always the theory's), [`Sense::None`] when still.
    pub sense: Option<Sense>,
    /// Δ, the exact small-swing theory's mean rate (rad/s; [`super::FoucaultModes`]), or
    /// `None` where the rest position is not stable.
    pub theory_rate: Option<f64>,
    /// −ω sin λ, the unit's rate (rad/s): the limit of Δ for a slow spin.
    pub expected_rate: f64,
    /// The unit's time for one full turn, 2π/|ω sin λ| (s; infinite at the equator, where
    /// −ω sin λ = 0, or on a planet that does not spin).
    pub expected_full_turn_period: f64,
    /// The small-swing theory's rate fitted through its own turning points over the same run
    /// (rad/s): what the measurement tends to as the amplitude goes to 0.
    pub theory_fit_rate: Option<f64>,
    /// The number of turning points fitted.
    pub turning_points: usize,
    /// One sentence on the regime, with its figures, for the front ends to show.
    pub note: String,
}

impl FoucaultMeasurement {
    /// The sense's name, or "undefined" where the regime defines no rate.
    pub fn sense_name(&self) -> &'static str {
        self.sense.map_or("undefined", Sense::name)
    }
}

/// How close the unit's rate −ω sin λ must be to a run for it to describe the run, as a
/// fraction ([`UnitRateCheck`]): 1 %, the unit's formula to two significant digits. The spin's
/// departure stays below it while ω is small against the pendulum's √(g/L) (on the browser
/// lab's planet spinning 1000 times faster than the Earth, at 49° up to L ≈ 40 m, ω/√(g/L) ≈
/// 0.15), the amplitude's, about 0.3 (A/L)², while A/L ≲ 0.18 (docs/lab.md lists measured
/// values).
pub const UNIT_RATE_TOLERANCE: f64 = 0.01;

/// Whether the unit's rate −ω sin λ (the Foucault rate of eq. 2.33) describes a Foucault run,
/// and if not why ([`super::FoucaultSwing::unit_rate`]).
///
/// −ω sin λ is the rate of a small swing on a planet that spins slowly against the pendulum
/// (ω ≪ √(g/L)). Two departures measure how far a run is from that limit:
///
/// * the spin's, |Δ − (−ω sin λ)| / max(|Δ|, |ω sin λ|): the exact small-swing theory's mean
///   rate Δ ([`super::FoucaultModes`]) against the unit's (0 where both vanish: the equator);
/// * the amplitude's, |r − r_lin| / |r_lin|: the rate r measured through the run's turning
///   points against the small-swing theory's own fit r_lin through its turning points over the
///   same run (so that the wobble, common to both, cancels): the swing's own precession.
///
/// It holds when the run shows a steady turn (regime precessing, or still: then only the spin's
/// departure is judged) and both departures are at most [`UNIT_RATE_TOLERANCE`].
#[derive(Debug, Clone, PartialEq)]
pub struct UnitRateCheck {
    /// Whether −ω sin λ describes the run.
    pub holds: bool,
    /// ω / √(g/L): the planet's spin against the pendulum's own frequency (dimensionless).
    pub spin_ratio: f64,
    /// A / L: the release's distance from the rest position against the length (dimensionless).
    pub amplitude_ratio: f64,
    /// The spin's departure (a fraction), or `None` where the bob has no stable rest position.
    pub spin_departure: Option<f64>,
    /// The amplitude's departure (a fraction), or `None` where the run gives no rate to compare
    /// (its regime is neither precessing nor still) or does not turn (still).
    pub amplitude_departure: Option<f64>,
    /// One sentence for the front ends to show, with the figures.
    pub note: String,
}

/// The time of one full turn at `rate` (rad/s), 2π/|rate| (s): infinite at a rate of 0.
fn full_turn(rate: f64) -> f64 {
    if rate == 0.0 {
        f64::INFINITY
    } else {
        2.0 * PI / rate.abs()
    }
}

/// |diff| / scale, 0 when both vanish (∞ when only the scale does).
fn fraction(diff: f64, scale: f64) -> f64 {
    if diff == 0.0 {
        0.0
    } else if scale == 0.0 {
        f64::INFINITY
    } else {
        diff.abs() / scale
    }
}

impl FoucaultMeasurement {
    /// Whether the unit's rate −ω sin λ describes the measured run ([`UnitRateCheck`]), given
    /// the run's `spin_ratio` ω/√(g/L) and `amplitude_ratio` A/L (for the note).
    pub fn unit_rate_check(&self, spin_ratio: f64, amplitude_ratio: f64) -> UnitRateCheck {
        let e = self.expected_rate;
        let spin_departure = self
            .theory_rate
            .map(|d| fraction(d - e, d.abs().max(e.abs())));
        let still = self.regime == FoucaultRegime::Still;
        let amplitude_departure = match (self.regime, self.precession_rate, self.theory_fit_rate) {
            (FoucaultRegime::Precessing, Some(r), Some(f)) => Some(fraction(r - f, f.abs())),
            _ => None,
        };
        let percent = |x: f64| format!("{} %", sig(100.0 * x));
        let spin_ok = spin_departure.is_some_and(|x| x <= UNIT_RATE_TOLERANCE);
        let amplitude_ok = still || amplitude_departure.is_some_and(|x| x <= UNIT_RATE_TOLERANCE);
        let steady = still || self.regime == FoucaultRegime::Precessing;
        let holds = steady && spin_ok && amplitude_ok;
        let note = if !steady {
            format!(
                "-omega sin(lambda) cannot be compared with this run: its swing plane does not turn steadily (regime {}; \
                 omega/sqrt(g/L) = {}, A/L = {})",
                self.regime.name(),
                sig(spin_ratio),
                sig(amplitude_ratio)
            )
        } else if holds {
            let spin = spin_departure.map_or_else(String::new, &percent);
            match amplitude_departure {
                Some(a) => format!(
                    "-omega sin(lambda) applies: the small-swing rate is within {spin} of it (omega/sqrt(g/L) = {}) and the \
                     measured rate within {} of the small-swing theory's (A/L = {})",
                    sig(spin_ratio),
                    percent(a),
                    sig(amplitude_ratio)
                ),
                None => format!(
                    "-omega sin(lambda) applies: the plane does not turn measurably, and the small-swing rate is within \
                     {spin} of the unit's (omega/sqrt(g/L) = {})",
                    sig(spin_ratio)
                ),
            }
        } else {
            let mut why = Vec::new();
            if !spin_ok {
                why.push(match spin_departure {
                    Some(x) => format!(
                        "the spin is not small against the pendulum (omega/sqrt(g/L) = {}): the exact small-swing rate \
                         departs from it by {}",
                        sig(spin_ratio),
                        percent(x)
                    ),
                    None => "the bob has no stable rest position".to_string(),
                });
            }
            if !amplitude_ok {
                if let Some(x) = amplitude_departure {
                    why.push(format!(
                        "the swing is wide (A/L = {}): its own precession moves the measured rate {} from the small-swing \
                         theory's",
                        sig(amplitude_ratio),
                        percent(x)
                    ));
                }
            }
            format!(
                "-omega sin(lambda) does not apply (tolerance {}): {}",
                percent(UNIT_RATE_TOLERANCE),
                why.join("; and ")
            )
        };
        UnitRateCheck {
            holds,
            spin_ratio,
            amplitude_ratio,
            spin_departure,
            amplitude_departure,
            note,
        }
    }
}

/// A least-squares line through the swing-plane angles at turning points, fed one by one and
/// unwrapped modulo π on the way (a swing plane has no head or tail; the turning points
/// alternate between its two ends). Welford's updates, free of cancellation over long runs.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PlaneFit {
    n: usize,
    prev: f64,
    mean_t: f64,
    mean_u: f64,
    m_tt: f64,
    c_tu: f64,
    first: (f64, f64),
    last_t: f64,
    u_min: f64,
    u_max: f64,
    /// Range of u − rate·(t − t_first) for a given rate (the deviation from a steady turn).
    detrend: f64,
    d_min: f64,
    d_max: f64,
}

impl PlaneFit {
    pub(crate) fn new(detrend: f64) -> Self {
        Self {
            n: 0,
            prev: 0.0,
            mean_t: 0.0,
            mean_u: 0.0,
            m_tt: 0.0,
            c_tu: 0.0,
            first: (0.0, 0.0),
            last_t: 0.0,
            u_min: f64::INFINITY,
            u_max: f64::NEG_INFINITY,
            detrend,
            d_min: f64::INFINITY,
            d_max: f64::NEG_INFINITY,
        }
    }

    /// Adds the angle `a` (rad) at time `t` (s); returns the unwrapped angle.
    pub(crate) fn push(&mut self, t: f64, a: f64) -> f64 {
        let u = if self.n == 0 {
            a
        } else {
            a + ((self.prev - a) / PI).round() * PI
        };
        if self.n == 0 {
            self.first = (t, u);
        }
        self.n += 1;
        self.prev = u;
        self.last_t = t;
        let k = self.n as f64;
        let (dt, du) = (t - self.mean_t, u - self.mean_u);
        self.mean_t += dt / k;
        self.mean_u += du / k;
        self.m_tt += dt * (t - self.mean_t);
        self.c_tu += dt * (u - self.mean_u);
        self.u_min = self.u_min.min(u);
        self.u_max = self.u_max.max(u);
        let d = u - self.detrend * (t - self.first.0);
        self.d_min = self.d_min.min(d);
        self.d_max = self.d_max.max(d);
        u
    }

    pub(crate) fn len(&self) -> usize {
        self.n
    }

    /// The fitted slope (rad/s), with at least 3 points spread in time.
    pub(crate) fn slope(&self) -> Option<f64> {
        (self.n >= 3 && self.m_tt > 0.0).then(|| self.c_tu / self.m_tt)
    }

    /// The fitted line's value at `t`.
    fn line(&self, t: f64) -> f64 {
        self.mean_u + self.slope().unwrap_or(0.0) * (t - self.mean_t)
    }

    /// Time from the first to the last point (s).
    pub(crate) fn span(&self) -> f64 {
        if self.n == 0 {
            0.0
        } else {
            self.last_t - self.first.0
        }
    }

    /// Range of the unwrapped angles (rad).
    pub(crate) fn spread(&self) -> f64 {
        if self.n == 0 {
            0.0
        } else {
            self.u_max - self.u_min
        }
    }

    /// Range of the angles about the steady turn at the `detrend` rate (rad).
    fn deviation(&self) -> f64 {
        if self.n == 0 {
            0.0
        } else {
            self.d_max - self.d_min
        }
    }
}

/// `x` to 4 significant digits, in plain notation between 1e-3 and 1e6, else scientific.
fn sig(x: f64) -> String {
    let a = x.abs();
    if (1e-3..1e6).contains(&a) {
        let decimals = (3 - a.log10().floor() as i32).max(0) as usize;
        format!("{x:.decimals$}")
    } else {
        format!("{x:.3e}")
    }
}

/// Checks the turning points handed to a fit or a measurement: equal lengths, finite,
/// times increasing.
pub(crate) fn check_turning_points(turn_times: &[f64], turn_angles: &[f64]) -> Result<()> {
    if turn_times.len() != turn_angles.len() {
        return Err(Error::invalid(
            "turn_times",
            format!(
                "must have the length of turn_angles ({} != {})",
                turn_times.len(),
                turn_angles.len()
            ),
        ));
    }
    check_finite("turn_times", turn_times)?;
    check_finite("turn_angles", turn_angles)?;
    if let Some(i) = turn_times.windows(2).position(|w| w[1] <= w[0]) {
        return Err(Error::invalid(
            "turn_times",
            format!(
                "must increase, got {} after {} at index {}",
                turn_times[i + 1],
                turn_times[i],
                i + 1
            ),
        ));
    }
    Ok(())
}

impl Earth {
    /// Measures a Foucault run of a pendulum of `length` (m) at `latitude` (rad) that started
    /// from `state0` at `t0` and ran to `t_end` (s), from its turning points (`turn_times`, s,
    /// increasing, and `turn_angles`, rad: [`super::FoucaultRun`]'s, the direction of the bob
    /// from its rest position): the fitted rate of turn of the swing plane and the regime.
    ///
    /// The regime is judged against the exact small-swing theory ([`Earth::foucault_theory`])
    /// of the same run, whose turning points are computed in closed form:
    ///
    /// * no stable rest position → [`FoucaultRegime::NoRest`];
    /// * the theory's plane turns by more than [`MAX_TURN_PER_SWING`] of a turn per swing →
    ///   [`FoucaultRegime::NotASwing`];
    /// * fewer than [`MIN_TURNING_POINTS`] turning points → [`FoucaultRegime::TooShort`];
    /// * the theory's and the measured angles, and Δ over the run, all within
    ///   [`STILL_ANGLE`] → [`FoucaultRegime::Still`] (rate ≈ 0, sense none);
    /// * the theory's swing has no mean turn (Δ = 0) or wobbles by more than [`MAX_WOBBLE`]
    ///   → [`FoucaultRegime::Unsteady`] (the plane rocks, whatever the length of the run);
    /// * the theory's own fit within [`STEADY_TOLERANCE`] of its mean rate Δ, and the
    ///   measured rate within [`AMPLITUDE_TOLERANCE`] of that fit and scattering less than
    ///   [`SCATTER_TOLERANCE`] of its turn → [`FoucaultRegime::Precessing`]; the theory steady
    ///   (or still) but the measurement not → [`FoucaultRegime::WideSwing`];
    /// * otherwise the run is too short to average the wobble out → [`FoucaultRegime::TooShort`],
    ///   with the duration that would do in the note.
    ///
    /// Hence a rate is returned only with the sense of the theory's mean rate Δ (or as ≈ 0):
    /// never the wrong sense. Errors name `latitude`, `length`, `state0`, `t_end`,
    /// `turn_times` or `turn_angles`.
    #[allow(clippy::too_many_arguments)]
    pub fn foucault_measurement(
        &self,
        latitude: f64,
        length: f64,
        state0: &ParticleState,
        t0: f64,
        t_end: f64,
        turn_times: &[f64],
        turn_angles: &[f64],
    ) -> Result<FoucaultMeasurement> {
        let theory = self.foucault_theory(latitude, length)?;
        let expected_rate = self.foucault_rate(latitude)?;
        check_finite("state0", state0)?;
        check_finite("t0", &[t0])?;
        if !(t_end.is_finite() && t_end > t0) {
            return Err(Error::invalid(
                "t_end",
                format!("must be finite and > t0 = {t0}, got {t_end}"),
            ));
        }
        check_turning_points(turn_times, turn_angles)?;
        let n = turn_times.len();
        let omega = self.rotation_rate;
        let w0 = self.g.sqrt() / length.sqrt();
        let mut out = FoucaultMeasurement {
            regime: FoucaultRegime::NoRest,
            precession_rate: None,
            full_turn_period: None,
            sense: None,
            theory_rate: None,
            expected_rate,
            expected_full_turn_period: full_turn(expected_rate),
            theory_fit_rate: None,
            turning_points: n,
            note: String::new(),
        };
        let Some(modes) = theory.modes else {
            out.note = format!(
                "the planet spins so fast that the centrifugal force beats gravity: the bob has no stable rest \
                 position to swing about (spin {omega:.4e} rad/s against the pendulum's sqrt(g/L) = {w0:.4e} rad/s)"
            );
            return Ok(out);
        };
        let delta = modes.precession_rate;
        let sigma = modes.swing_frequency;
        out.theory_rate = Some(delta);
        let period = 2.0 * PI / sigma;
        if delta.abs() > MAX_TURN_PER_SWING * sigma {
            out.regime = FoucaultRegime::NotASwing;
            out.note = format!(
                "the planet spins too fast for this pendulum: its swing plane would turn by {:.0} degrees per swing, more \
                 than a quarter turn, so the bob runs round a loop instead of swinging (spin {omega:.4e} rad/s against \
                 the pendulum's sqrt(g/L) = {w0:.4e} rad/s)",
                (delta.abs() * period).to_degrees()
            );
            return Ok(out);
        }
        if n < MIN_TURNING_POINTS {
            out.regime = FoucaultRegime::TooShort;
            out.note = format!(
                "too few swings to measure a turn: {n} turning point{}, at least {MIN_TURNING_POINTS} are needed \
                 (two swings of {} s)",
                if n == 1 { "" } else { "s" },
                sig(period)
            );
            return Ok(out);
        }
        // The measured angles.
        let mut measured = PlaneFit::new(delta);
        let unwrapped: Vec<f64> = turn_times
            .iter()
            .zip(turn_angles)
            .map(|(&t, &a)| measured.push(t, a))
            .collect();
        let span = measured.span();
        let rate = measured.slope().filter(|r| r.is_finite());
        let scatter = turn_times
            .iter()
            .zip(&unwrapped)
            .map(|(&t, &u)| (u - measured.line(t)).abs())
            .fold(0.0, f64::max);
        // The small-swing theory of the same run, from the same start.
        let r0 = Vec3::new(state0[0], state0[1], state0[2]);
        let v0 = Vec3::new(state0[3], state0[4], state0[5]);
        let q0 = theory.displacement_of(&r0);
        let swing = modes.swing(q0, [v0.dot(&theory.east), v0.dot(&theory.north)], t0)?;
        let mut linear = PlaneFit::new(delta);
        // As many as the run shows and some: more would mean the run lost its swing.
        swing.turning_points(t0, t_end, 4 * n + 16, |t, a| {
            linear.push(t, a);
        });
        let linear_rate = linear.slope();
        out.theory_fit_rate = linear_rate;
        let turn = delta.abs() * span;
        // Still: neither the theory nor the run turns measurably.
        if turn <= STILL_ANGLE && linear.spread() <= STILL_ANGLE && measured.spread() <= STILL_ANGLE
        {
            out.regime = FoucaultRegime::Still;
            out.precession_rate = rate.or(Some(0.0));
            out.full_turn_period = Some(f64::INFINITY);
            out.sense = Some(Sense::None);
            out.note = format!(
                "the swing plane does not turn measurably: by less than {STILL_ANGLE:e} rad over the {} s of the {n} \
                 turning points (the equator, or a planet that does not spin)",
                sig(span)
            );
            return Ok(out);
        }
        let wobble = swing.wobble(theory.vertical_spin);
        let theory_still = turn <= STILL_ANGLE && linear.spread() <= STILL_ANGLE;
        if !theory_still && (delta == 0.0 || wobble > MAX_WOBBLE) {
            out.regime = FoucaultRegime::Unsteady;
            out.note = format!(
                "the swing plane does not turn steadily but rocks: the centrifugal force makes east-west and \
                 north-south swings differ in frequency by {:.3e} rad/s, not small against twice the spin's vertical \
                 part, {:.3e} rad/s, that turns the plane (its wobble {wobble:.2} exceeds {MAX_WOBBLE}: near the \
                 equator, or a planet spinning fast against the pendulum)",
                modes.splitting,
                2.0 * theory.vertical_spin.abs()
            );
            return Ok(out);
        }
        let theory_steady = !theory_still
            && linear_rate.is_some_and(|r| (r - delta).abs() <= STEADY_TOLERANCE * delta.abs());
        if theory_steady {
            let r_lin = linear_rate.unwrap_or(delta);
            if let Some(r) = rate.filter(|&r| {
                (r - r_lin).abs() <= AMPLITUDE_TOLERANCE * r_lin.abs()
                    && scatter <= SCATTER_TOLERANCE * r.abs() * span
            }) {
                out.regime = FoucaultRegime::Precessing;
                out.precession_rate = Some(r);
                out.full_turn_period = Some(full_turn(r));
                out.sense = Some(if r > 0.0 {
                    Sense::Counterclockwise
                } else {
                    Sense::Clockwise
                });
                out.note = format!(
                    "the swing plane turns steadily: {} rad over the {} s of the {n} turning points",
                    sig(r * span),
                    sig(span)
                );
                return Ok(out);
            }
        }
        if theory_steady || theory_still {
            let amplitude = q0[0].hypot(q0[1]);
            out.regime = FoucaultRegime::WideSwing;
            out.note = format!(
                "the swing is too wide for the Foucault rate: at amplitude / length = {:.3} the pendulum's own \
                 precession (measured {}) departs from the small-swing theory's {:.4e} rad/s by more than half; release \
                 it closer to rest",
                amplitude / length,
                rate.map_or("no steady turn".to_string(), |r| format!("{r:.4e} rad/s")),
                linear_rate.unwrap_or(delta),
            );
            return Ok(out);
        }
        // The slope error of a fit over a span T from a wobble W is ~3W/T: 30 W/|Δ| keeps it
        // within 10 %.
        let need = (3.0 * wobble / (STEADY_TOLERANCE * delta.abs()))
            .max(MIN_TURNING_POINTS as f64 * period / 2.0);
        out.regime = FoucaultRegime::TooShort;
        out.note = format!(
            "the run is too short: over its {} s the plane turns by {turn:.3e} rad, not enough beside its wobble of \
             {:.3e} rad to measure the rate; run for at least about {} s",
            sig(span),
            linear.deviation().max(wobble),
            sig(need)
        );
        Ok(out)
    }
}
