"""How long each derivation of poinsot.derive takes to build and check (issue 14: under 2 s
each on the project's 2-core machine), and errata() on top of them.

Each derivation is built in a fresh interpreter (``python -X importtime`` is not needed: the
import of sympy and of the module is timed apart from ``derive()``), three times, best kept.

    .venv/bin/python bench/derive_times.py
"""

from __future__ import annotations

import json
import subprocess
import sys

CHILD = r"""
import json, sys, time
t0 = time.perf_counter()
import sympy  # noqa: F401
from poinsot import derive
t1 = time.perf_counter()
name = sys.argv[1]
if name == "errata()":
    for n in derive.names():
        derive.derivation(n)
    t2 = time.perf_counter()
    derive.errata()
else:
    t2 = time.perf_counter()
    derive._module(name).derive()  # the module's import (its models, PRINTED) counts too
t3 = time.perf_counter()
print(json.dumps({"import": t1 - t0, "work": t3 - t2}))
"""


def main() -> None:
    from poinsot import derive

    rows = []
    for name in [*derive.names(), "errata()"]:
        runs = []
        for _ in range(3):
            out = subprocess.run(
                [sys.executable, "-c", CHILD, name], capture_output=True, text=True, check=True
            )
            runs.append(json.loads(out.stdout))
        best = min(runs, key=lambda r: r["work"])
        rows.append((name, best["work"], best["import"]))
    print(f"{'derivation':<18} {'build + check (s)':>18} {'import (s)':>11}")
    for name, work, imp in rows:
        flag = "" if work < 2.0 or name == "errata()" else "   over 2 s"
        print(f"{name:<18} {work:>18.3f} {imp:>11.3f}{flag}")


if __name__ == "__main__":
    main()
