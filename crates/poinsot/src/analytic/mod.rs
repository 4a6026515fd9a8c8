//! Closed-form solutions: the heavy symmetric top (the unit's eqs. 2.98–2.121), exactly, by
//! elliptic functions.

mod heavy_top;
mod heavy_top_cubic;
mod heavy_top_fourier;
mod heavy_top_motion;
mod heavy_top_steady;

pub use heavy_top::{
    lagrangian, EulerState, HeavyTop, MotionClass, CUSP_TOLERANCE, STEADY_NUTATION_TOLERANCE,
};
pub use heavy_top_steady::{
    check_theta, check_top, min_spin, sleeping_threshold, steady_precession, SteadyPrecession,
};
