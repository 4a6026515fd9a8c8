"""The rotating Earth seen from a local frame on its surface (the unit's eqs. 2.29–2.42).

Conventions: local ENU frame (x east, y north, z up along the plumb line), latitude λ
north-positive, ω = ω (0, cos λ, sin λ) (eq. 2.33); the sidereal rate 7.2921150e-5 rad/s by
default, the unit's solar-day rate 2π/86400 with :meth:`Earth.solar_day` or
``rotation_rate="solar"``. Angles in radians unless ``degrees=True``.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field, fields
from typing import Any, TypeVar

import numpy as np

from . import _core
from . import _display as show
from ._props import core_property
from ._validate import (
    FloatArray,
    as_angle,
    as_choice,
    as_count,
    as_flag,
    as_flat,
    as_float_array,
    as_scalar,
    in_degrees,
    run_settings,
    shaped,
    tolerances,
)
from .errors import PoinsotError

__all__ = [
    "Earth",
    "Fall",
    "Flight",
    "FoucaultRun",
    "InertialOscillation",
    "LowFlow",
    "SIDEREAL_RATE",
    "SOLAR_DAY_RATE",
]

SIDEREAL_RATE: float = _core.SIDEREAL_RATE
"""The Earth's sidereal rotation rate (rad/s), 2π / 86164.0905 s: the default (the core's)."""
SOLAR_DAY_RATE: float = _core.SOLAR_DAY_RATE
"""The unit's rate (rad/s), one turn per solar day 2π / (24·3600) s (see the errata)."""
_MEAN_RADIUS: float = _core.MEAN_RADIUS
_STANDARD_GRAVITY: float = _core.STANDARD_GRAVITY

# The defaults of the runs are the core's (the browser lab uses the same ones).
_DROP = _core.DEFAULTS["Earth.drop"]
_FOUCAULT = _core.DEFAULTS["Earth.foucault"]
_INERTIAL = _core.DEFAULTS["Earth.inertial_oscillation"]
_LOW = _core.DEFAULTS["Earth.flow_into_low"]

_GRAVITY = ("uniform", "inverse-square")


@dataclass(frozen=True, repr=False)
class Fall(show.Displayed):
    """A body dropped from rest, integrated in the rotating frame until it lands.

    Attributes
    ----------
    time:
        Time of fall (s).
    east, north:
        Landing point relative to the foot of the plumb line through the release point (m);
        ``north`` < 0 is south.
    t:
        Sample times (s), shape (N,), from release to landing.
    position, velocity:
        ENU position (m) and velocity (m/s) at ``t``, shape (N, 3).
    first_order_east:
        The unit's eq. 2.42, ⅓ ω cos λ √(8h³/g) (m).
    second_order_south:
        The second-order equatorward deflection ¾ ω² sin 2λ h²/g (m; uniform gravity).
    """

    time: float
    east: float
    north: float
    t: FloatArray = field(repr=False)
    position: FloatArray = field(repr=False)
    velocity: FloatArray = field(repr=False)
    first_order_east: float = 0.0
    second_order_south: float = 0.0

    def _rows(self) -> list[show.Row]:
        return [
            *_landing(self, "fall", "the plumb line"),
            show.scalar(
                "first_order_east",
                "eastward deflection, first order (2.42)",
                "",
                self.first_order_east,
                "m",
            ),
            show.scalar(
                "second_order_south",
                "southward deflection, second order",
                "",
                self.second_order_south,
                "m",
            ),
            *_sampled(self.t, self.position, self.velocity),
        ]


@dataclass(frozen=True, repr=False)
class Flight(show.Displayed):
    """A projectile's flight until it lands.

    Attributes
    ----------
    time:
        Time of flight (s).
    east, north:
        Landing point (m, ENU).
    range:
        Horizontal distance from launch to landing (m).
    downrange:
        Landing displacement along the launch azimuth (m).
    drift:
        Landing displacement across the launch azimuth, positive to the right (m).
    t:
        Sample times of the flight (s), shape (N,).
    position, velocity:
        The flight's samples (m, m/s, ENU), shape (N, 3).
    """

    time: float
    east: float
    north: float
    range: float
    downrange: float
    drift: float
    t: FloatArray = field(repr=False)
    position: FloatArray = field(repr=False)
    velocity: FloatArray = field(repr=False)

    def _rows(self) -> list[show.Row]:
        return [
            *_landing(self, "flight", "the launch"),
            show.scalar("range", "horizontal distance to the landing point", "", self.range, "m"),
            show.scalar(
                "downrange", "displacement along the launch azimuth", "", self.downrange, "m"
            ),
            show.scalar("drift", "displacement to the right of the azimuth", "", self.drift, "m"),
            *_sampled(self.t, self.position, self.velocity),
        ]


@dataclass(frozen=True, repr=False)
class FoucaultRun(show.Displayed):
    """A Foucault pendulum integrated in the rotating frame, and what its swing plane did.

    Attributes
    ----------
    t:
        Sample times (s), shape (N,).
    position, velocity:
        The bob's samples (m, m/s) in ENU, origin at the point of suspension, shape (N, 3).
    turn_times, turn_angles:
        The turning points of the swing — the bob's largest distances from its rest position —
        and the bob's direction from its rest position there, counterclockwise from east seen
        from above (rad).
    precession_rate:
        The swing plane's rate of turn fitted through the turning points (rad/s,
        counterclockwise seen from above positive), or ``None`` where the run shows no steady
        turn (see ``regime``); ≈ 0 when ``regime == "still"``.
    expected_rate:
        −ω sin λ, the unit's rate (rad/s).
    sense:
        ``"clockwise"``, ``"counterclockwise"`` (seen from above; always the theory's sense),
        ``"none"`` (``regime == "still"``) or ``"undefined"`` (no rate).
    regime:
        ``"precessing"`` (the plane turns steadily), ``"still"`` (it does not turn measurably:
        the equator, or no spin), ``"too_short"`` (too few swings, or a turn within the plane's
        wobble), ``"unsteady"`` (the plane rocks: near the equator, or a planet spinning fast
        against the pendulum), ``"wide_swing"`` (the amplitude's own precession competes),
        ``"not_a_swing"`` (the plane would turn by over a quarter turn per swing) or
        ``"no_rest"`` (the spin flings the bob off any rest position).
    regime_note:
        One sentence on the regime, with its figures.
    theory_rate:
        The exact small-swing theory's mean rate of turn (rad/s): −ω sin λ for a slow spin, exactly
        −ω at the poles; ``None`` where the bob has no stable rest position.
    unit_rate_holds:
        Whether the unit's −ω sin λ describes this run: the small-swing rate is within
        1 % (the core's ``UNIT_RATE_TOLERANCE``) of it (ω ≪ √(g/L)) and the measured rate within 1 % of the
        small-swing theory's (a small amplitude), in a run that turns steadily. The core's rule,
        the same as the lab's warning.
    unit_rate_note:
        One sentence saying why (or why not), with the figures.
    spin_ratio:
        ω / √(g/L), the planet's spin against the pendulum's frequency (dimensionless).
    amplitude_ratio:
        A / L, the release's distance from the rest position over the length (dimensionless).
    spin_departure, amplitude_departure:
        The two departures (fractions) judged against 1 %; ``None`` where there is nothing to
        compare (no rest position; no rate).
    full_turn_period:
        The simulated swing plane's time for one full turn, 2π/|``precession_rate``| (s), beside
        the rate: ``inf`` where the plane does not turn measurably (``regime == "still"``),
        ``None`` where the run gives no rate.
    expected_full_turn_period:
        The unit's time for one full turn, 2π/|ω sin λ| (s; ``inf`` at the equator).
    """

    t: FloatArray = field(repr=False)
    position: FloatArray = field(repr=False)
    velocity: FloatArray = field(repr=False)
    turn_times: FloatArray = field(repr=False)
    turn_angles: FloatArray = field(repr=False)
    precession_rate: float | None = None
    expected_rate: float = 0.0
    sense: str = "undefined"
    regime: str = "too_short"
    regime_note: str = ""
    theory_rate: float | None = None
    unit_rate_holds: bool = False
    unit_rate_note: str = ""
    spin_ratio: float = 0.0
    amplitude_ratio: float = 0.0
    spin_departure: float | None = None
    amplitude_departure: float | None = None
    full_turn_period: float | None = None
    expected_full_turn_period: float = np.inf

    def _rows(self) -> list[show.Row]:
        return [
            show.scalar(
                "precession_rate",
                "swing plane's rate of turn, fitted",
                "",
                self.precession_rate,
                "rad/s",
            ),
            show.scalar(
                "expected_rate", "the unit's rate", "−ω sin λ", self.expected_rate, "rad/s"
            ),
            show.words("sense", "sense seen from above", self.sense),
            show.words("regime", "regime", self.regime),
            show.words("regime_note", "note", self.regime_note),
            show.scalar(
                "theory_rate", "small-swing theory's mean rate", "", self.theory_rate, "rad/s"
            ),
            *_sampled(self.t, self.position, self.velocity),
            show.samples("turn_times", "times of the turning points", "", self.turn_times, "s"),
            show.samples(
                "turn_angles", "directions at the turning points", "", self.turn_angles, "rad"
            ),
        ]


def _landing(run: Fall | Flight, what: str, origin: str) -> list[show.Row]:
    """The rows of a run to the ground (``what``: "fall", "flight"): its time and its landing
    point east and north of ``origin`` (the sweeps' outputs say the same: ``sweep._landing``)."""
    return [
        show.scalar("time", f"time of {what}", "t", run.time, "s"),
        show.scalar("east", f"landing point east of {origin}", "x", run.east, "m"),
        show.scalar("north", f"landing point north of {origin}", "y", run.north, "m"),
    ]


def _sampled(t: FloatArray, position: FloatArray, velocity: FloatArray) -> list[show.Row]:
    """The rows of a run's samples (ENU)."""
    return [
        show.samples("t", "sample times", "t", t, "s"),
        show.samples("position", "position, east-north-up", "r", position, "m"),
        show.samples("velocity", "velocity, east-north-up", "v", velocity, "m/s"),
    ]


@dataclass(frozen=True)
class InertialOscillation:
    """A parcel moving horizontally under the Coriolis force alone.

    Attributes
    ----------
    t:
        Sample times (s), (N,).
    position, velocity:
        ``[east, north]`` (m) and ``[v_east, v_north]`` (m/s), (N, 2).
    turning_rate:
        Rate at which the velocity turns, measured from the run (rad/s, counterclockwise
        positive); the theory says −2ω sin λ.
    measured_period:
        The period measured from the run, 2π/|turning_rate| (s; inf where it does not turn).
    period:
        The inertial period π/(ω |sin λ|) (s; inf at the equator).
    sense:
        ``"clockwise"`` (deflected to the right: the north), ``"counterclockwise"`` (the
        south) or ``"none"`` (the equator: within 1e-9 of 2ω, round-off), from the measured
        rate by the core's rule.
    """

    t: FloatArray = field(repr=False)
    position: FloatArray = field(repr=False)
    velocity: FloatArray = field(repr=False)
    turning_rate: float = 0.0
    period: float = float("inf")
    sense: str = "none"
    measured_period: float = float("inf")


@dataclass(frozen=True)
class LowFlow:
    """Parcels drawn into a low-pressure centre at the origin.

    Attributes
    ----------
    t:
        Sample times (s), (N,).
    position, velocity:
        (P, N, 2) arrays for P parcels (m, m/s; ``[east, north]``).
    circulation:
        Mean specific angular momentum about the centre (m²/s): > 0 counterclockwise.
    sense:
        ``"counterclockwise"`` (the north: cyclones), ``"clockwise"`` (the south) or
        ``"none"`` (within 1e-9 of radius × √(pull × radius): round-off), from the simulated
        circulation by the core's rule.
    energy:
        (P, N): each parcel's energy per unit mass ½|v|² + ½k|r|² (J/kg; kinetic plus the
        pressure potential, k = pull / radius), which the Coriolis force leaves unchanged.
    dissipated:
        (P, N): the work done against friction per unit mass since the start, ∫γ|v|² dt
        (J/kg), integrated with the motion; ``energy + dissipated`` stays at its initial value
        (the energy budget).
    """

    t: FloatArray = field(repr=False)
    position: FloatArray = field(repr=False)
    velocity: FloatArray = field(repr=False)
    circulation: float = 0.0
    sense: str = "none"
    energy: FloatArray = field(default_factory=lambda: np.zeros((0, 0)), repr=False)
    dissipated: FloatArray = field(default_factory=lambda: np.zeros((0, 0)), repr=False)


_R = TypeVar("_R", Fall, Flight, FoucaultRun, InertialOscillation, LowFlow)
#: The fields of each run's dataclass, in order: the attributes of the core's result.
_FIELDS = {c: tuple(f.name for f in fields(c)) for c in _R.__constraints__}


def _result(cls: type[_R], core: Any) -> _R:
    """The public dataclass ``cls`` of a run holding the core's result ``core``, whose
    attributes have the dataclass's field names."""
    return cls(*[getattr(core, name) for name in _FIELDS[cls]])


def _fall_model(
    gravity: Any, rotation: Any, centrifugal: Any, rtol: Any, atol: Any, max_steps: Any
) -> _core.FallModel:
    """The core's model of a drop or a projectile (also one sweep's), from the keywords."""
    return _core.FallModel(
        as_choice(gravity, "gravity", _GRAVITY),
        as_flag(rotation, "rotation"),
        as_flag(centrifugal, "centrifugal"),
        *tolerances(rtol, atol, max_steps),
    )


class Earth:
    """The rotating Earth: a sphere of ``radius`` turning at ``rotation_rate`` with gravity ``g``.

    Parameters
    ----------
    rotation_rate:
        ω (rad/s, ≥ 0), or ``"sidereal"`` (7.2921150e-5, the default) or ``"solar"``
        (2π/86400, the unit's value).
    radius:
        R (m, > 0); default the mean radius 6.371e6.
    g:
        Gravity at the surface (m/s², > 0); default 9.80665. As in the unit it is the
        attraction in :meth:`effective_gravity` (eq. 2.31) and the local plumb-line gravity of
        the near-surface motions (eqs. 2.32–2.42).

    Examples
    --------
    >>> import poinsot as ps
    >>> round(ps.Earth().eastward_deflection(100, 45, degrees=True), 5)   # eq. 2.42
    0.01552
    """

    __slots__ = ("_core",)

    def __init__(
        self,
        rotation_rate: Any = SIDEREAL_RATE,
        radius: float = _MEAN_RADIUS,
        g: float = _STANDARD_GRAVITY,
    ) -> None:
        if isinstance(rotation_rate, str):
            names = {"sidereal": SIDEREAL_RATE, "solar": SOLAR_DAY_RATE}
            if rotation_rate not in names:
                raise PoinsotError(
                    f"rotation_rate: must be a number, 'sidereal' or 'solar', got {rotation_rate!r}"
                )
            rotation_rate = names[rotation_rate]
        # The core's Earth, checked when made (the errors name the three); every method asks it.
        self._core = _core.EarthCore(
            as_scalar(rotation_rate, "rotation_rate"),
            as_scalar(radius, "radius"),
            as_scalar(g, "g"),
        )

    @classmethod
    def _of(cls, core: _core.EarthCore) -> Earth:
        """The Earth wrapping a core Earth already made (and checked) by the core."""
        earth = cls.__new__(cls)
        earth._core = core
        return earth

    @classmethod
    def solar_day(cls, radius: float = _MEAN_RADIUS, g: float = _STANDARD_GRAVITY) -> Earth:
        """The unit's Earth, turning once per solar day: ω = 2π/86400 = 7.2722e-5 rad/s."""
        return cls(SOLAR_DAY_RATE, radius, g)

    rotation_rate: float = core_property("rotation_rate", "ω (rad/s).")
    radius: float = core_property("radius", "R (m).")
    g: float = core_property("g", "g (m/s²).")

    def __repr__(self) -> str:
        c = self._core
        return f"Earth(rotation_rate={c.rotation_rate!r}, radius={c.radius!r}, g={c.g!r})"

    # -- local quantities -----------------------------------------------------------------
    def omega_enu(self, latitude: Any, degrees: bool = False) -> FloatArray:
        """ω in ENU components, ω (0, cos λ, sin λ) (eq. 2.33), shape ``latitude.shape + (3,)``."""
        lat, shape = as_flat(latitude, "latitude", degrees)
        return self._core.omega_enu(lat).reshape(shape + (3,))

    def effective_gravity(self, latitude: Any, degrees: bool = False) -> FloatArray:
        """The effective gravity g_e = g − ω × (ω × r) at the surface (eq. 2.31) as an ENU
        vector (m/s²), shape ``latitude.shape + (3,)``; g = −g ẑ (radial), r = R ẑ. See also
        :meth:`effective_gravity_magnitude` and :meth:`plumb_line_deviation`."""
        lat, shape = as_flat(latitude, "latitude", degrees)
        return self._core.effective_gravity(lat)[0].reshape(shape + (3,))

    def effective_gravity_magnitude(self, latitude: Any, degrees: bool = False) -> Any:
        """|g_e| (m/s²): g − ω²R at the equator, g at the poles."""
        lat, shape = as_flat(latitude, "latitude", degrees)
        return shaped(self._core.effective_gravity(lat)[1], shape)

    def plumb_line_deviation(self, latitude: Any, degrees: bool = False) -> Any:
        """Angle between the plumb line (along g_e) and the radial direction (rad, or degrees
        with ``degrees=True``), positive when it leans south (north of the equator): the plumb
        line leans towards the equator, by at most about 0.1° near 45°."""
        lat, shape = as_flat(latitude, "latitude", degrees)
        dev = self._core.effective_gravity(lat)[2]
        return shaped(np.degrees(dev) if as_flag(degrees, "degrees") else dev, shape)

    def centrifugal_magnitude(self, latitude: Any, degrees: bool = False) -> Any:
        """|ω × (ω × r)| = ω²R |cos λ| (m/s²) in closed form, the length of
        :meth:`centrifugal_acceleration` by a second route; shape ``latitude.shape``."""
        lat, shape = as_flat(latitude, "latitude", degrees)
        return shaped(self._core.centrifugal_magnitude(lat), shape)

    def plumb_line_deviation_closed(self, latitude: Any, degrees: bool = False) -> Any:
        """:meth:`plumb_line_deviation` (rad, or degrees with ``degrees=True``) in closed form,
        tan δ = q sin λ cos λ / (1 − q cos² λ) with q = ω²R/g: a second route beside the
        effective-gravity vector; shape ``latitude.shape``."""
        lat, shape = as_flat(latitude, "latitude", degrees)
        dev = self._core.plumb_line_deviation_closed(lat)
        return shaped(np.degrees(dev) if as_flag(degrees, "degrees") else dev, shape)

    def centrifugal_acceleration(self, latitude: Any, degrees: bool = False) -> FloatArray:
        """−ω × (ω × r) at the surface (m/s², ENU), of magnitude ω²R cos λ (ω²R at the
        equator: the unit's 3.4e-2 m/s²)."""
        lat, shape = as_flat(latitude, "latitude", degrees)
        return self._core.effective_gravity(lat)[3].reshape(shape + (3,))

    def coriolis_acceleration(
        self, latitude: Any, velocity_enu: Any, degrees: bool = False
    ) -> FloatArray:
        """The Coriolis acceleration −2 ω × v (m/s², ENU) of a particle moving with
        ``velocity_enu`` (m/s, ENU, ``(..., 3)``) at ``latitude`` (broadcast together) (eq. 2.30).
        To the right of horizontal motion in the north, to the left in the south."""
        lat = as_float_array(latitude, "latitude")
        vel = as_float_array(velocity_enu, "velocity_enu")
        if vel.ndim == 0 or vel.shape[-1] != 3:
            raise PoinsotError(f"velocity_enu: must have shape (..., 3), got {vel.shape}")
        try:
            lead = np.broadcast_shapes(lat.shape, vel.shape[:-1])
        except ValueError:
            raise PoinsotError(
                f"velocity_enu: shape {vel.shape} does not broadcast with latitude {lat.shape}"
            ) from None
        lat = np.broadcast_to(
            np.radians(lat) if in_degrees(latitude, degrees) else lat, lead
        ).reshape(-1)
        vel = np.broadcast_to(vel, lead + (3,)).reshape(-1, 3)
        out = self._core.coriolis_acceleration(np.ascontiguousarray(lat), np.ascontiguousarray(vel))
        return out.reshape(lead + (3,))

    def coriolis_parameter(self, latitude: Any, degrees: bool = False) -> Any:
        """f = 2ω sin λ (1/s); at the poles the unit's 2ω = 1.458e-4 s⁻¹ (sidereal)."""
        lat, shape = as_flat(latitude, "latitude", degrees)
        return shaped(self._core.coriolis_parameter(lat), shape)

    def foucault_rate(self, latitude: Any, degrees: bool = False) -> Any:
        """The Foucault pendulum's precession rate −ω sin λ (rad/s, counterclockwise seen from
        above positive: clockwise in the north)."""
        lat, shape = as_flat(latitude, "latitude", degrees)
        return shaped(self._core.foucault_rate(lat), shape)

    def inertial_period(self, latitude: Any, degrees: bool = False) -> Any:
        """The period of inertial oscillations π/(ω |sin λ|) (s; inf where ω sin λ = 0, at the
        equator; refused naming ``latitude`` where it is finite but beyond the largest double,
        |λ| ≲ 1e-304 on the Earth)."""
        lat, shape = as_flat(latitude, "latitude", degrees)
        return shaped(self._core.inertial_period(lat), shape)

    def jacobi_integral(
        self, latitude: float, position: Any, velocity: Any, degrees: bool = False
    ) -> Any:
        """Jacobi's integral, the energy per unit mass in the rotating local frame (J/kg):
        J = ½|v|² + g z − ½|ω × r|² for ENU ``position`` (m) and ``velocity`` (m/s), both
        ``(..., 3)`` (broadcast together), at ``latitude``; a float for one state, else shape
        ``(...)``. Gravity is uniform, ẑ the plumb line at the origin (eq. 2.30). The Coriolis
        force and a pendulum's string do no work, so J is constant along :meth:`foucault` and
        the uniform-gravity :meth:`drop`: its drift measures the integration error."""
        lat = as_angle(latitude, "latitude", degrees)
        pos = as_float_array(position, "position")
        vel = as_float_array(velocity, "velocity")
        for name, arr in (("position", pos), ("velocity", vel)):
            if arr.ndim == 0 or arr.shape[-1] != 3:
                raise PoinsotError(f"{name}: must have shape (..., 3), got {arr.shape}")
        try:
            lead = np.broadcast_shapes(pos.shape[:-1], vel.shape[:-1])
        except ValueError:
            raise PoinsotError(
                f"velocity: shape {vel.shape} does not broadcast with position {pos.shape}"
            ) from None
        # Two (N, 3) arrays, not one (N, 6): joining them took longer than the evaluation, and
        # could not be interrupted.
        r, v = (
            np.ascontiguousarray(np.broadcast_to(a, lead + (3,)).reshape(-1, 3)) for a in (pos, vel)
        )
        out = self._core.jacobi_integral(lat, r, v)
        return shaped(out, lead)

    def eastward_deflection(self, height: Any, latitude: Any, degrees: bool = False) -> Any:
        """The unit's first-order eastward deflection (eq. 2.42) of a body dropped from rest
        from ``height`` (m, ≥ 0): x = ⅓ ω cos λ √(8h³/g) (m). Broadcasts."""
        return self._deflection(self._core.eastward_deflection, height, latitude, degrees)

    def fall_time(self, height: float) -> float:
        """The unit's time of fall from rest from ``height`` (m, ≥ 0) without rotation,
        t = √(2h/g) (s, eq. 2.41)."""
        return self._core.fall_time(as_scalar(height, "height"))

    def southward_deflection(self, height: Any, latitude: Any, degrees: bool = False) -> Any:
        """The second-order equatorward deflection ¾ ω² sin 2λ h²/g (m, positive south) of a
        body dropped from ``height`` in uniform gravity (⅓ from Coriolis, 5/12 from the
        change of the centrifugal force with height). Broadcasts."""
        return self._deflection(self._core.southward_deflection, height, latitude, degrees)

    @staticmethod
    def _deflection(
        core: Callable[[FloatArray, FloatArray], FloatArray],
        height: Any,
        latitude: Any,
        degrees: bool,
    ) -> Any:
        h = as_float_array(height, "height")
        lat = as_float_array(latitude, "latitude")
        try:
            shape = np.broadcast_shapes(h.shape, lat.shape)
        except ValueError:
            raise PoinsotError(
                f"height: shape {h.shape} does not broadcast with latitude {lat.shape}"
            ) from None
        lat = np.radians(lat) if in_degrees(latitude, degrees) else lat
        hh = np.ascontiguousarray(np.broadcast_to(h, shape).reshape(-1))
        ll = np.ascontiguousarray(np.broadcast_to(lat, shape).reshape(-1))
        return shaped(core(hh, ll), shape)

    # -- motions --------------------------------------------------------------------------
    def drop(
        self,
        height: float,
        latitude: float,
        degrees: bool = False,
        *,
        gravity: str = "uniform",
        rotation: bool = True,
        centrifugal: bool = True,
        rtol: float = _DROP["rtol"],
        atol: float = _DROP["atol"],
        samples: int = _DROP["samples"],
        max_steps: int = _DROP["max_steps"],
    ) -> Fall:
        """Drop a body from rest at ``height`` (m, > 0) at ``latitude``, integrated exactly
        (to ``rtol``) in the rotating frame until it lands:

        r̈ = g(r) − 2 ω × ṙ − ω × (ω × r)   (eq. 2.30; the unit's 2.32 keeps only Coriolis),

        with ẑ the plumb line at the ground. ``gravity="uniform"`` (the unit's model, ground
        z = 0) or ``"inverse-square"`` (g falls off with height, ground a sphere of radius R);
        ``rotation=False`` drops it on a non-rotating Earth; ``centrifugal=False`` leaves out
        the change of the centrifugal force with position.

        Returns
        -------
        Fall
            ``time``, ``east``, ``north`` (north < 0: south), the trajectory (``samples``
            points), and the first-order (2.42) and second-order closed forms to compare.
        """
        h = as_scalar(height, "height")
        lat = as_angle(latitude, "latitude", degrees)
        model = _fall_model(gravity, rotation, centrifugal, rtol, atol, max_steps)
        return _result(Fall, self._core.drop(h, lat, model, as_count(samples, "samples", 2)))

    def projectile(
        self,
        speed: float,
        elevation: float,
        azimuth: float,
        latitude: float,
        degrees: bool = False,
        *,
        height: float = 0.0,
        gravity: str = "uniform",
        rotation: bool = True,
        centrifugal: bool = True,
        rtol: float = _DROP["rtol"],
        atol: float = _DROP["atol"],
        samples: int = _DROP["samples"],
        max_steps: int = _DROP["max_steps"],
    ) -> Flight:
        """Fly a projectile launched at ``speed`` (m/s, > 0), ``elevation`` above the horizon
        and ``azimuth`` clockwise from north (0 north, 90° east) from ``height`` (m, ≥ 0) at
        ``latitude``, integrated in the rotating frame until it lands (the model of
        :meth:`drop`). With ``rotation=False`` the same shot on a non-rotating Earth.

        Returns
        -------
        Flight
            ``time``, ``east``, ``north``, ``range``, ``downrange``, ``drift`` (to the right
            > 0: the north's deflection) and the trajectory.
        """
        args = (
            as_scalar(speed, "speed"),
            as_angle(elevation, "elevation", degrees),
            as_angle(azimuth, "azimuth", degrees),
            as_angle(latitude, "latitude", degrees),
            as_scalar(height, "height"),
        )
        model = _fall_model(gravity, rotation, centrifugal, rtol, atol, max_steps)
        return _result(Flight, self._core.projectile(*args, model, as_count(samples, "samples", 2)))

    def foucault(
        self,
        latitude: float,
        degrees: bool = False,
        *,
        length: float = _FOUCAULT["length"],
        amplitude: float = _FOUCAULT["amplitude"],
        azimuth: float = _FOUCAULT["azimuth"],
        duration: float = _FOUCAULT["duration"],
        samples: int = _FOUCAULT["samples"],
        rtol: float = _FOUCAULT["rtol"],
        atol: float = _FOUCAULT["atol"],
        max_steps: int = _FOUCAULT["max_steps"],
        progress: bool = False,
    ) -> FoucaultRun:
        """Swing a Foucault pendulum — a spherical pendulum of ``length`` (m; default the
        Panthéon's 67 m) released from rest ``amplitude`` (m) from its rest position towards
        ``azimuth`` (clockwise from north; radians unless ``degrees``) — for ``duration`` s in
        the rotating frame, and measure the turn of its swing plane: −ω sin λ, clockwise in the
        north, on a slowly turning planet.

        The result says whether the run shows a steadily turning swing plane at all
        (``regime``, ``regime_note``): on a planet spinning fast against the pendulum
        (ω not ≪ √(g/L)), near the equator or over too few swings it may not, and then no rate
        is given. A rate comes only with the sense of the exact small-swing theory
        (``theory_rate``).

        ``progress=True`` shows a progress bar (rich) while it runs.

        Returns
        -------
        FoucaultRun
            Samples, turning points, the fitted ``precession_rate`` (or ``None``), the unit's
            ``expected_rate`` and the small-swing ``theory_rate`` (rad/s, counterclockwise
            positive), the ``sense`` and the ``regime``.
        """
        lat = as_angle(latitude, "latitude", degrees)
        az = as_angle(azimuth, "azimuth", degrees)
        dur = as_scalar(duration, "duration")
        settings = run_settings(samples, rtol, atol, max_steps)
        progress = as_flag(progress, "progress")
        length = as_scalar(length, "length")
        amp = as_scalar(amplitude, "amplitude")
        # The whole run is the core's: release, sample grid, integration, measurement; with a
        # progress bar, integrated in stretches of about a minute, the bar advancing after each.
        bar, report = None, None
        if progress:
            from rich.progress import Progress

            bar = Progress(transient=True)
            bar.start()
            task = bar.add_task("Foucault pendulum", total=1.0)

            def report(fraction: float) -> None:
                bar.update(task, completed=fraction)

        try:
            r = self._core.foucault_swing(lat, length, amp, az, dur, settings, report)
        finally:
            if bar is not None:
                bar.stop()
        return _result(FoucaultRun, r)

    def inertial_oscillation(
        self,
        latitude: float,
        velocity: Any = tuple(_INERTIAL["velocity"]),
        degrees: bool = False,
        *,
        duration: float | None = None,
        samples: int = _INERTIAL["samples"],
        rtol: float = _INERTIAL["rtol"],
        atol: float = _INERTIAL["atol"],
        max_steps: int = _INERTIAL["max_steps"],
    ) -> InertialOscillation:
        """A parcel set moving horizontally with ``velocity`` ``[v_east, v_north]`` (m/s) on a
        frictionless level surface at ``latitude``: only the Coriolis force turns it, to the
        right in the north, to the left in the south, not at all at the equator. Default
        ``duration``: two inertial periods (or one day at the equator).

        Returns
        -------
        InertialOscillation
            The track, the measured ``turning_rate`` (−2ω sin λ) and ``sense``, and the
            ``period`` π/(ω |sin λ|).
        """
        lat = as_angle(latitude, "latitude", degrees)
        v = as_float_array(velocity, "velocity")
        if v.shape != (2,):
            raise PoinsotError(f"velocity: must have shape (2,) [v_east, v_north], got {v.shape}")
        dur = None if duration is None else as_scalar(duration, "duration")
        settings = run_settings(samples, rtol, atol, max_steps)
        r = self._core.inertial_swing(lat, np.ascontiguousarray(v), dur, settings)
        return _result(InertialOscillation, r)

    def flow_into_low(
        self,
        latitude: float,
        degrees: bool = False,
        *,
        radius: float = _LOW["radius"],
        parcels: int = _LOW["parcels"],
        pull: float = _LOW["pull"],
        friction: float = _LOW["friction"],
        duration: float = _LOW["duration"],
        samples: int = _LOW["samples"],
        rtol: float = _LOW["rtol"],
        atol: float = _LOW["atol"],
        max_steps: int = _LOW["max_steps"],
    ) -> LowFlow:
        """Parcels starting at rest on a ring of ``radius`` (m) around a low-pressure centre,
        pulled in by the pressure gradient (``pull``: its acceleration at the ring, m/s²,
        growing linearly with distance — a paraboloidal low), slowed by friction (1/s) and
        turned by the Coriolis force. The sense of the circulation comes out of the
        simulation: counterclockwise in the north, clockwise in the south (Fig. 2.7).

        Returns
        -------
        LowFlow
            Tracks (P, N, 2), the mean angular momentum about the centre ``circulation`` and
            its ``sense``.
        """
        lat = as_angle(latitude, "latitude", degrees)
        # The ring, the pull → strength set-up, the sample grid and the sense are the core's.
        r = self._core.low_flow(
            lat,
            as_scalar(radius, "radius"),
            as_count(parcels, "parcels", 1),
            as_scalar(pull, "pull"),
            as_scalar(friction, "friction"),
            as_scalar(duration, "duration"),
            run_settings(samples, rtol, atol, max_steps),
        )
        return _result(LowFlow, r)
