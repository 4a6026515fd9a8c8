"""Each erratum of the unit's first part (seed-errata.md, eqs. 2.2–2.30 and Earth's rate) pinned
by a test of the corrected result."""

from __future__ import annotations

import numpy as np
import poinsot as ps

#: Central differences with step 1e-4 on O(1) smooth motions: error ~1e-8.
FD_TOL = 1e-7


def _rot_z(a: float) -> np.ndarray:
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def test_erratum_2_2_2_3_velocities_and_accelerations_add() -> None:
    """ṙ' = Ṙ + ṙ and r̈' = R̈ + r̈ for a translating frame (the unit prints r' = R + r)."""
    f = ps.MovingFrame(origin=[1, 2, 3], velocity=[0.5, -1, 2], acceleration=[0, 0, -9.81])
    out = f.to_fixed([1, 1, 1], [3, 0, 0], [0, 1, 0])
    np.testing.assert_allclose(out.velocity, [3.5, -1, 2])
    np.testing.assert_allclose(out.acceleration, [0, 1, -9.81])


def test_erratum_2_5_effective_force_is_F_minus_m_Rddot() -> None:
    """m r̈ = F − m R̈: the translational fictitious force is −m R̈."""
    f = ps.MovingFrame(acceleration=[0.0, 2.0, 0.0])
    np.testing.assert_allclose(
        f.fictitious_forces(3.0, [1, 0, 0], [0, 0, 0])["translational"], [0, -6.0, 0]
    )


def test_erratum_2_10_2_14_derivative_in_a_rotating_frame() -> None:
    """(dV/dt)_fix = (dV/dt)_rot + ω × V (2.14, with dĵ/dt V_y in 2.10): a vector with moving
    components V(t) in a frame turning at ω about z, differentiated numerically in the fixed frame."""
    w, h, t = 0.7, 1e-4, 0.3
    V = lambda s: np.array([np.cos(s), s**2, 1.0 + s])  # moving components
    Vdot = np.array([-np.sin(t), 2 * t, 1.0])
    fixed = lambda s: _rot_z(w * s) @ V(s)
    numeric = (fixed(t + h) - fixed(t - h)) / (2 * h)
    frame = ps.MovingFrame(angular_velocity=[0, 0, w], attitude=_rot_z(w * t))
    out = frame.to_fixed(V(t), Vdot)  # the velocity transformation is 2.14 applied to r
    np.testing.assert_allclose(out.velocity, numeric, atol=FD_TOL)


def test_erratum_2_18_second_derivative() -> None:
    """d'²V/dt² = d²V/dt² + 2ω × dV/dt + ω × (ω × V) + ω̇ × V (the third line of 2.18 has
    ω × dV/dt where ω × V belongs): checked by differentiating twice numerically."""
    h, t = 1e-3, 0.4
    phi = lambda s: 0.5 * s + 0.3 * s**2  # angle about z: ω = 0.5 + 0.6 s, ω̇ = 0.6
    V = lambda s: np.array([1.0 + s, np.sin(s), s**3])
    Vd = np.array([1.0, np.cos(t), 3 * t**2])
    Vdd = np.array([0.0, -np.sin(t), 6 * t])
    fixed = lambda s: _rot_z(phi(s)) @ V(s)
    numeric = (fixed(t + h) - 2 * fixed(t) + fixed(t - h)) / h**2
    frame = ps.MovingFrame(
        angular_velocity=[0, 0, 0.5 + 0.6 * t],
        angular_acceleration=[0, 0, 0.6],
        attitude=_rot_z(phi(t)),
    )
    out = frame.to_fixed(V(t), Vd, Vdd)
    np.testing.assert_allclose(out.acceleration, numeric, atol=1e-5)


def test_erratum_2_26_constant_omega_means_no_euler_term() -> None:
    """ "ω constant, then ω̇ = 0": the Euler term vanishes and only Coriolis and centrifugal remain."""
    f = ps.MovingFrame(angular_velocity=[0.3, 0.2, 1.0])
    forces = f.fictitious_forces(1.0, [1, 2, 3], [0.5, 0, 0])
    assert np.all(forces["euler"] == 0) and np.all(forces["translational"] == 0)


def test_erratum_2_30_coriolis_force_carries_the_mass() -> None:
    """−2 m ω × ṙ (the unit drops the m): the Coriolis force doubles with the mass."""
    f = ps.MovingFrame(angular_velocity=[0, 0, 1.0])
    c1 = f.fictitious_forces(1.0, [1, 0, 0], [0, 1, 0])["coriolis"]
    c2 = f.fictitious_forces(2.0, [1, 0, 0], [0, 1, 0])["coriolis"]
    np.testing.assert_allclose(c1, [2.0, 0, 0])
    np.testing.assert_allclose(c2, 2 * c1)


def test_erratum_earth_rate_solar_day_and_sidereal() -> None:
    """The unit's 2π/(24·3600) is 7.27e-5 rad/s, not 7.25e-5; the true rate is sidereal."""
    assert abs(ps.Earth.solar_day().rotation_rate - 7.2722e-5) < 1e-9
    assert abs(ps.Earth().rotation_rate - 2 * np.pi / 86164.0905) < 1e-11
