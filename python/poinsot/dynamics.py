"""Rigid-body dynamics: Euler's equations of motion with torques (the unit's 2.67–2.76) and
:func:`simulate`, one interface to the exact torque-free flow, the Lie–Poisson splitting
(orders 2, 4, 6), RK4 and DOP853, plus :func:`simulate_batch` for many bodies at once.

Conventions (pinned by the ``test_convention_*`` tests):

* ω in **body** components (rad/s); the attitude a unit quaternion **[w, x, y, z]** rotating
  body components into space components; L in **space** components; torques in N·m;
* :class:`GravityTorque` is the unit's heavy top: pivot at the origin, centre of mass at
  distance l on body axis 3, gravity −g along the space Z axis, V = m g l cos θ; the inertia
  must then be about the pivot;
* samples are evenly spaced from 0 to ``duration``, both ends included; the step ``dt`` of
  the fixed-step methods is independent of the sampling (the step taken is Δ/⌈Δ/dt⌉ ≤ dt for
  the sample interval Δ, so samples fall on steps).

All physics runs in the compiled core; callbacks are called from it (slower: one Python call
per torque evaluation).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, ClassVar, Union

import numpy as np

from . import _core
from . import _display as show
from ._core import DEFAULTS as _DEFAULTS
from ._validate import (
    FloatArray,
    as_callable,
    as_count,
    as_float_array,
    as_rows,
    as_scalar,
    as_vector3,
)
from .errors import ArgumentTypeError, PoinsotError
from .free import _quat

__all__ = [
    "BodyTorque",
    "SpaceTorque",
    "GravityTorque",
    "GravityGradientTorque",
    "Trajectory",
    "simulate",
    "simulate_batch",
    "METHODS",
    "DEFAULT_MAX_STEPS",
]

#: The default step limit of :func:`simulate` and :func:`simulate_batch` (10⁸).
DEFAULT_MAX_STEPS: int = _core.DEFAULT_MAX_STEPS

#: The integration methods of :func:`simulate`.
METHODS = ("auto", "exact", "rk4", "dop853", "splitting2", "splitting4", "splitting6")


@dataclass(frozen=True)
class _ConstantTorque:
    """A constant torque (N·m, (3,)) in the components of the frame ``_FRAME``."""

    torque: Any
    _FRAME: ClassVar[str]

    def __post_init__(self) -> None:
        object.__setattr__(self, "torque", as_vector3(self.torque, "torque"))

    def _spec(self, body: Any) -> tuple[str, FloatArray, float]:
        return self._FRAME, as_vector3(self.torque, "torque"), 0.0


class BodyTorque(_ConstantTorque):
    """A constant torque in body components (N·m, (3,)), like a thruster fixed to the body."""

    _FRAME = "body"


class SpaceTorque(_ConstantTorque):
    """A constant torque in space components (N·m, (3,)): N_body = Rᵀ N_space."""

    _FRAME = "space"


@dataclass(frozen=True)
class GravityTorque:
    """Gravity on a body turning about a fixed pivot at the origin (the unit's heavy top):
    centre of mass at distance l on body axis 3, gravity −g along space Z,
    N_body = m g l (Rᵀ Z) × e₃, potential V = m g l cos θ.

    Give ``mgl`` (J), or leave it None with a :class:`RigidBody` whose centre of mass lies on
    its axis 3 (then m g l = mass · g · com_z and the inertia is taken about the origin)."""

    mgl: float | None = None
    g: float = _DEFAULTS["GravityTorque.__init__"]["g"]

    def __post_init__(self) -> None:
        if self.mgl is not None:
            object.__setattr__(self, "mgl", as_scalar(self.mgl, "mgl"))
        g = as_scalar(self.g, "g")
        if not g > 0:
            raise PoinsotError(f"g: must be > 0, got {g}")
        object.__setattr__(self, "g", g)

    def _spec(self, body: Any) -> tuple[str, FloatArray, float]:
        if self.mgl is not None:
            return "gravity", np.zeros(3), as_scalar(self.mgl, "mgl")
        if not hasattr(body, "center_of_mass"):
            raise PoinsotError("mgl: give m·g·l when the body is given by its moments")
        com = np.asarray(body.center_of_mass)
        scale = max(1.0, float(np.abs(com).max()))
        if abs(com[0]) > 1e-12 * scale or abs(com[1]) > 1e-12 * scale:
            raise PoinsotError(
                f"body: the centre of mass must lie on body axis 3 for GravityTorque, got {com.tolist()}"
            )
        return "gravity", np.zeros(3), float(body.mass) * as_scalar(self.g, "g") * float(com[2])


@dataclass(frozen=True)
class GravityGradientTorque:
    """The gravity-gradient torque on a satellite on a circular orbit of mean motion
    n = (μ/r³)^½ (rad/s) in the space XY plane, at r̂(t) = (cos nt, sin nt, 0):
    N_body = 3 n² r̂_b × (I·r̂_b), r̂_b = Rᵀ r̂."""

    mean_motion: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "mean_motion", as_scalar(self.mean_motion, "mean_motion"))

    def _spec(self, body: Any) -> tuple[str, FloatArray, float]:
        return "gravity_gradient", np.zeros(3), as_scalar(self.mean_motion, "mean_motion")


TorqueLike = Union[
    None,
    BodyTorque,
    SpaceTorque,
    GravityTorque,
    GravityGradientTorque,
    Callable[[float, FloatArray, FloatArray], Any],
]


class Trajectory(show.Displayed):
    """A sampled rigid-body trajectory (returned by :func:`simulate`).

    Attributes
    ----------
    t:
        Sample times (s), shape (N,), evenly spaced from 0 to the duration.
    omega:
        ω in body components (rad/s), (N, 3).
    attitude:
        Quaternions [w, x, y, z] (body → space), (N, 4), signs continuous.
    angular_momentum:
        L in space components (kg·m²/s), (N, 3).
    energy:
        Kinetic energy T = ½ ω·I·ω (J), (N,).
    potential_energy:
        V of a conservative torque (gravity: m g l cos θ), else zeros (J), (N,).
    power:
        ω·N, the power of the torque (W), (N,): equals dT/dt (2.76).
    method:
        The method used ("exact", "rk4", "dop853", "splitting2/4/6").
    step:
        The fixed step taken (s), or None for "exact" and "dop853".
    steps, torque_evaluations:
        Work counters.
    """

    def __init__(self, core: _core.TrajectoryCore) -> None:
        self.t: FloatArray = core.t
        self.omega: FloatArray = core.omega
        self.attitude: FloatArray = core.attitude
        self.angular_momentum: FloatArray = core.angular_momentum
        self.energy: FloatArray = core.energy
        self.potential_energy: FloatArray = core.potential
        self.power: FloatArray = core.power
        self.method: str = core.method
        self.step: float | None = core.step
        self.steps: int = core.steps
        self.torque_evaluations: int = core.torque_evaluations

    def _rows(self) -> list[show.Row]:
        return [
            show.scalar("samples", "samples", "N", len(self.t)),
            show.span("t", "time", "t", self.t[0], self.t[-1], "s"),
            show.words("method", "method", self.method),
            show.scalar("steps", "steps taken", "", self.steps),
            *show.scalars(
                self,
                ("step", "fixed step", "Δt", "s"),
                ("torque_evaluations", "torque evaluations", "", ""),
                brief=False,
            ),
            show.samples("omega", "angular velocity, body axes", "ω", self.omega, "rad/s"),
            show.samples("attitude", "attitude [w, x, y, z], body → space", "q", self.attitude),
            show.samples(
                "angular_momentum",
                "angular momentum, space axes",
                "L",
                self.angular_momentum,
                "kg·m²/s",
            ),
            show.samples("energy", "kinetic energy", "T", self.energy, "J"),
            show.samples("potential_energy", "potential energy", "V", self.potential_energy, "J"),
            show.samples("power", "power of the torque (2.76)", "ω·N", self.power, "W"),
        ]

    @property
    def total_energy(self) -> FloatArray:
        """T + V (J), (N,): conserved under gravity."""
        return self.energy + self.potential_energy

    def energy_error(self) -> FloatArray:
        """|E(t)/E(0) − 1| with E = T + V (relative; absolute when E(0) = 0), (N,)."""
        e = self.total_energy
        return np.abs(e - e[0]) / (abs(e[0]) if e[0] != 0 else 1.0)

    def momentum_error(self) -> FloatArray:
        """||L(t)| / |L(0)| − 1| (relative), (N,): round-off for the splitting without torque.

        |L| is a scaled hypotenuse, finite whenever the length is (L of 1e308 kg·m²/s: the
        sum of squares would overflow)."""
        n = _lengths(self.angular_momentum)
        return np.abs(n - n[0]) / (n[0] if n[0] != 0 else 1.0)

    def rotation(self) -> Any:
        """The attitudes as a ``scipy.spatial.transform.Rotation`` (needs scipy)."""
        from scipy.spatial.transform import Rotation

        q = self.attitude
        return Rotation.from_quat(np.column_stack([q[:, 1], q[:, 2], q[:, 3], q[:, 0]]))


def _lengths(rows: FloatArray) -> FloatArray:
    """The length of each row of ``rows`` (N, 3) without overflowing on the squares:
    hypot(hypot(x, y), z), finite whenever the length itself is a double."""
    return np.asarray(np.hypot(np.hypot(rows[:, 0], rows[:, 1]), rows[:, 2]))


def _inertia_of(body: Any, torque: TorqueLike) -> FloatArray:
    """The inertia tensor for the equations of motion: about the pivot (the origin) under
    GravityTorque without mgl, else about the centre of mass; moments (3,) or a tensor (3, 3)."""
    if hasattr(body, "inertia") and hasattr(body, "mass"):
        if isinstance(torque, GravityTorque) and torque.mgl is None:
            return np.asarray(body.inertia_about(np.zeros(3)))
        return np.asarray(body.inertia)
    arr = as_float_array(body, "body", finite=False)
    if arr.shape == (3,):
        return np.diag(arr)
    if arr.shape == (3, 3):
        return arr
    raise PoinsotError(
        f"body: must be a RigidBody, principal moments (3,) or an inertia tensor (3, 3), got shape {arr.shape}"
    )


def _torque_spec(torque: TorqueLike, body: Any) -> tuple[str, FloatArray, float, Any]:
    if torque is None:
        return "none", np.zeros(3), 0.0, None
    spec = getattr(torque, "_spec", None)
    if spec is not None:
        kind, vec, scalar = spec(body)
        return kind, np.ascontiguousarray(vec, dtype=np.float64), scalar, None
    if callable(torque):
        return "callback", np.zeros(3), 0.0, torque
    raise ArgumentTypeError(
        "torque: must be None, BodyTorque, SpaceTorque, GravityTorque, GravityGradientTorque or a callable "
        f"f(t, omega, attitude) -> (3,), got {type(torque).__name__}"
    )


def _optional_step(dt: Any) -> float | None:
    if dt is None:
        return None
    dt_f = as_scalar(dt, "dt")
    if not dt_f > 0:
        raise PoinsotError(f"dt: must be finite and > 0, got {dt}")
    return dt_f


def simulate(
    body: Any,
    omega0: Any,
    duration: float,
    *,
    attitude0: Any = None,
    torque: TorqueLike = None,
    method: str = _DEFAULTS["simulate"]["method"],
    dt: float | None = None,
    samples: int = _DEFAULTS["simulate"]["samples"],
    rtol: float = _DEFAULTS["simulate"]["rtol"],
    atol: float = _DEFAULTS["simulate"]["atol"],
    max_steps: int = _DEFAULTS["simulate"]["max_steps"],
    progress: Callable[[float], Any] | None = None,
    carried_by: Any = None,
    pivot: Any = None,
    gravity: Any = None,
) -> Trajectory:
    """Simulates a rigid body turning under a torque (Euler's equations 2.71 with the attitude).

    Parameters
    ----------
    body:
        A :class:`RigidBody` (inertia about its centre of mass; about the origin under
        ``GravityTorque()``), principal moments (3,) or an inertia tensor (3, 3) (kg·m²).
    omega0:
        Body angular velocity at t = 0 (rad/s, (3,)).
    duration:
        Simulated time (s, > 0).
    attitude0:
        [w, x, y, z] (body → space) or a scipy Rotation; identity if None.
    torque:
        None (torque-free), :class:`BodyTorque`, :class:`SpaceTorque`, :class:`GravityTorque`,
        :class:`GravityGradientTorque`, or a callable ``f(t, omega (3,), attitude (4,))``
        returning the body-frame torque (3,) — slower: one Python call per evaluation, and not
        usable with the splitting (it might depend on ω).
    method:
        "auto" (the exact flow without torque, DOP853 with one), "exact", "rk4", "dop853", or
        "splitting2" / "splitting4" / "splitting6" (the symplectic Lie–Poisson splitting).
    dt:
        Step of the fixed-step methods (s); None picks 1/1000 of a turn at the fastest rate.
    samples:
        Number of evenly spaced output times, both ends included (≥ 2). Memory grows with
        ``samples`` only, never with the number of steps.
    rtol, atol:
        DOP853 tolerances.
    max_steps:
        Step limit (default 10⁸). A fixed-step method refuses a request that needs more before
        the first step (the error says how many steps it needs); DOP853 stops when it reaches
        the limit.
    progress:
        Optional ``progress(fraction)``, called at most every 20 ms of wall-clock time with the
        fraction done and once with 1.0 at the end. An exception it raises stops the run and
        propagates.
    carried_by:
        None, or the frame carrying the body's pivot: a :class:`MovingFrame` (its state at
        t = 0, continued steadily: a turntable) or a :class:`Place` on the rotating Earth
        (Foucault's gyroscope). The attitude is then integrated in the inertial frame with the
        pivot's acceleration acting as the translational fictitious force (2.5) at the centre
        of mass (on the Earth: the effective gravity, 2.29); the body is a :class:`RigidBody`
        pivoted at its coordinate origin (inertia about it, centre of mass from it) or moments
        / a tensor about a pivot at the centre of mass; ``omega0`` and ``attitude0`` are
        **relative to the carrying frame** (0: at rest on it), whose axes are the fixed axes at
        t = 0; ``torque`` only None, :class:`BodyTorque` or :class:`SpaceTorque`; no ``dt``.
        Returns a :class:`CarriedTrajectory` (inertial attributes plus
        ``relative_attitude``, ``frame_attitude``, ``relative_omega``).
    pivot:
        With a :class:`MovingFrame`: the pivot in the frame's components (m, (3,); default the
        frame's origin).
    gravity:
        With a :class:`MovingFrame`: uniform gravity in fixed components (m/s², (3,); default
        (0, 0, −9.80665)).

    Notes
    -----
    The run can be stopped with Ctrl-C (``KeyboardInterrupt``, within a tenth of a second).
    ``samples`` is checked against the memory budget (:func:`memory_budget`) before any work.

    Raises
    ------
    PoinsotError
        Bad input; the message names the argument (``omega0``, ``duration``, ``dt``,
        ``samples``, ``max_steps``, ``method``, ``torque``, ...).
    ArgumentTypeError
        An argument of the wrong type (a ``PoinsotError`` and a ``TypeError``).
    InvalidInertiaError, InvalidRotationError
        Invalid inertia (naming ``body``); non-unit or zero ``attitude0``.
    IntegrationError
        The motion diverged (naming ``duration``, and the time it failed; ``torque`` when a
        callable returned NaN).
    """
    if carried_by is not None or pivot is not None or gravity is not None:
        from .gyrocompass import _simulate_carried

        if carried_by is None:
            raise PoinsotError("carried_by: pivot and gravity need a carrying frame")
        return _simulate_carried(
            body,
            omega0,
            duration,
            carried_by=carried_by,
            pivot=pivot,
            gravity=gravity,
            attitude0=attitude0,
            torque=torque,
            method=method,
            dt=dt,
            samples=samples,
            rtol=rtol,
            atol=atol,
            max_steps=max_steps,
            progress=progress,
        )
    kind, vec, scalar, fn = _torque_spec(torque, body)
    inertia = np.ascontiguousarray(_inertia_of(body, torque), dtype=np.float64)
    w0 = np.ascontiguousarray(as_float_array(omega0, "omega0", finite=False), dtype=np.float64)
    if w0.shape != (3,):
        raise PoinsotError(f"omega0: must have shape (3,), got {w0.shape}")
    dur = as_scalar(duration, "duration")
    dt_f = _optional_step(dt)
    n = as_count(samples, "samples", 2)
    q0 = _quat(attitude0, "attitude0")
    method = _method(method)
    steps = as_count(max_steps, "max_steps", 1)
    progress = as_callable(progress, "progress")
    fn_wrapped = None
    if fn is not None:

        def fn_wrapped(t: float, w: FloatArray, q: FloatArray) -> Any:
            out = np.asarray(fn(t, w, q))
            if out.dtype.kind not in "iuf":
                raise PoinsotError(f"torque: the callable must return 3 real numbers, got {out!r}")
            return out.astype(np.float64).reshape(-1).tolist()

    core = _core.dynamics_simulate(
        (inertia, w0, q0),
        dur,
        (kind, vec, scalar),
        fn_wrapped,
        method,
        dt_f,
        (n, as_scalar(rtol, "rtol"), as_scalar(atol, "atol"), steps),
        progress,
    )
    return Trajectory(core)


def _batch_settings(
    torque: Any, duration: Any, method: Any, dt: Any, max_steps: Any, refusal: str
) -> tuple[float, tuple[str, FloatArray, float], str, float | None, int]:
    """The settings of a batch of bodies (:func:`simulate_batch`, ``sweep.simulate``) as the
    core takes them: the duration (s), the torque's (kind, vector, scalar), the method, the
    step (s, None: each body's default) and the step limit. ``refusal`` is the caller's reason
    for refusing a callable torque, the message after ``"torque: "``."""
    if torque is not None and not hasattr(torque, "_spec"):
        raise ArgumentTypeError(f"torque: {refusal}")
    kind, vec, scalar, _ = _torque_spec(torque, None)
    return (
        as_scalar(duration, "duration"),
        (kind, vec, scalar),
        _method(method),
        _optional_step(dt),
        as_count(max_steps, "max_steps", 1),
    )


def _method(method: Any) -> str:
    if not isinstance(method, str):
        raise ArgumentTypeError(
            f"method: must be one of {', '.join(map(repr, METHODS))}, got {type(method).__name__}"
        )
    return method


def simulate_batch(
    moments: Any,
    omega0: Any,
    duration: float,
    *,
    attitude0: Any = None,
    torque: TorqueLike = None,
    method: str = _DEFAULTS["simulate_batch"]["method"],
    dt: float | None = None,
    max_steps: int = _DEFAULTS["simulate_batch"]["max_steps"],
    progress: Callable[[float], Any] | None = None,
) -> tuple[FloatArray, FloatArray]:
    """Integrates many bodies at once, in parallel (all cores), and returns their final states.

    RK4 and the splittings run on SIMD lanes in the core (a group of bodies per vector
    instruction: 8 with AVX2, detected at run time), the groups spread over the cores: RK4 gives
    :func:`simulate`'s numbers for each body bit for bit, the splittings the same to a relative
    1e-16 per step; a body's result does not depend on its place in the batch or on the number
    of threads. Every built-in torque runs on the lanes; a torque given as a Python callable is
    not taken here (the lanes need it in the core): integrate such bodies one by one with
    :func:`simulate`. The exact flow and DOP853 run body by body. For the exact torque-free
    states at many times, :func:`free_body_states`.

    Parameters
    ----------
    moments:
        Principal moments (kg·m², (N, 3)); body axes principal.
    omega0:
        Body angular velocities at t = 0 (rad/s, (N, 3)).
    duration:
        Simulated time (s).
    attitude0:
        Quaternions [w, x, y, z] (N, 4), identity if None.
    torque:
        As :func:`simulate`, except callables (the same torque model for every body, with
        each body's inertia; ``GravityTorque`` needs ``mgl``).
    method:
        "exact", "rk4" (default), "dop853", "splitting2/4/6" or "auto".
    dt:
        Fixed step (s); None: each body's default.
    max_steps:
        Step limit per body (default 10⁸), checked before the first step for the fixed-step
        methods (the error says how many steps the request needs).
    progress:
        Optional ``progress(fraction)`` (fraction of the bodies done), called at most every
        20 ms; an exception it raises stops the run. Ctrl-C stops it too.

    Returns
    -------
    (omega, attitude):
        Final ω (N, 3) and attitudes (N, 4).
    """
    m, w = as_rows(moments, "moments", 3), as_rows(omega0, "omega0", 3)
    q = None if attitude0 is None else as_rows(attitude0, "attitude0", 4)
    settings = _batch_settings(
        torque,
        duration,
        method,
        dt,
        max_steps,
        "simulate_batch takes the built-in torques only (no callables)",
    )
    w_out, q_out, _steps = _core.dynamics_simulate_batch(
        (m, w, q), settings, as_callable(progress, "progress")
    )
    return np.asarray(w_out), np.asarray(q_out)
