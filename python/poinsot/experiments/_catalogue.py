"""The catalogue of published measurements: :class:`Source`, :class:`Experiment`, the units
registry with the historical units, and the collection of the entries.

Each entry module in :mod:`poinsot.experiments.entries` holds a list ``ENTRIES`` of
:class:`Experiment`; :func:`catalogue` collects every module's list, sorted in the unit's order
of :data:`TOPICS`, then by year. An entry is data (who measured what, where, when, as
published, with its stated uncertainty) and two computations: ``predict``, through poinsot's
public API only, and ``closed_form``, the unit's closed form (a poinsot function too), both
taking the published inputs as pint quantities.
"""

from __future__ import annotations

import difflib
import importlib
import pkgutil
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import pint

from ..errors import PoinsotError

__all__ = [
    "TOPICS",
    "Experiment",
    "Source",
    "catalogue",
    "get",
    "names",
    "parse",
    "problems",
    "ureg",
]

#: The topics, in the order of the course unit (the catalogue's order).
TOPICS: tuple[str, ...] = (
    "falling bodies",
    "Foucault pendulums",
    "inertial oscillations",
    "vortices",
    "the Earth's figure",
    "the Earth's rotation",
    "free rotation",
)

# ---- the units: pint's, with the historical units of the sources -------------------------------

#: The registry of the catalogue: pint's units plus the old French and Prussian lengths.
#:
#: * ``paris_line`` (ligne): the French law of 19 frimaire an VIII (10 December 1799) made the
#:   metre legal at 443.296 lignes of the toise de Paris (Delambre's and Méchain's measure), so
#:   1 ligne = 1/443.296 m = 2.255829 mm; the pouce (``paris_inch``) is 12 lignes, the pied du
#:   roi (``paris_foot``) 12 pouces = 0.32483939 m, the toise 6 pieds = 1.949036 m (Bigourdan,
#:   *Le système métrique des poids et mesures*, Paris 1901).
#: * ``rhenish_foot`` (rheinländischer Fuß, the Prussian foot): 139.13 Paris lines by the
#:   Prussian Maß- und Gewichtsordnung of 16 May 1816, 0.313853 m, usually rounded to 0.3139 m
#:   (the value used here); ``rhenish_inch``, ``rhenish_line`` its twelfths.
ureg: pint.UnitRegistry = pint.UnitRegistry()
ureg.define("paris_line = meter / 443.296 = ligne")
ureg.define("paris_inch = 12 * paris_line = pouce")
ureg.define("paris_foot = 12 * paris_inch = pied_du_roi")
ureg.define("toise = 6 * paris_foot")
ureg.define("rhenish_foot = 0.3139 * meter")
ureg.define("rhenish_inch = rhenish_foot / 12")
ureg.define("rhenish_line = rhenish_inch / 12")
Quantity = ureg.Quantity


def parse(text: str) -> Any:
    """A published value as a quantity of :data:`ureg` (``"158.5 m"``, ``"50 deg + 55 arcmin"``,
    ``"12.6 paris_line"``, ``"3"`` dimensionless), or the text itself for a word (a sense,
    ``"counterclockwise"``: no digit in it). :class:`PoinsotError` naming the text otherwise.

    ``text`` is a string; the quantity returned keeps the text's own unit (convert with ``.to(...)``;
    a plain number is dimensionless), a scalar."""
    text = text.strip()
    if not re.search(r"\d", text):
        return text
    try:
        value = ureg.parse_expression(text)
    except (pint.errors.UndefinedUnitError, pint.errors.DimensionalityError, SyntaxError) as exc:
        raise PoinsotError(f"{text!r}: not a quantity pint reads ({exc})") from None
    return value if isinstance(value, ureg.Quantity) else ureg.Quantity(value)


def sense(counterclockwise: float) -> str:
    """The word of a turning seen from above for a rate or circulation ``counterclockwise``
    (any unit, counterclockwise positive): ``"counterclockwise"``, ``"clockwise"`` or ``"none"``
    (exactly zero). The entries' routes compare senses as words (``measured`` of a sense)."""
    if counterclockwise > 0:
        return "counterclockwise"
    return "clockwise" if counterclockwise < 0 else "none"


# ---- the data ------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Source:
    """Where a measurement is published.

    Attributes
    ----------
    who:
        Who measured (``"Ferdinand Reich"``).
    where:
        Where it was measured (``"Drei-Brüder-Schacht, Freiberg, Saxony"``).
    when:
        When it was measured (``"1831"``).
    publication:
        The full citation.
    page:
        Where the figure is printed (``"p. 45, table III"``).
    url:
        A stable link (archive.org, a DOI) when there is one.
    note:
        How it was checked, or the secondary source used.
    first_hand:
        Whether this publication itself was read (its text, a facsimile or a faithful
        transcription): ``True``; ``False`` when its figures are taken from the sources that
        quote it (``note`` says which); ``None``: not recorded.
    """

    who: str
    where: str
    when: str
    publication: str
    page: str
    url: str | None = None
    note: str = ""
    first_hand: bool | None = None

    @property
    def reading(self) -> str:
        """``"read first-hand"``, ``"second-hand"`` or ``""`` (not recorded), for a citation."""
        if self.first_hand is None:
            return ""
        return "read first-hand" if self.first_hand else "second-hand"

    def to_dict(self) -> dict[str, Any]:
        """The source as plain JSON values."""
        return {k: getattr(self, k) for k in ("who", "where", "when", "publication", "page")} | {
            "url": self.url,
            "note": self.note,
            "first_hand": self.first_hand,
        }


@dataclass(frozen=True)
class Experiment:
    """A published measurement and poinsot's computation of it.

    Attributes
    ----------
    name:
        Kebab-case, person-year (``"reich-1831"``).
    title:
        ``"Reich's drops in the Freiberg mine shaft"``.
    topic:
        One of :data:`TOPICS`.
    sources:
        The publications; the first is the primary source.
    inputs:
        The inputs as published, pint strings in their units (``{"height": "158.5 m",
        "latitude": "50 deg + 55 arcmin"}``; Paris feet and lines, knots allowed).
    quantity:
        What is compared, in words (``"eastward deflection"``).
    measured:
        The measured result, a pint string (``"28.4 mm"``), or a word for a sense
        (``"counterclockwise"``).
    uncertainty:
        One standard deviation (or the stated scatter) as a pint string; ``None`` for a sense
        or where none is stated.
    uncertainty_kind:
        What the uncertainty is (``"stated probable error"``, ``"scatter of the drops"``).
    predict:
        The inputs (pint quantities of :data:`ureg`, words as strings) → poinsot's prediction,
        through the public API only (``Earth().drop``, ``Earth().foucault``, ...), a pint
        quantity, or a word for a sense.
    closed_form:
        The same inputs → the unit's closed form, through the poinsot function that computes it
        (``Earth().eastward_deflection``), same dimension; ``None`` where there is none.
    assumptions:
        The model's assumptions (``("vacuum", "uniform gravity", "spherical Earth")``).
    story:
        A paragraph for the docs page.
    misquoted:
        Where a commonly quoted number is wrong, and why.
    expect:
        ``"agree"``, or ``"disagree"`` with ``why`` saying what the model leaves out.
    why:
        Why a disagreement is expected.
    unit:
        The unit results are shown in (``"mm"``, ``"h"``, ``"deg/h"``); by default the unit of
        ``measured``.
    """

    name: str
    title: str
    topic: str
    sources: tuple[Source, ...]
    inputs: Mapping[str, str]
    quantity: str
    measured: str
    uncertainty: str | None
    uncertainty_kind: str
    predict: Callable[[Mapping[str, Any]], Any]
    closed_form: Callable[[Mapping[str, Any]], Any]
    assumptions: tuple[str, ...]
    story: str
    misquoted: str = ""
    expect: str = "agree"
    why: str = ""
    unit: str = ""

    @property
    def year(self) -> int:
        """The year of the measurement: the first four-digit number in the primary source's
        ``when`` (else in the name)."""
        for text in (self.sources[0].when if self.sources else "", self.name):
            m = re.search(r"\d{4}", text)
            if m:
                return int(m.group())
        return 0

    def parsed_inputs(self) -> dict[str, Any]:
        """The inputs as quantities of :data:`ureg`, name → a scalar quantity in the published
        unit (words stay strings)."""
        return {k: parse(v) for k, v in self.inputs.items()}

    def run(self, **inputs: Any) -> Any:
        """:func:`poinsot.experiments.run` of this entry (``inputs`` as there: name → a pint
        string or quantity with its unit); returns an :class:`ExperimentResult`."""
        from ._result import run_entry

        return run_entry(self, inputs)


def problems(e: Experiment) -> list[str]:
    """What is missing or malformed in the entry ``e`` (an :class:`Experiment`; empty for a
    complete one): every source needs
    who, where, when, publication and page (none a "TODO" placeholder) and says whether it was
    read first-hand; the topic is one of :data:`TOPICS`; the measured
    value, its uncertainty and the inputs read in pint; ``expect`` is ``"agree"`` or
    ``"disagree"`` (with ``why``). A list of sentences (strings), one per problem."""
    out = []
    if not re.fullmatch(r"[a-z0-9]+(-[a-z0-9]+)*", e.name):
        out.append(f"name {e.name!r} is not kebab-case")
    if e.topic not in TOPICS:
        out.append(f"topic {e.topic!r} is not one of {TOPICS}")
    if not e.sources:
        out.append("no source")
    for i, s in enumerate(e.sources):
        for key in ("who", "where", "when", "publication", "page"):
            text = str(getattr(s, key)).strip()
            if not text:
                out.append(f"sources[{i}].{key} is empty")
            elif "TODO" in text.upper():
                out.append(f"sources[{i}].{key} is a placeholder: {text!r}")
        if s.first_hand is None:
            out.append(f"sources[{i}].first_hand is not recorded (was it read first-hand?)")
    if e.expect not in ("agree", "disagree"):
        out.append(f"expect {e.expect!r} is not 'agree' or 'disagree'")
    if e.expect == "disagree" and not e.why.strip():
        out.append("expect='disagree' without why")
    fields: list[tuple[str, str | None]] = [
        ("measured", e.measured),
        ("uncertainty", e.uncertainty),
        *e.inputs.items(),
    ]
    for label, value in fields:
        if value is None:
            continue
        try:
            parse(value)
        except PoinsotError as exc:
            out.append(f"{label}: {exc}")
    if not e.story.strip():
        out.append("no story")
    return out


# ---- the collection ---------------------------------------------------------------------------


@lru_cache(maxsize=1)
def _collect() -> tuple[Experiment, ...]:
    from . import entries

    found: list[Experiment] = []
    for info in sorted(pkgutil.iter_modules(entries.__path__), key=lambda i: i.name):
        if info.name.startswith("_"):
            continue
        module = importlib.import_module(f"{entries.__name__}.{info.name}")
        found.extend(getattr(module, "ENTRIES", []))
    seen: set[str] = set()
    for e in found:
        if e.name in seen:
            raise PoinsotError(f"experiments: two entries are named {e.name!r}")
        seen.add(e.name)
    order = {t: i for i, t in enumerate(TOPICS)}
    return tuple(sorted(found, key=lambda e: (order.get(e.topic, len(order)), e.year, e.name)))


def catalogue() -> tuple[Experiment, ...]:
    """Every entry (a tuple of :class:`Experiment`), in the unit's order of topics
    (:data:`TOPICS`), then by year."""
    return _collect()


def names() -> list[str]:
    """The entries' names (a list of strings), in catalogue order."""
    return [e.name for e in _collect()]


def get(name: str) -> Experiment:
    """The entry (an :class:`Experiment`) named ``name`` (a string, ``"reich-1831"``);
    :class:`PoinsotError` naming it, with the close names, when there is none."""
    for e in _collect():
        if e.name == name:
            return e
    close = difflib.get_close_matches(str(name), names(), n=3, cutoff=0.5)
    hint = (
        f"; did you mean {', '.join(close)}?" if close else f"; the entries: {', '.join(names())}"
    )
    raise PoinsotError(f"name: no experiment {name!r}{hint}")
