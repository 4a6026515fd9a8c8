"""Tops on the turning Earth: a rigid body carried by a moving frame (Foucault's gyroscope, a top
on a turntable) and the pendulous gyrocompass (issue 26).

* :class:`Place` — a place on the rotating :class:`~poinsot.Earth`, to give as
  ``poinsot.simulate(..., carried_by=Place(latitude))``; a :class:`~poinsot.MovingFrame` (its
  state at t = 0, continued steadily) is the other carrier.
* :class:`CarriedTrajectory` — what :func:`poinsot.simulate` returns for a carried body: the
  inertial :class:`~poinsot.Trajectory` plus the attitude seen from the carrying frame.
* :class:`Gyrocompass` — period (Schuler tuning), speed (steaming) error, latitude (damping)
  error, and the full nonlinear simulation on a ship.

Sign conventions (CONVENTIONS.md, "Gyrocompass"): local frame ENU (x east, y north, z up); a
*heading* is clockwise (east) from true north; the *tilt* is the north end's elevation; an
*error* is what the compass reads minus the truth (positive: reads high, its north lies west of
true north). Angles in radians, or pint quantities (``50 * ureg.deg``, ``20 * ureg.knot``).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from . import _core
from . import _display as show
from ._props import core_property
from ._units import ARGUMENTS, parse
from ._validate import (
    FloatArray,
    as_callable,
    as_float_array,
    as_scalar,
    as_vector3,
    run_settings,
)
from .dynamics import Trajectory, _torque_spec
from .earth import Earth
from .errors import ArgumentTypeError, PoinsotError

__all__ = ["Place", "CarriedTrajectory", "Gyrocompass", "CompassRun"]

_D = _core.DEFAULTS["Gyrocompass.__init__"]
_RUN = _core.DEFAULTS["Gyrocompass.simulate"]


def _earth_core(earth: Any) -> _core.EarthCore:
    """The core Earth held by ``earth`` (a :class:`~poinsot.Earth`; None: the default one)."""
    if earth is None:
        earth = Earth()
    if not isinstance(earth, Earth):
        raise ArgumentTypeError(f"earth: must be a poinsot.Earth, got {type(earth).__name__}")
    return earth._core


def _earth_numbers(core: _core.EarthCore) -> tuple[float, float, float]:
    """A core Earth's (rotation_rate, radius, g)."""
    return (core.rotation_rate, core.radius, core.g)


class Place:
    """A place at ``latitude`` (rad, north-positive) on the rotating ``earth`` (default
    :class:`~poinsot.Earth`), as a carrier for :func:`poinsot.simulate`: the local ENU frame
    turning at ω = Ω (0, cos λ, sin λ) (2.33), the pivot at the place, the specific force the
    effective (plumb-line) gravity −g ẑ (2.29–2.31) turning with the ground. The fixed axes of
    the simulation are the local ENU axes at t = 0."""

    __slots__ = ("latitude", "_earth")

    def __init__(self, latitude: Any, earth: Any = None) -> None:
        lat = as_scalar(latitude, "latitude")
        self._earth = _earth_core(earth)
        # The core makes the place (Carrier::earth) and refuses a latitude by name.
        _core.dynamics_check_place(self._earth, lat)
        self.latitude: float = lat

    @property
    def earth(self) -> Earth:
        """The :class:`~poinsot.Earth`."""
        return Earth._of(self._earth)

    def __repr__(self) -> str:
        return f"Place(latitude={self.latitude!r}, earth={self.earth!r})"

    def __reduce__(self) -> tuple[Any, ...]:
        return (Place, (self.latitude, self.earth))

    def __eq__(self, other: object) -> bool:
        return (
            isinstance(other, Place)
            and other.latitude == self.latitude
            and _earth_numbers(other._earth) == _earth_numbers(self._earth)
        )

    __hash__ = None  # type: ignore[assignment]


class CarriedTrajectory(Trajectory):
    """A :class:`~poinsot.Trajectory` of a body carried by a moving frame (returned by
    :func:`poinsot.simulate` with ``carried_by``): the inherited attributes are **inertial**
    (``omega`` body components, ``attitude`` body → fixed, ``angular_momentum`` fixed
    components; ``potential_energy`` is −m c·f, the potential of the specific force at that
    instant), and in addition:

    Attributes
    ----------
    relative_attitude:
        [w, x, y, z] (N, 4): body → carrying frame, the attitude seen from the frame.
    frame_attitude:
        [w, x, y, z] (N, 4): the carrying frame's axes, carrying frame → fixed.
    relative_omega:
        ω relative to the carrying frame, body components (rad/s), (N, 3).
    """

    def __init__(self, core: Any, relative: Any, frame: Any, relative_omega: Any) -> None:
        super().__init__(core)
        self.relative_attitude: FloatArray = np.asarray(relative)
        self.frame_attitude: FloatArray = np.asarray(frame)
        self.relative_omega: FloatArray = np.asarray(relative_omega)

    def _rows(self) -> list[show.Row]:
        return [
            *super()._rows(),
            show.samples(
                "relative_attitude",
                "attitude seen from the carrying frame",
                "q_rel",
                self.relative_attitude,
            ),
            show.samples("frame_attitude", "carrying frame → fixed", "A", self.frame_attitude),
            show.samples(
                "relative_omega",
                "angular velocity relative to the frame, body axes",
                "ω_rel",
                self.relative_omega,
                "rad/s",
            ),
        ]


def _simulate_carried(
    body: Any,
    omega0: Any,
    duration: Any,
    *,
    carried_by: Any,
    pivot: Any,
    gravity: Any,
    attitude0: Any,
    torque: Any,
    method: str,
    dt: Any,
    samples: Any,
    rtol: Any,
    atol: Any,
    max_steps: Any,
    progress: Any,
) -> CarriedTrajectory:
    """:func:`poinsot.simulate` with ``carried_by`` (see its docstring)."""
    from .dynamics import BodyTorque, SpaceTorque, _method
    from .frames import MovingFrame
    from .free import _quat

    if dt is not None:
        raise PoinsotError("dt: the carried body is integrated by 'exact' or 'dop853' (no dt)")
    if isinstance(carried_by, Place):
        kind = "earth"
        if pivot is not None or gravity is not None:
            name = "pivot" if pivot is not None else "gravity"
            raise PoinsotError(
                f"{name}: a Place sets the pivot (the place) and gravity (the Earth's); "
                "give them with a MovingFrame only"
            )
        frame = np.zeros(24)
        pivot_v, gravity_v = np.zeros(3), np.zeros(3)
        earth, lat = carried_by._earth, carried_by.latitude
    elif isinstance(carried_by, MovingFrame):
        kind = "frame"
        frame = carried_by._packed
        pivot_v = np.zeros(3) if pivot is None else as_vector3(pivot, "pivot")
        gravity_v = (
            np.array([0.0, 0.0, -_core.DEFAULTS["GravityTorque.__init__"]["g"]])
            if gravity is None
            else as_vector3(gravity, "gravity")
        )
        earth, lat = None, 0.0
    else:
        raise ArgumentTypeError(
            "carried_by: must be a poinsot.MovingFrame or a poinsot.Place, got "
            f"{type(carried_by).__name__}"
        )
    if hasattr(body, "inertia") and hasattr(body, "mass"):
        inertia = np.asarray(body.inertia_about(np.zeros(3)))
        mass_moment = float(body.mass) * np.asarray(body.center_of_mass, dtype=float)
    else:
        arr = as_float_array(body, "body", finite=False)
        if arr.shape == (3,):
            inertia = np.diag(arr)
        elif arr.shape == (3, 3):
            inertia = arr
        else:
            raise PoinsotError(
                "body: must be a RigidBody, principal moments (3,) or an inertia tensor (3, 3), "
                f"got shape {arr.shape}"
            )
        mass_moment = np.zeros(3)
    if torque is not None and not isinstance(torque, (BodyTorque, SpaceTorque)):
        raise ArgumentTypeError(
            "torque: with carried_by, only None, BodyTorque or SpaceTorque (gravity and the "
            f"frame's forces come from the carrier), got {type(torque).__name__}"
        )
    kind_, vec, scalar, _ = _torque_spec(torque, body)
    w0 = np.ascontiguousarray(as_float_array(omega0, "omega0", finite=False), dtype=np.float64)
    if w0.shape != (3,):
        raise PoinsotError(f"omega0: must have shape (3,), got {w0.shape}")
    core, rel, frame_q, rel_w = _core.dynamics_simulate_carried(
        (np.ascontiguousarray(inertia, dtype=np.float64), w0, _quat(attitude0, "attitude0")),
        as_scalar(duration, "duration"),
        kind,
        np.ascontiguousarray(frame, dtype=np.float64),
        np.ascontiguousarray(pivot_v, dtype=np.float64),
        np.ascontiguousarray(gravity_v, dtype=np.float64),
        earth,
        lat,
        np.ascontiguousarray(mass_moment, dtype=np.float64),
        (kind_, vec, scalar),
        _method(method),
        run_settings(samples, rtol, atol, max_steps),
        as_callable(progress, "progress"),
    )
    return CarriedTrajectory(core, rel, frame_q, rel_w)


class CompassRun(show.Displayed):
    """A gyrocompass's simulated motion (:meth:`Gyrocompass.simulate`).

    Attributes
    ----------
    t:
        Times (s), (N,).
    heading:
        Heading of the spin axis's north end, clockwise from true north (rad), (N,); minus the
        compass's error.
    tilt:
        Elevation of the north end above the horizontal (rad), (N,).
    latitude:
        The compass's (ship's) latitude (rad), (N,).
    envelope:
        Only for :meth:`Gyrocompass.linear_solution` (else None): the heading swing's envelope
        (rad, (N,)), the heading staying within ``settled_heading ± envelope``.
    settled_heading, settled_tilt:
        Only for :meth:`Gyrocompass.linear_solution` (else None): the heading and tilt (rad)
        the linear solution settles on.
    """

    def __init__(
        self,
        t: Any,
        heading: Any,
        tilt: Any,
        latitude: Any,
        envelope: Any = None,
        settled: tuple[float, float] | None = None,
    ) -> None:
        self.t: FloatArray = np.asarray(t)
        self.heading: FloatArray = np.asarray(heading)
        self.tilt: FloatArray = np.asarray(tilt)
        self.latitude: FloatArray = np.asarray(latitude)
        self.envelope: FloatArray | None = None if envelope is None else np.asarray(envelope)
        self.settled_heading: float | None = None if settled is None else float(settled[0])
        self.settled_tilt: float | None = None if settled is None else float(settled[1])

    def _rows(self) -> list[show.Row]:
        return [
            show.scalar("samples", "samples", "N", len(self.t)),
            show.span("t", "time", "t", self.t[0], self.t[-1], "s"),
            show.samples(
                "heading",
                "heading of the spin axis (east of north)",
                "α",
                self.heading,
                "rad",
                brief=True,
            ),
            show.samples("tilt", "tilt of the north end", "θ", self.tilt, "rad"),
            show.samples("latitude", "latitude", "λ", self.latitude, "rad"),
        ] + (
            []
            if self.envelope is None
            else [
                show.samples(
                    "envelope", "envelope of the swing", "A", self.envelope, "rad", brief=True
                )
            ]
        )


def _restore(*args: Any) -> Gyrocompass:
    out = Gyrocompass.__new__(Gyrocompass)
    out._core = _core.GyrocompassCore(*args)
    return out


def _item(name: str, index: int, doc: str) -> Any:
    """A read-only property: entry ``index`` of the core compass's tuple ``name`` (``args``,
    its constructor's arguments; ``settle``) as a float, documented by ``doc``."""
    return property(lambda self: float(getattr(self._core, name)[index]), doc=doc)


class Gyrocompass(show.Displayed):
    """A pendulous (gravity-controlled) gyrocompass at ``latitude`` on the rotating Earth.

    A rotor of angular momentum ``angular_momentum`` H along the spin axis, in a sensitive
    element hanging below its pivot (pendulosity P = m g l), optionally damped by a torque
    about its vertical proportional to the tilt (Sperry's damping; Arnold & Maunder,
    *Gyrodynamics and its Engineering Applications*, 1961, ch. 11). Linearised (Ω_c = Ω cos λ,
    Ω_s = Ω sin λ, heading α, tilt θ, D the damping coefficient)::

        dα/dt = Ω_s − (P/H + Ω_c) θ,    dθ/dt = Ω_c α − (D/H) θ,

    the spin axis oscillates about the meridian with the period 2π √(H/(P Ω cos λ)).

    Parameters
    ----------
    latitude:
        λ (rad, north-positive; or a pint angle), not at a pole (no meridian there).
    angular_momentum:
        H (kg·m²/s, > 0; default 40: a 0.02 kg·m² rotor at 20,000 rpm). Zero spin is refused.
        Defaults come from the core (``poinsot._core.DEFAULTS["Gyrocompass.__init__"]``).
    pendulosity:
        P = m g l (N·m, > 0; default 1.2: with the default H, Schuler-tuned near 45°).
    damping:
        Damping ratio ζ ∈ [0, 1) of the settling oscillation (default 0.3: the swing shrinks
        about 2.7 times per half period); D = 2 ζ ω_n H.
    inertia:
        Moments of the sensitive element about the pivot (kg·m², (spin axis, horizontal, up);
        default (0.5, 1, 1)): they set only the fast nutation H/I of :meth:`simulate`.
    earth:
        A :class:`~poinsot.Earth` (Ω, R, g); default the sidereal rate, mean radius, standard g.

    Examples
    --------
    >>> import poinsot as ps
    >>> c = ps.Gyrocompass.schuler_tuned(0.8)
    >>> round(c.period / 60, 1)    # Schuler's 84.4 min
    84.4
    """

    __slots__ = ("_core",)

    def __init__(
        self,
        latitude: Any,
        angular_momentum: Any = _D["angular_momentum"],
        pendulosity: Any = _D["pendulosity"],
        *,
        damping: Any = _D["damping"],
        inertia: Any = _D["inertia"],
        earth: Any = None,
    ) -> None:
        self._core = _core.GyrocompassCore(
            as_scalar(latitude, "latitude"),
            as_scalar(angular_momentum, "angular_momentum"),
            as_scalar(pendulosity, "pendulosity"),
            as_scalar(damping, "damping"),
            _moments(inertia),
            _earth_core(earth),
        )

    @classmethod
    def schuler_tuned(
        cls,
        latitude: Any,
        pendulosity: Any = _D["pendulosity"],
        *,
        damping: Any = _D["damping"],
        inertia: Any = _D["inertia"],
        earth: Any = None,
    ) -> Gyrocompass:
        """The compass whose period is Schuler's 2π √(R/g) (84.4 min on the default Earth):
        H = P Ω cos λ R / g. Arguments as the constructor."""
        out = cls.__new__(cls)
        out._core = _core.GyrocompassCore(
            as_scalar(latitude, "latitude"),
            None,
            as_scalar(pendulosity, "pendulosity"),
            as_scalar(damping, "damping"),
            _moments(inertia),
            _earth_core(earth),
        )
        return out

    @staticmethod
    def schuler_period(earth: Any = None) -> float:
        """2π √(R/g) (s): 5063.5 s = 84.4 min on the default Earth."""
        return float(_core.GyrocompassCore.schuler_period(_earth_core(earth)))

    def __reduce__(self) -> tuple[Any, ...]:
        return (_restore, tuple(self._core.args))

    # -- parameters ---------------------------------------------------------------------------
    latitude: float = _item("args", 0, "λ (rad).")
    angular_momentum: float = _item("args", 1, "H (kg·m²/s).")
    pendulosity: float = _item("args", 2, "P = m g l (N·m).")
    damping: float = _item("args", 3, "ζ.")

    @property
    def inertia(self) -> FloatArray:
        """Moments of the sensitive element (kg·m²), (3,)."""
        return np.array(self._core.args[4])

    @property
    def earth(self) -> Earth:
        """The :class:`~poinsot.Earth`."""
        return Earth._of(self._core.args[5])

    # -- results ------------------------------------------------------------------------------
    period = core_property(
        "period",
        """The undamped period of the settling oscillation about the meridian,
        2π √(H/(P Ω cos λ)) (s), from the linearised equations (the exact linear ω_n² =
        Ω_c (P/H + Ω_c) differs by the relative Ω_c H/(2P), 7e-4 for the defaults). Raises
        naming ``rotation_rate`` on a still Earth.""",
        float,
    )
    natural_frequency = core_property(
        "natural_frequency",
        "ω_n = √(Ω_c (P/H + Ω_c)) (rad/s) of the linearised equations.",
        float,
    )
    damping_coefficient = core_property(
        "damping_coefficient",
        "D = 2 ζ ω_n H (N·m/rad): the damping torque about the vertical per radian of tilt.",
        float,
    )
    ground_speed = core_property(
        "ground_speed", "The ground's eastward speed Ω R cos λ (m/s).", float
    )
    settle_error: float = _item(
        "settle",
        0,
        """The latitude (damping) error (rad): what the settled, damped compass at rest reads
        minus true north — negative (reads low, its north settled east of true north) in the
        north. From the full model's steady state, sin α = D θ/(H Ω cos λ) with tan θ =
        H Ω sin λ/(P + H Ω cos λ cos α); small-angle form −D tan λ/(P + H Ω cos λ). Zero
        when undamped.""",
    )
    settle_tilt: float = _item(
        "settle",
        1,
        "The settled tilt of the north end (rad): tan θ ≈ H Ω sin λ/(P + H Ω cos λ).",
    )

    def speed_error(self, speed: Any, course: Any) -> float:
        """The speed (steaming) error δ = atan(V cos C / (Ω R cos λ + V sin C)) (rad): the
        compass settles on the horizontal part of the local frame's angular velocity (the
        Earth's plus the ship's over the curved Earth); positive: it reads high, its north
        lies δ west of true north (northerly courses).

        ``speed`` V (m/s, ≥ 0, or a pint speed: ``20 * ureg.knot``), ``course`` C (rad,
        clockwise from north). Refused, naming ``speed``, when Ω R cos λ + V sin C ≤ 0: a ship
        going west at the ground's own speed or faster has no northward horizontal rotation
        to seek."""
        return float(self._core.speed_error(as_scalar(speed, "speed"), as_scalar(course, "course")))

    def speed_error_small_angle(self, speed: Any, course: Any) -> float:
        """The manufacturers' small-angle form V cos C / (Ω R cos λ) (rad) — in degrees with
        V in knots, about V cos C / (5π cos λ). It parts from :meth:`speed_error` at second
        order in V/(Ω R cos λ): by 0.8° at 50 knots due north at 81°. Same refusals."""
        return float(
            self._core.speed_error_small_angle(
                as_scalar(speed, "speed"), as_scalar(course, "course")
            )
        )

    def simulate(
        self,
        duration: Any,
        heading0: Any,
        *,
        tilt0: Any = None,
        speed: Any = None,
        course: Any = None,
        method: str = _RUN["method"],
        samples: int = _RUN["samples"],
        rtol: float = _RUN["rtol"],
        atol: float = _RUN["atol"],
        max_steps: int = _RUN["max_steps"],
        turns: Any = None,
        progress: Callable[[float], Any] | None = None,
    ) -> CompassRun:
        """Integrates the compass as a rigid gyrostat carried by the local frame (the full
        nonlinear equations of :func:`poinsot.simulate` with ``carried_by``; not the
        linearised ones), from rest relative to the ground.

        Parameters
        ----------
        duration:
            Simulated time (s, > 0).
        heading0:
            Starting heading of the spin axis, clockwise from north (rad).
        tilt0:
            Starting tilt (rad); None: the settled tilt :attr:`settle_tilt`.
        speed, course:
            The ship's speed (m/s, ≥ 0) and course (rad, clockwise from north), kept constant:
            a rhumb line from the compass's latitude (the ship's acceleration over the curved,
            turning Earth acts on the pendulous element). None: at rest.
        turns:
            Course and speed changes during the run, in time order: a sequence of ``(time,
            speed, course)`` or ``(time, speed, course, duration)``, each a number in SI (s,
            m/s, rad), a pint quantity, or text as typed at the command line (``("30min",
            "15kn", "180deg", "2min")``). From ``time`` the ship's velocity changes at a
            constant rate over ``duration`` (default one minute, the core's) to ``speed`` on
            ``course``; ``speed`` and ``course`` above are the start's. After a turn the
            compass settles on the new speed error; a Schuler-tuned compass goes there
            without swinging (no ballistic error: see docs/gyrocompass.md). Refused, naming
            ``turns``, when a turn starts before the one before it ends, or takes no time.
        method, samples, rtol, atol, max_steps, progress:
            As :func:`poinsot.simulate` ("dop853" or "rk4" — no fixed step is taken by
            "rk4" here: use "dop853").

        The element's nutation (at H/I, 40 rad/s for the defaults) sets the steps: about
        10⁵ per simulated hour.

        Examples
        --------
        >>> import poinsot as ps
        >>> c = ps.Gyrocompass.schuler_tuned(0.5, damping=0.0)
        >>> run = c.simulate(600, 0.0, speed=10, turns=[("2min", "10 m/s", "180deg", "1min")],
        ...                  samples=3)
        >>> len(run.t)
        3
        """
        tilt = self.settle_tilt if tilt0 is None else as_scalar(tilt0, "tilt0")
        span = as_scalar(duration, "duration")
        start = as_scalar(heading0, "heading0")
        v = 0.0 if speed is None else as_scalar(speed, "speed")
        c = 0.0 if course is None else as_scalar(course, "course")
        how = method if isinstance(method, str) else str(method)
        settings = run_settings(samples, rtol, atol, max_steps)
        report = as_callable(progress, "progress")
        track = [] if turns is None else _turns(turns)
        t, heading, tilt_out, lat = self._core.simulate(
            span, start, tilt, v, c, track, how, settings, report
        )
        return CompassRun(t, heading, tilt_out, lat)

    def linear_solution(
        self,
        t: Any,
        heading0: Any,
        *,
        tilt0: Any = None,
        speed: Any = None,
        course: Any = None,
    ) -> CompassRun:
        """The linearised compass at the times ``t`` (s), from heading ``heading0`` and tilt
        ``tilt0`` (rad; None: :attr:`settle_tilt`) at t = 0, on a ship at ``speed`` (m/s) on
        ``course`` (rad) or at rest: the linear equations of the class docstring, about the
        settled heading −(:attr:`settle_error` + :meth:`speed_error`) and tilt, solved in
        closed form by the core — a swing at ω_n √(1 − ζ²) decaying as e^{−ζ ω_n t}. Returns
        a :class:`CompassRun` whose ``envelope`` (rad) bounds the heading's swing and whose
        ``settled_heading``/``settled_tilt`` are its centre. Raises naming ``t``,
        ``heading0``, ``tilt0``, ``speed`` or ``rotation_rate`` (a still Earth)."""
        times = as_float_array(t, "t").reshape(-1)
        tilt = self.settle_tilt if tilt0 is None else as_scalar(tilt0, "tilt0")
        heading, tilt_out, envelope, settled = self._core.linear_solution(
            np.ascontiguousarray(times, dtype=np.float64),
            as_scalar(heading0, "heading0"),
            tilt,
            0.0 if speed is None else as_scalar(speed, "speed"),
            0.0 if course is None else as_scalar(course, "course"),
        )
        return CompassRun(
            times, heading, tilt_out, np.full(times.shape, self.latitude), envelope, settled
        )

    def _rows(self) -> list[show.Row]:
        rows = [
            show.scalar("latitude", "latitude", "λ", self.latitude, "rad"),
            show.scalar(
                "angular_momentum", "rotor angular momentum", "H", self.angular_momentum, "kg·m²/s"
            ),
            show.scalar("pendulosity", "pendulosity", "m g l", self.pendulosity, "N·m"),
            show.scalar("damping", "damping ratio", "ζ", self.damping),
        ]
        try:
            rows.append(show.scalar("period", "settling period", "T", self.period, "s"))
        except PoinsotError:
            pass
        rows.append(
            show.scalar(
                "settle_error",
                "latitude (damping) error",
                "δ_λ",
                self.settle_error,
                "rad",
                brief=False,
            )
        )
        return rows


#: A turn's fields in order; each converts by its dimension in ``_units.ARGUMENTS``.
_TURN_FIELDS = ("time", "speed", "course", "duration")


def _turn_field(value: Any, field: str, k: int) -> float:
    """Field ``field`` of turn ``k`` in SI: text as typed at the command line (``"15kn"``,
    ``"180deg"``, ``"2min"``; :func:`._units.parse`), a pint quantity or a number
    (:func:`._validate.as_scalar`, which converts a quantity once)."""
    try:
        if isinstance(value, str):
            return parse(value, ARGUMENTS[field][0])[0]
        return as_scalar(value, field)
    except ValueError as e:
        cls = type(e) if isinstance(e, PoinsotError) else PoinsotError
        raise cls(f"turns: turn {k}'s {field}: {str(e).removeprefix(field + ': ')}") from None


def _turns(turns: Any) -> list[tuple[float, float | None, float, float]]:
    """``turns`` as the core's (time s, duration s or None, speed m/s, course rad) rows."""
    if isinstance(turns, (str, bytes)) or not hasattr(turns, "__iter__"):
        raise ArgumentTypeError(
            f"turns: must be a sequence of (time, speed, course[, duration]), got "
            f"{type(turns).__name__}"
        )
    rows = []
    for k, turn in enumerate(turns):
        if (
            isinstance(turn, (str, bytes))
            or not hasattr(turn, "__len__")
            or len(turn) not in (3, 4)
        ):
            raise PoinsotError(
                f"turns: turn {k} must be (time, speed, course) or (time, speed, course, "
                f"duration), got {turn!r}"
            )
        got = [_turn_field(value, field, k) for value, field in zip(turn, _TURN_FIELDS)]
        rows.append((got[0], got[3] if len(got) == 4 else None, got[1], got[2]))
    return rows


def _moments(inertia: Any) -> tuple[float, float, float]:
    """The compass's three principal moments (kg·m²), shape ``(3,)``."""
    a, b, c = as_vector3(inertia, "inertia").tolist()
    return (a, b, c)
