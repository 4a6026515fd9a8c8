"""Writing generated pages into the source tree (shared by derive_pages.py and world_pages.py):
a page is rewritten only when its text changes (so Sphinx rebuilds only what changed), and a
folder of generated pages loses the pages that are no longer generated."""

from __future__ import annotations

from pathlib import Path


def write_page(path: Path, text: str) -> bool:
    """Writes ``text`` to ``path`` (UTF-8) unless it holds that text already; True if written."""
    if path.exists() and path.read_text(encoding="utf-8") == text:
        return False
    path.write_text(text, encoding="utf-8")
    return True


def write_folder(folder: Path, pages: dict[Path, str]) -> None:
    """Makes ``folder``, removes its ``*.md`` pages that are not in ``pages`` (path → text,
    paths inside ``folder``) and writes the others with :func:`write_page`."""
    folder.mkdir(parents=True, exist_ok=True)
    for stale in folder.glob("*.md"):
        if stale not in pages:
            stale.unlink()
    for path, text in pages.items():
        write_page(path, text)
