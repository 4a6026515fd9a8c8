# Stubs of the compiled module poinsot._core (checked with `python -m mypy.stubtest`).
# Sections mirror the binding files in crates/poinsot-py/src/.
from collections.abc import Callable, Sequence
from typing import Any, TypeAlias, TypedDict, final

import numpy as np
from numpy.typing import NDArray

# A long call's progress callback: called with the fraction done, in [0, 1].
_Progress: TypeAlias = Callable[[float], Any] | None
# A run's settings, as _validate.run_settings makes them: samples, rtol, atol, max_steps.
_RunSettings: TypeAlias = tuple[int, float, float, int]
# A run's start: the inertia tensor (3, 3), omega0 (3,) and the attitude (4,) or None.
_Start: TypeAlias = tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64] | None]
# A batch of bodies: principal moments (N, 3), omega0 (N, 3) and the attitudes (N, 4) or None.
_Bodies: TypeAlias = tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64] | None]
# A torque, as dynamics._torque_spec makes it: the kind, the (3,) vector and the scalar.
_TorqueSpec: TypeAlias = tuple[str, NDArray[np.float64], float]

__version__: str
DEFAULT_MAX_STEPS: int
DEFAULT_MEMORY_BUDGET: int

# ---- defaults (defaults.rs): every public call's defaults, by call and argument ----
_Vec3 = tuple[float, float, float]

class _Seq(TypedDict):
    seq: str

class _EulerRates(TypedDict):
    seq: str
    frame: str

class _Tol(TypedDict):
    tol: float

class _Rtol(TypedDict):
    rtol: float

class _CenterOfMass(TypedDict):
    center_of_mass: _Vec3

class _Cubature(TypedDict):
    rtol: float
    atol: float
    max_evals: int

class _Density(TypedDict):
    density: float

class _MovingFrame(TypedDict):
    origin: _Vec3
    velocity: _Vec3
    acceleration: _Vec3
    angular_velocity: _Vec3
    angular_acceleration: _Vec3

class _AtRest(TypedDict):
    velocity: _Vec3
    acceleration: _Vec3

class _Run(TypedDict):
    samples: int
    rtol: float
    atol: float
    max_steps: int

class _Particle(_Run):
    mass: float
    stiffness: float

class _Earth(TypedDict):
    rotation_rate: float
    radius: float
    g: float

class _RigidEarth(TypedDict):
    dynamical_flattening: float
    rotation_rate: float
    obliquity: float

class _RigidEarthSimulate(TypedDict):
    samples: int
    moon_node: float
    max_steps: int

class _RigidEarthAveragedPole(TypedDict):
    moon_node: float
    nutation_scale: float

class _PolarMotion(TypedDict):
    source: str

class _FitWobble(TypedDict):
    annual_period: float

class _SolarDay(TypedDict):
    radius: float
    g: float

class _SweepFall(TypedDict):
    gravity: str
    rtol: float
    atol: float
    max_steps: int

class _Fall(_SweepFall):
    samples: int

class _Projectile(_Fall):
    height: float

class _Foucault(_Run):
    length: float
    amplitude: float
    azimuth: float
    duration: float

class _Inertial(_Run):
    velocity: tuple[float, float]

class _Low(_Run):
    radius: float
    parcels: int
    pull: float
    friction: float
    duration: float

class _G(TypedDict):
    g: float

class _Simulate(_Run):
    method: str

class _Batch(TypedDict):
    method: str
    max_steps: int

class _Frame(TypedDict):
    frame: str

class _Samples(TypedDict):
    samples: int

class _Spin(TypedDict):
    spin: float

class _FromSpin(TypedDict):
    theta_dot: float
    phi_dot: float
    phi: float
    psi: float

class _HeavyTop(_FromSpin):
    psi_dot: float

class _FromBody(_FromSpin):
    g: float

class _CompassTuned(TypedDict):
    pendulosity: float
    damping: float
    inertia: tuple[float, float, float]

class _Compass(_CompassTuned):
    angular_momentum: float

_Defaults = TypedDict(
    "_Defaults",
    {
        "check_rotation_matrix": _Tol,
        "euler_to_matrix": _Seq,
        "matrix_to_euler": _Seq,
        "body_angular_velocity": _Seq,
        "space_angular_velocity": _Seq,
        "euler_rates": _EulerRates,
        "classify": _Rtol,
        "RigidBody.__init__": _CenterOfMass,
        "RigidBody.from_inertia": _CenterOfMass,
        "RigidBody.from_density": _Cubature,
        "RigidBody.from_mesh": _Density,
        "RigidBody.from_trimesh": _Density,
        "RigidBody.load_mesh": _Density,
        "MovingFrame.__init__": _MovingFrame,
        "MovingFrame.to_fixed": _AtRest,
        "MovingFrame.to_moving": _AtRest,
        "SpringParticle.simulate": _Run,
        "simulate_particle": _Particle,
        "Earth.__init__": _Earth,
        "Earth.solar_day": _SolarDay,
        "RigidEarth.__init__": _RigidEarth,
        "RigidEarth.simulate": _RigidEarthSimulate,
        "RigidEarth.averaged_pole": _RigidEarthAveragedPole,
        "polar_motion": _PolarMotion,
        "fit_wobble": _FitWobble,
        "Earth.drop": _Fall,
        "Earth.projectile": _Projectile,
        "Earth.foucault": _Foucault,
        "Earth.inertial_oscillation": _Inertial,
        "Earth.flow_into_low": _Low,
        "GravityTorque.__init__": _G,
        "simulate": _Simulate,
        "simulate_batch": _Batch,
        "Gyrocompass.__init__": _Compass,
        "Gyrocompass.schuler_tuned": _CompassTuned,
        "Gyrocompass.simulate": _Simulate,
        "FreeRigidBody.contact_point": _Frame,
        "FreeRigidBody.contact_polhode": _Samples,
        "FreeRigidBody.polhode": _Samples,
        "axis_stability": _Spin,
        "HeavyTop.__init__": _HeavyTop,
        "HeavyTop.from_spin": _FromSpin,
        "HeavyTop.from_body": _FromBody,
        "sweep.simulate": _Batch,
        "sweep.drop": _SweepFall,
        "sweep.projectile": _SweepFall,
    },
)

DEFAULTS: _Defaults

def memory_budget() -> int: ...
def set_memory_budget(bytes: int) -> int: ...
def _test_panic(message: str, place: str = ...) -> None: ...
def error_classes() -> list[tuple[str, str]]: ...

# ---- errors (errors.rs) ----
class PoinsotError(ValueError): ...
class InvalidInertiaError(PoinsotError): ...
class InvalidRotationError(PoinsotError): ...
class InvalidMeshError(PoinsotError): ...
class GimbalLockError(PoinsotError): ...
class IntegrationError(PoinsotError): ...
class InternalError(PoinsotError): ...

# ---- rotation (rotation.rs) ----
# Batches are C-contiguous float64 arrays (N, ...); python/poinsot/rotation.py prepares them.
# Quaternions are scalar-first [w, x, y, z]; matrices row-major (N, 3, 3); angles in rad.
ROTATION_MATRIX_TOL: float
NEAREST_ROTATION_DEFECT: float
EULER_LOCK_TOL: float
RATES_LOCK_TOL: float

def euler_to_matrix(
    angles: NDArray[np.float64], seq: str, intrinsic: bool
) -> NDArray[np.float64]: ...
def matrix_to_euler(
    R: NDArray[np.float64], seq: str, intrinsic: bool
) -> tuple[NDArray[np.float64], NDArray[np.bool_]]: ...
def matrix_to_quaternion(R: NDArray[np.float64]) -> NDArray[np.float64]: ...
def quaternion_to_matrix(q: NDArray[np.float64], normalize: bool) -> NDArray[np.float64]: ...
def quaternion_multiply(p: NDArray[np.float64], q: NDArray[np.float64]) -> NDArray[np.float64]: ...
def rotation_axis(R: NDArray[np.float64]) -> NDArray[np.float64]: ...
def axis_angle_to_matrix(
    axis: NDArray[np.float64], angle: NDArray[np.float64]
) -> NDArray[np.float64]: ...
def rotate_vectors(R: NDArray[np.float64], v: NDArray[np.float64]) -> NDArray[np.float64]: ...
def check_rotation_matrix(R: NDArray[np.float64], tol: float) -> None: ...
def angular_velocity(
    angles: NDArray[np.float64], rates: NDArray[np.float64], seq: str, intrinsic: bool, frame: str
) -> NDArray[np.float64]: ...
def euler_rates(
    angles: NDArray[np.float64], omega: NDArray[np.float64], seq: str, intrinsic: bool, frame: str
) -> NDArray[np.float64]: ...
def screw_axis(
    R: NDArray[np.float64], t: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.float64], float, float, float]: ...

# A screw as the core's functions take it: (axis (3,), point (3,), angle, slide).
_ScrewParts: TypeAlias = tuple[NDArray[np.float64], NDArray[np.float64], float, float]

def screw_new(
    screw: _ScrewParts, pitch: float | None = None
) -> tuple[NDArray[np.float64], NDArray[np.float64], float, float, float]: ...
def screw_displacement(
    screw: _ScrewParts, s: float | None = None
) -> tuple[NDArray[np.float64], NDArray[np.float64]]: ...
def screw_apply(screw: _ScrewParts, x: NDArray[np.float64]) -> NDArray[np.float64]: ...

# ---- inertia (inertia.rs) ----

@final
class MassProperties:
    @staticmethod
    def from_inertia(
        mass: float, center_of_mass: NDArray[np.float64], inertia: NDArray[np.float64]
    ) -> MassProperties: ...
    @staticmethod
    def from_inertia_about(
        mass: float,
        center_of_mass: NDArray[np.float64],
        inertia: NDArray[np.float64],
        about: NDArray[np.float64],
    ) -> MassProperties: ...
    @staticmethod
    def from_point_masses(
        masses: NDArray[np.float64], positions: NDArray[np.float64]
    ) -> MassProperties: ...
    @staticmethod
    def solid_sphere(mass: float, radius: float) -> MassProperties: ...
    @staticmethod
    def spherical_shell(mass: float, radius: float) -> MassProperties: ...
    @staticmethod
    def solid_cylinder(mass: float, radius: float, height: float) -> MassProperties: ...
    @staticmethod
    def solid_cone(mass: float, radius: float, height: float) -> MassProperties: ...
    @staticmethod
    def cuboid(mass: float, sides: NDArray[np.float64]) -> MassProperties: ...
    @staticmethod
    def cuboid_sides(mass: float, moments: NDArray[np.float64]) -> NDArray[np.float64]: ...
    @staticmethod
    def ellipsoid(mass: float, semi_axes: NDArray[np.float64]) -> MassProperties: ...
    @staticmethod
    def thin_rod(mass: float, length: float) -> MassProperties: ...
    @staticmethod
    def thin_disk(mass: float, radius: float) -> MassProperties: ...
    @staticmethod
    def thin_ring(mass: float, radius: float) -> MassProperties: ...
    @staticmethod
    def from_mesh(
        vertices: NDArray[np.float64],
        faces: NDArray[np.int64],
        density: float,
        merge: bool = False,
    ) -> MassProperties: ...
    @staticmethod
    def from_density(
        density: Callable[[NDArray[np.float64]], Any],
        bounds: NDArray[np.float64],
        options: tuple[float, float, int],  # rtol, atol, max_evals
    ) -> tuple[MassProperties, float, float, float, int, bool]: ...
    @staticmethod
    def combine(bodies: Sequence[MassProperties]) -> MassProperties: ...
    @property
    def mass(self) -> float: ...
    @property
    def center_of_mass(self) -> NDArray[np.float64]: ...
    @property
    def inertia(self) -> NDArray[np.float64]: ...
    def inertia_about(self, points: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def translated(self, offset: NDArray[np.float64]) -> MassProperties: ...
    def rotated(self, rotation: NDArray[np.float64]) -> MassProperties: ...
    def principal(self, rtol: float) -> tuple[NDArray[np.float64], NDArray[np.float64]]: ...
    def kind(self, rtol: float) -> str: ...
    def heavy_top_parameters(
        self, pivot_distance: float, g: float
    ) -> tuple[float, float, float]: ...
    def angular_momentum(
        self, omega: NDArray[np.float64], about: NDArray[np.float64] | None = None
    ) -> NDArray[np.float64]: ...
    def kinetic_energy(
        self, omega: NDArray[np.float64], about: NDArray[np.float64] | None = None
    ) -> NDArray[np.float64]: ...
    def holding_torque(
        self, omega: NDArray[np.float64], about: NDArray[np.float64] | None = None
    ) -> NDArray[np.float64]: ...
    def momentum_angle(
        self, omega: NDArray[np.float64], about: NDArray[np.float64] | None = None
    ) -> NDArray[np.float64]: ...

def classify(moments: NDArray[np.float64], rtol: float) -> str: ...
def check_inertia(inertia: NDArray[np.float64]) -> NDArray[np.float64]: ...
def check_mesh_file(triangles: float) -> None: ...

# ---- frames (frames.rs) ----
# A frame travels packed, as MovingFrame._packed: (24,) = origin, velocity, acceleration, omega,
# omega_dot (3 each), then the attitude (3, 3) row-major.

def frame_to_fixed(
    frame: NDArray[np.float64],
    position: NDArray[np.float64],
    velocity: NDArray[np.float64],
    acceleration: NDArray[np.float64],
) -> list[NDArray[np.float64]]: ...
def frame_to_moving(
    frame: NDArray[np.float64],
    position: NDArray[np.float64],
    velocity: NDArray[np.float64],
    acceleration: NDArray[np.float64],
) -> list[NDArray[np.float64]]: ...
def frame_fictitious_forces(
    frame: NDArray[np.float64],
    mass: NDArray[np.float64],
    position: NDArray[np.float64],
    velocity: NDArray[np.float64],
) -> list[NDArray[np.float64]]: ...
def frame_simulate_particle(
    frame: NDArray[np.float64],
    frame_fn: Callable[[float], Any] | None,
    mass: float,
    position: NDArray[np.float64],
    velocity: NDArray[np.float64],
    duration: float,
    samples: int,
    t_eval: NDArray[np.float64] | None,
    force: NDArray[np.float64],
    force_fn: Callable[..., tuple[float, float, float]] | None,
    rtol: float,
    atol: float,
    max_steps: int,
    stiffness: float = 0.0,
) -> tuple[NDArray[np.float64], int]: ...

@final
class SpringParticleCore:
    def __new__(cls, mass: float, stiffness: float) -> SpringParticleCore: ...
    @property
    def mass(self) -> float: ...
    @property
    def stiffness(self) -> float: ...
    def force(self, position: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def acceleration(self, position: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def potential(self, position: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def energy(
        self, position: NDArray[np.float64], velocity: NDArray[np.float64]
    ) -> NDArray[np.float64]: ...
    def jacobi_integral(
        self,
        frame: NDArray[np.float64],
        position: NDArray[np.float64],
        velocity: NDArray[np.float64],
    ) -> NDArray[np.float64]: ...

def frame_steady_at(
    frame: NDArray[np.float64],
    t: float,
) -> tuple[list[NDArray[np.float64]], NDArray[np.float64]]: ...

# ---- earth (earth.rs) ----
# The core's Earth and its runs; python/poinsot/earth.py checks the arguments' types and wraps the
# results in its public dataclasses. Latitudes in rad, arrays C-contiguous float64 (N,) or (N, 3).

@final
class EarthCore:
    def __new__(cls, rotation_rate: float, radius: float, g: float) -> EarthCore: ...
    def __reduce__(self) -> tuple[type[EarthCore], tuple[float, float, float]]: ...
    @property
    def rotation_rate(self) -> float: ...
    @property
    def radius(self) -> float: ...
    @property
    def g(self) -> float: ...
    def omega_enu(self, latitude: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def effective_gravity(
        self, latitude: NDArray[np.float64]
    ) -> tuple[
        NDArray[np.float64], NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]
    ]: ...
    def coriolis_acceleration(
        self, latitude: NDArray[np.float64], velocity_enu: NDArray[np.float64]
    ) -> NDArray[np.float64]: ...
    def coriolis_parameter(self, latitude: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def foucault_rate(self, latitude: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def inertial_period(self, latitude: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def centrifugal_magnitude(self, latitude: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def plumb_line_deviation_closed(self, latitude: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def fall_time(self, height: float) -> float: ...
    def eastward_deflection(
        self, height: NDArray[np.float64], latitude: NDArray[np.float64]
    ) -> NDArray[np.float64]: ...
    def southward_deflection(
        self, height: NDArray[np.float64], latitude: NDArray[np.float64]
    ) -> NDArray[np.float64]: ...
    def jacobi_integral(
        self, latitude: float, position: NDArray[np.float64], velocity: NDArray[np.float64]
    ) -> NDArray[np.float64]: ...
    def drop(self, height: float, latitude: float, model: FallModel, samples: int) -> FallCore: ...
    def projectile(
        self,
        speed: float,
        elevation: float,
        azimuth: float,
        latitude: float,
        height: float,
        model: FallModel,
        samples: int,
    ) -> FlightCore: ...
    def foucault_swing(
        self,
        latitude: float,
        length: float,
        amplitude: float,
        azimuth: float,
        duration: float,
        settings: _RunSettings,
        progress: _Progress = None,
    ) -> FoucaultRunCore: ...
    def inertial_swing(
        self,
        latitude: float,
        velocity: NDArray[np.float64],
        duration: float | None,
        settings: _RunSettings,
    ) -> InertialRunCore: ...
    def low_flow(
        self,
        latitude: float,
        radius: float,
        parcels: int,
        pull: float,
        friction: float,
        duration: float,
        settings: _RunSettings,
    ) -> LowFlowCore: ...

@final
class FallModel:
    def __new__(
        cls,
        gravity: str,
        rotation: bool,
        centrifugal: bool,
        rtol: float,
        atol: float,
        max_steps: int,
    ) -> FallModel: ...
    def __reduce__(
        self,
    ) -> tuple[type[FallModel], tuple[str, bool, bool, float, float, int]]: ...
    @property
    def gravity(self) -> str: ...
    @property
    def rotation(self) -> bool: ...
    @property
    def centrifugal(self) -> bool: ...
    @property
    def rtol(self) -> float: ...
    @property
    def atol(self) -> float: ...
    @property
    def max_steps(self) -> int: ...

@final
class FallCore:
    @property
    def time(self) -> float: ...
    @property
    def east(self) -> float: ...
    @property
    def north(self) -> float: ...
    @property
    def first_order_east(self) -> float: ...
    @property
    def second_order_south(self) -> float: ...
    @property
    def t(self) -> NDArray[np.float64]: ...
    @property
    def position(self) -> NDArray[np.float64]: ...
    @property
    def velocity(self) -> NDArray[np.float64]: ...

@final
class FlightCore:
    @property
    def time(self) -> float: ...
    @property
    def east(self) -> float: ...
    @property
    def north(self) -> float: ...
    @property
    def range(self) -> float: ...
    @property
    def downrange(self) -> float: ...
    @property
    def drift(self) -> float: ...
    @property
    def t(self) -> NDArray[np.float64]: ...
    @property
    def position(self) -> NDArray[np.float64]: ...
    @property
    def velocity(self) -> NDArray[np.float64]: ...

@final
class FoucaultRunCore:
    @property
    def t(self) -> NDArray[np.float64]: ...
    @property
    def position(self) -> NDArray[np.float64]: ...
    @property
    def velocity(self) -> NDArray[np.float64]: ...
    @property
    def turn_times(self) -> NDArray[np.float64]: ...
    @property
    def turn_angles(self) -> NDArray[np.float64]: ...
    @property
    def precession_rate(self) -> float | None: ...
    @property
    def full_turn_period(self) -> float | None: ...
    @property
    def expected_rate(self) -> float: ...
    @property
    def expected_full_turn_period(self) -> float: ...
    @property
    def sense(self) -> str: ...
    @property
    def regime(self) -> str: ...
    @property
    def regime_note(self) -> str: ...
    @property
    def theory_rate(self) -> float | None: ...
    @property
    def unit_rate_holds(self) -> bool: ...
    @property
    def unit_rate_note(self) -> str: ...
    @property
    def spin_ratio(self) -> float: ...
    @property
    def amplitude_ratio(self) -> float: ...
    @property
    def spin_departure(self) -> float | None: ...
    @property
    def amplitude_departure(self) -> float | None: ...

@final
class InertialRunCore:
    @property
    def t(self) -> NDArray[np.float64]: ...
    @property
    def position(self) -> NDArray[np.float64]: ...
    @property
    def velocity(self) -> NDArray[np.float64]: ...
    @property
    def turning_rate(self) -> float: ...
    @property
    def measured_period(self) -> float: ...
    @property
    def period(self) -> float: ...
    @property
    def sense(self) -> str: ...

@final
class LowFlowCore:
    @property
    def t(self) -> NDArray[np.float64]: ...
    @property
    def position(self) -> NDArray[np.float64]: ...
    @property
    def velocity(self) -> NDArray[np.float64]: ...
    @property
    def circulation(self) -> float: ...
    @property
    def sense(self) -> str: ...
    @property
    def energy(self) -> NDArray[np.float64]: ...
    @property
    def dissipated(self) -> NDArray[np.float64]: ...

def sample_times(t0: float, t_end: float, samples: int) -> NDArray[np.float64]: ...

SIDEREAL_RATE: float
SOLAR_DAY_RATE: float
MEAN_RADIUS: float
STANDARD_GRAVITY: float

# ---- the rigid Earth (rigid_earth.rs) ----
# A checked core RigidEarth; poinsot.RigidEarth (rigid_earth.py) holds one. SI units, radians.

@final
class RigidEarthCore:
    def __new__(
        cls, dynamical_flattening: float, rotation_rate: float, obliquity: float
    ) -> RigidEarthCore: ...
    def __reduce__(self) -> tuple[type[RigidEarthCore], tuple[float, float, float]]: ...
    @property
    def dynamical_flattening(self) -> float: ...
    @property
    def rotation_rate(self) -> float: ...
    @property
    def obliquity(self) -> float: ...
    @property
    def euler_rate(self) -> float: ...
    @property
    def euler_period(self) -> float: ...
    @property
    def precession_rate(self) -> float: ...
    @property
    def precession_parts(self) -> tuple[float, float]: ...
    @property
    def precession_period(self) -> float: ...
    @property
    def nutation_amplitudes(self) -> tuple[float, float]: ...
    @property
    def nutation_amplitudes_by_precession(self) -> tuple[float, float]: ...
    def chandler_period(self, k2: float, ks: float) -> float: ...
    def simulate(
        self, duration: float, samples: int, moon_node: float, mean_pole: bool, max_steps: int
    ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64], float, float]: ...
    def averaged_pole(
        self, t: NDArray[np.float64], moon_node: float, nutation_scale: float
    ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]: ...

def fit_pole(
    t: NDArray[np.float64],
    longitude: NDArray[np.float64],
    obliquity: NDArray[np.float64],
    moon_node: float,
    node_rate: float,
) -> tuple[float, float, float, float, float]: ...

DYNAMICAL_FLATTENING: float
OBLIQUITY_J2000: float
IAU2006_PRECESSION_RATE: float
IAU2000A_PRINCIPAL_NUTATION: tuple[float, float]

# ---- special (special.rs) ----
def special_jacobi(u: NDArray[np.float64], m: float) -> NDArray[np.float64]: ...
def special_elliptic(kind: str, phi: float, n: float, m: float) -> float: ...

# ---- analytic (analytic.rs) ----
# ω in body components, L in space components, quaternions [w, x, y, z] body → space.
@final
class SymmetricTopSolution:
    def __new__(
        cls,
        i1: float,
        i3: float,
        omega0: object,
        attitude0: NDArray[np.float64] | None = None,
    ) -> SymmetricTopSolution: ...
    @property
    def omega0(self) -> NDArray[np.float64]: ...
    @property
    def precession_rate(self) -> float: ...
    @property
    def amplitude(self) -> float: ...
    @property
    def phase(self) -> float: ...
    @property
    def omega3(self) -> float: ...
    @property
    def omega_magnitude(self) -> float: ...
    @property
    def energy(self) -> float: ...
    @property
    def angular_momentum_magnitude(self) -> float: ...
    @property
    def angular_momentum(self) -> NDArray[np.float64]: ...
    @property
    def precession_period(self) -> float: ...
    @property
    def body_cone_angle(self) -> float: ...
    @property
    def space_cone_angle(self) -> float: ...
    @property
    def nutation_angle(self) -> float: ...
    @property
    def space_precession_rate(self) -> float: ...
    @property
    def max_time(self) -> float: ...
    @property
    def shape(self) -> str: ...
    def omega(self, t: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def attitude(self, t: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def symmetry_axis(self, t: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def omega_at(self, t: float) -> NDArray[np.float64]: ...
    def attitude_at(self, t: float) -> NDArray[np.float64]: ...
    def symmetry_axis_at(self, t: float) -> NDArray[np.float64]: ...
    @staticmethod
    def omega3_squared_from(i1: float, i3: float, energy: float, l: float) -> float: ...
    @staticmethod
    def amplitude_squared_from(i1: float, i3: float, energy: float, l: float) -> float: ...

@final
class FreeBodySolution:
    def __new__(
        cls,
        moments: object,
        omega0: object,
        attitude0: NDArray[np.float64] | None = None,
    ) -> FreeBodySolution: ...
    @property
    def moments(self) -> NDArray[np.float64]: ...
    @property
    def omega0(self) -> NDArray[np.float64]: ...
    @property
    def energy(self) -> float: ...
    @property
    def angular_momentum(self) -> NDArray[np.float64]: ...
    @property
    def angular_momentum_magnitude(self) -> float: ...
    @property
    def regime(self) -> str: ...
    @property
    def parameter(self) -> float: ...
    @property
    def frequency(self) -> float: ...
    @property
    def period(self) -> float: ...
    @property
    def flip_interval(self) -> float: ...
    @property
    def pole_axis(self) -> int | None: ...
    @property
    def steady_rate(self) -> float | None: ...
    @property
    def flips_about(self) -> int | None: ...
    @property
    def invariable_plane_distance(self) -> float: ...
    @property
    def max_time(self) -> float: ...
    def state(self, t: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]: ...
    def state_at(self, t: float) -> tuple[NDArray[np.float64], NDArray[np.float64]]: ...
    def omega_space(self, t: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def angular_momentum_body(self, t: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def polhode(self, samples: int) -> NDArray[np.float64]: ...
    @property
    def invariable_plane_normal(self) -> NDArray[np.float64]: ...
    def contact_point(self, t: NDArray[np.float64], body: bool) -> NDArray[np.float64]: ...
    def contact_polhode(self, samples: int) -> NDArray[np.float64]: ...
    def axis_stability(self) -> list[tuple[str, float]]: ...

def axis_stability(moments: NDArray[np.float64], spin: float) -> list[tuple[str, float]]: ...

# The states of N free bodies at M times (flat t: M shared values, or N·M with per_body)
# -> (omega (N, M, 3), attitude (N, M, 4)).
def free_body_states(
    bodies: _Bodies,
    t: NDArray[np.float64],
    per_body: bool,
    progress: _Progress,
) -> tuple[NDArray[np.float64], NDArray[np.float64]]: ...

# ---- dynamics (dynamics.rs) ----
# torque_kind: "none", "body", "space", "gravity", "gravity_gradient" or "callback"
# (torque_fn(t, omega (3,), attitude (4,)) -> 3 floats, body components).
@final
class TrajectoryCore:
    @property
    def t(self) -> NDArray[np.float64]: ...
    @property
    def omega(self) -> NDArray[np.float64]: ...
    @property
    def attitude(self) -> NDArray[np.float64]: ...
    @property
    def angular_momentum(self) -> NDArray[np.float64]: ...
    @property
    def energy(self) -> NDArray[np.float64]: ...
    @property
    def potential(self) -> NDArray[np.float64]: ...
    @property
    def power(self) -> NDArray[np.float64]: ...
    @property
    def method(self) -> str: ...
    @property
    def step(self) -> float | None: ...
    @property
    def steps(self) -> int: ...
    @property
    def torque_evaluations(self) -> int: ...

def dynamics_simulate(
    start: _Start,
    duration: float,
    torque: _TorqueSpec,
    torque_fn: Callable[[float, NDArray[np.float64], NDArray[np.float64]], Any] | None,
    method: str,
    dt: float | None,
    settings: _RunSettings,
    progress: _Progress,
) -> TrajectoryCore: ...

# A batch's settings, as dynamics._batch_settings makes them: duration (s), the torque's
# (kind, vector, scalar), the method, dt (s or None) and max_steps.
_BatchSettings: TypeAlias = tuple[float, _TorqueSpec, str, float | None, int]

def dynamics_simulate_batch(
    bodies: _Bodies,
    settings: _BatchSettings,
    progress: _Progress,
) -> tuple[NDArray[np.float64], NDArray[np.float64], int]: ...

# ---- carried bodies and the gyrocompass (gyrocompass.rs) ----
# python/poinsot/gyrocompass.py prepares the arguments; angles in rad, SI units.

_GyroArgs: TypeAlias = tuple[float, float, float, float, tuple[float, float, float], EarthCore]

@final
class GyrocompassCore:
    def __new__(
        cls,
        latitude: float,
        angular_momentum: float | None,
        pendulosity: float,
        damping: float,
        inertia: tuple[float, float, float],
        earth: EarthCore,
    ) -> GyrocompassCore: ...
    @staticmethod
    def schuler_period(earth: EarthCore) -> float: ...
    def __reduce__(self) -> tuple[type[GyrocompassCore], _GyroArgs]: ...
    @property
    def args(self) -> _GyroArgs: ...
    @property
    def period(self) -> float: ...
    @property
    def natural_frequency(self) -> float: ...
    @property
    def damping_coefficient(self) -> float: ...
    @property
    def viscous_coefficient(self) -> float: ...
    @property
    def ground_speed(self) -> float: ...
    @property
    def settle(self) -> tuple[float, float]: ...
    def speed_error(self, speed: float, course: float) -> float: ...
    def speed_error_small_angle(self, speed: float, course: float) -> float: ...
    def simulate(
        self,
        duration: float,
        heading0: float,
        tilt0: float,
        speed: float,
        course: float,
        turns: list[tuple[float, float | None, float, float]],
        method: str,
        settings: _RunSettings,
        progress: _Progress,
    ) -> tuple[
        NDArray[np.float64], NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]
    ]: ...
    def linear_solution(
        self, t: NDArray[np.float64], heading0: float, tilt0: float, speed: float, course: float
    ) -> tuple[
        NDArray[np.float64], NDArray[np.float64], NDArray[np.float64], tuple[float, float]
    ]: ...

def dynamics_check_place(earth: EarthCore, latitude: float) -> None: ...
def dynamics_simulate_carried(
    start: _Start,
    duration: float,
    kind: str,
    frame: NDArray[np.float64],
    pivot: NDArray[np.float64],
    gravity: NDArray[np.float64],
    earth: EarthCore | None,
    latitude: float,
    mass_moment: NDArray[np.float64],
    torque: _TorqueSpec,
    method: str,
    settings: _RunSettings,
    progress: _Progress,
) -> tuple[TrajectoryCore, NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]: ...

# ---- heavy top (heavy_top.rs) ----
# Angles in rad, rates in rad/s, times in s; arrays C-contiguous float64 (N,); python/poinsot/top.py
# prepares them and wraps HeavyTopCore in the public poinsot.HeavyTop. A top travels as one
# (I1, I3, mgl) tuple (kg m^2, kg m^2, J), as top._parameters makes it.

_Top: TypeAlias = tuple[float, float, float]
_Six: TypeAlias = tuple[float, float, float, float, float, float]
_Four: TypeAlias = tuple[float, float, float, float]

@final
class HeavyTopCore:
    @staticmethod
    def from_state(top: _Top, state: _Six) -> HeavyTopCore: ...
    @staticmethod
    def from_spin(top: _Top, state: _Six) -> HeavyTopCore: ...
    @staticmethod
    def from_constants(top: _Top, constants: tuple[float, float, float]) -> HeavyTopCore: ...
    @property
    def parameters(self) -> tuple[float, float, float]: ...
    @property
    def p_phi(self) -> float: ...
    @property
    def p_psi(self) -> float: ...
    @property
    def omega3(self) -> float: ...
    @property
    def energy(self) -> float: ...
    @property
    def reduced_energy(self) -> float: ...
    @property
    def initial_state(self) -> tuple[float, float, float, float, float, float]: ...
    @property
    def turning_points(self) -> tuple[float, float]: ...
    @property
    def cubic_roots(self) -> tuple[float, float, float]: ...
    @property
    def motion_class(self) -> str: ...
    @property
    def vertical_pass(self) -> str | None: ...
    @property
    def is_sleeping_stable(self) -> bool: ...
    @property
    def nutation_period(self) -> float | None: ...
    @property
    def mean_precession_rate(self) -> float: ...
    @property
    def precession_period(self) -> float | None: ...
    @property
    def mean_spin_rate(self) -> float: ...
    @property
    def fourier_terms(self) -> int: ...
    def effective_potential(self, theta: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def effective_potential_derivative(self, theta: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def euler_angles(self, t: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def euler_rates(self, t: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def euler_angles_carlson(self, t: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def euler_angles_at(self, t: float) -> tuple[float, float, float]: ...
    def euler_rates_at(self, t: float) -> tuple[float, float, float]: ...

def heavy_top_steady_precession(top: _Top, theta0: float, omega3: float) -> dict[str, float]: ...
def heavy_top_min_spin(top: _Top, theta0: float) -> float: ...
def heavy_top_sleeping_threshold(top: _Top) -> float: ...

# One state: (theta, theta_dot, phi_dot, psi_dot).
def heavy_top_lagrangian(top: _Top, state: _Four) -> float: ...
def heavy_top_constants_of_state(top: _Top, state: _Four) -> tuple[float, float, float]: ...

# ---- sweeps (sweep.rs) ----
# dims: [(name, length, offset)]; columns: [(keyword, C-contiguous float64 values, dim or None)];
# results: flat arrays, one entry a point in row-major order; categories as uint8 codes into
# sweep_categories(). python/poinsot/sweep/ prepares the grid and labels the results.
SWEEP_HEAVY_TOP_KEYWORDS: list[str]
SWEEP_FREE_BODY_KEYWORDS: list[str]
SWEEP_SIMULATE_KEYWORDS: list[str]
SWEEP_DROP_KEYWORDS: list[str]
SWEEP_PROJECTILE_KEYWORDS: list[str]

# A sweep's grid (dims, columns) and its results (None when check_only).
_Dims: TypeAlias = Sequence[tuple[str, int, int, str]]
_Columns: TypeAlias = Sequence[tuple[str, NDArray[np.float64], int | None]]
_Swept: TypeAlias = dict[str, NDArray[Any]] | None

def sweep_categories() -> dict[str, list[str]]: ...
def sweep_check_memory(dims: _Dims, bytes_each: int) -> None: ...
def sweep_heavy_top(
    dims: _Dims, columns: _Columns, check_only: bool, progress: _Progress = None
) -> _Swept: ...
def sweep_free_body(
    dims: _Dims, columns: _Columns, check_only: bool, progress: _Progress = None
) -> _Swept: ...
def sweep_simulate(
    dims: _Dims,
    columns: _Columns,
    settings: _BatchSettings,
    check_only: bool,
    progress: _Progress = None,
) -> _Swept: ...
def sweep_drop(
    dims: _Dims,
    columns: _Columns,
    earth: EarthCore,
    model: FallModel,
    check_only: bool,
    progress: _Progress = None,
) -> _Swept: ...
def sweep_projectile(
    dims: _Dims,
    columns: _Columns,
    earth: EarthCore,
    model: FallModel,
    check_only: bool,
    progress: _Progress = None,
) -> _Swept: ...

# ---- the real pole's wobble (wobble.rs) ----
ANNUAL_PERIOD: float
CHANDLER_SEARCH: tuple[float, float]

class _WobbleTerm(TypedDict):
    period: float
    period_sigma: float
    amplitude: float
    amplitude_sigma: float
    phase: float
    phase_sigma: float
    prograde: bool

class _WobbleFit(TypedDict):
    chandler: _WobbleTerm
    annual_prograde: _WobbleTerm
    annual_retrograde: _WobbleTerm
    offset: tuple[float, float]
    offset_sigma: tuple[float, float]
    drift: tuple[float, float]
    drift_sigma: tuple[float, float]
    residual_rms: float
    serial_correlation: float
    sigma_inflation: float
    chandler_false_alarm: float
    chandler_significant: bool
    samples: int

def fit_wobble(
    t: NDArray[np.float64],
    x: NDArray[np.float64],
    y: NDArray[np.float64],
    chandler_period: float | None = None,
    chandler_band: tuple[float, float] | None = None,
    annual_period: float = ...,
) -> _WobbleFit: ...
