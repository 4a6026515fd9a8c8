"""Every ```python block of the README runs (in order, in one namespace), as a user would; every
`poinsot` command of a ```console block that shows its answer (the student start of the README and
of Getting started) prints that answer."""

from __future__ import annotations

import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
BLOCK = re.compile(r"```python\n(.*?)```", re.DOTALL)
CONSOLE = re.compile(r"```console\n(.*?)```", re.DOTALL)


def _blocks(path: Path) -> list[str]:
    return BLOCK.findall(path.read_text(encoding="utf-8"))


def test_readme_has_python_blocks() -> None:
    assert len(_blocks(ROOT / "README.md")) >= 3


@pytest.mark.parametrize("doc", ["README.md", "CONVENTIONS.md"])
def test_code_blocks_run(doc: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    namespace: dict[str, object] = {"__name__": "__readme__"}
    for i, block in enumerate(_blocks(ROOT / doc)):
        try:
            exec(compile(block, f"{doc}[block {i}]", "exec"), namespace)
        except Exception as exc:  # pragma: no cover - the failure message is the point
            raise AssertionError(f"{doc} block {i} failed:\n{block}") from exc


def test_readme_opens_with_make_demo_and_make_test() -> None:
    head = "\n".join((ROOT / "README.md").read_text(encoding="utf-8").splitlines()[:40])
    assert "make demo" in head and "make test" in head


def _sessions(path: Path) -> list[tuple[str, list[str]]]:
    """The ``$ poinsot ...`` commands of the console blocks that are followed by output lines,
    each with those lines (trailing spaces dropped)."""
    out: list[tuple[str, list[str]]] = []
    for block in CONSOLE.findall(path.read_text(encoding="utf-8")):
        command: str | None = None
        shown: list[str] = []
        for line in [*block.splitlines(), "$ "]:
            if line.startswith("$ "):
                if command is not None and shown:
                    out.append((command, shown))
                command = line[2:].split(" #")[0].strip()
                command = command if command.startswith("poinsot ") else None
                shown = []
            elif command is not None:
                shown.append(line.rstrip())
    return out


@pytest.mark.parametrize("doc", ["README.md", "docs/getting_started.md"])
def test_console_answers_are_real(doc: str, tmp_path: Path) -> None:
    sessions = _sessions(ROOT / doc)
    assert sessions, f"{doc}: no console block with a poinsot command and its answer"
    # as in a terminal 80 columns wide (rich wraps the tables to it)
    env = dict(os.environ, COLUMNS="80", MPLBACKEND="Agg")
    for command, shown in sessions:
        argv = [sys.executable, "-m", "poinsot", *shlex.split(command)[1:]]
        proc = subprocess.run(argv, env=env, cwd=tmp_path, capture_output=True, text=True)
        assert proc.returncode == 0, (command, proc.stderr)
        printed = [line.rstrip() for line in proc.stdout.rstrip("\n").splitlines()]
        assert printed == shown, (
            f"{doc}: `{command}` now prints:\n" + "\n".join(printed) + "\n(paste it there)"
        )
