"""Input conversion shared by the public modules: arrays of float64 with shape checks whose
errors name the argument. Physics never lives here."""

from __future__ import annotations

import math
import sys
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ._units import is_quantity, to_si
from .errors import ArgumentTypeError, PoinsotError

FloatArray = NDArray[np.float64]

#: The largest count (samples, parcels, steps) a call accepts before the core's memory budget
#: and step limits are asked: what a C ``ssize_t`` holds.
MAX_COUNT = sys.maxsize

_F64 = np.dtype(np.float64)
_isfinite = math.isfinite

#: Python containers and scalars from which ``np.asarray`` always builds a new array: when it is
#: already float64 it is used as it is (no ``astype`` copy, no overflow check: float64 to float64
#: cannot overflow).
_FRESH = (list, tuple, float, int, np.float64)

#: The largest ``int`` the scalar fast path converts itself (``float()`` of a larger one may
#: overflow; those take the general path and its error).
_INT_FAST = 2**1023


def as_float_array(value: Any, name: str, *, finite: bool = True) -> FloatArray:
    """``value`` as a float64 array; raises :class:`ArgumentTypeError` naming ``name`` for text,
    booleans or complex numbers (never silently dropping an imaginary part), and
    :class:`PoinsotError` if it cannot be converted (ragged lists, numbers beyond the double
    range) or, with ``finite``, holds NaN or infinity."""
    if type(value) is not np.ndarray or value.dtype != np.float64:
        if is_quantity(value):  # units at the door: SI for the argument's dimension
            value = to_si(value, name)
        try:
            raw = np.asarray(value)
        except (TypeError, ValueError) as exc:
            raise PoinsotError(f"{name}: must be an array of real numbers ({exc})") from None
        if raw.dtype is _F64 and type(value) in _FRESH:
            return _finite(raw, name) if finite else raw
        kind = raw.dtype.kind
        if kind == "c":
            raise ArgumentTypeError(f"{name}: must be real, got complex numbers")
        if kind in "USbVMm":
            what = {"U": "text", "S": "bytes", "b": "booleans"}.get(kind, str(raw.dtype))
            raise ArgumentTypeError(f"{name}: must be real numbers, got {what}")
        try:
            with np.errstate(over="raise"):
                value = raw.astype(np.float64)
        except OverflowError:
            raise PoinsotError(
                f"{name}: a number is beyond the range of doubles (about 1.8e308)"
            ) from None
        except (TypeError, ValueError) as exc:
            if any(isinstance(x, complex) for x in np.ravel(raw)):
                raise ArgumentTypeError(f"{name}: must be real, got complex numbers") from None
            raise ArgumentTypeError(f"{name}: must be an array of real numbers ({exc})") from None
        except FloatingPointError:
            raise PoinsotError(
                f"{name}: a number is beyond the range of doubles (about 1.8e308)"
            ) from None
    return _finite(value, name) if finite else value


def returned(got: Any, name: str, what: str, shown: Callable[[Any], str] = repr) -> FloatArray:
    """What the user's callable ``name`` returned, as a float64 array (finite or not: the core
    judges), or :class:`PoinsotError` naming ``name``: "the callable must return ``what``, got
    ``shown(got)``" (``shown`` runs only then)."""
    try:
        return as_float_array(got, name, finite=False)
    except PoinsotError:
        raise PoinsotError(f"{name}: the callable must return {what}, got {shown(got)}") from None


def _finite(arr: FloatArray, name: str) -> FloatArray:
    """``arr`` if every entry is finite, else :class:`PoinsotError` naming ``name`` and the
    first non-finite entry. Small arrays are checked entry by entry in Python (numpy's
    reductions cost microseconds of overhead on three numbers)."""
    if arr.size <= 8:
        if all(map(math.isfinite, arr.ravel().tolist())):
            return arr
    elif np.isfinite(arr).all():
        return arr
    bad = arr[~np.isfinite(arr)].ravel()[0]
    raise PoinsotError(f"{name}: must be finite, got {bad}")


def plain_float(value: Any) -> float | None:
    """The fast path of a scalar argument: ``value`` as a Python float when it plainly is a
    finite number — a ``float`` or numpy ``float64``, or an ``int`` (not a bool) of at most
    2**1023 in magnitude — else None, and the caller takes the general path
    (:func:`as_scalar`, :func:`as_float_array`), whose checks raise. It accepts nothing the
    general path refuses and returns the same number."""
    kind = type(value)
    if kind is float:
        return value if _isfinite(value) else None
    if kind is np.float64:
        return float(value) if _isfinite(value) else None
    if kind is int and -_INT_FAST <= value <= _INT_FAST:
        return float(value)
    return None


def as_scalar(value: Any, name: str) -> float:
    """``value`` as a finite Python float; raises :class:`PoinsotError` naming ``name``."""
    x = plain_float(value)
    if x is not None:
        return x
    arr = as_float_array(value, name)
    if arr.ndim != 0:
        raise PoinsotError(f"{name}: must be a scalar, got shape {arr.shape}")
    return float(arr)


def as_count(value: Any, name: str, minimum: int = 0) -> int:
    """``value`` as a Python int ≥ ``minimum``: an ``int`` or numpy integer (not a bool, not a
    float — ``2.5`` is refused, never truncated), else :class:`ArgumentTypeError` naming
    ``name``; out of range, :class:`PoinsotError`. The core then checks it against the memory
    budget."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise ArgumentTypeError(f"{name}: must be an integer, got {type(value).__name__} {value!r}")
    count = int(value)
    if count < minimum:
        what = "a positive integer" if minimum == 1 else f">= {minimum}"
        raise PoinsotError(f"{name}: must be {what}, got {count}")
    if count > MAX_COUNT:
        raise PoinsotError(f"{name}: must be <= {MAX_COUNT}, got {count}")
    return count


def as_flag(value: Any, name: str) -> bool:
    """``value`` as a bool: ``True``/``False`` (or numpy booleans) only — never read by
    truthiness (``"no"`` is refused) — else :class:`ArgumentTypeError` naming ``name``."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise ArgumentTypeError(f"{name}: must be True or False, got {type(value).__name__} {value!r}")


def tolerances(rtol: Any, atol: Any, max_steps: Any) -> tuple[float, float, int]:
    """An integration's tolerances and step limit (≥ 1), each checked naming its keyword."""
    return as_scalar(rtol, "rtol"), as_scalar(atol, "atol"), as_count(max_steps, "max_steps", 1)


def run_settings(
    samples: Any, rtol: Any, atol: Any, max_steps: Any
) -> tuple[int, float, float, int]:
    """A run's sample count (≥ 2), then :func:`tolerances`: the settings the core's runs take
    in this order (``samples, rtol, atol, max_steps``)."""
    return (as_count(samples, "samples", 2), *tolerances(rtol, atol, max_steps))


def as_choice(value: Any, name: str, choices: tuple[str, ...]) -> str:
    """``value`` as one of the strings ``choices``; :class:`ArgumentTypeError` for a
    non-string, :class:`PoinsotError` for another string, both naming ``name``."""
    if not isinstance(value, str):
        raise ArgumentTypeError(
            f"{name}: must be one of {', '.join(map(repr, choices))}, got {type(value).__name__} {value!r}"
        )
    if value not in choices:
        raise PoinsotError(f"{name}: must be one of {', '.join(map(repr, choices))}, got {value!r}")
    return value


def as_angle(value: Any, name: str, degrees: Any = False) -> float:
    """One angle (or angular rate) as a float in radians: ``value`` converted from degrees
    when ``degrees`` is true (a pint quantity carries its unit: converted to radians whatever
    ``degrees``)."""
    x = as_scalar(value, name)
    return float(np.radians(x)) if in_degrees(value, degrees) else x


def in_degrees(value: Any, degrees: Any) -> bool:
    """Whether the angles given as ``value`` are in degrees: ``degrees`` (checked a bool) for
    plain numbers; never for a pint quantity, already in radians (:mod:`poinsot._units`)."""
    return as_flag(degrees, "degrees") and not is_quantity(value)


def as_flat(
    value: Any, name: str, degrees: Any = False, *, finite: bool = True
) -> tuple[FloatArray, tuple[int, ...]]:
    """``value`` of any shape as a C-contiguous 1-D float64 array plus its shape (for
    :func:`shaped`), converted from degrees to radians when ``degrees`` is true. With
    ``finite=False`` NaN and infinity pass, for a core function that refuses them itself."""
    arr = as_float_array(value, name, finite=finite)
    if in_degrees(value, degrees):
        arr = np.radians(arr)
    return np.ascontiguousarray(arr.reshape(-1), dtype=np.float64), arr.shape


def shaped(arr: FloatArray, shape: tuple[int, ...]) -> Any:
    """``arr`` back in the caller's ``shape``: a float for a scalar input, else an array."""
    out = arr.reshape(shape)
    return float(out) if out.ndim == 0 else out


def as_vectors(value: Any, name: str, size: int = 3) -> tuple[FloatArray, tuple[int, ...]]:
    """``value`` of shape ``(..., size)`` as a C-contiguous ``(N, size)`` array plus the
    leading shape (for reshaping results back)."""
    arr = as_float_array(value, name)
    if arr.ndim == 0 or arr.shape[-1] != size:
        raise PoinsotError(f"{name}: must have shape (..., {size}), got {arr.shape}")
    lead = arr.shape[:-1]
    return np.ascontiguousarray(arr.reshape(-1, size)), lead


def as_vector3(value: Any, name: str, *, finite: bool = True) -> FloatArray:
    """``value`` as one 3-vector of shape ``(3,)`` (with ``finite=False`` non-finite entries
    pass, for the core to judge). The free bodies' vectors are converted by the binding instead
    (``crates/poinsot-py/src/convert.rs``, ``triple``), which reads plain lists, tuples and
    float64 arrays itself and hands anything else to :func:`as_float_array`."""
    arr = as_float_array(value, name, finite=finite)
    if arr.shape != (3,):
        raise PoinsotError(f"{name}: must have shape (3,), got {arr.shape}")
    return arr


def as_rows(value: Any, name: str, size: int, *, single: bool = False) -> FloatArray:
    """``value`` as a C-contiguous ``(N, size)`` float64 array of N bodies' rows (non-finite
    entries pass, for the core to judge); with ``single`` one row ``(size,)`` is accepted too,
    as ``(1, size)``."""
    arr = as_float_array(value, name, finite=False)
    if single and arr.ndim == 1 and arr.shape[0] == size:
        arr = arr[None, :]
    if arr.ndim != 2 or arr.shape[1] != size:
        either = f" or ({size},)" if single else ""
        raise PoinsotError(f"{name}: must have shape (N, {size}){either}, got {arr.shape}")
    return np.ascontiguousarray(arr, dtype=np.float64)


def as_matrices(value: Any, name: str) -> tuple[FloatArray, tuple[int, ...]]:
    """``value`` of shape ``(..., 3, 3)`` (or a ``scipy.spatial.transform.Rotation``) as a
    C-contiguous ``(N, 3, 3)`` array plus the leading shape."""
    if _is_scipy_rotation(value):
        mats = np.asarray(value.as_matrix(), dtype=np.float64)
        single = getattr(value, "single", mats.ndim == 2)
        if single:
            mats = mats.reshape(3, 3)
        value = mats
    arr = as_float_array(value, name)
    if arr.ndim < 2 or arr.shape[-2:] != (3, 3):
        raise PoinsotError(f"{name}: must have shape (..., 3, 3), got {arr.shape}")
    lead = arr.shape[:-2]
    return np.ascontiguousarray(arr.reshape(-1, 3, 3)), lead


def _is_scipy_rotation(value: Any) -> bool:
    cls = type(value)
    return cls.__name__ == "Rotation" and cls.__module__.startswith("scipy.spatial.transform")


def as_callable(value: Any, name: str, *, optional: bool = True) -> Any:
    """``value`` if it is callable (or None when ``optional``), else :class:`ArgumentTypeError`
    naming ``name``."""
    if value is None and optional:
        return None
    if not callable(value):
        raise ArgumentTypeError(
            f"{name}: must be callable{' or None' if optional else ''}, got {type(value).__name__}"
        )
    return value
