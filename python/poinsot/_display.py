"""How poinsot's objects show themselves: the text repr and the notebook's HTML table, both
built from one list of :class:`Row` (quantity, symbol, value, unit), so that the two views
cannot say different things.

A class lists its rows in ``_rows()`` and inherits :class:`Displayed`: ``repr(obj)`` is the
one-line ``Name(key=value unit, ...)`` of its *brief* rows (what the reprs said before), and
``obj._repr_html_()`` (what Jupyter shows) is a table of all its rows — the brief ones first,
then the details (derived quantities and sampled arrays, summarised by their shape and first
and last values). Every number is formatted here, once, by :func:`number` (6 significant
digits); the HTML escapes every string; its only style is inline, with inherited colours and
transparent backgrounds, so that it reads in light and dark themes.
"""

from __future__ import annotations

import html
import re
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

import numpy as np

SIGNIFICANT = 6
"""Significant digits of every number shown (the reprs' ``:.6g``)."""

ROUND_OFF = 1e-12
"""In a vector or matrix, an entry at most this fraction of the largest one shows as 0: it is
round-off (a centre of mass at [2e-17, 0, 1.5] m is shown [0, 0, 1.5]), as numpy's
``suppress_small`` does. The attribute keeps the exact number."""


# ---- numbers, formatted once ----------------------------------------------------------------


def number(x: Any) -> str:
    """One number: ``None`` → ``"None"``, an integer as it is, a float to :data:`SIGNIFICANT`
    digits (``"inf"``, ``"-inf"``, ``"nan"`` as Python writes them; −0 as ``"0"``)."""
    if x is None:
        return "None"
    if isinstance(x, (bool, np.bool_)):
        return str(bool(x))
    if isinstance(x, (int, np.integer)):
        return str(int(x))
    v = float(x)
    if v == 0.0:
        return "0"
    return f"{v:.{SIGNIFICANT}g}"


def _entries(a: Any) -> list[str]:
    """The entries of an array (any shape) as :func:`number` writes them, round-off as 0."""
    arr = np.asarray(a, dtype=float)
    finite = np.abs(arr[np.isfinite(arr)])
    big = float(finite.max()) if finite.size else 0.0
    return [number(0.0 if abs(v) <= ROUND_OFF * big else v) for v in arr.reshape(-1)]


def vector(v: Any) -> str:
    """``[a, b, c]``."""
    return "[" + ", ".join(_entries(v)) + "]"


def matrix(m: Any) -> str:
    """``[[a, b, c], [d, e, f], [g, h, i]]`` (rows; round-off judged on the whole matrix)."""
    arr = np.asarray(m, dtype=float)
    cells = _entries(arr)
    n = arr.shape[1]
    return (
        "["
        + ", ".join("[" + ", ".join(cells[i : i + n]) + "]" for i in range(0, len(cells), n))
        + "]"
    )


def summary(a: Any) -> str:
    """A sampled array by its shape and its first and last values, never dumped:
    ``(1001, 3): [a, b, c] … [x, y, z]`` or ``(1001,): a … b``."""
    arr = np.asarray(a)
    shape = "(" + ", ".join(str(n) for n in arr.shape) + ("," if arr.ndim == 1 else "") + ")"
    if arr.shape[0] == 0:
        return f"{shape}: empty"
    one = number if arr.ndim == 1 else vector
    ends = one(arr[0]) if arr.shape[0] == 1 else f"{one(arr[0])} … {one(arr[-1])}"
    return f"{shape}: {ends}"


# ---- rows -------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Row:
    """One line of an object's display.

    Attributes
    ----------
    key:
        The attribute's name where there is one (``"principal_moments"``): the HTML row's
        ``data-key``, and the name in the text repr unless ``label`` says otherwise.
    quantity:
        What it is, in words (the HTML's first column).
    symbol:
        The unit's symbol, Unicode; ``a_b`` shows ``b`` as a subscript in HTML. May be ``""``.
    value:
        The value, formatted once (by :func:`number`, :func:`vector`, ... or words).
    unit:
        SI unit (``"kg·m²"``), ``""`` for none.
    brief:
        Also in the one-line text repr (otherwise only in the HTML table).
    words:
        The value is words, not numbers: quoted after its name in the text repr.
    relation:
        ``"="``, or ``" in "`` for a range (``theta in [0.8, 1.00148] rad``).
    label:
        The name in the text repr when it is not ``key`` (``"Ω"``); ``""``: the value stands
        alone there (``"prolate"``).
    """

    key: str
    quantity: str
    symbol: str
    value: str
    unit: str = ""
    brief: bool = True
    words: bool = False
    relation: str = "="
    label: str | None = None

    def text(self) -> str:
        """The row in the text repr: ``name=value unit``, ``name='words'`` or ``value unit``."""
        name = self.key if self.label is None else self.label
        if self.words:
            return f"{name}={self.value!r}" if name else self.value
        head = f"{name}{self.relation}{self.value}" if name else self.value
        return f"{head} {self.unit}" if self.unit else head


def scalar(
    key: str,
    quantity: str,
    symbol: str,
    x: Any,
    unit: str = "",
    *,
    brief: bool = True,
    label: str | None = None,
) -> Row:
    """A number (``None`` shows as ``None``, without the unit)."""
    return Row(key, quantity, symbol, number(x), unit if x is not None else "", brief, label=label)


def scalars(obj: Any, *rows: tuple[str, str, str, str], brief: bool = True) -> list[Row]:
    """:func:`scalar` of ``obj``'s attribute ``key`` for each row (key, quantity, symbol,
    unit)."""
    return [scalar(k, q, s, getattr(obj, k), u, brief=brief) for k, q, s, u in rows]


def vec(key: str, quantity: str, symbol: str, v: Any, unit: str = "", *, brief: bool = True) -> Row:
    """A short vector, all of it."""
    return Row(key, quantity, symbol, vector(v), unit, brief)


def mat(
    key: str, quantity: str, symbol: str, m: Any, unit: str = "", *, brief: bool = False
) -> Row:
    """A small matrix, all of it."""
    return Row(key, quantity, symbol, matrix(m), unit, brief)


def span(key: str, quantity: str, symbol: str, lo: Any, hi: Any, unit: str = "", **kw: Any) -> Row:
    """A range ``[lo, hi]``: ``label in [lo, hi] unit`` in the text repr (``brief``, ``label``
    as :func:`scalar`)."""
    row = scalar(key, quantity, symbol, lo, unit, **kw)
    return replace(row, value=vector([lo, hi]), unit=unit, relation=" in ")


def samples(
    key: str, quantity: str, symbol: str, a: Any, unit: str = "", *, brief: bool = False
) -> Row:
    """A sampled array, summarised (:func:`summary`)."""
    return Row(key, quantity, symbol, summary(a), unit, brief)


def words(
    key: str, quantity: str, text: str, *, brief: bool = True, label: str | None = None
) -> Row:
    """Words (a kind, a regime, a note); with ``label=""`` they stand alone in the text repr."""
    return Row(key, quantity, "", str(text), "", brief, words=True, label=label)


# ---- the two views ----------------------------------------------------------------------------


def text_repr(name: str, rows: Sequence[Row]) -> str:
    """``Name(row, row, ...)`` of the brief rows, on one line."""
    return f"{name}(" + ", ".join(r.text() for r in rows if r.brief) + ")"


_TABLE = "border-collapse:collapse;color:inherit;background:transparent;margin:0 auto 0 0"
_CAPTION = "caption-side:top;text-align:left;font-weight:bold;padding:0 0 0.25em 0"
_CELL = "text-align:left;padding:0.1em 0.8em 0.1em 0;border:none"
_HEAD = _CELL + ";border-bottom:1px solid currentColor"
_DETAIL = _CELL + ";opacity:0.8"
_VALUE = ";font-family:monospace;white-space:nowrap"
COLUMNS = ("quantity", "symbol", "value", "unit")
"""The HTML table's columns."""


def _symbol_html(symbol: str) -> str:
    """The symbol, escaped, with ``a_b`` → a<sub>b</sub> in each comma-separated part."""
    parts = []
    for part in symbol.split(", "):
        base, sep, sub = part.partition("_")
        parts.append(
            html.escape(base)
            + (f'<sub style="line-height:0">{html.escape(sub)}</sub>' if sep else "")
        )
    return ", ".join(parts)


def html_table(name: str, rows: Sequence[Row]) -> str:
    """The table Jupyter shows: a caption with ``name``, a header of :data:`COLUMNS`, then one
    ``<tr data-key=...>`` per row: the brief rows (those of the text repr, in its order), then
    the details (``class="detail"``, dimmed). Every string is escaped; no CSS or script from
    outside, colours inherited."""
    head = "".join(f'<th style="{_HEAD}">{c}</th>' for c in COLUMNS)
    body = []
    for r in sorted(rows, key=lambda r: not r.brief):
        cell, kind = (_CELL, "") if r.brief else (_DETAIL, ' class="detail"')
        body.append(
            f'<tr data-key="{html.escape(r.key, quote=True)}"{kind}>'
            f'<td style="{cell}">{html.escape(r.quantity)}</td>'
            f'<td style="{cell}">{_symbol_html(r.symbol)}</td>'
            f'<td style="{cell}{_VALUE if not r.words else ""}">{html.escape(r.value)}</td>'
            f'<td style="{cell}">{html.escape(r.unit)}</td></tr>'
        )
    return (
        f'<table class="poinsot-repr" style="{_TABLE}">'
        f'<caption style="{_CAPTION}">{html.escape(name)}</caption>'
        f"<thead><tr>{head}</tr></thead><tbody>{''.join(body)}</tbody></table>"
    )


_EXPONENT = re.compile(r"^(-?)([0-9.]+)e([+-])0*([0-9]+)$")


def latex_number(text: str) -> str:
    """A number as :func:`number` wrote it, in LaTeX: ``1.5e-05`` → ``1.5\\times10^{-5}``; a
    leading minus as ``\\mathrm{-}``, an ordinary symbol (a sign, not a subtraction: no spaces
    around it in any renderer, and mathtext's ``\\substack`` refuses a group like ``{-}``)."""
    m = _EXPONENT.match(text)
    if m:
        sign, mant, esign, exp = m.groups()
        text = f"{sign}{mant}\\times10^{{{'-' if esign == '-' else ''}{exp}}}"
    return r"\mathrm{-}" + text[1:] if text.startswith("-") else text


def latex_matrix(symbol: str, m: Any, unit: str) -> str:
    """``$symbol = (matrix)\\ unit$`` for ``_repr_latex_``: the entries as :func:`matrix`
    formats them, the columns as ``\\substack``s inside ``\\left( \\right)`` — the one way to set
    a matrix that matplotlib's mathtext, MathJax, KaTeX and LaTeX (amsmath) all accept
    (mathtext has no ``pmatrix``); ``unit`` is LaTeX (``\\mathrm{kg\\,m^{2}}``)."""
    arr = np.asarray(m, dtype=float)
    cells = [latex_number(c) for c in _entries(arr)]
    rows, cols = arr.shape
    columns = [
        r"\substack{" + r"\\".join(cells[i * cols + j] for i in range(rows)) + "}"
        for j in range(cols)
    ]
    return f"${symbol} = \\left(" + r"\;\;".join(columns) + f"\\right)\\ {unit}$"


# ---- the mixin ----------------------------------------------------------------------------------


class Displayed:
    """Gives ``__repr__`` and ``_repr_html_`` from the class's ``_rows()``."""

    __slots__ = ()

    if TYPE_CHECKING:  # every subclass lists its own rows

        def _rows(self) -> list[Row]: ...

    def __repr__(self) -> str:
        return text_repr(type(self).__name__, self._rows())

    def _repr_html_(self) -> str:
        """The object as an HTML table of its quantities with their units (Jupyter shows it)."""
        return html_table(type(self).__name__, self._rows())
