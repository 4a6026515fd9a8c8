"""Pictures of poinsot's results (matplotlib, the optional ``plot`` extra), one module per topic.

* :mod:`poinsot.plots.inertia` — the inertia ellipsoid of a :class:`poinsot.RigidBody`;
* :mod:`poinsot.plots.free` — torque-free motion: ω(t), the body and space cones, polhodes,
  conservation, the tumbling box;
* :mod:`poinsot.plots.top` — the heavy top: V(θ), the locus of the axis, the angles, steady
  precession, the animation;
* :mod:`poinsot.plots.earth` — the rotating Earth: deflection, trajectories, the Foucault
  rosette, inertial circles, the pendulum's animation;
* :mod:`poinsot.plots.gyrocompass` — the gyrocompass settling on the meridian;
* :mod:`poinsot.plots.unit` — the unit's own Figs. 2.1–2.15 from poinsot's numbers, by number:
  :func:`unit_figure` and the registry :data:`UNIT_FIGURES` (importable from here, not in
  ``__all__``, which lists the drawing functions; docs/figures.md lists them).

Every function returns a :class:`matplotlib.figure.Figure` (or an animation) and never calls
``plt.show()``: save it with ``fig.savefig(...)`` or show it yourself. The physics comes from the
rest of poinsot; these functions only draw. matplotlib is imported when a picture is drawn, so
``import poinsot.plots`` works without it.
"""

from __future__ import annotations

from . import earth, free, gyrocompass, inertia, top, unit
from .earth import *  # noqa: F403 - each module's drawing functions, listed in its __all__
from .free import *  # noqa: F403
from .gyrocompass import *  # noqa: F403
from .inertia import *  # noqa: F403
from .top import *  # noqa: F403
from .unit import *  # noqa: F403
from .unit import UNIT_FIGURES  # noqa: F401 - the registry, importable from here

#: What :mod:`poinsot.plots.unit` lists besides its drawing functions (importable from there).
_UNIT_HELPERS = {"classroom_free_top", "classroom_heavy_top", "UnitFigure", "UNIT_FIGURES"}

__all__ = [  # the drawing functions, as their modules list them
    *inertia.__all__,
    *free.__all__,
    *top.__all__,
    *earth.__all__,
    *gyrocompass.__all__,
    *(name for name in unit.__all__ if name not in _UNIT_HELPERS),
]
