//! Rigid-body dynamics: Euler's equations of motion with torques (the unit's 2.67–2.76), the
//! attitude as a unit quaternion, and `simulate` — one interface to the exact torque-free
//! flow, the Lie–Poisson splitting (orders 2, 4, 6), RK4 and DOP853 — for one body or many.

mod batch;
mod carried;
mod equations;
mod gyrocompass;
mod lanes;
mod model;
mod simulate;
mod splitting;
mod torque;

pub use batch::{simulate_batch, BatchResult};
pub use carried::{
    fixed_axis_heading_rate, free_gyroscope, simulate_carried, CarriedTorque, CarriedTrajectory,
    Carrier, Carrying, Load,
};
pub use equations::{angular_acceleration, angular_acceleration_principal, power, quaternion_rate};
pub use gyrocompass::{
    CompassRun, Gyrocompass, LinearCompass, Ship, Track, Turn, COMPASS_ANGULAR_MOMENTUM,
    COMPASS_DAMPING, COMPASS_INERTIA, COMPASS_METHOD, COMPASS_PENDULOSITY, COMPASS_SAMPLES,
    COMPASS_TOLERANCES, COMPASS_TURN_DURATION, VISCOUS_FACTOR,
};
pub use model::BodyInertia;
pub use simulate::{default_step, simulate, Method, SimulateOptions, Trajectory};
pub use splitting::{free_steps, kicked_step, FreeStrang, SplitState};
pub use torque::{Torque, TorqueContext, TorqueKind, TorqueModel};
