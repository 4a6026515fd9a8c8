//! The free symmetric top, `I₁ = I₂ ≠ I₃` (the unit's "Torque free motion", eqs. 2.77–2.97),
//! in closed form: ω(t), the body and space cones, and the attitude.
//!
//! Conventions (the unit's, pinned by tests):
//! * body axes 1, 2 carry the equal moments `I₁`, axis 3 is the symmetry axis (`I₃`);
//! * `Ω = (I₁ − I₃) ω₃ / I₁` (2.83) with `ω̇₁ = Ω ω₂`, `ω̇₂ = −Ω ω₁` (2.81–2.82; the unit's
//!   2.78 misprints the sign, see the errata), so that `ω₁ = A sin(Ωt + θ₀)`,
//!   `ω₂ = A cos(Ωt + θ₀)` (2.85–2.86). Goldstein writes the opposite sign of Ω: same physics;
//! * attitudes are unit quaternions `[w, x, y, z]` rotating body components into space
//!   components; the angular momentum `L` is fixed in space.
//!
//! Scale and range as for the asymmetric body ([`super::free_scale`]): the motion is solved with
//! the larger moment and the largest |ω₀ᵢ| in [1, 2), so its accuracy does not depend on the
//! units; the time is limited to [`FreeSymmetricTop::max_time`] (the top has turned through
//! 2⁴² rad), and T, |L| and L refuse, naming `omega0`, when outside the normal double range.

use super::free_scale::{check_omega_range, representable, Scale};
use crate::error::{check_finite, Error, Result};
use crate::rotation::{
    axis_angle_quaternion, check_quaternion, coordinate_quaternion, hamilton,
    quaternion_rotate_unchecked, Quaternion,
};
use crate::special::fp::{describe, exponent, ldexp};
use crate::Vec3;

/// Whether the symmetric top is prolate (cigar, `I₃ < I₁`), oblate (disk, `I₃ > I₁`) or
/// spherical.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TopShape {
    /// `I₃ < I₁`: ω lies between the symmetry axis and L; the body cone rolls on the
    /// **outside** of the space cone, and Ω has the sense of ω₃.
    Prolate,
    /// `I₃ > I₁`: L lies between the symmetry axis and ω; the body cone surrounds the space cone
    /// and rolls on it with its **inside**, and Ω is opposite to ω₃.
    Oblate,
    /// `I₃ = I₁`: ω is constant, both cones degenerate to lines.
    Spherical,
}

impl TopShape {
    /// "prolate", "oblate" or "spherical".
    pub fn as_str(self) -> &'static str {
        match self {
            TopShape::Prolate => "prolate",
            TopShape::Oblate => "oblate",
            TopShape::Spherical => "spherical",
        }
    }
}

/// The exact torque-free motion of a symmetric top (all of the unit's 2.80–2.97).
///
/// ```
/// use poinsot::analytic::{FreeSymmetricTop, TopShape};
/// use poinsot::Vec3;
/// // I₁ = I₂ = 1, I₃ = 0.5 kg·m² (prolate), ω₀ = (0.1, 0, 2) rad/s in the body.
/// let top = FreeSymmetricTop::new(1.0, 0.5, Vec3::new(0.1, 0.0, 2.0), None)?;
/// assert_eq!(top.shape(), TopShape::Prolate);
/// // Ω = (I₁ − I₃) ω₃ / I₁ (2.83): ω circles the symmetry axis in the body at 1 rad/s.
/// assert!((top.precession_rate() - 1.0).abs() < 1e-15);
/// let w = top.omega(std::f64::consts::FRAC_PI_2)?; // a quarter turn later
/// assert!((w - Vec3::new(0.0, -0.1, 2.0)).norm() < 1e-14); // ω̇₁ = Ω ω₂, ω̇₂ = −Ω ω₁
/// # Ok::<(), poinsot::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct FreeSymmetricTop {
    i1: f64,
    i3: f64,
    omega0: Vec3,
    attitude0: Quaternion,
    scale: Scale,
    /// The motion at unit scale.
    sym: SymmetricMotion,
}

/// The closed-form motion of a body with two equal moments about symmetry axis `axis` (built
/// and evaluated at unit scale by its owners):
/// `R(t) = R₀ · Rot(L̂_b(0), |L| t / I⊥) · Rot(e_axis, Ω t)` with `Ω = (I⊥ − I_s) ω_s / I⊥`,
/// i.e. a precession about the fixed L at rate |L|/I⊥ composed with a spin about the symmetry
/// axis at rate Ω relative to the precessing frame (Landau & Lifshitz §33).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct SymmetricMotion {
    pub axis: usize,
    pub i_perp: f64,
    pub i_sym: f64,
    pub omega0: Vec3,
    pub attitude0: Quaternion,
    /// L(0) in body components, unit.
    pub l_hat_body0: Vec3,
    pub l_norm: f64,
    /// Ω = (I⊥ − I_s) ω_s / I⊥.
    pub big_omega: f64,
}

impl SymmetricMotion {
    pub(crate) fn new(axis: usize, moments: [f64; 3], omega0: Vec3, attitude0: Quaternion) -> Self {
        let i_sym = moments[axis];
        let i_perp = moments[(axis + 1) % 3];
        let l_body = Vec3::new(
            moments[0] * omega0.x,
            moments[1] * omega0.y,
            moments[2] * omega0.z,
        );
        let l_norm = l_body.norm();
        let l_hat_body0 = if l_norm > 0.0 {
            l_body / l_norm
        } else {
            Vec3::z()
        };
        let big_omega = (i_perp - i_sym) * omega0[axis] / i_perp;
        Self {
            axis,
            i_perp,
            i_sym,
            omega0,
            attitude0,
            l_hat_body0,
            l_norm,
            big_omega,
        }
    }

    /// ω(t) in body components: the part across the symmetry axis turns by −Ωt about it.
    pub(crate) fn omega(&self, t: f64) -> Vec3 {
        let (a, b) = ((self.axis + 1) % 3, (self.axis + 2) % 3);
        let (s, c) = (self.big_omega * t).sin_cos();
        let mut w = self.omega0;
        w[a] = self.omega0[a] * c + self.omega0[b] * s;
        w[b] = self.omega0[b] * c - self.omega0[a] * s;
        w
    }

    pub(crate) fn attitude(&self, t: f64) -> Quaternion {
        let precession = axis_angle_quaternion(&self.l_hat_body0, self.l_norm * t / self.i_perp);
        let spin = coordinate_quaternion(self.axis, self.big_omega * t);
        hamilton(&hamilton(&self.attitude0, &precession), &spin)
    }
}

/// Checks that `omega` (named `argument`) is finite and not zero (every component exactly 0:
/// the norm of a tiny nonzero vector may underflow).
pub(crate) fn check_omega(argument: &str, omega: &Vec3) -> Result<()> {
    check_finite(argument, omega.as_slice())?;
    if omega.iter().all(|&w| w == 0.0) {
        return Err(Error::invalid(
            argument,
            "must be nonzero: a body at rest has no torque-free motion to solve (got [0, 0, 0])",
        ));
    }
    Ok(())
}

/// Checks the moments of a symmetric top: `I1`, `I3` finite and > 0, and `I3 ≤ 2 I1` (the
/// triangle inequality `I₁ + I₂ ≥ I₃` of a real body, to 8 ε); errors name `I1` or `I3`
/// ([`crate::ErrorKind::InvalidInertia`]).
fn check_symmetric_moments(i1: f64, i3: f64) -> Result<()> {
    for (name, v) in [("I1", i1), ("I3", i3)] {
        if !(v.is_finite() && v > 0.0) {
            return Err(Error::inertia(
                name,
                format!("must be finite and > 0, got {v}"),
            ));
        }
    }
    // I3 / I1 ≤ 2 without overflow of 2·I1.
    if i3 / i1 > 2.0 * (1.0 + 8.0 * f64::EPSILON) {
        return Err(Error::inertia(
            "I3",
            format!(
                "must satisfy the triangle inequality I3 <= I1 + I2 = 2 I1 = {:e}, got {i3}",
                2.0 * i1
            ),
        ));
    }
    Ok(())
}

/// The inputs of 2.95–2.96 checked and brought to a common scale: `(a1, a3, l2, t, k)` with
/// `L² = l2 · 2^(k + 2c)`, `T I = t a · 2^(k + 2c)` for `I = a 2^c` (a1, a3 the moments at unit
/// scale), so that `ω₃² = (l2 − 2 t a1) / (a3 (a3 − a1)) · 2^k` (and A² likewise) with no
/// intermediate overflow or underflow whatever the units.
fn energy_momentum_terms(
    i1: f64,
    i3: f64,
    energy: f64,
    angular_momentum: f64,
) -> Result<(f64, f64, f64, f64, i32)> {
    check_symmetric_moments(i1, i3)?;
    if i1 == i3 {
        return Err(Error::inertia(
            "I3",
            format!(
                "must differ from I1 (= {i1}): for a spherical top (I1 = I3) T and |L| do not \
                 determine how ω splits between the axis and the plane (the formula divides by \
                 I3 − I1)"
            ),
        ));
    }
    for (name, v) in [("energy", energy), ("angular_momentum", angular_momentum)] {
        if !(v.is_finite() && v >= 0.0) {
            return Err(Error::invalid(
                name,
                format!("must be finite and >= 0, got {v}"),
            ));
        }
    }
    let c = exponent(i1.max(i3));
    let (a1, a3) = (ldexp(i1, -c), ldexp(i3, -c));
    // L = lm 2^a, T = tm 2^b; L² ~ 2^(2a) and T I ~ 2^(b + c), brought to the larger, 2^e.
    let split = |x: f64| if x > 0.0 { exponent(x) } else { i32::MIN / 4 };
    let (a, b) = (split(angular_momentum), split(energy));
    if a == i32::MIN / 4 && b == i32::MIN / 4 {
        return Ok((a1, a3, 0.0, 0.0, 0));
    }
    let e = (2 * a).max(b + c);
    let lm = ldexp(angular_momentum, -a);
    let l2 = ldexp(lm * lm, 2 * a - e);
    let t = ldexp(ldexp(energy, -b), b + c - e);
    // The pair must be reachable: 2T·min(I1, I3) ≤ L² ≤ 2T·max(I1, I3).
    let (lo, hi) = (2.0 * t * a1.min(a3), 2.0 * t * a1.max(a3));
    let slack = 8.0 * f64::EPSILON * hi;
    if l2 < lo - slack || l2 > hi + slack {
        return Err(Error::invalid(
            "angular_momentum",
            format!(
                "no motion of this top has T = {energy} J and |L| = {angular_momentum} kg·m²/s: \
                 L² must lie between 2T·min(I1, I3) = {} and 2T·max(I1, I3) = {} (kg·m²/s)², \
                 got L² = {}",
                describe(lo, e),
                describe(hi, e),
                describe(l2, e)
            ),
        ));
    }
    Ok((a1, a3, l2, t, e - 2 * c))
}

impl FreeSymmetricTop {
    /// The top with equal moments `i1` about body axes 1 and 2 and `i3` about the symmetry
    /// axis 3 (kg·m²), turning with body angular velocity `omega0` (rad/s) at t = 0 in the
    /// attitude `attitude0` (`[w, x, y, z]`, body → space; identity if `None`).
    ///
    /// Errors: `I1`, `I3` not finite and > 0, or `I3 > 2 I1` (the triangle inequality
    /// `I₁ + I₂ ≥ I₃` of a real body), named `I3` ([`crate::ErrorKind::InvalidInertia`]);
    /// `omega0` non-finite, zero, with its largest component below the smallest normal double,
    /// or turning faster than the largest double rad/s; `attitude0` not a unit quaternion.
    pub fn new(i1: f64, i3: f64, omega0: Vec3, attitude0: Option<Quaternion>) -> Result<Self> {
        check_symmetric_moments(i1, i3)?;
        check_omega("omega0", &omega0)?;
        let w_in = [omega0.x, omega0.y, omega0.z];
        check_omega_range("omega0", &w_in)?;
        let attitude0 = match attitude0 {
            Some(q) => check_quaternion("attitude0", &q, false)?,
            None => [1.0, 0.0, 0.0, 0.0],
        };
        let moments = [i1, i1, i3];
        let scale = Scale::new(&moments, &w_in);
        let mh = scale.moments_hat(&moments);
        let wh = Vec3::from(scale.omega_hat(&w_in));
        let sym = SymmetricMotion::new(2, mh, wh, attitude0);
        // |ω| is constant; the fastest rate is |Ω| ≤ |ω₃| or |L|/I₁ ≤ 2|ω|.
        let rate = sym.big_omega.abs().max(sym.l_norm / sym.i_perp);
        let top = ldexp(wh.norm().max(rate), scale.e_w);
        if !top.is_finite() {
            return Err(Error::invalid(
                "omega0",
                format!(
                    "this top turns faster than the largest double rad/s (|ω| or its \
                     precession rate ≈ {} rad/s)",
                    describe(wh.norm().max(rate), scale.e_w)
                ),
            ));
        }
        Ok(Self {
            i1,
            i3,
            omega0,
            attitude0,
            scale: scale.with_rate(rate),
            sym,
        })
    }

    /// I₁ = I₂ (kg·m²).
    pub fn i1(&self) -> f64 {
        self.i1
    }
    /// I₃ (kg·m²).
    pub fn i3(&self) -> f64 {
        self.i3
    }
    /// ω at t = 0 (body, rad/s).
    pub fn omega0(&self) -> Vec3 {
        self.omega0
    }
    /// The attitude at t = 0.
    pub fn attitude0(&self) -> Quaternion {
        self.attitude0
    }

    /// ω₃, constant (2.79–2.80) (rad/s).
    pub fn omega3(&self) -> f64 {
        self.omega0.z
    }

    /// Ω = (I₁ − I₃) ω₃ / I₁ (2.83), the rate at which ω precesses about the symmetry axis in
    /// the body (rad/s); ω̇₁ = Ω ω₂, ω̇₂ = −Ω ω₁. |Ω| ≤ |ω₃|; accurate to ε|ω| absolutely.
    pub fn precession_rate(&self) -> f64 {
        self.sym.big_omega * self.scale.s_w
    }

    /// The period 2π/|Ω| (s) of ω's precession about the symmetry axis in the body (2.83–2.88),
    /// in closed form. Refused, naming `omega0`, where Ω = 0 (a sphere, or ω₃ = 0: ω does not
    /// move in the body) or where the period is outside the normal double range.
    pub fn precession_period(&self) -> Result<f64> {
        let rate = self.sym.big_omega.abs();
        if rate == 0.0 {
            return Err(Error::invalid(
                "omega0",
                "the body-frame precession has no period where Ω = (I₁ − I₃) ω₃ / I₁ = 0 (a sphere, or ω₃ = 0: ω stays put in the body)",
            ));
        }
        // 2π/|Ω| as a mantissa 2π/(|Ω| 2^-e) in (π, 2π] and the power 2^(-e - e_w): the scaled
        // rate may be tiny (ω₃ ≪ |ω|), and 2π divided by it overflows before it is rescaled.
        let e = exponent(rate);
        representable(
            "omega0",
            "the precession period 2π/|Ω|",
            "s",
            std::f64::consts::TAU / ldexp(rate, -e),
            -e - self.scale.e_w,
        )
    }

    /// A = (ω₁² + ω₂²)^½, the constant magnitude of ω across the symmetry axis (2.85–2.88)
    /// (rad/s).
    pub fn amplitude(&self) -> f64 {
        self.omega0.x.hypot(self.omega0.y)
    }

    /// θ₀ of ω₁ = A sin(Ωt + θ₀), ω₂ = A cos(Ωt + θ₀) (2.85–2.86) (rad, in (−π, π]).
    pub fn phase(&self) -> f64 {
        self.omega0.x.atan2(self.omega0.y)
    }

    /// |ω| = (A² + ω₃²)^½, constant (2.89) (rad/s).
    pub fn omega_magnitude(&self) -> f64 {
        self.sym.omega0.norm() * self.scale.s_w
    }

    /// The kinetic energy T = ½ I₁ A² + ½ I₃ ω₃² (2.91) (J). Errors (naming `omega0`) when T
    /// is outside the normal double range.
    pub fn energy(&self) -> Result<f64> {
        let w = self.sym.omega0;
        let a2 = w.x * w.x + w.y * w.y;
        let t = 0.5 * (self.sym.i_perp * a2 + self.sym.i_sym * w.z * w.z);
        representable(
            "omega0",
            "the kinetic energy T",
            "J",
            t,
            self.scale.e_i + 2 * self.scale.e_w,
        )
    }

    /// |L| = (I₁² A² + I₃² ω₃²)^½ (2.93) (kg·m²/s). Errors (naming `omega0`) when |L| is
    /// outside the normal double range.
    pub fn angular_momentum_magnitude(&self) -> Result<f64> {
        representable(
            "omega0",
            "the angular momentum |L|",
            "kg·m²/s",
            self.sym.l_norm,
            self.scale.e_i + self.scale.e_w,
        )
    }

    /// L in space components (constant) (kg·m²/s). Errors as
    /// [`Self::angular_momentum_magnitude`].
    pub fn angular_momentum(&self) -> Result<Vec3> {
        self.angular_momentum_magnitude()?;
        let k = self.scale.e_i + self.scale.e_w;
        let l =
            quaternion_rotate_unchecked(&self.attitude0, &(self.sym.l_hat_body0 * self.sym.l_norm));
        Ok(l.map(|c| ldexp(c, k)))
    }

    /// The half-angle α_b of the body cone, traced by ω about the symmetry axis in the body:
    /// tan α_b = A / ω₃ (2.90) (rad, in [0, π]; above π/2 when ω₃ < 0).
    pub fn body_cone_angle(&self) -> f64 {
        self.amplitude().atan2(self.omega0.z)
    }

    /// The half-angle α_s of the space cone, traced by ω about the fixed L:
    /// cos α_s = ω·L / (ω L) = 2T / (ω L) (2.97) (rad, in [0, π/2]); computed as
    /// atan2(|ω × L|, ω·L) for accuracy at small angles (at unit scale).
    pub fn space_cone_angle(&self) -> f64 {
        let w = self.sym.omega0;
        let l = Vec3::new(
            self.sym.i_perp * w.x,
            self.sym.i_perp * w.y,
            self.sym.i_sym * w.z,
        );
        w.cross(&l).norm().atan2(w.dot(&l))
    }

    /// The constant angle between L and the symmetry axis: tan θ = I₁ A / (I₃ ω₃) (rad, in
    /// [0, π]).
    pub fn nutation_angle(&self) -> f64 {
        let w = self.sym.omega0;
        (self.sym.i_perp * w.x.hypot(w.y)).atan2(self.sym.i_sym * w.z)
    }

    /// The rate at which the symmetry axis and ω precess about L in space, |L| / I₁ (rad/s,
    /// at most 2|ω|).
    pub fn space_precession_rate(&self) -> f64 {
        self.sym.l_norm / self.sym.i_perp * self.scale.s_w
    }

    /// The largest |t| (s) at which ω(t) and the attitude are computed: the time in which
    /// the top turns through [`super::PHASE_LIMIT`] = 2⁴² rad at its fastest rate.
    pub fn max_time(&self) -> f64 {
        self.scale.t_max
    }

    /// Prolate, oblate or spherical (which cone rolls inside or outside which).
    pub fn shape(&self) -> TopShape {
        if self.i3 < self.i1 {
            TopShape::Prolate
        } else if self.i3 > self.i1 {
            TopShape::Oblate
        } else {
            TopShape::Spherical
        }
    }

    /// ω(t) in body components (2.80, 2.85–2.86) (rad/s). Errors name `t` (not finite, or
    /// beyond [`Self::max_time`]).
    pub fn omega(&self, t: f64) -> Result<Vec3> {
        let th = self.scale.time(t)?;
        Ok(self.scale.omega(&self.sym.omega(th)))
    }

    /// The attitude at t (`[w, x, y, z]`, body → space), in closed form:
    /// `R(t) = R₀ · Rot(L̂_b(0), |L| t / I₁) · Rot(e₃, Ω t)`. Errors name `t`.
    pub fn attitude(&self, t: f64) -> Result<Quaternion> {
        let th = self.scale.time(t)?;
        Ok(self.sym.attitude(th))
    }

    /// The symmetry axis e₃ in space components at t. Errors name `t`.
    pub fn symmetry_axis(&self, t: f64) -> Result<Vec3> {
        Ok(quaternion_rotate_unchecked(&self.attitude(t)?, &Vec3::z()))
    }

    /// ω₃² from the energy and |L|: ω₃² = (L² − 2 T I₁) / (I₃ (I₃ − I₁)) (2.95) (rad²/s²).
    ///
    /// Errors: `I1`, `I3` as for [`Self::new`], and `I3` equal to `I1` (the formula divides by
    /// I₃ − I₁); `energy`, `angular_momentum` not finite or negative; `angular_momentum` when
    /// no motion of this top has these T and |L| (L² outside [2T min(I₁, I₃), 2T max(I₁, I₃)]
    /// by more than 8 ε); `angular_momentum` when ω₃² is outside the normal double range.
    pub fn omega3_squared_from(
        i1: f64,
        i3: f64,
        energy: f64,
        angular_momentum: f64,
    ) -> Result<f64> {
        let (a1, a3, l2, t, k) = energy_momentum_terms(i1, i3, energy, angular_momentum)?;
        let v = ((l2 - 2.0 * t * a1) / (a3 * (a3 - a1))).max(0.0);
        representable("angular_momentum", "ω3²", "rad²/s²", v, k)
    }

    /// A² from the energy and |L|: A² = (L² − 2 I₃ T) / (I₁ (I₁ − I₃)) (2.96) (rad²/s²).
    /// Errors as [`Self::omega3_squared_from`].
    pub fn amplitude_squared_from(
        i1: f64,
        i3: f64,
        energy: f64,
        angular_momentum: f64,
    ) -> Result<f64> {
        let (a1, a3, l2, t, k) = energy_momentum_terms(i1, i3, energy, angular_momentum)?;
        let v = ((l2 - 2.0 * a3 * t) / (a1 * (a1 - a3))).max(0.0);
        representable("angular_momentum", "A²", "rad²/s²", v, k)
    }
}
