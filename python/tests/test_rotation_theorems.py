"""Euler's theorem (rotation_axis, axis_angle_to_matrix) and Chasles' theorem (screw_axis)
against high-precision references (mpmath), scipy, closed forms and invariants."""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from poinsot import (
    InvalidRotationError,
    PoinsotError,
    Screw,
    axis_angle_to_matrix,
    euler_to_matrix,
    rotation_axis,
    screw_axis,
)
from scipy.spatial.transform import Rotation

EPS = np.finfo(float).eps
# Round-off of Rodrigues' formula and of the extraction: a few eps.
MATRIX_TOL = 1e-14
HYP = settings(max_examples=200, derandomize=True, deadline=None)


def mp_rotation(axis: list[float], theta: mpmath.mpf) -> np.ndarray:
    """Rodrigues' formula in 50-digit arithmetic, rounded once to float64: the reference
    matrix whose axis and angle are known to far below double round-off."""
    with mpmath.workdps(50):
        n = mpmath.matrix(axis)
        n = n / mpmath.norm(n)
        k = mpmath.matrix([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]])
        r = mpmath.eye(3) + mpmath.sin(theta) * k + (1 - mpmath.cos(theta)) * (k * k)
        return np.array([[float(r[i, j]) for j in range(3)] for i in range(3)])


AXIS = [2.0, -1.0, 2.0]  # |AXIS| = 3
UNIT = np.array(AXIS) / 3.0


@pytest.mark.parametrize("theta", [1e-8, 1e-12, 1e-15, 1e-100])
def test_rotation_axis_tiny_angles_keep_relative_accuracy(theta: float) -> None:
    """acos((tr R - 1)/2) would give 0 or ~1e-8 here; the angle must have relative error ~eps."""
    r = mp_rotation(AXIS, mpmath.mpf(theta))
    n, angle = rotation_axis(r)
    assert abs(angle - theta) <= 4 * EPS * theta
    np.testing.assert_allclose(n, UNIT, atol=4 * EPS)


@pytest.mark.parametrize("delta", ["0", "1e-15", "1e-12", "1e-9", "1e-6", "1e-3"])
def test_rotation_axis_at_and_near_pi(delta: str) -> None:
    """Near pi the skew part vanishes: the axis must come from the symmetric part."""
    with mpmath.workdps(50):
        theta = mpmath.pi - mpmath.mpf(delta)
    r = mp_rotation(AXIS, theta)
    n, angle = rotation_axis(r)
    assert abs(angle - float(theta)) <= 4 * EPS
    if delta == "0":
        # A half turn about n is one about -n: either sign, the matrix is rebuilt.
        assert min(np.abs(n - UNIT).max(), np.abs(n + UNIT).max()) <= 4 * EPS
    else:
        np.testing.assert_allclose(n, UNIT, atol=4 * EPS)
    np.testing.assert_allclose(axis_angle_to_matrix(n, angle), r, atol=MATRIX_TOL)


def test_rotation_axis_identity_convention() -> None:
    n, angle = rotation_axis(np.eye(3))
    assert angle == 0.0 and list(n) == [0.0, 0.0, 1.0]
    assert isinstance(angle, float) and n.shape == (3,)


vec = st.tuples(*[st.floats(-1, 1, allow_nan=False)] * 3).filter(lambda v: np.linalg.norm(v) > 1e-3)


@HYP
@given(v=vec, theta=st.floats(-10, 10, allow_nan=False))
def test_rotation_axis_random_against_scipy(v: tuple[float, float, float], theta: float) -> None:
    r = axis_angle_to_matrix(v, theta)
    n, angle = rotation_axis(r)
    assert 0.0 <= angle <= math.pi
    np.testing.assert_allclose(r @ n, n, atol=MATRIX_TOL)  # the axis is fixed
    np.testing.assert_allclose(axis_angle_to_matrix(n, angle), r, atol=MATRIX_TOL)
    ref = Rotation.from_matrix(r).as_rotvec()
    if angle < math.pi - 1e-6:  # the rotation vector's sign is ambiguous only at pi
        np.testing.assert_allclose(n * angle, ref, atol=1e-13)
    # scipy's Rodrigues agrees with poinsot's
    np.testing.assert_allclose(
        Rotation.from_rotvec(np.array(v) / np.linalg.norm(v) * theta).as_matrix(),
        r,
        atol=MATRIX_TOL,
    )


def test_rotation_axis_batches_and_degrees() -> None:
    rng = np.random.default_rng(5)
    axes = rng.normal(size=(3, 4, 3))
    angles = rng.uniform(0, 180, (3, 4))
    r = axis_angle_to_matrix(axes, angles, degrees=True)
    assert r.shape == (3, 4, 3, 3)
    n, a = rotation_axis(r)
    assert n.shape == (3, 4, 3) and a.shape == (3, 4)
    np.testing.assert_allclose(np.degrees(a), angles, atol=1e-12)
    np.testing.assert_allclose(n, axes / np.linalg.norm(axes, axis=-1, keepdims=True), atol=1e-14)
    # one axis broadcast against many angles
    assert axis_angle_to_matrix([0, 0, 1], np.linspace(0, 1, 5)).shape == (5, 3, 3)
    # scipy Rotation input
    n1, a1 = rotation_axis(Rotation.from_rotvec([0.0, 0.3, 0.0]))
    np.testing.assert_allclose(n1, [0, 1, 0], atol=1e-15)
    assert a1 == pytest.approx(0.3, abs=1e-15)


# ---- Chasles ------------------------------------------------------------------------------


def test_screw_axis_closed_form_example() -> None:
    """Quarter turn about the vertical line through (1, 0, 0) with a 2 m slide:
    x -> R_z(90 deg)(x - p) + p + 2 e_z, so t = p - R p + 2 e_z = (1, -1, 2)."""
    r = euler_to_matrix([90.0, 0.0, 0.0], "zxz", degrees=True)
    s = screw_axis(r, [1.0, -1.0, 2.0])
    np.testing.assert_allclose(s.axis, [0, 0, 1], atol=1e-15)
    np.testing.assert_allclose(s.point, [1, 0, 0], atol=1e-15)
    assert s.angle == pytest.approx(math.pi / 2, abs=1e-15)
    assert s.slide == pytest.approx(2.0, abs=1e-15)
    assert s.pitch == pytest.approx(4 / math.pi, rel=1e-15)
    assert "pitch=1.27324 m/rad" in repr(s) and repr(s).startswith("Screw(axis=[")


def test_screw_limits() -> None:
    # Pure translation: axis t/|t|, point 0, angle 0, slide |t|, pitch inf.
    s = screw_axis(np.eye(3), [0.0, 3.0, 4.0])
    np.testing.assert_allclose(s.axis, [0, 0.6, 0.8], atol=1e-16)
    assert (s.angle, s.slide, s.pitch) == (0.0, 5.0, math.inf)
    assert list(s.point) == [0.0, 0.0, 0.0]
    # Pure rotation about an axis through the origin: point 0, slide 0, pitch 0.
    s = screw_axis(axis_angle_to_matrix([1, 1, 0], 1.0), [0.0, 0.0, 0.0])
    assert s.slide == 0.0 and s.pitch == 0.0
    np.testing.assert_allclose(s.point, 0.0, atol=1e-16)
    # Pure rotation (t perpendicular to the axis): pitch 0 (to round-off), point off origin.
    s = screw_axis(euler_to_matrix([1.0, 0, 0]), [1.0, 2.0, 0.0])
    assert abs(s.pitch) < 1e-16 and np.linalg.norm(s.point) > 1.0
    # Identity: documented conventional screw, never NaN.
    s = screw_axis(np.eye(3), np.zeros(3))
    assert list(s.axis) == [0.0, 0.0, 1.0] and (s.angle, s.slide, s.pitch) == (0.0, 0.0, 0.0)
    # Half turn: cot(pi/2) = 0, the point is half the perpendicular translation.
    s = screw_axis(np.diag([1.0, -1.0, -1.0]), [3.0, 2.0, 0.0])
    np.testing.assert_allclose(s.point, [0, 1, 0], atol=1e-15)
    assert abs(s.slide) == pytest.approx(3.0)


@HYP
@given(
    v=vec,
    theta=st.floats(1e-3, math.pi, allow_nan=False),
    t=st.tuples(*[st.floats(-10, 10, allow_nan=False)] * 3),
    x=st.tuples(*[st.floats(-5, 5, allow_nan=False)] * 3),
)
def test_screw_invariants(v, theta, t, x) -> None:  # type: ignore[no-untyped-def]
    r = axis_angle_to_matrix(v, theta)
    t = np.array(t)
    s = screw_axis(r, t)
    scale = 1.0 + np.linalg.norm(s.point)
    # The screw axis is mapped onto itself, shifted by the slide: R p + t = p + d n.
    np.testing.assert_allclose(r @ s.point + t, s.point + s.slide * s.axis, atol=1e-13 * scale)
    assert abs(s.point @ s.axis) < 1e-13 * scale  # nearest the origin
    assert abs(np.linalg.norm(s.axis) - 1) < 1e-15
    assert s.slide == pytest.approx(s.axis @ t, abs=1e-13)
    # The screw motion reproduces the displacement everywhere.
    np.testing.assert_allclose(s.apply(np.array(x)), r @ np.array(x) + t, atol=1e-13 * scale)
    r2, t2 = s.displacement()
    np.testing.assert_allclose(r2, r, atol=MATRIX_TOL)
    np.testing.assert_allclose(t2, t, atol=1e-13 * scale)
    # The slide is the displacement's smallest translation (points on the axis move least).
    assert abs(s.slide) <= np.linalg.norm(t) + 1e-12


def test_screw_is_frozen_and_checks_input() -> None:
    s = screw_axis(np.eye(3), [1.0, 0, 0])
    assert isinstance(s, Screw)
    with pytest.raises(AttributeError):
        s.angle = 1.0  # type: ignore[misc]
    with pytest.raises(ValueError):
        s.axis[0] = 2.0
    assert s == screw_axis(np.eye(3), [1.0, 0, 0]) and s != screw_axis(np.eye(3), [2.0, 0, 0])


@pytest.mark.parametrize(
    ("call", "exc", "pattern"),
    [
        (lambda: axis_angle_to_matrix([0.0, 0.0, 0.0], 1.0), PoinsotError, r"^axis: .*non-zero"),
        (lambda: axis_angle_to_matrix([0.0, math.nan, 1.0], 1.0), PoinsotError, r"^axis: .*finite"),
        (
            lambda: axis_angle_to_matrix([0.0, 0.0, 1.0], math.inf),
            PoinsotError,
            r"^angle: .*finite",
        ),
        (lambda: axis_angle_to_matrix([0.0, 1.0], 1.0), PoinsotError, r"^axis: .*shape"),
        (
            lambda: rotation_axis(np.diag([1.0, -1.0, 1.0])),
            InvalidRotationError,
            r"^R: .*reflection",
        ),
        (lambda: rotation_axis(np.ones((3, 3))), InvalidRotationError, r"^R: .*orthonormal"),
        (lambda: rotation_axis(np.full((3, 3), math.inf)), PoinsotError, r"^R: .*finite"),
        (lambda: rotation_axis(np.eye(2)), PoinsotError, r"^R: .*shape"),
        (lambda: screw_axis(np.eye(3), [1.0, math.nan, 0.0]), PoinsotError, r"^t: .*finite"),
        (lambda: screw_axis(np.eye(3), [1.0, 0.0]), PoinsotError, r"^t: .*shape"),
        (
            lambda: screw_axis(np.stack([np.eye(3)] * 2), [1.0, 0.0, 0.0]),
            PoinsotError,
            r"^R: .*one rotation",
        ),
        (lambda: screw_axis(-np.eye(3), [1.0, 0.0, 0.0]), InvalidRotationError, r"^R: .*det"),
    ],
)
def test_bad_input_is_named(call, exc, pattern) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(exc, match=pattern):
        call()
