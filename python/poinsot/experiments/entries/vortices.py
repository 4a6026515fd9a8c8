"""Vortices: the sense in which water drawn into a drain (or air into a low) turns, once every
other motion has died away: counterclockwise in the north, clockwise in the south.

The prediction is the sense of the circulation in :meth:`poinsot.Earth.flow_into_low` (parcels
at rest pulled towards a centre and turned by the Coriolis force, integrated); the closed form
is the sign of the Coriolis parameter f = 2ω sin λ, :meth:`poinsot.Earth.coriolis_parameter`
(f > 0: to the right of the motion, counterclockwise about a low).
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import partial
from typing import Any

from poinsot import Earth

from .._catalogue import Experiment, Source, sense

__all__ = ["ENTRIES"]


def _sense(inputs: Mapping[str, Any]) -> str:
    """The sense of the simulated inflow's circulation, seen from above."""
    return Earth().flow_into_low(inputs["latitude"]).sense


def _closed_sense(inputs: Mapping[str, Any]) -> str:
    """Counterclockwise where f = 2ω sin λ > 0, clockwise where it is < 0."""
    return sense(Earth().coriolis_parameter(inputs["latitude"]))


_STORY_COMMON = (
    "The Coriolis force on water creeping towards a drain at a centimetre a second is ten "
    "million times weaker than its weight; any swirl left from filling the tank, any draught or warm wall, decides "
    "the sense of an ordinary bath's vortex. "
)

#: The fields both vortex entries share: the topic, the quantity (a sense), the two routes and
#: the model's assumptions.
_vortex = partial(
    Experiment,
    topic="vortices",
    quantity="sense of the drain vortex, seen from above",
    uncertainty=None,
    uncertainty_kind="a sense (repeated runs after the water had settled)",
    predict=_sense,
    closed_form=_closed_sense,
    assumptions=(
        "water at rest before it drains",
        "Coriolis force the only asymmetry",
        "no friction at the scale of the tank",
    ),
)

ENTRIES = [
    _vortex(
        name="shapiro-1962",
        title="Shapiro's bath vortex",
        sources=(
            Source(
                who="Ascher H. Shapiro",
                first_hand=False,
                where="Watertown, Massachusetts (MIT, for the film 'Vorticity')",
                when="1962",
                publication="Shapiro, A. H. (1962), 'Bath-tub vortex', Nature 196, 1080–1081",
                page="p. 1080",
                note=(
                    "the citation as given in Trefethen et al. (1965), ref. 3, and a "
                    "bookseller's description of the volume (pp. 1080–1); the set-up (a tank "
                    "6 ft across and 6 in deep, a 3/8 in drain, left to settle for about a "
                    "day, covered) from MIT Technology Review's 'Verifying a vortex' and the "
                    "Irish Times weather column. The paper itself was not read here."
                ),
            ),
        ),
        inputs={"latitude": "42 deg + 22 arcmin"},
        measured="counterclockwise",
        story=(
            _STORY_COMMON + "Ascher Shapiro at MIT filled a circular tank six feet across "
            "with a clockwise swirl, covered it, kept the room at one temperature and waited "
            "about a day before pulling the plug. The vortex that formed as it drained turned "
            "counterclockwise, against the swirl he had filled it with: the sense of the "
            "Earth's rotation seen from above the northern hemisphere."
        ),
        misquoted=(
            "Shapiro's result is quoted as if every northern sink drained counterclockwise; "
            "it holds only for water left still for many hours in a symmetric tank."
        ),
    ),
    _vortex(
        name="trefethen-1965",
        title="Sydney's bath vortex",
        sources=(
            Source(
                who="L. M. Trefethen, R. W. Bilger, P. T. Fink, R. E. Luxton, R. I. Tanner",
                first_hand=True,
                where="Sydney, Australia",
                when="1965",
                publication=(
                    "Trefethen, L. M., Bilger, R. W., Fink, P. T., Luxton, R. E. and Tanner, "
                    "R. I. (1965), 'The bath-tub vortex in the southern hemisphere', Nature "
                    "207, 1084–1085"
                ),
                page="p. 1084",
                url="https://doi.org/10.1038/2071084a0",
                note=(
                    "read: the article's opening and reference list on nature.com and Time "
                    "magazine's account ('The bathtub vortex', 24 September 1965); the place "
                    "(Sydney) as commonly given, not seen on the pages read"
                ),
            ),
        ),
        inputs={"latitude": "-(33 deg + 52 arcmin)"},
        measured="clockwise",
        story=(
            _STORY_COMMON + "Three years after Shapiro, five engineers in Sydney repeated "
            "his experiment on the other side of the equator. Once the water had settled, it "
            "drained clockwise: the Earth's rotation seen from above the southern hemisphere."
        ),
    ),
]
