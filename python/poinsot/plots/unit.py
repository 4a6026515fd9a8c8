"""The unit's own figures (Figs. 2.1–2.15), drawn from poinsot's numbers.

Each figure of the course unit has a counterpart here: a plot function of this module, or an
existing one of :mod:`poinsot.plots` that already is the figure (the cones, V(θ)).
:data:`UNIT_FIGURES` maps the unit's figure number to its function and a caption, and
:func:`unit_figure` draws one by number, with the classroom example's numbers::

    from poinsot.plots import unit_figure
    unit_figure("2.5", style="slides").savefig("coriolis.png")

Every number drawn — positions, arrows, angles, tracks, the values written beside them — comes
from poinsot's public API (:class:`poinsot.MovingFrame`, :class:`poinsot.Earth`,
:class:`poinsot.RigidBody`, :class:`poinsot.FreeSymmetricTop`, :class:`poinsot.HeavyTop`, the
rotation functions); these functions only choose what to show and where. Arrows of
accelerations and angular velocities are drawn in directions exact and lengths proportional
within one picture (the scale is said in the figure); the value beside an arrow is the
computed one, with its unit.

Every function takes ``style="paper"`` (a page, the default) or ``"slides"`` (a projector),
returns a :class:`matplotlib.figure.Figure` and never calls ``plt.show()``.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from .._validate import as_choice, as_float_array, as_scalar, as_vector3
from ..body import RigidBody
from ..earth import Earth
from ..errors import PoinsotError
from ..frames import MovingFrame
from ..free import FreeSymmetricTop
from ..rotation import (
    axis_angle_to_matrix,
    body_angular_velocity,
    euler_to_matrix,
    rotate_vectors,
    rotation_axis,
    space_angular_velocity,
)
from ..top import HeavyTop
from ._mpl import figure_style, new_figure, subplots

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

__all__ = [
    "plot_translating_frame",
    "plot_rotating_frame",
    "plot_centripetal",
    "plot_earth_centrifugal",
    "plot_earth_coriolis",
    "plot_flow_into_low",
    "plot_euler_theorem",
    "plot_dumbbell",
    "plot_body_cone",
    "plot_euler_angle_steps",
    "plot_omega_components",
    "plot_heavy_top",
    "classroom_free_top",
    "classroom_heavy_top",
    "UnitFigure",
    "UNIT_FIGURES",
    "unit_figure",
]

# Colours of the quantities, the same in every figure of the unit.
_FIXED = "0.45"  # fixed (inertial) axes
_MOVING = "C0"  # moving / rotating / body axes
_POSITION = "k"
_OMEGA = "C2"  # angular velocities
_ACCEL = "C3"  # accelerations
_VELOCITY = "C1"  # velocities
_MOMENTUM = "C4"  # angular momentum
_TORQUE = "C5"

#: A quantity computed from numbers of size S is zero at the computation's precision when it is
#: below this many times S (a few ε).
_ROUND_OFF = 8 * float(np.finfo(float).eps)

_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


# ---------------------------------------------------------------------------------------------
# Formatting and drawing helpers (no physics)
# ---------------------------------------------------------------------------------------------
def _num(x: float, digits: int = 3, *, scale: float = 0.0) -> str:
    """``x`` with ``digits`` significant digits: plain between 0.01 and 10⁴, else as
    m×10ⁿ; ``"0"`` when ``|x|`` is below the round-off of a computation on numbers of size
    ``scale`` (a few ε × scale), so that a component that is zero at the computation's
    precision reads 0."""
    x = float(x)
    if x == 0.0 or abs(x) <= _ROUND_OFF * abs(scale):
        return "0"
    a = abs(x)
    if 1e-2 <= a < 1e4:
        text = f"{x:#.{digits}g}".rstrip(".")
    else:
        e = math.floor(math.log10(a))
        m = x / 10.0**e
        if round(abs(m), digits - 1) >= 10.0:
            e, m = e + 1, m / 10.0
        text = f"{m:.{digits - 1}f}×10{str(e).translate(_SUPERSCRIPT)}"
    return text.replace("-", "−")


def _deg(angle_rad: float, digits: int = 3) -> str:
    return f"{np.degrees(angle_rad):.{digits}g}°"


def _vec(v: Any, digits: int = 3) -> str:
    v = np.asarray(v, dtype=float)
    scale = float(np.max(np.abs(v))) if v.size else 0.0
    return "(" + ", ".join(_num(c, digits, scale=scale) for c in v) + ")"


def _style_lw() -> float:
    """The line width of the current style (points)."""
    from matplotlib import rcParams

    return float(rcParams["lines.linewidth"])


def _arrow2d(
    ax: Any, start: Any, end: Any, color: str, gid: str, *, lw: float | None = None
) -> Any:
    """An arrow from ``start`` to ``end`` (data coordinates) whose ``gid`` names the quantity;
    ``xyann`` and ``xy`` of the returned annotation are its two ends."""
    lw = _style_lw() if lw is None else lw
    ann = ax.annotate(
        "",
        xy=tuple(np.asarray(end, dtype=float)),
        xytext=tuple(np.asarray(start, dtype=float)),
        arrowprops={
            "arrowstyle": "-|>",
            "color": color,
            "lw": lw,
            "mutation_scale": 6 * lw + 6,
            "shrinkA": 0,
            "shrinkB": 0,
        },
        annotation_clip=False,
    )
    ann.set_gid(gid)
    return ann


def _arrow3d(
    ax: Any, start: Any, end: Any, color: str, gid: str, *, lw: float | None = None
) -> Any:
    """A 3-D arrow from ``start`` to ``end`` (data coordinates, (3,)); the returned artist keeps
    them as ``.start`` and ``.end`` and its ``gid`` names the quantity."""
    lw = _style_lw() if lw is None else lw
    arrow = _Arrow3D(start, end, color=color, lw=lw, mutation_scale=6 * lw + 6)
    arrow.set_gid(gid)
    ax.add_artist(arrow)
    return arrow


def _arrow3d_class() -> Any:
    from matplotlib.patches import FancyArrowPatch
    from mpl_toolkits.mplot3d import proj3d

    class Arrow3D(FancyArrowPatch):  # type: ignore[misc]
        """A FancyArrowPatch between two 3-D points, projected at each draw."""

        def __init__(self, start: Any, end: Any, **kwargs: Any) -> None:
            super().__init__(
                (0.0, 0.0), (0.0, 0.0), arrowstyle="-|>", shrinkA=0, shrinkB=0, **kwargs
            )
            self.start = np.asarray(start, dtype=float)
            self.end = np.asarray(end, dtype=float)

        def do_3d_projection(self, renderer: Any = None) -> float:
            pts = np.stack([self.start, self.end])
            axes: Any = self.axes
            xs, ys, zs = proj3d.proj_transform(pts[:, 0], pts[:, 1], pts[:, 2], axes.M)
            self.set_positions((xs[0], ys[0]), (xs[1], ys[1]))
            return float(np.min(zs))

    return Arrow3D


class _LazyArrow3D:
    """Builds the Arrow3D class on first use (matplotlib is imported only to draw)."""

    cls: Any = None

    def __call__(self, start: Any, end: Any, **kwargs: Any) -> Any:
        if _LazyArrow3D.cls is None:
            _LazyArrow3D.cls = _arrow3d_class()
        return _LazyArrow3D.cls(start, end, **kwargs)


_Arrow3D = _LazyArrow3D()


def _label3d(ax: Any, at: Any, text: str, gid: str, color: str = "k", **kwargs: Any) -> Any:
    p = np.asarray(at, dtype=float)
    t = ax.text(p[0], p[1], p[2], text, color=color, **kwargs)
    t.set_gid(gid)
    return t


def _label2d(ax: Any, at: Any, text: str, gid: str, color: str = "k", **kwargs: Any) -> Any:
    p = np.asarray(at, dtype=float)
    t = ax.text(p[0], p[1], text, color=color, **kwargs)
    t.set_gid(gid)
    return t


def _axes_3d(style: str, width: float, height: float, ax: Any) -> tuple[Any, Any, Any]:
    """(figure, 3-D axes, side axes): a new figure of the style with the 3-D picture on the
    left and a side panel (no axes drawn) for the numbers and the colour key on the right; or
    ``ax`` (which must be 3-D) and no side panel."""
    if ax is None:
        fig = new_figure(style, width, height)
        grid = fig.add_gridspec(1, 2, width_ratios=[1.45, 1.0])
        ax = fig.add_subplot(grid[0, 0], projection="3d")
        side = fig.add_subplot(grid[0, 1])
        side.set_axis_off()
        return fig, ax, side
    if not hasattr(ax, "zaxis"):
        raise PoinsotError("ax: must be a 3-D axes (add_subplot(projection='3d'))")
    return ax.figure, ax, None


def _axes_2d(style: str, width: float, height: float, ax: Any) -> tuple[Any, Any]:
    if ax is None:
        return subplots(style, width, height)  # type: ignore[no-any-return]
    if hasattr(ax, "zaxis"):
        raise PoinsotError("ax: must be a 2-D axes")
    return ax.figure, ax


def _schematic(
    ax: Any,
    points: Any,
    *,
    elev: float = 20.0,
    azim: float = 35.0,
    zoom: float = 1.0,
    pad: float = 0.1,
) -> None:
    """A 3-D picture without box or ticks, seen from (``elev``, ``azim``) degrees: equal scales
    on the smallest cube holding ``points`` (n, 3) with a margin of ``pad`` of its side."""
    pts = np.asarray(points, dtype=float).reshape(-1, 3)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    centre = 0.5 * (lo + hi)
    half = 0.5 * float(np.max(hi - lo)) * (1.0 + 2 * pad) or 1.0
    ax.set_xlim(centre[0] - half, centre[0] + half)
    ax.set_ylim(centre[1] - half, centre[1] + half)
    ax.set_zlim(centre[2] - half, centre[2] + half)
    ax.set_box_aspect((1, 1, 1), zoom=zoom)
    ax.view_init(elev=elev, azim=azim)
    ax.set_axis_off()


def _triad(
    ax: Any,
    R: Any,
    names: tuple[str, str, str],
    color: str,
    gid: str,
    *,
    length: float = 1.0,
    lw: float | None = None,
) -> list[Any]:
    """The three columns of ``R`` as arrows from the origin, labelled ``names``; gids
    ``f"{gid}-1"``, ``-2``, ``-3``."""
    R = np.asarray(R, dtype=float)
    out = []
    for k in range(3):
        tip = length * R[:, k]
        out.append(_arrow3d(ax, np.zeros(3), tip, color, f"{gid}-{k + 1}", lw=lw))
        _label3d(
            ax, 1.1 * tip, names[k], f"{gid}-{k + 1}-label", color=color, ha="center", va="center"
        )
    return out


def _arc(axis: Any, start: Any, angle: float, radius: float, n: int = 40) -> Any:
    """Points of the arc swept by the vector ``start`` turned about ``axis`` by 0 … ``angle``
    (rad), at distance ``radius`` from the origin: poinsot's rotations, (n, 3)."""
    s = np.linspace(0.0, 1.0, n)
    mats = axis_angle_to_matrix(np.broadcast_to(np.asarray(axis, dtype=float), (n, 3)), s * angle)
    v = np.asarray(start, dtype=float)
    return radius * rotate_vectors(mats, v / np.linalg.norm(v))


def _line_of_nodes(ax: Any, xi: Any, span: tuple[float, float], label_at: float, lw: float) -> None:
    """The line of nodes ξ (unit vector ``xi``) dashed grey from ``span[0]`` to ``span[1]``
    times ``xi`` (gid ``"line-of-nodes"``), labelled ξ at ``label_at`` times ``xi``; ``lw``
    the style's line width (points)."""
    ax.plot(
        *np.stack([span[0] * xi, span[1] * xi]).T,
        color="0.5",
        ls="--",
        lw=0.6 * lw,
        gid="line-of-nodes",
    )
    _label3d(ax, label_at * xi, "ξ", "xi-label", color="0.5")


def _caption(
    ax: Any, side: Any, title: str, lines: list[str], key: list[tuple[str, str]] | None = None
) -> Any:
    """The title and the numbers of a 3-D picture (with a colour ``key``: (colour, meaning)
    pairs). With a side panel: the numbers in it (gid ``"info"``), the key at its foot and the
    title over the whole figure (a 3-D axes' own title is not kept inside the figure by the
    layout); without: the numbers in the upper left corner of the axes and the axes' title.
    Returns the numbers' text."""
    text = "\n".join(lines)
    if side is None:
        t = ax.text2D(0.02, 0.98, text, transform=ax.transAxes, ha="left", va="top")
    else:
        t = side.text(
            0.0, 0.97, text, transform=side.transAxes, ha="left", va="top", linespacing=1.5
        )
        if key:
            _legend(side, "lower left", key, fontsize=None, frameon=False, borderaxespad=0.0)
    t.set_gid("info")
    if side is None:
        ax.set_title(title)
    else:
        ax.figure.suptitle(title)
    return t


def _latitude(latitude: Any, degrees: Any) -> tuple[float, float]:
    """(latitude in degrees, in radians), checked."""
    from .._validate import as_angle

    rad = as_angle(latitude, "latitude", degrees)
    if not -np.pi / 2 <= rad <= np.pi / 2:
        raise PoinsotError(f"latitude: must lie in [-90°, 90°], got {latitude!r}")
    return float(np.degrees(rad)), rad


def _hemisphere(lat_deg: float) -> str:
    if lat_deg == 90.0:
        return "the North Pole"
    if lat_deg == -90.0:
        return "the South Pole"
    if lat_deg == 0.0:
        return "the equator"
    return f"{abs(lat_deg):g}° {'N' if lat_deg > 0 else 'S'}"


# ---------------------------------------------------------------------------------------------
# The classroom examples
# ---------------------------------------------------------------------------------------------
def classroom_free_top() -> FreeSymmetricTop:
    """The torque-free symmetric top of Figs. 2.10–2.11: a prolate top, I₁ = 1 kg·m²,
    I₃ = 0.5 kg·m², ω₀ = (0.8, 0, 2) rad/s (body), so Ω = 1 rad/s (2.83),
    α_b = 21.8° (2.90), α_s = 16.9° (2.97) — cones wide enough to see."""
    return FreeSymmetricTop(1.0, 0.5, [0.8, 0.0, 2.0])


def classroom_heavy_top() -> HeavyTop:
    """The heavy top of Figs. 2.14–2.15 (the example of CONVENTIONS.md §16): I₁ = 1 kg·m²,
    I₃ = 0.5 kg·m², m g l = 1 N·m, θ₀ = 0.8 rad, φ̇₀ = 0.5 rad/s, ψ̇₀ = 6 rad/s: its axis
    nods in waves between θ₁ = 0.715 rad and θ₂ = 0.8 rad."""
    return HeavyTop(1.0, 0.5, 1.0, 0.8, phi_dot=0.5, psi_dot=6.0)


# ---------------------------------------------------------------------------------------------
# Fig. 2.1: frames in relative translation
# ---------------------------------------------------------------------------------------------
def plot_translating_frame(
    frame: MovingFrame | None = None,
    position: Any = (1.0, 1.5, 0.0),
    velocity: Any = (0.0, 0.5, 0.0),
    acceleration: Any = (0.0, -0.4, 0.0),
    *,
    times: Any = (1.0, 2.0),
    style: str = "paper",
) -> Figure:
    """Fig. 2.1: a frame O(x, y, z) moving in translation relative to the fixed O′(x′, y′, z′).

    Left: the positions r′ = R + r of a particle P (eq. 2.1), with the moving frame drawn
    again where it is at ``times`` (dashed: its steady motion, :meth:`MovingFrame.at`). Right:
    the accelerations r̈′ = R̈ + r̈ (eq. 2.3, with its erratum): the fixed-frame acceleration
    is the frame's plus the relative one, so m r̈ = F − m R̈ (2.5). All vectors from
    :meth:`MovingFrame.to_fixed`, drawn in the x′y′ plane (the legends give all three
    components).

    Parameters
    ----------
    frame:
        The moving frame, without rotation (``angular_velocity`` and ``angular_acceleration``
        zero); default: origin R = (3, 1, 0) m, Ṙ = (1, 0.5, 0) m/s, R̈ = (0.6, 0.3, 0) m/s².
    position, velocity, acceleration:
        r (m), ṙ (m/s), r̈ (m/s²) of P relative to the moving frame, shape (3,).
    times:
        Times (s) at which the moving frame is drawn again, dashed.
    style:
        ``"paper"`` or ``"slides"``.

    Raises
    ------
    PoinsotError
        ``frame`` rotates (use :func:`plot_rotating_frame`), or a vector is not of shape (3,).
    """
    if frame is None:
        frame = MovingFrame(
            origin=(3.0, 1.0, 0.0), velocity=(1.0, 0.5, 0.0), acceleration=(0.6, 0.3, 0.0)
        )
    if np.any(frame.angular_velocity != 0) or np.any(frame.angular_acceleration != 0):
        raise PoinsotError(
            "frame: must translate without rotating for Fig. 2.1 (angular_velocity and "
            "angular_acceleration 0); plot_rotating_frame draws a rotating one"
        )
    r = as_vector3(position, "position")
    v = as_vector3(velocity, "velocity")
    a = as_vector3(acceleration, "acceleration")
    ts = as_float_array(times, "times").reshape(-1)
    seen = frame.to_fixed(r, v, a)
    R = frame.origin
    later = [frame.at(float(t)) for t in ts]
    with figure_style(style) as name:
        fig, (ax1, ax2) = subplots(name, 10.0, 4.6, 1, 2)
        lw = _style_lw()
        # -- positions (2.1)
        pts = np.array([np.zeros(3), R, seen.position, *(f.origin for f in later)])
        span = float(np.max(pts[:, :2].max(axis=0) - pts[:, :2].min(axis=0))) or 1.0
        unit = 0.15 * span
        frames = [(R, None)] + [(f.origin, float(t)) for f, t in zip(later, ts)]
        for o, t in frames:
            ls = "-" if t is None else "--"
            ax1.plot([o[0], o[0] + unit], [o[1], o[1]], ls, color=_MOVING, lw=0.8 * lw)
            ax1.plot([o[0], o[0]], [o[1], o[1] + unit], ls, color=_MOVING, lw=0.8 * lw)
            if t is None:
                ax1.text(o[0] + 1.12 * unit, o[1], "x", color=_MOVING, va="center")
                ax1.text(o[0], o[1] + 1.12 * unit, "y", color=_MOVING, ha="center", va="bottom")
            else:
                ax1.text(
                    o[0] + 0.08 * unit,
                    o[1] - 0.1 * unit,
                    f"O at t = {t:g} s",
                    color=_MOVING,
                    ha="left",
                    va="top",
                )
        ax1.plot([0, unit], [0, 0], color=_FIXED, lw=0.8 * lw)
        ax1.plot([0, 0], [0, unit], color=_FIXED, lw=0.8 * lw)
        ax1.text(1.12 * unit, 0.0, "x′", color=_FIXED, va="center")
        ax1.text(0.0, 1.12 * unit, "y′", color=_FIXED, ha="center", va="bottom")
        _arrow2d(ax1, np.zeros(2), R[:2], _MOVING, "R")
        _arrow2d(ax1, R[:2], seen.position[:2], _POSITION, "r")
        _arrow2d(ax1, np.zeros(2), seen.position[:2], _ACCEL, "r_fixed")
        ax1.plot([0.0], [0.0], "o", color=_FIXED)
        ax1.text(-0.05 * unit, -0.1 * unit, "O′", ha="right", va="top")
        ax1.text(R[0] + 0.05 * unit, R[1] - 0.1 * unit, "O", ha="left", va="top", color=_MOVING)
        ax1.plot([seen.position[0]], [seen.position[1]], "o", color=_POSITION)
        ax1.text(
            seen.position[0] - 0.1 * unit,
            seen.position[1] + 0.1 * unit,
            "P",
            ha="right",
            va="bottom",
        )
        lo, hi = pts[:, :2].min(axis=0), pts[:, :2].max(axis=0)
        ax1.set_xlim(lo[0] - 0.6 * unit, hi[0] + 2.8 * unit)
        ax1.set_ylim(lo[1] - 0.8 * unit, hi[1] + 4.0 * unit)
        ax1.set_aspect("equal", adjustable="box")
        ax1.set(xlabel="x′ (m)", ylabel="y′ (m)", title="positions: r′ = R + r (2.1)")
        _legend(
            ax1,
            "upper left",
            [
                (_MOVING, f"R = {_vec(R)} m"),
                (_POSITION, f"r = {_vec(r)} m"),
                (_ACCEL, f"r′ = {_vec(seen.position)} m"),
            ],
        )
        # -- accelerations (2.3)
        terms = seen.acceleration_terms
        A, rel, tot = terms["origin"], terms["relative"], seen.acceleration
        _arrow2d(ax2, np.zeros(2), A[:2], _MOVING, "R_ddot")
        _arrow2d(ax2, A[:2], A[:2] + rel[:2], _POSITION, "r_ddot")
        _arrow2d(ax2, np.zeros(2), tot[:2], _ACCEL, "r_ddot_fixed")
        pts2 = np.array([np.zeros(3), A, tot, A + rel])
        lo, hi = pts2[:, :2].min(axis=0), pts2[:, :2].max(axis=0)
        pad = 0.15 * float(np.max(hi - lo) or 1.0)
        ax2.set_xlim(lo[0] - pad, hi[0] + pad)
        ax2.set_ylim(lo[1] - pad, hi[1] + 4 * pad)
        ax2.set_aspect("equal", adjustable="box")
        ax2.axhline(0.0, color="0.85", lw=0.8, zorder=0)
        ax2.axvline(0.0, color="0.85", lw=0.8, zorder=0)
        ax2.set_xlabel("x′ component (m/s²)")
        ax2.set_ylabel("y′ component (m/s²)")
        ax2.set_title("accelerations: r̈′ = R̈ + r̈ (2.3)")
        _legend(
            ax2,
            "upper left",
            [
                (_MOVING, f"R̈ = {_vec(A)} m/s² (the frame's)"),
                (_POSITION, f"r̈ = {_vec(rel)} m/s² (relative)"),
                (_ACCEL, f"r̈′ = {_vec(tot)} m/s²"),
            ],
        )
    return fig


def _legend(
    ax: Any, loc: str, items: list[tuple[str, str]], fontsize: str | None = "small", **kw: Any
) -> None:
    """A legend at ``loc`` of coloured lines, ``items`` (colour, label); small text unless
    ``fontsize`` says otherwise (``None``: the style's)."""
    from matplotlib.lines import Line2D

    handles = [Line2D([], [], color=c, label=text) for c, text in items]
    ax.legend(handles=handles, loc=loc, fontsize=fontsize, **kw)


# ---------------------------------------------------------------------------------------------
# Fig. 2.2: a rotating frame; Fig. 2.3: the centripetal term
# ---------------------------------------------------------------------------------------------
def plot_rotating_frame(
    frame: MovingFrame | None = None,
    position: Any = (0.8, 0.5, 0.6),
    t: float = 0.8,
    *,
    style: str = "paper",
    ax: Any = None,
) -> Figure:
    """Fig. 2.2: the fixed axes O′(x′, y′, z′) and the axes O(x, y, z) turning with angular
    velocity ω about the common origin, at time ``t``, with a point P fixed in the turning axes.

    The turning axes are the attitude of ``frame.at(t)`` (:meth:`MovingFrame.at`: the axes
    turned by ω t); P's components in both frames are eq. 2.6–2.7's (``to_fixed``), and the
    arrow at P is its velocity ω × r seen from the fixed frame (eq. 2.12).

    Parameters
    ----------
    frame:
        The rotating frame at t = 0 (default: ω = (0.25, −0.2, 1) rad/s, axes aligned with the
        fixed ones).
    position:
        r of P in the turning axes (m), shape (3,).
    t:
        Time (s) at which the frame is drawn.
    style, ax:
        ``"paper"`` or ``"slides"``; a 3-D axes to draw into (default: a new figure).
    """
    if frame is None:
        frame = MovingFrame(angular_velocity=(0.25, -0.2, 1.0))
    r = as_vector3(position, "position")
    t = as_scalar(t, "t")
    now = frame.at(t)
    seen = now.to_fixed(r)
    w = now.angular_velocity
    wn = float(np.linalg.norm(w))
    p = seen.position
    vel = seen.velocity
    vn = float(np.linalg.norm(vel))
    turned = float(rotation_axis(now.attitude @ frame.attitude.T)[1])
    with figure_style(style) as name:
        fig, ax, side = _axes_3d(name, 8.6, 4.8, ax)
        lw = _style_lw()
        shown = [np.zeros(3), p]
        _triad(ax, frame.attitude, ("x′", "y′", "z′"), _FIXED, "fixed", lw=0.7 * lw)
        _triad(ax, now.attitude, ("x", "y", "z"), _MOVING, "moving")
        shown += [*(1.12 * frame.attitude.T), *(1.12 * now.attitude.T)]
        if wn > 0:
            tip = 1.45 * w / wn
            _arrow3d(ax, np.zeros(3), tip, _OMEGA, "omega")
            _label3d(ax, 1.08 * tip, "ω", "omega-label", color=_OMEGA, ha="center")
            shown.append(1.1 * tip)
        _arrow3d(ax, np.zeros(3), p, _POSITION, "r")
        ax.plot([p[0]], [p[1]], [p[2]], "o", color=_POSITION)
        _label3d(ax, p + np.array([0.0, 0.0, 0.08]), "P", "P-label", ha="right")
        if vn > 0:
            _arrow3d(ax, p, p + 0.5 * vel / vn, _VELOCITY, "omega_cross_r")
            shown.append(p + 0.5 * vel / vn)
        _schematic(ax, shown, elev=22, azim=30, zoom=1.4)
        _caption(
            ax,
            side,
            "fixed and rotating axes (Fig. 2.2)",
            [
                f"ω = {_vec(w)} rad/s",
                f"t = {t:g} s: x y z have turned {_deg(turned)}",
                f"r = {_vec(r)} m in x y z,",
                f"    {_vec(p)} m in x′ y′ z′ (2.7)",
                f"ω × r = {_vec(vel)} m/s (2.12)",
            ],
            key=[
                (_FIXED, "fixed axes x′ y′ z′"),
                (_MOVING, "rotating axes x y z"),
                (_OMEGA, "angular velocity ω"),
                (_POSITION, "r, P fixed in x y z"),
                (_VELOCITY, "velocity ω × r"),
            ],
        )
    return fig


def plot_centripetal(
    frame: MovingFrame | None = None,
    position: Any = (0.9, 0.0, 1.0),
    velocity: Any = (0.0, 0.0, 0.0),
    *,
    style: str = "paper",
    ax: Any = None,
) -> Figure:
    """Fig. 2.3: the centripetal acceleration ω × (ω × r) of a point turning with the frame,
    directed to the axis, of magnitude ω² r sin θ (eq. 2.24) on the circle of radius r sin θ.

    The circle is P's path seen from the fixed frame (``frame.at(t).to_fixed(r)`` over one
    turn); the arrows are the terms of eqs. 2.21–2.23 from :meth:`MovingFrame.to_fixed`: the
    centripetal acceleration, and — when P also moves in the rotating frame (``velocity``) —
    the Coriolis term 2ω × ṙ, both on one scale (ω² r sin θ drawn as long as r sin θ).

    Parameters
    ----------
    frame:
        The rotating frame (default: ω = (0, 0, 2) rad/s).
    position:
        r of P (m), shape (3,): θ is its angle from ω.
    velocity:
        P's velocity relative to the rotating frame (m/s), shape (3,); zero: no Coriolis term.
    style, ax:
        ``"paper"`` or ``"slides"``; a 3-D axes to draw into.

    Raises
    ------
    PoinsotError
        ω = 0 (nothing turns), or P on the axis (no circle).
    """
    if frame is None:
        frame = MovingFrame(angular_velocity=(0.0, 0.0, 2.0))
    r = as_vector3(position, "position")
    v = as_vector3(velocity, "velocity")
    w = frame.angular_velocity
    wn = float(np.linalg.norm(w))
    if wn == 0.0:
        raise PoinsotError("frame: angular_velocity must not be zero for Fig. 2.3")
    seen = frame.to_fixed(r, v)
    cp = seen.acceleration_terms["centripetal"]
    co = seen.acceleration_terms["coriolis"]
    cpn, con = float(np.linalg.norm(cp)), float(np.linalg.norm(co))
    if cpn == 0.0:
        raise PoinsotError("position: lies on the axis of rotation: no circle, no centripetal term")
    # P's path over one turn, as the fixed frame sees it (the core's steady motion).
    turn = 2 * np.pi / wn
    path = np.array([frame.at(float(s)).to_fixed(r).position for s in np.linspace(0.0, turn, 73)])
    centre = path[:-1].mean(axis=0)  # the circle's centre, on the axis
    radius = float(np.linalg.norm(path[0] - centre))  # r sin θ, read off the path
    scale = radius / cpn  # the centripetal arrow reaches the axis
    p = seen.position
    still = frame.to_fixed(r)  # at rest in the frame: ṙ′ = ω × r
    vel = still.velocity
    vn = float(np.linalg.norm(vel))
    rn = float(np.linalg.norm(r))
    theta = float(np.arccos(np.clip(np.dot(r, w) / (rn * wn), -1.0, 1.0)))
    axis_dir = w / wn
    with figure_style(style) as name:
        fig, ax, side = _axes_3d(name, 8.6, 4.8, ax)
        lw = _style_lw()
        top = 1.25 * max(rn, float(np.max(path @ axis_dir)))
        ax.plot(
            *np.stack([-0.2 * top * axis_dir, top * axis_dir]).T, color=_OMEGA, lw=0.6 * lw, ls=":"
        )
        _arrow3d(ax, np.zeros(3), top * axis_dir, _OMEGA, "omega")
        _label3d(
            ax, 1.03 * top * axis_dir, "ω", "omega-label", color=_OMEGA, ha="center", va="bottom"
        )
        ax.plot(path[:, 0], path[:, 1], path[:, 2], color=_MOVING, lw=0.8 * lw, gid="circle")
        _arrow3d(ax, np.zeros(3), p, _POSITION, "r")
        ax.plot([p[0]], [p[1]], [p[2]], "o", color=_POSITION)
        _label3d(ax, p + 0.08 * rn * axis_dir, "P", "P-label", ha="left", va="bottom")
        foot = p + scale * cp
        arc = _arc(np.cross(w, r), w, theta, 0.35 * rn)
        ax.plot(arc[:, 0], arc[:, 1], arc[:, 2], color="0.3", lw=0.6 * lw)
        _label3d(ax, 1.2 * arc[len(arc) // 2], "θ", "theta-label", color="0.3")
        _arrow3d(ax, p, foot, _ACCEL, "centripetal")
        _label3d(
            ax,
            0.5 * (p + foot) + 0.05 * rn * axis_dir,
            f"{_num(cpn)} m/s²",
            "centripetal-label",
            color=_ACCEL,
            ha="center",
            va="bottom",
        )
        _arrow3d(ax, p, p + 0.35 * rn * vel / vn, _VELOCITY, "velocity")
        shown = [*path, 1.1 * top * axis_dir, -0.2 * top * axis_dir, p + 0.35 * rn * vel / vn]
        lines = [
            f"ω = {_num(wn)} rad/s, r = {_num(rn)} m, θ = {_deg(theta)}",
            f"radius of the circle r sin θ = {_num(radius)} m",
            f"|ω×(ω×r)| = ω² r sin θ = {_num(cpn)} m/s² (2.24)",
            f"speed ω r sin θ = {_num(vn)} m/s",
        ]
        key = [
            (_OMEGA, "angular velocity ω"),
            (_MOVING, "P's circle, seen from the fixed frame"),
            (_ACCEL, "centripetal ω×(ω×r)"),
            (_VELOCITY, "velocity ω × r"),
        ]
        if con > 0:
            _arrow3d(ax, p, p + scale * co, _TORQUE, "coriolis")
            _label3d(
                ax, p + scale * co, f" {_num(con)} m/s²", "coriolis-label", color=_TORQUE, ha="left"
            )
            shown.append(p + scale * co)
            lines.append(f"ṙ = {_vec(v)} m/s: |2ω×ṙ| = {_num(con)} m/s²")
            key.append((_TORQUE, "Coriolis 2ω×ṙ (same scale)"))
        _schematic(ax, shown, elev=16, azim=-60, zoom=1.4)
        _caption(ax, side, "the centripetal acceleration (Fig. 2.3)", lines, key=key)
    return fig


# ---------------------------------------------------------------------------------------------
# Figs. 2.4–2.6: the rotating Earth
# ---------------------------------------------------------------------------------------------
_MM = 1e6  # the Earth pictures are in 10³ km


def _meridian(ax: Any, earth: Earth) -> float:
    """The Earth's meridian section (10³ km) with its axis and ω drawn from the centre;
    returns R in 10³ km."""
    R = earth.radius / _MM
    a = np.linspace(0, 2 * np.pi, 241)
    lw = _style_lw()
    ax.fill(R * np.cos(a), R * np.sin(a), color="0.93", zorder=0)
    ax.plot(R * np.cos(a), R * np.sin(a), color="0.5", lw=0.8 * lw)
    ax.plot([0, 0], [-1.15 * R, 1.15 * R], color=_OMEGA, ls=":", lw=0.7 * lw)
    ax.plot([-R, R], [0, 0], color="0.75", lw=0.6 * lw)
    _arrow2d(ax, (0.0, 0.0), (0.0, 0.55 * R), _OMEGA, "omega")
    _label2d(ax, (-0.04 * R, 0.45 * R), "ω", "omega-label", color=_OMEGA, ha="right", va="center")
    ax.set_aspect("equal", adjustable="box")
    ax.set(xlabel="distance from the axis (10³ km)", ylabel="along the axis (10³ km)")
    return R


def _latitude_arc(ax: Any, R: float, lat: float, lat_deg: float) -> None:
    """The latitude λ as an arc at the centre, from the equator to the radius through P."""
    a = np.linspace(0.0, lat, 30)
    ax.plot(0.28 * R * np.cos(a), 0.28 * R * np.sin(a), color="k", lw=0.6 * _style_lw())
    mid = 0.5 * lat
    _label2d(
        ax,
        (0.33 * R * np.cos(mid), 0.33 * R * np.sin(mid)),
        f"λ = {lat_deg:g}°",
        "latitude-label",
        va="center",
    )


def _enu_to_meridian(lat_rad: float, enu: Any) -> Any:
    """An ENU vector's (north, up) part in the meridian section's (away from the axis, along
    the axis) axes, at latitude ``lat_rad``; the east part points out of the picture."""
    up = np.array([np.cos(lat_rad), np.sin(lat_rad)])
    north = np.array([-np.sin(lat_rad), np.cos(lat_rad)])
    enu = np.asarray(enu, dtype=float)
    return enu[..., 1, None] * north + enu[..., 2, None] * up


def plot_earth_centrifugal(
    earth: Earth | None = None,
    latitude: float = 45.0,
    *,
    degrees: bool = True,
    style: str = "paper",
    ax: Any = None,
) -> Figure:
    """Fig. 2.4: the centrifugal acceleration −ω × (ω × r) on the Earth's surface, pointing
    away from the axis: ω²R cos λ, the most at the equator (the unit's 3.4×10⁻² m/s²), zero at
    the poles (eq. 2.31).

    A meridian section of the Earth with the arrows of :meth:`Earth.centrifugal_acceleration`
    every 30° of latitude and at ``latitude`` (labelled with its value), and the effective
    gravity there (:meth:`Earth.effective_gravity_magnitude`,
    :meth:`Earth.plumb_line_deviation`). Arrows on one scale (the equator's is a third of the
    radius).

    Parameters
    ----------
    earth:
        The Earth (default :class:`poinsot.Earth`: sidereal rate; ``Earth.solar_day()`` gives
        the unit's numbers).
    latitude:
        The latitude λ to label (degrees, or radians with ``degrees=False``), in [−90°, 90°].
    style, ax:
        ``"paper"`` or ``"slides"``; a 2-D axes to draw into.
    """
    earth = earth or Earth()
    lat_deg, lat = _latitude(latitude, degrees)
    lats = np.radians(np.arange(-90.0, 91.0, 30.0))
    acc = earth.centrifugal_acceleration(lats)
    here = earth.centrifugal_acceleration(lat)
    a_max = float(np.linalg.norm(earth.centrifugal_acceleration(0.0)))
    mag = float(np.linalg.norm(here))
    with figure_style(style) as name:
        fig, ax = _axes_2d(name, 6.6, 6.2, ax)
        lw = _style_lw()
        R = _meridian(ax, earth)
        scale = R / 3 / a_max
        for la, a in zip(lats, acc):
            for side in (1.0, -1.0):
                p = np.array([side * R * np.cos(la), R * np.sin(la)])
                d = _enu_to_meridian(float(la), a) * np.array([side, 1.0])
                if np.linalg.norm(d) * scale > 1e-3 * R:
                    _arrow2d(ax, p, p + scale * d, "0.6", "centrifugal-grid", lw=0.8 * lw)
        for pole in (1.0, -1.0):
            ax.text(
                0.08 * R,
                pole * 1.03 * R,
                "0 at the pole",
                va="bottom" if pole > 0 else "top",
                color="0.4",
                fontsize="small",
            )
        p = np.array([R * np.cos(lat), R * np.sin(lat)])
        d = _enu_to_meridian(lat, here)
        ax.plot(*p, "o", color=_ACCEL)
        ax.plot([0, p[0]], [0, p[1]], color="0.5", lw=0.6 * lw, ls="--")
        _arrow2d(ax, p, p + scale * d, _ACCEL, "centrifugal")
        _label2d(
            ax,
            p + scale * d + np.array([0.05 * R, 0.03 * R]),
            f"{_num(mag)} m/s²",
            "centrifugal-label",
            color=_ACCEL,
            va="bottom",
        )
        _latitude_arc(ax, R, lat, lat_deg)
        ax.set_xlim(-1.9 * R, 1.9 * R)
        ax.set_ylim(-1.9 * R, 1.35 * R)
        g_e = earth.effective_gravity_magnitude(lat)
        dev = earth.plumb_line_deviation(lat_deg, degrees=True)
        ax.text(
            0.02,
            0.02,
            "\n".join(
                [
                    f"ω = {_num(earth.rotation_rate, 5)} rad/s, R = {_num(earth.radius / 1e3, 5)} km",
                    f"at {_hemisphere(lat_deg)}: |−ω×(ω×r)| = {_num(mag)} m/s²",
                    f"at the equator: ω²R = {_num(a_max)} m/s²",
                    f"$|g_e|$ = {_num(g_e, 6)} m/s², {_num(dev)}° off the radius (2.31)",
                ]
            ),
            transform=ax.transAxes,
            va="bottom",
            gid="info",
        )
        ax.set_title("centrifugal acceleration on the Earth (Fig. 2.4)")
    return fig


def plot_earth_coriolis(
    earth: Earth | None = None,
    latitude: float = 45.0,
    speed: float = 10.0,
    *,
    degrees: bool = True,
    duration: float | None = None,
    style: str = "paper",
) -> Figure:
    """Figs. 2.5 (a latitude) and 2.6 (the pole): the Coriolis acceleration −2ω × v of a
    particle moving horizontally at ``speed`` (m/s): to the right in the north, to the left
    in the south, of horizontal size 2ω v sin λ — the most at the poles (2ω v, with
    2ω = 1.458×10⁻⁴ s⁻¹), none at the equator.

    Left: the meridian section with P and ω's components there, ω cos λ along the local north
    and ω sin λ along the local vertical (:meth:`Earth.omega_enu`, eq. 2.33): only the
    vertical one turns horizontal motion. Right: the local horizontal plane seen from above:
    parcels launched north, east, south and west, their tracks under the Coriolis force alone
    (:meth:`Earth.inertial_oscillation`), and at the start the horizontal part of
    :meth:`Earth.coriolis_acceleration` (eq. 2.30, with its erratum), drawn so that 2ω v —
    its value at the pole — is as long as v; the northward parcel's is labelled.

    Parameters
    ----------
    earth:
        The Earth (default :class:`poinsot.Earth`).
    latitude:
        λ (degrees, or radians with ``degrees=False``), in [−90°, 90°]; 90 for Fig. 2.6.
    speed:
        The parcels' speed (m/s, > 0).
    duration:
        Length of the tracks (s); default a quarter of the inertial period π/(ω |sin λ|)
        (:meth:`Earth.inertial_period`; at the equator, where it is infinite, a quarter of a
        turn of the Earth).
    style:
        ``"paper"`` or ``"slides"``.
    """
    earth = earth or Earth()
    lat_deg, lat = _latitude(latitude, degrees)
    v = as_scalar(speed, "speed")
    if v <= 0:
        raise PoinsotError(f"speed: must be > 0, got {speed!r}")
    period = float(earth.inertial_period(lat))
    if duration is None:
        duration = period / 4 if np.isfinite(period) else np.pi / (2 * earth.rotation_rate)
    dur = as_scalar(duration, "duration")
    w_enu = earth.omega_enu(lat)
    wn = float(np.linalg.norm(w_enu))
    f_pole = float(earth.coriolis_parameter(np.pi / 2))
    headings = {"north": (0.0, v), "east": (v, 0.0), "south": (0.0, -v), "west": (-v, 0.0)}
    tracks = {
        k: earth.inertial_oscillation(lat, list(h), duration=dur) for k, h in headings.items()
    }
    acc = {k: earth.coriolis_acceleration(lat, [h[0], h[1], 0.0]) for k, h in headings.items()}
    a_n = acc["north"]
    with figure_style(style) as name:
        fig, (ax1, ax2) = subplots(name, 10.0, 5.6, 1, 2)
        lw = _style_lw()
        # -- the meridian section: ω at P and its components
        R = _meridian(ax1, earth)
        p = np.array([R * np.cos(lat), R * np.sin(lat)])
        ax1.plot([0, p[0]], [0, p[1]], color="0.5", lw=0.6 * lw, ls="--")
        ax1.plot(*p, "o", color="k")
        _label2d(ax1, p + np.array([0.06 * R, -0.06 * R]), "P", "P-label", ha="left", va="top")
        k = 0.7 * R / wn
        up = np.array([0.0, 0.0, w_enu[2]])
        north = np.array([0.0, w_enu[1], 0.0])
        for gid, part, color in (("omega_up", up, "C9"), ("omega_north", north, "C8")):
            d = _enu_to_meridian(lat, part)
            if np.linalg.norm(d) * k > 1e-3 * R:
                _arrow2d(ax1, p, p + k * d, color, gid)
        _latitude_arc(ax1, R, lat, lat_deg)
        ax1.set_xlim(-1.15 * R, 1.75 * R)
        ax1.set_ylim(-1.6 * R, 1.75 * R)
        _legend(
            ax1,
            "lower left",
            [
                (_OMEGA, f"ω = {_num(wn, 5)} rad/s"),
                ("C9", f"ω sin λ = {_num(w_enu[2], 4, scale=wn)} rad/s (vertical)"),
                ("C8", f"ω cos λ = {_num(w_enu[1], 4, scale=wn)} rad/s (north)"),
            ],
        )
        ax1.set_title(f"ω at P, {_hemisphere(lat_deg)} (2.33)")
        # -- the horizontal plane at P, from above
        reach = 0.0
        for key, tr in tracks.items():
            xy = tr.position / 1e3
            reach = max(reach, float(np.max(np.abs(xy))))
            ax2.plot(xy[:, 0], xy[:, 1], color=_MOVING, lw=0.8 * lw, gid=f"track-{key}")
        ell = 0.5 * reach
        for key, h in headings.items():
            start = ell * np.array(h) / v
            _arrow2d(ax2, (0.0, 0.0), start, _VELOCITY, f"v-{key}")
            _arrow2d(
                ax2, start, start + ell * acc[key][:2] / (f_pole * v), _ACCEL, f"coriolis-{key}"
            )
        mid = ell * np.array([0.0, 1.0]) + 0.5 * ell * a_n[:2] / (f_pole * v)
        _label2d(
            ax2,
            mid + np.array([0.0, 0.04 * reach]),
            f"{_num(float(np.linalg.norm(a_n)))} m/s²",
            "coriolis-label",
            color=_ACCEL,
            ha="center",
            va="bottom",
        )
        ax2.set_xlim(-1.15 * reach, 1.15 * reach)
        ax2.set_ylim(-1.8 * reach, 1.15 * reach)
        ax2.set_aspect("equal", adjustable="box")
        ax2.set(xlabel="east (km)", ylabel="north (km)")
        _legend(
            ax2,
            "lower left",
            [
                (_VELOCITY, f"v = {_num(v)} m/s"),
                (_ACCEL, "−2ω×v, horizontal part (2ω v ↦ |v|)"),
                (_MOVING, f"tracks over {_num(dur / 3600)} h: {tracks['north'].sense}"),
            ],
        )
        ax2.set_title(f"Coriolis: 2ω v sin λ = {_num(float(np.linalg.norm(a_n)))} m/s²")
    return fig


def plot_flow_into_low(
    earth: Earth | None = None,
    latitudes: Any = (45.0, -45.0),
    *,
    degrees: bool = True,
    style: str = "paper",
) -> Figure:
    """Fig. 2.7: the cyclone. Air drawn into a low-pressure centre from all sides is turned to
    the right in the north and ends up circling it counterclockwise (clockwise in the south).

    One panel per latitude: the parcels' tracks from :meth:`Earth.flow_into_low` (the core's
    run: pressure pull, Coriolis force, friction), their start on the ring, the centre L,
    and the circulation and its sense as the run measures them.

    Parameters
    ----------
    earth:
        The Earth (default :class:`poinsot.Earth`).
    latitudes:
        1 to 4 latitudes, one panel each (degrees, or radians with ``degrees=False``).
    style:
        ``"paper"`` or ``"slides"``.
    """
    earth = earth or Earth()
    lats = as_float_array(latitudes, "latitudes").reshape(-1)
    if lats.size == 0 or lats.size > 4:
        raise PoinsotError(f"latitudes: give 1 to 4 latitudes, got {lats.size}")
    checked = [_latitude(float(la), degrees) for la in lats]
    flows = [earth.flow_into_low(rad) for _, rad in checked]
    with figure_style(style) as name:
        fig, axes = subplots(name, 4.6 * len(flows), 5.0, 1, len(flows), squeeze=False)
        lw = _style_lw()
        for ax, (deg, _), flow in zip(axes[0], checked, flows):
            xy = flow.position / 1e3
            reach = float(np.max(np.abs(xy)))
            for k in range(xy.shape[0]):
                ax.plot(xy[k, :, 0], xy[k, :, 1], color=_MOVING, lw=0.8 * lw, gid=f"parcel-{k}")
                i = xy.shape[1] // 4
                _arrow2d(ax, xy[k, i], xy[k, i + 2], _MOVING, f"parcel-{k}-direction")
            ax.plot(xy[:, 0, 0], xy[:, 0, 1], "o", color=_VELOCITY, ms=0.6 * plt_ms(), gid="start")
            ax.plot([0.0], [0.0], "o", color=_ACCEL)
            ax.text(
                0.0, 0.05 * reach, "L", color=_ACCEL, ha="center", va="bottom", fontweight="bold"
            )
            lim = 1.12 * reach
            ax.set_xlim(-lim, lim)
            ax.set_ylim(-lim, 1.5 * lim)
            ax.set_aspect("equal", adjustable="box")
            ax.set(
                xlabel="east (km)", ylabel="north (km)", title=f"{_hemisphere(deg)}: {flow.sense}"
            )
            ax.text(
                0.03,
                0.97,
                f"circulation {_num(flow.circulation)} m²/s\nafter {_num(flow.t[-1] / 3600)} h",
                transform=ax.transAxes,
                va="top",
                gid="info",
            )
    return fig


def plt_ms() -> float:
    """The marker size of the current style (points)."""
    from matplotlib import rcParams

    return float(rcParams["lines.markersize"])


# ---------------------------------------------------------------------------------------------
# Fig. 2.8: Euler's theorem; Fig. 2.9: the dumbbell
# ---------------------------------------------------------------------------------------------
def _view_between(wings: list[Any], axis: Any) -> tuple[float, float]:
    """(elev, azim) in degrees of a view of two half-planes hinged on ``axis`` and going out
    along the unit vectors ``wings`` (both ⊥ axis) that shows both open: from in front of the
    pair, 40° round from their bisector, tilted 15° towards the axis."""
    n = np.asarray(axis, dtype=float)
    bis = np.asarray(wings[0], dtype=float) + np.asarray(wings[1], dtype=float)
    bis = bis / (np.linalg.norm(bis) or 1.0)
    side = np.cross(n, bis)
    v = np.cos(np.radians(40.0)) * bis + np.sin(np.radians(40.0)) * side
    d = np.cos(np.radians(15.0)) * v + np.sin(np.radians(15.0)) * n
    if d[2] < 0:
        d = -d
    return float(np.degrees(np.arcsin(np.clip(d[2], -1, 1)))), float(
        np.degrees(np.arctan2(d[1], d[0]))
    )


def plot_euler_theorem(
    rotation: Any = None,
    points: Any = ((1.0, 0.0, 0.0), (0.0, 0.0, 1.0)),
    *,
    style: str = "paper",
    ax: Any = None,
) -> Figure:
    """Fig. 2.8: Euler's theorem. A body turning about the fixed point O carries A to A′ and B to
    B′; the planes P₁ and P₂ through O bisecting AA′ and BB′ meet in the line OC, from which
    every point of the body keeps its distance: the axis of the one rotation that does it.

    The rotation's axis and angle are :func:`poinsot.rotation_axis` of ``rotation``; A′ and B′
    are ``rotate_vectors(rotation, ·)``; the dotted arcs are A and B carried about OC through
    the angle (:func:`poinsot.axis_angle_to_matrix`) — they end on A′ and B′.

    Parameters
    ----------
    rotation:
        A 3×3 rotation matrix (or a scipy Rotation); default the z-x-z Euler angles
        (10°, 50°, 30°).
    points:
        A and B (m), shape (2, 3), not on the axis.
    style, ax:
        ``"paper"`` or ``"slides"``; a 3-D axes to draw into.

    Raises
    ------
    PoinsotError
        ``points`` of the wrong shape or on the axis (A = A′), or the identity rotation.
    """
    if rotation is None:
        rotation = euler_to_matrix([10.0, 50.0, 30.0], degrees=True)
    pts = as_float_array(points, "points")
    if pts.shape != (2, 3):
        raise PoinsotError(f"points: must have shape (2, 3) (A and B), got {pts.shape}")
    n, angle = rotation_axis(rotation)
    angle = float(angle)
    moved = rotate_vectors(rotation, pts)
    chords = moved - pts
    if np.any(np.linalg.norm(chords, axis=1) <= 1e-9 * np.linalg.norm(pts, axis=1)):
        raise PoinsotError(
            "points: A and B must move (not lie on the rotation's axis, and the rotation not "
            "be the identity)"
        )
    normals = [c / np.linalg.norm(c) for c in chords]
    size = float(np.max(np.linalg.norm(pts, axis=1)))
    with figure_style(style) as name:
        fig, ax, side = _axes_3d(name, 8.6, 5.0, ax)
        lw = _style_lw()
        ax.plot(
            *np.stack([-1.2 * size * n, 1.2 * size * n]).T, color=_OMEGA, lw=1.3 * lw, gid="axis"
        )
        _label3d(ax, 1.3 * size * n, "C", "C-label", color=_OMEGA)
        ax.plot([0.0], [0.0], [0.0], "o", color="k")
        _label3d(ax, -0.12 * size * n, "O", "O-label", ha="right", va="top")
        shown = [1.3 * size * n, -1.2 * size * n]
        wings: list[Any] = []
        for k, (p0, p1, normal, nm, plane) in enumerate(
            zip(pts, moved, normals, ("A", "B"), ("P₁", "P₂"))
        ):
            color = _MOVING if k == 0 else _VELOCITY
            ax.plot(*np.stack([np.zeros(3), p0]).T, color="0.5", lw=0.8 * lw)
            ax.plot(*np.stack([np.zeros(3), p1]).T, color="k", lw=0.8 * lw)
            ax.plot(*np.stack([p0, p1]).T, color=color, ls="--", lw=0.8 * lw, gid=f"chord-{nm}")
            ax.plot(*p0, "o", color="0.5")
            ax.plot(*p1, "o", color="k", gid=f"{nm}'")
            _label3d(ax, 1.1 * p0, nm, f"{nm}-label", color="0.4")
            _label3d(ax, 1.1 * p1, nm + "′", f"{nm}'-label")
            # A carried about OC through the angle: the rotation's own arc, from A to A′.
            path = rotate_vectors(
                axis_angle_to_matrix(np.broadcast_to(n, (40, 3)), np.linspace(0.0, angle, 40)),
                p0,
            )
            ax.plot(
                path[:, 0],
                path[:, 1],
                path[:, 2],
                color=color,
                ls=":",
                lw=0.9 * lw,
                gid=f"arc-{nm}",
            )
            # The plane through O perpendicular to AA′ (its points are as far from A as from
            # A′), drawn as a wing from the axis OC towards the middle M of AA′, which it holds.
            mid = 0.5 * (p0 + p1)
            out = mid - np.dot(mid, n) * n
            out /= np.linalg.norm(out)
            wings.append(out)
            s, t = np.meshgrid(np.array([-0.9, 1.1]) * size, np.array([0.0, 1.15]) * size)
            corners = s[..., None] * n + t[..., None] * out
            surf = ax.plot_surface(
                corners[..., 0],
                corners[..., 1],
                corners[..., 2],
                color=color,
                alpha=0.15,
                linewidth=0,
            )
            surf.set_gid(f"plane-{nm}")
            surf.normal = normal  # for the tests: the plane ⊥ AA′ holds the axis OC
            _label3d(
                ax, 1.15 * size * out - 0.8 * size * n, plane, f"plane-{nm}-label", color=color
            )
            shown += [p0 * 1.1, p1 * 1.1, *corners.reshape(-1, 3)]
        from mpl_toolkits.mplot3d.art3d import Poly3DCollection

        for tri, shade in ((pts, "0.6"), (moved, "0.2")):
            face = Poly3DCollection([np.vstack([np.zeros(3), tri])], facecolor=shade, alpha=0.18)
            face.set_edgecolor("none")
            ax.add_collection3d(face)
        elev, azim = _view_between(wings, n)
        _schematic(ax, shown, elev=elev, azim=azim, zoom=1.35)
        _caption(
            ax,
            side,
            "Euler's theorem (Fig. 2.8)",
            [
                f"axis OC: n = {_vec(n)}",
                f"angle α = {_deg(angle, 4)}",
                "(rotation_axis of the rotation)",
                f"|A| = |A′| = {_num(float(np.linalg.norm(pts[0])))} m",
                f"|B| = |B′| = {_num(float(np.linalg.norm(pts[1])))} m",
            ],
            key=[
                ("0.5", "O A B: before"),
                ("k", "O A′ B′: after"),
                (_MOVING, "P₁ ⊥ AA′, A's arc about OC"),
                (_VELOCITY, "P₂ ⊥ BB′, B's arc about OC"),
                (_OMEGA, "OC = P₁ ∩ P₂, the axis"),
            ],
        )
    return fig


def plot_dumbbell(
    masses: Any = (1.0, 1.0),
    positions: Any = None,
    omega: Any = (0.0, 0.0, 2.0),
    *,
    style: str = "paper",
    ax: Any = None,
) -> Figure:
    """Fig. 2.9: the dumbbell. Two masses on a massless rod through the fixed point O, turned
    about an axis tilted from the rod: L (eq. 2.58) is perpendicular to the rod, not parallel
    to ω, and goes round a cone about ω as the body turns; keeping ω fixed takes the torque
    N = dL/dt = ω × L (eq. 2.59).

    L and N are :meth:`RigidBody.angular_momentum` and :meth:`RigidBody.holding_torque` about O
    of :meth:`RigidBody.from_point_masses`; the cone is L of the body turned about ω
    (:meth:`RigidBody.rotated`) through one revolution. The default numbers are the tour's.

    Parameters
    ----------
    masses:
        m₁, m₂ (kg, > 0), shape (2,).
    positions:
        Their positions relative to O (m), shape (2, 3); default ±0.5 m along a rod tilted 30°
        from z.
    omega:
        The angular velocity (rad/s), shape (3,), nonzero.
    style, ax:
        ``"paper"`` or ``"slides"``; a 3-D axes to draw into.
    """
    m = as_float_array(masses, "masses")
    if m.shape != (2,):
        raise PoinsotError(f"masses: must have shape (2,), got {m.shape}")
    if positions is None:
        tilt = axis_angle_to_matrix([0.0, 1.0, 0.0], 30.0, degrees=True)
        positions = rotate_vectors(tilt, [[0.0, 0.0, 0.5], [0.0, 0.0, -0.5]])
    pos = as_float_array(positions, "positions")
    if pos.shape != (2, 3):
        raise PoinsotError(f"positions: must have shape (2, 3), got {pos.shape}")
    w = as_vector3(omega, "omega")
    wn = float(np.linalg.norm(w))
    if wn == 0.0:
        raise PoinsotError("omega: must not be zero")
    body = RigidBody.from_point_masses(m, pos)
    origin = np.zeros(3)
    L = body.angular_momentum(w, about=origin)
    N = body.holding_torque(w, about=origin)
    # |L| and |N| at the computation's precision: zero below the round-off of numbers of the
    # size of Σ m r² ω (and of that times ω).
    size = wn * float(np.sum(m * np.sum(pos**2, axis=1)))
    Ln, Nn = float(np.linalg.norm(L)), float(np.linalg.norm(N))
    Ln = 0.0 if Ln <= _ROUND_OFF * size else Ln
    Nn = 0.0 if Nn <= _ROUND_OFF * size * wn else Nn
    angle = float(body.momentum_angle(w, about=origin)) if Ln > 0 else 0.0
    turns = np.linspace(0.0, 2 * np.pi, 61)
    cone = np.array(
        [
            body.rotated(axis_angle_to_matrix(w, float(a))).angular_momentum(w, about=origin)
            for a in turns
        ]
    )
    reach = float(np.max(np.linalg.norm(pos, axis=1)))
    kL = 0.8 * reach / Ln if Ln > 0 else 0.0
    axis_dir = w / wn
    with figure_style(style) as name:
        fig, ax, side = _axes_3d(name, 8.6, 5.0, ax)
        lw = _style_lw()
        ax.plot(
            *np.stack([-1.1 * reach * axis_dir, 1.1 * reach * axis_dir]).T,
            color=_OMEGA,
            ls=":",
            lw=0.6 * lw,
        )
        _arrow3d(ax, origin, 1.05 * reach * axis_dir, _OMEGA, "omega")
        _label3d(
            ax, 1.12 * reach * axis_dir, "ω", "omega-label", color=_OMEGA, ha="center", va="bottom"
        )
        ax.plot(*pos.T, color="0.3", lw=1.5 * lw, gid="rod")
        sizes = 140 * m / m.max() * (2.5 if name == "slides" else 1.0)
        ax.scatter(*pos.T, s=sizes, color=_MOVING, depthshade=False, zorder=5)
        for k in range(2):
            _label3d(
                ax, pos[k] * 1.15, f"m{'₁₂'[k]}", f"m{k + 1}-label", color=_MOVING, ha="center"
            )
        shown = [*(1.15 * pos), 1.12 * reach * axis_dir, -1.1 * reach * axis_dir]
        key = [(_OMEGA, "angular velocity ω"), ("0.3", "massless rod")]
        if Ln > 0:
            _arrow3d(ax, origin, kL * L, _MOMENTUM, "L")
            _label3d(
                ax,
                kL * L + 0.08 * reach * axis_dir,
                "L",
                "L-label",
                color=_MOMENTUM,
                ha="right",
                va="bottom",
            )
            ax.plot(*(kL * cone).T, color=_MOMENTUM, ls="--", lw=0.7 * lw, gid="L-cone")
            shown += list(kL * cone)
            key.append((_MOMENTUM, "L and its cone about ω"))
        if Nn > 0:
            end = kL * L + 0.6 * reach * N / Nn
            _arrow3d(ax, kL * L, end, _TORQUE, "N")
            _label3d(
                ax,
                end + 0.1 * reach * axis_dir,
                "N",
                "N-label",
                color=_TORQUE,
                ha="center",
                va="bottom",
            )
            shown.append(end)
            key.append((_TORQUE, "torque N = ω × L = dL/dt"))
        ax.plot([0.0], [0.0], [0.0], "o", color="k")
        _label3d(ax, [0.0, 0.0, -0.12 * reach], "O", "O-label", ha="right", va="top")
        _schematic(ax, shown, elev=22, azim=-50, zoom=1.5)
        _caption(
            ax,
            side,
            "the dumbbell: L is not along ω (Fig. 2.9)",
            [
                f"m₁ = {_num(m[0])} kg, m₂ = {_num(m[1])} kg, ω = {_num(wn)} rad/s",
                f"L = {_vec(L)} kg·m²/s (2.58)",
                f"L ⊥ rod; angle of L from ω: {_deg(angle, 4)}" if Ln > 0 else "L = 0",
                f"N = ω × L = {_vec(N)} N·m (2.59)",
            ],
            key=key,
        )
    return fig


# ---------------------------------------------------------------------------------------------
# Fig. 2.10: the body cone
# ---------------------------------------------------------------------------------------------
def plot_body_cone(
    top: FreeSymmetricTop | None = None, *, style: str = "paper", ax: Any = None
) -> Figure:
    """Fig. 2.10: in the body, ω precesses about the symmetry axis e₃ at the rate Ω (2.83),
    tracing the body cone of half-angle α_b, tan α_b = A / ω₃ (2.90).

    The trace is :meth:`FreeSymmetricTop.omega` over one period 2π/|Ω| (body components,
    drawn scaled so that |ω| is 1); the values written are the top's.

    Parameters
    ----------
    top:
        The torque-free symmetric top (default :func:`classroom_free_top`).
    style, ax:
        ``"paper"`` or ``"slides"``; a 3-D axes to draw into.
    """
    top = top or classroom_free_top()
    big_omega = top.precession_rate
    if big_omega != 0.0:
        t = np.linspace(0.0, 2 * np.pi / abs(big_omega), 121)
    else:  # a spherical top: ω stays put in the body
        t = np.zeros(1)
    trace = top.omega(t)
    pts = trace / float(np.linalg.norm(trace[0]))
    e3 = np.array([0.0, 0.0, 1.0 if top.omega3 >= 0 else -1.0])
    with figure_style(style) as name:
        fig, ax, side = _axes_3d(name, 8.6, 5.0, ax)
        lw = _style_lw()
        axes = np.diag([1.0, 1.0, e3[2]])
        _triad(ax, axes, ("e₁", "e₂", "e₃"), _MOVING, "body", length=1.15, lw=0.8 * lw)
        for k in range(0, len(pts) - 1, 6):
            ax.plot(*np.stack([np.zeros(3), pts[k]]).T, color=_OMEGA, alpha=0.25, lw=0.5 * lw)
        ax.plot(pts[:, 0], pts[:, 1], pts[:, 2], color=_OMEGA, lw=lw, gid="omega-trace")
        if len(pts) > 10:
            _arrow3d(ax, pts[len(pts) // 4], pts[len(pts) // 4 + 3], _OMEGA, "precession-sense")
        _arrow3d(ax, np.zeros(3), pts[0], _OMEGA, "omega")
        _label3d(ax, 1.2 * pts[0], "ω", "omega-label", color=_OMEGA, ha="left")
        foot = pts[0, 2] * np.array([0.0, 0.0, 1.0])
        ax.plot(*np.stack([foot, pts[0]]).T, color=_ACCEL, lw=0.8 * lw, gid="A")
        _label3d(ax, 0.5 * (foot + pts[0]), "A", "A-label", color=_ACCEL, va="bottom")
        arc = _arc(
            np.cross(e3, pts[0]),
            e3,
            top.body_cone_angle if e3[2] > 0 else np.pi - top.body_cone_angle,
            0.45,
        )
        ax.plot(arc[:, 0], arc[:, 1], arc[:, 2], color="0.3", lw=0.7 * lw)
        _label3d(ax, 1.25 * arc[len(arc) // 2], "$\\alpha_b$", "alpha-label", color="0.3")
        _schematic(
            ax,
            [*pts, 1.2 * axes[:, 0], 1.2 * axes[:, 1], 1.2 * axes[:, 2], np.zeros(3)],
            elev=18,
            azim=-55,
            zoom=1.35,
        )
        _caption(
            ax,
            side,
            "the body cone (Fig. 2.10)",
            [
                f"I₁ = {_num(top.I1)} kg·m², I₃ = {_num(top.I3)} kg·m² ({top.shape})",
                f"ω₃ = {_num(top.omega3)} rad/s, A = {_num(top.amplitude)} rad/s",
                f"Ω = (I₁ − I₃) ω₃ / I₁ = {_num(big_omega)} rad/s (2.83)",
                f"tan $\\alpha_b$ = A / ω₃ (2.90): $\\alpha_b$ = {_deg(top.body_cone_angle, 4)}",
            ],
            key=[
                (_MOVING, "body axes"),
                (_OMEGA, "ω and its path in the body"),
                (_ACCEL, "A = |ω₁ e₁ + ω₂ e₂|"),
            ],
        )
    return fig


# ---------------------------------------------------------------------------------------------
# Figs. 2.12a–d: Euler's angles; Fig. 2.13: ω resolved along ξηζ
# ---------------------------------------------------------------------------------------------
_STEPS = ("a", "b", "c", "d")


def _euler(angles: Any, degrees: Any) -> Any:
    from .._validate import as_flag

    a = as_float_array(angles, "angles")
    if a.shape != (3,):
        raise PoinsotError(f"angles: must have shape (3,) (φ, θ, ψ), got {a.shape}")
    return np.radians(a) if as_flag(degrees, "degrees") else a


def _step_panel(ax: Any, step: str, phi: float, theta: float, psi: float) -> None:
    """One of the unit's four pictures of Euler's angles (the axes after each rotation are
    ``euler_to_matrix`` of the angles turned so far)."""
    after_phi = euler_to_matrix([phi, 0.0, 0.0])
    after_theta = euler_to_matrix([phi, theta, 0.0])
    final = euler_to_matrix([phi, theta, psi])
    X, Z = np.array([1.0, 0.0, 0.0]), np.array([0.0, 0.0, 1.0])
    xi, zeta = after_theta[:, 0], after_theta[:, 2]
    lw = _style_lw()
    fixed_names = ("X", "Y", "") if step == "a" else ("X", "Y", "Z")
    _triad(ax, np.eye(3), fixed_names, _FIXED, "fixed", lw=0.6 * lw)
    if step == "a":
        _triad(ax, after_phi, ("ξ", "η′", "Z"), _MOVING, "step")
        arcs = [("φ", _arc(Z, X, phi, 0.5))]
        title = f"(a) φ = {_deg(phi)} about Z"
    elif step == "b":
        _triad(ax, after_theta, ("ξ", "η", "ζ"), _MOVING, "step")
        arcs = [("θ", _arc(xi, Z, theta, 0.5))]
        title = f"(b) θ = {_deg(theta)} about ξ"
    elif step == "c":
        _triad(ax, after_theta, ("", "", ""), "0.7", "xi-eta-zeta", lw=0.6 * lw)
        _label3d(ax, 1.1 * xi, "ξ", "xi-label", color="0.6")
        _label3d(ax, 1.1 * after_theta[:, 1], "η", "eta-label", color="0.6")
        _triad(ax, final, ("1", "2", "3 = ζ"), _MOVING, "step")
        arcs = [("ψ", _arc(zeta, xi, psi, 0.5))]
        title = f"(c) ψ = {_deg(psi)} about ζ"
    else:
        _triad(ax, final, ("1", "2", "3"), _MOVING, "step")
        _line_of_nodes(ax, xi, (-0.5, 1.0), 1.1, lw)
        arcs = [
            ("φ", _arc(Z, X, phi, 0.45)),
            ("θ", _arc(xi, Z, theta, 0.4)),
            ("ψ", _arc(zeta, xi, psi, 0.45)),
        ]
        title = "(d) the body axes 1 2 3"
    for label, arc in arcs:
        ax.plot(arc[:, 0], arc[:, 1], arc[:, 2], color=_ACCEL, lw=lw, gid=f"arc-{label}")
        _label3d(
            ax,
            1.25 * arc[len(arc) // 2],
            label,
            f"arc-{label}-label",
            color=_ACCEL,
            ha="center",
            va="center",
        )
    # The XY plane, where φ is measured.
    a = np.linspace(0, 2 * np.pi, 73)
    ax.plot(0.9 * np.cos(a), 0.9 * np.sin(a), 0 * a, color="0.85", lw=0.5 * lw)
    shown = [
        *(1.12 * np.eye(3)),
        *(1.12 * final.T),
        *(1.12 * after_theta.T),
        -0.5 * xi,
        [0.0, 0.0, -0.1],
    ]
    _schematic(ax, shown, elev=22, azim=25, zoom=1.45, pad=0.02)
    ax.set_title(title)


def plot_euler_angle_steps(
    angles: Any = (40.0, 55.0, 30.0),
    *,
    step: str | None = None,
    degrees: bool = True,
    style: str = "paper",
    ax: Any = None,
) -> Figure:
    """Figs. 2.12a–d: the unit's Euler angles (intrinsic z-x-z), one rotation at a time:
    (a) φ about Z takes X to the line of nodes ξ; (b) θ about ξ takes Z to ζ, giving ξηζ;
    (c) ψ about ζ takes ξ to body axis 1; (d) the body axes 1 2 3 with the three angles.

    The axes after each step are :func:`poinsot.euler_to_matrix` of the angles turned so far,
    (φ, 0, 0), (φ, θ, 0) and (φ, θ, ψ); the arcs are the rotations themselves
    (:func:`poinsot.axis_angle_to_matrix`).

    Parameters
    ----------
    angles:
        (φ, θ, ψ) in degrees (radians with ``degrees=False``).
    step:
        ``"a"``, ``"b"``, ``"c"`` or ``"d"``: one picture; ``None``: the four side by side.
    style, ax:
        ``"paper"`` or ``"slides"``; a 3-D axes to draw one step into.
    """
    phi, theta, psi = (float(x) for x in _euler(angles, degrees))
    if step is not None:
        step = as_choice(step, "step", _STEPS)
    elif ax is not None:
        raise PoinsotError("ax: holds one step; give step='a', 'b', 'c' or 'd' with it")
    with figure_style(style) as name:
        if step is not None:
            if ax is None:
                fig = new_figure(name, 4.6, 4.6)
                ax = fig.add_subplot(projection="3d")
            elif not hasattr(ax, "zaxis"):
                raise PoinsotError("ax: must be a 3-D axes (add_subplot(projection='3d'))")
            _step_panel(ax, step, phi, theta, psi)
            return ax.figure  # type: ignore[no-any-return]
        fig = new_figure(name, 12.0, 3.6)
        for k, s in enumerate(_STEPS):
            _step_panel(fig.add_subplot(1, 4, k + 1, projection="3d"), s, phi, theta, psi)
    return fig  # type: ignore[no-any-return]


def plot_omega_components(
    angles: Any = (40.0, 55.0, 30.0),
    rates: Any = (40.0, 30.0, 60.0),
    *,
    degrees: bool = True,
    style: str = "paper",
    ax: Any = None,
) -> Figure:
    """Fig. 2.13: the angular velocity as the sum of the three rotations' rates, φ̇ along Z,
    θ̇ along the line of nodes ξ, ψ̇ along ζ = 3 (drawn head to tail), and its components
    along ξ, η, ζ (eq. 2.98): ω_ξ = θ̇, ω_η = φ̇ sin θ, ω_ζ = ψ̇ + φ̇ cos θ; then along the
    body axes (eq. 2.99).

    ω is :func:`poinsot.space_angular_velocity`; its ξηζ components are ω turned into the
    ξηζ axes (``euler_to_matrix((φ, θ, 0))``, by :func:`poinsot.rotate_vectors`); the body
    components are :func:`poinsot.body_angular_velocity`.

    Parameters
    ----------
    angles:
        (φ, θ, ψ) in degrees (radians with ``degrees=False``).
    rates:
        (φ̇, θ̇, ψ̇) in deg/s (rad/s with ``degrees=False``); ω is always in rad/s.
    style, ax:
        ``"paper"`` or ``"slides"``; a 3-D axes to draw into.
    """
    ang = _euler(angles, degrees)
    rt = as_float_array(rates, "rates")
    if rt.shape != (3,):
        raise PoinsotError(f"rates: must have shape (3,) (φ̇, θ̇, ψ̇), got {rt.shape}")
    rt = np.radians(rt) if degrees else rt
    w = space_angular_velocity(ang, rt)
    wb = body_angular_velocity(ang, rt)
    xez = euler_to_matrix([ang[0], ang[1], 0.0])
    w_xez = rotate_vectors(xez.T, w)
    wn = float(np.linalg.norm(w))
    if wn == 0.0:
        raise PoinsotError("rates: all zero, no angular velocity to resolve")
    k = 1.0 / wn
    Z = np.array([0.0, 0.0, 1.0])
    xi, zeta = xez[:, 0], xez[:, 2]
    with figure_style(style) as name:
        fig, ax, side = _axes_3d(name, 8.8, 5.0, ax)
        lw = _style_lw()
        _triad(ax, xez, ("ξ", "η", "ζ = 3"), _MOVING, "xez", length=1.1, lw=0.6 * lw)
        ax.plot([0, 0], [0, 0], [0, 1.15], color=_FIXED, lw=0.6 * lw)
        _label3d(ax, [0, 0, 1.22], "Z", "Z-label", color=_FIXED)
        # φ̇ Z + θ̇ ξ + ψ̇ ζ, head to tail: they add up to ω.
        at = np.zeros(3)
        shown = [np.zeros(3), 1.25 * Z, *(1.2 * xez.T)]
        for gid, label, vec in (
            ("phi_dot", "φ̇", rt[0] * Z),
            ("theta_dot", "θ̇", rt[1] * xi),
            ("psi_dot", "ψ̇", rt[2] * zeta),
        ):
            if np.linalg.norm(vec) > 0:
                _arrow3d(ax, at, at + k * vec, _VELOCITY, gid, lw=0.8 * lw)
                _label3d(
                    ax, at + 0.5 * k * vec, f" {label}", f"{gid}-label", color=_VELOCITY, ha="left"
                )
            at = at + k * vec
            shown.append(at)
        _arrow3d(ax, np.zeros(3), k * w, _OMEGA, "omega")
        _label3d(ax, 1.08 * k * w, "ω", "omega-label", color=_OMEGA)
        for j in range(3):  # ω's feet on the ξ, η, ζ axes
            foot = k * w_xez[j] * xez[:, j]
            ax.plot(*np.stack([k * w, foot]).T, color="0.6", ls=":", lw=0.6 * lw, gid=f"foot-{j}")
        _schematic(ax, shown, elev=15, azim=-100, zoom=1.35)
        _caption(
            ax,
            side,
            "ω resolved along ξ, η, ζ (Fig. 2.13)",
            [
                f"φ̇, θ̇, ψ̇ = {_vec(rt)} rad/s",
                f"$\\omega_\\xi = \\dot\\theta$ = {_num(w_xez[0], 4, scale=wn)} rad/s",
                f"$\\omega_\\eta = \\dot\\varphi\\,\\sin\\theta$ = {_num(w_xez[1], 4, scale=wn)} rad/s",
                "$\\omega_\\zeta = \\dot\\psi + \\dot\\varphi\\,\\cos\\theta$"
                f" = {_num(w_xez[2], 4, scale=wn)} rad/s (2.98)",
                f"ω₁, ω₂, ω₃ = {_vec(wb, 4)} rad/s (2.99)",
            ],
            key=[
                (_MOVING, "axes ξ η ζ"),
                (_VELOCITY, "φ̇ Z, θ̇ ξ, ψ̇ ζ, head to tail"),
                (_OMEGA, "ω, their sum"),
                ("0.6", "ω's components on ξ, η, ζ"),
            ],
        )
    return fig


# ---------------------------------------------------------------------------------------------
# Fig. 2.14: the heavy top
# ---------------------------------------------------------------------------------------------
def plot_heavy_top(
    top: HeavyTop | None = None, t: float = 1.2, *, style: str = "paper", ax: Any = None
) -> Figure:
    """Fig. 2.14: the heavy symmetric top on its pivot O at time ``t``: the symmetry axis 3 at
    the nutation angle θ from the vertical Z, the line of nodes ξ at φ from X, the centre of
    mass at l on axis 3 with its weight m g, and the path of the axis over three nutation
    periods between the circles θ₁ and θ₂ (the turning points of eq. 2.110).

    The attitude is :meth:`HeavyTop.attitude` (the exact z-x-z Euler angles); the body (a cone
    with a disc at the centre of mass, a stripe showing the spin) is drawn turned by it.
    Lengths are in units of l: the top knows only m g l.

    Parameters
    ----------
    top:
        The heavy top (default :func:`classroom_heavy_top`).
    t:
        Time (s).
    style, ax:
        ``"paper"`` or ``"slides"``; a 3-D axes to draw into.
    """
    top = top or classroom_heavy_top()
    t = as_scalar(t, "t")
    phi, theta, _psi = (float(x) for x in top.euler_angles(t))
    R = top.attitude(t)
    axis = R[:, 2]
    period = top.nutation_period
    ts = np.linspace(0.0, 3 * period if np.isfinite(period) else 10.0, 600)
    tip_path = 1.25 * top.symmetry_axis(ts)
    t1, t2 = top.turning_points
    a = np.linspace(0.0, 2 * np.pi, 121)
    Z = np.array([0.0, 0.0, 1.0])
    with figure_style(style) as name:
        fig, ax, side = _axes_3d(name, 8.6, 5.2, ax)
        lw = _style_lw()
        _triad(ax, np.eye(3), ("X", "Y", "Z"), _FIXED, "fixed", length=1.3, lw=0.6 * lw)
        for th, nm in ((t1, "θ₁"), (t2, "θ₂")):
            ring = euler_to_matrix(np.stack([a, np.full_like(a, th), np.zeros_like(a)], axis=1))
            circle = 1.25 * ring[:, :, 2]
            ax.plot(*circle.T, color="0.6", ls=":", lw=0.6 * lw, gid=f"circle-{nm}")
        ax.plot(*tip_path.T, color=_ACCEL, lw=0.8 * lw, gid="tip-path")
        # The body: a cone from the pivot to a disc at the centre of mass (l = 1).
        u = np.linspace(0.0, 2 * np.pi, 48)
        uu, ss = np.meshgrid(u, np.linspace(0.0, 1.0, 8))
        body = np.stack([0.3 * ss * np.cos(uu), 0.3 * ss * np.sin(uu), ss], axis=-1)
        world = rotate_vectors(R, body)
        ax.plot_surface(
            world[..., 0], world[..., 1], world[..., 2], color=_MOVING, alpha=0.25, linewidth=0
        )
        rim = rotate_vectors(
            R, np.stack([0.3 * np.cos(u), 0.3 * np.sin(u), np.ones_like(u)], axis=1)
        )
        ax.plot(*rim.T, color=_MOVING, lw=0.8 * lw)
        stripe = rotate_vectors(R, np.array([[0.0, 0.0, 1.0], [0.3, 0.0, 1.0]]))
        ax.plot(*stripe.T, color="k", lw=lw, gid="spin-stripe")
        ax.plot(*np.stack([np.zeros(3), 1.25 * axis]).T, color="k", lw=0.8 * lw, gid="axis-3")
        _label3d(ax, 1.33 * axis, "3", "axis-3-label")
        ax.plot(*axis, "o", color="k")
        _label3d(ax, 0.5 * axis, "l  ", "l-label", ha="right")
        _arrow3d(ax, axis, axis - 0.4 * Z, _TORQUE, "weight")
        _label3d(ax, axis - 0.45 * Z, "m g", "weight-label", color=_TORQUE, ha="center", va="top")
        xi = euler_to_matrix([phi, 0.0, 0.0])[:, 0]
        _line_of_nodes(ax, xi, (0.0, 1.1), 1.18, lw)
        arc_t = _arc(xi, Z, theta, 0.55)
        ax.plot(*arc_t.T, color=_OMEGA, lw=lw, gid="arc-theta")
        _label3d(ax, 1.2 * arc_t[len(arc_t) // 2], "θ", "theta-label", color=_OMEGA)
        if abs(phi) > 1e-9:
            arc_p = _arc(Z, [1.0, 0.0, 0.0], phi, 0.6)
            ax.plot(*arc_p.T, color=_OMEGA, lw=lw, gid="arc-phi")
            _label3d(ax, 1.2 * arc_p[len(arc_p) // 2], "φ", "phi-label", color=_OMEGA)
        ax.plot([0.0], [0.0], [0.0], "o", color="k")
        _label3d(ax, [0.0, 0.0, -0.1], "O", "O-label", va="top")
        shown = [*tip_path, *(1.35 * np.eye(3)), axis - 0.6 * Z, np.zeros(3)]
        # Seen from the side the axis leans to (azimuth φ: the axis is along ξ turned by θ).
        _schematic(ax, shown, elev=20, azim=float(np.degrees(phi)) + 30.0, zoom=1.4)
        _caption(
            ax,
            side,
            "the heavy symmetric top (Fig. 2.14)",
            [
                f"I₁ = {_num(top.I1)}, I₃ = {_num(top.I3)} kg·m², m g l = {_num(top.mgl)} N·m",
                f"$p_\\psi$ = {_num(top.p_psi, 4)}, $p_\\varphi$ = {_num(top.p_phi, 4)} kg·m²/s",
                f"t = {t:g} s: θ = {_num(theta, 4)} rad, φ = {_num(phi, 4)} rad",
                f"θ₁ = {_num(t1, 4)} rad, θ₂ = {_num(t2, 4)} rad",
                f"{top.motion_class}, nutation period {_num(period, 4)} s",
            ],
            key=[
                (_FIXED, "fixed axes X Y Z"),
                (_MOVING, "the top (stripe: its spin)"),
                (_ACCEL, "path of the axis, 3 nutations"),
                ("0.6", "circles θ₁, θ₂ (2.110)"),
                (_TORQUE, "weight m g at the centre of mass"),
            ],
        )
    return fig


# ---------------------------------------------------------------------------------------------
# The registry: the unit's figure number → the function that draws it
# ---------------------------------------------------------------------------------------------
def _free_top_arguments() -> dict[str, Any]:
    return {"top": classroom_free_top()}


def _step_arguments(step: str) -> Callable[[], dict[str, Any]]:
    return lambda: {"step": step}


def _heavy_top_arguments() -> dict[str, Any]:
    return {"top": classroom_heavy_top()}


@dataclass(frozen=True)
class UnitFigure:
    """One figure of the unit and how poinsot draws it.

    Attributes
    ----------
    number:
        The unit's figure number (``"2.1"`` … ``"2.15"``, ``"2.12a"`` … ``"2.12d"``).
    caption:
        What it shows, in one line.
    function:
        The plot function (this module's, or an existing one of :mod:`poinsot.plots`).
    arguments:
        Builds the keyword arguments of the classroom example (models are made when drawn).
    lab:
        The browser lab's scene that shows the same thing, as the query of its address
        (``"scene=low&latitude=45"``: ``poinsot lab``, then ``?scene=low&latitude=45``), or
        ``None``.
    """

    number: str
    caption: str
    function: Callable[..., Any]
    arguments: Callable[[], dict[str, Any]] = field(default=dict)
    lab: str | None = None

    def draw(self, *, style: str = "paper") -> Figure:
        """The figure, drawn in ``style``."""
        return _draw(self.function, self.arguments(), style)


def _draw(function: Callable[..., Any], kwargs: dict[str, Any], style: str) -> Any:
    """``function(**kwargs, style=style)`` (every plot function takes ``style``)."""
    return function(**kwargs, style=style)


def _registry() -> dict[str, UnitFigure]:
    from .free import plot_cones
    from .top import plot_effective_potential

    entries = [
        UnitFigure(
            "2.1",
            "frames in relative translation: r′ = R + r and r̈′ = R̈ + r̈",
            plot_translating_frame,
        ),
        UnitFigure(
            "2.2",
            "fixed axes x′y′z′ and axes turning with ω about the common origin",
            plot_rotating_frame,
            lab="scene=frames",
        ),
        UnitFigure(
            "2.3",
            "the centripetal acceleration ω×(ω×r), ω² r sin θ towards the axis",
            plot_centripetal,
            lab="scene=frames",
        ),
        UnitFigure(
            "2.4",
            "the centrifugal acceleration on the Earth, ω²R cos λ away from the axis",
            plot_earth_centrifugal,
        ),
        UnitFigure(
            "2.5",
            "the Coriolis acceleration at 45° N: ω's vertical part turns horizontal motion to the right",
            plot_earth_coriolis,
            lambda: {"latitude": 45.0},
            lab="scene=low&latitude=45",
        ),
        UnitFigure(
            "2.6",
            "the Coriolis acceleration at the North Pole: the largest, 2ω v",
            plot_earth_coriolis,
            lambda: {"latitude": 90.0},
            lab="scene=low&latitude=90",
        ),
        UnitFigure(
            "2.7",
            "the cyclone: air drawn into a low circles it counterclockwise in the north",
            plot_flow_into_low,
            lab="scene=low&latitude=45",
        ),
        UnitFigure(
            "2.8",
            "Euler's theorem: A→A′, B→B′ is one rotation about OC",
            plot_euler_theorem,
            lab="scene=inertia",
        ),
        UnitFigure(
            "2.9", "the dumbbell: L ⊥ rod, not along ω; the torque ω×L keeps ω fixed", plot_dumbbell
        ),
        UnitFigure(
            "2.10",
            "the body cone: ω precesses about e₃ at Ω, half-angle α_b",
            plot_body_cone,
            lab="scene=freetop&I1=1&I3=0.5&w1=0.8&w3=2",
        ),
        UnitFigure(
            "2.11",
            "the body cone rolling on the space cone about the fixed L",
            plot_cones,
            _free_top_arguments,
            lab="scene=freetop&I1=1&I3=0.5&w1=0.8&w3=2",
        ),
        *(
            UnitFigure(
                f"2.12{s}",
                caption,
                plot_euler_angle_steps,
                _step_arguments(s),
                lab="scene=euler&phi=40&theta=55&psi=30",
            )
            for s, caption in zip(
                _STEPS,
                (
                    "Euler's angles (a): φ about Z takes X to the line of nodes ξ",
                    "Euler's angles (b): θ about ξ takes Z to ζ",
                    "Euler's angles (c): ψ about ζ takes ξ to body axis 1",
                    "Euler's angles (d): the body axes 1 2 3",
                ),
            )
        ),
        UnitFigure(
            "2.13",
            "ω = φ̇ Z + θ̇ ξ + ψ̇ ζ resolved along ξηζ (2.98) and 1 2 3 (2.99)",
            plot_omega_components,
            lab="scene=euler&phi=40&theta=55&psi=30&phiDot=40&thetaDot=30&psiDot=60",
        ),
        UnitFigure(
            "2.14",
            "the heavy symmetric top: θ, φ, l, m g, the axis between θ₁ and θ₂",
            plot_heavy_top,
            _heavy_top_arguments,
            lab="scene=heavytop",
        ),
        UnitFigure(
            "2.15",
            "the effective potential V(θ) with E′ and the turning points θ₁, θ₂",
            plot_effective_potential,
            _heavy_top_arguments,
            lab="scene=heavytop",
        ),
    ]
    return {e.number: e for e in entries}


#: The unit's figures: number (``"2.1"`` … ``"2.15"``, with ``"2.12a"`` … ``"2.12d"``) →
#: :class:`UnitFigure` (its function, caption, classroom arguments and lab scene).
UNIT_FIGURES: dict[str, UnitFigure] = _registry()


def unit_figure(number: str, *, style: str = "paper") -> Figure:
    """The unit's figure ``number`` (e.g. ``"2.5"``, ``"2.12a"``) drawn from poinsot's numbers
    with the classroom example (see :data:`UNIT_FIGURES`).

    Raises
    ------
    PoinsotError
        ``number`` is not one of the unit's figures (the message lists them), or ``style`` is
        not ``"paper"`` or ``"slides"``.
    """
    entry = UNIT_FIGURES[as_choice(number, "number", tuple(UNIT_FIGURES))]
    return entry.draw(style=style)
