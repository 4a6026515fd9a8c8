"""Euler angles
============

Euler angles, the unit's way (section "Euler's Angles", eqs. 2.98-2.101).

The unit turns the fixed axes XYZ into the body axes 123 in three steps: phi about Z (the X axis
becomes the line of nodes xi), theta about the line of nodes, psi about body axis 3. That is the
intrinsic z-x-z sequence, poinsot's default:

    R = R_z(phi) @ R_x(theta) @ R_z(psi)        (body components -> space components)

Run: .venv/bin/python examples/euler_angles.py
"""

from __future__ import annotations

import warnings

import numpy as np
import poinsot

np.set_printoptions(precision=4, suppress=True)

# ---- the attitude of a top: precession phi, nutation theta, spin psi -----------------------
phi, theta, psi = np.radians([30.0, 20.0, 45.0])
R = poinsot.euler_to_matrix([phi, theta, psi])
print("R = R_z(30°) R_x(20°) R_z(45°):\n", R)
print("body axis 3 in space (the top's figure axis):", R[:, 2])
print("  its angle from Z is theta:", np.degrees(np.arccos(R[2, 2])).round(6), "deg")
print("angles back:", poinsot.matrix_to_euler(R, degrees=True), "deg")

# The same attitude in other conventions (always lowercase + an explicit intrinsic flag).
for seq, intrinsic in [("zyz", True), ("xyz", True), ("xyz", False), ("zyx", True)]:
    a = poinsot.matrix_to_euler(R, seq, intrinsic=intrinsic, degrees=True)
    kind = "intrinsic" if intrinsic else "extrinsic"
    same = np.allclose(poinsot.euler_to_matrix(a, seq, intrinsic=intrinsic, degrees=True), R)
    print(f"  {kind} {seq}: {a} deg  (rebuilds R: {same})")

# ---- angular velocity from the angle rates: the unit's eq. 2.99 ----------------------------
rates = np.array([0.5, 0.0, 20.0])  # phi_dot (precession), theta_dot, psi_dot (spin), rad/s
w_body = poinsot.body_angular_velocity([phi, theta, psi], rates)
w_space = poinsot.space_angular_velocity([phi, theta, psi], rates)
print("\nsteady precession 0.5 rad/s, spin 20 rad/s, no nutation:")
print("  omega in body axes 1,2,3 (eq. 2.99):", w_body, "rad/s")
print("  omega in space axes X,Y,Z:          ", w_space, "rad/s")
print("  omega_3 = psi_dot + phi_dot cos(theta) =", rates[2] + rates[0] * np.cos(theta))
print("  rates back from omega:", poinsot.euler_rates([phi, theta, psi], w_body))

# Kinetic energy of a symmetric top (2.100 -> 2.101): T depends on theta only.
I1, I3 = 2.0e-4, 1.0e-4  # kg m^2
T_200 = 0.5 * (I1 * w_body[0] ** 2 + I1 * w_body[1] ** 2 + I3 * w_body[2] ** 2)
T_201 = (
    0.5 * I1 * (rates[1] ** 2 + rates[0] ** 2 * np.sin(theta) ** 2)
    + 0.5 * I3 * (rates[2] + rates[0] * np.cos(theta)) ** 2
)
print(f"  T from 2.100: {T_200:.6e} J, from 2.101: {T_201:.6e} J")

# ---- gimbal lock ---------------------------------------------------------------------------
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
