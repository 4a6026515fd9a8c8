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


@section("Euler's theorem: any rotation about a fixed point is one rotation about one axis")
def _euler_theorem(con: Console) -> None:
    angles = np.radians([30.0, 60.0, 45.0])
    R = ps.euler_to_matrix(angles)
    axis, angle = ps.rotation_axis(R)
    con.print("Euler angles (φ, θ, ψ) = (30°, 60°, 45°), intrinsic z-x-z as in the unit:")
    con.print(f"  R = R_z(φ) R_x(θ) R_z(ψ) =\n{np.array2string(R, precision=6, suppress_small=True)}")
    con.print(f"  one rotation about axis n = {_vec(axis)} by {np.degrees(angle):.6f}°")
    con.print(f"  check: |R n − n| = {np.linalg.norm(R @ axis - axis):.1e} (the axis is left fixed)")
    back = ps.matrix_to_euler(R, degrees=True)
    con.print(f"  and back to Euler angles: {_vec(back, 10)} °")


@section("Chasles' theorem: any displacement is a screw motion")
def _chasles(con: Console) -> None:
    R = ps.axis_angle_to_matrix([0.0, 0.0, 1.0], np.pi / 2)
    t = np.array([1.0, 1.0, 0.5])
    s = ps.screw_axis(R, t)
    con.print("x ↦ R x + t with R = 90° about z and t = (1, 1, 0.5) m is a screw:")
    con.print(f"  axis {_vec(s.axis)} through the point {_vec(s.point)} m")
    con.print(f"  rotation {np.degrees(s.angle):.6g}°, slide {s.slide:.6g} m, pitch {s.pitch:.6g} m/rad")


@section("Euler's angles: angular velocity from the angle rates (eq. 2.99)")
def _euler_rates(con: Console) -> None:
    angles = np.radians([20.0, 40.0, 10.0])
    rates = np.array([0.5, 0.2, 3.0])
    w = ps.body_angular_velocity(angles, rates)
    phi, theta, psi = angles
    dphi, dtheta, dpsi = rates
    unit = np.array([dtheta * np.cos(psi) + dphi * np.sin(theta) * np.sin(psi),
                     -dtheta * np.sin(psi) + dphi * np.sin(theta) * np.cos(psi),
                     dpsi + dphi * np.cos(theta)])
    con.print("φ, θ, ψ = 20°, 40°, 10°; φ̇, θ̇, ψ̇ = 0.5, 0.2, 3.0 rad/s:")
    con.print(f"  poinsot ω (body)  = {_vec(w, 12)} rad/s")
    con.print(f"  the unit's 2.99   = {_vec(unit, 12)} rad/s")
    try:
        ps.euler_rates([0.3, 0.0, 0.2], [0.1, 0.2, 0.3])
    except ps.GimbalLockError as exc:
        con.print(f"  at θ = 0 the rates are undefined (gimbal lock): [italic]{exc}[/italic]")


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
    table = Table(title=f"m = {m} kg, r = {r} m, h = l = {h} m")
    table.add_column("body")
    table.add_column("principal moments (kg·m²)", justify="right")
    table.add_column("textbook")
    table.add_column("kind")
    for name, body, formula in rows:
        table.add_row(name, ", ".join(f"{x:.6g}" for x in body.principal_moments), formula, body.kind)
    con.print(table)


@section("Angular momentum is not parallel to ω: the unit's dumbbell (eqs. 2.58–2.59)")
def _dumbbell(con: Console) -> None:
    m, r, alpha, omega = 1.0, 0.5, np.radians(30.0), 2.0
    direction = np.array([np.sin(alpha), 0.0, np.cos(alpha)])
    body = ps.RigidBody.from_point_masses([m, m], [r * direction, -r * direction])
    w = np.array([0.0, 0.0, omega])
    L = body.angular_momentum(w)
    N = body.holding_torque(w)
    cos = L @ w / (np.linalg.norm(L) * np.linalg.norm(w))
    con.print("two 1 kg masses at ±0.5 m on a massless rod tilted 30° from the spin axis z, ω = 2 rad/s:")
    con.print(f"  L = I·ω = {_vec(L)} kg·m²/s, at {np.degrees(np.arccos(cos)):.4f}° from ω")
    con.print(f"  torque needed to keep ω fixed, ω × L = {_vec(N)} N·m")
    con.print(f"  closed form |N| = m r² ω² sin 2α = {m * r**2 * omega**2 * np.sin(2 * alpha):.6g} N·m"
              " (2 masses × m r² ω² sinα cosα)")


def run_tour(console: Console | None = None) -> None:
    """Print every section of the tour to ``console`` (a new rich Console by default)."""
    con = console or Console()
    con.print(Panel.fit(f"[bold]poinsot {ps.__version__}[/bold] — moving frames and the motion "
                        "of rigid bodies\nthe course unit, computed", border_style="blue"))
    for i, (title, fn) in enumerate(_SECTIONS, start=1):
        con.rule(f"[bold]{i}. {title}")
        fn(con)
    con.rule()
    con.print("More: `poinsot inertia --help`, the examples/ folder, and the docs/ pages.")
