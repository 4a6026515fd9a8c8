//! Bindings of `poinsot::analytic`: the exact torque-free motion of the symmetric top (the unit's
//! 2.77–2.97) and of any rigid body (Jacobi elliptic functions). Body-frame ω, attitude
//! quaternions scalar-first `[w, x, y, z]` mapping body to space components.

use crate::args::{number, numbers, triple, vector, Number, Numbers};
use crate::convert::{at_time, getters, quat, quat_out, vec_out, Out};
use poinsot::analytic as an;
use wasm_bindgen::prelude::wasm_bindgen;

/// The free symmetric top (`poinsot.FreeSymmetricTop` in Python).
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct FreeSymmetricTop {
    inner: an::FreeSymmetricTop,
}

#[wasm_bindgen]
impl FreeSymmetricTop {
    /// A symmetric top with transverse moment `i1` and axial moment `i3` (kg·m²) spinning with
    /// body angular velocity `omega0` (rad/s, 3 numbers) at t = 0, attitude the identity.
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "number")] i1: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] i3: Number,
        #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] omega0: Numbers,
    ) -> Out<FreeSymmetricTop> {
        let (i1, i3) = (number("i1", &i1)?, number("i3", &i3)?);
        let omega0 = vector("omega0", &omega0)?;
        let inner = an::FreeSymmetricTop::new(i1, i3, omega0, None)?;
        // Refused here, as the getters would refuse them: T and L beyond the doubles (ω₀ = 1e300).
        inner.energy()?;
        inner.angular_momentum()?;
        Ok(FreeSymmetricTop { inner })
    }
    /// "prolate", "oblate" or "spherical".
    #[wasm_bindgen(getter)]
    pub fn shape(&self) -> String {
        self.inner.shape().as_str().to_string()
    }
}

/// Getters of the core's values that it refuses beyond the doubles: `results!(Type { " doc"
/// jsName rust_name: kind; ... })` is one `#[wasm_bindgen] impl Type` block of
/// `#[wasm_bindgen(getter)] pub fn rust_name(&self) -> Out<...>`, `self.inner.rust_name()?` as
/// `kind` ([`kind!`]). Doc lines are string
/// literals (wasm-bindgen writes a doc comment passed through `macro_rules!` as `r" ..."`).
macro_rules! results {
    ($ty:ident { $($($doc:literal)* $js:ident $name:ident: $kind:ident;)* }) => {
        #[wasm_bindgen]
        impl $ty {
            $(
                $(#[doc = $doc])*
                #[wasm_bindgen(getter, js_name = $js)]
                pub fn $name(&self) -> Out<kind!(type $kind)> {
                    Ok(kind!(out $kind self.inner.$name()?))
                }
            )*
        }
    };
}

/// A core value as JavaScript receives it, by kind: `kind!(type k)` is its Rust type and
/// `kind!(out k value)` converts it (`number`: the `f64` itself, `vector`: 3 numbers).
macro_rules! kind {
    (type number) => { f64 };
    (type vector) => { Vec<f64> };
    (out number $value:expr) => { $value };
    (out vector $value:expr) => { crate::convert::vec_out(&$value) };
}
pub(crate) use kind;

results!(FreeSymmetricTop {
    " Kinetic energy (J), conserved."
    energy energy: number;
    " Angular momentum in space components (kg·m²/s), conserved."
    angularMomentum angular_momentum: vector;
});

at_time!(FreeSymmetricTop {
    " Body angular velocity (rad/s) at time `t` (s)."
    omega omega -> vec_out;
    " Attitude quaternion `[w, x, y, z]` at time `t` (s)."
    attitude attitude -> quat_out;
    " The symmetry axis in space components at time `t` (s)."
    symmetryAxis symmetry_axis -> vec_out;
});

getters!(FreeSymmetricTop {
    " The unit's Ω = (I₁ − I₃) ω₃ / I₁ (rad/s, 2.83): the body-frame precession rate of ω."
    precessionRate precession_rate;
    " The amplitude A of the transverse components of ω (rad/s)."
    amplitude amplitude;
    " Half-angle (rad) of the body cone (ω about the symmetry axis)."
    bodyConeAngle body_cone_angle;
    " Half-angle (rad) of the space cone (ω about L)."
    spaceConeAngle space_cone_angle;
    " Angle (rad) between the symmetry axis and L."
    nutationAngle nutation_angle;
    " Rate (rad/s) at which the symmetry axis precesses about L in space."
    spacePrecessionRate space_precession_rate;
    " The largest |t| (s) at which ω(t) and the attitude are computed: the time in which the"
    " top turns through 2⁴² rad at its fastest rate (a later `t` is refused naming `t`)."
    maxTime max_time;
});

/// The time argument `t` (s): a finite number.
pub(crate) fn time(t: &Number) -> Out<f64> {
    let t = number("t", t)?;
    poinsot::error::check_finite("t", &[t])?;
    Ok(t)
}

/// The exact torque-free motion of any rigid body (`poinsot.FreeRigidBody` in Python).
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct FreeRigidBody {
    pub(crate) inner: an::FreeRigidBody,
}

#[wasm_bindgen]
impl FreeRigidBody {
    /// A body of principal `moments` (kg·m², 3 numbers) with body angular velocity `omega0`
    /// (rad/s) and attitude `attitude0` (`[w, x, y, z]`; an empty array means the identity) at t = 0.
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] moments: Numbers,
        #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] omega0: Numbers,
        #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] attitude0: Numbers,
    ) -> Out<FreeRigidBody> {
        let moments = triple("moments", &moments)?;
        let omega0 = vector("omega0", &omega0)?;
        let attitude0 = numbers("attitude0", &attitude0)?;
        let q = if attitude0.is_empty() {
            None
        } else {
            Some(quat("attitude0", &attitude0)?)
        };
        let inner = an::FreeRigidBody::new(moments, omega0, q)?;
        // Refused here, as the getters would refuse them: T, L, λ and the period beyond the doubles.
        inner.energy()?;
        inner.angular_momentum()?;
        inner.frequency()?;
        inner.period()?;
        Ok(FreeRigidBody { inner })
    }
    /// The regime of the motion (the core's name for it).
    #[wasm_bindgen(getter)]
    pub fn regime(&self) -> String {
        self.inner.regime().as_str().to_string()
    }
    /// Body ω (3 numbers) then attitude (4 numbers) at time `t` (s), in one call.
    pub fn state(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] t: Number,
    ) -> Out<Vec<f64>> {
        let (w, q) = self.inner.state(time(&t)?)?;
        Ok(vec![w.x, w.y, w.z, q[0], q[1], q[2], q[3]])
    }
}

results!(FreeRigidBody {
    " Kinetic energy (J), conserved."
    energy energy: number;
    " Angular momentum in space components (kg·m²/s), conserved."
    angularMomentum angular_momentum: vector;
    " Period (s) of ω(t); `Infinity` on the separatrix."
    period period: number;
});

at_time!(FreeRigidBody {
    " Body angular velocity (rad/s) at time `t` (s)."
    omega omega -> vec_out;
    " Attitude quaternion `[w, x, y, z]` at time `t` (s)."
    attitude attitude -> quat_out;
    " Angular momentum in body components (kg·m²/s) at time `t` (s)."
    angularMomentumBody angular_momentum_body -> vec_out;
});

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convert::refused;

    #[test]
    fn symmetric_top_precession_rate_is_the_units_omega() {
        let top = FreeSymmetricTop::new(1.0, 2.0, vec![0.1, 0.0, 3.0]).unwrap();
        // Ω = (I₁ − I₃) ω₃ / I₁ (2.83) = (1 − 2)·3/1.
        assert!((top.precession_rate() + 3.0).abs() < 1e-15);
        assert_eq!(top.shape(), "oblate");
    }

    #[test]
    fn free_body_conserves_energy_through_the_binding() {
        let b = FreeRigidBody::new(vec![1.0, 2.0, 3.0], vec![0.3, 1.0, 0.2], vec![]).unwrap();
        let s = b.state(7.3).unwrap();
        let t = 0.5 * (s[0] * s[0] + 2.0 * s[1] * s[1] + 3.0 * s[2] * s[2]);
        assert!((t / b.energy().unwrap() - 1.0).abs() < 1e-12);
        refused(b.omega(f64::NAN), "t: must be finite");
        refused(
            FreeRigidBody::new(vec![1.0, 2.0, 4.0], vec![1.0; 3], vec![]),
            "moments",
        );
    }
}
