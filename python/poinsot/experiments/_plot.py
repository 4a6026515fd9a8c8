"""The picture of an experiment: the measurement with its uncertainty beside poinsot's
prediction and the closed form, on the quantity's own axis (a sense: two turning arrows)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from ..plots._mpl import figure_style, line_width, subplots
from ._result import AGREE_RELATIVE, AGREE_SIGMA, ExperimentResult

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["plot"]


def plot(result: ExperimentResult, *, style: str = "paper", ax: Any = None) -> Figure:
    """Measured (with bars at 1 σ and :data:`AGREE_SIGMA` σ of its stated uncertainty) against
    poinsot's prediction and the closed form, along the quantity's axis in ``result.unit``; for a
    sense, the measured and the predicted sense of turning as arrows. ``result``: an
    :class:`ExperimentResult`; ``style``: ``"paper"`` or ``"slides"``, as the other plots;
    ``ax``: matplotlib axes to draw into instead of a new figure. Returns the matplotlib figure
    (the quantities on its axis in ``result.unit``)."""
    with figure_style(style) as style:
        if ax is None:
            fig, ax = subplots(style, 4.5 if result.is_sense else 7.0, 2.4)
        else:
            fig = ax.figure
        if result.is_sense:
            _senses(ax, result)
        else:
            _numbers(ax, result)
        ax.set_title(f"{result.title} ({result.year})")
    return fig


def _numbers(ax: Any, r: ExperimentResult) -> None:
    m = float(r.measured.magnitude)
    p = float(r.predicted.magnitude)
    lw = line_width()
    values = [m, p]
    if r.uncertainty is not None:
        u = float(r.uncertainty.magnitude)
        ax.errorbar(
            [m],
            [2],
            xerr=[[AGREE_SIGMA * u], [AGREE_SIGMA * u]],
            fmt="none",
            ecolor="0.6",
            elinewidth=3 * lw,
            capsize=0,
            label=f"{AGREE_SIGMA:g} σ",
        )
        ax.errorbar(
            [m],
            [2],
            xerr=[[u], [u]],
            fmt="o",
            color="C0",
            elinewidth=2 * lw,
            capsize=4,
            label=f"measured ± 1 σ ({r.uncertainty_kind})",
        )
        values += [m - AGREE_SIGMA * u, m + AGREE_SIGMA * u]
    else:
        # no uncertainty stated: the band of agreement is ±AGREE_RELATIVE about the prediction
        band = AGREE_RELATIVE * abs(p)
        ax.errorbar(
            [p], [1], xerr=[[band], [band]], fmt="none", ecolor="0.6", elinewidth=3 * lw,
            capsize=0,
        )  # fmt: skip
        ax.plot([m], [2], "o", color="C0", label="measured (no uncertainty stated)")
        values += [p - band, p + band]
    ax.plot([p], [1], "D", color="C1", label="poinsot")
    if r.closed_form is not None:
        c = float(r.closed_form.magnitude)
        ax.plot([c], [0], "s", color="C2", label="closed form")
        values.append(c)
    lo, hi = float(np.min(values)), float(np.max(values))
    pad = 0.15 * (hi - lo or abs(hi) or 1.0)
    ax.set_xlim(lo - pad, hi + pad)
    ax.set_ylim(-0.5, 2.9)
    ax.set_yticks([])
    if r.uncertainty is not None:
        measured = f"measured {r.shown_measured()} (bar: 1 σ, grey: {AGREE_SIGMA:g} σ)"
        predicted = f"poinsot {r.shown('predicted')}"
    else:
        measured = f"measured {r.shown_measured()} (no uncertainty stated)"
        pct = f"{100 * AGREE_RELATIVE:g} %"
        predicted = f"poinsot {r.shown('predicted')} (grey: ± {pct}, the band of agreement)"
    rows = [(2, measured), (1, predicted)]
    if r.closed_form is not None:
        rows.append((0, f"closed form {r.shown('closed_form')}"))
    for y, text in rows:
        ax.text(0.01, y + 0.28, text, transform=ax.get_yaxis_transform(), va="bottom")
    ax.set_xlabel(f"{r.quantity} ({r.unit_symbol})")
    ax.grid(axis="x", color="0.85", lw=0.5 * lw)


def _senses(ax: Any, r: ExperimentResult) -> None:
    from matplotlib.patches import FancyArrowPatch

    for x, label, word in ((0.0, "measured", r.measured), (3.4, "poinsot", r.predicted)):
        turn = -1.0 if "anti" in str(word) or "counter" in str(word) else 1.0
        t = np.linspace(0.3, 2 * np.pi - 0.3, 60) * (-turn)
        ax.plot(x + np.cos(t[:-1]), np.sin(t[:-1]), color="C0", lw=2 * line_width())
        ax.add_patch(
            FancyArrowPatch(
                (x + np.cos(t[-2]), np.sin(t[-2])),
                (x + np.cos(t[-1]), np.sin(t[-1])),
                arrowstyle="-|>",
                mutation_scale=18,
                color="C0",
            )
        )
        ax.text(x, -1.3, f"{label}\n{word}", ha="center", va="top")
    ax.set_xlim(-1.9, 5.3)
    ax.set_ylim(-2.3, 1.3)
    ax.set_aspect("equal")
    ax.set_axis_off()
