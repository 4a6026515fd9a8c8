"""Rigid bodies: mass, centre of mass, inertia tensor, principal axes, kind of top, and the
angular momentum, kinetic energy and holding torque of a body turning with angular velocity ω
(the unit's eqs. 2.43–2.66).

Conventions (pinned by the ``test_convention_*`` tests):

* SI units: mass in kg, lengths in m, inertia in kg·m², ω in rad/s, L in kg·m²/s, T in J,
  torque in N·m.
* Products of inertia are **negated** as in the unit (2.49–2.50): ``I_xy = −Σ m x y``, so that
  ``L = I·ω`` (2.63) and ``T = ½ ω·I·ω`` (2.64). For one kilogram at (1, 2, 3) m::

      I = [[13, -2, -3],
           [-2, 10, -6],
           [-3, -6,  5]]  kg·m²

* :attr:`RigidBody.inertia` is about the **centre of mass**, in the body's reference axes.
* :attr:`RigidBody.principal_moments` are **ascending**; :attr:`RigidBody.principal_axes` holds
  the principal axes as **columns** of a proper rotation (``det = +1``), so
  ``inertia == axes @ diag(moments) @ axes.T``.
* Standard solids have their axis of symmetry along z and are centred on their centre of mass,
  except the cone, whose **apex is at the origin** with its axis along +z (centre of mass at
  ``(0, 0, 3h/4)``).

All physics runs in the compiled core (``poinsot._core``); this module converts arrays, adds
broadcasting and warnings.
"""

from __future__ import annotations

import dataclasses
import os
import stat
import warnings
from collections.abc import Callable, Iterable
from typing import Any

import numpy as np

from . import _core
from . import _display as show
from ._core import DEFAULTS as _DEFAULTS
from ._props import core_property
from ._validate import (
    FloatArray,
    as_callable,
    as_count,
    as_flag,
    as_float_array,
    as_matrices,
    as_scalar,
    as_vector3,
    as_vectors,
    returned,
)
from .errors import ArgumentTypeError, InvalidMeshError, PoinsotError

__all__ = [
    "RigidBody",
    "IntegrationErrorEstimate",
    "IntegrationWarning",
    "classify",
    "check_inertia",
    "DEFAULT_KIND_RTOL",
]

#: Default relative tolerance of :func:`classify` and :attr:`RigidBody.kind` (in units of the
#: largest principal moment): moments closer than this are "equal", smaller than this "zero".
DEFAULT_KIND_RTOL: float = _DEFAULTS["classify"]["rtol"]


def _type_name(value: Any) -> str:
    return type(value).__name__


class IntegrationWarning(UserWarning):
    """:meth:`RigidBody.from_density` stopped at ``max_evals`` before reaching ``rtol``; the
    body holds the best estimate, and :attr:`RigidBody.integration_error` its error."""


@dataclasses.dataclass(frozen=True)
class IntegrationErrorEstimate:
    """Error estimates of a body integrated from a density (:meth:`RigidBody.from_density`).

    Attributes
    ----------
    mass
        error estimate of the mass (kg).
    center_of_mass
        largest error estimate of the three coordinates of the centre of
        mass (m).
    inertia
        largest error estimate of the nine entries of the inertia tensor (kg·m²).
    evaluations
        number of density evaluations (points).
    converged
        whether ``rtol`` was reached within ``max_evals``.
    """

    mass: float
    center_of_mass: float
    inertia: float
    evaluations: int
    converged: bool


def classify(moments: Any, rtol: float = DEFAULT_KIND_RTOL) -> str:
    """The kind of top of principal moments ``moments`` (kg·m², shape (3,), any order).

    Returns one of ``"spherical top"`` (I1 = I2 = I3), ``"symmetric top"`` (two equal),
    ``"asymmetric top"`` (all different) or ``"rotor"`` (two equal and the third zero, like a
    thin rod or a diatomic molecule) — the unit's classification after eq. 2.66. Moments are
    "equal" when they differ by at most ``rtol`` times the largest, "zero" when at most ``rtol``
    times the largest. A single point mass (all moments zero) satisfies the unit's definition
    of a rotor (I1 = I2, I3 = 0) and is reported as ``"rotor"``.

    Raises
    ------
    InvalidInertiaError
        the moments are negative or violate I1 + I2 ≥ I3 (message names
        ``moments``).
    PoinsotError
        non-finite moments, a shape other than (3,), or a negative ``rtol``.
    """
    m = as_float_array(moments, "moments")
    if m.shape != (3,):
        raise PoinsotError(f"moments: must have shape (3,), got {m.shape}")
    return _core.classify(m, float(as_scalar(rtol, "rtol")))


def check_inertia(inertia: Any) -> FloatArray:
    """Checks that ``inertia`` (kg·m², shape (3, 3)) is the inertia tensor of some body about
    its centre of mass and returns it as a float array, exactly symmetrised.

    Conditions: finite; symmetric within 1e-9 of the largest entry; principal moments ≥ 0;
    the triangle inequality I1 + I2 ≥ I3 (tolerance 16 ε of the largest moment, so thin rods,
    plates and rings, which lie on the boundary, pass).

    Raises
    ------
    InvalidInertiaError
        one of the conditions fails; the message names ``inertia``, the
        failing condition and by how much.
    PoinsotError
        the shape is not (3, 3).
    """
    arr = as_float_array(inertia, "inertia", finite=False)
    if arr.shape != (3, 3):
        raise PoinsotError(f"inertia: must have shape (3, 3), got {arr.shape}")
    return _core.check_inertia(np.ascontiguousarray(arr))


def _scalar(value: Any, name: str) -> float:
    """A finite scalar; the core checks the sign (and names ``name``)."""
    return as_scalar(value, name)


class RigidBody(show.Displayed):
    """The mass properties of a rigid body, and what follows from them for a body turning with
    angular velocity ω.

    Build one with a constructor: :meth:`from_point_masses`, :meth:`from_inertia` (also
    ``RigidBody(mass, inertia, center_of_mass)``), the standard solids (:meth:`solid_sphere`,
    :meth:`spherical_shell`, :meth:`solid_cylinder`, :meth:`solid_cone`, :meth:`cuboid`,
    :meth:`ellipsoid`, :meth:`thin_rod`, :meth:`thin_disk`, :meth:`thin_ring`),
    :meth:`from_density`, :meth:`from_mesh`, :meth:`from_trimesh`, :meth:`load_mesh`; combine
    bodies with ``a + b`` or :meth:`combine`. Instances are immutable.

    Attributes
    ----------
    mass
        mass (kg).
    center_of_mass
        centre of mass (m), shape (3,).
    inertia
        inertia tensor about the centre of mass (kg·m², (3, 3)), products of inertia
        negated (eqs. 2.46–2.50).
    principal_moments
        principal moments (kg·m², (3,)), ascending.
    principal_axes
        principal axes as the columns of a proper rotation ((3, 3), det +1).
    kind
        "spherical top", "symmetric top", "asymmetric top" or "rotor".
    integration_error
        for bodies from :meth:`from_density` (and their translations), an
        :class:`IntegrationErrorEstimate`; otherwise ``None``.
    """

    __slots__ = ("_core", "_integration_error")

    def __init__(
        self,
        mass: float,
        inertia: Any,
        center_of_mass: Any = _DEFAULTS["RigidBody.__init__"]["center_of_mass"],
    ) -> None:
        """Same as :meth:`from_inertia`."""
        self._core: Any = _core.MassProperties.from_inertia(
            _scalar(mass, "mass"),
            as_vector3(center_of_mass, "center_of_mass"),
            _inertia_array(inertia),
        )
        self._integration_error: IntegrationErrorEstimate | None = None

    @classmethod
    def _wrap(
        cls, core: Any, integration_error: IntegrationErrorEstimate | None = None
    ) -> RigidBody:
        body = cls.__new__(cls)
        body._core = core
        body._integration_error = integration_error
        return body

    # ---- constructors ---------------------------------------------------------------------

    @classmethod
    def from_inertia(
        cls,
        mass: float,
        inertia: Any,
        center_of_mass: Any = _DEFAULTS["RigidBody.from_inertia"]["center_of_mass"],
        *,
        about: Any = None,
    ) -> RigidBody:
        """A body of mass ``mass`` (kg) whose inertia tensor about its centre of mass
        ``center_of_mass`` (m, (3,)) is ``inertia`` (kg·m², (3, 3), products negated as in
        eqs. 2.49–2.50).

        With ``about=P`` (m, (3,)), ``inertia`` is the tensor about the point P instead (as CAD
        programs often report it about the part's origin); it is shifted to the centre of mass
        by the parallel-axis theorem run backwards, I_cm = I_P − m (|d|² 1 − d dᵀ),
        d = com − P, and the checks allow for the round-off of that subtraction.

        Raises
        ------
        InvalidInertiaError
            ``inertia`` (about the centre of mass) is not finite, not
            symmetric, has a negative principal moment or violates I1 + I2 ≥ I3 (see
            :func:`check_inertia`).
        PoinsotError
            ``mass`` not finite and > 0, non-finite ``center_of_mass`` or
            ``about``, shapes.
        """
        if about is None:
            return cls(mass, inertia, center_of_mass)
        return cls._wrap(
            _core.MassProperties.from_inertia_about(
                _scalar(mass, "mass"),
                as_vector3(center_of_mass, "center_of_mass"),
                _inertia_array(inertia),
                as_vector3(about, "about"),
            )
        )

    @classmethod
    def from_point_masses(cls, masses: Any, positions: Any) -> RigidBody:
        """Point masses ``masses`` (kg, (N,), each > 0) at ``positions`` (m, (N, 3)): the sums
        of eqs. 2.46–2.50, taken about the centre of mass Σ m r / Σ m. One point mass is
        allowed (zero inertia about itself; its kind is "rotor", see :func:`classify`).

        Raises
        ------
        PoinsotError
            empty, non-finite or non-positive masses (with the index), non-finite
            positions, or shapes that do not match; the message names the argument.
        """
        m = as_float_array(masses, "masses")
        if m.ndim == 0:
            m = m.reshape(1)
        if m.ndim != 1:
            raise PoinsotError(f"masses: must have shape (N,), got {m.shape}")
        p = as_float_array(positions, "positions")
        if p.ndim == 1 and p.shape == (3,):
            p = p.reshape(1, 3)
        if p.ndim != 2 or p.shape[1] != 3:
            raise PoinsotError(f"positions: must have shape (N, 3), got {p.shape}")
        return cls._wrap(
            _core.MassProperties.from_point_masses(np.ascontiguousarray(m), np.ascontiguousarray(p))
        )

    @classmethod
    def solid_sphere(cls, mass: float, radius: float) -> RigidBody:
        """A uniform solid sphere of mass ``mass`` (kg) and radius ``radius`` (m), centred at the
        origin: I = 2/5 m r² about every axis (a spherical top)."""
        return cls._wrap(
            _core.MassProperties.solid_sphere(_scalar(mass, "mass"), _scalar(radius, "radius"))
        )

    @classmethod
    def spherical_shell(cls, mass: float, radius: float) -> RigidBody:
        """A thin uniform spherical shell of mass ``mass`` (kg) and radius ``radius`` (m),
        centred at the origin: I = 2/3 m r² about every axis."""
        return cls._wrap(
            _core.MassProperties.spherical_shell(_scalar(mass, "mass"), _scalar(radius, "radius"))
        )

    @classmethod
    def solid_cylinder(cls, mass: float, radius: float, height: float) -> RigidBody:
        """A uniform solid cylinder (kg; radius and height in m), axis along z, centred at its
        centre of mass: I_zz = m r²/2, I_xx = I_yy = m (3 r² + h²)/12."""
        return cls._wrap(
            _core.MassProperties.solid_cylinder(
                _scalar(mass, "mass"), _scalar(radius, "radius"), _scalar(height, "height")
            )
        )

    @classmethod
    def solid_cone(cls, mass: float, radius: float, height: float) -> RigidBody:
        """A uniform solid right circular cone (kg; base radius and height in m) with its
        **apex at the origin** and axis along +z (base at z = h): centre of mass (0, 0, 3h/4);
        about it I_zz = 3/10 m r², I_xx = I_yy = 3/20 m r² + 3/80 m h²."""
        return cls._wrap(
            _core.MassProperties.solid_cone(
                _scalar(mass, "mass"), _scalar(radius, "radius"), _scalar(height, "height")
            )
        )

    @classmethod
    def cuboid(cls, mass: float, sides: Any) -> RigidBody:
        """A uniform solid cuboid of mass ``mass`` (kg) with sides ``sides`` = (a, b, c) (m)
        along x, y, z, centred at the origin: I_xx = m (b² + c²)/12 and cyclically."""
        return cls._wrap(
            _core.MassProperties.cuboid(_scalar(mass, "mass"), as_vector3(sides, "sides"))
        )

    @staticmethod
    def cuboid_sides(mass: float, moments: Any) -> FloatArray:
        """The sides (a, b, c) (m), shape (3,), of the uniform solid cuboid of mass ``mass``
        (kg) whose principal moments about x, y, z are ``moments`` (kg·m², shape (3,)): the
        inverse of :meth:`cuboid`, a² = 6 (I_yy + I_zz − I_xx)/m and cyclically (computed in
        the core, to the last bits at any scale).

        Raises
        ------
        PoinsotError
            ``mass`` not finite and > 0; ``moments`` not finite and ≥ 0, not those of a box
            (each needs the other two to sum to more than it), or sides beyond the double
            range — the message names ``mass`` or ``moments``.
        """
        return np.asarray(
            _core.MassProperties.cuboid_sides(
                _scalar(mass, "mass"), np.ascontiguousarray(as_vector3(moments, "moments"))
            )
        )

    @classmethod
    def ellipsoid(cls, mass: float, semi_axes: Any) -> RigidBody:
        """A uniform solid ellipsoid of mass ``mass`` (kg) with semi-axes ``semi_axes`` =
        (a, b, c) (m) along x, y, z, centred at the origin: I_xx = m (b² + c²)/5 and
        cyclically."""
        return cls._wrap(
            _core.MassProperties.ellipsoid(
                _scalar(mass, "mass"), as_vector3(semi_axes, "semi_axes")
            )
        )

    @classmethod
    def thin_rod(cls, mass: float, length: float) -> RigidBody:
        """A thin uniform rod of mass ``mass`` (kg) and length ``length`` (m) along z, centred at
        the origin: I_xx = I_yy = m L²/12, I_zz = 0 (a rotor)."""
        return cls._wrap(
            _core.MassProperties.thin_rod(_scalar(mass, "mass"), _scalar(length, "length"))
        )

    @classmethod
    def thin_disk(cls, mass: float, radius: float) -> RigidBody:
        """A thin uniform disk of mass ``mass`` (kg) and radius ``radius`` (m) in the xy plane,
        centred at the origin: I_xx = I_yy = m r²/4, I_zz = m r²/2."""
        return cls._wrap(
            _core.MassProperties.thin_disk(_scalar(mass, "mass"), _scalar(radius, "radius"))
        )

    @classmethod
    def thin_ring(cls, mass: float, radius: float) -> RigidBody:
        """A thin uniform ring (hoop) of mass ``mass`` (kg) and radius ``radius`` (m) in the xy
        plane, centred at the origin: I_xx = I_yy = m r²/2, I_zz = m r²."""
        return cls._wrap(
            _core.MassProperties.thin_ring(_scalar(mass, "mass"), _scalar(radius, "radius"))
        )

    @classmethod
    def from_density(
        cls,
        density: Callable[[FloatArray], Any],
        bounds: Any,
        *,
        rtol: float = _DEFAULTS["RigidBody.from_density"]["rtol"],
        atol: float = _DEFAULTS["RigidBody.from_density"]["atol"],
        max_evals: int = _DEFAULTS["RigidBody.from_density"]["max_evals"],
    ) -> RigidBody:
        """The body of density ``density`` (kg/m³) over the box ``bounds`` (m), by adaptive
        cubature of eqs. 2.61–2.62 (Genz–Malik degree-7/5 rules, subdivision where the density
        varies most).

        Parameters
        ----------
        density
            a **vectorised** callable: given points of shape (N, 3) (m) it returns the
            densities, shape (N,) (kg/m³, finite and ≥ 0; a scalar is broadcast). It is
            called with batches of many points at once.
        bounds
            ``((xmin, xmax), (ymin, ymax), (zmin, zmax))`` (m), shape (3, 2), with
            min < max; the density is taken as zero outside.
        rtol
            relative tolerance: the mass to ``rtol·m``, the centre of mass to ``rtol`` times
            the half-diagonal of the box, the inertia to ``rtol·tr(I)/2``.
        atol
            absolute tolerance on the inertia entries (kg·m²); the looser one wins.
        max_evals
            the most density evaluations (points).

        Notes
        -----
        The error estimates are in :attr:`integration_error`. If ``max_evals`` is reached
        before the tolerance, the best estimate is returned with an :class:`IntegrationWarning`
        (discontinuous densities, e.g. the indicator of a shape, converge slowly).

        Raises
        ------
        PoinsotError
            bad ``bounds`` (shape, non-finite, min ≥ max), ``rtol``, ``atol`` or
            ``max_evals``; a density value that is negative, not finite or of the wrong
            shape; a density that integrates to zero mass (message names ``density``).
            Exceptions raised by ``density`` itself propagate unchanged.
        """
        if not callable(density):
            raise PoinsotError(
                f"density: must be a callable (N, 3) -> (N,), got {type(density).__name__}"
            )
        b = as_float_array(bounds, "bounds")
        if b.shape != (3, 2):
            raise PoinsotError(
                f"bounds: must have shape (3, 2) ((xmin, xmax), (ymin, ymax), (zmin, zmax)), got {b.shape}"
            )
        max_evals = as_count(max_evals, "max_evals", 1)
        as_callable(density, "density", optional=False)

        def batched(points: FloatArray) -> FloatArray:
            values = returned(density(points), "density", "real numbers", _type_name)
            if values.ndim == 0:
                values = np.full(points.shape[0], float(values))
            if values.shape != (points.shape[0],):
                raise PoinsotError(
                    f"density: must return shape (N,) = ({points.shape[0]},) for points of shape "
                    f"{points.shape}, got {values.shape}"
                )
            return np.ascontiguousarray(values)

        core, mass_err, com_err, inertia_err, evals, converged = _core.MassProperties.from_density(
            batched,
            np.ascontiguousarray(b),
            (as_scalar(rtol, "rtol"), as_scalar(atol, "atol"), int(max_evals)),
        )
        estimate = IntegrationErrorEstimate(mass_err, com_err, inertia_err, evals, converged)
        if not converged:
            warnings.warn(
                f"from_density: max_evals={max_evals} reached before rtol={rtol}; estimated "
                f"errors: mass {mass_err:.3e} kg, centre of mass {com_err:.3e} m, inertia "
                f"{inertia_err:.3e} kg·m² (see RigidBody.integration_error)",
                IntegrationWarning,
                stacklevel=2,
            )
        return cls._wrap(core, estimate)

    @classmethod
    def from_mesh(
        cls,
        vertices: Any,
        faces: Any,
        density: float = _DEFAULTS["RigidBody.from_mesh"]["density"],
        *,
        merge_vertices: bool = False,
    ) -> RigidBody:
        """The solid bounded by a closed triangle mesh, of uniform ``density`` (kg/m³), by exact
        polyhedral integrals (eqs. 2.61–2.62 summed over signed tetrahedra).

        Parameters
        ----------
        vertices
            vertex coordinates (m), shape (N, 3).
        faces
            vertex indices, integer array of shape (M, 3); each face counter-clockwise
            seen from outside (normals point out of the solid).
        density
            uniform density (kg/m³), > 0.
        merge_vertices
            first merge vertices that lie within ``2**-22`` (``MERGE_RTOL`` of the core)
            of the largest coordinate magnitude of each other, in each coordinate: two
            units in the last place of single precision, the precision of binary STL
            files. Needed for meshes that repeat vertices per face, such as STL
            "triangle soups", and for CAD exports whose shared corners differ in their
            last bits. Each corner becomes the lowest-numbered vertex of its group; when
            the merged mesh is still open, the message gives the distance used.

        Notes
        -----
        The mesh is checked before integrating and refused, never silently integrated, if it
        does not bound a solid: indices out of range, non-finite vertices, all faces degenerate,
        open (boundary edges), non-manifold (an edge shared by more than two faces),
        inconsistently oriented, inside-out (inward normals), of zero volume, self-intersecting
        (two faces meet beyond a vertex or edge they share; faces that merely touch count),
        or with shells nested wrongly (a shell inside another of the same winding, a cavity
        outside any solid). Vertices that no face uses are ignored.

        Raises
        ------
        InvalidMeshError
            one of the conditions above; the message names ``faces`` or
            ``vertices`` and says what is wrong and where (e.g. the number of boundary
            edges and one of them).
        PoinsotError
            ``density`` not finite and > 0.
        """
        v = as_float_array(vertices, "vertices", finite=False)
        if v.ndim != 2 or v.shape[1] != 3:
            raise InvalidMeshError(f"vertices: must have shape (N, 3), got {v.shape}")
        try:
            f = np.asarray(faces)
        except (TypeError, ValueError) as exc:
            raise InvalidMeshError(
                f"faces: must be an (M, 3) array of integer vertex indices ({exc})"
            ) from None
        if f.ndim != 2 or f.shape[1] != 3:
            raise InvalidMeshError(f"faces: must have shape (M, 3), got {f.shape}")
        if f.size and not np.issubdtype(f.dtype, np.integer):
            raise InvalidMeshError(
                f"faces: must be an array of integer vertex indices, got dtype {f.dtype}"
            )
        if f.dtype == np.uint64 and f.size and int(f.max()) > np.iinfo(np.int64).max:
            raise InvalidMeshError(
                f"faces: index {int(f.max())} is out of range for {len(v)} vertices"
            )
        merge = as_flag(merge_vertices, "merge_vertices")
        rho = _scalar(density, "density")
        return cls._wrap(
            _core.MassProperties.from_mesh(
                np.ascontiguousarray(v, dtype=np.float64),
                np.ascontiguousarray(f, dtype=np.int64),
                rho,
                merge,
            )
        )

    @classmethod
    def from_trimesh(
        cls,
        mesh: Any,
        density: float = _DEFAULTS["RigidBody.from_trimesh"]["density"],
        *,
        merge_vertices: bool = False,
    ) -> RigidBody:
        """The solid bounded by a ``trimesh.Trimesh`` (vertices in m), of uniform ``density``
        (kg/m³): :meth:`from_mesh` of ``mesh.vertices`` and ``mesh.faces`` with the mesh's
        topology as it is (pass ``merge_vertices=True`` for a mesh built with
        ``process=False`` from a triangle soup). Raises :class:`InvalidMeshError` for meshes
        that do not bound a solid, unlike ``mesh.mass_properties``."""
        if not (hasattr(mesh, "vertices") and hasattr(mesh, "faces")):
            raise InvalidMeshError(
                f"mesh: must be a trimesh.Trimesh (with .vertices and .faces), got {type(mesh).__name__}"
            )
        return cls.from_mesh(mesh.vertices, mesh.faces, density, merge_vertices=merge_vertices)

    @classmethod
    def load_mesh(
        cls,
        path: str | bytes | os.PathLike[str] | os.PathLike[bytes],
        density: float = _DEFAULTS["RigidBody.load_mesh"]["density"],
    ) -> RigidBody:
        """The solid bounded by the triangle mesh in the file ``path`` (.stl, .obj, .ply, ...;
        coordinates in m), of uniform ``density`` (kg/m³), read with trimesh (the optional
        extra ``poinsot[mesh]``).

        The file is read with ``process=False`` (trimesh repairs nothing, so the checks see the
        real topology), then vertices within ``2**-22`` of the largest coordinate magnitude of
        each other are merged (:meth:`from_mesh` with ``merge_vertices=True``): STL files store
        every triangle with its own three vertices, and CAD exports (SolidWorks) give a shared
        corner coordinates that differ in their last bits; without merging every STL would look
        open. See :meth:`from_mesh` for the checks.

        Memory: a binary STL file's triangle count (in its header) is checked against the
        memory budget (``poinsot.memory_budget()``) before the file is read, at the peak bytes
        per triangle of reading and checking it (``MESH_FILE_BYTES_PER_TRIANGLE`` of the core,
        768); other formats are refused when the file alone is larger than the budget, and
        running out of memory while reading is reported as that, not as an invalid mesh. A
        file name may hold any bytes but NUL (names that are not UTF-8 included: pass them as
        ``bytes`` or as Python decodes them, with surrogate escapes).

        Raises
        ------
        ImportError
            trimesh is not installed.
        PoinsotError
            ``path`` does not exist, holds a NUL byte, is not a regular file (a
            directory, a device such as ``/dev/zero``), is larger than the memory budget,
            or holds more triangles than the memory budget allows.
        InvalidMeshError
            the file cannot be read as a mesh, holds no triangles, or holds a
            mesh that does not bound a solid.
        """
        try:
            import trimesh
        except ImportError:  # pragma: no cover - exercised only without the extra
            raise ImportError(
                "RigidBody.load_mesh reads files with trimesh, which is not installed: "
                "pip install 'poinsot[mesh]' (or pip install trimesh)"
            ) from None
        if not isinstance(path, (str, bytes, os.PathLike)):
            raise ArgumentTypeError(
                f"path: must be a file name (str, bytes or os.PathLike), got {type(path).__name__}"
            )
        name = os.fsdecode(os.fspath(path))
        if "\x00" in name:
            raise PoinsotError(f"path: {name!r} holds a NUL byte, which no file name can hold")
        try:
            info = os.stat(name)
        except OSError as exc:
            raise PoinsotError(f"path: cannot read {name!r}: {exc.strerror or exc}") from None
        if not stat.S_ISREG(info.st_mode):
            raise PoinsotError(f"path: {name!r} is not a regular file")
        from .limits import memory_budget

        if info.st_size > memory_budget():
            raise PoinsotError(
                f"path: {name!r} has {info.st_size} bytes, more than the memory budget "
                f"of {memory_budget()} bytes (see poinsot.set_memory_budget)"
            )
        kind = os.path.splitext(name)[1].lstrip(".").lower()
        try:
            with open(name, "rb") as handle:
                if kind == "stl":
                    _check_stl_size(handle, info.st_size)
                # The open file, not its name: trimesh encodes names as UTF-8, which a name
                # that is not UTF-8 (decoded with surrogate escapes) cannot be.
                loaded = trimesh.load(
                    handle,
                    file_type=kind,
                    process=False,
                    force="mesh",
                    resolver=trimesh.resolvers.FilePathResolver(name),
                )
        except PoinsotError:
            raise
        except MemoryError:
            raise PoinsotError(
                f"path: reading {name!r} ran out of memory (the memory budget is "
                f"{memory_budget()} bytes; see poinsot.set_memory_budget)"
            ) from None
        except OSError as exc:
            raise PoinsotError(f"path: cannot read {name!r}: {exc.strerror or exc}") from None
        except ImportError as exc:  # a decoder trimesh needs for this file is missing
            raise ImportError(
                f"path: reading {name!r} needs the Python package {exc.name!r}, which is not "
                "installed: pip install 'poinsot[mesh]'",
                name=exc.name,
            ) from None
        except Exception as exc:
            raise InvalidMeshError(
                f"path: {name!r} cannot be read as a triangle mesh ({type(exc).__name__}: {exc})"
            ) from None
        if not isinstance(loaded, trimesh.Trimesh) or len(loaded.faces) == 0:
            raise InvalidMeshError(f"path: {name!r} holds no triangle mesh")
        return cls.from_mesh(loaded.vertices, loaded.faces, density, merge_vertices=True)

    @classmethod
    def combine(cls, bodies: Iterable[RigidBody]) -> RigidBody:
        """The body made of ``bodies`` rigidly joined: masses add, the centre of mass is the
        mass-weighted mean, each inertia is shifted to the common centre of mass by the
        parallel-axis theorem and summed. ``a + b`` is the same for two bodies."""
        try:
            items = list(bodies)
        except TypeError:
            raise ArgumentTypeError(
                f"bodies: must be an iterable of RigidBody, got {type(bodies).__name__}"
            ) from None
        if not items:
            raise PoinsotError("bodies: must hold at least one body, got none")
        for i, b in enumerate(items):
            if not isinstance(b, RigidBody):
                raise ArgumentTypeError(
                    f"bodies: item {i} is a {type(b).__name__}, not a RigidBody"
                )
        return cls._wrap(_core.MassProperties.combine([b._core for b in items]))

    # ---- attributes -----------------------------------------------------------------------

    mass = core_property("mass", "Mass (kg).", float)
    center_of_mass = core_property("center_of_mass", "Centre of mass (m), shape (3,).", np.asarray)

    inertia = core_property(
        "inertia",
        """Inertia tensor about the centre of mass (kg·m², (3, 3)), products of inertia negated
        (I_xy = −Σ m x y, eqs. 2.46–2.50), so that L = I·ω.""",
        np.asarray,
    )

    @property
    def principal_moments(self) -> FloatArray:
        """Principal moments of inertia (kg·m², (3,)), ascending (the I1, I2, I3 of eq. 2.66)."""
        return np.asarray(self._core.principal(DEFAULT_KIND_RTOL)[0])

    @property
    def principal_axes(self) -> FloatArray:
        """Principal axes as the columns of a proper rotation matrix ((3, 3), det = +1): column
        k is the axis of ``principal_moments[k]`` and ``inertia = axes @ diag(moments) @
        axes.T``. Where moments coincide (within :data:`DEFAULT_KIND_RTOL`) the axes are chosen
        cleanly: identity for a spherical top; for a symmetric top the pair spans the plane
        perpendicular to the distinct axis starting from the first coordinate axis."""
        return np.asarray(self._core.principal(DEFAULT_KIND_RTOL)[1])

    @property
    def kind(self) -> str:
        """ "spherical top", "symmetric top", "asymmetric top" or "rotor" (see :func:`classify`;
        relative tolerance :data:`DEFAULT_KIND_RTOL`)."""
        return str(self._core.kind(DEFAULT_KIND_RTOL))

    @property
    def integration_error(self) -> IntegrationErrorEstimate | None:
        """Error estimates of a body from :meth:`from_density` (kept by :meth:`translated`);
        ``None`` for every other body."""
        return self._integration_error

    # ---- methods --------------------------------------------------------------------------

    def inertia_about(self, point: Any) -> FloatArray:
        """Inertia tensor about ``point`` (m, shape (..., 3)) in the same axes (kg·m², shape
        (..., 3, 3)): the parallel-axis theorem I_P = I_cm + m (|d|² 1 − d dᵀ), d = com − P."""
        pts, lead = as_vectors(point, "point")
        return np.asarray(self._core.inertia_about(pts)).reshape(lead + (3, 3))

    def _per_omega(self, name: str, omega: Any, about: Any, tail: tuple[int, ...]) -> Any:
        w, lead = as_vectors(omega, "omega")
        p = None if about is None else as_vector3(about, "about")
        out = np.asarray(getattr(self._core, name)(w, p)).reshape(lead + tail)
        # One ω and a scalar result: a numpy float, not a 0-d array.
        return out[()] if out.ndim == 0 else out

    def angular_momentum(self, omega: Any, about: Any = None) -> FloatArray:
        """Angular momentum L = I·ω (kg·m²/s; eqs. 2.44, 2.51, 2.63) of the body turning with
        angular velocity ``omega`` (rad/s, shape (..., 3)) → shape (..., 3).

        ``about=None``: about the centre of mass (spin angular momentum). ``about=P`` (m, (3,)):
        the body turning about the fixed point P, L_P = I_P·ω = Σ m r × (ω × r) with r from P.
        """
        return self._per_omega("angular_momentum", omega, about, (3,))

    def kinetic_energy(self, omega: Any, about: Any = None) -> FloatArray | float:
        """Kinetic energy of rotation T = ½ ω·I·ω = ½ ω·L (J; eqs. 2.53, 2.55, 2.64) for angular
        velocity ``omega`` (rad/s, shape (..., 3)) → shape (...) (a float for one ω).

        ``about=None``: the energy of rotation about the centre of mass. ``about=P`` (m, (3,)):
        the whole kinetic energy of the body turning about the fixed point P.
        """
        return self._per_omega("kinetic_energy", omega, about, ())

    def holding_torque(self, omega: Any, about: Any = None) -> FloatArray:
        """The torque N = ω × L (N·m; eqs. 2.58–2.59) that keeps the body turning at the constant
        angular velocity ``omega`` (rad/s, shape (..., 3)) → shape (..., 3): L is carried round
        with the body, dL/dt = ω × L = N. Zero exactly when ω lies along a principal axis.
        ``about`` as in :meth:`angular_momentum`."""
        return self._per_omega("holding_torque", omega, about, (3,))

    def momentum_angle(
        self, omega: Any, about: Any = None, *, degrees: bool = False
    ) -> FloatArray | float:
        """The angle between L and ω (rad, or degrees with ``degrees=True``) for angular velocity
        ``omega`` (rad/s, shape (..., 3)) → shape (...) (a float for one ω): zero when ω lies along a principal
        axis; otherwise L is not parallel to ω (eq. 2.57).

        Raises
        ------
        PoinsotError
            ω = 0, or L = 0 (ω along an axis of zero moment), where the angle is
            undefined (message names ``omega``).
        """
        a = self._per_omega("momentum_angle", omega, about, ())
        return np.degrees(a)[()] if as_flag(degrees, "degrees") else a

    def translated(self, offset: Any) -> RigidBody:
        """The same body moved by ``offset`` (m, (3,)): the centre of mass moves, the inertia
        about it is unchanged."""
        return RigidBody._wrap(
            self._core.translated(as_vector3(offset, "offset")), self._integration_error
        )

    def rotated(self, rotation: Any) -> RigidBody:
        """The same body rotated actively by ``rotation`` (a 3×3 rotation matrix or a
        ``scipy.spatial.transform.Rotation``) **about the origin** of its axes (not about its
        centre of mass): com ↦ R·com, I ↦ R I Rᵀ. To turn it in place, rotate then translate
        back, or build it at the origin first.

        Raises
        ------
        InvalidRotationError
            ``rotation`` is not orthonormal with det = +1 (within 1e-9).
        """
        mats, lead = as_matrices(rotation, "rotation")
        if lead != ():
            raise PoinsotError(
                f"rotation: must be a single rotation, got {mats.shape[0]} of shape {lead}"
            )
        return RigidBody._wrap(self._core.rotated(mats[0]))

    def __add__(self, other: object) -> RigidBody:
        if not isinstance(other, RigidBody):
            return NotImplemented
        return RigidBody.combine([self, other])

    def __radd__(self, other: object) -> RigidBody:
        # So that sum(bodies) works (it starts from 0).
        if isinstance(other, (int, float)) and other == 0:
            return self
        return NotImplemented

    def to_dict(self) -> dict[str, Any]:
        """A JSON-ready summary: mass (kg), center_of_mass (m), inertia (kg·m², about the
        centre of mass), principal_moments, principal_axes (columns), kind, and for bodies
        from a density the integration error estimates."""
        d: dict[str, Any] = {
            "mass": self.mass,
            "center_of_mass": self.center_of_mass.tolist(),
            "inertia": self.inertia.tolist(),
            "principal_moments": self.principal_moments.tolist(),
            "principal_axes": self.principal_axes.tolist(),
            "kind": self.kind,
            "units": {"mass": "kg", "center_of_mass": "m", "inertia": "kg m^2"},
        }
        if self._integration_error is not None:
            d["integration_error"] = dataclasses.asdict(self._integration_error)
        return d

    def _rows(self) -> list[show.Row]:
        rows = [
            show.scalar("mass", "mass", "m", self.mass, "kg"),
            show.vec("center_of_mass", "centre of mass", "r_cm", self.center_of_mass, "m"),
            show.vec(
                "principal_moments",
                "principal moments",
                "I₁, I₂, I₃",
                self.principal_moments,
                "kg·m²",
            ),
            show.words("kind", "kind of top (after 2.66)", self.kind),
            show.mat(
                "inertia",
                "inertia tensor about the centre of mass (2.60)",
                "I",
                self.inertia,
                "kg·m²",
            ),
            show.mat("principal_axes", "principal axes (columns)", "", self.principal_axes),
        ]
        err = self._integration_error
        if err is not None:
            rows += [
                show.scalar(
                    "integration_error.mass",
                    "error estimate of the mass",
                    "",
                    err.mass,
                    "kg",
                    brief=False,
                ),
                show.scalar(
                    "integration_error.center_of_mass",
                    "error estimate of the centre of mass",
                    "",
                    err.center_of_mass,
                    "m",
                    brief=False,
                ),
                show.scalar(
                    "integration_error.inertia",
                    "error estimate of the inertia",
                    "",
                    err.inertia,
                    "kg·m²",
                    brief=False,
                ),
                show.scalar(
                    "integration_error.evaluations",
                    "density evaluations",
                    "",
                    err.evaluations,
                    brief=False,
                ),
                show.words(
                    "integration_error.converged", "converged", str(err.converged), brief=False
                ),
            ]
        return rows

    def _repr_latex_(self) -> str:
        """The inertia tensor about the centre of mass as a matrix with its unit (eq. 2.60;
        products of inertia negated, 2.49–2.50), for Jupyter and nbconvert."""
        return show.latex_matrix(r"\overline{I}", self.inertia, r"\mathrm{kg\,m^{2}}")

    def __reduce__(self) -> tuple[Any, ...]:
        return (_restore, (self.mass, self.inertia, self.center_of_mass, self._integration_error))


def _restore(
    mass: float,
    inertia: FloatArray,
    center_of_mass: FloatArray,
    err: IntegrationErrorEstimate | None,
) -> RigidBody:
    body = RigidBody(mass, inertia, center_of_mass)
    body._integration_error = err
    return body


def _inertia_array(inertia: Any) -> FloatArray:
    arr = as_float_array(inertia, "inertia", finite=False)
    if arr.shape != (3, 3):
        raise PoinsotError(f"inertia: must have shape (3, 3), got {arr.shape}")
    return np.ascontiguousarray(arr)


def _check_stl_size(handle: Any, size: int) -> None:
    """For a binary STL file (84 header bytes, then 50 bytes per triangle, the count in bytes
    80–84), checks its triangle count against the memory budget before it is read
    (``_core.check_mesh_file``: the error names ``path`` and the budget); ASCII STL files
    pass (the file size was checked)."""
    head = handle.read(84)
    handle.seek(0)
    if len(head) == 84:
        count = int.from_bytes(head[80:84], "little")
        if size == 84 + 50 * count:
            _core.check_mesh_file(float(count))
