//! Parameter studies: a model computed at every point of a grid (or a sample) of its
//! keywords, in parallel, with every point validated before any work.
//!
//! A sweep is a [`Grid`]: named dimensions ([`Dim`]) and the model's keywords ([`Column`]),
//! each constant or varying along one dimension; the points are the row-major product of the
//! dimensions. Each model has a `check_*` function, which checks every point as the model's own
//! constructor checks its arguments (tens of nanoseconds a point, no motion solved), and a
//! function that computes every point after that check and the memory budget
//! ([`crate::limits`]) passed, across the cores (rayon), polling [`crate::control`] (Ctrl-C,
//! progress). An error names the keyword and the point, in the indices of the whole sweep:
//! `"theta: must be finite and in [0, pi], got 4 (at theta[3], psi_dot[0])"`; of several
//! failing points the first in row-major order is reported, whatever the number of threads.
//!
//! A block of a sweep (a chunk computed on its own, e.g. on another machine) is the grid of
//! the block's slices of the keywords, with each dimension's `offset` the index of its first
//! element: its points are computed by the same code from the same numbers, so the blocks of a
//! sweep reproduce the whole sweep bit for bit, and their errors name the same indices.
//!
//! | model | function | keywords |
//! |---|---|---|
//! | the heavy symmetric top (2.102–2.121) | [`heavy_top`] | [`HEAVY_TOP_KEYWORDS`] |
//! | the torque-free rigid body (2.67–2.97) | [`free_body`] | [`FREE_BODY_KEYWORDS`] |
//! | rigid bodies under a torque (2.71) | [`simulate`] | [`SIMULATE_KEYWORDS`] |
//! | a body dropped on the rotating Earth (2.30–2.42) | [`drop`] | [`DROP_KEYWORDS`] |
//! | a projectile on the rotating Earth | [`projectile`] | [`PROJECTILE_KEYWORDS`] |

mod earth;
mod free_body;
mod grid;
mod heavy_top;
mod simulate;

pub use earth::{
    check_drop, check_projectile, drop, projectile, DropPoint, ProjectilePoint, DROP_KEYWORDS,
    PROJECTILE_KEYWORDS,
};
pub use free_body::{
    check_free_body, free_body, regime_code, stability_code, FreeBodyPoint, FREE_BODY_KEYWORDS,
    FREE_REGIMES, STABILITIES,
};
pub use grid::{Column, Dim, Grid, Param};
pub use heavy_top::{
    check_heavy_top, heavy_top, motion_class_code, HeavyTopPoint, HEAVY_TOP_KEYWORDS,
    MOTION_CLASSES,
};
pub use simulate::{check_simulate, simulate, SimulatePoint, SIMULATE_KEYWORDS};
