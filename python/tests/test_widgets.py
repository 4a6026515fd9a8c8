"""poinsot.widgets: the Python side of the notebook widgets (trait sync, the objects built from
the synced parameters, refusals); the front end is tested in chromium by web/tests/widget.test.mjs."""

from __future__ import annotations

import importlib
import math
import re
import sys

import pytest

pytest.importorskip("anywidget")

import poinsot
from poinsot import FreeRigidBody, HeavyTop, PoinsotError, widgets


def test_import_without_anywidget_names_the_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "anywidget", None)
    monkeypatch.delitem(sys.modules, "poinsot.widgets")
    with pytest.raises(ImportError, match=re.escape("pip install 'poinsot[notebook]'")):
        importlib.import_module("poinsot.widgets")


def test_defaults_are_the_scenes_and_synced():
    w = widgets.HeavyTopWidget()
    assert w.scene == "heavytop"
    assert w.params == {k: s.value for k, s in widgets.SCENE_PARAMS["heavytop"].items()}
    # The synced traits: what the comm sends to the front end.
    assert {"scene", "params"} <= set(w.keys)
    assert widgets.PoinsotWidget().scene == "poinsot" and widgets.FramesWidget().scene == "frames"


def test_assigning_a_top_writes_the_params_and_reads_back_the_same_top():
    top = HeavyTop.from_spin(1.3, 0.6, 2.1, 0.7, 15.0, theta_dot=-0.4, phi_dot=0.9)
    w = widgets.HeavyTopWidget(top)
    assert w.params == {
        "preset": "custom",
        "w3": 15.0,
        "tilt": math.degrees(0.7),  # the lab's slider: degrees
        "phiDot0": 0.9,
        "thetaDot0": -0.4,
        "mgl": 2.1,
        "I1": 1.3,
        "I3": 0.6,
    }
    back = w.top
    assert (back.I1, back.I3, back.mgl, back.omega3) == (1.3, 0.6, 2.1, 15.0)
    assert back.initial_state == pytest.approx(top.initial_state, rel=1e-14, abs=1e-14)
    # The same constants and motion, cross-checked on the core's own numbers.
    assert back.turning_points == pytest.approx(top.turning_points, rel=1e-13)
    assert back.energy == pytest.approx(top.energy, rel=1e-14)


def test_params_from_the_front_end_move_w_top():
    w = widgets.HeavyTopWidget()
    # What the comm does when a slider moves: the trait is set to the front end's dict.
    w.params = {**w.params, "preset": "cusps", "w3": 20.0, "I3": 0.8}
    top = w.top
    assert top.omega3 == 20.0 and top.I3 == 0.8
    # Cusps: released at rest in phi and theta (the scene's preset), so p_psi = I3 w3 (2.103)
    # and the top starts at the upper turning point.
    s = top.initial_state
    assert s["phi_dot"] == 0.0 and s["theta_dot"] == 0.0
    assert top.p_psi == pytest.approx(0.8 * 20.0, rel=1e-15)
    assert min(top.turning_points) == pytest.approx(math.radians(50), rel=1e-12)  # tilt 50°


def test_presets_follow_the_cores_steady_precession():
    w = widgets.HeavyTopWidget(preset="steady precession", w3=12.0)
    top = w.top
    # Released at the slow steady rate (2.116): theta does not move.
    assert top.turning_points[1] - top.turning_points[0] == pytest.approx(0.0, abs=1e-9)
    slow = HeavyTop.steady_precession(1.0, 0.5, 1.5, math.radians(50), 12.0).slow
    assert top.initial_state["phi_dot"] == pytest.approx(slow, rel=1e-15)
    w.params = {**w.params, "preset": "loops"}
    assert w.top.initial_state["phi_dot"] == pytest.approx(-0.5 * slow, rel=1e-15)
    assert w.top.motion_class == "loops"


def test_a_top_outside_the_sliders_is_refused_naming_top_and_the_parameter():
    w = widgets.HeavyTopWidget()
    before = dict(w.params)
    with pytest.raises(
        PoinsotError, match=r"top: w3 = 250.0 \(rad/s\) is outside the slider's range \[0.5, 200\]"
    ):
        w.top = HeavyTop.from_spin(1.0, 0.5, 1.5, 0.6, 250.0)
    with pytest.raises(PoinsotError, match=r"top: I1 = 5.0"):
        w.top = HeavyTop.from_spin(5.0, 0.5, 1.5, 0.6, 10.0)
    with pytest.raises(PoinsotError, match=r"top: .*phi = 0.3"):
        w.top = HeavyTop.from_spin(1.0, 0.5, 1.5, 0.6, 10.0, phi=0.3)
    with pytest.raises(PoinsotError, match="top: must be a poinsot.HeavyTop"):
        w.top = "a top"  # type: ignore[assignment]
    assert w.params == before  # nothing half-applied
    # Negative control: a top inside the ranges is taken.
    w.top = HeavyTop.from_spin(1.0, 0.5, 1.5, 0.6, 199.5)
    assert w.params["w3"] == 199.5


def test_params_are_checked_by_key():
    with pytest.raises(PoinsotError, match=r"params: unknown parameter\(s\) \['spin'\]"):
        widgets.HeavyTopWidget(spin=3.0)
    w = widgets.FramesWidget()
    with pytest.raises(PoinsotError, match=r"params: omega = 9.0 \(rad/s\) is outside"):
        w.params = {"omega": 9.0}
    with pytest.raises(PoinsotError, match=r"params: launch must be one of"):
        w.params = {"launch": "sideways"}
    w.params = {"omega": -1.5}
    assert w.params["omega"] == -1.5 and w.params["r0"] == 0.8  # completed with the defaults


def test_angles_in_params_are_the_labs_degrees_and_the_objects_radians():
    # One angle unit per lab: the synced params hold the slider's degrees; w.top is SI.
    w = widgets.HeavyTopWidget(preset="cusps", tilt=30.0)
    assert w.params["tilt"] == 30.0
    assert w.top.initial_state["theta"] == math.radians(30.0) == 30.0 * (math.pi / 180)
    assert widgets.SCENE_PARAMS["heavytop"]["tilt"].unit == "°"
    assert widgets.SCENE_PARAMS["frames"]["launchAngle"].unit == "°"
    # No slider of any widget is an angle in radians (rates in rad/s are not angles).
    units = {
        s.unit for p in widgets.SCENE_PARAMS.values() for s in p.values() if hasattr(s, "unit")
    }
    assert "rad" not in units, units


def test_the_earlier_keys_in_radians_are_converted_not_misread():
    # theta0 = 0.52 rad (the earlier key) is a 29.8° tilt, not 0.52°.
    w = widgets.HeavyTopWidget(preset="cusps", theta0=0.52)
    assert "theta0" not in w.params
    assert w.params["tilt"] == pytest.approx(math.degrees(0.52), rel=1e-15)
    assert w.top.initial_state["theta"] == pytest.approx(0.52, rel=1e-15)
    f = widgets.FramesWidget(direction=-1.0)
    assert f.params["launchAngle"] == pytest.approx(math.degrees(-1.0), rel=1e-15)
    with pytest.raises(PoinsotError, match=r"params: give tilt \(degrees\) or theta0"):
        widgets.HeavyTopWidget(theta0=0.5, tilt=30.0)
    with pytest.raises(PoinsotError, match=r"params: tilt = 171.8\d* \(°\) is outside"):
        widgets.HeavyTopWidget(theta0=3.0)  # 171.9°: the slider's range is checked after
    with pytest.raises(PoinsotError, match=r"params: direction must be a finite number"):
        widgets.FramesWidget(direction="north")


def test_poinsot_body_round_trip_uses_the_cores_box():
    w = widgets.PoinsotWidget(axis="largest", spin=6.0, eps=0.1, a=0.3, b=0.2, c=0.1)
    body = w.body
    # The box's moments from the core, against the closed form M (b² + c²)/12 (1 kg).
    assert body.moments == pytest.approx(
        [(0.04 + 0.01) / 12, (0.09 + 0.01) / 12, (0.09 + 0.04) / 12], rel=1e-14
    )
    assert list(body.omega0) == pytest.approx([0.6, 0.6, 6.0], rel=1e-15)  # largest moment: z
    assert body.regime == "about max axis"
    other = widgets.PoinsotWidget()
    other.body = body
    p = other.params
    assert (p["axis"], p["spin"]) == ("largest", 6.0)
    assert (p["eps"], p["a"], p["b"], p["c"]) == pytest.approx((0.1, 0.3, 0.2, 0.1), rel=1e-12)
    assert other.body.energy == pytest.approx(body.energy, rel=1e-13)


def test_a_body_the_scene_cannot_show_is_refused_naming_body():
    w = widgets.PoinsotWidget()
    with pytest.raises(PoinsotError, match="body: omega0 .* is not a spin about one axis"):
        w.body = FreeRigidBody([1.0, 2.0, 2.5], [1.0, 0.2, 0.3])
    with pytest.raises(PoinsotError, match=r"body: a = 0.7\d* \(m\) is outside"):
        w.body = FreeRigidBody(poinsot.RigidBody.cuboid(1.0, [0.7, 0.2, 0.1]), [4.0, 0.2, 0.2])
    with pytest.raises(
        PoinsotError, match="body: not the scene.s .* box .*moments: .* not the moments of a box"
    ):
        w.body = FreeRigidBody([1.0, 1.0, 2.0], [4.0, 0.2, 0.2])
    with pytest.raises(PoinsotError, match="body: the scene starts at the identity attitude"):
        w.body = FreeRigidBody([0.004, 0.005, 0.007], [4.0, 0.2, 0.2], [0.0, 1.0, 0.0, 0.0])


def test_the_bundle_exists_and_exports_a_render():
    esm = widgets.STATIC / "widget.js"
    if not esm.is_file():
        pytest.skip("the widget bundle is not built (bash web/build.sh)")
    text = esm.read_text(encoding="utf-8")
    assert re.search(r"export \{[^}]*\bas default\b", text)
    assert "render" in text
    assert "module_or_path" in text  # the core is instantiated from the bundled bytes
    assert widgets.HeavyTopWidget()._esm == text  # anywidget serves that file
