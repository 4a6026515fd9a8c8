"""Issuing sets of variants (:func:`generate`) and checking a student's answer (:func:`check`)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from .._units import parse as parse_suffixed
from ..errors import PoinsotError
from ._template import Template, Variant, register, registry, variant_seed
from ._text import si_factor, ureg
from .entries import bodies, earth, frames, tops

__all__ = ["TOPICS", "Check", "check", "generate", "names", "template", "templates"]

#: The topics, in the order of the course unit.
TOPICS: tuple[str, ...] = (
    "moving frames",
    "earth",
    "rigid bodies",
    "free tops",
    "euler angles",
    "heavy top",
)

#: The most variants one set may hold.
MAX_VARIANTS = 2000

register(*frames.ENTRIES, *earth.ENTRIES, *bodies.ENTRIES, *tops.ENTRIES)


def names() -> list[str]:
    """The templates' names, in the unit's order of their topics."""
    return [t.name for t in templates()]


def templates(topic: str | None = None) -> list[Template]:
    """Every template (of ``topic``), in the unit's order."""
    out = sorted(registry().values(), key=lambda t: TOPICS.index(t.topic))
    return [t for t in out if topic is None or t.topic == topic]


def template(name: str) -> Template:
    """The template called ``name``; :class:`PoinsotError` naming ``template`` otherwise."""
    if not isinstance(name, str) or name not in registry():
        raise PoinsotError(f"template: no template {name!r}; one of {', '.join(names())}")
    return registry()[name]


def _selected(topics: Any) -> list[Template]:
    if isinstance(topics, str):
        topics = [topics]
    chosen: list[Template] = []
    for item in topics:
        if item == "all":
            chosen += templates()
        elif item in TOPICS:
            chosen += templates(item)
        elif isinstance(item, str) and item in registry():
            chosen.append(registry()[item])
        else:
            raise PoinsotError(
                f"topics: no topic or template {item!r}; topics: {', '.join(TOPICS)}, 'all', "
                f"or a template: {', '.join(names())}"
            )
    if not chosen:
        raise PoinsotError("topics: give at least one topic or template")
    return list(dict.fromkeys(chosen))


def generate(topics: Any, n: int = 30, seed: int = 2026) -> list[Variant]:
    """A set of ``n`` variants of the templates of ``topics`` (topic names of :data:`TOPICS`,
    template names, or ``"all"``), taken in turn; variant ``i`` of template ``t`` has the seed
    :func:`variant_seed` ``(seed, t, i)``. Raises :class:`PoinsotError` naming ``topics``, ``n``
    or ``seed``."""
    chosen = _selected(topics)
    if isinstance(n, bool) or not isinstance(n, int) or not 1 <= n <= MAX_VARIANTS:
        raise PoinsotError(f"n: must be an integer from 1 to {MAX_VARIANTS}, got {n!r}")
    if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
        raise PoinsotError(f"seed: must be a non-negative integer, got {seed!r}")
    return [
        chosen[i % len(chosen)].variant(variant_seed(seed, chosen[i % len(chosen)].name, i))
        for i in range(n)
    ]


@dataclass(frozen=True)
class Check:
    """A student's answer judged: ``right``, the answer given and the expected one (both in
    ``unit``), how far off (absolute, and relative to the expected), the tolerance, the common
    mistake it matches (its name, text and the step of the solution to look at), and a sentence
    (``verdict``)."""

    template: str
    seed: int
    given: float
    expected: float
    unit: str
    tolerance: float
    right: bool
    off_by: float
    relative: float
    mistake: str | None
    mistake_text: str | None
    step: int | None
    verdict: str

    def to_dict(self) -> dict[str, Any]:
        """The check as plain JSON values."""
        return dict(self.__dict__)


def _answer(answer: Any, unit: str) -> float:
    """A student's answer in ``unit``: a number, or text (``"12.3"``, ``"1.23 cm"``)."""
    if isinstance(answer, bool):
        raise PoinsotError(f"answer: not a number: {answer!r}")
    if isinstance(answer, (int, float)):
        value = float(answer)
    elif isinstance(answer, str):
        try:
            value = float(answer)
        except ValueError:
            value = _with_unit(answer, unit)
    else:
        raise PoinsotError(f"answer: not a number: {answer!r}")
    if not math.isfinite(value):
        raise PoinsotError(f"answer: must be finite, got {answer!r}")
    return value


def _with_unit(text: str, unit: str) -> float:
    """``text`` with a unit, in ``unit``: read by pint, else by the CLI's suffixes."""
    try:
        q: Any = ureg.Quantity(text)
    except Exception:  # pint raises several kinds for text it cannot read
        raise PoinsotError(f"answer: not a number: {text!r}") from None
    if not hasattr(q, "to"):
        raise PoinsotError(f"answer: not a number: {text!r}")
    try:
        return float(q.to(unit).magnitude)
    except Exception:
        try:  # the CLI's suffixes (50d53m)
            return parse_suffixed(text, "angle")[0] / si_factor(unit)
        except ValueError:
            pass
        raise PoinsotError(f"answer: {text!r} is not in units of {unit}") from None


def check(name: str, seed: int, answer: Any) -> Check:
    """Judges ``answer`` (a number in the template's unit, or text with a unit) to the variant
    ``seed`` of the template ``name``: right or wrong, how far off, and, when it matches one of
    the template's common mistakes, which and the step to look at."""
    v = template(name).variant(seed)
    given = _answer(answer, v.unit)
    off = given - v.answer
    rel = off / abs(v.answer)  # an issued answer is never 0: its tolerance is a share of it
    right = abs(off) <= v.tolerance
    match = None
    if not right:
        near = [
            (abs(given - w), m, w)
            for m, w in v.mistakes
            if abs(given - w) <= max(v.tolerance, 1e-3 * abs(w))
        ]
        match = min(near, key=lambda x: x[0]) if near else None
    unit = v.unit
    if right:
        verdict = f"right: {given:.6g} {unit} (expected {v.answer:.4g} ± {v.tolerance:.2g})"
    elif match is not None:
        _, m, _w = match
        verdict = (
            f"wrong: {given:.6g} {unit} is off by {off:.3g} ({rel:+.2%}); it is what "
            f"'{m.name}' gives: {m.text}. Look at step {m.step} of the solution."
        )
    else:
        verdict = (
            f"wrong: {given:.6g} {unit} is off by {off:.3g} ({rel:+.2%}; accepted ± "
            f"{v.tolerance:.2g}). Check the units and each step of the solution."
        )
    return Check(
        name,
        v.seed,
        given,
        v.answer,
        unit,
        v.tolerance,
        right,
        off,
        rel,
        match[1].name if match else None,
        match[1].text if match else None,
        match[1].step if match else None,
        verdict,
    )
