"""`poinsot tour`'s section "Tops on the turning Earth" (issue 26): Foucault's free gyroscope
drifts at Ω sin λ in Paris (the full carried simulation), the Schuler-tuned compass's period is
2π√(R/g) = 84.4 min, and the steaming error is Gyrocompass's; it fits 80 columns."""

from __future__ import annotations

import io
import math
import re

import poinsot as ps
from poinsot.tour import _SECTIONS
from rich.cells import cell_len
from rich.console import Console

OMEGA = 7.292115e-5  # rad/s, the sidereal rate (the test's own constant)


def _text(width: int = 80) -> str:
    con = Console(width=width, record=True, file=io.StringIO())
    (fn,) = [f for title, f in _SECTIONS if title.startswith("Tops on the turning Earth")]
    fn(con)
    return con.export_text()


def test_the_section_prints_the_drift_the_schuler_period_and_the_steaming_error() -> None:
    text = _text()
    paris = math.radians(48.8566)
    rate = math.degrees(OMEGA * math.sin(paris)) * 3600
    assert abs(rate - 11.3269) < 1e-4
    (drift,) = re.findall(r"drift\s+│\s+([0-9.]+) °/h", text)
    assert abs(float(drift) - rate) <= 0.0011  # the simulated drift, to the printed digit
    assert f"Ω sin λ = {rate:.3f} °/h" in text
    schuler = ps.Gyrocompass.schuler_period()
    assert abs(schuler / 60 - 84.4) < 0.05
    assert f"2π√(R/g) = {schuler / 60:.4g} min" in text
    tuned = ps.Gyrocompass.schuler_tuned(math.radians(50.0)).period
    assert f"{tuned / 60:.4g} min" in text
    c, v = ps.Gyrocompass(math.radians(50.0)), 20 * 1852 / 3600
    assert f"{math.degrees(c.speed_error(v, 0.0)):+.3f}°" in text
    assert f"small-angle {math.degrees(c.speed_error_small_angle(v, 0.0)):+.3f}°" in text
    assert "poinsot gyrocompass" in text and "poinsot derive gyrocompass" in text
    assert max(cell_len(line) for line in text.splitlines()) <= 80
    assert "…" not in text


def test_the_drift_is_clockwise_and_a_still_earth_gives_none() -> None:
    """Negative control: on a still Earth the same gyroscope's axis does not drift."""
    from poinsot.tour import _axis_heading

    north = [math.cos(math.pi / 4), -math.sin(math.pi / 4), 0.0, 0.0]
    for omega, expected in ((OMEGA, OMEGA * math.sin(0.85)), (0.0, 0.0)):
        run = ps.simulate(
            [1.0, 1.0, 2.0],
            [0.0, 0.0, 1000.0],
            60.0,
            carried_by=ps.Place(0.85, ps.Earth(omega)),
            attitude0=north,
            method="exact",
            samples=2,
        )
        assert isinstance(run, ps.CarriedTrajectory)
        heading = _axis_heading(run.relative_attitude)
        assert heading[0] == 0.0
        assert abs((heading[1] - heading[0]) / 60.0 - expected) <= 1e-4 * OMEGA


def test_the_section_sits_among_the_tops_before_the_rigid_earth() -> None:
    titles = [t for t, _ in _SECTIONS]
    here = next(i for i, t in enumerate(titles) if t.startswith("Tops on the turning Earth"))
    earth = next(i for i, t in enumerate(titles) if t.startswith("The Earth as a rigid body"))
    assert here == earth - 1
