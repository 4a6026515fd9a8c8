//! Batch kernels: the conversions of this module over slices of many rotations, in parallel
//! (rayon) above [`PARALLEL_MIN`] items, writing into caller-provided buffers (no allocation).
//!
//! Layout: flat `f64` slices, one record after another — angles and vectors as 3 values,
//! quaternions as 4 (`[w, x, y, z]`), rotation matrices as 9 in **row-major** order
//! (`[R00, R01, R02, R10, ...]`, the layout of a C-contiguous numpy array of shape `(N, 3, 3)`).
//!
//! Errors are those of the single-item functions, with `(at flat index k)` appended to the
//! message; `k` is the first failing record (deterministic even when run in parallel).

use crate::control;
use crate::error::{check_finite, Error, ErrorKind, Result};
use crate::rotation::axis_angle::rotation_axis_unchecked;
use crate::rotation::euler::{euler_to_matrix_unchecked, matrix_to_euler_unchecked, EulerSequence};
use crate::rotation::euler_kinematics::{
    angular_velocity_checked_input, euler_rates_checked_input, Frame,
};
use crate::rotation::matrix::{
    rotation_defects, rotation_to_convert, rotation_verdict, row_major, ROTATION_MATRIX_TOL,
};
use crate::rotation::quaternion::{
    check_quaternion, hamilton, matrix_to_quaternion_unchecked, quaternion_to_matrix_unchecked,
};
use crate::Vec3;

/// Batches of at least this many records run in parallel; smaller ones on the calling thread.
const PARALLEL_MIN: usize = 4096;
/// Smallest number of records one rayon task handles.
const TASK_MIN: usize = 2048;

/// Appends the record index to an error.
fn at_index(e: Error, k: usize) -> Error {
    Error {
        message: format!("{} (at flat index {k})", e.message),
        ..e
    }
}

/// Number of records of width `w` in `data` named `argument`.
fn records(argument: &str, data: &[f64], w: usize) -> Result<usize> {
    if !data.len().is_multiple_of(w) {
        return Err(Error::invalid(
            argument,
            format!(
                "length must be a multiple of {w} (records of {w} values), got {}",
                data.len()
            ),
        ));
    }
    Ok(data.len() / w)
}

/// Checks that `out` holds `n` records of width `w`.
fn check_out(out_len: usize, n: usize, w: usize) -> Result<()> {
    if out_len != n * w {
        return Err(Error::invalid(
            "out",
            format!(
                "must hold {n} records of {w} values ({}), got length {out_len}",
                n * w
            ),
        ));
    }
    Ok(())
}

/// Runs `f(k, out_k)` for every record `k`, in parallel for large batches; returns the error of
/// the first failing record.
fn drive<const O: usize, F>(n: usize, out: &mut [f64], f: F) -> Result<()>
where
    F: Fn(usize, &mut [f64; O]) -> Result<()> + Sync,
{
    let run = |(k, y): (usize, &mut [f64])| {
        let y: &mut [f64; O] = y.try_into().expect("chunks_exact_mut gives O values");
        f(k, y).map_err(|e| at_index(e, k))
    };
    if n < PARALLEL_MIN {
        return out.chunks_exact_mut(O).enumerate().try_for_each(run);
    }
    // In tasks of TASK_MIN records, each stoppable by Ctrl-C before it starts.
    let result = control::fill_chunks(out, O * TASK_MIN, true, |start, ys| {
        ys.chunks_exact_mut(O)
            .enumerate()
            .try_for_each(|(k, y)| run((start / O + k, y)))
    });
    first_error(result, || {
        out.chunks_exact_mut(O).enumerate().try_for_each(run)
    })
}

/// The error of a parallel loop, made deterministic: which record failed first is not known
/// in parallel, so `serial` finds it in order (an interruption is returned as it is).
fn first_error(result: Result<()>, serial: impl FnOnce() -> Result<()>) -> Result<()> {
    match result {
        Err(e) if e.kind != ErrorKind::Interrupted => serial().and(Err(e)),
        other => other,
    }
}

#[inline]
fn rec<const W: usize>(data: &[f64], k: usize) -> &[f64; W] {
    data[W * k..W * (k + 1)]
        .try_into()
        .expect("record of W values")
}

/// Finite check then rotation check of one row-major matrix named `argument`.
#[inline]
fn check_matrix(argument: &str, m: &[f64; 9], tol: f64) -> Result<()> {
    if !m.iter().all(|v| v.is_finite()) {
        check_finite(argument, m)?;
    }
    let (defect, det) = rotation_defects(m);
    rotation_verdict(argument, defect, det, tol)
}

#[inline]
fn check_rec(argument: &str, v: &[f64]) -> Result<()> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        check_finite(argument, v)
    }
}

/// Euler angles (`angles`: N×3, rad, order of `seq`'s name) → rotation matrices (`out`: N×9,
/// row-major), as [`crate::rotation::euler_to_matrix`]. Errors name `"angles"`.
pub fn euler_to_matrix_batch(seq: EulerSequence, angles: &[f64], out: &mut [f64]) -> Result<()> {
    let n = records("angles", angles, 3)?;
    check_out(out.len(), n, 9)?;
    drive::<9, _>(n, out, |k, y| {
        let a = rec::<3>(angles, k);
        check_rec("angles", a)?;
        *y = row_major(&euler_to_matrix_unchecked(*a, seq));
        Ok(())
    })
}

/// Rotation matrices (`matrices`: N×9, row-major) → Euler angles (`out`: N×3, rad) in the
/// canonical ranges, as [`crate::rotation::matrix_to_euler`]; `locked[k]` is set to the
/// gimbal-lock flag of record `k`. Returns the number of records at gimbal lock. Each matrix is
/// checked with [`ROTATION_MATRIX_TOL`] and, off orthonormal by more than
/// [`crate::rotation::NEAREST_ROTATION_DEFECT`], replaced by the nearest rotation; errors name
/// `"R"`.
pub fn matrix_to_euler_batch(
    seq: EulerSequence,
    matrices: &[f64],
    out: &mut [f64],
    locked: &mut [bool],
) -> Result<usize> {
    let n = records("R", matrices, 9)?;
    check_out(out.len(), n, 3)?;
    if locked.len() != n {
        return Err(Error::invalid(
            "locked",
            format!("must hold {n} flags, got {}", locked.len()),
        ));
    }
    let run = |(k, (y, flag)): (usize, (&mut [f64], &mut bool))| -> Result<()> {
        let m = rotation_to_convert("R", rec::<9>(matrices, k)).map_err(|e| at_index(e, k))?;
        let e = matrix_to_euler_unchecked(&m, seq);
        y.copy_from_slice(&e.angles);
        *flag = e.gimbal_lock;
        Ok(())
    };
    if n < PARALLEL_MIN {
        out.chunks_exact_mut(3)
            .zip(locked.iter_mut())
            .enumerate()
            .try_for_each(run)?;
    } else {
        // Tasks of TASK_MIN records (their angles and flags), each stoppable by Ctrl-C.
        let mut tasks: Vec<(&mut [f64], &mut [bool])> = out
            .chunks_mut(3 * TASK_MIN)
            .zip(locked.chunks_mut(TASK_MIN))
            .collect();
        let result = control::fill_chunks(&mut tasks, 1, true, |task, parts| {
            let (ys, flags) = &mut parts[0];
            ys.chunks_exact_mut(3)
                .zip(flags.iter_mut())
                .enumerate()
                .try_for_each(|(k, yf)| run((task * TASK_MIN + k, yf)))
        });
        drop(tasks);
        first_error(result, || {
            out.chunks_exact_mut(3)
                .zip(locked.iter_mut())
                .enumerate()
                .try_for_each(run)
        })?;
    }
    Ok(locked.iter().filter(|l| **l).count())
}

/// Rotation matrices (N×9, row-major) → unit quaternions (`out`: N×4, `[w, x, y, z]`, `w >= 0`),
/// as [`crate::rotation::matrix_to_quaternion`] (of the nearest rotation for a matrix off
/// orthonormal by more than [`crate::rotation::NEAREST_ROTATION_DEFECT`]). Errors name `"R"`.
pub fn matrix_to_quaternion_batch(matrices: &[f64], out: &mut [f64]) -> Result<()> {
    let n = records("R", matrices, 9)?;
    check_out(out.len(), n, 4)?;
    drive::<4, _>(n, out, |k, y| {
        *y = matrix_to_quaternion_unchecked(&rotation_to_convert("R", rec::<9>(matrices, k))?);
        Ok(())
    })
}

/// Quaternions (`quaternions`: N×4, `[w, x, y, z]`) → rotation matrices (`out`: N×9,
/// row-major), as [`crate::rotation::quaternion_to_matrix`]. Errors name `"q"`.
pub fn quaternion_to_matrix_batch(
    quaternions: &[f64],
    normalize: bool,
    out: &mut [f64],
) -> Result<()> {
    let n = records("q", quaternions, 4)?;
    check_out(out.len(), n, 9)?;
    drive::<9, _>(n, out, |k, y| {
        let q = check_quaternion("q", rec::<4>(quaternions, k), normalize)?;
        *y = quaternion_to_matrix_unchecked(&q);
        Ok(())
    })
}

/// Hamilton products `p_k ⊗ q_k` (N×4 each, `[w, x, y, z]`) into `out` (N×4), as
/// [`crate::rotation::quaternion_multiply`]. Errors name `"p"` or `"q"`.
pub fn quaternion_multiply_batch(p: &[f64], q: &[f64], out: &mut [f64]) -> Result<()> {
    let n = records("p", p, 4)?;
    if records("q", q, 4)? != n {
        return Err(Error::invalid(
            "q",
            format!("must hold as many quaternions as p ({n})"),
        ));
    }
    check_out(out.len(), n, 4)?;
    drive::<4, _>(n, out, |k, y| {
        let (a, b) = (rec::<4>(p, k), rec::<4>(q, k));
        check_rec("p", a)?;
        check_rec("q", b)?;
        *y = hamilton(a, b);
        Ok(())
    })
}

/// Euler's theorem over a batch: rotation matrices (N×9, row-major) → `out` (N×4) records
/// `[n_x, n_y, n_z, θ]` (unit axis, angle in `[0, π]`), as [`crate::rotation::rotation_axis`].
/// Errors name `"R"`.
pub fn rotation_axis_batch(matrices: &[f64], out: &mut [f64]) -> Result<()> {
    let n = records("R", matrices, 9)?;
    check_out(out.len(), n, 4)?;
    drive::<4, _>(n, out, |k, y| {
        let (a, theta) = rotation_axis_unchecked(&rotation_to_convert("R", rec::<9>(matrices, k))?);
        *y = [a[0], a[1], a[2], theta];
        Ok(())
    })
}

/// Rodrigues over a batch: axes (N×3, any non-zero length) and angles (N, rad) → matrices
/// (`out`: N×9, row-major), as [`crate::rotation::axis_angle_to_matrix`]. Errors name `"axis"`
/// or `"angle"`.
pub fn axis_angle_to_matrix_batch(axes: &[f64], angles: &[f64], out: &mut [f64]) -> Result<()> {
    let n = records("axis", axes, 3)?;
    if angles.len() != n {
        return Err(Error::invalid(
            "angle",
            format!("must hold {n} angles, got {}", angles.len()),
        ));
    }
    check_out(out.len(), n, 9)?;
    drive::<9, _>(n, out, |k, y| {
        let a = rec::<3>(axes, k);
        let r = crate::rotation::axis_angle_to_matrix(&Vec3::from(*a), angles[k])?;
        *y = row_major(&r);
        Ok(())
    })
}

/// `R_k v_k` for matrices (N×9, row-major) and vectors (N×3) into `out` (N×3). Each matrix is
/// checked with [`ROTATION_MATRIX_TOL`]; errors name `"R"` or `"v"`.
pub fn rotate_vectors_batch(matrices: &[f64], vectors: &[f64], out: &mut [f64]) -> Result<()> {
    let n = records("R", matrices, 9)?;
    if records("v", vectors, 3)? != n {
        return Err(Error::invalid(
            "v",
            format!("must hold as many vectors as R has matrices ({n})"),
        ));
    }
    check_out(out.len(), n, 3)?;
    drive::<3, _>(n, out, |k, y| {
        let (m, v) = (rec::<9>(matrices, k), rec::<3>(vectors, k));
        check_matrix("R", m, ROTATION_MATRIX_TOL)?;
        check_rec("v", v)?;
        for (i, yi) in y.iter_mut().enumerate() {
            *yi = m[3 * i] * v[0] + m[3 * i + 1] * v[1] + m[3 * i + 2] * v[2];
        }
        Ok(())
    })
}

/// Checks every matrix (N×9, row-major) with tolerance `tol`, as
/// [`crate::rotation::check_rotation_matrix`]; the error names `"R"` and the first bad index.
pub fn check_rotation_matrix_batch(matrices: &[f64], tol: f64) -> Result<()> {
    if !(tol.is_finite() && tol >= 0.0) {
        return Err(Error::invalid(
            "tol",
            format!("must be finite and >= 0, got {tol}"),
        ));
    }
    let n = records("R", matrices, 9)?;
    let check =
        |k: usize| check_matrix("R", rec::<9>(matrices, k), tol).map_err(|e| at_index(e, k));
    if n < PARALLEL_MIN {
        return (0..n).try_for_each(check);
    }
    let result = control::for_ranges(n, TASK_MIN, true, |range| {
        range.into_iter().try_for_each(check)
    });
    first_error(result, || (0..n).try_for_each(check))
}

/// Angular velocities (`out`: N×3, rad/s, in `frame`) from Euler angles and rates (N×3 each,
/// rad and rad/s), as [`crate::rotation::angular_velocity`]. Errors name `"angles"`/`"rates"`.
pub fn angular_velocity_batch(
    seq: EulerSequence,
    frame: Frame,
    angles: &[f64],
    rates: &[f64],
    out: &mut [f64],
) -> Result<()> {
    let n = records("angles", angles, 3)?;
    if records("rates", rates, 3)? != n {
        return Err(Error::invalid(
            "rates",
            format!("must hold as many triples as angles ({n})"),
        ));
    }
    check_out(out.len(), n, 3)?;
    drive::<3, _>(n, out, |k, y| {
        let (a, r) = (rec::<3>(angles, k), rec::<3>(rates, k));
        check_rec("angles", a)?;
        check_rec("rates", r)?;
        let w = angular_velocity_checked_input(*a, *r, seq, frame)?;
        *y = [w.x, w.y, w.z];
        Ok(())
    })
}

/// Euler-angle rates (`out`: N×3, rad/s) from angles (N×3, rad) and angular velocities (N×3,
/// rad/s, in `frame`), as [`crate::rotation::euler_rates`]; [`Error::gimbal_lock`] at the first
/// singular record. Errors name `"angles"`/`"omega_body"`.
pub fn euler_rates_batch(
    seq: EulerSequence,
    frame: Frame,
    angles: &[f64],
    omega: &[f64],
    out: &mut [f64],
) -> Result<()> {
    let n = records("angles", angles, 3)?;
    if records("omega_body", omega, 3)? != n {
        return Err(Error::invalid(
            "omega_body",
            format!("must hold as many vectors as angles ({n})"),
        ));
    }
    check_out(out.len(), n, 3)?;
    drive::<3, _>(n, out, |k, y| {
        let (a, w) = (rec::<3>(angles, k), rec::<3>(omega, k));
        check_rec("angles", a)?;
        check_rec("omega_body", w)?;
        *y = euler_rates_checked_input(*a, &Vec3::from(*w), seq, frame)?;
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rotation::{euler_to_matrix, matrix_to_euler};

    #[test]
    fn batch_equals_single_and_reports_first_bad_index() {
        let seq = EulerSequence::new("yzx", false).unwrap();
        let n = PARALLEL_MIN + 17;
        let angles: Vec<f64> = (0..3 * n)
            .map(|i| ((i * 7919) % 1000) as f64 * 0.006 - 3.0)
            .collect();
        let mut mats = vec![0.0; 9 * n];
        euler_to_matrix_batch(seq, &angles, &mut mats).unwrap();
        let k = n - 5;
        let single =
            euler_to_matrix([angles[3 * k], angles[3 * k + 1], angles[3 * k + 2]], seq).unwrap();
        assert_eq!(&mats[9 * k..9 * k + 9], &row_major(&single));
        let mut back = vec![0.0; 3 * n];
        let mut locked = vec![false; n];
        matrix_to_euler_batch(seq, &mats, &mut back, &mut locked).unwrap();
        let e = matrix_to_euler(&single, seq).unwrap();
        assert_eq!(&back[3 * k..3 * k + 3], &e.angles);
        // Two bad records: the error names the first, also when run in parallel.
        mats[9 * 300] = 2.0;
        mats[9 * 4000 + 4] = f64::NAN;
        let err = matrix_to_euler_batch(seq, &mats, &mut back, &mut locked).unwrap_err();
        assert!(err.message.ends_with("(at flat index 300)"), "{err}");
        assert!(check_rotation_matrix_batch(&mats, 1e-9)
            .unwrap_err()
            .message
            .contains("index 300"));
    }
}
