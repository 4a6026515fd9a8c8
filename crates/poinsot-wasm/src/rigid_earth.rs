//! Bindings of `poinsot::earth::RigidEarth` (conversion and error mapping only): the Earth as a
//! rigid symmetric top — Euler's free nutation, the Chandler period of the elastic Earth, the
//! luni-solar precession of the equinoxes and the principal (18.6-year) nutation. SI units,
//! radians; the core names every argument as the caller knows it, so no error is renamed here.

use crate::calls;
use crate::convert::{getters, Out};
use poinsot::earth as ea;
use wasm_bindgen::prelude::wasm_bindgen;

/// The Earth as a rigid symmetric top (`poinsot.RigidEarth` in Python).
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct RigidEarth {
    inner: ea::RigidEarth,
}

calls!(RigidEarth::new {
    " A rigid Earth of dynamical flattening H = (C − A)/C in (0, 1), rotation rate ω > 0"
    " (rad/s) and obliquity ε in [0, π/2) (rad), torqued by the Sun and the Moon on their mean"
    " orbits. The IERS 2010 values are `RigidEarth.dynamicalFlattening()`,"
    " `Earth.siderealRate()` and `RigidEarth.obliquityJ2000()`."
    (dynamical_flattening: number, rotation_rate: number, obliquity: number) = ea::RigidEarth::new;
});

getters!(RigidEarth {
    " The unit's Ω of 2.83 for the Earth, −H/(1 − H) ω (rad/s; negative: the free wobble is"
    " prograde)."
    eulerRate euler_rate;
    " The luni-solar precession rate (rad/s): the signed angular velocity of the spin axis about"
    " the ecliptic pole, negative (retrograde); the Sun's part plus the Moon's."
    precessionRate precession_rate;
});

calls!(RigidEarth {
    " The Chandler period T_E ks/(ks − k2) (s) of the elastic Earth, for the Love number `k2`"
    " and the secular Love number `ks` (0 < k2 < ks)."
    chandlerPeriod chandler_period(k2: number, ks: number) -> number;
});

#[wasm_bindgen]
impl RigidEarth {
    /// H = (C − A)/C of the IERS Conventions (2010), Table 1.1: 3.273795e-3 (the default).
    #[wasm_bindgen(js_name = dynamicalFlattening)]
    pub fn dynamical_flattening() -> f64 {
        ea::DYNAMICAL_FLATTENING
    }
    /// ε₀, the obliquity of the ecliptic at J2000.0 (rad): 84381.406″ (IAU 2006; the default).
    #[wasm_bindgen(js_name = obliquityJ2000)]
    pub fn obliquity_j2000() -> f64 {
        ea::OBLIQUITY_J2000
    }
    /// The IAU 2006 luni-solar precession rate ψ̇_A (rad/s, westward positive): 5038.481507″
    /// per Julian century.
    #[wasm_bindgen(js_name = iau2006PrecessionRate)]
    pub fn iau2006_precession_rate() -> f64 {
        ea::IAU2006_PRECESSION_RATE
    }
    /// The IAU 2000A principal nutation `[Δψ₀, Δε₀]` (rad): −17.2064161″ and 9.2052331″.
    #[wasm_bindgen(js_name = iau2000aPrincipalNutation)]
    pub fn iau2000a_principal_nutation() -> Vec<f64> {
        let (dpsi, deps) = ea::IAU2000A_PRINCIPAL_NUTATION;
        vec![dpsi, deps]
    }

    /// The period (s) of the regression of the Moon's node, 6798.38 days (18.6 years): the
    /// period of the principal nutation, Ω(t) = Ω₀ − 2π t / T.
    #[wasm_bindgen(getter, js_name = moonNodePeriod)]
    pub fn moon_node_period(&self) -> f64 {
        self.inner.moon.node_period
    }
    /// The Sun's and the Moon's parts of the precession rate `[sun, moon]` (rad/s, negative).
    #[wasm_bindgen(getter, js_name = precessionParts)]
    pub fn precession_parts(&self) -> Vec<f64> {
        let (sun, moon) = self.inner.precession_parts();
        vec![sun, moon]
    }
    /// Euler's free-nutation period (s): ((1 − H)/H) sidereal days, 304.46 for the IERS H.
    #[wasm_bindgen(getter, js_name = eulerPeriod)]
    pub fn euler_period(&self) -> Out<f64> {
        Ok(self.inner.euler_period()?)
    }
    /// The precession period 2π/|precession rate| (s): 25,714 Julian years for the defaults.
    #[wasm_bindgen(getter, js_name = precessionPeriod)]
    pub fn precession_period(&self) -> Out<f64> {
        Ok(self.inner.precession_period()?)
    }
    /// The principal nutation `[Δψ₀, Δε₀]` (rad) of Δψ = Δψ₀ sin Ω, Δε = Δε₀ cos Ω (Ω the
    /// longitude of the Moon's ascending node), in the IAU convention (Δψ westward, as ψ_A).
    /// Refused, naming `obliquity`, at ε = 0.
    #[wasm_bindgen(getter, js_name = nutationAmplitudes)]
    pub fn nutation_amplitudes(&self) -> Out<Vec<f64>> {
        let (dpsi, deps) = self.inner.nutation_amplitudes()?;
        Ok(vec![dpsi, deps])
    }
}
