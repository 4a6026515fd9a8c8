"""Chasles' theorem as a continuous motion: ``Screw.displacement_at(s)``, the pose at fraction
``s`` of the screw motion (rotate about the screw axis while sliding along it), against scipy's
rotation vectors (an independent reference), the group property and the axis invariants."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from poinsot import PoinsotError, euler_to_matrix, screw_axis
from scipy.spatial.transform import Rotation

# Round-off of Rodrigues' formula, of the axis extraction and of one composition: a few eps
# on quantities of order 1–10.
POSE_TOL = 1e-13
HYP = settings(max_examples=200, derandomize=True, deadline=None)

R_EXAMPLE = euler_to_matrix([0.4, 1.1, -0.7])
T_EXAMPLE = np.array([0.8, -1.5, 2.0])


def test_ends_are_identity_and_the_displacement() -> None:
    s = screw_axis(R_EXAMPLE, T_EXAMPLE)
    r0, t0 = s.displacement_at(0.0)
    assert np.array_equal(r0, np.eye(3)) and np.array_equal(t0, np.zeros(3))
    r1, t1 = s.displacement_at(1.0)
    np.testing.assert_allclose(r1, R_EXAMPLE, atol=POSE_TOL)
    np.testing.assert_allclose(t1, T_EXAMPLE, atol=POSE_TOL)


def test_rotation_part_is_scipys_rotvec_of_the_fraction() -> None:
    s = screw_axis(R_EXAMPLE, T_EXAMPLE)
    for f in (0.1, 0.37, 0.5, 0.9, -0.3, 1.6):
        rf, tf = s.displacement_at(f)
        ref = Rotation.from_rotvec(f * s.angle * s.axis).as_matrix()
        np.testing.assert_allclose(rf, ref, atol=POSE_TOL)
        # The axis point only slides, by the same fraction of the slide.
        p = s.point + 2.5 * s.axis
        np.testing.assert_allclose(rf @ p + tf, p + f * s.slide * s.axis, atol=POSE_TOL)


def test_pure_translation_moves_in_a_straight_line() -> None:
    s = screw_axis(np.eye(3), [0.0, 3.0, 4.0])
    r, t = s.displacement_at(0.25)
    assert np.array_equal(r, np.eye(3))
    np.testing.assert_allclose(t, [0.0, 0.75, 1.0], atol=1e-15)


def test_non_finite_fraction_is_refused() -> None:
    s = screw_axis(R_EXAMPLE, T_EXAMPLE)
    with pytest.raises(PoinsotError, match="^s: "):
        s.displacement_at(math.nan)


@HYP
@given(
    angles=st.tuples(*[st.floats(-math.pi, math.pi, allow_nan=False)] * 3),
    t=st.tuples(*[st.floats(-5, 5, allow_nan=False)] * 3),
    f=st.floats(0.0, 1.0, allow_nan=False),
)
def test_two_fractions_compose_to_their_sum(angles, t, f) -> None:  # type: ignore[no-untyped-def]
    """One screw: D(f) ∘ D(1 − f) = D(1) = (R, t) — the intermediate poses lie on one motion."""
    r = euler_to_matrix(list(angles))
    s = screw_axis(r, t)
    ra, ta = s.displacement_at(f)
    rb, tb = s.displacement_at(1.0 - f)
    np.testing.assert_allclose(ra @ rb, r, atol=POSE_TOL)
    np.testing.assert_allclose(ra @ tb + ta, np.asarray(t), atol=10 * POSE_TOL)


# ---- a Screw built from its parts (issue 21, item 9) -------------------------------------------


def _written_out(axis: np.ndarray, point: np.ndarray, angle: float, slide: float, x: np.ndarray):  # type: ignore[no-untyped-def]
    """``point + R (x - point) + slide n`` with R = cos a I + sin a [n]x + (1 - cos a) n n^T
    written out for the unit axis n (an independent closed form, not poinsot's Rodrigues)."""
    n = np.asarray(axis, float) / np.linalg.norm(axis)
    c, s = math.cos(angle), math.sin(angle)
    d = np.asarray(x, float) - point
    turned = c * d + s * np.cross(n, d) + (1 - c) * (d @ n)[..., None] * n
    return point + turned + slide * n


def test_the_issues_example_applies_the_screw() -> None:
    # Screw([0,0,1.],[0,0,0],.5,.1,.2).apply([1.,2.,3.]) raised a bare TypeError (the list
    # axis reached the binding); pitch .2 = slide / angle, so it is a valid screw.
    from poinsot import Screw

    s = Screw([0, 0, 1.0], [0, 0, 0], 0.5, 0.1, 0.2)
    c, sn = math.cos(0.5), math.sin(0.5)
    want = [c * 1 - sn * 2, sn * 1 + c * 2, 3.0 + 0.1]  # turn 0.5 rad about z, rise 0.1
    np.testing.assert_allclose(s.apply([1.0, 2.0, 3.0]), want, rtol=0, atol=4e-16)
    assert s.pitch == 0.1 / 0.5 and isinstance(s.axis, np.ndarray) and s.angle == 0.5
    assert not s.axis.flags.writeable and not s.point.flags.writeable


def test_a_screw_from_parts_broadcasts_over_points_as_written_out() -> None:
    from poinsot import Screw

    axis, point = np.array([1.0, -2.0, 2.0]), np.array([0.3, 1.7, -0.4])
    s = Screw(axis, point, 2.2, -0.6)
    np.testing.assert_array_equal(s.axis, axis / 3.0)
    x = np.random.default_rng(7).normal(size=(2, 4, 3)) * 5
    got = s.apply(x)
    assert got.shape == (2, 4, 3)
    np.testing.assert_allclose(got, _written_out(axis, point, 2.2, -0.6, x), rtol=0, atol=1e-14)
    # scipy's rotation vector, a second reference for R
    ref = point + Rotation.from_rotvec(2.2 * axis / 3.0).apply((x - point).reshape(-1, 3))
    np.testing.assert_allclose(got.reshape(-1, 3), ref - 0.6 * axis / 3.0, atol=1e-14)
    # the displacement it was built as: R x + t
    r, t = s.displacement()
    np.testing.assert_allclose(got, x @ r.T + t, rtol=0, atol=1e-13)


def test_the_point_kept_is_the_axis_point_nearest_the_origin() -> None:
    # The contract of Screw.point (point @ axis == 0): a point elsewhere on the line is moved
    # along it to the minimiser of |p + lam n|, lam = -(p.n)/(n.n); the motion is the same.
    from poinsot import Screw

    n, p = np.array([1.0, -2.0, 2.0]), np.array([3.0, 0.25, -4.0])
    s = Screw(n, p, 1.1, -0.3)
    want = p - (p @ n) / (n @ n) * n
    np.testing.assert_allclose(s.point, want, rtol=0, atol=4e-15)
    assert abs(s.point @ s.axis) < 4e-15
    x = np.array([-0.7, 1.3, 2.9])
    np.testing.assert_allclose(s.apply(x), _written_out(n, p, 1.1, -0.3, x), atol=1e-14)
    # negative control: a point already nearest the origin is kept bit for bit
    q = np.array([0.0, 2.0, 3.0])
    np.testing.assert_array_equal(Screw([1.0, 0, 0], q, 0.5, 0.1).point, q)


@pytest.mark.parametrize(
    ("args", "name"),
    [
        (([0.0, 0.0, 0.0], [0, 0, 0], 0.5, 0.1), "axis"),
        (([0.0, math.nan, 1.0], [0, 0, 0], 0.5, 0.1), "axis"),
        (([0.0, 0.0, 1.0, 0.0], [0, 0, 0], 0.5, 0.1), "axis"),
        (([0.0, 0.0, 1.0], [0, math.inf, 0], 0.5, 0.1), "point"),
        (([0.0, 0.0, 1.0], [0, 0], 0.5, 0.1), "point"),
        (([0.0, 0.0, 1.0], [0, 0, 0], -0.5, 0.1), "angle"),
        (([0.0, 0.0, 1.0], [0, 0, 0], 3.5, 0.1), "angle"),
        (([0.0, 0.0, 1.0], [0, 0, 0], math.nan, 0.1), "angle"),
        (([0.0, 0.0, 1.0], [0, 0, 0], [0.5, 0.6], 0.1), "angle"),
        (([0.0, 0.0, 1.0], [0, 0, 0], 0.5, math.inf), "slide"),
        (([0.0, 0.0, 1.0], [0, 0, 0], 0.5, 0.1, 0.3), "pitch"),  # slide / angle = 0.2
        (([0.0, 0.0, 1.0], [0, 0, 0], 0.5, 0.1, 0.2 * (1 + 1e-6)), "pitch"),
        (([0.0, 0.0, 1.0], [0, 0, 0], 0.5, 0.1, math.nan), "pitch"),
        (([0.0, 0.0, 1.0], [0, 0, 0], 0.0, 1.0, 1e300), "pitch"),  # a translation: inf
    ],
)
def test_each_bad_part_is_refused_by_name(args: tuple, name: str) -> None:  # type: ignore[type-arg]
    from poinsot import Screw

    with pytest.raises(PoinsotError, match=rf"^{name}: "):
        Screw(*args)


@pytest.mark.parametrize(("field", "value"), [("axis", "xyz"), ("angle", "0.5"), ("pitch", 1j)])
def test_text_and_complex_parts_are_type_errors_naming_the_part(field: str, value: object) -> None:
    from poinsot import ArgumentTypeError, Screw

    parts: dict[str, object] = {"axis": [0, 0, 1.0], "point": [0, 0, 0], "angle": 0.5}
    parts.update(slide=0.1, **{field: value})
    with pytest.raises(ArgumentTypeError, match=rf"^{field}: "):
        Screw(**parts)  # type: ignore[arg-type]


def test_the_limits_are_accepted() -> None:
    # negative controls of the refusals above
    from poinsot import Screw

    assert Screw([0, 0, 1.0], [0, 0, 0], math.pi, 0.1).angle == math.pi
    assert Screw([0, 0, 1.0], [0, 0, 0], 0.0, 2.0).pitch == math.inf  # a pure translation
    assert Screw([0, 0, 1.0], [0, 0, 0], 0.0, 0.0, 0.0).pitch == 0.0  # the identity
    assert Screw([0, 0, 1.0], [0, 0, 0], 0.5, 0.1, 0.2 * (1 + 1e-12)).pitch == 0.1 / 0.5
    assert Screw([0, 0, 1.0], [0, 0, 0], 0.5, 0.1, np.float64(0.2)).pitch == 0.2


@HYP
@given(
    angles=st.tuples(*[st.floats(-math.pi, math.pi)] * 3),
    t=st.tuples(*[st.floats(-1e6, 1e6)] * 3),
    scale=st.sampled_from([1e-8, 1.0, 1e8]),
)
def test_screw_axis_results_are_unchanged_bit_for_bit(angles, t, scale) -> None:  # type: ignore[no-untyped-def]
    # screw_axis now goes through Screw's checks: its result must be the core's, bit for bit,
    # and a Screw rebuilt from its five parts the same screw.
    from poinsot import Screw, _core

    r = euler_to_matrix(list(angles))
    tt = scale * np.array(t)
    s = screw_axis(r, tt)
    axis, point, angle, slide, pitch = _core.screw_axis(r, tt)
    np.testing.assert_array_equal(s.axis, axis)
    np.testing.assert_array_equal(s.point, point)
    assert (s.angle, s.slide, s.pitch) == (angle, slide, pitch)
    assert Screw(s.axis, s.point, s.angle, s.slide, s.pitch) == s
    assert Screw(list(s.axis), list(s.point), s.angle, s.slide) == s
