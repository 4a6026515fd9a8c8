"""docs/gyrocompass.md, the chapter "Tops on the turning Earth" (issue 26): its numbers are
computed when the site is built (myst-nb's glue), so every value the prose shows is glued by the
page's own cells — run here in order, with a stand-in for ``glue`` — and the values are
Gyrocompass's, its simulation's and the catalogue's, checked against closed forms written here.
The gallery example runs. Negative control: a key the cells do not glue is reported."""

from __future__ import annotations

import functools
import math
import runpy
import sys
from pathlib import Path
from typing import Any

import pytest
from _glued_page import CELL, USED, glued, missing

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "gyrocompass.md"

# The test's own constants: the sidereal rate, the mean radius, standard gravity.
OMEGA, R, G = 7.292115e-5, 6.371e6, 9.80665
KNOT = 1852 / 3600


@functools.cache
def _glued() -> dict[str, Any]:
    return glued(PAGE)


def test_every_number_the_prose_shows_is_glued_and_finite() -> None:
    values = _glued()
    text = PAGE.read_text(encoding="utf-8")
    assert len(USED.findall(text)) >= 20
    assert missing(text, values) == []
    assert all(math.isfinite(float(v)) for v in values.values())


def test_the_glued_values_against_closed_forms() -> None:
    v = _glued()
    assert v["paris_drift"] == pytest.approx(
        math.degrees(OMEGA * math.sin(math.radians(48 + 50 / 60))) * 3600, rel=1e-4
    )
    assert v["schuler_min"] == pytest.approx(2 * math.pi * math.sqrt(R / G) / 60, rel=1e-6)
    assert v["period_tuned_min"] == pytest.approx(v["schuler_min"], rel=1e-3)
    lat = math.radians(50)
    h, p = v["h_default"], v["p_default"]
    assert v["period_default_min"] == pytest.approx(
        2 * math.pi * math.sqrt(h / (p * OMEGA * math.cos(lat))) / 60, rel=1e-3
    )
    assert v["h_tuned"] == pytest.approx(p * OMEGA * math.cos(lat) * R / G, rel=1e-4)
    # the 1.2° at 50 kn at 81°: the printed (arcsine) table against the settled atan
    ground = OMEGA * R * math.cos(math.radians(81))
    assert v["exact_81"] == pytest.approx(math.degrees(math.atan(50 * KNOT / ground)), rel=1e-4)
    assert v["small_81"] == pytest.approx(math.degrees(50 * KNOT / ground), rel=1e-4)
    assert v["table_81"] == pytest.approx(20.7) and v["table_gap"] == pytest.approx(1.2, abs=0.05)
    c = 50 * KNOT / math.sqrt(2)  # on 045° and 315°: the table's one 14.5° parts in two
    assert v["ne_81"] == pytest.approx(math.degrees(math.atan(c / (ground + c))), rel=1e-4)
    assert v["nw_81"] == pytest.approx(math.degrees(math.atan(c / (ground - c))), rel=1e-4)
    assert v["settle_deg"] < 0  # a damped compass reads low in the north
    # the simulation: the damped swing within 1 % of the linearised; a pendulum's growth
    assert abs(v["damped_off_pct"]) < 1.0
    assert v["ratio_2"] == pytest.approx(1.0, abs=0.005)
    assert 1.0 < v["ratio_20"] < 1.01 < 1.17 < v["ratio_90"] < 1.19
    # a course reversal at 10 m/s: the steaming error's jump 2 atan(V/(Ω R cos λ)); the
    # Schuler-tuned compass lands on it (no ballistic error), twice the rotor swings by half
    assert v["turn_jump"] == pytest.approx(
        math.degrees(2 * math.atan(10.0 / (OMEGA * R * math.cos(lat)))), rel=1e-4
    )
    assert v["turn_swing_tuned"] < 0.02 * v["turn_jump"]
    assert v["turn_swing_heavy"] == pytest.approx(0.5 * v["turn_jump"], rel=0.05)
    assert v["heavy_period_min"] == pytest.approx(math.sqrt(2) * v["schuler_min"], rel=1e-3)
    # the steaming error in the full run: the Coriolis estimate 2 Ω V_N sin λ tan λ / g plus a
    # residual under 0.005°; within 0.01° at 30°, not at 60°
    for band in (30, 60):
        s = math.radians(band)
        est = math.degrees(
            2 * OMEGA * 10.0 * math.cos(math.radians(20)) * math.sin(s) * math.tan(s) / G
        )
        assert v[f"band_est_{band}"] == pytest.approx(est, rel=1e-4)
        assert 0.0 < v[f"band_sim_{band}"] - est < 0.005
    assert abs(v["band_sim_30"]) < 0.01 < v["band_sim_60"]


def test_the_page_shows_its_figures_under_the_agg_backend() -> None:
    first = CELL.findall(PAGE.read_text(encoding="utf-8"))[0]
    assert first.startswith("%matplotlib inline\n")


def test_negative_control_an_unglued_key_is_reported() -> None:
    values = _glued()
    assert missing("{glue:text}`not_a_key:.2f`", values) == ["not_a_key"]


def test_the_gallery_example_runs(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    pytest.importorskip("matplotlib")
    script = ROOT / "examples" / "gyrocompass.py"
    monkeypatch.setattr(sys, "argv", [str(script), str(tmp_path)])
    runpy.run_path(str(script), run_name="__main__")
    assert (tmp_path / "gyrocompass.png").stat().st_size > 10_000
