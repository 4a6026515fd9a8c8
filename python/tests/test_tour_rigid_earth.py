"""`poinsot tour`'s section "The Earth as a rigid body" (issue 25): its numbers are
RigidEarth's, beside (1 − H)/H and the IAU values, and it fits 80 columns."""

from __future__ import annotations

import io
import math

import poinsot as ps
from poinsot.tour import _SECTIONS
from rich.cells import cell_len
from rich.console import Console


def _text(width: int = 80) -> str:
    con = Console(width=width, record=True, file=io.StringIO())
    (fn,) = [f for title, f in _SECTIONS if title.startswith("The Earth as a rigid body")]
    fn(con)
    return con.export_text()


def test_the_section_prints_rigid_earths_numbers_beside_the_references() -> None:
    text = _text()
    e = ps.RigidEarth()
    h = e.dynamical_flattening
    sidereal_days = e.euler_period / (2 * math.pi / e.rotation_rate)
    assert f"{sidereal_days:.6g} sidereal d" in text and f"(1 − H)/H = {(1 - h) / h:.6g}" in text
    year, arcsec = 365.25 * 86400, math.pi / 648000
    assert f"{-e.precession_rate * year / arcsec:.3f} ″/yr" in text
    assert f"IAU 2006 {ps.IAU2006_PRECESSION_RATE * year / arcsec:.3f}" in text
    assert f"{e.chandler_period(0.30, 0.938) / 86400:.4g} d" in text
    assert f"{e.nutation_amplitudes[0] / arcsec:.4g}″" in text
    assert max(cell_len(line) for line in text.splitlines()) <= 80
    assert "…" not in text


def test_the_section_sits_before_the_catalogue() -> None:
    titles = [t for t, _ in _SECTIONS]
    earth = next(i for i, t in enumerate(titles) if t.startswith("The Earth as a rigid body"))
    world = next(i for i, t in enumerate(titles) if t.startswith("The unit against the world"))
    assert earth == world - 1
