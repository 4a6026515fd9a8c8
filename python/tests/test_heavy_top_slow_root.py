"""The slow steady-precession root of the heavy top at a horizontal axis (θ₀ = π/2).

2.117 as printed, (p_ψ − √(p_ψ² − 4mglI₁ cos θ₀)) / (2I₁ cos θ₀), is 0/0 at θ₀ = π/2 in
floating point (cos θ₀ ≈ 6e-17), so a variant of ``top-slow-precession`` fixed at 90° (the
gyroscope of OpenStax University Physics Vol. 1, Example 11.10) was refused with "two routes
disagree: 3.12, 0.0". The derivation now registers the slow rate as the product of the roots over
the fast one, 2mgl / (p_ψ + √(p_ψ² − 4mglI₁ cos θ₀)), a step sympy checks; at θ₀ = π/2 the
quadratic 2.116 is linear, −p_ψ φ̇ + mgl = 0, so φ̇ = mgl/p_ψ exactly (the reference here).
"""

from __future__ import annotations

import math

import poinsot as ps
import poinsot.exercises as x
from poinsot import derive


def test_the_derived_slow_rate_holds_at_a_horizontal_axis() -> None:
    slow = derive.derivation("heavy_top").lambdify("2.117 slow")
    i1, i3, mgl, spin = 0.1, 0.05, 1.0, 50.0
    assert math.isclose(slow(i1, i3, mgl, math.pi / 2, spin), mgl / (i3 * spin), rel_tol=1e-15)
    # Away from the horizontal it is still the quadratic's root, as the core computes it.
    for theta0 in (0.3, 1.2, math.pi / 2 - 1e-9, 2.0):
        core, _ = ps.HeavyTop.steady_precession_rates(i1, i3, mgl, theta0, spin)
        assert math.isclose(slow(i1, i3, mgl, theta0, spin), core, rel_tol=1e-12), theta0


def test_a_variant_fixed_at_90_degrees_is_issued() -> None:
    t = x.template("top-slow-precession")
    v = t.fixed(I1=4000, I3=2000, mass=100, arm=2, theta0=90, spin=3000)
    p = 2000e-7 * 3000 * 2 * math.pi / 60
    mgl = 0.1 * 9.80665 * 0.02  # standard gravity, as the template states it
    # The answer in rpm: mgl/p_ψ rad/s.
    assert math.isclose(v.answer, mgl / p * 60 / (2 * math.pi), rel_tol=1e-9)


def test_negative_control_the_printed_form_loses_its_digits_there() -> None:
    i1, i3, mgl, spin = 0.1, 0.05, 1.0, 50.0
    p, c = i3 * spin, math.cos(math.pi / 2)
    printed = (p - math.sqrt(p * p - 4 * mgl * i1 * c)) / (2 * i1 * c)
    assert not math.isclose(printed, mgl / p, rel_tol=1e-3)
