"""The errata of the unit's Euler equations and torque-free motion (seed-errata.md), each pinned
by its corrected result, and the unit's sign convention of Ω."""

from __future__ import annotations

import numpy as np
import pytest
from poinsot import FreeRigidBody, FreeSymmetricTop, simulate

I123 = np.array([1.0, 2.0, 3.0])
W0 = np.array([1.0, 0.1, 1.0])


def euler_rhs(moments, w):
    """ω̇ from Euler's equations 2.72 (torque-free), written out independently of the core."""
    i1, i2, i3 = moments
    return np.array(
        [(i2 - i3) * w[1] * w[2] / i1, (i3 - i1) * w[2] * w[0] / i2, (i1 - i2) * w[0] * w[1] / i3]
    )


def test_erratum_2_70_body_rate_of_l_is_i_dot_omega_dot():
    # (dL/dt)_rot = I·ω̇ (the unit prints I·ω, a lost dot): along the exact motion the body
    # components of L = I·ω change at I·ω̇ — and not at I·ω.
    body = FreeRigidBody(I123, W0)
    t, h = 0.8, 1e-5
    dl = (body.angular_momentum_body(t + h) - body.angular_momentum_body(t - h)) / (2 * h)
    w = body.omega(t)
    np.testing.assert_allclose(dl, I123 * euler_rhs(I123, w), atol=1e-8)
    assert np.linalg.norm(dl - I123 * w) > 0.1
    # And 2.71 follows: in space L is constant although its body components turn.
    tr = simulate(I123, W0, 10.0, samples=11)
    np.testing.assert_allclose(
        tr.angular_momentum, np.tile(tr.angular_momentum[0], (11, 1)), atol=1e-12
    )


def test_erratum_2_73_74_torque_free_omega_is_not_parallel_to_l():
    # The unit concludes ω ∥ L for torque-free motion; that holds only for steady rotation about
    # a principal axis. In general L is fixed and ω is not parallel to it (the cones 2.90–2.97).
    body = FreeRigidBody(I123, W0)
    ell = body.angular_momentum
    ws = body.herpolhode(np.linspace(0, 5, 11))
    sin_angle = np.linalg.norm(np.cross(ws, ell), axis=1) / (
        np.linalg.norm(ws, axis=1) * np.linalg.norm(ell)
    )
    assert sin_angle.min() > 0.05
    assert np.linalg.norm(ws[5] - ws[0]) > 0.1  # ω moves in space, L does not
    # The exception: steady rotation about a principal axis, where ω ∥ L indeed.
    steady = FreeRigidBody(I123, [0.0, 0.0, 2.0])
    assert np.linalg.norm(np.cross(steady.herpolhode(3.0), steady.angular_momentum)) < 1e-15
    # For the symmetric top the angle between ω and L is the space cone's half-angle, not 0.
    top = FreeSymmetricTop(2.0, 1.0, [0.3, 0.4, 2.0])
    assert top.space_cone_angle > 0.05


def test_erratum_2_78_omega2_dot_is_minus_big_omega_omega1():
    # The unit's 2.78 reads I₂ω̇₂ = (I₁ − I₃) ω₃ω₁; Euler's equation gives I₁ω̇₂ = (I₃ − I₁) ω₃ω₁,
    # i.e. ω̇₂ = −Ω ω₁ as 2.82 says.
    i1, i3 = 2.0, 1.0
    top = FreeSymmetricTop(i1, i3, [0.3, 0.4, 2.0])
    big = top.precession_rate
    for t in (0.0, 0.37, 5.0):
        w = top.omega(t)
        wd = euler_rhs([i1, i1, i3], w)
        assert wd[1] == pytest.approx(-big * w[0], abs=1e-15)
        assert wd[0] == pytest.approx(big * w[1], abs=1e-15)
        assert wd[1] != pytest.approx((i1 - i3) * w[2] * w[0] / i1, abs=1e-3)  # the misprint


def test_erratum_2_84_omega1_double_dot_is_minus_big_omega_squared_omega1():
    # ω̈₁ = Ω ω̇₂ = −Ω² ω₁ (the unit's middle step drops the minus sign): harmonic, not growing.
    top = FreeSymmetricTop(2.0, 1.0, [0.3, 0.4, 2.0])
    big, t, h = top.precession_rate, 0.37, 1e-4
    w1 = top.omega(np.array([t - h, t, t + h]))[:, 0]
    w1dd = (w1[0] - 2 * w1[1] + w1[2]) / h**2
    assert w1dd == pytest.approx(-(big**2) * w1[1], rel=1e-6)
    assert np.abs(top.omega(np.linspace(0, 100, 1001))[:, 0]).max() <= top.amplitude * (1 + 1e-15)


def test_convention_unit_sign_of_big_omega():
    # The unit's Ω = (I₁ − I₃) ω₃ / I₁ with ω̇₁ = Ω ω₂: for a prolate top (I₁ > I₃) Ω has the
    # sense of ω₃, and ω₁ + iω₂ turns as e^{−iΩt} (Goldstein's Ω has the opposite sign).
    top = FreeSymmetricTop(2.0, 1.0, [1.0, 0.0, 2.0])
    assert top.precession_rate == pytest.approx(1.0)
    w = top.omega(0.1)
    assert w[1] < 0  # ω₂ = A cos(Ωt + θ₀) with θ₀ = π/2: ω₂ = −A sin(Ωt)
    np.testing.assert_allclose(w[0] + 1j * w[1], np.exp(-1j * 0.1), atol=1e-15)
