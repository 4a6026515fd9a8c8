"""The one place poinsot's plots reach matplotlib (the optional ``plot`` extra)."""

from __future__ import annotations

from pathlib import Path
from typing import Any


def pyplot() -> Any:
    """``matplotlib.pyplot``, imported on first use, or an ImportError saying how to install it."""
    try:
        import matplotlib.pyplot as plt
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise ImportError("poinsot's plots need matplotlib: pip install 'poinsot[plot]'") from exc
    return plt


def save_animation(anim: Any, path: str | Path, fps: int) -> None:
    """Writes a matplotlib animation to ``path``: a ``.gif`` through Pillow (always available),
    any other suffix (``.mp4``) through ffmpeg, which must then be installed."""
    from matplotlib import animation

    path = Path(path)
    if path.suffix.lower() == ".gif":
        writer: Any = animation.PillowWriter(fps=fps)
    else:
        writer = animation.FFMpegWriter(fps=fps)
    anim.save(str(path), writer=writer)
