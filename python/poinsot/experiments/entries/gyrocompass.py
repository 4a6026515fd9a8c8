"""Gyrocompasses: the speed (steaming) error of a maker's printed table.

The prediction is :meth:`poinsot.Gyrocompass.speed_error`, the direction a settled compass
takes on a moving ship: the horizontal part of the local frame's angular velocity (the Earth's
Ω cos λ northward plus the ship's V/R about the horizontal normal to its track), δ =
atan(V cos C / (Ω R cos λ + V sin C)). That is also the closed form (the entry compares a
formula printed by the maker with the exact one; the full nonlinear settling is
:meth:`poinsot.Gyrocompass.simulate`, shown in the docs chapter).
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import partial
from typing import Any

from poinsot import Gyrocompass

from .._catalogue import Experiment, Source, ureg

__all__ = ["ENTRIES"]


def _speed_error(inputs: Mapping[str, Any]) -> Any:
    """The settled compass's speed error (deg; positive: the compass reads high)."""
    compass = Gyrocompass(inputs["latitude"])
    return ureg.Quantity(compass.speed_error(inputs["speed"], inputs["course"]), "rad")


_PLATH = Source(
    who="C. Plath GmbH, Hamburg",
    first_hand=True,
    where="Hamburg",
    when="1998",
    publication=(
        "NAVIGAT X MK 1 Mod. 10 / SR 180 MK 1 Mod. 10 Digital Gyrocompass System: Operator, "
        "Technical, Installation and Service Manual, 11 Aug 1998, Rev. A, Stock No. 056310"
    ),
    page=(
        "Appendix, p. A-07, the speed-error tables ('the tables give the north speed error δ "
        "of an uncorrected gyrocompass in degrees, i.e. the correction which must be applied "
        "to the gyrocompass heading in order to obtain true heading'), the 81° table, heading "
        "0/360 north (180 south), speeds 5 to 50 kn"
    ),
    url="https://manualshive.com/en/manual/c-plath/navigat-x-mk-1-mod-10/3123976?page=73",
    note=(
        "read as the page's text layer on manualshive.com (the scan itself not seen). Every "
        "printed value checked reproduces the arcsine form asin(V cos C / (Ω R cos λ)) with "
        "Ω R ≈ 904 kn (the equatorial radius) to the printed 0.1°, and the table gives one "
        "value for courses C and −C: it leaves out the V sin C of the exact form"
    ),
)

_speed_entry = partial(
    Experiment,
    topic="the Earth's rotation",
    sources=(_PLATH,),
    quantity="speed error of an uncorrected gyrocompass (what it reads minus true heading)",
    uncertainty="0.05 deg",
    uncertainty_kind=(
        "half the last printed digit: a maker's printed table, computed from a formula, "
        "not a measurement"
    ),
    predict=_speed_error,
    closed_form=_speed_error,
    assumptions=(
        "the compass settled on the horizontal part of the local frame's rotation",
        "steady course and speed (no Schuler transient)",
        "spherical Earth of mean radius",
        "sidereal rotation",
    ),
    unit="deg",
)

_STORY = (
    "A gyrocompass seeks the horizontal part of the rotation of the ground it stands on. On "
    "a ship that part is not the Earth's alone: steaming north at V over an Earth of radius "
    "R turns the local frame about the west at V/R, and the compass settles west of north by "
    "δ with tan δ = V cos C / (Ω R cos λ + V sin C), largest near the poles where the "
    "ground's eastward speed Ω R cos λ is small. Makers print the correction in tables for "
    "the officer of the watch; C. Plath's 1998 manual prints it to 0.1° for latitudes up "
    "to 85° and speeds up to 50 knots."
)

ENTRIES = [
    _speed_entry(
        name="plath-1998-20-knots",
        title="C. Plath's speed-error table: 20 knots due north at 81°",
        inputs={"latitude": "81 deg", "speed": "20 knot", "course": "0 deg"},
        measured="8.1 deg",
        story=_STORY,
    ),
    _speed_entry(
        name="plath-1998-50-knots",
        title="C. Plath's speed-error table: 50 knots due north at 81°",
        inputs={"latitude": "81 deg", "speed": "50 knot", "course": "0 deg"},
        measured="20.7 deg",
        story=_STORY,
        expect="disagree",
        why=(
            "the table is printed from the arcsine form asin(V cos C / (Ω R cos λ)), which "
            "parts from the settled direction atan(V cos C / (Ω R cos λ + V sin C)) at "
            "second order in V / (Ω R cos λ): by 1.2° at 50 kn at 81°"
        ),
    ),
]
