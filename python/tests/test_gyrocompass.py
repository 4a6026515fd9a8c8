"""poinsot.Gyrocompass (issue 26): the period against 2π√(H/(P Ω cos λ)) and Schuler's 84.4
min, the speed error against its closed form (written here) and the full simulation, the
latitude error against the settled simulation, the negative control, refusals by name."""

from __future__ import annotations

import math
import pickle

import numpy as np
import poinsot as ps
import pytest

OMEGA = 7.2921150e-5
R = 6.371e6
G = 9.80665


def test_period_closed_form_and_schuler():
    c = ps.Gyrocompass(math.radians(50), 40.0, 1.2)
    assert c.period == pytest.approx(
        2 * math.pi * math.sqrt(40.0 / (1.2 * OMEGA * math.cos(math.radians(50)))), rel=1e-14
    )
    s = ps.Gyrocompass.schuler_tuned(math.radians(50))
    assert s.period / 60 == pytest.approx(84.4, abs=0.05)
    assert s.period == pytest.approx(2 * math.pi * math.sqrt(R / G), rel=1e-13)
    assert ps.Gyrocompass.schuler_period() == pytest.approx(s.period, rel=1e-13)


def _closed(v: float, c: float, lat: float) -> float:
    return math.atan(v * math.cos(c) / (OMEGA * R * math.cos(lat) + v * math.sin(c)))


def test_speed_error_closed_form_small_angle_and_signs():
    lat = math.radians(50)
    c = ps.Gyrocompass(lat)
    for v, course in [
        (10.0, 0.0),
        (15.0, math.radians(45)),
        (8.0, math.radians(200)),
        (12.0, math.radians(-80)),
    ]:
        assert c.speed_error(v, course) == pytest.approx(_closed(v, course, lat), abs=1e-15)
        assert c.speed_error_small_angle(v, course) == pytest.approx(
            v * math.cos(course) / (OMEGA * R * math.cos(lat)), rel=1e-14
        )
    assert c.speed_error(10.0, 0.0) > 0  # northerly course: reads high (north settles west)
    assert c.speed_error(10.0, math.pi) < 0
    # 50 knots due north at 81°: the two forms part by about 0.8°.
    hi = ps.Gyrocompass(math.radians(81))
    v = 50 * 1852 / 3600
    gap = math.degrees(hi.speed_error_small_angle(v, 0.0) - hi.speed_error(v, 0.0))
    assert 0.7 < gap < 0.9


def test_speed_error_matches_the_full_simulation():
    # Undamped: the settled heading is the mean over one period of the swing about it.
    # At 30°: the simulation settles 0.006° off the formula (0.009° at 45°), about what the
    # Coriolis force on the tilted pendulous element, which the kinematic formula leaves
    # out, is estimated to move it (2 Ω sin λ V_N m l θ / (H Ω cos λ)).
    c = ps.Gyrocompass.schuler_tuned(math.radians(30), damping=0.0)
    v, course = 10.0, math.radians(20)
    delta = c.speed_error(v, course)
    n = 1001
    run = c.simulate(
        c.period, -delta + math.radians(0.05), speed=v, course=course, samples=n, rtol=1e-9
    )
    h = run.heading
    mean = (h.sum() - 0.5 * (h[0] + h[-1])) / (n - 1)
    mid = ps.Gyrocompass.schuler_tuned(run.latitude[n // 2], damping=0.0)
    assert math.degrees(mean + mid.speed_error(v, course)) == pytest.approx(0.0, abs=0.01)


def test_simulated_settling_period_within_one_percent():
    c = ps.Gyrocompass.schuler_tuned(math.radians(50), damping=0.0)
    run = c.simulate(2.2 * c.period, math.radians(0.5), samples=2201, rtol=1e-9)
    h = run.heading
    k = np.nonzero((h[:-1] < 0) & (h[1:] >= 0))[0]
    ups = run.t[k] + (run.t[k + 1] - run.t[k]) * (-h[k]) / (h[k + 1] - h[k])
    assert len(ups) >= 2
    assert (ups[1] - ups[0]) / c.period == pytest.approx(1.0, abs=0.01)


def test_damped_compass_settles_on_the_latitude_error():
    c = ps.Gyrocompass.schuler_tuned(math.radians(40), damping=0.5)
    err = c.settle_error
    # Small-angle form, written here: −D tan λ / (P + H Ω cos λ).
    lat = math.radians(40)
    small = (
        -c.damping_coefficient
        * math.tan(lat)
        / (c.pendulosity + c.angular_momentum * OMEGA * math.cos(lat))
    )
    assert err == pytest.approx(small, rel=2e-3)
    run = c.simulate(4 * c.period, -err + math.radians(0.3), samples=11, rtol=1e-9)
    assert math.degrees(run.heading[-1] + err) == pytest.approx(0.0, abs=0.01)
    assert err < 0


def test_negative_control_no_earth_rotation_no_north_seeking():
    still = ps.Earth(rotation_rate=0.0)
    c = ps.Gyrocompass(math.radians(50), 40.0, 1.2, damping=0.0, earth=still)
    run = c.simulate(3000.0, 0.3, tilt0=0.0, samples=11, rtol=1e-9)
    np.testing.assert_allclose(run.heading, 0.3, atol=1e-9)
    with pytest.raises(ps.PoinsotError, match="^rotation_rate"):
        c.period
    turning = ps.Gyrocompass(math.radians(50), 40.0, 1.2, damping=0.0)
    run = turning.simulate(3000.0, 0.3, tilt0=0.0, samples=11, rtol=1e-9)
    assert abs(run.heading[-1] - 0.3) > 0.1


def test_units_pickle_and_repr():
    pint = pytest.importorskip("pint")
    u = pint.UnitRegistry()
    c = ps.Gyrocompass(50 * u.deg)
    assert c.latitude == pytest.approx(math.radians(50))
    assert c.speed_error(20 * u.knot, 45 * u.deg) == pytest.approx(
        c.speed_error(20 * 1852 / 3600, math.radians(45)), rel=1e-12
    )
    back = pickle.loads(pickle.dumps(c))
    assert back.period == c.period and back.settle_error == c.settle_error
    assert repr(c).startswith("Gyrocompass(")
    with pytest.raises(ps.PoinsotError, match="^latitude: expected an angle, got 3 m$"):
        ps.Gyrocompass(3 * u.m)
    # Every argument converts once at the door by its dimension (_units.ARGUMENTS), the
    # simulation's start angles too: 10 degrees is 10 degrees, 3 metres is refused by name.
    deg = c.simulate(60.0, 10 * u.deg, tilt0=0.5 * u.deg, samples=3)
    rad = c.simulate(60.0, math.radians(10), tilt0=math.radians(0.5), samples=3)
    # pint's degree and math.radians may round differently in the last place (pint scales by
    # its own π/180): the starts agree to an ulp, the runs within the integration's tolerance.
    assert deg.heading[0] == pytest.approx(rad.heading[0], rel=1e-15, abs=0)
    np.testing.assert_allclose(deg.heading, rad.heading, rtol=1e-9, atol=0)
    with pytest.raises(ps.PoinsotError, match="^heading0: expected an angle"):
        c.simulate(60.0, 3 * u.m, samples=3)
    with pytest.raises(ps.PoinsotError, match="^turns: turn 0's speed: expected a speed, got 3 m$"):
        c.simulate(60.0, 0.0, turns=[(10.0, 3 * u.m, 0.0)], samples=3)


def test_the_compass_holds_the_earths_core_object():
    """The compass and the place take the Earth's core object itself (not its three numbers
    flattened and rebuilt): the core compass holds it, and an unusual Earth survives pickling
    and comes back as a poinsot.Earth equal in its numbers."""
    from poinsot import _core

    earth = ps.Earth(1e-4, 6.0e6, 9.5)
    c = ps.Gyrocompass(0.7, earth=earth)
    assert isinstance(c._core.args[5], _core.EarthCore)
    back = pickle.loads(pickle.dumps(c))
    for got in (c.earth, back.earth):
        assert isinstance(got, ps.Earth)
        assert (got.rotation_rate, got.radius, got.g) == (1e-4, 6.0e6, 9.5)
    assert back.period == c.period
    assert ps.Gyrocompass.schuler_period(earth) == pytest.approx(
        2 * math.pi * math.sqrt(6.0e6 / 9.5), rel=1e-14
    )
    place = ps.Place(0.7, earth)
    assert place == ps.Place(0.7, ps.Earth(1e-4, 6.0e6, 9.5)) and place != ps.Place(0.7)
    assert pickle.loads(pickle.dumps(place)) == place


def test_bad_input_refused_by_name():
    with pytest.raises(ps.PoinsotError, match="^latitude.*pole"):
        ps.Gyrocompass(math.pi / 2)
    with pytest.raises(ps.PoinsotError, match="^angular_momentum"):
        ps.Gyrocompass(0.5, 0.0)
    with pytest.raises(ps.PoinsotError, match="^angular_momentum"):
        ps.Gyrocompass(0.5, 5e-324)  # P/H beyond the doubles: refused, never an infinity
    with pytest.raises(ps.PoinsotError, match="^pendulosity"):
        ps.Gyrocompass(0.5, 40.0, -1.0)
    with pytest.raises(ps.PoinsotError, match="^damping"):
        ps.Gyrocompass(0.5, damping=1.0)
    c = ps.Gyrocompass(math.radians(60))
    with pytest.raises(ps.PoinsotError, match="^speed.*westward"):
        c.speed_error(c.ground_speed, -math.pi / 2)
    with pytest.raises(ps.PoinsotError, match="^speed"):
        c.speed_error(-1.0, 0.0)
    with pytest.raises(ps.PoinsotError, match="^heading0"):
        c.simulate(10.0, float("nan"))
    with pytest.raises(ps.PoinsotError, match="^duration"):
        c.simulate(-1.0, 0.0)


def test_cli_gyrocompass_json_and_refusal():
    import json

    from click.testing import CliRunner
    from poinsot.cli import main

    res = CliRunner().invoke(
        main, ["gyrocompass", "--latitude", "50deg", "--speed", "20kn", "--json"]
    )
    assert res.exit_code == 0, res.output
    data = json.loads(res.stdout)
    c = ps.Gyrocompass(math.radians(50))
    assert data["speed_error"] == pytest.approx(c.speed_error(20 * 1852 / 3600, 0.0), rel=1e-12)
    assert data["period"] == pytest.approx(c.period, rel=1e-12)
    assert data["settle_error"] == pytest.approx(c.settle_error, rel=1e-12)
    res = CliRunner().invoke(main, ["gyrocompass", "--latitude", "90deg"])
    assert res.exit_code == 1 and "latitude" in res.output
