"""Mass properties of a closed ~10⁶-triangle mesh: poinsot vs trimesh, same input, same run.

poinsot's time is the whole call, numpy in and results out, *including* its topology checks
(closed, manifold, consistently oriented, outward); trimesh's ``mass_properties`` checks none of
these. Both are also timed with trimesh's own checks (``is_watertight``,
``is_winding_consistent``) added, for a like-for-like validated comparison.

Run: python bench/mesh_vs_trimesh.py [--subdivisions 8] [--repeat 7]
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np

import poinsot as ps

try:
    import trimesh
except ImportError:  # pragma: no cover
    raise SystemExit("bench/mesh_vs_trimesh.py needs trimesh: pip install 'poinsot[mesh]'") from None


def best(fn, repeat: int) -> float:
    """Best wall time of ``repeat`` calls (s)."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--subdivisions", type=int, default=8, help="icosphere subdivisions (8: 1.31M faces)")
    parser.add_argument("--repeat", type=int, default=7)
    args = parser.parse_args()

    mesh = trimesh.creation.icosphere(subdivisions=args.subdivisions)
    vertices = np.ascontiguousarray(mesh.vertices, dtype=np.float64)
    faces = np.ascontiguousarray(mesh.faces, dtype=np.int64)
    print(
        f"icosphere({args.subdivisions}): {len(faces):,} triangles, {len(vertices):,} vertices; "
        f"{os.cpu_count()} CPUs; best of {args.repeat}"
    )

    def ours() -> tuple:
        b = ps.RigidBody.from_mesh(vertices, faces, density=1.0)
        return b.mass, b.center_of_mass, b.inertia

    def theirs_build() -> tuple:
        props = trimesh.Trimesh(vertices, faces, process=False).mass_properties
        return props["mass"], props["center_mass"], props["inertia"]

    prebuilt = trimesh.Trimesh(vertices, faces, process=False)

    def theirs_only() -> tuple:
        prebuilt._cache.clear()  # mass_properties is cached: time a fresh computation
        props = prebuilt.mass_properties
        return props["mass"], props["center_mass"], props["inertia"]

    def theirs_checked() -> tuple:
        m = trimesh.Trimesh(vertices, faces, process=False)
        if not (m.is_watertight and m.is_winding_consistent and m.volume > 0):
            raise ValueError("not a closed outward mesh")
        props = m.mass_properties
        return props["mass"], props["center_mass"], props["inertia"]

    a, b = ours(), theirs_build()
    assert np.isclose(a[0], b[0], rtol=1e-10) and np.allclose(a[2], b[2], rtol=1e-9, atol=1e-12)

    t_ours = best(ours, args.repeat)
    rows = [
        ("trimesh.Trimesh(v, f, process=False).mass_properties", best(theirs_build, args.repeat)),
        ("trimesh mass_properties only (mesh prebuilt, cache cleared)", best(theirs_only, args.repeat)),
        ("trimesh with is_watertight + is_winding_consistent checks", best(theirs_checked, args.repeat)),
    ]
    print(f"{'poinsot RigidBody.from_mesh (with topology checks)':62s} {t_ours * 1e3:9.1f} ms")
    for name, t in rows:
        print(f"{name:62s} {t * 1e3:9.1f} ms   poinsot is {t / t_ours:5.1f}x faster")


if __name__ == "__main__":
    main()
