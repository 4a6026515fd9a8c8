"""poinsot.special against scipy and mpmath."""

from __future__ import annotations

import mpmath as mp
import numpy as np
import pytest
import scipy.special as sc
from poinsot import PoinsotError, special

#: scipy's ellipj is accurate to ~1e-15 for moderate m; ours to a few ulp.
SCIPY_TOL = 5e-15


@pytest.mark.parametrize("m", [0.0, 0.1, 0.5, 0.9])
def test_jacobi_matches_scipy(m):
    u = np.linspace(-20, 20, 401)
    sn, cn, dn, am = special.jacobi(u, m)
    ssn, scn, sdn, sph = sc.ellipj(u, m)
    np.testing.assert_allclose(sn, ssn, atol=SCIPY_TOL * 10)
    np.testing.assert_allclose(cn, scn, atol=SCIPY_TOL * 10)
    np.testing.assert_allclose(dn, sdn, atol=SCIPY_TOL * 10)
    np.testing.assert_allclose(am, sph, atol=1e-13)


def test_jacobi_near_m_one_matches_mpmath():
    m = 1 - 2.0**-40
    u = np.array([0.5, 3.0, 10.0, 14.7])
    sn, cn, dn, _ = special.jacobi(u, m)
    mp.mp.dps = 40
    for k, x in enumerate(u):
        for got, kind in ((sn[k], "sn"), (cn[k], "cn"), (dn[k], "dn")):
            want = float(mp.ellipfun(kind, x, m=m))
            assert got == pytest.approx(want, rel=1e-14), (kind, x)


def test_integrals_match_scipy():
    assert special.ellipk(0.3) == pytest.approx(sc.ellipk(0.3), rel=1e-15)
    assert special.ellipe(0.3) == pytest.approx(sc.ellipe(0.3), rel=1e-15)
    assert special.ellipf(1.1, 0.3) == pytest.approx(sc.ellipkinc(1.1, 0.3), rel=1e-15)
    assert special.ellipeinc(1.1, 0.3) == pytest.approx(sc.ellipeinc(1.1, 0.3), rel=1e-15)
    mp.mp.dps = 30
    assert special.ellippiinc(1.1, -2.0, 0.3) == pytest.approx(
        float(mp.ellippi(-2.0, 1.1, 0.3)), rel=1e-14
    )
    assert special.ellippi(-2.0, 0.3) == pytest.approx(float(mp.ellippi(-2.0, 0.3)), rel=1e-14)


def test_bad_parameters_are_named():
    with pytest.raises(PoinsotError, match="^m: "):
        special.jacobi([1.0], 1.5)
    with pytest.raises(PoinsotError, match="^u: "):
        special.jacobi([np.nan], 0.5)
    with pytest.raises(PoinsotError, match="^n: "):
        special.ellippi(1.0, 0.5)


# --- The edges of the double range (issue 10, item 4.13) ---------------------------------------


@pytest.mark.parametrize(
    ("fn", "args", "ref"),
    [
        # "phi: ellipf: Unexpected error" from the ellip crate before.
        (special.ellipf, (0.5, -1e308), lambda: mp.ellipf(0.5, -1e308)),
        (special.ellipeinc, (1e308, 0.5), lambda: mp.ellipe(mp.mpf(1e308), 0.5)),
        (special.ellippiinc, (1e308, 0.3, 0.5), lambda: mp.ellippi(0.3, mp.mpf(1e308), 0.5)),
        # 0.0 before (the answer is 3.5e-152).
        (special.ellippi, (0.3, -1e308), lambda: mp.ellippi(0.3, -1e308)),
        (special.ellipk, (-1.7976931348623157e308,), lambda: mp.ellipk(-1.7976931348623157e308)),
        (special.ellippi, (-1e300, 0.9), lambda: mp.ellippi(-1e300, 0.9)),
        (special.ellippi, (2.5, 0.3), lambda: mp.re(mp.ellippi(2.5, 0.3))),
    ],
)
def test_integrals_at_the_edges_match_mpmath(fn, args, ref):
    # A phase of 1e308 needs 310 digits to be reduced by π; 40 do otherwise.
    with mp.workdps(350 if max(abs(a) for a in args) > 1e100 else 40):
        want = float(ref())
    assert fn(*args) == pytest.approx(want, rel=1e-14)


@pytest.mark.parametrize(
    ("fn", "args", "name"),
    [
        (special.ellipk, (1.0,), "m"),
        (special.ellippi, (0.5, 1.0), "m"),
        (special.ellipf, (2.0, 1.0), "phi"),
        (special.ellipeinc, (1e308, -1e308), "phi"),
    ],
)
def test_divergent_or_unrepresentable_integrals_name_the_argument(fn, args, name):
    with pytest.raises(PoinsotError, match=f"^{name}: "):
        fn(*args)


def test_jacobi_refuses_arguments_past_its_limit():
    # 2^50 K(m): beyond, consecutive doubles are more than K/8 apart.
    with pytest.raises(PoinsotError, match="^u: "):
        special.jacobi([0.5, 1e300], 0.5)
    sn, cn, dn, _ = special.jacobi([1e300], 1.0)
    assert sn[0] == 1.0 and cn[0] == 0.0 and dn[0] == 0.0
