//! Euler's equations of motion (the unit's 2.67–2.76) and the attitude kinematics.
//!
//! In the body frame, `N = (dL/dt)_fix = I·ω̇ + ω × (I·ω)` (2.71; the unit's 2.70 lost the dot
//! of ω̇), which in principal axes reads (2.72)
//!
//! ```text
//! N₁ = I₁ω̇₁ + (I₃ − I₂) ω₂ω₃,   N₂ = I₂ω̇₂ + (I₁ − I₃) ω₃ω₁,   N₃ = I₃ω̇₃ + (I₂ − I₁) ω₁ω₂,
//! ```
//!
//! and the attitude quaternion q (body → space, `[w, x, y, z]`) follows `q̇ = ½ q ⊗ (0, ω)`.
//! Dotting 2.71 with ω gives the energy theorem `ω·N = dT/dt` (2.76).

use crate::rotation::Quaternion;
use crate::{Mat3, Vec3};

/// ω̇ from Euler's equations for a full inertia tensor (2.71):
/// `ω̇ = I⁻¹ (N − ω × I·ω)`, body components; `inverse` is `I⁻¹`.
#[inline]
pub fn angular_acceleration(inertia: &Mat3, inverse: &Mat3, omega: &Vec3, torque: &Vec3) -> Vec3 {
    inverse * (torque - omega.cross(&(inertia * omega)))
}

/// ω̇ from Euler's equations in principal axes (2.72), body components.
#[inline]
pub fn angular_acceleration_principal(moments: &[f64; 3], omega: &Vec3, torque: &Vec3) -> Vec3 {
    let [i1, i2, i3] = *moments;
    Vec3::new(
        (torque.x - (i3 - i2) * omega.y * omega.z) / i1,
        (torque.y - (i1 - i3) * omega.z * omega.x) / i2,
        (torque.z - (i2 - i1) * omega.x * omega.y) / i3,
    )
}

/// q̇ = ½ q ⊗ (0, ω) for body angular velocity ω (q body → space, `[w, x, y, z]`).
#[inline]
pub fn quaternion_rate(q: &Quaternion, omega: &Vec3) -> Quaternion {
    let [w, x, y, z] = *q;
    let (a, b, c) = (omega.x, omega.y, omega.z);
    [
        -0.5 * (x * a + y * b + z * c),
        0.5 * (w * a + y * c - z * b),
        0.5 * (w * b + z * a - x * c),
        0.5 * (w * c + x * b - y * a),
    ]
}

/// The power of the torque, ω·N = dT/dt (2.76) (W).
#[inline]
pub fn power(omega: &Vec3, torque: &Vec3) -> f64 {
    omega.dot(torque)
}

/// Euler's equations in principal axes with the divisions done once:
/// `ω̇₁ = k₁ ω₂ω₃ + N₁/I₁` with `k₁ = (I₂ − I₃)/I₁` and cyclically (2.72), and
/// `q̇ = ½ q ⊗ (0, ω)`, on the state `[ω₁, ω₂, ω₃, q_w, q_x, q_y, q_z]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct RigidRhs {
    k: [f64; 3],
    inv: [f64; 3],
}

impl RigidRhs {
    pub(crate) fn new(moments: &[f64; 3]) -> Self {
        let [i1, i2, i3] = *moments;
        Self {
            k: [(i2 - i3) / i1, (i3 - i1) / i2, (i1 - i2) / i3],
            inv: [1.0 / i1, 1.0 / i2, 1.0 / i3],
        }
    }

    #[inline(always)]
    fn eval(&self, y: &[f64; 7], n: &Vec3) -> [f64; 7] {
        let (w1, w2, w3) = (y[0], y[1], y[2]);
        let (qw, qx, qy, qz) = (y[3], y[4], y[5], y[6]);
        [
            self.k[0] * w2 * w3 + n.x * self.inv[0],
            self.k[1] * w3 * w1 + n.y * self.inv[1],
            self.k[2] * w1 * w2 + n.z * self.inv[2],
            -0.5 * (qx * w1 + qy * w2 + qz * w3),
            0.5 * (qw * w1 + qy * w3 - qz * w2),
            0.5 * (qw * w2 + qz * w1 - qx * w3),
            0.5 * (qw * w3 + qx * w2 - qy * w1),
        ]
    }

    /// One classic RK4 step of size `h` from `(t, y)`, the quaternion renormalised after it;
    /// `torque(t, ω, q)` gives N in principal body components.
    #[inline(always)]
    pub(crate) fn rk4_step<F: FnMut(f64, &Vec3, &Quaternion) -> Vec3>(
        &self,
        t: f64,
        y: &[f64; 7],
        h: f64,
        torque: &mut F,
    ) -> [f64; 7] {
        #[inline(always)]
        fn axpy(y: &[f64; 7], a: f64, k: &[f64; 7]) -> [f64; 7] {
            std::array::from_fn(|i| y[i] + a * k[i])
        }
        let mut n = |t: f64, y: &[f64; 7]| {
            torque(t, &Vec3::new(y[0], y[1], y[2]), &[y[3], y[4], y[5], y[6]])
        };
        let k1 = self.eval(y, &n(t, y));
        let y2 = axpy(y, 0.5 * h, &k1);
        let k2 = self.eval(&y2, &n(t + 0.5 * h, &y2));
        let y3 = axpy(y, 0.5 * h, &k2);
        let k3 = self.eval(&y3, &n(t + 0.5 * h, &y3));
        let y4 = axpy(y, h, &k3);
        let k4 = self.eval(&y4, &n(t + h, &y4));
        let h6 = h * (1.0 / 6.0);
        let mut out: [f64; 7] =
            std::array::from_fn(|i| y[i] + h6 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]));
        // Renormalise q by one Newton step for |q|⁻¹ about 1, (3 − |q|²)/2: |q|² − 1 is O(h⁵)
        // per step, so this leaves an error (|q|² − 1)² below round-off, and keeps a square root
        // and a division off the step's critical path.
        let n2 = out[3] * out[3] + out[4] * out[4] + out[5] * out[5] + out[6] * out[6];
        let f = 1.5 - 0.5 * n2;
        for v in &mut out[3..] {
            *v *= f;
        }
        out
    }
}
