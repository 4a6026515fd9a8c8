"""Moving frames
=============

Moving frames (the unit's eqs. 2.1–2.28): the acceleration of a particle seen from a turning,
accelerating frame, split into its named terms; the fictitious forces; and a particle integrated
in the moving frame that agrees with the same motion integrated in the fixed frame.

Run: python examples/moving_frames.py [out-folder]   (prints; writes moving_frames_axes.png and
moving_frames_centripetal.png into out/, or the folder given as the first argument)
"""

# %%
# The frame: a turntable on a lift
# --------------------------------
#
# A :class:`poinsot.MovingFrame` holds the frame's state at one instant, in fixed components:
# here a turntable turning at ω = 1.5 rad/s about the vertical and spinning up at
# ω̇ = 0.2 rad/s² (ω̇ ∥ ω), carried by a lift that accelerates upwards at R̈ = 2 m/s². A bead sits
# 0.4 m from the centre and slides across the turntable at 0.3 m/s.

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import poinsot as ps

out = Path(sys.argv[1] if len(sys.argv) > 1 else "out")
out.mkdir(parents=True, exist_ok=True)

frame = ps.MovingFrame(
    acceleration=[0.0, 0.0, 2.0],
    angular_velocity=[0.0, 0.0, 1.5],
    angular_acceleration=[0.0, 0.0, 0.2],
)
r, v, a = np.array([0.4, 0.0, 0.0]), np.array([0.0, 0.3, 0.0]), np.zeros(3)

# %%
# The acceleration seen from the fixed frame (eq. 2.21)
# -----------------------------------------------------
#
# ``to_fixed`` turns the bead's position, velocity and acceleration relative to the turntable
# into the fixed frame's. Its ``acceleration_terms`` are the five terms of eq. 2.21: the
# relative acceleration, the origin's R̈, the Coriolis term 2ω × ṙ, the centripetal
# ω × (ω × r) (of magnitude ω² r sin θ, eq. 2.24) and the Euler term ω̇ × r. Look at the last
# line: the terms add up to the total. ``to_moving`` is the inverse, and brings the bead back.

fixed = frame.to_fixed(r, v, a)
print("a bead at r = (0.4, 0, 0) m sliding at (0, 0.3, 0) m/s on the turntable:")
for name, term in fixed.acceleration_terms.items():
    print(f"  {name:12s} {np.array2string(term, precision=4, suppress_small=True)} m/s²")
print(
    f"  {'total':12s} {np.array2string(fixed.acceleration, precision=4, suppress_small=True)} m/s²  (eq. 2.21)"
)
assert np.allclose(sum(fixed.acceleration_terms.values()), fixed.acceleration)

# Going back: the fixed-frame motion seen from the turntable.
back = frame.to_moving(fixed.position, fixed.velocity, fixed.acceleration)
assert (
    np.allclose(back.position, r)
    and np.allclose(back.velocity, v)
    and np.allclose(back.acceleration, a)
)

# %%
# The fictitious forces (eqs. 2.5, 2.26–2.28)
# -------------------------------------------
#
# Seen from the turntable, the same terms moved to the other side of m r̈ = F are forces: the
# translational force −m R̈ (2.5), the Coriolis force −2m ω × ṙ, the centrifugal force
# −m ω × (ω × r) and the Euler force −m ω̇ × r, in the turntable's components. For a 50 g bead
# the centrifugal force points outwards along x and the Coriolis force is across the bead's
# sliding. A frame in uniform motion has none at all: Newton's laws keep their form there
# (Galilean invariance, 2.5 with R̈ = 0).

forces = frame.fictitious_forces(0.05, r, v)  # a 50 g bead
print("fictitious forces on a 50 g bead (eqs. 2.5, 2.26–2.28):")
for name, f in forces.items():
    print(f"  {name:13s} {np.array2string(f + 0.0, precision=5, suppress_small=True)} N")

# Galilean invariance (2.5 with R̈ = 0): a uniformly moving frame has no fictitious force.
uniform = ps.MovingFrame(velocity=[30.0, 0.0, 0.0])
assert all(np.all(f == 0) for f in uniform.fictitious_forces(1.0, r, v).values())

# %%
# A ball thrown on the turntable (eqs. 2.25–2.28)
# -----------------------------------------------
#
# ``simulate_particle`` integrates a ball thrown upwards at 3 m/s from the bead's place, in the
# turntable's frame, with gravity and every fictitious force. Carried back to the fixed frame
# (``to_fixed``), its path must be the plain parabola of the fixed frame; the printed difference
# is at the integrator's tolerance.

g = np.array([0.0, 0.0, -9.81])
traj = ps.simulate_particle(
    frame,
    [0.4, 0.0, 0.0],
    [0.0, 0.0, 3.0],
    0.5,
    samples=6,
    force=lambda t, r_, v_: frame.at(t).attitude.T @ g,
    rtol=1e-12,
    atol=1e-12,
)
pos, vel = traj.to_fixed()
start = frame.to_fixed([0.4, 0.0, 0.0], [0.0, 0.0, 3.0])
parabola = start.position + np.outer(traj.t, start.velocity) + 0.5 * np.outer(traj.t**2, g)
print(
    f"ball on the turntable: largest difference from the fixed-frame parabola "
    f"{np.max(np.abs(pos - parabola)):.2e} m"
)
assert np.max(np.abs(pos - parabola)) < 1e-10

# %%
# The pictures (the unit's Figs. 2.2 and 2.3)
# -------------------------------------------
#
# The pictures draw the turntable without its lift (a frame that only turns, as in the unit's
# figures; R̈ adds the same 2 m/s² upwards everywhere). First, the turntable's axes at t = 0.8 s,
# turned through ω t + ½ ω̇ t² = 72.4° from the fixed axes, with the bead's place P held in
# them and its velocity ω × r seen from the fixed frame (eqs. 2.7, 2.12). Second, the circle a
# bead at rest on the turntable describes, and its centripetal acceleration ω × (ω × r) pointing
# to the axis, 0.9 m/s² = ω² r sin θ (2.24). The sliding bead's Coriolis term is left out: here
# it is the very same vector, 2ω × ṙ = (−0.9, 0, 0) m/s² in the table above, as the bead slides
# at half the speed ω r it is carried at.

import matplotlib

matplotlib.use("Agg")
from poinsot.plots import plot_centripetal, plot_rotating_frame

# sphinx_gallery_thumbnail_number = 2
turntable = ps.MovingFrame(
    angular_velocity=frame.angular_velocity, angular_acceleration=frame.angular_acceleration
)
plot_rotating_frame(turntable, r, t=0.8).savefig(
    out / "moving_frames_axes.png", dpi=110, bbox_inches="tight"
)
plot_centripetal(ps.MovingFrame(angular_velocity=frame.angular_velocity), r).savefig(
    out / "moving_frames_centripetal.png", dpi=110, bbox_inches="tight"
)
print("pictures written: moving_frames_axes.png, moving_frames_centripetal.png")
