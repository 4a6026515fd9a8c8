"""Pictures of torque-free motion (matplotlib, the optional ``plot`` extra).

Every function returns a :class:`matplotlib.figure.Figure` (or an animation) and never calls
``plt.show()``. The physics comes from :class:`poinsot.FreeRigidBody`,
:class:`poinsot.FreeSymmetricTop` and :func:`poinsot.simulate`; these functions only draw.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from ..dynamics import Trajectory
from ..free import FreeRigidBody, FreeSymmetricTop
from ..rotation import quaternion_to_matrix, rotate_vectors
from ._mpl import pyplot as _pyplot
from ._mpl import save_animation

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

__all__ = ["plot_omega", "plot_cones", "plot_polhodes", "plot_conservation", "animate_tumbling_box"]


def _rotate(q: np.ndarray, v: np.ndarray) -> np.ndarray:
    """R(q) v for attitudes q (..., 4) [w, x, y, z] and body vectors v (..., 3), by the core."""
    return rotate_vectors(quaternion_to_matrix(q, normalize=True), v)


def plot_omega(
    trajectory: Trajectory,
    exact: FreeRigidBody | None = None,
    ax: Any = None,
    *,
    title: str | None = None,
) -> Figure:
    """ω components (body, rad/s) against time from ``trajectory``, with the exact solution
    ``exact`` overlaid as thin black lines when given."""
    plt = _pyplot()
    if ax is None:
        fig, ax = plt.subplots(figsize=(9, 4))
    else:
        fig = ax.figure
    for k, color in enumerate(("C0", "C1", "C2")):
        ax.plot(
            trajectory.t,
            trajectory.omega[:, k],
            color=color,
            lw=2.2,
            alpha=0.7,
            label=f"ω{k + 1} ({trajectory.method})",
        )
    if exact is not None:
        t = np.linspace(trajectory.t[0], trajectory.t[-1], 2000)
        om = exact.omega(t)
        for k in range(3):
            ax.plot(t, om[:, k], color="k", lw=0.8, ls="--", label="exact" if k == 0 else None)
    ax.set_xlabel("t (s)")
    ax.set_ylabel("ω, body components (rad/s)")
    ax.legend(loc="upper right", ncol=4, fontsize=8)
    ax.set_title(title or "angular velocity in the body")
    return fig


def _cone(
    ax: Any, axis: np.ndarray, half_angle: float, height: float, color: str, label: str
) -> None:
    axis = axis / np.linalg.norm(axis)
    helper = np.array([1.0, 0, 0]) if abs(axis[0]) < 0.9 else np.array([0, 1.0, 0])
    e1 = np.cross(axis, helper)
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(axis, e1)
    phi = np.linspace(0, 2 * np.pi, 60)
    r = np.linspace(0, height, 10)
    pp, rr = np.meshgrid(phi, r)
    rad = rr * np.tan(half_angle)
    pts = rr[..., None] * axis + rad[..., None] * (
        np.cos(pp)[..., None] * e1 + np.sin(pp)[..., None] * e2
    )
    ax.plot_surface(pts[..., 0], pts[..., 1], pts[..., 2], color=color, alpha=0.25, linewidth=0)
    ax.plot(
        [0, height * axis[0]],
        [0, height * axis[1]],
        [0, height * axis[2]],
        color=color,
        lw=2,
        label=label,
    )


def plot_cones(top: FreeSymmetricTop, t: float = 0.0, ax: Any = None) -> Figure:
    """The body cone (half-angle α_b about the symmetry axis, 2.90) and the space cone (α_s
    about L, 2.97) at time ``t`` in space, touching along ω: prolate tops roll the body cone on
    the outside of the space cone, oblate ones around it."""
    plt = _pyplot()
    if ax is None:
        fig = plt.figure(figsize=(6, 6))
        ax = fig.add_subplot(projection="3d")
    else:
        fig = ax.figure
    ell = top.angular_momentum
    e3 = top.symmetry_axis(t)
    q = top.attitude(t)
    w = _rotate(q, top.omega(t))
    h = 1.0
    _cone(ax, ell, top.space_cone_angle, h, "C0", "space cone about L")
    body_axis = e3 if np.dot(e3, w) >= 0 else -e3
    _cone(
        ax,
        body_axis,
        min(top.body_cone_angle, np.pi - top.body_cone_angle),
        h,
        "C1",
        "body cone about e₃",
    )
    wn = w / np.linalg.norm(w) * h / np.cos(top.space_cone_angle)
    ax.plot([0, wn[0]], [0, wn[1]], [0, wn[2]], color="k", lw=2.5, label="ω (contact line)")
    trace = _rotate(
        top.attitude(np.linspace(0, 2 * np.pi / max(top.space_precession_rate, 1e-12), 200)),
        top.omega(np.linspace(0, 2 * np.pi / max(top.space_precession_rate, 1e-12), 200)),
    )
    trace = trace / np.linalg.norm(trace, axis=1)[:, None] * h / np.cos(top.space_cone_angle)
    ax.plot(trace[:, 0], trace[:, 1], trace[:, 2], color="C0", lw=1)
    ax.set_box_aspect((1, 1, 1))
    lim = 1.2 * h
    ax.set(xlim=(-lim, lim), ylim=(-lim, lim), zlim=(-lim, lim), xlabel="X", ylabel="Y", zlabel="Z")
    ax.legend(loc="upper left", fontsize=8)
    ax.set_title(
        f"{top.shape} top: α_b = {np.degrees(top.body_cone_angle):.2f}°, "
        f"α_s = {np.degrees(top.space_cone_angle):.2f}°"
    )
    return fig


def plot_polhodes(
    moments: Any = (1.0, 2.0, 3.0), energy: float = 0.5, n: int = 13, ax: Any = None
) -> Figure:
    """Polhodes on the energy ellipsoid ω·I·ω = 2T of a body with principal ``moments``: the
    curves ω traces in the body for |L| from √(2T I₁) to √(2T I₃), closed loops about the
    smallest- and largest-moment axes, and the separatrix (red) through the intermediate
    axis."""
    plt = _pyplot()
    m = np.asarray(moments, dtype=float)
    if ax is None:
        fig = plt.figure(figsize=(6.5, 6))
        ax = fig.add_subplot(projection="3d")
    else:
        fig = ax.figure
    a = np.sqrt(2 * energy / m)
    u, v = np.meshgrid(np.linspace(0, 2 * np.pi, 48), np.linspace(0, np.pi, 24))
    ax.plot_surface(
        a[0] * np.cos(u) * np.sin(v),
        a[1] * np.sin(u) * np.sin(v),
        a[2] * np.cos(v),
        color="0.85",
        alpha=0.35,
        linewidth=0,
    )
    order = np.argsort(m)
    lo, mid, hi = order
    for frac in np.linspace(0.04, 0.96, n):
        # |L|² = 2T (I_lo + frac (I_hi − I_lo)); start on the ellipsoid in the (lo, hi) plane.
        l2 = 2 * energy * (m[lo] + frac * (m[hi] - m[lo]))
        # ω_lo, ω_hi with I_lo ω_lo² + I_hi ω_hi² = 2T, I_lo² ω_lo² + I_hi² ω_hi² = L².
        w_hi2 = (l2 - 2 * energy * m[lo]) / (m[hi] * (m[hi] - m[lo]))
        w_lo2 = (2 * energy - m[hi] * w_hi2) / m[lo]
        for sign in (1.0, -1.0):
            w0 = np.zeros(3)
            w0[lo], w0[hi] = np.sqrt(max(w_lo2, 0.0)), sign * np.sqrt(max(w_hi2, 0.0))
            if abs(l2 - 2 * energy * m[mid]) < 1e-9 * l2 or not np.any(w0):
                continue
            body = FreeRigidBody(m, w0)
            p = body.polhode(300)
            ax.plot(p[:, 0], p[:, 1], p[:, 2], color="C0", lw=1)
    # The separatrix: |L|² = 2T I_mid, through ±e_mid.
    w0 = np.zeros(3)
    w_hi2 = 2 * energy * (m[mid] - m[lo]) / (m[hi] * (m[hi] - m[lo]))
    w0[hi], w0[lo] = np.sqrt(w_hi2), np.sqrt((2 * energy - m[hi] * w_hi2) / m[lo])
    for s_lo in (1, -1):
        for s_hi in (1, -1):
            w = w0.copy()
            w[lo] *= s_lo
            w[hi] *= s_hi
            p = FreeRigidBody(m, w).polhode(400)
            ax.plot(p[:, 0], p[:, 1], p[:, 2], color="C3", lw=1.6)
    ax.set_box_aspect(tuple(a / a.max()))
    ax.set(xlabel="ω₁", ylabel="ω₂", zlabel="ω₃")
    ax.set_title(f"polhodes on the energy ellipsoid, I = {tuple(float(x) for x in np.round(m, 3))}")
    return fig


def plot_conservation(
    trajectories: list[Trajectory], ax: Any = None, *, title: str | None = None
) -> Figure:
    """Relative energy error |ΔE/E| (solid) and momentum error |Δ|L|/|L|| (dotted) of each
    trajectory against time, on log axes (errors below 1e-17 are drawn at 1e-17)."""
    plt = _pyplot()
    if ax is None:
        fig, ax = plt.subplots(figsize=(9, 4.5))
    else:
        fig = ax.figure
    for k, tr in enumerate(trajectories):
        color = f"C{k}"
        label = tr.method + (f" (dt = {tr.step:g})" if tr.step else "")
        t = tr.t[1:]
        ax.loglog(
            t,
            np.maximum(tr.energy_error()[1:], 1e-17),
            color=color,
            lw=1.5,
            label=f"{label}: energy",
        )
        ax.loglog(
            t,
            np.maximum(tr.momentum_error()[1:], 1e-17),
            color=color,
            lw=1,
            ls=":",
            label=f"{label}: |L|",
        )
    ax.set_xlabel("t (s)")
    ax.set_ylabel("relative error")
    ax.legend(fontsize=7, ncol=2)
    ax.set_title(title or "conservation of energy and |L|")
    return fig


def animate_tumbling_box(
    sides: Any = (2.0, 1.0, 0.4),
    spin: float = 2.0,
    wobble: float = 1e-2,
    duration: float | None = None,
    path: str | Path | None = None,
    *,
    frames: int = 240,
    fps: int = 30,
) -> Any:
    """An animation of a box (``sides`` along body x, y, z, m; the middle side along y makes y
    the intermediate axis for the default) spun at ``spin`` rad/s about body y with a small
    ``wobble`` (rad/s) about x and z: the exact free motion flips it over every
    :attr:`FreeRigidBody.flip_interval` (the Dzhanibekov effect). Saves to ``path`` (.gif with
    Pillow, else ffmpeg) if given; returns the FuncAnimation."""
    plt = _pyplot()
    from matplotlib import animation
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    a_, b_, c_ = (float(x) for x in sides)
    m = np.array([b_**2 + c_**2, a_**2 + c_**2, a_**2 + b_**2]) / 12.0  # a unit-mass cuboid
    body = FreeRigidBody(m, [wobble, spin, wobble])
    if duration is None:
        duration = 2.5 * body.period if np.isfinite(body.period) else 30.0
    t = np.linspace(0, duration, frames)
    q = body.attitude(t)
    s = np.array([a_, b_, c_]) / 2
    corners = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]) * s
    faces = [[0, 1, 3, 2], [4, 5, 7, 6], [0, 1, 5, 4], [2, 3, 7, 6], [0, 2, 6, 4], [1, 3, 7, 5]]
    colors = ["C0", "C0", "C1", "C1", "C2", "C2"]
    fig = plt.figure(figsize=(5.5, 5.5))
    ax = fig.add_subplot(projection="3d")
    lim = 1.1 * np.linalg.norm(s)
    ax.set(xlim=(-lim, lim), ylim=(-lim, lim), zlim=(-lim, lim))
    ax.set_box_aspect((1, 1, 1))
    ax.set_axis_off()
    poly = Poly3DCollection([], edgecolor="k", linewidths=0.6)
    ax.add_collection3d(poly)
    text = ax.text2D(0.02, 0.95, "", transform=ax.transAxes)

    def update(i: int) -> Any:
        pts = _rotate(np.broadcast_to(q[i], (8, 4)), corners)
        poly.set_verts([pts[f] for f in faces])
        poly.set_facecolor(colors)
        text.set_text(f"t = {t[i]:5.2f} s   (flip every {body.flip_interval:.2f} s)")
        return poly, text

    anim = animation.FuncAnimation(fig, update, frames=frames, interval=1000 / fps, blit=False)
    if path is not None:
        save_animation(anim, path, fps)
    return anim
