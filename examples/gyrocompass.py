"""The gyrocompass: a maker's speed-error table and Schuler's 84.4 minutes
========================================================================

A gyrocompass is the unit's heavy symmetric top (2.98–2.121) carried by the turning Earth,
ω = Ω(0, cos λ, sin λ) (2.29): gravity torques its pendulous sensitive element whenever the
Earth's rotation tilts the spin axis, and the axis settles on the meridian.
:class:`poinsot.Gyrocompass` computes the settled direction on a moving ship and integrates the
compass as a rigid body in the moving frame. This example sets its speed error beside the
table a maker prints for the officer of the watch, and starts a Schuler-tuned compass 20° off
the meridian.

Writes gyrocompass.png into out/ (or the folder given as the first argument).
"""

# %%
# The speed-error table
# ---------------------
#
# C. Plath, *NAVIGAT X MK 1 Mod. 10 / SR 180 MK 1 Mod. 10 Digital Gyrocompass System*,
# Operator, Technical, Installation and Service Manual (Hamburg, 11 Aug 1998, Rev. A, Stock
# No. 056310), Appendix p. A-07, prints "the north speed error δ of an uncorrected gyrocompass
# in degrees" for latitudes up to 85° and speeds of 5 to 50 knots. Below are its rows for a
# ship heading due north (0°) at 81°, 82° and 84°, beside the settled direction
# :meth:`~poinsot.Gyrocompass.speed_error`, δ = atan(V cos C / (Ω R cos λ + V sin C)), and
# the small-angle form V cos C / (Ω R cos λ). The printed values are the arcsine form
# asin(V cos C / (Ω R cos λ)) with the equatorial radius: they match the exact direction at low
# speed and part from it by 1.2° at 50 knots at 81° (the catalogue's entries
# ``plath-1998-20-knots`` and ``plath-1998-50-knots``, :mod:`poinsot.experiments`).

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import poinsot as ps

out = Path(sys.argv[1] if len(sys.argv) > 1 else "out")
out.mkdir(parents=True, exist_ok=True)

KNOT = 1852.0 / 3600.0  # m/s
DEG = math.pi / 180.0
SPEEDS_KN = np.arange(5, 55, 5)
#: The maker's printed values (deg), heading 0°, speeds 5 … 50 kn (C. Plath 1998, p. A-07).
PRINTED = {
    81: [2.0, 4.1, 6.1, 8.1, 10.2, 12.2, 14.3, 16.4, 18.6, 20.7],
    82: [2.3, 4.6, 6.8, 9.1, 11.5, 13.8, 16.2, 18.5, 21.0, 23.4],
    84: [3.0, 6.1, 9.1, 12.2, 15.3, 18.5, 21.7, 25.0, 28.4, 31.9],
}

rows = {}
for lat, printed in PRINTED.items():
    c = ps.Gyrocompass(lat * DEG)
    exact = [c.speed_error(v * KNOT, 0.0) / DEG for v in SPEEDS_KN]
    small = [c.speed_error_small_angle(v * KNOT, 0.0) / DEG for v in SPEEDS_KN]
    rows[lat] = (np.array(printed), np.array(exact), np.array(small))
    print(f"{lat}° N, heading 000°   kn: " + " ".join(f"{v:5d}" for v in SPEEDS_KN))
    print("  printed (Plath 1998)     " + " ".join(f"{x:5.1f}" for x in printed))
    print("  speed_error (exact)      " + " ".join(f"{x:5.1f}" for x in exact))
    print("  small-angle V/(ΩR cos λ) " + " ".join(f"{x:5.1f}" for x in small))

printed81, exact81, small81 = rows[81]
print(
    f"At 81° and 50 kn the table prints {printed81[-1]:.1f}°, the settled compass is off by "
    f"{exact81[-1]:.2f}° (small-angle {small81[-1]:.2f}°): the table is "
    f"{printed81[-1] - exact81[-1]:.2f}° high."
)
assert abs(printed81[1] - exact81[1]) < 0.1 and 1.1 < printed81[-1] - exact81[-1] < 1.3

# %%
# Schuler's 84.4 minutes
# ----------------------
#
# A compass whose rotor momentum is H = P Ω cos λ R / g
# (:meth:`~poinsot.Gyrocompass.schuler_tuned`) swings about the meridian with the period of a
# pendulum as long as the Earth's radius, 2π √(R/g) = 84.4 min: then a ship's change of speed
# or course moves it straight to its new settled heading, without a swing. Started 20° east of
# north, the integrated rigid body (:meth:`~poinsot.Gyrocompass.simulate`, the full equations
# in the moving frame) spirals onto the meridian inside the linearised envelope
# ± 20° e^(−ζ ω_n t)/√(1 − ζ²), with the damped period T/√(1 − ζ²), and settles a little east
# of north: the compass then reads low by the latitude (damping) error
# :attr:`~poinsot.Gyrocompass.settle_error`.

LAT = 50 * DEG
compass = ps.Gyrocompass.schuler_tuned(LAT, damping=0.15)
print(compass)
T, zeta, wn = compass.period, compass.damping, compass.natural_frequency
run = compass.simulate(4.5 * T, 20 * DEG, samples=1500)
t, heading = np.asarray(run.t), np.asarray(run.heading)
settled = -compass.settle_error  # the spin axis settles east of north: the compass reads low
swing = heading - settled
down = np.nonzero((swing[:-1] > 0) & (swing[1:] <= 0))[0]
crossings = t[down] - swing[down] * (t[down + 1] - t[down]) / (swing[down + 1] - swing[down])
damped = float(np.mean(np.diff(crossings)))
expected = T / math.sqrt(1 - zeta**2)
print(
    f"Schuler period {ps.Gyrocompass.schuler_period() / 60:.1f} min; the compass's linearised "
    f"{T / 60:.1f} min, damped {expected / 60:.1f} min; the integrated swing {damped / 60:.1f} "
    f"min; the axis settles {settled / DEG:.3f}° east of north (at {heading[-1] / DEG:.3f}° "
    f"after {t[-1] / 3600:.1f} h)."
)
assert abs(damped / expected - 1) < 0.01

# %%
# The picture
# -----------
#
# Left: the speed error against speed due north, the maker's printed values (dots), the settled
# direction (lines) and the small-angle form (dashed). Right: the heading of the Schuler-tuned
# compass against time, in units of the 84.4-min period, with the linearised envelope.

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11.5, 4.8), constrained_layout=True)
for k, (lat, (table_row, exact_row, small_row)) in enumerate(rows.items()):
    color = f"C{k}"
    ax.plot(SPEEDS_KN, table_row, "o", color=color, label=f"{lat}° printed (Plath 1998)")
    ax.plot(SPEEDS_KN, exact_row, "-", color=color, label=f"{lat}° speed_error (exact)")
    ax.plot(SPEEDS_KN, small_row, "--", color=color, lw=1)
ax.plot([], [], "--", color="0.4", lw=1, label="small-angle V / (ΩR cos λ)")
ax.set_xlabel("speed due north (kn)")
ax.set_ylabel("speed error δ (deg)")
ax.set_title("Speed error: the maker's table and the settled compass")
ax.legend(fontsize=8, loc="upper left")

envelope = (20 - settled / DEG) * np.exp(-zeta * wn * t) / math.sqrt(1 - zeta**2)
ax2.plot(t / T, heading / DEG, color="C0", label="heading, integrated rigid body")
ax2.plot(t / T, settled / DEG + envelope, color="0.5", ls="--", lw=1, label="linearised envelope")
ax2.plot(t / T, settled / DEG - envelope, color="0.5", ls="--", lw=1)
ax2.axhline(0, color="0.7", lw=0.8)
ax2.set_xlabel(f"time / {T / 60:.1f} min")
ax2.set_ylabel("heading of the spin axis (deg east of north)")
ax2.set_title(f"A Schuler-tuned compass at 50° N, ζ = {zeta}")
ax2.legend(loc="upper right")
fig.savefig(out / "gyrocompass.png", dpi=110)
print("picture written: gyrocompass.png")
