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
//! are the turning points θ₂ ≥ θ₁ ([`cubic`]); θ(t) is a Jacobi elliptic function and φ(t),
//! ψ(t) elliptic integrals of the third kind (the unit calls this "very difficult"; see
//! [`HeavyTop::euler_angles`]).
//!
//! The parts, each depending only on those before it: `cubic` (the cubic and its turning
//! points), `state` ([`EulerState`], the solution's limits, the time unit), `validate` (every
//! check of input and output), `fourier` (the motion as Fourier series), `motion` (the exact
//! nutating motion), `steady` (steady precession, 2.114–2.121); this module assembles them into
//! [`HeavyTop`].

mod cubic;
pub(super) mod fourier;
mod motion;
mod pivot;
mod state;
mod steady;
mod validate;

use crate::error::{Error, Result};
use cubic::{
    theta_from_wv, turning_points_from_constants, turning_points_from_state, w_v, Local, Reduced,
    Turning,
};
use motion::Nutation;
pub use pivot::{heavy_top_parameters, PIVOT_SYMMETRY_RTOL};
use state::TimeScale;
pub use state::{
    EulerState, CUSP_TOLERANCE, MAX_PHASE, MIN_POLE_DISTANCE, STEADY_NUTATION_TOLERANCE,
};
pub use steady::{min_spin, sleeping_threshold, steady_precession, SteadyPrecession};
use validate::{
    check_constants, check_representable, finite_at_t, finite_at_theta, largest_rate,
    resolve_pole_passage,
};
pub use validate::{check_theta, check_top};
// Also for the sweeps (`crate::sweep`): they check every point's start before any work.
pub(crate) use validate::{check_spin, check_state};

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

/// The pole a top of [`MotionClass::ThroughVertical`] passes through
/// ([`HeavyTop::vertical_pass`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum VerticalPass {
    /// θ₁ = 0: the axis swings through the upright position.
    Upright,
    /// θ₂ = π: the axis swings through the straight-down position (a pendulum through its
    /// lowest point).
    StraightDown,
    /// θ₁ = 0 and θ₂ = π: the axis goes over both poles (a pendulum swung round).
    Both,
}

impl VerticalPass {
    /// "upright", "straight down" or "both".
    pub fn name(self) -> &'static str {
        match self {
            VerticalPass::Upright => "upright",
            VerticalPass::StraightDown => "straight down",
            VerticalPass::Both => "both",
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
    /// The constants, the time unit, the start and the turning points (what the constructors
    /// computed).
    a: Assembly,
    class: MotionClass,
    motion: Motion,
    /// The largest |t| (s) evaluated: [`MAX_PHASE`] over the fastest rate (∞ if none).
    max_time: f64,
}

/// What the constructors of [`HeavyTop`] compute before the motion is classified and solved
/// ([`HeavyTop::assemble`]); the top keeps it.
#[derive(Debug, Clone)]
struct Assembly {
    i1: f64,
    i3: f64,
    mgl: f64,
    p_phi: f64,
    p_psi: f64,
    energy: f64,
    reduced_energy: f64,
    /// The reduced constants in the time unit 1/σ of `ts`.
    r: Reduced,
    ts: TimeScale,
    /// The state at time 0.
    start: EulerState,
    turning: Turning,
    /// Started from a state ([`HeavyTop::new`]) rather than given by its constants
    /// ([`HeavyTop::from_constants`]).
    from_state: bool,
}

/// The state of a top started with the spin ω₃ (rad/s) instead of ψ̇: ψ̇ = ω₃ − φ̇ cos θ (2.99),
/// so that p_ψ = I₃ω₃ (2.103) whatever φ̇; `omega3` checked finite ([`check_spin`]). Used by
/// [`HeavyTop::with_spin`] and the sweeps.
pub(crate) fn spin_state(
    phi: f64,
    theta: f64,
    psi: f64,
    phi_dot: f64,
    theta_dot: f64,
    omega3: f64,
) -> Result<EulerState> {
    check_spin(theta, phi_dot, omega3)?;
    Ok(EulerState {
        phi,
        theta,
        psi,
        phi_dot,
        theta_dot,
        psi_dot: omega3 - phi_dot * theta.cos(), // 2.99
    })
}

impl HeavyTop {
    /// The top with moments I₁ (about a transverse axis through the pivot, kg·m²), I₃ (about the
    /// symmetry axis), `mgl` = m g l (N·m: weight times pivot-to-centre-of-mass distance), started
    /// at time 0 from the Euler angles and rates of `state`.
    ///
    /// Errors name the argument: `I1`, `I3` (> 0, finite; I₃ ≤ 2I₁), `mgl` (≥ 0, finite), `theta`
    /// (finite, in [0, π]), `phi`, `psi`, `phi_dot`, `theta_dot`, `psi_dot` (finite).
    pub fn new(i1: f64, i3: f64, mgl: f64, state: EulerState) -> Result<Self> {
        check_state(i1, i3, mgl, &state, true)?;
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
        let (w0, v0) = w_v(st.theta);
        let (s, c) = cubic::sin_cos(st.theta);
        let s2 = s * s;
        // The rates in the top's own time unit 1/σ (σ = 2ᵏ ≈ its fastest rate, see
        // `TimeScale`): exact, and the squares and products below then neither overflow nor
        // underflow however fast or slow the top is.
        let ts = TimeScale::of(&[
            st.theta_dot,
            st.phi_dot,
            st.psi_dot,
            (2.0 * mgl).sqrt() / i1.sqrt(),
        ]);
        let (theta_dot, phi_dot, psi_dot) = (
            ts.in_unit(st.theta_dot),
            ts.in_unit(st.phi_dot),
            ts.in_unit(st.psi_dot),
        );
        let omega3 = psi_dot + phi_dot * c; // 2.99
        let beta = ts.beta(mgl, i1);
        let a = (i3 / i1) * omega3; // p_ψ / I₁ (2.103)
                                    // I₁φ̇ sin²θ: the transverse part of p_φ (2.104).
        let ps = phi_dot * s2;
        // θ̇² + φ̇² sin²θ = 2 T_⊥ / I₁.
        let tperp = theta_dot * theta_dot + phi_dot * ps;
        let r = Reduced {
            a,
            b: ps + a * c,
            d: ps - a * w0,
            e: ps + a * v0,
            beta,
            gamma: tperp - beta * w0,
            delta: tperp + beta * v0,
        };
        // The constants of the motion in SI (2.103–2.105), each representable or refused.
        let largest = largest_rate(&st);
        let p_psi = ts.moment_to_si(i3, omega3, 1);
        let p_phi = ts.moment_to_si(i1, r.b, 1);
        let reduced_energy = ts.moment_to_si(0.5 * i1, tperp, 2) + mgl * c; // 2.109
        let energy = reduced_energy + ts.moment_to_si(0.5 * i3, omega3 * omega3, 2); // 2.105
        check_representable(&[
            ("p_psi", p_psi, largest),
            ("spin omega3 = p_psi/I3", p_psi / i3, largest),
            ("p_phi", p_phi, largest),
            ("E", energy, largest),
            ("E'", reduced_energy, largest),
        ])?;
        let local = Local {
            w0,
            v0,
            f0: s2 * theta_dot * theta_dot,
            f1: 2.0 * c * tperp + beta * s2 - 2.0 * a * ps,
            f2: 2.0 * beta * c - a * a - tperp,
        };
        let turning = turning_points_from_state(&r, &local);
        let turning = resolve_pole_passage("theta", turning, Some((w0, v0)))?;
        Self::assemble(Assembly {
            i1,
            i3,
            mgl,
            p_phi,
            p_psi,
            energy,
            reduced_energy,
            r,
            ts,
            start: st,
            turning,
            from_state: true,
        })
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
        let state = spin_state(phi, theta, psi, phi_dot, theta_dot, omega3)?;
        Self::new(i1, i3, mgl, state).map_err(|e| e.renamed("psi_dot", "omega3"))
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
        check_constants(i1, i3, mgl, p_phi, p_psi, energy)?;
        let reduced_energy = energy - p_psi * p_psi / (2.0 * i3);
        let si = Reduced {
            a: p_psi / i1,
            b: p_phi / i1,
            d: (p_phi - p_psi) / i1,
            e: (p_phi + p_psi) / i1,
            beta: 2.0 * mgl / i1,
            gamma: 2.0 * (reduced_energy - mgl) / i1,
            delta: 2.0 * (reduced_energy + mgl) / i1,
        };
        let culprit = if p_phi.abs() > p_psi.abs() {
            "p_phi"
        } else {
            "p_psi"
        };
        check_representable(&[
            ("E' = E - p_psi^2/(2 I3)", reduced_energy, "energy"),
            ("p_psi/I1", si.a, "p_psi"),
            ("spin omega3 = p_psi/I3", p_psi / i3, "p_psi"),
            ("p_phi/I1", si.b, "p_phi"),
            ("(p_phi - p_psi)/I1", si.d, culprit),
            ("(p_phi + p_psi)/I1", si.e, culprit),
            ("2 mgl/I1", si.beta, "mgl"),
            ("2 (E' - mgl)/I1", si.gamma, "energy"),
            ("2 (E' + mgl)/I1", si.delta, "energy"),
        ])?;
        // In the top's own time unit (see `TimeScale`).
        let ts = TimeScale::of(&[
            si.a,
            si.b,
            si.gamma.abs().sqrt(),
            si.delta.abs().sqrt(),
            si.beta.sqrt(),
        ]);
        let r = ts.reduced_to_unit(&si);
        let turning = turning_points_from_constants(&r).ok_or_else(|| {
            Error::invalid(
                "energy",
                format!(
                    "E' = E - p_psi^2/(2 I3) = {reduced_energy} lies below the minimum of the effective \
                     potential V(theta) (2.110) for p_phi = {p_phi}, p_psi = {p_psi}: no motion has these constants"
                ),
            )
        })?;
        // Time 0 at θ₁: where θ₁ is a double root of the cubic (u₂ = u₃, β(u₃ − u₂) = 0: the top
        // balanced upright on the separatrix, which it would take forever to leave), it stays.
        let turning = if r.p_and_complement(&turning).1 <= 0.0 {
            Turning::coincident(turning.w_lo, turning.v_hi)
        } else {
            turning
        };
        let turning = resolve_pole_passage("p_phi", turning, None)?;
        let (theta1, _) = turning.thetas();
        let start = EulerState {
            theta: theta1,
            ..Default::default()
        };
        Self::assemble(Assembly {
            i1,
            i3,
            mgl,
            p_phi,
            p_psi,
            energy,
            reduced_energy,
            r,
            ts,
            start,
            turning,
            from_state: false,
        })
    }

    /// Classifies and solves the motion of `a`, and refuses it (naming `theta` for a top started
    /// from a state, `p_phi` for one given by its constants) where the solution is not finite.
    fn assemble(a: Assembly) -> Result<Self> {
        let Assembly {
            i1,
            i3,
            ref r,
            ref ts,
            ref start,
            ref turning,
            from_state,
            ..
        } = a;
        let class = classify(r, turning);
        // Steady where the turning points coincide in the pole distance that is exact here (w
        // near the upright, v near the hanging pole: there the w's round to 2 alike).
        let motion = if turning.spread() == 0.0 {
            let theta = theta_from_wv(turning.w_lo, turning.v_lo);
            let (phi_rate, psi_rate) = uniform_rates(i1, i3, r, ts, turning, start, from_state);
            Motion::Uniform {
                theta,
                phi_rate,
                psi_rate,
            }
        } else {
            // Built in the time unit 1/σ, then carried to seconds (exactly: σ = 2ᵏ).
            let mut n = Nutation::new(i1, i3, r, turning, start, from_state, ts.sigma)?;
            n.rescale_time(ts.sigma);
            Motion::Nutating(Box::new(n))
        };
        // The fastest phase of the motion (rad/s): the nutation's, and the mean precession and
        // spin (the angles' linear parts).
        let (phase_rate, mean_phi, mean_psi) = match &motion {
            Motion::Uniform {
                phi_rate, psi_rate, ..
            } => (0.0, *phi_rate, *psi_rate),
            Motion::Nutating(n) => {
                let (p, s) = n.mean_rates();
                (n.phase_rate(), p, s)
            }
        };
        let fastest = phase_rate.max(mean_phi.abs()).max(mean_psi.abs());
        let max_time = if fastest > 0.0 {
            MAX_PHASE / fastest
        } else {
            f64::INFINITY
        };
        let top = Self {
            a,
            class,
            motion,
            max_time,
        };
        top.check_solution(if from_state { "theta" } else { "p_phi" })?;
        Ok(top)
    }

    /// Refuses (naming `argument`) a motion whose solution is not finite where it starts: one
    /// whose scales — the distance from a pole, the rates against each other — lie further
    /// apart than double precision spans (the fuzzed envelope is stated in docs/heavy_top.md).
    fn check_solution(&self, argument: &str) -> Result<()> {
        let (t1, t2) = self.turning_points();
        let mut values = vec![t1, t2, self.mean_precession_rate(), self.mean_spin_rate()];
        values.extend(self.angles_unchecked(0.0));
        values.extend(self.rates_unchecked(0.0));
        if values.iter().all(|v| v.is_finite()) {
            return Ok(());
        }
        Err(Error::invalid(
            argument,
            format!(
                "the exact solution of this motion cannot be represented in double precision: its \
                 scales (theta1 = {t1:e} rad from the vertical, the rates |p_psi|/I1 = {:e} and |p_phi|/I1 \
                 = {:e} rad/s against each other and against sqrt(2 mgl/I1) = {:e} rad/s) lie further apart \
                 than it spans",
                self.a.ts.rate_to_si(self.a.r.a).abs(),
                self.a.ts.rate_to_si(self.a.r.b).abs(),
                self.a.ts.rate_to_si(self.a.r.beta.sqrt()),
            ),
        ))
    }

    /// Checks one time: finite and within [`MAX_PHASE`] of this motion. The error names
    /// `argument` (`t`, or `times` with the index `at`).
    #[inline]
    fn check_time(&self, argument: &str, t: f64, at: Option<usize>) -> Result<()> {
        if t.abs() <= self.max_time && t.is_finite() {
            return Ok(());
        }
        let index = at.map_or(String::new(), |i| format!(" at index {i}"));
        if !t.is_finite() {
            return Err(Error::invalid(
                argument,
                format!("must be finite, got {t}{index}"),
            ));
        }
        if t.abs() > self.max_time {
            return Err(Error::invalid(
                argument,
                format!(
                    "|t| = {:e} s{index} is beyond {:.6e} s, the longest time over which this motion \
                     keeps its phase: its fastest rate times t, {:.3e} rad, would carry a rounding \
                     error of more than 1e-6 rad (the phase of the nutation, and with it theta, is lost)",
                    t.abs(),
                    self.max_time,
                    MAX_PHASE * t.abs() / self.max_time
                ),
            ));
        }
        Ok(())
    }

    /// I₁ (kg·m²), the moment about a transverse axis through the pivot.
    pub fn i1(&self) -> f64 {
        self.a.i1
    }
    /// I₃ (kg·m²), the moment about the symmetry axis.
    pub fn i3(&self) -> f64 {
        self.a.i3
    }
    /// m g l (N·m).
    pub fn mgl(&self) -> f64 {
        self.a.mgl
    }
    /// p_φ = I₁ φ̇ sin²θ + p_ψ cos θ (kg·m²/s), the conserved vertical angular momentum L_Z (2.104).
    pub fn p_phi(&self) -> f64 {
        self.a.p_phi
    }
    /// p_ψ = I₃ ω₃ (kg·m²/s), the conserved angular momentum about the symmetry axis (2.103).
    pub fn p_psi(&self) -> f64 {
        self.a.p_psi
    }
    /// ω₃ = ψ̇ + φ̇ cos θ = p_ψ / I₃ (rad/s), the constant spin (2.99, 2.103).
    pub fn omega3(&self) -> f64 {
        self.a.p_psi / self.a.i3
    }
    /// The total energy E = T + V (J, 2.105).
    pub fn energy(&self) -> f64 {
        self.a.energy
    }
    /// The reduced energy E' = E − p_ψ²/(2I₃) = ½ I₁ θ̇² + V(θ) (J, 2.109).
    pub fn reduced_energy(&self) -> f64 {
        self.a.reduced_energy
    }
    /// The state at time 0 (as given to [`HeavyTop::new`], with θ̇ turned into [0, π] at a pole;
    /// for [`HeavyTop::from_constants`], the upper turning point with φ = ψ = 0 and rates 0).
    pub fn initial_state(&self) -> EulerState {
        self.a.start
    }
    /// The turning points (θ₁, θ₂), θ₁ ≤ θ₂ (rad): the roots of the cubic f(cos θ) in [0, π]
    /// (where E' = V(θ), 2.109–2.110), computed without cancellation at the poles.
    pub fn turning_points(&self) -> (f64, f64) {
        self.a.turning.thetas()
    }
    /// The cosines of the turning points (u₂ = cos θ₁, u₁ = cos θ₂), and the third root u₃ ≥ 1 of
    /// the cubic (infinite for m g l = 0).
    pub fn cubic_roots(&self) -> (f64, f64, f64) {
        let u2 = 1.0 - self.a.turning.w_lo;
        let u1 = self.a.turning.v_lo - 1.0;
        let u1 = if u1 > 0.0 {
            1.0 - self.a.turning.w_hi
        } else {
            u1
        };
        let u2 = if u2 < 0.0 {
            self.a.turning.v_hi - 1.0
        } else {
            u2
        };
        let (p, _) = self.a.r.p_and_complement(&self.a.turning);
        let u3 = if self.a.r.beta > 0.0 {
            u1 + p / self.a.r.beta
        } else {
            f64::INFINITY
        };
        (u1, u2, u3)
    }
    /// The shape of the axis' path.
    pub fn motion_class(&self) -> MotionClass {
        self.class
    }
    /// Which pole the axis passes through, for a motion of [`MotionClass::ThroughVertical`]
    /// (a turning point at a pole: θ₁ = 0 upright, θ₂ = π straight down, exactly as
    /// [`Self::turning_points`] gives them); `None` for every other class (a sleeping or hanging
    /// top stays at its pole, it does not pass through it).
    pub fn vertical_pass(&self) -> Option<VerticalPass> {
        if self.class != MotionClass::ThroughVertical {
            return None;
        }
        let t = &self.a.turning;
        match (t.w_lo == 0.0, t.v_lo == 0.0) {
            (true, true) => Some(VerticalPass::Both),
            (true, false) => Some(VerticalPass::Upright),
            (false, true) => Some(VerticalPass::StraightDown),
            // `classify` gives this class only with one of the two at its pole.
            (false, false) => None,
        }
    }
    /// Whether an upright top with this spin would sleep stably: ω₃² > 4 m g l I₁ / I₃².
    pub fn is_sleeping_stable(&self) -> bool {
        let w3 = self.omega3();
        w3 * w3 * self.a.i3 * self.a.i3 > 4.0 * self.a.mgl * self.a.i1
    }
    /// The period of θ(t) (s): `2K(m)/κ` with κ = ½√(β(u₃ − u₁)) (β = 2mgl/I₁) and
    /// m = (u₂ − u₁)/(u₃ − u₁); for steady motion (θ₁ = θ₂), the period of small nutations about
    /// it, `2π/√P` with P = β(u₃ − u₁). `None` where θ never returns: an unstable sleeping top,
    /// an asymptotic motion (m = 1), or a period beyond the largest double.
    pub fn nutation_period(&self) -> Option<f64> {
        match &self.motion {
            Motion::Nutating(n) => n.period(),
            Motion::Uniform { .. } => {
                // P in the unit 1/σ²: the period 2π/√P in units of 1/σ.
                let (p, _) = self.a.r.p_and_complement(&self.a.turning);
                (p > 0.0).then(|| 2.0 * std::f64::consts::PI / p.sqrt() / self.a.ts.sigma)
            }
        }
        .filter(|p| p.is_finite())
    }
    /// The mean precession rate ⟨φ̇⟩ over a nutation period (rad/s): φ advances by
    /// `⟨φ̇⟩ · period` per period (including the jumps of ±π where the axis crosses a vertical).
    pub fn mean_precession_rate(&self) -> f64 {
        match &self.motion {
            Motion::Uniform { phi_rate, .. } => *phi_rate,
            Motion::Nutating(n) => n.mean_rates().0,
        }
    }
    /// The precession period (s): the time of one turn of the axis about the vertical at the
    /// mean rate, `2π/|⟨φ̇⟩|` (for steady precession, exactly the time φ takes to advance by 2π;
    /// for a nutating top, the mean over many nutations). `None` where the axis does not turn on
    /// average (⟨φ̇⟩ = 0: a sleeping or hanging top) or the period is beyond the largest double.
    pub fn precession_period(&self) -> Option<f64> {
        let rate = self.mean_precession_rate().abs();
        (rate > 0.0)
            .then(|| 2.0 * std::f64::consts::PI / rate)
            .filter(|p| p.is_finite())
    }
    /// The mean spin rate ⟨ψ̇⟩ over a nutation period (rad/s).
    pub fn mean_spin_rate(&self) -> f64 {
        match &self.motion {
            Motion::Uniform { psi_rate, .. } => *psi_rate,
            Motion::Nutating(n) => n.mean_rates().1,
        }
    }

    /// The effective potential V(θ) = (p_φ − p_ψ cos θ)²/(2 I₁ sin²θ) + m g l cos θ (J, 2.110),
    /// to a few ulp at every θ (evaluated as ½ I₁ (k/sin θ ± a tan(θ/2)^±1)² + m g l cos θ about
    /// the nearer pole, k = (p_φ ∓ p_ψ)/I₁: no 1 − cos θ, no underflow of sin²θ). At a pole it is
    /// the limit m g l cos θ where p_φ = ±p_ψ. Errors name `theta`: not finite or outside [0, π];
    /// or V infinite (at a pole with p_φ ≠ ±p_ψ, which the axis never reaches) or beyond the
    /// largest double (that close to such a pole).
    pub fn effective_potential(&self, theta: f64) -> Result<f64> {
        check_theta("theta", theta)?;
        finite_at_theta(
            "V(theta)",
            theta,
            effective_potential_reduced(self.a.i1, self.a.mgl, &self.a.r, &self.a.ts, theta),
        )
    }

    /// dV/dθ = (p_φ − p_ψ cos θ)(p_ψ − p_φ cos θ)/(I₁ sin³θ) − m g l sin θ (N·m, 2.113); the
    /// generalized force −dV/dθ drives θ̈ (I₁θ̈ = −dV/dθ). At a pole where V is finite the limit
    /// (0) is returned. Errors name `theta` as [`HeavyTop::effective_potential`].
    pub fn effective_potential_derivative(&self, theta: f64) -> Result<f64> {
        check_theta("theta", theta)?;
        finite_at_theta(
            "dV/dtheta",
            theta,
            effective_potential_derivative_reduced(
                self.a.i1, self.a.mgl, &self.a.r, &self.a.ts, theta,
            ),
        )
    }

    /// The Euler angles (φ, θ, ψ) at time `t` (s; the initial state is at t = 0), exact: θ from
    /// the Jacobi elliptic solution of the cubic, φ and ψ from complete and incomplete elliptic
    /// integrals of the third kind (Carlson's R_J). φ and ψ are continuous (not reduced modulo
    /// 2π) except for jumps of ±π where the axis passes exactly through a vertical.
    ///
    /// Accuracy: a few ulp of each angle near t = 0 — θ *relative* to itself even a hair's
    /// breadth from upright (θ₀ = 1e-12 and below: everything is formed in 1 − cos θ = 2 sin²(θ/2)
    /// without cancellation) — plus ε × (rate × |t|) rad for the phase the motion accumulates.
    /// Errors: `t` when it is not finite, or when |t| × the fastest rate of the motion exceeds
    /// [`MAX_PHASE`] (the phase would carry more than 1e-6 rad of rounding error).
    pub fn euler_angles(&self, t: f64) -> Result<[f64; 3]> {
        self.check_time("t", t, None)?;
        finite_at_t(t, self.angles_unchecked(t))
    }

    fn angles_unchecked(&self, t: f64) -> [f64; 3] {
        match &self.motion {
            Motion::Uniform {
                theta,
                phi_rate,
                psi_rate,
            } => [
                self.a.start.phi + phi_rate * t,
                *theta,
                self.a.start.psi + psi_rate * t,
            ],
            Motion::Nutating(n) => n.angles(t),
        }
    }

    /// [`HeavyTop::euler_angles`] evaluated through the incomplete elliptic integrals (Jacobi's
    /// sn, cn, dn and Carlson's R_J at every t) rather than through their Fourier series: slower,
    /// the same numbers to round-off; kept as the cross-check of the fast path. Errors as
    /// [`HeavyTop::euler_angles`].
    pub fn euler_angles_carlson(&self, t: f64) -> Result<[f64; 3]> {
        self.check_time("t", t, None)?;
        finite_at_t(
            t,
            match &self.motion {
                Motion::Nutating(n) => n.angles_carlson(t),
                Motion::Uniform { .. } => self.angles_unchecked(t),
            },
        )
    }

    /// The number of Fourier terms [`HeavyTop::euler_angles`] sums per time (see
    /// `heavy_top::fourier`); 0 when the motion is uniform or evaluated by R_J (axis passing through or
    /// very near a pole, or m near 1, where the series would converge slowly).
    pub fn fourier_terms(&self) -> usize {
        match &self.motion {
            Motion::Nutating(n) => n.fourier_terms(),
            Motion::Uniform { .. } => 0,
        }
    }

    /// The Euler-angle rates (φ̇, θ̇, ψ̇) at time `t` (rad/s), from 2.106 (φ̇), ψ̇ = ω₃ − φ̇ cos θ
    /// (2.99) and θ̇ from the elliptic solution (its sign is that of the motion). Errors as
    /// [`HeavyTop::euler_angles`].
    pub fn euler_rates(&self, t: f64) -> Result<[f64; 3]> {
        self.check_time("t", t, None)?;
        finite_at_t(t, self.rates_unchecked(t))
    }

    fn rates_unchecked(&self, t: f64) -> [f64; 3] {
        match &self.motion {
            Motion::Uniform {
                phi_rate, psi_rate, ..
            } => [*phi_rate, 0.0, *psi_rate],
            Motion::Nutating(n) => n.rates(t),
        }
    }

    /// [`HeavyTop::euler_angles`] at many times, in parallel: `out[3i..3i + 3] = [φ, θ, ψ](times[i])`
    /// (`out` flat, row-major (N, 3)). Errors name `times` (each finite and within the limit of
    /// [`HeavyTop::euler_angles`]) or `out` (length 3N).
    pub fn euler_angles_into(&self, times: &[f64], out: &mut [f64]) -> Result<()> {
        match &self.motion {
            Motion::Nutating(n) => self.batch_chunks(times, out, |ts, o| n.angles_into(ts, o)),
            Motion::Uniform { .. } => self.batch(times, out, |t| self.angles_unchecked(t)),
        }
    }

    /// [`HeavyTop::euler_rates`] at many times, in parallel (`out` flat (N, 3): φ̇, θ̇, ψ̇).
    /// Errors name `times` or `out`.
    pub fn euler_rates_into(&self, times: &[f64], out: &mut [f64]) -> Result<()> {
        self.batch(times, out, |t| self.rates_unchecked(t))
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
        // Per chunk, in parallel: the times checked, evaluated, and the results checked finite
        // (the last line of defence of "finite or an error", see `finite_at_t`); the first
        // failing index is reported.
        // Under `control::parallel`: Ctrl-C stops the loop between two chunks.
        let first_bad = crate::control::parallel(times.len() as u64, |cancel| {
            Ok(out
                .par_chunks_mut(3 * CHUNK)
                .zip(times.par_chunks(CHUNK))
                .enumerate()
                .filter_map(|(c, (o, ts))| {
                    if cancel.check().is_err() {
                        return None;
                    }
                    cancel.advance(ts.len() as u64);
                    // `check_time`'s condition, inline (the error is made below, once).
                    let max_time = self.max_time;
                    if let Some(i) = ts
                        .iter()
                        .position(|&t| !(t.abs() <= max_time && t.is_finite()))
                    {
                        return Some(c * CHUNK + i);
                    }
                    f(ts, o);
                    if all_finite(o) {
                        return None;
                    }
                    o.iter()
                        .position(|v| !v.is_finite())
                        .map(|i| c * CHUNK + i / 3)
                })
                .min())
        })?;
        match first_bad {
            None => Ok(()),
            Some(i) => {
                let t = times[i];
                self.check_time("times", t, Some(i))?;
                Err(Error::invalid(
                    "times",
                    format!("at index {i}: the solution at t = {t:e} s is not finite"),
                ))
            }
        }
    }
}

/// Whether every value is finite: `0 · v` is ±0 for a finite v and NaN otherwise, summed in
/// eight independent accumulators (a loop without an early exit, which vectorizes).
fn all_finite(values: &[f64]) -> bool {
    let mut acc = [0.0f64; 8];
    let mut chunks = values.chunks_exact(8);
    for c in &mut chunks {
        for (a, &v) in acc.iter_mut().zip(c) {
            *a += 0.0 * v;
        }
    }
    acc.iter().all(|&a| a == 0.0) && chunks.remainder().iter().all(|v| v.is_finite())
}

/// The Lagrangian of the heavy symmetric top (J, 2.102):
/// `L = ½ I₁ (θ̇² + φ̇² sin²θ) + ½ I₃ (ψ̇ + φ̇ cos θ)² − m g l cos θ`.
/// Errors name `I1`, `I3`, `mgl`, `theta` and the rates.
pub fn lagrangian(i1: f64, i3: f64, mgl: f64, state: &EulerState) -> Result<f64> {
    check_state(i1, i3, mgl, state, false)?;
    let (s, c) = cubic::sin_cos(state.theta);
    // In the unit of the state's fastest rate (exact; see `TimeScale`), so that no square
    // overflows where the Lagrangian itself is representable.
    let ts = TimeScale::of(&[state.theta_dot, state.phi_dot, state.psi_dot]);
    let (thd, phd, psd) = (
        ts.in_unit(state.theta_dot),
        ts.in_unit(state.phi_dot),
        ts.in_unit(state.psi_dot),
    );
    let w3 = psd + phd * c;
    let l = ts.moment_to_si(0.5 * i1, thd.powi(2) + (phd * s).powi(2), 2)
        + ts.moment_to_si(0.5 * i3, w3 * w3, 2)
        - mgl * c;
    check_representable(&[("Lagrangian", l, largest_rate(state))])?;
    Ok(l)
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
    check_state(i1, i3, mgl, state, false)?;
    let (s, c) = cubic::sin_cos(state.theta);
    // The arithmetic of `HeavyTop::new`, in the unit of the fastest rate (exact).
    let ts = TimeScale::of(&[state.theta_dot, state.phi_dot, state.psi_dot]);
    let (thd, phd, psd) = (
        ts.in_unit(state.theta_dot),
        ts.in_unit(state.phi_dot),
        ts.in_unit(state.psi_dot),
    );
    let omega3 = psd + phd * c; // 2.99
    let a = (i3 / i1) * omega3; // p_ψ/I₁ (2.103)
    let ps = phd * (s * s);
    let tperp = thd * thd + phd * ps;
    let out = StateConstants {
        p_phi: ts.moment_to_si(i1, ps + a * c, 1), // 2.104
        p_psi: ts.moment_to_si(i3, omega3, 1),
        energy: (ts.moment_to_si(0.5 * i1, tperp, 2) + mgl * c)
            + ts.moment_to_si(0.5 * i3, omega3 * omega3, 2), // 2.105
    };
    let largest = largest_rate(state);
    check_representable(&[
        ("p_phi", out.p_phi, largest),
        ("p_psi", out.p_psi, largest),
        ("E", out.energy, largest),
    ])?;
    Ok(out)
}

/// `(p_φ − p_ψ cos θ)/(I₁ sin θ)` and `(p_ψ − p_φ cos θ)/(I₁ sin θ)` about the nearer pole, with
/// p_φ − p_ψ cos θ = I₁(d + a w) = I₁(e − a v), p_ψ − p_φ cos θ = I₁(b w − d) = I₁(e − b v) and
/// w/sin θ = tan(θ/2), v/sin θ = cot(θ/2): no cancellation, and no underflow of w or sin²θ
/// however small θ is. At a pole (sin θ = 0) the limits where they are finite (k = d or e = 0:
/// both → 0), else ±∞.
fn momentum_ratios(r: &Reduced, theta: f64) -> (f64, f64) {
    let s = theta.sin();
    let upper = theta <= std::f64::consts::FRAC_PI_2;
    let k = if upper { r.d } else { r.e };
    if s == 0.0 {
        return if k == 0.0 {
            (0.0, 0.0)
        } else {
            // V → +∞ at both poles; (k/s)(∓k/s)/s gives dV/dθ → −∞ at θ = 0, +∞ at θ = π.
            let inf = f64::INFINITY.copysign(k);
            if upper {
                (inf, -inf)
            } else {
                (inf, inf)
            }
        };
    }
    if upper {
        // tan(θ/2) directly: w = 2 sin²(θ/2) would underflow below θ ≈ 1e-154.
        let t = (0.5 * theta).tan();
        (r.d / s + r.a * t, r.b * t - r.d / s)
    } else {
        // cot(θ/2) = v/sin θ; near π, v ≥ 1e-32 (θ ≤ π − ulp(π)).
        let (_, v) = w_v(theta);
        let t = v / s;
        (r.e / s - r.a * t, r.e / s - r.b * t)
    }
}

/// V(θ) (2.110) from the reduced constants (in the unit σ of `ts`):
/// ½ I₁ ((p_φ − p_ψ cos θ)/(I₁ sin θ))² + m g l cos θ.
fn effective_potential_reduced(i1: f64, mgl: f64, r: &Reduced, ts: &TimeScale, theta: f64) -> f64 {
    let (n1, _) = momentum_ratios(r, theta);
    let n1 = ts.rate_to_si(n1);
    0.5 * i1 * n1 * n1 + mgl * theta.cos()
}

/// dV/dθ (2.113) from the reduced constants: I₁ (n₁/sin θ)(n₂/sin θ)/sin θ − m g l sin θ.
fn effective_potential_derivative_reduced(
    i1: f64,
    mgl: f64,
    r: &Reduced,
    ts: &TimeScale,
    theta: f64,
) -> f64 {
    let (n1, n2) = momentum_ratios(r, theta);
    let (n1, n2) = (ts.rate_to_si(n1), ts.rate_to_si(n2));
    let s = theta.sin();
    if s == 0.0 {
        // Where V is finite at the pole, n₁ n₂/sin θ ∝ a b tan²(θ/2)/sin θ → 0 linearly.
        return if n1 == 0.0 { 0.0 } else { i1 * n1 * n2 };
    }
    (i1 * n1) * (n2 / s) - mgl * s
}

/// The class of the motion from the turning points and the sign of φ̇ there.
///
/// Near a pole both tests are relative: the nutation θ₂ − θ₁ against the distance from that pole
/// (a top nutating between 1e-12 and 1.15e-12 rad nutates by 15 %; it is not asleep), and φ̇'s
/// numerator `p_φ − p_ψ cos θᵢ` (∝ I₁(b − a cos θᵢ)) written about the pole the turning point is
/// nearer to (`d + a wᵢ` or `e − a vᵢ`), where both terms are small and exact, instead of as the
/// difference of two numbers near ±a.
fn classify(r: &Reduced, t: &Turning) -> MotionClass {
    let (theta1, theta2) = t.thetas();
    let pi = std::f64::consts::PI;
    // The nutation and the distance from the nearer pole; near the hanging pole both from the
    // distances π − θᵢ themselves (θ₂ − θ₁ of the doubles θᵢ ≈ π is a multiple of an ulp of π,
    // which a steady precession at π − 1e-12 exceeds a millionfold).
    let (nutation, scale) = if t.nearer_lower_pole() {
        let (chi1, chi2) = t.hanging_distances();
        (chi1 - chi2, chi1.min(1.0))
    } else {
        (theta2 - theta1, theta2.min(pi - theta1).min(1.0))
    };
    if t.spread() == 0.0 || nutation <= STEADY_NUTATION_TOLERANCE * scale {
        // At a pole itself (θ = π is the double nearest π: the bottom as the API spells it).
        return if theta2 == 0.0 {
            MotionClass::Sleeping
        } else if theta1 == pi {
            MotionClass::Hanging
        } else {
            MotionClass::SteadyPrecession
        };
    }
    if t.w_lo == 0.0 || t.v_lo == 0.0 {
        return MotionClass::ThroughVertical;
    }
    // φ̇ ∝ b − a cos θ (2.106): at θᵢ it is d + a wᵢ = e − a vᵢ; each with the scale of its terms.
    let numerator = |w: f64, v: f64| {
        if w <= v {
            (r.d + r.a * w, r.d.abs() + (r.a * w).abs())
        } else {
            (r.e - r.a * v, r.e.abs() + (r.a * v).abs())
        }
    };
    let (r1, s1) = numerator(t.w_lo, t.v_hi);
    let (r2, s2) = numerator(t.w_hi, t.v_lo);
    let cusp1 = r1.abs() <= CUSP_TOLERANCE * s1;
    let cusp2 = r2.abs() <= CUSP_TOLERANCE * s2;
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
    ts: &TimeScale,
    t: &Turning,
    start: &EulerState,
    from_state: bool,
) -> (f64, f64) {
    let omega3 = r.a * (i1 / i3);
    let (w, v) = (t.w_lo, t.v_lo);
    if w == 0.0 || v == 0.0 {
        return if from_state {
            (start.phi_dot, start.psi_dot)
        } else {
            (0.0, ts.rate_to_si(omega3))
        };
    }
    // φ̇ = (b − a u)/(1 − u²) (2.106/2.115), written about the nearer pole; ψ̇ = ω₃ − φ̇ cos θ.
    let phi_rate = if w <= 1.0 {
        (r.d + r.a * w) / (w * v)
    } else {
        (r.e - r.a * v) / (w * v)
    };
    let c = if w <= 1.0 { 1.0 - w } else { v - 1.0 };
    (
        ts.rate_to_si(phi_rate),
        ts.rate_to_si(omega3 - phi_rate * c),
    )
}
