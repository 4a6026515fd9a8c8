"""The rigid body, derived: angular momentum and kinetic energy from the particles, the inertia
tensor, principal axes, the dumbbell's holding torque, the parallel-axis theorem and the inertia
tensors of the nine standard solids (the unit's eqs. 2.43–2.66).

Covers
------
2.43–2.51
    v⃗_a = ω⃗ × r⃗_a from the rotating-frame operator (2.14); L⃗ = Σ m_a r⃗_a × (ω⃗ × r⃗_a) by the
    triple product; its components define I_xx … I_zz and the products of inertia, **negated**
    as in the unit (I_xy = −Σ m_a x_a y_a, the project's convention), so L_i = Σ_j I_ij ω_j.
2.52–2.57
    T = ½ Σ m_a v_a² = ½ ω⃗·L⃗ = ½ Σ_ij I_ij ω_i ω_j; turning about z (ω_x = ω_y = 0) L⃗ has
    components I_xz ω_z, I_yz ω_z off the axis, so it is not along ω⃗ unless z is principal.
2.58–2.59
    The dumbbell (masses m₁, m₂ at b₁n̂ and −b₂n̂ on a massless rod through O, at angle α to
    ω⃗ = ω k̂): L⃗ ⟂ rod, and the torque that keeps ω⃗ constant, N⃗ = (dL⃗/dt)_fix = ω⃗ × L⃗
    = −(m₁b₁² + m₂b₂²) ω² sin α cos α ĵ.
2.60–2.66
    The tensor 2.60, its integrals 2.61–2.62, L⃗ = I·ω⃗, T = ½ ω⃗·I·ω⃗, and in principal axes
    L_i = I_i ω_i, T = ½ (I₁ω₁² + I₂ω₂² + I₃ω₃²).
Beyond the unit
    The parallel-axis theorem I_O = I_cm + M (d² 𝟙 − d⃗ d⃗ᵀ), and the inertia tensor of each
    solid of :class:`poinsot.RigidBody` (sphere, spherical shell, cylinder, cone, cuboid,
    ellipsoid, thin rod, thin disk, thin ring) by integrating 2.61–2.62 over the body, about the
    point and in the axes the core uses (the cone about its apex, then about its centre of mass).

Model
-----
Every step is checked in components (SI units throughout: kg, m, rad/s, kg·m², J, N·m), in the
body its symbols name:

* **particles** (the default): two point masses m₁, m₂ at general positions, written
  r⃗_a = d⃗ + s⃗_a from the centre of mass d⃗ (s⃗₂ = −m₁ s⃗₁/m₂, so Σ m_a s⃗_a = 0), and a general
  constant ω⃗ = (ω_x, ω_y, ω_z), all in the body's axes (the rotating frame: (dX/dt)_rot is d/dt
  of the components, which are constant; (dX/dt)_fix adds ω⃗ × X, 2.14). Every identity of
  2.43–2.64 is linear in the particles, so two general ones prove it; the products of inertia
  are not zero, so a misplaced one is caught. ∫ ρ(r⃗) f dτ is Σ m_a f(r⃗_a) (ρ = Σ m_a δ(r⃗−r⃗_a)).
* **principal axes** (an equation that names a principal moment I₁, I₂, I₃ or I_i): three masses
  on the three axes, whose tensor is diagonal with independent moments.
* **the dumbbell** (an equation that names α, b₁, b₂ or n̂): m₁ at b₁ n̂, m₂ at −b₂ n̂,
  n̂ = (sin α, 0, cos α), ω⃗ = ω k̂.
* **solids** (an equation with an integral over a body or a Jacobian): r⃗ is given by the
  integral's coordinates (spherical, cylindrical, Cartesian, scaled spherical, or the surface
  and line coordinates of the thin bodies); integrals of polynomials in the lengths and of
  sin^m cos^n over whole periods are exact (:func:`_integrate`).

An equation with a free index (a over the particles, i, j over 1, 2, 3) holds when it holds for
each value of it; a sum Σ binds its index. Everything is polynomial (trigonometric only in α and
the angular coordinates), so every check is an expansion.

Results
-------
``result`` holds 2.43–2.66 (2.49: I_xy; 2.50: the components of L⃗, the one 2.51 cites; the
unit numbers I_zx 2.49 and I_yz 2.50 as well). ``functions`` holds the numeric forms: 2.59,
2.60, 2.63, 2.64 of the particles (arguments m₁, m₂, d⃗, s⃗₁, ω⃗), ``I_cm`` (the particles' tensor
about their centre of mass), 2.65 and 2.66 (I₁, I₂, I₃, ω⃗), ``parallel_axis``
(I_cm's six entries xx, yy, zz, xy, yz, zx, M, d⃗), ``dumbbell_torque`` (m₁, m₂, b₁, b₂, α, ω)
and one per solid named like its constructor (``solid_sphere``: M, R; …; ``solid_cone_apex``:
the cone about its apex).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from typing import Any

import sympy as sp

from ..errors import PoinsotError
from ._core import Cross, Derivation, Dot, DtFix, DtRot, Printed, Unit, Vec, dot_value, in_order
from ._core import add as _add
from ._core import eq as _eq
from ._core import mul as _mul

__all__ = ["derive", "PRINTED"]

# ---- notation of this topic ---------------------------------------------------------------------


class _Index(sp.Symbol):
    """A summation index: ``a`` runs over the particles, ``i`` and ``j`` over the axes 1, 2, 3.
    Free in an equation, the equation must hold for each of its values."""


_a, _i, _j = _Index("a"), _Index("i"), _Index("j")


def _power(s: str, exp: Any) -> str:
    return s if exp is None else s + "^{" + str(exp) + "}"


class _Comp(sp.Function):
    """A scalar with indices: ``_Comp(m, a)`` is m_a, ``_Comp(I, x, y)`` is I_xy, ``_Comp(I, 1)``
    the principal moment I₁, ``_Comp(omega, i)`` is ω_i."""

    def _latex(self, printer: Any, exp: Any = None) -> str:
        base, *idx = self.args
        s = printer._print(base) + "_{" + "".join(printer._print(k) for k in idx) + "}"
        return _power(s, exp)


class _PVec(sp.Function):
    """The vector of a particle: ``_PVec(r, a)`` is r⃗_a (also v⃗_a, l⃗_a, s⃗_a)."""

    nargs = 2

    def _latex(self, printer: Any, exp: Any = None) -> str:
        base, k = self.args
        s = r"\vec{" + printer._print(base) + "}_{" + printer._print(k) + "}"
        return _power(s, exp)


def _parens(printer: Any, e: Any) -> str:
    s = printer._print(e)
    return r"\left(" + s + r"\right)" if isinstance(e, (sp.Add, _Sum, Cross)) else s


class _Sum(sp.Function):
    """Σ over the indices after the first argument (the summand), unevaluated."""

    def _latex(self, printer: Any, exp: Any = None) -> str:
        body, *idx = self.args
        sub = ",".join(printer._print(k) for k in idx)
        s = r"\sum_{" + sub + "} " + _parens(printer, body)
        return s if exp is None else r"\left(" + s + r"\right)^{" + str(exp) + "}"


class _Tensor(sp.Symbol):
    """A tensor of inertia: ``_Tensor("I")`` prints Ī, ``_Tensor("I_cm")`` prints Ī_cm."""

    def _latex(self, printer: Any) -> str:
        base, _, sub = self.name.partition("_")
        out = r"\overline{" + base + "}"
        return out + (r"_{\mathrm{" + sub + "}}" if sub else "")


class _Kernel(sp.Function):
    """r² 𝟙 − r⃗ r⃗ᵀ for the vector r⃗ (the integrand of the inertia tensor, 2.46–2.50)."""

    nargs = 1

    def _latex(self, printer: Any) -> str:
        (v,) = self.args
        if isinstance(v, Vec):
            mag = printer._print(sp.Symbol(v.name))
        elif isinstance(v, _PVec):
            mag = printer._print(_Comp(*v.args))
        else:
            mag = r"\left|" + printer._print(v) + r"\right|"
        vv = _parens(printer, v)
        return r"\left(" + mag + r"^{2}\,\mathbb{1} - " + vv + r"\," + vv + r"^{\mathsf{T}}\right)"


class _Outer(sp.Function):
    """The outer product a⃗ b⃗ᵀ (a 3×3 matrix)."""

    nargs = 2

    def _latex(self, printer: Any) -> str:
        x, y = self.args
        return _parens(printer, x) + r"\," + _parens(printer, y) + r"^{\mathsf{T}}"


class _BodyIntegral(sp.Function):
    """∫ ρ(r⃗) f dτ over the body, f a function of the field point's x, y, z, r (2.61–2.62)."""

    nargs = 1

    def _latex(self, printer: Any) -> str:
        return r"\int \rho(\vec{r})\, " + _parens(printer, self.args[0]) + r"\, d\tau"


class _Jacobian(sp.Function):
    """det ∂(x, y, z)/∂(u, v, w) of the coordinates (u, v, w) of an integral."""

    def _latex(self, printer: Any) -> str:
        names = ", ".join(printer._print(v) for v in self.args)
        return r"\det \frac{\partial(x, y, z)}{\partial(" + names + ")}"


class _At(sp.Function):
    """``expr`` under the conditions ``((var, value), ...)``: expr|_{var = value}."""

    nargs = 2

    def _latex(self, printer: Any) -> str:
        e, conds = self.args
        sub = r",\ ".join(printer._print(v) + " = " + printer._print(x) for v, x in conds)
        return r"\left. " + printer._print(e) + r" \right|_{" + sub + "}"


class _Dot(Dot):
    """The scalar product, printed with its cross-product operands in parentheses:
    (ω⃗ × r⃗)·(ω⃗ × r⃗)."""

    def _body_latex(self, printer: Any) -> str:
        x, y = self.args
        return _parens(printer, x) + r" \cdot " + _parens(printer, y)


def _neg(x: Any) -> Any:
    return sp.Mul(-1, x, evaluate=False)


def _sub(x: Any, y: Any) -> Any:
    return _add(x, _neg(y))


def _chain(*xs: Any) -> list[Any]:
    return [_eq(x, y) for x, y in zip(xs, xs[1:])]


def _at(e: Any, **conds: Any) -> Any:
    pairs = [sp.Tuple(_omega(k), v) for k, v in conds.items()]
    return _At(e, sp.Tuple(*pairs))


_HALF = sp.Rational(1, 2)
_X, _Y, _Z = sp.symbols("x y z")  # axis labels of components (I_xy, ω_x)
_m, _r, _v, _l, _s = sp.symbols("m r v l s")
_w_name, _L_name, _I_name, _N_name = sp.symbols("omega L I N")

W, L, N = Vec("omega"), Vec("L"), Vec("N")
IBAR, ICM = _Tensor("I"), _Tensor("I_cm")
ONE = sp.Symbol(r"\mathbb{1}")  # the unit tensor 𝟙
ZERO = Vec("0")
D = Vec("d")
I_HAT, J_HAT, K_HAT, N_HAT = Unit("i"), Unit("j"), Unit("k"), Unit("n")
T, M = sp.Symbol("T"), sp.Symbol("M")
L_MAG, I_MOM, OMEGA = sp.Symbol("L"), sp.Symbol("I"), sp.Symbol("omega")
ALPHA = sp.Symbol("alpha")
B1, B2 = sp.Symbol("b_1"), sp.Symbol("b_2")


def _omega(k: Any) -> Any:
    return _Comp(_w_name, k)


def _Lc(k: Any) -> Any:
    return _Comp(_L_name, k)


def _I(*k: Any) -> Any:
    return _Comp(_I_name, *k)


def _ma(k: Any = _a) -> Any:
    return _Comp(_m, k)


def _xa(c: Any, k: Any = _a) -> Any:
    return _Comp(c, k)


def _ra(k: Any = _a) -> Any:
    return _PVec(_r, k)


def _va(k: Any = _a) -> Any:
    return _PVec(_v, k)


def _sum_a(e: Any) -> Any:
    return _Sum(e, _a)


# ---- exact integration over the solids ----------------------------------------------------------


def _trig_moment(m: int, n: int, period: Any) -> Any:
    """∫ sin^m u cos^n u du over [0, π] or [0, 2π] (Wallis: a ratio of Γ functions), exact."""
    g = sp.gamma(sp.Rational(m + 1, 2)) * sp.gamma(sp.Rational(n + 1, 2))
    g = g / sp.gamma(sp.Rational(m + n, 2) + 1)
    if period == sp.pi:
        return sp.Integer(0) if n % 2 else g
    if period == 2 * sp.pi:
        return sp.Integer(0) if (m % 2 or n % 2) else 2 * g
    raise PoinsotError(f"the angular integral must run over [0, π] or [0, 2π], not [0, {period}]")


def _integrate1(e: Any, var: Any, lo: Any, hi: Any) -> Any:
    """∫_lo^hi e d var, term by term, for e a polynomial in var or in sin var and cos var (then
    over [0, π] or [0, 2π])."""
    sin, cos = sp.sin(var), sp.cos(var)
    out = []
    for term in sp.Add.make_args(sp.expand(e)):
        if not term.has(var):
            out.append(term * (hi - lo))
            continue
        powers = dict(term.as_powers_dict())
        p, q, n = powers.pop(sin, 0), powers.pop(cos, 0), powers.pop(var, 0)
        rest = sp.Mul(*(base**k for base, k in powers.items()))
        if rest.has(var) or (n and (p or q)):
            raise PoinsotError(f"cannot integrate {term} over {var} exactly here")
        if p or q:
            if lo != 0:
                raise PoinsotError(f"the angular integral over {var} must start at 0")
            out.append(rest * _trig_moment(int(p), int(q), hi))
        else:
            out.append(rest * (hi ** (n + 1) - lo ** (n + 1)) / (n + 1))
    return sp.expand(sp.Add(*out))


def _integrate(e: Any, limits: Any) -> Any:
    """The iterated integral of ``e`` over ``limits`` ((var, lo, hi), innermost first), exact."""
    for var, lo, hi in limits:
        e = _integrate1(e, var, lo, hi)
    return e


# the coordinates of the solids: symbols, and r⃗ as a function of them
_rr, _th, _ph, _ss, _uu = sp.symbols("r theta phi s u", real=True)
_cx, _cy, _cz = sp.symbols("x y z", real=True)
_R, _H, _A, _B, _C, _ELL = sp.symbols("R h a b c ell", positive=True)
_SIN, _COS = sp.sin, sp.cos

_COORDS: dict[tuple[Any, ...], tuple[Any, Any, Any]] = {
    # spherical (solid sphere)
    (_rr, _th, _ph): (_rr * _SIN(_th) * _COS(_ph), _rr * _SIN(_th) * _SIN(_ph), _rr * _COS(_th)),
    # the sphere of radius R (spherical shell)
    (_th, _ph): (_R * _SIN(_th) * _COS(_ph), _R * _SIN(_th) * _SIN(_ph), _R * _COS(_th)),
    # cylindrical (cylinder, cone)
    (_ss, _ph, _cz): (_ss * _COS(_ph), _ss * _SIN(_ph), _cz),
    # Cartesian (cuboid)
    (_cx, _cy, _cz): (_cx, _cy, _cz),
    # scaled spherical (ellipsoid of semi-axes a, b, c)
    (_uu, _th, _ph): (
        _A * _uu * _SIN(_th) * _COS(_ph),
        _B * _uu * _SIN(_th) * _SIN(_ph),
        _C * _uu * _COS(_th),
    ),
    # the z axis (thin rod), polar in the xy plane (thin disk), the circle of radius R (ring)
    (_cz,): (sp.Integer(0), sp.Integer(0), _cz),
    (_ss, _ph): (_ss * _COS(_ph), _ss * _SIN(_ph), sp.Integer(0)),
    (_ph,): (_R * _COS(_ph), _R * _SIN(_ph), sp.Integer(0)),
}

# ---- the model: the bodies in which the steps are checked ----------------------------------------

_AXIS = {_X: 0, _Y: 1, _Z: 2, sp.Integer(1): 0, sp.Integer(2): 1, sp.Integer(3): 2}
_PARTICLE = {"m", "x", "y", "z", "r", "v"}
_t = sp.Symbol("t")
_DUMBBELL_MARKS = {ALPHA, B1, B2, N_HAT}


def _col(*xs: Any) -> sp.Matrix:
    return sp.Matrix(list(xs))


def _kernel(v: sp.Matrix) -> sp.Matrix:
    return (v.T * v)[0, 0] * sp.eye(3) - v * v.T


@dataclass
class _Body:
    """Components for one body: particle masses and positions (body axes), ω⃗, and named values
    (vectors, tensors, scalars) and definitions (notation to be evaluated)."""

    masses: list[Any] = field(default_factory=list)
    positions: list[sp.Matrix] = field(default_factory=list)
    omega: sp.Matrix = field(default_factory=lambda: sp.zeros(3, 1))
    values: dict[Any, Any] = field(default_factory=dict)
    defs: dict[Any, Any] = field(default_factory=dict)
    velocities: list[sp.Matrix] = field(default_factory=list)

    def dt_fix(self, x: sp.Matrix) -> sp.Matrix:
        """(dX/dt)_fix = (dX/dt)_rot + ω⃗ × X (2.14) on body components."""
        return x.diff(_t) + self.omega.cross(x)

    def fill(self) -> None:
        """The particles' v⃗_a, L⃗, T, N⃗ and tensor (the definitions 2.43, 2.46–2.52, 2.59)."""
        ms, rs = self.masses, self.positions
        vs = [self.dt_fix(r) for r in rs]
        Lv = sp.zeros(3, 1)
        for mk, rk, vk in zip(ms, rs, vs):
            Lv += rk.cross(mk * vk)
        tensor = sp.zeros(3, 3)
        for mk, rk in zip(ms, rs):
            tensor += mk * _kernel(rk)
        self.values.update(
            {
                W: self.omega,
                L: Lv,
                N: self.dt_fix(Lv),
                IBAR: tensor,
                T: sum((_HALF * mk * (vk.T * vk)[0, 0] for mk, vk in zip(ms, vs)), sp.Integer(0)),
                M: sum(ms, sp.Integer(0)),
                L_MAG: sp.sqrt((Lv.T * Lv)[0, 0]),
                I_MOM: tensor[2, 2],
            }
        )
        self.velocities = vs

    def particle(self, name: str, k: int) -> Any:
        rk = self.positions[k]
        if name == "m":
            return self.masses[k]
        if name in "xyz":
            return rk["xyz".index(name)]
        if name == "r":
            return sp.sqrt((rk.T * rk)[0, 0])
        v = self.velocities[k]
        return sp.sqrt((v.T * v)[0, 0])

    def pvec(self, name: str, k: int) -> sp.Matrix:
        if name == "r":
            return self.positions[k]
        if name == "v":
            return self.velocities[k]
        if name == "l":
            return self.positions[k].cross(self.masses[k] * self.velocities[k])
        if name == "s":
            return self.positions[k] - self.values[D]
        raise PoinsotError(f"no particle vector {name}")


def _common(b: _Body) -> _Body:
    b.values.update(
        {
            I_HAT: _col(1, 0, 0),
            J_HAT: _col(0, 1, 0),
            K_HAT: _col(0, 0, 1),
            ZERO: sp.zeros(3, 1),
            ONE: sp.eye(3),
        }
    )
    return b


def _particles() -> _Body:
    """Two general masses, positions d⃗ + s⃗_a about their centre of mass d⃗."""
    m1, m2 = sp.symbols("m_1 m_2")
    d = _col(*sp.symbols("d_x d_y d_z"))
    s1 = _col(*sp.symbols("s_x s_y s_z"))
    s2 = -m1 / m2 * s1
    b = _common(_Body([m1, m2], [d + s1, d + s2], _col(*sp.symbols("omega_x omega_y omega_z"))))
    b.values[D] = d
    b.fill()
    b.values[ICM] = m1 * _kernel(s1) + m2 * _kernel(s2)
    return b


def _principal() -> _Body:
    """Three masses on the three axes: a body whose axes are principal, moments independent."""
    ms = list(sp.symbols("m_1 m_2 m_3"))
    p = sp.symbols("p_1 p_2 p_3")
    rs = [_col(p[0], 0, 0), _col(0, p[1], 0), _col(0, 0, p[2])]
    b = _common(_Body(ms, rs, _col(*sp.symbols("omega_x omega_y omega_z"))))
    b.fill()
    return b


def _dumbbell() -> _Body:
    """m₁ at b₁ n̂ and m₂ at −b₂ n̂, n̂ = (sin α, 0, cos α), turning with ω⃗ = ω k̂."""
    n = _col(sp.sin(ALPHA), 0, sp.cos(ALPHA))
    b = _common(
        _Body(list(sp.symbols("m_1 m_2")), [B1 * n, -B2 * n], _col(0, 0, OMEGA)),
    )
    b.values[N_HAT] = n
    b.fill()
    return b


def _free() -> _Body:
    """Independent symbols for a formula's numeric form: I_cm's entries, M, d⃗, I₁…I₃, ω⃗."""
    b = _common(_Body(omega=_col(*sp.symbols("omega_x omega_y omega_z"))))
    j = sp.symbols("J_xx J_yy J_zz J_xy J_yz J_zx")
    b.values.update(
        {
            W: b.omega,
            ICM: sp.Matrix([[j[0], j[3], j[5]], [j[3], j[1], j[4]], [j[5], j[4], j[2]]]),
            M: M,
            D: _col(*sp.symbols("d_x d_y d_z")),
            IBAR: sp.diag(*sp.symbols("I_1 I_2 I_3")),
        }
    )
    return b


class _Model:
    """Evaluates the notation in one of the bodies ``"particles"`` (the default when called),
    ``"principal"``, ``"dumbbell"``, ``"solid"`` or ``"free"`` (see the module docstring)."""

    def __init__(self) -> None:
        self.bodies = {
            "particles": _particles(),
            "principal": _principal(),
            "dumbbell": _dumbbell(),
            "solid": _common(_Body()),
            "free": _free(),
        }
        self._integrals: dict[Any, Any] = {}

    def __call__(self, e: Any) -> Any:
        return self.evaluate(e, "particles")

    def define(self, mode: str, name: Any, expr: Any) -> None:
        """Binds ``name`` to the notation ``expr`` in the body ``mode``."""
        self.bodies[mode].defs[name] = expr

    def mode(self, e: Any) -> str:
        """The body an equation is judged in, from the symbols it names."""
        if e.atoms(sp.Integral, _Jacobian) or (e.free_symbols & set(self.bodies["solid"].defs)):
            return "solid"
        if e.free_symbols & _DUMBBELL_MARKS:
            return "dumbbell"
        if any(c.args[0] == _I_name and len(c.args) == 2 for c in e.atoms(_Comp)):
            return "principal"
        return "particles"

    def evaluate(self, e: Any, mode: str) -> Any:
        """The components of ``e`` (a matrix for a vector or tensor, else a scalar)."""
        return self._ev(sp.sympify(e), self.bodies[mode], {})

    def _ev(self, e: Any, b: _Body, env: dict[Any, Any]) -> Any:
        ev = self._ev
        if isinstance(e, sp.MatrixBase):
            return sp.Matrix(e.rows, e.cols, [ev(x, b, env) for x in e])
        if e in env:
            return env[e]
        if e in b.defs:
            return ev(b.defs[e], b, env)
        if isinstance(e, _Index):
            raise PoinsotError(f"the index {e} is free here; the equation must bind it")
        if e.is_Symbol:
            if e in b.values:
                return b.values[e]
            if isinstance(e, (Vec, Unit, _Tensor)):
                raise PoinsotError(f"the model has no components for {e}")
            return e
        if isinstance(e, _Comp):
            return self._comp(e, b)
        if isinstance(e, _PVec):
            return b.pvec(e.args[0].name, int(e.args[1]) - 1)
        if isinstance(e, _Sum):
            return self._sum(e, b, env)
        if isinstance(e, Cross):
            x, y = (ev(a, b, env) for a in e.args)
            return x.cross(y)
        if isinstance(e, Dot):
            return dot_value(*(ev(a, b, env) for a in e.args))
        if isinstance(e, DtFix):
            return b.dt_fix(ev(e.args[0], b, env))
        if isinstance(e, DtRot):
            return ev(e.args[0], b, env).diff(_t)
        if isinstance(e, _Kernel):
            return _kernel(ev(e.args[0], b, env))
        if isinstance(e, _Outer):
            return ev(e.args[0], b, env) * ev(e.args[1], b, env).T
        if isinstance(e, _BodyIntegral):
            total = sp.Integer(0)
            for mk, rk in zip(b.masses, b.positions):
                bind = {_cx: rk[0], _cy: rk[1], _cz: rk[2], _rr: sp.sqrt((rk.T * rk)[0, 0])}
                total += mk * ev(e.args[0].xreplace(bind), b, env)
            return total
        if isinstance(e, _Jacobian):
            cmap = sp.Matrix(_COORDS[tuple(e.args)])
            return cmap.jacobian(list(e.args)).det()
        if isinstance(e, _At):
            inner = ev(e.args[0], b, env)
            return inner.subs({ev(v, b, env): ev(x, b, env) for v, x in e.args[1]})
        if isinstance(e, sp.Integral):
            return self._integral(e, b)
        if isinstance(e, (sp.Add, sp.Mul)):
            return in_order(e, [ev(x, b, env) for x in e.args])
        if isinstance(e, sp.Pow):
            return ev(e.base, b, env) ** e.exp
        if e.args and isinstance(e, sp.Function):
            return e.func(*(ev(x, b, env) for x in e.args))
        return e

    def _comp(self, e: Any, b: _Body) -> Any:
        base, *idx = e.args
        name = base.name
        if name in _PARTICLE and len(idx) == 1:
            return b.particle(name, int(idx[0]) - 1)
        pos = [_AXIS[k] for k in idx]
        if name == "I":
            tensor = b.values[IBAR]
            return tensor[pos[0], pos[0]] if len(pos) == 1 else tensor[pos[0], pos[1]]
        return b.values[Vec(name)][pos[0]]

    def _sum(self, e: Any, b: _Body, env: dict[Any, Any]) -> Any:
        body, *idx = e.args
        ranges = [range(1, len(b.masses) + 1) if k == _a else range(1, 4) for k in idx]
        total: Any = None
        for vals in itertools.product(*ranges):
            term = self._ev(_bind(body, dict(zip(idx, map(sp.Integer, vals)))), b, env)
            total = term if total is None else total + term
        return total

    def _integral(self, e: Any, b: _Body) -> Any:
        if e not in self._integrals:
            limits = [tuple(lim) for lim in e.limits]
            cmap = _COORDS[tuple(lim[0] for lim in limits)]
            f = self._ev(e.function, b, {Vec("r"): _col(*cmap)})
            if isinstance(f, sp.MatrixBase):
                val: Any = f.applyfunc(lambda x: _integrate(x, limits))
            else:
                val = _integrate(f, limits)
            self._integrals[e] = val
        return self._integrals[e]


def _free_indices(e: Any) -> set[Any]:
    if isinstance(e, _Index):
        return {e}
    if isinstance(e, _Sum):
        body, *idx = e.args
        return _free_indices(body) - set(idx)
    out: set[Any] = set()
    for x in getattr(e, "args", ()):
        out |= _free_indices(x)
    return out


def _bind(e: Any, sub: dict[Any, Any]) -> Any:
    """``e`` with the free occurrences of the indices in ``sub`` replaced by their values."""
    if not sub:
        return e
    if isinstance(e, _Index):
        return sub.get(e, e)
    if isinstance(e, _Sum):
        body, *idx = e.args
        return _Sum(_bind(body, {k: v for k, v in sub.items() if k not in idx}), *idx)
    if isinstance(e, sp.MatrixBase):
        return e.applyfunc(lambda x: _bind(x, sub))
    if not e.args:
        return e
    return e.func(*(_bind(x, sub) for x in e.args))


@dataclass
class _RigidDerivation(Derivation):
    """A :class:`Derivation` whose equations may carry free indices and are judged in the body
    their symbols name (:meth:`_Model.mode`)."""

    rigid: Any = None

    def residual(self, eq: Any) -> Any:
        """``lhs − rhs`` in components, one entry per value of the free indices."""
        model: _Model = self.rigid
        mode = model.mode(eq)
        free = sorted(_free_indices(eq.lhs) | _free_indices(eq.rhs), key=str)
        n = len(model.bodies[mode].masses)
        ranges = [range(1, n + 1) if k == _a else range(1, 4) for k in free]
        parts: list[Any] = []
        for vals in itertools.product(*ranges):
            sub = dict(zip(free, map(sp.Integer, vals)))
            lhs = model.evaluate(_bind(eq.lhs, sub), mode)
            rhs = model.evaluate(_bind(eq.rhs, sub), mode)
            lm, rm = isinstance(lhs, sp.MatrixBase), isinstance(rhs, sp.MatrixBase)
            if lm != rm:
                raise PoinsotError(f"{sp.sstr(eq)}: one side is a vector, the other a scalar")
            diff = lhs - rhs
            parts.extend(list(diff) if lm else [diff])
        out: Any = sp.Matrix(parts) if len(parts) > 1 else parts[0]
        if self.context:
            out = out.subs(self.context)
        return out

    def function_of(self, number: str, e: Any, mode: str, symbols: Any) -> None:
        """Registers the numeric form of ``e`` evaluated in ``mode`` (free indices enumerated)."""
        model: _Model = self.rigid
        free = sorted(_free_indices(e), key=str)
        if free:
            (k,) = free
            expr: Any = sp.Matrix(
                [model.evaluate(_bind(e, {k: sp.Integer(v)}), mode) for v in (1, 2, 3)]
            )
        else:
            expr = model.evaluate(e, mode)
        self.function(number, expr, symbols)


# ---- the derivation -----------------------------------------------------------------------------


def _components(vec: str) -> list[Any]:
    return [_Comp(sp.Symbol(vec), c) for c in (_X, _Y, _Z)]


def _tensor_matrix() -> sp.ImmutableMatrix:
    return sp.ImmutableMatrix(3, 3, [_I(p, q) for p in (_X, _Y, _Z) for q in (_X, _Y, _Z)])


def _particle_symbols() -> tuple[Any, ...]:
    return sp.symbols("m_1 m_2 d_x d_y d_z s_x s_y s_z omega_x omega_y omega_z")


def derive() -> Derivation:
    """Builds and checks the derivation of 2.43–2.66 (see the module docstring)."""
    model = _Model()
    d = _RigidDerivation(
        "rigid_body",
        "The rigid body: angular momentum, kinetic energy and the inertia tensor (2.43–2.66)",
        summary=(
            "From the particles of a body turning about a fixed point to its inertia tensor, "
            "the principal axes, the dumbbell's holding torque, the parallel-axis theorem and "
            "the tensors of the standard solids. Products of inertia are negated as in the "
            "unit (I_xy = −Σ m x y)."
        ),
        model=model,
        rigid=model,
    )
    _particles_part(d)
    _energy_part(d)
    _dumbbell_part(d)
    _tensor_part(d)
    _parallel_axis_part(d)
    _solids_part(d, model)
    return d


def _carried(lhs: Any, x: Any) -> list[Any]:
    """``lhs`` = the fixed-frame rate of a vector ``x`` fixed in the body, by the operator 2.14
    with (dx/dt)_rot = 0: (dx/dt)_fix = (dx/dt)_rot + ω⃗ × x = ω⃗ × x."""
    return _chain(lhs, DtFix(x), _add(DtRot(x), Cross(W, x)), Cross(W, x))


def _particles_part(d: _RigidDerivation) -> None:
    ra, va, ma = _ra(), _va(), _ma()
    d.given(
        "A rigid body of particles m_a at positions r⃗_a from the fixed point O turns with "
        "angular velocity ω⃗. In axes fixed in the body (the rotating frame of 2.14) no particle "
        "moves.",
        _eq(DtRot(ra), ZERO),
    )
    d.step(
        "The velocity of particle a is the rate of r⃗_a seen from the fixed frame; by the "
        "operator 2.14, with (dr⃗_a/dt)_rot = 0:",
        _carried(va, ra),
        "2.43",
    )
    d.given(
        "The angular momentum about O is the sum of the particles' r⃗_a × m_a v⃗_a.",
        _chain(L, _sum_a(_PVec(_l, _a)), _sum_a(Cross(ra, _mul(ma, va)))),
    )
    d.step("Substitute 2.43:", _eq(L, _sum_a(_mul(ma, Cross(ra, Cross(W, ra))))))
    d.step(
        "Expand with the triple product A⃗ × (B⃗ × C⃗) = B⃗ (A⃗·C⃗) − C⃗ (A⃗·B⃗):",
        _eq(L, _sub(_sum_a(_mul(ma, W, _Dot(ra, ra))), _sum_a(_mul(ma, ra, _Dot(ra, W))))),
    )
    r2 = _Comp(_r, _a) ** 2
    d.step(
        "With r⃗_a·r⃗_a = r_a²:",
        _eq(L, _sub(_sum_a(_mul(ma, r2, W)), _sum_a(_mul(ma, _Dot(ra, W), ra)))),
        "2.44",
    )
    x, y, z = (_xa(c) for c in (_X, _Y, _Z))
    wx, wy, wz = (_omega(c) for c in (_X, _Y, _Z))
    d.step(
        "The x component of 2.44, with r⃗_a·ω⃗ = x_a ω_x + y_a ω_y + z_a ω_z:",
        _chain(
            _Lc(_X),
            _sub(
                _sum_a(_mul(ma, r2, wx)),
                _sum_a(_mul(ma, _add(_mul(x, wx), _mul(y, wy), _mul(z, wz)), x)),
            ),
            _add(
                _sum_a(_mul(ma, _sub(r2, x**2), wx)),
                _neg(_sum_a(_mul(ma, x, y, wy))),
                _neg(_sum_a(_mul(ma, x, z, wz))),
            ),
        ),
        "2.45",
    )
    for (p, q1, q2), number in zip(((x, y, z), (y, z, x), (z, x, y)), ("2.46", "2.47", "2.48")):
        lab = p.args[0]
        d.step(
            (
                "Call the coefficient of ω_x in 2.45 the moment of inertia about x; since "
                "r_a² = x_a² + y_a² + z_a²:"
                if number == "2.46"
                else f"The same about {lab} (from the {lab} component of 2.44):"
            ),
            _chain(
                _I(lab, lab),
                _sum_a(_mul(ma, _sub(r2, p**2))),
                _sum_a(_mul(ma, _add(q1**2, q2**2))),
            ),
            number,
        )
    pairs: tuple[tuple[Any, Any, str | None, str], ...] = (
        (
            x,
            y,
            "2.49",
            "The coefficient of ω_y in 2.45 is the product of inertia, negated as in "
            "the unit (the project's convention); it is symmetric:",
        ),
        (y, z, None, "Likewise I_yz (the unit's first 2.50):"),
        (z, x, None, "and I_zx (the unit numbers it 2.49 a second time):"),
    )
    for p, q, num, text in pairs:
        lp, lq = p.args[0], q.args[0]
        d.step(text, _chain(_I(lp, lq), _neg(_sum_a(_mul(ma, p, q))), _I(lq, lp)), num)
    rows = [_add(*(_mul(_I(p, q), _omega(q)) for q in (_X, _Y, _Z))) for p in (_X, _Y, _Z)]
    d.step(
        "With 2.46–2.49 the three components of 2.44 (the unit's second 2.50, the one 2.51 "
        "cites) are",
        _eq(sp.ImmutableMatrix(_components("L")), sp.ImmutableMatrix(rows)),
        "2.50",
    )
    d.step(
        "Number the axes x, y, z as 1, 2, 3: row i of 2.50 is a sum over the column index j, "
        "for each i = 1, 2, 3. (The unit prints Σ_i; i is the free row index, the sum runs "
        "over j.)",
        _eq(_Lc(_i), _Sum(_mul(_I(_i, _j), _omega(_j)), _j)),
        "2.51",
    )


def _energy_part(d: _RigidDerivation) -> None:
    ra, va, ma = _ra(), _va(), _ma()
    w_cross_r = Cross(W, ra)
    d.given(
        "The kinetic energy is the particles' sum:",
        _eq(T, _sum_a(_mul(_HALF, ma, _Comp(_v, _a) ** 2))),
        "2.52",
    )
    d.step(
        "Double it and substitute 2.43; the scalar triple product is cyclic, "
        "(ω⃗ × r⃗)·C⃗ = ω⃗·(r⃗ × C⃗); the sum that remains is L⃗:",
        _chain(
            _mul(2, T),
            _sum_a(_mul(ma, _Dot(va, va))),
            _sum_a(_mul(ma, _Dot(w_cross_r, w_cross_r))),
            _sum_a(_mul(ma, _Dot(W, Cross(ra, w_cross_r)))),
            _Dot(W, _sum_a(_mul(ma, Cross(ra, w_cross_r)))),
            _Dot(W, L),
        ),
    )
    d.step("Halve it:", _eq(T, _mul(_HALF, _Dot(W, L))), "2.53")
    d.step(
        "Write the scalar product in components and substitute 2.51:",
        _chain(
            T,
            _mul(_HALF, _Sum(_mul(_omega(_i), _Lc(_i)), _i)),
            _mul(_HALF, _Sum(_mul(_I(_i, _j), _omega(_i), _omega(_j)), _i, _j)),
        ),
        "2.54",
    )
    lab = (_X, _Y, _Z)
    diag = [_mul(_I(p, p), _omega(p) ** 2) for p in lab]
    off = [_mul(2, _I(p, q), _omega(p), _omega(q)) for p, q in ((_X, _Y), (_Y, _Z), (_Z, _X))]
    d.step(
        "Write out the nine terms; the tensor is symmetric (2.49–2.50), so each product of "
        "inertia appears twice:",
        _eq(T, _mul(_HALF, _add(*diag, *off))),
        "2.55",
    )
    conds = {"x": 0, "y": 0, "z": OMEGA}
    d.step(
        "Turning about the z axis, ω_x = ω_y = 0 and ω_z = ω; 2.55 keeps one term, with "
        "I = I_zz the moment of inertia about z:",
        _chain(
            _at(T, **conds),
            _mul(_HALF, _I(_Z, _Z), OMEGA**2),
            _mul(_HALF, I_MOM, OMEGA**2),
        ),
        "2.56",
    )
    d.step(
        "The same rotation in 2.50: L⃗ keeps the components I_xz ω_z and I_yz ω_z off the "
        "axis of rotation,",
        _eq(
            _at(sp.ImmutableMatrix(_components("L")), x=0, y=0),
            sp.ImmutableMatrix([_mul(_I(p, _Z), _omega(_Z)) for p in lab]),
        ),
        "2.57",
    )
    d.step(
        "so L⃗ is not along ω⃗: ω⃗ × L⃗ vanishes only when I_xz = I_yz = 0, i.e. when z is a "
        "principal axis (2.65).",
        _eq(
            _at(Cross(W, L), x=0, y=0),
            sp.ImmutableMatrix(
                [
                    _neg(_mul(_I(_Y, _Z), _omega(_Z) ** 2)),
                    _mul(_I(_X, _Z), _omega(_Z) ** 2),
                    0,
                ]
            ),
        ),
    )


def _dumbbell_part(d: _RigidDerivation) -> None:
    r1, r2, v1, v2 = _ra(1), _ra(2), _va(1), _va(2)
    m1, m2 = _ma(1), _ma(2)
    d.given(
        "The dumbbell of Fig. 2.9: masses m_1 and m_2 on a massless rod through O along the "
        "unit vector n̂, m_1 at the distance b_1 from O,",
        _eq(r1, _mul(B1, N_HAT)),
    )
    d.given("and m_2 at b_2 on the other side,", _eq(r2, _neg(_mul(B2, N_HAT))))
    d.given(
        "It turns about the z axis, ω⃗ = ω k̂, with the rod at the angle α to it (drawn at the "
        "instant the rod lies in the xz plane):",
        _eq(N_HAT, _add(_mul(sp.sin(ALPHA), I_HAT), _mul(sp.cos(ALPHA), K_HAT))),
    )
    d.step(
        "The component of ω⃗ along the rod is then", _eq(_Dot(N_HAT, W), _mul(OMEGA, sp.cos(ALPHA)))
    )
    i_rod = _add(_mul(m1, B1**2), _mul(m2, B2**2))
    d.step(
        "Its angular momentum (2.58), with 2.43 and the triple product as in 2.44 (n̂·n̂ = 1):",
        _chain(
            L,
            _add(_mul(m1, Cross(r1, v1)), _mul(m2, Cross(r2, v2))),
            _mul(i_rod, _sub(W, _mul(_Dot(N_HAT, W), N_HAT))),
        ),
        "2.58",
    )
    d.step(
        "L⃗ is perpendicular to the rod:",
        _eq(_Dot(L, N_HAT), 0),
    )
    d.step(
        "In components it lies in the plane of the rod and ω⃗, tilted from ω⃗:",
        _eq(
            L,
            _mul(
                i_rod,
                OMEGA,
                sp.sin(ALPHA),
                _add(_neg(_mul(sp.cos(ALPHA), I_HAT)), _mul(sp.sin(ALPHA), K_HAT)),
            ),
        ),
    )
    d.step(
        "so L⃗ is along ω⃗ only when α = 0 (the rod on the axis) or α = π/2 (the rod across it):",
        _eq(
            Cross(W, L),
            _neg(_mul(i_rod, OMEGA**2, sp.sin(ALPHA), sp.cos(ALPHA), J_HAT)),
        ),
    )
    d.given(
        "The law of rotation about the fixed point: the rate of L⃗ in the fixed frame is the "
        "torque. (The unit prints 2.59 as L⃗ = N⃗; the dot over L⃗ was lost in the scan, as in "
        'the words before it, "L⃗ ≠ 0".)',
        _eq(DtFix(L), N),
    )
    d.step(
        "At constant ω⃗ the body-frame components of L⃗ (2.50) are constant, (dL⃗/dt)_rot = 0, "
        "and by 2.14 the torque that must hold the body is",
        _carried(N, L),
        "2.59",
    )
    torque = _neg(_mul(i_rod, OMEGA**2, sp.sin(ALPHA), sp.cos(ALPHA), J_HAT))
    d.step(
        "For the dumbbell it is perpendicular to the plane of the rod and ω⃗, of magnitude "
        "½ (m_1 b_1² + m_2 b_2²) ω² sin 2α; it turns with the body:",
        _chain(N, Cross(W, L), torque),
    )
    d.function_of("dumbbell_torque", torque, "dumbbell", sp.symbols("m_1 m_2 b_1 b_2 alpha omega"))
    d.function_of("2.59", Cross(W, L), "particles", _particle_symbols())


def _tensor_part(d: _RigidDerivation) -> None:
    ra, ma = _ra(), _ma()
    tm = _tensor_matrix()
    d.step(
        "Collect the coefficients of 2.50 into the inertia tensor; it is symmetric, "
        "I_ij = I_ji, with six independent entries, and in vector form it is the sum of "
        "m_a (r_a² 𝟙 − r⃗_a r⃗_aᵀ):",
        _chain(IBAR, tm, _sum_a(_mul(ma, _Kernel(ra)))),
        "2.60",
    )
    d.step(
        "For matter of density ρ(r⃗) the sums become integrals over the volume (a body of "
        "particles is ρ = Σ m_a δ(r⃗ − r⃗_a), for which they are the sums 2.46):",
        _eq(_I(_X, _X), _BodyIntegral(_sub(_rr**2, _cx**2))),
        "2.61",
    )
    d.step(
        "and the products of inertia (2.49):",
        _eq(_I(_X, _Y), _neg(_BodyIntegral(_mul(_cx, _cy)))),
        "2.62",
    )
    d.step(
        "2.51 is the product of the matrix 2.60 with the column ω⃗:",
        _eq(L, _Dot(IBAR, W)),
        "2.63",
    )
    d.step(
        "Substitute 2.63 into 2.53:",
        _chain(T, _mul(_HALF, _Dot(W, L)), _mul(_HALF, _Dot(W, _Dot(IBAR, W)))),
        "2.64",
    )
    d.given(
        "I is real and symmetric, so three orthogonal axes exist in which it is diagonal: the "
        "principal axes, with the principal moments I_1, I_2, I_3 (the spectral theorem).",
        _eq(IBAR, sp.ImmutableMatrix(sp.diag(_I(1), _I(2), _I(3)))),
    )
    d.step(
        "In principal axes 2.51 keeps one term: L_i = I_i ω_i, no sum (the unit prints L = "
        "I_i ω_i; the index of L was lost).",
        _chain(_Lc(_i), _Sum(_mul(_I(_i, _j), _omega(_j)), _j), _mul(_I(_i), _omega(_i))),
        "2.65",
    )
    d.step(
        "and 2.54 keeps the squares (the unit prints I_i for I_1 in the first term):",
        _chain(
            T,
            _mul(_HALF, _Sum(_mul(_I(_i), _omega(_i) ** 2), _i)),
            _mul(_HALF, _add(*(_mul(_I(k), _omega(k) ** 2) for k in (1, 2, 3)))),
        ),
        "2.66",
    )
    syms = _particle_symbols()
    d.function_of("2.60", IBAR, "particles", syms)
    d.function_of("2.63", _Dot(IBAR, W), "particles", syms)
    d.function_of("2.64", _mul(_HALF, _Dot(W, _Dot(IBAR, W))), "particles", syms)
    d.function_of("I_cm", ICM, "particles", syms)
    principal = sp.symbols("I_1 I_2 I_3 omega_x omega_y omega_z")
    d.function_of("2.65", _mul(_I(_i), _omega(_i)), "free", principal)
    d.function_of(
        "2.66",
        _mul(_HALF, _add(*(_mul(_I(k), _omega(k) ** 2) for k in (1, 2, 3)))),
        "free",
        principal,
    )


def _parallel_axis_part(d: _RigidDerivation) -> None:
    ra, ma, sa = _ra(), _ma(), _PVec(_s, _a)
    d.given(
        "The parallel-axis theorem. Measure the particles from the centre of mass d⃗ "
        "(seen from O): r⃗_a = d⃗ + s⃗_a,",
        _eq(ra, _add(D, sa)),
    )
    d.given(
        "where, by the definition of the centre of mass,",
        _eq(_sum_a(_mul(ma, sa)), ZERO),
    )
    d.given("The total mass is", _eq(M, _sum_a(ma)))
    d.given(
        "the tensor about the centre of mass is that of 2.60 with s⃗_a for r⃗_a:",
        _eq(ICM, _sum_a(_mul(ma, _Kernel(sa)))),
    )
    msum = _sum_a(_mul(ma, sa))
    cross_terms = (
        _mul(2, _Dot(D, msum), ONE),
        _neg(_Outer(D, msum)),
        _neg(_Outer(msum, D)),
    )
    shift = _mul(M, _Kernel(D))
    d.step(
        "Substitute into 2.60 and expand; the terms linear in s⃗_a carry Σ m_a s⃗_a = 0:",
        _chain(
            IBAR,
            _sum_a(_mul(ma, _Kernel(_add(D, sa)))),
            _add(ICM, shift, *cross_terms),
            _add(ICM, shift),
        ),
    )
    d.function_of(
        "parallel_axis",
        _add(ICM, shift),
        "free",
        sp.symbols("J_xx J_yy J_zz J_xy J_yz J_zx M d_x d_y d_z"),
    )


# the solids: (constructor, label, description, what is measured, limits, element, symbols)
def _solids() -> list[tuple[str, str, str, str, list[tuple[Any, Any, Any]], Any, tuple[Any, ...]]]:
    pi = sp.pi
    return [
        (
            "solid_sphere",
            "sphere",
            "The solid sphere of radius R, centred on O, in spherical coordinates",
            "volume",
            [(_rr, 0, _R), (_th, 0, pi), (_ph, 0, 2 * pi)],
            _rr**2 * sp.sin(_th),
            (M, _R),
        ),
        (
            "spherical_shell",
            "shell",
            "The spherical shell of radius R, a surface (area element R² sin θ dθ dφ)",
            "area",
            [(_th, 0, pi), (_ph, 0, 2 * pi)],
            _R**2 * sp.sin(_th),
            (M, _R),
        ),
        (
            "solid_cylinder",
            "cylinder",
            "The solid cylinder of radius R and height h along z, centred on O, in "
            "cylindrical coordinates",
            "volume",
            [(_ss, 0, _R), (_ph, 0, 2 * pi), (_cz, -_H / 2, _H / 2)],
            _ss,
            (M, _R, _H),
        ),
        (
            "solid_cone_apex",
            "cone,O",
            "The solid cone of base radius R and height h, with its apex at O and its axis "
            "along +z as the core builds it, in cylindrical coordinates (at height z its radius "
            "is R z/h)",
            "volume",
            [(_ss, 0, _R * _cz / _H), (_ph, 0, 2 * pi), (_cz, 0, _H)],
            _ss,
            (M, _R, _H),
        ),
        (
            "cuboid",
            "cuboid",
            "The cuboid of sides a, b, c along x, y, z, centred on O",
            "volume",
            [(_cx, -_A / 2, _A / 2), (_cy, -_B / 2, _B / 2), (_cz, -_C / 2, _C / 2)],
            sp.Integer(1),
            (M, _A, _B, _C),
        ),
        (
            "ellipsoid",
            "ellipsoid",
            "The solid ellipsoid of semi-axes a, b, c along x, y, z, in scaled spherical "
            "coordinates",
            "volume",
            [(_uu, 0, 1), (_th, 0, pi), (_ph, 0, 2 * pi)],
            _A * _B * _C * _uu**2 * sp.sin(_th),
            (M, _A, _B, _C),
        ),
        (
            "thin_rod",
            "rod",
            "The thin rod of length ℓ along z, centred on O, a line (length element dz)",
            "length",
            [(_cz, -_ELL / 2, _ELL / 2)],
            sp.Integer(1),
            (M, _ELL),
        ),
        (
            "thin_disk",
            "disk",
            "The thin disk of radius R in the xy plane, centred on O, a surface (area element "
            "s ds dφ)",
            "area",
            [(_ss, 0, _R), (_ph, 0, 2 * pi)],
            _ss,
            (M, _R),
        ),
        (
            "thin_ring",
            "ring",
            "The thin ring of radius R in the xy plane, centred on O, a line (length element R dφ)",
            "length",
            [(_ph, 0, 2 * pi)],
            _R,
            (M, _R),
        ),
    ]


def _solids_part(d: _RigidDerivation, model: _Model) -> None:
    rvec = Vec("r")
    for coords, form, text in (
        (
            (_rr, _th, _ph),
            _rr**2 * sp.sin(_th),
            "Beyond the unit: the tensors of the nine solids of poinsot.RigidBody, by 2.61–2.62 "
            "with uniform density. Spherical coordinates x = r sin θ cos φ, y = r sin θ sin φ, "
            "z = r cos θ have the volume element dτ = r² sin θ dr dθ dφ:",
        ),
        (
            (_ss, _ph, _cz),
            _ss,
            "Cylindrical coordinates x = s cos φ, y = s sin φ, z have dτ = s ds dφ dz:",
        ),
        (
            (_uu, _th, _ph),
            _A * _B * _C * _uu**2 * sp.sin(_th),
            "Scaled spherical coordinates x = a u sin θ cos φ, y = b u sin θ sin φ, "
            "z = c u cos θ have dτ = a b c u² sin θ du dθ dφ:",
        ),
    ):
        d.step(text, _eq(_Jacobian(*coords), form))
    for key, label, text, kind, limits, jac, symbols in _solids():
        measure = sp.factor(model.evaluate(sp.Integral(jac, *limits), "solid"))
        d.step(f"{text}. Its {kind} is", _eq(sp.Integral(jac, *limits), measure))
        density = M / measure
        integral = sp.Integral(_mul(density, _Kernel(rvec), jac), *limits)
        tensor = _Tensor("I_" + label)
        model.define("solid", tensor, integral)
        value = model.evaluate(integral, "solid").applyfunc(sp.factor)
        d.step(
            f"so its uniform density is M over that {kind}, and by 2.61–2.62 its tensor "
            "(products negated) is",
            _chain(tensor, integral, sp.ImmutableMatrix(value)),
        )
        d.function(key, value, symbols)
        if key == "solid_cone_apex":
            _cone_about_centre(d, model, density, limits, jac, tensor)


def _cone_about_centre(
    d: _RigidDerivation, model: _Model, density: Any, limits: Any, jac: Any, apex: Any
) -> None:
    rvec, dc = Vec("r"), Vec("d_c")
    zc = sp.Symbol("z_c")
    centre = _mul(1 / M, sp.Integral(_mul(density, _cz, jac), *limits))
    model.define("solid", zc, centre)
    d.step(
        "The cone's centre of mass lies on its axis, at the height",
        _chain(zc, centre, model.evaluate(zc, "solid")),
    )
    model.define("solid", dc, _mul(zc, K_HAT))
    d.given("Seen from the apex it is at", _eq(dc, _mul(zc, K_HAT)))
    tensor = _Tensor(r"I_cone")
    integral = sp.Integral(_mul(density, _Kernel(_sub(rvec, dc)), jac), *limits)
    model.define("solid", tensor, integral)
    value = model.evaluate(integral, "solid").applyfunc(sp.factor)
    d.step(
        "About the centre of mass the tensor is the integral of 2.60 with r⃗ − d⃗_c for r⃗; the "
        "parallel-axis theorem gives the same from the tensor about the apex:",
        _chain(tensor, integral, _sub(apex, _mul(M, _Kernel(dc))), sp.ImmutableMatrix(value)),
    )
    d.function("solid_cone", value, (M, _R, _H))


# ---- the unit as printed ------------------------------------------------------------------------


def _printed() -> tuple[Printed, ...]:
    ra, va, ma = _ra(), _va(), _ma()
    x, y, z = (_xa(c) for c in (_X, _Y, _Z))
    wx, wy, wz = (_omega(c) for c in (_X, _Y, _Z))
    r2 = _Comp(_r, _a) ** 2
    lab = (_X, _Y, _Z)

    def p(number: str, latex: str, eq: Any, note: str = "") -> Printed:
        return Printed(number, "rigid_body", latex, eq, note)

    rows = [_add(*(_mul(_I(a, b), _omega(b)) for b in lab)) for a in lab]
    return (
        p("2.43", r"\vec{v}_a = \vec{\omega} \times \vec{r}_a", _eq(va, Cross(W, ra))),
        p(
            "2.44",
            r"\therefore \vec{L} = \sum_{a} m_{a} r_{a}^{2} \vec{\omega} - \sum_{a} m_{a} "
            r"(\vec{r}_{a} \cdot \vec{\omega}) \vec{r}_{a}",
            _eq(L, _sub(_sum_a(_mul(ma, r2, W)), _sum_a(_mul(ma, _Dot(ra, W), ra)))),
        ),
        p(
            "2.45",
            r"\therefore L_x = \sum_a m_a (r_a^2 - x_a^2) \omega_x - \sum_a m_a x_a y_a "
            r"\omega_y - \sum_a m_a x_a z_a \omega_z",
            _eq(
                _Lc(_X),
                _add(
                    _sum_a(_mul(ma, _sub(r2, x**2), wx)),
                    _neg(_sum_a(_mul(ma, x, y, wy))),
                    _neg(_sum_a(_mul(ma, x, z, wz))),
                ),
            ),
        ),
        p(
            "2.46",
            r"I_{xx} = \sum_{a} m_a (r_a^2 - x_a^2) = \sum_{a} m_a (y_a^2 + z_a^2)",
            _chain(_I(_X, _X), _sum_a(_mul(ma, _sub(r2, x**2))), _sum_a(_mul(ma, y**2 + z**2))),
        ),
        p(
            "2.47",
            r"I_{yy} = \sum m_a (r_a^2 - y_a^2) = \sum m_a (z_a^2 + x_a^2)",
            _chain(_I(_Y, _Y), _sum_a(_mul(ma, _sub(r2, y**2))), _sum_a(_mul(ma, z**2 + x**2))),
            "the sums are printed without their index a",
        ),
        p(
            "2.48",
            r"I_{zz} = \sum_{a}^{a} m_a (r_a^2 - z_a^2) = \sum_{a}^{a} m_a (x_a^2 + y_a^2)",
            _chain(_I(_Z, _Z), _sum_a(_mul(ma, _sub(r2, z**2))), _sum_a(_mul(ma, x**2 + y**2))),
            "the scan prints each Σ_a with a stray superscript a, read as Σ_a",
        ),
        p(
            "2.49",
            r"I_{xy} = -\sum_{a} m_a x_a y_a = I_{yx}",
            _chain(_I(_X, _Y), _neg(_sum_a(_mul(ma, x, y))), _I(_Y, _X)),
        ),
        p(
            "2.50",
            r"I_{yz} = -\sum_{\alpha} m_{\alpha} y_{\alpha} z_{\alpha} = I_{zy}",
            _chain(_I(_Y, _Z), _neg(_sum_a(_mul(ma, y, z))), _I(_Z, _Y)),
            "the unit's first 2.50; the scan prints the particle index a as α",
        ),
        p(
            "2.49",
            r"I_{zx} = -\sum_{\alpha} m_{\alpha} z_{\alpha} x_{\alpha} = I_{xz}",
            _chain(_I(_Z, _X), _neg(_sum_a(_mul(ma, z, x))), _I(_X, _Z)),
            "the unit numbers this 2.49 a second time; the scan prints the index a as α",
        ),
        p(
            "2.50",
            r"L_{x} = I_{xx}\omega_{x} + I_{xy}\omega_{y} + I_{xz}\omega_{z} \\ "
            r"L_{y} = I_{yx}\omega_{x} + I_{yy}\omega_{y} + I_{yz}\omega_{z} \\ "
            r"L_{z} = I_{zx}\omega_{x} + I_{zy}\omega_{y} + I_{zz}\omega_{z}",
            _eq(sp.ImmutableMatrix(_components("L")), sp.ImmutableMatrix(rows)),
            "the unit's second 2.50 (three displayed lines, joined here), the one 2.51 cites",
        ),
        p(
            "2.51",
            r"L_i = \sum_{i} I_{ij} \omega_j",
            _eq(_Lc(_i), _Sum(_mul(_I(_i, _j), _omega(_j)), _i)),
            '"where i = 1, 2, 3"; as printed the sum binds i, leaving j free on the right',
        ),
        p(
            "2.52",
            r"T = \sum_{a} \frac{1}{2} m_{a} v_{a}^{2}",
            _eq(T, _sum_a(_mul(_HALF, ma, _Comp(_v, _a) ** 2))),
        ),
        p(
            "2.53",
            r"\therefore T = \frac{1}{2} \vec{\omega} \cdot \vec{L}",
            _eq(T, _mul(_HALF, _Dot(W, L))),
        ),
        p(
            "2.54",
            r"T = \frac{1}{2} \sum_{i} \omega_{i} L_{i} = \frac{1}{2} \sum_{i,j} I_{ij} "
            r"\omega_{i} \omega_{j}",
            _chain(
                T,
                _mul(_HALF, _Sum(_mul(_omega(_i), _Lc(_i)), _i)),
                _mul(_HALF, _Sum(_mul(_I(_i, _j), _omega(_i), _omega(_j)), _i, _j)),
            ),
        ),
        p(
            "2.55",
            r"T = \frac{1}{2} \left[ I_{xx} \omega_x^2 + I_{yy} \omega_y^2 + I_{zz} \omega_z^2 "
            r"+ 2I_{xy} \omega_x \omega_y + 2I_{yz} \omega_y \omega_z + 2I_{zx} \omega_z "
            r"\omega_x \right]",
            _eq(
                T,
                _mul(
                    _HALF,
                    _add(
                        *(_mul(_I(a, a), _omega(a) ** 2) for a in lab),
                        *(
                            _mul(2, _I(a, b), _omega(a), _omega(b))
                            for a, b in ((_X, _Y), (_Y, _Z), (_Z, _X))
                        ),
                    ),
                ),
            ),
        ),
        p(
            "2.56",
            r"\therefore T = \frac{1}{2} I \omega^2",
            _eq(_at(T, x=0, y=0, z=OMEGA), _mul(_HALF, I_MOM, OMEGA**2)),
            "under the unit's condition before it (rotation about z: ω_z = ω, ω_x = ω_y = 0), "
            "written as the substitution; I is the moment about z (the unit's words after it)",
        ),
        p(
            "2.57",
            r"L_x = I_{xz}\omega_z,\ L_y = I_{yz}\omega_z\ \text{and}\ L_z = I_{zz}\omega_z",
            _eq(
                _at(sp.ImmutableMatrix(_components("L")), x=0, y=0),
                sp.ImmutableMatrix([_mul(_I(a, _Z), _omega(_Z)) for a in lab]),
            ),
            "the scan splits the line over two displays; under the same condition as 2.56 "
            "(ω_x = ω_y = 0), written as the substitution",
        ),
        p(
            "2.58",
            r"\vec{L} = m_1 \vec{r}_1 \times \vec{v}_1 + m_2 \vec{r}_2 \times \vec{v}_2",
            _eq(
                L,
                _add(_mul(_ma(1), Cross(_ra(1), _va(1))), _mul(_ma(2), Cross(_ra(2), _va(2)))),
            ),
        ),
        p(
            "2.59",
            r"\vec{L} = \vec{N}",
            _eq(L, N),
            "printed as it stands: no dot over L⃗",
        ),
        p(
            "2.60",
            r"\vec{I} = \begin{pmatrix} I_{xx} & I_{xy} & I_{xz} \\ I_{yx} & I_{yy} & I_{yz} \\ "
            r"I_{zx} & I_{zy} & I_{zz} \end{pmatrix}",
            _eq(IBAR, _tensor_matrix()),
            "the scan prints the tensor Ī (the text's \\overline{I}) with an arrow",
        ),
        p(
            "2.61",
            r"I_{xx} = \int \rho(\vec{r}) (r^2 - x^2) d\tau",
            _eq(_I(_X, _X), _BodyIntegral(_sub(_rr**2, _cx**2))),
        ),
        p(
            "2.62",
            r"I_{xy} = -\int \rho(\vec{r}) xy d\tau",
            _eq(_I(_X, _Y), _neg(_BodyIntegral(_mul(_cx, _cy)))),
        ),
        p(
            "2.63",
            r"\therefore \vec{L} = \vec{I} \cdot \vec{\omega}",
            _eq(L, _Dot(IBAR, W)),
            "the tensor Ī printed with an arrow",
        ),
        p(
            "2.64",
            r"T = \frac{1}{2}\vec{\omega} \cdot \vec{L} = \frac{1}{2}\vec{\omega} \cdot "
            r"\vec{I} \cdot \vec{\omega}",
            _chain(T, _mul(_HALF, _Dot(W, L)), _mul(_HALF, _Dot(W, _Dot(IBAR, W)))),
            "the tensor Ī printed with an arrow",
        ),
        p(
            "2.65",
            r"L = I_i \omega_i",
            _eq(L_MAG, _mul(_I(_i), _omega(_i))),
            "as printed: L without index (the magnitude |L⃗|), i free on the right only",
        ),
        p(
            "2.66",
            r"T = \frac{1}{2} [I_i \omega_1^2 + I_2 \omega_2^2 + I_3 \omega_3^2]",
            _eq(
                T,
                _mul(
                    _HALF,
                    _add(
                        _mul(_I(_i), _omega(1) ** 2),
                        _mul(_I(2), _omega(2) ** 2),
                        _mul(_I(3), _omega(3) ** 2),
                    ),
                ),
            ),
        ),
    )


#: The unit's numbered equations 2.43–2.66 as printed (each formula; 2.49 and 2.50 twice, as the
#: unit numbers them), in this derivation's notation.
PRINTED: tuple[Printed, ...] = _printed()
