"""Euler's equations of motion (the unit's 2.67–2.76), derived and checked.

Coverage
--------
From the law of rotation in the fixed frame, (dL⃗/dt)_fix = N⃗ (2.67), with the operator of the
rotating frame (2.68, the unit's 2.14) and L⃗ = I⃗·ω⃗ (2.63) in principal body axes, to

* 2.69–2.71: N⃗ = (dL⃗/dt)_rot + ω⃗ × L⃗ = I⃗·ω̇⃗ + ω⃗ × L⃗;
* 2.72: Euler's equations N₁ = I₁ω̇₁ + (I₃ − I₂)ω₂ω₃ and cyclically (N·m);
* 2.73–2.74: what torque-free motion really gives, ω⃗ × (I⃗·ω⃗) = −I⃗·ω̇⃗: ω⃗ ∥ L⃗ only for
  steady rotation about a principal axis (the unit claims it always);
* 2.75–2.76: the energy theorem ω⃗·N⃗ = dT/dt (W).

Model
-----
Every step is checked in components along the principal body axes, the rotating frame: ω⃗ has
components ω₁(t), ω₂(t), ω₃(t) (rad/s, arbitrary functions of time), I⃗ is diag(I₁, I₂, I₃)
(kg·m², constant in the body), L⃗ = I⃗·ω⃗, (d/dt)_rot differentiates the components and
(dX⃗/dt)_fix = Ẋ + ω⃗ × X (2.68, the product rule on R(t)X(t) with Ṙ = R[ω]×, proved in the frames
derivation). The torque N⃗ is what 2.67 says it is, (dL⃗/dt)_fix, and T = ½ ω⃗·I⃗·ω⃗ (2.64). The
checks are polynomial identities in ω, ω̇ and the moments: the whole derivation builds in
milliseconds.

Results
-------
``result`` holds 2.67, 2.68, 2.69, 2.70, 2.71, 2.72, 2.73, 2.74, 2.75 and 2.76. Numeric forms
(:meth:`~poinsot.derive.Derivation.lambdify`): ``"2.72"`` gives (ω̇₁, ω̇₂, ω̇₃) (rad/s²) from
(I₁, I₂, I₃, ω₁, ω₂, ω₃, N₁, N₂, N₃); ``"2.76"`` gives dT/dt (W) from
(I₁, I₂, I₃, ω₁, ω₂, ω₃, ω̇₁, ω̇₂, ω̇₃).

The unit as printed (:data:`PRINTED`) loses the dot of ω̇ in 2.70 and again in 2.71, and claims
ω⃗ ∥ L⃗ for every torque-free motion in 2.73–2.74: :func:`poinsot.derive.errata` reports these four.

The private helpers here (:class:`_Model`, :class:`_Ddt`, :class:`_Norm`, :func:`_trig_reduce`)
are shared with :mod:`poinsot.derive.torque_free_top`.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import sympy as sp
from sympy.physics.vector import dynamicsymbols

from ._core import Cross, Derivation, Dot, DtFix, DtRot, Printed, Unit, Vec, VectorModel, dot_value
from ._core import add as _add
from ._core import eq as _eq
from ._core import mul as _mul

__all__ = ["derive", "PRINTED"]

# ---- notation the machinery lacks (candidates for _core.py) ---------------------------------


class _Ddt(sp.Function):
    """d/dt of a scalar, unevaluated: ``_Ddt(T)`` prints dT/dt, ``_Ddt(x + y)`` d/dt(x + y).

    (sympy's ``Derivative`` is evaluated by the vector printer, and of a symbol it is zero.)"""

    nargs = 1

    def _latex(self, printer: Any) -> str:
        order, inner = 1, self.args[0]
        while isinstance(inner, _Ddt):
            order, inner = order + 1, inner.args[0]
        d = "d" if order == 1 else f"d^{{{order}}}"
        dt = "dt" if order == 1 else f"dt^{{{order}}}"
        if isinstance(inner, (sp.Symbol, sp.core.function.AppliedUndef)):
            return r"\frac{" + d + " " + printer._print(inner) + "}{" + dt + "}"
        return r"\frac{" + d + "}{" + dt + r"}\left(" + printer._print(inner) + r"\right)"


class _Cross(Cross):
    """a⃗ × b⃗ with a scalar product on either side in parentheses: ω⃗ × (I⃗·ω⃗), as the unit
    writes it (``Cross`` prints ω⃗ × I⃗ · ω⃗)."""

    def _body_latex(self, printer: Any) -> str:
        a, b = self.args
        wrap = lambda x: (
            r"\left(" + printer._print(x) + r"\right)"
            if isinstance(x, (sp.Add, Dot, Cross))
            else printer._print(x)
        )
        left = printer._print(a) if isinstance(a, Cross) else wrap(a)
        return left + r" \times " + wrap(b)


class _Norm(sp.Function):
    """The magnitude |X⃗| of a vector, unevaluated (the model gives √(X⃗·X⃗))."""

    nargs = 1

    def _latex(self, printer: Any) -> str:
        return r"\left|" + printer._print(self.args[0]) + r"\right|"


#: ½ as the unit prints it, in front of a product (sympy would fold it into a fraction).
HALF = sp.UnevaluatedExpr(sp.Rational(1, 2))


def _trig_reduce(e: Any) -> Any:
    """``e`` with sin² a replaced by 1 − cos² a for each angle a (a rational function in the
    sines and cosines of its angles, other atoms as coefficients): a canonical form, so that
    e.g. A² sin² a + A² cos² a becomes A² before a square root is taken."""
    atoms = sorted(e.atoms(sp.sin, sp.cos), key=sp.default_sort_key)
    if not atoms:
        return e
    rep: dict[Any, Any] = {}
    back: dict[Any, Any] = {}
    mods = []
    for k, a in enumerate(sorted({x.args[0] for x in atoms}, key=sp.default_sort_key)):
        s, c = sp.Dummy(f"s{k}"), sp.Dummy(f"c{k}")
        rep[sp.sin(a)], rep[sp.cos(a)] = s, c
        back[s], back[c] = sp.sin(a), sp.cos(a)
        mods.append((s, c))
    num, den = sp.fraction(sp.together(e.xreplace(rep)))
    num, den = sp.expand(num), sp.expand(den)
    for s, c in mods:
        if num.has(s):
            num = sp.expand(sp.rem(num, s**2 + c**2 - 1, s))
        if den.has(s):
            den = sp.expand(sp.rem(den, s**2 + c**2 - 1, s))
    return (num / den).xreplace(back)


def _canon_roots(e: Any) -> Any:
    """Every fractional power in ``e`` with its base in canonical form (trigonometric reduction,
    then factored), so that equal roots are written alike (√((A² + ω₃²)(I₁²A² + I₃²ω₃²)) splits
    into the product of the two roots when both factors are positive); the arguments of atan2
    reduced likewise."""
    if isinstance(e, sp.MatrixBase):
        return e.applyfunc(_canon_roots)
    e = sp.sympify(e)
    if e.has(sp.atan2):
        e = e.replace(
            lambda x: isinstance(x, sp.atan2),
            lambda x: sp.atan2(*(_trig_reduce(sp.expand(a)) for a in x.args)),
        )
    if not e.has(sp.Pow):
        return e
    return e.replace(
        lambda x: isinstance(x, sp.Pow) and x.exp.is_Rational and not x.exp.is_Integer,
        lambda x: sp.Pow(sp.factor(_trig_reduce(x.base)), x.exp),
    )


@dataclass
class _Model(VectorModel):
    """A :class:`VectorModel` that also knows the inertia tensor (a 3×3 matrix among
    ``vectors``: ``Dot(I, ω)`` is the matrix product), scalar rates (:class:`_Ddt` and
    ``Derivative``, differentiated in ``t``), magnitudes (:class:`_Norm`) and, optionally, the
    equations of motion: ``flow`` rewrites the rates a differentiation produced (e.g. ω̇ by
    Euler's equations), so that a step is checked along every motion; ``post`` rewrites every
    value last."""

    t: Any = None
    flow: Callable[[Any], Any] | None = None
    #: a last rewriting of every value (e.g. a constant's relation to the others)
    post: Callable[[Any], Any] | None = None

    def __call__(self, e: Any) -> Any:
        out = self._ev(sp.sympify(e))
        if self.post is not None:
            out = out.applyfunc(self.post) if isinstance(out, sp.MatrixBase) else self.post(out)
        return _canon_roots(out)

    def _rate(self, x: Any, variables: Sequence[tuple[Any, int]]) -> Any:
        for v, n in variables:
            x = sp.diff(x, v, n)
        return self.flow(x) if self.flow is not None else x

    def _ev(self, e: Any) -> Any:
        if isinstance(e, sp.UnevaluatedExpr):
            return self._ev(e.args[0])
        if isinstance(e, Dot):
            return dot_value(*(sp.Matrix(self._ev(x)) for x in e.args))
        if isinstance(e, _Ddt):
            return self._rate(self._ev(e.args[0]), [(self.t, 1)])
        if isinstance(e, sp.Derivative) and e not in self.scalars:
            return self._rate(self._ev(e.expr), list(e.variable_count))
        if isinstance(e, _Norm):
            v = sp.Matrix(self._ev(e.args[0]))
            return sp.sqrt(sp.factor(_trig_reduce(sp.expand((v.T * v)[0, 0]))))
        return super()._ev(e)


def _chain(*sides: Any) -> list[sp.Equality]:
    """a = b = c … as the list of its links."""
    return [_eq(a, b) for a, b in zip(sides[:-1], sides[1:])]


def _plain(expr: Any, names: Mapping[Any, Any]) -> Any:
    """``expr`` with functions of time and their rates replaced by plain symbols and ½ made a
    number again (for lambdify)."""
    out = sp.sympify(expr).replace(lambda x: isinstance(x, sp.UnevaluatedExpr), lambda x: x.args[0])
    return out.xreplace(dict(names))


# ---- the notation of this derivation -------------------------------------------------------

t = dynamicsymbols._t
w1, w2, w3 = dynamicsymbols("omega_1 omega_2 omega_3")
I1, I2, I3 = sp.symbols("I_1 I_2 I_3", positive=True)
N1, N2, N3 = sp.symbols("N_1 N_2 N_3")
T = sp.Symbol("T")
omega, L, N, I, V = Vec("omega"), Vec("L"), Vec("N"), Vec("I"), Vec("V")
ZERO = Vec("0")
i_, j_, k_ = Unit("i"), Unit("j"), Unit("k")
#: The scalar I of the unit's 2.74, L⃗ = Iω⃗ (one moment of inertia: L⃗ parallel to ω⃗).
I_scalar = sp.Symbol("I")

W = sp.Matrix([w1, w2, w3])
INERTIA = sp.diag(I1, I2, I3)


def _model() -> _Model:
    """Body (principal-axis) components of the notation; see the module docstring."""
    dt_rot = lambda x: sp.Matrix(x).diff(t)
    dt_fix = lambda x: sp.Matrix(x).diff(t) + W.cross(sp.Matrix(x))
    LW = INERTIA * W
    torque = dt_fix(LW)  # 2.67: the torque is the fixed-frame rate of L
    vectors = {
        omega: W,
        I: INERTIA,
        L: LW,
        N: torque,
        V: sp.Matrix(dynamicsymbols("V_1 V_2 V_3")),
        ZERO: sp.zeros(3, 1),
        i_: sp.Matrix([1, 0, 0]),
        j_: sp.Matrix([0, 1, 0]),
        k_: sp.Matrix([0, 0, 1]),
    }
    scalars = {
        N1: torque[0],
        N2: torque[1],
        N3: torque[2],
        T: sp.Rational(1, 2) * (W.T * LW)[0, 0],
    }
    return _Model(vectors=vectors, dt_fix=dt_fix, dt_rot=dt_rot, scalars=scalars, t=t)


# ---- the unit as printed -------------------------------------------------------------------

_E = "euler_equations"

#: Euler's equations in principal axes as the unit prints them (2.72), line by line.
_EULER_RHS = (
    _add(I1 * w1.diff(t), _mul(I3 - I2, w2, w3)),
    _add(I2 * w2.diff(t), _mul(I1 - I3, w3, w1)),
    _add(I3 * w3.diff(t), _mul(I2 - I1, w1, w2)),
)

PRINTED: tuple[Printed, ...] = (
    Printed("2.67", _E, r"\left(\frac{d\vec{L}}{dt}\right)_{fix} = \vec{N}", _eq(DtFix(L), N)),
    Printed(
        "2.68",
        _E,
        r"\left(\frac{d}{dt}\right)_{fix} = \left(\frac{d}{dt}\right)_{rot} + \vec{\omega} \times",
        _eq(DtFix(V), _add(DtRot(V), _Cross(omega, V))),
        note="the operator, applied to a vector V⃗ as in 2.14",
    ),
    Printed(
        "2.69",
        _E,
        r"\vec{N} = \left(\frac{d\vec{L}}{dt}\right)_{fix} = \left(\frac{d\vec{L}}{dt}\right)_{rot}"
        r" + \vec{\omega} \times \vec{L}",
        _chain(N, DtFix(L), _add(DtRot(L), _Cross(omega, L))),
    ),
    Printed(
        "2.70",
        _E,
        r"\therefore \begin{pmatrix} \frac{d\vec{L}}{dt} \end{pmatrix}_{rot} = \vec{I} \cdot "
        r"\vec{\omega}",
        _eq(DtRot(L), Dot(I, omega)),
        note="the numbered line; (dL/dt)_body is (dL/dt)_rot",
    ),
    Printed(
        "2.71",
        _E,
        r"\vec{N} = \vec{I} \cdot \vec{\omega} + \vec{\omega} \times \vec{L}",
        _eq(N, _add(Dot(I, omega), _Cross(omega, L))),
    ),
    Printed(
        "2.72",
        _E,
        r"N_{1} = I_{1}\dot{\omega}_{1} + (I_{3} - I_{2})\omega_{2}\omega_{3}",
        _eq(N1, _EULER_RHS[0]),
    ),
    Printed(
        "2.72",
        _E,
        r"N_{2} = I_{2}\dot{\omega}_{2} + (I_{1} - I_{3})\omega_{3}\omega_{1}",
        _eq(N2, _EULER_RHS[1]),
    ),
    Printed(
        "2.72",
        _E,
        r"N_{3} = I_{3}\dot{\omega}_{3} + (I_{2} - I_{1})\omega_{1}\omega_{2}",
        _eq(N3, _EULER_RHS[2]),
    ),
    Printed(
        "2.73",
        _E,
        r"\vec{\omega} \times (\vec{l} \cdot \vec{\omega}) = 0",
        _eq(_Cross(omega, Dot(I, omega)), ZERO),
        note="the scan's l⃗ is the inertia tensor I⃗; the unit's claim for a torque-free body",
    ),
    Printed(
        "2.74",
        _E,
        r"\therefore \vec{L} = I\omega",
        _eq(_Cross(omega, L), ZERO),
        note="L⃗ = Iω⃗ with one scalar I says L⃗ ∥ ω⃗, i.e. ω⃗ × L⃗ = 0⃗ (the unit: 'true if "
        "ω⃗ ∥ L⃗'), claimed for every torque-free body",
    ),
    Printed(
        "2.75",
        _E,
        r"\vec{\omega} \cdot \vec{N} = \frac{1}{2} \frac{d}{dt} (\vec{\omega} \cdot \vec{I} \cdot "
        r"\vec{\omega})",
        _eq(Dot(omega, N), _mul(HALF, _Ddt(Dot(omega, Dot(I, omega))))),
    ),
    Printed("2.76", _E, r"\vec{\omega} \cdot \vec{N} = \frac{dT}{dt}", _eq(Dot(omega, N), _Ddt(T))),
)


# ---- the derivation ------------------------------------------------------------------------


def derive() -> Derivation:
    """Builds and checks the derivation of Euler's equations (2.67–2.76)."""
    d = Derivation(
        "euler_equations",
        "Euler's equations of motion (2.67–2.76)",
        summary=(
            "From the law of rotation in the fixed frame to Euler's equations in principal axes "
            "and the energy theorem ω⃗·N⃗ = dT/dt, checked in body components; the torque-free "
            "claim of 2.73–2.74 corrected."
        ),
        model=_model(),
    )
    wdot = sp.Matrix([w1.diff(t), w2.diff(t), w3.diff(t)])

    d.given(
        "In the fixed (inertial) frame the rate of change of the angular momentum about the "
        "fixed point is the torque (2.67).",
        _eq(DtFix(L), N),
        "2.67",
    )
    d.given(
        "The rate of a vector in the fixed frame is its rate in the rotating frame plus ω⃗ × "
        "(2.68, which is 2.14, proved in the frames derivation).",
        _eq(DtFix(V), _add(DtRot(V), _Cross(omega, V))),
        "2.68",
    )
    d.step(
        "Take the body itself as the rotating frame (it turns with ω⃗) and apply 2.68 to L⃗ in 2.67.",
        _chain(N, DtFix(L), _add(DtRot(L), _Cross(omega, L))),
        "2.69",
    )
    d.given(
        "The angular momentum is L⃗ = I⃗·ω⃗ (2.63); in the body's principal axes the inertia "
        "tensor is diag(I₁, I₂, I₃), constant in time.",
        _eq(L, Dot(I, omega)),
    )
    d.step(
        "Since I⃗ is constant in the body frame, only ω⃗ changes there. The unit prints I⃗·ω⃗ "
        "at the end of 2.70: the dot of ω̇⃗ was lost in the scan.",
        _chain(DtRot(L), DtRot(Dot(I, omega)), Dot(I, DtRot(omega))),
        "2.70",
    )
    d.step(
        "ω̇⃗ is the same in both frames, because ω⃗ × ω⃗ = 0⃗ (the unit's remark after 2.70).",
        _chain(DtFix(omega), _add(DtRot(omega), _Cross(omega, omega)), DtRot(omega)),
    )
    d.step(
        "Put 2.70 in 2.69. The unit prints I⃗·ω⃗ for the first term here too: the same lost dot.",
        _eq(N, _add(Dot(I, DtRot(omega)), _Cross(omega, L))),
        "2.71",
    )
    # 2.72: the components of 2.71 along the principal axes
    lhs = _add(_mul(N1, i_), _mul(N2, j_), _mul(N3, k_))
    rhs = _add(*(_mul(r, u) for r, u in zip(_EULER_RHS, (i_, j_, k_))))
    d.step(
        "Along the principal axes I⃗·ω̇⃗ = I₁ω̇₁ î + I₂ω̇₂ ĵ + I₃ω̇₃ k̂, and ω⃗ × (I⃗·ω⃗) has the "
        "components (I₃ − I₂)ω₂ω₃, (I₁ − I₃)ω₃ω₁, (I₂ − I₁)ω₁ω₂: Euler's equations (2.72).",
        _eq(lhs, rhs),
        "2.72",
    )
    # the rates, solved from 2.72 (the numeric form of Euler's equations)
    rates = (
        (N1 - _mul(I3 - I2, w2, w3)) / I1,
        (N2 - _mul(I1 - I3, w3, w1)) / I2,
        (N3 - _mul(I2 - I1, w1, w2)) / I3,
    )
    d.step(
        "Solved for the rates, 2.72 gives ω̇⃗ from ω⃗ and N⃗: the right-hand side that a "
        "numerical integration of the motion evaluates.",
        _eq(
            _add(*(_mul(r, u) for r, u in zip(wdot, (i_, j_, k_)))),
            _add(*(_mul(r, u) for r, u in zip(rates, (i_, j_, k_)))),
        ),
    )
    # torque-free motion: what 2.69 really gives
    d.step(
        "Torque-free motion (N⃗ = 0⃗): L⃗ is constant in the fixed frame, but not in the body. "
        "By 2.69–2.70, ω⃗ × (I⃗·ω⃗) = −I⃗·ω̇⃗, which vanishes only when ω̇⃗ = 0⃗ (steady "
        "rotation). The unit's 2.73, ω⃗ × (I⃗·ω⃗) = 0, drops (dL⃗/dt)_rot.",
        _chain(
            _Cross(omega, Dot(I, omega)),
            _add(N, -DtRot(L)),
            _add(N, -Dot(I, DtRot(omega))),
        ),
        "2.73",
    )
    cross_rhs = _add(
        _mul(_mul(I3 - I2, w2, w3), i_),
        _mul(_mul(I1 - I3, w3, w1), j_),
        _mul(_mul(I2 - I1, w1, w2), k_),
    )
    d.step(
        "In components ω⃗ × L⃗ is not zero in general: ω⃗ ∥ L⃗ (the unit's 2.74, L⃗ = Iω⃗) only "
        "for a spherical top or with ω⃗ along a principal axis — steady rotation. In general "
        "torque-free motion L⃗ is fixed in space and ω⃗ turns about it (the cones of 2.90–2.97).",
        _eq(_Cross(omega, L), cross_rhs),
        "2.74",
    )
    # the energy theorem
    d.step(
        "Dot 2.71 with ω⃗: ω⃗·(ω⃗ × L⃗) = 0, and I⃗ is symmetric, so ω⃗·I⃗·ω̇⃗ = ω̇⃗·I⃗·ω⃗ is half "
        "the rate of ω⃗·I⃗·ω⃗ (2.75). (The unit's first line, ω⃗·[I⃗·ω⃗ + ω⃗ × L⃗], lost the dot "
        "again.)",
        _chain(
            Dot(omega, N),
            Dot(omega, _add(Dot(I, DtRot(omega)), _Cross(omega, L))),
            Dot(omega, Dot(I, DtRot(omega))),
            Dot(DtRot(omega), Dot(I, omega)),
            _mul(HALF, _Ddt(Dot(omega, Dot(I, omega)))),
        ),
        "2.75",
    )
    d.given(
        "The kinetic energy of rotation is T = ½ ω⃗·I⃗·ω⃗ (2.64).",
        _eq(T, _mul(HALF, Dot(omega, Dot(I, omega)))),
    )
    d.step(
        "So the power of the torque is the rate of change of the kinetic energy (2.76).",
        _chain(Dot(omega, N), _mul(HALF, _Ddt(Dot(omega, Dot(I, omega)))), _Ddt(T)),
        "2.76",
    )
    dTdt = _add(*(_mul(m, w, r) for m, w, r in zip((I1, I2, I3), W, wdot)))
    d.step(
        "In principal components dT/dt = I₁ω₁ω̇₁ + I₂ω₂ω̇₂ + I₃ω₃ω̇₃: with ω̇⃗ from 2.72 it "
        "equals ω⃗·N⃗ = ω₁N₁ + ω₂N₂ + ω₃N₃.",
        _chain(_Ddt(T), dTdt, _add(_mul(w1, N1), _mul(w2, N2), _mul(w3, N3))),
    )

    # numeric forms for the bridge to the core
    plain = {w: sp.Symbol(f"omega_{k}") for k, w in enumerate(W, 1)}
    plain.update({w: sp.Symbol(f"omegadot_{k}") for k, w in enumerate(wdot, 1)})
    om_p = [plain[w] for w in W]
    od_p = [plain[w] for w in wdot]
    d.function(
        "2.72", sp.Matrix([_plain(r, plain) for r in rates]), (I1, I2, I3, *om_p, N1, N2, N3)
    )
    d.function("2.76", _plain(dTdt, plain), (I1, I2, I3, *om_p, *od_p))
    return d
