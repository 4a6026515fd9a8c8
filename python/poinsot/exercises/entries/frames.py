"""Templates of moving frames (the unit's eqs. 2.1–2.23; its long questions L 1 and L 2): a
plumb bob in an accelerating car (translation) and a bug crawling on a turntable (rotation)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ...frames import MovingFrame
from .._build import draws, plain, prose
from .._steps import Mistake
from .._template import Template

_G = 9.80665

# ---- a frame with relative translational motion (2.1–2.5; L 1) -----------------------------------


def _car_acceleration(v: Any) -> float:
    """The car's acceleration R̈ (m/s²): from rest to ``speed`` in ``time``."""
    return float(v.speed / v.time)


def _bob_angle(v: Any) -> float:
    """The bob's angle from the vertical (rad): gravity and the translational fictitious force
    −m R̈ (2.5) of the car's frame, through :meth:`poinsot.MovingFrame.fictitious_forces`."""
    car = MovingFrame(acceleration=[_car_acceleration(v), 0.0, 0.0])
    push = car.fictitious_forces(1.0, [0.0, 0.0, 0.0], [0.0, 0.0, 0.0])["translational"]
    return math.atan2(float(np.hypot(push[0], push[1])), v.g)


CAR = Template(
    name="car-plumb-bob",
    title="A plumb bob in an accelerating car",
    text=prose("""A car starts from rest on a level road and speeds up uniformly, reaching {speed}
        in {time}. A small bob hangs on a string from the mirror. Take g = 9.807 m/s²."""),
    params=draws("km/h", speed=(50, 120, 10)) + draws("s", time=(4, 15, 1)),
    question=prose("""While the car speeds up, at what angle from the vertical does the string hang
        (the bob swung back), in degrees?"""),
    answer=_bob_angle,
    check=lambda v: math.atan(v.speed / v.time / v.g),
    agree=1e-12,
    agree_why="the core's fictitious force −m R̈ (2.5) against tan α = a/g by hand",
    steps=(
        plain(
            "The car's acceleration, from rest to v in t",
            r"a [m/s**2] = \frac{{{speed}}}{{{time}}}",
            _car_acceleration,
        ),
        plain(
            "In the car's frame the bob feels −m a besides m g (eq. 2.5): tan α = a/g",
            r"\alpha [deg] = \arctan\frac{{a}}{{{g}}}",
            _bob_angle,
        ),
    ),
    mistakes=(
        Mistake(
            "km/h for m/s",
            "put the speed in km/h into a = v/t",
            2,
            lambda v: math.atan(3.6 * v.speed / v.time / v.g),
        ),
        Mistake(
            "g over a",
            "took tan α = g/a: that is the angle from the horizontal",
            3,
            lambda v: math.atan(v.g * v.time / v.speed),
        ),
    ),
    topic="moving frames",
    difficulty=1,
    answer_range=(0.0, 45.0),
    constants={"g": _G},
)

# ---- a rotating frame: velocity and acceleration (2.19–2.23; L 2) --------------------------------


def _bug_acceleration(v: Any) -> float:
    """|r̈'| (m/s²) of a bug crawling outward at ``speed`` at ``radius`` on a turntable turning
    at ``rate``: :meth:`poinsot.MovingFrame.to_fixed` (2.23)."""
    table = MovingFrame(angular_velocity=[0.0, 0.0, v.rate])
    seen = table.to_fixed([v.radius, 0.0, 0.0], [v.speed, 0.0, 0.0])
    return float(np.linalg.norm(seen.acceleration))


def _centripetal(v: Any) -> float:
    return v.rate**2 * v.radius


def _coriolis(v: Any) -> float:
    return 2 * v.rate * v.speed


TURNTABLE = Template(
    name="turntable-bug",
    title="A bug crawling on a turntable",
    text=prose("""A turntable turns at a steady {rate}. A bug crawls straight outward along a
        radius painted on it, at a steady {speed} relative to the table."""),
    params=draws("rpm", rate=(10, 60, 5))
    + draws("cm/s", speed=(1, 10, 0.5))
    + draws("cm", radius=(5, 15, 1)),
    question=prose("""When the bug is {radius} from the centre, what is the magnitude of its
        acceleration seen from the ground, in m/s²?"""),
    answer=_bug_acceleration,
    check=lambda v: math.hypot(_centripetal(v), _coriolis(v)),
    agree=1e-12,
    agree_why="the core's r̈' = r̈ + 2ω×ṙ + ω×(ω×r) (2.23) against its two terms by hand",
    steps=(
        plain(
            "The centripetal term ω×(ω×r), inward, of magnitude ω² r",
            r"a_c [m/s**2] = {rate}^2 \cdot {radius}",
            _centripetal,
        ),
        plain(
            "The Coriolis term 2ω×u (u the bug's velocity on the table), across the radius, of magnitude 2 ω u",
            r"a_{cor} [m/s**2] = 2 \cdot {rate} \cdot {speed}",
            _coriolis,
        ),
        plain(
            "The two are perpendicular (the bug's speed on the table is steady: no third term)",
            r"a [m/s**2] = \sqrt{{a_c^2 + a_{{cor}}^2}}",
            _bug_acceleration,
        ),
    ),
    mistakes=(
        Mistake(
            "no Coriolis term",
            "left out the Coriolis term 2ω×u: the bug moves in the rotating frame",
            3,
            _centripetal,
        ),
        Mistake(
            "factor 2",
            "forgot the factor 2 of the Coriolis term",
            3,
            lambda v: math.hypot(_centripetal(v), v.rate * v.speed),
        ),
        Mistake(
            "terms added",
            "added the two magnitudes; they are perpendicular",
            4,
            lambda v: _centripetal(v) + _coriolis(v),
        ),
    ),
    topic="moving frames",
    difficulty=2,
    answer_range=(0.0, 10.0),
)

ENTRIES = (CAR, TURNTABLE)
