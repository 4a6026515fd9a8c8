"""Input conversion shared by the public modules: arrays of float64 with shape checks whose
errors name the argument. Physics never lives here."""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import NDArray

from .errors import PoinsotError

FloatArray = NDArray[np.float64]


def as_float_array(value: Any, name: str, *, finite: bool = True) -> FloatArray:
    """``value`` as a float64 array; raises :class:`PoinsotError` naming ``name`` if it cannot be
    converted or (with ``finite``) holds NaN or infinity."""
    try:
        arr = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError) as exc:
        raise PoinsotError(f"{name}: must be an array of real numbers ({exc})") from None
    if finite and not np.all(np.isfinite(arr)):
        bad = arr[~np.isfinite(arr)].ravel()[0]
        raise PoinsotError(f"{name}: must be finite, got {bad}")
    return arr


def as_scalar(value: Any, name: str) -> float:
    """``value`` as a finite Python float; raises :class:`PoinsotError` naming ``name``."""
    arr = as_float_array(value, name)
    if arr.ndim != 0:
        raise PoinsotError(f"{name}: must be a scalar, got shape {arr.shape}")
    return float(arr)


def as_vectors(value: Any, name: str, size: int = 3) -> tuple[FloatArray, tuple[int, ...]]:
    """``value`` of shape ``(..., size)`` as a C-contiguous ``(N, size)`` array plus the
    leading shape (for reshaping results back)."""
    arr = as_float_array(value, name)
    if arr.ndim == 0 or arr.shape[-1] != size:
        raise PoinsotError(f"{name}: must have shape (..., {size}), got {arr.shape}")
    lead = arr.shape[:-1]
    return np.ascontiguousarray(arr.reshape(-1, size)), lead


def as_vector3(value: Any, name: str) -> FloatArray:
    """``value`` as one 3-vector of shape ``(3,)``."""
    arr = as_float_array(value, name)
    if arr.shape != (3,):
        raise PoinsotError(f"{name}: must have shape (3,), got {arr.shape}")
    return arr


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
