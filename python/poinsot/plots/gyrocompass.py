"""Pictures of the gyrocompass (matplotlib, the optional ``plot`` extra).

The physics comes from :class:`poinsot.Gyrocompass`; these functions only draw (see
:mod:`poinsot.plots`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, cast

import numpy as np

from ..gyrocompass import CompassRun, Gyrocompass
from ._mpl import figure_style, line_width, subplots

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

__all__ = ["plot_gyrocompass"]


def plot_gyrocompass(
    compass: Gyrocompass,
    run: CompassRun | None = None,
    *,
    speed: float = 0.0,
    course: float = 0.0,
    style: str = "paper",
) -> Figure:
    """The compass settling on the meridian, two panels against time (min): the heading of
    the spin axis (degrees east of north) and its tilt (degrees), from the full simulation
    ``run`` (:meth:`Gyrocompass.simulate`; default three periods from 10° east of north, at
    ``speed`` (m/s) on ``course`` (rad)), with the linearised prediction
    (:meth:`Gyrocompass.linear_solution`, from the run's first heading and tilt): the settled
    heading −(latitude error + speed error) and the envelope of the damped swing about it,
    ±A e^{−ζ ω_n t} (A = |α₀ − α*|/√(1 − ζ²) started at the settled tilt). ``style``:
    ``"paper"`` or ``"slides"``."""
    if not isinstance(compass, Gyrocompass):
        from ..errors import ArgumentTypeError

        raise ArgumentTypeError(
            f"compass: must be a poinsot.Gyrocompass, got {type(compass).__name__}"
        )
    if run is None:
        run = compass.simulate(
            3 * compass.period, np.radians(10.0), speed=speed, course=course, samples=600
        )
    with figure_style(style) as style:
        fig, (top, bottom) = subplots(style, 8.0, 5.6, 2, 1, sharex=True)
        minutes = run.t / 60.0
        linear = compass.linear_solution(
            run.t, run.heading[0], tilt0=run.tilt[0], speed=speed, course=course
        )
        # linear_solution always sets both (None only on a simulated run).
        settled = cast(float, linear.settled_heading)
        env = cast(np.ndarray, linear.envelope)
        zeta = compass.damping
        top.plot(minutes, np.degrees(run.heading), lw=line_width(), label="simulated (full)")
        top.axhline(np.degrees(settled), color="k", lw=0.8, ls="--", label="settled (linear)")
        for sign in (1.0, -1.0):
            top.plot(
                minutes,
                np.degrees(settled + sign * env),
                color="0.5",
                lw=0.8,
                ls=":",
                label="linear envelope" if sign > 0 else None,
            )
        top.set_ylabel("heading (° east of north)")
        top.legend(loc="upper right", fontsize="small")
        top.set_title(
            f"λ = {np.degrees(compass.latitude):.4g}°, period {compass.period / 60:.4g} min, "
            f"ζ = {zeta:g}"
        )
        bottom.plot(minutes, np.degrees(run.tilt), lw=line_width())
        bottom.axhline(np.degrees(compass.settle_tilt), color="k", lw=0.8, ls="--")
        bottom.set_ylabel("tilt of the north end (°)")
        bottom.set_xlabel("time (min)")
        return fig
