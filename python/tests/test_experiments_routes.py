"""The experiment entries' shared pieces (issue 22): a turning's sign becomes a word in one place,
:func:`poinsot.experiments._catalogue.sense`, for every entry that compares senses; and the
Chandler entry's closed form is the core's (:meth:`poinsot.RigidEarth.chandler_period`), not a
formula written in the entry."""

from __future__ import annotations

import ast
import inspect
from pathlib import Path

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


def test_a_publication_that_two_topics_cite_is_written_once() -> None:
    """A publication cited by entries of more than one topic (the IERS Conventions 2010: the free
    period and the Earth as a rigid top) is one :class:`Source` in ``entries/_sources.py``; each
    citation adds only its page and note, so who, where, when, url and first_hand agree."""
    from poinsot.experiments.entries import _sources

    shared = {s.publication: s for s in vars(_sources).values() if isinstance(s, _catalogue.Source)}
    topics: dict[str, set[str]] = {}
    cited: dict[str, list[_catalogue.Source]] = {}
    for e in x.catalogue():
        for s in e.sources:
            topics.setdefault(s.publication, set()).add(e.topic)
            cited.setdefault(s.publication, []).append(s)
    across = [p for p, t in topics.items() if len(t) > 1]
    assert across, "no publication is cited by two topics: the check is vacuous"
    written = {
        path.name: {
            node.value
            for node in ast.walk(ast.parse(path.read_text(encoding="utf-8")))
            if isinstance(node, ast.Constant) and isinstance(node.value, str)
        }
        for path in Path(_sources.__file__).parent.glob("*.py")
    }
    for publication in across:
        assert publication in shared
        assert [name for name, texts in written.items() if publication in texts] == [
            "_sources.py"
        ], f"{publication[:60]!r} is written out in an entry module"
        base = shared[publication]
        for s in cited[publication]:
            fields = ("who", "where", "when", "url", "first_hand")
            assert [getattr(s, f) for f in fields] == [getattr(base, f) for f in fields]
            assert s.page.startswith(base.page)
