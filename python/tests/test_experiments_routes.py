"""The experiment entries' shared pieces (issue 22): a turning's sign becomes a word in one place,
:func:`poinsot.experiments._catalogue.sense`, for every entry that compares senses; and the
Chandler entry's closed form is the core's (:meth:`poinsot.RigidEarth.chandler_period`), not a
formula written in the entry."""

from __future__ import annotations

import inspect

import pytest

pytest.importorskip("pint")

from poinsot import Earth, RigidEarth
from poinsot import experiments as x
from poinsot.experiments import _catalogue
from poinsot.experiments.entries import gyrocompass, vortices


def test_sense_words_a_counterclockwise_positive_sign() -> None:
    assert _catalogue.sense(2.5e-5) == "counterclockwise"
    assert _catalogue.sense(-1e-300) == "clockwise"
    assert _catalogue.sense(0.0) == "none"


def test_the_sense_entries_word_their_sign_through_the_shared_helper() -> None:
    for route in (
        vortices._closed_sense,
        gyrocompass._gyroscope_sense,
        gyrocompass._closed_gyroscope_sense,
    ):
        source = inspect.getsource(route)
        assert "sense(" in source and '"clockwise" if' not in source, route.__name__
    north = {"latitude": x.parse("45 deg")}
    south = {"latitude": x.parse("-45 deg")}
    assert vortices._closed_sense(north) == "counterclockwise"  # f = 2ω sin λ > 0
    assert gyrocompass._closed_gyroscope_sense(north) == "clockwise"  # −ω sin λ < 0
    assert vortices._closed_sense(south) == gyrocompass._closed_gyroscope_sense(north)
    assert Earth().coriolis_parameter(0.7) > 0 > Earth().foucault_rate(0.7)


def test_the_chandler_closed_form_is_the_cores_chandler_period() -> None:
    e = x.get("vicente-wilson-1997")
    assert e.closed_form is e.predict
    inputs = e.parsed_inputs()
    r = x.run("vicente-wilson-1997")
    earth = RigidEarth(
        dynamical_flattening=float(inputs["dynamical_flattening"].to("").magnitude),
        obliquity=float(inputs["obliquity"].to("rad").magnitude),
    )
    k2 = float(inputs["k2"].magnitude)
    ks = float(inputs["ks"].magnitude)
    assert r.closed_form_si == earth.chandler_period(k2, ks)
