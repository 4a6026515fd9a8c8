"""Tests of the derivation "earth" (poinsot.derive.earth: the unit's eqs. 2.29–2.42 and the
second-order southward deflection 2.42a–2.42c): it builds and every step holds, the errata it
finds are exactly the misprints of its range, a false step is refused, and the derived formulas
agree with the Rust core (poinsot.Earth) at random inputs — exactly where the core computes the
same closed form, and to the next order of the series where the core integrates the drop."""

from __future__ import annotations

import dataclasses
import time
from typing import Any

import numpy as np
import pytest

sp = pytest.importorskip("sympy")

import poinsot as ps  # noqa: E402
from poinsot.derive import (  # noqa: E402
    Derivation,
    earth,
    judge,
)

#: The exact bridge: relative difference between the lambdified result and the core.
RTOL = 1e-12
N_POINTS = 30


@pytest.fixture(scope="module")
def d() -> Derivation:
    start = time.perf_counter()
    out = earth.derive()
    print(f"derive() earth: {time.perf_counter() - start:.3f} s")
    return out


@pytest.fixture(scope="module")
def fns(d: Derivation) -> dict[str, Any]:
    return {k: d.lambdify(k) for k in d.functions}


def _eq(lhs: Any, rhs: Any) -> Any:
    return sp.Eq(lhs, rhs, evaluate=False)


def _rel(a: Any, b: Any) -> float:
    """Largest difference relative to the largest component of ``b``."""
    a, b = np.asarray(a, float).ravel(), np.asarray(b, float).ravel()
    assert a.shape == b.shape
    return float(np.max(np.abs(a - b)) / np.max(np.abs(b)))


# ---- the derivation -----------------------------------------------------------------------------


def test_the_derivation_builds_and_every_step_holds(d: Derivation) -> None:
    assert d.name == "earth" and d.steps
    for s in d.steps:
        assert d.holds(s.equation), s.text


def test_results_carry_the_unit_numbers_and_the_second_order(d: Derivation) -> None:
    unit = {f"2.{k}" for k in range(29, 43)}
    second = {"2.42a", "2.42b", "2.42c"}
    numbers = {"Earth's rate", "centrifugal at the equator", "Coriolis at the poles"}
    assert unit | second | numbers | {"2.42 at 100 m"} == set(d.result)
    assert set(d.functions) == {
        "2.30",
        "2.31",
        "2.33",
        "centrifugal",
        "2.41",
        "2.42",
        "2.42a",
        "2.42b",
        "2.42c",
    }


def test_the_derived_forms(d: Derivation) -> None:
    """The results say what the unit (corrected) and the issue say."""
    w, g, h, lam, m = earth.omega, earth.g, earth.h, earth.lam, earth.m
    last = {k: (v[-1] if isinstance(v, list) else v) for k, v in d.result.items()}
    s2 = w**2 * sp.sin(2 * lam) * h**2 / g
    assert d.holds(_eq(last["2.42"].rhs, w * sp.cos(lam) * sp.sqrt(8 * h**3 / g) / 3))
    assert d.holds(_eq(last["2.42a"].rhs, -s2 / 3))
    assert d.holds(_eq(last["2.42b"].rhs, -5 * s2 / 12))
    assert d.holds(_eq(last["2.42c"].rhs, 3 * s2 / 4))
    # 2.30 with the mass on the Coriolis term
    mg_e = m * (earth.gv - earth.Cross(earth.W, earth.Cross(earth.W, earth.r)))
    coriolis = -2 * m * earth.Cross(earth.W, earth.DtRot(earth.r))
    assert d.holds(_eq(last["2.30"].rhs, earth.F + mg_e + coriolis))
    assert not d.holds(_eq(last["2.30"].rhs, earth.F + mg_e + coriolis / m))
    assert d.holds(_eq(last["2.41"].rhs, sp.sqrt(2 * h / g)))


def test_the_steps_cite_the_unit_and_say_where_it_errs(d: Derivation) -> None:
    text = {s.number: s.text for s in d.steps if s.number}
    assert "lost" in text["2.30"] and "7.25" in text["Earth's rate"]
    assert any("this derivation's numbers" in s.text for s in d.steps)
    md = d.markdown()
    assert r"\tag{2.42c}" in md and r"\tag{Earth's rate}" in md


# ---- the unit as printed ------------------------------------------------------------------------


def test_every_numbered_equation_of_the_range_is_transcribed() -> None:
    numbers = [p.number for p in earth.PRINTED]
    assert {f"2.{k}" for k in range(29, 43)} <= set(numbers)
    assert len(numbers) == len(set(numbers))
    assert all(p.derivation == "earth" and p.as_printed for p in earth.PRINTED)


def test_the_errata_are_exactly_the_misprints_of_the_range(d: Derivation) -> None:
    """2.30 (mass missing on the Coriolis term) and the Earth's rate (7.25e-5 for 7.27e-5), as
    seed-errata.md lists them; nothing else of 2.29–2.42 is wrong."""
    errata = judge(earth.PRINTED, {"earth": d})
    assert [e.number for e in errata] == ["2.30", "Earth's rate"]
    by = {e.number: e for e in errata}
    # the rate's first link, ω = 2π/(24·60·60), is right; only the value 7.25e-5 is wrong
    (failing,) = by["Earth's rate"].failing
    assert "7.25" in sp.latex(failing.rhs)
    assert "7.27" in by["Earth's rate"].derived_latex()
    assert "2 m" in by["2.30"].derived_latex()


def _changed(number: str, eq: Any) -> list[Any]:
    return [dataclasses.replace(p, equation=eq) for p in earth.PRINTED if p.number == number]


def test_negative_control_a_changed_term_is_reported(d: Derivation) -> None:
    w, g, h, t = earth.omega, earth.g, earth.h, earth.t
    theta = earth.theta
    ok = [p for p in earth.PRINTED if p.number in ("2.35", "2.38", "2.42", "2.39")]
    assert judge(ok, {"earth": d}) == []  # right as printed
    wrong = (
        # 2.35 with sin for cos
        _changed("2.35", sp.Eq(earth.x1.diff(t, 2), 2 * w * g * t * sp.sin(theta), evaluate=False))
        # 2.38 with ½ for ⅓
        + _changed("2.38", sp.Eq(earth.x1, w * g * t**3 * sp.cos(theta) / 2, evaluate=False))
        # 2.39 with +½gt²
        + _changed("2.39", sp.Eq(earth.z1, earth.z_0 + g * t**2 / 2, evaluate=False))
        # the 100 m example as 1.65e-2
        + _changed(
            "2.42 at 100 m", sp.Eq(earth._Num(earth.x1.subs(t, earth.T), 3), earth._Dec("1.65e-2"))
        )
        # 2.42's second link with h² for h³
        + _changed(
            "2.42",
            [
                sp.Eq(earth.x1.subs(t, earth.T), w * g * sp.cos(theta) * (2 * h / g) ** 1.5 / 3),
                sp.Eq(
                    w * g * sp.cos(theta) * (2 * h / g) ** 1.5 / 3,
                    w * sp.cos(theta) * sp.sqrt(8 * h**2 / g) / 3,
                ),
            ],
        )
    )
    assert [e.number for e in judge(wrong, {"earth": d})] == [
        "2.35",
        "2.38",
        "2.39",
        "2.42 at 100 m",
        "2.42",
    ]


def test_negative_control_a_false_step_raises() -> None:
    probe = Derivation("probe", "probe", model=earth._model())
    w, g, h, lam = earth.omega, earth.g, earth.h, earth.lam
    with pytest.raises(ps.PoinsotError, match="does not hold"):
        # the southward deflection with ½ for 5/12 from the centrifugal force
        probe.step(
            "false",
            sp.Eq(earth.y_cf.subs(earth.t, earth.T), -(w**2) * sp.sin(2 * lam) * h**2 / (2 * g)),
        )
    with pytest.raises(ps.PoinsotError, match="does not hold"):
        # the unit's 2.30 without the mass
        probe.step("false", earth.PRINTED[1].equation)
    assert probe.steps == []


# ---- the bridge to the core ---------------------------------------------------------------------


def _earths(rng: np.random.Generator) -> Any:
    for _ in range(N_POINTS):
        w = 10 ** rng.uniform(-6, -2)  # rad/s
        radius = rng.uniform(1e5, 1e8)  # m
        g = rng.uniform(0.5, 30.0)  # m/s²
        lat = rng.uniform(-np.pi / 2, np.pi / 2)
        h = 10 ** rng.uniform(-1, 5)  # m
        yield ps.Earth(w, radius, g), w, radius, g, lat, h


def test_bridge_exact_closed_forms(fns: dict[str, Any]) -> None:
    """Where the core computes the same closed form: ω (2.33), g_e and the centrifugal
    acceleration at the surface (2.31), the Coriolis acceleration (2.30), the time of fall
    (2.41), the eastward (2.42) and southward (2.42c) deflections. Relative to the largest
    component (components cross zero with the latitude)."""
    worst: dict[str, float] = {}
    rng = np.random.default_rng(20240614)
    for e, w, radius, g, lat, h in _earths(rng):
        vel = rng.normal(size=3) * 10 ** rng.uniform(-2, 3)
        pairs = {
            "2.33": (fns["2.33"](w, lat), e.omega_enu(lat)),
            "2.31": (fns["2.31"](w, radius, g, lat), e.effective_gravity(lat)),
            "centrifugal": (fns["centrifugal"](w, radius, lat), e.centrifugal_acceleration(lat)),
            "2.30": (fns["2.30"](w, lat, *vel), e.coriolis_acceleration(lat, vel)),
            "2.41": (fns["2.41"](h, g), e.fall_time(h)),
            "2.42": (fns["2.42"](w, h, lat, g), e.eastward_deflection(h, lat)),
            "2.42c": (fns["2.42c"](w, h, lat, g), e.southward_deflection(h, lat)),
        }
        for k, (ours, core) in pairs.items():
            if k in ("2.42", "2.42c") and abs(core) == 0:
                continue  # the poles (east) / the equator (south): no scale to compare
            worst[k] = max(worst.get(k, 0.0), _rel(ours, core))
    print("worst relative differences:", {k: f"{v:.1e}" for k, v in worst.items()})
    assert max(worst.values()) <= RTOL, worst


def _next_order(centrifugal: bool) -> tuple[Any, Any]:
    """The next terms of the series for the landing point, x at order ω³ and y at order ω⁴,
    from the module's successive approximations carried to ρ_(4) and the landing time
    T + τ ω² (z = 0 at order ω²): functions of (ω, h, λ, g)."""
    w, g, h, lam, t = earth.omega, earth.g, earth.h, earth.lam, earth.t
    rho4 = earth._successive(4, centrifugal)[4]
    tau = sp.Symbol("tau")
    at = [sp.expand(c.subs(t, sp.sqrt(2 * h / g) + tau * w**2)) for c in rho4]
    (shift,) = sp.solve(at[2].coeff(w, 2), tau)
    x3 = at[0].coeff(w, 3).subs(tau, shift) * w**3
    y4 = at[1].coeff(w, 4).subs(tau, shift) * w**4
    args = (w, h, lam, g)
    return sp.lambdify(args, x3, "numpy"), sp.lambdify(args, y4, "numpy")


@pytest.mark.parametrize(("centrifugal", "south"), [(True, "2.42c"), (False, "2.42a")])
def test_bridge_the_exact_drop_to_the_next_order(
    fns: dict[str, Any], centrifugal: bool, south: str
) -> None:
    """The core integrates the drop exactly (uniform gravity, to 1e-12); the series 2.42 and
    2.42c (or 2.42a, Coriolis only, where the core leaves out the change of the centrifugal
    force) differ from it by the next order, relative (ωT)²: x by the ω³ term, y by the ω⁴ term
    (computed by carrying the same approximation two orders further). What is left after the
    next order is of relative order (ωT)⁴. The y scale is ω²h²/g, an absolute floor: y crosses
    zero at the equator and the poles. ωT in [0.03, 0.1] keeps (ωT)⁴ far above the
    integrator's 1e-12."""
    x3, y4 = _next_order(centrifugal)
    rng = np.random.default_rng(1414 + centrifugal)
    worst_series = worst_next = 0.0
    for _ in range(N_POINTS):
        w = 10 ** rng.uniform(-5, -2)
        g = rng.uniform(1.0, 25.0)
        lat = rng.uniform(-np.pi / 2, np.pi / 2) * 0.98
        wt = rng.uniform(0.03, 0.1)
        h = 0.5 * g * (wt / w) ** 2  # T = √(2h/g) = wt / w
        fall = ps.Earth(w, 6.4e6, g).drop(h, lat, centrifugal=centrifugal)
        x1 = fns["2.42"](w, h, lat, g)
        y2 = -fns[south](w, h, lat, g)  # north component
        y_scale = w**2 * h**2 / g
        dx, dy = fall.east - x1, fall.north - y2
        # the series is right to its order: the rest is the next order, at most 0.6 (ωT)² (x)
        # and 0.37 (ωT)² (y) at any latitude, plus the order after it
        assert abs(dx) <= (0.6 * wt**2 + wt**4) * abs(x1)
        assert abs(dy) <= (0.37 * wt**2 + wt**4) * y_scale
        # and the next order is the one the approximation predicts
        rx = abs(dx - x3(w, h, lat, g)) / (wt**4 * abs(x1))
        ry = abs(dy - y4(w, h, lat, g)) / (wt**4 * y_scale)
        assert rx <= 1.0 and ry <= 1.0, (rx, ry, wt, lat)
        worst_series = max(worst_series, abs(dx) / (wt**2 * abs(x1)), abs(dy) / (wt**2 * y_scale))
        worst_next = max(worst_next, rx, ry)
    print(
        f"centrifugal={centrifugal}: |series − exact| ≤ {worst_series:.2f} (ωT)² scale, "
        f"after the next order ≤ {worst_next:.2f} (ωT)⁴ scale"
    )


def test_bridge_the_two_second_order_parts(fns: dict[str, Any]) -> None:
    """2.42a + 2.42b = 2.42c (the core's southward deflection), at random inputs."""
    rng = np.random.default_rng(7)
    for e, w, _radius, g, lat, h in _earths(rng):
        core = e.southward_deflection(h, lat)
        ours = fns["2.42a"](w, h, lat, g) + fns["2.42b"](w, h, lat, g)
        assert abs(ours - core) <= RTOL * abs(core)


def _to_digits(value: float, printed: str) -> bool:
    """Whether ``value`` rounds to ``printed`` ("3.38e-02") at the digits printed."""
    n = len(printed.split("e")[0].split(".")[1])
    return f"{value:.{n}e}" == printed


@pytest.mark.parametrize(
    ("rate", "g", "centrifugal", "coriolis", "east"),
    [
        (ps.SOLAR_DAY_RATE, 9.81, "3.38e-02", "1.45e-04", "1.548e-02"),
        (ps.SIDEREAL_RATE, 9.80665, "3.40e-02", "1.458e-04", "1.552e-02"),
    ],
)
def test_the_checked_numbers(
    fns: dict[str, Any], rate: float, g: float, centrifugal: str, coriolis: str, east: str
) -> None:
    """seed-errata.md's checked numbers, from the derived formulas and from the core: ω²r at
    the equator with r = 6.4e6 m, the largest horizontal Coriolis factor 2ω (at the pole), and
    the eastward deflection of a body dropped 100 m at 45° (2.42)."""
    e = ps.Earth(rate, 6.4e6, g)
    c = float(np.linalg.norm(fns["centrifugal"](rate, 6.4e6, 0.0)))
    assert abs(c - np.linalg.norm(e.centrifugal_acceleration(0.0))) <= RTOL * c
    assert _to_digits(c, centrifugal)
    # the Coriolis acceleration of a unit horizontal velocity at the pole: 2ω
    two_w = float(np.linalg.norm(fns["2.30"](rate, np.pi / 2, 1.0, 0.0, 0.0)))
    assert abs(two_w - e.coriolis_parameter(np.pi / 2)) <= RTOL * two_w
    assert _to_digits(two_w, coriolis)
    x = float(fns["2.42"](rate, 100.0, np.pi / 4, g))
    assert abs(x - e.eastward_deflection(100.0, np.pi / 4)) <= RTOL * x
    assert _to_digits(x, east)
