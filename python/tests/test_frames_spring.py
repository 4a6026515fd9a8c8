"""SpringParticle (frames.py): the particle on an isotropic spring, seen from a turning frame.

Against the closed form (an ellipse centred on the anchor at √(k/m) in the fixed frame), the
conservation of the fixed-frame energy and of the Jacobi integral in a uniformly turning frame
(with a turning-up frame as the negative control), and the errors naming the argument."""

from __future__ import annotations

import numpy as np
import poinsot as ps
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st


def test_force_acceleration_and_potential_are_hookes_law() -> None:
    p = ps.SpringParticle(mass=2.0, stiffness=8.0)
    r = np.array([[0.5, -1.0, 2.0], [0.0, 0.0, 0.0]])
    np.testing.assert_array_equal(p.force(r), -8.0 * r)
    np.testing.assert_array_equal(p.acceleration(r), -4.0 * r)
    np.testing.assert_allclose(p.potential(r), 0.5 * 8.0 * (r**2).sum(axis=1), rtol=1e-15)
    assert p.potential([1.0, 0, 0]) == 4.0  # a scalar for one position
    assert repr(p) == "SpringParticle(mass=2.0, stiffness=8.0)"


@settings(max_examples=25, deadline=None)
@given(
    k=st.floats(0.5, 20.0),
    m=st.floats(0.2, 5.0),
    rate=st.floats(-2.0, 2.0),
    x=st.floats(-2.0, 2.0),
    vy=st.floats(-2.0, 2.0),
)
def test_fixed_frame_orbit_is_the_closed_form_ellipse(
    k: float, m: float, rate: float, x: float, vy: float
) -> None:
    p = ps.SpringParticle(m, k)
    table = ps.MovingFrame(angular_velocity=[0, 0, rate])
    r0, v0 = np.array([x, 0.3, 0.1]), np.array([0.2, vy, -0.1])
    run = p.simulate(table, r0, v0, 5.0, samples=50, rtol=1e-12, atol=1e-12)
    pos, vel = run.to_fixed()
    w = np.sqrt(k / m)
    v0_fixed = table.to_fixed(r0, v0).velocity  # ṙ' = ṙ + ω × r at t = 0
    t = run.t[:, None]
    exact = np.cos(w * t) * r0 + np.sin(w * t) * v0_fixed / w
    scale = np.linalg.norm(r0) + np.linalg.norm(v0_fixed) / w
    assert np.abs(pos - exact).max() < 1e-8 * scale
    # E = ½ m |ṙ'|² + ½ k |r'|² is conserved in the fixed frame.
    e = p.energy(pos, vel)
    assert np.ptp(e) < 1e-9 * abs(e[0]) + 1e-15


def test_jacobi_integral_is_conserved_on_a_uniform_turntable_only() -> None:
    p = ps.SpringParticle(1.0, 3.0)
    uniform = ps.MovingFrame(angular_velocity=[0, 0, 1.3])
    run = p.simulate(
        uniform, [1.0, 0.5, 0.0], [0.0, -0.4, 0.2], 30.0, samples=300, rtol=1e-12, atol=1e-12
    )
    j = np.array(
        [
            p.jacobi_integral(run.frame_at(float(t)), r, v)
            for t, r, v in zip(run.t, run.position, run.velocity)
        ]
    )
    assert np.ptp(j) < 1e-9 * abs(j[0])
    # Negative control: a turntable spinning up (ω̇ ≠ 0) does work through the Euler force.
    spinning_up = ps.MovingFrame(angular_velocity=[0, 0, 1.3], angular_acceleration=[0, 0, 0.2])
    run = p.simulate(spinning_up, [1.0, 0.5, 0.0], [0.0, -0.4, 0.2], 30.0, samples=300)
    j = np.array(
        [
            p.jacobi_integral(run.frame_at(float(t)), r, v)
            for t, r, v in zip(run.t, run.position, run.velocity)
        ]
    )
    assert np.ptp(j) > 1e-2 * abs(j[0])


def test_without_a_spring_it_is_simulate_particle() -> None:
    table = ps.MovingFrame(angular_velocity=[0, 0, 0.9])
    a = ps.SpringParticle(1.5, 0.0).simulate(table, [1.0, 0, 0], [0, 1.0, 0], 4.0, samples=20)
    b = ps.simulate_particle(table, [1.0, 0, 0], [0, 1.0, 0], 4.0, mass=1.5, samples=20)
    np.testing.assert_array_equal(a.states, b.states)


def test_stiffness_adds_to_a_callable_force() -> None:
    # −k r given as a Python callable and as the core's spring give the same motion.
    table = ps.MovingFrame(angular_velocity=[0, 0, 0.5])
    p = ps.SpringParticle(1.0, 2.0)
    a = p.simulate(table, [1.0, 0, 0], [0, 0.5, 0], 6.0, samples=30, rtol=1e-12, atol=1e-12)
    b = ps.simulate_particle(
        table,
        [1.0, 0, 0],
        [0, 0.5, 0],
        6.0,
        samples=30,
        rtol=1e-12,
        atol=1e-12,
        force=lambda t, r, v: -2.0 * np.asarray(r),
    )
    np.testing.assert_allclose(a.states, b.states, atol=1e-10)


@pytest.mark.parametrize(
    ("args", "name"),
    [
        ((0.0, 1.0), "mass"),
        ((-1.0, 1.0), "mass"),
        ((float("nan"), 1.0), "mass"),
        ((1.0, -1.0), "stiffness"),
        ((1.0, float("inf")), "stiffness"),
        (("a", 1.0), "mass"),
    ],
)
def test_bad_particles_are_refused_by_name(args: tuple[object, object], name: str) -> None:
    with pytest.raises(ps.PoinsotError, match=f"^{name}"):
        ps.SpringParticle(*args)  # type: ignore[arg-type]


def test_bad_states_are_refused_by_name() -> None:
    p = ps.SpringParticle(1.0, 1.0)
    table = ps.MovingFrame(angular_velocity=[0, 0, 1.0])
    with pytest.raises(ps.PoinsotError, match="^position"):
        p.force([np.nan, 0, 0])
    with pytest.raises(ps.PoinsotError, match="^position"):
        p.potential([1.0, 2.0])
    with pytest.raises(ps.PoinsotError, match="^velocity"):
        p.energy([1.0, 0, 0], [np.inf, 0, 0])
    with pytest.raises(ps.PoinsotError, match="^velocity"):
        p.jacobi_integral(table, np.zeros((2, 3)), np.zeros((3, 3)))
    with pytest.raises(ps.PoinsotError, match="^frame"):
        p.jacobi_integral("table", [1.0, 0, 0], [0, 0, 0])  # type: ignore[arg-type]
    with pytest.raises(TypeError):
        p.simulate(table, [1.0, 0, 0], [0, 0, 0], 1.0, mass=2.0)  # type: ignore[call-arg]
    with pytest.raises(ps.PoinsotError, match="^position"):
        ps.SpringParticle(1.0, 10.0).force([1e308, 0, 0])  # −k r overflows
    with pytest.raises(ps.PoinsotError, match="^velocity"):
        p.energy([1.0, 0, 0], [1e200, 0, 0])
    with pytest.raises(ps.PoinsotError, match="^stiffness"):
        ps.simulate_particle(table, [1.0, 0, 0], [0, 0, 0], 1.0, stiffness=-2.0)


def test_results_beyond_the_doubles_are_refused_by_the_core_naming_the_argument() -> None:
    """Issue 22 item 1: the core's SpringParticle is fallible (the bindings guarded its results
    themselves before); a stiffness or state so large that a result overflows is a
    PoinsotError naming the argument it comes from, never inf."""
    stiff = ps.SpringParticle(1.0, 1e308)
    for call, what in [
        (lambda: stiff.force([10.0, 0, 0]), "force"),
        (lambda: stiff.acceleration([10.0, 0, 0]), "acceleration"),
        (lambda: stiff.potential([1e10, 0, 0]), "potential"),
        (lambda: stiff.energy([1e10, 0, 0], [0, 0, 0]), "energy"),
    ]:
        with pytest.raises(ps.PoinsotError, match=rf"^position: the result \({what}\)"):
            call()
    p = ps.SpringParticle(1.0, 1.0)
    with pytest.raises(ps.PoinsotError, match=r"^velocity: the result \(Jacobi integral\)"):
        p.jacobi_integral(ps.MovingFrame(), [1.0, 0, 0], [1e200, 0, 0])
    # Negative control: the same calls within range are finite.
    assert np.isfinite(stiff.force([1e-10, 0, 0])).all()
    assert np.isfinite(p.energy([1.0, 0, 0], [1e100, 0, 0]))


def test_polhode_samples_are_checked_once_by_the_core() -> None:
    """Issue 22 item 1: one statement of the polhode's limit (the core's): at least 2 points,
    within the memory budget; the Python layer only converts the count."""
    body = ps.FreeRigidBody([1.0, 2.0, 3.0], [0.3, 1.0, 0.2])
    for method in (body.polhode, body.contact_polhode):
        with pytest.raises(ps.PoinsotError, match=r"^samples: must be >= 2, got 1$"):
            method(1)
        with pytest.raises(ps.PoinsotError, match=r"^samples: 1000000000000 would need"):
            method(10**12)
        with pytest.raises(ps.ArgumentTypeError, match="^samples: must be an integer"):
            method(2.5)
        assert method(2).shape == (2, 3)
