"""The derivation of the torque-free symmetric top (the unit's 2.77–2.97): it builds, every
step holds, the misprints of the range are found by computation, and each derived formula the
core also computes agrees with :class:`poinsot.FreeSymmetricTop`."""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import pytest
from unit_source import unit_text

sp = pytest.importorskip("sympy")

import poinsot as ps  # noqa: E402
from poinsot.derive import torque_free_top as tf  # noqa: E402
from poinsot.derive._core import Printed, judge  # noqa: E402

#: Derived formula against the core: the same closed forms in double precision, so only
#: round-off (a few ε, times the cancellation in L² − 2TI₁ for 2.95–2.96) separates them.
TIGHT = 1e-12
#: Random valid inputs per bridge test.
POINTS = 25

ROOT = Path(__file__).resolve().parents[2]

NUMBERS = {f"2.{k}" for k in range(77, 98)} - {"2.92"}  # the unit has no 2.92


@pytest.fixture(scope="module")
def d():
    t0 = time.perf_counter()
    out = tf.derive()
    print(f"torque_free_top.derive(): {time.perf_counter() - t0:.3f} s")
    return out


def _judge(printed, d):
    return [e.number for e in judge(printed, {"torque_free_top": d})]


# ---- the derivation --------------------------------------------------------------------------


def test_builds_and_every_recorded_step_holds(d):
    """Every step, including those checked on the flow of Euler's equations before the switch
    to the general solution, holds in the final model (the solution reaches every motion)."""
    assert d.name == "torque_free_top" and d.context == {tf.I2: tf.I1}
    for s in d.steps:
        assert d.holds(s.equation), s.text


def test_results_carry_the_unit_numbers(d):
    assert set(d.result) == NUMBERS
    assert set(d.functions) == {
        "2.83", "2.85", "2.86", "2.88", "2.89", "2.90", "2.91", "2.93", "2.95", "2.96", "2.97"
    }  # fmt: skip


def test_the_registry_serves_it():
    from poinsot.derive import derivation

    assert derivation("torque_free_top").name == "torque_free_top"


def test_the_flow_model_derives_without_the_solution():
    """Before the switch the model knows Euler's equations only: 2.82 and 2.84 follow there,
    and the solution's form is not assumed (ω₁ = A sin(Ωt + θ₀) is not an identity of it)."""
    flow = tf._flow_model()
    d = tf.derive()
    d.model = flow
    assert d.holds(d.result["2.82"]) and d.holds(d.result["2.84"])
    assert not d.holds(d.result["2.85"])


def test_a_false_step_is_refused():
    """Negative control of the step check: the unit's middle line of 2.84 is not recorded."""
    d = tf.derive()
    n = len(d.steps)
    bad = sp.Eq(tf.w1.diff(tf.t, 2), tf.Omega**2 * tf.w1)
    with pytest.raises(ps.PoinsotError, match="does not hold"):
        d.step("the unit's middle line of 2.84", bad)
    assert len(d.steps) == n


def test_renders_with_the_unit_numbers(d):
    tex = d.latex()
    for n in d.result:
        assert f"\\tag{{{n}}}" in tex
    assert r"A \sin{\left(\Omega t + \theta_{0} \right)}" in tex


# ---- the unit as printed ---------------------------------------------------------------------


def test_every_numbered_equation_of_the_range_is_transcribed():
    assert {p.number for p in tf.PRINTED} == NUMBERS
    assert all(p.derivation == "torque_free_top" for p in tf.PRINTED)


def test_transcriptions_are_verbatim():
    text = unit_text()
    for p in tf.PRINTED:
        for line in p.as_printed.split("\n"):
            assert line in text, (p.number, line)


def test_errata_are_exactly_the_misprints_of_the_range(d):
    """seed-errata.md: 2.78 (sign; I₂ for I₁ is harmless with I₂ = I₁) and the middle line of
    2.84 (sign). The numbered line of 2.84 and everything else is right."""
    found = judge(tf.PRINTED, {"torque_free_top": d})
    assert [e.number for e in found] == ["2.78", "2.84"]
    middle = next(e for e in found if e.number == "2.84")
    assert len(middle.failing) == 1 and middle.failing[0].rhs == tf.Omega**2 * tf.w1
    for e in found:
        assert e.derived is d.result[e.number] and d.holds(e.derived)


def test_negative_controls_of_the_errata(d):
    """A right printed equation is not reported; the same with one term changed is."""
    right = next(p for p in tf.PRINTED if p.number == "2.96")
    swapped = Printed(
        "2.96",
        "torque_free_top",
        right.as_printed,
        sp.Eq(tf.A**2, (tf.L_mag**2 - 2 * tf.I1 * tf.T) / (tf.I1 * (tf.I1 - tf.I3))),
    )
    assert _judge([right], d) == []
    assert _judge([swapped], d) == ["2.96"]
    ok = next(p for p in tf.PRINTED if p.number == "2.82")
    flipped = Printed("2.82", "torque_free_top", "", sp.Eq(tf.w2.diff(tf.t), tf.Omega * tf.w1))
    assert _judge([ok], d) == []
    assert _judge([flipped], d) == ["2.82"]


def test_the_question_bank_form_without_its_minus_signs_is_wrong(d):
    """The long question 10 prints A² = (L² 2I₃T)/(I₁(I₁ I₃)): the minus signs were lost in
    the scan. Read with plus signs it does not hold; 2.96 does."""
    plus = sp.Eq(tf.A**2, (tf.L_mag**2 + 2 * tf.I3 * tf.T) / (tf.I1 * (tf.I1 + tf.I3)))
    assert not d.holds(plus)
    assert d.holds(d.result["2.96"])


# ---- the bridge to the numbers ---------------------------------------------------------------


def _random_top(rng):
    """I₁ (kg·m²), I₃ ≤ 2I₁ away from I₁ (prolate and oblate), ω₀ (rad/s) with every component
    at least 0.3 in size."""
    I1 = rng.uniform(0.5, 2.0)
    ratio = rng.uniform(0.2, 0.8) if rng.random() < 0.5 else rng.uniform(1.25, 1.95)
    w0 = rng.choice([-1.0, 1.0], 3) * rng.uniform(0.3, 2.0, 3)
    return I1, ratio * I1, w0


def _rel(a, b):
    return abs(a - b) / abs(b)


def _tops():
    rng = np.random.default_rng(2097)
    for _ in range(POINTS):
        I1, I3, w0 = _random_top(rng)
        yield I1, I3, w0, ps.FreeSymmetricTop(I1, I3, w0)


def test_bridge_constants_and_cones(d):
    """Ω (2.83), A (2.88), |ω⃗| (2.89), α_b (2.90), T (2.91), L² (2.93) and α_s (2.97) from
    the lambdified results against the core's free symmetric top."""
    f = {n: d.lambdify(n) for n in ("2.83", "2.88", "2.89", "2.90", "2.91", "2.93", "2.97")}
    worst = dict.fromkeys(f, 0.0)
    for I1, I3, w0, top in _tops():
        A = float(f["2.88"](w0[0], w0[1]))
        pairs = {
            "2.83": (f["2.83"](I1, I3, w0[2]), top.precession_rate),
            "2.88": (A, top.amplitude),
            "2.89": (f["2.89"](A, w0[2]), top.omega_magnitude),
            "2.90": (f["2.90"](A, w0[2]), top.body_cone_angle),
            "2.91": (f["2.91"](I1, I3, A, w0[2]), top.energy),
            "2.93": (f["2.93"](I1, I3, A, w0[2]), top.angular_momentum_magnitude**2),
            "2.97": (f["2.97"](I1, I3, A, w0[2]), top.space_cone_angle),
        }
        for n, (derived, core) in pairs.items():
            worst[n] = max(worst[n], _rel(float(derived), core))
    print("torque-free top against the core, worst relative differences:")
    for n, v in worst.items():
        print(f"  {n}: {v:.2e}")
    assert max(worst.values()) <= TIGHT


def test_bridge_constants_from_energy_and_momentum(d):
    """ω₃² (2.95) and A² (2.96) from T and |L| against the core's closed forms of the same
    (and against the top's own ω₃² and A², looser: L² − 2TI₁ cancels)."""
    w3sq, a2 = d.lambdify("2.95"), d.lambdify("2.96")
    worst = 0.0
    for I1, I3, w0, top in _tops():
        T, L = top.energy, top.angular_momentum_magnitude
        c3 = ps.FreeSymmetricTop.omega3_squared_from(I1, I3, T, L)
        ca = ps.FreeSymmetricTop.amplitude_squared_from(I1, I3, T, L)
        worst = max(worst, _rel(float(w3sq(I1, I3, T, L)), c3), _rel(float(a2(I1, I3, T, L)), ca))
        assert _rel(float(w3sq(I1, I3, T, L)), w0[2] ** 2) < 1e-9
        assert _rel(float(a2(I1, I3, T, L)), w0[0] ** 2 + w0[1] ** 2) < 1e-9
    print(f"2.95, 2.96 against the core: worst relative difference {worst:.2e}")
    assert worst <= TIGHT


def test_bridge_omega_of_t(d):
    """ω(t) from its initial value (2.85–2.86 expanded) against the core's ω(t), and the unit's
    phase: the core's amplitude A and phase θ₀ put in the derived 2.85–2.86 give the same
    ω(t), and A sin θ₀ = ω₁(0), A cos θ₀ = ω₂(0). Vector norm (components cross zero)."""
    f1, f2 = d.lambdify("2.85"), d.lambdify("2.86")
    Om, A, th = sp.Symbol("Omega"), tf.A, tf.theta0
    unit_form = sp.lambdify(
        (A, Om, th, tf.t),
        [_rhs(d.result[n]).xreplace({tf.Omega: Om}) for n in ("2.85", "2.86")],
        "numpy",
    )
    ts = np.linspace(0.0, 10.0, 7)
    worst = 0.0
    for I1, I3, w0, top in _tops():
        core = top.omega(ts)
        mine = np.column_stack(
            [
                f1(I1, I3, w0[0], w0[1], w0[2], ts),
                f2(I1, I3, w0[0], w0[1], w0[2], ts),
                np.full_like(ts, w0[2]),
            ]
        )
        unit = np.column_stack(
            [*unit_form(top.amplitude, top.precession_rate, top.phase, ts), np.full_like(ts, w0[2])]
        )
        for k in range(len(ts)):
            worst = max(worst, _rel_vec(mine[k], core[k]), _rel_vec(unit[k], core[k]))
    print(f"2.85–2.86 against the core's ω(t): worst relative difference {worst:.2e}")
    assert worst <= TIGHT


def _rhs(eq):
    """The right-hand side of an equation, or of the last link of a chain."""
    return (eq[-1] if isinstance(eq, list) else eq).rhs


def _rel_vec(a, b):
    return float(np.linalg.norm(a - b) / np.linalg.norm(b))
