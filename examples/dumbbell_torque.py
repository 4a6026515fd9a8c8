"""The dumbbell and the torque that keeps it turning
=================================================

The unit's two-particle example (eqs. 2.58–2.59): a dumbbell turning about an axis that is not
along its rod has an angular momentum L that is not parallel to ω; L turns with the body and
traces a cone, so a torque N = dL/dt = ω × L must act to keep ω constant.

Run: python examples/dumbbell_torque.py [out-folder]   (prints; writes dumbbell.png into out/,
or the folder given as the first argument)
"""

# %%
# The dumbbell
# ------------
#
# Two 1 kg masses 0.5 m either side of the centre on a massless rod tilted α = 30° from the z
# axis, turned at ω = 2 rad/s about z. :meth:`poinsot.RigidBody.from_point_masses` makes the
# body; its inertia tensor about the centre holds the sums of eqs. 2.46–2.50.

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import poinsot as ps

out = Path(sys.argv[1] if len(sys.argv) > 1 else "out")
out.mkdir(parents=True, exist_ok=True)

m1 = m2 = 1.0  # kg
half = 0.5  # m, each mass at this distance from the centre
alpha = np.radians(30.0)  # angle between the rod and the rotation axis z
omega = 2.0  # rad/s

rod = np.array([np.sin(alpha), 0.0, np.cos(alpha)])
positions = np.array([half * rod, -half * rod])
body = ps.RigidBody.from_point_masses([m1, m2], positions)
w = np.array([0.0, 0.0, omega])

# %%
# L is not parallel to ω, and a torque must act (eqs. 2.58–2.59)
# ----------------------------------------------------------------
#
# The angular momentum L = I·ω (2.63) equals the particles' own sum Σ m r × (ω × r) (2.58): the
# two printed vectors agree. Look at L · rod: it is zero, so L is perpendicular to the rod and
# leans 90° − α = 60° away from ω. As the body turns, L turns with it; keeping ω fixed takes the
# torque N = dL/dt = ω × L (2.59), of magnitude 2 m a² ω² sin α cos α.

L = body.angular_momentum(w)  # L = I·ω (2.63) = Σ m r × v (2.58)
direct = sum(m * np.cross(r, np.cross(w, r)) for m, r in zip([m1, m2], positions))
N = body.holding_torque(w)  # ω × L

print(
    f"two {m1} kg masses at ±{half} m on a massless rod tilted {np.degrees(alpha):.0f}° from z, ω = {omega} rad/s about z"
)
print(f"  kind of body:           {body.kind} (principal moments {body.principal_moments} kg·m²)")
print(f"  L = I·ω                 {L} kg·m²/s")
print(f"  Σ m r × (ω × r) (2.58)  {direct} kg·m²/s")
print(f"  L · rod = {L @ rod:.2e}: L is perpendicular to the rod, not parallel to ω")
print(f"  angle between L and ω:  {body.momentum_angle(w, degrees=True):.4f}° (= 90° − α)")
print(f"  T = ½ ω·L (2.53)        {body.kinetic_energy(w):.6f} J")
print(f"  torque N = ω × L (2.59) {N} N·m, |N| = {np.linalg.norm(N):.6f} N·m")
print(
    f"  closed form 2 m a² ω² sin α cos α = {2 * m1 * half**2 * omega**2 * np.sin(alpha) * np.cos(alpha):.6f} N·m"
)


# %%
# An independent check: L(t) differentiated
# -----------------------------------------
#
# Carry the two particles round the z axis, recompute L from them at each time and
# differentiate by central differences: the result is ω × L. Then L over half a turn: its angle
# to z stays 60°, so its tip goes round a cone about ω — the unit's Fig. 2.9. A rotation about
# a principal axis instead needs no torque at all.


# Independent check: L(t) of the particles carried round by the rotation, differentiated.
def L_at(t: float) -> np.ndarray:
    c, s = np.cos(omega * t), np.sin(omega * t)
    Rz = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    return sum(m * np.cross(Rz @ r, np.cross(w, Rz @ r)) for m, r in zip([m1, m2], positions))


dt = 1e-5
dLdt = (L_at(dt) - L_at(-dt)) / (2 * dt)
print(f"  dL/dt by finite differences of the turning particles: {dLdt} N·m")
assert np.allclose(dLdt, N, rtol=1e-8, atol=1e-9)
print("\nL traces a cone about z with vertex at the centre (the unit's fig. 2.9):")
for t in np.linspace(0.0, np.pi / omega, 5):
    Lt = L_at(t)
    print(
        f"  t = {t:5.3f} s  L = {np.array2string(Lt, precision=4, suppress_small=True)}  "
        f"angle to z = {np.degrees(np.arccos(Lt[2] / np.linalg.norm(Lt))):.2f}°"
    )
axis = body.principal_axes[:, 2]
print(
    f"\nturning about a principal axis instead ({np.array2string(axis, precision=4)}) needs no torque: "
    f"N = {np.array2string(body.holding_torque(omega * axis), precision=3, suppress_small=True)} N·m"
)

# %%
# The picture (the unit's Fig. 2.9)
# ---------------------------------
#
# The same masses, positions and ω drawn by :func:`poinsot.plots.plot_dumbbell`: the rod through
# O, ω along z, L perpendicular to the rod, the cone L sweeps in one revolution, and the torque
# N = ω × L, perpendicular to both ω and L.

import matplotlib

matplotlib.use("Agg")
from poinsot.plots import plot_dumbbell

plot_dumbbell([m1, m2], positions, w).savefig(out / "dumbbell.png", dpi=110, bbox_inches="tight")
print("picture written: dumbbell.png")
