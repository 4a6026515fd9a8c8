"""RK4 steps of one free rigid body: poinsot versus MuJoCo's ``mj_step`` with the RK4
integrator (no gravity, no contacts; inertia diag(1, 2, 3), ω₀ = (1, 0.1, 1) rad/s in the body,
dt = 1 ms), timed in the same run; MuJoCo steps in C (``mj_step(m, d, nstep)``), poinsot in one
``simulate(method="rk4")`` call. Checks that both agree with the exact solution.

Needs ``pip install mujoco`` (benchmark only; not a dependency of poinsot).

    python bench/free_body_vs_mujoco.py
"""

from __future__ import annotations

import timeit

import numpy as np

import poinsot as ps

XML = """
<mujoco>
  <option timestep="0.001" integrator="RK4" gravity="0 0 0"/>
  <worldbody>
    <body name="b"><freejoint/><inertial pos="0 0 0" mass="1" diaginertia="1 2 3"/></body>
  </worldbody>
</mujoco>"""


def main() -> None:
    try:
        import mujoco
    except ImportError:
        print("mujoco is not installed (pip install mujoco): skipped")
        return
    n = 20_000
    m = mujoco.MjModel.from_xml_string(XML)

    def run_mujoco():
        d = mujoco.MjData(m)
        d.qvel[3:6] = [1.0, 0.1, 1.0]  # angular velocity of a free joint: body frame
        mujoco.mj_step(m, d, nstep=n)
        return d

    def run_poinsot():
        return ps.simulate([1.0, 2.0, 3.0], [1.0, 0.1, 1.0], n * 1e-3, method="rk4", dt=1e-3, samples=2)

    d, tr = run_mujoco(), run_poinsot()
    exact = ps.FreeRigidBody([1.0, 2.0, 3.0], [1.0, 0.1, 1.0]).omega(n * 1e-3)
    t_mj = min(timeit.repeat(run_mujoco, number=3, repeat=3)) / 3 / n
    t_ps = min(timeit.repeat(run_poinsot, number=20, repeat=3)) / 20 / n
    print(f"one free body, RK4, dt = 1 ms, {n} steps (t = {n * 1e-3:g} s)")
    print(f"  MuJoCo {mujoco.__version__} mj_step: {t_mj * 1e9:8.1f} ns/step, |ω − exact| = "
          f"{np.linalg.norm(d.qvel[3:6] - exact):.1e}")
    print(f"  poinsot simulate rk4:   {t_ps * 1e9:8.1f} ns/step, |ω − exact| = {np.linalg.norm(tr.omega[-1] - exact):.1e}")
    print(f"  ratio: poinsot is {t_mj / t_ps:.0f}× faster per step")


if __name__ == "__main__":
    main()
