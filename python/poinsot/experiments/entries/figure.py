"""The Earth's figure: gravity and the plumb line of the unit's sphere (radius 6371 km, gravity
9.80665 m/s², turning at the sidereal rate) against the WGS 84 reference ellipsoid.

The unit's Earth is a sphere with the centrifugal term (eq. 2.31); it leaves out the
flattening the rotation gives the Earth. Both entries expect to disagree, and say by how much:
the sphere has the centrifugal part of the pole-to-equator difference, not the part due to
the flattening itself (the equatorial bulge and the pole's nearness to the centre).
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import partial
from typing import Any

from poinsot import Earth

from .._catalogue import Experiment, Source, ureg

__all__ = ["ENTRIES"]


def _gravity_step(inputs: Mapping[str, Any]) -> Any:
    """|g_e| at the pole minus |g_e| at the equator of the unit's sphere."""
    e = Earth()
    pole = e.effective_gravity_magnitude(inputs["pole_latitude"])
    equator = e.effective_gravity_magnitude(inputs["equator_latitude"])
    return ureg.Quantity(pole - equator, "m/s^2")


def _closed_gravity_step(inputs: Mapping[str, Any]) -> Any:
    """The centrifugal acceleration's magnitude ω²R cos λ at the equator minus at the pole (the
    sphere's whole difference: its attraction is the same everywhere)."""
    e = Earth()
    pole = e.centrifugal_magnitude(inputs["pole_latitude"])
    equator = e.centrifugal_magnitude(inputs["equator_latitude"])
    return ureg.Quantity(equator - pole, "m/s^2")


def _plumb(inputs: Mapping[str, Any]) -> Any:
    """The angle between the unit's plumb line and the radius at the latitude."""
    return ureg.Quantity(Earth().plumb_line_deviation(inputs["latitude"]), "rad")


def _closed_plumb(inputs: Mapping[str, Any]) -> Any:
    """The same angle in closed form, tan δ = q sin λ cos λ / (1 − q cos² λ) with q = ω²R/g
    (Earth.plumb_line_deviation_closed)."""
    return ureg.Quantity(Earth().plumb_line_deviation_closed(inputs["latitude"]), "rad")


_TR8350 = Source(
    who="National Imagery and Mapping Agency (NIMA)",
    first_hand=False,
    where="(the WGS 84 reference ellipsoid, from satellite and surface gravimetry)",
    when="2000",
    publication=(
        "NIMA Technical Report TR8350.2, Department of Defense World Geodetic System 1984: its "
        "definition and relationships with local geodetic systems, 3rd edition (2000)"
    ),
    page=(
        "the table of derived physical constants (not seen here): γe = 9.7803253359 m/s² at "
        "the equator, γp = 9.8321849378 m/s² at the poles"
    ),
    note=(
        "the 2000 report's table of derived constants was not read here (only the first page "
        "of Chapter 3 of the earlier edition, in an fdocuments copy; a calculator page cites "
        "the gravity formula as eq. 4-3 of that edition, with its older γe 9.7803267714, so "
        "the chapter and the page of the 2000 values are not confirmed). The two values "
        "are as quoted with the formula on a copy of the 'International gravity formula' "
        "encyclopaedia page, and they follow from the four defining constants (a = 6378137 "
        "m, 1/f = 298.257223563, GM = 3986004.418e8 m³/s², ω = 7292115e-11 rad/s, as "
        "pyshtools quotes them from TR8350.2): the boule documentation computes 9.7803253359 "
        "and 9.8321849379 (fatiando/boule, doc/ellipsoids/wgs84.rst), an hpmuseum.org forum "
        "thread 9.78032533482 and 9.83218494001"
    ),
)

#: The fields both entries share: the topic, no uncertainty (the reference ellipsoid's values
#: are defined), and the expected disagreement of the unit's spherical Earth.
_ellipsoid_entry = partial(
    Experiment, topic="the Earth's figure", uncertainty=None, expect="disagree"
)

ENTRIES = [
    _ellipsoid_entry(
        name="wgs84-gravity",
        title="Gravity, pole − equator",
        sources=(_TR8350,),
        inputs={"pole_latitude": "90 deg", "equator_latitude": "0 deg"},
        quantity="normal gravity at the pole minus at the equator",
        measured="9.8321849378 m/s^2 - 9.7803253359 m/s^2",
        uncertainty_kind="defined values of the reference ellipsoid (no uncertainty)",
        predict=_gravity_step,
        closed_form=_closed_gravity_step,
        assumptions=(
            "spherical Earth of radius 6371 km",
            "attraction 9.80665 m/s² everywhere on the surface",
            "centrifugal term of the sidereal rotation",
        ),
        story=(
            "In 1672 Jean Richer found at Cayenne that a pendulum beating seconds had to be "
            "shorter than in Paris: gravity is weaker near the equator. The modern reference, WGS 84, gives 9.7803 m/s² at "
            "the equator and 9.8322 at the poles, a difference of 0.0519 m/s². The unit's "
            "spinning sphere explains only the centrifugal part of it, ω²R = 0.0339 m/s²."
        ),
        why=(
            "the sphere leaves out the flattening (1/298): the poles are 21 km nearer the "
            "centre and the equatorial bulge pulls sideways, adding about 0.018 m/s² "
            "(Clairaut's theorem: (5/2 m − f) γe with m = ω²a/γe)"
        ),
        unit="m/s^2",
    ),
    _ellipsoid_entry(
        name="wgs84-plumb-line",
        title="The plumb line at 45°",
        sources=(
            Source(
                who="George H. Kaplan (U.S. Naval Observatory)",
                first_hand=True,
                where="(the WGS 84 ellipsoid's flattening)",
                when="2005",
                publication=(
                    "Kaplan, G. H. (2005), The IAU resolutions on astronomical reference "
                    "systems, time scales, and Earth rotation models, USNO Circular 179"
                ),
                page="p. ix ('WGS 84 ... uses an Earth ellipsoid with aE = 6378137 m and "
                "f = 1/298.257223563')",
                url="https://arxiv.org/abs/astro-ph/0602086",
                note=(
                    "the measured angle is the ellipsoid's geodetic minus geocentric "
                    "latitude at 45°, atan((1 − f)² tan φ), computed here from the published f"
                ),
            ),
        ),
        inputs={"latitude": "45 deg"},
        quantity="angle between the plumb line (normal) and the radius at 45°",
        measured="11.545 arcmin",
        uncertainty_kind="defined by the reference ellipsoid (no uncertainty)",
        predict=_plumb,
        closed_form=_closed_plumb,
        assumptions=(
            "spherical Earth of radius 6371 km",
            "uniform radial attraction",
            "centrifugal term of the sidereal rotation",
        ),
        story=(
            "On a spinning sphere the plumb line leans towards the equator, away from the "
            "radius, because the centrifugal force pulls the bob away from the axis: by at "
            "most 0.1° (6′), at 45°. On the real Earth the plumb line is square to the "
            "flattened sea surface, and at 45° it departs from the radius by 11.5′, the "
            "difference between geodetic and geocentric latitude that every map projection "
            "must know."
        ),
        why=(
            "the sphere leaves out the flattening: the sea surface itself is tilted against "
            "the sphere by about f sin 2λ = 11.5′ at 45°, twice the centrifugal lean "
            "(m/2) sin 2λ ≈ 6′ that the sphere keeps"
        ),
        unit="arcmin",
    ),
]
