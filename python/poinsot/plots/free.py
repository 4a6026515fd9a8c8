"""Pictures of torque-free motion (matplotlib, the optional ``plot`` extra).

The physics comes from :class:`poinsot.FreeRigidBody`, :class:`poinsot.FreeSymmetricTop` and
:func:`poinsot.simulate`; these functions only draw (see :mod:`poinsot.plots`).
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from ..dynamics import Trajectory
from ..free import FreeRigidBody, FreeSymmetricTop
from ..rotation import quaternion_to_matrix, rotate_vectors
from ._axes import cube_limits, few_ticks, label_3d
from ._mpl import figure_style, func_animation, line_width, new_figure, save_animation, subplots

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

__all__ = [
    "plot_omega",
    "plot_cones",
    "plot_polhodes",
    "plot_conservation",
    "animate_tumbling_box",
    "animate_free_body",
]


def _rotate(q: np.ndarray, v: np.ndarray) -> np.ndarray:
    """R(q) v for attitudes q (..., 4) [w, x, y, z] and body vectors v (..., 3), by the core."""
    return rotate_vectors(quaternion_to_matrix(q, normalize=True), v)


def plot_omega(
    trajectory: Trajectory,
    exact: FreeRigidBody | None = None,
    ax: Any = None,
    *,
    title: str | None = None,
    style: str = "paper",
) -> Figure:
    """ω components in the body (rad/s) against time (s) from ``trajectory`` (Euler's
    equations 2.71–2.76 integrated by :func:`poinsot.simulate`), with the exact solution
    ``exact`` overlaid as thin dashed black lines when given.

    ``style`` is ``"paper"`` (default) or ``"slides"``; ``ax`` a matplotlib axes to draw into
    (a new figure if None). Returns the figure.
    """
    with figure_style(style) as style:
        if ax is None:
            fig, ax = subplots(style, 9.0, 4.0)
        else:
            fig = ax.figure
        for k, color in enumerate(("C0", "C1", "C2")):
            ax.plot(
                trajectory.t,
                trajectory.omega[:, k],
                color=color,
                alpha=0.7,
                label=f"ω{'₁₂₃'[k]} ({trajectory.method})",
            )
        if exact is not None:
            t = np.linspace(trajectory.t[0], trajectory.t[-1], 2000)
            om = exact.omega(t)
            for k in range(3):
                ax.plot(
                    t,
                    om[:, k],
                    color="k",
                    lw=0.4 * line_width(),
                    ls="--",
                    label="exact" if k == 0 else None,
                )
        ax.set(xlabel="t (s)", ylabel="ω, body components (rad/s)")
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
        ax.set_title(title or "angular velocity in the body")
    return fig


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v)


def _basis(axis: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Two unit vectors completing the unit ``axis`` to a right-handed frame."""
    helper = np.array([1.0, 0, 0]) if abs(axis[0]) < 0.9 else np.array([0, 1.0, 0])
    e1 = _unit(np.cross(axis, helper))
    return e1, np.cross(axis, e1)


def _rim(axis: np.ndarray, half_angle: float, n: int = 181) -> np.ndarray:
    """Unit vectors at ``half_angle`` from the unit ``axis`` (the rim of a cone), (n, 3)."""
    e1, e2 = _basis(axis)
    phi = np.linspace(0.0, 2.0 * np.pi, n)[:, None]
    return np.cos(half_angle) * axis + np.sin(half_angle) * (np.cos(phi) * e1 + np.sin(phi) * e2)


def _cone(
    ax: Any, axis: np.ndarray, half_angle: float, height: float, color: str, label: str
) -> np.ndarray:
    """A cone of ``half_angle`` about ``axis`` with its apex at the origin, drawn to
    ``height`` along the axis in 3-D; returns the points drawn."""
    axis = _unit(axis)
    rim = _rim(axis, half_angle, 60) / np.cos(half_angle) * height
    r = np.linspace(0.0, 1.0, 8)[:, None, None]
    pts = r * rim[None]
    ax.plot_surface(pts[..., 0], pts[..., 1], pts[..., 2], color=color, alpha=0.3, linewidth=0)
    ax.plot(rim[:, 0], rim[:, 1], rim[:, 2], color=color, lw=0.5 * line_width())
    ax.plot(*np.stack([np.zeros(3), height * axis], axis=1), color=color, label=label)
    return pts.reshape(-1, 3)


def _along(axis: np.ndarray, e1: np.ndarray, e2: np.ndarray, u: np.ndarray) -> np.ndarray:
    """The azimuthal equidistant projection about ``axis``: unit vectors ``u`` (..., 3) to
    (angle from the axis) × (direction in the e1, e2 plane), in degrees, (..., 2)."""
    c = np.clip(u @ axis, -1.0, 1.0)
    a, b = u @ e1, u @ e2
    s = np.hypot(a, b)
    ang = np.degrees(np.arccos(c))
    with np.errstate(invalid="ignore", divide="ignore"):
        k = np.where(s > 0, ang / np.where(s > 0, s, 1.0), 0.0)
    return np.stack([k * a, k * b], axis=-1)


def _view_across(normal: np.ndarray) -> tuple[float, float]:
    """(elevation, azimuth) in degrees of a 3-D view looking as nearly along ``normal`` as
    possible (across the plane it is normal to) while no coordinate axis points at the eye
    (its tick labels would fall on one another)."""
    best, view = -1.0, (30.0, -60.0)
    for elev in (10.0, 20.0, 30.0, 40.0, 50.0):
        for azim in np.arange(-180.0, 180.0, 5.0):
            e, a = np.radians(elev), np.radians(azim)
            eye = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
            if np.max(np.abs(eye)) > 0.85:
                continue
            score = abs(float(eye @ normal))
            if score > best:
                best, view = score, (elev, float(azim))
    return view


def plot_cones(
    top: FreeSymmetricTop, t: float = 0.0, ax: Any = None, *, style: str = "paper"
) -> Figure:
    """The body cone (half-angle α_b about the symmetry axis e₃, 2.90) and the space cone
    (half-angle α_s about L, 2.97) of a torque-free symmetric top at time ``t`` (s), touching
    along ω: a prolate top's body cone rolls on the outside of the space cone, an oblate
    top's surrounds it (the unit's Fig. 2.11).

    Two panels: the cones in space at their true angles (a 3-D view across the plane of L and
    e₃), and the same seen along L — each direction drawn at its angle from L (°), so that
    cones of a few degrees are as clear as wide ones: the space cone is the circle about L
    that ω runs round, the body cone the circle about e₃ touching it at ω, with the paths of
    ω and e₃ over one turn about L.

    Parameters
    ----------
    top:
        A :class:`poinsot.FreeSymmetricTop`.
    t:
        The time shown (s).
    ax:
        Draw one panel into this axes instead: the 3-D view into a 3-D axes, the view along
        L into a 2-D one.
    style:
        ``"paper"`` (default) or ``"slides"``.

    Returns
    -------
    matplotlib.figure.Figure
    """
    with figure_style(style) as style:
        if ax is None:
            fig = new_figure(style, 11.0, 5.5)
            # room between the panels for the 3-D view's z label, which constrained layout
            # does not see
            fig.get_layout_engine().set(wspace=0.12)
            ax3 = fig.add_subplot(1, 2, 1, projection="3d")
            ax2 = fig.add_subplot(1, 2, 2)
        else:
            fig = ax.figure
            ax3, ax2 = (ax, None) if ax.name == "3d" else (None, ax)
        ell = _unit(np.asarray(top.angular_momentum, dtype=float))
        e3 = np.asarray(top.symmetry_axis(t), dtype=float)
        w = _unit(_rotate(top.attitude(t), top.omega(t)))
        # the body cone's axis: the half of the symmetry axis on ω's side
        body_axis = e3 if np.dot(e3, w) >= 0 else -e3
        a_b = min(top.body_cone_angle, np.pi - top.body_cone_angle)
        a_s = top.space_cone_angle
        turn = 2 * np.pi / max(top.space_precession_rate, 1e-300)
        ts = t + np.linspace(0.0, turn, 181)
        w_path = _rotate(top.attitude(ts), top.omega(ts))
        w_path = w_path / np.linalg.norm(w_path, axis=1)[:, None]
        e3_path = np.asarray(top.symmetry_axis(ts), dtype=float)
        e3_path = np.where(np.einsum("ij,ij->i", e3_path, w_path)[:, None] >= 0, e3_path, -e3_path)
        space_label = f"space cone about L, α_s = {np.degrees(a_s):.3g}°"
        body_label = f"body cone about e₃, α_b = {np.degrees(a_b):.3g}°"
        if ax3 is not None:
            h = 1.0
            pts = [np.zeros((1, 3))]
            pts.append(_cone(ax3, ell, a_s, h, "C0", space_label))
            pts.append(_cone(ax3, body_axis, a_b, h, "C1", body_label))
            tip = w * h / max(np.cos(a_s), 0.05)
            ax3.plot(
                *np.stack([np.zeros(3), tip], axis=1), color="k", label="ω: the line of contact"
            )
            pts.append(tip[None])
            cube_limits(ax3, np.concatenate(pts), zoom=0.85)
            normal = np.cross(ell, body_axis)
            if np.linalg.norm(normal) > 1e-9:
                ax3.view_init(*_view_across(_unit(normal)))
            few_ticks(ax3, 4)
            label_3d(ax3, "X (1)", "Y (1)", "Z (1)")
            ax3.set_title("in space, true angles")
            if ax2 is None:
                ax3.legend(loc="upper left")
        if ax2 is not None:
            e1, e2 = _basis(ell)
            rim_s = _along(ell, e1, e2, _rim(ell, a_s))
            rim_b = _along(ell, e1, e2, _rim(body_axis, a_b))
            ax2.plot(rim_s[:, 0], rim_s[:, 1], color="C0", label=space_label)
            ax2.plot(rim_b[:, 0], rim_b[:, 1], color="C1", label=body_label)
            p = _along(ell, e1, e2, e3_path)
            ax2.plot(
                p[:, 0], p[:, 1], color="C1", ls=":", lw=0.5 * line_width(), label="path of e₃"
            )
            q = _along(ell, e1, e2, np.stack([w, body_axis]))
            ax2.plot([0.0, q[0, 0]], [0.0, q[0, 1]], color="k", lw=0.5 * line_width())
            ax2.plot([q[1, 0], q[0, 0]], [q[1, 1], q[0, 1]], color="C1", lw=0.5 * line_width())
            ax2.plot(*q[0], "o", color="k", label="ω: the line of contact")
            ax2.plot(*q[1], "s", color="C1", label="e₃")
            ax2.plot(0.0, 0.0, "P", color="C0", label="L (fixed)")
            ax2.set_aspect("equal", adjustable="datalim")
            few_ticks(ax2, 5)
            ax2.set_xlabel("angle from L, along x′ (°)")
            ax2.set_ylabel("angle from L, along y′ (°)")
            ax2.set_title("seen along L")
            ax2.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0)
        head = (
            f"{top.shape} top, I₁ = {top.I1:g}, I₃ = {top.I3:g} kg·m², t = {t:g} s: "
            f"the body cone rolls on the {top.cone_contact} of the space cone"
        )
        if ax is None:
            fig.suptitle(head)
    return fig


def plot_polhodes(
    moments: Any = (1.0, 2.0, 3.0),
    energy: float = 0.5,
    n: int = 13,
    ax: Any = None,
    *,
    style: str = "paper",
) -> Figure:
    """Polhodes on the energy ellipsoid ω·I·ω = 2T (rad/s) of a body with principal
    ``moments`` (kg·m²) and kinetic ``energy`` T (J): the curves ω traces in the body for |L|
    from √(2T I₁) to √(2T I₃) (``n`` of them), closed loops about the smallest- and
    largest-moment axes, and the separatrix (red) through the intermediate axis (Poinsot's
    construction, beyond the unit's symmetric top). ``style``: ``"paper"`` or ``"slides"``."""
    with figure_style(style) as style:
        m = np.asarray(moments, dtype=float)
        if ax is None:
            fig = new_figure(style, 6.5, 6.5)
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
                first = not ax.get_legend_handles_labels()[1]
                ax.plot(
                    p[:, 0],
                    p[:, 1],
                    p[:, 2],
                    color="C0",
                    lw=0.5 * line_width(),
                    label="polhodes" if first else None,
                )
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
                ax.plot(
                    p[:, 0],
                    p[:, 1],
                    p[:, 2],
                    color="C3",
                    label="separatrix" if (s_lo, s_hi) == (1, 1) else None,
                )
        ax.set_box_aspect(tuple(a / a.max()), zoom=0.85)
        ax.legend(loc="upper left")
        few_ticks(ax, 4)
        label_3d(ax, "ω₁ (rad/s)", "ω₂ (rad/s)", "ω₃ (rad/s)")
        shown = ", ".join(f"{x:.3g}" for x in m)
        ax.set_title(f"polhodes on the energy ellipsoid\nI = ({shown}) kg·m², T = {energy:g} J")
    return fig


def plot_conservation(
    trajectories: list[Trajectory],
    ax: Any = None,
    *,
    title: str | None = None,
    style: str = "paper",
) -> Figure:
    """Relative energy error |ΔE/E| (solid) and momentum error |Δ|L|/|L|| (dotted) of each
    trajectory against time (s), on log axes (errors below 1e-17 are drawn at 1e-17).
    ``style``: ``"paper"`` or ``"slides"``."""
    with figure_style(style) as style:
        if ax is None:
            fig, ax = subplots(style, 9.0, 4.5)
        else:
            fig = ax.figure
        for k, tr in enumerate(trajectories):
            color = f"C{k}"
            label = tr.method + (f" (dt = {tr.step:g} s)" if tr.step else "")
            t = tr.t[1:]
            ax.loglog(
                t, np.maximum(tr.energy_error()[1:], 1e-17), color=color, label=f"{label}: energy"
            )
            ax.loglog(
                t,
                np.maximum(tr.momentum_error()[1:], 1e-17),
                color=color,
                lw=0.7 * line_width(),
                ls=":",
                label=f"{label}: |L|",
            )
        ax.set(xlabel="t (s)", ylabel="relative error (1)")
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
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
    style: str = "paper",
    progress: Callable[[int, int], Any] | None = None,
) -> Any:
    """An animation of a box (``sides`` along body x, y, z, m; the middle side along y makes y
    the intermediate axis for the default) spun at ``spin`` rad/s about body y with a small
    ``wobble`` (rad/s) about x and z: the exact free motion flips it over every
    :attr:`FreeRigidBody.flip_interval` (the Dzhanibekov effect).

    Saves to ``path`` (.gif with Pillow, .mp4 with ffmpeg) if given, calling
    ``progress(frame, frames)`` after each frame written; returns the FuncAnimation (its
    figure is ``anim._fig``). ``style``: ``"paper"`` or ``"slides"``.
    """
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    with figure_style(style) as style:
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
        fig = new_figure(style, 5.5, 5.5)
        ax = fig.add_subplot(projection="3d")
        lim = 1.05 * np.linalg.norm(s)
        ax.set(xlim=(-lim, lim), ylim=(-lim, lim), zlim=(-lim, lim))
        ax.set_box_aspect((1, 1, 1), zoom=1.1)
        ax.set_axis_off()
        poly = Poly3DCollection([], edgecolor="k", linewidths=0.6)
        ax.add_collection3d(poly)
        ax.set_title(
            f"box {a_:g} × {b_:g} × {c_:g} m spun about its middle axis\n"
            f"flips every {body.flip_interval:.3g} s"
        )
        text = ax.text2D(0.02, 0.02, "", transform=ax.transAxes)

        def update(i: int) -> Any:
            pts = _rotate(np.broadcast_to(q[i], (8, 4)), corners)
            poly.set_verts([pts[f] for f in faces])
            poly.set_facecolor(colors)
            text.set_text(f"t = {t[i]:5.2f} s")
            return poly, text

        anim = func_animation(fig, update, frames, fps)
    if path is not None:
        save_animation(anim, path, fps, progress=progress)
    return anim


def animate_free_body(
    body: FreeRigidBody,
    path: str | Path | None = None,
    *,
    duration: float | None = None,
    frames: int = 200,
    fps: int = 25,
    trail: int = 60,
    style: str = "paper",
    progress: Callable[[int, int], Any] | None = None,
) -> Any:
    """An animation of the exact torque-free motion of ``body`` (a
    :class:`poinsot.FreeRigidBody`) in space: its principal axes e₁, e₂, e₃ with the three
    principal sections of its inertia ellipsoid (semi-axes ∝ 1/√Iᵢ, scaled so the longest is
    1), the fixed angular momentum L and the angular velocity ω with the trail of its
    direction (Poinsot's picture, eqs. 2.71–2.97; the flips of Dzhanibekov's wing nut near the
    separatrix).

    ``duration`` (s; default two periods of ω, or 20 s for a steady rotation) is shown in
    ``frames`` frames at ``fps``. Saved to ``path`` if given (``.gif`` with Pillow, ``.mp4``
    with ffmpeg), calling ``progress(frame, frames)`` after each frame written; returns the
    :class:`matplotlib.animation.FuncAnimation` (its figure is ``anim._fig``). ``style``:
    ``"paper"`` or ``"slides"``.
    """

    with figure_style(style) as style:
        period = body.period
        if duration is None:
            duration = 2.0 * period if np.isfinite(period) and period > 0 else 20.0
        t = np.linspace(0.0, duration, frames)
        rot = quaternion_to_matrix(body.attitude(t), normalize=True)
        moments = np.asarray(body.moments, dtype=float)
        semi = 1.0 / np.sqrt(moments)
        semi = semi / semi.max()
        ell = np.asarray(body.angular_momentum, dtype=float)
        ell = ell / np.linalg.norm(ell)
        w = body.herpolhode(t)
        w = w / np.linalg.norm(w, axis=1)[:, None]
        a = np.linspace(0.0, 2.0 * np.pi, 73)
        c, s_ = np.cos(a), np.sin(a)
        sections = []  # the ellipse in the plane of axes (i, j), in body components
        for i, j in ((0, 1), (1, 2), (2, 0)):
            e = np.zeros((a.size, 3))
            e[:, i], e[:, j] = semi[i] * c, semi[j] * s_
            sections.append(e)
        fig = new_figure(style, 6.0, 6.0)
        ax = fig.add_subplot(projection="3d")
        ax.set(xlim=(-1.15, 1.15), ylim=(-1.15, 1.15), zlim=(-1.15, 1.15))
        ax.set_box_aspect((1, 1, 1), zoom=0.9)
        few_ticks(ax, 4)
        for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
            axis.set_ticks([-1.0, 0.0, 1.0])
        label_3d(ax, "X (1)", "Y (1)", "Z (1)")
        ax.plot(*np.stack([np.zeros(3), 1.1 * ell], axis=1), "--", color="k", label="L (fixed)")
        colors = ("C3", "C2", "C4")
        axes_lines = [
            ax.plot(
                [],
                [],
                [],
                color=colors[k],
                label=f"e{'₁₂₃'[k]}, I{'₁₂₃'[k]} = {moments[k]:.3g} kg·m²",
            )[0]
            for k in range(3)
        ]
        rings = [ax.plot([], [], [], color="0.5", lw=0.4 * line_width())[0] for _ in sections]
        (omega_line,) = ax.plot([], [], [], color="C0", marker="o", markevery=[1], label="ω")
        (omega_trail,) = ax.plot([], [], [], color="C0", lw=0.4 * line_width(), alpha=0.7)
        ax.legend(loc="upper left", bbox_to_anchor=(0.0, 1.0))
        ax.set_title(f"free body: {body.regime}, period of ω {period:.4g} s")
        text = ax.text2D(0.98, 0.02, "", transform=ax.transAxes, ha="right")

        def update(k: int) -> tuple[Any, ...]:
            r = rot[k]
            for i, line in enumerate(axes_lines):
                tip = r[:, i] * semi[i]
                line.set_data_3d([-tip[0], tip[0]], [-tip[1], tip[1]], [-tip[2], tip[2]])
            for ring, e in zip(rings, sections):
                p = e @ r.T
                ring.set_data_3d(p[:, 0], p[:, 1], p[:, 2])
            omega_line.set_data_3d([0, w[k, 0]], [0, w[k, 1]], [0, w[k, 2]])
            lo = max(0, k - trail)
            omega_trail.set_data_3d(w[lo : k + 1, 0], w[lo : k + 1, 1], w[lo : k + 1, 2])
            text.set_text(f"t = {t[k]:.2f} s")
            return (*axes_lines, *rings, omega_line, omega_trail, text)

        anim = func_animation(fig, update, frames, fps)
    if path is not None:
        save_animation(anim, path, fps, progress=progress)
    return anim
