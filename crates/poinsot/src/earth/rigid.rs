//! The Earth as a rigid body: an oblate symmetric top (the unit's 2.77–2.97 applied to it),
//! spinning once a sidereal day and torqued by the Sun and the Moon. Its free motion is Euler's
//! free nutation (the unit's Ω of 2.83), lengthened by the mantle's elasticity into the
//! Chandler wobble; the orbit-averaged gravity-gradient torque of the Sun and the Moon on its
//! equatorial bulge precesses its axis (the luni-solar precession of the equinoxes), and the
//! 18.6-year regression of the Moon's node makes the axis nod (the principal nutation).
//!
//! # The constants and their sources
//!
//! * H = (C − A)/C, the dynamical flattening: [`DYNAMICAL_FLATTENING`], IERS Conventions (2010),
//!   IERS Technical Note 36 (Petit & Luzum eds.), Table 1.1 "IERS numerical standards", p. 18.
//! * ω, the sidereal rotation rate: [`SIDEREAL_RATE`](super::SIDEREAL_RATE) = 7.292115e-5 rad/s,
//!   the "nominal mean angular velocity of the Earth" of IERS 2010 Table 1.1 (the GRS80 value).
//! * ε₀, the obliquity of the ecliptic at J2000.0: [`OBLIQUITY_J2000`] = 84381.406″, the IAU 2006
//!   precession (Capitaine, Wallace & Chapront 2003, A&A 412, 567, the P03 solution; IERS 2010
//!   Table 1.1).
//! * The Sun's mean orbit [`SUN_ORBIT`] and the Moon's [`MOON_ORBIT`], with GM_⊙
//!   ([`GM_SUN`]) and GM_⊕ ([`GM_EARTH`]) from IERS 2010 Table 1.1 (the IAU 2009 system), the
//!   Moon/Earth mass ratio ([`MOON_EARTH_MASS_RATIO`]) from the same table (the IAU 2009 value,
//!   Pitjeva & Standish 2009; DE430's EMRAT 81.30056907 agrees to 1e-10), the astronomical unit
//!   ([`ASTRONOMICAL_UNIT`], IAU 2012 Resolution B2), the Earth's orbital eccentricity at J2000
//!   (Simon et al. 1994, A&A 282, 663; Meeus, *Astronomical Algorithms*, 2nd ed. 1998,
//!   eq. 25.4, p. 163: e = 0.016708634 − …), and the Moon's mean elements of JPL's Horizons
//!   physical-data sheet for the Moon (301): a = 384400 km, e = 0.05490, i = 5.145°, nodal period
//!   6798.38 d (the period of the fundamental argument Ω in the IERS 2010 / Simon et al. 1994
//!   series, 18.613 Julian years).
//! * The references the results are compared with: the IAU 2006 luni-solar precession rate
//!   [`IAU2006_PRECESSION_RATE`] (ψ_A = 5038.481507″ t, Capitaine et al. 2003; IERS 2010
//!   chapter 5; ERFA's `p06e`) and the IAU 2000A principal nutation term
//!   [`IAU2000A_PRINCIPAL_NUTATION`]
//!   (−17.2064161″ sin Ω, 9.2052331″ cos Ω: Mathews, Herring & Buffett 2002, the MHB2000
//!   model; the first luni-solar term of SOFA's `iauNut00a`, ERFA's `nut00a`).
//!
//! # Signs
//!
//! [`RigidEarth::precession_rate`] is the signed angular velocity of the spin axis about the
//! ecliptic's north pole (the rate of the pole's, and of the equinox's, ecliptic longitude):
//! negative, the precession is retrograde (westward). Its magnitude is the IAU's ψ̇_A.
//! [`RigidEarth::nutation_amplitudes`] are the coefficients of sin Ω and cos Ω in the IAU's own
//! convention (Δψ counted westward, as ψ_A), so that they compare directly with IAU 2000A.

use std::f64::consts::{PI, TAU};

use crate::error::{
    check_finite, check_non_negative, check_positive, check_result, finite_result, num, Error,
    Result,
};

use super::{AveragedPole, SIDEREAL_RATE};

/// One second of arc (rad).
const ARCSECOND: f64 = PI / 648_000.0;
/// One Julian century (s): 36525 days of 86400 s.
const JULIAN_CENTURY: f64 = 36_525.0 * 86_400.0;
/// One day (s).
const DAY: f64 = 86_400.0;
/// Bytes kept per time of [`RigidEarth::averaged_pole`]: ψ, ε and Ω.
const AVERAGED_POLE_BYTES_PER_TIME: usize = 24;

/// H = (C − A)/C, the Earth's dynamical flattening (dimensionless): 3273795e-9, IERS
/// Conventions (2010), Table 1.1, p. 18 (fitted to the observed precession rate).
pub const DYNAMICAL_FLATTENING: f64 = 3.273_795e-3;
/// ε₀, the obliquity of the ecliptic at J2000.0 (rad): 84381.406″, IAU 2006 (Capitaine et al.
/// 2003; IERS Conventions (2010), Table 1.1).
pub const OBLIQUITY_J2000: f64 = 84_381.406 * ARCSECOND;
/// GM_⊙, the heliocentric gravitational constant (m³/s²): 1.32712442099e20, TCB-compatible,
/// IERS Conventions (2010), Table 1.1 (the IAU 2009 system).
pub const GM_SUN: f64 = 1.327_124_420_99e20;
/// GM_⊕, the geocentric gravitational constant (m³/s²): 3.986004418e14, IERS Conventions
/// (2010), Table 1.1.
pub const GM_EARTH: f64 = 3.986_004_418e14;
/// μ = M_Moon / M_Earth: 0.0123000371, IERS Conventions (2010), Table 1.1 (IAU 2009 system,
/// Pitjeva & Standish 2009; DE430's EMRAT = 81.30056907 gives the same to 1e-10).
pub const MOON_EARTH_MASS_RATIO: f64 = 0.012_300_037_1;
/// The astronomical unit (m): 149597870700, exact by IAU 2012 Resolution B2.
pub const ASTRONOMICAL_UNIT: f64 = 1.495_978_707e11;

/// A body's mean orbit about the Earth (geocentric), as the precession theory needs it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeanOrbit {
    /// GM of the body (m³/s²).
    pub gm: f64,
    /// Semi-major axis a of its geocentric orbit (m).
    pub semi_major_axis: f64,
    /// Eccentricity e, in [0, 1).
    pub eccentricity: f64,
    /// Mean inclination i of the orbit to the ecliptic (rad).
    pub inclination: f64,
    /// Period of the regression of the orbit's node on the ecliptic (s); infinite for the Sun,
    /// whose orbit is the ecliptic.
    pub node_period: f64,
}

impl MeanOrbit {
    /// GM / (a³ (1 − e²)^{3/2}) (1/s²): the orbit average of GM/r³ (for a Kepler ellipse,
    /// ⟨1/r³⟩ over time is 1/(a³ (1 − e²)^{3/2})).
    pub fn mean_inverse_cube(&self) -> f64 {
        let a = self.semi_major_axis;
        self.gm / (a * a * a * (1.0 - self.eccentricity * self.eccentricity).powf(1.5))
    }
}

/// The Sun's mean geocentric orbit: GM_⊙; a = 1 au (IAU 2012 B2); e = 0.0167086 (Simon et al.
/// 1994; Meeus 1998 eq. 25.4, p. 163, at J2000); the ecliptic itself (i = 0, no node).
pub const SUN_ORBIT: MeanOrbit = MeanOrbit {
    gm: GM_SUN,
    semi_major_axis: ASTRONOMICAL_UNIT,
    eccentricity: 0.016_708_6,
    inclination: 0.0,
    node_period: f64::INFINITY,
};

/// The Moon's mean geocentric orbit: GM_☾ = μ GM_⊕ (IERS 2010 Table 1.1); a = 384400 km,
/// e = 0.0549, i = 5.145° to the ecliptic, node regression period 6798.38 d (18.6 yr): JPL
/// Horizons' physical-data sheet of the Moon (301), "Semi-major axis, a = 384400 km,
/// Eccentricity = 0.05490, Inclination = 5.145 deg, Nodal period = 6798.38 d"; the same nodal
/// period is that of the argument Ω of the IERS 2010 nutation series.
pub const MOON_ORBIT: MeanOrbit = MeanOrbit {
    gm: MOON_EARTH_MASS_RATIO * GM_EARTH,
    semi_major_axis: 3.844e8,
    eccentricity: 0.0549,
    inclination: 5.145 * PI / 180.0,
    node_period: 6_798.38 * DAY,
};

/// The IAU 2006 luni-solar precession rate ψ̇_A at J2000 (rad/s, positive westward):
/// 5038.481507″ per Julian century (Capitaine et al. 2003; IERS Conventions (2010),
/// chapter 5; ERFA's `p06e`, which test_rigid_earth.py differentiates). It contains, besides
/// the first-order luni-solar term of this module, the geodesic precession (−1.92″/cy),
/// planetary and second-order terms (Capitaine et al. 2003).
pub const IAU2006_PRECESSION_RATE: f64 = 5_038.481_507 * ARCSECOND / JULIAN_CENTURY;
/// The IAU 2000A principal (18.6-year) nutation term (rad): (Δψ, Δε) = (−17.2064161″ sin Ω,
/// 9.2052331″ cos Ω), the first luni-solar term of the IAU 2000A series (SOFA's `iauNut00a`;
/// MHB2000, Mathews, Herring & Buffett 2002), non-rigid Earth.
pub const IAU2000A_PRINCIPAL_NUTATION: (f64, f64) =
    (-17.206_416_1 * ARCSECOND, 9.205_233_1 * ARCSECOND);

/// The Earth as a rigid, symmetric (A = B < C) top: dynamical flattening H = (C − A)/C, spin
/// rate ω about its figure axis, obliquity ε of its equator to the ecliptic, torqued by the Sun
/// and the Moon on their mean orbits ([`SUN_ORBIT`], [`MOON_ORBIT`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidEarth {
    /// H = (C − A)/C, in (0, 1).
    pub dynamical_flattening: f64,
    /// ω (rad/s), > 0.
    pub rotation_rate: f64,
    /// ε (rad), in [0, π/2).
    pub obliquity: f64,
    /// The Sun's mean orbit.
    pub sun: MeanOrbit,
    /// The Moon's mean orbit.
    pub moon: MeanOrbit,
}

impl Default for RigidEarth {
    /// The IERS 2010 Earth: H, the sidereal rate, the obliquity at J2000, the mean orbits.
    fn default() -> Self {
        Self {
            dynamical_flattening: DYNAMICAL_FLATTENING,
            rotation_rate: SIDEREAL_RATE,
            obliquity: OBLIQUITY_J2000,
            sun: SUN_ORBIT,
            moon: MOON_ORBIT,
        }
    }
}

impl RigidEarth {
    /// A rigid Earth of dynamical flattening H ∈ (0, 1), rotation rate ω > 0 (rad/s) and
    /// obliquity ε ∈ [0, π/2) (rad), with the Sun's and the Moon's mean orbits; each error
    /// names its argument. H = 0 (a sphere: no bulge, no torque, no free wobble) is refused.
    pub fn new(dynamical_flattening: f64, rotation_rate: f64, obliquity: f64) -> Result<Self> {
        let h = dynamical_flattening;
        if !(h.is_finite() && h > 0.0 && h < 1.0) {
            return Err(Error::invalid(
                "dynamical_flattening",
                format!(
                    "must be in (0, 1): H = (C - A)/C of an oblate body (C > A; A + B >= C bounds it by 1), got {}",
                    num(h)
                ),
            ));
        }
        check_positive("rotation_rate", rotation_rate)?;
        if !(obliquity.is_finite() && (0.0..PI / 2.0).contains(&obliquity)) {
            return Err(Error::invalid(
                "obliquity",
                format!(
                    "must be finite and in [0, pi/2) rad ([0, 90) degrees), got {} rad",
                    num(obliquity)
                ),
            ));
        }
        Ok(Self {
            dynamical_flattening: h,
            rotation_rate,
            obliquity,
            sun: SUN_ORBIT,
            moon: MOON_ORBIT,
        })
    }

    /// (C − A)/A = H/(1 − H): the unit's |I₃ − I₁|/I₁.
    fn flattening_over_a(&self) -> f64 {
        let h = self.dynamical_flattening;
        h / (1.0 - h)
    }

    /// The unit's Ω of 2.83 for the Earth (rad/s): Ω = (I₁ − I₃) ω₃ / I₁ = −H/(1 − H) ω.
    /// Negative: by Euler's equations ω₁′ = Ω ω₂, ω₂′ = −Ω ω₁, so the equatorial part of ω turns
    /// about the figure axis at −Ω > 0, in the sense of the rotation (prograde), as seen in the
    /// body: Euler's free nutation.
    pub fn euler_rate(&self) -> f64 {
        -self.flattening_over_a() * self.rotation_rate
    }

    /// Euler's free-nutation period (s): 2π/|Ω| = (A/(C − A)) · 2π/ω = ((1 − H)/H) sidereal
    /// days — 304.46 sidereal days (303.62 days of 86400 s) for the IERS H. Refused, naming
    /// `rotation_rate`, where it overflows.
    pub fn euler_period(&self) -> Result<f64> {
        let days = (1.0 - self.dynamical_flattening) / self.dynamical_flattening;
        finite_result(
            "rotation_rate",
            "the Euler period (1 - H)/H * 2 pi/omega",
            days * (TAU / self.rotation_rate),
        )
    }

    /// The elastic Earth's free wobble, the Chandler period (s), from the Love number `k2` and
    /// the secular (fluid) Love number `ks` (0 < k2 < ks):
    ///
    /// T_C = T_E · ks/(ks − k2).
    ///
    /// Derivation (Munk & MacDonald 1960, *The Rotation of the Earth*; Smith & Dahlen
    /// 1981, Geophys. J. R. astr. Soc. 64, 223): a wobble of the rotation axis by m
    /// tilts the centrifugal potential, whose degree-2 part raises a bulge that yields with
    /// the Love number k2: the products of inertia follow the axis by (k2/ks) of the way a
    /// fluid Earth's would (ks = 3G(C − A)/(ω² a⁵) being the fluid, secular, response that
    /// made the bulge). In Euler's (Liouville's) linearised equations the restoring C − A is
    /// so reduced to (C − A)(1 − k2/ks), and the frequency σ_E = (C − A)/A ω to σ_E(1 − k2/ks):
    /// the period grows by ks/(ks − k2). With k2 ≈ 0.30 and ks ≈ 0.938 (Lambeck 1980, *The
    /// Earth's Variable Rotation*), 445 days against the observed 433: the oceans'
    /// pole tide, the fluid core (which does not follow the mantle, lowering the effective A)
    /// and the mantle's anelasticity make up the rest.
    pub fn chandler_period(&self, k2: f64, ks: f64) -> Result<f64> {
        check_positive("k2", k2)?;
        check_positive("ks", ks)?;
        if k2 >= ks {
            return Err(Error::invalid(
                "k2",
                format!(
                    "must be < ks (the Love number of the elastic Earth is below the fluid Earth's secular ks; at k2 >= ks the wobble has no restoring bulge), got k2 = {}, ks = {}",
                    num(k2),
                    num(ks)
                ),
            ));
        }
        let t = self.euler_period()? * (ks / (ks - k2));
        finite_result("k2", "the Chandler period", t)
    }

    /// The orbit-averaged precession rate caused by one body (rad/s, negative: retrograde).
    ///
    /// Derivation. MacCullagh's formula gives the potential energy of the Earth (moments A, A,
    /// C about its figure axis ŝ) in the field of a mass at distance r in direction r̂:
    /// V = (3GM/(2r³)) (C − A) (ŝ·r̂)² + const, and the torque N = −ŝ × ∂V/∂ŝ =
    /// (3GM/r³)(C − A)(ŝ·r̂)(r̂ × ŝ) (the unit's torque of a gravity gradient). Over an orbit of
    /// normal n̂, ⟨r̂ r̂ᵀ/r³⟩ = (I − n̂ n̂ᵀ)/(2 a³ (1 − e²)^{3/2}), so
    /// ⟨N⟩ = −(3GM/(2a³(1 − e²)^{3/2}))(C − A)(ŝ·n̂)(n̂ × ŝ). The spin's angular momentum is
    /// L ≈ Cω ŝ (the nutation's own ω is ~1e-8 of it): ŝ′ = ⟨N⟩/(Cω) = −K (ŝ·n̂)(n̂ × ŝ) with
    /// K = (3/2)(GM/(a³(1 − e²)^{3/2}))(H/ω). For n̂ along the ecliptic pole k̂, ŝ turns about k̂
    /// at −K cos ε: the precession, retrograde — the unit's 2.98-style torque theory, averaged.
    /// For the Moon, n̂ is inclined by i to k̂ and its node regresses: averaged over the node,
    /// ⟨n̂ n̂ᵀ⟩ = diag(sin²i/2, sin²i/2, cos²i), and ⟨(n̂ n̂ᵀ ŝ) × ŝ⟩ = (1 − (3/2) sin² i) cos ε
    /// (k̂ × ŝ): the factor (1 − (3/2) sin² i). The Moon's GM is μ GM_⊕ and a is its distance from
    /// the Earth's centre (the relative orbit about the Earth–Moon barycentre: with the mean
    /// motion n_☾² a³ = G(M_⊕ + M_☾) it reads GM_☾/a³ = n_☾² μ/(1 + μ)); the Earth's own
    /// excursion about the barycentre changes the Sun's ⟨1/r³⟩ by order (4700 km/1 au)², 1e-9.
    pub fn precession_rate_of(&self, orbit: &MeanOrbit) -> f64 {
        let k = 1.5 * orbit.mean_inverse_cube() * self.dynamical_flattening / self.rotation_rate;
        let s = orbit.inclination.sin();
        -k * self.obliquity.cos() * (1.0 - 1.5 * s * s)
    }

    /// The Sun's and the Moon's parts of the precession rate (rad/s, negative).
    pub fn precession_parts(&self) -> (f64, f64) {
        (
            self.precession_rate_of(&self.sun),
            self.precession_rate_of(&self.moon),
        )
    }

    /// The luni-solar precession rate (rad/s): the signed angular velocity of the spin axis
    /// about the ecliptic pole, the Sun's part plus the Moon's ([`Self::precession_rate_of`]).
    /// Negative (retrograde, westward): −5040.03″ per Julian century for the defaults, whose
    /// magnitude is within 0.03 % of the IAU 2006 ψ̇_A = 5038.481507″/cy
    /// ([`IAU2006_PRECESSION_RATE`]); the difference is the geodesic precession (−1.92″/cy),
    /// the planetary and second-order terms that the first-order rigid theory leaves out.
    pub fn precession_rate(&self) -> f64 {
        let (sun, moon) = self.precession_parts();
        sun + moon
    }

    /// The precession period 2π/|precession_rate| (s): 25,714 Julian years for the defaults
    /// (the luni-solar period; the general precession, 5028.8″/cy, takes 25,772). Refused,
    /// naming `dynamical_flattening`, where it overflows.
    pub fn precession_period(&self) -> Result<f64> {
        finite_result(
            "dynamical_flattening",
            "the precession period 2 pi/|rate|",
            TAU / self.precession_rate().abs(),
        )
    }

    /// The principal nutation (rad): the amplitudes (Δψ₀, Δε₀) of Δψ = Δψ₀ sin Ω,
    /// Δε = Δε₀ cos Ω, Ω the longitude of the Moon's ascending node, in the IAU convention.
    ///
    /// Derivation. With the Moon's orbit normal n̂ = (sin i sin Ω, −sin i cos Ω, cos i) (ecliptic
    /// axes, x to the equinox) and the pole ŝ = (sin ε sin ψ, sin ε cos ψ, cos ε), the terms of
    /// ŝ′ = −K_☾(ŝ·n̂)(n̂ × ŝ) of first order in sin i (they carry sin i cos i) are
    /// ψ′ sin ε = K_☾ sin i cos i cos 2ε cos Ω and ε′ = K_☾ sin i cos i cos ε sin Ω. The node
    /// regresses uniformly, Ω′ = −ν with ν = 2π/T_node, and integrating gives
    ///
    /// Δψ₀ = −K_☾ sin i cos i cos 2ε / (ν sin ε),  Δε₀ = K_☾ sin i cos i cos ε / ν,
    ///
    /// K_☾ = (3/2)(GM_☾/(a³(1 − e²)^{3/2}))(H/ω). For the defaults, −17.281″ and 9.227″
    /// against IAU 2000A's −17.2064161″ and 9.2052331″ ([`IAU2000A_PRINCIPAL_NUTATION`]): 0.43 %
    /// and 0.23 % larger. IAU 2000A is the non-rigid Earth (MHB2000: the rigid-Earth series,
    /// REN-2000 of Souchay et al. 1999, A&AS 135, 111, multiplied by a transfer function with the
    /// fluid core and the elastic mantle), whose response to the 18.6-year torque is slightly
    /// smaller than the rigid body's; the first-order theory on a Kepler orbit also leaves out
    /// the solar perturbations of the lunar orbit and the second-order terms. Refused, naming
    /// `obliquity`, at ε = 0 (Δψ is a longitude, undefined when the equator lies in the
    /// ecliptic) or where it overflows.
    pub fn nutation_amplitudes(&self) -> Result<(f64, f64)> {
        let moon = &self.moon;
        if self.obliquity == 0.0 {
            return Err(Error::invalid(
                "obliquity",
                "must be > 0 for the nutation in longitude (a longitude of the pole is undefined when the equator lies in the ecliptic), got 0 rad",
            ));
        }
        let k = 1.5 * moon.mean_inverse_cube() * self.dynamical_flattening / self.rotation_rate;
        let nu = TAU / moon.node_period;
        let (si, ci) = moon.inclination.sin_cos();
        let (se, ce) = self.obliquity.sin_cos();
        let base = k * si * ci / nu;
        let dpsi = finite_result(
            "obliquity",
            "the nutation in longitude",
            -base * (2.0 * self.obliquity).cos() / se,
        )?;
        Ok((dpsi, base * ce))
    }

    /// The principal nutation (Δψ₀, Δε₀) (rad) by a second route, in closed form from the
    /// Moon's part of the precession ([`Self::precession_parts`]): the Moon alone turns the
    /// pole about its own orbit's normal, and the normal circles the ecliptic pole once a node
    /// period T_node, so with ν = 2π/T_node
    ///
    /// Δψ₀ = −K sin i cos i cos 2ε/(ν sin ε),  Δε₀ = K sin i cos i cos ε/ν,
    /// K = −P_☾/(cos ε (1 − (3/2) sin² i)),
    ///
    /// P_☾ the Moon's precession part (the Moon's constant K_☾ read back off it). Equal to
    /// [`Self::nutation_amplitudes`] to round-off; the experiment catalogue shows it as the
    /// closed-form column. Refused, naming `obliquity`, at ε = 0 or where it overflows.
    pub fn nutation_amplitudes_by_precession(&self) -> Result<(f64, f64)> {
        if self.obliquity == 0.0 {
            return Err(Error::invalid(
                "obliquity",
                "must be > 0 for the nutation in longitude (a longitude of the pole is undefined when the equator lies in the ecliptic), got 0 rad",
            ));
        }
        let (_, moon_part) = self.precession_parts();
        let (si, ci) = self.moon.inclination.sin_cos();
        let (se, ce) = self.obliquity.sin_cos();
        let nu = TAU / self.moon.node_period;
        let k = -moon_part / (ce * (1.0 - 1.5 * si * si));
        let base = k * si * ci / nu;
        let dpsi = finite_result(
            "obliquity",
            "the nutation in longitude",
            -base * (2.0 * self.obliquity).cos() / se,
        )?;
        let deps = finite_result("obliquity", "the nutation in obliquity", base * ce)?;
        Ok((dpsi, deps))
    }

    /// The averaged pole at the times `t` (s): the mean pole precessing uniformly about the
    /// ecliptic pole, nodding with the principal nutation,
    ///
    /// Ω(t) = Ω₀ − 2π t/T_node,
    /// ψ(t) = −P t + s Δψ₀ sin Ω(t),
    /// ε(t) = ε₀ + s Δε₀ cos Ω(t),
    ///
    /// with P the luni-solar precession rate ([`Self::precession_rate`], rad/s, negative:
    /// retrograde, so ψ grows westward as the IAU's ψ_A = |P| t), (Δψ₀, Δε₀) the principal
    /// nutation ([`Self::nutation_amplitudes`], rad, IAU convention), ε₀ the mean obliquity
    /// ([`Self::obliquity`](RigidEarth::obliquity)), Ω₀ = `moon_node` (rad) the longitude of the
    /// Moon's ascending node at t = 0 and T_node its period of regression (18.6 years); s =
    /// `nutation_scale` (dimensionless, ≥ 0) multiplies the nutation: 1 is the Earth's, 0 the
    /// mean pole alone, and a drawing uses a larger s to make the 9″ nod visible.
    ///
    /// This is the pole that [`Self::simulate`] with [`SimulateOptions::mean_pole`]
    /// (`super::SimulateOptions`) and the same Ω₀ integrates from the instantaneous torques,
    /// less the semi-annual (0.55″) and fortnightly (0.09″) nods of the Sun's and the Moon's
    /// orbital motions and the second-order terms.
    ///
    /// Errors name `t` (not finite, or more times than the memory budget holds), `moon_node`
    /// (not finite), `nutation_scale` (negative or not finite, or so large that an angle
    /// overflows) and `obliquity` (0: the nutation in longitude is undefined,
    /// [`Self::nutation_amplitudes`]).
    ///
    /// [`SimulateOptions::mean_pole`]: super::SimulateOptions::mean_pole
    /// [`AveragedPole`]: super::AveragedPole
    pub fn averaged_pole(
        &self,
        t: &[f64],
        moon_node: f64,
        nutation_scale: f64,
    ) -> Result<AveragedPole> {
        check_finite("t", t)?;
        check_finite("moon_node", &[moon_node])?;
        check_finite("nutation_scale", &[nutation_scale])?;
        check_non_negative("nutation_scale", nutation_scale)?;
        crate::limits::check_memory("t", t.len() as f64, AVERAGED_POLE_BYTES_PER_TIME)?;
        let rate = self.precession_rate();
        let (dpsi, deps) = self.nutation_amplitudes()?;
        let node_rate = -TAU / self.moon.node_period;
        let (mut psi, mut obliquity, mut node) = (
            Vec::with_capacity(t.len()),
            Vec::with_capacity(t.len()),
            Vec::with_capacity(t.len()),
        );
        for &time in t {
            let omega = moon_node + node_rate * time;
            let (s, c) = omega.sin_cos();
            psi.push(-rate * time + nutation_scale * dpsi * s);
            obliquity.push(self.obliquity + nutation_scale * deps * c);
            node.push(omega);
        }
        check_result("nutation_scale", "the nutation in longitude", &psi)?;
        check_result("nutation_scale", "the nutation in obliquity", &obliquity)?;
        Ok(AveragedPole {
            psi,
            obliquity,
            moon_node: node,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::ErrorKind;
    use proptest::prelude::*;

    const ARCSEC_PER_CY: f64 = ARCSECOND / JULIAN_CENTURY;

    #[test]
    fn euler_period_is_a_over_c_minus_a_sidereal_days() {
        let e = RigidEarth::default();
        let sidereal_day = TAU / SIDEREAL_RATE;
        let days = e.euler_period().unwrap() / sidereal_day;
        // (1 − H)/H = A/(C − A), independently: 1/H − 1.
        assert!((days - (1.0 / DYNAMICAL_FLATTENING - 1.0)).abs() < 1e-9);
        assert!((days - 304.456).abs() < 1e-3, "{days}");
        // The unit's 2.83 with I₁ = A = 1 − H, I₃ = C = 1 (units of C): Ω = (I₁ − I₃)ω/I₁.
        let omega_283 =
            ((1.0 - DYNAMICAL_FLATTENING) - 1.0) * SIDEREAL_RATE / (1.0 - DYNAMICAL_FLATTENING);
        assert!((e.euler_rate() / omega_283 - 1.0).abs() < 1e-12);
        assert!(e.euler_rate() < 0.0);
    }

    #[test]
    fn chandler_period_lengthens_euler_and_refuses_bad_love_numbers() {
        let e = RigidEarth::default();
        let t = e.chandler_period(0.30, 0.938).unwrap() / DAY;
        assert!((t - 446.4).abs() < 0.5, "{t}");
        let err = e.chandler_period(0.94, 0.938).unwrap_err();
        assert_eq!(err.argument, "k2");
        assert_eq!(e.chandler_period(0.0, 0.938).unwrap_err().argument, "k2");
        assert_eq!(e.chandler_period(0.3, -1.0).unwrap_err().argument, "ks");
        assert_eq!(e.chandler_period(f64::NAN, 0.9).unwrap_err().argument, "k2");
    }

    #[test]
    fn precession_lands_within_half_a_percent_of_iau_2006() {
        let e = RigidEarth::default();
        let rate = e.precession_rate();
        assert!(rate < 0.0);
        let rel = rate.abs() / IAU2006_PRECESSION_RATE - 1.0;
        assert!(rel.abs() < 0.005, "{rel}");
        assert!(rel.abs() < 0.0005, "{rel}"); // 0.03 % in fact
        let (sun, moon) = e.precession_parts();
        // The Moon does about 2.16 times the Sun's part.
        assert!((moon / sun - 2.16).abs() < 0.01, "{}", moon / sun);
        assert!((sun / ARCSEC_PER_CY + 1594.9).abs() < 0.5);
        let years = e.precession_period().unwrap() / (365.25 * DAY);
        assert!((years - 25_714.0).abs() < 5.0, "{years}");
    }

    #[test]
    fn precession_matches_the_closed_form_written_out() {
        // −(3/2) (n² H/ω) cos ε summed, each body's n² = GM/(a³(1−e²)^{3/2}); the Moon with
        // (1 − 3/2 sin² i) and GM = μ GM_⊕.
        let (h, w, eps) = (
            3.273795e-3,
            7.292115e-5,
            (84381.406 / 3600.0_f64).to_radians(),
        );
        let n2s = 1.32712442099e20
            / (1.495978707e11_f64.powi(3) * (1.0 - 0.0167086_f64.powi(2)).powf(1.5));
        let n2m = 0.0123000371 * 3.986004418e14
            / (3.844e8_f64.powi(3) * (1.0 - 0.0549_f64.powi(2)).powf(1.5));
        let im = 5.145_f64.to_radians();
        let want = -1.5 * h / w * eps.cos() * (n2s + n2m * (1.0 - 1.5 * im.sin().powi(2)));
        let got = RigidEarth::default().precession_rate();
        assert!((got / want - 1.0).abs() < 1e-12);
    }

    #[test]
    fn nutation_by_precession_equals_the_direct_closed_form() {
        for e in [
            RigidEarth::default(),
            RigidEarth::new(0.01, 1e-4, 0.3).unwrap(),
        ] {
            let (a, b) = e.nutation_amplitudes().unwrap();
            let (c, d) = e.nutation_amplitudes_by_precession().unwrap();
            assert!((c / a - 1.0).abs() < 1e-13 && (d / b - 1.0).abs() < 1e-13);
        }
        let flat = RigidEarth::new(0.01, 1e-4, 0.0).unwrap();
        let err = flat.nutation_amplitudes_by_precession().unwrap_err();
        assert!(err.to_string().contains("obliquity"));
    }

    #[test]
    fn nutation_agrees_with_iau_2000a_to_half_a_percent() {
        let (dpsi, deps) = RigidEarth::default().nutation_amplitudes().unwrap();
        let (p, q) = IAU2000A_PRINCIPAL_NUTATION;
        assert!(dpsi < 0.0 && deps > 0.0);
        assert!((dpsi / p - 1.0).abs() < 0.005, "{}", dpsi / ARCSECOND);
        assert!((deps / q - 1.0).abs() < 0.005, "{}", deps / ARCSECOND);
        assert!(
            (dpsi / ARCSECOND + 17.281).abs() < 0.001 && (deps / ARCSECOND - 9.2265).abs() < 0.001
        );
        // Independent relation: Δψ₀/Δε₀ = −cos 2ε/(sin ε cos ε) = −2 cot 2ε.
        let eps = OBLIQUITY_J2000;
        assert!((dpsi / deps + 2.0 / (2.0 * eps).tan()).abs() < 1e-12);
    }

    #[test]
    fn bad_input_is_refused_by_name() {
        for h in [0.0, 1.0, -0.1, 1.5, f64::NAN, f64::INFINITY] {
            let err = RigidEarth::new(h, SIDEREAL_RATE, OBLIQUITY_J2000).unwrap_err();
            assert_eq!(err.argument, "dynamical_flattening", "{h}");
            assert_eq!(err.kind, ErrorKind::InvalidArgument);
        }
        for w in [0.0, -1.0, f64::NAN] {
            assert_eq!(
                RigidEarth::new(0.003, w, 0.4).unwrap_err().argument,
                "rotation_rate"
            );
        }
        for eps in [-0.1, PI / 2.0, 2.0, f64::NAN] {
            assert_eq!(
                RigidEarth::new(0.003, 7e-5, eps).unwrap_err().argument,
                "obliquity"
            );
        }
        let flat = RigidEarth::new(0.003, 7e-5, 0.0).unwrap();
        assert_eq!(
            flat.nutation_amplitudes().unwrap_err().argument,
            "obliquity"
        );
        let slow = RigidEarth::new(0.003, 1e-320, 0.4).unwrap();
        assert_eq!(slow.euler_period().unwrap_err().argument, "rotation_rate");
    }

    #[test]
    fn a_rounder_earth_precesses_slower_negative_control() {
        // H → 0: no bulge, no torque (H = 0 itself is refused above).
        let e = RigidEarth::new(1e-12, SIDEREAL_RATE, OBLIQUITY_J2000).unwrap();
        assert!(e.precession_rate().abs() < 1e-9 * RigidEarth::default().precession_rate().abs());
        // At ε = 90° − tiny the torque averages to (almost) nothing: cos ε.
        let side = RigidEarth::new(DYNAMICAL_FLATTENING, SIDEREAL_RATE, PI / 2.0 - 1e-9).unwrap();
        assert!(
            side.precession_rate().abs() < 1e-8 * RigidEarth::default().precession_rate().abs()
        );
    }

    /// ŝ′ = (3 GM/r⁵)(H/ω)(ŝ·r)(r × ŝ) (the instantaneous gravity-gradient torque over Cω),
    /// averaged over one Kepler orbit of `orbit` with its node at `node` and its perigee
    /// `perigee` from the node, by the trapezoid rule in the eccentric anomaly E (weight
    /// dM = (1 − e cos E) dE), in ecliptic axes (x to the equinox); ŝ the pole of `earth`.
    fn orbit_averaged_spin_rate(
        earth: &RigidEarth,
        orbit: &MeanOrbit,
        node: f64,
        perigee: f64,
    ) -> crate::Vec3 {
        use crate::Vec3;
        let (a, e) = (orbit.semi_major_axis, orbit.eccentricity);
        let (se, ce) = earth.obliquity.sin_cos();
        let s = Vec3::new(0.0, se, ce);
        let turn = |v: Vec3, angle: f64, axis: usize| {
            let (sn, cs) = angle.sin_cos();
            match axis {
                0 => Vec3::new(v.x, cs * v.y - sn * v.z, sn * v.y + cs * v.z),
                _ => Vec3::new(cs * v.x - sn * v.y, sn * v.x + cs * v.y, v.z),
            }
        };
        let n = 4000;
        let mut sum = Vec3::zeros();
        for k in 0..n {
            let big_e = TAU * k as f64 / n as f64;
            let p = Vec3::new(
                a * (big_e.cos() - e),
                a * (1.0 - e * e).sqrt() * big_e.sin(),
                0.0,
            );
            let r = turn(turn(turn(p, perigee, 2), orbit.inclination, 0), node, 2);
            let rn = r.norm();
            let rate =
                3.0 * orbit.gm / rn.powi(5) * earth.dynamical_flattening / earth.rotation_rate;
            sum += rate * s.dot(&r) * r.cross(&s) * (1.0 - e * big_e.cos());
        }
        sum / n as f64
    }

    #[test]
    fn the_orbit_average_of_the_instantaneous_torque_is_the_closed_form() {
        // The precession: ŝ′ averaged over the orbit and over the node (trapezoid in Ω too),
        // projected on k̂ × ŝ, is precession_rate_of — the (1 − e²)^{-3/2} and the
        // (1 − 3/2 sin² i) of the derivation, checked numerically with an exaggerated orbit.
        let earth = RigidEarth::default();
        let k_cross_s = crate::Vec3::new(-earth.obliquity.sin(), 0.0, 0.0);
        for orbit in [
            SUN_ORBIT,
            MOON_ORBIT,
            MeanOrbit {
                eccentricity: 0.4,
                inclination: 0.5,
                ..MOON_ORBIT
            },
        ] {
            let m = 64;
            let mut mean = crate::Vec3::zeros();
            for j in 0..m {
                let node = TAU * j as f64 / m as f64;
                mean += orbit_averaged_spin_rate(&earth, &orbit, node, 0.7) / m as f64;
            }
            let rate = mean.dot(&k_cross_s) / k_cross_s.norm_squared();
            let want = earth.precession_rate_of(&orbit);
            assert!((rate / want - 1.0).abs() < 1e-9, "{rate} vs {want}");
            // Nothing but the precession survives the average: no mean nodding.
            assert!(mean.y.abs() < 1e-9 * want.abs() && mean.z.abs() < 1e-9 * want.abs());
        }
        // The nutation: ε′ = ŝ′·∂ŝ/∂ε over the node has the Fourier coefficient
        // K sin i cos i cos ε at sin Ω (ν Δε₀ of nutation_amplitudes), and ψ′ sin ε = ŝ′·∂ŝ/∂ψ
        // has −ν Δψ₀ sin ε at cos Ω.
        let moon = MOON_ORBIT;
        let (se, ce) = earth.obliquity.sin_cos();
        let d_eps = crate::Vec3::new(0.0, ce, -se);
        let d_psi = crate::Vec3::new(se, 0.0, 0.0);
        let m = 64;
        let (mut c_eps, mut c_psi) = (0.0, 0.0);
        for j in 0..m {
            let node = TAU * j as f64 / m as f64;
            let v = orbit_averaged_spin_rate(&earth, &moon, node, 0.7);
            c_eps += 2.0 / m as f64 * v.dot(&d_eps) * node.sin();
            c_psi += 2.0 / m as f64 * v.dot(&d_psi) / se * node.cos();
        }
        let nu = TAU / moon.node_period;
        let (dpsi, deps) = earth.nutation_amplitudes().unwrap();
        assert!(
            (c_eps / (nu * deps) - 1.0).abs() < 1e-9,
            "{c_eps} vs {}",
            nu * deps
        );
        assert!(
            (c_psi / (-nu * dpsi * se) - 1.0).abs() < 1e-9,
            "{c_psi} vs {}",
            -nu * dpsi * se
        );
    }

    proptest! {
        #[test]
        fn euler_period_scales_as_one_minus_h_over_h(
            h in 1e-6f64..0.9, w in 1e-7f64..10.0, eps in 0.0f64..1.5
        ) {
            let e = RigidEarth::new(h, w, eps).unwrap();
            let t = e.euler_period().unwrap();
            let want = (1.0 - h) / h * TAU / w;
            prop_assert!((t / want - 1.0).abs() < 1e-12);
            // Precession scales as H/ω; the Chandler period is always longer than Euler's.
            let r = e.precession_rate();
            let base = RigidEarth::new(h, 1.0, eps).unwrap().precession_rate();
            prop_assert!((r * w / base - 1.0).abs() < 1e-12);
            prop_assert!(e.chandler_period(0.3, 0.938).unwrap() > t);
        }
    }
}
