"""poinsot's own Sphinx hooks.

* ``config-inited``: MathJax is copied from docs/node_modules/mathjax (``npm ci`` in docs/) into
  the build, so the site serves it itself; the API page is written from ``poinsot.__all__``
  and the public submodules, so a new public name gets its page without an edit here; the
  teaching notebooks (``notebooks/*.ipynb``, outside docs/ where Sphinx cannot read them) are
  copied into docs/notebooks/ (git-ignored), where myst-nb executes them at build time.
* ``config-inited`` too: the derivations page and the errata page are written from
  :mod:`poinsot.derive` (docs/_ext/derive_pages.py).
* ``build-finished``: the built browser lab (python/poinsot/lab, ``make lab-build``) is copied
  to ``lab/`` of the site, so the site alone is a complete offline companion (its one-file form,
  ``lab/poinsot-lab.html``, too: a download); the teaching notebooks are copied beside their
  pages (``notebooks/NAME.ipynb``), and ``html-page-context`` puts a link to download the
  notebook under each notebook page's title (issue 23, item 7).
"""

from __future__ import annotations

import inspect
import re
import shutil
import sys
from pathlib import Path
from typing import Any

import derive_pages  # docs/_ext/, on the path beside this module
from sphinx.pycode import ModuleAnalyzer

DOCS = Path(__file__).resolve().parent.parent
ROOT = DOCS.parent
MATHJAX = DOCS / "node_modules" / "mathjax" / "es5"
# The parts of MathJax 3 that the TeX → CommonHTML page needs: the combined component, its
# fonts, the TeX extensions it may autoload, the menu and the assistive MathML.
MATHJAX_PARTS = ["tex-chtml.js", "output/chtml", "input/tex/extensions", "ui", "a11y"]
LAB = ROOT / "python" / "poinsot" / "lab"
NOTEBOOKS = ROOT / "notebooks"
NOTEBOOK_COPIES = DOCS / "notebooks"

# The public submodules documented beside the package's top-level names.
SUBMODULES = [
    "poinsot.plots",
    "poinsot.special",
    "poinsot.derive",
    "poinsot.sweep",
    "poinsot.experiments",
    "poinsot.exercises",
]


def _copy_mathjax(app: Any, config: Any) -> None:
    if not (MATHJAX / "tex-chtml.js").is_file():
        raise RuntimeError(
            f"MathJax is missing ({MATHJAX}): run `npm ci` in docs/ (make docs does)"
        )
    static = Path(app.outdir).parent / "_mathjax_static"
    dest = static / "mathjax"
    if dest.exists():
        shutil.rmtree(dest)
    for part in MATHJAX_PARTS:
        src = MATHJAX / part
        if src.is_dir():
            shutil.copytree(src, dest / part)
        else:
            (dest / part).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(src, dest / part)
    config.html_static_path.append(str(static))


def _copy_notebooks(app: Any, config: Any) -> None:
    """notebooks/*.ipynb into docs/notebooks/ (the page notebooks.md lists them by glob): a
    copy whose bytes are unchanged is left alone (Sphinx reads a file again when it changes),
    and a copy whose notebook is gone is removed, so the site shows exactly the folder."""
    sources = sorted(NOTEBOOKS.glob("*.ipynb"))
    if not sources:
        raise RuntimeError(f"no notebook in {NOTEBOOKS}: the docs' notebooks page lists them")
    NOTEBOOK_COPIES.mkdir(exist_ok=True)
    names = {src.name for src in sources}
    for stale in NOTEBOOK_COPIES.glob("*.ipynb"):
        if stale.name not in names:
            stale.unlink()
    for src in sources:
        dest = NOTEBOOK_COPIES / src.name
        if not dest.exists() or dest.read_bytes() != src.read_bytes():
            shutil.copy2(src, dest)


def _kind(obj: Any) -> str:
    if inspect.isclass(obj):
        return "class"
    if callable(obj):
        return "function"
    return "data"


def api_names() -> dict[str, list[str]]:
    """The documented names: ``poinsot.__all__`` and each public submodule's ``__all__``."""
    import importlib

    import poinsot

    out = {"poinsot": [n for n in poinsot.__all__ if n != "__version__"]}
    for mod in SUBMODULES:
        out[mod] = list(importlib.import_module(mod).__all__)
    return out


def _write_api(app: Any, config: Any) -> None:
    import importlib

    lines = [
        "API reference",
        "=============",
        "",
        "Every public name of poinsot, generated from the docstrings (numpydoc: parameters "
        "with their units and shapes). SI units and radians throughout; quaternions are "
        "scalar-first ``[w, x, y, z]``.",
        "",
    ]
    for mod, names in api_names().items():
        module = importlib.import_module(mod)
        title = f"``{mod}``"
        lines += [title, "-" * len(title), "", f".. currentmodule:: {mod}", ""]
        doc = inspect.getdoc(module) or ""
        if mod != "poinsot" and doc:
            lines += [doc.split("\n\n")[0], ""]
        for kind, heading in (
            ("class", "Classes"),
            ("function", "Functions"),
            ("data", "Constants"),
        ):
            group = [n for n in names if _kind(getattr(module, n)) == kind]
            if not group:
                continue
            lines += [f"**{heading}**", "", ".. autosummary::", "   :toctree: generated/", ""]
            if kind == "class":
                lines.insert(len(lines) - 1, "   :template: class.rst")
            lines += [f"   {n}" for n in group] + [""]
    target = DOCS / "api.rst"
    text = "\n".join(lines) + "\n"
    if not target.exists() or target.read_text() != text:
        target.write_text(text)


def _copy_lab(app: Any, exc: Exception | None) -> None:
    if exc is not None or app.builder.format != "html":
        return
    if not (LAB / "index.html").is_file():
        raise RuntimeError(f"the built lab is missing ({LAB}): run `make lab-build` first")
    dest = Path(app.outdir) / "lab"
    if dest.exists():
        shutil.rmtree(dest)
    shutil.copytree(LAB, dest)


def _copy_notebook_sources(app: Any, exc: Exception | None) -> None:
    """notebooks/*.ipynb beside their pages (notebooks/NAME.html), for the download links."""
    if exc is not None or app.builder.format != "html":
        return
    dest = Path(app.outdir) / "notebooks"
    dest.mkdir(exist_ok=True)
    for src in sorted(NOTEBOOKS.glob("*.ipynb")):
        shutil.copy2(src, dest / src.name)


#: The first heading's end in a page's body: the download link goes right after it.
_FIRST_H1_END = re.compile(r"</h1>")


def _notebook_download_link(
    app: Any, pagename: str, templatename: str, context: dict[str, Any], doctree: Any
) -> None:
    """A notebook's page (notebooks/NAME) gets "Download this notebook" under its title: a
    relative link to NAME.ipynb, copied beside the page by :func:`_copy_notebook_sources`."""
    folder, _, name = pagename.partition("/")
    if folder != "notebooks" or "/" in name or not (NOTEBOOKS / f"{name}.ipynb").is_file():
        return
    body = context.get("body")
    if not isinstance(body, str):
        return
    link = (
        f'<p class="poinsot-download"><a class="reference download" href="{name}.ipynb" '
        f'download="{name}.ipynb">Download this notebook</a> ({name}.ipynb) to run it '
        "yourself in Jupyter, with poinsot installed.</p>"
    )
    body, n = _FIRST_H1_END.subn("</h1>\n" + link, body, count=1)
    context["body"] = body if n else link + body


_BAR = re.compile(r"(?<!\\)\|")


def _escape_bars(app: Any, what: str, name: str, obj: Any, options: Any, lines: list[str]) -> None:
    """The docstrings write magnitudes as ``|L|`` and ``|sin λ|`` (readable in ``help()``);
    reStructuredText would read them as substitutions, so they are escaped for the site."""
    for i, line in enumerate(lines):
        bare = line.strip()
        table = bare.startswith(("+-", "+=")) or (
            bare.startswith("|") and bare.endswith("|") and bare.count("|") >= 3
        )
        if "|" in line and not table:
            lines[i] = _BAR.sub(r"\\|", line)


def _data_docs(app: Any, what: str, name: str, obj: Any, options: Any, lines: list[str]) -> None:
    """A module constant re-exported by the package (``poinsot.J2000``, ``poinsot.exercises.FORMATS``)
    has no docstring of its own: autodoc would show its type's (numpy's ``datetime64``, ``dict``'s),
    which is not about it. Its ``#:`` comment in the module that defines it is shown instead."""
    if what != "data" or not name.startswith("poinsot."):
        return
    short = name.rsplit(".", 1)[1]
    for modname, module in sorted(sys.modules.items()):
        if not modname.startswith("poinsot") or getattr(module, short, None) is not obj:
            continue
        try:
            docs = ModuleAnalyzer.for_module(modname).find_attr_docs()
        except Exception:  # a compiled module: no source to read
            continue
        if ("", short) in docs:
            lines[:] = list(docs[("", short)])
            return
    if (
        lines
        and type(obj).__doc__
        and inspect.cleandoc(type(obj).__doc__).startswith(lines[0].strip())
    ):
        lines[:] = []


def setup(app: Any) -> dict[str, Any]:
    app.connect("autodoc-process-docstring", _escape_bars, priority=400)
    app.connect("autodoc-process-docstring", _data_docs, priority=300)
    app.connect("config-inited", _copy_mathjax)
    app.connect("config-inited", _write_api)
    app.connect("config-inited", _copy_notebooks)
    app.connect("config-inited", derive_pages.write_pages)
    app.connect("build-finished", _copy_lab)
    app.connect("build-finished", _copy_notebook_sources)
    app.connect("html-page-context", _notebook_download_link)
    return {"parallel_read_safe": True, "parallel_write_safe": True}


def gallery_argv(gallery_conf: Any, script_vars: Any) -> list[str]:
    """The arguments the gallery passes to each example: the folder for the files it writes
    (a scratch folder inside the build, so a build never writes into the source tree)."""
    return [str(DOCS / "_build" / "gallery_out")]
