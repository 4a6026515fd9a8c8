//! Bindings of `poinsot::dynamics::{Gyrocompass, free_gyroscope}` (conversion and error
//! mapping only): the pendulous gyrocompass at a latitude on the rotating Earth — its settling
//! period, Schuler tuning, the steaming (speed) error exact and small-angle, the latitude
//! (damping) error, and its full simulation as a rigid gyrostat carried by the local frame of a
//! ship — and Foucault's free gyroscope, a torque-free rotor carried by a place on the Earth.
//! SI units, radians; the core names every argument as the caller knows it. The Earth is the
//! core's default (sidereal rate, mean radius, standard gravity), as Python's default `earth`.

use crate::args::{count, let_numbers, Count, Number};
use crate::convert::{getters, Failure, Out};
use crate::{calls, fields};
use poinsot::dynamics::{self as dy, Method, Ship, SimulateOptions};
use poinsot::earth::Earth;
use wasm_bindgen::prelude::wasm_bindgen;

/// The browser's step limit for a compass run (the core's tolerances; the default moments take
/// about 10⁵ steps per simulated hour, the lab's ten times heavier element 10⁴): a longer run is
/// refused naming `duration`.
const BROWSER_MAX_STEPS: usize = 1_000_000;

/// Bytes kept per sample of a run (the inertial trajectory's state, the relative attitude and
/// the headings): the samples' budget.
const BYTES_PER_SAMPLE: usize = 320;

fn step_limit(mut e: poinsot::Error) -> Failure {
    if e.argument == "max_steps" {
        e.message = format!("too long for the step limit of the browser: {}", e.message);
        e.argument = "duration".into();
    }
    Failure::from(e)
}

fn options(samples: &Count) -> Out<SimulateOptions> {
    let t = dy::COMPASS_TOLERANCES;
    Ok(SimulateOptions {
        method: Method::Dop853,
        samples: count("samples", samples, BYTES_PER_SAMPLE)?,
        rtol: t.rtol,
        atol: t.atol,
        max_steps: BROWSER_MAX_STEPS,
        ..SimulateOptions::default()
    })
}

/// A pendulous gyrocompass at a latitude (`poinsot.Gyrocompass` in Python).
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct Gyrocompass {
    inner: dy::Gyrocompass,
}

/// The sampled motion of a compass (`poinsot.CompassRun`): times (s), heading of the spin axis
/// clockwise from true north (rad), its tilt above the horizontal (rad), the ship's latitude.
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct CompassRun {
    inner: dy::CompassRun,
}

calls!(Gyrocompass::new {
    " A compass at `latitude` λ (rad; not a pole) with rotor momentum `angular_momentum` H"
    " (kg·m²/s, > 0), pendulosity `pendulosity` P = m g l (N·m), damping ratio `damping` ζ in"
    " [0, 1) and the element's moments `inertia` (kg·m², 3 numbers) on the default Earth."
    (latitude: number, angular_momentum: number, pendulosity: number, damping: number, inertia: triple)
        = dy::Gyrocompass::new[Earth::default()];
});

calls!(fn Gyrocompass {
    " The compass whose period is Schuler's 2π √(R/g) (84.4 min): H = P Ω cos λ R / g"
    " (`Gyrocompass.schuler_tuned`)."
    schulerTuned schuler_tuned(latitude: number, pendulosity: number, damping: number, inertia: triple)
        -> Gyrocompass = dy::Gyrocompass::schuler_tuned[Earth::default()];
});

calls!(Gyrocompass {
    " The steaming error δ = atan(V cos C / (Ω R cos λ + V sin C)) (rad; positive: reads"
    " high) for `speed` V (m/s) and `course` C (rad, clockwise from north)."
    speedError speed_error(speed: number, course: number) -> number;
    " The manufacturers' small-angle form V cos C / (Ω R cos λ) (rad)."
    speedErrorSmallAngle speed_error_small_angle(speed: number, course: number) -> number;
});

fields!(Gyrocompass {
    " Latitude λ (rad)."
    latitude latitude -> number(latitude);
    " The rotor's angular momentum H (kg·m²/s)."
    angularMomentum angular_momentum -> number(angular_momentum);
});

getters!(Gyrocompass {
    " ω_n of the linearised equations (rad/s)."
    naturalFrequency natural_frequency;
    " The damping torque's coefficient D = 2 ζ ω_n H (N·m/rad)."
    dampingCoefficient damping_coefficient;
    " The ground's eastward speed Ω R cos λ (m/s)."
    groundSpeed ground_speed;
});

getters!(Gyrocompass? {
    " The undamped period of the settling oscillation, 2π √(H/(P Ω cos λ)) (s)."
    period period;
});

fields!(CompassRun {
    " The sample times (s)."
    times times -> numbers(t);
    " The spin axis's heading at each sample, clockwise from true north (rad, (−π, π])."
    heading heading -> numbers(heading);
    " The spin axis's tilt above the horizontal at each sample (rad)."
    tilt tilt -> numbers(tilt);
    " The ship's latitude at each sample (rad)."
    latitude latitude -> numbers(latitude);
});

#[wasm_bindgen]
impl Gyrocompass {
    /// Schuler's period 2π √(R/g) (s) of the default Earth: 5063.5 s = 84.4 min.
    #[wasm_bindgen(js_name = schulerPeriod)]
    pub fn schuler_period() -> f64 {
        dy::Gyrocompass::schuler_period(&Earth::default())
    }

    /// The core's default pendulosity P (N·m).
    #[wasm_bindgen(js_name = defaultPendulosity)]
    pub fn default_pendulosity() -> f64 {
        dy::COMPASS_PENDULOSITY
    }

    /// The core's default damping ratio ζ.
    #[wasm_bindgen(js_name = defaultDamping)]
    pub fn default_damping() -> f64 {
        dy::COMPASS_DAMPING
    }

    /// The latitude (damping) error of the settled compass at rest (rad; what it reads minus
    /// true north): `Gyrocompass.settle_error`.
    #[wasm_bindgen(getter, js_name = settleError)]
    pub fn settle_error(&self) -> Out<f64> {
        Ok(self.inner.settle()?.0)
    }
    /// The settled spin axis's tilt (rad): `Gyrocompass.settle_tilt`.
    #[wasm_bindgen(getter, js_name = settleTilt)]
    pub fn settle_tilt(&self) -> Out<f64> {
        Ok(self.inner.settle()?.1)
    }

    /// The compass integrated as a rigid gyrostat carried by the ship's local frame for
    /// `duration` s from heading `heading0` and tilt `tilt0` (rad), at rest on a ship of `speed`
    /// (m/s) on `course` (rad), `samples` evenly spaced times; DOP853 with the core's
    /// tolerances (`Gyrocompass.simulate`). A run beyond the browser's step limit is refused
    /// naming `duration`.
    pub fn simulate(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] duration: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] heading0: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] tilt0: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] speed: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] course: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] samples: Count,
    ) -> Out<CompassRun> {
        let_numbers!(duration, heading0, tilt0, speed, course);
        let opts = options(&samples)?;
        let ship = Ship::new(speed, course)?;
        let inner = self
            .inner
            .simulate(duration, heading0, tilt0, Some(ship), &opts)
            .map_err(step_limit)?;
        Ok(CompassRun { inner })
    }
}

/// Foucault's free gyroscope (1852) on the default Earth: the core's `free_gyroscope` (a rotor
/// spinning at `spin` rad/s, its axis at heading `heading0` and tilt `tilt0` (rad) at rest on
/// the ground at `latitude` (rad), for `duration` s, `samples` evenly spaced times). Returns the
/// rotor's attitude relative to the ground at each sample, `[w, x, y, z, ...]` (body → ENU; the
/// spin axis is body axis 1, x). Errors name `latitude`, `heading0`, `tilt0`, `spin`,
/// `duration` or `samples`.
#[wasm_bindgen(js_name = freeGyroscope)]
pub fn free_gyroscope(
    #[wasm_bindgen(unchecked_param_type = "number")] latitude: Number,
    #[wasm_bindgen(unchecked_param_type = "number")] heading0: Number,
    #[wasm_bindgen(unchecked_param_type = "number")] tilt0: Number,
    #[wasm_bindgen(unchecked_param_type = "number")] spin: Number,
    #[wasm_bindgen(unchecked_param_type = "number")] duration: Number,
    #[wasm_bindgen(unchecked_param_type = "number")] samples: Count,
) -> Out<Vec<f64>> {
    let_numbers!(latitude, heading0, tilt0, spin, duration);
    let samples = count("samples", &samples, BYTES_PER_SAMPLE)?;
    let earth = Earth::default();
    let run = dy::free_gyroscope(earth, latitude, heading0, tilt0, spin, duration, samples)?;
    Ok(run.into_iter().flatten().collect())
}

/// The rate (rad/s, clockwise positive) at which the heading of an axis fixed in inertial space
/// — Foucault's free gyroscope's — turns as seen from the ground at `latitude` (rad) on the
/// default Earth, the axis at heading `heading` (rad, clockwise from north) and tilt `tilt`
/// (rad): the core's `fixed_axis_heading_rate`, Ω (sin λ − cos λ tan θ cos α) (Ω sin λ for a
/// horizontal axis). Errors name `latitude`, `heading` or `tilt`.
#[wasm_bindgen(js_name = fixedAxisHeadingRate)]
pub fn fixed_axis_heading_rate(
    #[wasm_bindgen(unchecked_param_type = "number")] latitude: Number,
    #[wasm_bindgen(unchecked_param_type = "number")] heading: Number,
    #[wasm_bindgen(unchecked_param_type = "number")] tilt: Number,
) -> Out<f64> {
    let_numbers!(latitude, heading, tilt);
    Ok(dy::fixed_axis_heading_rate(
        &Earth::default(),
        latitude,
        heading,
        tilt,
    )?)
}
