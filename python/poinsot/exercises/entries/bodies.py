"""Templates of rigid bodies (the unit's eqs. 2.43–2.76): the inertia of a composite body and its
principal moments, the rotating dumbbell's kinetic energy and holding torque, and the power of a
torque by Euler's equations (L 9)."""

from __future__ import annotations

import math
from functools import partial
from typing import Any

import numpy as np

from ...body import RigidBody
from .._build import derived, draws, plain, prose, route, scaled
from .._steps import Mistake
from .._template import Template

# ---- a composite body: a rod with a ball on its end (parallel axes; L 8) --------------------------


def _lollipop(v: Any) -> RigidBody:
    rod = RigidBody.thin_rod(v.rod_mass, v.length).translated([0.0, 0.0, v.length / 2])
    ball = RigidBody.solid_sphere(v.ball_mass, v.radius).translated([0.0, 0.0, v.length + v.radius])
    return RigidBody.combine([rod, ball])


def _lollipop_hand(v: Any, parallel: bool = True, ball_spread: bool = True) -> float:
    """I about the centre of mass, perpendicular to the rod, by the parallel-axis theorem."""
    m, M, L, R = v.rod_mass, v.ball_mass, v.length, v.radius
    zc = (m * L / 2 + M * (L + R)) / (m + M)
    own = m * L**2 / 12 + (0.4 * M * R**2 if ball_spread else 0.0)
    return own + (m * (L / 2 - zc) ** 2 + M * (L + R - zc) ** 2 if parallel else 0.0)


COMPOSITE = Template(
    name="composite-inertia",
    title="A rod with a ball on its end",
    text=prose("""A thin uniform rod of mass {rod_mass} and length {length} carries on one end a
        solid ball of mass {ball_mass} and radius {radius}, its centre on the rod's line, the ball
        touching the rod's end."""),
    params=draws("g", rod_mass=(50, 500, 10))
    + draws("cm", length=(10, 60, 1))
    + draws("g", ball_mass=(100, 1000, 10))
    + draws("cm", radius=(2, 8, 0.5)),
    question=prose("""What is the body's moment of inertia about an axis through its centre of mass
        perpendicular to the rod, in kg·cm²?"""),
    answer=lambda v: float(_lollipop(v).principal_moments[-1]),
    check=_lollipop_hand,
    agree=1e-9,
    agree_why="the core's composition of tensors against the parallel-axis theorem by hand",
    steps=(
        plain(
            "The centre of mass, from the rod's free end",
            r"z_c [cm] = \frac{{m\,L/2 + M\,(L + R)}}{{m + M}}",
            lambda v: (
                (v.rod_mass * v.length / 2 + v.ball_mass * (v.length + v.radius))
                / (v.rod_mass + v.ball_mass)
            ),
        ),
        derived(
            "The rod about its own centre",
            "I_{rod} [kg*cm**2] = rigid_body thin_rod[0](rod_mass, length)",
        ),
        derived(
            "The ball about its own centre",
            "I_{ball} [kg*cm**2] = rigid_body solid_sphere[0](ball_mass, radius)",
        ),
        plain(
            "Both moved to the common centre (parallel axes, eq. 2.65)",
            r"I [kg*cm**2] = I_{{rod}} + m d_1^2 + I_{{ball}} + M d_2^2",
            _lollipop_hand,
        ),
    ),
    mistakes=(
        Mistake(
            "no parallel-axis terms",
            "added the two moments about their own centres",
            5,
            lambda v: _lollipop_hand(v, parallel=False),
        ),
        Mistake(
            "ball as a point",
            "took the ball as a point mass at its centre",
            4,
            lambda v: _lollipop_hand(v, ball_spread=False),
        ),
        Mistake(
            "about the free end",
            "took the moments about the rod's free end, not the centre of mass",
            2,
            lambda v: (
                v.rod_mass * v.length**2 / 3
                + 0.4 * v.ball_mass * v.radius**2
                + v.ball_mass * (v.length + v.radius) ** 2
            ),
        ),
    ),
    topic="rigid bodies",
    difficulty=2,
    answer_range=(1.0, 1e3),
)


# ---- point masses: the inertia tensor and its principal moments (2.51–2.60) ----------------------


def _points(v: Any) -> tuple[np.ndarray, np.ndarray]:
    masses = np.array([v.m1, v.m2, v.m3])
    positions = np.array([[v.x1, 0.0, 0.0], [0.0, v.y2, 0.0], [v.x3, v.y3, 0.0]])
    return masses, positions


def _tensor(v: Any, about_cm: bool = True) -> np.ndarray:
    """The unit's I = Σ m (r² 1 − r rᵀ) (eqs. 2.55–2.57: products of inertia negated), about the
    centre of mass (or the origin)."""
    m, r = _points(v)
    if about_cm:
        r = r - (m @ r) / m.sum()
    return np.einsum(
        "a,aij->ij", m, (r**2).sum(1)[:, None, None] * np.eye(3) - r[:, :, None] * r[:, None, :]
    )


POINT_MASSES = Template(
    name="principal-moments",
    title="The principal moments of three point masses",
    text=prose("""Three small balls are fixed on a light frame in the xy plane: {m1} at ({x1}, 0),
        {m2} at (0, {y2}) and {m3} at ({x3}, {y3})."""),
    params=draws("kg", m1=(1, 5, 0.5))
    + draws("cm", x1=(10, 50, 1))
    + draws("kg", m2=(1, 5, 0.5))
    + draws("cm", y2=(10, 50, 1))
    + draws("kg", m3=(1, 5, 0.5))
    + draws("cm", x3=(10, 50, 1), y3=(10, 50, 1)),
    question="What is the smallest principal moment of inertia about the centre of mass, in kg·m²?",
    answer=lambda v: float(RigidBody.from_point_masses(*_points(v)).principal_moments[0]),
    check=lambda v: float(np.linalg.eigvalsh(_tensor(v))[0]),
    agree=1e-9,
    agree_why="the core's tensor and eigen-solver against numpy's eigvalsh of the unit's 2.55",
    steps=(
        plain(
            "The centre of mass, then the tensor about it: I_xx = Σm y², I_yy = Σm x², "
            "I_zz = I_xx + I_yy, I_xy = −Σm x y (eqs. 2.55–2.57)",
            r"I_{xy} [kg*m**2] = I_{{xy}} = -\sum m\,x\,y",
            lambda v: float(_tensor(v)[0, 1]),
        ),
        plain(
            "The principal moments are the eigenvalues of I (eq. 2.60): the smallest",
            r"I_1 [kg*m**2] = \tfrac12 (I_{{xx}} + I_{{yy}}) - \sqrt{{\tfrac14 (I_{{xx}} - I_{{yy}})^2 + I_{{xy}}^2}}",
            lambda v: float(np.linalg.eigvalsh(_tensor(v))[0]),
        ),
    ),
    mistakes=(
        Mistake(
            "about the origin",
            "took the moments about the origin, not the centre of mass",
            2,
            lambda v: float(np.linalg.eigvalsh(_tensor(v, about_cm=False))[0]),
        ),
        Mistake(
            "smallest diagonal entry",
            "gave the smallest of I_xx, I_yy: the axes x, y are not principal",
            3,
            lambda v: float(min(_tensor(v)[0, 0], _tensor(v)[1, 1])),
        ),
        Mistake(
            "cm for m",
            "left the positions in cm",
            1,
            lambda v: float(np.linalg.eigvalsh(_tensor(v))[0]) * 1e4,
        ),
    ),
    topic="rigid bodies",
    difficulty=3,
    answer_range=(1e-6, 10.0),
)


# ---- the rotating dumbbell: T and the holding torque (2.43–2.50, the unit's example) -------------


def _dumbbell(v: Any) -> RigidBody:
    u = np.array([math.sin(v.tilt), 0.0, math.cos(v.tilt)]) * v.arm
    return RigidBody.from_point_masses([v.mass, v.mass], [u, -u])


def _torque(v: Any) -> float:
    return float(np.linalg.norm(_dumbbell(v).holding_torque([0.0, 0.0, v.rate])))


def _energy(v: Any) -> float:
    return float(_dumbbell(v).kinetic_energy([0.0, 0.0, v.rate]))


#: A template of the rotating dumbbell: its parameters and statement.
_dumbbell_template = partial(
    Template,
    topic="rigid bodies",
    params=draws("g", mass=(50, 500, 10))
    + draws("cm", arm=(5, 30, 1))
    + draws("deg", tilt=(10, 80, 1))
    + draws("rpm", rate=(60, 1200, 30)),
    text=prose("""Two small balls of {mass} each sit on a light rod, {arm} either side of its
        midpoint. The rod turns at {rate} about a fixed axis through its midpoint, making a
        constant angle {tilt} with the axis."""),
)
_DUMBBELL_TORQUE = "rigid_body dumbbell_torque[1](mass, mass, arm, arm, tilt, rate)"
_torque_y = route(_DUMBBELL_TORQUE)
#: 1 rpm taken for 1 rad/s: a rate's square is (60/2π)² too large.
_RPM_SQUARED = (60 / (2 * math.pi)) ** 2

DUMBBELL_TORQUE = _dumbbell_template(
    name="dumbbell-torque",
    title="The torque that holds a rotating dumbbell",
    question="What torque must the bearings exert to keep it turning, in N·m?",
    answer=_torque,
    check=lambda v: abs(_torque_y(v)),
    agree=1e-12,
    agree_why="the core's ω×L against the derivation's dumbbell torque",
    steps=(
        derived("The torque ω × L for ω along the axis", "N_y [N*m] = " + _DUMBBELL_TORQUE),
        plain("The torque is along −y, of magnitude |N_y|", "N [N*m] = |N_y|", _torque),
    ),
    mistakes=(
        scaled(
            "rpm as rad/s",
            "used the rate in rpm as if in rad/s (1 rpm = 2π/60 rad/s)",
            1,
            _torque,
            _RPM_SQUARED,
        ),
        Mistake(
            "sin for sin 2α",
            "took the lever as sin α: the torque is m r² ω² sin 2α = 2 m r² ω² sin α cos α",
            2,
            lambda v: 2 * v.mass * v.arm**2 * v.rate**2 * math.sin(v.tilt),
        ),
        scaled("one ball", "counted one ball only", 2, _torque, 0.5),
    ),
    difficulty=2,
    answer_range=(1e-5, 1e3),
)

DUMBBELL_ENERGY = _dumbbell_template(
    name="dumbbell-energy",
    title="The kinetic energy of a rotating dumbbell",
    question="What is its kinetic energy, in J?",
    answer=_energy,
    check=lambda v: v.mass * (v.arm * math.sin(v.tilt) * v.rate) ** 2,
    agree=1e-12,
    agree_why="the core's ½ω·I·ω against ½ Σ m v² with v = ω r sin α by hand",
    steps=(
        plain(
            "Each ball moves on a circle of radius r sin α at speed ω r sin α",
            r"v [m/s] = {arm} \sin {tilt}\,{rate}",
            lambda v: v.arm * math.sin(v.tilt) * v.rate,
        ),
        plain("T = ½ ω·I·ω = 2 · ½ m v² (eq. 2.50)", r"T [J] = {mass}\,v^2", _energy),
    ),
    mistakes=(
        scaled("rpm as rad/s", "used the rate in rpm as if in rad/s", 1, _energy, _RPM_SQUARED),
        Mistake(
            "cos for sin",
            "took the distance from the axis as r cos α",
            2,
            lambda v: v.mass * (v.arm * math.cos(v.tilt) * v.rate) ** 2,
        ),
    ),
    difficulty=1,
    answer_range=(1e-6, 1e3),
)

# ---- Euler's equations and the work of the torque (2.72, 2.75–2.76; L 9) ---------------------------

#: Euler's equations (2.72) solved for ω̇ᵢ, i = 0, 1, 2.
_EULER = "euler_equations 2.72[{}](I1, I2, I3, w1, w2, w3, N1, N2, N3)"
#: dT/dt = Σ Iᵢ ωᵢ ω̇ᵢ (W), the derivation's 2.76.
_POWER = "euler_equations 2.76(I1, I2, I3, w1, w2, w3, wdot1, wdot2, wdot3)"


def _euler_extra(v: Any) -> dict[str, float]:
    """ω̇ (rad/s²) from Euler's equations (2.72) of the derivation, for the steps and the answer."""
    return {f"wdot{i + 1}": route(_EULER.format(i))(v) for i in range(3)}


#: dT/dt (W): the derivation's 2.76 with ω̇ from Euler's equations 2.72.
_power = route(_POWER)


def _dot_wn(v: Any) -> float:
    return v.w1 * v.N1 + v.w2 * v.N2 + v.w3 * v.N3


EULER_POWER = Template(
    name="euler-power",
    title="The power of a torque, by Euler's equations",
    text=prose("""A rigid body has principal moments of inertia I₁ = {I1}, I₂ = {I2}, I₃ = {I3}. At
        one instant it turns with ω = ({w1}, {w2}, {w3}) along its principal axes, and a torque
        with components N₁ = {N1}, N₂ = {N2}, N₃ = {N3} along the same axes acts on it."""),
    params=draws("kg*cm**2", I1=(50, 500, 10), I2=(50, 500, 10), I3=(50, 500, 10))
    + draws("rad/s", w1=(1, 10, 0.5), w2=(1, 10, 0.5), w3=(1, 10, 0.5))
    + draws("mN*m", N1=(-50, 50, 5), N2=(-50, 50, 5), N3=(-50, 50, 5)),
    question="At what rate is its kinetic energy changing at that instant, in mW?",
    answer=_power,
    check=_dot_wn,
    agree=1e-9,
    agree_why="ω̇ from Euler's equations (2.72) and dT/dt = Σ Iᵢωᵢω̇ᵢ (2.76), both from the "
    "derivation, against the energy theorem ω·N (2.75) by hand",
    steps=(
        *(
            derived(
                f"ω̇{sub} from Euler's {nth} equation",
                rf"\dot\omega_{i + 1} [rad/s**2] = " + _EULER.format(i),
            )
            for i, (sub, nth) in enumerate(zip("₁₂₃", ("first", "second", "third")))
        ),
        derived(
            "dT/dt = ω·I·ω̇; the gyroscopic terms cancel, leaving ω·N (2.75–2.76)",
            r"\frac{dT}{dt} [mW] = " + _POWER,
        ),
    ),
    mistakes=(
        Mistake(
            "half the power",
            "took dT/dt = ½ ω·N from T = ½ ω·I·ω: the derivative of the square gives a factor 2",
            5,
            lambda v: _dot_wn(v) / 2,
        ),
        Mistake(
            "one axis only",
            "kept only the first axis, I₁ω₁ω̇₁",
            5,
            lambda v: v.I1 * v.w1 * v.wdot1,
        ),
    ),
    topic="rigid bodies",
    difficulty=2,
    answer_range=(-1e4, 1e4),
    extra=_euler_extra,
)

ENTRIES = (COMPOSITE, POINT_MASSES, DUMBBELL_TORQUE, DUMBBELL_ENERGY, EULER_POWER)
