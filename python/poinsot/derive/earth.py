"""The Earth, derived: motion in the rotating Earth frame and the falling body (the unit's
eqs. 2.29–2.42), carried one order further than the unit, to the southward deflection.

What it covers
--------------
- 2.29–2.31: Newton's law in the fixed frame, the equation of motion in the Earth's rotating
  frame (2.30, with the mass on the Coriolis term, which the unit lost), the effective gravity
  g_e = g − ω × (ω × r) (2.31); the centrifugal acceleration at the surface, the Earth's rate
  2π/(24·60·60) = 7.27e-5 rad/s (the unit prints 7.25e-5), ω²R and 2ω.
- 2.32–2.42: the falling body by successive approximation, in local axes x east, y north,
  z up along the plumb line at the ground, ω = ω (0, cos λ, sin λ) (2.33, λ the latitude, the
  unit's θ): zeroth order free fall (2.34), first order the eastward deflection
  x = ⅓ ω g t³ cos λ (2.38), t = √(2h/g) (2.41), x = ⅓ ω cos λ √(8h³/g) (2.42).
- One order further (numbers of this module, not the unit's): at order ω² the body is also
  deflected towards the equator, y = −⅓ ω² sin 2λ h²/g from the Coriolis force of the eastward
  velocity ("2.42a"), −5/12 ω² sin 2λ h²/g from the change of the centrifugal force with
  height ("2.42b"), together a southward deflection ¾ ω² sin 2λ h²/g ("2.42c"), measured from
  the foot of the plumb line hung from the release point, in the unit's uniform gravity.

The model (what a check computes)
---------------------------------
Every vector is a column of ENU components. ω = ω (0, cos λ, sin λ) is constant; a particle is
at r = R + ρ, R the ground point (constant components R_x, R_y, R_z), ρ = (x, y, z) functions
of time. (d/dt)_rot differentiates the components, (d/dt)_fix = (d/dt)_rot + ω × (2.14).
Newton's law 2.29, m (d²r/dt²)_fix = F + m g, is solved for ẍ, ÿ, z̈ and substituted (so a
step is checked for every motion the law allows), and the free body's acceleration a is that
with F = 0. g = −g ê_z + ω × (ω × R): ê_z is the plumb line at the ground, g the gravity a
pendulum measures there (m/s²). The successive approximations ρ_(n) (order ωⁿ) are computed by
the method itself: ρ_(n) is h ê_z plus the double integral from rest of
−g ê_z − 2 ω × ρ̇_(n−1) − ω × (ω × ρ_(n−1)), cut at order ωⁿ. The landing time T is the
positive root of z_(1)(T) = 0. Numbers the unit quotes are checked at the precision it prints
them (2.42's example: h = 100 m, λ = 45°, g = 9.81 m/s², which the unit does not state).

Results
-------
``"2.29"``–``"2.42"`` (the unit's numbers); the unit's unnumbered numbers ``"Earth's rate"``
(7.27e-5 rad/s), ``"centrifugal at the equator"`` (ω²R = 3.38e-2 m/s²), ``"Coriolis at the
poles"`` (2ω = 1.45e-4 s⁻¹) and ``"2.42 at 100 m"`` (1.548e-2 m); ``"2.42a"``, ``"2.42b"``,
``"2.42c"`` (this derivation's second order, not the unit's numbers). Numeric forms for the
bridge to the core (:meth:`Derivation.lambdify`): ``"2.33"`` ω (rad/s), ``"2.31"`` g_e and
``"centrifugal"`` −ω × (ω × r) at the surface (m/s²), ``"2.30"`` the Coriolis acceleration
−2 ω × v (m/s²), ``"2.41"`` the time of fall (s), ``"2.42"`` the eastward and ``"2.42a"``,
``"2.42b"``, ``"2.42c"`` the southward deflections (m, positive south).
"""

from __future__ import annotations

from functools import cache
from typing import Any

import sympy as sp
from sympy.physics.vector import dynamicsymbols

from ._core import Cross, Derivation, Dot, DtFix, DtRot, Printed, Unit, Vec, VectorModel
from ._core import add as _add
from ._core import eq as _eq
from ._core import mul as _mul

__all__ = ["derive", "PRINTED"]

# ---- notation -----------------------------------------------------------------------------------

t = dynamicsymbols._t
#: ω (rad/s), g (m/s²), h (m), m (kg), R (the Earth's radius, m), T (time of fall, s)
omega, g, h, m, R, T = sp.symbols("omega g h m R T", positive=True)
lam = sp.Symbol("lambda", real=True)  # the latitude (the unit's θ)
theta = sp.Symbol("theta", real=True)  # the unit's latitude, in transcriptions only
z_0, Z_0 = sp.symbols("z_0 Z_0", positive=True)  # the unit's release height (= h)
v_x, v_y, v_z = sp.symbols("v_x v_y v_z", real=True)
omega_x, omega_y, omega_z = sp.symbols("omega_x omega_y omega_z", real=True)
a_x, a_y, a_z = sp.symbols("a_x a_y a_z", real=True)
v_r = sp.Symbol("v_r", positive=True)  # a horizontal speed (m/s)
t1, t2 = sp.Symbol("t'"), sp.Symbol("t''")  # dummies of integration

W, r, Rv, rho, F, gv, g_e = (Vec(n) for n in ("omega", "r", "R", "rho", "F", "g", "g_e"))
a, v, vr = Vec("a"), Vec("v"), Vec("v_r")
rho0, rho1 = Vec("rho_(0)"), Vec("rho_(1)")


class _E(Unit):
    """The unit's ê_x, ê_y, ê_z (printed with the hat on the e only)."""

    def _latex(self, printer: Any) -> str:
        return r"\hat{e}_{" + self.name[-1] + "}"


ex, ey, ez = _E("e_x"), _E("e_y"), _E("e_z")

x, y, z = dynamicsymbols("x y z")  # the body's exact coordinates (m)
x0, y0, z0 = dynamicsymbols("x_(0) y_(0) z_(0)")
x1, y1, z1 = dynamicsymbols("x_(1) y_(1) z_(1)")
x2, y2, z2 = dynamicsymbols("x_(2) y_(2) z_(2)")
y_cor, y_cf = dynamicsymbols(r"y_{\mathrm{Cor}} y_{\mathrm{cf}}")


class _Dec(sp.Symbol):
    """A decimal number as the unit prints it (``_Dec("7.25e-5")`` is 7.25 × 10⁻⁵); exact (a
    rational) in the model."""

    def _latex(self, printer: Any) -> str:
        mant, _, exp = self.name.partition("e")
        return mant + (rf" \times 10^{{{int(exp)}}}" if exp else "")

    def _pretty(self, printer: Any) -> Any:
        from sympy.printing.pretty.stringpict import prettyForm

        mant, _, exp = self.name.partition("e")
        sup = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")
        return prettyForm(mant + (f"×10{str(int(exp)).translate(sup)}" if exp else ""))


class _Num(sp.Function):
    """``_Num(expr, digits)``: ``expr`` at the unit's data (ω = 2π/(24·60·60), R = 6.4e6 m,
    h = 100 m, λ = 45°, g = 9.81 m/s²), rounded to ``digits`` significant figures (exactly,
    when ``digits`` is 0). Printed as ``expr``: the unit's numbers are checked at the precision
    it prints them."""

    nargs = 2

    def _latex(self, printer: Any) -> str:
        return str(printer._print(self.args[0]))

    def _pretty(self, printer: Any) -> Any:
        return printer._print(self.args[0])


def _row(*items: Any) -> sp.ImmutableMatrix:
    return sp.ImmutableMatrix([list(items)])


_DAY = _mul(2, sp.pi, sp.Pow(_mul(24, 60, 60), -1, evaluate=False))  # 2π/(24·60·60)
_SIDEREAL_DAY = _mul(2, sp.pi, sp.Pow(sp.Float("86164.0905", 12), -1, evaluate=False))
_UNIT_DATA = {  # the unit's data for its numbers (g for the 100 m example: not stated there)
    omega: 2 * sp.pi / 86400,
    R: sp.Rational("6.4e6"),
    h: 100,
    lam: sp.pi / 4,
    g: sp.Rational("9.81"),
}


def _east(omega: Any, g: Any, h: Any, latitude: Any) -> tuple[Any, Any]:
    """The eastward deflection of a body dropped from ``h`` (2.42) in the unit's two printed
    forms, unevaluated: ⅓ ω g cos λ (2h/g)^{3/2} and ⅓ ω cos λ (8h³/g)^{1/2}."""
    third = sp.Rational(1, 3)
    return (
        _mul(
            third, omega, g, sp.cos(latitude), sp.Pow(2 * h / g, sp.Rational(3, 2), evaluate=False)
        ),
        _mul(
            third, omega, sp.cos(latitude), sp.Pow(8 * h**3 / g, sp.Rational(1, 2), evaluate=False)
        ),
    )


def _half(e: Any) -> Any:
    return _mul(sp.Rational(1, 2), e)


def _second(c: Any) -> Any:
    """c ω² sin 2λ h²/g, printed in that order."""
    return _mul(c, omega**2, sp.sin(2 * lam), h**2, sp.Pow(g, -1, evaluate=False))


# ---- the model ----------------------------------------------------------------------------------


def _col(*c: Any) -> sp.Matrix:
    return sp.Matrix(c)


def _order(term: Any) -> int:
    """The power of ω in a product."""
    return int(term.as_powers_dict().get(omega, 0))


def _cut(e: sp.Matrix, n: int) -> sp.Matrix:
    """The components of ``e`` to order ωⁿ."""
    return e.applyfunc(
        lambda c: sp.Add(*[u for u in sp.Add.make_args(sp.expand(c)) if _order(u) <= n])
    )


def _from_rest(acc: Any) -> Any:
    """The double integral of ``acc(t)`` from rest at the origin at t = 0."""
    s, u = sp.Dummy("s"), sp.Dummy("u")
    inner = sp.integrate(sp.sympify(acc).subs(t, s), (s, 0, u))
    return sp.integrate(inner, (u, 0, t))


def _successive(n_max: int, centrifugal: bool = True) -> list[sp.Matrix]:
    """The successive approximations ρ_(0), …, ρ_(n_max) of the dropped body (ENU components,
    functions of t): ρ_(n) is h ê_z plus the double integral from rest of
    −g ê_z − 2 ω × ρ̇_(n−1) − ω × (ω × ρ_(n−1)), cut at order ωⁿ. ``centrifugal=False`` leaves
    out the change of the centrifugal force with height (the unit's 2.32 with g constant)."""
    w = omega * _col(0, sp.cos(lam), sp.sin(lam))
    e_z = _col(0, 0, 1)
    out: list[sp.Matrix] = []
    prev = sp.zeros(3, 1)
    for n in range(n_max + 1):
        acc = -g * e_z - 2 * w.cross(prev.diff(t))
        if centrifugal:
            acc -= w.cross(w.cross(prev))
        prev = _cut(acc.applyfunc(_from_rest) + h * e_z, n)
        out.append(prev)
    return out


class _EarthModel:
    """The components of the notation (see the module docstring), with the body's second
    derivatives from Newton's law and the successive approximations computed by the method."""

    def __init__(self) -> None:
        w = omega * _col(0, sp.cos(lam), sp.sin(lam))  # 2.33
        e_x, e_y, e_z = _col(1, 0, 0), _col(0, 1, 0), _col(0, 0, 1)
        ground = _col(*sp.symbols("R_x R_y R_z", real=True))
        pos = _col(x, y, z)
        force = _col(*sp.symbols("F_x F_y F_z", real=True))
        grav = -g * e_z + w.cross(w.cross(ground))  # ê_z: the plumb line at the ground

        def fix(c: sp.Matrix) -> sp.Matrix:
            return c.diff(t) + w.cross(c)

        # Newton's law 2.29, solved for the body's second derivatives
        rr = ground + pos
        law = m * fix(fix(rr)) - force - m * grav
        dd = [q.diff(t, 2) for q in (x, y, z)]
        (sol,) = sp.solve(list(law), dd, dict=True)
        self.newton = {k: sp.expand(vv) for k, vv in sol.items()}
        free = _col(*dd).xreplace(self.newton).xreplace(dict(zip(force, (0, 0, 0), strict=True)))

        # the successive approximations ρ_(n): order ωⁿ
        r0, r1, r2 = _successive(2)
        parts = {  # the two second-order pushes on y, each integrated from rest
            y_cor: _from_rest((-2 * w.cross(r1.diff(t)))[1]),
            y_cf: _from_rest((-w.cross(w.cross(r1)))[1]),
        }
        self.iterates: dict[Any, Any] = {}
        for syms, comp in (((x0, y0, z0), r0), ((x1, y1, z1), r1), ((x2, y2, z2), r2)):
            self.iterates.update(zip(syms, comp, strict=True))
        self.iterates.update(parts)
        (landing,) = [s for s in sp.solve(r1[2].subs(t, T), T) if s.is_positive]
        self.scalars: dict[Any, Any] = {
            T: landing,
            z_0: h,
            Z_0: h,
            theta: lam,
            a_x: x1.diff(t, 2),
            a_y: y1.diff(t, 2),
            a_z: z1.diff(t, 2),
        }
        self.vm = VectorModel(
            vectors={
                W: w,
                ex: e_x,
                ey: e_y,
                ez: e_z,
                Rv: ground,
                rho: pos,
                r: rr,
                F: force,
                gv: grav,
                g_e: grav - w.cross(w.cross(rr)),  # 2.31
                v: pos.diff(t),
                a: free,
                vr: _col(v_x, v_y, v_z),
                rho0: _col(x0, y0, z0),
                rho1: _col(x1, y1, z1),
            },
            dt_fix=fix,
            dt_rot=lambda c: c.diff(t),
        )
        for comp, unit in ((omega_x, ex), (omega_y, ey), (omega_z, ez)):
            self.scalars[comp] = self.vm(Dot(W, unit))  # ω_x = ω · ê_x, ...

    def __call__(self, e: Any) -> Any:
        if isinstance(e, sp.MatrixBase):
            return sp.ImmutableMatrix(e.applyfunc(self))
        out = self.vm(e)
        if isinstance(out, sp.MatrixBase):
            return sp.ImmutableMatrix(out.applyfunc(self._post))
        return self._post(out)

    def _post(self, e: Any) -> Any:
        e = sp.sympify(e).xreplace(self.scalars).xreplace(self.newton)
        for f, expr in self.iterates.items():
            if e.has(f.func):
                s = sp.Dummy("s")
                e = e.replace(f.func, sp.Lambda(s, expr.subs(t, s)))
        if e.atoms(_Dec):
            e = e.xreplace({d: sp.Rational(d.name) for d in e.atoms(_Dec)})
        e = e.doit()
        if e.has(_Num):
            e = e.replace(_Num, _unit_value)
        return e


def _unit_value(expr: Any, digits: Any) -> Any:
    """``expr`` at the unit's data, to ``digits`` significant figures (exact when 0)."""
    val = sp.sympify(expr).xreplace(_UNIT_DATA).doit()
    n = int(digits)
    if n == 0:
        return val
    return sp.Rational(format(float(sp.N(val, 30)), f".{n - 1}e"))


@cache
def _model() -> _EarthModel:
    return _EarthModel()


# ---- the derivation -----------------------------------------------------------------------------


def _coriolis(vel: Any) -> Any:
    return _mul(-2, Cross(W, vel))


def _centrifugal(pos: Any) -> Any:
    return -Cross(W, Cross(W, pos))


def derive() -> Derivation:
    """The derivation "earth": the unit's 2.29–2.42 and the second-order southward deflection
    (2.42a–2.42c), every step checked in the model of the module docstring."""
    M = _model()
    d = Derivation(
        "earth",
        "Motion on the Earth and the falling body",
        summary=(
            "Newton's law seen from the rotating Earth (2.29–2.31), and a body dropped from "
            "height h by successive approximation (2.32–2.42): to first order in ω it lands "
            "⅓ ω cos λ √(8h³/g) east of the plumb line; carried one order further, also "
            "¾ ω² sin 2λ h²/g towards the equator (2.42a–2.42c, not in the unit)."
        ),
        model=M,
    )
    vel, acc = DtRot(r), DtRot(DtRot(r))

    # -- 2.29–2.31: the equation of motion in the Earth's frame ------------------------------
    d.given(
        "Newton's law in the fixed (inertial) frame, for a particle of mass m pulled by "
        "gravity m g and any other real force F (2.29).",
        _eq(_mul(m, DtFix(DtFix(r))), _add(F, _mul(m, gv))),
        "2.29",
    )
    d.step(
        "Apply the operator (d/dt)_fix = (d/dt)_rot + ω × (2.15) twice; the Earth turns at a "
        "constant rate, so the term dω/dt × r of 2.18 is absent.",
        [
            _eq(
                DtFix(DtFix(r)),
                _add(DtRot(_add(vel, Cross(W, r))), Cross(W, _add(vel, Cross(W, r)))),
            ),
            _eq(
                _add(DtRot(_add(vel, Cross(W, r))), Cross(W, _add(vel, Cross(W, r)))),
                _add(acc, _mul(2, Cross(W, vel)), Cross(W, Cross(W, r))),
            ),
        ],
    )
    d.step(
        "Put this into 2.29 and solve for the rotating-frame acceleration: the equation of "
        "motion in the Earth's frame (2.30). The Coriolis force carries the mass m like every "
        "force; the unit's 2.30 lost it (− 2 ω × (dr/dt)_rot).",
        _eq(
            _mul(m, acc),
            _add(F, _mul(m, _add(gv, -Cross(W, Cross(W, r)))), _mul(-2, m, Cross(W, vel))),
        ),
        "2.30",
    )
    d.given(
        "The effective gravity: the attraction and the centrifugal acceleration together "
        "(2.31), what a plumb line and a pendulum feel.",
        _eq(g_e, _add(gv, -Cross(W, Cross(W, r)))),
        "2.31",
    )
    d.step(
        "With 2.31, 2.30 reads as Newton's law with g_e for g and the Coriolis force added.",
        _eq(_mul(m, acc), _add(F, _mul(m, g_e), _mul(-2, m, Cross(W, vel)))),
    )
    d.step(
        "The centrifugal acceleration is ω² times the distance from the Earth's axis, pointing "
        "away from the axis: zero at the poles, largest at the equator (the unit's \"radially "
        'outwards" holds only at the equator).',
        _eq(_centrifugal(r), _add(_mul(omega**2, r), -_mul(Dot(W, r), W))),
    )
    surf = d.step(
        "At the surface, r = R ê_z with ê_z radial, and ω in the local axes of 2.33 below: "
        "the centrifugal acceleration is ω² R cos λ, ω² R at the equator.",
        _eq(
            _centrifugal(_mul(R, ez)),
            _mul(omega**2, R, sp.cos(lam), _add(_mul(-sp.sin(lam), ey), _mul(sp.cos(lam), ez))),
        ),
    )
    d.function("centrifugal", M(surf), (omega, R, lam))
    ge = d.step(
        "So with the attraction −g ê_z along the radius, the effective gravity 2.31 at the "
        "surface is a little weaker than g and leans towards the equator.",
        _eq(
            _add(_mul(-g, ez), _centrifugal(_mul(R, ez))),
            _add(
                _mul(-(omega**2), R, sp.sin(lam), sp.cos(lam), ey),
                _mul(_add(omega**2 * R * sp.cos(lam) ** 2, -g), ez),
            ),
        ),
    )
    d.function("2.31", M(ge), (omega, R, g, lam))
    d.given(
        "The Earth turns once a day (the unit's value: a solar day of 24 h).",
        _eq(_Num(omega, 0), _DAY),
    )
    d.step(
        "Evaluated, ω = 7.27 × 10⁻⁵ rad/s; the unit prints 7.25 × 10⁻⁵, an arithmetic slip.",
        [_eq(_Num(omega, 0), _DAY), _eq(_Num(_DAY, 3), _Dec("7.27e-5"))],
        "Earth's rate",
    )
    d.step(
        "The Earth's true rate is one turn per sidereal day of 86164.0905 s (the core's "
        "default): 7.2921 × 10⁻⁵ rad/s.",
        _eq(_Num(_SIDEREAL_DAY, 5), _Dec("7.2921e-5")),
    )
    d.step(
        "With the unit's radius R = 6.4 × 10⁶ m, the centrifugal acceleration at the equator "
        "is ω² R = 3.38 × 10⁻² m/s², the unit's 3.4 × 10⁻².",
        [
            _eq(_Num(_mul(omega**2, R), 3), _Dec("3.38e-2")),
            _eq(_Num(_mul(omega**2, R), 2), _Dec("3.4e-2")),
        ],
        "centrifugal at the equator",
    )
    d.step(
        "The Coriolis force −2 m ω × v_r is at right angles to both v_r and ω.",
        [_eq(Dot(vr, Cross(W, vr)), 0), _eq(0, Dot(W, Cross(W, vr)))],
    )
    d.function("2.30", M(_coriolis(vr)), (omega, lam, v_x, v_y, v_z))
    vh = _add(_mul(v_x, ex), _mul(v_y, ey))
    d.step(
        "For a horizontal velocity v_x ê_x + v_y ê_y (with ω of 2.33 below), the horizontal "
        "Coriolis acceleration is 2 ω sin λ times it, turned to the right in the north: "
        "largest, 2 ω v_r, at the poles, zero at the equator.",
        _eq(
            _add(_coriolis(vh), _mul(2, Dot(Cross(W, vh), ez), ez)),
            _mul(-2, omega, sp.sin(lam), Cross(ez, vh)),
        ),
    )
    d.step(
        "At the unit's rate 2ω = 1.45 × 10⁻⁴ s⁻¹, the unit's 1.5 × 10⁻⁴.",
        [
            _eq(_mul(_Num(2 * omega, 3), v_r), _mul(_Dec("1.45e-4"), v_r)),
            _eq(_mul(_Num(2 * omega, 2), v_r), _mul(_Dec("1.5e-4"), v_r)),
        ],
        "Coriolis at the poles",
    )

    # -- 2.32–2.42: the falling body ----------------------------------------------------------
    d.step(
        "A freely falling body (F = 0; a, v its acceleration and velocity in the Earth's "
        "frame): 2.30 divided by m (2.32). The unit writes g for this g_e and takes it "
        "constant over the small height.",
        _eq(a, _add(g_e, _coriolis(v))),
        "2.32",
    )
    d.given(
        "Measure the body's position ρ = x ê_x + y ê_y + z ê_z from the ground point R below "
        "it (r = R + ρ), ê_z up along the plumb line there, g the gravity measured there "
        "(the centrifugal acceleration at the ground is part of it).",
        _eq(_add(gv, _centrifugal(Rv)), _mul(-g, ez)),
    )
    d.step(
        "Then g_e at the body is the ground's plus the change of the centrifugal acceleration "
        "with ρ: the unit's neglected 'variation in g', of order ω².",
        [
            _eq(g_e, _add(gv, _centrifugal(Rv), _centrifugal(rho))),
            _eq(
                _add(gv, _centrifugal(Rv), _centrifugal(rho)), _add(_mul(-g, ez), _centrifugal(rho))
            ),
        ],
    )
    d.step(
        "So the body's equation of motion, exact in the unit's uniform gravity:",
        _eq(a, _add(_mul(-g, ez), _coriolis(v), _centrifugal(rho))),
    )
    w33 = d.given(
        "The local axes: x east, y north, z up. The axis ω lies in the meridian plane (y, z) "
        "at the angle λ, the latitude (the unit's θ), above the horizontal northward "
        "direction (2.33).",
        _eq(W, _add(_mul(omega, sp.cos(lam), ey), _mul(omega, sp.sin(lam), ez))),
        "2.33",
    )
    d.function("2.33", M(w33), (omega, lam))
    d.step(
        "Successive approximation: ρ_(n) is the motion to order ωⁿ. Without the terms in ω, "
        "the body released from rest at height h falls freely: ρ_(0).",
        _eq(rho0, _mul(_add(h, -_half(g * t**2)), ez)),
    )
    d.step(
        "Its velocity, the unit's ẋ ≃ 0, ẏ ≃ 0, ż ≃ −g t (2.34).",
        _eq(_row(x0.diff(t), y0.diff(t), z0.diff(t)), _row(0, 0, _mul(-g, t))),
        "2.34",
    )
    d.step(
        "The Coriolis acceleration of this velocity points along x: ω × v = −ω g t cos λ ê_x.",
        _eq(Cross(W, DtRot(rho0)), _mul(-omega, g, t, sp.cos(lam), ex)),
    )
    d.given(
        "The first approximation ρ_(1) keeps the terms of first order in ω, evaluated on "
        "ρ_(0): 2.32 with g_e at the ground and v = v_(0).",
        _eq(DtRot(DtRot(rho1)), _add(_mul(-g, ez), _coriolis(DtRot(rho0)))),
    )
    d.step(
        "Its x component: the Coriolis force pushes the body east (2.35).",
        [_eq(a_x, x1.diff(t, 2)), _eq(x1.diff(t, 2), _mul(2, omega, g, t, sp.cos(lam)))],
        "2.35",
    )
    d.step(
        "Nothing acts along y at this order (2.36).",
        [_eq(a_y, y1.diff(t, 2)), _eq(y1.diff(t, 2), 0)],
        "2.36",
    )
    d.step(
        "Along z, gravity alone (2.37).", [_eq(a_z, z1.diff(t, 2)), _eq(z1.diff(t, 2), -g)], "2.37"
    )
    d.step(
        "The body starts at rest at the height z_0 = h (2.40; the unit's Z_0 is this z_0).",
        _eq(
            _row(z1.subs(t, 0), x1.subs(t, 0), x1.diff(t).subs(t, 0), z1.diff(t).subs(t, 0)),
            _row(h, 0, 0, 0),
        ),
        "2.40",
    )
    d.step(
        "Integrate 2.35 twice from rest (2.40): the eastward drift grows as t³ (2.38).",
        [
            _eq(
                x1,
                sp.Integral(sp.Integral(2 * omega * g * t2 * sp.cos(lam), (t2, 0, t1)), (t1, 0, t)),
            ),
            _eq(
                sp.Integral(sp.Integral(2 * omega * g * t2 * sp.cos(lam), (t2, 0, t1)), (t1, 0, t)),
                _mul(sp.Rational(1, 3), omega, g, t**3, sp.cos(lam)),
            ),
        ],
        "2.38",
    )
    d.step(
        "Integrate 2.37 twice from rest at z_0 = h (2.39).",
        _eq(z1, _add(h, -_half(g * t**2))),
        "2.39",
    )
    d.step(
        "The body lands, z = 0, at the time of fall T (2.41; the unit calls it t).",
        [_eq(z1.subs(t, T), _add(h, -_half(g * T**2))), _eq(_add(h, -_half(g * T**2)), 0)],
    )
    tf = d.step(
        "Solve for T (2.41).", _eq(T, sp.Pow(2 * h / g, sp.Rational(1, 2), evaluate=False)), "2.41"
    )
    d.function("2.41", tf, (h, g))
    east = d.step(
        "Put T into 2.38: the eastward deflection at landing (2.42).",
        [
            _eq(x1.subs(t, T), _mul(sp.Rational(1, 3), omega, g, sp.cos(lam), T**3)),
            _eq(_mul(sp.Rational(1, 3), omega, g, sp.cos(lam), T**3), _east(omega, g, h, lam)[0]),
            _eq(*_east(omega, g, h, lam)),
        ],
        "2.42",
    )
    d.function("2.42", M(east), (omega, h, lam, g))
    d.step(
        "The unit's example, 100 m at 45° (with g = 9.81 m/s², which it does not state): "
        "1.548 × 10⁻² m east, the unit's 1.55 × 10⁻² m.",
        [
            _eq(_Num(x1.subs(t, T), 4), _Dec("1.548e-2")),
            _eq(_Num(x1.subs(t, T), 3), _Dec("1.55e-2")),
        ],
        "2.42 at 100 m",
    )

    # -- one order further: the southward deflection ------------------------------------------
    d.step(
        "One order further than the unit (2.42a–2.42c are this derivation's numbers, not the "
        "unit's): at order ω² the equation of motion on ρ_(1) pushes along y by the Coriolis "
        "force of the eastward velocity and the change of the centrifugal force with height.",
        _eq(
            y2.diff(t, 2),
            _add(Dot(_coriolis(DtRot(rho1)), ey), -Dot(Cross(W, Cross(W, rho1)), ey)),
        ),
    )
    d.step(
        "The Coriolis part: ω_z = ω sin λ turns the eastward velocity ẋ_(1) = ω g t² cos λ "
        "towards the south (to the right of its motion).",
        [
            _eq(y_cor.diff(t, 2), Dot(_coriolis(DtRot(rho1)), ey)),
            _eq(Dot(_coriolis(DtRot(rho1)), ey), _mul(-2, omega, sp.sin(lam), x1.diff(t))),
            _eq(
                _mul(-2, omega, sp.sin(lam), x1.diff(t)),
                _mul(-(omega**2), g, t**2, sp.sin(2 * lam)),
            ),
        ],
    )
    d.step(
        "Integrated twice from rest, and at the landing time T = √(2h/g) (2.41):",
        [
            _eq(y_cor, _mul(sp.Rational(-1, 12), omega**2, g, t**4, sp.sin(2 * lam))),
            _eq(y_cor.subs(t, T), _mul(sp.Rational(-1, 12), omega**2, g, T**4, sp.sin(2 * lam))),
        ],
    )
    cor2 = d.step(
        "So the Coriolis force moves the body ⅓ ω² sin 2λ h²/g to the south (2.42a).",
        [
            _eq(_mul(sp.Rational(-1, 12), omega**2, g, T**4, sp.sin(2 * lam)), y_cor.subs(t, T)),
            _eq(y_cor.subs(t, T), _second(sp.Rational(-1, 3))),
        ],
        "2.42a",
    )
    d.step(
        "The centrifugal part: the change −ω × (ω × ρ_(1)) pushes the body towards the equator "
        "in proportion to its height z above the ground.",
        [
            _eq(y_cf.diff(t, 2), Dot(_centrifugal(rho1), ey)),
            _eq(Dot(_centrifugal(rho1), ey), _mul(-(omega**2), sp.sin(lam), sp.cos(lam), z1)),
            _eq(
                _mul(-(omega**2), sp.sin(lam), sp.cos(lam), z1),
                _mul(-_half(omega**2), sp.sin(2 * lam), _add(h, -_half(g * t**2))),
            ),
        ],
    )
    d.step(
        "Integrated twice from rest, and at the landing time T:",
        [
            _eq(
                y_cf,
                _mul(-_half(omega**2), sp.sin(2 * lam), _add(_half(h * t**2), -g * t**4 / 24)),
            ),
            _eq(
                y_cf.subs(t, T),
                _mul(-_half(omega**2), sp.sin(2 * lam), _add(_half(h * T**2), -g * T**4 / 24)),
            ),
        ],
    )
    cf2 = d.step(
        "So the change of the centrifugal force with height moves it 5/12 ω² sin 2λ h²/g to "
        "the south (2.42b).",
        [
            _eq(
                _mul(-_half(omega**2), sp.sin(2 * lam), _add(_half(h * T**2), -g * T**4 / 24)),
                y_cf.subs(t, T),
            ),
            _eq(y_cf.subs(t, T), _second(sp.Rational(-5, 12))),
        ],
        "2.42b",
    )
    d.step(
        "The second approximation's y is the sum of the two parts (nothing else acts along y "
        "at order ω²).",
        _eq(y2, _add(y_cor, y_cf)),
    )
    south = d.step(
        "The southward deflection at landing, ⅓ + 5/12 = ¾ of ω² sin 2λ h²/g (2.42c): towards "
        "the equator in both hemispheres, from the foot of the plumb line hung from the "
        "release point (its bob at the ground, along ê_z).",
        [
            _eq(-y2.subs(t, T), _add(-y_cor.subs(t, T), -y_cf.subs(t, T))),
            _eq(
                _add(-y_cor.subs(t, T), -y_cf.subs(t, T)),
                _add(
                    _second(sp.Rational(1, 3)),
                    _second(sp.Rational(5, 12)),
                ),
            ),
            _eq(
                _add(
                    _second(sp.Rational(1, 3)),
                    _second(sp.Rational(5, 12)),
                ),
                _second(sp.Rational(3, 4)),
            ),
        ],
        "2.42c",
    )
    d.function("2.42a", -M(cor2), (omega, h, lam, g))
    d.function("2.42b", -M(cf2), (omega, h, lam, g))
    d.function("2.42c", M(south), (omega, h, lam, g))
    d.step(
        "At T the second approximation is still 3/2 ω² cos²λ h²/g above the ground: the "
        "landing comes later by a time of order ω², which moves y only at order ω⁴ and x at "
        "order ω³, so 2.42 and 2.42c are complete to their orders.",
        _eq(
            z2.subs(t, T),
            _mul(
                sp.Rational(3, 2), omega**2, sp.cos(lam) ** 2, h**2, sp.Pow(g, -1, evaluate=False)
            ),
        ),
    )
    return d


# ---- the unit as printed ------------------------------------------------------------------------

_R_FIX = r"\left(\frac{d^2\vec{r}}{dt^2}\right)"
_UNIT_THETA = "the unit's θ is the latitude λ"

PRINTED: tuple[Printed, ...] = (
    Printed(
        "2.29",
        "earth",
        r"m\left(\frac{d^2\vec{r}}{dt^2}\right)_{fix} = \vec{F} + m\vec{g}",
        _eq(_mul(m, DtFix(DtFix(r))), _add(F, _mul(m, gv))),
    ),
    Printed(
        "2.30",
        "earth",
        r"m\left(\frac{d^2\vec{r}}{dt^2}\right)_{rot} = \vec{F} + m[\vec{g} - \vec{\omega} \times "
        r"(\vec{\omega} \times \vec{r})] - 2\vec{\omega} \times \left(\frac{d\vec{r}}{dt}\right)_{rot}",
        _eq(
            _mul(m, DtRot(DtRot(r))),
            _add(F, _mul(m, _add(gv, -Cross(W, Cross(W, r)))), _mul(-2, Cross(W, DtRot(r)))),
        ),
    ),
    Printed(
        "2.31",
        "earth",
        r"\vec{g}_e = \vec{g} - \vec{\omega} \times (\vec{\omega} \times \vec{r})",
        _eq(g_e, _add(gv, -Cross(W, Cross(W, r)))),
    ),
    Printed(
        "Earth's rate",
        "earth",
        r"\vec{\omega} = \frac{2\pi}{24 \times 60 \times 60} = 7.25 \times 10^{-5} \ rad/sec.",
        [_eq(_Num(omega, 0), _DAY), _eq(_Num(_DAY, 3), _Dec("7.25e-5"))],
        "unnumbered, after 2.31; the arrow on ω means its magnitude; 7.25e-5 is judged to the "
        "three figures printed",
    ),
    Printed(
        "centrifugal at the equator",
        "earth",
        r"\omega^2 r=3.4\times 10^{-2}\ m/s^2",
        _eq(_Num(_mul(omega**2, R), 2), _Dec("3.4e-2")),
        "unnumbered, after the Earth's rate; the unit's r = 6.4e6 m is the Earth's radius R; "
        "judged to the two figures printed",
    ),
    Printed(
        "Coriolis at the poles",
        "earth",
        r"2\omega v_r = 1.5 \times 10^{-4} v_r",
        _eq(_mul(_Num(2 * omega, 2), v_r), _mul(_Dec("1.5e-4"), v_r)),
        "unnumbered, the largest horizontal Coriolis acceleration; judged to the two figures "
        "printed",
    ),
    Printed(
        "2.32",
        "earth",
        r"\vec{a} = \vec{g} - 2\vec{\omega} \times \vec{v}",
        _eq(a, _add(g_e, _coriolis(v))),
        "the unit's g here is the effective gravity g_e of 2.31 (it then neglects its change "
        "with height); a and v are the free body's, in the Earth's frame",
    ),
    Printed(
        "2.33",
        "earth",
        r"\omega_{x} = 0, \quad \omega_{y} = \omega \cos\theta \quad \text{and} \quad "
        r"\omega_{z} = \omega \sin\theta",
        _eq(_row(omega_x, omega_y, omega_z), _row(0, omega * sp.cos(theta), omega * sp.sin(theta))),
        "printed as three formulas in a sentence, joined here; " + _UNIT_THETA,
    ),
    Printed(
        "2.34",
        "earth",
        r"\dot{x} \simeq 0, \dot{y} \simeq 0 \quad and \, \dot{z} \simeq -gt",
        _eq(_row(x0.diff(t), y0.diff(t), z0.diff(t)), _row(0, 0, _mul(-g, t))),
        "≃: the zeroth approximation, ρ_(0) here",
    ),
    Printed(
        "2.35",
        "earth",
        r"a_x = \ddot{x} = 2\omega gt \cos\theta",
        [_eq(a_x, x1.diff(t, 2)), _eq(x1.diff(t, 2), 2 * omega * g * t * sp.cos(theta))],
        "the first approximation, ρ_(1) here; " + _UNIT_THETA,
    ),
    Printed(
        "2.36",
        "earth",
        r"a_y = \ddot{y} = 0",
        [_eq(a_y, y1.diff(t, 2)), _eq(y1.diff(t, 2), 0)],
        "the first approximation",
    ),
    Printed(
        "2.37",
        "earth",
        r"a_z = \ddot{z} = -g",
        [_eq(a_z, z1.diff(t, 2)), _eq(z1.diff(t, 2), -g)],
        "the first approximation",
    ),
    Printed(
        "2.38",
        "earth",
        r"x = \frac{1}{3}\omega g t^3 \cos\theta",
        _eq(x1, _mul(sp.Rational(1, 3), omega, g, t**3, sp.cos(theta))),
        "the first approximation; " + _UNIT_THETA,
    ),
    Printed(
        "2.39",
        "earth",
        r"z = z_0 - \frac{1}{2}gt^2",
        _eq(z1, _add(z_0, -_half(g * t**2))),
        "the first approximation; z_0 is the release height h",
    ),
    Printed(
        "2.40",
        "earth",
        r"z(0) = Z_0 \quad \text{and} \quad x(0) = 0, \quad \dot{x}(0) = 0 \quad \text{and} "
        r"\quad \dot{z}(0) = 0",
        _eq(
            _row(z1.subs(t, 0), x1.subs(t, 0), x1.diff(t).subs(t, 0), z1.diff(t).subs(t, 0)),
            _row(Z_0, 0, 0, 0),
        ),
        "printed as four formulas in a sentence, joined here; the unit's Z_0 is the z_0 of 2.39 "
        "(a capital in the scan)",
    ),
    Printed(
        "2.41",
        "earth",
        r"t = \sqrt{\frac{2h}{g}}",
        _eq(T, sp.Pow(2 * h / g, sp.Rational(1, 2), evaluate=False)),
        "the unit's t here is the time of fall T",
    ),
    Printed(
        "2.42",
        "earth",
        r"x = \frac{1}{3}\omega g \cos\theta \left(\frac{2h}{g}\right)^{3/2} = \frac{1}{3}\omega "
        r"\cos\theta \left(\frac{8h^3}{g}\right)^{1/2}",
        [_eq(x1.subs(t, T), _east(omega, g, h, theta)[0]), _eq(*_east(omega, g, h, theta))],
        "x at the landing time; " + _UNIT_THETA,
    ),
    Printed(
        "2.42 at 100 m",
        "earth",
        r"1.55\times 10^{-2}m",
        _eq(_Num(x1.subs(t, T), 3), _Dec("1.55e-2")),
        "unnumbered, after 2.42: h = 100 m, θ = 45°, with g = 9.81 m/s² (not stated); judged to "
        "the three figures printed",
    ),
)
