"""poinsot.RigidBody: conventions, standard solids, composition, L, T, the holding torque, kinds
of top and the refusal of bad input (the unit's eqs. 2.43–2.66).

References are independent of the code under test: textbook formulas written out here, direct
sums over particles (2.44, 2.46–2.50, 2.52), finite differences of rotating particles, scipy
rotations.
"""

from __future__ import annotations

import json
import pickle

import numpy as np
import poinsot as ps
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

#: Round-off of closed forms and O(1) sums in float64.
EXACT = 1e-12
RNG_SEED = 20261121


def direct_inertia(masses: np.ndarray, positions: np.ndarray, about: np.ndarray) -> np.ndarray:
    """Σ m (|r|² 1 − r rᵀ) with r measured from ``about`` (2.46–2.50), by explicit loops."""
    out = np.zeros((3, 3))
    for m, p in zip(masses, positions):
        x, y, z = p - about
        out += m * np.array(
            [
                [y * y + z * z, -x * y, -x * z],
                [-y * x, z * z + x * x, -y * z],
                [-z * x, -z * y, x * x + y * y],
            ]
        )
    return out


def random_particles(rng: np.random.Generator, n: int = 6) -> tuple[np.ndarray, np.ndarray]:
    return rng.uniform(0.2, 3.0, size=n), rng.normal(size=(n, 3))


# ---- conventions (cited by CONVENTIONS.md) -------------------------------------------------------


def test_convention_products_of_inertia_negated() -> None:
    """I_xy = −Σ m x y (2.49): two unit masses at ±(1, 1, 0) have Σ m x y = 2, so I_xy = −2."""
    pts = ps.RigidBody.from_point_masses([1.0, 1.0], [[1.0, 1.0, 0.0], [-1.0, -1.0, 0.0]])
    np.testing.assert_array_equal(pts.inertia, [[2, -2, 0], [-2, 2, 0], [0, 0, 4]])
    # One kilogram at (1, 2, 3) about the origin: I_xx = y² + z² = 13, I_xy = −2, I_yz = −6.
    one = ps.RigidBody.from_point_masses([1.0], [[1.0, 2.0, 3.0]])
    np.testing.assert_array_equal(
        one.inertia_about([0.0, 0.0, 0.0]), [[13, -2, -3], [-2, 10, -6], [-3, -6, 5]]
    )
    # ... so that L = I·ω equals Σ m r × (ω × r) (2.44, 2.63).
    w = np.array([0.3, -1.2, 0.8])
    r = np.array([1.0, 2.0, 3.0])
    np.testing.assert_allclose(
        one.angular_momentum(w, about=[0, 0, 0]), np.cross(r, np.cross(w, r)), rtol=EXACT
    )


def test_convention_principal_moments_ascending() -> None:
    b = ps.RigidBody.cuboid(1.0, (3.0, 1.0, 2.0))  # I_xx = 5/12, I_yy = 13/12, I_zz = 10/12
    np.testing.assert_allclose(b.principal_moments, [5 / 12, 10 / 12, 13 / 12], rtol=EXACT)
    rng = np.random.default_rng(RNG_SEED)
    for _ in range(20):
        body = ps.RigidBody.from_point_masses(*random_particles(rng))
        assert np.all(np.diff(body.principal_moments) >= 0)


def test_convention_principal_axes_proper_rotation() -> None:
    """Columns are the axes, det = +1, inertia = A diag(moments) Aᵀ, also when moments coincide."""
    rng = np.random.default_rng(RNG_SEED)
    bodies = [
        ps.RigidBody.cuboid(1.0, (3.0, 1.0, 2.0)),  # a signed permutation
        ps.RigidBody.solid_sphere(1.0, 1.0),  # all equal: identity
        ps.RigidBody.solid_cylinder(1.0, 1.0, 1.0),  # two equal
        ps.RigidBody.thin_rod(1.0, 2.0),  # (0, I, I)
        ps.RigidBody.from_point_masses([1.0], [[1.0, 2.0, 3.0]]),  # zero tensor
    ]
    bodies += [b.rotated(Rotation.random(random_state=k)) for k, b in enumerate(list(bodies))]
    bodies += [ps.RigidBody.from_point_masses(*random_particles(rng)) for _ in range(10)]
    for b in bodies:
        A = b.principal_axes
        np.testing.assert_allclose(A.T @ A, np.eye(3), atol=EXACT)
        assert np.linalg.det(A) == pytest.approx(1.0, abs=EXACT)
        scale = max(1.0, np.abs(b.inertia).max())
        np.testing.assert_allclose(
            A @ np.diag(b.principal_moments) @ A.T, b.inertia, atol=1e-9 * scale
        )
    np.testing.assert_array_equal(ps.RigidBody.solid_sphere(1.0, 1.0).principal_axes, np.eye(3))
    # A symmetric top about z keeps the coordinate axes: the pair spans x, y.
    np.testing.assert_array_equal(
        ps.RigidBody.solid_cylinder(1.0, 1.0, 0.1).principal_axes, np.eye(3)
    )


def test_convention_cone_apex_at_origin() -> None:
    m, r, h = 1.0, 0.5, 2.0
    cone = ps.RigidBody.solid_cone(m, r, h)
    np.testing.assert_allclose(cone.center_of_mass, [0.0, 0.0, 0.75 * h], rtol=EXACT)
    # About the apex (the origin): I_xx = 3/20 m r² + 3/5 m h², I_zz = 3/10 m r².
    I_apex = cone.inertia_about([0.0, 0.0, 0.0])
    np.testing.assert_allclose(
        np.diag(I_apex), [0.15 * m * r**2 + 0.6 * m * h**2] * 2 + [0.3 * m * r**2], rtol=EXACT
    )


# ---- standard solids against textbook formulas --------------------------------------------------

M, R, H = 2.5, 0.4, 1.3
SOLIDS = {
    "solid_sphere": (
        lambda: ps.RigidBody.solid_sphere(M, R),
        [0.4 * M * R**2] * 3,
        "spherical top",
    ),
    "spherical_shell": (
        lambda: ps.RigidBody.spherical_shell(M, R),
        [2 / 3 * M * R**2] * 3,
        "spherical top",
    ),
    "solid_cylinder": (
        lambda: ps.RigidBody.solid_cylinder(M, R, H),
        [M * (3 * R**2 + H**2) / 12] * 2 + [M * R**2 / 2],
        "symmetric top",
    ),
    "solid_cone": (
        lambda: ps.RigidBody.solid_cone(M, R, H),
        [M * (3 / 20 * R**2 + 3 / 80 * H**2)] * 2 + [3 / 10 * M * R**2],
        "symmetric top",
    ),
    "cuboid": (
        lambda: ps.RigidBody.cuboid(M, (0.5, 1.0, 2.0)),
        [M * 5 / 12, M * 4.25 / 12, M * 1.25 / 12],
        "asymmetric top",
    ),
    "ellipsoid": (
        lambda: ps.RigidBody.ellipsoid(M, (0.5, 1.0, 2.0)),
        [M * 5 / 5, M * 4.25 / 5, M * 1.25 / 5],
        "asymmetric top",
    ),
    "thin_rod": (lambda: ps.RigidBody.thin_rod(M, H), [M * H**2 / 12] * 2 + [0.0], "rotor"),
    "thin_disk": (
        lambda: ps.RigidBody.thin_disk(M, R),
        [M * R**2 / 4] * 2 + [M * R**2 / 2],
        "symmetric top",
    ),
    "thin_ring": (
        lambda: ps.RigidBody.thin_ring(M, R),
        [M * R**2 / 2] * 2 + [M * R**2],
        "symmetric top",
    ),
}


@pytest.mark.parametrize("name", sorted(SOLIDS))
def test_solid_matches_textbook_formula(name: str) -> None:
    make, diag, _ = SOLIDS[name]
    body = make()
    assert body.mass == M
    np.testing.assert_allclose(body.inertia, np.diag(diag), rtol=EXACT, atol=0)
    com = [0.0, 0.0, 0.75 * H] if name == "solid_cone" else [0.0, 0.0, 0.0]
    np.testing.assert_allclose(body.center_of_mass, com, rtol=EXACT, atol=0)


@pytest.mark.parametrize("name", sorted(SOLIDS))
def test_kind_standard_solids(name: str) -> None:
    make, _, kind = SOLIDS[name]
    assert make().kind == kind


def test_kind_unit_examples() -> None:
    """The unit's classification after 2.66, on its own examples."""
    # A diatomic molecule (two atoms on a line) is a rotor: I1 = I2, I3 = 0.
    co = ps.RigidBody.from_point_masses([12.0, 16.0], [[0, 0, 0], [0, 0, 1.128e-10]])
    assert co.kind == "rotor"
    assert co.principal_moments[0] == pytest.approx(0.0, abs=1e-12 * co.principal_moments[2])
    # A cube (three equal moments) is a spherical top, also seen from any tilted frame.
    cube = ps.RigidBody.cuboid(1.0, (1.0, 1.0, 1.0)).rotated(
        Rotation.from_euler("zxz", [0.3, 0.9, -0.4])
    )
    assert cube.kind == "spherical top"
    # The unit's dumbbell (2.58) is a rotor; a 1×1×2 box a symmetric top; a brick asymmetric.
    assert ps.RigidBody.from_point_masses([1.0, 1.0], [[1, 0, 1], [-1, 0, -1]]).kind == "rotor"
    assert ps.RigidBody.cuboid(1.0, (1.0, 1.0, 2.0)).kind == "symmetric top"
    assert ps.RigidBody.cuboid(1.0, (1.0, 2.0, 3.0)).kind == "asymmetric top"


def test_kind_point_mass_is_rotor() -> None:
    """A single point mass (zero tensor) meets the unit's rotor definition I1 = I2, I3 = 0."""
    p = ps.RigidBody.from_point_masses([2.0], [[1.0, 2.0, 3.0]])
    np.testing.assert_array_equal(p.inertia, np.zeros((3, 3)))
    assert p.kind == "rotor"
    assert ps.classify([0.0, 0.0, 0.0]) == "rotor"


def test_kind_tolerance_is_relative() -> None:
    assert ps.classify([1.0, 1.0 + 1e-12, 1.0]) == "spherical top"
    assert ps.classify([1.0, 1.0 + 1e-12, 1.0], rtol=0.0) == "symmetric top"
    assert ps.classify([1e-30, 1e-30, 2e-30]) == "symmetric top"  # scale-free
    assert ps.classify([1.0, 1.0 + 1e-3, 1.0], rtol=1e-2) == "spherical top"
    assert ps.classify([3.0, 1.0, 2.0]) == "asymmetric top"
    assert ps.classify([1.0, 1e-12, 1.0]) == "rotor"


# ---- composition and re-expression --------------------------------------------------------------


def test_three_stacked_unit_cubes_equal_one_cuboid() -> None:
    """Compound = monolith (parry's parallel-axis sign bug failed this for a 1×3×1 box)."""
    for axis in range(3):
        cubes = [
            ps.RigidBody.cuboid(1.0, (1, 1, 1)).translated(np.eye(3)[axis] * k) for k in range(3)
        ]
        sides = np.ones(3)
        sides[axis] = 3.0
        monolith = ps.RigidBody.cuboid(3.0, sides).translated(np.eye(3)[axis])
        for compound in (ps.RigidBody.combine(cubes), cubes[0] + cubes[1] + cubes[2], sum(cubes)):
            assert isinstance(compound, ps.RigidBody)
            assert compound.mass == pytest.approx(3.0, rel=EXACT)
            np.testing.assert_allclose(compound.center_of_mass, monolith.center_of_mass, atol=EXACT)
            np.testing.assert_allclose(compound.inertia, monolith.inertia, rtol=EXACT, atol=EXACT)


def test_composition_equals_particles() -> None:
    rng = np.random.default_rng(RNG_SEED)
    masses, positions = random_particles(rng, 8)
    whole = ps.RigidBody.from_point_masses(masses, positions)
    parts = ps.RigidBody.combine(
        [
            ps.RigidBody.from_point_masses(masses[:3], positions[:3]),
            ps.RigidBody.from_point_masses(masses[3:], positions[3:]),
        ]
    )
    np.testing.assert_allclose(parts.inertia, whole.inertia, rtol=1e-12, atol=1e-12)
    com = masses @ positions / masses.sum()
    np.testing.assert_allclose(whole.center_of_mass, com, rtol=1e-13)
    np.testing.assert_allclose(
        whole.inertia, direct_inertia(masses, positions, com), rtol=1e-12, atol=1e-12
    )


def test_inertia_about_points_is_the_parallel_axis_theorem() -> None:
    rng = np.random.default_rng(RNG_SEED + 1)
    masses, positions = random_particles(rng)
    body = ps.RigidBody.from_point_masses(masses, positions)
    points = rng.normal(size=(4, 2, 3)) * 3
    got = body.inertia_about(points)
    assert got.shape == (4, 2, 3, 3)
    for idx in np.ndindex(4, 2):
        np.testing.assert_allclose(
            got[idx], direct_inertia(masses, positions, points[idx]), rtol=1e-12, atol=1e-11
        )
    # ... and back: I_cm = I_P − m (|d|² 1 − d dᵀ).
    P = points[0, 0]
    d = body.center_of_mass - P
    back = got[0, 0] - body.mass * (d @ d * np.eye(3) - np.outer(d, d))
    np.testing.assert_allclose(back, body.inertia, atol=1e-11 * np.abs(got[0, 0]).max())


def test_from_inertia_about_a_point_shifts_back_to_the_centre_of_mass() -> None:
    """CAD-style input: the cone's inertia about its apex, I_xx = 3/20 m r² + 3/5 m h²."""
    m, r, h = 1.5, 0.5, 2.0
    apex = np.diag([0.15 * m * r**2 + 0.6 * m * h**2] * 2 + [0.3 * m * r**2])
    body = ps.RigidBody.from_inertia(m, apex, (0.0, 0.0, 0.75 * h), about=(0.0, 0.0, 0.0))
    np.testing.assert_allclose(body.inertia, ps.RigidBody.solid_cone(m, r, h).inertia, rtol=1e-13)
    # A rod about its end: m L²/3 → m L²/12 about the centre, on the triangle boundary (I_zz = 0).
    rod = ps.RigidBody.from_inertia(2.0, np.diag([2 / 3, 2 / 3, 0.0]), (0, 0, 0.5), about=(0, 0, 0))
    assert rod.kind == "rotor"
    with pytest.raises(ps.PoinsotError, match="^about:"):
        ps.RigidBody.from_inertia(1.0, np.eye(3), about=(0, 0))
    with pytest.raises(ps.InvalidInertiaError, match="^inertia:"):
        # About the origin, too little inertia for a body whose centre of mass is 1 m away.
        ps.RigidBody.from_inertia(1.0, 0.1 * np.eye(3), (1.0, 0.0, 0.0), about=(0.0, 0.0, 0.0))


@settings(max_examples=60, deadline=None, derandomize=True)
@given(
    quat=st.lists(st.floats(-1, 1), min_size=4, max_size=4).filter(
        lambda q: np.linalg.norm(q) > 0.1
    ),
    seed=st.integers(0, 2**31),
)
def test_rotated_body_has_the_same_principal_moments(quat: list[float], seed: int) -> None:
    rng = np.random.default_rng(seed)
    body = ps.RigidBody.from_point_masses(*random_particles(rng))
    rot = Rotation.from_quat(quat)  # scipy: scalar-last; any unit quaternion will do
    turned = body.rotated(rot)
    np.testing.assert_allclose(
        turned.principal_moments, body.principal_moments, rtol=1e-11, atol=1e-12
    )
    # rotated about the origin: com ↦ R com, I ↦ R I Rᵀ
    R = rot.as_matrix()
    np.testing.assert_allclose(turned.center_of_mass, R @ body.center_of_mass, atol=1e-12)
    np.testing.assert_allclose(turned.inertia, R @ body.inertia @ R.T, atol=1e-11)
    assert np.linalg.det(turned.principal_axes) == pytest.approx(1.0, abs=1e-12)


def test_translated_and_rotated_keep_what_they_should() -> None:
    b = ps.RigidBody.cuboid(2.0, (1.0, 2.0, 3.0))
    t = b.translated([1.0, -2.0, 0.5])
    np.testing.assert_array_equal(t.inertia, b.inertia)
    np.testing.assert_array_equal(t.center_of_mass, [1.0, -2.0, 0.5])
    r = t.rotated(np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]))  # 90° about z
    np.testing.assert_allclose(r.center_of_mass, [2.0, 1.0, 0.5], atol=EXACT)  # about the origin
    np.testing.assert_allclose(np.diag(r.inertia), np.diag(b.inertia)[[1, 0, 2]], rtol=EXACT)


# ---- angular momentum, kinetic energy, holding torque --------------------------------------------


def test_l_and_t_about_com_and_about_a_point_equal_direct_sums() -> None:
    """L = Σ m r × (ω × r) (2.44) and T = Σ ½ m |ω × r|² (2.52) = ½ ω·L (2.53)."""
    rng = np.random.default_rng(RNG_SEED + 2)
    masses, positions = random_particles(rng)
    body = ps.RigidBody.from_point_masses(masses, positions)
    omegas = rng.normal(size=(5, 3))
    for about in (None, np.array([0.3, -1.0, 2.0])):
        origin = body.center_of_mass if about is None else about
        r = positions - origin
        L = np.array(
            [sum(m * np.cross(ri, np.cross(w, ri)) for m, ri in zip(masses, r)) for w in omegas]
        )
        T = np.array(
            [
                sum(0.5 * m * np.dot(np.cross(w, ri), np.cross(w, ri)) for m, ri in zip(masses, r))
                for w in omegas
            ]
        )
        np.testing.assert_allclose(
            body.angular_momentum(omegas, about=about), L, rtol=1e-12, atol=1e-12
        )
        np.testing.assert_allclose(body.kinetic_energy(omegas, about=about), T, rtol=1e-12)
        np.testing.assert_allclose(T, 0.5 * np.einsum("ij,ij->i", omegas, L), rtol=1e-12)
    # Broadcasting over leading dimensions, and a float for one ω.
    assert body.angular_momentum(np.zeros((2, 3, 3))).shape == (2, 3, 3)
    assert isinstance(body.kinetic_energy([1.0, 0.0, 0.0]), float)


def test_dumbbell_needs_a_torque_equal_to_dl_dt() -> None:
    """The unit's 2.58–2.59: a dumbbell turning about an axis tilted from its rod has L not
    parallel to ω; the torque ω × L that keeps ω constant equals dL/dt of the rotating
    particles, computed here by central finite differences."""
    m, r, alpha, omega = 1.0, 0.5, np.radians(30.0), 2.0
    d = np.array([np.sin(alpha), 0.0, np.cos(alpha)])
    positions = np.array([r * d, -r * d])
    body = ps.RigidBody.from_point_masses([m, m], positions)
    w = np.array([0.0, 0.0, omega])
    L = body.angular_momentum(w)
    # Not parallel: the angle is 90° − α for a massless rod (L ⟂ rod).
    assert body.momentum_angle(w, degrees=True) == pytest.approx(60.0, rel=1e-12)
    assert abs(L @ d) < 1e-15
    N = body.holding_torque(w)

    def L_at(t: float) -> np.ndarray:
        rot = Rotation.from_rotvec(w * t).as_matrix()
        return sum(m * np.cross(rot @ p, np.cross(w, rot @ p)) for p in positions)

    dt = 1e-5
    dLdt = (L_at(dt) - L_at(-dt)) / (2 * dt)
    # Central differences: truncation ~ (ω dt)² / 6 ≈ 7e-11 relative.
    np.testing.assert_allclose(N, dLdt, rtol=1e-8, atol=1e-9)
    assert np.linalg.norm(N) == pytest.approx(
        2 * m * r**2 * omega**2 * np.sin(alpha) * np.cos(alpha), rel=1e-12
    )
    # Negative control: turning about a principal axis needs no torque, and L ∥ ω.
    axis = body.principal_axes[:, 2]
    np.testing.assert_allclose(body.holding_torque(axis), 0.0, atol=1e-15)
    assert body.momentum_angle(axis) == pytest.approx(0.0, abs=1e-7)


def test_momentum_angle_undefined_is_refused() -> None:
    rod = ps.RigidBody.thin_rod(1.0, 1.0)
    with pytest.raises(ps.PoinsotError, match="omega"):
        rod.momentum_angle([0.0, 0.0, 0.0])
    with pytest.raises(ps.PoinsotError, match="omega"):
        rod.momentum_angle([0.0, 0.0, 1.0])  # along the rod: L = 0


# ---- the object itself ---------------------------------------------------------------------------


def test_repr_dict_pickle() -> None:
    b = ps.RigidBody.solid_cone(1.0, 0.5, 2.0)
    text = repr(b)
    assert "kg" in text and "symmetric top" in text and "RigidBody(" in text
    d = json.loads(json.dumps(b.to_dict()))
    assert d["kind"] == "symmetric top" and d["mass"] == 1.0
    np.testing.assert_array_equal(d["inertia"], b.inertia)
    again = pickle.loads(pickle.dumps(b))
    np.testing.assert_array_equal(again.inertia, b.inertia)
    np.testing.assert_array_equal(again.center_of_mass, b.center_of_mass)
    c = ps.RigidBody(2.0, np.diag([1.0, 2.0, 2.5]), (1, 2, 3))
    np.testing.assert_array_equal(c.center_of_mass, [1, 2, 3])
    assert c.integration_error is None


def test_check_inertia_returns_the_symmetrised_tensor() -> None:
    a = np.diag([1.0, 2.0, 2.5])
    a[0, 1], a[1, 0] = 0.1, 0.1 + 1e-12
    out = ps.check_inertia(a)
    assert out[0, 1] == out[1, 0]
    # Rotated thin plates and rods lie on the triangle boundary and pass.
    for diag in ([1.0, 2.0, 3.0], [0.0, 1.0, 1.0]):
        for k in range(20):
            R = Rotation.random(random_state=k).as_matrix()
            ps.check_inertia(R @ np.diag(diag) @ R.T)


# ---- bad input: type and message naming the argument ---------------------------------------------

BAD = [
    (lambda: ps.RigidBody.solid_sphere(-1.0, 1.0), ps.PoinsotError, "mass"),
    (lambda: ps.RigidBody.solid_sphere(0.0, 1.0), ps.PoinsotError, "mass"),
    (lambda: ps.RigidBody.solid_sphere(float("nan"), 1.0), ps.PoinsotError, "mass"),
    (lambda: ps.RigidBody.solid_sphere(1.0, -1.0), ps.PoinsotError, "radius"),
    (lambda: ps.RigidBody.spherical_shell(1.0, float("inf")), ps.PoinsotError, "radius"),
    (lambda: ps.RigidBody.solid_cylinder(1.0, 1.0, -2.0), ps.PoinsotError, "height"),
    (lambda: ps.RigidBody.solid_cone(1.0, 0.0, 1.0), ps.PoinsotError, "radius"),
    (lambda: ps.RigidBody.cuboid(1.0, (1.0, -1.0, 1.0)), ps.PoinsotError, "sides"),
    (lambda: ps.RigidBody.cuboid(1.0, (1.0, 1.0)), ps.PoinsotError, "sides"),
    (lambda: ps.RigidBody.ellipsoid(1.0, (1.0, 1.0, 0.0)), ps.PoinsotError, "semi_axes"),
    (lambda: ps.RigidBody.thin_rod(1.0, -1.0), ps.PoinsotError, "length"),
    (lambda: ps.RigidBody.thin_disk(-1.0, 1.0), ps.PoinsotError, "mass"),
    (lambda: ps.RigidBody.thin_ring(1.0, float("nan")), ps.PoinsotError, "radius"),
    (
        lambda: ps.RigidBody.from_inertia(1.0, np.diag([1.0, 1.0, 3.0])),
        ps.InvalidInertiaError,
        "inertia",
    ),
    (
        lambda: ps.RigidBody.from_inertia(1.0, np.diag([-1.0, 1.0, 1.0])),
        ps.InvalidInertiaError,
        "inertia",
    ),
    (
        lambda: ps.RigidBody.from_inertia(1.0, [[1, 0.5, 0], [0, 1, 0], [0, 0, 1]]),
        ps.InvalidInertiaError,
        "inertia",
    ),
    (
        lambda: ps.RigidBody.from_inertia(1.0, np.diag([1.0, np.nan, 1.0])),
        ps.InvalidInertiaError,
        "inertia",
    ),
    (lambda: ps.RigidBody.from_inertia(1.0, np.eye(2)), ps.PoinsotError, "inertia"),
    (lambda: ps.RigidBody.from_inertia(0.0, np.eye(3)), ps.PoinsotError, "mass"),
    (lambda: ps.RigidBody.from_inertia(1.0, np.eye(3), (0, 0)), ps.PoinsotError, "center_of_mass"),
    (
        lambda: ps.RigidBody.from_inertia(1.0, np.eye(3), (0, 0, np.inf)),
        ps.PoinsotError,
        "center_of_mass",
    ),
    (
        lambda: ps.RigidBody.from_point_masses([1.0, -1.0], [[0, 0, 0], [1, 0, 0]]),
        ps.PoinsotError,
        "masses",
    ),
    (lambda: ps.RigidBody.from_point_masses([], np.zeros((0, 3))), ps.PoinsotError, "masses"),
    (lambda: ps.RigidBody.from_point_masses([1.0, 1.0], [[0, 0, 0]]), ps.PoinsotError, "positions"),
    (lambda: ps.RigidBody.from_point_masses([1.0], [[0, 0]]), ps.PoinsotError, "positions"),
    (lambda: ps.RigidBody.from_point_masses([1.0], [[0, np.nan, 0]]), ps.PoinsotError, "positions"),
    (
        lambda: ps.RigidBody.cuboid(1.0, (1, 1, 1)).angular_momentum([1.0, 2.0]),
        ps.PoinsotError,
        "omega",
    ),
    (
        lambda: ps.RigidBody.cuboid(1.0, (1, 1, 1)).kinetic_energy([1.0, np.nan, 2.0]),
        ps.PoinsotError,
        "omega",
    ),
    (
        lambda: ps.RigidBody.cuboid(1.0, (1, 1, 1)).holding_torque([1, 2, 3], about=[1, 2]),
        ps.PoinsotError,
        "about",
    ),
    (
        lambda: ps.RigidBody.cuboid(1.0, (1, 1, 1)).inertia_about([1.0, np.inf, 0.0]),
        ps.PoinsotError,
        "point",
    ),
    (lambda: ps.RigidBody.cuboid(1.0, (1, 1, 1)).translated([1.0, 2.0]), ps.PoinsotError, "offset"),
    (
        lambda: ps.RigidBody.cuboid(1.0, (1, 1, 1)).rotated(np.diag([1.0, 1.0, -1.0])),
        ps.InvalidRotationError,
        "rotation",
    ),
    (
        lambda: ps.RigidBody.cuboid(1.0, (1, 1, 1)).rotated(2 * np.eye(3)),
        ps.InvalidRotationError,
        "rotation",
    ),
    (lambda: ps.RigidBody.combine([]), ps.PoinsotError, "bodies"),
    (lambda: ps.RigidBody.combine([ps.RigidBody.thin_rod(1, 1), 3]), ps.PoinsotError, "bodies"),
    (lambda: ps.classify([1.0, 1.0, 3.0]), ps.InvalidInertiaError, "moments"),
    (lambda: ps.classify([1.0, 1.0]), ps.PoinsotError, "moments"),
    (lambda: ps.classify([1.0, 1.0, 1.0], rtol=-1.0), ps.PoinsotError, "rtol"),
    (lambda: ps.check_inertia(np.diag([1.0, 2.0, 4.0])), ps.InvalidInertiaError, "inertia"),
]


@pytest.mark.parametrize("case", range(len(BAD)))
def test_bad_input_is_refused_naming_the_argument(case: int) -> None:
    call, exc, argument = BAD[case]
    with pytest.raises(exc) as info:
        call()
    assert isinstance(info.value, ValueError)
    assert str(info.value).startswith(f"{argument}:"), str(info.value)


def test_triangle_message_says_by_how_much() -> None:
    with pytest.raises(ps.InvalidInertiaError, match=r"I1 \+ I2 >= I3.*by 1\.0"):
        ps.RigidBody.from_inertia(1.0, np.diag([1.0, 1.0, 3.0]))
    with pytest.raises(ps.InvalidInertiaError, match="symmetric"):
        ps.check_inertia([[1, 0.5, 0], [0, 1, 0], [0, 0, 1]])
    with pytest.raises(ps.PoinsotError, match=r"index 1"):
        ps.RigidBody.from_point_masses([1.0, -1.0], [[0, 0, 0], [1, 0, 0]])


def test_extreme_sizes_are_exact_or_refused_naming_the_argument() -> None:
    """Issue 10, 1.4: solid_sphere(1.0, 1e308) returned an infinite inertia."""
    with pytest.raises(ps.PoinsotError, match="^radius: .*largest finite"):
        ps.RigidBody.solid_sphere(1.0, 1e308)
    # Representable although r² overflows: exact (2/5 m r² = 0.4e100).
    b = ps.RigidBody.solid_sphere(1e-300, 1e200)
    assert b.inertia[0, 0] == pytest.approx(0.4e100, rel=1e-15)
    assert np.isfinite(b.inertia).all()
    with pytest.raises(ps.PoinsotError, match="^omega: "):
        ps.RigidBody.solid_sphere(1.0, 1.0).kinetic_energy([1e200, 0.0, 0.0])
    with pytest.raises(ps.PoinsotError, match="^point: "):
        ps.RigidBody.solid_sphere(1.0, 1.0).inertia_about([1e200, 0.0, 0.0])


def test_cuboid_sides_is_the_inverse_of_cuboid() -> None:
    """RigidBody.cuboid_sides (the core's inverse of cuboid): the sides come back from the
    principal moments; a cube of 12 kg and moments 2 kg·m² has sides 1 m (I = m a²/6, closed
    form); moments that no box has are refused naming ``moments`` (negative control)."""
    for mass, sides in (
        (2.0, (1.0, 2.0, 3.0)),
        (0.3, (0.24, 0.16, 0.04)),
        (5.0, (1e-9, 2e-9, 3e-9)),
    ):
        moments = np.diag(ps.RigidBody.cuboid(mass, sides).inertia)
        np.testing.assert_allclose(ps.RigidBody.cuboid_sides(mass, moments), sides, rtol=1e-13)
    np.testing.assert_allclose(
        ps.RigidBody.cuboid_sides(12.0, [2.0, 2.0, 2.0]), [1, 1, 1], rtol=1e-15
    )
    with pytest.raises(ps.PoinsotError, match="^moments: .*not the moments of a box"):
        ps.RigidBody.cuboid_sides(1.0, [1.0, 1.0, 3.0])
    with pytest.raises(ps.PoinsotError, match="^mass:"):
        ps.RigidBody.cuboid_sides(-1.0, [1.0, 1.0, 1.0])
