"""The parts of a template's worked solution and its known mistakes: :class:`SolutionStep` (a
step as shown), :class:`Derived` (a result of :mod:`poinsot.derive` with the variant's numbers:
also a second route), :class:`Plain` (a step without a derivation) and :class:`Mistake`."""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass
from functools import cache
from typing import Any

import numpy as np
import sympy as sp

from ._text import UNITS, number_latex, number_symbol, si_factor, sig

__all__ = ["Derived", "Mistake", "Plain", "SolutionStep"]


@dataclass(frozen=True)
class SolutionStep:
    """One step of a worked solution: a sentence, its equation in LaTeX (the body of an amsmath
    ``aligned`` block: lines joined by ``\\\\``, aligned at ``&=``; the numbers substituted;
    empty where there is none), and the value it gives in ``unit``."""

    text: str
    latex: str
    value: float | None = None
    unit: str = ""

    def plain(self) -> str:
        """The step as one line of text."""
        tail = (
            f" = {sig(self.value)} {UNITS[self.unit][0]}".rstrip() if self.value is not None else ""
        )
        return self.text + tail


@dataclass(frozen=True)
class Plain:
    """A worked step where no derivation of :mod:`poinsot.derive` gives the formula: a sentence,
    its formula in LaTeX with ``{name}`` placeholders (the variant's numbers in SI), and the
    value (SI) it gives, shown in ``unit``."""

    text: str
    formula: str
    value: Callable[[Any], float]
    unit: str = ""
    symbol: str = ""

    def solve(self, v: Any) -> SolutionStep:
        value = float(self.value(v)) / si_factor(self.unit)
        numbers = {k: number_latex(x, True) for k, x in vars(v).items() if isinstance(x, float)}
        tex = self.formula.format(**numbers)
        if self.symbol:
            tex = f"{self.symbol} &= {tex} = {number_latex(value)}\\,{UNITS[self.unit][1]}"
        return SolutionStep(self.text, tex, value, self.unit)


@dataclass(frozen=True)
class Derived:
    """A worked step whose formula is a result of a :mod:`poinsot.derive` derivation (``topic``,
    the unit's equation ``number``), evaluated with the variant's numbers: ``args`` name the
    variant's values (SI) in the order of the derivation's symbols; ``component`` picks one of a
    vector result; the value is shown in ``unit`` with the LaTeX ``symbol``."""

    text: str
    topic: str
    number: str
    args: tuple[str, ...]
    symbol: str
    unit: str = ""
    component: int | None = None

    def formula(self) -> tuple[Any, tuple[Any, ...]]:
        """The derived expression (the component asked for) and its symbols (sympy)."""
        expr, symbols, _ = _derived(self.topic, self.number, self.component)
        return expr, symbols

    def evaluate(self, v: Any) -> float:
        """The derived formula at the variant's values (SI): the derive-substituted route."""
        _, _, f = _derived(self.topic, self.number, self.component)
        return float(f(*(getattr(v, a) for a in self.args)))

    def evaluate_vector(self, v: Any) -> list[float]:
        """A vector result at the variant's values (SI), as a list."""
        _, _, f = _derived(self.topic, self.number, None)
        return [float(x) for x in np.asarray(f(*(getattr(v, a) for a in self.args))).ravel()]

    def solve(self, v: Any) -> SolutionStep:
        expr, symbols = self.formula()
        value = self.evaluate(v) / si_factor(self.unit)
        numbers = {s: number_symbol(getattr(v, a)) for s, a in zip(symbols, self.args)}
        substituted = sp.latex(_substituted(expr, numbers), order="none", mul_symbol="dot")
        tex = (  # the formula, the numbers substituted, the value: one line each
            f"{self.symbol} &= {sp.latex(expr)} \\\\ &= {substituted}"
            f" \\\\ &= {number_latex(value)}\\,{UNITS[self.unit][1]}"
        )
        where = (
            f"the unit's eq. {self.number}"
            if re.fullmatch(r"\d+\.\d+", self.number)
            else f"result {self.number!r}"
        )
        text = f"{self.text} ({where}, poinsot.derive '{self.topic}')"
        return SolutionStep(text, tex, value, self.unit)


def _substituted(expr: Any, numbers: dict[Any, Any]) -> Any:
    """``expr`` with ``numbers`` put for its symbols, unevaluated: each product's factors and
    each sum's terms in the order the formula is printed in (the numbers beside the symbols they
    stand for: ``I₁ω₁ω̇₁`` as ``0.026 · 10 · 0.5``, not in the order of the numbers' digits)."""
    if expr in numbers:
        return numbers[expr]
    if not expr.args:
        return expr
    if expr.is_Mul:
        coefficient, _ = expr.as_coeff_mul()
        factors = [f for f in expr.as_ordered_factors() if not f.is_Number]
        args = ([coefficient] if coefficient != 1 else []) + factors
    elif expr.is_Add:
        args = expr.as_ordered_terms()
    else:
        args = list(expr.args)
    with sp.evaluate(False):
        return expr.func(*(_substituted(a, numbers) for a in args))


@cache
def _derived(topic: str, number: str, component: int | None) -> tuple[Any, tuple[Any, ...], Any]:
    """The result ``number`` of the derivation ``topic``: (expression, symbols, its numpy
    function), built once per process."""
    from .. import derive

    expr, symbols = derive.derivation(topic).functions[number]
    if component is not None:
        expr = expr[component]
    return expr, symbols, sp.lambdify(symbols, expr, "numpy")


@dataclass(frozen=True)
class Mistake:
    """A common mistake: what it is (``text``), the step of the worked solution to look at
    (1-based), and the wrong answer it produces (SI) from the variant's values."""

    name: str
    text: str
    step: int
    wrong: Callable[[Any], float]
