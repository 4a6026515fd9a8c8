//! Bindings of `poinsot::frames` (conversion and error mapping only).
//!
//! A frame travels packed, one flat array of 24 floats (`MovingFrame._packed`): origin,
//! velocity, acceleration, angular velocity, angular acceleration (3 each, fixed components),
//! then the attitude (3, 3) row-major; [`frame_arg`] makes the core's frame of it. Particles
//! travel as (N, 3) arrays.
use std::cell::RefCell;

use numpy::{PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2};
use poinsot::frames::ParticleState;
use poinsot::frames::{
    simulate_particle_at, FrameMotion, MovingFrame, SpringParticle, SteadyMotion,
};
use poinsot::integrate::Scan;
use poinsot::{Mat3, Vec3};
use poinsot_py_macros::export;
use pyo3::prelude::*;

use crate::control::{map_each, run, run_attached};
use crate::convert::{a3, mat3_out, rows_view, v3, vec3, vec3_out, Values};
use crate::errors::{invalid, IntoPy};

pub(crate) use crate::convert::{options, rows_out, vec_in};

/// Checks that a packed frame holds its 24 numbers (naming `frame`).
fn check_packed(p: &[f64]) -> PyResult<()> {
    if p.len() != 24 {
        return Err(invalid(
            "frame",
            format!("must hold 24 numbers, got {}", p.len()),
        ));
    }
    Ok(())
}

/// A packed frame → the checked core frame: the 15 state numbers (origin, velocity,
/// acceleration, ω, ω̇) then the attitude (3, 3) row-major, as `MovingFrame._packed` holds them.
fn frame_from(p: &[f64]) -> PyResult<MovingFrame> {
    check_packed(p)?;
    let v = |i: usize| Vec3::new(p[i], p[i + 1], p[i + 2]);
    let att = Mat3::from_fn(|i, j| p[15 + 3 * i + j]);
    MovingFrame::new(v(0), v(3), v(6), v(9), v(12))
        .py()?
        .with_attitude(att)
        .py()
}

/// A frame argument: Python's `MovingFrame._packed` (24,) → the checked core frame.
pub(crate) fn frame_arg(packed: &PyReadonlyArray1<'_, f64>) -> PyResult<MovingFrame> {
    frame_from(&vec_in(packed))
}

/// Applies `transform` to each row of (N, 3) positions, velocities and accelerations and returns
/// its eight (N, 3) outputs (the transformed state and the named acceleration terms); the GIL
/// released and Ctrl-C polled every chunk of rows ([`run`], [`poinsot::control::try_map_n`]).
fn transform_rows<'py>(
    py: Python<'py>,
    position: &PyReadonlyArray2<'py, f64>,
    velocity: &PyReadonlyArray2<'py, f64>,
    acceleration: &PyReadonlyArray2<'py, f64>,
    transform: impl Fn(&Vec3, &Vec3, &Vec3) -> poinsot::Result<[Vec3; 8]> + Sync,
) -> PyResult<Vec<Bound<'py, PyArray2<f64>>>> {
    let (r, v, a) = (
        rows_view::<3>("position", position)?,
        rows_view::<3>("velocity", velocity)?,
        rows_view::<3>("acceleration", acceleration)?,
    );
    let n = same_rows(
        "position, velocity and acceleration",
        &[r.len(), v.len(), a.len()],
    )?;
    per_row(py, n, |i| transform(&v3(&r[i]), &v3(&v[i]), &v3(&a[i])))
}

/// The common number of rows of the arrays `names` (`lens`, the first of them listed first),
/// else an error naming `velocity` (one of them in each caller).
fn same_rows(names: &str, lens: &[usize]) -> PyResult<usize> {
    let n = lens[0];
    if lens.iter().any(|&l| l != n) {
        let message = format!("{names} must have the same number of rows");
        return Err(invalid("velocity", message));
    }
    Ok(n)
}

/// `f` at each row index 0..n (the GIL released, Ctrl-C polled every chunk of rows: [`run`],
/// [`poinsot::control::try_map_n`]), its K outputs as K (N, 3) arrays. The outputs are split
/// into columns with the GIL still released and handed to numpy without a copy.
fn per_row<'py, const K: usize>(
    py: Python<'py>,
    n: usize,
    f: impl Fn(usize) -> poinsot::Result<[Vec3; K]> + Send,
) -> PyResult<Vec<Bound<'py, PyArray2<f64>>>> {
    let columns = run(py, None, || {
        let each = poinsot::control::try_map_n(n, f)?;
        Ok(columns(&each))
    })?;
    columns
        .into_iter()
        .map(|c| PyArray1::from_vec(py, c).reshape([n, 3]))
        .collect()
}

/// The K outputs of each row as K flat row-major (N·3) vectors.
fn columns<const K: usize>(each: &[[Vec3; K]]) -> Vec<Vec<f64>> {
    (0..K)
        .map(|k| each.iter().flat_map(|x| a3(&x[k])).collect())
        .collect()
}

/// Exports `$name`, which transforms (N, 3) positions, velocities and accelerations by the
/// frame's `$method` (`to_fixed`, `to_moving`): its eight (N, 3) outputs, the transformed
/// state then the acceleration's `$term`s.
macro_rules! transform_export {
    ($(#[$doc:meta])* $name:ident = $method:ident: $($term:ident),+) => {
        $(#[$doc])*
        #[export]
        fn $name<'py>(
            py: Python<'py>,
            frame: PyReadonlyArray1<'py, f64>,
            position: PyReadonlyArray2<'py, f64>,
            velocity: PyReadonlyArray2<'py, f64>,
            acceleration: PyReadonlyArray2<'py, f64>,
        ) -> PyResult<Vec<Bound<'py, PyArray2<f64>>>> {
            let f = frame_arg(&frame)?;
            transform_rows(py, &position, &velocity, &acceleration, |r, v, a| {
                let m = f.$method(r, v, a)?;
                Ok([m.position, m.velocity, m.acceleration, $(m.terms.$term),+])
            })
        }
    };
}

transform_export!(
    /// Transforms (N, 3) moving-frame positions, velocities and accelerations to the fixed
    /// frame: (position, velocity, acceleration, relative, origin, coriolis, centripetal, euler).
    frame_to_fixed = to_fixed: relative, origin, coriolis, centripetal, euler
);
transform_export!(
    /// Transforms (N, 3) fixed-frame positions, velocities and accelerations to the moving
    /// frame: (position, velocity, acceleration, inertial, translational, coriolis, centrifugal,
    /// euler).
    frame_to_moving = to_moving: inertial, translational, coriolis, centrifugal, euler
);

/// Fictitious forces on (N,) masses at (N, 3) positions with (N, 3) velocities in the frame:
/// (translational, coriolis, centrifugal, euler).
#[export]
fn frame_fictitious_forces<'py>(
    py: Python<'py>,
    frame: PyReadonlyArray1<'py, f64>,
    mass: PyReadonlyArray1<'py, f64>,
    position: PyReadonlyArray2<'py, f64>,
    velocity: PyReadonlyArray2<'py, f64>,
) -> PyResult<Vec<Bound<'py, PyArray2<f64>>>> {
    let f = frame_arg(&frame)?;
    let m = vec_in(&mass);
    let (r, v) = (
        rows_view::<3>("position", &position)?,
        rows_view::<3>("velocity", &velocity)?,
    );
    let n = same_rows("mass, position and velocity", &[m.len(), r.len(), v.len()])?;
    per_row(py, n, |i| {
        let ff = f.fictitious_forces(m[i], &v3(&r[i]), &v3(&v[i]))?;
        Ok([ff.translational, ff.coriolis, ff.centrifugal, ff.euler])
    })
}

/// A frame motion that asks a Python callable `t -> 24 floats` (a packed frame); the first
/// Python error is kept and the integration is stopped by non-finite values.
struct PyFrame<'a, 'py> {
    py: Python<'py>,
    func: &'a Bound<'py, PyAny>,
    error: &'a RefCell<Option<PyErr>>,
}

impl FrameMotion for PyFrame<'_, '_> {
    fn at(&self, t: f64) -> MovingFrame {
        let _ = self.py;
        let got = self
            .func
            .call1((t,))
            .and_then(|r| r.extract::<Vec<f64>>())
            .and_then(|p| frame_from(&p));
        match got {
            Ok(f) => f,
            Err(e) => {
                self.error.borrow_mut().get_or_insert(e);
                MovingFrame {
                    acceleration: Vec3::repeat(f64::NAN),
                    ..MovingFrame::default()
                }
            }
        }
    }
}

/// Integrates a particle in a moving frame (see `poinsot.simulate_particle`). The frame is 24
/// floats — 15 state numbers and the attitude row-major — (a steady frame from t = 0) or a
/// callable `t -> 24 floats`; the output times are `t_eval` or, if None, `samples`
/// evenly spaced ones from 0 to `duration`; the force is a
/// constant (3,) vector in moving components plus, optionally, a callable
/// `(t, x, y, z, vx, vy, vz) -> (fx, fy, fz)`.
#[export]
#[pyo3(signature = (frame, frame_fn, mass, position, velocity, duration, samples, t_eval, force, force_fn, rtol, atol, max_steps, stiffness = 0.0))]
#[allow(clippy::too_many_arguments)]
fn frame_simulate_particle<'py>(
    py: Python<'py>,
    frame: PyReadonlyArray1<'py, f64>,
    frame_fn: Option<Bound<'py, PyAny>>,
    mass: f64,
    position: PyReadonlyArray1<'py, f64>,
    velocity: PyReadonlyArray1<'py, f64>,
    duration: f64,
    samples: usize,
    t_eval: Option<PyReadonlyArray1<'py, f64>>,
    force: PyReadonlyArray1<'py, f64>,
    force_fn: Option<Bound<'py, PyAny>>,
    rtol: f64,
    atol: f64,
    max_steps: usize,
    stiffness: f64,
) -> PyResult<ScanOut<'py>> {
    // The spring −k r anchored at the origin (0 for stiffness 0), checked by the core.
    let spring = SpringParticle::new(mass, stiffness).py()?;
    let r0 = v3(&vec3("position", &position)?);
    let v0 = v3(&vec3("velocity", &velocity)?);
    // A force not finite at the start is refused by the core, naming `force`.
    let f_const = v3(&vec3("force", &force)?);
    // The frame travels packed: 15 state numbers then the attitude, row-major.
    let packed = vec_in(&frame);
    check_packed(&packed)?;
    let steady = || -> PyResult<SteadyMotion> { SteadyMotion::new(frame_from(&packed)?).py() };
    let times = match &t_eval {
        Some(t) => vec_in(t),
        None => poinsot::integrate::sample_times(
            0.0,
            duration,
            samples,
            poinsot::frames::PARTICLE_BYTES_PER_SAMPLE,
        )
        .py()?,
    };
    let opts = options(rtol, atol, max_steps, false);
    let error: RefCell<Option<PyErr>> = RefCell::new(None);
    if frame_fn.is_none() && force_fn.is_none() {
        let motion = steady()?;
        let force = |_t: f64, r: &Vec3, _v: &Vec3| f_const + spring.force_unchecked(r);
        let work = || simulate_particle_at(&motion, mass, r0, v0, duration, &times, force, &opts);
        // Release the GIL only for long outputs: for a handful of samples the release costs
        // more than it frees. Either way Ctrl-C stops the run.
        let scan = if times.len() > 64 {
            run(py, None, work)?
        } else {
            run_attached(py, None, work)?
        };
        return Ok(scan_out(py, &scan));
    }
    let force = |t: f64, r: &Vec3, v: &Vec3| -> Vec3 {
        let base = f_const + spring.force_unchecked(r);
        let Some(func) = &force_fn else { return base };
        match func
            .call1((t, r.x, r.y, r.z, v.x, v.y, v.z))
            .and_then(|o| o.extract::<(f64, f64, f64)>())
        {
            Ok((a, b, c)) => base + Vec3::new(a, b, c),
            Err(e) => {
                error.borrow_mut().get_or_insert(e);
                Vec3::repeat(f64::NAN)
            }
        }
    };
    let (called, steady_motion);
    let motion: &dyn FrameMotion = match &frame_fn {
        Some(func) => {
            called = PyFrame {
                py,
                func,
                error: &error,
            };
            &called
        }
        None => {
            steady_motion = steady()?;
            &steady_motion
        }
    };
    let result = run_attached(py, None, || {
        simulate_particle_at(motion, mass, r0, v0, duration, &times, force, &opts)
    });
    // A callback's own exception explains a run it stopped.
    if let Some(e) = error.into_inner() {
        return Err(e);
    }
    Ok(scan_out(py, &result?))
}

/// A scan's samples as (states (N, 6): position then velocity, evaluations).
fn scan_out<'py>(py: Python<'py>, scan: &Scan<ParticleState>) -> ScanOut<'py> {
    (rows_out(py, &scan.y), scan.stats.evaluations)
}

type ScanOut<'py> = (Bound<'py, PyArray2<f64>>, usize);

/// The state of a steady frame at time `t`: (origin, velocity, acceleration, angular velocity,
/// angular acceleration, attitude).
#[export]
#[allow(clippy::type_complexity)]
fn frame_steady_at<'py>(
    py: Python<'py>,
    frame: PyReadonlyArray1<'py, f64>,
    t: f64,
) -> PyResult<(Vec<Bound<'py, PyArray1<f64>>>, Bound<'py, PyArray2<f64>>)> {
    let motion = SteadyMotion::new(frame_arg(&frame)?).py()?;
    let f = motion.state_at(t).py()?;
    let vecs = [
        f.origin,
        f.velocity,
        f.acceleration,
        f.angular_velocity,
        f.angular_acceleration,
    ]
    .iter()
    .map(|v| vec3_out(py, a3(v)))
    .collect();
    let att: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| f.attitude[(i, j)]));
    Ok((vecs, mat3_out(py, att)))
}

/// A particle of `mass` (kg) on an isotropic spring of `stiffness` (N/m) anchored at the common
/// origin of the fixed and the rotating frame (`poinsot::frames::SpringParticle`).
#[pyclass(name = "SpringParticleCore", module = "poinsot._core", frozen)]
struct SpringParticleCore {
    inner: SpringParticle,
}

core_export! {
    impl SpringParticleCore;
    getters {
        /// m (kg).
        mass -> f64;
        /// k (N/m).
        stiffness -> f64;
    }

    #[new]
    fn new(mass: f64, stiffness: f64) -> PyResult<Self> {
        Ok(Self {
            inner: SpringParticle::new(mass, stiffness).py()?,
        })
    }
    /// (N, 3) forces −k r (N) at (N, 3) positions (m).
    fn force<'py>(
        &self,
        py: Python<'py>,
        position: PyReadonlyArray2<'py, f64>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let out = at_positions(py, &position, |x| self.inner.force(x).map(|f| a3(&f)))?;
        Ok(rows_out(py, &out))
    }
    /// (N, 3) accelerations −(k/m) r (m/s²) at (N, 3) positions (m).
    fn acceleration<'py>(
        &self,
        py: Python<'py>,
        position: PyReadonlyArray2<'py, f64>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let out = at_positions(py, &position, |x| {
            self.inner.acceleration(x).map(|a| a3(&a))
        })?;
        Ok(rows_out(py, &out))
    }
    /// (N,) potentials ½ k |r|² (J) at (N, 3) positions (m).
    fn potential(&self, py: Python<'_>, position: PyReadonlyArray2<'_, f64>) -> PyResult<Values> {
        at_positions(py, &position, |x| self.inner.potential(x)).map(Values)
    }
    /// (N,) fixed-frame energies (J) of (N, 3) positions (m) and velocities (m/s).
    fn energy(
        &self,
        py: Python<'_>,
        position: PyReadonlyArray2<'_, f64>,
        velocity: PyReadonlyArray2<'_, f64>,
    ) -> PyResult<Values> {
        at_states(py, &position, &velocity, |r, v| self.inner.energy(r, v))
    }
    /// (N,) Jacobi integrals (J) in the packed frame (24 floats) of (N, 3) relative positions
    /// (m) and velocities (m/s) in moving components.
    fn jacobi_integral(
        &self,
        py: Python<'_>,
        frame: PyReadonlyArray1<'_, f64>,
        position: PyReadonlyArray2<'_, f64>,
        velocity: PyReadonlyArray2<'_, f64>,
    ) -> PyResult<Values> {
        let f = frame_arg(&frame)?;
        at_states(py, &position, &velocity, |r, v| {
            self.inner.jacobi_integral(&f, r, v)
        })
    }
}

/// `f` at each of the (N, 3) positions (m), borrowed from a C-contiguous array (its values are
/// the core's to check); the GIL released, Ctrl-C polled.
fn at_positions<R: Send>(
    py: Python<'_>,
    position: &PyReadonlyArray2<'_, f64>,
    f: impl Fn(&Vec3) -> poinsot::Result<R> + Send + Sync,
) -> PyResult<Vec<R>> {
    let r = rows_view::<3>("position", position)?;
    map_each(py, &r, |x| f(&v3(x)))
}

/// `f` at each of the (N, 3) positions and velocities, as [`at_positions`]; the error names
/// `velocity` when the numbers of rows differ.
fn at_states(
    py: Python<'_>,
    position: &PyReadonlyArray2<'_, f64>,
    velocity: &PyReadonlyArray2<'_, f64>,
    f: impl Fn(&Vec3, &Vec3) -> poinsot::Result<f64> + Send + Sync,
) -> PyResult<Values> {
    let (r, v) = (
        rows_view::<3>("position", position)?,
        rows_view::<3>("velocity", velocity)?,
    );
    if r.len() != v.len() {
        return Err(invalid(
            "velocity",
            format!(
                "must have as many rows as position ({}), got {}",
                r.len(),
                v.len()
            ),
        ));
    }
    let each = run(py, None, || {
        poinsot::control::try_map_n(r.len(), |i| f(&v3(&r[i]), &v3(&v[i])))
    })?;
    Ok(Values(each))
}

/// Registers this file's functions and classes on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<SpringParticleCore>()?;
    add_functions!(m; frame_to_fixed, frame_to_moving, frame_fictitious_forces,
        frame_simulate_particle, frame_steady_at);
    Ok(())
}
