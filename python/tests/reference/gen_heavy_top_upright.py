"""Reference trajectories of the heavy symmetric top near upright (theta0 = 1e-12 ... 1e-2) by a
40-digit integration of its Lagrangian.

The same independent method as ``gen_heavy_top.py`` (mpmath's Taylor-series ODE solver
``mpmath.odefun`` on the Euler-Lagrange equations of the unit's 2.102, at 40 significant digits,
from initial conditions that are exactly the double-precision numbers the tests pass to poinsot),
for the tops that double precision finds hardest: released a hair's breadth from the upright
position, where 1 - cos(theta) ~ theta^2/2 is 1e-24 and any formula that forms it by subtraction
loses every digit (issue 10, item 1.1). At 40 digits 1 - cos(1e-12) still carries 15 digits, and the
equations (which have sin(theta), never 1 - cos(theta), in their denominators) need no more.

Cases (I1 = 1, I3 = 0.5, m g l = 1 kg m^2 / N m; the sleeping threshold is
2 sqrt(m g l I1) / I3 = 4 rad/s):

* ``fall_*``: released at rest without spin at theta0 = 1e-12 ... 1e-2: the top falls, theta grows
  like theta0 cosh(t), until it swings through the bottom (the times stop before it gets there);
* ``half_*``: spin omega3 = 2 rad/s, half the threshold (``HeavyTop.from_spin``), released at rest
  in phi (cusps at theta0) or moving: falls to theta2 = 2 pi / 3 and comes back;
* ``above_*``: spin 8 rad/s, twice the threshold: nutation between two angles near upright (cusps,
  loops, waves), theta0 = 1e-12 ... 1e-2;
* ``threshold_*``: spin 1 % below, at, and 1 % above the threshold.

psi_dot is the double nearest to omega3 - phi_dot cos(theta0) where a case gives omega3 (as
``from_spin`` forms it). Each case records the Euler angles and rates at its times and checks that
p_phi, p_psi and E drift by less than 1e-30 along the integration. The class of the path is read
off the trajectory: the sign of phi' on a fine grid over the sampled span (one sign = waves, both =
loops; released at rest in phi = cusps, by construction).

Run (about half an hour):  python python/tests/reference/gen_heavy_top_upright.py
Writes heavy_top_upright_mpmath.csv (read by crates/poinsot/tests/heavy_top_upright.rs), in the
format of heavy_top_mpmath.csv.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import mpmath as mp
from gen_heavy_top import constants_of_motion, euler_lagrange_rhs  # same directory

DPS = 40
HERE = Path(__file__).resolve().parent
I1, I3, MGL = 1.0, 0.5, 1.0


def psi_dot_for_spin(theta: float, phi_dot: float, omega3: float) -> float:
    """psi' = omega3 - phi' cos(theta) (2.99) in double precision, as HeavyTop.from_spin forms it."""
    import math

    return omega3 - phi_dot * math.cos(theta)


def fractions(t_end: float, fs: tuple[float, ...]) -> list[float]:
    return [float(mp.nstr(mp.mpf(f) * mp.mpf(t_end), 6)) for f in fs]


FALL = (0.1, 0.25, 0.5, 0.75, 0.9, 0.95)


def case_list() -> list[dict]:
    cases = []
    # Released at rest without spin: theta ~ theta0 cosh t; the bottom is reached near
    # t = ln(8 / theta0) (the quarter period of the separatrix-like swing).
    for th in (1e-12, 1e-9, 1.5e-8, 3e-8, 1e-7, 1e-5, 1e-2):
        t_bottom = float(mp.log(8 / mp.mpf(th)))
        times = fractions(t_bottom, FALL)
        if th == 1e-9:
            times = sorted(set(times) | {5.0, 10.0})  # the figures
        cases.append(
            dict(
                name=f"fall_{th:g}",
                theta=th,
                theta_dot=0.0,
                phi_dot=0.0,
                psi_dot=0.0,
                times=times,
                label="through vertical",
            )
        )
    # Half the sleeping threshold: the fall is slower (growth rate sqrt(2 beta - a^2) / 2 = 0.87/s)
    # and ends at theta2 = 2 pi / 3; the times go past the lower turning point.
    for th in (1e-12, 1e-9, 1e-6, 1e-3):
        t_bottom = float(mp.log(4 / mp.mpf(th)) / mp.sqrt(3) * 2)
        cases.append(
            dict(
                name=f"half_{th:g}",
                theta=th,
                theta_dot=0.0,
                phi_dot=0.0,
                psi_dot=psi_dot_for_spin(th, 0.0, 2.0),
                times=fractions(t_bottom, (0.1, 0.3, 0.5, 0.7, 0.9, 1.0, 1.1)),
                label="cusps",
            )
        )
    cases.append(
        dict(
            name="half_moving_1e-09",
            theta=1e-9,
            theta_dot=5e-10,
            phi_dot=0.3,
            psi_dot=psi_dot_for_spin(1e-9, 0.3, 2.0),
            times=[2.0, 5.0, 10.0, 15.0, 20.0, 25.0, 27.0],
        )
    )
    # Twice the threshold: nutation near upright, period ~ 1-3 s.
    near = [0.25, 0.7, 1.3, 2.1, 3.0, 4.2, 5.5]
    for th in (1e-12, 1e-9, 1e-6, 1e-2):
        cases.append(
            dict(
                name=f"above_cusps_{th:g}",
                theta=th,
                theta_dot=0.0,
                phi_dot=0.0,
                psi_dot=psi_dot_for_spin(th, 0.0, 8.0),
                times=near,
                label="cusps",
            )
        )
    for name, th, thd, phd in (
        ("above_loops_1e-09", 1e-9, 0.0, -1.0),
        ("above_waves_1e-09", 1e-9, 0.0, 1.0),
        ("above_fast_1e-09", 1e-9, 0.0, 6.0),
        ("above_moving_1e-09", 1e-9, 1e-9, 0.0),
        ("above_moving_1e-12", 1e-12, 1e-12, -2.0),
        ("above_moving_1e-06", 1e-6, 1e-6, 3.0),
        ("above_slow_1e-09", 1e-9, 0.0, 0.25),
    ):
        cases.append(
            dict(
                name=name,
                theta=th,
                theta_dot=thd,
                phi_dot=phd,
                psi_dot=psi_dot_for_spin(th, phd, 8.0),
                times=near,
            )
        )
    # Around the threshold 4 rad/s.
    for name, w3, times in (
        ("threshold_below", 3.96, [1.0, 5.0, 10.0, 20.0, 30.0, 40.0]),
        ("threshold_at", 4.0, [1.0, 5.0, 10.0, 20.0, 30.0, 40.0]),
        ("threshold_above", 4.04, [1.0, 5.0, 10.0, 20.0, 30.0, 40.0]),
    ):
        cases.append(
            dict(
                name=name,
                theta=1e-9,
                theta_dot=0.0,
                phi_dot=0.0,
                psi_dot=psi_dot_for_spin(1e-9, 0.0, w3),
                times=times,
                label="cusps",
            )
        )
    return cases


def integrate(case: dict) -> dict:
    i1, i3, mgl = (mp.mpf(x) for x in (I1, I3, MGL))
    th0, thd0, phd0, psd0 = (mp.mpf(case[k]) for k in ("theta", "theta_dot", "phi_dot", "psi_dot"))

    rhs = euler_lagrange_rhs(i1, i3, mgl)
    constants = constants_of_motion(i1, i3, mgl)

    y0 = [th0, mp.mpf(0), mp.mpf(0), thd0, phd0, psd0]
    sol = mp.odefun(rhs, 0, y0)
    c0 = constants(y0)
    times = case["times"]
    grid = sorted(set(times) | {times[-1] * k / 200 for k in range(1, 201)})
    out = {k: [] for k in ("phi", "theta", "psi", "phi_dot", "theta_dot", "psi_dot")}
    drift = mp.mpf(0)
    phi_dots = []
    for t in grid:
        y = sol(mp.mpf(t))
        if not 0 < y[0] < mp.pi:
            raise RuntimeError(f"{case['name']}: theta left (0, pi) at t = {t}")
        phi_dots.append(y[4])
        if t in times:
            for k, v in zip(("theta", "phi", "psi", "theta_dot", "phi_dot", "psi_dot"), y):
                out[k].append(float(v))
            drift = max(drift, *(abs(a - b) / max(1, abs(b)) for a, b in zip(constants(y), c0)))
    if drift > mp.mpf("1e-30"):
        raise RuntimeError(f"{case['name']}: constants drift by {drift}")
    label = case.get("label")
    if label is None:
        label = "loops" if min(phi_dots) < 0 < max(phi_dots) else "waves"
    return {**case, "class": label, "trajectory": out}


def main() -> None:
    mp.mp.dps = DPS
    results = []
    only = set(sys.argv[1:])
    for case in case_list():
        if only and case["name"] not in only:
            continue
        start = time.time()
        results.append(integrate(case))
        print(f"{case['name']}: {time.time() - start:.0f} s", file=sys.stderr, flush=True)
    write(results)


def write(results: list[dict]) -> None:
    keys = ("phi", "theta", "psi", "phi_dot", "theta_dot", "psi_dot")
    lines = [
        "# heavy symmetric top near upright: Euler angles (phi, theta, psi; rad) and rates (rad/s) from a "
        f"{DPS}-digit mpmath.odefun integration of the Euler-Lagrange equations of 2.102; phi(0) = psi(0) = 0; "
        f"mpmath {mp.__version__}; generator python/tests/reference/gen_heavy_top_upright.py",
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
    path = HERE / "heavy_top_upright_mpmath.csv"
    path.write_text("\n".join(lines) + "\n")
    print(f"wrote {path}", file=sys.stderr)


if __name__ == "__main__":
    main()
