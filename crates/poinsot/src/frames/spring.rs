//! A particle tied to the common origin of the fixed and the rotating frame by an isotropic
//! linear spring (a free particle when the stiffness is zero): its force, its energy in the fixed
//! frame, its Jacobi integral in the rotating frame, and its motion integrated in a moving frame
//! with every fictitious force (eqs. 2.21, 2.26–2.28).

use super::kinematics::MovingFrame;
use super::motion::FrameMotion;
use super::particle::{simulate_particle_at, ParticleState};
use crate::error::{check_non_negative, check_positive, Result};
use crate::integrate::{Options, Scan};
use crate::Vec3;

/// A particle of `mass` m (kg) pulled towards the origin by the force F = −k r of an isotropic
/// linear spring of `stiffness` k (N/m); k = 0 is a free particle.
///
/// The spring's anchor is the origin shared by the fixed frame and a frame rotating about it
/// (R = 0), so F = −k r holds in either frame's components and the potential ½ k |r|² is the
/// same function of position in both. In the fixed frame the orbit is an ellipse centred on the
/// origin at the angular frequency √(k/m) (a straight line when k = 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpringParticle {
    mass: f64,
    stiffness: f64,
}

impl SpringParticle {
    /// A particle of `mass` (kg, > 0) on a spring of `stiffness` (N/m, ≥ 0). Errors name
    /// `mass` or `stiffness`.
    pub fn new(mass: f64, stiffness: f64) -> Result<Self> {
        check_positive("mass", mass)?;
        check_non_negative("stiffness", stiffness)?;
        Ok(Self { mass, stiffness })
    }

    /// The mass m (kg).
    pub fn mass(&self) -> f64 {
        self.mass
    }

    /// The stiffness k (N/m).
    pub fn stiffness(&self) -> f64 {
        self.stiffness
    }

    /// The spring force F = −k r (N) at `position` r (m), in the components of `position`.
    #[inline]
    pub fn force(&self, position: &Vec3) -> Vec3 {
        -self.stiffness * position
    }

    /// The acceleration F / m = −(k / m) r (m/s²) at `position` r (m): in the fixed frame, the
    /// particle's whole acceleration r̈' (eq. 2.25).
    #[inline]
    pub fn acceleration(&self, position: &Vec3) -> Vec3 {
        self.force(position) / self.mass
    }

    /// The potential energy U = ½ k |r|² (J).
    pub fn potential(&self, position: &Vec3) -> f64 {
        0.5 * self.stiffness * position.norm_squared()
    }

    /// The energy in the fixed frame, E = ½ m |ṙ'|² + ½ k |r'|² (J), from the fixed-frame
    /// `position` r' (m) and `velocity` ṙ' (m/s). Conserved along any motion (eq. 2.25).
    pub fn energy(&self, position: &Vec3, velocity: &Vec3) -> f64 {
        0.5 * self.mass * velocity.norm_squared() + self.potential(position)
    }

    /// The Jacobi integral in the rotating `frame`:
    ///
    /// J = ½ m |(dr/dt)_rot|² + ½ k |r|² − ½ m |ω × r|²  (J),
    ///
    /// from the relative `position` r (m) and `velocity` (dr/dt)_rot (m/s) in moving components.
    /// The last term is the potential of the centrifugal force −m ω × (ω × r) (eq. 2.28); the
    /// Coriolis force does no work in the rotating frame. J is conserved when the frame turns
    /// uniformly (ω̇ = 0) about its fixed origin (R = 0); with ω̇ ≠ 0 the Euler force makes it
    /// change. With ω = 0 it is [`SpringParticle::energy`].
    pub fn jacobi_integral(&self, frame: &MovingFrame, position: &Vec3, velocity: &Vec3) -> f64 {
        let w = frame.angular_velocity_moving();
        0.5 * self.mass * (velocity.norm_squared() - w.cross(position).norm_squared())
            + self.potential(position)
    }

    /// Integrates the particle relative to the moving `frame` from t = 0 to `duration` with every
    /// fictitious force ([`simulate_particle_at`]), the spring force taken in moving components,
    /// and returns the states `[r, (dr/dt)_rot]` (moving components) at `times` (monotone, in
    /// `[0, duration]`). `position` and `velocity` are r and (dr/dt)_rot at t = 0. Errors name
    /// `position`, `velocity`, `t_end` (a non-finite `duration`), `times` or an option of `opts`.
    pub fn simulate_at<M: FrameMotion + ?Sized>(
        &self,
        frame: &M,
        position: Vec3,
        velocity: Vec3,
        duration: f64,
        times: &[f64],
        opts: &Options,
    ) -> Result<Scan<ParticleState>> {
        simulate_particle_at(
            frame,
            self.mass,
            position,
            velocity,
            0.0,
            duration,
            times,
            |_t, r, _v| self.force(r),
            opts,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::frames::SteadyMotion;

    /// DOP853 at rtol 1e-12 over a few turns: positions agree with the closed forms to well
    /// below this (measured ~1e-11).
    const TRAJECTORY_TOL: f64 = 1e-9;
    /// Energy drift allowed at rtol 1e-12 (measured ~1e-13 relative).
    const DRIFT_TOL: f64 = 1e-10;

    fn table(rate: f64, rate_dot: f64) -> SteadyMotion {
        let f = MovingFrame::new(
            Vec3::zeros(),
            Vec3::zeros(),
            Vec3::zeros(),
            Vec3::new(0.0, 0.0, rate),
            Vec3::new(0.0, 0.0, rate_dot),
        )
        .unwrap();
        SteadyMotion::new(f).unwrap()
    }

    fn opts() -> Options {
        Options {
            rtol: 1e-12,
            atol: 1e-14,
            dense: false,
            ..Options::default()
        }
    }

    /// Integrates in the rotating frame and maps each sample back to the fixed frame.
    fn fixed_path(
        p: &SpringParticle,
        m: &SteadyMotion,
        r0: Vec3,
        v0_fixed: Vec3,
        times: &[f64],
    ) -> Vec<(Vec3, Vec3, Vec3, Vec3)> {
        let rel0 = m.at(0.0).to_moving(&r0, &v0_fixed, &Vec3::zeros());
        let scan = p
            .simulate_at(
                m,
                rel0.position,
                rel0.velocity,
                *times.last().unwrap(),
                times,
                &opts(),
            )
            .unwrap();
        times
            .iter()
            .zip(&scan.y)
            .map(|(&t, y)| {
                let (r, v) = (Vec3::new(y[0], y[1], y[2]), Vec3::new(y[3], y[4], y[5]));
                let f = m.at(t).to_fixed(&r, &v, &Vec3::zeros());
                (f.position, f.velocity, r, v)
            })
            .collect()
    }

    #[test]
    fn spring_orbit_seen_from_a_turntable_is_the_fixed_ellipse() {
        // Fixed frame: r'(t) = r₀ cos Ωt + (v₀/Ω) sin Ωt with Ω = √(k/m) (closed form).
        let p = SpringParticle::new(2.0, 4.5).unwrap();
        let big_omega = (4.5f64 / 2.0).sqrt();
        let (r0, v0) = (Vec3::new(0.8, 0.1, 0.0), Vec3::new(-0.2, 0.7, 0.1));
        let times: Vec<f64> = (1..=40).map(|i| 0.25 * i as f64).collect();
        for (rate, rate_dot) in [(1.3, 0.0), (-0.7, 0.4)] {
            for ((x, v, _, _), &t) in fixed_path(&p, &table(rate, rate_dot), r0, v0, &times)
                .iter()
                .zip(&times)
            {
                let exact = r0 * (big_omega * t).cos() + v0 * ((big_omega * t).sin() / big_omega);
                let exact_v =
                    -r0 * (big_omega * (big_omega * t).sin()) + v0 * (big_omega * t).cos();
                assert!(
                    (x - exact).norm() < TRAJECTORY_TOL,
                    "t = {t}: {x} vs {exact}"
                );
                assert!((v - exact_v).norm() < TRAJECTORY_TOL, "t = {t}");
            }
        }
    }

    #[test]
    fn free_particle_is_a_straight_line_in_the_fixed_frame_even_with_euler_force() {
        let p = SpringParticle::new(1.0, 0.0).unwrap();
        let (r0, v0) = (Vec3::new(0.8, 0.0, 0.0), Vec3::new(-0.5, 0.3, 0.0));
        let times: Vec<f64> = (1..=30).map(|i| 0.2 * i as f64).collect();
        for ((x, v, r, _), &t) in fixed_path(&p, &table(1.5, -0.3), r0, v0, &times)
            .iter()
            .zip(&times)
        {
            assert!((x - (r0 + v0 * t)).norm() < TRAJECTORY_TOL, "t = {t}");
            assert!((v - v0).norm() < TRAJECTORY_TOL, "t = {t}");
            // Negative control: in the rotating frame the path is not the straight line.
            if t > 1.0 {
                assert!((r - (r0 + v0 * t)).norm() > 0.1, "t = {t}");
            }
        }
    }

    #[test]
    fn energy_is_conserved_and_jacobi_only_while_the_table_turns_uniformly() {
        let p = SpringParticle::new(1.5, 2.0).unwrap();
        let (r0, v0) = (Vec3::new(0.6, 0.2, 0.0), Vec3::new(0.1, -0.4, 0.0));
        let times: Vec<f64> = (1..=50).map(|i| 0.2 * i as f64).collect();
        for (rate_dot, jacobi_conserved) in [(0.0, true), (0.25, false)] {
            let m = table(1.1, rate_dot);
            let e0 = p.energy(&r0, &v0);
            let rel0 = m.at(0.0).to_moving(&r0, &v0, &Vec3::zeros());
            let j0 = p.jacobi_integral(&m.at(0.0), &rel0.position, &rel0.velocity);
            let mut worst_j: f64 = 0.0;
            for ((x, v, r, rv), &t) in fixed_path(&p, &m, r0, v0, &times).iter().zip(&times) {
                assert!(((p.energy(x, v) - e0) / e0).abs() < DRIFT_TOL, "t = {t}");
                worst_j = worst_j.max((p.jacobi_integral(&m.at(t), r, rv) - j0).abs());
            }
            if jacobi_conserved {
                assert!(
                    worst_j < DRIFT_TOL * j0.abs().max(1.0),
                    "J drifted by {worst_j}"
                );
            } else {
                assert!(
                    worst_j > 1e-2,
                    "the Euler force must change J (got {worst_j})"
                );
            }
        }
    }

    #[test]
    fn jacobi_integral_without_rotation_is_the_energy_and_has_the_centrifugal_potential() {
        let p = SpringParticle::new(3.0, 0.5).unwrap();
        let (r, v) = (Vec3::new(0.3, -0.4, 0.2), Vec3::new(1.0, 2.0, -0.5));
        let still = MovingFrame::default();
        assert_eq!(p.jacobi_integral(&still, &r, &v), p.energy(&r, &v));
        // ω = 2 ẑ: |ω × r|² = 4 (x² + y²) = 1, so J = E − ½ m · 1.
        let turning = MovingFrame::rotating(Vec3::new(0.0, 0.0, 2.0)).unwrap();
        assert!((p.jacobi_integral(&turning, &r, &v) - (p.energy(&r, &v) - 1.5)).abs() < 1e-14);
        assert_eq!(p.force(&r), Vec3::new(-0.15, 0.2, -0.1));
        assert!((p.acceleration(&r) - Vec3::new(-0.05, 0.2 / 3.0, -0.1 / 3.0)).norm() < 1e-16);
    }

    #[test]
    fn bad_mass_and_stiffness_are_named() {
        assert_eq!(SpringParticle::new(0.0, 1.0).unwrap_err().argument, "mass");
        assert_eq!(
            SpringParticle::new(f64::NAN, 1.0).unwrap_err().argument,
            "mass"
        );
        assert_eq!(
            SpringParticle::new(1.0, -1.0).unwrap_err().argument,
            "stiffness"
        );
        assert_eq!(
            SpringParticle::new(1.0, f64::INFINITY)
                .unwrap_err()
                .argument,
            "stiffness"
        );
    }
}
