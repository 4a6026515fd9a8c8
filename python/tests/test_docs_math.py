"""The topic chapters' formulas are LaTeX, and good LaTeX (issue 13: "Formulas in LaTeX").

The chapters of the unit (docs/frames.md … docs/heavy_top.md, docs/rigid_earth.md) write their
formulas as MyST math: ``$…$`` inline, ``$$…$$`` or an amsmath environment
(``\\begin{align*}``) on display, the unit's number as ``\\tag{2.NN}``. Parsed with the site's
own MyST parser and configuration (docs/conf.py), every formula must

* render with matplotlib's mathtext (the check of the equation index, ``latex_problem``: balanced
  braces and environments, aligned lines and matrix cells rendered one by one), after the
  constructs mathtext lacks are reduced to what it has (``MATHTEXT_LACKS``, each with its
  reason: nothing is skipped);
* carry in ``\\tag`` only equation numbers that the unit has (a row of docs/equations.md);

and the prose around them (everything outside math and code) must

* have balanced dollars in every paragraph, and none left over after parsing;
* hold no formula still written in Unicode (``TELLTALES``: Greek letters, dotted letters,
  subscript digits, ``½``, ``√(``, ``×(``, ``²/``, ``x_i`` …).

Negative controls: a page with Unicode formulas, an unclosed dollar and broken LaTeX is caught;
the same formulas in code or in math are not.
"""

from __future__ import annotations

import ast
import re
import sys
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(ROOT / "docs" / "_ext"))

from test_equation_index import latex_problem  # noqa: E402  (the index's LaTeX check)
from unit_equations import citations_in, index_rows  # noqa: E402

pytest.importorskip("myst_parser", reason="the docs extra (poinsot[docs]) parses the pages")

from markdown_it import MarkdownIt  # noqa: E402
from markdown_it.renderer import RendererHTML  # noqa: E402
from markdown_it.token import Token  # noqa: E402
from myst_parser.config.main import MdParserConfig  # noqa: E402
from myst_parser.parsers.mdit import create_md_parser  # noqa: E402

#: The unit's topics, in the unit's order (docs/index.md's toctree).
CHAPTERS = (
    "docs/frames.md",
    "docs/earth.md",
    "docs/inertia.md",
    "docs/dynamics.md",
    "docs/rotation.md",
    "docs/heavy_top.md",
    "docs/rigid_earth.md",
    "docs/gyrocompass.md",
)

MATH_TOKENS = frozenset(
    {"math_inline", "math_inline_double", "math_block", "math_block_label", "amsmath"}
)
CODE_TOKENS = frozenset({"code_inline", "fence", "code_block", "html_inline", "html_block"})

_TAG = re.compile(r"\\tag\*?\{([^{}]*)\}")
_UNDERBRACE = re.compile(r"\\underbrace\{")
_OUTER_ENV = re.compile(r"^\s*\\begin\{(\w+)\*?\}(.*)\\end\{\1\*?\}\s*$", re.S)


def _drop_underbraces(tex: str) -> str:
    """``\\underbrace{A}_{B}`` → ``{A}_{B}``: the same pieces, without the brace."""
    while m := _UNDERBRACE.search(tex):
        tex = tex[: m.start()] + "{" + tex[m.end() :]
    return tex


def _outer_environment(tex: str) -> str:
    """An amsmath display environment (``align*``, ``equation*``, …) → what mathtext checks:
    its rows as ``aligned`` (``equation``'s body as it is)."""
    m = _OUTER_ENV.match(tex)
    if not m or m.group(1) == "aligned" or m.group(1).endswith("matrix"):
        return tex
    env, body = m.group(1), m.group(2)
    if env in ("equation", "gather", "multline"):
        return body
    return r"\begin{aligned}" + body + r"\end{aligned}"


#: What MathJax typesets and matplotlib's mathtext cannot, and what mathtext is given instead
#: (``latex_problem`` also maps ``\lvert``, ``\le``, ``\tfrac``, … to mathtext's names).
MATHTEXT_LACKS: dict[str, tuple[str, Callable[[str], str]]] = {
    r"\tag": (
        "mathtext numbers no equations: the unit's number is checked against the index instead",
        lambda tex: _TAG.sub("", tex),
    ),
    r"\begin{align*}": (
        "mathtext has no display environments: their rows are checked as an aligned block",
        _outer_environment,
    ),
    r"\underbrace": (
        "mathtext has no under-braces: the term and its label are checked without the brace",
        _drop_underbraces,
    ),
}

#: Formulas still written in Unicode, as they were before the chapters were moved to LaTeX.
#: Numbers with units (m/s², kg·m², 10⁷ steps, 50×) are prose, not formulas, and stay.
TELLTALES: dict[str, re.Pattern[str]] = {
    "a Greek letter": re.compile(r"[\u0391-\u03a9\u03b1-\u03c9\u03d1\u03d5\u03f5]"),
    "a dotted letter (ṙ, θ̇)": re.compile(r"[A-Za-z\u0370-\u03ff][\u0307\u0308]|[ṘṙẊẋẍẎẏÿŻż]"),
    "a subscript (I₁, ω_p)": re.compile(r"[\u2080-\u209c\u1d62-\u1d6a]|(?<![\w/.-])[A-Za-z]_\{?\w"),
    "a vulgar fraction (½)": re.compile(r"[½⅓⅔¼¾⅛⅜]"),
    "a root (√)": re.compile(r"√"),
    "an integral or a sum (∫, Σ, ∂)": re.compile(r"[∫∑∂∮]|(?<![A-Za-z])Σ"),
    "a cross product (r × ()": re.compile(r"[A-Za-z)\]] ?× ?[(A-Za-z]"),
    "a squared quotient (v²/)": re.compile(r"(?<![·/])[A-Za-z)]²/"),
    "a power of a letter (x², r³, qᵏ)": re.compile(r"(?<![\w·/])[A-Za-z][²³⁴ᵏᵀ]"),
    "a relation between symbols (∥, ∝, ≲, ↦)": re.compile(r"[∥∝≲≳⊗↦⟨⟩⌈⌉∓]"),
    "a caret power (x^2)": re.compile(r"\w\^[\w{(±-]"),
}


# ---- parsing ----------------------------------------------------------------------------------


@cache
def _parser() -> MarkdownIt:
    """MyST's markdown-it parser with the site's settings (docs/conf.py)."""
    conf = ast.parse((ROOT / "docs" / "conf.py").read_text(encoding="utf-8"))
    values = {
        t.id: ast.literal_eval(node.value)
        for node in conf.body
        if isinstance(node, ast.Assign)
        for t in node.targets
        if isinstance(t, ast.Name) and t.id.startswith("myst_")
    }
    config = MdParserConfig(
        enable_extensions=set(values["myst_enable_extensions"]),
        dmath_double_inline=values.get("myst_dmath_double_inline", False),
    )
    return create_md_parser(config, RendererHTML)


@dataclass(frozen=True)
class Formula:
    where: str  # path:line
    tex: str
    display: bool


def _walk(tokens: list[Token]) -> Iterator[tuple[Token, int]]:
    """Every token with the source line of its block."""
    for tok in tokens:
        line = tok.map[0] + 1 if tok.map else 0
        yield tok, line
        for child in tok.children or []:
            yield child, line


def formulas(text: str, where: str) -> list[Formula]:
    out = []
    for tok, line in _walk(_parser().parse(text)):
        if tok.type in MATH_TOKENS:
            display = tok.type != "math_inline"
            out.append(Formula(f"{where}:{line}", tok.content, display))
    return out


def prose(text: str) -> list[tuple[int, str]]:
    """(line, text) of each paragraph-like block, math and code left out."""
    out = []
    for tok, line in _walk(_parser().parse(text)):
        if tok.type == "inline":
            parts = [c.content if c.type == "text" else " " for c in tok.children or []]
            out.append((line, "".join(parts)))
    return out


def paragraphs(text: str) -> Iterator[tuple[int, str]]:
    """(line, raw text) of each blank-line-separated paragraph outside fenced and indented code,
    inline code spans blanked."""
    lines = text.splitlines()
    fence: str | None = None
    block: list[str] = []
    start = 0
    for k, line in enumerate(lines + [""], 1):
        stripped = line.strip()
        if fence is not None:
            if stripped.startswith(fence):
                fence = None
            continue
        if m := re.match(r"\s*(`{3,}|~{3,})", line):
            fence = m.group(1)
            continue
        if not stripped or (line.startswith("    ") and not block):
            if block:
                yield start, re.sub(r"(`+)(?:(?!\1).)+?\1", " ", "\n".join(block), flags=re.S)
            block = []
            continue
        if not block:
            start = k
        block.append(line)


# ---- the checks -------------------------------------------------------------------------------


def formula_problem(tex: str) -> str | None:
    """Why MathJax would not typeset ``tex`` as meant, judged by mathtext (None: it renders)."""
    tex = " ".join(tex.split())  # a formula's source lines: TeX reads a line break as a space
    for _construct, (_why, reduce) in MATHTEXT_LACKS.items():
        tex = reduce(tex)
    return latex_problem(tex)


def tag_problem(tex: str) -> str | None:
    """A ``\\tag`` that names no equation of the unit (no row, or a row without a formula)."""
    rows = {r.number: r for r in index_rows()}
    for tag in _TAG.findall(tex):
        numbers = [c.number for c in citations_in(tag, "docs/tag")]
        if not numbers:
            return rf"\tag{{{tag}}} names no equation number"
        for n in numbers:
            if n not in rows or not rows[n].formulas():
                return rf"\tag{{{tag}}}: the unit has no equation 2.{n}"
    return None


def page_problems(text: str, where: str) -> list[str]:
    problems = []
    for f in formulas(text, where):
        if p := formula_problem(f.tex):
            problems.append(f"{f.where}: {p}")
        if p := tag_problem(f.tex):
            problems.append(f"{f.where}: {p}")
    for line, para in paragraphs(text):
        n = len(re.findall(r"(?<!\\)\$", para))
        if n % 2:
            problems.append(f"{where}:{line}: {n} dollar signs in the paragraph (unbalanced)")
    for line, words in prose(text):
        if "$" in words:
            problems.append(f"{where}:{line}: a dollar sign left in the prose: {words.strip()!r}")
        for what, pattern in TELLTALES.items():
            if m := pattern.search(words):
                a, b = max(0, m.start() - 30), m.end() + 30
                problems.append(
                    f"{where}:{line}: {what} outside math: {words[a:b].strip()!r} — write it in LaTeX"
                )
    return problems


def _read(path: str) -> str:
    return (ROOT / path).read_text(encoding="utf-8")


# ---- the tests --------------------------------------------------------------------------------


@pytest.mark.parametrize("path", CHAPTERS)
def test_chapter_formulas_are_latex_that_renders(path: str) -> None:
    text = _read(path)
    found = formulas(text, path)
    assert sum(f.display for f in found) >= 3, f"{path}: fewer than three displayed formulas"
    assert sum(not f.display for f in found) >= 20, f"{path}: fewer than twenty inline formulas"
    assert any(_TAG.search(f.tex) for f in found), f"{path} shows none of the unit's equations"
    problems = page_problems(text, path)
    assert not problems, "\n".join(problems)


def test_chapters_tag_the_unit_equations_they_show() -> None:
    """Between them the chapters display, numbered, the unit's central equations."""
    tagged: set[int] = set()
    for path in CHAPTERS:
        for f in formulas(_read(path), path):
            for tag in _TAG.findall(f.tex):
                tagged.update(c.number for c in citations_in(tag, path))
    for n in (1, 5, 21, 23, 31, 42, 44, 60, 66, 69, 71, 72, 83, 98, 99, 101, 102, 110, 117, 120):
        assert n in tagged, f"eq. 2.{n} is not displayed with its number"


def test_every_reduction_is_needed_and_changes_what_it_names() -> None:
    """Each construct of MATHTEXT_LACKS is used by the chapters, mathtext really fails on it, and
    its reduction removes it."""
    tex_all = [f.tex for path in CHAPTERS for f in formulas(_read(path), path)]
    samples = {
        r"\tag": r"x = 1 \tag{2.42}",
        r"\begin{align*}": r"\begin{align*} a &= b \\ c &= d \end{align*}",
        r"\underbrace": r"\underbrace{a + b}_{\text{sum}}",
    }
    for construct, (why, reduce) in MATHTEXT_LACKS.items():
        assert why
        assert any(construct in tex for tex in tex_all), f"{construct} is not used: drop it"
        assert latex_problem(samples[construct]) is not None, f"mathtext renders {construct}"
        reduced = reduce(samples[construct])
        assert construct not in reduced
        assert formula_problem(samples[construct]) is None


# ---- negative controls ------------------------------------------------------------------------

BAD_PAGE = """\
# A page written as before

For a particle at **r**, moving with (dr/dt)_rot:

    r̈' = R̈ + r̈ + 2 ω × ṙ + ω × (ω × r)

The kinetic energy is T = ½ I₁ ω₁² and x = ⅓ ω cos λ √(8 h³ / g).

A dollar $x = 1$ and an unclosed $y.

Broken: $\\frac{a}{b$ and $\\vec{r} = \\foo$.

$$ x = 2 \\tag{2.92} $$
"""

GOOD_PAGE = """\
# The same page in LaTeX

For a particle at $\\vec{r}$, moving with $(d\\vec{r}/dt)_{\\mathrm{rot}}$:

\\begin{align*}
\\ddot{\\vec{r}}' &= \\underbrace{\\ddot{\\vec{R}}}_{\\text{origin}} + \\ddot{\\vec{r}}
  + 2\\vec{\\omega}\\times\\dot{\\vec{r}} + \\vec{\\omega}\\times(\\vec{\\omega}\\times\\vec{r}) \\tag{2.21, 2.23}
\\end{align*}

The kinetic energy is $T = \\tfrac{1}{2}I_1\\omega_1^2$ and
$$ x = \\frac{1}{3}\\,\\omega\\cos\\lambda\\,\\sqrt{\\frac{8h^3}{g}}. \\tag{2.42} $$

```python
out.acceleration_terms["coriolis"]   # 2 ω × ṙ = (−4, 0, 0), ½ m|ṙ|²
```

The code `ω × (ω × r)` and the units 3.4e-2 m/s², kg·m², 10⁷ steps, 50× are not formulas.
"""


def test_negative_control_unicode_formulas_dollars_and_bad_latex_are_caught() -> None:
    problems = "\n".join(page_problems(BAD_PAGE, "bad.md"))
    for expected in (
        "a Greek letter",
        "a subscript",
        "a vulgar fraction",
        "a root",
        "a power of a letter",
        "dollar signs in the paragraph (unbalanced)",
        "a dollar sign left in the prose",
        "unbalanced '{'",
        r"mathtext cannot render '\\vec{r} = \\foo'",
        "the unit has no equation 2.92",
    ):
        assert expected in problems, f"not caught: {expected}\n{problems}"
    # The indented formula of the old pages is a code block: prose checks cannot see it, which is
    # why the chapters must not keep formulas there (test_no_formula_left_in_indented_blocks).
    assert "r̈'" not in problems


def test_negative_control_the_same_formulas_in_latex_or_code_pass() -> None:
    assert page_problems(GOOD_PAGE, "good.md") == []
    found = formulas(GOOD_PAGE, "good.md")
    assert [f.display for f in found] == [False, False, True, False, True]


@pytest.mark.parametrize(
    "sentence",
    [
        "where ω × (ω × r) points to the axis",
        "with I_xx = Σ m (y² + z²)",
        "the rate φ̇ of precession",
        "with ẋ ≈ ẏ ≈ 0",
        "by the amount ¾ g h²/g",
        "so u^2 grows",
        "at √(g/L)",
    ],
)
def test_negative_control_each_telltale_fires(sentence: str) -> None:
    assert page_problems(sentence + "\n", "one.md"), sentence


def test_no_formula_left_in_indented_blocks() -> None:
    """An indented block is code to Markdown: formulas there would escape the prose checks and
    render as monospace Unicode. The chapters' indented and unlabelled fenced blocks hold only
    commands and program output."""
    formula_like = re.compile(r"[\u0391-\u03c9\u0307\u0308½⅓√∫Σ∂₀-₉]| × \(|²/")
    problems = []
    for path in CHAPTERS:
        for tok, line in _walk(_parser().parse(_read(path))):
            unlabelled = tok.type == "code_block" or (tok.type == "fence" and not tok.info.strip())
            if unlabelled and formula_like.search(tok.content):
                problems.append(f"{path}:{line}: {tok.content.strip()[:70]!r}")
    assert not problems, "\n".join(problems)


def test_negative_control_a_formula_in_an_indented_block_is_caught() -> None:
    page = "Text:\n\n    x = ⅓ ω cos λ √(8 h³ / g)\n"
    toks = [t for t, _ in _walk(_parser().parse(page)) if t.type == "code_block"]
    assert toks and re.search(r"[\u0391-\u03c9⅓√]", toks[0].content)
