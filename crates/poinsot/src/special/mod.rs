//! Special functions: the Jacobi elliptic functions sn, cn, dn and the amplitude am of real
//! argument, and Legendre's elliptic integrals F, E, K, Π on Carlson's symmetric integrals
//! (all written here: no crate has them to the needed accuracy over the whole double range).
//!
//! Convention: the **parameter** `m = k²` throughout (as mpmath, scipy and DLMF), `0 ≤ m ≤ 1`
//! for the Jacobi functions. These solve the free asymmetric top (the `analytic` module):
//! ω(t) by sn, cn, dn and the attitude by Π.

pub(crate) mod carlson;
mod dd;
pub(crate) mod fp;
pub(crate) mod integrals;
mod jacobi;

pub use integrals::{
    ellipe, ellipeinc, ellipf, ellipf_complement, ellipk, ellippi, ellippiinc,
    ellippiinc_complement,
};
pub use jacobi::{am, cn, dn, jacobi_all, sn, sncndn, Jacobi, JacobiValues};

/// Legendre's elliptic integral named `kind` at (φ, n, m): `"K"` K(m), `"E"` E(m), `"PI"`
/// Π(n | m), `"F"` F(φ | m), `"EINC"` E(φ | m), `"PIINC"` Π(n; φ | m) (the arguments a kind
/// does not take are ignored). An unknown kind is refused naming `kind`.
pub fn elliptic(kind: &str, phi: f64, n: f64, m: f64) -> crate::Result<f64> {
    match kind {
        "K" => ellipk(m),
        "E" => ellipe(m),
        "PI" => ellippi(n, m),
        "F" => ellipf(phi, m),
        "EINC" => ellipeinc(phi, m),
        "PIINC" => ellippiinc(phi, n, m),
        _ => Err(crate::Error::invalid(
            "kind",
            format!("must be one of K, E, PI, F, EINC, PIINC, got {kind:?}"),
        )),
    }
}
