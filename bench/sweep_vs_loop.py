"""poinsot.sweep versus the loop a user would write over the scalar API, on the same grids, in
the same run (the peer computes the same numbers: each sweep point equals the scalar call's).

* the heavy top's phase diagram of issue 15, 81 tilts × 200 spins (16,200 tops), every result
  of the Dataset, against a Python loop building ``HeavyTop`` and reading the same properties;
* the free body over 100 × 100 directions of ω₀, against a loop over ``FreeRigidBody``;
* drops on the rotating Earth, 20 latitudes × 20 heights, against a loop over ``Earth.drop``;
* with dask.distributed installed: the heavy top over 400 × 400 points in one local call against
  the same sweep chunk by chunk on a LocalCluster of two single-threaded worker processes
  (``client=``), and the share of a sweep's time spent labelling (xarray) rather than computing.

    python bench/sweep_vs_loop.py
"""

from __future__ import annotations

import os
import timeit

import numpy as np

import poinsot as ps
from poinsot import _core, sweep

THETA = np.radians(np.linspace(5.0, 85.0, 81))
PSI_DOT = np.linspace(0.5, 20.0, 200)


def best(fn, repeat: int = 3) -> float:
    return min(timeit.repeat(fn, number=1, repeat=repeat))


def heavy_top() -> None:
    def run_sweep():
        return sweep.heavy_top(I1=1.0, I3=0.5, mgl=1.0, theta=THETA, psi_dot=PSI_DOT,
                               phi_dot=0.5, progress=False)

    def run_loop():
        out = []
        for th in THETA:
            for pd in PSI_DOT:
                top = ps.HeavyTop(1.0, 0.5, 1.0, th, psi_dot=pd, phi_dot=0.5)
                out.append((top.motion_class, top.turning_points, top.nutation_period,
                            top.mean_precession_rate, top.mean_spin_rate, top.omega3, top.p_phi,
                            top.p_psi, top.energy, top.reduced_energy, top.is_sleeping_stable))
        return out

    dims = [("theta", len(THETA), 0), ("psi_dot", len(PSI_DOT), 0)]
    one, half = np.array([1.0]), np.array([0.5])
    cols = [("I1", one, None), ("I3", half, None), ("mgl", one, None), ("theta", THETA, 0),
            ("psi_dot", PSI_DOT, 1), ("phi_dot", half, None)]

    def run_core():
        return _core.sweep_heavy_top(dims, cols, False)

    run_sweep()
    n = THETA.size * PSI_DOT.size
    t_s, t_l, t_c = best(run_sweep), best(run_loop, 1), best(run_core)
    print(f"heavy top phase diagram, {n:,} tops (81 tilts × 200 spins), every result")
    print(f"  sweep.heavy_top     {t_s * 1e3:8.1f} ms  ({n / t_s:,.0f} tops/s)")
    print(f"    of which the core {t_c * 1e3:8.1f} ms  ({n / t_c:,.0f} tops/s; the rest: labels)")
    print(f"  loop over HeavyTop  {t_l * 1e3:8.1f} ms  ({n / t_l:,.0f} tops/s)")
    print(f"  ratio {t_l / t_s:.1f}×")


def free_body() -> None:
    polar = np.linspace(0.01, np.pi - 0.01, 100)
    azimuth = np.linspace(0.0, np.pi, 100)

    def run_sweep():
        return sweep.free_body(moments=[1.0, 2.0, 3.0], omega_magnitude=1.0, omega_polar=polar,
                               omega_azimuth=azimuth, progress=False)

    def run_loop():
        out = []
        for th in polar:
            for ph in azimuth:
                w = np.array([np.sin(th) * np.cos(ph), np.sin(th) * np.sin(ph), np.cos(th)])
                b = ps.FreeRigidBody([1.0, 2.0, 3.0], w)
                out.append((b.regime, b.period, b.flip_interval, b.energy))
        return out

    run_sweep()
    n = polar.size * azimuth.size
    t_s, t_l = best(run_sweep), best(run_loop, 1)
    print(f"free body, {n:,} directions of ω₀ (regime, period, flip interval, T, L, stability)")
    print(f"  sweep.free_body         {t_s * 1e3:8.1f} ms  ({n / t_s:,.0f} bodies/s)")
    print(f"  loop over FreeRigidBody {t_l * 1e3:8.1f} ms  ({n / t_l:,.0f} bodies/s)")
    print(f"  ratio {t_l / t_s:.1f}×")


def drop() -> None:
    lat = np.linspace(-80.0, 80.0, 20)
    height = np.geomspace(1.0, 1000.0, 20)
    earth = ps.Earth()

    def run_sweep():
        return sweep.drop(latitude=lat, height=height, degrees=True, progress=False)

    def run_loop():
        return [earth.drop(h, la, degrees=True).east for la in lat for h in height]

    run_sweep()
    n = lat.size * height.size
    t_s, t_l = best(run_sweep), best(run_loop, 1)
    print(f"drops on the rotating Earth, {n} (20 latitudes × 20 heights), DOP853 to 1e-12")
    print(f"  sweep.drop           {t_s * 1e3:8.1f} ms  ({n / t_s:,.0f} drops/s)")
    print(f"  loop over Earth.drop {t_l * 1e3:8.1f} ms  ({n / t_l:,.0f} drops/s)")
    print(f"  ratio {t_l / t_s:.1f}×")


def cluster() -> None:
    try:
        from distributed import Client, LocalCluster
    except ImportError:
        print("cluster: dask.distributed is not installed (pip install 'poinsot[parallel]')")
        return
    theta = np.linspace(0.05, 3.0, 400)
    psi_dot = np.linspace(-20.0, 40.0, 400)
    kw = dict(I1=1.0, I3=0.5, mgl=1.0, theta=theta, psi_dot=psi_dot, phi_dot=0.4, progress=False)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address=None) as lc, Client(lc) as client:
        # Each worker's core call would use every core: one thread each, as the cluster's.
        client.run(os.environ.__setitem__, "RAYON_NUM_THREADS", "1")
        local = sweep.heavy_top(**kw)
        remote = sweep.heavy_top(**kw, client=client)
        assert all(np.array_equal(local[v].values, remote[v].values) for v in local.data_vars)
        n = theta.size * psi_dot.size
        t_l = best(lambda: sweep.heavy_top(**kw))
        t_c = best(lambda: sweep.heavy_top(**kw, client=client))
        t_8 = best(lambda: sweep.heavy_top(**kw, client=client, chunks={"theta": 50}))
        print(f"heavy top, {n:,} tops: here (rayon, 2 cores) against a LocalCluster of 2 worker "
              "processes × 1 thread")
        print(f"  here                          {t_l * 1e3:8.1f} ms  ({n / t_l:,.0f} tops/s)")
        print(f"  cluster, default chunks (5)   {t_c * 1e3:8.1f} ms  ({n / t_c:,.0f} tops/s)")
        print(f"  cluster, 8 chunks of 20,000   {t_8 * 1e3:8.1f} ms  ({n / t_8:,.0f} tops/s)")
        print(f"  cluster / here {t_c / t_l:.2f}  (same numbers, bit for bit)")


if __name__ == "__main__":
    print(f"load average {os.getloadavg()[0]:.2f} {os.getloadavg()[1]:.2f} {os.getloadavg()[2]:.2f}")
    heavy_top()
    free_body()
    drop()
    cluster()
