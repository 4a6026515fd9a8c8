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


def _tour_text(width: int) -> str:
    import io

    from poinsot.tour import run_tour
    from rich.console import Console

    con = Console(width=width, record=True, file=io.StringIO())
    run_tour(con)
    return con.export_text()


def test_tour_fits_80_columns() -> None:
    # At 80 columns every heading was cut with "…" (rich's rule) and the heavy-top table cut
    # its cells: now headings wrap, and the text at 80 columns holds every "…" it holds at 200
    # (the ones written in the tour's own text) and no more.
    from poinsot.tour import _SECTIONS

    narrow, wide = _tour_text(80), _tour_text(200)
    from rich.cells import cell_len  # columns on screen (φ̇ is two characters, one column)

    assert max(cell_len(line) for line in narrow.splitlines()) <= 80
    assert narrow.count("…") == wide.count("…")
    flat = " ".join(narrow.split())
    for i, (title, _) in enumerate(_SECTIONS, start=1):
        assert f"{i}. {title}" in flat, title
    for value in ("2.347420", "1.832820", "1.255704", "cusps", "loops", "waves"):
        assert value in narrow
    # negative control: the same headings drawn as rich rules are cut at 80 columns
    import io

    from rich.console import Console

    con = Console(width=80, record=True, file=io.StringIO())
    con.rule(f"1. {_SECTIONS[0][0]}")
    assert "…" in con.export_text()


def test_at_precision_shows_round_off_as_zero_and_keeps_small_results() -> None:
    from poinsot.cli import at_precision

    eps = np.finfo(float).eps
    # the drifts of a shot on a planet that does not turn, over a 65 km range: round-off
    assert at_precision(8.07793567e-28, 65261.8376) == "0"
    assert at_precision(3.63797881e-12, 65261.8376) == "0"
    assert at_precision(-3.6e-12, -65261.8376) == "0"
    # the bound, 8 ε × scale, and just above it
    assert at_precision(8 * eps * 1000.0, 1000.0) == "0"
    assert at_precision(9 * eps * 1000.0, 1000.0) != "0"
    # negative controls: real small values stay, in the format asked for
    assert at_precision(1e-9, 1.0) == "1e-09"
    assert at_precision(424.582113, 65496.2) == "424.582113"
    assert at_precision(2.5e-7, 0.0, "+.3g") == "+2.5e-07"
    assert at_precision(float("nan"), 1.0) == "nan"


def test_projectile_prints_a_zero_drift_without_rotation() -> None:
    args = ("projectile", "--speed", "800", "--elevation", "45", "--azimuth", "90")
    code, out, _ = run(*args, "--latitude", "50", "--degrees", "--json")
    data = json.loads(out)
    still, spin = data["without_rotation"], data["with_rotation"]
    # the computed drift without rotation is round-off, below ε × range (not exactly 0)
    assert abs(still["drift"]) <= 8 * np.finfo(float).eps * still["range"]
    code, out, _ = run(*args, "--latitude", "50", "--degrees")
    assert code == 0
    row = next(line for line in out.splitlines() if "drift" in line)
    cells = [c.strip() for c in row.strip("│ ").split("│")]
    assert cells[2] == "0" and float(cells[1]) == pytest.approx(spin["drift"], rel=1e-8)
