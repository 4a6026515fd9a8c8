"""Euler's and Chasles' theorems
=============================

Euler's and Chasles' theorems (the unit's section "Euler's Theorem").

Euler: a displacement of a rigid body with one point fixed is a rotation about one axis through
that point. Chasles: the most general displacement is a rotation about an axis plus a
translation along that same axis (a screw motion).

Run: python examples/euler_and_chasles_theorems.py [out-folder]   (prints; writes
euler_theorem.png into out/, or the folder given as the first argument)
"""

# %%
# Euler's theorem: two rotations are one rotation
# -----------------------------------------------
#
# A quarter turn about x followed by a quarter turn about z leaves the origin where it is, so by
# Euler's theorem it is a single rotation about one axis. :func:`poinsot.rotation_axis` finds
# it: 120° about the body diagonal (1, 1, 1)/√3, which is the one line R leaves in place.

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import poinsot

out = Path(sys.argv[1] if len(sys.argv) > 1 else "out")
out.mkdir(parents=True, exist_ok=True)
np.set_printoptions(precision=5, suppress=True)

R1 = poinsot.axis_angle_to_matrix([1, 0, 0], 90.0, degrees=True)  # a quarter turn about x
R2 = poinsot.axis_angle_to_matrix([0, 0, 1], 90.0, degrees=True)  # then one about z
R = R2 @ R1
axis, angle = poinsot.rotation_axis(R)
print("quarter turn about x, then about z = one rotation of")
print(f"  {np.degrees(angle):.6f} deg about {axis} (the body diagonal (1,1,1)/sqrt 3)")
print("  the axis is fixed by R:", np.allclose(R @ axis, axis))

# %%
# The construction of the unit's Fig. 2.8
# ---------------------------------------
#
# Every point of the body keeps its distance from the axis OC. Five points drawn at random are
# moved by R (:func:`poinsot.rotate_vectors`): the two printed rows of distances are the same.

rng = np.random.default_rng(1)
points = rng.normal(size=(5, 3))
moved = poinsot.rotate_vectors(R, points)


def dist(p: np.ndarray) -> np.ndarray:
    return np.linalg.norm(np.cross(p, axis), axis=-1)


print("  distances from the axis, before:", dist(points))
print("                           after: ", dist(moved))

# %%
# Small angles
# ------------
#
# The textbook reads the angle off the trace, cos α = (tr R − 1)/2. For a rotation of 1e-9 rad
# the trace is 3 to within rounding and the formula returns 0; poinsot's ``rotation_axis``
# returns the angle itself.

tiny = poinsot.axis_angle_to_matrix([0, 1, 0], 1e-9)
print(
    "\nangle of a 1e-9 rad rotation: acos formula",
    np.arccos((np.trace(tiny) - 1) / 2),
    " poinsot",
    poinsot.rotation_axis(tiny)[1],
)

# %%
# Chasles' theorem: every displacement is a screw
# -----------------------------------------------
#
# A displacement x → R x + t of a free body is a rotation about one axis plus a slide along
# that same axis. :func:`poinsot.screw_axis` returns the axis (a point on it and its
# direction), the angle and the slide; applying the screw reproduces the displacement. Then a
# general one, and the two limits: a pure translation (angle 0, the axis along t) and a
# rotation with t perpendicular to the axis (slide 0: a plain rotation about a shifted axis).

t = np.array([1.0, -1.0, 2.0])  # m
Rq = poinsot.axis_angle_to_matrix([0, 0, 1], 90.0, degrees=True)
screw = poinsot.screw_axis(Rq, t)
print("\nx -> R_z(90°) x + (1, -1, 2) m is the screw motion")
print(" ", screw)
x = np.array([0.3, 0.7, -1.0])
print("  screw reproduces the displacement:", np.allclose(screw.apply(x), Rq @ x + t))

Rg = poinsot.euler_to_matrix([0.4, 1.2, -0.7])
tg = np.array([0.5, 2.0, -1.0])
s = poinsot.screw_axis(Rg, tg)
print("\ngeneral displacement:", s)
print("  R p + t - p = slide * axis:", np.allclose(Rg @ s.point + tg - s.point, s.slide * s.axis))
print("pure translation:", poinsot.screw_axis(np.eye(3), [0.0, 3.0, 4.0]))
print("pure rotation:   ", poinsot.screw_axis(Rq, [1.0, 1.0, 0.0]))

# %%
# The picture (the unit's Fig. 2.8)
# ---------------------------------
#
# The rotation R of the first step carries A to A′ and B to B′ (A and B are the first two of
# the random points above). The plane P₁ through O bisecting AA′ and the plane P₂ bisecting BB′
# meet in the line OC, the axis :func:`poinsot.rotation_axis` found; the dotted arcs carry A and
# B about OC through 120° and end on A′ and B′.

import matplotlib

matplotlib.use("Agg")
from poinsot.plots import plot_euler_theorem

plot_euler_theorem(R, points[:2]).savefig(out / "euler_theorem.png", dpi=110, bbox_inches="tight")
print("picture written: euler_theorem.png")
