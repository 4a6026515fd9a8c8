"""Defaults once (issue 22): every default of a public signature is the core's.

``poinsot._core.DEFAULTS`` (crates/poinsot-py/src/defaults.rs, every value from the core's
``poinsot::defaults``) holds, by call and argument, the default of every argument of the public
calls that has one; a default of ``None`` (absent) or a flag (``True``/``False``) is not a number
and is not listed. These tests hold every public function and method (``poinsot.__all__``,
``poinsot.special``, ``poinsot.sweep``) to that table: a default restated with another value, a
new default the core does not state, or a table entry no signature has, fails.
"""

from __future__ import annotations

import dataclasses
import inspect
import types
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import poinsot
import pytest
from poinsot import _core, special, sweep

#: Result records: the library builds them from the core's results (their fields are data, not
#: options), so their constructors' field defaults are not options of a call.
RECORDS = {"Fall", "FoucaultRun", "InertialOscillation", "LowFlow"}


def _public() -> Iterator[tuple[str, Callable[..., Any]]]:
    """(the table's key, the callable) for every public function and method."""
    for prefix, module in (("", poinsot), ("special.", special), ("sweep.", sweep)):
        for name in module.__all__:
            obj = getattr(module, name)
            if inspect.isclass(obj):
                if obj.__name__ in RECORDS or issubclass(obj, BaseException):
                    continue
                for attr, value in vars(obj).items():
                    if attr.startswith("_") and attr != "__init__":
                        continue
                    if isinstance(value, (classmethod, staticmethod)):
                        value = value.__func__
                    if callable(value) and not isinstance(value, type):
                        yield f"{prefix}{obj.__name__}.{attr}", value
            elif callable(obj):
                yield f"{prefix}{name}", obj


def _defaults(fn: Callable[..., Any]) -> dict[str, Any]:
    """The signature's defaults that are values (not None, not a flag)."""
    try:
        sig = inspect.signature(fn)
    except (TypeError, ValueError):  # a builtin without a text signature: no defaults
        return {}
    out = {}
    for name, p in sig.parameters.items():
        d = p.default
        if d is inspect.Parameter.empty or d is None or isinstance(d, bool):
            continue
        if d is dataclasses.MISSING:
            continue
        out[name] = d
    return out


def _same(a: Any, b: Any) -> bool:
    """Equal values of the same type (an int 1001 is not the float 1001.0)."""
    if isinstance(a, tuple) and isinstance(b, tuple):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b))
    return type(a) is type(b) and a == b


def mismatches(key: str, fn: Callable[..., Any], table: dict[str, dict[str, Any]]) -> list[str]:
    """What differs between ``fn``'s signature defaults and ``table[key]`` (empty if nothing)."""
    got = _defaults(fn)
    want = table.get(key, {})
    out = []
    for name in sorted(set(got) | set(want)):
        if name not in want:
            out.append(f"{key}({name}={got[name]!r}): a default the core does not state")
        elif name not in got:
            out.append(f"{key}: the core's default {name}={want[name]!r} is not in the signature")
        elif not _same(got[name], want[name]):
            out.append(f"{key}({name}={got[name]!r}): the core's default is {want[name]!r}")
    return out


PUBLIC = dict(_public())


@pytest.mark.parametrize("key", sorted(PUBLIC))
def test_every_public_default_is_the_cores(key):
    assert mismatches(key, PUBLIC[key], _core.DEFAULTS) == []


def test_every_entry_of_the_table_is_a_public_call():
    assert sorted(set(_core.DEFAULTS) - set(PUBLIC)) == []


def test_the_table_holds_the_documented_numbers():
    # A few values as the docs state them, so that the table is not compared with itself only.
    d = _core.DEFAULTS
    assert (d["simulate"]["samples"], d["simulate"]["rtol"], d["simulate"]["atol"]) == (
        1001,
        1e-10,
        1e-12,
    )
    assert d["simulate"]["max_steps"] == poinsot.DEFAULT_MAX_STEPS == 10**8
    assert d["RigidBody.from_density"] == {"rtol": 1e-6, "atol": 0.0, "max_evals": 10_000_000}
    assert d["Earth.__init__"]["rotation_rate"] == poinsot.SIDEREAL_RATE
    assert d["classify"]["rtol"] == poinsot.DEFAULT_KIND_RTOL == 1e-9
    assert d["check_rotation_matrix"]["tol"] == 1e-9


def _with_kwdefaults(fn: Callable[..., Any], **changed: Any) -> Callable[..., Any]:
    """A copy of ``fn`` with some keyword-only defaults changed."""
    copy = types.FunctionType(
        fn.__code__, fn.__globals__, fn.__name__, fn.__defaults__, fn.__closure__
    )
    copy.__kwdefaults__ = {**(fn.__kwdefaults__ or {}), **changed}
    return copy


def test_negative_control_a_restated_default_that_differs_is_caught():
    fn = inspect.unwrap(poinsot.simulate)
    assert mismatches("simulate", fn, _core.DEFAULTS) == []
    wrong = _with_kwdefaults(fn, samples=1000)
    assert mismatches("simulate", wrong, _core.DEFAULTS) == [
        "simulate(samples=1000): the core's default is 1001"
    ]
    # The same number of another type, and a tolerance one ulp off.
    assert mismatches("simulate", _with_kwdefaults(fn, samples=1001.0), _core.DEFAULTS)
    assert mismatches("simulate", _with_kwdefaults(fn, rtol=1e-10 * (1 + 2**-52)), _core.DEFAULTS)


def test_negative_control_a_default_the_core_does_not_state_is_caught():
    def f(x: float, *, samples: int = 5, flag: bool = False, out: Any = None) -> None: ...

    assert mismatches("f", f, _core.DEFAULTS) == ["f(samples=5): a default the core does not state"]
    assert mismatches("f", f, {"f": {"samples": 5, "rtol": 1.0}}) == [
        "f: the core's default rtol=1.0 is not in the signature"
    ]


#: The command-line options that mean an argument of the API: (command, option) -> (call, argument).
CLI = {
    ("fall", "gravity"): ("Earth.drop", "gravity"),
    ("projectile", "height"): ("Earth.projectile", "height"),
    ("foucault", "length"): ("Earth.foucault", "length"),
    ("foucault", "amplitude"): ("Earth.foucault", "amplitude"),
    ("foucault", "duration"): ("Earth.foucault", "duration"),
    ("free", "method"): ("simulate", "method"),
    ("top", "theta_dot"): ("HeavyTop.__init__", "theta_dot"),
    ("top", "phi_dot"): ("HeavyTop.__init__", "phi_dot"),
    ("top", "psi_dot"): ("HeavyTop.__init__", "psi_dot"),
}


@pytest.mark.parametrize(("command", "option"), sorted(CLI))
def test_the_command_line_defaults_are_the_cores(command, option):
    from poinsot.cli import main

    param = next(p for p in main.commands[command].params if p.name == option)
    call, argument = CLI[command, option]
    assert _same(param.default, _core.DEFAULTS[call][argument]), (param.default, call, argument)


def _stub_rows() -> dict[str, set[str]]:
    """The arguments of each call as _core.pyi types DEFAULTS (its TypedDicts)."""
    import ast

    tree = ast.parse((Path(_core.__file__).parent / "_core.pyi").read_text(encoding="utf-8"))
    classes: dict[str, ast.ClassDef] = {n.name: n for n in tree.body if isinstance(n, ast.ClassDef)}

    def fields(name: str) -> set[str]:
        cls = classes[name]
        own = {s.target.id for s in cls.body if isinstance(s, ast.AnnAssign)}  # type: ignore[union-attr]
        for base in cls.bases:
            if isinstance(base, ast.Name) and base.id in classes:
                own |= fields(base.id)
        return own

    for node in tree.body:
        if (
            isinstance(node, ast.Assign)
            and isinstance(node.targets[0], ast.Name)
            and node.targets[0].id == "_Defaults"
        ):
            table = node.value.args[1]  # type: ignore[attr-defined]
            return {k.value: fields(v.id) for k, v in zip(table.keys, table.values)}
    raise AssertionError("_core.pyi has no _Defaults")


def test_the_stub_types_every_row_of_the_table():
    assert _stub_rows() == {call: set(row) for call, row in _core.DEFAULTS.items()}
