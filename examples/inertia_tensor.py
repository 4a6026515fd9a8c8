"""The inertia tensor of the standard solids
=========================================

The inertia tensor (the unit's eqs. 2.46–2.50, 2.60–2.66): the standard solids side by side
with their textbook formulas, then the principal axes of a skewed body.

Run: python examples/inertia_tensor.py [out-folder]   (prints; writes inertia_solids.png and
inertia_skewed_body.png into out/, or the folder given as the first argument)
"""

# %%
# The standard solids against their textbook formulas
# ---------------------------------------------------
#
# Each constructor of :class:`poinsot.RigidBody` gives a solid's mass, centre of mass and
# inertia tensor I (the sums 2.46–2.50 done as integrals). For nine solids of mass 2 kg, radius
# 0.5 m and height 1.5 m the diagonal I_xx, I_yy, I_zz about the centre of mass is checked
# against the formula of the tables (the third column); the last column is the kind of top the
# principal moments make (symmetric when two are equal, a rotor when one is zero).

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import poinsot as ps

out = Path(sys.argv[1] if len(sys.argv) > 1 else "out")
out.mkdir(parents=True, exist_ok=True)
np.set_printoptions(precision=5, suppress=True)

m, r, h = 2.0, 0.5, 1.5  # kg, m, m
print(f"Standard solids, m = {m} kg, r = {r} m, h = {h} m (axis of symmetry z)\n")
solids = [
    ("solid sphere", ps.RigidBody.solid_sphere(m, r), "2/5 m r²", [0.4 * m * r**2] * 3),
    ("spherical shell", ps.RigidBody.spherical_shell(m, r), "2/3 m r²", [2 / 3 * m * r**2] * 3),
    (
        "solid cylinder",
        ps.RigidBody.solid_cylinder(m, r, h),
        "m(3r²+h²)/12, m r²/2",
        [m * (3 * r**2 + h**2) / 12] * 2 + [m * r**2 / 2],
    ),
    (
        "solid cone (apex at 0)",
        ps.RigidBody.solid_cone(m, r, h),
        "3/20 m r² + 3/80 m h², 3/10 m r²",
        [m * (3 / 20 * r**2 + 3 / 80 * h**2)] * 2 + [0.3 * m * r**2],
    ),
    (
        "cuboid 1×2×3",
        ps.RigidBody.cuboid(m, (1.0, 2.0, 3.0)),
        "m(b²+c²)/12, ...",
        [m * 13 / 12, m * 10 / 12, m * 5 / 12],
    ),
    (
        "ellipsoid 1, 2, 3",
        ps.RigidBody.ellipsoid(m, (1.0, 2.0, 3.0)),
        "m(b²+c²)/5, ...",
        [m * 13 / 5, m * 10 / 5, m * 5 / 5],
    ),
    ("thin rod (length h)", ps.RigidBody.thin_rod(m, h), "m h²/12, 0", [m * h**2 / 12] * 2 + [0.0]),
    (
        "thin disk",
        ps.RigidBody.thin_disk(m, r),
        "m r²/4, m r²/2",
        [m * r**2 / 4] * 2 + [m * r**2 / 2],
    ),
    ("thin ring", ps.RigidBody.thin_ring(m, r), "m r²/2, m r²", [m * r**2 / 2] * 2 + [m * r**2]),
]
print(f"{'solid':24s} {'I_xx, I_yy, I_zz about the c.o.m. (kg·m²)':44s} {'textbook':34s} kind")
for name, body, formula, expected in solids:
    diag = np.diag(body.inertia)
    assert np.allclose(diag, expected, rtol=1e-12, atol=0), name
    cells = ", ".join(f"{x:.5f}" for x in diag)
    print(f"{name:24s} {cells:44s} {formula:34s} {body.kind}")

# %%
# Moving the reference point: the cone about its apex
# ---------------------------------------------------
#
# The cone is built with its apex at the origin, so its centre of mass is 3h/4 up the axis.
# ``inertia_about`` moves the tensor to another point by the parallel-axis theorem: about the
# apex the two transverse moments grow by m (3h/4)², the axial one is unchanged.

cone = solids[3][1]
print(f"\nThe cone's apex is at the origin: centre of mass {cone.center_of_mass} m (3h/4 on z),")
print("and its inertia about the apex (parallel-axis theorem) is")
print(cone.inertia_about([0.0, 0.0, 0.0]))

# %%
# A skewed body and its principal axes (eqs. 2.46–2.50, 2.60–2.66)
# ----------------------------------------------------------------
#
# Four point masses placed with no symmetry make a body with products of inertia: I is full,
# and L is not parallel to ω. The principal axes are the eigenvectors of I (columns of a
# proper rotation A); in them Aᵀ I A is diagonal — look at the vanishing off-diagonal entries —
# and the principal moments I₁ ≤ I₂ ≤ I₃ are its diagonal. Spun at 3 rad/s about z, the body's
# angular momentum L = I·ω (2.63) leans away from ω by the printed angle.

# Products of inertia are negated (I_xy = −Σ m x y), so L = I·ω (2.63).
masses = np.array([1.0, 2.0, 1.5, 0.5])
positions = np.array([[1.0, 0.2, 0.0], [-0.3, 0.8, 0.5], [0.1, -0.6, -0.4], [0.4, 0.3, 1.2]])
body = ps.RigidBody.from_point_masses(masses, positions)
print("\nA skewed body of four point masses:")
print(body)
print("inertia about the centre of mass (kg·m²):")
print(body.inertia)
A = body.principal_axes
print("principal moments I1 ≤ I2 ≤ I3 (kg·m²):", body.principal_moments)
print(f"principal axes (columns, a proper rotation, det = {np.linalg.det(A):+.1f}):")
print(A)
print("in principal axes the products of inertia vanish (2.65–2.66): Aᵀ I A =")
print(A.T @ body.inertia @ A)
omega = np.array([0.0, 0.0, 3.0])
print(
    f"ω = {omega} rad/s: L = I·ω = {body.angular_momentum(omega)} kg·m²/s,"
    f" T = ½ ω·I·ω = {body.kinetic_energy(omega):.5f} J,"
    f" angle(L, ω) = {body.momentum_angle(omega, degrees=True):.3f}°"
)

# %%
# The inertia ellipsoids (eqs. 2.63–2.66)
# ---------------------------------------
#
# Poinsot's inertia ellipsoid ρ·I·ρ = 1 has its semi-axes along the principal axes with lengths
# 1/√Iᵢ: the longest belongs to the smallest moment. First three of the solids above: the
# cylinder (I₁ < I₂ = I₃: long along its axis e₁), the thin disk (I₁ = I₂ < I₃: flattened along
# its axis e₃) and the cuboid 1 × 2 × 3 m (three different moments). Second, the skewed body:
# its ellipsoid is turned with its principal axes, away from x, y, z.

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from poinsot.plots import plot_inertia_ellipsoid

# sphinx_gallery_thumbnail_number = 2
by_name = {name: solid for name, solid, _, _ in solids}
fig = plt.figure(figsize=(15, 5.6), layout="constrained")
for k, name in enumerate(("solid cylinder", "thin disk", "cuboid 1×2×3")):
    plot_inertia_ellipsoid(by_name[name], fig.add_subplot(1, 3, k + 1, projection="3d"), name=name)
fig.savefig(out / "inertia_solids.png", dpi=110, bbox_inches="tight")
plot_inertia_ellipsoid(body, name="skewed body").savefig(
    out / "inertia_skewed_body.png", dpi=110, bbox_inches="tight"
)
print("pictures written: inertia_solids.png, inertia_skewed_body.png")
