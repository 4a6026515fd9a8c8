//! The rotating Earth seen from a local frame on its surface (the unit's eqs. 2.29–2.42):
//! effective gravity, the Coriolis force, the falling body, projectiles, the Foucault
//! pendulum, inertial oscillations and the flow into a low; and the Earth as a rigid body
//! (`rigid`: Euler's free nutation, the Chandler period, the luni-solar precession and the
//! principal nutation).
//!
//! The local frame is ENU: x east, y north, z up; latitude λ is north-positive and the
//! Earth's angular velocity there is ω = ω (0, cos λ, sin λ) (eq. 2.33). The default rate
//! is sidereal, 7.2921150e-5 rad/s; [`Earth::solar_day`] uses the unit's 2π/86400.

mod fall;
mod pendulum;
mod pendulum_measurement;
mod pendulum_theory;
mod planet;
mod rigid;
mod rigid_pole;
mod rigid_simulate;
mod runs;
mod winds;
mod wobble;

pub use fall::{Fall, FallModel, Flight, Gravity};
pub use pendulum::{fit_precession_rate, FoucaultRun};
pub use pendulum_measurement::{
    FoucaultMeasurement, FoucaultRegime, Sense, UnitRateCheck, AMPLITUDE_TOLERANCE,
    MAX_TURN_PER_SWING, MAX_WOBBLE, MIN_TURNING_POINTS, SCATTER_TOLERANCE, STEADY_TOLERANCE,
    STILL_ANGLE, UNIT_RATE_TOLERANCE,
};
pub use pendulum_theory::{FoucaultModes, FoucaultTheory, LinearSwing};
pub use planet::{
    check_latitude, Earth, EffectiveGravity, MEAN_RADIUS, SIDEREAL_RATE, SOLAR_DAY_RATE,
    STANDARD_GRAVITY,
};
pub use rigid::{
    MeanOrbit, RigidEarth, ASTRONOMICAL_UNIT, DYNAMICAL_FLATTENING, GM_EARTH, GM_SUN,
    IAU2000A_PRINCIPAL_NUTATION, IAU2006_PRECESSION_RATE, MOON_EARTH_MASS_RATIO, MOON_ORBIT,
    OBLIQUITY_J2000, SUN_ORBIT,
};
pub use rigid_pole::{AveragedPole, NUTATION_SCALE};
pub use rigid_simulate::{
    fit_pole, PoleFit, PoleRun, SimulateOptions, MAX_STEP_FRACTION, POLE_BYTES_PER_SAMPLE,
    POLE_MAX_STEPS, POLE_MOON_NODE, POLE_SAMPLES,
};
pub use runs::{
    foucault_stretches, parcel_ring, FoucaultSwing, InertialSwing, LowFlow, LowSetup, DROP_SAMPLES,
    DROP_TOLERANCES, FOUCAULT_AMPLITUDE, FOUCAULT_AZIMUTH, FOUCAULT_BYTES_PER_SAMPLE,
    FOUCAULT_DURATION, FOUCAULT_LENGTH, FOUCAULT_MAX_STRETCHES, FOUCAULT_SAMPLES, FOUCAULT_STRETCH,
    FOUCAULT_TOLERANCES, INERTIAL_BYTES_PER_SAMPLE, INERTIAL_EQUATOR_DURATION, INERTIAL_PERIODS,
    INERTIAL_SAMPLES, INERTIAL_TOLERANCES, INERTIAL_VELOCITY, LOW_BYTES_PER_PARCEL_SAMPLE,
    LOW_BYTES_PER_SAMPLE, LOW_DURATION, LOW_FRICTION, LOW_PARCELS, LOW_PULL, LOW_RADIUS,
    LOW_SAMPLES, LOW_TOLERANCES, SENSE_THRESHOLD,
};
pub use winds::{InertialRun, LowRun};
pub use wobble::{
    fit_wobble, ChandlerPeriod, WobbleFit, WobbleTerm, ANNUAL_PERIOD, CHANDLER_SEARCH,
    POLAR_MOTION_SOURCE,
};
