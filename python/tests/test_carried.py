"""simulate(..., carried_by=...): a body carried by a moving frame (issue 26), against closed
forms written here: Foucault's free gyroscope on the rotating Earth and a top on a turntable."""

from __future__ import annotations

import pickle

import numpy as np
import poinsot as ps
import pytest

DAY = 86164.0905
OMEGA = 7.2921150e-5


def _axis3(q: np.ndarray) -> np.ndarray:
    """Body axis 3 in the frame of the quaternions q (N, 4) [w, x, y, z]."""
    w, x, y, z = q.T
    return np.column_stack([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def _aim_north() -> np.ndarray:
    """Body axis 3 to north (ENU y): a quarter turn about east (x), negative sense."""
    h = np.pi / 4
    return np.array([np.cos(h), -np.sin(h), 0.0, 0.0])


def _foucault(lat: float, q0: np.ndarray, duration: float, samples: int) -> ps.CarriedTrajectory:
    """A free rotor (pivot at the centre of mass) whose inertial ω is 50 rad/s along its axis."""
    place = ps.Place(lat)
    axis = _axis3(q0[None])[0]
    earth_w = OMEGA * np.array([0.0, np.cos(lat), np.sin(lat)])
    # ω relative to the ground, body components: 50 e3 minus the ground's ω in body axes.
    r = ps.quaternion_to_matrix(q0)
    w_rel = np.array([0.0, 0.0, 50.0]) - r.T @ earth_w
    assert np.allclose(r @ [0, 0, 1], axis)
    run = ps.simulate(
        [1.0, 1.0, 1.5], w_rel, duration, attitude0=q0, carried_by=place, samples=samples
    )
    assert isinstance(run, ps.CarriedTrajectory)
    return run


def test_free_gyroscope_keeps_its_inertial_axis_and_drifts_at_omega_sin_lat_on_the_ground():
    lat = np.radians(49.0)
    run = _foucault(lat, _aim_north(), DAY, 25)
    assert isinstance(run, ps.CarriedTrajectory) and isinstance(run, ps.Trajectory)
    inertial = _axis3(run.attitude)
    np.testing.assert_allclose(inertial, np.tile([0.0, 1.0, 0.0], (25, 1)), atol=1e-12)
    # Seen from the ground: the inertial axis turned back by the Earth (Rodrigues, about k).
    k = np.array([0.0, np.cos(lat), np.sin(lat)])
    s0 = np.array([0.0, 1.0, 0.0])
    a = -OMEGA * run.t[:, None]
    want = s0 * np.cos(a) + np.cross(k, s0) * np.sin(a) + k * (k @ s0) * (1 - np.cos(a))
    np.testing.assert_allclose(_axis3(run.relative_attitude), want, atol=1e-10)
    # The first minute: clockwise (east of north) at Ω sin λ.
    short = _foucault(lat, _aim_north(), 60.0, 2)
    s = _axis3(short.relative_attitude)[-1]
    assert np.arctan2(s[0], s[1]) / 60.0 == pytest.approx(OMEGA * np.sin(lat), rel=1e-5)


def test_axis_at_the_celestial_pole_stays_put():
    lat = np.radians(40.0)
    # Axis 3 to the pole (0, cos λ, sin λ): a turn of −(90° − λ) about east.
    h = -(np.pi / 2 - lat) / 2
    q0 = np.array([np.cos(h), np.sin(h), 0.0, 0.0])
    run = _foucault(lat, q0, DAY / 3, 7)
    pole = np.array([0.0, np.cos(lat), np.sin(lat)])
    np.testing.assert_allclose(_axis3(run.relative_attitude), np.tile(pole, (7, 1)), atol=1e-12)


def test_top_on_a_turntable_matches_the_fixed_pivot_top():
    # Pivot on the table's axis: no pivot acceleration; the carried top is the heavy top seen
    # from the turning table. A RigidBody pivoted at its coordinate origin: a cone (apex at 0).
    cone = ps.RigidBody.solid_cone(mass=1.0, radius=0.1, height=0.4)
    table = ps.MovingFrame(angular_velocity=[0.0, 0.0, 0.7])
    tilt = np.array([np.cos(0.15), np.sin(0.15), 0.0, 0.0])
    w_rel = np.array([0.0, 0.0, 60.0])
    run = ps.simulate(
        cone, w_rel, 2.0, attitude0=tilt, carried_by=table, gravity=[0, 0, -9.81], samples=5
    )
    r0 = ps.quaternion_to_matrix(tilt)
    plain = ps.simulate(
        cone,
        w_rel + r0.T @ [0.0, 0.0, 0.7],
        2.0,
        attitude0=tilt,
        torque=ps.GravityTorque(g=9.81),
        method="dop853",
        samples=5,
    )
    np.testing.assert_allclose(run.attitude, plain.attitude, atol=1e-8)
    # The relative attitude: the inertial one turned back by the table about z.
    ang = -0.35 * run.t  # half-angles of −0.7 t
    back = np.column_stack([np.cos(ang), 0 * ang, 0 * ang, np.sin(ang)])
    want = np.array([ps.quaternion_multiply(b, q) for b, q in zip(back, plain.attitude)])
    sign = np.sign(np.sum(want * run.relative_attitude, axis=1))[:, None]
    np.testing.assert_allclose(run.relative_attitude, sign * want, atol=1e-8)


def test_carried_results_pickle_and_show():
    run = ps.simulate([1.0, 1.0, 1.5], [0, 0, 1.0], 1.0, carried_by=ps.Place(0.5), samples=3)
    back = pickle.loads(pickle.dumps(run))
    np.testing.assert_array_equal(back.relative_attitude, run.relative_attitude)
    assert "relative_attitude" in repr(run) or "CarriedTrajectory" in repr(run)
    place = ps.Place(0.5)
    assert pickle.loads(pickle.dumps(place)) == place
    assert "Place(latitude=0.5" in repr(place)


def test_bad_carried_input_is_refused_by_name():
    # The core's refusal (Carrier::earth), in the user's words: the range in rad and degrees,
    # the value given in both.
    with pytest.raises(ps.PoinsotError, match=r"^latitude: must be finite and in \[-pi/2, pi/2\]"):
        ps.Place(2.0)
    with pytest.raises(ps.PoinsotError, match=r"^latitude: .*got 2 rad \(114\.59"):
        ps.Place(2.0)
    with pytest.raises(ps.ArgumentTypeError, match="^carried_by"):
        ps.simulate([1, 1, 1.5], [0, 0, 1], 1.0, carried_by="earth")
    with pytest.raises(ps.PoinsotError, match="^pivot"):
        ps.simulate([1, 1, 1.5], [0, 0, 1], 1.0, carried_by=ps.Place(0.5), pivot=[1, 0, 0])
    with pytest.raises(ps.ArgumentTypeError, match="^torque"):
        ps.simulate(
            [1, 1, 1.5], [0, 0, 1], 1.0, carried_by=ps.Place(0.5), torque=ps.GravityTorque(mgl=1.0)
        )
    with pytest.raises(ps.PoinsotError, match="^carried_by"):
        ps.simulate([1, 1, 1.5], [0, 0, 1], 1.0, gravity=[0, 0, -9.8])
    with pytest.raises(ps.PoinsotError, match="^duration"):
        ps.simulate([1, 1, 1.5], [0, 0, 1], -1.0, carried_by=ps.Place(0.5))
