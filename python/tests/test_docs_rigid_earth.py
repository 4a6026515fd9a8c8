"""docs/rigid_earth.md, the chapter "The Earth as a rigid body" (issue 25): its numbers are
computed when the site is built (myst-nb's glue), so every value the prose shows is glued by the
page's own cells — run here in order, with a stand-in for ``glue`` — and the values are
RigidEarth's, its simulation's, the pole fit's and the catalogue's. Negative control: a key the
cells do not glue is reported."""

from __future__ import annotations

import functools
import math
from pathlib import Path
from typing import Any

import poinsot as ps
import pytest
from _glued_page import CELL, USED, glued, missing

PAGE = Path(__file__).resolve().parents[2] / "docs" / "rigid_earth.md"


@functools.cache
def _glued() -> dict[str, Any]:
    return glued(PAGE)


def test_every_number_the_prose_shows_is_glued_and_finite() -> None:
    values = _glued()
    text = PAGE.read_text(encoding="utf-8")
    assert len(USED.findall(text)) >= 25
    assert missing(text, values) == []
    assert all(math.isfinite(float(v)) for v in values.values())


def test_the_glued_values_are_rigid_earths_and_the_catalogues() -> None:
    v = _glued()
    e = ps.RigidEarth()
    h = e.dynamical_flattening
    assert v["euler_sidereal"] == pytest.approx((1 - h) / h, rel=1e-12)
    assert v["chandler_days"] == pytest.approx(e.chandler_period(0.30, 0.938) / 86400)
    assert v["chandler_obs"] == pytest.approx(433.1) and v["chandler_sigma"] == pytest.approx(1.7)
    year, arcsec = 365.25 * 86400, math.pi / 648000
    assert v["rate"] == pytest.approx(-e.precession_rate * year / arcsec, rel=1e-12)
    assert v["sun_rate"] + v["moon_rate"] == pytest.approx(v["rate"], rel=1e-12)
    assert abs(v["rate_off_pct"]) < 0.5  # the bound against IAU 2006
    assert v["dpsi"] == pytest.approx(e.nutation_amplitudes[0] / arcsec, rel=1e-12)
    # the simulated axis reproduces the averaged rate (the issue: to 1 %) and the nutation
    assert abs(v["sim_off_pct"]) < 1.0
    assert v["sim_dpsi"] == pytest.approx(v["dpsi"], rel=0.02)
    assert v["sim_deps"] == pytest.approx(v["deps"], rel=0.02)
    # the real pole's Chandler period, near the catalogue's observed one
    assert abs(v["fit_period"] - v["chandler_obs"]) < 5.0


def test_the_page_shows_its_figures_under_the_agg_backend() -> None:
    """make test and make docs run with MPLBACKEND=Agg, under which a kernel shows no figure
    unless the inline backend is asked for first (the built page had none without it)."""
    first = CELL.findall(PAGE.read_text(encoding="utf-8"))[0]
    assert first.startswith("%matplotlib inline\n")


def test_negative_control_an_unglued_key_is_reported() -> None:
    values = _glued()
    assert missing("{glue:text}`not_a_key:.2f`", values) == ["not_a_key"]
