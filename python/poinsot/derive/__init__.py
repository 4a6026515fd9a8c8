"""The unit, derived: each topic of the course unit as steps a reader can follow, from the unit's
starting point to its result, in the unit's notation, on sympy (the optional ``symbolic`` extra:
``pip install 'poinsot[symbolic]'``).

Entry points
------------
:func:`derivations`
    Every derivation, in the unit's order.
:func:`derivation`
    One derivation by name (:func:`names` lists the unit's, :func:`applied` those that apply
    the unit's theory beyond its equations, e.g. ``"rigid_earth"``).
:func:`errata`
    The unit's equations as printed (transcribed once, :func:`printed`) that do not follow from
    the derivations, each with its derived form. Found by computation, not by hand.
:func:`questions`
    The unit's question bank, answered from the package.

Each :class:`Derivation` has ``name``, ``title``, ``steps`` (a sentence and a sympy equation
each), ``result`` (the derived equations keyed by the unit's equation numbers, e.g. ``"2.42"``)
and renders itself with :meth:`Derivation.latex` and :meth:`Derivation.markdown`.

Every step is checked when it is made: its ``lhs − rhs`` must reduce to zero in the derivation's
model (components for the vector notation), so a derivation that builds is a proof of what it
shows. A derivation is built once per process and then shared: treat it as read-only.
"""

from __future__ import annotations

import importlib
from functools import cache
from typing import Any

from ..errors import PoinsotError

try:  # pragma: no cover - depends on the environment
    import sympy  # noqa: F401
except ImportError as exc:  # pragma: no cover
    raise ImportError("poinsot.derive needs sympy: pip install 'poinsot[symbolic]'") from exc

from ._core import Derivation, Erratum, Printed, Step, judge
from .questions import Question, questions

__all__ = [
    "Step",
    "Derivation",
    "Printed",
    "Erratum",
    "names",
    "applied",
    "derivations",
    "derivation",
    "printed",
    "errata",
    "questions",
    "Question",
]

#: The derivations in the unit's order: name → module (each module has ``derive()`` returning
#: its :class:`Derivation` and ``PRINTED``, the unit's equations of its range as printed).
_TOPICS: dict[str, str] = {
    "frames": "frames",  # 2.1–2.28: translation, the rotating frame, fictitious forces
    "earth": "earth",  # 2.29–2.42: effective gravity, the falling body (to second order)
    "rigid_body": "rigid_body",  # 2.43–2.66: L and T from particles, the inertia tensor
    "euler_equations": "euler_equations",  # 2.67–2.76
    "torque_free_top": "torque_free_top",  # 2.77–2.97
    "euler_angles": "euler_angles",  # 2.98–2.101, all 12 sequences
    "heavy_top": "heavy_top",  # 2.102–2.121
}

#: The unit's theory applied beyond its equations: name → module (issue 25: the Earth as a
#: rigid body). Not among :func:`names` (the unit's topics); :func:`derivation` builds them too.
#: They have no ``PRINTED``: the unit, which stops at the heavy top, prints none of their equations.
_APPLIED: dict[str, str] = {
    "rigid_earth": "rigid_earth",  # 2.83 and the torque theory: Euler's period, the precession
    "gyrocompass": "gyrocompass",  # issue 26: the rotating frame and torque law, linearised
}


def names() -> list[str]:
    """The derivations' names, in the unit's order."""
    return list(_TOPICS)


def applied() -> list[str]:
    """The names of the derivations that apply the unit's theory beyond its equations (the
    rigid Earth's free nutation and precession, the linearised gyrocompass);
    :func:`derivation` builds them."""
    return list(_APPLIED)


def _module(name: str) -> Any:
    return importlib.import_module(f".{_TOPICS.get(name) or _APPLIED[name]}", __name__)


@cache
def derivation(name: str) -> Derivation:
    """The derivation called ``name`` (built and checked on first use, then shared).

    Raises :class:`~poinsot.PoinsotError` naming ``name`` when there is no such derivation."""
    if not isinstance(name, str) or (name not in _TOPICS and name not in _APPLIED):
        known = ", ".join([*_TOPICS, *_APPLIED])
        raise PoinsotError(f"name: no derivation {name!r}; one of {known}")
    d: Derivation = _module(name).derive()
    return d


def derivations() -> list[Derivation]:
    """Every derivation, in the unit's order."""
    return [derivation(n) for n in _TOPICS]


def printed() -> list[Printed]:
    """The unit's equations as printed, transcribed once, in the unit's order."""
    out: list[Printed] = []
    for n in _TOPICS:
        out.extend(_module(n).PRINTED)
    return out


@cache
def _errata() -> tuple[Erratum, ...]:
    return tuple(judge(printed(), {n: derivation(n) for n in _TOPICS}))


def errata() -> list[Erratum]:
    """Each printed equation of the unit that does not follow from its derivation, with the
    derived form (:class:`Erratum`), in the unit's order."""
    return list(_errata())
