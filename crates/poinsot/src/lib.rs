//! # poinsot — moving frames and the motion of rigid bodies
//!
//! The physics core of poinsot, in pure Rust. Every front end (Python, the command line, the
//! browser lab) calls into this crate and holds no physics of its own.
//!
//! Modules follow the course unit *Moving Coordinate Systems and Motion of a Rigid Body*, and
//! their docs cite its equation numbers (2.1–2.121; "the unit's 2.116" is its equation 2.116):
//!
//! | module | topic | unit equations |
//! |---|---|---|
//! | [`rotation`] | SO(3), quaternions, Euler angles, Euler's theorem, Chasles' screw, Euler-angle kinematics | 2.98–2.99 |
//! | [`inertia`] | inertia tensor, principal axes, standard solids, density and mesh integrals, L and T | 2.43–2.66 |
//! | [`frames`] | moving frames: velocity and acceleration terms, fictitious forces, particles in time-dependent frames | 2.1–2.28 |
//! | [`earth`] | the rotating Earth: effective gravity, Coriolis, falling bodies, projectiles, Foucault, winds | 2.29–2.42 |
//! | [`integrate`] | ODE integrators that know no physics: adaptive DOP853 with dense output and events, symmetric composition (the splittings' orders 4 and 6) | — |
//! | [`dynamics`] | Euler's equations with torques, attitude quaternions, `simulate` (exact flow, Lie–Poisson splitting, RK4, DOP853), batches | 2.67–2.76 |
//! | [`analytic`] | closed forms: the free symmetric top, the free asymmetric top (Jacobi functions, Π), Poinsot's construction, axis stability; the heavy symmetric top (Lagrangian, effective potential, turning points, steady precession, exact motion) | 2.77–2.121 |
//! | [`control`] | stopping long computations (Ctrl-C) and reporting their progress | — |
//! | [`defaults`] | the defaults of every public call's options, stated once for every front end | — |
//! | [`limits`] | the memory budget and step limits checked before work starts | — |
//! | `rows` (private) | the checks of a batch's rows of bodies (moments, ω₀, attitude), shared by `dynamics` and `analytic` | — |
//! | `simd` (private) | lanes of doubles for the batch kernels, run with the widest vector instructions of the CPU | — |
//! | [`special`] | Jacobi elliptic functions sn, cn, dn, am (parameter m = k²) and elliptic integrals F, E, K, Π | — |
//! | [`sweep`] | parameter studies: a model at every point of a grid of its keywords, validated first, in parallel | — |
//!
//! Conventions (the crate's README lists them; `CONVENTIONS.md` in the project's repository pins
//! each by a test): SI units, radians, right-handed frames, active rotations (`v_space =
//! R v_body`), scalar-first quaternions `[w, x, y, z]` (body → space), the unit's intrinsic
//! z-x-z Euler angles by default, products of inertia negated (`I_xy = −Σ m x y`) so that
//! `L = I·ω`.
//!
//! # Example
//!
//! The exact torque-free body and the heavy symmetric top (more in the crate's README):
//!
//! ```
//! use poinsot::analytic::{EulerState, FreeRigidBody, HeavyTop};
//! use poinsot::Vec3;
//!
//! // Principal moments 1, 2, 3 kg·m², spun near the intermediate axis: ω₂ flips sign.
//! let body = FreeRigidBody::new([1.0, 2.0, 3.0], Vec3::new(0.01, 3.0, 0.01), None)?;
//! assert!(body.omega(body.flip_interval()?)?.y < -2.9);
//!
//! // I₁ = 1, I₃ = 0.5 kg·m², m g l = 1 N·m, released at θ = 0.8 rad.
//! let start = EulerState { theta: 0.8, phi_dot: 0.5, psi_dot: 6.0, ..Default::default() };
//! let top = HeavyTop::new(1.0, 0.5, 1.0, start)?;
//! let (theta1, theta2) = top.turning_points();
//! let [_phi, theta, _psi] = top.euler_angles(10.0)?;
//! assert!(theta1 <= theta && theta <= theta2);
//! # Ok::<(), poinsot::Error>(())
//! ```
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod analytic;
pub mod control;
pub mod defaults;
pub mod dynamics;
pub mod earth;
pub mod error;
pub mod frames;
pub mod inertia;
pub mod integrate;
pub mod limits;
pub mod rotation;
mod rows;
pub(crate) mod simd;
pub mod special;
pub mod sweep;

pub use error::{Error, ErrorKind, Result};

/// 3-vectors of `f64` (nalgebra).
pub type Vec3 = nalgebra::Vector3<f64>;
/// 3×3 matrices of `f64` (nalgebra).
pub type Mat3 = nalgebra::Matrix3<f64>;

/// The examples of the crate's README, run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
