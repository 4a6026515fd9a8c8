//! Euler angles: the 24 conventions (12 sequences × intrinsic/extrinsic) and the conversions to
//! and from rotation matrices.
//!
//! A sequence is a **lowercase** three-letter string of axes (`"zxz"`, `"xyz"`, ...) plus an
//! explicit `intrinsic` flag — never letter case, whose meaning scipy and MuJoCo use in opposite
//! ways. With axes `(a, b, c)` and angles `(α, β, γ)`:
//!
//! - intrinsic (rotations about the moving, body axes): `R = R_a(α) R_b(β) R_c(γ)`;
//! - extrinsic (rotations about the fixed, space axes): `R = R_c(γ) R_b(β) R_a(α)`,
//!   so extrinsic `(a, b, c)` with `(α, β, γ)` is intrinsic `(c, b, a)` with `(γ, β, α)`.
//!
//! The unit's convention (section "Euler's Angles", Fig. 2.12) is intrinsic `zxz`: φ about Z,
//! θ about the line of nodes ξ, ψ about body axis 3, `R = R_z(φ) R_x(θ) R_z(ψ)`
//! ([`EulerSequence::UNIT`]).
//!
//! Canonical ranges of [`matrix_to_euler`]: first and third angle in `(−π, π]`; the second in
//! `[0, π]` for proper Euler sequences (`a == c`) and in `[−π/2, π/2]` for Tait–Bryan sequences.
//!
//! Extraction is accurate to round-off everywhere, near gimbal lock included: the second angle
//! comes from an `atan2` of a sine and a cosine (never `acos`/`asin` of one element). Of the
//! first and third angles, the one smaller in magnitude comes from an `atan2` of its own matrix
//! entries (a row and a column of `R`, each entry a product with its sine or cosine), so a small
//! angle keeps its relative accuracy (no `α + γ − α` cancellation); the other comes from the sum
//! `α + γ` (or difference `α − γ`), which the matrix determines well at the lock that is near,
//! so that the triple reconstructs the matrix to round-off even where the split between `α` and
//! `γ` is ill-conditioned. A sequence whose axes are an odd permutation is extracted in the
//! user's signs directly (no `π − α` shift, which would cost a small angle its digits).

use std::f64::consts::{PI, TAU};

use crate::error::{check_finite, Error, Result};
use crate::rotation::matrix::{elementary_rotation, rotation_to_convert, row_major};
use crate::Mat3;

/// Gimbal lock in [`matrix_to_euler`]: the middle angle's `|sin β|` (proper Euler) or `|cos β|`
/// (Tait–Bryan), read from the matrix, is at most this. There the first and third angles are not
/// separately defined; the third is set to 0, and the triple reconstructs the matrix within
/// `2·EULER_LOCK_TOL` (`1e-14`, about 45 ε: a matrix built at the lock in floating point, e.g.
/// with `β = π`, has `sin β ≈ 1.2e-16`). Closer than about `1e-7` to the lock the split between
/// first and third angle is ill-conditioned, but the returned triple is still the one of the
/// given matrix, to round-off.
pub const EULER_LOCK_TOL: f64 = 1e-14;

/// A coordinate axis of an Euler sequence.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Axis {
    /// The x axis (index 0).
    X,
    /// The y axis (index 1).
    Y,
    /// The z axis (index 2).
    Z,
}

impl Axis {
    /// Index of the axis: x = 0, y = 1, z = 2.
    pub fn index(self) -> usize {
        self as usize
    }
    /// The lowercase letter of the axis.
    pub fn letter(self) -> char {
        ['x', 'y', 'z'][self as usize]
    }
    fn from_index(i: usize) -> Self {
        [Axis::X, Axis::Y, Axis::Z][i]
    }
}

/// The two families of Euler sequences.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SequenceKind {
    /// First and third axes equal (`zxz`, `xyx`, ...): the middle angle is in `[0, π]`, gimbal
    /// lock at `sin β = 0`.
    ProperEuler,
    /// Three different axes (`xyz`, `zyx`, ...): the middle angle is in `[−π/2, π/2]`, gimbal
    /// lock at `cos β = 0`.
    TaitBryan,
}

/// An Euler-angle convention: three axes and whether the rotations are intrinsic (about the
/// body axes) or extrinsic (about the space axes). See the module documentation.
///
/// ```
/// use poinsot::rotation::{euler_to_matrix, matrix_to_euler, rot_x, rot_z, EulerSequence};
/// // The unit's intrinsic z-x-z: R = R_z(φ) R_x(θ) R_z(ψ).
/// let r = euler_to_matrix([0.3, 0.7, 0.1], EulerSequence::UNIT)?;
/// assert!((r - rot_z(0.3) * rot_x(0.7) * rot_z(0.1)).amax() < 1e-15);
/// // The same rotation in extrinsic x-y-z angles, and back.
/// let xyz = EulerSequence::new("xyz", false)?;
/// let angles = matrix_to_euler(&r, xyz)?.angles;
/// assert!((euler_to_matrix(angles, xyz)? - r).amax() < 1e-15);
/// // Intrinsic or extrinsic is a flag, never letter case.
/// assert!(EulerSequence::new("ZXZ", true).is_err());
/// # Ok::<(), poinsot::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct EulerSequence {
    axes: [usize; 3],
    intrinsic: bool,
}

impl EulerSequence {
    /// The twelve sequences: six proper Euler, then six Tait–Bryan.
    pub const NAMES: [&'static str; 12] = [
        "xyx", "xzx", "yxy", "yzy", "zxz", "zyz", "xyz", "xzy", "yxz", "yzx", "zxy", "zyx",
    ];

    /// The unit's convention: intrinsic `zxz` (φ, θ, ψ), `R = R_z(φ) R_x(θ) R_z(ψ)`.
    pub const UNIT: EulerSequence = EulerSequence {
        axes: [2, 0, 2],
        intrinsic: true,
    };

    /// Parses `seq` (three lowercase letters from `x`, `y`, `z`, no two consecutive equal).
    ///
    /// Errors ([`Error::invalid`] naming `"seq"`): uppercase letters (intrinsic/extrinsic is
    /// chosen by `intrinsic`, not by letter case), a length other than 3, letters other than
    /// `x`, `y`, `z`, or two equal consecutive axes (`"xxz"`).
    pub fn new(seq: &str, intrinsic: bool) -> Result<Self> {
        let valid = "three letters from 'x', 'y', 'z' with no two consecutive axes equal, e.g. \
                     'zxz' or 'xyz'";
        if seq.chars().any(|c| c.is_uppercase()) {
            return Err(Error::invalid(
                "seq",
                format!(
                    "must be lowercase, got {seq:?}: intrinsic or extrinsic rotations are chosen \
                     by the `intrinsic` argument, not by letter case (scipy and MuJoCo give letter \
                     case opposite meanings)"
                ),
            ));
        }
        let chars: Vec<char> = seq.chars().collect();
        if chars.len() != 3 {
            return Err(Error::invalid(
                "seq",
                format!("must be {valid}; got {seq:?}"),
            ));
        }
        let mut axes = [0usize; 3];
        for (slot, c) in axes.iter_mut().zip(&chars) {
            *slot = match c {
                'x' => 0,
                'y' => 1,
                'z' => 2,
                _ => {
                    return Err(Error::invalid(
                        "seq",
                        format!("must be {valid}; got {seq:?}"),
                    ))
                }
            };
        }
        if axes[0] == axes[1] || axes[1] == axes[2] {
            return Err(Error::invalid(
                "seq",
                format!("consecutive axes must differ (a rotation about the same axis twice is one rotation); must be {valid}; got {seq:?}"),
            ));
        }
        Ok(Self { axes, intrinsic })
    }

    /// All 24 conventions: the 12 sequences of [`Self::NAMES`], intrinsic then extrinsic.
    pub fn all() -> Vec<EulerSequence> {
        [true, false]
            .iter()
            .flat_map(|&intr| {
                Self::NAMES
                    .iter()
                    .map(move |s| Self::new(s, intr).expect("valid"))
            })
            .collect()
    }

    /// The axes in the order of the sequence's name.
    pub fn axes(&self) -> [Axis; 3] {
        self.axes.map(Axis::from_index)
    }

    /// The sequence's name, lowercase (e.g. `"zxz"`).
    pub fn name(&self) -> String {
        self.axes().iter().map(|a| a.letter()).collect()
    }

    /// True for rotations about the body (moving) axes.
    pub fn is_intrinsic(&self) -> bool {
        self.intrinsic
    }

    /// Proper Euler or Tait–Bryan.
    pub fn kind(&self) -> SequenceKind {
        if self.axes[0] == self.axes[2] {
            SequenceKind::ProperEuler
        } else {
            SequenceKind::TaitBryan
        }
    }

    /// The axes `(a, b, c)` of the equivalent intrinsic sequence, `R = R_a R_b R_c`: the name's
    /// axes for an intrinsic sequence, reversed for an extrinsic one.
    pub(crate) fn intrinsic_axes(&self) -> [usize; 3] {
        if self.intrinsic {
            self.axes
        } else {
            [self.axes[2], self.axes[1], self.axes[0]]
        }
    }

    /// `a` (angles, rates, Jacobian columns) in the order of the equivalent intrinsic sequence:
    /// reversed if extrinsic. The map is its own inverse.
    pub(crate) fn in_intrinsic_order<T: Copy>(&self, a: [T; 3]) -> [T; 3] {
        if self.intrinsic {
            a
        } else {
            [a[2], a[1], a[0]]
        }
    }
}

impl std::fmt::Display for EulerSequence {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let which = if self.intrinsic {
            "intrinsic"
        } else {
            "extrinsic"
        };
        write!(f, "{which} {}", self.name())
    }
}

/// Euler angles extracted from a matrix, with the gimbal-lock flag.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EulerAngles {
    /// `(α, β, γ)` in rad, in the order of the sequence's name, in the canonical ranges.
    pub angles: [f64; 3],
    /// True at gimbal lock (see [`EULER_LOCK_TOL`]): the third angle was set to 0.
    pub gimbal_lock: bool,
}

/// The rotation matrix of Euler angles `angles = (α, β, γ)` (rad) in convention `seq`:
/// intrinsic `R = R_a(α) R_b(β) R_c(γ)`, extrinsic `R = R_c(γ) R_b(β) R_a(α)`. For the unit's
/// intrinsic `zxz`, `R = R_z(φ) R_x(θ) R_z(ψ)` maps body to space components.
///
/// Errors: non-finite angles ([`Error::invalid`] naming `"angles"`).
pub fn euler_to_matrix(angles: [f64; 3], seq: EulerSequence) -> Result<Mat3> {
    check_finite("angles", &angles)?;
    Ok(euler_to_matrix_unchecked(angles, seq))
}

/// [`euler_to_matrix`] without the finiteness check (the batch kernel checks first).
pub(crate) fn euler_to_matrix_unchecked(angles: [f64; 3], seq: EulerSequence) -> Mat3 {
    let [a, b, c] = seq.intrinsic_axes();
    let [al, be, ga] = seq.in_intrinsic_order(angles);
    elementary_rotation(a, al) * elementary_rotation(b, be) * elementary_rotation(c, ga)
}

/// The Euler angles of rotation matrix `r` in convention `seq` (the inverse of
/// [`euler_to_matrix`]), in the canonical ranges, with the gimbal-lock flag.
///
/// `r` is checked with [`crate::rotation::ROTATION_MATRIX_TOL`]; one off orthonormal by more
/// than [`crate::rotation::NEAREST_ROTATION_DEFECT`] gives the angles of the nearest rotation.
/// Errors: non-finite entries ([`Error::invalid`]) or a matrix that is not a proper rotation
/// ([`Error::rotation`]), naming `"R"`.
pub fn matrix_to_euler(r: &Mat3, seq: EulerSequence) -> Result<EulerAngles> {
    Ok(matrix_to_euler_unchecked(
        &rotation_to_convert("R", &row_major(r))?,
        seq,
    ))
}

/// Parity of a permutation `(a, b, c)` of `(0, 1, 2)`: +1 if cyclic, −1 otherwise.
fn parity(a: usize, b: usize) -> f64 {
    if (b + 3 - a) % 3 == 1 {
        1.0
    } else {
        -1.0
    }
}

/// Maps an angle in `[−2π, 2π]` to `(−π, π]` (and −0 to +0).
#[inline]
fn wrap(x: f64) -> f64 {
    let y = if x > PI {
        x - TAU
    } else if x <= -PI {
        x + TAU
    } else {
        x
    };
    y + 0.0
}

/// Extraction from a row-major matrix `m` (assumed a rotation; not checked).
pub(crate) fn matrix_to_euler_unchecked(m: &[f64; 9], seq: EulerSequence) -> EulerAngles {
    let [i, j, k] = seq.intrinsic_axes();
    // An extrinsic sequence is extracted as the reversed intrinsic one, whose *first* angle is
    // the user's third: that one is set to 0 at gimbal lock.
    let zero_first = !seq.is_intrinsic();
    // Relabel the axes (i, j, l) → (x, y, z): M[a][b] = R[σ(a)][σ(b)] is P R Pᵀ with the
    // permutation matrix P, and P R_σ(a)(α) Pᵀ = R_a(ε α) with ε = det P = parity of σ. So the
    // sequence becomes xyx (proper) or xyz (Tait–Bryan) with angles multiplied by ε.
    let proper = i == k;
    let l = 3 - i - j;
    let sigma = [i, j, l];
    let eps = parity(i, j);
    let at = |a: usize, b: usize| m[3 * sigma[a] + sigma[b]];
    let (e, lock) = if proper {
        // Proper: extracted in the user's signs (ε enters the formulas), so that no angle is
        // computed as π − x, which would lose a small angle's relative accuracy.
        canonical_xyx(&at, eps, zero_first)
    } else {
        // Tait–Bryan: (−α, −β, −γ) is in range, and negation is exact.
        let (e, lock) = canonical_xyz(&at, zero_first);
        if eps < 0.0 {
            ([wrap(-e[0]), -e[1] + 0.0, wrap(-e[2])], lock)
        } else {
            (e, lock)
        }
    };
    EulerAngles {
        angles: seq.in_intrinsic_order(e),
        gimbal_lock: lock,
    }
}

/// Angles of `M = R_x(εα) R_y(εβ) R_x(εγ)` with sign `ε = ±1` (the parity of the relabelling),
/// returned as `(α, β, γ)`, β in [0, π] (for `ε = −1` that is the triple `(α, β, γ)` with
/// `R_x(−α) R_y(−β) R_x(−γ) = M`, the equivalent of `(π − α', β', π − γ')` of the `ε = +1`
/// extraction, without its cancellation).
///
/// `M[:,0] = (cβ, sβ sα, −ε sβ cα)`, `M[0,:] = (cβ, sβ sγ, ε sβ cγ)`, and on the (y, z) block
/// `M11 + M22 = (1 + cβ) cos(α + γ)`, `ε (M21 − M12) = (1 + cβ) sin(α + γ)`,
/// `M11 − M22 = (1 − cβ) cos(α − γ)`, `ε (M21 + M12) = (1 − cβ) sin(α − γ)`.
#[inline]
fn canonical_xyx(
    at: &impl Fn(usize, usize) -> f64,
    eps: f64,
    zero_first: bool,
) -> ([f64; 3], bool) {
    let cb = at(0, 0);
    let (m10, m20) = (at(1, 0), at(2, 0));
    let sb = (m10 * m10 + m20 * m20).sqrt();
    let beta = sb.atan2(cb);
    let sum = || (eps * (at(2, 1) - at(1, 2))).atan2(at(1, 1) + at(2, 2));
    let diff = || (eps * (at(2, 1) + at(1, 2))).atan2(at(1, 1) - at(2, 2));
    if sb <= EULER_LOCK_TOL {
        return (lock_angles(cb > 0.0, beta, sum, diff, zero_first), true);
    }
    let (alpha, gamma) = split(
        [m10, -eps * m20],
        [at(0, 1), eps * at(0, 2)],
        cb >= 0.0,
        sum,
        diff,
    );
    ([alpha, beta, gamma], false)
}

/// Angles of `M = R_x(α) R_y(β) R_z(γ)`, β in [−π/2, π/2].
///
/// `M02 = sβ`, `M[:,2] = (sβ, −sα cβ, cα cβ)`, `M[0,:2] = (cβ cγ, −cβ sγ)`, and
/// `M11 − M20 = (1 + sβ) cos(α + γ)`, `M21 + M10 = (1 + sβ) sin(α + γ)`,
/// `M11 + M20 = (1 − sβ) cos(α − γ)`, `M21 − M10 = (1 − sβ) sin(α − γ)`.
#[inline]
fn canonical_xyz(at: &impl Fn(usize, usize) -> f64, zero_first: bool) -> ([f64; 3], bool) {
    let sb = at(0, 2);
    let (m12, m22) = (at(1, 2), at(2, 2));
    let cb = (m12 * m12 + m22 * m22).sqrt();
    let beta = sb.atan2(cb);
    let sum = || (at(2, 1) + at(1, 0)).atan2(at(1, 1) - at(2, 0));
    let diff = || (at(2, 1) - at(1, 0)).atan2(at(1, 1) + at(2, 0));
    if cb <= EULER_LOCK_TOL {
        return (lock_angles(sb > 0.0, beta, sum, diff, zero_first), true);
    }
    let (alpha, gamma) = split([-m12, m22], [-at(0, 1), at(0, 0)], sb >= 0.0, sum, diff);
    ([alpha, beta, gamma], false)
}

/// The first and third angles from their own entries `a = (y, x)` and `g = (y, x)` (each
/// `s (sin, cos)` of its angle with the same factor `s = |sin β|` or `|cos β| > 0`, so an
/// `atan2` of them is accurate relative to the angle's size, but only to `ε/s` absolutely, the
/// split being ill-conditioned near the lock) and the well-conditioned combination:
/// `sum() = α + γ` (`near_sum`, the factor `1 + |cβ|` or `1 + |sβ|` ≥ 1 in front of it) or
/// `diff() = α − γ`. The angle smaller in magnitude (the larger cosine, `x`: no `atan2` needed
/// to choose) is the `atan2` of its entries, so it keeps its relative accuracy; the larger is
/// the combination minus (or plus) the smaller, so that `α ± γ` is exact and the triple
/// rebuilds the matrix to round-off also where the split is ill-conditioned. Three `atan2` in
/// all with β's, as before; both angles in `(−π, π]`.
#[inline]
fn split(
    a: [f64; 2],
    g: [f64; 2],
    near_sum: bool,
    sum: impl Fn() -> f64,
    diff: impl Fn() -> f64,
) -> (f64, f64) {
    if a[1] >= g[1] {
        let alpha = wrap(a[0].atan2(a[1]));
        let gamma = if near_sum {
            sum() - alpha
        } else {
            alpha - diff()
        };
        (alpha, wrap(gamma))
    } else {
        let gamma = wrap(g[0].atan2(g[1]));
        let alpha = if near_sum {
            sum() - gamma
        } else {
            diff() + gamma
        };
        (wrap(alpha), gamma)
    }
}

/// At gimbal lock only `α + γ` (lock where the sum is defined) or `α − γ` is defined: put it
/// all in one angle and set the other (the sequence's third) to 0.
#[inline]
fn lock_angles(
    at_sum: bool,
    beta: f64,
    sum: impl Fn() -> f64,
    diff: impl Fn() -> f64,
    zero_first: bool,
) -> [f64; 3] {
    let (alpha, gamma) = match (at_sum, zero_first) {
        (true, false) => (wrap(sum()), 0.0),
        (true, true) => (0.0, wrap(sum())),
        (false, false) => (wrap(diff()), 0.0),
        (false, true) => (0.0, wrap(-diff())),
    };
    [alpha, beta, gamma]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rotation::{rot_x, rot_z};
    use crate::ErrorKind;

    #[test]
    fn parsing_rejects_case_length_letters_and_repeats() {
        for bad in ["ZXZ", "zXz", "xxz", "xzz", "zx", "zxzx", "abc", "", "zxw"] {
            let e = EulerSequence::new(bad, true).unwrap_err();
            assert_eq!(e.kind, ErrorKind::InvalidArgument);
            assert!(e.to_string().starts_with("seq: "), "{e}");
        }
        let e = EulerSequence::new("ZXZ", false).unwrap_err();
        assert!(
            e.message
                .contains("`intrinsic` argument, not by letter case"),
            "{e}"
        );
        assert_eq!(EulerSequence::all().len(), 24);
        assert_eq!(
            EulerSequence::UNIT,
            EulerSequence::new("zxz", true).unwrap()
        );
        assert_eq!(EulerSequence::UNIT.to_string(), "intrinsic zxz");
    }

    #[test]
    fn unit_default_is_rz_rx_rz() {
        let (phi, theta, psi) = (0.3, 1.1, -2.0);
        let r = euler_to_matrix([phi, theta, psi], EulerSequence::UNIT).unwrap();
        let expected = rot_z(phi) * rot_x(theta) * rot_z(psi);
        assert!((r - expected).norm() < 1e-15);
        let e = matrix_to_euler(&r, EulerSequence::UNIT).unwrap();
        assert!(!e.gimbal_lock);
        for (a, b) in e.angles.iter().zip([phi, theta, psi]) {
            assert!((a - b).abs() < 1e-14, "{:?}", e.angles);
        }
    }

    #[test]
    fn wrap_is_half_open() {
        assert_eq!(wrap(-PI), PI);
        assert_eq!(wrap(PI), PI);
        assert_eq!(wrap(-TAU), 0.0);
        assert!(wrap(-0.0).is_sign_positive());
    }
}
