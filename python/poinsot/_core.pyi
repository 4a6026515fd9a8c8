# Stubs of the compiled module poinsot._core (checked with `python -m mypy.stubtest`).
# Sections mirror the binding files in crates/poinsot-py/src/.
import numpy as np
from numpy.typing import NDArray

__version__: str

# ---- errors (errors.rs) ----
class PoinsotError(ValueError): ...
class InvalidInertiaError(PoinsotError): ...
class InvalidRotationError(PoinsotError): ...
class InvalidMeshError(PoinsotError): ...
class GimbalLockError(PoinsotError): ...
class IntegrationError(PoinsotError): ...

# ---- rotation (rotation.rs) ----

# ---- inertia (inertia.rs) ----

# ---- frames (frames.rs) ----
from collections.abc import Callable
from typing import Any

def frame_to_fixed(
    frame: NDArray[np.float64], attitude: NDArray[np.float64], position: NDArray[np.float64],
    velocity: NDArray[np.float64], acceleration: NDArray[np.float64],
) -> list[NDArray[np.float64]]: ...
def frame_to_moving(
    frame: NDArray[np.float64], attitude: NDArray[np.float64], position: NDArray[np.float64],
    velocity: NDArray[np.float64], acceleration: NDArray[np.float64],
) -> list[NDArray[np.float64]]: ...
def frame_fictitious_forces(
    frame: NDArray[np.float64], attitude: NDArray[np.float64], mass: NDArray[np.float64],
    position: NDArray[np.float64], velocity: NDArray[np.float64],
) -> list[NDArray[np.float64]]: ...
def frame_simulate_particle(
    frame: NDArray[np.float64], frame_fn: Callable[[float], Any] | None, mass: float,
    position: NDArray[np.float64], velocity: NDArray[np.float64], t0: float, t_end: float,
    samples: int, times: NDArray[np.float64] | None, force: NDArray[np.float64],
    force_fn: Callable[..., tuple[float, float, float]] | None, rtol: float, atol: float,
    max_steps: int,
) -> tuple[NDArray[np.float64], int]: ...
def frame_steady_at(
    frame: NDArray[np.float64], attitude: NDArray[np.float64], t: float,
) -> tuple[list[NDArray[np.float64]], NDArray[np.float64]]: ...

# ---- earth (earth.rs) ----
def earth_omega_enu(rotation_rate: float, radius: float, g: float, latitude: NDArray[np.float64]) -> NDArray[np.float64]: ...
def earth_effective_gravity(
    rotation_rate: float, radius: float, g: float, latitude: NDArray[np.float64],
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]: ...
def earth_coriolis_acceleration(
    rotation_rate: float, radius: float, g: float, latitude: NDArray[np.float64], velocity: NDArray[np.float64],
) -> NDArray[np.float64]: ...
def earth_latitude_scalar(
    rotation_rate: float, radius: float, g: float, quantity: str, latitude: NDArray[np.float64],
) -> NDArray[np.float64]: ...
def earth_deflection(
    rotation_rate: float, radius: float, g: float, direction: str, height: NDArray[np.float64],
    latitude: NDArray[np.float64],
) -> NDArray[np.float64]: ...
def earth_drop(
    rotation_rate: float, radius: float, g: float, height: float, latitude: float, gravity: str,
    rotation: bool, centrifugal: bool, rtol: float, atol: float, max_steps: int, samples: int,
) -> dict[str, Any]: ...
def earth_projectile(
    rotation_rate: float, radius: float, g: float, speed: float, elevation: float, azimuth: float,
    latitude: float, height: float, gravity: str, rotation: bool, centrifugal: bool, rtol: float,
    atol: float, max_steps: int, samples: int,
) -> dict[str, Any]: ...
def earth_foucault_release(length: float, amplitude: float, azimuth: float) -> NDArray[np.float64]: ...
def earth_foucault(
    rotation_rate: float, radius: float, g: float, latitude: float, length: float,
    state0: NDArray[np.float64], t0: float, t_end: float, times: NDArray[np.float64], rtol: float,
    atol: float, max_steps: int,
) -> dict[str, Any]: ...
def earth_fit_precession_rate(turn_times: NDArray[np.float64], turn_angles: NDArray[np.float64]) -> float: ...
def earth_inertial_oscillation(
    rotation_rate: float, radius: float, g: float, latitude: float, velocity: NDArray[np.float64],
    t_end: float, times: NDArray[np.float64], rtol: float, atol: float, max_steps: int,
) -> dict[str, Any]: ...
def earth_flow_into_low(
    rotation_rate: float, radius: float, g: float, latitude: float, starts: NDArray[np.float64],
    strength: float, friction: float, t_end: float, times: NDArray[np.float64], rtol: float,
    atol: float, max_steps: int,
) -> dict[str, Any]: ...
