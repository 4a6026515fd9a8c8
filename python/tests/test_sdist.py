"""The source distribution, as a student on a platform without a wheel gets it (issue 23, item 1):
`pip install poinsot-<version>.tar.gz` into a fresh virtual environment builds the Rust core with
only pip and Rust (no node, npm or wasm-bindgen: the browser lab is not built from the sdist, it
travels in it prebuilt when `make sdist` ran after `make lab-build`), then the first commands
answer as they do in this checkout.

`make test-sdist` (part of `make test`) builds the sdist (`make sdist`, into dist/) and runs this
file with POINSOT_SDIST naming it; CARGO_TARGET_DIR=target/sdist keeps the build incremental from
one run to the next. Without POINSOT_SDIST these tests are skipped (and `make test-python`
deselects them: they need the built sdist, a Rust toolchain, and the network or pip's cache for
maturin, numpy, click and rich).
"""

from __future__ import annotations

import os
import subprocess
import sys
import tarfile
from collections.abc import Iterator
from pathlib import Path

import pytest
from _venv import install_in_fresh_venv

pytestmark = pytest.mark.sdist

SDIST = os.environ.get("POINSOT_SDIST", "")
ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "python" / "poinsot"
# The tools of the browser lab's build, which an sdist install must never call.
WEB_TOOLS = ("node", "npm", "npx", "wasm-bindgen")
# The first answer of the README's student start.
FIRST = ["fall", "--height", "100", "--latitude", "45", "--degrees"]


@pytest.fixture(scope="module")
def sdist() -> Path:
    if not SDIST:
        pytest.skip("needs the built sdist: run `make test-sdist` (POINSOT_SDIST names it)")
    path = Path(SDIST).resolve()
    assert path.is_file(), f"POINSOT_SDIST={SDIST!r} is not a file"
    return path


@pytest.fixture(scope="module")
def members(sdist: Path) -> dict[str, bytes]:
    """The sdist's files by path inside its top folder (``poinsot-<version>/``), with contents."""
    out: dict[str, bytes] = {}
    with tarfile.open(sdist) as tar:
        for info in tar.getmembers():
            if info.isfile():
                top, _, rest = info.name.partition("/")
                assert top == sdist.name.removesuffix(".tar.gz"), info.name
                data = tar.extractfile(info)
                assert data is not None
                out[rest] = data.read()
    return out


def test_sdist_carries_the_workspace_the_package_and_the_licences(
    members: dict[str, bytes],
) -> None:
    for required in (
        "PKG-INFO",
        "pyproject.toml",
        "README.md",
        "LICENSE-MIT",
        "LICENSE-APACHE",
        "Cargo.toml",
        "Cargo.lock",
        "crates/poinsot/Cargo.toml",
        "crates/poinsot/src/lib.rs",
        "crates/poinsot-py/Cargo.toml",
        "crates/poinsot-py/src/lib.rs",
        "crates/poinsot-py-macros/Cargo.toml",
        "crates/poinsot-py-macros/src/lib.rs",
        "python/poinsot/py.typed",
        "python/poinsot/_core.pyi",
    ):
        assert required in members, required
    # every module of the package, as in this checkout
    for module in PACKAGE.rglob("*.py"):
        rel = module.relative_to(ROOT).as_posix()
        if "/lab/" not in rel:
            assert rel in members, rel
    # the browser lab's sources, the wasm crate and build outputs stay out: the sdist builds with
    # pip and Rust only, and its workspace manifest names no crate it does not carry
    for name in members:
        assert not name.startswith(("web/", "crates/poinsot-wasm/", "target/", "python/tests/"))
        assert "node_modules" not in name and not name.endswith((".so", ".pyd")), name
    assert b"poinsot-wasm" not in members["Cargo.toml"]
    assert members["Cargo.lock"] == (ROOT / "Cargo.lock").read_bytes()


def test_sdist_carries_the_built_lab(members: dict[str, bytes]) -> None:
    """`make sdist` runs after `make lab-build`: the page and its WebAssembly travel prebuilt, as
    this checkout built them, and so do the notebook widgets' front end."""
    built = PACKAGE / "lab"
    if not (built / "index.html").is_file():
        pytest.skip("no built lab in this checkout (make lab-build)")
    assert members["python/poinsot/lab/index.html"] == (built / "index.html").read_bytes()
    assert any(n.startswith("python/poinsot/lab/") and n.endswith(".wasm") for n in members)
    widget = PACKAGE / "widgets" / "static" / "widget.js"
    if widget.is_file():
        assert members["python/poinsot/widgets/static/widget.js"] == widget.read_bytes()


def _shims(folder: Path, log: Path) -> None:
    """Commands named like the web tools that only record that they were called."""
    folder.mkdir()
    for tool in WEB_TOOLS:
        shim = folder / tool
        shim.write_text(f'#!/bin/sh\necho "{tool} $*" >> "{log}"\nexit 1\n')
        shim.chmod(0o755)


@pytest.fixture(scope="module")
def installed(
    sdist: Path, tmp_path_factory: pytest.TempPathFactory
) -> Iterator[tuple[Path, dict[str, str], Path]]:
    """A fresh virtual environment with the sdist installed by plain `pip install` (maturin builds
    the core with the Rust on PATH), the environment to run it in, and the log of the web tools'
    calls (empty when none was called)."""
    if os.name == "nt":
        pytest.skip("the web tools' shims are shell scripts")
    root = tmp_path_factory.mktemp("sdist-venv")
    log = root / "web-tools.log"
    _shims(root / "shims", log)
    bindir, env = install_in_fresh_venv(
        root,
        [str(sdist)],
        drop=("PYO3", "MATURIN", "VIRTUAL_ENV", "PYTHON"),
        path=([str(root / "shims")], os.environ["PATH"]),
        timeout=1800,
        extra_env={"COLUMNS": "80"},
    )
    yield bindir, env, log


def test_the_build_calls_no_web_tool(installed: tuple[Path, dict[str, str], Path]) -> None:
    _, _, log = installed
    assert not log.exists(), log.read_text()


def _run(argv: list[str], env: dict[str, str], cwd: Path) -> str:
    proc = subprocess.run(argv, env=env, cwd=cwd, capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    return proc.stdout


def test_first_answers_are_this_checkouts(
    installed: tuple[Path, dict[str, str], Path], tmp_path: Path
) -> None:
    bindir, env, _ = installed
    here = dict(os.environ, COLUMNS="80", MPLBACKEND="Agg")
    # the first command of the README's student start
    got = _run([str(bindir / "poinsot"), *FIRST], env, tmp_path)
    assert got == _run([sys.executable, "-m", "poinsot", *FIRST], here, tmp_path)
    assert "1.552394e-02" in got  # the unit's 1.55e-2 m east (eq. 2.42)
    # the API, imported from the fresh environment
    code = (
        "import poinsot as ps, poinsot._core as c; print(ps.__file__); print(c.__file__); "
        "print(repr(ps.Earth().eastward_deflection(100, 45, degrees=True))); "
        "print(ps.HeavyTop.from_spin(1.0, 0.5, 1.0, 0.5, 20.0).motion_class)"
    )
    lines = _run([str(bindir / "python"), "-c", code], env, tmp_path).splitlines()
    for line in lines[:2]:
        assert Path(line).resolve().is_relative_to(bindir.parent.resolve()), line
    assert lines[2:] == _run([sys.executable, "-c", code], here, tmp_path).splitlines()[2:]


def test_the_installed_lab_is_the_built_one(
    installed: tuple[Path, dict[str, str], Path], members: dict[str, bytes], tmp_path: Path
) -> None:
    """`poinsot lab` from an sdist install serves the page the sdist carried."""
    if "python/poinsot/lab/index.html" not in members:
        pytest.skip("this sdist carries no built lab")
    bindir, env, _ = installed
    code = "import poinsot._labserver as s; print(s.page_dir())"
    lab = Path(_run([str(bindir / "python"), "-c", code], env, tmp_path).strip())
    assert (lab / "index.html").read_bytes() == members["python/poinsot/lab/index.html"]
    assert sorted(lab.rglob("*.wasm")), lab
