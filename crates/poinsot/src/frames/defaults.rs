//! The defaults of a particle integrated in a moving frame, as the front ends run it
//! (`poinsot.simulate_particle` in Python, `simulateParticle` in the browser lab): written once
//! here so that they cannot differ.

use crate::integrate::Tolerances;

/// Tolerances of a particle in a moving frame: rtol 1e-10, atol 1e-12 (m, m/s), 10⁶ steps
/// (DOP853; a free particle's straight line to ~1e-10 m over a few turns).
pub const PARTICLE_TOLERANCES: Tolerances = Tolerances {
    rtol: 1e-10,
    atol: 1e-12,
    max_steps: 1_000_000,
};
/// The default mass of the particle (kg).
pub const PARTICLE_MASS: f64 = 1.0;
/// The default number of evenly spaced output times, both ends included.
pub const PARTICLE_SAMPLES: usize = 1001;
/// Bytes per output time of a particle's run: the time and the state (8 + 48).
pub const PARTICLE_BYTES_PER_SAMPLE: usize = 8 + 48;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_make_the_options_of_a_scan() {
        let o = PARTICLE_TOLERANCES.options(false);
        assert_eq!(
            (o.rtol, o.atol, o.max_steps, o.dense),
            (1e-10, 1e-12, 1_000_000, false)
        );
        assert!(crate::integrate::sample_times(
            0.0,
            1.0,
            PARTICLE_SAMPLES,
            PARTICLE_BYTES_PER_SAMPLE
        )
        .is_ok());
    }
}
