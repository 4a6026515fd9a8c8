"""Builders of templates, so that a template states only its physics choices: the parameter
draws in user units (:func:`draws`), a worked step from a :mod:`poinsot.derive` result
(:func:`derived`) or by hand (:func:`plain`), the derived formula as a second route
(:func:`route`), and the common mistakes every template of a kind shares (:func:`solar_day`,
:func:`scaled`).

A step is written as an equation, ``"x_E [mm] = earth 2.42(omega, height, latitude, g)"``: the
LaTeX symbol, the unit the value is shown in, and the derivation (``topic`` of
:func:`poinsot.derive.derivation`, the result's number, ``[i]`` for one component of a vector)
called with the variant's values (SI) in the order of its symbols.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Any

from ..earth import SOLAR_DAY_RATE
from ._steps import Derived, Mistake, Plain
from ._template import Param

__all__ = ["derived", "draws", "formula", "plain", "prose", "route", "scaled", "solar_day"]

#: ``topic number[component](arg, arg, ...)``: a result of a derivation, called.
_CALL = re.compile(r"(\w+) ([^\[(]+?)(?:\[(\d+)\])?\(([\w, ]*)\)")
#: ``symbol [unit] = rest``: what a step shows (the symbol may be empty).
_EQUATION = re.compile(r"(.*?) ?\[([^\]]*)\] = (.*)", re.S)


def draws(unit: str, /, **ranges: Any) -> tuple[Param, ...]:
    """Parameters drawn in ``unit`` (a unit people use), in the order given: ``name=(low, high,
    step)`` for a value on a grid, ``name=((label, value), ...)`` for one of a few choices (a
    city and its latitude). Parameters in several units are the sum of their ``draws``."""
    out = []
    for name, spec in ranges.items():
        if isinstance(spec[0], tuple):
            out.append(Param(name, unit, choices=tuple(spec)))
        else:
            out.append(Param(name, unit, *spec))
    return tuple(out)


def prose(*parts: str) -> str:
    """A statement written as a paragraph (or several parts) as one line: white space folded,
    the parts joined by a space."""
    return " ".join(" ".join(part.split()) for part in parts)


def _call(call: str, text: str = "", symbol: str = "", unit: str = "") -> Derived:
    m = _CALL.fullmatch(call)
    if m is None:
        raise ValueError(f"call: not 'topic number[i](args)': {call!r}")
    topic, number, component, args = m.groups()
    names = tuple(a.strip() for a in args.split(","))
    index = None if component is None else int(component)
    return Derived(text, topic, number, names, symbol, unit, component=index)


def _equation(equation: str) -> tuple[str, str, str]:
    m = _EQUATION.fullmatch(equation)
    if m is None:
        raise ValueError(f"equation: not 'symbol [unit] = ...': {equation!r}")
    symbol, unit, rest = m.groups()
    return symbol, unit, rest


def derived(text: str, equation: str) -> Derived:
    """A worked step from a derivation: ``derived("Time of fall", "T [s] = earth 2.41(height,
    g)")``."""
    symbol, unit, call = _equation(equation)
    return _call(call, text, symbol, unit)


def formula(call: str) -> Derived:
    """The derived formula ``call`` (``"earth 2.31(omega, R, g, latitude)"``), to evaluate at a
    variant's values (SI)."""
    return _call(call)


def route(call: str) -> Callable[[Any], float]:
    """The derived formula ``call`` (``"earth 2.42(omega, height, latitude, g)"``) at a
    variant's values (SI): a second route to the core's closed form."""
    return _call(call).evaluate


def plain(text: str, equation: str, value: Callable[[Any], float]) -> Plain:
    """A worked step by hand: ``equation`` is ``"symbol [unit] = formula"`` (the formula in
    LaTeX with ``{name}`` for the variant's numbers), ``value`` the value it gives (SI)."""
    symbol, unit, formula = _equation(equation)
    return Plain(text, formula, value, unit, symbol)


def solar_day(
    step: int, at_rate: Callable[[Any, float], float], text: str = "used the solar day for ω"
) -> Mistake:
    """The solar day 2π/86400 s taken for the Earth's rate: ``at_rate(values, rate)`` is the
    answer (SI) with the Earth turning at ``rate``."""
    return Mistake("solar day", text, step, lambda v: at_rate(v, SOLAR_DAY_RATE))


def scaled(name: str, text: str, step: int, answer: Callable[[Any], float], by: float) -> Mistake:
    """A mistake whose wrong answer is the right one times ``by`` (a unit mixed up, a factor
    left out)."""
    return Mistake(name, text, step, lambda v: answer(v) * by)
