"""Every public class pickles and deep-copies to an equal object that computes the same numbers,
bit for bit (issue 21, item 8: FreeRigidBody, FreeSymmetricTop, HeavyTop and SpringParticle
could not, so a Dask task could not return them).

The classes are found, not listed: every class in ``poinsot.__all__`` and in the ``__all__`` of
every public submodule. A class without a case below (or an exemption saying why) fails
``test_every_public_class_has_a_round_trip_case``, so a new class cannot skip this.
"""

from __future__ import annotations

import copy
import importlib
import inspect
import pickle
import pkgutil
from collections.abc import Callable
from typing import Any

import numpy as np
import poinsot as ps
import pytest
from poinsot import _core

#: Public classes that are not values, with the reason; everything else must round-trip.
EXEMPT = {
    "poinsot.widgets.HeavyTopWidget": "a live notebook view bound to its kernel's comm channel "
    "(its state is `params`; `w.top` gives the HeavyTop, which round-trips)",
    "poinsot.widgets.PoinsotWidget": "a live notebook view (`w.body` round-trips)",
    "poinsot.widgets.FramesWidget": "a live notebook view",
    "poinsot.derive._core.Derivation": "the shared, checked sympy derivation of a topic, "
    "holding its notation's model function; fetched by name with poinsot.derive.derivation",
}


def public_classes() -> dict[str, type]:
    modules = ["poinsot"] + [
        m.name
        for m in pkgutil.walk_packages(ps.__path__, "poinsot.")
        if not any(part.startswith("_") for part in m.name.split(".")[1:])
    ]
    found: dict[str, type] = {}
    for name in modules:
        try:
            mod = importlib.import_module(name)
        except ImportError:  # an extra that is not installed
            continue
        for attr in getattr(mod, "__all__", ()):
            obj = getattr(mod, attr, None)
            if inspect.isclass(obj) and obj.__module__.startswith("poinsot"):
                found[f"{obj.__module__}.{obj.__qualname__}"] = obj
    return found


def _earth() -> ps.Earth:
    return ps.Earth()


def _wobble() -> ps.WobbleFit:
    pm = ps.polar_motion("shipped")
    return ps.fit_wobble(pm.dates, pm.x, pm.y, chandler_period=433.0 * 86400.0)


def _pole_run() -> ps.PoleRun:
    # 19 Julian years: a fit needs one node period (18.6 years)
    return ps.RigidEarth().simulate(19 * 365.25 * 86400.0, samples=50)


def _derive(kind: str) -> Any:
    d = pytest.importorskip("poinsot.derive")
    if kind == "Step":
        return d.derivation("euler_equations").steps[1]
    if kind == "Printed":
        return d.printed()[3]
    if kind == "Erratum":
        return d.errata()[0]
    return d.questions()[0]


def _experiments() -> Any:
    return pytest.importorskip("poinsot.experiments")


def _a_sense() -> str:
    """The first entry of the catalogue that compares a sense (a word, not a number)."""
    return next(e.name for e in _experiments().catalogue() if not any(map(str.isdigit, e.measured)))


def _unit_figure() -> Any:
    from poinsot.plots.unit import UNIT_FIGURES

    return (
        UNIT_FIGURES[0]
        if isinstance(UNIT_FIGURES, (list, tuple))
        else next(iter(UNIT_FIGURES.values()))
    )


T = np.array([0.0, 0.37, 2.5, 41.0])

#: class name → (object, the numbers it computes) for each way of making one.
CASES: dict[str, list[tuple[Callable[[], Any], Callable[[Any], Any]]]] = {
    "FreeRigidBody": [
        (lambda: ps.FreeRigidBody([1.0, 2.0, 3.0], [1.0, 0.1, 1.0]), lambda b: b.state(T)),
        (
            lambda: ps.FreeRigidBody((3.0, 2.0, 1.5), np.array([0.2, 1.0, 0.3]), [0.6, 0, 0.8, 0]),
            lambda b: (b.state(T), b.polhode(16), b.contact_point(T)),
        ),
        (  # from a RigidBody (its principal moments) and a scipy Rotation
            lambda: ps.FreeRigidBody(
                ps.RigidBody.cuboid(2.0, (3.0, 1.0, 2.0)),
                [0.3, 2.0, 0.1],
                pytest.importorskip("scipy.spatial.transform").Rotation.from_rotvec(
                    [0.1, 0.2, 0.3]
                ),
            ),
            lambda b: (b.state(T), b.period, b.regime),
        ),
    ],
    "FreeSymmetricTop": [
        (lambda: ps.FreeSymmetricTop(2.0, 1.0, [0.3, 0.4, 2.0]), lambda s: s.attitude(T)),
        (
            lambda: ps.FreeSymmetricTop(1.0, 1.5, [0.3, 0.0, 1.0], [0.8, 0.6, 0, 0]),
            lambda s: (s.attitude(T), s.omega(T), s.symmetry_axis(T)),
        ),
    ],
    "HeavyTop": [
        (lambda: ps.HeavyTop(1.0, 0.5, 1.0, 0.8, psi_dot=6.0), lambda h: h.euler_angles(T)),
        (
            lambda: ps.HeavyTop(1.0, 0.5, 1.0, 40.0, phi_dot=5.0, psi_dot=300.0, degrees=True),
            lambda h: (h.euler_angles(T), h.turning_points),
        ),
        (
            lambda: ps.HeavyTop.from_spin(1.0, 0.5, 1.0, 0.8, 6.0, phi_dot=0.4, theta_dot=0.1),
            lambda h: (h.euler_angles(T), h.symmetry_axis(T), h.p_psi),
        ),
        (
            lambda: ps.HeavyTop.from_constants(1.0, 0.5, 1.0, 2.0, 3.0, 12.0),
            lambda h: (h.euler_angles(T), h.nutation_period, h.motion_class),
        ),
    ],
    "SpringParticle": [
        (
            lambda: ps.SpringParticle(mass=2.0, stiffness=8.0),
            lambda p: (
                p.simulate(
                    ps.MovingFrame(angular_velocity=[0, 0, 1.0]),
                    [1.0, 0, 0],
                    [0, 0.5, 0],
                    3.0,
                    samples=5,
                ).position
            ),
        ),
    ],
    "RigidBody": [
        (lambda: ps.RigidBody.cuboid(2.0, (3.0, 1.0, 2.0)), lambda b: b.principal_moments),
        (
            lambda: ps.RigidBody.from_density(
                lambda x: 1.0 + 0 * x[..., 0], [[0, 1], [0, 2], [0, 1]], rtol=1e-3
            ),
            lambda b: (b.inertia, b.integration_error),
        ),
    ],
    "IntegrationErrorEstimate": [
        (lambda: ps.IntegrationErrorEstimate(1e-9, 2e-9, 3e-9, 1000, True), lambda e: e.mass)
    ],
    "Screw": [
        (
            lambda: ps.screw_axis(ps.axis_angle_to_matrix([0, 0, 1], 0.5), [1.0, 2, 3]),
            lambda s: s.apply([[1.0, 2.0, 3.0]]),
        ),
        # built from its parts (issue 21, item 9): list input, the point moved along the axis
        (
            lambda: ps.Screw([0.0, 0.0, 2.0], [0.5, -1.0, 7.0], 0.5, 0.1),
            lambda s: (s.point, s.pitch, s.apply([1.0, 2.0, 3.0])),
        ),
    ],
    "MovingFrame": [
        (
            lambda: ps.MovingFrame(origin=[1, 2, 3], angular_velocity=[0, 0.1, 1.0]),
            lambda f: f.to_fixed([1.0, 0, 0], [0, 1.0, 0]).acceleration,
        )
    ],
    "FrameTransform": [
        (
            lambda: ps.MovingFrame(angular_velocity=[0, 0, 1.0]).to_fixed([1.0, 0, 0], [0, 1.0, 0]),
            lambda t: t.acceleration,
        )
    ],
    "ParticleTrajectory": [
        (
            lambda: ps.SpringParticle(2.0, 8.0).simulate(
                ps.MovingFrame(angular_velocity=[0, 0, 1.0]), [1.0, 0, 0], [0, 0, 0], 1.0, samples=3
            ),
            lambda r: r.to_fixed(),
        )
    ],
    "Earth": [(lambda: ps.Earth(radius=6.0e6), lambda e: e.effective_gravity(0.7))],
    "RigidEarth": [
        (lambda: ps.RigidEarth(0.004, 7e-5, 0.3), lambda e: (e.euler_period, e.precession_rate))
    ],
    "PoleRun": [(lambda: _pole_run(), lambda r: (r.t, r.longitude, r.obliquity, r.fit()))],
    "AveragedPole": [
        (lambda: ps.RigidEarth().averaged_pole([0.0, 3e8], moon_node=0.4), lambda p: p.psi)
    ],
    "PoleFit": [
        (lambda: _pole_run().fit(), lambda f: (f.precession_rate, f.nutation_longitude, repr(f)))
    ],
    "PolarMotion": [(lambda: ps.polar_motion("shipped"), lambda p: (p.t, p.x, p.y, p.dates))],
    "WobbleFit": [(lambda: _wobble(), lambda f: (f.chandler.amplitude, f.drift, str(f)))],
    "WobbleTerm": [(lambda: _wobble().annual_prograde, lambda w: (w.phase, w.period_days))],
    "Fall": [(lambda: _earth().drop(100.0, 0.7, samples=5), lambda f: f.first_order_east)],
    "Flight": [(lambda: _earth().projectile(50.0, 0.7, 0.2, 0.5, samples=5), lambda f: f.position)],
    "FoucaultRun": [
        (lambda: _earth().foucault(0.8, duration=60.0, samples=5), lambda f: f.precession_rate)
    ],
    "InertialOscillation": [
        (lambda: _earth().inertial_oscillation(0.8, samples=5), lambda o: o.period)
    ],
    "LowFlow": [(lambda: _earth().flow_into_low(0.8, parcels=2, samples=5), lambda f: f.position)],
    "BodyTorque": [(lambda: ps.BodyTorque([0.0, 0.1, 0.0]), lambda t: repr(t))],
    "SpaceTorque": [(lambda: ps.SpaceTorque([0.0, 0.1, 0.0]), lambda t: repr(t))],
    "GravityTorque": [(lambda: ps.GravityTorque(mgl=2.0), lambda t: repr(t))],
    "GravityGradientTorque": [(lambda: ps.GravityGradientTorque(1e-3), lambda t: repr(t))],
    "Trajectory": [
        (
            lambda: ps.simulate(
                ps.RigidBody.cuboid(1.0, (3.0, 1.0, 2.0)), [1, 0.1, 1], 1.0, samples=4
            ),
            lambda r: (r.total_energy, r.rotation().as_quat()),
        )
    ],
    "CarriedTrajectory": [
        (
            lambda: ps.simulate(
                [1.0, 1.0, 1.5], [0, 0, 1.0], 1.0, carried_by=ps.Place(0.5), samples=3
            ),
            lambda r: (r.relative_attitude, r.frame_attitude, r.relative_omega, r.attitude),
        )
    ],
    "Place": [(lambda: ps.Place(0.5), lambda p: (p.latitude, p.earth.g))],
    "Gyrocompass": [
        (lambda: ps.Gyrocompass(0.8), lambda c: (c.period, c.settle_error, c.speed_error(9.0, 0.3)))
    ],
    "CompassRun": [
        (lambda: ps.Gyrocompass(0.8).simulate(5.0, 0.1, samples=3), lambda r: (r.heading, r.tilt))
    ],
    "AxisStability": [(lambda: ps.axis_stability([1.0, 2.0, 3.0])[1], lambda a: a.rate)],
    "SteadyPrecession": [
        (lambda: ps.HeavyTop.steady_precession(1.0, 0.5, 1.0, 0.8, 20.0), lambda s: s.slow)
    ],
    "Step": [(lambda: _derive("Step"), lambda s: str(s))],
    "Printed": [(lambda: _derive("Printed"), lambda p: str(p.equation))],
    "Erratum": [(lambda: _derive("Erratum"), lambda e: str(e.derived))],
    "Question": [(lambda: _derive("Question"), lambda q: q.number)],
    "UnitFigure": [(_unit_figure, lambda u: sorted(u.arguments()))],
    "Experiment": [(lambda: _experiments().get("reich-1831"), lambda e: e.parsed_inputs())],
    "Source": [(lambda: _experiments().get("reich-1831").sources[0], lambda s: s.to_dict())],
    "ExperimentResult": [
        (lambda: _experiments().run("reich-1831"), lambda r: (r.predicted_si, r.sigma)),
        (lambda: _experiments().run(_a_sense()), lambda r: (r.predicted, r.verdict)),
    ],
    "Template": [(lambda: _exercises().template("dropped-ball"), lambda t: t.variant(1).answer)],
    "Variant": [(lambda: _exercises().template("top-nutation").variant(4), lambda v: v.to_dict())],
    "Check": [(lambda: _exercises().check("dropped-ball", 1, 3.0), lambda c: c.to_dict())],
    "Param": [(lambda: _exercises().Param("h", "m", 1, 9, 0.5), lambda p: p.draw(_rng()))],
    "SolutionStep": [
        (lambda: _exercises().template("dropped-ball").variant(1).steps[1], lambda s: s.plain())
    ],
}


def _exercises() -> Any:
    return pytest.importorskip("poinsot.exercises")


def _rng() -> Any:
    return np.random.default_rng(5)


#: The public exceptions and warnings, read from the package (a new one is covered unasked).
ERRORS_AND_WARNINGS = {
    name
    for name, obj in vars(ps).items()
    if isinstance(obj, type) and issubclass(obj, BaseException) and not name.startswith("_")
}


def same(a: Any, b: Any) -> bool:
    """Equal state, floats compared bit for bit (NaN, −0.0); the core's own objects are compared
    through the numbers they compute (the probes)."""
    if type(a) is not type(b):
        return False
    if type(a).__module__ == _core.__name__:
        return True
    if isinstance(a, np.ndarray):
        return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()
    if isinstance(a, (float, np.floating)):
        return np.float64(a).tobytes() == np.float64(b).tobytes()
    if isinstance(a, (tuple, list)):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if isinstance(a, dict):
        return list(a) == list(b) and all(same(a[k], b[k]) for k in a)
    if isinstance(a, BaseException):
        return same(a.args, b.args) and str(a) == str(b)
    if inspect.isroutine(a) or inspect.isclass(a):
        return a is b
    if not type(a).__module__.startswith("poinsot"):  # sympy, scipy, ...: their own equality
        return bool(a == b)
    fields = dict(getattr(a, "__dict__", {}))
    for cls in type(a).__mro__:
        for slot in getattr(cls, "__slots__", ()):
            if hasattr(a, slot):
                fields[slot] = getattr(a, slot)
    if not fields:
        return bool(a == b)
    other = dict(getattr(b, "__dict__", {}))
    for cls in type(b).__mro__:
        for slot in getattr(cls, "__slots__", ()):
            if hasattr(b, slot):
                other[slot] = getattr(b, slot)
    return same(fields, other)


def round_trips(obj: Any) -> list[Any]:
    return [pickle.loads(pickle.dumps(obj, protocol=p)) for p in (2, pickle.HIGHEST_PROTOCOL)] + [
        copy.deepcopy(obj),
        copy.copy(obj),
    ]


def test_every_public_class_has_a_round_trip_case() -> None:
    classes = public_classes()
    names = {qual.rsplit(".", 1)[1] for qual in classes if qual not in EXEMPT}
    assert names - set(CASES) - ERRORS_AND_WARNINGS == set()  # a new class needs a case
    assert set(EXEMPT) <= set(classes)  # no stale exemption
    assert {"FreeRigidBody", "FreeSymmetricTop", "HeavyTop", "SpringParticle"} <= names
    # The scan finds the exceptions (negative control of ERRORS_AND_WARNINGS' reading).
    assert {"PoinsotError", "InternalError", "GimbalLockWarning", "IntegrationWarning"} <= (
        ERRORS_AND_WARNINGS
    )
    assert len(ERRORS_AND_WARNINGS) >= 10


@pytest.mark.parametrize(
    ("name", "k"), [(name, k) for name, cases in CASES.items() for k in range(len(cases))]
)
def test_pickle_and_deepcopy_round_trip(name: str, k: int) -> None:
    make, numbers = CASES[name][k]
    obj = make()
    assert type(obj).__name__ == name
    want = numbers(obj)
    for twin in round_trips(obj):
        assert type(twin) is type(obj)
        assert same(obj, twin), name
        assert same(numbers(twin), want), name  # bit for bit


@pytest.mark.parametrize("name", sorted(ERRORS_AND_WARNINGS))
def test_errors_and_warnings_round_trip(name: str) -> None:
    cls = getattr(ps, name)
    err = cls("theta: must be in [0, pi], got 4")
    for twin in round_trips(err):
        assert type(twin) is cls and twin.args == err.args and str(twin) == str(err)
    if issubclass(cls, ps.PoinsotError):
        assert isinstance(pickle.loads(pickle.dumps(err)), ValueError)


def test_the_copy_is_the_same_construction_not_a_nearby_one() -> None:
    # A top with the same motion made by another constructor (from_state with the psi_dot that
    # from_spin derives) agrees to round-off only; the round trip of each reproduces its own
    # numbers bit for bit (the recipe is kept). Negative control: `same` sees one ulp.
    spun = ps.HeavyTop.from_spin(1.0, 0.5, 1.0, 0.8, 6.0, phi_dot=0.4)
    psi_dot = 6.0 - 0.4 * np.cos(0.8)
    stated = ps.HeavyTop(1.0, 0.5, 1.0, 0.8, phi_dot=0.4, psi_dot=psi_dot)
    assert np.allclose(spun.euler_angles(T), stated.euler_angles(T), rtol=1e-9)
    assert same(pickle.loads(pickle.dumps(spun)).euler_angles(T), spun.euler_angles(T))
    assert same(pickle.loads(pickle.dumps(stated)).euler_angles(T), stated.euler_angles(T))
    assert not same(np.array([0.1 + 0.2]), np.array([0.3]))  # one ulp apart


def test_a_dask_task_can_return_them() -> None:
    # Through distributed's wire format (what a task's result becomes between processes), and
    # from a task of an in-process client.
    distributed = pytest.importorskip("distributed")
    from distributed.protocol import deserialize, serialize

    names = ("FreeRigidBody", "FreeSymmetricTop", "HeavyTop", "SpringParticle")
    for name in names:
        make, numbers = CASES[name][-1]
        obj = make()
        twin = deserialize(*serialize(obj, serializers=("dask", "pickle")))
        assert type(twin) is type(obj) and same(numbers(twin), numbers(obj))
    with distributed.Client(
        processes=False, n_workers=1, threads_per_worker=1, dashboard_address=None
    ) as client:
        back = client.gather([client.submit(CASES[n][0][0], pure=False) for n in names])
    assert [type(b).__name__ for b in back] == list(names)
