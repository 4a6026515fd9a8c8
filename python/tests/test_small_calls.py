"""The fast paths of small calls (issue 15, "Small calls from Python"): a plain number ``t``, a
list or tuple of plain numbers, a float64 array (3,) skip the general conversion
(``as_float_array``, arrays of times, reshapes) — and must change nothing but the time.

References: the general path itself, forced by switching the fast paths off
(:func:`general_path`), compared outcome for outcome — the same numbers bit for bit, or the
same exception with the same message — over valid and adversarial inputs; and the array entry
points of the binding, whose first row is the scalar call's answer. A negative control shows
the comparison catches a fast path that accepts what the general path refuses."""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

import numpy as np
import pytest
from poinsot import FreeRigidBody, FreeSymmetricTop, HeavyTop, _core, _validate, free, top
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

#: Scalar times of each plain kind the fast path takes (float, int, numpy float64, −0).
PLAIN_TIMES = [0.0, -0.0, 0.7316, -3.5, 1000.0, 7, -2, np.float64(2.5), 123456.789]


class _Float(float):
    """A float subclass: not a plain float (the general path converts it)."""


#: Inputs for one argument: valid ones of every form, and what the fuzz suite throws.
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
VECTORS = [
    [1.0, 0.1, 1.0],
    (1.0, 0.1, 1.0),
    [1, 0, 2],
    [np.float64(1.0), 0.1, 1],
    np.array([1.0, 0.1, 1.0]),
    np.array([1, 0, 2]),
    np.array([1.0, 0.1, 1.0], dtype=np.float32),
    np.arange(6.0)[::2],
    np.array([1.0, 0.1, 1.0], dtype=">f8"),
    np.array([1.0, 0.1, 1.0]).view(np.recarray),
    np.ma.masked_array([1.0, 0.1, 1.0], mask=[False, True, False]),
    [_Float(1.0), 0.1, 1.0],
    [1.0, 0.1, 1.0, 1.0][:3],
    [-0.0, 0.0, 2.0],
    [1e308, 1e308, 1e308],
    [1.0, math.nan, 1.0],
    (math.inf, 0.0, 1.0),
    np.array([1.0, math.nan, 1.0]),
    [1.0, True, 1.0],
    [1.0, 2.0],
    [1.0, 2.0, 3.0, 4.0],
    [[1.0, 2.0, 3.0]],
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


@contextmanager
def general_path() -> Iterator[None]:
    """Switch the fast paths off (every call then takes the general conversion, the code path
    that was there before them)."""
    mp = pytest.MonkeyPatch()
    none: Callable[[Any], None] = lambda value: None
    for module in (_validate, free, top):
        if hasattr(module, "plain_float"):
            mp.setattr(module, "plain_float", none)
    mp.setattr(_validate, "_plain_triple", none)
    mp.setattr(free, "_free_body_from_plain", lambda moments, omega0: None)
    try:
        yield
    finally:
        mp.undo()


def outcome(call: Callable[[], Any]) -> tuple[Any, ...]:
    """What ``call`` does: ("ok", type and bytes of each number it returns) or ("raises", the
    exception's type and message)."""
    try:
        result = call()
    except Exception as exc:  # any exception is an outcome to compare
        return ("raises", type(exc), str(exc))
    return ("ok", _bits(result))


def _bits(value: Any) -> Any:
    if isinstance(value, tuple):
        return tuple(_bits(v) for v in value)
    if isinstance(value, np.ndarray):
        return ("array", value.dtype.str, value.shape, value.tobytes())
    if isinstance(value, float):
        return ("float", np.float64(value).tobytes())
    if isinstance(value, FreeRigidBody | FreeSymmetricTop | HeavyTop):
        return repr(value)
    return value


def same_either_way(call: Callable[[], Any]) -> tuple[Any, ...]:
    """``call``'s outcome, asserted equal with the fast paths on and off."""
    fast = outcome(call)
    with general_path():
        general = outcome(call)
    assert fast == general
    return fast


# ---- the fast paths give the general path's numbers -------------------------------------


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
        same_either_way(lambda t=t: body.state(t))


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
            same_either_way(lambda t=t, method=method: method(t))


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
                same_either_way(lambda t=t, method=method: method(t, degrees=degrees))


# ---- and the general path's errors -----------------------------------------------------


@pytest.mark.parametrize("value", ADVERSARIAL + VECTORS, ids=repr)
def test_free_body_arguments_fast_or_general_same_outcome(value: Any) -> None:
    same_either_way(lambda: FreeRigidBody(value, [1.0, 0.1, 1.0]).state(0.5))
    same_either_way(lambda: FreeRigidBody([1.0, 2.0, 3.0], value).state(0.5))
    body = FreeRigidBody([1.0, 2.0, 3.0], [1.0, 0.1, 1.0])
    same_either_way(lambda: body.state(value))
    same_either_way(lambda: FreeSymmetricTop(1.0, 0.5, value).attitude(0.5))
    same_either_way(lambda: FreeSymmetricTop(value, 0.5, [1.0, 0.1, 1.0]).omega(0.5))


@pytest.mark.parametrize("value", ADVERSARIAL, ids=repr)
def test_heavy_top_arguments_fast_or_general_same_outcome(value: Any) -> None:
    same_either_way(lambda: HeavyTop(value, 0.5, 1.0, 0.8, psi_dot=6.0).euler_angles(1.0))
    same_either_way(lambda: HeavyTop(1.0, 0.5, 1.0, value, psi_dot=6.0).euler_angles(1.0))
    same_either_way(lambda: HeavyTop(1.0, 0.5, 1.0, 0.8, psi_dot=value).euler_rates(1.0))
    ht = HeavyTop(1.0, 0.5, 1.0, 0.8, psi_dot=6.0)
    same_either_way(lambda: ht.euler_angles(value))
    same_either_way(lambda: ht.euler_angles(value, degrees=True))
    same_either_way(lambda: ht.euler_angles(1.0, degrees=value))


def test_bad_scalar_t_still_raises_naming_t() -> None:
    body = FreeRigidBody([1.0, 2.0, 3.0], [1.0, 0.1, 1.0])
    for bad in (math.nan, math.inf, "1.0", True, 1e300):
        with pytest.raises((PoinsotError, TypeError), match=r"^t:"):
            body.state(bad)
    ht = HeavyTop(1.0, 0.5, 1.0, 0.8, psi_dot=6.0)
    for bad in (math.nan, 1e300):
        with pytest.raises(PoinsotError, match=r"^t:"):
            ht.euler_angles(bad)


def test_the_comparison_catches_a_fast_path_that_accepts_booleans() -> None:
    """Negative control: a fast path that took ``True`` for 1.0 (bool is an int subclass)
    answers where the general path refuses, and :func:`same_either_way` fails."""
    body = FreeRigidBody([1.0, 2.0, 3.0], [1.0, 0.1, 1.0])
    mp = pytest.MonkeyPatch()
    mp.setattr(free, "plain_float", lambda v: float(v) if isinstance(v, int | float) else None)
    try:
        with pytest.raises(AssertionError):
            same_either_way(lambda: body.state(True))
    finally:
        mp.undo()
    assert same_either_way(lambda: body.state(True))[0] == "raises"


# ---- the helpers themselves ------------------------------------------------------------


def test_plain_float_takes_only_plain_finite_numbers() -> None:
    pf = _validate.plain_float
    assert pf(0.5) == 0.5 and type(pf(np.float64(0.5))) is float
    assert pf(3) == 3.0 and type(pf(3)) is float and pf(2**1023) == 2.0**1023
    assert math.copysign(1.0, pf(-0.0)) == -1.0
    for refused in (
        math.nan,
        math.inf,
        True,
        np.bool_(True),
        2**1024,
        np.float32(0.5),
        np.int64(1),
        "1",
        None,
        1 + 0j,
        np.array(0.5),
    ):
        assert pf(refused) is None, refused


def test_finite_check_of_small_and_large_arrays_agrees_with_numpy() -> None:
    rng = np.random.default_rng(3)
    for size in (1, 3, 8, 9, 50):
        for bad in (math.nan, math.inf, -math.inf, None):
            a = rng.standard_normal(size)
            if bad is None:
                assert _validate._finite(a, "x") is a
                continue
            k = int(rng.integers(size))
            a[k] = bad
            first = a[~np.isfinite(a)].ravel()[0]
            with pytest.raises(PoinsotError, match=rf"^x: must be finite, got {first}$"):
                _validate._finite(a, "x")
    scalar = np.array(math.inf)
    with pytest.raises(PoinsotError, match="^x: must be finite, got inf$"):
        _validate._finite(scalar, "x")


def test_as_float_array_still_copies_what_it_does_not_own() -> None:
    """Only lists, tuples and Python scalars skip the ``astype`` copy (``np.asarray`` made
    their array); an object lending its own float64 buffer through ``__array__`` is copied,
    as before."""
    buf = np.array([1.0, 2.0, 3.0])

    class Lender:
        def __array__(self, dtype: Any = None, copy: Any = None) -> np.ndarray:
            return buf

    out = _validate.as_float_array(Lender(), "x")
    assert not np.shares_memory(out, buf)
    lst = [1.0, 2.0, 3.0]
    np.testing.assert_array_equal(_validate.as_float_array(lst, "x"), lst)


def test_as_triple_and_as_vector3_agree_with_the_general_conversion() -> None:
    for value in VECTORS:
        fast = outcome(lambda value=value: _validate.as_triple(value, "v"))
        fast3 = outcome(lambda value=value: _validate.as_vector3(value, "v"))
        with general_path():
            general = outcome(lambda value=value: _validate.as_triple(value, "v"))
            general3 = outcome(lambda value=value: _validate.as_vector3(value, "v"))
        assert fast == general, value
        assert fast3 == general3, value
        if fast[0] == "ok":
            assert all(type(x) is float for x in _validate.as_triple(value, "v"))


def test_moments_and_omega0_are_the_inputs_in_new_arrays() -> None:
    body = FreeRigidBody((3, 1, 2), np.array([0.5, -1.0, 0.25]))
    np.testing.assert_array_equal(body.moments, [3.0, 1.0, 2.0])
    np.testing.assert_array_equal(body.omega0, [0.5, -1.0, 0.25])
    assert body.moments.dtype == np.float64 and body.omega0.shape == (3,)
    body.moments[0] = 99.0
    body.omega0[0] = 99.0
    assert body.moments[0] == 3.0 and body.omega0[0] == 0.5
    sym = FreeSymmetricTop(2, 1.5, (0.1, 0.2, 1))
    assert sym.I1 == 2.0 and type(sym.I1) is float
    np.testing.assert_array_equal(sym.omega0, [0.1, 0.2, 1.0])


# ---- the binding's entry points --------------------------------------------------------


def test_binding_takes_tuples_or_arrays_and_names_the_argument() -> None:
    a = _core.FreeBodySolution((1.0, 2.0, 3.0), (1.0, 0.1, 1.0))
    b = _core.FreeBodySolution(np.array([1.0, 2.0, 3.0]), np.array([1.0, 0.1, 1.0]))
    t = np.array([0.5, 3.0])
    for x, y in zip(a.state(t), b.state(t), strict=True):
        assert x.tobytes() == y.tobytes()
    w, q = a.state_at(3.0)
    assert w.tobytes() == a.state(t)[0][1].tobytes() and q.tobytes() == a.state(t)[1][1].tobytes()
    cases = [
        (((1.0, 2.0), (1.0, 0.1, 1.0)), r"^moments: must have shape \(3,\), got \(2,\)"),
        (((1.0, 2.0, 3.0), ("a", 0.1, 1.0)), "^omega0: must be three real numbers"),
        (((1.0, 2.0, 3.0), [1.0, 0.1, 1.0]), "^omega0: must be a float64 array"),
        (((1.0, 2.0, 3.0), np.array([1, 0, 1])), "^omega0: must be a float64 array"),
        ((np.zeros(4), (1.0, 0.1, 1.0)), r"^moments: must have shape \(3,\)"),
    ]
    for args, message in cases:
        with pytest.raises(PoinsotError, match=message):
            _core.FreeBodySolution(*args)
    with pytest.raises(PoinsotError, match="^omega0:"):
        _core.SymmetricTopSolution(1.0, 0.5, (1.0, 0.1))
    for bad in (math.nan, math.inf, 1e300):
        with pytest.raises(PoinsotError, match="^t:"):
            a.state_at(bad)
    ht = _core.HeavyTopCore.from_state(1.0, 0.5, 1.0, 0.0, 0.8, 0.0, 0.0, 0.0, 6.0)
    with pytest.raises(PoinsotError, match="^t:"):
        ht.euler_angles_at(math.nan)


def test_binding_reads_plain_vectors_and_declines_the_rest() -> None:
    """``FreeBodySolution.from_plain`` builds the body only from three exact, finite Python
    floats (list or tuple) or a contiguous float64 ndarray (3,); for anything else it returns
    None and the Python layer converts. Reference: the constructor on the same numbers."""
    plain = [
        [1.0, 2.0, 3.0],
        (1.0, 2.0, 3.0),
        np.array([1.0, 2.0, 3.0]),
    ]
    w0 = (1.0, 0.1, 1.0)
    ref = _core.FreeBodySolution((1.0, 2.0, 3.0), w0)
    t = np.array([0.0, 2.5, 100.0])
    for m in plain:
        body = _core.FreeBodySolution.from_plain(m, w0)
        assert body is not None
        for x, y in zip(body.state(t), ref.state(t), strict=True):
            assert x.tobytes() == y.tobytes()
        assert body.moments.tobytes() == np.array([1.0, 2.0, 3.0]).tobytes()
    declined = [
        [1, 2, 3],
        [1.0, 2.0, True],
        [1.0, 2.0, np.float64(3.0)],
        [1.0, 2.0, _Float(3.0)],
        [1.0, 2.0, math.inf],
        (1.0, math.nan, 3.0),
        np.array([1.0, math.nan, 3.0]),
        [1.0, 2.0],
        (1.0, 2.0, 3.0, 4.0),
        np.arange(6.0)[::2],
        np.array([1.0, 2.0, 3.0], dtype=np.float32),
        np.array([1.0, 2.0, 3.0], dtype=">f8"),
        np.array([1.0, 2.0, 3.0]).view(np.recarray),
        np.array([[1.0, 2.0, 3.0]]),
        "abc",
        None,
        3.0,
    ]
    for m in declined:
        assert _core.FreeBodySolution.from_plain(m, w0) is None, m
        assert _core.FreeBodySolution.from_plain(w0, m) is None, m
    # The core's own errors come through (plain numbers, impossible body).
    with pytest.raises(PoinsotError, match="^moments:"):
        _core.FreeBodySolution.from_plain([1.0, 1.0, 5.0], w0)
    with pytest.raises(PoinsotError, match="^omega0:"):
        _core.FreeBodySolution.from_plain([1.0, 2.0, 3.0], [0.0, 0.0, 0.0])
