"""The unit's equation numbers as the project cites them, and the equation index
(docs/equations.md) that gives each one its formula, function and test.

Shared by the documentation build (``poinsot_docs`` shows, on every page that cites an equation,
the formula of each number it cites) and by ``python/tests/test_equation_index.py``, which checks
the index against every citation in the code. Standard library only.
"""

from __future__ import annotations

import io
import re
import tokenize
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from functools import cache
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]  # docs/_ext/ → the repository
INDEX = ROOT / "docs" / "equations.md"
ERRATA = ROOT / "docs" / "errata.md"
PY_TESTS = ROOT / "python" / "tests"
RS_TESTS = ROOT / "crates" / "poinsot" / "tests"

#: Where the project cites the unit (paths relative to the repository root).
SOURCE_GLOBS = (
    "python/poinsot/**/*.py",
    "crates/*/src/**/*.rs",
    "docs/*.md",
    "README.md",
    "CONVENTIONS.md",
    "web/src/**/*.ts",
    "web/src/**/*.js",
    "web/index.html",
)
#: The index itself cites every number; it is what is checked, not a source.
NOT_SOURCES = frozenset({"docs/equations.md"})

#: Numbers that the rules below cannot tell from a citation, with the reason. Each entry must
#: still occur in its file (a stale entry fails ``test_exceptions_are_still_needed``).
NOT_CITATIONS: dict[tuple[str, str], str] = {
    ("docs/lab.md", "truncated 2.5 to 2"): "a count that wasm-bindgen truncated",
    ("docs/lab.md", "2.5 samples"): "a count refused by the lab's argument checks",
    ("crates/poinsot-wasm/src/lib.rs", "2.5 is not a count"): "a count refused by the checks",
    ("crates/poinsot-wasm/src/args.rs", "(2.5 samples become 2)"): "a count truncated",
    ("crates/poinsot-wasm/src/args.rs", '2.5"`), and a count'): "a value in an error message",
    ("crates/poinsot/src/integrate/grid.rs", "sample_before(&times, 2.5)"): "a doctest's argument",
}


# ---- the scanner: prose of each kind of file --------------------------------------------------


def _blank(text: str, spans: Iterable[tuple[int, int]]) -> str:
    """``text`` with everything outside ``spans`` replaced by spaces (newlines kept), so that
    offsets and line numbers stay those of the file."""
    out = [c if c == "\n" else " " for c in text]
    for a, b in spans:
        out[a:b] = text[a:b]
    return "".join(out)


def _clike_spans(
    text: str, *, quote_strings: bool, hash_comments: bool = False
) -> list[tuple[int, int]]:
    """Comment and string-literal spans of Rust, TypeScript/JavaScript (``quote_strings``: '…'
    is a string, else a Rust char literal or lifetime) or, as a fallback, Python."""
    spans, i, n = [], 0, len(text)
    char_lit = re.compile(r"'(?:\\u\{[0-9a-fA-F]+\}|\\.|[^\\'\n])'")
    raw = re.compile(r"(?<![\w])r(#*)\"")
    while i < n:
        c = text[i]
        if text.startswith("//", i) or (hash_comments and c == "#"):
            j = text.find("\n", i)
            j = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
        elif not quote_strings and (m := raw.match(text, i)):
            end = '"' + m.group(1)
            j = text.find(end, m.end())
            j = n if j < 0 else j + len(end)
        elif c == "'" and not quote_strings:
            m = char_lit.match(text, i)
            i = m.end() if m else i + 1
            continue
        elif c in '"`' or (c == "'" and quote_strings):
            if hash_comments and text.startswith(c * 3, i):
                j = text.find(c * 3, i + 3)
                j = n if j < 0 else j + 3
            else:
                j = i + 1
                while j < n and text[j] != c and not (c != "`" and text[j] == "\n"):
                    j += 2 if text[j] == "\\" else 1
                j = min(j + 1, n)
        else:
            i += 1
            continue
        spans.append((i, j))
        i = j
    return spans


def _python_spans(text: str, base: int = 0) -> list[tuple[int, int]]:
    """Comment and string spans of Python source (docstrings, messages, f-strings)."""
    starts = [0]
    for line in text.splitlines(keepends=True):
        starts.append(starts[-1] + len(line))
    try:
        toks = list(tokenize.generate_tokens(io.StringIO(text).readline))
    except (tokenize.TokenError, IndentationError, SyntaxError):
        return [
            (base + a, base + b)
            for a, b in _clike_spans(text, quote_strings=True, hash_comments=True)
        ]
    spans = []
    for tok in toks:
        if tok.type in (tokenize.STRING, tokenize.COMMENT):
            (r0, c0), (r1, c1) = tok.start, tok.end
            spans.append((base + starts[r0 - 1] + c0, base + starts[r1 - 1] + c1))
    return spans


_FENCE = re.compile(
    r"^(\s*)(`{3,}|~{3,})\s*(\{[\w-]+\})?\s*([\w-]*)[^\n]*\n(.*?)^\1\2\s*$", re.M | re.S
)


def _markdown_spans(text: str) -> list[tuple[int, int]]:
    """All of a markdown page except the code of its Python blocks (whose comments and strings
    still count)."""
    spans, pos = [], 0
    for m in _FENCE.finditer(text):
        lang = (m.group(4) or "").lower()
        if m.group(3) == "{code-cell}" or lang in ("python", "py", "pycon", "ipython3"):
            spans.append((pos, m.start(5)))
            spans += _python_spans(m.group(5), m.start(5))
            pos = m.end(5)
    spans.append((pos, len(text)))
    return spans


def prose(path: Path, text: str | None = None) -> str:
    """The prose of a source file, everything else blanked (offsets kept)."""
    text = path.read_text(encoding="utf-8") if text is None else text
    suffix = path.suffix
    if suffix == ".py":
        spans = _python_spans(text)
    elif suffix == ".rs":
        spans = _clike_spans(text, quote_strings=False)
    elif suffix in (".ts", ".js", ".mjs"):
        spans = _clike_spans(text, quote_strings=True)
    elif suffix == ".md":
        spans = _markdown_spans(text)
    else:  # html and anything else: all of it
        spans = [(0, len(text))]
    return _blank(text, spans)


# ---- the scanner: citations in prose ----------------------------------------------------------

_NUM = r"(?<![\w.])2\.(\d{1,3})(?![\w]|\.\d)"
_SEP = r"\s*(?:[–—‑-]|/|,|;|&|\band\b|\bor\b|\bto\b)\s*"
_GROUP = re.compile(rf"{_NUM}(?:{_SEP}{_NUM})*")
_MEMBER = re.compile(rf"({_SEP})?{_NUM}")
_RANGE_SEP = re.compile(r"^\s*(?:[–—‑-]|to)\s*$")
#: A group right after these is not the unit's equation: a figure, a section, another work's
#: equation ("Carlson (1995) eq. (2.19)"), an assigned, compared, negative or reported value.
_NOT_EQ_BEFORE = re.compile(
    r"(?:(?i:\bfig(?:ure)?s?)\.?\s*|§\s*|\(\d{4}\)\s*eqs?\.[^;\n]*|[=≤≥<>≈~]\s*|[-−]"
    r"|\bgot(?:\s+\w+)?\s+|--[a-z][\w-]*[ =]\s*)$"
)
#: A number followed by a unit or a sign like these is a quantity: "2.2°", "2.6 µs", "2.4 ε",
#: "2.8 ′", "2.3 m/s²" (an exercise's answer), and in LaTeX "2.2\times 10^{-308}",
#: "2.5\,\mathrm{m}".
_UNIT_AFTER = re.compile(
    r"^(?:\s*[°%×ε′″]|\s+[ck]?m/s|\s+(?:[µmn]?s|[KMG]iB|[kMG]B)\b"
    r"|\s*\\(?:times|cdot|mathrm|text)\b|\s*\\[,;])"
)
_PLAIN_NUMBER_BEFORE = re.compile(r"([\d.⁰¹²³⁴⁵⁶⁷⁸⁹]+)\s*[,/]\s*$")
_PLAIN_NUMBER_AFTER = re.compile(r"^\s*(?:[×%]|[/,–—-]\s*(\d[\d.]*))")
_EQ_NUMBER = re.compile(r"2\.\d{1,3}")


@dataclass(frozen=True)
class Citation:
    number: int  # the N of eq. 2.N
    path: str  # relative to the repository root
    line: int
    text: str  # the cited group as written

    def where(self) -> str:
        return f"{self.path}:{self.line} ({self.text!r})"


def _excluded_spans(rel: str, raw: str) -> list[tuple[int, int]]:
    spans = []
    for (path, snippet), _why in NOT_CITATIONS.items():
        if path == rel:
            spans += [(m.start(), m.end()) for m in re.finditer(re.escape(snippet), raw)]
    return spans


def citations_in(text: str, rel: str, raw: str | None = None) -> Iterator[Citation]:
    """The unit's equation numbers cited in ``text`` (already reduced to prose), ranges expanded."""
    raw = text if raw is None else raw
    skip = _excluded_spans(rel, raw)
    for g in _GROUP.finditer(text):
        a, b = g.span()
        before, after = text[max(0, a - 24) : a], text[b : b + 16]
        if _NOT_EQ_BEFORE.search(before) or any(s <= a and b <= e for s, e in skip):
            continue
        if before.endswith("`") and after.startswith("`"):
            continue  # a literal in inline code: ``2.5``
        m = _PLAIN_NUMBER_BEFORE.search(before)
        if m and not _EQ_NUMBER.fullmatch(m.group(1)):
            continue  # in a list of plain numbers: "−2³¹, 2.5"
        m = _PLAIN_NUMBER_AFTER.match(after)
        if m and not (m.group(1) and _EQ_NUMBER.fullmatch(m.group(1))):
            continue  # "2.7–28×", "2.9 / 7.0", "2.2, 1.95"
        if _UNIT_AFTER.match(after):
            continue
        line = text.count("\n", 0, a) + 1
        members = [(mm.group(1) or "", int(mm.group(2))) for mm in _MEMBER.finditer(g.group())]
        numbers: list[int] = []
        for k, (sep, n) in enumerate(members):
            if k and _RANGE_SEP.match(sep) and numbers and numbers[-1] < n:
                numbers += range(numbers[-1] + 1, n + 1)
            else:
                numbers.append(n)
        for n in numbers:
            if n >= 1:
                yield Citation(n, rel, line, g.group())


def source_files(root: Path = ROOT) -> list[Path]:
    files: set[Path] = set()
    for pattern in SOURCE_GLOBS:
        files.update(p for p in root.glob(pattern) if p.is_file())
    return sorted(p for p in files if p.relative_to(root).as_posix() not in NOT_SOURCES)


def scan(root: Path = ROOT) -> dict[int, list[Citation]]:
    """Every cited equation number → where it is cited."""
    out: dict[int, list[Citation]] = {}
    for path in source_files(root):
        raw = path.read_text(encoding="utf-8")
        rel = path.relative_to(root).as_posix()
        for c in citations_in(prose(path, raw), rel, raw):
            out.setdefault(c.number, []).append(c)
    return out


@cache
def cited() -> dict[int, list[Citation]]:
    return scan()


# ---- the index --------------------------------------------------------------------------------

_ROW = re.compile(r"^\|\s*2\.(\d{1,3})\s*\|")
_ROLE = re.compile(r"\{(func|meth|class|attr|data)\}`([^`]+)`")
_TEST = re.compile(r"`([\w./-]+\.(?:py|rs))::(\w+)`")
_MATH = re.compile(r"\$\$(.+?)\$\$|\$(.+?)\$")
NOT_IN_UNIT = "not in the unit"
NOT_CITED = "not cited"


@dataclass(frozen=True)
class Row:
    number: int
    line: int
    formula: str
    functions: str
    tests: str

    @property
    def text(self) -> str:
        return " | ".join((self.formula, self.functions, self.tests))

    def roles(self) -> list[tuple[str, str]]:
        out = []
        for kind, body in _ROLE.findall(self.functions):
            target = body.rsplit("<", 1)[1].rstrip(">") if body.endswith(">") else body
            out.append((kind, target.strip().lstrip("~")))
        return out

    def test_refs(self) -> list[tuple[str, str]]:
        return _TEST.findall(self.tests)

    def formulas(self) -> list[str]:
        return [a or b for a, b in _MATH.findall(self.formula)]


def parse_index(text: str) -> list[Row]:
    rows = []
    lines = text.splitlines()
    for k, line in enumerate(lines, 1):
        m = _ROW.match(line)
        if not m:
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        assert len(cells) == 4, (
            f"docs/equations.md:{k}: a row needs 4 cells (eq. | formula | computed by | checked "
            f"by), found {len(cells)}; write |x| in LaTeX as \\lvert x \\rvert"
        )
        rows.append(Row(int(m.group(1)), k, cells[1], cells[2], cells[3]))
    return rows


@cache
def index_rows() -> tuple[Row, ...]:
    return tuple(parse_index(INDEX.read_text(encoding="utf-8")))


def missing_rows(numbers: Iterable[int], rows: Iterable[Row]) -> list[int]:
    have = {r.number for r in rows}
    return sorted(set(numbers) - have)


def uncited_rows(rows: Iterable[Row], numbers: Iterable[int]) -> list[Row]:
    """Rows that nobody cites and that do not say why they are listed anyway."""
    numbers = set(numbers)
    return [r for r in rows if r.number not in numbers and NOT_CITED not in r.text]
