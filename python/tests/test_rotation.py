"""Euler angles, quaternions and matrices: conventions (test_convention_*), scipy cross-checks
for all 24 conventions, round trips, gimbal lock, broadcasting and bad input.

scipy's ``Rotation.from_euler`` reads letter case: UPPERCASE = intrinsic, lowercase =
extrinsic. poinsot never does; the mapping used here is explicit (:func:`scipy_seq`).
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import poinsot
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from poinsot import (
    EULER_SEQUENCES,
    GimbalLockWarning,
    InvalidRotationError,
    PoinsotError,
    check_rotation_matrix,
    euler_to_matrix,
    matrix_to_euler,
    matrix_to_quaternion,
    quaternion_multiply,
    quaternion_to_matrix,
    rotate_vectors,
)
from scipy.spatial.transform import Rotation

# Round-off of three elementary rotations multiplied (and of scipy's quaternion route): a few eps.
MATRIX_TOL = 1e-14
# At gimbal lock the third angle is set to 0: rebuilt within 2 * EULER_LOCK_TOL + round-off.
LOCK_TOL = 2 * poinsot.rotation.EULER_LOCK_TOL + MATRIX_TOL
CONVENTIONS = [(s, i) for s in EULER_SEQUENCES for i in (True, False)]
HYP = settings(max_examples=150, derandomize=True, deadline=None)

PROPER = [s for s in EULER_SEQUENCES if s[0] == s[2]]


def scipy_seq(seq: str, intrinsic: bool) -> str:
    """scipy's spelling of a poinsot convention: uppercase letters mean intrinsic there."""
    return seq.upper() if intrinsic else seq.lower()


def rx(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def ry(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])


def rz(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


ELEMENTARY = {"x": rx, "y": ry, "z": rz}


def lock_betas(seq: str) -> tuple[float, float]:
    return (0.0, math.pi) if seq[0] == seq[2] else (math.pi / 2, -math.pi / 2)


angle = st.floats(-math.pi, math.pi, allow_nan=False)


# ---- conventions --------------------------------------------------------------------------


def test_convention_intrinsic_zxz_default_matrix_product() -> None:
    """The default is the unit's intrinsic zxz: R = R_z(phi) R_x(theta) R_z(psi), pinned by a
    hard-coded matrix (phi = 90 deg, theta = 90 deg, psi = 0: body 1 -> Y, body 2 -> Z)."""
    r = euler_to_matrix([90.0, 90.0, 0.0], degrees=True)
    expected = np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
    np.testing.assert_allclose(r, expected, atol=1e-15)
    phi, theta, psi = 0.3, 1.1, -2.0
    np.testing.assert_allclose(
        euler_to_matrix([phi, theta, psi]), rz(phi) @ rx(theta) @ rz(psi), atol=MATRIX_TOL
    )
    # The line of nodes (body x after the first rotation) is R_z(phi) e_x.
    assert np.allclose(euler_to_matrix([phi, 0, 0]) @ [1, 0, 0], [math.cos(phi), math.sin(phi), 0])


@pytest.mark.parametrize("seq", EULER_SEQUENCES)
def test_convention_intrinsic_and_extrinsic_matrix_products(seq: str) -> None:
    """intrinsic: R = R_a(alpha) R_b(beta) R_c(gamma); extrinsic: R = R_c(gamma) R_b(beta) R_a(alpha)."""
    a, b, c = 0.4, -1.3, 2.2
    ra, rb, rc = ELEMENTARY[seq[0]](a), ELEMENTARY[seq[1]](b), ELEMENTARY[seq[2]](c)
    np.testing.assert_allclose(euler_to_matrix([a, b, c], seq), ra @ rb @ rc, atol=MATRIX_TOL)
    np.testing.assert_allclose(
        euler_to_matrix([a, b, c], seq, intrinsic=False), rc @ rb @ ra, atol=MATRIX_TOL
    )


def test_convention_active_rotation() -> None:
    """Rotations are active and right-handed: R_z(+90 deg) turns e_x into e_y."""
    r = euler_to_matrix([math.pi / 2, 0.0, 0.0], "zxz")
    np.testing.assert_allclose(r @ [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], atol=1e-15)
    np.testing.assert_allclose(rotate_vectors(r, [1.0, 0.0, 0.0]), [0.0, 1.0, 0.0], atol=1e-15)
    axis, ang = poinsot.rotation_axis(r)
    np.testing.assert_allclose(axis, [0, 0, 1], atol=1e-15)
    assert ang == pytest.approx(math.pi / 2, abs=1e-15)


def test_convention_quaternion_scalar_first() -> None:
    """Quaternions are [w, x, y, z]: 90 deg about z is [cos 45, 0, 0, sin 45]."""
    h = math.sqrt(0.5)
    q = matrix_to_quaternion(rz(math.pi / 2))
    np.testing.assert_allclose(q, [h, 0.0, 0.0, h], atol=1e-15)
    np.testing.assert_allclose(quaternion_to_matrix([h, h, 0.0, 0.0]), rx(math.pi / 2), atol=1e-15)
    # scipy's default order is scalar-last; scalar_first=True matches poinsot.
    r = Rotation.from_euler("ZXZ", [0.3, 1.1, -2.0])
    np.testing.assert_allclose(
        matrix_to_quaternion(r), r.as_quat(canonical=True, scalar_first=True), atol=1e-15
    )
    # Canonical sign: w >= 0.
    assert matrix_to_quaternion(rx(3.0))[0] >= 0.0
    assert matrix_to_quaternion(rx(-3.0))[0] >= 0.0


@pytest.mark.parametrize(("seq", "intrinsic"), CONVENTIONS)
def test_convention_canonical_ranges(seq: str, intrinsic: bool) -> None:
    """First and third angle in (-pi, pi]; second in [0, pi] (proper) or [-pi/2, pi/2]."""
    rng = np.random.default_rng(7)
    mats = Rotation.random(2000, random_state=rng).as_matrix()
    # Include half turns, where atan2 meets -pi: those must come out as +pi.
    mats = np.concatenate([mats, [rx(math.pi), ry(math.pi), rz(math.pi), np.eye(3)]])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", GimbalLockWarning)  # the half turns and I lock some
        a = matrix_to_euler(mats, seq, intrinsic=intrinsic)
    assert np.all((a[:, 0] > -math.pi) & (a[:, 0] <= math.pi))
    assert np.all((a[:, 2] > -math.pi) & (a[:, 2] <= math.pi))
    if seq[0] == seq[2]:
        assert np.all((a[:, 1] >= 0.0) & (a[:, 1] <= math.pi))
    else:
        assert np.all((a[:, 1] >= -math.pi / 2) & (a[:, 1] <= math.pi / 2))


@pytest.mark.parametrize(("seq", "intrinsic"), CONVENTIONS)
def test_convention_gimbal_lock_third_angle_zero(seq: str, intrinsic: bool) -> None:
    """At gimbal lock: GimbalLockWarning, third angle 0, and the triple rebuilds R."""
    for beta in lock_betas(seq):
        r = euler_to_matrix([0.7, beta, -2.1], seq, intrinsic=intrinsic)
        with pytest.warns(GimbalLockWarning, match="gimbal lock"):
            a = matrix_to_euler(r, seq, intrinsic=intrinsic)
        assert a[2] == 0.0
        assert abs(a[1] - beta) < 1e-14 or abs(abs(a[1]) - abs(beta)) < 1e-14
        np.testing.assert_allclose(euler_to_matrix(a, seq, intrinsic=intrinsic), r, atol=LOCK_TOL)


def test_convention_uppercase_is_rejected_not_reinterpreted() -> None:
    """Letter case never selects intrinsic/extrinsic (scipy and MuJoCo disagree on it)."""
    with pytest.raises(PoinsotError, match=r"seq: .*`intrinsic` argument, not by letter case"):
        euler_to_matrix([0.1, 0.2, 0.3], "ZXZ")
    with pytest.raises(PoinsotError, match="seq"):
        matrix_to_euler(np.eye(3), "Xyz", intrinsic=False)


# ---- cross-checks against scipy -----------------------------------------------------------


@pytest.mark.parametrize(("seq", "intrinsic"), CONVENTIONS)
@HYP
@given(a=angle, b=angle, c=angle)
def test_euler_to_matrix_matches_scipy(
    seq: str, intrinsic: bool, a: float, b: float, c: float
) -> None:
    ours = euler_to_matrix([a, b, c], seq, intrinsic=intrinsic)
    ref = Rotation.from_euler(scipy_seq(seq, intrinsic), [a, b, c]).as_matrix()
    np.testing.assert_allclose(ours, ref, atol=MATRIX_TOL)


@pytest.mark.parametrize(("seq", "intrinsic"), CONVENTIONS)
@HYP
@given(a=angle, b=angle, c=angle)
def test_matrix_to_euler_matches_scipy_matrices(
    seq: str, intrinsic: bool, a: float, b: float, c: float
) -> None:
    """Angles differ by convention-equivalent choices near lock, so compare MATRICES: scipy's
    matrix of poinsot's angles must be the input matrix."""
    r = Rotation.from_euler("ZYX", [a, b, c]).as_matrix()  # a generic rotation
    with warnings.catch_warnings():
        # hypothesis also tries the lock (e.g. b = 0): both libraries warn there.
        warnings.simplefilter("ignore", UserWarning)
        ours = matrix_to_euler(r, seq, intrinsic=intrinsic)
        scipy_angles = Rotation.from_matrix(r).as_euler(scipy_seq(seq, intrinsic))
    back = Rotation.from_euler(scipy_seq(seq, intrinsic), ours).as_matrix()
    np.testing.assert_allclose(back, r, atol=MATRIX_TOL)
    # Away from lock the angles are unique and equal scipy's.
    mid = ours[1]
    if (abs(math.sin(mid)) if seq[0] == seq[2] else abs(math.cos(mid))) > 1e-3:
        d = np.angle(np.exp(1j * (ours - scipy_angles)))
        np.testing.assert_allclose(d, 0.0, atol=1e-10)


@pytest.mark.parametrize(("seq", "intrinsic"), CONVENTIONS)
def test_batch_round_trip_including_near_lock(seq: str, intrinsic: bool) -> None:
    """R -> angles -> R to round-off for random angles and for middle angles 1e-13 ... 1e-4
    from the lock, where the first/third split is ill-conditioned (acos-based extraction would
    lose ~8 digits there)."""
    rng = np.random.default_rng(11)
    n = 4000
    a = rng.uniform(-math.pi, math.pi, (n, 3))
    near = np.array(lock_betas(seq))[rng.integers(0, 2, n)]
    offsets = rng.choice([-1, 1], n) * 10.0 ** rng.uniform(-13, -4, n)
    a[n // 2 :, 1] = (near + offsets)[n // 2 :]
    r = euler_to_matrix(a, seq, intrinsic=intrinsic)
    back = euler_to_matrix(matrix_to_euler(r, seq, intrinsic=intrinsic), seq, intrinsic=intrinsic)
    assert np.abs(back - r).max() < MATRIX_TOL


@HYP
@given(a=angle, b=angle, c=angle)
def test_matrix_quaternion_round_trip_and_scipy(a: float, b: float, c: float) -> None:
    r = euler_to_matrix([a, b, c], "zyx")
    q = matrix_to_quaternion(r)
    assert q[0] >= 0.0 and abs(np.linalg.norm(q) - 1.0) < 1e-15
    np.testing.assert_allclose(quaternion_to_matrix(q), r, atol=MATRIX_TOL)
    ref = Rotation.from_matrix(r).as_quat(canonical=True, scalar_first=True)
    if abs(q[0]) > 1e-12:  # at w = 0 the canonical signs may differ
        np.testing.assert_allclose(q, ref, atol=1e-14)


@HYP
@given(a=angle, b=angle, c=angle, d=angle)
def test_quaternion_multiply_composes_like_matrices(a: float, b: float, c: float, d: float) -> None:
    p = matrix_to_quaternion(euler_to_matrix([a, b, 0.3], "xyz"))
    q = matrix_to_quaternion(euler_to_matrix([c, d, -0.8], "zxz"))
    np.testing.assert_allclose(
        quaternion_to_matrix(quaternion_multiply(p, q)),
        quaternion_to_matrix(p) @ quaternion_to_matrix(q),
        atol=MATRIX_TOL,
    )


def test_quaternion_normalize_flag() -> None:
    with pytest.raises(InvalidRotationError, match=r"q: .*unit quaternion"):
        quaternion_to_matrix([2.0, 0.0, 0.0, 0.0])
    np.testing.assert_allclose(
        quaternion_to_matrix([2.0, 0.0, 0.0, 0.0], normalize=True), np.eye(3)
    )


def test_degrees_and_broadcasting_and_scipy_input() -> None:
    rng = np.random.default_rng(3)
    a = rng.uniform(-3, 3, (4, 5, 3))
    r = euler_to_matrix(a, "yxz", intrinsic=False)
    assert r.shape == (4, 5, 3, 3)
    np.testing.assert_allclose(
        euler_to_matrix(np.degrees(a), "yxz", intrinsic=False, degrees=True), r, atol=1e-15
    )
    back = matrix_to_euler(r, "yxz", intrinsic=False, degrees=True)
    assert back.shape == (4, 5, 3)
    np.testing.assert_allclose(
        euler_to_matrix(back, "yxz", intrinsic=False, degrees=True), r, atol=MATRIX_TOL
    )
    # scipy Rotation accepted wherever a rotation is taken (single and stacked).
    single = Rotation.from_euler("ZXZ", [0.3, 1.1, -2.0])
    np.testing.assert_allclose(matrix_to_euler(single), [0.3, 1.1, -2.0], atol=1e-14)
    stacked = Rotation.from_matrix(r.reshape(-1, 3, 3))
    assert matrix_to_quaternion(stacked).shape == (20, 4)
    # rotate_vectors broadcasts R (..., 3, 3) against v (..., 3).
    v = rng.normal(size=(7, 3))
    out = rotate_vectors(r[0, 0], v)
    np.testing.assert_allclose(out, v @ r[0, 0].T, atol=1e-14)
    np.testing.assert_allclose(rotate_vectors(single, v), single.apply(v), atol=1e-14)
    assert quaternion_multiply(matrix_to_quaternion(r), [1.0, 0, 0, 0]).shape == (4, 5, 4)


def test_check_rotation_matrix_and_scipy_conversion() -> None:
    r = euler_to_matrix([[0.1, 0.2, 0.3], [1.0, 2.0, 3.0]])
    out = check_rotation_matrix(r)
    assert out.dtype == np.float64 and out.shape == (2, 3, 3)
    bad = r.copy()
    bad[1, 0, 0] += 1e-6
    check_rotation_matrix(bad, tol=1e-5)
    with pytest.raises(InvalidRotationError, match=r"R: .*orthonormal.*flat index 1"):
        check_rotation_matrix(bad)
    rot = poinsot.as_scipy_rotation(r)
    np.testing.assert_allclose(rot.as_matrix(), r, atol=1e-15)
    assert poinsot.as_scipy_rotation(rot) is rot


def test_all_lists_every_public_name() -> None:
    for name in [
        "euler_to_matrix", "matrix_to_euler", "rotation_axis", "screw_axis", "Screw",
        "body_angular_velocity", "space_angular_velocity", "euler_rates", "axis_angle_to_matrix",
        "matrix_to_quaternion", "quaternion_to_matrix", "quaternion_multiply", "rotate_vectors",
        "check_rotation_matrix", "as_scipy_rotation", "EULER_SEQUENCES",
    ]:  # fmt: skip
        assert name in poinsot.rotation.__all__ and hasattr(poinsot, name), name


# ---- bad input ----------------------------------------------------------------------------

REFLECTION = np.diag([1.0, 1.0, -1.0])


@pytest.mark.parametrize(
    ("call", "exc", "pattern"),
    [
        (lambda: euler_to_matrix([0.0, math.nan, 0.0]), PoinsotError, r"^angles: .*finite"),
        (lambda: euler_to_matrix([0.0, 0.0, math.inf]), PoinsotError, r"^angles: .*finite"),
        (lambda: euler_to_matrix([0.0, 0.0]), PoinsotError, r"^angles: .*shape"),
        (lambda: euler_to_matrix("abc"), PoinsotError, r"^angles: "),
        (lambda: euler_to_matrix([0.1, 0.2, 0.3], "xxz"), PoinsotError, r"^seq: .*consecutive"),
        (lambda: euler_to_matrix([0.1, 0.2, 0.3], "xyw"), PoinsotError, r"^seq: "),
        (lambda: euler_to_matrix([0.1, 0.2, 0.3], "zx"), PoinsotError, r"^seq: "),
        (lambda: euler_to_matrix([0.1, 0.2, 0.3], "ZXZ"), PoinsotError, r"^seq: .*intrinsic"),
        (lambda: euler_to_matrix([0.1, 0.2, 0.3], 3), PoinsotError, r"^seq: "),
        (lambda: euler_to_matrix([0.1, 0.2, 0.3], intrinsic="yes"), PoinsotError, r"^intrinsic: "),
        (lambda: matrix_to_euler(np.full((3, 3), math.nan)), PoinsotError, r"^R: .*finite"),
        (lambda: matrix_to_euler(np.eye(4)), PoinsotError, r"^R: .*shape"),
        (lambda: matrix_to_euler(2 * np.eye(3)), InvalidRotationError, r"^R: .*orthonormal"),
        (
            lambda: matrix_to_euler(REFLECTION),
            InvalidRotationError,
            r"^R: .*det R = -1.*reflection",
        ),
        (lambda: matrix_to_quaternion(REFLECTION), InvalidRotationError, r"^R: .*reflection"),
        (lambda: rotate_vectors(REFLECTION, [1, 0, 0]), InvalidRotationError, r"^R: "),
        (lambda: rotate_vectors(np.eye(3), [1, math.nan, 0]), PoinsotError, r"^v: .*finite"),
        (
            lambda: rotate_vectors(np.eye(3)[None].repeat(2, 0), np.ones((3, 3))),
            PoinsotError,
            r"^v: .*broadcast",
        ),
        (lambda: check_rotation_matrix(REFLECTION), InvalidRotationError, r"^R: .*reflection"),
        (lambda: check_rotation_matrix(np.eye(3), tol=-1.0), PoinsotError, r"^tol: "),
        (lambda: quaternion_to_matrix([0.0, 0.0, 0.0, 0.0]), InvalidRotationError, r"^q: .*zero"),
        (
            lambda: quaternion_to_matrix([0.0, 0.0, 0.0, 0.0], normalize=True),
            InvalidRotationError,
            r"^q: .*zero",
        ),
        (lambda: quaternion_to_matrix([1.0, 0.0, math.nan, 0.0]), PoinsotError, r"^q: .*finite"),
        (lambda: quaternion_to_matrix([1.0, 0.0, 0.0]), PoinsotError, r"^q: .*shape"),
        (
            lambda: quaternion_multiply([1.0, math.inf, 0, 0], [1.0, 0, 0, 0]),
            PoinsotError,
            r"^p: .*finite",
        ),
    ],
)
def test_bad_input_is_named(call, exc, pattern) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(exc, match=pattern):
        call()


def test_errors_are_value_errors_and_batch_errors_give_the_index() -> None:
    mats = euler_to_matrix(np.zeros((10, 3)))
    mats[6] = REFLECTION
    with pytest.raises(ValueError, match=r"R: .*\(at flat index 6\)"):
        matrix_to_euler(mats)
