"""Parameter studies as labelled arrays: a model computed at every point of a grid (or a random
sample) of its keywords, returned as an xarray ``Dataset``.

The shape of a call is the model's own keywords; any of them may be a 1-D array, which becomes
a dimension of the result, in the order given::

    ds = poinsot.sweep.heavy_top(I1=1.0, I3=0.5, mgl=1.0,
                                 theta=np.radians(np.linspace(5, 85, 81)),
                                 psi_dot=np.linspace(0.5, 20.0, 200))
    ds.motion_class            # dims (theta, psi_dot): "cusps", "loops", ...
    ds.turning_points.sel(turning_point="theta2")

* **Dimensions and coordinates.** A number is a constant (a 0-d coordinate); a 1-D array of a
  number keyword is a dimension of its own name; an ``(N, 3)`` array of a vector keyword
  (``moments``, ``omega0``; ``(N, 4)`` for ``attitude0``) a dimension ``<keyword>_index``, with
  the vectors as the coordinate ``<keyword>`` on it and the components along ``axis`` (0, 1, 2:
  the principal axes) or ``quaternion`` (w, x, y, z). ``paired={"name": ("kw1", "kw2")}``
  puts arrays of equal length along one dimension ``name`` instead of their product (an
  ensemble of initial states, each its own ω₀ and attitude). Every coordinate has ``units`` and
  ``long_name`` attributes, every result too; categories (``motion_class``, ``regime``,
  ``axis_stability``) are strings, their values listed in the attribute ``categories``.
* **Random samples.** ``samples=N, seed=S``: each keyword given as a range,
  :func:`uniform` ``(low, high)`` or :func:`log_uniform` ``(low, high)``, is drawn N times
  (numpy's default generator seeded with ``seed``) along one dimension ``sample``; arrays given
  as usual remain dimensions of their own (the sample is repeated along them).
* **Where it runs.** By default here, in one call of the compiled core over every point
  (all cores, the GIL released, Ctrl-C stops it), with a progress bar on stderr when it is a
  terminal (``progress=`` a callable ``progress(fraction)`` instead, or ``False``). Given a
  ``dask.distributed.Client`` (``client=``), the sweep runs chunk by chunk on its cluster
  (``chunks=``: an int for every dimension or ``{dimension: size}``; by default blocks of
  about 30 000 points, 1 000 for the integrating models) and returns the same numbers bit for
  bit: each chunk is computed by the same core code from the slices of the keywords. When a
  keyword is a dask array the result is a lazy Dataset (dask arrays, one chunk per block,
  computed by ``.compute()`` with whatever scheduler is active). ``to_zarr=PATH`` writes the
  results chunk by chunk into a new zarr store (on the cluster, or here one chunk at a time:
  results larger than memory) and returns it opened lazily.
* **Validation.** Every point is checked as the model's constructor checks its arguments before
  any work (before any chunk is sent out): an error names the keyword and the point, in the
  indices of the whole sweep (``"theta: must be finite and in [0, pi], got 4.0 (at theta[3],
  psi_dot[0])"``). A keyword that is not the model's, a 2-D array, an empty one and paired
  arrays of different lengths are refused by name. The results' memory is checked against the
  budget (:func:`poinsot.memory_budget`) before work, unless they go to zarr.

xarray, dask, distributed and zarr come with the optional extra ``poinsot[parallel]`` and are
imported only when a sweep runs (an ``ImportError`` names the extra when they are missing).
"""

from __future__ import annotations

import inspect
from typing import Any, Callable, Union

from .. import _core
from ..dynamics import DEFAULT_MAX_STEPS, _batch_settings
from ..earth import _DROP, Earth, _fall_model
from ..errors import ArgumentTypeError
from ._run import run
from ._spec import Key, Model, Output, Range, plan

__all__ = ["heavy_top", "free_body", "simulate", "drop", "projectile", "uniform", "log_uniform"]

ProgressLike = Union[None, bool, Callable[[float], Any]]


def uniform(low: Any, high: Any) -> Range:
    """A keyword drawn uniformly in [``low``, ``high``] in a random sample (``samples=N``).

    ``low`` and ``high`` are in the keyword's own units (degrees or deg/s for an angle or a
    rate with ``degrees=True``): numbers, shape (), or for a vector keyword vectors of its
    length, (3,), each component drawn on its own. Raises :class:`PoinsotError` naming ``low``
    or ``high`` (not finite, ``high < low``, shapes that differ)."""
    return Range(low, high)


def log_uniform(low: Any, high: Any) -> Range:
    """A keyword drawn log-uniformly in [``low``, ``high``] (``low`` > 0): uniform in the
    logarithm, for a quantity spanning decades. Units and shapes as :func:`uniform`."""
    return Range(low, high, log=True)


def _keys(names: list[str], table: dict[str, Key]) -> tuple[Key, ...]:
    """The core's keywords of a model (its list, in its order) with their labels."""
    missing = [n for n in names if n not in table]
    if missing:  # a keyword added to the core needs its label here
        raise RuntimeError(f"no label for the core's sweep keywords {missing}")
    return tuple(table[n] for n in names)


_ROT = "kg m^2"
_MOM = "kg m^2/s"

_HEAVY_TOP = Model(
    "heavy_top",
    "HeavyTop",
    _keys(
        list(_core.SWEEP_HEAVY_TOP_KEYWORDS),
        {
            "I1": Key("I1", "moment of inertia about a transverse axis through the pivot", _ROT),
            "I3": Key("I3", "moment of inertia about the symmetry axis", _ROT),
            "mgl": Key("mgl", "weight times pivot-to-centre-of-mass distance", "N m"),
            "theta": Key("theta", "initial nutation angle θ₀", "rad", angle="angle"),
            "theta_dot": Key("theta_dot", "initial nutation rate", "rad/s", angle="rate"),
            "phi_dot": Key("phi_dot", "initial precession rate", "rad/s", angle="rate"),
            "psi_dot": Key("psi_dot", "initial spin rate ψ̇", "rad/s", angle="rate"),
            "omega3": Key("omega3", "spin ω₃ = ψ̇ + φ̇ cos θ (2.99)", "rad/s", angle="rate"),
            "phi": Key("phi", "initial precession angle", "rad", angle="angle"),
            "psi": Key("psi", "initial spin angle", "rad", angle="angle"),
        },
    ),
    (
        Output(
            "motion_class",
            "shape of the axis' path (Goldstein Fig. 5.9)",
            "",
            "category",
            table="motion_class",
        ),
        Output(
            "turning_points",
            "turning points θ₁ ≤ θ₂ of the nutation (roots of the cubic in cos θ)",
            "rad",
            extra="turning_point",
        ),
        Output("nutation_period", "period of θ(t) (inf where θ never returns)", "s"),
        Output("mean_precession_rate", "mean precession rate ⟨φ̇⟩", "rad/s"),
        Output("mean_spin_rate", "mean spin rate ⟨ψ̇⟩", "rad/s"),
        Output("omega3", "spin ω₃ = ψ̇ + φ̇ cos θ (2.99)", "rad/s"),
        Output("p_phi", "momentum about the vertical p_φ (2.104)", _MOM),
        Output("p_psi", "momentum about the symmetry axis p_ψ (2.103)", _MOM),
        Output("energy", "total energy E (2.105)", "J"),
        Output("reduced_energy", "reduced energy E' = E − p_ψ²/(2 I₃) (2.109)", "J"),
        Output(
            "is_sleeping_stable",
            "the spin keeps an upright top asleep: ω₃² > 4 m g l I₁ / I₃²",
            "",
            "bool",
        ),
    ),
    _core.sweep_heavy_top,
    1 << 15,
)

_FREE_BODY = Model(
    "free_body",
    "FreeRigidBody",
    _keys(
        list(_core.SWEEP_FREE_BODY_KEYWORDS),
        {
            "moments": Key("moments", "principal moments of inertia", _ROT, 3),
            "omega0": Key("omega0", "initial angular velocity, body axes", "rad/s", 3),
            "omega_magnitude": Key("omega_magnitude", "|ω₀|", "rad/s"),
            "omega_polar": Key("omega_polar", "angle of ω₀ from body axis 3", "rad", angle="angle"),
            "omega_azimuth": Key(
                "omega_azimuth",
                "azimuth of ω₀ from body axis 1 towards axis 2",
                "rad",
                angle="angle",
            ),
        },
    ),
    (
        Output("omega0", "initial angular velocity, body axes", "rad/s", extra="axis"),
        Output("regime", "regime of the torque-free motion", "", "category", table="regime"),
        Output("period", "period of ω(t) in the body (inf when steady or on the separatrix)", "s"),
        Output("flip_interval", "half the period: time between flips of ω₂", "s"),
        Output("parameter", "Jacobi parameter m = k²", ""),
        Output("frequency", "rate λ of the Jacobi argument λt + τ₀", "rad/s"),
        Output("pole_axis", "principal axis ω circles (-1: none)", "", "int"),
        Output("energy", "kinetic energy T", "J"),
        Output("angular_momentum", "angular momentum L = I ω₀", _MOM, extra="axis"),
        Output(
            "axis_stability",
            "stability of steady rotation about each principal axis",
            "",
            "category",
            extra="axis",
            table="stability",
        ),
        Output(
            "axis_rate",
            "oscillation frequency (stable) or growth rate (unstable) of steady rotation at |ω₀|",
            "1/s",
            extra="axis",
        ),
    ),
    _core.sweep_free_body,
    1 << 15,
)

_SIMULATE = Model(
    "simulate",
    "simulate_batch",
    _keys(
        list(_core.SWEEP_SIMULATE_KEYWORDS),
        {
            "moments": Key("moments", "principal moments of inertia", _ROT, 3),
            "omega0": Key("omega0", "initial angular velocity, body axes", "rad/s", 3),
            "attitude0": Key(
                "attitude0", "initial attitude, quaternion [w, x, y, z] body → space", "", 4
            ),
        },
    ),
    (
        Output("omega", "final angular velocity, body axes", "rad/s", extra="axis"),
        Output(
            "attitude",
            "final attitude, quaternion [w, x, y, z] body → space",
            "",
            extra="quaternion",
        ),
    ),
    _core.sweep_simulate,
    1 << 10,
)

_LAT = Key("latitude", "latitude, north-positive", "rad", angle="angle")


def _landing(run: str, origin: str) -> tuple[Output, Output, Output]:
    """The first outputs of a run to the ground (``run``: "fall", "flight"): its time and the
    landing point east and north of ``origin``."""
    return (
        Output("time", f"time of {run}", "s"),
        Output("east", f"landing point east of {origin}", "m"),
        Output("north", f"landing point north of {origin}", "m"),
    )


_DROP_MODEL = Model(
    "drop",
    "Earth.drop",
    _keys(
        list(_core.SWEEP_DROP_KEYWORDS),
        {"height": Key("height", "release height above the ground", "m"), "latitude": _LAT},
    ),
    (
        *_landing("fall", "the plumb line"),
        Output("first_order_east", "eastward deflection to first order in ω (2.42)", "m"),
        Output("second_order_south", "southward deflection to second order in ω", "m"),
    ),
    _core.sweep_drop,
    1 << 10,
)

_PROJECTILE = Model(
    "projectile",
    "Earth.projectile",
    _keys(
        list(_core.SWEEP_PROJECTILE_KEYWORDS),
        {
            "speed": Key("speed", "launch speed", "m/s"),
            "elevation": Key(
                "elevation", "launch elevation above the horizon", "rad", angle="angle"
            ),
            "azimuth": Key("azimuth", "launch azimuth, clockwise from north", "rad", angle="angle"),
            "latitude": _LAT,
            "height": Key("height", "launch height above the ground", "m"),
        },
    ),
    (
        *_landing("flight", "the launch"),
        Output("range", "horizontal distance from launch to landing", "m"),
        Output("downrange", "landing displacement along the launch azimuth", "m"),
        Output("drift", "landing displacement to the right of the azimuth", "m"),
    ),
    _core.sweep_projectile,
    1 << 10,
)

#: The sweepable models by name (a chunk computed on a dask worker finds its model here).
MODELS: dict[str, Model] = {
    m.name: m for m in (_HEAVY_TOP, _FREE_BODY, _SIMULATE, _DROP_MODEL, _PROJECTILE)
}

_DEGREES = """    degrees : bool
        Angles in degrees and angular rates in degrees per second (the coordinates keep the
        values as given, with units "deg" or "deg/s"; the results stay in rad and rad/s).
"""

_COMMON = """    quantities : str or list of str, optional
        The results to keep (default: all).
    samples, seed : int, optional
        Draw ``samples`` points of the keywords given as :func:`uniform` or
        :func:`log_uniform` ranges, along the dimension ``sample`` (numpy's default generator,
        seeded with ``seed``).
    paired : dict, optional
        ``{"name": ("kw1", "kw2", ...)}``: arrays of equal length along one dimension ``name``.
    client : dask.distributed.Client, optional
        Run chunk by chunk on its cluster.
    chunks : int or dict, optional
        Chunk sizes along the dimensions (an int for every dimension, or ``{dimension: size}``;
        the others are not split): with a client, the tasks of the cluster; without one, the
        sweep also runs chunk by chunk here (one core call a chunk).
    to_zarr : str or path, optional
        Write the results chunk by chunk into this new zarr store and return it opened lazily.
    progress : callable, bool or None
        ``progress(fraction)``, called as the sweep advances (an exception it raises stops the
        sweep); ``None`` (default) draws a bar on stderr once the sweep has run a second, when
        stderr is a terminal; ``True`` draws it in any case; ``False`` reports nothing.

    Returns
    -------
    xarray.Dataset
        The results as variables over the sweep's dimensions, the keywords as coordinates
        (units and long names in their attributes), the model and its settings in the
        dataset's attributes.

    Raises
    ------
    PoinsotError
        A keyword at a point where the model refuses it (the message names the keyword and the
        point), a keyword that is not the model's (``ArgumentTypeError``), a 2-D or empty array,
        paired arrays of different lengths, results beyond the memory budget.
    ImportError
        xarray, dask, distributed or zarr missing (the extra ``poinsot[parallel]``).
"""


def _doc(text: str, degrees: bool) -> str:
    """A sweep's docstring: its summary and model keywords, then the options every sweep takes,
    what it returns and raises, and last (as Notes) the paragraph on its results."""
    head, sep, results = text.partition("\n\n    The results")
    notes = f"\n    Notes\n    -----\n    The results{results.rstrip()}\n" if sep else ""
    return head.rstrip() + "\n" + (_DEGREES if degrees else "") + _COMMON + notes


#: The options every sweep takes after its own (name, annotation, default), keyword-only; then
#: ``**keywords``, the model's keywords.
_OPTIONS = (
    ("quantities", "Any", None),
    ("samples", "Optional[int]", None),
    ("seed", "Optional[int]", None),
    ("paired", "Optional[dict[str, Any]]", None),
    ("client", "Any", None),
    ("chunks", "Any", None),
    ("to_zarr", "Any", None),
    ("progress", "ProgressLike", None),
)
_DEGREES_OPTION = (("degrees", "bool", False),)
_NO_SETTINGS: Callable[[dict[str, Any], dict[str, Any]], Any] = lambda args, keywords: ((), None)


def _sweep_function(
    name: str,
    model: Model,
    doc: str,
    own: tuple[tuple[str, str, Any], ...] = _DEGREES_OPTION,
    settings: Callable[[dict[str, Any], dict[str, Any]], Any] = _NO_SETTINGS,
) -> Callable[..., Any]:
    """The public sweep ``name`` of ``model``: keyword-only arguments ``own`` (its settings, and
    ``degrees`` where it takes angles), then :data:`_OPTIONS` and the model's ``**keywords``;
    ``settings(arguments, keywords)`` gives the core's settings of the sweep and the attributes
    that record them. Its docstring is ``doc`` completed by :func:`_doc`."""
    P = inspect.Parameter
    signature = inspect.Signature(
        [P(n, P.KEYWORD_ONLY, default=d, annotation=a) for n, a, d in own + _OPTIONS]
        + [P("keywords", P.VAR_KEYWORD, annotation="Any")],
        return_annotation="Any",
    )

    def sweep(**given: Any) -> Any:
        try:
            bound = signature.bind(**given)
        except TypeError as exc:  # a required setting missing
            raise TypeError(f"{name}() {exc}") from None
        bound.apply_defaults()
        args = bound.arguments
        keywords = dict(args["keywords"])
        setting, attrs = settings(args, keywords)
        p = plan(
            model,
            keywords,
            degrees=args.get("degrees", False),
            samples=args["samples"],
            seed=args["seed"],
            paired=args["paired"],
            quantities=args["quantities"],
            settings=setting,
            attrs=attrs,
        )
        return run(
            p,
            client=args["client"],
            chunks=args["chunks"],
            to_zarr=args["to_zarr"],
            progress=args["progress"],
        )

    sweep.__name__ = sweep.__qualname__ = name
    sweep.__doc__ = _doc(doc, any(n == "degrees" for n, _, _ in own))
    sweep.__signature__ = signature  # type: ignore[attr-defined]
    return sweep


heavy_top = _sweep_function(
    "heavy_top",
    _HEAVY_TOP,
    """The heavy symmetric top (:class:`poinsot.HeavyTop`, eqs. 2.102–2.121) at every point of
    a grid of its keywords.

    Parameters
    ----------
    I1, I3, mgl, theta : float or 1-D array
        As :class:`poinsot.HeavyTop`: I₁, I₃ (kg m², > 0, I₃ ≤ 2 I₁), m g l (N m, ≥ 0), θ₀ (rad,
        in [0, π]). Required.
    theta_dot, phi_dot, psi_dot, phi, psi : float or 1-D array
        The initial rates (rad/s) and angles (rad); 0 when not given.
    omega3 : float or 1-D array
        The spin ω₃ (rad/s) instead of ``psi_dot``, as :meth:`poinsot.HeavyTop.from_spin`
        (then p_ψ = I₃ ω₃ whatever ``phi_dot``).

    The results: ``motion_class`` (one of :data:`poinsot.MOTION_CLASSES`), ``turning_points``
    (θ₁, θ₂ along the dimension ``turning_point``, rad), ``nutation_period`` (s, inf where θ
    never returns), ``mean_precession_rate``, ``mean_spin_rate``, ``omega3`` (rad/s),
    ``p_phi``, ``p_psi`` (kg m²/s), ``energy``, ``reduced_energy`` (J),
    ``is_sleeping_stable``: at each point the property of that name of
    ``HeavyTop(I1, I3, mgl, theta, ...)``, bit for bit.
    """,
)

free_body = _sweep_function(
    "free_body",
    _FREE_BODY,
    """The torque-free rigid body (:class:`poinsot.FreeRigidBody`) at every point of a grid of
    its moments and initial angular velocities.

    Parameters
    ----------
    moments : (3,) or (N, 3) array
        Principal moments (kg m², > 0, any order, obeying the triangle inequality).
    omega0 : (3,) or (N, 3) array
        The initial angular velocity in body components (rad/s, nonzero); or instead:
    omega_magnitude, omega_polar, omega_azimuth : float or 1-D array
        Its size |ω₀| (rad/s, > 0) and direction: the angle from body axis 3 (rad, in [0, π])
        and the azimuth from body axis 1 towards axis 2 (rad), ω₀ = |ω₀| (sin θ cos φ,
        sin θ sin φ, cos θ); the intermediate axis of ascending moments is at θ = φ = π/2.

    The results, at each point those of ``FreeRigidBody(moments, omega0)`` (initial attitude
    the identity), bit for bit: ``omega0`` (when given by size and direction), ``regime``,
    ``period`` and ``flip_interval`` (s, inf when steady or on the separatrix), ``parameter``,
    ``frequency`` (rad/s), ``pole_axis`` (-1: none), ``energy`` (J), ``angular_momentum``
    (kg m²/s); and :func:`poinsot.axis_stability` at the spin |ω₀|: ``axis_stability``
    ("stable", "unstable", "neutral") and ``axis_rate`` (1/s) along ``axis``.
    """,
)


def _simulate_settings(args: dict[str, Any], keywords: dict[str, Any]) -> Any:
    """The settings of :func:`simulate` (as ``simulate_batch``'s) and their attributes."""
    settings = _batch_settings(
        args["torque"],
        args["duration"],
        args["method"],
        args["dt"],
        args["max_steps"],
        "a sweep takes the built-in torques only (no callables), as simulate_batch",
    )
    dur, _, m, step, steps = settings
    attrs = {
        "duration": dur,
        "torque": repr(args["torque"]),
        "method": m,
        "dt": "default" if step is None else step,
        "max_steps": steps,
    }
    # The core's sweep takes the batch's settings as one tuple, as simulate_batch.
    return (settings,), attrs


simulate = _sweep_function(
    "simulate",
    _SIMULATE,
    """Ensembles of rigid bodies under a torque: the final state of every point of a grid of
    moments and initial states, integrated by :func:`poinsot.simulate_batch` (Euler's equations
    2.71 with the attitude).

    Parameters
    ----------
    moments : (3,) or (N, 3) array
        Principal moments (kg m²).
    omega0 : (3,) or (N, 3) array
        Initial angular velocities, body components (rad/s).
    attitude0 : (4,) or (N, 4) array, optional
        Initial attitudes, quaternions [w, x, y, z] (body → space); the identity if not given.
    duration, torque, method, dt, max_steps
        As :func:`poinsot.simulate_batch`, one for the whole sweep: ``torque`` a built-in torque
        (``BodyTorque``, ``SpaceTorque``, ``GravityTorque(mgl=...)``,
        ``GravityGradientTorque``), not a callable.

    The results: ``omega`` (rad/s, along ``axis``) and ``attitude`` (along ``quaternion``) at
    ``duration``: at each point those of ``simulate_batch`` of that body, bit for bit.
    """,
    (
        ("duration", "float", inspect.Parameter.empty),
        ("torque", "TorqueLike", None),
        ("method", "str", "rk4"),
        ("dt", "Optional[float]", None),
        ("max_steps", "int", DEFAULT_MAX_STEPS),
    ),
    _simulate_settings,
)

#: The settings of the Earth's sweeps (as :meth:`poinsot.Earth.drop`'s), then ``degrees``.
_EARTH_OPTIONS = (
    ("earth", "Optional[Earth]", None),
    ("gravity", "str", "uniform"),
    ("rotation", "bool", True),
    ("centrifugal", "bool", True),
    ("rtol", "float", _DROP["rtol"]),
    ("atol", "float", _DROP["atol"]),
    ("max_steps", "int", _DROP["max_steps"]),
) + _DEGREES_OPTION


def _earth_settings(args: dict[str, Any], keywords: dict[str, Any]) -> Any:
    """The core's Earth and fall model of a sweep (its settings), and the attributes that
    record them; a projectile's ``height`` is 0 when not given."""
    earth = Earth() if args["earth"] is None else args["earth"]
    if not isinstance(earth, Earth):
        raise ArgumentTypeError(
            f"earth: must be a poinsot.Earth or None, got {type(earth).__name__}"
        )
    model = _fall_model(*(args[n] for n, _, _ in _EARTH_OPTIONS[1:7]))
    attrs: dict[str, Any] = {
        "rotation_rate": earth.rotation_rate,
        "radius": earth.radius,
        "g": earth.g,
        "gravity": model.gravity,
        "rotation": int(model.rotation),
        "centrifugal": int(model.centrifugal),
        "rtol": model.rtol,
        "atol": model.atol,
        "max_steps": model.max_steps,
    }
    return (earth._core, model), attrs


drop = _sweep_function(
    "drop",
    _DROP_MODEL,
    """A body dropped from rest on the rotating Earth (:meth:`poinsot.Earth.drop`, eqs.
    2.30–2.42) at every point of a grid of heights and latitudes.

    Parameters
    ----------
    height : float or 1-D array
        Release height (m, > 0).
    latitude : float or 1-D array
        Latitude (rad, north-positive).
    earth, gravity, rotation, centrifugal, rtol, atol, max_steps
        As :meth:`poinsot.Earth.drop` (``earth`` the :class:`poinsot.Earth`, default
        ``Earth()``), one for the whole sweep.

    The results, at each point those of ``earth.drop(height, latitude, ...)``, bit for bit:
    ``time`` (s), ``east``, ``north`` (m), and the closed forms ``first_order_east`` (2.42) and
    ``second_order_south`` (m).
    """,
    _EARTH_OPTIONS,
    _earth_settings,
)


def _projectile_settings(args: dict[str, Any], keywords: dict[str, Any]) -> Any:
    """As :func:`_earth_settings`, the launch height 0 when not given."""
    keywords.setdefault("height", 0.0)
    return _earth_settings(args, keywords)


projectile = _sweep_function(
    "projectile",
    _PROJECTILE,
    """A projectile on the rotating Earth (:meth:`poinsot.Earth.projectile`) at every point of
    a grid of launches.

    Parameters
    ----------
    speed : float or 1-D array
        Launch speed (m/s, > 0).
    elevation, azimuth, latitude : float or 1-D array
        Elevation above the horizon, azimuth clockwise from north, latitude (rad).
    height : float or 1-D array
        Launch height (m, ≥ 0), 0 when not given (as :meth:`poinsot.Earth.projectile`).
    earth, gravity, rotation, centrifugal, rtol, atol, max_steps
        As :func:`drop`.

    The results, at each point those of ``earth.projectile(...)``, bit for bit: ``time`` (s),
    ``east``, ``north``, ``range``, ``downrange``, ``drift`` (m).
    """,
    _EARTH_OPTIONS,
    _projectile_settings,
)
