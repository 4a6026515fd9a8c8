"""The public surface of poinsot, for the fuzz suite (``test_fuzz.py``, ``make fuzz``).

Every name of ``poinsot.__all__`` and ``poinsot.special.__all__`` is discovered here, so that a
function is fuzzed the day it is added: a callable whose parameters have no valid example (and no
default) makes ``test_every_public_name_is_fuzzed`` fail until one is added to ``VALID``.

A *call site* is a callable with a dict of valid arguments; the fuzzer replaces one (or several)
of them by adversarial values and checks poinsot's contract (``check_outcome``):

* it raises a :class:`poinsot.PoinsotError` (or ``TypeError`` for a wrong type) whose message
  starts with the name of one of the call's own arguments, ``"samples: ..."``; or
* it returns, and every number in what it returns is finite (but for the documented infinities
  of ``DOCUMENTED_INF``);
* never ``PanicException``, ``OverflowError``, ``IndexError`` or any other exception, never NaN,
  never a hang (``DEADLINE_S`` per call, enforced with SIGALRM, which the core's long loops
  obey).
"""

from __future__ import annotations

import dataclasses
import inspect
import math
import re
import signal
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

import numpy as np
import poinsot as ps
from poinsot import special

#: Seconds a single call may take (the slowest valid calls take ~0.2 s).
DEADLINE_S = 20.0


class Deadline(BaseException):
    """Raised by the SIGALRM handler when a call overruns :data:`DEADLINE_S`."""


@contextmanager
def deadline(seconds: float = DEADLINE_S) -> Iterator[None]:
    """Raise :class:`Deadline` in the main thread after ``seconds`` (the core's long loops run
    Python's signal handlers at least every 20 ms, so a hang inside Rust is caught too)."""

    def handler(signum: int, frame: Any) -> None:
        raise Deadline(f"call took more than {seconds} s")

    old = signal.signal(signal.SIGALRM, handler)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


# -- valid arguments -----------------------------------------------------------------------

R0 = ps.euler_to_matrix([0.1, 0.2, 0.3])
FRAME = ps.MovingFrame(angular_velocity=[0.0, 0.0, 1.0], velocity=[1.0, 0.0, 0.0])
CUBE_V = np.array(
    [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], float
)
CUBE_F = np.array(
    [
        [0, 2, 1],
        [0, 3, 2],
        [4, 5, 6],
        [4, 6, 7],
        [0, 1, 5],
        [0, 5, 4],
        [1, 2, 6],
        [1, 6, 5],
        [2, 3, 7],
        [2, 7, 6],
        [3, 0, 4],
        [3, 4, 7],
    ]
)

_TOP = ps.HeavyTop(1.0, 0.5, 1.0, 0.5, psi_dot=6.0)

_POLE_T = np.arange(0.0, 30 * 365.25, 20.0) * 86400.0
_POLE_X = 1e-6 * np.cos(2 * np.pi * _POLE_T / (433 * 86400.0)) + 4e-7 * np.cos(2e-7 * _POLE_T)
_POLE_Y = -1e-6 * np.sin(2 * np.pi * _POLE_T / (433 * 86400.0)) + 1e-8 * np.sin(_POLE_T)

#: Valid example arguments by parameter name; ``VALID_FOR`` overrides by "Qualified.name".
VALID: dict[str, Any] = {
    "angles": [0.1, 0.2, 0.3],
    "rates": [0.5, 0.2, 3.0],
    "omega_body": [0.1, 0.2, 0.3],
    "seq": "zxz",
    "intrinsic": True,
    "degrees": False,
    "frame": "body",
    "R": R0,
    "axis": [0.0, 0.0, 1.0],
    "angle": 0.5,
    "tol": 1e-9,
    "p": [1.0, 0.0, 0.0, 0.0],
    "q": [0.9, 0.1, 0.3, 0.3],
    "normalize": True,
    "v": [1.0, 2.0, 3.0],
    "t": 1.5,
    "s": 0.5,
    "x": [1.0, 2.0, 3.0],
    "mass": 2.0,
    "inertia": np.diag([1.0, 2.0, 2.5]),
    "center_of_mass": [0.0, 0.0, 0.1],
    "about": None,
    "masses": [1.0, 2.0, 3.0],
    "positions": [[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]],
    "radius": 0.5,
    "height": 2.0,
    "sides": [1.0, 2.0, 3.0],
    "semi_axes": [1.0, 2.0, 3.0],
    "length": 1.5,
    "density": 1000.0,
    "bounds": [(-0.5, 0.5), (-0.5, 0.5), (-0.5, 0.5)],
    "rtol": 1e-6,
    "atol": 1e-12,
    "max_evals": 100_000,
    "vertices": CUBE_V,
    "faces": CUBE_F,
    "merge_vertices": False,
    "point": [0.1, 0.2, 0.3],
    "omega": [1.0, 0.1, 1.0],
    "offset": [1.0, 2.0, 3.0],
    "rotation": R0,
    "moments": [1.0, 2.0, 3.0],
    "origin": [1.0, 0.0, 0.0],
    "velocity": [0.0, 1.0, 0.0],
    "acceleration": [0.0, 0.0, 0.1],
    "angular_velocity": [0.0, 0.0, 1.0],
    "angular_acceleration": [0.0, 0.0, 0.1],
    "attitude": None,
    "position": [1.0, 0.0, 0.0],
    "duration": 1.0,
    "force": None,
    "samples": 11,
    "t_eval": None,
    "max_steps": 1_000_000,
    "rotation_rate": 7.2921150e-5,
    "g": 9.80665,
    "latitude": 0.7,
    "velocity_enu": [10.0, 0.0, 0.0],
    "gravity": "uniform",
    "centrifugal": True,
    "speed": 100.0,
    "elevation": 0.7,
    "azimuth": 0.3,
    "amplitude": 1.0,
    "progress": None,
    "parcels": 4,
    "pull": 1e-3,
    "friction": 1e-5,
    "torque": None,
    "mgl": 1.0,
    "mean_motion": 1e-3,
    "body": [1.0, 2.0, 3.0],
    "omega0": [1.0, 0.1, 1.0],
    "attitude0": None,
    "method": "auto",
    "dt": None,
    "I1": 1.0,
    "I3": 0.5,
    "energy": 2.0,
    "angular_momentum": 2.5,
    "spin": 1.0,
    "theta": 0.5,
    "theta_dot": 0.0,
    "phi_dot": 0.0,
    "psi_dot": 6.0,
    "phi": 0.0,
    "psi": 0.0,
    "omega3": 6.0,
    "p_phi": 3.0,
    "p_psi": 3.0,
    "theta0": 0.5,
    "u": [0.1, 0.5, 2.0],
    "m": 0.5,
    "n": 0.3,
    "bytes": 4 * 2**30,
    "dynamical_flattening": 0.003273795,
    "obliquity": 0.409,
    "k2": 0.30,
    "ks": 0.938,
}

VALID_FOR: dict[str, dict[str, Any]] = {
    # The real pole: 30 years every 20 days of a 433-day and an annual circle (issue 25).
    "fit_wobble": {"t": _POLE_T, "x": _POLE_X, "y": _POLE_Y, "chandler_period": None},
    "polar_motion": {"source": "shipped"},
    # The sweeps: the model's own keywords (passed as **keywords) and small grids.
    "sweep.heavy_top": {
        "samples": None,
        "I1": 1.0,
        "I3": 0.5,
        "mgl": 1.0,
        "theta": [0.3, 0.6],
        "psi_dot": [4.0, 8.0],
    },
    "sweep.free_body": {
        "samples": None,
        "moments": [1.0, 2.0, 3.0],
        "omega_magnitude": 1.0,
        "omega_polar": [0.5, 1.5],
        "omega_azimuth": [0.2, 1.2],
    },
    "sweep.simulate": {
        "samples": None,
        "moments": [1.0, 2.0, 3.0],
        "omega0": [[1.0, 0.1, 1.0], [0.0, 0.5, 1.0]],
        "duration": 0.5,
        "dt": 1e-2,
    },
    "sweep.drop": {
        "height": [10.0, 100.0],
        "latitude": [0.3, 0.8],
        "samples": None,
        "rotation": True,
    },
    "sweep.projectile": {
        "samples": None,
        "rotation": True,
        "speed": [50.0, 100.0],
        "elevation": 0.5,
        "azimuth": 0.3,
        "latitude": 0.7,
    },
    "sweep.uniform": {"low": 0.5, "high": 2.0},
    "sweep.log_uniform": {"low": 0.5, "high": 2.0},
    "screw_axis": {"t": [1.0, 2.0, 3.0]},
    "Screw.__init__": {"slide": 0.1},
    "RigidBody.rotated": {"rotation": R0},
    "RigidBody.load_mesh": {"path": "__CUBE_STL__"},
    "RigidBody.from_density": {"density": 1000.0},
    "RigidBody.combine": {
        "bodies": [
            ps.RigidBody.solid_sphere(1.0, 0.5),
            ps.RigidBody.cuboid(1.0, (1, 1, 1)).translated([1, 0, 0]),
        ]
    },
    "RigidBody.__init__": {"inertia": np.diag([1.0, 2.0, 2.5])},
    "RigidBody.from_trimesh": {"mesh": "__TRIMESH_CUBE__"},
    "MovingFrame.at": {"t": 0.5},
    "ParticleTrajectory.frame_at": {"t": 0.5},
    "simulate_particle": {
        "frame": FRAME,
        "position": [1.0, 0.0, 0.0],
        "velocity": [0.0, 1.0, 0.0],
        "duration": 1.0,
    },
    "MovingFrame.fictitious_forces": {"mass": 2.0},
    "SpringParticle.__init__": {"mass": 2.0, "stiffness": 3.0},
    "SpringParticle.jacobi_integral": {"frame": FRAME},
    "SpringParticle.simulate": {
        "frame": FRAME,
        "position": [1.0, 0.0, 0.0],
        "velocity": [0.0, 1.0, 0.0],
        "duration": 1.0,
    },
    "Earth.projectile": {"height": 0.0, "rotation": True},
    "Earth.drop": {"height": 100.0, "rotation": True},
    "Earth.foucault": {"duration": 30.0, "samples": 11, "max_steps": 100_000, "progress": False},
    "Gyrocompass.speed_error": {"speed": 10.0, "course": 0.3},
    "Gyrocompass.speed_error_small_angle": {"speed": 10.0, "course": 0.3},
    "Gyrocompass.linear_solution": {"t": [0.0, 60.0, 120.0], "heading0": 0.1},
    "Gyrocompass.simulate": {
        "duration": 5.0,
        "heading0": 0.1,
        "samples": 5,
        "max_steps": 100_000,
    },
    "Earth.inertial_oscillation": {"velocity": (10.0, 0.0), "duration": None},
    "Earth.flow_into_low": {"radius": 5e5, "duration": 3600.0, "samples": 11},
    "Earth.jacobi_integral": {"position": [1.0, 2.0, 3.0], "velocity": [0.5, 0.0, 0.1]},
    "Earth.__init__": {"radius": 6.371e6},
    "Earth.solar_day": {"radius": 6.371e6},
    "BodyTorque.__init__": {"torque": [0.0, 0.0, 1.0]},
    "SpaceTorque.__init__": {"torque": [0.0, 0.0, 1.0]},
    "simulate": {"duration": 2.0, "samples": 11},
    "simulate_batch": {
        "moments": [[1.0, 2.0, 3.0], [2.0, 2.0, 3.0]],
        "omega0": [[1.0, 0.1, 1.0], [0.0, 0.5, 1.0]],
        "duration": 1.0,
        "dt": 1e-3,
    },
    "free_body_states": {
        "moments": [[1.0, 2.0, 3.0], [2.0, 2.0, 3.0]],
        "omega0": [[1.0, 0.1, 1.0], [0.0, 0.5, 1.0]],
        "t": [0.0, 1.0],
    },
    "FreeSymmetricTop.__init__": {"I1": 1.0, "I3": 2.0, "omega0": [0.3, 0.0, 1.0]},
    "FreeSymmetricTop.omega3_squared_from": {
        "I1": 1.0,
        "I3": 2.0,
        "energy": 1.5,
        "angular_momentum": 2.0,
    },
    "FreeSymmetricTop.amplitude_squared_from": {
        "I1": 1.0,
        "I3": 2.0,
        "energy": 1.5,
        "angular_momentum": 2.0,
    },
    "HeavyTop.from_body": {"body": ps.RigidBody.thin_disk(0.2, 0.05), "pivot_distance": 0.1},
    "HeavyTop.from_constants": {"p_phi": _TOP.p_phi, "p_psi": _TOP.p_psi, "energy": _TOP.energy},
    "HeavyTop.effective_potential": {"theta": [0.3, 0.5, 1.0]},
    "HeavyTop.effective_potential_derivative": {"theta": [0.3, 0.5, 1.0]},
    "HeavyTop.euler_angles": {"t": [0.0, 0.5, 3.0]},
    "RigidEarth.averaged_pole": {"t": [0.0, 3.15e7, 6e8]},
    "HeavyTop.lagrangian": {"theta": 0.5},
    "FreeRigidBody.contact_point": {"frame": "space"},
    "FreeRigidBody.contact_polhode": {"samples": 31},
    "FreeRigidBody.polhode": {"samples": 31},
    "axis_stability": {"moments": [1.0, 2.0, 3.0]},
    "classify": {"moments": [1.0, 2.0, 3.0], "rtol": 1e-9},
    "check_inertia": {"inertia": np.diag([1.0, 2.0, 2.5])},
    "jacobi": {"u": [0.1, 0.5, 2.0], "m": 0.5},
    "ellippiinc": {"phi": 0.5, "n": 0.3, "m": 0.5},
    "ellipf": {"phi": 0.5},
    "ellipeinc": {"phi": 0.5},
}

#: Result types that poinsot constructs and users only read: their constructors are not part
#: of the input surface (their methods and fields are fuzzed through ``INSTANCES``).
RESULT_TYPES = {
    "IntegrationErrorEstimate",
    "FrameTransform",
    "ParticleTrajectory",
    "Fall",
    "Flight",
    "FoucaultRun",
    "InertialOscillation",
    "LowFlow",
    "Trajectory",
    "AxisStability",
    "SteadyPrecession",
    "PolarMotion",
    "WobbleFit",
    "WobbleTerm",
    "CarriedTrajectory",
    "CompassRun",
    "PoleRun",
    "PoleFit",
    "AveragedPole",
}

#: Valid instances whose methods and properties are fuzzed, by class name.
INSTANCES: dict[str, Callable[[], Any]] = {
    "Screw": lambda: ps.screw_axis(R0, [1.0, 2.0, 3.0]),
    "RigidBody": lambda: ps.RigidBody.cuboid(2.0, (1.0, 2.0, 3.0)),
    "MovingFrame": lambda: FRAME,
    "ParticleTrajectory": lambda: ps.simulate_particle(
        FRAME, [1.0, 0, 0], [0, 1.0, 0], 1.0, samples=11
    ),
    "Earth": lambda: ps.Earth(),
    "RigidEarth": lambda: ps.RigidEarth(),
    "PolarMotion": lambda: ps.polar_motion("shipped"),
    "WobbleTerm": lambda: ps.fit_wobble(_POLE_T, _POLE_X, _POLE_Y).chandler,
    "Trajectory": lambda: ps.simulate([1.0, 2.0, 3.0], [1.0, 0.1, 1.0], 1.0, samples=11),
    "FreeSymmetricTop": lambda: ps.FreeSymmetricTop(1.0, 2.0, [0.3, 0.0, 1.0]),
    "FreeRigidBody": lambda: ps.FreeRigidBody([1.0, 2.0, 3.0], [1.0, 0.1, 1.0]),
    "HeavyTop": lambda: ps.HeavyTop(1.0, 0.5, 1.0, 0.5, psi_dot=6.0),
    "SpringParticle": lambda: ps.SpringParticle(2.0, 3.0),
    "Place": lambda: ps.Place(0.7),
    "Gyrocompass": lambda: ps.Gyrocompass(0.7),
    "CarriedTrajectory": lambda: ps.simulate(
        [1.0, 1.0, 1.5], [0.0, 0.0, 1.0], 1.0, carried_by=ps.Place(0.7), samples=5
    ),
    "CompassRun": lambda: ps.Gyrocompass(0.7).simulate(5.0, 0.1, samples=5),
    # 19 Julian years: PoleRun.fit needs one node period (18.6 years)
    "PoleRun": lambda: ps.RigidEarth().simulate(19 * 365.25 * 86400.0, samples=50),
}

#: Numbers that may be infinite by documented design, as (qualified name, field).
DOCUMENTED_INF = {
    ("screw_axis", "pitch"),  # a pure translation has infinite pitch (the contract)
    ("Screw", "pitch"),
    ("Earth.inertial_period", ""),  # no inertial oscillation at the equator
    ("Earth.inertial_oscillation", "period"),
    ("Earth.inertial_oscillation", "measured_period"),  # a velocity that does not turn
    ("Earth.foucault", "full_turn_period"),  # a swing plane that does not turn
    ("Earth.foucault", "expected_full_turn_period"),  # ω sin λ = 0 at the equator
    ("FreeRigidBody", "period"),  # on the separatrix the motion is asymptotic
    ("FreeRigidBody", "flip_interval"),
    ("FreeRigidBody", "max_time"),  # never 2^42 rad within the doubles (omega0 ~ 1e-300)
    ("FreeSymmetricTop", "max_time"),
    ("HeavyTop", "nutation_period"),  # steady precession and the sleeping top
    ("HeavyTop", "precession_period"),  # an axis that does not turn (sleeping, no gravity)
    ("HeavyTop", "cubic_roots"),  # u3 = inf for m g l = 0: the cubic has no third root
    ("axis_stability", "rate"),
    ("sweep.heavy_top", "nutation_period"),  # as HeavyTop's
    ("sweep.free_body", "period"),  # as FreeRigidBody's
    ("sweep.free_body", "flip_interval"),
    ("sweep.free_body", "axis_rate"),  # as axis_stability's rate
}


#: Parameters the fuzzer leaves at their defaults, by name: a sweep's ``client`` (a Dask
#: cluster: test_sweep_cluster.py) and ``to_zarr`` (a path it would write to: test_sweep.py).
NOT_FUZZED = {"client", "to_zarr"}


def qualname(owner: str | None, name: str) -> str:
    return name if owner is None else f"{owner}.{name}"


@dataclasses.dataclass
class Site:
    """One callable of the surface, with valid arguments for each of its parameters."""

    qualname: str
    func: Callable[..., Any]
    params: list[inspect.Parameter]
    valid: dict[str, Any]
    missing: list[str]

    @property
    def names(self) -> set[str]:
        return {p.name for p in self.params}

    def call(self, args: dict[str, Any]) -> Any:
        pos = [args[p.name] for p in self.params if p.kind == p.POSITIONAL_ONLY]
        kw = {
            p.name: args[p.name]
            for p in self.params
            if p.kind != p.POSITIONAL_ONLY and p.name in args
        }
        return self.func(*pos, **kw)


def _resolve(value: Any, tmp: Any) -> Any:
    if isinstance(value, str) and value == "__CUBE_STL__":
        import trimesh

        path = tmp / "cube.stl"
        if not path.exists():
            trimesh.Trimesh(CUBE_V, CUBE_F).export(path)
        return str(path)
    if isinstance(value, str) and value == "__TRIMESH_CUBE__":
        import trimesh

        return trimesh.Trimesh(CUBE_V, CUBE_F)
    return value


def _site(owner: str | None, name: str, func: Callable[..., Any], tmp: Any) -> Site:
    q = qualname(owner, name)
    sig = inspect.signature(func)
    params = [
        p
        for p in sig.parameters.values()
        if p.name not in ("self", "cls")
        and p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)
        and p.name not in NOT_FUZZED
    ]
    valid: dict[str, Any] = {}
    missing: list[str] = []
    override = VALID_FOR.get(q, {})
    if any(p.kind == p.VAR_KEYWORD for p in sig.parameters.values()):
        # A function taking **keywords (a sweep: the model's own keywords) gets those of its
        # valid example as keyword parameters of their own, fuzzed like the others.
        named = {p.name for p in params}
        params += [
            inspect.Parameter(k, inspect.Parameter.KEYWORD_ONLY) for k in override if k not in named
        ]
    for p in params:
        if p.name in override:
            valid[p.name] = _resolve(override[p.name], tmp)
        elif p.name in VALID:
            valid[p.name] = _resolve(VALID[p.name], tmp)
        elif p.default is not p.empty:
            valid[p.name] = p.default
        else:
            missing.append(p.name)
    return Site(q, func, params, valid, missing)


def public_api() -> list[tuple[str, Any, str]]:
    """(name, object, module label) for every public name of poinsot, poinsot.special and
    poinsot.sweep."""
    out = [(n, getattr(ps, n), "poinsot") for n in ps.__all__]
    out += [(n, getattr(special, n), "poinsot.special") for n in special.__all__]
    out += [(n, getattr(ps.sweep, n), "poinsot.sweep") for n in ps.sweep.__all__]
    return out


def sites(tmp: Any) -> list[Site]:
    """Every call site: functions, constructors, class/static methods, and the methods of the
    valid instances in :data:`INSTANCES` (bound)."""
    out: list[Site] = []
    for name, obj, _module in public_api():
        if inspect.isclass(obj):
            if issubclass(obj, BaseException) or issubclass(obj, Warning):
                continue
            if name not in RESULT_TYPES:
                out.append(_site(name, "__init__", obj, tmp))
            instance = INSTANCES[name]() if name in INSTANCES else None
            for attr, raw in vars(obj).items():
                if attr.startswith("_"):
                    continue
                if isinstance(raw, (classmethod, staticmethod)):
                    out.append(_site(name, attr, getattr(obj, attr), tmp))
                elif inspect.isfunction(raw) and instance is not None:
                    out.append(_site(name, attr, getattr(instance, attr), tmp))
        elif callable(obj):
            owner = "sweep" if _module == "poinsot.sweep" else None
            out.append(_site(owner, name, obj, tmp))
    return out


def properties(cls_name: str) -> list[str]:
    """The public properties of a class (read on every instance the fuzzer makes)."""
    cls = getattr(ps, cls_name)
    return [a for a, v in vars(cls).items() if not a.startswith("_") and isinstance(v, property)]


# -- adversarial values ----------------------------------------------------------------------

SPECIAL_FLOATS = [
    math.nan,
    math.inf,
    -math.inf,
    1e308,
    -1e308,
    5e-324,
    -5e-324,
    0.0,
    -1.0,
    1e-300,
    1e300,
    1e154,
    1e-160,
]


def _nan_torque(t: float, w: Any, q: Any) -> Any:
    return [math.nan, 0.0, 0.0]


class UserCallbackError(Exception):
    """Raised by the fuzzer's failing callbacks: poinsot must let it propagate unchanged."""


def _raising(*args: Any) -> Any:
    raise UserCallbackError("user callback failed")


def _wrong_shape(*args: Any) -> Any:
    return [1.0, 2.0]


def adversarial(name: str, valid: Any) -> list[Any]:
    """Bad or extreme values for a parameter called ``name`` whose valid example is ``valid``."""
    vals: list[Any] = list(SPECIAL_FLOATS)
    vals += [
        None,
        "no",
        "",
        True,
        1 + 5j,
        10**400,
        -(2**31),
        2**63,
        2**64 + 1,
        2.5,
        -1,
        0,
        [],
        [[1.0, 2.0], [3.0]],
        np.ones((3, 3)),
        np.ones(7),
        np.array([1 + 5j, 2, 3]),
        object(),
        {"a": 1},
        np.array(["a", "b", "c"]),
        np.array([True, False, True]),
    ]
    arr = None
    if valid is not None and not isinstance(valid, (str, bool, dict)) and not callable(valid):
        try:
            arr = np.asarray(valid, dtype=float)
        except (TypeError, ValueError):
            arr = None
    if arr is not None and arr.ndim >= 1 and arr.size:
        for x in (math.nan, math.inf, 1e308, -1e308, 5e-324, 0.0, 1e-300, 1e300):
            vals.append(np.full(arr.shape, x))
            one = arr.copy().ravel()
            one[0] = x
            vals.append(one.reshape(arr.shape))
        vals.append(arr.astype(np.complex128))
        vals.append(arr.ravel().tolist() + [1.0])
        vals.append(np.zeros((0,) + arr.shape[1:]))
    if name in ("torque",):
        vals += [
            ps.BodyTorque([1e308, 0, 0]),
            ps.SpaceTorque([1e308] * 3),
            ps.GravityTorque(mgl=1e308),
            ps.GravityGradientTorque(1e154),
            _nan_torque,
            _raising,
            _wrong_shape,
        ]
    if name in ("force", "density", "progress", "frame"):
        vals += [_raising, _wrong_shape, lambda *a: math.nan, lambda *a: "x"]
    if name == "path":
        # File names: a NUL byte, names that are not UTF-8 (bytes, and str with surrogate
        # escapes), a directory (issue 21, item 11).
        vals += ["mesh\x00.stl", b"no\xffsuch.stl", "no\udcffsuch.stl", "/"]
    return vals


# -- the contract ------------------------------------------------------------------------------

ALLOWED_TYPES: tuple[type[BaseException], ...] = (ps.PoinsotError, TypeError)
#: Exceptions that pass through as they are: the user's own callback failing.
PASS_THROUGH: tuple[type[BaseException], ...] = (UserCallbackError,)


def _numbers(value: Any, path: str, depth: int = 0) -> Iterator[tuple[str, float]]:
    """Every float in a result: scalars, arrays, tuples, dicts, dataclasses, simple objects."""
    if depth > 3:
        return
    if isinstance(value, (bool, str, bytes)) or value is None:
        return
    if isinstance(value, (int, np.integer)):
        return  # integers are always finite
    if isinstance(value, (float, np.floating)):
        yield path, float(value)
        return
    if isinstance(value, np.ndarray):
        if value.dtype.kind in "fc":
            bad = ~np.isfinite(value)
            if bad.any():
                yield path, float(value[bad].ravel()[0].real)
        return
    variables = getattr(value, "variables", None)
    if type(value).__name__ == "Dataset" and variables is not None:  # a sweep's xarray result
        for k, v in variables.items():
            yield from _numbers(np.asarray(v.values), str(k), depth + 1)
        return
    if isinstance(value, dict):
        for k, v in value.items():
            yield from _numbers(v, f"{path}.{k}" if path else str(k), depth + 1)
        return
    if isinstance(value, (tuple, list)):
        fields = getattr(value, "_fields", None)
        for i, v in enumerate(value):
            key = fields[i] if fields else ""
            yield from _numbers(v, f"{path}.{key}" if key else path, depth + 1)
        return
    if dataclasses.is_dataclass(value):
        for f in dataclasses.fields(value):
            yield from _numbers(getattr(value, f.name), f.name, depth + 1)
        return
    slots = getattr(type(value), "__slots__", ())
    attrs = dict(getattr(value, "__dict__", {}))
    for s in slots:
        if hasattr(value, s):
            attrs[s] = getattr(value, s)
    for k, v in attrs.items():
        if not k.startswith("_"):
            yield from _numbers(v, k, depth + 1)


def check_result(qual: str, value: Any) -> list[str]:
    """Problems with a returned value: non-finite numbers outside :data:`DOCUMENTED_INF`."""
    problems = []
    owner = qual.split(".")[0]
    for path, x in _numbers(value, ""):
        if math.isfinite(x):
            continue
        field = path.split(".")[-1] if path else ""
        if math.isinf(x) and (
            (qual, field) in DOCUMENTED_INF
            or (owner, field) in DOCUMENTED_INF
            or (type(value).__name__, field) in DOCUMENTED_INF
        ):
            continue
        problems.append(f"{qual} returned {x} at {path or 'the result'}")
    return problems


def check_exception(
    qual: str, exc: BaseException, names: set[str], given: frozenset[str] = frozenset()
) -> list[str]:
    """Problems with a raised exception: its type, the argument its message names, and a
    float spelled out in full (``given``: the digits of the exact integers the call was given,
    which a message may echo as they are)."""
    if isinstance(exc, Deadline):
        return [f"{qual}: {exc}"]
    if isinstance(exc, PASS_THROUGH):
        return []
    if not isinstance(exc, ALLOWED_TYPES):
        return [f"{qual} raised {type(exc).__module__}.{type(exc).__name__}: {exc}"]
    msg = str(exc)
    head = msg.split(":", 1)[0].strip()
    if head not in names:
        return [
            f"{qual} raised {type(exc).__name__} naming {head!r}, not one of its arguments "
            f"{sorted(names)}: {msg[:200]}"
        ]
    long = spelled_out_number(msg, given)
    if long is not None:
        return [f"{qual}: a number spelled out in full, {long[:40]}…, in {msg[:200]}"]
    return []


_DIGITS = re.compile(r"(?<![\w.])\d+(?:\.\d+)?(?![\w.])")


def spelled_out_number(msg: str, given: frozenset[str] = frozenset()) -> str | None:
    """A number of ``msg`` beyond [1e-4, 1e16) written out in full (what Rust's ``{}`` prints
    for 1e-308: 310 characters) instead of the documented exponent form, or None. Runs of
    more than 17 significant digits (an exact whole number) are not floats and pass."""
    for m in _DIGITS.finditer(msg):
        token = m.group()
        if token in given:
            continue
        int_part, _, frac = token.partition(".")
        digits = (int_part + frac).strip("0")
        large = len(int_part) > 16 and not int_part.startswith("0")
        small = int_part.strip("0") == "" and frac.startswith("0000") and digits != ""
        if (large or small) and len(digits) <= 17:
            return token
    return None


def run_call(site: Site, args: dict[str, Any], read_properties: bool = True) -> list[str]:
    """Calls ``site`` with ``args`` under the deadline and checks the contract; returns the
    problems found (empty when the call kept the contract)."""
    budget = ps.memory_budget()  # set_memory_budget is fuzzed too: every call starts afresh
    try:
        return _run_call(site, args, read_properties)
    finally:
        ps.set_memory_budget(budget)


def _run_call(site: Site, args: dict[str, Any], read_properties: bool) -> list[str]:
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # warnings are allowed (GimbalLockWarning); errors are not
        try:
            with deadline():
                result = site.call(args)
        except BaseException as exc:
            if isinstance(exc, KeyboardInterrupt) and not isinstance(exc, Deadline):
                raise
            return check_exception(site.qualname, exc, site.names, _integers(args))
        problems = check_result(site.qualname, result)
        cls = type(result).__name__
        if read_properties and hasattr(ps, cls) and inspect.isclass(getattr(ps, cls)):
            for prop in properties(cls):
                try:
                    with deadline():
                        value = getattr(result, prop)
                except BaseException as exc:
                    if isinstance(exc, KeyboardInterrupt) and not isinstance(exc, Deadline):
                        raise
                    # A valid object's property may be undefined for that object; it must say
                    # so as a PoinsotError, not crash.
                    if isinstance(exc, Deadline) or not isinstance(exc, ps.PoinsotError):
                        problems.append(
                            f"{site.qualname} -> .{prop} raised {type(exc).__name__}: {exc}"
                        )
                    continue
                problems += check_result(f"{cls}", {prop: value})
        return problems


def _integers(args: dict[str, Any]) -> frozenset[str]:
    """The decimal digits of every integer among ``args`` (and in their lists, one level)."""
    values: list[Any] = []
    for v in args.values():
        values.extend(v if isinstance(v, list | tuple) else [v])
    return frozenset(
        str(abs(v)) for v in values if isinstance(v, int | np.integer) and not isinstance(v, bool)
    )


def describe(value: Any) -> str:
    text = repr(value)
    return text if len(text) < 80 else text[:77] + "..."


if __name__ == "__main__":  # pragma: no cover - a quick listing for people
    import tempfile
    from pathlib import Path

    for s in sites(Path(tempfile.mkdtemp())):
        print(
            s.qualname,
            sorted(s.valid),
            "MISSING" if s.missing else "",
            s.missing or "",
            file=sys.stdout,
        )
