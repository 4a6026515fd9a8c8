"""Pictures of the heavy symmetric top (matplotlib, the optional ``plot`` extra).

The physics comes from :class:`poinsot.HeavyTop`; these functions only draw (see
:mod:`poinsot.plots`).
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from ..top import HeavyTop
from ._axes import cube_limits, few_ticks, label_3d, legend_below
from ._mpl import (
    check_style,
    figure_style,
    func_animation,
    line_width,
    new_figure,
    save_animation,
    subplots,
)
from ._mpl import pyplot as _pyplot

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

__all__ = [
    "plot_effective_potential",
    "plot_axis_locus",
    "plot_angles",
    "plot_steady_precession",
    "animate_top",
    "save_top_plots",
]


def _periods(top: HeavyTop, periods: float, fallback: float = 10.0) -> float:
    p = top.nutation_period
    return periods * p if np.isfinite(p) else fallback


def plot_effective_potential(
    top: HeavyTop, ax: Any = None, *, samples: int = 600, style: str = "paper"
) -> Figure:
    """The effective potential V(θ) (J, 2.110) against θ (rad) with the line E′ (2.109) and
    the turning points θ₁, θ₂ where they meet (Fig. 2.15 of the unit). ``style``:
    ``"paper"`` (default) or ``"slides"``."""
    with figure_style(style) as style:
        fig, ax = (ax.figure, ax) if ax is not None else subplots(style, 6.0, 4.0)
        t1, t2 = top.turning_points
        lo = max(1e-3, t1 - 0.6 * (t2 - t1) - 0.3)
        hi = min(np.pi - 1e-3, t2 + 0.6 * (t2 - t1) + 0.3)
        theta = np.linspace(lo, hi, samples)
        v = top.effective_potential(theta)
        ep = top.reduced_energy
        ax.plot(theta, v, label="V(θ)  (2.110)")
        ax.axhline(ep, color="C1", lw=0.6 * line_width(), label="E′  (2.109)")
        ax.plot([t1, t2], [ep, ep], "o", color="C3", label=f"θ₁ = {t1:.4g}, θ₂ = {t2:.4g} rad")
        span = max(ep - np.min(v), 1e-12)
        ax.set_ylim(np.min(v) - 0.5 * span, ep + 2.0 * span)
        few_ticks(ax, 6)
        ax.set(
            xlabel="θ (rad)", ylabel="energy (J)", title=f"effective potential: {top.motion_class}"
        )
        ax.legend(loc="upper center")
    return fig


def plot_axis_locus(
    top: HeavyTop,
    ax: Any = None,
    *,
    periods: float = 3.0,
    samples: int = 3000,
    style: str = "paper",
) -> Figure:
    """The path of the symmetry axis on the unit sphere seen from above the pivot (waves, loops
    or cusps between the circles θ₁ and θ₂, 2.110–2.114), by orthographic projection onto the
    XY plane (points of the lower hemisphere drawn dashed), over ``periods`` nutation periods.
    ``style``: ``"paper"`` (default) or ``"slides"``."""
    with figure_style(style) as style:
        fig, ax = (ax.figure, ax) if ax is not None else subplots(style, 5.0, 6.0)
        t = np.linspace(0.0, _periods(top, periods), samples)
        n = top.symmetry_axis(t)
        upper = n[:, 2] >= 0
        x, y = n[:, 0], n[:, 1]
        ax.plot(
            np.where(upper, x, np.nan),
            np.where(upper, y, np.nan),
            label="axis, upper hemisphere",
        )
        if not np.all(upper):
            ax.plot(
                np.where(~upper, x, np.nan),
                np.where(~upper, y, np.nan),
                "--",
                label="axis, lower hemisphere",
            )
        a = np.linspace(0, 2 * np.pi, 361)
        t1, t2 = top.turning_points
        circles = [(t1, ":", f"θ₁ = {t1:.4g} rad")]
        if not np.isclose(t1, t2, rtol=0.0, atol=1e-9):
            circles.append((t2, "--", f"θ₂ = {t2:.4g} rad"))
        for th, ls, name in circles:
            ax.plot(
                np.sin(th) * np.cos(a),
                np.sin(th) * np.sin(a),
                ls,
                color="0.45",
                lw=0.5 * line_width(),
                label=name,
            )
        ax.plot(np.cos(a), np.sin(a), color="k", lw=0.4 * line_width())
        ax.plot([x[0]], [y[0]], "o", color="C3", label="t = 0")
        ax.set_aspect("equal")
        ax.set_xlim(-1.05, 1.05)
        ax.set_ylim(-1.05, 1.05)
        ax.set_xticks([-1.0, -0.5, 0.0, 0.5, 1.0])
        ax.set_yticks([-1.0, -0.5, 0.0, 0.5, 1.0])
        ax.set(xlabel="X of the axis (1)", ylabel="Y of the axis (1)")
        ax.set_title(f"axis seen from above: {top.motion_class}")
        legend_below(ax, ncol=2, drop=0.14)
    return fig


def plot_angles(
    top: HeavyTop, *, periods: float = 3.0, samples: int = 2000, style: str = "paper"
) -> Figure:
    """θ(t) (rad), φ̇(t) and ψ̇(t) (rad/s) against t (s) from the exact solution (2.112 and
    2.106), with the turning points and the mean rates marked. ``style``: ``"paper"``
    (default) or ``"slides"``."""
    with figure_style(style) as style:
        t = np.linspace(0.0, _periods(top, periods), samples)
        _, theta, _ = top.euler_angles(t)
        phid, _, psid = top.euler_rates(t)
        fig, axes = subplots(style, 7.0, 7.0, 3, 1, sharex=True)
        axes[0].plot(t, theta)
        for th in top.turning_points:
            axes[0].axhline(th, ls=":", color="gray", lw=0.5 * line_width())
        axes[0].set_ylabel("θ (rad)")
        axes[1].plot(t, phid)
        axes[1].axhline(
            top.mean_precession_rate, ls="--", color="C1", lw=0.6 * line_width(), label="mean"
        )
        axes[1].axhline(0.0, color="k", lw=0.3 * line_width())
        axes[1].set_ylabel("φ̇ (rad/s)")
        axes[1].legend(loc="best")
        axes[2].plot(t, psid)
        axes[2].axhline(
            top.mean_spin_rate, ls="--", color="C1", lw=0.6 * line_width(), label="mean"
        )
        axes[2].set_ylabel("ψ̇ (rad/s)")
        axes[2].set_xlabel("t (s)")
        axes[2].legend(loc="best")
        for ax in axes:
            few_ticks(ax, 6)
        axes[0].set_title(
            f"exact motion: {top.motion_class}, nutation period {top.nutation_period:.4g} s"
        )
    return fig


def plot_steady_precession(
    I1: float,
    I3: float,
    mgl: float,
    theta0: float,
    ax: Any = None,
    *,
    max_spin: float | None = None,
    samples: int = 400,
    style: str = "paper",
) -> Figure:
    """The two exact steady-precession rates φ̇ (rad/s) at ``theta0`` (rad) against the spin
    ω₃ (rad/s), beside the fast-top approximations 2.120 (corrected) and 2.121, with the
    minimum spin 2.119 marked. Below the horizontal (θ₀ > π/2) every spin has a slow and a
    (negative) fast rate. ``style``: ``"paper"`` (default) or ``"slides"``."""
    with figure_style(style) as style:
        fig, ax = (ax.figure, ax) if ax is not None else subplots(style, 6.5, 5.5)
        w_min = HeavyTop.min_spin(I1, I3, mgl, theta0)
        top_spin = max_spin if max_spin is not None else max(6.0 * w_min, 1.0)
        start = w_min * (1 + 1e-9) if w_min > 0 else top_spin / samples
        spins = np.linspace(start, top_spin, samples)
        rates = [HeavyTop.steady_precession(I1, I3, mgl, theta0, w) for w in spins]
        slow = np.array([r.slow for r in rates])
        fast = np.array([r.fast for r in rates])
        thin = 0.5 * line_width()
        ax.plot(spins, fast, color="C0", label="fast (exact, 2.116)")
        ax.plot(spins, slow, color="C1", label="slow (exact, 2.116)")
        # The fast-top approximations, dashed in their exact rate's colour.
        for approx, colour, label in (
            ("fast_approx", "C0", "p_ψ/(I₁ cos θ₀)  (2.120, corrected)"),
            ("slow_approx", "C1", "mgl/p_ψ  (2.121)"),
        ):
            values = [getattr(r, approx) for r in rates]
            ax.plot(spins, values, "--", color=colour, lw=thin, label=label)
        if w_min > 0:
            ax.axvline(w_min, color="C3", lw=thin, label=f"minimum spin {w_min:.4g} rad/s (2.119)")
        finite = np.concatenate([slow[np.isfinite(slow)], fast[np.isfinite(fast)]])
        if finite.size:
            lo, hi = np.min(finite), np.max(finite)
            ax.set_ylim(min(lo, 0.0) - 0.05 * (hi - lo), hi + 0.05 * (hi - lo))
        few_ticks(ax, 6)
        ax.set(xlabel="spin ω₃ (rad/s)", ylabel="precession rate φ̇ (rad/s)")
        ax.set_title(f"steady precession at θ₀ = {theta0:.4g} rad")
        legend_below(ax, ncol=1, drop=0.16)
    return fig


def animate_top(
    top: HeavyTop,
    path: str | Path | None = None,
    *,
    periods: float = 2.0,
    frames: int = 120,
    fps: int = 24,
    trail: int = 60,
    style: str = "paper",
    progress: Callable[[int, int], Any] | None = None,
) -> Any:
    """An animation of the heavy top in 3-D over ``periods`` nutation periods: its symmetry
    axis (a stick of unit length from the pivot), a disk at 0.8 of it carrying a mark that
    shows the spin ψ, the trail of the axis' tip, and the circles θ₁ and θ₂ between which
    the tip nutates (2.110–2.114); the view is fitted to the top.

    Saved to ``path`` if given (``.gif`` with Pillow, ``.mp4`` with ffmpeg), calling
    ``progress(frame, frames)`` after each frame written; returns the
    :class:`matplotlib.animation.FuncAnimation` (its figure is ``anim._fig``). ``style``:
    ``"paper"`` (default) or ``"slides"``."""

    with figure_style(style) as style:
        t = np.linspace(0.0, _periods(top, periods), frames)
        rot = top.attitude(t)
        tip = rot[:, :, 2]
        a = np.linspace(0, 2 * np.pi, 40)
        ring_body = 0.35 * np.stack([np.cos(a), np.sin(a), np.zeros_like(a)], axis=1) + np.array(
            [0, 0, 0.8]
        )
        mark_body = np.array([[0, 0, 0.8], [0.35, 0, 0.8]])
        rings = np.einsum("kij,nj->kni", rot, ring_body)
        t1, t2 = top.turning_points
        circle = np.stack([np.cos(a), np.sin(a)], axis=1)
        fig = new_figure(style, 6.0, 6.5)
        ax = fig.add_subplot(projection="3d")
        ax.plot(
            [0, 0],
            [0, 0],
            [0, 1.0],
            color="0.5",
            ls="--",
            lw=0.4 * line_width(),
            label="vertical Z",
        )
        bands = []
        for th, ls in ((t1, ":"), (t2, "-.")):
            xy = np.sin(th) * circle
            bands.append(np.column_stack([xy, np.full(len(a), np.cos(th))]))
            ax.plot(*bands[-1].T, ls, color="0.45", lw=0.5 * line_width())
        ax.plot([], [], ":", color="0.45", label=f"circles θ₁ = {t1:.3g}, θ₂ = {t2:.3g} rad")
        (stick,) = ax.plot([], [], [], color="k", label="symmetry axis")
        (ring,) = ax.plot([], [], [], color="C0", label="disk")
        (mark,) = ax.plot([], [], [], color="C3", label="mark: the spin ψ")
        (trail_line,) = ax.plot(
            [], [], [], lw=0.5 * line_width(), color="C1", label="path of the tip"
        )
        ax.plot([0], [0], [0], "o", color="k", ms=4)
        cube_limits(
            ax, np.concatenate([rings.reshape(-1, 3), tip, *bands, np.zeros((1, 3))]), zoom=0.85
        )
        few_ticks(ax, 4)
        label_3d(ax, "X (1)", "Y (1)", "Z (1)")
        fig.legend(loc="outside lower center", ncol=2)
        ax.set_title(f"heavy top: {top.motion_class}")
        text = ax.text2D(0.98, 0.02, "", transform=ax.transAxes, ha="right")

        def update(k: int) -> tuple[Any, ...]:
            r = rot[k]
            stick.set_data_3d([0, tip[k, 0]], [0, tip[k, 1]], [0, tip[k, 2]])
            ring.set_data_3d(rings[k, :, 0], rings[k, :, 1], rings[k, :, 2])
            mb = mark_body @ r.T
            mark.set_data_3d(mb[:, 0], mb[:, 1], mb[:, 2])
            lo = max(0, k - trail)
            trail_line.set_data_3d(tip[lo : k + 1, 0], tip[lo : k + 1, 1], tip[lo : k + 1, 2])
            text.set_text(f"t = {t[k]:.2f} s")
            return stick, ring, mark, trail_line, text

        anim = func_animation(fig, update, len(t), fps)
    if path is not None:
        save_animation(anim, path, fps, progress=progress)
    return anim


def save_top_plots(
    top: HeavyTop,
    directory: str | Path,
    *,
    animation: bool = False,
    style: str = "paper",
    progress: Callable[[int, int], Any] | None = None,
) -> list[Path]:
    """Saves the four pictures of ``top`` (``potential.png``, ``axis_locus.png``,
    ``angles.png``, ``steady_precession.png``) and, with ``animation``, ``top.gif`` into
    ``directory`` (created if needed) in ``style``; returns the paths written. ``progress``,
    if given, is called as ``progress(done, total)`` after each picture and each frame of the
    animation."""
    plt = _pyplot()
    check_style(style)
    d = Path(directory)
    d.mkdir(parents=True, exist_ok=True)
    theta0 = top.initial_state["theta"]
    figures = {
        "potential.png": lambda: plot_effective_potential(top, style=style),
        "axis_locus.png": lambda: plot_axis_locus(top, style=style),
        "angles.png": lambda: plot_angles(top, style=style),
        "steady_precession.png": lambda: plot_steady_precession(
            top.I1, top.I3, top.mgl, theta0 if 0.0 < theta0 < np.pi else 0.5, style=style
        ),
    }
    frames = 120
    total = len(figures) + (frames if animation else 0)
    paths = []
    for i, (name, draw) in enumerate(figures.items(), start=1):
        fig = draw()
        p = d / name
        fig.savefig(p)
        plt.close(fig)
        paths.append(p)
        if progress is not None:
            progress(i, total)
    if animation:
        p = d / "top.gif"
        done = len(figures)

        def frame_done(k: int, _n: int) -> None:
            if progress is not None:
                progress(done + k + 1, total)

        anim = animate_top(top, p, frames=frames, style=style, progress=frame_done)
        plt.close(anim._fig)
        paths.append(p)
    return paths
