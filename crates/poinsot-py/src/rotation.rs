//! Bindings of `poinsot::rotation` (conversion and error mapping only).
//!
//! Every function takes C-contiguous float64 batches `(N, ...)` prepared by
//! `python/poinsot/rotation.py` (which broadcasts leading dimensions, handles degrees and scipy
//! rotations) and returns new arrays; the GIL is released while the core computes, and Ctrl-C
//! stops it ([`run`]).
use numpy::{PyArray1, PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn};
use poinsot::rotation::{self as rot, EulerSequence, Frame};
use poinsot::Vec3;
use poinsot_py_macros::export;
use pyo3::prelude::*;

use crate::control::run;
use crate::convert::{matrix, parse, records, rows_view, vector, zeros, Matrix, Vector};
use crate::errors::{invalid, IntoPy};

type Out<'py> = Bound<'py, PyArrayDyn<f64>>;

/// Runs `kernel(input, out)` with the GIL released, into a new array of shape `dims`.
fn batch<'py>(
    py: Python<'py>,
    dims: &[usize],
    kernel: impl FnOnce(&mut [f64]) -> poinsot::Result<()> + Send,
) -> PyResult<Out<'py>> {
    let out = zeros(py, dims);
    {
        let mut rw = out.readwrite();
        let slice = rw
            .as_slice_mut()
            .map_err(|_| invalid("out", "not contiguous"))?;
        run(py, None, || kernel(slice))?;
    }
    Ok(out)
}

/// Exports `$name`, the batch kernel `$kernel` of the arrays `$arg` (`N` records of shape
/// `$shape` each, the first argument's `N`) into a new array of shape `(N, $out…)`.
macro_rules! batch_export {
    ($(#[$doc:meta])* $name:ident($($arg:ident: $shape:expr),+) -> $out:expr, $kernel:path) => {
        $(#[$doc])*
        #[export]
        #[allow(non_snake_case)]
        fn $name<'py>(py: Python<'py>, $($arg: PyReadonlyArrayDyn<'py, f64>),+) -> PyResult<Out<'py>> {
            $(let $arg = records(stringify!($arg), &$arg, &$shape)?;)+
            let n = [$($arg.1),+][0];
            let dims: Vec<usize> = std::iter::once(n).chain($out).collect();
            batch(py, &dims, |out| $kernel($($arg.0),+, out))
        }
    };
}

batch_export!(
    /// Rotation matrices `(N, 3, 3)` → quaternions `(N, 4)`, `[w, x, y, z]`, `w >= 0`.
    matrix_to_quaternion(R: [3, 3]) -> [4], rot::matrix_to_quaternion_batch
);
batch_export!(
    /// Hamilton products of quaternions `(N, 4)` and `(N, 4)` → `(N, 4)`.
    quaternion_multiply(p: [4], q: [4]) -> [4], rot::quaternion_multiply_batch
);
batch_export!(
    /// Rotation matrices `(N, 3, 3)` → `(N, 4)` records `[n_x, n_y, n_z, angle]`.
    rotation_axis(R: [3, 3]) -> [4], rot::rotation_axis_batch
);
batch_export!(
    /// Axes `(N, 3)` and angles `(N,)` (rad) → rotation matrices `(N, 3, 3)`.
    axis_angle_to_matrix(axis: [3], angle: []) -> [3, 3], rot::axis_angle_to_matrix_batch
);
batch_export!(
    /// `R_k v_k` for matrices `(N, 3, 3)` and vectors `(N, 3)` → `(N, 3)`.
    rotate_vectors(R: [3, 3], v: [3]) -> [3], rot::rotate_vectors_batch
);

/// Euler angles `(N, 3)` (rad) → rotation matrices `(N, 3, 3)`.
#[export]
fn euler_to_matrix<'py>(
    py: Python<'py>,
    angles: PyReadonlyArrayDyn<'py, f64>,
    seq: &str,
    intrinsic: bool,
) -> PyResult<Out<'py>> {
    let seq = EulerSequence::new(seq, intrinsic).py()?;
    let (a, n) = records("angles", &angles, &[3])?;
    batch(py, &[n, 3, 3], |out| {
        rot::euler_to_matrix_batch(seq, a, out)
    })
}

/// Rotation matrices `(N, 3, 3)` → Euler angles `(N, 3)` (rad) and gimbal-lock flags `(N,)`.
#[export]
#[allow(non_snake_case)]
fn matrix_to_euler<'py>(
    py: Python<'py>,
    R: PyReadonlyArrayDyn<'py, f64>,
    seq: &str,
    intrinsic: bool,
) -> PyResult<(Out<'py>, Bound<'py, PyArray1<bool>>)> {
    let seq = EulerSequence::new(seq, intrinsic).py()?;
    let (m, n) = records("R", &R, &[3, 3])?;
    let mut locked = vec![false; n];
    let out = batch(py, &[n, 3], |out| {
        rot::matrix_to_euler_batch(seq, m, out, &mut locked).map(|_| ())
    })?;
    Ok((out, PyArray1::from_vec(py, locked)))
}

/// Quaternions `(N, 4)` `[w, x, y, z]` → rotation matrices `(N, 3, 3)`.
#[export]
fn quaternion_to_matrix<'py>(
    py: Python<'py>,
    q: PyReadonlyArrayDyn<'py, f64>,
    normalize: bool,
) -> PyResult<Out<'py>> {
    let (d, n) = records("q", &q, &[4])?;
    batch(py, &[n, 3, 3], |out| {
        rot::quaternion_to_matrix_batch(d, normalize, out)
    })
}

/// Checks matrices `(N, 3, 3)` are rotations within `tol`; raises `InvalidRotationError`.
#[export]
#[allow(non_snake_case)]
fn check_rotation_matrix(py: Python<'_>, R: PyReadonlyArrayDyn<'_, f64>, tol: f64) -> PyResult<()> {
    let (m, _) = records("R", &R, &[3, 3])?;
    run(py, None, || rot::check_rotation_matrix_batch(m, tol))
}

/// Exports `$name`, the Euler kinematics' batch kernel `$kernel` of angles `(N, 3)` and
/// `$arg` `(N, 3)` (named `$public` in errors) in `frame` → `(N, 3)`.
macro_rules! kinematics_export {
    ($(#[$doc:meta])* $name:ident($arg:ident as $public:literal) = $kernel:path) => {
        $(#[$doc])*
        #[export]
        fn $name<'py>(
            py: Python<'py>,
            angles: PyReadonlyArrayDyn<'py, f64>,
            $arg: PyReadonlyArrayDyn<'py, f64>,
            seq: &str,
            intrinsic: bool,
            frame: &str,
        ) -> PyResult<Out<'py>> {
            let seq = EulerSequence::new(seq, intrinsic).py()?;
            let frame: Frame = parse(frame)?;
            let (a, n) = records("angles", &angles, &[3])?;
            let (b, _) = records($public, &$arg, &[3])?;
            batch(py, &[n, 3], |out| $kernel(seq, frame, a, b, out))
        }
    };
}

kinematics_export!(
    /// Angular velocities `(N, 3)` (rad/s, in `frame`) from angles and rates `(N, 3)`.
    angular_velocity(rates as "rates") = rot::angular_velocity_batch
);
kinematics_export!(
    /// Euler-angle rates `(N, 3)` (rad/s) from angles `(N, 3)` and ω `(N, 3)` (in `frame`).
    euler_rates(omega as "omega_body") = rot::euler_rates_batch
);

/// Chasles' screw of `x ↦ R x + t` for one `R` `(3, 3)` and `t` `(3,)`:
/// `(axis, point, angle, slide, pitch)`.
#[export]
#[allow(non_snake_case)]
fn screw_axis(
    R: numpy::PyReadonlyArray2<'_, f64>,
    t: numpy::PyReadonlyArray1<'_, f64>,
) -> PyResult<(Vector, Vector, f64, f64, f64)> {
    let (r, t) = (matrix("R", &R)?, vector("t", &t)?);
    Ok(screw_out(rot::screw_axis(&r, &t).py()?))
}

/// A screw as Python takes it: `(axis, point, angle, slide, pitch)`.
fn screw_out(s: rot::Screw) -> (Vector, Vector, f64, f64, f64) {
    (Vector(s.axis), Vector(s.point), s.angle, s.slide, s.pitch)
}

/// A screw as Python passes it: `(axis (3,), point (3,) m, angle rad, slide m)`.
type ScrewParts<'py> = (
    numpy::PyReadonlyArray1<'py, f64>,
    numpy::PyReadonlyArray1<'py, f64>,
    f64,
    f64,
);

/// The screw of `parts` and `pitch` as a core `Screw` (checked by `Screw::new`).
fn screw_from_parts(parts: &ScrewParts<'_>, pitch: Option<f64>) -> PyResult<rot::Screw> {
    let (axis, point, angle, slide) = parts;
    let (axis, point) = (vector("axis", axis)?, vector("point", point)?);
    rot::Screw::new(axis, point, *angle, *slide, pitch).py()
}

/// A screw from its parts, checked by the core: `(axis, point, angle, slide, pitch)` with the
/// axis normalised and the pitch derived (a `pitch` given must agree).
#[export]
#[pyo3(signature = (screw, pitch=None))]
fn screw_new(
    screw: ScrewParts<'_>,
    pitch: Option<f64>,
) -> PyResult<(Vector, Vector, f64, f64, f64)> {
    Ok(screw_out(screw_from_parts(&screw, pitch)?))
}

/// The displacement `(R (3, 3), t (3,))` of a screw, or with `s` the displacement `(R(s),
/// t(s))` at fraction `s` of its motion.
#[export]
#[pyo3(signature = (screw, s=None))]
fn screw_displacement(screw: ScrewParts<'_>, s: Option<f64>) -> PyResult<(Matrix, Vector)> {
    let screw = screw_from_parts(&screw, None)?;
    let (r, t) = match s {
        Some(s) => screw.displacement_at(s).py()?,
        None => screw.displacement(),
    };
    Ok((Matrix(r), Vector(t)))
}

/// Applies a screw motion to points `x` `(N, 3)` → `(N, 3)`.
#[export]
fn screw_apply<'py>(
    py: Python<'py>,
    screw: ScrewParts<'py>,
    x: numpy::PyReadonlyArray2<'py, f64>,
) -> PyResult<Out<'py>> {
    let screw = screw_from_parts(&screw, None)?;
    let points = rows_view::<3>("x", &x)?;
    // In chunks of points, Ctrl-C polled between two (on this thread: `run`'s monitor).
    batch(py, &[points.len(), 3], |out| {
        poinsot::control::fill_chunks(out, 3 * poinsot::control::CHUNK, false, |start, ys| {
            for (p, y) in points[start / 3..].iter().zip(ys.chunks_exact_mut(3)) {
                y.copy_from_slice(screw.apply(&Vec3::from(*p))?.as_slice());
            }
            Ok(())
        })
    })
}

/// Registers this file's functions and classes on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    add_functions!(m; euler_to_matrix, matrix_to_euler, matrix_to_quaternion,
        quaternion_to_matrix, quaternion_multiply, rotation_axis, axis_angle_to_matrix,
        rotate_vectors, check_rotation_matrix, angular_velocity, euler_rates, screw_axis,
        screw_new, screw_displacement, screw_apply);
    m.add("EULER_LOCK_TOL", rot::EULER_LOCK_TOL)?;
    m.add("RATES_LOCK_TOL", rot::RATES_LOCK_TOL)?;
    m.add("ROTATION_MATRIX_TOL", rot::ROTATION_MATRIX_TOL)?;
    m.add("NEAREST_ROTATION_DEFECT", rot::NEAREST_ROTATION_DEFECT)?;
    Ok(())
}
