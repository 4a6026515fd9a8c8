"""Generate 40-digit mpmath references for poinsot's special functions.

Writes ``special_jacobi.csv`` (u, m, sn, cn, dn, am) and ``special_integrals.csv``
(kind, phi, n, m, value) next to this script; the Rust tests (crates/poinsot/tests/special.rs)
read them. Every input is a double, written exactly (Python's shortest round-trip repr), and the reference is the
value of the function at that exact double, computed with 40 significant digits and rounded
to the nearest double (printed with 17 significant digits).

Convention: parameter m = k² (mpmath's ``ellipfun(kind, u, m=m)``).

Run:  python python/tests/reference/gen_special.py
"""

from __future__ import annotations

import random
from pathlib import Path

import mpmath as mp

mp.mp.dps = 40
HERE = Path(__file__).resolve().parent


def am_ref(u: mp.mpf, m: mp.mpf) -> mp.mpf:
    """am(u|m), continuous: am(u + 2K) = am(u) + π (m < 1); gd(u) at m = 1."""
    if m == 1:
        return mp.atan(mp.sinh(u))
    if m == 0:
        return u
    k = mp.ellipk(m)
    j = mp.nint(u / (2 * k))
    r = u - 2 * k * j
    return j * mp.pi + mp.atan2(mp.ellipfun("sn", r, m=m), mp.ellipfun("cn", r, m=m))


def jacobi_rows() -> list[tuple[float, float]]:
    rng = random.Random(20240604)
    ms = [0.0, 1e-300, 1e-20, 1e-8, 1e-3, 0.1, 0.3355, 0.5, 0.7, 0.9, 0.99, 0.999999]
    ms += [1.0 - 2.0**-k for k in (10, 20, 30, 40, 45, 52)] + [1.0]
    ms += [rng.random() for _ in range(12)]
    points = []
    for m in ms:
        k = float(mp.ellipk(m)) if m < 1 else 20.0
        us = [
            0.0,
            1e-300,
            1e-10,
            -1e-10,
            1e-3,
            0.3,
            -0.7,
            1.0,
            2.0,
            10.0,
            -57.3,
            100.0,
            1000.0,
            -12345.678,
        ]
        us += [
            k * f
            for f in (
                0.25,
                0.5,
                0.5000001,
                0.9,
                0.999,
                0.999999,
                1.0,
                1.5,
                2.0,
                3.0 + 1e-3,
                4.0,
                40.5,
            )
        ]
        us += [rng.choice((-1, 1)) * 10 ** rng.uniform(-6, 4) for _ in range(10)]
        points += [(u, m) for u in us]
    return points


def main() -> None:
    lines = [
        "# u,m,sn,cn,dn,am   (u and m as Python repr, which round-trips exactly; values 40-digit mpmath rounded to double)"
    ]
    for u, m in jacobi_rows():
        if u == 0.0:
            sn, cn, dn, am = 0.0, 1.0, 1.0, 0.0
        else:
            # mpmath's error is absolute (~10⁻⁴⁰): add the digits a tiny |u| needs.
            extra = max(0, int(-mp.log10(abs(u)))) + 10
            with mp.workdps(40 + extra):
                U, M = mp.mpf(u), mp.mpf(m)
                sn, cn, dn = (mp.ellipfun(kind, U, m=M) for kind in ("sn", "cn", "dn"))
                am = am_ref(U, M)
        vals = ",".join(f"{float(v):.17e}" for v in (sn, cn, dn, am))
        lines.append(f"{u!r},{m!r},{vals}")
    (HERE / "special_jacobi.csv").write_text("\n".join(lines) + "\n")

    rng = random.Random(7)
    rows = ["# kind,phi,n,m,value   (phi, n, m as Python repr; kind K|E|PI|F|EINC|PIINC)"]
    ms = [0.0, 0.1, 0.3355, 0.5, 0.9, 0.999999, 1.0 - 2.0**-30] + [rng.random() for _ in range(5)]
    ns = [-50.0, -3.0, -0.5, 0.0, 0.3, 0.9]
    phis = [0.0, 0.1, 0.7, 1.5, 1.5707963267948966, 2.0, 3.0, -1.2, 10.0]
    for m in ms:
        M = mp.mpf(m)
        rows.append(f"K,0,0,{m!r},{float(mp.ellipk(M)):.17e}")
        rows.append(f"E,0,0,{m!r},{float(mp.ellipe(M)):.17e}")
        for n in ns:
            rows.append(f"PI,0,{n!r},{m!r},{float(mp.ellippi(mp.mpf(n), M)):.17e}")
        for phi in phis:
            P = mp.mpf(phi)
            rows.append(f"F,{phi!r},0,{m!r},{float(mp.ellipf(P, M)):.17e}")
            rows.append(f"EINC,{phi!r},0,{m!r},{float(mp.ellipe(P, M)):.17e}")
            for n in ns:
                rows.append(f"PIINC,{phi!r},{n!r},{m!r},{float(mp.ellippi(mp.mpf(n), P, M)):.17e}")
    (HERE / "special_integrals.csv").write_text("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
