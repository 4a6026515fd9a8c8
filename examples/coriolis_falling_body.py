"""The falling body and projectiles on the rotating Earth
======================================================

The falling body on the rotating Earth (the unit's eqs. 2.32–2.42), effective gravity (2.31),
the unit's worked numbers, and projectiles deflected to the right in the north.

Writes deflection.png and inertial_circles.png into out/ (or the folder given as argument).
"""

# %%
# The unit's numbers, with both day lengths
# -----------------------------------------
#
# The unit takes the Earth's rate from the solar day (2π per 24 h) and its radius as 6400 km;
# the true rate is the sidereal one (2π per 23 h 56 min). For each: the rate ω, the centripetal
# acceleration ω² r at the equator (2.31), the Coriolis parameter 2ω at the pole, and the
# first-order eastward deflection of a body dropped 100 m at 45° (2.42). Look at the last
# column: the day's length changes the deflection in the third digit.

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import poinsot as ps

out = Path(sys.argv[1] if len(sys.argv) > 1 else "out")
out.mkdir(parents=True, exist_ok=True)

# The unit's numbers, with its solar-day rate and with the true (sidereal) one.
solar = ps.Earth.solar_day(radius=6.4e6, g=9.81)
sidereal = ps.Earth(radius=6.4e6)
for name, e in (("solar day", solar), ("sidereal ", sidereal)):
    print(
        f"{name}: ω = {e.rotation_rate:.4e} rad/s, ω²r = {np.linalg.norm(e.centrifugal_acceleration(0)):.3e} m/s², "
        f"2ω = {e.coriolis_parameter(90, degrees=True):.3e} 1/s, "
        f"100 m at 45°: {e.eastward_deflection(100, 45, degrees=True):.4e} m east (2.42)"
    )

# %%
# Effective gravity (eq. 2.31)
# ----------------------------
#
# What a plumb line feels is gravity plus the centrifugal term −ω × (ω × r): at 45° it is
# weaker than g and tilted towards the equator. The vector is in local east-north-up
# components; the deviation from the radial direction is about a tenth of a degree.

earth = ps.Earth()
g_e = earth.effective_gravity(45, degrees=True)
print(
    f"effective gravity at 45° (ENU): {np.array2string(g_e, precision=5)} m/s², "
    f"plumb line {earth.plumb_line_deviation(45, degrees=True):.4f}° from the radial, towards the equator"
)

# %%
# The falling body (eqs. 2.32–2.42)
# ---------------------------------
#
# ``drop`` integrates the fall in the rotating frame with every term kept. Look at the
# eastward deflection beside the unit's first-order 2.42: for 100 m they agree to all the
# printed digits, 1.55 cm. The body also lands a little south (a second-order
# effect the unit leaves out).

fall = earth.drop(100, 45, degrees=True)
print(
    f"exact drop from 100 m at 45°: {fall.east:.6e} m east (2.42 says {fall.first_order_east:.6e}), "
    f"{-fall.north:.3e} m south, {fall.time:.6f} s"
)
assert abs(fall.east / 1.552e-2 - 1) < 1e-3

# %%
# Projectiles: to the right in the north, to the left in the south
# ----------------------------------------------------------------
#
# A shell fired north at 800 m/s and 45° elevation, at 60° north and at 60° south, against the
# same shot on an Earth that does not turn: the Coriolis force 2m v × ω bends it to the right
# of its motion in the northern hemisphere and to the left in the southern one, by hundreds
# of metres, and changes its range by about a metre.

for lat in (60, -60):
    shot = earth.projectile(800, 45, 0, lat, degrees=True)
    flat = earth.projectile(800, 45, 0, lat, degrees=True, rotation=False)
    side = "right" if shot.drift > 0 else "left"
    print(
        f"a shell fired north at 800 m/s, 45°, latitude {lat:+d}°: lands {abs(shot.drift):.1f} m to the {side}, "
        f"range {shot.range:.0f} m ({shot.range - flat.range:+.1f} m from rotation)"
    )

# %%
# The pictures
# ------------
#
# First, the eastward deflection against latitude (100 m drop) and against height (at 45°):
# the unit's 2.42 beside the exact fall. Second, inertial oscillations (the unit's Fig. 2.6):
# a parcel set moving at 10 m/s with no force but Coriolis' goes round a circle, clockwise in
# the north, counterclockwise in the south, and straight on at the equator.

import matplotlib

matplotlib.use("Agg")
from poinsot.plots.earth import plot_deflection, plot_inertial_circles

plot_deflection(earth, n=13).savefig(out / "deflection.png", dpi=110, bbox_inches="tight")
plot_inertial_circles(earth).savefig(out / "inertial_circles.png", dpi=110, bbox_inches="tight")
print("pictures written: deflection.png, inertial_circles.png")
