"""Gyrocompass.simulate with a ship's course and speed changes (``turns``, issue 26) and the
core's linearised solution (Gyrocompass.linear_solution) that the plot draws: units at the
door (SI, pint, text as typed at the CLI), refusals by name, the linear solution against the
full simulation and against its closed form written here."""

from __future__ import annotations

import math
import pickle

import numpy as np
import poinsot as ps
import pytest
from poinsot.errors import PoinsotError

KNOT = 1852 / 3600


def _compass() -> ps.Gyrocompass:
    return ps.Gyrocompass.schuler_tuned(math.radians(40), damping=0.0)


def test_turns_take_si_text_and_quantities_alike():
    c = _compass()
    si = [(120.0, 12 * KNOT, math.pi / 2, 90.0)]
    text = [("2min", "12kn", "90deg", "1.5min")]
    a = c.simulate(400.0, 0.0, speed=10 * KNOT, turns=si, samples=5)
    b = c.simulate(400.0, 0.0, speed=10 * KNOT, turns=text, samples=5)
    np.testing.assert_array_equal(a.heading, b.heading)
    pint = pytest.importorskip("pint")
    u = pint.UnitRegistry()
    q = [(2 * u.minute, 12 * u.knot, 90 * u.degree, 90 * u.second)]
    d = c.simulate(400.0, 0.0, speed=10 * KNOT, turns=q, samples=5)
    np.testing.assert_allclose(d.heading, a.heading, rtol=0, atol=1e-15)
    # No turns and an empty track are the same run; a turn changes it.
    plain = c.simulate(400.0, 0.0, speed=10 * KNOT, samples=5)
    empty = c.simulate(400.0, 0.0, speed=10 * KNOT, turns=[], samples=5)
    np.testing.assert_array_equal(plain.heading, empty.heading)
    assert abs(plain.heading[-1] - a.heading[-1]) > 1e-6


def test_turns_refused_by_name():
    c = _compass()
    with pytest.raises(PoinsotError, match=r"turns: turn 1: it starts at 130 s"):
        c.simulate(400.0, 0.0, turns=[(100, 5, 0, 60), (130, 5, 1)], samples=3)
    with pytest.raises(PoinsotError, match=r"turns: turn 0: its duration must be finite and > 0"):
        c.simulate(400.0, 0.0, turns=[(100, 5, 0, 0)], samples=3)
    with pytest.raises(PoinsotError, match=r"turns: turn 0's speed: expected a speed"):
        c.simulate(400.0, 0.0, turns=[("1min", "5deg", "0deg")], samples=3)
    with pytest.raises(PoinsotError, match=r"turns: turn 0 must be \(time, speed, course\)"):
        c.simulate(400.0, 0.0, turns=[(1, 2)], samples=3)
    with pytest.raises(ps.errors.ArgumentTypeError, match="turns"):
        c.simulate(400.0, 0.0, turns=5, samples=3)


def test_linear_solution_closed_form_and_full_simulation():
    c = ps.Gyrocompass.schuler_tuned(math.radians(40), damping=0.3)
    t = np.linspace(0.0, 0.5 * c.period, 41)
    start = -c.settle_error + math.radians(0.5)
    lin = c.linear_solution(t, start)
    # The closed form written here: settled tilt, so x = x0 e^{-σt}(cos ω_d t + σ/ω_d sin ω_d t).
    sigma = c.damping * c.natural_frequency
    wd = c.natural_frequency * math.sqrt(1 - c.damping**2)
    x0 = math.radians(0.5)
    want = -c.settle_error + x0 * np.exp(-sigma * t) * (
        np.cos(wd * t) + sigma / wd * np.sin(wd * t)
    )
    np.testing.assert_allclose(lin.heading, want, rtol=0, atol=1e-15)
    np.testing.assert_allclose(
        lin.envelope, x0 / math.sqrt(1 - c.damping**2) * np.exp(-sigma * t), rtol=1e-13
    )
    assert lin.settled_heading == pytest.approx(-c.settle_error, abs=1e-17)
    assert lin.settled_tilt == c.settle_tilt
    # Against the full gyrostat: within 2 % of the offset over half a period.
    run = c.simulate(t[-1], start, samples=len(t))
    assert np.max(np.abs(run.heading - lin.heading)) < 0.02 * x0
    assert "envelope" in repr(lin)
    assert pickle.loads(pickle.dumps(lin)).envelope[3] == lin.envelope[3]
    with pytest.raises(PoinsotError, match="heading0"):
        c.linear_solution(t, float("nan"))
    with pytest.raises(PoinsotError, match="speed"):
        c.linear_solution(t, 0.0, speed=1e4, course=-math.pi / 2)


def test_plot_draws_the_core_linear_envelope():
    pytest.importorskip("matplotlib")
    from poinsot.plots.gyrocompass import plot_gyrocompass

    c = ps.Gyrocompass.schuler_tuned(math.radians(40), damping=0.3)
    run = c.simulate(0.3 * c.period, math.radians(3), samples=30)
    fig = plot_gyrocompass(c, run)
    top = fig.axes[0]
    lin = c.linear_solution(run.t, run.heading[0], tilt0=run.tilt[0])
    upper = next(ln for ln in top.get_lines() if ln.get_label() == "linear envelope")
    np.testing.assert_allclose(
        upper.get_ydata(), np.degrees(lin.settled_heading + lin.envelope), rtol=1e-14
    )
