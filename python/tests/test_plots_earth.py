"""Smoke tests of the Earth's pictures and the Foucault animation (they draw what the core
computes; the numbers are tested elsewhere)."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import poinsot as ps
from poinsot.plots import earth as pe


def test_figures_draw(tmp_path) -> None:
    earth = ps.Earth()
    for fig in (
        pe.plot_deflection(earth, n=4),
        pe.plot_trajectory(earth.drop(50, 30, degrees=True)),
        pe.plot_trajectory(earth.projectile(100, 45, 30, 30, degrees=True)),
        pe.plot_inertial_circles(earth),
    ):
        fig.savefig(tmp_path / "f.png")
    fast = ps.Earth(rotation_rate=1e-2)
    run = fast.foucault(45, degrees=True, length=5.0, amplitude=0.5, duration=60.0, samples=601)
    pe.plot_foucault_rosette(run).savefig(tmp_path / "r.png")
    pe.animate_foucault(run, tmp_path / "a.gif", frames=8, fps=4)
    assert (tmp_path / "a.gif").stat().st_size > 1000
