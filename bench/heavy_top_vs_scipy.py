"""poinsot.HeavyTop.euler_angles (the exact solution) versus scipy.integrate.solve_ivp(DOP853)
on the same heavy top, at 10⁶ output times.

The top: I1 = 1, I3 = 0.5, m g l = 1, released at theta = 0.8 rad with theta' = 0.3, phi' = 0.6,
psi' = 6 rad/s (loops; nutation period 2.29 s). scipy integrates the Euler-Lagrange equations in
their cheapest form, the state (theta, theta', phi, psi) with phi' and psi' from the conserved
momenta (2.106, 2.99), written with math.sin/cos on Python floats (faster than numpy for 4
components), rtol = atol = 1e-12, its dense output sampled at the 10⁶ times (t_eval). poinsot
evaluates the exact angles at the same times (numpy in, numpy out).

Both runs are timed in the same process (best of a few); the script checks that the two agree
to scipy's own accuracy (printed) and prints the ratio for a few time spans: scipy's cost grows
with the span (steps), the exact solution's only with the number of times.

    python bench/heavy_top_vs_scipy.py
"""

from __future__ import annotations

import math
import timeit

import numpy as np
from scipy.integrate import solve_ivp

import poinsot as ps

RTOL = ATOL = 1e-12
N_TIMES = 1_000_000
I1, I3, MGL = 1.0, 0.5, 1.0
TH0, THD0, PHD0, PSD0 = 0.8, 0.3, 0.6, 6.0
# Spans in nutation periods.
SPANS = (10, 100, 1000, 3000)


def scipy_rhs():
    c0 = math.cos(TH0)
    w3 = PSD0 + PHD0 * c0
    p_psi = I3 * w3
    p_phi = I1 * PHD0 * math.sin(TH0) ** 2 + p_psi * c0
    a, b = p_psi / I1, p_phi / I1
    g = MGL / I1
    spin = p_psi / I3

    def rhs(_t: float, y: np.ndarray) -> list[float]:
        th, thd = y[0], y[1]
        s, c = math.sin(th), math.cos(th)
        phd = (b - a * c) / (s * s)  # 2.106
        thdd = phd * phd * s * c - a * phd * s + g * s  # Euler-Lagrange for theta
        return [thd, thdd, phd, spin - phd * c]

    return rhs


def main() -> None:
    top = ps.HeavyTop(I1, I3, MGL, TH0, theta_dot=THD0, phi_dot=PHD0, psi_dot=PSD0)
    period = top.nutation_period
    rhs = scipy_rhs()
    print(f"heavy top {top!r}")
    print(f"  nutation period {period:.6f} s, {top._core.fourier_terms} Fourier terms; "
          f"{N_TIMES:,} output times; solve_ivp DOP853 rtol = atol = {RTOL:g}")
    for n_periods in SPANS:
        span = n_periods * period
        t = np.linspace(0.0, span, N_TIMES)

        def run_poinsot() -> tuple:
            return top.euler_angles(t)

        def run_scipy():
            return solve_ivp(rhs, (0.0, span), [TH0, THD0, 0.0, 0.0], method="DOP853", rtol=RTOL,
                             atol=ATOL, t_eval=t)

        phi, theta, psi = run_poinsot()
        sol = run_scipy()
        err_theta = float(np.max(np.abs(sol.y[0] - theta)))
        err_phi = float(np.max(np.abs(sol.y[2] - phi)))
        err_psi = float(np.max(np.abs(sol.y[3] - psi)))
        reps = 3 if n_periods <= 100 else 1
        t_p = min(timeit.repeat(run_poinsot, number=1, repeat=10))
        t_s = min(timeit.repeat(run_scipy, number=1, repeat=reps))
        print(f"  span {n_periods:5d} periods ({span:8.1f} s): poinsot {t_p * 1e3:8.1f} ms, "
              f"scipy {t_s * 1e3:9.1f} ms ({sol.nfev} evaluations), ratio {t_s / t_p:7.1f}x; "
              f"|scipy - exact| theta {err_theta:.1e}, phi {err_phi:.1e}, psi {err_psi:.1e} rad")


if __name__ == "__main__":
    main()
