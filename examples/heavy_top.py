"""The heavy symmetric top
=======================

The heavy symmetric top, exactly (the unit's "Motion of a Symmetrical Top", eqs. 2.102–2.114).

One top (I1 = 1 kg m², I3 = 0.5 kg m², m g l = 1 N m, spin about 6 rad/s, axis released at
0.8 rad from the vertical) started three ways: with a forward push in φ (waves), at rest in φ
(cusps), and with a backward push (loops) — Goldstein's Fig. 5.9 computed from the elliptic
solution the unit calls "very difficult". Prints the constants, the turning points where E' meets
V(θ), the nutation period and the mean precession; checks the exact angles against a direct
integration of the Lagrangian; writes the pictures (V(θ), the axis' locus, θ/φ̇/ψ̇ against time)
and an animation into out/ (or the folder given as the first argument).
"""

# %%
# One top, three starts: waves, cusps, loops (eqs. 2.102–2.112)
# -------------------------------------------------------------
#
# :class:`poinsot.HeavyTop` solves the top exactly from its initial state. Each start has its
# own conserved momenta p_ψ and p_φ (2.103–2.104) and reduced energy E′ (2.109); the axis nods
# between the turning points θ₁ and θ₂, where E′ meets the effective potential V(θ) (2.110),
# once every nutation period. Look at the class: a forward push in φ gives waves, none gives
# cusps, a backward push loops. Look also at the mean precession rate: forward in all three,
# about 0.35 rad/s — the push changes the shape of the path more than where the axis goes.

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import poinsot as ps
from scipy.integrate import solve_ivp

out = Path(sys.argv[1] if len(sys.argv) > 1 else "out")
out.mkdir(parents=True, exist_ok=True)

I1, I3, MGL, THETA0, OMEGA3 = 1.0, 0.5, 1.0, 0.8, 6.0
tops = {}
for phi_dot in (0.5, 0.0, -0.5):
    top = ps.HeavyTop(
        I1, I3, MGL, THETA0, phi_dot=phi_dot, psi_dot=OMEGA3 - phi_dot * np.cos(THETA0)
    )
    tops[top.motion_class] = top
    t1, t2 = top.turning_points
    print(
        f"phi'0 = {phi_dot:+.1f} rad/s: {top.motion_class:6s}  p_phi = {top.p_phi:.6f}, p_psi = {top.p_psi:.6f}, "
        f"E' = {top.reduced_energy:.6f} J; theta in [{t1:.6f}, {t2:.6f}] rad; "
        f"nutation period {top.nutation_period:.6f} s; mean phi' {top.mean_precession_rate:.6f} rad/s"
    )
    # E' = V(theta) at the turning points (2.109-2.110).
    assert max(abs(top.effective_potential(th) - top.reduced_energy) for th in (t1, t2)) < 1e-12
assert set(tops) == {"waves", "cusps", "loops"}

# %%
# The exact solution against a direct integration
# -----------------------------------------------
#
# The Euler–Lagrange equations of the Lagrangian 2.102, written out for θ, φ, ψ and integrated
# by scipy's DOP853 at a tolerance of 1e-12, against the exact angles of the looping top over
# three nutation periods: the largest difference is at the integrator's tolerance.

# The exact solution against the Euler-Lagrange equations of 2.102 integrated by scipy.
top = tops["loops"]


def lagrange(_t, y):
    th, _ph, _ps, thd, phd, psd = y
    s, c = np.sin(th), np.cos(th)
    w3 = psd + phd * c
    thdd = (I1 * phd**2 * s * c - I3 * w3 * phd * s + MGL * s) / I1
    phdd = thd * (I3 * w3 - 2 * I1 * phd * c) / (I1 * s)
    return [thd, phd, psd, thdd, phdd, -phdd * c + phd * thd * s]


s0 = top.initial_state
t = np.linspace(0.0, 3 * top.nutation_period, 50)
sol = solve_ivp(
    lagrange,
    (0, t[-1]),
    [s0["theta"], 0, 0, s0["theta_dot"], s0["phi_dot"], s0["psi_dot"]],
    method="DOP853",
    rtol=1e-12,
    atol=1e-12,
    t_eval=t,
)
phi, theta, psi = top.euler_angles(t)
err = max(
    np.max(np.abs(phi - sol.y[1])), np.max(np.abs(theta - sol.y[0])), np.max(np.abs(psi - sol.y[2]))
)
print(
    f"loops over three nutation periods: exact angles vs solve_ivp(DOP853, 1e-12): max difference {err:.1e} rad"
)
assert err < 1e-8

# %%
# The pictures
# ------------
#
# First, the path of the axis' tip on the unit sphere for the three starts, between the
# circles θ₁ and θ₂ (Goldstein's Fig. 5.9). Second, V(θ) of the cusped top with E′ and the
# turning points (the unit's Fig. 2.15). Third, θ, φ̇ and ψ̇ of the looping top against time:
# φ̇ changes sign at every loop. Last, the looping top animated.

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from poinsot.plots.top import animate_top, plot_angles, plot_axis_locus, plot_effective_potential

fig, axes = plt.subplots(1, 3, figsize=(15, 6), layout="constrained")  # labels kept apart
for ax, name in zip(axes, ("waves", "cusps", "loops")):
    plot_axis_locus(tops[name], ax)
fig.savefig(out / "heavy_top_loci.png", dpi=110, bbox_inches="tight")
plot_effective_potential(tops["cusps"]).savefig(
    out / "heavy_top_potential.png", dpi=110, bbox_inches="tight"
)
plot_angles(tops["loops"]).savefig(out / "heavy_top_angles.png", dpi=110, bbox_inches="tight")
animate_top(tops["loops"], out / "heavy_top.gif", frames=60, fps=15)
print(
    "pictures written: heavy_top_loci.png, heavy_top_potential.png, heavy_top_angles.png,"
    " heavy_top.gif"
)
