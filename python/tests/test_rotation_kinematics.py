"""Kinematics of Euler angles (the unit's eqs. 2.98-2.101): the unit's 2.99 against a sympy
derivation, all 24 conventions against finite differences of R(t), the inverse, gimbal lock."""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from poinsot import (
    EULER_SEQUENCES,
    GimbalLockError,
    PoinsotError,
    body_angular_velocity,
    euler_rates,
    euler_to_matrix,
    space_angular_velocity,
)

CONVENTIONS = [(s, i) for s in EULER_SEQUENCES for i in (True, False)]
# Central differences, step H: truncation H^2/6 |R'''| ~ 1e-11 for rates <= 3 rad/s, round-off
# eps/H ~ 1e-11.
H = 1e-5
FD_TOL = 1e-8
HYP = settings(max_examples=100, derandomize=True, deadline=None)


def unskew(w: np.ndarray) -> np.ndarray:
    return np.array([w[2, 1], w[0, 2], w[1, 0]])


@functools.cache
def sympy_zxz() -> tuple[sp.Expr, ...]:
    """Body and space angular velocity of R = R_z(phi) R_x(theta) R_z(psi), derived by sympy:
    skew(omega_body) = R^T dR/dt, skew(omega_space) = dR/dt R^T, simplified."""
    t = sp.symbols("t")
    phi, theta, psi = (sp.Function(n)(t) for n in ("phi", "theta", "psi"))
    rz = lambda a: sp.Matrix([[sp.cos(a), -sp.sin(a), 0], [sp.sin(a), sp.cos(a), 0], [0, 0, 1]])
    rx = lambda a: sp.Matrix([[1, 0, 0], [0, sp.cos(a), -sp.sin(a)], [0, sp.sin(a), sp.cos(a)]])
    r = rz(phi) * rx(theta) * rz(psi)
    rdot = r.diff(t)
    wb = sp.simplify(r.T * rdot)
    ws = sp.simplify(rdot * r.T)
    syms = sp.symbols("phi theta psi dphi dtheta dpsi")
    subs = {
        phi.diff(t): syms[3], theta.diff(t): syms[4], psi.diff(t): syms[5],
        phi: syms[0], theta: syms[1], psi: syms[2],
    }  # fmt: skip
    body = [sp.simplify(wb[i, j].subs(subs)) for i, j in ((2, 1), (0, 2), (1, 0))]
    space = [sp.simplify(ws[i, j].subs(subs)) for i, j in ((2, 1), (0, 2), (1, 0))]
    return (*syms, *body, *space)


def test_unit_eq_2_99_matches_sympy_symbolically() -> None:
    """The sympy derivation reduces to the unit's 2.99 (with its erratum omega_3 = omega_zeta):
    omega_1 = phidot sin(theta) sin(psi) + thetadot cos(psi), omega_2 = phidot sin(theta) cos(psi)
    - thetadot sin(psi), omega_3 = phidot cos(theta) + psidot."""
    _phi, theta, psi, dphi, dtheta, dpsi, *rest = sympy_zxz()
    body = rest[:3]
    eq_299 = [
        dphi * sp.sin(theta) * sp.sin(psi) + dtheta * sp.cos(psi),
        dphi * sp.sin(theta) * sp.cos(psi) - dtheta * sp.sin(psi),
        dphi * sp.cos(theta) + dpsi,
    ]
    for got, want in zip(body, eq_299):
        assert sp.simplify(got - want) == 0


@HYP
@given(
    a=st.tuples(*[st.floats(-math.pi, math.pi, allow_nan=False)] * 3),
    d=st.tuples(*[st.floats(-5, 5, allow_nan=False)] * 3),
)
def test_body_and_space_omega_match_sympy_numerically(a, d) -> None:  # type: ignore[no-untyped-def]
    *syms, b1, b2, b3, s1, s2, s3 = sympy_zxz()
    f = sp.lambdify(syms, [b1, b2, b3, s1, s2, s3], "math")
    ref = np.array(f(*a, *d))
    np.testing.assert_allclose(body_angular_velocity(a, d), ref[:3], atol=1e-13)
    np.testing.assert_allclose(space_angular_velocity(a, d), ref[3:], atol=1e-13)


def test_unit_eq_2_101_symmetric_top_energy() -> None:
    """2.100 with I1 = I2 is 2.101: T = I1/2 (thetadot^2 + phidot^2 sin^2 theta)
    + I3/2 (psidot + phidot cos theta)^2."""
    i1, i3 = 2.0, 0.7
    rng = np.random.default_rng(9)
    for _ in range(20):
        (phi, theta, psi), (dphi, dtheta, dpsi) = rng.uniform(-3, 3, (2, 3))
        w = body_angular_velocity([phi, theta, psi], [dphi, dtheta, dpsi])
        t_200 = 0.5 * (i1 * w[0] ** 2 + i1 * w[1] ** 2 + i3 * w[2] ** 2)
        t_201 = (
            0.5 * i1 * (dtheta**2 + dphi**2 * math.sin(theta) ** 2)
            + 0.5 * i3 * (dpsi + dphi * math.cos(theta)) ** 2
        )
        assert t_200 == pytest.approx(t_201, rel=1e-14)


def test_unit_eq_2_98_line_of_nodes_components() -> None:
    """2.98: along (xi, eta, zeta) = R_z(phi) R_x(theta) axes, omega = (thetadot,
    phidot sin(theta), psidot + phidot cos(theta))."""
    phi, theta, psi, dphi, dtheta, dpsi = 0.3, 1.2, -0.4, 0.9, -1.1, 2.5
    w_space = space_angular_velocity([phi, theta, psi], [dphi, dtheta, dpsi])
    r_nodes = euler_to_matrix([phi, theta, 0.0])
    np.testing.assert_allclose(
        r_nodes.T @ w_space,
        [dtheta, dphi * math.sin(theta), dpsi + dphi * math.cos(theta)],
        atol=1e-14,
    )


@pytest.mark.parametrize(("seq", "intrinsic"), CONVENTIONS)
def test_kinematics_against_finite_differences(seq: str, intrinsic: bool) -> None:
    """skew(omega_space) = Rdot R^T and skew(omega_body) = R^T Rdot, Rdot by central
    differences of R(angles + t * rates), for all 24 conventions."""
    rng = np.random.default_rng(2 * EULER_SEQUENCES.index(seq) + intrinsic)
    n = 50
    a = rng.uniform(-math.pi, math.pi, (n, 3))
    if seq[0] == seq[2]:
        a[:, 1] = rng.uniform(0.1, math.pi - 0.1, n)
    else:
        a[:, 1] = rng.uniform(-math.pi / 2 + 0.1, math.pi / 2 - 0.1, n)
    d = rng.uniform(-3, 3, (n, 3))
    r = euler_to_matrix(a, seq, intrinsic=intrinsic)
    rdot = (
        euler_to_matrix(a + H * d, seq, intrinsic=intrinsic)
        - euler_to_matrix(a - H * d, seq, intrinsic=intrinsic)
    ) / (2 * H)
    wb = body_angular_velocity(a, d, seq, intrinsic=intrinsic)
    ws = space_angular_velocity(a, d, seq, intrinsic=intrinsic)
    for k in range(n):
        np.testing.assert_allclose(unskew(r[k].T @ rdot[k]), wb[k], atol=FD_TOL)
        np.testing.assert_allclose(unskew(rdot[k] @ r[k].T), ws[k], atol=FD_TOL)
    np.testing.assert_allclose(np.einsum("nij,nj->ni", r, wb), ws, atol=1e-13)
    # The inverse, both frames (conditioning 1/|sin beta| <= 10).
    np.testing.assert_allclose(euler_rates(a, wb, seq, intrinsic=intrinsic), d, atol=1e-12)
    np.testing.assert_allclose(
        euler_rates(a, ws, seq, intrinsic=intrinsic, frame="space"), d, atol=1e-12
    )


def test_degrees_apply_to_angles_and_rates_not_omega() -> None:
    a, d = np.array([30.0, 60.0, -45.0]), np.array([10.0, -20.0, 5.0])
    w = body_angular_velocity(a, d, degrees=True)
    np.testing.assert_allclose(w, body_angular_velocity(np.radians(a), np.radians(d)), atol=1e-15)
    np.testing.assert_allclose(euler_rates(a, w, degrees=True), d, atol=1e-12)


def test_broadcasting() -> None:
    a = np.zeros((4, 1, 3)) + [0.1, 0.9, 0.2]
    d = np.ones((5, 3))
    assert body_angular_velocity(a, d).shape == (4, 5, 3)
    assert euler_rates(a, d, frame="space").shape == (4, 5, 3)


@pytest.mark.parametrize(("seq", "intrinsic"), CONVENTIONS)
@pytest.mark.parametrize("frame", ["body", "space"])
def test_euler_rates_raise_gimbal_lock(seq: str, intrinsic: bool, frame: str) -> None:
    betas = (0.0, math.pi) if seq[0] == seq[2] else (math.pi / 2, -math.pi / 2)
    for beta in betas:
        with pytest.raises(GimbalLockError, match=r"^angles: .*gimbal lock.*angles\[1\]"):
            euler_rates([0.3, beta, -0.2], [0.1, 0.2, 0.3], seq, intrinsic=intrinsic, frame=frame)
        # A batch names the first singular record.
        a = np.array([[0.3, beta + 0.5, -0.2], [0.3, beta, -0.2]])
        with pytest.raises(GimbalLockError, match=r"flat index 1"):
            euler_rates(a, np.ones((2, 3)), seq, intrinsic=intrinsic, frame=frame)
    # The forward map is defined at the lock.
    assert np.all(np.isfinite(body_angular_velocity([0.3, betas[0], 0.2], [1, 2, 3], seq)))


def test_gimbal_lock_error_is_a_value_error() -> None:
    with pytest.raises(ValueError, match=r"^angles: "):
        euler_rates([0.0, 0.0, 0.0], [1.0, 0.0, 0.0])


@pytest.mark.parametrize(
    ("call", "pattern"),
    [
        (lambda: body_angular_velocity([0.1, math.nan, 0.0], [1, 2, 3]), r"^angles: .*finite"),
        (lambda: body_angular_velocity([0.1, 0.2, 0.0], [1, math.inf, 3]), r"^rates: .*finite"),
        (lambda: space_angular_velocity([0.1, 0.2], [1, 2, 3]), r"^angles: .*shape"),
        (lambda: body_angular_velocity(np.zeros((2, 3)), np.zeros((3, 3))), r"^rates: .*broadcast"),
        (lambda: euler_rates([0.1, 0.2, 0.3], [1, math.nan, 3]), r"^omega_body: .*finite"),
        (lambda: euler_rates([0.1, 0.2, 0.3], [1, 2, 3], frame="world"), r"^frame: "),
        (lambda: euler_rates([0.1, 0.2, 0.3], [1, 2, 3], "ZYX"), r"^seq: .*intrinsic"),
        (lambda: body_angular_velocity([0.1, 0.2, 0.3], [1, 2, 3], "zzy"), r"^seq: "),
    ],
)
def test_bad_input_is_named(call, pattern) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(PoinsotError, match=pattern):
        call()
