"""Special functions of the core: the Jacobi elliptic functions sn, cn, dn and the amplitude am
(parameter m = k², as scipy and mpmath), and Legendre's elliptic integrals K, E, Π, F.

These are the functions behind :class:`poinsot.FreeRigidBody`; they are exposed for checks and
for users (scipy's ``ellipj`` is accurate only to ~1e-9 near m = 1; these to a few ulp).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from . import _core
from ._validate import FloatArray, as_float_array, as_scalar

__all__ = ["jacobi", "ellipk", "ellipe", "ellippi", "ellipf", "ellipeinc", "ellippiinc"]


def jacobi(u: Any, m: float) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """(sn, cn, dn, am)(u | m) for real ``u`` (any shape) and parameter ``0 ≤ m ≤ 1``; each
    result has the shape of ``u``. ``am`` is continuous: am(u + 2K) = am(u) + π."""
    arr = as_float_array(u, "u")
    out = np.asarray(_core.special_jacobi(np.ascontiguousarray(arr.reshape(-1)), as_scalar(m, "m")))
    sn, cn, dn, am = (out[:, k].reshape(arr.shape) for k in range(4))
    return sn, cn, dn, am


def ellipk(m: float) -> float:
    """K(m), the complete elliptic integral of the first kind (m < 1; it diverges at m = 1,
    where a ``PoinsotError`` names ``m``)."""
    return float(_core.special_elliptic("K", 0.0, 0.0, as_scalar(m, "m")))


def ellipe(m: float) -> float:
    """E(m), the complete elliptic integral of the second kind (m ≤ 1)."""
    return float(_core.special_elliptic("E", 0.0, 0.0, as_scalar(m, "m")))


def ellippi(n: float, m: float) -> float:
    """Π(n | m), the complete elliptic integral of the third kind (mpmath's ``ellippi(n, m)``)."""
    return float(_core.special_elliptic("PI", 0.0, as_scalar(n, "n"), as_scalar(m, "m")))


def ellipf(phi: float, m: float) -> float:
    """F(φ | m), the incomplete elliptic integral of the first kind."""
    return float(_core.special_elliptic("F", as_scalar(phi, "phi"), 0.0, as_scalar(m, "m")))


def ellipeinc(phi: float, m: float) -> float:
    """E(φ | m), the incomplete elliptic integral of the second kind."""
    return float(_core.special_elliptic("EINC", as_scalar(phi, "phi"), 0.0, as_scalar(m, "m")))


def ellippiinc(phi: float, n: float, m: float) -> float:
    """Π(n; φ | m), the incomplete elliptic integral of the third kind (mpmath's
    ``ellippi(n, phi, m)``)."""
    return float(
        _core.special_elliptic("PIINC", as_scalar(phi, "phi"), as_scalar(n, "n"), as_scalar(m, "m"))
    )
