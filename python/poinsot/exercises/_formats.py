"""A set of variants as files: Markdown and LaTeX (a problem sheet and a separate solution
sheet), PDF (the LaTeX built by a TeX engine where one is installed), Moodle GIFT and Moodle XML
(numerical questions: the answer, its tolerance, and the common mistakes as wrong answers with
feedback), and JSON. The files hold no date or machine name: the same set gives the same bytes.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import tempfile
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from xml.etree import ElementTree as ET

from ..errors import PoinsotError
from ._template import Variant
from ._text import UNITS, latex_text, sig

__all__ = ["FORMATS", "catalogue_markdown", "render", "sample_sheet_markdown", "write"]

#: The formats, each with the files it makes.
FORMATS: dict[str, tuple[str, ...]] = {
    "markdown": ("problems.md", "solutions.md"),
    "latex": ("problems.tex", "solutions.tex"),
    "pdf": ("problems.pdf", "solutions.pdf"),
    "gift": ("quiz.gift",),
    "moodle-xml": ("quiz.xml",),
    "json": ("exercises.json",),
}

#: The Debian packages that give a TeX engine for ``format="pdf"``.
TEX_PACKAGES = "texlive-latex-base latexmk"


def _check_code(v: Variant) -> str:
    return f"poinsot check {v.name} --seed {v.seed} --answer VALUE"


def _unit(v: Variant, latex: bool = False) -> str:
    return UNITS[v.unit][1 if latex else 0]


# ---- Markdown ---------------------------------------------------------------------------------------


def _markdown(variants: Sequence[Variant]) -> dict[str, str]:
    problems = ["# Problems", ""]
    solutions = ["# Solutions", ""]
    for k, v in enumerate(variants, 1):
        head = f"## {k}. {v.template.title}"
        problems += [head, "", v.statement, "", f"*Check your answer:* `{_check_code(v)}`", ""]
        solutions += [head, "", f"**Answer:** {sig(v.answer)} {_unit(v)} (± {v.tolerance:.2g})", ""]
        for j, s in enumerate(v.steps, 1):
            solutions.append(f"{j}. {s.text}")
            if s.latex:
                solutions += ["", f"   $$ \\begin{{aligned}} {s.latex} \\end{{aligned}} $$", ""]
        if v.mistakes:
            solutions += ["", "Common mistakes:", ""]
            solutions += [
                f"- {m.name}: {m.text} → {sig(w)} {_unit(v)} (step {m.step})" for m, w in v.mistakes
            ]
        solutions.append("")
    return {"problems.md": "\n".join(problems), "solutions.md": "\n".join(solutions)}


# ---- LaTeX ------------------------------------------------------------------------------------------

_PREAMBLE = r"""\documentclass[11pt]{article}
\usepackage[utf8]{inputenc}
\usepackage[T1]{fontenc}
\usepackage{amsmath,amssymb}
\usepackage[margin=2.2cm]{geometry}
\pdfinfoomitdate=1
\pdftrailerid{}
\renewcommand{\labelenumii}{\arabic{enumii}.}
\begin{document}
"""


def _latex(variants: Sequence[Variant]) -> dict[str, str]:
    problems = [_PREAMBLE, r"\section*{Problems}", r"\begin{enumerate}"]
    solutions = [_PREAMBLE, r"\section*{Solutions}", r"\begin{enumerate}"]
    for v in variants:
        title = latex_text(v.template.title)
        code = latex_text(_check_code(v)).replace("--", "-{}-")
        problems += [
            rf"\item \textbf{{{title}.}} {v.latex}",
            "",
            rf"\emph{{Check your answer:}} \texttt{{{code}}}",
            "",
        ]
        solutions += [
            rf"\item \textbf{{{title}.}} Answer: ${sig(v.answer)}\,{_unit(v, True)}$ "
            rf"($\pm {v.tolerance:.2g}$).",
            r"\begin{enumerate}",
        ]
        for s in v.steps:
            solutions.append(rf"\item {latex_text(s.text)}")
            if s.latex:
                solutions.append(rf"\begin{{align*}} {s.latex} \end{{align*}}")
        solutions.append(r"\end{enumerate}")
        if v.mistakes:
            solutions.append(r"Common mistakes: \begin{itemize}")
            solutions += [
                rf"\item {latex_text(m.name)}: {latex_text(m.text)} gives "
                rf"${sig(w)}\,{_unit(v, True)}$ (step {m.step})."
                for m, w in v.mistakes
            ]
            solutions.append(r"\end{itemize}")
    end = [r"\end{enumerate}", r"\end{document}", ""]
    return {"problems.tex": "\n".join(problems + end), "solutions.tex": "\n".join(solutions + end)}


def tex_engine() -> list[str] | None:
    """The command that builds a PDF from a .tex file, or ``None`` where no TeX engine is
    installed: ``pdflatex`` (one pass: the sheets have no cross-references), else
    ``latexmk -pdf``."""
    if shutil.which("pdflatex"):
        return ["pdflatex", "-interaction=nonstopmode", "-halt-on-error"]
    if shutil.which("latexmk"):
        return ["latexmk", "-pdf", "-interaction=nonstopmode", "-quiet"]
    return None


def _pdf(variants: Sequence[Variant]) -> dict[str, bytes]:
    engine = tex_engine()
    if engine is None:
        raise PoinsotError(
            "format: 'pdf' needs a TeX engine (latexmk or pdflatex), and none is installed: "
            f"on Debian or Ubuntu, apt install {TEX_PACKAGES}; or use --format latex"
        )
    out: dict[str, bytes] = {}
    with tempfile.TemporaryDirectory() as tmp:
        for name, text in _latex(variants).items():
            (Path(tmp) / name).write_text(text, encoding="utf-8")
            env = os.environ | {"SOURCE_DATE_EPOCH": "0", "FORCE_SOURCE_DATE": "1"}
            run = subprocess.run(
                [*engine, name], cwd=tmp, env=env, capture_output=True, text=True, timeout=300
            )
            pdf = Path(tmp) / name.replace(".tex", ".pdf")
            if run.returncode != 0 or not pdf.exists():
                raise PoinsotError(f"format: the TeX engine failed on {name}: {run.stdout[-800:]}")
            out[pdf.name] = pdf.read_bytes()
    return out


# ---- Moodle GIFT and XML ----------------------------------------------------------------------------


def _gift_escape(text: str) -> str:
    """Text with GIFT's special characters escaped (``~ = # { } :`` and the backslash)."""
    for c in "\\~=#{}:":
        text = text.replace(c, "\\" + c)
    return text.replace("\n", " ")


def _num(x: float) -> str:
    return f"{x:.10g}"


def _gift(variants: Sequence[Variant]) -> dict[str, str]:
    lines = ["// poinsot exercises: numerical questions with tolerances (Moodle GIFT)", ""]
    for k, v in enumerate(variants, 1):
        answers = [f"={_num(v.answer)}:{_num(v.tolerance)}#Right."]
        answers += [
            f"=%0%{_num(w)}:{_num(v.tolerance)}#{_gift_escape(f'{m.text} (step {m.step})')}"
            for m, w in v.mistakes
        ]
        title = _gift_escape(f"{k:03d} {v.name} {v.seed}")
        text = _gift_escape(f"{v.statement} [{_unit(v)}]")
        lines += [f"::{title}::{text} {{#", *(f"    {a}" for a in answers), "}", ""]
    return {"quiz.gift": "\n".join(lines)}


def _moodle_xml(variants: Sequence[Variant]) -> dict[str, str]:
    quiz = ET.Element("quiz")
    for k, v in enumerate(variants, 1):
        q = ET.SubElement(quiz, "question", type="numerical")
        ET.SubElement(ET.SubElement(q, "name"), "text").text = f"{k:03d} {v.name} {v.seed}"
        qt = ET.SubElement(q, "questiontext", format="html")
        ET.SubElement(qt, "text").text = f"<p>{_html(v.statement)} [{_html(_unit(v))}]</p>"
        fb = ET.SubElement(q, "generalfeedback", format="html")
        ET.SubElement(fb, "text").text = (
            "<ol>" + "".join(f"<li>{_html(s.plain())}</li>" for s in v.steps) + "</ol>"
        )
        ET.SubElement(q, "defaultgrade").text = "1.0000000"
        ET.SubElement(q, "penalty").text = "0.3333333"
        ET.SubElement(q, "hidden").text = "0"
        rows = [(100, v.answer, "Right.")]
        rows += [(0, w, f"{m.text} (step {m.step})") for m, w in v.mistakes]
        for fraction, value, feedback in rows:
            a = ET.SubElement(q, "answer", fraction=str(fraction), format="moodle_auto_format")
            ET.SubElement(a, "text").text = _num(value)
            f = ET.SubElement(a, "feedback", format="html")
            ET.SubElement(f, "text").text = _html(feedback)
            ET.SubElement(a, "tolerance").text = _num(v.tolerance)
        units = ET.SubElement(q, "units")
        u = ET.SubElement(units, "unit")
        ET.SubElement(u, "multiplier").text = "1"
        ET.SubElement(u, "unit_name").text = _unit(v)
        ET.SubElement(q, "unitgradingtype").text = "0"
        ET.SubElement(q, "unitpenalty").text = "0.1000000"
        ET.SubElement(q, "showunits").text = "3"
        ET.SubElement(q, "unitsleft").text = "0"
    ET.indent(quiz)
    text = ET.tostring(quiz, encoding="unicode")
    return {"quiz.xml": '<?xml version="1.0" encoding="UTF-8"?>\n' + text + "\n"}


def _html(text: str) -> str:
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def _json(variants: Sequence[Variant]) -> dict[str, str]:
    data = {"format": "poinsot-exercises/1", "exercises": [v.to_dict() for v in variants]}
    return {"exercises.json": json.dumps(data, indent=2, ensure_ascii=False) + "\n"}


_RENDER: dict[str, Callable[[Sequence[Variant]], Mapping[str, str | bytes]]] = {
    "markdown": _markdown,
    "latex": _latex,
    "pdf": _pdf,
    "gift": _gift,
    "moodle-xml": _moodle_xml,
    "json": _json,
}


def render(variants: Sequence[Variant], format: str) -> dict[str, str | bytes]:
    """The files of ``variants`` in ``format`` (one of :data:`FORMATS`): file name → text
    (bytes for PDF). Raises :class:`PoinsotError` naming ``format``."""
    if format not in _RENDER:
        raise PoinsotError(f"format: no format {format!r}; one of {', '.join(FORMATS)}")
    return dict(_RENDER[format](variants))


def write(variants: Sequence[Variant], format: str, out: str | os.PathLike[str]) -> list[Path]:
    """Writes the files of ``variants`` in ``format`` into the folder ``out`` (made if
    missing); returns their paths."""
    files = render(variants, format)
    folder = Path(out)
    folder.mkdir(parents=True, exist_ok=True)
    paths = []
    for name, content in files.items():
        path = folder / name
        if isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_text(content, encoding="utf-8")
        paths.append(path)
    return paths


def catalogue_markdown(seed: int = 2026) -> str:
    """The templates as a Markdown section for the docs' "For teachers" page: each with its
    topic, difficulty, routes and a sample (variant 0 of a set made with ``seed``)."""
    from ._issue import TOPICS, templates
    from ._template import variant_seed

    out = []
    for topic in TOPICS:
        out += [f"### {topic[0].upper()}{topic[1:]}", ""]
        for t in templates(topic):
            v = t.variant(variant_seed(seed, t.name, 0))
            out += [
                f"**`{t.name}`** — {t.title} (difficulty {t.difficulty}). "
                f"Second route: {t.agree_why}.",
                "",
                f"> {v.statement}",
                ">",
                f"> Answer: {sig(v.answer)} {_unit(v)} (± {v.tolerance:.2g}); "
                f"`{_check_code(v).replace('VALUE', sig(v.answer))}`",
                "",
            ]
    return "\n".join(out)


def sample_sheet_markdown(seed: int = 2026, n: int = 3) -> str:
    """A sample sheet for the docs: the Markdown problem and solution sheets of ``n`` variants of
    ``all`` made with ``seed``, their headings two levels down."""
    from ._issue import generate

    files = _markdown(generate(["all"], n=n, seed=seed))
    text = files["problems.md"] + "\n" + files["solutions.md"]
    return "\n".join("##" + line if line.startswith("#") else line for line in text.splitlines())
