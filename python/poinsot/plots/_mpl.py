"""The one place poinsot's plots reach matplotlib (the optional ``plot`` extra)."""

from __future__ import annotations

from typing import Any


def pyplot() -> Any:
    """``matplotlib.pyplot``, imported on first use, or an ImportError saying how to install it."""
    try:
        import matplotlib.pyplot as plt
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise ImportError("poinsot's plots need matplotlib: pip install 'poinsot[plot]'") from exc
    return plt
