"""poinsot.HeavyTop a hair's breadth from the hanging pole, theta0 = pi - delta (issue 21, item 1),
through the Python API, the command line and the sweep: against the 30-digit mpmath integration
of the Lagrangian in pi - theta (python/tests/reference/gen_heavy_top_hanging.py ->
heavy_top_hanging_mpmath.csv), and the issue's example, which read as steady precession with
euler_rates(0) = (4, 0, 5) instead of its own (0, 0, 1) for 4e-16 <= delta <~ 1e-8."""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import numpy as np
import poinsot as ps
import pytest
from click.testing import CliRunner
from poinsot import HeavyTop
from poinsot.cli import main

CSV = Path(__file__).parent / "reference" / "heavy_top_hanging_mpmath.csv"
# As near upright: phi and psi to 1e-10 of max(|x|, 1 rad); theta to 1e-10 of pi - theta itself
# (stricter than of theta ~ pi), plus two ulp of pi, all that the double theta can carry.
HANGING_TOL = 1e-10
THETA_FLOOR = 2 * math.ulp(math.pi)
PI_LO = 1.2246467991473532e-16  # pi - math.pi
ONE_ULP = math.nextafter(math.pi, 0.0)


def _cases() -> dict[str, list[dict]]:
    rows = list(
        csv.DictReader(line for line in CSV.read_text().splitlines() if not line.startswith("#"))
    )
    cases: dict[str, list[dict]] = {}
    for r in rows:
        cases.setdefault(r["name"], []).append(r)
    return cases


CASES = _cases()


def _top(r0: dict) -> HeavyTop:
    f = {k: float(r0[k]) for k in ("theta0", "theta_dot0", "phi_dot0", "psi_dot0")}
    return HeavyTop(
        1.0,
        0.5,
        1.0,
        f["theta0"],
        theta_dot=f["theta_dot0"],
        phi_dot=f["phi_dot0"],
        psi_dot=f["psi_dot0"],
    )


@pytest.mark.parametrize("name", sorted(CASES))
def test_near_hanging_matches_mpmath(name: str) -> None:
    rows = CASES[name]
    top = _top(rows[0])
    assert top.motion_class == rows[0]["class"]
    t = np.array([float(r["t"]) for r in rows])
    phi, theta, psi = top.euler_angles(t)
    ref = {k: np.array([float(r[k]) for r in rows]) for k in ("phi", "theta", "psi")}
    chi = np.array([float(r["pole_distance"]) for r in rows])
    got_chi = (math.pi - theta) + PI_LO  # math.pi - theta is exact
    assert np.all(np.abs(got_chi - chi) <= HANGING_TOL * chi + THETA_FLOOR)
    assert np.max(np.abs(theta / ref["theta"] - 1.0)) < HANGING_TOL
    for key, got in (("phi", phi), ("psi", psi)):
        assert np.max(np.abs(got - ref[key]) / np.maximum(1.0, np.abs(ref[key]))) < HANGING_TOL, key
    # The batch (SIMD lanes of the Fourier series) is the scalar call, time by time.
    for i, ti in enumerate(t):
        assert top.euler_angles(float(ti)) == (phi[i], theta[i], psi[i])


@pytest.mark.parametrize("delta", [1e-7, 1e-8, 1e-10, 1e-12, 1e-14, 0.0])
def test_issue_example_starts_from_its_own_state(delta: float) -> None:
    """HeavyTop(1.0, 0.5, 1.0, math.pi - 1e-8, psi_dot=1.0) was "steady precession" with
    euler_rates(0.0) == (4, 0, 5); delta = 0 here is theta0 one ulp below pi."""
    theta0 = ONE_ULP if delta == 0.0 else math.pi - delta
    top = HeavyTop(1.0, 0.5, 1.0, theta0, psi_dot=1.0)
    assert top.motion_class == "cusps"
    assert top.euler_rates(0.0) == pytest.approx((0.0, 0.0, 1.0), abs=1e-15)
    assert top.euler_angles(0.0) == (0.0, theta0, 0.0)
    theta1, theta2 = top.turning_points
    assert theta1 == theta0 and theta2 > theta1
    # Negative control: the issue's numbers at the exact pole (the double pi) hang.
    assert HeavyTop(1.0, 0.5, 1.0, math.pi, psi_dot=1.0).motion_class == "hanging"


def test_command_line_gives_the_class() -> None:
    """poinsot top at theta = pi - 1e-8 prints cusps (it printed steady precession)."""
    args = ["top", "--I1", "1", "--I3", "0.5", "--mgl", "1", "--theta", repr(math.pi - 1e-8)]
    res = CliRunner().invoke(main, [*args, "--psi-dot", "1", "--json"])
    assert res.exit_code == 0, res.output
    data = json.loads(res.output)
    assert data["motion_class"] == "cusps"
    assert data["turning_points"][1] > data["turning_points"][0]
    res = CliRunner().invoke(main, [*args, "--psi-dot", "1"])
    assert res.exit_code == 0, res.output
    (line,) = [x for x in res.output.splitlines() if "motion class" in x]
    assert "cusps" in line and "steady" not in line, line


def test_sweep_next_to_the_hanging_pole_is_the_scalar_top() -> None:
    """poinsot.sweep.heavy_top at theta0 = pi - delta: each point the scalar top, bit for bit."""
    xr = pytest.importorskip("xarray")
    del xr
    thetas = np.array([math.pi - 1e-3, math.pi - 1e-8, math.pi - 1e-12, ONE_ULP])
    psi_dots = np.array([-1.0, 1.0, 8.0])
    phi_dots = np.array([0.0, 0.3])
    ds = ps.sweep.heavy_top(
        I1=1.0, I3=0.5, mgl=1.0, theta=thetas, psi_dot=psi_dots, phi_dot=phi_dots
    )
    for i, th in enumerate(thetas):
        for j, psd in enumerate(psi_dots):
            for k, phd in enumerate(phi_dots):
                top = HeavyTop(1.0, 0.5, 1.0, th, psi_dot=psd, phi_dot=phd)
                at = ds.isel(theta=i, psi_dot=j, phi_dot=k)
                assert at.motion_class.item() == top.motion_class != "steady precession"
                assert tuple(at.turning_points.values) == top.turning_points
                assert at.nutation_period.item() == top.nutation_period
                assert at.mean_precession_rate.item() == top.mean_precession_rate
