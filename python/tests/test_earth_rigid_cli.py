"""`poinsot earth`: the rigid Earth's periods and rates beside the catalogue's measured values."""

from __future__ import annotations

import json
import math
import re

import poinsot as ps
import pytest
from click.testing import CliRunner
from poinsot import experiments as x
from poinsot.cli import CHANDLER_LOVE_NUMBERS, EARTH_MEASURED, main

# The test's own constants: a Julian year, an arcsecond, the sidereal rate (WGS 84).
YEAR = 365.25 * 86400.0
ARCSEC = math.pi / 648000
OMEGA = 7.292115e-5


def _run(*args: str) -> tuple[int, str, str]:
    res = CliRunner().invoke(main, ["earth", *args])
    return res.exit_code, res.stdout, res.stderr


def _json(*args: str) -> dict:
    code, out, err = _run(*args, "--json")
    assert code == 0, err
    return json.loads(out)


def test_the_json_keys_and_their_values_from_the_api() -> None:
    d = _json()
    e = ps.RigidEarth()
    assert {
        "euler_period",
        "euler_period_sidereal_days",
        "chandler_period",
        "chandler_period_days",
        "precession_rate",
        "precession_rate_arcsec_per_year",
        "precession_parts",
        "precession_period",
        "precession_period_years",
        "nutation_amplitudes",
        "nutation_amplitudes_arcsec",
        "measured",
        "summary",
        "k2",
        "ks",
    } <= set(d)
    assert d["euler_period"] == e.euler_period
    assert d["chandler_period"] == e.chandler_period(0.30, 0.938)
    assert d["precession_rate"] == e.precession_rate
    assert d["precession_parts"] == list(e.precession_parts)
    assert d["nutation_amplitudes"] == list(e.nutation_amplitudes)
    # the unit changes, against the test's own constants
    h = e.dynamical_flattening
    assert d["euler_period_sidereal_days"] == pytest.approx((1 - h) / h, rel=1e-9)
    assert d["precession_rate_arcsec_per_year"] == pytest.approx(
        -e.precession_rate * YEAR / ARCSEC, rel=1e-12
    )
    assert d["precession_period_years"] == pytest.approx(
        2 * math.pi / abs(e.precession_rate) / YEAR, rel=1e-9
    )


def test_the_measured_values_are_the_catalogues_not_a_second_copy() -> None:
    d = _json()
    assert set(d["measured"]) == set(EARTH_MEASURED)
    for key, (name, unit, _) in EARTH_MEASURED.items():
        r = x.run(name)
        assert d["measured"][key]["experiment"] == name
        assert d["measured"][key]["value"] == pytest.approx(r.measured.to(unit).magnitude)
    assert d["measured"]["chandler_period"]["value"] == pytest.approx(433.1)
    assert d["measured"]["chandler_period"]["uncertainty"] == pytest.approx(1.7)
    assert d["measured"]["precession_rate"]["value"] == pytest.approx(50.38481507)
    assert d["measured"]["nutation_longitude"]["value"] == pytest.approx(-17.2064161)
    assert d["measured"]["nutation_obliquity"]["value"] == pytest.approx(9.2052331)


def test_the_default_love_numbers_are_the_catalogue_entrys_inputs() -> None:
    inputs = x.get("vicente-wilson-1997").parsed_inputs()
    assert (
        float(inputs["k2"].magnitude),
        float(inputs["ks"].magnitude),
    ) == CHANDLER_LOVE_NUMBERS


def _numbers(text: str) -> list[float]:
    return [float(n) for n in re.findall(r"-?\d+(?:\.\d+)?", text.replace("−", "-"))]


def test_the_sentence_words_the_json_numbers() -> None:
    d = _json()
    s = d["summary"]
    m = d["measured"]
    dpsi, deps = d["nutation_amplitudes_arcsec"]
    expected = [
        (d["euler_period_sidereal_days"], 3),
        (d["chandler_period_days"], 3),
        (m["chandler_period"]["value"], 3),
        (d["precession_rate_arcsec_per_year"], 4),
        (m["precession_rate"]["value"], 4),
        (d["precession_period_years"], 3),
        (d["moon_to_sun"], 3),
        (dpsi, 3),
        (deps, 3),
        (m["nutation_longitude"]["value"], 3),
        (m["nutation_obliquity"]["value"], 3),
    ]
    words = _numbers(s)
    for value, digits in expected:
        rounded = float(f"{value:.{digits}g}")
        assert any(w == pytest.approx(rounded) for w in words), (value, s)
    assert "304 sidereal days" in s and "446 days (observed 433 days)" in s
    assert "50.4″ a year (IAU 2006: 50.38″)" in s
    # the text output opens with the same sentence
    code, out, _ = _run()
    assert code == 0
    assert " ".join(out.split()).startswith(" ".join(s.split()))
    assert "vicente-wilson-1997" in out and "capitaine-2003" in out


def test_k2_changes_the_chandler_period_only() -> None:
    base, other = _json(), _json("--k2", "0.35")
    assert other["chandler_period"] == pytest.approx(
        ps.RigidEarth().euler_period * 0.938 / (0.938 - 0.35), rel=1e-12
    )
    assert other["euler_period"] == base["euler_period"]
    assert other["precession_rate"] == base["precession_rate"]
    assert "k2 = 0.35" in other["summary"]


def test_options_read_units_and_the_obliquity_its_degrees() -> None:
    a = _json("--obliquity", "22.1deg")
    b = _json("--obliquity", str(math.radians(22.1)))
    assert a["obliquity"] == pytest.approx(b["obliquity"], rel=1e-12)
    assert a["precession_rate"] == pytest.approx(b["precession_rate"], rel=1e-12)
    # the rate goes as cos ε (first order): a negative control that the option is used
    base = _json()
    ratio = a["precession_rate"] / base["precession_rate"]
    assert ratio == pytest.approx(math.cos(math.radians(22.1)) / math.cos(base["obliquity"]))


@pytest.mark.parametrize(
    ("args", "code", "flag"),
    [
        (["--k2", "5cm"], 2, "--k2"),
        (["--k2", "nan"], 2, "--k2"),
        (["--k2", "1", "--ks", "0.9"], 1, "--k2"),
        (["--ks", "-1"], 1, "--ks"),
        (["--dynamical-flattening", "1"], 1, "--dynamical-flattening"),
        (["--dynamical-flattening", "0"], 1, "--dynamical-flattening"),
        (["--obliquity", "40"], 1, "--obliquity"),
    ],
)
def test_bad_input_is_one_line_naming_the_option(args: list[str], code: int, flag: str) -> None:
    got, out, err = _run(*args)
    assert got == code, (out, err)
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and flag in lines[0], err
    assert "Traceback" not in err


def test_plot_saves_the_precession_cone_and_the_comparison(
    tmp_path: pytest.TempPathFactory,
) -> None:
    """--plot FILE (issue 25): the figure is written, listed in the JSON and on the table, and
    its two panels show the precession circle of radius ε and one bar per measured value (the
    Chandler period's from the catalogue)."""
    pytest.importorskip("matplotlib")
    from poinsot import plots

    path = tmp_path / "earth.png"  # type: ignore[operator]
    d = _json("--plot", str(path))
    assert path.is_file() and path.stat().st_size > 10_000
    assert d["plots"] == [str(path)]
    code, out, _ = _run("--plot", str(path), "--style", "slides")
    assert code == 0 and f"saved {path}" in out
    fig = plots.plot_rigid_earth(ps.RigidEarth(), chandler_observed=(433.1, 1.7))
    sky, bars = fig.axes
    x, _ = sky.lines[0].get_data()
    assert float(max(abs(x))) == pytest.approx(math.degrees(ps.OBLIQUITY_J2000), rel=1e-3)
    assert len(bars.patches) == 4  # precession, Δψ₀, Δε₀, Chandler
    widths = [p.get_width() for p in bars.patches]
    assert widths[0] == pytest.approx(
        100 * (d["precession_rate"] / -ps.IAU2006_PRECESSION_RATE - 1)
    )
    assert widths[3] == pytest.approx(100 * (d["chandler_period_days"] / 433.1 - 1))
    # negative control: without an observed Chandler period there is no Chandler bar
    assert len(plots.plot_rigid_earth().axes[1].patches) == 3


def test_plot_to_a_missing_directory_is_refused_naming_plot(
    tmp_path: pytest.TempPathFactory,
) -> None:
    code, _, err = _run("--plot", str(tmp_path / "nowhere" / "earth.png"))  # type: ignore[operator]
    assert code == 2 and "--plot" in err
