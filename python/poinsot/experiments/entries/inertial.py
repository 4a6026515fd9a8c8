"""Inertial oscillations: water set moving and left to the Coriolis force turns in circles with
the period π/(ω |sin λ|), half a pendulum day.

The prediction integrates a parcel with :meth:`poinsot.Earth.inertial_oscillation` and takes
the period from the rate at which its velocity turns in the run; the closed form is
:meth:`poinsot.Earth.inertial_period`.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from poinsot import Earth

from .._catalogue import Experiment, Source, ureg

__all__ = ["ENTRIES"]


def _period(inputs: Mapping[str, Any]) -> Any:
    """The period measured from the integrated parcel, 2π over the rate at which its velocity
    turns (InertialOscillation.measured_period)."""
    run = Earth().inertial_oscillation(inputs["latitude"])
    return ureg.Quantity(run.measured_period, "s")


def _closed_period(inputs: Mapping[str, Any]) -> Any:
    """π / (ω |sin λ|)."""
    return ureg.Quantity(Earth().inertial_period(inputs["latitude"]), "s")


ENTRIES = [
    Experiment(
        name="gustafson-kullenberg-1936",
        title="Baltic inertial currents",
        topic="inertial oscillations",
        sources=(
            Source(
                who="Torsten Gustafson and Börje Kullenberg",
                first_hand=False,
                where="the Baltic Sea (position: see the note)",
                when="August 1936 (published 1936)",
                publication=(
                    "Gustafson, T. and Kullenberg, B. (1936), 'Untersuchungen von "
                    "Trägheitsströmungen in der Ostsee', Svenska Hydrografisk-Biologiska "
                    "Kommissionens Skrifter, Ny Serie, Hydrografi 13"
                ),
                page="the period of the oscillations (not seen here)",
                note=(
                    "the original was not found in the stored copies. The month (August "
                    "1936) and the '14 hour period of oscillation' are from a Rutgers "
                    "teaching problem set (third source) whose figure is adapted from Gill, "
                    "Atmosphere–Ocean Dynamics (1982). The input latitude 57.8° N came with "
                    "the task and is in none of the sources read: it is kept because Ekman's "
                    "half pendulum day 'hier gleich 14.1 Stunden' (second source) puts the "
                    "station between 57.75° and 58.4° N (14.05–14.15 h), and 57.8° gives "
                    "14.14 h."
                ),
            ),
            Source(
                who="V. Walfrid Ekman",
                first_hand=True,
                where="(review)",
                when="c. 1939",
                publication=(
                    "Ekman, V. W., 'Trägheitsschwingungen und Trägheitsperiode im Meere', "
                    "Annalen der Hydrographie und maritimen Meteorologie (BSH digital "
                    "library, item 142204)"
                ),
                page="p. 239 (the Baltic oscillations: period equal to half a pendulum day, "
                "14.1 h; circular and turning to the right)",
                url="https://digitale-bibliothek.bsh.de/viewer/fulltext/142204/301/",
                note="read in the BSH digital library's full text; volume and year not shown",
            ),
            Source(
                who="Rutgers University, Physical Oceanography course (Fall 2000)",
                first_hand=True,
                where="(teaching material)",
                when="2000",
                publication="Physical Oceanography, Problem #9, due October 23, 2000",
                page=(
                    "parts b and c ('In August 1936, Gustafson and Kullenberg observed "
                    "inertial motion in the Baltic Sea'; 'a 14 hour period of oscillation')"
                ),
                url="https://marine.rutgers.edu/cool/education/physical.oceanography/hw9.html",
                note="secondary (after Gill 1982); no position or uncertainty on the page",
            ),
        ),
        inputs={"latitude": "57.8 deg"},
        quantity="period of the inertial oscillation",
        measured="14 hour",
        uncertainty=None,
        uncertainty_kind=(
            "none stated (a '14 hour period'; Ekman: equal to half a pendulum day as well as "
            "it could be determined)"
        ),
        predict=_period,
        closed_form=_closed_period,
        assumptions=("frictionless level surface", "Coriolis force only", "sidereal rotation"),
        story=(
            "In the 1930s the Swedish oceanographers Torsten Gustafson and Börje Kullenberg "
            "measured the currents of the open Baltic for days on end. Long after the wind that "
            "set the water moving had dropped, the current kept turning clockwise through the "
            "compass, once in about 14 hours: half a pendulum day, the "
            "period of a body that only the Coriolis force turns. Ekman noted that the "
            "oscillations were circular and turned to the right, as the theory requires in "
            "the north."
        ),
        unit="hour",
    ),
]
