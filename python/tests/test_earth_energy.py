"""The conserved quantities of the rotating Earth's motions (issue 6's lab shows them live):
Jacobi's integral of the Foucault pendulum and of the drop, and the energy budget of the flow
into a low. References: scipy's solve_ivp for an independent integration of the low, and the
closed form of J for a state at rest."""

from __future__ import annotations

import numpy as np
import poinsot as ps
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp

#: Drift allowed of J along a Foucault run at the default rtol 1e-10, relative to g L.
JACOBI_DRIFT = 1e-8
#: Closing error allowed of the low's energy budget at rtol 1e-12, relative to the initial energy.
BUDGET = 1e-9
#: Agreement with scipy's DOP853 at rtol 1e-11 (both errors well below it).
SCIPY = 1e-7


def test_jacobi_integral_is_conserved_by_the_foucault_pendulum() -> None:
    # A planet spinning 1000 × faster: the centrifugal potential matters.
    e = ps.Earth(1000 * ps.earth.SIDEREAL_RATE)
    run = e.foucault(40, degrees=True, length=10.0, amplitude=1.0, duration=120.0, samples=241)
    j = e.jacobi_integral(40, run.position, run.velocity, degrees=True)
    assert j.shape == (241,)
    assert np.max(np.abs(j - j[0])) < JACOBI_DRIFT * e.g * 10.0
    # Negative control: without the centrifugal potential the energy is not conserved.
    plain = 0.5 * np.sum(run.velocity**2, axis=1) + e.g * run.position[:, 2]
    assert np.max(np.abs(plain - plain[0])) > 1e3 * JACOBI_DRIFT * e.g * 10.0


def test_jacobi_integral_is_conserved_by_the_drop() -> None:
    e = ps.Earth(100 * ps.earth.SIDEREAL_RATE)
    fall = e.drop(200.0, 0.6)
    j = e.jacobi_integral(0.6, fall.position, fall.velocity)
    assert np.max(np.abs(j - j[0])) < 1e-9 * e.g * 200.0


@settings(max_examples=50, deadline=None)
@given(st.floats(-1.5, 1.5), st.lists(st.floats(-50, 50), min_size=3, max_size=3))
def test_jacobi_integral_at_rest_is_the_potential(lat: float, r: list[float]) -> None:
    e = ps.Earth()
    w = e.omega_enu(lat)
    want = e.g * r[2] - 0.5 * np.sum(np.cross(w, r) ** 2)
    assert e.jacobi_integral(lat, r, [0.0, 0.0, 0.0]) == pytest.approx(want, rel=1e-14, abs=1e-12)


def test_jacobi_integral_broadcasts_and_checks() -> None:
    e = ps.Earth()
    out = e.jacobi_integral(0.3, np.zeros((4, 1, 3)), np.ones((5, 3)))
    assert out.shape == (4, 5)
    assert isinstance(e.jacobi_integral(0.3, [0, 0, 1.0], [1.0, 0, 0]), float)
    with pytest.raises(ps.PoinsotError, match="position"):
        e.jacobi_integral(0.3, [0, 0], [1.0, 0, 0])
    with pytest.raises(ps.PoinsotError, match="latitude"):
        e.jacobi_integral(2.0, [0, 0, 1.0], [1.0, 0, 0])
    with pytest.raises(ps.PoinsotError, match="^position: must be finite"):
        e.jacobi_integral(0.3, [0, 0, np.nan], [1.0, 0, 0])
    with pytest.raises(ps.PoinsotError, match="^velocity"):
        e.jacobi_integral(0.3, [0, 0, 1.0], np.ones((2, 3)) * [[1], [np.inf]])


@pytest.mark.parametrize("friction", [0.0, 1e-5, 4e-5])
def test_low_energy_budget_closes(friction: float) -> None:
    e = ps.Earth()
    flow = e.flow_into_low(45, degrees=True, friction=friction)
    k = 1e-3 / 5e5
    r2 = np.sum(flow.position**2, axis=2)
    v2 = np.sum(flow.velocity**2, axis=2)
    np.testing.assert_allclose(flow.energy, 0.5 * v2 + 0.5 * k * r2, rtol=1e-13)
    total = flow.energy + flow.dissipated
    e0 = flow.energy[:, :1]
    assert np.max(np.abs(total - e0) / e0) < BUDGET
    if friction == 0:
        assert np.all(flow.dissipated == 0)
    else:
        # Friction takes a real share of the energy: the budget is not trivially closed.
        assert np.all(flow.dissipated[:, -1] > 0.1 * e0[:, 0])


def test_low_agrees_with_scipy() -> None:
    e = ps.Earth()
    lat, pull, gamma, rad = np.radians(-30), 1.5e-3, 2e-5, 5e5
    flow = e.flow_into_low(
        lat, radius=rad, parcels=3, pull=pull, friction=gamma, duration=86400.0, samples=25
    )
    f, k = 2 * e.rotation_rate * np.sin(lat), pull / rad

    def rhs(_t: float, y: np.ndarray) -> list[float]:
        x, yy, vx, vy, _w = y
        return [
            vx,
            vy,
            -k * x - gamma * vx + f * vy,
            -k * yy - gamma * vy - f * vx,
            gamma * (vx * vx + vy * vy),
        ]

    for p in range(3):
        a = 2 * np.pi * p / 3
        sol = solve_ivp(
            rhs,
            (0, 86400.0),
            [rad * np.cos(a), rad * np.sin(a), 0, 0, 0],
            method="DOP853",
            t_eval=flow.t,
            rtol=1e-11,
            atol=1e-9,
        )
        np.testing.assert_allclose(flow.position[p], sol.y[:2].T, rtol=0, atol=SCIPY * rad)
        np.testing.assert_allclose(
            flow.dissipated[p], sol.y[4], rtol=0, atol=SCIPY * flow.energy[p, 0]
        )
