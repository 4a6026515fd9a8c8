//! The defaults of the public calls' options, in one place.
//!
//! Every default a front end offers (a sample count, a tolerance, a step limit, an integration
//! method, a planet, a convention) is one of these constants: the Python binding exports them as
//! `poinsot._core.DEFAULTS` (by call and argument, read by the Python signatures and compared
//! with every public signature by `python/tests/test_defaults_once.py`), so that no front end
//! restates a number. Constants that belong to one topic stay beside it (the Earth's runs in
//! [`crate::earth`], the particle's in [`crate::frames`]) and are re-exported here.

pub use crate::analytic::EulerState;
pub use crate::dynamics::{
    COMPASS_ANGULAR_MOMENTUM, COMPASS_DAMPING, COMPASS_INERTIA, COMPASS_METHOD,
    COMPASS_PENDULOSITY, COMPASS_SAMPLES, COMPASS_TOLERANCES,
};
pub use crate::earth::{ANNUAL_PERIOD, POLAR_MOTION_SOURCE};
pub use crate::earth::{
    DROP_SAMPLES, DROP_TOLERANCES, DYNAMICAL_FLATTENING, FOUCAULT_AMPLITUDE, FOUCAULT_AZIMUTH,
    FOUCAULT_DURATION, FOUCAULT_LENGTH, FOUCAULT_SAMPLES, FOUCAULT_TOLERANCES, INERTIAL_SAMPLES,
    INERTIAL_TOLERANCES, INERTIAL_VELOCITY, LOW_DURATION, LOW_FRICTION, LOW_PARCELS, LOW_PULL,
    LOW_RADIUS, LOW_SAMPLES, LOW_TOLERANCES, MEAN_RADIUS, OBLIQUITY_J2000, SIDEREAL_RATE,
    STANDARD_GRAVITY,
};
pub use crate::earth::{NUTATION_SCALE, POLE_MAX_STEPS, POLE_MOON_NODE, POLE_SAMPLES};
pub use crate::frames::{PARTICLE_MASS, PARTICLE_SAMPLES, PARTICLE_TOLERANCES};
pub use crate::inertia::{CubatureOptions, DEFAULT_KIND_RTOL};
use crate::integrate::Tolerances;
pub use crate::limits::DEFAULT_MAX_STEPS;

/// The tolerance of the explicit validator of rotation matrices (`check_rotation_matrix`) on
/// `max |RᵀR − I|` and `|det R − 1|`: 1e-9, stricter than the [`crate::rotation::ROTATION_MATRIX_TOL`]
/// with which the other calls accept a rotation.
pub const CHECK_ROTATION_TOL: f64 = 1e-9;
/// The Euler-angle sequence of every call that takes one: the unit's intrinsic z-x-z.
pub const EULER_SEQUENCE: &str = "zxz";
/// The components of the rates of Euler angles' angular velocity (`"body"` or `"space"`): body.
pub const EULER_RATES_FRAME: &str = "body";

/// A body's centre of mass when none is given: the origin (m).
pub const CENTER_OF_MASS: [f64; 3] = [0.0; 3];
/// The uniform density of a mesh body when none is given (kg/m³).
pub const MESH_DENSITY: f64 = 1.0;
/// The options of a density's cubature ([`crate::inertia::density_mass_properties`]): rtol
/// 1e-6 (of tr I / 2), atol 0 (kg·m²), at most 10⁷ evaluations; [`CubatureOptions::default`].
pub const CUBATURE: CubatureOptions = CubatureOptions::DEFAULT;

/// A point's velocity and acceleration relative to a moving frame when none is given: at rest
/// (m/s, m/s²).
pub const AT_REST: [f64; 3] = [0.0; 3];
/// The spring of a particle in a moving frame when none is given: none (N/m).
pub const PARTICLE_STIFFNESS: f64 = 0.0;

/// The integration method of one body's motion (`simulate`): the exact flow for a torque-free
/// body, DOP853 otherwise ([`crate::dynamics::Method::Auto`]).
pub const SIMULATE_METHOD: &str = "auto";
/// The integration method of a batch of bodies (`simulate_batch`, the sweeps): RK4 on SIMD lanes.
pub const BATCH_METHOD: &str = "rk4";
/// The evenly spaced output times of one body's motion, both ends included.
pub const SIMULATE_SAMPLES: usize = 1001;
/// Tolerances of one body's motion by DOP853: rtol 1e-10, atol 1e-12 (rad/s and the
/// quaternion's components), [`DEFAULT_MAX_STEPS`] steps.
pub const SIMULATE_TOLERANCES: Tolerances = Tolerances {
    rtol: 1e-10,
    atol: 1e-12,
    max_steps: DEFAULT_MAX_STEPS,
};

/// Points of a polhode (one period of ω(t)), both ends included: a point every half degree.
pub const POLHODE_SAMPLES: usize = 721;
/// The components of the contact point of Poinsot's construction: space.
pub const CONTACT_POINT_FRAME: &str = "space";
/// The spin of [`crate::analytic::axis_stability`] when none is given (rad/s).
pub const AXIS_SPIN: f64 = 1.0;

/// The gravity of falls and projectiles: uniform ([`crate::earth::Gravity::Uniform`]).
pub const GRAVITY: &str = "uniform";
/// A projectile's launch height when none is given: the ground (m).
pub const LAUNCH_HEIGHT: f64 = 0.0;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::Method;
    use crate::earth::Gravity;
    use crate::rotation::{EulerSequence, Frame};

    #[test]
    fn the_named_choices_are_the_cores_defaults() {
        assert_eq!(Method::parse(SIMULATE_METHOD).unwrap(), Method::default());
        assert_eq!(Method::parse(BATCH_METHOD).unwrap(), Method::Rk4);
        assert_eq!(GRAVITY.parse::<Gravity>().unwrap(), Gravity::default());
        assert_eq!(
            EulerSequence::new(EULER_SEQUENCE, true).unwrap().name(),
            "zxz"
        );
        assert_eq!(EULER_RATES_FRAME.parse::<Frame>().unwrap(), Frame::Body);
        assert_eq!(CONTACT_POINT_FRAME.parse::<Frame>().unwrap(), Frame::Space);
        assert_eq!(CUBATURE, CubatureOptions::default());
        let o = SIMULATE_TOLERANCES.options(true);
        assert!(o.validate().is_ok());
    }
}
