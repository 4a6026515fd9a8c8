//! Bindings of `poinsot::earth::RigidEarth` (conversion and error mapping only): the Earth as a
//! rigid symmetric top — Euler's free nutation, the Chandler period of the elastic Earth, the
//! luni-solar precession of the equinoxes and the principal (18.6-year) nutation. SI units,
//! radians; the core names every argument as the caller knows it, so no error is renamed here.
//! With it, the fit of the real pole's wobble (`fitWobble`), which the lab's scene "The Earth as
//! a top" runs on the pole path it shows.

use crate::args::{numbers, Numbers};
use crate::convert::{getters, Out};
use crate::{calls, fields};
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
    /// The principal nutation `[Δψ₀, Δε₀]` (rad) of Δψ = Δψ₀ sin Ω, Δε = Δε₀ cos Ω (Ω the
    /// longitude of the Moon's ascending node), in the IAU convention (Δψ westward, as ψ_A).
    /// Refused, naming `obliquity`, at ε = 0.
    #[wasm_bindgen(getter, js_name = nutationAmplitudes)]
    pub fn nutation_amplitudes(&self) -> Out<Vec<f64>> {
        let (dpsi, deps) = self.inner.nutation_amplitudes()?;
        Ok(vec![dpsi, deps])
    }
}

/// One circle of a fitted wobble (`poinsot.WobbleTerm` in Python): period (s), radius (rad) and
/// phase at t = 0 (rad), each with its 1-σ uncertainty (0 for a quantity held fixed).
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct WobbleTerm {
    inner: ea::WobbleTerm,
}

fields!(WobbleTerm {
    " Period (s)."
    period period -> number(period);
    " Its 1-σ uncertainty (s); 0 when the period was held fixed."
    periodSigma period_sigma -> number(period_sigma);
    " Radius of the circle (rad)."
    amplitude amplitude -> number(amplitude);
    " Its 1-σ uncertainty (rad)."
    amplitudeSigma amplitude_sigma -> number(amplitude_sigma);
    " φ at t = 0 (rad, in (−π, π]): the term is A e^{i(±ωt + φ)} in p = x − i y."
    phase phase -> number(phase);
    " Its 1-σ uncertainty (rad)."
    phaseSigma phase_sigma -> number(phase_sigma);
    " Whether the circle turns prograde (with the Earth's rotation)."
    prograde prograde -> flag(prograde);
});

/// The real pole fitted to a trend, the prograde Chandler circle and the annual circles
/// (`poinsot.WobbleFit` in Python): the core's `fit_wobble`.
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct WobbleFit {
    inner: ea::WobbleFit,
}

fields!(WobbleFit {
    " RMS of the residuals over x and y (rad)."
    residualRms residual_rms -> number(residual_rms);
    " The chance that noise alone gives a Chandler amplitude this large."
    chandlerFalseAlarm chandler_false_alarm -> number(chandler_false_alarm);
    " √((1 + ρ)/(1 − ρ)), the factor by which the formal uncertainties were widened."
    sigmaInflation sigma_inflation -> number(sigma_inflation);
});

#[wasm_bindgen]
impl WobbleFit {
    /// The prograde Chandler circle.
    #[wasm_bindgen(getter)]
    pub fn chandler(&self) -> WobbleTerm {
        WobbleTerm {
            inner: self.inner.chandler,
        }
    }
    /// The prograde annual circle.
    #[wasm_bindgen(getter, js_name = annualPrograde)]
    pub fn annual_prograde(&self) -> WobbleTerm {
        WobbleTerm {
            inner: self.inner.annual_prograde,
        }
    }
    /// The retrograde annual circle.
    #[wasm_bindgen(getter, js_name = annualRetrograde)]
    pub fn annual_retrograde(&self) -> WobbleTerm {
        WobbleTerm {
            inner: self.inner.annual_retrograde,
        }
    }
    /// Number of samples.
    #[wasm_bindgen(getter)]
    pub fn samples(&self) -> f64 {
        self.inner.samples as f64
    }
}

/// Fits the pole (x, y) (rad; x towards Greenwich, y towards 90° W) sampled at times `t` (s,
/// strictly increasing) to a trend, the prograde Chandler circle (its period searched over the
/// core's band, 380–500 days) and the annual circles (one tropical year), as Python's
/// `poinsot.fit_wobble(t, x, y)` with its defaults. Errors name `t`, `x` or `y`.
#[wasm_bindgen(js_name = fitWobble)]
pub fn fit_wobble(
    #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] t: Numbers,
    #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] x: Numbers,
    #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] y: Numbers,
) -> Out<WobbleFit> {
    let (t, x, y) = (numbers("t", &t)?, numbers("x", &x)?, numbers("y", &y)?);
    let inner = ea::fit_wobble(&t, &x, &y, ea::ChandlerPeriod::default(), ea::ANNUAL_PERIOD)?;
    Ok(WobbleFit { inner })
}

getters!(RigidEarth? {
    " Euler's free-nutation period (s): ((1 − H)/H) sidereal days, 304.46 for the IERS H."
    eulerPeriod euler_period;
    " The precession period 2π/|precession rate| (s): 25,714 Julian years for the defaults."
    precessionPeriod precession_period;
});

/// The rigid Earth's averaged pole at a list of times (`RigidEarth.averagedPole`;
/// `poinsot.AveragedPole` in Python): the uniform precession plus the principal nutation.
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct AveragedPole {
    inner: ea::AveragedPole,
}

fields!(AveragedPole {
    " ψ(t), the precession angle of the spin axis (rad, unwrapped): its ecliptic longitude"
    " counted westward from its place at t = 0, the IAU's ψ_A plus the nutation Δψ."
    psi psi -> numbers(psi);
    " ε(t), the obliquity: the angle of the spin axis from the ecliptic's pole (rad)."
    obliquity obliquity -> numbers(obliquity);
    " Ω(t), the ecliptic longitude of the Moon's ascending node (rad, unwrapped)."
    moonNode moon_node -> numbers(moon_node);
});

#[wasm_bindgen]
impl RigidEarth {
    /// The averaged pole at the times `t` (s): Ω = Ω₀ − 2π t/T_node, ψ = −P t + s Δψ₀ sin Ω,
    /// ε = ε₀ + s Δε₀ cos Ω, with P the precession rate, (Δψ₀, Δε₀) the principal nutation,
    /// Ω₀ = `moonNode` (rad) and s = `nutationScale` (≥ 0; 1 the Earth's, larger to draw the
    /// nod visibly). Errors name `t`, `moon_node`, `nutation_scale` or `obliquity`.
    #[wasm_bindgen(js_name = averagedPole)]
    pub fn averaged_pole(
        &self,
        #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] t: Numbers,
        #[wasm_bindgen(unchecked_param_type = "number")] moon_node: crate::args::Number,
        #[wasm_bindgen(unchecked_param_type = "number")] nutation_scale: crate::args::Number,
    ) -> Out<AveragedPole> {
        let t = numbers("t", &t)?;
        let moon_node = crate::args::number("moon_node", &moon_node)?;
        let nutation_scale = crate::args::number("nutation_scale", &nutation_scale)?;
        let inner = self.inner.averaged_pole(&t, moon_node, nutation_scale)?;
        Ok(AveragedPole { inner })
    }
}
