//! The result of the rigid Earth's averaged pole at given times
//! ([`RigidEarth::averaged_pole`], written in `rigid.rs` beside the rate and the amplitudes it
//! composes): the uniform luni-solar precession plus the principal (18.6-year) nutation, the two
//! results of the orbit-averaged theory ([`RigidEarth::precession_rate`],
//! [`RigidEarth::nutation_amplitudes`]) composed into the pole's angles.
//! [`RigidEarth::simulate`] integrates the instantaneous torques instead; the averaged pole
//! follows its run to within the short-period (semi-annual and fortnightly) nods that the average
//! leaves out.

#[cfg(doc)]
use super::RigidEarth;

/// The default `nutation_scale` of [`RigidEarth::averaged_pole`]: 1, the Earth's own nutation.
pub const NUTATION_SCALE: f64 = 1.0;

/// The averaged pole of a [`RigidEarth`] at a list of times ([`RigidEarth::averaged_pole`]),
/// one entry per time, in the order given.
#[derive(Debug, Clone, PartialEq)]
pub struct AveragedPole {
    /// ψ(t), the precession angle of the spin axis (rad, unwrapped): its ecliptic longitude
    /// counted westward from its place at t = 0 — the IAU's ψ_A plus the nutation Δψ, the
    /// negative of [`super::PoleRun::longitude`].
    pub psi: Vec<f64>,
    /// ε(t), the obliquity: the angle of the spin axis from the ecliptic's pole (rad).
    pub obliquity: Vec<f64>,
    /// Ω(t), the ecliptic longitude of the Moon's ascending node (rad, unwrapped).
    pub moon_node: Vec<f64>,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::earth::{MeanOrbit, RigidEarth, MOON_ORBIT};
    use crate::error::Result;
    use std::f64::consts::{PI, TAU};

    const YEAR: f64 = 365.25 * 86_400.0;
    const ARCSEC: f64 = PI / 648_000.0;

    #[test]
    fn the_averaged_pole_is_the_closed_form() {
        // Written out independently: P = −(3/2)(H/ω) cos ε Σ GM/(a³(1 − e²)^{3/2}) (the Moon's
        // with 1 − (3/2) sin² i), Δψ₀ = −K sin i cos i cos 2ε/(ν sin ε), Δε₀ = K sin i cos i
        // cos ε/ν with K the Moon's (3/2)(GM/(a³(1 − e²)^{3/2}))(H/ω), ν = 2π/T_node.
        let e = RigidEarth::default();
        let (h, w, eps) = (e.dynamical_flattening, e.rotation_rate, e.obliquity);
        let inv = |o: &MeanOrbit| {
            o.gm / (o.semi_major_axis.powi(3) * (1.0 - o.eccentricity.powi(2)).powf(1.5))
        };
        let si = e.moon.inclination.sin();
        let ci = e.moon.inclination.cos();
        let k_moon = 1.5 * inv(&e.moon) * h / w;
        let p = -1.5 * h / w * eps.cos() * (inv(&e.sun) + inv(&e.moon) * (1.0 - 1.5 * si * si));
        let nu = TAU / e.moon.node_period;
        let dpsi = -k_moon * si * ci * (2.0 * eps).cos() / (nu * eps.sin());
        let deps = k_moon * si * ci * eps.cos() / nu;
        let times: Vec<f64> = (0..50)
            .map(|k| k as f64 * 0.9 * YEAR - 3.0 * YEAR)
            .collect();
        let (node0, scale) = (0.7, 3.0);
        let got = e.averaged_pole(&times, node0, scale).unwrap();
        assert_eq!(got.psi.len(), times.len());
        for (k, &t) in times.iter().enumerate() {
            let node = node0 - TAU * t / e.moon.node_period;
            let psi = -p * t + scale * dpsi * node.sin();
            let obl = eps + scale * deps * node.cos();
            assert!((got.psi[k] - psi).abs() < 1e-12 * (1.0 + psi.abs()), "{k}");
            assert!((got.obliquity[k] - obl).abs() < 1e-14, "{k}");
            assert!((got.moon_node[k] - node).abs() < 1e-13, "{k}");
        }
        // About 50.4″ a year westward, and at t = 0 the nod in full: ε₀ + 3 Δε₀ cos 0.7.
        let year = e.averaged_pole(&[0.0, YEAR], 0.0, 0.0).unwrap();
        assert!(((year.psi[1] - year.psi[0]) / ARCSEC - 50.40).abs() < 0.02);
        assert!((year.obliquity[0] - eps).abs() == 0.0);
        // Negative control: without the nutation (nutation_scale 0) the pole does not nod by
        // the 3 × 9.2″ of the scaled one.
        let flat = e.averaged_pole(&times, node0, 0.0).unwrap();
        let nod = (0..times.len())
            .map(|k| (flat.obliquity[k] - got.obliquity[k]).abs())
            .fold(0.0, f64::max);
        assert!(nod > 25.0 * ARCSEC && nod < 3.0 * deps, "{nod}");
    }

    #[test]
    fn bad_input_is_refused_by_name() {
        let e = RigidEarth::default();
        let arg = |r: Result<AveragedPole>| r.unwrap_err().argument;
        assert_eq!(arg(e.averaged_pole(&[0.0, f64::NAN], 0.0, 1.0)), "t");
        assert_eq!(
            arg(e.averaged_pole(&[0.0], f64::INFINITY, 1.0)),
            "moon_node"
        );
        assert_eq!(arg(e.averaged_pole(&[0.0], 0.0, -1.0)), "nutation_scale");
        assert_eq!(
            arg(e.averaged_pole(&[0.0], 0.0, f64::NAN)),
            "nutation_scale"
        );
        // An equator all but in the ecliptic: Δψ₀ ∝ 1/sin ε is 1e291 rad, and × 1e20 overflows.
        let nearly = RigidEarth::new(3e-3, 7e-5, 1e-300).unwrap();
        assert_eq!(
            arg(nearly.averaged_pole(&[0.0], 1.0, 1e20)),
            "nutation_scale"
        );
        assert!(nearly.averaged_pole(&[0.0], 1.0, 1.0).is_ok());
        let flat = RigidEarth::new(3e-3, 7e-5, 0.0).unwrap();
        assert_eq!(arg(flat.averaged_pole(&[0.0], 0.0, 1.0)), "obliquity");
        // No times, no pole.
        assert!(e.averaged_pole(&[], 0.0, 1.0).unwrap().psi.is_empty());
        // The Moon's node held still: the nod has no period, the nutation is refused by name.
        let still = RigidEarth {
            moon: MeanOrbit {
                node_period: f64::INFINITY,
                ..MOON_ORBIT
            },
            ..RigidEarth::default()
        };
        assert_eq!(arg(still.averaged_pole(&[0.0], 0.0, 1.0)), "obliquity");
    }
}
