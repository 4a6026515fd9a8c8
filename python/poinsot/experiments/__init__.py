"""The unit against the world: a catalogue of published measurements, reproduced.

Each entry (:class:`Experiment`) is a measurement as its author published it — who, where,
when, the publication and the page the figure is printed on; the inputs in their own units
(Paris feet and lines, degrees and minutes, knots) read by pint; the measured value with its
stated uncertainty — and a computation through poinsot's public API that predicts it, beside
the unit's closed form, with the model's assumptions named::

    from poinsot import experiments
    experiments.names()                 # ['reich-1831', ...]
    r = experiments.run("reich-1831")   # ExperimentResult
    r.summary                           # "... measured 28.4 ± ... mm, poinsot predicts ..."
    r.measured, r.predicted, r.sigma, r.verdict

The command line: ``poinsot experiments`` (the table), ``poinsot experiments NAME [--json]``.

pint comes with the extra ``poinsot[units]``; this module needs it (the rest of poinsot does
not): importing it without pint raises an ``ImportError`` naming the extra.
"""

from __future__ import annotations

try:
    import pint  # noqa: F401
except ImportError as exc:  # pragma: no cover - pint is installed in the test environment
    raise ImportError("poinsot.experiments needs pint: pip install 'poinsot[units]'") from exc

from ._catalogue import (
    TOPICS,
    Experiment,
    Source,
    catalogue,
    get,
    names,
    parse,
    problems,
    ureg,
)
from ._plot import plot
from ._result import (
    AGREE_RELATIVE,
    AGREE_SIGMA,
    ExperimentResult,
    catalogue_summary,
    run,
    run_all,
)

__all__ = [
    "AGREE_RELATIVE",
    "AGREE_SIGMA",
    "TOPICS",
    "Experiment",
    "ExperimentResult",
    "Source",
    "catalogue",
    "catalogue_summary",
    "get",
    "names",
    "parse",
    "plot",
    "problems",
    "run",
    "run_all",
    "ureg",
]
