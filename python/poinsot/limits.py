"""Limits on the work one call may ask for, checked before any work starts (issue 10).

* The **memory budget**: the largest output, in bytes, that one call may allocate — the arrays
  it returns (samples of a trajectory, a polhode, parcels × samples of a flow). Default 4 GiB
  (:data:`DEFAULT_MEMORY_BUDGET`). A request beyond it raises :class:`PoinsotError` naming the
  argument and saying how many bytes it would need::

      >>> import poinsot as ps
      >>> try:
      ...     ps.simulate([1, 2, 3], [0.1, 0.5, 1], 10.0, samples=10**12)
      ... except ps.PoinsotError as err:
      ...     print(str(err)[:60])
      samples: 1000000000000 would need 112000000000000 bytes (112

* The **step limit**: every integrating call takes ``max_steps`` (default 10⁸ for
  :func:`poinsot.simulate`, about a minute of its slowest method); a fixed-step request that
  needs more is refused before the first step, with the number of steps it needs.

Every long run also stops on Ctrl-C (``KeyboardInterrupt``) within a tenth of a second, and
stops when its ``progress`` callback raises.
"""

from __future__ import annotations

from typing import Any

from . import _core
from ._validate import as_count

__all__ = ["memory_budget", "set_memory_budget", "DEFAULT_MEMORY_BUDGET"]

#: The default memory budget of one call's outputs: 4 GiB.
DEFAULT_MEMORY_BUDGET: int = _core.DEFAULT_MEMORY_BUDGET


def memory_budget() -> int:
    """The memory budget (bytes) of one call's outputs."""
    return int(_core.memory_budget())


def set_memory_budget(bytes: Any) -> int:
    """Set the memory budget (bytes, ≥ 1 MiB) of every later call in this process; returns the
    previous budget, so that ``old = set_memory_budget(n); ...; set_memory_budget(old)``
    restores it."""
    return int(_core.set_memory_budget(as_count(bytes, "bytes", 1)))
