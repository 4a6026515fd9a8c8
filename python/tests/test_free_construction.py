"""Poinsot's construction from the exact free-body solution (the lab's Poinsot scene): the
contact point ρ = ω/(2T)^½ lies on the inertia ellipsoid ρ·I·ρ = 1 and on the invariable plane
ρ·L̂ = (2T)^½/|L|, the ellipsoid is tangent to the plane there, and the body point at ρ is at
rest (rolling without slipping). References: the definitions evaluated with numpy, the attitude
turned into a matrix by scipy, and a central difference of the attitude."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from poinsot import FreeRigidBody
from poinsot.errors import PoinsotError
from scipy.spatial.transform import Rotation

#: T and |L| of the exact solution are conserved to ~1e-13 relative (test_free.py); the
#: contact conditions are products of O(1) numbers on top of that.
CONTACT_TOL = 1e-12


def matrices(q: np.ndarray) -> np.ndarray:
    """Rotation matrices of quaternions [w, x, y, z] (scipy is scalar-last)."""
    return Rotation.from_quat(np.roll(q, -1, axis=-1)).as_matrix()


def test_convention_contact_point_is_omega_over_root_2T_in_space_and_body() -> None:
    body = FreeRigidBody([1.0, 2.0, 3.0], [1.0, 0.1, 1.0], attitude0=[0.6, 0.0, 0.8, 0.0])
    t = np.linspace(0.0, 40.0, 81)
    s = np.sqrt(2 * body.energy)
    w, q = body.state(t)
    rho_b = body.contact_point(t, frame="body")
    rho = body.contact_point(t)
    assert rho.shape == rho_b.shape == (81, 3)
    np.testing.assert_allclose(rho_b * s, w, rtol=0, atol=1e-14 * s)
    np.testing.assert_allclose(
        rho, np.einsum("nij,nj->ni", matrices(q), rho_b), rtol=0, atol=CONTACT_TOL
    )
    np.testing.assert_allclose(rho * s, body.herpolhode(t), rtol=0, atol=1e-14 * s)
    # Broadcasting over t's shape, like the other methods.
    assert body.contact_point(t.reshape(9, 9)).shape == (9, 9, 3)
    assert body.contact_point(2.5).shape == (3,)


@settings(max_examples=60, deadline=None)
@given(
    m=st.lists(st.floats(0.3, 3.0), min_size=3, max_size=3),
    w=st.lists(st.floats(-3.0, 3.0), min_size=3, max_size=3),
    t=st.floats(0.0, 60.0),
)
def test_contact_point_is_on_the_ellipsoid_and_the_plane_and_tangent(
    m: list[float], w: list[float], t: float
) -> None:
    srt = sorted(m)
    assume(srt[0] + srt[1] >= 1.01 * srt[2] and np.linalg.norm(w) > 0.1)
    body = FreeRigidBody(m, w)
    inertia = np.diag(m)
    rho_b = body.contact_point(t, frame="body")
    rho = body.contact_point(t)
    L = body.angular_momentum
    n = body.invariable_plane_normal
    d = body.invariable_plane_distance
    np.testing.assert_allclose(n, L / np.linalg.norm(L), rtol=0, atol=1e-15)
    assert abs(rho_b @ inertia @ rho_b - 1) < CONTACT_TOL
    assert abs(rho @ n - d) < CONTACT_TOL * max(1.0, d)
    # Tangency: the ellipsoid's normal at ρ, R·I·ρ, is along L.
    normal = matrices(body.attitude(t)) @ (inertia @ rho_b)
    assert np.linalg.norm(np.cross(normal, n)) < CONTACT_TOL * np.linalg.norm(normal)


def test_the_ellipsoid_rolls_without_slipping() -> None:
    body = FreeRigidBody([1.0, 2.0, 3.0], [0.4, 1.5, 0.3])
    h = 1e-4
    for t in np.linspace(0.0, 25.0, 11):
        rho_b = body.contact_point(t, frame="body")
        rp, rm = matrices(body.attitude(np.array([t + h, t - h])))
        v = (rp - rm) @ rho_b / (2 * h)
        off = rho_b + np.array([0.0, 0.0, 0.5])
        assert np.linalg.norm(v) < 1e-6
        assert np.linalg.norm((rp - rm) @ off / (2 * h)) > 0.1  # negative control: it moves


def test_contact_polhode_is_the_scaled_polhode_on_the_ellipsoid() -> None:
    body = FreeRigidBody([1.0, 2.0, 3.0], [0.05, 1.0, 0.05])
    p = body.contact_polhode(101)
    np.testing.assert_allclose(p * np.sqrt(2 * body.energy), body.polhode(101), rtol=0, atol=1e-13)
    np.testing.assert_allclose(
        np.einsum("ni,i,ni->n", p, [1.0, 2.0, 3.0], p), 1.0, rtol=0, atol=CONTACT_TOL
    )
    np.testing.assert_allclose(p[0], p[-1], atol=1e-12)  # one period: closed


def test_bad_input_names_the_argument() -> None:
    body = FreeRigidBody([1.0, 2.0, 3.0], [0.3, 1.0, 0.2])
    with pytest.raises(PoinsotError, match="^frame: "):
        body.contact_point(1.0, frame="inertial")
    with pytest.raises(PoinsotError, match="^t: "):
        body.contact_point([0.0, np.nan])
    with pytest.raises(PoinsotError, match="^samples: "):
        body.contact_polhode(1)
