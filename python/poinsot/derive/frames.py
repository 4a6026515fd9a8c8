"""Moving frames, derived: the unit's equations 2.1–2.28.

Covers
------
2.1–2.5
    A frame in translation: r⃗′ = R⃗ + r⃗, its rates ṙ′ = Ṙ + ṙ and r̈′ = R̈ + r̈, and the moving
    observer's law m r̈ = F⃗ − m R̈ = F⃗_eff.
2.6–2.14
    A vector on the fixed and on the rotating axes (2.6–2.8), its rate in each (2.9–2.11), the
    turning axes dî/dt = ω⃗ × î shown from RᵀR = 1 (2.12–2.13), and
    (dV⃗/dt)_fix = (dV⃗/dt)_rot + ω⃗ × V⃗ (2.14).
2.15–2.23
    The operator (d/dt)_fix = (d/dt)_rot + ω⃗× (2.15), ω̇ the same in both frames (2.16), the
    second rate with the unit's intermediate lines (2.17–2.18), and the velocity and acceleration
    of a particle with their named terms: relative, Coriolis 2ω⃗ × ṙ, centripetal ω⃗ × (ω⃗ × r⃗),
    Euler (transverse) ω̇ × r⃗ (2.19–2.23, with the compact "subscript f / r" forms).
2.24–2.28
    The centripetal magnitude ω² r sin θ (2.24) and the fictitious forces: Newton's law in the
    fixed frame (2.25), the rotating frame's law with Coriolis and centrifugal forces for constant
    ω⃗ (2.26), in general with the translational and Euler forces too (2.27), and the observer at
    rest in the rotating frame (2.28).

Model
-----
Each paragraph of the unit has its own setting (its figure and its assumptions), and each step
is checked in the components of its setting. The setting is carried by the vectors' class (all
print alike, in the unit's notation); an expression may not mix settings.

* Translation (2.1–2.5): components on axes that keep their directions, arbitrary functions of
  t; a rate is the derivative of the components; r⃗′ = R⃗ + r⃗, F⃗ = m r̈′ (Newton, 2.4) and
  F⃗_eff = m r̈ (what the moving observer calls the force).
* The axes (2.6–2.14): the rotating axes turned from the fixed ones by z-x-z Euler angles φ(t),
  θ(t), ψ(t) of arbitrary time dependence, R = R_z(φ) R_x(θ) R_z(ψ) (its columns are î, ĵ, k̂
  in fixed components). Components are on the rotating axes, exactly, as polynomials in the
  sines, cosines and rates of the angles reduced modulo sin² + cos² = 1 (fast and exact). The
  fixed-frame rate of a vector is computed as it is defined: Rᵀ d/dt (R X). ω⃗ has the
  components of the unit's 2.99; the derivation shows that RᵀṘ = [ω⃗]× with them.
* A point carried by the rotating frame (2.12): the same axes, constant components on them.
* The rotating frame (2.15–2.23, 2.27): components on the rotating axes, arbitrary functions of
  t, ω⃗ too; (d/dt)_rot differentiates the components and (d/dt)_fix X = Ẋ + ω⃗ × X (2.15, shown
  in the previous setting as 2.14 for every vector and every rotation). The moving origin R⃗ is
  arbitrary; r⃗′ = R⃗ + r⃗ and F⃗ = m (d²r⃗′/dt²)_fix.
* The angle θ of 2.24: ω⃗ = ω k̂ and r⃗ = r (sin θ î + cos θ k̂) (axes chosen so; ω, r > 0,
  0 < θ < π).
* Constant ω⃗ with the origins together (2.25–2.26): ω⃗'s components are constants, R⃗ = 0.
* At rest in the rotating frame (2.28): r⃗'s components are constants too.

The unit's dots (ṙ, ω̇) are rates seen from the fixed frame; d′/dt and d/dt of 2.17–2.18 are
(d/dt)_fix and (d/dt)_rot; subscripts f and r in 2.22–2.23 mark the same two rates.

Results
-------
Every number of the range, "2.1" to "2.28". Numeric forms (``Derivation.functions``, for the
bridge to :class:`poinsot.MovingFrame`): "2.1" r⃗′ (m), "2.2" ṙ′ (m/s), "2.3" r̈′ (m/s²) of the
translating frame; "2.5" F⃗_eff (N); "2.20" ṙ′ (m/s), "2.21" r̈′ (m/s²); "2.24"
|ω⃗ × (ω⃗ × r⃗)| (m/s²); "2.27" F⃗_eff with every fictitious force (N); "2.28" F⃗_eff at rest (N).
Vector arguments are 3-sequences of components on any one set of axes (the formulas hold on
any).

The printed equations (``PRINTED``) are the unit's as scanned, equation numbers dropped; their
misprints are found by :func:`poinsot.derive.errata`.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import sympy as sp
from sympy.physics.vector import dynamicsymbols
from sympy.polys.domains import QQ
from sympy.polys.orderings import lex
from sympy.polys.rings import ring

from ..errors import PoinsotError
from ._core import Cross, Derivation, Dot, DtFix, DtRot, Printed, Unit, Vec, VectorModel
from ._core import add as _sum
from ._core import eq as _eq
from ._core import mul as _mul

__all__ = ["derive", "PRINTED"]

_t = dynamicsymbols._t
m = sp.Symbol("m", positive=True)

# ---- notation of this part of the unit ----------------------------------------------------------


def _nest(e: Any) -> tuple[int, Any]:
    """How many times ``e`` applies its own class, and to what."""
    order, inner = 1, e.args[0]
    while isinstance(inner, type(e)):
        order, inner = order + 1, inner.args[0]
    return order, inner


def _base_prime(printer: Any, v: Any) -> tuple[str, str]:
    """A vector's LaTeX without its prime, and the prime (to put an accent under it)."""
    if isinstance(v, (Vec, Unit)) and v.name.endswith("'"):
        return printer._print(type(v)(v.name[:-1])), "'"
    return printer._print(v), ""


_ACCENT = {1: r"\dot", 2: r"\ddot", 3: r"\dddot"}


class _Dot(DtFix):
    """Ẋ: the unit's dot, the rate seen from the fixed frame (nested: Ẍ)."""

    def _body_latex(self, printer: Any) -> str:
        order, inner = _nest(self)
        if isinstance(inner, (Vec, Unit)) and order in _ACCENT:
            base, prime = _base_prime(printer, inner)
            return _ACCENT[order] + "{" + base + "}" + prime
        n = str(order)
        return r"\frac{d^{" + n + r"}}{dt^{" + n + r"}}\left(" + printer._print(inner) + r"\right)"


def _frac(printer: Any, e: Any, d: str) -> str:
    order, inner = _nest(e)
    dd = d if order == 1 else d + "^{" + str(order) + "}"
    dt = "dt" if order == 1 else "dt^{" + str(order) + "}"
    if isinstance(inner, (Vec, Unit)):
        return r"\frac{" + dd + printer._print(inner) + "}{" + dt + "}"
    return r"\frac{" + dd + "}{" + dt + r"}\left(" + printer._print(inner) + r"\right)"


class _DPrime(DtFix):
    """d′X/dt: the unit's notation (2.17) for the fixed-frame rate."""

    def _body_latex(self, printer: Any) -> str:
        return _frac(printer, self, "d'")


class _DPlain(DtRot):
    """dX/dt: the unit's notation (2.17) for the rotating-frame rate."""

    def _body_latex(self, printer: Any) -> str:
        return _frac(printer, self, "d")


def _subscripted(printer: Any, e: Any, sub: str, dots: bool) -> str:
    order, inner = _nest(e)
    base, prime = _base_prime(printer, inner)
    if dots:
        base = _ACCENT[order] + "{" + base + "}"
    return base + prime + "_{" + sub + "}"


class _SubF(DtFix):
    """ṙ′_f, r̈′_f: the compact form of 2.22–2.23, subscript f for the fixed-frame rate."""

    def _body_latex(self, printer: Any) -> str:
        return _subscripted(printer, self, "f", True)


class _SubR(DtRot):
    """ṙ_r, r̈_r: subscript r for the rotating-frame rate."""

    def _body_latex(self, printer: Any) -> str:
        return _subscripted(printer, self, "r", True)


class _ScanF(DtFix):
    """The scan's r⃗_f of 2.22–2.23: a subscript f with its dots lost (the order is read from
    the text: first rates in 2.22, the compact 2.20, second in 2.23, the compact 2.21)."""

    def _body_latex(self, printer: Any) -> str:
        return _subscripted(printer, self, "f", False)


class _ScanR(DtRot):
    """The scan's r⃗_r: a subscript r with its dot lost."""

    def _body_latex(self, printer: Any) -> str:
        return _subscripted(printer, self, "r", False)


class _Norm(sp.Function):
    """|X|, the magnitude of a vector."""

    nargs = 1

    def _latex(self, printer: Any) -> str:
        return r"\left|" + printer._print(self.args[0]) + r"\right|"


class _Zero(Vec):
    """The zero vector, printed 0 as in the unit."""

    def _latex(self, printer: Any) -> str:
        return "0"


ZERO = _Zero("0")

# The settings: a vector's class says which paragraph of the unit, and so which model, it
# belongs to. Vec itself is the rotating frame of 2.15–2.23 and 2.27.


class _InTranslation(Vec):
    """A vector of 2.1–2.5: the moving frame only translates."""


class _OnAxes(Vec):
    """A vector of 2.6–2.14: the rotating axes turned by Euler angles."""


class _Carried(Vec):
    """A vector of 2.12: a point carried by the rotating axes."""


class _AtAngle(Vec):
    """A vector of 2.24: ω⃗ along k̂, r⃗ at the angle θ from it."""


class _Steady(Vec):
    """A vector of 2.25–2.26: ω⃗ constant, the origins together."""


class _AtRest(Vec):
    """A vector of 2.28: ω⃗ constant, the particle at rest in the rotating frame."""


def _chain(*sides: Any) -> list[Any]:
    """a = b = c as the list [Eq(a, b), Eq(b, c)]."""
    return [_eq(a, b) for a, b in zip(sides[:-1], sides[1:])]


# ---- the models ---------------------------------------------------------------------------------


def _vec(*names: str) -> sp.Matrix:
    return sp.Matrix(dynamicsymbols(" ".join(names)))


def _zero3() -> sp.Matrix:
    return sp.zeros(3, 1)


class _Mat(tuple):  # type: ignore[type-arg]
    """A 3×3 matrix of ring elements (rows), told apart from a vector (a plain 3-tuple)."""


class _Axes:
    """Exact components on the rotating axes, the axes turned from the fixed ones by z-x-z Euler
    angles φ(t), θ(t), ψ(t): R = R_z(φ) R_x(θ) R_z(ψ), columns î, ĵ, k̂ in fixed components.

    Values are polynomials over ℚ in sin and cos of the angles, their rates and the components
    (a sparse polynomial ring), reduced modulo sin² + cos² = 1: the reduced form is canonical,
    so an identity reduces to the same polynomial on both sides. ``(d/dt)_fix X = Rᵀ d/dt(R X)``
    and ``(d/dt)_rot X = d/dt X`` as the unit defines them (2.9, 2.11)."""

    _ORDER = 3  # the highest rate of an angle or a component that a step may need

    def __init__(self) -> None:
        angles = ("phi", "theta", "psi")
        comps = ("x", "y", "z", "V_x", "V_y", "V_z")
        names = [f"{f}_{a}" for a in angles for f in ("sin", "cos")]
        names += [f"{a}_{n}" for a in angles for n in range(1, self._ORDER + 1)]
        names += [f"{c}__{n}" for c in comps for n in range(self._ORDER + 1)]
        names += ["x_c", "y_c", "z_c"]  # a point carried by the axes: constant components
        self._ring, *gens = ring(sp.symbols(names), QQ, lex)
        g = dict(zip(names, gens))
        self._g = g
        index = {n: k for k, n in enumerate(names)}
        self._rate: dict[int, Any] = {}  # generator index → its rate (absent: constant)
        self._top: set[int] = set()  # generators whose rate is beyond _ORDER
        for a in angles:
            s, c, a1 = g[f"sin_{a}"], g[f"cos_{a}"], g[f"{a}_1"]
            self._rate[index[f"sin_{a}"]] = c * a1
            self._rate[index[f"cos_{a}"]] = -s * a1
            for n in range(1, self._ORDER):
                self._rate[index[f"{a}_{n}"]] = g[f"{a}_{n + 1}"]
            self._top.add(index[f"{a}_{self._ORDER}"])
        for c in comps:
            for n in range(self._ORDER):
                self._rate[index[f"{c}__{n}"]] = g[f"{c}__{n + 1}"]
            self._top.add(index[f"{c}__{self._ORDER}"])
        self._ideal = [g[f"sin_{a}"] ** 2 + g[f"cos_{a}"] ** 2 - 1 for a in angles]
        one, zero = self._ring.one, self._ring.zero

        def rz(a: str) -> _Mat:
            s, c = g[f"sin_{a}"], g[f"cos_{a}"]
            return _Mat(((c, -s, zero), (s, c, zero), (zero, zero, one)))

        def rx(a: str) -> _Mat:
            s, c = g[f"sin_{a}"], g[f"cos_{a}"]
            return _Mat(((one, zero, zero), (zero, c, -s), (zero, s, c)))

        self.R = self._matmul(self._matmul(rz("phi"), rx("theta")), rz("psi"))
        sth, cth = g["sin_theta"], g["cos_theta"]
        sps, cps = g["sin_psi"], g["cos_psi"]
        p1, t1, s1 = g["phi_1"], g["theta_1"], g["psi_1"]
        # ω on the rotating axes, the unit's 2.99 (z-x-z)
        self.omega = (p1 * sth * sps + t1 * cps, p1 * sth * cps - t1 * sps, p1 * cth + s1)
        e = [tuple(one if k == j else zero for k in range(3)) for j in range(3)]
        rt = self._transpose(self.R)
        self._leaves: dict[Any, Any] = {
            Unit("i"): e[0],
            Unit("j"): e[1],
            Unit("k"): e[2],
            # a fixed axis on the rotating ones: the row of R (Rᵀ e_k)
            Unit("i'"): tuple(rt[k][0] for k in range(3)),
            Unit("j'"): tuple(rt[k][1] for k in range(3)),
            Unit("k'"): tuple(rt[k][2] for k in range(3)),
            _OnAxes("r"): (g["x__0"], g["y__0"], g["z__0"]),
            _OnAxes("V"): (g["V_x__0"], g["V_y__0"], g["V_z__0"]),
            _OnAxes("omega"): self.omega,
            _Carried("r"): (g["x_c"], g["y_c"], g["z_c"]),
            _Carried("omega"): self.omega,
            ZERO: (zero, zero, zero),
        }
        self._leaves[_OnAxes("V_r")] = self._d(self._leaves[_OnAxes("V")])
        self._leaves[_Carried("v")] = self._fix(self._leaves[_Carried("r")])
        self._leaves[MAT_R] = self.R
        self._leaves[MAT_RDOT] = self._d(self.R)
        self._leaves[MAT_OMEGA] = self._crossmat(self.omega)
        # scalar components: x, y, z and V_x, V_y, V_z on the rotating axes; the primed ones on
        # the fixed axes, (R X)_k
        self._base: dict[Any, str] = {}
        self._derived: dict[Any, Any] = {}
        for v, names3, primed in (
            (_OnAxes("r"), ("x", "y", "z"), ("x'", "y'", "z'")),
            (_OnAxes("V"), ("V_x", "V_y", "V_z"), ("V'_x", "V'_y", "V'_z")),
        ):
            fixed = self._apply(self.R, self._leaves[v])
            for k in range(3):
                self._base[dynamicsymbols(names3[k])] = names3[k]
                self._derived[dynamicsymbols(primed[k])] = fixed[k]

    # -- scalars: the symbols this model gives values to (for the dispatch on settings) --------
    def scalars(self) -> list[Any]:
        return list(self._base) + list(self._derived)

    # -- ring arithmetic --------------------------------------------------------------------
    def _reduce(self, p: Any) -> Any:
        return p.rem(self._ideal) if p else p

    def _d(self, x: Any) -> Any:
        """The time derivative (of a scalar, vector or matrix)."""
        if isinstance(x, _Mat):
            return _Mat(tuple(tuple(self._d(a) for a in row) for row in x))
        if isinstance(x, tuple):
            return tuple(self._d(a) for a in x)
        out = self._ring.zero
        for k, deg in enumerate(x.degrees()):
            if deg:
                if k in self._top:
                    raise PoinsotError("the explicit-axes model: a rate of too high an order")
                rate = self._rate.get(k)
                if rate is not None:
                    out += x.diff(self._ring.gens[k]) * rate
        return self._reduce(out)

    @staticmethod
    def _matmul(a: _Mat, b: _Mat) -> _Mat:
        def entry(i: int, j: int) -> Any:
            return a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j]

        return _Mat(tuple(tuple(entry(i, j) for j in range(3)) for i in range(3)))

    @staticmethod
    def _transpose(a: _Mat) -> _Mat:
        return _Mat(tuple(tuple(a[j][i] for j in range(3)) for i in range(3)))

    @staticmethod
    def _apply(a: _Mat, v: tuple[Any, ...]) -> tuple[Any, ...]:
        return tuple(a[i][0] * v[0] + a[i][1] * v[1] + a[i][2] * v[2] for i in range(3))

    @staticmethod
    def _cross(a: tuple[Any, ...], b: tuple[Any, ...]) -> tuple[Any, ...]:
        return (
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        )

    def _crossmat(self, a: tuple[Any, ...]) -> _Mat:
        z = self._ring.zero
        return _Mat(((z, -a[2], a[1]), (a[2], z, -a[0]), (-a[1], a[0], z)))

    def _fix(self, x: Any) -> Any:
        """(d/dt)_fix: differentiate the fixed components R X, back on the rotating axes."""
        if isinstance(x, tuple) and not isinstance(x, _Mat):
            return self._apply(self._transpose(self.R), self._d(self._apply(self.R, x)))
        return self._d(x)

    # -- evaluation ---------------------------------------------------------------------------
    def __call__(self, e: Any) -> Any:
        return self._out(self._ev(e))

    def _out(self, x: Any) -> Any:
        if isinstance(x, _Mat):
            return sp.Matrix([[self._reduce(a).as_expr() for a in row] for row in x])
        if isinstance(x, tuple):
            return sp.Matrix([self._reduce(a).as_expr() for a in x])
        return self._reduce(x).as_expr()

    def _ev(self, e: Any) -> Any:
        if e in self._leaves:
            return self._leaves[e]
        if isinstance(e, sp.Rational):
            return self._ring(QQ(int(e.p), int(e.q)))
        if e in self._base:
            return self._g[self._base[e] + "__0"]
        if e in self._derived:
            return self._derived[e]
        if isinstance(e, sp.Derivative):
            f, n = e.expr, sum(int(c) for _, c in e.variable_count)
            if f in self._base:
                if n > self._ORDER:
                    raise PoinsotError("the explicit-axes model: a rate of too high an order")
                return self._g[f"{self._base[f]}__{n}"]
            x = self._ev(f)
            for _ in range(n):
                x = self._d(x)
            return x
        if isinstance(e, Cross):
            return self._cross(self._ev(e.args[0]), self._ev(e.args[1]))
        if isinstance(e, Dot):
            a, b = self._ev(e.args[0]), self._ev(e.args[1])
            return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
        if isinstance(e, DtFix):
            return self._fix(self._ev(e.args[0]))
        if isinstance(e, DtRot):
            return self._d(self._ev(e.args[0]))
        if isinstance(e, (sp.Add, sp.MatAdd)):
            parts = [self._ev(a) for a in e.args]
            total = parts[0]
            for p in parts[1:]:
                total = self._add(total, p)
            return total
        if isinstance(e, (sp.Mul, sp.MatMul)):
            out: Any = self._ring.one
            for a in e.args:
                out = self._times(out, self._ev(a))
            return out
        if isinstance(e, sp.Pow) and e.exp.is_Integer and e.exp >= 0:
            return self._ev(e.base) ** int(e.exp)
        if isinstance(e, sp.Transpose):
            return self._transpose(self._ev(e.arg))
        if isinstance(e, sp.ZeroMatrix):
            z = self._ring.zero
            return _Mat(((z, z, z), (z, z, z), (z, z, z)))
        if isinstance(e, sp.Identity):
            return self._leaves_identity()
        raise PoinsotError(f"the explicit-axes model cannot evaluate {e}")

    def _leaves_identity(self) -> _Mat:
        one, z = self._ring.one, self._ring.zero
        return _Mat(((one, z, z), (z, one, z), (z, z, one)))

    @staticmethod
    def _add(a: Any, b: Any) -> Any:
        if isinstance(a, _Mat):
            return _Mat(tuple(tuple(x + y for x, y in zip(ra, rb)) for ra, rb in zip(a, b)))
        if isinstance(a, tuple):
            return tuple(x + y for x, y in zip(a, b))
        return a + b

    def _times(self, a: Any, b: Any) -> Any:
        if isinstance(a, _Mat) and isinstance(b, _Mat):
            return self._matmul(a, b)
        if isinstance(a, _Mat) and isinstance(b, tuple):
            return self._apply(a, b)
        if isinstance(a, tuple) and isinstance(b, tuple):
            raise PoinsotError("the explicit-axes model: a product of two vectors")
        if isinstance(b, (tuple, _Mat)):
            a, b = b, a
        if isinstance(a, _Mat):
            return _Mat(tuple(tuple(x * b for x in row) for row in a))
        if isinstance(a, tuple):
            return tuple(x * b for x in a)
        return a * b


MAT_R = sp.MatrixSymbol("R", 3, 3)
MAT_RDOT = sp.MatrixSymbol(r"\dot{R}", 3, 3)
MAT_OMEGA = sp.MatrixSymbol(r"[\vec{\omega}]_{\times}", 3, 3)


def _translation_model() -> VectorModel:
    r, big_r = _vec("r_1", "r_2", "r_3"), _vec("R_1", "R_2", "R_3")
    v = _InTranslation
    return VectorModel(
        vectors={
            v("r"): r,
            v("R"): big_r,
            v("r'"): big_r + r,
            v("F"): m * (big_r + r).diff(_t, 2),
            v("F_eff"): m * r.diff(_t, 2),
            ZERO: _zero3(),
        },
        dt_fix=lambda x: x.diff(_t),
        dt_rot=lambda x: x.diff(_t),
    )


def _rotating(omega: sp.Matrix) -> tuple[Callable[[Any], Any], Callable[[Any], Any]]:
    """(d/dt)_fix and (d/dt)_rot on the rotating axes (2.15)."""
    return (lambda x: x.diff(_t) + omega.cross(x)), (lambda x: x.diff(_t))


def _rotating_model() -> VectorModel:
    w = _vec("omega_1", "omega_2", "omega_3")
    r, big_r, v = _vec("r_1", "r_2", "r_3"), _vec("R_1", "R_2", "R_3"), _vec("V_1", "V_2", "V_3")
    fix, rot = _rotating(w)
    return VectorModel(
        vectors={
            Vec("omega"): w,
            Vec("r"): r,
            Vec("R"): big_r,
            Vec("r'"): big_r + r,
            Vec("V"): v,
            Vec("F"): m * fix(fix(big_r + r)),
            Vec("F_eff"): m * rot(rot(r)),
            # the non-inertial forces: translational, Coriolis, centrifugal, Euler
            Vec("F_ni"): -m * fix(fix(big_r))
            - 2 * m * w.cross(rot(r))
            - m * w.cross(w.cross(r))
            - m * rot(w).cross(r),
            ZERO: _zero3(),
        },
        dt_fix=fix,
        dt_rot=rot,
    )


def _steady_model(at_rest: bool) -> VectorModel:
    w = sp.Matrix(sp.symbols("Omega_1:4"))
    r = sp.Matrix(sp.symbols("a_1:4")) if at_rest else _vec("r_1", "r_2", "r_3")
    fix, rot = _rotating(w)
    v = _AtRest if at_rest else _Steady
    return VectorModel(
        vectors={
            v("omega"): w,
            v("r"): r,
            v("r'"): r,
            v("R"): _zero3(),
            v("F"): m * fix(fix(r)),
            v("F_eff"): m * rot(rot(r)),
            ZERO: _zero3(),
        },
        dt_fix=fix,
        dt_rot=rot,
    )


# the scalars of 2.24 (ω = |ω⃗|, r = |r⃗|, θ the angle between them, v the speed on the circle)
OMEGA, RADIUS, THETA, SPEED = sp.symbols("omega r theta v", positive=True)
_SIN = sp.Symbol("s", positive=True)  # sin θ > 0 for 0 < θ < π


class _AngleModel:
    """2.24's setting: ω⃗ = ω k̂, r⃗ = r (sin θ î + cos θ k̂), v = ω r sin θ."""

    def __init__(self) -> None:
        self._m = VectorModel(
            vectors={
                _AtAngle("omega"): sp.Matrix([0, 0, OMEGA]),
                _AtAngle("r"): RADIUS * sp.Matrix([_SIN, 0, sp.cos(THETA)]),
                ZERO: _zero3(),
            },
            scalars={sp.sin(THETA): _SIN, SPEED: OMEGA * RADIUS * _SIN},
        )

    def __call__(self, e: Any) -> Any:
        e = sp.sympify(e).replace(
            lambda x: isinstance(x, _Norm), lambda x: sp.sqrt(Dot(x.args[0], x.args[0]))
        )
        return self._m(e)


class _Settings:
    """The derivation's model: each expression is evaluated in the model of the setting its
    vectors (and scalars) belong to; an expression with none (0, a number) is itself."""

    def __init__(self) -> None:
        axes = _Axes()
        self._models: dict[str, Callable[[Any], Any]] = {
            "translation": _translation_model(),
            "axes": axes,
            "rotating": _rotating_model(),
            "angle": _AngleModel(),
            "steady": _steady_model(False),
            "rest": _steady_model(True),
        }
        self._by_class: dict[type, str] = {
            _InTranslation: "translation",
            _OnAxes: "axes",
            _Carried: "axes",
            Unit: "axes",
            sp.MatrixSymbol: "axes",
            Vec: "rotating",
            _AtAngle: "angle",
            _Steady: "steady",
            _AtRest: "rest",
        }
        self._by_symbol: dict[Any, str] = dict.fromkeys(axes.scalars(), "axes")
        self._by_symbol.update(dict.fromkeys((OMEGA, RADIUS, THETA, SPEED), "angle"))

    def setting(self, e: Any) -> str | None:
        """The setting of ``e`` (None when it has no vector or scalar of one)."""
        found = set()
        for node in sp.preorder_traversal(sp.sympify(e)):
            s = self._by_class.get(type(node)) or self._by_symbol.get(node)
            if s is not None:
                found.add(s)
        if len(found) > 1:
            raise PoinsotError(f"frames: {e} mixes the unit's settings {sorted(found)}")
        return found.pop() if found else None

    def __call__(self, e: Any) -> Any:
        e = sp.sympify(e)
        s = self.setting(e)
        if s is not None:
            return self._models[s](e)
        if e == ZERO:
            return _zero3()
        if isinstance(e, sp.MatrixExpr):
            return sp.Matrix(e.as_explicit())
        return e


_MODEL = _Settings()

# ---- the notation, setting by setting ------------------------------------------------------------

_T = {n: _InTranslation(n) for n in ("r", "R", "r'", "F", "F_eff")}
_X = {n: _OnAxes(n) for n in ("r", "V", "omega", "V_r")}
_C = {n: _Carried(n) for n in ("r", "v", "omega")}
_P = {n: Vec(n) for n in ("r", "R", "r'", "V", "omega", "F", "F_eff", "F_ni")}
_G = {n: _AtAngle(n) for n in ("r", "omega")}
_S = {n: _Steady(n) for n in ("r", "R", "r'", "omega", "F", "F_eff")}
_A = {n: _AtRest(n) for n in ("r", "omega", "F", "F_eff")}

_I, _J, _K = Unit("i"), Unit("j"), Unit("k")
_IP, _JP, _KP = Unit("i'"), Unit("j'"), Unit("k'")
_XYZ = dynamicsymbols("x y z")
_XYZP = dynamicsymbols("x' y' z'")
_VC = dynamicsymbols("V_x V_y V_z")
_VCP = dynamicsymbols("V'_x V'_y V'_z")


def _expand_on(axes: Sequence[Any], comps: Sequence[Any]) -> Any:
    """î x + ĵ y + k̂ z, in that order."""
    return _sum(*(_mul(a, c) for a, c in zip(axes, comps)))


def _d2(op: type, x: Any) -> Any:
    return op(op(x))


def _second_rate(w: Any, big_v: Any, inner: Any, last: Any) -> Any:
    """2.18: the rotating frame's second rate of V⃗ by 2.15 applied twice (``inner`` the first
    rate, dV⃗/dt + ω⃗ × V⃗), expanded by the product rule (the third line ending in ``last``, ω⃗
    × ``inner``; the unit prints another), then collected."""
    return _chain(
        _d2(_DPrime, big_v),
        _DPrime(inner),
        _sum(_DPlain(inner), Cross(w, inner)),
        _sum(_d2(_DPlain, big_v), Cross(_DPlain(w), big_v), Cross(w, _DPlain(big_v)), last),
        _sum(
            _d2(_DPlain, big_v),
            2 * Cross(w, _DPlain(big_v)),
            Cross(w, Cross(w, big_v)),
            Cross(_DPlain(w), big_v),
        ),
    )


def _acceleration(fix: type, rot: type, dot: type, rp: Any, big_r: Any, r: Any, w: Any) -> Any:
    """2.21 in the derivative notation given (``fix``, ``rot``: in the fixed and the rotating
    frame; ``dot``: of ω, the same in both): the fixed-frame acceleration of r⃗' = R⃗ + r⃗ as
    the origin's, the relative, Coriolis, centripetal and Euler terms."""
    coriolis = 2 * Cross(w, rot(r))
    terms = _sum(_d2(fix, big_r), _d2(rot, r), coriolis, Cross(w, Cross(w, r)), Cross(dot(w), r))
    return _eq(_d2(fix, rp), terms)


# ---- the derivation -----------------------------------------------------------------------------


def _numeric(d: Derivation, number: str, expr: Any, leaves: Sequence[tuple[Any, Any]]) -> None:
    """Registers ``expr`` (a vector or scalar in the notation, from a checked result) as the
    numeric form of ``number``: each leaf (a vector, or a rate of one) becomes a 3-tuple of
    symbols (a scalar leaf one symbol), the arguments in the order of ``leaves``."""
    vectors, scalars, args = {}, {}, []
    for k, (leaf, name) in enumerate(leaves):
        if leaf in (m, OMEGA, RADIUS, THETA):
            s = sp.Symbol(f"{name}_{k}")
            scalars[leaf] = s
            args.append(s)
        else:
            syms = sp.symbols(f"{name}_{k}_1:4")
            vectors[leaf] = sp.Matrix(syms)
            args.append(tuple(syms))
    model = VectorModel(vectors=vectors, scalars=scalars)
    value = model(expr)
    d.function(number, value, args)


def derive() -> Derivation:
    """The derivation of 2.1–2.28 (each step checked in its setting's model; see the module)."""
    d = Derivation(
        "frames",
        "Moving frames: translation, the rotating frame, fictitious forces (2.1–2.28)",
        summary=(
            "From r⃗′ = R⃗ + r⃗ to the effective force in a rotating frame: the rate of a vector in a "
            "turning frame, the velocity and the acceleration of a particle with their named "
            "terms, and the fictitious forces. Primed: fixed (inertial) frame; unprimed: moving "
            "frame; ω⃗: its angular velocity."
        ),
        model=_MODEL,
    )
    _translation(d)
    _axes(d)
    _rotating_frame(d)
    _forces(d)
    return d


def _translation(d: Derivation) -> None:
    r, big_r, rp, f, f_eff = (_T[n] for n in ("r", "R", "r'", "F", "F_eff"))
    d.given(
        "The moving frame only translates (Fig. 2.1): the position from O′ is the position R⃗ of "
        "the moving origin O plus the position r⃗ from O.",
        _eq(rp, _sum(big_r, r)),
        "2.1",
    )
    d.step(
        "Differentiate 2.1 with respect to time: the velocities add. (The unit prints "
        "r⃗′ = R⃗ + r⃗ again: the dots were lost in the scan.)",
        _eq(_Dot(rp), _sum(_Dot(big_r), _Dot(r))),
        "2.2",
    )
    d.step(
        "Differentiate again: the accelerations add (dots lost in the unit's 2.3 too).",
        _eq(_d2(_Dot, rp), _sum(_d2(_Dot, big_r), _d2(_Dot, r))),
        "2.3",
    )
    d.given(
        "Newton's second law in the fixed (inertial) frame, F⃗ the total real force.",
        _eq(m * _d2(_Dot, rp), f),
        "2.4",
    )
    mrdd, mbig = m * _d2(_Dot, r), m * _d2(_Dot, big_r)
    d.step(
        "Multiply 2.3 by m and use 2.4: the law the moving observer finds, with the effective "
        "force F⃗_eff = m r̈, smaller than F⃗ by m R̈. (The scan lost every dot of 2.5.)",
        _chain(
            mrdd,
            _sum(m * _d2(_Dot, rp), -mbig),
            _sum(f, -mbig),
            f_eff,
        ),
        "2.5",
    )
    res = d.result
    _numeric(d, "2.1", res["2.1"].rhs, [(big_r, "R"), (r, "r")])
    _numeric(d, "2.2", res["2.2"].rhs, [(_Dot(big_r), "Rdot"), (_Dot(r), "rdot")])
    _numeric(d, "2.3", res["2.3"].rhs, [(_d2(_Dot, big_r), "Rddot"), (_d2(_Dot, r), "rddot")])
    _numeric(d, "2.5", res["2.5"][1].rhs, [(f, "F"), (m, "m"), (_d2(_Dot, big_r), "Rddot")])


def _axes(d: Derivation) -> None:
    r, big_v, w, v_r = (_X[n] for n in ("r", "V", "omega", "V_r"))
    axes, fixed_axes = (_I, _J, _K), (_IP, _JP, _KP)
    d.step(
        "Expand r⃗ on the fixed axes î′, ĵ′, k̂′ (components x′, y′, z′) and on the rotating axes "
        "î, ĵ, k̂ (components x, y, z).",
        _chain(r, _expand_on(fixed_axes, _XYZP), _expand_on(axes, _XYZ)),
        "2.6",
    )
    for k, (primed, axis) in enumerate(zip(_XYZP, fixed_axes)):
        text = (
            "Take the scalar product of 2.6 with î′ (the fixed axes are orthonormal), and expand "
            "r⃗ on the rotating axes: x′ in terms of x, y, z, with the direction cosines î·î′, …"
            if k == 0
            else "Likewise with ĵ′."
            if k == 1
            else "And with k̂′. (The unit prints ż′ on the left: a dot the scan added.)"
        )
        d.step(
            text,
            _chain(
                primed,
                Dot(r, axis),
                _sum(*(_mul(Dot(a, axis), c) for a, c in zip(axes, _XYZ))),
            ),
            "2.7",
        )
    d.step(
        "Any vector V⃗(t) likewise has components on both sets of axes.",
        _chain(big_v, _expand_on(axes, _VC), _expand_on(fixed_axes, _VCP)),
        "2.8",
    )
    d.step(
        "Seen from the fixed frame î′, ĵ′, k̂′ are constant: only the components change.",
        _eq(DtFix(big_v), _expand_on(fixed_axes, [c.diff(_t) for c in _VCP])),
        "2.9",
    )
    turning = [_mul(DtFix(a), c) for a, c in zip(axes, _VC)]
    d.step(
        "Differentiate the rotating expansion of 2.8 instead, by the product rule: the rotating "
        "axes turn, so their rates stay. (The unit prints dî/dt V_y for dĵ/dt V_y.)",
        _eq(DtFix(big_v), _sum(*(_mul(a, c.diff(_t)) for a, c in zip(axes, _VC)), *turning)),
        "2.10",
    )
    d.given(
        "The first three terms of 2.10 are the rate seen by an observer turning with the axes, "
        "who holds î, ĵ, k̂ constant: the rate in the rotating frame, V⃗_r.",
        _chain(DtRot(big_v), _expand_on(axes, [c.diff(_t) for c in _VC]), v_r),
        "2.11",
    )
    d.step(
        "Why the axes turn with ω⃗ × (2.12–2.13): the rotating axes in fixed components are the "
        "columns of a rotation matrix R (its entries are the direction cosines of 2.7); they are "
        "orthonormal. (Checked with R = R_z(φ) R_x(θ) R_z(ψ), φ, θ, ψ arbitrary functions of t.)",
        _eq(MAT_R.T * MAT_R, sp.Identity(3)),
    )
    d.step(
        "Differentiate: ṘᵀR + RᵀṘ = 0, so RᵀṘ is antisymmetric.",
        _eq(MAT_RDOT.T * MAT_R + MAT_R.T * MAT_RDOT, sp.ZeroMatrix(3, 3)),
    )
    d.step(
        "An antisymmetric 3×3 matrix has three independent entries, the components of a vector "
        "ω⃗ with [ω⃗]× b⃗ = ω⃗ × b⃗: the angular velocity of the axes. For the z-x-z angles they "
        "are the unit's 2.99: ω₁ = φ̇ sin θ sin ψ + θ̇ cos ψ, ω₂ = φ̇ sin θ cos ψ − θ̇ sin ψ, "
        "ω₃ = φ̇ cos θ + ψ̇.",
        _eq(MAT_R.T * MAT_RDOT, MAT_OMEGA),
    )
    d.step(
        "Multiply by R on the left (RRᵀ = 1): Ṙ = R[ω⃗]×.",
        _eq(MAT_RDOT, MAT_R * MAT_OMEGA),
    )
    rc, vc, wc = _C["r"], _C["v"], _C["omega"]
    d.step(
        "A point carried by the rotating frame has constant components c on its axes, so its "
        "fixed components are R c and its velocity Ṙ c = R [ω⃗]× c: the velocity of rigid "
        "rotation (here d/dt is the rate seen from the fixed frame).",
        _chain(vc, DtFix(rc), Cross(wc, rc)),
        "2.12",
    )
    for a in axes:
        d.step(
            "The rotating unit vectors are such points (the columns of Ṙ = R[ω⃗]×):"
            if a is _I
            else "likewise,"
            if a is _J
            else "and",
            _eq(DtFix(a), Cross(w, a)),
            "2.13",
        )
    d.step(
        "Substitute 2.13 into 2.10; by 2.11 the first three terms are (dV⃗/dt)_rot, and the "
        "last three are ω⃗ × V⃗.",
        _chain(
            DtFix(big_v),
            _sum(
                *(_mul(a, c.diff(_t)) for a, c in zip(axes, _VC)),
                *(_mul(Cross(w, a), c) for a, c in zip(axes, _VC)),
            ),
            _sum(DtRot(big_v), Cross(w, big_v)),
        ),
        "2.14",
    )


def _rotating_frame(d: Derivation) -> None:
    r, big_r, rp, big_v, w = (_P[n] for n in ("r", "R", "r'", "V", "omega"))
    d.given(
        "2.14 holds for every vector and every rotation: as an operator, "
        "(d/dt)_fix = (d/dt)_rot + ω⃗×. From here on the check takes the fixed-frame rate by "
        "2.15 from components on the rotating axes, arbitrary functions of t (ω⃗ too).",
        _eq(DtFix(big_v), _sum(DtRot(big_v), Cross(w, big_v))),
        "2.15",
    )
    d.step(
        "Apply 2.15 to ω⃗ itself: ω⃗ × ω⃗ = 0, so the angular acceleration is the same in both "
        "frames, and either is written ω̇. (The unit ends 2.16 with ω⃗: the dot was lost.)",
        _chain(DtFix(w), _sum(DtRot(w), Cross(w, w)), DtRot(w), _Dot(w)),
        "2.16",
    )
    d.given(
        "The unit's shorthand (2.17): d′/dt for the rate seen from the fixed frame,",
        _eq(DtFix(big_v), _DPrime(big_v)),
        "2.17",
    )
    d.given("d/dt for the rate in the rotating frame.", _eq(DtRot(big_v), _DPlain(big_v)), "2.17")
    inner = _sum(_DPlain(big_v), Cross(w, big_v))
    d.step(
        "Apply 2.15 twice and expand, d/dt of ω⃗ × V⃗ by the product rule. (The unit's third line "
        "prints ω⃗ × [dV⃗/dt + ω⃗ × dV⃗/dt]: the last V⃗ is not differentiated. Its last line is "
        "right, ω⃗ × ω⃗ × V⃗ meaning ω⃗ × (ω⃗ × V⃗).)",
        _second_rate(w, big_v, inner, Cross(w, inner)),
        "2.18",
    )
    d.given("Now let the origin O of the rotating frame move too (Fig. 2.2).", _eq(rp, big_r + r))
    rate = _sum(DtFix(big_r), DtFix(r))
    d.step("Differentiate in the fixed frame:", _eq(DtFix(rp), rate), "2.19")
    velocity = _sum(DtFix(big_r), DtRot(r), Cross(w, r))
    d.step(
        "Apply 2.15 to r⃗: the velocity seen from the fixed frame is the origin's, the relative "
        "velocity and the velocity of rotation.",
        _chain(DtFix(rp), rate, velocity),
        "2.20",
    )
    acceleration = _sum(
        _d2(DtFix, big_r),
        _d2(DtRot, r),
        2 * Cross(w, DtRot(r)),
        Cross(w, Cross(w, r)),
        Cross(_DPlain(w), r),
    )
    d.step(
        "Differentiate 2.19 once more in the fixed frame and use 2.18 with V⃗ = r⃗ (ω̇ is the same "
        "in both frames, 2.16).",
        _chain(
            _d2(DtFix, rp),
            _sum(_d2(DtFix, big_r), _d2(DtFix, r)),
            acceleration,
        ),
        "2.21",
    )
    d.step(
        "In compact form, a subscript f or r marking the rate seen in the fixed or the rotating "
        "frame. (The unit prints r⃗_f where 2.20 has the relative velocity ṙ_r: with ṙ_f the "
        "term ω⃗ × r⃗ would be counted twice. Its dots were lost too.)",
        _eq(_SubF(rp), _sum(_SubF(big_r), _SubR(r), Cross(w, r))),
        "2.22",
    )
    d.step(
        "And 2.21: the origin's acceleration, the relative acceleration r̈_r, the Coriolis "
        "acceleration 2ω⃗ × ṙ_r, the centripetal acceleration ω⃗ × (ω⃗ × r⃗) and the Euler "
        "(transverse) acceleration ω̇ × r⃗. (The unit prints r⃗_f for r̈_r and ω⃗ × r⃗ for the last "
        "term: a subscript wrong and the dots lost.)",
        _acceleration(_SubF, _SubR, _Dot, rp, big_r, r, w),
        "2.23",
    )
    res = d.result
    _numeric(
        d,
        "2.20",
        res["2.20"][-1].rhs,
        [(DtFix(big_r), "Rdot"), (DtRot(r), "rdot"), (w, "omega"), (r, "r")],
    )
    _numeric(
        d,
        "2.21",
        res["2.21"][-1].rhs,
        [
            (_d2(DtFix, big_r), "Rddot"),
            (_d2(DtRot, r), "rddot"),
            (w, "omega"),
            (DtRot(r), "rdot"),
            (r, "r"),
            (_DPlain(w), "omegadot"),
        ],
    )


def _forces(d: Derivation) -> None:
    wg, rg = _G["omega"], _G["r"]
    sin = sp.sin(THETA)
    d.given(
        "θ is the angle between ω⃗ and r⃗, and v = ω r sin θ the speed of a point carried round "
        "the circle of radius r sin θ (Fig. 2.3).",
        _eq(SPEED, _mul(OMEGA, RADIUS, sin)),
    )
    d.step(
        "ω⃗ × r⃗ has magnitude ω r sin θ and is perpendicular to ω⃗, so ω⃗ × (ω⃗ × r⃗) has magnitude "
        "ω · ω r sin θ: the centripetal acceleration, towards the axis. (Checked with ω⃗ along "
        "k̂ and r⃗ in the plane of î and k̂.)",
        _chain(
            _Norm(Cross(wg, Cross(wg, rg))),
            _mul(OMEGA**2, RADIUS, sin),
            SPEED**2 / _mul(RADIUS, sin),
        ),
        "2.24",
    )
    _numeric(
        d, "2.24", d.result["2.24"][0].rhs, [(OMEGA, "omega"), (RADIUS, "r"), (THETA, "theta")]
    )
    rs, ws, fs, fs_eff = (_S[n] for n in ("r", "omega", "F", "F_eff"))
    d.given(
        "Newton's second law holds in the fixed frame. As the unit does, let the origins "
        "coincide (R⃗ = 0, r⃗ = r⃗′) and ω⃗ be constant.",
        _eq(fs, m * _d2(DtFix, rs)),
        "2.25",
    )
    d.step(
        "ω⃗ constant means its rate is zero. (The unit writes ω⃗ = 0 here: the dot was lost; ω⃗ "
        "itself is not zero.)",
        _eq(_Dot(ws), ZERO),
    )
    coriolis = -2 * m * Cross(ws, DtRot(rs))
    centrifugal = -m * Cross(ws, Cross(ws, rs))
    d.step(
        "Solve 2.21 (R⃗ = 0) for the rotating-frame acceleration and multiply by m; the Euler "
        "term goes with ω̇ = 0, and 2.25 gives F⃗. What the rotating observer calls the force is "
        "F⃗_eff: the real force with the Coriolis force −2m ω⃗ × ṙ and the centrifugal force "
        "−m ω⃗ × (ω⃗ × r⃗).",
        _chain(
            m * _d2(DtRot, rs),
            _sum(m * _d2(DtFix, rs), coriolis, centrifugal, -m * Cross(_DPlain(ws), rs)),
            _sum(m * _d2(DtFix, rs), coriolis, centrifugal),
            _sum(fs, coriolis, centrifugal),
            fs_eff,
        ),
        "2.26",
    )
    r, big_r, rp, w, f, f_eff, f_ni = (
        _P[n] for n in ("r", "R", "r'", "omega", "F", "F_eff", "F_ni")
    )
    d.given(
        "In general (moving origin, ω̇ ≠ 0) Newton's law holds in the fixed frame:",
        _eq(f, m * _d2(DtFix, rp)),
    )
    general = _sum(
        f,
        -m * _d2(DtFix, big_r),
        -2 * m * Cross(w, DtRot(r)),
        -m * Cross(w, Cross(w, r)),
        -m * Cross(_DPlain(w), r),
    )
    d.step(
        "and 2.21 times m gives the law in the rotating frame, with four fictitious forces: the "
        "translational −m R̈, Coriolis −2m ω⃗ × ṙ, centrifugal −m ω⃗ × (ω⃗ × r⃗) and Euler "
        "−m ω̇ × r⃗.",
        _eq(m * _d2(DtRot, r), general),
    )
    d.step(
        "Their sum is the non-inertial force F⃗_ni; with the real force it makes F⃗_eff (with "
        "R⃗ = 0 and ω̇ = 0 only the Coriolis and centrifugal forces the unit lists remain).",
        _chain(_sum(f, f_ni), general, f_eff),
        "2.27",
    )
    _numeric(
        d,
        "2.27",
        d.result["2.27"][0].rhs,
        [
            (f, "F"),
            (m, "m"),
            (_d2(DtFix, big_r), "Rddot"),
            (w, "omega"),
            (DtRot(r), "rdot"),
            (r, "r"),
            (_DPlain(w), "omegadot"),
        ],
    )
    ra, wa, fa, fa_eff = (_A[n] for n in ("r", "omega", "F", "F_eff"))
    d.step(
        "An observer at rest in the rotating frame (in the satellite) has ṙ = 0 there:",
        _eq(DtRot(ra), ZERO),
    )
    at_rest = _sum(fa, -m * Cross(wa, Cross(wa, ra)))
    d.step(
        "so no Coriolis force, and with ω⃗ constant F⃗_eff is the real force and the centrifugal "
        "force, which balance: the observer feels no force.",
        _chain(fa_eff, at_rest, ZERO),
        "2.28",
    )
    _numeric(
        d,
        "2.28",
        d.result["2.28"][0].rhs,
        [(fa, "F"), (m, "m"), (wa, "omega"), (ra, "r")],
    )


# ---- the unit as printed ------------------------------------------------------------------------


def _printed() -> tuple[Printed, ...]:
    def p(number: str, as_printed: str, equation: Any, note: str = "") -> Printed:
        return Printed(number, "frames", as_printed, equation, note)

    rt, big_rt, rpt, ft, ft_eff = (_T[n] for n in ("r", "R", "r'", "F", "F_eff"))
    rx, vx, wx, v_r = (_X[n] for n in ("r", "V", "omega", "V_r"))
    r, big_r, rp, big_v, w, f, f_eff, f_ni = (
        _P[n] for n in ("r", "R", "r'", "V", "omega", "F", "F_eff", "F_ni")
    )
    axes, fixed_axes = (_I, _J, _K), (_IP, _JP, _KP)
    dots_read = (
        "The text calls this r⃗′ 'the {}' (and R⃗, r⃗ too): the chain starts from that {} so "
        "that the dots are judged; as printed the equation is 2.1 again."
    )
    out = [
        p("2.1", r"\vec{r}' = \vec{R} + \vec{r}", _eq(rpt, _sum(big_rt, rt))),
        p(
            "2.2",
            r"\vec{r}' = \vec{R} + \vec{r}",
            _chain(_Dot(rpt), rpt, _sum(big_rt, rt)),
            dots_read.format("velocity", "velocity ṙ′"),
        ),
        p(
            "2.3",
            r"\vec{r}' = \vec{R} + \vec{r}",
            _chain(_d2(_Dot, rpt), rpt, _sum(big_rt, rt)),
            dots_read.format("acceleration", "acceleration r̈′"),
        ),
        p("2.4", r"m\vec{\ddot{r}}' = \vec{F}", _eq(m * _d2(_Dot, rpt), ft)),
        p(
            "2.5",
            r"m\vec{r} = m\vec{r}' - m\vec{R} \\ \therefore m\vec{r} = \vec{F} - m\vec{R} "
            r"\\ \therefore m\vec{r} = \vec{F}_{eff}",
            _chain(m * rt, _sum(m * rpt, -m * big_rt), _sum(ft, -m * big_rt), ft_eff),
            "The three lines as one chain.",
        ),
        p(
            "2.6",
            r"\vec{r} = \hat{i}'x' + \hat{j}'y' + \hat{k}'z'",
            _eq(rx, _expand_on(fixed_axes, _XYZP)),
        ),
        p("2.6", r"\vec{r} = \hat{i}x + \hat{j}y + \hat{k}z", _eq(rx, _expand_on(axes, _XYZ))),
    ]
    lines_27 = (
        r"x' = (\vec{r} \cdot \hat{i}') = \hat{\imath} \cdot \hat{\imath}' x + \hat{\jmath} \cdot "
        r"\hat{\imath}' y + \hat{k} \cdot \hat{\imath}' z",
        r"y' = (\vec{r} \cdot \hat{\jmath}') = \hat{\imath} \cdot \hat{\jmath}' x + \hat{\jmath} "
        r"\cdot \hat{\jmath}' y + \hat{k} \cdot \hat{\jmath}' z",
        r"\dot{z}' = (\vec{r} \cdot \hat{k}') = \hat{\imath} \cdot \hat{k}' x + \hat{\jmath} \cdot "
        r"\hat{k}' y + \hat{k} \cdot \hat{k}' z",
    )
    for k, (line, primed, axis) in enumerate(zip(lines_27, _XYZP, fixed_axes)):
        lhs = primed.diff(_t) if k == 2 else primed
        cosines = _sum(*(_mul(Dot(a, axis), c) for a, c in zip(axes, _XYZ)))
        out.append(
            p(
                "2.7",
                line,
                _chain(lhs, Dot(rx, axis), cosines),
                "î·î′ x read as (î·î′) x." + (" The left side ż′ as printed." if k == 2 else ""),
            )
        )
    out += [
        p(
            "2.8",
            r"\vec{V} = \hat{\imath}V_x + \hat{\jmath}V_y + \hat{k}V_z = \hat{\imath}'V_x' + "
            r"\hat{\jmath}'V_y' + \hat{k}'V_z'",
            _chain(vx, _expand_on(axes, _VC), _expand_on(fixed_axes, _VCP)),
        ),
        p(
            "2.9",
            r"\left(\frac{d\vec{V}}{dt}\right)_{fix} = \hat{\imath}'\dot{V}_x' + "
            r"\hat{\jmath}'\dot{V}_y' + \hat{k}'\dot{V}_z'",
            _eq(DtFix(vx), _expand_on(fixed_axes, [c.diff(_t) for c in _VCP])),
        ),
        p(
            "2.10",
            r"\left(\frac{d\vec{V}}{dt}\right)_{fix} = \hat{i}\dot{V}_x + \hat{j}\dot{V}_y + "
            r"\hat{k}\dot{V}_z + \frac{d\hat{i}}{dt}V_x + \frac{d\hat{i}}{dt}V_y + "
            r"\frac{d\hat{k}}{dt}V_z",
            _eq(
                DtFix(vx),
                _sum(
                    *(_mul(a, c.diff(_t)) for a, c in zip(axes, _VC)),
                    *(_mul(DtFix(a), c) for a, c in zip((_I, _I, _K), _VC)),
                ),
            ),
            "The '+ …' before the equation number dropped; dî/dt is the rate seen from the "
            "fixed frame.",
        ),
        p(
            "2.11",
            r"\left(\frac{d\vec{V}}{dt}\right)_{rot} = \hat{\imath}\dot{V}_x + "
            r"\hat{\jmath}\dot{V}_y + \hat{k}\dot{V}_z = \vec{V}_r",
            _chain(DtRot(vx), _expand_on(axes, [c.diff(_t) for c in _VC]), v_r),
        ),
        p(
            "2.12",
            r"\vec{v} = \frac{d\vec{r}}{dt} = \vec{\omega} \times \vec{r}",
            _chain(_C["v"], DtFix(_C["r"]), Cross(_C["omega"], _C["r"])),
            "r⃗ of a point carried by the rotating frame, as the text applies it ('to unit "
            "vectors as a special case'); d/dt the rate seen from the fixed frame.",
        ),
    ]
    for a, latex_a in zip(axes, (r"\hat{\imath}", r"\hat{\jmath}", r"\hat{k}")):
        out.append(
            p(
                "2.13",
                r"\frac{d" + latex_a + r"}{dt} = \vec{\omega} \times " + latex_a,
                _eq(DtFix(a), Cross(wx, a)),
                "One of the three equations of 2.13.",
            )
        )
    out += [
        p(
            "2.14",
            r"\left(\frac{d\vec{V}}{dt}\right)_{fix} = \left(\frac{d\vec{V}}{dt}\right)_{rot} + "
            r"\vec{\omega} \times \vec{V}",
            _eq(DtFix(vx), _sum(DtRot(vx), Cross(wx, vx))),
        ),
        p(
            "2.15",
            r"\left(\frac{d}{dt}\right)_{fix} = \left(\frac{d}{dt}\right)_{rot} + \vec{\omega} "
            r"\times",
            _eq(DtFix(big_v), _sum(DtRot(big_v), Cross(w, big_v))),
            "The operators applied to a vector V⃗.",
        ),
        p(
            "2.16",
            r"\left(\frac{d\vec{\omega}}{dt}\right)_{fix} = "
            r"\left(\frac{d\vec{\omega}}{dt}\right)_{rot} = \vec{\omega}",
            _chain(DtFix(w), DtRot(w), w),
        ),
        p(
            "2.17",
            r"\left(\frac{d}{dt}\right)_{fix} = \frac{d'}{dt}",
            _eq(DtFix(big_v), _DPrime(big_v)),
            "The operators applied to a vector V⃗.",
        ),
        p(
            "2.17",
            r"\left(\frac{d}{dt}\right)_{rot} = \frac{d}{dt}",
            _eq(DtRot(big_v), _DPlain(big_v)),
            "The operators applied to a vector V⃗.",
        ),
    ]
    inner = _sum(_DPlain(big_v), Cross(w, big_v))
    out.append(
        p(
            "2.18",
            r"\frac{d'^{2}\vec{V}}{dt^{2}} = \frac{d'}{dt} \left( \frac{d'\vec{V}}{dt} \right) "
            r"= \frac{d'}{dt} \left[ \frac{d\vec{V}}{dt} + \vec{\omega} \times \vec{V} \right] "
            r"\\ \therefore \frac{d'^{2}\vec{V}}{dt^{2}} = \left[ \frac{d}{dt} + \vec{\omega} "
            r"\times \right] \left[ \frac{d\vec{V}}{dt} + \vec{\omega} \times \vec{V} \right] "
            r"\\ \therefore \frac{d'^{2}\vec{V}}{dt^{2}} = \frac{d^{2}\vec{V}}{dt^{2}} + "
            r"\frac{d\vec{\omega}}{dt} \times \vec{V} + \vec{\omega} \times \frac{d\vec{V}}{dt} "
            r"+ \vec{\omega} \times \left[ \frac{d\vec{V}}{dt} + \vec{\omega} \times "
            r"\frac{d\vec{V}}{dt} \right] \\ \therefore \frac{d'^2 \vec{V}}{dt^2} = "
            r"\frac{d^2 \vec{V}}{dt^2} + 2\vec{\omega} \times \frac{d\vec{V}}{dt} + \vec{\omega} "
            r"\times \vec{\omega} \times \vec{V} + \frac{d\vec{\omega}}{dt} \times \vec{V}",
            _second_rate(w, big_v, inner, Cross(w, _sum(_DPlain(big_v), Cross(w, _DPlain(big_v))))),
            "The four lines as one chain (the identity d′/dt(d′V⃗/dt) of the first dropped); "
            "the operator product [d/dt + ω⃗×][X⃗] as dX⃗/dt + ω⃗ × X⃗; ω⃗ × ω⃗ × V⃗ read as "
            "ω⃗ × (ω⃗ × V⃗) (the other grouping is 0).",
        )
    )
    out += [
        p(
            "2.19",
            r"\left(\frac{d\vec{r}'}{dt}\right)_{fix} = \left(\frac{d\vec{R}}{dt}\right)_{fix} + "
            r"\left(\frac{d\vec{r}}{dt}\right)_{fix}",
            _eq(DtFix(rp), _sum(DtFix(big_r), DtFix(r))),
        ),
        p(
            "2.20",
            r"\left(\frac{d\vec{r}'}{dt}\right)_{fix} = \left(\frac{d\vec{R}}{dt}\right)_{fix} + "
            r"\left(\frac{d\vec{r}}{dt}\right)_{rot} + \vec{\omega} \times \vec{r}",
            _eq(DtFix(rp), _sum(DtFix(big_r), DtRot(r), Cross(w, r))),
        ),
        p(
            "2.21",
            r"\left(\frac{d^2\vec{r}'}{dt^2}\right)_{fix} = "
            r"\left(\frac{d^2\vec{R}}{dt^2}\right)_{fix} + "
            r"\left(\frac{d^2\vec{r}}{dt^2}\right)_{rot} + 2\vec{\omega} \times "
            r"\left(\frac{d\vec{r}}{dt}\right)_{rot} + \vec{\omega} \times (\vec{\omega} \times "
            r"\vec{r}) + \frac{d\vec{\omega}}{dt} \times \vec{r}",
            _acceleration(DtFix, DtRot, _DPlain, rp, big_r, r, w),
            "dω⃗/dt is the same in both frames (2.16).",
        ),
        p(
            "2.22",
            r"\vec{r}_f' = \vec{R}_f + \vec{r}_f + \vec{\omega} \times \vec{r}",
            _eq(_ScanF(rp), _sum(_ScanF(big_r), _ScanF(r), Cross(w, r))),
            "The compact form of 2.20, as the text says: a subscript f read as the rate seen "
            "from the fixed frame, r as the rate in the rotating frame, first rates (no dots "
            "are printed).",
        ),
        p(
            "2.23",
            r"\vec{r}_f' = \vec{R}_f + \vec{r}_f + 2\vec{\omega} \times \vec{r}_r + \vec{\omega} "
            r"\times (\vec{\omega} \times \vec{r}) + \vec{\omega} \times \vec{r}",
            _eq(
                _d2(_ScanF, rp),
                _sum(
                    _d2(_ScanF, big_r),
                    _d2(_ScanF, r),
                    2 * Cross(w, _ScanR(r)),
                    Cross(w, Cross(w, r)),
                    Cross(w, r),
                ),
            ),
            "The compact form of 2.21, as the text says: subscripts f and r as in 2.22; r⃗′_f, "
            "R⃗_f and r⃗_f read as second rates, r⃗_r of the Coriolis term as a first rate (no "
            "dots are printed); the last term ω⃗ × r⃗ as printed.",
        ),
        p(
            "2.24",
            r"|\vec{\omega} \times (\vec{\omega} \times \vec{r})| = \omega^2 r \sin\theta = "
            r"\frac{v^2}{r \sin\theta}",
            _chain(
                _Norm(Cross(_G["omega"], Cross(_G["omega"], _G["r"]))),
                _mul(OMEGA**2, RADIUS, sp.sin(THETA)),
                SPEED**2 / _mul(RADIUS, sp.sin(THETA)),
            ),
            "θ the angle between ω⃗ and r⃗, v = ω r sin θ (the text).",
        ),
    ]
    rs, ws, fs, fs_eff = (_S[n] for n in ("r", "omega", "F", "F_eff"))
    steady = "The unit's setting of 2.25–2.26: ω⃗ constant, R⃗ = 0, r⃗ = r⃗′."
    out += [
        p(
            "2.25",
            r"\vec{F} = m \left( \frac{d^2 \vec{r}}{dt^2} \right)_{fix}",
            _eq(fs, m * _d2(DtFix, rs)),
            steady,
        ),
        p(
            "2.26",
            r"\vec{\omega}=0",
            _eq(ws, ZERO),
            "The condition the text states before 2.26: 'Let the angular velocity of the "
            "rotating system be constant. Then, ω⃗ = 0'.",
        ),
        p("2.26", r"\vec{R}=0", _eq(_S["R"], ZERO), "The text before 2.26."),
        p("2.26", r"\vec{r}=\vec{r}'", _eq(rs, _S["r'"]), "The text before 2.26."),
        p(
            "2.26",
            r"m\left(\frac{d^2\vec{r}}{dt^2}\right)_{rot} = "
            r"m\left(\frac{d^2\vec{r}}{dt^2}\right)_{fix} - 2m\vec{\omega} \times "
            r"\left(\frac{d\vec{r}}{dt}\right)_{rot} - m\vec{\omega} \times (\vec{\omega} \times "
            r"\vec{r}) \\ \therefore m\left(\frac{d^2\vec{r}}{dt^2}\right)_{rot} = \vec{F}_{eff}",
            _chain(
                m * _d2(DtRot, rs),
                _sum(
                    m * _d2(DtFix, rs),
                    -2 * m * Cross(ws, DtRot(rs)),
                    -m * Cross(ws, Cross(ws, rs)),
                ),
                fs_eff,
            ),
            steady + " The two lines as one chain.",
        ),
        p(
            "2.27",
            r"\vec{F} + Non - inertial force = \vec{F}_{eff}",
            _eq(_sum(f, f_ni), f_eff),
            "'Non-inertial force' as F⃗_ni, the sum of the fictitious forces (in the unit's "
            "setting the Coriolis and centrifugal forces it lists).",
        ),
        p(
            "2.28",
            r"\vec{F}_{eff} = \vec{F} - m \vec{\omega} \times (\vec{\omega} \times \vec{r})",
            _eq(_A["F_eff"], _sum(_A["F"], -m * Cross(_A["omega"], Cross(_A["omega"], _A["r"])))),
            "The observer at rest in the rotating frame (the satellite), as the text says; ω⃗ "
            "constant.",
        ),
    ]
    return tuple(out)


#: The unit's equations 2.1–2.28 as printed (scanned), in the unit's order.
PRINTED: tuple[Printed, ...] = _printed()
