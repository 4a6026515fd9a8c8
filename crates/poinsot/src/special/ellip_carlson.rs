//! Carlson's symmetric integrals R_F, R_D, R_J as the `ellip` crate evaluates them (Boost's
//! duplication algorithms): the one entry point to that crate. The heavy top's exact motion
//! and its Fourier series are computed with these, and their numbers are pinned to them; the
//! rest of the crate uses [`super::carlson`], which also converges at widely spread arguments.
//!
//! Each returns NaN where `ellip` refuses the arguments (negative, two zeros, NaN, or no
//! convergence): the callers pass arguments they guarantee valid, or test for NaN.

/// R_F(x, y, z) (DLMF 19.16.1); NaN where `ellip` refuses the arguments.
#[inline]
pub(crate) fn rf(x: f64, y: f64, z: f64) -> f64 {
    ellip::elliprf(x, y, z).unwrap_or(f64::NAN)
}

/// R_D(x, y, z) = R_J(x, y, z, z) (DLMF 19.16.5); NaN where `ellip` refuses the arguments.
#[inline]
pub(crate) fn rd(x: f64, y: f64, z: f64) -> f64 {
    ellip::elliprd(x, y, z).unwrap_or(f64::NAN)
}

/// R_J(x, y, z, p) (DLMF 19.16.2); NaN where `ellip` refuses the arguments.
#[inline]
pub(crate) fn rj(x: f64, y: f64, z: f64, p: f64) -> f64 {
    ellip::elliprj(x, y, z, p).unwrap_or(f64::NAN)
}
