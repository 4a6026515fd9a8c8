"""Tests of poinsot.MovingFrame and poinsot.simulate_particle (the unit's eqs. 2.1–2.28).

References: sympy.physics.vector kinematics (orientation → ω, α; a1pt_theory; direct double
differentiation in the fixed frame), closed-form straight-line motion in the fixed frame.
"""

from __future__ import annotations

import numpy as np
import poinsot as ps
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from sympy.physics.vector import Point, ReferenceFrame, dynamicsymbols

#: Round-off allowance for O(1..10) quantities transformed once in float64.
ROUND_OFF = 1e-12
#: The issue's bar for moving-frame integration against the fixed frame.
FRAME_AGREEMENT = 1e-10


# ---------------------------------------------------------------------------------------------
# sympy reference: a frame B oriented in N by a body-fixed 3-2-1 rotation with angles q(t), its
# origin Q at R(t), and a point P at r(t) (coordinates in B). sympy derives ω and α from the
# orientation; the accelerations come from a1pt_theory and from differentiating twice in N.
# ---------------------------------------------------------------------------------------------
def _sympy_model():
    t = dynamicsymbols._t
    q = dynamicsymbols("q1:4")
    X = dynamicsymbols("X1:4")
    x = dynamicsymbols("x1:4")
    N = ReferenceFrame("N")
    B = N.orientnew("B", "Body", list(q), "321")
    O = Point("O")
    O.set_vel(N, 0)
    O.set_acc(N, 0)
    Rvec = X[0] * N.x + X[1] * N.y + X[2] * N.z
    Q = O.locatenew("Q", Rvec)
    Q.set_vel(N, Rvec.dt(N))
    Q.set_acc(N, Rvec.dt(N).dt(N))
    Q.set_vel(B, 0)
    Q.set_acc(B, 0)
    rvec = x[0] * B.x + x[1] * B.y + x[2] * B.z
    P = Q.locatenew("P", rvec)
    P.set_vel(B, rvec.dt(B))
    P.set_acc(B, rvec.dt(B).dt(B))
    omega = B.ang_vel_in(N)
    alpha = B.ang_acc_in(N)
    v_rel = P.vel(B)
    a_total_1pt = P.a1pt_theory(Q, N, B)
    direct = (Rvec + rvec).dt(N).dt(N)
    exprs = {
        "omega": omega,
        "alpha": alpha,
        "position": Rvec + rvec,
        "velocity": (Rvec + rvec).dt(N),
        "relative": P.acc(B) if False else rvec.dt(B).dt(B),
        "origin": Q.acc(N),
        "coriolis": 2 * omega.cross(v_rel),
        "centripetal": omega.cross(omega.cross(rvec)),
        "euler": alpha.cross(rvec),
        "a1pt": a_total_1pt,
        "direct": direct,
    }
    syms = []
    for f in (*q, *X, *x):
        syms += [f.diff(t, 2), f.diff(t), f]
    mats = {k: v.to_matrix(N) for k, v in exprs.items()}
    mats["attitude"] = N.dcm(B)
    funcs = {k: sp.lambdify(syms, m, "numpy") for k, m in mats.items()}
    return funcs


_FUNCS = _sympy_model()


def _evaluate(rng: np.random.Generator) -> dict[str, np.ndarray]:
    vals = rng.uniform(-1.5, 1.5, size=27)  # (q̈, q̇, q) × 3 angles, origin, point
    return {k: np.asarray(f(*vals), dtype=float) for k, f in _FUNCS.items()} | {"_vals": vals}


@pytest.mark.parametrize("seed", range(8))
def test_each_acceleration_term_matches_sympy_kinematics(seed: int) -> None:
    rng = np.random.default_rng(seed)
    ref = _evaluate(rng)
    vals = ref["_vals"].reshape(9, 3)  # rows: (ddot, dot, value) for q1..q3, X1..X3, x1..x3
    X_dd, X_d, X = vals[3:6, 0], vals[3:6, 1], vals[3:6, 2]
    x_dd, x_d, x = vals[6:9, 0], vals[6:9, 1], vals[6:9, 2]
    A = ref["attitude"]
    assert np.allclose(A.T @ A, np.eye(3)) and np.linalg.det(A) > 0
    frame = ps.MovingFrame(
        origin=X,
        velocity=X_d,
        acceleration=X_dd,
        angular_velocity=ref["omega"].ravel(),
        angular_acceleration=ref["alpha"].ravel(),
        attitude=A,
    )
    out = frame.to_fixed(x, x_d, x_dd)
    assert np.linalg.norm(ref["omega"]) > 0.1, "non-trivial rotation"
    np.testing.assert_allclose(out.position, ref["position"].ravel(), atol=ROUND_OFF * 10)
    np.testing.assert_allclose(out.velocity, ref["velocity"].ravel(), atol=ROUND_OFF * 10)
    for name in ("relative", "origin", "coriolis", "centripetal", "euler"):
        np.testing.assert_allclose(
            out.acceleration_terms[name], ref[name].ravel(), atol=ROUND_OFF * 100, err_msg=name
        )
    total = sum(out.acceleration_terms.values())
    np.testing.assert_allclose(total, out.acceleration, atol=ROUND_OFF)
    # Against sympy's one-point theorem and against differentiating r' = R + r twice in N.
    np.testing.assert_allclose(out.acceleration, ref["a1pt"].ravel(), atol=ROUND_OFF * 100)
    np.testing.assert_allclose(out.acceleration, ref["direct"].ravel(), atol=ROUND_OFF * 100)


def test_convention_moving_frame_attitude_columns_are_moving_axes() -> None:
    """attitude's columns are the moving axes in fixed components: with the axes turned 90°
    about z, the moving x axis is the fixed y axis."""
    Rz = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    f = ps.MovingFrame(origin=[1.0, 0, 0], attitude=Rz)
    np.testing.assert_allclose(f.to_fixed([1.0, 0, 0]).position, [1.0, 1.0, 0.0])
    np.testing.assert_allclose(f.to_moving([1.0, 1.0, 0.0]).position, [1.0, 0.0, 0.0], atol=1e-15)


def test_convention_terms_are_named_as_in_the_unit() -> None:
    f = ps.MovingFrame(angular_velocity=[0, 0, 1.0])
    assert set(f.to_fixed([1, 0, 0]).acceleration_terms) == {
        "relative",
        "origin",
        "coriolis",
        "centripetal",
        "euler",
    }
    assert set(f.fictitious_forces(1.0, [1, 0, 0], [0, 0, 0])) == {
        "translational",
        "coriolis",
        "centrifugal",
        "euler",
    }
    # Centripetal points to the axis; centrifugal away from it (eqs. 2.23–2.24, 2.28).
    assert f.to_fixed([2.0, 0, 0]).acceleration_terms["centripetal"][0] < 0
    assert f.fictitious_forces(1.0, [2.0, 0, 0], [0, 0, 0])["centrifugal"][0] > 0


vec = st.lists(st.floats(-3, 3), min_size=3, max_size=3).map(np.array)


@settings(max_examples=60, deadline=None)
@given(o=vec, v=vec, a=vec, w=vec, wd=vec, r=vec, rv=vec, ra=vec)
def test_to_moving_inverts_to_fixed(o, v, a, w, wd, r, rv, ra) -> None:
    f = ps.MovingFrame(
        origin=o, velocity=v, acceleration=a, angular_velocity=w, angular_acceleration=wd
    )
    out = f.to_fixed(r, rv, ra)
    back = f.to_moving(out.position, out.velocity, out.acceleration)
    np.testing.assert_allclose(back.position, r, atol=1e-11)
    np.testing.assert_allclose(back.velocity, rv, atol=1e-10)
    np.testing.assert_allclose(back.acceleration, ra, atol=1e-9)
    np.testing.assert_allclose(sum(back.acceleration_terms.values()), back.acceleration, atol=1e-11)
    # The fictitious forces are m times the fictitious terms of to_moving.
    ff = f.fictitious_forces(2.5, r, rv)
    for name in ("translational", "coriolis", "centrifugal", "euler"):
        np.testing.assert_allclose(ff[name], 2.5 * back.acceleration_terms[name], atol=1e-9)


def test_pure_translation_galilean_invariance() -> None:
    """Eqs. 2.1–2.5 with the errata's dots: velocities and accelerations add; with R̈ = 0 there
    is no fictitious force (Galilean invariance)."""
    f = ps.MovingFrame(origin=[1, 2, 3], velocity=[4, 0, 0], acceleration=[0, 0, -9.8])
    out = f.to_fixed([1, 1, 1], [0, 1, 0], [0, 0, 1])
    np.testing.assert_allclose(out.velocity, [4, 1, 0])
    np.testing.assert_allclose(out.acceleration, [0, 0, -8.8])
    forces = f.fictitious_forces(2.0, [1, 1, 1], [0, 1, 0])
    np.testing.assert_allclose(forces["translational"], [0, 0, 19.6])  # −m R̈ (eq. 2.5)
    uniform = ps.MovingFrame(velocity=[3, 0, 0])
    assert all(
        np.all(x == 0) for x in uniform.fictitious_forces(1.0, [1, 2, 3], [4, 5, 6]).values()
    )


def test_broadcasting_over_leading_dimensions() -> None:
    f = ps.MovingFrame(angular_velocity=[0.1, 0.2, 0.3], acceleration=[1, 0, 0])
    r = np.random.default_rng(1).normal(size=(4, 5, 3))
    out = f.to_fixed(r, [0, 1, 0])
    assert out.position.shape == (4, 5, 3) and out.acceleration_terms["coriolis"].shape == (4, 5, 3)
    np.testing.assert_allclose(out.position[2, 3], f.to_fixed(r[2, 3], [0, 1, 0]).position)
    forces = f.fictitious_forces(np.ones((4, 5)), r, 0)
    assert forces["euler"].shape == (4, 5, 3)


def _fixed_frame_truth(frame: ps.MovingFrame | object, r0, v0, g, times):
    """A particle in a uniform field g (fixed frame) moves on r' = r'₀ + v'₀ t + ½ g t²; returned
    in the moving frame's components at each time."""
    f0 = frame.at(0.0) if isinstance(frame, ps.MovingFrame) else frame(0.0)
    start = f0.to_fixed(r0, v0)
    out = []
    for t in times:
        ft = frame.at(t) if isinstance(frame, ps.MovingFrame) else frame(t)
        pos = start.position + start.velocity * t + 0.5 * g * t * t
        vel = start.velocity + g * t
        m = ft.to_moving(pos, vel)
        out.append(np.concatenate([m.position, m.velocity]))
    return np.array(out)


def test_rotating_frame_integration_matches_inertial_motion() -> None:
    """Moving-frame integration (with every fictitious force) against the exact fixed-frame
    motion transformed into the frame, to 1e-10 relative."""
    w = np.array([0.2, -0.3, 0.9])
    A0 = ps.MovingFrame(angular_velocity=[1, 0, 0]).at(0.7).attitude  # some rotation
    frame = ps.MovingFrame(
        origin=[1, -1, 0.5],
        velocity=[0.3, 0.1, 0],
        acceleration=[-0.4, 0.2, 0.1],
        angular_velocity=w,
        angular_acceleration=0.3 * w,
        attitude=A0,
    )
    r0, v0, mass = np.array([1.0, 0.5, -0.2]), np.array([0.1, -0.3, 0.8]), 2.0
    g = np.array([0.0, 0.0, -9.81])
    traj = ps.simulate_particle(
        frame,
        r0,
        v0,
        3.0,
        mass=mass,
        samples=31,
        rtol=1e-13,
        atol=1e-13,
        force=lambda t, r, v: mass * frame.at(t).attitude.T @ g,
    )
    truth = _fixed_frame_truth(frame, r0, v0, g, traj.t)
    got = np.hstack([traj.position, traj.velocity])
    scale = np.maximum(np.abs(truth).max(axis=0), 1.0)
    assert np.max(np.abs(got - truth) / scale) < FRAME_AGREEMENT
    # Free particle, all in Rust (no callable): straight line in the fixed frame.
    free = ps.simulate_particle(frame, r0, v0, 3.0, samples=31, rtol=1e-13, atol=1e-13)
    truth = _fixed_frame_truth(frame, r0, v0, np.zeros(3), free.t)
    got = np.hstack([free.position, free.velocity])
    assert (
        np.max(np.abs(got - truth) / np.maximum(np.abs(truth).max(axis=0), 1.0)) < FRAME_AGREEMENT
    )
    pos, _ = free.to_fixed()
    start = frame.to_fixed(r0, v0)
    np.testing.assert_allclose(pos, start.position + np.outer(free.t, start.velocity), atol=1e-9)


def test_frame_given_as_a_function_of_time() -> None:
    """A tumbling frame, A(t) = R_z(φ) R_x(θ) with ω = φ̇ ẑ + θ̇ R_z(φ) x̂: a free particle must
    still move on a straight line in the fixed frame."""

    def rot(axis, a):
        return (
            ps.MovingFrame(angular_velocity=axis).at(a).attitude
        )  # rotation by a about a unit axis

    def frame(t: float) -> ps.MovingFrame:
        phi, dphi, ddphi = 0.8 * t, 0.8, 0.0
        th, dth, ddth = 0.5 * np.sin(1.3 * t), 0.65 * np.cos(1.3 * t), -0.845 * np.sin(1.3 * t)
        rz = rot([0, 0, 1.0], phi)
        nodes = rz @ [1.0, 0, 0]
        w = dphi * np.array([0, 0, 1.0]) + dth * nodes
        wd = (
            ddphi * np.array([0, 0, 1.0]) + ddth * nodes + dth * dphi * np.cross([0, 0, 1.0], nodes)
        )
        return ps.MovingFrame(
            origin=[np.cos(t), np.sin(t), 0],
            velocity=[-np.sin(t), np.cos(t), 0],
            acceleration=[-np.cos(t), -np.sin(t), 0],
            angular_velocity=w,
            angular_acceleration=wd,
            attitude=rz @ rot([1.0, 0, 0], th),
        )

    r0, v0 = np.array([0.5, 0.0, 0.2]), np.array([0.0, 0.3, 0.0])
    traj = ps.simulate_particle(frame, r0, v0, 2.0, samples=21, rtol=1e-12, atol=1e-13)
    truth = _fixed_frame_truth(frame, r0, v0, np.zeros(3), traj.t)
    got = np.hstack([traj.position, traj.velocity])
    assert np.max(np.abs(got - truth)) < 1e-9


def test_negative_control_frame_mismatch_is_detected() -> None:
    """Integrating in one frame and transforming with another must fail the comparison."""
    frame = ps.MovingFrame(angular_velocity=[0, 0, 1.0])
    other = ps.MovingFrame(angular_velocity=[0, 0, 1.1])
    traj = ps.simulate_particle(frame, [1, 0, 0], [0, 0.5, 0], 2.0, samples=5)
    truth = _fixed_frame_truth(other, [1, 0, 0], [0, 0.5, 0], np.zeros(3), traj.t)
    assert np.max(np.abs(np.hstack([traj.position, traj.velocity]) - truth)) > 1e-2


@pytest.mark.parametrize(
    "kwargs, name",
    [
        ({"mass": -1.0}, "mass"),
        ({"rtol": 0.0}, "rtol"),
        ({"rtol": -1e-9}, "rtol"),
        ({"atol": 0.0}, "atol"),
        ({"atol": float("nan")}, "atol"),
        ({"samples": 1}, "samples"),
    ],
)
def test_simulate_particle_bad_input_names_the_argument(kwargs, name) -> None:
    frame = ps.MovingFrame(angular_velocity=[0, 0, 1.0])
    with pytest.raises(ps.PoinsotError, match=name):
        ps.simulate_particle(frame, [1, 0, 0], [0, 0, 0], 1.0, **kwargs)


def test_bad_input_is_refused_with_the_argument_named() -> None:
    with pytest.raises(ps.PoinsotError, match="origin"):
        ps.MovingFrame(origin=[np.nan, 0, 0])
    with pytest.raises(ps.PoinsotError, match="angular_velocity"):
        ps.MovingFrame(angular_velocity=[1, 2])
    with pytest.raises(ps.InvalidRotationError, match="attitude"):
        ps.MovingFrame(attitude=np.diag([1.0, 1.0, -1.0]))
    f = ps.MovingFrame(angular_velocity=[0, 0, 1.0])
    with pytest.raises(ps.PoinsotError, match="mass"):
        f.fictitious_forces(0.0, [1, 0, 0], [0, 0, 0])
    with pytest.raises(ps.PoinsotError, match="position"):
        ps.simulate_particle(f, [np.inf, 0, 0], [0, 0, 0], 1.0)
    with pytest.raises(ps.PoinsotError, match="duration"):
        ps.simulate_particle(f, [1, 0, 0], [0, 0, 0], -1.0)
    with pytest.raises(ps.PoinsotError, match="angular_acceleration"):
        ps.MovingFrame(angular_velocity=[0, 0, 1.0], angular_acceleration=[1.0, 0, 0]).at(1.0)

    # A failing user force surfaces as its own exception; a wrong shape names force.
    def boom(t, r, v):
        raise ZeroDivisionError("inside the force")

    with pytest.raises(ZeroDivisionError):
        ps.simulate_particle(f, [1, 0, 0], [0, 0, 0], 1.0, force=boom)
    with pytest.raises(ps.PoinsotError, match="force"):
        ps.simulate_particle(f, [1, 0, 0], [0, 0, 0], 1.0, force=lambda t, r, v: [1.0, 2.0])


def test_blow_up_reports_the_time() -> None:
    """A force that blows up in finite time: IntegrationError naming t."""
    f = ps.MovingFrame()
    with pytest.raises(ps.IntegrationError, match="t = "):
        ps.simulate_particle(
            f, [1, 0, 0], [1, 0, 0], 5.0, force=lambda t, r, v: np.array([r[0] ** 3, 0, 0]) * 10
        )
