"""`poinsot free`: the JSON document, the table, and errors as one line."""

from __future__ import annotations

import json

import numpy as np
from click.testing import CliRunner
from poinsot import FreeRigidBody
from poinsot.cli import main


def test_free_json_reports_the_exact_solution_and_the_method():
    res = CliRunner().invoke(
        main,
        [
            "free",
            "--moments",
            "1",
            "2",
            "3",
            "--omega",
            "1",
            "0.1",
            "1",
            "--duration",
            "50",
            "--method",
            "splitting4",
            "--dt",
            "0.01",
            "--json",
        ],
    )
    assert res.exit_code == 0, res.output
    data = json.loads(res.output)
    exact = FreeRigidBody([1, 2, 3], [1, 0.1, 1])
    assert data["regime"] == "about max axis" and data["method"] == "splitting4"
    assert abs(data["period"] - exact.period) < 1e-12
    np.testing.assert_allclose(data["omega_exact"], exact.omega(50.0), atol=1e-13)
    assert data["omega_error"] < 1e-6 and data["max_momentum_error"] < 1e-12
    assert data["axis_stability"] == ["stable", "unstable", "stable"]


def test_free_table_and_bad_input():
    res = CliRunner().invoke(main, ["free", "--moments", "1", "2", "3", "--omega", "1", "0.1", "1"])
    assert res.exit_code == 0 and "regime" in res.output
    res = CliRunner().invoke(
        main, ["free", "--moments", "1", "1", "3", "--omega", "1", "0", "0", "--json"]
    )
    assert res.exit_code == 1  # refused input (poinsot --help)
    assert "--moments:" in res.output
