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
    assert "prolate" in fig.get_suptitle() and "outside" in fig.get_suptitle()
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


@pytest.mark.parametrize(
    ("I1", "I3", "omega0", "t"),
    [
        (1.0, 0.5, [0.1, 0.0, 2.0], 0.0),
        (1.0, 1.8, [0.8, 0.0, 1.0], 0.5),
        (2.0, 1.0, [0.8, 0, 1], 3.0),
    ],
)
def test_cones_seen_along_L_put_omega_and_e3_at_their_angles_from_L(I1, I3, omega0, t):
    # The README's top has cones of 2.9°: the panel seen along L draws every direction at its
    # angle from L, so ω sits at α_s (2.97) and e₃ at the nutation angle from the centre.
    top = ps.FreeSymmetricTop(I1, I3, omega0)
    fig = plots_free.plot_cones(top, t)
    along = fig.axes[1]
    points = {line.get_label(): np.ravel(line.get_xydata())[:2] for line in along.get_lines()}
    w = points["ω: the line of contact"]
    e3 = points["e₃"]
    np.testing.assert_allclose(np.hypot(*w), np.degrees(top.space_cone_angle), rtol=1e-9)
    e3_angle = min(top.nutation_angle, np.pi - top.nutation_angle)
    np.testing.assert_allclose(np.hypot(*e3), np.degrees(e3_angle), rtol=1e-9)
    # the space cone's rim is the circle of radius α_s about L (the origin)
    rim = along.get_lines()[0].get_xydata()
    np.testing.assert_allclose(np.hypot(rim[:, 0], rim[:, 1]), np.degrees(top.space_cone_angle))
    # negative control, in every case: the body cone's angle, the likeliest wrong one, is told
    # apart from what is drawn (2.85° vs 2.86° for the README's top, 14.7° vs 38.7° and 19.3° vs
    # 38.7° for the others) by far more than the tolerance above
    wrong = np.degrees(top.body_cone_angle)
    assert abs(np.hypot(*w) - wrong) > 1e3 * 1e-9 * wrong
