//! Closed-form solutions: the free symmetric top (the unit's 2.77–2.97), the free asymmetric
//! top (Jacobi elliptic functions and the integral of the third kind), Poinsot's construction
//! and the stability of rotation about the principal axes.

mod free_rigid_body;
mod free_symmetric_top;
mod poinsot_construction;
mod rotations;

pub use free_rigid_body::{check_moments, FreeRegime, FreeRigidBody};
pub use free_symmetric_top::{FreeSymmetricTop, TopShape};
pub use poinsot_construction::{axis_stability, AxisStability, Stability};
pub(crate) use rotations::{
    conj, hamilton, matrix_to_quaternion_unchecked as matrix_quaternion, normalized,
    quaternion_matrix, same_hemisphere,
};
