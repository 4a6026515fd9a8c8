"""The exception tree of poinsot.

Every error poinsot raises for bad input is a :class:`PoinsotError`, which is also a
:class:`ValueError`; its message names the argument and the condition it violates::

    ValueError
    └── PoinsotError
        ├── InvalidInertiaError    inertia no body can have
        ├── InvalidRotationError   a matrix that is not a proper rotation
        ├── InvalidMeshError       a mesh that does not bound a solid
        ├── GimbalLockError        Euler-angle rates at the singular angles
        ├── IntegrationError       an integration that diverged
        ├── ArgumentTypeError      an argument of the wrong type (also a TypeError)
        └── InternalError          a bug: a panic in the compiled core (please report it)

The types but :class:`ArgumentTypeError` are created by the compiled core (so that Rust errors
and panics map to them in one place, ``crates/poinsot-py/src/errors.rs``) and re-exported here.

The contract (pinned by the fuzz suite, ``python/tests/test_fuzz.py``): every call either
returns finite numbers only (but for documented infinities, such as the pitch of a pure
translation) or raises one of these errors, whose message starts with the name of the argument
at fault — ``"samples: must be >= 2, got 1"``. A long run is stopped by Ctrl-C
(``KeyboardInterrupt``) within a tenth of a second.
"""

from __future__ import annotations

from ._core import (
    GimbalLockError,
    IntegrationError,
    InternalError,
    InvalidInertiaError,
    InvalidMeshError,
    InvalidRotationError,
    PoinsotError,
)


class ArgumentTypeError(PoinsotError, TypeError):
    """An argument of the wrong type: text or complex numbers where real numbers are expected,
    a float where a count is, a non-boolean flag. Both a :class:`PoinsotError` and a
    ``TypeError``, so either ``except`` clause catches it."""


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
    "ArgumentTypeError",
    "InternalError",
    "GimbalLockWarning",
]
