"""RigidBody.from_mesh / from_trimesh / load_mesh: exact polyhedral integrals against closed
forms (faceted solids have exact formulas: n-gon prisms and pyramids), against the standard
solids (tolerance from the mesh's own resolution), against trimesh on watertight meshes, and
the refusal of meshes that do not bound a solid (trimesh integrates those silently).
"""

from __future__ import annotations

import sys

import numpy as np
import poinsot as ps
import pytest
from scipy.spatial.transform import Rotation

trimesh = pytest.importorskip("trimesh")

#: Round-off of the exact integrals on meshes of up to ~10⁵ faces.
EXACT = 1e-11


def ngon(n: int, r: float) -> tuple[float, float]:
    """Area and polar second moment about the centre of a regular n-gon of circumradius r."""
    a = 2 * np.pi / n
    return n * r * r * np.sin(a) / 2, n * r**4 * np.sin(a) * (2 + np.cos(a)) / 12


def boundary_edges(faces: np.ndarray) -> int:
    """Number of undirected edges used by exactly one face (independent numpy count)."""
    e = np.sort(np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]]), axis=1)
    _, counts = np.unique(e, axis=0, return_counts=True)
    return int((counts == 1).sum())


def apex_down_cone(r: float, h: float, sections: int) -> trimesh.Trimesh:
    """trimesh's cone (base at z = 0, apex at z = h) turned 180° about x and lifted by h: apex at
    the origin, axis +z (poinsot's convention). A proper rotation keeps the faces outward."""
    cone = trimesh.creation.cone(radius=r, height=h, sections=sections)
    cone.apply_transform(trimesh.transformations.rotation_matrix(np.pi, [1, 0, 0]))
    cone.apply_translation([0, 0, h])
    return cone


# ---- faceted solids: exact ------------------------------------------------------------------------


@pytest.mark.parametrize("n", [3, 5, 64])
def test_prism_and_pyramid_meshes_are_exact(n: int) -> None:
    r, h, rho = 0.5, 1.5, 3.0
    area, J = ngon(n, r)
    cyl = ps.RigidBody.from_trimesh(
        trimesh.creation.cylinder(radius=r, height=h, sections=n), density=rho
    )
    m = rho * area * h
    ixx = rho * h * J / 2 + m * h * h / 12
    assert cyl.mass == pytest.approx(m, rel=EXACT)
    np.testing.assert_allclose(
        cyl.inertia, np.diag([ixx, ixx, rho * h * J]), rtol=EXACT, atol=EXACT * ixx
    )
    cone = ps.RigidBody.from_trimesh(apex_down_cone(r, h, n), density=rho)
    m = rho * area * h / 3
    ixx_apex = rho * (J * h / 10 + area * h**3 / 5)
    ixx = ixx_apex - m * (0.75 * h) ** 2
    assert cone.mass == pytest.approx(m, rel=EXACT)
    np.testing.assert_allclose(cone.center_of_mass, [0, 0, 0.75 * h], atol=EXACT)
    np.testing.assert_allclose(
        cone.inertia, np.diag([ixx, ixx, rho * J * h / 5]), rtol=EXACT, atol=EXACT * ixx
    )


def test_box_mesh_equals_cuboid_exactly() -> None:
    sides, rho = np.array([0.3, 1.7, 2.2]), 7850.0
    box = trimesh.creation.box(extents=sides)
    body = ps.RigidBody.from_mesh(box.vertices, box.faces, density=rho)
    ref = ps.RigidBody.cuboid(rho * sides.prod(), sides)
    assert body.mass == pytest.approx(ref.mass, rel=EXACT)
    np.testing.assert_allclose(
        body.inertia, ref.inertia, rtol=EXACT, atol=EXACT * ref.inertia.max()
    )
    np.testing.assert_allclose(body.center_of_mass, 0.0, atol=EXACT)


# ---- every standard solid against a mesh of it ----------------------------------------------------


def volume_deficit(mesh: trimesh.Trimesh, exact_volume: float) -> float:
    """Relative volume lost by faceting: the resolution of an inscribed mesh."""
    return abs(1 - mesh.volume / exact_volume)


def test_sphere_ellipsoid_and_shell_meshes_within_resolution() -> None:
    """An inscribed mesh loses volume ε; with the mesh's own mass, the inertia then differs from
    the formula by about (2/3) ε (I ∝ m r², r shrinks by ε/3): tolerance 2 ε."""
    r = 0.7
    sphere = trimesh.creation.icosphere(subdivisions=5, radius=r)
    eps = volume_deficit(sphere, 4 / 3 * np.pi * r**3)
    assert 0 < eps < 1e-3
    body = ps.RigidBody.from_trimesh(sphere, density=1000.0)
    ref = ps.RigidBody.solid_sphere(body.mass, r)
    np.testing.assert_allclose(
        body.inertia, ref.inertia, rtol=2 * eps, atol=2 * eps * ref.inertia.max()
    )
    assert ps.classify(body.principal_moments, rtol=2 * eps) == "spherical top"
    # Ellipsoid: the same sphere scaled (a positive scaling keeps faces outward).
    axes = np.array([0.5, 1.0, 2.0])
    ell = sphere.copy()
    ell.apply_scale(1 / r)
    ell.apply_transform(np.diag([*axes, 1.0]))
    body = ps.RigidBody.from_trimesh(ell)
    ref = ps.RigidBody.ellipsoid(body.mass, axes)
    np.testing.assert_allclose(
        body.inertia, ref.inertia, rtol=2 * eps, atol=2 * eps * ref.inertia.max()
    )
    # Thick spherical shell: outer sphere outward plus inner sphere inward (two components).
    outer = trimesh.creation.icosphere(subdivisions=5, radius=1.0)
    inner = trimesh.creation.icosphere(subdivisions=5, radius=0.95)
    v = np.vstack([outer.vertices, inner.vertices])
    f = np.vstack([outer.faces, inner.faces[:, ::-1] + len(outer.vertices)])
    shell = ps.RigidBody.from_mesh(v, f)
    a, b = 1.0, 0.95
    exact_mass = 4 / 3 * np.pi * (a**3 - b**3)
    eps = volume_deficit(outer, 4 / 3 * np.pi)
    assert shell.mass == pytest.approx(
        exact_mass, rel=20 * eps
    )  # thin shell: ε relative to volume grows
    thick = 0.4 * shell.mass * (a**5 - b**5) / (a**3 - b**3)  # 2/5 m (a⁵ − b⁵)/(a³ − b³)
    np.testing.assert_allclose(np.diag(shell.inertia), [thick] * 3, rtol=5 * eps)
    # ... which tends to the thin shell's 2/3 m r² as the thickness vanishes (here within 5 %).
    thin = ps.RigidBody.spherical_shell(shell.mass, 1.0)
    np.testing.assert_allclose(np.diag(shell.inertia), np.diag(thin.inertia), rtol=0.05)


def test_cylinder_and_cone_meshes_tend_to_the_solids() -> None:
    """Faceting an n-gon loses O((2π/n)²) of the moments: tolerance (2π/n)²."""
    r, h, n = 0.5, 1.5, 256
    tol = (2 * np.pi / n) ** 2
    cyl = ps.RigidBody.from_trimesh(trimesh.creation.cylinder(radius=r, height=h, sections=n))
    np.testing.assert_allclose(
        cyl.inertia,
        ps.RigidBody.solid_cylinder(cyl.mass, r, h).inertia,
        rtol=tol,
        atol=tol * cyl.inertia.max(),
    )
    cone = ps.RigidBody.from_trimesh(apex_down_cone(r, h, n))
    ref = ps.RigidBody.solid_cone(cone.mass, r, h)
    np.testing.assert_allclose(cone.center_of_mass, ref.center_of_mass, atol=EXACT)
    np.testing.assert_allclose(cone.inertia, ref.inertia, rtol=tol, atol=tol * ref.inertia.max())
    assert cone.kind == "symmetric top"


def test_thin_shapes_as_limits_of_meshes_and_particles() -> None:
    """Thin rod, disk and ring have no volume, so no mesh or density of their own: they are
    checked as limits of meshes (thin prism, thin torus) and against particles."""
    m, r, L = 2.0, 0.5, 1.2
    # Disk: an n-gon prism of height h has I_xx = ρ h J/2 + m h²/12 → m r²/4.
    n, h = 512, 1e-4
    disk = ps.RigidBody.from_trimesh(trimesh.creation.cylinder(radius=r, height=h, sections=n))
    ref = ps.RigidBody.thin_disk(disk.mass, r)
    tol = (2 * np.pi / n) ** 2 + (h / r) ** 2
    np.testing.assert_allclose(disk.inertia, ref.inertia, rtol=tol, atol=EXACT * ref.inertia.max())
    # Ring: a torus of minor radius a has I_zz = m (R² + 3/4 a²), I_xx = m (R²/2 + 5/8 a²).
    a = 0.01
    torus = trimesh.creation.torus(
        major_radius=r, minor_radius=a, major_sections=256, minor_sections=64
    )
    ring_mesh = ps.RigidBody.from_trimesh(torus)
    eps = volume_deficit(torus, 2 * np.pi**2 * r * a * a)
    mt = ring_mesh.mass
    torus_formula = np.diag([mt * (r * r / 2 + 5 / 8 * a * a)] * 2 + [mt * (r * r + 0.75 * a * a)])
    tol = 2 * eps + (2 * np.pi / 256) ** 2
    scale = EXACT * torus_formula.max()
    np.testing.assert_allclose(ring_mesh.inertia, torus_formula, rtol=tol, atol=scale)
    ring = ps.RigidBody.thin_ring(mt, r)
    np.testing.assert_allclose(
        ring_mesh.inertia, ring.inertia, rtol=tol + 2 * (a / r) ** 2, atol=scale
    )
    # ... and particles: N ≥ 3 equal masses on a circle have exactly the ring's inertia.
    phi = 2 * np.pi * np.arange(7) / 7
    pts = ps.RigidBody.from_point_masses(
        np.full(7, m / 7), np.c_[r * np.cos(phi), r * np.sin(phi), np.zeros(7)]
    )
    np.testing.assert_allclose(
        pts.inertia, ps.RigidBody.thin_ring(m, r).inertia, rtol=1e-14, atol=1e-15
    )
    # Rod: N particles at the midpoints of N equal segments give m L²/12 (1 − 1/N²) exactly.
    N = 50
    z = (np.arange(N) + 0.5) / N * L - L / 2
    rod_pts = ps.RigidBody.from_point_masses(np.full(N, m / N), np.c_[np.zeros(N), np.zeros(N), z])
    rod = ps.RigidBody.thin_rod(m, L)
    np.testing.assert_allclose(
        rod_pts.inertia, rod.inertia * (1 - 1 / N**2), rtol=1e-13, atol=1e-15
    )
    assert rod_pts.kind == rod.kind == "rotor"
    # ... and a long thin prism (n-gon radius ρ_r): I_xx = m (J/(2A) + L²/12) → m L²/12.
    rr = 1e-3
    stick = ps.RigidBody.from_trimesh(trimesh.creation.cylinder(radius=rr, height=L, sections=64))
    tol = 2 * (rr / L) ** 2 * 12
    rod = ps.RigidBody.thin_rod(stick.mass, L)
    np.testing.assert_allclose(
        stick.inertia[:2, :2], rod.inertia[:2, :2], rtol=tol, atol=EXACT * rod.inertia.max()
    )


# ---- trimesh agreement ----------------------------------------------------------------------------


def test_convention_trimesh_products_of_inertia_are_negated_too() -> None:
    """trimesh's mass_properties['inertia'] uses the same sign convention: for the unit
    tetrahedron (0, e1, e2, e3) about its centre of mass, Σ m x y = ρ V (1/20 − 1/16) = −1/480
    (ρ = 1, V = 1/6), so I_xy = +1/480."""
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    f = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    ours = ps.RigidBody.from_mesh(v, f)
    theirs = trimesh.Trimesh(v, f, process=False).mass_properties
    assert ours.inertia[0, 1] == pytest.approx(1 / 480, rel=1e-14)
    assert theirs["inertia"][0, 1] == pytest.approx(1 / 480, rel=1e-12)
    # I_xx = ρ ∫ (y² + z²) − m (c_y² + c_z²) = 2/60 − 1/6 · 2/16 = 1/80.
    assert ours.inertia[0, 0] == pytest.approx(1 / 80, rel=1e-14)


def _watertight_meshes() -> list[trimesh.Trimesh]:
    rng = np.random.default_rng(7)
    skew = trimesh.creation.box(extents=(0.3, 1.1, 2.0))
    skew.apply_transform(
        trimesh.transformations.compose_matrix(angles=[0.3, -0.8, 1.9], translate=[5.0, -2.0, 1.0])
    )
    hull = trimesh.convex.convex_hull(rng.normal(size=(200, 3)) * [1.0, 2.0, 0.5] + [1, 2, 3])
    two = trimesh.util.concatenate(
        [
            trimesh.creation.icosphere(3),
            trimesh.creation.box(extents=(1, 1, 1)).apply_translation([3, 0, 0]),
        ]
    )
    return [
        trimesh.creation.icosphere(subdivisions=4, radius=2.0),
        trimesh.creation.cylinder(radius=0.3, height=2.0, sections=40),
        trimesh.creation.torus(major_radius=1.0, minor_radius=0.3),
        trimesh.creation.capsule(height=1.0, radius=0.4),
        skew,
        hull,
        two,
    ]


@pytest.mark.parametrize("index", range(7))
def test_agrees_with_trimesh_on_watertight_meshes(index: int) -> None:
    mesh = _watertight_meshes()[index]
    assert mesh.is_watertight and mesh.is_winding_consistent and mesh.volume > 0
    mesh.density = 2700.0
    theirs = mesh.mass_properties
    ours = ps.RigidBody.from_trimesh(mesh, density=2700.0)
    assert ours.mass == pytest.approx(theirs["mass"], rel=1e-10)
    np.testing.assert_allclose(ours.center_of_mass, theirs["center_mass"], rtol=1e-10, atol=1e-10)
    np.testing.assert_allclose(
        ours.inertia, theirs["inertia"], rtol=1e-9, atol=1e-10 * np.abs(theirs["inertia"]).max()
    )


# ---- refusals -------------------------------------------------------------------------------------


def _sphere() -> tuple[np.ndarray, np.ndarray]:
    s = trimesh.creation.icosphere(subdivisions=2)
    return np.asarray(s.vertices), np.asarray(s.faces)


def test_open_mesh_is_refused_with_the_number_of_boundary_edges() -> None:
    v, f = _sphere()
    holed = f[3:]  # three faces removed
    n = boundary_edges(holed)
    with pytest.raises(ps.InvalidMeshError, match=rf"^faces: the mesh is open: {n} boundary edge"):
        ps.RigidBody.from_mesh(v, holed)
    # trimesh integrates the open mesh silently (a wrong number):
    assert np.isfinite(trimesh.Trimesh(v, holed, process=False).mass_properties["mass"])
    # Negative control: the same faces, closed, pass.
    assert ps.RigidBody.from_mesh(v, f).mass > 0


def test_non_manifold_mesh_is_refused() -> None:
    v, f = _sphere()
    # Two more faces hung on the edge (f[0][0], f[0][1]), both ways: that edge has 4 faces.
    a, b = f[0][0], f[0][1]
    v2 = np.vstack([v, [[3.0, 3.0, 3.0]]])
    tip = len(v)
    fin = np.vstack([f, [[a, b, tip], [b, a, tip]]])
    with pytest.raises(ps.InvalidMeshError, match="non-manifold.*used by 4 faces"):
        ps.RigidBody.from_mesh(v2, fin)
    # Negative control: without the fin (the extra vertex unused) the mesh passes.
    assert ps.RigidBody.from_mesh(v2, fin[:-2]).mass == pytest.approx(
        ps.RigidBody.from_mesh(v, f).mass
    )


def test_inside_out_mesh_is_refused_and_reversed_passes() -> None:
    v, f = _sphere()
    with pytest.raises(ps.InvalidMeshError, match="faces are oriented inward; reverse the winding"):
        ps.RigidBody.from_mesh(v, f[:, ::-1])
    # trimesh returns a negative mass for it; reversing the winding fixes the mesh.
    assert trimesh.Trimesh(v, f[:, ::-1], process=False).mass_properties["mass"] < 0
    fixed = ps.RigidBody.from_mesh(v, f[:, ::-1][:, ::-1])
    np.testing.assert_array_equal(fixed.inertia, ps.RigidBody.from_mesh(v, f).inertia)


def test_inconsistently_oriented_mesh_is_refused() -> None:
    v, f = _sphere()
    bad = f.copy()
    bad[10] = bad[10][::-1]
    with pytest.raises(ps.InvalidMeshError, match="inconsistently oriented: 3 edge"):
        ps.RigidBody.from_mesh(v, bad)
    # Negative control: the face turned back passes.
    bad[10] = bad[10][::-1]
    assert ps.RigidBody.from_mesh(v, bad).mass > 0


BAD_MESHES = [
    (lambda v, f: (v, np.where(f == f[5, 1], len(v) + 7, f)), "faces", "out of range"),
    (lambda v, f: (v, np.where(f == f[5, 1], -1, f)), "faces", "out of range"),
    (lambda v, f: (v, f.astype(float)), "faces", "integer"),
    (lambda v, f: (v, f[:, :2]), "faces", "shape"),
    (lambda v, f: (v[:, :2], f), "vertices", "shape"),
    (lambda v, f: (np.where(np.arange(len(v))[:, None] == 4, np.nan, v), f), "vertices", "finite"),
    (lambda v, f: (v * [1.0, 1.0, 0.0], f), "vertices", "zero volume"),
    (lambda v, f: (np.zeros_like(v), f), "faces", "degenerate"),
    (lambda v, f: (v, f[:3]), "faces", "at least 4 faces"),
]


@pytest.mark.parametrize("case", range(len(BAD_MESHES)))
def test_bad_meshes_are_refused_naming_the_argument(case: int) -> None:
    make, argument, words = BAD_MESHES[case]
    v, f = make(*_sphere())
    with pytest.raises(ps.InvalidMeshError, match=f"^{argument}:.*{words}"):
        ps.RigidBody.from_mesh(v, f)


def test_bad_density_for_a_mesh() -> None:
    v, f = _sphere()
    for rho in (0.0, -1.0, float("nan")):
        with pytest.raises(ps.PoinsotError, match="^density:"):
            ps.RigidBody.from_mesh(v, f, density=rho)
    with pytest.raises(ps.InvalidMeshError, match="^mesh:"):
        ps.RigidBody.from_trimesh("not a mesh")


# ---- files ---------------------------------------------------------------------------------------


@pytest.mark.parametrize("suffix", [".stl", ".obj", ".ply"])
def test_load_mesh_merges_duplicate_vertices(tmp_path, suffix: str) -> None:
    mesh = trimesh.creation.icosphere(subdivisions=3)
    path = tmp_path / f"ball{suffix}"
    mesh.export(path)
    body = ps.RigidBody.load_mesh(path, density=1000.0)
    ref = ps.RigidBody.from_trimesh(mesh, density=1000.0)
    # STL and PLY store coordinates in float32, OBJ in 8 decimals: single-precision agreement.
    rtol = 1e-6
    assert body.mass == pytest.approx(ref.mass, rel=rtol)
    np.testing.assert_allclose(body.inertia, ref.inertia, rtol=rtol, atol=rtol * ref.inertia.max())
    if suffix == ".stl":
        # The STL as stored (a triangle soup, no shared vertices) looks open until merged.
        soup = trimesh.load(path, process=False, force="mesh")
        with pytest.raises(ps.InvalidMeshError, match="open"):
            ps.RigidBody.from_trimesh(soup)
        merged = ps.RigidBody.from_trimesh(soup, density=1000.0, merge_vertices=True)
        assert merged.mass == pytest.approx(body.mass, rel=1e-12)


def test_load_mesh_without_trimesh_says_how_to_install(monkeypatch, tmp_path) -> None:
    monkeypatch.setitem(sys.modules, "trimesh", None)
    with pytest.raises(ImportError, match=r"poinsot\[mesh\]"):
        ps.RigidBody.load_mesh(tmp_path / "x.stl")


def test_large_mesh_runs_and_agrees() -> None:
    """~1.3·10⁵ triangles (timing lives in bench/mesh_vs_trimesh.py, not here)."""
    mesh = trimesh.creation.icosphere(subdivisions=6)
    ours = ps.RigidBody.from_trimesh(mesh)
    np.testing.assert_allclose(
        ours.inertia, mesh.mass_properties["inertia"], rtol=1e-10, atol=1e-13
    )
    rot = Rotation.from_euler("xyz", [0.1, 0.2, 0.3])
    turned = ps.RigidBody.from_mesh(rot.apply(mesh.vertices), mesh.faces)
    np.testing.assert_allclose(turned.principal_moments, ours.principal_moments, rtol=1e-11)


def _two(a: trimesh.Trimesh, b: trimesh.Trimesh) -> tuple[np.ndarray, np.ndarray]:
    """One vertex and face array holding both meshes (b's indices renumbered)."""
    return np.vstack([a.vertices, b.vertices]), np.vstack([a.faces, b.faces + len(a.vertices)])


def test_self_intersecting_meshes_are_refused_naming_two_faces() -> None:
    """Issue 10, 1.6: two overlapping unit cubes gave mass 2 (their union is 1.5, trimesh's
    boolean union says so); a sphere with a vertex pushed through it was accepted."""
    a = trimesh.creation.box()
    b = trimesh.creation.box()
    b.apply_translation([0.5, 0.0, 0.0])
    v, f = _two(a, b)
    with pytest.raises(
        ps.InvalidMeshError, match=r"faces: the mesh intersects itself: faces \d+ and \d+"
    ):
        ps.RigidBody.from_mesh(v, f)
    # Negative control: apart, they are a composite body of mass 2.
    b.apply_translation([0.5 + 1e-9, 0.0, 0.0])
    v, f = _two(a, b)
    assert ps.RigidBody.from_mesh(v, f).mass == pytest.approx(2.0, abs=EXACT)
    s = trimesh.creation.icosphere(subdivisions=2)
    top = int(np.argmax(s.vertices[:, 2]))
    s.vertices[top] = [0.01, 0.02, -1.5]
    with pytest.raises(ps.InvalidMeshError, match="intersects itself"):
        ps.RigidBody.from_mesh(s.vertices, s.faces)


def test_nested_shells_must_alternate_winding() -> None:
    """Two nested shells of the same winding gave 28 for 27; with the inner one reversed they
    are a hollow body (27 − 1), as trimesh's volume of the difference says."""
    outer = trimesh.creation.box(extents=[3, 3, 3])
    inner = trimesh.creation.box(extents=[1, 1, 1])
    v, f = _two(outer, inner)
    with pytest.raises(ps.InvalidMeshError, match="counted twice"):
        ps.RigidBody.from_mesh(v, f)
    hollow = ps.RigidBody.from_mesh(
        v, np.vstack([outer.faces, inner.faces[:, ::-1] + len(outer.vertices)])
    )
    assert hollow.mass == pytest.approx(26.0, abs=EXACT)


def test_unused_far_vertex_changes_nothing() -> None:
    """An unused vertex at 1e5 cost 1.9e-6 of relative accuracy, one at 1e6 a refusal."""
    m = trimesh.creation.box(extents=[1, 2, 3])
    base = ps.RigidBody.from_mesh(m.vertices, m.faces, 2.0)
    for far in (1e5, 1e6, 1e300):
        body = ps.RigidBody.from_mesh(np.vstack([m.vertices, [[far, far, far]]]), m.faces, 2.0)
        assert body.mass == base.mass
        np.testing.assert_array_equal(body.inertia, base.inertia)
