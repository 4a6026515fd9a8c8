"""Pictures of the heavy symmetric top (matplotlib, the optional ``plot`` extra).

Every function returns a :class:`matplotlib.figure.Figure` (or an animation) and never calls
``plt.show()``. The physics comes from :class:`poinsot.HeavyTop`; these functions only draw.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from ..top import HeavyTop
from ._mpl import pyplot as _pyplot
from ._mpl import save_animation

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


def plot_effective_potential(top: HeavyTop, ax: Any = None, *, samples: int = 600) -> Figure:
    """The effective potential V(theta) (2.110) with the line E' (2.109) and the turning points
    theta1, theta2 where they meet (Fig. 2.15 of the unit)."""
    plt = _pyplot()
    fig, ax = (ax.figure, ax) if ax is not None else plt.subplots(figsize=(6, 4))
    t1, t2 = top.turning_points
    lo, hi = max(1e-3, t1 - 0.6 * (t2 - t1) - 0.3), min(np.pi - 1e-3, t2 + 0.6 * (t2 - t1) + 0.3)
    theta = np.linspace(lo, hi, samples)
    v = top.effective_potential(theta)
    ep = top.reduced_energy
    ax.plot(theta, v, label="V(θ)  (2.110)")
    ax.axhline(ep, color="C1", lw=1, label="E′  (2.109)")
    ax.plot([t1, t2], [ep, ep], "o", color="C3", label=f"θ₁ = {t1:.4g}, θ₂ = {t2:.4g} rad")
    span = max(ep - np.min(v), 1e-12)
    ax.set_ylim(np.min(v) - 0.5 * span, ep + 2.0 * span)
    ax.set_xlabel("θ (rad)")
    ax.set_ylabel("energy (J)")
    ax.set_title(f"effective potential: {top.motion_class}")
    ax.legend(fontsize=8)
    return fig


def plot_axis_locus(
    top: HeavyTop, ax: Any = None, *, periods: float = 3.0, samples: int = 3000
) -> Figure:
    """The path of the symmetry axis on the unit sphere seen from above the pivot (waves, loops
    or cusps between the circles theta1 and theta2), by orthographic projection onto the XY plane
    (points of the lower hemisphere drawn dashed)."""
    plt = _pyplot()
    fig, ax = (ax.figure, ax) if ax is not None else plt.subplots(figsize=(5, 5))
    t = np.linspace(0.0, _periods(top, periods), samples)
    n = top.symmetry_axis(t)
    upper = n[:, 2] >= 0
    x, y = n[:, 0], n[:, 1]
    ax.plot(
        np.where(upper, x, np.nan),
        np.where(upper, y, np.nan),
        lw=1.2,
        label="axis (upper hemisphere)",
    )
    if not np.all(upper):
        ax.plot(
            np.where(~upper, x, np.nan),
            np.where(~upper, y, np.nan),
            "--",
            lw=1.0,
            label="axis (lower hemisphere)",
        )
    a = np.linspace(0, 2 * np.pi, 361)
    for th, name in zip(top.turning_points, ("θ₁", "θ₂")):
        ax.plot(np.sin(th) * np.cos(a), np.sin(th) * np.sin(a), ":", lw=0.8, color="gray")
        ax.annotate(
            name, (np.sin(th) / np.sqrt(2), -np.sin(th) / np.sqrt(2)), fontsize=8, color="gray"
        )
    ax.plot(np.cos(a), np.sin(a), color="k", lw=0.6)
    ax.plot([x[0]], [y[0]], "o", ms=4, color="C3", label="t = 0")
    ax.set_aspect("equal")
    ax.set_xlabel("X")
    ax.set_ylabel("Y")
    ax.set_title(f"locus of the symmetry axis: {top.motion_class}")
    ax.legend(fontsize=8, loc="upper right")
    return fig


def plot_angles(top: HeavyTop, *, periods: float = 3.0, samples: int = 2000) -> Figure:
    """theta(t), phi'(t) and psi'(t) from the exact solution, with the turning points and the
    mean rates marked."""
    plt = _pyplot()
    t = np.linspace(0.0, _periods(top, periods), samples)
    _, theta, _ = top.euler_angles(t)
    phid, _, psid = top.euler_rates(t)
    fig, axes = plt.subplots(3, 1, figsize=(7, 7), sharex=True)
    axes[0].plot(t, theta)
    for th in top.turning_points:
        axes[0].axhline(th, ls=":", color="gray", lw=0.8)
    axes[0].set_ylabel("θ (rad)")
    axes[1].plot(t, phid)
    axes[1].axhline(top.mean_precession_rate, ls="--", color="C1", lw=0.8, label="mean")
    axes[1].axhline(0.0, color="k", lw=0.5)
    axes[1].set_ylabel("φ̇ (rad/s)")
    axes[1].legend(fontsize=8)
    axes[2].plot(t, psid)
    axes[2].axhline(top.mean_spin_rate, ls="--", color="C1", lw=0.8, label="mean")
    axes[2].set_ylabel("ψ̇ (rad/s)")
    axes[2].set_xlabel("t (s)")
    axes[2].legend(fontsize=8)
    axes[0].set_title(
        f"exact motion ({top.motion_class}, nutation period {top.nutation_period:.4g} s)"
    )
    fig.tight_layout()
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
) -> Figure:
    """The two exact steady-precession rates at ``theta0`` (rad) against the spin omega3, beside
    the fast-top approximations 2.120 (corrected) and 2.121, with the minimum spin 2.119 marked.
    Below the horizontal (theta0 > pi/2) every spin has a slow and a (negative) fast rate."""
    plt = _pyplot()
    fig, ax = (ax.figure, ax) if ax is not None else plt.subplots(figsize=(6, 4))
    w_min = HeavyTop.min_spin(I1, I3, mgl, theta0)
    top_spin = max_spin if max_spin is not None else max(6.0 * w_min, 1.0)
    spins = np.linspace(w_min * (1 + 1e-9) if w_min > 0 else top_spin / samples, top_spin, samples)
    rates = [HeavyTop.steady_precession(I1, I3, mgl, theta0, w) for w in spins]
    slow = np.array([r.slow for r in rates])
    fast = np.array([r.fast for r in rates])
    ax.plot(spins, fast, color="C0", label="fast (exact, 2.116)")
    ax.plot(spins, slow, color="C1", label="slow (exact, 2.116)")
    ax.plot(
        spins,
        [r.fast_approx for r in rates],
        "--",
        color="C0",
        lw=0.8,
        label="p_ψ/(I₁ cos θ₀)  (2.120, corrected)",
    )
    ax.plot(
        spins, [r.slow_approx for r in rates], "--", color="C1", lw=0.8, label="mgl/p_ψ  (2.121)"
    )
    if w_min > 0:
        ax.axvline(w_min, color="C3", lw=0.8, label=f"minimum spin {w_min:.4g} rad/s (2.119)")
    finite = np.concatenate([slow[np.isfinite(slow)], fast[np.isfinite(fast)]])
    if finite.size:
        lo, hi = np.min(finite), np.max(finite)
        ax.set_ylim(min(lo, 0.0) - 0.05 * (hi - lo), hi + 0.05 * (hi - lo))
    ax.set_xlabel("spin ω₃ (rad/s)")
    ax.set_ylabel("precession rate φ̇ (rad/s)")
    ax.set_title(f"steady precession at θ₀ = {theta0:.4g} rad")
    ax.legend(fontsize=8)
    return fig


def animate_top(
    top: HeavyTop,
    path: str | Path | None = None,
    *,
    periods: float = 2.0,
    frames: int = 150,
    fps: int = 25,
    trail: int = 60,
) -> Any:
    """An animation of the top in 3-D: its symmetry axis (a stick from the pivot, with a disk
    drawn at the centre of mass carrying a mark that shows the spin) and the trail of the axis'
    tip. Saved to ``path`` if given (``.gif`` with Pillow, ``.mp4`` with ffmpeg); returns the
    :class:`matplotlib.animation.FuncAnimation`."""
    plt = _pyplot()
    from matplotlib import animation

    t = np.linspace(0.0, _periods(top, periods), frames)
    rot = top.attitude(t)
    tip = rot[:, :, 2]
    a = np.linspace(0, 2 * np.pi, 40)
    ring_body = 0.35 * np.stack([np.cos(a), np.sin(a), np.zeros_like(a)], axis=1) + np.array(
        [0, 0, 0.8]
    )
    mark_body = np.array([[0, 0, 0.8], [0.35, 0, 0.8]])
    fig = plt.figure(figsize=(5, 5))
    ax = fig.add_subplot(projection="3d")
    ax.set_xlim(-1, 1)
    ax.set_ylim(-1, 1)
    ax.set_zlim(-1, 1)
    ax.set_xlabel("X")
    ax.set_ylabel("Y")
    ax.set_zlabel("Z")
    (stick,) = ax.plot([], [], [], lw=2, color="k")
    (ring,) = ax.plot([], [], [], lw=1.5, color="C0")
    (mark,) = ax.plot([], [], [], lw=2, color="C3")
    (trail_line,) = ax.plot([], [], [], lw=0.8, color="C1", alpha=0.7)
    text = ax.text2D(0.02, 0.95, "", transform=ax.transAxes, fontsize=9)

    def update(k: int) -> tuple[Any, ...]:
        r = rot[k]
        stick.set_data_3d([0, tip[k, 0]], [0, tip[k, 1]], [0, tip[k, 2]])
        rb = ring_body @ r.T
        ring.set_data_3d(rb[:, 0], rb[:, 1], rb[:, 2])
        mb = mark_body @ r.T
        mark.set_data_3d(mb[:, 0], mb[:, 1], mb[:, 2])
        lo = max(0, k - trail)
        trail_line.set_data_3d(tip[lo : k + 1, 0], tip[lo : k + 1, 1], tip[lo : k + 1, 2])
        text.set_text(f"t = {t[k]:.2f} s  ({top.motion_class})")
        return stick, ring, mark, trail_line, text

    anim = animation.FuncAnimation(fig, update, frames=len(t), interval=1000 / fps, blit=False)
    if path is not None:
        save_animation(anim, path, fps)
    return anim


def save_top_plots(top: HeavyTop, directory: str | Path, *, animation: bool = False) -> list[Path]:
    """Saves the four pictures of ``top`` (and, with ``animation``, ``top.gif``) into
    ``directory`` (created if needed); returns the paths written."""
    plt = _pyplot()
    d = Path(directory)
    d.mkdir(parents=True, exist_ok=True)
    theta0 = top.initial_state["theta"]
    figures = {
        "potential.png": plot_effective_potential(top),
        "axis_locus.png": plot_axis_locus(top),
        "angles.png": plot_angles(top),
        "steady_precession.png": plot_steady_precession(
            top.I1, top.I3, top.mgl, theta0 if 0.0 < theta0 < np.pi else 0.5
        ),
    }
    paths = []
    for name, fig in figures.items():
        p = d / name
        fig.savefig(p, dpi=110, bbox_inches="tight")
        plt.close(fig)
        paths.append(p)
    if animation:
        p = d / "top.gif"
        anim = animate_top(top, p)
        plt.close(anim._fig)
        paths.append(p)
    return paths
