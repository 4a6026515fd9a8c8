"""mpmath references of poinsot's special functions at the edges of the double range.

Writes ``special_edges.csv`` next to this script (read by crates/poinsot/tests/special.rs):

* ``K``, ``E``, ``PI``, ``F``, ``EINC``, ``PIINC`` rows ``kind,phi,n,m,value`` as in
  ``special_integrals.csv``, at huge and subnormal arguments, hugely negative m, m just below
  1, |n| up to 1.8e308 and n > 1 (the principal value: the real part of mpmath's complex
  value). ``value`` is ``ERR:<argument>`` where poinsot must refuse, naming that argument: a
  divergent integral, or one beyond the largest double;
* ``JAC`` rows ``JAC,u,m,sn,cn,dn`` with u up to just below poinsot's limit 2⁵⁰K(m) (and
  ``ERR:u`` beyond it);
* ``JKC`` rows ``JKC,u,kc,sn,cn,dn``: the Jacobi functions for m = 1 − kc² with the
  complementary modulus kc = 1e-200, 1e-300 (1 − m underflows in double precision), from
  K(m) at full precision and the closed forms at m₁ → 0 (DLMF 22.10(ii)), exact to O(kc).

Every input is a double written exactly (Python's repr). Each value (but the JKC rows) is
computed at a working precision sufficient for its inputs (up to 350 digits: a phase of 1e308
needs 310 digits to be reduced by π) and checked against a second evaluation 30 digits
higher; it is then rounded to double.

Run:  python python/tests/reference/gen_special_edges.py
"""

from __future__ import annotations

import math
from pathlib import Path

import mpmath as mp

HERE = Path(__file__).resolve().parent
MAX = 1.7976931348623157e308


def stable(f, digits: int):
    """f() at `digits` and at digits + 30; they must agree to 1e-30 relative."""
    import time

    start = time.perf_counter()
    try:
        return _stable(f, digits)
    finally:
        if time.perf_counter() - start > 5:
            print(f"  slow: {time.perf_counter() - start:.0f} s", flush=True)


def _stable(f, digits: int):
    with mp.workdps(digits):
        a = f()
    with mp.workdps(digits + 30):
        b = f()
    a, b = mp.re(a), mp.re(b)
    with mp.workdps(digits + 30):
        if b != 0:
            assert abs(a - b) <= abs(b) * mp.mpf(10) ** -30, (a, b)
    return b


def digits_for(*xs: float) -> int:
    """Working digits: 40 plus the decimal exponent of the largest |x| (to reduce a phase)."""
    big = max((abs(x) for x in xs if x != 0), default=1.0)
    return 40 + max(0, int(math.log10(big)))


def fmt(v) -> str:
    x = float(v)
    if math.isinf(x):
        raise OverflowError
    return f"{x:.17e}"


def integral_rows() -> list[str]:
    rows = []
    ms = [
        -MAX,
        -1e308,
        -1e200,
        -1e100,
        -1e20,
        -1e10,
        -10.0,
        -1.0,
        -1e-300,
        -5e-324,
        5e-324,
        1e-300,
        0.5,
        1.0 - 2.0**-30,
        1.0 - 2.0**-52,
        1.0 - 2.0**-53,
    ]
    for m in ms:
        M = mp.mpf(m)
        rows.append(f"K,0,0,{m!r},{fmt(stable(lambda: mp.ellipk(M), 60))}")
        rows.append(f"E,0,0,{m!r},{fmt(stable(lambda: mp.ellipe(M), 60))}")
    rows.append("K,0,0,1.0,ERR:m")
    rows.append("E,0,0,1.0,1.00000000000000000e+00")
    ns = [
        -MAX,
        -1e200,
        -1e20,
        -1e5,
        -3.0,
        -5e-324,
        5e-324,
        0.5,
        1.0 - 2.0**-40,
        1.0 + 2.0**-40,
        2.5,
        1e10,
        1e300,
    ]
    for n in ns:
        for m in [-1e300, -1e10, -0.5, 0.0, 0.3, 0.9, 1.0 - 2.0**-40]:
            N, M = mp.mpf(n), mp.mpf(m)
            if n > 1:
                # The principal value by DLMF 19.6.5, Π(n|m) = K(m) − Π(m/n|m): mpmath's own
                # complex quadrature takes minutes here, and at n = 1e300 returns K(m).
                def pv(N=N, M=M):
                    return mp.ellipk(M) - mp.ellippi(M / N, M)

                # K − Π(m/n|m) cancels to ~|m|/n of K: that many more digits.
                extra = max(0, int(math.log10(n) - math.log10(max(abs(m), 1e-300))))
                rows.append(f"PI,0,{n!r},{m!r},{fmt(stable(pv, 80 + extra))}")
            else:
                rows.append(f"PI,0,{n!r},{m!r},{fmt(stable(lambda: mp.ellippi(N, M), 80))}")
    print("complete done", flush=True)
    rows.append("PI,0,1.0,0.5,ERR:n")
    rows.append("PI,0,0.5,1.0,ERR:m")
    phis = [
        5e-324,
        1e-300,
        0.3,
        1.5707963267948966,
        1.6,
        3.0,
        -7.5,
        1e3,
        1e15,
        1.4e16,
        -1e20,
        1e300,
        MAX,
    ]
    for m in [-1e308, -1e100, -1e10, -1.0, 0.0, 5e-324, 0.5, 0.9, 1.0 - 2.0**-40, 1.0]:
        M = mp.mpf(m)
        for phi in phis:
            P = mp.mpf(phi)
            d = digits_for(phi)
            if m == 1.0 and abs(phi) > math.pi / 2:
                rows.append(f"F,{phi!r},0,{m!r},ERR:phi")
            elif m == 1.0:
                # F(φ|1) = asinh(tan φ) (DLMF 19.6.8): mpmath's ellipf is unstable at m = 1
                # next to π/2.
                rows.append(f"F,{phi!r},0,{m!r},{fmt(stable(lambda: mp.asinh(mp.tan(P)), d))}")
            else:
                try:
                    rows.append(f"F,{phi!r},0,{m!r},{fmt(stable(lambda: mp.ellipf(P, M), d))}")
                except OverflowError:
                    rows.append(f"F,{phi!r},0,{m!r},ERR:phi")
            try:
                rows.append(f"EINC,{phi!r},0,{m!r},{fmt(stable(lambda: mp.ellipe(P, M), d))}")
            except OverflowError:
                rows.append(f"EINC,{phi!r},0,{m!r},ERR:phi")
        print(f"F, EINC m = {m} done", flush=True)
    for n in [-MAX, -1e10, -3.0, 0.5, 0.999, 2.5, 1e10]:
        for m in [-1e10, -0.5, 0.3, 0.99, 1.0 - 2.0**-40]:
            N, M = mp.mpf(n), mp.mpf(m)
            for phi in [1e-300, 0.3, 1.2, 1.5707963267948966, 3.0, 1e3, -1e20]:
                # For n > 1 past a pole (sin²φ > 1/n) the principal value: mpmath's real part.
                # Past π/2, Π(n; φ) = Π(n; r) + 2jΠ(n) with φ = jπ + r, |r| ≤ π/2 (DLMF
                # 19.2.10), r reduced at the digits φ needs (mpmath integrates a large φ of
                # n > 1 numerically: minutes per value).
                d = digits_for(phi) + (int(math.log10(n)) + 10 if n > 1 else 0)  # 19.7.9 cancels ~n

                def piinc(phi=phi, N=N, M=M):
                    P = mp.mpf(phi)
                    j = mp.nint(P / mp.pi)
                    r = P - j * mp.pi
                    if N > 1:
                        # The principal value by DLMF 19.7.9 (mpmath's complex quadrature is
                        # minutes per value and unstable here): with ω = m/n,
                        # p = √((n − 1)(1 − ω)), Δ = √(1 − m sin²r),
                        # Π(n; r|m) = F(r|m) − Π(ω; r|m) + ln|(Δ + p tan r)/(Δ − p tan r)|/(2p) (as Re atanh),
                        # and Π(n|m) = K(m) − Π(ω|m) (19.6.5).
                        w = M / N
                        p = mp.sqrt((N - 1) * (1 - w))
                        delta = mp.sqrt(1 - M * mp.sin(r) ** 2)
                        t = mp.tan(r)
                        v = (
                            mp.ellipf(r, M)
                            - mp.ellippi(w, r, M)
                            + mp.re(mp.atanh(p * t / delta)) / p
                        )  # ½ln|(1+x)/(1−x)|
                        whole = mp.ellipk(M) - mp.ellippi(w, M)
                    else:
                        v = mp.ellippi(N, r, M)
                        whole = mp.ellippi(N, M) if j != 0 else 0
                    return v + 2 * j * whole if j != 0 else v

                v = stable(piinc, d)
                rows.append(f"PIINC,{phi!r},{n!r},{m!r},{fmt(v)}")
        print(f"PIINC n = {n} done", flush=True)
    return rows


def jacobi_rows() -> list[str]:
    rows = []
    for m in [1e-300, 0.5, 0.9, 1.0 - 2.0**-30]:
        M = mp.mpf(m)
        with mp.workdps(60):
            k = float(mp.ellipk(M))
        limit = 2.0**50 * k
        for u in [0.999 * limit, -0.7 * limit, 2.0**40 * k + 0.3, 123456789.123]:
            U = mp.mpf(u)
            d = digits_for(u)
            vals = [
                stable(lambda kind=kind: mp.ellipfun(kind, U, m=M), d)
                for kind in ("sn", "cn", "dn")
            ]
            rows.append(f"JAC,{u!r},{m!r}," + ",".join(fmt(v) for v in vals))
        rows.append(f"JAC,{1.001 * limit!r},{m!r},ERR:u")
    for kc in [1e-200, 1e-300]:
        # m = 1 − kc²: mpmath's ellipfun (theta series with the nome → 1) does not finish at
        # the 600+ digits this needs; the functions are instead taken from K (AGM, at full
        # precision) and the forms of DLMF 22.10(ii) at m₁ → 0, exact to O(kc) = 1e-200
        # relative: sn, cn, dn = tanh r, sech r, sech r for |r| ≤ K/2 and, with v = K − |r|,
        # cd v, k' sd v, k' nd v = 1, kc sinh v, kc cosh v beyond (u = 2Kj + r, DLMF 22.4.3).
        digits = 40 + 2 * int(-math.log10(kc))
        with mp.workdps(digits):
            k = mp.ellipk(1 - mp.mpf(kc) ** 2)
        kf = float(k)
        for u in [
            0.5,
            10.0,
            200.0,
            kf - 3.0,
            kf - 1e-9,
            kf,
            kf + 0.7,
            2 * kf - 3.0,
            3.3 * kf,
            -5.5 * kf,
        ]:
            with mp.workdps(60):
                U, K, KC = mp.mpf(u), +k, mp.mpf(kc)
                j = mp.nint(U / (2 * K))
                r = U - 2 * K * j
                a = abs(r)
                if a <= K / 2:
                    sn, cn, dn = mp.tanh(a), mp.sech(a), mp.sech(a)
                else:
                    v = K - a
                    sn, cn, dn = mp.mpf(1), KC * mp.sinh(v), KC * mp.cosh(v)
                if r < 0:
                    sn = -sn
                if int(j) % 2:
                    sn, cn = -sn, -cn
            rows.append(f"JKC,{u!r},{kc!r},{fmt(sn)},{fmt(cn)},{fmt(dn)}")
    return rows


def main() -> None:
    lines = [
        "# kind,phi,n,m,value (K|E|PI|F|EINC|PIINC) | JAC,u,m,sn,cn,dn | JKC,u,kc,sn,cn,dn;"
        " ERR:<argument> where poinsot must refuse naming it"
    ]
    lines += integral_rows()
    lines += jacobi_rows()
    (HERE / "special_edges.csv").write_text("\n".join(lines) + "\n")
    print(len(lines) - 1, "rows")


if __name__ == "__main__":
    main()
