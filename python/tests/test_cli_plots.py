"""The command line's pictures: ``--plot PATH`` on every computing command, ``--animate PATH``
where the motion is the point (foucault, free, top), ``--style paper|slides``, the refusals of
a path it cannot write (exit status 2, naming the option, before any work), and the progress
bar of a long render (on stderr, only on a terminal)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, ClassVar

import pytest
from click.testing import CliRunner

pytest.importorskip("matplotlib")
from PIL import Image
from poinsot import cli
from poinsot.cli import main

#: A short run of each computing command.
RUNS: dict[str, list[str]] = {
    "inertia": ["inertia", "cuboid", "--mass", "2", "--sides", "1", "2", "3"],
    "fall": ["fall", "--height", "100", "--latitude", "45", "--degrees"],
    "projectile": [
        "projectile",
        "--speed",
        "300",
        "--elevation",
        "45",
        "--azimuth",
        "90",
        "--latitude",
        "50",
        "--degrees",
    ],
    "foucault": [
        "foucault",
        "--latitude",
        "45",
        "--degrees",
        "--length",
        "5",
        "--amplitude",
        "0.5",
        "--duration",
        "120",
        "--solar-day",
    ],
    "free": ["free", "--moments", "1", "2", "3", "--omega", "0.01", "2", "0.01", "--duration", "8"],
    "top": ["top", "--I1", "1", "--I3", "0.5", "--mgl", "1", "--theta", "0.8", "--psi-dot", "6"],
}
ANIMATED = ("foucault", "free", "top")


def invoke(args: list[str]) -> tuple[int, str, str]:
    res = CliRunner().invoke(main, args)
    return res.exit_code, res.stdout, res.stderr


def one_line_error(err: str, needle: str) -> None:
    assert len(err.splitlines()) == 1 and err.startswith("error: ") and needle in err, err


@pytest.mark.parametrize("command", list(RUNS))
def test_every_computing_command_has_the_picture_options(command: str) -> None:
    code, out, _ = invoke([command, "--help"])
    assert code == 0
    for option in ("--plot", "--style"):
        assert option in out
    assert ("--animate" in out) == (command in ANIMATED)


@pytest.mark.parametrize("style", ["paper", "slides"])
@pytest.mark.parametrize("command", list(RUNS))
def test_plot_saves_the_picture_in_the_style(command: str, style: str, tmp_path: Path) -> None:
    # every command's --plot names one file (top's folder of pictures is --plot-dir)
    target = tmp_path / "picture.png"
    code, out, err = invoke([*RUNS[command], "--plot", str(target), "--style", style])
    assert code == 0, err
    assert target.stat().st_size > 10_000
    with Image.open(target) as im:
        assert im.info["dpi"][0] == pytest.approx(200 if style == "slides" else 150, abs=0.5)
    assert f"saved {target}" in out
    code, out, _ = invoke([*RUNS[command], "--plot", str(target), "--json"])
    assert code == 0 and json.loads(out)["plots"]


@pytest.mark.parametrize("command", ANIMATED)
def test_animate_writes_a_gif(command: str, tmp_path: Path) -> None:
    target = tmp_path / "motion.gif"
    code, out, err = invoke([*RUNS[command], "--animate", str(target)])
    assert code == 0, err
    with Image.open(target) as im:
        assert im.n_frames >= 100 and im.width >= 500
    assert f"saved {target}" in out


@pytest.mark.parametrize("command", ANIMATED)
@pytest.mark.parametrize(
    ("name", "needle"),
    [("motion.avi", "cannot write '.avi' animations"), ("motion", "ending in .gif")],
)
def test_animate_refuses_a_suffix_it_cannot_write(
    command: str, name: str, needle: str, tmp_path: Path
) -> None:
    code, out, err = invoke([*RUNS[command], "--animate", str(tmp_path / name)])
    assert code == cli.EXIT_USAGE and out == ""
    one_line_error(err, "--animate")
    assert needle in err
    assert not list(tmp_path.iterdir())


def test_animate_mp4_needs_ffmpeg(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import shutil

    monkeypatch.setattr(shutil, "which", lambda name: None)
    code, out, err = invoke([*RUNS["free"], "--animate", str(tmp_path / "flip.mp4")])
    assert code == cli.EXIT_USAGE and out == ""
    one_line_error(err, "--animate")
    assert "ffmpeg" in err and "not installed" in err
    # with ffmpeg on PATH the same path passes the check (and is written by ffmpeg)
    monkeypatch.setattr(shutil, "which", lambda name: f"/usr/bin/{name}")
    cli._check_animation_path(str(tmp_path / "flip.mp4"))


def test_pictures_are_checked_before_the_run(tmp_path: Path) -> None:
    for option in ("--plot", "--animate"):
        code, _, err = invoke([*RUNS["foucault"], option, str(tmp_path / "no" / "x.gif")])
        assert code == cli.EXIT_USAGE
        one_line_error(err, option)
    code, _, err = invoke([*RUNS["fall"], "--plot", str(tmp_path / "x.nosuchformat")])
    assert code == cli.EXIT_USAGE
    one_line_error(err, "--plot")
    code, _, err = invoke([*RUNS["fall"], "--plot", str(tmp_path / "x.png"), "--style", "poster"])
    assert code == cli.EXIT_USAGE
    one_line_error(err, "--style")


class _SpyBar:
    """Stands for rich's Progress: records what a render reports."""

    made: ClassVar[list[_SpyBar]] = []

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        self.kwargs = kwargs
        self.updates: list[tuple[int, int]] = []
        self.stopped = False
        _SpyBar.made.append(self)

    def start(self) -> None:
        pass

    def add_task(self, description: str, total: int) -> int:
        self.description = description
        return 0

    def update(self, task: int, completed: int, total: int) -> None:
        self.updates.append((completed, total))

    def stop(self) -> None:
        self.stopped = True


@pytest.fixture
def spy_bar(monkeypatch: pytest.MonkeyPatch) -> type[_SpyBar]:
    import rich.progress

    _SpyBar.made = []
    monkeypatch.setattr(rich.progress, "Progress", _SpyBar)
    return _SpyBar


def test_a_long_render_shows_a_progress_bar_on_a_terminal(
    spy_bar: type[_SpyBar], monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    monkeypatch.setattr(cli, "_stderr_interactive", lambda: True)
    monkeypatch.setattr(cli, "SHOW_PROGRESS_AFTER_S", 0.0)  # as if every render were long
    code, _, err = invoke([*RUNS["top"], "--plot-dir", str(tmp_path / "top")])
    assert code == 0, err
    (bar,) = spy_bar.made
    assert bar.stopped and bar.kwargs["console"].stderr  # on stderr, removed when done
    # the four pictures, then the 120 frames of top.gif, in order, to the end
    done = [d for d, _ in bar.updates]
    assert done == sorted(done) and bar.updates[-1] == (124, 124)


def test_no_progress_bar_off_a_terminal_or_for_a_short_render(
    spy_bar: type[_SpyBar], monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    code, _, err = invoke([*RUNS["top"], "--plot-dir", str(tmp_path / "top")])
    assert code == 0 and err == ""
    assert spy_bar.made == []  # CliRunner's stderr is not a terminal
    monkeypatch.setattr(cli, "_stderr_interactive", lambda: True)
    monkeypatch.setattr(cli, "SHOW_PROGRESS_AFTER_S", 3600.0)  # a terminal, a short render
    code, _, _ = invoke([*RUNS["free"], "--animate", str(tmp_path / "flip.gif")])
    assert code == 0 and spy_bar.made == []


def test_top_plot_dir_saves_the_folder_of_pictures(tmp_path: Path) -> None:
    target = tmp_path / "pictures"
    code, out, err = invoke([*RUNS["top"], "--plot-dir", str(target)])
    assert code == 0, err
    names = {"potential.png", "axis_locus.png", "angles.png", "steady_precession.png", "top.gif"}
    assert {p.name for p in target.iterdir()} == names
    for name in sorted(names):
        assert f"saved {target / name}" in out


def test_top_plot_refuses_a_folder_as_every_command_does(tmp_path: Path) -> None:
    # --plot takes a file on every command; a folder is refused before any work, naming --plot
    for command in RUNS:
        code, out, err = invoke([*RUNS[command], "--plot", str(tmp_path)])
        assert code == cli.EXIT_USAGE and out == "", command
        one_line_error(err, "--plot")
