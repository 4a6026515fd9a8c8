"""Tests of the derivation "gyrocompass" (poinsot.derive.gyrocompass, issue 26): it builds and every
step holds, false steps are refused (negative controls), and the derived formulas agree with the
Rust core (poinsot.Gyrocompass): the period, the natural frequency, Schuler's rotor and period,
the speed error and the small-angle latitude error, at random inputs."""

from __future__ import annotations

import math

import numpy as np
import pytest

sp = pytest.importorskip("sympy")

import poinsot as ps  # noqa: E402
from poinsot import derive  # noqa: E402
from poinsot.derive import Derivation  # noqa: E402
from poinsot.derive import gyrocompass as gd  # noqa: E402
from poinsot.derive._core import Dot  # noqa: E402


@pytest.fixture(scope="module")
def d() -> Derivation:
    return derive.derivation("gyrocompass")


def test_builds_every_step_holds_and_is_listed(d: Derivation) -> None:
    assert d.name == "gyrocompass" and "gyrocompass" in derive.applied()
    assert "gyrocompass" not in derive.names()
    checked = [s for s in d.steps if not s.text.startswith("Given")]
    assert len(checked) >= 15
    for s in checked:
        assert d.holds(s.equation), s.text
    assert {s.number for s in d.steps if s.number} == set(d.result)
    for key in ("heading equation", "tilt equation", "characteristic equation", "period"):
        assert key in d.result
    for key in ("Schuler tuning", "Schuler period", "speed error", "settle error"):
        assert key in d.result
    assert "$$" in d.markdown() and "\\tag{period}" in d.latex()


def test_listed_by_the_cli() -> None:
    from click.testing import CliRunner
    from poinsot.cli import main

    out = CliRunner().invoke(main, ["derive", "--list"])
    assert out.exit_code == 0, out.output
    assert "gyrocompass" in out.output and "Schuler period" in out.output


def test_false_steps_are_refused(d: Derivation) -> None:
    """Negative controls: the heading equation without the Earth's vertical rate, the tilt
    equation with the vertical rate Ω sin λ in place of Ω cos λ, a characteristic equation
    without the damping, the speed error with the course's sign flipped, and Schuler's rotor
    with sin λ do not hold."""
    H, P, D = gd.H, gd.P, gd.D
    first_x = gd.First(Dot(gd.x_hat, gd.E)) / H
    good = gd.alpha_dot - gd.Om_s + (P / H + gd.Om_c) * gd.theta
    assert d.holds(sp.Eq(first_x, good, evaluate=False))
    assert not d.holds(sp.Eq(first_x, good + gd.Om_s, evaluate=False))
    first_z = gd.First(Dot(gd.z_hat, gd.E)) / H
    assert d.holds(sp.Eq(first_z, gd.theta_dot - gd.Om_c * gd.alpha + D / H * gd.theta))
    assert not d.holds(sp.Eq(first_z, gd.theta_dot - gd.Om_s * gd.alpha + D / H * gd.theta))
    s, Om_c = gd.s, gd.Om_c
    det = sp.Determinant(sp.ImmutableMatrix([[s, P / H + Om_c], [-Om_c, s + D / H]]))
    assert d.holds(sp.Eq(det, s**2 + D / H * s + Om_c * (P / H + Om_c), evaluate=False))
    assert not d.holds(sp.Eq(det, s**2 + Om_c * (P / H + Om_c), evaluate=False))
    V, C, R, Om, lat = gd.V, gd.C, gd.R, gd.Om, gd.lat
    both = gd.W + gd.W_ship
    ratio = -Dot(gd.x_hat, both) / Dot(gd.y_hat, both)
    right = V * sp.cos(C) / (Om * R * sp.cos(lat) + V * sp.sin(C))
    assert d.holds(sp.Eq(ratio, right, evaluate=False))
    wrong = V * sp.cos(C) / (Om * R * sp.cos(lat) - V * sp.sin(C))
    assert not d.holds(sp.Eq(ratio, wrong, evaluate=False))
    g = gd.g
    swing = P * gd.dV / (gd.H_S * g)
    assert d.holds(sp.Eq(swing, gd.dV / (Om * R * sp.cos(lat)), evaluate=False))
    assert not d.holds(sp.Eq(swing, gd.dV / (Om * R * sp.sin(lat)), evaluate=False))


def test_derived_formulas_equal_the_cores_at_random_inputs(d: Derivation) -> None:
    period, freq = d.lambdify("period"), d.lambdify("natural frequency")
    tuned, schuler = d.lambdify("Schuler tuning"), d.lambdify("Schuler period")
    speed, settle = d.lambdify("speed error"), d.lambdify("settle error")
    rng = np.random.default_rng(26)
    for _ in range(12):
        lat = rng.uniform(-1.4, 1.4)
        H, P, zeta = rng.uniform(5, 200), rng.uniform(0.2, 5), rng.uniform(0.0, 0.9)
        Om, R, g = rng.uniform(3e-5, 1.5e-4), rng.uniform(3e6, 9e6), rng.uniform(3, 15)
        earth = ps.Earth(Om, R, g)
        c = ps.Gyrocompass(lat, H, P, damping=zeta, earth=earth)
        assert period(H, P, Om, lat) == pytest.approx(c.period, rel=1e-12, abs=0)
        assert freq(H, P, Om, lat) == pytest.approx(c.natural_frequency, rel=1e-12, abs=0)
        s = ps.Gyrocompass.schuler_tuned(lat, P, earth=earth)
        assert tuned(P, Om, R, g, lat) == pytest.approx(s.angular_momentum, rel=1e-12, abs=0)
        assert schuler(R, g) == pytest.approx(ps.Gyrocompass.schuler_period(earth), rel=1e-12)
        V, C = rng.uniform(0, 0.5) * Om * R * math.cos(lat), rng.uniform(-math.pi, math.pi)
        assert speed(V, C, Om, R, lat) == pytest.approx(c.speed_error(V, C), rel=1e-12, abs=1e-15)
        # the linear equilibrium is the small-angle form of the core's full steady state: they
        # part at second order in the settled angles (sin α ≈ α, tan θ ≈ θ)
        lin = settle(c.damping_coefficient, H, P, Om, lat)
        second = 1e-6 + c.settle_error**2 + c.settle_tilt**2
        assert lin == pytest.approx(c.settle_error, rel=second, abs=1e-12)


def test_negative_control_a_still_earth_seeks_no_north(d: Derivation) -> None:
    """With Ω = 0 the derived period is infinite and the core refuses the period, naming the
    rotation rate; the derived formula is not the core's at a wrong latitude."""
    period = d.lambdify("period")
    with np.errstate(divide="ignore"):
        assert not np.isfinite(period(40.0, 1.2, 0.0, 0.8))
    with pytest.raises(ps.PoinsotError, match="rotation_rate"):
        ps.Gyrocompass(0.8, earth=ps.Earth(0.0, 6.371e6, 9.81)).period
    c = ps.Gyrocompass(0.8)
    Om = c.earth.rotation_rate
    assert abs(period(40.0, 1.2, Om, 0.7) / c.period - 1) > 1e-3
