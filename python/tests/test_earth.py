"""Tests of poinsot.Earth (the unit's eqs. 2.29–2.42): conventions, the unit's worked numbers,
hemisphere signs, limits, and exact integrations against independent references (scipy's
matrix exponential of the linear drop equations, closed-form ballistics)."""

from __future__ import annotations

import numpy as np
import poinsot as ps
import pytest
from scipy.linalg import expm

#: The unit prints 2–3 significant figures; relative tolerance for comparing with them.
UNIT_DIGITS = 5e-3


def test_convention_enu_omega_direction() -> None:
    """ENU: x east, y north, z up; ω = ω (0, cos λ, sin λ) — north at the equator, up at the
    north pole, down at the south pole."""
    e = ps.Earth()
    w = e.rotation_rate
    np.testing.assert_allclose(
        e.omega_enu(30, degrees=True), w * np.array([0, np.cos(np.pi / 6), 0.5]), rtol=1e-15
    )
    np.testing.assert_allclose(e.omega_enu(0.0), [0, w, 0], atol=1e-25)
    np.testing.assert_allclose(e.omega_enu(np.pi / 2), [0, 0, w], atol=1e-20)
    np.testing.assert_allclose(e.omega_enu(-np.pi / 2), [0, 0, -w], atol=1e-20)


def test_convention_sidereal_rate_by_default() -> None:
    assert ps.Earth().rotation_rate == 7.2921150e-5 == ps.SIDEREAL_RATE
    assert (
        ps.Earth("solar").rotation_rate == ps.Earth.solar_day().rotation_rate == 2 * np.pi / 86400
    )
    assert ps.Earth().g == 9.80665 and ps.Earth().radius == 6.371e6


def test_convention_latitude_north_positive() -> None:
    """Latitude is north-positive: the Foucault plane turns clockwise (negative rate) at +45°."""
    e = ps.Earth()
    assert e.foucault_rate(45, degrees=True) < 0 < e.foucault_rate(-45, degrees=True)
    assert e.coriolis_parameter(45, degrees=True) > 0


def test_the_units_numbers_with_the_solar_day() -> None:
    """The unit's 7.25e-5 (errata: 2π/86400 = 7.27e-5), ω²r = 3.4e-2 with r = 6.4e6 m,
    2ω = 1.5e-4 (1.45e-4), and 1.55e-2 m for 100 m at 45° (g = 9.81)."""
    e = ps.Earth.solar_day(radius=6.4e6, g=9.81)
    assert f"{e.rotation_rate:.2e}" == "7.27e-05"
    c = np.linalg.norm(e.centrifugal_acceleration(0.0))
    assert abs(c / 3.38e-2 - 1) < UNIT_DIGITS and f"{c:.1e}" == "3.4e-02"
    assert abs(e.coriolis_parameter(90, degrees=True) / 1.45e-4 - 1) < UNIT_DIGITS
    x = e.eastward_deflection(100, 45, degrees=True)
    assert f"{x:.2e}" == "1.55e-02" and abs(x / 1.548e-2 - 1) < 1e-3


def test_the_units_numbers_with_the_sidereal_rate() -> None:
    e = ps.Earth(radius=6.4e6)
    assert abs(e.rotation_rate / 7.2921e-5 - 1) < 1e-5
    assert abs(np.linalg.norm(e.centrifugal_acceleration(0.0)) / 3.40e-2 - 1) < 2e-3
    assert abs(e.coriolis_parameter(np.pi / 2) / 1.458e-4 - 1) < 1e-3
    assert abs(ps.Earth().eastward_deflection(100, 45, degrees=True) / 1.552e-2 - 1) < 1e-3
    fall = ps.Earth().drop(100, 45, degrees=True)
    assert abs(fall.east / 1.552e-2 - 1) < 1e-3


def test_effective_gravity_vector_magnitude_and_plumb_line() -> None:
    e = ps.Earth()
    w2r = e.rotation_rate**2 * e.radius
    lat = np.radians([-90, -45, 0, 45, 90])
    g = e.effective_gravity(lat)
    assert g.shape == (5, 3)
    # Eq. 2.31 by hand: g_e = −g ẑ + ω² R cos λ (0, −sin λ, cos λ).
    expect = np.stack(
        [np.zeros(5), -w2r * np.cos(lat) * np.sin(lat), -e.g + w2r * np.cos(lat) ** 2], axis=1
    )
    np.testing.assert_allclose(g, expect, atol=1e-15)
    mag = e.effective_gravity_magnitude(lat)
    np.testing.assert_allclose(mag, np.linalg.norm(expect, axis=1), rtol=1e-15)
    assert mag[2] == pytest.approx(e.g - w2r) and mag[4] == pytest.approx(e.g)
    dev = e.plumb_line_deviation([45, -45, 0], degrees=True)
    assert dev[0] > 0 > dev[1] and dev[2] == 0 and abs(dev[0] - 0.0995) < 2e-3


def test_coriolis_hemispheres_and_equator() -> None:
    """Deflected to the right in the north, to the left in the south, not at all horizontally
    at the equator (the unit after eq. 2.31)."""
    e = ps.Earth()
    v = np.array([[10.0, 0, 0], [0, 10.0, 0], [-10.0, 0, 0], [0, -10.0, 0]])
    for lat, side in ((45, 1), (-45, -1)):
        a = e.coriolis_acceleration(lat, v, degrees=True)
        # right of v = (vx, vy) is (vy, −vx): the horizontal part points that way in the north.
        right = np.stack([v[:, 1], -v[:, 0]], axis=1)
        assert np.all(side * np.sum(a[:, :2] * right, axis=1) > 0)
    a0 = e.coriolis_acceleration(0.0, v)
    np.testing.assert_allclose(a0[:, :2], 0, atol=1e-20)
    # Broadcasting latitude (3,) against one velocity.
    assert e.coriolis_acceleration([0, 10, 20], [1.0, 0, 0], degrees=True).shape == (3, 3)


def _linear_drop_reference(e: ps.Earth, lat: float, h: float, times: np.ndarray) -> np.ndarray:
    """The uniform-gravity drop r̈ = −g ẑ − 2ω×ṙ − ω×(ω×r) is linear: solve it exactly with the
    matrix exponential of the augmented 7×7 system (scipy)."""
    w = e.omega_enu(lat)
    W = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
    M = np.zeros((7, 7))
    M[0:3, 3:6] = np.eye(3)
    M[3:6, 0:3] = -W @ W
    M[3:6, 3:6] = -2 * W
    M[5, 6] = -e.g
    y0 = np.array([0, 0, h, 0, 0, 0, 1.0])
    return np.array([expm(M * t) @ y0 for t in times])[:, :6]


def test_drop_matches_the_exact_linear_solution() -> None:
    e = ps.Earth(rotation_rate=2e-3)  # a fast planet makes every term visible
    lat = np.radians(35.0)
    fall = e.drop(500.0, lat)
    ref = _linear_drop_reference(e, lat, 500.0, fall.t)
    got = np.hstack([fall.position, fall.velocity])
    np.testing.assert_allclose(got, ref, rtol=0, atol=1e-9 * 500)
    assert fall.position[-1, 2] == pytest.approx(0.0, abs=1e-9)
    assert fall.east > 0 and fall.north < 0


def test_drop_exact_tends_to_first_order_as_height_falls() -> None:
    e = ps.Earth()
    diffs = []
    for h in (1e4, 1e3, 1e2, 1e1):
        fall = e.drop(h, 45, degrees=True)
        diffs.append(abs(fall.east / fall.first_order_east - 1))
        assert abs(-fall.north / fall.second_order_south - 1) < 1e-3
    assert all(a > b for a, b in zip(diffs, diffs[1:])), diffs
    assert diffs[-1] < 1e-7


def test_drop_hemispheres_equator_poles_and_options() -> None:
    e = ps.Earth()
    n, s = e.drop(200, 40, degrees=True), e.drop(200, -40, degrees=True)
    assert n.east > 0 and s.east > 0 and n.north < 0 < s.north
    q, p = e.drop(200, 0.0), e.drop(200, 90, degrees=True)
    assert q.east > n.east and abs(q.north) < 1e-12
    assert abs(p.east) < 1e-12 and abs(p.north) < 1e-12
    still = e.drop(200, 40, degrees=True, rotation=False)
    assert abs(still.east) < 1e-14 and still.time == pytest.approx(np.sqrt(400 / e.g), rel=1e-12)
    high = e.drop(1e4, 40, degrees=True, gravity="inverse-square")
    assert high.time > e.drop(1e4, 40, degrees=True).time
    # Without the centrifugal variation the south deflection is the Coriolis third: (1/3)/(3/4).
    no_cf = e.drop(1e3, 40, degrees=True, centrifugal=False)
    full = e.drop(1e3, 40, degrees=True)
    assert no_cf.north / full.north == pytest.approx(4 / 9, rel=1e-3)


def test_projectile_range_drift_and_hemispheres() -> None:
    e = ps.Earth()
    v, el = 300.0, 45.0
    still = e.projectile(v, el, 30, 45, degrees=True, rotation=False)
    assert still.range == pytest.approx(v * v / e.g, rel=1e-10)
    assert abs(still.drift) < 1e-8 and still.time == pytest.approx(
        2 * v * np.sin(np.pi / 4) / e.g, rel=1e-10
    )
    for az in (0, 90, 180, 270):
        n = e.projectile(v, el, az, 45, degrees=True)
        s = e.projectile(v, el, az, -45, degrees=True)
        assert n.drift > 0 > s.drift, az
    # From a height, shooting horizontally works; refuse downward shots from the ground.
    assert e.projectile(100, 0, 0, 45, degrees=True, height=50).time > 0
    with pytest.raises(ps.PoinsotError, match="elevation"):
        e.projectile(100, -10, 0, 45, degrees=True)


def test_foucault_plane_turns_at_omega_sin_latitude() -> None:
    e = ps.Earth()
    run = e.foucault(45, degrees=True, duration=3600, samples=11)
    assert run.precession_rate == pytest.approx(-e.rotation_rate * np.sin(np.pi / 4), rel=2e-3)
    assert run.expected_rate == pytest.approx(-e.rotation_rate * np.sin(np.pi / 4), rel=1e-14)
    assert run.sense == "clockwise"
    south = e.foucault(-45, degrees=True, duration=3600, samples=11)
    assert south.sense == "counterclockwise"
    pole = e.foucault(90, degrees=True, duration=3600, samples=11)
    assert pole.precession_rate == pytest.approx(-e.rotation_rate, rel=2e-3)
    eq = e.foucault(0.0, duration=1800, samples=11)
    assert eq.sense == "none" and abs(eq.precession_rate) < 1e-3 * e.rotation_rate
    r = np.linalg.norm(run.position, axis=1)
    np.testing.assert_allclose(r, 67.0, rtol=1e-9)


def test_inertial_oscillation_and_the_low() -> None:
    e = ps.Earth()
    n = e.inertial_oscillation(45, [10.0, 0.0], degrees=True)
    assert n.sense == "clockwise" and n.turning_rate == pytest.approx(
        -e.coriolis_parameter(45, degrees=True), rel=1e-9
    )
    assert n.period == pytest.approx(np.pi / (e.rotation_rate * np.sin(np.pi / 4)), rel=1e-14)
    # After two periods it is back where it started.
    assert np.hypot(*n.position[-1]) < 1e-6 * np.hypot(*n.position.T).max()
    assert e.inertial_oscillation(-45, degrees=True).sense == "counterclockwise"
    eq = e.inertial_oscillation(0.0, [3.0, 4.0])
    assert eq.sense == "none" and np.isinf(eq.period)
    assert e.flow_into_low(45, degrees=True).sense == "counterclockwise"
    assert e.flow_into_low(-45, degrees=True).sense == "clockwise"
    assert e.flow_into_low(0.0).sense == "none"


@pytest.mark.parametrize(
    "call, name",
    [
        (lambda e: e.omega_enu(91, degrees=True), "latitude"),
        (lambda e: e.omega_enu(-1.6), "latitude"),
        (lambda e: e.effective_gravity(np.nan), "latitude"),
        (lambda e: e.eastward_deflection(-1.0, 0.3), "height"),
        (lambda e: e.drop(-5.0, 0.3), "height"),
        (lambda e: e.drop(np.inf, 0.3), "height"),
        (lambda e: e.drop(10.0, 100, degrees=True), "latitude"),
        (lambda e: e.drop(10.0, 0.3, rtol=0.0), "rtol"),
        (lambda e: e.drop(10.0, 0.3, atol=-1.0), "atol"),
        (lambda e: e.drop(10.0, 0.3, gravity="flat"), "gravity"),
        (lambda e: e.projectile(0.0, 0.5, 0.0, 0.3), "speed"),
        (lambda e: e.foucault(0.5, amplitude=100.0), "amplitude"),
        (lambda e: e.foucault(0.5, rtol=-1.0), "rtol"),
        (lambda e: e.coriolis_acceleration(0.5, [1.0, 2.0]), "velocity_enu"),
        (lambda e: ps.Earth(rotation_rate=-1.0), "rotation_rate"),
        (lambda e: ps.Earth(g=0.0), "g"),
        (lambda e: ps.Earth(rotation_rate="lunar"), "rotation_rate"),
    ],
)
def test_bad_input_names_the_argument(call, name) -> None:
    with pytest.raises(ps.PoinsotError, match=name) as info:
        call(ps.Earth())
    assert isinstance(info.value, ValueError)


def test_fall_time_is_the_units_2_41() -> None:
    """t = √(2h/g) (2.41), checked by hand; and the exact fall lands within 1e-6 of it
    (rotation changes the time only at second order)."""
    import math

    earth = ps.Earth()
    assert earth.fall_time(100.0) == pytest.approx(math.sqrt(2 * 100.0 / 9.80665), rel=1e-15)
    assert earth.drop(100.0, 45, degrees=True).time == pytest.approx(
        earth.fall_time(100.0), rel=1e-6
    )
    with pytest.raises(ps.PoinsotError, match="^height:"):
        earth.fall_time(-1.0)


class _Counting:
    """A stand-in for an Earth's core object that records which of its methods are called."""

    def __init__(self, inner: object) -> None:
        self.inner, self.calls = inner, []

    def __getattr__(self, name: str) -> object:
        self.calls.append(name)
        return getattr(self.inner, name)


def test_drop_is_one_call_into_the_core_with_its_closed_forms() -> None:
    """Issue 22: ``Earth.drop`` asks the core once (it made three calls, the drop and the two
    closed forms), and the closed forms it brings are the core's 2.42 and second order."""
    e = ps.Earth()
    e._core = _Counting(e._core)  # type: ignore[assignment]
    fall = e.drop(100.0, 0.7, samples=5)
    assert e._core.calls == ["drop"]  # type: ignore[attr-defined]
    assert fall.first_order_east == ps.Earth().eastward_deflection(100.0, 0.7)
    assert fall.second_order_south == ps.Earth().southward_deflection(100.0, 0.7)
    assert fall.position.shape == fall.velocity.shape == (5, 3)
    assert fall.t[-1] == fall.time and np.array_equal(
        fall.position[-1, :2], [fall.east, fall.north]
    )


def test_the_earth_is_the_cores_object_and_pickles_through_it() -> None:
    """``poinsot.Earth`` holds the core's checked Earth (no re-validation by a discarded call);
    the core's object and the fall model pickle by their arguments (a sweep sends them to
    workers)."""
    import pickle

    from poinsot import _core

    e = ps.Earth.solar_day(radius=6.0e6)
    assert isinstance(e._core, _core.EarthCore)
    c = pickle.loads(pickle.dumps(e._core))
    assert (c.rotation_rate, c.radius, c.g) == (ps.SOLAR_DAY_RATE, 6.0e6, 9.80665)
    m = _core.FallModel("inverse-square", True, False, 1e-10, 1e-11, 1000)
    m2 = pickle.loads(pickle.dumps(m))
    got = (m2.gravity, m2.rotation, m2.centrifugal, m2.rtol, m2.atol, m2.max_steps)
    assert got == ("inverse-square", True, False, 1e-10, 1e-11, 1000)
    with pytest.raises(ps.PoinsotError, match="^radius"):
        _core.EarthCore(1e-5, -1.0, 9.8)


def test_a_fall_time_beyond_doubles_is_refused_naming_the_height() -> None:
    """The core returns finite numbers or refuses: √(2h/g) for h = 1e300 m and g = 1e-300 m/s²
    overflows (it was returned as inf)."""
    with pytest.raises(ps.PoinsotError, match="^height"):
        ps.Earth(g=1e-300).fall_time(1e300)
