"""``FreeRigidBody.max_time`` and ``FreeSymmetricTop.max_time`` (issue 21, item 14: documented in
docs/dynamics.md, missing from the API): the largest |t| the closed forms follow, 2⁴² rad at the
fastest rate of the motion, against that rate written out; a time just inside computes, one just
outside is refused naming ``t``."""

from __future__ import annotations

import math

import numpy as np
import poinsot as ps
import pytest

PHASE_LIMIT = 2.0**42  # rad (docs/dynamics.md, "Time")


def test_steady_rotation_max_time_is_the_phase_limit_over_omega() -> None:
    # Steady rotation about the major axis at |omega| = 2 rad/s: the one rate is |omega|.
    body = ps.FreeRigidBody([1.0, 2.0, 3.0], [0.0, 0.0, 2.0])
    assert body.regime == "steady"
    assert body.max_time == PHASE_LIMIT / 2.0  # powers of two: exact


def test_symmetric_top_max_time_is_the_phase_limit_over_its_fastest_rate() -> None:
    # Rates (2.83): the body precession Omega = (I1 - I3) w3 / I1, and |L| / I1 in space.
    i1, i3, w = 1.0, 2.0, np.array([0.3, 0.0, 1.0])
    big_omega = (i1 - i3) * w[2] / i1
    l_over_i1 = math.hypot(i1 * math.hypot(w[0], w[1]), i3 * w[2]) / i1
    top = ps.FreeSymmetricTop(i1, i3, w)
    assert top.max_time == pytest.approx(PHASE_LIMIT / max(abs(big_omega), l_over_i1), rel=4e-16)
    # negative control: the slower rate would give a later limit
    assert top.max_time < PHASE_LIMIT / abs(big_omega) * (1 - 1e-3)


def test_the_documented_figure() -> None:
    # docs/dynamics.md: 1.39e12 s for I = (1, 2, 3), omega0 = (1, 0.1, 1).
    assert f"{ps.FreeRigidBody([1.0, 2.0, 3.0], [1.0, 0.1, 1.0]).max_time:.3g}" == "1.39e+12"


@pytest.mark.parametrize(
    "make",
    [
        lambda: ps.FreeRigidBody([1.0, 2.0, 3.0], [1.0, 0.1, 1.0]),
        lambda: ps.FreeRigidBody([1.0, 2.0, 2.0], [0.4, 0.1, 1.0]),
        lambda: ps.FreeSymmetricTop(1.0, 2.0, [0.3, 0.0, 1.0]),
    ],
    ids=["asymmetric", "symmetric body", "symmetric top"],
)
def test_just_inside_computes_and_just_outside_is_refused_naming_t(make) -> None:  # type: ignore[no-untyped-def]
    obj = make()
    tmax = obj.max_time
    assert math.isfinite(tmax) and tmax > 0
    inside = np.array([-tmax, np.nextafter(tmax, 0.0), tmax])
    outside = [np.nextafter(tmax, np.inf), -np.nextafter(tmax, np.inf), tmax * (1 + 1e-9)]
    evaluate = obj.state if isinstance(obj, ps.FreeRigidBody) else obj.attitude
    result = evaluate(inside)
    for part in result if isinstance(result, tuple) else (result,):
        assert np.all(np.isfinite(part))
    for t in outside:
        with pytest.raises(ps.PoinsotError, match=r"^t: "):
            evaluate(t)
        with pytest.raises(ps.PoinsotError, match=r"^t: "):
            obj.omega(t)


def test_a_body_that_never_turns_that_far_has_no_limit() -> None:
    # omega0 ~ 1e-300 rad/s: 2^42 rad would take ~4e312 s, beyond the doubles; documented inf.
    body = ps.FreeRigidBody([1.0, 2.0, 3.0], [0.0, 0.0, 1e-300])
    assert body.max_time == math.inf
    assert np.all(np.isfinite(body.omega(1e300)))
