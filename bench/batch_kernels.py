"""The batch kernels on SIMD lanes (issue 15), from Python, each against its peer in the same run:

* ``simulate_batch`` RK4, 10⁶ bodies × 20 steps (body-steps/s), against one core's single-body
  ``simulate`` (RK4 steps/s of one body: a single trajectory cannot use more than one core) —
  target ≥ 10⁸ body-steps/s and ≥ 4× the single-body rate; the splittings alongside;
* ``free_body_states``, 10³ bodies × 10³ times (states/s), against ``FreeRigidBody.state``
  called body by body on the same inputs — target ≥ 10⁷ states/s; also 10⁵ bodies at one time
  each (the construction of every body then dominates);
* ``HeavyTop.euler_angles`` at 10⁶ times (ns per output time) — target ≤ 10 ns;

each with rayon's pool of 1 and of 2 threads (``RAYON_NUM_THREADS`` in a child process: the
pool is sized once per process), so that the scaling from one core to two is printed too.

    python bench/batch_kernels.py
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time

import numpy as np
import poinsot as ps

I123 = [1.0, 2.0, 3.0]
W0 = [1.0, 0.1, 1.0]


def best(fn, repeat: int = 5) -> float:
    """The best of ``repeat`` wall-clock times of ``fn()`` (s)."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def bodies(n: int) -> tuple[np.ndarray, np.ndarray]:
    """N bodies with different moments and initial states."""
    i = np.arange(n, dtype=float)
    moments = np.column_stack([np.ones(n), 1.5 + 0.4 * np.abs(np.sin(0.37 * i)), np.full(n, 2.2)])
    omega = np.column_stack([np.cos(0.7 * i), 0.1 + np.sin(1.3 * i), 1.0 + 0.3 * np.cos(0.11 * i)])
    return moments, omega


def measure() -> dict[str, float]:
    """One set of figures with this process's thread pool."""
    out: dict[str, float] = {}
    n = 1_000_000
    moments, omega = bodies(n)
    for method in ("rk4", "splitting2", "splitting6"):
        steps = 100_000 if method == "rk4" else 20_000
        out[f"single_{method}_per_s"] = steps / best(
            lambda m=method, k=steps: ps.simulate(I123, W0, k * 1e-3, method=m, dt=1e-3, samples=2),
            3,
        )
        el = best(lambda m=method: ps.simulate_batch(moments, omega, 0.02, method=m, dt=1e-3), 3)
        out[f"batch_{method}_per_s"] = n * 20 / el
    m, w = bodies(1000)
    t = np.linspace(-3.0, 10.0, 1000)
    out["states_per_s"] = 1e6 / best(lambda: ps.free_body_states(m, w, t), 5)
    sub = 50
    out["states_single_per_s"] = (
        sub * 1000 / best(lambda: [ps.FreeRigidBody(m[i], w[i]).state(t) for i in range(sub)], 3)
    )
    m1, w1 = bodies(100_000)
    out["states_one_time_per_s"] = 1e5 / best(lambda: ps.free_body_states(m1, w1, 7.5), 3)
    top = ps.HeavyTop(1.0, 0.5, 1.0, 0.8, theta_dot=0.3, phi_dot=0.6, psi_dot=6.0)
    times = np.linspace(0.0, 1000.0, 1_000_000)
    out["top_ns_per_time"] = best(lambda: top.euler_angles(times), 7) / times.size * 1e9
    return out


def main() -> None:
    if len(sys.argv) > 1 and sys.argv[1] == "--child":
        print(json.dumps(measure()))
        return
    runs = {}
    for threads in (1, 2):
        # numpy's OpenBLAS threads would spin on the same cores after a BLAS call: one thread.
        env = dict(os.environ, RAYON_NUM_THREADS=str(threads), OPENBLAS_NUM_THREADS="1")
        proc = subprocess.run(
            [sys.executable, __file__, "--child"],
            env=env,
            capture_output=True,
            text=True,
            check=True,
        )
        runs[threads] = json.loads(proc.stdout.strip().splitlines()[-1])
    load = os.getloadavg()
    print(
        f"batch kernels (poinsot {ps.__version__}, load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f})"
    )
    one, two = runs[1], runs[2]
    for method in ("rk4", "splitting2", "splitting6"):
        single = two[f"single_{method}_per_s"]
        a, b = one[f"batch_{method}_per_s"], two[f"batch_{method}_per_s"]
        print(
            f"  {method:10s} one core, single-body simulate: {single:.3e} steps/s "
            f"({1e9 / single:.1f} ns per step)\n"
            f"  {method:10s} simulate_batch 10⁶ bodies × 20 steps: 1 thread {a:.3e}, 2 threads "
            f"{b:.3e} body-steps/s (scaling {b / a:.2f}×; {b / single:.1f}× the single-body rate)"
        )
    a, b = one["states_per_s"], two["states_per_s"]
    print(
        f"  free_body_states 10³ bodies × 10³ times: 1 thread {a:.3e}, 2 threads {b:.3e} states/s "
        f"(scaling {b / a:.2f}×; {b / two['states_single_per_s']:.0f}× FreeRigidBody.state body by "
        f"body, {two['states_single_per_s']:.3e} states/s)"
    )
    a, b = one["states_one_time_per_s"], two["states_one_time_per_s"]
    print(f"  free_body_states 10⁵ bodies × 1 time: 1 thread {a:.3e}, 2 threads {b:.3e} states/s")
    a, b = one["top_ns_per_time"], two["top_ns_per_time"]
    print(
        f"  HeavyTop.euler_angles at 10⁶ times: 1 thread {a:.1f} ns, 2 threads {b:.1f} ns per time "
        f"(scaling {a / b:.2f}×)"
    )


if __name__ == "__main__":
    main()
