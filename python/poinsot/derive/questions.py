"""The unit's question bank (after eq. 2.121), each question answered from the package.

Covers
------
All 31 questions of the unit's "Question Bank", in its order: six multiple-choice (the scan
numbers them 14, 14, 15, 16, 17, 18; kept as "MC 14a", "MC 14b", "MC 15" … "MC 18"), thirteen
short ("S 1" … "S 13"; the scan lost the number of S 9) and twelve long ("L 1" … "L 12").

How they are answered
---------------------
* Multiple choice, by computation: the kind of top for the stated moments is what
  :attr:`poinsot.RigidBody.kind` says for moments sampled under the question's condition
  (:func:`kind_of_top`, :func:`answer_kind`); what torque-free motion conserves is read off a
  torque-free asymmetric body integrated by :func:`poinsot.simulate`
  (:func:`torque_free_variation`); what keeps a rotation going is what the unit's dumbbell turned
  at constant ω needs, the force M r̈_cm and the torque dL/dt computed from the package's turned
  body (:func:`holding_requirements`). The letter comes out of the computation.
* Derivation questions name the derivation of :mod:`poinsot.derive` that answers them
  (``Question.derivation``) and the unit's equation numbers of its results that hold the answer
  (``Question.results``); those derivations are built only when asked for.
* Short questions with a number compute it (S 4: :class:`poinsot.Earth`'s rate; S 9: the angle
  between ω and L of the dumbbell); definitions get a sentence and, in ``how``, the place where
  the package shows the idea.

Entry points: :func:`questions` (the list), :func:`render` (the plain-text listing that
``poinsot derive questions`` prints). SI units throughout (kg·m², rad/s, N, N·m).
"""

from __future__ import annotations

import textwrap
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from functools import cache
from typing import Any

import numpy as np

import poinsot as ps

from ..errors import PoinsotError

__all__ = [
    "Question",
    "KINDS",
    "questions",
    "render",
    "UNIT_KIND",
    "kind_of_top",
    "answer_kind",
    "torque_free_variation",
    "constant_quantities",
    "holding_requirements",
    "needed_to_hold",
    "dumbbell",
]

#: The kinds of question, in the unit's order (the headings of its question bank).
KINDS = ("multiple choice", "short", "long")
_LETTERS = "abcd"


@dataclass(frozen=True)
class Question:
    """One question of the unit's question bank, with its answer.

    Attributes
    ----------
    number:
        As printed, prefixed by its kind: "MC 14a", "S 4", "L 10".
    kind:
        "multiple choice", "short" or "long".
    text:
        The question, with the scan's stray tabs and broken words mended (``note`` says what).
    choices:
        The four choices (a)–(d) of a multiple-choice question, else ``()``.
    answer:
        A sentence; for multiple choice the letter and the choice first, "(a) spherical top: …".
    how:
        What computed the answer, or where the package shows the idea (a function, a docs page).
    derivation:
        The name of the :mod:`poinsot.derive` derivation that answers it, or ``None``.
    note:
        What was read into the scan, if anything.
    results:
        The unit's equation numbers of ``derivation``'s results that hold the answer (keys of
        its ``result``), possibly empty.
    """

    number: str
    kind: str
    text: str
    choices: tuple[str, ...] = ()
    answer: str = ""
    how: str = ""
    derivation: str | None = None
    note: str = ""
    results: tuple[str, ...] = ()

    @property
    def letter(self) -> str | None:
        """The letter of a multiple-choice answer ("a"…"d"), else ``None``."""
        if not self.choices or not self.answer.startswith("("):
            return None
        return self.answer[1]


# ---- small formatting helpers --------------------------------------------------------------------


def _sci(x: float, digits: int = 4) -> str:
    """``x`` as "7.2921e-5" (no zero padding of the exponent)."""
    mant, exp = f"{x:.{digits}e}".split("e")
    return f"{mant}e{int(exp)}"


def _vec(v: Any, digits: int = 4) -> str:
    return "(" + ", ".join(f"{float(x):.{digits}g}" for x in np.asarray(v, dtype=float)) + ")"


def _choice(choices: Sequence[str], word: str) -> str:
    """ "(c) angular momentum" for the choice ``word`` (raises if it is not one of them)."""
    if word not in choices:
        raise PoinsotError(f"the computed answer {word!r} is none of the choices {choices}")
    k = list(choices).index(word)
    return f"({_LETTERS[k]}) {word}"


# ---- MC 14–16: the kind of top -------------------------------------------------------------------

#: The package's names of the kinds of top (:func:`poinsot.classify`) → the unit's words (its
#: definitions after eq. 2.66 and the choices of MC 14–16).
UNIT_KIND: Mapping[str, str] = {
    "spherical top": "spherical top",
    "symmetric top": "symmetrical top",
    "asymmetric top": "asymmetrical top",
    "rotor": "rotator",
}


def kind_of_top(moments: Any) -> str:
    """The unit's name of the kind of top of principal moments ``moments`` (kg·m², (3,)): the
    :attr:`poinsot.RigidBody.kind` of a 1 kg body with that diagonal inertia tensor, in the
    unit's words (:data:`UNIT_KIND`)."""
    body = ps.RigidBody.from_inertia(1.0, np.diag(np.asarray(moments, dtype=float)))
    return UNIT_KIND[body.kind]


def _equal3(g: np.random.Generator) -> np.ndarray:
    return np.full(3, g.uniform(0.1, 10.0))


def _two_equal(g: np.random.Generator) -> np.ndarray:
    a = g.uniform(0.1, 10.0)
    ratio = g.uniform(0.05, 0.95) if g.uniform() < 0.5 else g.uniform(1.05, 2.0)
    return np.array([a, a, a * ratio])


def _all_different(g: np.random.Generator) -> np.ndarray:
    # x < y < z ≤ x + y (a body's moments obey the triangle inequality), in a random order
    x = g.uniform(0.1, 10.0)
    y = x * (1.0 + g.uniform(0.05, 1.0))
    z = y + x * g.uniform(0.05, 0.95)
    return g.permutation(np.array([x, y, z]))


def _rotator(g: np.random.Generator) -> np.ndarray:
    a = g.uniform(0.1, 10.0)
    return np.array([a, a, 0.0])


#: Samplers of principal moments obeying each condition of MC 14–16 (as the unit defines them).
_CONDITIONS: dict[str, Callable[[np.random.Generator], np.ndarray]] = {
    "I₁ = I₂ = I₃": _equal3,
    "I₁ = I₂ ≠ I₃": _two_equal,
    "I₁ ≠ I₂ ≠ I₃ (all different)": _all_different,
    "I₁ = I₂, I₃ = 0": _rotator,
}


def _examples() -> dict[str, tuple[str, Any]]:
    """A solid of each condition: (its description, the body)."""
    return {
        "I₁ = I₂ = I₃": ("a solid sphere", ps.RigidBody.solid_sphere(1.0, 0.1)),
        "I₁ = I₂ ≠ I₃": ("a solid cylinder", ps.RigidBody.solid_cylinder(1.0, 0.1, 0.5)),
        "I₁ ≠ I₂ ≠ I₃ (all different)": (
            "a 0.1 × 0.2 × 0.3 m cuboid",
            ps.RigidBody.cuboid(1.0, (0.1, 0.2, 0.3)),
        ),
        "I₁ = I₂, I₃ = 0": (
            "a diatomic molecule (two point masses)",
            ps.RigidBody.from_point_masses([1.0, 1.0], [[0.0, 0.0, 0.06], [0.0, 0.0, -0.06]]),
        ),
    }


def answer_kind(condition: str, samples: int = 20, seed: int = 14) -> str:
    """The unit's name of the kind of top of every body whose principal moments obey
    ``condition`` (a key of the samplers: "I₁ = I₂ = I₃", "I₁ = I₂ ≠ I₃",
    "I₁ ≠ I₂ ≠ I₃ (all different)", "I₁ = I₂, I₃ = 0"): :func:`kind_of_top` of ``samples``
    moments drawn under the condition (seeded) and of a solid that obeys it.

    Raises
    ------
    PoinsotError
        the bodies do not all get the same kind (the question would have no single answer).
    """
    if condition not in _CONDITIONS:
        raise PoinsotError(f"condition: one of {', '.join(_CONDITIONS)}, got {condition!r}")
    g = np.random.default_rng(seed)
    kinds = {kind_of_top(_CONDITIONS[condition](g)) for _ in range(samples)}
    _, example = _examples()[condition]
    kinds.add(UNIT_KIND[example.kind])
    if len(kinds) != 1:
        raise PoinsotError(f"bodies with {condition} are classified as {sorted(kinds)}")
    return kinds.pop()


# ---- MC 17: what torque-free motion conserves ----------------------------------------------------

#: The four choices of MC 17, in the unit's order.
_MC17 = ("angular velocity", "linear velocity", "angular momentum", "angular acceleration")


def torque_free_variation(
    moments: Any = (1.0, 2.0, 3.0),
    omega0: Any = (1.0, 0.1, 1.0),
    point: Any = (0.3, 0.2, 0.1),
    samples: int = 4001,
) -> dict[str, float]:
    """How much each quantity of MC 17 varies in the fixed frame while a body of principal
    moments ``moments`` (kg·m²) turns free of torque from body angular velocity ``omega0``
    (rad/s), over one period of ω(t) (:attr:`poinsot.FreeRigidBody.period`; 10 s if steady).

    The motion is :func:`poinsot.simulate` without torque; ω in space is R(t) ω_body(t), the
    angular acceleration its time derivative (second-order central differences of the samples),
    the angular momentum the trajectory's space-frame L, the linear velocity that of the
    material point at body position ``point`` (m), v = ω × R(t) r.

    Returns
    -------
    dict
        choice → max_t |x(t) − x(0)| / its natural scale (max |ω|, max |ω| |r|, max |L|,
        max |ω|²): dimensionless, 0 for a constant vector (a zero one included).
    """
    moments = np.asarray(moments, dtype=float)
    r = np.asarray(point, dtype=float)
    period = ps.FreeRigidBody(moments, omega0).period
    duration = period if np.isfinite(period) else 10.0
    tr = ps.simulate(moments, omega0, duration, samples=samples)
    R = ps.quaternion_to_matrix(tr.attitude)
    w = np.einsum("nij,nj->ni", R, tr.omega)
    L = np.asarray(tr.angular_momentum)
    rate = float(np.max(np.linalg.norm(w, axis=1)))
    series = {
        "angular velocity": (w, rate),
        "linear velocity": (
            np.cross(w, np.einsum("nij,j->ni", R, r)),
            rate * float(np.linalg.norm(r)),
        ),
        "angular momentum": (L, float(np.max(np.linalg.norm(L, axis=1)))),
        "angular acceleration": (np.gradient(w, tr.t, axis=0, edge_order=2), rate**2),
    }
    return {
        name: float(np.max(np.linalg.norm(x - x[0], axis=1)) / scale)
        for name, (x, scale) in series.items()
    }


def constant_quantities(
    variation: Mapping[str, float], constant: float = 1e-9, changing: float = 1e-3
) -> tuple[str, ...]:
    """The quantities whose relative variation (:func:`torque_free_variation`) is at most
    ``constant``. Raises :class:`PoinsotError` for one between ``constant`` and ``changing``:
    neither clearly conserved nor clearly changing, so no answer should be read from it."""
    unclear = [k for k, v in variation.items() if constant < v < changing]
    if unclear:
        raise PoinsotError(f"cannot tell whether {unclear} are constant: {dict(variation)}")
    return tuple(k for k, v in variation.items() if v <= constant)


# ---- MC 18: what must be applied to keep a rotation ----------------------------------------------

#: The four choices of MC 18, in the unit's order.
_MC18 = ("force", "momentum", "velocity", "torque")
#: What can be *applied* to a body: the actions on the right of Newton's F = dp/dt and of
#: dL/dt = N (2.67). Momentum and velocity are states of the motion, not actions on it.
_APPLIED = ("force", "torque")


def dumbbell(mass: float = 1.0, half_length: float = 0.5, angle_deg: float = 30.0) -> Any:
    """The unit's dumbbell (Fig. 2.9): two point masses ``mass`` (kg) at ±``half_length`` (m)
    on a massless rod through the origin, at ``angle_deg`` (degrees) from the z axis in the
    x-z plane (a :class:`poinsot.RigidBody`)."""
    a = np.radians(angle_deg)
    r = half_length * np.array([np.sin(a), 0.0, np.cos(a)])
    return ps.RigidBody.from_point_masses([mass, mass], [r, -r])


def holding_requirements(body: Any, omega: Any, step: float = 1e-3) -> dict[str, np.ndarray]:
    """The net force (N) and torque about the origin (N·m) that must act on ``body`` (a
    :class:`poinsot.RigidBody`) to keep it turning at the constant angular velocity ``omega``
    (rad/s, (3,)) about a fixed axis through the origin.

    Computed from the package's body turned by R(t) = rotation by |ω| t about ω
    (:meth:`poinsot.RigidBody.rotated`): force = M d²r_cm/dt², torque = dL/dt with
    L(t) = I_O(t)·ω (:meth:`poinsot.RigidBody.angular_momentum` about the origin), by central
    differences of step ``step``/|ω| s. The torque is checked against the package's
    :meth:`poinsot.RigidBody.holding_torque` (ω × L, eqs. 2.58–2.59).

    Raises
    ------
    PoinsotError
        ω = 0, or the two torques disagree by more than 1e-5 of |ω|² I (I the largest moment
        about the origin; they cannot, unless the package is wrong).
    """
    w = np.asarray(omega, dtype=float)
    rate = float(np.linalg.norm(w))
    if rate == 0.0:
        raise PoinsotError("omega: must be nonzero")
    h = step / rate
    origin = np.zeros(3)

    def turned(t: float) -> Any:
        return body.rotated(ps.axis_angle_to_matrix(w, rate * t))

    before, now, after = turned(-h), turned(0.0), turned(h)
    accel = (after.center_of_mass - 2 * now.center_of_mass + before.center_of_mass) / h**2
    torque = (
        after.angular_momentum(w, about=origin) - before.angular_momentum(w, about=origin)
    ) / (2 * h)
    held = body.holding_torque(w, about=origin)
    big = float(np.max(np.linalg.eigvalsh(body.inertia_about(origin))))
    if np.linalg.norm(torque - held) > 1e-5 * rate**2 * big:
        raise PoinsotError(f"dL/dt = {torque} but holding_torque = {held}")
    return {"force": body.mass * accel, "torque": torque}


def needed_to_hold(body: Any, omega: Any, rtol: float = 1e-6) -> tuple[str, ...]:
    """Which of the choices of MC 18 must be applied to keep ``body`` turning at constant
    ``omega`` about a fixed axis through the origin: the applied actions (force, torque) whose
    required value (:func:`holding_requirements`) is nonzero, i.e. above ``rtol`` times its
    scale (M |ω|² ρ for the force, |ω| I ω for the torque; ρ the radius of gyration about the
    origin, I the largest moment there). Empty when nothing needs to act."""
    w = np.asarray(omega, dtype=float)
    req = holding_requirements(body, w)
    io = body.inertia_about(np.zeros(3))
    big = float(np.max(np.linalg.eigvalsh(io)))
    rate = float(np.linalg.norm(w))
    scale = {
        "force": body.mass * rate**2 * np.sqrt(big / body.mass),
        "torque": rate * big * rate,
    }
    return tuple(k for k in _APPLIED if np.linalg.norm(req[k]) > rtol * scale[k])


# ---- the questions -------------------------------------------------------------------------------

_TOPS = ("spherical top", "symmetrical top", "asymmetrical top", "rotator")

#: A question's kind by the prefix of its number ("MC 14a", "S 4", "L 10").
_KIND_OF_PREFIX = dict(zip(("MC", "S", "L"), KINDS))


def _ask(number: str, *fields: Any, **named: Any) -> Question:
    """The :class:`Question` numbered ``number``, of the kind its prefix says; ``fields`` and
    ``named`` are the rest of its fields (``text`` first), as :class:`Question` takes them."""
    return Question(number, _KIND_OF_PREFIX[number.split()[0]], *fields, **named)


def _mc_kind(number: str, condition: str, text: str, note: str) -> Question:
    word = answer_kind(condition)
    desc, example = _examples()[condition]
    pkg = {v: k for k, v in UNIT_KIND.items()}[word]
    return _ask(
        number,
        text,
        _TOPS,
        f"{_choice(_TOPS, word)}: poinsot classifies every body with {condition} as {pkg!r}.",
        f"poinsot.RigidBody(...).kind of 20 bodies with principal moments drawn under "
        f"{condition} (seeded), and of {desc} ({_vec(example.principal_moments, 3)} kg·m²): "
        f"{pkg!r}, the unit's {word!r} (its definitions after eq. 2.66; "
        "poinsot.derive.questions.answer_kind, poinsot.classify, docs/inertia.md).",
        None,
        note,
    )


def _mc17() -> Question:
    var = torque_free_variation()
    const = constant_quantities(var)
    if len(const) != 1:
        raise PoinsotError(f"MC 17: the constant quantities are {const}, not exactly one")
    spread = ", ".join(f"{k} {_sci(v, 1)}" for k, v in var.items())
    return _ask(
        "MC 17",
        "In a torque free motion of a rigid body, the ____ of the body is a constant vector",
        _MC17,
        f"{_choice(_MC17, const[0])}: of the four, only it stays fixed in space while a "
        "torque-free body turns (L = constant, 2.67 with N = 0).",
        "poinsot.simulate of a torque-free asymmetric body (I = (1, 2, 3) kg·m², "
        "ω₀ = (1, 0.1, 1) rad/s) over one period; relative variation in the fixed frame: "
        f"{spread} (poinsot.derive.questions.torque_free_variation). The linear velocity is that "
        "of a point of the body, v = ω × r, which turns with it; the centre of mass's velocity "
        "is set by the net force, about which 'torque-free' says nothing (in free fall a body "
        "is torque-free about its centre of mass while that velocity grows by g t).",
        None,
        "The scan reads 'In a torque free motion of a rig vector<tab>id body, the of the body is a "
        "constant': 'vector' slipped into 'rig|id' and the blank was lost; mended after the "
        "unit's own sentence after eq. 2.96 ('the angular momentum of the body is a constant "
        "vector').",
    )


def _mc18() -> Question:
    body = dumbbell()
    spin = np.array([0.0, 0.0, 2.0])
    need = needed_to_hold(body, spin)
    if len(need) != 1:
        raise PoinsotError(f"MC 18: the dumbbell needs {need}, not exactly one applied action")
    req = holding_requirements(body, spin)
    principal = body.principal_axes[:, 2] * 2.0
    free = needed_to_hold(body, principal)
    return _ask(
        "MC 18",
        "____ must be applied to maintain the rotation of the system about given axis",
        _MC18,
        f"{_choice(_MC18, need[0])}: L turns with the body, so dL/dt = N ≠ 0 must be supplied "
        "(eqs. 2.58–2.59); no net force is needed, the centre of mass is on the axis.",
        "The unit's dumbbell (two 1 kg masses at ±0.5 m on a rod at 30° to ω = 2 rad/s ẑ, "
        "poinsot.derive.questions.dumbbell) turned by the package: required force "
        f"M r̈_cm = {_vec(req['force'], 3)} N, torque dL/dt = {_vec(req['torque'], 4)} N·m "
        "(= RigidBody.holding_torque, ω × L); spun about a principal axis it needs "
        f"{' and '.join(free) if free else 'nothing'}. Momentum and velocity are states of the "
        "motion, not something applied (poinsot.derive.questions.needed_to_hold).",
        "rigid_body",
        "The blank at the start is the scan's; 'm<tab>naintain' mended to 'maintain'.",
    )


def _s3_how() -> str:
    r, v = [1.0, 2.0, 0.5], [0.3, -0.2, 0.4]
    moving = ps.MovingFrame(velocity=[3.0, 0.0, 0.0]).fictitious_forces(1.0, r, v)
    turning = ps.MovingFrame(angular_velocity=[0.0, 0.0, 1.0]).fictitious_forces(1.0, r, v)
    biggest = max(float(np.linalg.norm(f)) for f in moving.values())
    return (
        "poinsot.MovingFrame(...).fictitious_forces(1 kg, r, ṙ): in a frame moving at 3 m/s "
        f"the largest is {biggest:g} N; in one turning at 1 rad/s the Coriolis force is "
        f"{np.linalg.norm(turning['coriolis']):.3g} N and the centrifugal "
        f"{np.linalg.norm(turning['centrifugal']):.3g} N (docs/frames.md)."
    )


def _s4() -> Question:
    sidereal = ps.Earth()
    solar = ps.Earth.solar_day()
    ws, wd = sidereal.rotation_rate, solar.rotation_rate
    return _ask(
        "S 4",
        "Find the angular velocity of the earth",
        answer=(
            f"ω = 2π / (one turn): with the sidereal day ({2 * np.pi / ws:.1f} s) "
            f"ω = {_sci(ws)} rad/s, the true rate; with the unit's solar day "
            f"2π/(24 × 60 × 60 s) = {_sci(wd)} rad/s, which the unit prints as 7.25e-5 rad/s "
            "(an arithmetic slip). It points along the axis from the South to the North Pole."
        ),
        how=(
            "poinsot.Earth().rotation_rate (sidereal, the default) and "
            "poinsot.Earth.solar_day().rotation_rate (the unit's value); docs/earth.md."
        ),
        derivation="earth",
        note="The unit's value 2π/(24·60·60) = 7.25e-5 rad/s (before eq. 2.32) is a slip for "
        "7.27e-5 (seed errata, 'Earth's rate').",
    )


def _s9() -> Question:
    body = dumbbell()
    spin = np.array([0.0, 0.0, 2.0])
    angle = float(body.momentum_angle(spin, degrees=True))
    axis = body.principal_axes[:, 2] * 2.0
    along = float(body.momentum_angle(axis, degrees=True))
    along = 0.0 if abs(along) < 1e-9 else along  # round-off of an exact 0 reads 0
    return _ask(
        "S 9",
        "Show that the directions of the angular velocity and the angular momentum are different",
        answer=(
            "L = I·ω (2.63): turning about z, L = (I_xz ω, I_yz ω, I_zz ω) (2.57), which has "
            "x and y parts whenever the products of inertia are nonzero, so L leaves the "
            "direction of ω unless ω is along a principal axis. For the unit's dumbbell (two "
            f"1 kg masses at ±0.5 m, rod at 30° to ω) L is {angle:.6g}° from ω (it is "
            f"perpendicular to the rod); about a principal axis the angle is {along:.3g}°."
        ),
        how=(
            "poinsot.RigidBody.momentum_angle of poinsot.derive.questions.dumbbell(); "
            "docs/inertia.md ('Angular momentum and kinetic energy')."
        ),
        derivation="rigid_body",
        note="The scan lost this question's number 9 (it stands between 8 and 10).",
    )


def _s10_s11_how(*names: str) -> str:
    examples = {
        "spherical top": [2.0, 2.0, 2.0],
        "asymmetric top": [1.0, 2.0, 3.0],
        "symmetric top": [2.0, 2.0, 3.0],
        "rotor": [1.0, 1.0, 0.0],
    }
    calls = "; ".join(
        f"poinsot.classify({[int(x) for x in examples[n]]}) = {ps.classify(examples[n])!r}"
        for n in names
    )
    return f"{calls} (the unit's {' and '.join(UNIT_KIND[n] for n in names)}); docs/inertia.md."


def _l4_answer() -> str:
    unit = ps.Earth("solar", radius=6.4e6)
    a = float(np.linalg.norm(unit.centrifugal_acceleration(0.0)))
    return (
        "In the Earth's turning frame m r̈ = F + m g_e − 2m ω × ṙ (2.30; the unit drops the m of "
        "the Coriolis term), with effective gravity g_e = g − ω × (ω × r) (2.31): the "
        "centrifugal part points away from the axis, is zero at the poles and largest at the "
        f"equator, ω²r = {a:.3g} m/s² (unit's ω and r = 6.4e6 m); the Coriolis force deflects "
        "moving bodies (falling bodies east, winds, the Foucault pendulum's plane)."
    )


def _l5_answer() -> str:
    unit = ps.Earth.solar_day(g=9.81).eastward_deflection(100.0, 45.0, degrees=True)
    true = ps.Earth().eastward_deflection(100.0, 45.0, degrees=True)
    return (
        "Solving m r̈ = m g − 2m ω × ṙ by successive approximation (2.32–2.41), the first order "
        "gives an eastward deflection x = ⅓ ω g t³ cos λ = ⅓ ω cos λ √(8h³/g) (2.42); for "
        f"100 m at latitude 45°: {_sci(float(unit), 3)} m (unit's solar-day ω, g = 9.81) or "
        f"{_sci(float(true), 3)} m (sidereal ω), the unit's 1.55e-2 m. The next order adds a "
        "small southward deflection (derived in 'earth')."
    )


def _l6_how() -> str:
    R = ps.euler_to_matrix([0.3, 0.5, 0.7])
    n, a = ps.rotation_axis(R)
    return (
        "poinsot.rotation_axis(R) returns the axis n and angle of any rotation: for "
        f"R = euler_to_matrix([0.3, 0.5, 0.7]), n = {_vec(n, 4)}, angle {a:.4f} rad, "
        f"|R n − n| = {_sci(float(np.linalg.norm(R @ n - n)), 1)}; docs/rotation.md "
        "('Euler's theorem'). None of the seven derivations covers this theorem."
    )


def _l10_answer() -> str:
    top = ps.FreeSymmetricTop(2.0, 1.0, [0.3, 0.4, 2.0])
    a2 = ps.FreeSymmetricTop.amplitude_squared_from(
        2.0, 1.0, top.energy, top.angular_momentum_magnitude
    )
    return (
        "With I₁ = I₂ and N = 0, Euler's equations give ω₃ constant and ω̇₁ = Ωω₂, "
        "ω̇₂ = −Ωω₁ with Ω = (I₁ − I₃)ω₃/I₁ (2.77–2.83): ω₁, ω₂ turn at Ω with constant "
        "amplitude A (2.85–2.88), ω precesses on the body cone, tan α_b = A/ω₃ (2.90). From "
        "T = ½I₁A² + ½I₃ω₃² and L² = I₁²A² + I₃²ω₃² (2.91, 2.93), eliminating ω₃ gives "
        "A² = (L² − 2I₃T)/(I₁(I₁ − I₃)) (2.96). L is fixed in space and ω goes round it on the "
        "space cone, cos α_s = 2T/(ωL) (2.97). E.g. I₁ = 2, I₃ = 1 kg·m², "
        f"ω = (0.3, 0.4, 2) rad/s: A² = {top.amplitude**2:.12g} (rad/s)² from ω₁² + ω₂², "
        f"{a2:.12g} from T and L."
    )


def _l12_answer() -> str:
    s = ps.HeavyTop.steady_precession(1.0, 0.5, 0.3, 0.6, 40.0)
    wmin = ps.HeavyTop.min_spin(1.0, 0.5, 0.3, 0.6)
    return (
        "With V = m g l cos θ the Lagrangian (2.102) has φ and ψ cyclic: p_ψ = I₃ω₃ and p_φ are "
        "constant (2.103–2.104); the total energy E = ½I₁(θ̇² + φ̇² sin²θ) + ½I₃ω₃² + m g l cos θ "
        "(2.105), or E′ = E − p_ψ²/(2I₃) = ½I₁θ̇² + V(θ) (2.108–2.109), confines θ between two "
        "turning points. Steady precession (θ̇ = 0 at the minimum of V) needs "
        "φ̇ = p_ψ(1 ± √(1 − 4 m g l I₁ cos θ₀/p_ψ²))/(2I₁ cos θ₀) (2.117, p_ψ not the unit's "
        "p_φ), real only for ω₃ ≥ (2/I₃)√(m g l I₁ cos θ₀) (2.119); fast ≈ I₃ω₃/(I₁ cos θ₀) "
        "(2.120 without the unit's factor 2), slow ≈ m g l/(I₃ω₃) (2.121). E.g. I₁ = 1, "
        "I₃ = 0.5 kg·m², m g l = 0.3 J, θ₀ = 0.6 rad, ω₃ = 40 rad/s: "
        f"slow {s.slow:.6g} rad/s, fast {s.fast:.6g} rad/s; minimum spin {wmin:.4g} rad/s."
    )


@cache
def _questions() -> tuple[Question, ...]:
    mc = [
        _mc_kind(
            "MC 14a",
            "I₁ = I₂ = I₃",
            "If I₁ = I₂ = I₃, then the body is called",
            "The scan numbers two questions 14; this is the first (14a). 'c<tab>called' mended.",
        ),
        _mc_kind(
            "MC 14b",
            "I₁ = I₂ ≠ I₃",
            "If I₁ = I₂ ≠ I₃, then the body is called",
            "The scan numbers two questions 14; this is the second (14b). 'a<tab>alled' mended to "
            "'called'.",
        ),
        _mc_kind(
            "MC 15",
            "I₁ ≠ I₂ ≠ I₃ (all different)",
            "If I₁ ≠ I₂ ≠ I₃, then the body is called",
            "'a<tab>called' mended to 'called'. I₁ ≠ I₂ ≠ I₃ as printed would allow I₁ = I₃; read "
            "as the unit's definition after eq. 2.66, all three different.",
        ),
        _mc_kind(
            "MC 16",
            "I₁ = I₂, I₃ = 0",
            "If I₁ = I₂ and I₃ = 0, then the body is called",
            "'bo<tab>dy' mended to 'body'.",
        ),
        _mc17(),
        _mc18(),
    ]
    short = [
        _ask(
            "S 1",
            "Define rigid body",
            answer="A system of particles whose mutual distances never change, "
            "|r_a − r_b| = constant: its motion is a translation of one point plus a rotation "
            "about it (six coordinates).",
            how="poinsot.RigidBody: mass, centre of mass and inertia tensor are all of a rigid "
            "body that its motion needs; docs/inertia.md.",
        ),
        _ask(
            "S 2",
            "Define frame of reference",
            answer="A set of coordinate axes with an origin (and a clock) from which positions, "
            "velocities and accelerations are measured; the unit uses a fixed (primed) and a "
            "moving (unprimed) frame.",
            how="poinsot.MovingFrame (a moving frame's origin, velocity, acceleration, ω, ω̇ and "
            "attitude relative to the fixed one); docs/frames.md.",
        ),
        _ask(
            "S 3",
            "Define inertial and non-inertial frame of reference",
            answer="An inertial frame is one in which Newton's laws hold as they stand (a free "
            "particle moves uniformly); every frame moving at constant velocity relative to one "
            "is inertial. A non-inertial frame accelerates or rotates relative to an inertial "
            "one: in it a particle seems pushed by fictitious forces −m R̈, −2m ω × ṙ, "
            "−m ω × (ω × r), −m ω̇ × r (2.5, 2.26).",
            how=_s3_how(),
            derivation="frames",
        ),
        _s4(),
        _ask(
            "S 5",
            "State the Euler's theorem",
            answer="Any displacement of a rigid body with one point fixed is a rotation about "
            "some axis through that fixed point.",
            how="poinsot.rotation_axis(R) gives that axis and angle for any rotation matrix; "
            "docs/rotation.md ('Euler's theorem').",
        ),
        _ask(
            "S 6",
            "State the Chasles' theorem",
            answer="The most general displacement of a rigid body is a translation plus a "
            "rotation about some axis; choosing the translation along that axis makes it a "
            "screw motion.",
            how="poinsot.screw_axis(R, t) gives the screw (axis, point, angle, slide) of any "
            "displacement x ↦ R x + t; docs/rotation.md ('Chasles' theorem').",
        ),
        _ask(
            "S 7",
            "Write the expressions of components of angular momentum",
            answer="L_x = I_xx ω_x + I_xy ω_y + I_xz ω_z, L_y = I_yx ω_x + I_yy ω_y + I_yz ω_z, "
            "L_z = I_zx ω_x + I_zy ω_y + I_zz ω_z (2.50), i.e. L_i = Σ_j I_ij ω_j (2.51, summed "
            "over j; the unit prints Σ_i), with I_xx = Σ m (y² + z²), I_xy = −Σ m x y.",
            how="Derived from L = Σ m r × (ω × r) in 'rigid_body'; computed by "
            "poinsot.RigidBody.angular_momentum; docs/inertia.md.",
            derivation="rigid_body",
            results=("2.51",),
        ),
        _ask(
            "S 8",
            "Derive the expression of kinetic energy of rotation of rigid body",
            answer="T = Σ ½ m v² with v = ω × r gives T = ½ ω·L = ½ Σ_ij I_ij ω_i ω_j "
            "(2.52–2.55); in principal axes T = ½(I₁ω₁² + I₂ω₂² + I₃ω₃²) (2.66, the unit "
            "prints I_i for I₁), and ½Iω² for a rotation about one axis (2.56).",
            how="The derivation 'rigid_body' (poinsot derive rigid_body); computed by "
            "poinsot.RigidBody.kinetic_energy; docs/inertia.md.",
            derivation="rigid_body",
            results=("2.66",),
        ),
        _s9(),
        _ask(
            "S 10",
            "Define spherical top and asymmetric top",
            answer="A spherical top has its three principal moments equal, I₁ = I₂ = I₃; an "
            "asymmetric top has all three different.",
            how=_s10_s11_how("spherical top", "asymmetric top"),
        ),
        _ask(
            "S 11",
            "Define symmetrical top and rigid rotator",
            answer="A symmetrical top has two equal principal moments, I₁ = I₂ ≠ I₃ (axis 3 is "
            "its symmetry axis); a rigid rotator has I₁ = I₂ and I₃ = 0, all its mass on one "
            "line, like a diatomic molecule.",
            how=_s10_s11_how("symmetric top", "rotor"),
        ),
        _ask(
            "S 12",
            "What you mean by torque free motion",
            answer="The motion of a rigid body on which the net external torque is zero: its "
            "angular momentum L is constant in space (2.67 with N = 0) and so is its kinetic "
            "energy, while ω moves round L (the body cone rolls on the space cone, 2.90–2.97).",
            how="poinsot.FreeSymmetricTop (2.77–2.97) and poinsot.FreeRigidBody (any body), "
            "poinsot.simulate without torque; docs/dynamics.md.",
            derivation="torque_free_top",
        ),
        _ask(
            "S 13",
            "Define precessional velocity",
            answer="The angular velocity with which the axis of a spinning body turns about "
            "another direction: for the heavy top φ̇ (with θ̇ = 0), the rate at which axis 3 goes "
            "round the vertical Z; for the free symmetric top Ω = (I₁ − I₃)ω₃/I₁, the rate at "
            "which ω goes round axis 3 (2.83).",
            how="poinsot.HeavyTop.steady_precession (2.116–2.121) and "
            "poinsot.FreeSymmetricTop.precession_rate (2.83); docs/heavy_top.md, "
            "docs/dynamics.md.",
            derivation="heavy_top",
        ),
    ]
    long = [
        _ask(
            "L 1",
            "Explain the coordinates with relative translational motion",
            answer="With the frame O(x, y, z) translating relative to the fixed O′(x′, y′, z′), "
            "R = O′O: r′ = R + r (2.1), ṙ′ = Ṙ + ṙ and r̈′ = R̈ + r̈ (2.2–2.3; the scan lost "
            "the dots), so m r̈ = F − m R̈ (2.5): a frame moving uniformly (R̈ = 0) is inertial "
            "(Galilean invariance), an accelerated one adds the force −m R̈.",
            how="The derivation 'frames'; poinsot.MovingFrame(velocity=..., "
            "acceleration=...).to_fixed; docs/frames.md.",
            derivation="frames",
            results=("2.3", "2.5"),
        ),
        _ask(
            "L 2",
            "Discuss the rotating coordinate systems and derive the expressions of velocity and "
            "acceleration of the particle.",
            answer="A vector's rate seen from fixed and turning axes differ by the turning of "
            "the unit vectors, dî/dt = ω × î (2.12–2.13): (d/dt)_fix = (d/dt)_rot + ω × (2.14). "
            "Then ṙ′ = Ṙ + ṙ_rot + ω × r (2.20) and r̈′ = R̈ + r̈_rot + 2ω × ṙ_rot + ω × (ω × r) "
            "+ ω̇ × r (2.21): relative, Coriolis, centripetal and transverse accelerations.",
            how="The derivation 'frames'; poinsot.MovingFrame.to_fixed / to_moving compute "
            "both; docs/frames.md.",
            derivation="frames",
            results=("2.20", "2.21"),
        ),
        _ask(
            "L 3",
            "Write note on Coriolis force",
            answer="In a frame turning with ω, a particle moving with velocity v_r relative to "
            "it feels the Coriolis force −2m ω × v_r (2.26, 2.30): perpendicular to ω and v_r, "
            "it does no work and vanishes for a particle at rest in the frame. On the Earth it "
            "deflects falling bodies to the east, horizontal motion to the right in the north "
            "(winds round cyclones) and turns the Foucault pendulum's plane.",
            how="poinsot.MovingFrame.fictitious_forces ('coriolis'), "
            "poinsot.Earth.coriolis_acceleration, Earth.foucault; docs/frames.md, docs/earth.md.",
            derivation="frames",
        ),
        _ask(
            "L 4",
            "Explain the motion of the earth with necessary diagrams",
            answer=_l4_answer(),
            how="poinsot.Earth: effective_gravity, centrifugal_acceleration, "
            "coriolis_acceleration (ENU axes, λ the latitude); the pictures in poinsot.plots "
            "(docs/earth.md, docs/figures.md).",
            derivation="earth",
            results=("2.30",),
        ),
        _ask(
            "L 5",
            "Discuss the effect of Coriolis force on a freely falling particle",
            answer=_l5_answer(),
            how="poinsot.Earth.eastward_deflection (2.42), Earth.drop (the exact motion); "
            "docs/earth.md ('The falling body').",
            derivation="earth",
            results=("2.42",),
        ),
        _ask(
            "L 6",
            "State and prove Euler's theorem",
            answer="Any displacement of a rigid body with one point fixed is a rotation about an "
            "axis through that point. Proof: the displacement is a matrix R with RᵀR = 1 and "
            "det R = 1; then det(R − 1) = det(Rᵀ) det(R − 1) = det(1 − Rᵀ) = det(1 − R) = "
            "−det(R − 1) in three dimensions, so det(R − 1) = 0: some n ≠ 0 has R n = n, and the "
            "points on the line along n stay put (the unit proves it with two bisecting planes).",
            how=_l6_how(),
        ),
        _ask(
            "L 7",
            "Derive the expressions of angular momentum and kinetic energy",
            answer="With v_a = ω × r_a (2.43), L = Σ m_a r_a × (ω × r_a) = Σ m_a (r_a² ω − "
            "(r_a·ω) r_a) (2.44), i.e. L_i = Σ_j I_ij ω_j (2.51) with I_xx = Σ m (y² + z²), "
            "I_xy = −Σ m x y (2.46–2.50); T = Σ ½ m_a v_a² = ½ ω·L = ½ Σ I_ij ω_i ω_j "
            "(2.52–2.55), in principal axes ½(I₁ω₁² + I₂ω₂² + I₃ω₃²) (2.66).",
            how="The derivation 'rigid_body'; poinsot.RigidBody.angular_momentum, "
            "kinetic_energy, from_point_masses; docs/inertia.md.",
            derivation="rigid_body",
            results=("2.51", "2.66"),
        ),
        _ask(
            "L 8",
            "Discuss the inertia tensor of rigid body",
            answer="The nine I_ij form a symmetric rank-2 tensor (six independent components, "
            "2.60), I_xx = ∫ρ(r² − x²)dτ, I_xy = −∫ρ x y dτ (2.61–2.62), with L = I·ω and "
            "T = ½ ω·I·ω (2.63–2.64). Being symmetric it is diagonal in the principal axes, "
            "with the principal moments I₁, I₂, I₃ (2.65–2.66), which classify the body "
            "(spherical, symmetrical, asymmetrical top, rotator); the parallel-axis theorem "
            "moves it to another point.",
            how="poinsot.RigidBody.inertia, principal_moments, principal_axes, inertia_about, "
            "from_density, the standard solids; docs/inertia.md.",
            derivation="rigid_body",
        ),
        _ask(
            "L 9",
            "Derive the Euler's equations of the motion and find the relation between the rate "
            "at which work done by the torque and the rate of change of kinetic energy",
            answer="(dL/dt)_fix = N (2.67) with the operator 2.68 gives N = (dL/dt)_rot + ω × L "
            "(2.69), (dL/dt)_rot = I·ω̇ (2.70; the unit's dot is lost); in principal axes "
            "N₁ = I₁ω̇₁ + (I₃ − I₂)ω₂ω₃ and cyclically (2.72). Dotting with ω kills ω × L: "
            "ω·N = ω·I·ω̇ = d/dt(½ ω·I·ω) = dT/dt (2.75–2.76), the power of the torque.",
            how="The derivation 'euler_equations'; poinsot.simulate integrates 2.71 and "
            "reports ω·N as Trajectory.power (= dT/dt); docs/dynamics.md.",
            derivation="euler_equations",
            results=("2.72", "2.76"),
        ),
        _ask(
            "L 10",
            "Discuss the torque free motion of a rigid body and derive the expression "
            "A² = (L² − 2I₃T)/(I₁(I₁ − I₃))",
            answer=_l10_answer(),
            how="The derivation 'torque_free_top'; poinsot.FreeSymmetricTop (amplitude, "
            "amplitude_squared_from, the cone angles); docs/dynamics.md.",
            derivation="torque_free_top",
            note="The scan lost both minus signs: it prints A² = (L² 2I₃T)/(I₁(I₁ I₃)); "
            "restored from eq. 2.96.",
            results=("2.96",),
        ),
        _ask(
            "L 11",
            "Discuss the Euler's angles of the rigid body with neat diagrams",
            answer="Three successive rotations take the fixed axes XYZ to the body axes 123: φ "
            "about Z (X goes to the line of nodes ξ), θ about ξ, ψ about the new axis ζ = 3; "
            "R = R_z(φ) R_x(θ) R_z(ψ). φ̇ is the precession, θ̇ the nutation and ψ̇ the spin, and "
            "ω₁ = φ̇ sin θ sin ψ + θ̇ cos ψ, ω₂ = φ̇ sin θ cos ψ − θ̇ sin ψ, ω₃ = φ̇ cos θ + ψ̇ "
            "(2.98–2.99, with ω₃ = ω_ζ: the unit prints ω_ξ).",
            how="poinsot.euler_to_matrix, matrix_to_euler, body_angular_velocity, euler_rates "
            "(all 12 sequences, intrinsic and extrinsic); docs/rotation.md; the pictures in "
            "poinsot.plots (docs/figures.md).",
            derivation="euler_angles",
            results=("2.99",),
        ),
        _ask(
            "L 12",
            "Discuss the motion of a symmetrical top and derive the expressions of its total "
            "energy and precessional velocity",
            answer=_l12_answer(),
            how="The derivation 'heavy_top'; poinsot.HeavyTop (energy, effective_potential, "
            "turning_points, steady_precession, min_spin); docs/heavy_top.md.",
            derivation="heavy_top",
            results=("2.117",),
        ),
    ]
    return (*mc, *short, *long)


def questions() -> list[Question]:
    """The unit's question bank in its order (6 multiple-choice, 13 short, 12 long), each
    question answered from the package (computed once per process)."""
    return list(_questions())


def render(
    questions: Iterable[Question], answers: bool = True, width: int = 100, markdown: bool = False
) -> str:
    """The plain-text listing of ``questions`` (e.g. those of :func:`questions`) that
    ``poinsot derive questions`` prints, grouped by kind under headings, wrapped at ``width``
    columns. With ``answers=False`` only the questions and their choices (a quiz sheet);
    with ``markdown=True`` Markdown for the docs (``poinsot derive questions --markdown``)."""
    items = list(questions)
    if markdown:
        return _render_markdown(items, answers)
    titles = {
        "multiple choice": "Multiple-choice questions",
        "short": "Short questions",
        "long": "Long questions",
    }
    head = "The unit's question bank" + (", answered by poinsot" if answers else "")
    out = [head, "=" * len(head)]
    pad = " " * 8
    for kind in KINDS:
        group = [q for q in items if q.kind == kind]
        if not group:
            continue
        out += ["", titles[kind], "-" * len(titles[kind])]
        for q in group:
            out.append("")
            out.append(
                textwrap.fill(q.text, width, initial_indent=f"{q.number:<8}", subsequent_indent=pad)
            )
            if q.choices:
                line = "   ".join(f"({_LETTERS[k]}) {c}" for k, c in enumerate(q.choices))
                out.append(textwrap.fill(line, width, initial_indent=pad, subsequent_indent=pad))
            if not answers:
                continue
            parts = [("Answer", q.answer), ("How", q.how)]
            if q.derivation:
                where = f"poinsot derive {q.derivation}"
                if q.results:
                    where += f" (eqs. {', '.join(q.results)})"
                parts.append(("Derived", where))
            if q.note:
                parts.append(("Note", q.note))
            for label, body in parts:
                out.append(
                    textwrap.fill(
                        body,
                        width,
                        initial_indent=f"{pad}{label}: ",
                        subsequent_indent=pad + "  ",
                    )
                )
    return "\n".join(out) + "\n"


def _render_markdown(items: list[Question], answers: bool) -> str:
    titles = {
        "multiple choice": "Multiple-choice questions",
        "short": "Short questions",
        "long": "Long questions",
    }
    out: list[str] = []
    for kind in KINDS:
        group = [q for q in items if q.kind == kind]
        if not group:
            continue
        out += [f"### {titles[kind]}", ""]
        for q in group:
            out += [f"**{q.number}.** {q.text}", ""]
            if q.choices:
                out += ["   ".join(f"({_LETTERS[k]}) {c}" for k, c in enumerate(q.choices)), ""]
            if not answers:
                continue
            out.append(f"- *Answer:* {q.answer}")
            out.append(f"- *How:* {q.how}")
            if q.derivation:
                where = f"[{q.derivation}]({q.derivation}.md)"  # the pages sit side by side
                if q.results:
                    where += f" (eqs. {', '.join(q.results)})"
                out.append(f"- *Derived:* {where}")
            if q.note:
                out.append(f"- *Note:* {q.note}")
            out.append("")
    return "\n".join(out)
