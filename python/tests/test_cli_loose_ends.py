"""The command line's loose ends (issue 23, item 7): ``poinsot --help`` lists whole summaries,
``poinsot tour`` ends at the documentation site (not at folders a wheel user lacks),
``poinsot notebooks DIR`` copies the teaching notebooks out of the package, and Getting started
lists the extras that pyproject.toml declares."""

from __future__ import annotations

import re
import sys
from pathlib import Path

import click
import pytest
from click.testing import CliRunner
from poinsot import cli
from poinsot.cli import main

ROOT = Path(__file__).resolve().parents[2]


def _pyproject() -> dict:
    if sys.version_info >= (3, 11):
        import tomllib
    else:  # pragma: no cover - the venv's Python is 3.11+
        tomllib = pytest.importorskip("tomli")
    return tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))


def _balanced(text: str) -> bool:
    depth = 0
    for ch in text:
        depth += {"(": 1, ")": -1}.get(ch, 0)
        if depth < 0:
            return False
    return depth == 0


def _whole(summary: str) -> bool:
    """A summary is whole: its brackets close and it does not end in "..." (click's cut)."""
    return bool(summary) and _balanced(summary) and not summary.rstrip().endswith("...")


@pytest.mark.parametrize("name", sorted(main.commands))
def test_every_summary_of_poinsot_help_is_whole(name: str) -> None:
    command = main.commands[name]
    summary = command.get_short_help_str(limit=45)
    assert _whole(summary), summary
    assert summary.endswith("."), summary
    # the first paragraph of the command's help, not a cut of it
    first = " ".join((command.help or "").split("\n\n")[0].split())
    assert summary in (first, " ".join((command.short_help or "").split()))


@pytest.mark.parametrize("columns", [80, 120])
def test_poinsot_help_lists_the_whole_summaries(columns: int) -> None:
    res = CliRunner().invoke(main, ["--help"], terminal_width=columns)
    assert res.exit_code == 0
    listing = res.stdout.split("Commands:")[1].split("Exit status")[0]
    assert "..." not in listing
    flat = " ".join(listing.split())
    for name, command in main.commands.items():
        assert f"{name} {command.get_short_help_str()}" in flat


def test_click_would_cut_the_summaries_negative_control() -> None:
    # what click does by itself: "The heavy symmetric top (eqs." — cut mid-parenthesis
    cut = click.Command("top", help=main.commands["top"].help).get_short_help_str(limit=45)
    assert not _whole(cut)


def test_tour_ends_at_the_documentation_site() -> None:
    from poinsot import tour

    url = _pyproject()["project"]["urls"]["Documentation"]
    assert url == tour.DOCS_URL  # the copy used where the metadata is missing
    assert tour.docs_url() == url  # the installed package's metadata
    res = CliRunner().invoke(main, ["tour"])
    assert res.exit_code == 0
    last = " ".join(res.stdout.strip().splitlines()[-5:])
    assert url in last
    # no folder of the repository, which a wheel user does not have
    assert not re.search(r"\b(examples|docs|notebooks)/", last), last
    for pointer in ("poinsot lab", "poinsot notebooks DIR", "poinsot --help"):
        assert pointer in last


def test_notebooks_copies_the_lessons_out(tmp_path: Path) -> None:
    installed = sorted(cli.NOTEBOOKS_DIR.glob("*.ipynb"))
    assert len(installed) >= 4
    target = tmp_path / "lessons" / "unit"
    res = CliRunner().invoke(main, ["notebooks", str(target)])
    assert res.exit_code == 0, res.stderr
    for nb in installed:
        assert (target / nb.name).read_bytes() == nb.read_bytes()
        assert f"saved {target / nb.name}" in res.stdout
    assert "jupyter lab" in res.stdout
    # a second copy would overwrite the student's work: refused, naming DIRECTORY, unless --force
    (target / installed[0].name).write_text("my answers", encoding="utf-8")
    res = CliRunner().invoke(main, ["notebooks", str(target)])
    assert res.exit_code == cli.EXIT_USAGE and "DIRECTORY" in res.stderr and "--force" in res.stderr
    assert (target / installed[0].name).read_text(encoding="utf-8") == "my answers"
    res = CliRunner().invoke(main, ["notebooks", str(target), "--force"])
    assert res.exit_code == 0
    assert (target / installed[0].name).read_bytes() == installed[0].read_bytes()


def test_notebooks_refuses_a_file_as_directory(tmp_path: Path) -> None:
    f = tmp_path / "a-file"
    f.write_text("", encoding="utf-8")
    res = CliRunner().invoke(main, ["notebooks", str(f)])
    assert res.exit_code == cli.EXIT_USAGE and "DIRECTORY" in res.stderr


def test_the_notebooks_are_in_the_package() -> None:
    # the wheel carries python/poinsot/*; notebooks/ at the root of a checkout is a link to them
    assert Path(cli.__file__).parent / "notebooks" == cli.NOTEBOOKS_DIR
    root = ROOT / "notebooks"
    if root.exists():
        assert sorted(p.name for p in root.glob("*.ipynb")) == sorted(
            p.name for p in cli.NOTEBOOKS_DIR.glob("*.ipynb")
        )


def test_getting_started_lists_every_extra() -> None:
    extras = set(_pyproject()["project"]["optional-dependencies"])
    text = (ROOT / "docs" / "getting_started.md").read_text(encoding="utf-8")
    section = text.split("The extras")[1].split("\n## ")[0]
    listed = set(re.findall(r"^- `([a-z]+)`", section, flags=re.M)) | set(
        re.findall(r"; `([a-z]+)`:", section)
    )
    assert listed == extras, listed ^ extras
    # "all" is described as what it holds: the extras whose packages it holds
    deps = _pyproject()["project"]["optional-dependencies"]
    inside = [e for e in extras - {"all"} if deps[e] and set(deps[e]) <= set(deps["all"])]
    line = next(ln for ln in section.splitlines() if ln.startswith("- `all`"))
    count = {2: "two", 3: "three", 4: "four", 5: "five", 6: "six"}[len(inside)]
    assert f"the {count} above" in line, (inside, line)
