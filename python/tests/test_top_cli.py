"""`poinsot top`, the heavy-top plots, tour sections, examples and docs/heavy_top.md."""

from __future__ import annotations

import json
import re
import runpy
import sys
from pathlib import Path

import matplotlib
import numpy as np
import poinsot as ps
import pytest
from click.testing import CliRunner
from poinsot.cli import main
from rich.console import Console

matplotlib.use("Agg")

ROOT = Path(__file__).resolve().parents[2]
BLOCK = re.compile(r"```python\n(.*?)```", re.DOTALL)


def _json(args: list[str]) -> dict:
    res = CliRunner().invoke(main, args)
    assert res.exit_code == 0, res.output
    return json.loads(res.output)


def test_top_json_matches_the_api() -> None:
    data = _json(
        [
            "top",
            "--I1",
            "1",
            "--I3",
            "0.5",
            "--mgl",
            "1",
            "--theta",
            "0.8",
            "--psi-dot",
            "6",
            "--json",
        ]
    )
    top = ps.HeavyTop(1.0, 0.5, 1.0, 0.8, psi_dot=6.0)
    assert data["motion_class"] == "cusps" == top.motion_class
    assert data["turning_points"] == list(top.turning_points)
    assert data["p_phi"] == top.p_phi and data["p_psi"] == top.p_psi
    assert data["nutation_period"] == top.nutation_period
    slow, fast = ps.HeavyTop.steady_precession_rates(1.0, 0.5, 1.0, 0.8, 6.0)
    assert data["steady_precession_at_theta0"]["slow"] == slow
    assert data["steady_precession_at_theta0"]["fast"] == fast
    assert data["sleeping_stable"] is True


def test_top_errata_example_and_degrees() -> None:
    data = _json(
        [
            "top",
            "--I1",
            "1",
            "--I3",
            "0.5",
            "--mgl",
            "0.3",
            "--theta",
            "0.6",
            "--psi-dot",
            "40",
            "--json",
        ]
    )
    steady = data["steady_precession_at_theta0"]
    assert round(steady["fast"], 4) == 24.2176 and round(steady["fast_approx_2_120"], 4) == 24.2326
    deg = _json(
        [
            "top",
            "--I1",
            "1",
            "--I3",
            "0.5",
            "--mgl",
            "0.3",
            "--theta",
            str(np.degrees(0.6)),
            "--degrees",
            "--psi-dot",
            str(np.degrees(40.0)),
            "--json",
        ]
    )
    assert deg["turning_points"] == pytest.approx(data["turning_points"], abs=1e-13)


def test_top_below_minimum_spin_and_sleeping() -> None:
    data = _json(
        [
            "top",
            "--I1",
            "1",
            "--I3",
            "0.5",
            "--mgl",
            "1",
            "--theta",
            "0.0",
            "--psi-dot",
            "3",
            "--json",
        ]
    )
    assert data["motion_class"] == "sleeping" and data["sleeping_stable"] is False
    assert data["nutation_period"] == "inf"
    assert "omega3" in data["steady_precession_at_theta0"]["error"]


def test_top_table_and_bad_input() -> None:
    res = CliRunner().invoke(
        main,
        [
            "top",
            "--I1",
            "1",
            "--I3",
            "0.5",
            "--mgl",
            "1",
            "--theta",
            "0.8",
            "--phi-dot",
            "-0.5",
            "--psi-dot",
            "6",
        ],
    )
    assert res.exit_code == 0 and "loops" in res.output and "2.116" in res.output
    bad = CliRunner().invoke(
        main, ["top", "--I1", "1", "--I3", "0.5", "--mgl", "-1", "--theta", "0.8"]
    )
    assert bad.exit_code == 1 and "--mgl:" in bad.output  # refused input (poinsot --help)
    bad = CliRunner().invoke(
        main, ["top", "--I1", "1", "--I3", "0.5", "--mgl", "1", "--theta", "4"]
    )
    assert bad.exit_code == 1 and "--theta:" in bad.output


def test_plots_return_figures(tmp_path: Path) -> None:
    from poinsot.plots import top as plots_top

    top = ps.HeavyTop(1.0, 0.5, 1.0, 0.8, phi_dot=-0.5, psi_dot=6.0)
    for fig in (
        plots_top.plot_effective_potential(top),
        plots_top.plot_axis_locus(top),
        plots_top.plot_angles(top),
        plots_top.plot_steady_precession(1.0, 0.5, 1.0, 0.8),
        plots_top.plot_steady_precession(1.0, 0.5, 1.0, 2.0),
    ):
        assert fig.axes
    anim = plots_top.animate_top(top, tmp_path / "top.gif", frames=5)
    assert (tmp_path / "top.gif").stat().st_size > 0
    assert anim is not None
    paths = plots_top.save_top_plots(
        ps.HeavyTop(1.0, 0.5, 1.0, 0.0, psi_dot=3.0), tmp_path / "sleep"
    )
    assert len(paths) == 4 and all(p.stat().st_size > 0 for p in paths)


def test_tour_sections_run() -> None:
    from poinsot import tour

    con = Console(record=True, width=200)
    tour._heavy_top(con)
    tour._fast_top(con)
    text = con.export_text()
    assert "cusps" in text and "loops" in text and "waves" in text
    assert "24.2176" in text and "24.2326" in text and "12.1163" in text


@pytest.mark.parametrize("script", ["examples/heavy_top.py", "examples/steady_precession.py"])
def test_examples_run(script: str, monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(sys, "argv", [script])
    runpy.run_path(str(ROOT / script), run_name="__main__")


def test_doc_blocks_run() -> None:
    doc = "docs/heavy_top.md"
    blocks = BLOCK.findall((ROOT / doc).read_text(encoding="utf-8"))
    assert blocks
    namespace: dict[str, object] = {"__name__": "__doc__"}
    for i, block in enumerate(blocks):
        exec(compile(block, f"{doc}[block {i}]", "exec"), namespace)
