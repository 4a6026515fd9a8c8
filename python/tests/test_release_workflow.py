"""The release workflow (.github/workflows/release.yml, issue 23, item 1) cannot run here: no GitHub
runner, no macOS or Windows. What can be checked is its text: it parses, its wheel and test
matrices cover the five platforms (Linux x86-64 and aarch64, macOS x86-64 and arm64, Windows x64),
every build starts from the built lab, each wheel is tested on a runner of its own platform, and
PyPI and GitHub Pages are published only on a tag, PyPI without a stored token. actionlint, when
installed (on PATH or in Go's ~/go/bin: `go install github.com/rhysd/actionlint/cmd/actionlint@v1.7.12`),
checks the expressions, the runner labels and the actions' inputs."""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path
from typing import Any

import pytest

yaml = pytest.importorskip("yaml")

ROOT = Path(__file__).resolve().parents[2]
WORKFLOW = ROOT / ".github" / "workflows" / "release.yml"
# (runner family, maturin-action target) of every platform a wheel is published for
PLATFORMS = {
    "linux-x86_64": ("ubuntu", "x86_64"),
    "linux-aarch64": ("ubuntu", "aarch64"),
    "macos-x86_64": ("macos", "x86_64"),
    "macos-arm64": ("macos", "aarch64"),
    "windows-x64": ("windows", "x64"),
}
ON_TAG = "github.event_name == 'push' && startsWith(github.ref, 'refs/tags/v')"


@pytest.fixture(scope="module")
def workflow() -> dict[Any, Any]:
    doc = yaml.safe_load(WORKFLOW.read_text(encoding="utf-8"))
    assert isinstance(doc, dict)
    return doc


def _steps(job: dict[str, Any]) -> list[dict[str, Any]]:
    return list(job.get("steps", []))


def _uses(job: dict[str, Any]) -> list[str]:
    return [str(s.get("uses", "")) for s in _steps(job)]


def _matrix(job: dict[str, Any]) -> dict[str, dict[str, str]]:
    return {row["platform"]: row for row in job["strategy"]["matrix"]["include"]}


def _needs(job: dict[str, Any]) -> list[str]:
    needs = job.get("needs", [])
    return [needs] if isinstance(needs, str) else list(needs)


def test_triggers(workflow: dict[Any, Any]) -> None:
    # YAML 1.1 (PyYAML) reads the key `on` as True
    on = workflow.get("on", workflow.get(True))
    assert on["push"]["tags"] == ["v*"]
    assert "workflow_dispatch" in on


def test_wheels_cover_the_five_platforms_with_maturin(workflow: dict[Any, Any]) -> None:
    job = workflow["jobs"]["wheels"]
    rows = _matrix(job)
    assert set(rows) == set(PLATFORMS)
    for platform, (family, target) in PLATFORMS.items():
        assert rows[platform]["os"].startswith(family), platform
        assert rows[platform]["target"] == target, platform
    assert any(u.startswith("PyO3/maturin-action@") for u in _uses(job))
    # Linux wheels for glibc >= 2.17 (manylinux2014), not the build machine's glibc
    assert rows["linux-x86_64"]["manylinux"] == rows["linux-aarch64"]["manylinux"] == "2_17"


def test_every_build_has_the_lab_first(workflow: dict[Any, Any]) -> None:
    jobs = workflow["jobs"]
    assert "bash web/build.sh" in [s.get("run") for s in _steps(jobs["lab"])]
    for name in ("wheels", "sdist"):
        job = jobs[name]
        assert "lab" in _needs(job), name
        steps = _steps(job)
        uses = _uses(job)
        download = uses.index("actions/download-artifact@v4")
        build = next(i for i, u in enumerate(uses) if u.startswith("PyO3/maturin-action@"))
        assert download < build, name
        assert steps[download]["with"] == {"name": "lab", "path": "python/poinsot"}, name
    sdist = next(s for s in _steps(jobs["sdist"]) if "maturin-action" in str(s.get("uses")))
    assert sdist["with"]["command"] == "sdist"


def test_each_wheel_is_tested_on_its_own_platform(workflow: dict[Any, Any]) -> None:
    job = workflow["jobs"]["test"]
    assert _needs(job) == ["wheels"]
    rows = _matrix(job)
    assert set(rows) == set(PLATFORMS)
    for platform, (family, _) in PLATFORMS.items():
        assert rows[platform]["os"].startswith(family), platform
    assert rows["linux-aarch64"]["os"].endswith("-arm"), "the aarch64 wheel on an ARM runner"
    script = "\n".join(str(s.get("run", "")) for s in _steps(job))
    assert "--only-binary" in script and "dist/*.whl" in script
    assert "import poinsot" in script and "poinsot top" in script and "pytest" in script
    # the sdist too, built from source
    sdist = "\n".join(str(s.get("run", "")) for s in _steps(workflow["jobs"]["test-sdist"]))
    assert "pip install" in sdist and "dist/*.tar.gz" in sdist


def test_publishing_runs_only_on_tags_and_after_the_tests(workflow: dict[Any, Any]) -> None:
    jobs = workflow["jobs"]
    assert workflow["permissions"] == {"contents": "read"}
    for name in ("publish", "site", "pages"):
        assert jobs[name]["if"] == ON_TAG, name
    for name in ("publish", "site"):
        assert {"test", "test-sdist"} <= set(_needs(jobs[name])), name
    publish = jobs["publish"]
    assert "pypa/gh-action-pypi-publish@release/v1" in _uses(publish)
    assert publish["permissions"] == {"id-token": "write"}  # trusted publishing
    assert "secrets." not in WORKFLOW.read_text(encoding="utf-8")  # no stored token
    assert "make site" in [s.get("run") for s in _steps(jobs["site"])]
    assert "actions/deploy-pages@v4" in _uses(jobs["pages"])
    # the folder uploaded to Pages is the one `make site` writes and checks
    site_dir = re.search(r"^SITE_DIR := (\S+)$", (ROOT / "Makefile").read_text(), re.MULTILINE)
    assert site_dir, "Makefile: no SITE_DIR"
    assert jobs["site"]["env"]["SITE"] == site_dir.group(1)
    upload = next(s for s in _steps(jobs["site"]) if "upload-pages-artifact" in str(s.get("uses")))
    assert upload["with"]["path"] == "${{ env.SITE }}"
    # the jobs no tag runs are the only ones a pull request can reach
    untagged = {n for n, j in jobs.items() if "if" not in j}
    assert untagged == {"lab", "wheels", "sdist", "test", "test-sdist"}


def test_the_file_says_what_cannot_run_here() -> None:
    head = WORKFLOW.read_text(encoding="utf-8").split("\nname:")[0]
    assert "WHAT CANNOT RUN HERE" in head and "never run" in head


def test_actionlint() -> None:
    tool = shutil.which("actionlint") or shutil.which(
        "actionlint", path=str(Path.home() / "go/bin")
    )
    if tool is None:
        pytest.skip("actionlint is not installed")
    proc = subprocess.run(
        [tool, "-no-color", str(WORKFLOW)], capture_output=True, text=True, timeout=120
    )
    assert proc.returncode == 0, proc.stdout + proc.stderr
