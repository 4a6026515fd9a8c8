"""`poinsot gyrocompass` (issue 26): the compass's period, Schuler tuning, latitude and speed
errors — the API's numbers, units as people type them, --plot, and refusals that name the
option."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import poinsot as ps
import pytest
from click.testing import CliRunner
from poinsot.cli import main

KNOT = 1852.0 / 3600.0  # m/s, the test's own constant


def _run(*args: str) -> tuple[int, str, str]:
    res = CliRunner().invoke(main, ["gyrocompass", *args])
    return res.exit_code, res.stdout, res.stderr


def _json(*args: str) -> dict:
    code, out, err = _run(*args, "--json")
    assert code == 0, err
    return json.loads(out)


def test_the_json_keys_and_the_apis_numbers() -> None:
    d = _json("--latitude", "50deg", "--speed", "20kn", "--course", "0deg")
    assert {
        "latitude",
        "angular_momentum",
        "pendulosity",
        "damping",
        "period",
        "schuler_period",
        "schuler_angular_momentum",
        "settle_error",
        "settle_tilt",
        "speed",
        "course",
        "speed_error",
        "speed_error_small_angle",
        "summary",
    } <= set(d)
    lat = math.radians(50.0)
    c = ps.Gyrocompass(lat)
    assert d["latitude"] == pytest.approx(lat, rel=1e-15)
    assert d["speed"] == pytest.approx(20 * KNOT, rel=1e-12)
    assert d["period"] == c.period
    assert d["schuler_period"] == ps.Gyrocompass.schuler_period()
    assert d["schuler_period"] / 60 == pytest.approx(84.4, abs=0.05)
    assert d["schuler_angular_momentum"] == ps.Gyrocompass.schuler_tuned(lat).angular_momentum
    assert d["settle_error"] == c.settle_error and d["settle_tilt"] == c.settle_tilt
    assert d["speed_error"] == c.speed_error(d["speed"], 0.0)
    assert d["speed_error_small_angle"] == c.speed_error_small_angle(d["speed"], 0.0)
    # due north the compass reads high by about V/(Ω R cos λ): 2° at 20 knots at 50°
    assert math.degrees(d["speed_error"]) == pytest.approx(1.97, abs=0.01)
    assert "plots" not in d


def test_the_rotor_and_the_damping_reach_the_api() -> None:
    d = _json("--latitude", "0.6", "--angular-momentum", "25", "--pendulosity", "2")
    c = ps.Gyrocompass(0.6, 25.0, 2.0)
    assert d["period"] == c.period and d["settle_error"] == c.settle_error
    undamped = _json("--latitude", "0.6", "--damping", "0")
    assert undamped["settle_error"] == 0.0
    assert undamped["period"] == ps.Gyrocompass(0.6).period  # ζ leaves the period
    # units as typed: the pendulosity as an energy (N·m = J), the rotor's momentum as one
    typed = _json("--latitude", "0.6", "--pendulosity", "1500mJ", "--angular-momentum", "25")
    assert typed["pendulosity"] == pytest.approx(1.5, rel=1e-12)


def test_the_table_says_it_in_words_first() -> None:
    code, out, err = _run("--latitude", "50deg", "--speed", "20kn")
    assert code == 0, err
    first = out.strip().splitlines()[0]
    assert first.startswith("At 50° the compass swings")
    words = " ".join(out.split())
    assert "88.31 min" in words and "Schuler's 84.41 min" in words
    assert "latitude error" in words and "small-angle form" in words
    assert "settling period" in out and "speed error, small-angle form" in out


def test_plot_writes_the_settling_heading_and_tilt(tmp_path: Path) -> None:
    pytest.importorskip("matplotlib")
    from poinsot import plots

    path = tmp_path / "compass.png"
    d = _json("--latitude", "50deg", "--speed", "10kn", "--plot", str(path))
    assert path.stat().st_size > 10_000 and d["plots"] == [str(path)]
    code, out, _ = _run("--latitude", "50deg", "--plot", str(path), "--style", "slides")
    assert code == 0 and f"saved {path}" in out
    # the figure: heading and tilt panels, the full run settling on the linear settled heading
    c = ps.Gyrocompass(math.radians(50.0))
    run = c.simulate(3 * c.period, math.radians(10.0), samples=200)
    fig = plots.plot_gyrocompass(c, run)
    heading_ax, tilt_ax = fig.axes
    assert "heading" in heading_ax.get_ylabel() and "tilt" in tilt_ax.get_ylabel()
    sim = heading_ax.lines[0].get_ydata()
    settled = float(np.asarray(heading_ax.lines[1].get_ydata())[0])
    assert settled == pytest.approx(-math.degrees(c.settle_error), rel=1e-12)
    assert np.asarray(sim)[-1] == pytest.approx(settled, abs=0.2)
    with pytest.raises(ps.ArgumentTypeError, match="compass"):
        plots.plot_gyrocompass("not a compass")  # type: ignore[arg-type]


@pytest.mark.parametrize(
    ("args", "option", "reason"),
    [
        (("--latitude", "90deg"), "--latitude", "pole"),
        (("--latitude", "-90deg"), "--latitude", "pole"),
        (("--latitude", "50deg", "--angular-momentum", "0"), "--angular-momentum", "spin"),
        (("--latitude", "50deg", "--pendulosity", "-1"), "--pendulosity", "> 0"),
        (("--latitude", "50deg", "--damping", "1"), "--damping", "[0, 1)"),
        (("--latitude", "50deg", "--speed", "400", "--course", "270deg"), "--speed", "ground"),
        (("--latitude", "3m"), "--latitude", "expected an angle"),
        (("--latitude", "50deg", "--speed", "3deg"), "--speed", "expected a speed"),
        (("--latitude", "50deg", "--plot", "/nonexistent-dir/x.png"), "--plot", "no directory"),
        ((), "--latitude", "Missing option"),
    ],
)
def test_bad_input_is_refused_naming_the_option(
    args: tuple[str, ...], option: str, reason: str
) -> None:
    code, _, err = _run(*args)
    assert code != 0
    assert option in err and reason in err, err


def test_the_sentence_is_worded_from_the_json() -> None:
    from poinsot import _answers

    d = _json("--latitude", "50deg", "--speed", "20kn")
    assert d["summary"] == _answers.gyrocompass({k: v for k, v in d.items() if k != "summary"})
    assert "1.62° low (latitude error)" in d["summary"]
    assert "1.97° high" in d["summary"] and "small-angle form: 1.97°" in d["summary"]
    rest = _json("--latitude", "50deg", "--damping", "0")["summary"]
    assert "undamped, settles on it" in rest and "no speed error" in rest
    south = _json("--latitude", "-50deg", "--speed", "20kn", "--course", "180deg")["summary"]
    assert "1.62° high (latitude error)" in south and "1.97° low" in south
