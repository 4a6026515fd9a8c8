//! Rotations of rigid bodies: SO(3), quaternions, Euler angles, Euler's and Chasles' theorems,
//! and the kinematics of Euler angles (the unit's eqs. 2.98–2.99).
//!
//! Conventions (pinned by tests, see `CONVENTIONS.md`):
//! - rotations are **active** and right-handed: `R` maps body-fixed components to space
//!   components, `x_space = R x_body`; the elementary rotation `R_z(φ)` turns `e_x` towards `e_y`;
//! - quaternions are **scalar-first** `[w, x, y, z]`, `q = [cos(θ/2), sin(θ/2) n]`;
//! - Euler angles: a lowercase three-letter sequence plus an explicit `intrinsic` flag (never
//!   letter case). Intrinsic `(a, b, c)` with angles `(α, β, γ)` means
//!   `R = R_a(α) R_b(β) R_c(γ)`; extrinsic means `R = R_c(γ) R_b(β) R_a(α)`. The unit's default is
//!   intrinsic `zxz`: `R = R_z(φ) R_x(θ) R_z(ψ)`;
//! - rotation matrices are stored row-major in the batch kernels (`[R00, R01, R02, R10, ...]`).
//!
//! Facets, one file each: `matrix` (validation, elementary rotations, composition),
//! `quaternion`, `euler` (the 24 conventions and the conversions), `axis_angle` (Euler's
//! theorem), `screw` (Chasles' theorem), `euler_kinematics` (2.98–2.99), `batch` (kernels
//! over slices, parallel with rayon) and `lanes` (quaternion algebra on SIMD lanes).

mod axis_angle;
mod batch;
mod euler;
mod euler_kinematics;
mod lanes;
mod matrix;
mod quaternion;
mod screw;

pub use axis_angle::{axis_angle_to_matrix, rotation_axis, IDENTITY_AXIS};
pub use batch::{
    angular_velocity_batch, axis_angle_to_matrix_batch, check_rotation_matrix_batch,
    euler_rates_batch, euler_to_matrix_batch, matrix_to_euler_batch, matrix_to_quaternion_batch,
    quaternion_multiply_batch, quaternion_to_matrix_batch, rotate_vectors_batch,
    rotation_axis_batch,
};
pub use euler::{
    euler_to_matrix, matrix_to_euler, Axis, EulerAngles, EulerSequence, SequenceKind,
    EULER_LOCK_TOL,
};
pub use euler_kinematics::{
    angular_velocity, angular_velocity_matrix, body_angular_velocity, euler_rates,
    space_angular_velocity, Frame, RATES_LOCK_TOL,
};
pub(crate) use lanes::{
    hamilton_lanes, matrix_to_quaternion_lanes, normalized_lanes, quaternion_to_matrix_lanes,
    QuatLanes,
};
pub(crate) use matrix::row_major;
pub use matrix::{
    check_rotation_matrix, check_rotation_matrix_named, compose, elementary_rotation, rot_x, rot_y,
    rot_z, rotate_vectors, NEAREST_ROTATION_DEFECT, ROTATION_MATRIX_TOL,
};
pub(crate) use quaternion::{
    axis_angle_quaternion, conj, coordinate_quaternion, hamilton, matrix_to_quaternion_any_sign,
    normalized, quaternion_rotate_unchecked, quaternion_to_mat3_unchecked, same_hemisphere,
};
pub use quaternion::{
    check_quaternion, matrix_to_quaternion, quaternion_multiply, quaternion_normalize,
    quaternion_rotate, quaternion_to_matrix, Quaternion, QUATERNION_UNIT_TOL,
};
pub use screw::{screw_axis, Screw, POINT_ALONG_TOL, SCREW_PITCH_RTOL, TRANSLATION_ANGLE_TOL};
