"""The site's pictures, made at build time from poinsot's own numbers and from the lab itself.

* ``builder-inited``: every figure of the unit (:data:`poinsot.plots.UNIT_FIGURES`, Figs.
  2.1–2.15) is drawn by :func:`poinsot.plots.unit_figure` into ``docs/_generated/figures/``
  (git-ignored), so a page shows what the installed poinsot computes, never a stored picture.
* ``{unit-figure} 2.5``: one of them on a page, as a figure whose caption is the unit's caption,
  the function that draws it and the command that writes it.
* ``{unit-figures}``: all of them, in the unit's order, as a grid (the unit's figures page).
* ``{lab-shot} heavytop``: the lab's scene as the browser shows it, a screenshot taken of the
  built lab in Debian's chromium by ``web/shots/shots.test.mjs`` (``make lab-shots``, which ``make docs``
  runs first) into ``docs/_generated/lab/``; ``{lab-shots}``: every scene, in the tabs' order.
* :class:`UnitOrder`: the gallery's examples in the unit's order (frames, the Earth, inertia,
  Euler's equations, the free top, the heavy top), not alphabetically.
"""

from __future__ import annotations

import json
from collections.abc import Iterable
from pathlib import Path
from typing import Any, ClassVar

from docutils import nodes
from docutils.parsers.rst import Directive, directives

DOCS = Path(__file__).resolve().parent.parent
GENERATED = DOCS / "_generated"
FIGURES = GENERATED / "figures"
LAB_SHOTS = GENERATED / "lab"
# The lab's scenes in the order of its tabs, with a caption each (web/shots/shots.test.mjs writes the list
# it shot into scenes.json beside the pictures; the build checks that the two agree).
SCENES = {
    "frames": "Rotating frames: a particle on a turntable seen from the fixed and the turning frame",
    "drop": "Falling body: the eastward deflection of a body dropped from a tower",
    "foucault": "Foucault pendulum: the rosette traced on the floor and the turning swing plane",
    "low": "Flow into a low: parcels turned by the Coriolis force circle the low",
    "inertia": "Inertia: a solid with its principal axes and its ellipsoid of inertia",
    "euler": "Euler angles: the gimbal's three discs and the line of nodes",
    "freetop": "Free top: the body cone rolling on the space cone",
    "poinsot": "Poinsot's construction: the inertia ellipsoid rolling on the invariable plane",
    "heavytop": "Heavy top: the tip of the axis nodding between its turning circles",
    "earthtop": "The Earth as a top: the spin axis sweeping its precession cone under the Sun's and the Moon's pull, beside the real pole's path",
    "gyrocompass": "Gyrocompass: the spin axis of a compass on a ship swinging about north and settling there once a Schuler period",
}
# The gallery's examples in the unit's order (2.1 onward); an example missing here sorts last,
# alphabetically, and the build says so.
GALLERY_ORDER = [
    "moving_frames.py",
    "coriolis_falling_body.py",
    "foucault_pendulum.py",
    "inertia_tensor.py",
    "dumbbell_torque.py",
    "euler_and_chasles_theorems.py",
    "torque_free_top.py",
    "dzhanibekov.py",
    "dzhanibekov_flip_map.py",
    "euler_angles.py",
    "heavy_top.py",
    "steady_precession.py",
    "heavy_top_phase_diagram.py",
    "chandler_wobble.py",
    "gyrocompass.py",
    "exercise_sheet.py",  # after the unit: a problem sheet made from all of it
]


class UnitOrder:
    """sphinx-gallery's ``within_subsection_order``: the examples in :data:`GALLERY_ORDER`."""

    def __init__(self, src_dir: str) -> None:
        self.src_dir = src_dir

    def __call__(self, filename: str) -> tuple[int, str]:
        name = Path(filename).name
        rank = GALLERY_ORDER.index(name) if name in GALLERY_ORDER else len(GALLERY_ORDER)
        return rank, name

    def __repr__(self) -> str:  # sphinx-gallery keys its cache on the repr
        return f"<{type(self).__name__}: {', '.join(GALLERY_ORDER)}>"


def figure_path(number: str) -> Path:
    return FIGURES / f"fig-{number}.png"


def _draw_figures(app: Any) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from poinsot.plots import UNIT_FIGURES, unit_figure

    FIGURES.mkdir(parents=True, exist_ok=True)
    for number in UNIT_FIGURES:
        fig = unit_figure(number)
        fig.savefig(figure_path(number), dpi=110, bbox_inches="tight")
        plt.close(fig)


def _uri(path: Path) -> str:
    """A source-relative URI (Sphinx reads a leading ``/`` as the source folder)."""
    return "/" + path.relative_to(DOCS).as_posix()


def _figure(path: Path, alt: str, caption: list[nodes.Node], width: str) -> nodes.figure:
    fig = nodes.figure(classes=["poinsot-picture"])
    fig += nodes.image(uri=_uri(path), alt=alt, width=width)
    cap = nodes.caption()
    cap.extend(caption)
    fig += cap
    return fig


def _unit_figure(number: str, width: str) -> nodes.figure:
    from poinsot.plots import UNIT_FIGURES

    if number not in UNIT_FIGURES:
        raise ValueError(
            f"unit-figure: {number!r} is not one of the unit's figures ({', '.join(UNIT_FIGURES)})"
        )
    entry = UNIT_FIGURES[number]
    caption = [
        nodes.strong(text=f"Fig. {number}"),
        nodes.Text(f" — {entry.caption}; drawn by "),
        nodes.literal(text=f"poinsot.plots.{entry.function.__name__}"),
        nodes.Text(", written by "),
        nodes.literal(text=f"poinsot figure {number}"),
        nodes.Text("."),
    ]
    return _figure(figure_path(number), f"Fig. {number}: {entry.caption}", caption, width)


class UnitFigureDirective(Directive):
    """``{unit-figure} 2.5`` with an optional ``:width:`` (default 80%)."""

    required_arguments = 1
    option_spec: ClassVar[dict[str, Any]] = {"width": directives.unchanged}

    def run(self) -> list[nodes.Node]:
        return [_unit_figure(self.arguments[0], self.options.get("width", "80%"))]


def _grid(figures: Iterable[nodes.figure]) -> list[nodes.Node]:
    """What a grid directive returns: the figures side by side (CSS ``poinsot-picture-grid``)."""
    grid = nodes.container(classes=["poinsot-picture-grid"])
    grid.extend(figures)
    return [grid]


class UnitFiguresDirective(Directive):
    """Every unit figure, in the unit's order, as a grid."""

    def run(self) -> list[nodes.Node]:
        from poinsot.plots import UNIT_FIGURES

        return _grid(_unit_figure(number, "100%") for number in UNIT_FIGURES)


def _lab_shot(scene: str, width: str) -> nodes.figure:
    if scene not in SCENES:
        raise ValueError(f"lab-shot: {scene!r} is not a scene of the lab ({', '.join(SCENES)})")
    path = LAB_SHOTS / f"{scene}.png"
    caption = [
        nodes.Text(f"{SCENES[scene]} — "),
        nodes.reference(text="open this scene", refuri=f"lab/index.html?scene={scene}"),
        nodes.Text(" (the lab as Debian's chromium draws it, screenshot taken at build time)."),
    ]
    return _figure(path, f"the lab's {scene} scene", caption, width)


class LabShotDirective(Directive):
    """``{lab-shot} heavytop`` with an optional ``:width:`` (default 90%)."""

    required_arguments = 1
    option_spec: ClassVar[dict[str, Any]] = {"width": directives.unchanged}

    def run(self) -> list[nodes.Node]:
        return [_lab_shot(self.arguments[0], self.options.get("width", "90%"))]


class LabShotsDirective(Directive):
    """Every scene of the lab, in the order of its tabs, as a grid."""

    def run(self) -> list[nodes.Node]:
        return _grid(_lab_shot(scene, "100%") for scene in SCENES)


def _check_lab_shots(app: Any) -> None:
    listing = LAB_SHOTS / "scenes.json"
    if not listing.is_file():
        raise RuntimeError(
            f"the lab's screenshots are missing ({LAB_SHOTS}): run `make lab-shots` "
            "(make docs does) — web/shots/shots.test.mjs takes them in chromium"
        )
    shot = json.loads(listing.read_text())
    if shot != list(SCENES):
        raise RuntimeError(
            f"web/shots/shots.test.mjs shot the scenes {shot}, docs/_ext/pictures.py captions {list(SCENES)}: "
            "make the two lists agree"
        )


def _drop_execution_times(app: Any, config: Any) -> None:
    """conf.py turns sphinx-gallery's execution-times pages off (they load scripts and styles
    from public CDNs); a checkout that built the site before keeps their stale sources
    (git-ignored) and built pages, which Sphinx would still publish: they go."""
    out = Path(app.outdir)
    for stale in (
        DOCS / "sg_execution_times.rst",
        DOCS / "gallery" / "sg_execution_times.rst",
        out / "sg_execution_times.html",
        out / "gallery" / "sg_execution_times.html",
    ):
        stale.unlink(missing_ok=True)


def _builder_inited(app: Any) -> None:
    _draw_figures(app)
    _check_lab_shots(app)


def setup(app: Any) -> dict[str, Any]:
    app.add_directive("unit-figure", UnitFigureDirective)
    app.add_directive("unit-figures", UnitFiguresDirective)
    app.add_directive("lab-shot", LabShotDirective)
    app.add_directive("lab-shots", LabShotsDirective)
    app.connect("config-inited", _drop_execution_times)
    app.connect("builder-inited", _builder_inited)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
