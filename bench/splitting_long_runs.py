"""Long runs of the Lie–Poisson splittings (issue 10, item 17): how |L| and the energy of the
torque-free body drift over up to 10⁸ steps, for splitting2/4/6 and, as the positive control of
the measurement, RK4 (whose errors do drift).

Every sub-step of a splitting is an exact rotation of L, so |L| is kept exactly in exact
arithmetic and only round-off moves it. Independent round-off errors add up like a random walk,
|ΔL|/|L| ∝ √n; a systematic bias of the rounding adds up linearly, ∝ n. For each method this
script integrates several initial conditions (generic ones and spins close to a principal axis,
where a rotation angle stays nearly the same from step to step and a biased rounding would show)
with dt = 0.01 and prints, from 1000 evenly spaced samples over the run:

* per initial condition: the final relative |L| error and energy error;
* the exponent p of |L| error ∝ nᵖ fitted to the root mean square over the initial conditions
  (samples from n = N/1000 to N, three decades; 0.5 for a random walk, 1 for a drift);
* the drift ratio: the least-squares slope through the origin of each run's signed |L| error,
  times N, over the root mean square of the residual about that line (mean and largest over the
  initial conditions): for a pure random walk of 1000 samples its mean is 3.2 and 99 % of walks
  stay below 12 (20 000 simulated walks); a drift makes it hundreds and more.

Reproduce the figures of docs/dynamics.md ("Long runs") with

    python bench/splitting_long_runs.py --steps 1e8

(about 80 minutes on the project's 2-core machine with other jobs running; ``--steps 1e7``
takes about ten, ``--steps 1e6`` one).
"""

from __future__ import annotations

import argparse
import time

import numpy as np

import poinsot as ps

# (principal moments, ω₀): generic motions, and spins close to a principal axis (the first of
# them with the least moment, the second the greatest; the third near the intermediate axis's
# separatrix), where the rotation angle about that axis hardly changes from step to step.
CASES: list[tuple[tuple[float, float, float], tuple[float, float, float]]] = [
    ((1.0, 2.0, 3.0), (1.0, 0.1, 1.0)),
    ((1.0, 2.0, 3.0), (0.3, -0.7, 0.2)),
    ((1.0, 2.0, 3.0), (-1.3, 0.9, 0.45)),
    ((1.0, 2.0, 3.0), (1.0, 0.0, 0.01)),
    ((1.0, 2.0, 3.0), (0.01, 0.0, 1.0)),
    ((1.0, 2.0, 3.0), (0.1, 1.0, 0.1)),
    ((2.0, 3.0, 5.0), (0.2, 0.5, -1.1)),
    ((1.0, 1.0, 2.0), (0.4, 0.3, 1.0)),
    ((3.0, 4.0, 4.5), (0.9, -0.2, 0.05)),
    ((1.0, 5.0, 6.0), (0.02, 0.6, 0.8)),
]
DT = 0.01
SAMPLES = 1001


def run(method: str, moments: tuple[float, ...], w0: tuple[float, ...], steps: int) -> tuple[np.ndarray, np.ndarray]:
    """Relative |L| and energy errors at the samples of one run (the first sample is t = 0)."""
    tr = ps.simulate(np.array(moments), np.array(w0), steps * DT, method=method, dt=DT, samples=SAMPLES)
    lnorm = np.linalg.norm(tr.omega * np.array(moments), axis=1)
    return lnorm / lnorm[0] - 1.0, tr.energy / tr.energy[0] - 1.0


def exponent(n: np.ndarray, err: np.ndarray) -> float:
    """Slope of log(rms over the runs) against log n (rows: runs; columns: samples)."""
    rms = np.sqrt(np.mean(err**2, axis=0))
    keep = rms > 0
    return float(np.polyfit(np.log(n[keep]), np.log(rms[keep]), 1)[0])


def drift_ratio(n: np.ndarray, e: np.ndarray) -> float:
    """|slope through the origin| · N over the rms residual about that line, for one run."""
    slope = float(n @ e / (n @ n))
    resid = e - slope * n
    noise = float(np.sqrt(np.mean(resid**2)))
    return abs(slope) * n[-1] / noise if noise > 0 else float("inf")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--steps", type=float, default=1e6, help="steps per run (default 1e6)")
    parser.add_argument("--methods", default="splitting2,splitting4,splitting6,rk4")
    args = parser.parse_args()
    steps = int(args.steps)
    if steps % (SAMPLES - 1):
        parser.error(f"--steps must be a multiple of {SAMPLES - 1}")
    n = np.arange(1, SAMPLES) * (steps // (SAMPLES - 1))
    print(f"poinsot {ps.__version__}: {len(CASES)} initial conditions, dt = {DT}, {steps:.0e} steps each")
    summary = []
    for method in args.methods.split(","):
        lerr, eerr, ratios = [], [], []
        start = time.perf_counter()
        for moments, w0 in CASES:
            dl, de = run(method, moments, w0, steps)
            lerr.append(dl[1:])
            eerr.append(de[1:])
            ratios.append(drift_ratio(n.astype(float), dl[1:]))
            print(f"  {method:10s} I = {moments}, w0 = {w0}: |L| error {dl[-1]:+.2e} "
                  f"(max {np.abs(dl).max():.2e}), energy error {de[-1]:+.2e} (max {np.abs(de).max():.2e}), "
                  f"drift ratio {ratios[-1]:.1f}", flush=True)
        lerr_a, eerr_a = np.array(lerr), np.array(eerr)
        p_l, p_e = exponent(n, lerr_a), exponent(n, eerr_a)
        rms_end = float(np.sqrt(np.mean(lerr_a[:, -1] ** 2)))
        summary.append((method, p_l, p_e, float(np.mean(ratios)), float(np.max(ratios)), rms_end,
                        float(np.abs(eerr_a).max()), time.perf_counter() - start))
    print(f"\n{'method':10s}  {'|L| exponent':>12s}  {'energy exponent':>15s}  {'drift ratio mean/max':>20s}  "
          f"{'rms |L| error at N':>18s}  {'max energy error':>16s}  {'time':>7s}")
    for method, p_l, p_e, rmean, rmax, rms_end, emax, secs in summary:
        print(f"{method:10s}  {p_l:12.2f}  {p_e:15.2f}  {rmean:9.1f} / {rmax:8.1f}  {rms_end:18.2e}  {emax:16.2e}  {secs:6.0f}s")


if __name__ == "__main__":
    main()
