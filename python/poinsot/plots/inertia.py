"""Pictures of poinsot's results (matplotlib, the optional ``plot`` extra).

Every function returns a :class:`matplotlib.figure.Figure` (or draws into the axes it is
given) and never calls ``plt.show()``: save it with ``fig.savefig(...)`` or show it yourself.
"""

from __future__ import annotations

import textwrap
from typing import TYPE_CHECKING, Any

import numpy as np

from ._axes import cube_limits, few_ticks, label_3d
from ._mpl import figure_style, new_figure

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

    from ..body import RigidBody


def plot_inertia_ellipsoid(
    body: RigidBody,
    ax: Any = None,
    *,
    title: str | None = None,
    resolution: int = 40,
    name: str | None = None,
    style: str = "paper",
) -> Figure:
    """Draw the inertia ellipsoid of ``body`` with its principal axes.

    The inertia ellipsoid (Poinsot's ellipsoid, the unit's eqs. 2.63–2.66) is the surface
    ρ·I·ρ = 1 about the centre of mass, in the body's reference axes: its semi-axes lie along
    the principal axes e₁, e₂, e₃ and have lengths 1/√Iᵢ (kg^-½·m^-1), so the longest
    semi-axis belongs to the smallest moment. A zero principal moment (a rotor, a thin rod)
    has an infinite semi-axis, drawn cut at three times the longest finite one and marked ∞.

    Parameters
    ----------
    body:
        A :class:`poinsot.RigidBody`.
    ax:
        A 3-D matplotlib axes to draw into (``projection="3d"``); a new figure if None.
    title:
        The whole axes title, replacing the default (which says what is drawn, names the
        body and gives its principal moments in kg·m²).
    resolution:
        Number of mesh lines in each direction of the surface.
    name:
        What the body is, for the default title (for example ``"cuboid 1 × 2 × 3 m, 2 kg"``;
        default: its kind, ``"asymmetric top"``).
    style:
        ``"paper"`` (default) or ``"slides"`` (larger text and lines, saved at 200 dpi).

    Returns
    -------
    matplotlib.figure.Figure
        The figure drawn into.
    """
    with figure_style(style) as style:
        if ax is None:
            fig = new_figure(style, 6.0, 6.0)
            ax = fig.add_subplot(projection="3d")
        else:
            fig = ax.figure
        moments = np.asarray(body.principal_moments, dtype=float)
        axes = np.asarray(body.principal_axes, dtype=float)
        scale = float(np.max(moments)) if np.max(moments) > 0 else 1.0
        finite = moments > 1e-12 * scale
        semi = np.where(finite, 1.0 / np.sqrt(np.where(finite, moments, 1.0)), np.inf)
        longest = float(np.max(semi[finite])) if np.any(finite) else 1.0
        semi = np.where(finite, semi, 3.0 * longest)

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
            xyz[0], xyz[1], xyz[2], color="tab:blue", alpha=0.2, linewidth=0.3, edgecolor="tab:blue"
        )
        colors = ("tab:red", "tab:green", "tab:purple")
        for i in range(3):
            tip = axes[:, i] * semi[i] * 1.2
            ax.plot(*np.stack([-tip, tip], axis=1), color=colors[i], lw=0.8, ls=":")
            ax.quiver(0, 0, 0, *tip, color=colors[i], arrow_length_ratio=0.1)
            label = f"e{'₁₂₃'[i]}" + ("" if finite[i] else " (∞)")
            ax.text(*(tip * 1.08), label, color=colors[i], fontweight="bold")
        cube_limits(ax, np.concatenate([xyz.reshape(3, -1).T, (axes * semi * 1.3).T]))
        few_ticks(ax, 4)
        unit = r"$\mathrm{kg^{-1/2}\,m^{-1}}$"
        label_3d(ax, f"x ({unit})", f"y ({unit})", f"z ({unit})")
        if title is None:
            shown = ", ".join(f"{m:.4g}" for m in moments)
            what = textwrap.fill(f"inertia ellipsoid ρ·I·ρ = 1 of the {name or body.kind}", 50)
            kind = f"{body.kind}: " if name else ""
            title = f"{what}\n{kind}I₁, I₂, I₃ = {shown} kg·m²"
        ax.set_title(title)
    return fig


__all__ = ["plot_inertia_ellipsoid"]
