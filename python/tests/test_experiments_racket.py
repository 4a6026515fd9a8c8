"""The tennis racket's entry (bubbar-zhu-2025): the published moments as printed, why the
prediction takes the racquet flat, and how little the moments' uncertainties move it."""

from __future__ import annotations

import pytest
from poinsot import FreeRigidBody, InvalidInertiaError
from poinsot import experiments as x

#: The report's table (g·m²) and its stated one-sigma uncertainties, typed here from the page.
I1, I2, I3 = 20.7, 18.8, 1.391
S1, S2, S3 = 3.8, 5.7, 0.076


def test_the_published_central_moments_are_not_a_bodys_and_poinsot_refuses_them() -> None:
    assert I2 + I3 < I1  # by 0.509 g·m², 2.5 % of I1
    e = x.get("bubbar-zhu-2025")
    w = [
        float(e.parsed_inputs()[f"omega_{k}"].to("rad/s").magnitude)
        for k in ("primary", "intermediate", "tertiary")
    ]
    with pytest.raises(InvalidInertiaError, match="moments"):
        FreeRigidBody([I1 * 1e-3, I2 * 1e-3, I3 * 1e-3], w)


def test_the_flat_racquets_intermediate_moment_is_within_the_published_one() -> None:
    flat = I1 - I3
    assert abs(flat - I2) / S2 < 0.1
    e = x.get("bubbar-zhu-2025")
    i = e.parsed_inputs()
    assert i["moment_primary"].to("g*m**2").magnitude == pytest.approx(I1)
    assert i["moment_tertiary"].to("g*m**2").magnitude == pytest.approx(I3)
    assert "flat" in " ".join(e.assumptions)


def test_the_moments_uncertainties_move_the_prediction_by_a_few_percent_only() -> None:
    base = x.run("bubbar-zhu-2025").predicted_si
    assert base == pytest.approx(0.9238, abs=1e-4)
    for d1 in (-S1, S1):
        for d3 in (-S3, S3):
            r = x.run(
                "bubbar-zhu-2025",
                moment_primary=f"{I1 + d1} g*m**2",
                moment_tertiary=f"{I3 + d3} g*m**2",
            )
            assert r.predicted_si is not None
            assert abs(r.predicted_si / base - 1) < 0.03


def test_the_measured_period_and_its_stated_spread_give_the_verdict_in_sigma() -> None:
    r = x.run("bubbar-zhu-2025")
    assert r.measured_si == pytest.approx(0.9690)
    assert r.uncertainty_si == pytest.approx(0.0507)
    assert r.sigma == pytest.approx((0.9690 - r.predicted_si) / 0.0507)
    assert r.agrees and 0.5 < r.sigma < 1.2
    assert "σ" in r.verdict and "no uncertainty stated" not in r.verdict
    assert r.sources[0].url == "https://doi.org/10.14288/1.0448943"
    assert all("first-hand" in s.note for s in r.sources)


# ---- how each source was read, and the verdict without a stated uncertainty ---------------------


def test_a_source_records_whether_it_was_read_first_hand_and_keeps_it_through_json() -> None:
    import json

    from poinsot.experiments import Source

    r = x.run("bubbar-zhu-2025")
    back = type(r).from_dict(json.loads(json.dumps(r.to_dict())))
    assert [s.first_hand for s in back.sources] == [True, True]
    assert back.sources[0].reading == "read first-hand"
    assert Source("w", "x", "y", "z", "p", first_hand=False).reading == "second-hand"
    assert Source("w", "x", "y", "z", "p").reading == ""  # not recorded
    reich = x.get("reich-1831").sources
    assert reich[0].first_hand is False and reich[1].first_hand is True


def test_the_docs_page_says_how_each_source_was_read() -> None:
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "docs" / "_ext"))
    import world_pages

    e = x.get("reich-1831")
    page = world_pages.page_markdown(e, x.run("reich-1831"))
    assert page.count("*(second-hand)*") == 1 and page.count("*(read first-hand)*") == 3


def test_without_a_stated_uncertainty_the_verdict_names_the_five_percent_rule() -> None:
    r = x.run("foucault-1851")
    assert r.uncertainty is None and r.sigma is None
    assert (
        "no uncertainty stated" in r.verdict and f"within {x.AGREE_RELATIVE * 100:g} %" in r.verdict
    )


def test_every_source_says_whether_it_was_read_and_problems_flags_one_that_does_not() -> None:
    import dataclasses

    for e in x.catalogue():
        assert all(s.first_hand is not None for s in e.sources), e.name
    e = x.get("reich-1831")
    blank = dataclasses.replace(e.sources[0], first_hand=None)
    bad = dataclasses.replace(e, sources=(blank, *e.sources[1:]))
    assert x.problems(bad) == ["sources[0].first_hand is not recorded (was it read first-hand?)"]
