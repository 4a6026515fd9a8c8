"""The heavy symmetric top, derived: the unit's 2.102–2.121.

Covers
------
From the kinetic energy 2.100 with I₁ = I₂ and the Euler-angle rates 2.99 (the unit's z-x-z
angles φ, θ, ψ; the pivot at the origin, the centre of mass at distance l along body axis 3,
gravity −g along the fixed Z′ axis, so V = m g l cos θ):

* the Lagrangian 2.102, its cyclic coordinates φ and ψ and the conserved momenta
  p_ψ = ∂L/∂ψ̇ = I₃ω₃ (2.103) and p_φ = ∂L/∂φ̇ (2.104), both from Lagrange's equations;
* the energy E = T + V (2.105, the Jacobi integral of a Lagrangian without t), in momenta
  (2.106–2.108), the reduced energy E′ and the effective potential V(θ) (2.109–2.110);
* the quadrature 2.111–2.112 and the cubic f(u) = (1 − u²)(α − βu) − (b − au)² of u = cos θ
  (Goldstein §5.7, with α = 2E′/I₁, β = 2mgl/I₁, a = p_ψ/I₁, b = p_φ/I₁), whose roots in
  [−1, 1] are the turning points;
* ∂V/∂θ (2.113), the steady-precession condition 2.114–2.116, its roots 2.117 (corrected: the
  unit prints p_φ² under the root where p_ψ² belongs), the two exact precession rates, the
  minimum spin 2.118–2.119 and the fast-top approximations 2.120 (corrected: the unit's factor
  ½ is wrong) and 2.121;
* the sleeping top: its stability ω₃² > 4 m g l I₁ / I₃², from the curvature of V at θ = 0 and
  from the double root u = 1 of the cubic.

Model
-----
Every step is checked in one model of the heavy top (:class:`_TopModel`), in four stages:

1. *definitions*: ω₁, ω₂, ω₃ (2.99), T (2.100), L = T − mgl cos θ, E = T + mgl cos θ,
   E′ = E − p_ψ²/(2I₃), V(θ) (2.110), t(θ) = ∫dθ/θ̇, u = cos θ, the constants of the cubic,
   the unit's b, the precession rate φ̇₀ (2.106 at θ₀) and the two roots of the
   steady-precession condition (solved by sympy in the model, not typed in) are substituted;
   partial and time derivatives are taken in the variables in which each quantity is defined
   (∂L/∂φ̇ at fixed θ, θ̇, ψ̇; ∂V/∂θ at fixed p_φ, p_ψ); a value at a point (``Subs``) is taken
   after cancelling, so that a removable 0/0 (V at θ = 0 of the sleeping top) is removed;
2. *coordinates*: the rates φ̇, ψ̇ are replaced by the momenta (the Legendre map p = ∂L/∂q̇,
   solved by sympy), θ̇ and p_ψ by positive symbols, and p_φ and mgl by a labelling of every top
   by the angle θ₀ at which its effective potential is least: p_φ = p_ψ cos θ₀ + I₁ φ̇₀ sin²θ₀
   with φ̇₀ = p_ψ(1 + σr)/(2 I₁ cos θ₀), r > 0 and the branch σ = ±1 (σ² = 1), and mgl solved
   from ∂V/∂θ(θ₀) = 0. (p_φ, mgl) ↔ (θ₀, r, σ) is a change of variables, so an identity in the
   unit's variables stays one, while the steady-precession equations (true only at θ₀) hold
   too; a printed ± is the branch σ of the top;
3. *roots*: the argument of every fractional power is put in canonical form and factored, so
   that √(θ̇²) = θ̇ and √(p_ψ² − 4 mgl I₁ cos θ₀) = p_ψ r;
4. *canonical form*: the value becomes N/D, polynomials in the sines and cosines of its angles,
   σ and the other symbols, N reduced modulo sin² + cos² = 1 and σ² = 1, D rationalised free of
   sines and σ, common factors cancelled (:func:`_canonical`). Equal values give the same
   expression, so checking a step is a subtraction.

An inequality a ≥ b (2.118, 2.119) is written max(a, b) = a and checked by proving a ≥ b in the
model (a p_ψ > 0 top);
an approximation "for a fast top" (2.120, 2.121) is the leading term of the exact root as
p_ψ → ∞ at fixed mgl, I₁, θ₀. The derivation builds and checks in about 1 s.

Results
-------
``2.102`` … ``2.117``, ``2.119``, ``2.120``, ``2.121`` (the unit's numbers; 2.117 and 2.120 in
their corrected forms), with numeric forms (:meth:`Derivation.lambdify`) for ``2.102``,
``2.103``, ``2.104``, ``2.105``, ``2.109``, ``2.110``, ``2.113``, ``2.119``, ``2.120``,
``2.121``, the two exact steady-precession rates ``"2.117 slow"`` and ``"2.117 fast"`` (rad/s),
the cubic ``"cubic"`` and the sleeping-top threshold ``"sleeping"`` (rad/s). Quantities are SI:
moments of inertia in kg m², mgl in N m (J), angles in rad, rates in rad/s, momenta in
kg m²/s, energies in J.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.physics.vector import dynamicsymbols
from sympy.polys.domains import QQ
from sympy.polys.fields import field
from sympy.printing.pretty.stringpict import prettyForm

from ._core import Derivation, Printed
from ._core import add as _add
from ._core import eq as _eq
from ._core import mul as _mul
from ._core import power as _pow

__all__ = ["derive", "PRINTED"]

# ---- notation ------------------------------------------------------------------------------

#: what a :class:`_Named` symbol shows: name → (LaTeX, plain text)
_SHOWN: dict[str, tuple[str, str]] = {}


class _Named(sp.Symbol):
    """A symbol shown as the unit writes it but distinct by name (e.g. Goldstein's b = p_φ/I₁
    beside the unit's b of 2.116, or the precession rate φ̇₀)."""

    def _latex(self, printer: Any) -> str:
        return _SHOWN[self.name][0]

    def _pretty(self, printer: Any) -> Any:
        return prettyForm(_SHOWN[self.name][1])


def _named(name: str, latex: str, text: str) -> _Named:
    _SHOWN[name] = (latex, text)
    return _Named(name)


class _Partial(sp.Function):
    """∂f/∂x, or ∂ⁿf/∂xⁿ as ``_Partial(f, x, n)``, unevaluated (the model differentiates, in the
    variables in which f is defined)."""

    nargs = (2, 3)

    def _order(self) -> str:
        return "" if len(self.args) == 2 else str(self.args[2])

    def _latex(self, printer: Any) -> str:
        f, x = (printer._print(a) for a in self.args[:2])
        n = self._order()
        up, down = ("", "") if not n else ("^{" + n + "}", "^{" + n + "}")
        return r"\frac{\partial" + up + " " + f + r"}{\partial " + x + down + "}"

    def _pretty(self, printer: Any) -> Any:
        f, x = (printer._print(a).render(wrap_line=False) for a in self.args[:2])
        n = {"": "", "2": "²", "3": "³"}.get(self._order(), self._order())
        return prettyForm(f"∂{n}{f}/∂{x}{n}")


class _Bracket(sp.Function):
    """[x]: square brackets as the unit prints them (the model drops them)."""

    nargs = 1

    def _latex(self, printer: Any) -> str:
        return r"\left[" + printer._print(self.args[0]) + r"\right]"

    def _pretty(self, printer: Any) -> Any:
        return prettyForm(*printer._print(self.args[0]).parens("[", "]"))


class _PlusMinus(sp.Function):
    """a ± b: either root (the model reads ± as the branch sign σ of the top it describes)."""

    nargs = 2

    def _latex(self, printer: Any) -> str:
        a, b = self.args
        return printer._print(a) + r" \pm " + printer._print(b)

    def _pretty(self, printer: Any) -> Any:
        a, b = (printer._print(x) for x in self.args)
        return prettyForm(*a.right(" ± ", b))


class _Larger(sp.Function):
    """max(a, b), unevaluated (the model evaluates it where it proves which is larger)."""

    nargs = 2

    def _latex(self, printer: Any) -> str:
        a, b_ = (printer._print(x) for x in self.args)
        return r"\max\left(" + a + ", " + b_ + r"\right)"

    def _pretty(self, printer: Any) -> Any:
        a, b_ = (printer._print(x) for x in self.args)
        inner = prettyForm(*a.right(", ", b_))
        return prettyForm(*prettyForm(*inner.parens()).left("max"))


def _at_least(a: Any, b_: Any) -> Any:
    """The inequality a ≥ b as an equation, max(a, b) = a (the machinery checks equations; the
    model proves a ≥ b to evaluate the max)."""
    return _eq(_Larger(a, b_), a)


def _frac(num: Any, den: Any) -> Any:
    return _mul(num, _pow(den, -1))


HALF = sp.Rational(1, 2)
t = dynamicsymbols._t
theta, phi, psi = dynamicsymbols("theta phi psi")
theta_dot, phi_dot, psi_dot = (q.diff(t) for q in (theta, phi, psi))
u = dynamicsymbols("u")
u_dot = u.diff(t)
I1, I2, I3 = sp.symbols("I_1 I_2 I_3")
mgl = sp.Symbol("mgl")
omega1, omega2, omega3 = sp.symbols("omega_1 omega_2 omega_3")
T, L, E = sp.symbols("T L E")
E_red = sp.Symbol("E'")
p_phi = _named("p_phi", r"p_{\phi}", "p_φ")
p_psi = _named("p_psi", r"p_{\psi}", "p_ψ")
V = sp.Function("V")
t_of = sp.Function("t")
f = sp.Function("f")
theta0 = sp.Symbol("theta_0")
b = sp.Symbol("b")  # the unit's b = p_φ − p_ψ cos θ₀ (2.116)
alpha, beta = sp.symbols("alpha beta")
a_G = _named("a_G", "a", "a")  # Goldstein's a = p_ψ/I₁
b_G = _named("b_G", "b", "b")  # Goldstein's b = p_φ/I₁ (not the unit's b)
phid0 = _named("phidot_0", r"\dot{\phi}_{0}", "φ̇₀")
phid_plus = _named("phidot_0+", r"\dot{\phi}_{0+}", "φ̇₀₊")
phid_minus = _named("phidot_0-", r"\dot{\phi}_{0-}", "φ̇₀₋")
phid_fast = _named("phidot_0fast", r"\dot{\phi}_{0\,\mathrm{fast}}", "φ̇₀ fast")
phid_slow = _named("phidot_0slow", r"\dot{\phi}_{0\,\mathrm{slow}}", "φ̇₀ slow")
u3 = sp.Symbol("u_3")  # the third root of the sleeping top's cubic

c, s = sp.cos(theta), sp.sin(theta)
c0, s0 = sp.cos(theta0), sp.sin(theta0)

#: the standing assumption of the symmetric top
CONTEXT = {I2: I1}

# the unit's definitions, shown by the derivation's givens and used by the model
OMEGA = {
    omega1: _add(_mul(theta_dot, sp.cos(psi)), _mul(phi_dot, sp.sin(theta), sp.sin(psi))),
    omega2: _add(-_mul(theta_dot, sp.sin(psi)), _mul(phi_dot, sp.sin(theta), sp.cos(psi))),
    omega3: _add(psi_dot, _mul(phi_dot, c)),
}
T_DEF = _mul(HALF, _add(_mul(I1, omega1**2), _mul(I2, omega2**2), _mul(I3, omega3**2)))
L_DEF = _add(T, -_mul(mgl, c))
E_DEF = _add(T, _mul(mgl, c))
E_RED_DEF = _add(E, -_frac(p_psi**2, _mul(2, I3)))


def _v_of(x: Any) -> Any:
    """2.110 at the angle x."""
    return _add(
        _frac(_pow(_add(p_phi, -_mul(p_psi, sp.cos(x))), 2), _mul(2, I1, sp.sin(x) ** 2)),
        _mul(mgl, sp.cos(x)),
    )


def _f_of(x: Any) -> Any:
    """Goldstein's cubic at x."""
    return _add(
        _mul(_add(1, -(x**2)), _add(alpha, -_mul(beta, x))), -_pow(_add(b_G, -_mul(a_G, x)), 2)
    )


THIRD = _add(_frac(a_G**2, beta), -1)  # u₃ of the sleeping top

GOLDSTEIN = {
    alpha: _frac(_mul(2, E_red), I1),
    beta: _frac(_mul(2, mgl), I1),
    a_G: _frac(p_psi, I1),
    b_G: _frac(p_phi, I1),
}

# ---- the model -------------------------------------------------------------------------------


def _fraction(e: Any, ring: Any, gens: dict[Any, Any]) -> tuple[Any, Any]:
    """``e`` (a rational function of ``gens``) as numerator and denominator in ``ring``, without
    cancelling on the way (one gcd at the end is cheaper than one per sum)."""
    if e in gens:
        return gens[e], ring.one
    if e.is_Rational:
        return ring(QQ(int(e.p), int(e.q))), ring.one
    if isinstance(e, sp.Add):
        num, den = ring.zero, ring.one
        for a in e.args:
            n, d = _fraction(a, ring, gens)
            if d == den:
                num += n
            else:
                num, den = num * d + n * den, den * d
        return num, den
    if isinstance(e, sp.Mul):
        num, den = ring.one, ring.one
        for a in e.args:
            n, d = _fraction(a, ring, gens)
            num, den = num * n, den * d
        return num, den
    if isinstance(e, sp.Pow) and e.exp.is_Integer:
        n, d = _fraction(e.base, ring, gens)
        k = int(e.exp)
        return (n**k, d**k) if k >= 0 else (d ** (-k), n ** (-k))
    raise TypeError(f"not a rational function of the generators: {e}")


#: the branch sign σ = ±1 of the model (σ² = 1 is one of the relations of :func:`_canonical`)
SIGMA = sp.Symbol("sigma_branch")


def _canonical(expr: Any) -> Any:
    """The same value in a canonical form: a quotient N/D of polynomials (sparse, exact) in the
    sines and cosines of its angles, the branch sign σ = (−1)ᵏ and its other atoms, with D free
    of every sine and of σ (rationalised by conjugates), N reduced modulo sin² + cos² = 1 and
    σ² = 1, common factors cancelled and D's leading coefficient 1. Equal values give the same
    expression, so the check of an equation in this form is a subtraction."""
    expr = sp.sympify(expr)
    if expr.is_number or expr.has(sp.Integral):
        return expr
    angles = sorted({a.args[0] for a in expr.atoms(sp.sin, sp.cos)}, key=sp.default_sort_key)
    rep: dict[Any, Any] = {}
    roots: list[tuple[Any, Any]] = []  # (g, g²) for each relation g² = ...
    for k, ang in enumerate(angles):
        sv, cv = sp.Dummy(f"s{k}"), sp.Dummy(f"c{k}")
        rep[sp.sin(ang)], rep[sp.cos(ang)] = sv, cv
        roots.append((sv, 1 - cv**2))
    if expr.has(SIGMA):
        rep[SIGMA] = sp.Dummy("sigma")
        roots.append((rep[SIGMA], sp.S.One))
    e = expr.xreplace(rep)
    opaque = [
        x
        for x in e.atoms(sp.Pow, sp.Derivative, AppliedUndef, sp.Function)
        if not (isinstance(x, sp.Pow) and x.exp.is_Integer)
    ]
    back = {v: k for k, v in rep.items()}
    inner = {x: sp.Dummy(f"x{k}") for k, x in enumerate(sorted(opaque, key=sp.default_sort_key))}
    e = e.xreplace(inner)
    back.update({v: k.xreplace(back) for k, v in inner.items()})
    first = [g for g, _ in roots]
    rest = (e.free_symbols | {x for _, sq in roots for x in sq.free_symbols}) - set(first)
    gens = first + sorted(rest, key=sp.default_sort_key)
    ring = field(gens, QQ)[0].ring
    try:
        num, den = _fraction(e, ring, {g: ring(g) for g in gens})
    except TypeError:  # an atom this form does not cover (a float, π): left to the zero test
        return expr
    rels = [ring(g) ** 2 - ring(sq) for g, sq in roots]
    if rels:
        num, den = num.rem(rels), den.rem(rels)
        for g, sq in roots:
            gg = ring(g)
            d1 = den.diff(gg)
            if d1:
                d0 = den - d1 * gg
                num = (num * (d0 - d1 * gg)).rem(rels)
                den = (d0**2 - d1**2 * ring(sq)).rem(rels)
    _, num, den = num.cofactors(den)
    lc = den.LC
    num, den = num.quo_ground(lc), den.quo_ground(lc)
    return (num.as_expr() / den.as_expr()).xreplace(back)


class _TopModel:
    """The heavy top's model (see the module docstring): definitions, then coordinates
    (momenta, the θ₀-parametrisation, positive θ̇ and p_ψ), then reduced square roots."""

    def __init__(self) -> None:
        self._values: dict[Any, Any] = {}
        self.symbols: dict[Any, Any] = {**OMEGA, T: T_DEF, L: L_DEF, E: E_DEF, E_red: E_RED_DEF}
        self.symbols.update(GOLDSTEIN)
        self.symbols[b] = _add(p_phi, -_mul(p_psi, c0))
        self.symbols[u3] = THIRD
        self.functions: dict[Any, Callable[..., Any]] = {
            V: _v_of,
            f: _f_of,
            u.func: lambda _t: c,
            t_of: lambda _x: sp.Integral(1 / theta_dot, theta),
        }
        # T of 2.100 with 2.99, its sines and cosines of ψ reduced (exact; checks get shorter).
        self.symbols[T] = _canonical(self.unfold(T).subs(CONTEXT))
        # The Legendre map: solve p_φ = ∂L/∂φ̇, p_ψ = ∂L/∂ψ̇ (linear) for the rates.
        lag = self.unfold(L)
        rates = [phi_dot, psi_dot]
        moms = sp.Matrix([sp.diff(lag, q) for q in rates])
        jac = moms.jacobian(rates)
        rest = moms - jac * sp.Matrix(rates)
        sol = jac.LUsolve(sp.Matrix([p_phi, p_psi]) - rest)
        self.legendre = {q: _canonical(x) for q, x in zip(rates, sol)}
        # φ̇₀: the precession rate 2.106 (the Legendre φ̇) at θ = θ₀.
        self.symbols[phid0] = self.legendre[phi_dot].subs(theta, theta0)
        # The steady-precession condition: ∂V/∂θ = 0 at θ₀ with p_φ = p_ψ cos θ₀ + I₁ φ̇ sin²θ₀;
        # its two roots φ̇₀₊ ≥ φ̇₀₋ (for p_ψ > 0) and, for a fast top, their leading terms.
        rate = sp.Dummy("rate")
        dv0 = sp.diff(self.unfold(V(theta)), theta).subs(theta, theta0)
        cond = sp.numer(_canonical(dv0.subs(p_phi, p_psi * c0 + I1 * rate * s0**2)))
        roots = list(sp.roots(sp.Poly(cond, rate)))
        probe = {p_psi: 3, mgl: 1, I1: 1, theta0: sp.Rational(1, 2)}
        roots.sort(key=lambda e: float(e.subs(probe)))
        self.symbols[phid_minus], self.symbols[phid_plus] = roots
        eps = sp.Symbol("epsilon", positive=True)
        for sym, root in ((phid_slow, roots[0]), (phid_fast, roots[1])):
            lead = root.subs(p_psi, 1 / eps).as_leading_term(eps).subs(eps, 1 / p_psi)
            self.symbols[sym] = lead
        # Coordinates: every top parametrised by θ₀ (the least V), r ≥ 0 and the branch σ.
        self.p_psi = sp.Symbol("p_psi", positive=True)
        self.theta_dot = sp.Symbol("thetadot", positive=True)
        self.r = sp.Symbol("r", positive=True)
        steady_rate = self.p_psi * (1 + SIGMA * self.r) / (2 * I1 * c0)
        p_phi_of = self.p_psi * c0 + I1 * steady_rate * s0**2
        dv0 = dv0.subs({p_phi: p_phi_of, p_psi: self.p_psi})
        lin = sp.Poly(sp.numer(_canonical(dv0)), mgl).all_coeffs()  # linear in mgl
        self.params = {
            p_phi: p_phi_of,
            mgl: sp.factor(_canonical(-lin[1] / lin[0])),
            p_psi: self.p_psi,
            theta_dot: self.theta_dot,
        }

    # stage 1
    def unfold(self, e: Any, keep: frozenset[Any] = frozenset()) -> Any:
        """``e`` with the definitions substituted and the derivatives taken."""
        if e in keep:
            return e
        if e in self.symbols:
            return self.unfold(self.symbols[e], keep)
        if isinstance(e, AppliedUndef) and e.func in self.functions:
            args = [self.unfold(a, keep) for a in e.args]
            return self.unfold(self.functions[e.func](*args), keep)
        if isinstance(e, _Partial):
            return sp.diff(self.unfold(e.args[0], keep), *e.args[1:])
        if isinstance(e, sp.Derivative):
            inner = self.unfold(e.expr, keep)
            return e if inner == e.expr else sp.diff(inner, *e.variable_count)
        if isinstance(e, sp.Subs):
            # one variable after the other (in the order given), each into the canonical form,
            # so that a removable singularity (0/0) at the point is removed first
            inner = self.unfold(e.expr, keep | set(e.variables))
            for var, at in zip(e.variables, e.point):
                inner = _canonical(inner).subs(var, at)
            return self.unfold(inner, keep)
        if e.args:
            return e.func(*(self.unfold(a, keep) for a in e.args))
        return e

    # stage 2
    def coordinates(self, e: Any) -> Any:
        """``e`` in the model's coordinates."""
        e = e.xreplace(self.legendre).xreplace(self.params).subs(CONTEXT)
        e = e.replace(_PlusMinus, lambda x, y: x + SIGMA * y)
        return e.replace(_Bracket, lambda x: x)

    # stage 3
    def roots(self, e: Any) -> Any:
        """``e`` with the argument of every fractional power reduced."""
        if not e.args:
            return e
        args = [self.roots(a) for a in e.args]
        if isinstance(e, sp.Pow) and e.exp.is_Rational and not e.exp.is_Integer:
            return sp.Pow(sp.factor(_canonical(args[0])), e.exp)
        return e.func(*args)

    def value(self, e: Any) -> Any:
        """The value of the notation ``e`` in the model (remembered: a chain a = b = c asks for
        b twice)."""
        e = sp.sympify(e)
        if e not in self._values:
            self._values[e] = _canonical(self.roots(self.coordinates(self.unfold(e))))
        return self._values[e]

    def at_least(self, x: Any, y: Any) -> bool:
        """Whether x ≥ y (values of the model): x − y reduces to a manifestly non-negative
        expression, or x ≥ 0 and x² − y² ≥ 0 (y real). Moments of inertia are positive."""
        pos = {I1: sp.Symbol("I1p", positive=True), I3: sp.Symbol("I3p", positive=True)}
        diff = sp.factor(_canonical(x - y)).xreplace(pos)
        if diff == 0 or diff.is_nonnegative:
            return True
        square = sp.factor(_canonical(x**2 - y**2)).xreplace(pos)
        return bool(sp.factor(x).xreplace(pos).is_nonnegative and square.is_nonnegative)

    def __call__(self, e: Any) -> Any:
        e = sp.sympify(e)
        if isinstance(e, _Larger):
            # the larger, where the model proves which it is; else the max stays unevaluated
            x, y = (self.value(a) for a in e.args)
            if self.at_least(x, y):
                return x
            if self.at_least(y, x):
                return y
            return _Larger(x, y)
        return self.value(e)


# ---- the equations -----------------------------------------------------------------------------
# Built once, shown by the derivation's steps and, where the unit prints the same equation, by
# its transcription in PRINTED.

THD2 = theta_dot**2
SPIN = _add(psi_dot, _mul(phi_dot, c))  # ω₃ by 2.99
T101 = _add(_mul(HALF, I1, _add(THD2, _mul(phi_dot**2, s**2))), _mul(HALF, I3, _pow(SPIN, 2)))
LAG = _add(*T101.args, -_mul(mgl, c))  # 2.102
PPHI = _add(_mul(I1, phi_dot, s**2), _mul(I3, SPIN, c))  # 2.104
E105 = _add(
    _mul(HALF, I1, THD2),
    _mul(HALF, I1, phi_dot**2, s**2),
    _mul(HALF, I3, _pow(SPIN, 2)),
    _mul(mgl, c),
)
RATE106 = _frac(_add(p_phi, -_mul(p_psi, c)), _mul(I1, s**2))
PP2 = _frac(p_psi**2, _mul(2, I3))
E107 = _add(_mul(HALF, I1, THD2), _mul(HALF, I1, phi_dot**2, s**2), PP2, _mul(mgl, c))
VEFF = _frac(_pow(_add(p_phi, -_mul(p_psi, c)), 2), _mul(2, I1, s**2))
E108 = _add(_mul(HALF, I1, THD2), VEFF, PP2, _mul(mgl, c))
E109 = _add(_mul(HALF, I1, THD2), VEFF, _mul(mgl, c))
ROOT111 = _pow(_mul(_frac(2, I1), _Bracket(_add(E_red, -V(theta)))), HALF)
DV113 = _add(
    _frac(_mul(_add(p_phi, -_mul(p_psi, c)), _add(p_psi, -_mul(p_phi, c))), _mul(I1, s**3)),
    -_mul(mgl, s),
)
COND114 = _eq(
    _mul(_add(p_phi, -_mul(p_psi, c0)), _add(p_psi, -_mul(p_phi, c0))), _mul(mgl, I1, s0**4)
)
RATE115 = _frac(_add(p_phi, -_mul(p_psi, c0)), _mul(I1, s0**2))
B116 = _add(p_phi, -_mul(p_psi, c0))
QUAD116 = _add(_mul(b**2, c0), -_mul(b, p_psi, s0**2), _mul(mgl, I1, s0**4))


def _roots117(momentum: Any) -> Any:
    """The right-hand side of 2.117 with ``momentum`` squared under the root."""
    disc = _add(1, -_frac(_mul(4, mgl, I1, c0), momentum**2))
    return _mul(_frac(_mul(p_psi, s0**2), _mul(2, c0)), _Bracket(_PlusMinus(1, _pow(disc, HALF))))


MIN_SPIN = _mul(_frac(2, I3), _pow(_mul(mgl, I1, c0), HALF))  # 2.119


def _fast120(two: int) -> list[Any]:
    """2.120 as a chain, with the denominator's factor ``two`` (2 as printed, 1 derived)."""
    k = [] if two == 1 else [two]
    fast = _frac(p_psi, _mul(*k, I1, c0))
    return [_eq(phid_fast, fast), _eq(fast, _frac(_mul(I3, omega3), _mul(*k, I1, c0)))]


SLOW121 = [
    _eq(phid_slow, _frac(mgl, p_psi)),
    _eq(_frac(mgl, p_psi), _frac(mgl, _mul(I3, omega3))),
]

# ---- the derivation --------------------------------------------------------------------------

#: plain symbols for the numeric forms: θ (rad), θ̇, φ̇, ψ̇ (rad/s), u = cos θ
NUMERIC = dict(
    zip((theta_dot, phi_dot, psi_dot, theta, u), sp.symbols("theta_dot phi_dot psi_dot theta u"))
)


def _numeric(expr: Any) -> Any:
    """``expr`` with the functions of time replaced by plain symbols (:data:`NUMERIC`) and the
    notation's brackets dropped, ready for lambdify."""
    return expr.replace(_Bracket, lambda x: x).xreplace(NUMERIC)


def _branch(expr: Any, sign: int) -> Any:
    """``expr`` with every a ± b taken as a + b (``sign`` = 1) or a − b (``sign`` = −1)."""
    return expr.replace(_PlusMinus, lambda x, y: x + sign * y)


def derive() -> Derivation:
    """The heavy symmetric top, 2.102–2.121 (see the module docstring), built and checked.

    Returns
    -------
    Derivation
        ``name`` "heavy_top"; ``result`` keyed "2.102" … "2.121" (2.117 and 2.120 corrected);
        numeric forms as listed in the module docstring.

    Raises
    ------
    PoinsotError
        If a step does not hold in the model (it cannot, unless the code is changed).
    """
    d = Derivation(
        "heavy_top",
        "The heavy symmetric top (2.102–2.121)",
        summary=(
            "A symmetric top (I₁ = I₂) spins about its symmetry axis 3 with its tip fixed at the "
            "origin; its centre of mass is at distance l along axis 3 and gravity pulls along "
            "−Z′, so its potential energy is mgl cos θ. In the unit's z-x-z Euler angles φ "
            "(precession), θ (nutation) and ψ (spin) its Lagrangian has two cyclic coordinates; "
            "the two conserved momenta and the energy reduce the motion to θ alone in an "
            "effective potential V(θ), whose minimum is steady precession. Each step is checked "
            "in a model where the rates become momenta and every top is labelled by the angle θ₀ "
            "at which its V is least (see poinsot.derive.heavy_top)."
        ),
        model=_TopModel(),
        context=dict(CONTEXT),
    )
    # -- the Lagrangian and its constants of motion ----------------------------------------
    d.given("The body components of ω in Euler angles (2.99): ω₁ ...", _eq(omega1, OMEGA[omega1]))
    d.given("... ω₂ ...", _eq(omega2, OMEGA[omega2]))
    d.given(
        "... and the spin ω₃ (the unit prints ω₃ = ω_ξ; it is ω_ζ, see its errata).",
        _eq(omega3, OMEGA[omega3]),
    )
    d.given("The kinetic energy in principal axes (2.100).", _eq(T, T_DEF))
    t_mid = _add(_mul(HALF, I1, _add(omega1**2, omega2**2)), _mul(HALF, I3, omega3**2))
    d.step(
        "For a symmetric top I₂ = I₁; by 2.99, ω₁² + ω₂² = θ̇² + φ̇² sin²θ (the angle ψ drops "
        "out): T is 2.101.",
        [_eq(T, t_mid), _eq(t_mid, T101)],
    )
    d.given(
        "The centre of mass stands l cos θ above the tip, so the potential energy is mgl cos θ "
        "and the Lagrangian is L = T − mgl cos θ.",
        _eq(L, L_DEF),
    )
    d.step("With 2.101, the Lagrangian of the heavy top (2.102).", _eq(L, LAG), "2.102")
    d.step(
        "L contains neither φ nor ψ (they are cyclic), so Lagrange's equations "
        "d/dt(∂L/∂q̇) = ∂L/∂q give d/dt(∂L/∂φ̇) = d/dt(∂L/∂ψ̇) = 0: the momenta p_φ = ∂L/∂φ̇ and "
        "p_ψ = ∂L/∂ψ̇ are constants of the motion.",
        [_eq(_Partial(L, phi), _Partial(L, psi)), _eq(_Partial(L, psi), 0)],
    )
    d.step(
        "Differentiate 2.102 by ψ̇: p_ψ is I₃ times the spin ω₃ of 2.99 (2.103).",
        [
            _eq(p_psi, _Partial(L, psi_dot)),
            _eq(_Partial(L, psi_dot), _mul(I3, SPIN)),
            _eq(_mul(I3, SPIN), _mul(I3, omega3)),
        ],
        "2.103",
    )
    d.step(
        "Differentiate 2.102 by φ̇ (2.104): p_φ is the angular momentum about the vertical Z′.",
        [_eq(p_phi, _Partial(L, phi_dot)), _eq(_Partial(L, phi_dot), PPHI)],
        "2.104",
    )
    jacobi = _add(
        _mul(theta_dot, _Partial(L, theta_dot)),
        _mul(phi_dot, _Partial(L, phi_dot)),
        _mul(psi_dot, _Partial(L, psi_dot)),
        -L,
    )
    d.step(
        "L does not contain t, so Jacobi's integral Σ q̇ ∂L/∂q̇ − L is conserved. T is "
        "quadratic in the rates, so it is 2T − L = T + mgl cos θ: the total energy E = T + V, "
        "the third constant of the motion.",
        [_eq(jacobi, _add(T, _mul(mgl, c))), _eq(_add(T, _mul(mgl, c)), E)],
    )
    d.step("With 2.101, the energy (2.105).", _eq(E, E105), "2.105")
    # -- E′ and the effective potential ----------------------------------------------------
    d.step(
        "Use 2.103 in 2.104: the spin term is p_ψ cos θ.",
        _eq(p_phi, _add(_mul(I1, phi_dot, s**2), _mul(p_psi, c))),
    )
    d.step("Solve for the precession rate (2.106).", _eq(phi_dot, RATE106), "2.106")
    d.step("Use 2.103 in 2.105: the spin energy is p_ψ²/(2I₃) (2.107).", _eq(E, E107), "2.107")
    d.step("Substitute 2.106 in 2.107: E depends on θ and θ̇ alone (2.108).", _eq(E, E108), "2.108")
    d.step(
        "p_ψ²/(2I₃) is constant, so E′ = E − p_ψ²/(2I₃) is a constant too: the energy of a "
        "motion in θ alone, with kinetic energy ½I₁θ̇² in the effective potential V(θ) of 2.110 "
        "(2.109).",
        [
            _eq(E_red, _add(E, -PP2)),
            _eq(_add(E, -PP2), E109),
            _eq(E109, _add(_mul(HALF, I1, THD2), V(theta))),
        ],
        "2.109",
    )
    d.given(
        "The effective potential (2.110). It depends on θ alone, and is infinite at θ = 0 and "
        "θ = π unless p_φ = ±p_ψ.",
        _eq(V(theta), _v_of(theta)),
        "2.110",
    )
    d.step(
        "Solve 2.109 for θ̇ (2.111), taking the root θ̇ ≥ 0 as the unit does (θ̇ = −√… where θ "
        "decreases).",
        _eq(theta_dot, ROOT111),
        "2.111",
    )
    d.given(
        "Between turning points θ(t) is monotonic; its inverse t(θ) has dt/dθ = 1/θ̇.",
        _eq(t_of(theta), sp.Integral(_pow(theta_dot, -1), theta)),
    )
    d.step(
        "With 2.111, the time as a function of θ (2.112): an elliptic integral, as the cubic "
        "below shows.",
        _eq(t_of(theta), sp.Integral(_pow(ROOT111, -1), theta)),
        "2.112",
    )
    # -- the cubic in u = cos θ ------------------------------------------------------------
    d.given("Let u = cos θ (Goldstein §5.7).", _eq(u, c))
    for sym, text in (
        (alpha, "Four constants per unit I₁ (Goldstein's): α, from the energy E′ ..."),
        (beta, "... β, from the weight ..."),
        (a_G, "... a, from the spin momentum ..."),
        (b_G, "... and b, from the vertical momentum (not the unit's b of 2.116)."),
    ):
        d.given(text, _eq(sym, GOLDSTEIN[sym]))
    d.given("The cubic f(u).", _eq(f(u), _f_of(u)))
    d.step(
        "u̇ = −sin θ θ̇, so u̇² = (1 − u²)θ̇²; 2.111 and 2.110 with sin²θ = 1 − u² make it "
        "u̇² = f(u), a cubic in u: θ(t) is an elliptic function and 2.112 an elliptic integral.",
        [_eq(u_dot**2, _mul(_add(1, -(u**2)), THD2)), _eq(_mul(_add(1, -(u**2)), THD2), f(u))],
    )
    f_unit = _add(
        _mul(_add(1, -(u**2)), _add(_frac(_mul(2, E_red), I1), -_frac(_mul(2, mgl, u), I1))),
        -_frac(_pow(_add(p_phi, -_mul(p_psi, u)), 2), I1**2),
    )
    d.step("The cubic in the unit's constants.", _eq(f(u), f_unit))
    d.step(
        "At the upper pole u = 1, f = −(b − a)² ≤ 0 ...",
        _eq(sp.Subs(f(u), u, 1), -_pow(_add(b_G, -a_G), 2)),
    )
    d.step(
        "... and at the lower pole f = −(b + a)² ≤ 0, while f → +∞ as u → +∞ (β > 0). So the "
        "motion, where u̇² = f ≥ 0, lies between two roots u₁ ≤ u₂ in [−1, 1]: the turning points "
        "cos θ₂ and cos θ₁ of the unit's text after 2.114. The third root is u₃ ≥ 1.",
        _eq(sp.Subs(f(u), u, -1), -_pow(_add(b_G, a_G), 2)),
    )
    # -- steady precession -------------------------------------------------------------------
    d.step(
        "Differentiate 2.110 at fixed p_φ and p_ψ (2.113).",
        _eq(_Partial(V(theta), theta), DV113),
        "2.113",
    )
    d.step(
        "V is least at an angle θ₀ between 0 and π, where ∂V/∂θ = 0: a top started there with "
        "θ̇ = 0 keeps θ = θ₀ and precesses steadily.",
        _eq(sp.Subs(_Partial(V(theta), theta), theta, theta0), 0),
    )
    d.step("With 2.113 (2.114).", COND114, "2.114")
    d.step("At θ₀ the precession rate 2.106 is constant (2.115).", _eq(phid0, RATE115), "2.115")
    d.given("The unit's b (2.116).", _eq(b, B116))
    d.step(
        "With p_φ = b + p_ψ cos θ₀ the second factor of 2.114 is p_ψ sin²θ₀ − b cos θ₀ (2.116): "
        "a quadratic in b.",
        _eq(QUAD116, 0),
        "2.116",
    )
    d.step(
        "Solve 2.116 for b (2.117). The unit prints p_φ² under the root; it is p_ψ², from the "
        "coefficient p_ψ sin²θ₀ of b in 2.116 (2.118 then uses p_ψ², correctly).",
        [_eq(b, B116), _eq(B116, _roots117(p_psi))],
        "2.117",
    )
    quad = _add(_mul(I1, c0, phid0**2), -_mul(p_psi, phid0), mgl)
    d.step("By 2.115 and 2.116, b is ...", _eq(b, _mul(I1, phid0, s0**2)))
    d.step(
        "... so 2.116 divided by I₁ sin⁴θ₀ is the steady-precession condition, a quadratic in "
        "the precession rate.",
        _eq(quad, 0),
    )
    rates = _frac(
        _PlusMinus(p_psi, _pow(_add(p_psi**2, -_mul(4, mgl, I1, c0)), HALF)), _mul(2, I1, c0)
    )
    d.step(
        "Its two exact roots: at a given θ₀ and spin the top can precess steadily at two rates.",
        _eq(phid0, rates),
    )
    d.step(
        "Name them φ̇₀₊ (with +, the fast one for p_ψ > 0) and φ̇₀₋ (the slow one). Their sum is "
        "p_ψ/(I₁ cos θ₀) ...",
        _eq(_add(phid_plus, phid_minus), _frac(p_psi, _mul(I1, c0))),
    )
    d.step(
        "... and their product mgl/(I₁ cos θ₀): for θ₀ < π/2 both rates have the same sense, as "
        "the unit says, and for a fast top one of them is small.",
        _eq(_mul(phid_plus, phid_minus), _frac(mgl, _mul(I1, c0))),
    )
    disc = _add(p_psi**2, -_mul(4, mgl, I1, c0))
    # The slow root as the product over the fast one: the same number, without 2.117's 0/0 at
    # θ₀ = π/2 (where cos θ₀ is a round-off and the printed form loses every digit).
    slow = _frac(_mul(2, mgl), _add(p_psi, _pow(disc, HALF)))
    d.step(
        "Dividing the product by φ̇₀₊ gives the slow rate in a form that holds at θ₀ = π/2 too "
        "(a horizontal axis), where 2.117's numerator and denominator both vanish.",
        _eq(phid_minus, slow),
    )
    d.step(
        "The quantity under the root of 2.117 (times p_ψ²) is the square of I₁ cos θ₀ "
        "(φ̇₀₊ − φ̇₀₋): steady precession, with real rates, needs it ≥ 0.",
        _eq(disc, _pow(_mul(I1, c0, _add(phid_plus, -phid_minus)), 2)),
    )
    d.step(
        "So p_ψ² ≥ 4mglI₁ cos θ₀ (2.118), written as max(p_ψ², 4mglI₁ cos θ₀) = p_ψ². Below the "
        "horizontal (θ₀ > π/2, cos θ₀ < 0) it holds for any spin.",
        _at_least(p_psi**2, _mul(4, mgl, I1, c0)),
        "2.118",
    )
    d.step(
        "With p_ψ = I₃ω₃ (2.103): (I₃ω₃)² ≥ 4mglI₁ cos θ₀.",
        _at_least(_pow(_mul(I3, omega3), 2), _mul(4, mgl, I1, c0)),
    )
    d.step(
        "For ω₃ > 0 and θ₀ < π/2 the square root gives the minimum spin for steady precession, "
        "ω₃ ≥ (2/I₃)√(mglI₁ cos θ₀) (2.119). At equality the two rates coincide.",
        _at_least(omega3, MIN_SPIN),
        "2.119",
    )
    d.step(
        "A fast top (p_ψ² ≫ 4mglI₁ cos θ₀): √(1 − x) ≈ 1 − x/2, so with the + sign the bracket "
        "of 2.117 is ≈ 2, b ≈ p_ψ sin²θ₀/cos θ₀ and φ̇₀ = b/(I₁ sin²θ₀) ≈ p_ψ/(I₁ cos θ₀): the "
        "leading term of φ̇₀₊ (2.120). The unit prints p_ψ/(2I₁ cos θ₀); its factor ½ is wrong.",
        _fast120(1),
        "2.120",
    )
    d.step(
        "With the − sign the bracket is ≈ x/2 = 2mglI₁ cos θ₀/p_ψ², so b ≈ mglI₁ sin²θ₀/p_ψ and "
        "φ̇₀ ≈ mgl/p_ψ, the leading term of φ̇₀₋ (2.121): the slow precession usually seen.",
        SLOW121,
        "2.121",
    )
    # -- the sleeping top ------------------------------------------------------------------
    d.step(
        "The sleeping top spins upright, θ = 0; there 2.104 gives p_φ = p_ψ.",
        _eq(sp.Subs(_add(_mul(I1, phi_dot, s**2), _mul(p_psi, c)), theta, 0), p_psi),
    )
    vs = _add(_frac(_mul(p_psi**2, _add(1, -c)), _mul(2, I1, _add(1, c))), _mul(mgl, c))
    d.step(
        "With p_φ = p_ψ, (1 − cos θ)²/sin²θ = (1 − cos θ)/(1 + cos θ): V(θ) is finite at θ = 0, "
        "where it is mgl.",
        _eq(sp.Subs(V(theta), p_phi, p_psi), vs),
    )
    curv = sp.Subs(sp.Subs(_Partial(V(theta), theta, 2), p_phi, p_psi), theta, 0)
    curv_p = _frac(_add(p_psi**2, -_mul(4, mgl, I1)), _mul(4, I1))
    d.step(
        "Its curvature at θ = 0, with p_ψ = I₃ω₃ (2.103): the upright top is a minimum of V, and "
        "sleeps stably, exactly when ω₃² > 4mglI₁/I₃².",
        [
            _eq(curv, curv_p),
            _eq(curv_p, _frac(_add(_mul(I3**2, omega3**2), -_mul(4, mgl, I1)), _mul(4, I1))),
        ],
    )
    sleeping = _mul(_frac(2, I3), _pow(_mul(mgl, I1), HALF))
    d.step(
        "The threshold spin 2√(mglI₁)/I₃ is the minimum spin 2.119 at θ₀ = 0.",
        _eq(sp.Subs(MIN_SPIN, theta0, 0), sleeping),
    )
    d.step(
        "The same from the cubic: the sleeping top has b = a (p_φ = p_ψ) and α = β (E′ = mgl), "
        "so u = 1 is a double root of f.",
        _eq(
            sp.Subs(f(u), (b_G, alpha), (a_G, beta)),
            _mul(_pow(_add(1, -u), 2), _add(_mul(beta, _add(1, u)), -(a_G**2))),
        ),
    )
    d.given("Let u₃ = a²/β − 1 ...", _eq(u3, THIRD))
    d.step(
        "... for the other factor vanishes there: u₃ is the third root of f.",
        _eq(sp.Subs(_add(_mul(beta, _add(1, u)), -(a_G**2)), u, u3), 0),
    )
    d.step(
        "If u₃ > 1, f < 0 just below u = 1 and the axis cannot leave the vertical; if u₃ < 1 it "
        "falls to u = u₃. With 2.103, u₃ > 1 is again ω₃² > 4mglI₁/I₃².",
        _eq(
            _add(u3, -1),
            _frac(_add(_mul(I3**2, omega3**2), -_mul(4, mgl, I1)), _mul(2, mgl, I1)),
        ),
    )
    # -- numeric forms, from the equations above -------------------------------------------
    th, thd, phd, psd = (NUMERIC[q] for q in (theta, theta_dot, phi_dot, psi_dot))
    d.function("2.102", _numeric(LAG), (I1, I3, mgl, th, thd, phd, psd))
    d.function("2.103", _numeric(_mul(I3, SPIN)), (I3, th, phd, psd))
    d.function("2.104", _numeric(PPHI), (I1, I3, th, phd, psd))
    d.function("2.105", _numeric(E105), (I1, I3, mgl, th, thd, phd, psd))
    d.function("2.109", _numeric(E109), (I1, mgl, p_phi, p_psi, th, thd))
    d.function("2.110", _numeric(_v_of(theta)), (I1, mgl, p_phi, p_psi, th))
    d.function("2.113", _numeric(DV113), (I1, mgl, p_phi, p_psi, th))
    d.function("cubic", _numeric(f_unit), (I1, mgl, p_phi, p_psi, E_red, NUMERIC[u]))
    on_spin = {p_psi: _mul(I3, omega3)}
    d.function("2.117 slow", slow.xreplace(on_spin), (I1, I3, mgl, theta0, omega3))
    d.function("2.117 fast", _branch(rates, 1).xreplace(on_spin), (I1, I3, mgl, theta0, omega3))
    d.function("2.119", MIN_SPIN, (I1, I3, mgl, theta0))
    d.function("2.120", _fast120(1)[-1].rhs, (I1, I3, theta0, omega3))
    d.function("2.121", SLOW121[-1].rhs, (I3, mgl, omega3))
    d.function("sleeping", sleeping, (I1, I3, mgl))
    return d


# ---- the unit as printed -----------------------------------------------------------------------

_PSI = "the scan's capital Ψ̇ read as ψ̇"
_EMPTYSET = "the scan's p_∅ read as p_φ"

#: The unit's equations 2.102–2.121 as printed (LaTeX copied from the unit, without the
#: equation tag), each with the same equation in this module's notation. 2.117 and 2.120 are
#: wrong as printed; :func:`poinsot.derive.errata` finds them.
PRINTED: tuple[Printed, ...] = (
    Printed(
        "2.102",
        "heavy_top",
        r"L = \frac{1}{2}I_1(\dot{\theta}^2 + \dot{\phi}^2 sin^2\theta) + \frac{1}{2}I_3"
        r"(\dot{\Psi} + \dot{\phi} cos\theta)^2 - mgl cos\theta",
        _eq(L, LAG),
        _PSI,
    ),
    Printed(
        "2.103", "heavy_top", r"\therefore p_{\psi} = I_3\omega_3", _eq(p_psi, _mul(I3, omega3))
    ),
    Printed(
        "2.104",
        "heavy_top",
        r"p_{\phi} = \frac{\partial L}{\partial \dot{\phi}} = I_1\dot{\phi}\sin^2\theta + "
        r"I_3(\dot{\Psi} + \dot{\phi}\cos\theta)\cos\theta",
        [_eq(p_phi, _Partial(L, phi_dot)), _eq(_Partial(L, phi_dot), PPHI)],
        _PSI,
    ),
    Printed(
        "2.105",
        "heavy_top",
        r"\therefore E = \frac{1}{2} I_1 \dot{\theta}^2 + \frac{1}{2} I_1 \dot{\phi}^2 \sin^2 "
        r"\theta + \frac{1}{2} I_3 (\dot{\Psi} + \dot{\phi} \cos \theta)^2 + mgl \cos \theta",
        _eq(E, E105),
        _PSI,
    ),
    Printed(
        "2.106",
        "heavy_top",
        r"\therefore \dot{\phi} = \frac{p_{\emptyset} - p_{\psi}\cos\theta}{I_{1}\sin^{2}\theta}",
        _eq(phi_dot, RATE106),
        _EMPTYSET,
    ),
    Printed(
        "2.107",
        "heavy_top",
        r"E = \frac{1}{2}I_1\dot{\theta}^2 + \frac{1}{2}I_1\dot{\phi}^2\sin^2\theta + "
        r"\frac{p_{\psi}^2}{2I_3} + mgl\cos\theta",
        _eq(E, E107),
    ),
    Printed(
        "2.108",
        "heavy_top",
        r"\therefore E = \frac{1}{2}I_{1}\dot{\theta}^{2} + \frac{(p_{\emptyset} - "
        r"p_{\psi}\cos\theta)^{2}}{2I_{1}\sin^{2}\theta} + \frac{p_{\psi}^{2}}{2I_{3}} + "
        r"mgl\cos\theta",
        _eq(E, E108),
        _EMPTYSET,
    ),
    Printed(
        "2.109",
        "heavy_top",
        r"\therefore E' = E - \frac{p_{\psi}^{2}}{2I_{3}} = \frac{1}{2}I_{1}\dot{\theta}^{2} + "
        r"V(\theta)",
        [_eq(E_red, _add(E, -PP2)), _eq(_add(E, -PP2), _add(_mul(HALF, I1, THD2), V(theta)))],
    ),
    Printed(
        "2.110",
        "heavy_top",
        r"V(\theta) = \frac{(p_{\emptyset} - p_{\psi} \cos \theta)^2}{2I_1 \sin^2 \theta} + "
        r"mgl \cos \theta",
        _eq(V(theta), _v_of(theta)),
        _EMPTYSET,
    ),
    Printed(
        "2.111",
        "heavy_top",
        r"\dot{\theta} = \frac{d\theta}{dt} = \sqrt{\frac{2}{I_1} [E' - V(\theta)]}",
        _eq(theta_dot, ROOT111),
        "the middle member dθ/dt is θ̇ itself; the root is θ̇ ≥ 0",
    ),
    Printed(
        "2.112",
        "heavy_top",
        r"t(\theta) = \int \frac{d\theta}{\sqrt{\frac{2}{l_1} [E' - V(\theta)]}}",
        _eq(t_of(theta), sp.Integral(_pow(ROOT111, -1), theta)),
        "the scan's l₁ read as I₁",
    ),
    Printed(
        "2.113",
        "heavy_top",
        r"\frac{\partial V(\theta)}{\partial \theta} = \frac{(p_{\emptyset} - p_{\psi} \cos "
        r"\theta)(p_{\psi} - p_{\emptyset} \cos \theta)}{I_{1} \sin^{3} \theta} - mgl \sin \theta",
        _eq(_Partial(V(theta), theta), DV113),
        _EMPTYSET,
    ),
    Printed(
        "2.114",
        "heavy_top",
        r"(p_{\emptyset} - p_{\Psi} \cos\theta)(p_{\Psi} - p_{\emptyset} \cos\theta) = "
        r"mgll_1 \sin^4\theta",
        COND114,
        "the unit writes θ for the root θ₀ of this equation (its text and 2.116 call it θ₀); "
        "p_∅, p_Ψ read as p_φ, p_ψ and mgll₁ as mglI₁",
    ),
    Printed(
        "2.115",
        "heavy_top",
        r"\dot{ } \dot{ } \dot{ } \dot{ } \dot{ } \dot{ } o = \frac{p_{\emptyset} - p_{\Psi} "
        r"\cos \theta_0}{l_1 sin^2 \theta_0}",
        _eq(phid0, RATE115),
        "the scan garbles φ̇₀ into six detached dots and an o (the text: 'the precessional "
        "velocity of this uniform motion'); p_∅, p_Ψ read as p_φ, p_ψ and l₁ as I₁",
    ),
    Printed(
        "2.116",
        "heavy_top",
        r"b^{2}\cos\theta_{0} - bp_{\psi}\sin^{2}\theta_{0} + mglI_{1}\sin^{4}\theta_{0} = 0",
        _eq(QUAD116, 0),
    ),
    Printed(
        "2.117",
        "heavy_top",
        r"b = p_{\emptyset} - p_{\Psi} \cos \theta_{0} = \frac{p_{\Psi} \sin^{2} \theta_{0}}{2 "
        r"\cos \theta_{0}} \left[ 1 \pm \sqrt{1 - \frac{4 m g l I_{1} \cos \theta_{0}}"
        r"{p_{\emptyset}^{2}}} \right]",
        [_eq(b, B116), _eq(B116, _roots117(p_phi))],
        "p_Ψ read as p_ψ; the p_∅² under the root is kept as printed (p_φ²)",
    ),
    Printed(
        "2.118",
        "heavy_top",
        r"p_{\Psi}^2 \ge 4mglI_1cos\theta_0, for \theta_0 < \frac{\pi}{2}",
        _at_least(p_psi**2, _mul(4, mgl, I1, c0)),
        "an inequality a ≥ b, written max(a, b) = a; p_Ψ read as p_ψ; it holds for every θ₀ "
        "(for θ₀ > π/2 trivially)",
    ),
    Printed(
        "2.119",
        "heavy_top",
        r"\therefore \omega_3 \ge \frac{2}{I_3}\sqrt{mglI_1cos\theta_0}",
        _at_least(omega3, MIN_SPIN),
        "an inequality a ≥ b, written max(a, b) = a; for ω₃ > 0 and θ₀ < π/2, as the unit's "
        "2.118 assumes",
    ),
    Printed(
        "2.120",
        "heavy_top",
        r"\dot{\phi}_{0\,fast} = \frac{p_{\Psi}}{2I_1 cos\theta_0} = \frac{I_3 \omega_3}{2I_1 "
        r"cos\theta_0}",
        _fast120(2),
        "'=' read as the leading term for a fast top (p_ψ → ∞); p_Ψ read as p_ψ",
    ),
    Printed(
        "2.121",
        "heavy_top",
        r"\dot{\phi}_{0 \, slow} = \frac{mgl}{p_{\Psi}} = \frac{mgl}{l_3 \omega_3}",
        SLOW121,
        "'=' read as the leading term for a fast top (p_ψ → ∞); p_Ψ read as p_ψ and l₃ as I₃",
    ),
)
