"""The Earth as a rigid body (issue 25): the unit's free symmetric top (2.83) and its torque
theory applied to the Earth, derived and checked. Not a range of the unit's equations but the
unit's theory applied: :func:`poinsot.derive.applied` lists it, beside the unit's topics.

Coverage
--------
* Euler's free nutation: the unit's Ω = (I₁ − I₃)ω₃/I₁ (2.83) with I₁ = A, I₃ = C, ω₃ = ω is
  Ω = −H/(1 − H) ω (rad/s), H = (C − A)/C the dynamical flattening; its period
  T_E = 2π/|Ω| = ((1 − H)/H) T_sid, T_sid = 2π/ω the sidereal day (s).
* The gravity-gradient torque of a distant point mass M at R⃗ = r r̂ on a body with its centre
  of mass at the origin: each mass element's torque expanded to second order in ρ/r, summed,
  N⃗ = (3GM/r³) r̂ × (I⃗·r̂) (N·m), and for a symmetric body I⃗ = A 1 + (C − A) k̂k̂ᵀ MacCullagh's
  N⃗ = (3GM/r³)(C − A)(r̂·k̂)(r̂ × k̂).
* Its average over a Kepler orbit of semi-major axis a, eccentricity e and normal n̂ (time
  average through r²ḟ = h): ⟨1/r³⟩ = 1/(a³(1 − e²)^{3/2}) (1/m³) and
  N̄⃗ = −(3GM(C − A)/(2a³(1 − e²)^{3/2}))(n̂·k̂)(n̂ × k̂), of size ∝ sin ε cos ε.
* The precession it drives: with L⃗ ≈ Cω k̂, k̂ turns about n̂ at
  ψ̇ = −(3/2)(GM/(a³(1 − e²)^{3/2}))(H/ω) cos ε (rad/s, retrograde), and for the Moon, whose
  orbit is inclined by i and whose node regresses, the factor (1 − (3/2) sin² i) from the
  average over the node; the luni-solar rate is the Sun's part plus the Moon's.

Model
-----
Ecliptic components: n̂ = (0, 0, 1) the ecliptic pole (the Sun's orbit normal), the body's
figure axis k̂ = (sin ε sin ψ, −sin ε cos ψ, cos ε) with ψ(t) its longitude (the unit's
precession angle φ of 2.98), the distant mass on its orbit at true anomaly f:
r̂ = (cos f, sin f, 0), r = a(1 − e²)/(1 + e cos f), h = √(μa(1 − e²)), T = 2π√(a³/μ)
(μ = G(M_E + M) the orbit's own constant). A mass element dm at ρ⃗ = λ(ρ₁, ρ₂, ρ₃) carries
the bookkeeping λ: a value holding λ is checked to second order in it (its Taylor polynomial
of degree 2, then λ = 1), which is what "to second order in ρ/r" means; every other step is
an exact identity. Integrals (over f, over the node's longitude Ω_N) are evaluated in closed
form (∫cosᵖ f sinᵠ f over a period).
Once the precession is reached, ψ̇ is the rate found (the *solution* model, as in the
torque-free top's derivation): the step that uses it checks that this motion satisfies
(dL⃗/dt) = N̄⃗.

Results
-------
``result`` holds "2.83" (Ω for the Earth), "Euler period", "element torque",
"gravity-gradient torque", "MacCullagh", "mean inverse cube", "mean torque", "mean torque
size", "precession rate", "Moon factor" and "luni-solar rate". Numeric forms
(:meth:`~poinsot.derive.Derivation.lambdify`), SI units: ``"2.83"`` Ω(H, ω) (rad/s); ``"Euler
period"`` T_E(H, ω) (s); ``"mean inverse cube"`` ⟨1/r³⟩(a, e) (1/m³); ``"precession rate"``
ψ̇(GM, a, e, H, ω, ε) (rad/s); ``"luni-solar rate"`` ψ̇(GM_Sun, a_Sun, e_Sun, GM_Moon, a_Moon,
e_Moon, i, H, ω, ε) (rad/s).
``python/tests/test_derive_rigid_earth.py`` checks them against :class:`poinsot.RigidEarth`.
"""

from __future__ import annotations

from typing import Any

import sympy as sp
from sympy.physics.vector import dynamicsymbols
from sympy.printing.pretty.stringpict import prettyForm

from ._core import (
    Cross,
    Derivation,
    Dot,
    DtFix,
    Unit,
    Vec,
    VectorModel,
    _Notation,
    dot_value,
    in_order,
)
from ._core import add as _add
from ._core import eq as _eq
from ._core import mul as _mul
from ._core import power as _pow
from .euler_equations import _Cross, _trig_reduce

__all__ = ["derive"]

# ---- the notation --------------------------------------------------------------------------

t = sp.Symbol("t")
I1, I3, w3 = sp.symbols("I_1 I_3 omega_3", positive=True)
A, C, H, w = sp.symbols("A C H omega", positive=True)
Om = sp.Symbol("Omega")
T_E, T_sid = sp.symbols("T_E T_sid", positive=True)
G, M, dm, r, a, mu, h, T = sp.symbols("G M dm r a mu h T", positive=True)
e = sp.Symbol("e", nonnegative=True)
f, eps, inc, node = sp.symbols("f epsilon i Omega_N", real=True)
psi = dynamicsymbols("psi")
psi_dot = psi.diff(t)
lam = sp.Symbol("lambda_bookkeeping")
rho_c = sp.symbols("rho_1 rho_2 rho_3", real=True)
GM_S, a_S, e_S, GM_M, a_M, e_M = sp.symbols(
    "GM_Sun a_Sun e_Sun GM_Moon a_Moon e_Moon", positive=True
)
psi_S, psi_M = (x.diff(t) for x in dynamicsymbols("psi_Sun psi_Moon"))

rho, R, dI, Iv, N, N_bar = Vec("rho"), Vec("R"), Vec("I_dm"), Vec("I"), Vec("N"), Vec("N_avg")
r_hat, k_hat, n_hat, n_moon, one = Unit("r"), Unit("k"), Unit("n"), Unit("n_Moon"), Vec("1")

TWO_PI = _mul(2, sp.pi)
THREE_HALVES = sp.UnevaluatedExpr(sp.Rational(3, 2))


def _frac(n: Any, den: Any) -> Any:
    """n/den as written."""
    return sp.Mul(n, sp.Pow(den, -1, evaluate=False), evaluate=False)


def _orbit_mean() -> Any:
    """a³(1 − e²)^{3/2} as written."""
    return _mul(_pow(a, 3), _pow(_add(1, -(e**2)), sp.Rational(3, 2)))


class _Norm(_Notation):
    """The magnitude |X⃗| of a vector, unevaluated (the model gives √(X⃗·X⃗)); raised to a power
    it prints |X⃗|³."""

    nargs = 1

    def _latex(self, printer: Any, exp: Any = None) -> str:
        body = r"\left|" + printer._print(self.args[0]) + r"\right|"
        return body if exp is None else body + "^{" + str(exp) + "}"

    def _pretty(self, printer: Any) -> Any:
        inner = printer._print(self.args[0]).render(wrap_line=False)
        return prettyForm("|" + inner + "|")


# ---- the model -----------------------------------------------------------------------------

_K = sp.Matrix([sp.sin(eps) * sp.sin(psi), -sp.sin(eps) * sp.cos(psi), sp.cos(eps)])
_RHAT = sp.Matrix([sp.cos(f), sp.sin(f), 0])
_RHO = lam * sp.Matrix(rho_c)
_NMOON = sp.Matrix([sp.sin(inc) * sp.sin(node), -sp.sin(inc) * sp.cos(node), sp.cos(inc)])
_R_ORBIT = a * (1 - e**2) / (1 + e * sp.cos(f))


#: the precession rate the torque drives (the solution model's ψ̇); H through the context
def _rate(gm: Any, a_: Any, e_: Any) -> Any:
    """−(3/2)(GM/(a³(1 − e²)^{3/2}))(H/ω) cos ε, evaluated."""
    return (
        -sp.Rational(3, 2) * gm / (a_**3 * (1 - e_**2) ** sp.Rational(3, 2)) * H / w * sp.cos(eps)
    )


_PSI_RATE = _rate(G * M, a, e)


def _double_factorial(n: int) -> int:
    return 1 if n <= 0 else n * _double_factorial(n - 2)


def _period_integral(term: Any, var: Any, lo: Any, hi: Any) -> Any:
    """∫ term d(var) from lo to hi: over a full period [0, 2π] a monomial c·cosᵖ·sinᵠ of
    ``var`` by the closed form 2π (p − 1)!!(q − 1)!!/(p + q)!! (zero unless p and q are even),
    anything else by ``sympy.integrate`` (whose general search takes minutes here)."""
    coeff, rest = term.as_independent(var, as_Add=False)
    powers = rest.as_powers_dict() if rest != 1 else {}
    p = powers.pop(sp.cos(var), 0)
    q = powers.pop(sp.sin(var), 0)
    if (
        (lo, hi) == (0, 2 * sp.pi)
        and not powers
        and all(isinstance(n, (int, sp.Integer)) and n >= 0 for n in (p, q))
    ):
        p, q = int(p), int(q)
        if p % 2 or q % 2:
            return sp.Integer(0)
        num = _double_factorial(p - 1) * _double_factorial(q - 1)
        return coeff * 2 * sp.pi * sp.Rational(num, _double_factorial(p + q))
    return sp.integrate(term, (var, lo, hi))  # pragma: no cover - not reached by this derivation


class _Model(VectorModel):
    """Ecliptic components (module docstring); integrals evaluated, λ to second order, ψ̇ the
    precession rate."""

    def __call__(self, x: Any) -> Any:
        out = self._ev(sp.sympify(x))
        fix = lambda v: self._second_order(sp.sympify(v).subs(psi_dot, _PSI_RATE))
        return out.applyfunc(fix) if isinstance(out, sp.MatrixBase) else fix(out)

    @staticmethod
    def _second_order(v: Any) -> Any:
        if not v.has(lam):
            return v
        terms = [v.subs(lam, 0), sp.diff(v, lam).subs(lam, 0), sp.diff(v, lam, 2).subs(lam, 0) / 2]
        return sp.Add(*terms)

    def _ev(self, x: Any) -> Any:
        if isinstance(x, sp.UnevaluatedExpr):
            return self._ev(x.args[0])
        if isinstance(x, sp.Integral):
            (var, lo, hi) = x.limits[0]
            body = self._ev(x.function)

            def integrate(v: Any) -> Any:
                v = sp.expand(sp.sympify(v).subs({psi_dot: _PSI_RATE, r: _R_ORBIT}))
                return sp.Add(*(_period_integral(u, var, lo, hi) for u in sp.Add.make_args(v)))

            return body.applyfunc(integrate) if isinstance(body, sp.MatrixBase) else integrate(body)
        if isinstance(x, _Norm):
            v = sp.Matrix(self._ev(x.args[0]))
            return sp.sqrt(sp.factor(_trig_reduce(sp.expand((v.T * v)[0, 0]))))
        if isinstance(x, Dot):
            return dot_value(*(sp.Matrix(self._ev(y)) for y in x.args))
        if x.has(sp.Integral, _Norm, sp.UnevaluatedExpr) and isinstance(x, (sp.Add, sp.Mul)):
            return in_order(x, [self._ev(y) for y in x.args])
        if x.has(sp.Integral, _Norm, sp.UnevaluatedExpr) and isinstance(x, sp.Pow):
            return self._ev(x.base) ** x.exp
        return super()._ev(x)


def _model() -> _Model:
    inertia = A * sp.eye(3) + (C - A) * _K * _K.T
    mac = 3 * G * M / r**3 * (C - A) * (_RHAT.T * _K)[0, 0] * _RHAT.cross(_K)
    m = _Model(
        vectors={
            rho: _RHO,
            R: r * _RHAT,
            r_hat: _RHAT,
            k_hat: _K,
            n_hat: sp.Matrix([0, 0, 1]),
            n_moon: _NMOON,
            one: sp.eye(3),
            Iv: inertia,
            dI: dm * ((_RHO.T * _RHO)[0, 0] * sp.eye(3) - _RHO * _RHO.T),
            N: mac,
        },
        dt_fix=lambda v: sp.Matrix(v).diff(t),
        scalars={
            Om: (I1 - I3) * w3 / I1,
            T_E: -2 * sp.pi / ((I1 - I3) * w3 / I1),
            T_sid: 2 * sp.pi / w,
            h: sp.sqrt(mu * a * (1 - e**2)),
            T: 2 * sp.pi * sp.sqrt(a**3 / mu),
            psi_S: _rate(GM_S, a_S, e_S),
            psi_M: _rate(GM_M, a_M, e_M) * (1 - sp.Rational(3, 2) * sp.sin(inc) ** 2),
        },
    )
    # N̄⃗: the orbit average, by definition (the step that names it checks the closed form)
    m.vectors = dict(m.vectors)
    m.vectors[N_bar] = m._ev(_frac(sp.Integral(_mul(N, _frac(r**2, h)), (f, 0, 2 * sp.pi)), T))
    return m


# ---- the derivation ------------------------------------------------------------------------


def derive() -> Derivation:
    """Builds and checks the derivation of the rigid Earth's free nutation and precession."""
    d = Derivation(
        "rigid_earth",
        "The Earth as a rigid body: Euler's free nutation and the precession of the equinoxes",
        summary=(
            "The unit's free symmetric top (2.83) with the Earth's moments gives Euler's period "
            "(1 − H)/H sidereal days; the gravity-gradient torque of a distant mass on the bulge "
            "(MacCullagh), averaged over a Kepler orbit and, for the Moon, over its regressing "
            "node, gives the luni-solar precession of the equinoxes."
        ),
        model=_model(),
        context={I1: A, I3: C, w3: w, H: (C - A) / C},
    )
    # (a) Euler's free nutation
    d.given(
        "The unit's free symmetric top (derivation torque_free_top): ω₁ and ω₂ turn at "
        "Ω = (I₁ − I₃)ω₃/I₁ (2.83, rad/s).",
        _eq(Om, _frac(_mul(I1 - I3, w3), I1)),
    )
    d.step(
        "The Earth is that top: I₁ = I₂ = A, I₃ = C > A, spinning at ω₃ = ω, once a sidereal "
        "day. With the dynamical flattening H = (C − A)/C, (C − A)/A = H/(1 − H): Ω is negative, "
        "the wobble prograde.",
        [
            _eq(Om, -_mul(_frac(C - A, A), w)),
            _eq(-_mul(_frac(C - A, A), w), -_mul(_frac(H, 1 - H), w)),
        ],
        "2.83",
    )
    d.step(
        "Euler's period, 2π/|Ω| (s), in sidereal days T_sid = 2π/ω: A/(C − A) = (1 − H)/H of "
        "them — 304.5 for the IERS H = 0.003273795.",
        [
            _eq(T_E, -_frac(TWO_PI, Om)),
            _eq(-_frac(TWO_PI, Om), _mul(_frac(A, C - A), _frac(TWO_PI, w))),
            _eq(_mul(_frac(A, C - A), _frac(TWO_PI, w)), _mul(_frac(1 - H, H), T_sid)),
        ],
        "Euler period",
    )
    d.function("2.83", -H / (1 - H) * w, (H, w))
    d.function("Euler period", (1 - H) / H * 2 * sp.pi / w, (H, w))

    # (b) the gravity-gradient torque
    d.given(
        "A point mass M at R⃗ = r r̂ pulls a mass element dm of the body at ρ⃗ (from its centre of "
        "mass) with GM dm (R⃗ − ρ⃗)/|R⃗ − ρ⃗|³; the element's torque about the centre of mass is "
        "ρ⃗ × that, and ρ⃗ × ρ⃗ = 0⃗.",
        _eq(Vec("N_dm"), _frac(_mul(G, M, dm, Cross(rho, R)), _pow(_Norm(_add(R, -rho)), 3))),
    )
    d.step(
        "To second order in ρ/r (the Earth's radius over the distance of the Sun or the Moon): "
        "a first-order term, and the second-order term written with the element's inertia "
        "tensor dI⃗ = dm(ρ² 1 − ρ⃗ρ⃗ᵀ).",
        [
            _eq(
                _frac(_mul(G, M, dm, Cross(rho, R)), _pow(_Norm(_add(R, -rho)), 3)),
                _add(
                    _frac(_mul(G, M, dm, Cross(rho, R)), _pow(r, 3)),
                    _frac(_mul(3, G, M, dm, Dot(rho, R), Cross(rho, R)), _pow(r, 5)),
                ),
            ),
            _eq(
                _add(
                    _frac(_mul(G, M, dm, Cross(rho, R)), _pow(r, 3)),
                    _frac(_mul(3, G, M, dm, Dot(rho, R), Cross(rho, R)), _pow(r, 5)),
                ),
                _add(
                    _frac(_mul(G, M, dm, Cross(rho, R)), _pow(r, 3)),
                    _mul(_frac(_mul(3, G, M), _pow(r, 3)), _Cross(r_hat, Dot(dI, r_hat))),
                ),
            ),
        ],
        "element torque",
    )
    d.given(
        "Summed over the body, the first term vanishes (Σ dm ρ⃗ = 0⃗ about the centre of mass) "
        "and the elements' tensors add up to the body's, I⃗ = Σ dI⃗: the gravity-gradient torque.",
        _eq(N, _mul(_frac(_mul(3, G, M), _pow(r, 3)), _Cross(r_hat, Dot(Iv, r_hat)))),
        "gravity-gradient torque",
    )
    d.step(
        "For a symmetric body, I⃗ = A 1 + (C − A) k̂k̂ᵀ (k̂ its figure axis): MacCullagh's torque, "
        "zero when the mass is on the axis or in the equator.",
        _eq(
            _mul(_frac(_mul(3, G, M), _pow(r, 3)), _Cross(r_hat, Dot(Iv, r_hat))),
            _mul(_frac(_mul(3, G, M), _pow(r, 3)), C - A, Dot(r_hat, k_hat), Cross(r_hat, k_hat)),
        ),
        "MacCullagh",
    )

    # the orbit average
    inv_cube = sp.Pow(_orbit_mean(), -1, evaluate=False)
    d.step(
        "On a Kepler orbit, r = a(1 − e²)/(1 + e cos f) and r² df/dt = h = √(μa(1 − e²)) over a "
        "period T = 2π√(a³/μ): the time average of 1/r³ is an integral over the true anomaly f.",
        [
            _eq(
                _frac(
                    sp.Integral(
                        _mul(sp.Pow(r**3, -1, evaluate=False), _frac(r**2, h)), (f, 0, 2 * sp.pi)
                    ),
                    T,
                ),
                inv_cube,
            ),
        ],
        "mean inverse cube",
    )
    d.function("mean inverse cube", 1 / (a**3 * (1 - e**2) ** sp.Rational(3, 2)), (a, e))
    mean_coeff = _frac(_mul(3, G, M, C - A), _mul(2, _orbit_mean()))
    d.step(
        "The torque averaged the same way, with r̂ = cos f p̂ + sin f q̂ in the orbit's plane "
        "(normal n̂): only the part of k̂ along n̂ averages out of (r̂·k̂) r̂, leaving a torque "
        "along n̂ × k̂, the line of the equinoxes.",
        [
            _eq(N_bar, _frac(sp.Integral(_mul(N, _frac(r**2, h)), (f, 0, 2 * sp.pi)), T)),
            _eq(
                _frac(sp.Integral(_mul(N, _frac(r**2, h)), (f, 0, 2 * sp.pi)), T),
                -_mul(mean_coeff, Dot(n_hat, k_hat), Cross(n_hat, k_hat)),
            ),
        ],
        "mean torque",
    )
    d.step(
        "With ε the obliquity, the angle between k̂ and n̂: n̂·k̂ = cos ε,",
        _eq(Dot(n_hat, k_hat), sp.cos(eps)),
    )
    d.step(
        "and |n̂ × k̂|² = sin² ε,",
        _eq(Dot(Cross(n_hat, k_hat), Cross(n_hat, k_hat)), sp.sin(eps) ** 2),
    )
    d.step(
        "so the mean torque's size is ∝ sin ε cos ε (N·m) — none for an upright or a lying axis.",
        _eq(Dot(N_bar, N_bar), _pow(_mul(mean_coeff, sp.sin(eps), sp.cos(eps)), 2)),
        "mean torque size",
    )

    # (c) the precession
    d.given(
        "The spin's angular momentum is L⃗ ≈ Cω k̂ (the precession's own angular velocity is "
        "~1e-12 of ω), and (dL⃗/dt)_fix = N̄⃗ (2.67) with the mean torque.",
        _eq(_mul(C, w, DtFix(k_hat)), N_bar),
    )
    rate = -_mul(THREE_HALVES, _frac(_mul(G, M), _orbit_mean()), _frac(H, w), sp.cos(eps))
    d.step(
        "The axis keeps its obliquity and turns about n̂: k̂ = (sin ε sin ψ, −sin ε cos ψ, cos ε) "
        "in ecliptic axes, dk̂/dt = ψ̇ n̂ × k̂. This motion, with the rate ψ̇ below, satisfies "
        "Cω dk̂/dt = N̄⃗ (checked).",
        [
            _eq(_mul(C, w, DtFix(k_hat)), _mul(C, w, _mul(psi_dot, Cross(n_hat, k_hat)))),
            _eq(_mul(C, w, _mul(psi_dot, Cross(n_hat, k_hat))), N_bar),
        ],
    )
    d.step(
        "The precession rate (rad/s): negative, the equinoxes move westward, ∝ H/ω and cos ε.",
        _eq(psi_dot, rate),
        "precession rate",
    )
    d.function(
        "precession rate",
        -sp.Rational(3, 2) * G / (a**3 * (1 - e**2) ** sp.Rational(3, 2)) * H / w * sp.cos(eps),
        (G, a, e, H, w, eps),
    )
    d.step(
        "The Moon's orbit is inclined by i to the ecliptic and its node regresses in 18.6 years: "
        "averaged over the node's longitude Ω_N, n̂_Moon = (sin i sin Ω_N, −sin i cos Ω_N, cos i) "
        "acts as n̂ with the factor (1 − (3/2) sin² i).",
        _eq(
            _frac(
                sp.Integral(_mul(Dot(n_moon, k_hat), Cross(n_moon, k_hat)), (node, 0, 2 * sp.pi)),
                TWO_PI,
            ),
            _mul(
                _add(1, -_mul(THREE_HALVES, sp.sin(inc) ** 2)),
                Dot(n_hat, k_hat),
                Cross(n_hat, k_hat),
            ),
        ),
        "Moon factor",
    )
    both = _mul(
        -THREE_HALVES,
        _frac(H, w),
        sp.cos(eps),
        _add(
            _frac(GM_S, _mul(_pow(a_S, 3), _pow(1 - e_S**2, sp.Rational(3, 2)))),
            _mul(
                _add(1, -_mul(THREE_HALVES, sp.sin(inc) ** 2)),
                _frac(GM_M, _mul(_pow(a_M, 3), _pow(1 - e_M**2, sp.Rational(3, 2)))),
            ),
        ),
    )
    d.step(
        "The torques add: the luni-solar precession is the Sun's rate plus the Moon's (GM the "
        "body's own, a and e of its geocentric orbit).",
        _eq(_add(psi_S, psi_M), both),
        "luni-solar rate",
    )
    d.function(
        "luni-solar rate",
        -sp.Rational(3, 2)
        * H
        / w
        * sp.cos(eps)
        * (
            GM_S / (a_S**3 * (1 - e_S**2) ** sp.Rational(3, 2))
            + (1 - sp.Rational(3, 2) * sp.sin(inc) ** 2)
            * GM_M
            / (a_M**3 * (1 - e_M**2) ** sp.Rational(3, 2))
        ),
        (GM_S, a_S, e_S, GM_M, a_M, e_M, inc, H, w, eps),
    )
    return d
