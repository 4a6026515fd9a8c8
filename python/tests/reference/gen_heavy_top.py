"""Reference trajectories of the heavy symmetric top by a 40-digit integration of its Lagrangian.

Independent of poinsot: the Euler-Lagrange equations of the unit's Lagrangian (2.102),

    L = 1/2 I1 (th'^2 + ph'^2 sin^2 th) + 1/2 I3 (ps' + ph' cos th)^2 - mgl cos th,

are integrated by mpmath's Taylor-series ODE solver (``mpmath.odefun``) at 40 significant
digits, from initial conditions that are exactly the double-precision numbers the tests pass
to poinsot. The equations, with w3 = ps' + ph' cos th (constant, since d/dt dL/dps' = 0):

    th'' = (I1 ph'^2 sin th cos th - I3 w3 ph' sin th + mgl sin th) / I1        (d/dt dL/dth' = dL/dth)
    ph'' = th' (I3 w3 - 2 I1 ph' cos th) / (I1 sin th)                        (d/dt p_phi = 0)
    ps'' = -ph'' cos th + ph' th' sin th                                      (d/dt w3 = 0)

Each case records the Euler angles and rates at a few times, the constants p_phi, p_psi, E
(whose drift along the integration is checked here to stay below 1e-30), and the class of the
axis' path read off the trajectory itself (the sign of ph' on a fine grid over two nutation
periods: one-signed = "waves", both signs = "loops"); cusps and steady precession are labelled
by construction (released at rest in phi; started at the exact steady rate).

Run (a few minutes):  python python/tests/reference/gen_heavy_top.py
Writes python/tests/reference/heavy_top_mpmath.json (read by python/tests/test_top_reference.py)
and the same trajectories flat in heavy_top_mpmath.csv (read by crates/poinsot/tests/heavy_top_reference.rs).
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import mpmath as mp

DPS = 40
HERE = Path(__file__).resolve().parent

# Sample times (s); the nutation periods of the cases are 0.6-5 s.
TIMES = [0.25, 0.7, 1.3, 2.1, 3.0, 4.2, 5.5]
# Fine grid for the sign of phi' (s).
GRID = [k * 0.01 for k in range(1, 551)]


def steady_rates(
    i1: float, i3: float, mgl: float, theta0: float, omega3: float
) -> tuple[mp.mpf, mp.mpf]:
    """The two roots of I1 cos(th0) ph'^2 - p_psi ph' + mgl = 0 (the unit's 2.116), at 40 digits."""
    c = mp.cos(mp.mpf(theta0))
    p = mp.mpf(i3) * mp.mpf(omega3)
    disc = mp.sqrt(p * p - 4 * mp.mpf(mgl) * mp.mpf(i1) * c)
    return (p - disc) / (2 * mp.mpf(i1) * c), (p + disc) / (2 * mp.mpf(i1) * c)


def case_list() -> list[dict]:
    cases = [
        dict(
            name="cusps",
            I1=1.0,
            I3=0.5,
            mgl=1.0,
            theta=0.8,
            theta_dot=0.0,
            phi_dot=0.0,
            psi_dot=6.0,
            label="cusps",
        ),
        dict(
            name="loops",
            I1=1.0,
            I3=0.5,
            mgl=1.0,
            theta=0.8,
            theta_dot=0.0,
            phi_dot=-0.5,
            psi_dot=6.0,
        ),
        dict(
            name="waves",
            I1=1.0,
            I3=0.5,
            mgl=1.0,
            theta=0.8,
            theta_dot=0.0,
            phi_dot=0.5,
            psi_dot=6.0,
        ),
        dict(
            name="moving_start",
            I1=1.0,
            I3=0.5,
            mgl=1.0,
            theta=0.8,
            theta_dot=0.3,
            phi_dot=0.6,
            psi_dot=6.0,
        ),
        dict(
            name="near_sleeping",
            I1=1.0,
            I3=0.5,
            mgl=1.0,
            theta=0.01,
            theta_dot=0.001,
            phi_dot=0.2,
            psi_dot=10.0,
        ),
        dict(
            name="near_sleeping_loops",
            I1=1.0,
            I3=0.5,
            mgl=1.0,
            theta=1e-3,
            theta_dot=0.0,
            phi_dot=1.0,
            psi_dot=10.0,
        ),
        dict(
            name="below_horizontal",
            I1=1.0,
            I3=0.5,
            mgl=1.0,
            theta=2.5,
            theta_dot=0.5,
            phi_dot=0.3,
            psi_dot=2.0,
        ),
        dict(
            name="free_top",
            I1=1.0,
            I3=0.5,
            mgl=0.0,
            theta=0.8,
            theta_dot=0.2,
            phi_dot=1.0,
            psi_dot=3.0,
        ),
        dict(
            name="near_bottom_pass",
            I1=1.0,
            I3=0.5,
            mgl=1.0,
            theta=0.8,
            theta_dot=0.0,
            phi_dot=1e-3,
            psi_dot=0.0,
        ),
        dict(
            name="fast_top_cusps",
            I1=1.0,
            I3=0.5,
            mgl=0.3,
            theta=0.6,
            theta_dot=0.0,
            phi_dot=0.0,
            psi_dot=40.0,
            label="cusps",
        ),
    ]
    # Steady precession at the slow and fast rates (rounded to doubles: the nutation left is
    # of the order of that rounding).
    for which, idx in (("steady_slow", 0), ("steady_fast", 1)):
        i1, i3, mgl, th, w3 = 1.0, 0.5, 1.0, 0.8, 6.0
        rate = float(steady_rates(i1, i3, mgl, th, w3)[idx])
        psi_dot = float(mp.mpf(w3) - mp.mpf(rate) * mp.cos(mp.mpf(th)))
        cases.append(
            dict(
                name=which,
                I1=i1,
                I3=i3,
                mgl=mgl,
                theta=th,
                theta_dot=0.0,
                phi_dot=rate,
                psi_dot=psi_dot,
                label="steady precession",
            )
        )
    return cases


def euler_lagrange_rhs(i1, i3, mgl):
    """The right-hand side ``(t, y) -> y'`` of the Euler-Lagrange equations of 2.102 for
    ``y = [θ, φ, ψ, θ̇, φ̇, ψ̇]`` (rad, rad/s), moments ``i1``, ``i3`` (kg m²), ``mgl`` (N m)."""

    def rhs(_t, y):
        th, _ph, _ps, thd, phd, psd = y
        s, c = mp.sin(th), mp.cos(th)
        w3 = psd + phd * c
        thdd = (i1 * phd**2 * s * c - i3 * w3 * phd * s + mgl * s) / i1
        phdd = thd * (i3 * w3 - 2 * i1 * phd * c) / (i1 * s)
        psdd = -phdd * c + phd * thd * s
        return [thd, phd, psd, thdd, phdd, psdd]

    return rhs


def constants_of_motion(i1, i3, mgl):
    """``y -> (p_φ, p_ψ, E)`` (kg m²/s, kg m²/s, J) of a state ``y`` as in
    :func:`euler_lagrange_rhs` (2.103–2.105)."""

    def constants(y):
        th, _ph, _ps, thd, phd, psd = y
        s, c = mp.sin(th), mp.cos(th)
        w3 = psd + phd * c
        p_psi = i3 * w3
        p_phi = i1 * phd * s**2 + p_psi * c
        energy = i1 * (thd**2 + phd**2 * s**2) / 2 + i3 * w3**2 / 2 + mgl * c
        return p_phi, p_psi, energy

    return constants


def integrate(case: dict) -> dict:
    i1, i3, mgl = (mp.mpf(case[k]) for k in ("I1", "I3", "mgl"))
    th0, thd0, phd0, psd0 = (mp.mpf(case[k]) for k in ("theta", "theta_dot", "phi_dot", "psi_dot"))

    rhs = euler_lagrange_rhs(i1, i3, mgl)
    constants = constants_of_motion(i1, i3, mgl)

    y0 = [th0, mp.mpf(0), mp.mpf(0), thd0, phd0, psd0]
    sol = mp.odefun(rhs, 0, y0)
    c0 = constants(y0)
    phi_dots = []
    out = {k: [] for k in ("phi", "theta", "psi", "phi_dot", "theta_dot", "psi_dot")}
    drift = mp.mpf(0)
    for t in sorted(set(GRID) | set(TIMES)):
        y = sol(mp.mpf(t))
        phi_dots.append(y[4])
        if t in TIMES:
            for k, v in zip(("theta", "phi", "psi", "theta_dot", "phi_dot", "psi_dot"), y):
                out[k].append(float(v))
            drift = max(drift, *(abs(a - b) for a, b in zip(constants(y), c0)))
    if drift > mp.mpf("1e-30"):
        raise RuntimeError(f"{case['name']}: constants drift by {drift}")
    label = case.get("label")
    if label is None:
        label = "loops" if min(phi_dots) < 0 < max(phi_dots) else "waves"
    return {
        **{k: case[k] for k in ("name", "I1", "I3", "mgl")},
        "initial": {k: case[k] for k in ("theta", "theta_dot", "phi_dot", "psi_dot")},
        "class": label,
        "p_phi": mp.nstr(c0[0], 30),
        "p_psi": mp.nstr(c0[1], 30),
        "energy": mp.nstr(c0[2], 30),
        "times": TIMES,
        "trajectory": out,
    }


def main() -> None:
    mp.mp.dps = DPS
    results = []
    for case in case_list():
        print(f"integrating {case['name']} ...", file=sys.stderr, flush=True)
        results.append(integrate(case))
    write(results)


def write(results: list[dict]) -> None:
    """Writes the JSON and CSV files from the integrated cases."""
    doc = {
        "description": "heavy symmetric top: Euler angles (phi, theta, psi; rad) and rates (rad/s) "
        "from a 40-digit mpmath.odefun integration of the Euler-Lagrange equations of 2.102; "
        "phi(0) = psi(0) = 0",
        "generator": "python/tests/reference/gen_heavy_top.py",
        "mpmath": mp.__version__,
        "dps": DPS,
        "cases": results,
    }
    path = HERE / "heavy_top_mpmath.json"
    path.write_text(json.dumps(doc, indent=1) + "\n")
    print(f"wrote {path}", file=sys.stderr)
    keys = ("phi", "theta", "psi", "phi_dot", "theta_dot", "psi_dot")
    lines = [
        "# " + doc["description"] + "; generator " + doc["generator"],
        "name,class,I1,I3,mgl,theta0,theta_dot0,phi_dot0,psi_dot0,t," + ",".join(keys),
    ]
    for c in results:
        head = [
            c["name"],
            c["class"],
            *(repr(c[k]) for k in ("I1", "I3", "mgl")),
            *(repr(c["initial"][k]) for k in ("theta", "theta_dot", "phi_dot", "psi_dot")),
        ]
        for i, t in enumerate(c["times"]):
            lines.append(",".join([*head, repr(t), *(repr(c["trajectory"][k][i]) for k in keys)]))
    (HERE / "heavy_top_mpmath.csv").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
