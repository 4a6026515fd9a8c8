//! Integrators of ordinary differential equations that know nothing of physics.
//!
//! * [`dop853`] / [`Dop853`]: the adaptive embedded Dormand–Prince 8(5,3) pair with error
//!   control, 7th-order dense output and terminal events (Hairer, Nørsett & Wanner,
//!   *Solving Ordinary Differential Equations I*, §II.5–II.6);
//! * [`compose`]: symmetric composition of a symmetric second-order map to orders 4 and 6
//!   (triple jump, Kahan–Li), used by the Lie–Poisson splitting of the rigid body
//!   (`crate::dynamics`).
//!
//! A system is anything implementing [`OdeSystem`] — in particular any closure
//! `FnMut(t, &y, &mut dy)` — over a state implementing [`OdeState`] (fixed-size arrays
//! `[f64; N]`, `Vec<f64>`, nalgebra `SVector<f64, N>`).

mod composition;
mod dop853;
mod dop853_coefficients;
mod grid;
mod options;
mod solution;
mod state;

pub use composition::{
    compose, composition_coefficients, SymmetricStep, KAHAN_LI_6, TRIPLE_JUMP_4,
};
pub use dop853::{dop853, dop853_scan, dop853_until, Dop853, Scan};
pub use grid::{even_times, sample_before, sample_times};
pub use options::{Crossing, Options, Stats, Tolerances, MIN_RTOL};
pub use solution::{DenseStep, EventHit, Solution};
pub use state::{OdeState, OdeSystem};
