"""Moving frames: a particle seen from a translating and rotating frame (the unit's eqs. 2.1–2.28).

Notation of the unit: primed quantities belong to the fixed (inertial) frame, unprimed ones to
the moving frame; ``R`` is the moving origin and ω the moving frame's angular velocity.

* :class:`MovingFrame` — the state of a moving frame at one instant; transforms positions,
  velocities and accelerations both ways with the acceleration split into its named terms
  (eqs. 2.20–2.23), and gives the fictitious forces (eqs. 2.5, 2.26–2.28).
* :func:`simulate_particle` — a particle integrated in a moving frame (steady or given by
  functions of time) under a force of your choice, with every fictitious force.

Vectors are NumPy arrays of shape ``(..., 3)`` (leading dimensions broadcast); SI units.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, Union

import numpy as np

from . import _core
from ._props import core_property
from ._validate import (
    FloatArray,
    as_count,
    as_float_array,
    as_matrices,
    as_scalar,
    as_vectors,
    returned,
    shaped,
)
from .errors import PoinsotError

__all__ = [
    "MovingFrame",
    "FrameTransform",
    "ParticleTrajectory",
    "SpringParticle",
    "simulate_particle",
]

# The defaults are the core's (the browser lab's particle uses the same ones).
_PARTICLE = _core.DEFAULTS["simulate_particle"]
_SPRING = _core.DEFAULTS["SpringParticle.simulate"]
_FRAME = _core.DEFAULTS["MovingFrame.__init__"]


def _vector(value: Any, name: str) -> FloatArray:
    """A 3-vector from a vector or a scalar (broadcast to the three components)."""
    arr = as_float_array(value, name)
    if arr.ndim == 0:
        return np.full(3, float(arr))
    if arr.shape != (3,):
        raise PoinsotError(f"{name}: must be a scalar or have shape (3,), got {arr.shape}")
    return arr.copy()


_ZERO3 = np.zeros(3)


def _fast_scalar(value: Any, name: str) -> float:
    """A finite float (fast path for Python floats and ints)."""
    if type(value) is float:
        if math.isfinite(value):
            return value
    elif type(value) is int and -(2**53) <= value <= 2**53:
        return float(value)
    return as_scalar(value, name)


_F64 = np.dtype(np.float64)
_IDENTITY_FRAME = np.concatenate([np.zeros(15), np.eye(3).ravel()])


def _fast_vector(value: Any, name: str) -> FloatArray:
    """A C-contiguous float64 (3,) array; finiteness is left to the core."""
    if (
        type(value) is np.ndarray
        and value.dtype is _F64
        and value.shape == (3,)
        and value.flags.c_contiguous
    ):
        return value
    return _vector(value, name)


def _broadcast(values: list[tuple[Any, str]]) -> tuple[list[FloatArray], tuple[int, ...]]:
    """Broadcast ``(..., 3)`` arrays together; returns them flattened to ``(N, 3)`` and the
    leading shape."""
    arrs = []
    for v, name in values:
        a = as_float_array(v, name)
        if a.ndim == 0:
            a = np.full(3, float(a))
        if a.shape[-1] != 3:
            raise PoinsotError(f"{name}: must have shape (..., 3), got {a.shape}")
        arrs.append(a)
    try:
        shape = np.broadcast_shapes(*(a.shape for a in arrs))
    except ValueError:
        shapes = ", ".join(f"{n} {a.shape}" for a, (_, n) in zip(arrs, values))
        raise PoinsotError(f"{values[0][1]}: shapes do not broadcast together ({shapes})") from None
    flat = [np.ascontiguousarray(np.broadcast_to(a, shape).reshape(-1, 3)) for a in arrs]
    return flat, shape[:-1]


@dataclass(frozen=True)
class FrameTransform:
    """A particle's position, velocity and acceleration in the other frame.

    Attributes
    ----------
    position:
        Array of shape ``(..., 3)`` (m).
    velocity:
        Array of shape ``(..., 3)`` (m/s).
    acceleration:
        Array of shape ``(..., 3)`` (m/s²).
    acceleration_terms:
        The named terms of ``acceleration`` (each ``(..., 3)``), which sum to it. From
        :meth:`MovingFrame.to_fixed` (fixed components, eq. 2.21): ``"relative"`` (d²r/dt²)_rot,
        ``"origin"`` R̈, ``"coriolis"`` 2ω×ṙ, ``"centripetal"`` ω×(ω×r), ``"euler"`` ω̇×r.
        From :meth:`MovingFrame.to_moving` (moving components): ``"inertial"`` r̈',
        ``"translational"`` −R̈, ``"coriolis"`` −2ω×ṙ, ``"centrifugal"`` −ω×(ω×r),
        ``"euler"`` −ω̇×r.
    """

    position: FloatArray
    velocity: FloatArray
    acceleration: FloatArray
    acceleration_terms: dict[str, FloatArray] = field(repr=False)


def _state_property(start: int, doc: str) -> Any:
    """A read-only vector of :class:`MovingFrame`: its state's three numbers from ``start``
    (a copy), documented by ``doc``."""
    return property(lambda self: self._packed[start : start + 3].copy(), doc=doc)


class MovingFrame:
    """The state of a moving frame at one instant, relative to the fixed (inertial) frame.

    Parameters (keyword-only; vectors of shape ``(3,)`` in fixed-frame components, or scalars
    broadcast to all three components; default 0):

    origin:
        Position R of the moving origin (m).
    velocity:
        Its velocity Ṙ (m/s).
    acceleration:
        Its acceleration R̈ (m/s²).
    angular_velocity:
        Angular velocity ω of the moving axes (rad/s).
    angular_acceleration:
        Angular acceleration ω̇ (rad/s²); the same seen from either frame (eq. 2.16).
    attitude:
        The moving axes as the columns of a rotation matrix in fixed components (a ``(3, 3)``
        array or a ``scipy.spatial.transform.Rotation``); ``None`` (default): momentarily
        aligned with the fixed axes, as in the unit.

    The particle's own (relative) quantities are in moving-frame components. With ω = 0 the
    frame only translates (eqs. 2.1–2.5, Galilean invariance when R̈ = 0).

    Examples
    --------
    >>> import poinsot as ps
    >>> turntable = ps.MovingFrame(angular_velocity=[0, 0, 2.0])
    >>> turntable.to_fixed([3.0, 0, 0]).acceleration   # at rest on it: −ω² r
    array([-12.,   0.,   0.])
    """

    # One array, the core's packed frame (24,): origin, velocity, acceleration, angular
    # velocity, angular acceleration (3 each), then the attitude (3, 3) row-major; the
    # properties below are copies of its pieces.
    __slots__ = ("_packed",)

    def __init__(
        self,
        *,
        origin: Any = _FRAME["origin"],
        velocity: Any = _FRAME["velocity"],
        acceleration: Any = _FRAME["acceleration"],
        angular_velocity: Any = _FRAME["angular_velocity"],
        angular_acceleration: Any = _FRAME["angular_acceleration"],
        attitude: Any = None,
    ) -> None:
        parts = [
            _vector(origin, "origin"),
            _vector(velocity, "velocity"),
            _vector(acceleration, "acceleration"),
            _vector(angular_velocity, "angular_velocity"),
            _vector(angular_acceleration, "angular_acceleration"),
        ]
        if attitude is None:
            parts.append(np.eye(3).ravel())
        else:
            mats, lead = as_matrices(attitude, "attitude")
            if lead != ():
                raise PoinsotError(f"attitude: must be one (3, 3) rotation, got {lead + (3, 3)}")
            parts.append(mats[0].ravel())
        self._packed = np.concatenate(parts)
        # Let the core check the attitude (a proper rotation) once.
        empty = np.zeros((0, 3))
        _core.frame_to_fixed(self._packed, empty, empty, empty)

    # -- the state ------------------------------------------------------------------------
    origin = _state_property(0, "R (m), shape (3,).")
    velocity = _state_property(3, "Ṙ (m/s), shape (3,).")
    acceleration = _state_property(6, "R̈ (m/s²), shape (3,).")
    angular_velocity = _state_property(9, "ω (rad/s), shape (3,), fixed components.")
    angular_acceleration = _state_property(12, "ω̇ (rad/s²), shape (3,), fixed components.")

    @property
    def attitude(self) -> FloatArray:
        """The moving axes as columns (3, 3), fixed components."""
        return self._packed[15:].reshape(3, 3).copy()

    def __repr__(self) -> str:
        def f(v: FloatArray) -> str:
            return "[" + ", ".join(f"{x:.6g}" for x in v) + "]"

        extra = "" if np.array_equal(self._packed[15:], np.eye(3).ravel()) else ", attitude=..."
        return (
            f"MovingFrame(origin={f(self.origin)}, velocity={f(self.velocity)}, "
            f"acceleration={f(self.acceleration)}, angular_velocity={f(self.angular_velocity)}, "
            f"angular_acceleration={f(self.angular_acceleration)}{extra})"
        )

    # -- transformations ------------------------------------------------------------------
    def to_fixed(
        self,
        position: Any,
        velocity: Any = _core.DEFAULTS["MovingFrame.to_fixed"]["velocity"],
        acceleration: Any = _core.DEFAULTS["MovingFrame.to_fixed"]["acceleration"],
    ) -> FrameTransform:
        """The fixed-frame view of a particle given relative to this frame (eqs. 2.19–2.23).

        r' = R + r,  ṙ' = Ṙ + ṙ + ω × r,  r̈' = R̈ + r̈ + 2ω × ṙ + ω × (ω × r) + ω̇ × r.

        Parameters
        ----------
        position, velocity, acceleration:
            r, (dr/dt)_rot, (d²r/dt²)_rot in moving components, shape ``(..., 3)`` (broadcast
            together; scalars broadcast to vectors), m, m/s, m/s².

        Returns
        -------
        FrameTransform
            Fixed-frame position, velocity, acceleration ``(..., 3)`` and the terms
            ``"relative"``, ``"origin"``, ``"coriolis"``, ``"centripetal"``, ``"euler"``.
        """
        names = ("relative", "origin", "coriolis", "centripetal", "euler")
        return self._transform(_core.frame_to_fixed, names, position, velocity, acceleration)

    def to_moving(
        self,
        position: Any,
        velocity: Any = _core.DEFAULTS["MovingFrame.to_moving"]["velocity"],
        acceleration: Any = _core.DEFAULTS["MovingFrame.to_moving"]["acceleration"],
    ) -> FrameTransform:
        """The moving-frame view of a particle given in the fixed frame (inverse of
        :meth:`to_fixed`).

        r = r' − R,  ṙ = ṙ' − Ṙ − ω × r,  r̈ = r̈' − R̈ − 2ω × ṙ − ω × (ω × r) − ω̇ × r.

        Parameters
        ----------
        position, velocity, acceleration:
            r', ṙ', r̈' in fixed components, shape ``(..., 3)`` (broadcast together).

        Returns
        -------
        FrameTransform
            Moving-frame position, velocity, acceleration in moving components and the terms
            ``"inertial"``, ``"translational"``, ``"coriolis"``, ``"centrifugal"``, ``"euler"``.
        """
        names = ("inertial", "translational", "coriolis", "centrifugal", "euler")
        return self._transform(_core.frame_to_moving, names, position, velocity, acceleration)

    def _transform(
        self, core: Any, names: tuple[str, ...], position: Any, velocity: Any, acceleration: Any
    ) -> FrameTransform:
        """A particle's position, velocity and acceleration (broadcast together, each checked
        naming it) carried by the core's ``core`` transform; its terms named ``names``."""
        (r, v, a), lead = _broadcast(
            [(position, "position"), (velocity, "velocity"), (acceleration, "acceleration")]
        )
        out = core(self._packed, r, v, a)
        shape = lead + (3,)
        x, xd, xdd = (out[i].reshape(shape) for i in range(3))
        return FrameTransform(x, xd, xdd, {n: t.reshape(shape) for n, t in zip(names, out[3:])})

    def fictitious_forces(self, mass: Any, position: Any, velocity: Any) -> dict[str, FloatArray]:
        """The fictitious forces on a particle of ``mass`` (kg, > 0) at ``position`` (m) moving
        with ``velocity`` (m/s) relative to this frame (moving components, ``(..., 3)``).

        Returns
        -------
        dict
            ``"translational"`` −m R̈ (2.5), ``"coriolis"`` −2m ω × ṙ (2.26; 2.30 with its
            erratum), ``"centrifugal"`` −m ω × (ω × r), ``"euler"`` −m ω̇ × r; each ``(..., 3)``
            in newtons, moving components.
        """
        (r, v), lead = _broadcast([(position, "position"), (velocity, "velocity")])
        m = as_float_array(mass, "mass")
        try:
            m = np.broadcast_to(m, lead).reshape(-1)
        except ValueError:
            raise PoinsotError(f"mass: shape {m.shape} does not broadcast to {lead}") from None
        out = _core.frame_fictitious_forces(
            self._packed, np.ascontiguousarray(m, dtype=np.float64), r, v
        )
        names = ("translational", "coriolis", "centrifugal", "euler")
        return {n: x.reshape(lead + (3,)) for n, x in zip(names, out)}

    def at(self, t: float) -> MovingFrame:
        """The state at time ``t`` (s) of the steady motion that starts from this state at
        t = 0: origin at constant acceleration, axes turning about the fixed axis of ω with
        constant ω̇ (ω̇ must be parallel to ω)."""
        vecs, att = _core.frame_steady_at(self._packed, as_scalar(t, "t"))
        return MovingFrame(
            origin=vecs[0],
            velocity=vecs[1],
            acceleration=vecs[2],
            angular_velocity=vecs[3],
            angular_acceleration=vecs[4],
            attitude=att,
        )


FrameLike = Union[MovingFrame, Callable[[float], MovingFrame]]


class ParticleTrajectory:
    """A particle integrated in a moving frame (returned by :func:`simulate_particle`).

    Attributes
    ----------
    t:
        Sample times, shape (N,) (s).
    position, velocity:
        r and (dr/dt)_rot at ``t`` in moving components, shape (N, 3) (read-only views of
        ``states``).
    states:
        ``[x, y, z, vx, vy, vz]`` at ``t``, shape (N, 6).
    frame:
        The frame (a :class:`MovingFrame` taken as steady from t = 0, or a callable).
    evaluations:
        Evaluations of the right-hand side the integration took.
    """

    __slots__ = ("_t", "states", "frame", "evaluations")

    def __init__(self, t: Any, states: FloatArray, frame: Any, evaluations: int) -> None:
        # t: the sample times, or (duration, samples) for evenly spaced ones (made on demand).
        self._t = t
        self.states = states
        self.frame = frame
        self.evaluations = evaluations

    @property
    def t(self) -> FloatArray:
        """Sample times (s), shape (N,)."""
        if isinstance(self._t, tuple):
            dur, n = self._t
            self._t = _core.sample_times(0.0, dur, n)  # the times the core integrated to
        return self._t

    @property
    def position(self) -> FloatArray:
        """r (m), shape (N, 3), moving components."""
        return self.states[:, :3]

    @property
    def velocity(self) -> FloatArray:
        """(dr/dt)_rot (m/s), shape (N, 3), moving components."""
        return self.states[:, 3:]

    def __repr__(self) -> str:
        return (
            f"ParticleTrajectory({len(self.t)} samples over [{self.t[0]:g}, {self.t[-1]:g}] s, "
            f"{self.evaluations} evaluations)"
        )

    def frame_at(self, t: float) -> MovingFrame:
        """The frame's state at time ``t``."""
        if isinstance(self.frame, MovingFrame):
            return self.frame.at(t)
        return self.frame(t)

    def to_fixed(self) -> tuple[FloatArray, FloatArray]:
        """The trajectory seen from the fixed frame: positions and velocities (N, 3)."""
        pos = np.empty_like(self.position)
        vel = np.empty_like(self.velocity)
        for i, t in enumerate(self.t):
            out = self.frame_at(float(t)).to_fixed(self.position[i], self.velocity[i])
            pos[i], vel[i] = out.position, out.velocity
        return pos, vel


def _frame_callable(frame: Callable[[float], MovingFrame]) -> Callable[[float], Any]:
    def call(t: float) -> Any:
        f = frame(t)
        if not isinstance(f, MovingFrame):
            raise PoinsotError(
                f"frame: the callable must return a MovingFrame, got {type(f).__name__}"
            )
        return f._packed.tolist()

    return call


def _force_callable(force: Callable[..., Any]) -> Callable[..., tuple[float, float, float]]:
    def call(
        t: float, x: float, y: float, z: float, vx: float, vy: float, vz: float
    ) -> tuple[float, float, float]:
        f = returned(
            force(t, np.array((x, y, z)), np.array((vx, vy, vz))), "force", "3 real numbers"
        )
        if f.shape != (3,):
            raise PoinsotError(f"force: the callable must return shape (3,), got {f.shape}")
        if (
            np.isnan(f).any()
            and math.isfinite(t)
            and all(map(math.isfinite, (x, y, z, vx, vy, vz)))
        ):
            raise PoinsotError(
                f"force: the callable returned {f.tolist()} at t = {t} s: a force must be finite"
            )
        return float(f[0]), float(f[1]), float(f[2])

    return call


def simulate_particle(
    frame: FrameLike,
    position: Any,
    velocity: Any,
    duration: float,
    *,
    mass: float = _PARTICLE["mass"],
    force: Any = None,
    samples: int = _PARTICLE["samples"],
    t_eval: Any = None,
    rtol: float = _PARTICLE["rtol"],
    atol: float = _PARTICLE["atol"],
    max_steps: int = _PARTICLE["max_steps"],
    stiffness: float = _PARTICLE["stiffness"],
) -> ParticleTrajectory:
    """Integrate a particle relative to a moving frame, with every fictitious force.

    m (d²r/dt²)_rot = F − m R̈ − 2m ω × ṙ − m ω × (ω × r) − m ω̇ × r   (eqs. 2.5, 2.21, 2.26)

    integrated by the adaptive DOP853 method of the core to the tolerances given.

    Parameters
    ----------
    frame:
        A :class:`MovingFrame`, taken as the state at t = 0 of a steady motion (origin at
        constant acceleration, axes about a fixed axis with constant ω̇ ∥ ω), or a callable
        ``t -> MovingFrame`` giving the frame as a function of time (it must be consistent:
        Ṙ = dR/dt, and the attitude must turn with ω).
    position, velocity:
        Initial r (m) and (dr/dt)_rot (m/s), moving components, shape (3,).
    duration:
        Integrate over [0, duration] (s, > 0).
    mass:
        Mass (kg, > 0).
    force:
        The true force F in moving components (N): None (free particle), a constant (3,)
        vector (integrated entirely in Rust: fast), or a callable ``force(t, r, v) -> (3,)``.
    stiffness:
        k (N/m, ≥ 0) of an isotropic spring −k r anchored at the frame's origin, added to
        ``force`` and integrated in Rust (default 0: no spring); see :class:`SpringParticle`.
    samples:
        Number of evenly spaced output times, both ends included (≥ 2); ignored if ``t_eval``
        is given.
    t_eval:
        Explicit output times in [0, duration], increasing.
    rtol, atol:
        Relative and absolute tolerances (> 0; rtol ≥ 2.2e-14).
    max_steps:
        Maximum number of steps before :class:`poinsot.IntegrationError`.

    Returns
    -------
    ParticleTrajectory
        ``t`` (N,), ``position`` and ``velocity`` (N, 3) in the moving frame; ``to_fixed()``
        gives the fixed-frame view.
    """
    dur = _fast_scalar(duration, "duration")
    if not dur > 0:
        raise PoinsotError(f"duration: must be > 0, got {dur}")
    # Finiteness of the vectors is checked by the core (naming the argument).
    r0 = _fast_vector(position, "position")
    v0 = _fast_vector(velocity, "velocity")
    if t_eval is None:
        n = (
            samples
            if type(samples) is int and 2 <= samples <= 100_000
            else as_count(samples, "samples", 2)
        )
        times = None
    else:
        times = as_float_array(t_eval, "t_eval")
        if times.ndim != 1:
            raise PoinsotError(f"t_eval: must have shape (N,), got {times.shape}")
        times = np.ascontiguousarray(times)
        if times.size == 0 or np.any(np.diff(times) < 0) or times[0] < 0 or times[-1] > dur:
            raise PoinsotError("t_eval: must be non-empty, increasing and inside [0, duration]")
        n = times.size
    if force is None:
        f_const, f_fn = _ZERO3, None
    elif callable(force):
        f_const, f_fn = _ZERO3, _force_callable(force)
    else:
        f_const, f_fn = _fast_vector(force, "force"), None
    if isinstance(frame, MovingFrame):
        packed, frame_fn = frame._packed, None
    elif callable(frame):
        packed, frame_fn = _IDENTITY_FRAME, _frame_callable(frame)
    else:
        raise PoinsotError(
            f"frame: must be a MovingFrame or a callable t -> MovingFrame, got {type(frame).__name__}"
        )
    steps = (
        max_steps
        if type(max_steps) is int and 1 <= max_steps <= 2**62
        else as_count(max_steps, "max_steps", 1)
    )
    # Plain floats go straight to the core, which checks their ranges and names them.
    m = mass if type(mass) is float else _fast_scalar(mass, "mass")
    rt = rtol if type(rtol) is float else _fast_scalar(rtol, "rtol")
    at = atol if type(atol) is float else _fast_scalar(atol, "atol")
    states, evaluations = _core.frame_simulate_particle(
        packed,
        frame_fn,
        m,
        r0,
        v0,
        dur,
        n,
        times,
        f_const,
        f_fn,
        rt,
        at,
        steps,
        stiffness if type(stiffness) is float else _fast_scalar(stiffness, "stiffness"),
    )
    return ParticleTrajectory(times if times is not None else (dur, n), states, frame, evaluations)


class SpringParticle:
    """A particle of ``mass`` m (kg, > 0) on an isotropic linear spring of ``stiffness`` k (N/m,
    ≥ 0; 0 is a free particle), anchored at the origin shared by the fixed frame and a frame
    turning about it (R = 0).

    The spring force F = −k r holds in either frame's components and its potential ½ k |r|² is the
    same function of position in both. In the fixed frame the orbit is an ellipse centred on the
    origin at the angular frequency √(k/m); seen from a turntable it becomes a rosette, and the
    Jacobi integral J = ½ m |ṙ|² + ½ k |r|² − ½ m |ω × r|² (the centrifugal potential, eq. 2.28)
    is conserved while the frame turns uniformly. The rules (validation, the force, the
    integrals) are the core's (``poinsot::frames::SpringParticle``), the same as the browser
    lab's.

    Examples
    --------
    >>> import poinsot as ps
    >>> p = ps.SpringParticle(mass=2.0, stiffness=8.0)     # orbits at √(k/m) = 2 rad/s
    >>> p.force([0.5, 0.0, 0.0])
    array([-4., -0., -0.])
    >>> table = ps.MovingFrame(angular_velocity=[0, 0, 1.0])
    >>> run = p.simulate(table, [1.0, 0, 0], [0, 0, 0], 3.0, samples=4)
    >>> run.position.shape
    (4, 3)
    """

    __slots__ = ("_core",)

    def __init__(self, mass: float, stiffness: float) -> None:
        self._core = _core.SpringParticleCore(
            _fast_scalar(mass, "mass"), _fast_scalar(stiffness, "stiffness")
        )

    def __reduce__(self) -> tuple[Any, ...]:  # pickling and copying: the constructor again
        return (SpringParticle, (self.mass, self.stiffness))

    mass: float = core_property("mass", "m (kg).")
    stiffness: float = core_property("stiffness", "k (N/m).")

    def force(self, position: Any) -> FloatArray:
        """F = −k r (N) at ``position`` r (m), shape (..., 3), in the components of ``position``."""
        rows, lead = as_vectors(position, "position")
        return self._core.force(rows).reshape(lead + (3,))

    def acceleration(self, position: Any) -> FloatArray:
        """F / m = −(k/m) r (m/s²) at ``position`` (m), shape (..., 3): in the fixed frame the
        particle's whole acceleration (eq. 2.25)."""
        rows, lead = as_vectors(position, "position")
        return self._core.acceleration(rows).reshape(lead + (3,))

    def potential(self, position: Any) -> Any:
        """U = ½ k |r|² (J) at ``position`` (m), shape (..., 3) → (...)."""
        rows, lead = as_vectors(position, "position")
        return shaped(np.asarray(self._core.potential(rows)), lead)

    def energy(self, position: Any, velocity: Any) -> Any:
        """E = ½ m |ṙ'|² + ½ k |r'|² (J) from the fixed-frame ``position`` r' (m) and ``velocity``
        ṙ' (m/s), shapes (..., 3) → (...). Conserved along any motion (eq. 2.25)."""
        (r, v), lead = _pairs(position, velocity)
        return shaped(np.asarray(self._core.energy(r, v)), lead)

    def jacobi_integral(self, frame: MovingFrame, position: Any, velocity: Any) -> Any:
        """J = ½ m |(dr/dt)_rot|² + ½ k |r|² − ½ m |ω × r|² (J) in the rotating ``frame`` (a
        :class:`MovingFrame` about the spring's anchor), from the relative ``position`` (m) and
        ``velocity`` (m/s) in moving components, shapes (..., 3) → (...). Conserved while the
        frame turns uniformly (ω̇ = 0); with ω = 0 it is :meth:`energy`."""
        if not isinstance(frame, MovingFrame):
            raise PoinsotError(f"frame: must be a MovingFrame, got {type(frame).__name__}")
        (r, v), lead = _pairs(position, velocity)
        return shaped(np.asarray(self._core.jacobi_integral(frame._packed, r, v)), lead)

    def simulate(
        self,
        frame: FrameLike,
        position: Any,
        velocity: Any,
        duration: float,
        *,
        force: Any = None,
        samples: int = _SPRING["samples"],
        t_eval: Any = None,
        rtol: float = _SPRING["rtol"],
        atol: float = _SPRING["atol"],
        max_steps: int = _SPRING["max_steps"],
    ) -> ParticleTrajectory:
        """Integrate the particle relative to ``frame`` with every fictitious force and the
        spring force, in the core: :func:`simulate_particle` with this ``mass`` and
        ``stiffness`` (``force`` adds a further true force; the other arguments as there)."""
        return simulate_particle(
            frame,
            position,
            velocity,
            duration,
            mass=self.mass,
            stiffness=self.stiffness,
            force=force,
            samples=samples,
            t_eval=t_eval,
            rtol=rtol,
            atol=atol,
            max_steps=max_steps,
        )

    def __repr__(self) -> str:
        return f"SpringParticle(mass={self.mass!r}, stiffness={self.stiffness!r})"


def _pairs(position: Any, velocity: Any) -> tuple[tuple[FloatArray, FloatArray], tuple[int, ...]]:
    """Positions and velocities (..., 3) broadcast together, as (N, 3) rows and the lead shape."""
    r = as_float_array(position, "position")
    v = as_float_array(velocity, "velocity")
    for arr, name in ((r, "position"), (v, "velocity")):
        if arr.ndim == 0 or arr.shape[-1] != 3:
            raise PoinsotError(f"{name}: must have shape (..., 3), got {arr.shape}")
    try:
        r, v = np.broadcast_arrays(r, v)
    except ValueError as exc:
        raise PoinsotError(
            f"velocity: shape {v.shape} does not broadcast with position's {r.shape}"
        ) from exc
    lead = r.shape[:-1]
    return (np.ascontiguousarray(r.reshape(-1, 3)), np.ascontiguousarray(v.reshape(-1, 3))), lead
