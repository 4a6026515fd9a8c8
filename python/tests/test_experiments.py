"""poinsot.experiments, the framework (issue 24): the catalogue's interface, running an entry,
its result (summary, JSON, pickle), the historical units, the command ``poinsot experiments``,
the tour's section and the docs chapter's generator. The physics of each entry (its prediction
against an independent closed form, its agreement with the measurement) is tested in
test_experiment_entries.py."""

from __future__ import annotations

import dataclasses
import json
import pickle
import sys
from pathlib import Path

import pytest

pint = pytest.importorskip("pint")

from click.testing import CliRunner  # noqa: E402
from poinsot import PoinsotError  # noqa: E402
from poinsot import experiments as x  # noqa: E402
from poinsot.cli import main  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]

# The interface the entries are written against (the brief of issue 24): names and order.
SOURCE_FIELDS = ["who", "where", "when", "publication", "page", "url", "note", "first_hand"]
EXPERIMENT_FIELDS = [
    "name", "title", "topic", "sources", "inputs", "quantity", "measured", "uncertainty",
    "uncertainty_kind", "predict", "closed_form", "assumptions", "story", "misquoted", "expect",
    "why", "unit",
]  # fmt: skip


def _reich(**changes: object) -> x.Experiment:
    return dataclasses.replace(x.get("reich-1831"), **changes)


# ---- the interface ---------------------------------------------------------------------------


def test_interface_fields_are_the_ones_the_entries_use() -> None:
    assert [f.name for f in dataclasses.fields(x.Source)] == SOURCE_FIELDS
    assert [f.name for f in dataclasses.fields(x.Experiment)] == EXPERIMENT_FIELDS
    cat = x.catalogue()
    assert isinstance(cat, tuple) and cat and all(isinstance(e, x.Experiment) for e in cat)
    assert x.names() == [e.name for e in cat]
    assert len(set(x.names())) == len(cat)
    assert x.get("reich-1831").topic == "falling bodies"


def test_catalogue_is_in_the_units_order_then_by_year() -> None:
    keys = [(x.TOPICS.index(e.topic), e.year) for e in x.catalogue()]
    assert keys == sorted(keys)


def test_every_entry_is_complete_and_cites_its_sources() -> None:
    """Every source names who, where, when, the publication and the page; the topic, the
    inputs, the measured value and its uncertainty read in pint."""
    bad = {e.name: x.problems(e) for e in x.catalogue() if x.problems(e)}
    assert bad == {}


def test_problems_finds_a_missing_page_and_a_bad_unit() -> None:
    # negative control of the completeness test
    e = x.get("reich-1831")
    no_page = dataclasses.replace(e.sources[0], page=" ")
    found = x.problems(_reich(sources=(no_page,), measured="28.4 parsec_line"))
    assert "sources[0].page is empty" in found
    todo = dataclasses.replace(e.sources[0], page="TODO-verify")
    assert "sources[0].page is a placeholder: 'TODO-verify'" in x.problems(_reich(sources=(todo,)))
    assert any(p.startswith("measured:") for p in found)
    assert any("topic" in p for p in x.problems(_reich(topic="astrology")))
    assert any("why" in p for p in x.problems(_reich(expect="disagree", why="")))


def test_unknown_name_is_refused_with_the_close_names() -> None:
    with pytest.raises(
        PoinsotError, match=r"^name: no experiment 'reich-1813'; did you mean reich-1831"
    ):
        x.run("reich-1813")
    with pytest.raises(PoinsotError, match=r"the entries: .*reich-1831"):
        x.get("zzzz")
    with pytest.raises(PoinsotError, match="^name: expected an experiment's name"):
        x.run(1831)  # type: ignore[arg-type]


# ---- a run -----------------------------------------------------------------------------------


def test_run_compares_measured_predicted_and_closed_form_in_the_entrys_unit() -> None:
    r = x.run("reich-1831")
    e = x.get("reich-1831")
    assert r.unit == e.unit and str(r.predicted.units) == str(x.ureg.Unit(e.unit))
    measured = x.ureg(e.measured)
    assert r.measured_si == pytest.approx(measured.to("m").magnitude, rel=1e-12)
    assert r.uncertainty_si == pytest.approx(x.ureg(e.uncertainty).to("m").magnitude, rel=1e-12)
    assert r.si_unit == "m"
    assert r.predicted_si == pytest.approx(r.predicted.to("m").magnitude, rel=1e-12)
    # sigma is (measured - predicted) / uncertainty, worked here from the SI floats
    assert r.sigma == pytest.approx((r.measured_si - r.predicted_si) / r.uncertainty_si)
    assert r.agrees == (abs(r.sigma) <= x.AGREE_SIGMA)
    assert r.verdict.startswith("agrees within" if r.agrees else "disagrees by")
    assert r.sources == e.sources and r.assumptions == e.assumptions
    assert r.summary.startswith(f"{e.title} ({e.year}), {e.quantity}: measured ")
    assert r.verdict in r.summary
    html = r._repr_html_()
    assert html.startswith("<p>") and "<table" in html and "verdict" in html
    assert "reich-1831" in repr(r)


def test_verdict_in_sigma_expected_and_unexpected_disagreement() -> None:
    far = _reich(measured="100 mm", uncertainty="2 mm").run()
    assert far.sigma == pytest.approx((100 - far.predicted.to("mm").magnitude) / 2)
    assert not far.agrees and not far.as_expected
    assert far.verdict.startswith("disagrees by ") and far.verdict.endswith("— not expected")
    why = "the model leaves out the air"
    expected = _reich(measured="100 mm", uncertainty="2 mm", expect="disagree", why=why).run()
    assert expected.as_expected and expected.verdict.endswith(f"— expected: {why}")
    near = _reich(expect="disagree", why=why).run()
    assert near.agrees and not near.as_expected and "a disagreement was expected" in near.verdict
    none = _reich(uncertainty=None).run()
    assert none.sigma is None and "no uncertainty stated" in none.verdict


def test_a_sense_compares_words() -> None:
    same = _reich(measured="eastward", uncertainty=None, unit="", predict=lambda i: "eastward",
                  closed_form=lambda i: None).run()  # fmt: skip
    assert same.is_sense and same.agrees and same.verdict == "same sense"
    assert same.measured_si is None and same.sigma is None and same.closed_form is None
    other = _reich(measured="westward", uncertainty=None, unit="", predict=lambda i: "eastward",
                   closed_form=lambda i: None).run()  # fmt: skip
    assert not other.agrees and other.verdict.startswith("opposite sense")


def test_a_prediction_must_carry_its_unit() -> None:
    bare = _reich(predict=lambda inputs: 0.0276)
    with pytest.raises(PoinsotError, match=r"^reich-1831: predict\(\) must be a pint quantity"):
        bare.run()
    wrong = _reich(predict=lambda inputs: x.ureg.Quantity(1.0, "s"))
    with pytest.raises(PoinsotError, match=r"^reich-1831: predict\(\) 1.0 s is not in mm"):
        wrong.run()


def test_changed_inputs_move_the_prediction() -> None:
    base = x.run("reich-1831")
    higher = x.run("reich-1831", height="160 m")
    # the first-order deflection grows as h^(3/2)
    ratio = higher.closed_form_si / base.closed_form_si
    assert ratio == pytest.approx((160 / 158.5) ** 1.5, rel=1e-12)
    assert higher.inputs["height"] == "160 m" and base.inputs["height"] == "158.5 m"
    same = x.run("reich-1831", height=x.ureg.Quantity(158.5, "m"))
    assert same.predicted_si == pytest.approx(base.predicted_si, rel=1e-12)
    with pytest.raises(PoinsotError, match="^depth: not an input of reich-1831"):
        x.run("reich-1831", depth="3 m")
    with pytest.raises(PoinsotError, match="^height: give a quantity with its unit"):
        x.run("reich-1831", height=160)


def test_run_all_runs_every_entry_in_order() -> None:
    results = x.run_all(progress=False)
    assert [r.name for r in results] == x.names()
    words = x.catalogue_summary(results)
    assert words.startswith(f"{len(results)} published measurement")


# ---- plain data: JSON and pickle ------------------------------------------------------------------


def test_json_round_trip() -> None:
    r = x.run("reich-1831")
    data = json.loads(json.dumps(r.to_dict()))
    assert data["measured"] == pytest.approx(r.measured.magnitude)
    assert data["sources"][0]["who"] == r.sources[0].who
    back = x.ExperimentResult.from_dict(data)
    assert back.to_dict() == r.to_dict()
    assert back.predicted.units == r.predicted.units and back.sources == r.sources


def test_pickles_with_its_quantities_in_the_catalogues_registry() -> None:
    r = x.run("reich-1831", height="488 paris_foot")
    back = pickle.loads(pickle.dumps(r))
    assert back.to_dict() == r.to_dict()
    assert back.predicted._REGISTRY is x.ureg
    assert (back.predicted - r.predicted).magnitude == 0.0


# ---- the historical units -------------------------------------------------------------------------


def test_paris_units_as_defined_by_the_law_of_1799() -> None:
    u = x.ureg
    # 1 m = 443.296 lignes; the pied du roi 144 lignes, the toise 6 pieds
    assert u("443.296 paris_line").to("m").magnitude == pytest.approx(1.0, rel=1e-15)
    assert u("1 paris_foot").to("m").magnitude == pytest.approx(0.32483939, abs=1e-8)
    assert u("1 toise").to("m").magnitude == pytest.approx(1.949036, abs=5e-7)
    assert u("12 paris_line").to("paris_inch").magnitude == pytest.approx(1.0, rel=1e-15)
    assert u("1 ligne").to("mm").magnitude == pytest.approx(2.2558291, rel=1e-7)
    assert u("1 rhenish_foot").to("m").magnitude == pytest.approx(0.3139, rel=1e-15)
    assert u("144 rhenish_line").to("rhenish_foot").magnitude == pytest.approx(1.0, rel=1e-15)
    # negative control: pint's foot is the international foot, 6 % shorter than the Paris one
    assert u("1 foot").to("m").magnitude == pytest.approx(0.3048, rel=1e-15)
    assert u("1 paris_foot").to("foot").magnitude == pytest.approx(1.0657, rel=1e-4)


def test_historical_inputs_go_through_the_units_at_the_door() -> None:
    """The same height in Paris feet gives the same prediction; in pint's feet it does not."""
    metres = x.run("reich-1831", height="158.5 m")
    feet = 158.5 / 0.3248393849707645
    paris = x.run("reich-1831", height=f"{feet!r} paris_foot")
    assert paris.predicted_si == pytest.approx(metres.predicted_si, rel=1e-12)
    english = x.run("reich-1831", height=f"{feet!r} foot")
    assert english.predicted_si < 0.91 * metres.predicted_si  # (0.3048/0.3248)^1.5 = 0.909
    lat = x.parse("50 deg + 55 arcmin")
    assert lat.to("deg").magnitude == pytest.approx(50 + 55 / 60, rel=1e-15)
    assert x.parse("clockwise") == "clockwise"
    with pytest.raises(PoinsotError, match="^'3 furlongs_per_fortnight': not a quantity"):
        x.parse("3 furlongs_per_fortnight")


# ---- the command line -----------------------------------------------------------------------------


def _cli(*args: str) -> tuple[int, str, str]:
    res = CliRunner().invoke(main, ["experiments", *args])
    return res.exit_code, res.stdout, res.stderr


def test_cli_lists_the_catalogue_with_a_sentence_first() -> None:
    code, out, _ = _cli()
    assert code == 0, out
    assert out.startswith(f"{len(x.names())} published measurement")
    flat = " ".join(out.split())
    for name in x.names():
        assert name in flat


def test_cli_one_experiment_and_its_json() -> None:
    code, out, _ = _cli("reich-1831")
    assert code == 0, out
    r = x.run("reich-1831")
    flat = " ".join(out.split())
    assert flat.startswith(" ".join(r.summary.split()))
    assert "Ferdinand Reich" in flat and "assumptions: vacuum" in flat
    code, out, _ = _cli("reich-1831", "--json")
    assert code == 0
    data = json.loads(out)
    assert data == json.loads(json.dumps(r.to_dict()))
    code, out, _ = _cli("--json")
    assert [d["name"] for d in json.loads(out)["experiments"]] == x.names()


def test_cli_unknown_name_names_the_argument() -> None:
    code, _, err = _cli("reich-1813")
    assert code == 2
    assert "NAME: no experiment 'reich-1813'; did you mean reich-1831" in err


# ---- the tour and the docs --------------------------------------------------------------------------


def test_tour_has_the_section() -> None:
    import io

    from poinsot.tour import _SECTIONS
    from rich.console import Console

    titles = [t for t, _ in _SECTIONS]
    assert any(t.startswith("The unit against the world") for t in titles)
    con = Console(width=240, record=True, file=io.StringIO())  # cells unwrapped
    dict(_SECTIONS)[titles[-1]](con)
    text = " ".join(con.export_text().split())
    firsts = {}
    for e in x.catalogue():
        firsts.setdefault(e.topic, e)
    for e in firsts.values():  # the first entry of each topic
        r = e.run()
        assert f"{r.title} ({r.year})" in text
        assert r.shown_measured() in text


def test_plot_shows_the_measurement_and_the_prediction() -> None:
    sys.path.insert(0, str(Path(__file__).parent))
    from figure_checks import axes_without_units, layout_problems

    r = x.run("reich-1831")
    fig = x.plot(r)
    assert axes_without_units(fig) == [] and layout_problems(fig) == []
    texts = " ".join(t.get_text() for t in fig.axes[0].texts)
    assert f"measured {r.shown_measured()}" in texts
    assert f"poinsot {r.shown('predicted')}" in texts
    assert fig.axes[0].get_xlabel() == "eastward deflection (mm)"
    sense = _reich(measured="eastward", uncertainty=None, unit="", predict=lambda i: "eastward",
                   closed_form=lambda i: None).run()  # fmt: skip
    fig = x.plot(sense)
    assert layout_problems(fig) == []
    assert "measured\neastward" in [t.get_text() for t in fig.axes[0].texts]


def test_docs_chapter_lists_every_entry() -> None:
    sys.path.insert(0, str(ROOT / "docs" / "_ext"))
    import world_pages

    pages = world_pages.pages(draw=False)
    index = pages[world_pages.WORLD / "index.md"]
    for r in x.run_all(progress=False):
        assert f"[{r.title} ({r.year})]({r.name}.md)" in index
        assert r.shown_measured() in index and r.short_verdict in index
        page = pages[world_pages.WORLD / f"{r.name}.md"]
        assert page.startswith(f"# {r.title}")
        assert r.sources[0].publication in page
        assert "def " in page  # the computation, as code
        assert f"world-{r.name}.png" in page


def test_without_pint_the_error_names_the_extra() -> None:
    import subprocess

    code = (
        "import sys; sys.modules['pint'] = None\n"
        "try:\n"
        "    import poinsot.experiments\n"
        "except ImportError as exc:\n"
        "    print(exc)\n"
        "from click.testing import CliRunner\n"
        "from poinsot.cli import main\n"
        "res = CliRunner().invoke(main, ['experiments'])\n"
        "print(res.exit_code, res.stderr.strip())\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    ).stdout.splitlines()
    assert out[0] == "poinsot.experiments needs pint: pip install 'poinsot[units]'"
    assert out[1].startswith("1 error: poinsot experiments needs pint")
    assert "pip install 'poinsot[units]'" in out[1]


def test_every_entry_round_trips_through_json_and_pickle() -> None:
    for r in x.run_all(progress=False):
        data = json.loads(json.dumps(r.to_dict()))
        assert x.ExperimentResult.from_dict(data).to_dict() == r.to_dict(), r.name
        assert pickle.loads(pickle.dumps(r)).to_dict() == r.to_dict(), r.name
        assert r.summary.endswith(f"{r.verdict}."), r.name
