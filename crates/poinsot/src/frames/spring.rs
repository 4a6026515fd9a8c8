//! A particle tied to the common origin of the fixed and the rotating frame by an isotropic
//! linear spring (a free particle when the stiffness is zero): its force, its energy in the fixed
//! frame, its Jacobi integral in the rotating frame, and its motion integrated in a moving frame
//! with every fictitious force (eqs. 2.21, 2.26–2.28).

use super::defaults::PARTICLE_TOLERANCES;
use super::kinematics::MovingFrame;
use super::motion::FrameMotion;
use super::particle::{simulate_particle_at, ParticleState};
use crate::error::{check_finite, check_non_negative, check_positive, check_result, Result};
use crate::integrate::Scan;
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
    /// Errors name `position`: not finite, or a force beyond the doubles (k |r| > ~1.8e308).
    #[inline]
    pub fn force(&self, position: &Vec3) -> Result<Vec3> {
        let f = self.force_unchecked(position);
        if !all_finite(f.as_slice()) {
            // A non-finite position gives a non-finite force: say which.
            check_finite("position", position.as_slice())?;
            check_result("position", "force", f.as_slice())?;
        }
        Ok(f)
    }

    /// [`SpringParticle::force`] without the checks: the hot path of the integrators (the state
    /// they pass is checked by the integrator itself).
    #[inline]
    pub fn force_unchecked(&self, position: &Vec3) -> Vec3 {
        -self.stiffness * position
    }

    /// The acceleration F / m = −(k / m) r (m/s²) at `position` r (m): in the fixed frame, the
    /// particle's whole acceleration r̈' (eq. 2.25). Errors name `position` (as
    /// [`SpringParticle::force`]).
    #[inline]
    pub fn acceleration(&self, position: &Vec3) -> Result<Vec3> {
        let a = self.force_unchecked(position) / self.mass;
        if !all_finite(a.as_slice()) {
            check_finite("position", position.as_slice())?;
            check_result("position", "acceleration", a.as_slice())?;
        }
        Ok(a)
    }

    /// The potential energy U = ½ k |r|² (J). Errors name `position`: not finite, or U beyond
    /// the doubles.
    #[inline]
    pub fn potential(&self, position: &Vec3) -> Result<f64> {
        let u = self.potential_unchecked(position);
        if !u.is_finite() {
            check_finite("position", position.as_slice())?;
            check_result("position", "potential", &[u])?;
        }
        Ok(u)
    }

    fn potential_unchecked(&self, position: &Vec3) -> f64 {
        0.5 * self.stiffness * position.norm_squared()
    }

    /// The energy in the fixed frame, E = ½ m |ṙ'|² + ½ k |r'|² (J), from the fixed-frame
    /// `position` r' (m) and `velocity` ṙ' (m/s). Conserved along any motion (eq. 2.25).
    /// Errors name `position` or `velocity`: not finite, or the term they give (½ k |r|², ½ m
    /// |v|²) beyond the doubles; a sum beyond them names `position`.
    #[inline]
    pub fn energy(&self, position: &Vec3, velocity: &Vec3) -> Result<f64> {
        self.energy_with(position, velocity, 0.0, "energy")
    }

    /// The Jacobi integral in the rotating `frame`:
    ///
    /// J = ½ m |(dr/dt)_rot|² + ½ k |r|² − ½ m |ω × r|²  (J),
    ///
    /// from the relative `position` r (m) and `velocity` (dr/dt)_rot (m/s) in moving components.
    /// The last term is the potential of the centrifugal force −m ω × (ω × r) (eq. 2.28); the
    /// Coriolis force does no work in the rotating frame. J is conserved when the frame turns
    /// uniformly (ω̇ = 0) about its fixed origin (R = 0); with ω̇ ≠ 0 the Euler force makes it
    /// change. With ω = 0 it is [`SpringParticle::energy`]. Errors as
    /// [`SpringParticle::energy`] (the centrifugal term's overflow names `position`).
    #[inline]
    pub fn jacobi_integral(
        &self,
        frame: &MovingFrame,
        position: &Vec3,
        velocity: &Vec3,
    ) -> Result<f64> {
        let w = frame.angular_velocity_moving();
        self.energy_with(
            position,
            velocity,
            w.cross(position).norm_squared(),
            "Jacobi integral",
        )
    }

    /// ½ m (|v|² − `c2`) + ½ k |r|² (J), checked (only when it is not finite: the fast path is
    /// one test): the arguments finite, then the potential (naming `position`), the kinetic
    /// energy (`velocity`), then the whole (`position`: the centrifugal term ½ m `c2` or the
    /// sum).
    #[inline]
    fn energy_with(&self, position: &Vec3, velocity: &Vec3, c2: f64, what: &str) -> Result<f64> {
        let u = self.potential_unchecked(position);
        let v2 = velocity.norm_squared();
        let e = 0.5 * self.mass * (v2 - c2) + u;
        if !e.is_finite() {
            // A finite E has finite terms and arguments; otherwise blame the first culprit.
            check_finite("position", position.as_slice())?;
            check_finite("velocity", velocity.as_slice())?;
            check_result("position", what, &[u])?;
            check_result("velocity", what, &[0.5 * self.mass * v2])?;
            check_result("position", what, &[e])?;
        }
        Ok(e)
    }

    /// Integrates the particle relative to the moving `frame` from t = 0 to `duration` (s) with
    /// every fictitious force ([`simulate_particle_at`]) and the core's default tolerances
    /// ([`PARTICLE_TOLERANCES`], as the browser lab runs it), the spring force taken in moving
    /// components, and returns the states `[r, (dr/dt)_rot]` (moving components) at `t_eval`
    /// (monotone, in `[0, duration]`). `position` and `velocity` are r and (dr/dt)_rot at t = 0.
    /// Errors name `position` (also a spring force beyond the doubles), `velocity`, `frame`,
    /// `duration` (also a run longer than the default step limit, which the caller did not
    /// choose) or `t_eval`.
    pub fn simulate_at<M: FrameMotion + ?Sized>(
        &self,
        frame: &M,
        position: Vec3,
        velocity: Vec3,
        duration: f64,
        t_eval: &[f64],
    ) -> Result<Scan<ParticleState>> {
        self.force(&position)?;
        let opts = PARTICLE_TOLERANCES.options(false);
        simulate_particle_at(
            frame,
            self.mass,
            position,
            velocity,
            duration,
            t_eval,
            |_t, r, _v| self.force_unchecked(r),
            &opts,
        )
        .map_err(|mut e| {
            if e.argument == "max_steps" {
                e.argument = "duration".into();
                e.message = format!(
                    "too long for the default step limit ({} steps): {}",
                    opts.max_steps, e.message
                );
            }
            e
        })
    }
}

/// Whether every value is finite.
#[inline]
fn all_finite(values: &[f64]) -> bool {
    values.iter().all(|v| v.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::frames::SteadyMotion;
    use crate::integrate::Options;

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
        let rel0 = m.at(0.0).to_moving(&r0, &v0_fixed, &Vec3::zeros()).unwrap();
        let scan = simulate_particle_at(
            m,
            p.mass(),
            rel0.position,
            rel0.velocity,
            *times.last().unwrap(),
            times,
            |_t, r, _v| p.force_unchecked(r),
            &opts(),
        )
        .unwrap();
        times
            .iter()
            .zip(&scan.y)
            .map(|(&t, y)| {
                let (r, v) = (Vec3::new(y[0], y[1], y[2]), Vec3::new(y[3], y[4], y[5]));
                let f = m.at(t).to_fixed(&r, &v, &Vec3::zeros()).unwrap();
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
            let e0 = p.energy(&r0, &v0).unwrap();
            let rel0 = m.at(0.0).to_moving(&r0, &v0, &Vec3::zeros()).unwrap();
            let j0 = p
                .jacobi_integral(&m.at(0.0), &rel0.position, &rel0.velocity)
                .unwrap();
            let mut worst_j: f64 = 0.0;
            for ((x, v, r, rv), &t) in fixed_path(&p, &m, r0, v0, &times).iter().zip(&times) {
                assert!(
                    ((p.energy(x, v).unwrap() - e0) / e0).abs() < DRIFT_TOL,
                    "t = {t}"
                );
                worst_j = worst_j.max((p.jacobi_integral(&m.at(t), r, rv).unwrap() - j0).abs());
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
        assert!(
            (p.jacobi_integral(&turning, &r, &v).unwrap() - (p.energy(&r, &v).unwrap() - 1.5))
                .abs()
                < 1e-14
        );
        assert_eq!(p.force(&r), Ok(Vec3::new(-0.15, 0.2, -0.1)));
        assert!(
            (p.acceleration(&r).unwrap() - Vec3::new(-0.05, 0.2 / 3.0, -0.1 / 3.0)).norm() < 1e-16
        );
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

    /// Finite or refused: a stiffness or a state so large that a result overflows is an error
    /// naming the argument it comes from, never ±inf (the bindings guarded this before).
    #[test]
    fn results_beyond_the_doubles_name_the_argument() {
        let stiff = SpringParticle::new(1.0, 1e308).unwrap();
        let r = Vec3::new(10.0, 0.0, 0.0);
        for e in [
            stiff.force(&r).unwrap_err(),
            stiff.acceleration(&r).unwrap_err(),
        ] {
            assert_eq!(e.argument, "position");
            assert!(e.message.starts_with("the result ("), "{e}");
        }
        assert!(stiff
            .acceleration(&r)
            .unwrap_err()
            .to_string()
            .starts_with("position: the result (acceleration) is not a finite number"));
        assert_eq!(stiff.potential(&r).unwrap_err().argument, "position");
        let p = SpringParticle::new(1.0, 1.0).unwrap();
        let fast = Vec3::new(1e200, 0.0, 0.0);
        assert_eq!(
            p.energy(&Vec3::x(), &fast).unwrap_err().argument,
            "velocity"
        );
        assert!(p
            .energy(&Vec3::new(f64::NAN, 0.0, 0.0), &Vec3::zeros())
            .unwrap_err()
            .to_string()
            .starts_with("position: must be finite, got NaN"));
        // The centrifugal term alone overflows: blamed on the position.
        let spinning = MovingFrame::rotating(Vec3::new(0.0, 0.0, 1e160)).unwrap();
        let e = p
            .jacobi_integral(&spinning, &Vec3::new(1e160, 0.0, 0.0), &Vec3::zeros())
            .unwrap_err();
        assert_eq!(e.argument, "position");
        // Negative control: ordinary magnitudes give the closed forms.
        assert!((stiff.force(&Vec3::new(1e-10, 0.0, 0.0)).unwrap().x + 1e298).abs() < 1e284);
        assert_eq!(p.energy(&Vec3::x(), &Vec3::y()).unwrap(), 1.0);
    }

    /// The run with the core's defaults (the lab's) names the caller's arguments: `t_eval`
    /// outside the run, a negative `duration`, and a run longer than the default step limit
    /// (which the caller did not choose) as `duration`.
    #[test]
    fn the_default_run_names_the_callers_arguments() {
        let p = SpringParticle::new(1.0, 4.0).unwrap();
        let m = table(1.0, 0.0);
        let run = |d: f64, t: &[f64]| p.simulate_at(&m, Vec3::x(), Vec3::zeros(), d, t);
        assert_eq!(run(1.0, &[2.0]).unwrap_err().argument, "t_eval");
        assert_eq!(run(-1.0, &[0.0]).unwrap_err().argument, "duration");
        assert_eq!(run(f64::NAN, &[0.0]).unwrap_err().argument, "duration");
        let e = run(1e9, &[1e9]).unwrap_err();
        assert_eq!(e.argument, "duration", "{e}");
        assert!(
            e.message.starts_with("too long for the default step limit"),
            "{e}"
        );
        let stiff = SpringParticle::new(1.0, 1e308).unwrap();
        let e = stiff
            .simulate_at(&m, Vec3::new(10.0, 0.0, 0.0), Vec3::zeros(), 1.0, &[1.0])
            .unwrap_err();
        assert_eq!(e.argument, "position");
        // Negative control: the same run within range; at t = π/2 the spring (ω = 2 rad/s in
        // the fixed frame) has swung through half a period.
        let y = run(1.0, &[0.0, 1.0]).unwrap().y;
        assert_eq!(y[0][0], 1.0);
    }
}
