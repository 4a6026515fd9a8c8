"""Small calls (issue 15; one conversion path since issue 22): a scalar ``t`` and a 3-vector of
any form give what the general forms give.

References, all public: a scalar ``t`` against the first row of the array of times, and against
a 0-d array (the general conversion of ``t``); the free bodies' ``moments`` and ``omega0`` of
any form (read by the binding, ``convert::triple``) against the float64 arrays of the same
numbers, and, for what is refused, against the general conversion of every other 3-vector
argument (``as_vector3``: same exception, same message). Outcomes are compared bit for bit."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest
from poinsot import FreeRigidBody, FreeSymmetricTop, HeavyTop, _validate
from poinsot.errors import PoinsotError

#: Bodies in every regime of the exact solution (moments, ω₀, attitude₀).
BODIES = {
    "about max axis": ([1.0, 2.0, 3.0], [1.0, 0.1, 1.0], None),
    "about min axis": ([1.0, 2.0, 3.0], [1.0, 0.1, 0.1], None),
    "separatrix": ([1.0, 2.0, 3.0], [1.0, 0.0, 1.0], None),
    "symmetric": ([2.0, 2.0, 3.0], [0.3, 0.4, 2.0], [0.6, 0.0, 0.8, 0.0]),
    "steady": ([1.0, 2.0, 3.0], [0.0, 0.0, 2.5], None),
    "unsorted, attitude": ([3.0, 1.0, 2.0], [-0.2, 1.0, 0.7], [0.5, 0.5, 0.5, 0.5]),
}

#: Scalar times of each plain kind (float, int, numpy float64, −0).
PLAIN_TIMES = [0.0, -0.0, 0.7316, -3.5, 1000.0, 7, -2, np.float64(2.5), 123456.789]


class _Float(float):
    """A float subclass."""


#: Inputs for one scalar argument: valid ones of every form, and what the fuzz suite throws.
ADVERSARIAL = [
    math.nan,
    math.inf,
    -math.inf,
    1e308,
    5e-324,
    0.0,
    -1.0,
    True,
    None,
    "no",
    1 + 5j,
    10**400,
    2**63,
    2**1023,
    np.float32(0.5),
    np.int64(3),
    np.bool_(True),
    np.array(0.5),
    np.array([0.5]),
]

#: 3-vectors of every form, valid and not.
VECTORS = [
    [1.0, 0.1, 1.0],
    (1.0, 0.1, 1.0),
    [1, 0, 2],
    (2**53, 1, 2),
    [2**53 + 1, 1.0, 2.0],
    [np.float64(1.0), 0.1, 1],
    np.array([1.0, 0.1, 1.0]),
    np.array([1, 0, 2]),
    np.array([1.0, 0.1, 1.0], dtype=np.float32),
    np.arange(6.0)[::2],
    np.array([1.0, 0.1, 1.0], dtype=">f8"),
    np.array([1.0, 0.1, 1.0]).view(np.recarray),
    np.ma.masked_array([1.0, 0.1, 1.0], mask=[False, True, False]),
    [_Float(1.0), 0.1, 1.0],
    [-0.0, 0.0, 2.0],
    [1e308, 1e308, 1e308],
    [1.0, math.nan, 1.0],
    (math.inf, 0.0, 1.0),
    np.array([1.0, math.nan, 1.0]),
    [1.0, True, 1.0],
    [True, True, True],
    [1.0, 2.0],
    (1.0, 2.0, 3.0, 4.0),
    [[1.0, 2.0, 3.0]],
    np.array([[1.0, 2.0, 3.0]]),
    np.array(1.0),
    [1.0, "a", 2.0],
    [1.0, 1 + 2j, 2.0],
    [1.0, 10**400, 2.0],
    [1.0, 2**1023, 2.0],
    [0.0, 0.0, 0.0],
    [-1.0, 2.0, 3.0],
    [1.0, 2.0, 30.0],
    "abc",
    None,
    5.0,
]


def outcome(call: Callable[[], Any]) -> tuple[Any, ...]:
    """What ``call`` does: ("ok", type and bytes of each number it returns) or ("raises", the
    exception's type and message)."""
    try:
        result = call()
    except Exception as exc:  # any exception is an outcome to compare
        return ("raises", type(exc), str(exc))
    return ("ok", _bits(result))


def _bits(value: Any) -> Any:
    if isinstance(value, tuple | list):
        return tuple(_bits(v) for v in value)
    if isinstance(value, np.ndarray):
        return ("array", value.dtype.str, value.shape, value.tobytes())
    if isinstance(value, float):
        return ("float", np.float64(value).tobytes())
    if isinstance(value, FreeRigidBody | FreeSymmetricTop | HeavyTop):
        return repr(value)
    return value


def test_the_comparison_is_bit_for_bit_and_sees_messages() -> None:
    """Negative control of :func:`outcome`: −0.0 is not 0.0, one message is not another."""
    assert outcome(lambda: -0.0) != outcome(lambda: 0.0)
    assert outcome(lambda: np.zeros(3)) != outcome(lambda: np.zeros(3, dtype=np.float32))

    def fails(message: str) -> Callable[[], Any]:
        def call() -> Any:
            raise PoinsotError(message)

        return call

    assert outcome(fails("t: a")) != outcome(fails("t: b"))


# ---- a scalar t: the first row of the array path, and the 0-d array's outcome --------------


@pytest.mark.parametrize("name", list(BODIES))
def test_free_body_state_at_a_scalar_t_is_the_first_row_of_the_array_path(name: str) -> None:
    moments, w0, q0 = BODIES[name]
    body = FreeRigidBody(moments, w0, attitude0=q0)
    for t in PLAIN_TIMES:
        w, q = body.state(t)
        assert w.shape == (3,) and q.shape == (4,)
        wa, qa = body.state(np.array([float(t)]))
        assert w.tobytes() == wa[0].tobytes() and q.tobytes() == qa[0].tobytes(), t
        assert body.omega(t).tobytes() == w.tobytes()
        assert body.attitude(t).tobytes() == q.tobytes()
        assert outcome(lambda t=t: body.state(t)) == outcome(lambda t=t: body.state(np.array(t)))


def test_free_body_scalar_results_are_new_writable_arrays() -> None:
    body = FreeRigidBody([1.0, 2.0, 3.0], [1.0, 0.1, 1.0])
    w1, q1 = body.state(1.5)
    w1[:] = 0.0
    q1[:] = 0.0
    w2, q2 = body.state(1.5)
    assert np.all(w2 != 0.0) and np.linalg.norm(q2) == pytest.approx(1.0, abs=1e-15)


def test_symmetric_top_at_a_scalar_t_is_the_first_row_of_the_array_path() -> None:
    sym = FreeSymmetricTop(1.0, 0.5, [0.3, -0.4, 2.0], attitude0=[0.6, 0.0, 0.8, 0.0])
    for t in PLAIN_TIMES:
        for method, size in ((sym.omega, 3), (sym.attitude, 4), (sym.symmetry_axis, 3)):
            one = method(t)
            assert one.shape == (size,)
            assert one.tobytes() == method(np.array([float(t)]))[0].tobytes()
            assert outcome(lambda t=t, m=method: m(t)) == outcome(
                lambda t=t, m=method: m(np.array(t))
            )


@pytest.mark.parametrize("degrees", [False, True])
def test_heavy_top_at_a_scalar_t_is_the_array_path(degrees: bool) -> None:
    tops = [
        HeavyTop(1.0, 0.5, 1.0, 0.8, psi_dot=6.0),  # cusps (nutating)
        HeavyTop(1.0, 0.5, 1.0, 0.5, phi_dot=-1.0, psi_dot=8.0),  # loops
        HeavyTop(1.0, 0.5, 1.0, 0.0, psi_dot=10.0),  # sleeping (uniform)
    ]
    for ht in tops:
        for t in PLAIN_TIMES:
            for method in (ht.euler_angles, ht.euler_rates):
                one = method(t, degrees=degrees)
                assert all(type(x) is float for x in one)
                rows = method(np.array([float(t)]), degrees=degrees)
                assert np.array(one).tobytes() == np.array([r[0] for r in rows]).tobytes()


@pytest.mark.parametrize("value", ADVERSARIAL, ids=repr)
def test_scalar_t_of_any_form_as_the_general_conversion(value: Any) -> None:
    """``t`` of any form behaves as the same value wrapped in a 0-d array would, or raises as the
    general conversion does (for what a 0-d array cannot hold, the message names ``t``)."""
    body = FreeRigidBody([1.0, 2.0, 3.0], [1.0, 0.1, 1.0])
    ht = HeavyTop(1.0, 0.5, 1.0, 0.8, psi_dot=6.0)
    sym = FreeSymmetricTop(1.0, 0.5, [0.3, -0.4, 2.0])
    for call in (body.state, ht.euler_angles, sym.attitude):
        got = outcome(lambda call=call: call(value))
        if got[0] == "raises":
            assert issubclass(got[1], PoinsotError) and got[2].startswith("t:"), got
        else:
            wrapped = np.asarray(value, dtype=np.float64)
            assert got == outcome(lambda call=call: call(wrapped)), value


def test_bad_scalar_t_still_raises_naming_t() -> None:
    body = FreeRigidBody([1.0, 2.0, 3.0], [1.0, 0.1, 1.0])
    for bad in (math.nan, math.inf, "1.0", True, 1e300):
        with pytest.raises((PoinsotError, TypeError), match=r"^t:"):
            body.state(bad)
    ht = HeavyTop(1.0, 0.5, 1.0, 0.8, psi_dot=6.0)
    for bad in (math.nan, 1e300):
        with pytest.raises(PoinsotError, match=r"^t:"):
            ht.euler_angles(bad)


# ---- 3-vectors of any form: one conversion -----------------------------------------------


def _reference(build: Callable[[Any], Any], value: Any, name: str, finite: bool) -> tuple[Any, ...]:
    """The outcome of ``build`` on ``value`` converted by the general conversion of every other
    3-vector argument (its error if it refuses ``value``)."""
    try:
        arr = _validate.as_vector3(value, name, finite=finite)
    except Exception as exc:  # the refusal is the outcome
        return ("raises", type(exc), str(exc))
    return outcome(lambda: build(np.array(arr, dtype=np.float64)))


@pytest.mark.parametrize("value", VECTORS + ADVERSARIAL, ids=repr)
def test_free_body_vectors_of_any_form_as_float64_arrays(value: Any) -> None:
    w0 = np.array([1.0, 0.1, 1.0])

    def moments(v: Any) -> Any:
        return FreeRigidBody(v, w0).state(0.5)

    def omega0(v: Any) -> Any:
        return FreeRigidBody([1.0, 2.0, 3.0], v).state(0.5)

    def sym_omega0(v: Any) -> Any:
        return FreeSymmetricTop(1.0, 0.5, v).attitude(0.5)

    for build, name, finite in (
        (moments, "moments", False),
        (omega0, "omega0", True),
        (sym_omega0, "omega0", True),
    ):
        got = outcome(lambda build=build: build(value))
        assert got == _reference(build, value, name, finite), (name, value)
        if got[0] == "raises":
            # named by the argument (or by t, for a fast body whose time limit 0.5 s passes)
            assert issubclass(got[1], PoinsotError), got
            assert got[2].startswith((f"{name}:", "t:")), got


def test_moments_and_omega0_are_the_inputs_in_new_arrays() -> None:
    body = FreeRigidBody((3, 1, 2), np.array([0.5, -1.0, 0.25]))
    np.testing.assert_array_equal(body.moments, [3.0, 1.0, 2.0])
    np.testing.assert_array_equal(body.omega0, [0.5, -1.0, 0.25])
    assert body.moments.dtype == np.float64 and body.omega0.shape == (3,)
    body.moments[0] = 99.0
    body.omega0[0] = 99.0
    assert body.moments[0] == 3.0 and body.omega0[0] == 0.5
    w0 = np.array([0.1, 0.2, 1.0])
    sym = FreeSymmetricTop(2, 1.5, w0)
    assert sym.I1 == 2.0 and type(sym.I1) is float
    np.testing.assert_array_equal(sym.omega0, [0.1, 0.2, 1.0])
    w0[0] = 99.0  # the top keeps the numbers it was given, not the caller's array
    assert sym.omega0[0] == 0.1 and sym.omega0 is not sym.omega0
    assert math.copysign(1.0, FreeRigidBody([1.0, 2.0, 3.0], [-0.0, 0.0, 2.0]).omega0[0]) == -1.0
