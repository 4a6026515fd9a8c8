//! The rigid Earth's spin axis integrated under the instantaneous torques of the Sun and the
//! Moon along their Kepler orbits ([`RigidEarth::simulate`]), and the fit that reads the mean
//! precession rate and the principal nutation back off the run ([`fit_pole`]): the averaged
//! [`RigidEarth::precession_rate`] and [`RigidEarth::nutation_amplitudes`] *checked*, not
//! recomputed.
//!
//! # The equations
//!
//! MacCullagh's formula gives the potential energy of the Earth (moments A = B < C about its
//! figure axis k̂) in the field of a point mass GM at geocentric position r:
//! V = (3GM/(2r⁵))(C − A)(k̂·r)² + terms free of k̂, so the torque is
//!
//! τ = −k̂ × ∂V/∂k̂ = (3GM/r⁵)(C − A)(r·k̂)(r × k̂)
//!
//! (the gravity-gradient torque on a symmetric body). It depends on k̂ alone, never on the
//! angle of the daily spin about it, and has no part along k̂. The angular momentum of a
//! symmetric top is L = C ω₃ k̂ + A k̂ × k̂′ (the spin about the figure axis plus the figure
//! axis's own turning; the unit's 2.98-style decomposition), so with L′ = τ:
//!
//! * k̂ × L = −A k̂′, i.e. k̂′ = (L × k̂)/A;
//! * ω₃ = L·k̂/C is constant, since (L·k̂)′ = τ·k̂ + L·(L × k̂)/A = 0.
//!
//! These are Euler's equations of the symmetric top written for L and k̂ in space (the
//! non-spinning, Resal, frame): exact for A = B, they need no resolution of the daily spin,
//! and they keep the free (Euler) nutation, which in space is the nearly diurnal circling of
//! k̂ about L at |L|/A. The integrated state is (k̂, ℓ) with ℓ = L/(C ω), ω the Earth's
//! [`RigidEarth::rotation_rate`]: ℓ′ = (3GM/r⁵)(H/ω)(r·k̂)(r × k̂) summed over the Sun and the
//! Moon, k̂′ = ω (ℓ × k̂)/(1 − H), H = (C − A)/C. The step is capped at [`MAX_STEP_FRACTION`] of
//! the free nutation's period in space (a quarter of a day): the explicit integrator
//! ([`crate::integrate::dop853`]) must follow that turn to stay stable.
//!
//! # The orbits
//!
//! Both bodies move on geocentric Kepler ellipses (Kepler's equation solved by Newton's method)
//! of the [`MeanOrbit`]s of the [`RigidEarth`] ([`super::SUN_ORBIT`], [`super::MOON_ORBIT`]):
//! the Sun in the ecliptic; the Moon inclined at i to it, its ascending node at longitude
//! Ω(t) = Ω₀ − 2π t/T_node (regressing). Ecliptic axes: x to the initial equinox, z the
//! ecliptic's north pole. The torquing GM is each orbit's `gm` (the Moon's μ GM_⊕), and r the
//! body's distance from the Earth's centre (the relative orbit), as in
//! [`RigidEarth::precession_rate_of`]; the mean motions are n² a³ = GM_⊕ + GM_☾ for the Moon
//! and GM_⊙ + GM_⊕ + GM_☾ for the Sun (they set the periods; the orbit averages of GM/r³ do not
//! depend on them). Each body starts at its perigee; the perigee lies on the ascending node
//! (the Moon's) or at the equinox (the Sun's) and does not turn (a [`MeanOrbit`] carries no
//! apsidal motion; the averaged theory does not depend on the perigee either).

use std::f64::consts::TAU;

use super::rigid::{MeanOrbit, RigidEarth, GM_EARTH};
use crate::error::{check_finite, check_positive, Error, Result};
use crate::integrate::{dop853_scan, sample_times, Crossing, Options, Stats};
use crate::Vec3;

/// The largest step of [`RigidEarth::simulate`], as a fraction of the shorter of the free
/// nutation's period in space, 2π(1 − H)/ω (0.997 sidereal days for the Earth), and the
/// bodies' orbital periods: a quarter, so that the explicit integrator follows the nearly
/// diurnal turn of the axis about L (its stability needs about a third) and the Moon's
/// fortnightly pull. For the Earth, 0.248 days.
pub const MAX_STEP_FRACTION: f64 = 0.25;
/// The default step limit of [`RigidEarth::simulate`]: 10⁷ steps (6800 years of quarter days).
pub const POLE_MAX_STEPS: usize = 10_000_000;
/// The default number of samples of [`RigidEarth::simulate`].
pub const POLE_SAMPLES: usize = 2001;
/// The default longitude of the Moon's ascending node at the start of
/// [`RigidEarth::simulate`] (rad): 0, the node at the equinox (the obliquity's nod at its
/// largest).
pub const POLE_MOON_NODE: f64 = 0.0;
/// Bytes kept per sample of [`RigidEarth::simulate`]: the time, the longitude and the
/// obliquity (24), and the integrator's state while it runs (48).
pub const POLE_BYTES_PER_SAMPLE: usize = 72;
/// The relative tolerance of [`RigidEarth::simulate`]'s integration.
const RTOL: f64 = 1e-11;
/// Its absolute tolerance (the state, k̂ and ℓ, is of order 1).
const ATOL: f64 = 1e-13;

/// The options of [`RigidEarth::simulate`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimulateOptions {
    /// Number of evenly spaced samples from 0 to the duration, both included (≥ 2).
    pub samples: usize,
    /// Ω₀, the ecliptic longitude of the Moon's ascending node at the start (rad).
    pub moon_node: f64,
    /// Whether the axis starts on the true pole of the principal nutation about the mean pole
    /// (ε₀, longitude 0): displaced by (Δψ₀ sin Ω₀, Δε₀ cos Ω₀) of
    /// [`RigidEarth::nutation_amplitudes`], so that the run nods about the mean pole. Otherwise
    /// (the default) the axis starts at obliquity ε₀, longitude 0, and the run nods about
    /// ε₀ − Δε₀ cos Ω₀.
    pub mean_pole: bool,
    /// Step limit: a run needing more than duration / (the largest step,
    /// [`MAX_STEP_FRACTION`]) steps is refused before it starts.
    pub max_steps: usize,
}

impl Default for SimulateOptions {
    fn default() -> Self {
        Self {
            samples: POLE_SAMPLES,
            moon_node: POLE_MOON_NODE,
            mean_pole: false,
            max_steps: POLE_MAX_STEPS,
        }
    }
}

/// A run of [`RigidEarth::simulate`]: the spin axis against time, in ecliptic axes.
#[derive(Debug, Clone)]
pub struct PoleRun {
    /// Sample times (s), from 0 to the duration.
    pub t: Vec<f64>,
    /// The ecliptic longitude of the equinox (the ascending node of the ecliptic on the
    /// equator), counted from the initial equinox (rad, unwrapped): the pole's own ecliptic
    /// longitude less π/2, or −ψ of the IAU. It falls at [`RigidEarth::precession_rate`].
    pub longitude: Vec<f64>,
    /// The obliquity, the angle of the axis from the ecliptic's pole (rad).
    pub obliquity: Vec<f64>,
    /// Ω₀, the longitude of the Moon's node at t = 0 (rad).
    pub moon_node: f64,
    /// Ω′ = −2π/T_node, the rate of the Moon's node (rad/s; 0 when it does not move).
    pub node_rate: f64,
    /// Work counters of the integration.
    pub stats: Stats,
}

/// What [`fit_pole`] reads off a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PoleFit {
    /// The mean rate of the longitude (rad/s): the precession rate, negative (retrograde).
    pub precession_rate: f64,
    /// The mean obliquity at t = 0 (rad).
    pub mean_obliquity: f64,
    /// The mean rate of the obliquity (rad/s): zero for a rigid Earth under a fixed ecliptic,
    /// up to the second-order terms.
    pub obliquity_rate: f64,
    /// Δψ₀ (rad): the coefficient of sin Ω in ψ = −longitude (the IAU convention of
    /// [`RigidEarth::nutation_amplitudes`]).
    pub nutation_longitude: f64,
    /// Δε₀ (rad): the coefficient of cos Ω in the obliquity.
    pub nutation_obliquity: f64,
}

/// The least-squares fit of `longitude` and `obliquity` (rad) sampled at `t` (s) to a straight
/// line plus the principal nutation, the terms in sin Ω and cos Ω of the Moon's node
/// Ω(t) = `moon_node` + `node_rate` t:
///
/// longitude = λ₀ + λ′ t − Δψ₀ sin Ω + c cos Ω,  obliquity = ε̄ + ε̄′ t + s sin Ω + Δε₀ cos Ω.
///
/// The other periodic terms (the fortnightly and semi-annual nutations, the free nutation)
/// average out over many samples. With `node_rate` 0 only the lines are fitted (the
/// nutations are 0). Errors name `t` (fewer than 4 samples, not increasing, or spanning less
/// than one node period 2π/|node_rate|: the nutation and the precession are then not told
/// apart), `longitude` and `obliquity` (lengths, not finite), `moon_node` and `node_rate`.
pub fn fit_pole(
    t: &[f64],
    longitude: &[f64],
    obliquity: &[f64],
    moon_node: f64,
    node_rate: f64,
) -> Result<PoleFit> {
    check_finite("t", t)?;
    check_finite("longitude", longitude)?;
    check_finite("obliquity", obliquity)?;
    check_finite("moon_node", &[moon_node])?;
    check_finite("node_rate", &[node_rate])?;
    let n = t.len();
    for (name, len) in [
        ("longitude", longitude.len()),
        ("obliquity", obliquity.len()),
    ] {
        if len != n {
            return Err(Error::invalid(
                name,
                format!("must have one value per time: {len} values for {n} times"),
            ));
        }
    }
    if n < 4 {
        return Err(Error::invalid(
            "t",
            format!("need at least 4 samples to fit a line and the nutation, got {n}"),
        ));
    }
    if let Some(i) = (1..n).find(|&i| t[i] <= t[i - 1]) {
        return Err(Error::invalid(
            "t",
            format!("must increase, but t[{i}] <= t[{}]", i - 1),
        ));
    }
    let span = t[n - 1] - t[0];
    let with_nutation = node_rate != 0.0;
    if with_nutation && span * node_rate.abs() < TAU {
        return Err(Error::invalid(
            "t",
            format!(
                "must span at least one period of the Moon's node (2 pi/|node_rate| = {:.4e} s) to tell the nutation from the precession, got {span:.4e} s",
                TAU / node_rate.abs()
            ),
        ));
    }
    // Columns 1, τ, sin Ω, cos Ω with τ = (t − t_mid)/span for conditioning; normal equations.
    let mid = 0.5 * (t[0] + t[n - 1]);
    let m = if with_nutation { 4 } else { 2 };
    let mut ata = nalgebra::Matrix4::<f64>::zeros();
    let mut b_lon = nalgebra::Vector4::<f64>::zeros();
    let mut b_obl = nalgebra::Vector4::<f64>::zeros();
    for i in 0..n {
        let tau = (t[i] - mid) / span;
        let (s, c) = (moon_node + node_rate * t[i]).sin_cos();
        let row = if with_nutation {
            nalgebra::Vector4::new(1.0, tau, s, c)
        } else {
            nalgebra::Vector4::new(1.0, tau, 0.0, 0.0)
        };
        ata += row * row.transpose();
        b_lon += row * longitude[i];
        b_obl += row * obliquity[i];
    }
    for j in m..4 {
        ata[(j, j)] = 1.0;
    }
    let lu = ata.lu();
    let (Some(x_lon), Some(x_obl)) = (lu.solve(&b_lon), lu.solve(&b_obl)) else {
        return Err(Error::invalid(
            "t",
            "the samples do not determine the fit (singular normal equations)",
        ));
    };
    let fit = PoleFit {
        precession_rate: x_lon[1] / span,
        mean_obliquity: x_obl[0] - x_obl[1] * mid / span,
        obliquity_rate: x_obl[1] / span,
        nutation_longitude: -x_lon[2],
        nutation_obliquity: x_obl[3],
    };
    crate::error::check_result(
        "t",
        "the fitted rates and amplitudes",
        &[
            fit.precession_rate,
            fit.mean_obliquity,
            fit.obliquity_rate,
            fit.nutation_longitude,
            fit.nutation_obliquity,
        ],
    )?;
    Ok(fit)
}

impl PoleRun {
    /// The mean precession rate and the principal nutation fitted to this run ([`fit_pole`]).
    pub fn fit(&self) -> Result<PoleFit> {
        fit_pole(
            &self.t,
            &self.longitude,
            &self.obliquity,
            self.moon_node,
            self.node_rate,
        )
    }
}

/// A body on its Kepler orbit: what the right-hand side needs, precomputed.
#[derive(Debug, Clone, Copy)]
struct Orbiter {
    /// 3 GM (H/ω) (m³/s³ per rad/s: times (r·k̂)(r × k̂)/r⁵ gives ℓ′ in 1/s).
    strength: f64,
    a: f64,
    e: f64,
    /// a √(1 − e²) (m).
    b: f64,
    /// Mean motion n (rad/s).
    n: f64,
    sin_i: f64,
    cos_i: f64,
    node0: f64,
    node_rate: f64,
}

impl Orbiter {
    fn new(orbit: &MeanOrbit, mu_total: f64, earth: &RigidEarth, node0: f64) -> Self {
        let a = orbit.semi_major_axis;
        let e = orbit.eccentricity;
        let (sin_i, cos_i) = orbit.inclination.sin_cos();
        Self {
            strength: 3.0 * orbit.gm * earth.dynamical_flattening / earth.rotation_rate,
            a,
            e,
            b: a * (1.0 - e * e).sqrt(),
            n: (mu_total / (a * a * a)).sqrt(),
            sin_i,
            cos_i,
            node0,
            node_rate: node_rate(orbit),
        }
    }

    /// The geocentric position (m) at time `t` (s), in ecliptic axes.
    fn position(&self, t: f64) -> Vec3 {
        let m = (self.n * t).rem_euclid(TAU);
        let e = self.e;
        // Kepler's equation E − e sin E = M by Newton's method from E = M + e sin M, to a
        // correction below 1e-9 rad (the next would be below 1e-17: quadratic convergence); the
        // sine and cosine of E then follow from the last ones turned by that correction.
        let (mut s, mut c) = m.sin_cos();
        let mut big_e = m + e * s;
        for _ in 0..50 {
            (s, c) = big_e.sin_cos();
            let d = (big_e - e * s - m) / (1.0 - e * c);
            big_e -= d;
            if d.abs() < 1e-9 {
                (s, c) = (s - c * d, c + s * d);
                break;
            }
        }
        // In the orbit's plane, x to the perigee (on the node), then tilted by i about the
        // node line, then turned by Ω about the ecliptic pole.
        let (x, y) = (self.a * (c - e), self.b * s);
        let (y, z) = (y * self.cos_i, y * self.sin_i);
        let (sn, cn) = if self.node_rate == 0.0 {
            self.node0.sin_cos()
        } else {
            (self.node0 + self.node_rate * t).sin_cos()
        };
        Vec3::new(cn * x - sn * y, sn * x + cn * y, z)
    }

    /// This body's part of ℓ′ = τ/(C ω) (1/s) on the axis `k`.
    fn pull(&self, t: f64, k: &Vec3) -> Vec3 {
        let r = self.position(t);
        let r2 = r.norm_squared();
        let scale = self.strength * r.dot(k) / (r2 * r2 * r2.sqrt());
        scale * r.cross(k)
    }
}

/// Ω′ = −2π/T_node of `orbit` (rad/s): 0 for an infinite period (the Sun).
fn node_rate(orbit: &MeanOrbit) -> f64 {
    if orbit.node_period.is_infinite() {
        0.0
    } else {
        -TAU / orbit.node_period
    }
}

/// Checks a [`MeanOrbit`] of the Earth; errors name `{body}.{field}`.
fn check_orbit(body: &str, orbit: &MeanOrbit) -> Result<()> {
    let name = |field: &str| format!("{body}.{field}");
    if !(orbit.gm.is_finite() && orbit.gm >= 0.0) {
        return Err(Error::invalid(
            name("gm"),
            format!("must be finite and >= 0 m^3/s^2, got {}", orbit.gm),
        ));
    }
    check_positive(&name("semi_major_axis"), orbit.semi_major_axis)?;
    if !(orbit.eccentricity.is_finite() && (0.0..1.0).contains(&orbit.eccentricity)) {
        return Err(Error::invalid(
            name("eccentricity"),
            format!("must be in [0, 1), got {}", orbit.eccentricity),
        ));
    }
    check_finite(&name("inclination"), &[orbit.inclination])?;
    if orbit.node_period.is_nan() || orbit.node_period <= 0.0 {
        return Err(Error::invalid(
            name("node_period"),
            format!(
                "must be > 0 s (infinite: a fixed node), got {}",
                orbit.node_period
            ),
        ));
    }
    Ok(())
}

impl RigidEarth {
    /// The spin axis integrated for `duration` (s) under the gravity-gradient torques of the
    /// Sun and the Moon moving on their Kepler orbits (the module's equations: exact for a
    /// symmetric Earth, the free nutation kept, the daily spin not resolved), sampled at
    /// `options.samples` even times. The mean slope of the longitude is
    /// [`Self::precession_rate`] and the obliquity nods by [`Self::nutation_amplitudes`]
    /// ([`PoleRun::fit`] reads both back).
    ///
    /// The axis starts at obliquity [`Self::obliquity`] and longitude 0 (or on the true pole
    /// about that mean pole: [`SimulateOptions::mean_pole`]), with L = C ω k̂ (no initial
    /// turning of the axis: the free nutation this leaves is of order |k̂′|/ω ~ 1e-8 rad).
    /// The work: 1.5e5 steps, 1.8e6 evaluations of the two torques, per century of the Earth
    /// (4 s of one loaded core for 400 years in the test machine; the bound is the free
    /// nutation's diurnal turn, which the explicit step must follow).
    ///
    /// Errors name `duration` (not finite and > 0), `samples` (< 2, or over the memory
    /// budget), `max_steps` (the run needs more than duration/(the largest step) steps: 1.5e5
    /// per century for the Earth),
    /// `moon_node` (not finite), `sun.*` / `moon.*` (an orbit out of range) and `obliquity`
    /// (`mean_pole` at obliquity 0); a stopped run returns the monitor's error
    /// ([`crate::control`]), polled every 1024 steps.
    pub fn simulate(&self, duration: f64, options: &SimulateOptions) -> Result<PoleRun> {
        check_positive("duration", duration)?;
        check_finite("moon_node", &[options.moon_node])?;
        check_orbit("sun", &self.sun)?;
        check_orbit("moon", &self.moon)?;
        let times = sample_times(0.0, duration, options.samples, POLE_BYTES_PER_SAMPLE)?;
        let moon_gm_total = GM_EARTH + self.moon.gm;
        let sun = Orbiter::new(&self.sun, self.sun.gm + moon_gm_total, self, 0.0);
        let moon = Orbiter::new(&self.moon, moon_gm_total, self, options.moon_node);
        let spin = self.rotation_rate / (1.0 - self.dynamical_flattening);
        let max_step = MAX_STEP_FRACTION * (TAU / spin).min(TAU / sun.n).min(TAU / moon.n);
        crate::limits::check_steps(
            duration / max_step,
            options.max_steps,
            "shorten the duration",
        )?;
        let (mut eps, mut psi) = (self.obliquity, 0.0);
        if options.mean_pole {
            let (dpsi, deps) = self.nutation_amplitudes()?;
            psi += dpsi * options.moon_node.sin();
            eps += deps * options.moon_node.cos();
        }
        let rhs = |t: f64, y: &[f64; 6], dy: &mut [f64; 6]| {
            let k = Vec3::new(y[0], y[1], y[2]);
            let l = Vec3::new(y[3], y[4], y[5]);
            let dl = sun.pull(t, &k) + moon.pull(t, &k);
            let dk = spin * l.cross(&k);
            *dy = [dk.x, dk.y, dk.z, dl.x, dl.y, dl.z];
        };
        let (se, ce) = eps.sin_cos();
        let (sp, cp) = psi.sin_cos();
        let k0 = [se * sp, se * cp, ce];
        let y0 = [k0[0], k0[1], k0[2], k0[0], k0[1], k0[2]];
        let opts = Options {
            rtol: RTOL,
            atol: ATOL,
            max_steps: options.max_steps,
            max_step,
            dense: false,
            ..Options::default()
        };
        let scan = dop853_scan(
            rhs,
            0.0,
            y0,
            duration,
            &times,
            &opts,
            |_t, _y: &[f64; 6]| 1.0,
            Crossing::Any,
        )?;
        let mut longitude = Vec::with_capacity(times.len());
        let mut obliquity = Vec::with_capacity(times.len());
        let mut previous = 0.0;
        for y in &scan.y {
            // ψ = atan2(k_x, k_y) (the IAU's, westward); the longitude is −ψ, unwrapped.
            let raw = -y[0].atan2(y[1]);
            let lon = previous + (raw - previous + std::f64::consts::PI).rem_euclid(TAU)
                - std::f64::consts::PI;
            previous = lon;
            longitude.push(lon);
            obliquity.push(y[0].hypot(y[1]).atan2(y[2]));
        }
        crate::error::check_result("duration", "the simulated longitude", &longitude)?;
        crate::error::check_result("duration", "the simulated obliquity", &obliquity)?;
        Ok(PoleRun {
            t: scan.t,
            longitude,
            obliquity,
            moon_node: options.moon_node,
            node_rate: moon.node_rate,
            stats: scan.stats,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::earth::MOON_ORBIT;

    #[test]
    fn the_kepler_orbit_has_its_distance_range_and_its_mean_inverse_cube() {
        // An exaggerated orbit (e = 0.6) so that Newton's method has work to do: the distance
        // stays in [a(1 − e), a(1 + e)], the time average of 1/r³ over a period is
        // 1/(a³(1 − e²)^{3/2}) (MeanOrbit::mean_inverse_cube), and the node turns the orbit.
        let orbit = MeanOrbit {
            eccentricity: 0.6,
            ..MOON_ORBIT
        };
        let earth = RigidEarth::default();
        let body = Orbiter::new(&orbit, GM_EARTH + orbit.gm, &earth, 0.3);
        let (a, e) = (orbit.semi_major_axis, orbit.eccentricity);
        let period = TAU / body.n;
        let n = 20_000;
        let mut mean = 0.0;
        for j in 0..n {
            let r = body.position(period * (j as f64 + 0.5) / n as f64);
            let d = r.norm();
            assert!(d >= a * (1.0 - e) * (1.0 - 1e-12) && d <= a * (1.0 + e) * (1.0 + 1e-12));
            mean += orbit.gm / (d * d * d) / n as f64;
        }
        assert!(
            (mean / orbit.mean_inverse_cube() - 1.0).abs() < 1e-9,
            "{mean}"
        );
        // Perigee at t = 0 on the node: along (cos Ω₀, sin Ω₀, 0) at a(1 − e).
        let p = body.position(0.0);
        let want = a * (1.0 - e) * Vec3::new(0.3_f64.cos(), 0.3_f64.sin(), 0.0);
        assert!((p - want).norm() < 1e-6 * a);
    }
}
