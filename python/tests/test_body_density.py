"""RigidBody.from_density: adaptive cubature of eqs. 2.61–2.62 against the standard solids
(indicator densities, checked within the reported error estimate), a smooth density to tight
tolerance, the batched calling convention, the max_evals warning and the refusal of bad input.
"""

from __future__ import annotations

import json
import warnings

import numpy as np
import poinsot as ps
import pytest

#: Relative tolerance asked of the cubature for indicator densities (they converge like the
#: region size near the boundary, so tight tolerances cost many evaluations).
INDICATOR_RTOL = 2e-2


def indicator(inside, rho: float = 1000.0):
    return lambda p: np.where(inside(p[:, 0], p[:, 1], p[:, 2]), rho, 0.0)


R, H, A, B = 0.6, 1.4, 1.0, 0.8
RHO = 1000.0
SHAPES = {
    # name: (density, bounds, exact body of the same mass, exact mass)
    "solid_sphere": (
        indicator(lambda x, y, z: x * x + y * y + z * z <= R * R),
        [(-R, R)] * 3,
        lambda m: ps.RigidBody.solid_sphere(m, R),
        RHO * 4 / 3 * np.pi * R**3,
    ),
    "solid_cylinder": (
        indicator(lambda x, y, z: x * x + y * y <= R * R),
        [(-R, R), (-R, R), (-H / 2, H / 2)],
        lambda m: ps.RigidBody.solid_cylinder(m, R, H),
        RHO * np.pi * R * R * H,
    ),
    "solid_cone": (  # apex at the origin, axis +z
        indicator(lambda x, y, z: np.sqrt(x * x + y * y) <= R * z / H),
        [(-R, R), (-R, R), (0.0, H)],
        lambda m: ps.RigidBody.solid_cone(m, R, H),
        RHO * np.pi * R * R * H / 3,
    ),
    "ellipsoid": (
        indicator(lambda x, y, z: (x / 0.5) ** 2 + (y / 0.8) ** 2 + (z / 1.2) ** 2 <= 1),
        [(-0.5, 0.5), (-0.8, 0.8), (-1.2, 1.2)],
        lambda m: ps.RigidBody.ellipsoid(m, (0.5, 0.8, 1.2)),
        RHO * 4 / 3 * np.pi * 0.5 * 0.8 * 1.2,
    ),
}


@pytest.mark.parametrize("name", sorted(SHAPES))
def test_indicator_density_matches_the_solid_within_its_error_estimate(name: str) -> None:
    density, bounds, make, exact_mass = SHAPES[name]
    body = ps.RigidBody.from_density(density, bounds, rtol=INDICATOR_RTOL)
    err = body.integration_error
    assert err is not None and err.converged
    assert abs(body.mass - exact_mass) <= err.mass
    assert err.mass <= INDICATOR_RTOL * exact_mass
    exact = make(exact_mass)
    assert np.abs(body.center_of_mass - exact.center_of_mass).max() <= err.center_of_mass
    assert np.abs(body.inertia - exact.inertia).max() <= err.inertia
    assert (
        body.kind == exact.kind
        or ps.classify(body.principal_moments, rtol=3 * INDICATOR_RTOL) == exact.kind
    )


def test_cuboid_and_thick_shell_densities() -> None:
    # Uniform density filling the box: the rule is exact (polynomial integrand).
    sides = np.array([0.4, 1.0, 2.2])
    box = ps.RigidBody.from_density(
        lambda p: np.full(len(p), 7.0), [(-0.2, 0.2), (-0.5, 0.5), (-1.1, 1.1)]
    )
    ref = ps.RigidBody.cuboid(7.0 * sides.prod(), sides)
    assert box.mass == pytest.approx(ref.mass, rel=1e-13)
    np.testing.assert_allclose(box.inertia, ref.inertia, rtol=1e-12, atol=1e-14)
    # A scalar return value is broadcast (constant density).
    np.testing.assert_allclose(
        ps.RigidBody.from_density(lambda p: 7.0, [(-0.2, 0.2), (-0.5, 0.5), (-1.1, 1.1)]).inertia,
        ref.inertia,
        rtol=1e-12,
        atol=1e-14,
    )
    # Thick spherical shell b ≤ r ≤ a: I = 2/5 m (a⁵ − b⁵)/(a³ − b³) (→ 2/3 m a² as b → a).
    a, b = 1.0, 0.7
    shell = ps.RigidBody.from_density(
        indicator(
            lambda x, y, z: (x * x + y * y + z * z <= a * a) & (x * x + y * y + z * z >= b * b)
        ),
        [(-a, a)] * 3,
        rtol=INDICATOR_RTOL,
    )
    m = RHO * 4 / 3 * np.pi * (a**3 - b**3)
    err = shell.integration_error
    assert abs(shell.mass - m) <= err.mass
    ref = ps.RigidBody.spherical_shell(m, a)  # the thin-shell formula, corrected for thickness:
    thick = 0.4 * m * (a**5 - b**5) / (a**3 - b**3)
    assert np.abs(np.diag(shell.inertia) - thick).max() <= err.inertia
    assert thick < ref.inertia[0, 0]


def test_smooth_density_converges_tightly_and_is_called_in_batches() -> None:
    """ρ = exp(−½ Σ ((x_i − c_i)/σ_i)²): m = (2π)^{3/2} σx σy σz, I_xx = m (σy² + σz²)."""
    s, c = np.array([0.5, 0.8, 1.1]), np.array([0.3, -0.2, 0.1])
    calls: list[tuple[int, ...]] = []

    def rho(p: np.ndarray) -> np.ndarray:
        calls.append(p.shape)
        return np.exp(-0.5 * (((p - c) / s) ** 2).sum(axis=1))

    body = ps.RigidBody.from_density(rho, [(-8, 8), (-9, 9), (-10, 10)], rtol=1e-8)
    m = (2 * np.pi) ** 1.5 * s.prod()
    v = s * s
    assert body.mass == pytest.approx(m, rel=1e-8)
    np.testing.assert_allclose(body.center_of_mass, c, atol=1e-8)
    np.testing.assert_allclose(
        body.inertia, m * np.diag([v[1] + v[2], v[2] + v[0], v[0] + v[1]]), rtol=1e-8, atol=1e-9
    )
    err = body.integration_error
    assert err.converged and abs(body.mass - m) <= max(err.mass, 1e-14 * m)
    # Vectorised: every call gets an (N, 3) batch, and there are far fewer calls than points.
    assert all(len(shape) == 2 and shape[1] == 3 for shape in calls)
    assert len(calls) < err.evaluations / 1000
    # The estimate travels with translations and into to_dict().
    moved = body.translated([1.0, 0.0, 0.0])
    assert moved.integration_error == err
    d = json.loads(json.dumps(moved.to_dict()))
    assert d["integration_error"]["converged"] is True
    assert body.rotated(np.eye(3)).integration_error is None


def test_max_evals_returns_the_estimate_with_a_warning() -> None:
    density, bounds, _, exact_mass = SHAPES["solid_sphere"]
    with pytest.warns(ps.IntegrationWarning, match="max_evals"):
        body = ps.RigidBody.from_density(density, bounds, rtol=1e-9, max_evals=50_000)
    err = body.integration_error
    assert not err.converged and err.evaluations <= 50_000
    assert abs(body.mass - exact_mass) <= err.mass


def test_density_exceptions_propagate() -> None:
    class Boom(RuntimeError):
        pass

    def bad(p: np.ndarray) -> np.ndarray:
        raise Boom("from the user's function")

    with pytest.raises(Boom):
        ps.RigidBody.from_density(bad, [(0, 1)] * 3)


BAD = [
    (
        lambda: ps.RigidBody.from_density(lambda p: -np.ones(len(p)), [(0, 1)] * 3),
        "density",
        ">= 0",
    ),
    (
        lambda: ps.RigidBody.from_density(lambda p: np.full(len(p), np.nan), [(0, 1)] * 3),
        "density",
        "finite",
    ),
    (
        lambda: ps.RigidBody.from_density(lambda p: np.zeros(len(p)), [(0, 1)] * 3),
        "density",
        "zero mass",
    ),
    (
        lambda: ps.RigidBody.from_density(lambda p: np.ones((len(p), 2)), [(0, 1)] * 3),
        "density",
        "shape",
    ),
    (lambda: ps.RigidBody.from_density(lambda p: np.ones(3), [(0, 1)] * 3), "density", "shape"),
    (lambda: ps.RigidBody.from_density(3.0, [(0, 1)] * 3), "density", "callable"),
    (
        lambda: ps.RigidBody.from_density(lambda p: 1.0, [(0, 1), (1, 1), (0, 1)]),
        "bounds",
        "min < max",
    ),
    (
        lambda: ps.RigidBody.from_density(lambda p: 1.0, [(0, 1), (2, 1), (0, 1)]),
        "bounds",
        "min < max",
    ),
    (lambda: ps.RigidBody.from_density(lambda p: 1.0, [(0, 1), (0, 1)]), "bounds", "shape"),
    (
        lambda: ps.RigidBody.from_density(lambda p: 1.0, [(0, 1), (0, np.inf), (0, 1)]),
        "bounds",
        "finite",
    ),
    (lambda: ps.RigidBody.from_density(lambda p: 1.0, [(0, 1)] * 3, rtol=0.0), "rtol", "> 0"),
    (lambda: ps.RigidBody.from_density(lambda p: 1.0, [(0, 1)] * 3, atol=-1.0), "atol", ">= 0"),
    (
        lambda: ps.RigidBody.from_density(lambda p: 1.0, [(0, 1)] * 3, max_evals=10),
        "max_evals",
        "at least",
    ),
    (
        lambda: ps.RigidBody.from_density(lambda p: 1.0, [(0, 1)] * 3, max_evals=-5),
        "max_evals",
        "positive",
    ),
]


@pytest.mark.parametrize("case", range(len(BAD)))
def test_bad_density_input_is_refused_naming_the_argument(case: int) -> None:
    call, argument, words = BAD[case]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(ps.PoinsotError, match=f"^{argument}:.*{words}"):
            call()
