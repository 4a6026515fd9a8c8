"""Rotations: Euler angles, Euler's and Chasles' theorems, quaternions and the kinematics of
Euler angles (the unit's "Euler's Theorem" and "Euler's Angles", eqs. 2.98-2.101).

Conventions (each pinned by a ``test_convention_*`` test, see ``CONVENTIONS.md``):

* rotations are **active** and right-handed: an attitude ``R`` maps body components to space
  components, ``x_space = R @ x_body``; ``R_z(a)`` turns ``e_x`` towards ``e_y``;
* Euler angles: a **lowercase** sequence plus an explicit ``intrinsic`` flag (never letter case,
  which scipy and MuJoCo read in opposite ways). For axes ``(a, b, c)`` and angles
  ``(alpha, beta, gamma)``::

      intrinsic=True  (body axes):  R = R_a(alpha) @ R_b(beta) @ R_c(gamma)
      intrinsic=False (space axes): R = R_c(gamma) @ R_b(beta) @ R_a(alpha)

  The default is the unit's intrinsic ``"zxz"`` ``(phi, theta, psi)``:
  ``R = R_z(phi) @ R_x(theta) @ R_z(psi)`` (precession, nutation, spin);
* canonical ranges returned by :func:`matrix_to_euler`: first and third angle in (-pi, pi];
  second in [0, pi] (proper Euler, e.g. ``zxz``) or [-pi/2, pi/2] (Tait-Bryan, e.g. ``xyz``);
* quaternions are **scalar-first** ``[w, x, y, z]``;
* SI units, radians (``degrees=True`` where angles are user-facing); angular velocity always
  in rad/s.

Every function broadcasts over leading dimensions like numpy: ``(..., 3)`` angles or vectors,
``(..., 3, 3)`` matrices, ``(..., 4)`` quaternions. Wherever a rotation is taken, a
``scipy.spatial.transform.Rotation`` is accepted too. Bad input raises a
:class:`~poinsot.PoinsotError` (a ``ValueError``) whose message names the argument.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field
from typing import Any, Union

import numpy as np
from numpy.typing import NDArray

from . import _core
from . import _display as show
from ._core import DEFAULTS as _DEFAULTS
from ._units import is_quantity
from ._validate import _is_scipy_rotation, as_float_array, as_scalar, as_vector3
from .errors import GimbalLockWarning, PoinsotError

FloatArray = NDArray[np.float64]

#: The twelve Euler sequences: six proper Euler, then six Tait-Bryan.
EULER_SEQUENCES: tuple[str, ...] = (
    "xyx", "xzx", "yxy", "yzy", "zxz", "zyz",
    "xyz", "xzy", "yxz", "yzx", "zxy", "zyx",
)  # fmt: skip

#: Tolerance on ``max|R^T R - I|`` and ``|det R - 1|`` with which every function that takes a
#: rotation matrix accepts it (:func:`check_rotation_matrix` has its own ``tol``).
ROTATION_MATRIX_TOL: float = _core.ROTATION_MATRIX_TOL
#: Orthonormality defect ``max|R^T R - I|`` (16 eps = 3.6e-15) above which the conversions
#: (:func:`matrix_to_quaternion`, :func:`matrix_to_euler`, :func:`rotation_axis`,
#: :func:`screw_axis`) convert an accepted matrix (e.g. one printed to 7 decimals) as its
#: nearest rotation, the polar factor, as scipy's ``Rotation.from_matrix`` does; up to it (any
#: rotation built in double precision) a matrix is converted from its own entries.
NEAREST_ROTATION_DEFECT: float = _core.NEAREST_ROTATION_DEFECT
#: The former name of :data:`ROTATION_MATRIX_TOL` (the same value), kept for existing code.
ROTATION_TOL: float = ROTATION_MATRIX_TOL

#: :func:`matrix_to_euler` reports gimbal lock where ``|sin beta|`` (proper Euler) or
#: ``|cos beta|`` (Tait-Bryan) read from the matrix is at most this.
EULER_LOCK_TOL: float = _core.EULER_LOCK_TOL

#: :func:`euler_rates` raises :class:`~poinsot.GimbalLockError` where ``|sin beta|`` (proper
#: Euler) or ``|cos beta|`` (Tait-Bryan) is at most this.
RATES_LOCK_TOL: float = _core.RATES_LOCK_TOL

_DEG = np.pi / 180.0


# ---- input helpers (conversion only) -------------------------------------------------------


def _seq(seq: Any) -> str:
    if not isinstance(seq, str):
        raise PoinsotError(f"seq: must be a string such as 'zxz' or 'xyz', got {seq!r}")
    return seq


def _flag(value: Any, name: str) -> bool:
    if not isinstance(value, (bool, np.bool_)):
        raise PoinsotError(f"{name}: must be True or False, got {value!r}")
    return bool(value)


def _records(value: Any, name: str, tail: tuple[int, ...]) -> tuple[FloatArray, tuple[int, ...]]:
    """``value`` of shape ``(..., *tail)`` as a C-contiguous float64 ``(N, *tail)`` array plus
    the leading shape. Finiteness is checked by the core (in the same pass as the work)."""
    arr = as_float_array(value, name, finite=False)
    k = len(tail)
    if arr.ndim < k or arr.shape[arr.ndim - k :] != tail:
        want = ", ".join(str(d) for d in tail)
        raise PoinsotError(f"{name}: must have shape (..., {want}), got {arr.shape}")
    lead = arr.shape[: arr.ndim - k]
    return np.ascontiguousarray(arr.reshape((-1, *tail))), lead


def _rotations(value: Any, name: str = "R") -> tuple[FloatArray, tuple[int, ...]]:
    """Rotation matrices ``(..., 3, 3)`` or a scipy ``Rotation`` as ``(N, 3, 3)`` + lead."""
    if _is_scipy_rotation(value):
        mats = np.asarray(value.as_matrix(), dtype=np.float64)
        if getattr(value, "single", mats.ndim == 2):
            mats = mats.reshape(3, 3)
        value = mats
    return _records(value, name, (3, 3))


def _tol(tol: Any) -> float:
    try:
        return float(tol)
    except (TypeError, ValueError, OverflowError):
        raise PoinsotError(f"tol: must be a real number, got {tol!r}") from None


def _broadcast(
    *items: tuple[Any, str, tuple[int, ...]],
) -> tuple[list[FloatArray], tuple[int, ...]]:
    """Broadcasts several arrays over their leading dimensions; returns flat ``(N, *tail)``
    C-contiguous arrays and the common leading shape."""
    arrays = []
    for value, name, tail in items:
        arr = as_float_array(value, name, finite=False)
        k = len(tail)
        if arr.ndim < k or arr.shape[arr.ndim - k :] != tail:
            want = ", ".join(str(d) for d in tail) if tail else ""
            shape = f"(..., {want})" if tail else "(...)"
            raise PoinsotError(f"{name}: must have shape {shape}, got {arr.shape}")
        arrays.append((arr, name, tail))
    leads = [a.shape[: a.ndim - len(t)] for a, _, t in arrays]
    try:
        lead = np.broadcast_shapes(*leads)
    except ValueError:
        names = ", ".join(f"{n} {a.shape}" for a, n, _ in arrays)
        raise PoinsotError(
            f"{arrays[-1][1]}: leading dimensions do not broadcast together ({names})"
        ) from None
    out = [
        np.ascontiguousarray(np.broadcast_to(a, lead + t).reshape((-1, *t))) for a, _, t in arrays
    ]
    return out, lead


def _run(lead: tuple[int, ...], fn: Any, *args: Any) -> Any:
    """Calls the core; for a single record (empty leading shape) drops the batch index that the
    core appends to error messages, which would only confuse there."""
    try:
        return fn(*args)
    except PoinsotError as exc:
        if lead:
            raise
        raise type(exc)(str(exc).replace(" (at flat index 0)", "")) from None


# ---- Euler angles --------------------------------------------------------------------------


def euler_to_matrix(
    angles: Any,
    seq: str = _DEFAULTS["euler_to_matrix"]["seq"],
    *,
    intrinsic: bool = True,
    degrees: bool = False,
) -> FloatArray:
    """Rotation matrices of Euler angles.

    For axes ``seq = "abc"`` and ``angles = (alpha, beta, gamma)``::

        intrinsic=True:  R = R_a(alpha) @ R_b(beta) @ R_c(gamma)   (about the body axes)
        intrinsic=False: R = R_c(gamma) @ R_b(beta) @ R_a(alpha)   (about the space axes)

    The default is the unit's convention (section "Euler's Angles", Fig. 2.12): intrinsic
    ``zxz`` with ``(phi, theta, psi)``, ``R = R_z(phi) @ R_x(theta) @ R_z(psi)``; ``R`` maps body
    components (axes 1, 2, 3) to space components (X, Y, Z). ``R_z(a) = [[cos a, -sin a, 0],
    [sin a, cos a, 0], [0, 0, 1]]`` (active rotations).

    Parameters
    ----------
    angles : array_like, shape (..., 3)
        ``(alpha, beta, gamma)`` in rad (degrees with ``degrees=True``), in the order of ``seq``.
    seq : str
        One of the twelve lowercase sequences of :data:`EULER_SEQUENCES`.
    intrinsic : bool, keyword-only
        Rotations about the body axes (True, default) or the space axes (False). Letter case
        never selects this: uppercase ``seq`` is an error.
    degrees : bool, keyword-only
        Angles in degrees.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        Rotation matrices.
    """
    flat, lead = _records(angles, "angles", (3,))
    if _flag(degrees, "degrees") and not is_quantity(angles):
        flat = flat * _DEG
    out = _run(lead, _core.euler_to_matrix, flat, _seq(seq), _flag(intrinsic, "intrinsic"))
    return out.reshape(lead + (3, 3))


def matrix_to_euler(
    R: Any,
    seq: str = _DEFAULTS["matrix_to_euler"]["seq"],
    *,
    intrinsic: bool = True,
    degrees: bool = False,
) -> FloatArray:
    """Euler angles of rotation matrices: the inverse of :func:`euler_to_matrix`.

    Returns ``(alpha, beta, gamma)`` in the canonical ranges: ``alpha, gamma`` in (-pi, pi];
    ``beta`` in [0, pi] for proper Euler sequences (``zxz``, ...) and in [-pi/2, pi/2] for
    Tait-Bryan sequences (``xyz``, ...). For the default intrinsic ``zxz``,
    ``R = R_z(phi) @ R_x(theta) @ R_z(psi)`` and the result is ``(phi, theta, psi)``.

    Accurate to round-off everywhere, near gimbal lock included (``atan2`` forms only; the
    matrix rebuilt from the angles equals ``R`` to round-off), and a small first or third angle
    (``1e-12``) to a few ulps relative. At gimbal lock
    (``|sin beta| <= EULER_LOCK_TOL`` for proper sequences, ``|cos beta| <= EULER_LOCK_TOL``
    for Tait-Bryan) only ``alpha + gamma`` or ``alpha - gamma`` is defined: the third angle is
    set to 0, the returned triple still rebuilds ``R``, and a
    :class:`~poinsot.GimbalLockWarning` is issued.

    Parameters
    ----------
    R : array_like, shape (..., 3, 3), or scipy Rotation
        Rotation matrices (orthonormal with det +1 within :data:`ROTATION_MATRIX_TOL`; one
        off by more than :data:`NEAREST_ROTATION_DEFECT` gives its nearest rotation's angles).
    seq, intrinsic, degrees
        As in :func:`euler_to_matrix`.

    Returns
    -------
    ndarray, shape (..., 3)
        Angles in rad (degrees with ``degrees=True``).

    Raises
    ------
    InvalidRotationError
        ``R`` is not a proper rotation (names ``R`` and the failing condition).
    """
    flat, lead = _rotations(R)
    out, locked = _run(lead, _core.matrix_to_euler, flat, _seq(seq), _flag(intrinsic, "intrinsic"))
    count = int(np.count_nonzero(locked))
    if count:
        first = int(np.flatnonzero(locked)[0])
        where = "" if not lead else f" ({count} of {locked.size}, first at flat index {first})"
        warnings.warn(
            f"matrix_to_euler: gimbal lock{where}: the middle angle is at the singularity of "
            f"sequence {seq!r}, so only the sum or difference of the first and third angles is "
            "defined; the third angle was set to 0 (the triple still reproduces R)",
            GimbalLockWarning,
            stacklevel=2,
        )
    if _flag(degrees, "degrees"):
        np.multiply(out, 1.0 / _DEG, out=out)
    return out.reshape(lead + (3,))


# ---- Euler's theorem -----------------------------------------------------------------------


def rotation_axis(R: Any) -> tuple[FloatArray, Union[float, FloatArray]]:
    """Euler's theorem: the axis and angle of a rotation, ``R = R_axis(angle)``.

    The unit's section "Euler's Theorem": a displacement with one point fixed is a rotation
    about one axis through that point. The angle is in [0, pi] (rad), right-hand rule about
    the returned unit axis. Accurate to round-off for every angle: tiny angles (``1e-12``) keep
    their relative accuracy and angles at and near pi their absolute accuracy (via the
    quaternion, Shepperd's method; no ``arccos`` of the trace). The identity returns angle 0
    and the conventional axis ``[0, 0, 1]``; at exactly pi the axis sign is conventional
    (``axis`` and ``-axis`` are the same half turn).

    Parameters
    ----------
    R : array_like, shape (3, 3) or (..., 3, 3), or scipy Rotation
        Rotation matrices (one off orthonormal by more than :data:`NEAREST_ROTATION_DEFECT`:
        its nearest rotation's axis and angle).

    Returns
    -------
    axis : ndarray, shape (3,) or (..., 3)
        Unit axis.
    angle : float or ndarray, shape (...)
        Angle in rad, in [0, pi]. A plain float for a single rotation.
    """
    flat, lead = _rotations(R)
    out = _run(lead, _core.rotation_axis, flat)
    if not lead:
        return out[0, :3].copy(), float(out[0, 3])
    return out[:, :3].reshape(lead + (3,)), out[:, 3].reshape(lead)


def axis_angle_to_matrix(axis: Any, angle: Any, *, degrees: bool = False) -> FloatArray:
    """Rodrigues' formula: the rotation by ``angle`` about ``axis`` (right-hand rule).

    ``R = I + sin(angle) K + (1 - cos(angle)) K @ K`` with ``K`` the cross-product matrix of the
    unit axis; the inverse of :func:`rotation_axis`.

    Parameters
    ----------
    axis : array_like, shape (..., 3)
        Rotation axes, any non-zero length (normalised here).
    angle : array_like, shape (...)
        Angles in rad (degrees with ``degrees=True``), any value; broadcast against ``axis``.

    Returns
    -------
    ndarray, shape (..., 3, 3)

    Raises
    ------
    PoinsotError
        A zero axis (names ``axis``) or non-finite input.
    """
    (ax, an), lead = _broadcast((axis, "axis", (3,)), (angle, "angle", ()))
    if _flag(degrees, "degrees") and not is_quantity(angle):
        an = an * _DEG
    return _run(lead, _core.axis_angle_to_matrix, ax, an).reshape(lead + (3, 3))


# ---- Chasles' theorem ----------------------------------------------------------------------


@dataclass(frozen=True, eq=False, repr=False)
class Screw(show.Displayed):
    """The screw of a rigid displacement ``x -> R @ x + t`` (Chasles' theorem).

    The displacement is a rotation by ``angle`` about the line through ``point`` along ``axis``
    plus a translation ``slide`` along ``axis``:
    ``R @ x + t == point + R @ (x - point) + slide * axis`` for every ``x``.

    A screw is usually :func:`screw_axis`'s result, but may be built from its parts,
    ``Screw(axis, point, angle, slide)``, checked by the core: ``axis`` (3,) finite and
    non-zero (normalised), ``point`` (3,) any finite point of the axis, m (kept as the point of
    the axis nearest the origin), ``angle`` in [0, pi] rad (a screw turning the other way has
    the opposite axis), ``slide`` finite, m. The pitch is derived, ``slide / angle`` (``-inf``
    for a pure translation with a negative slide); a ``pitch`` given must equal it to 1e-9
    relative. A :func:`screw_axis` result rebuilt from its five parts is the same screw, bit
    for bit. Errors name the part (:class:`PoinsotError`; :class:`ArgumentTypeError` for text
    and the like).

    Attributes
    ----------
    axis : ndarray, shape (3,)
        Unit direction of the screw axis (``t/|t|`` for a pure translation; ``[0, 0, 1]`` for
        the identity displacement).
    point : ndarray, shape (3,)
        The point of the axis nearest the origin, m (``point @ axis == 0``).
    angle : float
        Rotation angle about ``axis``, rad, in [0, pi].
    slide : float
        Signed translation along ``axis``, m (``axis @ t``).
    pitch : float
        ``slide / angle``, m/rad: ``inf`` for a pure translation, 0 for a pure rotation and for
        the identity displacement (never NaN).
    """

    axis: FloatArray = field(repr=False)
    point: FloatArray = field(repr=False)
    angle: float
    slide: float
    # None when built: derived by the core, a float on every Screw (the attribute's type).
    pitch: float = None  # type: ignore[assignment]

    def __post_init__(self) -> None:
        parts = _core.screw_new(
            (
                as_vector3(self.axis, "axis", finite=False),
                as_vector3(self.point, "point", finite=False),
                _real(self.angle, "angle"),
                _real(self.slide, "slide"),
            ),
            None if self.pitch is None else _real(self.pitch, "pitch"),
        )
        for name, value in zip(("axis", "point", "angle", "slide", "pitch"), parts):
            if isinstance(value, np.ndarray):
                value.flags.writeable = False
            object.__setattr__(self, name, value)

    def _rows(self) -> list[show.Row]:
        return [
            show.vec("axis", "direction of the screw axis", "n", self.axis),
            show.vec("point", "point of the axis nearest the origin", "p", self.point, "m"),
            show.scalar("angle", "rotation about the axis", "α", self.angle, "rad"),
            show.scalar("slide", "translation along the axis", "d", self.slide, "m"),
            show.scalar("pitch", "pitch, slide / angle", "", self.pitch, "m/rad"),
        ]

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Screw):
            return NotImplemented
        return (
            np.array_equal(self.axis, other.axis)
            and np.array_equal(self.point, other.point)
            and (self.angle, self.slide, self.pitch) == (other.angle, other.slide, other.pitch)
        )

    __hash__ = None  # type: ignore[assignment]  # holds arrays

    @property
    def _parts(self) -> tuple[FloatArray, FloatArray, float, float]:
        """The screw as the core's functions take it: (axis, point, angle, slide)."""
        return self.axis, self.point, self.angle, self.slide

    def displacement(self) -> tuple[FloatArray, FloatArray]:
        """The displacement ``(R, t)`` of this screw: ``R`` (3, 3) is the rotation by ``angle``
        about ``axis`` and ``t = point - R @ point + slide * axis`` (3,), m."""
        return _core.screw_displacement(self._parts)

    def displacement_at(self, s: float) -> tuple[FloatArray, FloatArray]:
        """The displacement ``(R(s), t(s))`` at fraction ``s`` (dimensionless) of the screw
        motion: the rotation by ``s * angle`` about the screw axis together with the slide
        ``s * slide`` along it (Chasles' theorem as a continuous motion). ``R(s)`` is (3, 3),
        ``t(s) = point - R(s) @ point + s * slide * axis`` is (3,), m. ``s = 0`` gives the
        identity, ``s = 1`` gives :meth:`displacement`; any finite ``s`` is accepted (negative
        runs the motion backwards).

        Raises
        ------
        PoinsotError
            ``s`` not finite.
        """
        return _core.screw_displacement(self._parts, as_scalar(s, "s"))

    def apply(self, x: Any) -> FloatArray:
        """Moves points ``x`` (..., 3), m, by the screw motion:
        ``point + R @ (x - point) + slide * axis`` (= ``R @ x + t``). Returns (..., 3)."""
        flat, lead = _records(x, "x", (3,))
        return _core.screw_apply(self._parts, flat).reshape(lead + (3,))


def screw_axis(R: Any, t: Any) -> Screw:
    """Chasles' theorem: the screw of the rigid displacement ``x -> R @ x + t``.

    With Euler's axis ``n`` and angle ``theta`` of ``R`` (:func:`rotation_axis`): the slide is
    ``d = n @ t``; the axis passes through ``p = (t_perp + cot(theta/2) n x t_perp) / 2`` with
    ``t_perp = t - d n``, the solution of ``R @ p + t = p + d n`` nearest the origin.

    Limits: a pure translation (angle 0 to round-off) gives ``axis = t/|t|``, ``point = 0``,
    ``angle = 0``, ``slide = |t|``, ``pitch = inf``; the identity displacement gives axis
    ``[0, 0, 1]``, point 0, angle 0, slide 0, pitch 0; a pure rotation gives pitch 0.

    Parameters
    ----------
    R : array_like, shape (3, 3), or scipy Rotation
        The rotation part.
    t : array_like, shape (3,)
        The translation part, m.

    Returns
    -------
    Screw
    """
    flat, lead = _rotations(R)
    if lead:
        raise PoinsotError(f"R: must be one rotation of shape (3, 3), got {lead + (3, 3)}")
    tt = as_float_array(t, "t", finite=False)
    if tt.shape != (3,):
        raise PoinsotError(f"t: must have shape (3,), got {tt.shape}")
    axis, point, angle, slide, pitch = _core.screw_axis(flat[0], np.ascontiguousarray(tt))
    return Screw(axis=axis, point=point, angle=angle, slide=slide, pitch=pitch)


def _real(value: Any, name: str) -> float:
    """A real scalar (finite or not: the core judges) for the screw's parts."""
    arr = as_float_array(value, name, finite=False)
    if arr.ndim != 0:
        raise PoinsotError(f"{name}: must be a scalar, got shape {arr.shape}")
    return float(arr)


# ---- kinematics of Euler angles (2.98-2.99) --------------------------------------------------


def _angular_velocity(
    angles: Any, rates: Any, seq: str, intrinsic: bool, degrees: bool, frame: str
) -> FloatArray:
    (a, r), lead = _broadcast((angles, "angles", (3,)), (rates, "rates", (3,)))
    if _flag(degrees, "degrees"):  # a pint quantity is in rad or rad/s already
        a = a if is_quantity(angles) else a * _DEG
        r = r if is_quantity(rates) else r * _DEG
    out = _run(lead, _core.angular_velocity, a, r, _seq(seq), _flag(intrinsic, "intrinsic"), frame)
    return out.reshape(lead + (3,))


def body_angular_velocity(
    angles: Any,
    rates: Any,
    seq: str = _DEFAULTS["body_angular_velocity"]["seq"],
    *,
    intrinsic: bool = True,
    degrees: bool = False,
) -> FloatArray:
    """Body-frame angular velocity from Euler angles and their rates (the unit's eq. 2.99).

    For the default intrinsic ``zxz`` ``(phi, theta, psi)`` this is eq. 2.99 (with its erratum
    ``omega_3 = omega_zeta``)::

        omega_1 = phi_dot sin(theta) sin(psi) + theta_dot cos(psi)
        omega_2 = phi_dot sin(theta) cos(psi) - theta_dot sin(psi)
        omega_3 = phi_dot cos(theta) + psi_dot

    For any intrinsic sequence ``"abc"`` (``R = R_a(alpha) @ R_b(beta) @ R_c(gamma)``)::

        omega_body = alpha_dot R_c(gamma)^T R_b(beta)^T e_a + beta_dot R_c(gamma)^T e_b
                     + gamma_dot e_c

    (``skew(omega_body) = R^T @ dR/dt``); an extrinsic ``"abc"`` with ``(alpha, beta, gamma)``
    is the intrinsic ``"cba"`` with ``(gamma, beta, alpha)``.

    Parameters
    ----------
    angles : array_like, shape (..., 3)
        Euler angles, rad (degrees with ``degrees=True``).
    rates : array_like, shape (..., 3)
        Their time derivatives, rad/s (deg/s with ``degrees=True``); broadcast with ``angles``.
    seq, intrinsic
        As in :func:`euler_to_matrix`.
    degrees : bool, keyword-only
        Angles in degrees and rates in deg/s. The angular velocity is **always rad/s**.

    Returns
    -------
    ndarray, shape (..., 3)
        Angular velocity, body components (axes 1, 2, 3), rad/s.
    """
    return _angular_velocity(angles, rates, seq, intrinsic, degrees, "body")


def space_angular_velocity(
    angles: Any,
    rates: Any,
    seq: str = _DEFAULTS["space_angular_velocity"]["seq"],
    *,
    intrinsic: bool = True,
    degrees: bool = False,
) -> FloatArray:
    """Space-frame angular velocity from Euler angles and their rates (eq. 2.98 generalised).

    For an intrinsic sequence ``"abc"``::

        omega_space = alpha_dot e_a + beta_dot R_a(alpha) e_b
                      + gamma_dot R_a(alpha) @ R_b(beta) e_c  (= R @ omega_body)

    (``skew(omega_space) = dR/dt @ R^T``). For the unit's ``zxz``: ``phi_dot`` about Z,
    ``theta_dot`` about the line of nodes, ``psi_dot`` about body axis 3. Parameters and units
    as in :func:`body_angular_velocity`; returns space components (X, Y, Z), rad/s,
    shape (..., 3).
    """
    return _angular_velocity(angles, rates, seq, intrinsic, degrees, "space")


def euler_rates(
    angles: Any,
    omega_body: Any,
    seq: str = _DEFAULTS["euler_rates"]["seq"],
    *,
    intrinsic: bool = True,
    frame: str = _DEFAULTS["euler_rates"]["frame"],
    degrees: bool = False,
) -> FloatArray:
    """Euler-angle rates from the angular velocity: the inverse of
    :func:`body_angular_velocity` (``frame="body"``) or :func:`space_angular_velocity`
    (``frame="space"``).

    For the default intrinsic ``zxz`` and the body frame (eq. 2.99 solved for the rates)::

        phi_dot   = (omega_1 sin(psi) + omega_2 cos(psi)) / sin(theta)
        theta_dot =  omega_1 cos(psi) - omega_2 sin(psi)
        psi_dot   =  omega_3 - phi_dot cos(theta)

    Parameters
    ----------
    angles : array_like, shape (..., 3)
        Euler angles, rad (degrees with ``degrees=True``).
    omega_body : array_like, shape (..., 3)
        Angular velocity, **rad/s** (also with ``degrees=True``): its body-frame components
        (eq. 2.99's ω₁, ω₂, ω₃), or its space-frame components with ``frame="space"``.
    seq, intrinsic
        As in :func:`euler_to_matrix`.
    frame : {"body", "space"}, keyword-only
        The frame of ``omega_body``'s components.
    degrees : bool, keyword-only
        Angles in degrees and the returned rates in deg/s.

    Returns
    -------
    ndarray, shape (..., 3)
        Rates in the order of ``seq``, rad/s (deg/s with ``degrees=True``).

    Raises
    ------
    GimbalLockError
        At the singular angles: ``|sin beta| <= RATES_LOCK_TOL`` for proper Euler sequences
        (theta = 0 or pi for ``zxz``), ``|cos beta| <= RATES_LOCK_TOL`` for Tait-Bryan
        (beta = +-pi/2). The message names ``angles`` and the middle angle.
    """
    if not isinstance(frame, str):
        raise PoinsotError(f"frame: must be 'body' or 'space', got {frame!r}")
    (a, w), lead = _broadcast((angles, "angles", (3,)), (omega_body, "omega_body", (3,)))
    deg = _flag(degrees, "degrees")
    if deg:
        a = a * _DEG
    out = _run(lead, _core.euler_rates, a, w, _seq(seq), _flag(intrinsic, "intrinsic"), frame)
    if deg:
        np.multiply(out, 1.0 / _DEG, out=out)
    return out.reshape(lead + (3,))


# ---- quaternions and matrices ----------------------------------------------------------------


def matrix_to_quaternion(R: Any) -> FloatArray:
    """Unit quaternions of rotation matrices, **scalar-first** ``[w, x, y, z]``, ``w >= 0``.

    ``q = [cos(a/2), sin(a/2) n]`` for the rotation by ``a`` about unit axis ``n``; robust for
    every angle (Shepperd/Markley). At ``w = 0`` (half turns) the first non-zero of ``x, y, z``
    is positive. A matrix off orthonormal by more than :data:`NEAREST_ROTATION_DEFECT` (and
    within :data:`ROTATION_MATRIX_TOL`; e.g. printed to 7 decimals) gives the quaternion of its
    nearest rotation (the polar factor, as scipy's ``Rotation.from_matrix``), not of its raw
    entries.

    Parameters
    ----------
    R : array_like, shape (..., 3, 3), or scipy Rotation

    Returns
    -------
    ndarray, shape (..., 4)
        ``[w, x, y, z]``.
    """
    flat, lead = _rotations(R)
    return _run(lead, _core.matrix_to_quaternion, flat).reshape(lead + (4,))


def quaternion_to_matrix(q: Any, *, normalize: bool = False) -> FloatArray:
    """Rotation matrices of quaternions given **scalar-first** ``[w, x, y, z]``.

    ``R = [[1-2(y^2+z^2), 2(xy-wz), 2(xz+wy)], [2(xy+wz), 1-2(x^2+z^2), 2(yz-wx)],
    [2(xz-wy), 2(yz+wx), 1-2(x^2+y^2)]]``.

    Parameters
    ----------
    q : array_like, shape (..., 4)
        Quaternions ``[w, x, y, z]``; unit within 1e-6 unless ``normalize=True``.
    normalize : bool, keyword-only
        Divide any finite non-zero quaternion by its norm first.

    Returns
    -------
    ndarray, shape (..., 3, 3)

    Raises
    ------
    InvalidRotationError
        A zero quaternion, or a non-unit one without ``normalize`` (names ``q``).
    """
    flat, lead = _records(q, "q", (4,))
    norm = _flag(normalize, "normalize")
    return _run(lead, _core.quaternion_to_matrix, flat, norm).reshape(lead + (3, 3))


def quaternion_multiply(p: Any, q: Any) -> FloatArray:
    """Hamilton products ``p * q`` of quaternions given **scalar-first** ``[w, x, y, z]``.

    For unit quaternions the product is the rotation "first ``q``, then ``p``":
    ``quaternion_to_matrix(p * q) == quaternion_to_matrix(p) @ quaternion_to_matrix(q)``.
    Not normalised. ``p`` (..., 4) and ``q`` (..., 4) broadcast; returns (..., 4).
    """
    (a, b), lead = _broadcast((p, "p", (4,)), (q, "q", (4,)))
    return _run(lead, _core.quaternion_multiply, a, b).reshape(lead + (4,))


def rotate_vectors(R: Any, v: Any) -> FloatArray:
    """Applies rotations to vectors: ``R @ v`` (active; for an attitude ``R``, body components
    in, space components out).

    Parameters
    ----------
    R : array_like, shape (..., 3, 3), or scipy Rotation
    v : array_like, shape (..., 3)
        Broadcast against ``R``'s leading dimensions.

    Returns
    -------
    ndarray, shape (..., 3)
    """
    if _is_scipy_rotation(R):
        flat, rlead = _rotations(R)
        R = flat.reshape(rlead + (3, 3))
    (m, x), lead = _broadcast((R, "R", (3, 3)), (v, "v", (3,)))
    return _run(lead, _core.rotate_vectors, m, x).reshape(lead + (3,))


def check_rotation_matrix(
    R: Any, *, tol: float = _DEFAULTS["check_rotation_matrix"]["tol"]
) -> FloatArray:
    """Validates rotation matrices and returns them as a float64 array.

    Each matrix must be finite, orthonormal (``max|R^T R - I| <= tol``) and proper
    (``|det R - 1| <= tol``).

    Parameters
    ----------
    R : array_like, shape (..., 3, 3), or scipy Rotation
    tol : float, keyword-only
        Tolerance of both conditions.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        ``R`` as float64.

    Raises
    ------
    InvalidRotationError
        Naming ``R``, the failing condition and by how much (and the flat index in a batch).
    PoinsotError
        Non-finite entries or a wrong shape.
    """
    flat, lead = _rotations(R)
    _run(lead, _core.check_rotation_matrix, flat, _tol(tol))
    return flat.reshape(lead + (3, 3))


def as_scipy_rotation(R: Any) -> Any:
    """``R`` (..., 3, 3) as a ``scipy.spatial.transform.Rotation`` (checked first with
    :data:`ROTATION_MATRIX_TOL`; a scipy Rotation is returned as it is). Needs scipy
    (``pip install poinsot[scipy]``)."""
    if _is_scipy_rotation(R):
        return R
    try:
        from scipy.spatial.transform import Rotation
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise ImportError(
            "as_scipy_rotation needs scipy: pip install 'poinsot[scipy]' (or pip install scipy)"
        ) from exc
    mats = check_rotation_matrix(R, tol=ROTATION_MATRIX_TOL)
    return Rotation.from_matrix(mats)


__all__ = [
    "EULER_SEQUENCES",
    "Screw",
    "as_scipy_rotation",
    "axis_angle_to_matrix",
    "body_angular_velocity",
    "check_rotation_matrix",
    "euler_rates",
    "euler_to_matrix",
    "matrix_to_euler",
    "matrix_to_quaternion",
    "quaternion_multiply",
    "quaternion_to_matrix",
    "rotate_vectors",
    "rotation_axis",
    "screw_axis",
    "space_angular_velocity",
]
