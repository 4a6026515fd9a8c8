"""The dumbbell and the torque that keeps it turning
=================================================

The unit's two-particle example (eqs. 2.58–2.59): a dumbbell turning about an axis that is not
along its rod has an angular momentum L that is not parallel to ω; L turns with the body and
traces a cone, so a torque N = dL/dt = ω × L must act to keep ω constant.

Run: python examples/dumbbell_torque.py   (prints; no display needed)
"""

from __future__ import annotations

import numpy as np
import poinsot as ps

m1 = m2 = 1.0  # kg
half = 0.5  # m, each mass at this distance from the centre
alpha = np.radians(30.0)  # angle between the rod and the rotation axis z
omega = 2.0  # rad/s

rod = np.array([np.sin(alpha), 0.0, np.cos(alpha)])
positions = np.array([half * rod, -half * rod])
body = ps.RigidBody.from_point_masses([m1, m2], positions)
w = np.array([0.0, 0.0, omega])

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
