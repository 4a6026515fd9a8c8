"""Run every peer-comparison script in bench/ (each prints its own times and ratios), and the
batch kernels against their single-body peers (batch_kernels.py)."""

from __future__ import annotations

import runpy
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent

if __name__ == "__main__":
    for script in [*sorted(HERE.glob("*_vs_*.py")), HERE / "batch_kernels.py"]:
        print(f"== {script.name}", flush=True)
        sys.argv = [str(script)]
        runpy.run_path(str(script), run_name="__main__")
