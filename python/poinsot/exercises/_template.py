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
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from types import SimpleNamespace
from typing import Any, cast

import numpy as np

from ..errors import PoinsotError
from ._steps import Derived, Mistake, Plain, SolutionStep
from ._text import CARRIED_DIGITS, UNITS, latex_text, shown, si_factor, si_unit, sig

__all__ = [
    "ANSWER_RTOL",
    "MAX_REDRAWS",
    "MAX_RTOL",
    "Param",
    "Template",
    "Variant",
    "register",
    "registry",
    "variant_seed",
]

#: Draws tried for one variant before its template is refused (two routes that disagree).
MAX_REDRAWS = 20
#: The least relative tolerance of a graded answer (half a unit of the 4th significant figure
#: of a number near 5000 is 1e-4; one per mille leaves room for honest rounding, and still tells
#: the solar day from the sidereal one, 2.7e-3 apart).
ANSWER_RTOL = 1e-3
#: The largest relative tolerance a variant may need: a draw whose answer is more sensitive to
#: its inputs' rounding (a near-cancellation, an answer near zero) is drawn again.
MAX_RTOL = 0.02
#: Relative change of each input when the answer's conditioning is measured.
_CARRY = 0.5 * 10.0 ** (1 - CARRIED_DIGITS)


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


# ---- the template -----------------------------------------------------------------------------


class _LastStep:
    """The default of :attr:`Template.check`: replaced by the last step's derived formula."""

    def __repr__(self) -> str:
        return "<the last step's derived formula>"


#: The sentinel, typed as the field it stands in for (it is never called: __post_init__ replaces it).
_LAST_STEP: Callable[[Any], float] = cast("Callable[[Any], float]", _LastStep())


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
    answer:
        Values (SI, as attributes) → the answer (SI) through poinsot's public API.
    agree:
        The relative difference of the two routes a variant may have (with the reason in
        ``agree_why``).
    unit:
        The unit of the answer (pint's spelling, a key of :data:`UNITS`); by default the unit
        of the last worked step (the worked solution arrives at the answer).
    check:
        The second, independent route (closed form vs integration, exact vs derived formula);
        by default the last worked step's derived formula (a :class:`Derived` step: the
        :mod:`poinsot.derive` result against the core's closed form).
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
    answer: Callable[[Any], float]
    agree: float
    agree_why: str
    unit: str = ""
    check: Callable[[Any], float] = _LAST_STEP
    steps: tuple[Derived | Plain, ...] = ()
    mistakes: tuple[Mistake, ...] = ()
    constants: Mapping[str, float] = field(default_factory=dict)
    extra: Callable[[Any], Mapping[str, float]] | None = None
    answer_range: tuple[float, float] = (-math.inf, math.inf)
    max_rtol: float = MAX_RTOL
    source: str = ""

    def __post_init__(self) -> None:
        last = self.steps[-1] if self.steps else None
        if self.check is _LAST_STEP:
            if not isinstance(last, Derived):
                raise TypeError(
                    f"template {self.name!r}: no check, and its last step is not derived"
                )
            object.__setattr__(self, "check", last.evaluate)
        if not self.unit and last is not None:
            object.__setattr__(self, "unit", last.unit)

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
                    return Variant(self, seed, drawn, v, labels, a, b, tolerance)
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
            self, _seed(seed, "seed"), dict(drawn), v, chosen, a, b, self.tolerance(v, a)
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

    ``drawn`` (each parameter in its unit), ``values`` (SI, what the routes read), ``labels``
    (the labels of choices), ``answer_si`` and ``check_si`` (the two routes, SI),
    ``tolerance_si`` (the accepted absolute error, SI). ``steps`` and ``mistakes`` are worked
    out when read."""

    template: Template
    seed: int
    drawn: dict[str, float]
    values: SimpleNamespace
    labels: dict[str, str]
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
            f"{p.name} = {sig(getattr(self.values, p.name))} {UNITS[si_unit(p.unit)][0]}".rstrip()
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
