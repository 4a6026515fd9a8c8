"""The heavy top's phase diagram
==============================

How a heavy symmetric top moves depends on how fast it spins and how far it leans. This example
sweeps both at once — 177 tilts × 240 spins, 42,480 tops in one call of
:func:`poinsot.sweep.heavy_top` — and colours the plane by the shape the axis traces
(:data:`poinsot.MOTION_CLASSES`), with the unit's closed-form curves drawn on it and checked
against the sweep.

Writes heavy_top_phase_diagram.png into out/ (or the folder given as first argument).
"""

# %%
# One sweep over tilt and spin
# ----------------------------
#
# Each top starts at rest in θ (θ̇₀ = 0) at tilt θ₀ with spin ω₃ and precession rate
# φ̇₀ = Ω = 2 rad/s (I₁ = 1 kg m², I₃ = 0.5 kg m², m g l = 1 N m). The sweep returns each top's
# motion class, turning points and whether it would sleep upright; the counts say how many
# tops wave, loop, or sit exactly on a boundary.

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np
import poinsot as ps

out = Path(sys.argv[1] if len(sys.argv) > 1 else "out")
out.mkdir(parents=True, exist_ok=True)

I1, I3, MGL, OMEGA = 1.0, 0.5, 1.0, 2.0  # kg m², kg m², N m, rad/s
tilt = np.radians(np.linspace(1.0, 89.0, 177))  # θ₀, rad (every half degree)
spin = np.linspace(0.05, 12.0, 240)  # ω₃, rad/s

start = time.perf_counter()
ds = ps.sweep.heavy_top(I1=I1, I3=I3, mgl=MGL, theta=tilt, omega3=spin, phi_dot=OMEGA)
elapsed = time.perf_counter() - start
print(f"{ds.motion_class.size:,} tops (θ₀ × ω₃) swept in {elapsed:.2f} s")
classes, counts = np.unique(ds.motion_class.values, return_counts=True)
print("  " + ", ".join(f"{c}: {n:,}" for c, n in zip(classes, counts)))

# %%
# The closed-form curves
# ----------------------
#
# None of these is computed by the sweep:
#
# * the steady-precession curve: the tops for which Ω is a root of the unit's quadratic 2.116,
#   m g l = Ω (I₃ ω₃ − I₁ Ω cos θ₀), i.e. ω₃ = (m g l + I₁ Ω² cos θ₀) / (I₃ Ω). Below it θ₀ is
#   the top's highest point and it waves below; above it θ₀ is the lowest point and the top
#   rises;
# * the minimum spin for steady precession at any rate, 2.118–2.119:
#   ω₃ ≥ (2 / I₃) (m g l I₁ cos θ₀)^½ — the envelope of the steady curves of all Ω; this one
#   touches it where Ω² = m g l / (I₁ cos θ₀) (θ₀ = 75.5°): left of there Ω is the fast root,
#   right of there the slow one;
# * its value at θ₀ → 0, the sleeping-top threshold 2 (m g l I₁)^½ / I₃ = 4 rad/s: an upright
#   top spinning faster stays asleep (``is_sleeping_stable``);
# * the tops whose axis passes through the vertical, p_φ = p_ψ, i.e.
#   ω₃ = I₁ Ω (1 + cos θ₀) / I₃: on it the rising axis reaches the vertical (θ₁ = 0); a faster
#   top turns back short of it with φ̇ reversed near its highest point — the axis loops.

# The closed-form curves, one value of ω₃ per tilt.
steady = (MGL + I1 * OMEGA**2 * np.cos(tilt)) / (I3 * OMEGA)  # Ω a root of 2.116
minimum = np.array([ps.HeavyTop.min_spin(I1, I3, MGL, th) for th in tilt])  # 2.119
sleeping = ps.HeavyTop.sleeping_threshold(I1, I3, MGL)
vertical = I1 * OMEGA * (1.0 + np.cos(tilt)) / I3  # p_φ = p_ψ
assert np.all(minimum <= steady + 1e-12), "2.119 is the least spin of any steady precession"
touch = tilt[np.argmin(steady - minimum)]
print(
    f"  the steady curve touches 2.119 at θ₀ = {np.degrees(touch):.1f}°"
    f" (Ω² = m g l/(I₁ cos θ₀): {np.degrees(np.arccos(MGL / (I1 * OMEGA**2))):.1f}°)"
)
assert abs(np.cos(touch) - MGL / (I1 * OMEGA**2)) < 0.01
assert np.isclose(sleeping, 2.0 * np.sqrt(MGL * I1) / I3) and np.isclose(
    minimum[0], sleeping, rtol=1e-3
)

# %%
# The sweep against the curves
# ----------------------------
#
# To the grid's resolution (one step of ω₃): per tilt, the spin of least nutation lies on the
# steady-precession curve, the first spin that loops lies on p_φ = p_ψ, every top that neither
# waves nor loops lies on one of the two, and ``is_sleeping_stable`` switches at the threshold.
# Look at the two "worst" numbers: both within one grid step.

step = spin[1] - spin[0]
amplitude = ds.turning_points.sel(turning_point="theta2") - ds.turning_points.sel(
    turning_point="theta1"
)
flattest = spin[np.argmin(amplitude.values, axis=1)]  # per tilt, the spin of least nutation
print(
    f"  least nutation per tilt vs the steady curve: worst {np.max(np.abs(flattest - steady)):.3f}"
    f" rad/s (grid step {step:.3f})"
)
assert np.all(np.abs(flattest - steady) <= step)
loops = ds.motion_class.values == "loops"
first_loop = spin[np.argmax(loops, axis=1)]  # per tilt, the least spin that loops
print(
    f"  first loop per tilt vs p_φ = p_ψ: worst {np.max(np.abs(first_loop - vertical)):.3f} rad/s"
)
near = np.abs(spin[None, :] - vertical[:, None]) <= step  # within a grid step of the curve
assert np.all((loops == (spin[None, :] > vertical[:, None])) | near), "loops exactly above it"
others = ~loops & (ds.motion_class.values != "waves")  # steady precession, through vertical
assert np.all(near[others] | (np.abs(spin[None, :] - steady[:, None]) <= step)[others])
asleep = ds.is_sleeping_stable.values
assert np.all(asleep == (spin > sleeping)[None, :])
print(f"  is_sleeping_stable switches at ω₃ = {sleeping:.4f} rad/s, the threshold 2(m g l I₁)^½/I₃")

# %%
# Released without precession: always cusps
# -----------------------------------------
#
# A second sweep over the same plane with φ̇₀ = 0: the axis starts at rest, at its highest
# point, so whatever the spin and tilt it traces cusps (the middle case of Goldstein's Fig. 5.9).

cusps = ps.sweep.heavy_top(
    I1=I1, I3=I3, mgl=MGL, theta=tilt, omega3=spin, quantities=["motion_class"]
)
assert np.all(cusps.motion_class.values == "cusps")
print(f"  released with φ̇₀ = 0: all {cusps.motion_class.size:,} tops trace cusps")

# %%
# The diagram
# -----------
#
# Left, the motion class over the plane (blue: waves, orange: loops) with the four curves.
# Right, the nutation's amplitude θ₂ − θ₁ from the same sweep: it vanishes on the
# steady-precession curve (dashed), where the top precesses without nodding.

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.colors import ListedColormap

shown = ["waves", "loops"]
code = np.where(ds.motion_class.values == "loops", 1.0, 0.0)
deg = np.degrees(tilt)
fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11.5, 4.8), constrained_layout=True)
ax.pcolormesh(
    deg,
    spin,
    code.T,
    cmap=ListedColormap(["#cfe3f3", "#f7d9b0"]),
    vmin=-0.5,
    vmax=1.5,
    shading="nearest",
    rasterized=True,
)
ax.plot(deg, steady, color="k", lw=2.2, label="steady precession at Ω (2.116)")
ax.plot(
    deg, minimum, color="#1f6fb4", ls="--", lw=1.8, label="least spin for steady precession (2.119)"
)
ax.plot(
    deg, vertical, color="#b45f06", ls="-.", lw=1.8, label="axis through the vertical, p_φ = p_ψ"
)
ax.axhline(
    sleeping, color="#8e1f1f", ls=":", lw=1.5, label=f"sleeping threshold {sleeping:g} rad/s"
)
ax.text(16, 10.4, "loops", ha="center", fontsize=13, color="#7a4300")
ax.text(30, 1.2, "waves", ha="center", fontsize=13, color="#0d4a7a")
ax.text(18, 6.2, "waves", ha="center", fontsize=13, color="#0d4a7a")
ax.set_xlabel("tilt θ₀ (degrees)")
ax.set_ylabel("spin ω₃ (rad/s)")
ax.set_title(f"motion class, φ̇₀ = Ω = {OMEGA:g} rad/s, θ̇₀ = 0")
ax.set_xlim(deg[0], deg[-1])
ax.set_ylim(spin[0], spin[-1])
ax.legend(loc="upper right", fontsize=8, framealpha=0.9)

img = ax2.pcolormesh(
    deg,
    spin,
    np.degrees(amplitude.values.T),
    norm=matplotlib.colors.LogNorm(vmin=0.05, vmax=90),
    cmap="viridis",
    shading="nearest",
    rasterized=True,
)
ax2.plot(deg, steady, color="w", lw=1.2, ls="--", label="steady precession (2.116)")
ax2.set_xlabel("tilt θ₀ (degrees)")
ax2.set_ylabel("spin ω₃ (rad/s)")
ax2.set_title("nutation amplitude θ₂ − θ₁ (degrees)")
ax2.legend(loc="upper right", fontsize=8)
fig.colorbar(img, ax=ax2, label="θ₂ − θ₁ (degrees)")
fig.suptitle(
    f"heavy top, I₁ = {I1:g}, I₃ = {I3:g} kg m², m g l = {MGL:g} N m: {ds.motion_class.size:,} tops in one sweep"
)
fig.savefig(out / "heavy_top_phase_diagram.png", dpi=110)
print("figure written: heavy_top_phase_diagram.png")
