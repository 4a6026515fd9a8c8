"""Tests of poinsot.RigidEarth (issue 25): the Earth as a rigid symmetric top — Euler's free
nutation against (1 − H)/H sidereal days and the unit's 2.83, the Chandler period, the
luni-solar precession against a closed form written here and against IAU 2006 (pyerfa's
``p06e`` when installed), the principal nutation against IAU 2000A (pyerfa's ``nut00a`` when
installed), bad input refused by name, pickling, and negative controls."""

from __future__ import annotations

import math
import pickle

import numpy as np
import poinsot as ps
import pytest

ARCSEC = math.pi / 648000
CENTURY = 36525 * 86400.0
SIDEREAL_DAY = 2 * math.pi / ps.SIDEREAL_RATE

#: The constants as the tests state them, independently of the core (IERS 2010 Table 1.1, IAU
#: 2012 B2, JPL Horizons' Moon sheet, Simon et al. 1994).
H = 0.003273795
OMEGA = 7.292115e-5
EPS = 84381.406 * ARCSEC
GM_SUN = 1.32712442099e20
GM_EARTH = 3.986004418e14
MU = 0.0123000371
AU = 1.495978707e11
E_SUN = 0.0167086
A_MOON = 3.844e8
E_MOON = 0.0549
I_MOON = math.radians(5.145)
NODE_PERIOD = 6798.38 * 86400


def test_defaults_are_the_iers_2010_values() -> None:
    e = ps.RigidEarth()
    assert e.dynamical_flattening == H == ps.DYNAMICAL_FLATTENING
    assert e.rotation_rate == OMEGA == ps.SIDEREAL_RATE
    assert e.obliquity == pytest.approx(EPS, rel=1e-15) and e.obliquity == ps.OBLIQUITY_J2000
    assert math.degrees(e.obliquity) == pytest.approx(23.4392794, abs=1e-7)


def test_euler_period_is_one_minus_h_over_h_sidereal_days() -> None:
    e = ps.RigidEarth()
    assert e.euler_period / SIDEREAL_DAY == pytest.approx((1 - H) / H, rel=1e-12)
    assert e.euler_period / SIDEREAL_DAY == pytest.approx(304.5, abs=0.05)  # the figure
    assert e.euler_period / 86400 == pytest.approx(303.62, abs=0.01)


def test_euler_rate_is_the_units_2_83_and_a_free_symmetric_top_agrees() -> None:
    """Ω = (I₁ − I₃) ω₃ / I₁ (2.83) with I₁ = A = (1 − H) C, I₃ = C; and poinsot's own free
    symmetric top, built with those moments, turns ω at the same rate."""
    e = ps.RigidEarth()
    i1, i3 = 1 - H, 1.0
    assert e.euler_rate == pytest.approx((i1 - i3) * OMEGA / i1, rel=1e-12)
    assert e.euler_rate < 0
    top = ps.FreeSymmetricTop(i1, i3, [1e-6 * OMEGA, 0.0, OMEGA])
    assert top.precession_rate == pytest.approx(e.euler_rate, rel=1e-12)
    assert e.euler_period == pytest.approx(2 * math.pi / abs(top.precession_rate), rel=1e-12)


@pytest.mark.parametrize("h", [1e-4, 0.003273795, 0.05, 0.3])
def test_euler_period_scales_as_one_minus_h_over_h(h: float) -> None:
    e = ps.RigidEarth(h, 1.0, 0.4)
    assert e.euler_period == pytest.approx((1 - h) / h * 2 * math.pi, rel=1e-12)


def test_chandler_period_is_euler_lengthened_by_ks_over_ks_minus_k2() -> None:
    e = ps.RigidEarth()
    t = e.chandler_period(0.30, 0.938)
    assert t == pytest.approx(e.euler_period * 0.938 / (0.938 - 0.30), rel=1e-12)
    assert t / 86400 == pytest.approx(446.4, abs=0.1)  # about 445 d, against the observed 433
    assert 430 < t / 86400 < 460


def _closed_form_rate() -> tuple[float, float]:
    """The orbit-averaged luni-solar precession, written out: −(3/2)(GM/(a³(1−e²)^{3/2}))(H/ω)
    cos ε for the Sun; the Moon's with GM = μ GM_⊕ and the factor (1 − (3/2) sin² i)."""
    k = 1.5 * H / OMEGA * math.cos(EPS)
    sun = -k * GM_SUN / (AU**3 * (1 - E_SUN**2) ** 1.5)
    moon = -k * MU * GM_EARTH / (A_MOON**3 * (1 - E_MOON**2) ** 1.5)
    return sun, moon * (1 - 1.5 * math.sin(I_MOON) ** 2)


def test_precession_matches_the_closed_form() -> None:
    e = ps.RigidEarth()
    sun, moon = _closed_form_rate()
    assert e.precession_parts[0] == pytest.approx(sun, rel=1e-12)
    assert e.precession_parts[1] == pytest.approx(moon, rel=1e-12)
    assert e.precession_rate == pytest.approx(sun + moon, rel=1e-12)
    assert e.precession_rate < 0  # retrograde: the equinoxes move west
    assert moon / sun == pytest.approx(2.16, abs=0.01)


def test_precession_is_within_half_a_percent_of_iau_2006() -> None:
    e = ps.RigidEarth()
    iau = 5038.481507 * ARCSEC / CENTURY
    assert abs(ps.IAU2006_PRECESSION_RATE / iau - 1) < 1e-15
    assert abs(e.precession_rate) == pytest.approx(iau, rel=5e-3)
    assert abs(e.precession_rate) / iau - 1 == pytest.approx(3.1e-4, abs=0.5e-4)
    years = e.precession_period / (365.25 * 86400)
    assert years == pytest.approx(25714, abs=5)


def test_precession_against_pyerfa_iau_2006() -> None:
    """ψ̇_A of the IAU 2006 precession, differentiated from erfa.p06e at J2000."""
    erfa = pytest.importorskip("erfa")
    d = 1e-3  # Julian centuries
    psi = [erfa.p06e(2451545.0, t * 36525.0)[1] for t in (-d, d)]
    rate = (psi[1] - psi[0]) / (2 * d) / CENTURY  # rad/s
    assert rate == pytest.approx(ps.IAU2006_PRECESSION_RATE, rel=1e-8)
    assert abs(ps.RigidEarth().precession_rate) == pytest.approx(rate, rel=5e-3)


def test_nutation_is_within_half_a_percent_of_iau_2000a() -> None:
    dpsi, deps = ps.RigidEarth().nutation_amplitudes
    p, q = ps.IAU2000A_PRINCIPAL_NUTATION
    assert (p, q) == pytest.approx((-17.2064161 * ARCSEC, 9.2052331 * ARCSEC), rel=1e-12)
    assert dpsi / ARCSEC == pytest.approx(-17.281, abs=1e-3)
    assert deps / ARCSEC == pytest.approx(9.2265, abs=1e-3)
    assert dpsi == pytest.approx(p, rel=5e-3)  # +0.43 %
    assert deps == pytest.approx(q, rel=5e-3)  # +0.23 %


def test_nutation_closed_form_and_its_ratio() -> None:
    """Δψ₀ = −K sin i cos i cos 2ε/(ν sin ε), Δε₀ = K sin i cos i cos ε/ν, K the Moon's
    (3/2)(GM/(a³(1−e²)^{3/2}))(H/ω), ν = 2π/T_node; their ratio is −2 cot 2ε."""
    k = 1.5 * MU * GM_EARTH / (A_MOON**3 * (1 - E_MOON**2) ** 1.5) * H / OMEGA
    b = k * math.sin(I_MOON) * math.cos(I_MOON) / (2 * math.pi / NODE_PERIOD)
    dpsi, deps = ps.RigidEarth().nutation_amplitudes
    assert dpsi == pytest.approx(-b * math.cos(2 * EPS) / math.sin(EPS), rel=1e-12)
    assert deps == pytest.approx(b * math.cos(EPS), rel=1e-12)
    assert dpsi / deps == pytest.approx(-2 / math.tan(2 * EPS), rel=1e-12)


def test_nutation_against_pyerfa_iau_2000a() -> None:
    """The 18.6-year term fitted from erfa.nut00a over two node periods (sin Ω, cos Ω with Ω
    from erfa.faom03, plus a constant) is IAU 2000A's coefficient; the rigid Earth is within
    0.5 % of it."""
    erfa = pytest.importorskip("erfa")
    t = np.linspace(-18.6, 18.6, 6001) / 100  # Julian centuries from J2000
    dpsi, deps = erfa.nut00a(2451545.0, t * 36525.0)
    om = np.array([erfa.faom03(x) for x in t])
    basis = np.column_stack([np.sin(om), np.cos(om), np.ones_like(t)])
    cpsi = np.linalg.lstsq(basis, dpsi, rcond=None)[0][0]
    ceps = np.linalg.lstsq(basis, deps, rcond=None)[0][1]
    assert cpsi / ARCSEC == pytest.approx(-17.2064, abs=0.02)
    assert ceps / ARCSEC == pytest.approx(9.2052, abs=0.02)
    a, b = ps.RigidEarth().nutation_amplitudes
    assert a == pytest.approx(cpsi, rel=5e-3)
    assert b == pytest.approx(ceps, rel=5e-3)


def test_obliquity_in_degrees_and_as_a_quantity() -> None:
    e = ps.RigidEarth(obliquity=23.4392794, degrees=True)
    assert e.obliquity == pytest.approx(EPS, rel=1e-8)
    pint = pytest.importorskip("pint")
    u = pint.UnitRegistry()
    q = ps.RigidEarth(rotation_rate=1 / u.day * 2 * math.pi, obliquity=23.4392794 * u.deg)
    assert q.obliquity == pytest.approx(EPS, rel=1e-8)
    assert q.rotation_rate == pytest.approx(2 * math.pi / 86400, rel=1e-12)


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        ({"dynamical_flattening": 0.0}, "dynamical_flattening"),
        ({"dynamical_flattening": -0.01}, "dynamical_flattening"),
        ({"dynamical_flattening": 1.0}, "dynamical_flattening"),
        ({"dynamical_flattening": float("nan")}, "dynamical_flattening"),
        ({"rotation_rate": 0.0}, "rotation_rate"),
        ({"rotation_rate": -7e-5}, "rotation_rate"),
        ({"obliquity": -0.1}, "obliquity"),
        ({"obliquity": math.pi / 2}, "obliquity"),
        ({"obliquity": 90, "degrees": True}, "obliquity"),
        ({"obliquity": "23"}, "obliquity"),
    ],
)
def test_bad_input_is_refused_naming_the_argument(kwargs: dict, name: str) -> None:
    with pytest.raises(ps.PoinsotError, match=rf"^{name}: "):
        ps.RigidEarth(**kwargs)


@pytest.mark.parametrize(
    ("k2", "ks", "name"),
    [(0.94, 0.938, "k2"), (0.938, 0.938, "k2"), (0.0, 0.938, "k2"), (-0.3, 0.938, "k2"),
     (0.3, 0.0, "ks"), (0.3, float("inf"), "ks")],
)  # fmt: skip
def test_chandler_refuses_bad_love_numbers(k2: float, ks: float, name: str) -> None:
    with pytest.raises(ps.PoinsotError, match=rf"^{name}: "):
        ps.RigidEarth().chandler_period(k2, ks)


def test_nutation_in_longitude_is_refused_at_zero_obliquity() -> None:
    e = ps.RigidEarth(obliquity=0.0)
    assert e.precession_rate < 0  # the precession is still defined
    with pytest.raises(ps.PoinsotError, match=r"^obliquity: "):
        e.nutation_amplitudes


def test_negative_controls_sphere_refused_round_earth_barely_precesses() -> None:
    """H = 0 (a sphere: no bulge) is refused; as H → 0 the precession vanishes and the Euler
    period grows without bound; the precession scales as H, so the test above would fail for a
    wrong H."""
    with pytest.raises(ps.PoinsotError, match="^dynamical_flattening: "):
        ps.RigidEarth(dynamical_flattening=0)
    tiny = ps.RigidEarth(dynamical_flattening=1e-9)
    base = ps.RigidEarth()
    assert abs(tiny.precession_rate) < 1e-6 * abs(base.precession_rate)
    assert tiny.euler_period > 1e6 * base.euler_period
    double = ps.RigidEarth(dynamical_flattening=2 * H)
    assert double.precession_rate == pytest.approx(2 * base.precession_rate, rel=1e-12)
    assert abs(double.precession_rate) / ps.IAU2006_PRECESSION_RATE > 1.9


def test_pickle_repr_equality() -> None:
    e = ps.RigidEarth(0.004, 7e-5, 0.3)
    back = pickle.loads(pickle.dumps(e))
    assert back == e and hash(back) == hash(e)
    assert back.euler_period == e.euler_period
    assert repr(e) == "RigidEarth(dynamical_flattening=0.004, rotation_rate=7e-05, obliquity=0.3)"
    assert eval(repr(e), {"RigidEarth": ps.RigidEarth}) == e
    assert e != ps.RigidEarth()
    core = pickle.loads(pickle.dumps(e._core))
    assert core.obliquity == 0.3


def test_exported() -> None:
    for name in (
        "RigidEarth",
        "DYNAMICAL_FLATTENING",
        "OBLIQUITY_J2000",
        "IAU2006_PRECESSION_RATE",
        "IAU2000A_PRINCIPAL_NUTATION",
    ):
        assert name in ps.__all__ and hasattr(ps, name)


# ---- RigidEarth.simulate: the axis integrated along the orbits, against the averaged theory ----

YEAR = 365.25 * 86400.0


@pytest.fixture(scope="module")
def pole_run() -> ps.PoleRun:
    """60 years (3.2 turns of the Moon's node) of the default Earth: about 1 s."""
    return ps.RigidEarth().simulate(60 * YEAR, samples=601)


def test_simulated_precession_is_the_averaged_rate_and_the_closed_form(pole_run) -> None:
    e = ps.RigidEarth()
    fit = pole_run.fit()
    # The 1 %; the run gives ~1e-4 (second-order terms, short-period leakage).
    assert fit.precession_rate == pytest.approx(e.precession_rate, rel=0.01)
    assert fit.precession_rate == pytest.approx(e.precession_rate, rel=1e-3)
    # Independently: −(3/2)(H/ω) cos ε Σ GM/(a³(1 − e²)^{3/2}), the Moon's × (1 − 3/2 sin² i).
    sun = GM_SUN / (AU**3 * (1 - E_SUN**2) ** 1.5)
    moon = MU * GM_EARTH / (A_MOON**3 * (1 - E_MOON**2) ** 1.5) * (1 - 1.5 * math.sin(I_MOON) ** 2)
    want = -1.5 * H / OMEGA * math.cos(EPS) * (sun + moon)
    assert fit.precession_rate == pytest.approx(want, rel=1e-3)
    assert pole_run.t[0] == 0 and pole_run.t[-1] == pytest.approx(60 * YEAR, rel=1e-15)
    assert pole_run.longitude.shape == pole_run.obliquity.shape == (601,)


def test_simulated_nod_is_the_principal_nutation(pole_run) -> None:
    """Δψ₀, Δε₀ fitted to the run against nutation_amplitudes' first-order theory: within 1 %
    (the run gives 0.2 %: the fortnightly and semi-annual nods over three node periods and the
    theory's second-order terms)."""
    dpsi, deps = ps.RigidEarth().nutation_amplitudes
    fit = pole_run.fit()
    assert fit.nutation_obliquity == pytest.approx(deps, rel=0.01)
    assert fit.nutation_longitude == pytest.approx(dpsi, rel=0.01)
    # The obliquity's swing over the run: twice Δε₀ (9.2″), give or take the short nods.
    swing = np.ptp(pole_run.obliquity) / ARCSEC
    assert swing == pytest.approx(2 * deps / ARCSEC, rel=0.1)


def test_simulate_negative_control_a_round_earth_does_not_precess() -> None:
    run = ps.RigidEarth(dynamical_flattening=1e-9).simulate(20 * YEAR, samples=201)
    assert np.ptp(run.longitude) < 1e-6 * abs(ps.RigidEarth().precession_rate) * 20 * YEAR
    assert np.ptp(run.obliquity) < 1e-9


def test_simulate_takes_quantities_pickles_and_refuses_by_name(pole_run) -> None:
    pint = pytest.importorskip("pint")
    ureg = pint.UnitRegistry()
    run = ps.RigidEarth().simulate(2 * ureg.year, samples=3, moon_node=90 * ureg.deg)
    assert run.t[-1] == pytest.approx(2 * 365.25 * 86400, rel=1e-12)
    assert run.moon_node == pytest.approx(math.pi / 2)
    assert run.node_rate == pytest.approx(-2 * math.pi / NODE_PERIOD, rel=1e-12)
    back = pickle.loads(pickle.dumps(pole_run))
    assert np.array_equal(back.longitude, pole_run.longitude)
    assert "601 samples over 60 Julian years" in repr(pole_run)
    fit = pole_run.fit()
    assert pickle.loads(pickle.dumps(fit)) == fit and "PoleFit(" in repr(fit)
    e = ps.RigidEarth()
    for bad in (0.0, -1.0, float("nan")):
        with pytest.raises(ps.PoinsotError, match="^duration"):
            e.simulate(bad)
    with pytest.raises(ps.PoinsotError, match="^duration"):
        e.simulate(3 * ureg.meter)
    with pytest.raises(ps.PoinsotError, match="^samples"):
        e.simulate(YEAR, samples=1)
    with pytest.raises(ps.PoinsotError, match="^max_steps"):
        e.simulate(1000 * YEAR, max_steps=1000)
    with pytest.raises(ps.PoinsotError, match="^moon_node"):
        e.simulate(YEAR, moon_node=float("inf"))
    with pytest.raises(TypeError, match="^mean_pole"):
        e.simulate(YEAR, mean_pole="yes")
    with pytest.raises(ps.PoinsotError, match="^t:"):
        run.fit()  # two years: less than one node period


# ---- RigidEarth.averaged_pole: the averaged theory's pole at given times ----


def test_averaged_pole_is_the_closed_form_and_follows_the_run() -> None:
    """ψ = −P t + s Δψ₀ sin Ω, ε = ε₀ + s Δε₀ cos Ω, Ω = Ω₀ − 2π t/T_node, written out here with
    the rate and amplitudes of the closed forms above; and a simulate(mean_pole=True) run of the
    same Ω₀ follows it to within the short-period nods (about 2″ in ψ, 1.3″ in ε)."""
    e = ps.RigidEarth()
    sun = GM_SUN / (AU**3 * (1 - E_SUN**2) ** 1.5)
    k_moon = 1.5 * MU * GM_EARTH / (A_MOON**3 * (1 - E_MOON**2) ** 1.5) * H / OMEGA
    rate = -1.5 * H / OMEGA * math.cos(EPS) * sun - k_moon * math.cos(EPS) * (
        1 - 1.5 * math.sin(I_MOON) ** 2
    )
    nu = 2 * math.pi / NODE_PERIOD
    si, ci = math.sin(I_MOON), math.cos(I_MOON)
    dpsi = -k_moon * si * ci * math.cos(2 * EPS) / (nu * math.sin(EPS))
    deps = k_moon * si * ci * math.cos(EPS) / nu
    t = np.array([[0.0, 1.0], [7.0, 30.0]]) * YEAR
    got = e.averaged_pole(t, moon_node=40, nutation_scale=2.0, degrees=True)
    node = math.radians(40) - nu * t
    assert got.psi.shape == got.obliquity.shape == got.moon_node.shape == (2, 2)
    np.testing.assert_allclose(got.moon_node, node, rtol=1e-12)
    # The constants as written here differ from the core's by ~1e-6 (the Moon's node period).
    np.testing.assert_allclose(got.psi, -rate * t + 2 * dpsi * np.sin(node), atol=1e-4 * ARCSEC)
    np.testing.assert_allclose(got.obliquity, EPS + 2 * deps * np.cos(node), atol=1e-5 * ARCSEC)
    run = e.simulate(20 * YEAR, samples=81, moon_node=0.5, mean_pole=True)
    pole = e.averaged_pole(run.t, moon_node=0.5)
    assert np.max(np.abs(pole.psi + run.longitude)) < 2.5 * ARCSEC
    assert np.max(np.abs(pole.obliquity - run.obliquity)) < 1.5 * ARCSEC
    # Negative control: the mean pole alone (scale 0) misses the 17″ nod.
    mean = e.averaged_pole(run.t, moon_node=0.5, nutation_scale=0)
    assert np.max(np.abs(mean.psi + run.longitude)) > 10 * ARCSEC
    assert mean.obliquity[0] == e.obliquity


def test_averaged_pole_takes_quantities_pickles_and_refuses_by_name() -> None:
    e = ps.RigidEarth()
    one = e.averaged_pole(YEAR)
    # 50.40″ westward in a year, plus −17.28″ sin Ω with Ω = −2π/18.6 (the node from 0).
    nod = -17.281 * math.sin(-2 * math.pi * YEAR / NODE_PERIOD)
    assert one.psi.shape == () and float(one.psi) / ARCSEC == pytest.approx(50.40 + nod, abs=0.02)
    back = pickle.loads(pickle.dumps(one))
    assert isinstance(back, ps.AveragedPole) and back.psi == one.psi
    assert "AveragedPole(psi=" in repr(one)
    pint = pytest.importorskip("pint")
    ureg = pint.UnitRegistry()
    q = e.averaged_pole([1, 2] * ureg.year, moon_node=90 * ureg.deg)
    np.testing.assert_allclose(
        q.moon_node, math.pi / 2 - 2 * math.pi * np.array([1, 2]) * YEAR / NODE_PERIOD, rtol=1e-6
    )
    for kwargs, name in (
        ({"t": [0.0, float("nan")]}, "t"),
        ({"t": 0.0, "moon_node": float("inf")}, "moon_node"),
        ({"t": 0.0, "nutation_scale": -1.0}, "nutation_scale"),
    ):
        with pytest.raises(ps.PoinsotError, match=f"^{name}"):
            e.averaged_pole(**kwargs)
    with pytest.raises(ps.PoinsotError, match="^obliquity"):
        ps.RigidEarth(obliquity=0.0).averaged_pole(0.0)
