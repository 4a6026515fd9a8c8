"""The answer in plain words that each computing command of ``poinsot`` prints first.

Each function here takes the result a command prints with ``--json`` (the same numbers as its
tables) and returns one or two sentences a student can quote: what the body does, with the
figures rounded for reading (3 significant digits, 2 for percentages). Only wording lives here;
every number and every fact of the physics is read from the result (the period of a turn, |ω|
of a steady rotation, the axis ω circles or flips about, the pole a top passes through: the
core's), none is computed again except a unit change (rad → °, s → min or h, m → cm or km),
the difference of the two printed turning points, and the ratio of two printed quantities
(how far the spin is above the least for steady precession).
"""

from __future__ import annotations

import math
from typing import Any

#: Significant digits of the numbers in a sentence (percentages: 2).
DIGITS = 3


def num(x: float, digits: int = DIGITS) -> str:
    """``x`` rounded to ``digits`` significant digits, written without an exponent between
    1e-3 and 1e6 ("5.8", "1.08", "1230", "0.0155"; trailing zeros dropped: "45", not "45.0")
    and with one outside ("5.49e-05")."""
    if x == 0 or not math.isfinite(x):
        return "0" if x == 0 else str(x)
    a = abs(x)
    if 1e-3 <= a < 1e6:
        place = digits - 1 - math.floor(math.log10(a))  # < 0: round to tens, hundreds, ...
        decimals = max(0, place)
        text = f"{round(x, place):.{decimals}f}"
        # rounding up may add a digit (9.996 → "10.00"): drop the extra decimal
        if decimals > 0 and len(text.lstrip("-").replace(".", "").lstrip("0")) > digits:
            text = text[:-1]
        # trailing zeros say nothing a student needs: "45", "1.5"
        return text.rstrip("0").rstrip(".") if "." in text else text
    return f"{x:.{digits - 1}e}"


def given(x: float) -> str:
    """A number the user gave, as short as it prints ("45", "0.8", "1e+04")."""
    return f"{x:g}"


def degrees(rad: float) -> str:
    """An angle in radians, written in degrees ("45.8°")."""
    return f"{num(math.degrees(rad))}°"


def angle(value: float, in_degrees: bool) -> str:
    """An angle as the user gave it: "45°" with --degrees, else "0.8 rad (45.8°)" — the degrees
    beside radians, so that `--latitude 0.8` meant as 0.8° is seen to run at 45.8°."""
    if in_degrees:
        return f"{given(value)}°"
    return f"{given(value)} rad ({degrees(value)})" if value != 0 else "0 rad"


def length(m: float) -> str:
    """A length in m, in the unit a student reads it in: km, m, cm, mm or µm ("1.55 cm")."""
    a = abs(m)
    for unit, size in LENGTH_UNITS[:-1]:
        if a >= size:
            return f"{num(m / size)} {unit}"
    unit, size = LENGTH_UNITS[-1]
    return f"{num(m / size)} {unit}"


#: The units a sentence writes lengths in, largest first, with their size in m.
LENGTH_UNITS = (("km", 1e3), ("m", 1.0), ("cm", 1e-2), ("mm", 1e-3), ("µm", 1e-6))
#: The units a sentence writes times in, with their size in s.
TIME_UNITS = (("s", 1.0), ("min", 60.0), ("h", 3600.0))


def duration(s: float) -> str:
    """A time in s, in seconds up to 2 minutes, minutes up to 2 hours, hours beyond."""
    if abs(s) < 120:
        return f"{num(s)} s"
    if abs(s) < 7200:
        return f"{num(s / 60)} min"
    return f"{num(s / 3600)} h"


def _spin_clause(data: dict[str, Any]) -> str:
    """How the spin compares with the least for steady precession at θ₀ (2.119)."""
    w = abs(data["omega3"])
    steady = data["steady_precession_at_theta0"]
    least = steady["min_spin_2_119"]
    if least == 0:
        return "tilted below the horizontal, it could precess steadily at any spin"
    if "error" in steady and w == 0:
        return (
            f"without spin it cannot precess steadily at this tilt (that needs at least "
            f"{num(least)} rad/s)"
        )
    if "error" in steady:
        below = (1 - w / least) * 100
        return (
            f"the spin of {num(w)} rad/s is {num(below, 2)} % below the least for steady "
            f"precession at this tilt ({num(least)} rad/s), so it cannot precess steadily there"
        )
    ratio = w / least
    if ratio >= 2:
        return (
            f"the spin is {num(ratio)} times the least for steady precession ({num(least)} rad/s)"
        )
    above = (ratio - 1) * 100
    only = "only " if above < 20 else ""
    return (
        f"the spin is {only}{num(above, 2)} % above the least for steady precession "
        f"({num(least)} rad/s)"
    )


#: What the axis' path looks like, per motion class of a nutating top.
_PATHS = {
    "waves": "its axis traces waves (it always moves forward)",
    "loops": "its axis traces loops (it moves backward at the top of each nod)",
    "cusps": "its axis traces cusps (it stops at the top of each nod, as a top released "
    "without precession does)",
}


#: Where the axis of a top of the class "through vertical" passes, per pole (the core's
#: ``HeavyTop.vertical_pass``).
_POLES = {
    "upright": "the upright position",
    "straight down": "the straight down position",
    "both": "both the upright and the straight down positions",
}


def _turning(data: dict[str, Any], mean: str = "") -> str:
    """The precession: its rate (``mean``: " on average" for the mean of a nutating top) and the
    period of one turn, or that the axis does not turn."""
    rate, period = abs(data["mean_precession_rate"]), data["precession_period"]
    if rate == 0 or not math.isfinite(period):
        return "does not turn about the vertical on average"
    return f"at {num(rate)} rad/s{mean}, one turn every {duration(period)}"


def top(data: dict[str, Any]) -> str:
    """``poinsot top``: how the heavy top moves, by motion class."""
    cls = data["motion_class"]
    w = abs(data["omega3"])
    t1, t2 = data["turning_points"]
    nod = data["nutation_period"]
    threshold = data["sleeping_threshold"]
    if cls == "sleeping":
        if data["sleeping_stable"]:
            return (
                f"The top sleeps: it spins upright at {num(w)} rad/s, above the sleeping "
                f"threshold of {num(threshold)} rad/s, so it stays up without wobbling."
            )
        return (
            f"The top spins upright at {num(w)} rad/s, below the sleeping threshold of "
            f"{num(threshold)} rad/s: it cannot stay upright, and the smallest push topples it."
        )
    if cls == "hanging":
        return (
            f"The top hangs straight down from its pivot, spinning at {num(w)} rad/s; "
            "it does not precess."
        )
    if cls == "steady precession":
        return (
            f"The top precesses steadily {_turning(data)}, its axis held at {degrees(t1)} from "
            f"the vertical; {_spin_clause(data)}."
        )
    if cls == "through vertical":
        return (
            f"The top's axis swings through {_POLES[data['vertical_pass']]}, between "
            f"{degrees(t1)} and "
            f"{degrees(t2)} from the vertical, every {duration(nod)}, its azimuth jumping by half "
            "a turn at each pass; " + _spin_clause(data) + "."
        )
    path = _PATHS.get(cls, f"its axis' path is of the class '{cls}'")
    turning = _turning(data, " on average")
    opening = (
        f"The top precesses {turning}" if not turning.startswith("does") else f"The top {turning}"
    )
    nodding = (
        f"nodding between {degrees(t1)} and {degrees(t2)}"
        if degrees(t1) != degrees(t2)
        else f"nodding by only {num(math.degrees(t2 - t1))}° about {degrees(t1)}"
    )
    return f"{opening}, {nodding} every {duration(nod)}; {path}; {_spin_clause(data)}."


def fall(data: dict[str, Any]) -> str:
    """``poinsot fall``: where the dropped body lands."""
    east, south = data["east"], -data["north"]
    return (
        f"Dropped from {given(data['height'])} m at latitude "
        f"{angle(data['latitude'], data['degrees'])}, the body falls for {num(data['time'])} s "
        f"and lands {length(abs(east))} {'east' if east >= 0 else 'west'} of the point straight "
        f"below (eq. 2.42 gives {length(abs(data['first_order_east']))}) and "
        f"{length(abs(south))} {'south' if south >= 0 else 'north'} of it."
    )


def projectile(data: dict[str, Any], drift: str) -> str:
    """``poinsot projectile``: how far the projectile flies and how the Earth's rotation moves
    its landing point; ``drift`` is the drift as the table prints it ("0" below round-off)."""
    spin = data["with_rotation"]
    deg = data["degrees"]
    opening = (
        f"Fired at {given(data['speed'])} m/s, {angle(data['elevation'], deg)} above the horizon "
        f"towards azimuth {angle(data['azimuth'], deg)} at latitude "
        f"{angle(data['latitude'], deg)}, the projectile flies for {num(spin['time'])} s and "
        f"lands {length(spin['range'])} away"
    )
    if drift == "0":
        return f"{opening}; the Earth's rotation does not move it sideways."
    d = spin["drift"]
    side = "right" if d > 0 else "left"
    return (
        f"{opening}; the Earth's rotation moves the landing point {length(abs(d))} to the "
        f"{side} of the line of fire."
    )


def foucault(data: dict[str, Any]) -> str:
    """``poinsot foucault``: how the swing plane turns, or why this run shows no steady turn."""
    where = f"At latitude {angle(data['latitude'], data['degrees'])}"
    rate, expected = data["precession_rate"], data["expected_rate"]
    theory = (
        f"the unit's ω sin λ gives {num(math.degrees(abs(expected)) * 3600)}° an hour, one "
        f"turn every {duration(data['full_turn_hours'] * 3600)}"
        if math.isfinite(data["full_turn_hours"])
        else "the unit's ω sin λ is 0 here"
    )
    if data["regime"] == "precessing" and rate is not None and rate != 0:
        return (
            f"{where}, the swing plane turns {data['sense']} seen from above by "
            f"{num(math.degrees(abs(rate)) * 3600)}° an hour in the simulation, one full turn "
            f"every {duration(data['full_turn_period'])}; {theory}."
        )
    if data["regime"] == "still":
        return f"{where}, the swing plane does not turn measurably; {theory}."
    return (
        f"{where}, this run shows no steady turn of the swing plane "
        f"({data['regime'].replace('_', ' ')}); {theory}."
    )


def free(data: dict[str, Any]) -> str:
    """``poinsot free``: what ω does in the body, and how well the method kept the invariants."""
    regime = data["regime"]
    period = data["period"]
    if regime == "steady":
        what = (
            f"The body spins steadily at {num(data['steady_rate'])} rad/s about one principal "
            "axis: ω does not move in the body"
        )
    elif regime == "separatrix":
        what = (
            "ω starts on the separatrix: it leaves the middle axis and creeps back towards it "
            "forever, with no period"
        )
    elif regime == "symmetric":
        what = f"The body is a symmetric top: ω circles its symmetry axis once every {duration(period)} in the body"
    else:
        smallest = regime == "about min axis"
        what = (
            f"ω circles axis {data['pole_axis'] + 1}, the axis of the "
            f"{'smallest' if smallest else 'largest'} moment, once every {duration(period)} in "
            "the body"
        )
        middle = data["flips_about"]
        if middle is not None:
            # started near the unstable middle axis: the Dzhanibekov flips
            what += (
                f"; started near axis {middle + 1}, the middle one, the body flips over every "
                f"{duration(data['flip_interval'])}"
            )
    return (
        f"{what}; {data['method']} kept the energy to a relative {data['max_energy_error']:.1e} "
        f"over {num(data['duration'])} s."
    )


#: What each kind of top means for a student.
_KINDS = {
    "spherical top": "a spherical top: every axis through the centre of mass is a principal axis",
    "symmetric top": "a symmetric top: two equal moments",
    "asymmetric top": "an asymmetric top: it spins stably about the axes of its smallest and "
    "largest moments, not about the middle one",
    "rotor": "a rotor: one moment is zero, like a thin rod's about its length",
}


def inertia(data: dict[str, Any]) -> str:
    """``poinsot inertia``: the mass, the principal moments and what kind of top it is."""
    i1, i2, i3 = data["principal_moments"]
    kind = data["kind"]
    return (
        f"The {data['source']} has mass {num(data['mass'])} kg and principal moments {num(i1)}, "
        f"{num(i2)} and {num(i3)} kg·m² about its centre of mass; it is "
        f"{_KINDS.get(kind, kind)}."
    )


def rigid_earth(data: dict[str, Any]) -> str:
    """``poinsot earth``: Euler's and Chandler's periods, the precession of the equinoxes and
    the principal nutation, each beside its measured value where the catalogue has one (only
    unit changes: s → days or years, rad → ″)."""
    measured = data.get("measured") or {}

    def beside(key: str, unit: str, what: str, digits: int = DIGITS) -> str:
        m = measured.get(key)
        return f" ({what} {num(m['value'], digits)}{unit})" if m else ""

    dpsi, deps = data["nutation_amplitudes_arcsec"]
    nut = ""
    if measured.get("nutation_longitude") and measured.get("nutation_obliquity"):
        nut = (
            f" (IAU 2000A: {num(measured['nutation_longitude']['value'])}″, "
            f"{num(measured['nutation_obliquity']['value'])}″)"
        )
    return (
        f"As a rigid top, the Earth's axis of rotation would circle its axis of figure in "
        f"{num(data['euler_period_sidereal_days'])} sidereal days (Euler's free wobble); with "
        f"k2 = {given(data['k2'])} and ks = {given(data['ks'])} the elastic Earth's takes "
        f"{num(data['chandler_period_days'])} days"
        f"{beside('chandler_period', ' days', 'observed')}. The Sun and the Moon turn the axis "
        f"westward by {num(data['precession_rate_arcsec_per_year'], 4)}″ a year"
        f"{beside('precession_rate', '″', 'IAU 2006:', 4)}, once in "
        f"{num(data['precession_period_years'])} years, the Moon doing "
        f"{num(data['moon_to_sun'])} times the Sun's share; the 18.6-year nutation swings it "
        f"by {num(dpsi)}″ in longitude and {num(deps)}″ in obliquity{nut}."
    )


def gyrocompass(data: dict[str, Any]) -> str:
    """``poinsot gyrocompass``: the settling period beside Schuler's and the rotor that tunes
    to it, the latitude (damping) error, and on a moving ship the speed error beside its
    small-angle form (only unit changes: s → min, rad → °; errors are reading minus truth)."""
    minutes = num(data["period"] / 60, 4)
    schuler = num(data["schuler_period"] / 60, 4)
    settle = data["settle_error"]
    text = (
        f"At {degrees(data['latitude'])} the compass swings about the meridian once in "
        f"{minutes} min (Schuler's {schuler} min needs H = "
        f"{num(data['schuler_angular_momentum'], 4)} kg·m²/s) and settles reading "
        f"{degrees(abs(settle))} {'low' if settle < 0 else 'high'} (latitude error)"
        if settle != 0
        else f"At {degrees(data['latitude'])} the compass swings about the meridian once in "
        f"{minutes} min (Schuler's {schuler} min needs H = "
        f"{num(data['schuler_angular_momentum'], 4)} kg·m²/s) and, undamped, settles on it"
    )
    if data["speed"] == 0:
        return text + "; the ship is at rest: no speed error."
    speed = data["speed_error"]
    return (
        f"{text}; steaming at {num(data['speed'])} m/s the speed error makes it read "
        f"{degrees(abs(speed))} {'high' if speed >= 0 else 'low'} besides (small-angle form: "
        f"{degrees(abs(data['speed_error_small_angle']))})."
    )
