"""The answers in plain words (issue 23, item 6): every computing command opens with a sentence
a student can quote, made from the numbers of its tables. Each sentence is checked against the
numbers it summarises: its figures are read back out of the words (with their units) and
compared with the command's --json values, to the rounding the sentence shows; for every motion
class of the heavy top. Negative controls: a sentence checked against another run's numbers, or
with one figure moved by 5 %, is caught."""

from __future__ import annotations

import json
import math
import re
from typing import Any

import pytest
from click.testing import CliRunner
from poinsot import _answers
from poinsot.cli import main

#: A number as a sentence writes it ("5.8", "1230", "-0.5", "5.49e-05").
N = r"-?\d+(?:\.\d+)?(?:e[+-]?\d+)?"
#: Units of a sentence's times and lengths, in s and m.
TIMES = dict(_answers.TIME_UNITS)
LENGTHS = dict(_answers.LENGTH_UNITS)
T = rf"{N} (?:{'|'.join(TIMES)})\b"
L = rf"{N} (?:{'|'.join(LENGTHS)})\b"


def run(args: list[str]) -> tuple[dict[str, Any], str]:
    """The command's --json document and its output as a table."""
    res = CliRunner().invoke(main, [*args, "--json"])
    assert res.exit_code == 0, res.stderr
    table = CliRunner().invoke(main, args)
    assert table.exit_code == 0, table.stderr
    return json.loads(res.stdout), table.stdout


def value(text: str) -> float:
    """A figure of a sentence in SI units: "1.08 s" → 1.08, "2 min" → 120, "1.55 cm" → 0.0155."""
    number, _, unit = text.partition(" ")
    scale = TIMES.get(unit) or LENGTHS.get(unit) or 1.0
    return float(number) * scale


def shown_tolerance(text: str) -> float:
    """How far the figure may be from the value it rounds: half a unit of its last digit,
    and at least the relative 0.5 % of 3 significant digits."""
    number, _, unit = text.partition(" ")
    mantissa = number.split("e")[0]
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    exponent = int(number.split("e")[1]) if "e" in number else 0
    scale = TIMES.get(unit) or LENGTHS.get(unit) or 1.0
    last_digit = 0.5 * 10.0 ** (exponent - decimals) * scale
    return max(last_digit, 5e-3 * abs(float(number) * scale)) * (1 + 1e-9)


def check(sentence: str, pattern: str, expected: dict[str, Any]) -> None:
    """``sentence`` matches ``pattern`` and each named figure equals ``expected[name]`` to the
    rounding the sentence shows (words compare as they are)."""
    flat = " ".join(sentence.split())
    m = re.search(pattern, flat)
    assert m, f"{pattern!r} not in {flat!r}"
    for name, want in expected.items():
        got = m.group(name)
        if got is None and name in OPTIONAL:
            continue  # the other form of an alternative
        if isinstance(want, str):
            assert got == want, (name, got, want)
            continue
        assert abs(value(got) - want) <= shown_tolerance(got), (name, got, want, flat)


#: Figures of a pattern's alternatives: one of each pair is in the sentence (a nutation range
#: too narrow to show as two different angles is written "by only 0.0486° about 34.4°").
OPTIONAL = frozenset({"t1", "t2", "dt", "about"})


def degrees(rad: float) -> float:
    return math.degrees(rad)


# -- the heavy top: one sentence per motion class ------------------------------------------------
TOP = ["top", "--I1", "1", "--I3", "0.5", "--mgl", "1"]
SPIN = (
    rf"the spin is (?:only )?(?:(?P<above>{N}) % above|(?P<times>{N}) times) the least for "
    rf"steady precession \((?P<least>{N}) rad/s\)"
)


def spin_expected(d: dict[str, Any]) -> dict[str, Any]:
    least = d["steady_precession_at_theta0"]["min_spin_2_119"]
    return {"least": least}


def check_spin(sentence: str, d: dict[str, Any]) -> None:
    flat = " ".join(sentence.split())
    m = re.search(SPIN, flat)
    assert m, flat
    least = d["steady_precession_at_theta0"]["min_spin_2_119"]
    ratio = abs(d["omega3"]) / least
    if m.group("above") is not None:
        got = m.group("above")
        assert abs(float(got) - (ratio - 1) * 100) <= shown_tolerance(got), (got, ratio)
    else:
        got = m.group("times")
        assert abs(float(got) - ratio) <= shown_tolerance(got), (got, ratio)
    check(flat, SPIN, spin_expected(d))


NUTATING = (
    rf"The top precesses at (?P<rate>{N}) rad/s on average, one turn every (?P<period>{T}), "
    rf"nodding (?:between (?P<t1>{N})° and (?P<t2>{N})°|by only (?P<dt>{N})° about "
    rf"(?P<about>{N})°) every (?P<nod>{T}); its axis traces (?P<path>\w+)"
)


def nutating_expected(d: dict[str, Any]) -> dict[str, Any]:
    t1, t2 = d["turning_points"]
    return {
        "rate": abs(d["mean_precession_rate"]),
        "period": d["precession_period"],
        "t1": degrees(t1),
        "t2": degrees(t2),
        "dt": degrees(t2 - t1),
        "about": degrees(t1),
        "nod": d["nutation_period"],
        "path": d["motion_class"],
    }


@pytest.mark.parametrize(
    ("args", "motion"),
    [
        (["--theta", "0.8", "--psi-dot", "6"], "cusps"),
        (["--theta", "0.8", "--psi-dot", "6", "--phi-dot", "-0.5"], "loops"),
        (["--theta", "0.8", "--psi-dot", "6", "--phi-dot", "0.5"], "waves"),
        (["--theta", "0.6", "--psi-dot", "40", "--mgl", "0.3"], "cusps"),  # a fast top
        (["--theta", "0.8", "--psi-dot", "3.4"], "cusps"),  # 2 % above the least spin
    ],
)
def test_top_sentence_of_a_nutating_top(args: list[str], motion: str) -> None:
    d, out = run(TOP + args)
    assert d["motion_class"] == motion
    check(d["summary"], NUTATING, nutating_expected(d))
    check_spin(d["summary"], d)
    # the sentence opens the table's output, and the period is printed in the table too
    assert " ".join(out.split()).startswith(" ".join(d["summary"].split()))
    assert "precession period" in out
    assert d["precession_period"] == pytest.approx(2 * math.pi / abs(d["mean_precession_rate"]))


def test_top_sentence_quotes_the_issue_example_shape() -> None:
    # "precesses at 5.8 rad/s, one turn every 1.08 s, nodding between 30° and 65°; the spin is
    # only 3 % above the least for steady precession": a spin just above the least
    d, _ = run(TOP + ["--theta", "0.8", "--psi-dot", "3.4"])
    assert "the spin is only" in d["summary"] and "% above the least" in d["summary"]


def test_top_sentence_of_steady_precession() -> None:
    from poinsot.top import HeavyTop

    s = HeavyTop.steady_precession(1, 0.5, 1, 0.8, 12.0)
    d, _ = run(TOP + ["--theta", "0.8", "--phi-dot", repr(s.slow), "--spin", "12"])
    assert d["motion_class"] == "steady precession"
    pattern = (
        rf"The top precesses steadily at (?P<rate>{N}) rad/s, one turn every (?P<period>{T}), "
        rf"its axis held at (?P<t1>{N})° from the vertical"
    )
    check(
        d["summary"],
        pattern,
        {
            "rate": abs(d["mean_precession_rate"]),
            "period": d["precession_period"],
            "t1": degrees(0.8),
        },
    )
    check_spin(d["summary"], d)


@pytest.mark.parametrize(("spin", "stable"), [("10", True), ("1", False)])
def test_top_sentence_of_a_sleeping_top(spin: str, stable: bool) -> None:
    d, _ = run(TOP + ["--theta", "0", "--psi-dot", spin])
    assert d["motion_class"] == "sleeping" and d["sleeping_stable"] is stable
    assert d["precession_period"] == "inf"  # the axis does not turn: no period
    words = "above" if stable else "below"
    pattern = (
        rf"spins upright at (?P<w>{N}) rad/s, {words} the sleeping threshold of "
        rf"(?P<thr>{N}) rad/s"
    )
    check(d["summary"], pattern, {"w": abs(d["omega3"]), "thr": d["sleeping_threshold"]})
    assert ("sleeps" in d["summary"]) is stable
    assert ("topples" in d["summary"]) is not stable


def test_top_sentence_of_a_hanging_top() -> None:
    d, _ = run(TOP + ["--theta", "180", "--degrees", "--psi-dot", "120"])  # 120°/s
    assert d["motion_class"] == "hanging" and d["precession_period"] == "inf"
    pattern = rf"hangs straight down from its pivot, spinning at (?P<w>{N}) rad/s; it does not"
    check(d["summary"], pattern, {"w": math.radians(120)})


def test_top_sentence_below_the_least_spin_for_steady_precession() -> None:
    d, _ = run(TOP + ["--theta", "0.8", "--psi-dot", "2"])
    assert "error" in d["steady_precession_at_theta0"]
    least = d["steady_precession_at_theta0"]["min_spin_2_119"]
    pattern = (
        rf"the spin of (?P<w>{N}) rad/s is (?P<below>{N}) % below the least for steady "
        rf"precession at this tilt \((?P<least>{N}) rad/s\), so it cannot precess steadily"
    )
    check(
        d["summary"],
        pattern,
        {"w": abs(d["omega3"]), "below": (1 - abs(d["omega3"]) / least) * 100, "least": least},
    )
    check(d["summary"], NUTATING, nutating_expected(d))


def test_top_sentence_of_a_top_swinging_through_the_vertical() -> None:
    d, _ = run(TOP + ["--theta", "0.8"])  # no spin: a pendulum through the lowest point
    assert d["motion_class"] == "through vertical"
    t1, t2 = d["turning_points"]
    pattern = (
        rf"swings through the straight down position, between (?P<t1>{N})° and (?P<t2>{N})° "
        rf"from the vertical, every (?P<nod>{T})"
    )
    check(
        d["summary"],
        pattern,
        {"t1": degrees(t1), "t2": degrees(t2), "nod": d["nutation_period"]},
    )


def test_top_sentence_words_the_pole_the_core_names() -> None:
    # the pole is the core's (HeavyTop.vertical_pass), not guessed from the angles: a pendulum
    # thrown over the top passes both poles, θ from 0 to π (the old guess said "upright")
    d, _ = run(TOP + ["--theta", "0.8"])
    assert d["vertical_pass"] == "straight down"
    d, _ = run(TOP + ["--theta", "0.8", "--theta-dot", "5"])
    assert d["motion_class"] == "through vertical" and d["vertical_pass"] == "both"
    assert d["turning_points"] == [0, math.pi]
    assert "swings through both the upright and the straight down positions" in d["summary"]
    # the sentence reads the field: another pole in the data, another pole in the words
    assert "the upright position" in _answers.top({**d, "vertical_pass": "upright"})
    # negative control: a nutating top passes no pole
    d, _ = run(TOP + ["--theta", "0.8", "--psi-dot", "6"])
    assert d["vertical_pass"] is None


def test_top_sentence_below_the_horizontal() -> None:
    d, _ = run(TOP + ["--theta", "2.0", "--psi-dot", "6"])
    assert d["steady_precession_at_theta0"]["min_spin_2_119"] == 0
    assert "below the horizontal, it could precess steadily at any spin" in d["summary"]
    check(d["summary"], NUTATING, nutating_expected(d))


def test_top_sentence_checked_against_other_numbers_fails() -> None:
    # negative controls: the check catches a sentence from another top, and one figure off by 5 %
    cusps, _ = run(TOP + ["--theta", "0.8", "--psi-dot", "6"])
    waves, _ = run(TOP + ["--theta", "0.8", "--psi-dot", "6", "--phi-dot", "0.5"])
    with pytest.raises(AssertionError):
        check(cusps["summary"], NUTATING, nutating_expected(waves))
    period = re.search(rf"one turn every ({N})", cusps["summary"])
    assert period
    moved = cusps["summary"].replace(
        period.group(0), f"one turn every {float(period.group(1)) * 1.05:.3g}"
    )
    with pytest.raises(AssertionError):
        check(moved, NUTATING, nutating_expected(cusps))


# -- the other computing commands ---------------------------------------------------------------
def test_fall_sentence() -> None:
    d, out = run(["fall", "--height", "100", "--latitude", "45", "--degrees"])
    pattern = (
        rf"Dropped from (?P<h>{L}) at latitude (?P<lat>{N})°, the body falls for (?P<t>{N}) s "
        rf"and lands (?P<east>{L}) east of the point straight below \(eq\. 2\.42 gives "
        rf"(?P<first>{L})\) and (?P<south>{L}) south of it"
    )
    check(
        d["summary"],
        pattern,
        {
            "h": d["height"],
            "lat": d["latitude"],
            "t": d["time"],
            "east": d["east"],
            "first": d["first_order_east"],
            "south": -d["north"],
        },
    )
    assert " ".join(out.split()).startswith(" ".join(d["summary"].split()))


def test_fall_sentence_in_the_southern_hemisphere() -> None:
    d, _ = run(["fall", "--height", "50", "--latitude", "-0.6"])
    assert "latitude -0.6 rad" in d["summary"]
    assert d["north"] > 0 and "north of it" in " ".join(d["summary"].split())


@pytest.mark.parametrize(("latitude", "side"), [("50", "right"), ("-50", "left")])
def test_projectile_sentence(latitude: str, side: str) -> None:
    d, _ = run(
        ["projectile", "--speed", "800", "--elevation", "45", "--azimuth", "90"]
        + ["--latitude", latitude, "--degrees"]
    )
    spin = d["with_rotation"]
    pattern = (
        rf"Fired at (?P<v>{N}) m/s, (?P<el>{N})° above the horizon towards azimuth (?P<az>{N})° "
        rf"at latitude (?P<lat>{N})°, the projectile flies for (?P<t>{N}) s and lands "
        rf"(?P<range>{L}) away; the Earth's rotation moves the landing point (?P<drift>{L}) to "
        rf"the (?P<side>\w+) of the line of fire"
    )
    check(
        d["summary"],
        pattern,
        {
            "v": 800,
            "el": 45,
            "az": 90,
            "lat": float(latitude),
            "t": spin["time"],
            "range": spin["range"],
            "drift": abs(spin["drift"]),
            "side": side,
        },
    )


def test_projectile_sentence_on_a_planet_that_does_not_turn_sideways() -> None:
    # at the equator, fired east: ω × v has no component across the line of fire, the drift
    # is round-off, printed 0 in the table, and the sentence says there is none
    d, _ = run(
        ["projectile", "--speed", "300", "--elevation", "45", "--azimuth", "90"]
        + ["--latitude", "0", "--degrees"]
    )
    assert "does not move it sideways" in d["summary"]


def test_foucault_sentence() -> None:
    d, _ = run(["foucault", "--latitude", "48.85", "--degrees", "--duration", "7200"])
    assert d["regime"] == "precessing"
    pattern = (
        rf"At latitude (?P<lat>{N})°, the swing plane turns (?P<sense>\w+) seen from above by "
        rf"(?P<deg>{N})° an hour in the simulation, one full turn every (?P<turn>{T}); the "
        rf"unit's ω sin λ gives (?P<theory>{N})° an hour, one turn every (?P<hours>{T})"
    )
    check(
        d["summary"],
        pattern,
        {
            "lat": 48.85,
            "sense": d["sense"],
            "deg": math.degrees(abs(d["precession_rate"])) * 3600,
            "turn": 2 * math.pi / abs(d["precession_rate"]),
            "theory": math.degrees(abs(d["expected_rate"])) * 3600,
            "hours": d["full_turn_hours"] * 3600,
        },
    )


def test_foucault_turn_period_is_the_cores() -> None:
    # the simulated full turn is the core's field beside the rate (2π/|rate|), not computed by
    # the sentence; a run without a rate has none
    d, _ = run(["foucault", "--latitude", "48.85", "--degrees", "--duration", "7200"])
    assert d["full_turn_period"] == 2 * math.pi / abs(d["precession_rate"])
    moved = _answers.foucault({**d, "full_turn_period": 2 * d["full_turn_period"]})
    assert _answers.duration(2 * d["full_turn_period"]) in moved
    d, _ = run(["foucault", "--latitude", "45", "--degrees", "--duration", "10"])
    assert d["full_turn_period"] is None
    d, _ = run(["foucault", "--latitude", "0", "--degrees", "--duration", "600"])
    assert d["regime"] == "still" and d["full_turn_period"] == "inf"


def test_foucault_sentence_of_a_run_too_short() -> None:
    d, _ = run(["foucault", "--latitude", "45", "--degrees", "--duration", "10"])
    assert d["regime"] != "precessing"
    assert "no steady turn of the swing plane" in d["summary"]
    check(
        d["summary"],
        rf"one turn every (?P<hours>{T})",
        {"hours": d["full_turn_hours"] * 3600},
    )


@pytest.mark.parametrize(
    ("omega", "axis", "which"),
    [(["1", "0.1", "1"], 3, "largest"), (["1", "0.1", "0.01"], 1, "smallest")],
)
def test_free_sentence(omega: list[str], axis: int, which: str) -> None:
    d, _ = run(["free", "--moments", "1", "2", "3", "--omega", *omega, "--duration", "20"])
    pattern = (
        rf"ω circles axis (?P<axis>\d), the axis of the (?P<which>\w+) moment, once every "
        rf"(?P<period>{T}) in the body; (?P<method>\w+) kept the energy to a relative "
        rf"(?P<err>{N}) over (?P<dur>{N}) s"
    )
    check(
        d["summary"],
        pattern,
        {
            "axis": str(axis),
            "which": which,
            "period": d["period"],
            "method": d["method"],
            "dur": 20,
        },
    )
    m = re.search(rf"relative ({N})", d["summary"])
    assert m and float(m.group(1)) == pytest.approx(d["max_energy_error"], rel=0.06, abs=1e-300)


def test_free_sentence_of_the_dzhanibekov_flips() -> None:
    # spun near the middle axis: ω circles an outer axis and the body flips every half period
    d, _ = run(["free", "--moments", "1", "2", "3", "--omega", "0.01", "3", "0.01"])
    pattern = (
        rf"once every (?P<period>{T}) in the body; started near axis (?P<axis>\d), the middle "
        rf"one, the body flips over every (?P<flip>{T})"
    )
    check(d["summary"], pattern, {"period": d["period"], "axis": "2", "flip": d["flip_interval"]})
    # negative control: spun near an outer axis, no flip is announced
    d, _ = run(["free", "--moments", "1", "2", "3", "--omega", "0.01", "0.01", "3"])
    assert "flips" not in d["summary"]


def test_free_sentence_reads_the_cores_rate_and_axes() -> None:
    d, _ = run(["free", "--moments", "1", "2", "3", "--omega", "0", "-2", "0"])
    assert d["regime"] == "steady" and d["steady_rate"] == 2
    assert "spins steadily at 2 rad/s" in d["summary"]
    assert (d["pole_axis"], d["flips_about"]) == (None, None)
    d, _ = run(["free", "--moments", "2", "3", "1", "--omega", "3", "0.01", "0.01"])
    # I = (2, 3, 1): axis 1 is the middle one, ω circles axis 2 (the largest moment)
    assert (d["pole_axis"], d["flips_about"]) == (1, 0)
    assert "ω circles axis 2, the axis of the largest moment" in d["summary"]
    assert "started near axis 1, the middle one" in d["summary"]


def test_inertia_sentence() -> None:
    d, out = run(["inertia", "cuboid", "--mass", "2", "--sides", "1", "2", "3"])
    pattern = (
        rf"The cuboid has mass (?P<m>{N}) kg and principal moments (?P<i1>{N}), (?P<i2>{N}) and "
        rf"(?P<i3>{N}) kg·m² about its centre of mass; it is an (?P<kind>asymmetric top)"
    )
    i1, i2, i3 = d["principal_moments"]
    check(
        d["summary"],
        pattern,
        {"m": d["mass"], "i1": i1, "i2": i2, "i3": i3, "kind": d["kind"]},
    )
    assert " ".join(out.split()).startswith(" ".join(d["summary"].split()))


@pytest.mark.parametrize(
    ("x", "shown"),
    [
        (5.8123, "5.81"),
        (1.0849, "1.08"),
        (45.0, "45"),
        (1234.5, "1230"),
        (0.015524, "0.0155"),
        (9.9996, "10"),
        (5.49e-5, "5.49e-05"),
        (-0.5, "-0.5"),
        (0.0, "0"),
    ],
)
def test_numbers_are_rounded_to_three_significant_digits(x: float, shown: str) -> None:
    assert _answers.num(x) == shown


@pytest.mark.parametrize(
    "command",
    [
        ["fall", "--height", "100"],
        ["foucault"],
        ["projectile", "--speed", "50", "--elevation", "0.5"],
    ],
)
def test_an_angle_in_radians_is_shown_in_degrees_too(command: list[str]) -> None:
    """`--latitude 0.8` meant as 0.8° runs at 45.8°: the sentence says so beside the radians
    (issue 23: the case a unit suffix cannot catch, an angle valid in both units)."""
    res = CliRunner().invoke(main, [*command, "--latitude", "0.8"])
    assert res.exit_code == 0, res.output
    first = " ".join(res.output.split("\n\n")[0].split())
    shown = re.search(r"latitude 0\.8 rad \(([\d.]+)°\)", first)
    assert shown, first
    assert float(shown.group(1)) == pytest.approx(math.degrees(0.8), abs=0.05)
    # negative control: in degrees the sentence has no radians to explain
    res = CliRunner().invoke(main, [*command, "--latitude", "0.8", "--degrees"])
    first = " ".join(res.output.split("\n\n")[0].split())
    assert "latitude 0.8°" in first and " rad (" not in first
