"""Measuring a drawn matplotlib figure: text that leaves the figure, tick labels that collide,
axes without units. Used by the plot tests of every module (``layout_problems(fig)`` returns
a list of sentences, empty when the figure is clean)."""

from __future__ import annotations

import re
from typing import Any

# A text may overhang the figure's edge by this many pixels (antialiasing of the glyphs'
# bounding boxes) before it counts as cut off.
EDGE_TOLERANCE_PX = 1.0
# Two tick labels of one axis whose boxes overlap by more than this many pixels (in both
# directions) collide; touching boxes (0 px) do not.
OVERLAP_TOLERANCE_PX = 0.5

_UNIT = re.compile(r"\(([^()]*)\)\s*$|\[[^\[\]]+\]\s*$")


def _draw(fig: Any) -> dict[int, Any]:
    """Draws ``fig`` and returns the window extent (pixels) of each text matplotlib drew, by
    the text's id, measured as it is drawn: an axis also keeps labelled ticks beyond its ends
    that it does not draw (no part of the picture), and a 3-D text is at its projected place
    only while it is drawn."""
    from matplotlib.text import Text

    drawn: dict[int, Any] = {}
    original = Text.draw

    def draw(self: Any, renderer: Any) -> Any:
        if self.get_visible() and self.get_text().strip():
            drawn[id(self)] = self.get_window_extent(renderer)
        return original(self, renderer)

    Text.draw = draw  # type: ignore[method-assign]
    try:
        fig.canvas.draw()
    finally:
        Text.draw = original  # type: ignore[method-assign]
    return drawn


def _visible_texts(fig: Any, drawn: dict[int, Any]) -> list[Any]:
    from matplotlib.text import Text

    out = []
    for t in fig.findobj(Text):
        if not t.get_visible() or not t.get_text().strip() or id(t) not in drawn:
            continue
        if t.axes is not None and not t.axes.get_visible():
            continue
        out.append(t)
    return out


def _name(ax: Any) -> str:
    """The first line of an axes' title, to name it in a message."""
    lines = ax.get_title().splitlines()
    return lines[0] if lines else ""


def _owners(fig: Any) -> dict[int, Any]:
    """The axes each text of an axes belongs to, by the text's id: its title, axis labels,
    tick labels, legend and texts (the other texts belong to the figure)."""
    from matplotlib.text import Text

    out: dict[int, Any] = {}
    for ax in fig.axes:
        for t in ax.findobj(Text):
            out[id(t)] = ax
    return out


def _says(ax: Any) -> str:
    """What a text belongs to, for a message: an axes (by title) or the figure."""
    return f"axes {_name(ax)!r}" if ax is not None else "the figure"


def _overlap(a: Any, b: Any) -> bool:
    w = min(a.x1, b.x1) - max(a.x0, b.x0)
    h = min(a.y1, b.y1) - max(a.y0, b.y0)
    return w > OVERLAP_TOLERANCE_PX and h > OVERLAP_TOLERANCE_PX


def layout_problems(fig: Any) -> list[str]:
    """Draws ``fig`` and lists every text outside the figure, every two texts of different
    axes (or of an axes and the figure) that overlap — a label running into the next panel
    —, every pair of overlapping tick labels on one axis and every axis label overlapping its
    axis' tick labels (as sentences naming the text)."""
    drawn = _draw(fig)
    box = fig.bbox
    problems = []
    free = []  # the texts not clipped to an axes
    for t in _visible_texts(fig, drawn):
        if t.get_clip_on() and t.axes is not None and t.get_clip_box() is not None:
            # Clipped to its axes (annotations inside a plot): only the axes must fit.
            continue
        free.append(t)
        e = drawn[id(t)]
        if (
            e.x0 < box.x0 - EDGE_TOLERANCE_PX
            or e.y0 < box.y0 - EDGE_TOLERANCE_PX
            or e.x1 > box.x1 + EDGE_TOLERANCE_PX
            or e.y1 > box.y1 + EDGE_TOLERANCE_PX
        ):
            problems.append(
                f"text {t.get_text()!r} leaves the figure "
                f"({e.x0:.0f}..{e.x1:.0f} × {e.y0:.0f}..{e.y1:.0f} px in "
                f"{box.x1:.0f} × {box.y1:.0f})"
            )
    owner = _owners(fig)
    for i, a in enumerate(free):
        for b in free[i + 1 :]:
            oa, ob = owner.get(id(a)), owner.get(id(b))
            if oa is not ob and _overlap(drawn[id(a)], drawn[id(b)]):
                problems.append(
                    f"texts {a.get_text()!r} ({_says(oa)}) and {b.get_text()!r} ({_says(ob)}) "
                    "overlap"
                )
    for ax in fig.axes:
        if not ax.get_visible():
            continue
        axes = [ax.xaxis, ax.yaxis] + ([ax.zaxis] if hasattr(ax, "zaxis") else [])
        for axis in axes:
            labels = [
                lab
                for lab in axis.get_ticklabels()
                if lab.get_visible() and lab.get_text().strip() and id(lab) in drawn
            ]
            extents = [drawn[id(lab)] for lab in labels]
            title = axis.label
            if id(title) in drawn:
                for lab, ext in zip(labels, extents):
                    if _overlap(drawn[id(title)], ext):
                        problems.append(
                            f"axis label {title.get_text()!r} overlaps tick label "
                            f"{lab.get_text()!r} on the {axis.axis_name}-axis of {_name(ax)!r}"
                        )
            for i in range(len(labels)):
                for j in range(i + 1, len(labels)):
                    if _overlap(extents[i], extents[j]):
                        problems.append(
                            f"tick labels {labels[i].get_text()!r} and {labels[j].get_text()!r} "
                            f"overlap on the {axis.axis_name}-axis of {_name(ax)!r}"
                        )
    return problems


def axes_without_units(fig: Any) -> list[str]:
    """Every visible axis (x, y, z of each axes that shows ticks) whose label does not end in
    a unit in parentheses or brackets: ``"t (s)"``, ``"θ (rad)"``, ``"x / L (1)"``."""
    out = []
    for ax in fig.axes:
        # a 3-D axes keeps ``axison`` False and says whether it shows its axes in _axis3don
        shown = ax._axis3don if hasattr(ax, "zaxis") else ax.axison
        if not ax.get_visible() or not shown:
            continue
        axes = [ax.xaxis, ax.yaxis] + ([ax.zaxis] if hasattr(ax, "zaxis") else [])
        for axis in axes:
            if not axis.get_visible() or not [t for t in axis.get_ticklabels() if t.get_text()]:
                continue
            label = axis.get_label_text()
            if not _UNIT.search(label):
                out.append(f"{axis.axis_name}-axis of {_name(ax)!r}: label {label!r}")
    return out
