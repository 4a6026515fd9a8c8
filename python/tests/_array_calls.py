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
#: Latitudes (rad), all inside [-pi/2, pi/2]: a latitude past the pole is refused, by name.
_LAT = "lat = np.linspace(-1.5, 1.5, {n})"
_ANG = "a = np.random.default_rng(0).uniform(-3, 3, ({n}, 3))"
_MATS = _ANG + "\nR = ps.euler_to_matrix(a)"
#: (n, 3) points (m) or vectors, made without a random generator (fast to set up).
_PTS = "x = np.linspace(-1.0, 1.0, 3 * {n}).reshape({n}, 3)"
_SCREW = "s = ps.screw_axis(ps.axis_angle_to_matrix([0.0, 0.0, 1.0], 0.5), [0.0, 0.0, 1.0])"
_FRAME = (
    "f = ps.MovingFrame(angular_velocity=[0.0, 0.0, 1.0], angular_acceleration=[0.1, 0.0, 0.0])"
)
_SPRING = "sp = ps.SpringParticle(1.0, 2.0)"
_CUBOID = "c = ps.RigidBody.cuboid(1.0, (3.0, 1.0, 2.0))"
#: A closed UV sphere of radius 1 m: n − 1 rings of m vertices and two poles, 2 m (n − 1) faces
#: (5.2 M for n = 1000, m = 2600), built by numpy in about a second.
_SPHERE = """\
n, m = {n}, {m}
th = np.pi * np.arange(1, n) / n
ph = 2 * np.pi * np.arange(m) / m
ring = np.stack([np.outer(np.sin(th), np.cos(ph)), np.outer(np.sin(th), np.sin(ph)),
                 np.repeat(np.cos(th)[:, None], m, axis=1)], axis=-1).reshape(-1, 3)
v = np.vstack([[0.0, 0.0, 1.0], ring, [0.0, 0.0, -1.0]])
k = np.arange(n - 2)[:, None]
j = np.arange(m)[None, :]
a = 1 + k * m + j
b = 1 + k * m + (j + 1) % m
c, d = b + m, a + m
south = 1 + (n - 1) * m
jj = np.arange(m)
f = np.vstack([np.stack([np.zeros(m, int), 1 + jj, 1 + (jj + 1) % m], axis=1),
               np.stack([a, d, c], axis=-1).reshape(-1, 3),
               np.stack([a, c, b], axis=-1).reshape(-1, 3),
               np.stack([np.full(m, south), south - m + (jj + 1) % m, south - m + jj], axis=1)])"""

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
        "e = ps.Earth()\n" + _LAT.format(n=5 * 10**7),
        "e.effective_gravity(lat)",
    ),
    "Earth.coriolis_parameter": (
        "e = ps.Earth()\n" + _LAT.format(n=5 * 10**7),
        "e.coriolis_parameter(lat)",
    ),
    "Earth.jacobi_integral": (
        "e = ps.Earth()\n" + _PTS.format(n=2 * 10**7),
        "e.jacobi_integral(0.7, x, x)",
    ),
    "Screw.apply": (_SCREW + "\n" + _PTS.format(n=3 * 10**7), "s.apply(x)"),
    "MovingFrame.to_fixed": (_FRAME + "\n" + _PTS.format(n=10**7), "f.to_fixed(x, x, x)"),
    "MovingFrame.to_moving": (_FRAME + "\n" + _PTS.format(n=10**7), "f.to_moving(x, x, x)"),
    "MovingFrame.fictitious_forces": (
        _FRAME + "\n" + _PTS.format(n=2 * 10**7),
        "f.fictitious_forces(1.0, x, x)",
    ),
    "SpringParticle.jacobi_integral": (
        _FRAME + "\n" + _SPRING + "\n" + _PTS.format(n=2 * 10**7),
        "sp.jacobi_integral(f, x, x)",
    ),
    "RigidBody.from_point_masses": (
        _PTS.format(n=3 * 10**7) + "\nm = np.ones(len(x))",
        "ps.RigidBody.from_point_masses(m, x)",
    ),
    "RigidBody.inertia_about": (_CUBOID + "\n" + _PTS.format(n=2 * 10**7), "c.inertia_about(x)"),
    "RigidBody.angular_momentum": (
        _CUBOID + "\n" + _PTS.format(n=2 * 10**7),
        "c.angular_momentum(x)",
    ),
    # 20 M faces: the star-shaped proof got fast enough (2026-11-29) that 5 M finished in 0.46 s,
    # before the SIGINT 0.5 s in
    "RigidBody.from_mesh": (
        _SPHERE.format(n=2000, m=5000),
        "ps.RigidBody.from_mesh(v, f, density=1.0)",
    ),
    "RigidBody.from_mesh(merge_vertices=True)": (
        _SPHERE.format(n=1000, m=2600),
        "ps.RigidBody.from_mesh(v, f, density=1.0, merge_vertices=True)",
    ),
    # the real pole: each trial period a least-squares pass over the samples, some 200 passes
    "fit_wobble": (
        "t = np.linspace(0.0, 2e9, 2 * 10**6)\nx = np.cos(1.68e-7 * t)\ny = -np.sin(1.68e-7 * t)",
        "ps.fit_wobble(t, x, y)",
    ),
    "free_body_states": (
        _PTS.format(n=10**6) + "\nI = np.ones((len(x), 3)) * [1.0, 2.0, 3.0]",
        "ps.free_body_states(I, x + [0.1, 0.2, 0.3], np.linspace(0.0, 1.0, 2))",
    ),
}

#: Evaluators over a user's array that are fast per element (tens to a few hundred ns): an
#: array that fits in memory keeps them busy for a second or less, so they are measured by the
#: bench only (the same helpers as the calls above stop them).
FAST_CALLS: dict[str, tuple[str, str]] = {
    "SpringParticle.force": (_SPRING + "\n" + _PTS.format(n=2 * 10**7), "sp.force(x)"),
    "SpringParticle.acceleration": (
        _SPRING + "\n" + _PTS.format(n=2 * 10**7),
        "sp.acceleration(x)",
    ),
    "SpringParticle.potential": (_SPRING + "\n" + _PTS.format(n=2 * 10**7), "sp.potential(x)"),
    "SpringParticle.energy": (_SPRING + "\n" + _PTS.format(n=2 * 10**7), "sp.energy(x, x)"),
    "RigidBody.kinetic_energy": (
        _CUBOID + "\n" + _PTS.format(n=2 * 10**7),
        "c.kinetic_energy(x)",
    ),
    "RigidBody.holding_torque": (
        _CUBOID + "\n" + _PTS.format(n=2 * 10**7),
        "c.holding_torque(x)",
    ),
    "RigidBody.momentum_angle": (
        _CUBOID + "\n" + _PTS.format(n=2 * 10**7),
        "c.momentum_angle(x)",
    ),
    "HeavyTop.effective_potential": (
        _HEAVY + "\nth = np.linspace(0.1, 3.0, 5 * 10**7)",
        "h.effective_potential(th)",
    ),
    "HeavyTop.effective_potential_derivative": (
        _HEAVY + "\nth = np.linspace(0.1, 3.0, 5 * 10**7)",
        "h.effective_potential_derivative(th)",
    ),
}

#: Rotation conversions: fast per record (a few ns), so no array that fits in memory keeps
#: them busy for seconds; measured by the bench (latency ≤ the call's own time) only.
ROTATION_CALLS: dict[str, tuple[str, str]] = {
    "euler_to_matrix": (_ANG.format(n=10**7), "ps.euler_to_matrix(a)"),
    "rotate_vectors": (_MATS.format(n=10**7), "ps.rotate_vectors(R, a)"),
    "matrix_to_euler": (_MATS.format(n=10**7), "ps.matrix_to_euler(R)"),
    "body_angular_velocity": (_ANG.format(n=10**7), "ps.body_angular_velocity(a, a)"),
    "euler_rates": (
        _ANG.format(n=10**7) + "\nb = a * [1.0, 0.3, 1.0] + [0.0, 1.2, 0.0]",
        "ps.euler_rates(b, a)",
    ),
    "quaternion_multiply": (
        _ANG.format(n=10**7) + "\nq = ps.matrix_to_quaternion(ps.euler_to_matrix(a))",
        "ps.quaternion_multiply(q, q)",
    ),
}
