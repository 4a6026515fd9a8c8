"""The public evaluators whose work grows with a user's array, each with a call that runs for
seconds (shared by ``test_interrupt_arrays.py`` and ``bench/ctrl_c_latency.py``).

Each entry is ``name: (setup, call)``: ``setup`` builds the arguments (not timed), ``call`` is
the statement that the test interrupts. Sizes are chosen so that each call takes several
seconds on a slow 2-core machine, and allocate little before the interrupt.
"""

from __future__ import annotations

_BODY = "b = ps.FreeRigidBody([1.0, 2.0, 3.0], [1.0, 0.1, 1.0])"
_TOP = "top = ps.FreeSymmetricTop(1.0, 0.5, [0.1, 0.0, 2.0])"
_HEAVY = "h = ps.HeavyTop(1.0, 0.5, 1.0, 0.8, phi_dot=0.5, psi_dot=6.0)"
_T = "t = np.linspace(0.0, 100.0, {n})"
_ANG = "a = np.random.default_rng(0).uniform(-3, 3, ({n}, 3))"
_MATS = _ANG + "\nR = ps.euler_to_matrix(a)"

ARRAY_CALLS: dict[str, tuple[str, str]] = {
    "FreeRigidBody.polhode": (_BODY, "b.polhode(10**8)"),
    "FreeRigidBody.contact_polhode": (_BODY, "b.contact_polhode(10**8)"),
    "FreeRigidBody.state": (_BODY + "\n" + _T.format(n=3 * 10**7), "b.state(t)"),
    "FreeRigidBody.omega": (_BODY + "\n" + _T.format(n=3 * 10**7), "b.omega(t)"),
    "FreeRigidBody.contact_point": (_BODY + "\n" + _T.format(n=2 * 10**7), "b.contact_point(t)"),
    "FreeSymmetricTop.attitude": (_TOP + "\n" + _T.format(n=3 * 10**7), "top.attitude(t)"),
    "HeavyTop.euler_angles": (_HEAVY + "\n" + _T.format(n=10**8), "h.euler_angles(t)"),
    "special.jacobi": (_T.format(n=3 * 10**7), "ps.special.jacobi(t, 0.7)"),
    "Earth.effective_gravity": (
        "e = ps.Earth()\n" + _T.format(n=5 * 10**7),
        "e.effective_gravity(t)",
    ),
    "Earth.coriolis_parameter": (
        "e = ps.Earth()\n" + _T.format(n=5 * 10**7),
        "e.coriolis_parameter(t)",
    ),
}

#: Rotation conversions: fast per record (a few ns), so no array that fits in memory keeps
#: them busy for seconds; measured by the bench (latency ≤ the call's own time) only.
ROTATION_CALLS: dict[str, tuple[str, str]] = {
    "euler_to_matrix": (_ANG.format(n=10**7), "ps.euler_to_matrix(a)"),
    "rotate_vectors": (_MATS.format(n=10**7), "ps.rotate_vectors(R, a)"),
    "matrix_to_euler": (_MATS.format(n=10**7), "ps.matrix_to_euler(R)"),
}
