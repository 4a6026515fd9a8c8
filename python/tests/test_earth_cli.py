"""The `poinsot fall / projectile / foucault` commands and the frames/Earth tour sections."""

from __future__ import annotations

import json

import numpy as np
import poinsot as ps
from click.testing import CliRunner
from poinsot.cli import main
from rich.console import Console


def _json(args: list[str]) -> dict:
    res = CliRunner().invoke(main, args)
    assert res.exit_code == 0, res.output
    return json.loads(res.output)


def test_fall_json_reproduces_the_unit() -> None:
    data = _json(["fall", "--height", "100", "--latitude", "45", "--degrees", "--json"])
    assert abs(data["east"] / 1.552e-2 - 1) < 1e-3 and data["north"] < 0
    assert abs(data["east"] / data["first_order_east"] - 1) < 1e-6
    solar = _json(
        ["fall", "--height", "100", "--latitude", "45", "--degrees", "--solar-day", "--json"]
    )
    assert f"{solar['east']:.2e}" == "1.55e-02"
    rad = _json(["fall", "--height", "100", "--latitude", str(np.pi / 4), "--json"])
    assert abs(rad["east"] - data["east"]) < 1e-12


def test_fall_table_and_errors() -> None:
    res = CliRunner().invoke(main, ["fall", "--height", "100", "--latitude", "45", "--degrees"])
    assert res.exit_code == 0 and "eq. 2.42" in res.output
    bad = CliRunner().invoke(main, ["fall", "--height", "-1", "--latitude", "45", "--degrees"])
    assert bad.exit_code == 1 and "--height" in bad.output  # refused input (poinsot --help)
    bad = CliRunner().invoke(main, ["fall", "--height", "10", "--latitude", "95", "--degrees"])
    assert bad.exit_code == 1 and "--latitude" in bad.output


def test_fall_inverse_square_is_one_integration(monkeypatch) -> None:
    """`--gravity inverse-square` reports that model's drop, integrated once (it integrated the
    uniform drop first and then the inverse-square one)."""
    calls: list[object] = []
    drop = ps.Earth.drop

    def counted(self, *args, **kwargs):  # type: ignore[no-untyped-def]
        calls.append(kwargs.get("gravity"))
        return drop(self, *args, **kwargs)

    monkeypatch.setattr(ps.Earth, "drop", counted)
    args = ["fall", "--height", "1000", "--latitude", "0.7", "--json"]
    data = _json([*args, "--gravity", "inverse-square"])
    assert calls == ["inverse-square"]
    ref = drop(ps.Earth(), 1000.0, 0.7, gravity="inverse-square")
    assert (data["time"], data["east"], data["north"]) == (ref.time, ref.east, ref.north)
    # Negative control: the uniform model falls faster (g does not weaken with height).
    uniform = _json(args)
    assert uniform["time"] < data["time"]


def test_projectile_json_drifts_right_in_the_north() -> None:
    n = _json(
        [
            "projectile",
            "--speed",
            "500",
            "--elevation",
            "40",
            "--azimuth",
            "0",
            "--latitude",
            "50",
            "--degrees",
            "--json",
        ]
    )
    s = _json(
        [
            "projectile",
            "--speed",
            "500",
            "--elevation",
            "40",
            "--azimuth",
            "0",
            "--latitude",
            "-50",
            "--degrees",
            "--json",
        ]
    )
    assert n["with_rotation"]["drift"] > 0 > s["with_rotation"]["drift"]
    assert abs(n["without_rotation"]["drift"]) < 1e-6
    g = ps.Earth().g
    assert abs(n["without_rotation"]["range"] / (500**2 * np.sin(np.radians(80)) / g) - 1) < 1e-9


def test_foucault_json() -> None:
    data = _json(["foucault", "--latitude", "45", "--degrees", "--duration", "1200", "--json"])
    assert data["sense"] == "clockwise"
    assert abs(data["precession_rate"] / data["expected_rate"] - 1) < 5e-3


def test_tour_sections_print_the_units_numbers() -> None:
    from poinsot import tour

    con = Console(record=True, width=140)
    titles = []
    for title, fn in tour._SECTIONS:
        words = ("Moving frames", "rotating Earth", "falling body", "Foucault's pendulum")
        if any(w in title for w in words):
            fn(con)
            titles.append(title)
    assert len(titles) == 4
    text = con.export_text()
    for needle in (
        "1.55e-2",
        "3.4e-2",
        "7.2722e-05",
        "1.5524e-02",
        "clockwise",
        "counterclockwise",
    ):
        assert needle in text, needle
