//! Bindings of `poinsot::frames`: a particle seen from a translating and rotating frame, its
//! fixed-frame acceleration split into the unit's terms (2.1–2.28); the steady motion of a frame
//! (`MovingFrame.at`), and a particle on a spring (free when k = 0) integrated in a turning frame.

use crate::args::{count, let_numbers, number, numbers_each, vector, Count, Number, Numbers};
use crate::convert::Out;
use crate::{calls, fields};
use poinsot::frames as fr;
use wasm_bindgen::prelude::wasm_bindgen;

/// Bytes per time of `simulateParticle`: the copy of the time (8), the core's time and state
/// (8 + 48) and the flat output (48).
const BYTES_PER_TIME: usize = 8 + 8 + 48 + 48;

/// The state of a moving frame at one instant (vectors in fixed-frame components, axes
/// momentarily aligned with the fixed axes), as `poinsot.MovingFrame` in Python.
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct MovingFrame {
    inner: fr::MovingFrame,
}

/// A particle's motion seen in the fixed frame, with the acceleration split into the relative,
/// origin, Coriolis, centripetal and Euler terms (each 3 numbers, m/s²).
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct FixedMotion {
    inner: fr::FixedMotion,
}

fields!(FixedMotion {
    " Position in the fixed frame (m)."
    position position -> vector(position);
    " Velocity in the fixed frame (m/s)."
    velocity velocity -> vector(velocity);
    " Acceleration in the fixed frame (m/s²): the sum of the five terms."
    acceleration acceleration -> vector(acceleration);
    " The relative acceleration term (m/s²)."
    relative relative -> vector(terms.relative);
    " The acceleration of the moving origin (m/s²)."
    origin origin -> vector(terms.origin);
    " The Coriolis term 2 ω × v (m/s²)."
    coriolis coriolis -> vector(terms.coriolis);
    " The centripetal term ω × (ω × r) (m/s²)."
    centripetal centripetal -> vector(terms.centripetal);
    " The Euler term ω̇ × r (m/s²)."
    euler euler -> vector(terms.euler);
});

/// A particle's motion seen in the moving frame (moving components), with the relative
/// acceleration split into the true acceleration and the fictitious ones (each 3 numbers, m/s²),
/// as `MovingFrame.to_moving` in Python.
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct RelativeMotion {
    inner: fr::RelativeMotion,
}

fields!(RelativeMotion {
    " Position r in the moving frame (m)."
    position position -> vector(position);
    " Velocity (dr/dt)_rot (m/s)."
    velocity velocity -> vector(velocity);
    " Acceleration (d²r/dt²)_rot (m/s²): the sum of the five terms."
    acceleration acceleration -> vector(acceleration);
    " The true (inertial) acceleration r̈' (m/s²)."
    inertial inertial -> vector(terms.inertial);
    " −R̈, from the acceleration of the moving origin (m/s²)."
    translational translational -> vector(terms.translational);
    " The Coriolis term −2 ω × (dr/dt)_rot (m/s²)."
    coriolis coriolis -> vector(terms.coriolis);
    " The centrifugal term −ω × (ω × r) (m/s²)."
    centrifugal centrifugal -> vector(terms.centrifugal);
    " The Euler term −ω̇ × r (m/s²)."
    euler euler -> vector(terms.euler);
});

calls!(MovingFrame::new {
    " A moving frame from its origin (m), velocity (m/s), acceleration (m/s²), angular velocity"
    " (rad/s) and angular acceleration (rad/s²), each 3 numbers in fixed components."
    (
        origin: vector,
        velocity: vector,
        acceleration: vector,
        angular_velocity: vector,
        angular_acceleration: vector,
    ) = fr::MovingFrame::new;
});

#[wasm_bindgen]
impl MovingFrame {
    /// The state at time `t` (s) of the steady motion that starts from this state at t = 0:
    /// origin at constant acceleration, axes turning about the fixed axis of ω with constant ω̇
    /// (which must be parallel to ω), as `MovingFrame.at` in Python.
    pub fn at(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] t: Number,
    ) -> Out<MovingFrame> {
        let t = crate::free::time(&t)?;
        let motion = fr::SteadyMotion::new(self.inner)?;
        Ok(MovingFrame {
            inner: motion.state_at(t)?,
        })
    }
}

calls!(MovingFrame {
    " The fixed-frame motion of a particle at `position` (m) with `velocity` (m/s) and"
    " `acceleration` (m/s²) relative to the moving frame."
    toFixed to_fixed(position: vector, velocity: vector, acceleration: vector) -> FixedMotion;
    " The moving-frame motion (moving components) of a particle whose fixed-frame `position`"
    " (m), `velocity` (m/s) and `acceleration` (m/s²) are given: the inverse of `toFixed`."
    toMoving to_moving(position: vector, velocity: vector, acceleration: vector) -> RelativeMotion;
});

fields!(MovingFrame {
    " R, the moving origin (m)."
    origin origin -> vector(origin);
    " ω, the angular velocity (rad/s, fixed components)."
    angularVelocity angular_velocity -> vector(angular_velocity);
    " ω̇, the angular acceleration (rad/s², fixed components)."
    angularAcceleration angular_acceleration -> vector(angular_acceleration);
    " The moving axes as the columns of a rotation matrix in fixed components (9 numbers,"
    " row-major)."
    attitude attitude -> matrix(attitude);
});

/// A particle of mass m on an isotropic linear spring F = −k r anchored at the origin shared by
/// the fixed and the turning frame (a free particle when k = 0): its energies. The Python
/// equivalent is `simulate_particle(..., force=lambda t, r, v: -k * r)` and NumPy sums.
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct SpringParticle {
    inner: fr::SpringParticle,
}

calls!(SpringParticle::new {
    " A particle of `mass` (kg, > 0) on a spring of `stiffness` (N/m, ≥ 0)."
    (mass: number, stiffness: number) = fr::SpringParticle::new;
});

#[wasm_bindgen]
impl SpringParticle {
    /// The Jacobi integral ½ m |ṙ|² + ½ k |r|² − ½ m |ω × r|² (J) in the turning `frame`, from the
    /// relative `position` (m) and `velocity` (m/s) in moving components; conserved while ω̇ = 0.
    #[wasm_bindgen(js_name = jacobiIntegral)]
    pub fn jacobi_integral(
        &self,
        frame: &MovingFrame,
        #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] position: Numbers,
        #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] velocity: Numbers,
    ) -> Out<f64> {
        let (r, v) = state(&position, &velocity)?;
        Ok(self.inner.jacobi_integral(&frame.inner, &r, &v)?)
    }
}

calls!(SpringParticle {
    " The spring force −k r (N) at `position` (m), in the components of `position`."
    force force(position: vector) -> vector;
    " The acceleration F / m = −(k / m) r (m/s²) at `position` (m): the fixed-frame r̈'."
    acceleration acceleration(position: vector) -> vector;
    " The fixed-frame energy ½ m |ṙ'|² + ½ k |r'|² (J) from the fixed-frame `position` (m)"
    " and `velocity` (m/s)."
    energy energy(position: vector, velocity: vector) -> number;
});

/// Integrates a particle of `mass` (kg) on a spring of `stiffness` (N/m; 0: a free particle)
/// relative to `frame` (its state at t = 0 of a steady motion, as `simulate_particle` in Python)
/// from t = 0 to `duration` (s), with every fictitious force, and returns the states
/// `[x, y, z, vx, vy, vz]` (moving components, m and m/s) at the times `t_eval` (increasing, in
/// [0, duration]) one after another (6 numbers per time). `position` and `velocity` are r and
/// (dr/dt)_rot at t = 0. Tolerances: the core's defaults (`frames::PARTICLE_TOLERANCES`), as in
/// Python.
#[wasm_bindgen(js_name = simulateParticle)]
pub fn simulate_particle(
    frame: &MovingFrame,
    #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] position: Numbers,
    #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] velocity: Numbers,
    #[wasm_bindgen(unchecked_param_type = "number")] duration: Number,
    #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] t_eval: Numbers,
    #[wasm_bindgen(unchecked_param_type = "number")] mass: Number,
    #[wasm_bindgen(unchecked_param_type = "number")] stiffness: Number,
) -> Out<Vec<f64>> {
    let_numbers!(mass, stiffness);
    let particle = fr::SpringParticle::new(mass, stiffness)?;
    let (r0, v0) = state(&position, &velocity)?;
    let duration = number("duration", &duration)?;
    let t_eval = numbers_each("t_eval", &t_eval, BYTES_PER_TIME)?;
    let motion = fr::SteadyMotion::new(frame.inner)?;
    let scan = particle.simulate_at(&motion, r0, v0, duration, &t_eval)?;
    Ok(scan.y.iter().flatten().copied().collect())
}

/// A particle's `position` and `velocity` (3 numbers each) as core vectors.
fn state(position: &Numbers, velocity: &Numbers) -> Out<(poinsot::Vec3, poinsot::Vec3)> {
    Ok((vector("position", position)?, vector("velocity", velocity)?))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convert::refused;

    #[test]
    fn terms_sum_to_the_acceleration_and_coriolis_is_two_omega_cross_v() {
        let f = table(2.0, 0.0);
        let m = f
            .to_fixed(vec![1.0, 0.0, 0.0], vec![0.0, 3.0, 0.0], vec![0.0; 3])
            .unwrap();
        assert_eq!(m.coriolis(), vec![-12.0, 0.0, 0.0]);
        assert_eq!(m.centripetal(), vec![-4.0, 0.0, 0.0]);
        let sum: Vec<f64> = (0..3)
            .map(|i| {
                m.relative()[i]
                    + m.origin()[i]
                    + m.coriolis()[i]
                    + m.centripetal()[i]
                    + m.euler()[i]
            })
            .collect();
        assert_eq!(sum, m.acceleration());
    }

    #[test]
    fn non_finite_particle_state_is_refused() {
        let f = table(1.0, 0.0);
        assert!(f
            .to_fixed(vec![f64::NAN, 0.0, 0.0], vec![0.0; 3], vec![0.0; 3])
            .unwrap_err()
            .message
            .starts_with("position"));
    }

    #[test]
    fn the_constructor_made_by_calls_names_each_vector() {
        let three = || vec![0.0; 3];
        let names = [
            "origin",
            "velocity",
            "acceleration",
            "angular_velocity",
            "angular_acceleration",
        ];
        for (i, name) in names.into_iter().enumerate() {
            let mut v: Vec<Vec<f64>> = (0..5).map(|_| three()).collect();
            v[i] = vec![0.0; 2];
            let [a, b, c, d, f] = <[Vec<f64>; 5]>::try_from(v).unwrap();
            refused(
                MovingFrame::new(a, b, c, d, f),
                &format!("{name}: must hold 3"),
            );
        }
    }

    fn table(rate: f64, rate_dot: f64) -> MovingFrame {
        MovingFrame::new(
            vec![0.0; 3],
            vec![0.0; 3],
            vec![0.0; 3],
            vec![0.0, 0.0, rate],
            vec![0.0, 0.0, rate_dot],
        )
        .unwrap()
    }

    #[test]
    fn steady_attitude_turns_by_omega_t_plus_half_omega_dot_t_squared() {
        let (rate, rate_dot, t) = (1.2, -0.3, 2.5);
        let a = table(rate, rate_dot).at(t).unwrap();
        let angle: f64 = rate * t + 0.5 * rate_dot * t * t;
        let (c, s) = (angle.cos(), angle.sin());
        // Row-major, columns are the moving axes: î = (c, s, 0), ĵ = (−s, c, 0).
        let want = [c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0];
        for (x, y) in a.attitude().iter().zip(want) {
            assert!((x - y).abs() < 1e-15, "{:?}", a.attitude());
        }
        assert!((a.angular_velocity()[2] - (rate + rate_dot * t)).abs() < 1e-15);
        assert_eq!(a.angular_acceleration(), vec![0.0, 0.0, rate_dot]);
    }

    #[test]
    fn to_moving_inverts_to_fixed_and_its_terms_are_the_fictitious_ones() {
        let f = table(0.7, 0.4).at(1.3).unwrap();
        let (r, v, a) = ([0.3, -0.2, 0.1], [0.5, 0.25, -0.1], [0.05, 0.0, 0.2]);
        let fixed = f.to_fixed(r.to_vec(), v.to_vec(), a.to_vec()).unwrap();
        let back = f
            .to_moving(fixed.position(), fixed.velocity(), fixed.acceleration())
            .unwrap();
        for (x, y) in back
            .position()
            .iter()
            .chain(&back.velocity())
            .chain(&back.acceleration())
            .zip(r.iter().chain(&v).chain(&a))
        {
            assert!((x - y).abs() < 1e-14);
        }
        // Negative control: with ω = 0 the Coriolis and centrifugal terms vanish.
        let still = table(0.0, 0.0);
        let m = still.to_moving(r.to_vec(), v.to_vec(), a.to_vec()).unwrap();
        assert_eq!(m.coriolis(), vec![0.0; 3]);
        assert_eq!(m.centrifugal(), vec![0.0; 3]);
    }

    #[test]
    fn simulated_free_particle_is_straight_in_the_fixed_frame() {
        let f0 = table(1.5, 0.2);
        let (r0, v0) = ([0.8, 0.0, 0.0], [-0.4, 0.3, 0.0]);
        let rel = f0
            .to_moving(r0.to_vec(), v0.to_vec(), vec![0.0; 3])
            .unwrap();
        let t = 3.0;
        let y = simulate_particle(
            &f0,
            rel.position(),
            rel.velocity(),
            t,
            vec![0.0, t],
            1.0,
            0.0,
        )
        .unwrap();
        assert_eq!(y.len(), 12);
        assert_eq!(
            &y[..6],
            &[0.8, 0.0, 0.0, rel.velocity()[0], rel.velocity()[1], 0.0][..]
        );
        let fixed = f0
            .at(t)
            .unwrap()
            .to_fixed(y[6..9].to_vec(), y[9..12].to_vec(), vec![0.0; 3])
            .unwrap();
        for i in 0..3 {
            // DOP853 at rtol 1e-10 over ~5 rad: ~1e-10 (measured 2e-11).
            assert!((fixed.position()[i] - (r0[i] + v0[i] * t)).abs() < 1e-8);
        }
    }

    #[test]
    fn bad_arguments_of_the_turning_frame_are_named() {
        let tilted = MovingFrame::new(
            vec![0.0; 3],
            vec![0.0; 3],
            vec![0.0; 3],
            vec![0.0, 0.0, 1.0],
            vec![1.0, 0.0, 0.0],
        )
        .unwrap();
        refused(tilted.at(1.0), "angular_acceleration");
        refused(table(1.0, 0.0).at(f64::NAN), "t:");
        let f = table(1.0, 0.0);
        let run = |d: f64, times: Vec<f64>, m: f64, k: f64| {
            simulate_particle(&f, vec![1.0, 0.0, 0.0], vec![0.0; 3], d, times, m, k).unwrap_err()
        };
        assert!(run(-1.0, vec![0.0], 1.0, 0.0)
            .message
            .starts_with("duration"));
        assert!(run(1.0, vec![2.0], 1.0, 0.0).message.starts_with("t_eval"));
        assert!(run(1.0, vec![1.0], 0.0, 0.0).message.starts_with("mass"));
        let e = run(1.0, vec![1.0], 1.0, -2.0);
        assert!(e.message.starts_with("stiffness") && e.name == "PoinsotError");
        let p = SpringParticle::new(1.0, 2.0).unwrap();
        refused(p.force(vec![1.0, f64::NAN, 0.0]), "position");
        assert!(p
            .energy(vec![1.0, 0.0], vec![0.0; 3])
            .unwrap_err()
            .message
            .starts_with("position"));
        // A NaN in the state names the argument (it used to surface as "energy: the result is
        // not finite", naming no argument).
        assert!(p
            .energy(vec![f64::NAN, 0.0, 0.0], vec![0.0; 3])
            .unwrap_err()
            .message
            .starts_with("position: must be finite"));
        assert!(p
            .jacobi_integral(
                &table(1.0, 0.0),
                vec![0.0; 3],
                vec![0.0, f64::INFINITY, 0.0]
            )
            .unwrap_err()
            .message
            .starts_with("velocity: must be finite"));
        // Results beyond the doubles are refused by the core, naming the argument (the
        // binding guarded them itself before).
        let stiff = SpringParticle::new(1.0, 1e308).unwrap();
        let e = stiff.force(vec![10.0, 0.0, 0.0]).unwrap_err();
        assert_eq!(e.name, "PoinsotError");
        assert!(
            e.message
                .starts_with("position: the result (force) is not a finite number"),
            "{}",
            e.message
        );
        refused(
            p.energy(vec![1.0, 0.0, 0.0], vec![1e200, 0.0, 0.0]),
            "velocity: the result (energy)",
        );
        refused(table(1.0, 0.2).at(1e300), "t: the frame's");
        // ½·2·1² + ½·1·(1² − (2·1)²) at ω = 2 ẑ, r = x̂, v = ŷ: 1 + ½(1 − 4) = −0.5.
        let j = p
            .jacobi_integral(&table(2.0, 0.0), vec![1.0, 0.0, 0.0], vec![0.0, 1.0, 0.0])
            .unwrap();
        assert_eq!(j, -0.5);
    }
}

/// `samples` evenly spaced times (s) from `t0` to `t_end`, both ends included: the core's one
/// grid (`poinsot::integrate::sample_times`, the one Python's runs use), so that the lab samples
/// a run exactly where Python does. `samples` is a whole number ≥ 2 within the memory budget;
/// errors name `t0`, `t_end` or `samples`.
#[wasm_bindgen(js_name = sampleTimes)]
pub fn sample_times(
    #[wasm_bindgen(unchecked_param_type = "number")] t0: Number,
    #[wasm_bindgen(unchecked_param_type = "number")] t_end: Number,
    #[wasm_bindgen(unchecked_param_type = "number")] samples: Count,
) -> Out<Vec<f64>> {
    let (t0, t_end) = (number("t0", &t0)?, number("t_end", &t_end)?);
    let n = count("samples", &samples, 8)?;
    Ok(poinsot::integrate::sample_times(t0, t_end, n, 8)?)
}
