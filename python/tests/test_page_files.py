"""docs/_ext/page_files.py, the page writer shared by derive_pages.py and world_pages.py: a page
is rewritten only when its text changes, and a generated folder loses its stale pages."""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "docs" / "_ext"))

from page_files import write_folder, write_page  # noqa: E402


def test_write_page_only_when_the_text_changes(tmp_path: Path) -> None:
    page = tmp_path / "a.md"
    assert write_page(page, "# A\n")
    assert not write_page(page, "# A\n")
    assert write_page(page, "# B\n")
    assert page.read_text(encoding="utf-8") == "# B\n"


def test_write_folder_removes_stale_pages_and_keeps_other_files(tmp_path: Path) -> None:
    folder = tmp_path / "world"
    write_folder(folder, {folder / "a.md": "a", folder / "b.md": "b"})
    (folder / "figure.png").write_bytes(b"png")
    write_folder(folder, {folder / "b.md": "b2"})
    assert sorted(p.name for p in folder.iterdir()) == ["b.md", "figure.png"]
    assert (folder / "b.md").read_text(encoding="utf-8") == "b2"
