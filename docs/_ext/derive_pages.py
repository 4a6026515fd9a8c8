"""The pages of the site that :mod:`poinsot.derive` writes, so the text and the code cannot differ.

* ``docs/derivations.md`` and ``docs/derivations/`` (git-ignored, written at every build): the
  derivations' index, one page per derivation of the unit, step by step, from
  :func:`poinsot.derive.derivations`, and the question bank with the package's answers from
  :func:`poinsot.derive.questions`.
* ``docs/errata.md`` (kept in git, because the equation index and its test read it before any
  build): the unit's misprints from :func:`poinsot.derive.errata`. The docs build rewrites it;
  ``python/tests/test_derive_pages.py`` fails when the kept file differs from what the errata
  give, and ``python docs/_ext/derive_pages.py`` (``make errata-page``) rewrites it.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path
from typing import Any

from page_files import write_folder, write_page  # docs/_ext/, on the path beside this module

DOCS = Path(__file__).resolve().parent.parent
ROOT = DOCS.parent
DERIVATIONS = DOCS / "derivations.md"
PAGES = DOCS / "derivations"
ERRATA = DOCS / "errata.md"
PY_TESTS = ROOT / "python" / "tests"

_ERRATUM_TEST = re.compile(r"def (test_erratum_(\w+?))\(")


def pinning_tests() -> dict[str, list[str]]:
    """Equation number → the tests named ``test_erratum_2_x[_2_y...]_...`` that pin its
    corrected result (``python/tests/<file>::<test>``)."""
    out: dict[str, list[str]] = {}
    for path in sorted(PY_TESTS.glob("test_*.py")):
        for m in _ERRATUM_TEST.finditer(path.read_text(encoding="utf-8")):
            numbers = re.findall(r"(?:^|_)2_(\d{1,3})(?=_|$)", m.group(2))
            for n in numbers:
                out.setdefault(f"2.{n}", []).append(f"python/tests/{path.name}::{m.group(1)}")
    return out


def _cell(text: str) -> str:
    return text.replace("|", r"\|").replace("\n", " ")


def _number_key(number: str) -> str:
    """ "2.73–2.74" → "2.73"; "2.18 (third line)" → "2.18"."""
    m = re.match(r"2\.\d{1,3}", number)
    return m.group(0) if m else number


def _anchor(number: str) -> str:
    """The anchor MyST gives the heading "(2.18)" (lower case, punctuation dropped, spaces to
    hyphens)."""
    text = re.sub(r"[^\w\s-]", "", f"({number})".lower()).strip()
    return re.sub(r"\s+", "-", text)


def errata_markdown() -> str:
    """docs/errata.md, from :func:`poinsot.derive.errata`."""
    from poinsot import derive

    pins = pinning_tests()
    errata = derive.errata()
    lines = [
        "# Errata of the course unit",
        "",
        "<!-- Written by docs/_ext/derive_pages.py from poinsot.derive.errata(): do not edit;",
        "     run `make errata-page` after changing a derivation or a transcription. -->",
        "",
        "The unit (`shared/seed/unit-2-moving-frames-and-rigid-bodies.md`) is a scanned text: "
        "some dots, primes and indices were lost, and a few equations are wrong. poinsot "
        "implements the physics, not the typos.",
        "",
        "This page is computed, not written: every numbered equation of the unit is transcribed "
        "once as printed ({func}`poinsot.derive.printed`), and each is judged in the model of the "
        "derivation it belongs to ([Derivations](derivations.md)). The equations listed here "
        "are those that do not follow — {func}`poinsot.derive.errata` — with the derived form "
        "beside them; a printed equation that follows cannot appear, and one that does not "
        "cannot be missed. `poinsot derive errata` prints the same list.",
        "",
        f"{len(errata)} of the {len(derive.printed())} transcribed equations do not follow.",
        "",
        "| eq. | derivation | how the scan was read |",
        "|---|---|---|",
    ]
    for e in errata:
        link = f"[{e.number}](#{_anchor(e.number)})"
        lines.append(f"| {link} | {e.derivation} | {_cell(e.note) or '—'} |")
    lines += ["", "## Each erratum, printed and derived", ""]
    for e in errata:
        lines += [
            f"### ({e.number})",
            "",
            f"Derivation [{e.derivation}](derivations/{e.derivation}.md). The unit prints:",
            "",
            f"$$ {e.printed_latex()} $$",
            "",
            "Derived:",
            "",
            f"$$ {e.derived_latex()} $$",
            "",
        ]
        tests = pins.get(_number_key(e.number), [])
        if tests:
            lines += ["The corrected result is pinned by:", ""]
            lines += [f"- `{t}`" for t in tests] + [""]
    lines += [
        "",
        "Conventions the unit uses, and poinsot keeps as defaults: primed = fixed (inertial), "
        "unprimed = moving; Earth ENU (x east, y north, z up), ω = ω(0, cos λ, sin λ); Euler "
        "angles intrinsic z-x-z (φ precession, θ nutation, ψ spin); heavy top pivot at the "
        "origin with the centre of mass at +l on body axis 3 and gravity −g along fixed Z; "
        "torque-free top Ω = (I₁ − I₃) ω₃ / I₁ with ω̇₁ = Ω ω₂.",
        "",
    ]
    return "\n".join(lines)


def derivations_markdown() -> str:
    """docs/derivations.md: what the derivations are and how they are checked, with a table of
    the seven and links to their pages (:func:`derivation_pages`)."""
    from poinsot import derive

    lines = [
        "# Derivations",
        "",
        "<!-- Written by docs/_ext/derive_pages.py at every build: do not edit. -->",
        "",
        "The unit as executable mathematics ({mod}`poinsot.derive`, on sympy: "
        "`pip install 'poinsot[symbolic]'`). Each topic is a derivation from the unit's "
        "starting point to its result, in the unit's notation, and every step is checked when "
        "it is made: the step's two sides are reduced, in components, to the same expression, "
        "or the derivation does not build. The numbers in brackets are the unit's equation "
        "numbers; each derived formula is also checked against poinsot's numeric core at "
        "random inputs (the tests `python/tests/test_derive_*.py`). The printed equations "
        "that do not follow are on the [errata](errata.md) page; the unit's question bank is "
        "answered on [its own page](derivations/questions.md).",
        "",
        "```python",
        "from poinsot import derive",
        "d = derive.derivation('heavy_top')",
        "d.result['2.118']        # a sympy equation",
        "print(d.markdown())      # its page below",
        "```",
        "",
        "On the command line: `poinsot derive --list`, `poinsot derive heavy_top "
        "[--latex | --markdown]`, `poinsot derive errata`, `poinsot derive questions`.",
        "",
        "| derivation | the unit's equations | steps | derives |",
        "|---|---|---|---|",
    ]
    for d in derive.derivations():
        unit = [n for n in d.result if re.fullmatch(r"2\.\d{1,3}[a-z]?", n)]
        span = f"{unit[0]}–{unit[-1]}" if unit else ""
        others = len(d.result) - len(unit)
        more = f" and {others} more" if others else ""
        lines.append(
            f"| [{_cell(d.title)}](derivations/{d.name}.md) | {span} | {len(d.steps)} "
            f"| {', '.join(unit)}{more} |"
        )
    applied = [derive.derivation(n) for n in derive.applied()]
    if applied:
        lines += [
            "",
            "The unit's theory applied beyond its equations (its results keyed by name; "
            "each checked against poinsot's core in `python/tests/test_derive_<name>.py`):",
            "",
            "| derivation | steps | derives |",
            "|---|---|---|",
        ]
        for d in applied:
            lines.append(
                f"| [{_cell(d.title)}](derivations/{d.name}.md) | {len(d.steps)} "
                f"| {', '.join(d.result)} |"
            )
    lines += [
        "",
        "```{toctree}",
        ":hidden:",
        "",
        *[f"derivations/{d.name}" for d in [*derive.derivations(), *applied]],
        "derivations/questions",
        "```",
        "",
    ]
    return "\n".join(lines)


def derivation_pages() -> dict[Path, str]:
    """docs/derivations/<name>.md for each derivation and docs/derivations/questions.md."""
    from poinsot import derive
    from poinsot.derive.questions import render

    out = {}
    for d in [*derive.derivations(), *(derive.derivation(n) for n in derive.applied())]:
        head = f"<!-- Written by docs/_ext/derive_pages.py from poinsot.derive.derivation({d.name!r}). -->"
        out[PAGES / f"{d.name}.md"] = f"{d.markdown(heading='#')}\n\n{head}\n"
    out[PAGES / "questions.md"] = "\n".join(
        [
            "# The question bank, answered",
            "",
            "The unit's questions (its last section), each answered from poinsot: the "
            "multiple-choice ones by computation, the derivation questions by the derivation "
            "named (`poinsot derive questions` prints the same).",
            "",
            render(derive.questions(), markdown=True),
            "",
        ]
    )
    return out


def write_pages(app: Any = None, config: Any = None) -> None:
    """The Sphinx hook (``config-inited``): both pages, rewritten only when they change."""
    write_page(DERIVATIONS, derivations_markdown())
    write_folder(PAGES, derivation_pages())
    write_page(ERRATA, errata_markdown())


if __name__ == "__main__":  # `make errata-page`
    changed = write_page(ERRATA, errata_markdown())
    sys.stdout.write(f"{ERRATA.relative_to(ROOT)}: {'rewritten' if changed else 'unchanged'}\n")
