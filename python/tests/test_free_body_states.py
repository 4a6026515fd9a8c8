"""``poinsot.free_body_states`` (many free bodies at many times, on SIMD lanes in the core)
against ``FreeRigidBody.state`` body by body, its shapes and broadcasting, its errors, progress
and a negative control."""

from __future__ import annotations

import numpy as np
import poinsot
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from poinsot import FreeRigidBody, free_body_states


def assert_attitudes(a, ae, moments, omega, t) -> None:
    """|a - ae| within the attitude's tolerance against FreeRigidBody.state: 1e-13 plus 8 ε per
    radian turned (the state's own error model: the batch sums the precession integral as a
    Fourier series, the scalar path by Carlson's R_J), the rates bounded by |ω₀| I_max / I_min.
    ``a`` is (N, M, 4) with t (M,) or (N, M); (N, 4) with t (N,); or one body's (M, 4)."""
    moments, omega = np.atleast_2d(moments), np.atleast_2d(omega)
    rate = np.linalg.norm(omega, axis=1) * moments.max(axis=1) / moments.min(axis=1)
    t = np.abs(np.asarray(t, dtype=float))
    if a.ndim == 3:
        turned = rate[:, None] * (t[None, :] if t.ndim == 1 else t)
    else:
        turned = rate * t
    tol = 1e-13 + 8 * np.finfo(float).eps * turned
    excess = np.abs(a - ae) / tol[..., None]
    assert np.all(excess <= 1.0), excess.max()


def bodies(n: int, seed: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    a, b = rng.uniform(0.5, 2.0, n), rng.uniform(0.5, 2.0, n)
    lo = np.abs(a - b)
    c = lo + rng.uniform(0.05, 0.95, n) * (a + b - lo)
    moments = np.column_stack([a, b, c])
    omega = rng.normal(size=(n, 3))
    q = rng.normal(size=(n, 4))
    return moments, omega, q / np.linalg.norm(q, axis=1, keepdims=True)


def reference(moments, omega, q, t):
    """The states body by body: (N, M, 3) and (N, M, 4), or (N, 3), (N, 4) for a number t."""
    ws, qs = [], []
    t = np.asarray(t, dtype=float)
    for i in range(len(moments)):
        ti = t[i] if t.ndim == 2 else t
        w, a = FreeRigidBody(moments[i], omega[i], q[i]).state(np.atleast_1d(ti))
        ws.append(w if t.ndim else w[0])
        qs.append(a if t.ndim else a[0])
    return np.array(ws), np.array(qs)


@settings(max_examples=25, deadline=None)
@given(
    n=st.integers(1, 9),
    m=st.integers(1, 40),
    seed=st.integers(0, 2**31),
    span=st.floats(0.1, 500.0),
)
def test_shared_times_equal_single_bodies(n, m, seed, span):
    moments, omega, q = bodies(n, seed)
    t = np.linspace(-span, span, m)
    w, a = free_body_states(moments, omega, t, attitude0=q)
    assert w.shape == (n, m, 3) and a.shape == (n, m, 4)
    we, ae = reference(moments, omega, q, t)
    np.testing.assert_array_equal(w, we)  # ω bit for bit
    assert_attitudes(a, ae, moments, omega, t)


def test_per_body_times_and_a_number():
    moments, omega, q = bodies(7, 3)
    t = np.random.default_rng(4).uniform(-50, 50, size=(7, 25))
    w, a = free_body_states(moments, omega, t, attitude0=q)
    we, ae = reference(moments, omega, q, t)
    np.testing.assert_array_equal(w, we)
    assert_attitudes(a, ae, moments, omega, t)
    w, a = free_body_states(moments, omega, 12.5, attitude0=q)
    assert w.shape == (7, 3) and a.shape == (7, 4)
    we, ae = reference(moments, omega, q, 12.5)
    np.testing.assert_array_equal(w, we)
    assert_attitudes(a, ae, moments, omega, np.full(7, 12.5))


def test_rows_broadcast_and_a_body_at_rest_keeps_its_attitude():
    t = np.linspace(0.0, 3.0, 11)
    omega = [[1.0, 0.1, 1.0], [0.0, 0.0, 0.0], [0.2, -1.0, 0.3]]
    w, a = free_body_states([1.0, 2.0, 3.0], omega, t)
    assert w.shape == (3, 11, 3)
    we, ae = FreeRigidBody([1.0, 2.0, 3.0], omega[2]).state(t)
    np.testing.assert_array_equal(w[2], we)
    assert_attitudes(a[2], ae, np.array([1.0, 2.0, 3.0]), np.array(omega[2]), t)
    assert np.all(w[1] == 0.0) and np.all(a[1] == [1.0, 0.0, 0.0, 0.0])


def test_a_later_time_or_another_body_is_seen_negative_control():
    moments, omega, q = bodies(4, 9)
    t = np.linspace(0.0, 20.0, 30)
    w, a = free_body_states(moments, omega, t + 1e-9, attitude0=q)
    we, ae = reference(moments, omega, q, t)
    assert np.abs(w - we).max() > 1e-12 and np.abs(a - ae).max() > 1e-12
    w, a = free_body_states(moments, omega[::-1], t, attitude0=q)
    assert np.abs(w - we).max() > 1e-3


def test_errors_name_the_argument():
    moments, omega, q = bodies(5, 1)
    with pytest.raises(poinsot.PoinsotError, match="^omega0: "):
        free_body_states(moments, omega[:3], 1.0)
    with pytest.raises(poinsot.PoinsotError, match="^attitude0: "):
        free_body_states(moments, omega, 1.0, attitude0=q[:, :3])
    bad = moments.copy()
    bad[3] = [1.0, 1.0, 3.0]
    with pytest.raises(poinsot.InvalidInertiaError, match="^moments: row 3: "):
        free_body_states(bad, omega, [0.0, 1.0])
    with pytest.raises(poinsot.PoinsotError, match="^t: "):
        free_body_states(moments, omega, [0.0, np.nan])
    with pytest.raises(poinsot.PoinsotError, match="^t: "):
        free_body_states(moments, omega, np.zeros((4, 2)))
    with pytest.raises(poinsot.PoinsotError, match="^t: body 2: "):
        fast = omega.copy()
        fast[2] = 1e4
        free_body_states(moments, fast, [0.0, 1e10])
    with pytest.raises(poinsot.PoinsotError, match="memory budget"):
        free_body_states(moments, omega, np.zeros(2 * 10**7))


def test_progress_is_reported_and_can_stop_the_run():
    moments, omega, q = bodies(200, 5)
    t = np.linspace(0.0, 100.0, 20_000)
    seen = []
    free_body_states(moments, omega, t, attitude0=q, progress=seen.append)
    assert seen and seen[-1] == 1.0 and seen == sorted(seen)

    def stop(_fraction):
        raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough"):
        free_body_states(moments, omega, np.linspace(0.0, 100.0, 200_000), progress=stop)
