"""The torque-free symmetric top
=============================

The free symmetric top of the unit (eqs. 2.77–2.97), and the asymmetric top beside it.

A prolate and an oblate top: Ω, A, the body and space cones, ω₃² and A² from T and L, checked
against an integration of Euler's equations; then the asymmetric top I = (1, 2, 3) solved
exactly and by the geometric integrators. Writes free_omega.png, free_cones.png,
free_polhodes.png and free_conservation.png into out/ (or the folder given as the argument).
"""

# %%
# A prolate and an oblate top (eqs. 2.77–2.97)
# --------------------------------------------
#
# :class:`poinsot.FreeSymmetricTop` gives the free symmetric top in closed form. For each top
# (I₁ = 2, I₃ = 1 kg m²: prolate; I₁ = 1, I₃ = 1.8: oblate), started with ω = (0.6, 0, 1)
# rad/s: ω precesses about the symmetry axis at the rate Ω (2.83) with amplitude A (2.88),
# tracing the body cone of half-angle α_b (2.90), which rolls on the space cone α_s
# (2.97) — outside it for the prolate top, inside for the oblate one. Look at the sign of Ω and
# at "rolls". Each is checked against an integration of Euler's equations, and ω₃² and A² are
# recovered from the energy and the size of L alone (2.95–2.96).

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import poinsot as ps

out = Path(sys.argv[1] if len(sys.argv) > 1 else "out")
out.mkdir(parents=True, exist_ok=True)

for i1, i3 in ((2.0, 1.0), (1.0, 1.8)):
    top = ps.FreeSymmetricTop(i1, i3, [0.6, 0.0, 1.0])
    tr = ps.simulate(
        [i1, i1, i3], [0.6, 0.0, 1.0], 20.0, method="dop853", rtol=1e-12, atol=1e-14, samples=201
    )
    err = np.abs(tr.omega - top.omega(tr.t)).max()
    print(
        f"{top.shape} top I₁ = {i1}, I₃ = {i3}: Ω = {top.precession_rate:+.6f} rad/s (2.83), A = {top.amplitude:.6f} "
        f"(2.88), α_b = {np.degrees(top.body_cone_angle):.4f}° (2.90), α_s = {np.degrees(top.space_cone_angle):.4f}° "
        f"(2.97), body cone rolls {top.cone_contact}; |ω_closed − ω_integrated| = {err:.1e}"
    )
    assert err < 1e-9
    l_mag = top.angular_momentum_magnitude
    assert (
        abs(ps.FreeSymmetricTop.omega3_squared_from(i1, i3, top.energy, l_mag) - 1.0) < 1e-12
    )  # 2.95
    assert (
        abs(ps.FreeSymmetricTop.amplitude_squared_from(i1, i3, top.energy, l_mag) - 0.36) < 1e-12
    )  # 2.96

# %%
# The asymmetric top, exactly and by three integrators
# ----------------------------------------------------
#
# I = (1, 2, 3) kg m² with ω₀ = (1, 0.1, 1) rad/s: :class:`poinsot.FreeRigidBody` solves it with
# Jacobi elliptic functions. Then 1000 s by three integrators with the same step 0.01 s,
# against it. Look at the columns: the two splitting methods keep the size of L to rounding
# (each of their sub-steps turns L without changing its length); the sixth-order one also
# keeps the energy and ends within 1e-10 of the exact ω; the second-order one drifts most in
# ω, RK4 lies in between.

body = ps.FreeRigidBody([1.0, 2.0, 3.0], [1.0, 0.1, 1.0])
print(
    f"\nasymmetric top I = (1, 2, 3), ω₀ = (1, 0.1, 1): {body.regime}, m = {body.parameter:.6f}, "
    f"period of ω = {body.period:.6f} s"
)
runs = []
for method, dt in (("splitting2", 0.01), ("splitting6", 0.01), ("rk4", 0.01)):
    tr = ps.simulate([1.0, 2.0, 3.0], [1.0, 0.1, 1.0], 1000.0, method=method, dt=dt, samples=401)
    runs.append(tr)
    dw = np.linalg.norm(tr.omega[-1] - body.omega(1000.0))
    print(
        f"  {method:10s} dt = {dt}: |Δω(1000)| = {dw:.1e}, max |ΔE/E| = {tr.energy_error().max():.1e}, "
        f"max |Δ|L|/|L|| = {tr.momentum_error().max():.1e}"
    )

# %%
# The pictures
# ------------
#
# First, ω(t) of the asymmetric top: an RK4 run beside the exact solution (dashed). Second,
# the body cone rolling on the outside of the space cone for a prolate top (the unit's
# Fig. 2.11). Third, the polhodes of a body with the same moments: the paths of ω on its
# energy ellipsoid, circling the largest and smallest axes and parted by the separatrix
# through the intermediate one. Last, the errors in the energy and in the size of L of the
# three integrators over the 1000 s run.

import matplotlib

matplotlib.use("Agg")
from poinsot.plots.free import plot_cones, plot_conservation, plot_omega, plot_polhodes

short = ps.simulate([1.0, 2.0, 3.0], [1.0, 0.1, 1.0], 20.0, method="rk4", dt=0.05, samples=81)
plot_omega(short, body).savefig(out / "free_omega.png", dpi=110, bbox_inches="tight")
plot_cones(ps.FreeSymmetricTop(2.0, 1.0, [0.8, 0.0, 1.0]), 0.5).savefig(
    out / "free_cones.png", dpi=110
)
plot_polhodes().savefig(out / "free_polhodes.png", dpi=110)
plot_conservation(runs).savefig(out / "free_conservation.png", dpi=110, bbox_inches="tight")
print("pictures written: free_omega.png, free_cones.png, free_polhodes.png, free_conservation.png")
