//! Moving frames: kinematics of a particle seen from a translating and rotating frame, the
//! fictitious forces, and particle motion integrated in a time-dependent frame
//! (the unit's eqs. 2.1–2.28).
//!
//! Notation of the unit: primed quantities belong to the fixed (inertial) frame, unprimed to
//! the moving frame; `R` is the moving origin, `ω` the moving frame's angular velocity.

mod defaults;
mod kinematics;
mod motion;
mod particle;
mod spring;

pub use defaults::{
    PARTICLE_BYTES_PER_SAMPLE, PARTICLE_MASS, PARTICLE_SAMPLES, PARTICLE_TOLERANCES,
};
pub use kinematics::{
    AccelerationTerms, FictitiousForces, FictitiousTerms, FixedMotion, MovingFrame, RelativeMotion,
};
pub use motion::{FrameMotion, SteadyMotion};
pub use particle::{
    simulate_particle, simulate_particle_at, simulate_particle_fixed, ParticleState,
};
pub use spring::SpringParticle;
