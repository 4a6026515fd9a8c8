//! Bindings of `poinsot::earth`: the falling body (the unit's 2.42 and the exact drop), effective
//! gravity, the Coriolis acceleration and the Foucault rate. Local frame ENU, latitude in radians
//! north-positive.

use crate::convert::{finite, finite1, vec3, vec_out, Out};
use poinsot::earth::{self as ea, FallModel, Gravity};
use poinsot::integrate::Options;
use wasm_bindgen::prelude::wasm_bindgen;

/// Tolerances of the exact drop: the Python API's defaults (`Earth.drop(rtol=1e-12,
/// atol=1e-12, max_steps=1_000_000)`), so that the page and Python give the same numbers.
pub const DROP_TOL: f64 = 1e-12;
/// Step limit of the exact drop (the Python default).
pub const DROP_MAX_STEPS: usize = 1_000_000;

/// The rotating Earth (`poinsot.Earth` in Python).
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct Earth {
    inner: ea::Earth,
}

/// Where and when a dropped body lands (exact, integrated in the rotating frame), and its path.
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct Fall {
    inner: ea::Fall,
}

#[wasm_bindgen]
impl Fall {
    /// Time of flight (s).
    #[wasm_bindgen(getter)]
    pub fn time(&self) -> f64 {
        self.inner.time
    }
    /// Eastward displacement at landing (m).
    #[wasm_bindgen(getter)]
    pub fn east(&self) -> f64 {
        self.inner.east
    }
    /// Northward displacement at landing (m).
    #[wasm_bindgen(getter)]
    pub fn north(&self) -> f64 {
        self.inner.north
    }
    /// The state `[x, y, z, vx, vy, vz]` (ENU, m and m/s, origin at the ground below the
    /// release point) at time `t` (s, in [0, time]) from the integrator's dense output.
    pub fn state(&self, t: f64) -> Out<Vec<f64>> {
        poinsot::error::check_finite("t", &[t])?;
        finite("state", self.inner.solution.at(t)?.to_vec())
    }
}

#[wasm_bindgen]
impl Earth {
    /// An Earth of angular rate `rotation_rate` (rad/s), `radius` (m) and surface gravity `g`
    /// (m/s²). The Python defaults are [`Earth::sidereal_rate`], 6.371e6 m and 9.80665 m/s².
    #[wasm_bindgen(constructor)]
    pub fn new(rotation_rate: f64, radius: f64, g: f64) -> Out<Earth> {
        Ok(Earth {
            inner: ea::Earth::new(rotation_rate, radius, g)?,
        })
    }

    /// The sidereal rotation rate 7.2921150e-5 rad/s (the default).
    #[wasm_bindgen(js_name = siderealRate)]
    pub fn sidereal_rate() -> f64 {
        ea::SIDEREAL_RATE
    }
    /// The unit's solar-day rate 2π/86400 rad/s.
    #[wasm_bindgen(js_name = solarDayRate)]
    pub fn solar_day_rate() -> f64 {
        ea::SOLAR_DAY_RATE
    }
    /// The mean radius 6.371e6 m (the default).
    #[wasm_bindgen(js_name = meanRadius)]
    pub fn mean_radius() -> f64 {
        ea::MEAN_RADIUS
    }
    /// Standard gravity 9.80665 m/s² (the default).
    #[wasm_bindgen(js_name = standardGravity)]
    pub fn standard_gravity() -> f64 {
        ea::STANDARD_GRAVITY
    }

    /// The first-order eastward deflection (m) of a body dropped from `height` (m) at
    /// `latitude` (rad): the unit's 2.42.
    #[wasm_bindgen(js_name = eastwardDeflection)]
    pub fn eastward_deflection(&self, height: f64, latitude: f64) -> Out<f64> {
        finite1("east", self.inner.eastward_deflection(height, latitude)?)
    }

    /// The second-order southward deflection (m) in the northern hemisphere.
    #[wasm_bindgen(js_name = southwardDeflection)]
    pub fn southward_deflection(&self, height: f64, latitude: f64) -> Out<f64> {
        finite1("south", self.inner.southward_deflection(height, latitude)?)
    }

    /// The time (s) to fall `height` (m) in uniform gravity without rotation, √(2h/g).
    #[wasm_bindgen(js_name = fallTime)]
    pub fn fall_time(&self, height: f64) -> Out<f64> {
        finite1("time", self.inner.fall_time(height)?)
    }

    /// The exact drop from rest at `height` (m) and `latitude` (rad), with the Python API's
    /// defaults (uniform gravity, Coriolis and centrifugal terms, tolerances [`DROP_TOL`]).
    pub fn drop(&self, height: f64, latitude: f64) -> Out<Fall> {
        let model = FallModel {
            gravity: Gravity::Uniform,
            rotation: true,
            centrifugal: true,
            options: Options {
                rtol: DROP_TOL,
                atol: DROP_TOL,
                max_steps: DROP_MAX_STEPS,
                dense: true,
                ..Options::default()
            },
        };
        let f = self.inner.drop(height, latitude, &model)?;
        finite("fall", vec![f.time, f.east, f.north])?;
        Ok(Fall { inner: f })
    }

    /// The precession rate (rad/s) of a Foucault pendulum's swing plane, ω sin λ (clockwise seen
    /// from above in the north).
    #[wasm_bindgen(js_name = foucaultRate)]
    pub fn foucault_rate(&self, latitude: f64) -> Out<f64> {
        finite1("rate", self.inner.foucault_rate(latitude)?)
    }

    /// The Earth's angular velocity in the local ENU frame, ω (0, cos λ, sin λ) (rad/s).
    #[wasm_bindgen(js_name = omegaEnu)]
    pub fn omega_enu(&self, latitude: f64) -> Out<Vec<f64>> {
        finite("omega", vec_out(&self.inner.omega_enu(latitude)?))
    }

    /// The effective gravity vector (ENU, m/s²) at `latitude` (rad).
    #[wasm_bindgen(js_name = effectiveGravity)]
    pub fn effective_gravity(&self, latitude: f64) -> Out<Vec<f64>> {
        finite(
            "g_eff",
            vec_out(&self.inner.effective_gravity(latitude)?.vector),
        )
    }

    /// The Coriolis acceleration −2 ω × v (ENU, m/s²) of a velocity `velocity` (ENU, m/s).
    #[wasm_bindgen(js_name = coriolisAcceleration)]
    pub fn coriolis_acceleration(&self, latitude: f64, velocity: &[f64]) -> Out<Vec<f64>> {
        finite(
            "coriolis",
            vec_out(
                &self
                    .inner
                    .coriolis_acceleration(latitude, &vec3("velocity", velocity)?)?,
            ),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn earth() -> Earth {
        Earth::new(
            Earth::sidereal_rate(),
            Earth::mean_radius(),
            Earth::standard_gravity(),
        )
        .unwrap()
    }

    #[test]
    fn first_order_deflection_is_the_units_2_42() {
        let (h, lat): (f64, f64) = (100.0, 0.7);
        let e = earth();
        let expect = Earth::sidereal_rate() * lat.cos() / 3.0
            * (8.0 * h.powi(3) / Earth::standard_gravity()).sqrt();
        assert!((e.eastward_deflection(h, lat).unwrap() - expect).abs() < 1e-15);
        let exact = e.drop(h, lat).unwrap();
        assert!((exact.east() / expect - 1.0).abs() < 1e-3, "{} vs {}", exact.east(), expect);
        let land = exact.state(exact.time()).unwrap();
        assert!((land[0] - exact.east()).abs() < 1e-9 && land[2].abs() < 1e-9, "{land:?}");
        assert!(exact.state(-1.0).is_err());
    }

    #[test]
    fn bad_latitude_throws_with_the_core_message() {
        let f = earth().drop(100.0, 2.0).unwrap_err();
        assert!(f.message.starts_with("latitude"), "{}", f.message);
        assert!(earth()
            .drop(-1.0, 0.5)
            .unwrap_err()
            .message
            .starts_with("height"));
    }
}
