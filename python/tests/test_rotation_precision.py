"""Near-rotations and small Euler angles against mpmath at 50 digits (issue 21, item 3).

* A matrix printed to 7 decimals (off orthonormal by ~1e-7, inside ``ROTATION_MATRIX_TOL``) is
  converted as its nearest rotation: the polar factor computed here in mpmath (``svd_r``,
  ``U V``). poinsot's quaternion is at least as close to it as scipy's (which projects by SVD);
  the negative control, Shepperd's formula on the raw entries (poinsot before the fix), is
  ~1e-8 away.
* Small first or third Euler angles (1e-3 ... 1e-12) come out to a few ulps relative, in all
  12 sequences, intrinsic and extrinsic, from matrices built in mpmath; the negative control,
  the third angle as the difference (alpha + gamma) - alpha (poinsot before the fix), is off by
  ~1e-13 relative at the issue's psi = -0.0034.
"""

from __future__ import annotations

import mpmath as mp
import numpy as np
import poinsot as ps
import pytest
from scipy.spatial.transform import Rotation

EPS = np.finfo(float).eps
SEQUENCES = ["xyx", "xzx", "yxy", "yzy", "zxz", "zyz", "xyz", "xzy", "yxz", "yzx", "zxy", "zyx"]


def _mp_rot(axis: str, angle: float) -> mp.matrix:
    c, s = mp.cos(angle), mp.sin(angle)
    if axis == "x":
        return mp.matrix([[1, 0, 0], [0, c, -s], [0, s, c]])
    if axis == "y":
        return mp.matrix([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    return mp.matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def _mp_euler_matrix(angles: list[float], seq: str, intrinsic: bool) -> np.ndarray:
    """The Euler matrix at 50 digits from the (exact, double) angles, rounded once to doubles."""
    with mp.workdps(50):
        a, b, c = (mp.mpf(x) for x in angles)
        if intrinsic:
            m = _mp_rot(seq[0], a) * _mp_rot(seq[1], b) * _mp_rot(seq[2], c)
        else:
            m = _mp_rot(seq[2], c) * _mp_rot(seq[1], b) * _mp_rot(seq[0], a)
        return np.array([[float(m[i, j]) for j in range(3)] for i in range(3)])


def _mp_nearest(a: np.ndarray) -> mp.matrix:
    """The rotation nearest to ``a`` (Frobenius): the polar factor U Vᵀ of its SVD, 50 digits."""
    with mp.workdps(50):
        u, _, v = mp.svd_r(mp.matrix(a.tolist()))
        return u * v


def _mp_quaternion(r: mp.matrix) -> np.ndarray:
    """Quaternion [w, x, y, z] (w >= 0) of a 50-digit rotation, from its largest component."""
    with mp.workdps(50):
        d = [1 + r[0, 0] + r[1, 1] + r[2, 2], 1 + r[0, 0] - r[1, 1] - r[2, 2]]
        d += [1 - r[0, 0] + r[1, 1] - r[2, 2], 1 - r[0, 0] - r[1, 1] + r[2, 2]]
        k = max(range(4), key=lambda i: d[i])
        c = mp.sqrt(d[k]) / 2  # |q_k|
        sums = {  # 4 q_i q_j for i != j
            (0, 1): r[2, 1] - r[1, 2],
            (0, 2): r[0, 2] - r[2, 0],
            (0, 3): r[1, 0] - r[0, 1],
            (1, 2): r[0, 1] + r[1, 0],
            (1, 3): r[0, 2] + r[2, 0],
            (2, 3): r[1, 2] + r[2, 1],
        }
        q = [c if i == k else sums[(min(i, k), max(i, k))] / (4 * c) for i in range(4)]
        sign = -1 if q[0] < 0 else 1
        return np.array([float(sign * x) for x in q])


def _raw_quaternion(r: np.ndarray) -> np.ndarray:
    """Shepperd's quaternion of the raw entries (what poinsot returned before the projection)."""
    tr = np.trace(r)
    k = int(np.argmax([tr, r[0, 0], r[1, 1], r[2, 2]]))
    if k == 0:
        q = [1 + tr, r[2, 1] - r[1, 2], r[0, 2] - r[2, 0], r[1, 0] - r[0, 1]]
    elif k == 1:
        q = [
            r[2, 1] - r[1, 2],
            1 + r[0, 0] - r[1, 1] - r[2, 2],
            r[0, 1] + r[1, 0],
            r[0, 2] + r[2, 0],
        ]
    elif k == 2:
        q = [
            r[0, 2] - r[2, 0],
            r[0, 1] + r[1, 0],
            1 - r[0, 0] + r[1, 1] - r[2, 2],
            r[1, 2] + r[2, 1],
        ]
    else:
        q = [
            r[1, 0] - r[0, 1],
            r[0, 2] + r[2, 0],
            r[1, 2] + r[2, 1],
            1 - r[0, 0] - r[1, 1] + r[2, 2],
        ]
    qa = np.array(q) / np.linalg.norm(q)
    return np.asarray(qa if qa[0] >= 0 else -qa)


def _qdist(p: np.ndarray, q: np.ndarray) -> float:
    return float(min(np.abs(p - q).max(), np.abs(p + q).max()))


def _to_np(m: mp.matrix) -> np.ndarray:
    return np.array([[float(m[i, j]) for j in range(3)] for i in range(3)])


def test_printed_matrix_converts_as_its_nearest_rotation() -> None:
    rng = np.random.default_rng(2103)
    worst_poinsot = worst_scipy = 0.0
    raw_errors = []
    for _ in range(60):
        angles = [rng.uniform(-3, 3), rng.uniform(0.1, 3.0), rng.uniform(-3, 3)]
        a = np.round(ps.euler_to_matrix(angles), 7)  # as users paste them
        defect = np.abs(a.T @ a - np.eye(3)).max()
        assert 1e-9 < defect < ps.rotation.ROTATION_MATRIX_TOL
        nearest = _mp_nearest(a)
        q_ref = _mp_quaternion(nearest)
        err_p = _qdist(ps.matrix_to_quaternion(a), q_ref)
        err_s = _qdist(Rotation.from_matrix(a).as_quat()[[3, 0, 1, 2]], q_ref)
        worst_poinsot, worst_scipy = max(worst_poinsot, err_p), max(worst_scipy, err_s)
        assert err_p <= max(err_s, 2 * EPS), (angles, err_p, err_s)
        raw_errors.append(_qdist(_raw_quaternion(a), q_ref))
        # The other conversions of the same matrix rebuild the nearest rotation.
        r_ref = _to_np(nearest)
        back = ps.euler_to_matrix(
            ps.matrix_to_euler(a, "yzy", intrinsic=False), "yzy", intrinsic=False
        )
        assert np.abs(back - r_ref).max() < 2e-15
        axis, angle = ps.rotation_axis(a)
        assert np.abs(ps.axis_angle_to_matrix(axis, angle) - r_ref).max() < 2e-15
        assert np.allclose(ps.screw_axis(a, [0.0, 0.0, 0.0]).axis, axis, rtol=0, atol=1e-15)
    assert worst_poinsot < 1e-15
    # Negative control: the raw entries' quaternion is ~1e-8 from the nearest rotation's.
    assert np.median(raw_errors) > 1e-9


def test_documented_example_of_the_projection() -> None:
    """docs/rotation.md: zxz (1.45, 1.63, -1.11) printed to 7 decimals."""
    r = ps.euler_to_matrix([1.45, 1.63, -1.11])
    a = np.round(r, 7)
    defect = np.abs(a.T @ a - np.eye(3)).max()
    assert (
        defect == pytest.approx(1.04e-7, abs=0.01e-7)
        and defect > ps.rotation.NEAREST_ROTATION_DEFECT
    )
    q_true = ps.matrix_to_quaternion(r)
    q = ps.matrix_to_quaternion(a)
    assert _qdist(q, _mp_quaternion(_mp_nearest(a))) < 2e-16
    assert _qdist(q, q_true) == pytest.approx(3.6e-9, abs=0.05e-9)  # the nearest rotation's
    assert _qdist(_raw_quaternion(a), q_true) == pytest.approx(3.2e-8, abs=0.05e-8)  # raw entries
    q_scipy = Rotation.from_matrix(a).as_quat()[[3, 0, 1, 2]]
    assert _qdist(q, q_scipy) < 4e-16


@pytest.mark.parametrize("seq", SEQUENCES)
@pytest.mark.parametrize("intrinsic", [True, False])
def test_small_first_and_third_angles_to_relative_accuracy(seq: str, intrinsic: bool) -> None:
    rng = np.random.default_rng(2 * SEQUENCES.index(seq) + intrinsic)
    proper = seq[0] == seq[2]
    for small in [-0.0034, 1e-3, -1e-5, 1e-7, -1e-9, 1e-12]:
        for pos in (0, 2):
            beta = rng.uniform(0.3, 2.8) if proper else rng.uniform(-1.3, 1.3)
            angles = [rng.uniform(-3, 3), beta, rng.uniform(-3, 3)]
            angles[pos] = small * (1 + 0.3 * rng.uniform())
            r = _mp_euler_matrix(angles, seq, intrinsic)
            got = ps.matrix_to_euler(r, seq, intrinsic=intrinsic)
            rel = abs(got[pos] - angles[pos]) / abs(angles[pos])
            assert rel <= 4 * EPS, (seq, intrinsic, angles, got, rel)
            # The other two to round-off (conditioning 1/sin(beta) <= 3.4 here).
            assert np.abs(got - angles).max() < 8 * EPS * 3.4, (angles, got)


@pytest.mark.parametrize(("psi", "old_error"), [(-0.0034, 5e-15), (1e-9, 1e-8)])
def test_negative_control_third_angle_as_a_difference(psi: float, old_error: float) -> None:
    """The extraction before the fix, psi = (phi + psi) - phi, loses what poinsot now keeps."""
    angles = [1.0, 0.5, psi]
    r = _mp_euler_matrix(angles, "zxz", True)
    phi = np.arctan2(r[0, 2], -r[1, 2])
    psi_old = np.arctan2(r[1, 0] - r[0, 1], r[0, 0] + r[1, 1]) - phi
    assert abs(psi_old - psi) / abs(psi) > old_error
    assert abs(ps.matrix_to_euler(r)[2] - psi) / abs(psi) <= 2 * EPS
