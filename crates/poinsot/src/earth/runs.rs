//! The Earth's runs as the front ends make them: their default arguments and tolerances, their
//! sample grid, the ring of parcels of the flow into a low and its pull → strength set-up, the
//! sense of a measured rotation, and the state at any time of a sampled run (seeking by
//! continuing the integration from the last sample before it).
//!
//! Python (`poinsot.Earth.foucault`, `.inertial_oscillation`, `.flow_into_low`, `.drop`) and the
//! browser lab call these, so that their defaults, samples and classifications cannot differ:
//! they are written once, here.

use std::f64::consts::TAU;

use super::pendulum::FoucaultRun;
use super::pendulum_measurement::{FoucaultMeasurement, Sense};
use super::planet::Earth;
use super::winds::{InertialRun, LowRun};
use crate::error::{check_finite, check_non_negative, check_positive, Error, Result};
use crate::frames::ParticleState;
use crate::integrate::{sample_before, sample_times, Options, Tolerances};
use crate::limits::{check_bytes, check_count};
use crate::Vec3;

/// Tolerances of the exact drop and of projectiles ([`Earth::drop`], [`Earth::projectile`]):
/// rtol = atol = 1e-12 (m, m/s), 10⁶ steps.
pub const DROP_TOLERANCES: Tolerances = Tolerances {
    rtol: 1e-12,
    atol: 1e-12,
    max_steps: 1_000_000,
};
/// Samples of a drop's or a projectile's trajectory.
pub const DROP_SAMPLES: usize = 201;

/// Tolerances of the Foucault pendulum ([`Earth::foucault_swing`]): rtol 1e-10, atol 1e-12
/// (m, m/s), 10⁷ steps — the swing plane's angle to ~1e-9 rad over an hour.
pub const FOUCAULT_TOLERANCES: Tolerances = Tolerances {
    rtol: 1e-10,
    atol: 1e-12,
    max_steps: 10_000_000,
};
/// The Foucault pendulum's default length (m): the Panthéon's, 67 m.
pub const FOUCAULT_LENGTH: f64 = 67.0;
/// The default release distance of the bob from its rest position (m).
pub const FOUCAULT_AMPLITUDE: f64 = 1.0;
/// The default release direction (rad, clockwise from north): north.
pub const FOUCAULT_AZIMUTH: f64 = 0.0;
/// The default length of a Foucault run (s): an hour.
pub const FOUCAULT_DURATION: f64 = 3600.0;
/// The default samples of a Foucault run.
pub const FOUCAULT_SAMPLES: usize = 1001;

/// The length (s) of one stretch of a Foucault run integrated in stretches to report progress
/// ([`foucault_stretches`]): a minute.
pub const FOUCAULT_STRETCH: f64 = 60.0;
/// The most stretches of a Foucault run integrated in stretches.
pub const FOUCAULT_MAX_STRETCHES: usize = 100;

/// The number of stretches in which a Foucault run of `duration` (s) is integrated when its
/// progress is shown: one per [`FOUCAULT_STRETCH`], between 1 and [`FOUCAULT_MAX_STRETCHES`].
pub fn foucault_stretches(duration: f64) -> usize {
    let n = (duration / FOUCAULT_STRETCH).ceil();
    if n.is_nan() || n < 1.0 {
        1
    } else {
        n.min(FOUCAULT_MAX_STRETCHES as f64) as usize
    }
}

/// Tolerances of inertial oscillations ([`Earth::inertial_swing`]): rtol 1e-12, atol 1e-9
/// (m, m/s), 10⁶ steps.
pub const INERTIAL_TOLERANCES: Tolerances = Tolerances {
    rtol: 1e-12,
    atol: 1e-9,
    max_steps: 1_000_000,
};
/// The default velocity `[v_east, v_north]` of an inertial oscillation (m/s).
pub const INERTIAL_VELOCITY: [f64; 2] = [10.0, 0.0];
/// The default length of an inertial oscillation, in inertial periods π/(ω |sin λ|).
pub const INERTIAL_PERIODS: f64 = 2.0;
/// The default length of an inertial oscillation where there is no period (the equator, or a
/// planet that does not spin): a day (s).
pub const INERTIAL_EQUATOR_DURATION: f64 = 86400.0;
/// The default samples of an inertial oscillation.
pub const INERTIAL_SAMPLES: usize = 401;

/// Tolerances of the flow into a low ([`Earth::low_flow`]): rtol 1e-12, atol 1e-6 (m, m/s:
/// the parcels travel hundreds of km), 10⁶ steps.
pub const LOW_TOLERANCES: Tolerances = Tolerances {
    rtol: 1e-12,
    atol: 1e-6,
    max_steps: 1_000_000,
};
/// The default radius of the ring of parcels (m): 500 km.
pub const LOW_RADIUS: f64 = 5e5;
/// The default number of parcels on the ring.
pub const LOW_PARCELS: usize = 8;
/// The default pull of the low at the ring (m/s²).
pub const LOW_PULL: f64 = 1e-3;
/// The default friction rate γ (1/s).
pub const LOW_FRICTION: f64 = 1e-5;
/// The default length of the flow into a low (s): two days.
pub const LOW_DURATION: f64 = 2.0 * 86400.0;
/// The default samples of the flow into a low.
pub const LOW_SAMPLES: usize = 401;

/// Bytes per sample of a Foucault run's output: the time and the state (8 + 48), and the
/// front ends' copy of the time (8).
pub const FOUCAULT_BYTES_PER_SAMPLE: usize = 8 + 8 + 48;
/// Bytes per sample of an inertial oscillation: the time (twice) and the state (32).
pub const INERTIAL_BYTES_PER_SAMPLE: usize = 8 + 8 + 32;
/// Bytes per sample shared by all parcels of a flow into a low: the time (twice).
pub const LOW_BYTES_PER_SAMPLE: usize = 8 + 8;
/// Bytes per parcel and sample of a flow into a low: the state (32), its energy and the work
/// against friction (8 + 8).
pub const LOW_BYTES_PER_PARCEL_SAMPLE: usize = 32 + 8 + 8;

/// The relative threshold of [`Sense::of`]: a rate or circulation within `SENSE_THRESHOLD ·
/// scale` of zero has no sense. 1e-9 is far above the round-off of the runs (rtol 1e-12: a
/// circulation at the equator comes out at ~1e-13 of its scale) and far below any rotation the
/// Coriolis force causes away from the equator (≥ 1e-5 of its scale within 0.001° of it).
pub const SENSE_THRESHOLD: f64 = 1e-9;

impl Sense {
    /// The sense of a rate or circulation `value` (counterclockwise seen from above positive)
    /// measured on a `scale` of the same unit (≥ 0: what the motion would show if it turned at
    /// all): [`Sense::None`] within [`SENSE_THRESHOLD`] · `scale` of zero (|value| ≤ 1e-9 ·
    /// scale, round-off), else [`Sense::Counterclockwise`] (> 0) or [`Sense::Clockwise`] (< 0).
    /// A NaN `value` has no sense.
    pub fn of(value: f64, scale: f64) -> Sense {
        if value.is_nan() || value.abs() <= SENSE_THRESHOLD * scale.abs() {
            Sense::None
        } else if value > 0.0 {
            Sense::Counterclockwise
        } else {
            Sense::Clockwise
        }
    }
}

/// Checks the length of a run (s): finite and > 0; the error names `duration`.
fn check_duration(duration: f64) -> Result<()> {
    check_positive("duration", duration)
}

/// The starts `[east, north]` (m) of `parcels` parcels evenly spaced on a ring of `radius` (m)
/// about the origin, the first due east, counterclockwise: parcel i at the angle 2π i / parcels.
/// Errors name `radius` (finite and > 0) and `parcels` (≥ 1).
pub fn parcel_ring(radius: f64, parcels: usize) -> Result<Vec<[f64; 2]>> {
    check_positive("radius", radius)?;
    if parcels < 1 {
        return Err(Error::invalid(
            "parcels",
            format!("must be >= 1, got {parcels}"),
        ));
    }
    Ok(ring(radius, parcels))
}

/// The ring of [`parcel_ring`], unchecked.
fn ring(radius: f64, parcels: usize) -> Vec<[f64; 2]> {
    (0..parcels)
        .map(|i| {
            let a = TAU * i as f64 / parcels as f64;
            [radius * a.cos(), radius * a.sin()]
        })
        .collect()
}

/// The flow into a low as the front ends set it up: `parcels` parcels at rest on a ring of
/// `radius` ([`parcel_ring`]) pulled in by a paraboloidal low whose pull is `pull` at the ring,
/// slowed by `friction`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LowSetup {
    /// Radius of the ring R (m, > 0).
    pub radius: f64,
    /// Number of parcels (≥ 1).
    pub parcels: usize,
    /// The pressure gradient's acceleration at the ring (m/s², > 0), growing linearly with the
    /// distance from the centre.
    pub pull: f64,
    /// The friction rate γ (1/s, ≥ 0).
    pub friction: f64,
}

impl Default for LowSetup {
    /// [`LOW_RADIUS`], [`LOW_PARCELS`], [`LOW_PULL`], [`LOW_FRICTION`].
    fn default() -> Self {
        Self {
            radius: LOW_RADIUS,
            parcels: LOW_PARCELS,
            pull: LOW_PULL,
            friction: LOW_FRICTION,
        }
    }
}

impl LowSetup {
    /// A checked set-up; errors name `radius`, `parcels`, `pull` (finite and > 0) and
    /// `friction` (≥ 0), and `radius` or `pull` where the strength [`LowSetup::strength`]
    /// overflows or underflows.
    pub fn new(radius: f64, parcels: usize, pull: f64, friction: f64) -> Result<Self> {
        check_positive("radius", radius)?;
        if parcels < 1 {
            return Err(Error::invalid(
                "parcels",
                format!("must be >= 1, got {parcels}"),
            ));
        }
        check_positive("pull", pull)?;
        check_non_negative("friction", friction)?;
        let setup = Self {
            radius,
            parcels,
            pull,
            friction,
        };
        // k = pull / R overflows for a tiny ring, underflows for a tiny pull.
        let k = setup.strength();
        if !k.is_finite() {
            return Err(Error::invalid(
                "radius",
                format!("too small for pull = {pull:e} m/s²: the low's strength pull / radius overflows"),
            ));
        }
        if k <= 0.0 {
            return Err(Error::invalid(
                "pull",
                format!("too small for radius = {radius:e} m: the low's strength pull / radius underflows to 0"),
            ));
        }
        Ok(setup)
    }

    /// The low's strength k = pull / R (1/s²): the pressure gradient's acceleration is −k r,
    /// `pull` at the ring (a paraboloidal low, the unit's Fig. 2.7).
    pub fn strength(&self) -> f64 {
        self.pull / self.radius
    }

    /// The parcels' starts on the ring ([`parcel_ring`]).
    pub fn starts(&self) -> Vec<[f64; 2]> {
        ring(self.radius, self.parcels)
    }

    /// The scale of the circulation (m²/s) for its [`Sense`]: R √(pull R), the radius times
    /// the speed the pull alone would give over the radius.
    pub fn circulation_scale(&self) -> f64 {
        self.radius * (self.pull * self.radius).sqrt()
    }
}

/// A Foucault run as the front ends make it ([`Earth::foucault_swing`]): its samples, its
/// measurement, and its state at any time of the run ([`FoucaultSwing::state_at`]).
#[derive(Debug, Clone)]
pub struct FoucaultSwing {
    /// The planet.
    pub earth: Earth,
    /// Latitude λ (rad).
    pub latitude: f64,
    /// The pendulum's length (m).
    pub length: f64,
    /// The released state (ENU, m and m/s, origin at the point of suspension).
    pub state0: ParticleState,
    /// The integrator's options of the run (and of its continuations).
    pub options: Options,
    /// The samples and turning points.
    pub run: FoucaultRun,
    /// What the run says about its swing plane.
    pub measurement: FoucaultMeasurement,
}

impl FoucaultSwing {
    /// Whether the unit's rate −ω sin λ describes this run, and if not why
    /// ([`super::UnitRateCheck`]): from the measurement, with ω/√(g/L) and the release's
    /// distance from the rest position over the length, A/L. Errors as
    /// [`Earth::foucault_theory`] (never, for a run that was made).
    pub fn unit_rate(&self) -> Result<super::UnitRateCheck> {
        let theory = self.earth.foucault_theory(self.latitude, self.length)?;
        let r0 = Vec3::new(self.state0[0], self.state0[1], self.state0[2]);
        let [east, north] = theory.displacement_of(&r0);
        let spin_ratio = self.earth.rotation_rate / (self.earth.g / self.length).sqrt();
        Ok(self
            .measurement
            .unit_rate_check(spin_ratio, east.hypot(north) / self.length))
    }

    /// The length of the run (s).
    pub fn duration(&self) -> f64 {
        self.run.t[self.run.t.len() - 1]
    }

    /// The bob's state `[x, y, z, vx, vy, vz]` (ENU, m and m/s) at time `t` (s, in [0,
    /// duration]): the sample at `t`, or the run continued from the last sample before `t`
    /// (a step or two) with the run's options. Errors name `t` (and `max_steps`, the run's).
    pub fn state_at(&self, t: f64) -> Result<ParticleState> {
        let i = sample_before(&self.run.t, t)?;
        if self.run.t[i] == t {
            return Ok(self.run.states[i]);
        }
        // The continuation's end, start and time are the caller's `t`.
        let at_t = |e: Error| {
            e.renamed("t_end", "t")
                .renamed("y0", "t")
                .renamed("state0", "t")
        };
        let rest = self
            .earth
            .foucault(
                self.latitude,
                self.length,
                self.run.states[i],
                self.run.t[i],
                t,
                &[t],
                &self.options,
            )
            .map_err(at_t)?;
        let s = rest.states[0];
        check_finite("t", &s).map(|_| s)
    }
}

/// An inertial oscillation as the front ends make it ([`Earth::inertial_swing`]).
#[derive(Debug, Clone)]
pub struct InertialSwing {
    /// The samples and the measured turning rate.
    pub run: InertialRun,
    /// The inertial period π/(ω |sin λ|) (s; ∞ at the equator).
    pub period: f64,
    /// The sense of the measured turning rate, on the scale 2ω ([`Sense::of`]): clockwise in
    /// the north, counterclockwise in the south, none at the equator.
    pub sense: Sense,
}

/// The flow into a low as the front ends make it ([`Earth::low_flow`]): the run, the sense of
/// its circulation, and the parcels at any time of the run ([`LowFlow::at`]).
#[derive(Debug, Clone)]
pub struct LowFlow {
    /// The planet.
    pub earth: Earth,
    /// Latitude λ (rad).
    pub latitude: f64,
    /// The set-up.
    pub setup: LowSetup,
    /// The integrator's options of the run (and of its continuations).
    pub options: Options,
    /// The samples, energies, dissipated work and circulation.
    pub run: LowRun,
    /// The sense of the circulation on the scale [`LowSetup::circulation_scale`]
    /// ([`Sense::of`]): counterclockwise in the north (cyclones), clockwise in the south.
    pub sense: Sense,
}

impl LowFlow {
    /// The length of the run (s).
    pub fn duration(&self) -> f64 {
        self.run.t[self.run.t.len() - 1]
    }

    /// Every parcel at time `t` (s, in [0, duration]): `[x, y, vx, vy, energy, dissipated]`
    /// (m, m/s, J/kg, J/kg), from the samples or by continuing the run from the last sample
    /// before `t`; `energy + dissipated` is each parcel's initial energy. Errors name `t` (and
    /// `max_steps`, the run's).
    pub fn at(&self, t: f64) -> Result<Vec<[f64; 6]>> {
        let i = sample_before(&self.run.t, t)?;
        let n = self.run.parcels.len();
        if self.run.t[i] == t {
            return Ok((0..n)
                .map(|p| {
                    let s = self.run.parcels[p][i];
                    let (e, d) = (self.run.energy[p][i], self.run.dissipated[p][i]);
                    [s[0], s[1], s[2], s[3], e, d]
                })
                .collect());
        }
        let from: Vec<[f64; 4]> = self.run.parcels.iter().map(|p| p[i]).collect();
        let rest = self
            .earth
            .flow_into_low_from(
                self.latitude,
                &from,
                self.run.t[i],
                self.setup.strength(),
                self.setup.friction,
                t,
                &[t],
                &self.options,
            )
            .map_err(|e| {
                e.renamed("t_end", "t")
                    .renamed("y0", "t")
                    .renamed("states", "t")
            })?;
        let rows: Vec<[f64; 6]> = (0..n)
            .map(|p| {
                let s = rest.parcels[p][0];
                // The work against friction before the sample plus the work since.
                let lost = self.run.dissipated[p][i] + rest.dissipated[p][0];
                [s[0], s[1], s[2], s[3], rest.energy[p][0], lost]
            })
            .collect();
        check_finite("t", rows.as_flattened()).map(|_| rows)
    }
}

impl Earth {
    /// A Foucault pendulum of `length` (m) released from rest `amplitude` (m) from its rest
    /// position towards `azimuth` (rad, clockwise from north) at `latitude` (rad), swung for
    /// `duration` (s) in the rotating frame ([`Earth::foucault`], the unit's eq. 2.30 with the
    /// string's tension), sampled at `samples` even times ([`sample_times`]) and measured
    /// ([`Earth::foucault_measurement`]). The defaults of the front ends are
    /// [`FOUCAULT_LENGTH`], [`FOUCAULT_AMPLITUDE`], [`FOUCAULT_AZIMUTH`],
    /// [`FOUCAULT_DURATION`], [`FOUCAULT_SAMPLES`] and [`FOUCAULT_TOLERANCES`].
    ///
    /// Errors name the arguments: `samples` (≥ 2, within the memory budget), `duration`
    /// (finite, > 0; also a run too long to represent), `latitude`, `length`, `amplitude`,
    /// `azimuth`, `max_steps` (also `rtol`, `atol`), and `amplitude` for a release that cannot be
    /// represented; `rotation_rate` where the spin overflows the pendulum's theory. Only the
    /// caller's arguments are named.
    #[allow(clippy::too_many_arguments)]
    pub fn foucault_swing(
        &self,
        latitude: f64,
        length: f64,
        amplitude: f64,
        azimuth: f64,
        duration: f64,
        samples: usize,
        tolerances: &Tolerances,
    ) -> Result<FoucaultSwing> {
        self.foucault_swing_in(
            latitude, length, amplitude, azimuth, duration, samples, tolerances, 1,
        )
    }

    /// [`Earth::foucault_swing`] integrated in `stretches` (≥ 1) equal stretches of time, each
    /// continuing from the end of the one before, with the fraction of the run done reported
    /// to the core's monitor ([`crate::control::report`]) after each: a front end shows the
    /// progress of a long run (see [`foucault_stretches`]) and can stop it between stretches.
    /// One stretch is [`Earth::foucault_swing`]; more agree with it to the tolerances (the
    /// integrator restarts at each joint).
    #[allow(clippy::too_many_arguments)]
    pub fn foucault_swing_in(
        &self,
        latitude: f64,
        length: f64,
        amplitude: f64,
        azimuth: f64,
        duration: f64,
        samples: usize,
        tolerances: &Tolerances,
        stretches: usize,
    ) -> Result<FoucaultSwing> {
        check_count("samples", samples, 2, FOUCAULT_BYTES_PER_SAMPLE)?;
        if stretches < 1 {
            return Err(Error::invalid(
                "stretches",
                format!("must be >= 1, got {stretches}"),
            ));
        }
        check_duration(duration)?;
        // The inner calls' names for the run's arguments: the integration's end and time, and
        // the turning points, are the duration's; its start (a release that cannot be
        // represented: a `length` beyond double precision, which `amplitude` < `length` follows)
        // is the amplitude's.
        let names = |e: Error| {
            e.renamed("t_end", "duration")
                .renamed("t", "duration")
                .renamed("turn_times", "duration")
                .renamed("turn_angles", "duration")
                .renamed("state0", "amplitude")
                .renamed("y0", "amplitude")
        };
        let state0 = self
            .foucault_release(latitude, length, amplitude, azimuth)
            .map_err(names)?;
        let times =
            sample_times(0.0, duration, samples, FOUCAULT_BYTES_PER_SAMPLE).map_err(names)?;
        let options = tolerances.options(false);
        let run = if stretches == 1 {
            self.foucault(latitude, length, state0, 0.0, duration, &times, &options)
                .map_err(names)?
        } else {
            let edges = crate::integrate::even_times(0.0, duration, stretches + 1);
            let mut run = FoucaultRun {
                t: Vec::with_capacity(samples),
                states: Vec::with_capacity(samples),
                turn_times: Vec::new(),
                turn_angles: Vec::new(),
                final_state: state0,
                stats: Default::default(),
            };
            let mut next = 0;
            for (i, edge) in edges.windows(2).enumerate() {
                let (a, b) = (edge[0], edge[1]);
                // The samples of this stretch: [a, b), and b itself in the last.
                let last = i + 2 == edges.len();
                let end = next + times[next..].partition_point(|&t| t < b || last);
                let part = self
                    .foucault(
                        latitude,
                        length,
                        run.final_state,
                        a,
                        b,
                        &times[next..end],
                        &options,
                    )
                    .map_err(names)?;
                next = end;
                run.t.extend(part.t);
                run.states.extend(part.states);
                run.turn_times.extend(part.turn_times);
                run.turn_angles.extend(part.turn_angles);
                run.final_state = part.final_state;
                run.stats.accepted += part.stats.accepted;
                run.stats.rejected += part.stats.rejected;
                run.stats.evaluations += part.stats.evaluations;
                crate::control::report((i + 1) as f64 / stretches as f64)?;
            }
            run
        };
        let measurement = self
            .foucault_measurement(
                latitude,
                length,
                &state0,
                0.0,
                duration,
                &run.turn_times,
                &run.turn_angles,
            )
            .map_err(names)?;
        Ok(FoucaultSwing {
            earth: *self,
            latitude,
            length,
            state0,
            options,
            run,
            measurement,
        })
    }

    /// The default length of an inertial oscillation at `latitude` (s): [`INERTIAL_PERIODS`]
    /// inertial periods, or [`INERTIAL_EQUATOR_DURATION`] where there is no period.
    pub fn inertial_duration(&self, latitude: f64) -> Result<f64> {
        let period = self.inertial_period(latitude)?;
        Ok(if period.is_finite() {
            INERTIAL_PERIODS * period
        } else {
            INERTIAL_EQUATOR_DURATION
        })
    }

    /// A parcel moving with `velocity` `[v_east, v_north]` (m/s) on a frictionless level
    /// surface at `latitude` (rad) for `duration` (s; `None`: [`Earth::inertial_duration`]),
    /// sampled at `samples` even times ([`Earth::inertial_oscillation`]), with its period and
    /// the sense of its measured turning rate. Errors name `samples`, `duration`, `latitude`,
    /// `velocity` and `max_steps` (only the caller's arguments).
    pub fn inertial_swing(
        &self,
        latitude: f64,
        velocity: [f64; 2],
        duration: Option<f64>,
        samples: usize,
        tolerances: &Tolerances,
    ) -> Result<InertialSwing> {
        check_count("samples", samples, 2, INERTIAL_BYTES_PER_SAMPLE)?;
        let period = self.inertial_period(latitude)?;
        let duration = match duration {
            Some(d) => d,
            None => self.inertial_duration(latitude)?,
        };
        check_duration(duration)?;
        // The inner calls' end and time are the duration's, their start the velocity's.
        let names = |e: Error| {
            e.renamed("t_end", "duration")
                .renamed("t", "duration")
                .renamed("y0", "velocity")
        };
        let times =
            sample_times(0.0, duration, samples, INERTIAL_BYTES_PER_SAMPLE).map_err(names)?;
        let run = self
            .inertial_oscillation(
                latitude,
                velocity,
                duration,
                &times,
                &tolerances.options(false),
            )
            .map_err(names)?;
        let sense = Sense::of(run.turning_rate, 2.0 * self.rotation_rate);
        Ok(InertialSwing { run, period, sense })
    }

    /// Parcels of `setup` drawn into a low at `latitude` (rad) for `duration` (s), sampled at
    /// `samples` even times ([`Earth::flow_into_low`] from [`LowSetup::starts`] with
    /// [`LowSetup::strength`]), with the sense of their circulation. The defaults of the front
    /// ends are [`LowSetup::default`], [`LOW_DURATION`], [`LOW_SAMPLES`] and
    /// [`LOW_TOLERANCES`]. Errors name `samples` (≥ 2; parcels × samples within the memory
    /// budget), `duration`, `latitude`, `radius`, `parcels`, `pull`, `friction` and `max_steps`
    /// (only the caller's arguments).
    pub fn low_flow(
        &self,
        latitude: f64,
        setup: &LowSetup,
        duration: f64,
        samples: usize,
        tolerances: &Tolerances,
    ) -> Result<LowFlow> {
        let setup = LowSetup::new(setup.radius, setup.parcels, setup.pull, setup.friction)?;
        check_count(
            "parcels",
            setup.parcels,
            1,
            LOW_BYTES_PER_SAMPLE + LOW_BYTES_PER_PARCEL_SAMPLE,
        )?;
        check_count(
            "samples",
            samples,
            2,
            LOW_BYTES_PER_SAMPLE + LOW_BYTES_PER_PARCEL_SAMPLE,
        )?;
        let (np, ns) = (setup.parcels as f64, samples as f64);
        check_bytes(
            "samples",
            &format!("{} parcels × {samples} samples", setup.parcels),
            np * ns * LOW_BYTES_PER_PARCEL_SAMPLE as f64 + ns * LOW_BYTES_PER_SAMPLE as f64,
        )?;
        check_duration(duration)?;
        // The inner calls' end and time are the duration's; their start (the parcels at rest on
        // the ring) and the strength are the pull's.
        let names = |e: Error| {
            e.renamed("t_end", "duration")
                .renamed("t", "duration")
                .renamed("y0", "pull")
                .renamed("strength", "pull")
                .renamed("starts", "radius")
        };
        let times = sample_times(0.0, duration, samples, LOW_BYTES_PER_SAMPLE).map_err(names)?;
        let options = tolerances.options(false);
        let run = self
            .flow_into_low(
                latitude,
                &setup.starts(),
                setup.strength(),
                setup.friction,
                duration,
                &times,
                &options,
            )
            .map_err(names)?;
        let sense = Sense::of(run.circulation, setup.circulation_scale());
        Ok(LowFlow {
            earth: *self,
            latitude,
            setup,
            options,
            run,
            sense,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn fast() -> Earth {
        Earth::new(300.0 * super::super::SIDEREAL_RATE, 6.371e6, 9.80665).unwrap()
    }

    #[test]
    fn sense_has_a_dead_band_of_1e_9_of_the_scale() {
        assert_eq!(Sense::of(2e-9, 1.0), Sense::Counterclockwise);
        assert_eq!(Sense::of(-2e-9, 1.0), Sense::Clockwise);
        assert_eq!(Sense::of(1e-9, 1.0), Sense::None);
        assert_eq!(Sense::of(-1e-9, 1.0), Sense::None);
        assert_eq!(Sense::of(0.0, 0.0), Sense::None);
        assert_eq!(Sense::of(f64::NAN, 1.0), Sense::None);
        // Negative control: without a scale any non-zero round-off would have a sense.
        assert_eq!(Sense::of(1e-300, 0.0), Sense::Counterclockwise);
    }

    #[test]
    fn ring_starts_due_east_and_turns_counterclockwise() {
        let r = parcel_ring(2.0, 4).unwrap();
        assert_eq!(r[0], [2.0, 0.0]);
        assert!((r[1][0]).abs() < 1e-15 && r[1][1] == 2.0, "{r:?}");
        assert!(r[2][0] == -2.0 && r[2][1].abs() < 1e-15, "{r:?}");
        assert_eq!(parcel_ring(0.0, 4).unwrap_err().argument, "radius");
        assert_eq!(parcel_ring(1.0, 0).unwrap_err().argument, "parcels");
        let setup = LowSetup::default();
        assert_eq!(
            setup.starts(),
            parcel_ring(LOW_RADIUS, LOW_PARCELS).unwrap()
        );
    }

    #[test]
    fn the_pull_at_the_ring_is_strength_times_radius() {
        let s = LowSetup::new(5e5, 8, 1e-3, 1e-5).unwrap();
        assert!((s.strength() * s.radius / s.pull - 1.0).abs() < 1e-15);
        assert_eq!(
            LowSetup::new(5e5, 8, -1.0, 0.0).unwrap_err().argument,
            "pull"
        );
        assert_eq!(
            LowSetup::new(5e5, 8, 1e-3, -1.0).unwrap_err().argument,
            "friction"
        );
        assert_eq!(
            LowSetup::new(5e5, 0, 1e-3, 0.0).unwrap_err().argument,
            "parcels"
        );
        assert_eq!(
            LowSetup::new(1e-300, 8, 1e300, 0.0).unwrap_err().argument,
            "radius"
        );
        assert_eq!(
            LowSetup::new(1e300, 8, 1e-300, 0.0).unwrap_err().argument,
            "pull"
        );
    }

    proptest! {
        /// Every parcel on the ring, evenly spaced: neighbours a chord 2R sin(π/n) apart.
        #[test]
        fn ring_is_even(radius in 1e-3f64..1e7, n in 1usize..64) {
            let r = parcel_ring(radius, n).unwrap();
            prop_assert_eq!(r.len(), n);
            let chord = 2.0 * radius * (std::f64::consts::PI / n as f64).sin();
            for (i, p) in r.iter().enumerate() {
                prop_assert!((p[0].hypot(p[1]) / radius - 1.0).abs() < 1e-14);
                let q = r[(i + 1) % n];
                prop_assert!(((p[0] - q[0]).hypot(p[1] - q[1]) - chord).abs() <= 1e-12 * radius);
            }
        }

        /// The sense is odd in the value and blind to the scale's sign.
        #[test]
        fn sense_is_odd(v in -1e3f64..1e3, scale in 0.0f64..1e6) {
            let flip = |s: Sense| match s {
                Sense::Clockwise => Sense::Counterclockwise,
                Sense::Counterclockwise => Sense::Clockwise,
                Sense::None => Sense::None,
            };
            prop_assert_eq!(Sense::of(-v, scale), flip(Sense::of(v, scale)));
            prop_assert_eq!(Sense::of(v, -scale), Sense::of(v, scale));
        }
    }

    #[test]
    fn foucault_swing_seeks_by_continuing_the_run() {
        let e = fast();
        let swing = e
            .foucault_swing(0.8, 10.0, 1.0, 0.0, 60.0, 601, &FOUCAULT_TOLERANCES)
            .unwrap();
        assert_eq!(swing.run.t.len(), 601);
        assert_eq!(swing.duration(), 60.0);
        assert_eq!(swing.measurement.sense, Some(Sense::Clockwise));
        // On a sample: the sample itself.
        assert_eq!(
            swing.state_at(swing.run.t[10]).unwrap(),
            swing.run.states[10]
        );
        // Between samples: on the sphere |r| = L, and Jacobi's integral kept.
        let t = 0.5 * (swing.run.t[10] + swing.run.t[11]);
        let s = swing.state_at(t).unwrap();
        let r = (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]).sqrt();
        assert!((r - 10.0).abs() < 1e-8, "{r}");
        let j0 = e.jacobi_integral(0.8, &swing.state0).unwrap();
        assert!((e.jacobi_integral(0.8, &s).unwrap() - j0).abs() < 1e-8 * 98.0);
        // Continuing from the sample before t agrees with a run sampled at t from the start.
        let direct = e
            .foucault(0.8, 10.0, swing.state0, 0.0, t, &[t], &swing.options)
            .unwrap();
        for k in 0..3 {
            assert!(
                (direct.states[0][k] - s[k]).abs() < 1e-8,
                "{direct:?} {s:?}"
            );
        }
        assert_eq!(swing.state_at(61.0).unwrap_err().argument, "t");
        for (args, name) in [
            ((0.8, 10.0, 1.0, 0.0, 60.0, 1), "samples"),
            ((0.8, 10.0, 1.0, 0.0, 0.0, 11), "duration"),
            ((0.8, 10.0, 11.0, 0.0, 60.0, 11), "amplitude"),
            ((2.0, 10.0, 1.0, 0.0, 60.0, 11), "latitude"),
        ] {
            let (lat, l, a, az, d, n) = args;
            let err = e
                .foucault_swing(lat, l, a, az, d, n, &FOUCAULT_TOLERANCES)
                .unwrap_err();
            assert_eq!(err.argument, name, "{err}");
        }
    }

    #[test]
    fn a_run_in_stretches_is_the_run_to_its_tolerances() {
        assert_eq!(foucault_stretches(3600.0), 60);
        assert_eq!(foucault_stretches(1.0), 1);
        assert_eq!(foucault_stretches(1e9), FOUCAULT_MAX_STRETCHES);
        assert_eq!(foucault_stretches(f64::NAN), 1);
        let e = fast();
        let one = e
            .foucault_swing(0.8, 10.0, 1.0, 0.0, 60.0, 601, &FOUCAULT_TOLERANCES)
            .unwrap();
        let seven = e
            .foucault_swing_in(0.8, 10.0, 1.0, 0.0, 60.0, 601, &FOUCAULT_TOLERANCES, 7)
            .unwrap();
        assert_eq!(seven.run.t, one.run.t);
        assert_eq!(seven.run.turn_times.len(), one.run.turn_times.len());
        for (a, b) in seven.run.states.iter().zip(&one.run.states) {
            for k in 0..3 {
                // rtol 1e-10 on a 10 m pendulum over ~20 swings: ~1e-8 m.
                assert!((a[k] - b[k]).abs() < 1e-6, "{a:?} {b:?}");
            }
        }
        let (r1, r7) = (
            one.measurement.precession_rate.unwrap(),
            seven.measurement.precession_rate.unwrap(),
        );
        assert!((r7 / r1 - 1.0).abs() < 1e-6, "{r1} {r7}");
        // Negative control: a run of another length is not the same run.
        let other = e
            .foucault_swing_in(0.8, 10.0, 1.0, 0.0, 61.0, 601, &FOUCAULT_TOLERANCES, 7)
            .unwrap();
        assert_ne!(other.run.t, one.run.t);
        assert_eq!(
            e.foucault_swing_in(0.8, 10.0, 1.0, 0.0, 60.0, 601, &FOUCAULT_TOLERANCES, 0)
                .unwrap_err()
                .argument,
            "stretches"
        );
    }

    #[test]
    fn low_turns_with_the_hemisphere_and_seeks_within_its_energy_budget() {
        let e = Earth::default();
        let setup = LowSetup::default();
        let run = |lat| {
            e.low_flow(lat, &setup, 172800.0, 481, &LOW_TOLERANCES)
                .unwrap()
        };
        let north = run(0.8);
        assert_eq!(north.sense, Sense::Counterclockwise);
        assert_eq!(run(-0.8).sense, Sense::Clockwise);
        // The equator's circulation is round-off: not zero, but within the dead band.
        let equator = run(0.0);
        assert_eq!(equator.sense, Sense::None);
        let start = north.at(0.0).unwrap();
        for t in [3600.0, 5000.5, 172800.0] {
            let now = north.at(t).unwrap();
            for p in 0..LOW_PARCELS {
                let budget = now[p][4] + now[p][5] - start[p][4];
                assert!(
                    budget.abs() < 1e-9 * start[p][4],
                    "t {t} parcel {p}: {budget:e}"
                );
            }
        }
        assert_eq!(north.at(-1.0).unwrap_err().argument, "t");
        let big = LowSetup {
            parcels: 20_000,
            ..setup
        };
        let err = e
            .low_flow(0.8, &big, 1e5, 20_000, &LOW_TOLERANCES)
            .unwrap_err();
        assert_eq!(err.argument, "samples");
        assert!(
            err.message
                .starts_with("20000 parcels × 20000 samples would need"),
            "{err}"
        );
        assert_eq!(
            e.low_flow(0.8, &setup, 1e5, 1, &LOW_TOLERANCES)
                .unwrap_err()
                .argument,
            "samples"
        );
    }

    #[test]
    fn inertial_swing_runs_two_periods_by_default_and_turns_right_in_the_north() {
        let e = Earth::default();
        let swing = e
            .inertial_swing(
                0.7,
                INERTIAL_VELOCITY,
                None,
                INERTIAL_SAMPLES,
                &INERTIAL_TOLERANCES,
            )
            .unwrap();
        assert_eq!(swing.run.t[INERTIAL_SAMPLES - 1], 2.0 * swing.period);
        assert_eq!(swing.sense, Sense::Clockwise);
        let f = e.coriolis_parameter(0.7).unwrap();
        assert!((swing.run.turning_rate / -f - 1.0).abs() < 1e-9);
        let equator = e
            .inertial_swing(0.0, INERTIAL_VELOCITY, None, 11, &INERTIAL_TOLERANCES)
            .unwrap();
        assert_eq!(
            (equator.sense, equator.period),
            (Sense::None, f64::INFINITY)
        );
        assert_eq!(equator.run.t[10], INERTIAL_EQUATOR_DURATION);
    }

    #[test]
    fn tolerances_make_the_options() {
        let o = FOUCAULT_TOLERANCES.options(true);
        assert_eq!(
            (o.rtol, o.atol, o.max_steps, o.dense),
            (1e-10, 1e-12, 10_000_000, true)
        );
    }
}
