"""mpmath references of the torque-free rigid body at the edges of its range.

Writes ``free_body_edges.csv`` next to this script, in the format of ``free_body.csv`` with one
more column, the digits of working precision used:

* ``far``: the headline state (I = (1, 2, 3), ω₀ = (1, 0.1, 1)) at t = 1e6, 1e9 and 1.3e12 s
  (just inside poinsot's time limit, where the body has turned through ~4e12 rad), at 60
  digits: the phase accuracy at long times;
* ``hair_*``: spin about the intermediate axis perturbed by 1e-170 to 1e-300 (relative) along
  the other axes, at 400–700 digits (1 − m ≈ 1e-340 … 1e-600, beyond what a double holds):
  the Dzhanibekov flips of a body a hair's breadth off the unstable axis, at times before,
  during and after the first flip (all within the first period, so the precession angle is
  one quadrature from 0 to t).

Method: the same independent solution as ``gen_free_body.py`` (its ``Exact`` class: mpmath's
Jacobi functions checked against Euler's equations, the precession angle by tanh-sinh
quadrature of φ̇, no elliptic integral of the third kind), run at the precision the case needs.

Run:  python python/tests/reference/gen_free_body_edges.py [case ...]   (tens of minutes; the
named cases only, replacing their rows, when given)
"""

from __future__ import annotations

import sys
from pathlib import Path

import mpmath as mp

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from gen_free_body import Exact, matrix_to_quat  # noqa: E402

CASES = [
    # (name, digits, moments, omega0, q0, times)
    ("far", 60, (1.0, 2.0, 3.0), (1.0, 0.1, 1.0), (1.0, 0.0, 0.0, 0.0), (1e6, 1e9, 1.3e12)),
    (
        "hair_above",
        400,
        (1.0, 2.0, 3.0),
        (1e-170, 1.0, 1e-170),
        (1.0, 0.0, 0.0, 0.0),
        (60.0, 400.0, 680.0, 1000.0),
    ),
    (
        "hair_below",
        450,
        (1.0, 2.0, 3.0),
        (1e-200, 1.0, 0.0),
        (0.5, 0.5, 0.5, 0.5),
        (120.0, 800.0, 1500.0),
    ),
    ("hair_max", 700, (1.0, 2.0, 3.0), (0.0, -1.0, 1e-300), (1.0, 0.0, 0.0, 0.0), (790.0, 1190.0)),
]
HEADER = "# case,I1,I2,I3,w1,w2,w3,qw,qx,qy,qz,t,w1(t),w2(t),w3(t),qw(t),qx(t),qy(t),qz(t),digits"
OUT = HERE / "free_body_edges.csv"


class Hair(Exact):
    """Exact next to the separatrix (1 − m ≈ 1e-340 and below): mpmath's ellipfun (a theta
    series whose nome tends to 1) does not finish at the digits such an m needs, so ω(t) is
    taken from K(m) (AGM, at full precision) and the closed forms of DLMF 22.10(ii) at
    m₁ = k'² → 0, exact to O(k') relative: sn, cn, dn = tanh r, sech r, sech r for |r| ≤ K/2,
    and cd v, k' sd v, k' nd v = 1, k' sinh v, k' cosh v with v = K − |r| beyond (τ = 2Kj + r,
    DLMF 22.4.3). The constructor (m, τ₀ by mpmath's ellipf, the check of Euler's equations)
    runs at the case's digits; the precession angle is one quadrature from 0 to t (all times lie
    within the first period) at 50 digits, which is all φ̇ needs once τ₀, K and k' are known."""

    def __init__(self, *args):
        self._kc = None
        super().__init__(*args)

    def jacobi(self, tau):
        if self._kc is None:
            self._kc = mp.sqrt(1 - self.m)
            self._K = mp.ellipk(self.m)
        K, kc = +self._K, +self._kc
        j = mp.nint(tau / (2 * K))
        r = tau - 2 * K * j
        a = abs(r)
        if a <= K / 2:
            sn, cn, dn = mp.tanh(a), mp.sech(a), mp.sech(a)
        else:
            v = K - a
            sn, cn, dn = mp.mpf(1), kc * mp.sinh(v), kc * mp.cosh(v)
        if r < 0:
            sn = -sn
        if int(j) % 2:
            sn, cn = -sn, -cn
        return sn, cn, dn

    def omega_sorted(self, t):
        tau = self.lam * t + self.tau0
        sn, cn, dn = self.jacobi(tau)
        w = mp.matrix(3, 1)
        w[self.o] = self.wo * cn
        w[1] = self.s2 * self.w2 * sn
        w[self.p] = self.sp * self.wp * dn
        return w

    def _phi_integral(self, a, b):
        if getattr(self, "_skip", True):
            return mp.mpf(0)
        with mp.workdps(50):
            return super()._phi_integral(a, b)

    def phi(self, t):
        assert 0 < t < self.period, "only within the first period"
        self._skip = False
        try:
            return self._phi_integral(mp.mpf(0), t)
        finally:
            self._skip = True


def case_rows(name, digits, moments, omega0, q0, times) -> list[str]:
    rows = []
    with mp.workdps(digits):
        ex = (Exact if name == "far" else Hair)(moments, omega0, q0)
        print(
            f"{name}: 1 - m = {mp.nstr(1 - ex.m, 5)}, period = {mp.nstr(ex.period, 8)}", flush=True
        )
        for t in times:
            w, R = ex.state(t)
            q = matrix_to_quat(R)
            head = ",".join(repr(float(v)) for v in (*moments, *omega0, *q0, t))
            rows.append(
                f"{name},{head}," + ",".join(f"{float(v):.17e}" for v in (*w, *q)) + f",{digits}"
            )
            print(f"  t = {t}: ω = {[mp.nstr(v, 8) for v in w]}", flush=True)
    return rows


def main() -> None:
    wanted = set(sys.argv[1:]) or {c[0] for c in CASES}
    old = OUT.read_text().splitlines()[1:] if OUT.exists() else []
    keep = [r for r in old if r and r.split(",", 1)[0] not in wanted]
    for case in CASES:
        if case[0] in wanted:
            keep += case_rows(*case)
            OUT.write_text("\n".join([HEADER, *keep]) + "\n")


if __name__ == "__main__":
    main()
