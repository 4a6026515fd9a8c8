//! Bindings of `poinsot::analytic`'s heavy symmetric top (`poinsot.HeavyTop` in Python; the
//! unit's 2.98–2.121): its constants, turning points, motion class, effective potential and the
//! exact Euler angles (z-x-z: φ about Z, θ about the line of nodes, ψ about axis 3) at any time.
//! Angles in rad, rates in rad/s, times in s. Batches are flat: N times in, N×3 numbers out
//! (row-major, `[φ₀, θ₀, ψ₀, φ₁, ...]`).

use crate::args::{let_numbers, numbers_each, Number, Numbers};
use crate::calls;
use crate::convert::{attributed, getters, Failure, Out};
use crate::free::time;
use poinsot::analytic as an;
use poinsot::rotation::{euler_to_matrix_batch, EulerSequence};
use wasm_bindgen::prelude::wasm_bindgen;

/// A heavy symmetric top with its exact motion (`poinsot.HeavyTop` in Python).
#[wasm_bindgen]
#[derive(Debug, Clone)]
pub struct HeavyTop {
    inner: an::HeavyTop,
}

/// The steady-precession rates at one nutation angle and spin (`poinsot.SteadyPrecession`).
#[wasm_bindgen]
#[derive(Debug, Clone, Copy)]
pub struct SteadyPrecession {
    inner: an::SteadyPrecession,
}

#[wasm_bindgen]
impl SteadyPrecession {
    /// The exact slow rate (rad/s), the root of 2.116 of smaller magnitude.
    #[wasm_bindgen(getter)]
    pub fn slow(&self) -> f64 {
        self.inner.slow
    }
    /// The exact fast rate (rad/s); `Infinity` at θ₀ = π/2.
    #[wasm_bindgen(getter)]
    pub fn fast(&self) -> f64 {
        self.inner.fast
    }
    /// The unit's 2.121, m g l / p_ψ (rad/s); `undefined` without spin (p_ψ = 0).
    #[wasm_bindgen(getter, js_name = slowApprox)]
    pub fn slow_approx(&self) -> Option<f64> {
        self.inner.slow_approx
    }
    /// The unit's 2.120 corrected, p_ψ / (I₁ cos θ₀) (rad/s).
    #[wasm_bindgen(getter, js_name = fastApprox)]
    pub fn fast_approx(&self) -> f64 {
        self.inner.fast_approx
    }
    /// The minimum spin 2.119 at this angle (rad/s).
    #[wasm_bindgen(getter, js_name = minSpin)]
    pub fn min_spin(&self) -> f64 {
        self.inner.min_spin
    }
}

/// Renames the core's `times` (its batch argument) to the binding's `t`.
fn times_as_t(e: poinsot::Error) -> Failure {
    let mut e = e;
    if e.argument == "times" {
        e.argument = "t".into();
    }
    Failure::from(e)
}

/// The constructors from the state at t = 0, which differ only in their last argument (ψ̇ or
/// ω₃): `from_state!(" doc" #[how] rust_name(last) => make; ...)` is one `#[wasm_bindgen] impl
/// HeavyTop` block of `pub fn rust_name(i1, i3, mgl, phi, theta, psi, phi_dot, theta_dot, last)`
/// (JavaScript numbers) returning `make(i1, i3, mgl, [phi, …, last])`, its errors attributed to
/// those arguments (doc lines as string literals, see [`crate::convert::getters`]).
macro_rules! from_state {
    ($($($doc:literal)* #[$how:meta] $name:ident($last:ident) => $make:expr;)*) => {
        #[wasm_bindgen]
        impl HeavyTop {
            $(
                $(#[doc = $doc])*
                #[$how]
                #[allow(clippy::too_many_arguments)]
                pub fn $name(
                    #[wasm_bindgen(unchecked_param_type = "number")] i1: Number,
                    #[wasm_bindgen(unchecked_param_type = "number")] i3: Number,
                    #[wasm_bindgen(unchecked_param_type = "number")] mgl: Number,
                    #[wasm_bindgen(unchecked_param_type = "number")] phi: Number,
                    #[wasm_bindgen(unchecked_param_type = "number")] theta: Number,
                    #[wasm_bindgen(unchecked_param_type = "number")] psi: Number,
                    #[wasm_bindgen(unchecked_param_type = "number")] phi_dot: Number,
                    #[wasm_bindgen(unchecked_param_type = "number")] theta_dot: Number,
                    #[wasm_bindgen(unchecked_param_type = "number")] $last: Number,
                ) -> Out<HeavyTop> {
                    let_numbers!(i1, i3, mgl, phi, theta, psi, phi_dot, theta_dot, $last);
                    let make: fn(f64, f64, f64, [f64; 6]) -> poinsot::Result<an::HeavyTop> = $make;
                    let state = [phi, theta, psi, phi_dot, theta_dot, $last];
                    let arguments =
                        concat!("i1, i3, mgl, phi, theta, psi, phi_dot, theta_dot, ", stringify!($last));
                    let inner = make(i1, i3, mgl, state).map_err(attributed(arguments))?;
                    Ok(HeavyTop { inner })
                }
            )*
        }
    };
}

from_state! {
    " The top with moments `i1` (about a transverse axis through the pivot) and `i3` (about the"
    " symmetry axis, kg·m²) and `mgl` = m g l (N·m), started at t = 0 from the Euler angles"
    " `phi`, `theta`, `psi` (rad) and their rates `phi_dot`, `theta_dot`, `psi_dot` (rad/s) — the"
    " core's order, as `HeavyTopCore.from_state` in Python. Errors name `I1`, `I3`, `mgl`, `theta`"
    " (in [0, π]), an angle or a rate."
    #[wasm_bindgen(constructor)]
    new(psi_dot) => |i1, i3, mgl, [phi, theta, psi, phi_dot, theta_dot, psi_dot]| {
        let state = an::EulerState::new(phi, theta, psi, phi_dot, theta_dot, psi_dot);
        an::HeavyTop::new(i1, i3, mgl, state)
    };
    " The top started from the Euler angles `phi`, `theta`, `psi`, the rates `phi_dot`,"
    " `theta_dot` and the spin `omega3` (rad/s) given instead of ψ̇ (ψ̇ = ω₃ − φ̇ cos θ, 2.99; the"
    " core's order, as `HeavyTop.from_spin` in Python)."
    #[wasm_bindgen(js_name = fromSpin)]
    from_spin(omega3) => |i1, i3, mgl, [phi, theta, psi, phi_dot, theta_dot, omega3]| {
        an::HeavyTop::with_spin(i1, i3, mgl, phi, theta, psi, phi_dot, theta_dot, omega3)
    };
}

#[wasm_bindgen]
impl HeavyTop {
    /// The top with the constants p_φ, p_ψ (kg·m²/s) and E (J); t = 0 at the upper turning point.
    #[wasm_bindgen(js_name = fromConstants)]
    pub fn from_constants(
        #[wasm_bindgen(unchecked_param_type = "number")] i1: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] i3: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] mgl: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] p_phi: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] p_psi: Number,
        #[wasm_bindgen(unchecked_param_type = "number")] energy: Number,
    ) -> Out<HeavyTop> {
        let_numbers!(i1, i3, mgl, p_phi, p_psi, energy);
        let inner = an::HeavyTop::from_constants(i1, i3, mgl, p_phi, p_psi, energy)
            .map_err(attributed("i1, i3, mgl, p_phi, p_psi, energy"))?;
        Ok(HeavyTop { inner })
    }

    /// The state at t = 0: `[φ, θ, ψ, φ̇, θ̇, ψ̇]`.
    #[wasm_bindgen(getter, js_name = initialState)]
    pub fn initial_state(&self) -> Vec<f64> {
        let s = self.inner.initial_state();
        vec![s.phi, s.theta, s.psi, s.phi_dot, s.theta_dot, s.psi_dot]
    }
    /// The turning points `[θ₁, θ₂]` (rad), θ₁ ≤ θ₂ (2.109–2.110).
    #[wasm_bindgen(getter, js_name = turningPoints)]
    pub fn turning_points(&self) -> Vec<f64> {
        let (a, b) = self.inner.turning_points();
        vec![a, b]
    }
    /// `[u₁, u₂, u₃]`, the roots of the cubic in u = cos θ (u₃ = `Infinity` when m g l = 0).
    #[wasm_bindgen(getter, js_name = cubicRoots)]
    pub fn cubic_roots(&self) -> Vec<f64> {
        let (a, b, c) = self.inner.cubic_roots();
        vec![a, b, c]
    }
    /// The shape of the axis' path: "waves", "loops", "cusps", "steady precession", "sleeping",
    /// "hanging" or "through vertical".
    #[wasm_bindgen(getter, js_name = motionClass)]
    pub fn motion_class(&self) -> String {
        self.inner.motion_class().name().to_string()
    }
    /// The pole a top of class "through vertical" passes through: "upright", "straight down"
    /// or "both"; `undefined` for every other class.
    #[wasm_bindgen(getter, js_name = verticalPass)]
    pub fn vertical_pass(&self) -> Option<String> {
        self.inner.vertical_pass().map(|p| p.name().to_string())
    }
    /// Whether this spin keeps an upright top asleep: ω₃² > 4 m g l I₁ / I₃².
    #[wasm_bindgen(getter, js_name = isSleepingStable)]
    pub fn is_sleeping_stable(&self) -> bool {
        self.inner.is_sleeping_stable()
    }
    /// The period of θ(t) (s); for steady motion that of small nutations about it; `Infinity`
    /// where θ never returns (an unstable sleeping top), as in Python.
    #[wasm_bindgen(getter, js_name = nutationPeriod)]
    pub fn nutation_period(&self) -> f64 {
        self.inner.nutation_period().unwrap_or(f64::INFINITY)
    }
    /// The precession period 2π/|⟨φ̇⟩| (s): one turn of the axis about the vertical at the mean
    /// precession rate (for steady precession exactly the time φ takes to advance by 2π);
    /// `Infinity` where the axis does not turn on average (a sleeping or hanging top), as in
    /// Python.
    #[wasm_bindgen(getter, js_name = precessionPeriod)]
    pub fn precession_period(&self) -> f64 {
        self.inner.precession_period().unwrap_or(f64::INFINITY)
    }

    /// Angles and rates at one time `t` (s): `[φ, θ, ψ, φ̇, θ̇, ψ̇]`.
    pub fn state(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] t: Number,
    ) -> Out<Vec<f64>> {
        let t = time(&t)?;
        let (a, r) = (self.inner.euler_angles(t)?, self.inner.euler_rates(t)?);
        Ok(vec![a[0], a[1], a[2], r[0], r[1], r[2]])
    }
}

calls!(fn HeavyTop {
    " Both steady-precession rates at `theta0` (rad) and spin `omega3` (rad/s), 2.114–2.121."
    " Errors name `omega3` below the minimum spin 2.119 (the message gives it)."
    steadyPrecession steady_precession(i1: number, i3: number, mgl: number, theta0: number,
        omega3: number) -> SteadyPrecession = an::steady_precession;
    " The minimum spin for steady precession at `theta0` (rad/s, 2.119)."
    minSpin min_spin(i1: number, i3: number, mgl: number, theta0: number) -> number = an::min_spin;
    " The spin above which an upright top sleeps stably, 2√(m g l I₁)/I₃ (rad/s)."
    sleepingThreshold sleeping_threshold(i1: number, i3: number, mgl: number) -> number =
        an::sleeping_threshold;
});

/// Functions of the top (`i1`, `i3` kg·m², `mgl` N·m) at one state (`theta` rad; `theta_dot`,
/// `phi_dot`, `psi_dot` rad/s): `of_state!(" doc" rust_name -> T = compute; ...)` is one
/// `#[wasm_bindgen] impl HeavyTop` block of the static `pub fn rust_name(i1, i3, mgl, theta,
/// theta_dot, phi_dot, psi_dot) -> Out<T>` (JavaScript numbers) returning `compute(i1, i3, mgl,
/// &state)` (doc lines as string literals, see [`crate::convert::getters`]).
macro_rules! of_state {
    ($($($doc:literal)* $(#[$how:meta])* $name:ident -> $out:ty = $compute:expr;)*) => {
        #[wasm_bindgen]
        impl HeavyTop {
            $(
                $(#[doc = $doc])*
                $(#[$how])*
                pub fn $name(
                    #[wasm_bindgen(unchecked_param_type = "number")] i1: Number,
                    #[wasm_bindgen(unchecked_param_type = "number")] i3: Number,
                    #[wasm_bindgen(unchecked_param_type = "number")] mgl: Number,
                    #[wasm_bindgen(unchecked_param_type = "number")] theta: Number,
                    #[wasm_bindgen(unchecked_param_type = "number")] theta_dot: Number,
                    #[wasm_bindgen(unchecked_param_type = "number")] phi_dot: Number,
                    #[wasm_bindgen(unchecked_param_type = "number")] psi_dot: Number,
                ) -> Out<$out> {
                    let_numbers!(i1, i3, mgl, theta, theta_dot, phi_dot, psi_dot);
                    let s = an::EulerState::with_rates(theta, theta_dot, phi_dot, psi_dot);
                    let compute: fn(f64, f64, f64, &an::EulerState) -> poinsot::Result<$out> =
                        $compute;
                    Ok(compute(i1, i3, mgl, &s)?)
                }
            )*
        }
    };
}

of_state! {
    " The Lagrangian 2.102 (J) at one state (rad, rad/s)."
    lagrangian -> f64 = an::lagrangian;
    " `[p_φ, p_ψ, E]` of one state (2.103–2.105; `HeavyTop.constants_of_state` in Python): at"
    " the exact state at t they equal the constants to round-off (their drift)."
    #[wasm_bindgen(js_name = constantsOfState)]
    constants_of_state -> Vec<f64> = |i1, i3, mgl, s| {
        let c = an::constants_of_state(i1, i3, mgl, s)?;
        Ok(vec![c.p_phi, c.p_psi, c.energy])
    };
}

/// A batch kernel of the core's top: N times in, N×3 numbers out.
type Kernel = fn(&an::HeavyTop, &[f64], &mut [f64]) -> poinsot::Result<()>;

/// Bytes per time of `attitude`: the copy of the time (8), the angles (24) and the matrix (72).
const BYTES_PER_ATTITUDE: usize = 8 + 24 + 72;

impl HeavyTop {
    /// The core's batch `kernel` at the times `t` (N×3), its `times` named `t`.
    fn per_time(&self, t: &[f64], kernel: Kernel) -> Out<Vec<f64>> {
        let mut out = vec![0.0; 3 * t.len()];
        kernel(&self.inner, t, &mut out).map_err(times_as_t)?;
        Ok(out)
    }
    /// The Euler angles at the times `t` (N×3).
    fn angles_at(&self, t: &[f64]) -> Out<Vec<f64>> {
        self.per_time(t, an::HeavyTop::euler_angles_into)
    }
    /// The Euler-angle rates at the times `t` (N×3).
    fn rates_at(&self, t: &[f64]) -> Out<Vec<f64>> {
        self.per_time(t, an::HeavyTop::euler_rates_into)
    }
    /// The symmetry axes at the times `t` (N×3): the third columns of the attitudes.
    fn axes_at(&self, t: &[f64]) -> Out<Vec<f64>> {
        let mats = self.attitudes_at(t)?;
        Ok(mats
            .chunks_exact(9)
            .flat_map(|r| [r[2], r[5], r[8]])
            .collect())
    }
    /// V(θ) (J) at each angle of `theta` (rad).
    fn potentials_at(&self, theta: &[f64]) -> Out<Vec<f64>> {
        each_theta(theta, |th| self.inner.effective_potential(th))
    }
    /// dV/dθ (N·m) at each angle of `theta` (rad).
    fn potential_derivatives_at(&self, theta: &[f64]) -> Out<Vec<f64>> {
        each_theta(theta, |th| self.inner.effective_potential_derivative(th))
    }
    /// The attitude matrices at the times `t` (N×9, row-major).
    fn attitudes_at(&self, t: &[f64]) -> Out<Vec<f64>> {
        let angles = self.angles_at(t)?;
        let mut out = vec![0.0; 9 * t.len()];
        euler_to_matrix_batch(EulerSequence::new("zxz", true)?, &angles, &mut out)?;
        Ok(out)
    }
}

/// Methods over a batch of numbers: `batches!(Type { " doc" jsName rust_name(arg, bytes) =>
/// method; ... })` is one `#[wasm_bindgen] impl Type` block of `pub fn rust_name(&self, arg)
/// -> Out<Vec<f64>>` that reads `arg` (any array-like of numbers, named in errors, within the
/// memory budget at `bytes` per number: `args::numbers_each`) and returns `self.method(&arg)`.
/// Doc lines are string literals (wasm-bindgen writes a doc comment passed through
/// `macro_rules!` as `r" ..."`).
macro_rules! batches {
    ($ty:ident { $($($doc:literal)* $js:ident $name:ident($arg:ident, $bytes:expr) => $method:ident;)* }) => {
        #[wasm_bindgen]
        impl $ty {
            $(
                $(#[doc = $doc])*
                #[wasm_bindgen(js_name = $js)]
                pub fn $name(
                    &self,
                    #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] $arg: Numbers,
                ) -> Out<Vec<f64>> {
                    self.$method(&numbers_each(stringify!($arg), &$arg, $bytes)?)
                }
            )*
        }
    };
}

batches!(HeavyTop {
    " V(θ) (J, 2.110) at each θ of `theta` (rad, in [0, π]). Errors name `theta`, also where V is"
    " infinite (a pole the axis never reaches) or beyond the largest double."
    effectivePotential effective_potential(theta, 8 + 8) => potentials_at;
    " dV/dθ (N·m, 2.113) at each θ of `theta` (rad); ±`Infinity` at a pole where V is"
    " infinite. Errors name `theta`."
    effectivePotentialDerivative effective_potential_derivative(theta, 8 + 8)
        => potential_derivatives_at;
    " The exact Euler angles at the times `t` (s): N×3 numbers `[φ, θ, ψ]` per time (rad)."
    eulerAngles euler_angles(t, 8 + 24) => angles_at;
    " The Euler-angle rates at the times `t` (s): N×3 numbers `[φ̇, θ̇, ψ̇]` (rad/s)."
    eulerRates euler_rates(t, 8 + 24) => rates_at;
    " The attitudes R(t) = R_z(φ) R_x(θ) R_z(ψ) at the times `t`: N×9 numbers (row-major, body"
    " to space components)."
    attitude attitude(t, BYTES_PER_ATTITUDE) => attitudes_at;
    " The symmetry axis (body axis 3, a unit vector in space components) at the times `t`: N×3"
    " numbers — the points that trace waves, loops or cusps on the unit sphere."
    symmetryAxis symmetry_axis(t, BYTES_PER_ATTITUDE + 24) => axes_at;
});

/// `f` at each angle of `theta` (rad); the core names `theta` where V or dV/dθ is not finite.
fn each_theta(theta: &[f64], f: impl Fn(f64) -> poinsot::Result<f64>) -> Out<Vec<f64>> {
    Ok(theta
        .iter()
        .map(|&th| f(th))
        .collect::<poinsot::Result<_>>()?)
}

getters!(HeavyTop {
    " I₁ (kg·m²)."
    I1 i1;
    " I₃ (kg·m²)."
    I3 i3;
    " m g l (N·m)."
    mgl mgl;
    " p_φ = I₁ φ̇ sin²θ + p_ψ cos θ (kg·m²/s, 2.104), conserved."
    pPhi p_phi;
    " p_ψ = I₃ ω₃ (kg·m²/s, 2.103), conserved."
    pPsi p_psi;
    " The spin ω₃ = ψ̇ + φ̇ cos θ (rad/s, 2.99), constant."
    omega3 omega3;
    " The total energy E (J, 2.105), conserved."
    energy energy;
    " E' = E − p_ψ²/(2I₃) = ½ I₁ θ̇² + V(θ) (J, 2.109)."
    reducedEnergy reduced_energy;
    " The mean of φ̇ over a nutation period (rad/s)."
    meanPrecessionRate mean_precession_rate;
    " The mean of ψ̇ over a nutation period (rad/s)."
    meanSpinRate mean_spin_rate;
});

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convert::refused;

    /// Round-off of O(1) quantities after a few dozen operations.
    const ROUND_OFF: f64 = 1e-12;

    #[test]
    fn binding_matches_the_core_and_keeps_the_constants() {
        let top = HeavyTop::from_spin(1.0, 0.5, 1.5, 0.0, 0.7, 0.0, 0.0, 0.0, 8.0).unwrap();
        assert_eq!(top.motion_class(), "cusps");
        let core = an::HeavyTop::with_spin(1.0, 0.5, 1.5, 0.0, 0.7, 0.0, 0.0, 0.0, 8.0).unwrap();
        assert_eq!(top.energy(), core.energy());
        let ts = [0.0, 0.4, 1.3];
        let a = top.euler_angles(ts.to_vec()).unwrap();
        let r = top.euler_rates(ts.to_vec()).unwrap();
        for (k, &t) in ts.iter().enumerate() {
            assert_eq!(&a[3 * k..3 * k + 3], &core.euler_angles(t).unwrap()[..]);
            let s = top.state(t).unwrap();
            assert_eq!(&s[..3], &a[3 * k..3 * k + 3]);
            assert_eq!(&s[3..], &r[3 * k..3 * k + 3]);
            // The energy recomputed from the state is E to round-off (2.105).
            let c = HeavyTop::constants_of_state(1.0, 0.5, 1.5, s[1], s[4], s[3], s[5]).unwrap();
            assert!((c[2] - top.energy()).abs() < ROUND_OFF * (1.0 + top.energy().abs()));
            assert!((c[0] - top.p_phi()).abs() < ROUND_OFF * (1.0 + top.p_psi().abs()));
            let (t1, t2) = core.turning_points();
            assert!(s[1] >= t1 - ROUND_OFF && s[1] <= t2 + ROUND_OFF);
        }
        // The symmetry axis is the third column of the zxz matrix: (sinθ sinφ, −sinθ cosφ, cosθ).
        let axis = top.symmetry_axis(ts.to_vec()).unwrap();
        for k in 0..ts.len() {
            let (ph, th) = (a[3 * k], a[3 * k + 1]);
            let want = [th.sin() * ph.sin(), -th.sin() * ph.cos(), th.cos()];
            for i in 0..3 {
                assert!((axis[3 * k + i] - want[i]).abs() < ROUND_OFF);
            }
        }
        let tp = top.turning_points();
        let v = top.effective_potential(tp.clone()).unwrap();
        for x in v {
            assert!((x - top.reduced_energy()).abs() < ROUND_OFF * (1.0 + x.abs()));
        }
        assert_eq!(top.initial_state()[1], 0.7);
        assert!(top.nutation_period().is_finite());
        assert_eq!(top.precession_period(), core.precession_period().unwrap());
    }

    #[test]
    fn precession_period_is_one_turn_at_the_mean_rate_and_infinite_when_the_axis_does_not_turn() {
        // Steady precession: φ advances by 2π in exactly one period.
        let (i1, i3, mgl, theta0, w3) = (1.0, 0.5, 1.5, 0.87, 12.0);
        let slow = an::steady_precession(i1, i3, mgl, theta0, w3).unwrap().slow;
        let top = HeavyTop::from_spin(i1, i3, mgl, 0.0, theta0, 0.0, slow, 0.0, w3).unwrap();
        let period = top.precession_period();
        assert!((period - 2.0 * std::f64::consts::PI / slow.abs()).abs() < ROUND_OFF * period);
        // φ turns at that rate: a quarter turn in a quarter period.
        let phi = top.state(period / 4.0).unwrap()[0];
        assert!((phi - slow * period / 4.0).abs() < 1e-9, "{phi}");
        assert!(
            (phi.abs() - std::f64::consts::FRAC_PI_2).abs() < 1e-9,
            "{phi}"
        );
        // A sleeping top: the axis stays upright, no turn, no period (Infinity, not NaN).
        let sleeping = HeavyTop::from_spin(i1, i3, mgl, 0.0, 0.0, 0.0, 0.0, 0.0, 7.0).unwrap();
        assert_eq!(sleeping.precession_period(), f64::INFINITY);
    }

    #[test]
    fn errors_name_the_argument() {
        refused(
            HeavyTop::new(1.0, 0.5, 1.0, 0.0, 4.0, 0.0, 0.0, 0.0, 1.0),
            "theta",
        );
        refused(
            HeavyTop::new(1.0, 0.5, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0),
            "mgl",
        );
        let e = HeavyTop::new(1.0, 3.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0).unwrap_err();
        assert_eq!(e.name, "InvalidInertiaError");
        let nan = f64::NAN;
        refused(
            HeavyTop::from_spin(1.0, 0.5, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, nan),
            "omega3",
        );
        let top = HeavyTop::new(1.0, 0.5, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 6.0).unwrap();
        refused(top.euler_angles(vec![0.0, nan]), "t:");
        refused(top.state(f64::INFINITY), "t:");
        refused(top.effective_potential(vec![-0.1]), "theta");
        refused(
            HeavyTop::steady_precession(1.0, 0.5, 1.0, 0.3, 0.1),
            "omega3",
        );
        refused(
            HeavyTop::constants_of_state(1.0, 0.5, 1.0, 1.0, 0.0, nan, 1.0),
            "phi_dot",
        );
        // A spin beyond the doubles from finite constants (p_psi / I3 overflows): refused by the
        // core, naming p_psi, where the binding's own guard used to refuse it.
        refused(
            HeavyTop::from_constants(1.0, 5e-324, 0.0, 0.0, 1e-15, 1e300),
            "p_psi",
        );
    }

    #[test]
    fn steady_and_sleeping_statics() {
        let s = HeavyTop::steady_precession(1.0, 0.5, 1.5, 0.7, 8.0).unwrap();
        // The slow root solves I₁ cos θ₀ φ̇² − p_ψ φ̇ + m g l = 0 (2.116).
        let res = 0.7f64.cos() * s.slow() * s.slow() - 4.0 * s.slow() + 1.5;
        assert!(res.abs() < ROUND_OFF);
        let top = HeavyTop::from_spin(1.0, 0.5, 1.5, 0.0, 0.7, 0.0, s.slow(), 0.0, 8.0).unwrap();
        assert_eq!(top.motion_class(), "steady precession");
        let thr = HeavyTop::sleeping_threshold(1.0, 0.5, 1.5).unwrap();
        assert!((thr - 2.0 * 1.5f64.sqrt() / 0.5).abs() < ROUND_OFF);
        assert_eq!(HeavyTop::min_spin(1.0, 0.5, 1.5, 0.0).unwrap(), thr);
        let up = HeavyTop::from_spin(1.0, 0.5, 1.5, 0.0, 0.0, 0.0, 0.0, 0.0, 1.01 * thr).unwrap();
        assert_eq!(up.motion_class(), "sleeping");
        assert!(up.is_sleeping_stable());
        let weak = HeavyTop::from_spin(1.0, 0.5, 1.5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.99 * thr).unwrap();
        assert!(!weak.is_sleeping_stable());
    }
}
