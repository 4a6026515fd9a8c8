"""Templates of tops (the unit's eqs. 2.77–2.121): the free symmetric top's precession and cones,
the Dzhanibekov flip, Euler angles and ω, the heavy top's steady precession, minimum spin and
nutation bounds."""

from __future__ import annotations

import math
from functools import partial
from typing import Any

import numpy as np

from ...body import RigidBody
from ...dynamics import simulate
from ...free import FreeRigidBody, FreeSymmetricTop
from ...rotation import body_angular_velocity
from ...top import HeavyTop
from .._build import derived, draws, plain, prose, scaled
from .._steps import Mistake, Plain
from .._template import Template

_G = 9.80665

# ---- the free symmetric top: Ω (2.83, L 10) and the cones (2.90–2.97) ----------------------------


def _cylinder(v: Any) -> tuple[float, float]:
    """(I₁, I₃) of the solid cylinder (kg·m²), from the public API."""
    moments = RigidBody.solid_cylinder(v.mass, v.radius, v.height).inertia.diagonal()
    return float(moments[0]), float(moments[2])


def _cyl_extra(v: Any) -> dict[str, float]:
    i1, i3 = _cylinder(v)
    return {"I1": i1, "I3": i3}


def _precession(v: Any) -> float:
    return float(FreeSymmetricTop(v.I1, v.I3, [v.wobble, 0.0, v.spin]).precession_rate)


def _precession_by_integration(v: Any) -> float:
    """Ω from ω(t) integrated by :func:`poinsot.simulate`: ω₁ + iω₂ turns at −Ω (eq. 2.82)."""
    period = 2 * math.pi / abs(v.spin * (v.I1 - v.I3) / v.I1)
    run = simulate(
        [v.I1, v.I1, v.I3],
        [v.wobble, 0.0, v.spin],
        3 * period,
        method="rk4",
        dt=period / 4000,
        samples=601,
    )
    phase = np.unwrap(np.arctan2(run.omega[:, 1], run.omega[:, 0]))
    return float(-(phase[-1] - phase[0]) / (run.t[-1] - run.t[0]))


#: A template of the thrown cylinder: its parameters, statement and moments.
_thrown_cylinder = partial(
    Template,
    topic="free tops",
    params=draws("g", mass=(100, 900, 20))
    + draws("cm", radius=(2, 10, 0.5), height=(1, 30, 1))
    + draws("rpm", spin=(60, 600, 30), wobble=(1, 20, 1)),
    text=prose("""A solid uniform cylinder of mass {mass}, radius {radius} and height {height} is
        thrown spinning in free fall (no torque) at ω₃ = {spin} about its axis, with a small wobble
        ω₁ = {wobble} across it (ω₂ = 0)."""),
    extra=_cyl_extra,
)
_CYLINDER_MOMENT = "rigid_body solid_cylinder[{}](mass, radius, height)"

FREE_PRECESSION = _thrown_cylinder(
    name="free-top-precession",
    title="The precession of a thrown cylinder",
    question=prose("""At what rate Ω = (I₁ − I₃)ω₃/I₁ does ω precess about the axis in the body
        (the unit's sign: ω̇₁ = Ωω₂), in rad/s?"""),
    answer=_precession,
    check=_precession_by_integration,
    agree=1e-6,
    agree_why="RK4 with 4000 steps a period: error ~ (Ω dt)⁴ ≈ 6e-13 relative; the phase read "
    "from 601 samples is exact (no interpolation)",
    steps=(
        derived(
            "I₁ of the cylinder about a diameter", "I_1 [kg*m**2] = " + _CYLINDER_MOMENT.format(0)
        ),
        derived("I₃ about its axis", "I_3 [kg*m**2] = " + _CYLINDER_MOMENT.format(8)),
        derived(
            "Euler's equations with I₂ = I₁ give Ω",
            r"\Omega [rad/s] = torque_free_top 2.83(I1, I3, spin)",
        ),
    ),
    mistakes=(
        Mistake(
            "the unit's 2.78 sign",
            "used the misprinted 2.78 (I₁ − I₃ swapped): the sign of Ω flips",
            4,
            lambda v: -_precession(v),
        ),
        Mistake(
            "rpm as rad/s",
            "used ω₃ in rpm as if in rad/s",
            1,
            lambda v: _precession(v) * 60 / (2 * math.pi),
        ),
        Mistake(
            "I₃ in the denominator",
            "divided by I₃ instead of I₁",
            4,
            lambda v: (v.I1 - v.I3) * v.spin / v.I3,
        ),
    ),
    difficulty=2,
    answer_range=(-100.0, 100.0),
)


def _cones(v: Any) -> float:
    return float(FreeSymmetricTop(v.I1, v.I3, [v.wobble, 0.0, v.spin]).space_cone_angle)


FREE_CONES = _thrown_cylinder(
    name="free-top-cones",
    title="The space cone of a thrown cylinder",
    question=prose("""What is the half-angle of the space cone, the cone ω sweeps about the fixed
        L, in degrees?"""),
    answer=_cones,
    check=lambda v: abs(math.atan2(v.I1 * v.wobble, v.I3 * v.spin) - math.atan2(v.wobble, v.spin)),
    agree=1e-9,
    agree_why="the core's cone angles against the angle between L = I·ω and ω by hand",
    steps=(
        derived(
            "The body cone: ω against the axis",
            r"\alpha [deg] = torque_free_top 2.90(wobble, spin)",
        ),
        plain(
            "L = (I₁ω₁, 0, I₃ω₃) against the axis",
            r"\beta [deg] = \arctan\frac{{I_1\,\omega_1}}{{I_3\,\omega_3}}",
            lambda v: math.atan2(v.I1 * v.wobble, v.I3 * v.spin),
        ),
        plain(
            "The space cone's half-angle is the angle between ω and L",
            r"\gamma [deg] = |\beta - \alpha|",
            _cones,
        ),
    ),
    mistakes=(
        Mistake(
            "the body cone",
            "gave the body cone's half-angle",
            4,
            lambda v: math.atan2(v.wobble, v.spin),
        ),
        Mistake(
            "L's angle",
            "gave the angle of L from the axis",
            4,
            lambda v: math.atan2(v.I1 * v.wobble, v.I3 * v.spin),
        ),
    ),
    difficulty=3,
    answer_range=(0.0, 90.0),
)


# ---- the Dzhanibekov flip (the exact free body, elliptic functions) ------------------------------


def _agm_k(m: float) -> float:
    """K(m) = π / (2 AGM(1, √(1 − m))), Gauss's arithmetic-geometric mean."""
    a, b = 1.0, math.sqrt(1.0 - m)
    while abs(a - b) > 1e-15 * a:
        a, b = (a + b) / 2, math.sqrt(a * b)
    return math.pi / (2 * a)


def _flip_period_by_hand(v: Any) -> float:
    """The period of ω(t) (Landau & Lifshitz, Mechanics, §37): 4K(k²)/rate, I₁ < I₂ < I₃."""
    i1, i2, i3 = v.I1, v.I2, v.I3
    w = np.array([v.wobble, v.spin, v.wobble])
    e2 = float(np.dot([i1, i2, i3], w**2))
    l2 = float(np.dot(np.array([i1, i2, i3]) ** 2, w**2))
    if l2 > e2 * i2:
        rate2, m = (i3 - i2) * (l2 - e2 * i1), (i2 - i1) * (e2 * i3 - l2)
    else:
        rate2, m = (i2 - i1) * (e2 * i3 - l2), (i3 - i2) * (l2 - e2 * i1)
    return 4 * _agm_k(m / rate2) / math.sqrt(rate2 / (i1 * i2 * i3))


def _flip_period(v: Any) -> float:
    return float(FreeRigidBody([v.I1, v.I2, v.I3], [v.wobble, v.spin, v.wobble]).period)


DZHANIBEKOV = Template(
    name="dzhanibekov-flip",
    title="The Dzhanibekov flip of a T-handle",
    text=prose("""A T-handle floats in a space station. Its principal moments are I₁ = {I1}, I₂ =
        {I2}, I₃ = {I3}. It is set spinning at ω₂ = {spin} about the intermediate axis 2, with
        small disturbances ω₁ = ω₃ = {wobble}."""),
    params=draws("g*cm**2", I1=(40, 50, 1), I2=(60, 70, 1), I3=(80, 100, 1))
    + draws("rpm", spin=(120, 600, 30), wobble=(1, 5, 0.5)),
    question=prose("""After how long is ω back to its starting value (one full period of ω(t): two
        flips), in s?"""),
    answer=_flip_period,
    check=_flip_period_by_hand,
    agree=1e-9,
    agree_why="the core's Carlson-integral period against K(k) by Gauss's AGM",
    steps=(
        plain(
            "The energy and the angular momentum: 2T = Σ I ω², L² = Σ I² ω²",
            r"[J] = 2T = I_1\omega_1^2 + I_2\omega_2^2 + I_3\omega_3^2",
            lambda v: v.I1 * v.wobble**2 + v.I2 * v.spin**2 + v.I3 * v.wobble**2,
        ),
        plain(
            "The period of ω(t) is 4K(k)/λ with Landau's λ and k (Mechanics §37)",
            r"T [s] = \frac{{4K(k)}}{{\lambda}}",
            _flip_period,
        ),
    ),
    mistakes=(
        scaled(
            "one flip", "gave the time between two flips (half the period)", 3, _flip_period, 0.5
        ),
        Mistake(
            "rpm as rad/s", "used rpm as rad/s", 1, lambda v: _flip_period(v) * 2 * math.pi / 60
        ),
    ),
    topic="free tops",
    difficulty=3,
    answer_range=(0.05, 1e3),
)


# ---- Euler angles and ω (2.99, L 11) ---------------------------------------------------------------


def _omega1(v: Any) -> float:
    w = body_angular_velocity([v.phi, v.theta, v.psi], [v.phi_dot, v.theta_dot, v.psi_dot])
    return float(w[0])


_OMEGA_1 = "euler_angles 2.99[0](phi, theta, psi, phi_dot, theta_dot, psi_dot)"

EULER_RATES = Template(
    name="euler-rates",
    title="ω from the rates of the Euler angles",
    text=prose("""A body's attitude is given by the unit's z-x-z Euler angles φ = {phi}, θ =
        {theta}, ψ = {psi}, changing at φ̇ = {phi_dot}, θ̇ = {theta_dot}, ψ̇ = {psi_dot}."""),
    params=draws("deg", phi=(0, 350, 10), theta=(10, 170, 5), psi=(5, 355, 5))
    + draws("deg/s", phi_dot=(-90, 90, 5), theta_dot=(-90, 90, 5), psi_dot=(-360, 360, 10)),
    question="What is the component ω₁ of its angular velocity along body axis 1, in rad/s?",
    answer=_omega1,
    agree=1e-12,
    agree_why="the core's 2.99 against the derivation's 2.99 (same closed form)",
    steps=(derived("ω₁ = φ̇ sin θ sin ψ + θ̇ cos ψ", r"\omega_1 [rad/s] = " + _OMEGA_1),),
    mistakes=(
        Mistake(
            "degrees for radians",
            "put the rates in °/s into the formula",
            1,
            lambda v: _omega1(v) * 180 / math.pi,
        ),
        Mistake(
            "sin ψ ↔ cos ψ",
            "swapped sin ψ and cos ψ (that is ω₂'s pattern)",
            2,
            lambda v: (
                v.phi_dot * math.sin(v.theta) * math.cos(v.psi) + v.theta_dot * math.sin(v.psi)
            ),
        ),
    ),
    topic="euler angles",
    difficulty=2,
    answer_range=(-10.0, 10.0),
)


# ---- the heavy top (2.102–2.121, L 12) ------------------------------------------------------------


def _top_extra(v: Any) -> dict[str, float]:
    return {"mgl": v.mass * _G * v.arm, "p_psi": v.I3 * getattr(v, "spin", 0.0)}


_TOP = (
    draws("g*cm**2", I1=(2000, 6000, 100), I3=(1000, 3000, 100))
    + draws("g", mass=(50, 120, 5))
    + draws("cm", arm=(1, 4, 0.5))
    + draws("deg", theta0=(10, 70, 5))
    + draws("rpm", spin=(1500, 4000, 100))
)
_TOP_TEXT = (
    "A top with I₁ = {I1} about a horizontal axis through its pivot and I₃ = {I3} about its "
    "symmetry axis has mass {mass}; its centre of mass is {arm} from the pivot (g = 9.807 m/s²). "
)
_SPINNING = _TOP_TEXT + "It spins at ω₃ = {spin} with its axis at θ₀ = {theta0} from the vertical."
#: A heavy top's template: its parameters, statement, mgl and p_ψ.
_heavy_top = partial(
    Template,
    topic="heavy top",
    params=_TOP,
    text=_SPINNING,
    extra=_top_extra,
)
_MGL = plain(
    "The torque's strength mgl", r"mgl [N*m] = {mass}\cdot 9.807 \cdot {arm}", lambda v: v.mgl
)
_P_PSI = r"p_\psi [kg*m**2/s] = {I3}\cdot{spin}"


def _rates(v: Any) -> tuple[float, float]:
    slow, fast = HeavyTop.steady_precession_rates(v.I1, v.I3, v.mgl, v.theta0, v.spin)
    return float(slow), float(fast)


def _steady(
    branch: int, first: Plain, mistakes: tuple[Mistake, ...], answer_range: tuple[float, float]
) -> Template:
    """The heavy top's steady precession on its slow (0) or fast (1) branch: the core's roots of
    2.116 against the derivation's 2.117."""
    name = ("slow", "fast")[branch]
    root = f"heavy_top 2.117 {name}(I1, I3, mgl, theta0, spin)"
    return _heavy_top(
        name=f"top-{name}-precession",
        title=f"The heavy top's {name} steady precession",
        question=f"At what rate φ̇ does it precess steadily on the {name} branch, in rpm?",
        answer=lambda v: _rates(v)[branch],
        agree=1e-9,
        agree_why="the core's roots of 2.116 against the derivation's 2.117 (a sympy root)",
        steps=(
            first,
            derived(
                f"The {name} root of the steady-precession quadratic",
                rf"\dot\phi_\mathrm{{{name}}} [rpm] = {root}",
            ),
        ),
        mistakes=mistakes,
        difficulty=2,
        answer_range=answer_range,
    )


SLOW = _steady(
    0,
    _MGL,
    (
        Mistake(
            "the gyroscope formula",
            "used the fast-spin limit mgl/(I₃ω₃) (2.121)",
            3,
            lambda v: v.mgl / (v.I3 * v.spin),
        ),
        Mistake(
            "rad/s, not rpm", "gave the rate in rad/s", 3, lambda v: _rates(v)[0] * 2 * math.pi / 60
        ),
    ),
    (0.1, 500.0),
)

FAST = _steady(
    1,
    plain("p_ψ = I₃ω₃", _P_PSI, lambda v: v.p_psi),
    (
        Mistake(
            "the unit's 2.120",
            "used the unit's misprinted 2.120, p_ψ/(2I₁cos θ₀): the factor 2 is wrong",
            3,
            lambda v: v.p_psi / (2 * v.I1 * math.cos(v.theta0)),
        ),
        Mistake(
            "the approximation 2.120",
            "gave the fast-spin estimate p_ψ/(I₁cos θ₀)",
            3,
            lambda v: v.p_psi / (v.I1 * math.cos(v.theta0)),
        ),
    ),
    (100.0, 1e5),
)


def _min_spin(v: Any) -> float:
    return float(HeavyTop.min_spin(v.I1, v.I3, v.mgl, v.theta0))


_LEAST = "heavy_top 2.119(I1, I3, mgl, theta0)"

MIN_SPIN = _heavy_top(
    name="top-min-spin",
    title="The least spin for steady precession",
    text=_TOP_TEXT + "Its axis is held at θ₀ = {theta0} from the vertical.",
    params=_TOP[:5],
    question="What is the least spin ω₃ for which it can precess steadily at θ₀, in rpm?",
    answer=_min_spin,
    agree=1e-12,
    agree_why="the core's 2.119 against the derivation's 2.119",
    steps=(
        _MGL,
        derived(
            "The discriminant of 2.116 must not be negative", r"\omega_{3,\min} [rpm] = " + _LEAST
        ),
    ),
    mistakes=(
        Mistake(
            "no cos θ₀",
            "left out cos θ₀ (that is the sleeping top's threshold)",
            3,
            lambda v: _min_spin(v) / math.sqrt(math.cos(v.theta0)),
        ),
        scaled("no factor 4", "left out the 4 under the root", 3, _min_spin, 0.5),
        Mistake(
            "rad/s, not rpm", "gave the spin in rad/s", 3, lambda v: _min_spin(v) * 2 * math.pi / 60
        ),
    ),
    difficulty=2,
    answer_range=(10.0, 5000.0),
)


def _lowest(v: Any) -> float:
    return float(HeavyTop(v.I1, v.I3, v.mgl, v.theta0, psi_dot=v.spin).turning_points[1])


def _dip(v: Any) -> float:
    return _lowest(v) - v.theta0


def _lowest_by_hand(v: Any) -> float:
    """θ₂ from the released top's cubic f(u) = (u₁ − u)[(2mgl/I₁)(1 − u²) − (p_ψ/I₁)²(u₁ − u)]
    (θ̇ = φ̇ = 0 at u₁ = cos θ₀): the root of the bracket in [−1, u₁]."""
    u1, a, b = math.cos(v.theta0), 2 * v.mgl / v.I1, (v.p_psi / v.I1) ** 2
    roots = np.roots([-a, b, a - b * u1])
    u2 = max(r.real for r in roots if abs(r.imag) < 1e-12 and r.real <= u1 + 1e-12)
    return math.acos(min(u2, 1.0))


NUTATION = _heavy_top(
    name="top-nutation",
    title="How far a released top dips",
    text=_SPINNING + " It is released with its axis at rest (θ̇ = φ̇ = 0).",
    question=prose("""By how much does its axis dip as it nutates: the largest angle θ₂ from the
        vertical less θ₀, in degrees?"""),
    answer=_dip,
    check=lambda v: _lowest_by_hand(v) - v.theta0,
    agree=1e-7,
    agree_why="the core's turning points against numpy's roots of the quadratic factor "
    "(θ₂ − θ₀ is small: its conditioning amplifies the roots' round-off)",
    steps=(
        plain(
            "The conserved p_ψ = I₃ω₃; at release p_φ = p_ψ cos θ₀ and E′ = mgl cos θ₀",
            _P_PSI,
            lambda v: v.p_psi,
        ),
        plain(
            "θ̇ = 0 again where (2mgl/I₁)(1 − u²) = (p_ψ/I₁)²(cos θ₀ − u), u = cos θ",
            r"\theta_2 [deg] = \arccos u_2",
            _lowest,
        ),
        plain("The dip", r"\Delta\theta [deg] = \theta_2 - \theta_0", _dip),
    ),
    mistakes=(
        Mistake(
            "no spin",
            "ignored the spin: a pendulum would swing to π − θ₀",
            3,
            lambda v: math.pi - 2 * v.theta0,
        ),
        Mistake("θ₂ itself", "gave θ₂, not the dip θ₂ − θ₀", 4, _lowest),
        Mistake(
            "radians, not degrees", "gave the dip in radians", 4, lambda v: _dip(v) * math.pi / 180
        ),
    ),
    difficulty=3,
    answer_range=(0.0, 90.0),
)

ENTRIES = (FREE_PRECESSION, FREE_CONES, DZHANIBEKOV, EULER_RATES, SLOW, FAST, MIN_SPIN, NUTATION)
