//! Poinsot's construction and the stability of steady rotations.
//!
//! In the body, ω lies on the energy ellipsoid `ω·I·ω = 2T` and on the momentum ellipsoid
//! `|I·ω|² = L²`; their intersection is the **polhode**. In space, ω's tip moves on the
//! **invariable plane** `ω·L̂ = 2T/|L|`, tracing the **herpolhode**: the inertia ellipsoid
//! `x·I·x = 1`, scaled by (2T)^½ and fixed to the body, rolls without slipping on that plane,
//! touching it at ω (Poinsot 1834; Goldstein §5.6).

use super::free_rigid_body::FreeRigidBody;
use crate::error::{check_finite, Result};
use crate::special::fp::{exponent, ldexp};
use crate::Vec3;

/// Whether small deviations from a steady rotation stay small.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stability {
    /// Rotation about the largest- or smallest-moment axis: deviations oscillate.
    Stable,
    /// Rotation about the intermediate axis: deviations grow exponentially.
    Unstable,
    /// Two equal moments about the other axes: deviations neither grow nor oscillate
    /// (linearly).
    Neutral,
}

impl Stability {
    /// "stable", "unstable" or "neutral".
    pub fn as_str(self) -> &'static str {
        match self {
            Stability::Stable => "stable",
            Stability::Unstable => "unstable",
            Stability::Neutral => "neutral",
        }
    }
}

/// The linear stability of the steady rotation about one principal axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisStability {
    /// Stable, unstable or neutral.
    pub stability: Stability,
    /// The angular frequency of the small oscillations (stable) or the exponential growth
    /// rate σ (unstable, deviations ∝ e^{σt}) (1/s); 0 when neutral.
    pub rate: f64,
}

/// The stability of steady rotation at rate `spin` (rad/s) about each principal axis of a
/// body with principal moments `moments` (kg·m², any order).
///
/// Linearising Euler's equations (2.72) about ω = spin·e_i gives, for the other two
/// components, `ε̈ = −spin² (I_i − I_j)(I_i − I_k)/(I_j I_k) ε`: oscillation (stable) when I_i
/// is the largest or smallest moment, exponential growth with
/// `σ = |spin| ((I₂ − I₁)(I₃ − I₂)/(I₁I₃))^½` about the intermediate axis (the tennis-racket
/// or Dzhanibekov instability). The ratio of moments is formed at unit scale and the rate as
/// `|spin| · ratio^½` (the ratio is at most 1 by the triangle inequality, so the rate never
/// exceeds |spin| and never overflows). Errors name `moments` or `spin`.
pub fn axis_stability(moments: [f64; 3], spin: f64) -> Result<[AxisStability; 3]> {
    super::check_moments(&moments)?;
    check_finite("spin", &[spin])?;
    let e = exponent(moments.iter().cloned().fold(0.0, f64::max));
    let m = moments.map(|v| ldexp(v, -e));
    Ok(std::array::from_fn(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        let q = (m[i] - m[j]) * (m[i] - m[k]) / (m[j] * m[k]);
        if q > 0.0 {
            AxisStability {
                stability: Stability::Stable,
                rate: spin.abs() * q.sqrt(),
            }
        } else if q < 0.0 {
            AxisStability {
                stability: Stability::Unstable,
                rate: spin.abs() * (-q).sqrt(),
            }
        } else {
            AxisStability {
                stability: Stability::Neutral,
                rate: 0.0,
            }
        }
    }))
}

impl FreeRigidBody {
    /// `samples` points of the polhode: ω (body components, rad/s) over one period of ω(t),
    /// from t = 0. On the separatrix (infinite period) the half-branch from t = −12/λ to 12/λ
    /// (within e⁻¹² of the intermediate axis at both ends); a single point, repeated, when ω
    /// is constant. Sampled at unit scale, so a period beyond the double range does not
    /// matter. Errors name `samples` (must be ≥ 2, and the points within the memory budget).
    pub fn polhode(&self, samples: usize) -> Result<Vec<Vec3>> {
        let scale = *self.scale();
        self.polhode_hat(samples, |w| scale.omega(&w))
    }

    /// The polhode at unit scale (ω̂ over one unit-scale period), each point mapped by `f`.
    fn polhode_hat(&self, samples: usize, f: impl Fn(Vec3) -> Vec3) -> Result<Vec<Vec3>> {
        // The one statement of the limit: at least 2 points, each (3 numbers) within the memory
        // budget; the front ends pass the count on.
        crate::limits::check_count("samples", samples, 2, 24)?;
        let (period, frequency) = self.period_and_frequency_hat();
        let (t0, span) = if period.is_finite() {
            (0.0, period)
        } else if frequency > 0.0 {
            (-12.0 / frequency, 24.0 / frequency)
        } else {
            (0.0, 0.0)
        };
        // Polled every chunk of samples: Ctrl-C on a huge request.
        crate::control::try_map_n(samples, |i| {
            let th = t0 + span * i as f64 / (samples - 1) as f64;
            Ok(f(self.state_at_hat(th).0))
        })
    }

    /// The factor that takes ω̂ to the contact point: ω/(2T)^½ = ω̂ 2^e_w / ((2T̂)^½ 2^(e_i/2)
    /// 2^e_w) = ω̂ / ((2T̂)^½ 2^(e_i/2)).
    fn contact_factor(&self) -> f64 {
        let (energy_hat, _, e_i) = self.unit_scale();
        // (2T)^½ = (2T̂)^½ 2^(e_i/2) 2^e_w: split e_i = 2h + r.
        let h = e_i.div_euclid(2);
        let r = e_i - 2 * h;
        let root = (2.0 * energy_hat * if r == 1 { 2.0 } else { 1.0 }).sqrt();
        ldexp(1.0 / root, -h)
    }

    /// The distance of the invariable plane from the fixed point in Poinsot's construction,
    /// (2T)^½ / |L| (kg^-½, in the units of the inertia ellipsoid `x·I·x = 1`), with the
    /// contact point at ω / (2T)^½. Computed at unit scale: always representable
    /// (between ~1e-162 and ~1e155 for any moments of the double range).
    pub fn invariable_plane_distance(&self) -> f64 {
        let (energy_hat, l_hat, e_i) = self.unit_scale();
        let h = e_i.div_euclid(2);
        let r = e_i - 2 * h;
        let d = (2.0 * energy_hat).sqrt() / l_hat.norm();
        ldexp(
            if r == 1 {
                d / std::f64::consts::SQRT_2
            } else {
                d
            },
            -h,
        )
    }

    /// The unit normal L̂ = L / |L| of the invariable plane (space components, constant).
    pub fn invariable_plane_normal(&self) -> Vec3 {
        let (_, l_hat, _) = self.unit_scale();
        l_hat / l_hat.norm()
    }

    /// The point of contact of Poinsot's construction at time `t` (s), in **body** components:
    /// ρ = ω(t) / (2T)^½, the point of the inertia ellipsoid `ρ·I·ρ = 1` where it touches the
    /// invariable plane (kg^-½, the units of the inertia ellipsoid). Its locus over time
    /// is the polhode, scaled by (2T)^-½. Independent of the scale of ω, so always
    /// representable. Errors name `t`.
    pub fn contact_point_body(&self, t: f64) -> Result<Vec3> {
        let th = self.scale().time(t)?;
        Ok(self.state_at_hat(th).0 * self.contact_factor())
    }

    /// The point of contact at time `t` (s) in **space** components: R(t) ω(t) / (2T)^½. It
    /// lies on the invariable plane `ρ·L̂ = d` with d = [`Self::invariable_plane_distance`]
    /// (because ω·L = 2T, the unit's 2.53), and the ellipsoid's normal there, R I ρ, is
    /// parallel to L (so the ellipsoid is tangent to the plane). The contact point lies on the
    /// instantaneous axis ω, so its velocity as a point of the body, ω × ρ, vanishes: the
    /// ellipsoid rolls without slipping. Its locus over time is the herpolhode (scaled).
    /// Errors name `t`.
    pub fn contact_point(&self, t: f64) -> Result<Vec3> {
        let th = self.scale().time(t)?;
        let (w, q) = self.state_at_hat(th);
        Ok(crate::rotation::quaternion_rotate_unchecked(&q, &w) * self.contact_factor())
    }

    /// `samples` points of the polhode on the inertia ellipsoid `ρ·I·ρ = 1`: the
    /// [`Self::polhode`] scaled by (2T)^-½, body components (the same times). Errors name
    /// `samples` (must be ≥ 2).
    pub fn contact_polhode(&self, samples: usize) -> Result<Vec<Vec3>> {
        let f = self.contact_factor();
        self.polhode_hat(samples, |w| w * f)
    }
}
