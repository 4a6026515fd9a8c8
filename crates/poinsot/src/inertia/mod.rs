//! Mass properties of rigid bodies (the unit's 2.43–2.66): the inertia tensor with its
//! validation, parallel-axis shift, rotation, principal axes and kind of top (`tensor`); bodies,
//! their composition, angular momentum, kinetic energy and holding torque (`body`,
//! [`MassProperties`]); the standard solids (`shapes`); continuous densities by adaptive
//! cubature (`density`, [`density_mass_properties`]); and closed triangle meshes by exact
//! polyhedral integrals (`mesh`, [`mesh_mass_properties`]). The submodules are private; their
//! public items are re-exported here.
//!
//! Sign convention: products of inertia negated, `I_xy = −Σ m x y` (2.49), so `L = I·ω` (2.63);
//! tensors are stored about the centre of mass in body axes; principal moments ascending,
//! principal axes a proper rotation.

mod body;
mod density;
mod mesh;
mod mesh_embedding;
mod moments;
mod scaling;
mod shapes;
mod tensor;

pub use body::{MassProperties, BODY_ROTATION_TOL};
pub use density::{
    density_mass_properties, CubatureOptions, DensityIntegral, MAX_BATCH, POINTS_PER_REGION,
};
pub use mesh::{
    check_mesh_file, merge_close_vertices, mesh_mass_properties, mesh_mass_properties_merging,
    mesh_mass_properties_rows, FaceIndex, MAX_VERTICES, MERGE_RTOL, MESH_FILE_BYTES_PER_TRIANGLE,
};
pub use moments::check_moments;
pub use shapes::{
    cuboid, cuboid_sides, ellipsoid, solid_cone, solid_cylinder, solid_sphere, spherical_shell,
    thin_disk, thin_ring, thin_rod,
};
pub use tensor::{
    check_inertia, check_inertia_scaled, classify, point_inertia, principal, rotate,
    shift_from_com, shift_to_com, Principal, TopKind, DEFAULT_KIND_RTOL, PHYSICAL_RTOL,
    SYMMETRY_RTOL,
};
