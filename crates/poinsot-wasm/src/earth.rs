//! Bindings of `poinsot::earth`: the falling body (the unit's 2.42 and the exact drop), effective
//! gravity, the Coriolis acceleration, the Foucault pendulum, inertial oscillations and the flow
//! into a low. Local frame ENU, latitude in radians north-positive.
//!
//! The runs ([`Foucault`], [`LowFlow`], [`InertialOscillation`]) are the core's
//! (`Earth::foucault_swing`, `Earth::low_flow`, `Earth::inertial_swing`): the same tolerances,
//! sample grid, set-up and sense as Python's `Earth.foucault`, `Earth.flow_into_low` and
//! `Earth.inertial_oscillation`, written once in the core. They keep their samples and give the
//! state at any time by the core's continuation of the run from the last sample before it, so
//! that an animation can be evaluated — or seeked — anywhere.

use crate::args::{count, index_in, let_numbers, number, numbers, Count, Number, Numbers};
use crate::convert::{vec_out, Failure, Out};
use crate::{calls, fields};
use poinsot::earth::{self as ea, FallModel, Gravity, LowSetup};
use poinsot::frames::ParticleState;
use wasm_bindgen::prelude::wasm_bindgen;

/// The core's errors name the caller's arguments and its results are finite, so they pass as
/// they are; but the browser's runs take the core's tolerances with a fixed step limit, not an
/// argument: a run that needs more steps is refused naming `argument`, what makes it long.
fn step_limit(argument: &'static str) -> impl Fn(poinsot::Error) -> Failure {
    move |mut e| {
        if e.argument == "max_steps" {
            e.message = format!("too long for the step limit of the browser: {}", e.message);
            e.argument = argument.into();
        }
        Failure::from(e)
    }
}

/// Bytes of a low flow's run per sample and per parcel and sample: the counts' budget.
const LOW_BYTES: usize = ea::LOW_BYTES_PER_SAMPLE + ea::LOW_BYTES_PER_PARCEL_SAMPLE;

/// The `N` numbers `what` of `value`, or a failure naming `argument`.
fn exactly<const N: usize>(argument: &str, value: &Numbers, what: &str) -> Out<[f64; N]> {
    let v = numbers(argument, value)?;
    v.as_slice().try_into().map_err(|_| {
        let message = format!("must hold {N} numbers {what}, got {}", v.len());
        Failure::invalid(argument, &message)
    })
}

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

fields!(Fall {
    " Time of flight (s)."
    time time -> number(time);
    " Eastward displacement at landing (m)."
    east east -> number(east);
    " Northward displacement at landing (m)."
    north north -> number(north);
});

#[wasm_bindgen]
impl Fall {
    /// The state `[x, y, z, vx, vy, vz]` (ENU, m and m/s, origin at the ground below the
    /// release point) at time `t` (s, in [0, time]) from the integrator's dense output.
    pub fn state(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] t: Number,
    ) -> Out<Vec<f64>> {
        let t = number("t", &t)?;
        Ok(self.inner.state_at(t)?.to_vec())
    }
}

calls!(Earth::new {
    " An Earth of angular rate `rotation_rate` (rad/s), `radius` (m) and surface gravity `g`"
    " (m/s²). The defaults (the core's, as in Python) are [`Earth::sidereal_rate`],"
    " [`Earth::mean_radius`] and [`Earth::standard_gravity`]."
    (rotation_rate: number, radius: number, g: number) = ea::Earth::new;
});

#[wasm_bindgen]
impl Earth {
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

    /// The exact drop from rest at `height` (m) and `latitude` (rad), with the core's defaults
    /// (uniform gravity, Coriolis and centrifugal terms, tolerances `DROP_TOLERANCES`).
    pub fn drop(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] height: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] latitude: Number,
    ) -> Out<Fall> {
        let_numbers!(height, latitude);
        let model = FallModel {
            gravity: Gravity::Uniform,
            rotation: true,
            centrifugal: true,
            options: ea::DROP_TOLERANCES.options(true),
        };
        let f = self
            .inner
            .drop(height, latitude, &model)
            .map_err(step_limit("height"))?;
        Ok(Fall { inner: f })
    }

    /// The effective gravity vector (ENU, m/s²) at `latitude` (rad).
    #[wasm_bindgen(js_name = effectiveGravity)]
    pub fn effective_gravity(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] latitude: Number,
    ) -> Out<Vec<f64>> {
        let latitude = number("latitude", &latitude)?;
        Ok(vec_out(&self.inner.effective_gravity(latitude)?.vector))
    }
}

calls!(Earth {
    " The first-order eastward deflection (m) of a body dropped from `height` (m) at"
    " `latitude` (rad): the unit's 2.42."
    eastwardDeflection eastward_deflection(height: number, latitude: number) -> number;
    " The second-order southward deflection (m) in the northern hemisphere."
    southwardDeflection southward_deflection(height: number, latitude: number) -> number;
    " The time (s) to fall `height` (m) in uniform gravity without rotation, √(2h/g)."
    fallTime fall_time(height: number) -> number;
    " The precession rate (rad/s) of a Foucault pendulum's swing plane, ω sin λ (clockwise seen"
    " from above in the north)."
    foucaultRate foucault_rate(latitude: number) -> number;
    " The Earth's angular velocity in the local ENU frame, ω (0, cos λ, sin λ) (rad/s)."
    omegaEnu omega_enu(latitude: number) -> vector;
    " The Coriolis acceleration −2 ω × v (ENU, m/s²) of a velocity `velocity_enu` (ENU, m/s)"
    " (`Earth.coriolis_acceleration`, the same argument's name)."
    coriolisAcceleration coriolis_acceleration(latitude: number, velocity_enu: vector) -> vector;
    " The period of inertial oscillations π/(ω |sin λ|) (s); `Infinity` at the equator (the"
    " one non-finite number this module returns: there is no inertial oscillation there)."
    inertialPeriod inertial_period(latitude: number) -> number;
    " The Coriolis parameter f = 2 ω sin λ (1/s) at `latitude` (rad)."
    coriolisParameter coriolis_parameter(latitude: number) -> number;
});

/// A Foucault pendulum swung in the rotating frame (`Earth.foucault` in Python): its samples,
/// its turning points, the core's measurement of its swing plane (rate and regime), and its
/// state at any time of the run.
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct FoucaultRun {
    inner: ea::FoucaultSwing,
    /// Whether the unit's rate −ω sin λ describes the run (`FoucaultSwing::unit_rate`, made
    /// once with the run).
    unit_rate: ea::UnitRateCheck,
}

impl FoucaultRun {
    /// The state at the time argument `t` (s).
    fn state_at(&self, t: &Number) -> Out<ParticleState> {
        let t = number("t", t)?;
        self.inner.state_at(t).map_err(step_limit("t"))
    }
}

fields!(FoucaultRun {
    " The swing plane's rate of turn fitted through the turning points (rad/s,"
    " counterclockwise seen from above positive), or `undefined` where the run shows no"
    " steady turn (see `regime`): `FoucaultRun.precession_rate`."
    precessionRate precession_rate -> option(measurement.precession_rate);
    " The swing plane's time for one full turn, 2π/|rate| (s): `Infinity` where it does not"
    " turn measurably (`regime` \"still\"), `undefined` where the run gives no rate:"
    " `FoucaultRun.full_turn_period`."
    fullTurnPeriod full_turn_period -> option(measurement.full_turn_period);
    " The unit's rate −ω sin λ (rad/s): `FoucaultRun.expected_rate`."
    expectedRate expected_rate -> number(measurement.expected_rate);
    " The unit's time for one full turn, 2π/|ω sin λ| (s; `Infinity` at the equator):"
    " `FoucaultRun.expected_full_turn_period`."
    expectedFullTurnPeriod expected_full_turn_period -> number(measurement.expected_full_turn_period);
    " The exact small-swing theory's mean rate (rad/s), or `undefined` without a stable rest"
    " position: `FoucaultRun.theory_rate`."
    theoryRate theory_rate -> option(measurement.theory_rate);
    " One sentence on the regime, with its figures: `FoucaultRun.regime_note`."
    regimeNote regime_note -> text(measurement.note);
});

fields!(FoucaultRun.unit_rate {
    " Whether the unit's rate −ω sin λ describes this run (both departures within the core's"
    " `UNIT_RATE_TOLERANCE`, the plane turning steadily or not at all): `UnitRateCheck.holds`."
    unitRateHolds unit_rate_holds -> flag(holds);
    " One sentence on whether −ω sin λ describes this run, with its figures:"
    " `UnitRateCheck.note`."
    unitRateNote unit_rate_note -> text(note);
    " ω/√(g/L), the planet's spin against the pendulum's own frequency (dimensionless):"
    " `UnitRateCheck.spin_ratio`."
    spinRatio spin_ratio -> number(spin_ratio);
    " A/L, the release's distance from rest against the length (dimensionless):"
    " `UnitRateCheck.amplitude_ratio`."
    amplitudeRatio amplitude_ratio -> number(amplitude_ratio);
    " |Δ − (−ω sin λ)| / max(|Δ|, |ω sin λ|), the exact small-swing rate's departure from the"
    " unit's (a fraction), or `undefined` without a stable rest: `UnitRateCheck.spin_departure`."
    spinDeparture spin_departure -> option(spin_departure);
    " |r − r_lin| / |r_lin|, the measured rate's departure from the small-swing theory's fit"
    " over the run (a fraction), or `undefined` without a steady turn:"
    " `UnitRateCheck.amplitude_departure`."
    amplitudeDeparture amplitude_departure -> option(amplitude_departure);
});

fields!(fn FoucaultRun {
    " The sample times (s)."
    times times -> numbers(run.t);
    " The times of the turning points of the swing (s)."
    turnTimes turn_times -> numbers(run.turn_times);
    " The bob's direction at each turning point, counterclockwise from east seen from above"
    " (rad)."
    turnAngles turn_angles -> numbers(run.turn_angles);
});

#[wasm_bindgen]
impl FoucaultRun {
    /// The length of the run (s).
    #[wasm_bindgen(getter)]
    pub fn duration(&self) -> f64 {
        self.inner.duration()
    }
    /// `"clockwise"`, `"counterclockwise"`, `"none"` (the plane does not turn) or
    /// `"undefined"` (no rate): `FoucaultRun.sense`.
    #[wasm_bindgen(getter)]
    pub fn sense(&self) -> String {
        self.inner.measurement.sense_name().into()
    }
    /// Whether the run shows a steadily turning swing plane: `"precessing"`, `"still"`,
    /// `"too_short"`, `"unsteady"`, `"wide_swing"`, `"not_a_swing"` or `"no_rest"`:
    /// `FoucaultRun.regime`.
    #[wasm_bindgen(getter)]
    pub fn regime(&self) -> String {
        self.inner.measurement.regime.name().into()
    }
    /// The core's tolerance on both departures (a fraction): `UNIT_RATE_TOLERANCE`.
    #[wasm_bindgen(js_name = unitRateTolerance)]
    pub fn unit_rate_tolerance() -> f64 {
        ea::UNIT_RATE_TOLERANCE
    }
    /// The bob's positions at the sample times, `[x0, y0, z0, x1, ...]` (ENU, m, origin at the
    /// point of suspension).
    pub fn positions(&self) -> Vec<f64> {
        self.inner
            .run
            .states
            .iter()
            .flat_map(|s| [s[0], s[1], s[2]])
            .collect()
    }
    /// The bob's state `[x, y, z, vx, vy, vz]` at time `t` (s, in [0, duration]): the sample at
    /// `t`, or the core's integration continued from the last sample before `t`.
    pub fn state(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] t: Number,
    ) -> Out<Vec<f64>> {
        Ok(self.state_at(&t)?.to_vec())
    }
    /// Jacobi's integral (J/kg) of the state at `t`: constant along the run.
    #[wasm_bindgen(js_name = jacobiIntegral)]
    pub fn jacobi_integral(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] t: Number,
    ) -> Out<f64> {
        let s = self.state_at(&t)?;
        Ok(self.inner.earth.jacobi_integral(self.inner.latitude, &s)?)
    }
}

/// Parcels drawn into a low-pressure centre (`Earth.flow_into_low` in Python): their tracks, the
/// circulation measured from the run, and their states, energies and the work done against
/// friction at any time of the run.
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct LowFlow {
    inner: ea::LowFlow,
}

fields!(fn LowFlow {
    " The sample times (s)."
    times times -> numbers(run.t);
});

#[wasm_bindgen]
impl LowFlow {
    /// The length of the run (s).
    #[wasm_bindgen(getter)]
    pub fn duration(&self) -> f64 {
        self.inner.duration()
    }
    /// The number of parcels.
    #[wasm_bindgen(getter)]
    pub fn parcels(&self) -> usize {
        self.inner.run.parcels.len()
    }
    /// The mean specific angular momentum about the centre over the run (m²/s, > 0
    /// counterclockwise): `LowFlow.circulation`.
    #[wasm_bindgen(getter)]
    pub fn circulation(&self) -> f64 {
        self.inner.run.circulation
    }
    /// `"counterclockwise"`, `"clockwise"` or `"none"`, from the simulated circulation, with the
    /// core's round-off threshold (`Sense::of`: 1e-9 · radius · √(pull · radius)):
    /// `LowFlow.sense`.
    #[wasm_bindgen(getter)]
    pub fn sense(&self) -> String {
        self.inner.sense.name().into()
    }
    /// The track of parcel `index`: `[x0, y0, x1, y1, ...]` (m, east and north) at the samples.
    pub fn track(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] index: Count,
    ) -> Out<Vec<f64>> {
        let parcels = &self.inner.run.parcels;
        let p = &parcels[index_in("index", &index, parcels.len(), "parcels")?];
        Ok(p.iter().flat_map(|s| [s[0], s[1]]).collect())
    }
    /// Every parcel at time `t` (s, in [0, duration]): six numbers each, `[x, y, vx, vy, energy,
    /// dissipated]` (m, m/s, J/kg), from the samples or by the core's continuation of the run
    /// from the last sample before `t`; `energy + dissipated` is each parcel's initial energy.
    pub fn at(&self, #[wasm_bindgen(unchecked_param_type = "number")] t: Number) -> Out<Vec<f64>> {
        let t = number("t", &t)?;
        Ok(self.inner.at(t).map_err(step_limit("t"))?.concat())
    }
}

/// An inertial oscillation (`Earth.inertial_oscillation` in Python): the measured turning rate.
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct InertialOscillation {
    inner: ea::InertialSwing,
}

#[wasm_bindgen]
impl InertialOscillation {
    /// The rate at which the velocity turned, measured from the run (rad/s, counterclockwise
    /// positive; the theory says −2 ω sin λ).
    #[wasm_bindgen(getter, js_name = turningRate)]
    pub fn turning_rate(&self) -> f64 {
        self.inner.run.turning_rate
    }
    /// The track `[x0, y0, x1, y1, ...]` (m) at the samples.
    pub fn track(&self) -> Vec<f64> {
        self.inner
            .run
            .states
            .iter()
            .flat_map(|s| [s[0], s[1]])
            .collect()
    }
}

#[wasm_bindgen]
impl Earth {
    /// Swing a Foucault pendulum of `length` (m) released from rest `amplitude` (m) from its
    /// rest position towards `azimuth` (rad, clockwise from north) at `latitude` (rad) for
    /// `duration` (s), sampled at `samples` even times, and measure its swing plane:
    /// `Earth.foucault` with the core's tolerances (`FOUCAULT_TOLERANCES`), as in Python.
    pub fn foucault(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] latitude: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] length: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] amplitude: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] azimuth: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] duration: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] samples: Count,
    ) -> Out<FoucaultRun> {
        let_numbers!(latitude, length, amplitude, azimuth, duration);
        // The count is parsed (a whole number within the memory budget) before the core checks
        // it again and makes the sample times.
        let samples = count("samples", &samples, ea::FOUCAULT_BYTES_PER_SAMPLE)?;
        // Too short a run has too few turning points to fit a rate: the measurement says so in
        // its regime. The core names the user's arguments; the step limit is the browser's.
        let inner = self
            .inner
            .foucault_swing(
                latitude,
                length,
                amplitude,
                azimuth,
                duration,
                samples,
                &ea::FOUCAULT_TOLERANCES,
            )
            .map_err(step_limit("duration"))?;
        let unit_rate = inner.unit_rate()?;
        Ok(FoucaultRun { inner, unit_rate })
    }

    /// Parcels starting at rest on a ring of `radius` (m) — `parcels` of them, the first due east,
    /// counterclockwise — pulled into a low at the centre by `pull` (m/s² at the ring, growing
    /// linearly with distance), slowed by `friction` (1/s) and turned by the Coriolis force at
    /// `latitude` (rad), for `duration` (s) sampled at `samples` even times:
    /// `Earth.flow_into_low` with the core's tolerances (`LOW_TOLERANCES`), as in Python.
    #[wasm_bindgen(js_name = flowIntoLow)]
    #[allow(clippy::too_many_arguments)]
    pub fn flow_into_low(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] latitude: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] radius: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] parcels: Count,
        #[wasm_bindgen(unchecked_param_type = "number")] pull: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] friction: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] duration: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] samples: Count,
    ) -> Out<LowFlow> {
        // The counts are parsed (whole numbers within the memory budget) before the core checks
        // them again, with their product, and makes the ring and the sample times; the numbers
        // and the counts are read in the order of the arguments.
        let_numbers!(latitude, radius);
        let parcels = count("parcels", &parcels, LOW_BYTES)?;
        let_numbers!(pull, friction, duration);
        let samples = count("samples", &samples, LOW_BYTES)?;
        let setup = LowSetup {
            radius,
            parcels,
            pull,
            friction,
        };
        let inner = self
            .inner
            .low_flow(latitude, &setup, duration, samples, &ea::LOW_TOLERANCES)
            .map_err(step_limit("duration"))?;
        Ok(LowFlow { inner })
    }

    /// A parcel set moving with `[v_east, v_north]` (m/s) on a frictionless level surface at
    /// `latitude` (rad) for `duration` (s), sampled at `samples` even times:
    /// `Earth.inertial_oscillation` with the core's tolerances (`INERTIAL_TOLERANCES`), as in
    /// Python.
    #[wasm_bindgen(js_name = inertialOscillation)]
    pub fn inertial_oscillation(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] latitude: Number,
        #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] velocity: Numbers,
        #[wasm_bindgen(unchecked_param_type = "number")] duration: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] samples: Count,
    ) -> Out<InertialOscillation> {
        let latitude = number("latitude", &latitude)?;
        let v = exactly::<2>("velocity", &velocity, "[v_east, v_north]")?;
        let duration = number("duration", &duration)?;
        let samples = count("samples", &samples, ea::INERTIAL_BYTES_PER_SAMPLE)?;
        let inner = self
            .inner
            .inertial_swing(
                latitude,
                v,
                Some(duration),
                samples,
                &ea::INERTIAL_TOLERANCES,
            )
            .map_err(step_limit("duration"))?;
        Ok(InertialOscillation { inner })
    }

    /// Jacobi's integral ½ |v|² + g z − ½ |ω × r|² (J/kg) of an ENU `state` `[x, y, z, vx, vy,
    /// vz]` at `latitude` (rad): `Earth.jacobi_integral`.
    #[wasm_bindgen(js_name = jacobiIntegral)]
    pub fn jacobi_integral(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] latitude: Number,
        #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] state: Numbers,
    ) -> Out<f64> {
        let latitude = number("latitude", &latitude)?;
        let s: ParticleState = exactly("state", &state, "[x, y, z, vx, vy, vz]")?;
        Ok(self.inner.jacobi_integral(latitude, &s)?)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convert::refused;

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
        assert!(
            (exact.east() / expect - 1.0).abs() < 1e-3,
            "{} vs {}",
            exact.east(),
            expect
        );
        let land = exact.state(exact.time()).unwrap();
        assert!(
            (land[0] - exact.east()).abs() < 1e-9 && land[2].abs() < 1e-9,
            "{land:?}"
        );
        assert!(exact.state(-1.0).is_err());
    }

    #[test]
    fn bad_latitude_throws_with_the_core_message() {
        refused(earth().drop(100.0, 2.0), "latitude");
        refused(earth().drop(-1.0, 0.5), "height");
    }

    #[test]
    fn errors_are_the_cores_with_pythons_names() {
        // Issue 22: the core names the caller's arguments as Python does; nothing is renamed here.
        let e = earth();
        let fast = Earth::new(1e300, Earth::mean_radius(), Earth::standard_gravity()).unwrap();
        refused(
            fast.coriolis_acceleration(0.5, vec![1e10, 0.0, 0.0]),
            "velocity_enu: ",
        );
        refused(e.foucault(0.8, 1e300, 1.0, 0.0, 60.0, 11.0), "amplitude: ");
        refused(e.drop(1e308, 0.5), "height: ");
    }

    #[test]
    fn methods_made_by_calls_name_each_argument() {
        // The methods `calls!` writes convert each argument under its own name, in order, and
        // the core names it when refused.
        let e = earth();
        let nan = f64::NAN;
        refused(e.eastward_deflection(nan, 0.5), "height");
        refused(e.southward_deflection(100.0, nan), "latitude");
        refused(e.fall_time(-1.0), "height");
        for refusal in [
            e.foucault_rate(nan),
            e.inertial_period(nan),
            e.coriolis_parameter(nan),
        ] {
            refused(refusal, "latitude");
        }
        refused(e.omega_enu(nan), "latitude");
        refused(e.coriolis_acceleration(nan, vec![0.0; 3]), "latitude");
        refused(
            e.coriolis_acceleration(0.5, vec![0.0; 2]),
            "velocity_enu: must hold 3",
        );
        refused(Earth::new(nan, 1.0, 1.0), "rotation_rate");
        refused(Earth::new(1.0, 1.0, -1.0), "g");
    }

    #[test]
    fn sample_times_are_the_cores() {
        let run = earth()
            .foucault(0.8, 10.0, 1.0, 0.0, 120.0, 1201.0)
            .unwrap();
        let core = poinsot::integrate::sample_times(0.0, 120.0, 1201, 8).unwrap();
        assert_eq!(run.times(), core);
        assert_eq!((run.times()[0], run.times()[1200]), (0.0, 120.0));
    }

    #[test]
    fn foucault_turns_clockwise_in_the_north_and_seeks_by_continuing() {
        let fast = Earth::new(
            300.0 * Earth::sidereal_rate(),
            Earth::mean_radius(),
            Earth::standard_gravity(),
        )
        .unwrap();
        let lat = 0.8;
        let run = fast.foucault(lat, 10.0, 1.0, 0.0, 60.0, 601.0).unwrap();
        // The fit agrees with −ω sin λ to the Airy and (ω/ω₀)² corrections (< 1 %).
        let rate = run.precession_rate().unwrap();
        assert!((rate / run.expected_rate() - 1.0).abs() < 1e-2);
        assert!((rate / run.theory_rate().unwrap() - 1.0).abs() < 1e-2);
        // One full turn beside the rate, and the unit's beside −ω sin λ (the core's fields).
        let tau = 2.0 * std::f64::consts::PI;
        assert_eq!(run.full_turn_period(), Some(tau / rate.abs()));
        assert_eq!(
            run.expected_full_turn_period(),
            tau / run.expected_rate().abs()
        );
        assert_eq!(
            (run.sense(), run.regime()),
            ("clockwise".into(), "precessing".into())
        );
        let south = fast.foucault(-lat, 10.0, 1.0, 0.0, 60.0, 601.0).unwrap();
        assert_eq!(south.sense(), "counterclockwise");
        // On a sample: the sample itself; between samples: the continued integration, close to
        // the neighbouring samples and on the sphere |r| = L.
        let times = run.times();
        assert_eq!(run.state(times[10]).unwrap(), run.state(times[10]).unwrap());
        let mid = run.state(0.5 * (times[10] + times[11])).unwrap();
        let r = (mid[0] * mid[0] + mid[1] * mid[1] + mid[2] * mid[2]).sqrt();
        assert!((r - 10.0).abs() < 1e-8, "{r}");
        let j0 = run.jacobi_integral(0.0).unwrap();
        assert!((run.jacobi_integral(37.123).unwrap() - j0).abs() < 1e-8 * 98.0);
        refused(run.state(61.0), "t: must lie in [0, 60]");
        refused(
            fast.foucault(lat, 10.0, 11.0, 0.0, 60.0, 601.0),
            "amplitude",
        );
        refused(fast.foucault(lat, 10.0, 1.0, 0.0, 0.0, 601.0), "duration");
        refused(fast.foucault(lat, 10.0, 1.0, 0.0, 60.0, 1.0), "samples");
        refused(fast.foucault(2.0, 10.0, 1.0, 0.0, 60.0, 601.0), "latitude");
    }

    #[test]
    fn low_turns_with_the_hemisphere_and_closes_its_energy_budget() {
        let e = earth();
        let low = |lat| {
            e.flow_into_low(lat, 5e5, 8.0, 1e-3, 1e-5, 172800.0, 481.0)
                .unwrap()
        };
        let (north, south, equator) = (low(0.8), low(-0.8), low(0.0));
        assert_eq!(north.sense(), "counterclockwise");
        assert_eq!(south.sense(), "clockwise");
        assert_eq!(equator.sense(), "none");
        let start = north.at(0.0).unwrap();
        for t in [3600.0, 5000.5, 172800.0] {
            let now = north.at(t).unwrap();
            for p in 0..8 {
                let budget = now[6 * p + 4] + now[6 * p + 5] - start[6 * p + 4];
                assert!(
                    budget.abs() < 1e-9 * start[6 * p + 4],
                    "t {t} parcel {p}: {budget:e}"
                );
            }
        }
        assert_eq!(north.track(0.0).unwrap().len(), 2 * 481);
        refused(north.track(8.0), "index");
        refused(north.at(-1.0), "t: ");
        let bad = |radius, parcels, pull, friction| {
            e.flow_into_low(0.8, radius, parcels, pull, friction, 1e5, 11.0)
        };
        refused(bad(5e5, 8.0, -1.0, 1e-5), "pull");
        refused(bad(5e5, 8.0, 1e-3, -1.0), "friction");
        refused(bad(0.0, 8.0, 1e-3, 0.0), "radius");
        refused(bad(5e5, 0.0, 1e-3, 0.0), "parcels");
    }

    #[test]
    fn inertial_oscillation_and_period() {
        let e = earth();
        let f = e.coriolis_parameter(0.7).unwrap();
        let period = e.inertial_period(0.7).unwrap();
        let run = e
            .inertial_oscillation(0.7, vec![10.0, 0.0], 2.0 * period, 401.0)
            .unwrap();
        assert!((run.turning_rate() / -f - 1.0).abs() < 1e-9);
        assert_eq!(e.inertial_period(0.0).unwrap(), f64::INFINITY);
        refused(
            e.inertial_oscillation(0.7, vec![10.0], 1.0, 11.0),
            "velocity",
        );
        assert!(e
            .jacobi_integral(0.7, vec![0.0; 5])
            .unwrap_err()
            .message
            .starts_with("state"));
    }
}
