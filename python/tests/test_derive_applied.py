"""The derivations that apply the unit beyond its equations (``derive.applied()``) carry no
``PRINTED``: the unit prints none of their equations, and :func:`poinsot.derive.printed` reads
only the unit's topics. Every question's kind is the one its number's prefix names (issue 22:
the bank states each kind once, by the prefix)."""

from __future__ import annotations

import importlib

import pytest

pytest.importorskip("sympy")

from poinsot import derive


@pytest.mark.parametrize("name", derive.applied())
def test_applied_derivations_have_no_printed_equations(name: str) -> None:
    module = importlib.import_module(f"poinsot.derive.{name}")
    assert not hasattr(module, "PRINTED")
    assert "PRINTED" not in module.__all__
    assert {p.derivation for p in derive.printed()} <= set(derive.names())


def test_each_questions_kind_is_named_by_its_numbers_prefix() -> None:
    kinds = {"MC": "multiple choice", "S": "short", "L": "long"}
    questions = importlib.import_module("poinsot.derive.questions")
    bank = questions.questions()
    assert [q.kind for q in bank] == [kinds[q.number.split()[0]] for q in bank]
    assert [sum(q.kind == k for q in bank) for k in questions.KINDS] == [6, 13, 12]
