"""Small drawing helpers shared by the plot modules (no physics: layout only)."""

from __future__ import annotations

from typing import Any

import numpy as np


def few_ticks(ax: Any, n: int = 5) -> None:
    """At most ``n`` major ticks on every axis of ``ax`` (2-D or 3-D) at round values, so
    that their labels do not run together in either style. In 3-D the axis labels are set
    off from the tick labels by one and a half tick-label heights (matplotlib's pad does not
    grow with the text) and not turned by matplotlib (see :func:`label_3d`)."""
    from matplotlib import rcParams
    from matplotlib.font_manager import FontProperties
    from matplotlib.ticker import MaxNLocator

    three_d = hasattr(ax, "zaxis")
    size = FontProperties(size=rcParams["xtick.labelsize"]).get_size_in_points()
    for axis in (ax.xaxis, ax.yaxis, *((ax.zaxis,) if three_d else ())):
        axis.set_major_locator(MaxNLocator(nbins=n, steps=[1, 2, 2.5, 5, 10]))
        if three_d:
            axis.set_rotate_label(False)
            axis.labelpad = 1.5 * size


def legend_below(ax: Any, ncol: int, drop: float) -> None:
    """The legend of ``ax`` in ``ncol`` columns, centred under the axes with its top ``drop``
    (a fraction of the axes' height) below their bottom edge, clear of the x label."""
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -drop), ncol=ncol, borderaxespad=0.0)


def label_3d(ax: Any, x: str, y: str, z: str) -> None:
    """The axis labels of a 3-D axes: x and y upright, z upright too when short, else
    turned to read upwards along the axis (matplotlib's own turn may set it upside down)."""
    ax.set(xlabel=x, ylabel=y)
    ax.set_zlabel(z, rotation=90 if len(z) > 8 else 0)


def cube_limits(ax: Any, points: Any, pad: float = 0.05, zoom: float = 0.9) -> None:
    """Equal-scale limits of a 3-D axes that just hold ``points`` (..., 3), with ``pad``
    (a fraction of the largest extent) on each side; the box is a cube drawn at ``zoom`` of
    the axes' area (below 1 it leaves room for the axis labels, which constrained layout
    does not measure exactly in 3-D)."""
    p = np.asarray(points, dtype=float).reshape(-1, 3)
    p = p[np.all(np.isfinite(p), axis=1)]
    lo, hi = p.min(axis=0), p.max(axis=0)
    centre = 0.5 * (lo + hi)
    half = 0.5 * float(np.max(hi - lo))
    half = half * (1.0 + 2.0 * pad) if half > 0 else 1.0
    ax.set_xlim(centre[0] - half, centre[0] + half)
    ax.set_ylim(centre[1] - half, centre[1] + half)
    ax.set_zlim(centre[2] - half, centre[2] + half)
    ax.set_box_aspect((1, 1, 1), zoom=zoom)
