"""The falling body and projectiles on the rotating Earth
======================================================

The falling body on the rotating Earth (the unit's eqs. 2.32–2.42), effective gravity (2.31),
the unit's worked numbers, and projectiles deflected to the right in the north.

Writes deflection.png and inertial_circles.png into out/ (or the folder given as argument).
"""

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

earth = ps.Earth()
g_e = earth.effective_gravity(45, degrees=True)
print(
    f"effective gravity at 45° (ENU): {np.array2string(g_e, precision=5)} m/s², "
    f"plumb line {earth.plumb_line_deviation(45, degrees=True):.4f}° from the radial, towards the equator"
)

fall = earth.drop(100, 45, degrees=True)
print(
    f"exact drop from 100 m at 45°: {fall.east:.6e} m east (2.42 says {fall.first_order_east:.6e}), "
    f"{-fall.north:.3e} m south, {fall.time:.6f} s"
)
assert abs(fall.east / 1.552e-2 - 1) < 1e-3

for lat in (60, -60):
    shot = earth.projectile(800, 45, 0, lat, degrees=True)
    flat = earth.projectile(800, 45, 0, lat, degrees=True, rotation=False)
    side = "right" if shot.drift > 0 else "left"
    print(
        f"a shell fired north at 800 m/s, 45°, latitude {lat:+d}°: lands {abs(shot.drift):.1f} m to the {side}, "
        f"range {shot.range:.0f} m ({shot.range - flat.range:+.1f} m from rotation)"
    )

import matplotlib

matplotlib.use("Agg")
from poinsot.plots.earth import plot_deflection, plot_inertial_circles

plot_deflection(earth, n=13).savefig(out / "deflection.png", dpi=110, bbox_inches="tight")
plot_inertial_circles(earth).savefig(out / "inertial_circles.png", dpi=110, bbox_inches="tight")
print(f"pictures written to {out}/")
