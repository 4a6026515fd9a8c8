"""Pictures of poinsot's results (matplotlib, the optional ``plot`` extra), one module per topic.

* :mod:`poinsot.plots.inertia` — the inertia ellipsoid of a :class:`poinsot.RigidBody`;
* :mod:`poinsot.plots.free` — torque-free motion: ω(t), the body and space cones, polhodes,
  conservation, the tumbling box;
* :mod:`poinsot.plots.top` — the heavy top: V(θ), the locus of the axis, the angles, steady
  precession, the animation;
* :mod:`poinsot.plots.earth` — the rotating Earth: deflection, trajectories, the Foucault
  rosette, inertial circles, the pendulum's animation;
* :mod:`poinsot.plots.unit` — the unit's own Figs. 2.1–2.15 from poinsot's numbers, by number:
  :func:`unit_figure` and the registry :data:`UNIT_FIGURES` (importable from here, not in
  ``__all__``, which lists the drawing functions; docs/figures.md lists them).

Every function returns a :class:`matplotlib.figure.Figure` (or an animation) and never calls
``plt.show()``: save it with ``fig.savefig(...)`` or show it yourself. The physics comes from the
rest of poinsot; these functions only draw. matplotlib is imported when a picture is drawn, so
``import poinsot.plots`` works without it.
"""

from __future__ import annotations

from .earth import (
    animate_foucault,
    plot_deflection,
    plot_foucault_rosette,
    plot_inertial_circles,
    plot_trajectory,
)
from .free import (
    animate_free_body,
    animate_tumbling_box,
    plot_cones,
    plot_conservation,
    plot_omega,
    plot_polhodes,
)
from .inertia import plot_inertia_ellipsoid
from .top import (
    animate_top,
    plot_angles,
    plot_axis_locus,
    plot_effective_potential,
    plot_steady_precession,
    save_top_plots,
)
from .unit import (
    UNIT_FIGURES,  # noqa: F401 - the registry, importable from here; __all__ lists the functions
    plot_body_cone,
    plot_centripetal,
    plot_dumbbell,
    plot_earth_centrifugal,
    plot_earth_coriolis,
    plot_euler_angle_steps,
    plot_euler_theorem,
    plot_flow_into_low,
    plot_heavy_top,
    plot_omega_components,
    plot_rotating_frame,
    plot_translating_frame,
    unit_figure,
)

__all__ = [
    "plot_inertia_ellipsoid",
    "plot_omega",
    "plot_cones",
    "plot_polhodes",
    "plot_conservation",
    "animate_tumbling_box",
    "animate_free_body",
    "plot_effective_potential",
    "plot_axis_locus",
    "plot_angles",
    "plot_steady_precession",
    "animate_top",
    "save_top_plots",
    "plot_deflection",
    "plot_trajectory",
    "plot_foucault_rosette",
    "plot_inertial_circles",
    "animate_foucault",
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
    "unit_figure",
]
