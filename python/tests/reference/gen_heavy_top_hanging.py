"""Reference trajectories of the heavy symmetric top next to the hanging pole (theta0 = pi - delta,
delta from one ulp of pi up to 1e-3) by a high-precision integration of its Lagrangian.

The mirror of ``gen_heavy_top_upright.py`` for the other pole (issue 21, item 1). Near theta = pi
the distance from the pole is carried by 1 + cos(theta) = 2 cos^2(theta/2) ~ delta^2/2, 1e-32 at
delta = 1e-16: any formula that forms it by subtraction loses every digit (in double precision the
top released at pi - 1e-8 read as steady precession, its nutation of 2.4e-9 rad lost in
1 - cos(theta) rounded to 2). The reference is independent of poinsot: the Euler-Lagrange
equations of the unit's Lagrangian 2.102 (as in ``gen_heavy_top.py``), written in the distance
from the pole chi = pi - theta, so that chi keeps its own relative precision however small it is
(sin th = sin chi, cos th = -cos chi, th' = -chi'; w3 = ps' - ph' cos chi):

    chi'' = (I1 ph'^2 sin chi cos chi + I3 w3 ph' sin chi - mgl sin chi) / I1
    ph''  = -chi' (I3 w3 + 2 I1 ph' cos chi) / (I1 sin chi)
    ps''  = ph'' cos chi - ph' chi' sin chi

integrated by mpmath's Taylor-series ODE solver (``mpmath.odefun``) at ``DPS`` = 30 significant
digits (chi ~ 5.7e-16 then still carries 30 digits), from initial conditions that are exactly the
double-precision numbers the tests pass to poinsot (theta0 a double; chi0 = pi - theta0 at 30
digits). p_phi, p_psi and E are checked to drift by less than 1e-20 of their terms along the integration.

Cases (I1 = 1, I3 = 0.5, m g l = 1; delta = pi - theta0 as the double theta0 gives it):

* ``cusps_*``: released at rest in phi with psi_dot = 1 rad/s (the issue's example), delta = 1e-3,
  1e-6, 1e-7, 1e-8, 1e-10, 1e-12, 1e-14 and one ulp (theta0 the largest double below pi);
  the other cases at delta = 1e-3, 1e-8 and one ulp:
* ``fast_cusps_*``, ``back_cusps_*``: spin omega3 = 8 rad/s, and psi_dot = -1 rad/s;
* ``phidot_minus_*``, ``phidot_plus_*``: with phi_dot = -/+ 0.3 rad/s and spin 1 (the class read
  off the trajectory: the sign of phi' on a fine grid; both are waves);
* ``moving_*``, ``pendulum_*``: theta_dot = 0.7 delta (kicked towards the pole), and a top with
  psi_dot = 0, phi_dot = 0.5 rad/s, theta_dot = 0.3 delta (omega3 = 0.5 rad/s);
* ``steady_*``: started at the double nearest to the slow steady precession rate for omega3 = 1
  (the root of I1 cos(th0) ph'^2 - p_psi ph' + mgl = 0, 2.116): steady precession.

The times cover about two nutation periods (to 6 s). The class of a case is by construction for
cusps and steady precession, else "loops" if phi' changes sign on the grid, else "waves".
Each row also records chi = pi - theta itself (column ``pole_distance``), which the double theta
cannot carry below an ulp of pi.

Run (about 25 minutes):  python python/tests/reference/gen_heavy_top_hanging.py [case names]
Writes heavy_top_hanging_mpmath.csv (read by crates/poinsot/tests/heavy_top_hanging.rs and
python/tests/test_top_hanging.py), in the format of heavy_top_upright_mpmath.csv plus the column
pole_distance.
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import mpmath as mp

DPS = 30
HERE = Path(__file__).resolve().parent
I1, I3, MGL = 1.0, 0.5, 1.0
ONE_ULP = math.nextafter(math.pi, 0.0)  # the largest double below pi: delta = 5.7e-16
TIMES = [0.4, 1.1, 2.0, 3.3, 4.5, 6.0]


def theta0_of(delta: float) -> float:
    """The double theta0 = pi - delta as a test passes it (``ONE_ULP`` for delta = 0)."""
    return ONE_ULP if delta == 0 else math.pi - delta


def psi_dot_for_spin(theta: float, phi_dot: float, omega3: float) -> float:
    """psi' = omega3 - phi' cos(theta) (2.99) in double precision, as HeavyTop.from_spin forms it."""
    return omega3 - phi_dot * math.cos(theta)


DELTAS = (1e-3, 1e-6, 1e-7, 1e-8, 1e-10, 1e-12, 1e-14, 0.0)


def label(delta: float) -> str:
    return "1ulp" if delta == 0 else f"{delta:g}"


def case_list() -> list[dict]:
    cases = []
    for d in DELTAS:
        th = theta0_of(d)
        cases.append(
            dict(
                name=f"cusps_{label(d)}",
                theta=th,
                theta_dot=0.0,
                phi_dot=0.0,
                psi_dot=1.0,
                label="cusps",
            )
        )
    for d in (1e-3, 1e-8, 0.0):
        th = theta0_of(d)
        chi = float(mp.pi - mp.mpf(th))
        cases += [
            dict(
                name=f"fast_cusps_{label(d)}",
                theta=th,
                theta_dot=0.0,
                phi_dot=0.0,
                psi_dot=psi_dot_for_spin(th, 0.0, 8.0),
                label="cusps",
            ),
            dict(
                name=f"back_cusps_{label(d)}",
                theta=th,
                theta_dot=0.0,
                phi_dot=0.0,
                psi_dot=-1.0,
                label="cusps",
            ),
            dict(
                name=f"phidot_minus_{label(d)}",
                theta=th,
                theta_dot=0.0,
                phi_dot=-0.3,
                psi_dot=psi_dot_for_spin(th, -0.3, 1.0),
            ),
            dict(
                name=f"phidot_plus_{label(d)}",
                theta=th,
                theta_dot=0.0,
                phi_dot=0.3,
                psi_dot=psi_dot_for_spin(th, 0.3, 1.0),
            ),
            dict(
                name=f"moving_{label(d)}",
                theta=th,
                theta_dot=0.7 * chi,
                phi_dot=0.2,
                psi_dot=psi_dot_for_spin(th, 0.2, 1.0),
            ),
            dict(
                name=f"pendulum_{label(d)}", theta=th, theta_dot=0.3 * chi, phi_dot=0.5, psi_dot=0.0
            ),
            dict(
                name=f"steady_{label(d)}",
                theta=th,
                theta_dot=0.0,
                phi_dot=steady_slow(th, 1.0),
                psi_dot=None,
                omega3=1.0,
                label="steady precession",
            ),
        ]
    for c in cases:
        if c["psi_dot"] is None:
            c["psi_dot"] = psi_dot_for_spin(c["theta"], c["phi_dot"], c.pop("omega3"))
        c["times"] = TIMES
    return cases


def steady_slow(theta0: float, omega3: float) -> float:
    """The double nearest to the slow root of I1 cos(th0) ph'^2 - p_psi ph' + mgl = 0 (2.116)."""
    c = mp.cos(mp.mpf(theta0))
    p = mp.mpf(I3) * mp.mpf(omega3)
    disc = mp.sqrt(p * p - 4 * mp.mpf(MGL) * mp.mpf(I1) * c)
    roots = ((p - disc) / (2 * mp.mpf(I1) * c), (p + disc) / (2 * mp.mpf(I1) * c))
    return float(min(roots, key=abs))


def rhs_chi(i1, i3, mgl):
    """``(t, y) -> y'`` for ``y = [chi, phi, psi, chi', phi', psi']``, chi = pi - theta."""

    def rhs(_t, y):
        ch, _ph, _ps, chd, phd, psd = y
        s, c = mp.sin(ch), mp.cos(ch)
        w3 = psd - phd * c
        chdd = (i1 * phd**2 * s * c + i3 * w3 * phd * s - mgl * s) / i1
        phdd = -chd * (i3 * w3 + 2 * i1 * phd * c) / (i1 * s)
        psdd = phdd * c - phd * chd * s
        return [chd, phd, psd, chdd, phdd, psdd]

    return rhs


def constants_chi(i1, i3, mgl):
    """``y -> (p_phi + p_psi, p_psi, E + mgl)`` of a state in chi (2.103-2.105), each formed
    without cancellation near the pole (p_phi + p_psi = I1 ph' sin^2 + p_psi (1 - cos chi))."""

    def constants(y):
        ch, _ph, _ps, chd, phd, psd = y
        s, c = mp.sin(ch), mp.cos(ch)
        w3 = psd - phd * c
        p_psi = i3 * w3
        e = i1 * phd * s**2 + p_psi * 2 * mp.sin(ch / 2) ** 2
        energy = i1 * (chd**2 + phd**2 * s**2) / 2 + i3 * w3**2 / 2 + mgl * 2 * mp.sin(ch / 2) ** 2
        return e, p_psi, energy

    return constants


def integrate(case: dict) -> dict:
    i1, i3, mgl = (mp.mpf(x) for x in (I1, I3, MGL))
    chi0 = mp.pi - mp.mpf(case["theta"])
    chd0 = -mp.mpf(case["theta_dot"])
    phd0, psd0 = mp.mpf(case["phi_dot"]), mp.mpf(case["psi_dot"])
    constants = constants_chi(i1, i3, mgl)
    y0 = [chi0, mp.mpf(0), mp.mpf(0), chd0, phd0, psd0]
    sol = mp.odefun(rhs_chi(i1, i3, mgl), 0, y0)
    c0 = constants(y0)
    times = case["times"]
    grid = sorted(set(times) | {times[-1] * k / 100 for k in range(1, 101)})
    keys = ("theta", "phi", "psi", "theta_dot", "phi_dot", "psi_dot", "pole_distance")
    out: dict[str, list[float]] = {k: [] for k in keys}
    drift = mp.mpf(0)
    phi_dots, chis = [], []
    for t in grid:
        y = sol(mp.mpf(t))
        if not 0 < y[0] < mp.pi:
            raise RuntimeError(f"{case['name']}: theta left (0, pi) at t = {t}")
        phi_dots.append(y[4])
        chis.append(y[0])
        if t in times:
            ch, ph, ps, chd, phd, psd = y
            for k, v in zip(keys, (mp.pi - ch, ph, ps, -chd, phd, psd, ch)):
                out[k].append(float(v))
            # Relative to the size of each constant's terms (E' + mgl ~ chi^2 near the pole).
            scale = [
                abs(i1 * phd) * ch**2 + abs(c0[1]) * ch**2,
                abs(c0[1]),
                i1 * (chd**2 + phd**2 * ch**2) + i3 * (psd - phd) ** 2 + mgl * ch**2,
            ]
            drift = max(drift, *(abs(a - b) / sc for a, b, sc in zip(constants(y), c0, scale)))
    if drift > mp.mpf("1e-20"):
        raise RuntimeError(f"{case['name']}: constants drift by {drift}")
    name_label = case.get("label")
    if name_label == "steady precession":
        spread = (max(chis) - min(chis)) / chis[0]
        if spread > mp.mpf("1e-12"):
            raise RuntimeError(f"{case['name']}: not steady (nutation {spread} of chi)")
    elif name_label is None:
        name_label = "loops" if min(phi_dots) < 0 < max(phi_dots) else "waves"
    return {**case, "class": name_label, "trajectory": out, "drift": drift}


def main() -> None:
    mp.mp.dps = DPS
    results = []
    only = set(sys.argv[1:])
    for case in case_list():
        if only and case["name"] not in only:
            continue
        start = time.time()
        results.append(integrate(case))
        print(
            f"{case['name']}: {results[-1]['class']}, drift {mp.nstr(results[-1]['drift'], 3)}, "
            f"{time.time() - start:.0f} s",
            file=sys.stderr,
            flush=True,
        )
    write(results, partial=bool(only))


def write(results: list[dict], partial: bool) -> None:
    keys = ("phi", "theta", "psi", "phi_dot", "theta_dot", "psi_dot", "pole_distance")
    lines = [
        "# heavy symmetric top next to the hanging pole: Euler angles (phi, theta, psi; rad), rates (rad/s) and "
        f"pole_distance = pi - theta (rad) from a {DPS}-digit mpmath.odefun integration of the Euler-Lagrange "
        f"equations of 2.102 in chi = pi - theta; phi(0) = psi(0) = 0; mpmath {mp.__version__}; generator "
        "python/tests/reference/gen_heavy_top_hanging.py",
        "name,class,I1,I3,mgl,theta0,theta_dot0,phi_dot0,psi_dot0,t," + ",".join(keys),
    ]
    for c in results:
        head = [
            c["name"],
            c["class"],
            repr(I1),
            repr(I3),
            repr(MGL),
            *(repr(c[k]) for k in ("theta", "theta_dot", "phi_dot", "psi_dot")),
        ]
        for i, t in enumerate(c["times"]):
            lines.append(",".join([*head, repr(t), *(repr(c["trajectory"][k][i]) for k in keys)]))
    path = HERE / ("heavy_top_hanging_partial.csv" if partial else "heavy_top_hanging_mpmath.csv")
    path.write_text("\n".join(lines) + "\n")
    print(f"wrote {path}", file=sys.stderr)


if __name__ == "__main__":
    main()
