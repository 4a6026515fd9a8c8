"""The unit's question bank answered from the package (poinsot.derive.questions).

The unit's question bank section is parsed here, independently of the module, to check that
every question is present in the unit's order; the multiple-choice answers are checked against
the computed facts they claim (poinsot.classify, a torque-free simulation, the dumbbell's
holding torque), with negative controls; the derivation questions against their derivations
(every derivation the bank cites must exist: a missing one fails, it is not skipped).
"""

from __future__ import annotations

import dataclasses
import importlib
import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from unit_source import unit_text

pytest.importorskip("sympy")

import poinsot as ps
import poinsot.derive as pd
from poinsot.derive import names

_entry = pd.questions
qb = importlib.import_module("poinsot.derive.questions")
from poinsot.derive.questions import Question  # noqa: E402

if pd.questions is qb:
    # importing the submodule bound it over the package's function questions() (see the last
    # test); put the function back so that other tests of this session see the entry point
    pd.questions = _entry

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def bank() -> list[Question]:
    return qb.questions()


@pytest.fixture(scope="module")
def by_number(bank: list[Question]) -> dict[str, Question]:
    return {q.number: q for q in bank}


# ---- the unit's question bank, parsed independently -----------------------------------------------


def _parse_bank(text: str) -> dict[str, list[dict[str, object]]]:
    """The unit's questions after "Question Bank": kind → [{number, text, choices}]."""
    section = text[text.index("Question Bank") :]
    out: dict[str, list[dict[str, object]]] = {"multiple choice": [], "short": [], "long": []}
    kind = "multiple choice"
    for line in section.splitlines()[1:]:
        if "Short Questions" in line:
            kind = "short"
            continue
        if "Long Questions" in line:
            kind = "long"
            continue
        if not line.strip():
            continue
        if kind == "multiple choice":
            m = re.match(r"\s*\((\d+)\)\s*(.*)", line)
            if m:
                out[kind].append({"number": m.group(1), "text": m.group(2), "choices": []})
                continue
            for letter, word in re.findall(r"\(\s*([a-d])\s*\)\s*([^\t(]+)", line):
                choices = out[kind][-1]["choices"]
                assert isinstance(choices, list)
                choices.append((letter, word.strip()))
        elif line.startswith("- "):
            m = re.match(r"-\s+(?:(\d+)\.\s+)?(.*)", line)
            assert m is not None
            out[kind].append({"number": m.group(1), "text": m.group(2).strip(), "choices": []})
    return out


def _first_word(text: str) -> str:
    m = re.search(r"[A-Za-z]{2,}", text)
    assert m is not None, text
    return m.group(0)


def test_every_question_of_the_unit_is_there_in_its_order(bank: list[Question]) -> None:
    unit = _parse_bank(unit_text())
    assert [len(unit[k]) for k in qb.KINDS] == [6, 13, 12]
    for kind, prefix in zip(qb.KINDS, ("MC", "S", "L")):
        ours = [q for q in bank if q.kind == kind]
        assert len(ours) == len(unit[kind]), kind
        for q, u in zip(ours, unit[kind]):
            assert _first_word(q.text) == _first_word(str(u["text"])), (q.number, u)
            if u["number"] is not None:
                # the number as printed; the two MC 14 are told apart by a letter
                assert re.fullmatch(rf"{prefix} {u['number']}[ab]?", q.number), (q.number, u)
            else:
                assert "number" in q.note, q  # the scan lost it: the note says so
            utext = str(u["text"])
            if "$" not in utext and "\t" not in utext:
                assert q.text == utext  # nothing to mend: verbatim
            if kind == "multiple choice":
                words = [w for _, w in u["choices"]]  # type: ignore[attr-defined]
                assert list(q.choices) == words, q.number


def test_numbers_kinds_and_scan_notes(bank: list[Question]) -> None:
    numbers = [q.number for q in bank]
    assert numbers[:6] == ["MC 14a", "MC 14b", "MC 15", "MC 16", "MC 17", "MC 18"]
    assert numbers[6:19] == [f"S {k}" for k in range(1, 14)]
    assert numbers[19:] == [f"L {k}" for k in range(1, 13)]
    assert len(set(numbers)) == len(numbers)
    for q in bank:
        assert q.kind in qb.KINDS
        assert "\t" not in q.text and q.answer and q.how
        assert (len(q.choices) == 4) == (q.kind == "multiple choice")
        assert q.derivation is None or q.derivation in names()
        assert not q.results or q.derivation is not None
    assert "two questions 14" in bank[0].note and "two questions 14" in bank[1].note
    l10 = bank[-3]
    assert l10.number == "L 10" and "A² = (L² − 2I₃T)/(I₁(I₁ − I₃))" in l10.text
    assert "minus" in l10.note


def test_questions_are_frozen_and_shared(bank: list[Question]) -> None:
    assert qb.questions() == bank
    with pytest.raises(dataclasses.FrozenInstanceError):
        bank[0].answer = "(b) symmetrical top"  # type: ignore[misc]


# ---- MC 14–16: the kind of top ------------------------------------------------------------------


@pytest.mark.parametrize(
    ("number", "moments"),
    [
        ("MC 14a", (2.0, 2.0, 2.0)),
        ("MC 14b", (2.0, 2.0, 3.0)),
        ("MC 15", (2.0, 3.0, 4.0)),
        ("MC 16", (1.0, 1.0, 0.0)),
    ],
)
def test_mc_kind_answer_is_the_classification(
    by_number: dict[str, Question], number: str, moments: tuple[float, float, float]
) -> None:
    q = by_number[number]
    word = qb.UNIT_KIND[ps.classify(moments)]
    assert q.letter == "abcd"[q.choices.index(word)]
    assert q.answer.startswith(f"({q.letter}) {word}:")
    assert q.derivation is None  # answered by computation


def test_mc_kind_letters_and_the_unit_words(by_number: dict[str, Question]) -> None:
    letters = [by_number[n].letter for n in ("MC 14a", "MC 14b", "MC 15", "MC 16")]
    assert letters == ["a", "b", "c", "d"]
    assert set(qb.UNIT_KIND) == {"spherical top", "symmetric top", "asymmetric top", "rotor"}
    assert qb.UNIT_KIND["rotor"] == "rotator"


def test_kind_of_top_agrees_with_classify_at_random_moments() -> None:
    g = np.random.default_rng(2024)
    samplers = list(qb._CONDITIONS.values())
    for _ in range(25):
        for sample in samplers:
            m = sample(g)
            assert qb.kind_of_top(m) == qb.UNIT_KIND[ps.classify(m)]


def test_negative_control_kinds() -> None:
    # a body with all moments different is never answered "symmetrical top"
    assert qb.kind_of_top((1.0, 2.0, 2.5)) == "asymmetrical top"
    assert qb.answer_kind("I₁ ≠ I₂ ≠ I₃ (all different)") != "symmetrical top"
    # nor is a cuboid of three different sides
    assert qb.UNIT_KIND[ps.RigidBody.cuboid(1.0, (0.1, 0.2, 0.3)).kind] != "symmetrical top"


def test_negative_control_a_condition_with_two_answers_raises(monkeypatch) -> None:
    # I₁ ≠ I₂ ≠ I₃ read literally allows I₁ = I₃: then the question has no single answer
    def literal(g: np.random.Generator) -> np.ndarray:
        a, b = g.uniform(1.0, 2.0, size=2)
        return np.array([a, b, a if g.uniform() < 0.5 else 1.3 * a])

    monkeypatch.setitem(qb._CONDITIONS, "I₁ ≠ I₂ ≠ I₃ (all different)", literal)
    with pytest.raises(ps.PoinsotError, match="classified as"):
        qb.answer_kind("I₁ ≠ I₂ ≠ I₃ (all different)")
    with pytest.raises(ps.PoinsotError, match="condition"):
        qb.answer_kind("I₁ > I₂")


# ---- MC 17: what torque-free motion conserves ---------------------------------------------------


def test_mc17_only_the_angular_momentum_is_constant(by_number: dict[str, Question]) -> None:
    var = qb.torque_free_variation()
    assert var["angular momentum"] < 1e-12
    for k in ("angular velocity", "linear velocity", "angular acceleration"):
        assert var[k] > 1e-2, (k, var)
    q = by_number["MC 17"]
    assert qb.constant_quantities(var) == ("angular momentum",)
    assert q.letter == "c" and q.choices[2] == "angular momentum"


def test_mc17_momentum_agrees_with_the_exact_free_body() -> None:
    # the conserved L of simulate is the exact solution's (independent route: FreeRigidBody)
    moments, w0 = np.array([1.0, 2.0, 3.0]), np.array([1.0, 0.1, 1.0])
    tr = ps.simulate(moments, w0, 7.0, samples=50, method="dop853", rtol=1e-12, atol=1e-14)
    L = ps.FreeRigidBody(moments, w0).angular_momentum
    err = np.max(np.linalg.norm(tr.angular_momentum - L, axis=1)) / np.linalg.norm(L)
    assert err < 1e-9


def test_negative_control_a_steady_spin_conserves_too_much() -> None:
    # a symmetric top spun about its axis keeps ω (and ω̇ = 0) too: MC 17 would have three
    # answers, which is why it is answered with a generic asymmetric body
    var = qb.torque_free_variation((1.0, 1.0, 2.0), (0.0, 0.0, 3.0))
    assert set(qb.constant_quantities(var)) == {
        "angular velocity",
        "angular momentum",
        "angular acceleration",
    }
    with pytest.raises(ps.PoinsotError, match="cannot tell"):
        qb.constant_quantities({"angular momentum": 1e-6})


# ---- MC 18: what keeps a rotation going ----------------------------------------------------------


def test_mc18_the_dumbbell_needs_a_torque(by_number: dict[str, Question]) -> None:
    body, w = qb.dumbbell(), np.array([0.0, 0.0, 2.0])
    req = qb.holding_requirements(body, w)
    held = body.holding_torque(w)
    assert np.linalg.norm(req["torque"] - held) <= 1e-6 * np.linalg.norm(held)
    assert np.linalg.norm(held) > 0.5
    assert np.linalg.norm(req["force"]) < 1e-12
    assert qb.needed_to_hold(body, w) == ("torque",)
    q = by_number["MC 18"]
    assert q.letter == "d" and q.choices[3] == "torque"


def test_negative_control_principal_axis_needs_no_torque() -> None:
    # spun about a principal axis the dumbbell needs nothing: the axis is what makes MC 18 true
    body = qb.dumbbell()
    for k in range(3):
        w = 2.0 * body.principal_axes[:, k]
        assert qb.needed_to_hold(body, w) == ()
        assert np.linalg.norm(body.holding_torque(w)) < 1e-12


def test_negative_control_centre_off_the_axis_needs_a_force_too() -> None:
    body = qb.dumbbell().translated([0.2, 0.0, 0.0])
    w = np.array([0.0, 0.0, 2.0])
    req = qb.holding_requirements(body, w)
    # M ω × (ω × r_cm): centripetal force towards the axis, 2 kg · 4 s⁻² · 0.2 m = 1.6 N
    assert np.allclose(req["force"], [-1.6, 0.0, 0.0], rtol=1e-6)
    assert qb.needed_to_hold(body, w) == ("force", "torque")


def test_holding_torque_bridge_at_random_dumbbells() -> None:
    # the core's ω × L against numpy's ω × (I_O·ω) and the finite-difference dL/dt, 20 points
    g = np.random.default_rng(18)
    worst = 0.0
    for _ in range(20):
        m1, m2 = g.uniform(0.1, 5.0, size=2)
        r1, r2 = g.normal(size=(2, 3))
        body = ps.RigidBody.from_point_masses([m1, m2], [r1, r2])
        w = g.normal(size=3)
        n = body.holding_torque(w, about=np.zeros(3))
        io = body.inertia_about(np.zeros(3))
        ref = np.cross(w, io @ w)
        worst = max(worst, float(np.linalg.norm(n - ref) / np.linalg.norm(ref)))
        fd = qb.holding_requirements(body, w)["torque"]
        assert np.linalg.norm(fd - ref) <= 1e-5 * np.linalg.norm(ref)
    print(f"holding torque: worst relative difference {worst:.2e}")
    assert worst <= 1e-12


# ---- computed short answers ------------------------------------------------------------------------


def test_s4_the_earth_rates(by_number: dict[str, Question]) -> None:
    q = by_number["S 4"]
    solar = ps.Earth.solar_day().rotation_rate
    assert abs(solar / (2 * np.pi / 86400.0) - 1) <= 1e-15
    assert qb._sci(ps.Earth().rotation_rate) == "7.2921e-5"
    assert "7.2921e-5 rad/s" in q.answer and "7.2722e-5 rad/s" in q.answer
    assert "7.25e-5" in q.answer  # the unit's printed value, named as its slip


def test_s9_the_angle_between_omega_and_l(by_number: dict[str, Question]) -> None:
    # L of the dumbbell is perpendicular to its rod: at α from ω, L is 90° − α from ω
    g = np.random.default_rng(9)
    worst = 0.0
    for alpha in g.uniform(5.0, 85.0, size=20):
        body = qb.dumbbell(angle_deg=alpha)
        got = float(body.momentum_angle([0.0, 0.0, 2.0], degrees=True))
        worst = max(worst, abs(got - (90.0 - alpha)) / (90.0 - alpha))
    print(f"dumbbell angle: worst relative difference {worst:.2e}")
    assert worst <= 1e-12
    q = by_number["S 9"]
    assert "60° from ω" in q.answer and "principal axis the angle is 0°" in q.answer
    assert q.derivation == "rigid_body"


def test_long_answers_carry_the_package_numbers(by_number: dict[str, Question]) -> None:
    east = ps.Earth.solar_day(g=9.81).eastward_deflection(100.0, 45.0, degrees=True)
    assert qb._sci(float(east), 3) in by_number["L 5"].answer
    s = ps.HeavyTop.steady_precession(1.0, 0.5, 0.3, 0.6, 40.0)
    assert f"fast {s.fast:.6g} rad/s" in by_number["L 12"].answer
    assert "24.2176" in by_number["L 12"].answer  # seed-errata's exact fast root


# ---- the listing ------------------------------------------------------------------------------------


def test_render(bank: list[Question]) -> None:
    full = qb.render(bank)
    quiz = qb.render(bank, answers=False)
    for q in bank:
        assert re.search(rf"^{re.escape(q.number)} +\S", full, re.M), q.number
        assert re.search(rf"^{re.escape(q.number)} +\S", quiz, re.M), q.number
    assert full.count("Answer: ") == len(bank)
    assert "Answer:" not in quiz and "How:" not in quiz
    assert "(a) spherical top   (b) symmetrical top" in quiz
    assert max(len(line) for line in full.splitlines()) <= 100
    assert "poinsot derive torque_free_top (eqs. 2.96)" in full


# ---- the derivations that answer the derivation questions ------------------------------------------


@pytest.mark.parametrize("name", names())
def test_derivation_questions_point_at_derived_results(bank: list[Question], name: str) -> None:
    from poinsot.derive import derivation

    cited = [q for q in bank if q.derivation == name]
    d = derivation(name)  # a derivation the bank cites must exist: an ImportError fails
    assert d.steps
    for q in cited:
        missing = set(q.results) - set(d.result)
        assert not missing, f"{q.number} cites {sorted(missing)}, which {name} does not derive"


def test_package_entry_point_survives_a_second_call() -> None:
    code = (
        "import poinsot.derive as pd\n"
        "pd.questions()\n"
        "assert callable(pd.questions), type(pd.questions)\n"
        "assert pd.questions()[0].number == 'MC 14a'\n"
    )
    env = dict(os.environ, PYTHONPATH=str(Path(ps.__file__).resolve().parents[1]))
    run = subprocess.run(
        [sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=120
    )
    assert run.returncode == 0, run.stderr[-500:]
