"""The chapter "poinsot and the world" (docs/world/), written at build time from
:mod:`poinsot.experiments`: never by hand, so that the pages say what the installed poinsot
computes.

* ``docs/world/index.md``: the chapter's introduction and one table of every entry of the
  catalogue (measured, poinsot's prediction, the closed form, the verdict), in its order.
* ``docs/world/<name>.md``: a page per experiment: the story, the result with its figure, the
  set-up (the inputs as published and in SI, the model's assumptions), the computation as
  code (the entry's ``predict`` and ``closed_form``, read from their source), what is
  misquoted and the sources.
* ``docs/_generated/world/world-<name>.png``: each figure, drawn by
  :func:`poinsot.experiments.plot`.

The pages are written at ``config-inited`` and only rewritten when their text changes (so an
unchanged page is not rebuilt); ``docs/world/.gitignore`` keeps them out of git.
"""

from __future__ import annotations

import inspect
import textwrap
from pathlib import Path
from typing import Any

from page_files import write_folder  # docs/_ext/, on the path beside this module

DOCS = Path(__file__).resolve().parent.parent
WORLD = DOCS / "world"
FIGURES = DOCS / "_generated" / "world"

INTRO = """\
Every formula of poinsot is checked against closed forms and high-precision references; this
chapter checks the unit against what physics is finally answerable to: measurement. Each entry
is a published experiment — who measured what, where and when, the publication and the page the
figure is printed on — with its inputs as published, in their own units (Paris feet and lines,
degrees and minutes, knots, read by pint), the measured value with the uncertainty its author
stated, and poinsot's prediction computed through its public API, beside the unit's closed form.
The verdict is the difference in units of the stated uncertainty σ: within {sigma:g} σ the
measurement agrees. Where the model leaves something out (the Earth's elasticity, the air), the
entry says so and the disagreement is expected.

The same numbers from Python, `experiments.run(name)`, and from the command line,
`poinsot experiments [NAME] [--json]`; the notebook *world* lets you change an input and see how
far the measurement could have moved.
"""


def _cell(text: str) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


def figure_name(name: str) -> str:
    return f"world-{name}.png"


def _source_code(fn: Any) -> str:
    try:
        return textwrap.dedent(inspect.getsource(fn)).rstrip()
    except (OSError, TypeError):  # pragma: no cover - a function without a source file
        return f"# {getattr(fn, '__qualname__', fn)!r}: no source"


def index_markdown(results: Any) -> str:
    from poinsot import experiments as x

    lines = [
        "# poinsot and the world",
        "",
        "<!-- Written by docs/_ext/world_pages.py from poinsot.experiments at every build: "
        "do not edit. -->",
        "",
        INTRO.format(sigma=x.AGREE_SIGMA),
        x.catalogue_summary(results),
        "",
        "| experiment | verdict | measured | poinsot | closed form |",
        "|---|---|---|---|---|",
    ]
    for r in results:
        lines.append(
            "| "
            + " | ".join(
                _cell(c)
                for c in (
                    f"[{r.title} ({r.year})]({r.name}.md)",
                    r.short_verdict,
                    r.shown_measured(),
                    r.shown("predicted"),
                    r.shown("closed_form"),
                )
            )
            + " |"
        )
    lines += ["", "```{toctree}", ":hidden:", "", *[r.name for r in results], "```", ""]
    return "\n".join(lines)


def page_markdown(entry: Any, r: Any) -> str:
    from poinsot import experiments as x

    lines = [
        f"# {r.title}",
        "",
        f"<!-- Written by docs/_ext/world_pages.py from poinsot.experiments.get({r.name!r}). -->",
        "",
        entry.story,
        "",
        "## The result",
        "",
        r.summary,
        "",
        f"```{{image}} ../_generated/world/{figure_name(r.name)}",
        f":alt: {r.quantity}: measured {r.shown_measured()}, poinsot {r.shown('predicted')}",
        f":width: {'60%' if r.is_sense else '100%'}",
        "```",
        "",
        "| | |",
        "|---|---|",
        f"| {_cell(r.quantity)}, measured | {_cell(r.shown('measured'))} |",
        f"| uncertainty ({_cell(r.uncertainty_kind)}) | {_cell(r.shown('uncertainty'))} |",
        f"| poinsot's prediction | {_cell(r.shown('predicted'))} |",
        f"| the closed form | {_cell(r.shown('closed_form'))} |",
        f"| (measured − predicted) / uncertainty | "
        f"{'—' if r.sigma is None else f'{r.sigma:.3g} σ'} |",
        f"| verdict | {_cell(r.verdict)} |",
        "",
    ]
    if entry.expect == "disagree":
        lines += ["## Why the model disagrees", "", entry.why, ""]
    lines += ["## The set-up", "", "| input | as published | SI |", "|---|---|---|"]
    for key, text in entry.inputs.items():
        value = x.parse(text)
        si = value if isinstance(value, str) else f"{value.to_base_units():~.6g}"
        lines.append(f"| {_cell(key)} | {_cell(text)} | {_cell(si)} |")
    lines += ["", "The model assumes: " + ", ".join(entry.assumptions) + ".", ""]
    lines += [
        "## The computation",
        "",
        "Through poinsot's public API; the inputs arrive as pint quantities, converted to SI at "
        "the door:",
        "",
        "```python",
        "from poinsot import experiments",
        "",
        f"r = experiments.run({r.name!r})",
        "r.measured, r.predicted, r.closed_form, r.sigma, r.verdict",
        "```",
        "",
        "The prediction (the entry's `predict`):",
        "",
        "```python",
        _source_code(entry.predict),
        "```",
        "",
        "The closed form (the entry's `closed_form`):",
        "",
        "```python",
        _source_code(entry.closed_form),
        "```",
        "",
    ]
    if entry.misquoted:
        lines += ["## A number often misquoted", "", entry.misquoted, ""]
    lines += ["## Sources", ""]
    for i, s in enumerate(entry.sources):
        role = "Primary source" if i == 0 else "Also"
        text = f"- **{role}.** {s.who}, {s.where}, {s.when}. {s.publication}, {s.page}."
        if s.url:
            text += f" <{s.url}>"
        if s.reading:
            text += f" *({s.reading})*"
        if s.note:
            text += f" {s.note}"
        lines.append(text)
    lines.append("")
    return "\n".join(lines)


def pages(draw: bool = True) -> dict[Path, str]:
    """Every page of the chapter, path → text; ``draw``: the figures too (into FIGURES)."""
    from poinsot import experiments as x

    entries = x.catalogue()
    results = x.run_all(progress=False)
    out = {WORLD / "index.md": index_markdown(results)}
    if draw:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        FIGURES.mkdir(parents=True, exist_ok=True)
    for e, r in zip(entries, results):
        out[WORLD / f"{e.name}.md"] = page_markdown(e, r)
        if draw:
            fig = x.plot(r)
            fig.savefig(FIGURES / figure_name(e.name), dpi=110, bbox_inches="tight")
            plt.close(fig)
    return out


def write_pages(app: Any = None, config: Any = None) -> None:
    """The Sphinx hook (``config-inited``): the chapter's pages, stale ones removed."""
    write_folder(WORLD, pages())


def setup(app: Any) -> dict[str, Any]:
    app.connect("config-inited", write_pages)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
