//! Special functions: the Jacobi elliptic functions sn, cn, dn and the amplitude am of real
//! argument (written here: no crate has them to the needed accuracy), and Legendre's elliptic
//! integrals F, E, K, Π (thin checked wrappers of the `ellip` crate).
//!
//! Convention: the **parameter** `m = k²` throughout (as mpmath, scipy and DLMF), `0 ≤ m ≤ 1`
//! for the Jacobi functions. These solve the free asymmetric top (the `analytic` module):
//! ω(t) by sn, cn, dn and the attitude by Π.

mod dd;
mod integrals;
mod jacobi;

pub use integrals::{
    ellipe, ellipeinc, ellipf, ellipf_complement, ellipk, ellippi, ellippiinc, ellippiinc_complement,
};
pub use jacobi::{am, cn, dn, jacobi_all, sn, sncndn, Jacobi, JacobiValues};
