"""The machinery of :mod:`poinsot.exercises`: a :class:`Template` (parameters drawn from a seeded
generator, a statement, an answer by two routes, worked steps, known mistakes), the
:class:`Variant` it issues, and the registry of templates.

A variant is issued only when its two routes agree to the template's ``agree`` (relative): a draw
whose routes disagree is drawn again (at most :data:`MAX_REDRAWS` times), then the template is
refused with a :class:`~poinsot.PoinsotError` naming it. The tolerance a student's answer is
graded with comes from the answer's conditioning: how far the answer moves when every input is
carried to :data:`CARRIED_DIGITS` significant figures (at least :data:`ANSWER_RTOL` of the
answer).
"""

from __future__ import annotations

import math
import re
import zlib
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cache
from types import SimpleNamespace
from typing import Any

import numpy as np
import pint
import sympy as sp

from ..errors import PoinsotError

__all__ = [
    "ANSWER_RTOL",
    "CARRIED_DIGITS",
    "MAX_REDRAWS",
    "Derived",
    "Mistake",
    "Param",
    "Plain",
    "SolutionStep",
    "Template",
    "Variant",
    "register",
    "registry",
    "variant_seed",
]

#: Draws tried for one variant before its template is refused (two routes that disagree).
MAX_REDRAWS = 20
#: Significant figures a student is expected to carry through the working.
CARRIED_DIGITS = 4
#: The least relative tolerance of a graded answer (half a unit of the 4th significant figure
#: of a number near 5000 is 1e-4; one per mille leaves room for honest rounding, and still tells
#: the solar day from the sidereal one, 2.7e-3 apart).
ANSWER_RTOL = 1e-3
#: The largest relative tolerance a variant may need: a draw whose answer is more sensitive to
#: its inputs' rounding (a near-cancellation, an answer near zero) is drawn again.
MAX_RTOL = 0.02
#: Relative change of each input when the answer's conditioning is measured.
_CARRY = 0.5 * 10.0 ** (1 - CARRIED_DIGITS)

ureg: pint.UnitRegistry = pint.UnitRegistry()

#: How each unit is printed: pint's spelling → (plain text, LaTeX math).
UNITS: dict[str, tuple[str, str]] = {
    "m": ("m", r"\mathrm{m}"),
    "cm": ("cm", r"\mathrm{cm}"),
    "mm": ("mm", r"\mathrm{mm}"),
    "um": ("µm", r"\mu\mathrm{m}"),
    "km": ("km", r"\mathrm{km}"),
    "g": ("g", r"\mathrm{g}"),
    "kg": ("kg", r"\mathrm{kg}"),
    "tonne": ("t", r"\mathrm{t}"),
    "deg": ("°", r"^\circ"),
    "arcmin": ("′", r"'"),
    "rad": ("rad", r"\mathrm{rad}"),
    "rpm": ("rpm", r"\mathrm{rpm}"),
    "rad/s": ("rad/s", r"\mathrm{rad/s}"),
    "deg/s": ("°/s", r"^\circ/\mathrm{s}"),
    "km/h": ("km/h", r"\mathrm{km/h}"),
    "m/s": ("m/s", r"\mathrm{m/s}"),
    "m/s**2": ("m/s²", r"\mathrm{m/s^2}"),
    "s": ("s", r"\mathrm{s}"),
    "min": ("min", r"\mathrm{min}"),
    "h": ("h", r"\mathrm{h}"),
    "N": ("N", r"\mathrm{N}"),
    "kN": ("kN", r"\mathrm{kN}"),
    "N*m": ("N·m", r"\mathrm{N\,m}"),
    "mN*m": ("mN·m", r"\mathrm{mN\,m}"),
    "J": ("J", r"\mathrm{J}"),
    "mJ": ("mJ", r"\mathrm{mJ}"),
    "kg*m**2": ("kg·m²", r"\mathrm{kg\,m^2}"),
    "kg*cm**2": ("kg·cm²", r"\mathrm{kg\,cm^2}"),
    "g*cm**2": ("g·cm²", r"\mathrm{g\,cm^2}"),
    "kg*m**2/s": ("kg·m²/s", r"\mathrm{kg\,m^2/s}"),
    "": ("", ""),
}


def si_factor(unit: str) -> float:
    """The SI value of one ``unit`` (``"cm"`` → 0.01, ``"rpm"`` → 2π/60, ``"deg"`` → π/180)."""
    if unit == "":
        return 1.0
    return float(ureg.Quantity(1.0, unit).to_base_units().magnitude)


def shown(value: float, unit: str, latex: bool = False) -> str:
    """``value`` (in ``unit``) with its unit, as printed in a statement."""
    plain, tex = UNITS[unit]
    number = _number(value)
    if latex:
        return f"${number}\\,{tex}$" if tex and not tex.startswith("^") else f"${number}{tex}$"
    return f"{number}{plain}" if plain in ("°", "′") else f"{number} {plain}".rstrip()


def _number(value: float) -> str:
    """A number printed exactly as drawn (a grid value): no trailing zeros, no exponent."""
    text = f"{value:.6f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def sig(value: float, digits: int = CARRIED_DIGITS) -> str:
    """``value`` to ``digits`` significant figures (for answers and worked steps)."""
    return f"{value:.{digits}g}"


# ---- a template's parts ---------------------------------------------------------------------------


@dataclass(frozen=True)
class Param:
    """A parameter drawn for each variant, on a grid in a unit people use.

    ``name`` is the key of the value (in SI) the routes read; the value is ``low + k·step``
    (``k`` drawn uniformly), in ``unit`` (pint's spelling, a key of :data:`UNITS`). With
    ``choices`` (label, value in ``unit``) one of them is drawn instead (a city and its
    latitude); ``{name@}`` in a statement prints the label."""

    name: str
    unit: str
    low: float = 0.0
    high: float = 0.0
    step: float = 1.0
    choices: tuple[tuple[str, float], ...] = ()

    def draw(self, rng: np.random.Generator) -> tuple[float, str]:
        """(value in ``unit``, label) drawn from ``rng``."""
        if self.choices:
            label, value = self.choices[int(rng.integers(len(self.choices)))]
            return float(value), label
        count = round((self.high - self.low) / self.step)
        value = self.low + self.step * int(rng.integers(count + 1))
        return float(round(value, 9)), ""


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
        numbers = {s: _number_symbol(getattr(v, a)) for s, a in zip(symbols, self.args)}
        tex = (  # the formula, the numbers substituted, the value: one line each
            f"{self.symbol} &= {sp.latex(expr)} \\\\ &= {sp.latex(expr.xreplace(numbers))}"
            f" \\\\ &= {number_latex(value)}\\,{UNITS[self.unit][1]}"
        )
        where = (
            f"the unit's eq. {self.number}"
            if re.fullmatch(r"\d+\.\d+", self.number)
            else f"result {self.number!r}"
        )
        text = f"{self.text} ({where}, poinsot.derive '{self.topic}')"
        return SolutionStep(text, tex, value, self.unit)


class _Number(sp.Symbol):
    """A number shown in a worked step: a sympy atom whose name is its LaTeX."""

    def _latex(self, printer: Any) -> str:
        return self.name


def number_latex(value: float, grouped: bool = False) -> str:
    """``value`` to :data:`CARRIED_DIGITS` figures in LaTeX (``7.292 \\cdot 10^{-5}``); with
    ``grouped``, in parentheses where it has a power of ten or a sign (a factor or a base)."""
    text = sig(value)
    mantissa, _, exponent = text.partition("e")
    if exponent:
        text = f"{mantissa} \\cdot 10^{{{int(exponent)}}}"
    if grouped and (exponent or value < 0):
        text = f"\\left({text}\\right)"
    return text


def _number_symbol(value: float) -> Any:
    """``value`` as a sympy atom that prints as :func:`number_latex` (grouped: a square of it
    is ``(7.292 \\cdot 10^{-5})^{2}``, not a double superscript)."""
    return _Number(number_latex(value, grouped=True))


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


# ---- the template -----------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class Template:
    """A problem with seeded variants.

    Attributes
    ----------
    name:
        Kebab-case (``"dropped-ball"``), what ``poinsot check`` takes.
    topic:
        One of :data:`poinsot.exercises.TOPICS`.
    difficulty:
        1 (one formula), 2 (two or three steps), 3 (a chain of reasoning).
    title:
        A short title.
    params:
        The drawn parameters (:class:`Param`).
    text:
        The statement, Unicode; ``{name}`` prints a parameter with its unit, ``{name@}`` the
        label of a choice.
    question:
        The quantity asked for, in words, ending with the unit the answer is wanted in.
    unit:
        The unit of the answer (pint's spelling, a key of :data:`UNITS`).
    answer:
        Values (SI, as attributes) → the answer (SI) through poinsot's public API.
    check:
        The second, independent route (closed form vs integration, exact vs derived formula).
    agree:
        The relative difference of the two routes a variant may have (with the reason in
        ``agree_why``).
    steps:
        The worked solution (:class:`Derived` or :class:`Plain`).
    mistakes:
        The common mistakes (:class:`Mistake`).
    constants:
        Values every variant shares (SI): ``omega`` (the Earth's rate), ``g``, ...
    extra:
        Values (SI) → more named values the steps use (``mgl``, ``p_psi``).
    answer_range:
        (low, high) of the answer in ``unit``, for the tests' range check.
    max_rtol:
        The largest tolerance relative to the answer a variant may need (ill-conditioned
        draws are drawn again).
    source:
        A published problem this template reproduces, if any.
    """

    name: str
    topic: str
    difficulty: int
    title: str
    params: tuple[Param, ...]
    text: str
    question: str
    unit: str
    answer: Callable[[Any], float]
    check: Callable[[Any], float]
    agree: float
    agree_why: str
    steps: tuple[Derived | Plain, ...] = ()
    mistakes: tuple[Mistake, ...] = ()
    constants: Mapping[str, float] = field(default_factory=dict)
    extra: Callable[[Any], Mapping[str, float]] | None = None
    answer_range: tuple[float, float] = (-math.inf, math.inf)
    max_rtol: float = MAX_RTOL
    source: str = ""

    def __repr__(self) -> str:
        return (
            f"Template({self.name!r}, topic={self.topic!r}, difficulty={self.difficulty}, "
            f"unit={self.unit!r})"
        )

    def __reduce__(self) -> tuple[Any, tuple[str]]:
        """A registered template pickles by its name (its routes are functions)."""
        if _REGISTRY.get(self.name) is not self:
            raise TypeError(f"template {self.name!r} is not registered: it pickles by name only")
        return _registered, (self.name,)

    # -- drawing -------------------------------------------------------------------------------

    def values(self, drawn: Mapping[str, float]) -> SimpleNamespace:
        """The namespace the routes read: each parameter in SI (``drawn`` in its unit), the
        constants and the extra values."""
        v = SimpleNamespace(**self.constants)
        for p in self.params:
            setattr(v, p.name, float(drawn[p.name]) * si_factor(p.unit))
        if self.extra is not None:
            for k, x in self.extra(v).items():
                setattr(v, k, float(x))
        return v

    def variant(self, seed: int) -> Variant:
        """The variant of ``seed`` (a non-negative integer): drawn from
        ``numpy.random.default_rng([seed, attempt])`` (PCG64, the same on every machine), the
        first draw whose two routes agree. Raises :class:`PoinsotError` naming the template
        when :data:`MAX_REDRAWS` draws all disagree."""
        seed = _seed(seed, "seed")
        worst = ""
        for attempt in range(MAX_REDRAWS):
            rng = np.random.default_rng([seed, attempt])
            drawn: dict[str, float] = {}
            labels: dict[str, str] = {}
            for p in self.params:
                drawn[p.name], labels[p.name] = p.draw(rng)
            try:
                v = self.values(drawn)
                a, b = float(self.answer(v)), float(self.check(v))
            except PoinsotError as exc:  # a draw the API refuses: draw again
                worst = f"the API refused a draw ({exc})"
                continue
            scale = max(abs(a), abs(b))
            if math.isfinite(a) and math.isfinite(b) and abs(a - b) <= self.agree * scale:
                tolerance = self.tolerance(v, a)
                if 0 < tolerance <= self.max_rtol * abs(a):  # finite, and an answer can be graded
                    return Variant(self, seed, drawn, labels, v, a, b, tolerance)
                worst = f"ill-conditioned: tolerance {tolerance:.3g} of answer {a:.3g}"
                continue
            worst = f"answer {a!r}, second route {b!r} (seed {seed}, draw {attempt})"
        raise PoinsotError(
            f"template: {self.name!r} issued no variant in {MAX_REDRAWS} draws: its two routes "
            f"disagreed beyond {self.agree:g} (relative) or the API refused; last: {worst}"
        )

    def fixed(
        self, seed: int = 0, labels: Mapping[str, str] | None = None, **drawn: float
    ) -> Variant:
        """The variant with the parameters ``drawn`` (each in its unit; a published problem
        reproduced), checked by both routes like a drawn one: :class:`PoinsotError` naming the
        template when they disagree, naming a parameter that is missing or unknown."""
        names = {p.name for p in self.params}
        for key in set(drawn) ^ names:
            raise PoinsotError(
                f"{key}: {'not a parameter' if key in drawn else 'missing'} of {self.name!r}"
            )
        v = self.values(drawn)
        a, b = float(self.answer(v)), float(self.check(v))
        if not (math.isfinite(a) and abs(a - b) <= self.agree * max(abs(a), abs(b))):
            raise PoinsotError(f"template: {self.name!r}: its two routes disagree: {a!r}, {b!r}")
        chosen = {p.name: (labels or {}).get(p.name, "") for p in self.params}
        return Variant(
            self, _seed(seed, "seed"), dict(drawn), chosen, v, a, b, self.tolerance(v, a)
        )

    def tolerance(self, v: SimpleNamespace, answer_si: float) -> float:
        """The tolerance (SI, absolute) of a graded answer: the answer's spread (root sum of
        squares) when each input is carried to :data:`CARRIED_DIGITS` figures, at least
        :data:`ANSWER_RTOL` of the answer."""
        spread = 0.0
        for p in self.params:
            for carry in (_CARRY, -_CARRY):  # inwards where the outward move leaves the domain
                moved = SimpleNamespace(**vars(v))
                setattr(moved, p.name, getattr(v, p.name) * (1.0 + carry))
                if self.extra is not None:
                    for k, x in self.extra(moved).items():
                        setattr(moved, k, float(x))
                try:
                    spread += (float(self.answer(moved)) - answer_si) ** 2
                    break
                except PoinsotError:
                    continue
        return max(ANSWER_RTOL * abs(answer_si), math.sqrt(spread))

    # -- the statement ----------------------------------------------------------------------------

    def statement(self, drawn: Mapping[str, float], labels: Mapping[str, str], latex: bool) -> str:
        """The statement with the drawn numbers (plain Unicode, or LaTeX)."""
        units = {p.name: p.unit for p in self.params}

        def fill(m: re.Match[str]) -> str:
            name, at = m.group(1), m.group(2)
            if at:
                return labels[name]
            return shown(drawn[name], units[name], latex)

        parts = re.split(r"(\{\w+@?\})", self.text + " " + self.question)
        return "".join(
            fill(m)
            if (m := re.fullmatch(r"\{(\w+)(@?)\}", part))
            else (latex_text(part) if latex else part)
            for part in parts
        )


def _seed(value: Any, name: str) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 0:
        raise PoinsotError(f"{name}: must be a non-negative integer, got {value!r}")
    return int(value)


def variant_seed(seed: int, template: str, index: int) -> int:
    """The seed of variant ``index`` of ``template`` in a set made with ``seed``: a 32-bit
    number from numpy's ``SeedSequence`` of (seed, CRC-32 of the name, index), the same on
    every machine; it is what a student gives ``poinsot check --seed``."""
    entropy = [_seed(seed, "seed"), zlib.crc32(template.encode()), _seed(index, "index")]
    return int(np.random.SeedSequence(entropy).generate_state(1, np.uint32)[0])


# ---- the issued variant ----------------------------------------------------------------------------


@dataclass
class Variant:
    """A variant of a template, issued: its numbers agree by both routes.

    ``drawn`` (each parameter in its unit), ``labels`` (the labels of choices), ``values`` (SI,
    what the routes read), ``answer_si`` and ``check_si`` (the two routes, SI),
    ``tolerance_si`` (the accepted absolute error, SI). ``steps`` and ``mistakes`` are worked
    out when read."""

    template: Template
    seed: int
    drawn: dict[str, float]
    labels: dict[str, str]
    values: SimpleNamespace
    answer_si: float
    check_si: float
    tolerance_si: float

    def __repr__(self) -> str:
        return (
            f"Variant({self.name!r}, seed={self.seed}, answer={self.answer:.6g} {self.unit}, "
            f"tolerance={self.tolerance:.3g})"
        )

    @property
    def name(self) -> str:
        """The template's name."""
        return self.template.name

    @property
    def unit(self) -> str:
        """The unit of :attr:`answer`."""
        return self.template.unit

    @property
    def answer(self) -> float:
        """The answer in :attr:`unit`."""
        return self.answer_si / si_factor(self.unit)

    @property
    def tolerance(self) -> float:
        """The accepted absolute error of an answer, in :attr:`unit`."""
        return self.tolerance_si / si_factor(self.unit)

    @property
    def statement(self) -> str:
        """The statement, plain Unicode."""
        return self.template.statement(self.drawn, self.labels, latex=False)

    @property
    def latex(self) -> str:
        """The statement in LaTeX (text mode)."""
        return self.template.statement(self.drawn, self.labels, latex=True)

    @property
    def steps(self) -> list[SolutionStep]:
        """The worked solution: the data in SI, then the template's steps with this variant's
        numbers (from :mod:`poinsot.derive` where a derivation exists)."""
        data = ", ".join(
            f"{p.name} = {sig(getattr(self.values, p.name))} {UNITS[_si_unit(p.unit)][0]}".rstrip()
            for p in self.template.params
        )
        first = SolutionStep(f"The data in SI units: {data}.", "")
        return [first, *(s.solve(self.values) for s in self.template.steps)]

    @property
    def mistakes(self) -> list[tuple[Mistake, float]]:
        """The template's common mistakes with the wrong answer each gives (in :attr:`unit`),
        those that an answer can be told from the right one by (outside the tolerance)."""
        out = []
        for m in self.template.mistakes:
            try:
                wrong = float(m.wrong(self.values)) / si_factor(self.unit)
            except (PoinsotError, ValueError, ZeroDivisionError):
                continue
            if math.isfinite(wrong) and abs(wrong - self.answer) > self.tolerance:
                out.append((m, wrong))
        return out

    def to_dict(self) -> dict[str, Any]:
        """The variant as plain JSON values."""
        return {
            "template": self.name,
            "seed": self.seed,
            "topic": self.template.topic,
            "difficulty": self.template.difficulty,
            "title": self.template.title,
            "statement": self.statement,
            "statement_latex": self.latex,
            "parameters": {
                p.name: {"value": self.drawn[p.name], "unit": p.unit}
                | ({"label": self.labels[p.name]} if self.labels[p.name] else {})
                for p in self.template.params
            },
            "answer": self.answer,
            "unit": self.unit,
            "tolerance": self.tolerance,
            "second_route": self.check_si / si_factor(self.unit),
            "solution": [
                {"text": s.text, "latex": s.latex, "value": s.value, "unit": s.unit}
                for s in self.steps
            ],
            "common_mistakes": [
                {"name": m.name, "text": m.text, "step": m.step, "wrong_answer": w}
                for m, w in self.mistakes
            ],
        }


def _si_unit(unit: str) -> str:
    """The SI unit (a key of :data:`UNITS`) of values given in ``unit``."""
    base = str(ureg.Quantity(1.0, unit).to_base_units().units) if unit else ""
    return {
        "meter": "m",
        "kilogram": "kg",
        "radian": "rad",
        "radian / second": "rad/s",
        "meter / second": "m/s",
        "second": "s",
        "kilogram * meter ** 2": "kg*m**2",
        "dimensionless": "",
    }.get(base, "")


# ---- LaTeX text ------------------------------------------------------------------------------------

_GREEK = dict(
    zip(
        "αβγδεθλμνπρστφχψωΩΦΨΘΛΔΣ",
        [
            r"\alpha",
            r"\beta",
            r"\gamma",
            r"\delta",
            r"\varepsilon",
            r"\theta",
            r"\lambda",
            r"\mu",
            r"\nu",
            r"\pi",
            r"\rho",
            r"\sigma",
            r"\tau",
            r"\phi",
            r"\chi",
            r"\psi",
            r"\omega",
            r"\Omega",
            r"\Phi",
            r"\Psi",
            r"\Theta",
            r"\Lambda",
            r"\Delta",
            r"\Sigma",
        ],
    )
)
_SUB = dict(zip("₀₁₂₃₄₅₆₇₈₉", "0123456789"))
_SUP = dict(zip("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789"))
_POWER = re.compile("([" + "".join(_SUP) + "]+)")
_LETTER = "[A-Za-z" + "".join(_GREEK) + "]"
_DOTTED = re.compile(f"({_LETTER})\u0307([₀-₉]*)")
_SYMBOL = re.compile(f"({_LETTER})([₀-₉]+)|([" + "".join(_GREEK) + "])")
#: Other Unicode of the statements and steps, as LaTeX (pdflatex's utf8 input knows none of it).
_OTHER = {
    "°": r"$^\circ$",
    "′": "'",
    "−": "$-$",
    "×": r"$\times$",
    "≈": r"$\approx$",
    "½": r"$\frac12$",
    "⅓": r"$\frac13$",
    "¾": r"$\frac34$",
    "↔": r"$\leftrightarrow$",
    "→": r"$\to$",
    "µ": r"$\mu$",
    "√": r"$\surd$",
    "≤": r"$\le$",
    "≥": r"$\ge$",
    "§": r"\S{}",
}


def _sub(digits: str) -> str:
    return f"_{{{''.join(_SUB[c] for c in digits)}}}" if digits else ""


def latex_text(text: str) -> str:
    """Unicode statement text as LaTeX text: specials escaped, Greek letters, dotted and
    subscripted symbols (I₁, θ₀, ω̇₁) set in math, powers (10⁻⁵), ° and the other signs of
    :data:`_OTHER` as LaTeX."""
    for a, b in (("\\", r"\textbackslash{}"), ("%", r"\%"), ("&", r"\&"), ("#", r"\#")):
        text = text.replace(a, b)
    text = text.replace("_", r"\_").replace("²", r"$^2$").replace("·", r"$\cdot$")

    def dotted(m: re.Match[str]) -> str:
        return r"$\dot{" + _GREEK.get(m.group(1), m.group(1)) + "}" + _sub(m.group(2)) + "$"

    def symbol(m: re.Match[str]) -> str:
        if m.group(3):
            return f"${_GREEK[m.group(3)]}$"
        return f"${_GREEK.get(m.group(1), m.group(1))}{_sub(m.group(2))}$"

    text = _DOTTED.sub(dotted, text)
    text = _SYMBOL.sub(symbol, text)
    text = _POWER.sub(lambda m: "$^{" + "".join(_SUP[c] for c in m.group(1)) + "}$", text)
    for a, b in _OTHER.items():
        text = text.replace(a, b)
    return text


# ---- the registry ------------------------------------------------------------------------------

_REGISTRY: dict[str, Template] = {}


def register(*templates: Template) -> None:
    """Adds ``templates`` to the registry (a name is registered once)."""
    for t in templates:
        if t.name in _REGISTRY:
            raise PoinsotError(f"template: {t.name!r} registered twice")
        _REGISTRY[t.name] = t


def _registered(name: str) -> Template:
    return _REGISTRY[name]


def registry() -> Mapping[str, Template]:
    """Every registered template by name."""
    return _REGISTRY


def steps_text(steps: Sequence[SolutionStep]) -> list[str]:
    """The worked steps as numbered lines of text."""
    return [f"{k}. {s.plain()}" for k, s in enumerate(steps, 1)]
