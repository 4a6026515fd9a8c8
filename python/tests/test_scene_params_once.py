"""The lab's scene parameters in one place (issue 22): python/poinsot/widgets/scenes.json holds the
sliders, choices and presets of the scenes the notebook widgets show; the lab's scenes import it
(web/src/scenes/params.ts) and poinsot.widgets reads it, so neither restates them."""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import pytest

pytest.importorskip("anywidget")

from poinsot import widgets

ROOT = Path(__file__).resolve().parents[2]
SCENES = ("heavytop", "poinsot", "frames")


def _differences(params: dict[str, dict[str, Any]], data: dict[str, Any]) -> list[str]:
    """Where the widgets' SCENE_PARAMS differ from scenes.json (empty if nowhere)."""
    out = []
    for scene in SCENES:
        specs = {s["key"]: s for s in data[scene]["params"]}
        if list(params[scene]) != list(specs):
            out.append(f"{scene}: keys {list(params[scene])} != {list(specs)}")
            continue
        for key, spec in specs.items():
            p = params[scene][key]
            if spec["kind"] == "choice":
                want: tuple[Any, ...] = (tuple(spec["options"]), spec["value"])
                got: tuple[Any, ...] = (p.options, p.value)
            else:
                fields = ("min", "max", "step", "value", "unit")
                want = tuple(spec[f] for f in fields)
                got = tuple(getattr(p, f) for f in fields)
            if got != want:
                out.append(f"{scene}.{key}: {got} != {want}")
    return out


def test_the_widgets_parameters_are_the_json():
    data = json.loads(widgets.SCENES_JSON.read_text(encoding="utf-8"))
    assert _differences(widgets.SCENE_PARAMS, data) == []
    assert widgets.BOX_MASS == data["poinsot"]["boxMass"] == 1.0
    # The presets released at a fraction of the slow precession, and nothing else.
    presets = data["heavytop"]["params"][0]["options"]
    assert set(data["heavytop"]["precessionFactors"]) <= set(presets)


def test_negative_control_a_slider_restated_differently_is_caught():
    data = json.loads(widgets.SCENES_JSON.read_text(encoding="utf-8"))
    w3 = data["heavytop"]["params"][1]
    was = (w3["min"], w3["max"], w3["step"], w3["value"], w3["unit"])
    w3["max"] += 1
    assert _differences(widgets.SCENE_PARAMS, data) == [
        f"heavytop.w3: {was} != {(*was[:1], was[1] + 1, *was[2:])}"
    ]


def test_the_json_is_in_the_package_not_in_a_build():
    # Shipped by maturin's python-source with the package (not git-ignored like static/).
    path = widgets.SCENES_JSON
    assert path.parent == Path(widgets.__file__).parent
    gitignore = (ROOT / ".gitignore").read_text(encoding="utf-8")
    assert "scenes.json" not in gitignore


@pytest.mark.skipif(not (ROOT / "web" / "src").is_dir(), reason="the lab's sources are not here")
def test_the_lab_scenes_import_the_json_and_restate_no_parameter():
    shared = (ROOT / "web/src/scenes/params.ts").read_text(encoding="utf-8")
    assert 'from "../../../python/poinsot/widgets/scenes.json"' in shared
    for scene in SCENES:
        src = (ROOT / f"web/src/scenes/{scene}.ts").read_text(encoding="utf-8")
        assert re.search(rf'params: sceneParams\("{scene}"', src), scene
        assert not re.search(r'kind: "(number|choice)"', src), f"{scene}.ts restates a parameter"


def test_angles_are_degrees_and_the_earlier_radian_keys_map_onto_degree_sliders():
    # One angle unit per lab (issue 23 item 4): no slider of a shared scene is an angle in
    # radians; each earlier key in radians (kept for old share links and notebooks) names a
    # current slider in degrees that has another name.
    data = json.loads(widgets.SCENES_JSON.read_text(encoding="utf-8"))
    for scene in SCENES:
        units = {s["key"]: s.get("unit") for s in data[scene]["params"]}
        assert "rad" not in units.values(), f"{scene}: a slider in radians"
        for old, spec in data[scene].get("legacyParams", {}).items():
            assert spec["unit"] == "rad" and old not in units, (scene, old)
            assert units[spec["key"]] == "°", (scene, old, spec)
    assert data["heavytop"]["legacyParams"] == {"theta0": {"key": "tilt", "unit": "rad"}}
    assert data["frames"]["legacyParams"] == {"direction": {"key": "launchAngle", "unit": "rad"}}
    # The lab reads the same table (params.ts legacyParams), converting by 180/π.
    if (ROOT / "web" / "src").is_dir():
        shared = (ROOT / "web/src/scenes/params.ts").read_text(encoding="utf-8")
        assert "legacyParams" in shared and "1 / DEG" in shared
