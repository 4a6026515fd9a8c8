"""`poinsot lab --export FILE.html`: the lab as one self-contained file (issue 23, item 2).

The copy and its refusals run on a stand-in file (no built page needed); the checks of the built
file itself (one file, nothing loaded from elsewhere, under 4 MB) run where the lab is built
(`make lab-build`), and web/tests/export.test.mjs opens it from file:// in chromium.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from click.testing import CliRunner
from poinsot import _labserver
from poinsot.cli import main

#: Most bytes the one-file lab may have: small enough to e-mail (about 2.2 MB is built).
MAX_EXPORT_BYTES = 4_000_000


@pytest.fixture()
def built(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> bytes:
    """A stand-in for the built page's folder, with its one-file lab."""
    page = tmp_path / "page"
    page.mkdir()
    body = b"<!doctype html><title>poinsot lab</title><script type=module>1</script>\n"
    (page / _labserver.EXPORT_NAME).write_bytes(body)
    monkeypatch.setattr(_labserver, "page_dir", lambda: page)
    return body


def run(*args: str) -> tuple[int, str]:
    result = CliRunner().invoke(main, ["lab", *args])
    return result.exit_code, result.output


def test_export_copies_the_one_file_lab_and_says_how_to_open_it(
    built: bytes, tmp_path: Path
) -> None:
    target = tmp_path / "for the class" / "poinsot-lab.html"
    target.parent.mkdir()
    code, out = run("--export", str(target))
    assert code == 0, out
    assert target.read_bytes() == built
    assert "double-click" in out and str(target) in out
    # an existing file is replaced
    target.write_bytes(b"old")
    assert run("--export", str(target))[0] == 0
    assert target.read_bytes() == built


@pytest.mark.parametrize(
    ("make", "expected"),
    [
        (lambda d: d, "is a folder; give a file name"),
        (lambda d: d / "missing" / "lab.html", "no folder"),
        (lambda d: d / "lab.txt", "does not end in .html"),
    ],
)
def test_export_refuses_a_path_it_cannot_use_naming_the_option(
    built: bytes, tmp_path: Path, make: object, expected: str
) -> None:
    target = make(tmp_path)  # type: ignore[operator]
    code, out = run("--export", str(target))
    assert code == 2
    assert "--export" in out and expected in out


def test_export_refuses_an_unwritable_file_naming_the_option(built: bytes, tmp_path: Path) -> None:
    # A folder that exists but cannot take the file (works as root too: /proc refuses creation).
    target = Path("/proc/poinsot-lab.html")
    if not Path("/proc").is_dir():
        pytest.skip("no /proc")
    code, out = run("--export", str(target))
    assert code == 1
    assert "--export: cannot write" in out and str(target) in out


def test_export_without_a_built_lab_says_how_to_build_it(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    monkeypatch.setattr(_labserver, "page_dir", lambda: tmp_path / "nothing")
    code, out = run("--export", str(tmp_path / "lab.html"))
    assert code == 1
    assert "make lab-build" in out
    assert not (tmp_path / "lab.html").exists()


def test_the_built_one_file_lab_is_self_contained() -> None:
    path = _labserver.export_file()
    if not path.is_file():
        pytest.skip(f"the lab is not built ({path}): make lab-build")
    text = path.read_text(encoding="utf-8")
    assert 1_000_000 < len(text.encode()) < MAX_EXPORT_BYTES
    # no script, stylesheet or image loaded from a file beside it or from the network
    assert not re.search(r"<script[^>]*\bsrc=", text)
    assert not re.search(r"<link[^>]*\brel=\"(stylesheet|modulepreload)\"", text)
    assert not re.search(r"\b(src|href)=\"(?!data:|#)[^\"]+\"", text)
    assert "poinsot_wasm_bg.wasm" not in text  # the core is inside, not fetched beside it
    # its own policy: inline code and WebAssembly, nothing from anywhere
    assert "Content-Security-Policy" in text and "default-src 'none'" in text
