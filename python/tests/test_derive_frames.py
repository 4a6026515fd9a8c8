"""The derivation of the unit's 2.1–2.28 (poinsot.derive.frames): it builds, every step holds,
its numbered results match the Rust core at random frames (the bridge), and the printed
equations it judges wrong are exactly the unit's misprints of that range."""

from __future__ import annotations

import dataclasses
import time

import numpy as np
import pytest

sp = pytest.importorskip("sympy")

import poinsot as ps  # noqa: E402
from poinsot import derive  # noqa: E402
from poinsot.derive import _core  # noqa: E402
from poinsot.derive import frames as fr  # noqa: E402

NUMBERS = [f"2.{k}" for k in range(1, 29)]

#: The misprints of 2.1–2.28: seed-errata.md's (2.2, 2.3, 2.5, 2.10, 2.18, 2.26) and those the
#: computation found besides (2.7: a stray dot on z′; 2.16: ω for ω̇; 2.22, 2.23: r⃗_f for the
#: rotating-frame rate, and in 2.23 ω × r for ω̇ × r).
MISPRINTS = ["2.2", "2.3", "2.5", "2.7", "2.10", "2.16", "2.18", "2.22", "2.23", "2.26"]
SEED_ERRATA = {"2.2", "2.3", "2.5", "2.10", "2.18", "2.26"}

N_POINTS = 30
RTOL = 1e-12


@pytest.fixture(scope="module")
def d() -> _core.Derivation:
    t0 = time.perf_counter()
    out = fr.derive()
    print(f"\nframes: derive() {time.perf_counter() - t0:.3f} s")
    return out


def _rel(a, b) -> float:
    a, b = np.asarray(a, float).ravel(), np.asarray(b, float).ravel()
    return float(np.linalg.norm(a - b) / np.linalg.norm(b))


def _vec(f, *args) -> np.ndarray:
    return np.asarray(f(*args), dtype=float).reshape(3)


def _frames(seed: int):
    """Random frames (attitude, R, Ṙ, R̈, ω, ω̇ in fixed components) and particle states (r,
    ṙ, r̈ in moving components) and masses."""
    rng = np.random.default_rng(seed)
    for _ in range(N_POINTS):
        att = ps.euler_to_matrix(rng.uniform(-np.pi, np.pi, 3))
        v = {k: rng.normal(size=3) for k in ("R", "Rd", "Rdd", "w", "wd", "r", "rd", "rdd", "F")}
        yield att, v, float(rng.uniform(0.1, 10.0))


def _frame(att, v, **zero) -> ps.MovingFrame:
    pick = lambda k: np.zeros(3) if zero.get(k) else v[k]
    return ps.MovingFrame(
        origin=v["R"],
        velocity=v["Rd"],
        acceleration=pick("Rdd"),
        angular_velocity=pick("w"),
        angular_acceleration=pick("wd"),
        attitude=att,
    )


# ---- the derivation --------------------------------------------------------------------------


def test_builds_and_every_recorded_step_holds(d):
    assert d.name == "frames" and d.steps
    assert derive.derivation("frames").result.keys() == d.result.keys()  # the registry's
    for s in d.steps:
        assert d.holds(s.equation), s.text


def test_results_carry_every_number_of_the_range(d):
    assert set(d.result) == set(NUMBERS)
    assert set(d.functions) == {"2.1", "2.2", "2.3", "2.5", "2.20", "2.21", "2.24", "2.27", "2.28"}


def test_renders_in_the_units_notation(d):
    md, tex = d.markdown(), d.latex()
    assert r"\tag{2.21}" in md and r"\tag{2.28}" in tex
    assert r"\ddot{\vec{r}}'_{f} = \ddot{\vec{R}}_{f} + \ddot{\vec{r}}_{r}" in md  # 2.23
    assert r"\dot{\vec{\omega}} \times \vec{r}" in md
    assert not any("(t)" in s.latex() for s in d.steps)  # no "(t)" in the equations


def test_a_false_step_raises(d):
    big_v, w = fr._P["V"], fr._P["omega"]
    with pytest.raises(ps.PoinsotError, match="does not hold"):
        d.step("(d/dt)_fix is (d/dt)_rot", sp.Eq(_core.DtFix(big_v), _core.DtRot(big_v)))
    # in the explicit-axes setting too: dî/dt is ω × î, not ω × ĵ
    with pytest.raises(ps.PoinsotError, match="does not hold"):
        d.step("wrong axis", sp.Eq(_core.DtFix(fr._I), _core.Cross(fr._X["omega"], fr._J)))
    # and a step mixing the settings of two paragraphs is refused
    with pytest.raises(ps.PoinsotError, match="mixes"):
        d.step("mixed", sp.Eq(_core.Cross(w, fr._X["V"]), fr.ZERO))
    assert "wrong axis" not in [s.text for s in d.steps]


def test_the_axes_setting_checks_2_13_2_14_rather_than_assuming_them(d):
    # There (d/dt)_fix X = Rᵀ d/dt (R X) with R = R_z(φ)R_x(θ)R_z(ψ) and ω⃗ has 2.99's components
    # on the rotating axes: RᵀṘ = [ω]× holds, ṘRᵀ = [ω]× (the fixed-axes form) does not, and
    # 2.14 holds only with its ω⃗ × V⃗ term.
    big_v, w = fr._X["V"], fr._X["omega"]
    assert d.holds(sp.Eq(fr.MAT_R.T * fr.MAT_RDOT, fr.MAT_OMEGA))
    assert not d.holds(sp.Eq(fr.MAT_RDOT * fr.MAT_R.T, fr.MAT_OMEGA))
    assert d.holds(sp.Eq(_core.DtFix(big_v), _core.DtRot(big_v) + _core.Cross(w, big_v)))
    assert not d.holds(sp.Eq(_core.DtFix(big_v), _core.DtRot(big_v)))


# ---- the bridge to the core -------------------------------------------------------------------


def test_bridge_translation_2_1_to_2_5(d):
    f1, f2, f3, f5 = (d.lambdify(n) for n in ("2.1", "2.2", "2.3", "2.5"))
    worst = 0.0
    for att, v, m in _frames(1):
        frame = _frame(att, v, w=True, wd=True)  # the frame only translates
        out = frame.to_fixed(v["r"], v["rd"], v["rdd"])
        worst = max(
            worst,
            _rel(_vec(f1, v["R"], att @ v["r"]), out.position),
            _rel(_vec(f2, v["Rd"], att @ v["rd"]), out.velocity),
            _rel(_vec(f3, v["Rdd"], att @ v["rdd"]), out.acceleration),
        )
        # 2.5 in moving components: F_eff = F − m R̈
        forces = frame.fictitious_forces(m, v["r"], v["rd"])
        core = v["F"] + sum(forces.values())
        worst = max(worst, _rel(_vec(f5, v["F"], m, att.T @ v["Rdd"]), core))
    print(f"2.1–2.5 worst relative difference {worst:.2e}")
    assert worst <= RTOL


def test_bridge_velocity_and_acceleration_2_20_2_21(d):
    f20, f21 = d.lambdify("2.20"), d.lambdify("2.21")
    worst = 0.0
    for att, v, _ in _frames(2):
        out = _frame(att, v).to_fixed(v["r"], v["rd"], v["rdd"])
        r, rd, rdd = att @ v["r"], att @ v["rd"], att @ v["rdd"]  # fixed components
        w, wd, z = v["w"], v["wd"], np.zeros(3)
        worst = max(
            worst,
            _rel(_vec(f20, v["Rd"], rd, w, r), out.velocity),
            _rel(_vec(f21, v["Rdd"], rdd, w, rd, r, wd), out.acceleration),
            # each named term of 2.21 alone (the others' inputs zero)
            _rel(_vec(f21, z, z, w, rd, z, z), out.acceleration_terms["coriolis"]),
            _rel(_vec(f21, z, z, w, z, r, z), out.acceleration_terms["centripetal"]),
            _rel(_vec(f21, z, z, z, z, r, wd), out.acceleration_terms["euler"]),
            _rel(_vec(f21, z, rdd, z, z, z, z), out.acceleration_terms["relative"]),
        )
    print(f"2.20–2.21 worst relative difference {worst:.2e}")
    assert worst <= RTOL


def test_bridge_centripetal_magnitude_2_24(d):
    f24 = d.lambdify("2.24")
    worst = 0.0
    for att, v, _ in _frames(3):
        out = _frame(att, v).to_fixed(v["r"])
        w, r = v["w"], att @ v["r"]
        theta = np.arctan2(np.linalg.norm(np.cross(w, r)), w @ r)
        mine = float(f24(np.linalg.norm(w), np.linalg.norm(r), theta))
        worst = max(worst, _rel(mine, np.linalg.norm(out.acceleration_terms["centripetal"])))
    print(f"2.24 worst relative difference {worst:.2e}")
    assert worst <= RTOL


def test_bridge_fictitious_forces_2_27(d):
    f27 = d.lambdify("2.27")
    worst = 0.0
    for att, v, m in _frames(4):
        core = _frame(att, v).fictitious_forces(m, v["r"], v["rd"])
        # moving components throughout, as the core gives the forces
        F, Rdd, w, wd = v["F"], att.T @ v["Rdd"], att.T @ v["w"], att.T @ v["wd"]
        r, rd, z = v["r"], v["rd"], np.zeros(3)
        total = F + sum(core.values())
        worst = max(
            worst,
            _rel(_vec(f27, F, m, Rdd, w, rd, r, wd), total),
            _rel(_vec(f27, z, m, Rdd, z, z, z, z), core["translational"]),
            _rel(_vec(f27, z, m, z, w, rd, z, z), core["coriolis"]),
            _rel(_vec(f27, z, m, z, w, z, r, z), core["centrifugal"]),
            _rel(_vec(f27, z, m, z, z, z, r, wd), core["euler"]),
        )
    print(f"2.27 worst relative difference {worst:.2e}")
    assert worst <= RTOL


def test_bridge_observer_at_rest_2_28(d):
    f28 = d.lambdify("2.28")
    worst = 0.0
    for att, v, m in _frames(5):
        frame = _frame(att, v, Rdd=True, wd=True)  # ω constant, origin not accelerated
        core = frame.fictitious_forces(m, v["r"], np.zeros(3))
        total = v["F"] + sum(core.values())
        worst = max(worst, _rel(_vec(f28, v["F"], m, att.T @ v["w"], v["r"]), total))
    print(f"2.28 worst relative difference {worst:.2e}")
    assert worst <= RTOL


# ---- the unit as printed ----------------------------------------------------------------------


def test_every_numbered_equation_is_transcribed():
    assert [p.number for p in fr.PRINTED] == sorted(
        (p.number for p in fr.PRINTED), key=lambda n: float(n[2:])
    )
    assert {p.number for p in fr.PRINTED} == set(NUMBERS)
    assert all(p.derivation == "frames" and p.as_printed for p in fr.PRINTED)


def test_errata_are_exactly_the_misprints_of_the_range(d):
    errata = _core.judge(fr.PRINTED, {"frames": d})
    assert [e.number for e in errata] == MISPRINTS
    assert {e.number for e in errata} >= SEED_ERRATA
    by = {e.number: e for e in errata}
    for e in errata:
        assert e.derived is d.result[e.number]
    # 2.2, 2.3: the printed r⃗′ is not the velocity (acceleration) the text says it is
    assert len(by["2.2"].failing) == 1 and by["2.2"].failing[0].rhs == fr._T["r'"]
    # 2.7: only the third line (ż′), and only its left side
    sevens = [p for p in fr.PRINTED if p.number == "2.7"]
    assert by["2.7"].printed is sevens[2].equation and len(by["2.7"].failing) == 1
    # 2.18: the third line is the one that breaks the chain (the links into and out of it)
    chain = by["2.18"].printed
    assert by["2.18"].failing == (chain[2], chain[3])
    # 2.26: the condition ω⃗ = 0, not the equation
    assert by["2.26"].as_printed == r"\vec{\omega}=0"


def test_judge_negative_controls(d):
    printed = {p.number: p for p in fr.PRINTED}
    right = [printed[n] for n in ("2.14", "2.20", "2.21", "2.28")]
    assert _core.judge(right, {"frames": d}) == []
    # 2.20 with the relative velocity taken in the fixed frame (one term changed)
    r, w = fr._P["r"], fr._P["omega"]
    eq = printed["2.20"].equation
    wrong = dataclasses.replace(
        printed["2.20"], equation=sp.Eq(eq.lhs, eq.rhs.subs(_core.DtRot(r), _core.DtFix(r)))
    )
    # 2.21 without the factor 2 of the Coriolis term
    eq = printed["2.21"].equation
    coriolis = 2 * _core.Cross(w, _core.DtRot(r))
    no_two = dataclasses.replace(
        printed["2.21"], equation=sp.Eq(eq.lhs, eq.rhs.subs(coriolis, coriolis / 2))
    )
    assert [e.number for e in _core.judge([wrong, no_two], {"frames": d})] == ["2.20", "2.21"]
