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
