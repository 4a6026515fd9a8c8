"""The heavy symmetric top (the unit's "Euler's Angles" and "Motion of a Symmetrical Top",
eqs. 2.98–2.121), exactly.

Conventions: the pivot at the origin, the centre of mass at distance ``l`` along body axis 3,
gravity ``-g`` along the fixed Z axis, so the potential is ``V = m g l cos(theta)``. Euler angles
are the unit's intrinsic z-x-z: ``phi`` (precession, about Z), ``theta`` (nutation, about the
line of nodes), ``psi`` (spin, about axis 3); ``R = R_z(phi) @ R_x(theta) @ R_z(psi)`` maps body
to space components. ``I1`` is the moment about a transverse axis *through the pivot*, ``I3``
about the symmetry axis. SI units, radians (``degrees=True`` where angles are user-facing).

The unit stops at the effective potential and calls the exact motion "very difficult"; here it
is computed: ``theta(t)`` by Jacobi's ``sn`` and ``phi(t)``, ``psi(t)`` by elliptic integrals of
the third kind (summed as their closed-form Fourier series, or by Carlson's ``R_J``), from the
Rust core. Two misprints of the unit are corrected (see ``docs/heavy_top.md``): in 2.117 the
square root holds ``p_psi**2`` (not ``p_phi**2``), and the fast precession 2.120 is
``p_psi / (I1 cos theta0)`` (no factor 1/2).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from . import _core
from . import _display as show
from ._props import core_property
from ._validate import FloatArray, as_angle, as_flag, as_flat, as_scalar, plain_float, shaped
from .errors import ArgumentTypeError

if TYPE_CHECKING:
    from .body import RigidBody

__all__ = ["HeavyTop", "SteadyPrecession", "MOTION_CLASSES"]

# The start rates and angles left out: the core's (poinsot::defaults::EulerState).
_TOP = _core.DEFAULTS["HeavyTop.__init__"]
_FROM_SPIN = _core.DEFAULTS["HeavyTop.from_spin"]
_FROM_BODY = _core.DEFAULTS["HeavyTop.from_body"]

MOTION_CLASSES = (
    "waves",
    "loops",
    "cusps",
    "steady precession",
    "sleeping",
    "hanging",
    "through vertical",
)
"""The values of :attr:`HeavyTop.motion_class`: the shape of the symmetry axis' path on the unit
sphere (Goldstein Fig. 5.9) — ``"waves"`` (phi' keeps one sign between the turning circles),
``"loops"`` (phi' changes sign), ``"cusps"`` (phi' = 0 at a turning point: released at rest),
``"steady precession"`` (theta constant, 0 < theta < pi), ``"sleeping"`` (theta stays 0: spinning
upright), ``"hanging"`` (theta stays pi), ``"through vertical"`` (the axis passes through a pole,
where phi and psi jump by pi)."""


def _parameters(I1: Any, I3: Any, mgl: Any) -> tuple[float, float, float]:
    """The top's ``I1``, ``I3`` (kg m^2) and ``mgl`` (N m) as floats, each refused naming its
    argument (the core judges their values)."""
    return as_scalar(I1, "I1"), as_scalar(I3, "I3"), as_scalar(mgl, "mgl")


def _state(degrees: Any, angles: tuple[Any, ...], spin: tuple[str, Any]) -> tuple[float, ...]:
    """The core's start state: ``angles`` = (phi, theta, psi) (rad) and (phi_dot, theta_dot)
    (rad/s), then the spin rate ``spin`` (its name and value: ``psi_dot``, or ``omega3`` for
    :meth:`HeavyTop.from_spin`); degrees and deg/s with ``degrees=True``; each refused naming
    its own argument."""
    names = ("phi", "theta", "psi", "phi_dot", "theta_dot")
    return tuple(as_angle(v, n, degrees) for n, v in (*zip(names, angles), spin))


def _degrees(values: tuple[float, float, float], degrees: Any) -> tuple[float, float, float]:
    """Three angles (or rates) of one time, in degrees when ``degrees`` is true: ``math.degrees``
    is the same product as ``np.degrees`` (x · (180/π), bit for bit)."""
    if as_flag(degrees, "degrees"):
        a, b, c = values
        return math.degrees(a), math.degrees(b), math.degrees(c)
    return values


@dataclass(frozen=True)
class SteadyPrecession:
    """The steady-precession rates of a top held at ``theta0`` spinning at ``omega3`` (rad/s).

    Attributes
    ----------
    slow, fast:
        The two exact roots of 2.116, ``I1 cos(theta0) phi'**2 - p_psi phi' + m g l = 0``
        (near ``theta0 = pi/2``, where the fast rate leaves the range of doubles and only the
        slow one exists, :meth:`HeavyTop.steady_precession` raises, naming ``theta0``).
    slow_approx:
        The unit's 2.121, ``m g l / p_psi``: the slow rate of a fast top; ``None`` without spin
        (``p_psi = 0``, a conical pendulum: its exact rates are ``slow`` and ``fast``) or where it
        exceeds the largest double.
    fast_approx:
        The unit's 2.120 *corrected*, ``p_psi / (I1 cos theta0)``: the fast rate of a fast top.
    fast_approx_as_printed:
        2.120 as the unit prints it, ``p_psi / (2 I1 cos theta0)``: a misprint, off by a factor 2.
    min_spin:
        The minimum spin 2.119 for steady precession at ``theta0`` (rad/s).
    """

    slow: float
    fast: float
    slow_approx: float | None
    fast_approx: float
    fast_approx_as_printed: float
    min_spin: float


class HeavyTop(show.Displayed):
    """A heavy symmetric top started from Euler angles and rates, with its exact motion.

    Parameters
    ----------
    I1 : float
        Moment of inertia about a transverse axis through the pivot (kg m^2), > 0.
    I3 : float
        Moment of inertia about the symmetry axis (kg m^2), > 0 and <= 2 I1.
    mgl : float
        Weight times the pivot-to-centre-of-mass distance, ``m g l`` (N m), >= 0.
    theta : float
        Initial nutation angle (rad), in [0, pi].
    theta_dot, phi_dot, psi_dot : float, keyword-only
        Initial rates (rad/s); the spin is ``omega3 = psi_dot + phi_dot cos(theta)`` (2.99).
    phi, psi : float, keyword-only
        Initial precession and spin angles (rad), default 0.
    degrees : bool, keyword-only
        Angles in degrees and rates in degrees per second.

    Raises
    ------
    PoinsotError
        Naming the argument: ``I1`` or ``I3`` not finite and > 0, ``mgl`` < 0 or not finite,
        ``theta`` outside [0, pi], a non-finite rate or angle.
    InvalidInertiaError
        ``I3 > 2 I1`` (no body has it: the triangle inequality of principal moments).

    Examples
    --------
    >>> top = HeavyTop(1.0, 0.5, 1.0, 0.8, psi_dot=6.0)   # released at rest in phi
    >>> top.motion_class
    'cusps'
    >>> round(top.turning_points[1], 6)
    1.001477
    >>> phi, theta, psi = top.euler_angles([0.0, 1.0, 2.0])
    """

    __slots__ = ("_core", "_made")

    def _build(self, constructor: str, *args: Any) -> None:
        """Makes the core's top with its ``constructor`` (``from_state``, ``from_spin``,
        ``from_constants``) and remembers how, for pickling and copying: the copy is the same
        constructor on the same floats, so it computes the same numbers bit for bit."""
        self._core = getattr(_core.HeavyTopCore, constructor)(*args)
        self._made = (constructor, args)

    def __reduce__(self) -> tuple[Any, ...]:
        return (_rebuild_heavy_top, self._made)

    def __init__(
        self,
        I1: float,
        I3: float,
        mgl: float,
        theta: float,
        *,
        theta_dot: float = _TOP["theta_dot"],
        phi_dot: float = _TOP["phi_dot"],
        psi_dot: float = _TOP["psi_dot"],
        phi: float = _TOP["phi"],
        psi: float = _TOP["psi"],
        degrees: bool = False,
    ) -> None:
        self._build(
            "from_state",
            _parameters(I1, I3, mgl),
            _state(degrees, (phi, theta, psi, phi_dot, theta_dot), ("psi_dot", psi_dot)),
        )

    @classmethod
    def from_spin(
        cls,
        I1: float,
        I3: float,
        mgl: float,
        theta: float,
        omega3: float,
        *,
        theta_dot: float = _FROM_SPIN["theta_dot"],
        phi_dot: float = _FROM_SPIN["phi_dot"],
        phi: float = _FROM_SPIN["phi"],
        psi: float = _FROM_SPIN["psi"],
        degrees: bool = False,
    ) -> HeavyTop:
        """The top started at ``theta`` with the spin ``omega3`` (rad/s) given instead of
        ``psi_dot``: ``psi_dot = omega3 - phi_dot cos(theta)`` (2.99), so that ``p_psi = I3 omega3``
        whatever ``phi_dot`` (the rates as in :class:`HeavyTop`; ``omega3`` in deg/s with
        ``degrees=True``). Raises as :class:`HeavyTop`, and naming ``omega3`` if not finite."""
        top = cls.__new__(cls)
        top._build(
            "from_spin",
            _parameters(I1, I3, mgl),
            _state(degrees, (phi, theta, psi, phi_dot, theta_dot), ("omega3", omega3)),
        )
        return top

    @classmethod
    def from_body(
        cls,
        body: RigidBody,
        pivot_distance: float,
        theta: float,
        omega3: float,
        *,
        theta_dot: float = _FROM_BODY["theta_dot"],
        phi_dot: float = _FROM_BODY["phi_dot"],
        phi: float = _FROM_BODY["phi"],
        psi: float = _FROM_BODY["psi"],
        g: float = _FROM_BODY["g"],
        degrees: bool = False,
    ) -> HeavyTop:
        """The top made of a real body: the symmetric :class:`~poinsot.RigidBody` ``body``,
        whose symmetry axis is its axis 3 (z), pivoted on that axis at ``pivot_distance`` (m,
        >= 0) from its centre of mass, under gravity ``g`` (m/s^2), started at the tilt
        ``theta`` (rad) spinning at ``omega3`` (rad/s) as :meth:`from_spin` (the other angles
        and rates likewise; degrees and deg/s with ``degrees=True``).

        The core computes ``I1 = I_xx + m d**2`` (the parallel-axis theorem: the transverse
        moment about the pivot), ``I3 = I_zz`` and ``mgl = m g d``.

        Raises :class:`PoinsotError` naming ``body`` when its axis 3 is not a principal axis or
        its transverse moments differ (``I_xx != I_yy`` beyond 1e-9 of the largest moment),
        ``pivot_distance`` or ``g`` when negative, and as :meth:`from_spin`.

        Examples
        --------
        >>> from poinsot import RigidBody
        >>> disk = RigidBody.thin_disk(0.2, 0.05)            # 0.2 kg, radius 5 cm
        >>> top = HeavyTop.from_body(disk, 0.1, 30, 1500 * 6, degrees=True)  # 1500 rpm
        >>> round(top.I1, 7), round(top.I3, 7), round(top.mgl, 6)
        (0.002125, 0.00025, 0.196133)
        """
        from .body import RigidBody

        if not isinstance(body, RigidBody):
            raise ArgumentTypeError(f"body: must be a poinsot.RigidBody, got {type(body).__name__}")
        i1, i3, mgl = body._core.heavy_top_parameters(
            as_scalar(pivot_distance, "pivot_distance"), as_scalar(g, "g")
        )
        return cls.from_spin(
            i1,
            i3,
            mgl,
            theta,
            omega3,
            theta_dot=theta_dot,
            phi_dot=phi_dot,
            phi=phi,
            psi=psi,
            degrees=degrees,
        )

    @classmethod
    def from_constants(
        cls,
        I1: float,
        I3: float,
        mgl: float,
        p_phi: float,
        p_psi: float,
        energy: float,
    ) -> HeavyTop:
        """The top with the constants of motion ``p_phi``, ``p_psi`` (kg m^2/s; 2.103–2.104) and
        total energy ``energy`` (J; 2.105). Time 0 is then a moment when the axis is at its upper
        turning point ``theta1``, with ``phi = psi = 0`` there.

        Raises :class:`PoinsotError` naming ``energy`` when ``E' = E - p_psi**2/(2 I3)`` lies below
        the minimum of the effective potential (no motion has these constants)."""
        top = cls.__new__(cls)
        top._build(
            "from_constants",
            _parameters(I1, I3, mgl),
            (as_scalar(p_phi, "p_phi"), as_scalar(p_psi, "p_psi"), as_scalar(energy, "energy")),
        )
        return top

    def _rows(self) -> list[show.Row]:
        i1, i3, mgl = self._core.parameters
        t1, t2 = self.turning_points
        q = "kg·m²/s"
        return [
            show.scalar(
                "I1", "moment about a transverse axis through the pivot", "I₁", i1, "kg·m²"
            ),
            show.scalar("I3", "moment about the symmetry axis", "I₃", i3, "kg·m²"),
            show.scalar("mgl", "weight × pivot-to-centre-of-mass distance", "mgl", mgl, "N·m"),
            show.words("motion_class", "motion of the axis", self.motion_class, label=""),
            show.span(
                "turning_points",
                "nutation between the turning points",
                "θ₁, θ₂",
                t1,
                t2,
                "rad",
                label="theta",
            ),
            show.scalar("omega3", "spin (2.99)", "ω₃", self.omega3, "rad/s"),
            *show.scalars(
                self,
                ("p_phi", "momentum about the vertical (2.104)", "p_φ", q),
                ("p_psi", "momentum about the symmetry axis (2.103)", "p_ψ", q),
                ("energy", "total energy (2.105)", "E", "J"),
                ("reduced_energy", "reduced energy (2.109)", "E′", "J"),
                ("nutation_period", "period of θ", "", "s"),
                ("mean_precession_rate", "mean precession rate", "⟨φ′⟩", "rad/s"),
                ("mean_spin_rate", "mean spin rate", "⟨ψ′⟩", "rad/s"),
                brief=False,
            ),
        ]

    # ---- parameters and constants of the motion -------------------------------------------
    @property
    def I1(self) -> float:
        """Moment about a transverse axis through the pivot (kg m^2)."""
        return self._core.parameters[0]

    @property
    def I3(self) -> float:
        """Moment about the symmetry axis (kg m^2)."""
        return self._core.parameters[1]

    @property
    def mgl(self) -> float:
        """``m g l`` (N m)."""
        return self._core.parameters[2]

    p_phi: float = core_property(
        "p_phi",
        """``p_phi = I1 phi' sin^2(theta) + p_psi cos(theta)`` (kg m^2/s, 2.104): the conserved
        vertical angular momentum ``L_Z``.""",
    )

    p_psi: float = core_property(
        "p_psi",
        "``p_psi = I3 omega3`` (kg m^2/s, 2.103): the conserved angular momentum about axis 3.",
    )

    omega3: float = core_property(
        "omega3",
        "The spin ``omega3 = psi' + phi' cos(theta)`` (rad/s, 2.99), constant.",
    )

    energy: float = core_property(
        "energy", "The total energy ``E = T + m g l cos(theta)`` (J, 2.105)."
    )

    reduced_energy: float = core_property(
        "reduced_energy",
        "``E' = E - p_psi**2/(2 I3) = I1 theta'**2/2 + V(theta)`` (J, 2.109).",
    )

    @property
    def initial_state(self) -> dict[str, float]:
        """The state at ``t = 0``: ``phi, theta, psi`` (rad) and ``phi_dot, theta_dot, psi_dot``
        (rad/s). At a pole a negative ``theta_dot`` is turned into [0, pi] (``phi + pi``,
        ``psi -+ pi``: the same rotation)."""
        keys = ("phi", "theta", "psi", "phi_dot", "theta_dot", "psi_dot")
        return dict(zip(keys, self._core.initial_state))

    # ---- the analysis of the unit ----------------------------------------------------------
    def effective_potential(self, theta: Any, *, degrees: bool = False) -> Any:
        """The effective potential ``V(theta) = (p_phi - p_psi cos)^2 / (2 I1 sin^2) + m g l cos``
        (J, 2.110), broadcasting over ``theta`` (rad, in [0, pi]). At a pole it is the limit
        ``m g l cos`` where the numerator vanishes there; where V is infinite (a pole the axis
        never reaches) or beyond the largest double next to it, :class:`PoinsotError` names
        ``theta``."""
        flat, shape = as_flat(theta, "theta", degrees)
        return shaped(self._core.effective_potential(flat), shape)

    def effective_potential_derivative(self, theta: Any, *, degrees: bool = False) -> Any:
        """``dV/dtheta`` (N m, 2.113; always per radian), broadcasting over ``theta``."""
        flat, shape = as_flat(theta, "theta", degrees)
        return shaped(self._core.effective_potential_derivative(flat), shape)

    turning_points: tuple[float, float] = core_property(
        "turning_points",
        """``(theta1, theta2)`` (rad), ``theta1 <= theta2``: where ``E' = V(theta)``, the roots of
        the cubic ``f(u) = (1 - u^2)(alpha - beta u) - (b - a u)^2`` in ``u = cos(theta)``, computed
        without cancellation at the poles (both equal for steady precession).""",
    )

    cubic_roots: tuple[float, float, float] = core_property(
        "cubic_roots",
        """``(u1, u2, u3)``: the roots of the cubic in ``u = cos(theta)``, ``u1 = cos(theta2) <= u2
        = cos(theta1) <= 1 <= u3`` (``u3 = inf`` when ``m g l = 0``).""",
    )

    motion_class: str = core_property(
        "motion_class",
        "The shape of the axis' path: one of :data:`MOTION_CLASSES`.",
    )

    vertical_pass: str | None = core_property(
        "vertical_pass",
        """The pole the axis passes through when :attr:`motion_class` is ``"through vertical"``:
        ``"upright"`` (``theta1 == 0``), ``"straight down"`` (``theta2 == pi``) or ``"both"``;
        None for every other class.""",
    )

    is_sleeping_stable: bool = core_property(
        "is_sleeping_stable",
        "Whether this spin keeps an upright top asleep: ``omega3**2 > 4 m g l I1 / I3**2``.",
    )

    @property
    def nutation_period(self) -> float:
        """The period of ``theta(t)`` (s), ``2 K(m) / kappa``; for steady motion the period of small
        nutations about it; ``inf`` where theta never returns (an unstable sleeping top)."""
        p = self._core.nutation_period
        return math.inf if p is None else p

    mean_precession_rate: float = core_property(
        "mean_precession_rate",
        "The mean of ``phi'`` over a nutation period (rad/s).",
    )

    @property
    def precession_period(self) -> float:
        """The precession period ``2 pi / |<phi'>|`` (s): the time of one turn of the axis about the
        vertical at the mean precession rate (for steady precession, exactly the time ``phi``
        takes to advance by ``2 pi``); ``inf`` where the axis does not turn on average (a sleeping
        or hanging top)."""
        p = self._core.precession_period
        return math.inf if p is None else p

    mean_spin_rate: float = core_property(
        "mean_spin_rate",
        "The mean of ``psi'`` over a nutation period (rad/s).",
    )

    # ---- the exact motion ------------------------------------------------------------------
    def euler_angles(self, t: Any, *, degrees: bool = False) -> tuple[Any, Any, Any]:
        """The exact Euler angles ``(phi, theta, psi)`` at times ``t`` (s; the initial state is at
        ``t = 0``), each shaped like ``t`` (floats for a scalar ``t``), in rad (degrees with
        ``degrees=True``). ``phi`` and ``psi`` are continuous, not reduced modulo 2 pi, except for
        jumps of pi where the axis passes exactly through a pole. θ keeps its relative accuracy
        however close to upright (down to 1e-60 rad). Raises :class:`PoinsotError` naming ``t``
        beyond ``|t| = 4.5e9 rad / (the motion's fastest rate)``, where the phase would carry more
        than 1e-6 rad of rounding (see docs/heavy_top.md, *Range of validity*)."""
        x = plain_float(t)
        if x is not None:  # one plain number: the same kernel without the arrays
            return _degrees(self._core.euler_angles_at(x), degrees)
        flat, shape = as_flat(
            t, "t", finite=False
        )  # the core names a non-finite time and its index
        out = self._core.euler_angles(flat)
        if as_flag(degrees, "degrees"):
            out = np.degrees(out)
        return shaped(out[:, 0], shape), shaped(out[:, 1], shape), shaped(out[:, 2], shape)

    def euler_rates(self, t: Any, *, degrees: bool = False) -> tuple[Any, Any, Any]:
        """The rates ``(phi', theta', psi')`` (rad/s; deg/s with ``degrees=True``) at times ``t``:
        ``phi'`` by 2.106, ``psi' = omega3 - phi' cos(theta)``, ``theta'`` from the solution."""
        x = plain_float(t)
        if x is not None:
            return _degrees(self._core.euler_rates_at(x), degrees)
        flat, shape = as_flat(t, "t", finite=False)
        out = self._core.euler_rates(flat)
        if as_flag(degrees, "degrees"):
            out = np.degrees(out)
        return shaped(out[:, 0], shape), shaped(out[:, 1], shape), shaped(out[:, 2], shape)

    def attitude(self, t: Any) -> FloatArray:
        """Rotation matrices ``R(t) = R_z(phi) R_x(theta) R_z(psi)``, shape ``t.shape + (3, 3)``
        (body to space components)."""
        flat, shape = as_flat(t, "t")
        mats = _core.euler_to_matrix(self._core.euler_angles(flat), "zxz", True)
        return np.asarray(mats).reshape(*shape, 3, 3)

    def symmetry_axis(self, t: Any) -> FloatArray:
        """The unit vector of body axis 3 in space components at times ``t``, shape
        ``t.shape + (3,)``: the point that traces waves, loops or cusps on the unit sphere."""
        return self.attitude(t)[..., :, 2]

    # ---- steady precession (static) ------------------------------------------------------
    @staticmethod
    def steady_precession(
        I1: float,
        I3: float,
        mgl: float,
        theta0: float,
        omega3: float,
        *,
        degrees: bool = False,
    ) -> SteadyPrecession:
        """Both exact steady-precession rates at ``theta0`` and spin ``omega3`` (2.116, errata of
        2.117 fixed), beside the unit's approximations 2.120 (corrected) and 2.121 and the minimum
        spin 2.119. With ``degrees=True``, ``theta0`` is in degrees (rates stay in rad/s).

        Raises :class:`PoinsotError` naming ``omega3`` when ``|omega3|`` is below the minimum
        spin (the message gives it), and ``theta0`` where the fast rate exceeds the largest double
        (``slow_approx`` is ``None`` without spin)."""
        d = _core.heavy_top_steady_precession(
            _parameters(I1, I3, mgl),
            as_angle(theta0, "theta0", degrees),
            as_scalar(omega3, "omega3"),
        )
        return SteadyPrecession(**d)

    @staticmethod
    def steady_precession_rates(
        I1: float,
        I3: float,
        mgl: float,
        theta0: float,
        omega3: float,
        *,
        degrees: bool = False,
    ) -> tuple[float, float]:
        """``(slow, fast)``: the two exact steady-precession rates (rad/s) of 2.116 at ``theta0``
        (rad) and spin ``omega3`` (rad/s). See :meth:`steady_precession` for the approximations."""
        s = HeavyTop.steady_precession(I1, I3, mgl, theta0, omega3, degrees=degrees)
        return s.slow, s.fast

    @staticmethod
    def min_spin(
        I1: float,
        I3: float,
        mgl: float,
        theta0: float,
        *,
        degrees: bool = False,
    ) -> float:
        """The minimum spin for steady precession at ``theta0`` (2.119):
        ``omega3_min = (2 / I3) sqrt(m g l I1 cos theta0)`` (rad/s), 0 below the horizontal."""
        return _core.heavy_top_min_spin(
            _parameters(I1, I3, mgl),
            as_angle(theta0, "theta0", degrees),
        )

    @staticmethod
    def sleeping_threshold(I1: float, I3: float, mgl: float) -> float:
        """The spin above which an upright top sleeps stably, ``2 sqrt(m g l I1) / I3`` (rad/s):
        stable iff ``omega3**2 > 4 m g l I1 / I3**2``."""
        return _core.heavy_top_sleeping_threshold(_parameters(I1, I3, mgl))

    @staticmethod
    def lagrangian(
        I1: float,
        I3: float,
        mgl: float,
        theta: float,
        theta_dot: float,
        phi_dot: float,
        psi_dot: float,
    ) -> float:
        """The Lagrangian 2.102, ``I1 (theta'^2 + phi'^2 sin^2)/2 + I3 (psi' + phi' cos)^2/2 - m g l
        cos(theta)`` (J), at one state (rad, rad/s)."""
        return _core.heavy_top_lagrangian(
            _parameters(I1, I3, mgl),
            (
                as_scalar(theta, "theta"),
                as_scalar(theta_dot, "theta_dot"),
                as_scalar(phi_dot, "phi_dot"),
                as_scalar(psi_dot, "psi_dot"),
            ),
        )

    @staticmethod
    def constants_of_state(
        I1: float,
        I3: float,
        mgl: float,
        theta: float,
        theta_dot: float,
        phi_dot: float,
        psi_dot: float,
        *,
        degrees: bool = False,
    ) -> dict[str, float]:
        """The constants of the motion evaluated at one state: ``{"p_phi", "p_psi", "energy"}``,
        ``p_phi = I1 phi' sin^2 + p_psi cos`` (kg m^2/s, 2.104), ``p_psi = I3 (psi' + phi' cos)``
        (kg m^2/s, 2.103) and ``E = I1 (theta'^2 + phi'^2 sin^2)/2 + I3 omega3^2/2 + m g l cos``
        (J, 2.105), with ``theta`` in rad (in [0, pi]) and the rates in rad/s (degrees and deg/s
        with ``degrees=True``).

        Evaluated at ``euler_angles(t)`` and ``euler_rates(t)`` of a :class:`HeavyTop` they equal
        its ``p_phi``, ``p_psi`` and ``energy`` to round-off (the difference is the drift of the
        solution); at the initial state they are identical.

        Raises :class:`PoinsotError` naming ``I1``, ``I3``, ``mgl``, ``theta`` or a rate."""
        p_phi, p_psi, energy = _core.heavy_top_constants_of_state(
            _parameters(I1, I3, mgl),
            (
                as_angle(theta, "theta", degrees),
                as_angle(theta_dot, "theta_dot", degrees),
                as_angle(phi_dot, "phi_dot", degrees),
                as_angle(psi_dot, "psi_dot", degrees),
            ),
        )
        return {"p_phi": p_phi, "p_psi": p_psi, "energy": energy}


def _rebuild_heavy_top(constructor: str, args: tuple[Any, ...]) -> HeavyTop:
    """A :class:`HeavyTop` unpickled or copied: the core's ``constructor`` on ``args`` again."""
    top = HeavyTop.__new__(HeavyTop)
    top._build(constructor, *args)
    return top
