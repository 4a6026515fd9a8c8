"""Foucault's pendulum
===================

The Foucault pendulum, simulated in the rotating frame (the unit's discussion of Figs. 2.5–2.6).

Its swing plane turns at −ω sin λ: clockwise seen from above in the northern hemisphere, once in
about 32 h in Paris. To see the rosette in a short run this example also spins a fictitious
planet 30 times faster. Writes foucault_rosette.png and foucault.gif into out/ (or the folder
given as the first argument).
"""

# %%
# Paris, half an hour
# -------------------
#
# ``Earth.foucault`` integrates a 67 m pendulum (Foucault's, in the Panthéon) at latitude
# 48.85° in the Earth's rotating frame and measures how fast its swing plane turns. Look at
# the rate beside the theory −ω sin λ: they agree to better than 0.1 %, and the sense is
# clockwise seen from above.

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import poinsot as ps

out = Path(sys.argv[1] if len(sys.argv) > 1 else "out")
out.mkdir(parents=True, exist_ok=True)

earth = ps.Earth()
run = earth.foucault(48.85, degrees=True, duration=1800.0, samples=2)
print(
    f"Paris, 67 m, 30 min in the rotating frame: the plane turns at {run.precession_rate:.5e} rad/s, "
    f"{run.sense}; −ω sin λ = {run.expected_rate:.5e} rad/s "
    f"(one turn in {2 * np.pi / abs(run.expected_rate) / 3600:.1f} h)"
)
assert run.sense == "clockwise" and abs(run.precession_rate / run.expected_rate - 1) < 5e-3

# %%
# The rate against latitude
# -------------------------
#
# At the pole the plane turns once a sidereal day; at the equator it does not turn at all; in
# the south it turns counterclockwise. Each row is a 15 min run beside −ω sin λ.

for lat in (90.0, 45.0, 0.0, -45.0):
    r = earth.foucault(lat, degrees=True, duration=900.0, samples=2)
    print(
        f"  latitude {lat:+5.1f}°: {r.precession_rate:+.4e} rad/s ({r.sense}), theory {r.expected_rate:+.4e}"
    )

# %%
# The rosette, on a planet 30 times faster
# ----------------------------------------
#
# On the real Earth the plane turns by under 2° in 10 min, too little to see. A fictitious
# planet turning 30 times faster, with a 10 m pendulum swung 1 m, shows in 10 minutes the
# rosette the bob draws on the floor, each swing a little turned from the last, and the
# animation shows the swing itself.

fast = ps.Earth(rotation_rate=30 * ps.SIDEREAL_RATE)
show = fast.foucault(48.85, degrees=True, length=10.0, amplitude=1.0, duration=600.0, samples=6001)
import matplotlib

matplotlib.use("Agg")
from poinsot.plots.earth import animate_foucault, plot_foucault_rosette

plot_foucault_rosette(show).savefig(out / "foucault_rosette.png", dpi=110, bbox_inches="tight")
animate_foucault(show, out / "foucault.gif", frames=150, fps=20)
print("pictures written: foucault_rosette.png, foucault.gif")
