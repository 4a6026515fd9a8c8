"""The teaching notebooks of ``notebooks/`` (issue 13): four lessons in the unit's order.

Each notebook found in the folder (by glob, so a new one is covered without an edit here) is
executed top to bottom in a real Jupyter kernel (nbclient, kernel ``python3``, in a temporary
folder so nothing is written into the tree). A lesson compares poinsot's numbers with the
closed forms it derives in ``assert`` statements, so a wrong number is an error of a cell and
fails here. Beyond running:

* every figure a notebook draws is measured as it is drawn (``figure_checks``): no text leaving
  the figure or running into another, every axis with its unit — and there is at least one;
* the markdown holds the lesson's equations in LaTeX, each section ends with a question for
  students, and the closing "Explore" section names scenes of the browser lab that exist;
* the committed file has no outputs, so that its diffs stay readable.

Negative controls: a notebook with a failing assertion fails to execute, a lesson with one
closed form broken fails, and a figure without units or cut off is reported.
"""

from __future__ import annotations

import json
import os
import re
import time
from pathlib import Path
from typing import Any

import poinsot as ps
import pytest

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOKS = ROOT / "notebooks"
TESTS = Path(__file__).resolve().parent
NOTEBOOK_PATHS = sorted(NOTEBOOKS.glob("*.ipynb"))
# The four lessons issue 13 asks for, in the unit's order.
LESSONS = (
    "01_rotating_frames_and_coriolis",
    "02_falling_body_and_foucault",
    "03_inertia_euler_dzhanibekov",
    "04_heavy_top",
)
# Seconds a cell may run before nbclient stops it (the lessons take a few seconds each).
CELL_TIMEOUT_S = 300
# A display equation $$ … $$ of the markdown, and an equation number of the unit cited in it.
DISPLAY_MATH = re.compile(r"\$\$(.+?)\$\$", re.S)
UNIT_TAG = re.compile(r"\\tag\{2\.\d+")
# The value of a cell's last line that only says a matplotlib object was made (a lesson ends such
# a line with ";"): noise on a projected page.
STRAY_REPR = re.compile(r"\[?<matplotlib\.|\[?Text\(|\[?<mpl_toolkits\.")

# Injected before a notebook's first cell when the test runs it (never saved into the file): a
# post_execute hook, registered before matplotlib's inline backend registers its own (which
# shows and closes the figures), that measures every open figure with figure_checks and
# appends what it finds to a JSON file in the working folder.
FIGURE_HOOK = """\
import json as _json, sys as _sys
_sys.path.insert(0, {tests!r})
from figure_checks import axes_without_units as _units, layout_problems as _layout
_seen = set()
def _poinsot_check_figures():
    plt = _sys.modules.get("matplotlib.pyplot")
    if plt is None:
        return
    for num in plt.get_fignums():
        fig = plt.figure(num)
        if id(fig) in _seen:
            continue
        _seen.add(id(fig))
        titles = [ax.get_title() for ax in fig.axes if ax.get_title()]
        name = fig._suptitle.get_text() if fig._suptitle is not None else ""
        with open("figures.json", "a") as out:
            out.write(_json.dumps({{"name": name or (titles[0] if titles else ""),
                                   "problems": _layout(fig) + _units(fig)}}) + "\\n")
get_ipython().events.register("post_execute", _poinsot_check_figures)
"""


def _markdown(nb: dict[str, Any]) -> str:
    return "\n\n".join(
        "".join(c["source"]) if isinstance(c["source"], list) else c["source"]
        for c in nb["cells"]
        if c["cell_type"] == "markdown"
    )


def _load(path: Path) -> dict[str, Any]:
    return json.loads(path.read_text(encoding="utf-8"))


def _ids(paths: list[Path]) -> list[str]:
    return [p.stem for p in paths]


def run_notebook(nb: Any, workdir: Path) -> tuple[Any, list[dict[str, Any]], float]:
    """Executes ``nb`` (an nbformat notebook, changed in place) with the figure hook in a
    ``python3`` kernel whose working folder is ``workdir``; returns the executed notebook
    without the hook's cell, the figure reports and the seconds it took. A cell's error raises
    ``nbclient.exceptions.CellExecutionError``."""
    nbformat = pytest.importorskip("nbformat", reason="nbformat is not installed")
    nbclient = pytest.importorskip("nbclient", reason="nbclient is not installed")
    pytest.importorskip("ipykernel", reason="ipykernel is not installed")
    hook = nbformat.v4.new_code_cell(FIGURE_HOOK.format(tests=str(TESTS)))
    nb.cells.insert(0, hook)
    # The kernel imports the same poinsot as this test (the source tree, not an installed copy).
    package_root = str(Path(ps.__file__).resolve().parents[1])
    env = dict(os.environ)
    env["PYTHONPATH"] = package_root + ((":" + env["PYTHONPATH"]) if env.get("PYTHONPATH") else "")
    client = nbclient.NotebookClient(
        nb,
        timeout=CELL_TIMEOUT_S,
        kernel_name="python3",
        resources={"metadata": {"path": str(workdir)}},
    )
    start = time.perf_counter()
    try:
        client.execute(env=env)
    finally:
        nb.cells.pop(0)
    seconds = time.perf_counter() - start
    report = workdir / "figures.json"
    figures = (
        [json.loads(line) for line in report.read_text().splitlines()] if report.exists() else []
    )
    return nb, figures, seconds


def figure_outputs(nb: Any) -> list[int]:
    """The index of the cell of each picture (PNG) the notebook's outputs show, in order."""
    return [
        i
        for i, cell in enumerate(nb.cells)
        if cell.cell_type == "code"
        for out in cell.outputs
        if "image/png" in out.get("data", {})
    ]


def output_problems(nb: Any, figures: list[dict[str, Any]]) -> list[str]:
    """What is wrong with an executed notebook's outputs: error outputs, no picture, pictures
    the figure hook did not measure, and every figure's layout and unit problems."""
    problems = []
    for i, cell in enumerate(nb.cells):
        for out in cell.get("outputs", []):
            if out.get("output_type") == "error":
                problems.append(f"cell {i}: {out.get('ename')}")
            text = out.get("data", {}).get("text/plain", "")
            if out.get("output_type") == "execute_result" and STRAY_REPR.match(text):
                problems.append(f"cell {i} shows {text[:40]}")
    shown = figure_outputs(nb)
    if not shown:
        problems.append("no figure is shown")
    if len(figures) != len(shown):
        problems.append(f"{len(shown)} pictures shown but {len(figures)} figures measured")
    for i, fig in zip(shown, figures):
        problems += [f"cell {i} ({fig['name']!r}): {p}" for p in fig["problems"]]
    return problems


# ---- the folder --------------------------------------------------------------------------------


def test_the_four_lessons_are_there() -> None:
    """notebooks/ holds the four lessons (and whatever else it holds is tested as well)."""
    assert set(LESSONS) <= {p.stem for p in NOTEBOOK_PATHS}, _ids(NOTEBOOK_PATHS)


# ---- each notebook, as committed ---------------------------------------------------------------


@pytest.mark.parametrize("path", NOTEBOOK_PATHS, ids=_ids(NOTEBOOK_PATHS))
def test_committed_without_outputs(path: Path) -> None:
    """Outputs, execution counts and a kernel's run-time metadata stay out of the committed
    file: the docs and the tests execute the notebooks, and diffs stay readable."""
    nb = _load(path)
    assert nb["nbformat"] == 4
    assert nb["metadata"]["kernelspec"]["name"] == "python3"
    for i, cell in enumerate(nb["cells"]):
        if cell["cell_type"] == "code":
            assert cell["outputs"] == [], f"cell {i} has outputs"
            assert cell["execution_count"] is None, f"cell {i} has an execution count"
            assert not {"execution", "scrolled", "collapsed"} & set(cell["metadata"]), i


@pytest.mark.parametrize("path", NOTEBOOK_PATHS, ids=_ids(NOTEBOOK_PATHS))
def test_lesson_structure(path: Path) -> None:
    """A title, the unit's equations in LaTeX with their numbers, a question for students at
    the end of every numbered section, and an "Explore" section that points to the lab."""
    nb = _load(path)
    text = _markdown(nb)
    assert text.startswith("# "), "the notebook starts with its title"
    equations = DISPLAY_MATH.findall(text)
    assert equations, "no display equation $$ … $$ in the markdown"
    assert any(UNIT_TAG.search(e) for e in equations), "no equation carries the unit's number"
    assert all("\\" in e for e in equations), "an equation without any LaTeX command"
    # Sphinx wraps a display equation holding a line break \\ in a split environment, where
    # MathJax refuses \tag: such an equation breaks its lines with \cr.
    tagged_breaks = [e for e in equations if "\\tag" in e and "\\\\" in e]
    assert tagged_breaks == [], "use \\cr, not \\\\, in an equation with a \\tag"
    code = [c for c in nb["cells"] if c["cell_type"] == "code"]
    assert any("assert" in "".join(c["source"]) for c in code), "no comparison is asserted"
    sections = re.split(r"^## ", text, flags=re.M)[1:]
    assert len(sections) >= 3
    *lessons, explore = sections
    assert explore.startswith("Explore")
    for section in lessons:
        heading = section.splitlines()[0]
        assert "**Question.**" in section, f"section {heading!r} ends without a question"


@pytest.mark.parametrize("path", NOTEBOOK_PATHS, ids=_ids(NOTEBOOK_PATHS))
def test_explore_names_scenes_of_the_lab(path: Path) -> None:
    """The scenes the "Explore" section names exist: each ``?scene=<id>`` is the id of a scene
    of the lab (web/src/scenes) and each scene it names in bold is in docs/lab.md's list."""
    scenes = ROOT / "web" / "src" / "scenes"
    if not scenes.is_dir():  # pragma: no cover - an installed copy without the sources
        pytest.skip("the lab's sources (web/src/scenes) are not here")
    ids = set(re.findall(r'^\s*id: "([a-z]+)"', _read_all(scenes), flags=re.M))
    titles = set(re.findall(r"^\| ([^|]+?) \|", (ROOT / "docs" / "lab.md").read_text(), re.M))
    explore = _markdown(_load(path)).split("## Explore", 1)[1]
    assert "poinsot lab" in explore
    named_ids = re.findall(r"\?scene=([a-z]+)", explore)
    named_titles = [" ".join(t.split()) for t in re.findall(r"\*\*([^*]+)\*\*", explore)]
    assert named_ids and named_titles
    assert set(named_ids) <= ids, (named_ids, ids)
    assert set(named_titles) <= titles, (named_titles, titles)


def _read_all(folder: Path) -> str:
    return "\n".join(p.read_text() for p in sorted(folder.glob("*.ts")))


@pytest.mark.parametrize("path", NOTEBOOK_PATHS, ids=_ids(NOTEBOOK_PATHS))
def test_notebook_runs_and_shows_clean_figures(path: Path, tmp_path: Path) -> None:
    """The lesson runs without an error (each closed form it derives equals poinsot's number,
    or an assert fails), shows at least one figure, and every figure passes the figure checks."""
    nbformat = pytest.importorskip("nbformat", reason="nbformat is not installed")
    nb = nbformat.read(path, as_version=4)
    nb, figures, seconds = run_notebook(nb, tmp_path)
    assert output_problems(nb, figures) == []
    print(f"{path.name}: {seconds:.1f} s, {len(figures)} figures")
    assert list(tmp_path.iterdir()) == [tmp_path / "figures.json"], "the notebook wrote files"


# ---- negative controls -------------------------------------------------------------------------


def test_negative_control_a_failing_assertion_fails_the_notebook(tmp_path: Path) -> None:
    """A notebook whose assertion fails is an error of the run, not a quiet output."""
    nbformat = pytest.importorskip("nbformat", reason="nbformat is not installed")
    nbclient = pytest.importorskip("nbclient", reason="nbclient is not installed")
    nb = nbformat.v4.new_notebook()
    nb.cells = [
        nbformat.v4.new_markdown_cell("# A wrong number\n\n$$\nx = 1 \\tag{2.1}\n$$"),
        nbformat.v4.new_code_cell("import poinsot as ps\nassert ps.Earth().g == 9.81"),
    ]
    with pytest.raises(nbclient.exceptions.CellExecutionError, match="AssertionError"):
        run_notebook(nb, tmp_path)


def test_negative_control_a_broken_closed_form_fails_the_lesson(tmp_path: Path) -> None:
    """The lessons' comparisons can fail: notebook 02 with the unit's 2.42 off by a factor
    (⅓ → ½) stops at the assertion that compares it with poinsot's deflection."""
    nbformat = pytest.importorskip("nbformat", reason="nbformat is not installed")
    nbclient = pytest.importorskip("nbclient", reason="nbclient is not installed")
    nb = nbformat.read(NOTEBOOKS / "02_falling_body_and_foucault.ipynb", as_version=4)
    right = "np.sqrt(8 * h**3 / g) / 3"
    cells = [c for c in nb.cells if right in c.source]
    assert len(cells) == 1, "the closed form 2.42 of notebook 02 is not where this test expects"
    cells[0].source = cells[0].source.replace(right, "np.sqrt(8 * h**3 / g) / 2")
    with pytest.raises(nbclient.exceptions.CellExecutionError, match="AssertionError"):
        run_notebook(nb, tmp_path)


def test_negative_control_bad_figures_are_reported(tmp_path: Path) -> None:
    """A figure with an axis without its unit and a title running off the figure is reported
    by the figure hook, and so is the stray value of the cell's last line (``Text(...)``); a
    notebook that shows no figure is reported too."""
    nbformat = pytest.importorskip("nbformat", reason="nbformat is not installed")
    nb = nbformat.v4.new_notebook()
    nb.cells = [
        nbformat.v4.new_code_cell("%matplotlib inline\nimport matplotlib.pyplot as plt"),
        nbformat.v4.new_code_cell(
            "fig, ax = plt.subplots(figsize=(3, 2))\nax.plot([0, 1], [0, 1])\n"
            "ax.set_xlabel('time')\nax.set_ylabel('x (m)')\n"
            "ax.set_title('a title far too long to fit in a figure only three inches wide')"
        ),
    ]
    nb, figures, _ = run_notebook(nb, tmp_path)
    problems = output_problems(nb, figures)
    assert any("label 'time'" in p for p in problems), problems
    assert any("leaves the figure" in p for p in problems), problems
    assert any("shows Text(" in p for p in problems), problems  # set_title's value, shown
    clean = nbformat.v4.new_notebook()
    clean.cells = [nbformat.v4.new_code_cell("x = 1")]
    (tmp_path / "none").mkdir()
    nb, figures, _ = run_notebook(clean, tmp_path / "none")
    assert output_problems(nb, figures) == ["no figure is shown"]
