"""The derivation of Euler's equations (the unit's 2.67–2.76): it builds, every step holds, the
misprints of the range are found by computation, and the derived right-hand side of Euler's
equations and the energy theorem agree with the core's rigid-body integrator."""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import pytest
from unit_source import unit_text

sp = pytest.importorskip("sympy")

import poinsot as ps  # noqa: E402
from poinsot.derive import euler_equations as ee  # noqa: E402
from poinsot.derive._core import Dot, DtRot, Printed, judge  # noqa: E402

#: Derived formula against the core: both evaluate the same few products in double precision,
#: so only round-off (a few ε) separates them.
TIGHT = 1e-12
#: Random valid inputs per bridge test.
POINTS = 25

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def d():
    t0 = time.perf_counter()
    out = ee.derive()
    print(f"euler_equations.derive(): {time.perf_counter() - t0:.3f} s")
    return out


def _errata(d):
    return [e.number for e in judge(ee.PRINTED, {"euler_equations": d})]


# ---- the derivation --------------------------------------------------------------------------


def test_builds_and_every_recorded_step_holds(d):
    assert d.name == "euler_equations" and d.steps
    for s in d.steps:
        assert d.holds(s.equation), s.text


def test_results_carry_the_unit_numbers(d):
    assert set(d.result) == {f"2.{k}" for k in range(67, 77)}
    assert set(d.functions) == {"2.72", "2.76"}


def test_the_registry_serves_it():
    from poinsot.derive import derivation

    assert derivation("euler_equations").name == "euler_equations"


def test_the_corrected_2_70_has_the_rate_of_omega(d):
    """2.70 ends in I⃗·(dω⃗/dt)_rot, not the unit's I⃗·ω⃗."""
    last = d.result["2.70"][-1]
    assert last.rhs == Dot(ee.I, DtRot(ee.omega))


def test_renders_with_the_unit_numbers(d):
    tex = d.latex()
    for n in d.result:
        assert f"\\tag{{{n}}}" in tex
    assert r"\vec{\omega} \times \left(\vec{I} \cdot \vec{\omega}\right)" in tex
    assert "2.72" in d.markdown()


def test_a_false_step_is_refused():
    """Negative control of the step check: dropping ω⃗ × L⃗ from 2.71 must not be recorded."""
    d = ee.derive()
    n = len(d.steps)
    with pytest.raises(ps.PoinsotError, match="does not hold"):
        d.step("2.71 without the gyroscopic term", sp.Eq(ee.N, Dot(ee.I, DtRot(ee.omega))))
    assert len(d.steps) == n


# ---- the unit as printed ---------------------------------------------------------------------


def test_every_numbered_equation_of_the_range_is_transcribed():
    numbers = {p.number for p in ee.PRINTED}
    assert numbers == {f"2.{k}" for k in range(67, 77)}
    assert all(p.derivation == "euler_equations" for p in ee.PRINTED)
    assert sum(p.number == "2.72" for p in ee.PRINTED) == 3  # its three lines


def test_transcriptions_are_verbatim():
    text = unit_text()
    for p in ee.PRINTED:
        for line in p.as_printed.split("\n"):
            assert line in text, (p.number, line)


def test_errata_are_exactly_the_misprints_of_the_range(d):
    """2.70 (dot lost) and 2.73–2.74 (ω⃗ ∥ L⃗ claimed for every torque-free body) are in
    seed-errata.md; 2.71 is found by the computation: it is 2.70 put in 2.69, and the unit
    prints it with the same lost dot (N⃗ = I⃗·ω⃗ + ω⃗ × L⃗)."""
    assert _errata(d) == ["2.70", "2.71", "2.73", "2.74"]
    for e in judge(ee.PRINTED, {"euler_equations": d}):
        assert e.derived is d.result[e.number]
        assert d.holds(e.derived)


def test_the_torque_free_claim_fails_and_its_correction_holds(d):
    """ω⃗ × (I⃗·ω⃗) = −I⃗·ω̇⃗ for N⃗ = 0⃗: zero only for steady rotation."""
    w = ee.omega
    assert not d.holds(sp.Eq(ee._Cross(w, ee.L), ee.ZERO))
    assert d.holds(sp.Eq(ee._Cross(w, Dot(ee.I, w)), ee.N - Dot(ee.I, DtRot(w)), evaluate=False))


def test_negative_controls_of_the_errata(d):
    """A right printed equation is not reported; the same with one term changed is."""
    right = next(p for p in ee.PRINTED if p.number == "2.72")
    changed = Printed(
        "2.72",
        "euler_equations",
        right.as_printed,
        sp.Eq(
            ee.N1,
            sp.Add(ee.I1 * ee.w1.diff(ee.t), (ee.I2 - ee.I3) * ee.w2 * ee.w3, evaluate=False),
            evaluate=False,
        ),
    )
    assert judge([right], {"euler_equations": d}) == []
    assert [e.number for e in judge([changed], {"euler_equations": d})] == ["2.72"]
    energy = next(p for p in ee.PRINTED if p.number == "2.76")
    twice = Printed("2.76", "euler_equations", "", sp.Eq(Dot(ee.omega, ee.N), 2 * ee._Ddt(ee.T)))
    assert judge([energy], {"euler_equations": d}) == []
    assert len(judge([twice], {"euler_equations": d})) == 1


# ---- the bridge to the numbers ---------------------------------------------------------------


def _random_body(rng):
    """Principal moments obeying the triangle inequality (kg·m²), ω (rad/s), N (N·m)."""
    while True:
        m = rng.uniform(0.3, 3.0, 3)
        if np.all(m.sum() - m > m * 1.05):
            return m, rng.uniform(-2.0, 2.0, 3), rng.uniform(-1.5, 1.5, 3)


def _one_rk4_step(moments, omega0, torque, h):
    """The states at which the core's RK4 evaluates Euler's equations in one step of size h,
    read through a torque callback, and the state after the step."""
    calls = []

    def f(t, w, q):
        calls.append((t, np.array(w, dtype=float)))
        return torque

    run = ps.simulate(moments, omega0, h, torque=f, method="rk4", dt=h, samples=2)
    assert run.steps == 1
    y2, y3 = (w for t, w in calls if t == 0.5 * h)
    y4 = next(w for t, w in calls if t == h)
    return y2, y3, y4, run


def _rel(a, b):
    return float(np.linalg.norm(np.asarray(a) - np.asarray(b)) / np.linalg.norm(b))


def test_bridge_euler_rates_2_72_against_the_core_integrator(d):
    """The derived rates ω̇⃗(ω⃗, N⃗) of 2.72 are the right-hand side the core integrates: the four
    RK4 stage slopes, recovered from the stage states the core hands to a torque callback,
    equal the lambdified 2.72 at those states (vector norm; components can cross zero)."""
    rates = d.lambdify("2.72")
    F = lambda m, w, n: np.asarray(rates(*m, *w, *n), dtype=float).ravel()
    rng = np.random.default_rng(2072)
    worst = 0.0
    h = 0.5
    for _ in range(POINTS):
        m, w0, n = _random_body(rng)
        y2, y3, y4, run = _one_rk4_step(m, w0, n, h)
        k1, k2, k3 = (y2 - w0) / (0.5 * h), (y3 - w0) / (0.5 * h), (y4 - w0) / h
        k4 = 6.0 * (run.omega[1] - w0) / h - k1 - 2.0 * (k2 + k3)
        for k, y in ((k1, w0), (k2, y2), (k3, y3)):
            worst = max(worst, _rel(k, F(m, y, n)))
        # k4 comes from a difference of four slopes: a looser, stated bound
        assert _rel(k4, F(m, y4, n)) < 1e-11
    print(f"2.72 against the core's RK4 slopes: worst relative difference {worst:.2e}")
    assert worst <= TIGHT


def test_bridge_energy_theorem_2_76_against_the_core_power(d):
    """dT/dt = I₁ω₁ω̇₁ + I₂ω₂ω̇₂ + I₃ω₃ω̇₃ (from 2.76), with ω̇⃗ the core's own slope, equals the
    core's power ω⃗·N⃗. The power crosses zero, so the difference is measured against the sum of
    the absolute values of the three terms (the floor where it cancels)."""
    dTdt = d.lambdify("2.76")
    rng = np.random.default_rng(2076)
    worst = 0.0
    h = 0.5
    for _ in range(POINTS):
        m, w0, n = _random_body(rng)
        y2, _, _, run = _one_rk4_step(m, w0, n, h)
        wdot = (y2 - w0) / (0.5 * h)
        derived = float(dTdt(*m, *w0, *wdot))
        scale = float(np.sum(np.abs(m * w0 * wdot)))
        worst = max(worst, abs(derived - run.power[0]) / max(abs(run.power[0]), scale))
    print(f"2.76 against the core's power: worst relative difference {worst:.2e}")
    assert worst <= TIGHT
