"""Notebook widgets: the browser lab's scenes in a Jupyter cell (JupyterLab, Notebook 7, VS Code).

Each widget is an `anywidget <https://anywidget.dev>`_ whose front end
(``static/widget.js``, built from ``web/src/widget.ts`` by ``web/build.sh``) runs the lab's
scene on the same WebAssembly core as the lab; no physics runs in JavaScript or in this module.
The scene's parameters are the synced trait ``params`` (a dict, in the units of the scene's
sliders): moving a slider changes ``w.params`` in Python, assigning ``w.params`` (or a property
below) moves the scene and its sliders. Angles in ``params`` are in degrees, as on every slider of
the lab (its one angle unit: ``tilt``, ``launchAngle``); rates are in rad/s. The objects the
properties build (``w.top``, ``w.body``) are the Python API's, in SI units (radians): the
conversion happens once, here, as in the lab where a scene calls the core. The keys of an earlier
version, ``theta0`` and ``direction`` in radians, are still accepted and converted to degrees.

- :class:`HeavyTopWidget` — the heavy symmetric top (the unit's 2.102–2.121); ``w.top`` is a
  :class:`poinsot.HeavyTop`.
- :class:`PoinsotWidget` — Poinsot's construction and the tumbling box (2.87–2.97); ``w.body``
  is a :class:`poinsot.FreeRigidBody` (a uniform 1 kg box, as the scene).
- :class:`FramesWidget` — a particle seen from the fixed and from the rotating frame (2.20–2.28).

Needs the ``notebook`` extra: ``pip install 'poinsot[notebook]'``.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

try:
    import anywidget
    import traitlets
except ImportError as exc:  # pragma: no cover - exercised by test_widgets with anywidget hidden
    raise ImportError(
        f"poinsot.widgets needs anywidget ({exc}): pip install 'poinsot[notebook]'"
    ) from exc

from ..body import RigidBody
from ..errors import PoinsotError
from ..free import FreeRigidBody
from ..top import HeavyTop

__all__ = ["FramesWidget", "HeavyTopWidget", "PoinsotWidget", "SCENE_PARAMS", "STATIC"]

#: Where the built front end lives (``widget.js``, ``widget.css``).
STATIC = Path(__file__).with_name("static")
_ESM = STATIC / "widget.js"
_CSS = STATIC / "widget.css"
_NOT_BUILT = (
    "export default { render({ el }) { el.textContent = 'poinsot.widgets: the front end is not "
    "built (bash web/build.sh builds python/poinsot/widgets/static/widget.js)'; } };"
)


@dataclass(frozen=True)
class Slider:
    """A numeric parameter of a scene: its slider's range and step, its default (the lab's)."""

    min: float
    max: float
    step: float
    value: float
    unit: str


@dataclass(frozen=True)
class Choice:
    """A choice parameter of a scene: its options and default."""

    options: tuple[str, ...]
    value: str


#: The lab's parameters of the scenes the widgets show, and their presets: the one data file
#: that the lab's scenes (``web/src/scenes/params.ts``) import too.
SCENES_JSON = Path(__file__).with_name("scenes.json")
_SCENES: dict[str, Any] = json.loads(SCENES_JSON.read_text(encoding="utf-8"))


def _param(spec: dict[str, Any]) -> Slider | Choice:
    """A scene parameter of scenes.json (a slider's or a select's declaration in the lab)."""
    if spec["kind"] == "choice":
        return Choice(tuple(spec["options"]), spec["value"])
    return Slider(spec["min"], spec["max"], spec["step"], spec["value"], spec["unit"])


#: The parameters of the scenes the widgets show, as the lab's scenes declare them (read from
#: ``scenes.json``; the browser test checks that the sliders the widget draws have these ranges).
SCENE_PARAMS: dict[str, dict[str, Slider | Choice]] = {
    scene: {spec["key"]: _param(spec) for spec in _SCENES[scene]["params"]}
    for scene in ("heavytop", "poinsot", "frames")
}

#: The mass of the Poinsot scene's box (kg), the lab's.
BOX_MASS: float = _SCENES["poinsot"]["boxMass"]
#: The heavy top's presets released at a fraction of the core's slow steady precession at θ₀:
#: that fraction, by preset (the lab's).
_PRECESSION_FACTORS: dict[str, float] = _SCENES["heavytop"]["precessionFactors"]
#: The parameters of an earlier version, by scene: an angle in radians whose slider is now in
#: degrees (``theta0`` -> ``tilt``, ``direction`` -> ``launchAngle``), still accepted.
_LEGACY: dict[str, dict[str, str]] = {
    scene: {old: spec["key"] for old, spec in _SCENES[scene].get("legacyParams", {}).items()}
    for scene in ("heavytop", "poinsot", "frames")
}
#: The Poinsot scene's names of the spun axis, by the rank of its moment.
_RANKS = ("smallest", "intermediate", "largest")
#: Relative tolerance of the round trip object -> params -> object (a few roundings).
_RTOL = 1e-9


def _check_params(scene: str, given: Any, name: str) -> dict[str, Any]:
    """``given`` completed with the scene's defaults; PoinsotError naming ``name`` and the key
    for an unknown key, a non-number, a value outside its slider's range or an unknown option."""
    spec = SCENE_PARAMS[scene]
    if not isinstance(given, dict):
        raise PoinsotError(
            f"{name}: must be a dict of the scene's parameters, got {type(given).__name__}"
        )
    legacy = {old: new for old, new in _LEGACY[scene].items() if old in given}
    if legacy:
        given = dict(given)
        for old, new in legacy.items():
            if new in given:
                raise PoinsotError(
                    f"{name}: give {new} (degrees) or {old} (radians, the earlier key), not both"
                )
            v = given.pop(old)
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
                raise PoinsotError(f"{name}: {old} must be a finite number (radians), got {v!r}")
            given[new] = math.degrees(v)
    unknown = sorted(set(given) - set(spec))
    if unknown:
        raise PoinsotError(
            f"{name}: unknown parameter(s) {unknown} (the {scene} scene has {list(spec)})"
        )
    out: dict[str, Any] = {}
    for key, s in spec.items():
        v = given.get(key, s.value)
        if isinstance(s, Choice):
            if v not in s.options:
                raise PoinsotError(f"{name}: {key} must be one of {list(s.options)}, got {v!r}")
            out[key] = v
            continue
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
            raise PoinsotError(f"{name}: {key} must be a finite number, got {v!r}")
        slack = _RTOL * max(abs(s.min), abs(s.max))  # round-off of a conversion, not a value
        if s.min - slack <= v < s.min or s.max < v <= s.max + slack:
            v = min(s.max, max(s.min, v))
        if not s.min <= v <= s.max:
            raise PoinsotError(
                f"{name}: {key} = {v} ({s.unit}) is outside the slider's range [{s.min}, {s.max}]"
            )
        out[key] = float(v)
    return out


def _close(a: float, b: float, scale: float = 1.0) -> bool:
    return abs(a - b) <= _RTOL * max(abs(a), abs(b), scale)


class _SceneWidget(anywidget.AnyWidget):  # type: ignore[misc]
    """One of the lab's scenes (``scene``) with its parameters ``params`` (synced both ways)."""

    _esm = _ESM if _ESM.is_file() else _NOT_BUILT
    _css = _CSS if _CSS.is_file() else ""
    scene = traitlets.Unicode().tag(sync=True)
    params = traitlets.Dict().tag(sync=True)
    _scene_id = ""

    def __init__(self, **params: Any) -> None:
        super().__init__(
            scene=self._scene_id, params=_check_params(self._scene_id, params, "params")
        )

    @traitlets.validate("params")
    def _valid_params(self, proposal: Any) -> dict[str, Any]:
        return _check_params(self._scene_id, proposal["value"], "params")


class HeavyTopWidget(_SceneWidget):
    """The lab's heavy symmetric top (the unit's 2.102–2.121) in a notebook cell.

    Parameters
    ----------
    top : HeavyTop, optional
        The top to show (``w.top = top``); the lab's default top (the "loops" preset) if None.
    **params
        Or the scene's parameters by key (see ``SCENE_PARAMS["heavytop"]``): ``preset``, ``w3``
        (spin ω₃, rad/s), ``tilt`` (θ₀ in degrees, as the lab's slider), ``phiDot0``,
        ``thetaDot0`` (rad/s; the "custom" preset), ``mgl`` (N·m), ``I1``, ``I3`` (kg·m²).
        ``theta0`` (radians, the earlier key) is accepted and converted to ``tilt``.

    Raises
    ------
    PoinsotError
        Naming ``top`` and the parameter for a top the sliders cannot show, or ``params`` and
        the key for a parameter outside its slider's range.

    Examples
    --------
    >>> from poinsot import HeavyTop
    >>> w = HeavyTopWidget(HeavyTop.from_spin(1.0, 0.5, 1.5, 0.6, 12.0))
    >>> w.params["w3"], w.params["preset"]
    (12.0, 'custom')
    >>> w.top.omega3
    12.0
    """

    _scene_id = "heavytop"

    def __init__(self, top: HeavyTop | None = None, **params: Any) -> None:
        super().__init__(**params)
        if top is not None:
            self.top = top

    @property
    def top(self) -> HeavyTop:
        """The top the scene shows now, built by :meth:`HeavyTop.from_spin` from ``params`` as
        the scene builds it (θ₀ = ``tilt`` in radians; a preset's initial rates from the core's
        steady precession, 2.116); assigning a :class:`HeavyTop` sets ``params`` (preset
        "custom", ``tilt`` in degrees)."""
        p = self.params
        I1, I3, mgl, w3 = p["I1"], p["I3"], p["mgl"], p["w3"]
        # The slider's degrees to the core's radians, as the scene does (x * pi/180).
        preset, theta0 = p["preset"], math.radians(p["tilt"])
        # The scene's presets (web/src/scenes/heavytop.ts, initialState): initial conditions, not
        # physics; loops/waves/steady are released at a fraction of the core's slow rate
        # (scenes.json's precessionFactors).
        if preset == "sleeping":
            return HeavyTop.from_spin(I1, I3, mgl, 0.0, w3)
        if preset == "custom":
            return HeavyTop.from_spin(
                I1, I3, mgl, theta0, w3, theta_dot=p["thetaDot0"], phi_dot=p["phiDot0"]
            )
        if preset == "cusps":
            return HeavyTop.from_spin(I1, I3, mgl, theta0, w3)
        slow = HeavyTop.steady_precession(I1, I3, mgl, theta0, w3).slow
        factor = _PRECESSION_FACTORS[preset]
        return HeavyTop.from_spin(I1, I3, mgl, theta0, w3, phi_dot=factor * slow)

    @top.setter
    def top(self, top: HeavyTop) -> None:
        if not isinstance(top, HeavyTop):
            raise PoinsotError(f"top: must be a poinsot.HeavyTop, got {type(top).__name__}")
        s = top.initial_state
        for angle in ("phi", "psi"):
            if not _close(s[angle], 0.0):
                raise PoinsotError(
                    f"top: the scene starts at phi = psi = 0; this top has {angle} = {s[angle]} rad"
                )
        params = {
            "preset": "custom",
            "w3": top.omega3,
            "tilt": math.degrees(s["theta"]),
            "phiDot0": s["phi_dot"],
            "thetaDot0": s["theta_dot"],
            "mgl": top.mgl,
            "I1": top.I1,
            "I3": top.I3,
        }
        self.params = _check_params(self._scene_id, params, "top")


class PoinsotWidget(_SceneWidget):
    """The lab's Poinsot construction and tumbling box (2.87–2.97) in a notebook cell.

    The scene's body is a uniform box of 1 kg with sides ``a, b, c`` (m) along x, y, z, spun at
    ``spin`` (rad/s) about the axis of the chosen moment (``axis``: "smallest", "intermediate",
    "largest") with ``eps`` × spin on each other axis.

    Parameters
    ----------
    body : FreeRigidBody, optional
        The body to show (``w.body = body``): its moments must be those of a 1 kg box with sides
        in the sliders' ranges, its ω₀ a spin about one axis plus ε·spin on the other two, its
        initial attitude the identity. The lab's default if None.
    **params
        Or the scene's parameters by key (``SCENE_PARAMS["poinsot"]``), e.g. ``view="tumbling box"``.

    Raises
    ------
    PoinsotError
        Naming ``body`` and the parameter or condition for a body the scene cannot show.

    Examples
    --------
    >>> w = PoinsotWidget(view="tumbling box", axis="largest")
    >>> w.body.regime
    'about max axis'
    """

    _scene_id = "poinsot"

    def __init__(self, body: FreeRigidBody | None = None, **params: Any) -> None:
        super().__init__(**params)
        if body is not None:
            self.body = body

    @staticmethod
    def _moments(sides: list[float]) -> list[float]:
        """The box's principal moments along x, y, z (kg·m²), from the core (RigidBody.cuboid)."""
        inertia = RigidBody.cuboid(BOX_MASS, sides).inertia
        return [float(inertia[k][k]) for k in range(3)]

    @staticmethod
    def _axis(moments: list[float], rank: str) -> int:
        """The axis (0, 1, 2) of the moment of ``rank``, ties broken as the scene (stable order)."""
        order = sorted(range(3), key=lambda i: moments[i])
        return order[_RANKS.index(rank)]

    @property
    def body(self) -> FreeRigidBody:
        """The body the scene shows now: :class:`FreeRigidBody` of the box's moments (from the
        core) and ω₀ = spin on the chosen axis + eps·spin on the others; assigning one sets
        ``params``."""
        p = self.params
        m = self._moments([p["a"], p["b"], p["c"]])
        i = self._axis(m, p["axis"])
        omega0 = [p["eps"] * p["spin"]] * 3
        omega0[i] = p["spin"]
        return FreeRigidBody(m, omega0)

    @body.setter
    def body(self, body: FreeRigidBody) -> None:
        if not isinstance(body, FreeRigidBody):
            raise PoinsotError(f"body: must be a poinsot.FreeRigidBody, got {type(body).__name__}")
        m = [float(x) for x in body.moments]
        w = [float(x) for x in body.omega0]
        q0 = [float(x) for x in body.attitude(0.0)]
        if not _close(abs(q0[0]), 1.0):
            raise PoinsotError(
                f"body: the scene starts at the identity attitude; this body starts at {q0}"
            )
        # The uniform box with these moments: the core's inverse of RigidBody.cuboid.
        try:
            sides = [float(x) for x in RigidBody.cuboid_sides(BOX_MASS, m)]
        except PoinsotError as err:
            raise PoinsotError(f"body: not the scene's {BOX_MASS} kg box ({err})") from None
        # ω₀ = spin on one axis, eps·spin on the other two (0 ≤ eps ≤ 1).
        found = None
        for i in range(3):
            j, k = [x for x in range(3) if x != i]
            if (
                w[i] > 0
                and _close(w[j], w[k], w[i])
                and -_RTOL * w[i] <= w[j] <= w[i] * (1 + _RTOL)
            ):
                found = (i, w[i], max(0.0, min(1.0, w[j] / w[i])))
                break
        if found is None:
            raise PoinsotError(
                f"body: omega0 = {w} is not a spin about one axis plus eps * spin on the other two "
                "(0 <= eps <= 1), the scene's initial condition"
            )
        i, spin, eps = found
        order = sorted(range(3), key=lambda n: m[n])
        params = dict(self.params)
        params.update(
            a=sides[0], b=sides[1], c=sides[2], spin=spin, eps=eps, axis=_RANKS[order.index(i)]
        )
        self.params = _check_params(self._scene_id, params, "body")


class FramesWidget(_SceneWidget):
    """The lab's rotating frames (2.20–2.28) in a notebook cell: a particle on a turntable seen
    from the fixed frame and from the table's frame.

    Parameters
    ----------
    **params
        The scene's parameters (``SCENE_PARAMS["frames"]``): ``omega`` (rad/s), ``omegaDot``
        (rad/s²), ``stiffness`` (N/m, m = 1 kg), ``r0`` (m), ``speed`` (m/s), ``launchAngle``
        (degrees, as the lab's slider; ``direction`` in radians, the earlier key, is accepted and
        converted), ``launch`` ("fixed frame" or "rotating frame").

    Raises
    ------
    PoinsotError
        Naming ``params`` and the key for a value outside its slider's range.

    Examples
    --------
    >>> FramesWidget(omega=1.2).params["omega"]
    1.2
    """

    _scene_id = "frames"
