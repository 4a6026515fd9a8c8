"""Pictures of the rotating Earth's effects (matplotlib, the optional ``plot`` extra).

The physics comes from :class:`poinsot.Earth`; these functions only draw (see
:mod:`poinsot.plots`).
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from ..earth import Earth, Fall, Flight, FoucaultRun
from ..rigid_earth import IAU2000A_PRINCIPAL_NUTATION, IAU2006_PRECESSION_RATE, RigidEarth
from ._axes import few_ticks, label_3d
from ._mpl import figure_style, func_animation, line_width, new_figure, save_animation, subplots

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

__all__ = [
    "plot_deflection",
    "plot_trajectory",
    "plot_foucault_rosette",
    "plot_inertial_circles",
    "animate_foucault",
    "plot_rigid_earth",
]


# Units for lengths too small to read in metres: (factor from m, name), largest first.
_LENGTHS = ((1.0, "m"), (1e2, "cm"), (1e3, "mm"), (1e6, "µm"), (1e9, "nm"))


def _length_unit(values: Any) -> tuple[float, str]:
    """The factor (from metres) and the name of the unit in which the largest of ``values``
    (m) reads between 1 and 1000 (or in m when larger, in nm when smaller)."""
    big = float(np.max(np.abs(values))) if np.size(values) else 0.0
    for factor, name in _LENGTHS:
        if big * factor >= 1.0:
            return factor, name
    return _LENGTHS[-1]


def plot_deflection(
    earth: Earth | None = None,
    *,
    height: float = 100.0,
    latitude: float = 45.0,
    n: int = 19,
    style: str = "paper",
) -> Figure:
    """The eastward deflection of a dropped body: against latitude (at ``height`` m) and against
    height (at ``latitude`` degrees), the unit's first-order eq. 2.42 beside the exact fall in
    the rotating frame, with the exact southward deflection too.

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
    style:
        ``"paper"`` (default) or ``"slides"``.
    """
    with figure_style(style) as style:
        earth = earth or Earth()
        fig, (ax1, ax2) = subplots(style, 11.0, 4.6, 1, 2)
        lats = np.linspace(-90.0, 90.0, n)
        first = earth.eastward_deflection(height, lats, degrees=True)
        exact = [earth.drop(height, la, degrees=True) for la in lats]
        ax1.plot(lats, first * 100, "-", label="first order (2.42)")
        ax1.plot(lats, [f.east * 100 for f in exact], "o", label="exact, east")
        ax1.plot(lats, [-f.north * 1e5 for f in exact], "s", label="exact, south (×1000)")
        ax1.set(xlabel="latitude (°)", ylabel="deflection (cm)", title=f"drop from {height:g} m")
        ax1.axhline(0, color="0.7", lw=0.5 * line_width())
        ax1.set_xticks([-90, -45, 0, 45, 90])
        ax1.legend(loc="best")
        heights = np.logspace(0, 4, n)
        first_h = earth.eastward_deflection(heights, latitude, degrees=True)
        exact_h = [earth.drop(h, latitude, degrees=True) for h in heights]
        ax2.loglog(heights, first_h, "-", label="east, first order (2.42)")
        ax2.loglog(heights, [f.east for f in exact_h], "o", label="east, exact")
        ax2.loglog(
            heights,
            earth.southward_deflection(heights, latitude, degrees=True),
            "--",
            label="south, ¾ω² sin2λ h²/g",
        )
        ax2.loglog(heights, [-f.north for f in exact_h], "s", label="south, exact")
        ax2.set(xlabel="height (m)", ylabel="deflection (m)", title=f"latitude {latitude:g}°")
        ax2.legend(loc="upper left")
    return fig


def plot_trajectory(
    result: Fall | Flight, ax: Any = None, *, title: str | None = None, style: str = "paper"
) -> Figure:
    """A fall or a flight in the local East-North-Up axes (eqs. 2.32–2.42).

    A fall (:class:`poinsot.Fall`) is drawn as two panels against the height (m): the
    eastward displacement beside the unit's first-order landing point (2.42), and the
    southward one beside its second-order value, each in the unit that reads (cm, mm, µm);
    into a given ``ax``, the eastward panel only. A flight (:class:`poinsot.Flight`) is its
    3-D track (m). ``style``: ``"paper"`` (default) or ``"slides"``.
    """
    with figure_style(style) as style:
        pos = result.position
        if isinstance(result, Fall):
            if ax is None:
                fig, (ax, ax_s) = subplots(style, 8.0, 5.0, 1, 2, sharey=True)
            else:
                fig, ax_s = ax.figure, None
            k, unit = _length_unit(np.append(pos[:, 0], result.first_order_east))
            east = f"{result.east * k:.3g} {unit} east in {result.time:.4g} s"
            ax.plot(pos[:, 0] * k, pos[:, 2], label="exact")
            ax.plot(result.first_order_east * k, pos[-1, 2], "o", label="first order (2.42)")
            ax.set(xlabel=f"east ({unit})", ylabel="height (m)")
            ax.legend(loc="upper right")
            few_ticks(ax, 5)
            if ax_s is not None:
                south = -pos[:, 1]
                k, unit = _length_unit(np.append(south, result.second_order_south))
                ax_s.plot(south * k, pos[:, 2], color="C2", label="exact")
                ax_s.plot(
                    result.second_order_south * k,
                    pos[-1, 2],
                    "s",
                    color="C3",
                    label="second order, ¾ω² sin2λ h²/g",
                )
                ax_s.set_xlabel(f"south ({unit})")
                ax_s.legend(loc="upper right")
                few_ticks(ax_s, 5)
                ax_s.set_title("… and a little south")
                ax.set_title("the body lands east …")
                fig.suptitle(title or f"fall from {pos[0, 2]:.4g} m: {east}")
            else:
                ax.set_title(title or f"fall: {east}")
            return fig
        if ax is None:
            fig = new_figure(style, 6.0, 5.5)
            ax = fig.add_subplot(projection="3d")
        else:
            fig = ax.figure
        ax.plot(pos[:, 0], pos[:, 1], pos[:, 2])
        ax.plot(*pos[0], "o", color="C2", label="launch")
        ax.plot(*pos[-1], "s", color="C3", label="landing")
        ax.legend(loc="upper left")
        few_ticks(ax, 4)
        ax.set_box_aspect(None, zoom=0.85)
        label_3d(ax, "east (m)", "north (m)", "up (m)")
        ax.set_title(
            title or f"flight: range {result.range:.4g} m,\ndrift {result.drift:+.3g} m (right +)"
        )
    return fig


def _swing_angles(run: FoucaultRun) -> np.ndarray:
    """The swing plane's direction at the turning points (rad, counterclockwise from east),
    made continuous: the bob's direction there alternates by π between the two ends of the
    swing, and a plane is the same line turned by π."""
    a = np.asarray(run.turn_angles, dtype=float)
    return np.unwrap(2.0 * a) / 2.0


def plot_foucault_rosette(
    run: FoucaultRun, ax: Any = None, *, title: str | None = None, style: str = "paper"
) -> Figure:
    """The Foucault pendulum seen from above (:meth:`poinsot.Earth.foucault`; the unit's
    Fig. 2.5), zoomed to what moves.

    The upper panel is the bob's track in a frame turned so that the first swing runs across
    the figure (equal scales, m): the rosette fills a wide panel instead of a sliver, with the
    swing plane at the first and the last turning point. The lower panel is the angle of the
    swing plane at every turning point against time (°, s), with the measured rate of turn
    (``run.precession_rate``) and the unit's −ω sin λ (``run.expected_rate``) as lines through
    the first turning point. Into a given ``ax``, the track only. ``style``: ``"paper"``
    (default) or ``"slides"``.
    """
    with figure_style(style) as style:
        p = np.asarray(run.position, dtype=float)
        planes = _swing_angles(run)
        r_xy = np.hypot(p[:, 0], p[:, 1])
        a0 = planes[0] if planes.size else float(np.arctan2(*p[np.argmax(r_xy), 1::-1]))
        c, s_ = np.cos(a0), np.sin(a0)
        along = p[:, 0] * c + p[:, 1] * s_
        across = -p[:, 0] * s_ + p[:, 1] * c
        if ax is None:
            # the track's panel as flat as the track (equal scales), within reason
            # (inches of the paper figure: the panels are about 5.5 wide, the lower 3 high)
            flat = np.ptp(across) / max(np.ptp(along), 1e-300)
            high = 5.5 * float(np.clip(1.15 * flat, 0.3, 1.0))
            fig, (ax, ax_t) = subplots(
                style, 8.0, high + 4.5, 2, 1, gridspec_kw={"height_ratios": [high, 3.0]}
            )
        else:
            fig, ax_t = ax.figure, None
        ax.plot(along, across, lw=0.3 * line_width())
        r = float(np.max(r_xy))
        if planes.size:
            for a, ls, color, name in (
                (planes[0], "--", "k", f"swing plane at t = {run.turn_times[0]:.4g} s"),
                (planes[-1], "--", "C3", f"swing plane at t = {run.turn_times[-1]:.4g} s"),
            ):
                d = a - a0
                ax.plot(
                    [-r * np.cos(d), r * np.cos(d)],
                    [-r * np.sin(d), r * np.sin(d)],
                    ls,
                    color=color,
                    lw=0.6 * line_width(),
                    label=name,
                )
            ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0)
        ax.set_aspect("equal", adjustable="datalim")
        few_ticks(ax, 7)
        ax.set(xlabel="along the first swing (m)", ylabel="across it (m)")
        if run.precession_rate is not None:
            turns = f"the swing plane turns {run.sense}"
        else:
            turns = f"no steady turn ({run.regime})"
        ax.set_title(title or f"Foucault pendulum seen from above: {turns}")
        if ax_t is not None:
            t = np.asarray(run.turn_times, dtype=float)
            deg = np.degrees(planes - a0)
            ax_t.plot(t, deg, ".", color="C0", label="turning points")
            if t.size:
                ends = np.array([t[0], t[-1]])
                if run.precession_rate is not None:
                    ax_t.plot(
                        ends,
                        deg[0] + np.degrees(run.precession_rate * (ends - t[0])),
                        color="C3",
                        label=f"measured rate {run.precession_rate:.3e} rad/s",
                    )
                ax_t.plot(
                    ends,
                    deg[0] + np.degrees(run.expected_rate * (ends - t[0])),
                    "--",
                    color="k",
                    lw=0.6 * line_width(),
                    label=f"−ω sin λ = {run.expected_rate:.3e} rad/s",
                )
            ax_t.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0)
            few_ticks(ax_t, 6)
            ax_t.set_xlabel("t (s)")
            ax_t.set_ylabel("swing plane turned (°)")
            ax_t.set_title("the swing plane at the turning points")
    return fig


def plot_inertial_circles(
    earth: Earth | None = None,
    *,
    latitudes: tuple[float, ...] = (45.0, -45.0, 0.0),
    speed: float = 10.0,
    style: str = "paper",
) -> Figure:
    """Inertial oscillations started eastward at ``speed`` m/s at each latitude (degrees):
    clockwise circles in the north, counterclockwise in the south, a straight line at the
    equator (over two inertial periods, or one day at the equator; the unit's Fig. 2.6).
    ``style``: ``"paper"`` (default) or ``"slides"``."""
    with figure_style(style) as style:
        earth = earth or Earth()
        fig, ax = subplots(style, 6.5, 5.0)
        for lat in latitudes:
            osc = earth.inertial_oscillation(lat, [speed, 0.0], degrees=True)
            x, y = osc.position[:, 0] / 1e3, osc.position[:, 1] / 1e3
            (line,) = ax.plot(x, y, label=f"{lat:+g}°: {osc.sense}")
            ax.annotate(
                "",
                xy=(x[5], y[5]),
                xytext=(x[0], y[0]),
                arrowprops={"arrowstyle": "->", "color": line.get_color(), "lw": line_width()},
            )
        ax.set_aspect("equal", adjustable="datalim")
        few_ticks(ax, 6)
        ax.set_xlabel("east (km)")
        ax.set_ylabel("north (km)")
        ax.set_title("inertial oscillations (Coriolis force only)")
        ax.legend(loc="best")
    return fig


def animate_foucault(
    run: FoucaultRun,
    path: str | Path | None = None,
    *,
    frames: int = 200,
    fps: int = 25,
    trail: int = 40,
    style: str = "paper",
    progress: Callable[[int, int], Any] | None = None,
) -> Any:
    """An animation of the Foucault pendulum seen from above: the bob with its recent trail
    and the swing plane at the last turning point passed. Saved to ``path`` if given
    (``.gif`` with Pillow, ``.mp4`` with ffmpeg), calling ``progress(frame, frames)`` after
    each frame written; returns the :class:`matplotlib.animation.FuncAnimation` (its figure is
    ``anim._fig``). ``style``: ``"paper"`` (default) or ``"slides"``.

    ``run`` should be sampled densely enough (``samples``) to show the swing: ``frames`` frames
    are taken evenly from its samples.
    """

    with figure_style(style) as style:
        p = run.position
        idx = np.linspace(0, len(p) - 1, min(frames, len(p))).astype(int)
        r = np.max(np.hypot(p[:, 0], p[:, 1])) * 1.1
        planes = _swing_angles(run)
        turn_times = np.asarray(run.turn_times, dtype=float)
        fig, ax = subplots(style, 5.5, 5.5)
        ax.set_xlim(-r, r)
        ax.set_ylim(-r, r)
        ax.set_aspect("equal")
        few_ticks(ax, 5)
        ax.set_xlabel("east (m)")
        ax.set_ylabel("north (m)")
        ax.set_title(f"Foucault pendulum from above, turning {run.sense}")
        (plane,) = ax.plot([], [], "--", color="C3", lw=0.6 * line_width(), label="swing plane")
        (tr,) = ax.plot([], [], lw=0.5 * line_width(), alpha=0.6)
        (bob,) = ax.plot([], [], "o", color="C0", label="bob")
        ax.legend(loc="upper right")
        text = ax.text(0.02, 0.98, "", transform=ax.transAxes, va="top")

        def update(k: int) -> tuple[Any, ...]:
            i = idx[k]
            lo = idx[max(0, k - trail)]
            tr.set_data(p[lo : i + 1, 0], p[lo : i + 1, 1])
            bob.set_data([p[i, 0]], [p[i, 1]])
            j = int(np.searchsorted(turn_times, run.t[i], side="right")) - 1
            if j >= 0:
                a = planes[j]
                plane.set_data([-r * np.cos(a), r * np.cos(a)], [-r * np.sin(a), r * np.sin(a)])
            text.set_text(f"t = {run.t[i]:.0f} s")
            return plane, tr, bob, text

        anim = func_animation(fig, update, len(idx), fps)
    if path is not None:
        save_animation(anim, path, fps, progress=progress)
    return anim


def plot_rigid_earth(
    earth: RigidEarth | None = None,
    *,
    k2: float = 0.30,
    ks: float = 0.938,
    chandler_observed: tuple[float, float] | None = None,
    style: str = "paper",
) -> Figure:
    """The Earth as a rigid top, two panels. Left: the precession cone — the celestial pole's
    track around the ecliptic pole (a circle of radius ε, degrees), marked every 4000 years
    from J2000 at :attr:`RigidEarth.precession_rate`. Right: each prediction against its
    measured value, (poinsot − measured)/measured in %: the luni-solar precession against
    IAU 2006, the principal nutation (Δψ₀, Δε₀) against IAU 2000A and, when
    ``chandler_observed`` = (period, uncertainty) in days is given, the elastic Chandler period
    for ``k2``, ``ks`` (the rigid model leaves the oceans and the core out: it is expected to
    miss). ``style``: ``"paper"`` (default) or ``"slides"``."""
    with figure_style(style) as style:
        earth = earth or RigidEarth()
        fig, (sky, bars) = subplots(style, 10.0, 4.6, 1, 2, width_ratios=(1.0, 1.15))
        eps = np.degrees(earth.obliquity)
        year = 365.25 * 86_400.0
        full = np.linspace(0, 2 * np.pi, 361)
        sky.plot(eps * np.sin(full), -eps * np.cos(full), lw=line_width())
        sky.plot([0], [0], "k+", ms=10)
        sky.annotate(
            "ecliptic pole",
            (0, 0),
            xytext=(0, 6),
            textcoords="offset points",
            ha="center",
            va="bottom",
        )
        years = np.arange(-12_000, 12_001, 4_000)
        psi = earth.precession_rate * years * year  # the pole's longitude from J2000 (rad)
        x, y = eps * np.sin(-psi), -eps * np.cos(-psi)
        sky.plot(x, y, "o", ms=4)
        for yr, xi, yi in zip(years, x, y):
            label = "J2000" if yr == 0 else f"{yr:+,d}".replace(",", " ")
            sky.annotate(
                label, (xi, yi), xytext=(4, 4), textcoords="offset points", fontsize="small"
            )
        sky.set_aspect("equal", adjustable="datalim")
        few_ticks(sky, 5)
        sky.set_xlabel("from the ecliptic pole, x (deg)")
        sky.set_ylabel("y (deg)")
        period = earth.precession_period / year
        sky.set_title(f"the pole's precession: one turn in {period:,.0f} yr".replace(",", " "))

        rows: list[tuple[str, float, float]] = []
        rate = -earth.precession_rate
        rows.append(("precession vs IAU 2006", rate / IAU2006_PRECESSION_RATE - 1, 0.0))
        dpsi, deps = earth.nutation_amplitudes
        rows.append(("nutation Δψ₀ vs IAU 2000A", dpsi / IAU2000A_PRINCIPAL_NUTATION[0] - 1, 0.0))
        rows.append(("nutation Δε₀ vs IAU 2000A", deps / IAU2000A_PRINCIPAL_NUTATION[1] - 1, 0.0))
        if chandler_observed is not None:
            observed, sigma = chandler_observed
            chandler = earth.chandler_period(k2, ks) / 86_400.0
            rows.append(
                (
                    f"Chandler period (k2 = {k2:g}) vs observed",
                    chandler / observed - 1,
                    sigma / observed,
                )
            )
        names = [r[0] for r in rows]
        values = np.array([100 * r[1] for r in rows])
        errors = np.array([100 * r[2] for r in rows])
        pos = np.arange(len(rows))
        bars.barh(pos, values, xerr=errors if errors.any() else None, height=0.55)
        bars.axvline(0.0, color="k", lw=line_width() * 0.6)
        for p_, v, err in zip(pos, values, errors):
            end = v + err if v >= 0 else v - err
            bars.annotate(
                f"{v:+.2f} %",
                (end, p_),
                xytext=(4 if v >= 0 else -4, 0),
                textcoords="offset points",
                va="center",
                ha="left" if v >= 0 else "right",
                fontsize="small",
            )
        # the names above their bars (a category axis has no unit to label)
        bars.set_yticks([])
        for p_, name in zip(pos, names):
            bars.text(
                0.02,
                p_ - 0.32,
                name,
                transform=bars.get_yaxis_transform(),
                va="bottom",
                fontsize="small",
            )
        bars.set_ylim(len(rows) - 0.5, -0.9)
        lo, hi = min(0.0, values.min()), max(0.0, values.max())
        span = hi - lo or 1.0
        bars.set_xlim(lo - 0.35 * span, hi + 0.45 * span)
        few_ticks(bars, 5)
        bars.set_yticks([])
        bars.set_xlabel("poinsot − measured (%)")
        bars.set_title("rigid Earth vs measured")
    return fig
