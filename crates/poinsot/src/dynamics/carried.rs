//! A rigid body whose pivot is carried by a moving frame: a top on a turntable, a gyroscope on
//! the rotating Earth (Foucault, 1852), a gyrocompass on a ship.
//!
//! The attitude is integrated in the **inertial** frame by [`simulate`] with Euler's equations
//! about the pivot (2.71). The pivot accelerates, so about it the body feels, besides gravity,
//! the translational fictitious force −m R̈ₚ (the unit's 2.5) acting at the centre of mass:
//! the torque is `N = (R c) × m f(t)` with `f = g − R̈ₚ` the specific force at the pivot and
//! `c` the centre of mass from the pivot in body axes. On the Earth, `g − R̈ₚ` of a place at rest
//! is the effective gravity (2.29–2.31), the plumb-line `−g ẑ` of the local frame, turning with
//! the Earth. A rotor spinning at constant rate inside the body (a gyrostat: its momentum `h`
//! fixed in the body axes) adds `−ω × h` (from `d(I·ω + h)/dt = N` in the fixed frame).
//!
//! The carrying frame's axes coincide with the inertial axes at `t = 0` (for a [`Carrier::Frame`],
//! the frame's own attitude at `t = 0` is kept); the attitude *seen from* the carrying frame is
//! `Aᵀ(t) R(t)`, `A(t)` the frame's attitude.

use super::model::BodyInertia;
use super::simulate::{simulate, SimulateOptions, Trajectory};
use super::torque::{TorqueContext, TorqueModel};
use crate::earth::{check_latitude, Earth};
use crate::error::{check_finite, Error, Result};
use crate::frames::{FrameMotion, MovingFrame, SteadyMotion};
use crate::rotation::{
    axis_angle_to_matrix, matrix_to_quaternion, matrix_to_quaternion_any_sign, row_major,
    same_hemisphere, Quaternion,
};
use crate::{Mat3, Vec3};

/// What a carrying frame must give at time `t` (s), in **fixed (inertial)** components.
pub trait Carrying {
    /// The frame's attitude A(t): carrying-frame components → fixed components.
    fn attitude(&self, t: f64) -> Mat3;
    /// The frame's angular velocity ω(t) (rad/s, fixed components).
    fn angular_velocity(&self, t: f64) -> Vec3;
    /// The specific force at the pivot, `f = g − R̈ₚ` (m/s², fixed components): gravity less
    /// the pivot's acceleration (the translational fictitious force per unit mass, 2.5).
    fn specific_force(&self, t: f64) -> Vec3;
}

/// A carrying frame: a steadily moving frame with the pivot fixed in it, or a place on the
/// rotating Earth.
// One carrier per run, passed by reference: the size of the steady frame's variant is no cost.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Carrier {
    /// A frame in steady motion ([`SteadyMotion`] from its state at `t = 0`), the pivot fixed
    /// in it at `pivot` (m, moving components), in a uniform gravity `gravity` fixed in space
    /// (m/s², fixed components). A turntable: `angular_velocity` along the vertical, `pivot`
    /// off the axis. The pivot's acceleration is `R̈ + ω̇ × Ap + ω × (ω × Ap)` (2.5–2.7).
    Frame {
        /// The frame's motion.
        motion: SteadyMotion,
        /// The pivot in moving components (m).
        pivot: Vec3,
        /// Gravity in fixed components (m/s²).
        gravity: Vec3,
    },
    /// A place at `latitude` (rad) on the rotating `earth`: the local ENU frame (x east, y
    /// north, z up along the plumb line), turning at ω = Ω (0, cos λ, sin λ) (2.33) about the
    /// Earth's axis; the specific force is the effective gravity `−g ẑ` (2.29–2.31: `g` is the
    /// plumb-line gravity, the centrifugal part included), turning with the ground. The fixed
    /// axes are the local ENU axes at `t = 0`.
    Earth {
        /// The Earth (rate Ω, radius, g).
        earth: Earth,
        /// Latitude λ (rad, north-positive).
        latitude: f64,
    },
}

impl Carrier {
    /// A steadily moving frame from its state at `t = 0` (errors name `angular_acceleration`
    /// if not parallel to ω, `pivot`, `gravity` if not finite).
    pub fn frame(initial: MovingFrame, pivot: Vec3, gravity: Vec3) -> Result<Self> {
        check_finite("pivot", pivot.as_slice())?;
        check_finite("gravity", gravity.as_slice())?;
        Ok(Carrier::Frame {
            motion: SteadyMotion::new(initial)?,
            pivot,
            gravity,
        })
    }

    /// A place on the Earth (errors name `latitude`).
    pub fn earth(earth: Earth, latitude: f64) -> Result<Self> {
        check_latitude(latitude)?;
        Ok(Carrier::Earth { earth, latitude })
    }

    /// For a place on the Earth: ω (rad/s, ENU = fixed components: the axis does not turn).
    fn earth_omega(earth: &Earth, latitude: f64) -> Vec3 {
        earth.rotation_rate * Vec3::new(0.0, latitude.cos(), latitude.sin())
    }
}

/// The rate (rad/s, clockwise from above positive) at which the heading of an axis **fixed in
/// inertial space** — Foucault's free gyroscope's (1852) — turns as seen from the ground at
/// `latitude` λ (rad) on `earth`, when the axis has heading `heading` α (rad, clockwise from
/// north) and tilt `tilt` θ (rad, above the horizontal): seen from the ground the axis s turns
/// as ṡ = −ω × s with ω = Ω (0, cos λ, sin λ) (2.29, 2.33), so
///
/// ```text
/// α̇ = Ω (sin λ − cos λ tan θ cos α).
/// ```
///
/// A horizontal axis (θ = 0) drifts at Ω sin λ, clockwise in the north like Foucault's
/// pendulum; an axis aimed at the celestial pole (α = 0, θ = λ) stays put. Errors name
/// `latitude`, `heading` (not finite) and `tilt` (a vertical axis has no heading).
pub fn fixed_axis_heading_rate(
    earth: &Earth,
    latitude: f64,
    heading: f64,
    tilt: f64,
) -> Result<f64> {
    check_latitude(latitude)?;
    check_finite("heading", &[heading])?;
    if !(tilt.is_finite() && tilt.abs() < std::f64::consts::FRAC_PI_2) {
        return Err(Error::invalid(
            "tilt",
            format!(
                "must be finite and in (-pi/2, pi/2) rad: a vertical axis has no heading, got {}",
                crate::error::num(tilt)
            ),
        ));
    }
    let rate = earth.rotation_rate * (latitude.sin() - latitude.cos() * tilt.tan() * heading.cos());
    if rate.is_finite() {
        Ok(rate)
    } else {
        Err(Error::invalid(
            "tilt",
            format!(
                "{} rad is too near the vertical: the heading's rate is not a finite number",
                crate::error::num(tilt)
            ),
        ))
    }
}

/// Foucault's free gyroscope (1852): a symmetric rotor (moments `[2, 1, 1]` kg·m², pivot at its
/// centre of mass, no torque) spinning at `spin` (rad/s) about its axis (body axis 1), the axis
/// starting at heading `heading0` (rad, clockwise from north) and tilt `tilt0` (rad, above the
/// horizontal) at rest relative to the ground, carried by the place at `latitude` (rad) on
/// `earth` for `duration` s by the exact flow, `samples` evenly spaced times. Returns the
/// rotor's attitude relative to the ground (body → ENU) at each sample; seen from the ground its
/// axis turns at [`fixed_axis_heading_rate`]. Errors name `heading0`, `tilt0`, `spin` (not
/// finite), `latitude`, `duration` or `samples`.
#[allow(clippy::too_many_arguments)]
pub fn free_gyroscope(
    earth: Earth,
    latitude: f64,
    heading0: f64,
    tilt0: f64,
    spin: f64,
    duration: f64,
    samples: usize,
) -> Result<Vec<Quaternion>> {
    check_finite("heading0", &[heading0])?;
    check_finite("tilt0", &[tilt0])?;
    check_finite("spin", &[spin])?;
    let place = Carrier::earth(earth, latitude)?;
    let rotor = BodyInertia::from_moments([2.0, 1.0, 1.0])?;
    // Body → ENU: a turn by −tilt0 about y (the x axis up), then by π/2 − heading0 about up.
    let rel = axis_angle_to_matrix(&Vec3::z(), std::f64::consts::FRAC_PI_2 - heading0)?
        * axis_angle_to_matrix(&Vec3::y(), -tilt0)?;
    let q0 = matrix_to_quaternion(&rel)?;
    let opts = SimulateOptions {
        method: super::simulate::Method::Exact,
        samples,
        ..SimulateOptions::default()
    };
    let spin = Vec3::new(spin, 0.0, 0.0);
    let free = &mut super::torque::Torque::None;
    let run = simulate_carried(
        &rotor,
        spin,
        Some(q0),
        duration,
        &place,
        Load::default(),
        free,
        &opts,
    )?;
    Ok(run.relative_attitude)
}

/// The rotation by `angle` (rad) about the unit vector `axis` (Rodrigues).
pub(crate) fn turn(axis: &Vec3, angle: f64) -> Mat3 {
    let k = axis.cross_matrix();
    Mat3::identity() + angle.sin() * k + (1.0 - angle.cos()) * (k * k)
}

impl Carrying for Carrier {
    fn attitude(&self, t: f64) -> Mat3 {
        match self {
            Carrier::Frame { motion, .. } => motion.at(t).attitude,
            Carrier::Earth { earth, latitude } => {
                let axis = Vec3::new(0.0, latitude.cos(), latitude.sin());
                turn(&axis, earth.rotation_rate * t)
            }
        }
    }

    fn angular_velocity(&self, t: f64) -> Vec3 {
        match self {
            Carrier::Frame { motion, .. } => motion.at(t).angular_velocity,
            Carrier::Earth { earth, latitude } => Self::earth_omega(earth, *latitude),
        }
    }

    fn specific_force(&self, t: f64) -> Vec3 {
        match self {
            Carrier::Frame {
                motion,
                pivot,
                gravity,
            } => {
                let f = motion.at(t);
                let p = f.attitude * pivot;
                let w = f.angular_velocity;
                gravity
                    - (f.acceleration + f.angular_acceleration.cross(&p) + w.cross(&w.cross(&p)))
            }
            Carrier::Earth { earth, .. } => self.attitude(t) * Vec3::new(0.0, 0.0, -earth.g),
        }
    }
}

/// The body's load in the carrying frame: its mass moment `m c` (kg·m, body axes: mass times
/// the centre of mass from the pivot) and an internal rotor's momentum `h` (kg·m²/s, body axes,
/// constant; zero for a plain rigid body).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Load {
    /// m c (kg·m), body components.
    pub mass_moment: Vec3,
    /// h (kg·m²/s), body components.
    pub rotor: Vec3,
}

impl Load {
    /// Checks the load; errors name `mass_moment` and `rotor`.
    pub fn validate(&self) -> Result<()> {
        check_finite("mass_moment", self.mass_moment.as_slice())?;
        check_finite("rotor", self.rotor.as_slice())
    }

    /// The torque of the load (N·m, body components) at attitude `r` (body → fixed), body ω
    /// `omega` (rad/s) and specific force `f` (m/s², fixed): `m c × Rᵀ f − ω × h`.
    #[inline]
    pub fn torque(&self, r: &Mat3, omega: &Vec3, f: &Vec3) -> Vec3 {
        self.mass_moment.cross(&(r.transpose() * f)) - omega.cross(&self.rotor)
    }
}

/// The torque on a carried body: the load's (fictitious force and gravity at the centre of
/// mass, the rotor's gyroscopic term) plus any other torque model `inner` (body components).
pub struct CarriedTorque<'a, C: Carrying + ?Sized, T: TorqueModel + ?Sized> {
    /// The carrying frame.
    pub carrier: &'a C,
    /// The load.
    pub load: Load,
    /// Any other torque.
    pub inner: &'a mut T,
}

impl<C: Carrying + ?Sized, T: TorqueModel + ?Sized> TorqueModel for CarriedTorque<'_, C, T> {
    fn torque(&mut self, ctx: &TorqueContext<'_>) -> Vec3 {
        let f = self.carrier.specific_force(ctx.t);
        let own = self.load.torque(ctx.attitude, ctx.omega, &f);
        if self.inner.is_zero() {
            own
        } else {
            own + self.inner.torque(ctx)
        }
    }
    fn depends_on_omega(&self) -> bool {
        self.load.rotor != Vec3::zeros() || self.inner.depends_on_omega()
    }
    fn is_zero(&self) -> bool {
        self.load.mass_moment == Vec3::zeros()
            && self.load.rotor == Vec3::zeros()
            && self.inner.is_zero()
    }
    /// V = −m c·f (R c the centre of mass from the pivot): the potential of the specific force
    /// at that instant (J), plus the inner model's.
    fn potential(&self, ctx: &TorqueContext<'_>) -> f64 {
        let f = self.carrier.specific_force(ctx.t);
        -(ctx.attitude * self.load.mass_moment).dot(&f) + self.inner.potential(ctx)
    }
}

/// A trajectory of a carried body: the inertial [`Trajectory`] and the attitude seen from the
/// carrying frame.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CarriedTrajectory {
    /// The motion in the inertial frame (ω body components, attitude body → fixed, L fixed
    /// components; `potential` is −m c·f, see [`CarriedTorque`]).
    pub inertial: Trajectory,
    /// The attitude seen from the carrying frame, `Aᵀ R` (body → carrying frame, `[w, x, y,
    /// z]`), continuous in sign.
    pub relative_attitude: Vec<[f64; 4]>,
    /// The carrying frame's attitude A(t) (carrying → fixed, `[w, x, y, z]`).
    pub frame_attitude: Vec<[f64; 4]>,
    /// The angular velocity relative to the carrying frame, body components (rad/s):
    /// `ω − Rᵀ ω_frame`.
    pub relative_omega: Vec<[f64; 3]>,
}

fn quat_of(m: &Mat3) -> Quaternion {
    matrix_to_quaternion_any_sign(&row_major(m))
}

fn mat_of(q: &Quaternion) -> Mat3 {
    crate::rotation::quaternion_to_mat3_unchecked(q)
}

/// Simulates a body carried by `carrier`: inertia `inertia` about the **pivot**, start attitude
/// `attitude0` **relative to the carrying frame** (body → carrying frame; identity if `None`)
/// and start angular velocity `omega0` **relative to the carrying frame** (rad/s, body
/// components: a body at rest on the ground has `omega0 = 0`), under the load's torque and
/// `torque` (body components), for `duration` seconds; options as [`simulate`]. Errors name
/// the argument (`omega0`, `attitude0`, `duration`, `mass_moment`, `rotor`, ...).
///
/// ```
/// use poinsot::dynamics::{simulate_carried, BodyInertia, Carrier, Load, SimulateOptions, Torque};
/// use poinsot::earth::Earth;
/// use poinsot::Vec3;
/// // Foucault's gyroscope at 49° N: a free rotor (pivot at its centre of mass) spinning about
/// // a horizontal axis pointing north; seen from the ground its axis turns at Ω sin λ.
/// let lat = 49f64.to_radians();
/// let place = Carrier::earth(Earth::default(), lat)?;
/// let rotor = BodyInertia::from_moments([1.0, 1.0, 2.0])?;
/// // Body axis 3 along north: a quarter turn about east (x).
/// let h = std::f64::consts::FRAC_PI_4;
/// let q0 = [h.cos(), -h.sin(), 0.0, 0.0];
/// let opts = SimulateOptions { samples: 3, ..Default::default() };
/// let run = simulate_carried(&rotor, Vec3::new(0.0, 0.0, 100.0), Some(q0), 3600.0, &place,
///     Load::default(), &mut Torque::None, &opts)?;
/// assert_eq!(run.relative_attitude.len(), 3);
/// # Ok::<(), poinsot::Error>(())
/// ```
#[allow(clippy::too_many_arguments)]
pub fn simulate_carried<C: Carrying + ?Sized, T: TorqueModel + ?Sized>(
    inertia: &BodyInertia,
    omega0: Vec3,
    attitude0: Option<Quaternion>,
    duration: f64,
    carrier: &C,
    load: Load,
    torque: &mut T,
    opts: &SimulateOptions,
) -> Result<CarriedTrajectory> {
    load.validate()?;
    check_finite("omega0", omega0.as_slice())?;
    let q_rel0 = match attitude0 {
        Some(q) => crate::rotation::check_quaternion("attitude0", &q, false)?,
        None => [1.0, 0.0, 0.0, 0.0],
    };
    let a0 = carrier.attitude(0.0);
    let r0 = a0 * mat_of(&q_rel0);
    // Inertial ω = relative ω + the frame's, body components.
    let w0 = omega0 + r0.transpose() * carrier.angular_velocity(0.0);
    let mut model = CarriedTorque {
        carrier,
        load,
        inner: torque,
    };
    let inertial = simulate(inertia, w0, Some(quat_of(&r0)), duration, &mut model, opts)?;
    let n = inertial.t.len();
    let mut out = CarriedTrajectory {
        relative_attitude: Vec::with_capacity(n),
        frame_attitude: Vec::with_capacity(n),
        relative_omega: Vec::with_capacity(n),
        ..CarriedTrajectory::default()
    };
    for k in 0..n {
        let t = inertial.t[k];
        let a = carrier.attitude(t);
        let r = mat_of(&inertial.attitude[k]);
        let rel = a.transpose() * r;
        let mut q = quat_of(&rel);
        if let Some(prev) = out.relative_attitude.last() {
            q = same_hemisphere(q, prev);
        }
        let mut qa = quat_of(&a);
        if let Some(prev) = out.frame_attitude.last() {
            qa = same_hemisphere(qa, prev);
        }
        let w = Vec3::from(inertial.omega[k]) - r.transpose() * carrier.angular_velocity(t);
        if !(q
            .iter()
            .chain(qa.iter())
            .chain(w.iter())
            .all(|x| x.is_finite()))
        {
            return Err(Error::diverged(
                "duration",
                format!("the carried attitude stopped being finite at t = {t} s"),
            ));
        }
        out.relative_attitude.push(q);
        out.frame_attitude.push(qa);
        out.relative_omega.push([w.x, w.y, w.z]);
    }
    out.inertial = inertial;
    Ok(out)
}
