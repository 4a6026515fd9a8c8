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
