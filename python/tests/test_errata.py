"""Each erratum of the unit (docs/errata.md) that this part of poinsot covers, pinned.

Each test computes the corrected result independently (direct sums, hand-written closed forms)
and checks poinsot against it, and where possible shows that the misprinted form differs (a
negative control: the typo would have been caught).
"""

from __future__ import annotations

import numpy as np
import poinsot as ps

RNG = np.random.default_rng(20261121)


def _random_body() -> ps.RigidBody:
    masses = RNG.uniform(0.5, 2.0, size=5)
    positions = RNG.normal(size=(5, 3))
    return ps.RigidBody.from_point_masses(masses, positions)


def test_erratum_2_51_sum_over_j() -> None:
    """L_i = Σ_j I_ij ω_j (the unit prints Σ_i): L = I·ω, equal to Σ m r × (ω × r) (2.44)."""
    masses = RNG.uniform(0.5, 2.0, size=6)
    positions = RNG.normal(size=(6, 3))
    body = ps.RigidBody.from_point_masses(masses, positions)
    omega = RNG.normal(size=3)
    about = np.zeros(3)
    direct = sum(m * np.cross(r, np.cross(omega, r)) for m, r in zip(masses, positions))
    I_O = body.inertia_about(about)
    L_sum_over_j = np.array([sum(I_O[i, j] * omega[j] for j in range(3)) for i in range(3)])
    np.testing.assert_allclose(
        body.angular_momentum(omega, about=about), direct, rtol=1e-12, atol=1e-12
    )
    np.testing.assert_allclose(L_sum_over_j, direct, rtol=1e-12, atol=1e-12)
    # the misprint (sum over i: the column sums times ω_j) gives another vector
    L_misprint = np.array([sum(I_O[i, j] * omega[j] for i in range(3)) for j in range(3)])
    assert not np.allclose(L_misprint, direct, rtol=1e-3)


def test_erratum_2_66_kinetic_energy_principal() -> None:
    """T = ½ (I₁ω₁² + I₂ω₂² + I₃ω₃²) in principal axes (the unit prints I_i ω₁²)."""
    body = _random_body()
    omega_principal = np.array([0.3, -1.1, 0.7])
    axes = body.principal_axes
    omega = axes @ omega_principal  # the same ω in the body's reference axes
    I1, I2, I3 = body.principal_moments
    corrected = 0.5 * (
        I1 * omega_principal[0] ** 2 + I2 * omega_principal[1] ** 2 + I3 * omega_principal[2] ** 2
    )
    np.testing.assert_allclose(body.kinetic_energy(omega), corrected, rtol=1e-12)
    # T = ½ ω·L (2.53) as well
    np.testing.assert_allclose(
        body.kinetic_energy(omega), 0.5 * omega @ body.angular_momentum(omega), rtol=1e-12
    )


def test_erratum_2_99_omega3_is_omega_zeta() -> None:
    """ω₃ = ω_ζ = ψ̇ + φ̇ cos θ (the unit prints ω₃ = ω_ξ = θ̇)."""
    phi, theta, psi = 0.4, 1.1, -0.7
    dphi, dtheta, dpsi = 0.3, -0.8, 2.5
    w = ps.body_angular_velocity([phi, theta, psi], [dphi, dtheta, dpsi])
    np.testing.assert_allclose(w[2], dpsi + dphi * np.cos(theta), rtol=1e-14)
    assert abs(w[2] - dtheta) > 0.1  # the misprint would give θ̇
    np.testing.assert_allclose(
        w[0], dtheta * np.cos(psi) + dphi * np.sin(theta) * np.sin(psi), rtol=1e-14
    )
    np.testing.assert_allclose(
        w[1], -dtheta * np.sin(psi) + dphi * np.sin(theta) * np.cos(psi), rtol=1e-14
    )
