//! `DEFAULTS`: the default of every argument of the public Python calls that has one (other than
//! `None` and the flags), by the call's public name (`"simulate"`, `"RigidBody.from_density"`,
//! `"sweep.drop"`) and the argument's name. Every value is the core's (`poinsot::defaults`);
//! `python/poinsot` reads its signatures' defaults from here and
//! `python/tests/test_defaults_once.py` holds every public signature to this table.

use poinsot::defaults as d;
use poinsot::integrate::Tolerances;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

/// One default value: a float, a count, a name or a vector (a tuple of floats in Python).
enum V {
    F(f64),
    N(usize),
    S(&'static str),
    T(Vec<f64>),
}

impl From<f64> for V {
    fn from(x: f64) -> Self {
        V::F(x)
    }
}
impl From<usize> for V {
    fn from(n: usize) -> Self {
        V::N(n)
    }
}
impl From<&'static str> for V {
    fn from(s: &'static str) -> Self {
        V::S(s)
    }
}
impl<const N: usize> From<[f64; N]> for V {
    fn from(v: [f64; N]) -> Self {
        V::T(v.to_vec())
    }
}
impl From<poinsot::Vec3> for V {
    fn from(v: poinsot::Vec3) -> Self {
        V::T(v.iter().copied().collect())
    }
}

type Row = Vec<(&'static str, V)>;

/// A row of the table: `argument => value, ...`.
macro_rules! row {
    ($($arg:literal => $value:expr),* $(,)?) => { vec![$(($arg, V::from($value))),*] };
}

/// `row` followed by the integrator arguments of a run with tolerances `t`.
fn with(mut row: Row, t: Tolerances) -> Row {
    row.extend(row! { "rtol" => t.rtol, "atol" => t.atol, "max_steps" => t.max_steps });
    row
}

/// Every public call's defaults.
#[rustfmt::skip]
fn calls() -> Vec<(&'static str, Row)> {
    let frame = poinsot::frames::MovingFrame::default();
    let s = d::EulerState::default();
    let seq = || row! { "seq" => d::EULER_SEQUENCE };
    let com = || row! { "center_of_mass" => d::CENTER_OF_MASS };
    let mesh = || row! { "density" => d::MESH_DENSITY };
    let rest = || row! { "velocity" => d::AT_REST, "acceleration" => d::AT_REST };
    let polhode = || row! { "samples" => d::POLHODE_SAMPLES };
    let batch = || row! { "method" => d::BATCH_METHOD, "max_steps" => d::DEFAULT_MAX_STEPS };
    let sweep_fall = || with(row! { "gravity" => d::GRAVITY }, d::DROP_TOLERANCES);
    let drop = || with(row! { "gravity" => d::GRAVITY, "samples" => d::DROP_SAMPLES }, d::DROP_TOLERANCES);
    let mut projectile = drop();
    projectile.extend(row! { "height" => d::LAUNCH_HEIGHT });
    let from_spin = || row! { "theta_dot" => s.theta_dot, "phi_dot" => s.phi_dot, "phi" => s.phi, "psi" => s.psi };
    let mut from_body = from_spin();
    from_body.extend(row! { "g" => d::STANDARD_GRAVITY });
    let mut start = from_spin();
    start.extend(row! { "psi_dot" => s.psi_dot });
    vec![
        ("check_rotation_matrix", row! { "tol" => d::CHECK_ROTATION_TOL }),
        ("euler_to_matrix", seq()),
        ("matrix_to_euler", seq()),
        ("body_angular_velocity", seq()),
        ("space_angular_velocity", seq()),
        ("euler_rates", row! { "seq" => d::EULER_SEQUENCE, "frame" => d::EULER_RATES_FRAME }),
        ("classify", row! { "rtol" => d::DEFAULT_KIND_RTOL }),
        ("RigidBody.__init__", com()),
        ("RigidBody.from_inertia", com()),
        ("RigidBody.from_density", row! {
            "rtol" => d::CUBATURE.rtol, "atol" => d::CUBATURE.atol, "max_evals" => d::CUBATURE.max_evals,
        }),
        ("RigidBody.from_mesh", mesh()),
        ("RigidBody.from_trimesh", mesh()),
        ("RigidBody.load_mesh", mesh()),
        ("MovingFrame.__init__", row! {
            "origin" => frame.origin, "velocity" => frame.velocity, "acceleration" => frame.acceleration,
            "angular_velocity" => frame.angular_velocity, "angular_acceleration" => frame.angular_acceleration,
        }),
        ("MovingFrame.to_fixed", rest()),
        ("MovingFrame.to_moving", rest()),
        ("SpringParticle.simulate", with(row! { "samples" => d::PARTICLE_SAMPLES }, d::PARTICLE_TOLERANCES)),
        ("simulate_particle", with(row! {
            "samples" => d::PARTICLE_SAMPLES, "mass" => d::PARTICLE_MASS, "stiffness" => d::PARTICLE_STIFFNESS,
        }, d::PARTICLE_TOLERANCES)),
        ("Earth.__init__", row! {
            "rotation_rate" => d::SIDEREAL_RATE, "radius" => d::MEAN_RADIUS, "g" => d::STANDARD_GRAVITY,
        }),
        ("Earth.solar_day", row! { "radius" => d::MEAN_RADIUS, "g" => d::STANDARD_GRAVITY }),
        ("RigidEarth.__init__", row! {
            "dynamical_flattening" => d::DYNAMICAL_FLATTENING, "rotation_rate" => d::SIDEREAL_RATE,
            "obliquity" => d::OBLIQUITY_J2000,
        }),
        ("RigidEarth.simulate", row! {
            "samples" => d::POLE_SAMPLES, "moon_node" => d::POLE_MOON_NODE,
            "max_steps" => d::POLE_MAX_STEPS,
        }),
        ("RigidEarth.averaged_pole", row! {
            "moon_node" => d::POLE_MOON_NODE, "nutation_scale" => d::NUTATION_SCALE,
        }),
        ("polar_motion", row! { "source" => d::POLAR_MOTION_SOURCE }),
        ("fit_wobble", row! { "annual_period" => d::ANNUAL_PERIOD }),
        ("Earth.drop", drop()),
        ("Earth.projectile", projectile),
        ("Earth.foucault", with(row! {
            "samples" => d::FOUCAULT_SAMPLES, "length" => d::FOUCAULT_LENGTH, "amplitude" => d::FOUCAULT_AMPLITUDE,
            "azimuth" => d::FOUCAULT_AZIMUTH, "duration" => d::FOUCAULT_DURATION,
        }, d::FOUCAULT_TOLERANCES)),
        ("Earth.inertial_oscillation", with(row! {
            "samples" => d::INERTIAL_SAMPLES, "velocity" => d::INERTIAL_VELOCITY,
        }, d::INERTIAL_TOLERANCES)),
        ("Earth.flow_into_low", with(row! {
            "samples" => d::LOW_SAMPLES, "radius" => d::LOW_RADIUS, "parcels" => d::LOW_PARCELS,
            "pull" => d::LOW_PULL, "friction" => d::LOW_FRICTION, "duration" => d::LOW_DURATION,
        }, d::LOW_TOLERANCES)),
        ("GravityTorque.__init__", row! { "g" => d::STANDARD_GRAVITY }),
        ("simulate", with(row! {
            "method" => d::SIMULATE_METHOD, "samples" => d::SIMULATE_SAMPLES,
        }, d::SIMULATE_TOLERANCES)),
        ("simulate_batch", batch()),
        ("Gyrocompass.__init__", row! {
            "angular_momentum" => d::COMPASS_ANGULAR_MOMENTUM, "pendulosity" => d::COMPASS_PENDULOSITY,
            "damping" => d::COMPASS_DAMPING, "inertia" => d::COMPASS_INERTIA,
        }),
        ("Gyrocompass.schuler_tuned", row! {
            "pendulosity" => d::COMPASS_PENDULOSITY, "damping" => d::COMPASS_DAMPING,
            "inertia" => d::COMPASS_INERTIA,
        }),
        ("Gyrocompass.simulate", with(row! {
            "method" => d::COMPASS_METHOD, "samples" => d::COMPASS_SAMPLES,
        }, d::COMPASS_TOLERANCES)),
        ("FreeRigidBody.contact_point", row! { "frame" => d::CONTACT_POINT_FRAME }),
        ("FreeRigidBody.contact_polhode", polhode()),
        ("FreeRigidBody.polhode", polhode()),
        ("axis_stability", row! { "spin" => d::AXIS_SPIN }),
        ("HeavyTop.__init__", start),
        ("HeavyTop.from_spin", from_spin()),
        ("HeavyTop.from_body", from_body),
        ("sweep.simulate", batch()),
        ("sweep.drop", sweep_fall()),
        ("sweep.projectile", sweep_fall()),
    ]
}

/// Registers `DEFAULTS` on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    let table = PyDict::new(py);
    for (call, args) in calls() {
        let row = PyDict::new(py);
        for (name, value) in args {
            match value {
                V::F(x) => row.set_item(name, x)?,
                V::N(n) => row.set_item(name, n)?,
                V::S(s) => row.set_item(name, s)?,
                V::T(v) => row.set_item(name, PyTuple::new(py, v)?)?,
            }
        }
        table.set_item(call, row)?;
    }
    m.add("DEFAULTS", table)
}
