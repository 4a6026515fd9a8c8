//! The heavy symmetric top over a grid of its parameters and initial states (the unit's
//! 2.102–2.121): motion class, turning points, nutation period, mean precession and spin, and
//! the constants of the motion at every point.

use super::grid::{Grid, Param};
use crate::analytic::{check_state, spin_state, EulerState, HeavyTop, MotionClass};
use crate::error::{Error, Result};

/// The keywords of [`heavy_top`]: those of [`HeavyTop::new`] (`I1`, `I3`, `mgl`, the angles
/// `theta`, `phi`, `psi` and the rates `theta_dot`, `phi_dot`, `psi_dot`) and `omega3`, the spin
/// given instead of `psi_dot` as in [`HeavyTop::with_spin`].
pub const HEAVY_TOP_KEYWORDS: [&str; 10] = [
    "I1",
    "I3",
    "mgl",
    "theta",
    "theta_dot",
    "phi_dot",
    "psi_dot",
    "omega3",
    "phi",
    "psi",
];

/// Every [`MotionClass`], in the order of their codes in a sweep (a class's code is its index
/// here): waves, loops, cusps, steady precession, sleeping, hanging, through vertical.
pub const MOTION_CLASSES: [MotionClass; 7] = [
    MotionClass::Waves,
    MotionClass::Loops,
    MotionClass::Cusps,
    MotionClass::SteadyPrecession,
    MotionClass::Sleeping,
    MotionClass::Hanging,
    MotionClass::ThroughVertical,
];

/// What a sweep of the heavy top gives at one point: the quantities of [`HeavyTop`] of that
/// point's top.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeavyTopPoint {
    /// The shape of the axis' path ([`HeavyTop::motion_class`]).
    pub motion_class: MotionClass,
    /// The turning points (θ₁, θ₂), θ₁ ≤ θ₂ (rad).
    pub turning_points: (f64, f64),
    /// The period of θ(t) (s); infinite where θ never returns (as `HeavyTop.nutation_period`
    /// in Python: [`HeavyTop::nutation_period`] is `None` there).
    pub nutation_period: f64,
    /// The mean precession rate ⟨φ̇⟩ (rad/s).
    pub mean_precession_rate: f64,
    /// The mean spin rate ⟨ψ̇⟩ (rad/s).
    pub mean_spin_rate: f64,
    /// The spin ω₃ = ψ̇ + φ̇ cos θ (rad/s, 2.99).
    pub omega3: f64,
    /// p_φ (kg·m²/s, 2.104).
    pub p_phi: f64,
    /// p_ψ = I₃ω₃ (kg·m²/s, 2.103).
    pub p_psi: f64,
    /// The total energy E (J, 2.105).
    pub energy: f64,
    /// The reduced energy E' = E − p_ψ²/(2I₃) (J, 2.109).
    pub reduced_energy: f64,
    /// Whether the spin keeps the top asleep upright: ω₃² > 4 m g l I₁ / I₃².
    pub is_sleeping_stable: bool,
}

/// A motion class's code in a sweep: its index in [`MOTION_CLASSES`].
pub fn motion_class_code(class: MotionClass) -> u8 {
    match class {
        MotionClass::Waves => 0,
        MotionClass::Loops => 1,
        MotionClass::Cusps => 2,
        MotionClass::SteadyPrecession => 3,
        MotionClass::Sleeping => 4,
        MotionClass::Hanging => 5,
        MotionClass::ThroughVertical => 6,
    }
}

/// The keywords read at every point.
struct Inputs<'a> {
    i1: Param<'a>,
    i3: Param<'a>,
    mgl: Param<'a>,
    theta: Param<'a>,
    theta_dot: Param<'a>,
    phi_dot: Param<'a>,
    /// `psi_dot`, or `omega3` when `with_spin`.
    spin: Param<'a>,
    with_spin: bool,
    phi: Param<'a>,
    psi: Param<'a>,
}

const ZERO: [f64; 1] = [0.0];

impl<'a> Inputs<'a> {
    fn of(grid: &Grid<'a>) -> Result<Self> {
        grid.check_keywords("heavy_top", &HEAVY_TOP_KEYWORDS)?;
        let with_spin = grid.has("omega3");
        if with_spin && grid.has("psi_dot") {
            return Err(Error::invalid(
                "omega3",
                "give the spin omega3 or psi_dot, not both (psi_dot = omega3 - phi_dot cos(theta), 2.99)",
            ));
        }
        // The defaults of a start are those of `EulerState::default()`: 0 rad and 0 rad/s.
        let default = EulerState::default();
        debug_assert!(default.phi == 0.0 && default.psi_dot == 0.0);
        Ok(Self {
            i1: grid.required("I1", 1)?,
            i3: grid.required("I3", 1)?,
            mgl: grid.required("mgl", 1)?,
            theta: grid.required("theta", 1)?,
            theta_dot: grid.or_default("theta_dot", &ZERO)?,
            phi_dot: grid.or_default("phi_dot", &ZERO)?,
            spin: if with_spin {
                grid.required("omega3", 1)?
            } else {
                grid.or_default("psi_dot", &ZERO)?
            },
            with_spin,
            phi: grid.or_default("phi", &ZERO)?,
            psi: grid.or_default("psi", &ZERO)?,
        })
    }

    /// The top's parameters and its start at `p`, checked as the constructors check them.
    fn start(&self, p: usize) -> Result<(f64, f64, f64, EulerState)> {
        let (i1, i3, mgl) = (self.i1.scalar(p), self.i3.scalar(p), self.mgl.scalar(p));
        let (phi, theta, psi) = (self.phi.scalar(p), self.theta.scalar(p), self.psi.scalar(p));
        let (phi_dot, theta_dot) = (self.phi_dot.scalar(p), self.theta_dot.scalar(p));
        let spin = self.spin.scalar(p);
        let state = if self.with_spin {
            spin_state(phi, theta, psi, phi_dot, theta_dot, spin)? // as HeavyTop::with_spin
        } else {
            EulerState {
                phi,
                theta,
                psi,
                phi_dot,
                theta_dot,
                psi_dot: spin,
            }
        };
        check_state(i1, i3, mgl, &state, true).map_err(|e| self.renamed(e))?;
        Ok((i1, i3, mgl, state))
    }

    fn renamed(&self, e: Error) -> Error {
        if self.with_spin {
            e.renamed("psi_dot", "omega3")
        } else {
            e
        }
    }

    fn top(&self, p: usize) -> Result<HeavyTop> {
        let (i1, i3, mgl, s) = self.start(p)?;
        HeavyTop::new(i1, i3, mgl, s).map_err(|e| self.renamed(e))
    }
}

/// Checks every point of a sweep of the heavy top as [`HeavyTop::new`] (or
/// [`HeavyTop::with_spin`] when `omega3` is given) checks its arguments, without solving any
/// motion: cheap (tens of ns a point), so that a sweep on a cluster is refused before any work
/// is sent out. Errors name the keyword and the first point at fault
/// (`"theta: must be finite and in [0, pi], got 4 (at theta[3], psi_dot[0])"`), a keyword that
/// is not one of [`HEAVY_TOP_KEYWORDS`], a required one missing (`I1`, `I3`, `mgl`, `theta`), or
/// `omega3` given with `psi_dot`.
pub fn check_heavy_top(grid: &Grid<'_>) -> Result<()> {
    let inputs = Inputs::of(grid)?;
    grid.validate(|p| inputs.start(p).map(|_| ()))
}

/// The heavy top at every point of `grid` ([`HeavyTop::new`], or [`HeavyTop::with_spin`] when
/// `omega3` is given; missing angles and rates are 0), in row-major order, computed in parallel
/// after [`check_heavy_top`] and the memory budget passed. Stoppable through
/// [`crate::control`]. A point whose exact solution is refused (its scales beyond double
/// precision) stops the sweep with that error, located.
pub fn heavy_top(grid: &Grid<'_>) -> Result<Vec<HeavyTopPoint>> {
    let inputs = Inputs::of(grid)?;
    grid.check_memory(std::mem::size_of::<HeavyTopPoint>())?;
    grid.validate(|p| inputs.start(p).map(|_| ()))?;
    grid.compute(|p| {
        let top = inputs.top(p)?;
        Ok(HeavyTopPoint {
            motion_class: top.motion_class(),
            turning_points: top.turning_points(),
            nutation_period: top.nutation_period().unwrap_or(f64::INFINITY),
            mean_precession_rate: top.mean_precession_rate(),
            mean_spin_rate: top.mean_spin_rate(),
            omega3: top.omega3(),
            p_phi: top.p_phi(),
            p_psi: top.p_psi(),
            energy: top.energy(),
            reduced_energy: top.reduced_energy(),
            is_sleeping_stable: top.is_sleeping_stable(),
        })
    })
}
