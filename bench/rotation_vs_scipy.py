"""poinsot vs scipy: batched Euler-angle <-> matrix conversions of 10^6 rotations.

Times, in the same run and on the same input, numpy array in -> numpy array out (poinsot's
time includes its Python wrapper: conversion, validation of every matrix, output allocation):

* euler -> matrix: ``poinsot.euler_to_matrix(a, "zxz")`` vs
  ``Rotation.from_euler("ZXZ", a).as_matrix()`` (scipy: uppercase = intrinsic);
* matrix -> euler: ``poinsot.matrix_to_euler(R, "zxz")`` vs
  ``Rotation.from_matrix(R).as_euler("ZXZ")``.

Also checks that both give the same matrices. Prints the best of ``--repeat`` runs and the
ratios scipy/poinsot. Run: ``.venv/bin/python bench/rotation_vs_scipy.py [--n 1000000]``.
"""

from __future__ import annotations

import argparse
import os
import platform
import time
from typing import Any, Callable

import numpy as np
from scipy.spatial.transform import Rotation

import poinsot


def best_time(fn: Callable[[], Any], repeat: int) -> float:
    """Best wall time of ``repeat`` calls, s."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=1_000_000, help="number of rotations")
    parser.add_argument("--repeat", type=int, default=5, help="timed runs per case (best kept)")
    parser.add_argument("--seq", default="zxz", help="lowercase sequence (intrinsic)")
    args = parser.parse_args()

    import scipy

    rng = np.random.default_rng(20240601)
    angles = rng.uniform(-np.pi, np.pi, (args.n, 3))
    angles[:, 1] = rng.uniform(0.0, np.pi, args.n)
    seq, scipy_seq = args.seq, args.seq.upper()  # scipy: uppercase letters = intrinsic

    mats = poinsot.euler_to_matrix(angles, seq)
    ref = Rotation.from_euler(scipy_seq, angles).as_matrix()
    agree_e2m = float(np.abs(mats - ref).max())
    back = poinsot.matrix_to_euler(mats, seq)
    agree_m2e = float(np.abs(poinsot.euler_to_matrix(back, seq) - mats).max())

    t_p_e2m = best_time(lambda: poinsot.euler_to_matrix(angles, seq), args.repeat)
    t_s_e2m = best_time(lambda: Rotation.from_euler(scipy_seq, angles).as_matrix(), args.repeat)
    t_p_m2e = best_time(lambda: poinsot.matrix_to_euler(mats, seq), args.repeat)
    t_s_m2e = best_time(lambda: Rotation.from_matrix(mats).as_euler(scipy_seq), args.repeat)

    print(f"poinsot {poinsot.__version__} vs scipy {scipy.__version__}, numpy {np.__version__}")
    print(f"{platform.machine()} with {os.cpu_count()} CPUs, n = {args.n}, intrinsic {seq}")
    print(f"max |R_poinsot - R_scipy| = {agree_e2m:.1e}; matrix round trip {agree_m2e:.1e}")
    print(f"{'case':<16}{'poinsot (ms)':>14}{'scipy (ms)':>14}{'scipy/poinsot':>16}")
    for name, tp, ts in (
        ("euler -> matrix", t_p_e2m, t_s_e2m),
        ("matrix -> euler", t_p_m2e, t_s_m2e),
    ):
        print(f"{name:<16}{tp * 1e3:>14.1f}{ts * 1e3:>14.1f}{ts / tp:>15.1f}x")


if __name__ == "__main__":
    main()
