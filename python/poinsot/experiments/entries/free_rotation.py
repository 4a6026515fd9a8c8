"""Free rotation: the Earth as a free rigid body, whose axis of rotation should circle its axis
of figure once in A/(C − A) sidereal days (Euler's free period).

The prediction is the period of ω in the body of :class:`poinsot.FreeRigidBody` (the exact
torque-free motion) for the Earth's moments, spinning once per sidereal day, with a small tilt
of the axis; the closed form is the symmetric top's 2π / |Ω|, Ω = (C − A)/A ω₃
(:class:`poinsot.FreeSymmetricTop`, the unit's eqs. 2.85–2.88).

The tennis-racket flip of a real object, timed against its measured moments, is
:mod:`.racket` (bubbar-zhu-2025); that module says which other measurements were looked for.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace
from typing import Any

from poinsot import Earth, FreeRigidBody, FreeSymmetricTop

from .._catalogue import Experiment, Source, ureg
from ._sources import IERS_2010

__all__ = ["ENTRIES"]

#: The tilt of the rotation axis from the figure axis (rad): small, like the real wobble's
#: 0.3″; the free period does not depend on it to first order.
_TILT = 1e-6


def _moments(inputs: Mapping[str, Any]) -> tuple[float, float]:
    """A and C for C = 1 from the dynamical ellipticity H = (C − A)/C."""
    h = float(inputs["dynamical_ellipticity"].to("dimensionless").magnitude)
    return 1.0 - h, 1.0


def _omega0() -> list[float]:
    w = Earth().rotation_rate
    return [_TILT * w, 0.0, w]


def _euler_period(inputs: Mapping[str, Any]) -> Any:
    """The period of ω in the body of the free rigid Earth (exact solution)."""
    a, c = _moments(inputs)
    body = FreeRigidBody([a, a, c], _omega0())
    return ureg.Quantity(body.period, "s")


def _closed_euler_period(inputs: Mapping[str, Any]) -> Any:
    """2π / |Ω|, Ω = (C − A)/A ω₃ (FreeSymmetricTop.precession_period, the symmetric top's
    body-frame precession in closed form)."""
    a, c = _moments(inputs)
    return ureg.Quantity(FreeSymmetricTop(a, c, _omega0()).precession_period, "s")


ENTRIES = [
    Experiment(
        name="chandler-1891",
        title="Chandler's wobble",
        topic="free rotation",
        sources=(
            Source(
                who="Seth Carlo Chandler",
                first_hand=False,
                where="Cambridge, Massachusetts (latitude series of many observatories)",
                when="1891",
                publication=(
                    "Chandler, S. C. (1891), 'On the variation of latitude', I and II, "
                    "Astronomical Journal 11, 59 and 65"
                ),
                page="p. 65 (the period of 427 days)",
                note=(
                    "the papers were not read here; the 427 days as quoted from them in "
                    "H. H. Turner, Astronomical Discovery (London 1904), ch. on the variation "
                    "of latitude, and in Popular Science Monthly 75 (1909), p. 421. The RAS "
                    "Gold Medal address (MNRAS 56, 299, 1896) gives 428 days."
                ),
            ),
            Source(
                who="Simon Newcomb",
                first_hand=False,
                where="Washington",
                when="1891",
                publication=(
                    "Newcomb, S. (1891), note on Chandler's period in the Astronomical Journal "
                    "11 (the same volume)"
                ),
                page="as quoted by Turner (rigid theory: 306 days; the ocean's fluidity and "
                "the Earth's elasticity lengthen it)",
                note=(
                    "read as quoted at length in Turner, Astronomical Discovery (1904); the AJ "
                    "page not checked here. Newcomb's 306 days used the ellipticity of his "
                    "time; the input H is today's (third source)."
                ),
            ),
            replace(
                IERS_2010,
                page="Table 1.1 (H, the dynamical flattening: 3273795 × 10⁻⁹ ± 1 × 10⁻⁹)",
                note=(
                    "the table itself was not read here (only the report's title pages, in a "
                    "stored copy); the value and its uncertainty as pyshtools quotes them "
                    "from the report (SHTOOLS/SHTOOLS, pyshtools/constants/Earth.py, "
                    "dynamical_flattening_earth), the table's number as the orb library's "
                    "constants cite it for the Earth's parameters (benelsen/orb, "
                    "src/constants/earth.js)"
                ),
            ),
        ),
        inputs={"dynamical_ellipticity": "3273795e-9"},
        quantity="period of the free wobble of the rotation axis",
        measured="427 day",
        uncertainty=None,
        uncertainty_kind="none stated in the sources read (427 d in 1891, 428 d by 1896)",
        predict=_euler_period,
        closed_form=_closed_euler_period,
        assumptions=(
            "rigid Earth",
            "symmetric about the figure axis (A = B)",
            "no torque",
            "one turn per sidereal day",
        ),
        story=(
            "Euler showed in 1758 that a rigid spinning body flattened like the Earth must, "
            "if its axis of rotation is not exactly its axis of figure, let the one circle the "
            "other in A/(C − A) turns: about 305 days for the Earth's flattening of mass "
            "known from precession. Astronomers looked for a ten-month variation of latitude "
            "and found none. In 1891 Seth Chandler, an amateur working through a century of "
            "latitude observations, found the pole circling with a period of 427 days, and a "
            "yearly term besides."
        ),
        expect="disagree",
        why=(
            "the Earth is not rigid: its elastic body and its oceans yield to the wobble's "
            "centrifugal force and follow the axis, which lengthens the period (Newcomb "
            "1891); a rigid Earth's 304 days is the shortest the period can be"
        ),
        unit="day",
    ),
]
