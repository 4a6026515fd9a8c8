"""The linearised pendulous gyrocompass (issue 26): the unit's rotating frame (2.29–2.33) and
torque law (dL⃗/dt)_fix = N⃗ applied to a rotor whose axis is held near the horizontal, derived
and checked. Not a range of the unit's equations but its theory applied:
:func:`poinsot.derive.applied` lists it, beside the unit's topics.

Coverage
--------
* The Earth's rate in the local frame, ω⃗ = Ω(0, cos λ, sin λ): its north part Ω cos λ and its
  vertical part Ω sin λ (rad/s).
* The rotor's angular momentum H ŝ along its spin axis ŝ at heading α (east of north) and tilt
  θ (the north end's elevation); the pendulous torque of the element hanging at l below the
  pivot, m g l ẑ × d̂ (N·m), to first order −m g l θ about east; Sperry's damping −D θ ẑ.
* (dL⃗/dt)_rot = N⃗ − ω⃗ × L⃗ to first order in α and θ: the two coupled linear equations
  dα/dt = Ω sin λ − (m g l/H + Ω cos λ) θ and dθ/dt = Ω cos λ α − (D/H) θ.
* Their characteristic equation s² + (D/H) s + Ω cos λ (m g l/H + Ω cos λ) = 0, the undamped
  ω_n² = Ω cos λ (m g l/H + Ω cos λ) (rad²/s²), and the period to leading order in
  Ω cos λ H/(m g l), T = 2π √(H/(m g l Ω cos λ)) (s) — :attr:`poinsot.Gyrocompass.period`.
* The settled (equilibrium) tilt and heading; the latitude (damping) error −D tan λ/(m g l +
  H Ω cos λ) (rad).
* Schuler tuning: a northward change of speed ΔV swings the axis by (m g l/(H g)) ΔV, the settle
  point moves by ΔV/(Ω R cos λ); equal for H = m g l R Ω cos λ/g, whose period is 2π √(R/g).
* The steaming error: the compass settles on the horizontal part of the Earth's rate plus the
  ship's rate over the sphere, δ = atan(V cos C/(Ω R cos λ + V sin C)) (rad).

Model
-----
Components in the local frame (x̂ east, ŷ north, ẑ up, CONVENTIONS "Gyrocompass"), α(t) and
θ(t) functions of time; (dX/dt)_rot differentiates the components. ``[X]₁`` is X to first
order in α and θ (each scaled by a bookkeeping ε, the Taylor polynomial of degree 1 in ε, then
ε = 1); every other step is an exact identity. ``Determinant`` is evaluated; cos λ > 0
(off the poles) in a check.

Results
-------
``result`` holds "Earth's rate", "pendulous torque", "heading equation", "tilt equation",
"characteristic equation", "natural frequency", "period", "settled tilt", "settle error",
"Schuler tuning", "Schuler period" and "speed error". Numeric forms
(:meth:`~poinsot.derive.Derivation.lambdify`), SI units: ``"natural frequency"``
ω_n(H, P, Ω, λ) (rad/s); ``"period"`` T(H, P, Ω, λ) (s); ``"settle error"`` (D, H, P, Ω, λ)
(rad, reading minus truth); ``"Schuler tuning"`` H(P, Ω, R, g, λ) (kg·m²/s); ``"Schuler
period"`` T(R, g) (s); ``"speed error"`` δ(V, C, Ω, R, λ) (rad). P = m g l (N·m).
``python/tests/test_derive_gyrocompass.py`` checks them against :class:`poinsot.Gyrocompass`.
"""

from __future__ import annotations

from typing import Any

import sympy as sp
from sympy.physics.vector import dynamicsymbols

from ._core import (
    Cross,
    Derivation,
    Dot,
    DtRot,
    Unit,
    Vec,
    VectorModel,
    _Notation,
)
from ._core import add as _add
from ._core import eq as _eq
from ._core import mul as _mul
from ._core import power as _pow

__all__ = ["derive"]

# ---- the notation --------------------------------------------------------------------------

t = sp.Symbol("t")
Om, lat = sp.Symbol("Omega", positive=True), sp.Symbol("lambda", real=True)
Om_c, Om_s = sp.symbols("Omega_c Omega_s")
H, m, g, l, D, R, V = sp.symbols("H m g l D R V", positive=True)
P = sp.Symbol("P", positive=True)  # m g l, the pendulosity
C = sp.Symbol("C", real=True)
s = sp.Symbol("s")
w_n, T_n, H_S, T_S, delta = sp.symbols("omega_n T H_S T_S delta", positive=True)
dV = sp.Symbol("Delta_V", real=True)
theta_eq, alpha_eq = sp.symbols("theta_* alpha_*", real=True)
alpha, theta = dynamicsymbols("alpha theta")
alpha_dot, theta_dot = alpha.diff(t), theta.diff(t)
eps = sp.Symbol("epsilon_bookkeeping")
#: cos λ in a check: positive, off the poles (where no meridian exists)
_COS = sp.Symbol("cos_lambda", positive=True)

W, W_ship, L, N_P, N_D, E = (Vec(n) for n in ("omega", "omega_ship", "L", "N_P", "N_D", "E"))
x_hat, y_hat, z_hat, s_hat, d_hat = (Unit(n) for n in ("x", "y", "z", "s", "d"))

TWO_PI = _mul(2, sp.pi)
HALF = sp.Rational(1, 2)


def _frac(n: Any, den: Any) -> Any:
    """n/den as written."""
    return sp.Mul(n, sp.Pow(den, -1, evaluate=False), evaluate=False)


class First(_Notation):
    """[X]₁: X to first order in the heading α and the tilt θ."""

    nargs = 1

    def _body_latex(self, printer: Any) -> str:
        return r"\left[" + printer._print(self.args[0]) + r"\right]_{1}"

    def _pretty(self, printer: Any) -> Any:
        from sympy.printing.pretty.stringpict import prettyForm

        return prettyForm("[" + printer._print(self.args[0]).render(wrap_line=False) + "]₁")


# ---- the model -----------------------------------------------------------------------------

_S = sp.Matrix([sp.sin(alpha) * sp.cos(theta), sp.cos(alpha) * sp.cos(theta), sp.sin(theta)])
_UP = sp.Matrix(  # the element's own up axis: ŝ tilted, no roll
    [-sp.sin(alpha) * sp.sin(theta), -sp.cos(alpha) * sp.sin(theta), sp.cos(theta)]
)
_W = Om * sp.Matrix([0, sp.cos(lat), sp.sin(lat)])
#: the ship's frame over the sphere: north speed V cos C turns it about west, east speed about
#: north (and the vertical, V sin C tan λ/R, which the compass does not seek)
_W_SHIP = sp.Matrix([-V * sp.cos(C) / R, V * sp.sin(C) / R, V * sp.sin(C) * sp.tan(lat) / R])


def _first_order(v: Any) -> Any:
    v = sp.sympify(v).subs({alpha: eps * alpha, theta: eps * theta}).doit()
    return (v.subs(eps, 0) + sp.diff(v, eps).subs(eps, 0)).subs(eps, 1)


class _Model(VectorModel):
    """ENU components, [X]₁ to first order in α, θ, determinants evaluated."""

    def __call__(self, x: Any) -> Any:
        out = self._ev(sp.sympify(x))
        fix = lambda v: (
            sp.sympify(v).subs(sp.tan(lat), sp.sin(lat) / sp.cos(lat)).subs(sp.cos(lat), _COS)
        )
        return out.applyfunc(fix) if isinstance(out, sp.MatrixBase) else fix(out)

    def _ev(self, x: Any) -> Any:
        if isinstance(x, First):
            out = self._ev(x.args[0])
            return (
                out.applyfunc(_first_order) if isinstance(out, sp.MatrixBase) else _first_order(out)
            )
        if isinstance(x, sp.Determinant):
            return self._ev(x.arg.as_explicit().det())
        if x.has(First, sp.Determinant) and isinstance(x, (sp.Add, sp.Mul)):
            from ._core import in_order

            return in_order(x, [self._ev(y) for y in x.args])
        return super()._ev(x)


def _model() -> _Model:
    torque_p = m * g * l * z_hat_v().cross(-_UP)
    ev = {
        W: _W,
        W_ship: _W_SHIP,
        x_hat: sp.Matrix([1, 0, 0]),
        y_hat: sp.Matrix([0, 1, 0]),
        z_hat: z_hat_v(),
        s_hat: _S,
        d_hat: -_UP,
        L: H * _S,
        N_P: torque_p,
        N_D: -D * theta * z_hat_v(),
    }
    # E⃗: what the torque law leaves, H (dŝ/dt)_rot + ω⃗ × Hŝ − N⃗_P − N⃗_D (zero on a motion)
    ev[E] = H * _S.diff(t) + _W.cross(H * _S) - ev[N_P] - ev[N_D]
    omega_n = sp.sqrt(Om * sp.cos(lat) * (P / H + Om * sp.cos(lat)))
    theta_star = H * Om * sp.sin(lat) / (P + H * Om * sp.cos(lat))
    return _Model(
        vectors=ev,
        dt_rot=lambda v: sp.Matrix(v).diff(t),
        scalars={
            Om_c: Om * sp.cos(lat),
            Om_s: Om * sp.sin(lat),
            w_n: omega_n,
            T_n: 2 * sp.pi * sp.sqrt(H / (P * Om * sp.cos(lat))),
            H_S: P * R * Om * sp.cos(lat) / g,
            T_S: 2 * sp.pi * sp.sqrt(R / g),
            theta_eq: theta_star,
            alpha_eq: D * theta_star / (H * Om * sp.cos(lat)),
        },
    )


def z_hat_v() -> sp.Matrix:
    """ẑ's components."""
    return sp.Matrix([0, 0, 1])


# ---- the derivation ------------------------------------------------------------------------


def derive() -> Derivation:
    """Builds and checks the derivation of the linearised pendulous gyrocompass."""
    d = Derivation(
        "gyrocompass",
        "The gyrocompass: a pendulous rotor on the turning Earth, linearised",
        summary=(
            "A rotor of angular momentum H whose axis hangs near the horizontal, torqued by "
            "gravity (m g l) whenever the Earth's rotation tilts it: the torque law in the "
            "local frame, to first order in heading α and tilt θ, gives two coupled linear "
            "equations; their characteristic equation gives the settling period "
            "2π √(H/(m g l Ω cos λ)), Schuler's 2π √(R/g) for the tuned rotor, the damping "
            "error, and the steaming error of a moving ship."
        ),
        model=_model(),
        context={P: m * g * l},
    )
    # (a) the frame and the rotor
    d.given(
        "The local frame turns with the Earth: in its axes (x̂ east, ŷ north, ẑ up at latitude "
        "λ) ω⃗ = Ω(0, cos λ, sin λ) (2.33, rad/s). The rotor's angular momentum is L⃗ = H ŝ, "
        "ŝ = (sin α cos θ, cos α cos θ, sin θ): heading α east of north, tilt θ of the north "
        "end.",
        _eq(L, _mul(H, s_hat)),
    )
    d.step(
        "The Earth's rate has a north (horizontal) part Ω_c = Ω cos λ, which the compass "
        "seeks, ...",
        _eq(Dot(y_hat, W), Om_c),
        "Earth's rate",
    )
    d.step(
        "... and a vertical part Ω_s = Ω sin λ, which turns the meridian under it.",
        _eq(Dot(z_hat, W), Om_s),
    )
    d.step(
        "The sensitive element's mass m hangs at l below the pivot along d̂ (the element's "
        "down axis): gravity's torque l d̂ × (−m g ẑ) (N·m).",
        _eq(N_P, _mul(m, g, l, Cross(z_hat, d_hat))),
    )
    d.step(
        "About east it is −m g l sin θ cos α, ...",
        _eq(Dot(x_hat, N_P), -_mul(m, g, l, sp.sin(theta), sp.cos(alpha))),
    )
    d.step(
        "... to first order ([·]₁: to first order in α and θ) the pendulous torque −P θ, with "
        "P = m g l the pendulosity (N·m).",
        _eq(First(Dot(x_hat, N_P)), -_mul(P, theta)),
        "pendulous torque",
    )
    d.given(
        "Sperry's damping: a torque about the vertical proportional to the tilt, N⃗_D = −D θ ẑ "
        "(D in N·m/rad). The rotor's spin dominates the element's angular momentum, so the "
        "torque law (dL⃗/dt)_fix = (dL⃗/dt)_rot + ω⃗ × L⃗ = N⃗_P + N⃗_D leaves nothing of E⃗:",
        _eq(E, _add(_mul(H, DtRot(s_hat)), Cross(W, L), -N_P, -N_D)),
    )
    # (b) the linear equations
    heading_rhs = _add(Om_s, -_mul(_add(_frac(P, H), Om_c), theta))
    tilt_rhs = _add(_mul(Om_c, alpha), -_mul(_frac(D, H), theta))
    d.step(
        "Its east component, to first order in α and θ, divided by H: E⃗ = 0⃗ is the heading "
        "equation dα/dt = Ω_s − (P/H + Ω_c) θ — the Earth's vertical rate drifts the axis off "
        "the meridian, the pendulous torque on a tilt brings it back.",
        _eq(_frac(First(Dot(x_hat, E)), H), _add(alpha_dot, -heading_rhs)),
        "heading equation",
    )
    d.step(
        "Its vertical component: the tilt equation dθ/dt = Ω_c α − (D/H) θ — an axis east of "
        "the meridian rises as the ground turns under it (Ω_c α), the damping lowers it.",
        _eq(_frac(First(Dot(z_hat, E)), H), _add(theta_dot, -tilt_rhs)),
        "tilt equation",
    )
    # (c) the characteristic equation and the period
    mat = sp.ImmutableMatrix([[s, _add(_frac(P, H), Om_c)], [-Om_c, _add(s, _frac(D, H))]])
    char = _add(s**2, _mul(_frac(D, H), s), _mul(Om_c, _add(_frac(P, H), Om_c)))
    d.step(
        "Free motions α, θ ∝ e^{st} (about the equilibrium below) need a zero determinant: the "
        "characteristic equation.",
        _eq(sp.Determinant(mat), char),
        "characteristic equation",
    )
    d.step(
        "Undamped (D = 0) it has s = ±iω_n, with ω_n² = Ω_c (P/H + Ω_c) (rad²/s²): the axis "
        "swings about the meridian at ω_n.",
        _eq(_add(s**2, _mul(Om_c, _add(_frac(P, H), Om_c))).subs(s, sp.I * w_n), 0),
        "natural frequency",
    )
    kappa = _frac(_mul(Om_c, H), P)
    d.step(
        "The swing's period 2π/ω_n is T (1 + Ω_c H/P)^(−1/2), and the Earth's rate is tiny "
        "beside the pendulous rate P/H (Ω_c H/P ≈ 7e-4 for a ship's compass), ...",
        _eq(_frac(TWO_PI, w_n), _mul(T_n, sp.Pow(_add(1, kappa), -HALF))),
    )
    d.step(
        "... so to leading order the period is T (s), the one Gyrocompass.period gives.",
        _eq(T_n, _mul(TWO_PI, _pow(_frac(H, _mul(m, g, l, Om, sp.cos(lat))), HALF))),
        "period",
    )
    d.function(
        "natural frequency", sp.sqrt(Om * sp.cos(lat) * (P / H + Om * sp.cos(lat))), (H, P, Om, lat)
    )
    d.function("period", 2 * sp.pi * sp.sqrt(H / (P * Om * sp.cos(lat))), (H, P, Om, lat))
    # (d) the equilibrium: the latitude (damping) error
    d.step(
        "The settled compass: both rates vanish at the tilt θ* = H Ω_s/(P + H Ω_c) (the "
        "pendulous torque cancels the vertical drift) ...",
        _eq(heading_rhs.subs(theta, theta_eq), 0),
        "settled tilt",
    )
    d.step(
        "... and the heading α* = D θ*/(H Ω_c) east of north.",
        _eq(tilt_rhs.subs({alpha: alpha_eq, theta: theta_eq}), 0),
    )
    d.step(
        "The damped compass reads −α*: the latitude (damping) error (rad), negative in the "
        "north, zero when undamped.",
        _eq(-alpha_eq, -_frac(_mul(D, sp.tan(lat)), _add(P, _mul(H, Om_c)))),
        "settle error",
    )
    d.function(
        "settle error",
        -D * sp.tan(lat) / (P + H * Om * sp.cos(lat)),
        (D, H, P, Om, lat),
    )
    # (e) Schuler tuning
    d.step(
        "A northward change of speed ΔV tilts the effective vertical: the element's inertial "
        "force −m a ŷ adds −P a/g about east, and the heading equation integrates it to a "
        "swing (P/(H g)) ΔV; the settle point (f) moves by ΔV/(Ω R cos λ). They are equal — "
        "the compass lands on its new settle point without swinging — for Schuler's "
        "H_S = m g l R Ω cos λ/g (kg·m²/s).",
        _eq(_frac(_mul(P, dV), _mul(H_S, g)), _frac(dV, _mul(Om, R, sp.cos(lat)))),
    )
    d.step(
        "Schuler's rotor (kg·m²/s): more momentum the stronger the pendulum, less toward the "
        "poles.",
        _eq(H_S, _frac(_mul(m, g, l, R, Om, sp.cos(lat)), g)),
        "Schuler tuning",
    )
    d.function("Schuler tuning", P * R * Om * sp.cos(lat) / g, (P, Om, R, g, lat))
    d.step(
        "Its period is the Schuler period 2π √(R/g) (s), 84.4 min on the Earth, whatever the "
        "latitude: the period of a pendulum as long as the Earth's radius.",
        _eq(_mul(TWO_PI, _pow(_frac(H_S, _mul(P, Om, sp.cos(lat))), HALF)), T_S),
        "Schuler period",
    )
    d.function("Schuler period", 2 * sp.pi * sp.sqrt(R / g), (R, g))
    # (f) the steaming error
    d.given(
        "A ship at speed V on course C (clockwise from north) carries the local frame over the "
        "sphere of radius R: it turns at ω⃗_ship = (−V cos C/R, V sin C/R, V sin C tan λ/R) "
        "besides the Earth's ω⃗. The compass settles on the horizontal part of ω⃗ + ω⃗_ship.",
        _eq(Vec("omega_total"), _add(W, W_ship)),
    )
    d.step(
        "Its east part ...",
        _eq(Dot(x_hat, _add(W, W_ship)), -_frac(_mul(V, sp.cos(C)), R)),
    )
    d.step(
        "... and its north part:",
        _eq(Dot(y_hat, _add(W, W_ship)), _add(_mul(Om, sp.cos(lat)), _frac(_mul(V, sp.sin(C)), R))),
    )
    d.step(
        "so the axis settles δ west of north, δ the speed (steaming) error (rad, the compass "
        "reads high on northerly courses): tan δ = V cos C/(Ω R cos λ + V sin C); for "
        "V ≪ Ω R cos λ the manufacturers' V cos C/(Ω R cos λ).",
        _eq(
            -_frac(Dot(x_hat, _add(W, W_ship)), Dot(y_hat, _add(W, W_ship))),
            _frac(_mul(V, sp.cos(C)), _add(_mul(Om, R, sp.cos(lat)), _mul(V, sp.sin(C)))),
        ),
        "speed error",
    )
    d.function(
        "speed error",
        sp.atan(V * sp.cos(C) / (Om * R * sp.cos(lat) + V * sp.sin(C))),
        (V, C, Om, R, lat),
    )
    return d
