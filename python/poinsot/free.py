"""Torque-free motion in closed form: the free symmetric top of the unit (eqs. 2.77–2.97) and
the exact free asymmetric top (Jacobi elliptic functions, the elliptic integral of the third
kind), Poinsot's construction and the stability of steady rotation.

Conventions (pinned by the ``test_convention_*`` and ``test_erratum_*`` tests):

* ω is in **body** components (rad/s); L in **space** components (kg·m²/s); attitudes are unit
  quaternions **[w, x, y, z]** that rotate body components into space components
  (``x_space = R(q) x_body``); the initial attitude defaults to the identity;
* the symmetric top has its equal moments I₁ = I₂ about body axes 1, 2 and I₃ about the
  symmetry axis 3; the unit's Ω = (I₁ − I₃) ω₃ / I₁ (2.83) with ω̇₁ = Ω ω₂, ω̇₂ = −Ω ω₁
  (2.81–2.82; Goldstein writes the opposite sign of Ω: the same physics).

All computation runs in the compiled core; this module converts arrays and broadcasts ``t``.
A plain number ``t`` (a float or an int) takes a fast path: one call of the binding that
returns the arrays of that one time, without building and reshaping an array of times (same
numbers, same checks: anything not plainly a finite number goes the general way).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, NamedTuple

import numpy as np

from . import _core
from . import _display as show
from ._props import core_property
from ._validate import (
    FloatArray,
    as_callable,
    as_choice,
    as_count,
    as_flat,
    as_float_array,
    as_rows,
    as_scalar,
    plain_float,
)
from .errors import PoinsotError

__all__ = [
    "FreeSymmetricTop",
    "FreeRigidBody",
    "AxisStability",
    "axis_stability",
    "free_body_states",
]


def _quat(value: Any, name: str) -> FloatArray | None:
    if value is None:
        return None
    if hasattr(value, "as_quat") and hasattr(value, "as_matrix"):  # scipy Rotation
        q = np.asarray(value.as_quat(), dtype=np.float64)  # scalar-last
        if q.shape != (4,):
            raise PoinsotError(f"{name}: must be a single rotation, got {q.shape[0]}")
        return np.array([q[3], q[0], q[1], q[2]])
    arr = as_float_array(value, name)
    if arr.shape != (4,):
        raise PoinsotError(f"{name}: must have shape (4,) ([w, x, y, z]), got {arr.shape}")
    return arr


def _times(t: Any) -> tuple[FloatArray, tuple[int, ...]]:
    arr = as_float_array(t, "t")
    return np.ascontiguousarray(arr.reshape(-1)), arr.shape


def _per_time(name: str, width: int, doc: str) -> Callable[[FreeSymmetricTop, Any], FloatArray]:
    """The method ``name(self, t)`` of :class:`FreeSymmetricTop` (``doc``): the core's ``name_at``
    for a plain number ``t``, else its ``name`` over ``t`` flat, shaped ``t.shape + (width,)``."""
    one = getattr(_core.SymmetricTopSolution, f"{name}_at")
    many = getattr(_core.SymmetricTopSolution, name)

    def method(self, t: Any) -> FloatArray:
        x = plain_float(t)
        if x is not None:
            return one(self._core, x)
        ts, shape = _times(t)
        return np.asarray(many(self._core, ts)).reshape(shape + (width,))

    method.__name__, method.__qualname__, method.__doc__ = name, f"FreeSymmetricTop.{name}", doc
    return method


#: ``omega0`` of both free bodies.
_OMEGA0 = core_property(
    "omega0",
    "ω at t = 0 in body components, as given (rad/s, shape (3,); a new array).",
    np.asarray,
)


class FreeSymmetricTop(show.Displayed):
    """The exact torque-free motion of a symmetric top, I₁ = I₂ ≠ I₃ (the unit's 2.77–2.97).

    Parameters
    ----------
    I1, I3:
        The equal moments about body axes 1 and 2, and the moment about the symmetry axis 3
        (kg·m², > 0, I3 ≤ 2·I1).
    omega0:
        Body angular velocity at t = 0 (rad/s, shape (3,), nonzero).
    attitude0:
        Attitude at t = 0, quaternion [w, x, y, z] (body → space) or a scipy Rotation;
        identity if None.

    Attributes
    ----------
    precession_rate:
        Ω = (I₁ − I₃) ω₃ / I₁ (2.83), rad/s: ω precesses about the symmetry axis in the body.
    amplitude:
        A = (ω₁² + ω₂²)^½ (2.85–2.88), rad/s.
    phase:
        θ₀ of ω₁ = A sin(Ωt + θ₀), ω₂ = A cos(Ωt + θ₀) (2.85–2.86), rad.
    omega3:
        ω₃, constant (2.80), rad/s.
    body_cone_angle:
        α_b with tan α_b = A / ω₃ (2.90), rad.
    space_cone_angle:
        α_s with cos α_s = 2T / (ω L) (2.97), rad.
    shape:
        "prolate" (I₃ < I₁: the body cone rolls on the outside of the space cone) or "oblate"
        (I₃ > I₁: the body cone surrounds the space cone and rolls on it with its inside).

    Raises
    ------
    InvalidInertiaError
        I1 or I3 not > 0, or I3 > 2·I1 (the message names ``I1`` or ``I3``).
    PoinsotError
        ω₀ zero or not finite (names ``omega0``); InvalidRotationError for a non-unit
        ``attitude0``.
    """

    def __init__(self, I1: float, I3: float, omega0: Any, attitude0: Any = None) -> None:
        i1 = as_scalar(I1, "I1")
        i3 = as_scalar(I3, "I3")
        q = None if attitude0 is None else _quat(attitude0, "attitude0")
        # omega0 of any form: converted once, by the binding (its errors name omega0)
        self._core = _core.SymmetricTopSolution(i1, i3, omega0, q)
        self.I1 = i1
        self.I3 = i3
        self._attitude0 = q

    def __reduce__(self) -> tuple[Any, ...]:  # pickling and copying: the constructor again
        return (FreeSymmetricTop, (self.I1, self.I3, self.omega0, self._attitude0))

    omega0 = _OMEGA0

    def _rows(self) -> list[show.Row]:
        return [
            show.scalar("I1", "moment about axes 1 and 2", "I₁", self.I1, "kg·m²"),
            show.scalar("I3", "moment about the symmetry axis", "I₃", self.I3, "kg·m²"),
            show.vec("omega0", "ω at t = 0, body axes", "ω(0)", self.omega0, "rad/s"),
            show.words("shape", "shape", self.shape, label=""),
            show.scalar(
                "precession_rate",
                "precession rate of ω in the body (2.83)",
                "Ω",
                self.precession_rate,
                "rad/s",
                label="Ω",
            ),
            *show.scalars(
                self,
                ("omega3", "spin, constant (2.80)", "ω₃", "rad/s"),
                ("amplitude", "amplitude of ω₁, ω₂ (2.88)", "A", "rad/s"),
                ("phase", "phase of ω₁ = A sin(Ωt + θ₀) (2.85)", "θ₀", "rad"),
                ("omega_magnitude", "|ω|, constant (2.89)", "|ω|", "rad/s"),
                ("body_cone_angle", "body cone half-angle (2.90)", "α_b", "rad"),
                ("space_cone_angle", "space cone half-angle (2.97)", "α_s", "rad"),
                ("energy", "kinetic energy (2.91)", "T", "J"),
                ("angular_momentum_magnitude", "|L| (2.93)", "|L|", "kg·m²/s"),
                ("nutation_angle", "angle between L and the symmetry axis", "θ", "rad"),
                ("space_precession_rate", "rate of the axis about L", "|L|/I₁", "rad/s"),
                brief=False,
            ),
        ]

    precession_rate = core_property(
        "precession_rate",
        "Ω = (I₁ − I₃) ω₃ / I₁ (2.83), rad/s.",
        float,
    )

    amplitude = core_property("amplitude", "A = (ω₁² + ω₂²)^½ (2.88), rad/s.", float)
    phase = core_property("phase", "θ₀ of ω₁ = A sin(Ωt + θ₀) (2.85), rad.", float)
    omega3 = core_property("omega3", "ω₃ (2.80), rad/s.", float)

    omega_magnitude = core_property(
        "omega_magnitude",
        "|ω| = (A² + ω₃²)^½, constant (2.89), rad/s.",
        float,
    )

    energy = core_property("energy", "T = ½ I₁ A² + ½ I₃ ω₃² (2.91), J.", float)

    angular_momentum_magnitude = core_property(
        "angular_momentum_magnitude",
        "|L| = (I₁² A² + I₃² ω₃²)^½ (2.93), kg·m²/s.",
        float,
    )

    angular_momentum = core_property(
        "angular_momentum",
        "L in space components (constant), kg·m²/s, shape (3,).",
        np.asarray,
    )

    precession_period = core_property(
        "precession_period",
        """2π/|Ω| (s): the period of ω's precession about the symmetry axis in the body (2.83),
        in closed form. Raises PoinsotError (naming ``omega0``) where Ω = 0.""",
        float,
    )

    body_cone_angle = core_property(
        "body_cone_angle",
        "Half-angle of the body cone, tan α_b = A / ω₃ (2.90), rad.",
        float,
    )

    space_cone_angle = core_property(
        "space_cone_angle",
        "Half-angle of the space cone, cos α_s = 2T / (ω L) (2.97), rad.",
        float,
    )

    nutation_angle = core_property(
        "nutation_angle",
        "The constant angle between L and the symmetry axis, tan θ = I₁A / (I₃ω₃), rad.",
        float,
    )

    space_precession_rate = core_property(
        "space_precession_rate",
        "|L| / I₁: the rate at which ω and the symmetry axis go round L in space, rad/s.",
        float,
    )

    max_time = core_property(
        "max_time",
        """The largest ``|t|`` at which :meth:`omega` and the attitude are computed, s: the time in
        which the top turns through 2⁴² ≈ 4.4e12 rad at its fastest rate (the phase is then good to
        ~1e-3 rad); a later ``t`` is refused naming ``t``; ``inf`` when the top never turns that far
        within the double range (docs/dynamics.md).""",
        float,
    )

    shape = core_property(
        "shape",
        """"prolate" (I₃ < I₁), "oblate" (I₃ > I₁) or "spherical".""",
        str,
    )

    @property
    def cone_contact(self) -> str:
        """How the body cone rolls on the space cone: "outside" (prolate), "inside" (oblate:
        the body cone surrounds the space cone) or "none" (spherical)."""
        return {"prolate": "outside", "oblate": "inside"}.get(self.shape, "none")

    omega = _per_time(
        "omega",
        3,
        """ω(t) in body components (2.85–2.86), rad/s; ``t`` (s) of any shape → shape + (3,).""",
    )
    attitude = _per_time(
        "attitude",
        4,
        """The attitude at ``t`` (s), quaternions [w, x, y, z] (body → space), shape + (4,):
        R(t) = R₀ · Rot(L̂_body(0), |L| t / I₁) · Rot(e₃, Ω t).""",
    )
    symmetry_axis = _per_time(
        "symmetry_axis", 3, """The symmetry axis e₃ in space components at ``t``, shape + (3,)."""
    )

    @staticmethod
    def omega3_squared_from(I1: float, I3: float, energy: float, angular_momentum: float) -> float:
        """ω₃² = (L² − 2 T I₁) / (I₃ (I₃ − I₁)) (2.95), from T (J) and |L| (kg·m²/s)."""
        return float(
            _core.SymmetricTopSolution.omega3_squared_from(
                as_scalar(I1, "I1"),
                as_scalar(I3, "I3"),
                as_scalar(energy, "energy"),
                as_scalar(angular_momentum, "angular_momentum"),
            )
        )

    @staticmethod
    def amplitude_squared_from(
        I1: float, I3: float, energy: float, angular_momentum: float
    ) -> float:
        """A² = (L² − 2 I₃ T) / (I₁ (I₁ − I₃)) (2.96), from T (J) and |L| (kg·m²/s)."""
        return float(
            _core.SymmetricTopSolution.amplitude_squared_from(
                as_scalar(I1, "I1"),
                as_scalar(I3, "I3"),
                as_scalar(energy, "energy"),
                as_scalar(angular_momentum, "angular_momentum"),
            )
        )


def _samples(samples: Any) -> int:
    """A polhode's point count as an int (the core checks it: ≥ 2, its (samples, 3) output within
    the memory budget)."""
    return as_count(samples, "samples")


class FreeRigidBody(show.Displayed):
    """The exact torque-free motion of any rigid body.

    ω(t) by the Jacobi elliptic functions on either side of the separatrix, the attitude by the
    elliptic integral of the third kind (Jacobi; Landau & Lifshitz §37); the symmetric and
    spherical tops and the steady rotations by their own closed forms. Accurate to ~1e-13 of
    |ω| and of the unit quaternion at t = 1000 for I = (1, 2, 3), ω₀ = (1, 0.1, 1) (checked
    against 40-digit mpmath in the tests).

    Parameters
    ----------
    moments:
        Principal moments (kg·m², shape (3,), > 0, any order, obeying I_a + I_b ≥ I_c); the
        body axes are the principal axes. A :class:`RigidBody` is accepted (its principal
        moments are used; ω₀ and attitudes are then in its principal axes).
    omega0:
        Body angular velocity at t = 0 (rad/s, shape (3,), nonzero).
    attitude0:
        [w, x, y, z] (body → space) or a scipy Rotation at t = 0; identity if None.

    Attributes
    ----------
    energy, angular_momentum:
        T (J) and L in space components (kg·m²/s, (3,)), conserved.
    period:
        The period of ω(t) in the body (s): 4K(m)/λ; 2π/|Ω| for a symmetric top; inf when ω
        is constant or on the separatrix.
    regime:
        "steady", "symmetric", "about max axis", "about min axis" or "separatrix".
    parameter, frequency:
        The Jacobi parameter m = k² and the rate λ of τ = λt + τ₀ (1/s).
    flip_interval:
        Half the period: the time between reversals of ω along the intermediate axis (the
        Dzhanibekov flips near the separatrix), s.
    pole_axis:
        Index of the principal axis ω circles (None when steady or on the separatrix).
    steady_rate:
        |ω| of a steady rotation (rad/s); None when ω moves in the body.
    flips_about:
        Index of the intermediate axis when ω₀ starts nearest it (its largest component; ω
        circling an outer axis): the body flips over every ``flip_interval``. None otherwise.
    """

    def __init__(self, moments: Any, omega0: Any, attitude0: Any = None) -> None:
        kind = type(moments)
        plain = kind is list or kind is tuple or kind is np.ndarray
        if not plain and hasattr(moments, "principal_moments"):
            moments = moments.principal_moments
        q = None if attitude0 is None else _quat(attitude0, "attitude0")
        # moments and omega0 of any form: converted once, by the binding (errors name them)
        self._core = _core.FreeBodySolution(moments, omega0, q)
        self._attitude0 = q

    def __reduce__(self) -> tuple[Any, ...]:
        # pickling and copying: the constructor again, on the floats the core was given
        return (FreeRigidBody, (self.moments, self.omega0, self._attitude0))

    moments = core_property(
        "moments",
        "The principal moments, as given (kg·m², shape (3,); a new array).",
        np.asarray,
    )

    omega0 = _OMEGA0

    def _rows(self) -> list[show.Row]:
        return [
            show.vec("moments", "principal moments", "I₁, I₂, I₃", self.moments, "kg·m²"),
            show.vec("omega0", "ω at t = 0, body axes", "ω(0)", self.omega0, "rad/s"),
            show.words("regime", "regime", self.regime, label=""),
            show.scalar("period", "period of ω in the body", "", self.period, "s"),
            show.scalar("energy", "kinetic energy", "T", self.energy, "J", brief=False),
            show.vec(
                "angular_momentum",
                "angular momentum, space axes",
                "L",
                self.angular_momentum,
                "kg·m²/s",
                brief=False,
            ),
            *show.scalars(
                self,
                ("parameter", "Jacobi parameter", "m = k²", ""),
                ("frequency", "rate of τ = λt + τ₀", "λ", "1/s"),
                ("flip_interval", "interval between flips", "", "s"),
                ("pole_axis", "principal axis ω circles (index)", "", ""),
                brief=False,
            ),
        ]

    energy = core_property("energy", "T = ½ ω·I·ω, conserved (J).", float)

    angular_momentum = core_property(
        "angular_momentum",
        "L in space components, conserved (kg·m²/s, (3,)).",
        np.asarray,
    )

    angular_momentum_magnitude = core_property(
        "angular_momentum_magnitude",
        "|L|, conserved (kg·m²/s), formed without overflow on the way.",
        float,
    )

    period = core_property(
        "period",
        "The period of ω(t) (s); inf when ω is constant or on the separatrix.",
        float,
    )

    max_time = core_property(
        "max_time",
        """The largest ``|t|`` at which the state is computed, s: the time in which the motion turns
        through 2⁴² ≈ 4.4e12 rad at its fastest rate (λ or the precession rate; the phase is then
        good to ~1e-3 rad). A later ``t`` is refused naming ``t`` (``duration`` in
        :func:`simulate`); ``inf`` when the body never turns that far within the double range
        (docs/dynamics.md).""",
        float,
    )

    regime = core_property(
        "regime",
        """"steady", "symmetric", "about max axis", "about min axis" or "separatrix".""",
        str,
    )

    parameter = core_property(
        "parameter",
        "The Jacobi parameter m = k² (0 steady/symmetric, 1 on the separatrix).",
        float,
    )

    frequency = core_property(
        "frequency",
        "λ of τ = λ t + τ₀ (1/s); |Ω| for a symmetric top.",
        float,
    )

    flip_interval = core_property(
        "flip_interval",
        "Half the period (s): the interval between Dzhanibekov flips near the separatrix.",
        float,
    )

    pole_axis: int | None = core_property(
        "pole_axis",
        "The principal axis (index into ``moments``) that ω circles, or None.",
    )

    steady_rate: float | None = core_property(
        "steady_rate",
        "|ω| of a steady rotation (rad/s, constant), or None when ω moves in the body.",
    )

    flips_about: int | None = core_property(
        "flips_about",
        """The intermediate axis (index into ``moments``) when ω₀ starts nearest it — its largest
        component (the first of equal ones) is along it, ω circling an outer axis: the body flips
        over every :attr:`flip_interval` (the Dzhanibekov effect). None otherwise.""",
    )

    invariable_plane_distance = core_property(
        "invariable_plane_distance",
        """(2T)^½ / |L|: in Poinsot's construction the inertia ellipsoid x·I·x = 1 rolls on the
        plane at this distance from its centre, touching it at ω / (2T)^½.""",
        float,
    )

    invariable_plane_normal = core_property(
        "invariable_plane_normal",
        "L̂ = L / |L|, the unit normal of the invariable plane (space components, (3,)).",
        np.asarray,
    )

    def contact_point(
        self, t: Any, frame: str = _core.DEFAULTS["FreeRigidBody.contact_point"]["frame"]
    ) -> FloatArray:
        """The point where the inertia ellipsoid ρ·I·ρ = 1 (fixed in the body) touches the
        invariable plane ρ·L̂ = :attr:`invariable_plane_distance` in Poinsot's construction:
        ρ = ω(t) / (2T)^½ (kg^-½·m^-1), shape t.shape + (3,).

        ``frame="space"`` (default) gives space components (their locus is the herpolhode,
        scaled), ``frame="body"`` body components (the polhode, scaled). The ellipsoid's normal
        there, I·ρ, is parallel to L, and the body point at ρ is at rest: it rolls without
        slipping. Raises PoinsotError for another ``frame`` or non-finite ``t``.
        """
        as_choice(frame, "frame", ("space", "body"))
        ts, shape = _times(t)
        return np.asarray(self._core.contact_point(ts, frame == "body")).reshape(shape + (3,))

    def contact_polhode(
        self, samples: int = _core.DEFAULTS["FreeRigidBody.contact_polhode"]["samples"]
    ) -> FloatArray:
        """The polhode drawn on the inertia ellipsoid ρ·I·ρ = 1: :meth:`polhode` scaled by
        (2T)^-½, body components, shape (samples, 3)."""
        return np.asarray(self._core.contact_polhode(_samples(samples)))

    def state(self, t: Any) -> tuple[FloatArray, FloatArray]:
        """(ω (body, rad/s), attitude [w, x, y, z]) at ``t`` (s): shapes t.shape + (3,) and
        t.shape + (4,); quaternion signs are continuous along ``t``."""
        x = plain_float(t)
        if x is not None:
            return self._core.state_at(x)
        ts, shape = _times(t)
        w, q = self._core.state(ts)
        return np.asarray(w).reshape(shape + (3,)), np.asarray(q).reshape(shape + (4,))

    def omega(self, t: Any) -> FloatArray:
        """ω(t) in body components (rad/s), shape t.shape + (3,)."""
        return self.state(t)[0]

    def attitude(self, t: Any) -> FloatArray:
        """The attitude at ``t``: quaternions [w, x, y, z] (body → space), shape t.shape + (4,)."""
        return self.state(t)[1]

    def angular_momentum_body(self, t: Any) -> FloatArray:
        """L(t) = I·ω(t) in body components (kg·m²/s), shape t.shape + (3,)."""
        ts, shape = _times(t)
        return np.asarray(self._core.angular_momentum_body(ts)).reshape(shape + (3,))

    def polhode(
        self, samples: int = _core.DEFAULTS["FreeRigidBody.polhode"]["samples"]
    ) -> FloatArray:
        """``samples`` points of the polhode — ω over one period in body components (rad/s),
        shape (samples, 3); on the separatrix the branch from t = −12/λ to 12/λ."""
        return np.asarray(self._core.polhode(_samples(samples)))

    def axis_stability(self) -> tuple[AxisStability, AxisStability, AxisStability]:
        """The stability of steady rotation about each principal axis at this body's spin |ω₀|
        (rad/s): :func:`axis_stability` of its moments and |ω₀|, three :class:`AxisStability`."""
        a, b, c = (AxisStability(str(k), float(r)) for k, r in self._core.axis_stability())
        return a, b, c

    def herpolhode(self, t: Any) -> FloatArray:
        """ω(t) in space components (rad/s), shape t.shape + (3,): its tip traces the herpolhode
        on the invariable plane ω·L̂ = 2T/|L|."""
        ts, shape = _times(t)
        return np.asarray(self._core.omega_space(ts)).reshape(shape + (3,))


class AxisStability(NamedTuple):
    """The linear stability of steady rotation about one principal axis.

    ``stability`` is "stable" (largest or smallest moment: deviations oscillate at ``rate``
    rad/s), "unstable" (intermediate: deviations grow like e^{rate·t}) or "neutral".
    """

    stability: str
    rate: float


def axis_stability(
    moments: Any, spin: float = _core.DEFAULTS["axis_stability"]["spin"]
) -> tuple[AxisStability, AxisStability, AxisStability]:
    """The stability of steady rotation at ``spin`` rad/s about each principal axis of a body
    with principal moments ``moments`` (kg·m², (3,), any order): ε̈ = −spin² (I_i − I_j)(I_i −
    I_k)/(I_j I_k) ε linearising Euler's equations (2.72). The intermediate axis is unstable
    with σ = |spin| ((I₂ − I₁)(I₃ − I₂)/(I₁I₃))^½ (the tennis-racket theorem).

    Raises InvalidInertiaError for invalid moments, PoinsotError for a non-finite spin.
    """
    m = as_float_array(moments, "moments", finite=False)
    if m.shape != (3,):
        raise PoinsotError(f"moments: must have shape (3,), got {m.shape}")
    res = _core.axis_stability(np.ascontiguousarray(m), as_scalar(spin, "spin"))
    a, b, c = (AxisStability(str(k), float(r)) for k, r in res)
    return a, b, c


def free_body_states(
    moments: Any,
    omega0: Any,
    t: Any,
    *,
    attitude0: Any = None,
    progress: Any = None,
) -> tuple[FloatArray, FloatArray]:
    """The exact torque-free states of many bodies at many times at once, in parallel (all
    cores), the elliptic motions on SIMD lanes.

    Body i is ``FreeRigidBody(moments[i], omega0[i], attitude0[i])``; its state at each time is
    what :meth:`FreeRigidBody.state` returns: ω bit for bit, the attitude within 1e-13 plus
    8·2⁻⁵² per radian the body has turned (the state's own error model; its elliptic integral
    of the third kind is summed as a Fourier series), the quaternions' signs continuous along
    each body's times. A body at rest (ω₀ = 0) keeps its attitude.

    Parameters
    ----------
    moments:
        Principal moments (kg·m², (N, 3), or (3,) for every body), any order, each obeying the
        triangle inequality; the body axes are the principal axes.
    omega0:
        Body angular velocities at t = 0 (rad/s, (N, 3), or (3,) for every body).
    t:
        Times (s): a number; a 1-D array (M,), the same times for every body; or a 2-D array
        (N, M), body i at its own times ``t[i]``.
    attitude0:
        Attitudes at t = 0, [w, x, y, z] (body → space), (N, 4) or (4,); identity if None.
    progress:
        Optional ``progress(fraction)`` (fraction of the states done), called at most every
        20 ms; an exception it raises stops the run. Ctrl-C stops it too.

    Returns
    -------
    (omega, attitude):
        ω in body components (rad/s) and attitudes [w, x, y, z]: shapes (N, 3) and (N, 4)
        for a number t, (N, M, 3) and (N, M, 4) for an array.

    Raises
    ------
    PoinsotError
        Naming ``moments``, ``omega0``, ``attitude0`` (wrong shape; a row at fault, "row i:
        ..."), or ``t`` (not finite, the wrong shape, beyond a body's time limit — 2⁴² rad of
        turning at its fastest rate: "body i: ..." —, or an output beyond the memory budget).
    """
    m = as_rows(moments, "moments", 3, single=True)
    w = as_rows(omega0, "omega0", 3, single=True)
    q = None if attitude0 is None else as_rows(attitude0, "attitude0", 4, single=True)
    n = max(len(m), len(w), 1 if q is None else len(q))

    def rows_for_all(arr: FloatArray, name: str) -> FloatArray:
        if len(arr) not in (1, n):
            raise PoinsotError(f"{name}: must have 1 or N = {n} rows, got {len(arr)}")
        return np.ascontiguousarray(np.broadcast_to(arr, (n, arr.shape[1])))

    m, w = rows_for_all(m, "moments"), rows_for_all(w, "omega0")
    q = None if q is None else rows_for_all(q, "attitude0")
    times, shape = as_flat(t, "t", finite=False)  # the core names a non-finite time
    if len(shape) > 2:
        raise PoinsotError(f"t: must be a number, (M,) or (N, M), got shape {shape}")
    per_body = len(shape) == 2
    if per_body and shape[0] != n:
        raise PoinsotError(f"t: a 2-D t must have N = {n} rows (one per body), got {shape}")
    omega, attitude = _core.free_body_states(
        (m, w, q), times, per_body, as_callable(progress, "progress")
    )
    omega, attitude = np.asarray(omega), np.asarray(attitude)
    if not shape:
        return omega[:, 0, :], attitude[:, 0, :]
    return omega, attitude
