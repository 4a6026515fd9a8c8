"""The Chandler wobble in 64 years of data
========================================

The Earth is the unit's symmetric top (I₁ = I₂ < I₃), and its rotation axis wanders about its
figure axis as the free top's ω wanders about its symmetry axis (eq. 2.83). The IERS have
measured that wander — the pole's x and y on the ground — every day since 1962. This example
reads the series (:func:`poinsot.polar_motion`: from ``astropy-iers-data`` when installed, else
the extract shipped with poinsot), fits it (:func:`poinsot.fit_wobble`: a trend, the prograde
Chandler circle and the annual circles), and follows the Chandler radius through the decades.

Writes chandler_wobble.png into out/ (or the folder given as the first argument).
"""

# %%
# The pole and its two wobbles
# ----------------------------
#
# The fit finds a prograde circle of about 433 days — the Chandler wobble — beside the annual
# one driven by the seasons. A rigid Earth would wobble in Euler's 304.5 sidereal days (the
# unit's Ω of eq. 2.83 with the Earth's H = (C − A)/C); the mantle's yielding lengthens it to
# about 445 days (:meth:`poinsot.RigidEarth.chandler_period`), and the oceans and the core
# account for the rest. Look at the period and its uncertainty: the residuals are correlated
# over months, and the fit widens its σ for it.

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import poinsot as ps

out = Path(sys.argv[1] if len(sys.argv) > 1 else "out")
out.mkdir(parents=True, exist_ok=True)

DAY = 86_400.0
MAS = math.pi / 648_000.0 / 1000.0  # one milliarcsecond in rad

pm = ps.polar_motion()
print(pm)
fit = ps.fit_wobble(pm.dates, pm.x, pm.y)
print(fit)

earth = ps.RigidEarth()
sidereal_day = 2 * math.pi / earth.rotation_rate
c = fit.chandler
print(
    f"The pole circles the figure axis prograde once every {c.period_days:.1f} ± "
    f"{c.period_sigma / DAY:.1f} days, {c.amplitude / MAS:.0f} mas (about "
    f"{c.amplitude * 6.371e6:.1f} m on the ground) on average; a rigid Earth would take "
    f"{earth.euler_period / sidereal_day:.1f} sidereal days, an elastic one without oceans "
    f"{earth.chandler_period(0.30, 0.938) / DAY:.0f} days."
)
assert 425 < c.period_days < 440 and c.prograde and fit.chandler_significant

# %%
# The Chandler radius through the decades
# ---------------------------------------
#
# In windows of 8 years (longer than the 6.4-year beat of the two wobbles, so the fit can tell
# them apart), the Chandler period held at the value just found, the radius of the Chandler
# circle is about 130 mas in the 1960s and 70s, peaks near 200 mas in the early 1990s, and
# falls from about 2000 on: in the windows centred after 2015 it is under 50 mas, a quarter of
# its peak and the smallest in the record, with a hint of a rise in the last ones. That is how
# the data show it; the wobble's excitation by the atmosphere and the oceans is irregular, and
# why it faded is a matter of current research.

t = pm.t
window = 8 * 365.25 * DAY
centres = np.arange(t[0] + window / 2, t[-1] - window / 2 + 1, 0.25 * 365.25 * DAY)
radius, sigma = [], []
for tc in centres:
    inside = np.abs(t - tc) <= window / 2
    w = ps.fit_wobble(t[inside], pm.x[inside], pm.y[inside], chandler_period=c.period)
    radius.append(w.chandler.amplitude)
    sigma.append(w.chandler.amplitude_sigma)
radius, sigma = np.array(radius), np.array(sigma)
years = 2000.0 + centres / (365.25 * DAY)
peak = int(np.argmax(radius))
late = years > 2015
low = int(np.argmin(np.where(late, radius, np.inf)))
print(
    f"Chandler radius in 8-year windows: largest {radius[peak] / MAS:.0f} ± "
    f"{sigma[peak] / MAS:.0f} mas (centred on {years[peak]:.1f}), smallest after 2015 "
    f"{radius[low] / MAS:.0f} ± {sigma[low] / MAS:.0f} mas (centred on {years[low]:.1f}), "
    f"{radius[-1] / MAS:.0f} ± {sigma[-1] / MAS:.0f} mas in the last (centred on {years[-1]:.1f})."
)
assert 1985 < years[peak] < 2000 and np.all(radius[late] < 0.3 * radius[peak])

# %%
# The picture
# -----------
#
# Left: the pole's path on the ground since 2000 (x towards Greenwich, y towards 90° W, as the
# IERS draw it), coloured by year: wide loops in the 2000s, where the two wobbles add, and the
# tight ones after 2015 with the Chandler circle nearly gone. Right: the Chandler radius in the
# sliding windows with its 1-σ band.

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11.5, 5.0), constrained_layout=True)
recent = pm.dates >= np.datetime64("2000-01-01")
year = 1970.0 + pm.dates.astype("datetime64[D]").astype(float) / 365.25
ax.plot(pm.x[recent] / MAS, pm.y[recent] / MAS, color="0.8", lw=0.6, zorder=1)
dots = ax.scatter(
    pm.x[recent] / MAS, pm.y[recent] / MAS, c=year[recent], s=4, cmap="viridis", zorder=2
)
fig.colorbar(dots, ax=ax, label="year")
ax.set_xlabel("x (mas, towards Greenwich)")
ax.set_ylabel("y (mas, towards 90° W)")
ax.set_aspect("equal")
ax.set_title("The pole's path since 2000 (IERS EOP 20 C04)")

ax2.fill_between(years, (radius - sigma) / MAS, (radius + sigma) / MAS, color="C0", alpha=0.25)
ax2.plot(years, radius / MAS, color="C0", label="Chandler radius, 8-year windows")
ax2.axhline(c.amplitude / MAS, color="0.5", ls="--", lw=1, label="its mean, 1962–now")
ax2.axvline(2015, color="C3", ls=":", lw=1, label="2015")
ax2.set_xlabel("window centre (year)")
ax2.set_ylabel("radius (mas)")
ax2.set_ylim(bottom=0)
ax2.legend(loc="upper left")
ax2.set_title(f"The Chandler wobble, period {c.period_days:.1f} days")
fig.savefig(out / "chandler_wobble.png", dpi=110)
print("picture written: chandler_wobble.png")
