"""Mass properties of closed ~10⁶-triangle meshes: poinsot vs trimesh, same input, same run.

poinsot's time is the whole call, numpy in and results out, *including* its checks (closed,
manifold, consistently oriented, outward, no self-intersection, shells nested properly);
trimesh's ``mass_properties`` checks none of these. Both are also timed with trimesh's own
checks (``is_watertight``, ``is_winding_consistent``) added, for a like-for-like comparison of
the topology checks (trimesh has no self-intersection check).

Two meshes, because poinsot's self-intersection check has two paths: an icosphere is
star-shaped about its centre of mass, which proves it embedded in one pass over the faces; a
torus is not, so every pair of faces whose boxes meet is tested (the bounding-volume hierarchy
and the exact pairwise tests). Both ratios are printed.

Run: python bench/mesh_vs_trimesh.py [--subdivisions 8] [--torus 1024 512] [--repeat 7] [--runs 1]

``--runs N`` repeats the whole comparison N times and also prints the median of each ratio (a
shared machine's load moves single runs by a factor of up to two).
"""

from __future__ import annotations

import argparse
import os
import statistics
import time

import numpy as np
import poinsot as ps

try:
    import trimesh
except ImportError:  # pragma: no cover
    raise SystemExit(
        "bench/mesh_vs_trimesh.py needs trimesh: pip install 'poinsot[mesh]'"
    ) from None


def best(fns: list, repeat: int) -> list[float]:
    """Best wall time (s) of ``repeat`` calls of each of ``fns``, called in turn (one call of each
    per round), so that a change of the machine's load between rounds reaches all of them alike
    (timed one after the other in blocks, a loaded machine gave trimesh's two near-identical
    rows 2.8 and 3.5 s in one run)."""
    times: list[list[float]] = [[] for _ in fns]
    for _ in range(repeat):
        for fn, ts in zip(fns, times):
            t0 = time.perf_counter()
            fn()
            ts.append(time.perf_counter() - t0)
    return [min(ts) for ts in times]


def compare(title: str, mesh, repeat: int) -> float:
    """Times poinsot and trimesh on ``mesh``, prints the rows; returns trimesh's plain time over
    poinsot's (the ratio of the first trimesh row)."""
    vertices = np.ascontiguousarray(mesh.vertices, dtype=np.float64)
    faces = np.ascontiguousarray(mesh.faces, dtype=np.int64)
    print(f"{title}: {len(faces):,} triangles, {len(vertices):,} vertices")

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

    t_ours, *t_theirs = best([ours, theirs_build, theirs_only, theirs_checked], repeat)
    names = [
        "trimesh.Trimesh(v, f, process=False).mass_properties",
        "trimesh mass_properties only (mesh prebuilt, cache cleared)",
        "trimesh with is_watertight + is_winding_consistent checks",
    ]
    rows = list(zip(names, t_theirs))
    print(f"  {'poinsot RigidBody.from_mesh (with all its checks)':62s} {t_ours * 1e3:9.1f} ms")
    for name, t in rows:
        print(f"  {name:62s} {t * 1e3:9.1f} ms   poinsot is {t / t_ours:5.1f}x faster")
    return rows[0][1] / t_ours


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--subdivisions", type=int, default=8, help="icosphere subdivisions (8: 1.31M faces)"
    )
    parser.add_argument(
        "--torus",
        type=int,
        nargs=2,
        default=(1024, 512),
        metavar=("MAJOR", "MINOR"),
        help="torus sections (1024 512: 1.05M faces)",
    )
    parser.add_argument("--repeat", type=int, default=7)
    parser.add_argument(
        "--runs", type=int, default=1, help="whole comparisons; medians printed when > 1"
    )
    args = parser.parse_args()
    print(f"{os.cpu_count()} CPUs; best of {args.repeat}")
    ico = trimesh.creation.icosphere(subdivisions=args.subdivisions)
    major, minor = args.torus
    ring = trimesh.creation.torus(1.0, 0.3, major_sections=major, minor_sections=minor)
    spheres, tori = [], []
    for run in range(args.runs):
        if args.runs > 1:
            load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
            print(f"run {run + 1} of {args.runs} (load average {load:.1f})")
        spheres.append(
            compare(
                f"icosphere({args.subdivisions}), star-shaped (one pass proves it embedded)",
                ico,
                args.repeat,
            )
        )
        tori.append(
            compare(
                f"torus({major}x{minor}), not star-shaped (pairwise self-intersection tests)",
                ring,
                args.repeat,
            )
        )
        print(
            f"poinsot against trimesh's mass_properties: {spheres[-1]:.1f}x (icosphere), {tori[-1]:.1f}x (torus)"
        )
    if args.runs > 1:
        print(
            f"median of {args.runs} runs: {statistics.median(spheres):.1f}x (icosphere), "
            f"{statistics.median(tori):.1f}x (torus); "
            f"icosphere {min(spheres):.1f}-{max(spheres):.1f}x, torus {min(tori):.1f}-{max(tori):.1f}x"
        )


if __name__ == "__main__":
    main()
