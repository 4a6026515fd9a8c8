//! Bindings of Poinsot's construction and of the stability of steady rotation
//! (`poinsot::analytic`): the contact point of the inertia ellipsoid with the invariable plane,
//! the polhode on the ellipsoid, the flip interval of the tumbling box (the Dzhanibekov effect)
//! and the linear stability of each principal axis. More methods of [`FreeRigidBody`] (the class
//! is defined in `free.rs`); body components along the principal axes, space components as the
//! attitude maps them.

use crate::args::{count, number, numbers_each, triple, Count, Number, Numbers};
use crate::convert::{at_time, getters, vec_out, Out};
use crate::free::FreeRigidBody;
use poinsot::analytic as an;
use wasm_bindgen::prelude::wasm_bindgen;

/// Bytes per time of the batches (`contactPoints`, `omegas`): the copy of the time (8), the
/// points (24) and the flat output (24).
const BYTES_PER_TIME: usize = 8 + 24 + 24;
/// Bytes per sample of `contactPolhode`: the core's points (24) and the flat output (24).
const BYTES_PER_POLHODE_SAMPLE: usize = 24 + 24;

fn flat(points: &[poinsot::Vec3]) -> Vec<f64> {
    points.iter().flat_map(|p| [p.x, p.y, p.z]).collect()
}

impl FreeRigidBody {
    /// `f` (a method of the core's body at one time) at each of `times` (s): 3N numbers;
    /// errors name `times`.
    fn at_times(
        &self,
        times: &Numbers,
        f: impl Fn(&an::FreeRigidBody, f64) -> poinsot::Result<poinsot::Vec3>,
    ) -> Out<Vec<f64>> {
        let times = numbers_each("times", times, BYTES_PER_TIME)?;
        poinsot::error::check_finite("times", &times)?;
        let points = times
            .iter()
            .map(|&t| f(&self.inner, t))
            .collect::<poinsot::Result<Vec<_>>>()
            .map_err(|e| e.renamed("t", "times"))?;
        Ok(flat(&points))
    }
}

getters!(FreeRigidBody? {
    " λ of the Jacobi argument τ = λt + τ₀ (1/s)."
    frequency frequency;
    " Half the period (s): the interval between reversals of ω along the intermediate axis"
    " (the Dzhanibekov flips near the separatrix); `Infinity` when the period is."
    flipInterval flip_interval;
});

#[wasm_bindgen]
impl FreeRigidBody {
    /// The principal axis (0, 1, 2) that ω circles; `undefined` when steady or on the separatrix.
    #[wasm_bindgen(getter, js_name = poleAxis)]
    pub fn pole_axis(&self) -> Option<u32> {
        self.inner.pole_axis().map(|i| i as u32)
    }
    /// L̂, the invariable plane's unit normal (space components).
    #[wasm_bindgen(getter, js_name = invariablePlaneNormal)]
    pub fn invariable_plane_normal(&self) -> Vec<f64> {
        vec_out(&self.inner.invariable_plane_normal())
    }
    /// The contact points (space components) at each of `times` (s): 3N numbers, the
    /// herpolhode (scaled) when the times are consecutive.
    #[wasm_bindgen(js_name = contactPoints)]
    pub fn contact_points(
        &self,
        #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] times: Numbers,
    ) -> Out<Vec<f64>> {
        self.at_times(&times, an::FreeRigidBody::contact_point)
    }
    /// ω (body components, rad/s) at each of `times` (s): 3N numbers.
    pub fn omegas(
        &self,
        #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] times: Numbers,
    ) -> Out<Vec<f64>> {
        self.at_times(&times, an::FreeRigidBody::omega)
    }
    /// `samples` points (3N numbers, body components) of the polhode on the inertia ellipsoid
    /// ρ·I·ρ = 1, over one period (on the separatrix, the branch from −12/λ to 12/λ).
    #[wasm_bindgen(js_name = contactPolhode)]
    pub fn contact_polhode(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] samples: Count,
    ) -> Out<Vec<f64>> {
        // A JavaScript number as a count (a whole number whose conversion is exact: within the
        // budget of the flat output); the limit of the polhode (>= 2 points, within the memory
        // budget) is the core's.
        let samples = count("samples", &samples, BYTES_PER_POLHODE_SAMPLE)?;
        Ok(flat(&self.inner.contact_polhode(samples)?))
    }
}

getters!(FreeRigidBody {
    " The Jacobi parameter m = k² (0 steady or symmetric, 1 on the separatrix)."
    parameter parameter;
    " (2T)^½ / |L|: the distance of the invariable plane from the centre in Poinsot's"
    " construction (the inertia ellipsoid ρ·I·ρ = 1)."
    invariablePlaneDistance invariable_plane_distance;
    " The largest |t| (s) at which the state is computed: the time in which the motion turns"
    " through 2⁴² rad at its fastest rate (a later `t` is refused naming `t`); `Infinity` when"
    " the body never turns that far within the double range."
    maxTime max_time;
});

at_time!(FreeRigidBody {
    " The contact point ρ = R(t) ω(t) / (2T)^½ of the inertia ellipsoid with the invariable"
    " plane at time `t` (s), space components."
    contactPoint contact_point -> vec_out;
    " The contact point ω(t) / (2T)^½ at time `t` (s), body components."
    contactPointBody contact_point_body -> vec_out;
});

/// The linear stability of steady rotation about each principal axis
/// (`poinsot.axis_stability` in Python).
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct AxisStability {
    kinds: Vec<String>,
    rates: Vec<f64>,
}

#[wasm_bindgen]
impl AxisStability {
    /// "stable", "unstable" or "neutral" for each axis, in the order of the moments.
    #[wasm_bindgen(getter)]
    pub fn kinds(&self) -> Vec<String> {
        self.kinds.clone()
    }
    /// The oscillation frequency (stable) or growth rate (unstable) of each axis (1/s).
    #[wasm_bindgen(getter)]
    pub fn rates(&self) -> Vec<f64> {
        self.rates.clone()
    }
}

/// The stability of steady rotation at `spin` (rad/s) about each principal axis of a body with
/// principal `moments` (kg·m², 3 numbers, any order): the intermediate axis is unstable.
#[wasm_bindgen(js_name = axisStability)]
pub fn axis_stability(
    #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] moments: Numbers,
    #[wasm_bindgen(unchecked_param_type = "number")] spin: Number,
) -> Out<AxisStability> {
    let moments = triple("moments", &moments)?;
    let s = an::axis_stability(moments, number("spin", &spin)?)?;
    Ok(AxisStability {
        kinds: s.iter().map(|a| a.stability.as_str().to_string()).collect(),
        rates: s.iter().map(|a| a.rate).collect(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convert::refused;

    #[test]
    fn contact_point_is_on_the_ellipsoid_and_the_plane() {
        let b = FreeRigidBody::new(vec![1.0, 2.0, 3.0], vec![0.05, 2.0, 0.05], vec![]).unwrap();
        let t = 3.7;
        let rb = b.contact_point_body(t).unwrap();
        let rs = b.contact_point(t).unwrap();
        let e = rb[0] * rb[0] + 2.0 * rb[1] * rb[1] + 3.0 * rb[2] * rb[2];
        assert!((e - 1.0).abs() < 1e-12, "{e}");
        let n = b.invariable_plane_normal();
        let h = rs[0] * n[0] + rs[1] * n[1] + rs[2] * n[2];
        assert!(
            (h / b.invariable_plane_distance() - 1.0).abs() < 1e-12,
            "{h}"
        );
        // The batch agrees with the single call.
        let many = b.contact_points(vec![0.0, t]).unwrap();
        assert_eq!(&many[3..], &rs[..]);
        assert_eq!(b.omegas(vec![t]).unwrap(), b.omega(t).unwrap());
        // The flip interval is half the period.
        assert!((2.0 * b.flip_interval().unwrap() / b.period().unwrap() - 1.0).abs() < 1e-14);
        // L² = 16.025 > 2T·I₂ = 16.02: just above the separatrix, ω circles the largest axis.
        assert_eq!(b.pole_axis(), Some(2));
        assert_eq!(b.regime(), "about max axis");
    }

    #[test]
    fn bad_input_names_the_argument() {
        let b = FreeRigidBody::new(vec![1.0, 2.0, 3.0], vec![0.3, 1.0, 0.2], vec![]).unwrap();
        refused(b.contact_point(f64::INFINITY), "t: must be finite");
        refused(
            b.contact_points(vec![0.0, f64::NAN]),
            "times: must be finite",
        );
        refused(b.contact_polhode(1.0), "samples");
        let e = axis_stability(vec![1.0, 2.0, 5.0], 1.0).unwrap_err();
        assert_eq!(e.name, "InvalidInertiaError");
        refused(axis_stability(vec![1.0, 2.0], 1.0), "moments");
        refused(axis_stability(vec![1.0, 2.0, 3.0], f64::NAN), "spin");
    }

    #[test]
    fn the_intermediate_axis_is_the_unstable_one() {
        let s = axis_stability(vec![3.0, 1.0, 2.0], 2.0).unwrap();
        assert_eq!(s.kinds(), ["stable", "stable", "unstable"]);
        // σ = |spin| ((I₂ − I₁)(I₃ − I₂)/(I₁I₃))^½ with sorted 1, 2, 3: 2·(1·1/3)^½.
        assert!((s.rates()[2] - 2.0 * (1.0f64 / 3.0).sqrt()).abs() < 1e-15);
    }
}
