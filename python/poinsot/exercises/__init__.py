"""Exercises for teachers: problem templates with seeded variants, answers checked by two routes,
worked solutions from :mod:`poinsot.derive`, and files for a printed sheet or a quiz::

    from poinsot import exercises
    exercises.names()                                   # ['car-plumb-bob', ...]
    sheet = exercises.generate(["earth"], n=30, seed=2026)
    sheet[0].statement, sheet[0].answer, sheet[0].tolerance, sheet[0].steps
    files = exercises.render(sheet, "moodle-xml")      # {"quiz.xml": "..."}
    exercises.check("dropped-ball", seed=sheet[0].seed, answer="12.3 mm")

Each variant is drawn from ``numpy.random.default_rng`` (PCG64) seeded from (seed, template,
index), so the same seed gives the same set on every machine; its answer is computed through
the public API and by a second, independent route (closed form against integration, or the
core's closed form against the sympy derivation's), and a variant whose routes disagree is never
issued. The command line: ``poinsot exercises TOPIC... --n 30 --seed 2026 --format FORMAT``
and ``poinsot check TEMPLATE --seed N --answer VALUE``.

Needs pint (``poinsot[units]``) and, for the worked solutions and the derived routes, sympy
(``poinsot[symbolic]``).
"""

from __future__ import annotations

try:
    import pint  # noqa: F401
    import sympy  # noqa: F401
except ImportError as exc:  # pragma: no cover - both are installed in the test environment
    raise ImportError(
        "poinsot.exercises needs pint and sympy: pip install 'poinsot[units,symbolic]'"
    ) from exc

from ._formats import FORMATS, render, write
from ._issue import TOPICS, Check, check, generate, names, template, templates
from ._steps import SolutionStep
from ._template import Param, Template, Variant, variant_seed

__all__ = [
    "FORMATS",
    "TOPICS",
    "Check",
    "Param",
    "SolutionStep",
    "Template",
    "Variant",
    "check",
    "generate",
    "names",
    "render",
    "template",
    "templates",
    "variant_seed",
    "write",
]
