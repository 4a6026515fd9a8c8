"""The Dzhanibekov flip-time map
==============================

How long does a body spun near its intermediate axis wait before it flips? The answer depends on
the direction of ω₀ in the body, and steeply so near the separatrix. This example maps it: one
call of :func:`poinsot.sweep.free_body` solves 130,321 bodies, exactly (Jacobi elliptic
functions), and colours each direction of ω₀ by the flip interval — the time between reversals
of the intermediate component ω₂, half the period of ω. The periods are checked against an
independent closed form and an RK4 integration.

Writes dzhanibekov_flip_map.png into out/ (or the folder given as first argument).
"""

# %%
# One sweep over the directions of ω₀
# -----------------------------------
#
# Moments 1, 2, 3 kg m², ω₀ of size 1 rad/s, its direction over 361 × 361 polar angles from
# axis 3 and azimuths from axis 1: :func:`poinsot.sweep.free_body` returns an xarray Dataset
# with each body's regime, period and flip interval. The counts say about which axis ω goes
# round (``about max axis``, ``about min axis``) and how many bodies start on a principal axis
# (``steady``).

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np
import poinsot as ps
from scipy.special import ellipkm1

out = Path(sys.argv[1] if len(sys.argv) > 1 else "out")
out.mkdir(parents=True, exist_ok=True)

I = np.array([1.0, 2.0, 3.0])  # principal moments, kg m²
W = 1.0  # |ω₀|, rad/s
polar = np.linspace(0.0, 180.0, 361)  # degrees from body axis 3
azimuth = np.linspace(0.0, 180.0, 361)  # degrees from body axis 1 towards axis 2

start = time.perf_counter()
ds = ps.sweep.free_body(
    moments=I, omega_magnitude=W, omega_polar=polar, omega_azimuth=azimuth, degrees=True
)
elapsed = time.perf_counter() - start
print(f"{ds.regime.size:,} free bodies (direction of ω₀) swept in {elapsed:.2f} s")
regimes, counts = np.unique(ds.regime.values, return_counts=True)
print("  " + ", ".join(f"{r}: {n:,}" for r, n in zip(regimes, counts)))

# %%
# The period in closed form (Landau & Lifshitz §37)
# -------------------------------------------------
#
# The period of ω is 4 K(m) / ω_p, with ω_p² = (I₃ − I₂)(L² − 2 T I₁) / (I₁ I₂ I₃) and
# 1 − m = (I₃ − I₁)(L² − 2 T I₂) / ((I₃ − I₂)(L² − 2 T I₁)) where L² > 2 T I₂ (I₁ and I₃
# swapped otherwise), from the energy T and the angular momentum L of ω₀ alone. It is evaluated
# here with scipy's ``ellipkm1``, an implementation independent of the core's Carlson forms.
# Look at the median relative difference (about 1e-16) and at the worst one in units of the
# closed form's own rounding near the separatrix, ``1e-15 × (1 + L²/|L² − 2 T I₂|)``: below
# one. On a principal axis nothing flips (no period), and at the intermediate axis itself the
# closed form in doubles loses what the core keeps.

# The closed-form period at every direction, from T and L of ω₀ alone.
w = ds.omega0.values  # (polar, azimuth, 3), rad/s
T2 = (I * w**2).sum(axis=-1)  # 2 T, J
L2 = ((I * w) ** 2).sum(axis=-1)  # L², (kg m²/s)²
I1, I2, I3 = I
gap = L2 - T2 * I2  # L² − 2 T I₂: its sign picks the axis ω circles, 0 on the separatrix
big = gap > 0
with np.errstate(divide="ignore", invalid="ignore"):
    wp = np.where(
        big,
        np.sqrt((I3 - I2) * (L2 - T2 * I1) / (I1 * I2 * I3)),
        np.sqrt((I2 - I1) * (T2 * I3 - L2) / (I1 * I2 * I3)),
    )
    m1 = np.where(
        big,
        (I3 - I1) * gap / ((I3 - I2) * (L2 - T2 * I1)),
        (I3 - I1) * -gap / ((I2 - I1) * (T2 * I3 - L2)),
    )
    closed = 4.0 * ellipkm1(m1) / wp
period = ds.period.values
both = np.isfinite(period) & np.isfinite(closed)
assert np.array_equal(ds.flip_interval.values[both], period[both] / 2)
rel = np.abs(period[both] - closed[both]) / closed[both]
# Near the separatrix L² − 2 T I₂ is a difference of nearly equal numbers: the closed form's own
# rounding grows as L² / |L² − 2 T I₂|, and the comparison allows for it (and for nothing else).
cond = 1.0 + L2[both] / np.abs(gap[both])
print(
    f"  period vs 4 K(m)/ω_p (scipy): median relative difference {np.median(rel):.1e},"
    f" worst {rel[cond < 10].max():.1e} where L²/|L² − 2 T I₂| < 9; worst over"
    f" 1e-15 × (1 + L²/|L² − 2 T I₂|) anywhere: {np.max(rel / cond) / 1e-15:.2f}"
)
assert np.max(rel / cond) < 4e-15
steady = ds.regime.values == "steady"
assert np.array_equal(~np.isfinite(period), steady)  # spun about a principal axis: no flips
print(f"  {np.count_nonzero(steady)} directions on a principal axis: steady, no flips")
# At the intermediate axis itself cos 90° rounds to 6e-17: ω₀ = (6e-17, 1, 6e-17) rad/s. The core
# finds that wobble's long period; the closed form in doubles cannot (L² − 2 T I₂ rounds to 0).
lost = np.isfinite(period) & ~np.isfinite(closed)
at = ds.omega0.values[lost]
assert lost.sum() == 1 and np.allclose(at, [0.0, 1.0, 0.0], atol=1e-16)
print(
    f"  at the intermediate axis, ω₀ = {at[0].tolist()} rad/s: period {period[lost][0]:.1f} s"
    " (the closed form in doubles: L² − 2 T I₂ rounds to 0)"
)

# %%
# The flip interval goes as one over the spin
# -------------------------------------------
#
# Euler's equations are unchanged when ω and 1/t are scaled together, so a body spun twice as
# fast flips twice as often. A coarser sweep over three sizes of ω₀ checks that flip interval
# × ``|ω₀|`` is the same at every direction.

sizes = ps.sweep.free_body(
    moments=I,
    omega_magnitude=[0.5, 1.0, 4.0],
    omega_polar=polar[::6],
    omega_azimuth=azimuth[::6],
    degrees=True,
    quantities=["flip_interval"],
)
scaled = sizes.flip_interval * sizes.omega_magnitude
finite = np.isfinite(scaled.values[0])
spread = np.ptp(scaled.values[:, finite], axis=0) / scaled.values[1, finite]
assert spread.max() < 1e-13
print(f"  flip interval × |ω₀| the same at |ω₀| = 0.5, 1, 4 rad/s: worst spread {spread.max():.1e}")

# %%
# An independent count of flips: RK4
# -----------------------------------
#
# Along the meridian at azimuth 60°, six bodies are integrated by RK4 (:func:`poinsot.simulate`,
# dt = 1 ms) over six flips, and the times between ω₂'s zero crossings are measured. The
# exact and the integrated intervals agree to better than 1e-4, on both sides of the
# separatrix.

cut = 60.0  # azimuth, degrees
line = ds.sel(omega_azimuth=cut)
sep = np.degrees(np.arctan(np.sqrt(I3 * (I3 - I2) / (I1 * (I2 - I1))) / np.cos(np.radians(cut))))
checks = []
for th in (20.0, 60.0, 70.0, 85.0, 100.0, 130.0):
    w0 = line.omega0.sel(omega_polar=th).values
    flip = float(line.flip_interval.sel(omega_polar=th))
    run = ps.simulate(I, w0, 6.2 * flip, method="rk4", dt=1e-3, samples=6001)
    w2 = run.omega[:, 1]
    k = np.nonzero(np.sign(w2[1:]) != np.sign(w2[:-1]))[0]
    crossings = run.t[k] - w2[k] * (run.t[k + 1] - run.t[k]) / (w2[k + 1] - w2[k])
    measured = float(np.mean(np.diff(crossings)))
    checks.append((th, flip, measured))
    assert abs(measured - flip) < 1e-4 * flip, (th, measured, flip)
print(
    f"  RK4 flips along azimuth {cut:g}° (separatrix at {sep:.1f}° and {180 - sep:.1f}°):"
    + "".join(f"\n    polar {th:5.1f}°: exact {f:8.5f} s, RK4 {m:8.5f} s" for th, f, m in checks)
)

# %%
# The map
# -------
#
# Drawn on it in closed form: the separatrix, the directions with 2 T I₂ = L², i.e.
# I₁ (I₂ − I₁) ω₁² = I₃ (I₃ − I₂) ω₃² — here tan²θ cos²φ = 3 — where the flip interval grows
# without bound. It divides the directions whose ω circles the largest axis from those that
# circle the smallest, and crosses itself at the intermediate axis (the star): spun near it,
# a body waits longer and longer before its first flip. The right panel is the dotted meridian:
# the closed form, the sweep and the RK4 flips on one curve, rising steeply at the separatrix.

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.colors import LogNorm

fig, (ax, ax2) = plt.subplots(
    1, 2, figsize=(12, 5), constrained_layout=True, gridspec_kw={"width_ratios": [1.15, 1]}
)
img = ax.pcolormesh(
    azimuth,
    polar,
    ds.flip_interval.values,
    norm=LogNorm(vmin=3, vmax=60),
    cmap="magma",
    shading="nearest",
    rasterized=True,
)
bar = fig.colorbar(img, ax=ax, label="flip interval (s)")
bar.set_ticks([3, 4, 6, 10, 20, 40, 60], labels=["3", "4", "6", "10", "20", "40", "60"])
bar.minorticks_off()
phi = np.radians(np.linspace(0.0, 180.0, 721))
with np.errstate(divide="ignore"):
    theta_sep = np.degrees(
        np.arctan(np.sqrt(I3 * (I3 - I2) / (I1 * (I2 - I1))) / np.abs(np.cos(phi)))
    )
for branch in (theta_sep, 180.0 - theta_sep):
    ax.plot(np.degrees(phi), branch, color="#7fd3ff", lw=1.0, ls="--")
ax.plot([], [], color="#7fd3ff", lw=1.0, ls="--", label="separatrix, L² = 2 T I₂")
ax.plot(90, 90, marker="*", ms=12, color="w", mec="k", ls="none", label="intermediate axis (2)")
ax.plot(
    [0, 180],
    [90, 90],
    marker="o",
    ms=7,
    color="#9be39b",
    mec="k",
    ls="none",
    label="axis 1 (smallest)",
)
ax.axvline(cut, color="w", lw=0.8, ls=":")
ax.text(128, 12, "ω circles axis 3 (largest)", ha="center", color="w", fontsize=9)
ax.text(22, 97, "ω circles\naxis 1", ha="center", color="w", fontsize=9)
ax.set_xlabel("azimuth of ω₀ from axis 1 towards axis 2 (degrees)")
ax.set_ylabel("polar angle of ω₀ from axis 3 (degrees)")
ax.set_title(f"flip interval, I = (1, 2, 3) kg m², |ω₀| = {W:g} rad/s")
ax.legend(loc="upper right", fontsize=8, framealpha=0.85)

ax2.semilogy(
    polar,
    closed[:, list(azimuth).index(cut)] / 2,
    color="k",
    lw=1.5,
    label="closed form 2 K(m)/ω_p (scipy)",
)
ax2.semilogy(
    polar[::4],
    line.flip_interval.values[::4],
    "o",
    ms=3.5,
    color="#c2410c",
    label="poinsot.sweep.free_body",
)
ax2.semilogy(
    [c[0] for c in checks],
    [c[2] for c in checks],
    "x",
    ms=9,
    mew=2,
    color="#1d4ed8",
    label="RK4: ω₂'s zero crossings",
)
for s in (sep, 180 - sep):
    ax2.axvline(s, color="0.5", lw=0.8, ls="--")
ax2.text(
    sep - 1.5,
    0.04,
    "separatrix",
    rotation=90,
    ha="right",
    va="bottom",
    color="0.35",
    fontsize=8,
    transform=ax2.get_xaxis_transform(),
)
ax2.set_xlabel("polar angle of ω₀ from axis 3 (degrees)")
ax2.set_ylabel("flip interval (s)")
ax2.set_title(f"along azimuth {cut:g}° (dotted on the map)")
ax2.set_xlim(0, 180)
ax2.set_yticks([3, 4, 6, 10, 20, 40], ["3", "4", "6", "10", "20", "40"])
ax2.minorticks_off()
ax2.legend(loc="upper left", fontsize=8)
fig.savefig(out / "dzhanibekov_flip_map.png", dpi=110)
print("figure written: dzhanibekov_flip_map.png")
