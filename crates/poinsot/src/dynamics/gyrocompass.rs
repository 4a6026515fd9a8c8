//! The gravity-controlled (pendulous) gyrocompass: a rotor of angular momentum H in a case
//! hanging below its pivot (pendulosity P = m g l), carried by the local frame of a place, or a
//! ship, on the rotating Earth (eq. 2.29–2.33), optionally damped by a torque about the case's
//! vertical proportional to the tilt (Sperry's damping: Arnold & Maunder, *Gyrodynamics and its
//! Engineering Applications*, 1961, ch. 11; Wrigley, Hollister & Denhard, *Gyroscopic Theory,
//! Design, and Instrumentation*, 1969, ch. 12).
//!
//! **Angles and signs** (CONVENTIONS.md, "Gyrocompass"). Local frame ENU; the *heading* α of the
//! spin axis is the azimuth of its north-seeking end, clockwise (east) from true north (rad);
//! the *tilt* θ is that end's elevation above the horizontal (rad). An *error* is what the
//! compass reads minus the truth: a positive error reads high, the spin axis settled that far
//! **west** of true north.
//!
//! **Linearised equations** (small α, θ; Ω_c = Ω cos λ, Ω_s = Ω sin λ; D the damping torque
//! coefficient, N·m/rad):
//!
//! ```text
//! α̇ = Ω_s − (P/H + Ω_c) θ,     θ̇ = Ω_c α − (D/H) θ,
//! ```
//!
//! an oscillation of ω_n² = Ω_c (P/H + Ω_c) ≈ P Ω_c / H about the meridian: the period
//! 2π √(H / (P Ω cos λ)), the printed form. D = 2 ζ ω_n H for the damping ratio ζ.
//!
//! **Full model** ([`Gyrocompass::simulate`]): the sensitive element as a gyrostat — a rigid
//! case (moments `inertia` about the pivot, body axes e₁ spin / north end, e₂ = e₃ × e₁, e₃ up)
//! holding the rotor's momentum H e₁ — carried by the moving local frame through
//! [`super::simulate_carried`]: nonlinear Euler equations in the inertial frame, the fictitious
//! translational force acting at the centre of mass (−(P/g) e₃ from the pivot), the damping
//! torque −D θ e₃ with θ = asin(e₁·ẑ).

use std::f64::consts::{FRAC_PI_2, PI};

use super::carried::{simulate_carried, turn, Carrier, Carrying, Load};
use super::model::BodyInertia;
use super::simulate::{Method, SimulateOptions};
use super::torque::{TorqueContext, TorqueModel};
use crate::earth::{check_latitude, Earth};
use crate::error::{check_finite, check_positive, num, Error, Result};
use crate::rotation::quaternion_to_mat3_unchecked;
use crate::{Mat3, Vec3};

/// The default rotor angular momentum H (kg·m²/s): a 0.02 kg·m² rotor at 20,000 rpm.
pub const COMPASS_ANGULAR_MOMENTUM: f64 = 40.0;
/// The default pendulosity P = m g l (N·m): with the default H, Schuler-tuned near 45°.
pub const COMPASS_PENDULOSITY: f64 = 1.2;
/// The default damping ratio ζ: the swing shrinks about 2.7 times per half period.
pub const COMPASS_DAMPING: f64 = 0.3;
/// The default moments of the sensitive element about its pivot (kg·m², (spin, horizontal,
/// up)): the nutation H/I is then 40 rad/s, about 10⁵ DOP853 steps per simulated hour.
pub const COMPASS_INERTIA: [f64; 3] = [0.5, 1.0, 1.0];
/// The default method of [`Gyrocompass::simulate`]: DOP853.
pub const COMPASS_METHOD: &str = "dop853";
/// The default samples of [`Gyrocompass::simulate`].
pub const COMPASS_SAMPLES: usize = 1001;
/// The default tolerances of [`Gyrocompass::simulate`] (as `simulate`'s).
pub const COMPASS_TOLERANCES: crate::integrate::Tolerances = crate::integrate::Tolerances {
    rtol: 1e-10,
    atol: 1e-12,
    max_steps: crate::limits::DEFAULT_MAX_STEPS,
};

/// A pendulous gyrocompass at a latitude on the Earth.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gyrocompass {
    /// Latitude λ (rad, north-positive), |λ| < π/2.
    pub latitude: f64,
    /// The rotor's angular momentum H (kg·m²/s), > 0.
    pub angular_momentum: f64,
    /// Pendulosity P = m g l (N·m), > 0: the centre of mass l below the pivot.
    pub pendulosity: f64,
    /// Damping ratio ζ ∈ [0, 1) of the linearised settling oscillation.
    pub damping: f64,
    /// Moments of the sensitive element about the pivot (kg·m²), axes (spin, e₃ × spin, up):
    /// they set only the fast nutation, H/I, not the compass's settling.
    pub inertia: [f64; 3],
    /// The Earth (Ω, R, g).
    pub earth: Earth,
}

/// A ship's track: constant `speed` (m/s, ≥ 0) on a constant `course` (rad, clockwise from
/// north), a rhumb line, from the compass's latitude at `t = 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ship {
    /// Speed over the ground V (m/s).
    pub speed: f64,
    /// Course C (rad, clockwise from north).
    pub course: f64,
}

impl Ship {
    /// A ship; errors name `speed` (finite, ≥ 0) and `course` (finite).
    pub fn new(speed: f64, course: f64) -> Result<Self> {
        crate::error::check_non_negative("speed", speed)?;
        check_finite("course", &[course])?;
        Ok(Self { speed, course })
    }
}

/// The default time a [`Turn`] takes (s) when none is given: a minute, a brisk ship's turn.
pub const COMPASS_TURN_DURATION: f64 = 60.0;

/// A change of a ship's velocity during a run ([`Track`]): from `time` (s after the start) the
/// ship's velocity over the ground changes at a constant rate, over `duration` s, to `speed`
/// (m/s) on `course` (rad, clockwise from north). The velocity's east and north components
/// move linearly (a constant acceleration Δv/τ: a reversal slows through rest and speeds up
/// again); what the compass feels of a manoeuvre is its change of velocity ∫ a dt, the same for
/// any path between the two velocities (the ballistic deflection, [`Gyrocompass::simulate_track`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Turn {
    /// When the turn starts (s after the start of the run), ≥ 0.
    pub time: f64,
    /// How long it takes (s), > 0; `None`: [`COMPASS_TURN_DURATION`].
    pub duration: Option<f64>,
    /// The speed over the ground after the turn (m/s), ≥ 0.
    pub speed: f64,
    /// The course after the turn (rad, clockwise from north).
    pub course: f64,
}

/// A ship's track: the `start`ing speed and course, then the `turns` (course and speed changes)
/// in the order of their times, each a rhumb line between them. Checked by [`Track::new`].
#[derive(Debug, Clone, PartialEq)]
pub struct Track {
    /// The ship's speed and course from `t = 0`.
    pub start: Ship,
    /// The course and speed changes, in time order, not overlapping.
    pub turns: Vec<Turn>,
}

impl Track {
    /// A steady track: `ship` all along (a rhumb line).
    pub fn steady(ship: Ship) -> Self {
        Self {
            start: ship,
            turns: Vec::new(),
        }
    }

    /// A track; errors name `speed`, `course` (the start) and `turns` (with the turn's index
    /// from 0): a time not finite or negative, a duration not finite and > 0 (a change of
    /// velocity in no time is an infinite acceleration), a speed not finite and ≥ 0, a course
    /// not finite, or a turn that starts before the one before it has ended.
    pub fn new(start: Ship, turns: Vec<Turn>) -> Result<Self> {
        Ship::new(start.speed, start.course)?;
        let mut end = 0.0;
        for (k, turn) in turns.iter().enumerate() {
            let bad = |why: String| Err(Error::invalid("turns", format!("turn {k}: {why}")));
            if !(turn.time.is_finite() && turn.time >= 0.0) {
                return bad(format!(
                    "its time must be finite and >= 0 s, got {}",
                    num(turn.time)
                ));
            }
            let duration = turn.duration.unwrap_or(COMPASS_TURN_DURATION);
            if !(duration.is_finite() && duration > 0.0) {
                return bad(format!(
                    "its duration must be finite and > 0 s (a change of velocity in no time \
                     is an infinite acceleration), got {}",
                    num(duration)
                ));
            }
            if !(turn.speed.is_finite() && turn.speed >= 0.0) {
                return bad(format!(
                    "its speed must be finite and >= 0 m/s, got {}",
                    num(turn.speed)
                ));
            }
            if !turn.course.is_finite() {
                return bad(format!(
                    "its course must be finite, got {}",
                    num(turn.course)
                ));
            }
            if turn.time < end {
                return bad(format!(
                    "it starts at {} s, before the turn before it ends at {} s",
                    num(turn.time),
                    num(end)
                ));
            }
            end = turn.time + duration;
            if !end.is_finite() {
                return bad("its end time is not a finite number of seconds".into());
            }
        }
        Ok(Self { start, turns })
    }

    /// The ship's velocity over the ground (east, north) (m/s) and its rate of change
    /// (m/s²) at time `t` (s).
    pub fn velocity(&self, t: f64) -> ([f64; 2], [f64; 2]) {
        let enu = |s: f64, c: f64| [s * c.sin(), s * c.cos()];
        let mut v = enu(self.start.speed, self.start.course);
        for turn in &self.turns {
            if t < turn.time {
                break;
            }
            let tau = turn.duration.unwrap_or(COMPASS_TURN_DURATION);
            let to = enu(turn.speed, turn.course);
            if t < turn.time + tau {
                let a = [(to[0] - v[0]) / tau, (to[1] - v[1]) / tau];
                let dt = t - turn.time;
                return ([v[0] + a[0] * dt, v[1] + a[1] * dt], a);
            }
            v = to;
        }
        (v, [0.0, 0.0])
    }
}

/// The sampled motion of a compass ([`Gyrocompass::simulate`]).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CompassRun {
    /// Times (s).
    pub t: Vec<f64>,
    /// Heading of the spin axis, clockwise from the local true north (rad, (−π, π]).
    pub heading: Vec<f64>,
    /// Tilt of the spin axis's north end above the horizontal (rad).
    pub tilt: Vec<f64>,
    /// The compass's (ship's) latitude (rad).
    pub latitude: Vec<f64>,
}

/// The linearised compass's motion ([`Gyrocompass::linear_solution`]) at given times.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LinearCompass {
    /// Heading of the spin axis, clockwise from true north (rad), not wrapped.
    pub heading: Vec<f64>,
    /// Tilt of the north end (rad).
    pub tilt: Vec<f64>,
    /// The heading swing's envelope (rad, ≥ 0): the heading stays within
    /// `settled_heading ± envelope`, touching it once a swing.
    pub envelope: Vec<f64>,
    /// The settled heading α* (rad): −(latitude error + speed error).
    pub settled_heading: f64,
    /// The settled tilt θ* (rad).
    pub settled_tilt: f64,
}

/// The local frame of a ship on a [`Track`] over the rotating spherical Earth, fixed axes the
/// ENU axes at the start; the specific force is the plumb-line gravity less the ship's
/// acceleration relative to the ground and its Coriolis acceleration, `−g ẑ − v̇ − ρ × v −
/// 2 Ω × v` (ENU, ρ the transport rate (−V_N/R, V_E/R, V_E tan φ/R), v̇ the rate of the
/// velocity's ENU components: nonzero only during a turn). The frame turns at Ω + ρ (2.33
/// plus the ship's motion over the curved Earth).
#[derive(Debug, Clone, PartialEq)]
struct ShipFrame {
    earth: Earth,
    /// The pieces of the track: cruising legs (a = 0) and turns, in time order.
    legs: Vec<Leg>,
    /// ENU → Earth-fixed at the start (longitude 0).
    enu0: Mat3,
}

/// One piece of a ship's track: from time `t0` (s) at latitude `lat0`, longitude `lon0` (rad)
/// with velocity `v` (east, north; m/s) changing at the constant rate `a` (m/s²).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Leg {
    t0: f64,
    lat0: f64,
    lon0: f64,
    v: [f64; 2],
    a: [f64; 2],
}

/// Gauss–Legendre nodes on [−1, 1] and weights, 8 points (exact for degree 15: the
/// longitude's integrand over a turn, 1/cos of a quadratic latitude, to round-off).
const GAUSS_8: [(f64, f64); 8] = [
    (-0.960_289_856_497_536_3, 0.101_228_536_290_376_26),
    (-0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (-0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (-0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_26),
];

/// ENU axes at (φ, L) as the columns of the matrix to Earth-fixed components.
fn enu_axes(lat: f64, lon: f64) -> Mat3 {
    let (sp, cp) = lat.sin_cos();
    let (sl, cl) = lon.sin_cos();
    Mat3::new(-sl, -sp * cl, cp * cl, cl, -sp * sl, cp * sl, 0.0, cp, sp)
}

impl Leg {
    /// (φ, L) at time `t` (s) on this leg. Cruising: φ linear in t, L from dL/dt = V_E /
    /// (R cos φ) in closed form as a divided difference of atanh(sin φ) (no cancellation for
    /// small steps); turning: φ quadratic in t, L by 8-point Gauss–Legendre.
    fn position(&self, t: f64, r: f64) -> (f64, f64) {
        let dt = t - self.t0;
        let [ve, vn] = self.v;
        if self.a == [0.0, 0.0] {
            let (a, b) = (self.lat0, self.lat0 + vn * dt / r);
            let d = b - a;
            let m = 0.5 * (a + b);
            let half = 0.5 * d;
            let sinc = if half.abs() < 1e-8 {
                1.0
            } else {
                half.sin() / half
            };
            let x = 2.0 * m.cos() * half.sin() / (1.0 - a.sin() * b.sin());
            let g = if x.abs() < 1e-8 { 1.0 } else { x.atanh() / x };
            // ∫ dt / cos φ = t · (atanh(sin b) − atanh(sin a)) / (b − a).
            let ratio = g * m.cos() * sinc / (1.0 - a.sin() * b.sin());
            return (b, self.lon0 + ve / r * dt * ratio);
        }
        let [ae, an] = self.a;
        let lat_at = |u: f64| self.lat0 + (vn * u + 0.5 * an * u * u) / r;
        let lon = GAUSS_8
            .iter()
            .map(|&(x, w)| {
                let u = 0.5 * dt * (1.0 + x);
                w * (ve + ae * u) / lat_at(u).cos()
            })
            .sum::<f64>()
            * 0.5
            * dt
            / r;
        (lat_at(dt), self.lon0 + lon)
    }
}

impl ShipFrame {
    fn new(earth: Earth, lat0: f64, track: &Track) -> Self {
        let r = earth.radius;
        let enu = |s: f64, c: f64| [s * c.sin(), s * c.cos()];
        let mut legs = vec![Leg {
            t0: 0.0,
            lat0,
            lon0: 0.0,
            v: enu(track.start.speed, track.start.course),
            a: [0.0, 0.0],
        }];
        for turn in &track.turns {
            let tau = turn.duration.unwrap_or(COMPASS_TURN_DURATION);
            let to = enu(turn.speed, turn.course);
            let cruise = legs[legs.len() - 1];
            let (lat, lon) = cruise.position(turn.time, r);
            let v = cruise.v;
            let turning = Leg {
                t0: turn.time,
                lat0: lat,
                lon0: lon,
                v,
                a: [(to[0] - v[0]) / tau, (to[1] - v[1]) / tau],
            };
            let (lat, lon) = turning.position(turn.time + tau, r);
            legs.push(turning);
            legs.push(Leg {
                t0: turn.time + tau,
                lat0: lat,
                lon0: lon,
                v: to,
                a: [0.0, 0.0],
            });
        }
        Self {
            earth,
            legs,
            enu0: enu_axes(lat0, 0.0),
        }
    }

    fn leg(&self, t: f64) -> &Leg {
        let k = self.legs.partition_point(|l| l.t0 <= t);
        &self.legs[k.saturating_sub(1)]
    }

    /// (φ, L) at time `t` (rad).
    fn position(&self, t: f64) -> (f64, f64) {
        self.leg(t).position(t, self.earth.radius)
    }

    /// The velocity (east, north, 0) (m/s) and its rate (m/s²) at `t`.
    fn velocity(&self, t: f64) -> (Vec3, Vec3) {
        let leg = self.leg(t);
        let dt = t - leg.t0;
        let [ae, an] = leg.a;
        let v = Vec3::new(leg.v[0] + ae * dt, leg.v[1] + an * dt, 0.0);
        (v, Vec3::new(ae, an, 0.0))
    }

    /// The largest |latitude| (rad) over [0, `duration`] s: at the legs' ends and where a
    /// turn's northward speed passes through zero.
    fn max_abs_latitude(&self, duration: f64) -> f64 {
        let mut times = vec![duration];
        for leg in &self.legs {
            if leg.t0 <= duration {
                times.push(leg.t0);
                if leg.a[1] != 0.0 {
                    let u = -leg.v[1] / leg.a[1];
                    if u > 0.0 && leg.t0 + u <= duration {
                        times.push(leg.t0 + u);
                    }
                }
            }
        }
        times
            .iter()
            .map(|&t| self.position(t).0.abs())
            .fold(0.0, f64::max)
    }

    fn transport(&self, lat: f64, v: &Vec3) -> (Vec3, Vec3) {
        let r = self.earth.radius;
        let rho = Vec3::new(-v.y / r, v.x / r, v.x * lat.tan() / r);
        let omega = self.earth.rotation_rate * Vec3::new(0.0, lat.cos(), lat.sin());
        (rho, omega)
    }
}

impl Carrying for ShipFrame {
    fn attitude(&self, t: f64) -> Mat3 {
        let (lat, lon) = self.position(t);
        let spin = turn(&Vec3::z(), self.earth.rotation_rate * t);
        self.enu0.transpose() * spin * enu_axes(lat, lon)
    }
    fn angular_velocity(&self, t: f64) -> Vec3 {
        let (lat, _) = self.position(t);
        let (v, _) = self.velocity(t);
        let (rho, omega) = self.transport(lat, &v);
        self.attitude(t) * (omega + rho)
    }
    fn specific_force(&self, t: f64) -> Vec3 {
        let (lat, _) = self.position(t);
        let (v, dv) = self.velocity(t);
        let (rho, omega) = self.transport(lat, &v);
        let f = Vec3::new(0.0, 0.0, -self.earth.g) - dv - rho.cross(&v) - 2.0 * omega.cross(&v);
        self.attitude(t) * f
    }
}

/// Sperry's damping torque −D θ e₃ (body components), θ = asin(e₁·ẑ) the tilt of the spin axis
/// over the carrying frame's horizontal, and the liquid's viscous torque −k (ω − Rᵀ ω_frame)
/// on the element turning relative to the frame.
struct Damping<'a, C: Carrying> {
    carrier: &'a C,
    coefficient: f64,
    viscous: f64,
}

impl<C: Carrying> TorqueModel for Damping<'_, C> {
    fn torque(&mut self, ctx: &TorqueContext<'_>) -> Vec3 {
        let back = ctx.attitude.transpose();
        let up = back * (self.carrier.attitude(ctx.t) * Vec3::z());
        let tilt = up.x.clamp(-1.0, 1.0).asin();
        let relative = ctx.omega - back * self.carrier.angular_velocity(ctx.t);
        Vec3::new(0.0, 0.0, -self.coefficient * tilt) - self.viscous * relative
    }
    fn depends_on_omega(&self) -> bool {
        self.viscous != 0.0
    }
    fn is_zero(&self) -> bool {
        self.coefficient == 0.0 && self.viscous == 0.0
    }
}

/// The viscous damping rate of the element's motion relative to the frame, in units of D/H:
/// k = `VISCOUS_FACTOR` (D/H) I_max.
pub const VISCOUS_FACTOR: f64 = 10.0;

/// The smallest cos λ taken for a latitude off the pole (6 mm from it on the Earth).
const MIN_COS_LATITUDE: f64 = 1e-9;

impl Gyrocompass {
    /// A compass; errors name `latitude` (a pole has no meridian), `angular_momentum` (zero
    /// spin), `pendulosity`, `damping` (in [0, 1)) and `inertia`.
    pub fn new(
        latitude: f64,
        angular_momentum: f64,
        pendulosity: f64,
        damping: f64,
        inertia: [f64; 3],
        earth: Earth,
    ) -> Result<Self> {
        check_latitude(latitude)?;
        if latitude.cos() < MIN_COS_LATITUDE {
            return Err(Error::invalid(
                "latitude",
                format!(
                    "{} degrees is a pole: there is no meridian to seek (the horizontal part of \
                     the Earth's rotation, Ω cos λ, vanishes)",
                    num(latitude.to_degrees())
                ),
            ));
        }
        if !(angular_momentum.is_finite() && angular_momentum > 0.0) {
            return Err(Error::invalid(
                "angular_momentum",
                format!(
                    "must be finite and > 0 (a rotor that does not spin seeks no meridian), got {}",
                    num(angular_momentum)
                ),
            ));
        }
        check_positive("pendulosity", pendulosity)?;
        if !(damping.is_finite() && (0.0..1.0).contains(&damping)) {
            return Err(Error::invalid(
                "damping",
                format!("the damping ratio must be in [0, 1), got {}", num(damping)),
            ));
        }
        for m in inertia {
            if !(m.is_finite() && m > 0.0) {
                return Err(Error::invalid(
                    "inertia",
                    format!("the moments must be finite and > 0 (kg·m²), got {inertia:?}"),
                ));
            }
        }
        BodyInertia::from_moments(inertia).map_err(|e| Error::invalid("inertia", e.message))?;
        let out = Self {
            latitude,
            angular_momentum,
            pendulosity,
            damping,
            inertia,
            earth,
        };
        // Every derived rate must be a double: P/H, ω_n, D, k and the period.
        let period = 2.0 * PI * (angular_momentum / (pendulosity * out.omega_c())).sqrt();
        let derived = [
            pendulosity / angular_momentum,
            out.natural_frequency(),
            out.damping_coefficient(),
            out.viscous_coefficient(),
        ];
        let period_ok = earth.rotation_rate == 0.0 || (period.is_finite() && period > 0.0);
        if !(derived.iter().all(|x| x.is_finite()) && period_ok) {
            return Err(Error::invalid(
                "angular_momentum",
                format!(
                    "H = {} kg·m²/s against the pendulosity P = {} N·m gives rates (P/H, the \
                     period, the damping torque) beyond the doubles",
                    num(angular_momentum),
                    num(pendulosity)
                ),
            ));
        }
        Ok(out)
    }

    /// The compass whose period is Schuler's, 2π √(R/g) (84.4 min on the default Earth): H =
    /// P Ω cos λ R / g. Errors as [`Gyrocompass::new`], and `rotation_rate` for a still Earth.
    pub fn schuler_tuned(
        latitude: f64,
        pendulosity: f64,
        damping: f64,
        inertia: [f64; 3],
        earth: Earth,
    ) -> Result<Self> {
        check_latitude(latitude)?;
        check_positive("pendulosity", pendulosity)?;
        Self::require_rotation(&earth)?;
        let h = pendulosity * earth.rotation_rate * latitude.cos() * earth.radius / earth.g;
        Self::new(latitude, h, pendulosity, damping, inertia, earth)
    }

    fn require_rotation(earth: &Earth) -> Result<()> {
        if earth.rotation_rate > 0.0 {
            Ok(())
        } else {
            Err(Error::invalid(
                "rotation_rate",
                "the Earth does not turn: a gyrocompass has no meridian to seek and no period",
            ))
        }
    }

    /// Schuler's period 2π √(R/g) (s) of `earth`.
    pub fn schuler_period(earth: &Earth) -> f64 {
        2.0 * PI * (earth.radius / earth.g).sqrt()
    }

    fn omega_c(&self) -> f64 {
        self.earth.rotation_rate * self.latitude.cos()
    }

    fn omega_s(&self) -> f64 {
        self.earth.rotation_rate * self.latitude.sin()
    }

    /// The undamped period of the settling oscillation about the meridian,
    /// 2π √(H / (P Ω cos λ)) (s) (errors name `rotation_rate` for a still Earth).
    pub fn period(&self) -> Result<f64> {
        Self::require_rotation(&self.earth)?;
        Ok(2.0 * PI * (self.angular_momentum / (self.pendulosity * self.omega_c())).sqrt())
    }

    /// ω_n of the linearised equations, √(Ω_c (P/H + Ω_c)) (rad/s; 0 on a still Earth).
    pub fn natural_frequency(&self) -> f64 {
        let wc = self.omega_c();
        (wc * (self.pendulosity / self.angular_momentum + wc)).sqrt()
    }

    /// The damping torque's coefficient D = 2 ζ ω_n H (N·m/rad).
    pub fn damping_coefficient(&self) -> f64 {
        2.0 * self.damping * self.natural_frequency() * self.angular_momentum
    }

    /// The viscous coefficient k = 10 (D/H) I_max (N·m·s) of the liquid the element floats in,
    /// acting on its angular velocity relative to the local frame: a torque about the
    /// vertical proportional to the tilt damps the settling but feeds the fast nutation (at
    /// the rate D/H); k damps the nutation ten times faster, leaves the steady state alone
    /// (the element is then at rest in the frame) and changes the slow motion by k/H ≈
    /// 10 (D/H)(I/H) (< 10⁻³ for the defaults). Zero for an undamped compass.
    pub fn viscous_coefficient(&self) -> f64 {
        let i_max = self.inertia.iter().copied().fold(0.0, f64::max);
        VISCOUS_FACTOR * self.damping_coefficient() / self.angular_momentum * i_max
    }

    /// The ground's eastward speed Ω R cos λ (m/s).
    pub fn ground_speed(&self) -> f64 {
        self.earth.rotation_rate * self.earth.radius * self.latitude.cos()
    }

    fn check_ship(&self, speed: f64, course: f64) -> Result<f64> {
        Ship::new(speed, course)?;
        Self::require_rotation(&self.earth)?;
        let denominator = self.ground_speed() + speed * course.sin();
        if denominator <= 0.0 {
            return Err(Error::invalid(
                "speed",
                format!(
                    "the ship's westward speed −V sin C = {} m/s reaches the ground's eastward \
                     speed Ω R cos λ = {} m/s: the local frame's horizontal rotation, which the \
                     compass seeks, no longer points north (it vanishes or points south), and \
                     δ = atan(V cos C / (Ω R cos λ + V sin C)) stops holding",
                    num(-speed * course.sin()),
                    num(self.ground_speed())
                ),
            ));
        }
        Ok(denominator)
    }

    /// The speed (steaming) error δ = atan(V cos C / (Ω R cos λ + V sin C)) (rad; positive:
    /// the compass reads high, its north settled δ west of true north): the compass settles on
    /// the horizontal part of the local frame's total angular velocity, the Earth's plus the
    /// ship's over the curved Earth. `speed` V (m/s, ≥ 0), `course` C (rad, clockwise from
    /// north). Refused (naming `speed`) when Ω R cos λ + V sin C ≤ 0.
    pub fn speed_error(&self, speed: f64, course: f64) -> Result<f64> {
        let d = self.check_ship(speed, course)?;
        Ok((speed * course.cos()).atan2(d))
    }

    /// The manufacturers' small-angle form V cos C / (Ω R cos λ) (rad); the same refusals as
    /// [`Gyrocompass::speed_error`].
    pub fn speed_error_small_angle(&self, speed: f64, course: f64) -> Result<f64> {
        self.check_ship(speed, course)?;
        Ok(speed * course.cos() / self.ground_speed())
    }

    /// The steady state of the damped compass at rest on the ground, (error, tilt) (rad): the
    /// latitude (damping) error — what it reads minus true north, negative (it reads low, its
    /// north settled east) in the northern hemisphere — and the spin axis's tilt. Solves the
    /// full model's balance `H ω × s = −P tan θ (s × ẑ) − D θ e₃` (e₃ in the plane of s and ẑ):
    /// `sin α = D θ / (H Ω cos λ)`, `tan θ = H Ω sin λ / (P + H Ω cos λ cos α)`; small-angle
    /// form α ≈ D tan λ / (P + H Ω cos λ). Errors name `damping` if no steady state exists.
    pub fn settle(&self) -> Result<(f64, f64)> {
        let h = self.angular_momentum;
        let (wc, ws) = (self.omega_c(), self.omega_s());
        let d = self.damping_coefficient();
        let mut alpha: f64 = 0.0;
        let mut theta = 0.0;
        for _ in 0..200 {
            theta = (h * ws).atan2(self.pendulosity + h * wc * alpha.cos());
            let s = if d == 0.0 { 0.0 } else { d * theta / (h * wc) };
            if s.abs() >= 1.0 {
                return Err(Error::invalid(
                    "damping",
                    "the damping torque exceeds the Earth's horizontal rotation: no steady state",
                ));
            }
            let next = s.asin();
            let done = (next - alpha).abs() <= 1e-16 * (1.0 + alpha.abs());
            alpha = next;
            if done {
                break;
            }
        }
        if !(alpha.is_finite() && theta.is_finite()) {
            return Err(Error::invalid(
                "damping",
                "the steady state is not representable for these parameters",
            ));
        }
        Ok((-alpha, theta))
    }

    /// The latitude (damping) error (rad), see [`Gyrocompass::settle`].
    pub fn settle_error(&self) -> Result<f64> {
        Ok(self.settle()?.0)
    }

    /// The linearised compass's motion at the times `t` (s) from heading `heading0` and tilt
    /// `tilt0` (rad) at `t = 0`, on a steady `ship` (or at rest): the linear equations of the
    /// module docs (the heavy symmetric top of 2.98–2.121 carried at ω = Ω (0, cos λ, sin λ),
    /// 2.29, linearised about the meridian) for the deviation (x, y) from the settled heading
    /// α* = −(latitude error + speed error) and tilt θ* ([`Gyrocompass::settle`]),
    /// `ẋ = −(P/H + Ω_c) y`, `ẏ = Ω_c x − (D/H) y`, solved in closed form: with σ = D/(2H) =
    /// ζ ω_n and ω_d = ω_n √(1 − ζ²),
    ///
    /// ```text
    /// x = e^{−σt} (x₀ cos ω_d t + (σ x₀ − (P/H + Ω_c) y₀) sin ω_d t / ω_d),
    /// y = e^{−σt} (y₀ cos ω_d t + (Ω_c x₀ − σ y₀) sin ω_d t / ω_d),
    /// ```
    ///
    /// and the heading's envelope α* ± e^{−σt} √(x₀² + ((σ x₀ − (P/H + Ω_c) y₀)/ω_d)²)
    /// (= |x₀|/√(1 − ζ²) started at the settled tilt). Errors name `t`, `heading0`, `tilt0`,
    /// `speed`/`course` (as [`Gyrocompass::speed_error`]), `rotation_rate` (a still Earth).
    pub fn linear_solution(
        &self,
        t: &[f64],
        heading0: f64,
        tilt0: f64,
        ship: Option<Ship>,
    ) -> Result<LinearCompass> {
        check_finite("t", t)?;
        check_finite("heading0", &[heading0])?;
        check_finite("tilt0", &[tilt0])?;
        Self::require_rotation(&self.earth)?;
        let ship = ship.unwrap_or(Ship {
            speed: 0.0,
            course: 0.0,
        });
        let (error, tilt) = self.settle()?;
        let settled = -(error + self.speed_error(ship.speed, ship.course)?);
        let h = self.angular_momentum;
        let b = self.pendulosity / h + self.omega_c();
        let c = self.omega_c();
        let sigma = 0.5 * self.damping_coefficient() / h;
        let wd = (b * c - sigma * sigma).sqrt();
        let (x0, y0) = (heading0 - settled, tilt0 - tilt);
        let sx = (sigma * x0 - b * y0) / wd;
        let sy = (c * x0 - sigma * y0) / wd;
        let amp = x0.hypot(sx);
        let mut out = LinearCompass {
            settled_heading: settled,
            settled_tilt: tilt,
            ..LinearCompass::default()
        };
        for &time in t {
            let decay = (-sigma * time).exp();
            let (sn, cs) = (wd * time).sin_cos();
            let x = decay * (x0 * cs + sx * sn);
            let y = decay * (y0 * cs + sy * sn);
            let e = decay * amp;
            if !(x.is_finite() && y.is_finite() && e.is_finite()) {
                return Err(Error::invalid(
                    "t",
                    format!(
                        "the linear solution at t = {} s is not a finite number (the decay \
                         e^(-sigma t) overflows before t = 0)",
                        num(time)
                    ),
                ));
            }
            out.heading.push(settled + x);
            out.tilt.push(tilt + y);
            out.envelope.push(e);
        }
        Ok(out)
    }

    /// Integrates the compass as a rigid gyrostat carried by the local frame (module docs) for
    /// `duration` s from heading `heading0` and tilt `tilt0` (rad), at rest relative to the
    /// ground, on a `ship` (or at rest), sampled at `samples` evenly spaced times; `opts`
    /// ([`SimulateOptions`], DOP853 unless told otherwise; `samples` taken from it). Errors
    /// name `heading0`, `tilt0`, `duration`, `samples`, and `duration` if the ship would come
    /// within 0.1° of a pole.
    pub fn simulate(
        &self,
        duration: f64,
        heading0: f64,
        tilt0: f64,
        ship: Option<Ship>,
        opts: &SimulateOptions,
    ) -> Result<CompassRun> {
        check_finite("heading0", &[heading0])?;
        let ship = ship.unwrap_or(Ship {
            speed: 0.0,
            course: 0.0,
        });
        let ship = Ship::new(ship.speed, ship.course)?;
        self.simulate_track(duration, heading0, tilt0, &Track::steady(ship), opts)
    }

    /// [`Gyrocompass::simulate`] on a ship's [`Track`]: course and speed changes during the
    /// run. After a turn the compass settles on the new speed error; during it the ship's
    /// acceleration a acts on the pendulous element (the translational fictitious force, 2.5),
    /// a torque P a/g that precesses the spin axis by the *ballistic deflection* P Δv_N/(g H)
    /// (Δv_N the change of the northward velocity). The change of the speed error is
    /// Δv_N/(Ω R cos λ) (small-angle): when H = P Ω R cos λ / g — Schuler tuning — the two are
    /// equal, and the compass goes straight to its new settled heading, without a swing about
    /// it, however fast the turn (Arnold & Maunder 1961, ch. 11; Wrigley et al. 1969, ch. 12).
    /// Errors as [`Gyrocompass::simulate`]; the track is checked by [`Track::new`] (errors
    /// name `speed`, `course`, `turns`).
    pub fn simulate_track(
        &self,
        duration: f64,
        heading0: f64,
        tilt0: f64,
        track: &Track,
        opts: &SimulateOptions,
    ) -> Result<CompassRun> {
        check_finite("heading0", &[heading0])?;
        if !(tilt0.is_finite() && tilt0.abs() < FRAC_PI_2) {
            return Err(Error::invalid(
                "tilt0",
                format!("must be finite and in (-pi/2, pi/2), got {}", num(tilt0)),
            ));
        }
        check_finite("duration", &[duration])?;
        let body = BodyInertia::from_moments(self.inertia)?;
        let load = Load {
            mass_moment: Vec3::new(0.0, 0.0, -self.pendulosity / self.earth.g),
            rotor: Vec3::new(self.angular_momentum, 0.0, 0.0),
        };
        // Body → local: a turn by −θ₀ about e₂ (north end up), then by π/2 − α₀ about up.
        let rel = turn(&Vec3::z(), FRAC_PI_2 - heading0) * turn(&Vec3::y(), -tilt0);
        let q0 = crate::rotation::matrix_to_quaternion(&rel)?;
        let opts = SimulateOptions {
            method: match opts.method {
                Method::Auto => Method::Dop853,
                m => m,
            },
            ..*opts
        };
        let track = Track::new(track.start, track.turns.clone())?;
        let frame = ShipFrame::new(self.earth, self.latitude, &track);
        let end_lat = frame.max_abs_latitude(duration.max(0.0));
        if end_lat.is_nan() || end_lat > FRAC_PI_2 - 0.1f64.to_radians() {
            return Err(Error::invalid(
                "duration",
                format!(
                    "the ship would reach latitude {} degrees, within 0.1 degrees of a pole, \
                     where the meridian is lost",
                    num(end_lat.to_degrees())
                ),
            ));
        }
        let mut damping = Damping {
            carrier: &frame,
            coefficient: self.damping_coefficient(),
            viscous: self.viscous_coefficient(),
        };
        let run = simulate_carried(
            &body,
            Vec3::zeros(),
            Some(q0),
            duration,
            &frame,
            load,
            &mut damping,
            &opts,
        )?;
        let mut out = CompassRun::default();
        for (k, q) in run.relative_attitude.iter().enumerate() {
            let t = run.inertial.t[k];
            let s = quaternion_to_mat3_unchecked(q) * Vec3::x();
            out.t.push(t);
            out.heading.push(s.x.atan2(s.y));
            out.tilt.push(s.z.atan2(s.x.hypot(s.y)));
            out.latitude.push(frame.position(t).0);
        }
        Ok(out)
    }
}

/// The carrier of a compass at rest: the place on the Earth.
impl Gyrocompass {
    /// The place of the compass as a [`Carrier`].
    pub fn place(&self) -> Carrier {
        Carrier::Earth {
            earth: self.earth,
            latitude: self.latitude,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn compass(lat_deg: f64, damping: f64) -> Gyrocompass {
        Gyrocompass::schuler_tuned(
            lat_deg.to_radians(),
            1.2,
            damping,
            [0.5, 1.0, 1.0],
            Earth::default(),
        )
        .unwrap()
    }

    #[test]
    fn schuler_period_is_84_4_minutes() {
        let c = compass(50.0, 0.0);
        let p = c.period().unwrap();
        assert!((p / 60.0 - 84.4).abs() < 0.05, "{}", p / 60.0);
        assert!((p - Gyrocompass::schuler_period(&c.earth)).abs() < 1e-9 * p);
    }

    #[test]
    fn speed_error_closed_form_and_refusals() {
        let c = compass(50.0, 0.0);
        let (v, course): (f64, f64) = (10.0, 0.3);
        let g = c.earth.rotation_rate * c.earth.radius * 50f64.to_radians().cos();
        let want = (v * course.cos() / (g + v * course.sin())).atan();
        assert!((c.speed_error(v, course).unwrap() - want).abs() < 1e-15);
        assert_eq!(
            c.speed_error(400.0, -FRAC_PI_2).unwrap_err().argument,
            "speed"
        );
        assert_eq!(c.speed_error(-1.0, 0.0).unwrap_err().argument, "speed");
        let pole = Gyrocompass::new(FRAC_PI_2, 1.0, 1.0, 0.0, [1.0; 3], Earth::default());
        assert_eq!(pole.unwrap_err().argument, "latitude");
        let still = Gyrocompass::new(0.5, 0.0, 1.0, 0.0, [1.0; 3], Earth::default());
        assert_eq!(still.unwrap_err().argument, "angular_momentum");
        // Rates beyond the doubles are refused, not returned as infinities.
        let tiny = Gyrocompass::new(0.5, 5e-324, 1.2, 0.3, [1.0; 3], Earth::default());
        assert_eq!(tiny.unwrap_err().argument, "angular_momentum");
        let huge = Gyrocompass::new(0.5, 1e300, 1e-300, 0.3, [1.0; 3], Earth::default());
        assert_eq!(huge.unwrap_err().argument, "angular_momentum");
    }

    #[test]
    fn ship_frame_turns_at_its_angular_velocity_through_a_turn() {
        let track = Track::new(
            Ship::new(12.0, 0.4).unwrap(),
            vec![Turn {
                time: 100.0,
                duration: Some(80.0),
                speed: 6.0,
                course: -2.5,
            }],
        )
        .unwrap();
        let frame = ShipFrame::new(Earth::default(), 0.7, &track);
        for t in [50.0, 100.5, 140.0, 179.5, 400.0] {
            let h = 0.25;
            let d = (frame.attitude(t + h) - frame.attitude(t - h)) / (2.0 * h);
            let want = frame.angular_velocity(t).cross_matrix() * frame.attitude(t);
            assert!((d - want).norm() < 1e-12, "t = {t}: {}", (d - want).norm());
        }
        // The position is continuous where the legs meet.
        for t in [100.0, 180.0] {
            let (a, b) = (frame.position(t - 1e-9), frame.position(t));
            assert!((a.0 - b.0).abs() < 1e-14 && (a.1 - b.1).abs() < 1e-14);
        }
    }

    #[test]
    fn settle_matches_small_angle_form() {
        let c = compass(30.0, 0.05);
        let (err, _) = c.settle().unwrap();
        let lat = c.latitude;
        let small = -c.damping_coefficient() * lat.tan()
            / (c.pendulosity + c.angular_momentum * c.omega_c());
        assert!((err - small).abs() < 1e-3 * small.abs(), "{err} {small}");
    }
}
