"""40-digit mpmath reference solutions of the torque-free rigid body.

Writes ``free_body.csv`` next to this script: for each case (principal moments, body ω₀,
attitude q₀ as [w, x, y, z] body → space) and time t, the body ω(t) and the attitude q(t)
(sign fixed by w > 0; q₀ is normalised in 40 digits first, as poinsot normalises it), computed with 40 significant digits and rounded to double.

Method (independent of poinsot's code):

* ω(t) from the Jacobi parametrisation (Landau & Lifshitz §37) evaluated with mpmath's
  ``ellipfun``; the sign of the sn term is chosen by, and checked with, the residual of Euler's
  equations (< 1e-30, derivatives by mpmath.diff), and ω(0) = ω₀ is checked;
* the attitude from the direction of L in the body (z-x-z angles θ, ψ with L along space Z)
  and the precession angle φ(t) = ∫ φ̇ dt by mpmath's tanh-sinh quadrature of
  φ̇ = |L| (2T − I_p ω_p²) / (L² − I_p² ω_p²) over whole periods plus the remainder — no
  elliptic integral of the third kind;
* the whole state is checked against mpmath's Taylor-series ODE solver (``odefun``) at t = 1
  (agreement < 1e-25).

Run:  python python/tests/reference/gen_free_body.py   (about a minute)
"""

from __future__ import annotations

from pathlib import Path

import mpmath as mp

mp.mp.dps = 40
HERE = Path(__file__).resolve().parent

CASES = [
    # (name, moments, omega0, q0, times)
    (
        "headline",
        (1.0, 2.0, 3.0),
        (1.0, 0.1, 1.0),
        (1.0, 0.0, 0.0, 0.0),
        (0.0, 0.5, 1.0, 10.0, 100.0, 1000.0),
    ),
    ("below", (1.0, 2.0, 3.0), (1.0, 0.1, 0.2), (1.0, 0.0, 0.0, 0.0), (0.7, 33.0, 1000.0)),
    (
        "near_separatrix",
        (1.0, 2.0, 3.0),
        (1e-3, 1.0, 1.3e-3),
        (1.0, 0.0, 0.0, 0.0),
        (3.0, 17.0, 250.0),
    ),
    ("unsorted", (3.0, 1.0, 2.5), (-0.4, 2.0, 0.9), (0.5, 0.5, -0.5, 0.5), (0.3, 12.5, 999.0)),
    ("flat", (0.5, 1.7, 2.0), (0.2, -1.1, -3.0), (0.8, 0.0, 0.6, 0.0), (1.0, 400.0)),
]


def rot(axis: int, angle: mp.mpf) -> mp.matrix:
    c, s = mp.cos(angle), mp.sin(angle)
    r = mp.eye(3)
    i, j = [(1, 2), (2, 0), (0, 1)][axis]
    r[i, i], r[i, j], r[j, i], r[j, j] = c, -s, s, c
    return r


def quat_to_matrix(q) -> mp.matrix:
    w, x, y, z = q
    return mp.matrix(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]
    )


def matrix_to_quat(r: mp.matrix) -> list:
    tr = r[0, 0] + r[1, 1] + r[2, 2]
    cands = [
        [1 + tr, r[2, 1] - r[1, 2], r[0, 2] - r[2, 0], r[1, 0] - r[0, 1]],
        [r[2, 1] - r[1, 2], 1 + 2 * r[0, 0] - tr, r[0, 1] + r[1, 0], r[0, 2] + r[2, 0]],
        [r[0, 2] - r[2, 0], r[0, 1] + r[1, 0], 1 + 2 * r[1, 1] - tr, r[1, 2] + r[2, 1]],
        [r[1, 0] - r[0, 1], r[0, 2] + r[2, 0], r[1, 2] + r[2, 1], 1 + 2 * r[2, 2] - tr],
    ]
    q = max(cands, key=lambda c: abs(c[cands.index(c)]))
    n = mp.sqrt(sum(c * c for c in q))
    q = [c / n for c in q]
    return [-c for c in q] if q[0] < 0 else q


class Exact:
    """The elliptic solution in the sorted frame (I1 < I2 < I3), mapped back."""

    def __init__(self, moments, omega0, q0):
        order = sorted(range(3), key=lambda k: moments[k])
        self.order = order
        P = mp.zeros(3, 3)
        for i, a in enumerate(order):
            P[i, a] = 1
        if mp.det(P) < 0:
            P[2, :] = -P[2, :]
        self.P = P
        I = [mp.mpf(moments[a]) for a in order]
        w = P * mp.matrix([mp.mpf(v) for v in omega0])
        self.I = I
        T2 = sum(I[k] * w[k] ** 2 for k in range(3))
        L2 = sum((I[k] * w[k]) ** 2 for k in range(3))
        self.T2, self.L = T2, mp.sqrt(L2)
        _I1, I2, _I3 = I
        if L2 > T2 * I2:
            p, o = 2, 0
        else:
            p, o = 0, 2
        self.p, self.o = p, o
        Ip, Io = I[p], I[o]
        # Amplitudes and rates in the generic labels (o, 2, p).
        self.wo = mp.sqrt((T2 * Ip - L2) / (Io * (Ip - Io)))
        self.w2 = mp.sqrt((T2 * Ip - L2) / (I2 * (Ip - I2)))
        self.wp = mp.sqrt((L2 - T2 * Io) / (Ip * (Ip - Io)))
        self.lam = mp.sqrt((Ip - I2) * (L2 - T2 * Io) / (Io * I2 * Ip))
        self.m = (I2 - Io) * (T2 * Ip - L2) / ((Ip - I2) * (L2 - T2 * Io))
        sp = 1 if w[p] > 0 else -1
        self.sp = sp
        # The sign of the sn term: the one for which ω(t) satisfies Euler's equations.
        for s2 in (1, -1):
            self.s2 = s2
            phi0 = mp.atan2(w[1] / (s2 * self.w2), w[o] / self.wo)
            self.tau0 = mp.ellipf(phi0, self.m)
            if self.euler_residual(mp.mpf("0.3")) < mp.mpf(10) ** -30:
                break
        else:
            raise AssertionError("no sign of the sn term solves Euler's equations")
        self.K = mp.ellipk(self.m)
        self.period = 4 * self.K / self.lam
        qn = mp.sqrt(sum(mp.mpf(c) ** 2 for c in q0))
        self.q0 = [mp.mpf(c) / qn for c in q0]
        assert mp.norm(self.omega_sorted(0) - w) < mp.mpf(10) ** -35, "omega0 not reproduced"
        assert self.euler_residual(mp.mpf(7)) < mp.mpf(10) ** -30, "Euler's equations not solved"
        self.phi_period = self._phi_integral(0, self.period)

    def omega_sorted(self, t):
        tau = self.lam * t + self.tau0
        sn, cn, dn = (mp.ellipfun(k, tau, m=self.m) for k in ("sn", "cn", "dn"))
        w = mp.matrix(3, 1)
        w[self.o] = self.wo * cn
        w[1] = self.s2 * self.w2 * sn
        w[self.p] = self.sp * self.wp * dn
        return w

    def euler_residual(self, t):
        """max |I ω̇ − (I − I) ω ω| of Euler's equations (2.72) at t (sorted frame)."""
        w = self.omega_sorted(t)
        dw = [mp.diff(lambda x, k=k: self.omega_sorted(x)[k], t) for k in range(3)]
        I = self.I
        res = [
            I[0] * dw[0] - (I[1] - I[2]) * w[1] * w[2],
            I[1] * dw[1] - (I[2] - I[0]) * w[2] * w[0],
            I[2] * dw[2] - (I[0] - I[1]) * w[0] * w[1],
        ]
        return max(abs(r) for r in res)

    def phidot(self, t):
        w = self.omega_sorted(t)
        p, I = self.p, self.I
        return self.L * (self.T2 - I[p] * w[p] ** 2) / (self.L**2 - (I[p] * w[p]) ** 2)

    def _phi_integral(self, a, b):
        n = 16
        pts = [a + (b - a) * k / n for k in range(n + 1)]
        return mp.quad(self.phidot, pts)

    def phi(self, t):
        k = mp.floor(t / self.period)
        return k * self.phi_period + self._phi_integral(k * self.period, t) if t > 0 else mp.mpf(0)

    def l_frame(self, t):
        """The rotation (user body → L-frame) without the precession: C(t) · W · P."""
        w = self.omega_sorted(t)
        l = [self.I[k] * w[k] for k in range(3)]
        axes = [0, 1, 2] if self.p == 2 else [1, 2, 0]
        W = mp.zeros(3, 3)
        for i, a in enumerate(axes):
            W[i, a] = 1
        lw = mp.matrix([l[a] for a in axes])
        lw = lw / mp.norm(lw)
        rho = mp.sqrt(lw[0] ** 2 + lw[1] ** 2)
        a, b = lw[1] / rho, lw[0] / rho
        C = mp.matrix([[a, -b, 0], [lw[2] * b, lw[2] * a, -rho], [lw[0], lw[1], lw[2]]])
        return C * W * self.P

    def state(self, t):
        t = mp.mpf(t)
        w = self.P.T * self.omega_sorted(t)
        R0 = quat_to_matrix(self.q0)
        R = R0 * self.l_frame(0).T * rot(2, self.phi(t)) * self.l_frame(t)
        return w, R


def odefun_check(ex: Exact, moments, omega0, q0, t_check=1):
    """The state at t_check by mpmath's Taylor ODE solver, in the user's body axes."""
    I = [mp.mpf(v) for v in moments]

    def f(_t, y):
        w1, w2, w3, qw, qx, qy, qz = y
        return [
            (I[1] - I[2]) * w2 * w3 / I[0],
            (I[2] - I[0]) * w3 * w1 / I[1],
            (I[0] - I[1]) * w1 * w2 / I[2],
            -(qx * w1 + qy * w2 + qz * w3) / 2,
            (qw * w1 + qy * w3 - qz * w2) / 2,
            (qw * w2 + qz * w1 - qx * w3) / 2,
            (qw * w3 + qx * w2 - qy * w1) / 2,
        ]

    with mp.workdps(45):
        qn = mp.sqrt(sum(mp.mpf(c) ** 2 for c in q0))
        sol = mp.odefun(f, 0, [mp.mpf(v) for v in omega0] + [mp.mpf(c) / qn for c in q0])
        y = sol(t_check)
    w, R = ex.state(t_check)
    q = matrix_to_quat(R)
    qn = y[3:]
    if qn[0] < 0:
        qn = [-c for c in qn]
    err = max(max(abs(w[k] - y[k]) for k in range(3)), max(abs(q[k] - qn[k]) for k in range(4)))
    assert err < mp.mpf(10) ** -25, f"odefun disagrees: {err}"
    return err


def main() -> None:
    rows = ["# case,I1,I2,I3,w1,w2,w3,qw,qx,qy,qz,t,w1(t),w2(t),w3(t),qw(t),qx(t),qy(t),qz(t)"]
    for name, moments, omega0, q0, times in CASES:
        n = mp.sqrt(sum(mp.mpf(c) ** 2 for c in q0))
        q0n = [float(mp.mpf(c) / n) for c in q0]
        ex = Exact(moments, omega0, q0n)
        err = odefun_check(ex, moments, omega0, q0n)
        print(
            f"{name}: m = {mp.nstr(ex.m, 8)}, period = {mp.nstr(ex.period, 8)}, odefun check {mp.nstr(err, 3)}"
        )
        for t in times:
            w, R = ex.state(t)
            q = matrix_to_quat(R)
            vals = [*w, *q]
            head = ",".join(repr(float(v)) for v in (*moments, *omega0, *q0n, t))
            rows.append(f"{name},{head}," + ",".join(f"{float(v):.17e}" for v in vals))
    (HERE / "free_body.csv").write_text("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
