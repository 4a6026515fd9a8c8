"""Ctrl-C latency of the evaluators over a user's array (issue 21, item 4).

Each call runs in a child process that sends itself SIGINT 0.5 s into the call; the time from
the signal to ``KeyboardInterrupt`` is measured, median over ``--tries`` runs. The calls and
their sizes are python/tests/_array_calls.py's (the same as test_interrupt_arrays.py), plus the
evaluators too fast per element to keep busy for seconds (``FAST_CALLS`` and the rotation
conversions: their latency is bounded by the call's own time). ``RigidBody.from_mesh`` is one of
the array calls (a UV sphere of 5.2 M faces).

    .venv/bin/python bench/ctrl_c_latency.py [--tries 3] [--only NAME ...]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import textwrap
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "python" / "tests"))
from _array_calls import ARRAY_CALLS, FAST_CALLS, ROTATION_CALLS
from _interrupt import interrupt

def latency(setup: str, call: str) -> tuple[str, float]:
    return interrupt(setup, call, timeout=600)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tries", type=int, default=3)
    parser.add_argument(
        "--only", nargs="*", default=None, help="run the calls named so (substrings)"
    )
    args = parser.parse_args()
    calls = {**ARRAY_CALLS, **FAST_CALLS, **ROTATION_CALLS}
    print("| call | Ctrl-C latency, median (ms) | runs interrupted |")
    print("|---|---|---|")
    for name, (setup, call) in calls.items():
        if args.only is not None and not any(o in name for o in args.only):
            continue
        runs = [latency(textwrap.dedent(setup), call) for _ in range(args.tries)]
        hit = [s for w, s in runs if w == "INTERRUPTED"]
        med = f"{1e3 * statistics.median(hit):.0f}" if hit else "—"
        print(f"| {name}: `{call}` | {med} | {len(hit)}/{len(runs)} |", flush=True)


if __name__ == "__main__":
    main()
