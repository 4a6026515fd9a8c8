//! The exact torque-free motion of any rigid body (Jacobi 1849; Landau & Lifshitz §37;
//! Celledoni, Fassò, Säfström & Zanna 2008): ω(t) by the Jacobi elliptic functions on both
//! sides of the separatrix, and the attitude by the elliptic integral of the third kind.
//!
//! With the principal moments sorted, `I₁ < I₂ < I₃`, the kinetic energy `T` and `L² = |L|²`
//! fix the motion's regime through the sign of `L² − 2TI₂ = I₁(I₁ − I₂)ω₁² + I₃(I₃ − I₂)ω₃²`:
//! above the separatrix ω circles the axis of the largest moment (the "pole" p = 3), below it
//! the axis of the smallest (p = 1); on it (`L² = 2TI₂`) ω leaves and approaches the
//! intermediate axis in infinite time — the unstable rotation whose neighbouring motions are the
//! Dzhanibekov flips. With `o` the other extreme axis,
//!
//! ```text
//! ω_o = ω_o,m cn(τ | m),  ω₂ = ±ω₂,m sn(τ | m),  ω_p = ±ω_p,m dn(τ | m),   τ = λ t + τ₀,
//! ```
//!
//! where (for p = 3; exchange 1 ↔ 3 for p = 1), with `d₃ = 2TI₃ − L²`, `d₁ = L² − 2TI₁` (both
//! ≥ 0 and computed as sums of positive terms):
//! `ω₁,m² = d₃ / (I₁(I₃ − I₁))`, `ω₂,m² = d₃ / (I₂(I₃ − I₂))`, `ω₃,m² = d₁ / (I₃(I₃ − I₁))`,
//! `λ² = (I₃ − I₂) d₁ / (I₁I₂I₃)`, `m = (I₂ − I₁) d₃ / ((I₃ − I₂) d₁)` and
//! `1 − m = (I₃ − I₁)(L² − 2TI₂) / ((I₃ − I₂) d₁)` (no cancellation near the separatrix).
//!
//! The attitude: with L along the Z axis of an inertial frame, the z-x-z Euler angles (θ, ψ)
//! follow from `L̂` in body components and the precession angle from
//! `φ̇ = |L| (2T − I_p ω_p²) / (L² − I_p² ω_p²)`, which integrates to
//! `φ = |L| t / I_p ± |L|(I₃ − I₁)/(I₁I₃λ) · [Π(n; am τ | m) − Π(n; am τ₀ | m)]`, with the
//! characteristic `n = −I₃(I₂ − I₁)/(I₁(I₃ − I₂))` for p = 3 (`−I₁(I₃ − I₂)/(I₃(I₂ − I₁))` for
//! p = 1) and `Π(n; am(τ + 2K)) = Π(n; am τ) + 2Π(n)`. The body frame is permuted cyclically
//! so that the pole is its third axis. Two equal moments, three, and a rotation about one
//! principal axis are solved by their own closed forms.

//!
//! **Scale and range.** The motion is solved at unit scale ([`super::free_scale`]): the largest
//! moment and the largest component of ω₀ are brought into [1, 2) by powers of two, so the
//! accuracy at unit scale holds for any moments and any normal ω₀ of the double range, and
//! `ω(t; 2^k ω₀) = 2^k ω(2^k t; ω₀)` bit for bit. Quadratic forms of ω (d₁, d₃, L² − 2TI₂) carry
//! their own power of two, so a component 10⁻³⁰⁰ times the largest still counts (next to the
//! intermediate axis it sets the time of the next flip, ≈ ln(1/δ)/σ). The limits, each refused
//! with an error naming the argument:
//! * `omega0` with its largest component below 2.2e-308, or a motion whose |ω(t)| or rates would
//!   leave the normal double range;
//! * `t` beyond [`FreeRigidBody::max_time`], where the motion has turned through
//!   [`super::PHASE_LIMIT`] = 2⁴² rad and the phase is no longer known to ~1e-3 rad;
//! * the conserved scalars (energy, |L|, the period, λ) outside the normal double range, at
//!   their getters only (the motion is still computed).
//!
//! A rotation within 2⁻⁹⁰⁰ (relative) of a *stable* principal axis is the steady rotation to
//! that accuracy forever; within that of the intermediate axis it is solved exactly (it flips).

mod lanes;

pub(crate) use lanes::PiSeries;

use super::free_scale::{check_omega_range, representable, Scale};
use super::free_symmetric_top::{check_omega, SymmetricMotion};
use crate::error::{check_finite, Error, Result};
use crate::inertia::check_moments;
use crate::rotation::{
    axis_angle_quaternion, check_quaternion, conj, coordinate_quaternion, hamilton,
    matrix_to_quaternion_any_sign, normalized, quaternion_rotate_unchecked as rotate, row_major,
    same_hemisphere, Quaternion,
};
use crate::special::carlson::{rf_cd, rj_cd};
use crate::special::fp::{exponent, ldexp};
use crate::special::integrals::{pi_complete_split, pi_reduced_split};
use crate::special::Jacobi;
use crate::{Mat3, Vec3};

/// Above this |n| sin²φ the two terms of Π = s R_F + (n/3) s³ R_J cancel by more than
/// log₂(1 + 16) ≈ 4 bits and the form with positive terms only is used instead (it costs an
/// extra R_C; below, the direct sum loses at most those 4 bits, ≤ 4e-15 relative).
const CANCELLATION: f64 = 16.0;

/// Components below this fraction of the largest (2⁻⁹⁰⁰ ≈ 1.2e-271) about a *stable* principal
/// axis are a steady rotation to that relative accuracy forever (their wobble never grows);
/// keeping them in the elliptic solution would leave L̂'s tilt to subnormal numbers.
const NEGLIGIBLE: f64 = 1.183_052_186_166_774_7e-271;

/// Which motion a free rigid body performs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FreeRegime {
    /// ω is constant: a spherical top, or a rotation about one principal axis (including the
    /// unstable rotation about the intermediate axis, which the exact solution keeps forever).
    Steady,
    /// Two equal moments: ω precesses uniformly about the symmetry axis (2.80–2.89).
    Symmetric,
    /// `L² > 2TI₂`: ω circles the axis of the largest moment.
    AboutMaxAxis,
    /// `L² < 2TI₂`: ω circles the axis of the smallest moment.
    AboutMinAxis,
    /// `L² = 2TI₂` exactly: the separatrix, ω tends to the intermediate axis as t → ±∞.
    Separatrix,
}

impl FreeRegime {
    /// "steady", "symmetric", "about max axis", "about min axis" or "separatrix".
    pub fn as_str(self) -> &'static str {
        match self {
            FreeRegime::Steady => "steady",
            FreeRegime::Symmetric => "symmetric",
            FreeRegime::AboutMaxAxis => "about max axis",
            FreeRegime::AboutMinAxis => "about min axis",
            FreeRegime::Separatrix => "separatrix",
        }
    }
}

/// The elliptic solution of the asymmetric top at unit scale, in the sorted frame
/// (`I₁ < I₂ < I₃`).
#[derive(Debug, Clone, PartialEq)]
struct Elliptic {
    /// User body components → sorted components (a signed permutation, det +1).
    to_sorted: Mat3,
    sorted: [f64; 3],
    /// The pole (dn) and the other extreme (cn) axes, sorted indices (2 and 0, or 0 and 2).
    pole: usize,
    other: usize,
    /// Signed amplitudes of cn (axis `other`), sn (axis 1) and dn (axis `pole`).
    amp_cn: f64,
    amp_sn: f64,
    amp_dn: f64,
    lambda: f64,
    tau0: f64,
    jacobi: Jacobi,
    separatrix: bool,
    /// The characteristic of Π, its complete value and Π(n; am τ₀).
    n: f64,
    pi_complete: f64,
    pi0: f64,
    /// φ = rate_p t + kappa (Π(τ) − Π(τ₀)).
    rate_p: f64,
    kappa: f64,
    /// The working frame W: its axis i is sorted axis `w_axes[i]`, the pole third.
    w_axes: [usize; 3],
    /// q₀ ⊗ q(M)* ⊗ q(C₀)*, and q(M), with M: user body → W.
    q_pre: Quaternion,
    q_post: Quaternion,
}

#[derive(Debug, Clone, PartialEq)]
enum Motion {
    Steady { omega: Vec3, axis: Vec3, rate: f64 },
    Symmetric(SymmetricMotion),
    Elliptic(Box<Elliptic>),
}

/// The exact torque-free motion of a rigid body with principal moments `moments` (any order,
/// body axes along the principal axes), from body angular velocity `omega0` and attitude
/// `attitude0` at t = 0.
///
/// ```
/// use poinsot::analytic::FreeRigidBody;
/// use poinsot::Vec3;
/// let body = FreeRigidBody::new([1.0, 2.0, 3.0], Vec3::new(1.0, 0.1, 1.0), None).unwrap();
/// let w = body.omega(1000.0).unwrap();
/// // T and |L| are conserved exactly.
/// let t = 0.5 * (w.x * w.x + 2.0 * w.y * w.y + 3.0 * w.z * w.z);
/// assert!((t - body.energy().unwrap()).abs() < 1e-13);
/// // Scale invariance: ω(t; 2¹⁰⁰⁰ ω₀) = 2¹⁰⁰⁰ ω(2¹⁰⁰⁰ t; ω₀), bit for bit.
/// let s = 2f64.powi(1000);
/// let fast = FreeRigidBody::new([1.0, 2.0, 3.0], Vec3::new(1.0, 0.1, 1.0) * s, None).unwrap();
/// assert_eq!(fast.omega(1000.0 / s).unwrap(), w * s);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct FreeRigidBody {
    moments: [f64; 3],
    omega0: Vec3,
    attitude0: Quaternion,
    scale: Scale,
    /// T̂ = ½ ω̂·Î·ω̂ and L̂ (space) of the unit-scale motion.
    energy_hat: f64,
    l_space_hat: Vec3,
    regime: FreeRegime,
    motion: Motion,
}

impl FreeRigidBody {
    /// The motion of a body with principal moments `moments` (kg·m², > 0, any order, obeying
    /// the triangle inequality), turning with body angular velocity `omega0` (rad/s, nonzero)
    /// in attitude `attitude0` (unit quaternion `[w, x, y, z]`, body → space; identity if
    /// `None`) at t = 0.
    ///
    /// Errors: `moments` ([`crate::ErrorKind::InvalidInertia`]), `omega0` (non-finite, zero,
    /// largest component below the smallest normal double 2.2e-308, or a motion whose |ω(t)|
    /// or rates would leave the normal double range), `attitude0` (non-finite, zero or not unit
    /// within 1e-6).
    pub fn new(moments: [f64; 3], omega0: Vec3, attitude0: Option<Quaternion>) -> Result<Self> {
        check_moments(&moments)?;
        check_omega("omega0", &omega0)?;
        let w_in = [omega0.x, omega0.y, omega0.z];
        check_omega_range("omega0", &w_in)?;
        let attitude0 = match attitude0 {
            Some(q) => check_quaternion("attitude0", &q, false)?,
            None => [1.0, 0.0, 0.0, 0.0],
        };
        let scale = Scale::new(&moments, &w_in);
        let mh = scale.moments_hat(&moments);
        let wh = Vec3::from(scale.omega_hat(&w_in));
        let l_body = Vec3::new(mh[0] * wh.x, mh[1] * wh.y, mh[2] * wh.z);
        let energy_hat = 0.5 * (l_body.x * wh.x + l_body.y * wh.y + l_body.z * wh.z);
        let l_space_hat = rotate(&attitude0, &l_body);
        let l_norm = l_body.norm();

        // The dominant component and whether the other two are negligible next to it.
        let k = (0..3)
            .max_by(|&a, &b| wh[a].abs().total_cmp(&wh[b].abs()))
            .unwrap_or(0);
        let others = [(k + 1) % 3, (k + 2) % 3];
        let exactly_one = others.iter().all(|&i| wh[i] == 0.0);
        let negligible = others.iter().all(|&i| wh[i].abs() < NEGLIGIBLE);
        let sym_axis = symmetry_axis(&mh);
        let all_equal = mh[0] == mh[1] && mh[1] == mh[2];
        let stable_axis = {
            let lo = mh.iter().cloned().fold(f64::INFINITY, f64::min);
            let hi = mh.iter().cloned().fold(0.0, f64::max);
            mh[k] == lo || mh[k] == hi
        };
        let steady = all_equal || exactly_one || (negligible && sym_axis.is_none() && stable_axis);
        let (regime, motion, rate_hat, w_range) = if steady {
            let rate = wh.norm();
            (
                FreeRegime::Steady,
                Motion::Steady {
                    omega: wh,
                    axis: wh / rate,
                    rate,
                },
                rate,
                (rate, rate),
            )
        } else if let Some(axis) = sym_axis {
            let s = SymmetricMotion::new(axis, mh, wh, attitude0);
            let rate = s.big_omega.abs().max(s.l_norm / s.i_perp);
            let w = wh.norm();
            (FreeRegime::Symmetric, Motion::Symmetric(s), rate, (w, w))
        } else {
            let (regime, e) = Elliptic::new(&mh, &wh, &attitude0, l_norm)?;
            let (rate, range) = e.rates_and_range();
            (regime, Motion::Elliptic(Box::new(e)), rate, range)
        };
        // |ω(t)| and the rates must stay within the normal range at the user's scale.
        let top = ldexp(w_range.1.max(rate_hat), scale.e_w);
        if !top.is_finite() {
            return Err(Error::invalid(
                "omega0",
                format!(
                    "this motion turns faster than the largest double rad/s (|ω(t)| or its \
                     precession reaches ≈ {} rad/s)",
                    crate::special::fp::describe(w_range.1.max(rate_hat), scale.e_w)
                ),
            ));
        }
        if ldexp(w_range.0, scale.e_w) < f64::MIN_POSITIVE {
            return Err(Error::invalid(
                "omega0",
                format!(
                    "|ω(t)| falls to ≈ {} rad/s during this motion, below the smallest normal \
                     double (2.2e-308): ω(t) would lose digits (use units in which ω is larger)",
                    crate::special::fp::describe(w_range.0, scale.e_w)
                ),
            ));
        }
        Ok(Self {
            moments,
            omega0,
            attitude0,
            scale: scale.with_rate(rate_hat),
            energy_hat,
            l_space_hat,
            regime,
            motion,
        })
    }

    /// The principal moments, as given (kg·m²).
    pub fn moments(&self) -> [f64; 3] {
        self.moments
    }
    /// ω at t = 0 (body, rad/s).
    pub fn omega0(&self) -> Vec3 {
        self.omega0
    }
    /// The attitude at t = 0.
    pub fn attitude0(&self) -> Quaternion {
        self.attitude0
    }
    /// The kinetic energy T = ½ ω·I·ω, conserved (J). Errors (naming `omega0`) when T is
    /// outside the normal double range (e.g. I = (1, 2, 3), |ω₀| = 1e160: T ≈ 1e320).
    pub fn energy(&self) -> Result<f64> {
        representable(
            "omega0",
            "the kinetic energy T",
            "J",
            self.energy_hat,
            self.scale.e_i + 2 * self.scale.e_w,
        )
    }
    /// The angular momentum in space components, conserved (kg·m²/s). Errors (naming
    /// `omega0`) when |L| is outside the normal double range.
    pub fn angular_momentum(&self) -> Result<Vec3> {
        let k = self.scale.e_i + self.scale.e_w;
        representable(
            "omega0",
            "the angular momentum |L|",
            "kg·m²/s",
            self.l_space_hat.norm(),
            k,
        )?;
        Ok(self.l_space_hat.map(|c| ldexp(c, k)))
    }
    /// |L|, conserved (kg·m²/s): the length of [`Self::angular_momentum`], formed on the
    /// scaled vector so that it does not overflow on the way. Errors as
    /// [`Self::angular_momentum`].
    pub fn angular_momentum_magnitude(&self) -> Result<f64> {
        representable(
            "omega0",
            "the angular momentum |L|",
            "kg·m²/s",
            self.l_space_hat.norm(),
            self.scale.e_i + self.scale.e_w,
        )
    }
    /// The stability of steady rotation about each principal axis ([`super::axis_stability`])
    /// at this body's spin |ω₀| (rad/s, formed without overflow on the way).
    pub fn axis_stability(&self) -> Result<[super::AxisStability; 3]> {
        let w = self.omega0;
        let big = w.amax();
        let spin = if big == 0.0 {
            0.0
        } else {
            big * (w / big).norm()
        };
        super::axis_stability(self.moments, spin)
    }
    /// Which motion this is.
    pub fn regime(&self) -> FreeRegime {
        self.regime
    }

    /// The parameter m = k² of the Jacobi functions (0 for the steady and symmetric motions,
    /// 1 on the separatrix); dimensionless, accurate to ε absolutely.
    pub fn parameter(&self) -> f64 {
        match &self.motion {
            Motion::Elliptic(e) => e.jacobi.m(),
            _ => 0.0,
        }
    }

    /// λ, the rate of the Jacobi argument τ = λ t + τ₀ (rad/s; for the symmetric top |Ω|,
    /// 0 when ω is constant). Errors (naming `omega0`) outside the normal double range.
    pub fn frequency(&self) -> Result<f64> {
        let hat = match &self.motion {
            Motion::Elliptic(e) => e.lambda,
            Motion::Symmetric(s) => s.big_omega.abs(),
            Motion::Steady { .. } => 0.0,
        };
        representable("omega0", "the frequency λ", "rad/s", hat, self.scale.e_w)
    }

    /// The period of ω(t) in the body (s): 4K(m)/λ for the asymmetric top, 2π/|Ω| for the
    /// symmetric top; infinite (the exact answer) when ω is constant or on the separatrix.
    /// Errors (naming `omega0`) when a finite period is outside the normal double range.
    pub fn period(&self) -> Result<f64> {
        let hat = match &self.motion {
            Motion::Elliptic(e) if !e.separatrix => 4.0 * e.jacobi.quarter_period() / e.lambda,
            Motion::Symmetric(s) if s.big_omega != 0.0 => {
                2.0 * std::f64::consts::PI / s.big_omega.abs()
            }
            _ => return Ok(f64::INFINITY),
        };
        representable("omega0", "the period", "s", hat, -self.scale.e_w)
    }

    /// The time between two successive reversals of the intermediate-axis component ω₂ (half
    /// the period, 2K/λ): near the separatrix, the interval between Dzhanibekov flips (s).
    pub fn flip_interval(&self) -> Result<f64> {
        Ok(0.5 * self.period()?)
    }

    /// The largest |t| (s) at which the state is computed: the time in which the motion turns
    /// through [`super::PHASE_LIMIT`] = 2⁴² rad (its fastest rate, λ or the precession rate,
    /// times t). Infinite when the body does not turn that far within the double range.
    pub fn max_time(&self) -> f64 {
        self.scale.t_max
    }

    /// The principal axis (index into `moments`) that ω circles: the largest-moment axis above
    /// the separatrix, the smallest below; the symmetry axis of a symmetric top; `None` when ω
    /// is constant or on the separatrix.
    pub fn pole_axis(&self) -> Option<usize> {
        match &self.motion {
            Motion::Elliptic(e) if !e.separatrix => {
                let row = e.to_sorted.row(e.pole);
                (0..3).find(|&k| row[k] != 0.0)
            }
            Motion::Symmetric(s) => Some(s.axis),
            _ => None,
        }
    }

    /// The rate of a steady rotation, |ω| (rad/s, constant: ω does not move in the body), or
    /// `None` where ω moves ([`FreeRegime::Steady`] only).
    pub fn steady_rate(&self) -> Option<f64> {
        match &self.motion {
            // Within the normal range at the user's scale: checked by `new`.
            Motion::Steady { rate, .. } => Some(ldexp(*rate, self.scale.e_w)),
            _ => None,
        }
    }

    /// The principal axis (index into `moments`) of the intermediate moment when ω circles an
    /// outer axis and ω₀ lies nearest this middle one — its largest component (the first of
    /// equal ones) is along it: the body, spun about its unstable axis, flips over every
    /// [`Self::flip_interval`] (the Dzhanibekov effect). `None` otherwise (a steady or
    /// symmetric motion, the separatrix, or ω₀ nearest an outer axis).
    pub fn flips_about(&self) -> Option<usize> {
        let Motion::Elliptic(e) = &self.motion else {
            return None;
        };
        if e.separatrix {
            return None;
        }
        let row = e.to_sorted.row(1);
        let middle = (0..3).find(|&k| row[k] != 0.0)?;
        let w = [
            self.omega0.x.abs(),
            self.omega0.y.abs(),
            self.omega0.z.abs(),
        ];
        let largest = (0..3).fold(0, |best, k| if w[k] > w[best] { k } else { best });
        (largest == middle).then_some(middle)
    }

    /// ω(t) in body components (rad/s). Errors name `t` (not finite, or beyond
    /// [`Self::max_time`]).
    pub fn omega(&self, t: f64) -> Result<Vec3> {
        let th = self.scale.time(t)?;
        Ok(self.scale.omega(&self.omega_hat(th)))
    }

    /// ω̂ at unit-scale time t̂.
    #[inline]
    pub(crate) fn omega_hat(&self, th: f64) -> Vec3 {
        match &self.motion {
            Motion::Steady { omega, .. } => *omega,
            Motion::Symmetric(s) => s.omega(th),
            Motion::Elliptic(e) => e.to_sorted.transpose() * e.omega_sorted(e.tau(th)).0,
        }
    }

    /// The attitude at t (`[w, x, y, z]`, body → space). Errors name `t`.
    pub fn attitude(&self, t: f64) -> Result<Quaternion> {
        Ok(self.state(t)?.1)
    }

    /// ω(t) (body, rad/s) and the attitude at t together (cheaper than separately). Errors
    /// name `t` (not finite, or beyond [`Self::max_time`]).
    pub fn state(&self, t: f64) -> Result<(Vec3, Quaternion)> {
        let th = self.scale.time(t)?;
        let (w, q) = self.state_hat(th);
        Ok((self.scale.omega(&w), q))
    }

    /// (ω̂, q) at unit-scale time t̂.
    #[inline]
    fn state_hat(&self, th: f64) -> (Vec3, Quaternion) {
        match &self.motion {
            Motion::Steady { omega, axis, rate } => (
                *omega,
                hamilton(&self.attitude0, &axis_angle_quaternion(axis, rate * th)),
            ),
            Motion::Symmetric(s) => (s.omega(th), s.attitude(th)),
            Motion::Elliptic(e) => {
                let (w_sorted, q) = e.state(th);
                (e.to_sorted.transpose() * w_sorted, q)
            }
        }
    }

    /// ω (body) and the attitude at each of `times`, the quaternions' signs made continuous
    /// from one time to the next (`q` and `−q` are the same attitude). Errors name `t`.
    pub fn sample(&self, times: &[f64]) -> Result<(Vec<[f64; 3]>, Vec<Quaternion>)> {
        let mut omega = Vec::with_capacity(times.len());
        let mut attitude: Vec<Quaternion> = Vec::with_capacity(times.len());
        for (i, &t) in times.iter().enumerate() {
            if i % crate::control::CHUNK == 0 {
                crate::control::tick_by(crate::control::CHUNK as u32)?; // Ctrl-C
            }
            let (w, q) = self.state(t)?;
            let q = match attitude.last() {
                Some(prev) => same_hemisphere(q, prev),
                None => q,
            };
            omega.push([w.x, w.y, w.z]);
            attitude.push(q);
        }
        Ok((omega, attitude))
    }

    /// L(t) in body components (kg·m²/s). Errors name `t`, or `omega0` when |L| is outside
    /// the normal double range.
    pub fn angular_momentum_body(&self, t: f64) -> Result<Vec3> {
        let th = self.scale.time(t)?;
        let k = self.scale.e_i + self.scale.e_w;
        representable(
            "omega0",
            "the angular momentum |L|",
            "kg·m²/s",
            self.l_space_hat.norm(),
            k,
        )?;
        let w = self.omega_hat(th);
        let m = self.scale.moments_hat(&self.moments);
        Ok(Vec3::new(
            ldexp(m[0] * w.x, k),
            ldexp(m[1] * w.y, k),
            ldexp(m[2] * w.z, k),
        ))
    }

    /// ω(t) in space components: its tip traces the herpolhode on the invariable plane
    /// `ω·L̂ = 2T/|L|` (rad/s). Errors name `t`.
    pub fn omega_space(&self, t: f64) -> Result<Vec3> {
        let (w, q) = self.state(t)?;
        Ok(rotate(&q, &w))
    }

    /// The unit-scale state for Poinsot's construction: ω̂(t̂), the attitude, T̂, L̂ (space),
    /// and the moments' exponent.
    pub(crate) fn unit_scale(&self) -> (f64, Vec3, i32) {
        (self.energy_hat, self.l_space_hat, self.scale.e_i)
    }

    /// The unit-scale period (∞ when there is none) and frequency, for sampling the polhode.
    pub(crate) fn period_and_frequency_hat(&self) -> (f64, f64) {
        match &self.motion {
            Motion::Elliptic(e) => (
                if e.separatrix {
                    f64::INFINITY
                } else {
                    4.0 * e.jacobi.quarter_period() / e.lambda
                },
                e.lambda,
            ),
            Motion::Symmetric(s) if s.big_omega != 0.0 => (
                2.0 * std::f64::consts::PI / s.big_omega.abs(),
                s.big_omega.abs(),
            ),
            _ => (f64::INFINITY, 0.0),
        }
    }

    /// ω (body, rad/s) and the attitude at each of `times` into `omega` and `attitude` (of the
    /// same length): [`FreeRigidBody::state`] at every time. With `series` (from
    /// [`FreeRigidBody::pi_series`]) the elliptic motion runs on SIMD lanes: ω bit for bit as
    /// `state`, the attitude to round-off of the phase (its Π summed as a Fourier series).
    /// Errors name `t`
    /// (the first time not finite or beyond [`FreeRigidBody::max_time`]), before any state.
    pub(crate) fn states_into(
        &self,
        times: &[f64],
        omega: &mut [[f64; 3]],
        attitude: &mut [Quaternion],
        series: Option<&PiSeries>,
    ) -> Result<()> {
        for &t in times {
            self.scale.time(t)?;
        }
        if let (Motion::Elliptic(e), Some(series)) = (&self.motion, series) {
            crate::simd::dispatch(lanes::EllipticStates {
                body: self,
                e,
                series,
                times,
                omega,
                attitude,
            });
            return Ok(());
        }
        for ((&t, w), q) in times.iter().zip(omega).zip(attitude) {
            let (ws, qs) = self.state(t)?;
            *w = [ws.x, ws.y, ws.z];
            *q = qs;
        }
        Ok(())
    }

    /// The Fourier series of Π of an elliptic motion, for [`FreeRigidBody::states_into`]:
    /// `None` for the other motions, or where the series would converge slowly.
    pub(crate) fn pi_series(&self) -> Option<PiSeries> {
        match &self.motion {
            Motion::Elliptic(e) => PiSeries::new(e),
            _ => None,
        }
    }

    /// The scale of the motion (Poinsot's construction and the tests of scale invariance).
    pub(crate) fn scale(&self) -> &Scale {
        &self.scale
    }

    /// (ω̂, q) at unit-scale time t̂ (Poinsot's construction).
    pub(crate) fn state_at_hat(&self, th: f64) -> (Vec3, Quaternion) {
        self.state_hat(th)
    }
}

/// The reduction τ = 2Kj + r and the Jacobi functions at r.
#[derive(Debug, Clone, Copy)]
struct Reduced {
    j: f64,
    sn: f64,
    cn: f64,
    dn: f64,
}

/// The index of the distinct moment when exactly two are equal.
fn symmetry_axis(m: &[f64; 3]) -> Option<usize> {
    if m[0] == m[1] && m[1] != m[2] {
        Some(2)
    } else if m[1] == m[2] && m[0] != m[1] {
        Some(0)
    } else if m[0] == m[2] && m[0] != m[1] {
        Some(1)
    } else {
        None
    }
}

/// A signed permutation matrix (det +1) whose row i picks axis `axes[i]`.
fn permutation(axes: [usize; 3]) -> Mat3 {
    let mut p = Mat3::zeros();
    for (i, &a) in axes.iter().enumerate() {
        p[(i, a)] = 1.0;
    }
    if p.determinant() < 0.0 {
        for k in 0..3 {
            p[(2, k)] = -p[(2, k)];
        }
    }
    p
}

/// The rotation C with third row `l` (a unit vector), C = R_x(θ) R_z(ψ) with
/// (sin θ sin ψ, sin θ cos ψ, cos θ) = l: the z-x-z Euler angles (θ, ψ) of the direction of L.
fn euler_tilt(l: &Vec3) -> Quaternion {
    let rho = l.x.hypot(l.y);
    let (a, b) = (l.y / rho, l.x / rho);
    let c = [a, -b, 0.0, l.z * b, l.z * a, -rho, l.x, l.y, l.z];
    matrix_to_quaternion_any_sign(&c)
}

/// `ca a² + cb b²` as (value, e) with the sum = value · 2^(2e): the squares of components
/// 10⁻³⁰⁰ apart neither underflow nor lose each other.
fn quad(a: f64, b: f64, ca: f64, cb: f64) -> (f64, i32) {
    let mx = a.abs().max(b.abs());
    if mx == 0.0 {
        return (0.0, 0);
    }
    let e = exponent(mx);
    let (a, b) = (ldexp(a, -e), ldexp(b, -e));
    (ca * a * a + cb * b * b, e)
}

/// `(num/den)^½ · 2^e` for a quad's value `num` (≥ 0) and a positive `den`.
fn root(num: f64, den: f64, e: i32) -> f64 {
    ldexp((num / den).sqrt(), e)
}

impl Elliptic {
    /// The solution at unit scale (largest moment and largest |ω̂_i| in [1, 2)).
    fn new(
        moments: &[f64; 3],
        omega0: &Vec3,
        attitude0: &Quaternion,
        l_norm: f64,
    ) -> Result<(FreeRegime, Self)> {
        let mut order = [0usize, 1, 2];
        order.sort_by(|&a, &b| moments[a].total_cmp(&moments[b]));
        let to_sorted = permutation(order);
        let [i1, i2, i3] = [moments[order[0]], moments[order[1]], moments[order[2]]];
        let w = to_sorted * omega0;
        // d₃ = 2TI₃ − L², d₁ = L² − 2TI₁, s₂ = L² − 2TI₂: sums without cancellation, each with
        // its own power of two.
        let (d3, e3) = quad(w.x, w.y, i1 * (i3 - i1), i2 * (i3 - i2));
        let (d1, e1) = quad(w.y, w.z, i2 * (i2 - i1), i3 * (i3 - i1));
        let (s2, es) = quad(w.x, w.z, i1 * (i1 - i2), i3 * (i3 - i2));
        let (pole, other, regime) = if s2 > 0.0 {
            (2, 0, FreeRegime::AboutMaxAxis)
        } else if s2 < 0.0 {
            (0, 2, FreeRegime::AboutMinAxis)
        } else {
            (2, 0, FreeRegime::Separatrix)
        };
        let separatrix = regime == FreeRegime::Separatrix;
        // Amplitudes, λ, m and k' = (1 − m)^½ (module docs; p = 1 exchanges 1 ↔ 3).
        let (amp_o, amp_2, amp_p, lambda, m, kc) = if pole == 2 {
            (
                root(d3, i1 * (i3 - i1), e3),
                root(d3, i2 * (i3 - i2), e3),
                root(d1, i3 * (i3 - i1), e1),
                root((i3 - i2) * d1, i1 * i2 * i3, e1),
                ldexp((i2 - i1) * d3 / ((i3 - i2) * d1), 2 * (e3 - e1)),
                root((i3 - i1) * s2.max(0.0), (i3 - i2) * d1, es - e1),
            )
        } else {
            (
                root(d1, i3 * (i3 - i1), e1),
                root(d1, i2 * (i2 - i1), e1),
                root(d3, i1 * (i3 - i1), e3),
                root((i2 - i1) * d3, i1 * i2 * i3, e3),
                ldexp((i3 - i2) * d1 / ((i2 - i1) * d3), 2 * (e1 - e3)),
                root((i3 - i1) * (-s2), (i2 - i1) * d3, es - e3),
            )
        };
        let jacobi = if separatrix {
            Jacobi::new(1.0)?
        } else if m <= 0.5 {
            Jacobi::new(m)?
        } else {
            Jacobi::with_complementary_modulus(kc.clamp(f64::from_bits(1), 1.0))?
        };
        // k' below the least subnormal (ω within 1e-323 of the intermediate axis): the
        // least subnormal, K = ln(4/k') ≈ 745 then being right to 0.1 %.
        let kc = if separatrix {
            0.0
        } else {
            jacobi.complementary_modulus().max(f64::from_bits(1))
        };
        // Signs: ω_p never vanishes (dn > 0); ω₂ = sign(ω_o ω_p) ω₂,m sn with ω_o ∝ +cn
        // (off the separatrix; on it cn > 0, so ω_o keeps the sign of ω_o(0)).
        let sign = |v: f64| if v < 0.0 { -1.0 } else { 1.0 };
        let s_p = sign(w[pole]);
        let s_o = if separatrix { sign(w[other]) } else { 1.0 };
        let amp_cn = s_o * amp_o;
        let amp_sn = s_o * s_p * amp_2;
        let amp_dn = s_p * amp_p;
        // τ₀ from sn τ₀ and cn τ₀ (ratios of ω₀'s components, accurate even where the amplitude
        // φ₀ is within round-off of ±π/2, as it is next to the separatrix).
        let (a, b) = (w.y / amp_sn, w[other] / amp_cn);
        let h = a.hypot(b);
        let (sn0, cn0) = (a / h, b / h);
        let tau0 = if separatrix {
            // sn = tanh τ, cn = sech τ: τ₀ = asinh(sn/cn), ln(2 sn/cn) when that overflows.
            let ratio = a / b;
            if ratio.abs() < 1e150 {
                ratio.asinh()
            } else {
                a.signum() * ((2.0 * a.abs()).ln() - b.abs().ln())
            }
        } else {
            let k = jacobi.quarter_period();
            let f = sn0.abs() * rf_cd(cn0.abs(), cn0.hypot(kc * sn0));
            let f = if cn0 >= 0.0 { f } else { 2.0 * k - f };
            if sn0 < 0.0 {
                -f
            } else {
                f
            }
        };
        // The precession angle φ (module docs).
        let n = if pole == 2 {
            -i3 * (i2 - i1) / (i1 * (i3 - i2))
        } else {
            -i1 * (i3 - i2) / (i3 * (i2 - i1))
        };
        let kappa_sign = if pole == 2 { 1.0 } else { -1.0 };
        let kappa = kappa_sign * l_norm * (i3 - i1) / (i1 * i3 * lambda);
        let sorted = [i1, i2, i3];
        let rate_p = l_norm / sorted[pole];
        let w_axes = if pole == 2 { [0, 1, 2] } else { [1, 2, 0] };
        let to_w = permutation(w_axes) * to_sorted;
        let mut e = Self {
            to_sorted,
            sorted,
            pole,
            other,
            amp_cn,
            amp_sn,
            amp_dn,
            lambda,
            tau0,
            jacobi,
            separatrix,
            n,
            pi_complete: 0.0,
            pi0: 0.0,
            rate_p,
            kappa,
            w_axes,
            q_pre: [1.0, 0.0, 0.0, 0.0],
            q_post: matrix_to_quaternion_any_sign(&row_major(&to_w)),
        };
        if !separatrix {
            // Π(n | m) = R_F(0, m₁, 1) + (n/3) R_J(0, m₁, 1, 1 − n) (DLMF 19.25.2); for n < −1
            // (a body nearly symmetric about its pole, |n| ~ 1/gap) the two terms would cancel:
            // the form with positive terms (DLMF 19.21.12), while m₁ = k'² is a normal double.
            e.pi_complete = if e.positive_form() {
                pi_complete_split(n, e.jacobi.m(), kc * kc)?
            } else {
                rf_cd(0.0, kc) + n / 3.0 * rj_cd(0.0, kc, 1.0 - n)
            };
        }
        let (w_s0, red0) = e.omega_sorted(tau0);
        e.pi0 = e.pi_of(tau0, red0);
        let c0 = euler_tilt(&e.l_hat_w(&w_s0));
        e.q_pre = hamilton(&hamilton(attitude0, &conj(&e.q_post)), &conj(&c0));
        check_finite(
            "omega0",
            &[e.lambda, e.tau0, e.kappa, e.pi0, e.pi_complete, e.q_pre[0]],
        )
        .map_err(|_| {
            Error::invalid(
                "omega0",
                "the elliptic solution is not finite for this state (report it as a bug)",
            )
        })?;
        Ok((regime, e))
    }

    /// The fastest rate of the motion (λ, or the precession rate's bound |L|/min I over the
    /// axes other than the pole: φ̇ = |L| Σ' I_i ω_i² / Σ' I_i² ω_i²) and the range of |ω̂(t)|:
    /// |ω|² is linear in sn², so its extremes are at sn² = 0 and 1.
    fn rates_and_range(&self) -> (f64, (f64, f64)) {
        let [i1, i2, i3] = self.sorted;
        let i_min_other = if self.pole == 2 {
            i1.min(i2)
        } else {
            i2.min(i3)
        };
        let l = self.rate_p * self.sorted[self.pole];
        let rate = self.lambda.max(l / i_min_other);
        let kc = self.jacobi.complementary_modulus();
        let at_sn0 = self.amp_cn.hypot(self.amp_dn);
        let at_sn1 = self.amp_sn.hypot(kc * self.amp_dn);
        (rate, (at_sn0.min(at_sn1), at_sn0.max(at_sn1)))
    }

    #[inline]
    fn tau(&self, t: f64) -> f64 {
        self.lambda.mul_add(t, self.tau0)
    }

    /// ω in sorted components at τ, and (j, sn r, cn r, dn r) of the reduction τ = 2Kj + r.
    #[inline]
    fn omega_sorted(&self, tau: f64) -> (Vec3, Reduced) {
        let (j, r) = self.jacobi.reduce(tau);
        let v = self.jacobi.eval_reduced(r);
        let flip = if j.rem_euclid(2.0) == 1.0 { -1.0 } else { 1.0 };
        let mut w = Vec3::zeros();
        w[self.other] = self.amp_cn * flip * v.cn;
        w[1] = self.amp_sn * flip * v.sn;
        w[self.pole] = self.amp_dn * v.dn;
        (
            w,
            Reduced {
                j,
                sn: v.sn,
                cn: v.cn,
                dn: v.dn,
            },
        )
    }

    /// Π(n; am τ | m) = 2jΠ(n) + Π(n; am r), the last in Carlson's form from sn r, cn r and
    /// dn r themselves (no amplitude angle, which near m = 1 sits within round-off of ±π/2,
    /// and no squares, which next to the separatrix underflow):
    /// `Π = s R_F(c², d², 1) + (n/3) s³ R_J(c², d², 1, 1 − n s²)` (DLMF 19.25.14); the
    /// closed form on the separatrix.
    #[inline]
    fn pi_of(&self, tau: f64, red: Reduced) -> f64 {
        if self.separatrix {
            // ∫₀^τ dτ / (1 − n tanh²τ) = [τ + √(−n) atan(√(−n) tanh τ)] / (1 − n).
            let r = (-self.n).sqrt();
            return (tau + r * (r * tau.tanh()).atan()) / (1.0 - self.n);
        }
        let (s, c, d) = (red.sn, red.cn.abs(), red.dn);
        let ns2 = self.n * s * s;
        let p = if ns2 < -CANCELLATION && self.positive_form() {
            // |n| s² > 1: the direct terms below would cancel (see `positive_form`).
            let kc = self.jacobi.complementary_modulus();
            let v = pi_reduced_split(self.n, s.abs(), c, d, self.jacobi.m(), kc * kc)
                .unwrap_or(f64::NAN);
            if s < 0.0 {
                -v
            } else {
                v
            }
        } else {
            s * rf_cd(c, d) + self.n / 3.0 * s * s * s * rj_cd(c, d, 1.0 - ns2)
        };
        2.0 * red.j * self.pi_complete + p
    }

    /// Whether Π may be summed in the form with positive terms only: n < −[`CANCELLATION`] (a
    /// body nearly symmetric about its pole, where `s R_F + (n/3) s³ R_J` cancels to
    /// ~1/√|n| of its terms and lost log₂|n| bits: 7e-9 in the attitude at
    /// I = (1, 2, 2 + 4e-14)), and m₁ = k'² a normal double (the form's R_J argument
    /// q ≥ m₁ s²/(1 − n) must not underflow).
    #[inline]
    fn positive_form(&self) -> bool {
        self.n < -CANCELLATION && self.jacobi.complementary_modulus() > 1e-140
    }

    /// L̂ in the working frame W (pole third) from ω in sorted components.
    #[inline]
    fn l_hat_w(&self, w: &Vec3) -> Vec3 {
        let l = Vec3::new(
            self.sorted[0] * w.x,
            self.sorted[1] * w.y,
            self.sorted[2] * w.z,
        );
        let lw = Vec3::new(l[self.w_axes[0]], l[self.w_axes[1]], l[self.w_axes[2]]);
        lw / lw.norm()
    }

    fn state(&self, t: f64) -> (Vec3, Quaternion) {
        let tau = self.tau(t);
        let (w, red) = self.omega_sorted(tau);
        let pi = self.pi_of(tau, red);
        let phi = self.rate_p.mul_add(t, self.kappa * (pi - self.pi0));
        let c = euler_tilt(&self.l_hat_w(&w));
        let q = hamilton(
            &hamilton(&self.q_pre, &coordinate_quaternion(2, phi)),
            &hamilton(&c, &self.q_post),
        );
        (w, normalized(&q))
    }
}
