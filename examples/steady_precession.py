"""Steady precession of the heavy top
==================================

Steady precession of a heavy top (the unit's eqs. 2.114–2.121), exact and approximate.

A top held at θ0 with spin ω3 precesses without nutation at exactly two rates, the roots of the
quadratic 2.116; they exist only above the minimum spin 2.119. For a fast top the unit
approximates them by m g l/p_ψ (2.121, slow) and p_ψ/(2 I1 cos θ0) (2.120, fast) — the latter a
misprint: the correct approximation is p_ψ/(I1 cos θ0). This example prints both roots beside
the approximations, shows that a top started at either exact rate does not nutate (and one
started at the misprinted rate does), and plots the rates against the spin into out/ (or the
folder given as the first argument).
"""

# %%
# The two rates against the spin (eqs. 2.116–2.121)
# -------------------------------------------------
#
# A top with I₁ = 1 kg m², I₃ = 0.5 kg m², m g l = 0.3 N m held at θ₀ = 0.6 rad. Below the
# minimum spin 2.119 it cannot precess steadily at all. Above it, for each spin ω₃, the two
# roots of 2.116 (``slow`` and ``fast``) beside the unit's approximations: m g l/p_ψ (2.121)
# for the slow one, and for the fast one the correct p_ψ/(I₁ cos θ₀) and 2.120 as printed,
# p_ψ/(2 I₁ cos θ₀). Look down the columns: the approximations close in on the roots as the
# spin grows, except the printed 2.120, which stays at half the fast rate.

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import poinsot as ps

out = Path(sys.argv[1] if len(sys.argv) > 1 else "out")
out.mkdir(parents=True, exist_ok=True)

I1, I3, MGL, THETA0 = 1.0, 0.5, 0.3, 0.6
w_min = ps.HeavyTop.min_spin(I1, I3, MGL, THETA0)
print(
    f"I1 = {I1}, I3 = {I3}, m g l = {MGL}, theta0 = {THETA0} rad: minimum spin (2.119) {w_min:.6f} rad/s"
)
print(
    f"{'omega3':>8} {'slow':>10} {'mgl/p_psi':>10} {'fast':>10} {'p_psi/I1cos':>12} {'as printed':>11}"
)
for w3 in (1.05 * w_min, 5.0, 10.0, 40.0, 200.0):
    s = ps.HeavyTop.steady_precession(I1, I3, MGL, THETA0, w3)
    print(
        f"{w3:8.3f} {s.slow:10.6f} {s.slow_approx:10.6f} {s.fast:10.4f} {s.fast_approx:12.4f} "
        f"{s.fast_approx_as_printed:11.4f}"
    )

# %%
# Started at each rate: no nutation, except at the misprint
# ---------------------------------------------------------
#
# At ω₃ = 40 rad/s (the errata's example), a top started at θ₀ with θ̇₀ = 0 and φ̇₀ at each
# rate. At the slow and the fast root its turning points coincide (θ₂ − θ₁ = 0):
# steady precession. Started at the rate 2.120 prints, it nods. Below the minimum spin, the
# call refuses and says why.

s = ps.HeavyTop.steady_precession(I1, I3, MGL, THETA0, 40.0)
assert round(s.fast, 4) == 24.2176 and round(s.fast_approx, 4) == 24.2326  # the errata example
for name, rate in (
    ("slow", s.slow),
    ("fast", s.fast),
    ("2.120 as printed", s.fast_approx_as_printed),
):
    top = ps.HeavyTop(I1, I3, MGL, THETA0, phi_dot=rate, psi_dot=40.0 - rate * np.cos(THETA0))
    t1, t2 = top.turning_points
    print(
        f"  started at the {name} rate {rate:.6f} rad/s: {top.motion_class}, nutation theta2 - theta1 = {t2 - t1:.2e} rad"
    )
    if name != "2.120 as printed":
        assert top.motion_class == "steady precession"
    else:
        assert t2 - t1 > 1e-3

try:
    ps.HeavyTop.steady_precession(I1, I3, MGL, THETA0, 0.9 * w_min)
except ps.PoinsotError as exc:
    print(f"  below the minimum spin: {exc}")

# %%
# The picture
# -----------
#
# Both roots of 2.116 against the spin up to 20 rad/s, with the minimum spin 2.119 where they
# meet and the fast-top approximations 2.120 (corrected) and 2.121 beside them.

import matplotlib

matplotlib.use("Agg")
from poinsot.plots.top import plot_steady_precession

plot_steady_precession(I1, I3, MGL, THETA0, max_spin=20.0).savefig(
    out / "steady_precession.png", dpi=110, bbox_inches="tight"
)
print("picture written: steady_precession.png")
