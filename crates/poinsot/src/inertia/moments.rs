//! Principal moments checked as a body's (the rule of [`super::check_inertia`] without its
//! eigen-decomposition), for every caller given moments rather than a tensor: the free body, the
//! integrators, the batches' rows, the sweeps.

use crate::error::{check_finite, Error, Result};
use crate::inertia::PHYSICAL_RTOL;
use crate::special::fp::{exponent, ldexp};

/// Checks principal moments: finite, > 0, and the triangle inequality `I₁ + I₂ ≥ I₃` of the
/// sorted moments within [`PHYSICAL_RTOL`] of the largest (the same
/// rule as [`super::check_inertia`], without its eigen-decomposition), tested at unit
/// scale so that the verdict does not depend on the units; errors name `moments`
/// ([`crate::ErrorKind::InvalidInertia`]).
pub fn check_moments(moments: &[f64; 3]) -> Result<()> {
    if let Err(e) = check_finite("moments", moments) {
        return Err(Error::inertia("moments", e.message));
    }
    if let Some(i) = moments.iter().position(|&v| v <= 0.0) {
        return Err(Error::inertia(
            "moments",
            format!(
                "principal moments must be > 0 for the body to turn, got {} at index {i}",
                moments[i]
            ),
        ));
    }
    // Sorted ascending (three positive finite values: a comparison network).
    let mut m = *moments;
    if m[0] > m[1] {
        m.swap(0, 1);
    }
    if m[1] > m[2] {
        m.swap(1, 2);
    }
    if m[0] > m[1] {
        m.swap(0, 1);
    }
    let e = exponent(m[2]);
    let u = m.map(|v| ldexp(v, -e));
    let excess = u[2] - (u[0] + u[1]);
    if excess > PHYSICAL_RTOL * u[2] {
        return Err(Error::inertia(
            "moments",
            format!(
                "principal moments {m:?} violate the triangle inequality I1 + I2 >= I3: {} + {} < {} by {:.6e} \
                 ({:.3e} of the largest moment); no distribution of mass has these moments",
                m[0],
                m[1],
                m[2],
                m[2] - (m[0] + m[1]),
                excess / u[2]
            ),
        ));
    }
    Ok(())
}
