"""poinsot.simulate_particle versus scipy.integrate.solve_ivp(method="DOP853") on the unit's
falling body: a body dropped from rest from 100 m at latitude 45°, integrated in the rotating
ENU frame (r̈ = −g ẑ − 2ω×ṙ − ω×(ω×r)) to rtol = atol = 1e-12, start to landing.

Both run the same method (Dormand–Prince 8(5,3)) on the same equations; scipy's right-hand side
is written as fast as numpy allows (one 6×6 matrix product). Prints the best-of times and the
ratio; checks that the two landing states agree.

    python bench/particle_vs_scipy.py
"""

from __future__ import annotations

import timeit

import numpy as np
from scipy.integrate import solve_ivp

import poinsot as ps

RTOL = ATOL = 1e-12


def main() -> None:
    earth = ps.Earth()
    w = earth.omega_enu(45, degrees=True)
    duration = earth.drop(100.0, 45, degrees=True).time  # the landing time
    frame = ps.MovingFrame(angular_velocity=w)
    mass = 1.0
    force = np.array([0.0, 0.0, -mass * earth.g])
    y0 = np.array([0.0, 0.0, 100.0, 0.0, 0.0, 0.0])

    r0, v0 = y0[:3].copy(), y0[3:].copy()

    def run_poinsot() -> ps.ParticleTrajectory:
        return ps.simulate_particle(frame, r0, v0, duration, mass=mass, force=force,
                                    samples=2, rtol=RTOL, atol=ATOL)

    W = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
    M = np.zeros((6, 6))
    M[0:3, 3:6] = np.eye(3)
    M[3:6, 0:3] = -W @ W
    M[3:6, 3:6] = -2 * W
    c = np.r_[0, 0, 0, force / mass]

    def rhs(_t: float, y: np.ndarray) -> np.ndarray:
        return M @ y + c

    def run_scipy() -> object:
        return solve_ivp(rhs, (0.0, duration), y0, method="DOP853", rtol=RTOL, atol=ATOL)

    # Both calls are timed alone; the final states are read afterwards.
    tr, sol = run_poinsot(), run_scipy()
    a = np.concatenate([tr.position[-1], tr.velocity[-1]])
    b = sol.y[:, -1]
    scale = np.maximum(np.abs(b), 1.0)
    agree = float(np.max(np.abs(a - b) / scale))
    n_p, n_s = 2000, 50
    t_p = min(timeit.repeat(run_poinsot, number=n_p, repeat=5)) / n_p
    t_s = min(timeit.repeat(run_scipy, number=n_s, repeat=5)) / n_s
    print(f"100 m drop at 45°, DOP853, rtol = atol = {RTOL:g}, {duration:.6f} s of fall")
    print(f"  landing east: poinsot {a[0]:.12e} m, scipy {b[0]:.12e} m (max rel. difference {agree:.1e})")
    print(f"  poinsot.simulate_particle: {t_p * 1e6:9.2f} µs per run")
    print(f"  scipy solve_ivp(DOP853):   {t_s * 1e6:9.2f} µs per run")
    print(f"  ratio scipy / poinsot:     {t_s / t_p:9.1f}x")


if __name__ == "__main__":
    main()
