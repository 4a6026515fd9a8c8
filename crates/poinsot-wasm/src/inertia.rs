//! Bindings of `poinsot::inertia`: the standard solids (axes of symmetry along z, centred on the
//! centre of mass except the cone, apex at the origin), inertia tensor, principal moments and
//! axes, kind of top, L and T (the unit's 2.43–2.66); closed triangle meshes (`fromMesh`).

use crate::args::{let_numbers, matrix, numbers, triple, vector, Number, Numbers};
use crate::calls;
use crate::convert::{getters, mat3, mat_out, vec_out, Failure, Out};
use crate::free::kind;
use poinsot::inertia::{self as inr, MassProperties, DEFAULT_KIND_RTOL};
use wasm_bindgen::prelude::wasm_bindgen;

/// A rigid body's mass properties (`poinsot.RigidBody` in Python).
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct RigidBody {
    inner: MassProperties,
}

/// The body made by the core (which refuses, naming the argument, a body any of whose numbers
/// would not be finite).
fn wrap(r: poinsot::Result<MassProperties>) -> Out<RigidBody> {
    Ok(RigidBody { inner: r? })
}

/// The standard solids of 3 dimensions: `solids!(" doc" jsName rust_name(dims); ...)` is one constructor per solid, calling the core's `inertia::rust_name(mass, dims)` with the
/// 3 dimensions (x, y, z) given as one array-like `dims` (doc lines as string literals, see
/// [`crate::convert::getters`]).
macro_rules! solids {
    ($($($doc:literal)* $js:ident $name:ident($dims:ident);)+) => {
        #[wasm_bindgen]
        impl RigidBody {
            $(
                $(#[doc = $doc])*
                #[wasm_bindgen(js_name = $js)]
                pub fn $name(
                    #[wasm_bindgen(unchecked_param_type = "number")] mass: Number,
                    #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] $dims: Numbers,
                ) -> Out<RigidBody> {
                    let_numbers!(mass);
                    wrap(inr::$name(mass, triple(stringify!($dims), &$dims)?))
                }
            )+
        }
    };
}

// The standard solids of scalar dimensions (the core's `inertia::rust_name(mass, dims...)`).
calls!(fn RigidBody {
    " A solid sphere of `mass` (kg) and `radius` (m)."
    solidSphere solid_sphere(mass: number, radius: number) -> RigidBody = inr::solid_sphere;
    " A thin spherical shell."
    sphericalShell spherical_shell(mass: number, radius: number) -> RigidBody =
        inr::spherical_shell;
    " A solid cylinder, axis along z."
    solidCylinder solid_cylinder(mass: number, radius: number, height: number) -> RigidBody =
        inr::solid_cylinder;
    " A solid cone, apex at the origin, axis along +z."
    solidCone solid_cone(mass: number, radius: number, height: number) -> RigidBody =
        inr::solid_cone;
    " A thin rod of `length` (m) along z."
    thinRod thin_rod(mass: number, length: number) -> RigidBody = inr::thin_rod;
    " A thin disk in the xy-plane."
    thinDisk thin_disk(mass: number, radius: number) -> RigidBody = inr::thin_disk;
    " A thin ring in the xy-plane."
    thinRing thin_ring(mass: number, radius: number) -> RigidBody = inr::thin_ring;
});

solids! {
    " A cuboid of `sides` (m, 3 numbers: x, y, z)."
    cuboid cuboid(sides);
    " A solid ellipsoid of `semi_axes` (m, 3 numbers)."
    ellipsoid ellipsoid(semi_axes);
}

#[wasm_bindgen]
impl RigidBody {
    /// A body of `mass` (kg) with inertia tensor `inertia` (kg·m², 9 numbers row-major, about the
    /// centre of mass, body axes) and centre of mass `center_of_mass` (m).
    #[wasm_bindgen(js_name = fromInertia)]
    pub fn from_inertia(
        #[wasm_bindgen(unchecked_param_type = "number")] mass: Number,
        #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] inertia: Numbers,
        #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] center_of_mass: Numbers,
    ) -> Out<RigidBody> {
        let_numbers!(mass);
        let inertia = numbers("inertia", &inertia)?;
        let center_of_mass = vector("center_of_mass", &center_of_mass)?;
        let inertia = mat3("inertia", &inertia)?;
        wrap(MassProperties::new(mass, center_of_mass, inertia))
    }
    /// The solid bounded by a closed triangle mesh of uniform `density` (kg/m³), by the core's
    /// exact polyhedral integrals (2.61–2.62; `poinsot.RigidBody.from_mesh` in Python).
    ///
    /// `vertices`: `3·n` coordinates (m), row-major `(n, 3)`; `faces`: `3·m` vertex indices,
    /// row-major `(m, 3)`, each face counter-clockwise seen from outside. Indices arrive as
    /// JavaScript numbers: each must be an integer (a fraction or a non-finite number is refused
    /// here; a negative or too large one by the core, which names it). The core refuses, with an
    /// `InvalidMeshError` naming `faces` or `vertices`, a mesh that does not bound a solid (open,
    /// non-manifold, inconsistently oriented, inside out, zero volume). Vertices are used as
    /// given, unless `mergeVertices` is true: then the core first merges the vertices within
    /// `2^-22` of the largest coordinate magnitude of each other (its `MERGE_RTOL`; Python's
    /// `merge_vertices=True`), so that a triangle soup or a CAD export whose shared corners
    /// differ in the last bits (SolidWorks' STL files) is read as the closed mesh it is.
    #[wasm_bindgen(js_name = fromMesh)]
    pub fn from_mesh(
        #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] vertices: Numbers,
        #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] faces: Numbers,
        #[wasm_bindgen(unchecked_param_type = "number")] density: Number,
        merge_vertices: Option<bool>,
    ) -> Out<RigidBody> {
        let vertices = numbers("vertices", &vertices)?;
        let faces = numbers("faces", &faces)?;
        let_numbers!(density);
        let indices = face_indices(&faces)?;
        let body = if merge_vertices.unwrap_or(false) {
            inr::mesh_mass_properties_merging(&vertices, &indices, density)
        } else {
            inr::mesh_mass_properties(&vertices, &indices, density)
        };
        wrap(body)
    }

    /// Centre of mass (m).
    #[wasm_bindgen(getter, js_name = centerOfMass)]
    pub fn center_of_mass(&self) -> Vec<f64> {
        vec_out(&self.inner.center_of_mass())
    }
    /// Inertia tensor about the centre of mass (kg·m², 9 numbers row-major).
    #[wasm_bindgen(getter)]
    pub fn inertia(&self) -> Vec<f64> {
        mat_out(&self.inner.inertia())
    }
    /// Principal moments (kg·m², ascending), with the Python API's tolerance for equal moments.
    #[wasm_bindgen(getter, js_name = principalMoments)]
    pub fn principal_moments(&self) -> Vec<f64> {
        self.inner.principal(DEFAULT_KIND_RTOL).moments.to_vec()
    }
    /// Principal axes as the columns of a proper rotation (9 numbers row-major).
    #[wasm_bindgen(getter, js_name = principalAxes)]
    pub fn principal_axes(&self) -> Vec<f64> {
        mat_out(&self.inner.principal(DEFAULT_KIND_RTOL).axes)
    }
    /// The margins of the triangle inequalities (kg·m²), `[I2 + I3 − I1, I3 + I1 − I2,
    /// I1 + I2 − I3]` for the ascending principal moments: each is twice the second moment of
    /// the mass along that principal axis, zero for a lamina ⟂ it.
    #[wasm_bindgen(getter, js_name = triangleMargins)]
    pub fn triangle_margins(&self) -> Vec<f64> {
        self.inner
            .principal(DEFAULT_KIND_RTOL)
            .triangle_margins()
            .to_vec()
    }
    /// The kind of top: "spherical top", "symmetric top", "asymmetric top" or "rotor".
    pub fn kind(&self) -> Out<String> {
        Ok(self.inner.kind(DEFAULT_KIND_RTOL)?.as_str().to_string())
    }
    /// The same body moved by `offset` (m, 3 numbers): the centre of mass moves, the inertia
    /// about it does not change (`RigidBody.translated` in Python).
    pub fn translated(
        &self,
        #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] offset: Numbers,
    ) -> Out<RigidBody> {
        wrap(self.inner.translated(&vector("offset", &offset)?))
    }
    /// The same body rotated actively by `rotation` (9 numbers row-major, a proper rotation)
    /// about the origin of its axes: `com ↦ R com`, `I ↦ R I Rᵀ` (`RigidBody.rotated`).
    pub fn rotated(
        &self,
        #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] rotation: Numbers,
    ) -> Out<RigidBody> {
        wrap(self.inner.rotated(&matrix("rotation", &rotation)?))
    }
    /// The inertia tensor about `point` (m), 9 numbers row-major (parallel-axis theorem).
    #[wasm_bindgen(js_name = inertiaAbout)]
    pub fn inertia_about(
        &self,
        #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] point: Numbers,
    ) -> Out<Vec<f64>> {
        Ok(mat_out(
            &self.inner.inertia_about(&vector("point", &point)?)?,
        ))
    }
}

/// The body's quantities at one angular velocity `omega` (rad/s, 3 numbers), about the centre
/// of mass: `at_omega!(" doc" jsName rust_name: kind; ...)` is one `#[wasm_bindgen] impl
/// RigidBody` block of `pub fn rust_name(&self, omega)`, the core's
/// `rust_name(&omega, None)?` as `kind` ([`crate::free::kind`]; doc lines as string literals,
/// see [`crate::convert::getters`]).
macro_rules! at_omega {
    ($($($doc:literal)* $js:ident $name:ident: $kind:ident;)+) => {
        #[wasm_bindgen]
        impl RigidBody {
            $(
                $(#[doc = $doc])*
                #[wasm_bindgen(js_name = $js)]
                pub fn $name(
                    &self,
                    #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] omega: Numbers,
                ) -> Out<kind!(type $kind)> {
                    let value = self.inner.$name(&vector("omega", &omega)?, None)?;
                    Ok(kind!(out $kind value))
                }
            )+
        }
    };
}

at_omega! {
    " L = I·ω (kg·m²/s) about the centre of mass for `omega` (rad/s)."
    angularMomentum angular_momentum: vector;
    " T = ½ ω·I·ω (J) about the centre of mass."
    kineticEnergy kinetic_energy: number;
    " ω × L (N·m): the torque that keeps the body turning at constant ω."
    holdingTorque holding_torque: vector;
}

getters!(RigidBody {
    " Mass (kg)."
    mass mass;
});

/// Face indices from JavaScript numbers: each must be an integer that fits an `i64` (range
/// against the vertex count is the core's check, which reports the offending index).
fn face_indices(faces: &[f64]) -> Out<Vec<i64>> {
    // 2⁶³ as f64: integers at or beyond it do not fit an i64.
    const LIMIT: f64 = 9_223_372_036_854_775_808.0;
    faces
        .iter()
        .enumerate()
        .map(|(k, &x)| {
            if x.is_finite() && x.fract() == 0.0 && x.abs() < LIMIT {
                Ok(x as i64)
            } else {
                Err(Failure::from(poinsot::Error::mesh(
                    "faces",
                    format!(
                        "must hold integer vertex indices, got {x} at face {} (corner {})",
                        k / 3,
                        k % 3
                    ),
                )))
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convert::refused;

    /// The unit cube [0, 1]³ as 8 vertices and 12 outward triangles.
    fn cube() -> (Vec<f64>, Vec<f64>) {
        let v: Vec<f64> = (0..8)
            .flat_map(|i: i32| {
                [
                    f64::from(i & 1),
                    f64::from((i >> 1) & 1),
                    f64::from((i >> 2) & 1),
                ]
            })
            .collect();
        let f = [
            0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4,
            6, 1, 3, 5, 3, 7, 5,
        ]
        .iter()
        .map(|&i: &i32| f64::from(i))
        .collect();
        (v, f)
    }

    #[test]
    fn mesh_cube_is_the_cuboid() {
        let (v, f) = cube();
        let b = RigidBody::from_mesh(v.clone(), f.clone(), 3.0, None).unwrap();
        let c = RigidBody::cuboid(3.0, vec![1.0, 1.0, 1.0]).unwrap();
        assert!((b.mass() - 3.0).abs() < 1e-15);
        assert!(b.center_of_mass().iter().all(|x| (x - 0.5).abs() < 1e-15));
        for (x, y) in b.inertia().iter().zip(c.inertia()) {
            assert!((x - y).abs() < 1e-15, "{x} vs {y}");
        }
        assert_eq!(b.kind().unwrap(), "spherical top");
    }

    #[test]
    fn mesh_shape_and_index_errors_name_the_argument() {
        let (v, f) = cube();
        // Shapes: a coordinate or an index too many.
        let short = RigidBody::from_mesh(v[..23].to_vec(), f.clone(), 1.0, None);
        let e = refused(short, "vertices: must have shape (N, 3)");
        assert_eq!(e.name, "InvalidMeshError");
        let short = RigidBody::from_mesh(v.clone(), f[..35].to_vec(), 1.0, None);
        refused(short, "faces: must have shape (M, 3)");
        // Index range: too large and negative, reported by the core with the index.
        let mut big = f.clone();
        big[7] = 8.0;
        let e = refused(
            RigidBody::from_mesh(v.clone(), big.clone(), 1.0, None),
            "faces: index 8 at face 2 (corner 1) is out of range",
        );
        assert_eq!(e.name, "InvalidMeshError");
        let mut neg = f.clone();
        neg[0] = -1.0;
        let e = RigidBody::from_mesh(v.clone(), neg.clone(), 1.0, None).unwrap_err();
        assert!(e.message.contains("index -1 at face 0"), "{}", e.message);
        // Not integers.
        for bad in [0.5, f64::NAN, f64::INFINITY, 1e300] {
            let mut g = f.clone();
            g[4] = bad;
            let bad = RigidBody::from_mesh(v.clone(), g.clone(), 1.0, None);
            let e = refused(bad, "faces: must hold integer vertex indices");
            assert_eq!(e.name, "InvalidMeshError");
            assert!(e.message.contains("at face 1 (corner 1)"), "{e}");
        }
        // Density is the core's argument check.
        let e = refused(
            RigidBody::from_mesh(v.clone(), f.clone(), -1.0, None),
            "density",
        );
        assert_eq!(e.name, "PoinsotError");
    }

    #[test]
    fn open_mesh_is_refused_as_invalid_mesh() {
        let (v, f) = cube();
        let e = RigidBody::from_mesh(v.clone(), f[..33].to_vec(), 1.0, None).unwrap_err();
        assert_eq!(e.name, "InvalidMeshError");
        assert!(e.message.contains("the mesh is open"), "{}", e.message);
        // A triangle soup (every face with its own vertices) looks open until merged.
        let soup: Vec<f64> = f
            .iter()
            .flat_map(|&i| v[3 * i as usize..3 * i as usize + 3].to_vec())
            .collect();
        let idx: Vec<f64> = (0..36).map(f64::from).collect();
        let e = RigidBody::from_mesh(soup.clone(), idx.clone(), 1.0, None).unwrap_err();
        assert!(e.message.contains("open"), "{}", e.message);
        // Merged by the core (mergeVertices): the cube, also with its copies of each corner a
        // few ulps apart as CAD exports write them; Some(false) is the default.
        let jittered: Vec<f64> = soup
            .iter()
            .enumerate()
            .map(|(k, &x)| x + [0.0, 1e-16, -2e-16, 3e-16][k % 4])
            .collect();
        let c = RigidBody::cuboid(1.0, vec![1.0, 1.0, 1.0]).unwrap();
        for s in [soup.clone(), jittered] {
            let b = RigidBody::from_mesh(s.clone(), idx.clone(), 1.0, Some(true)).unwrap();
            assert!((b.mass() - 1.0).abs() < 1e-15);
            for (x, y) in b.inertia().iter().zip(c.inertia()) {
                assert!((x - y).abs() < 1e-15, "{x} vs {y}");
            }
            let e = RigidBody::from_mesh(s, idx.clone(), 1.0, Some(false)).unwrap_err();
            assert!(e.message.contains("open"), "{}", e.message);
        }
    }

    #[test]
    fn moved_bodies_keep_their_moments() {
        let b = RigidBody::cuboid(2.0, vec![1.0, 2.0, 3.0]).unwrap();
        let r = crate::rotation::euler_to_matrix(vec![0.3, 1.0, -0.4], "zxz".into(), true).unwrap();
        let m = b
            .translated(vec![1.0, 2.0, 3.0])
            .unwrap()
            .rotated(r)
            .unwrap();
        for (x, y) in m.principal_moments().iter().zip(b.principal_moments()) {
            assert!((x - y).abs() < 1e-14, "{x} vs {y}");
        }
        assert!(m.center_of_mass().iter().map(|x| x * x).sum::<f64>() > 13.99);
        let e = b
            .rotated(vec![2.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0])
            .unwrap_err();
        assert_eq!(e.name, "InvalidRotationError");
        refused(b.translated(vec![1.0, 2.0]), "offset");
    }

    #[test]
    fn triangle_margins_of_a_disk_and_a_cuboid() {
        let d = RigidBody::thin_disk(2.0, 0.5).unwrap().triangle_margins();
        assert!(d[2].abs() < 1e-16 && d[0] > 0.0, "{d:?}");
        let c = RigidBody::cuboid(12.0, vec![1.0, 2.0, 3.0])
            .unwrap()
            .triangle_margins();
        assert_eq!(c, vec![18.0, 8.0, 2.0]);
    }

    #[test]
    fn cuboid_moments_are_the_closed_form_and_kind_is_asymmetric() {
        let b = RigidBody::cuboid(12.0, vec![1.0, 2.0, 3.0]).unwrap();
        let m = b.principal_moments();
        // m/12 (b² + c²), ... with m = 12, sides 1, 2, 3; ascending.
        let e = [1.0 + 4.0, 1.0 + 9.0, 4.0 + 9.0];
        for (a, b) in m.iter().zip(&e) {
            assert!((a - b).abs() < 1e-13, "{a} vs {b}");
        }
        assert_eq!(b.kind().unwrap(), "asymmetric top");
        assert_eq!(
            RigidBody::solid_sphere(1.0, 1.0).unwrap().kind().unwrap(),
            "spherical top"
        );
    }

    #[test]
    fn unphysical_inertia_is_an_inertia_error() {
        let e = RigidBody::from_inertia(
            1.0,
            vec![1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 5.0],
            vec![0.0; 3],
        )
        .unwrap_err();
        assert_eq!(e.name, "InvalidInertiaError");
        refused(RigidBody::solid_sphere(-1.0, 1.0), "mass");
    }
}
