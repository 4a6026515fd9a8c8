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
