"""The torque-free symmetric top (the unit's 2.77–2.97), derived and checked.

Coverage
--------
Euler's equations 2.72 with N⃗ = 0⃗ and I₁ = I₂ ≠ I₃ give

* 2.77–2.80: I₁ω̇₁ = (I₁ − I₃)ω₂ω₃, I₁ω̇₂ = (I₃ − I₁)ω₃ω₁, ω₃ constant;
* 2.81–2.84: Ω = (I₁ − I₃)ω₃/I₁ (2.83, rad/s, the unit's sign), ω̇₁ = Ωω₂, ω̇₂ = −Ωω₁,
  ω̈₁ = −Ω²ω₁;
* 2.85–2.89: ω₁ = A sin(Ωt + θ₀), ω₂ = A cos(Ωt + θ₀) (the unit's phase), |ω⃗_p| = A,
  |ω⃗| = (A² + ω₃²)^½ constant, and ω(t) from its initial value;
* 2.90: the body cone, tan α_b = A/ω₃;
* 2.91–2.96: T = ½I₁A² + ½I₃ω₃² (J), L² = I₁²A² + I₃²ω₃² (kg²·m⁴/s²) and, solved for the
  constants, ω₃² = (L² − 2TI₁)/(I₃(I₃ − I₁)), A² = (L² − 2I₃T)/(I₁(I₁ − I₃)) (the long
  question 10);
* 2.97: the space cone, cos α_s = 2T/(ωL), and α_s = atan2(|I₁ − I₃|A|ω₃|, I₁A² + I₃ω₃²).

Model
-----
Two models of the same motions, in body (principal-axis) components with I⃗ = diag(I₁, I₁, I₃)
(kg·m²) and the context I₂ → I₁:

* up to the solution (2.77–2.84 and the check that A sin(Ωt + θ₀), A cos(Ωt + θ₀) solve them),
  the *flow*: ω₁, ω₂, ω₃ are arbitrary functions of time whose rates are replaced, after each
  differentiation, by Euler's equations with N⃗ = 0⃗, ω̇⃗ = −I⃗⁻¹(ω⃗ × I⃗·ω⃗). A step checked
  there follows from Euler's equations alone;
* from 2.85 on, the *solution*: ω₁ = A sin(Ωt + θ₀), ω₂ = A cos(Ωt + θ₀), ω₃ constant, with A > 0,
  θ₀ and ω₃ free and Ω = (I₁ − I₃)ω₃/I₁. The step after the switch checks that it satisfies
  Euler's equations; as its constants reach every initial state, an identity along every
  torque-free motion is an identity here, and the printed equations are judged in it.

Angles are defined as the unit does, α_b between ω⃗ and the symmetry axis k̂ and α_s between ω⃗
and L⃗ (computed as atan2 of the cross and dot products). Square roots are taken of bases
reduced modulo sin² + cos² = 1 and factored, so every check is a polynomial identity: the
derivation builds in a fraction of a second.

Results
-------
``result`` holds 2.77–2.91 and 2.93–2.97 (the unit has no 2.92). Numeric forms
(:meth:`~poinsot.derive.Derivation.lambdify`), SI units: ``"2.83"`` Ω(I₁, I₃, ω₃);
``"2.85"``, ``"2.86"`` ω₁, ω₂(I₁, I₃, ω₁(0), ω₂(0), ω₃, t); ``"2.88"`` A(ω₁(0), ω₂(0));
``"2.89"`` |ω|(A, ω₃); ``"2.90"`` α_b(A, ω₃); ``"2.91"`` T(I₁, I₃, A, ω₃); ``"2.93"``
L²(I₁, I₃, A, ω₃); ``"2.95"`` ω₃²(I₁, I₃, T, L); ``"2.96"`` A²(I₁, I₃, T, L); ``"2.97"``
α_s(I₁, I₃, A, ω₃).

The unit as printed (:data:`PRINTED`) has the wrong sign in 2.78 and in the middle line of 2.84:
:func:`poinsot.derive.errata` reports these two.
"""

from __future__ import annotations

from typing import Any

import sympy as sp
from sympy.physics.vector import dynamicsymbols

from ._core import Derivation, Dot, Printed, Unit, Vec
from .euler_equations import (
    HALF,
    I1,
    I2,
    I3,
    ZERO,
    T,
    _add,
    _chain,
    _Cross,
    _Ddt,
    _eq,
    _Model,
    _mul,
    _Norm,
    _plain,
    _trig_reduce,
    t,
    w1,
    w2,
    w3,
)

__all__ = ["derive", "PRINTED"]

# ---- the notation of this derivation -------------------------------------------------------

Omega = dynamicsymbols("Omega")
A = sp.Symbol("A", positive=True)
theta0 = sp.Symbol("theta_0", real=True)
#: magnitudes, as the unit writes them: ω = |ω⃗|, L = |L⃗|, ω_p = |ω⃗_p|
w_mag, L_mag, wp_mag = sp.Symbol("omega"), sp.Symbol("L"), sp.Symbol("omega_p")
alpha_b, alpha_s = sp.Symbol("alpha_b"), sp.Symbol("alpha_s")
#: the initial values ω₁(0), ω₂(0)
w10, w20 = sp.Symbol(r"\omega_{1}(0)"), sp.Symbol(r"\omega_{2}(0)")
omega, L, I, omega_p = Vec("omega"), Vec("L"), Vec("I"), Vec("omega_p")
i_, j_, k_ = Unit("i"), Unit("j"), Unit("k")

W = sp.Matrix([w1, w2, w3])
#: the symmetric top's inertia tensor in principal axes (kg·m²)
INERTIA = sp.diag(I1, I1, I3)
#: Ω of 2.83 in the unit's sign
OMEGA_DEF = _mul((I1 - I3) / I1, w3)

#: the solution's constants inside the model (Ω_s stands for Ω inside the sines; ω₃ constant)
_Om_s, _w3_s = sp.Symbol("Omega_s", real=True), sp.Symbol("omega_3s", real=True)


def _frac(n: Any, den: Any) -> Any:
    """n/den with the denominator's factors in the order written."""
    return sp.Mul(n, sp.Pow(den, -1, evaluate=False), evaluate=False)


def _phase() -> Any:
    """Ωt + θ₀, printed in that order."""
    return _add(_mul(Omega, t), theta0)


def _vectors(Wm: sp.Matrix) -> dict[Any, sp.Matrix]:
    return {
        omega: Wm,
        I: INERTIA,
        L: INERTIA * Wm,
        omega_p: sp.Matrix([Wm[0], Wm[1], 0]),
        ZERO: sp.zeros(3, 1),
        i_: sp.Matrix([1, 0, 0]),
        j_: sp.Matrix([0, 1, 0]),
        k_: sp.Matrix([0, 0, 1]),
    }


def _add_scalars(m: _Model) -> _Model:
    """The scalars both models define through the vectors: T, the magnitudes and the angles."""
    s = dict(m.scalars)
    s[T] = m._ev(_mul(HALF, Dot(omega, Dot(I, omega))))
    for sym, vec in ((w_mag, omega), (L_mag, L), (wp_mag, omega_p)):
        s[sym] = m._ev(_Norm(vec))
    for sym, vec in ((alpha_b, k_), (alpha_s, L)):
        s[sym] = sp.atan2(
            _trig_reduce(m._ev(_Norm(_Cross(omega, vec)))),
            _trig_reduce(sp.expand(m._ev(Dot(omega, vec)))),
        )
    m.scalars = s
    return m


def _flow_model() -> _Model:
    """ω(t) arbitrary, its rates replaced by Euler's equations with N⃗ = 0⃗ (2.71 solved)."""
    LW = INERTIA * W
    rates = INERTIA.inv() * (-W.cross(LW))
    first = {w.diff(t): r for w, r in zip(W, rates)}
    second = {w.diff(t, 2): sp.diff(r, t).xreplace(first) for w, r in zip(W, rates)}
    flow = lambda x: x.xreplace(second).xreplace(first)
    m = _Model(
        vectors=_vectors(W),
        dt_rot=lambda x: sp.Matrix(x).diff(t),
        scalars={Omega: (I1 - I3) * w3 / I1},
        t=t,
        flow=flow,
    )
    return _add_scalars(m)


def _solution_model() -> _Model:
    """ω₁ = A sin(Ωt + θ₀), ω₂ = A cos(Ωt + θ₀), ω₃ constant; Ω = (I₁ − I₃)ω₃/I₁."""
    arg = _Om_s * t + theta0
    Ws = sp.Matrix([A * sp.sin(arg), A * sp.cos(arg), _w3_s])
    trig = lambda e: e.atoms(sp.sin, sp.cos)

    def post(e: Any) -> Any:
        # Ω_s → (I₁ − I₃)ω₃/I₁ outside the sines (inside, Ω_s is the same constant by name)
        e = sp.sympify(e)
        if not e.has(_Om_s):
            return e
        hide = {a: sp.Dummy() for a in trig(e)}
        out = e.xreplace(hide).xreplace({_Om_s: (I1 - I3) * _w3_s / I1})
        return out.xreplace({v: k for k, v in hide.items()})

    m = _Model(
        vectors=_vectors(Ws),
        dt_rot=lambda x: sp.Matrix(x).diff(t),
        scalars={
            w1: Ws[0],
            w2: Ws[1],
            w3: _w3_s,
            Omega: _Om_s,
            w10: Ws[0].subs(t, 0),
            w20: Ws[1].subs(t, 0),
        },
        t=t,
        post=post,
    )
    return _add_scalars(m)


# ---- the unit as printed -------------------------------------------------------------------

_F = "torque_free_top"

PRINTED: tuple[Printed, ...] = (
    Printed(
        "2.77",
        _F,
        r"I_1 \dot{\omega}_1 = (I_1 - I_3) \omega_2 \omega_3",
        _eq(I1 * w1.diff(t), _mul(I1 - I3, w2, w3)),
    ),
    Printed(
        "2.78",
        _F,
        r"I_2 \dot{\omega}_2 = (I_1 - I_3) \omega_3 \omega_1",
        _eq(I2 * w2.diff(t), _mul(I1 - I3, w3, w1)),
    ),
    Printed("2.79", _F, r"I_3 \dot{\omega}_3 = 0", _eq(I3 * w3.diff(t), 0)),
    Printed(
        "2.80",
        _F,
        r"\omega_3 = const",
        _eq(w3.diff(t), 0),
        note="'ω₃ = const' read as ω̇₃ = 0",
    ),
    Printed(
        "2.81",
        _F,
        r"\therefore \dot{\omega}_1 = \Omega \omega_2",
        _eq(w1.diff(t), _mul(Omega, w2)),
    ),
    Printed("2.82", _F, r"\dot{\omega}_2 = -\Omega \omega_1", _eq(w2.diff(t), -Omega * w1)),
    Printed(
        "2.83",
        _F,
        r"\Omega = \frac{I_1 - I_3}{I_1} \omega_3 = const",
        _eq(Omega, OMEGA_DEF),
        note="the definition; '= const' (Ω̇ = 0) is a step of the derivation",
    ),
    Printed(
        "2.84",
        _F,
        r"\ddot{\omega}_1 = \Omega \dot{\omega}_2" + "\n" + r"= \Omega^2 \omega_1",
        _chain(w1.diff(t, 2), _mul(Omega, w2.diff(t)), Omega**2 * w1),
        note="the two lines before the numbered one (the unit: 'using equation 2.82')",
    ),
    Printed(
        "2.84",
        _F,
        r"\ddot{\omega}_1 = -\Omega^2 \omega_1",
        _eq(w1.diff(t, 2), -(Omega**2) * w1),
    ),
    Printed(
        "2.85",
        _F,
        r"\omega_1 = A\sin(\Omega t + \theta_0)",
        _eq(w1, A * sp.sin(_phase())),
    ),
    Printed(
        "2.86",
        _F,
        r"\omega_2 = A\cos(\Omega t + \theta_0)",
        _eq(w2, A * sp.cos(_phase())),
    ),
    Printed(
        "2.87",
        _F,
        r"\therefore \vec{\omega}_p = \hat{\iota}\omega_1 + \hat{\jmath}\omega_2",
        _eq(omega_p, _add(_mul(i_, w1), _mul(j_, w2))),
    ),
    Printed("2.88", _F, r"\left|\vec{\omega}_{p}\right| = A", _eq(_Norm(omega_p), A)),
    Printed(
        "2.89",
        _F,
        r"|\vec{\omega}| = \sqrt{\omega_1^2 + \omega_2^2 + \omega_3^2} = \sqrt{\omega_p^2 + "
        r"\omega_3^2} = \sqrt{A^2 + \omega_3^2} = const.",
        _chain(
            _Norm(omega),
            sp.sqrt(_add(w1**2, w2**2, w3**2)),
            sp.sqrt(_add(wp_mag**2, w3**2)),
            sp.sqrt(_add(A**2, w3**2)),
        ),
        note="'= const.' is a step of the derivation (d|ω⃗|/dt = 0)",
    ),
    Printed("2.90", _F, r"\tan \alpha_b = \frac{A}{\omega_3}", _eq(sp.tan(alpha_b), A / w3)),
    Printed(
        "2.91",
        _F,
        r"T = \frac{1}{2}I_1A^2 + \frac{1}{2}I_3\omega_3^2",
        _eq(T, _add(_mul(HALF, I1, A**2), _mul(HALF, I3, w3**2))),
    ),
    Printed(
        "2.93",
        _F,
        r"L^2 = I_1^2 A^2 + I_3^2 \omega_3^2",
        _eq(L_mag**2, _add(_mul(I1**2, A**2), _mul(I3**2, w3**2))),
        note="the unit has no 2.92",
    ),
    Printed(
        "2.94",
        _F,
        r"A^2 = \frac{L^2 - I_3^2 \omega_3^2}{I_1^2}",
        _eq(A**2, _add(L_mag**2, -(I3**2) * w3**2) / I1**2),
    ),
    Printed(
        "2.95",
        _F,
        r"\therefore \omega_3^2 = \frac{L^2 - 2T l_1}{l_3(l_3 - l_1)}",
        _eq(w3**2, _add(L_mag**2, -_mul(2, T, I1)) / _mul(I3, I3 - I1)),
        note="the scan's l₁, l₃ are I₁, I₃",
    ),
    Printed(
        "2.96",
        _F,
        r"\therefore A^{2} = \frac{L^{2} - 2I_{3}T}{I_{1}(I_{1} - I_{3})}",
        _eq(A**2, _add(L_mag**2, -_mul(2, I3, T)) / _mul(I1, I1 - I3)),
    ),
    Printed(
        "2.97",
        _F,
        r"\therefore \cos \alpha_s = \frac{2T}{\omega L}",
        _eq(sp.cos(alpha_s), _frac(_mul(2, T), _mul(w_mag, L_mag))),
    ),
)


# ---- the derivation ------------------------------------------------------------------------


def derive() -> Derivation:
    """Builds and checks the derivation of the torque-free symmetric top (2.77–2.97)."""
    d = Derivation(
        "torque_free_top",
        "The torque-free symmetric top (2.77–2.97)",
        summary=(
            "Euler's equations without torque for I₁ = I₂ ≠ I₃: ω₃ constant, ω₁ and ω₂ turning "
            "at Ω = (I₁ − I₃)ω₃/I₁, the constants A and ω₃ from T and L, and the body and space "
            "cones. Checked along every torque-free motion, then on its general solution."
        ),
        model=_flow_model(),
        context={I2: I1},
    )
    wd1, wd2, wd3 = (w.diff(t) for w in W)
    # Euler's equations with N = 0 (2.72), the starting point
    euler = _add(
        _mul(_add(I1 * wd1, _mul(I3 - I2, w2, w3)), i_),
        _mul(_add(I2 * wd2, _mul(I1 - I3, w3, w1)), j_),
        _mul(_add(I3 * wd3, _mul(I2 - I1, w1, w2)), k_),
    )
    d.given(
        "A free symmetric top: no torque (N⃗ = 0⃗) and I₁ = I₂ ≠ I₃. Its angular velocity obeys "
        "Euler's equations 2.72 with N₁ = N₂ = N₃ = 0 (derivation euler_equations).",
        _eq(ZERO, euler),
    )
    d.step(
        "The first of them, with I₂ = I₁ (2.77).",
        _eq(I1 * wd1, _mul(I1 - I3, w2, w3)),
        "2.77",
    )
    d.step(
        "The second, with I₂ = I₁: the term (I₁ − I₃)ω₃ω₁ moves to the right-hand side with its "
        "sign changed. The unit prints I₂ω̇₂ = (I₁ − I₃)ω₃ω₁: the sign is wrong (2.82, which it "
        "prints right, needs this one).",
        _eq(I1 * wd2, _mul(I3 - I1, w3, w1)),
        "2.78",
    )
    d.step("The third: (I₂ − I₁)ω₁ω₂ = 0 for the symmetric top (2.79).", _eq(I3 * wd3, 0), "2.79")
    d.step("So ω₃ is constant (2.80).", _eq(wd3, 0), "2.80")
    d.given(
        "Define the constant Ω (2.83, the unit's sign; Goldstein writes the opposite one).",
        _eq(Omega, OMEGA_DEF),
        "2.83",
    )
    d.step(
        "Ω is constant, since ω₃ is (2.80).",
        _chain(Omega.diff(t), _mul((I1 - I3) / I1, wd3), 0),
    )
    d.step("Divide 2.77 by I₁ (2.81).", _chain(wd1, _mul(OMEGA_DEF, w2), _mul(Omega, w2)), "2.81")
    d.step(
        "Divide 2.78 by I₁ (2.82).",
        _chain(wd2, -_mul(OMEGA_DEF, w1), -_mul(Omega, w1)),
        "2.82",
    )
    d.step(
        "Differentiate 2.81 (Ω is constant) and use 2.82 (the unit says 'differentiate 2.82'). "
        "The unit's middle line reads Ω²ω₁: the minus sign of 2.82 was lost; its 2.84 is right.",
        _chain(w1.diff(t, 2), _mul(Omega, wd2), -(Omega**2) * w1),
        "2.84",
    )
    s1, c1 = A * sp.sin(_phase()), A * sp.cos(_phase())
    d.step(
        "2.84 is harmonic motion at angular frequency Ω: A sin(Ωt + θ₀) satisfies it for any "
        "constants A ≥ 0 and θ₀, which fit any initial ω₁ and ω̇₁, so every solution is of "
        "this form.",
        _eq(_Ddt(_Ddt(s1)), -(Omega**2) * s1),
    )
    d.step(
        "With ω₂ = A cos(Ωt + θ₀) the pair satisfies 2.81 …",
        _eq(_Ddt(s1), _mul(Omega, c1)),
    )
    d.step("… and 2.82.", _eq(_Ddt(c1), -_mul(Omega, s1)))

    # from here on: checked on the general solution
    d.model = _solution_model()
    d.step(
        "From here on the steps are checked on this solution, ω₁ = A sin(Ωt + θ₀), "
        "ω₂ = A cos(Ωt + θ₀), ω₃ constant; it satisfies Euler's equations without torque (the "
        "starting point, checked on it).",
        _eq(ZERO, euler),
    )
    d.step("The solution of 2.84 (2.85).", _eq(w1, s1), "2.85")
    d.step(
        "Put 2.85 in 2.81 (2.86; the unit integrates 2.82 instead, with the same result).",
        _chain(w2, wd1 / Omega, c1),
        "2.86",
    )
    d.step("At t = 0, ω₁(0) = A sin θ₀ …", _eq(w10, A * sp.sin(theta0)))
    d.step("… and ω₂(0) = A cos θ₀.", _eq(w20, A * sp.cos(theta0)))
    OmT = _mul(Omega, t)
    w1_of_t = _add(_mul(w10, sp.cos(OmT)), _mul(w20, sp.sin(OmT)))
    w2_of_t = _add(_mul(w20, sp.cos(OmT)), -_mul(w10, sp.sin(OmT)))
    d.step(
        "Expand the sine of the sum: ω(t) from its initial value, the part across the "
        "symmetry axis turned by −Ωt.",
        _chain(
            w1,
            _add(_mul(A, sp.sin(theta0), sp.cos(OmT)), _mul(A, sp.cos(theta0), sp.sin(OmT))),
            w1_of_t,
        ),
    )
    d.step(
        "Likewise for ω₂.",
        _chain(
            w2,
            _add(_mul(A, sp.cos(theta0), sp.cos(OmT)), -_mul(A, sp.sin(theta0), sp.sin(OmT))),
            w2_of_t,
        ),
    )
    d.given(
        "The component of ω⃗ across the symmetry axis (2.87).",
        _eq(omega_p, _add(_mul(i_, w1), _mul(j_, w2))),
        "2.87",
    )
    d.step(
        "Its magnitude is the constant A: ω⃗_p turns about the symmetry axis at rate Ω (2.88).",
        _chain(_Norm(omega_p), sp.sqrt(_add(w1**2, w2**2)), A),
        "2.88",
    )
    A_of_0 = sp.sqrt(_add(w10**2, w20**2))
    d.step("So A follows from the initial value.", _eq(A, A_of_0))
    mag = sp.sqrt(_add(A**2, w3**2))
    d.step(
        "The magnitude of ω⃗ (2.89) …",
        _chain(
            _Norm(omega),
            sp.sqrt(_add(w1**2, w2**2, w3**2)),
            sp.sqrt(_add(wp_mag**2, w3**2)),
            mag,
        ),
        "2.89",
    )
    d.step("… is constant: ω⃗ traces the body cone about k̂.", _eq(_Ddt(_Norm(omega)), 0))
    d.given(
        "The half-angle α_b of the body cone is the angle between ω⃗ and the symmetry axis k̂ "
        "(its cosine is ω⃗·k̂/|ω⃗|, its sine |ω⃗ × k̂|/|ω⃗|).",
        _eq(alpha_b, sp.atan2(_Norm(_Cross(omega, k_)), Dot(omega, k_))),
    )
    ab = sp.atan2(A, w3)
    d.step(
        "Here |ω⃗ × k̂| = |ω⃗_p| = A and ω⃗·k̂ = ω₃ …",
        _chain(alpha_b, sp.atan2(_Norm(_Cross(omega, k_)), Dot(omega, k_)), ab),
    )
    d.step("… so (2.90).", _eq(sp.tan(alpha_b), A / w3), "2.90")
    T_rhs = _add(_mul(HALF, I1, A**2), _mul(HALF, I3, w3**2))
    d.step(
        "The kinetic energy T = ½ ω⃗·I⃗·ω⃗ (2.64), with ω₁² + ω₂² = A² (2.91).",
        _chain(
            T,
            _mul(HALF, Dot(omega, Dot(I, omega))),
            _add(_mul(HALF, I1, _add(w1**2, w2**2)), _mul(HALF, I3, w3**2)),
            T_rhs,
        ),
        "2.91",
    )
    L2_rhs = _add(_mul(I1**2, A**2), _mul(I3**2, w3**2))
    d.step(
        "The square of the angular momentum L⃗ = I⃗·ω⃗ (2.93; the unit has no 2.92).",
        _chain(
            L_mag**2,
            Dot(L, L),
            _add(_mul(I1**2, _add(w1**2, w2**2)), I3**2 * w3**2),
            L2_rhs,
        ),
        "2.93",
    )
    d.step(
        "Solve 2.93 for A² (2.94).",
        _eq(A**2, _add(L_mag**2, -(I3**2) * w3**2) / I1**2),
        "2.94",
    )
    d.step(
        "Put 2.94 in 2.91 and multiply by 2I₁ …",
        _eq(_mul(2, T, I1), _add(L_mag**2, -(I3**2) * w3**2, _mul(I1, I3, w3**2))),
    )
    w3sq = _add(L_mag**2, -_mul(2, T, I1)) / _mul(I3, I3 - I1)
    d.step("… and solve for ω₃² (2.95).", _eq(w3**2, w3sq), "2.95")
    d.step(
        "Put 2.95 in 2.93 …",
        _eq(_mul(I1**2, A**2), _add(L_mag**2, -_mul(I3**2, w3sq))),
    )
    A2 = _add(L_mag**2, -_mul(2, I3, T)) / _mul(I1, I1 - I3)
    d.step("… and solve for A² (2.96; the long question 10 asks for this).", _eq(A**2, A2), "2.96")
    d.given(
        "The half-angle α_s of the space cone is the angle between ω⃗ and the fixed L⃗.",
        _eq(alpha_s, sp.atan2(_Norm(_Cross(omega, L)), Dot(omega, L))),
    )
    d.step(
        "Its cosine is ω⃗·L⃗/(ωL), and ω⃗·L⃗ = ω⃗·I⃗·ω⃗ = 2T (2.97): constant, so ω⃗ traces a "
        "cone about L⃗, fixed in space.",
        _chain(
            sp.cos(alpha_s),
            _frac(Dot(omega, L), _mul(w_mag, L_mag)),
            _frac(Dot(omega, Dot(I, omega)), _mul(w_mag, L_mag)),
            _frac(_mul(2, T), _mul(w_mag, L_mag)),
        ),
        "2.97",
    )
    cross_mag = _mul(sp.Abs(I1 - I3), A, sp.Abs(w3))
    d.step(
        "With |ω⃗ × L⃗| = |I₁ − I₃| A |ω₃| and ω⃗·L⃗ = I₁A² + I₃ω₃², α_s in closed form (accurate "
        "also for small cones, where the arccosine is not).",
        _chain(
            alpha_s,
            sp.atan2(_Norm(_Cross(omega, L)), Dot(omega, L)),
            sp.atan2(cross_mag, _add(I1 * A**2, I3 * w3**2)),
        ),
    )

    # numeric forms for the bridge to the core
    w3p, w10p, w20p = sp.symbols("omega_3 omega_10 omega_20")
    Tp, Lp = sp.symbols("T L")
    plain = {w3: w3p, w10: w10p, w20: w20p, L_mag: Lp, T: Tp}
    Om_plain = _plain(OMEGA_DEF, plain)
    d.function("2.83", Om_plain, (I1, I3, w3p))
    for number, expr in (("2.85", w1_of_t), ("2.86", w2_of_t)):
        d.function(
            number, _plain(expr, plain).xreplace({Omega: Om_plain}), (I1, I3, w10p, w20p, w3p, t)
        )
    d.function("2.88", _plain(A_of_0, plain), (w10p, w20p))
    d.function("2.89", _plain(mag, plain), (A, w3p))
    d.function("2.90", _plain(ab, plain), (A, w3p))
    d.function("2.91", _plain(T_rhs, plain), (I1, I3, A, w3p))
    d.function("2.93", _plain(L2_rhs, plain), (I1, I3, A, w3p))
    d.function("2.95", _plain(w3sq, plain), (I1, I3, Tp, Lp))
    d.function("2.96", _plain(A2, plain), (I1, I3, Tp, Lp))
    d.function(
        "2.97",
        _plain(sp.atan2(cross_mag, _add(I1 * A**2, I3 * w3**2)), plain),
        (I1, I3, A, w3p),
    )
    return d
