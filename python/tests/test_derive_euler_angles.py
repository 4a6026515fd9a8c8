"""The derivation "euler_angles" (the unit's 2.98–2.101 and all 24 Euler conventions): it builds,
each step holds, its results carry their numbers, the printed equations give exactly the unit's
misprints, and every derived formula agrees with the Rust core (poinsot.rotation) at random
inputs."""

from __future__ import annotations

import time
import warnings
from typing import Any

import numpy as np
import pytest

sp = pytest.importorskip("sympy")

import poinsot  # noqa: E402
from poinsot import PoinsotError  # noqa: E402
from poinsot.derive import Derivation, Printed  # noqa: E402
from poinsot.derive import euler_angles as ea  # noqa: E402
from poinsot.derive._core import judge  # noqa: E402

RTOL = 1e-12
#: absolute floor for values that cross zero (matrix entries, angles, a determinant)
FLOOR = 1e-15
POINTS = 24
TAGS = ea.tags()
PROPER = {s for s in ea.SEQUENCES if s[0] == s[2]}


@pytest.fixture(scope="module")
def d() -> Derivation:
    t0 = time.perf_counter()
    out = ea.derive()
    print(f"\nderive() of {ea.NAME}: {time.perf_counter() - t0:.3f} s, {len(out.steps)} steps")
    return out


def _split(tag: str) -> tuple[str, bool]:
    seq, kind = tag.split("-")
    return seq, kind == "intrinsic"


def _angles(rng: np.random.Generator, seq: str, margin: float = 0.0) -> np.ndarray:
    """Random angles in the canonical ranges, the middle one at least ``margin`` (rad) from the
    singular angles."""
    a, c = rng.uniform(-np.pi, np.pi, 2)
    if seq in PROPER:
        b = rng.uniform(margin, np.pi - margin)
    else:
        b = rng.uniform(-np.pi / 2 + margin, np.pi / 2 - margin)
    return np.array([a, b, c])


def _entrywise(got: Any, want: Any) -> float:
    """Worst |got − want| / max(|want|, FLOOR / RTOL): relative, with an absolute floor of FLOOR
    where a value crosses zero."""
    got, want = np.asarray(got, float), np.asarray(want, float)
    return float(np.max(np.abs(got - want) / np.maximum(np.abs(want), FLOOR / RTOL)))


def _normwise(got: Any, want: Any) -> float:
    """‖got − want‖ / ‖want‖ for a vector."""
    got, want = np.asarray(got, float).ravel(), np.asarray(want, float).ravel()
    return float(np.linalg.norm(got - want) / np.linalg.norm(want))


WORST: dict[str, float] = {}


def _record(name: str, value: float) -> None:
    WORST[name] = max(WORST.get(name, 0.0), value)


@pytest.fixture(scope="module", autouse=True)
def _report():
    yield
    if WORST:
        print("\nworst relative differences (derivation vs core):")
        for k, v in sorted(WORST.items()):
            print(f"  {k:14s} {v:.2e}")


# ---- the derivation builds, every step holds ---------------------------------------------------


def test_every_step_holds(d: Derivation) -> None:
    # re-check from scratch: forget the model's cached values first
    d.model._memo.clear()  # type: ignore[attr-defined]
    d.model._out.clear()  # type: ignore[attr-defined]
    t0 = time.perf_counter()
    for step in d.steps:
        assert d.holds(step.equation), step.text
    print(f"\nre-checked {len(d.steps)} steps in {time.perf_counter() - t0:.3f} s")


def test_results_carry_their_numbers(d: Derivation) -> None:
    for number in ("2.98", "2.99", "2.100", "2.101"):
        assert number in d.result
    assert len(TAGS) == 24
    for tag in TAGS:
        for key in ("R", "2.99", "space", "det", "rates", "rates-space", "angles"):
            assert f"{key}/{tag}" in d.result, (key, tag)
            assert f"{key}/{tag}" in d.functions, (key, tag)
        locks = [k for k in d.result if k.startswith(f"lock/{tag}@")]
        assert len(locks) == 2, (tag, locks)
    for key in d.result:
        assert not key.replace(".", "").isdigit() or key in ("2.98", "2.99", "2.100", "2.101")


def test_the_unit_result_is_the_corrected_2_99(d: Derivation) -> None:
    theta, psi = sp.symbols("theta psi")
    dphi, dtheta, dpsi = sp.symbols("phi_dot theta_dot psi_dot")
    expr, syms = d.functions["2.99"]
    assert [str(s) for s in syms] == ["phi", "theta", "psi", "phi_dot", "theta_dot", "psi_dot"]
    want = sp.Matrix(
        [
            dphi * sp.sin(theta) * sp.sin(psi) + dtheta * sp.cos(psi),
            dphi * sp.sin(theta) * sp.cos(psi) - dtheta * sp.sin(psi),
            dphi * sp.cos(theta) + dpsi,
        ]
    )
    assert sp.expand(sp.Matrix(expr) - want) == sp.zeros(3, 1)
    # the singular angles of the unit's z-x-z: det = −sin θ
    det, _ = d.functions["det/zxz-intrinsic"]
    assert sp.expand(det + sp.sin(theta)) == 0


def test_determinants_vanish_at_the_singular_angles(d: Derivation) -> None:
    b = sp.Symbol("beta")
    for tag in TAGS:
        seq, _ = _split(tag)
        expr, syms = d.functions[f"det/{tag}"]
        mid = syms[1]
        expr = expr.subs(mid, b)
        if seq in PROPER:
            assert sp.expand(expr**2 - sp.sin(b) ** 2) == 0, tag
        else:
            assert sp.expand(expr**2 - sp.cos(b) ** 2) == 0, tag


def test_renders_without_the_convention_tags(d: Derivation) -> None:
    latex, md = d.latex(), d.markdown()
    assert "|" not in latex.replace(r"\left|", "").replace(r"\right|", "")
    assert "intrinsic" in md and r"\tag{2.99}" in latex


# ---- the step check refuses false steps --------------------------------------------------------


def test_a_false_step_raises(d: Derivation) -> None:
    scratch = Derivation("scratch", "scratch", model=d.model, context=d.context)
    eq298 = d.result["2.98"]
    wrong = sp.Eq(eq298.lhs, eq298.rhs.subs(sp.sin(ea._THETA), sp.cos(ea._THETA)), evaluate=False)
    with pytest.raises(PoinsotError, match="does not hold"):
        scratch.step("ω_η with cos θ", wrong)
    # an inverse with a lost sign: atan2 reads the wrong angle
    eq = d.result["angles/zxz-intrinsic"]
    flipped = eq.rhs.applyfunc(lambda e: e.func(-e.args[0], e.args[1]) if e.args else e)
    with pytest.raises(PoinsotError):
        scratch.step("a lost sign", sp.Eq(eq.lhs, flipped, evaluate=False))
    assert scratch.steps == []


# ---- errata --------------------------------------------------------------------------------------


def test_printed_equations_give_exactly_the_misprints(d: Derivation) -> None:
    assert [p.number for p in ea.PRINTED] == ["2.98", "2.99", "2.100", "2.101"]
    errata = judge(ea.PRINTED, {ea.NAME: d})
    assert [e.number for e in errata] == ["2.99"]
    (e,) = errata
    assert e.derived is d.result["2.99"]
    # only the third row fails, in both links of the printed chain
    for link in e.failing:
        r = d.residual(link)
        assert r[0] == 0 and r[1] == 0 and r[2] != 0


def test_errata_negative_controls(d: Derivation) -> None:
    p98 = ea.PRINTED[0]
    changed = sp.Eq(
        p98.equation.lhs,
        p98.equation.rhs.subs(sp.sin(ea._THETA), sp.cos(ea._THETA)),
        evaluate=False,
    )
    control = Printed("2.98", ea.NAME, "changed", changed)
    assert [e.number for e in judge([control], {ea.NAME: d})] == ["2.98"]
    # 2.99 printed with ω_ζ in the third row is right and is not reported
    p99 = ea.PRINTED[1]
    zeta = ea._sym(r"\omega_{\zeta}", "zxz-intrinsic")
    mid = p99.equation[0].rhs
    fixed_mid = sp.ImmutableMatrix([mid[0], mid[1], zeta])
    fixed = [
        sp.Eq(p99.equation[0].lhs, fixed_mid, evaluate=False),
        sp.Eq(fixed_mid, p99.equation[1].rhs, evaluate=False),
    ]
    assert judge([Printed("2.99", ea.NAME, "fixed", fixed)], {ea.NAME: d}) == []
    # right as printed: 2.98, 2.100, 2.101 (with the standing I₂ = I₁ of the symmetric top)
    assert judge([ea.PRINTED[0], ea.PRINTED[2], ea.PRINTED[3]], {ea.NAME: d}) == []
    # 2.101 with the I₁ and I₃ terms swapped is reported
    p101 = ea.PRINTED[3]
    i1, i3 = sp.symbols("I_1 I_3")
    swapped = sp.Eq(p101.equation.lhs, p101.equation.rhs.xreplace({i1: i3, i3: i1}))
    assert [e.number for e in judge([Printed("2.101", ea.NAME, "x", swapped)], {ea.NAME: d})] == [
        "2.101"
    ]


# ---- the bridge to the numbers: poinsot.rotation ------------------------------------------------


@pytest.mark.parametrize("tag", TAGS)
def test_bridge_matrix_and_inverse(d: Derivation, tag: str) -> None:
    seq, intrinsic = _split(tag)
    rng = np.random.default_rng(TAGS.index(tag) + 14)
    matrix, angles_of = d.lambdify(f"R/{tag}"), d.lambdify(f"angles/{tag}")
    det = d.lambdify(f"det/{tag}")
    for _ in range(POINTS):
        q = _angles(rng, seq, margin=0.05)
        core = poinsot.euler_to_matrix(q, seq, intrinsic=intrinsic)
        mine = np.array(matrix(*q), dtype=float)
        _record("R", _entrywise(mine, core))
        assert _entrywise(mine, core) <= RTOL
        back = poinsot.matrix_to_euler(core, seq, intrinsic=intrinsic)
        mine_back = np.array(angles_of(*core.ravel()), dtype=float).ravel()
        _record("angles", _entrywise(mine_back, back))
        assert _entrywise(mine_back, back) <= RTOL
        assert _entrywise(mine_back, q) <= 1e-9  # and they are the angles we started from
        # det of the core's rate map (its columns: ω for unit rates)
        cols = [poinsot.body_angular_velocity(q, e, seq, intrinsic=intrinsic) for e in np.eye(3)]
        core_det = np.linalg.det(np.array(cols).T)
        _record("det", _entrywise(float(det(*q)), core_det))
        assert _entrywise(float(det(*q)), core_det) <= RTOL


@pytest.mark.parametrize("tag", TAGS)
def test_bridge_rates(d: Derivation, tag: str) -> None:
    seq, intrinsic = _split(tag)
    rng = np.random.default_rng(TAGS.index(tag) + 1014)
    body, space = d.lambdify(f"2.99/{tag}"), d.lambdify(f"space/{tag}")
    rates_b, rates_s = d.lambdify(f"rates/{tag}"), d.lambdify(f"rates-space/{tag}")
    for _ in range(POINTS):
        q = _angles(rng, seq, margin=0.1)
        qdot = rng.uniform(-5.0, 5.0, 3)
        w = rng.uniform(-5.0, 5.0, 3)
        for name, mine, core in (
            (
                "omega body",
                body(*q, *qdot),
                poinsot.body_angular_velocity(q, qdot, seq, intrinsic=intrinsic),
            ),
            (
                "omega space",
                space(*q, *qdot),
                poinsot.space_angular_velocity(q, qdot, seq, intrinsic=intrinsic),
            ),
            ("rates body", rates_b(*q, *w), poinsot.euler_rates(q, w, seq, intrinsic=intrinsic)),
            (
                "rates space",
                rates_s(*q, *w),
                poinsot.euler_rates(q, w, seq, frame="space", intrinsic=intrinsic),
            ),
        ):
            err = _normwise(np.array(mine, dtype=float), core)
            _record(name, err)
            assert err <= RTOL, (name, q, err)


@pytest.mark.parametrize("tag", TAGS)
def test_bridge_gimbal_lock(d: Derivation, tag: str) -> None:
    """At each singular angle the core returns the third angle 0 and puts the combination that
    the derivation says R depends on (α ± γ) into the first."""
    seq, intrinsic = _split(tag)
    rng = np.random.default_rng(TAGS.index(tag) + 2014)
    for key in (k for k in d.result if k.startswith(f"lock/{tag}@")):
        lhs, rhs = d.result[key].lhs, d.result[key].rhs
        beta = float(lhs.args[1].args[1])
        combination = rhs.args[0].args[1]  # the angle of the first factor, e.g. α + γ
        _, syms = d.functions[f"R/{tag}"]
        q_t = ea._ALPHA, ea._BETA, ea._GAMMA
        if tag == "zxz-intrinsic":
            q_t = ea._PHI, ea._THETA, ea._PSI
        f = sp.lambdify(syms, combination.xreplace(dict(zip(q_t, syms))))
        for _ in range(POINTS):
            a, c = rng.uniform(-np.pi, np.pi, 2)
            core = poinsot.euler_to_matrix([a, beta, c], seq, intrinsic=intrinsic)
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", poinsot.GimbalLockWarning)
                back = poinsot.matrix_to_euler(core, seq, intrinsic=intrinsic)
            assert back[2] == 0.0
            want, got = f(a, beta, c), f(back[0], back[1], back[2])
            diff = np.angle(np.exp(1j * (got - want)))
            assert abs(diff) <= 1e-12, (key, a, c, back)


def test_bridge_unit_2_99_and_kinetic_energy(d: Derivation) -> None:
    rng = np.random.default_rng(99)
    f299, f100, f101 = d.lambdify("2.99"), d.lambdify("2.100"), d.lambdify("2.101")
    for _ in range(POINTS):
        q = _angles(rng, "zxz")
        qdot = rng.uniform(-5.0, 5.0, 3)
        w = poinsot.body_angular_velocity(q, qdot)
        err = _normwise(np.array(f299(*q, *qdot), dtype=float), w)
        _record("2.99", err)
        assert err <= RTOL
        i1, i2 = rng.uniform(0.5, 2.0, 2)
        i3 = rng.uniform(abs(i1 - i2) + 0.1, i1 + i2 - 0.1)
        body = poinsot.RigidBody.from_inertia(1.0, np.diag([i1, i2, i3]))
        err = _entrywise(f100(*q, *qdot, i1, i2, i3), body.kinetic_energy(w))
        _record("2.100", err)
        assert err <= RTOL
        i3 = rng.uniform(0.1, 2 * i1 - 0.1)
        top = poinsot.RigidBody.from_inertia(1.0, np.diag([i1, i1, i3]))
        err = _entrywise(f101(*q, *qdot, i1, i3), top.kinetic_energy(w))
        _record("2.101", err)
        assert err <= RTOL
