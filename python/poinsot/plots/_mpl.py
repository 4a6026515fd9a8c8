"""The one place poinsot's plots reach matplotlib (the optional ``plot`` extra), and the two
figure styles every plot function takes.

``style="paper"`` (the default) suits a page or a notebook: 10 pt text, 150 dpi.
``style="slides"`` suits a projector: 16 pt text, thick lines, 200 dpi. Both use constrained
layout, so titles and labels are kept inside the figure.
"""

from __future__ import annotations

import shutil
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from functools import cache
from pathlib import Path
from typing import Any

from .._validate import as_choice

#: The names accepted by every plot function's ``style`` argument.
STYLES: tuple[str, ...] = ("paper", "slides")

# matplotlib rcParams of each style (read by every text, line and figure created inside
# ``figure_style``). Sizes in points; dpi in dots per inch.
_RC: dict[str, dict[str, Any]] = {
    "paper": {
        "figure.dpi": 100,
        "savefig.dpi": 150,
        "font.size": 10,
        "axes.titlesize": 11,
        "axes.labelsize": 10,
        "xtick.labelsize": 9,
        "ytick.labelsize": 9,
        "legend.fontsize": 9,
        "lines.linewidth": 1.5,
        "figure.constrained_layout.use": True,
    },
    "slides": {
        "figure.dpi": 100,
        "savefig.dpi": 200,
        "font.size": 16,
        "axes.titlesize": 18,
        "axes.labelsize": 16,
        "xtick.labelsize": 14,
        "ytick.labelsize": 14,
        "legend.fontsize": 13,
        "lines.linewidth": 3.0,
        "lines.markersize": 9,
        "axes.linewidth": 1.5,
        "xtick.major.width": 1.5,
        "ytick.major.width": 1.5,
        "grid.linewidth": 1.0,
        "figure.constrained_layout.use": True,
    },
}

# How much larger (width and height) a slides figure is than the paper figure of the same plot:
# the text grows 1.6×, so the canvas grows too, or the axes would shrink to make room.
_SCALE = {"paper": 1.0, "slides": 1.6}


def pyplot() -> Any:
    """``matplotlib.pyplot``, imported on first use, or an ImportError saying how to install it."""
    try:
        import matplotlib.pyplot as plt
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise ImportError("poinsot's plots need matplotlib: pip install 'poinsot[plot]'") from exc
    return plt


def func_animation(fig: Any, update: Any, frames: int, fps: float) -> Any:
    """The animation of ``frames`` frames at ``fps`` frames per second drawn by
    ``update(k)`` (returning the artists it changed, blitted) on ``fig``, its first frame
    drawn now: a ``matplotlib.animation.FuncAnimation`` that also plays inline in Jupyter (its
    ``_repr_html_`` is an HTML5 video where ffmpeg is installed, else JavaScript frames,
    ``to_jshtml``, no external tool; matplotlib's own returns nothing by default)."""
    update(0)
    return _inline_animation_class()(fig, update, frames=frames, interval=1000 / fps, blit=True)


@cache
def _inline_animation_class() -> Any:
    from matplotlib.animation import FuncAnimation

    class InlineAnimation(FuncAnimation):  # type: ignore[misc]
        """A FuncAnimation that displays itself in a notebook (see :func:`func_animation`)."""

        def _repr_html_(self) -> str:
            if shutil.which("ffmpeg"):
                return str(self.to_html5_video())
            return str(self.to_jshtml())

    return InlineAnimation


def line_width() -> float:
    """The current style's line width (points)."""
    from matplotlib import rcParams

    return float(rcParams["lines.linewidth"])


def check_style(style: Any) -> str:
    """``style`` as one of :data:`STYLES`; :class:`poinsot.PoinsotError` naming ``style``
    otherwise."""
    return as_choice(style, "style", STYLES)


@contextmanager
def figure_style(style: Any) -> Iterator[str]:
    """Draw inside this context to get the look of ``style`` (``"paper"`` or ``"slides"``);
    yields the checked name. Everything created inside (figures, lines, text) takes the
    style's sizes; a figure keeps them after the context ends, and its ``savefig`` dpi is
    stored on it (see :func:`figsize`)."""
    name = check_style(style)
    plt = pyplot()
    with plt.rc_context(_RC[name]):
        yield name


def figsize(style: str, width: float, height: float) -> tuple[float, float]:
    """The size (inches) of a figure drawn ``width × height`` in the paper style, in ``style``."""
    k = _SCALE[check_style(style)]
    return (width * k, height * k)


def savefig_dpi(style: str) -> float:
    """The resolution (dots per inch) at which figures of ``style`` are saved."""
    return float(_RC[check_style(style)]["savefig.dpi"])


def new_figure(style: str, width: float, height: float, **kwargs: Any) -> Any:
    """A new figure for ``style`` of paper size ``width × height`` inches (call inside
    :func:`figure_style`). Its ``savefig`` writes at the style's dpi even after the context
    ends (matplotlib reads ``savefig.dpi`` at save time, so it is kept on the figure)."""
    plt = pyplot()
    fig = plt.figure(figsize=figsize(style, width, height), **kwargs)
    _keep_dpi(fig, savefig_dpi(style))
    return fig


def subplots(style: str, width: float, height: float, *args: Any, **kwargs: Any) -> Any:
    """``plt.subplots(*args, **kwargs)`` for ``style`` of paper size ``width × height``
    (call inside :func:`figure_style`); returns ``(fig, axes)`` as matplotlib does."""
    plt = pyplot()
    fig, axes = plt.subplots(*args, figsize=figsize(style, width, height), **kwargs)
    _keep_dpi(fig, savefig_dpi(style))
    return fig, axes


def _keep_dpi(fig: Any, dpi: float) -> None:
    """Make ``fig.savefig`` default to ``dpi`` (an explicit ``dpi=`` still wins)."""
    original = fig.savefig

    def savefig(*args: Any, **kwargs: Any) -> Any:
        kwargs.setdefault("dpi", dpi)
        return original(*args, **kwargs)

    fig.savefig = savefig


def save_animation(
    anim: Any,
    path: str | Path,
    fps: int,
    dpi: float | None = None,
    progress: Callable[[int, int], Any] | None = None,
) -> None:
    """Writes a matplotlib animation to ``path``: a ``.gif`` through Pillow (always available),
    any other suffix (``.mp4``) through ffmpeg, which must then be installed. ``progress``, if
    given, is called as ``progress(frame, frames)`` after each frame is written (as
    matplotlib's ``progress_callback``). ``dpi``: the figure's own by default.

    A GIF of a blitting :class:`~matplotlib.animation.FuncAnimation` (``blit=True``: its
    function returns the artists it changes) is drawn by blitting: the still parts once, then
    only the moving artists on top of them, frame by frame — several times faster than
    matplotlib's saving loop, which redraws the whole figure twice a frame. Any other
    animation goes through ``anim.save``, drawn once a frame (the redraw for a screen is
    skipped)."""
    from matplotlib import animation

    path = Path(path)
    if path.suffix.lower() == ".gif" and getattr(anim, "_blit", False) and hasattr(anim, "_func"):
        _save_gif_blitting(anim, path, fps, dpi, progress)
        return
    if path.suffix.lower() == ".gif":
        writer: Any = animation.PillowWriter(fps=fps)
    else:
        writer = animation.FFMpegWriter(fps=fps)
    canvas = anim._fig.canvas
    canvas.draw_idle = lambda *args, **kwargs: None
    try:
        anim.save(str(path), writer=writer, dpi=dpi, progress_callback=progress)
    finally:
        del canvas.draw_idle  # back to the class' method


def _save_gif_blitting(
    anim: Any,
    path: Path,
    fps: int,
    dpi: float | None,
    progress: Callable[[int, int], Any] | None,
) -> None:
    """The frames of a blitting FuncAnimation drawn by blitting, written as a GIF by Pillow
    (as matplotlib's PillowWriter writes them, each opaque frame with its own 256 colours)."""
    import numpy as np
    from PIL import Image

    fig = anim._fig
    canvas = fig.canvas
    frames = list(anim.new_saved_frame_seq())
    moving = list(anim._func(frames[0], *anim._args))
    old_dpi = fig.dpi
    images = []
    try:
        if dpi is not None:
            fig.set_dpi(dpi)
        for artist in moving:
            artist.set_animated(True)
        canvas.draw()  # everything that does not move, once
        still = canvas.copy_from_bbox(fig.bbox)
        for i, frame in enumerate(frames):
            canvas.restore_region(still)
            for artist in anim._func(frame, *anim._args):
                if hasattr(artist, "do_3d_projection"):  # a 3-D collection sorts its faces
                    artist.do_3d_projection()
                fig.draw_artist(artist)
            rgba = np.array(canvas.buffer_rgba())
            im = Image.fromarray(rgba, "RGBA")
            if rgba[..., 3].min() == 255:
                # opaque: to a palette by the fast octree (Pillow's default median cut
                # takes ten times as long as drawing the frame)
                im = im.convert("RGB").quantize(256, method=Image.Quantize.FASTOCTREE)
            images.append(im)
            if progress is not None:
                progress(i, len(frames))
    finally:
        for artist in moving:
            artist.set_animated(False)
        fig.set_dpi(old_dpi)
    images[0].save(
        str(path), save_all=True, append_images=images[1:], duration=int(1000 / fps), loop=0
    )
