"""Euler's angles, derived: the unit's eqs. 2.98–2.101, then all twelve sequences.

Covers
------
The unit's section "Euler's Angles" (Fig. 2.12–2.13): the attitude
``R = R_z(φ) R_x(θ) R_z(ψ)`` (z-x-z, intrinsic: φ about the fixed Z, θ, the nutation, about the
line of nodes ξ, ψ about body axis 3), the body's angular velocity read off ``[ω]× = RᵀṘ``, its
components along ξ, η, ζ (2.98) and along the body axes 1, 2, 3 (2.99, with its misprint
ω₃ = ω_ξ corrected to ω_ζ), the kinetic energy (2.100) and that of the symmetric top (2.101).

Beyond the unit, each of the 24 conventions (the six proper Euler sequences ``xyx ... zyz`` and
the six Tait–Bryan ``xyz ... zyx``, each intrinsic and extrinsic, as in
:func:`poinsot.euler_to_matrix`): the matrix; ω in body axes (``[ω]× = RᵀṘ``) and in space axes
(``[ω′]× = ṘRᵀ``) from the angle rates; the determinant of the rate map, which vanishes at the
singular angles (sin β = 0 for proper Euler, cos β = 0 for Tait–Bryan); the rates from ω; the
angles from a matrix (``atan2`` forms, on the canonical ranges of
:func:`poinsot.matrix_to_euler`); and at each singular angle the matrix that depends on α ± γ
only (gimbal lock).

Model
-----
Every check is exact polynomial arithmetic. An angle q(t) (radians) is the point
(cos q, sin q) of the unit circle: two generators ``c_q, s_q`` of a polynomial ring over ℚ with
the relation ``s_q² + c_q² = 1``, and every value is reduced to its normal form modulo these
relations (a canonical form, so two sides agree exactly when their normal forms do). The rate q̇
(rad/s) is a further generator and d/dt acts by the chain rule (ṡ_q = c_q q̇, ċ_q = −s_q q̇).
``R_a(q)`` is the active elementary rotation. What the derivation *derives* is defined in the
model by what it *is*, never by the formula derived: ``R`` of a convention is the product of its
elementary rotations, ω (body) is read off ``RᵀṘ``, ω′ (space) off ``ṘRᵀ``, (ω_ξ, ω_η, ω_ζ) are
the space ω on the axes of ``R_z(φ) R_x(θ)``, ``M`` is ∂ω/∂(rates), ``T`` is ½ Σ I_k ω_k² (kg·m²,
rad/s → J). ``atan2(y, x)`` is the angle q for which (y, x) = ρ (sin q, cos q) with ρ = 1 or ρ
the factor that is positive on the convention's canonical range (sin β for proper Euler, cos β
for Tait–Bryan); ``√z`` is that ρ where ρ² = z. The standing assumption of 2.101 is I₂ = I₁.

Results
-------
``"2.98"``, ``"2.99"``, ``"2.100"``, ``"2.101"``; and for each convention ``tag`` (``"zxz-intrinsic"``,
``"xyz-extrinsic"``, ...): ``"R/tag"`` (the matrix), ``"2.99/tag"`` (ω in body axes),
``"space/tag"`` (ω′ in space axes), ``"det/tag"`` (det of the rate map), ``"rates/tag"`` and
``"rates-space/tag"`` (the rates from ω or ω′), ``"angles/tag"`` (the angles from R), and
``"lock/tag@β"`` (R at each singular angle β, e.g. ``"lock/xyz-intrinsic@π/2"``). The numeric
forms (:meth:`~poinsot.derive.Derivation.lambdify`) of all but the lock take plain arguments,
angles (rad) in the order of the sequence, then rates (rad/s) or ω components (rad/s), or else
the nine entries ``R11 ... R33`` of R row by row (``"angles/tag"``); ``"2.99"``, ``"2.100"``
(then I₁, I₂, I₃ in kg·m²) and ``"2.101"`` (then I₁, I₃) take (φ, θ, ψ, φ̇, θ̇, ψ̇).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from typing import Any

import sympy as sp
from sympy.physics.vector import dynamicsymbols
from sympy.polys.rings import ring
from sympy.printing.pretty.stringpict import prettyForm

from ..errors import PoinsotError
from ._core import Derivation, Printed
from ._core import add as _add
from ._core import eq as _eq

__all__ = ["NAME", "PRINTED", "SEQUENCES", "derive", "tags"]

NAME = "euler_angles"

#: The twelve sequences: six proper Euler, then six Tait–Bryan (as poinsot.EULER_SEQUENCES).
SEQUENCES: tuple[str, ...] = (
    "xyx", "xzx", "yxy", "yzy", "zxz", "zyz",
    "xyz", "xzy", "yxz", "yzx", "zxy", "zyx",
)  # fmt: skip

_t = dynamicsymbols._t
_PHI, _THETA, _PSI = dynamicsymbols("phi theta psi")
_ALPHA, _BETA, _GAMMA = dynamicsymbols("alpha beta gamma")
_ANGLES = (_PHI, _THETA, _PSI, _ALPHA, _BETA, _GAMMA)
_I1, _I2, _I3 = sp.symbols("I_1 I_2 I_3")
_SCALARS = (_I1, _I2, _I3)
_HALF = sp.Rational(1, 2)
_AXIS = "xyz"
_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def tags() -> list[str]:
    """The 24 conventions' keys, ``"<seq>-intrinsic"`` and ``"<seq>-extrinsic"``."""
    return [f"{s}-{k}" for s in SEQUENCES for k in ("intrinsic", "extrinsic")]


# ---- notation ---------------------------------------------------------------------------------


class _Sym(sp.Symbol):
    """A quantity of one convention: the name is ``"<LaTeX>|<tag>"``; it prints as the LaTeX, and
    the tag tells the model which convention's R (or ω, ...) it is."""

    def _latex(self, printer: Any) -> str:
        return self.name.split("|", 1)[0]

    def _pretty(self, printer: Any) -> Any:
        return prettyForm(_unicode(self.name.split("|", 1)[0]))

    @property
    def tag(self) -> str:
        return self.name.split("|", 1)[1]


def _unicode(latex: str) -> str:
    """A Unicode reading of the few LaTeX names used here (for the text rendering)."""
    out = latex
    for a, b in (
        (r"\vec{\omega}'", "ω⃗′"),
        (r"\vec{\omega}", "ω⃗"),
        (r"\hat{\imath}", "î"),
        (r"\hat{\jmath}", "ĵ"),
        (r"\hat{k}", "k̂"),
        (r"\omega", "ω"),
        (r"\xi", "ξ"),
        (r"\eta", "η"),
        (r"\zeta", "ζ"),
    ):
        out = out.replace(a, b)
    out = re.sub(r"_\{(\d+)\}", lambda g: g.group(1).translate(_SUB), out)
    return re.sub(r"_\{([^}]*)\}", r"_\1", out)


def _sym(latex: str, tag: str, vector: bool = False) -> _Sym:
    return _Sym(f"{latex}|{tag}", commutative=not vector)


class _Rot(sp.Function):
    """The elementary rotation R_a(q) (active, right-handed), a matrix: non-commutative."""

    nargs = 2
    is_commutative = False

    def _latex(self, printer: Any) -> str:
        return f"R_{{{_AXIS[int(self.args[0])]}}}\\left({printer._print(self.args[1])}\\right)"

    def _pretty(self, printer: Any) -> Any:
        head = prettyForm(f"R_{_AXIS[int(self.args[0])]}")
        return prettyForm(*head.right(prettyForm(*printer._print(self.args[1]).parens())))


class _MatrixOp(sp.Function):
    """An operation on one matrix of the notation (a matrix again: non-commutative)."""

    nargs = 1
    is_commutative = False


class _Tr(_MatrixOp):
    """The transpose Xᵀ."""

    def _latex(self, printer: Any) -> str:
        return f"{printer._print(self.args[0])}^{{\\mathsf{{T}}}}"

    def _pretty(self, printer: Any) -> Any:
        return prettyForm(*printer._print(self.args[0]).right("ᵀ"))


class _Dot(_MatrixOp):
    """The time derivative Ẋ of a matrix."""

    def _latex(self, printer: Any) -> str:
        return f"\\dot{{{printer._print(self.args[0])}}}"

    def _pretty(self, printer: Any) -> Any:
        return prettyForm(printer._print(self.args[0]).render(wrap_line=False) + "\u0307")


class _Skew(_MatrixOp):
    """[v]×, the matrix with [v]× u = v × u."""

    def _latex(self, printer: Any) -> str:
        return f"\\left[{printer._print(self.args[0])}\\right]_{{\\times}}"

    def _pretty(self, printer: Any) -> Any:
        return prettyForm(*prettyForm(*printer._print(self.args[0]).parens("[", "]")).right("×"))


class _Det(sp.Function):
    """det M."""

    nargs = 1

    def _latex(self, printer: Any) -> str:
        return f"\\det {printer._print(self.args[0])}"

    def _pretty(self, printer: Any) -> Any:
        return prettyForm(*prettyForm("det ").right(printer._print(self.args[0])))


def _mat(rows: Sequence[Sequence[Any]]) -> sp.ImmutableMatrix:
    return sp.ImmutableMatrix(rows)


def _col(items: Sequence[Any]) -> sp.ImmutableMatrix:
    return sp.ImmutableMatrix([[x] for x in items])


def _turned(x: Any, y: Any, psi: Any) -> list[Any]:
    """Components (x, y) on ξ, η turned by ψ about ζ onto the body axes 1, 2 (2.99):
    x cos ψ + y sin ψ, −x sin ψ + y cos ψ."""
    s, c = sp.sin(psi), sp.cos(psi)
    return [_add(x * c, y * s), _add(-x * s, y * c)]


def _body_rates(dphi: Any, dtheta: Any, dpsi: Any, theta: Any, psi: Any) -> sp.ImmutableMatrix:
    """The body components of ω from the Euler rates (2.99): ω on ξηζ (2.98) turned by ψ."""
    return _col([*_turned(dtheta, dphi * sp.sin(theta), psi), _add(dpsi, dphi * sp.cos(theta))])


_UNITS = tuple(
    _sym(latex, "e", vector=True) for latex in (r"\hat{\imath}", r"\hat{\jmath}", r"\hat{k}")
)


# ---- the model: angles on the unit circle, exact normal forms ----------------------------------


class _Model:
    """Components of the notation as exact normal forms (see the module docstring).

    A scalar is a pair ``(num, den)`` of ring elements in normal form; a matrix is a tuple of
    rows of scalars. :meth:`__call__` returns sympy (sines and cosines of the angles, rates as
    derivatives), so that :func:`~poinsot.derive._core.is_zero` judges what it returns."""

    def __init__(self) -> None:
        names = [f"{p}{k}" for k in range(len(_ANGLES)) for p in "ascd"]
        names += [f"p{k}" for k in range(len(_SCALARS))]
        self.ring, *gens = ring(names, sp.QQ)
        n = len(_ANGLES)
        self.a = [gens[4 * k] for k in range(n)]
        self.s = [gens[4 * k + 1] for k in range(n)]
        self.c = [gens[4 * k + 2] for k in range(n)]
        self.d = [gens[4 * k + 3] for k in range(n)]
        self.p = gens[4 * n :]
        self.basis = [self.s[k] ** 2 + self.c[k] ** 2 - 1 for k in range(n)]
        self._sine_slots = [4 * k + 1 for k in range(n)]
        self.one, self.zero = self.ring.one, self.ring.zero
        self.index = {q: k for k, q in enumerate(_ANGLES)}
        self.scalar_index = {x: k for k, x in enumerate(_SCALARS)}
        self.gen_expr: list[Any] = []
        for q in _ANGLES:
            self.gen_expr += [q, sp.sin(q), sp.cos(q), q.diff(_t)]
        self.gen_expr += list(_SCALARS)
        #: definitions of the convention quantities: symbol → a function giving its value
        self.defs: dict[Any, Callable[[], Any]] = {}
        #: per convention, the factor that is positive on its canonical range
        self.positive: dict[str, Any] = {}
        self._memo: dict[Any, Any] = {}
        self._out: dict[Any, Any] = {}
        for k, e in enumerate(_UNITS):
            self.define(e, _const(tuple((self.num(int(i == k)),) for i in range(3))))

    # -- values
    def nf(self, p: Any) -> Any:
        """The normal form of ``p`` modulo s² + c² − 1 for every angle (reduction skipped where
        no sine appears squared, where ``p`` already is one)."""
        sines = self._sine_slots
        if all(monom[i] < 2 for monom in p for i in sines):
            return p
        out: dict[Any, Any] = {}
        work = list(p.items())
        while work:
            monom, coeff = work.pop()
            slot = next((i for i in sines if monom[i] >= 2), None)
            if slot is None:
                out[monom] = out.get(monom, 0) + coeff
                continue
            # s^e = s^(e−2) (1 − c²): the sine's cosine is the next slot
            low = monom[:slot] + (monom[slot] - 2,) + monom[slot + 1 :]
            cos2 = low[: slot + 1] + (low[slot + 1] + 2,) + low[slot + 2 :]
            work += [(low, coeff), (cos2, -coeff)]
        return self.ring.from_dict({k: v for k, v in out.items() if v != 0})

    def sc(self, p: Any) -> tuple[Any, Any]:
        return (p, self.one)

    def _frac(self, n: Any, d: Any) -> tuple[Any, Any]:
        if d == 1:
            return (n, self.one)
        if n == 0:
            return (self.zero, self.one)
        n, d = n.cancel(d)
        return (self.nf(n), self.nf(d))

    def add(self, x: Any, y: Any) -> Any:
        if _is_mat(x) or _is_mat(y):
            if not (_is_mat(x) and _is_mat(y)):
                raise PoinsotError(f"derivation {NAME}: a matrix added to a scalar")
            return tuple(tuple(self.add(a, b) for a, b in zip(r, s)) for r, s in zip(x, y))
        if x[1] == y[1]:
            return self._frac(x[0] + y[0], x[1])
        return self._frac(self.nf(x[0] * y[1] + y[0] * x[1]), self.nf(x[1] * y[1]))

    def mul(self, x: Any, y: Any) -> Any:
        if _is_mat(x) and _is_mat(y):
            return tuple(
                tuple(
                    _sum(self, [self.mul(x[i][k], y[k][j]) for k in range(len(y))])
                    for j in range(len(y[0]))
                )
                for i in range(len(x))
            )
        if _is_mat(x):
            return tuple(tuple(self.mul(a, y) for a in r) for r in x)
        if _is_mat(y):
            return tuple(tuple(self.mul(x, a) for a in r) for r in y)
        if x[0] == 0 or y[0] == 0:
            return (self.zero, self.one)
        if x[1] == 1 and y[1] == 1:
            return (self.nf(x[0] * y[0]), self.one)
        return self._frac(self.nf(x[0] * y[0]), self.nf(x[1] * y[1]))

    def inv(self, x: Any) -> Any:
        if _is_mat(x) or x[0] == 0:
            raise PoinsotError(f"derivation {NAME}: division by a matrix or by zero")
        return self._frac(x[1], x[0])

    def dt(self, x: Any) -> Any:
        """d/dt by the chain rule (first derivatives of the angles only)."""
        if _is_mat(x):
            return tuple(tuple(self.dt(a) for a in r) for r in x)
        n, d = x
        if d == 1:
            return (self._dt(n), self.one)
        return self._frac(self.nf(self._dt(n) * d - n * self._dt(d)), self.nf(d * d))

    def _dt(self, p: Any) -> Any:
        out = self.zero
        for k in range(len(_ANGLES)):
            if p.degree(self.d[k]) > 0:
                raise PoinsotError(f"derivation {NAME}: the model has no second derivatives")
            out += (p.diff(self.s[k]) * self.c[k] - p.diff(self.c[k]) * self.s[k]) * self.d[k]
            out += p.diff(self.a[k]) * self.d[k]
        return self.nf(out)

    def trig(self, arg: Any) -> tuple[Any, Any]:
        """(sin, cos) of an angle expression: an angle, a sum, an integer multiple, a number."""
        if arg in self.index:
            k = self.index[arg]
            return self.sc(self.s[k]), self.sc(self.c[k])
        if not arg.free_symbols:
            s, c = sp.sin(arg), sp.cos(arg)
            if not (s.is_Rational and c.is_Rational):
                raise PoinsotError(f"derivation {NAME}: no exact sine of {arg}")
            return self.num(s), self.num(c)
        if isinstance(arg, sp.Add):
            (su, cu), (sv, cv) = self.trig(arg.args[0]), self.trig(sp.Add(*arg.args[1:]))
            sin = self.add(self.mul(su, cv), self.mul(cu, sv))
            cos = self.add(self.mul(cu, cv), self.mul(self.num(-1), self.mul(su, sv)))
            return sin, cos
        if isinstance(arg, sp.Mul) and arg.args[0].is_Integer and len(arg.args) == 2:
            n, x = int(arg.args[0]), arg.args[1]
            s, c = self.trig(sp.Add(*([x] * abs(n)), evaluate=False) if abs(n) > 1 else x)
            return (self.mul(self.num(-1), s), c) if n < 0 else (s, c)
        raise PoinsotError(f"derivation {NAME}: the model has no sine of {arg}")

    def num(self, x: Any) -> tuple[Any, Any]:
        x = sp.Rational(x)
        return (self.ring(sp.QQ(int(x.p), int(x.q))), self.one)

    # -- notation → value
    def define(self, symbol: Any, value: Callable[[], Any]) -> None:
        self.defs[symbol] = value

    def ev(self, e: Any) -> Any:
        try:
            return self._memo[e]
        except KeyError:
            pass
        v = self._ev(e)
        self._memo[e] = v
        return v

    def _ev(self, e: Any) -> Any:
        if isinstance(e, sp.MatrixBase):
            return tuple(tuple(self.ev(e[i, j]) for j in range(e.cols)) for i in range(e.rows))
        if e in self.defs:
            return self.defs[e]()
        if isinstance(e, _Sym):
            raise PoinsotError(f"derivation {NAME}: the model does not define {e.name}")
        if e in self.index:
            return self.sc(self.a[self.index[e]])
        if isinstance(e, sp.Derivative):
            if e.expr in self.index and e.variables == (_t,):
                return self.sc(self.d[self.index[e.expr]])
            raise PoinsotError(f"derivation {NAME}: the model has no {e}")
        if e in self.scalar_index:
            return self.sc(self.p[self.scalar_index[e]])
        if e.is_Rational:
            return self.num(e)
        if isinstance(e, sp.Add):
            return _sum(self, [self.ev(x) for x in e.args])
        if isinstance(e, sp.Mul):
            out = self.ev(e.args[0])
            for x in e.args[1:]:
                out = self.mul(out, self.ev(x))
            return out
        if isinstance(e, sp.Pow):
            if e.exp == _HALF:
                return self._sqrt(e)
            if e.exp.is_Integer:
                base = self.ev(e.base)
                out = (self.one, self.one)
                for _ in range(abs(int(e.exp))):
                    out = self.mul(out, base)
                return self.inv(out) if e.exp < 0 else out
        if isinstance(e, sp.sin):
            return self.trig(e.args[0])[0]
        if isinstance(e, sp.cos):
            return self.trig(e.args[0])[1]
        if isinstance(e, sp.atan2):
            return self._atan2(e)
        if isinstance(e, _Rot):
            (s, c), i = self.trig(e.args[1]), int(e.args[0])
            j, k = (i + 1) % 3, (i + 2) % 3
            m = [[self.num(1 if r == q else 0) for q in range(3)] for r in range(3)]
            m[j][j], m[k][k], m[k][j] = c, c, s
            m[j][k] = self.mul(self.num(-1), s)
            return tuple(tuple(r) for r in m)
        if isinstance(e, _Tr):
            x = self.ev(e.args[0])
            return tuple(zip(*x))
        if isinstance(e, _Dot):
            return self.dt(self.ev(e.args[0]))
        if isinstance(e, _Skew):
            v = [r[0] for r in self.ev(e.args[0])]
            neg = [self.mul(self.num(-1), x) for x in v]
            z = self.num(0)
            return ((z, neg[2], v[1]), (v[2], z, neg[0]), (neg[1], v[0], z))
        if isinstance(e, _Det):
            return self.det(self.ev(e.args[0]))
        raise PoinsotError(f"derivation {NAME}: the model cannot evaluate {e}")

    def det(self, m: Any) -> Any:
        terms = []
        for (i, j, k), sign in (((0, 1, 2), 1), ((1, 2, 0), 1), ((2, 0, 1), 1)):
            for cols, sg in (((0, 1, 2), sign), ((0, 2, 1), -sign)):
                t = self.num(sg)
                for r, col in zip((i, j, k), cols):
                    t = self.mul(t, m[r][col])
                terms.append(t)
        return _sum(self, terms)

    def _positive(self, e: Any) -> list[Any]:
        tags = {s.tag for s in e.atoms(_Sym)}
        out = [self.one]
        if len(tags) == 1:
            out.append(self.positive[tags.pop()])
        return out

    def _sqrt(self, e: Any) -> Any:
        z = self.ev(e.base)
        for rho in self._positive(e):
            if z[1] == 1 and self.nf(rho * rho - z[0]) == 0:
                return self.sc(rho)
        raise PoinsotError(f"derivation {NAME}: no positive square root of {e.base} in the model")

    def _atan2(self, e: Any) -> Any:
        y, x = (self.ev(a) for a in e.args)
        if y[1] == 1 and x[1] == 1:
            for rho in self._positive(e):
                for k in range(len(_ANGLES)):
                    if (
                        self.nf(y[0] - rho * self.s[k]) == 0
                        and self.nf(x[0] - rho * self.c[k]) == 0
                    ):
                        return self.sc(self.a[k])
        raise PoinsotError(
            f"derivation {NAME}: atan2{e.args} is not an angle of the model: its arguments are "
            "not ρ(sin q, cos q) with ρ > 0 on the canonical range"
        )

    # -- value → sympy
    def expr(self, v: Any) -> Any:
        if _is_mat(v):
            return sp.ImmutableMatrix([[self.expr(x) for x in r] for r in v])
        n, d = v
        return self._poly(n) if d == 1 else self._poly(n) / self._poly(d)

    def _poly(self, p: Any) -> Any:
        terms = []
        for monom, coeff in p.terms():
            factors = [sp.Rational(int(coeff.numerator), int(coeff.denominator))]
            factors += [g**k for g, k in zip(self.gen_expr, monom) if k]
            terms.append(sp.Mul(*factors))
        return sp.Add(*terms)

    def __call__(self, e: Any) -> Any:
        e = sp.sympify(e)
        try:
            return self._out[e]
        except KeyError:
            pass
        out = self.expr(self.ev(e))
        self._out[e] = out
        return out


def _is_mat(v: Any) -> bool:
    return (
        isinstance(v, tuple)
        and len(v) > 0
        and isinstance(v[0], tuple)
        and len(v[0]) > 0
        and (isinstance(v[0][0], tuple))
    )


def _sum(m: _Model, values: list[Any]) -> Any:
    out = values[0]
    for v in values[1:]:
        out = m.add(out, v)
    return out


def _const(value: Any) -> Callable[[], Any]:
    """A definition whose value is already known."""
    return lambda: value


def _item(values: Callable[[], Any], k: int) -> Callable[[], Any]:
    """A definition: component ``k`` of ``values()``."""
    return lambda: values()[k]


def _vee(w: Any) -> list[Any]:
    """The vector of an antisymmetric matrix [w]×: (W₃₂, W₁₃, W₂₁)."""
    return [w[2][1], w[0][2], w[1][0]]


# ---- plain symbols for the numeric forms -----------------------------------------------------


def _plain_angles(q: Sequence[Any]) -> tuple[list[Any], list[Any], dict[Any, Any]]:
    names = [str(x.func) for x in q]
    angles = [sp.Symbol(n) for n in names]
    rates = [sp.Symbol(f"{n}_dot") for n in names]
    rep: dict[Any, Any] = {x.diff(_t): r for x, r in zip(q, rates)}
    rep.update(dict(zip(q, angles)))
    return angles, rates, rep


def _subscript(m: int, n: int) -> str:
    return f"R{m + 1}{n + 1}".translate(_SUB)


# ---- the unit: 2.98–2.101 --------------------------------------------------------------------


def _unit(d: Derivation, m: _Model) -> None:
    tag = "zxz-intrinsic"
    phi, theta, psi = _PHI, _THETA, _PSI
    dphi, dtheta, dpsi = (x.diff(_t) for x in (phi, theta, psi))
    R = _sym("R", tag, vector=True)
    prod = sp.Mul(_Rot(2, phi), _Rot(0, theta), _Rot(2, psi))
    m.define(R, lambda: m.ev(prod))
    m.positive[tag] = m.s[m.index[theta]]
    w_vec = _sym(r"\vec{\omega}", tag, vector=True)
    w = [_sym(rf"\omega_{{{k + 1}}}", tag) for k in range(3)]
    ws_vec = _sym(r"\vec{\omega}'", tag, vector=True)
    body = lambda: _vee(m.ev(sp.Mul(_Tr(R), _Dot(R))))
    space = lambda: _vee(m.ev(sp.Mul(_Dot(R), _Tr(R))))
    m.define(w_vec, lambda: tuple((x,) for x in body()))
    m.define(ws_vec, lambda: tuple((x,) for x in space()))
    for k in range(3):
        m.define(w[k], _item(body, k))
    xez = [_sym(rf"\omega_{{\{n}}}", tag) for n in ("xi", "eta", "zeta")]
    nodes = sp.Mul(_Rot(2, phi), _Rot(0, theta))
    for k in range(3):
        m.define(xez[k], _item(lambda: [r[0] for r in m.mul(m.ev(_Tr(nodes)), m.ev(ws_vec))], k))

    for axis, q, turn in ((2, phi, "x̂ towards ŷ"), (0, theta, "ŷ towards ẑ")):
        d.given(
            f"the elementary rotation about {_AXIS[axis]} (active, right-handed: it turns "
            f"{turn}); its columns are the turned axes in the old ones.",
            _eq(_Rot(axis, q), _mat(m.expr(m.ev(_Rot(axis, q))))),
        )
    d.step(
        "Fig. 2.12: turn the fixed axes XYZ by φ about Z (X goes to the line of nodes ξ), then by "
        "θ about ξ (giving ξηζ), then by ψ about ζ (giving the body axes 1, 2, 3). Each turn is "
        "about an axis already turned (intrinsic), so the factors compose to the right; the "
        "columns of R are the body axes in fixed components.",
        [_eq(R, prod), _eq(prod, m(prod))],
        "R/zxz-intrinsic",
    )
    d.step(
        "The angular velocity in body axes is read off RᵀṘ: differentiating RᵀR = 1 gives "
        "RᵀṘ = −(RᵀṘ)ᵀ, so RᵀṘ is antisymmetric, [ω]× (as in 2.13, now in body axes).",
        _eq(_Skew(w_vec), sp.Mul(_Tr(R), _Dot(R))),
    )
    xez_col = _col(xez)
    d.step(
        "ω_ξ, ω_η, ω_ζ are the components of ω along the axes ξηζ of R_z(φ)R_x(θ) (Fig. 2.13); "
        "the body axes are those turned by ψ about ζ, so the ξηζ components are R_z(ψ) times the "
        "body ones.",
        _eq(xez_col, sp.Mul(_Rot(2, psi), w_vec)),
    )
    eq298 = _col([dtheta, dphi * sp.sin(theta), _add(dpsi, dphi * sp.cos(theta))])
    d.step(
        "Resolve each rate along ξηζ: θ̇ turns about ξ itself, φ̇ about Z, which on ξηζ is "
        "(0, sin θ, cos θ), and ψ̇ about ζ. Checked against RᵀṘ, this is 2.98.",
        _eq(xez_col, eq298),
        "2.98",
    )
    resolved = _col([*_turned(xez[0], xez[1], psi), xez[2]])
    result299 = _body_rates(dphi, dtheta, dpsi, theta, psi)
    d.step(
        "Back to the body axes, (ω₁, ω₂, ω₃) = R_z(ψ)ᵀ(ω_ξ, ω_η, ω_ζ), and substitute 2.98: this "
        "is 2.99. The unit prints ω₃ = ω_ξ; the component along 3 = ζ is ω_ζ (an index typo; "
        "the final ψ̇ + φ̇ cos θ is right).",
        [_eq(_col(w), resolved), _eq(resolved, result299)],
        "2.99",
    )
    angles, rates, rep = _plain_angles((phi, theta, psi))
    d.function("2.99", result299.xreplace(rep), [*angles, *rates])

    T = _sym("T", tag)
    t_def = _HALF * _add(_I1 * w[0] ** 2, _I2 * w[1] ** 2, _I3 * w[2] ** 2)
    m.define(T, lambda: m.ev(t_def))
    d.given(
        "the kinetic energy in principal body axes, with the principal moments I₁, I₂, I₃.",
        _eq(T, t_def),
        "2.100",
    )
    d.function(
        "2.100",
        t_def.xreplace({**{w[k]: result299[k] for k in range(3)}}).xreplace(rep),
        [*angles, *rates, _I1, _I2, _I3],
    )
    perp = _add(dtheta**2, dphi**2 * sp.sin(theta) ** 2)
    d.step(
        "Square and add the first two lines of 2.99: the cross terms 2θ̇φ̇ sin θ sin ψ cos ψ "
        "cancel and sin²ψ + cos²ψ = 1.",
        _eq(_add(w[0] ** 2, w[1] ** 2), perp),
    )
    r301 = _add(_HALF * _I1 * perp, _HALF * _I3 * _add(dpsi, dphi * sp.cos(theta)) ** 2)
    d.step(
        "A symmetric top has I₂ = I₁: put that in 2.100 and use the line above and ω₃ from "
        "2.99. T depends on θ but not on φ or ψ (2.101).",
        [
            _eq(T, _add(_HALF * _I1 * _add(w[0] ** 2, w[1] ** 2), _HALF * _I3 * w[2] ** 2)),
            _eq(_add(_HALF * _I1 * _add(w[0] ** 2, w[1] ** 2), _HALF * _I3 * w[2] ** 2), r301),
        ],
        "2.101",
    )
    d.function("2.101", r301.xreplace(rep), [*angles, *rates, _I1, _I3])


# ---- every convention ----------------------------------------------------------------------


def _rows_over(nums: list[list[Any]], den: Any) -> tuple[list[list[Any]], list[Any]]:
    """Cancels the common factor of the numerators of one row and the denominator; the
    denominator is made to start with a positive coefficient."""
    out = []
    dens = []
    for row in nums:
        g = den
        for x in row:
            g = g.gcd(x)
        r, dd = [x.exquo(g) for x in row], den.exquo(g)
        if dd.LC < 0:
            r, dd = [-x for x in r], -dd
        out.append(r)
        dens.append(dd)
    return out, dens


def _inverse_rates(m: _Model, jac: Any, omega: Sequence[Any]) -> tuple[sp.ImmutableMatrix, Any]:
    """q̇ = adj(M) ω / det M, row by row with common factors cancelled."""
    det = m.det(jac)[0]
    nums = []
    for i in range(3):
        row = []
        for j in range(3):
            # adj(M)[i][j] = cofactor of M[j][i]
            r = [a for a in range(3) if a != j]
            c = [b for b in range(3) if b != i]
            minor = m.nf(
                jac[r[0]][c[0]][0] * jac[r[1]][c[1]][0] - jac[r[0]][c[1]][0] * jac[r[1]][c[0]][0]
            )
            row.append(minor if (i + j) % 2 == 0 else -minor)
        nums.append(row)
    rows, dens = _rows_over(nums, det)
    out = []
    for r, dd in zip(rows, dens):
        top = sp.Add(*[m._poly(x) * w for x, w in zip(r, omega)])
        out.append(top if dd == 1 else sp.Mul(top, sp.Pow(m._poly(dd), -1), evaluate=False))
    return _col(out), det


def _sequence(d: Derivation, m: _Model, seq: str, intrinsic: bool, have_r: bool) -> None:
    kind = "intrinsic" if intrinsic else "extrinsic"
    tag = f"{seq}-{kind}"
    q = (_PHI, _THETA, _PSI) if tag == "zxz-intrinsic" else (_ALPHA, _BETA, _GAMMA)
    qa, qb, qc = (_name(x) for x in q)
    rates = [x.diff(_t) for x in q]
    axes = [_AXIS.index(ch) for ch in seq]
    order = (0, 1, 2) if intrinsic else (2, 1, 0)
    fax = [axes[i] for i in order]
    fq = [q[i] for i in order]
    proper = axes[0] == axes[2]
    mid = m.index[q[1]]
    m.positive[tag] = m.s[mid] if proper else m.c[mid]
    angles, plain_rates, rep = _plain_angles(q)
    label = f"{kind} {seq}"

    R = _sym("R", tag, vector=True)
    prod = sp.Mul(*[_Rot(a, x) for a, x in zip(fax, fq)])
    if R not in m.defs:
        m.define(R, lambda: m.ev(prod))
    if not have_r:
        how = (
            f"turn by {qa} about {seq[0]}, then by {qb} about the new {seq[1]}, then by {qc} "
            f"about the newest {seq[2]}: the factors compose to the right"
            if intrinsic
            else f"turn by {qa} about the fixed {seq[0]}, then by {qb} about the fixed {seq[1]}, "
            f"then by {qc} about the fixed {seq[2]}: each later turn multiplies from the left, "
            f"so this is the intrinsic {seq[::-1]} with the angles reversed"
        )
        d.step(f"{label.capitalize()}: {how}.", [_eq(R, prod), _eq(prod, m(prod))], f"R/{tag}")
    d.function(f"R/{tag}", m(prod).xreplace(rep), angles)

    # body and space angular velocity, each rate about its own axis
    w_vec = _sym(r"\vec{\omega}", tag, vector=True)
    ws_vec = _sym(r"\vec{\omega}'", tag, vector=True)
    w = [_sym(rf"\omega_{{{k + 1}}}", tag) for k in range(3)]
    ws = [_sym(rf"\omega_{{{n}}}", tag) for n in "XYZ"]
    body = lambda: _vee(m.ev(sp.Mul(_Tr(R), _Dot(R))))
    space = lambda: _vee(m.ev(sp.Mul(_Dot(R), _Tr(R))))
    if w_vec not in m.defs:
        m.define(w_vec, lambda: tuple((x,) for x in body()))
        m.define(ws_vec, lambda: tuple((x,) for x in space()))
    for k in range(3):
        m.define(w[k], _item(body, k))
        m.define(ws[k], _item(space, k))
    e = _UNITS
    fr = [x.diff(_t) for x in fq]
    per_axis_body = _add(
        sp.Mul(fr[0], _Tr(_Rot(fax[2], fq[2])), _Tr(_Rot(fax[1], fq[1])), e[fax[0]]),
        sp.Mul(fr[1], _Tr(_Rot(fax[2], fq[2])), e[fax[1]]),
        sp.Mul(fr[2], e[fax[2]]),
    )
    per_axis_space = _add(
        sp.Mul(fr[0], e[fax[0]]),
        sp.Mul(fr[1], _Rot(fax[0], fq[0]), e[fax[1]]),
        sp.Mul(fr[2], _Rot(fax[0], fq[0]), _Rot(fax[1], fq[1]), e[fax[2]]),
    )
    rb, rs = m(per_axis_body), m(per_axis_space)
    d.step(
        f"{label.capitalize()}, body axes ([ω]× = RᵀṘ as for 2.99): each rate turns the body "
        "about its own axis, carried into body axes by the turns that follow it.",
        [_eq(w_vec, per_axis_body), _eq(per_axis_body, rb)],
        f"2.99/{tag}",
    )
    d.function(f"2.99/{tag}", rb.xreplace(rep), [*angles, *plain_rates])

    jac = tuple(
        tuple(m.sc(x[0].diff(m.d[m.index[r]])) for r in q) for x in (r[0] for r in m.ev(w_vec))
    )
    M = _sym("M", tag, vector=True)
    m.define(M, _const(jac))
    det_val = m.det(jac)
    det_expr = m.expr(det_val)
    zeros = _singular(m, det_val[0], mid)
    d.step(
        f"The rates enter linearly, ω = M ({', '.join(x + '̇' for x in (qa, qb, qc))}) with "
        f"M = ∂ω/∂(rates). Its determinant vanishes at {qb} = {zeros[1]}: there M loses rank "
        "and the rates cannot be recovered from ω (the singular angles, gimbal lock).",
        [_eq(_Det(M), _Det(m(M))), _eq(_Det(m(M)), det_expr)],
        f"det/{tag}",
    )
    d.function(f"det/{tag}", det_expr.xreplace(rep), angles)
    inv, _ = _inverse_rates(m, jac, w)
    d.step(
        f"Away from {qb} = {zeros[1]}, invert: the rates are M⁻¹ω = adj(M) ω / det M.",
        _eq(_col(rates), inv),
        f"rates/{tag}",
    )
    wp = [sp.Symbol(f"omega_{k + 1}") for k in range(3)]
    d.function(f"rates/{tag}", inv.xreplace(dict(zip(w, wp))).xreplace(rep), [*angles, *wp])

    d.step(
        f"{label.capitalize()}, space axes ([ω′]× = ṘRᵀ): ω′ is ω carried to the fixed axes, "
        "R ω; the first rate turns about its fixed axis, each later one about its axis as "
        "turned by the turns before it.",
        [
            _eq(ws_vec, sp.Mul(R, w_vec)),
            _eq(sp.Mul(R, w_vec), per_axis_space),
            _eq(per_axis_space, rs),
        ],
        f"space/{tag}",
    )
    d.function(f"space/{tag}", rs.xreplace(rep), [*angles, *plain_rates])
    jac_s = tuple(
        tuple(m.sc(x[0].diff(m.d[m.index[r]])) for r in q) for x in (r[0] for r in m.ev(ws_vec))
    )
    inv_s, det_s = _inverse_rates(m, jac_s, ws)
    if m.nf(det_s - det_val[0]) != 0:
        raise PoinsotError(f"derivation {NAME}: det M′ ≠ det M for {tag}")
    d.step(
        "In space axes the rate map is R M, with the same determinant (det R = 1): the rates are "
        f"(R M)⁻¹ ω′, singular at the same {qb}.",
        _eq(_col(rates), inv_s),
        f"rates-space/{tag}",
    )
    wsp = [sp.Symbol(f"omega_{n}") for n in "XYZ"]
    d.function(
        f"rates-space/{tag}", inv_s.xreplace(dict(zip(ws, wsp))).xreplace(rep), [*angles, *wsp]
    )

    _angles_from_matrix(d, m, tag, q, prod, proper, label)

    # gimbal lock: at each singular angle R depends on one combination of the outer angles
    for beta in zeros[0]:
        turned = m.mul(m.ev(_Rot(fax[1], beta)), m.ev(e[fax[2]]))
        sigma = turned[fax[0]][0][0]
        if sigma not in (1, -1):
            raise PoinsotError(f"derivation {NAME}: {tag} at {beta}: no lock")
        sign = 1 if sigma == 1 else -1
        locked = sp.Mul(_Rot(fax[0], fq[0]), _Rot(fax[1], beta), _Rot(fax[2], fq[2]))
        merged = sp.Mul(_Rot(fax[0], _add(fq[0], sign * fq[2])), _Rot(fax[1], beta))
        first, last = _name(fq[0]), _name(fq[2])
        at = _ANGLE_TEXT[beta]
        d.step(
            f"At {qb} = {at} ({label}), R_{_AXIS[fax[1]]}({at}) carries the {_AXIS[fax[2]]} axis onto "
            f"{'+' if sign > 0 else '−'}{_AXIS[fax[0]]}, so R depends on {first} "
            f"{'+' if sign > 0 else '−'} {last} alone: only that combination can be read from R.",
            _eq(locked, merged),
            f"lock/{tag}@{at}",
        )


_ANGLE_TEXT = {sp.Integer(0): "0", sp.pi: "π", sp.pi / 2: "π/2", -sp.pi / 2: "−π/2"}


def _name(q: Any) -> str:
    """The angle's letter (φ, θ, ψ, α, β, γ)."""
    return str(sp.pretty(q, use_unicode=True)).replace("(t)", "")


def _singular(m: _Model, det: Any, mid: int) -> tuple[list[Any], str]:
    """The singular angles: where the determinant (±sin β or ±cos β) vanishes."""
    for sign in (1, -1):
        if m.nf(det - sign * m.s[mid]) == 0:
            return [sp.Integer(0), sp.pi], "0 and π (sin = 0)"
        if m.nf(det - sign * m.c[mid]) == 0:
            return [sp.pi / 2, -sp.pi / 2], "±π/2 (cos = 0)"
    raise PoinsotError(f"derivation {NAME}: the determinant {det} is not ±sin or ±cos")


def _angles_from_matrix(
    d: Derivation,
    m: _Model,
    tag: str,
    q: Sequence[Any],
    prod: Any,
    proper: bool,
    label: str,
) -> None:
    """The angles from R: the entries that are ±cos β (or ±sin β) and ρ(sin, cos) of the outer
    angles, found by scanning R, read back with atan2 on the canonical range."""
    entries = [[x[0] for x in row] for row in m.ev(prod)]
    ent = [[_sym(f"R_{{{i + 1}{j + 1}}}", tag) for j in range(3)] for i in range(3)]
    for i in range(3):
        for j in range(3):
            m.define(ent[i][j], _const(m.sc(entries[i][j])))
    mid = m.index[q[1]]
    rho = m.s[mid] if proper else m.c[mid]
    target = m.c[mid] if proper else m.s[mid]

    def find(p: Any) -> tuple[int, int, int]:
        for i in range(3):
            for j in range(3):
                for sign in (1, -1):
                    if m.nf(entries[i][j] - sign * p) == 0:
                        return i, j, sign
        raise PoinsotError(f"derivation {NAME}: {tag}: no entry of R is ±{p}")

    i0, j0, s0 = find(target)
    others = [ent[i0][j] for j in range(3) if j != j0]
    root = sp.sqrt(_add(others[0] ** 2, others[1] ** 2))
    middle = sp.atan2(root, s0 * ent[i0][j0]) if proper else sp.atan2(s0 * ent[i0][j0], root)
    k_entry = f"{'−' if s0 < 0 else ''}{_subscript(i0, j0)}"
    explain = [f"{k_entry} = {'cos' if proper else 'sin'} {_name(q[1])}"]
    forms = {1: middle}
    for pos in (0, 2):
        k = m.index[q[pos]]
        ys, xs = find(rho * m.s[k]), find(rho * m.c[k])
        forms[pos] = sp.atan2(ys[2] * ent[ys[0]][ys[1]], xs[2] * ent[xs[0]][xs[1]])
        name = _name(q[pos])
        explain.append(
            f"({'−' if ys[2] < 0 else ''}{_subscript(ys[0], ys[1])}, "
            f"{'−' if xs[2] < 0 else ''}{_subscript(xs[0], xs[1])}) = "
            f"{'sin' if proper else 'cos'} {_name(q[1])} "
            f"(sin {name}, cos {name})"
        )
    b = _name(q[1])
    rng = f"0 < {b} < π" if proper else f"−π/2 < {b} < π/2"
    d.step(
        f"Angles from the matrix ({label}): in R, {'; '.join(explain)}. On the canonical "
        f"ranges (first and third angle in (−π, π], {rng}, where "
        f"{'sin' if proper else 'cos'} {b} > 0) atan2 reads them back.",
        _eq(_col(list(q)), _col([forms[0], forms[1], forms[2]])),
        f"angles/{tag}",
    )
    plain = {ent[i][j]: sp.Symbol(f"R{i + 1}{j + 1}") for i in range(3) for j in range(3)}
    d.function(
        f"angles/{tag}",
        _col([forms[0], forms[1], forms[2]]).xreplace(plain),
        [plain[ent[i][j]] for i in range(3) for j in range(3)],
    )


# ---- the derivation ------------------------------------------------------------------------------


def derive() -> Derivation:
    """Builds and checks the derivation (each step is verified in the model as it is made)."""
    m = _Model()
    d = Derivation(
        NAME,
        "Euler's angles: the attitude and the angular velocity from the angle rates",
        summary=(
            "The unit's z-x-z Euler angles (Fig. 2.12): R = R_z(φ)R_x(θ)R_z(ψ), the angular "
            "velocity along ξηζ (2.98) and along the body axes (2.99) from [ω]× = RᵀṘ, and the "
            "kinetic energy of the symmetric top (2.100–2.101). Then every one of the 24 "
            "conventions (6 proper Euler and 6 Tait–Bryan sequences, intrinsic and extrinsic): "
            "the matrix, ω in body and space axes from the rates, the determinant of the rate "
            "map and its singular angles, the rates from ω, the angles from a matrix, and the "
            "matrix at gimbal lock. Each step is checked exactly, with every angle a point "
            "(cos, sin) of the unit circle."
        ),
        model=m,
        context={_I2: _I1},
    )
    _unit(d, m)
    d.given(
        "the elementary rotation about y (active, right-handed: it turns ẑ towards x̂), for the "
        "sequences that turn about y.",
        _eq(_Rot(1, _BETA), _mat(m.expr(m.ev(_Rot(1, _BETA))))),
    )
    for seq in SEQUENCES:
        for intrinsic in (True, False):
            _sequence(d, m, seq, intrinsic, have_r=(seq == "zxz" and intrinsic))
    return d


# ---- the unit as printed -------------------------------------------------------------------------


def _printed() -> tuple[Printed, ...]:
    tag = "zxz-intrinsic"
    phi, theta, psi = _PHI, _THETA, _PSI
    dphi, dtheta, dpsi = (x.diff(_t) for x in (phi, theta, psi))
    w = [_sym(rf"\omega_{{{k + 1}}}", tag) for k in range(3)]
    xez = [_sym(rf"\omega_{{\{n}}}", tag) for n in ("xi", "eta", "zeta")]
    T = _sym("T", tag)
    p299_mid = _col([*_turned(xez[0], xez[1], psi), xez[0]])  # the unit's third row: ω_ξ
    p299_end = _body_rates(dphi, dtheta, dpsi, theta, psi)
    perp = _add(dtheta**2, dphi**2 * sp.sin(theta) ** 2)
    psi_note = "the unit writes the spin angle Ψ; it is ψ here"
    return (
        Printed(
            "2.98",
            NAME,
            r"\omega_{\xi} = \dot{\theta}"
            r" ,  \omega_{\eta} = \dot{\phi} \sin\theta"
            r" ,  \omega_{\zeta} = \dot{\Psi} + \dot{\phi} \cos\theta",
            _eq(
                _col(xez),
                _col([dtheta, dphi * sp.sin(theta), _add(dpsi, dphi * sp.cos(theta))]),
            ),
            "three equations printed on one line (the first in its own display); read as one "
            "column; " + psi_note,
        ),
        Printed(
            "2.99",
            NAME,
            r"\omega_{1} = \omega_{\xi} \cos \Psi + \omega_{\eta} \sin \Psi = \dot{\theta} \cos "
            r"\Psi + \dot{\phi} \sin \theta \sin \Psi"
            r" \\ \omega_{2} = -\omega_{\xi} \sin \Psi + \omega_{\eta} \cos \Psi = -\dot{\theta} "
            r"\sin \Psi + \dot{\phi} \sin \theta \cos \Psi"
            r" \\ \omega_{3} = \omega_{\xi} = \dot{\Psi} + \dot{\phi} \cos \theta",
            [_eq(_col(w), p299_mid), _eq(p299_mid, p299_end)],
            "three chains read as one column chain; " + psi_note,
        ),
        Printed(
            "2.100",
            NAME,
            r"T = \frac{1}{2} (I_1 \omega_1^2 + I_2 \omega_2^2 + I_3 \omega_3^2)",
            _eq(T, _HALF * _add(_I1 * w[0] ** 2, _I2 * w[1] ** 2, _I3 * w[2] ** 2)),
        ),
        Printed(
            "2.101",
            NAME,
            r"T = \frac{1}{2}I_1(\dot{\theta}^2 + \dot{\phi}^2 \sin^2\theta) + "
            r"\frac{1}{2}I_3(\dot{\Psi} + \dot{\phi}\cos\theta)^2",
            _eq(T, _add(_HALF * _I1 * perp, _HALF * _I3 * _add(dpsi, dphi * sp.cos(theta)) ** 2)),
            "for a symmetric top, I₂ = I₁ (the derivation's standing assumption); " + psi_note,
        ),
    )


#: The unit's equations 2.98–2.101 as printed (transcribed, misprints included).
PRINTED: tuple[Printed, ...] = _printed()
