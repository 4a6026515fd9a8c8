//! Bindings of `poinsot::inertia`: the standard solids (axes of symmetry along z, centred on the
//! centre of mass except the cone, apex at the origin), inertia tensor, principal moments and
//! axes, kind of top, L and T (the unit's 2.43–2.66).

use crate::convert::{array3, finite, finite1, mat3, mat_out, vec3, vec_out, Out};
use poinsot::inertia::{self as inr, MassProperties, DEFAULT_KIND_RTOL};
use wasm_bindgen::prelude::wasm_bindgen;

/// A rigid body's mass properties (`poinsot.RigidBody` in Python).
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct RigidBody {
    inner: MassProperties,
}

fn wrap(r: poinsot::Result<MassProperties>) -> Out<RigidBody> {
    Ok(RigidBody { inner: r? })
}

#[wasm_bindgen]
impl RigidBody {
    /// A body of `mass` (kg) with inertia tensor `inertia` (kg·m², 9 numbers row-major, about the
    /// centre of mass, body axes) and centre of mass `center_of_mass` (m).
    #[wasm_bindgen(js_name = fromInertia)]
    pub fn from_inertia(mass: f64, inertia: &[f64], center_of_mass: &[f64]) -> Out<RigidBody> {
        wrap(MassProperties::new(
            mass,
            vec3("center_of_mass", center_of_mass)?,
            mat3("inertia", inertia)?,
        ))
    }
    /// A solid sphere of `mass` (kg) and `radius` (m).
    #[wasm_bindgen(js_name = solidSphere)]
    pub fn solid_sphere(mass: f64, radius: f64) -> Out<RigidBody> {
        wrap(inr::solid_sphere(mass, radius))
    }
    /// A thin spherical shell.
    #[wasm_bindgen(js_name = sphericalShell)]
    pub fn spherical_shell(mass: f64, radius: f64) -> Out<RigidBody> {
        wrap(inr::spherical_shell(mass, radius))
    }
    /// A solid cylinder, axis along z.
    #[wasm_bindgen(js_name = solidCylinder)]
    pub fn solid_cylinder(mass: f64, radius: f64, height: f64) -> Out<RigidBody> {
        wrap(inr::solid_cylinder(mass, radius, height))
    }
    /// A solid cone, apex at the origin, axis along +z.
    #[wasm_bindgen(js_name = solidCone)]
    pub fn solid_cone(mass: f64, radius: f64, height: f64) -> Out<RigidBody> {
        wrap(inr::solid_cone(mass, radius, height))
    }
    /// A cuboid of `sides` (m, 3 numbers: x, y, z).
    pub fn cuboid(mass: f64, sides: &[f64]) -> Out<RigidBody> {
        wrap(inr::cuboid(mass, array3("sides", sides)?))
    }
    /// A solid ellipsoid of `semi_axes` (m, 3 numbers).
    pub fn ellipsoid(mass: f64, semi_axes: &[f64]) -> Out<RigidBody> {
        wrap(inr::ellipsoid(mass, array3("semi_axes", semi_axes)?))
    }
    /// A thin rod of `length` (m) along z.
    #[wasm_bindgen(js_name = thinRod)]
    pub fn thin_rod(mass: f64, length: f64) -> Out<RigidBody> {
        wrap(inr::thin_rod(mass, length))
    }
    /// A thin disk in the xy-plane.
    #[wasm_bindgen(js_name = thinDisk)]
    pub fn thin_disk(mass: f64, radius: f64) -> Out<RigidBody> {
        wrap(inr::thin_disk(mass, radius))
    }
    /// A thin ring in the xy-plane.
    #[wasm_bindgen(js_name = thinRing)]
    pub fn thin_ring(mass: f64, radius: f64) -> Out<RigidBody> {
        wrap(inr::thin_ring(mass, radius))
    }

    /// Mass (kg).
    #[wasm_bindgen(getter)]
    pub fn mass(&self) -> f64 {
        self.inner.mass()
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
    /// The kind of top: "spherical top", "symmetric top", "asymmetric top" or "rotor".
    pub fn kind(&self) -> Out<String> {
        Ok(self.inner.kind(DEFAULT_KIND_RTOL)?.as_str().to_string())
    }
    /// The inertia tensor about `point` (m), 9 numbers row-major (parallel-axis theorem).
    #[wasm_bindgen(js_name = inertiaAbout)]
    pub fn inertia_about(&self, point: &[f64]) -> Out<Vec<f64>> {
        finite(
            "inertia",
            mat_out(&self.inner.inertia_about(&vec3("point", point)?)?),
        )
    }
    /// L = I·ω (kg·m²/s) about the centre of mass for `omega` (rad/s).
    #[wasm_bindgen(js_name = angularMomentum)]
    pub fn angular_momentum(&self, omega: &[f64]) -> Out<Vec<f64>> {
        finite(
            "L",
            vec_out(&self.inner.angular_momentum(&vec3("omega", omega)?, None)?),
        )
    }
    /// T = ½ ω·I·ω (J) about the centre of mass.
    #[wasm_bindgen(js_name = kineticEnergy)]
    pub fn kinetic_energy(&self, omega: &[f64]) -> Out<f64> {
        finite1(
            "T",
            self.inner.kinetic_energy(&vec3("omega", omega)?, None)?,
        )
    }
    /// ω × L (N·m): the torque that keeps the body turning at constant ω.
    #[wasm_bindgen(js_name = holdingTorque)]
    pub fn holding_torque(&self, omega: &[f64]) -> Out<Vec<f64>> {
        finite(
            "torque",
            vec_out(&self.inner.holding_torque(&vec3("omega", omega)?, None)?),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cuboid_moments_are_the_closed_form_and_kind_is_asymmetric() {
        let b = RigidBody::cuboid(12.0, &[1.0, 2.0, 3.0]).unwrap();
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
            &[1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 5.0],
            &[0.0; 3],
        )
        .unwrap_err();
        assert_eq!(e.name, "InvalidInertiaError");
        assert!(RigidBody::solid_sphere(-1.0, 1.0)
            .unwrap_err()
            .message
            .starts_with("mass"));
    }
}
