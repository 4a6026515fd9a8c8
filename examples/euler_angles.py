"""Euler angles
============

Euler angles, the unit's way (section "Euler's Angles", eqs. 2.98-2.101).

The unit turns the fixed axes XYZ into the body axes 123 in three steps: phi about Z (the X axis
becomes the line of nodes xi), theta about the line of nodes, psi about body axis 3. That is the
intrinsic z-x-z sequence, poinsot's default:

    R = R_z(phi) @ R_x(theta) @ R_z(psi)        (body components -> space components)

Run: python examples/euler_angles.py [out-folder]   (prints; writes euler_angle_steps.png and
euler_omega_components.png into out/, or the folder given as the first argument)
"""

# %%
# The attitude of a top from its three angles
# -------------------------------------------
#
# A top precessed by φ = 30°, nodding at θ = 20° from the vertical and spun round by ψ = 45°.
# :func:`poinsot.euler_to_matrix` builds R, whose columns are the body axes in space
# components: the third column is the top's figure axis, and its angle from Z is θ.
# :func:`poinsot.matrix_to_euler` gives the angles back.

from __future__ import annotations

import sys
import warnings
from pathlib import Path

import numpy as np
import poinsot

out = Path(sys.argv[1] if len(sys.argv) > 1 else "out")
out.mkdir(parents=True, exist_ok=True)
np.set_printoptions(precision=4, suppress=True)

phi, theta, psi = np.radians([30.0, 20.0, 45.0])
R = poinsot.euler_to_matrix([phi, theta, psi])
print("R = R_z(30°) R_x(20°) R_z(45°):\n", R)
print("body axis 3 in space (the top's figure axis):", R[:, 2])
print("  its angle from Z is theta:", np.degrees(np.arccos(R[2, 2])).round(6), "deg")
print("angles back:", poinsot.matrix_to_euler(R, degrees=True), "deg")

# %%
# The same attitude in other conventions
# --------------------------------------
#
# Other books use other sequences: z-y-z, x-y-z or the aircraft's z-y-x, intrinsic (about the
# turned axes) or extrinsic (about the fixed ones). The same R has different angles in each
# (always a lowercase sequence and an explicit ``intrinsic`` flag); each set rebuilds R.

for seq, intrinsic in [("zyz", True), ("xyz", True), ("xyz", False), ("zyx", True)]:
    a = poinsot.matrix_to_euler(R, seq, intrinsic=intrinsic, degrees=True)
    kind = "intrinsic" if intrinsic else "extrinsic"
    same = np.allclose(poinsot.euler_to_matrix(a, seq, intrinsic=intrinsic, degrees=True), R)
    print(f"  {kind} {seq}: {a} deg  (rebuilds R: {same})")

# %%
# The angular velocity from the angles' rates (eqs. 2.98–2.99)
# -------------------------------------------------------------
#
# A top in steady precession: φ̇ = 0.5 rad/s, no nutation (θ̇ = 0), spin ψ̇ = 20 rad/s. The
# angular velocity is the sum of the three rates along their own axes (Z, the line of nodes,
# the figure axis); eq. 2.99 gives its body components. Look at ω₃ = ψ̇ + φ̇ cos θ: the spin
# along the figure axis is not ψ̇ alone. :func:`poinsot.euler_rates` inverts eq. 2.99.

rates = np.array([0.5, 0.0, 20.0])  # phi_dot (precession), theta_dot, psi_dot (spin), rad/s
w_body = poinsot.body_angular_velocity([phi, theta, psi], rates)
w_space = poinsot.space_angular_velocity([phi, theta, psi], rates)
print("\nsteady precession 0.5 rad/s, spin 20 rad/s, no nutation:")
print("  omega in body axes 1,2,3 (eq. 2.99):", w_body, "rad/s")
print("  omega in space axes X,Y,Z:          ", w_space, "rad/s")
print("  omega_3 = psi_dot + phi_dot cos(theta) =", rates[2] + rates[0] * np.cos(theta))
print("  rates back from omega:", poinsot.euler_rates([phi, theta, psi], w_body))

# %%
# The kinetic energy of a symmetric top (eqs. 2.100–2.101)
# --------------------------------------------------------
#
# With I₁ = I₂, T = ½ (I₁ ω₁² + I₁ ω₂² + I₃ ω₃²) (2.100) becomes a function of θ and the rates
# alone, without φ and ψ (2.101) — the reason the heavy top has two conserved momenta. The two
# printed values agree.

I1, I3 = 2.0e-4, 1.0e-4  # kg m^2
T_200 = 0.5 * (I1 * w_body[0] ** 2 + I1 * w_body[1] ** 2 + I3 * w_body[2] ** 2)
T_201 = (
    0.5 * I1 * (rates[1] ** 2 + rates[0] ** 2 * np.sin(theta) ** 2)
    + 0.5 * I3 * (rates[2] + rates[0] * np.cos(theta)) ** 2
)
print(f"  T from 2.100: {T_200:.6e} J, from 2.101: {T_201:.6e} J")

# %%
# Gimbal lock
# -----------
#
# At θ = 0 the first and the last rotation are about the same axis, and only φ + ψ is defined:
# ``matrix_to_euler`` picks one split and warns, and ``euler_rates`` refuses with
# :class:`poinsot.GimbalLockError`, since the rates cannot be recovered from ω there.

print("\ngimbal lock: at theta = 0 only phi + psi is defined")
R0 = poinsot.euler_to_matrix([40.0, 0.0, 25.0], degrees=True)
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    a0 = poinsot.matrix_to_euler(R0, degrees=True)
print("  matrix_to_euler ->", a0, "deg;", caught[0].category.__name__)
try:
    poinsot.euler_rates([0.7, 0.0, 0.4], [0.0, 0.0, 1.0])
except poinsot.GimbalLockError as exc:
    print("  euler_rates raises GimbalLockError:", str(exc)[:90], "...")

# %%
# The pictures (the unit's Figs. 2.12 and 2.13)
# ---------------------------------------------
#
# First, the three steps that turn the fixed axes XYZ into the top's body axes, with this
# example's angles: (a) φ = 30° about Z takes X to the line of nodes ξ, (b) θ = 20° about ξ
# tilts Z to ζ, (c) ψ = 45° about ζ brings ξ to body axis 1, (d) the body axes with all three
# angles. Second, ω of the steady precession above built head to tail from φ̇ along Z, θ̇ along
# ξ and ψ̇ along ζ, with its components along ξ, η, ζ (eq. 2.98). The spin is 40 times the
# precession, so ω lies almost along the figure axis: that is what a fast top is.

import matplotlib

matplotlib.use("Agg")
from poinsot.plots import plot_euler_angle_steps, plot_omega_components

plot_euler_angle_steps([phi, theta, psi], degrees=False).savefig(
    out / "euler_angle_steps.png", dpi=110, bbox_inches="tight"
)
plot_omega_components([phi, theta, psi], rates, degrees=False).savefig(
    out / "euler_omega_components.png", dpi=110, bbox_inches="tight"
)
print("pictures written: euler_angle_steps.png, euler_omega_components.png")
