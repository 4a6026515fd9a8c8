"""Foucault pendulums: the turn of the swing plane, ω sin λ (clockwise in the north).

The prediction swings the pendulum with :meth:`poinsot.Earth.foucault` (a spherical pendulum
integrated in the rotating frame) and takes the rate of turn it fits through the turning
points; the closed form is the unit's −ω sin λ, :meth:`poinsot.Earth.foucault_rate`. Rates
are given clockwise seen from above, positive (the way the 1851 observers reported them).
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import partial
from typing import Any

from poinsot import Earth, PoinsotError
from poinsot.earth import FoucaultRun

from .._catalogue import Experiment, Source, ureg

__all__ = ["ENTRIES"]

#: How long the prediction swings the pendulum (s): an hour, as the 1851 audiences watched.
_DURATION = 3600.0


def _swing(inputs: Mapping[str, Any]) -> FoucaultRun:
    """The pendulum of the entry swung for :data:`_DURATION` (a pendulum of
    :data:`_UNPUBLISHED_LENGTH` where the source gives no length); refused where it shows no
    steady turn. The run of each (latitude, length) is kept, so the prediction and the closed
    form of one entry swing it once."""
    length = inputs.get("length", _UNPUBLISHED_LENGTH)
    key = (float(inputs["latitude"].to("rad").magnitude), float(length.to("m").magnitude))
    run = _RUNS.get(key)
    if run is None:
        run = Earth().foucault(
            inputs["latitude"],
            length=length,
            amplitude=length * _AMPLITUDE_RATIO,
            duration=_DURATION,
        )
        _RUNS[key] = run
    if run.precession_rate is None:
        raise PoinsotError(f"the pendulum shows no steady turn: {run.regime_note}")
    return run


#: The runs swung so far, by (latitude in rad, length in m): a handful (one per entry).
_RUNS: dict[tuple[float, float], FoucaultRun] = {}


#: The release's distance from rest as a fraction of the length: a small swing (the sources do
#: not give the amplitude; Foucault's Panthéon bob swung about 3 m each way on 67 m).
_AMPLITUDE_RATIO = 0.015
#: The pendulum swung where the source gives no length (m); the small-swing rate ω sin λ does
#: not depend on it.
_UNPUBLISHED_LENGTH = ureg.Quantity(10.0, "m")


def _rate(inputs: Mapping[str, Any]) -> Any:
    """The swing plane's rate of turn from the integrated pendulum (clockwise positive)."""
    rate = _swing(inputs).precession_rate
    assert rate is not None  # _swing refuses a run without a steady turn
    return ureg.Quantity(-rate, "rad/s")


def _closed_rate(inputs: Mapping[str, Any]) -> Any:
    """The unit's ω sin λ (clockwise positive)."""
    return ureg.Quantity(-Earth().foucault_rate(inputs["latitude"]), "rad/s")


def _turn_time(inputs: Mapping[str, Any]) -> Any:
    """The time the swing plane takes to turn once, from the integrated pendulum's rate
    (FoucaultRun.full_turn_period)."""
    return ureg.Quantity(_swing(inputs).full_turn_period, "s")


def _closed_turn_time(inputs: Mapping[str, Any]) -> Any:
    """2π / |ω sin λ| (FoucaultRun.expected_full_turn_period)."""
    return ureg.Quantity(_swing(inputs).expected_full_turn_period, "s")


_HANDBOOK = Source(
    who="(compiled from the 1851 reports)",
    first_hand=True,
    where="Paris, Bristol, Dublin, Aberdeen, New York, Ceylon",
    when="1851",
    publication=(
        "a nineteenth-century English handbook of astronomy, chapter 'Foucault's pendulum "
        "experiment to show the Earth's axial rotation' (Google Books id ifIRAAAAYAAJ)"
    ),
    page="p. 115 ('The angular deviation for 1 hour was found to be at Paris 11°; ... at "
    "Dublin nearly 12°; ... at New York (Lat. 40°) it was only 9° and in Ceylon (Lat. 7°) only "
    "1·8°'; 'At Dublin a complete revolution was watched and observed to occupy 28h 26m')",
    url="https://books.google.com/books?id=ifIRAAAAYAAJ&pg=PA115",
    note="secondary; the book's title was not shown on the page read",
)

#: The fields every pendulum entry shares (the topic; no uncertainty stated in the 1851 reports;
#: the model's assumptions, which an entry may replace), and a rate entry's quantity and two
#: routes besides.
_pendulum = partial(
    Experiment,
    topic="Foucault pendulums",
    uncertainty=None,
    assumptions=(
        "spherical pendulum, small swing",
        "no air drag",
        "spherical Earth",
        "sidereal rotation",
    ),
)
_rate_entry = partial(
    _pendulum,
    quantity="rate of turn of the swing plane (clockwise seen from above)",
    predict=_rate,
    closed_form=_closed_rate,
)

ENTRIES = [
    _rate_entry(
        name="foucault-1851",
        title="Foucault's Panthéon",
        sources=(
            Source(
                who="Léon Foucault",
                first_hand=True,
                where="Panthéon, Paris (first at the Observatoire, salle de la Méridienne)",
                when="1851",
                publication=(
                    "Foucault, L. (1851), 'Démonstration physique du mouvement de rotation de "
                    "la terre au moyen du pendule', Comptes rendus hebdomadaires des séances "
                    "de l'Académie des sciences 32, 135–138"
                ),
                page=(
                    "pp. 136–137 (the law: the plane turns by the Earth's turn times the sine "
                    "of the latitude); p. 138 ('ne fait pas un tour entier dans les vingt-"
                    "quatre heures'; the 11 m pendulum of the Méridienne)"
                ),
                url=(
                    "https://fr.wikisource.org/wiki/Page:Comptes_rendus_hebdomadaires_des_"
                    "s%C3%A9ances_de_l%E2%80%99Acad%C3%A9mie_des_sciences,_tome_032,_1851."
                    "djvu/146"
                ),
                note=(
                    "read on Wikisource (corrected pages). The note gives the law, not an "
                    "hourly figure; the 11° per hour measured in the Panthéon is the "
                    "handbook's (second source). 67 m and 28 kg: the Panthéon pendulum as "
                    "reported since (e.g. francearchives.fr, Commémorations 2001)."
                ),
            ),
            _HANDBOOK,
        ),
        inputs={"latitude": "48 deg + 50 arcmin + 46 arcsec", "length": "67 m"},
        measured="11 deg/hour",
        uncertainty_kind="none stated (the hourly figure is given to the whole degree)",
        story=(
            "In February 1851 Léon Foucault told the Académie des sciences that the plane "
            "of a freely hung pendulum turns from east to west, by the Earth's own turn times "
            "the sine of the latitude: the Earth turns under it. He had seen it first in his "
            "cellar with a 2 m wire, then on 11 m under the Observatoire's Méridienne; in "
            "March the prince-president had him hang a 28 kg ball on 67 m of wire from the "
            "dome of the Panthéon, where a stylus cut the swings into a bank of sand and the "
            "crowds saw the plane advance about 11° each hour."
        ),
        misquoted=(
            "'It rotates clockwise 11° per hour, making a full circle in 32.7 hours' is "
            "repeated across the web (for example harveybenge.blogspot.com, 2010, and "
            "walkingarizona.blogspot.com, 2012, with the same figures): 32.7 h is just "
            "360/11, the rounded hourly figure turned into a period. The law Foucault "
            "announced gives ω sin λ = 11.3° per hour at the Panthéon (48° 51′ N), a full turn "
            "in a sidereal day / sin λ = 31.8 h. The same handbook credits Binet with "
            "'32h 8m', also not the sidereal law's figure."
        ),
        unit="deg/hour",
    ),
    _pendulum(
        name="galbraith-haughton-1851",
        title="The Dublin pendulum",
        sources=(
            Source(
                who="Joseph Galbraith and Samuel Haughton",
                first_hand=False,
                where=(
                    "engine factory of the Dublin & Kingstown Railway, Grand Canal Basin, "
                    "Ringsend, Dublin"
                ),
                when="1851",
                publication=(
                    "Galbraith's diary, April–July 1851, Trinity College Dublin, Manuscripts "
                    "and Archives Research Library, TCD MS 3826; described in 'Galbraith's "
                    "account of the Foucault pendulum experiment in Dublin', TCD Library "
                    "manuscripts blog"
                ),
                page=(
                    "the blog's account of the final experiment ('a full rotation was achieved "
                    "in a time of 28 hours and 26 minutes'; length 35.4 feet; azimuth read "
                    "every 20 minutes)"
                ),
                url="https://www.tcd.ie/library/manuscripts/blog/category/scientific/page/2/",
                note=(
                    "secondary (the library's account of the diary). Their printed paper in "
                    "the Proceedings of the Royal Irish Academy was not found in the stored "
                    "copies."
                ),
            ),
            _HANDBOOK,
        ),
        inputs={"latitude": "53 deg + 20 arcmin", "length": "35.4 ft"},
        quantity="time for the swing plane to turn once",
        measured="28 hour + 26 minute",
        uncertainty_kind="none stated (one full turn timed; the azimuth was read every 20 min)",
        predict=_turn_time,
        closed_form=_closed_turn_time,
        story=(
            "Within weeks of Foucault's announcement two fellows of Trinity College Dublin, "
            "Joseph Galbraith and Samuel Haughton, hung a pendulum 35.4 feet (10.8 m) long "
            "under the lofty roof of the railway's engine factory at Ringsend and took turns "
            "reading its azimuth every 20 minutes, through runs of 15 to 30 hours. In the last "
            "run they watched the swing plane go once all the way round, in 28 h 26 min."
        ),
        unit="hour",
    ),
    _rate_entry(
        name="ceylon-1851",
        title="The pendulum in Ceylon",
        sources=(
            Source(
                who="observers in Ceylon (not named in the source found)",
                first_hand=False,
                where="Ceylon (latitude 7° N as the source gives it)",
                when="1851",
                publication=_HANDBOOK.publication,
                page=_HANDBOOK.page,
                url=_HANDBOOK.url,
                note=(
                    "secondary; francearchives.fr (Commémorations 2001) lists Ceylon among the "
                    "places the pendulum was installed in 1851. The observers' own report was "
                    "not found."
                ),
            ),
        ),
        inputs={"latitude": "7 deg"},
        measured="1.8 deg/hour",
        uncertainty_kind="none stated (the hourly figure is given to a tenth of a degree)",
        assumptions=(
            "spherical pendulum, small swing, 10 m long (the source gives no length)",
            "no air drag",
            "spherical Earth",
            "sidereal rotation",
        ),
        story=(
            "Within the year Foucault's pendulum was swung from Rio de Janeiro to Ceylon. "
            "Near the equator the experiment is at its hardest: at latitude 7° the swing "
            "plane turns only ω sin λ = 1.8° an hour, 38 times slower than at the pole, and "
            "any draught or ellipticity of the swing can mask it. The handbook that records "
            "11° an hour in Paris and nearly 12° in Dublin gives 1.8° for Ceylon, and 9° for "
            "New York at 40°, where the law gives 9.7°."
        ),
    ),
]
