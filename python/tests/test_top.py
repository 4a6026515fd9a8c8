"""poinsot.HeavyTop: the public contract, the unit's formulas (errata fixed) against the exact
roots, 2.113 against sympy, conservation along the exact solution, scipy cross-checks, bad input."""

from __future__ import annotations

import math

import numpy as np
import poinsot as ps
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from poinsot import HeavyTop
from scipy.integrate import solve_ivp

# Round-off of O(1) quantities after a few dozen operations.
ROUND_OFF = 1e-12
# solve_ivp (DOP853, rtol = atol = 1e-12) over ~10 s of a top: global error ≲ 1e-10.
SCIPY_TOL = 1e-8


def _constants(i1: float, i3: float, mgl: float, theta, theta_dot, phi_dot, psi_dot):
    """p_phi, p_psi, E from 2.103–2.105, written out here independently of poinsot."""
    s, c = np.sin(theta), np.cos(theta)
    w3 = psi_dot + phi_dot * c
    p_psi = i3 * w3
    p_phi = i1 * phi_dot * s**2 + p_psi * c
    e = 0.5 * i1 * (theta_dot**2 + phi_dot**2 * s**2) + 0.5 * i3 * w3**2 + mgl * c
    return p_phi, p_psi, e


# ---- the contract -------------------------------------------------------------------------


def test_contract_attributes_and_shapes() -> None:
    top = HeavyTop(1.0, 0.5, 1.0, 0.8, theta_dot=0.3, phi_dot=0.6, psi_dot=6.0)
    p_phi, p_psi, e = _constants(1.0, 0.5, 1.0, 0.8, 0.3, 0.6, 6.0)
    assert top.p_phi == pytest.approx(p_phi, abs=ROUND_OFF)
    assert top.p_psi == pytest.approx(p_psi, abs=ROUND_OFF)
    assert top.energy == pytest.approx(e, abs=ROUND_OFF)
    assert top.reduced_energy == pytest.approx(e - p_psi**2 / (2 * 0.5), abs=ROUND_OFF)
    t1, t2 = top.turning_points
    assert 0 < t1 < 0.8 < t2 < np.pi
    assert top.motion_class in ps.MOTION_CLASSES
    assert top.nutation_period > 0
    # Scalars in, floats out; arrays keep their shape.
    phi, theta, psi = top.euler_angles(1.5)
    assert all(isinstance(x, float) for x in (phi, theta, psi))
    t = np.linspace(0, 5, 12).reshape(3, 4)
    angles = top.euler_angles(t)
    rates = top.euler_rates(t)
    assert all(a.shape == (3, 4) for a in (*angles, *rates))
    assert top.attitude(t).shape == (3, 4, 3, 3)
    assert top.symmetry_axis(t).shape == (3, 4, 3)
    # The initial state is reproduced at t = 0.
    assert top.euler_angles(0.0) == pytest.approx((0.0, 0.8, 0.0), abs=1e-14)
    assert top.euler_rates(0.0) == pytest.approx((0.6, 0.3, 6.0), abs=1e-12)
    assert "loops" in repr(top)


def test_degrees_flag() -> None:
    a = HeavyTop(1.0, 0.5, 1.0, 45.0, phi_dot=10.0, psi_dot=300.0, degrees=True)
    b = HeavyTop(1.0, 0.5, 1.0, np.pi / 4, phi_dot=np.radians(10.0), psi_dot=np.radians(300.0))
    assert a.turning_points == pytest.approx(b.turning_points, abs=1e-14)
    deg = a.euler_angles(2.0, degrees=True)
    rad = b.euler_angles(2.0)
    assert deg == pytest.approx(tuple(np.degrees(rad)), rel=1e-12)
    assert a.effective_potential(45.0, degrees=True) == pytest.approx(
        b.effective_potential(np.pi / 4)
    )
    assert HeavyTop.min_spin(1, 0.5, 1, 30, degrees=True) == pytest.approx(
        HeavyTop.min_spin(1, 0.5, 1, np.pi / 6)
    )


@pytest.mark.parametrize("method", ["euler_angles", "euler_rates"])
@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
def test_a_non_finite_time_is_refused_by_the_core_naming_its_index(method, bad) -> None:
    """The core checks the times (Python passes them on unchecked): the error names ``t``, the
    value and its index, in any shape; a finite array beside it is accepted (control)."""
    top = HeavyTop(1.0, 0.5, 1.0, 0.8, psi_dot=6.0)
    t = np.array([[0.0, 1.0], [2.0, bad]])
    with pytest.raises(
        ps.PoinsotError, match=r"^t: must be finite, got (NaN|inf|-inf) at index 3$"
    ):
        getattr(top, method)(t)
    values = getattr(top, method)(np.nan_to_num(t, nan=3.0, posinf=3.0, neginf=3.0))
    assert all(v.shape == (2, 2) and np.all(np.isfinite(v)) for v in values)


def test_symmetry_axis_is_the_third_column_of_the_zxz_attitude() -> None:
    """Convention pin: body axis 3 in space = (sin θ sin φ, −sin θ cos φ, cos θ) for R = Rz(φ)Rx(θ)Rz(ψ)."""
    top = HeavyTop(1.0, 0.5, 1.0, 0.8, phi=0.3, psi=1.1, phi_dot=-0.5, psi_dot=6.0)
    t = np.linspace(0, 4, 9)
    phi, theta, _ = top.euler_angles(t)
    expect = np.stack(
        [np.sin(theta) * np.sin(phi), -np.sin(theta) * np.cos(phi), np.cos(theta)], axis=-1
    )
    assert np.max(np.abs(top.symmetry_axis(t) - expect)) < 1e-14


# ---- errata --------------------------------------------------------------------------------


def test_erratum_2_120_fast_rate_is_p_psi_over_I1_cos_theta0() -> None:
    """seed-errata.md: I1 = 1, I3 = 0.5, mgl = 0.3, omega3 = 40, theta0 = 0.6: the exact fast root is
    24.2176 and p_psi/(I1 cos theta0) = 24.2326; the unit's printed p_psi/(2 I1 cos theta0) is half."""
    slow, fast = HeavyTop.steady_precession_rates(1.0, 0.5, 0.3, 0.6, 40.0)
    s = HeavyTop.steady_precession(1.0, 0.5, 0.3, 0.6, 40.0)
    assert round(fast, 4) == 24.2176
    assert round(s.fast_approx, 4) == 24.2326
    assert s.fast_approx == pytest.approx(0.5 * 40.0 / math.cos(0.6))
    assert s.fast_approx_as_printed == pytest.approx(s.fast_approx / 2)
    assert abs(s.fast_approx_as_printed / fast - 0.5) < 1e-3
    assert slow == pytest.approx(0.3 / 20.0, rel=1e-3)  # 2.121


def test_erratum_2_117_square_root_holds_p_psi_squared() -> None:
    """2.117 from sympy: solving 2.116 for b gives 1 ± sqrt(1 − 4 mgl I1 cos θ0 / p_psi²), and a top
    started at either root does not nutate; the unit's p_phi² version gives a nutating top."""
    b, c, s2, pp, mgl, i1 = sp.symbols("b c s2 p_psi mgl I1", positive=True)
    roots = sp.solve(sp.Eq(b**2 * c - b * pp * s2 + mgl * i1 * s2**2, 0), b)
    disc = sp.simplify(sp.expand((2 * c * roots[0] / (pp * s2) - 1) ** 2))
    assert sp.simplify(disc - (1 - 4 * mgl * i1 * c / pp**2)) == 0
    i1v, i3v, mglv, th0, w3 = 1.0, 0.5, 1.0, 0.8, 6.0
    for rate in HeavyTop.steady_precession_rates(i1v, i3v, mglv, th0, w3):
        top = HeavyTop(i1v, i3v, mglv, th0, phi_dot=rate, psi_dot=w3 - rate * math.cos(th0))
        t1, t2 = top.turning_points
        assert top.motion_class == "steady precession" and t2 - t1 < 1e-12
        p_phi = top.p_phi
        bad = (
            0.5
            * top.p_psi
            * math.sin(th0) ** 2
            / math.cos(th0)
            * (
                1
                + (1 if rate > 1 else -1) * math.sqrt(1 - 4 * mglv * i1v * math.cos(th0) / p_phi**2)
            )
        )
        rate_bad = bad / (i1v * math.sin(th0) ** 2)
        top_bad = HeavyTop(
            i1v, i3v, mglv, th0, phi_dot=rate_bad, psi_dot=w3 - rate_bad * math.cos(th0)
        )
        u1, u2 = top_bad.turning_points
        assert u2 - u1 > 1e-3


def test_minimum_spin_2_119_is_where_the_rates_merge() -> None:
    w_min = HeavyTop.min_spin(1.0, 0.5, 1.0, 0.8)
    assert w_min == pytest.approx(2 / 0.5 * math.sqrt(1.0 * 1.0 * math.cos(0.8)))
    slow, fast = HeavyTop.steady_precession_rates(1.0, 0.5, 1.0, 0.8, w_min * (1 + 1e-12))
    assert slow == pytest.approx(fast, rel=1e-5)
    with pytest.raises(ps.PoinsotError, match="omega3.*2.119"):
        HeavyTop.steady_precession_rates(1.0, 0.5, 1.0, 0.8, 0.99 * w_min)
    assert HeavyTop.min_spin(1.0, 0.5, 1.0, 2.0) == 0.0
    assert HeavyTop.sleeping_threshold(1.0, 0.5, 1.0) == pytest.approx(
        HeavyTop.min_spin(1.0, 0.5, 1.0, 0.0)
    )


# ---- 2.110 and 2.113 against sympy ----------------------------------------------------------


def test_effective_potential_and_its_derivative_match_sympy() -> None:
    th, p1, p2, i1, mgl = sp.symbols("theta p_phi p_psi I1 mgl")
    v = (p1 - p2 * sp.cos(th)) ** 2 / (2 * i1 * sp.sin(th) ** 2) + mgl * sp.cos(th)  # 2.110
    dv = sp.lambdify((th, p1, p2, i1, mgl), sp.diff(v, th))
    vf = sp.lambdify((th, p1, p2, i1, mgl), v)
    unit_2_113 = sp.lambdify(
        (th, p1, p2, i1, mgl),
        (p1 - p2 * sp.cos(th)) * (p2 - p1 * sp.cos(th)) / (i1 * sp.sin(th) ** 3) - mgl * sp.sin(th),
    )
    for args in [(0.8, 0.0, 0.0, 6.0), (2.4, 0.1, 0.7, 3.0), (0.05, -0.2, 3.0, 10.0)]:
        top = HeavyTop(1.3, 0.6, 0.9, args[0], theta_dot=args[1], phi_dot=args[2], psi_dot=args[3])
        grid = np.linspace(0.05, np.pi - 0.05, 50)
        got_v = top.effective_potential(grid)
        got_d = top.effective_potential_derivative(grid)
        ref = (top.p_phi, top.p_psi, 1.3, 0.9)
        assert np.allclose(got_v, vf(grid, *ref), rtol=1e-12, atol=1e-12)
        assert np.allclose(got_d, dv(grid, *ref), rtol=1e-10, atol=1e-10)
        assert np.allclose(got_d, unit_2_113(grid, *ref), rtol=1e-10, atol=1e-10)
    # Lagrangian 2.102 against its definition.
    lag = HeavyTop.lagrangian(1.3, 0.6, 0.9, 0.7, 0.2, 0.4, 5.0)
    t = (
        0.5 * 1.3 * (0.2**2 + 0.4**2 * math.sin(0.7) ** 2)
        + 0.5 * 0.6 * (5.0 + 0.4 * math.cos(0.7)) ** 2
    )
    assert lag == pytest.approx(t - 0.9 * math.cos(0.7), abs=ROUND_OFF)


# ---- the exact motion ---------------------------------------------------------------------


def _lagrange_rhs(i1: float, i3: float, mgl: float):
    """Euler-Lagrange equations of 2.102 in (theta, phi, psi, theta', phi', psi')."""

    def rhs(_t, y):
        th, _ph, _ps, thd, phd, psd = y
        s, c = math.sin(th), math.cos(th)
        w3 = psd + phd * c
        thdd = (i1 * phd**2 * s * c - i3 * w3 * phd * s + mgl * s) / i1
        phdd = thd * (i3 * w3 - 2 * i1 * phd * c) / (i1 * s)
        return [thd, phd, psd, thdd, phdd, -phdd * c + phd * thd * s]

    return rhs


@pytest.mark.parametrize(
    "state",
    [
        (0.8, 0.0, 0.0, 6.0),
        (0.8, 0.0, -0.5, 6.0),
        (0.8, 0.3, 0.6, 6.0),
        (2.5, 0.5, 0.3, 2.0),
        (0.05, 0.01, 0.5, 9.0),
    ],
)
def test_exact_angles_match_scipy_on_the_lagrangian(state) -> None:
    i1, i3, mgl = 1.0, 0.5, 1.0
    th0, thd0, phd0, psd0 = state
    top = HeavyTop(i1, i3, mgl, th0, theta_dot=thd0, phi_dot=phd0, psi_dot=psd0)
    t = np.linspace(0, 10, 41)
    sol = solve_ivp(
        _lagrange_rhs(i1, i3, mgl),
        (0, 10),
        [th0, 0, 0, thd0, phd0, psd0],
        method="DOP853",
        rtol=1e-12,
        atol=1e-12,
        t_eval=t,
    )
    phi, theta, psi = top.euler_angles(t)
    for got, ref in ((phi, sol.y[1]), (theta, sol.y[0]), (psi, sol.y[2])):
        assert np.max(np.abs(got - ref)) < SCIPY_TOL
    phid, thd, psid = top.euler_rates(t)
    for got, ref in ((phid, sol.y[4]), (thd, sol.y[3]), (psid, sol.y[5])):
        assert np.max(np.abs(got - ref)) < SCIPY_TOL


@settings(max_examples=40, deadline=None)
@given(
    i3=st.floats(0.1, 2.0),
    mgl=st.floats(0.0, 3.0),
    th0=st.floats(0.02, 3.12),
    thd=st.floats(-2, 2),
    phd=st.floats(-3, 3),
    w3=st.floats(-20, 20),
)
def test_constants_are_conserved_along_the_exact_solution(i3, mgl, th0, thd, phd, w3) -> None:
    i1 = 1.0
    top = HeavyTop(i1, i3, mgl, th0, theta_dot=thd, phi_dot=phd, psi_dot=w3 - phd * math.cos(th0))
    t = np.linspace(0, 15, 31)
    _, theta, _ = top.euler_angles(t)
    phid, thetad, psid = top.euler_rates(t)
    p_phi, p_psi, e = _constants(i1, i3, mgl, theta, thetad, phid, psid)
    scale = 1 + abs(top.p_phi) + abs(top.p_psi)
    assert np.max(np.abs(p_phi - top.p_phi)) < 1e-10 * scale
    assert np.max(np.abs(p_psi - top.p_psi)) < 1e-10 * scale
    assert np.max(np.abs(e - top.energy)) < 1e-10 * (1 + abs(top.energy))
    t1, t2 = top.turning_points
    assert np.all((theta >= t1 - 1e-12) & (theta <= t2 + 1e-12))


def test_from_constants_matches_the_state_constructor() -> None:
    a = HeavyTop(1.0, 0.5, 1.0, 0.8, theta_dot=0.3, phi_dot=0.6, psi_dot=6.0)
    b = HeavyTop.from_constants(1.0, 0.5, 1.0, a.p_phi, a.p_psi, a.energy)
    assert b.turning_points == pytest.approx(a.turning_points, abs=1e-12)
    assert b.motion_class == a.motion_class
    assert b.euler_angles(0.0)[1] == pytest.approx(a.turning_points[0], abs=1e-15)
    with pytest.raises(ps.PoinsotError, match="^energy:"):
        HeavyTop.from_constants(1.0, 0.5, 1.0, a.p_phi, a.p_psi, a.energy - 5.0)


def test_sleeping_top_threshold_and_classes() -> None:
    thr = HeavyTop.sleeping_threshold(1.0, 0.5, 1.0)
    up = HeavyTop(1.0, 0.5, 1.0, 0.0, psi_dot=1.01 * thr)
    down = HeavyTop(1.0, 0.5, 1.0, 0.0, psi_dot=0.99 * thr)
    assert up.motion_class == down.motion_class == "sleeping"
    assert up.is_sleeping_stable and not down.is_sleeping_stable
    assert math.isfinite(up.nutation_period) and down.nutation_period == math.inf
    # Slightly tipped: bounded near the vertical above the threshold, falls far below it.
    tip_up = HeavyTop(1.0, 0.5, 1.0, 1e-3, psi_dot=1.05 * thr)
    tip_down = HeavyTop(1.0, 0.5, 1.0, 1e-3, psi_dot=0.95 * thr)
    assert tip_up.turning_points[1] < 1e-2 < 0.5 < tip_down.turning_points[1]
    assert HeavyTop(1.0, 0.5, 1.0, np.pi, psi_dot=3.0).motion_class == "hanging"
    assert HeavyTop(1.0, 0.5, 1.0, 0.8).motion_class == "through vertical"


# ---- bad input -----------------------------------------------------------------------------


@pytest.mark.parametrize(
    "kwargs, name, exc",
    [
        (dict(I1=0.0), "I1", ps.PoinsotError),
        (dict(I1=-1.0), "I1", ps.PoinsotError),
        (dict(I1=float("nan")), "I1", ps.PoinsotError),
        (dict(I3=0.0), "I3", ps.PoinsotError),
        (dict(I3=-0.5), "I3", ps.PoinsotError),
        (dict(I3=3.0), "I3", ps.InvalidInertiaError),
        (dict(mgl=-0.1), "mgl", ps.PoinsotError),
        (dict(mgl=float("inf")), "mgl", ps.PoinsotError),
        (dict(theta=-0.1), "theta", ps.PoinsotError),
        (dict(theta=3.2), "theta", ps.PoinsotError),
        (dict(theta=float("nan")), "theta", ps.PoinsotError),
        (dict(theta_dot=float("inf")), "theta_dot", ps.PoinsotError),
        (dict(phi_dot=float("nan")), "phi_dot", ps.PoinsotError),
        (dict(psi_dot=float("nan")), "psi_dot", ps.PoinsotError),
        (dict(theta="abc"), "theta", ps.PoinsotError),
    ],
)
def test_bad_input_names_the_argument(kwargs, name, exc) -> None:
    args = dict(I1=1.0, I3=0.5, mgl=1.0, theta=0.5)
    rates = {k: kwargs.pop(k) for k in ("theta_dot", "phi_dot", "psi_dot") if k in kwargs}
    args.update(kwargs)
    with pytest.raises(exc) as info:
        HeavyTop(args["I1"], args["I3"], args["mgl"], args["theta"], **rates)
    assert isinstance(info.value, ValueError)
    assert str(info.value).startswith(f"{name}:"), str(info.value)


def test_bad_input_to_methods() -> None:
    top = HeavyTop(1.0, 0.5, 1.0, 0.5, psi_dot=6.0)
    with pytest.raises(ps.PoinsotError, match="^theta:"):
        top.effective_potential([0.5, 4.0])
    with pytest.raises(ps.PoinsotError, match="^t:"):
        top.euler_angles([0.0, float("nan")])
    with pytest.raises(ps.PoinsotError, match="^omega3:"):
        HeavyTop.steady_precession_rates(1.0, 0.5, 1.0, 0.5, float("inf"))
    with pytest.raises(ps.PoinsotError, match="^theta0:"):
        HeavyTop.min_spin(1.0, 0.5, 1.0, 4.0)
    with pytest.raises(ps.PoinsotError, match="^p_phi:"):
        HeavyTop.from_constants(1.0, 0.5, 1.0, float("nan"), 1.0, 1.0)


def test_constants_of_state_equal_the_constants_along_the_motion() -> None:
    """HeavyTop.constants_of_state at the exact state at t equals the constants to round-off
    (and the independent 2.103–2.105 of ``_constants``); a perturbed state does not."""
    i1, i3, mgl = 1.3, 0.6, 0.9
    top = HeavyTop(i1, i3, mgl, 0.7, theta_dot=0.2, phi_dot=-0.4, psi_dot=8.0)
    c0 = HeavyTop.constants_of_state(i1, i3, mgl, 0.7, 0.2, -0.4, 8.0)
    assert (c0["p_phi"], c0["p_psi"], c0["energy"]) == (top.p_phi, top.p_psi, top.energy)
    ts = np.linspace(0.0, 6.0, 25)
    _, th, _ = top.euler_angles(ts)
    phd, thd, psd = top.euler_rates(ts)
    for k in range(ts.size):
        c = HeavyTop.constants_of_state(i1, i3, mgl, th[k], thd[k], phd[k], psd[k])
        ref = _constants(i1, i3, mgl, th[k], thd[k], phd[k], psd[k])
        assert c["energy"] == pytest.approx(top.energy, abs=ROUND_OFF * 50)
        assert c["p_phi"] == pytest.approx(top.p_phi, abs=ROUND_OFF * 10)
        assert c["p_psi"] == pytest.approx(top.p_psi, abs=ROUND_OFF * 10)
        assert (c["p_phi"], c["p_psi"], c["energy"]) == pytest.approx(ref, abs=ROUND_OFF * 50)
    k = int(np.argmax(np.abs(thd)))
    bad = HeavyTop.constants_of_state(i1, i3, mgl, th[k], thd[k] + 1e-6, phd[k], psd[k])
    assert abs(bad["energy"] - top.energy) > 1e-8
    deg = HeavyTop.constants_of_state(
        i1,
        i3,
        mgl,
        math.degrees(0.7),
        math.degrees(0.2),
        math.degrees(-0.4),
        math.degrees(8.0),
        degrees=True,
    )
    assert deg["energy"] == pytest.approx(top.energy, abs=ROUND_OFF)
    with pytest.raises(ps.PoinsotError, match="^theta"):
        HeavyTop.constants_of_state(i1, i3, mgl, 4.0, 0.0, 0.0, 1.0)
    with pytest.raises(ps.PoinsotError, match="^psi_dot"):
        HeavyTop.constants_of_state(i1, i3, mgl, 1.0, 0.0, 0.0, math.nan)


def test_from_spin_sets_omega3_and_psi_dot_by_2_99() -> None:
    top = HeavyTop.from_spin(1.0, 0.5, 1.0, 0.7, 9.0, phi_dot=-0.4, theta_dot=0.3)
    assert top.omega3 == pytest.approx(9.0, abs=ROUND_OFF)
    s = top.initial_state
    assert s["psi_dot"] == pytest.approx(9.0 + 0.4 * math.cos(0.7), abs=ROUND_OFF)
    assert (s["theta"], s["phi_dot"], s["theta_dot"]) == (0.7, -0.4, 0.3)
    ref = HeavyTop(1.0, 0.5, 1.0, 0.7, phi_dot=-0.4, theta_dot=0.3, psi_dot=s["psi_dot"])
    assert top.energy == ref.energy and top.p_phi == ref.p_phi
    deg = HeavyTop.from_spin(1.0, 0.5, 1.0, 40.0, math.degrees(9.0), degrees=True)
    assert deg.omega3 == pytest.approx(9.0, abs=ROUND_OFF)
    with pytest.raises(ps.PoinsotError, match="^omega3"):
        HeavyTop.from_spin(1.0, 0.5, 1.0, 0.7, math.inf)
