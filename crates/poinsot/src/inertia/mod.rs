//! Mass properties of rigid bodies (the unit's 2.43–2.66): the inertia tensor with its
//! validation, parallel-axis shift, rotation, principal axes and kind of top ([`tensor`]); bodies,
//! their composition, angular momentum, kinetic energy and holding torque ([`body`]); the
//! standard solids ([`shapes`]); continuous densities by adaptive cubature ([`density`]); and
//! closed triangle meshes by exact polyhedral integrals ([`mesh`]).
//!
//! Sign convention: products of inertia negated, `I_xy = −Σ m x y` (2.49), so `L = I·ω` (2.63);
//! tensors are stored about the centre of mass in body axes; principal moments ascending,
//! principal axes a proper rotation.

pub mod body;
pub mod density;
pub mod mesh;
mod mesh_embedding;
mod scaling;
pub mod shapes;
pub mod tensor;

pub use body::MassProperties;
pub use density::{density_mass_properties, CubatureOptions, DensityIntegral};
pub use mesh::{mesh_mass_properties, mesh_mass_properties_rows, FaceIndex};
pub use shapes::{
    cuboid, ellipsoid, solid_cone, solid_cylinder, solid_sphere, spherical_shell, thin_disk,
    thin_ring, thin_rod,
};
pub use tensor::{
    check_inertia, check_inertia_scaled, classify, principal, Principal, TopKind, DEFAULT_KIND_RTOL,
};
