"""Running an entry of the catalogue: :class:`ExperimentResult` (measured vs predicted vs the
closed form, and a verdict in units of the measurement's uncertainty), :func:`run` and
:func:`run_all`."""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import Any

from .. import _display as show
from .._answers import num
from .._progress import delayed_bar, stderr_interactive
from ..errors import PoinsotError
from ._catalogue import Experiment, Source, catalogue, get, parse, ureg

__all__ = [
    "AGREE_RELATIVE",
    "AGREE_SIGMA",
    "ExperimentResult",
    "catalogue_summary",
    "run",
    "run_all",
]

#: A measurement agrees with the prediction when they differ by at most this many of its
#: standard uncertainties (about 95 % for a normal error). Without a stated uncertainty the
#: verdict is the relative difference, and agreement is within :data:`AGREE_RELATIVE`.
AGREE_SIGMA = 2.0
#: Agreement of a measurement without a stated uncertainty: a relative difference below this.
AGREE_RELATIVE = 0.05

_QUANTITIES = ("measured", "uncertainty", "predicted", "closed_form")


@dataclass(frozen=True, repr=False)
class ExperimentResult(show.Displayed):
    """A catalogue entry run: what was measured, what poinsot predicts, and how they compare.

    Attributes
    ----------
    name, title, topic, quantity:
        The entry's (:class:`~poinsot.experiments.Experiment`).
    unit:
        The unit the quantities are in (``"mm"``, ``"h"``); ``""`` for a sense.
    si_unit:
        The SI unit of the ``*_si`` floats (``"m"``, ``"s"``, ``"rad/s"``).
    measured:
        The measured value as a pint quantity in ``unit`` (or the word of a sense,
        ``"counterclockwise"``).
    uncertainty:
        Its stated one-sigma uncertainty or scatter in ``unit`` (``None`` for a sense).
    predicted:
        poinsot's prediction (through its public API), in ``unit`` (or a word).
    closed_form:
        The unit's closed form, in ``unit`` (or a word; ``None`` where there is none).
    measured_si, uncertainty_si, predicted_si, closed_form_si:
        The same in SI units (``si_unit``) as floats (``None`` for words).
    sigma:
        (measured − predicted) / uncertainty, a dimensionless float (``None`` without a number
        or an uncertainty).
    relative:
        (measured − predicted) / predicted, a dimensionless float (``None`` for a sense).
    agrees:
        abs(sigma) ≤ :data:`AGREE_SIGMA` (abs(relative) ≤ :data:`AGREE_RELATIVE` without an
        uncertainty; the same word for a sense).
    as_expected:
        Whether ``agrees`` is what the entry expects (``expect``).
    verdict:
        In words: ``"agrees within 0.6 σ"``, ``"disagrees by 40 σ — expected: ..."``,
        ``"same sense"``.
    expect, why, uncertainty_kind, assumptions, sources, inputs:
        The entry's (inputs as published, strings; those changed by ``run(name, **inputs)`` as
        given).
    year:
        The year of the measurement (:attr:`Experiment.year`).
    """

    name: str
    title: str
    topic: str
    quantity: str
    unit: str
    si_unit: str
    measured: Any
    uncertainty: Any
    predicted: Any
    closed_form: Any
    measured_si: float | None
    uncertainty_si: float | None
    predicted_si: float | None
    closed_form_si: float | None
    sigma: float | None
    relative: float | None
    agrees: bool
    as_expected: bool
    verdict: str
    expect: str
    why: str
    uncertainty_kind: str
    assumptions: tuple[str, ...]
    sources: tuple[Source, ...]
    inputs: dict[str, str]
    year: int = 0

    # -- words and views ------------------------------------------------------------------
    @property
    def is_sense(self) -> bool:
        """Whether the compared quantity is a sense (a word), not a number."""
        return isinstance(self.measured, str)

    @property
    def unit_symbol(self) -> str:
        """``unit`` as pint abbreviates it (``"deg/h"``, ``"ligne"``, ``"m/s²"``)."""
        return f"{ureg.Unit(self.unit):~P}" if self.unit else ""

    @property
    def short_verdict(self) -> str:
        """The verdict in a few words, for a table: ``"agrees (0.78 σ)"``, ``"disagrees (40 σ),
        expected"``, ``"agrees (3.6 %)"`` (no uncertainty stated), ``"same sense"``."""
        if self.is_sense:
            word = "same sense" if self.agrees else "opposite sense"
        elif self.sigma is not None:
            word = f"{'agrees' if self.agrees else 'disagrees'} ({num(abs(self.sigma), 2)} σ)"
        else:
            assert self.relative is not None
            pct = num(abs(self.relative) * 100, 2)
            word = f"{'agrees' if self.agrees else 'differs'} ({pct} %)"
        if not self.as_expected:
            return word + ", not expected"
        return word + (", expected" if self.expect == "disagree" else "")

    def shown(self, key: str) -> str:
        """``measured``, ``uncertainty``, ``predicted`` or ``closed_form`` as text, rounded to
        3 significant digits (4 for the measured value and the prediction), with the unit."""
        value = getattr(self, key)
        if value is None:
            return "—"
        if isinstance(value, str):
            return value
        digits = 4 if key in ("measured", "predicted", "closed_form") else 2
        return f"{num(float(value.magnitude), digits)} {self.unit_symbol}".strip()

    def shown_measured(self) -> str:
        """The measured value with its uncertainty, ``"28.4 ± 4 mm"`` (a sense: the word)."""
        if self.is_sense or self.uncertainty is None:
            return self.shown("measured")
        value = num(float(self.measured.magnitude), 4)
        return f"{value} ± {self.shown('uncertainty')}"

    @property
    def summary(self) -> str:
        """The result in one plain sentence."""
        head = f"{self.title} ({self.year}), {self.quantity}:"
        if self.is_sense:
            body = f" observed {self.measured}, poinsot predicts {self.predicted}"
        else:
            body = f" measured {self.shown_measured()}, poinsot predicts {self.shown('predicted')}"
            if self.closed_form is not None:
                body += f" (closed form {self.shown('closed_form')})"
        return f"{head}{body}: {self.verdict}."

    def _rows(self) -> list[show.Row]:
        def row(key: str, quantity: str, brief: bool = True) -> show.Row:
            value = getattr(self, key)
            if value is None or isinstance(value, str):
                return show.words(key, quantity, "None" if value is None else value, brief=brief)
            return show.scalar(
                key, quantity, "", float(value.magnitude), self.unit_symbol, brief=brief
            )

        return [
            show.words("name", "experiment", self.name),
            row("measured", f"{self.quantity}, measured"),
            row("uncertainty", f"its uncertainty ({self.uncertainty_kind})", brief=False),
            row("predicted", "poinsot's prediction"),
            row("closed_form", "the closed form", brief=False),
            show.scalar(
                "sigma", "(measured − predicted) / uncertainty", "", self.sigma, "σ", brief=False
            ),
            show.words("verdict", "verdict", self.verdict),
            show.words("assumptions", "assumptions", ", ".join(self.assumptions), brief=False),
            show.words("source", "primary source", _cite(self.sources[0]), brief=False),
        ]

    def _repr_html_(self) -> str:
        import html

        return f"<p>{html.escape(self.summary)}</p>" + super()._repr_html_()

    # -- plain data ------------------------------------------------------------------------
    def to_dict(self) -> dict[str, Any]:
        """The result as plain JSON values (``poinsot experiments NAME --json``): the
        quantities as numbers in ``unit`` (words as they are), ``sources`` as dicts."""
        out: dict[str, Any] = {}
        for f in fields(self):
            value = getattr(self, f.name)
            if f.name in _QUANTITIES:
                value = value if value is None or isinstance(value, str) else float(value.magnitude)
            elif f.name == "sources":
                value = [s.to_dict() for s in value]
            elif f.name == "assumptions":
                value = list(value)
            elif f.name == "inputs":
                value = dict(value)
            out[f.name] = value
        out["summary"] = self.summary
        return out

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> ExperimentResult:
        """The result back from :meth:`to_dict` (its JSON)."""
        kw = {f.name: data[f.name] for f in fields(cls) if f.name in data}
        for key in _QUANTITIES:
            value = kw.get(key)
            if value is not None and not isinstance(value, str):
                kw[key] = ureg.Quantity(float(value), data["unit"])
        kw["sources"] = tuple(Source(**s) for s in data["sources"])
        kw["assumptions"] = tuple(data["assumptions"])
        kw["inputs"] = dict(data["inputs"])
        return cls(**kw)

    def __reduce__(self) -> tuple[Any, ...]:
        # The quantities belong to the catalogue's registry (with its Paris units): pickled as
        # plain data and rebuilt in it, not in pint's application registry.
        return (_from_dict, (self.to_dict(),))


def _from_dict(data: dict[str, Any]) -> ExperimentResult:
    return ExperimentResult.from_dict(data)


def _cite(s: Source) -> str:
    return f"{s.who}, {s.publication}, {s.page}"


# ---- running ----------------------------------------------------------------------------------


def _as_unit(value: Any, unit: str, label: str, name: str) -> Any:
    """``value`` (a quantity of any registry, or a word) in ``unit`` of :data:`ureg`."""
    if value is None or isinstance(value, str):
        return value
    try:
        q = ureg.Quantity(value.magnitude, str(value.units)) if hasattr(value, "units") else None
    except Exception:  # a unit only another registry knows
        q = None
    if q is None:
        raise PoinsotError(f"{name}: {label} must be a pint quantity or a word, got {value!r}")
    try:
        return q.to(unit)
    except Exception as exc:  # pint.DimensionalityError
        raise PoinsotError(f"{name}: {label} {q:~P} is not in {unit}: {exc}") from None


def _si(q: Any) -> tuple[float | None, str]:
    if q is None or isinstance(q, str):
        return None, ""
    base = q.to_base_units()
    return float(base.magnitude), f"{base.units:~P}"


def run_entry(e: Experiment, changes: dict[str, Any] | None = None) -> ExperimentResult:
    """Run one entry (an :class:`Experiment`): its inputs parsed (with ``changes``, name → a
    pint string or quantity with its unit, in place of the published ones), its prediction
    and closed form computed. Returns an :class:`ExperimentResult`."""
    inputs = e.parsed_inputs()
    for key, value in (changes or {}).items():
        if key not in inputs:
            raise PoinsotError(f"{key}: not an input of {e.name} (its inputs: {', '.join(inputs)})")
        if isinstance(value, str):
            inputs[key] = parse(value)
        elif hasattr(value, "units"):
            inputs[key] = ureg.Quantity(value.magnitude, str(value.units))
        else:
            raise PoinsotError(
                f"{key}: give a quantity with its unit (a pint string such as "
                f"{e.inputs[key]!r}, or a pint quantity), got {value!r}"
            )
    published = parse(e.measured)
    unit = e.unit or ("" if isinstance(published, str) else str(published.units))
    measured = _as_unit(published, unit, "measured", e.name)
    uncertainty = None
    if e.uncertainty is not None:
        uncertainty = _as_unit(parse(e.uncertainty), unit, "uncertainty", e.name)
    predicted = _as_unit(e.predict(inputs), unit, "predict()", e.name)
    closed = _as_unit(e.closed_form(inputs), unit, "closed_form()", e.name)
    m_si, si_unit = _si(measured)
    u_si, _ = _si(uncertainty)
    p_si, p_unit = _si(predicted)
    c_si, _ = _si(closed)
    sigma = relative = None
    if isinstance(measured, str) or isinstance(predicted, str):
        agrees = str(measured).lower() == str(predicted).lower()
        text = "same sense" if agrees else "opposite sense"
    else:
        assert m_si is not None and p_si is not None
        relative = (m_si - p_si) / p_si if p_si != 0 else math.inf
        if u_si:
            sigma = (m_si - p_si) / u_si
            agrees = abs(sigma) <= AGREE_SIGMA
            text = f"{'agrees within' if agrees else 'disagrees by'} {num(abs(sigma), 2)} σ"
        else:
            agrees = abs(relative) <= AGREE_RELATIVE
            pct = num(abs(relative) * 100, 2)
            rule = num(AGREE_RELATIVE * 100, 2)
            text = (
                f"{'agrees within' if agrees else 'differs by'} {pct} % "
                f"(no uncertainty stated; agreement means within {rule} %)"
            )
    expected = e.expect == "agree"
    as_expected = agrees == expected
    if not agrees and not expected:
        text += f" — expected: {e.why}"
    elif agrees and not expected:
        text += f" — a disagreement was expected: {e.why}"
    elif not agrees:
        text += " — not expected"
    shown_inputs = dict(e.inputs)
    for key, value in (changes or {}).items():
        shown_inputs[key] = value if isinstance(value, str) else f"{inputs[key]:~P}"
    return ExperimentResult(
        name=e.name,
        title=e.title,
        topic=e.topic,
        quantity=e.quantity,
        unit=unit,
        si_unit=si_unit or p_unit,
        measured=measured,
        uncertainty=uncertainty,
        predicted=predicted,
        closed_form=closed,
        measured_si=m_si,
        uncertainty_si=u_si,
        predicted_si=p_si,
        closed_form_si=c_si,
        sigma=sigma,
        relative=relative,
        agrees=agrees,
        as_expected=as_expected,
        verdict=text,
        expect=e.expect,
        why=e.why,
        uncertainty_kind=e.uncertainty_kind,
        assumptions=tuple(e.assumptions),
        sources=tuple(e.sources),
        inputs=shown_inputs,
        year=e.year,
    )


def run(name: str, **inputs: Any) -> ExperimentResult:
    """Run the catalogue's entry ``name`` (``"reich-1831"``): measured vs poinsot's prediction
    vs the closed form, and the verdict in units of the measurement's uncertainty.
    :class:`PoinsotError` naming ``name`` (with the close names) for an unknown one.

    ``inputs`` replace published inputs by name, as pint strings or quantities
    (``run("reich-1831", height="160 m")``): what the prediction would have been had the
    experimenter measured the set-up differently. ``inputs`` shows the ones used.

    Returns an :class:`ExperimentResult`: the quantities as pint scalars in the entry's
    ``unit`` and as floats in SI (``*_si``, in ``si_unit``)."""
    if not isinstance(name, str):
        raise PoinsotError(f"name: expected an experiment's name (a string), got {name!r}")
    return run_entry(get(name), inputs)


def run_all(progress: bool | None = None) -> tuple[ExperimentResult, ...]:
    """Run every entry, in catalogue order: a tuple of :class:`ExperimentResult`, one per
    entry. A progress bar on stderr when it is a terminal and the runs take over a second
    (``progress``, a bool or ``None`` for that default; ``False``: never)."""
    entries = catalogue()
    show_bar = stderr_interactive() if progress is None else bool(progress)
    out = []
    with delayed_bar("experiments", show=show_bar) as update:
        for i, e in enumerate(entries):
            out.append(run_entry(e))
            update(i + 1, len(entries))
    return tuple(out)


def catalogue_summary(results: tuple[ExperimentResult, ...] | list[ExperimentResult]) -> str:
    """The catalogue's ``results`` (a sequence of :class:`ExperimentResult`, as :func:`run_all`
    gives) in one or two plain sentences, a string: how many agree, how many disagree as
    expected, and any that does not do what its entry expects."""
    n = len(results)
    agree = sum(r.agrees for r in results)
    expected_off = [r for r in results if not r.agrees and r.as_expected]
    surprises = [r.name for r in results if not r.as_expected]
    words = f"{n} published measurement{'s' if n != 1 else ''} reproduced by poinsot: "
    words += f"{agree} agree with poinsot's prediction"
    if expected_off:
        words += f", {len(expected_off)} disagree as expected (the model leaves something out)"
    words += "."
    if surprises:
        words += f" Not as the entry expects: {', '.join(surprises)}."
    return words
