"""Bad input accepted, or refused badly (issue 10, items 4, 12 and 13): each case here was
observed on the previous release — a silent wrong answer, the wrong exception type, or an error
naming something the user never passed — and each has a negative control that the valid input
still works.
"""

from __future__ import annotations

import warnings

import numpy as np
import poinsot as ps
import pytest


def test_complex_arrays_are_refused_not_truncated() -> None:
    """``euler_to_matrix(np.array([1+5j, 2, 3]))`` dropped the imaginary part with only a
    ComplexWarning; now it is an ArgumentTypeError (a PoinsotError and a TypeError)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(ps.ArgumentTypeError, match="^angles: must be real, got complex"):
            ps.euler_to_matrix(np.array([1 + 5j, 2, 3]))
        with pytest.raises(TypeError, match="^omega0: "):
            ps.simulate([1, 2, 3], [1 + 0j, 0.1, 1], 1.0)
        with pytest.raises(ps.PoinsotError, match="^mass: "):
            ps.RigidBody.solid_sphere(complex(1, 0), 1.0)
    # Negative control: real values of any real dtype are accepted.
    ps.euler_to_matrix(np.array([1, 2, 3], dtype=np.int32))
    ps.euler_to_matrix(np.array([1.0, 2.0, 3.0], dtype=np.float32))


@pytest.mark.parametrize("bad", ["no", "", 1, 0.0, None, [True]])
def test_flags_are_booleans_not_truthiness(bad: object) -> None:
    """``Earth().drop(100, .5, rotation="no")`` ran *with* rotation; every flag now takes only
    True or False (numpy booleans too)."""
    with pytest.raises(ps.ArgumentTypeError, match="^rotation: must be True or False"):
        ps.Earth().drop(100.0, 0.5, rotation=bad)
    with pytest.raises(ps.ArgumentTypeError, match="^degrees: "):
        ps.Earth().effective_gravity(45.0, degrees=bad)
    with pytest.raises(ps.ArgumentTypeError, match="^degrees: "):
        ps.HeavyTop(1.0, 0.5, 1.0, 30.0, psi_dot=6.0, degrees=bad)
    with pytest.raises(ps.ArgumentTypeError, match="^merge_vertices: "):
        ps.RigidBody.from_mesh(np.eye(3), [[0, 1, 2]], merge_vertices=bad)
    # Negative control: real booleans, plain and numpy, pick the behaviour.
    with_rot = ps.Earth().drop(100.0, 0.5, rotation=np.bool_(True))
    without = ps.Earth().drop(100.0, 0.5, rotation=False)
    assert with_rot.east > 0.0 and without.east == 0.0


@pytest.mark.parametrize(
    ("bad", "error"),
    [
        (0, ps.PoinsotError),
        (-1, ps.PoinsotError),
        (1, ps.PoinsotError),
        (2.5, ps.ArgumentTypeError),
        (2.0, ps.ArgumentTypeError),
        ("5", ps.ArgumentTypeError),
        (True, ps.ArgumentTypeError),
    ],
)
def test_sample_counts_are_checked_everywhere(bad: object, error: type) -> None:
    """``samples`` of 0 or -1 silently gave 1–2 samples in the Earth runs, 2.5 became 2 and -1
    in ``drop`` raised OverflowError."""
    earth = ps.Earth()
    calls = [
        lambda: earth.drop(100.0, 0.5, samples=bad),
        lambda: earth.projectile(100.0, 0.7, 0.0, 0.5, samples=bad),
        lambda: earth.flow_into_low(0.7, samples=bad, duration=3600.0),
        lambda: earth.inertial_oscillation(0.7, samples=bad),
        lambda: earth.foucault(0.7, samples=bad, duration=30.0),
        lambda: ps.simulate_particle(ps.MovingFrame(), [1, 0, 0], [0, 1, 0], 1.0, samples=bad),
        lambda: ps.FreeRigidBody([1, 2, 3], [1, 0.1, 1]).polhode(bad),
    ]
    for call in calls:
        with pytest.raises(error, match="^samples: "):
            call()
    # Negative control: numpy integers are integers.
    assert len(earth.drop(100.0, 0.5, samples=np.int64(7)).t) == 7


def test_t_eval_must_be_one_dimensional() -> None:
    with pytest.raises(ps.PoinsotError, match=r"^t_eval: must have shape \(N,\)"):
        ps.simulate_particle(ps.MovingFrame(), [1, 0, 0], [0, 1, 0], 1.0, t_eval=np.ones((3, 3)))
    run = ps.simulate_particle(ps.MovingFrame(), [1, 0, 0], [0, 1, 0], 1.0, t_eval=[0.0, 0.5, 1.0])
    assert run.t.tolist() == [0.0, 0.5, 1.0]


def test_errors_name_the_users_argument() -> None:
    """Errors used to name internal quantities: ``OverflowError`` for an int beyond the double
    range, ``t`` for a NaN returned by a torque callable, ``inertia`` for a ``body``,
    ``strength`` for ``pull``, ``t_end`` for a drop's ``height``."""
    with pytest.raises(ps.PoinsotError, match="^mass: .*range of doubles"):
        ps.RigidBody.solid_sphere(10**400, 1.0)
    with pytest.raises(ps.IntegrationError, match=r"^torque: the callback returned \[NaN"):
        ps.simulate(
            [1, 2, 3], [0.1, 0.5, 1], 1.0, torque=lambda t, w, q: [np.nan, 0, 0], method="dop853"
        )
    with pytest.raises(ps.InvalidInertiaError, match="^body: "):
        ps.simulate([1.0, 1.0, 3.0], [0.1, 0.5, 1], 1.0)
    with pytest.raises(ps.PoinsotError, match="^pull: "):
        ps.Earth().flow_into_low(0.7, pull=-1.0, duration=3600.0)
    with pytest.raises(ps.PoinsotError, match="^height: "):
        ps.Earth().drop(1e308, 0.5)
    with pytest.raises(ps.PoinsotError, match="^height: .*overflows"):
        ps.Earth().eastward_deflection(1e308, 0.5)
    # The fall time of any finite height is finite (√(2h/g) without overflowing 2h).
    assert np.isfinite(ps.Earth().fall_time(1.7e308))


def test_large_finite_inputs_never_give_inf_or_nan() -> None:
    """Item 4: large finite inputs returned inf or NaN silently; now each returns finite numbers
    or names the argument."""
    with pytest.raises(ps.PoinsotError, match="^velocity: .*Coriolis"):
        ps.MovingFrame(angular_velocity=[0, 0, 1]).to_fixed([1, 0, 0], velocity=[1e308, 1e308, 0])
    with pytest.raises(ps.PoinsotError, match="^rates: .*overflows"):
        ps.body_angular_velocity([0.1, 0.2, 0.3], [1e308, 1e308, 1e308])
    with pytest.raises(ps.PoinsotError, match="^t: .*overflows"):
        ps.screw_axis(ps.euler_to_matrix([0.1, 0.2, 0.3]), [1e308, 1e308, 1e308])
    with pytest.raises(ps.PoinsotError, match="^s: "):
        ps.screw_axis(ps.euler_to_matrix([0.1, 0.2, 0.3]), [1.0, 2.0, 3.0]).displacement_at(1e308)
    # Negative controls: the same calls at ordinary magnitudes.
    ps.MovingFrame(angular_velocity=[0, 0, 1]).to_fixed([1, 0, 0], velocity=[1e100, 1e100, 0])
    assert np.isfinite(ps.body_angular_velocity([0.1, 0.2, 0.3], [1e300, 1e300, 1e300])).all()


def test_batch_rows_name_the_argument_and_the_shapes_taken() -> None:
    """The batch calls' rows (one helper, ``_validate.as_rows``): ``simulate_batch`` takes
    (N, 3) and (N, 4) rows only, ``free_body_states`` also one row for every body; another
    shape is refused naming the argument, the shapes taken and the shape given."""
    with pytest.raises(ps.PoinsotError, match=r"^omega0: must have shape \(N, 3\), got \(3,\)$"):
        ps.simulate_batch([[1.0, 2.0, 3.0]], [1.0, 0.0, 0.0], 1.0)
    with pytest.raises(
        ps.PoinsotError, match=r"^attitude0: must have shape \(N, 4\), got \(1, 3\)$"
    ):
        ps.simulate_batch([[1.0, 2.0, 3.0]], [[1.0, 0.0, 0.0]], 1.0, attitude0=[[1.0, 0.0, 0.0]])
    with pytest.raises(
        ps.PoinsotError, match=r"^moments: must have shape \(N, 3\) or \(3,\), got \(2, 2\)$"
    ):
        ps.free_body_states([[1.0, 2.0], [3.0, 4.0]], [1.0, 0.0, 0.0], 0.0)
    # Negative control: one row of moments serves every body.
    omega, attitude = ps.free_body_states([1.0, 2.0, 3.0], [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]], 0.0)
    assert omega.shape == (2, 3) and attitude.shape == (2, 4)
