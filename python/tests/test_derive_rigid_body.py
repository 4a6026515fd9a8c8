"""poinsot.derive.rigid_body: the derivation of 2.43–2.66 builds and every step holds; its
formulas, lambdified, agree with the compiled core (poinsot.RigidBody) at random inputs; the
unit's printed equations of the range are judged, and exactly the misprints are reported.
"""

from __future__ import annotations

import time
from typing import Any

import numpy as np
import pytest

sp = pytest.importorskip("sympy")

import poinsot as ps  # noqa: E402
from poinsot.derive import rigid_body as rb  # noqa: E402
from poinsot.derive._core import Derivation, Printed, judge  # noqa: E402

RNG_SEED = 20261124
POINTS = 40
#: relative difference allowed between the lambdified formulas and the core, per entry
REL = 1e-12

NUMBERS = [f"2.{k}" for k in range(43, 67)]
#: the misprints of this range: seed-errata.md's 2.51 and 2.66, and two more found by the
#: computation (2.59: L⃗ for dL⃗/dt, the dot lost; 2.65: L without its index i)
MISPRINTS = ["2.51", "2.59", "2.65", "2.66"]
SEED_ERRATA = {"2.51", "2.66"}


@pytest.fixture(scope="module")
def d() -> Derivation:
    start = time.perf_counter()
    out = rb.derive()
    print(
        f"\nrigid_body: derive() built {len(out.steps)} steps in "
        f"{time.perf_counter() - start:.3f} s"
    )
    return out


def worst_rel(core: Any, formula: Any, floor: float = 0.0) -> float:
    """The largest |core − formula| / max(|formula|, floor) over the entries. Without a floor,
    entries where the formula is exactly zero must be exactly zero in the core too (and are not
    counted)."""
    a = np.asarray(core, dtype=float).ravel()
    b = np.asarray(formula, dtype=float).ravel()
    if floor == 0.0:
        zero = b == 0.0
        assert np.all(a[zero] == 0.0), (a, b)
        a, b = a[~zero], b[~zero]
    if b.size == 0:
        return 0.0
    return float(np.max(np.abs(a - b) / np.maximum(np.abs(b), floor)))


#: Entries that cross zero as the inputs vary (products of inertia, components of L⃗ and N⃗ for a
#: general ω⃗) lose relative accuracy to cancellation in both codes; they are compared with an
#: absolute floor of FLOOR × the quantity's natural size (tr I_O, tr I_O |ω|, tr I_O |ω|²), i.e.
#: to 1e-14 of that size. Every other entry is compared relatively, to 1e-12.
FLOOR = 1e-2


# ---- the derivation ------------------------------------------------------------------------


def test_builds_and_every_step_holds(d: Derivation) -> None:
    assert d.name == "rigid_body"
    assert len(d.steps) > 60
    for step in d.steps:
        assert d.holds(step.equation), step.text


def test_results_carry_the_unit_numbers(d: Derivation) -> None:
    assert sorted(d.result) == NUMBERS
    for number in NUMBERS:
        assert any(s.number == number for s in d.steps)


def test_renders(d: Derivation) -> None:
    tex = d.latex()
    assert r"\tag{2.51}" in tex and r"\sum_{j} I_{ij} \omega_{j}" in tex
    assert r"\tag{2.66}" in tex and r"\overline{I}_{\mathrm{cone}}" in tex
    md = d.markdown()
    assert md.count("$$") == 2 * len(d.steps)


def test_numeric_forms_are_registered(d: Derivation) -> None:
    solids = {
        "solid_sphere",
        "spherical_shell",
        "solid_cylinder",
        "solid_cone",
        "solid_cone_apex",
        "cuboid",
        "ellipsoid",
        "thin_rod",
        "thin_disk",
        "thin_ring",
    }
    others = {"2.59", "2.60", "2.63", "2.64", "2.65", "2.66", "I_cm", "parallel_axis"}
    assert solids | others | {"dumbbell_torque"} == set(d.functions)


def test_false_steps_raise() -> None:
    model = rb._Model()
    d = rb._RigidDerivation("t", "t", model=model, rigid=model)
    ma, x, y = rb._ma(), rb._xa(rb._X), rb._xa(rb._Y)
    # the products of inertia without the unit's minus sign
    with pytest.raises(ps.PoinsotError, match="does not hold"):
        d.step("wrong sign", rb._eq(rb._I(rb._X, rb._Y), rb._sum_a(rb._mul(ma, x, y))))
    # 2.51 with the sum over the row index, as printed
    printed_2_51 = next(p for p in rb.PRINTED if p.number == "2.51")
    with pytest.raises(ps.PoinsotError, match="does not hold"):
        d.step("as printed", printed_2_51.equation)
    # L along ω (false for a general body)
    with pytest.raises(ps.PoinsotError, match="does not hold"):
        d.step("L ∥ ω", rb._eq(rb.L, rb._mul(rb._I(rb._X, rb._X), rb.W)))
    # a wrong solid: the sphere with the shell's 2/3
    sphere = next(s for s in rb._solids() if s[0] == "solid_sphere")
    limits, jac = sphere[4], sphere[5]
    volume = 4 * sp.pi * rb._R**3 / 3
    integral = sp.Integral(rb._mul(rb.M / volume, rb._Kernel(rb.Vec("r")), jac), *limits)
    wrong = sp.ImmutableMatrix(sp.eye(3) * sp.Rational(2, 3) * rb.M * rb._R**2)
    with pytest.raises(ps.PoinsotError, match="does not hold"):
        d.step("wrong moment", rb._eq(integral, wrong))
    assert d.steps == []


def test_exact_angular_integrals_match_sympy() -> None:
    u = sp.Symbol("u", real=True)
    for period in (sp.pi, 2 * sp.pi):
        for m in range(5):
            for n in range(5):
                expected = sp.integrate(sp.sin(u) ** m * sp.cos(u) ** n, (u, 0, period))
                assert sp.simplify(rb._trig_moment(m, n, period) - expected) == 0, (m, n)


def test_integrator_matches_sympy_on_the_cone(d: Derivation) -> None:
    # the cone about its apex, I_xx and I_zz, by sympy's own integrate
    s, ph, z, R, h, M = rb._ss, rb._ph, rb._cz, rb._R, rb._H, rb.M
    rho = 3 * M / (sp.pi * R**2 * h)
    limits = [(s, 0, R * z / h), (ph, 0, 2 * sp.pi), (z, 0, h)]
    ixx = sp.integrate(rho * ((s * sp.sin(ph)) ** 2 + z**2) * s, *limits)
    izz = sp.integrate(rho * s**2 * s, *limits)
    tensor = d.functions["solid_cone_apex"][0]
    assert sp.simplify(tensor[0, 0] - ixx) == 0
    assert sp.simplify(tensor[2, 2] - izz) == 0


# ---- the bridge to the numbers -----------------------------------------------------------------


def _two_particles(rng: np.random.Generator) -> tuple[Any, Any, tuple[float, ...]]:
    masses = rng.uniform(0.2, 3.0, size=2)
    positions = rng.uniform(-2.0, 2.0, size=(2, 3))
    omega = rng.uniform(-3.0, 3.0, size=3)
    com = masses @ positions / masses.sum()
    s1 = positions[0] - com
    args = (masses[0], masses[1], *com, *s1, *omega)
    return ps.RigidBody.from_point_masses(masses, positions), omega, args


def test_bridge_particles(d: Derivation) -> None:
    """2.59, 2.60, 2.63, 2.64 and the tensor about the centre of mass, for two particles about
    the fixed point O (the origin), against RigidBody.from_point_masses (with the floor
    :data:`FLOOR` for entries that cross zero)."""
    rng = np.random.default_rng(RNG_SEED)
    f = {k: d.lambdify(k) for k in ("2.59", "2.60", "2.63", "2.64", "I_cm")}
    worst = 0.0
    origin = np.zeros(3)
    for _ in range(POINTS):
        body, omega, args = _two_particles(rng)
        i_o = body.inertia_about(origin)
        size = np.trace(i_o)  # 2 Σ m r², the natural size of every entry of I
        w = np.linalg.norm(omega)
        worst = max(
            worst,
            worst_rel(i_o, f["2.60"](*args), FLOOR * size),
            worst_rel(body.inertia, f["I_cm"](*args), FLOOR * size),
            worst_rel(
                body.angular_momentum(omega, about=origin), f["2.63"](*args), FLOOR * size * w
            ),
            worst_rel(body.kinetic_energy(omega, about=origin), f["2.64"](*args)),
            worst_rel(
                body.holding_torque(omega, about=origin), f["2.59"](*args), FLOOR * size * w**2
            ),
        )
    print(f"\nparticles: worst relative difference {worst:.2e}")
    assert worst <= REL


def test_bridge_principal_axes(d: Derivation) -> None:
    """2.65 and 2.66 against a body given by its principal moments."""
    rng = np.random.default_rng(RNG_SEED + 1)
    f65, f66 = d.lambdify("2.65"), d.lambdify("2.66")
    worst = 0.0
    for _ in range(POINTS):
        a, b, c = rng.uniform(0.1, 2.0, size=3)
        moments = np.array([b + c, c + a, a + b])  # any valid moments
        omega = rng.uniform(-3.0, 3.0, size=3)
        body = ps.RigidBody(rng.uniform(0.5, 2.0), np.diag(moments))
        args = (*moments, *omega)
        worst = max(
            worst,
            worst_rel(body.angular_momentum(omega), f65(*args)),
            worst_rel(body.kinetic_energy(omega), f66(*args)),
        )
    print(f"\nprincipal axes: worst relative difference {worst:.2e}")
    assert worst <= REL


def test_bridge_parallel_axis(d: Derivation) -> None:
    """I_P = I_cm + M (d² 𝟙 − d⃗ d⃗ᵀ), d⃗ = com − P, against RigidBody.inertia_about for
    rotated, translated cuboids (products of inertia cross zero: floor :data:`FLOOR`)."""
    rng = np.random.default_rng(RNG_SEED + 2)
    f = d.lambdify("parallel_axis")
    worst = 0.0
    for _ in range(POINTS):
        q, _r = np.linalg.qr(rng.normal(size=(3, 3)))
        rot = q * np.sign(np.linalg.det(q))
        body = (
            ps.RigidBody.cuboid(rng.uniform(0.5, 3.0), rng.uniform(0.2, 2.0, size=3))
            .rotated(rot)
            .translated(rng.uniform(-2.0, 2.0, size=3))
        )
        point = rng.uniform(-2.0, 2.0, size=3)
        i = body.inertia
        j = (i[0, 0], i[1, 1], i[2, 2], i[0, 1], i[1, 2], i[2, 0])
        args = (*j, body.mass, *(body.center_of_mass - point))
        i_p = body.inertia_about(point)
        worst = max(worst, worst_rel(i_p, f(*args), FLOOR * np.trace(i_p)))
    print(f"\nparallel axis: worst relative difference {worst:.2e}")
    assert worst <= REL


SOLIDS: dict[str, tuple[Any, int]] = {
    # function: (constructor, sizes → constructor's arguments after the mass)
    "solid_sphere": (ps.RigidBody.solid_sphere, 1),
    "spherical_shell": (ps.RigidBody.spherical_shell, 1),
    "solid_cylinder": (ps.RigidBody.solid_cylinder, 2),
    "solid_cone": (ps.RigidBody.solid_cone, 2),
    "cuboid": (ps.RigidBody.cuboid, 3),
    "ellipsoid": (ps.RigidBody.ellipsoid, 3),
    "thin_rod": (ps.RigidBody.thin_rod, 1),
    "thin_disk": (ps.RigidBody.thin_disk, 1),
    "thin_ring": (ps.RigidBody.thin_ring, 1),
}


@pytest.mark.parametrize("name", sorted(SOLIDS))
def test_bridge_solids(d: Derivation, name: str) -> None:
    """Each solid's integrated tensor against the core's, at random masses and sizes (about the
    centre of mass; the cone also about its apex, and its centre of mass)."""
    rng = np.random.default_rng(RNG_SEED + 3)
    make, nsizes = SOLIDS[name]
    f = d.lambdify(name)
    apex = d.lambdify("solid_cone_apex")
    worst = 0.0
    for _ in range(POINTS):
        mass = rng.uniform(0.1, 10.0)
        sizes = rng.uniform(0.05, 5.0, size=nsizes)
        body = make(mass, sizes) if nsizes == 3 else make(mass, *sizes)
        worst = max(worst, worst_rel(body.inertia, f(mass, *sizes)))
        if name == "solid_cone":
            worst = max(worst, worst_rel(body.inertia_about(np.zeros(3)), apex(mass, *sizes)))
            assert body.center_of_mass[2] == pytest.approx(0.75 * sizes[1], rel=REL)
    print(f"\n{name}: worst relative difference {worst:.2e}")
    assert worst <= REL


def test_bridge_dumbbell_torque(d: Derivation) -> None:
    """N = −(m₁b₁² + m₂b₂²) ω² sin α cos α ĵ against RigidBody.holding_torque about O. The x and
    z components are zero in the formula; the core's are round-off, bounded by 1e-12 |N|."""
    rng = np.random.default_rng(RNG_SEED + 4)
    f = d.lambdify("dumbbell_torque")
    worst = 0.0
    for _ in range(POINTS):
        m1, m2 = rng.uniform(0.1, 3.0, size=2)
        b1, b2 = rng.uniform(0.1, 2.0, size=2)
        alpha = rng.uniform(0.05, np.pi / 2 - 0.05)
        omega = rng.uniform(0.1, 5.0)
        n = np.array([np.sin(alpha), 0.0, np.cos(alpha)])
        body = ps.RigidBody.from_point_masses([m1, m2], [b1 * n, -b2 * n])
        core = body.holding_torque([0.0, 0.0, omega], about=np.zeros(3))
        formula = np.asarray(f(m1, m2, b1, b2, alpha, omega), dtype=float).ravel()
        assert formula[0] == 0.0 and formula[2] == 0.0
        assert abs(core[0]) <= REL * abs(formula[1]) and abs(core[2]) <= REL * abs(formula[1])
        worst = max(worst, abs(core[1] - formula[1]) / abs(formula[1]))
    print(f"\ndumbbell torque: worst relative difference {worst:.2e}")
    assert worst <= REL


# ---- the unit as printed -----------------------------------------------------------------------


def test_every_numbered_equation_is_transcribed() -> None:
    numbers = [p.number for p in rb.PRINTED]
    assert sorted(set(numbers)) == NUMBERS
    # the unit numbers two equations 2.49 and two 2.50
    assert numbers.count("2.49") == 2 and numbers.count("2.50") == 2
    assert all(p.derivation == "rigid_body" and p.as_printed for p in rb.PRINTED)


def test_errata_are_exactly_the_misprints(d: Derivation) -> None:
    errata = judge(rb.PRINTED, {"rigid_body": d})
    assert [e.number for e in errata] == MISPRINTS
    assert {e.number for e in errata} >= SEED_ERRATA
    for e in errata:
        assert e.derived is d.result[e.number]
        assert e.failing


def test_errata_derived_forms_hold_and_the_printed_do_not(d: Derivation) -> None:
    printed = {p.number: p for p in rb.PRINTED}
    for number in MISPRINTS:
        assert d.holds(d.result[number])
        assert not d.holds(printed[number].equation)


def _replace(p: Printed, eq: Any) -> Printed:
    return Printed(p.number, p.derivation, p.as_printed, eq, p.note)


def test_negative_controls(d: Derivation) -> None:
    printed = {p.number: p for p in rb.PRINTED}
    right = [printed["2.53"], printed["2.55"], printed["2.63"]]
    assert judge(right, {"rigid_body": d}) == []
    # 2.55 with one term changed: 2 I_xy ω_x ω_y → I_xy ω_x ω_y
    eq = printed["2.55"].equation
    changed = eq.rhs.xreplace({sp.Integer(2): sp.Integer(1)})
    assert changed != eq.rhs
    bad = _replace(printed["2.55"], rb._eq(eq.lhs, changed))
    assert [e.number for e in judge([bad], {"rigid_body": d})] == ["2.55"]
    # 2.46 with the second sum changed: y² + z² → x² + z²
    x, z = rb._xa(rb._X), rb._xa(rb._Z)
    chain = printed["2.46"].equation
    wrong = rb._sum_a(rb._mul(rb._ma(), x**2 + z**2))
    bad = _replace(printed["2.46"], [chain[0], rb._eq(chain[1].lhs, wrong)])
    (err,) = judge([bad], {"rigid_body": d})
    assert err.number == "2.46" and len(err.failing) == 1
    # 2.57 with L_z off the axis: I_zz ω_z → I_xz ω_z
    eq = printed["2.57"].equation
    rows = list(eq.rhs)
    rows[2] = rb._mul(rb._I(rb._X, rb._Z), rb._omega(rb._Z))
    bad = _replace(printed["2.57"], rb._eq(eq.lhs, sp.ImmutableMatrix(rows)))
    assert [e.number for e in judge([bad], {"rigid_body": d})] == ["2.57"]
