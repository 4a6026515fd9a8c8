"""Rich display in Jupyter (issue 13): the HTML table (``_repr_html_``) and the text repr of the
nine result classes, both built from one list of rows (``poinsot/_display.py``), and the inertia
tensor as LaTeX (``RigidBody._repr_latex_``).

The tables are read back here with the standard library's ``html.parser`` and a parser of
numbers written for this file (not the formatting code): the tags must balance, every quantity
must be there with its unit, every number must equal the model's own attribute to the 6
significant digits shown, and the text repr must say, row by row, what the table's brief rows
say. Negative controls show that the checker catches a corrupted table, a text repr that says
something else, and a LaTeX matrix with a wrong entry or one mathtext cannot set.
"""

from __future__ import annotations

import dataclasses
import html.parser
import io
import json
import math
import os
import re
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import poinsot as ps
import pytest

ROOT = Path(__file__).resolve().parents[2]

ROUND_OFF = 1.01e-12
"""Entries of a vector or matrix at most 1e-12 of its largest are shown as 0 (round-off)."""

COLUMNS = ["quantity", "symbol", "value", "unit"]
EARTH = ps.Earth()


# ---- reading a table back -------------------------------------------------------------------


@dataclasses.dataclass
class Table:
    caption: str = ""
    header: list[str] = dataclasses.field(default_factory=list)
    rows: list[dict[str, Any]] = dataclasses.field(default_factory=list)
    problems: list[str] = dataclasses.field(default_factory=list)
    tables: int = 0


class _Reader(html.parser.HTMLParser):
    """Collects the caption, the header cells and each row's data-key, class and cell texts
    (entities decoded), and every unbalanced tag."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.out = Table()
        self.stack: list[str] = []
        self.text: list[str] | None = None
        self.row: dict[str, Any] | None = None

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.stack.append(tag)
        a = dict(attrs)
        if tag == "table":
            self.out.tables += 1
        elif tag == "tr" and "tbody" in self.stack:
            self.row = {"key": a.get("data-key"), "detail": a.get("class") == "detail", "cells": []}
        elif tag in ("td", "th", "caption"):
            self.text = []
        elif tag in ("script", "style", "link", "img", "iframe") or "src" in a or "href" in a:
            self.out.problems.append(f"<{tag}> brings something from outside or runs code")

    def handle_endtag(self, tag: str) -> None:
        if not self.stack or self.stack[-1] != tag:
            self.out.problems.append(f"unbalanced </{tag}> (open: {self.stack})")
            return
        self.stack.pop()
        text = "".join(self.text or [])
        if tag == "caption":
            self.out.caption = text
        elif tag == "th":
            self.out.header.append(text)
        elif tag == "td" and self.row is not None:
            self.row["cells"].append(text)
        elif tag == "tr" and self.row is not None:
            self.out.rows.append(self.row)
            self.row = None
        if tag in ("td", "th", "caption"):
            self.text = None

    def handle_data(self, data: str) -> None:
        if self.text is not None:
            self.text.append(data)


def read_table(markup: str) -> Table:
    reader = _Reader()
    reader.feed(markup)
    reader.close()
    if reader.stack:
        reader.out.problems.append(f"unclosed tags: {reader.stack}")
    return reader.out


def _item(value: str, unit: str) -> str:
    """A regex for one row of the text repr: ``name=value unit``, ``name in value unit``,
    ``name='value'`` or the value alone."""
    tail = re.escape(f" {unit}") if unit else ""
    name = r"[^\W\d][\w.]*"
    return (
        rf"(?:{name}=|{name} in )?{re.escape(value)}{tail}" + rf"|{name}={re.escape(repr(value))}"
    )


def table_problems(markup: str, name: str, text: str | None = None) -> list[str]:
    """Everything wrong with a display table: tags, caption, header, rows; and, given the text
    repr, where it does not say what the table's brief rows say (row by row, in order)."""
    t = read_table(markup)
    problems = list(t.problems)
    if t.tables != 1:
        problems.append(f"{t.tables} tables")
    if t.caption != name:
        problems.append(f"caption {t.caption!r}, expected {name!r}")
    if t.header != COLUMNS:
        problems.append(f"header {t.header}")
    keys = [r["key"] for r in t.rows]
    if len(set(keys)) != len(keys) or None in keys:
        problems.append(f"data-keys missing or repeated: {keys}")
    for r in t.rows:
        if len(r["cells"]) != len(COLUMNS):
            problems.append(f"row {r['key']}: {len(r['cells'])} cells")
    details = [r["detail"] for r in t.rows]
    if details != sorted(details):
        problems.append("a brief row after a detail row")
    if text is not None:
        if not (text.startswith(f"{name}(") and text.endswith(")")):
            return [*problems, f"text repr {text!r} is not {name}(...)"]
        rest = text[len(name) + 1 : -1]
        for r in t.rows:
            if r["detail"] or len(r["cells"]) != 4:
                continue
            _, _, value, unit = r["cells"]
            m = re.match(rf"(?:{_item(value, unit)})(?:, |$)", rest)
            if m is None:
                problems.append(
                    f"text repr does not say {r['key']} = {value} {unit} at {rest[:50]!r}"
                )
                return problems
            rest = rest[m.end() :]
        if rest:
            problems.append(f"text repr says more than the table: {rest!r}")
    return problems


# ---- reading numbers back (independently of poinsot._display) --------------------------------


@dataclasses.dataclass
class Summary:
    shape: tuple[int, ...]
    first: Any
    last: Any


def read_value(text: str) -> Any:
    """A displayed value as Python: None, a number, a (nested) list, or a :class:`Summary`."""
    if text == "None":
        return None
    m = re.fullmatch(r"\((\d+)(?:, (\d+))?,?\): (.*)", text)
    if m:
        shape = tuple(int(g) for g in m.groups()[:2] if g is not None)
        ends = m.group(3).split(" … ")
        return Summary(shape, read_value(ends[0]), read_value(ends[-1]))
    return json.loads(re.sub(r"(?<![\w.])(-?)inf\b", r"\1Infinity", text))


def assert_shows(shown: Any, expected: Any, what: str) -> None:
    """``shown`` (read back) equals ``expected`` (the model's attribute) to the 6 significant
    digits shown (within half a unit of the 6th), an entry shown 0 being round-off."""
    if expected is None or isinstance(expected, (str, bool)):
        assert shown == expected, what
        return
    if isinstance(shown, Summary):
        arr = np.asarray(expected)
        assert shown.shape == arr.shape, what
        assert_shows(shown.first, arr[0], f"{what}[0]")
        assert_shows(shown.last, arr[-1], f"{what}[-1]")
        return
    exp = np.asarray(expected, dtype=float)
    got = np.asarray(shown, dtype=float)
    assert got.shape == exp.shape, f"{what}: shape {got.shape}, expected {exp.shape}"
    finite = np.abs(exp[np.isfinite(exp)])
    biggest = finite.max() if finite.size else 0.0
    with np.errstate(invalid="ignore"):
        rounded = np.abs(got - exp) <= half_unit(exp) * (1 + 1e-9)
    same = (got == exp) | rounded | ((got == 0) & (np.abs(exp) <= ROUND_OFF * biggest))
    assert same.all(), f"{what}: shows {got}, the model has {exp}"


def half_unit(x: Any) -> Any:
    """Half a unit in the 6th significant digit of ``x``: how far a number shown with 6
    significant digits may be from the one it shows."""
    ax = np.abs(np.asarray(x, dtype=float))
    ok = np.isfinite(ax) & (ax > 0)
    e = np.floor(np.log10(np.where(ok, ax, 1.0)))
    return np.where(ok, 0.5 * 10.0 ** (e - 5), 0.0)


# ---- the nine classes: what each must show, in which unit ------------------------------------

KG_M2, MOMENTUM = "kg·m²", "kg·m²/s"


def _body_expected(b: ps.RigidBody) -> dict[str, tuple[Any, str]]:
    out: dict[str, tuple[Any, str]] = {
        "mass": (b.mass, "kg"),
        "center_of_mass": (b.center_of_mass, "m"),
        "principal_moments": (b.principal_moments, KG_M2),
        "kind": (b.kind, ""),
        "inertia": (b.inertia, KG_M2),
        "principal_axes": (b.principal_axes, ""),
    }
    err = b.integration_error
    if err is not None:
        out |= {
            "integration_error.mass": (err.mass, "kg"),
            "integration_error.center_of_mass": (err.center_of_mass, "m"),
            "integration_error.inertia": (err.inertia, KG_M2),
            "integration_error.evaluations": (err.evaluations, ""),
            "integration_error.converged": (str(err.converged), ""),
        }
    return out


def _top_expected(t: ps.HeavyTop) -> dict[str, tuple[Any, str]]:
    return {
        "I1": (t.I1, KG_M2),
        "I3": (t.I3, KG_M2),
        "mgl": (t.mgl, "N·m"),
        "motion_class": (t.motion_class, ""),
        "turning_points": (t.turning_points, "rad"),
        "omega3": (t.omega3, "rad/s"),
        "p_phi": (t.p_phi, MOMENTUM),
        "p_psi": (t.p_psi, MOMENTUM),
        "energy": (t.energy, "J"),
        "reduced_energy": (t.reduced_energy, "J"),
        "nutation_period": (t.nutation_period, "s"),
        "mean_precession_rate": (t.mean_precession_rate, "rad/s"),
        "mean_spin_rate": (t.mean_spin_rate, "rad/s"),
    }


def _free_expected(f: ps.FreeRigidBody) -> dict[str, tuple[Any, str]]:
    return {
        "moments": (f.moments, KG_M2),
        "omega0": (f.omega0, "rad/s"),
        "regime": (f.regime, ""),
        "period": (f.period, "s"),
        "energy": (f.energy, "J"),
        "angular_momentum": (f.angular_momentum, MOMENTUM),
        "parameter": (f.parameter, ""),
        "frequency": (f.frequency, "1/s"),
        "flip_interval": (f.flip_interval, "s"),
        "pole_axis": (f.pole_axis, ""),
    }


def _symmetric_expected(f: ps.FreeSymmetricTop) -> dict[str, tuple[Any, str]]:
    return {
        "I1": (f.I1, KG_M2),
        "I3": (f.I3, KG_M2),
        "omega0": (f.omega0, "rad/s"),
        "shape": (f.shape, ""),
        "precession_rate": (f.precession_rate, "rad/s"),
        "omega3": (f.omega3, "rad/s"),
        "amplitude": (f.amplitude, "rad/s"),
        "phase": (f.phase, "rad"),
        "omega_magnitude": (f.omega_magnitude, "rad/s"),
        "body_cone_angle": (f.body_cone_angle, "rad"),
        "space_cone_angle": (f.space_cone_angle, "rad"),
        "energy": (f.energy, "J"),
        "angular_momentum_magnitude": (f.angular_momentum_magnitude, MOMENTUM),
        "nutation_angle": (f.nutation_angle, "rad"),
        "space_precession_rate": (f.space_precession_rate, "rad/s"),
    }


def _trajectory_expected(tr: Any) -> dict[str, tuple[Any, str]]:
    return {
        "samples": (len(tr.t), ""),
        "t": ((tr.t[0], tr.t[-1]), "s"),
        "method": (tr.method, ""),
        "steps": (tr.steps, ""),
        "step": (tr.step, "s" if tr.step is not None else ""),
        "torque_evaluations": (tr.torque_evaluations, ""),
        "omega": (tr.omega, "rad/s"),
        "attitude": (tr.attitude, ""),
        "angular_momentum": (tr.angular_momentum, MOMENTUM),
        "energy": (tr.energy, "J"),
        "potential_energy": (tr.potential_energy, "J"),
        "power": (tr.power, "W"),
    }


def _samples_expected(r: Any) -> dict[str, tuple[Any, str]]:
    return {"t": (r.t, "s"), "position": (r.position, "m"), "velocity": (r.velocity, "m/s")}


def _fall_expected(r: Any) -> dict[str, tuple[Any, str]]:
    keys = ("time", "east", "north", "first_order_east", "second_order_south")
    return {k: (getattr(r, k), "s" if k == "time" else "m") for k in keys} | _samples_expected(r)


def _flight_expected(r: Any) -> dict[str, tuple[Any, str]]:
    keys = ("time", "east", "north", "range", "downrange", "drift")
    return {k: (getattr(r, k), "s" if k == "time" else "m") for k in keys} | _samples_expected(r)


def _foucault_expected(r: Any) -> dict[str, tuple[Any, str]]:
    def rate(x: float | None) -> tuple[Any, str]:
        return (x, "rad/s" if x is not None else "")

    return {
        "precession_rate": rate(r.precession_rate),
        "expected_rate": rate(r.expected_rate),
        "sense": (r.sense, ""),
        "regime": (r.regime, ""),
        "regime_note": (r.regime_note, ""),
        "theory_rate": rate(r.theory_rate),
        **_samples_expected(r),
        "turn_times": (r.turn_times, "s"),
        "turn_angles": (r.turn_angles, "rad"),
    }


def _screw_expected(s: ps.Screw) -> dict[str, tuple[Any, str]]:
    return {
        "axis": (s.axis, ""),
        "point": (s.point, "m"),
        "angle": (s.angle, "rad"),
        "slide": (s.slide, "m"),
        "pitch": (s.pitch, "m/rad"),
    }


def _density_body() -> ps.RigidBody:
    return ps.RigidBody.from_density(
        lambda p: 1.0 + p[:, 0] ** 2, [[-1.0, 1.0], [-0.5, 0.5], [0.0, 2.0]], rtol=1e-4
    )


CASES: dict[str, tuple[Callable[[], Any], Callable[[Any], dict[str, tuple[Any, str]]]]] = {
    "RigidBody/points": (
        lambda: ps.RigidBody.from_point_masses(
            [1.0, 2.0, 0.5], [[1, 2, 3], [-0.5, 0.1, 0.2], [0.3, -1, 0.7]]
        ),
        _body_expected,
    ),
    "RigidBody/cone": (lambda: ps.RigidBody.solid_cone(1.0, 0.5, 2.0), _body_expected),
    "RigidBody/density": (_density_body, _body_expected),
    "HeavyTop/loops": (
        lambda: ps.HeavyTop(1.0, 0.5, 1.0, 0.8, phi_dot=0.6, theta_dot=0.3, psi_dot=6.0),
        _top_expected,
    ),
    "HeavyTop/sleeping-unstable": (
        lambda: ps.HeavyTop(1.0, 0.5, 1.0, 0.0, psi_dot=1.0),
        _top_expected,
    ),
    "HeavyTop/hanging": (lambda: ps.HeavyTop(1.0, 0.5, 1.0, math.pi), _top_expected),
    "HeavyTop/through-vertical": (
        lambda: ps.HeavyTop(1.0, 0.5, 1.0, 0.5, theta_dot=3.0),
        _top_expected,
    ),
    "FreeRigidBody/max-axis": (
        lambda: ps.FreeRigidBody([1.0, 2.0, 3.0], [1.0, 0.1, 1.0]),
        _free_expected,
    ),
    "FreeRigidBody/steady": (
        lambda: ps.FreeRigidBody([1.0, 2.0, 3.0], [0.0, 1.0, 0.0]),
        _free_expected,
    ),
    "FreeSymmetricTop/prolate": (
        lambda: ps.FreeSymmetricTop(1.0, 0.5, [0.1, 0.0, 2.0]),
        _symmetric_expected,
    ),
    "FreeSymmetricTop/oblate": (
        lambda: ps.FreeSymmetricTop(1.0, 1.5, [0.3, -0.2, 2.0]),
        _symmetric_expected,
    ),
    "Trajectory/rk4-gravity": (
        lambda: ps.simulate(
            ps.RigidBody.solid_cone(1.0, 0.5, 2.0),
            [0.3, 0.0, 20.0],
            2.0,
            attitude0=[math.cos(0.25), math.sin(0.25), 0.0, 0.0],
            torque=ps.GravityTorque(),
            method="rk4",
            dt=0.01,
            samples=51,
        ),
        _trajectory_expected,
    ),
    "Trajectory/exact": (
        lambda: ps.simulate([1.0, 2.0, 3.0], [1.0, 0.1, 1.0], 10.0, samples=11),
        _trajectory_expected,
    ),
    "Fall": (lambda: EARTH.drop(100.0, 45.0, degrees=True), _fall_expected),
    "Flight": (lambda: EARTH.projectile(300.0, 45.0, 30.0, 45.0, degrees=True), _flight_expected),
    "FoucaultRun/precessing": (
        lambda: EARTH.foucault(45.0, degrees=True, duration=600.0, samples=201),
        _foucault_expected,
    ),
    "FoucaultRun/too-short": (
        lambda: EARTH.foucault(45.0, degrees=True, duration=20.0, samples=21),
        _foucault_expected,
    ),
    "Screw/quarter-turn": (
        lambda: ps.screw_axis(ps.euler_to_matrix([90.0, 0.0, 0.0], degrees=True), [1.0, -1.0, 2.0]),
        _screw_expected,
    ),
    "Screw/translation": (lambda: ps.screw_axis(np.eye(3), [0.0, 3.0, 4.0]), _screw_expected),
}


@pytest.fixture(scope="module")
def objects() -> dict[str, Any]:
    return {case: make() for case, (make, _) in CASES.items()}


def test_the_cases_cover_the_nine_classes(objects: dict[str, Any]) -> None:
    names = {type(o).__name__ for o in objects.values()}
    assert names == {
        "RigidBody", "HeavyTop", "FreeRigidBody", "FreeSymmetricTop", "Trajectory",
        "Fall", "Flight", "FoucaultRun", "Screw",
    }  # fmt: skip
    # The edge cases really are edge cases (None, inf, a pure translation, an error estimate).
    assert objects["FoucaultRun/too-short"].precession_rate is None
    assert objects["FreeRigidBody/steady"].pole_axis is None
    assert math.isinf(objects["HeavyTop/sleeping-unstable"].nutation_period)
    assert math.isinf(objects["Screw/translation"].pitch)
    assert objects["RigidBody/density"].integration_error is not None
    assert objects["Trajectory/exact"].step is None


@pytest.mark.parametrize("case", list(CASES))
def test_html_table_reads_back_as_the_model(case: str, objects: dict[str, Any]) -> None:
    """Tags balance, one row per quantity with its unit, and each number read back equals the
    model's attribute to the 6 significant digits shown."""
    obj = objects[case]
    name = type(obj).__name__
    markup = obj._repr_html_()
    assert table_problems(markup, name) == []
    rows = {r["key"]: r["cells"] for r in read_table(markup).rows}
    expected = CASES[case][1](obj)
    assert set(rows) == set(expected), f"{case}: shows {sorted(rows)}, expected {sorted(expected)}"
    for key, (value, unit) in expected.items():
        quantity, _symbol, shown, shown_unit = rows[key]
        assert quantity, f"{case}.{key}: no quantity"
        assert shown_unit == unit, f"{case}.{key}: unit {shown_unit!r}, expected {unit!r}"
        if isinstance(value, str):
            assert shown == value, f"{case}.{key}"
        else:
            assert_shows(read_value(shown), value, f"{case}.{key}")


@pytest.mark.parametrize("case", list(CASES))
def test_text_repr_says_what_the_table_says(case: str, objects: dict[str, Any]) -> None:
    obj = objects[case]
    assert table_problems(obj._repr_html_(), type(obj).__name__, repr(obj)) == []


def test_reprs_keep_their_text() -> None:
    """The texts the reprs had before the display module, kept where they said it this way (the
    tests of test_body, test_top and test_rotation_theorems pin parts of them too)."""
    assert repr(ps.FreeSymmetricTop(1.0, 0.5, [0.1, 0.0, 2.0])) == (
        "FreeSymmetricTop(I1=1 kg·m², I3=0.5 kg·m², omega0=[0.1, 0, 2] rad/s, prolate, Ω=1 rad/s)"
    )
    assert repr(ps.HeavyTop(1.0, 0.5, 1.0, 0.8, psi_dot=6.0)) == (
        "HeavyTop(I1=1 kg·m², I3=0.5 kg·m², mgl=1 N·m, cusps, theta in [0.8, 1.00148] rad, "
        "omega3=6 rad/s)"
    )
    assert repr(ps.RigidBody.solid_cone(1.0, 0.5, 2.0)) == (
        "RigidBody(mass=1 kg, center_of_mass=[0, 0, 1.5] m, "
        "principal_moments=[0.075, 0.1875, 0.1875] kg·m², kind='symmetric top')"
    )
    assert repr(ps.screw_axis(np.eye(3), [0.0, 0.0, 2.0])) == (
        "Screw(axis=[0, 0, 1], point=[0, 0, 0] m, angle=0 rad, slide=2 m, pitch=inf m/rad)"
    )


def test_arrays_are_summarised_not_dumped(objects: dict[str, Any]) -> None:
    run = objects["FoucaultRun/precessing"]
    markup = run._repr_html_()
    rows = {r["key"]: r["cells"] for r in read_table(markup).rows}
    assert rows["position"][2].startswith(f"({len(run.t)}, 3): [")
    assert rows["position"][2].count("[") == 2  # first and last sample, nothing between
    assert len(markup) < 8000
    assert len(objects["Trajectory/exact"]._repr_html_()) < 8000


def test_round_off_shows_as_zero_but_the_attribute_keeps_it() -> None:
    """A centre of mass off by round-off (2e-17 m beside 1.5 m) shows 0, as numpy's
    suppress_small; a small number that is not round-off keeps its digits."""
    b = ps.RigidBody(1.0, np.diag([1.0, 1.0, 1.5]), [2e-17, 0.0, 1.5])
    assert b.center_of_mass[0] == 2e-17
    assert "center_of_mass=[0, 0, 1.5] m" in repr(b)
    c = ps.RigidBody(1.0, np.diag([1.0, 1.0, 1.5]), [2e-9, 0.0, 1.5])
    assert "center_of_mass=[2e-09, 0, 1.5] m" in repr(c)


# ---- escaping -----------------------------------------------------------------------------------


def test_user_text_is_escaped() -> None:
    """A FoucaultRun is a dataclass a user may build with any words; they reach the table as
    text, never as markup, and the text repr quotes them as Python would."""
    run = EARTH.foucault(45.0, degrees=True, duration=20.0, samples=21)
    evil = '<script>alert("x")</script> & <b>'
    forged = dataclasses.replace(run, regime_note=evil, sense="<i>&amp;</i>")
    markup = forged._repr_html_()
    assert "<script" not in markup and "<b>" not in markup and "<i>" not in markup
    assert table_problems(markup, "FoucaultRun", repr(forged)) == []
    rows = {r["key"]: r["cells"] for r in read_table(markup).rows}
    assert rows["regime_note"][2] == evil and rows["sense"][2] == "<i>&amp;</i>"
    assert f"regime_note={evil!r}" in repr(forged)


def test_every_field_of_a_row_is_escaped() -> None:
    from poinsot import _display

    row = _display.Row('k"<&>', "q<&>", "s_<&>", "v<&>", "u<&>")
    markup = _display.html_table("N<&>", [row])
    assert "<&>" not in markup
    t = read_table(markup)
    assert t.problems == [] and t.caption == "N<&>"
    assert t.rows == [{"key": 'k"<&>', "detail": False, "cells": ["q<&>", "s<&>", "v<&>", "u<&>"]}]


# ---- negative controls: the checker catches a corrupted table ------------------------------------


def test_checker_catches_a_corrupted_table(objects: dict[str, Any]) -> None:
    top = objects["HeavyTop/loops"]
    good, text = top._repr_html_(), repr(top)
    assert table_problems(good, "HeavyTop", text) == []
    corrupt = {
        "unclosed cell": good.replace("</td>", "", 1),
        "stray end tag": good.replace("</tr>", "</tr></td>", 1),
        "cell dropped": re.sub(r"<td[^>]*>[^<]*</td></tr>", "</tr>", good, count=1),
        "row repeated": good.replace(
            "</tbody>", re.findall(r"<tr data-key.*?</tr>", good)[0] + "</tbody>"
        ),
        "header renamed": good.replace(">unit</th>", ">units</th>"),
        "wrong caption": good.replace(">HeavyTop</caption>", ">Top</caption>"),
        "outside script": good.replace(
            "</table>", '<script src="https://x/y.js"></script></table>'
        ),
    }
    for what, bad in corrupt.items():
        assert table_problems(bad, "HeavyTop", text), what
    # A text repr that says something else: another number, a lost unit, an extra item.
    for other in (
        text.replace("omega3=6.41802", "omega3=6.41803"),
        text.replace("mgl=1 N·m", "mgl=1"),
        text[:-1] + ", spin=1 rad/s)",
    ):
        assert table_problems(good, "HeavyTop", other)


def test_readback_catches_a_wrong_number(objects: dict[str, Any]) -> None:
    """The read-back comparison fails for a value off in its 6th digit, a wrong shape, a lost
    first or last sample."""
    top = objects["HeavyTop/loops"]
    with pytest.raises(AssertionError):
        assert_shows(read_value("6.41803"), top.omega3, "omega3")
    run = objects["Fall"]
    shown = read_value(ps._display.summary(run.position))
    with pytest.raises(AssertionError):
        assert_shows(shown, run.position[:-1], "position")
    with pytest.raises(AssertionError):
        assert_shows(Summary(shown.shape, shown.last, shown.first), run.position, "position")


# ---- LaTeX: the inertia tensor ---------------------------------------------------------------


def read_latex_matrix(latex: str) -> np.ndarray:
    r"""The entries of ``\left(\substack{..}\;\;\substack{..}...\right)``, columns of rows."""
    columns = re.findall(r"\\substack\{((?:[^{}]|\{[^{}]*\})*)\}", latex)
    cols = []
    for col in columns:
        entries = []
        for e in col.split(r"\\"):
            e = e.replace(r"\mathrm{-}", "-")
            m = re.fullmatch(r"(-?[0-9.]+)\\times10\^\{(-?\d+)\}", e)
            entries.append(float(m.group(1)) * 10.0 ** int(m.group(2)) if m else float(e))
        cols.append(entries)
    return np.array(cols).T


def _mathtext_renders(latex: str) -> bytes:
    from matplotlib import mathtext

    buf = io.BytesIO()
    mathtext.math_to_image(latex, buf, dpi=100, format="png")
    return buf.getvalue()


@pytest.mark.parametrize("case", ["RigidBody/points", "RigidBody/cone", "RigidBody/density"])
def test_latex_inertia_tensor_renders_and_equals_the_tensor(
    case: str, objects: dict[str, Any]
) -> None:
    pytest.importorskip("matplotlib")
    body = objects[case]
    latex = body._repr_latex_()
    assert latex.startswith(r"$\overline{I} = \left(") and latex.endswith(r"\ \mathrm{kg\,m^{2}}$")
    assert _mathtext_renders(latex).startswith(b"\x89PNG")
    assert_shows(read_latex_matrix(latex), body.inertia, f"{case} latex")


def test_latex_shows_products_of_inertia_negated() -> None:
    """CONVENTIONS §9: unit masses at (1, 1, 0) and (−1, −1, 0) m have I_xy = −Σ m x y = −2;
    the matrix is [[2, −2, 0], [−2, 2, 0], [0, 0, 4]] kg·m² by hand."""
    pytest.importorskip("matplotlib")
    b = ps.RigidBody.from_point_masses([1.0, 1.0], [[1.0, 1.0, 0.0], [-1.0, -1.0, 0.0]])
    latex = b._repr_latex_()
    np.testing.assert_array_equal(read_latex_matrix(latex), [[2, -2, 0], [-2, 2, 0], [0, 0, 4]])
    assert r"\mathrm{-}2" in latex
    _mathtext_renders(latex)


def test_latex_small_entries_use_powers_of_ten() -> None:
    pytest.importorskip("matplotlib")
    b = ps.RigidBody.cuboid(1e-4, (0.01, 0.02, 0.03)).rotated(ps.euler_to_matrix([0.3, 0.4, 0.5]))
    latex = b._repr_latex_()
    assert r"\times10^{-9}" in latex and "e-" not in latex
    _mathtext_renders(latex)
    assert_shows(read_latex_matrix(latex), b.inertia, "small body latex")


def test_latex_checks_can_fail() -> None:
    """Negative controls: a matrix environment mathtext cannot set is refused, and a wrong
    entry is caught by the read-back."""
    pytest.importorskip("matplotlib")
    b = ps.RigidBody.from_point_masses([1.0, 1.0], [[1.0, 1.0, 0.0], [-1.0, -1.0, 0.0]])
    with pytest.raises(ValueError):
        _mathtext_renders(r"$\begin{pmatrix}2 & -2\\ -2 & 2\end{pmatrix}$")
    wrong = b._repr_latex_().replace(r"\mathrm{-}2", "2", 1)  # the product's sign lost
    with pytest.raises(AssertionError):
        assert_shows(read_latex_matrix(wrong), b.inertia, "wrong sign")


# ---- a real notebook kernel ---------------------------------------------------------------------

NOTEBOOK_CELLS = [
    "import poinsot as ps",
    "ps.HeavyTop(1.0, 0.5, 1.0, 0.8, phi_dot=0.6, theta_dot=0.3, psi_dot=6.0)",
    "ps.RigidBody.from_point_masses([1.0, 1.0], [[1.0, 1.0, 0.0], [-1.0, -1.0, 0.0]])",
    "ps.Earth().foucault(45.0, degrees=True, duration=600.0, samples=201)",
]


def test_display_in_a_notebook_kernel(tmp_path: Path) -> None:
    """Executes a small notebook in a real IPython kernel (nbclient) and reads what it
    displays: the HTML table, the text repr as text/plain and, for a body, the LaTeX."""
    nbformat = pytest.importorskip("nbformat", reason="nbformat is not installed")
    nbclient = pytest.importorskip("nbclient", reason="nbclient is not installed")
    pytest.importorskip("ipykernel", reason="ipykernel is not installed")
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(src) for src in NOTEBOOK_CELLS]
    # The kernel imports the same poinsot as this test (the source tree, not an installed copy).
    package_root = str(Path(ps.__file__).resolve().parents[1])
    env = dict(os.environ)
    env["PYTHONPATH"] = package_root + ((":" + env["PYTHONPATH"]) if env.get("PYTHONPATH") else "")
    client = nbclient.NotebookClient(
        nb, timeout=120, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}}
    )
    client.execute(env=env)
    outputs = [cell.outputs for cell in nb.cells]
    assert all(o["output_type"] != "error" for out in outputs for o in out), outputs
    here = {
        1: ps.HeavyTop(1.0, 0.5, 1.0, 0.8, phi_dot=0.6, theta_dot=0.3, psi_dot=6.0),
        2: ps.RigidBody.from_point_masses([1.0, 1.0], [[1.0, 1.0, 0.0], [-1.0, -1.0, 0.0]]),
        3: ps.Earth().foucault(45.0, degrees=True, duration=600.0, samples=201),
    }
    for i, obj in here.items():
        (result,) = [o for o in outputs[i] if o["output_type"] == "execute_result"]
        data = result["data"]
        name = type(obj).__name__
        assert table_problems(data["text/html"], name, data["text/plain"]) == []
        assert data["text/html"] == obj._repr_html_()
        assert data["text/plain"] == repr(obj)
        rows = {r["key"]: r["cells"] for r in read_table(data["text/html"]).rows}
        assert rows  # the kernel's table has rows, checked against the model above
    assert "text/latex" in outputs[2][0]["data"]
    np.testing.assert_array_equal(
        read_latex_matrix(outputs[2][0]["data"]["text/latex"]), [[2, -2, 0], [-2, 2, 0], [0, 0, 4]]
    )


# ---- the docs page ------------------------------------------------------------------------------


def test_docs_page_shows_what_the_code_displays() -> None:
    """docs/jupyter.md runs, and the repr and the table it shows are what the code displays."""
    doc = (ROOT / "docs" / "jupyter.md").read_text(encoding="utf-8")
    blocks = re.findall(r"```python\n(.*?)```", doc, re.DOTALL)
    assert blocks
    namespace: dict[str, Any] = {"__name__": "__doc__"}
    for i, block in enumerate(blocks):
        exec(compile(block, f"docs/jupyter.md[block {i}]", "exec"), namespace)
    top = namespace["top"]
    assert f"```text\n{top!r}\n```" in doc
    shown = re.search(r"<!-- the table -->\n(.*?)\n<!-- end of the table -->", doc, re.DOTALL)
    assert shown is not None and shown.group(1) == top._repr_html_()
    latex = re.search(r"\$\$\n(.*?)\n\$\$", doc, re.DOTALL)
    assert latex is not None and f"${latex.group(1)}$" == namespace["body"]._repr_latex_()
