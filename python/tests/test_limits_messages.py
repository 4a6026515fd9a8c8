"""Issue 21, items 2, 12 and 13: an overflow is refused naming the argument (never returned as
inf or as an angle from inf/inf), a short toss lands, and messages name the user's argument and
print extreme numbers in exponent form."""

from __future__ import annotations

import re
import warnings

import numpy as np
import poinsot as ps
import pytest
from click.testing import CliRunner
from poinsot.cli import main
from scipy.integrate import solve_ivp

LONG_NUMBER = re.compile(r"\d{18,}")


def test_effective_gravity_overflow_is_refused_naming_rotation_rate() -> None:
    # ω² R cos λ sin λ ≈ 2.7e308 at ω = 1e151: the old code returned [0, -inf, inf], a
    # magnitude inf and a deviation 3π/4 from inf/inf.
    earth = ps.Earth(rotation_rate=1e151)
    for name in (
        "effective_gravity",
        "centrifugal_acceleration",
        "effective_gravity_magnitude",
        "plumb_line_deviation",
    ):
        with pytest.raises(ps.PoinsotError, match=r"^rotation_rate: .*overflows"):
            getattr(earth, name)(0.5)


def test_effective_gravity_magnitude_is_finite_where_the_vector_is() -> None:
    # ω = 1e150: the vector is finite (2.7e306, 4.9e306); its magnitude was inf (the squares).
    earth = ps.Earth(rotation_rate=1e150)
    lat = 0.5
    g = earth.effective_gravity(lat)
    mag = earth.effective_gravity_magnitude(lat)
    # Closed form at unit scale (g = 9.8 is far below the last bit of 1e306).
    a = earth.radius * np.cos(lat)
    assert np.allclose(g / 1e300, [0.0, -a * np.sin(lat), a * np.cos(lat)], rtol=1e-15)
    assert np.isfinite(mag) and mag / 1e300 == pytest.approx(a, rel=1e-15)
    # g_e points up and south: its angle from the downward radial direction is π − λ.
    assert earth.plumb_line_deviation(lat) == pytest.approx(np.pi - lat, abs=1e-15)


def test_inertial_period_beyond_the_doubles_is_refused_naming_latitude() -> None:
    earth = ps.Earth()
    with pytest.raises(ps.PoinsotError, match=r"^latitude: .*overflows") as err:
        earth.inertial_period(1e-305)  # π/(ω sin λ) = 4.3e309; was inf
    assert not LONG_NUMBER.search(str(err.value))
    assert earth.inertial_period(0.0) == np.inf  # the documented infinity at the equator
    assert earth.inertial_period(1e-300) == pytest.approx(np.pi / (earth.rotation_rate * 1e-300))


def _toss_reference(
    earth: ps.Earth, speed: float, elev: float, az: float, lat: float
) -> tuple[float, np.ndarray]:
    """The time of flight and the landing point (east, north) from scipy: r̈ = −g ẑ − 2 ω × ṙ − ω × (ω × r), ω = Ω (0, cos λ, sin λ)
    (ENU), launched from the origin, until z returns to 0."""
    w = earth.rotation_rate * np.array([0.0, np.cos(lat), np.sin(lat)])
    v0 = speed * np.array([np.cos(elev) * np.sin(az), np.cos(elev) * np.cos(az), np.sin(elev)])

    def rhs(_t: float, y: np.ndarray) -> np.ndarray:
        r, v = y[:3], y[3:]
        acc = np.array([0.0, 0.0, -earth.g]) - 2 * np.cross(w, v) - np.cross(w, np.cross(w, r))
        return np.concatenate([v, acc])

    def ground(t: float, y: np.ndarray) -> float:
        return float(y[2]) if t > 0 else 1.0

    ground.terminal = True  # type: ignore[attr-defined]
    ground.direction = -1  # type: ignore[attr-defined]
    t_flat = 2 * v0[2] / earth.g
    sol = solve_ivp(
        rhs,
        (0, 2 * t_flat),
        np.concatenate([np.zeros(3), v0]),
        events=ground,
        rtol=1e-12,
        atol=1e-16,
        max_step=t_flat / 50,
    )
    return float(sol.t_events[0][0]), sol.y_events[0][0][:2]


@pytest.mark.parametrize(("speed", "elevation"), [(0.15, 0.5), (100.0, 1e-6)])
def test_a_short_toss_lands_as_scipy_integrates_it(speed: float, elevation: float) -> None:
    # Refused before as "speed: ... (is 0.15 m/s an orbital speed?)": a flight of 0.015 s or
    # 2e-5 s fitted inside the integrator's first step.
    earth = ps.Earth()
    flight = earth.projectile(speed, elevation, 0.3, 0.5)
    t_ref, landing = _toss_reference(earth, speed, elevation, 0.3, 0.5)
    assert flight.time == pytest.approx(t_ref, rel=1e-9)
    assert np.allclose([flight.east, flight.north], landing, rtol=1e-8, atol=0)
    # And the flat closed form, to the Coriolis (Eötvös) shift: 2 ω cos λ v_east / g, 4e-4
    # relative at 100 m/s.
    flat = speed**2 * np.sin(2 * elevation) / earth.g
    assert flight.range == pytest.approx(flat, rel=1e-3)


def test_a_toss_too_low_for_doubles_names_elevation() -> None:
    with pytest.raises(ps.PoinsotError, match=r"^elevation: the toss is too low") as err:
        ps.Earth().projectile(1.0, 1e-200, 0.0, 0.5)
    assert "orbital" not in str(err.value)


def test_momentum_error_is_finite_for_moments_of_1e308() -> None:
    moments, omega = [1e308, 1.2e308, 1.5e308], [0.5, 0.05, 0.5]
    tr = ps.simulate(moments, omega, 1.0, method="rk4", dt=0.01)
    err = tr.momentum_error()  # was NaN: the norm squared 1e616
    # The same run at unit moments (ω's equations depend on ratios of moments only).
    ref = ps.simulate([1.0, 1.2, 1.5], omega, 1.0, method="rk4", dt=0.01).momentum_error()
    assert np.all(np.isfinite(err)) and np.max(err) < 1e-13
    assert np.allclose(err, ref, atol=1e-14)
    # Negative control: the plain norm overflows on these momenta.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        assert not np.all(np.isfinite(np.linalg.norm(tr.angular_momentum, axis=1)))


def test_cli_free_runs_moments_of_1e308_without_runtime_warnings() -> None:
    # pytest turns RuntimeWarning into errors (pyproject): the old run printed three of them
    # and then refused the run it had computed.
    result = CliRunner().invoke(
        main,
        [
            "free",
            "--moments",
            "1e308",
            "1.2e308",
            "1.5e308",
            "--omega",
            "0.5",
            "0.05",
            "0.5",
            "--duration",
            "1",
            "--method",
            "rk4",
            "--dt",
            "0.01",
            "--json",
        ],
    )
    assert result.exit_code == 0, result.output
    assert "max_momentum_error" in result.stdout


def test_moving_frame_at_a_time_that_overflows_names_t() -> None:
    frame = ps.MovingFrame(acceleration=[0, 0, 1.0])
    with pytest.raises(ps.PoinsotError, match=r"^t: "):
        frame.at(1e200)  # was "origin: must be finite, got inf"
    assert frame.at(1e100).origin[2] == 0.5e200  # negative control


def test_from_inertia_about_a_far_point_names_about() -> None:
    with pytest.raises(ps.PoinsotError, match=r"^about: "):
        ps.RigidBody.from_inertia(1.0, np.eye(3), [0, 0, 0], about=[1e155, 0, 0])
    with pytest.raises(ps.PoinsotError, match=r"^point: "):
        ps.RigidBody.solid_sphere(1.0, 1.0).inertia_about([1e155, 0, 0])


@pytest.mark.parametrize(
    ("call", "short"),
    [
        (lambda: ps.HeavyTop(1e-308, 0.5, 1, 0.5), "2e-308"),
        (lambda: ps.HeavyTop(1e-300, 1e300, 1, 0.5), "2e-300"),
        (lambda: ps.Earth().projectile(1.0, 1e-200, 0.0, 0.5), "1e-200"),
        (lambda: ps.Earth(rotation_rate=1e151).effective_gravity(0.5), "1e151"),
        (lambda: ps.FreeSymmetricTop(1e-308, 1.0, [0.1, 0, 1.0]), None),
    ],
)
def test_messages_print_extreme_numbers_in_exponent_form(call: object, short: str | None) -> None:
    with pytest.raises(ps.PoinsotError) as err:
        call()  # type: ignore[operator]
    msg = str(err.value)
    assert not LONG_NUMBER.search(msg), msg
    if short is not None:
        assert short in msg, msg
