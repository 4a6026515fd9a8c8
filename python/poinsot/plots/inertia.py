"""Pictures of poinsot's results (matplotlib, the optional ``plot`` extra).

Every function returns a :class:`matplotlib.figure.Figure` (or draws into the axes it is
given) and never calls ``plt.show()``: save it with ``fig.savefig(...)`` or show it yourself.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from ._mpl import pyplot as _pyplot

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

    from ..body import RigidBody


def plot_inertia_ellipsoid(
    body: RigidBody, ax: Any = None, *, title: str | None = None, resolution: int = 40
) -> Figure:
    """Draw the inertia ellipsoid of ``body`` with its principal axes.

    The inertia ellipsoid (Poinsot's ellipsoid) is the surface x·I·x = 1 about the centre of
    mass: its semi-axes lie along the principal axes and have lengths 1/√Iᵢ, so the longest
    semi-axis belongs to the smallest moment. It is drawn scaled so that the longest finite
    semi-axis has length 1; a zero principal moment (a rotor, a thin rod) has an infinite
    semi-axis, drawn cut at 3 and labelled ∞.

    Parameters
    ----------
    body:
        A :class:`poinsot.RigidBody`.
    ax:
        A 3-D matplotlib axes to draw into (``projection="3d"``); a new figure if None.
    title:
        The axes title (default: the body's kind).
    resolution:
        Number of mesh lines in each direction of the surface.

    Returns
    -------
    matplotlib.figure.Figure
        The figure drawn into.
    """
    plt = _pyplot()
    if ax is None:
        fig = plt.figure(figsize=(6, 6))
        ax = fig.add_subplot(projection="3d")
    else:
        fig = ax.figure
    moments = np.asarray(body.principal_moments, dtype=float)
    axes = np.asarray(body.principal_axes, dtype=float)
    scale = float(np.max(moments)) if np.max(moments) > 0 else 1.0
    tiny = 1e-12 * scale
    finite = moments > tiny
    semi = np.where(finite, 1.0 / np.sqrt(np.where(finite, moments, 1.0)), np.inf)
    longest = float(np.max(semi[finite])) if np.any(finite) else 1.0
    semi = np.where(finite, semi / longest, 3.0)

    u = np.linspace(0.0, 2.0 * np.pi, resolution)
    v = np.linspace(0.0, np.pi, resolution)
    local = np.stack(
        [
            np.outer(np.cos(u), np.sin(v)) * semi[0],
            np.outer(np.sin(u), np.sin(v)) * semi[1],
            np.outer(np.ones_like(u), np.cos(v)) * semi[2],
        ]
    )
    xyz = np.einsum("ij,jkl->ikl", axes, local)
    ax.plot_surface(
        xyz[0], xyz[1], xyz[2], color="tab:blue", alpha=0.25, linewidth=0.3, edgecolor="tab:blue"
    )
    colors = ("tab:red", "tab:green", "tab:purple")
    for i in range(3):
        tip = axes[:, i] * semi[i] * 1.15
        ax.quiver(0, 0, 0, *tip, color=colors[i], linewidth=2, arrow_length_ratio=0.08)
        label = f"e{i + 1}: I={moments[i]:.4g}" + ("" if finite[i] else " (∞ semi-axis)")
        ax.text(*(tip * 1.08), label, color=colors[i])
    lim = float(np.max(semi)) * 1.2
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.set_zlim(-lim, lim)
    ax.set_box_aspect((1, 1, 1))
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    ax.set_title(title if title is not None else f"inertia ellipsoid: {body.kind}")
    return fig


__all__ = ["plot_inertia_ellipsoid"]
