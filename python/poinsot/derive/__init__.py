"""The unit, derived: each topic's derivation as steps a reader can follow, from the unit's
starting point to its result, in the unit's notation (sympy, the optional ``symbolic`` extra).

Entry points: :func:`derivations` (all, in the unit's order) and :func:`derivation` (one by
name). Each :class:`Derivation` has ``name``, ``title``, ``steps`` (a sentence and a sympy
equation each), ``result`` (the derived formulas keyed by the unit's equation numbers, e.g.
``"2.14"``) and renders itself with :meth:`Derivation.latex` and :meth:`Derivation.markdown`.

Every step is checked when it is made: a step that claims ``lhs = rhs`` is simplified to
``lhs - rhs = 0`` before it is recorded, so a derivation that builds is a proof of its result.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from ..errors import PoinsotError

try:  # pragma: no cover - depends on the environment
    import sympy as sp
except ImportError as exc:  # pragma: no cover
    raise ImportError("poinsot.derive needs sympy: pip install 'poinsot[symbolic]'") from exc

__all__ = ["Step", "Derivation", "derivations", "derivation"]


@dataclass(frozen=True)
class Step:
    """One step of a derivation: what is done (a sentence) and the equation it gives."""

    text: str
    equation: Any  # a sympy Eq (or an expression shown as it is)
    number: str | None = None  # the unit's equation number this step reaches, if any

    def latex(self) -> str:
        tag = f" \\tag{{{self.number}}}" if self.number else ""
        return sp.latex(self.equation) + tag


@dataclass
class Derivation:
    """A derivation: ``steps`` from the unit's starting point to ``result`` (sympy equations
    keyed by the unit's equation numbers)."""

    name: str
    title: str
    steps: list[Step] = field(default_factory=list)
    result: dict[str, Any] = field(default_factory=dict)

    def step(self, text: str, lhs: Any, rhs: Any, number: str | None = None) -> Any:
        """Records ``lhs = rhs`` after checking it (``simplify(lhs - rhs) == 0``, componentwise
        for matrices); returns ``rhs``. A step that does not hold raises :class:`PoinsotError`
        naming the step: a derivation cannot record a false equation."""
        diff = sp.simplify(sp.Matrix(lhs) - sp.Matrix(rhs)) if _is_matrix(lhs) else sp.simplify(lhs - rhs)
        zero = diff.is_zero_matrix if _is_matrix(lhs) else diff == 0
        if not zero:
            raise PoinsotError(f"derivation {self.name}: the step {text!r} does not hold: {diff}")
        eq = sp.Eq(lhs, rhs, evaluate=False)
        self.steps.append(Step(text, eq, number))
        if number is not None:
            self.result[number] = eq
        return rhs

    def note(self, text: str, equation: Any, number: str | None = None) -> None:
        """Records a definition or a starting point (nothing to check)."""
        self.steps.append(Step(text, equation, number))
        if number is not None:
            self.result[number] = equation

    def latex(self) -> str:
        """The derivation as LaTeX: each step's sentence and its equation."""
        parts = [f"\\section*{{{self.title}}}"]
        for s in self.steps:
            parts.append(s.text)
            parts.append("\\begin{equation}" + s.latex() + "\\end{equation}")
        return "\n".join(parts)

    def markdown(self) -> str:
        """The derivation as MyST/markdown: each step's sentence and its display equation."""
        parts = [f"## {self.title}", ""]
        for k, s in enumerate(self.steps, 1):
            parts += [f"{k}. {s.text}", "", f"   $$ {s.latex()} $$", ""]
        return "\n".join(parts)


def _is_matrix(x: Any) -> bool:
    return isinstance(x, sp.MatrixBase)


# ---- the derivations, in the unit's order -------------------------------------------------------


def _cross(a: Any) -> Any:
    """The matrix [a]× with [a]× b = a × b."""
    return sp.Matrix([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])


def rotating_frame() -> Derivation:
    """The rotating frame (2.6–2.23): the operator (d/dt)_fix = (d/dt)_rot + ω×, and the
    velocity and acceleration of a particle with their named terms.

    The rotating axes are the columns of R(t) = R_z(φ) R_x(θ) R_z(ψ) with φ, θ, ψ arbitrary
    functions of time, so the result holds for every rotation of the frame."""
    d = Derivation("rotating_frame", "The rotating frame: (d/dt)_fix = (d/dt)_rot + ω×")
    t = sp.symbols("t", real=True)
    phi, theta, psi = (sp.Function(n, real=True)(t) for n in ("phi", "theta", "psi"))
    c, s = sp.cos, sp.sin
    rz = lambda a: sp.Matrix([[c(a), -s(a), 0], [s(a), c(a), 0], [0, 0, 1]])  # noqa: E731
    rx = lambda a: sp.Matrix([[1, 0, 0], [0, c(a), -s(a)], [0, s(a), c(a)]])  # noqa: E731
    R = rz(phi) * rx(theta) * rz(psi)
    V = sp.Matrix([sp.Function(f"V_{k}", real=True)(t) for k in "xyz"])  # rotating components
    d.note(
        "A vector is the same arrow in both frames (2.8); its fixed components are R(t) times "
        "its rotating components V, the columns of R being the rotating unit vectors.",
        sp.Eq(sp.Symbol("V'"), R * V, evaluate=False),
        "2.8",
    )
    Rdot = R.diff(t)
    W = sp.simplify(Rdot * R.T)
    d.step(
        "The unit vectors turn: Ṙ Rᵀ is skew-symmetric (differentiate R Rᵀ = 1), so it is [ω]× "
        "for one vector ω, and dî/dt = ω × î and cyclically (2.13).",
        W + W.T,
        sp.zeros(3, 3),
    )
    omega = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])
    d.step("Ṙ = [ω]× R defines ω (fixed components).", Rdot, _cross(omega) * R, "2.13")
    fixed_rate = (R * V).diff(t)
    rot_rate = R * V.diff(t)
    first = d.step(
        "Differentiate R V: the rate seen in the rotating frame plus the turning of the axes, "
        "(dV/dt)_fix = (dV/dt)_rot + ω × V (2.14), the operator (2.15).",
        fixed_rate,
        rot_rate + _cross(omega) * (R * V),
        "2.14",
    )
    d.step(
        "Applied to ω itself, ω × ω = 0: both frames see the same ω̇ (2.16).",
        omega.diff(t),
        omega.diff(t) + _cross(omega) * omega,
        "2.16",
    )
    second = d.step(
        "Apply the operator twice: (d²V/dt²)_fix = (d²V/dt²)_rot + 2 ω × (dV/dt)_rot "
        "+ ω × (ω × V) + ω̇ × V (2.18): the relative, Coriolis, centripetal and Euler terms.",
        first.diff(t),
        R * V.diff(t, 2)
        + 2 * _cross(omega) * (R * V.diff(t))
        + _cross(omega) * (_cross(omega) * (R * V))
        + _cross(omega.diff(t)) * (R * V),
        "2.18",
    )
    del second
    return d


_REGISTRY: dict[str, Callable[[], Derivation]] = {"rotating_frame": rotating_frame}


def derivations() -> list[Derivation]:
    """Every derivation, in the unit's order (each built and checked now)."""
    return [make() for make in _REGISTRY.values()]


def derivation(name: str) -> Derivation:
    """The derivation called ``name``; :class:`PoinsotError` naming ``name`` otherwise."""
    try:
        make = _REGISTRY[name]
    except KeyError:
        raise PoinsotError(f"name: no derivation {name!r}; one of {', '.join(_REGISTRY)}") from None
    return make()
