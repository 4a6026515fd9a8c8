"""Tops on the turning Earth: Foucault's free gyroscope (1852) and the speed (steaming) error
of a gyrocompass maker's printed table.

Foucault's gyroscope: the prediction integrates a free rotor (pivot at its centre of mass)
carried by the ground at the latitude (:func:`poinsot.simulate` with ``carried_by=``
:class:`poinsot.Place`), its axis started due north and horizontal, and reads the sense in
which the axis turns seen from the ground; the closed form is the sign of the unit's
−Ω sin λ (:meth:`poinsot.Earth.foucault_rate`).

The prediction is :meth:`poinsot.Gyrocompass.speed_error`, the direction a settled compass
takes on a moving ship: the horizontal part of the local frame's angular velocity (the Earth's
Ω cos λ northward plus the ship's V/R about the horizontal normal to its track), δ =
atan(V cos C / (Ω R cos λ + V sin C)). That is also the closed form (the entry compares a
formula printed by the maker with the exact one; the full nonlinear settling is
:meth:`poinsot.Gyrocompass.simulate`, shown in the docs chapter).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from poinsot import (
    CarriedTrajectory,
    Earth,
    Gyrocompass,
    Place,
    axis_angle_to_matrix,
    matrix_to_quaternion,
    quaternion_to_matrix,
    simulate,
)

from .._catalogue import Experiment, Source, sense, ureg

__all__ = ["ENTRIES"]


def _speed_error(inputs: Mapping[str, Any]) -> Any:
    """The settled compass's speed error (deg; positive: the compass reads high)."""
    compass = Gyrocompass(inputs["latitude"])
    return ureg.Quantity(compass.speed_error(inputs["speed"], inputs["course"]), "rad")


#: How long the gyroscope is watched (s): Foucault's rotor kept its speed about ten minutes.
_WATCH = 60.0


def _gyroscope_sense(inputs: Mapping[str, Any]) -> str:
    """The sense, seen from above, in which a free gyroscope's horizontal axis turns on the
    ground: a rotor of moments (1, 1, 1.5) kg·m² spinning at 50 rad/s about its axis, started
    due north, integrated for :data:`_WATCH` in inertial space; the axis's east component
    seen from the ground then says the sense (east of north: clockwise)."""
    north = matrix_to_quaternion(axis_angle_to_matrix([1.0, 0.0, 0.0], -90.0, degrees=True))
    run = simulate(
        [1.0, 1.0, 1.5],
        [0.0, 0.0, 50.0],
        _WATCH,
        attitude0=north,
        carried_by=Place(inputs["latitude"]),
        samples=2,
    )
    assert isinstance(run, CarriedTrajectory)  # simulate's answer for a carried body
    east = quaternion_to_matrix(run.relative_attitude[-1])[0][2]
    return sense(-east)  # east of north, seen from above: clockwise


def _closed_gyroscope_sense(inputs: Mapping[str, Any]) -> str:
    """The sign of the ground's turn under the axis, −Ω sin λ (negative: clockwise)."""
    return sense(Earth().foucault_rate(inputs["latitude"]))


_FOUCAULT_1852 = Experiment(
    name="foucault-1852-gyroscope",
    title="Foucault's gyroscope",
    topic="the Earth's rotation",
    sources=(
        Source(
            who="Léon Foucault",
            first_hand=False,
            where="Paris",
            when="1852",
            publication=(
                "Foucault, L. (1852), 'Sur une nouvelle démonstration expérimentale du "
                "mouvement de la terre, fondée sur la fixité du plan de rotation', Comptes "
                "rendus hebdomadaires des séances de l'Académie des sciences 35"
            ),
            page="the note of the séance of 27 September 1852",
            note="not read here; known through Arago's account (the second source)",
        ),
        Source(
            who="François Arago",
            first_hand=True,
            where="Paris",
            when="1857",
            publication=(
                "Arago, F., Astronomie populaire, tome 3 (Œuvres complètes; Gide et J. "
                "Baudry), livre XX, chapitre VI, 'Preuves matérielles du mouvement de "
                "rotation de la Terre'"
            ),
            page=(
                "chapter VI (pp. 32–55 of the volume), Wikisource page djvu/58: 'Au mois de septembre 1852, "
                "M. Foucault a présenté à l'Académie des sciences une autre démonstration "
                "physique du mouvement de rotation de la Terre, fondée ... sur [la fixité] du "
                "plan de rotation d'un corps librement suspendu par son centre de gravité ... "
                "l'observateur, se mouvant avec la Terre, croit voir, comme dans l'expérience "
                "du pendule, le plan dont nous parlons se déplacer de l'est à l'ouest'"
            ),
            url=(
                "https://fr.wikisource.org/wiki/Page:Arago_-_%C5%92uvres_compl%C3%A8tes_de_"
                "Fran%C3%A7ois_Arago,_secr%C3%A9taire_perp%C3%A9tuel_de_l%E2%80%99acad%C3%A9mie"
                "_des_sciences_-_Astronomie_populaire,_tome_3.djvu/58"
            ),
            note=(
                "read on Wikisource (corrected page). The account gives the "
                "sense, from east to west as the pendulum's (clockwise seen from above in the "
                "north), not a rate"
            ),
        ),
        Source(
            who="Musée des arts et métiers (Cnam), L. Dufaux",
            first_hand=True,
            where="Paris",
            when="2013",
            publication=(
                "'Gyroscope de Foucault' (inventory 07688-0001), in Dufaux, L. (dir.), Le "
                "Musée des arts et métiers, Guide des collections, Paris, 2013"
            ),
            page=(
                "the collection's web page: the torus spun at 150 to 200 turns a second, "
                "free of gravity's constraint for ten to fifteen minutes, the cardan's slow "
                "turn read with a needle or a microscope"
            ),
            url="https://www.arts-et-metiers.net/musee/gyroscope-de-foucault",
            note="the instrument's details for the story, not the observation",
        ),
    ),
    inputs={"latitude": "48 deg + 51 arcmin"},
    quantity="sense in which the free gyroscope's plane of rotation turns, seen from above",
    measured="clockwise",
    uncertainty=None,
    uncertainty_kind="a sense (reported as from east to west, like the pendulum's plane)",
    predict=_gyroscope_sense,
    closed_form=_closed_gyroscope_sense,
    assumptions=(
        "rotor supported at its centre of mass: no torque",
        "no friction in the gimbals",
        "sidereal rotation",
    ),
    story=(
        "A year after the pendulum, Foucault showed the Earth's rotation with a body that "
        "needs no swing: a bronze torus spun to 150–200 turns a second by a crank and set in "
        "gimbals at its centre of gravity, so that nothing could torque it. Its plane of "
        "rotation stays fixed in space; watched through a microscope for the ten minutes the "
        "rotor kept its speed, it seemed to turn from east to west, as the pendulum's plane "
        "does, at the Earth's rate times the sine of the latitude. He named it the gyroscope."
    ),
)

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

_STORY = (
    "A gyrocompass seeks the horizontal part of the rotation of the ground it stands on. On "
    "a ship that part is not the Earth's alone: steaming north at V over an Earth of radius "
    "R turns the local frame about the west at V/R, and the compass settles west of north by "
    "δ with tan δ = V cos C / (Ω R cos λ + V sin C), largest near the poles where the "
    "ground's eastward speed Ω R cos λ is small. Makers print the correction in tables for "
    "the officer of the watch; C. Plath's 1998 manual prints it to 0.1° for latitudes up "
    "to 85° and speeds up to 50 knots."
)


def _table_row(knots: int, measured: str, **fields: Any) -> Experiment:
    """The entry of C. Plath's printed correction ``measured`` for a ship steaming due north
    at ``knots`` at 81°, with the entry's own ``fields`` (an expected disagreement)."""
    return Experiment(
        name=f"plath-1998-{knots}-knots",
        title=f"C. Plath's speed-error table: {knots} knots due north at 81°",
        topic="the Earth's rotation",
        sources=(_PLATH,),
        inputs={"latitude": "81 deg", "speed": f"{knots} knot", "course": "0 deg"},
        quantity="speed error of an uncorrected gyrocompass (what it reads minus true heading)",
        measured=measured,
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
        story=_STORY,
        unit="deg",
        **fields,
    )


ENTRIES = [
    _FOUCAULT_1852,
    _table_row(20, "8.1 deg"),
    _table_row(
        50,
        "20.7 deg",
        expect="disagree",
        why=(
            "the table is printed from the arcsine form asin(V cos C / (Ω R cos λ)), which "
            "parts from the settled direction atan(V cos C / (Ω R cos λ + V sin C)) at "
            "second order in V / (Ω R cos λ): by 1.2° at 50 kn at 81°"
        ),
    ),
]
