//! Symmetric composition methods (Hairer, Lubich & Wanner, *Geometric Numerical Integration*,
//! §II.4 and §V.3): from a symmetric second-order one-step map Φ_h (Strang splitting, leapfrog),
//! `Φ_{γ_s h} ∘ … ∘ Φ_{γ_1 h}` with symmetric coefficients γ is a symmetric method of higher
//! order, and it inherits every geometric property of Φ (symplecticity, Poisson structure,
//! time reversibility, exact conservation of the Casimirs).
//!
//! * order 2: Φ itself (one stage);
//! * order 4: Yoshida's / Suzuki's triple jump (3 stages),
//!   `γ₁ = γ₃ = 1/(2 − 2^{1/3})`, `γ₂ = −2^{1/3}/(2 − 2^{1/3})`;
//! * order 6: Kahan & Li's `s9odr6a` (9 stages; HLW eq. V.3.11), among the most accurate
//!   9-stage sixth-order compositions.

use crate::error::{Error, Result};

/// The triple jump of order 4 (Yoshida 1990).
pub const TRIPLE_JUMP_4: [f64; 3] = {
    // 2^{1/3}, to the last bit.
    const CBRT2: f64 = 1.259_921_049_894_873_2;
    const G1: f64 = 1.0 / (2.0 - CBRT2);
    [G1, -CBRT2 / (2.0 - CBRT2), G1]
};

/// Kahan & Li's 9-stage symmetric composition of order 6 (`s9odr6a`), as published (20
/// digits; the literals round to the nearest doubles).
#[allow(clippy::excessive_precision)]
pub const KAHAN_LI_6: [f64; 9] = [
    0.392_161_444_007_314_139_3,
    0.332_599_136_789_359_438_6,
    -0.706_246_172_557_639_359_8,
    0.082_213_596_293_550_800_23,
    0.798_543_990_934_829_963_4,
    0.082_213_596_293_550_800_23,
    -0.706_246_172_557_639_359_8,
    0.332_599_136_789_359_438_6,
    0.392_161_444_007_314_139_3,
];

/// The step-size coefficients of the symmetric composition of order `order` (2, 4 or 6);
/// the error names `order` otherwise.
pub fn composition_coefficients(order: usize) -> Result<&'static [f64]> {
    match order {
        2 => Ok(&[1.0]),
        4 => Ok(&TRIPLE_JUMP_4),
        6 => Ok(&KAHAN_LI_6),
        _ => Err(Error::invalid(
            "order",
            format!("composition methods have order 2, 4 or 6, got {order}"),
        )),
    }
}

/// A symmetric second-order one-step map `Φ_h` (`Φ_{−h} = Φ_h⁻¹`) to compose.
pub trait SymmetricStep {
    /// Advances the state by one step of (signed) size `h`.
    fn step(&mut self, h: f64);
}

/// Advances `base` by one step `h` of the composition with coefficients `gammas`.
pub fn compose<S: SymmetricStep + ?Sized>(base: &mut S, gammas: &[f64], h: f64) {
    for &g in gammas {
        base.step(g * h);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Leapfrog (Störmer–Verlet) on the pendulum q̈ = −sin q: a symmetric base method.
    struct Pendulum {
        q: f64,
        p: f64,
    }
    impl SymmetricStep for Pendulum {
        fn step(&mut self, h: f64) {
            self.p -= 0.5 * h * self.q.sin();
            self.q += h * self.p;
            self.p -= 0.5 * h * self.q.sin();
        }
    }

    fn error(order: usize, n: usize) -> f64 {
        let reference = {
            let mut s = Pendulum { q: 1.0, p: 0.0 };
            for _ in 0..20000 {
                compose(&mut s, &KAHAN_LI_6, 1e-3);
            }
            (s.q, s.p)
        };
        let mut s = Pendulum { q: 1.0, p: 0.0 };
        let h = 20.0 / n as f64;
        for _ in 0..n {
            compose(&mut s, composition_coefficients(order).unwrap(), h);
        }
        (s.q - reference.0).hypot(s.p - reference.1)
    }

    #[test]
    fn compositions_have_their_order() {
        // Sum of the coefficients is 1 (consistency), and halving h divides the error by 2^order.
        for order in [2, 4, 6] {
            let g = composition_coefficients(order).unwrap();
            assert!((g.iter().sum::<f64>() - 1.0).abs() < 1e-15);
            let ratio = error(order, 100) / error(order, 200);
            let observed = ratio.log2();
            assert!(
                (observed - order as f64).abs() < 0.3,
                "order {order}: observed {observed}"
            );
        }
        assert_eq!(composition_coefficients(3).unwrap_err().argument, "order");
    }
}
