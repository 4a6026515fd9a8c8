"""Pictures of the rotating Earth's effects (matplotlib, the optional ``plot`` extra).

Every function returns a :class:`matplotlib.figure.Figure` (or an animation) and never calls
``plt.show()``. The physics comes from :class:`poinsot.Earth`; these functions only draw.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from ..earth import Earth, Fall, Flight, FoucaultRun
from ._mpl import pyplot as _pyplot
from ._mpl import save_animation

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

__all__ = [
    "plot_deflection",
    "plot_trajectory",
    "plot_foucault_rosette",
    "plot_inertial_circles",
    "animate_foucault",
]


def plot_deflection(
    earth: Earth | None = None, *, height: float = 100.0, latitude: float = 45.0, n: int = 19
) -> Figure:
    """The eastward deflection of a dropped body: against latitude (at ``height`` m) and against
    height (at ``latitude`` degrees), the unit's first-order eq. 2.42 beside the exact fall in
    the rotating frame, with the exact southward deflection on a second axis.

    Parameters
    ----------
    earth:
        The Earth (default :class:`poinsot.Earth`).
    height:
        Drop height (m) of the latitude panel.
    latitude:
        Latitude (degrees) of the height panel.
    n:
        Number of points per curve.
    """
    plt = _pyplot()
    earth = earth or Earth()
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    lats = np.linspace(-90.0, 90.0, n)
    first = earth.eastward_deflection(height, lats, degrees=True)
    exact = np.array([earth.drop(height, la, degrees=True) for la in lats], dtype=object)
    ax1.plot(lats, first * 100, "-", label="first order (2.42)")
    ax1.plot(lats, [f.east * 100 for f in exact], "o", ms=4, label="exact, east")
    ax1.plot(lats, [-f.north * 1e5 for f in exact], "s", ms=3, label="exact, south (×1000)")
    ax1.set_xlabel("latitude (°)")
    ax1.set_ylabel("deflection (cm)")
    ax1.set_title(f"drop from {height:g} m")
    ax1.axhline(0, color="0.7", lw=0.8)
    ax1.legend(fontsize=8)
    heights = np.logspace(0, 4, n)
    first_h = earth.eastward_deflection(heights, latitude, degrees=True)
    exact_h = [earth.drop(h, latitude, degrees=True) for h in heights]
    ax2.loglog(heights, first_h, "-", label="east, first order (2.42)")
    ax2.loglog(heights, [f.east for f in exact_h], "o", ms=4, label="east, exact")
    ax2.loglog(
        heights,
        earth.southward_deflection(heights, latitude, degrees=True),
        "--",
        label="south, ¾ω² sin2λ h²/g",
    )
    ax2.loglog(heights, [-f.north for f in exact_h], "s", ms=3, label="south, exact")
    ax2.set_xlabel("height (m)")
    ax2.set_ylabel("deflection (m)")
    ax2.set_title(f"latitude {latitude:g}°")
    ax2.legend(fontsize=8)
    fig.tight_layout()
    return fig


def plot_trajectory(result: Fall | Flight, ax: Any = None, *, title: str | None = None) -> Figure:
    """A fall or a flight in ENU: east and north displacement against height (for a fall, whose
    sideways motion is tiny) or a 3-D track (for a flight)."""
    plt = _pyplot()
    pos = result.position
    if isinstance(result, Fall):
        if ax is None:
            fig, ax = plt.subplots(figsize=(5, 5))
        else:
            fig = ax.figure
        ax.plot(pos[:, 0] * 100, pos[:, 2], label="east (cm)")
        ax.plot(pos[:, 1] * 1e4, pos[:, 2], label="north (×0.01 cm)")
        ax.set_xlabel("horizontal displacement")
        ax.set_ylabel("height (m)")
        ax.legend()
        ax.set_title(title or f"fall: {result.east * 100:.3f} cm east in {result.time:.3f} s")
        return fig
    if ax is None:
        fig = plt.figure(figsize=(6, 5))
        ax = fig.add_subplot(projection="3d")
    else:
        fig = ax.figure
    ax.plot(pos[:, 0], pos[:, 1], pos[:, 2])
    ax.set_xlabel("east (m)")
    ax.set_ylabel("north (m)")
    ax.set_zlabel("up (m)")
    ax.set_title(title or f"flight: range {result.range:.1f} m, drift {result.drift:+.2f} m")
    return fig


def plot_foucault_rosette(run: FoucaultRun, ax: Any = None, *, title: str | None = None) -> Figure:
    """The bob's track seen from above (the rosette), with the swing plane at the first and
    the last turning point."""
    plt = _pyplot()
    if ax is None:
        fig, ax = plt.subplots(figsize=(5.5, 5.5))
    else:
        fig = ax.figure
    p = run.position
    ax.plot(p[:, 0], p[:, 1], lw=0.5)
    r = np.max(np.hypot(p[:, 0], p[:, 1]))
    for a, style in ((run.turn_angles[0], "k--"), (run.turn_angles[-1], "r--")):
        ax.plot([-r * np.cos(a), r * np.cos(a)], [-r * np.sin(a), r * np.sin(a)], style, lw=1)
    ax.set_aspect("equal")
    ax.set_xlabel("east (m)")
    ax.set_ylabel("north (m)")
    rate = (
        f"{run.precession_rate:.3e} rad/s"
        if run.precession_rate is not None
        else f"no rate ({run.regime})"
    )
    ax.set_title(title or f"Foucault: {run.sense}, {rate} (−ω sin λ = {run.expected_rate:.3e})")
    return fig


def plot_inertial_circles(
    earth: Earth | None = None,
    *,
    latitudes: tuple[float, ...] = (45.0, -45.0, 0.0),
    speed: float = 10.0,
) -> Figure:
    """Inertial oscillations started eastward at ``speed`` m/s at each latitude (degrees): clockwise
    circles in the north, counterclockwise in the south, a straight line at the equator (over
    two inertial periods, or one day at the equator)."""
    plt = _pyplot()
    earth = earth or Earth()
    fig, ax = plt.subplots(figsize=(6, 5))
    for lat in latitudes:
        osc = earth.inertial_oscillation(lat, [speed, 0.0], degrees=True)
        x, y = osc.position[:, 0] / 1e3, osc.position[:, 1] / 1e3
        (line,) = ax.plot(x, y, label=f"{lat:+g}°: {osc.sense}")
        ax.annotate(
            "",
            xy=(x[5], y[5]),
            xytext=(x[0], y[0]),
            arrowprops={"arrowstyle": "->", "color": line.get_color()},
        )
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("east (km)")
    ax.set_ylabel("north (km)")
    ax.set_title("inertial oscillations (Coriolis force only)")
    ax.legend(fontsize=8)
    return fig


def animate_foucault(
    run: FoucaultRun,
    path: str | Path | None = None,
    *,
    frames: int = 200,
    fps: int = 25,
    trail: int = 40,
) -> Any:
    """An animation of the Foucault pendulum seen from above: the bob with a fading trail and the
    current swing plane. Saved to ``path`` if given (``.gif`` with Pillow, ``.mp4`` with
    ffmpeg); returns the :class:`matplotlib.animation.FuncAnimation`.

    ``run`` should be sampled densely enough (``samples``) to show the swing: ``frames`` frames
    are taken evenly from its samples.
    """
    plt = _pyplot()
    from matplotlib import animation

    p = run.position
    idx = np.linspace(0, len(p) - 1, min(frames, len(p))).astype(int)
    r = np.max(np.hypot(p[:, 0], p[:, 1])) * 1.1
    fig, ax = plt.subplots(figsize=(5, 5))
    ax.set_xlim(-r, r)
    ax.set_ylim(-r, r)
    ax.set_aspect("equal")
    ax.set_xlabel("east (m)")
    ax.set_ylabel("north (m)")
    (tr,) = ax.plot([], [], lw=0.8, alpha=0.6)
    (bob,) = ax.plot([], [], "o", ms=8)
    text = ax.text(0.02, 0.96, "", transform=ax.transAxes, va="top", fontsize=9)

    def update(k: int) -> tuple[Any, ...]:
        i = idx[k]
        lo = idx[max(0, k - trail)]
        tr.set_data(p[lo : i + 1, 0], p[lo : i + 1, 1])
        bob.set_data([p[i, 0]], [p[i, 1]])
        text.set_text(f"t = {run.t[i]:.0f} s")
        return tr, bob, text

    anim = animation.FuncAnimation(fig, update, frames=len(idx), interval=1000 / fps, blit=True)
    if path is not None:
        save_animation(anim, path, fps)
    return anim
