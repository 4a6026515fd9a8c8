"""Moving frames
=============

Moving frames (the unit's eqs. 2.1–2.28): the acceleration of a particle seen from a turning,
accelerating frame, split into its named terms; the fictitious forces; and a particle integrated
in the moving frame that agrees with the same motion integrated in the fixed frame.
"""

from __future__ import annotations

import numpy as np
import poinsot as ps

# A turntable spinning up (ω̇ ∥ ω) on a lift accelerating upwards.
frame = ps.MovingFrame(
    acceleration=[0.0, 0.0, 2.0],
    angular_velocity=[0.0, 0.0, 1.5],
    angular_acceleration=[0.0, 0.0, 0.2],
)
r, v, a = np.array([0.4, 0.0, 0.0]), np.array([0.0, 0.3, 0.0]), np.zeros(3)

out = frame.to_fixed(r, v, a)
print("a bead at r = (0.4, 0, 0) m sliding at (0, 0.3, 0) m/s on the turntable:")
for name, term in out.acceleration_terms.items():
    print(f"  {name:12s} {np.array2string(term, precision=4, suppress_small=True)} m/s²")
print(
    f"  {'total':12s} {np.array2string(out.acceleration, precision=4, suppress_small=True)} m/s²  (eq. 2.21)"
)
assert np.allclose(sum(out.acceleration_terms.values()), out.acceleration)

# Going back: the fixed-frame motion seen from the turntable.
back = frame.to_moving(out.position, out.velocity, out.acceleration)
assert (
    np.allclose(back.position, r)
    and np.allclose(back.velocity, v)
    and np.allclose(back.acceleration, a)
)

forces = frame.fictitious_forces(0.05, r, v)  # a 50 g bead
print("fictitious forces on a 50 g bead (eqs. 2.5, 2.26–2.28):")
for name, f in forces.items():
    print(f"  {name:13s} {np.array2string(f + 0.0, precision=5, suppress_small=True)} N")

# Galilean invariance (2.5 with R̈ = 0): a uniformly moving frame has no fictitious force.
uniform = ps.MovingFrame(velocity=[30.0, 0.0, 0.0])
assert all(np.all(f == 0) for f in uniform.fictitious_forces(1.0, r, v).values())

# A ball thrown on the spinning, lifting turntable, integrated in the turntable's frame with every
# fictitious force, against the parabola of the fixed frame transformed into the turntable.
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
