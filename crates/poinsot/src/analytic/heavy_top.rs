//! The heavy symmetric top (the unit's "Motion of a Symmetrical Top", eqs. 2.98–2.121).
//!
//! A symmetric top (I₁ = I₂ about the pivot, I₃ about its axis) pivots at the origin; its centre
//! of mass lies at distance l along body axis 3; gravity is −g along the fixed Z axis. Its
//! orientation is given by the unit's z-x-z Euler angles: φ (precession, about Z), θ (nutation,
//! about the line of nodes), ψ (spin, about axis 3). The Lagrangian (2.102)
//!
//! `L = ½ I₁ (θ̇² + φ̇² sin²θ) + ½ I₃ (ψ̇ + φ̇ cos θ)² − m g l cos θ`
//!
//! has the constants of the motion p_ψ = I₃ω₃ (2.103), p_φ = I₁φ̇ sin²θ + p_ψ cos θ (2.104) and
//! E (2.105); the reduced energy E' = E − p_ψ²/(2I₃) = ½I₁θ̇² + V(θ) (2.109) with the effective
//! potential V(θ) (2.110). With u = cos θ, `u̇² = f(u)`, a cubic whose roots u₁ ≤ u₂ in [−1, 1]
//! are the turning points θ₂ ≥ θ₁ ([`super::heavy_top_cubic`]); θ(t) is a Jacobi elliptic
//! function and φ(t), ψ(t) elliptic integrals of the third kind (the unit calls this "very
//! difficult"; see [`HeavyTop::euler_angles`]).

use super::heavy_top_cubic::{
    theta_from_wv, turning_points_from_constants, turning_points_from_state, Local, Reduced,
    Turning,
};
use super::heavy_top_motion::Nutation;
use super::heavy_top_steady::{check_theta, check_top};
use crate::error::{check_finite, Error, Result};

/// A nutation θ₂ − θ₁ at or below this (rad) is reported as steady precession (it is below the
/// round-off of turning points computed from double-precision data near a double root). The
/// motion itself is still evaluated exactly with the computed turning points.
pub const STEADY_NUTATION_TOLERANCE: f64 = 1e-10;

/// φ̇ at a turning point is taken as zero (a cusp) when `|b − a cos θᵢ|` is at most this times
/// the size of its terms (the round-off of the momenta, with margin).
pub const CUSP_TOLERANCE: f64 = 1e-10;

/// Euler angles (the unit's z-x-z: φ about Z, θ about the line of nodes, ψ about axis 3) and
/// their rates at one instant (rad, rad/s).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EulerState {
    /// Precession angle φ (rad).
    pub phi: f64,
    /// Nutation angle θ (rad), in [0, π].
    pub theta: f64,
    /// Spin angle ψ (rad).
    pub psi: f64,
    /// φ̇ (rad/s).
    pub phi_dot: f64,
    /// θ̇ (rad/s).
    pub theta_dot: f64,
    /// ψ̇ (rad/s).
    pub psi_dot: f64,
}

/// The shape of the path of the symmetry axis on the unit sphere (Goldstein §5.7, Fig. 5.9).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MotionClass {
    /// θ₁ < θ₂ and φ̇ keeps one sign: the axis traces waves between the two circles.
    Waves,
    /// φ̇ changes sign between θ₁ and θ₂: the axis traces loops.
    Loops,
    /// φ̇ = 0 at a turning point (the top released at rest in φ): the path has cusps there.
    Cusps,
    /// θ₁ = θ₂ (within [`STEADY_NUTATION_TOLERANCE`]) with 0 < θ < π: uniform precession.
    SteadyPrecession,
    /// θ stays 0: the top spins upright ("sleeping"); stable iff ω₃² > 4 m g l I₁ / I₃².
    Sleeping,
    /// θ stays π: the top hangs straight down from the pivot.
    Hanging,
    /// The axis passes through a vertical (θ₁ = 0 or θ₂ = π, e.g. a pendulum swinging through
    /// the bottom): φ and ψ jump by ±π there (the Euler angles are singular at the poles).
    ThroughVertical,
}

impl MotionClass {
    /// A short name: "waves", "loops", "cusps", "steady precession", "sleeping", "hanging",
    /// "through vertical".
    pub fn name(self) -> &'static str {
        match self {
            MotionClass::Waves => "waves",
            MotionClass::Loops => "loops",
            MotionClass::Cusps => "cusps",
            MotionClass::SteadyPrecession => "steady precession",
            MotionClass::Sleeping => "sleeping",
            MotionClass::Hanging => "hanging",
            MotionClass::ThroughVertical => "through vertical",
        }
    }
}

/// How the angles evolve in time.
#[derive(Debug, Clone)]
pub(crate) enum Motion {
    /// θ constant (steady precession, sleeping, hanging): φ and ψ grow linearly.
    Uniform {
        theta: f64,
        phi_rate: f64,
        psi_rate: f64,
    },
    /// θ oscillates between θ₁ and θ₂.
    Nutating(Box<Nutation>),
}

/// A heavy symmetric top with its constants of motion, turning points and exact motion.
///
/// ```
/// use poinsot::analytic::{EulerState, HeavyTop, MotionClass};
/// // Released at θ = 0.6 with spin 40 rad/s and no precession: cusps.
/// let state = EulerState { theta: 0.6, psi_dot: 40.0, ..Default::default() };
/// let top = HeavyTop::new(1.0, 0.5, 0.3, state).unwrap();
/// assert_eq!(top.motion_class(), MotionClass::Cusps);
/// let (theta1, theta2) = top.turning_points();
/// assert_eq!(theta1, 0.6); // released at the upper turning point
/// assert!(theta2 > theta1);
/// ```
#[derive(Debug, Clone)]
pub struct HeavyTop {
    i1: f64,
    i3: f64,
    mgl: f64,
    p_phi: f64,
    p_psi: f64,
    energy: f64,
    reduced_energy: f64,
    r: Reduced,
    start: EulerState,
    turning: Turning,
    class: MotionClass,
    motion: Motion,
}

impl HeavyTop {
    /// The top with moments I₁ (about a transverse axis through the pivot, kg·m²), I₃ (about the
    /// symmetry axis), `mgl` = m g l (N·m: weight times pivot-to-centre-of-mass distance), started
    /// at time 0 from the Euler angles and rates of `state`.
    ///
    /// Errors name the argument: `I1`, `I3` (> 0, finite; I₃ ≤ 2I₁), `mgl` (≥ 0, finite), `theta`
    /// (finite, in [0, π]), `phi`, `psi`, `phi_dot`, `theta_dot`, `psi_dot` (finite).
    pub fn new(i1: f64, i3: f64, mgl: f64, state: EulerState) -> Result<Self> {
        check_top(i1, i3, mgl)?;
        check_theta("theta", state.theta)?;
        check_finite("phi", &[state.phi])?;
        check_finite("psi", &[state.psi])?;
        check_finite("phi_dot", &[state.phi_dot])?;
        check_finite("theta_dot", &[state.theta_dot])?;
        check_finite("psi_dot", &[state.psi_dot])?;
        let mut st = state;
        // At a pole θ̇ must point into [0, π]: θ = 0 with θ̇ < 0 is θ = 0 with θ̇ > 0 and the line of
        // nodes reversed (φ + π, ψ − π: the same rotation and angular velocity); likewise at π.
        let pi = std::f64::consts::PI;
        if st.theta == 0.0 && st.theta_dot < 0.0 {
            st = EulerState {
                phi: st.phi + pi,
                psi: st.psi - pi,
                theta_dot: -st.theta_dot,
                ..st
            };
        } else if st.theta == pi && st.theta_dot > 0.0 {
            st = EulerState {
                phi: st.phi + pi,
                psi: st.psi + pi,
                theta_dot: -st.theta_dot,
                ..st
            };
        }
        let half = 0.5 * st.theta;
        // w = 1 − cos θ and v = 1 + cos θ without cancellation.
        let w0 = 2.0 * half.sin().powi(2);
        let v0 = 2.0 * half.cos().powi(2);
        let (s, c) = st.theta.sin_cos();
        let s2 = s * s;
        let omega3 = st.psi_dot + st.phi_dot * c; // 2.99
        let p_psi = i3 * omega3; // 2.103
        let beta = 2.0 * mgl / i1;
        let a = p_psi / i1;
        // I₁φ̇ sin²θ: the transverse part of p_φ (2.104).
        let ps = st.phi_dot * s2;
        // θ̇² + φ̇² sin²θ = 2 T_⊥ / I₁.
        let tperp = st.theta_dot * st.theta_dot + st.phi_dot * ps;
        let r = Reduced {
            a,
            b: ps + a * c,
            d: ps - a * w0,
            e: ps + a * v0,
            beta,
            gamma: tperp - beta * w0,
            delta: tperp + beta * v0,
        };
        let p_phi = i1 * r.b;
        let reduced_energy = 0.5 * i1 * tperp + mgl * c; // 2.109
        let energy = reduced_energy + 0.5 * i3 * omega3 * omega3; // 2.105
        let local = Local {
            w0,
            v0,
            f0: s2 * st.theta_dot * st.theta_dot,
            f1: 2.0 * c * tperp + beta * s2 - 2.0 * a * ps,
            f2: 2.0 * beta * c - a * a - tperp,
        };
        let turning = turning_points_from_state(&r, &local);
        Self::assemble(
            i1,
            i3,
            mgl,
            p_phi,
            p_psi,
            energy,
            reduced_energy,
            r,
            st,
            turning,
            true,
        )
    }

    /// The top started at time 0 from the angles φ, θ, ψ (rad), the rates φ̇, θ̇ (rad/s) and the
    /// spin ω₃ (rad/s) instead of ψ̇: the state of [`HeavyTop::new`] with ψ̇ = ω₃ − φ̇ cos θ (2.99),
    /// so that p_ψ = I₃ω₃ (2.103) whatever φ̇. Errors as [`HeavyTop::new`], `omega3` (finite).
    #[allow(clippy::too_many_arguments)]
    pub fn with_spin(
        i1: f64,
        i3: f64,
        mgl: f64,
        phi: f64,
        theta: f64,
        psi: f64,
        phi_dot: f64,
        theta_dot: f64,
        omega3: f64,
    ) -> Result<Self> {
        check_theta("theta", theta)?;
        check_finite("phi_dot", &[phi_dot])?;
        check_finite("omega3", &[omega3])?;
        let state = EulerState {
            phi,
            theta,
            psi,
            phi_dot,
            theta_dot,
            psi_dot: omega3 - phi_dot * theta.cos(), // 2.99
        };
        Self::new(i1, i3, mgl, state)
    }

    /// The top given by its constants of motion instead of an initial state: p_φ and p_ψ
    /// (kg·m²/s, 2.103–2.104) and the total energy E (J, 2.105). Time 0 is then a moment when
    /// the axis is at its upper turning point θ₁, with φ = ψ = 0 there.
    ///
    /// Errors name `I1`, `I3`, `mgl`, `p_phi`, `p_psi`, `energy` (finite), and `energy` when
    /// E' = E − p_ψ²/(2I₃) lies below the minimum of the effective potential V(θ) (no motion).
    pub fn from_constants(
        i1: f64,
        i3: f64,
        mgl: f64,
        p_phi: f64,
        p_psi: f64,
        energy: f64,
    ) -> Result<Self> {
        check_top(i1, i3, mgl)?;
        check_finite("p_phi", &[p_phi])?;
        check_finite("p_psi", &[p_psi])?;
        check_finite("energy", &[energy])?;
        let reduced_energy = energy - p_psi * p_psi / (2.0 * i3);
        let r = Reduced {
            a: p_psi / i1,
            b: p_phi / i1,
            d: (p_phi - p_psi) / i1,
            e: (p_phi + p_psi) / i1,
            beta: 2.0 * mgl / i1,
            gamma: 2.0 * (reduced_energy - mgl) / i1,
            delta: 2.0 * (reduced_energy + mgl) / i1,
        };
        let turning = turning_points_from_constants(&r).ok_or_else(|| {
            Error::invalid(
                "energy",
                format!(
                    "E' = E - p_psi^2/(2 I3) = {reduced_energy} lies below the minimum of the effective \
                     potential V(theta) (2.110) for p_phi = {p_phi}, p_psi = {p_psi}: no motion has these constants"
                ),
            )
        })?;
        let (theta1, _) = turning.thetas();
        let start = EulerState {
            theta: theta1,
            ..Default::default()
        };
        Self::assemble(
            i1,
            i3,
            mgl,
            p_phi,
            p_psi,
            energy,
            reduced_energy,
            r,
            start,
            turning,
            false,
        )
    }

    #[allow(clippy::too_many_arguments)]
    fn assemble(
        i1: f64,
        i3: f64,
        mgl: f64,
        p_phi: f64,
        p_psi: f64,
        energy: f64,
        reduced_energy: f64,
        r: Reduced,
        start: EulerState,
        turning: Turning,
        from_state: bool,
    ) -> Result<Self> {
        let class = classify(&r, &turning);
        let motion = if turning.w_lo == turning.w_hi {
            let theta = theta_from_wv(turning.w_lo, turning.v_lo);
            let (phi_rate, psi_rate) = uniform_rates(i1, i3, &r, &turning, &start, from_state);
            Motion::Uniform {
                theta,
                phi_rate,
                psi_rate,
            }
        } else {
            Motion::Nutating(Box::new(Nutation::new(
                i1, i3, &r, &turning, &start, from_state,
            )?))
        };
        Ok(Self {
            i1,
            i3,
            mgl,
            p_phi,
            p_psi,
            energy,
            reduced_energy,
            r,
            start,
            turning,
            class,
            motion,
        })
    }

    /// I₁ (kg·m²), the moment about a transverse axis through the pivot.
    pub fn i1(&self) -> f64 {
        self.i1
    }
    /// I₃ (kg·m²), the moment about the symmetry axis.
    pub fn i3(&self) -> f64 {
        self.i3
    }
    /// m g l (N·m).
    pub fn mgl(&self) -> f64 {
        self.mgl
    }
    /// p_φ = I₁ φ̇ sin²θ + p_ψ cos θ (kg·m²/s), the conserved vertical angular momentum L_Z (2.104).
    pub fn p_phi(&self) -> f64 {
        self.p_phi
    }
    /// p_ψ = I₃ ω₃ (kg·m²/s), the conserved angular momentum about the symmetry axis (2.103).
    pub fn p_psi(&self) -> f64 {
        self.p_psi
    }
    /// ω₃ = ψ̇ + φ̇ cos θ = p_ψ / I₃ (rad/s), the constant spin (2.99, 2.103).
    pub fn omega3(&self) -> f64 {
        self.p_psi / self.i3
    }
    /// The total energy E = T + V (J, 2.105).
    pub fn energy(&self) -> f64 {
        self.energy
    }
    /// The reduced energy E' = E − p_ψ²/(2I₃) = ½ I₁ θ̇² + V(θ) (J, 2.109).
    pub fn reduced_energy(&self) -> f64 {
        self.reduced_energy
    }
    /// The state at time 0 (as given to [`HeavyTop::new`], with θ̇ turned into [0, π] at a pole;
    /// for [`HeavyTop::from_constants`], the upper turning point with φ = ψ = 0 and rates 0).
    pub fn initial_state(&self) -> EulerState {
        self.start
    }
    /// The turning points (θ₁, θ₂), θ₁ ≤ θ₂ (rad): the roots of the cubic f(cos θ) in [0, π]
    /// (where E' = V(θ), 2.109–2.110), computed without cancellation at the poles.
    pub fn turning_points(&self) -> (f64, f64) {
        self.turning.thetas()
    }
    /// The cosines of the turning points (u₂ = cos θ₁, u₁ = cos θ₂), and the third root u₃ ≥ 1 of
    /// the cubic (infinite for m g l = 0).
    pub fn cubic_roots(&self) -> (f64, f64, f64) {
        let u2 = 1.0 - self.turning.w_lo;
        let u1 = self.turning.v_lo - 1.0;
        let u1 = if u1 > 0.0 {
            1.0 - self.turning.w_hi
        } else {
            u1
        };
        let u2 = if u2 < 0.0 {
            self.turning.v_hi - 1.0
        } else {
            u2
        };
        let (p, _) = self.r.p_and_complement(&self.turning);
        let u3 = if self.r.beta > 0.0 {
            u1 + p / self.r.beta
        } else {
            f64::INFINITY
        };
        (u1, u2, u3)
    }
    /// The shape of the axis' path.
    pub fn motion_class(&self) -> MotionClass {
        self.class
    }
    /// Whether an upright top with this spin would sleep stably: ω₃² > 4 m g l I₁ / I₃².
    pub fn is_sleeping_stable(&self) -> bool {
        let w3 = self.omega3();
        w3 * w3 * self.i3 * self.i3 > 4.0 * self.mgl * self.i1
    }
    /// The period of θ(t) (s): `2K(m)/κ` with κ = ½√(β(u₃ − u₁)) (β = 2mgl/I₁) and
    /// m = (u₂ − u₁)/(u₃ − u₁); for steady motion (θ₁ = θ₂), the period of small nutations about
    /// it, `2π/√P` with P = β(u₃ − u₁). `None` where θ never returns: an unstable sleeping top.
    pub fn nutation_period(&self) -> Option<f64> {
        match &self.motion {
            Motion::Nutating(n) => n.period(),
            Motion::Uniform { .. } => {
                let (p, _) = self.r.p_and_complement(&self.turning);
                (p > 0.0).then(|| 2.0 * std::f64::consts::PI / p.sqrt())
            }
        }
    }
    /// The mean precession rate ⟨φ̇⟩ over a nutation period (rad/s): φ advances by
    /// `⟨φ̇⟩ · period` per period (including the jumps of ±π where the axis crosses a vertical).
    pub fn mean_precession_rate(&self) -> f64 {
        match &self.motion {
            Motion::Uniform { phi_rate, .. } => *phi_rate,
            Motion::Nutating(n) => n.mean_rates().0,
        }
    }
    /// The mean spin rate ⟨ψ̇⟩ over a nutation period (rad/s).
    pub fn mean_spin_rate(&self) -> f64 {
        match &self.motion {
            Motion::Uniform { psi_rate, .. } => *psi_rate,
            Motion::Nutating(n) => n.mean_rates().1,
        }
    }

    /// The effective potential V(θ) = (p_φ − p_ψ cos θ)²/(2 I₁ sin²θ) + m g l cos θ (J, 2.110);
    /// +∞ at θ = 0 (unless p_φ = p_ψ) and at θ = π (unless p_φ = −p_ψ). Errors name `theta`
    /// (finite, in [0, π]).
    pub fn effective_potential(&self, theta: f64) -> Result<f64> {
        check_theta("theta", theta)?;
        Ok(effective_potential_reduced(
            self.i1, self.mgl, &self.r, theta,
        ))
    }

    /// dV/dθ = (p_φ − p_ψ cos θ)(p_ψ − p_φ cos θ)/(I₁ sin³θ) − m g l sin θ (N·m, 2.113); the
    /// generalized force −dV/dθ drives θ̈ (I₁θ̈ = −dV/dθ). Errors name `theta` (in (0, π) where
    /// V is finite; at a pole where V is finite the limit is returned).
    pub fn effective_potential_derivative(&self, theta: f64) -> Result<f64> {
        check_theta("theta", theta)?;
        Ok(effective_potential_derivative_reduced(
            self.i1, self.mgl, &self.r, theta,
        ))
    }

    /// The Euler angles (φ, θ, ψ) at time `t` (s; the initial state is at t = 0), exact: θ from
    /// the Jacobi elliptic solution of the cubic, φ and ψ from complete and incomplete elliptic
    /// integrals of the third kind (Carlson's R_J). φ and ψ are continuous (not reduced modulo
    /// 2π) except for jumps of ±π where the axis passes exactly through a vertical.
    pub fn euler_angles(&self, t: f64) -> [f64; 3] {
        match &self.motion {
            Motion::Uniform {
                theta,
                phi_rate,
                psi_rate,
            } => [
                self.start.phi + phi_rate * t,
                *theta,
                self.start.psi + psi_rate * t,
            ],
            Motion::Nutating(n) => n.angles(t),
        }
    }

    /// [`HeavyTop::euler_angles`] evaluated through the incomplete elliptic integrals (Jacobi's
    /// sn, cn, dn and Carlson's R_J at every t) rather than through their Fourier series: slower,
    /// the same numbers to round-off; kept as the cross-check of the fast path.
    pub fn euler_angles_carlson(&self, t: f64) -> [f64; 3] {
        match &self.motion {
            Motion::Nutating(n) => n.angles_carlson(t),
            Motion::Uniform { .. } => self.euler_angles(t),
        }
    }

    /// The number of Fourier terms [`HeavyTop::euler_angles`] sums per time (see
    /// `heavy_top_fourier`); 0 when the motion is uniform or evaluated by R_J (axis passing through or
    /// very near a pole, or m near 1, where the series would converge slowly).
    pub fn fourier_terms(&self) -> usize {
        match &self.motion {
            Motion::Nutating(n) => n.fourier_terms(),
            Motion::Uniform { .. } => 0,
        }
    }

    /// The Euler-angle rates (φ̇, θ̇, ψ̇) at time `t` (rad/s), from 2.106 (φ̇), ψ̇ = ω₃ − φ̇ cos θ
    /// (2.99) and θ̇ from the elliptic solution (its sign is that of the motion).
    pub fn euler_rates(&self, t: f64) -> [f64; 3] {
        match &self.motion {
            Motion::Uniform {
                phi_rate, psi_rate, ..
            } => [*phi_rate, 0.0, *psi_rate],
            Motion::Nutating(n) => n.rates(t),
        }
    }

    /// [`HeavyTop::euler_angles`] at many times, in parallel: `out[3i..3i + 3] = [φ, θ, ψ](times[i])`
    /// (`out` flat, row-major (N, 3)). Errors name `times` (finite) or `out` (length 3N).
    pub fn euler_angles_into(&self, times: &[f64], out: &mut [f64]) -> Result<()> {
        match &self.motion {
            Motion::Nutating(n) => self.batch_chunks(times, out, |ts, o| n.angles_into(ts, o)),
            Motion::Uniform { .. } => self.batch(times, out, |t| self.euler_angles(t)),
        }
    }

    /// [`HeavyTop::euler_rates`] at many times, in parallel (`out` flat (N, 3): φ̇, θ̇, ψ̇).
    /// Errors name `times` or `out`.
    pub fn euler_rates_into(&self, times: &[f64], out: &mut [f64]) -> Result<()> {
        self.batch(times, out, |t| self.euler_rates(t))
    }

    fn batch(
        &self,
        times: &[f64],
        out: &mut [f64],
        f: impl Fn(f64) -> [f64; 3] + Sync,
    ) -> Result<()> {
        self.batch_chunks(times, out, |ts, o| {
            for (oi, &t) in o.chunks_exact_mut(3).zip(ts) {
                oi.copy_from_slice(&f(t));
            }
        })
    }

    /// Checks `times` and `out`, then runs `f` on chunks of both in parallel.
    fn batch_chunks(
        &self,
        times: &[f64],
        out: &mut [f64],
        f: impl Fn(&[f64], &mut [f64]) + Sync,
    ) -> Result<()> {
        use rayon::prelude::*;
        check_finite("times", times)?;
        if out.len() != 3 * times.len() {
            return Err(Error::invalid(
                "out",
                format!(
                    "must have 3 x {} = {} values, got {}",
                    times.len(),
                    3 * times.len(),
                    out.len()
                ),
            ));
        }
        const CHUNK: usize = 8192;
        out.par_chunks_mut(3 * CHUNK)
            .zip(times.par_chunks(CHUNK))
            .for_each(|(o, ts)| f(ts, o));
        Ok(())
    }
}

/// The Lagrangian of the heavy symmetric top (J, 2.102):
/// `L = ½ I₁ (θ̇² + φ̇² sin²θ) + ½ I₃ (ψ̇ + φ̇ cos θ)² − m g l cos θ`.
/// Errors name `I1`, `I3`, `mgl`, `theta` and the rates.
pub fn lagrangian(i1: f64, i3: f64, mgl: f64, state: &EulerState) -> Result<f64> {
    check_top(i1, i3, mgl)?;
    check_theta("theta", state.theta)?;
    check_finite("phi_dot", &[state.phi_dot])?;
    check_finite("theta_dot", &[state.theta_dot])?;
    check_finite("psi_dot", &[state.psi_dot])?;
    let (s, c) = state.theta.sin_cos();
    let w3 = state.psi_dot + state.phi_dot * c;
    Ok(
        0.5 * i1 * (state.theta_dot.powi(2) + (state.phi_dot * s).powi(2)) + 0.5 * i3 * w3 * w3
            - mgl * c,
    )
}

/// The constants of the motion evaluated at one state: p_φ, p_ψ and E (see
/// [`constants_of_state`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StateConstants {
    /// p_φ = I₁ φ̇ sin²θ + p_ψ cos θ (kg·m²/s, 2.104): the vertical angular momentum L_Z.
    pub p_phi: f64,
    /// p_ψ = I₃ (ψ̇ + φ̇ cos θ) = I₃ ω₃ (kg·m²/s, 2.99, 2.103).
    pub p_psi: f64,
    /// E = ½ I₁ (θ̇² + φ̇² sin²θ) + ½ I₃ ω₃² + m g l cos θ (J, 2.105).
    pub energy: f64,
}

/// p_φ, p_ψ and E (2.103–2.105) of the heavy symmetric top at one state (angles in rad, rates in
/// rad/s; φ and ψ do not enter). Along an exact motion they equal [`HeavyTop::p_phi`],
/// [`HeavyTop::p_psi`] and [`HeavyTop::energy`] to round-off: evaluated at the state of
/// [`HeavyTop::euler_angles`] and [`HeavyTop::euler_rates`] at time t, their difference from the
/// constants is the drift of the solution. Uses the same arithmetic as [`HeavyTop::new`], so at
/// the initial state they are bit-identical. Errors name `I1`, `I3`, `mgl`, `theta` (in [0, π])
/// and the rates `phi_dot`, `theta_dot`, `psi_dot` (finite).
pub fn constants_of_state(
    i1: f64,
    i3: f64,
    mgl: f64,
    state: &EulerState,
) -> Result<StateConstants> {
    check_top(i1, i3, mgl)?;
    check_theta("theta", state.theta)?;
    check_finite("phi_dot", &[state.phi_dot])?;
    check_finite("theta_dot", &[state.theta_dot])?;
    check_finite("psi_dot", &[state.psi_dot])?;
    let (s, c) = state.theta.sin_cos();
    let omega3 = state.psi_dot + state.phi_dot * c; // 2.99
    let p_psi = i3 * omega3; // 2.103
    let a = p_psi / i1;
    let ps = state.phi_dot * (s * s);
    let tperp = state.theta_dot * state.theta_dot + state.phi_dot * ps;
    Ok(StateConstants {
        p_phi: i1 * (ps + a * c), // 2.104
        p_psi,
        energy: (0.5 * i1 * tperp + mgl * c) + 0.5 * i3 * omega3 * omega3, // 2.105
    })
}

/// w = 1 − cos θ and v = 1 + cos θ without cancellation.
fn w_v(theta: f64) -> (f64, f64) {
    let (sh, ch) = (0.5 * theta).sin_cos();
    (2.0 * sh * sh, 2.0 * ch * ch)
}

/// V(θ) from the reduced constants: p_φ − p_ψ cos θ = I₁(d + a w) = I₁(e − a v), sin²θ = w v.
fn effective_potential_reduced(i1: f64, mgl: f64, r: &Reduced, theta: f64) -> f64 {
    let (w, v) = w_v(theta);
    let c = theta.cos();
    let num = if w <= 1.0 {
        r.d + r.a * w
    } else {
        r.e - r.a * v
    };
    let wv = w * v;
    if wv == 0.0 {
        // At a pole: num → the pole's combination (d or e); V is finite only when it vanishes,
        // and then the kinetic term vanishes too (∝ w or v).
        let k = if w == 0.0 { r.d } else { r.e };
        return if k == 0.0 { mgl * c } else { f64::INFINITY };
    }
    0.5 * i1 * num * num / wv + mgl * c
}

/// dV/dθ (2.113) from the reduced constants: p_ψ − p_φ cos θ = I₁(b w − d) = I₁(e − b v).
fn effective_potential_derivative_reduced(i1: f64, mgl: f64, r: &Reduced, theta: f64) -> f64 {
    let (w, v) = w_v(theta);
    let s = theta.sin();
    let (n1, n2) = if w <= 1.0 {
        (r.d + r.a * w, r.b * w - r.d)
    } else {
        (r.e - r.a * v, r.e - r.b * v)
    };
    if s == 0.0 {
        let k = if w == 0.0 { r.d } else { r.e };
        if k != 0.0 {
            // −∞ at θ = 0 (V → +∞ as θ → 0⁺), +∞ at θ = π.
            return if w == 0.0 {
                f64::NEG_INFINITY
            } else {
                f64::INFINITY
            };
        }
        // n1 n2 / sin³θ → a b w²/(θ³)… → 0 linearly: the limit is 0 at the pole.
        return 0.0;
    }
    i1 * n1 * n2 / (s * s * s) - mgl * s
}

/// The class of the motion from the turning points and the sign of φ̇ there.
fn classify(r: &Reduced, t: &Turning) -> MotionClass {
    let (theta1, theta2) = t.thetas();
    if t.w_lo == t.w_hi || theta2 - theta1 <= STEADY_NUTATION_TOLERANCE {
        return if theta2 <= STEADY_NUTATION_TOLERANCE {
            MotionClass::Sleeping
        } else if std::f64::consts::PI - theta1 <= STEADY_NUTATION_TOLERANCE {
            MotionClass::Hanging
        } else {
            MotionClass::SteadyPrecession
        };
    }
    if t.w_lo == 0.0 || t.v_lo == 0.0 {
        return MotionClass::ThroughVertical;
    }
    // φ̇ ∝ b − a cos θ: at θ₁ it is d + a w_lo, at θ₂ it is e − a v_lo (2.106).
    let r1 = r.d + r.a * t.w_lo;
    let r2 = r.e - r.a * t.v_lo;
    let cusp1 = r1.abs() <= CUSP_TOLERANCE * (r.d.abs() + (r.a * t.w_lo).abs());
    let cusp2 = r2.abs() <= CUSP_TOLERANCE * (r.e.abs() + (r.a * t.v_lo).abs());
    if cusp1 || cusp2 {
        MotionClass::Cusps
    } else if r1 * r2 < 0.0 {
        MotionClass::Loops
    } else {
        MotionClass::Waves
    }
}

/// φ̇ and ψ̇ of a motion with θ constant. At a pole only φ̇ + ψ̇ (resp. φ̇ − ψ̇) is defined: the
/// given split is kept (from constants: all of it in ψ̇).
fn uniform_rates(
    i1: f64,
    i3: f64,
    r: &Reduced,
    t: &Turning,
    start: &EulerState,
    from_state: bool,
) -> (f64, f64) {
    let omega3 = r.a * i1 / i3;
    let (w, v) = (t.w_lo, t.v_lo);
    if w == 0.0 || v == 0.0 {
        return if from_state {
            (start.phi_dot, start.psi_dot)
        } else {
            (0.0, omega3)
        };
    }
    // φ̇ = (b − a u)/(1 − u²) (2.106/2.115), written about the nearer pole; ψ̇ = ω₃ − φ̇ cos θ.
    let phi_rate = if w <= 1.0 {
        (r.d + r.a * w) / (w * v)
    } else {
        (r.e - r.a * v) / (w * v)
    };
    let c = if w <= 1.0 { 1.0 - w } else { v - 1.0 };
    (phi_rate, omega3 - phi_rate * c)
}
