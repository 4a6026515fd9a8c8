"""The site's pages written from poinsot.derive (docs/_ext/derive_pages.py): the kept errata
page is exactly what poinsot.derive.errata() gives, and the derivations page carries every
derivation and the question bank."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

pytest.importorskip("sympy")

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "docs" / "_ext"))

import derive_pages  # noqa: E402
from poinsot import derive  # noqa: E402


def test_the_kept_errata_page_is_the_computed_one() -> None:
    kept = derive_pages.ERRATA.read_text(encoding="utf-8")
    assert kept == derive_pages.errata_markdown(), (
        "docs/errata.md differs from poinsot.derive.errata(): run `make errata-page`"
    )


def test_the_errata_page_lists_each_erratum_once() -> None:
    text = derive_pages.errata_markdown()
    table = text.split("|---|---|---|\n", 1)[1].split("\n\n", 1)[0]
    rows = table.splitlines()
    assert [r.split("|")[1].strip().split("]")[0][1:] for r in rows] == [
        e.number for e in derive.errata()
    ]
    for e in derive.errata():
        assert f"### ({e.number})" in text and e.derived_latex() in text


def test_a_changed_transcription_changes_the_page(monkeypatch: pytest.MonkeyPatch) -> None:
    """Negative control: the page follows the computation, so dropping one erratum shows."""
    errata = derive.errata()
    monkeypatch.setattr(derive, "errata", lambda: errata[1:])
    assert derive_pages.errata_markdown() != derive_pages.ERRATA.read_text(encoding="utf-8")


def test_the_derivations_pages_have_every_derivation_and_the_questions() -> None:
    index = derive_pages.derivations_markdown()
    pages = derive_pages.derivation_pages()
    for d in derive.derivations():
        assert f"derivations/{d.name}.md" in index and f"derivations/{d.name}\n" in index
        text = pages[derive_pages.PAGES / f"{d.name}.md"]
        assert text.startswith(f"# {d.title}")
        for n in d.result:
            assert f"\\tag{{{n}}}" in text
    questions = pages[derive_pages.PAGES / "questions.md"]
    for q in derive.questions():
        assert f"**{q.number}.**" in questions


def test_erratum_tests_are_found_by_number() -> None:
    pins = derive_pages.pinning_tests()
    assert any("test_erratum_2_78" in t for t in pins["2.78"])
    assert any("test_erratum_2_2_2_3" in t for t in pins["2.3"])
