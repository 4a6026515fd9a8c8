"""Units at the door (issue 23, item 5): pint quantities accepted by the public API, converted
once to SI where arguments enter (``poinsot._units``, hooked in ``_validate.as_float_array``);
the CLI's unit suffixes read without pint (``_units.SUFFIXES``); ``HeavyTop.from_body``.

Every conversion is checked against pint's own; negative controls: a quantity of the wrong
dimension is refused naming the argument, a plain float keeps its meaning (SI, radians)."""

from __future__ import annotations

import json
import math
import pickle
import subprocess
import sys

import numpy as np
import poinsot as ps
import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st
from poinsot import _units
from poinsot.cli import main

pint = pytest.importorskip("pint")
ureg = pint.UnitRegistry()
Q = ureg.Quantity

#: Units of each dimension, as pint spells them, for the property tests.
UNITS = {
    "length": ["m", "cm", "mm", "km", "inch", "ft", "mile"],
    "mass": ["kg", "g", "lb", "tonne"],
    "angle": ["rad", "deg", "arcmin", "turn", "grade"],
    "angular rate": ["rad/s", "rpm", "deg/s", "revolution/hour"],
    "time": ["s", "min", "h", "day", "ms"],
    "speed": ["m/s", "km/h", "knot", "mph"],
}

values = st.floats(min_value=-1e6, max_value=1e6, allow_nan=False, allow_infinity=False)


# ---- the Python API ------------------------------------------------------------------------


@settings(max_examples=60, deadline=None)
@given(x=values, dim=st.sampled_from(sorted(UNITS)), data=st.data())
def test_a_quantity_is_its_si_value_by_pints_own_conversion(x: float, dim: str, data) -> None:
    unit = data.draw(st.sampled_from(UNITS[dim]))
    name = {"length": "radius", "mass": "mass", "angle": "theta", "angular rate": "omega3",
            "time": "duration", "speed": "speed"}[dim]  # fmt: skip
    want = Q(x, unit).to(_units.DIMENSIONS[dim][1]).magnitude
    assert _units.to_si(Q(x, unit), name) == want
    # The same number reaches the core as the SI float would.
    assert ps._validate.as_scalar(Q(x, unit), name) == float(want)


@settings(max_examples=40, deadline=None)
@given(
    m=st.floats(min_value=1e-3, max_value=1e3),
    r=st.floats(min_value=1e-3, max_value=1e3),
    mass_unit=st.sampled_from(UNITS["mass"]),
    length_unit=st.sampled_from(UNITS["length"]),
)
def test_bodies_from_quantities_equal_bodies_from_si_floats(
    m: float, r: float, mass_unit: str, length_unit: str
) -> None:
    got = ps.RigidBody.solid_cylinder(Q(m, mass_unit), Q(r, length_unit), Q(2 * r, length_unit))
    kg, metres = Q(m, mass_unit).to("kg").magnitude, Q(r, length_unit).to("m").magnitude
    want = ps.RigidBody.solid_cylinder(kg, metres, Q(2 * r, length_unit).to("m").magnitude)
    assert np.array_equal(got.inertia, want.inertia) and got.mass == want.mass


def test_arrays_angles_and_rates_through_the_api() -> None:
    earth = ps.Earth()
    # Arrays of quantities: (N,) latitudes in degrees, heights in km.
    got = earth.eastward_deflection(Q([0.1, 0.2], "km"), Q([45.0, 60.0], "deg"))
    want = earth.eastward_deflection([100.0, 200.0], np.radians([45.0, 60.0]))
    assert np.allclose(got, want, rtol=1e-15, atol=0)
    # A vector quantity: ENU velocity in km/h.
    a = earth.coriolis_acceleration(Q(50, "deg"), Q([36.0, 0.0, 0.0], "km/h"))
    assert np.allclose(a, earth.coriolis_acceleration(np.radians(50), [10.0, 0.0, 0.0]))
    # Rates: 1500 rpm is 50 pi rad/s.
    top = ps.HeavyTop(1.0, 0.5, 1.0, Q(30, "deg"), psi_dot=Q(1500, "rpm"))
    assert top.initial_state["psi_dot"] == pytest.approx(50 * math.pi, rel=1e-15)
    assert top.initial_state["theta"] == pytest.approx(math.pi / 6, rel=1e-15)
    # Moments and m g l with their units (g·cm² is 1e-7 kg·m²).
    small = ps.HeavyTop(Q(1e7, "g*cm**2"), Q(0.5, "kg*m**2"), Q(1, "N*m"), 0.8, psi_dot=6.0)
    assert pytest.approx(1.0, rel=1e-15) == small.I1


def test_a_quantity_with_degrees_true_is_read_in_its_own_unit() -> None:
    """``degrees=True`` converts plain numbers; a quantity carries its unit and is not
    converted twice (the negative control: the plain number 30 with degrees=True is 30°)."""
    plain = ps.HeavyTop(1.0, 0.5, 1.0, 30.0, psi_dot=360.0, degrees=True).initial_state
    for flag in (False, True):
        q = ps.HeavyTop(1.0, 0.5, 1.0, Q(30, "deg"), psi_dot=Q(1, "turn/s"), degrees=flag)
        assert q.initial_state["theta"] == pytest.approx(plain["theta"], rel=1e-15)
        assert q.initial_state["psi_dot"] == pytest.approx(plain["psi_dot"], rel=1e-15)
        R = ps.euler_to_matrix(Q([90, 0, 0], "deg"), degrees=flag)
        assert np.allclose(R, ps.euler_to_matrix([90, 0, 0], degrees=True))
        lat = ps.Earth().eastward_deflection(100.0, Q(45, "deg"), degrees=flag)
        assert lat == ps.Earth().eastward_deflection(100.0, 45.0, degrees=True)


def test_a_plain_float_keeps_its_meaning() -> None:
    """Negative control: floats are SI and radians, unchanged by the units layer."""
    assert ps.Earth().eastward_deflection(100.0, 0.7) == ps.Earth().eastward_deflection(
        Q(100.0, "m"), Q(0.7, "rad")
    )
    assert ps._validate.as_scalar(2.5, "radius") == 2.5
    assert ps._validate.as_angle(30.0, "theta") == 30.0  # 30 rad, not 30°


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (
            lambda: ps.Earth().eastward_deflection(100.0, Q(3, "m")),
            "latitude: expected an angle, got 3 m",
        ),
        (lambda: ps.RigidBody.thin_disk(Q(1, "m"), 1.0), "mass: expected a mass, got 1 m"),
        (lambda: ps.RigidBody.thin_disk(1.0, Q(2, "s")), "radius: expected a length, got 2 s"),
        (
            lambda: ps.HeavyTop(1.0, 0.5, 1.0, 0.5, psi_dot=Q(3, "m/s")),
            "psi_dot: expected an angular rate, got 3 m/s",
        ),
        (lambda: ps.HeavyTop(Q(1, "kg"), 0.5, 1.0, 0.5), "I1: expected a moment of inertia"),
    ],
)
def test_a_quantity_of_the_wrong_dimension_is_refused_naming_the_argument(call, message) -> None:
    with pytest.raises(ps.PoinsotError) as info:
        call()
    assert message in str(info.value)
    assert isinstance(info.value, ValueError)


def test_hertz_counts_turns_for_an_angular_rate() -> None:
    """The one departure from pint, which converts 1 Hz to 1 rad/s: a spin of 25 Hz is 25
    turns per second, 50 pi rad/s (the same as 25 rev/s and 1500 rpm)."""
    assert Q(1, "Hz").to("rad/s").magnitude == 1.0  # pint's own reading
    got = _units.to_si(Q(25, "Hz"), "omega3")
    assert got == pytest.approx(Q(25, "revolution/s").to("rad/s").magnitude, rel=1e-15)
    assert got == pytest.approx(Q(1500, "rpm").to("rad/s").magnitude, rel=1e-15)
    assert _units.to_si(Q(2, "Hz"), "friction") == 2.0  # a rate that is no turning: 1/s


def test_every_argument_has_one_dimension_and_the_table_names_known_dimensions() -> None:
    for name, dims in _units.ARGUMENTS.items():
        assert dims and all(d in _units.DIMENSIONS for d in dims), name
    for _, si, _ in _units.DIMENSIONS.values():
        ureg.Unit(si)  # pint reads every SI unit of the table


def test_import_poinsot_does_not_import_pint() -> None:
    code = "import sys, poinsot; print('pint' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"


# ---- HeavyTop.from_body --------------------------------------------------------------------


def test_from_body_is_the_disk_on_its_pivot_by_hand() -> None:
    """The lead's example: a 0.2 kg disk of radius 5 cm, 10 cm from its pivot, 1500 rpm, tilted
    30°. By hand: I1 = m r²/4 + m d² = 2.125e-3 kg·m², I3 = m r²/2 = 2.5e-4 kg·m², m g l =
    0.196133 N·m, and the slow steady precession of 2.116 by the quadratic formula."""
    m, r, d, g = 0.2, 0.05, 0.1, 9.80665
    disk = ps.RigidBody.thin_disk(m, r)
    top = ps.HeavyTop.from_body(disk, d, math.radians(30), 1500 * 2 * math.pi / 60)
    assert pytest.approx(m * r**2 / 4 + m * d**2, rel=1e-15) == top.I1
    assert pytest.approx(m * r**2 / 2, rel=1e-15) == top.I3
    assert top.mgl == pytest.approx(m * g * d, rel=1e-15)
    p = top.p_psi
    a = top.I1 * math.cos(math.radians(30))
    slow = (p - math.sqrt(p * p - 4 * a * top.mgl)) / (2 * a)
    s = ps.HeavyTop.steady_precession(top.I1, top.I3, top.mgl, math.radians(30), top.omega3)
    assert s.slow == pytest.approx(slow, rel=1e-12) and 7.97 < slow < 7.98
    # Not a fast top: 1500 rpm is only 3.3 % above the least spin 2.119 at 30°, so the slow rate
    # is far from the fast-top value m g l / p_psi = 4.99 rad/s.
    least = 2 / top.I3 * math.sqrt(top.mgl * top.I1 * math.cos(math.radians(30)))
    assert s.min_spin == pytest.approx(least, rel=1e-14)
    assert top.omega3 / least == pytest.approx(1.0335, abs=1e-4)
    # The same top from quantities, and from degrees.
    q = ps.HeavyTop.from_body(
        ps.RigidBody.thin_disk(Q(200, "g"), Q(5, "cm")), Q(10, "cm"), Q(30, "deg"), Q(1500, "rpm")
    )
    assert (q.I1, q.I3, q.mgl) == pytest.approx((top.I1, top.I3, top.mgl), rel=1e-15)
    deg = ps.HeavyTop.from_body(disk, d, 30.0, 9000.0, degrees=True)
    assert deg.omega3 == pytest.approx(top.omega3, rel=1e-15)
    # It pickles as the top of its moments.
    again = pickle.loads(pickle.dumps(top))
    assert again.euler_angles(0.7) == top.euler_angles(0.7)


def test_from_body_refuses_an_asymmetric_body_naming_body() -> None:
    box = ps.RigidBody.cuboid(1.0, (0.1, 0.2, 0.3))
    with pytest.raises(ps.PoinsotError, match="^body: must be symmetric"):
        ps.HeavyTop.from_body(box, 0.1, 0.5, 10.0)
    tipped = ps.RigidBody.thin_disk(1.0, 1.0).rotated(ps.axis_angle_to_matrix([1, 0, 0], 0.3))
    with pytest.raises(ps.PoinsotError, match="^body: its axis 3"):
        ps.HeavyTop.from_body(tipped, 0.1, 0.5, 10.0)
    with pytest.raises(ps.PoinsotError, match="^pivot_distance"):
        ps.HeavyTop.from_body(ps.RigidBody.thin_disk(1.0, 1.0), -0.1, 0.5, 10.0)
    with pytest.raises(ps.ArgumentTypeError, match="^body"):
        ps.HeavyTop.from_body("disk", 0.1, 0.5, 10.0)  # type: ignore[arg-type]


# ---- the CLI -------------------------------------------------------------------------------


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(main, list(args))
    return result.exit_code, result.stdout, result.stderr


@pytest.mark.parametrize("suffix", sorted(_units.SUFFIXES))
def test_every_suffix_of_the_table_is_pints_conversion(suffix: str) -> None:
    dim, _ = _units.SUFFIXES[suffix]
    unit = _units.PINT_NAMES.get(suffix, suffix)
    want = Q(2.5, unit).to(_units.DIMENSIONS[dim][1]).magnitude
    assert _units.parse(f"2.5{suffix}", dim) == (pytest.approx(want, rel=1e-15), True)


def test_the_common_suffixes_need_no_pint(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "pint", None)  # import pint now fails
    assert _units.parse("158.5m", "length") == (158.5, True)
    assert _units.parse("1500rpm", "angular rate")[0] == pytest.approx(50 * math.pi, rel=1e-15)
    assert _units.parse("50d53m", "angle")[0] == pytest.approx(
        math.radians(50 + 53 / 60), rel=1e-15
    )
    assert _units.parse("12kn", "speed")[0] == pytest.approx(12 * 1852 / 3600, rel=1e-15)
    assert _units.parse("0.2", "mass") == (0.2, False)
    with pytest.raises(ValueError, match="expected an angle, got 3 m"):
        _units.parse("3m", "angle")
    with pytest.raises(ValueError, match="pip install pint"):
        _units.parse("3furlong", "length")


def test_top_from_a_real_disk_on_the_command_line() -> None:
    code, out, err = run(
        "top", "--shape", "disk", "--mass", "0.2", "--radius", "5cm", "--pivot", "10cm",
        "--spin", "1500rpm", "--tilt", "30deg", "--json",
    )  # fmt: skip
    assert code == 0, err
    data = json.loads(out)
    top = ps.HeavyTop.from_body(
        ps.RigidBody.thin_disk(0.2, 0.05), 0.1, math.radians(30), 50 * math.pi
    )
    assert (data["I1"], data["I3"], data["mgl"]) == (top.I1, top.I3, top.mgl)
    assert data["omega3"] == pytest.approx(50 * math.pi, rel=1e-15)
    assert data["initial_state"]["theta"] == pytest.approx(math.pi / 6, rel=1e-15)
    assert data["body"] == {"shape": "disk", "mass": 0.2, "radius": 0.05, "pivot_distance": 0.1}
    # The same in plain SI numbers, and in degrees with --degrees (the spin then in deg/s).
    plain = run(
        "top", "--shape", "disk", "--mass", "0.2", "--radius", "0.05", "--pivot", "0.1",
        "--spin", str(50 * math.pi), "--theta", str(math.pi / 6), "--json",
    )  # fmt: skip
    assert json.loads(plain[1])["I1"] == data["I1"]
    degrees = run(
        "top", "--shape", "disk", "--mass", "200g", "--radius", "5cm", "--pivot", "10cm",
        "--spin", "9000", "--tilt", "30", "--degrees", "--json",
    )  # fmt: skip
    assert json.loads(degrees[1])["omega3"] == pytest.approx(50 * math.pi, rel=1e-15)
    # A unit with --degrees is read in its own unit.
    mixed = run(
        "top", "--shape", "disk", "--mass", "0.2", "--radius", "5cm", "--pivot", "10cm",
        "--spin", "1500rpm", "--tilt", "30deg", "--degrees", "--json",
    )  # fmt: skip
    assert json.loads(mixed[1])["initial_state"]["theta"] == pytest.approx(math.pi / 6)
    assert json.loads(mixed[1])["omega3"] == pytest.approx(50 * math.pi, rel=1e-15)


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        (["top", "--shape", "disk", "--mass", "0.2", "--radius", "5cm", "--tilt", "30deg"],
         "--shape disk needs --pivot"),
        (["top", "--I1", "1", "--I3", "0.5", "--theta", "0.5"], "missing --mgl"),
        (["top", "--I1", "1", "--I3", "0.5", "--mgl", "1", "--theta", "0.5", "--mass", "1"],
         "--mass go with --shape"),
        (["top", "--I1", "1", "--I3", "0.5", "--mgl", "1", "--theta", "30m"],
         "--theta: expected an angle, got 30 m"),
        (["fall", "--height", "100", "--latitude", "3m"], "--latitude: expected an angle, got 3 m"),
    ],
)  # fmt: skip
def test_options_that_do_not_fit_are_usage_errors(args: list[str], needle: str) -> None:
    code, _, err = run(*args)
    assert code == 2 and needle in err, err


def test_an_angle_valid_only_in_degrees_hints_at_degrees() -> None:
    code, _, err = run("fall", "--height", "100", "--latitude", "50")
    assert code == 1 and "did you mean --degrees (or 50deg)?" in err, err
    # Negative controls: with a unit, or with --degrees, no hint (and 50deg runs).
    assert run("fall", "--height", "100", "--latitude", "50deg")[0] == 0
    code, _, err = run("fall", "--height", "100", "--latitude", "500", "--degrees")
    assert code == 1 and "did you mean" not in err
    assert run("fall", "--height", "0.1km", "--latitude", "50d53m", "--json")[0] == 0


def test_every_real_option_of_the_cli_has_a_dimension() -> None:
    """Each command's numeric options read units: their dimension is the API argument's."""
    import click
    from poinsot.cli import FiniteFloat, _dimension

    for name, command in main.commands.items():
        ctx = click.Context(command, info_name=name)
        for p in command.params:
            if isinstance(p.type, FiniteFloat):
                assert _dimension(ctx, p) in _units.DIMENSIONS, (name, p.name)


#: Public calls across the modules, each with quantities and with the same values as SI floats.
EVERYWHERE = {
    "FreeSymmetricTop": lambda q: (
        ps.FreeSymmetricTop(
            q(1, "kg*m**2"), q(0.5, "kg*m**2"), q([0.1, 0, 2], "rad/s")
        ).precession_rate
    ),
    "FreeRigidBody.omega": lambda q: ps.FreeRigidBody(
        q([1, 2, 3], "kg*m**2"), q([1, 0.1, 1], "rad/s")
    ).omega(q(2, "s")),
    "simulate": lambda q: (
        ps.simulate(
            ps.RigidBody.cuboid(1.0, (1, 2, 3)), q([1, 0.1, 1], "rad/s"), q(1, "s"), samples=3
        ).omega
    ),
    "MovingFrame.to_fixed": lambda q: (
        ps.MovingFrame(angular_velocity=q([0, 0, 2], "rad/s"))
        .to_fixed(q([3, 0, 0], "m"), velocity=q([0, 1, 0], "m/s"))
        .acceleration
    ),
    "Earth.drop": lambda q: ps.Earth(radius=q(6.371e6, "m")).drop(q(100, "m"), q(0.7, "rad")).east,
    "screw_axis": lambda q: ps.screw_axis(np.eye(3), q([0, 0, 2], "m")).slide,
    "RigidBody.from_point_masses": lambda q: (
        ps.RigidBody.from_point_masses(q([1, 2], "kg"), q([[1, 1, 0], [-1, -1, 0]], "m")).inertia
    ),
    "RigidBody.angular_momentum": lambda q: ps.RigidBody.cuboid(
        q(1, "kg"), q([1, 2, 3], "m")
    ).angular_momentum(q([0, 0, 2], "rad/s"), about=q([0, 0, 1], "m")),
    "HeavyTop.min_spin": lambda q: ps.HeavyTop.min_spin(
        q(1, "kg*m**2"), q(0.5, "kg*m**2"), q(1, "J"), q(0.5, "rad")
    ),
    "HeavyTop.euler_angles": lambda q: ps.HeavyTop(1, 0.5, 1, 0.8, psi_dot=6).euler_angles(
        q([1, 2], "s")
    ),
}


@pytest.mark.parametrize("call", sorted(EVERYWHERE))
def test_quantities_are_taken_everywhere_as_their_si_values(call: str) -> None:
    """Each public call gives the same numbers (bit for bit) for quantities in SI units and for
    the plain floats, and for the same quantities in other units to round-off."""

    def plain(x, unit):
        return x

    smaller = {"kg": "g", "m": "mm", "s": "ms", "rad": "mrad", "J": "mJ", "rad/s": "deg/s"}
    smaller.update({"kg*m**2": "g*cm**2", "m/s": "km/h"})

    def scaled(x, unit):  # the same value in another unit of its dimension
        return Q(x, unit).to(smaller[unit])

    f = EVERYWHERE[call]
    want = np.asarray(f(plain))
    assert np.array_equal(np.asarray(f(Q)), want)
    assert np.allclose(np.asarray(f(scaled)), want, rtol=1e-12, atol=0)


def test_a_sweep_takes_quantities_with_or_without_degrees() -> None:
    """A swept keyword given as a quantity is the same sweep as its SI floats; with
    ``degrees=True`` its labels are in degrees and the core still gets radians."""
    sweep = pytest.importorskip("poinsot.sweep")
    pytest.importorskip("xarray")
    theta = np.radians([20.0, 40.0])
    want = sweep.heavy_top(I1=1.0, I3=0.5, mgl=1.0, theta=theta, psi_dot=6.0)
    got = sweep.heavy_top(
        I1=Q(1, "kg*m**2"), I3=0.5, mgl=1.0, theta=Q([20.0, 40.0], "deg"), psi_dot=6.0
    )
    assert np.allclose(got["turning_points"], want["turning_points"], rtol=1e-14)
    deg = sweep.heavy_top(
        I1=1.0, I3=0.5, mgl=1.0, theta=Q([20.0, 40.0], "deg"), psi_dot=Q(6, "rad/s"), degrees=True
    )
    assert np.allclose(deg["theta"], [20.0, 40.0])
    assert np.allclose(deg["turning_points"], want["turning_points"], rtol=1e-14)
