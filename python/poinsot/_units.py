"""Units at the door: ``pint`` quantities turned into SI floats where arguments enter.

Every public function takes plain numbers in SI units and radians (CONVENTIONS.md §1); it also
takes a :class:`pint.Quantity`, converted here once to the SI unit of the argument's dimension
(``5 * ureg.cm`` as ``radius`` is 0.05, ``1500 * ureg.rpm`` as ``omega3`` is 157.08, ``30 *
ureg.deg`` as ``theta`` is 0.5236), before the core sees it: the core never meets a unit. The
dimension of each argument is :data:`ARGUMENTS` (argument name → dimension), written once; a
quantity of another dimension is refused naming the argument and the dimension expected
(``latitude: expected an angle, got 3 meter``).

pint is not imported here: a value is a quantity only if pint is already loaded (the user made
the quantity with it), so ``import poinsot`` stays as fast as without pint. The one departure
from pint's own conversions: a frequency in hertz given for an angular rate counts turns, ``1 Hz
= 2 pi rad/s`` (pint converts 1 Hz to 1 rad/s, since it treats the radian as dimensionless).

The CLI's unit suffixes (``5cm``, ``1500rpm``, ``50d53m``) are parsed by :func:`parse` from the
small table :data:`SUFFIXES`, without pint, with the same dimensions.
"""

from __future__ import annotations

import math
import re
import sys
from typing import Any

from .errors import PoinsotError

__all__ = ["ARGUMENTS", "DIMENSIONS", "SUFFIXES", "is_quantity", "parse", "to_si"]

#: Each dimension: (its name in messages, its SI unit as pint spells it, as poinsot prints it).
DIMENSIONS: dict[str, tuple[str, str, str]] = {
    "angle": ("an angle", "radian", "rad"),
    "angular rate": ("an angular rate", "radian / second", "rad/s"),
    "angular acceleration": ("an angular acceleration", "radian / second ** 2", "rad/s²"),
    "rate": ("a rate", "1 / second", "1/s"),
    "length": ("a length", "meter", "m"),
    "time": ("a time", "second", "s"),
    "mass": ("a mass", "kilogram", "kg"),
    "speed": ("a speed", "meter / second", "m/s"),
    "acceleration": ("an acceleration", "meter / second ** 2", "m/s²"),
    "moment of inertia": ("a moment of inertia", "kilogram * meter ** 2", "kg·m²"),
    "energy": ("an energy or torque", "joule", "J"),
    "angular momentum": ("an angular momentum", "kilogram * meter ** 2 / second", "kg·m²/s"),
    "density": ("a density", "kilogram / meter ** 3", "kg/m³"),
    "stiffness": ("a stiffness", "newton / meter", "N/m"),
    "number": ("a plain number", "dimensionless", ""),
}

_D = {
    "angle": (
        "theta phi psi theta0 latitude latitudes azimuth elevation angle angles course tilt "
        "spin_axis_angle obliquity moon_node heading0 tilt0"
    ),
    "angular rate": (
        "omega omega0 omega3 omega_3 omega_body rates phi_dot theta_dot psi_dot rotation_rate "
        "angular_velocity spin mean_motion precession_rate"
    ),
    "angular acceleration": "angular_acceleration",
    "rate": "friction",
    "length": (
        "radius height length sides semi_axes position positions point points about origin offset "
        "center_of_mass vertices bounds amplitude pivot_distance r_3 x"
    ),
    "time": "duration dt t_end t_eval times time",
    "mass": "mass masses",
    "speed": "velocity velocity_enu speed",
    "acceleration": "acceleration g gravity pull",
    "moment of inertia": "I1 I3 inertia moments",
    "energy": "mgl energy torque pendulosity",
    "angular momentum": "p_phi p_psi angular_momentum",
    "density": "density",
    "stiffness": "stiffness",
    "number": (
        "rtol atol R R_3 V_3 rotation attitude attitude0 q p u m n s axis low high "
        "dynamical_flattening k2 ks damping"
    ),
}

#: The dimension of every argument a public function takes a quantity for, by its name. ``t`` is
#: a time (the motions) or a length (the translation of :func:`~poinsot.screw_axis`), ``v`` any
#: vector: those take either and are converted to the SI unit of the dimension they have.
ARGUMENTS: dict[str, tuple[str, ...]] = {
    name: (dim,) for dim, names in _D.items() for name in names.split()
}
ARGUMENTS["t"] = ("time", "length")
ARGUMENTS["v"] = tuple(d for d in DIMENSIONS if d != "angle")


def is_quantity(value: Any) -> bool:
    """Whether ``value`` is a pint quantity (only if pint is loaded: never imports it)."""
    pint = sys.modules.get("pint")
    return pint is not None and isinstance(value, pint.Quantity)


def _base(name: str) -> str:
    """The argument's name without an index (``positions[2]`` → ``positions``)."""
    return name.split("[", 1)[0]


def to_si(value: Any, name: str) -> Any:
    """The magnitude of the pint quantity ``value`` in the SI unit of the dimension of argument
    ``name`` (a float or a numpy array); :class:`PoinsotError` naming ``name`` when its dimension
    is not the one expected ("latitude: expected an angle, got 3 meter")."""
    import pint

    dims = ARGUMENTS.get(_base(name), ("number",))
    quantity = value
    if "hertz" in str(value.units) and {"angular rate", "angular acceleration"} & set(dims):
        # Hz counts turns per second here (pint would give 1 rad/s per Hz).
        hz = value.to("hertz").magnitude
        quantity = value._REGISTRY.Quantity(hz, "revolution / second")
    for dim in dims:
        try:
            return quantity.to(DIMENSIONS[dim][1]).magnitude
        except pint.DimensionalityError:
            continue
    wanted = " or ".join(DIMENSIONS[d][0] for d in dims)
    raise PoinsotError(f"{name}: expected {wanted}, got {value:~P}")


# ---- the CLI's suffixes ---------------------------------------------------------------------

_TURN = 2.0 * math.pi
_DEG = math.pi / 180.0

#: The unit suffixes the CLI reads without pint: suffix → (dimension, factor to its SI unit).
#: ``Hz`` and ``rpm`` count turns (an angular rate: 2 pi rad per turn).
SUFFIXES: dict[str, tuple[str, float]] = {
    "m": ("length", 1.0),
    "cm": ("length", 0.01),
    "mm": ("length", 0.001),
    "km": ("length", 1000.0),
    "deg": ("angle", _DEG),
    "°": ("angle", _DEG),
    "rad": ("angle", 1.0),
    "rpm": ("angular rate", _TURN / 60.0),
    "rad/s": ("angular rate", 1.0),
    "deg/s": ("angular rate", _DEG),
    "Hz": ("angular rate", _TURN),
    "kg": ("mass", 1.0),
    "g": ("mass", 0.001),
    "s": ("time", 1.0),
    "min": ("time", 60.0),
    "h": ("time", 3600.0),
    "kn": ("speed", 1852.0 / 3600.0),
    "m/s": ("speed", 1.0),
    "km/h": ("speed", 1000.0 / 3600.0),
    "m/s2": ("acceleration", 1.0),
    "kg*m2": ("moment of inertia", 1.0),
    "N*m": ("energy", 1.0),
    "J": ("energy", 1.0),
}

#: How pint spells each suffix, for the test of :data:`SUFFIXES` against pint's conversions.
PINT_NAMES = {
    "deg": "degree",
    "°": "degree",
    "rad": "radian",
    "rpm": "revolution / minute",
    "rad/s": "radian / second",
    "deg/s": "degree / second",
    "Hz": "revolution / second",
    "g": "gram",
    "kn": "knot",
    "m/s2": "meter / second ** 2",
    "kg*m2": "kilogram * meter ** 2",
    "N*m": "newton * meter",
}

_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_SUFFIXED = re.compile(rf"\s*({_NUMBER})\s*(\S*)\s*$")
# Degrees and minutes (of arc): 50d53m, 50°53', -33d52.5m.
_DMS = re.compile(r"\s*([-+]?)(\d+\.?\d*)\s*(?:d|°)\s*(\d+\.?\d*)\s*(?:m|')\s*$")


def parse(text: str, dimension: str) -> tuple[float, bool]:
    """``text`` (``"5cm"``, ``"1500rpm"``, ``"50d53m"``, ``"0.2"``) read for an option of
    ``dimension`` (a key of :data:`DIMENSIONS`): ``(value in SI, whether a unit was given)``.
    A bare number is returned as it is. A suffix of :data:`SUFFIXES` is converted without pint;
    another is given to pint if it is installed. Raises ``ValueError`` saying what was expected
    ("expected an angle, got 3 m"), or that the text is not a number."""
    dms = _DMS.match(text)
    if dms is not None:
        sign = -1.0 if dms.group(1) == "-" else 1.0
        got = "angle", sign * (float(dms.group(2)) + float(dms.group(3)) / 60.0) * _DEG
        return _expect(got, dimension, text), True
    m = _SUFFIXED.match(text)
    if m is None:
        raise ValueError(f"not a number: {text!r}")
    number, suffix = float(m.group(1)), m.group(2)
    if not suffix:
        return number, False
    if suffix in SUFFIXES:
        dim, factor = SUFFIXES[suffix]
        return _expect((dim, number * factor), dimension, f"{m.group(1)} {suffix}"), True
    try:
        import pint
    except ImportError:
        known = ", ".join(s for s, (d, _) in SUFFIXES.items() if d == dimension)
        raise ValueError(
            f"unknown unit {suffix!r} (the units known without pint for "
            f"{DIMENSIONS[dimension][0]}: {known}; pip install pint for any other)"
        ) from None
    registry = pint.application_registry.get()
    try:
        q = registry.Quantity(number, suffix)
    except Exception:  # pint raises several kinds for text it cannot read
        raise ValueError(f"unknown unit {suffix!r}") from None
    if "hertz" in str(q.units) and dimension in ("angular rate", "angular acceleration"):
        q = registry.Quantity(q.to("hertz").magnitude, "revolution / second")
    try:
        return float(q.to(DIMENSIONS[dimension][1]).magnitude), True
    except pint.DimensionalityError:
        raise ValueError(f"expected {DIMENSIONS[dimension][0]}, got {number:g} {suffix}") from None


def _expect(got: tuple[str, float], dimension: str, shown: str) -> float:
    """The SI value of ``got`` (dimension, value) if its dimension is ``dimension``."""
    dim, value = got
    if dim != dimension:
        raise ValueError(f"expected {DIMENSIONS[dimension][0]}, got {shown}")
    return value
