"""The exception tree of poinsot.

Every error poinsot raises for bad input is a :class:`PoinsotError`, which is also a
:class:`ValueError`; its message names the argument and the condition it violates::

    ValueError
    └── PoinsotError
        ├── InvalidInertiaError    inertia no body can have
        ├── InvalidRotationError   a matrix that is not a proper rotation
        ├── InvalidMeshError       a mesh that does not bound a solid
        ├── GimbalLockError        Euler-angle rates at the singular angles
        └── IntegrationError       an integration that diverged

The types are created by the compiled core (so that Rust errors map to them in one place,
``crates/poinsot-py/src/errors.rs``) and re-exported here.
"""

from __future__ import annotations

from ._core import (
    GimbalLockError,
    IntegrationError,
    InvalidInertiaError,
    InvalidMeshError,
    InvalidRotationError,
    PoinsotError,
)


class GimbalLockWarning(UserWarning):
    """Euler angles were extracted at gimbal lock: the triple is valid but not unique
    (poinsot sets the third angle to 0)."""


__all__ = [
    "PoinsotError",
    "InvalidInertiaError",
    "InvalidRotationError",
    "InvalidMeshError",
    "GimbalLockError",
    "IntegrationError",
    "GimbalLockWarning",
]
