"""The equation index (docs/equations.md) checked against the code, so it cannot go stale.

The project cites the unit's equation numbers everywhere: docstrings and code of
python/poinsot, the Rust doc comments and messages (crates/*/src), the docs, README.md,
CONVENTIONS.md, the command line's help and output (python/poinsot/cli.py, tour.py) and the
browser lab (web/src). The scanner below finds every such citation — "eq. 2.42", "eqs.
2.32–2.42", "(2.99)", "2.61–2.62", "the unit's 2.119", a bare "2.103" in the CLI's table — and
a range cites every number in it. It reads only prose: comments, docstrings and string literals
of code, all of a markdown page except its Python code, so ``lw=2.5`` or ``[1.0, 2.0]`` never
count; figure numbers ("Fig. 2.12"), numbers with an exponent or a unit-like suffix ("2.2e-308",
"2.0x"), and numbers in lists of plain numbers ("2.9 / 7.0") are not citations either.

The index must then have exactly one row per cited number (a row nobody cites must say why it
is there), every function it names must import, every test it names must exist, each formula
must parse as LaTeX (matplotlib's mathtext renders it), and each erratum of docs/errata.md must
be marked in its row. Negative controls show that a fake citation, a missing row, a misspelt
function or test and broken LaTeX are caught.

Run as a script (``python python/tests/test_equation_index.py``) to list where each number is
cited.
"""

from __future__ import annotations

import ast
import dataclasses
import importlib
import inspect
import re
import sys
from functools import cache
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "docs" / "_ext"))

from unit_equations import (  # noqa: E402  (the scanner and the index's parser, shared with the docs build)
    _MATH,
    _ROW,
    ERRATA,
    INDEX,
    NOT_CITATIONS,
    NOT_CITED,
    NOT_IN_UNIT,
    PY_TESTS,
    RS_TESTS,
    Row,
    citations_in,
    cited,
    index_rows,
    missing_rows,
    parse_index,
    scan,
    uncited_rows,
)

# ---- resolving names --------------------------------------------------------------------------


def resolve(target: str) -> tuple[Any, Any]:
    """``(object, owner)`` for a dotted name such as ``poinsot.Earth.eastward_deflection``
    (``owner`` is the class or module it was found on); raises LookupError."""
    parts = target.split(".")
    for k in range(len(parts), 0, -1):
        try:
            obj: Any = importlib.import_module(".".join(parts[:k]))
        except ImportError:
            continue
        owner: Any = None
        for i, name in enumerate(parts[k:], k):
            owner = obj
            if name in getattr(obj, "__dict__", {}):
                obj = inspect.getattr_static(obj, name)
            elif dataclasses.is_dataclass(obj) and name in {
                f.name for f in dataclasses.fields(obj)
            }:
                obj = dataclasses.MISSING  # a dataclass field without a default
            elif hasattr(obj, name):
                obj = inspect.getattr_static(obj, name)
            else:
                raise LookupError(f"{target}: {'.'.join(parts[:i])} has no {name!r}")
        return obj, owner
    raise LookupError(f"{target}: no importable module")


def role_problem(kind: str, target: str) -> str | None:
    """Why ``{kind}`target``` is wrong, or None."""
    try:
        obj, owner = resolve(target)
    except LookupError as err:
        return str(err)
    if not target.startswith("poinsot."):
        return f"{target}: not a poinsot name"
    if kind == "class":
        return None if inspect.isclass(obj) else f"{target} is not a class"
    if kind == "func":
        ok = inspect.ismodule(owner) and callable(obj) and not inspect.isclass(obj)
        return None if ok else f"{target} is not a module-level function (use meth/class/attr)"
    if kind == "meth":
        ok = inspect.isclass(owner) and (
            isinstance(obj, (staticmethod, classmethod)) or inspect.isroutine(obj)
        )
        return None if ok else f"{target} is not a method"
    if kind == "attr":
        ok = (
            inspect.isclass(owner)
            and not inspect.isroutine(obj)
            and not isinstance(obj, (staticmethod, classmethod))
        )
        return None if ok else f"{target} is not an attribute or property"
    if kind == "data":
        return None if inspect.ismodule(owner) and not callable(obj) else f"{target} is not data"
    return f"unknown role {kind}"


def named_test_path(name: str) -> Path:
    if "/" in name:
        return ROOT / name
    return (PY_TESTS if name.endswith(".py") else RS_TESTS) / name


@cache
def _python_tests(path: Path) -> frozenset[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    return frozenset(
        n.name
        for n in ast.walk(tree)
        if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef)) and n.name.startswith("test")
    )


@cache
def _rust_tests(path: Path) -> frozenset[str]:
    """Functions with ``#[test]`` among the attributes right above them (proptest's too)."""
    names, attrs = set(), []
    for line in path.read_text(encoding="utf-8").splitlines():
        s = line.strip()
        if s.startswith("#[") or s.startswith("#!["):
            attrs.append(s)
            continue
        if not s or s.startswith("//"):
            continue
        m = re.match(r"(?:pub\s+)?(?:async\s+)?fn\s+(\w+)", s)
        if m and any(a.startswith("#[test]") for a in attrs):
            names.add(m.group(1))
        attrs = []
    return frozenset(names)


def named_test_problem(file: str, name: str) -> str | None:
    path = named_test_path(file)
    if not path.is_file():
        return f"{file}: no such file ({path.relative_to(ROOT)})"
    found = _python_tests(path) if path.suffix == ".py" else _rust_tests(path)
    return None if name in found else f"{file}::{name}: no such test"


# ---- LaTeX ------------------------------------------------------------------------------------

#: MathJax macros that matplotlib's mathtext lacks, and what mathtext renders in their place.
MATHJAX_ONLY = {
    r"\lvert": "|",
    r"\rvert": "|",
    r"\lVert": r"\Vert",
    r"\rVert": r"\Vert",
    r"\ge": r"\geq",
    r"\le": r"\leq",
    r"\tfrac": r"\frac",
    r"\displaystyle": "",
    r"\big": "",
    r"\Big": "",
    r"\bigg": "",
    r"\Bigg": "",
}
_ENV = re.compile(r"\\begin\{(\w+\*?)\}(.*?)\\end\{\1\}", re.S)
_MACRO = re.compile(r"\\([A-Za-z]+)")


def latex_problem(tex: str) -> str | None:
    """Why ``tex`` is not good LaTeX for MathJax, or None: balanced braces and environments, and
    every piece rendered by matplotlib's mathtext (aligned lines and matrix cells one by one)."""
    depth = 0
    for k, c in enumerate(tex):
        if c in "{}" and k and tex[k - 1] == "\\":
            continue
        depth += {"{": 1, "}": -1}.get(c, 0)
        if depth < 0:
            return f"unbalanced '}}' at {k}"
    if depth:
        return "unbalanced '{'"
    if tex.count(r"\begin{") != tex.count(r"\end{"):
        return r"unmatched \begin/\end"
    if len(re.findall(r"\\left\b", tex)) != len(re.findall(r"\\right\b", tex)):
        return r"unmatched \left/\right"
    pieces: list[str] = []

    def split_env(m: re.Match[str]) -> str:
        env, body = m.group(1), m.group(2)
        if env not in ("aligned", "pmatrix", "bmatrix", "matrix", "cases"):
            raise ValueError(f"environment {env} not allowed")
        rows = re.split(r"\\\\", body)
        cells = [
            c
            for r in rows
            for c in (r.split("&") if env.endswith("matrix") else [r.replace("&", "")])
        ]
        pieces.extend(c for c in cells if c.strip())
        return " X "

    try:
        rest = _ENV.sub(split_env, tex)
    except ValueError as err:
        return str(err)
    if "\\\\" in rest or "&" in rest:
        return r"\\ or & outside an aligned or matrix environment"
    pieces.append(rest)
    from matplotlib.mathtext import MathTextParser

    parser = MathTextParser("path")
    for piece in pieces:
        for macro, repl in sorted(MATHJAX_ONLY.items(), key=lambda kv: -len(kv[0])):
            piece = re.sub(re.escape(macro) + r"(?![A-Za-z])", repl.replace("\\", "\\\\"), piece)
        try:
            parser.parse(f"${piece}$")
        except Exception as err:  # mathtext raises pyparsing's exceptions and ValueError
            last = str(err).strip().splitlines()[-1]
            return f"mathtext cannot render {piece.strip()!r}: {last}"
    return None


# ---- errata -----------------------------------------------------------------------------------


def errata_numbers() -> set[int]:
    """The equation numbers of docs/errata.md's table (its first column)."""
    out: set[int] = set()
    for line in ERRATA.read_text(encoding="utf-8").splitlines():
        if line.startswith("| ") and not line.startswith("| eq.") and not line.startswith("|---"):
            first = line.split("|")[1]
            out.update(c.number for c in citations_in(first, "docs/errata.md"))
    return out


ERRATUM_LINK = "](errata.md)"
SCAN_LINK = "](#the-transcription)"


def scan_notes(text: str) -> set[int]:
    """The numbers that the page's section "The transcription" explains, one bullet each."""
    section = text.split("\n## The transcription", 1)[1]
    out: set[int] = set()
    for line in section.splitlines():
        m = re.match(r"\* ((?:2\.\d{1,3}(?:, )?)+):", line)
        if m:
            out.update(int(n) for n in re.findall(r"2\.(\d{1,3})", m.group(1)))
    return out


# ---- the tests --------------------------------------------------------------------------------


def test_every_kind_of_source_is_scanned() -> None:
    """Positive control of the lexers: each kind of file contributes citations."""
    kinds = {Path(c.path).suffix for cs in cited().values() for c in cs}
    assert {".py", ".rs", ".md", ".ts"} <= kinds, kinds
    where = {c.path for cs in cited().values() for c in cs}
    for must in (
        "python/poinsot/cli.py",
        "README.md",
        "CONVENTIONS.md",
        "web/src/scenes/heavytop.ts",
    ):
        assert must in where, f"no citation found in {must}"


def test_every_cited_number_has_a_row() -> None:
    missing = missing_rows(cited(), index_rows())
    assert not missing, "cited but not in docs/equations.md:\n" + "\n".join(
        f"  2.{n}: " + ", ".join(c.where() for c in cited()[n][:3]) for n in missing
    )


def test_every_row_is_cited_or_says_why() -> None:
    stale = uncited_rows(index_rows(), cited())
    assert not stale, (
        "rows nobody cites (say '"
        + NOT_CITED
        + ": …' in the row, or remove it): "
        + ", ".join(f"2.{r.number} (line {r.line})" for r in stale)
    )


def test_one_table_one_row_per_number_in_order() -> None:
    rows = index_rows()
    numbers = [r.number for r in rows]
    assert numbers == sorted(set(numbers)), "rows must be unique and in the unit's order"
    lines = [r.line for r in rows]
    assert lines == list(range(lines[0], lines[0] + len(lines))), "one table: no gaps between rows"


def test_every_row_names_a_function_and_a_test() -> None:
    bad = [
        r.number
        for r in index_rows()
        if (not r.roles() or not r.test_refs()) and NOT_IN_UNIT not in r.text
    ]
    assert not bad, f"rows without a function role or a test: {bad}"


def test_named_functions_exist() -> None:
    problems = [
        f"2.{r.number}: {p}"
        for r in index_rows()
        for kind, t in r.roles()
        if (p := role_problem(kind, t))
    ]
    assert not problems, "\n".join(problems)


def test_named_tests_exist() -> None:
    problems = [
        f"2.{r.number}: {p}"
        for r in index_rows()
        for f, n in r.test_refs()
        if (p := named_test_problem(f, n))
    ]
    assert not problems, "\n".join(problems)


def test_formulas_are_good_latex() -> None:
    rows = [r for r in index_rows() if NOT_IN_UNIT not in r.text]
    assert all(r.formulas() for r in rows), [r.number for r in rows if not r.formulas()]
    problems = [
        f"2.{r.number}: {p}" for r in rows for tex in r.formulas() if (p := latex_problem(tex))
    ]
    assert not problems, "\n".join(problems)
    # Pipes would split the markdown table's cells: |x| is written \lvert x \rvert.
    assert all("|" not in tex for r in rows for tex in r.formulas())


def test_errata_are_marked_and_only_they() -> None:
    errata = errata_numbers()
    assert {2, 3, 5, 10, 18, 26, 30, 51, 66, 70, 73, 74, 78, 84, 99, 117, 120} <= errata
    rows = {r.number: r for r in index_rows()}
    unmarked = sorted(n for n in errata if n in rows and ERRATUM_LINK not in rows[n].formula)
    assert not unmarked, f"errata whose row does not link docs/errata.md: {unmarked}"
    extra = sorted(n for n, r in rows.items() if ERRATUM_LINK in r.formula and n not in errata)
    assert not extra, f"rows marked as errata that docs/errata.md does not list: {extra}"


def test_scan_marks_are_explained() -> None:
    """Rows marked *scan* (a mark the scan lost, restored) are exactly those explained below the
    table."""
    marked = {r.number for r in index_rows() if SCAN_LINK in r.formula}
    assert marked == scan_notes(INDEX.read_text(encoding="utf-8"))


def test_math_outside_the_table_is_good_latex() -> None:
    text = "\n".join(
        line for line in INDEX.read_text(encoding="utf-8").splitlines() if not _ROW.match(line)
    )
    assert _MATH.search(text), "the notes below the table have formulas too"
    problems = [p for a, b in _MATH.findall(text) if (p := latex_problem(a or b))]
    assert not problems, "\n".join(problems)


def test_exceptions_are_still_needed() -> None:
    for (path, snippet), why in NOT_CITATIONS.items():
        assert snippet in (ROOT / path).read_text(encoding="utf-8"), (
            f"stale: {path}: {snippet!r} ({why})"
        )


# ---- negative controls ------------------------------------------------------------------------


def test_negative_control_a_fake_citation_is_missing_from_the_table(tmp_path: Path) -> None:
    (tmp_path / "python" / "poinsot").mkdir(parents=True)
    (tmp_path / "docs").mkdir()
    (tmp_path / "python" / "poinsot" / "fake.py").write_text(
        '"""The unit\'s eq. 2.150 and 2.151–2.153."""\n'
        "x = [1.0, 2.0, 2.5]  # see (2.42); lw=2.5 is code\n"
        'MSG = f"rtol ≥ 2.2e-14, Fig. 2.12, {x} 2.9 / 7.0, $2.2\\times 10^{{-308}}$"\n',
        encoding="utf-8",
    )
    (tmp_path / "docs" / "page.md").write_text(
        "Solving 2.112 is hard (Figs. 2.5–2.7).\n\n```python\nspin = 2.5  # eq. 2.119\n```\n"
        # an exercise's answers (docs/teachers.md): quantities and a command's option value
        "Answer: 2.355 m/s², 2.867 cm/s, 2.788 ′; `poinsot check x --answer 2.788 --seed 2`\n",
        encoding="utf-8",
    )
    found = scan(tmp_path)
    assert sorted(found) == [42, 112, 119, 150, 151, 152, 153], sorted(found)
    assert missing_rows(found, index_rows()) == [150, 151, 152, 153]
    # And a row dropped from the table is noticed.
    text = INDEX.read_text(encoding="utf-8")
    dropped = [r for r in parse_index(text) if r.number != 42]
    assert missing_rows(cited(), dropped) == [42]


def test_negative_control_uncited_rows_and_bad_names_are_caught() -> None:
    row = index_rows()[0]
    extra = Row(
        150, 0, "$x$", "{func}`poinsot.euler_to_matrix`", "`test_top.py::test_degrees_flag`"
    )
    assert uncited_rows([row, extra], cited()) == [extra]
    assert role_problem("func", "poinsot.no_such_function") is not None
    assert role_problem("meth", "poinsot.Earth.no_such_method") is not None
    assert role_problem("func", "poinsot.Earth") is not None  # a class named as a function
    assert role_problem("attr", "poinsot.HeavyTop.min_spin") is not None  # a method as attribute
    assert role_problem("meth", "poinsot.HeavyTop.min_spin") is None
    assert role_problem("attr", "poinsot.HeavyTop.p_psi") is None
    assert named_test_problem("test_top.py", "test_no_such_test") is not None
    assert named_test_problem("heavy_top.rs", "no_such_fn") is not None
    assert named_test_problem("heavy_top.rs", "top") is not None  # a helper, not a #[test]
    assert named_test_problem("no_such_file.py", "test_x") is not None
    assert named_test_problem("heavy_top.rs", "random_tops_keep_their_invariants") is None


@pytest.mark.parametrize(
    "tex",
    [
        r"\frac{a}{b",
        r"x^{2}}",
        r"\left( x",
        r"\vec{r} = \foo",
        r"a \\ b",
        r"\begin{aligned} a \end{align}",
    ],
)
def test_negative_control_broken_latex_is_caught(tex: str) -> None:
    assert latex_problem(tex) is not None
    assert latex_problem(r"\vec{r}' = \vec{R} + \vec{r}") is None


if __name__ == "__main__":
    for n, cs in sorted(cited().items()):
        print(f"2.{n}: {len(cs)} citation(s): " + "; ".join(c.where() for c in cs[:4]))
