"""The experiment catalogue's predictions and closed forms come through the public API, never a
formula of their own (the physics lives in crates/poinsot): the named closed forms the entries
call, each against the route it checks, and a scan of the entries' source for arithmetic."""

from __future__ import annotations

import ast
import math
from pathlib import Path

import numpy as np
import poinsot
import pytest
from poinsot import Earth, FreeRigidBody, FreeSymmetricTop, PoinsotError, RigidEarth
from poinsot.free import axis_stability

ENTRIES = Path(poinsot.__file__).parent / "experiments" / "entries"


@pytest.mark.parametrize("path", sorted(ENTRIES.glob("*.py")), ids=lambda p: p.name)
def test_entries_compute_no_physics_of_their_own(path: Path) -> None:
    """No module of math, no 2π/rate, hypot or atan2 in an entry: those are the core's."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    imported = {
        alias.name
        for node in ast.walk(tree)
        if isinstance(node, ast.Import)
        for alias in node.names
    }
    assert not imported & {"math", "cmath", "numpy"}, f"{path.name} imports {imported}"
    called = {
        node.func.attr
        for node in ast.walk(tree)
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
    }
    assert not called & {"hypot", "atan2", "atan", "sqrt", "sin", "cos"}, path.name


def test_rigid_earth_nutation_by_precession() -> None:
    e = RigidEarth()
    direct = e.nutation_amplitudes
    closed = e.nutation_amplitudes_by_precession
    assert closed == pytest.approx(direct, rel=1e-13)
    # The entries' old closed form written out (the Moon's constant read off its part).
    incl, node = math.radians(5.145), 6798.38 * 86400.0
    k = -e.precession_parts[1] / (math.cos(e.obliquity) * (1 - 1.5 * math.sin(incl) ** 2))
    base = k * math.sin(incl) * math.cos(incl) / (2 * math.pi / node)
    eps = e.obliquity
    assert closed[0] == pytest.approx(-base * math.cos(2 * eps) / math.sin(eps), rel=1e-12)
    assert closed[1] == pytest.approx(base * math.cos(eps), rel=1e-12)
    with pytest.raises(PoinsotError, match="obliquity"):
        _ = RigidEarth(obliquity=0.0).nutation_amplitudes_by_precession


def test_earth_closed_forms_match_the_vector_routes() -> None:
    e = Earth()
    lat = np.array([0.0, 0.4, 0.8, -1.1, math.pi / 2])
    c = np.linalg.norm(e.centrifugal_acceleration(lat), axis=-1)
    assert e.centrifugal_magnitude(lat) == pytest.approx(c, rel=1e-15, abs=1e-19)
    assert e.plumb_line_deviation_closed(lat) == pytest.approx(
        e.plumb_line_deviation(lat), abs=1e-16
    )
    assert e.plumb_line_deviation_closed(45, degrees=True) == pytest.approx(
        e.plumb_line_deviation(45, degrees=True), abs=1e-14
    )
    run = e.inertial_oscillation(0.9)
    assert run.measured_period == pytest.approx(2 * math.pi / abs(run.turning_rate), rel=1e-15)
    assert run.measured_period == pytest.approx(run.period, rel=1e-8)
    with pytest.raises(PoinsotError, match="rotation_rate"):
        Earth(rotation_rate=1e160).centrifugal_magnitude(0.3)


def test_free_body_closed_forms() -> None:
    w = [1e-6, 0.0, 1.0]
    top = FreeSymmetricTop(0.99, 1.0, w)
    assert top.precession_period == pytest.approx(2 * math.pi / abs(top.precession_rate))
    assert top.precession_period == pytest.approx(FreeRigidBody([0.99, 0.99, 1.0], w).period)
    with pytest.raises(PoinsotError, match="omega0"):
        _ = FreeSymmetricTop(1.0, 1.0, w).precession_period
    body = FreeRigidBody([1.0, 2.0, 3.0], [0.3, 2.0, -0.5])
    assert body.angular_momentum_magnitude == pytest.approx(
        float(np.linalg.norm(body.angular_momentum)), rel=1e-15
    )
    assert [s.stability for s in body.axis_stability()] == ["stable", "unstable", "stable"]
    mine = [s.rate for s in body.axis_stability()]
    spin = float(np.linalg.norm([0.3, 2.0, -0.5]))
    ref = [s.rate for s in axis_stability([1.0, 2.0, 3.0], spin)]
    assert mine == pytest.approx(ref, rel=1e-15)


def test_public_functions_document_their_parameters_and_returns() -> None:
    """Every public function of poinsot.experiments (and RigidEarth.chandler_period) names each
    of its parameters in its docstring and says what it returns."""
    import inspect

    from poinsot import experiments

    funcs = [getattr(experiments, n) for n in experiments.__all__]
    funcs = [f for f in funcs if inspect.isfunction(f)]
    funcs += [RigidEarth.chandler_period, experiments.Experiment.run]
    assert len(funcs) >= 9
    for f in funcs:
        doc = inspect.getdoc(f) or ""
        for p in inspect.signature(f).parameters:
            if p != "self":
                assert f"``{p}``" in doc, f"{f.__qualname__}: {p}"
        said = doc.lower()
        assert any(w in said for w in ("return", "a tuple", "a list", "a string")), f.__qualname__
