"""Templates of the rotating Earth (the unit's eqs. 2.29–2.42): the dropped ball, the Coriolis
force on a train and on a river, Foucault's period, effective gravity and the plumb line."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ...earth import SIDEREAL_RATE, SOLAR_DAY_RATE, Earth
from .._steps import Derived, Mistake, Plain
from .._template import Param, Template

#: The unit's printed value of the Earth's rate, 2π/(24·3600) "= 7.25e-5 rad/s" (its arithmetic
#: slip: 2π/86400 is 7.272e-5; seed-errata.md, "Earth's rate").
UNIT_MISPRINTED_RATE = 7.25e-5
_G = 9.80665
_R = 6.371e6
_EARTH = {"omega": SIDEREAL_RATE, "g": _G, "R": _R}
_ARCMIN = math.pi / 10800
_DATA = " Take the sidereal day (ω = 7.292×10⁻⁵ rad/s) and g = 9.807 m/s²."

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


def _earth(rate: float = SIDEREAL_RATE) -> Earth:
    return Earth(rotation_rate=rate, g=_G, radius=_R)


def _geff(v: Any) -> Any:
    """The derivation's g_eff (2.31) at the variant's latitude, ENU (m/s²)."""
    return np.asarray(
        Derived("", "earth", "2.31", ("omega", "R", "g", "latitude"), "").evaluate_vector(v)
    )


def _coriolis_east(v: Any) -> float:
    """The derivation's Coriolis acceleration (2.30), east component, for v = (0, speed, 0)."""
    d = Derived("", "earth", "2.30", ("omega", "latitude", "vx", "speed", "vz"), "", component=0)
    return d.evaluate(v)


# ---- the dropped ball (2.41–2.42; the unit's long question L 5) ---------------------------------


def _deflection(v: Any, rate: float = SIDEREAL_RATE) -> float:
    return float(_earth(rate).eastward_deflection(v.height, v.latitude))


DROPPED_BALL = Template(
    name="dropped-ball",
    topic="earth",
    difficulty=1,
    title="The eastward deflection of a dropped ball",
    params=(
        Param("height", "m", 20, 300, 5),
        Param("latitude", "deg", 5, 75, 1),
    ),
    text="A ball is dropped from rest from a tower {height} high at latitude {latitude} N. "
    "Neglect air resistance." + _DATA,
    question="How far east of the foot of the plumb line does it land, to first order in ω, in mm?",
    unit="mm",
    answer=_deflection,
    check=lambda v: Derived("", "earth", "2.42", ("omega", "height", "latitude", "g"), "").evaluate(
        v
    ),
    agree=1e-12,
    agree_why="the core's 2.42 and the sympy derivation's 2.42 are the same closed form",
    steps=(
        Derived("Time of fall", "earth", "2.41", ("height", "g"), "T", "s"),
        Derived(
            "Eastward deflection, first order in ω",
            "earth",
            "2.42",
            ("omega", "height", "latitude", "g"),
            "x_E",
            "mm",
        ),
    ),
    mistakes=(
        Mistake(
            "solar day",
            "used the solar day 2π/86400 s for ω: the Earth turns once in a sidereal day",
            3,
            lambda v: _deflection(v, SOLAR_DAY_RATE),
        ),
        Mistake(
            "wrong-sign Coriolis",
            "took the Coriolis acceleration as +2ω×v: the ball is deflected east, not west",
            3,
            lambda v: -_deflection(v),
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
    constants=_EARTH,
    answer_range=(0.0, 200.0),
    source="The unit's eq. 2.42 and its worked number: 100 m at 45° gives 1.55 cm.",
)


# ---- the Coriolis force on a train (2.30) -----------------------------------------------------------


def _train_force(v: Any, rate: float = SIDEREAL_RATE) -> float:
    """The eastward component (N) of the Coriolis force on a train heading north."""
    a = _earth(rate).coriolis_acceleration(v.latitude, [0.0, v.speed, 0.0])
    return float(v.mass * a[0])


TRAIN = Template(
    name="train-coriolis",
    topic="earth",
    difficulty=1,
    title="The Coriolis force on a train",
    params=(
        Param("mass", "tonne", 100, 800, 10),
        Param("speed", "km/h", 60, 320, 10),
        Param("latitude", "deg", 10, 70, 1),
    ),
    text="A train of mass {mass} runs due north at {speed} along a straight level track at "
    "latitude {latitude} N." + _DATA,
    question="What is the eastward horizontal component of the force the rails must exert on it "
    "to keep it on the track (positive east, negative west), in kN?",
    unit="kN",
    answer=lambda v: -_train_force(v),
    check=lambda v: -v.mass * _coriolis_east(v),
    agree=1e-12,
    agree_why="the core's −2ω×v and the derivation's 2.30 are the same closed form",
    steps=(
        Derived(
            "The Coriolis acceleration's east component for v = (0, v, 0)",
            "earth",
            "2.30",
            ("omega", "latitude", "vx", "speed", "vz"),
            "a_E",
            "m/s**2",
            component=0,
        ),
        Plain(
            "The rails push the other way: F_E = −m a_E",
            r"-{mass}\,a_E",
            lambda v: -_train_force(v),
            "kN",
            "F_E",
        ),
    ),
    mistakes=(
        Mistake(
            "wrong-sign Coriolis",
            "took the Coriolis force as the force of the rails: they push against it, west",
            3,
            _train_force,
        ),
        Mistake(
            "solar day",
            "used the solar day for ω",
            2,
            lambda v: -_train_force(v, SOLAR_DAY_RATE),
        ),
        Mistake(
            "cos for sin",
            "used the horizontal part ω cos λ; a horizontal velocity meets the vertical ω sin λ",
            2,
            lambda v: -_train_force(v) / math.tan(v.latitude),
        ),
        Mistake(
            "factor 2",
            "forgot the factor 2 of the Coriolis term −2m ω×v",
            2,
            lambda v: -_train_force(v) / 2,
        ),
        Mistake(
            "the unit's 2.30 (no mass)",
            "copied the unit's 2.30, which lost the mass: that is an acceleration, not a force",
            3,
            lambda v: -_train_force(v) / v.mass * 1e3,
        ),
        Mistake(
            "km/h for m/s",
            "put the speed in km/h into the formula",
            1,
            lambda v: -_train_force(v) * 3.6,
        ),
    ),
    constants=_EARTH | {"vx": 0.0, "vz": 0.0},
    answer_range=(-1e3, 0.0),
)


# ---- the tilt of a river's surface (2.30, 2.31) ---------------------------------------------------


def _river_tilt(v: Any, rate: float = SIDEREAL_RATE) -> float:
    """The rise (m) of the east bank over the west one of a river flowing north (geostrophic
    balance: the surface tilts until its slope g·dh/dx cancels the Coriolis acceleration)."""
    earth = _earth(rate)
    a = earth.coriolis_acceleration(v.latitude, [0.0, v.speed, 0.0])
    return float(a[0] / earth.effective_gravity_magnitude(v.latitude) * v.width)


RIVER = Template(
    name="river-tilt",
    topic="earth",
    difficulty=2,
    title="The Coriolis tilt of a river",
    params=(
        Param("width", "m", 100, 2000, 50),
        Param("speed", "m/s", 0.5, 4.0, 0.1),
        Param("latitude", "deg", 15, 70, 1),
    ),
    text="A river {width} wide flows due north at {speed} at latitude {latitude} N. Its surface "
    "tilts across the stream until the slope of the surface balances the Coriolis force on the "
    "water." + _DATA,
    question="By how much does the east bank's water level stand above the west bank's "
    "(negative if below), in mm?",
    unit="mm",
    answer=_river_tilt,
    check=lambda v: _coriolis_east(v) * v.width / float(np.linalg.norm(_geff(v))),
    agree=1e-9,
    agree_why="the core's Coriolis and g_eff against the derivation's 2.30 and 2.31",
    steps=(
        Derived(
            "The Coriolis acceleration's east component",
            "earth",
            "2.30",
            ("omega", "latitude", "vx", "speed", "vz"),
            "a_E",
            "m/s**2",
            component=0,
        ),
        Plain(
            "The surface is normal to g_eff + Coriolis: slope a_E/g_eff over the width",
            r"\frac{{a_E}}{{g_\mathrm{{eff}}}}\,{width}",
            _river_tilt,
            "mm",
            r"\Delta h",
        ),
    ),
    mistakes=(
        Mistake(
            "wrong-sign Coriolis",
            "deflection to the left in the north",
            2,
            lambda v: -_river_tilt(v),
        ),
        Mistake(
            "solar day", "used the solar day for ω", 2, lambda v: _river_tilt(v, SOLAR_DAY_RATE)
        ),
        Mistake(
            "cos for sin",
            "used ω cos λ instead of the vertical part ω sin λ",
            2,
            lambda v: _river_tilt(v) / math.tan(v.latitude),
        ),
        Mistake("factor 2", "forgot the factor 2 of 2ω×v", 2, lambda v: _river_tilt(v) / 2),
    ),
    constants=_EARTH | {"vx": 0.0, "vz": 0.0},
    answer_range=(0.0, 200.0),
)


# ---- Foucault's period at a city --------------------------------------------------------------------


def _foucault_hours(v: Any, rate: float = SIDEREAL_RATE) -> float:
    """The time (s) for a Foucault pendulum's plane to turn once."""
    return float(2 * math.pi / abs(_earth(rate).foucault_rate(v.latitude)))


FOUCAULT = Template(
    name="foucault-period",
    topic="earth",
    difficulty=1,
    title="Foucault's pendulum at a city",
    params=(Param("latitude", "deg", choices=tuple(c for c in CITIES if abs(c[1]) > 10)),),
    text="A Foucault pendulum swings in {latitude@} (latitude {latitude}, positive north). "
    "The Earth turns once in a sidereal day: ω = 7.2921150×10⁻⁵ rad/s.",
    question="How long does its plane of swing take to turn through a full circle, in hours?",
    unit="h",
    answer=_foucault_hours,
    check=lambda v: 2 * math.pi / (v.omega * abs(math.sin(v.latitude))),
    agree=1e-12,
    agree_why="the core's Foucault rate −ω sin λ against 2π/(ω |sin λ|) by hand",
    steps=(
        Plain(
            "The plane turns at the vertical part of the Earth's rate, ω sin λ",
            r"\omega \sin\lambda = {omega} \sin {latitude}",
            lambda v: v.omega * abs(math.sin(v.latitude)),
            "rad/s",
            r"\Omega_F",
        ),
        Plain(
            "One turn takes 2π/(ω |sin λ|), the sidereal day over |sin λ|",
            r"\frac{{2\pi}}{{\Omega_F}}",
            _foucault_hours,
            "h",
            "T_F",
        ),
    ),
    mistakes=(
        Mistake(
            "solar day",
            "used 24 h for the day: the Earth turns once in 23 h 56 min",
            2,
            lambda v: _foucault_hours(v, SOLAR_DAY_RATE),
        ),
        Mistake(
            "cos for sin",
            "used cos λ (the colatitude's sine)",
            2,
            lambda v: _foucault_hours(v) * abs(math.sin(v.latitude) / math.cos(v.latitude)),
        ),
        Mistake(
            "half turn",
            "gave the time for half a turn (the swing looks the same)",
            3,
            lambda v: _foucault_hours(v) / 2,
        ),
    ),
    constants=_EARTH,
    answer_range=(23.9, 24 * 8.0),
    source="Foucault's 1851 pendulum in the Panthéon, Paris: about 31.8 h (sidereal day / sin 48.85°).",
)


# ---- effective gravity and the plumb line (2.31; the unit's long question L 4) ----------------------


def _plumb(v: Any, rate: float = SIDEREAL_RATE) -> float:
    return float(_earth(rate).plumb_line_deviation(v.latitude))


PLUMB = Template(
    name="plumb-line",
    topic="earth",
    difficulty=2,
    title="The plumb line's deviation",
    params=(Param("latitude", "deg", 5, 85, 1),),
    text="A plumb line hangs at rest at latitude {latitude} N on a spherical Earth of radius "
    "6371 km with the attraction of gravity g = 9.807 m/s²; ω = 7.292×10⁻⁵ rad/s.",
    question="By what angle does it deviate from the radial direction (towards the equator), "
    "in minutes of arc?",
    unit="arcmin",
    answer=_plumb,
    check=lambda v: math.atan2(-_geff(v)[1], -_geff(v)[2]),
    agree=1e-9,
    agree_why="the core's g_eff against the derivation's 2.31 (sympy, evaluated)",
    steps=(
        Derived(
            "The effective gravity's north component, g − ω×(ω×r)",
            "earth",
            "2.31",
            ("omega", "R", "g", "latitude"),
            r"g_{\mathrm{eff},N}",
            "m/s**2",
            component=1,
        ),
        Derived(
            "Its vertical component",
            "earth",
            "2.31",
            ("omega", "R", "g", "latitude"),
            r"g_{\mathrm{eff},U}",
            "m/s**2",
            component=2,
        ),
        Plain(
            "The angle between g_eff and the vertical",
            r"\arctan\frac{{|g_N|}}{{|g_U|}}",
            _plumb,
            "arcmin",
            r"\delta",
        ),
    ),
    mistakes=(
        Mistake(
            "degrees, not arcmin",
            "gave the angle in degrees",
            4,
            lambda v: math.degrees(_plumb(v)) * _ARCMIN,
        ),
        Mistake(
            "radians, not arcmin", "gave the angle in radians", 4, lambda v: _plumb(v) * _ARCMIN
        ),
        Mistake("solar day", "used the solar day for ω", 2, lambda v: _plumb(v, SOLAR_DAY_RATE)),
    ),
    constants=_EARTH,
    answer_range=(0.0, 7.0),
)


def _geff_mag(v: Any, rate: float = SIDEREAL_RATE) -> float:
    return float(_earth(rate).effective_gravity_magnitude(v.latitude))


G_EFFECTIVE = Template(
    name="g-effective",
    topic="earth",
    difficulty=1,
    title="Effective gravity at a latitude",
    params=(Param("latitude", "deg", 0, 85, 1),),
    text="On a spherical Earth of radius 6371 km whose attraction alone gives g = 9.807 m/s², "
    "turning at ω = 7.292×10⁻⁵ rad/s, a stone rests on the ground at latitude {latitude}.",
    question="What is the magnitude of the effective gravity g_eff there, in m/s²?",
    unit="m/s**2",
    answer=_geff_mag,
    check=lambda v: float(np.linalg.norm(_geff(v))),
    agree=1e-12,
    agree_why="the core's |g − ω×(ω×r)| against the derivation's 2.31",
    steps=(
        Derived(
            "The centrifugal acceleration −ω×(ω×r) at the surface: north component",
            "earth",
            "centrifugal",
            ("omega", "R", "latitude"),
            r"a_N",
            "m/s**2",
            component=1,
        ),
        Derived(
            "Its upward component",
            "earth",
            "centrifugal",
            ("omega", "R", "latitude"),
            r"a_U",
            "m/s**2",
            component=2,
        ),
        Plain(
            "g_eff = (0, a_N, a_U − g): its magnitude",
            r"\sqrt{{a_N^2 + (g - a_U)^2}}",
            _geff_mag,
            "m/s**2",
            r"g_\mathrm{{eff}}",
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
    constants=_EARTH,
    answer_range=(9.77, 9.81),
)


# ---- the southward deflection, second order in ω (2.42c) -----------------------------------------


def _south(v: Any, rate: float = SIDEREAL_RATE) -> float:
    return float(_earth(rate).southward_deflection(v.height, v.latitude))


SOUTHWARD = Template(
    name="southward-deflection",
    topic="earth",
    difficulty=3,
    title="The southward deflection of a dropped ball",
    params=(
        Param("height", "m", 50, 500, 10),
        Param("latitude", "deg", 10, 80, 1),
    ),
    text="A ball is dropped from rest from a height of {height} at latitude {latitude} N, in "
    "uniform gravity and without air." + _DATA,
    question="How far south of the foot of the plumb line does it land, to second order in ω, "
    "in µm?",
    unit="um",
    answer=_south,
    check=lambda v: Derived(
        "", "earth", "2.42c", ("omega", "height", "latitude", "g"), ""
    ).evaluate(v),
    agree=1e-12,
    agree_why="the core's ¾ω² sin 2λ h²/g against the derivation's 2.42c",
    steps=(
        Derived("Time of fall", "earth", "2.41", ("height", "g"), "T", "s"),
        Derived(
            "Coriolis on the eastward drift and the centrifugal change with height, second order",
            "earth",
            "2.42c",
            ("omega", "height", "latitude", "g"),
            "y_S",
            "um",
        ),
    ),
    mistakes=(
        Mistake(
            "Coriolis only",
            "kept only the Coriolis part (⅓ of ¾): the centrifugal force changes with height too",
            3,
            lambda v: _south(v) * 4 / 9,
        ),
        Mistake("solar day", "used the solar day for ω", 3, lambda v: _south(v, SOLAR_DAY_RATE)),
        Mistake(
            "sin λ for sin 2λ",
            "wrote sin λ where the product sin λ cos λ = ½ sin 2λ appears",
            3,
            lambda v: _south(v) * math.sin(v.latitude) / math.sin(2 * v.latitude),
        ),
    ),
    constants=_EARTH,
    answer_range=(0.0, 1e3),
)


# ---- inertial oscillations: an ocean current left to itself ----------------------------------------


def _inertial_hours(v: Any, rate: float = SIDEREAL_RATE) -> float:
    return float(_earth(rate).inertial_period(v.latitude))


INERTIAL = Template(
    name="inertial-period",
    topic="earth",
    difficulty=2,
    title="The period of inertial oscillations",
    params=(Param("latitude", "deg", 10, 80, 1),),
    text="After a storm, the surface water of a calm sea at latitude {latitude} N keeps moving, "
    "free of forces but for the Coriolis force, on circles (inertial oscillations). "
    "ω = 7.2921150×10⁻⁵ rad/s.",
    question="How long does one circle take, in hours?",
    unit="h",
    answer=_inertial_hours,
    check=lambda v: math.pi / (v.omega * abs(math.sin(v.latitude))),
    agree=1e-12,
    agree_why="the core's π/(ω |sin λ|) against the same by hand",
    steps=(
        Derived(
            "The horizontal Coriolis acceleration of a horizontal velocity: its east part",
            "earth",
            "2.30",
            ("omega", "latitude", "vx", "one", "vz"),
            r"f = a_E / v",
            "rad/s",
            component=0,
        ),
        Plain(
            "v turns at the Coriolis parameter f = 2ω sin λ: one circle takes 2π/f",
            r"\frac{{2\pi}}{{f}}",
            _inertial_hours,
            "h",
            "T_i",
        ),
    ),
    mistakes=(
        Mistake(
            "Foucault's period",
            "took 2π/(ω sin λ), the Foucault period: the velocity turns at 2ω sin λ",
            3,
            lambda v: 2 * _inertial_hours(v),
        ),
        Mistake(
            "solar day", "used the solar day for ω", 3, lambda v: _inertial_hours(v, SOLAR_DAY_RATE)
        ),
        Mistake(
            "cos for sin",
            "used cos λ: the vertical part ω sin λ turns horizontal motion",
            2,
            lambda v: _inertial_hours(v) * math.sin(v.latitude) / math.cos(v.latitude),
        ),
    ),
    constants=_EARTH | {"vx": 0.0, "vz": 0.0, "one": 1.0},
    answer_range=(12.0, 72.0),
)

ENTRIES = (DROPPED_BALL, SOUTHWARD, TRAIN, RIVER, FOUCAULT, INERTIAL, PLUMB, G_EFFECTIVE)
