"""The child program of the Ctrl-C tests (``test_limits.py``, ``test_interrupt_arrays.py``) and
of ``bench/ctrl_c_latency.py``: one call run in a fresh interpreter that sends itself SIGINT
0.5 s in, as a terminal does on Ctrl-C, and prints how long ``KeyboardInterrupt`` took to
arrive (``INTERRUPTED s``) or how long the call ran without seeing it (``FINISHED s``).
"""

from __future__ import annotations

import subprocess
import sys
import textwrap

_CHILD = """
import os, signal, sys, threading, time
import numpy as np
import poinsot as ps
# Python raises KeyboardInterrupt on SIGINT only if SIGINT was not ignored when it started (a
# background job of a non-interactive shell inherits SIG_IGN): install the handler explicitly.
signal.signal(signal.SIGINT, signal.default_int_handler)
{setup}
sent = []
def fire():
    time.sleep(0.5)
    sent.append(time.perf_counter())
    os.kill(os.getpid(), signal.SIGINT)
start = time.perf_counter()
threading.Thread(target=fire, daemon=True).start()
try:
    {call}
except KeyboardInterrupt:
    print("INTERRUPTED", time.perf_counter() - sent[0])
else:
    print("FINISHED", time.perf_counter() - start)
"""


def child(setup: str, call: str) -> str:
    """The child program: ``setup`` (not timed), then ``call``, interrupted 0.5 s in."""
    return textwrap.dedent(_CHILD).replace("{setup}", setup).replace("{call}", call)


def interrupt(setup: str, call: str, *, timeout: float) -> tuple[str, float]:
    """Run ``call`` in a child interrupted 0.5 s in: ``("INTERRUPTED", s from SIGINT to
    KeyboardInterrupt)`` or ``("FINISHED", s the call ran)``. A child that fails otherwise
    raises ``RuntimeError`` with its stderr."""
    proc = subprocess.run(
        [sys.executable, "-c", child(setup, call)],
        capture_output=True,
        text=True,
        timeout=timeout,
    )
    if proc.returncode != 0:
        raise RuntimeError(proc.stderr[-2000:])
    word, seconds = proc.stdout.split()
    return word, float(seconds)
