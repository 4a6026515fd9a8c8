"""The built wheel, as a user without Rust gets it (issue 11, item 8): installed into a fresh
virtual environment with no Rust toolchain on PATH, `poinsot tour` runs and `poinsot lab` serves
the browser lab that the wheel carries.

`make test-wheel` (part of `make test`) builds the wheel (`make wheel`, into dist/) and runs this
file with POINSOT_WHEEL naming it; without POINSOT_WHEEL these tests are skipped (and `make
test-python` deselects them: they need the built wheel, the browser lab inside it, and the
network or pip's cache for numpy, click and rich).
"""

from __future__ import annotations

import os
import re
import shutil
import signal
import subprocess
import urllib.request
import zipfile
from collections.abc import Iterator
from pathlib import Path

import pytest
from _venv import install_in_fresh_venv

pytestmark = pytest.mark.wheel

WHEEL = os.environ.get("POINSOT_WHEEL", "")


@pytest.fixture(scope="module")
def wheel() -> Path:
    if not WHEEL:
        pytest.skip("needs the built wheel: run `make test-wheel` (POINSOT_WHEEL names it)")
    path = Path(WHEEL).resolve()
    assert path.is_file(), f"POINSOT_WHEEL={WHEEL!r} is not a file"
    return path


def rust_free_path() -> str:
    """PATH without any directory holding cargo or rustc (~/.cargo/bin, a system Rust)."""
    keep = []
    for entry in os.environ.get("PATH", os.defpath).split(os.pathsep):
        if entry and not any(
            shutil.which(tool, path=entry) for tool in ("cargo", "rustc", "rustup")
        ):
            keep.append(entry)
    return os.pathsep.join(keep)


@pytest.fixture(scope="module")
def installed(
    wheel: Path, tmp_path_factory: pytest.TempPathFactory
) -> Iterator[tuple[Path, dict[str, str]]]:
    """A fresh virtual environment with the wheel installed (binary packages only), and the
    environment to run it in: no Rust on PATH, no Cargo or PyO3 variables, no user site."""
    path = rust_free_path()
    for tool in ("cargo", "rustc", "rustup"):
        assert shutil.which(tool, path=path) is None, f"{tool} is still on PATH"
    # --only-binary: nothing may be compiled, the wheel and its dependencies install as they are.
    yield install_in_fresh_venv(
        tmp_path_factory.mktemp("wheel-venv"),
        ["--only-binary", ":all:", str(wheel)],
        drop=("CARGO", "RUSTUP", "RUSTC", "PYO3", "MATURIN", "VIRTUAL_ENV", "PYTHON"),
        path=([], path),
        timeout=600,
    )


def test_wheel_is_abi3_and_carries_the_lab(wheel: Path) -> None:
    assert re.fullmatch(r"poinsot-[^-]+-cp39-abi3-[^-]+\.whl", wheel.name), wheel.name
    names = set(zipfile.ZipFile(wheel).namelist())
    for required in (
        "poinsot/__init__.py",
        "poinsot/cli.py",
        "poinsot/py.typed",
        "poinsot/_core.pyi",
        "poinsot/lab/index.html",
        "poinsot/lab/poinsot-lab.html",  # the lab as one file: `poinsot lab --export`
    ):
        assert required in names, required
    assert any(re.fullmatch(r"poinsot/_core\.(abi3\.so|pyd)", n) for n in names), sorted(names)
    assert any(n.startswith("poinsot/lab/") and n.endswith(".wasm") for n in names)
    # Only the package: no tests, sources of the page, node modules or Rust build output.
    assert all(n.startswith(("poinsot/", "poinsot-")) for n in names), sorted(names)
    assert not any("node_modules" in n or "/tests/" in n for n in names)


def test_installs_without_rust_and_imports_from_the_venv(
    installed: tuple[Path, dict[str, str]],
) -> None:
    bindir, env = installed
    out = subprocess.run(
        [
            str(bindir / "python"),
            "-c",
            "import poinsot, poinsot._core as c; print(poinsot.__file__); print(c.__file__)",
        ],
        env=env,
        cwd=bindir.parent,
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    for line in out.splitlines():
        assert Path(line).resolve().is_relative_to(bindir.parent.resolve()), line


def test_tour_runs(installed: tuple[Path, dict[str, str]]) -> None:
    bindir, env = installed
    proc = subprocess.run(
        [str(bindir / "poinsot"), "tour"],
        env=env,
        cwd=bindir.parent,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert proc.returncode == 0, proc.stderr
    for topic in ("Euler's theorem", "Chasles", "2.99", "inertia tensor", "dumbbell"):
        assert topic in proc.stdout, topic


def fetch(url: str) -> tuple[int, str, bytes]:
    with urllib.request.urlopen(url, timeout=10) as resp:
        return resp.status, resp.headers.get("Content-Type", ""), resp.read()


def test_lab_serves_the_page_and_the_webassembly(installed: tuple[Path, dict[str, str]]) -> None:
    bindir, env = installed
    lab = subprocess.run(
        [str(bindir / "python"), "-c", "import poinsot._labserver as s; print(s.page_dir())"],
        env=env,
        capture_output=True,
        text=True,
        check=True,
    ).stdout.strip()
    wasm = sorted(Path(lab).rglob("*.wasm"))
    assert wasm, f"no .wasm under {lab}"
    proc = subprocess.Popen(
        [str(bindir / "poinsot"), "lab", "--port", "0", "--no-browser"],
        env=env,
        cwd=bindir.parent,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        # SIGINT's default action in the server, as in a terminal (a test run started as a
        # background job of a non-interactive shell would pass on SIG_IGN, and the server
        # would not stop on the SIGINT below).
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
    )
    try:
        assert proc.stdout is not None
        first = proc.stdout.readline()
        match = re.search(r"serving (http://127\.0\.0\.1:\d+/?)", first)
        assert match, (first, proc.stderr.read() if proc.poll() is not None and proc.stderr else "")
        url = match.group(1).rstrip("/")

        status, ctype, body = fetch(url + "/")
        assert status == 200 and ctype.startswith("text/html"), (status, ctype)
        assert b"<html" in body.lower() or b"<!doctype html" in body.lower()
        # every script the page loads comes back as JavaScript
        scripts = re.findall(rb'<script[^>]+src="([^"]+)"', body)
        assert scripts, body[:500]
        for src in scripts:
            status, ctype, _ = fetch(url + "/" + src.decode().lstrip("./"))
            assert status == 200 and ctype.startswith("text/javascript"), (src, status, ctype)

        for path in wasm:
            rel = path.relative_to(lab).as_posix()
            status, ctype, data = fetch(f"{url}/{rel}")
            assert status == 200 and ctype == "application/wasm", (rel, status, ctype)
            assert data[:4] == b"\0asm" and data == path.read_bytes()
    finally:
        proc.send_signal(signal.SIGINT)
        try:
            out, err = proc.communicate(timeout=20)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.communicate()
            raise
    assert proc.returncode == 0, err
    assert "poinsot lab: stopped" in out


def test_the_lab_page_is_the_one_built(wheel: Path) -> None:
    """The wheel's page is the page `make lab-build` produced in this checkout (not a stale one)."""
    built = Path(__file__).resolve().parents[1] / "poinsot" / "lab"
    if not (built / "index.html").is_file():
        pytest.skip("no built page in this checkout")
    with zipfile.ZipFile(wheel) as zf:
        assert zf.read("poinsot/lab/index.html") == (built / "index.html").read_bytes()


#: The teaching notebooks of the checkout, which the wheel carries as package data.
NOTEBOOKS = Path(__file__).resolve().parents[1] / "poinsot" / "notebooks"


def test_wheel_carries_the_notebooks(wheel: Path) -> None:
    names = set(zipfile.ZipFile(wheel).namelist())
    lessons = sorted(NOTEBOOKS.glob("*.ipynb"))
    assert len(lessons) >= 4
    for nb in lessons:
        assert f"poinsot/notebooks/{nb.name}" in names, nb.name


def test_wheel_carries_the_polar_motion_extract(wheel: Path) -> None:
    # poinsot.polar_motion("shipped") reads it as package data (issue 25)
    extract = NOTEBOOKS.parent / "data" / "eop_c04_polar_motion.csv"
    with zipfile.ZipFile(wheel) as zf:
        assert zf.read("poinsot/data/eop_c04_polar_motion.csv") == extract.read_bytes()


def test_notebooks_and_docs_url_from_the_installed_wheel(
    installed: tuple[Path, dict[str, str]],
) -> None:
    # a student with the wheel only: `poinsot notebooks DIR` copies the lessons out, and the
    # tour's last line is the documentation site, read from the installed package's metadata
    bindir, env = installed
    target = bindir.parent.parent / "lessons"
    proc = subprocess.run(
        [str(bindir / "poinsot"), "notebooks", str(target)],
        env=env,
        cwd=bindir.parent,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert proc.returncode == 0, proc.stderr
    assert sorted(p.name for p in target.glob("*.ipynb")) == sorted(
        p.name for p in NOTEBOOKS.glob("*.ipynb")
    )
    url = subprocess.run(
        [str(bindir / "python"), "-c", "from poinsot.tour import docs_url; print(docs_url())"],
        env=env,
        cwd=bindir.parent,
        capture_output=True,
        text=True,
        check=True,
    ).stdout.strip()
    assert url.startswith("https://") and url.endswith("/poinsot/"), url
