"""Euler's and Chasles' theorems
=============================

Euler's and Chasles' theorems (the unit's section "Euler's Theorem").

Euler: a displacement of a rigid body with one point fixed is a rotation about one axis through
that point. Chasles: the most general displacement is a rotation about an axis plus a
translation along that same axis (a screw motion).

Run: .venv/bin/python examples/euler_and_chasles_theorems.py
"""

from __future__ import annotations

import numpy as np
import poinsot

np.set_printoptions(precision=5, suppress=True)

# ---- Euler's theorem: two successive rotations are one rotation -----------------------------
R1 = poinsot.axis_angle_to_matrix([1, 0, 0], 90.0, degrees=True)  # a quarter turn about x
R2 = poinsot.axis_angle_to_matrix([0, 0, 1], 90.0, degrees=True)  # then one about z
R = R2 @ R1
axis, angle = poinsot.rotation_axis(R)
print("quarter turn about x, then about z = one rotation of")
print(f"  {np.degrees(angle):.6f} deg about {axis} (the body diagonal (1,1,1)/sqrt 3)")
print("  the axis is fixed by R:", np.allclose(R @ axis, axis))

# The fig. 2.8 construction: every point keeps its distance from the axis OC.
rng = np.random.default_rng(1)
points = rng.normal(size=(5, 3))
moved = poinsot.rotate_vectors(R, points)


def dist(p: np.ndarray) -> np.ndarray:
    return np.linalg.norm(np.cross(p, axis), axis=-1)


print("  distances from the axis, before:", dist(points))
print("                           after: ", dist(moved))

# Accurate where the textbook formula angle = acos((tr R - 1)/2) is not:
tiny = poinsot.axis_angle_to_matrix([0, 1, 0], 1e-9)
print(
    "\nangle of a 1e-9 rad rotation: acos formula",
    np.arccos((np.trace(tiny) - 1) / 2),
    " poinsot",
    poinsot.rotation_axis(tiny)[1],
)

# ---- Chasles' theorem: a general displacement is a screw ------------------------------------
t = np.array([1.0, -1.0, 2.0])  # m
Rq = poinsot.axis_angle_to_matrix([0, 0, 1], 90.0, degrees=True)
screw = poinsot.screw_axis(Rq, t)
print("\nx -> R_z(90°) x + (1, -1, 2) m is the screw motion")
print(" ", screw)
x = np.array([0.3, 0.7, -1.0])
print("  screw reproduces the displacement:", np.allclose(screw.apply(x), Rq @ x + t))

# A general one, and its limits.
Rg = poinsot.euler_to_matrix([0.4, 1.2, -0.7])
tg = np.array([0.5, 2.0, -1.0])
s = poinsot.screw_axis(Rg, tg)
print("\ngeneral displacement:", s)
print("  R p + t - p = slide * axis:", np.allclose(Rg @ s.point + tg - s.point, s.slide * s.axis))
print("pure translation:", poinsot.screw_axis(np.eye(3), [0.0, 3.0, 4.0]))
print("pure rotation:   ", poinsot.screw_axis(Rq, [1.0, 1.0, 0.0]))
