"""``poinsot tour``: the course unit, computed from end to end.

Each section takes one topic of the unit, computes it with poinsot and prints the unit's own
statement (or the textbook's closed form) beside poinsot's number. The tour grows with the
project; every section cites the unit's equation numbers.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from rich.console import Console
from rich.panel import Panel
from rich.table import Table
from rich.text import Text

import poinsot as ps

_SECTIONS: list[tuple[str, Callable[[Console], None]]] = []


def section(title: str) -> Callable[[Callable[[Console], None]], Callable[[Console], None]]:
    """Register a tour section (in order of definition)."""

    def deco(fn: Callable[[Console], None]) -> Callable[[Console], None]:
        _SECTIONS.append((title, fn))
        return fn

    return deco


def _vec(v: np.ndarray, digits: int = 6) -> str:
    v = np.asarray(v, dtype=float)
    v = np.where(np.abs(v) < 1e-12 * max(1.0, float(np.max(np.abs(v)))), 0.0, v)
    return "(" + ", ".join(f"{x: .{digits}g}" for x in v) + ")"


def _table(*columns: str, title: str | None = None, left: int = 1) -> Table:
    """A table of the tour: the first ``left`` columns (names) left-justified, the others
    (numbers) right-justified."""
    table = Table(title=title)
    for i, name in enumerate(columns):
        table.add_column(name, justify="left" if i < left else "right")
    return table


@section("Moving frames: the acceleration seen from a turning, accelerating frame (eqs. 2.20–2.24)")
def _moving_frames(con: Console) -> None:
    frame = ps.MovingFrame(
        acceleration=[0.0, 0.0, 1.0],
        angular_velocity=[0.0, 0.0, 2.0],
        angular_acceleration=[0.0, 0.0, 0.5],
    )
    out = frame.to_fixed([3.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.1, 0.0, 0.0])
    con.print("a frame with R̈ = (0, 0, 1) m/s², ω = (0, 0, 2) rad/s, ω̇ = (0, 0, 0.5) rad/s²;")
    con.print(
        "a particle at r = (3, 0, 0) m moving with ṙ = (0, 1, 0) m/s, r̈ = (0.1, 0, 0) m/s² in it:"
    )
    table = _table("term of eq. 2.21", "poinsot (m/s²)", "by hand")
    hand = {
        "relative": "(0.1, 0, 0)",
        "origin": "(0, 0, 1)",
        "coriolis": "2ω×ṙ = (−4, 0, 0)",
        "centripetal": "ω×(ω×r) = −ω² r = (−12, 0, 0)",
        "euler": "ω̇×r = (0, 1.5, 0)",
    }
    for name, value in out.acceleration_terms.items():
        table.add_row(name, _vec(value), hand[name])
    table.add_row("[bold]total r̈'", _vec(out.acceleration), "(−15.9, 1.5, 1)")
    con.print(table)
    f = frame.fictitious_forces(1.0, [3.0, 0.0, 0.0], [0.0, 1.0, 0.0])
    con.print(
        "fictitious forces on 1 kg there (2.26–2.28): "
        + ", ".join(f"{k} {_vec(v + 0.0, 4)} N" for k, v in f.items())
    )


@section("The rotating Earth: the unit's numbers (eqs. 2.29–2.33)")
def _earth_numbers(con: Console) -> None:
    solar = ps.Earth.solar_day(radius=6.4e6, g=9.81)
    sidereal = ps.Earth(radius=6.4e6)
    table = _table(
        "quantity",
        "the unit",
        "poinsot, solar day",
        "poinsot, sidereal (default)",
        title="r = 6.4e6 m as in the unit",
    )
    table.add_row(
        "ω (rad/s)",
        "7.25e-5 (misprint: 7.27e-5)",
        f"{solar.rotation_rate:.4e}",
        f"{sidereal.rotation_rate:.5e}",
    )
    table.add_row(
        "ω² r at the equator (m/s²)",
        "3.4e-2",
        f"{np.linalg.norm(solar.centrifugal_acceleration(0.0)):.4e}",
        f"{np.linalg.norm(sidereal.centrifugal_acceleration(0.0)):.4e}",
    )
    table.add_row(
        "2ω, horizontal Coriolis at the pole (1/s)",
        "1.5e-4",
        f"{solar.coriolis_parameter(np.pi / 2):.4e}",
        f"{sidereal.coriolis_parameter(np.pi / 2):.4e}",
    )
    e = ps.Earth()
    table.add_row(
        "|g_e| at the equator / pole (m/s², g = 9.80665)",
        "less at the equator",
        "",
        f"{e.effective_gravity_magnitude(0.0):.6g} / {e.effective_gravity_magnitude(np.pi / 2):.6g}",
    )
    table.add_row(
        "plumb-line deviation at 45°", "—", "", f"{e.plumb_line_deviation(45, degrees=True):.4f}°"
    )
    con.print(table)


@section("The falling body: deflected east (eqs. 2.32–2.42)")
def _falling_body(con: Console) -> None:
    table = _table(
        "model",
        "east (m)",
        "south (m)",
        "time (s)",
        title="a body dropped from rest from 100 m at latitude 45°",
    )
    solar = ps.Earth.solar_day(g=9.81)
    table.add_row("the unit (2.42)", "1.55e-2", "—", "√(2h/g)")
    table.add_row(
        "2.42, solar day, g = 9.81",
        f"{solar.eastward_deflection(100, 45, degrees=True):.4e}",
        "",
        "",
    )
    e = ps.Earth()
    fall = e.drop(100, 45, degrees=True)
    table.add_row(
        "2.42, sidereal, g = 9.80665",
        f"{fall.first_order_east:.4e}",
        f"{fall.second_order_south:.4e}",
        "",
    )
    table.add_row(
        "exact in the rotating frame", f"{fall.east:.4e}", f"{-fall.north:.4e}", f"{fall.time:.6f}"
    )
    con.print(table)
    s = e.drop(100, -45, degrees=True)
    con.print(
        f"southern hemisphere (−45°): east {s.east:.4e} m, north {s.north:+.3e} m — east again, "
        "and towards the equator"
    )


@section("Foucault's pendulum, inertial circles and cyclones (the unit's Figs. 2.5–2.7)")
def _foucault_and_winds(con: Console) -> None:
    e = ps.Earth()
    run = e.foucault(48.85, degrees=True, duration=900.0, samples=2)
    con.print(
        f"Paris (48.85° N), 67 m pendulum, 15 min simulated in the rotating frame: the swing plane "
        f"turns at {run.precession_rate:.5e} rad/s ({run.sense} seen from above); "
        f"−ω sin λ = {run.expected_rate:.5e} rad/s, one turn in {2 * np.pi / abs(run.expected_rate) / 3600:.1f} h"
    )
    for lat in (45.0, -45.0, 0.0):
        osc = e.inertial_oscillation(lat, [10.0, 0.0], degrees=True)
        low = e.flow_into_low(lat, degrees=True)
        period = f"{osc.period / 3600:.2f} h" if np.isfinite(osc.period) else "none"
        turns = f"turns {osc.sense}" if osc.sense != "none" else "goes straight on"
        circ = f"circulates {low.sense}" if low.sense != "none" else "flows straight in"
        con.print(
            f"  latitude {lat:+.0f}°: a parcel moving at 10 m/s {turns} "
            f"(inertial period π/(ω|sin λ|) = {period}); air flowing into a low {circ}"
        )


@section("Euler's theorem: any rotation about a fixed point is one rotation about one axis")
def _euler_theorem(con: Console) -> None:
    angles = np.radians([30.0, 60.0, 45.0])
    R = ps.euler_to_matrix(angles)
    axis, angle = ps.rotation_axis(R)
    con.print("Euler angles (φ, θ, ψ) = (30°, 60°, 45°), intrinsic z-x-z as in the unit:")
    con.print(
        f"  R = R_z(φ) R_x(θ) R_z(ψ) =\n{np.array2string(R, precision=6, suppress_small=True)}"
    )
    con.print(f"  one rotation about axis n = {_vec(axis)} by {np.degrees(angle):.6f}°")
    con.print(
        f"  check: |R n − n| = {np.linalg.norm(R @ axis - axis):.1e} (the axis is left fixed)"
    )
    back = ps.matrix_to_euler(R, degrees=True)
    con.print(f"  and back to Euler angles: {_vec(back, 10)} °")


@section("Chasles' theorem: any displacement is a screw motion")
def _chasles(con: Console) -> None:
    R = ps.axis_angle_to_matrix([0.0, 0.0, 1.0], np.pi / 2)
    t = np.array([1.0, 1.0, 0.5])
    s = ps.screw_axis(R, t)
    con.print("x ↦ R x + t with R = 90° about z and t = (1, 1, 0.5) m is a screw:")
    con.print(f"  axis {_vec(s.axis)} through the point {_vec(s.point)} m")
    con.print(
        f"  rotation {np.degrees(s.angle):.6g}°, slide {s.slide:.6g} m, pitch {s.pitch:.6g} m/rad"
    )


@section("Angular momentum is not parallel to ω: the unit's dumbbell (eqs. 2.58–2.59)")
def _dumbbell(con: Console) -> None:
    m, r, alpha, omega = 1.0, 0.5, np.radians(30.0), 2.0
    direction = np.array([np.sin(alpha), 0.0, np.cos(alpha)])
    body = ps.RigidBody.from_point_masses([m, m], [r * direction, -r * direction])
    w = np.array([0.0, 0.0, omega])
    L = body.angular_momentum(w)
    N = body.holding_torque(w)
    cos = L @ w / (np.linalg.norm(L) * np.linalg.norm(w))
    con.print(
        "two 1 kg masses at ±0.5 m on a massless rod tilted 30° from the spin axis z, ω = 2 rad/s:"
    )
    con.print(f"  L = I·ω = {_vec(L)} kg·m²/s, at {np.degrees(np.arccos(cos)):.4f}° from ω")
    con.print(f"  torque needed to keep ω fixed, ω × L = {_vec(N)} N·m")
    con.print(
        f"  closed form |N| = m r² ω² sin 2α = {m * r**2 * omega**2 * np.sin(2 * alpha):.6g} N·m"
        " (2 masses × m r² ω² sinα cosα)"
    )


@section("The inertia tensor: principal moments and the kind of top (eqs. 2.60–2.66)")
def _standard_solids(con: Console) -> None:
    m, r, h = 1.0, 0.5, 2.0
    rows = [
        ("solid sphere", ps.RigidBody.solid_sphere(m, r), "2/5 m r²"),
        ("spherical shell", ps.RigidBody.spherical_shell(m, r), "2/3 m r²"),
        ("solid cylinder", ps.RigidBody.solid_cylinder(m, r, h), "I₃ = ½ m r²"),
        ("solid cone (apex at 0)", ps.RigidBody.solid_cone(m, r, h), "I₃ = 3/10 m r²"),
        ("cuboid 1×2×3", ps.RigidBody.cuboid(m, (1.0, 2.0, 3.0)), "m(b²+c²)/12, …"),
        ("ellipsoid 1, 2, 3", ps.RigidBody.ellipsoid(m, (1.0, 2.0, 3.0)), "m(b²+c²)/5, …"),
        ("thin rod", ps.RigidBody.thin_rod(m, h), "m l²/12"),
        ("thin disk", ps.RigidBody.thin_disk(m, r), "¼ m r², ½ m r²"),
        ("thin ring", ps.RigidBody.thin_ring(m, r), "½ m r², m r²"),
    ]
    table = _table(
        "body", "principal moments (kg·m²)", title=f"m = {m} kg, r = {r} m, h = l = {h} m"
    )
    table.add_column("textbook")
    table.add_column("kind")
    for name, body, formula in rows:
        table.add_row(
            name, ", ".join(f"{x:.6g}" for x in body.principal_moments), formula, body.kind
        )
    con.print(table)


@section("Euler's equations and the free symmetric top (eqs. 2.71–2.97)")
def _free_symmetric_top(con: Console) -> None:
    top = ps.FreeSymmetricTop(2.0, 1.0, [0.3, 0.4, 2.0])
    con.print("A prolate top, I₁ = I₂ = 2, I₃ = 1 kg·m², ω₀ = (0.3, 0.4, 2) rad/s, no torque:")
    table = _table("quantity (the unit's eq.)", "closed form", "integrated (DOP853)")
    tr = ps.simulate(
        [2.0, 2.0, 1.0], [0.3, 0.4, 2.0], 10.0, method="dop853", rtol=1e-12, atol=1e-14, samples=101
    )
    om = tr.omega
    phase = np.unwrap(np.arctan2(om[:, 0], om[:, 1]))  # Ωt + θ₀ of 2.85–2.86
    table.add_row(
        "Ω = (I₁ − I₃) ω₃ / I₁ (2.83), rad/s",
        f"{top.precession_rate:.10f}",
        f"{(phase[-1] - phase[0]) / 10.0:.10f}",
    )
    table.add_row(
        "A = |ω_p| (2.88), rad/s", f"{top.amplitude:.10f}", f"{np.hypot(om[-1, 0], om[-1, 1]):.10f}"
    )
    table.add_row("ω₃ (2.80), rad/s", f"{top.omega3:.10f}", f"{om[-1, 2]:.10f}")
    table.add_row(
        "body cone α_b, tan α_b = A/ω₃ (2.90)",
        f"{np.degrees(top.body_cone_angle):.8f}°",
        f"{np.degrees(np.arctan2(np.hypot(om[-1, 0], om[-1, 1]), om[-1, 2])):.8f}°",
    )
    table.add_row(
        "space cone α_s, cos α_s = 2T/(ωL) (2.97)", f"{np.degrees(top.space_cone_angle):.8f}°", ""
    )
    table.add_row(
        "ω₃² from T and L (2.95)",
        f"{ps.FreeSymmetricTop.omega3_squared_from(2, 1, top.energy, top.angular_momentum_magnitude):.10f}",
        "4",
    )
    table.add_row(
        "A² from T and L (2.96)",
        f"{ps.FreeSymmetricTop.amplitude_squared_from(2, 1, top.energy, top.angular_momentum_magnitude):.10f}",
        "0.25",
    )
    con.print(table)
    con.print(
        f"  prolate: the body cone rolls on the {top.cone_contact} of the space cone; "
        "an oblate top (I₃ > I₁) reverses Ω and its body cone surrounds the space cone."
    )
    con.print(
        "  errata: 2.70 is I·ω̇; 2.78 reads ω̇₂ = −Ω ω₁; 2.84 is ω̈₁ = −Ω² ω₁; and torque-free ω is "
        "not parallel to L (2.73–2.74) — that is what the cones describe."
    )


@section("The free asymmetric top: exact solution, Dzhanibekov's flip, geometric integrators")
def _free_asymmetric_top(con: Console) -> None:
    body = ps.FreeRigidBody([1.0, 2.0, 3.0], [1.0, 0.1, 1.0])
    con.print(
        f"I = (1, 2, 3), ω₀ = (1, 0.1, 1): ω circles the {body.regime.replace('about ', '')} "
        f"(m = {body.parameter:.8f}); ω(t) by Jacobi sn, cn, dn with period {body.period:.10f} s; "
        "attitude by the elliptic integral of the third kind."
    )
    stab = ps.axis_stability([1.0, 2.0, 3.0])
    con.print(
        "  rotation about axes 1, 2, 3 is "
        + ", ".join(s.stability for s in stab)
        + f" (intermediate axis: perturbations grow like e^({stab[1].rate:.4f}·ω t))"
    )
    flip = ps.FreeRigidBody([1.0, 2.0, 3.0], [1e-3, 2.0, 1e-3])
    con.print(
        f"  spun about axis 2 at 2 rad/s with a 1e-3 wobble, the body flips over every "
        f"{flip.flip_interval:.4f} s (Dzhanibekov's wing nut)"
    )
    w_exact, _q_exact = body.state(1000.0)
    table = _table(
        "method",
        "step (s)",
        "|Δω| at t = 1000",
        "max |ΔE/E|",
        "max |Δ|L|/|L||",
        title="reaching t = 1000 s",
    )
    for method, dt in (("exact", None), ("splitting6", 0.01), ("splitting2", 0.01), ("rk4", 0.01)):
        tr = ps.simulate(
            [1.0, 2.0, 3.0], [1.0, 0.1, 1.0], 1000.0, method=method, dt=dt, samples=201
        )
        table.add_row(
            method,
            "—" if tr.step is None else f"{tr.step:g}",
            f"{np.linalg.norm(tr.omega[-1] - w_exact):.1e}",
            f"{tr.energy_error().max():.1e}",
            f"{tr.momentum_error().max():.1e}",
        )
    con.print(table)
    con.print(
        "  the splitting's every stage is an exact rotation: |L| stays at round-off and the energy "
        "error stays bounded; RK4's energy drifts."
    )


@section("Euler's angles: angular velocity from the angle rates (eq. 2.99)")
def _euler_rates(con: Console) -> None:
    angles = np.radians([20.0, 40.0, 10.0])
    rates = np.array([0.5, 0.2, 3.0])
    w = ps.body_angular_velocity(angles, rates)
    _phi, theta, psi = angles
    dphi, dtheta, dpsi = rates
    unit = np.array(
        [
            dtheta * np.cos(psi) + dphi * np.sin(theta) * np.sin(psi),
            -dtheta * np.sin(psi) + dphi * np.sin(theta) * np.cos(psi),
            dpsi + dphi * np.cos(theta),
        ]
    )
    con.print("φ, θ, ψ = 20°, 40°, 10°; φ̇, θ̇, ψ̇ = 0.5, 0.2, 3.0 rad/s:")
    con.print(f"  poinsot ω (body)  = {_vec(w, 12)} rad/s")
    con.print(f"  the unit's 2.99   = {_vec(unit, 12)} rad/s")
    try:
        ps.euler_rates([0.3, 0.0, 0.2], [0.1, 0.2, 0.3])
    except ps.GimbalLockError as exc:
        con.print(f"  at θ = 0 the rates are undefined (gimbal lock): [italic]{exc}[/italic]")


@section(
    "The heavy symmetric top: constants, effective potential, turning points (eqs. 2.102–2.114)"
)
def _heavy_top(con: Console) -> None:
    i1, i3, mgl = 1.0, 0.5, 1.0
    table = _table(
        "quantity",
        title=f"I₁ = {i1} kg·m², I₃ = {i3} kg·m², m g l = {mgl} N·m, θ₀ = 0.8 rad, ω₃ = 6 rad/s, "
        "released with θ̇₀ = 0",
    )
    tops = []
    for phi_dot in (0.5, 0.0, -0.5):
        tops.append(ps.HeavyTop.from_spin(i1, i3, mgl, 0.8, 6.0, phi_dot=phi_dot))
        table.add_column(f"φ̇₀ = {phi_dot:+.1f} rad/s", justify="right")
    rows: list[tuple[str, Callable[[ps.HeavyTop], str]]] = [
        ("p_φ (kg·m²/s)", lambda top: f"{top.p_phi:.6f}"),
        ("p_ψ (kg·m²/s)", lambda top: f"{top.p_psi:.6f}"),
        ("E′ (J)", lambda top: f"{top.reduced_energy:.6f}"),
        ("θ₁ (rad)", lambda top: f"{top.turning_points[0]:.6f}"),
        ("θ₂ (rad)", lambda top: f"{top.turning_points[1]:.6f}"),
        ("nutation period (s)", lambda top: f"{top.nutation_period:.6f}"),
        ("⟨φ̇⟩ (rad/s)", lambda top: f"{top.mean_precession_rate:.6f}"),
        ("the axis traces", lambda top: top.motion_class),
    ]
    for name, value in rows:
        table.add_row(name, *(value(top) for top in tops))
    con.print(table)
    top = ps.HeavyTop(i1, i3, mgl, 0.8, psi_dot=6.0)
    t1, t2 = top.turning_points
    con.print(
        f"  at the turning points E′ = V(θ) (2.109–2.110): V(θ₁) − E′ = {top.effective_potential(t1) - top.reduced_energy:.1e} J,"
        f" V(θ₂) − E′ = {top.effective_potential(t2) - top.reduced_energy:.1e} J"
    )
    phi, theta, psi = top.euler_angles(top.nutation_period / 2)
    con.print(
        f'  the exact motion (elliptic functions — the unit\'s "very difficult" 2.112): half a nutation period '
        f"later θ = {theta:.12f} rad = θ₂, φ = {phi:.9f} rad, ψ = {psi:.9f} rad"
    )
    thr = ps.HeavyTop.sleeping_threshold(i1, i3, mgl)
    con.print(
        f"  the sleeping top: upright spinning is stable iff ω₃² > 4 m g l I₁/I₃², i.e. ω₃ > {thr:.6g} rad/s"
    )


@section(
    "A fast top's slow and fast precession against the unit's approximations (eqs. 2.115–2.121)"
)
def _fast_top(con: Console) -> None:
    i1, i3, mgl, theta0 = 1.0, 0.5, 0.3, 0.6
    w_min = ps.HeavyTop.min_spin(i1, i3, mgl, theta0)
    con.print(
        f"I₁ = {i1}, I₃ = {i3}, m g l = {mgl}, θ₀ = {theta0} rad: minimum spin (2.119) "
        f"ω₃ = (2/I₃)√(m g l I₁ cos θ₀) = {w_min:.6f} rad/s"
    )
    table = _table(
        "ω₃ (rad/s)",
        "slow, exact",
        "m g l/p_ψ (2.121)",
        "fast, exact",
        "p_ψ/(I₁ cos θ₀) (2.120, corrected)",
        "p_ψ/(2 I₁ cos θ₀) (2.120 as printed)",
        title="steady precession rates φ̇ (rad/s): the two roots of 2.116 and the fast-top formulas",
        left=0,
    )
    for w3 in (1.01 * w_min, 5.0, 10.0, 40.0, 200.0):
        s = ps.HeavyTop.steady_precession(i1, i3, mgl, theta0, w3)
        table.add_row(
            f"{w3:.4g}",
            f"{s.slow:.6f}",
            f"{s.slow_approx:.6f}",
            f"{s.fast:.4f}",
            f"{s.fast_approx:.4f}",
            f"{s.fast_approx_as_printed:.4f}",
        )
    con.print(table)
    s = ps.HeavyTop.steady_precession(i1, i3, mgl, theta0, 40.0)
    con.print(
        f"  at ω₃ = 40 rad/s: exact fast root {s.fast:.4f} rad/s; the corrected 2.120 gives {s.fast_approx:.4f}, "
        f"the unit's printed formula {s.fast_approx_as_printed:.4f} (a factor 2 off: erratum)"
    )
    released = ps.HeavyTop(i1, i3, mgl, theta0, psi_dot=40.0)
    t1, t2 = released.turning_points
    con.print(
        f"  released at rest instead ({released.motion_class}): it nutates by {t2 - t1:.2e} rad and drifts at "
        f"⟨φ̇⟩ = {released.mean_precession_rate:.6f} rad/s — close to the slow rate: "
        '"it is normally the slow precession that is observed"'
    )


def _axis_heading(q: np.ndarray) -> np.ndarray:
    """Heading (rad, clockwise from north) of body z under the attitudes ``q`` [w, x, y, z]
    (N, 4), body → local ENU."""
    w, x, y, z = np.asarray(q, dtype=float).T
    return np.arctan2(2 * (x * z + w * y), 2 * (y * z - w * x))


@section("Tops on the turning Earth: Foucault's gyroscope (1852) and the gyrocompass")
def _turning_earth(con: Console) -> None:
    paris = np.radians(48.8566)
    omega = ps.Earth().rotation_rate
    north = [np.cos(np.pi / 4), -np.sin(np.pi / 4), 0.0, 0.0]  # body z along local north
    span = 60.0  # s: the drift's first minute (later the axis rises on its cone about the pole)
    run = ps.simulate(
        [1.0, 1.0, 2.0],
        [0.0, 0.0, 1000.0],
        span,
        carried_by=ps.Place(paris),
        attitude0=north,
        method="exact",
        samples=2,
    )
    assert isinstance(run, ps.CarriedTrajectory)
    drift = np.degrees(np.diff(_axis_heading(run.relative_attitude))[0]) * 3600 / span
    con.print(
        "Foucault's free gyroscope in Paris (48.86° N), its axis level toward north: seen "
        "from the ground it turns clockwise, like his pendulum; in space it stays put. "
        "Anschütz's gyrocompass (1908) hangs the rotor like a pendulum so that gravity "
        "torques it onto the meridian."
    )
    tuned = ps.Gyrocompass.schuler_tuned(np.radians(50.0))
    schuler = ps.Gyrocompass.schuler_period()
    knot, lat50 = 1852 / 3600, np.radians(50.0)
    compass = ps.Gyrocompass(lat50)
    exact = np.degrees(compass.speed_error(20 * knot, 0.0))
    small = np.degrees(compass.speed_error_small_angle(20 * knot, 0.0))
    table = _table("quantity", "poinsot", "check")
    table.add_row(
        "Foucault's gyroscope, drift",
        f"{drift:.3f} °/h",
        f"Ω sin λ = {np.degrees(omega * np.sin(paris)) * 3600:.3f} °/h",
    )
    table.add_row(
        "Schuler-tuned compass, 50° N",
        f"{tuned.period / 60:.4g} min",
        f"2π√(R/g) = {schuler / 60:.4g} min",
    )
    table.add_row("speed error, 20 kn north, 50° N", f"{exact:+.3f}°", f"small-angle {small:+.3f}°")
    con.print(table)
    con.print(
        "  a ship steaming north carries the compass's horizontal rotation west of north: it "
        "reads high; `poinsot gyrocompass --latitude 50deg --speed 20kn --plot FILE`, "
        "`poinsot derive gyrocompass`"
    )


@section(
    "The Earth as a rigid body: Euler's free wobble (eq. 2.83) and the precession of the equinoxes"
)
def _rigid_earth(con: Console) -> None:
    e = ps.RigidEarth()
    h, day = e.dynamical_flattening, 2 * np.pi / e.rotation_rate
    arcsec, year = np.pi / 648_000, 365.25 * 86_400.0
    con.print(
        f"The Earth is the unit's symmetric top: H = (C − A)/C = {h:.9g} (IERS 2010), one turn "
        "a sidereal day, torqued by the Sun and the Moon on its bulge."
    )
    table = _table("quantity", "poinsot", "check / measured")
    table.add_row(
        "Euler: 2π/|Ω| (2.83)",
        f"{e.euler_period / day:.6g} sidereal d",
        f"(1 − H)/H = {(1 - h) / h:.6g}",
    )
    try:  # the observed period from the catalogue (vicente-wilson-1997; needs pint)
        from poinsot import experiments as x

        seen = x.parse(x.get("vicente-wilson-1997").measured).to("day").magnitude
        observed = f"{seen:.4g} d (Vicente & Wilson)"
    except ImportError:
        observed = "— (needs pint)"
    k2, ks = 0.30, 0.938  # the elastic and the fluid Love numbers (Lambeck 1980)
    chandler = e.chandler_period(k2, ks) / 86_400
    table.add_row(f"Chandler, k2 {k2:g}", f"{chandler:.4g} d", observed)
    rate = -e.precession_rate * year / arcsec
    iau = ps.IAU2006_PRECESSION_RATE * year / arcsec
    table.add_row("precession (westward)", f"{rate:.3f} ″/yr", f"IAU 2006 {iau:.3f} ″/yr")
    dpsi, deps = (x / arcsec for x in e.nutation_amplitudes)
    ref = [x / arcsec for x in ps.IAU2000A_PRINCIPAL_NUTATION]
    table.add_row("nutation Δψ₀, Δε₀", f"{dpsi:.4g}″, {deps:.4g}″", f"{ref[0]:.5g}″, {ref[1]:.5g}″")
    con.print(table)
    con.print(
        "  the Chandler wobble is slower than Euler's (the mantle yields; the oceans and the "
        "core do the rest); `poinsot earth --plot FILE`, `poinsot derive rigid_earth`"
    )


@section("The unit against the world: published measurements, reproduced (poinsot.experiments)")
def _experiments(con: Console) -> None:
    try:
        from poinsot import experiments
    except ImportError:
        con.print("(needs pint: pip install 'poinsot[units]')")
        return
    firsts: dict[str, experiments.Experiment] = {}
    for e in experiments.catalogue():
        firsts.setdefault(e.topic, e)
    results = [e.run() for e in firsts.values()]
    con.print(
        f"The catalogue holds {len(experiments.catalogue())} published measurements, each "
        "recomputed through poinsot's public API from its inputs as published (Paris feet and "
        "lines read by pint); the first of each topic:"
    )
    table = _table("experiment", "measured", "poinsot")
    table.add_column("verdict")
    for r in results:
        table.add_row(
            f"{r.title} ({r.year})",
            r.shown_measured(),
            r.shown("predicted"),
            r.short_verdict,
        )
    con.print(table)
    con.print(
        "  all of them, with their sources: `poinsot experiments`, `poinsot experiments NAME`"
    )


def heading(con: Console, title: str) -> None:
    """A section's heading: a rule across the console, then the title in bold, wrapped at the
    console's width (a rule's own title is cut with "…" where it does not fit: at 80 columns
    most of the unit's headings did not)."""
    con.print()
    con.rule(style="blue")
    con.print(Text(title, style="bold"))


def run_tour(console: Console | None = None) -> None:
    """Print every section of the tour to ``console`` (a new rich Console by default)."""
    con = console or Console()
    con.print(
        Panel.fit(
            f"[bold]poinsot {ps.__version__}[/bold] — moving frames and the motion "
            "of rigid bodies\nthe course unit, computed",
            border_style="blue",
        )
    )
    for i, (title, fn) in enumerate(_SECTIONS, start=1):
        heading(con, f"{i}. {title}")
        fn(con)
    con.rule()
    con.print("More, all installed with poinsot: every command's --help (`poinsot --help` lists")
    con.print("them), the lab in your browser (`poinsot lab`), the teaching notebooks")
    con.print("(`poinsot notebooks DIR` copies them out), problem sets with checked answers for")
    con.print("teachers (`poinsot exercises TOPIC`, `poinsot check`). The documentation:")
    con.print(docs_url(), markup=False, highlight=False, soft_wrap=True)


#: The documentation site: pyproject.toml's [project.urls] Documentation, read from the installed
#: package's metadata; this copy only where the metadata is missing (a test keeps them equal).
DOCS_URL = "https://poinsot.github.io/poinsot/"


def docs_url() -> str:
    """The documentation site's address, as the installed package's metadata gives it."""
    from importlib.metadata import PackageNotFoundError, metadata

    try:
        entries = metadata("poinsot").get_all("Project-URL") or []
    except PackageNotFoundError:
        entries = []
    for entry in entries:
        label, _, url = entry.partition(",")
        if label.strip().lower() == "documentation":
            return url.strip()
    return DOCS_URL
