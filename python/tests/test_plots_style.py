"""Every function of ``poinsot.plots`` drawn in both styles (``"paper"``, ``"slides"``): no text
leaves the figure, no two tick labels (nor a label and the next panel's) collide, every axis
has a unit, slides text is larger and slides are saved at 200 dpi or more, and a style that is
neither is refused by name. The functions are discovered from ``poinsot.plots.__all__``: one
added without an entry in :data:`BUILD` fails here until it has one.

The checks themselves are tested on figures broken on purpose (the negative controls at the
end), so a check that stopped measuring would fail too."""

from __future__ import annotations

import io
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")

import poinsot as ps  # noqa: E402
from figure_checks import axes_without_units, layout_problems  # noqa: E402
from poinsot import plots  # noqa: E402
from poinsot.plots import _mpl  # noqa: E402

EARTH = ps.Earth()
# A planet spinning fast enough that a minute shows the swing plane turning.
FAST = ps.Earth(rotation_rate=1e-2)
TOP = ps.HeavyTop(1.0, 0.5, 1.0, 0.8, phi_dot=-0.5, psi_dot=6.0)  # loops
FRAMES = 3  # frames of each animation drawn here


def _foucault(samples: int = 601) -> ps.FoucaultRun:
    return FAST.foucault(
        45, degrees=True, length=5.0, amplitude=0.5, duration=60.0, samples=samples
    )


def _runs() -> list[ps.Trajectory]:
    return [
        ps.simulate([1, 2, 3], [1, 0.1, 1], 50.0, method=m, dt=0.01, samples=51)
        for m in ("splitting2", "rk4")
    ]


#: How to draw each function of ``poinsot.plots.__all__``: name → a callable taking the style
#: and returning a figure, an animation (its figure is checked, then it is saved), or the
#: paths of the pictures it saved (``save_top_plots``; the directory is made by the test).
BUILD: dict[str, Callable[..., Any]] = {
    "plot_inertia_ellipsoid": lambda style: plots.plot_inertia_ellipsoid(
        ps.RigidBody.cuboid(2.0, (1.0, 2.0, 3.0)), name="cuboid 1 × 2 × 3 m, 2 kg", style=style
    ),
    "plot_omega": lambda style: plots.plot_omega(
        ps.simulate([1, 2, 3], [1, 0.1, 1], 10.0, method="rk4", dt=0.05, samples=51),
        ps.FreeRigidBody([1, 2, 3], [1, 0.1, 1]),
        style=style,
    ),
    # the README's top: cones of 2.9°
    "plot_cones": lambda style: plots.plot_cones(
        ps.FreeSymmetricTop(1.0, 0.5, [0.1, 0.0, 2.0]), style=style
    ),
    "plot_polhodes": lambda style: plots.plot_polhodes(n=5, style=style),
    "plot_conservation": lambda style: plots.plot_conservation(_runs(), style=style),
    "animate_tumbling_box": lambda style: plots.animate_tumbling_box(frames=FRAMES, style=style),
    "animate_free_body": lambda style: plots.animate_free_body(
        ps.FreeRigidBody([1, 2, 3], [0.01, 2.0, 0.01]), frames=FRAMES, style=style
    ),
    "plot_effective_potential": lambda style: plots.plot_effective_potential(TOP, style=style),
    "plot_axis_locus": lambda style: plots.plot_axis_locus(TOP, style=style),
    "plot_angles": lambda style: plots.plot_angles(TOP, samples=400, style=style),
    "plot_steady_precession": lambda style: plots.plot_steady_precession(
        1.0, 0.5, 0.3, 0.6, samples=100, style=style
    ),
    "animate_top": lambda style: plots.animate_top(TOP, frames=FRAMES, style=style),
    "save_top_plots": lambda style, directory: plots.save_top_plots(TOP, directory, style=style),
    "plot_deflection": lambda style: plots.plot_deflection(EARTH, n=7, style=style),
    "plot_trajectory": lambda style: plots.plot_trajectory(
        EARTH.drop(50, 30, degrees=True), style=style
    ),
    "plot_foucault_rosette": lambda style: plots.plot_foucault_rosette(_foucault(), style=style),
    "plot_inertial_circles": lambda style: plots.plot_inertial_circles(EARTH, style=style),
    "plot_rigid_earth": lambda style: plots.plot_rigid_earth(
        ps.RigidEarth(), chandler_observed=(433.1, 1.7), style=style
    ),
    "animate_foucault": lambda style: plots.animate_foucault(
        _foucault(), frames=FRAMES, style=style
    ),
    "plot_gyrocompass": lambda style: plots.plot_gyrocompass(
        ps.Gyrocompass(0.8), ps.Gyrocompass(0.8).simulate(600.0, 0.1, samples=50), style=style
    ),
    # the unit's own figures (plots/unit.py, docs/figures.md), with their classroom defaults
    "plot_translating_frame": lambda style: plots.plot_translating_frame(style=style),
    "plot_rotating_frame": lambda style: plots.plot_rotating_frame(style=style),
    "plot_centripetal": lambda style: plots.plot_centripetal(velocity=[0.0, 0.3, 0.2], style=style),
    "plot_earth_centrifugal": lambda style: plots.plot_earth_centrifugal(style=style),
    "plot_earth_coriolis": lambda style: plots.plot_earth_coriolis(style=style),
    "plot_flow_into_low": lambda style: plots.plot_flow_into_low(style=style),
    "plot_euler_theorem": lambda style: plots.plot_euler_theorem(style=style),
    "plot_dumbbell": lambda style: plots.plot_dumbbell(style=style),
    "plot_body_cone": lambda style: plots.plot_body_cone(style=style),
    "plot_euler_angle_steps": lambda style: plots.plot_euler_angle_steps(style=style),
    "plot_omega_components": lambda style: plots.plot_omega_components(style=style),
    "plot_heavy_top": lambda style: plots.plot_heavy_top(style=style),
    "unit_figure": lambda style: plots.unit_figure("2.5", style=style),
}

#: More figures of the same functions, where one function draws different pictures.
EXTRA: dict[str, Callable[[str], Any]] = {
    "plot_trajectory of a flight": lambda style: plots.plot_trajectory(
        EARTH.projectile(100, 45, 30, 30, degrees=True), style=style
    ),
    "plot_cones of an oblate top": lambda style: plots.plot_cones(
        ps.FreeSymmetricTop(1.0, 1.8, [0.8, 0.0, 1.0]), 0.5, style=style
    ),
    "plot_inertia_ellipsoid of a rotor": lambda style: plots.plot_inertia_ellipsoid(
        ps.RigidBody.thin_rod(1.0, 2.0), style=style
    ),
    "plot_foucault_rosette of Paris, one hour": lambda style: plots.plot_foucault_rosette(
        EARTH.foucault(48.85, degrees=True, duration=3600.0, samples=4000), style=style
    ),
    "plot_axis_locus in the lower hemisphere": lambda style: plots.plot_axis_locus(
        ps.HeavyTop(1.0, 0.5, 1.0, 2.0, psi_dot=1.0), style=style
    ),
}

STYLES = ("paper", "slides")


def _draw(name: str, style: str, tmp_path: Path) -> list[tuple[str, Any]]:
    """What ``name`` draws in ``style``: ``("figure", fig)``, ``("animation", its figure)``
    (saved too, checking that its progress callback sees every frame) or ``("file", path)``
    for each picture saved."""
    build = BUILD.get(name) or EXTRA[name]
    if name == "save_top_plots":
        return [("file", p) for p in build(style, tmp_path / style)]
    out = build(style)
    if hasattr(out, "_fig"):
        calls: list[tuple[int, int]] = []
        _mpl.save_animation(
            out, tmp_path / f"{style}.gif", fps=5, progress=lambda i, n: calls.append((i, n))
        )
        assert calls == [(i, FRAMES) for i in range(FRAMES)], calls
        return [("animation", out._fig)]
    return [("figure", out)]


def test_every_plot_function_has_a_builder() -> None:
    missing = sorted(set(plots.__all__) - set(BUILD))
    assert not missing, f"add these to BUILD in {__file__}: {missing}"
    assert not set(BUILD) - set(plots.__all__), "BUILD names a function that is gone"


@pytest.mark.parametrize("style", STYLES)
@pytest.mark.parametrize("name", [*plots.__all__, *EXTRA])
def test_every_figure_fits_and_has_units(name: str, style: str, tmp_path: Path) -> None:
    if name not in BUILD and name not in EXTRA:
        pytest.fail(f"poinsot.plots.{name} has no entry in BUILD ({__file__})")
    for kind, fig in _draw(name, style, tmp_path):
        if kind == "file":  # saved by save_top_plots, from figures checked one by one
            assert fig.stat().st_size > 10_000
            continue
        assert layout_problems(fig) == [], name
        assert axes_without_units(fig) == [], name


def _text_sizes(fig: Any) -> float:
    """The median font size (points) of a figure's visible texts."""
    from matplotlib.text import Text

    fig.canvas.draw()
    sizes = [t.get_fontsize() for t in fig.findobj(Text) if t.get_visible() and t.get_text()]
    return float(np.median(sizes))


def _saved_dpi(fig: Any) -> float:
    from PIL import Image

    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    buf.seek(0)
    return float(Image.open(buf).info["dpi"][0])


@pytest.mark.parametrize("name", plots.__all__)
def test_slides_text_is_larger_and_saved_at_200_dpi(name: str, tmp_path: Path) -> None:
    if name not in BUILD:
        pytest.fail(f"poinsot.plots.{name} has no entry in BUILD ({__file__})")
    paper, slides = (_draw(name, style, tmp_path) for style in STYLES)
    for (kind, p), (_, s) in zip(paper, slides):
        if kind == "file":
            from PIL import Image

            with Image.open(p) as a, Image.open(s) as b:
                assert b.info["dpi"][0] >= 199.5 and b.width > 1.5 * a.width
            continue
        assert _text_sizes(s) >= 1.4 * _text_sizes(p)
        assert s.get_size_inches()[0] >= 1.5 * p.get_size_inches()[0]
        if kind == "figure":  # animations are written at the figure's own dpi (docs/plots.md)
            assert _saved_dpi(s) >= 199.5
            assert _saved_dpi(p) >= 149.5


@pytest.mark.parametrize("name", plots.__all__)
def test_a_bad_style_is_refused_by_name(name: str, tmp_path: Path) -> None:
    build = BUILD[name]
    for bad in ("poster", "", None, 2):
        with pytest.raises(ps.PoinsotError, match="style"):
            if name == "save_top_plots":
                build(bad, tmp_path)
            else:
                build(bad)


# ---- negative controls: the checks catch broken figures --------------------------------------


def _broken(what: str) -> Any:
    with _mpl.figure_style("paper") as style:
        fig, axes = _mpl.subplots(style, 4.0, 3.0, 1, 2)
        for ax in axes:
            ax.plot([0, 1], [0, 1])
            ax.set_xlabel("t (s)")
            ax.set_ylabel("x (m)")
        if what == "wide title":
            axes[0].set_title("a title much wider than the figure it is drawn on, cut at both ends")
        elif what == "crowded ticks":
            axes[0].set_xticks(np.linspace(0, 1, 40))
        elif what == "no unit":
            axes[1].set_ylabel("height")
        elif what == "titles run together":
            axes[0].set_title("left panel")
            axes[1].set_title("right panel")
            axes[1].title.set_x(-0.55)  # over the left panel's title
        elif what == "text off the edge":
            fig.text(0.98, 0.5, "a note placed past the right edge")
    return fig


@pytest.mark.parametrize(
    ("what", "needle"),
    [
        ("wide title", "leaves the figure"),
        ("crowded ticks", "overlap on the x-axis"),
        ("titles run together", "overlap"),
        ("text off the edge", "leaves the figure"),
    ],
)
def test_the_layout_check_catches_a_broken_figure(what: str, needle: str) -> None:
    assert layout_problems(_broken("none")) == []  # the same figure, unbroken, passes
    problems = layout_problems(_broken(what))
    assert problems and any(needle in p for p in problems), problems


def test_the_unit_check_catches_an_axis_without_unit() -> None:
    assert axes_without_units(_broken("none")) == []
    assert axes_without_units(_broken("no unit")) == ["y-axis of '': label 'height'"]
    with _mpl.figure_style("paper") as style:
        fig = _mpl.new_figure(style, 4.0, 4.0)
        ax = fig.add_subplot(projection="3d")  # 3-D axes are checked too
        ax.set(xlabel="x (m)", ylabel="y (m)", zlabel="z")
    assert axes_without_units(fig) == ["z-axis of '': label 'z'"]


def test_the_checks_ignore_what_is_not_drawn() -> None:
    # an axis keeps labelled ticks beyond its ends (at x = 1.2 here) that it never draws: they
    # are no part of the picture and must not count as text leaving the figure
    with _mpl.figure_style("slides") as style:
        fig, ax = _mpl.subplots(style, 3.0, 2.0)
        ax.plot([0, 1], [0, 1])
        ax.set(xlabel="t (s)", ylabel="x (m)", xlim=(0, 1))
    kept = [t.get_text() for t in ax.xaxis.get_ticklabels()]
    assert kept and layout_problems(fig) == []


def test_the_figures_page_runs() -> None:
    """docs/plots.md's Python blocks run in one namespace, and what they print holds."""
    import re

    doc = Path(__file__).resolve().parents[2] / "docs" / "plots.md"
    blocks = re.findall(r"```python\n(.*?)```", doc.read_text(encoding="utf-8"), re.DOTALL)
    assert len(blocks) >= 2
    namespace: dict[str, Any] = {"__name__": "__doc__"}
    for i, block in enumerate(blocks):
        exec(compile(block, f"docs/plots.md[block {i}]", "exec"), namespace)
    assert list(namespace["fig"].get_size_inches()) == pytest.approx([17.6, 8.8])
    from PIL import Image

    with Image.open(namespace["folder"] / "cones.png") as png:
        assert png.size == (3520, 1760) and png.info["dpi"][0] == pytest.approx(200, abs=0.5)


ANIMATIONS = [name for name in plots.__all__ if name.startswith("animate_")]


@pytest.mark.parametrize("name", ANIMATIONS)
def test_animations_play_inline_in_a_notebook(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Jupyter shows an object through ``_repr_html_``: every animation gives JavaScript frames
    without ffmpeg (one per frame drawn), and an HTML5 video where ffmpeg is installed."""
    import shutil

    anim = BUILD[name]("paper")
    monkeypatch.setattr(shutil, "which", lambda _name: None)
    html = anim._repr_html_()
    assert "<script" in html and html.count("data:image/png;base64") >= FRAMES, name
    monkeypatch.undo()
    if shutil.which("ffmpeg"):
        assert "<video" in anim._repr_html_()


def test_a_plain_matplotlib_animation_does_not_play_inline() -> None:
    """Negative control: matplotlib's own FuncAnimation shows nothing by default, which is why
    poinsot's animations carry their own ``_repr_html_``."""
    import matplotlib as mpl
    import matplotlib.pyplot as plt
    from matplotlib import animation

    fig = plt.figure()
    (line,) = fig.gca().plot([0, 1], [0, 1])
    anim = animation.FuncAnimation(fig, lambda i: (line,), frames=2, blit=True)
    assert mpl.rcParams["animation.html"] == "none"
    assert anim._repr_html_() is None
    plt.close(fig)
