"""Templates of the rotating Earth (the unit's eqs. 2.29–2.42): the dropped ball, the Coriolis
force on a train and on a river, Foucault's period, effective gravity and the plumb line."""

from __future__ import annotations

import math
from collections.abc import Callable
from functools import partial
from typing import Any

import numpy as np

from ...earth import SIDEREAL_RATE, Earth
from .._build import derived, draws, formula, plain, prose, route, scaled, solar_day
from .._steps import Derived, Mistake
from .._template import Template

#: The unit's printed value of the Earth's rate, 2π/(24·3600) "= 7.25e-5 rad/s" (its arithmetic
#: slip: 2π/86400 is 7.272e-5; seed-errata.md, "Earth's rate").
UNIT_MISPRINTED_RATE = 7.25e-5
_G = 9.80665
_R = 6.371e6
_EARTH = {"omega": SIDEREAL_RATE, "g": _G, "R": _R}
_ARCMIN = math.pi / 10800
_DATA = "Take the sidereal day (ω = 7.292×10⁻⁵ rad/s) and g = 9.807 m/s²."

#: Cities with a Foucault pendulum and their latitudes (degrees north, to 0.01°).
CITIES = (
    ("Paris (Panthéon)", 48.85),
    ("London", 51.51),
    ("Washington DC", 38.89),
    ("Oslo", 59.91),
    ("Rome", 41.90),
    ("Moscow", 55.76),
    ("Helsinki", 60.17),
    ("Singapore", 1.35),
    ("Quito", -0.18),
    ("Cape Town", -33.92),
    ("Sydney", -33.87),
    ("Reykjavík", 64.15),
    ("Chennai", 13.08),
    ("Tokyo", 35.68),
)
#: The cities away from the equator (a Foucault period under 2 sidereal days... at most 8).
_FOUCAULT_CITIES = tuple(c for c in CITIES if abs(c[1]) > 10)

#: A template of this topic: the Earth's ω, g and R as every variant's constants.
_earth_template = partial(Template, topic="earth", constants=_EARTH)
#: The constants of a horizontal velocity (0, v, 0) northward.
_NORTHWARD = _EARTH | {"vx": 0.0, "vz": 0.0}
_CORIOLIS_EAST = "earth 2.30[0](omega, latitude, vx, speed, vz)"
_G_EFF = "earth 2.31(omega, R, g, latitude)"


def _earth(rate: float = SIDEREAL_RATE) -> Earth:
    return Earth(rotation_rate=rate, g=_G, radius=_R)


def _core(method: str, *args: str) -> Callable[..., float]:
    """The answer (SI) by the core's ``Earth.method`` of the variant's values ``args``, on an
    Earth turning at ``rate`` (the sidereal rate, or a mistaken one)."""

    def answer(v: Any, rate: float = SIDEREAL_RATE) -> float:
        return float(getattr(_earth(rate), method)(*(getattr(v, a) for a in args)))

    return answer


#: The answers (SI) by the core, on an Earth turning at the sidereal rate or a mistaken one.
_deflection = _core("eastward_deflection", "height", "latitude")
_plumb = _core("plumb_line_deviation", "latitude")
_geff_mag = _core("effective_gravity_magnitude", "latitude")
_south = _core("southward_deflection", "height", "latitude")
_inertial_hours = _core("inertial_period", "latitude")


def _cos_for_sin(answer: Callable[[Any], float], text: str) -> Mistake:
    """The horizontal part ω cos λ of the Earth's rate taken where a horizontal velocity meets
    the vertical part ω sin λ (at step 2: the Coriolis acceleration)."""
    return Mistake("cos for sin", text, 2, lambda v: answer(v) / math.tan(v.latitude))


def _dropped(deflection: Derived, **fields: Any) -> Template:
    """A ball dropped from rest at a latitude, worked from the time of fall to ``deflection``: its
    derived formula is the second route, the same closed form as the core's (to 1e-12)."""
    fall = derived("Time of fall", "T [s] = earth 2.41(height, g)")
    return _earth_template(steps=(fall, deflection), agree=1e-12, **fields)


def _geff(v: Any) -> Any:
    """The derivation's g_eff (2.31) at the variant's latitude, ENU (m/s²)."""
    return np.asarray(formula(_G_EFF).evaluate_vector(v))


#: The derivation's Coriolis acceleration (2.30), east component, for v = (0, speed, 0).
_coriolis_east = route(_CORIOLIS_EAST)


# ---- the dropped ball (2.41–2.42; the unit's long question L 5) ---------------------------------


DROPPED_BALL = _dropped(
    derived(
        "Eastward deflection, first order in ω",
        "x_E [mm] = earth 2.42(omega, height, latitude, g)",
    ),
    name="dropped-ball",
    title="The eastward deflection of a dropped ball",
    text=prose(
        """A ball is dropped from rest from a tower {height} high at latitude {latitude} N.
        Neglect air resistance.""",
        _DATA,
    ),
    params=draws("m", height=(20, 300, 5)) + draws("deg", latitude=(5, 75, 1)),
    question="How far east of the foot of the plumb line does it land, to first order in ω, in mm?",
    answer=_deflection,
    agree_why="the core's 2.42 and the sympy derivation's 2.42 are the same closed form",
    mistakes=(
        solar_day(
            3,
            _deflection,
            "used the solar day 2π/86400 s for ω: the Earth turns once in a sidereal day",
        ),
        scaled(
            "wrong-sign Coriolis",
            "took the Coriolis acceleration as +2ω×v: the ball is deflected east, not west",
            3,
            _deflection,
            -1.0,
        ),
        Mistake(
            "degrees for radians",
            "put the latitude in degrees into cos λ",
            3,
            lambda v: _deflection(v) * math.cos(math.degrees(v.latitude)) / math.cos(v.latitude),
        ),
        Mistake(
            "sin for cos",
            "used sin λ (the vertical part of ω) where the horizontal part ω cos λ acts",
            3,
            lambda v: _deflection(v) * math.tan(v.latitude),
        ),
        Mistake(
            "the unit's 7.25e-5",
            "used the unit's misprinted ω = 7.25×10⁻⁵ rad/s (2π/86400 is 7.272×10⁻⁵)",
            3,
            lambda v: _deflection(v, UNIT_MISPRINTED_RATE),
        ),
    ),
    difficulty=1,
    answer_range=(0.0, 200.0),
    source="The unit's eq. 2.42 and its worked number: 100 m at 45° gives 1.55 cm.",
)


# ---- the Coriolis force on a train (2.30) -----------------------------------------------------------


def _train_force(v: Any, rate: float = SIDEREAL_RATE) -> float:
    """The eastward component (N) of the Coriolis force on a train heading north."""
    a = _earth(rate).coriolis_acceleration(v.latitude, [0.0, v.speed, 0.0])
    return float(v.mass * a[0])


def _rails(v: Any, rate: float = SIDEREAL_RATE) -> float:
    """The eastward force (N) of the rails: against the Coriolis force."""
    return -_train_force(v, rate)


TRAIN = _earth_template(
    name="train-coriolis",
    title="The Coriolis force on a train",
    text=prose(
        """A train of mass {mass} runs due north at {speed} along a straight level track at
        latitude {latitude} N.""",
        _DATA,
    ),
    params=draws("tonne", mass=(100, 800, 10))
    + draws("km/h", speed=(60, 320, 10))
    + draws("deg", latitude=(10, 70, 1)),
    question=prose("""What is the eastward horizontal component of the force the rails must exert
        on it to keep it on the track (positive east, negative west), in kN?"""),
    answer=_rails,
    check=lambda v: -v.mass * _coriolis_east(v),
    agree=1e-12,
    agree_why="the core's −2ω×v and the derivation's 2.30 are the same closed form",
    steps=(
        derived(
            "The Coriolis acceleration's east component for v = (0, v, 0)",
            f"a_E [m/s**2] = {_CORIOLIS_EAST}",
        ),
        plain("The rails push the other way: F_E = −m a_E", r"F_E [kN] = -{mass}\,a_E", _rails),
    ),
    mistakes=(
        Mistake(
            "wrong-sign Coriolis",
            "took the Coriolis force as the force of the rails: they push against it, west",
            3,
            _train_force,
        ),
        solar_day(2, _rails),
        _cos_for_sin(
            _rails,
            "used the horizontal part ω cos λ; a horizontal velocity meets the vertical ω sin λ",
        ),
        scaled("factor 2", "forgot the factor 2 of the Coriolis term −2m ω×v", 2, _rails, 0.5),
        Mistake(
            "the unit's 2.30 (no mass)",
            "copied the unit's 2.30, which lost the mass: that is an acceleration, not a force",
            3,
            lambda v: _rails(v) / v.mass * 1e3,
        ),
        scaled("km/h for m/s", "put the speed in km/h into the formula", 1, _rails, 3.6),
    ),
    difficulty=1,
    answer_range=(-1e3, 0.0),
    constants=_NORTHWARD,
)


# ---- the tilt of a river's surface (2.30, 2.31) ---------------------------------------------------


def _river_tilt(v: Any, rate: float = SIDEREAL_RATE) -> float:
    """The rise (m) of the east bank over the west one of a river flowing north (geostrophic
    balance: the surface tilts until its slope g·dh/dx cancels the Coriolis acceleration)."""
    earth = _earth(rate)
    a = earth.coriolis_acceleration(v.latitude, [0.0, v.speed, 0.0])
    return float(a[0] / earth.effective_gravity_magnitude(v.latitude) * v.width)


RIVER = _earth_template(
    name="river-tilt",
    title="The Coriolis tilt of a river",
    text=prose(
        """A river {width} wide flows due north at {speed} at latitude {latitude} N. Its
        surface tilts across the stream until the slope of the surface balances the Coriolis force
        on the water.""",
        _DATA,
    ),
    params=draws("m", width=(100, 2000, 50))
    + draws("m/s", speed=(0.5, 4.0, 0.1))
    + draws("deg", latitude=(15, 70, 1)),
    question=prose("""By how much does the east bank's water level stand above the west bank's
        (negative if below), in mm?"""),
    answer=_river_tilt,
    check=lambda v: _coriolis_east(v) * v.width / float(np.linalg.norm(_geff(v))),
    agree=1e-9,
    agree_why="the core's Coriolis and g_eff against the derivation's 2.30 and 2.31",
    steps=(
        derived("The Coriolis acceleration's east component", f"a_E [m/s**2] = {_CORIOLIS_EAST}"),
        plain(
            "The surface is normal to g_eff + Coriolis: slope a_E/g_eff over the width",
            r"\Delta h [mm] = \frac{{a_E}}{{g_\mathrm{{eff}}}}\,{width}",
            _river_tilt,
        ),
    ),
    mistakes=(
        scaled("wrong-sign Coriolis", "deflection to the left in the north", 2, _river_tilt, -1.0),
        solar_day(2, _river_tilt),
        _cos_for_sin(_river_tilt, "used ω cos λ instead of the vertical part ω sin λ"),
        scaled("factor 2", "forgot the factor 2 of 2ω×v", 2, _river_tilt, 0.5),
    ),
    difficulty=2,
    answer_range=(0.0, 200.0),
    constants=_NORTHWARD,
)


# ---- Foucault's period at a city --------------------------------------------------------------------


def _foucault_hours(v: Any, rate: float = SIDEREAL_RATE) -> float:
    """The time (s) for a Foucault pendulum's plane to turn once."""
    return float(2 * math.pi / abs(_earth(rate).foucault_rate(v.latitude)))


FOUCAULT = _earth_template(
    name="foucault-period",
    title="Foucault's pendulum at a city",
    text=prose("""A Foucault pendulum swings in {latitude@} (latitude {latitude}, positive north).
        The Earth turns once in a sidereal day: ω = 7.2921150×10⁻⁵ rad/s."""),
    params=draws("deg", latitude=_FOUCAULT_CITIES),
    question="How long does its plane of swing take to turn through a full circle, in hours?",
    answer=_foucault_hours,
    check=lambda v: 2 * math.pi / (v.omega * abs(math.sin(v.latitude))),
    agree=1e-12,
    agree_why="the core's Foucault rate −ω sin λ against 2π/(ω |sin λ|) by hand",
    steps=(
        plain(
            "The plane turns at the vertical part of the Earth's rate, ω sin λ",
            r"\Omega_F [rad/s] = \omega \sin\lambda = {omega} \sin {latitude}",
            lambda v: v.omega * abs(math.sin(v.latitude)),
        ),
        plain(
            "One turn takes 2π/(ω |sin λ|), the sidereal day over |sin λ|",
            r"T_F [h] = \frac{{2\pi}}{{\Omega_F}}",
            _foucault_hours,
        ),
    ),
    mistakes=(
        solar_day(2, _foucault_hours, "used 24 h for the day: the Earth turns once in 23 h 56 min"),
        Mistake(
            "cos for sin",
            "used cos λ (the colatitude's sine)",
            2,
            lambda v: _foucault_hours(v) * abs(math.sin(v.latitude) / math.cos(v.latitude)),
        ),
        scaled(
            "half turn",
            "gave the time for half a turn (the swing looks the same)",
            3,
            _foucault_hours,
            0.5,
        ),
    ),
    difficulty=1,
    answer_range=(23.9, 24 * 8.0),
    source="Foucault's 1851 pendulum in the Panthéon, Paris: about 31.8 h (sidereal day / sin 48.85°).",
)


# ---- effective gravity and the plumb line (2.31; the unit's long question L 4) ----------------------


PLUMB = _earth_template(
    name="plumb-line",
    title="The plumb line's deviation",
    text=prose("""A plumb line hangs at rest at latitude {latitude} N on a spherical Earth of
        radius 6371 km with the attraction of gravity g = 9.807 m/s²; ω = 7.292×10⁻⁵ rad/s."""),
    params=draws("deg", latitude=(5, 85, 1)),
    question=prose("""By what angle does it deviate from the radial direction (towards the
        equator), in minutes of arc?"""),
    answer=_plumb,
    check=lambda v: math.atan2(-_geff(v)[1], -_geff(v)[2]),
    agree=1e-9,
    agree_why="the core's g_eff against the derivation's 2.31 (sympy, evaluated)",
    steps=(
        derived(
            "The effective gravity's north component, g − ω×(ω×r)",
            r"g_{\mathrm{eff},N} [m/s**2] = earth 2.31[1](omega, R, g, latitude)",
        ),
        derived(
            "Its vertical component",
            r"g_{\mathrm{eff},U} [m/s**2] = earth 2.31[2](omega, R, g, latitude)",
        ),
        plain(
            "The angle between g_eff and the vertical",
            r"\delta [arcmin] = \arctan\frac{{|g_N|}}{{|g_U|}}",
            _plumb,
        ),
    ),
    mistakes=(
        Mistake(
            "degrees, not arcmin",
            "gave the angle in degrees",
            4,
            lambda v: math.degrees(_plumb(v)) * _ARCMIN,
        ),
        scaled("radians, not arcmin", "gave the angle in radians", 4, _plumb, _ARCMIN),
        solar_day(2, _plumb),
    ),
    difficulty=2,
    answer_range=(0.0, 7.0),
)


G_EFFECTIVE = _earth_template(
    name="g-effective",
    title="Effective gravity at a latitude",
    text=prose("""On a spherical Earth of radius 6371 km whose attraction alone gives g = 9.807
        m/s², turning at ω = 7.292×10⁻⁵ rad/s, a stone rests on the ground at latitude
        {latitude}."""),
    params=draws("deg", latitude=(0, 85, 1)),
    question="What is the magnitude of the effective gravity g_eff there, in m/s²?",
    answer=_geff_mag,
    check=lambda v: float(np.linalg.norm(_geff(v))),
    agree=1e-12,
    agree_why="the core's |g − ω×(ω×r)| against the derivation's 2.31",
    steps=(
        derived(
            "The centrifugal acceleration −ω×(ω×r) at the surface: north component",
            "a_N [m/s**2] = earth centrifugal[1](omega, R, latitude)",
        ),
        derived("Its upward component", "a_U [m/s**2] = earth centrifugal[2](omega, R, latitude)"),
        plain(
            "g_eff = (0, a_N, a_U − g): its magnitude",
            r"g_\mathrm{{eff}} [m/s**2] = \sqrt{{a_N^2 + (g - a_U)^2}}",
            _geff_mag,
        ),
    ),
    mistakes=(
        Mistake(
            "no cos λ",
            "took the whole ω²R off g, as at the equator",
            3,
            lambda v: v.g - v.omega**2 * v.R,
        ),
        Mistake(
            "added",
            "added the centrifugal term instead of subtracting it",
            4,
            lambda v: 2 * v.g - _geff_mag(v),
        ),
    ),
    difficulty=1,
    answer_range=(9.77, 9.81),
)


# ---- the southward deflection, second order in ω (2.42c) -----------------------------------------


SOUTHWARD = _dropped(
    derived(
        "Coriolis on the eastward drift and the centrifugal change with height, second order",
        "y_S [um] = earth 2.42c(omega, height, latitude, g)",
    ),
    name="southward-deflection",
    title="The southward deflection of a dropped ball",
    text=prose(
        """A ball is dropped from rest from a height of {height} at latitude {latitude} N,
        in uniform gravity and without air.""",
        _DATA,
    ),
    params=draws("m", height=(50, 500, 10)) + draws("deg", latitude=(10, 80, 1)),
    question=prose("""How far south of the foot of the plumb line does it land, to second order in
        ω, in µm?"""),
    answer=_south,
    agree_why="the core's ¾ω² sin 2λ h²/g against the derivation's 2.42c",
    mistakes=(
        Mistake(
            "Coriolis only",
            "kept only the Coriolis part (⅓ of ¾): the centrifugal force changes with height too",
            3,
            lambda v: _south(v) * 4 / 9,
        ),
        solar_day(3, _south),
        Mistake(
            "sin λ for sin 2λ",
            "wrote sin λ where the product sin λ cos λ = ½ sin 2λ appears",
            3,
            lambda v: _south(v) * math.sin(v.latitude) / math.sin(2 * v.latitude),
        ),
    ),
    difficulty=3,
    answer_range=(0.0, 1e3),
)


# ---- inertial oscillations: an ocean current left to itself ----------------------------------------


INERTIAL = _earth_template(
    name="inertial-period",
    title="The period of inertial oscillations",
    text=prose("""After a storm, the surface water of a calm sea at latitude {latitude} N keeps
        moving, free of forces but for the Coriolis force, on circles (inertial oscillations). ω =
        7.2921150×10⁻⁵ rad/s."""),
    params=draws("deg", latitude=(10, 80, 1)),
    question="How long does one circle take, in hours?",
    answer=_inertial_hours,
    check=lambda v: math.pi / (v.omega * abs(math.sin(v.latitude))),
    agree=1e-12,
    agree_why="the core's π/(ω |sin λ|) against the same by hand",
    steps=(
        derived(
            "The horizontal Coriolis acceleration of a horizontal velocity: its east part",
            "f = a_E / v [rad/s] = earth 2.30[0](omega, latitude, vx, one, vz)",
        ),
        plain(
            "v turns at the Coriolis parameter f = 2ω sin λ: one circle takes 2π/f",
            r"T_i [h] = \frac{{2\pi}}{{f}}",
            _inertial_hours,
        ),
    ),
    mistakes=(
        scaled(
            "Foucault's period",
            "took 2π/(ω sin λ), the Foucault period: the velocity turns at 2ω sin λ",
            3,
            _inertial_hours,
            2.0,
        ),
        solar_day(3, _inertial_hours),
        Mistake(
            "cos for sin",
            "used cos λ: the vertical part ω sin λ turns horizontal motion",
            2,
            lambda v: _inertial_hours(v) * math.sin(v.latitude) / math.cos(v.latitude),
        ),
    ),
    difficulty=2,
    answer_range=(12.0, 72.0),
    constants=_NORTHWARD | {"one": 1.0},
)

ENTRIES = (DROPPED_BALL, SOUTHWARD, TRAIN, RIVER, FOUCAULT, INERTIAL, PLUMB, G_EFFECTIVE)
