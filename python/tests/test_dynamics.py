"""simulate(): every method against the exact flow, orders, reversibility, long-run invariants,
torques and the energy theorem (2.76), the negative control, batches and bad input."""

from __future__ import annotations

import numpy as np
import poinsot
import pytest
from poinsot import (
    BodyTorque,
    FreeRigidBody,
    FreeSymmetricTop,
    GravityGradientTorque,
    GravityTorque,
    SpaceTorque,
    simulate,
    simulate_batch,
)
from scipy.integrate import solve_ivp

I123 = np.array([1.0, 2.0, 3.0])
W0 = np.array([1.0, 0.1, 1.0])


def qdist(a, b):
    return float(min(np.linalg.norm(a - b), np.linalg.norm(a + b)))


def final_error(tr):
    exact = FreeRigidBody(I123, W0)
    w, q = exact.state(tr.t[-1])
    return max(np.linalg.norm(tr.omega[-1] - w) / np.linalg.norm(W0), qdist(tr.attitude[-1], q))


@pytest.mark.parametrize(
    ("method", "tol"),
    [
        ("exact", 1e-14),
        ("auto", 1e-14),
        ("dop853", 1e-8),
        ("rk4", 1e-9),
        ("splitting2", 2e-4),
        ("splitting4", 1e-9),
        ("splitting6", 1e-11),
    ],
)
def test_every_method_agrees_with_the_exact_flow(method, tol):
    tr = simulate(I123, W0, 20.0, method=method, dt=1e-3, samples=11)
    assert tr.t.shape == (11,) and tr.t[0] == 0.0 and tr.t[-1] == 20.0
    assert tr.omega.shape == (11, 3) and tr.attitude.shape == (11, 4)
    assert final_error(tr) < tol, (method, final_error(tr))
    assert tr.method == ("exact" if method == "auto" else method)


def test_step_is_independent_of_the_sampling():
    a = simulate(I123, W0, 10.0, method="rk4", dt=0.01, samples=2)
    b = simulate(I123, W0, 10.0, method="rk4", dt=0.01, samples=101)
    assert a.step == b.step == pytest.approx(0.01)
    np.testing.assert_allclose(a.omega[-1], b.omega[-1], atol=1e-14)
    c = simulate(I123, W0, 10.0, method="rk4", dt=0.03, samples=101)  # Δ = 0.1 → h = 0.1/4
    assert c.step == pytest.approx(0.025)


@pytest.mark.parametrize(
    ("method", "order", "dt"),
    [("rk4", 4, 0.02), ("splitting2", 2, 0.02), ("splitting4", 4, 0.02), ("splitting6", 6, 0.1)],
)
def test_convergence_order_under_dt_halving(method, order, dt):
    e1 = final_error(simulate(I123, W0, 10.0, method=method, dt=dt, samples=2))
    e2 = final_error(simulate(I123, W0, 10.0, method=method, dt=dt / 2, samples=2))
    assert np.log2(e1 / e2) == pytest.approx(order, abs=0.35)


def test_time_reversibility_of_the_splitting():
    # The rigid body is reversible under ω → −ω. The symmetric splitting retraces its steps
    # to round-off; RK4 (not symmetric) does not.
    def back_and_forth(method):
        fwd = simulate(I123, W0, 20.0, method=method, dt=0.05, samples=2)
        back = simulate(
            I123,
            -fwd.omega[-1],
            20.0,
            attitude0=fwd.attitude[-1],
            method=method,
            dt=0.05,
            samples=2,
        )
        return max(
            np.linalg.norm(back.omega[-1] + W0), qdist(back.attitude[-1], np.array([1.0, 0, 0, 0]))
        )

    for method in ("splitting2", "splitting4", "splitting6"):
        assert back_and_forth(method) < 1e-12, method
    assert back_and_forth("rk4") > 1e-9


def test_invariants_over_a_million_steps():
    tr = simulate(I123, W0, 10_000.0, method="splitting2", dt=0.01, samples=1001)
    assert tr.steps == 1_000_000
    # |L| (a Casimir): round-off only.
    assert tr.momentum_error().max() < 1e-12
    # Energy: bounded O(dt²) oscillation, no drift.
    err = tr.energy_error()
    assert err.max() < 1e-4
    assert err[-100:].max() < 2 * err[:100].max()
    # RK4 at the same step drifts (monotonically, here) instead.
    rk = simulate(I123, W0, 10_000.0, method="rk4", dt=0.01, samples=11)
    drift = rk.energy_error()
    assert drift[-1] > 3 * drift[2] > 0  # linear growth: ×5 from t = 2000 to 10000


def test_symmetric_top_closed_forms_versus_integration():
    for i1, i3 in ((2.0, 1.0), (1.0, 1.8)):
        w = np.array([0.3, -0.4, 2.0])
        top = FreeSymmetricTop(i1, i3, w)
        tr = simulate([i1, i1, i3], w, 30.0, method="dop853", rtol=1e-13, atol=1e-15, samples=61)
        np.testing.assert_allclose(tr.omega, top.omega(tr.t), atol=1e-10)
        for q, qe in zip(tr.attitude, top.attitude(tr.t)):
            assert qdist(q, qe) < 1e-10
        # The body cone (2.90) and the space cone (2.97), measured on the integration.
        om = tr.omega
        np.testing.assert_allclose(
            np.arctan2(np.hypot(om[:, 0], om[:, 1]), om[:, 2]), top.body_cone_angle, atol=1e-10
        )
        rot = tr.rotation()
        ws = rot.apply(om)
        ll = tr.angular_momentum
        cos_s = np.einsum("ij,ij->i", ws, ll) / (
            np.linalg.norm(ws, axis=1) * np.linalg.norm(ll, axis=1)
        )
        np.testing.assert_allclose(cos_s, np.cos(top.space_cone_angle), atol=1e-10)


def test_energy_theorem_under_torque():
    # ω·N = dT/dt (2.76): the power output against the derivative of the sampled T.
    body = [1.0, 1.3, 0.6]
    q0 = [np.sqrt(0.9), np.sqrt(0.1), 0.0, 0.0]
    torques = [
        GravityTorque(mgl=0.8),
        SpaceTorque([0.1, -0.2, 0.3]),
        BodyTorque([0.0, 0.05, -0.1]),
        lambda t, w, q: [0.1 * np.sin(t), 0.0, -0.05 * w[2]],
    ]
    for torque in torques:
        tr = simulate(
            body,
            [0.2, 0.5, 3.0],
            4.0,
            attitude0=q0,
            torque=torque,
            method="dop853",
            rtol=1e-13,
            atol=1e-15,
            samples=2001,
        )
        dt = tr.t[1] - tr.t[0]
        e = tr.energy
        de = (e[:-4] - 8 * e[1:-3] + 8 * e[3:-1] - e[4:]) / (12 * dt)  # 4th-order central
        scale = np.abs(tr.power).max()
        assert scale > 1e-3
        assert np.abs(de - tr.power[2:-2]).max() < 1e-7 * scale


def test_negative_control_dropping_the_gyroscopic_term_fails():
    # Euler's equations without ω × I·ω (ω̇ = I⁻¹N) disagree with the exact motion by O(1);
    # with it, scipy agrees with the exact solution to 1e-9.
    def rhs(gyro):
        def f(_t, w):
            if not gyro:
                return [0.0, 0.0, 0.0]
            return [(2 - 3) * w[1] * w[2] / 1, (3 - 1) * w[2] * w[0] / 2, (1 - 2) * w[0] * w[1] / 3]

        return f

    exact = FreeRigidBody(I123, W0).omega(5.0)
    good = solve_ivp(rhs(True), (0, 5), W0, method="DOP853", rtol=1e-12, atol=1e-12).y[:, -1]
    bad = solve_ivp(rhs(False), (0, 5), W0, method="DOP853", rtol=1e-12, atol=1e-12).y[:, -1]
    assert np.linalg.norm(good - exact) < 1e-9
    assert np.linalg.norm(bad - exact) > 0.1


def test_heavy_top_with_a_rigid_body_cone():
    # A solid cone: apex at the origin (the pivot), axis +z, centre of mass at 3h/4 on axis 3.
    cone = poinsot.RigidBody.solid_cone(1.0, 0.2, 0.4)
    q0 = [np.cos(0.25), np.sin(0.25), 0.0, 0.0]
    tr = simulate(
        cone,
        [0.0, 0.0, 60.0],
        3.0,
        attitude0=q0,
        torque=GravityTorque(),
        method="dop853",
        rtol=1e-12,
        atol=1e-14,
        samples=301,
    )
    mgl = 1.0 * 9.80665 * 0.3
    assert tr.potential_energy[0] == pytest.approx(mgl * np.cos(0.5), rel=1e-14)  # V = m g l cos θ
    assert tr.energy_error().max() < 1e-9
    split = simulate(
        cone,
        [0.0, 0.0, 60.0],
        3.0,
        attitude0=q0,
        torque=GravityTorque(),
        method="splitting4",
        dt=1e-4,
        samples=301,
    )
    assert split.energy_error().max() < 1e-6
    assert qdist(split.attitude[-1], tr.attitude[-1]) < 1e-6
    with pytest.raises(poinsot.PoinsotError, match="^body: "):
        simulate(
            poinsot.RigidBody.from_inertia(1.0, np.eye(3), center_of_mass=(0.1, 0, 0.3)),
            [0, 0, 1],
            1.0,
            torque=GravityTorque(),
        )


def test_gravity_gradient_and_callback_agree_with_builtin():
    n = 0.3
    body = np.array([1.0, 2.0, 2.5])
    q0 = [np.sqrt(0.8), 0.0, np.sqrt(0.2), 0.0]
    a = simulate(
        body,
        [0.01, 0.02, 0.3],
        20.0,
        attitude0=q0,
        torque=GravityGradientTorque(n),
        method="dop853",
        rtol=1e-12,
        atol=1e-14,
        samples=3,
    )

    def gg(t, w, q):
        from scipy.spatial.transform import Rotation

        r = Rotation.from_quat([q[1], q[2], q[3], q[0]])
        rb = r.inv().apply([np.cos(n * t), np.sin(n * t), 0.0])
        return 3 * n * n * np.cross(rb, body * rb)

    b = simulate(
        body,
        [0.01, 0.02, 0.3],
        20.0,
        attitude0=q0,
        torque=gg,
        method="dop853",
        rtol=1e-12,
        atol=1e-14,
        samples=3,
    )
    np.testing.assert_allclose(a.omega, b.omega, atol=1e-10)
    assert b.torque_evaluations > 100


def test_full_tensor_and_rigid_body_inputs():
    from scipy.spatial.transform import Rotation

    r = Rotation.from_euler("xyz", [0.3, -0.5, 0.9]).as_matrix()
    tensor = r @ np.diag(I123) @ r.T
    w_body = r @ W0  # the same physical ω in the rotated axes
    q_body = Rotation.from_matrix(r.T).as_quat()  # R_B = R_P Aᵀ with R_P = identity
    q_body = np.array([q_body[3], *q_body[:3]])
    tr = simulate(tensor, w_body, 7.0, attitude0=q_body, method="exact", samples=2)
    exact = FreeRigidBody(I123, W0)
    np.testing.assert_allclose(r.T @ tr.omega[-1], exact.omega(7.0), atol=1e-12)
    np.testing.assert_allclose(tr.angular_momentum[-1], exact.angular_momentum, atol=1e-12)
    cuboid = poinsot.RigidBody.cuboid(2.0, [1.0, 2.0, 3.0])
    tr = simulate(cuboid, [0.1, 1.0, 0.1], 5.0, method="splitting6", dt=0.005, samples=2)
    ex = FreeRigidBody(np.diag(cuboid.inertia), [0.1, 1.0, 0.1])
    np.testing.assert_allclose(tr.omega[-1], ex.omega(5.0), atol=1e-9)


def test_batch_agrees_with_single_runs():
    rng = np.random.default_rng(7)
    moments = np.column_stack([np.ones(50), 1.5 + 0.4 * rng.random(50), 2.0 + 0.4 * rng.random(50)])
    omega = rng.normal(size=(50, 3))
    for method in ("exact", "rk4", "splitting4"):
        w, q = simulate_batch(moments, omega, 3.0, method=method, dt=1e-3)
        for i in (0, 17, 49):
            we, qe = FreeRigidBody(moments[i], omega[i]).state(3.0)
            np.testing.assert_allclose(w[i], we, atol=1e-8)
            assert qdist(q[i], qe) < 1e-8
    with pytest.raises(poinsot.PoinsotError, match="^omega0: "):
        simulate_batch(moments, omega[:3], 1.0)
    with pytest.raises(poinsot.InvalidInertiaError, match="^moments: row 0"):
        simulate_batch([[1.0, 1.0, 3.0]], [[1.0, 0, 0]], 1.0)


def test_progress_and_divergence():
    seen = []
    simulate(I123, W0, 5.0, method="rk4", dt=0.01, samples=101, progress=seen.append)
    assert seen and seen[-1] == pytest.approx(1.0) and np.all(np.diff(seen) > 0)

    def runaway(t, w, q):  # N ∝ |ω|⁴ ω: blows up in finite time
        with np.errstate(over="ignore", invalid="ignore"):
            return w * np.dot(w, w) ** 2

    with pytest.raises(poinsot.IntegrationError, match="t = "):
        simulate(I123, W0, 10.0, torque=runaway, method="rk4", dt=1e-3)
    with pytest.raises(poinsot.IntegrationError, match="t = "):
        simulate(I123, W0, 10.0, torque=runaway, method="dop853")


@pytest.mark.parametrize(
    ("kwargs", "exc", "name"),
    [
        ({"body": [1.0, 1.0, 3.0]}, poinsot.InvalidInertiaError, "body"),
        ({"omega0": [np.nan, 0, 0]}, poinsot.PoinsotError, "omega0"),
        ({"omega0": [1, 0]}, poinsot.PoinsotError, "omega0"),
        ({"duration": 0.0}, poinsot.PoinsotError, "duration"),
        ({"dt": 0.0, "method": "rk4"}, poinsot.PoinsotError, "dt"),
        ({"dt": -1.0, "method": "rk4"}, poinsot.PoinsotError, "dt"),
        ({"attitude0": [0, 0, 0, 0]}, poinsot.InvalidRotationError, "attitude0"),
        ({"attitude0": [2.0, 0, 0, 0]}, poinsot.InvalidRotationError, "attitude0"),
        ({"samples": 1}, poinsot.PoinsotError, "samples"),
        ({"method": "euler"}, poinsot.PoinsotError, "method"),
        ({"method": "exact", "torque": BodyTorque([1, 0, 0])}, poinsot.PoinsotError, "method"),
        ({"method": "splitting2", "torque": lambda t, w, q: w}, poinsot.PoinsotError, "method"),
        ({"torque": 3.0}, poinsot.PoinsotError, "torque"),
        ({"torque": lambda t, w, q: [1.0, 2.0]}, poinsot.PoinsotError, "torque"),
        # Issue 10: a huge torque overflows the state under every method; the splittings used
        # to return an infinite energy silently.
        (
            {"torque": SpaceTorque([1e308] * 3), "method": "splitting2", "dt": 0.01, "samples": 11},
            poinsot.PoinsotError,
            "torque",
        ),
        (
            {
                "torque": SpaceTorque([1e308, 0, 0]),
                "omega0": [0.0, 0.0, 1.0],
                "method": "splitting2",
                "dt": 0.01,
                "samples": 11,
            },
            poinsot.IntegrationError,
            "duration",
        ),
        (
            {
                "torque": SpaceTorque([1e308, 0, 0]),
                "omega0": [0.0, 0.0, 1.0],
                "method": "splitting6",
                "dt": 0.01,
                "samples": 11,
            },
            poinsot.IntegrationError,
            "duration",
        ),
        (
            {
                "torque": SpaceTorque([1e308, 0, 0]),
                "omega0": [0.0, 0.0, 1.0],
                "method": "rk4",
                "dt": 0.01,
                "samples": 11,
            },
            poinsot.IntegrationError,
            "duration",
        ),
        (
            {
                "torque": SpaceTorque([1e308, 0, 0]),
                "omega0": [0.0, 0.0, 1.0],
                "method": "dop853",
                "samples": 11,
            },
            poinsot.IntegrationError,
            "duration",
        ),
    ],
)
def test_bad_input_names_the_argument(kwargs, exc, name):
    args = {"body": I123, "omega0": W0, "duration": 1.0}
    args.update(kwargs)
    body, omega0, duration = args.pop("body"), args.pop("omega0"), args.pop("duration")
    with pytest.raises(exc, match=f"^{name}: "):
        simulate(body, omega0, duration, **args)


def test_torques_are_checked_when_made():
    """A torque holding NaN, infinity or the wrong shape is refused when it is made (issue 10)."""
    for bad in ([np.inf, 0, 0], [np.nan, 0, 0], [1.0, 2.0], "x"):
        with pytest.raises(poinsot.PoinsotError, match="^torque: "):
            BodyTorque(bad)
        with pytest.raises(poinsot.PoinsotError, match="^torque: "):
            SpaceTorque(bad)
    with pytest.raises(poinsot.PoinsotError, match="^mgl: "):
        poinsot.GravityTorque(mgl=np.nan)
    with pytest.raises(poinsot.PoinsotError, match="^mean_motion: "):
        poinsot.GravityGradientTorque(np.inf)


def test_the_core_returns_a_typed_trajectory() -> None:
    """simulate's one core call returns the class _core.TrajectoryCore (typed in _core.pyi,
    which holds no dict[str, Any]), whose values the Trajectory shows as they are."""
    from pathlib import Path

    from poinsot import _core

    stub = Path(_core.__file__).with_name("_core.pyi").read_text(encoding="utf-8")
    assert "dict[str, Any]" not in stub
    tr = simulate(I123, W0, 1.0, method="rk4", dt=0.01, samples=11)
    core = _core.dynamics_simulate(
        (np.diag(I123), W0, None), 1.0, ("none", np.zeros(3), 0.0), None, "rk4", 0.01,
        (11, 1e-10, 1e-12, 10**6), None,
    )  # fmt: skip
    assert isinstance(core, _core.TrajectoryCore)
    for name in ("t", "omega", "attitude", "angular_momentum", "energy", "power"):
        np.testing.assert_array_equal(getattr(tr, name), getattr(core, name))
    np.testing.assert_array_equal(tr.potential_energy, core.potential)
    assert (tr.method, tr.step, tr.steps) == (core.method, core.step, core.steps)
    assert tr.t.shape == (11,) and tr.omega.shape == (11, 3) and tr.attitude.shape == (11, 4)
