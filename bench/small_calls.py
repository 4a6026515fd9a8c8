"""Small calls from Python: one object and one state at a scalar ``t``, the way a script or a
notebook cell asks for them, against the core's own time per state measured in the same run
(a batch of 10⁵ times through the same object, divided by the count: the Rust kernel with the
Python overhead spread over 10⁵ states).

    python bench/small_calls.py            # the calls, and their ratios to the core
    python bench/small_calls.py --layers   # where one FreeRigidBody(...).state(t) goes

The batches run on one thread (``RAYON_NUM_THREADS=1``, set here before poinsot is imported):
a single call uses one core, so one core's time per state is its peer. Every figure is the
best of 7 repeats of the process's CPU time (``time.process_time``: on a shared machine the
time other processes hold the cores is not counted, though their contention for caches
still is); the load average is printed with them.
"""

from __future__ import annotations

import os
import sys
import time
import timeit
from collections.abc import Callable
from typing import Any

os.environ.setdefault("RAYON_NUM_THREADS", "1")

import numpy as np  # noqa: E402

import poinsot as ps  # noqa: E402
from poinsot import _core, _validate  # noqa: E402

MOMENTS = [1.0, 2.0, 3.0]
OMEGA0 = [1.0, 0.1, 1.0]
T = 0.7316
BATCH = 100_000


def best(fn: Callable[[], Any], number: int, repeat: int = 7) -> float:
    """Seconds per call: the best of ``repeat`` runs of ``number`` calls."""
    return min(timeit.repeat(fn, number=number, repeat=repeat, timer=time.process_time)) / number


def per_state(fn: Callable[[np.ndarray], Any]) -> float:
    """Seconds per time of ``fn`` over a batch of :data:`BATCH` times in [0, 10⁴) s."""
    times = np.random.default_rng(1).uniform(0.0, 1e4, BATCH)
    return best(lambda: fn(times), 1, 5) / BATCH


def load() -> str:
    one, five, _ = os.getloadavg()
    return f"load average {one:.2f} (1 min), {five:.2f} (5 min) on {os.cpu_count()} cores"


def calls() -> None:
    m_arr, w_arr = np.array(MOMENTS), np.array(OMEGA0)
    body = ps.FreeRigidBody(MOMENTS, OMEGA0)
    sym = ps.FreeSymmetricTop(1.0, 0.5, OMEGA0)
    top = ps.HeavyTop(1.0, 0.5, 1.0, 0.8, psi_dot=6.0)

    core_free = per_state(body.state)
    core_sym = per_state(sym.attitude)
    core_top = per_state(top.euler_angles)
    rows = [
        ("FreeRigidBody(lists).state(t)", lambda: ps.FreeRigidBody(MOMENTS, OMEGA0).state(T), core_free),
        ("FreeRigidBody(arrays).state(t)", lambda: ps.FreeRigidBody(m_arr, w_arr).state(T), core_free),
        ("FreeRigidBody(lists)", lambda: ps.FreeRigidBody(MOMENTS, OMEGA0), core_free),
        ("body.state(t)", lambda: body.state(T), core_free),
        ("body.state(np.array(t))  (0-d array: general path)", lambda: body.state(np.array(T)), core_free),
        ("FreeSymmetricTop(1, 0.5, list).attitude(t)", lambda: ps.FreeSymmetricTop(1.0, 0.5, OMEGA0).attitude(T), core_sym),
        ("top.attitude(t)  (FreeSymmetricTop)", lambda: sym.attitude(T), core_sym),
        ("HeavyTop(1, 0.5, 1, 0.8, psi_dot=6).euler_angles(t)", lambda: ps.HeavyTop(1.0, 0.5, 1.0, 0.8, psi_dot=6.0).euler_angles(T), core_top),
        ("HeavyTop(...)", lambda: ps.HeavyTop(1.0, 0.5, 1.0, 0.8, psi_dot=6.0), core_top),
        ("top.euler_angles(t)  (HeavyTop)", lambda: top.euler_angles(T), core_top),
    ]
    print(f"small calls from Python, poinsot from {os.path.dirname(ps.__file__)}")
    print(f"  {load()}")
    print(f"  the core per state (batch of {BATCH} times, one thread): free body {core_free * 1e9:.0f} ns, "
          f"symmetric top attitude {core_sym * 1e9:.0f} ns, heavy top angles {core_top * 1e9:.0f} ns")
    for name, fn, core in rows:
        t = best(fn, 20_000)
        print(f"  {name:<55} {t * 1e6:7.2f} µs  = {t / core:6.1f} × the core's time per state")
    print(f"  {load()}")


def layers() -> None:
    """The pieces of ``FreeRigidBody(lists).state(t)``, each timed alone (the rest of the
    whole is Python's own: calls, frames, attribute stores)."""
    body = ps.FreeRigidBody(MOMENTS, OMEGA0)
    m_arr, w_arr = np.array(MOMENTS), np.array(OMEGA0)
    m_tup, w_tup = tuple(MOMENTS), tuple(OMEGA0)
    ints = [1, 2, 3]
    cls = ps.FreeRigidBody
    steps: list[tuple[str, Callable[[], Any]]] = [
        ("whole: FreeRigidBody(lists).state(t)", lambda: cls(MOMENTS, OMEGA0).state(T)),
        ("FreeRigidBody(lists)", lambda: cls(MOMENTS, OMEGA0)),
        ("body.state(t)", lambda: body.state(T)),
        ("the pieces:", lambda: None),
        ("  object.__new__(FreeRigidBody)", lambda: object.__new__(cls)),
        ("  FreeBodySolution(lists)  (binding reads + core new)",
         lambda: _core.FreeBodySolution(MOMENTS, OMEGA0, None)),
        ("  FreeBodySolution(arrays)", lambda: _core.FreeBodySolution(m_arr, w_arr, None)),
        ("  FreeBodySolution(tuples)", lambda: _core.FreeBodySolution(m_tup, w_tup, None)),
        ("  FreeBodySolution(ints)  (read by the binding too)",
         lambda: _core.FreeBodySolution(ints, w_tup, None)),
        ("  plain_float(t)  (is t a plain finite number)", lambda: _validate.plain_float(T)),
        ("  c.state_at(t)  (binding + core state, two arrays out)", lambda: body._core.state_at(T)),
        ("the general path's pieces, for comparison:", lambda: None),
        ("  FreeBodySolution(float32 array)  (the package's general conversion)",
         lambda: _core.FreeBodySolution(m_arr.astype(np.float32), w_tup, None)),
        ("  as_float_array(list)", lambda: _validate.as_float_array(OMEGA0, "omega0")),
        ("  as_float_array(t)", lambda: _validate.as_float_array(T, "t")),
        ("  c.state(np.array([t]))  (the array entry point)", lambda: body._core.state(np.array([T]))),
        ("  np.all(np.isfinite(array (3,)))", lambda: np.all(np.isfinite(w_arr))),
        ("  np.asarray(list).astype(float64) under np.errstate", lambda: _astype(OMEGA0)),
        ("  np.array(list)", lambda: np.array(OMEGA0)),
    ]
    print("where FreeRigidBody(lists).state(t) goes")
    print(f"  {load()}")
    for name, fn in steps:
        if name.endswith(":"):
            print(f"  {name}")
            continue
        print(f"  {name:<66} {best(fn, 20_000) * 1e6:7.3f} µs")
    print(f"  {load()}")


def _astype(value: Any) -> Any:
    with np.errstate(over="raise"):
        return np.asarray(value).astype(np.float64)


if __name__ == "__main__":
    if "--layers" in sys.argv[1:]:
        layers()
    else:
        calls()
