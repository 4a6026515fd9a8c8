"""One table of exception classes for both front ends (issue 11, item 2).

The core maps each error kind to one class name (``ErrorKind::class_name`` in
``crates/poinsot/src/error.rs``); the Python binding raises the class of that name and the
WebAssembly binding throws an ``Error`` whose ``name`` it is. ``web/tests/error_table.test.mjs``
checks the JavaScript half against the same list.
"""

from __future__ import annotations

import numpy as np
import poinsot as ps
import pytest
from poinsot import _core

#: Every kind of core error and its class, in the core's order — the same list as in
#: web/tests/error_table.test.mjs.
EXPECTED = [
    ("InvalidArgument", "PoinsotError"),
    ("InvalidInertia", "InvalidInertiaError"),
    ("InvalidRotation", "InvalidRotationError"),
    ("InvalidMesh", "InvalidMeshError"),
    ("GimbalLock", "GimbalLockError"),
    ("Diverged", "IntegrationError"),
    ("Interrupted", "KeyboardInterrupt"),
]


def test_the_binding_exposes_the_cores_table() -> None:
    assert [tuple(row) for row in _core.error_classes()] == EXPECTED


def test_every_class_of_the_table_is_public() -> None:
    for _, name in EXPECTED:
        if name == "KeyboardInterrupt":  # Python's own: a stopped run
            continue
        cls = getattr(ps, name)
        assert cls.__name__ == name and cls is getattr(_core, name)
        assert issubclass(cls, ps.PoinsotError)


def _open_mesh() -> tuple[np.ndarray, np.ndarray]:
    vertices = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    faces = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2]])  # a tetrahedron missing a face
    return vertices, faces


#: A real error of each kind the Python API can raise (Interrupted is Ctrl-C: test_limits.py).
TRIGGERS = {
    "InvalidArgument": lambda: ps.RigidBody.solid_sphere(-1.0, 1.0),
    "InvalidInertia": lambda: ps.RigidBody.from_inertia(1.0, np.diag([1.0, 1.0, 3.0])),
    "InvalidRotation": lambda: ps.check_rotation_matrix(np.diag([1.0, 1.0, -1.0])),
    "InvalidMesh": lambda: ps.RigidBody.from_mesh(*_open_mesh()),
    "GimbalLock": lambda: ps.euler_rates([0.3, 0.0, 0.1], [0.5, 0.2, 3.0]),
    "Diverged": lambda: ps.simulate(
        [1, 2, 3], [0.1, 0.5, 1], 1.0, torque=lambda t, w, q: [np.nan, 0, 0], method="dop853"
    ),
}


@pytest.mark.parametrize(("kind", "name"), [row for row in EXPECTED if row[0] in TRIGGERS])
def test_a_real_error_of_each_kind_raises_its_class(kind: str, name: str) -> None:
    with pytest.raises(ps.PoinsotError) as info:
        TRIGGERS[kind]()
    assert type(info.value).__name__ == name, f"{kind}: {type(info.value).__name__}: {info.value}"
