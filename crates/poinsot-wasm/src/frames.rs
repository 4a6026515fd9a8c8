//! Bindings of `poinsot::frames`: a particle seen from a translating and rotating frame, its
//! fixed-frame acceleration split into the unit's terms (2.1–2.28).

use crate::convert::{finite, vec3, Out};
use poinsot::frames as fr;
use wasm_bindgen::prelude::wasm_bindgen;

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
    values: Vec<f64>,
}

#[wasm_bindgen]
impl FixedMotion {
    fn part(&self, k: usize) -> Vec<f64> {
        self.values[3 * k..3 * k + 3].to_vec()
    }
    /// Position in the fixed frame (m).
    #[wasm_bindgen(getter)]
    pub fn position(&self) -> Vec<f64> {
        self.part(0)
    }
    /// Velocity in the fixed frame (m/s).
    #[wasm_bindgen(getter)]
    pub fn velocity(&self) -> Vec<f64> {
        self.part(1)
    }
    /// Acceleration in the fixed frame (m/s²): the sum of the five terms.
    #[wasm_bindgen(getter)]
    pub fn acceleration(&self) -> Vec<f64> {
        self.part(2)
    }
    /// The relative acceleration term (m/s²).
    #[wasm_bindgen(getter)]
    pub fn relative(&self) -> Vec<f64> {
        self.part(3)
    }
    /// The acceleration of the moving origin (m/s²).
    #[wasm_bindgen(getter)]
    pub fn origin(&self) -> Vec<f64> {
        self.part(4)
    }
    /// The Coriolis term 2 ω × v (m/s²).
    #[wasm_bindgen(getter)]
    pub fn coriolis(&self) -> Vec<f64> {
        self.part(5)
    }
    /// The centripetal term ω × (ω × r) (m/s²).
    #[wasm_bindgen(getter)]
    pub fn centripetal(&self) -> Vec<f64> {
        self.part(6)
    }
    /// The Euler term ω̇ × r (m/s²).
    #[wasm_bindgen(getter)]
    pub fn euler(&self) -> Vec<f64> {
        self.part(7)
    }
}

#[wasm_bindgen]
impl MovingFrame {
    /// A moving frame from its origin (m), velocity (m/s), acceleration (m/s²), angular velocity
    /// (rad/s) and angular acceleration (rad/s²), each 3 numbers in fixed components.
    #[wasm_bindgen(constructor)]
    pub fn new(
        origin: &[f64],
        velocity: &[f64],
        acceleration: &[f64],
        angular_velocity: &[f64],
        angular_acceleration: &[f64],
    ) -> Out<MovingFrame> {
        let inner = fr::MovingFrame::new(
            vec3("origin", origin)?,
            vec3("velocity", velocity)?,
            vec3("acceleration", acceleration)?,
            vec3("angular_velocity", angular_velocity)?,
            vec3("angular_acceleration", angular_acceleration)?,
        )?;
        Ok(MovingFrame { inner })
    }

    /// The fixed-frame motion of a particle at `position` (m) with `velocity` (m/s) and
    /// `acceleration` (m/s²) relative to the moving frame.
    #[wasm_bindgen(js_name = toFixed)]
    pub fn to_fixed(
        &self,
        position: &[f64],
        velocity: &[f64],
        acceleration: &[f64],
    ) -> Out<FixedMotion> {
        let (r, v, a) = (
            vec3("position", position)?,
            vec3("velocity", velocity)?,
            vec3("acceleration", acceleration)?,
        );
        for (name, x) in [("position", &r), ("velocity", &v), ("acceleration", &a)] {
            poinsot::error::check_finite(name, x.as_slice())?;
        }
        let m = self.inner.to_fixed(&r, &v, &a);
        let t = &m.terms;
        let values: Vec<f64> = [
            m.position,
            m.velocity,
            m.acceleration,
            t.relative,
            t.origin,
            t.coriolis,
            t.centripetal,
            t.euler,
        ]
        .iter()
        .flat_map(|x| [x.x, x.y, x.z])
        .collect();
        Ok(FixedMotion {
            values: finite("acceleration", values)?,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn terms_sum_to_the_acceleration_and_coriolis_is_two_omega_cross_v() {
        let f =
            MovingFrame::new(&[0.0; 3], &[0.0; 3], &[0.0; 3], &[0.0, 0.0, 2.0], &[0.0; 3]).unwrap();
        let m = f
            .to_fixed(&[1.0, 0.0, 0.0], &[0.0, 3.0, 0.0], &[0.0; 3])
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
        let f =
            MovingFrame::new(&[0.0; 3], &[0.0; 3], &[0.0; 3], &[0.0, 0.0, 1.0], &[0.0; 3]).unwrap();
        assert!(f
            .to_fixed(&[f64::NAN, 0.0, 0.0], &[0.0; 3], &[0.0; 3])
            .unwrap_err()
            .message
            .starts_with("position"));
    }
}
