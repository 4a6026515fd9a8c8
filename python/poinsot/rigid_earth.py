"""The Earth as a rigid body: an oblate symmetric top (the unit's free top, 2.77–2.97, and its
torque theory) spinning once a sidereal day, torqued by the Sun and the Moon.

:class:`RigidEarth` gives Euler's free nutation (the unit's Ω of 2.83), the Chandler period of
the elastic Earth, the luni-solar precession of the equinoxes from the orbit-averaged
gravity-gradient torque, and the principal (18.6-year) nutation. The constants and their
sources are documented in the core (``crates/poinsot/src/earth/rigid.rs``): H = (C − A)/C =
0.003273795 (IERS Conventions 2010, Table 1.1), the sidereal rate 7.292115e-5 rad/s, the
obliquity at J2000 84381.406″ (IAU 2006), the mean orbits of the Sun and the Moon.

SI units and radians: periods in s, rates in rad/s, amplitudes in rad.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, NamedTuple

import numpy as np

from . import _core
from ._props import core_property
from ._validate import FloatArray, as_angle, as_count, as_flag, as_float_array, as_scalar
from .earth import SIDEREAL_RATE

__all__ = [
    "AveragedPole",
    "DYNAMICAL_FLATTENING",
    "IAU2000A_PRINCIPAL_NUTATION",
    "IAU2006_PRECESSION_RATE",
    "OBLIQUITY_J2000",
    "PoleFit",
    "PoleRun",
    "RigidEarth",
]

_SIMULATE = _core.DEFAULTS["RigidEarth.simulate"]
_AVERAGED = _core.DEFAULTS["RigidEarth.averaged_pole"]

#: H = (C − A)/C, the Earth's dynamical flattening: 0.003273795 (IERS Conventions 2010,
#: Table 1.1).
DYNAMICAL_FLATTENING: float = _core.DYNAMICAL_FLATTENING
#: ε₀, the obliquity of the ecliptic at J2000.0 (rad): 84381.406″ (IAU 2006).
OBLIQUITY_J2000: float = _core.OBLIQUITY_J2000
#: The IAU 2006 luni-solar precession rate ψ̇_A (rad/s, westward positive): 5038.481507″ per
#: Julian century (Capitaine et al. 2003).
IAU2006_PRECESSION_RATE: float = _core.IAU2006_PRECESSION_RATE
#: The IAU 2000A principal nutation (Δψ₀, Δε₀) (rad): (−17.2064161″, 9.2052331″), the
#: coefficients of sin Ω and cos Ω (the first luni-solar term of ERFA's ``nut00a``).
IAU2000A_PRINCIPAL_NUTATION: tuple[float, float] = _core.IAU2000A_PRINCIPAL_NUTATION


@dataclass(frozen=True)
class PoleFit:
    """The mean precession and the principal nutation read off a :class:`PoleRun` by least
    squares (:meth:`PoleRun.fit`): the longitude and the obliquity each fitted to a line plus
    the terms in sin Ω and cos Ω of the Moon's node Ω(t).

    Attributes
    ----------
    precession_rate:
        The mean rate of the longitude (rad/s): negative (retrograde); compare with
        :attr:`RigidEarth.precession_rate`.
    mean_obliquity:
        The mean obliquity at t = 0 (rad).
    obliquity_rate:
        The mean rate of the obliquity (rad/s): about 0 for a rigid Earth under a fixed ecliptic.
    nutation_longitude, nutation_obliquity:
        Δψ₀ and Δε₀ (rad), the coefficients of sin Ω in ψ = −longitude and of cos Ω in the
        obliquity: the IAU convention of :attr:`RigidEarth.nutation_amplitudes`.
    """

    precession_rate: float
    mean_obliquity: float
    obliquity_rate: float
    nutation_longitude: float
    nutation_obliquity: float


@dataclass(frozen=True, eq=False, repr=False)
class PoleRun:
    """The Earth's spin axis integrated under the Sun's and the Moon's torques
    (:meth:`RigidEarth.simulate`), in ecliptic axes (x to the initial equinox).

    Attributes
    ----------
    t:
        Sample times (s), (N,), from 0 to the duration.
    longitude:
        The ecliptic longitude of the equinox (the node of the equator on the ecliptic)
        counted from the initial equinox (rad, unwrapped), (N,): the pole's own ecliptic
        longitude less π/2, −ψ of the IAU. It falls at the precession rate.
    obliquity:
        The angle of the spin axis from the ecliptic's pole (rad), (N,).
    moon_node:
        Ω₀, the ecliptic longitude of the Moon's ascending node at t = 0 (rad).
    node_rate:
        Ω′, the rate of the Moon's node (rad/s): −2π/(18.6 years), regressing.
    """

    t: FloatArray = field(repr=False)
    longitude: FloatArray = field(repr=False)
    obliquity: FloatArray = field(repr=False)
    moon_node: float
    node_rate: float

    def __repr__(self) -> str:
        years = float(self.t[-1]) / (365.25 * 86400.0)
        return (
            f"PoleRun({len(self.t)} samples over {years:.6g} Julian years, "
            f"moon_node={self.moon_node!r}, node_rate={self.node_rate!r})"
        )

    def fit(self) -> PoleFit:
        """The mean precession rate and the principal nutation fitted to the run (the core's
        least squares: a line plus the sin Ω and cos Ω terms of the Moon's node, in the
        longitude and in the obliquity). The run must span at least one node period
        (18.6 years), or ``t`` is refused.

        Returns
        -------
        PoleFit
            rates in rad/s, angles in rad.
        """
        got = _core.fit_pole(
            np.ascontiguousarray(self.t, dtype=np.float64),
            np.ascontiguousarray(self.longitude, dtype=np.float64),
            np.ascontiguousarray(self.obliquity, dtype=np.float64),
            float(self.moon_node),
            float(self.node_rate),
        )
        return PoleFit(*(float(x) for x in got))


class AveragedPole(NamedTuple):
    """The rigid Earth's averaged pole at given times (:meth:`RigidEarth.averaged_pole`): the
    uniform luni-solar precession plus the principal (18.6-year) nutation, each array of the
    shape of the times asked for.

    ``psi`` is ψ(t), the precession angle of the spin axis (rad, unwrapped): its ecliptic
    longitude counted westward from its place at t = 0, the IAU's ψ_A plus the nutation Δψ, the
    negative of :attr:`PoleRun.longitude`. ``obliquity`` is ε(t), the angle of the spin axis
    from the ecliptic's pole (rad), and ``moon_node`` Ω(t), the ecliptic longitude of the Moon's
    ascending node (rad, unwrapped).
    """

    psi: FloatArray
    obliquity: FloatArray
    moon_node: FloatArray


class RigidEarth:
    """The Earth as a rigid symmetric top (A = B < C), torqued by the Sun and the Moon.

    Parameters
    ----------
    dynamical_flattening:
        H = (C − A)/C (dimensionless, a float), in (0, 1); default 0.003273795 (IERS Conventions 2010). ``0`` (a sphere:
        no bulge, no torque, no free wobble) is refused.
    rotation_rate:
        ω (rad/s, a float > 0); default the sidereal rate 7.292115e-5.
    obliquity:
        ε, the tilt of the equator to the ecliptic (rad, or degrees with ``degrees=True``), in
        [0, π/2); default 84381.406″ = 23.4393°, the J2000 value (IAU 2006).
    degrees:
        Whether a plain-number ``obliquity`` is in degrees.

    Examples
    --------
    >>> import poinsot as ps
    >>> e = ps.RigidEarth()
    >>> round(e.euler_period / (2 * 3.141592653589793 / e.rotation_rate), 1)  # sidereal days
    304.5
    >>> round(e.chandler_period(0.30, 0.938) / 86400)                         # days
    446
    """

    __slots__ = ("_core",)

    def __init__(
        self,
        dynamical_flattening: float = DYNAMICAL_FLATTENING,
        rotation_rate: float = SIDEREAL_RATE,
        obliquity: float = OBLIQUITY_J2000,
        degrees: bool = False,
    ) -> None:
        # The core's RigidEarth, checked when made (the errors name the three).
        self._core = _core.RigidEarthCore(
            as_scalar(dynamical_flattening, "dynamical_flattening"),
            as_scalar(rotation_rate, "rotation_rate"),
            as_angle(obliquity, "obliquity", degrees),
        )

    dynamical_flattening: float = core_property(
        "dynamical_flattening", "H = (C − A)/C (dimensionless)."
    )
    rotation_rate: float = core_property("rotation_rate", "ω (rad/s).")
    obliquity: float = core_property("obliquity", "ε (rad).")

    def __repr__(self) -> str:
        c = self._core
        return (
            f"RigidEarth(dynamical_flattening={c.dynamical_flattening!r}, "
            f"rotation_rate={c.rotation_rate!r}, obliquity={c.obliquity!r})"
        )

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, RigidEarth):
            return NotImplemented
        a, b = self._core, other._core
        return (a.dynamical_flattening, a.rotation_rate, a.obliquity) == (
            b.dynamical_flattening,
            b.rotation_rate,
            b.obliquity,
        )

    def __hash__(self) -> int:
        c = self._core
        return hash((RigidEarth, c.dynamical_flattening, c.rotation_rate, c.obliquity))

    def __reduce__(self) -> tuple[Any, ...]:
        c = self._core
        return (RigidEarth, (c.dynamical_flattening, c.rotation_rate, c.obliquity))

    @property
    def euler_rate(self) -> float:
        """The unit's Ω of eq. 2.83 applied to the Earth, Ω = (I₁ − I₃) ω₃ / I₁ = −H/(1 − H) ω
        (rad/s). Negative: the equatorial part of ω turns about the figure axis at −Ω > 0, in
        the sense of the rotation (prograde), as seen in the body."""
        return float(self._core.euler_rate)

    @property
    def euler_period(self) -> float:
        """Euler's free-nutation period 2π/|Ω| (s), Ω of eq. 2.83: A/(C − A) = (1 − H)/H
        sidereal days — about 304.5 sidereal days (303.6 days) for the IERS H."""
        return float(self._core.euler_period)

    def chandler_period(self, k2: float, ks: float) -> float:
        """The elastic Earth's free wobble (s): T_C = T_E · ks/(ks − k2) (Munk & MacDonald
        1960; Smith & Dahlen 1981), Euler's period lengthened by the yielding of the mantle.

        ``k2`` is the Love number, ``ks`` the secular (fluid) Love number (both dimensionless
        floats), 0 < k2 < ks; the period is returned in s (a float). With k2 = 0.30 and
        ks = 0.938 it is about 446 days against the observed 433: the oceans' pole tide, the
        fluid core and the mantle's anelasticity account for the rest. Raises PoinsotError
        naming ``k2`` or ``ks`` outside that range."""
        return float(self._core.chandler_period(as_scalar(k2, "k2"), as_scalar(ks, "ks")))

    def simulate(
        self,
        duration: Any,
        *,
        samples: int = _SIMULATE["samples"],
        moon_node: Any = _SIMULATE["moon_node"],
        mean_pole: bool = False,
        degrees: bool = False,
        max_steps: int = _SIMULATE["max_steps"],
    ) -> PoleRun:
        """The spin axis integrated for ``duration`` under the gravity-gradient torques of the
        Sun and the Moon moving along their Kepler orbits — not the averaged formula — so that
        :attr:`precession_rate` and :attr:`nutation_amplitudes` are checked (:meth:`PoleRun.fit`).

        The equations are the symmetric top's for its angular momentum L = Cω₃k̂ + A k̂ × k̂′
        and figure axis k̂ in space, L′ = (3GM/r⁵)(C − A)(r·k̂)(r × k̂) (MacCullagh): exact
        for A = B, the free (Euler) nutation kept, the daily spin not resolved (the torque does
        not depend on it); DOP853 with steps of a quarter of a day (1.5e5 steps per century: a
        few seconds for 400 years). The Sun moves on its ecliptic orbit, the Moon on its orbit inclined 5.145° with
        the node regressing in 18.6 years (the core's mean orbits); each starts at its perigee.

        Parameters
        ----------
        duration:
            Simulated time (s, > 0; or a pint quantity: ``400 * ureg.year``).
        samples:
            Number of evenly spaced samples, both ends included (≥ 2).
        moon_node:
            Ω₀, the ecliptic longitude of the Moon's ascending node at the start (rad, or
            degrees with ``degrees=True``).
        mean_pole:
            Start on the true pole about the mean pole (obliquity ε, longitude 0), displaced by
            the principal nutation (Δψ₀ sin Ω₀, Δε₀ cos Ω₀), so that the run nods about the mean
            pole; by default the axis starts at obliquity ε, longitude 0.
        degrees:
            Whether a plain-number ``moon_node`` is in degrees.
        max_steps:
            Step limit: a run needing more (duration / a quarter day) is refused at once.

        Returns
        -------
        PoleRun
            ``t`` (s), ``longitude`` and ``obliquity`` (rad) of the axis, and the Moon's node.
        """
        t, lon, obl, node0, node_rate = self._core.simulate(
            as_scalar(duration, "duration"),
            as_count(samples, "samples"),
            as_angle(moon_node, "moon_node", degrees),
            as_flag(mean_pole, "mean_pole"),
            as_count(max_steps, "max_steps"),
        )
        return PoleRun(t, lon, obl, float(node0), float(node_rate))

    def averaged_pole(
        self,
        t: Any,
        *,
        moon_node: Any = _AVERAGED["moon_node"],
        nutation_scale: float = _AVERAGED["nutation_scale"],
        degrees: bool = False,
    ) -> AveragedPole:
        """The averaged pole at the times ``t``: the mean pole precessing uniformly about the
        ecliptic pole, nodding with the principal nutation (the core's closed form),

        Ω(t) = Ω₀ − 2π t/T_node,  ψ(t) = −P t + s Δψ₀ sin Ω(t),  ε(t) = ε₀ + s Δε₀ cos Ω(t),

        P the :attr:`precession_rate` (rad/s, negative: ψ grows westward at |P|), (Δψ₀, Δε₀)
        the :attr:`nutation_amplitudes` (rad), ε₀ the :attr:`obliquity`, T_node the Moon's
        nodal period (18.6 years). It is the pole :meth:`simulate` with ``mean_pole=True`` and
        the same ``moon_node`` integrates from the instantaneous torques, to within the
        semi-annual and fortnightly nods (about 2″) that the average leaves out.

        Parameters
        ----------
        t:
            Times (s; or a pint quantity), any shape.
        moon_node:
            Ω₀, the ecliptic longitude of the Moon's ascending node at t = 0 (rad, or degrees
            with ``degrees=True``).
        nutation_scale:
            s, the factor on the nutation (dimensionless, ≥ 0): 1 is the Earth's, 0 the mean
            pole alone; a drawing uses more to make the 9″ nod visible.
        degrees:
            Whether a plain-number ``moon_node`` is in degrees (the results stay in rad).

        Returns
        -------
        AveragedPole
            ``psi``, ``obliquity`` and ``moon_node`` (rad), each of the shape of ``t``.

        Raises PoinsotError naming ``t``, ``moon_node``, ``nutation_scale`` or (at obliquity
        0, where the nutation in longitude is undefined) ``obliquity``.
        """
        times = as_float_array(t, "t")
        psi, obl, node = self._core.averaged_pole(
            np.ascontiguousarray(times.ravel()),
            as_angle(moon_node, "moon_node", degrees),
            as_scalar(nutation_scale, "nutation_scale"),
        )
        shape = times.shape
        return AveragedPole(psi.reshape(shape), obl.reshape(shape), node.reshape(shape))

    @property
    def precession_parts(self) -> tuple[float, float]:
        """The Sun's and the Moon's parts of :attr:`precession_rate` (rad/s, both negative):
        −(3/2) (GM/(a³(1 − e²)^{3/2})) (H/ω) cos ε each, the Moon's times (1 − (3/2) sin² i)
        for its inclined, regressing orbit; the Moon's is about 2.16 times the Sun's."""
        sun, moon = self._core.precession_parts
        return float(sun), float(moon)

    @property
    def precession_rate(self) -> float:
        """The luni-solar precession rate (rad/s): the signed angular velocity of the spin axis
        about the ecliptic pole, from the orbit-averaged gravity-gradient torque of the Sun and
        the Moon on the bulge. Negative (retrograde, westward): −5040.03″ per Julian century for
        the defaults; its magnitude is within 0.03 % of the IAU 2006 ψ̇_A, 5038.481507″/cy
        (:data:`IAU2006_PRECESSION_RATE`), which also holds the geodesic precession (−1.92″/cy)
        and the planetary and second-order terms."""
        return float(self._core.precession_rate)

    @property
    def precession_period(self) -> float:
        """2π/|:attr:`precession_rate`| (s): about 25,714 Julian years for the defaults."""
        return float(self._core.precession_period)

    @property
    def nutation_amplitudes(self) -> tuple[float, float]:
        """The principal (18.6-year) nutation driven by the regression of the Moon's node
        (rad): (Δψ₀, Δε₀) of Δψ = Δψ₀ sin Ω, Δε = Δε₀ cos Ω (Ω the longitude of the Moon's node),
        in the IAU convention. For the defaults −17.281″ and 9.227″, 0.43 % and 0.23 % above the
        non-rigid IAU 2000A terms −17.2064161″ and 9.2052331″
        (:data:`IAU2000A_PRINCIPAL_NUTATION`). Refused at ``obliquity`` 0."""
        dpsi, deps = self._core.nutation_amplitudes
        return float(dpsi), float(deps)

    @property
    def nutation_amplitudes_by_precession(self) -> tuple[float, float]:
        """(Δψ₀, Δε₀) (rad) of :attr:`nutation_amplitudes` by a second route, in closed form
        from the Moon's part of :attr:`precession_parts`: the Moon alone turns the pole about
        its orbit's normal, which circles the ecliptic pole once a node period (18.6 years), so
        Δψ₀ = −K sin i cos i cos 2ε/(ν sin ε) and Δε₀ = K sin i cos i cos ε/ν with
        K = −moon_part/(cos ε (1 − (3/2) sin² i)), i the Moon's inclination and ν = 2π/T_node.
        Equal to :attr:`nutation_amplitudes` to round-off. Refused at ``obliquity`` 0."""
        dpsi, deps = self._core.nutation_amplitudes_by_precession
        return float(dpsi), float(deps)
