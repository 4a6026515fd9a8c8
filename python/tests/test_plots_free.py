"""The torque-free plots draw (Agg backend) what they say they draw."""

from __future__ import annotations

import numpy as np
import pytest

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")

import poinsot as ps  # noqa: E402
from poinsot.plots import free as plots_free  # noqa: E402


def test_omega_plot_overlays_the_exact_solution():
    body = ps.FreeRigidBody([1, 2, 3], [1, 0.1, 1])
    tr = ps.simulate([1, 2, 3], [1, 0.1, 1], 10.0, method="rk4", dt=0.05, samples=51)
    fig = plots_free.plot_omega(tr, body)
    lines = fig.axes[0].get_lines()
    assert len(lines) == 6  # three integrated, three exact
    np.testing.assert_allclose(lines[0].get_ydata(), tr.omega[:, 0])


def test_cones_polhodes_conservation_and_animation(tmp_path):
    fig = plots_free.plot_cones(ps.FreeSymmetricTop(2.0, 1.0, [0.8, 0.0, 1.0]), 0.5)
    assert "prolate" in fig.axes[0].get_title()
    fig = plots_free.plot_polhodes((1.0, 2.0, 3.0), n=5)
    assert len(fig.axes[0].get_lines()) >= 4
    runs = [
        ps.simulate([1, 2, 3], [1, 0.1, 1], 50.0, method=m, dt=0.01, samples=51)
        for m in ("splitting2", "rk4")
    ]
    fig = plots_free.plot_conservation(runs)
    assert fig.axes[0].get_xscale() == "log" and fig.axes[0].get_yscale() == "log"
    anim = plots_free.animate_tumbling_box(frames=5, path=tmp_path / "box.gif")
    assert (tmp_path / "box.gif").stat().st_size > 0
    assert anim is not None
