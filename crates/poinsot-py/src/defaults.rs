//! `DEFAULTS`: the default of every argument of the public Python calls that has one (other than
//! `None` and the flags), by the call's public name (`"simulate"`, `"RigidBody.from_density"`,
//! `"sweep.drop"`) and the argument's name. Every value is the core's (`poinsot::defaults`);
//! `python/poinsot` reads its signatures' defaults from here and
//! `python/tests/test_defaults_once.py` holds every public signature to this table.

use poinsot::defaults as d;
use poinsot::integrate::Tolerances;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

/// One default value.
enum V {
    F(f64),
    N(usize),
    S(&'static str),
    /// A vector: a tuple of floats in Python.
    T(Vec<f64>),
}

/// The integrator arguments of a run with these tolerances.
fn tolerances(t: Tolerances) -> [(&'static str, V); 3] {
    [
        ("rtol", V::F(t.rtol)),
        ("atol", V::F(t.atol)),
        ("max_steps", V::N(t.max_steps)),
    ]
}

/// Every public call's defaults.
fn calls() -> Vec<(&'static str, Vec<(&'static str, V)>)> {
    use V::{F, N, S, T};
    let seq = || vec![("seq", S(d::EULER_SEQUENCE))];
    let frame = poinsot::frames::MovingFrame::default();
    let start = d::EulerState::default();
    let rest = || T(d::AT_REST.to_vec());
    let mesh = || vec![("density", F(d::MESH_DENSITY))];
    let polhode = || vec![("samples", N(d::POLHODE_SAMPLES))];
    let run = |samples: usize, t: Tolerances| {
        let mut v = vec![("samples", N(samples))];
        v.extend(tolerances(t));
        v
    };
    let fall = |samples: Option<usize>| {
        let mut v = vec![("gravity", S(d::GRAVITY))];
        v.extend(samples.map(|n| ("samples", N(n))));
        v.extend(tolerances(d::DROP_TOLERANCES));
        v
    };
    let com = || vec![("center_of_mass", T(d::CENTER_OF_MASS.to_vec()))];
    let batch = || {
        vec![
            ("method", S(d::BATCH_METHOD)),
            ("max_steps", N(d::DEFAULT_MAX_STEPS)),
        ]
    };
    let vec3 = |v: poinsot::Vec3| T(v.iter().copied().collect());
    let mut projectile = fall(Some(d::DROP_SAMPLES));
    projectile.push(("height", F(d::LAUNCH_HEIGHT)));
    let mut simulate = vec![("method", S(d::SIMULATE_METHOD))];
    simulate.extend(run(d::SIMULATE_SAMPLES, d::SIMULATE_TOLERANCES));
    let particle = run(d::PARTICLE_SAMPLES, d::PARTICLE_TOLERANCES);
    let mut simulate_particle = run(d::PARTICLE_SAMPLES, d::PARTICLE_TOLERANCES);
    simulate_particle.extend([
        ("mass", F(d::PARTICLE_MASS)),
        ("stiffness", F(d::PARTICLE_STIFFNESS)),
    ]);
    let mut foucault = run(d::FOUCAULT_SAMPLES, d::FOUCAULT_TOLERANCES);
    foucault.extend([
        ("length", F(d::FOUCAULT_LENGTH)),
        ("amplitude", F(d::FOUCAULT_AMPLITUDE)),
        ("azimuth", F(d::FOUCAULT_AZIMUTH)),
        ("duration", F(d::FOUCAULT_DURATION)),
    ]);
    let mut inertial = run(d::INERTIAL_SAMPLES, d::INERTIAL_TOLERANCES);
    inertial.push(("velocity", T(d::INERTIAL_VELOCITY.to_vec())));
    let mut low = run(d::LOW_SAMPLES, d::LOW_TOLERANCES);
    low.extend([
        ("radius", F(d::LOW_RADIUS)),
        ("parcels", N(d::LOW_PARCELS)),
        ("pull", F(d::LOW_PULL)),
        ("friction", F(d::LOW_FRICTION)),
        ("duration", F(d::LOW_DURATION)),
    ]);
    let top = |psi_dot: bool| {
        let mut v = vec![
            ("theta_dot", F(start.theta_dot)),
            ("phi_dot", F(start.phi_dot)),
            ("phi", F(start.phi)),
            ("psi", F(start.psi)),
        ];
        if psi_dot {
            v.push(("psi_dot", F(start.psi_dot)));
        }
        v
    };
    vec![
        // rotation
        (
            "check_rotation_matrix",
            vec![("tol", F(d::CHECK_ROTATION_TOL))],
        ),
        ("euler_to_matrix", seq()),
        ("matrix_to_euler", seq()),
        ("body_angular_velocity", seq()),
        ("space_angular_velocity", seq()),
        (
            "euler_rates",
            vec![
                ("seq", S(d::EULER_SEQUENCE)),
                ("frame", S(d::EULER_RATES_FRAME)),
            ],
        ),
        // body
        ("classify", vec![("rtol", F(d::DEFAULT_KIND_RTOL))]),
        ("RigidBody.__init__", com()),
        ("RigidBody.from_inertia", com()),
        (
            "RigidBody.from_density",
            vec![
                ("rtol", F(d::CUBATURE.rtol)),
                ("atol", F(d::CUBATURE.atol)),
                ("max_evals", N(d::CUBATURE.max_evals)),
            ],
        ),
        ("RigidBody.from_mesh", mesh()),
        ("RigidBody.from_trimesh", mesh()),
        ("RigidBody.load_mesh", mesh()),
        // frames
        (
            "MovingFrame.__init__",
            vec![
                ("origin", vec3(frame.origin)),
                ("velocity", vec3(frame.velocity)),
                ("acceleration", vec3(frame.acceleration)),
                ("angular_velocity", vec3(frame.angular_velocity)),
                ("angular_acceleration", vec3(frame.angular_acceleration)),
            ],
        ),
        (
            "MovingFrame.to_fixed",
            vec![("velocity", rest()), ("acceleration", rest())],
        ),
        (
            "MovingFrame.to_moving",
            vec![("velocity", rest()), ("acceleration", rest())],
        ),
        ("SpringParticle.simulate", particle),
        ("simulate_particle", simulate_particle),
        // earth
        (
            "Earth.__init__",
            vec![
                ("rotation_rate", F(d::SIDEREAL_RATE)),
                ("radius", F(d::MEAN_RADIUS)),
                ("g", F(d::STANDARD_GRAVITY)),
            ],
        ),
        (
            "Earth.solar_day",
            vec![("radius", F(d::MEAN_RADIUS)), ("g", F(d::STANDARD_GRAVITY))],
        ),
        ("Earth.drop", fall(Some(d::DROP_SAMPLES))),
        ("Earth.projectile", projectile),
        ("Earth.foucault", foucault),
        ("Earth.inertial_oscillation", inertial),
        ("Earth.flow_into_low", low),
        // dynamics
        (
            "GravityTorque.__init__",
            vec![("g", F(d::STANDARD_GRAVITY))],
        ),
        ("simulate", simulate),
        ("simulate_batch", batch()),
        // free bodies
        (
            "FreeRigidBody.contact_point",
            vec![("frame", S(d::CONTACT_POINT_FRAME))],
        ),
        ("FreeRigidBody.contact_polhode", polhode()),
        ("FreeRigidBody.polhode", polhode()),
        ("axis_stability", vec![("spin", F(d::AXIS_SPIN))]),
        // the heavy top
        ("HeavyTop.__init__", top(true)),
        ("HeavyTop.from_spin", top(false)),
        // sweeps
        ("sweep.simulate", batch()),
        ("sweep.drop", fall(None)),
        ("sweep.projectile", fall(None)),
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
