"""The catalogue's entries (poinsot.experiments.entries): each prediction against a reference
written here (a closed form or a scipy integration, not poinsot's second output), each verdict
as the entry documents it, every source complete, and the historical units converted by pint
as by hand (with a negative control)."""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

import pytest
from poinsot import Earth
from poinsot import experiments as x
from scipy.integrate import solve_ivp

# The test's own constants (not read from poinsot): the sidereal rate, standard gravity, the
# mean radius, and the Paris units by hand from the law of 10 December 1799 (1 m = 443.296
# lignes; 12 lignes a pouce, 12 pouces a pied; the toise, 6 pieds, is then 1.949036 m).
OMEGA = 7.292115e-5  # the WGS 84 value
G = 9.80665
R = 6.371e6
PARIS_LINE = 1 / 443.296
PARIS_FOOT = 144 * PARIS_LINE
DAY = 86400.0


def _si(inputs: Mapping[str, Any], key: str, unit: str) -> float:
    return float(inputs[key].to(unit).magnitude)


def _east_by_integration(h: float, lat: float) -> float:
    """A body dropped from rest at height h in the rotating frame, uniform gravity, Coriolis
    force only (the centrifugal change over the fall is of order ω² h/g ≈ 1e-9): the landing
    point's east coordinate, integrated by scipy."""
    w = (0.0, OMEGA * math.cos(lat), OMEGA * math.sin(lat))

    def rhs(_t: float, s: list[float]) -> list[float]:
        vx, vy, vz = s[3:]
        cx = w[1] * vz - w[2] * vy
        cy = w[2] * vx - w[0] * vz
        cz = w[0] * vy - w[1] * vx
        return [vx, vy, vz, -2 * cx, -2 * cy, -G - 2 * cz]

    def ground(_t: float, s: list[float]) -> float:
        return s[2]

    ground.terminal = True  # type: ignore[attr-defined]
    sol = solve_ivp(rhs, (0, 100), [0, 0, h, 0, 0, 0], events=ground, rtol=1e-12, atol=1e-15)
    return float(sol.y_events[0][0][0])


def _east(i: Mapping[str, Any]) -> float:
    return _east_by_integration(_si(i, "height", "m"), _si(i, "latitude", "rad"))


def _south(i: Mapping[str, Any]) -> float:
    h, lat = _si(i, "height", "m"), _si(i, "latitude", "rad")
    return 0.75 * OMEGA**2 * math.sin(2 * lat) * h**2 / G


def _foucault_rate(i: Mapping[str, Any]) -> float:
    return OMEGA * math.sin(_si(i, "latitude", "rad"))


def _foucault_turn(i: Mapping[str, Any]) -> float:
    return 2 * math.pi / (OMEGA * abs(math.sin(_si(i, "latitude", "rad"))))


def _inertial(i: Mapping[str, Any]) -> float:
    return math.pi / (OMEGA * abs(math.sin(_si(i, "latitude", "rad"))))


def _sense(i: Mapping[str, Any]) -> str:
    return "counterclockwise" if _si(i, "latitude", "rad") > 0 else "clockwise"


def _gravity_step(i: Mapping[str, Any]) -> float:
    # the sphere's attraction is the same everywhere: only the centrifugal ω²R cos λ differs
    pole, eq = _si(i, "pole_latitude", "rad"), _si(i, "equator_latitude", "rad")
    g = [
        math.hypot(G - OMEGA**2 * R * math.cos(a) ** 2, OMEGA**2 * R * math.sin(a) * math.cos(a))
        for a in (pole, eq)
    ]
    return g[0] - g[1]


def _plumb(i: Mapping[str, Any]) -> float:
    lat = _si(i, "latitude", "rad")
    c = OMEGA**2 * R
    return math.atan2(c * math.sin(lat) * math.cos(lat), G - c * math.cos(lat) ** 2)


def _euler(i: Mapping[str, Any]) -> float:
    h = float(i["dynamical_ellipticity"].to("dimensionless").magnitude)
    return 2 * math.pi / OMEGA * (1 - h) / h


#: Each entry's reference (inputs as pint quantities → SI value, or the sense) and the relative
#: tolerance of poinsot's prediction against it. An entry without one fails the test below.
REFERENCES: dict[str, tuple[Callable[[Mapping[str, Any]], Any], float]] = {
    "guglielmini-1791": (_east, 1e-6),
    "benzenberg-1802": (_east, 1e-6),
    "benzenberg-1804": (_east, 1e-6),
    "reich-1831": (_east, 1e-6),
    "hall-1902": (_south, 1e-3),
    "foucault-1851": (_foucault_rate, 5e-3),
    "galbraith-haughton-1851": (_foucault_turn, 5e-3),
    "ceylon-1851": (_foucault_rate, 5e-3),
    "gustafson-kullenberg-1936": (_inertial, 1e-6),
    "shapiro-1962": (_sense, 0.0),
    "trefethen-1965": (_sense, 0.0),
    "wgs84-gravity": (_gravity_step, 1e-9),
    "wgs84-plumb-line": (_plumb, 1e-9),
    "chandler-1891": (_euler, 1e-9),
}


def test_the_catalogue_has_at_least_twelve_entries_each_with_a_reference() -> None:
    names = x.names()
    assert len(names) >= 12
    assert sorted(names) == sorted(REFERENCES), "every entry needs an independent reference here"


@pytest.mark.parametrize("name", sorted(REFERENCES))
def test_prediction_and_closed_form_against_an_independent_reference(name: str) -> None:
    e = x.get(name)
    reference, rtol = REFERENCES[name]
    expected = reference(e.parsed_inputs())
    r = x.run(name)
    if isinstance(expected, str):
        assert r.predicted == expected
        assert r.closed_form == expected
        return
    assert r.predicted_si == pytest.approx(expected, rel=rtol)
    assert r.closed_form_si == pytest.approx(expected, rel=max(rtol, 1e-9))


@pytest.mark.parametrize("name", sorted(REFERENCES))
def test_the_verdict_is_the_one_the_entry_documents(name: str) -> None:
    e = x.get(name)
    r = x.run(name)
    assert r.as_expected, r.verdict
    if e.expect == "disagree":
        assert not r.agrees and e.why.strip() and e.why in r.verdict
        return
    assert r.agrees
    if r.is_sense:
        assert r.measured == r.predicted
        return
    assert r.measured_si is not None and r.predicted_si is not None
    if r.uncertainty_si:  # within the stated uncertainty (two of them at most)
        assert abs(r.measured_si - r.predicted_si) <= 2 * r.uncertainty_si
    else:  # no uncertainty stated: within 5 %, and the entry says so
        assert "none stated" in e.uncertainty_kind
        assert abs(r.measured_si - r.predicted_si) <= 0.05 * abs(r.predicted_si)


@pytest.mark.parametrize("name", sorted(REFERENCES))
def test_every_source_is_quoted_with_who_where_when_publication_and_page(name: str) -> None:
    e = x.get(name)
    assert x.problems(e) == []
    assert e.sources, name
    for s in e.sources:
        for key in ("who", "where", "when", "publication", "page"):
            assert str(getattr(s, key)).strip(), f"{name}: {key} is empty"
    assert str(e.year) in e.sources[0].when or str(e.year) in e.name
    assert e.story.strip() and e.assumptions


def test_paris_units_are_converted_by_pint_as_by_hand() -> None:
    inputs = x.get("benzenberg-1802").parsed_inputs()
    assert inputs["height"].to("m").magnitude == pytest.approx(235 * PARIS_FOOT, rel=1e-9)
    lat = inputs["latitude"].to("deg").magnitude
    assert lat == pytest.approx(53 + 33 / 60, rel=1e-12)
    assert x.parse("3.997 paris_line").to("mm").magnitude == pytest.approx(
        3.997 * PARIS_LINE * 1e3, rel=1e-9
    )
    assert x.parse("262 paris_foot").to("m").magnitude == pytest.approx(85.1079, rel=1e-6)
    assert x.parse("1 toise").to("m").magnitude == pytest.approx(1.949036, rel=1e-6)
    # negative control: the Rhenish (Prussian) foot or the English foot is not the Paris foot
    for wrong in (0.3139, 0.3048):
        assert inputs["height"].to("m").magnitude != pytest.approx(235 * wrong, rel=1e-3)
    # and the measured 4 lines are 9 mm, not the 4 English lines (8.5 mm) of a wrong factor
    assert x.run("benzenberg-1802").measured_si == pytest.approx(3.997 * PARIS_LINE, rel=1e-9)
    assert x.run("benzenberg-1802").measured_si != pytest.approx(3.997 * 0.0254 / 12, rel=1e-3)


@pytest.mark.parametrize(
    "name", [n for n in sorted(REFERENCES) if any("paris" in v for v in x.get(n).inputs.values())]
)
def test_every_paris_input_converts_as_by_hand(name: str) -> None:
    for text in x.get(name).inputs.values():
        if "paris_foot" in text:
            feet = float(text.split()[0])
            assert x.parse(text).to("m").magnitude == pytest.approx(feet * PARIS_FOOT, rel=1e-9)


def test_reported_southward_deviations_are_hundreds_of_times_what_physics_allows() -> None:
    earth = Earth()
    # Benzenberg, Hamburg: 1.5 Paris lines south, against ¾ ω² sin 2λ h²/g
    hamburg = x.get("benzenberg-1802").parsed_inputs()
    physics = earth.southward_deflection(hamburg["height"], hamburg["latitude"])
    assert physics == pytest.approx(_south(hamburg), rel=1e-9)
    ratio = 1.5 * PARIS_LINE / physics
    assert round(ratio, -2) == 1500
    assert "1500 times" in x.get("benzenberg-1802").misquoted
    # Hall: 0.0050 cm south in the Jefferson tower
    hall = x.get("hall-1902").parsed_inputs()
    ratio = 0.0050e-2 / earth.southward_deflection(hall["height"], hall["latitude"])
    assert round(ratio, -1) == 230
    assert "230 times" in x.get("hall-1902").misquoted
    # Guglielmini, Bologna: 5.272 lines south (Garthe's figure)
    bologna = x.get("guglielmini-1791").parsed_inputs()
    ratio = 5.272 * PARIS_LINE / earth.southward_deflection(bologna["height"], bologna["latitude"])
    assert 4500 < ratio < 5000
    assert "nearly 5000 times" in x.get("guglielmini-1791").misquoted


def test_the_pantheon_32_7_hours_is_360_over_11_and_the_law_gives_31_8() -> None:
    e = x.get("foucault-1851")
    lat = _si(e.parsed_inputs(), "latitude", "rad")
    assert round(360 / 11, 1) == 32.7
    assert round(2 * math.pi / (OMEGA * math.sin(lat)) / 3600, 1) == 31.8
    assert round(math.degrees(OMEGA * math.sin(lat)) * 3600, 1) == 11.3
    for text in ("32.7", "360/11", "31.8", "11.3"):
        assert text in e.misquoted


def test_the_measured_figures_of_the_reference_ellipsoid_follow_from_its_constants() -> None:
    f = 1 / 298.257223563
    plumb = math.degrees(math.pi / 4 - math.atan((1 - f) ** 2)) * 60
    assert x.run("wgs84-plumb-line").measured.magnitude == pytest.approx(plumb, abs=1e-3)
    assert x.run("wgs84-gravity").measured_si == pytest.approx(9.8321849378 - 9.7803253359)


def test_the_euler_period_is_about_304_days_and_chandler_427() -> None:
    r = x.run("chandler-1891")
    assert r.predicted_si is not None and r.measured_si is not None
    assert r.predicted_si / DAY == pytest.approx(303.6, abs=0.1)
    assert r.measured_si / DAY == 427
