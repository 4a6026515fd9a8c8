"""The Earth as a rigid top (:class:`poinsot.RigidEarth`): the precession of the equinoxes, the
principal (18.6-year) nutation, and the Chandler wobble of the elastic Earth.

Each prediction goes through the public :class:`poinsot.RigidEarth`; the closed forms are the
same theory in a second form (the Sun's and the Moon's parts summed); the Chandler period,
:meth:`poinsot.RigidEarth.chandler_period`, is itself the closed form (Euler's period times
ks/(ks − k2)) and serves as both. The measured values are the conventional IAU models, fitted
to decades of VLBI (precession, nutation), and the Chandler period from a century of polar
motion. ``poinsot earth`` prints these entries' measured values beside RigidEarth's numbers.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace
from typing import Any

from poinsot import RigidEarth

from .._catalogue import Experiment, Source, ureg
from ._sources import IERS_2010

__all__ = ["ENTRIES"]


def _earth(inputs: Mapping[str, Any]) -> RigidEarth:
    h = float(inputs["dynamical_flattening"].to("dimensionless").magnitude)
    eps = float(inputs["obliquity"].to("rad").magnitude)
    return RigidEarth(dynamical_flattening=h, obliquity=eps)


def _precession(inputs: Mapping[str, Any]) -> Any:
    """The westward luni-solar precession rate, −RigidEarth.precession_rate."""
    return ureg.Quantity(-_earth(inputs).precession_rate, "rad/s")


def _precession_parts(inputs: Mapping[str, Any]) -> Any:
    """The Sun's part plus the Moon's (RigidEarth.precession_parts), westward."""
    sun, moon = _earth(inputs).precession_parts
    return ureg.Quantity(-(sun + moon), "rad/s")


def _nutation(index: int) -> Any:
    def predict(inputs: Mapping[str, Any]) -> Any:
        return ureg.Quantity(_earth(inputs).nutation_amplitudes[index], "rad")

    predict.__doc__ = f"RigidEarth.nutation_amplitudes[{index}] (rad)."
    return predict


def _nutation_by_precession(index: int) -> Any:
    def closed(inputs: Mapping[str, Any]) -> Any:
        return ureg.Quantity(_earth(inputs).nutation_amplitudes_by_precession[index], "rad")

    closed.__doc__ = (
        f"RigidEarth.nutation_amplitudes_by_precession[{index}] (rad): the closed form from "
        "the Moon's precession part."
    )
    return closed


def _chandler(inputs: Mapping[str, Any]) -> Any:
    """RigidEarth.chandler_period(k2, ks): Euler's period times ks/(ks − k2), the core's closed
    form (no second route: the prediction is that closed form too)."""
    k2 = float(inputs["k2"].to("dimensionless").magnitude)
    ks = float(inputs["ks"].to("dimensionless").magnitude)
    return ureg.Quantity(_earth(inputs).chandler_period(k2, ks), "s")


_IERS = replace(
    IERS_2010,
    page="Table 1.1 (H = 3273795 × 10⁻⁹, the obliquity at J2000 84381.406″)",
    note=(
        "the inputs, as the core's constants cite them (crates/poinsot/src/earth/rigid.rs); "
        "H is itself fitted to the observed precession rate, so the rate's agreement checks "
        "the theory's form and the Sun's and Moon's orbits, not H"
    ),
)

#: The inputs of every entry here, as :data:`_IERS` prints them (Table 1.1): H and the
#: obliquity at J2000.
_IERS_INPUTS = {"dynamical_flattening": "3273795e-9", "obliquity": "84381.406 arcsec"}

_MHB = Source(
    who="P. M. Mathews, T. A. Herring and B. A. Buffett",
    first_hand=False,
    where="VLBI nutation series (IERS), the MHB2000 model adopted as IAU 2000A",
    when="2002",
    publication=(
        "Mathews, P. M., Herring, T. A. and Buffett, B. A. (2002), 'Modeling of nutation and "
        "precession: New nutation series for nonrigid Earth and insights into the Earth's "
        "interior', Journal of Geophysical Research 107 (B4), 2068"
    ),
    page=(
        "the principal term of the IAU 2000A series, argument Ω: Δψ −17.2064161″ sin Ω, "
        "Δε 9.2052331″ cos Ω (as ERFA's nut00a tabulates it)"
    ),
    url="https://doi.org/10.1029/2001JB000390",
    note=(
        "the paper was not read here; the coefficients as the IAU 2000A series carries them "
        "in ERFA's nut00a (its first luni-solar term), which python/tests/test_rigid_earth.py "
        "calls when pyerfa is installed"
    ),
)


def _nutation_entry(index: int, **fields: Any) -> Experiment:
    """An entry of the principal nutation's term ``index`` (0: Δψ₀ in longitude, 1: Δε₀ in
    obliquity): the fields the two entries share (sources, inputs, routes, assumptions) and
    ``fields``, the entry's own."""
    return Experiment(
        topic="the Earth's rotation",
        sources=(_MHB, _IERS),
        inputs=_IERS_INPUTS,
        uncertainty=None,
        uncertainty_kind="none stated in the sources read (a conventional model's coefficient)",
        predict=_nutation(index),
        closed_form=_nutation_by_precession(index),
        assumptions=(
            "rigid symmetric Earth (A = B)",
            "the Moon on a Kepler orbit whose node regresses uniformly in 18.6 years",
            "first order in the Moon's inclination",
        ),
        unit="arcsec",
        **fields,
    )


ENTRIES = [
    Experiment(
        name="capitaine-2003",
        title="The precession of the equinoxes",
        topic="the Earth's rotation",
        sources=(
            Source(
                who="N. Capitaine, P. T. Wallace and J. Chapront",
                first_hand=False,
                where="Observatoire de Paris (from VLBI and lunar laser ranging)",
                when="2003",
                publication=(
                    "Capitaine, N., Wallace, P. T. and Chapront, J. (2003), 'Expressions for "
                    "IAU 2000 precession quantities', Astronomy & Astrophysics 412, 567–586 "
                    "(adopted as the IAU 2006 precession)"
                ),
                page="the linear term of ψ_A, 5038.481507″ per Julian century",
                url="https://doi.org/10.1051/0004-6361:20031539",
                note=(
                    "the rate as ERFA's p06e evaluates ψ_A (differentiated in "
                    "python/tests/test_rigid_earth.py when pyerfa is installed); the paper's "
                    "table was not read here. ψ̇_A holds, besides the luni-solar torque, the "
                    "geodesic precession (−1.92″/cy) and planetary and second-order terms"
                ),
            ),
            _IERS,
        ),
        inputs=_IERS_INPUTS,
        quantity="luni-solar precession rate of the equator (westward)",
        measured="5038.481507 arcsec / (100 julian_year)",
        uncertainty=None,
        uncertainty_kind=(
            "none stated in the sources read (a conventional model's coefficient, given to "
            "1 µas per century)"
        ),
        predict=_precession,
        closed_form=_precession_parts,
        assumptions=(
            "rigid symmetric Earth (A = B)",
            "the Sun's and the Moon's torques averaged over their Kepler orbits",
            "first order in H",
            "no geodesic precession, no planetary terms",
        ),
        story=(
            "Hipparchus found around 130 BC that the stars' longitudes had grown by about a "
            "degree in a century and a half: the equinoxes slide westward along the ecliptic. "
            "Newton explained it in the Principia: the Sun and the Moon pull on the Earth's "
            "equatorial bulge and try to turn the equator into their orbits' planes, and the "
            "spinning Earth answers, as the unit's top does, by precessing. Averaged over the "
            "orbits, the torque makes the axis circle the pole of the ecliptic in about 25,700 "
            "years, the Moon doing twice the Sun's share. Today's rate comes from decades of "
            "VLBI; the dynamical flattening H is fitted to it, so the comparison tests the "
            "torque theory and the orbits, and shows how little the terms it leaves out weigh."
        ),
        unit="arcsec / julian_year",
    ),
    _nutation_entry(
        0,
        name="mathews-2002-longitude",
        title="The principal nutation in longitude",
        quantity="amplitude Δψ₀ of the 18.6-year nutation in longitude (of sin Ω)",
        measured="-17.2064161 arcsec",
        story=(
            "James Bradley found in 1748, after twenty years of observing the star γ Draconis, "
            "that the Earth's axis nods around its precession cone with the period of the "
            "Moon's node, 18.6 years. The Moon's orbit is tilted 5° to the ecliptic and turns "
            "backwards; the torque on the bulge follows the orbit's plane, so the precession "
            "speeds up and slows down and the obliquity rocks: a nutation of 17″ in longitude "
            "and 9″ in obliquity. The rigid top gives both within half a percent of the "
            "non-rigid IAU 2000A model, whose fluid core and elastic mantle answer a little "
            "less than a rigid body."
        ),
    ),
    _nutation_entry(
        1,
        name="mathews-2002-obliquity",
        title="The principal nutation in obliquity",
        quantity="amplitude Δε₀ of the 18.6-year nutation in obliquity (of cos Ω)",
        measured="9.2052331 arcsec",
        story=(
            "Bradley's nutation rocks the obliquity as well as the longitude: when the Moon's "
            "ascending node is at the equinox (Ω = 0) the Moon's orbit is tilted furthest from "
            "the equator and the obliquity is 9″ above its mean. The ratio of the two "
            "amplitudes, cos 2ε/(sin ε cos ε) for the rigid top, makes the pole trace a small "
            "ellipse, not a circle, about its mean place."
        ),
    ),
    Experiment(
        name="vicente-wilson-1997",
        title="The Chandler wobble of the elastic Earth",
        topic="free rotation",
        sources=(
            Source(
                who="R. O. Vicente and C. R. Wilson",
                first_hand=False,
                where="Lisbon and Austin (polar motion series 1846 to the early 1990s)",
                when="1997",
                publication=(
                    "Vicente, R. O. and Wilson, C. R. (1997), 'On the variability of the "
                    "Chandler frequency', Journal of Geophysical Research 102 (B9), 20439–20445"
                ),
                page=(
                    "the preferred estimate from the EOP93C01 series: F = 0.8433 ± 0.003 "
                    "cycles per year, a period of 433.1 ± 1.7 mean solar days"
                ),
                url="https://doi.org/10.1029/97JB01275",
                note=(
                    "the paper was not read here: the abstract (Semantic Scholar) and the "
                    "sentence with the estimate as scite.ai quotes it from the paper. The "
                    "scatter between methods is wider: Furuya and Chao (1996, Geophys. J. Int. "
                    "127, 693, 'Estimates of the Chandler wobble frequency and Q', abstract "
                    "read) find 439.5 days with atmospheric excitation against the maximum-"
                    "likelihood 433"
                ),
            ),
            Source(
                who="M. L. Smith and F. A. Dahlen",
                first_hand=False,
                where="Princeton",
                when="1981",
                publication=(
                    "Smith, M. L. and Dahlen, F. A. (1981), 'The period and Q of the Chandler "
                    "wobble', Geophysical Journal of the Royal Astronomical Society 64, 223–281"
                ),
                page="the elastic-mantle lengthening T_E ks/(ks − k2)",
                note=(
                    "the formula as the core documents it (RigidEarth.chandler_period, Munk & "
                    "MacDonald 1960; Smith & Dahlen 1981); the paper was not read here"
                ),
            ),
            _IERS,
        ),
        inputs={
            **_IERS_INPUTS,
            "k2": "0.30",
            "ks": "0.938",
        },
        quantity="period of the free wobble of the elastic Earth",
        measured="433.1 day",
        uncertainty="1.7 day",
        uncertainty_kind="the interval Vicente and Wilson state (its confidence level not read)",
        predict=_chandler,
        closed_form=_chandler,
        assumptions=(
            "symmetric Earth (A = B)",
            "an elastic mantle that yields to the wobble with Love number k2",
            "secular Love number ks from H",
            "no oceans, no fluid core, no anelasticity",
        ),
        story=(
            "Chandler's 427 days of 1891 were 40 % longer than Euler's rigid period, and "
            "Newcomb saw why at once: the Earth yields. The wobble's centrifugal force raises a "
            "pole tide in the solid Earth; the bulge then follows the axis part of the way, and "
            "the free motion slows by the factor ks/(ks − k2), the ratio of the fluid Love "
            "number to what the elastic Earth leaves of it. With the Love number k2 = 0.30 "
            "the rigid 304 days become about 446. A century of polar motion gives 433."
        ),
        expect="disagree",
        why=(
            "the model is the whole Earth yielding elastically: the fluid core, which does not "
            "follow the mantle's wobble, shortens the period, the oceans' pole tide lengthens "
            "it, and the mantle's anelasticity adds a few days; Smith & Dahlen (1981) model the "
            "three (their numbers not read here)"
        ),
        unit="day",
    ),
]
