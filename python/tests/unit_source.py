"""Where the tests find the course unit and its hand-made errata: they are kept beside the
repository (``shared/``), not in it. ``POINSOT_UNIT`` names the unit's file and
``POINSOT_SHARED`` the folder that holds ``seed/`` and ``seed-errata.md`` when they are
elsewhere; a test that needs a missing file is skipped, saying which variable names it."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
UNIT_NAME = "seed/unit-2-moving-frames-and-rigid-bodies.md"


def shared_file(name: str) -> Path | None:
    """``shared/<name>`` beside the repository (or under ``POINSOT_SHARED``), None if absent."""
    bases = [os.environ.get("POINSOT_SHARED", ""), ROOT.parent / "shared", ROOT.parent]
    if name == UNIT_NAME and os.environ.get("POINSOT_UNIT"):
        unit = Path(os.environ["POINSOT_UNIT"])
        if unit.is_file():
            return unit
    for base in bases:
        if base and (Path(base) / name).is_file():
            return Path(base) / name
    return None


def unit_path() -> Path | None:
    """The course unit's Markdown file, None if it is not at hand."""
    return shared_file(UNIT_NAME)


def unit_text() -> str:
    """The course unit's text; skips the calling test when it is not at hand."""
    path = unit_path()
    if path is None:
        pytest.skip("the course unit is not at hand (POINSOT_UNIT or POINSOT_SHARED names it)")
    return path.read_text(encoding="utf-8")
