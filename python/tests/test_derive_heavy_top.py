"""poinsot.derive.heavy_top: the heavy symmetric top derived (the unit's 2.102–2.121), its
printed equations judged, and the bridge from its formulas to the numeric core (HeavyTop).

The bridge evaluates each derived formula (lambdified) exactly, with mpmath at 50 digits, and
compares the core's double-precision value with it: relative difference ≤ 1e-12 (RTOL). Where a
quantity crosses zero (p_φ, E′, V(θ), ∂V/∂θ, u = cos θ) the denominator is at least the size of
its terms, named at each comparison (an absolute floor, as the tolerance says)."""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

sp = pytest.importorskip("sympy")
mp = pytest.importorskip("mpmath")

from poinsot import HeavyTop, PoinsotError, derive  # noqa: E402
from poinsot.derive import heavy_top as ht  # noqa: E402
from poinsot.derive._core import Derivation, Printed, judge  # noqa: E402

#: the bridge's tolerance: the core computes each quantity to a few ulps (double precision,
#: 2.2e-16); 1e-12 leaves room for the conditioning of the formulas at the sampled inputs
RTOL = 1e-12
#: random valid tops per bridge test
N = 25
NUMBERS = [f"2.{k}" for k in range(102, 122)]


@pytest.fixture(scope="module")
def d() -> Derivation:
    """The derivation through the package's registry (built on first use, then shared)."""
    t0 = time.perf_counter()
    out = derive.derivation("heavy_top")
    print(f"\nheavy_top: built in {time.perf_counter() - t0:.2f} s, {len(out.steps)} steps")
    return out


@pytest.fixture(scope="module")
def errata(d: Derivation) -> dict[str, Any]:
    return {e.number: e for e in judge(ht.PRINTED, {"heavy_top": d})}


def _exact(d: Derivation, number: str) -> Callable[..., Any]:
    """The numeric form ``number`` evaluated with mpmath at 50 digits (an mpf)."""
    expr, syms = d.functions[number]
    f = sp.lambdify(syms, expr, "mpmath")

    def g(*args: Any) -> Any:
        with mp.workdps(50):
            return f(*(x if isinstance(x, mp.mpf) else mp.mpf(float(x)) for x in args))

    return g


class _Worst:
    """The worst relative difference of each comparison (printed at the end of a test)."""

    def __init__(self) -> None:
        self.worst: dict[str, float] = {}

    def check(self, name: str, core: float, exact: Any, floor: float = 0.0) -> None:
        ref = float(exact)
        rel = abs(core - ref) / max(abs(ref), floor)
        self.worst[name] = max(self.worst.get(name, 0.0), rel)
        assert rel <= RTOL, f"{name}: core {core!r}, derived {ref!r}, relative {rel:.2e}"

    def report(self) -> None:
        print("\n" + ", ".join(f"{k}: {v:.1e}" for k, v in self.worst.items()))


def _top(rng: np.random.Generator) -> tuple[float, float, float]:
    i1 = rng.uniform(0.5, 2.0)
    return i1, rng.uniform(0.2, 2.0 * i1), rng.uniform(0.1, 3.0)  # I₃ ≤ 2 I₁


def _state(rng: np.random.Generator) -> tuple[float, float, float, float]:
    """θ away from the poles (rad), θ̇, φ̇, ψ̇ (rad/s)."""
    return (
        rng.uniform(0.2, math.pi - 0.2),
        rng.uniform(-3.0, 3.0),
        rng.uniform(-3.0, 3.0),
        rng.uniform(-20.0, 20.0),
    )


# ---- the derivation ----------------------------------------------------------------------------


def test_the_derivation_builds_and_every_step_holds(d: Derivation) -> None:
    assert d.name == "heavy_top" and "heavy_top" in derive.names()
    assert len(d.steps) > 40
    for step in d.steps:  # the givens too: each is a definition the model implements
        assert d.holds(step.equation), step.text


def test_results_carry_the_unit_numbers(d: Derivation) -> None:
    assert set(NUMBERS) <= set(d.result)
    assert {"2.119", "cubic", "sleeping", "2.117 slow", "2.117 fast"} <= set(d.functions)
    for number in d.functions:
        assert callable(d.lambdify(number))


def test_rendering(d: Derivation) -> None:
    tex, md = d.latex(), d.markdown()
    for number in NUMBERS:
        assert f"\\tag{{{number}}}" in tex
    assert r"\max" in md and r"\pm" in md and r"\dot{\phi}_{0\,\mathrm{fast}}" in md
    assert r"\frac{\partial L}{\partial \dot{\psi}}" in md


def test_a_false_step_raises(d: Derivation) -> None:
    probe = Derivation("probe", "probe", model=d.model, context=d.context)
    wrong = ht._frac(ht._add(ht.p_phi, ht.p_psi * ht.c), ht._mul(ht.I1, ht.s**2))  # sign of 2.106
    with pytest.raises(PoinsotError, match="does not hold"):
        probe.step("2.106 with a wrong sign", ht._eq(ht.phi_dot, wrong))
    with pytest.raises(PoinsotError, match="does not hold"):  # an inequality that is false
        probe.step("2.118 reversed", ht._at_least(ht._mul(4, ht.mgl, ht.I1, ht.c0), ht.p_psi**2))
    assert probe.steps == []


def test_the_derived_results(d: Derivation) -> None:
    """The corrected 2.117 has p_ψ² under the root, 2.120 no factor ½; 2.119 at θ₀ = 0 is the
    sleeping-top threshold."""
    root = d.result["2.117"][-1].rhs
    assert root.has(ht.p_psi**2) and not root.has(ht.p_phi)
    fast, _ = d.functions["2.120"]
    assert sp.simplify(fast - ht.I3 * ht.omega3 / (ht.I1 * ht.c0)) == 0
    assert d.lambdify("2.119")(1.0, 0.5, 0.3, 0.0) == pytest.approx(
        d.lambdify("sleeping")(1.0, 0.5, 0.3), rel=1e-15
    )


# ---- the unit as printed -----------------------------------------------------------------------


def test_every_numbered_equation_is_transcribed() -> None:
    assert [p.number for p in ht.PRINTED] == NUMBERS
    assert all(p.derivation == "heavy_top" and p.as_printed for p in ht.PRINTED)


def test_the_errata_are_exactly_2_117_and_2_120(errata: dict[str, Any]) -> None:
    assert set(errata) == {"2.117", "2.120"}


def test_erratum_2_117_p_psi_not_p_phi_under_the_root(
    d: Derivation, errata: dict[str, Any]
) -> None:
    e = errata["2.117"]
    assert len(e.failing) == 1  # b = p_φ − p_ψ cos θ₀ holds; the root does not
    assert "p_{\\emptyset}^{2}" in e.as_printed
    assert e.derived is d.result["2.117"]
    # the derived roots satisfy 2.116 at a random top; the printed ones do not
    vals = {ht.I1: 1.3, ht.mgl: 0.7, ht.theta0: 0.6, ht.p_psi: 5.0, ht.p_phi: 4.1}
    for link, ok in ((e.derived[-1], True), (e.printed[-1], False)):
        for sign in (1, -1):
            bval = ht._branch(link.rhs.replace(ht._Bracket, lambda x: x), sign).subs(vals)
            q = ht.QUAD116.subs(ht.b, bval).subs(vals)
            assert (abs(float(q)) < 1e-12) is ok


def test_erratum_2_120_fast_precession_has_no_factor_half(
    d: Derivation, errata: dict[str, Any]
) -> None:
    """seed-errata.md's example: I₁ = 1, I₃ = 0.5, mgl = 0.3, ω₃ = 40, θ₀ = 0.6: the exact fast
    root 24.2176, the corrected 2.120 24.2326, the printed one half of it."""
    i1, i3, mgl, w3, th0 = 1.0, 0.5, 0.3, 40.0, 0.6
    exact_fast = d.lambdify("2.117 fast")(i1, i3, mgl, th0, w3)
    exact_slow = d.lambdify("2.117 slow")(i1, i3, mgl, th0, w3)
    corrected = d.lambdify("2.120")(i1, i3, th0, w3)
    printed_rhs = errata["2.120"].printed[-1].rhs
    printed = float(printed_rhs.subs({ht.I1: i1, ht.I3: i3, ht.omega3: w3, ht.theta0: th0}))
    assert round(exact_fast, 4) == 24.2176
    assert round(corrected, 4) == 24.2326
    assert printed == pytest.approx(corrected / 2, rel=1e-15)
    assert abs(corrected - exact_fast) / exact_fast < 1e-3 < abs(printed - exact_fast) / exact_fast
    assert d.lambdify("2.121")(i3, mgl, w3) == pytest.approx(exact_slow, rel=1e-3)
    assert len(errata["2.120"].failing) == 1  # p_ψ/(2I₁cos θ₀) = I₃ω₃/(2I₁cos θ₀) holds


def test_judge_negative_controls(d: Derivation) -> None:
    """A right printed equation with one term changed is reported; the right ones are not."""
    right = {p.number: p for p in ht.PRINTED if p.number not in ("2.117", "2.120")}
    assert judge(right.values(), {"heavy_top": d}) == []
    p113 = right["2.113"]
    changed = Printed(
        "2.113",
        "heavy_top",
        p113.as_printed,
        ht._eq(p113.equation.lhs, ht._add(p113.equation.rhs.args[0], ht._mul(ht.mgl, ht.s))),
    )
    p107 = right["2.107"]
    terms = list(p107.equation.rhs.args)
    terms[2] = ht._frac(ht.p_psi**2, ht.I3)  # p_ψ²/I₃ for p_ψ²/(2I₃)
    changed2 = Printed("2.107", "heavy_top", p107.as_printed, ht._eq(ht.E, ht._add(*terms)))
    changed3 = Printed(  # 2.119 with I₁ for I₃
        "2.119",
        "heavy_top",
        right["2.119"].as_printed,
        ht._at_least(ht.omega3, ht.MIN_SPIN.subs(ht.I3, 2 * ht.I1)),
    )
    found = judge([changed, changed2, changed3], {"heavy_top": d})
    assert [e.number for e in found] == ["2.113", "2.107", "2.119"]


# ---- the bridge to the core ------------------------------------------------------------------


def test_bridge_lagrangian_and_constants_of_state(d: Derivation) -> None:
    """2.102–2.105 against HeavyTop.lagrangian and HeavyTop.constants_of_state."""
    rng, w = np.random.default_rng(102), _Worst()
    lag, p103, p104, e105 = (_exact(d, k) for k in ("2.102", "2.103", "2.104", "2.105"))
    for _ in range(N):
        i1, i3, mgl = _top(rng)
        th, thd, phd, psd = _state(rng)
        spin = psd + phd * math.cos(th)
        scale_p = i1 * abs(phd) + i3 * abs(spin)
        scale_e = 0.5 * i1 * (thd**2 + phd**2) + 0.5 * i3 * spin**2 + mgl
        w.check(
            "2.102 L",  # crosses zero: floor, the size of its terms
            HeavyTop.lagrangian(i1, i3, mgl, th, thd, phd, psd),
            lag(i1, i3, mgl, th, thd, phd, psd),
            scale_e,
        )
        k = HeavyTop.constants_of_state(i1, i3, mgl, th, thd, phd, psd)
        w.check("2.103 p_psi", k["p_psi"], p103(i3, th, phd, psd), i3 * abs(spin))
        w.check("2.104 p_phi", k["p_phi"], p104(i1, i3, th, phd, psd), scale_p)
        w.check("2.105 E", k["energy"], e105(i1, i3, mgl, th, thd, phd, psd), scale_e)
        # the numpy form agrees with the exact one
        assert d.lambdify("2.105")(i1, i3, mgl, th, thd, phd, psd) == pytest.approx(
            k["energy"], rel=1e-12, abs=1e-12 * scale_e
        )
    w.report()


def test_bridge_reduced_energy_and_effective_potential(d: Derivation) -> None:
    """2.109, 2.110, 2.113 against HeavyTop.reduced_energy, effective_potential and
    effective_potential_derivative, the constants from the derived 2.103–2.104 of the state."""
    rng, w = np.random.default_rng(109), _Worst()
    p103, p104, e109, v110, dv113 = (
        _exact(d, k) for k in ("2.103", "2.104", "2.109", "2.110", "2.113")
    )
    for _ in range(N):
        i1, i3, mgl = _top(rng)
        th, thd, phd, psd = _state(rng)
        top = HeavyTop(i1, i3, mgl, th, theta_dot=thd, phi_dot=phd, psi_dot=psd)
        p_phi, p_psi = p104(i1, i3, th, phd, psd), p103(i3, th, phd, psd)
        spin = psd + phd * math.cos(th)
        scale_e = 0.5 * i1 * (thd**2 + phd**2) + 0.5 * i3 * spin**2 + mgl
        w.check("2.109 E'", top.reduced_energy, e109(i1, mgl, p_phi, p_psi, th, thd), scale_e)
        for x in rng.uniform(0.2, math.pi - 0.2, 3):
            with mp.workdps(50):
                kin = float((p_phi - p_psi * mp.cos(x)) ** 2 / (2 * i1 * mp.sin(x) ** 2))
            v = v110(i1, mgl, p_phi, p_psi, x)
            w.check("2.110 V", float(top.effective_potential(x)), v, kin + mgl)
            dv = dv113(i1, mgl, p_phi, p_psi, x)
            w.check(
                "2.113 dV/dθ",
                float(top.effective_potential_derivative(x)),
                dv,
                abs(float(dv) + mgl * math.sin(x)) + mgl,
            )
    w.report()


def test_bridge_cubic_and_turning_points(d: Derivation) -> None:
    """The roots of the derived cubic f(u) (mpmath, 50 digits, from the constants of the state
    by the derived 2.103, 2.104, 2.109) against HeavyTop.cubic_roots and turning_points."""
    rng, w = np.random.default_rng(111), _Worst()
    expr, syms = d.functions["cubic"]
    coeffs = [sp.lambdify(syms[:-1], k, "mpmath") for k in sp.Poly(expr, syms[-1]).all_coeffs()]
    p103, p104, e109 = (_exact(d, k) for k in ("2.103", "2.104", "2.109"))
    for _ in range(N):
        i1, i3, mgl = _top(rng)
        th, thd, phd, psd = _state(rng)
        top = HeavyTop(i1, i3, mgl, th, theta_dot=thd, phi_dot=phd, psi_dot=psd)
        p_phi, p_psi = p104(i1, i3, th, phd, psd), p103(i3, th, phd, psd)
        with mp.workdps(50):
            e_red = e109(i1, mgl, p_phi, p_psi, th, thd)
            cs = [k(i1, mgl, p_phi, p_psi, e_red) for k in coeffs]
            roots = sorted(
                (mp.re(z) for z in mp.polyroots(cs, maxsteps=200, extraprec=300)), key=float
            )
            thetas = (mp.acos(roots[1]), mp.acos(roots[0]))
        for k, (core, ref) in enumerate(zip(top.cubic_roots, roots), 1):
            w.check(f"u{k}", core, ref, 1.0)  # u = cos θ crosses zero: floor 1
        for k, (core, ref) in enumerate(zip(top.turning_points, thetas), 1):
            w.check(f"θ{k}", core, ref)
    w.report()


def test_bridge_steady_precession(d: Derivation) -> None:
    """2.117's two exact rates, 2.119, 2.120 (corrected and as printed), 2.121 against
    HeavyTop.steady_precession and HeavyTop.min_spin, for θ₀ < π/2 and ω₃ above the minimum."""
    rng, w = np.random.default_rng(117), _Worst()
    slow, fast, spin_min, f120, f121 = (
        _exact(d, k) for k in ("2.117 slow", "2.117 fast", "2.119", "2.120", "2.121")
    )
    printed = ht.PRINTED[[p.number for p in ht.PRINTED].index("2.120")].equation[-1].rhs
    f120_printed = sp.lambdify((ht.I1, ht.I3, ht.theta0, ht.omega3), printed, "mpmath")
    for _ in range(N):
        i1, i3, mgl = _top(rng)
        th0 = rng.uniform(0.05, 1.45)
        w_min = spin_min(i1, i3, mgl, th0)
        w.check("2.119 min_spin", HeavyTop.min_spin(i1, i3, mgl, th0), w_min)
        w3 = float(w_min) * rng.uniform(1.05, 30.0)
        s = HeavyTop.steady_precession(i1, i3, mgl, th0, w3)
        w.check("2.117 slow", s.slow, slow(i1, i3, mgl, th0, w3))
        w.check("2.117 fast", s.fast, fast(i1, i3, mgl, th0, w3))
        w.check("2.119", s.min_spin, w_min)
        w.check("2.120", s.fast_approx, f120(i1, i3, th0, w3))
        with mp.workdps(50):
            w.check("2.120 as printed", s.fast_approx_as_printed, f120_printed(i1, i3, th0, w3))
        assert s.slow_approx is not None
        w.check("2.121", s.slow_approx, f121(i3, mgl, w3))
    w.report()


def test_bridge_sleeping_top(d: Derivation) -> None:
    """The sleeping-top threshold against HeavyTop.sleeping_threshold, and its stability against
    HeavyTop.is_sleeping_stable on either side of it."""
    rng, w = np.random.default_rng(121), _Worst()
    threshold = _exact(d, "sleeping")
    for _ in range(N):
        i1, i3, mgl = _top(rng)
        ref = threshold(i1, i3, mgl)
        w.check("sleeping", HeavyTop.sleeping_threshold(i1, i3, mgl), ref)
        for factor in (0.7, 0.99, 1.01, 3.0):
            top = HeavyTop.from_spin(i1, i3, mgl, 0.0, factor * float(ref))
            assert top.is_sleeping_stable is (factor > 1)
    w.report()
