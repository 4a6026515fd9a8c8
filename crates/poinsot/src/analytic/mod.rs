//! Closed-form solutions: the free symmetric top (the unit's 2.77–2.97), the free asymmetric
//! top (Jacobi elliptic functions and the integral of the third kind), Poinsot's construction
//! and the stability of rotation about the principal axes, and the heavy symmetric top (the
//! unit's eqs. 2.98–2.121), exactly, by elliptic functions; and the free body's exact states
//! for many bodies and times at once ([`free_body_states`], on SIMD lanes).

mod free_rigid_body;
mod free_scale;
mod free_states;
mod free_symmetric_top;
mod heavy_top;
mod poinsot_construction;

pub use crate::inertia::check_moments;
pub use free_rigid_body::{FreeRegime, FreeRigidBody};
pub use free_scale::PHASE_LIMIT;
pub use free_states::{free_body_states, FreeBodyStates, StateTimes};
pub use free_symmetric_top::{FreeSymmetricTop, TopShape};
pub use heavy_top::{
    check_theta, check_top, constants_of_state, heavy_top_parameters, lagrangian, min_spin,
    sleeping_threshold, steady_precession, EulerState, HeavyTop, MotionClass, StateConstants,
    SteadyPrecession, VerticalPass, CUSP_TOLERANCE, MAX_PHASE, MIN_POLE_DISTANCE,
    PIVOT_SYMMETRY_RTOL, STEADY_NUTATION_TOLERANCE,
};
pub use poinsot_construction::{axis_stability, AxisStability, Stability};
// The checks the constructors make, for the sweeps' validation before work ([`crate::sweep`]).
pub(crate) use free_scale::check_omega_range;
pub(crate) use free_symmetric_top::check_omega;
pub(crate) use heavy_top::{check_state, spin_state};
