"""poinsot: moving frames and the motion of rigid bodies.

The public API (the README and the docs/ pages describe each part; ARCHITECTURE.md the layers):

* rotations: :func:`euler_to_matrix`, :func:`matrix_to_euler`, :func:`rotation_axis`
  (Euler's theorem), :func:`screw_axis` (Chasles' theorem), :func:`body_angular_velocity`
  (the unit's eq. 2.99) and :func:`euler_rates`, quaternion helpers;
* mass properties: :class:`RigidBody` (inertia tensor, principal axes, kind, L, T);
* moving frames: :class:`MovingFrame` (eqs. 2.1–2.28), :func:`simulate_particle`;
* the rotating Earth: :class:`Earth` (effective gravity, Coriolis, the falling body of
  eq. 2.42, projectiles, the Foucault pendulum, inertial oscillations); :class:`RigidEarth`
  (the Earth as a rigid top: Euler's period, the Chandler period, precession, nutation);
  :func:`polar_motion` (the IERS pole, 1962 to now) and :func:`fit_wobble` (its Chandler and
  annual wobbles);
* rigid-body dynamics: :func:`simulate` (Euler's equations 2.71 with torques; exact flow,
  Lie–Poisson splitting, RK4, DOP853), :func:`simulate_batch`, :class:`FreeSymmetricTop`
  (2.77–2.97), :class:`FreeRigidBody` (the exact asymmetric top), :func:`axis_stability`;
  :mod:`poinsot.special` holds the Jacobi elliptic functions;
* the heavy symmetric top: :class:`HeavyTop` (eqs. 2.98–2.121: constants, effective
  potential, turning points, steady precession, the exact motion by elliptic functions);
* errors: :class:`PoinsotError` (a ``ValueError``) and its subclasses;
* limits: :func:`memory_budget`, :func:`set_memory_budget` (the largest output of one call;
  every long run also takes ``max_steps`` and stops on Ctrl-C);
* pictures: :mod:`poinsot.plots` (matplotlib, one module per topic);
* parameter studies: :mod:`poinsot.sweep` (a model over a grid of its keywords as an xarray
  ``Dataset``, locally or on a Dask cluster; the ``[parallel]`` extra).

SI units and radians everywhere; quaternions are scalar-first ``[w, x, y, z]``.
"""

from __future__ import annotations

from ._core import __version__
from .body import *  # noqa: F403
from .body import __all__ as _body_all
from .dynamics import *  # noqa: F403
from .dynamics import __all__ as _dynamics_all
from .earth import *  # noqa: F403
from .earth import __all__ as _earth_all
from .errors import *  # noqa: F403
from .errors import __all__ as _errors_all
from .frames import *  # noqa: F403
from .frames import __all__ as _frames_all
from .free import *  # noqa: F403
from .free import __all__ as _free_all
from .gyrocompass import *  # noqa: F403
from .gyrocompass import __all__ as _gyrocompass_all
from .limits import *  # noqa: F403
from .limits import __all__ as _limits_all
from .polar import *  # noqa: F403
from .polar import __all__ as _polar_all
from .rigid_earth import *  # noqa: F403
from .rigid_earth import __all__ as _rigid_earth_all
from .rotation import *  # noqa: F403
from .rotation import __all__ as _rotation_all
from .top import *  # noqa: F403
from .top import __all__ as _top_all

__all__ = [
    "__version__",
    *_errors_all,
    *_rotation_all,
    *_body_all,
    *_frames_all,
    *_earth_all,
    *_rigid_earth_all,
    *_polar_all,
    *_dynamics_all,
    *_gyrocompass_all,
    *_free_all,
    *_top_all,
    *_limits_all,
]

from . import special, sweep  # noqa: F401  (the public submodules, imported with the package)
