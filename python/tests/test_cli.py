"""The command line: `poinsot tour`, `poinsot inertia`, errors as one clear line, --json."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import poinsot as ps
import pytest
from click.testing import CliRunner
from poinsot.cli import main


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(main, list(args))
    return result.exit_code, result.stdout, result.stderr


def test_tour_runs_and_covers_the_topics() -> None:
    code, out, _ = run("tour")
    assert code == 0, out
    for topic in ("Euler's theorem", "Chasles", "2.99", "inertia tensor", "dumbbell"):
        assert topic in out


def test_python_dash_m_is_the_same_command() -> None:
    proc = subprocess.run(
        [
            sys.executable,
            "-m",
            "poinsot",
            "inertia",
            "sphere",
            "--mass",
            "2",
            "--radius",
            "0.5",
            "--json",
        ],
        capture_output=True,
        text=True,
        check=True,
    )
    data = json.loads(proc.stdout)
    assert data["kind"] == "spherical top"


def test_inertia_json_matches_the_api() -> None:
    code, out, _ = run("inertia", "cuboid", "--mass", "2", "--sides", "1", "2", "3", "--json")
    assert code == 0, out
    data = json.loads(out)
    body = ps.RigidBody.cuboid(2.0, (1.0, 2.0, 3.0))
    np.testing.assert_allclose(data["inertia"], body.inertia, rtol=0, atol=0)
    np.testing.assert_allclose(data["principal_moments"], body.principal_moments, rtol=0, atol=0)
    # and against the textbook formula m (b² + c²) / 12, independently
    np.testing.assert_allclose(
        data["principal_moments"], sorted([2 * (4 + 9) / 12, 2 * (1 + 9) / 12, 2 * (1 + 4) / 12])
    )
    assert data["kind"] == "asymmetric top"


def test_inertia_table_output() -> None:
    code, out, _ = run("inertia", "cone", "--mass", "1", "--radius", "0.5", "--height", "2")
    assert code == 0
    assert "symmetric top" in out and "principal moments" in out


def test_inertia_of_a_mesh_file(tmp_path: Path) -> None:
    trimesh = pytest.importorskip("trimesh")
    path = tmp_path / "box.stl"
    trimesh.creation.box(extents=(1.0, 2.0, 3.0)).export(path)
    code, out, _ = run("inertia", str(path), "--density", "10", "--json")
    assert code == 0, out
    data = json.loads(out)
    assert data["mass"] == pytest.approx(60.0, rel=1e-12)
    np.testing.assert_allclose(
        data["principal_moments"],
        sorted([60 * (4 + 9) / 12, 60 * (1 + 9) / 12, 60 * (1 + 4) / 12]),
        rtol=1e-12,
    )


def test_open_mesh_file_is_refused(tmp_path: Path) -> None:
    trimesh = pytest.importorskip("trimesh")
    mesh = trimesh.creation.box(extents=(1.0, 1.0, 1.0))
    mesh.update_faces(np.arange(len(mesh.faces)) != 0)  # drop one triangle: an open box
    path = tmp_path / "open.stl"
    mesh.export(path)
    code, _, err = run("inertia", str(path))
    assert code == 1  # refused input (poinsot --help)
    assert "error:" in err and "open" in err


def test_plot_option_writes_a_picture(tmp_path: Path) -> None:
    pytest.importorskip("matplotlib")
    path = tmp_path / "ellipsoid.png"
    code, out, _ = run("inertia", "cuboid", "--sides", "1", "2", "3", "--plot", str(path))
    assert code == 0, out
    assert path.stat().st_size > 10_000


@pytest.mark.parametrize(
    ("args", "needle", "status"),
    [
        (("inertia", "sphere", "--mass", "-1", "--radius", "1"), "--mass:", 1),  # refused
        (("inertia", "sphere", "--radius", "nan"), "--radius", 2),  # not a finite number: usage
        (("inertia", "cylinder", "--radius", "1"), "--height", 2),
        (("inertia", "sphere", "--radius", "1", "--height", "2"), "--height", 2),
        (("inertia", "no-such-shape-or-file"), "neither a shape", 2),
    ],
)
def test_bad_input_names_the_argument(args: tuple[str, ...], needle: str, status: int) -> None:
    code, out, err = run(*args)
    assert code == status
    assert needle in err and out == ""
    assert len(err.splitlines()) == 1 and err.startswith("error: ")
