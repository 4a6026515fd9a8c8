"""Falling bodies: the eastward deflection of a body dropped down a tower or a mine shaft."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from poinsot import Earth

from .._catalogue import Experiment, Source, ureg


def _drop_east(inputs: Mapping[str, Any]) -> Any:
    """The landing point east of the plumb line, integrated in the rotating frame (vacuum)."""
    fall = Earth().drop(inputs["height"], inputs["latitude"])
    return ureg.Quantity(fall.east, "m")


def _closed_east(inputs: Mapping[str, Any]) -> Any:
    """The unit's eq. 2.42, ⅓ ω cos λ √(8h³/g)."""
    return ureg.Quantity(Earth().eastward_deflection(inputs["height"], inputs["latitude"]), "m")


ENTRIES = [
    # TODO-verify (helper D): the figures below are from secondary memory, to be checked
    # against Reich (1832) and corrected (height, latitude, mean deflection, its probable error).
    Experiment(
        name="reich-1831",
        title="Reich's drops in the Freiberg mine shaft",
        topic="falling bodies",
        sources=(
            Source(
                who="Ferdinand Reich",
                where="Drei-Brüder-Schacht, Freiberg, Saxony",
                when="1831",
                publication=(
                    "Reich, F. (1832), Fallversuche über die Umdrehung der Erde, "
                    "Freiberg: J. G. Engelhardt"
                ),
                page="TODO-verify",
                note="figures to be checked against the original (helper D)",
            ),
        ),
        inputs={"height": "158.5 m", "latitude": "50 deg + 55 arcmin"},
        quantity="eastward deflection",
        measured="28.396 mm",
        uncertainty="4.0 mm",
        uncertainty_kind="stated probable error of the mean, as a standard error",
        predict=_drop_east,
        closed_form=_closed_east,
        assumptions=("vacuum", "uniform gravity", "spherical Earth", "sidereal rotation"),
        story=(
            "In 1831 Ferdinand Reich, professor at the Freiberg mining academy, dropped lead "
            "balls 158.5 m down the Drei-Brüder-Schacht, a mine shaft sheltered from the wind "
            "that had spoiled Benzenberg's church-tower drops. Their mean landing point lay "
            "east of the plumb line by a few centimetres, as the Earth's rotation requires: the "
            "top of the shaft moves east faster than its foot."
        ),
        unit="mm",
    ),
]
