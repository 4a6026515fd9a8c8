"""The unit's own figures (poinsot.plots.unit): every figure of the unit has one, each draws
cleanly in both styles, and the numbers drawn are the model's — read back from the artists
and compared with closed forms or with another route through the core.

The figure numbers come from the unit itself (reference/unit_figures.txt: the unit's lines
that name a figure, see reference/gen_unit_figures.py), so a figure of the unit without a
counterpart in UNIT_FIGURES fails here. docs/figures.md's table must match UNIT_FIGURES both
ways, and each of its calls must draw.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from unit_source import unit_text

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")

import poinsot as ps  # noqa: E402
import poinsot.plots as plots  # noqa: E402
from click.testing import CliRunner  # noqa: E402
from figure_checks import axes_without_units, layout_problems  # noqa: E402
from poinsot.cli import EXIT_USAGE, main  # noqa: E402
from poinsot.plots import UNIT_FIGURES, unit_figure  # noqa: E402
from poinsot.plots import unit as pu  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
REFERENCE = Path(__file__).resolve().parent / "reference"
sys.path.insert(0, str(REFERENCE))
from gen_unit_figures import figure_lines  # noqa: E402

#: Agreement of numbers read back from a drawing with their reference: the drawing stores
#: the core's doubles, so only round-off separates them.
TIGHT = 1e-12

# ---------------------------------------------------------------------------------------------
# Reading a figure back
# ---------------------------------------------------------------------------------------------
_SUP = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")
_NUMBER = re.compile(r"[−-]?\d+(?:\.\d*)?(?:×10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?")


def numbers(text: str) -> list[float]:
    """Every number written in ``text`` ("1.03×10⁻³", "−0.250", "45"), as floats."""
    out = []
    for m in _NUMBER.findall(text):
        m = m.replace("−", "-")
        if "×10" in m:
            mant, exp = m.split("×10")
            out.append(float(mant) * 10.0 ** int(exp.translate(_SUP)))
        else:
            out.append(float(m))
    return out


def shown(written: float, value: float, digits: int = 3) -> bool:
    """Whether ``written`` is ``value`` to the ``digits`` significant digits it was written
    with."""
    return written == float(f"{value:.{digits}g}")


def by_gid(fig: Any, gid: str) -> list[Any]:
    return [a for a in fig.findobj() if a.get_gid() == gid]


def one(fig: Any, gid: str) -> Any:
    found = by_gid(fig, gid)
    assert len(found) == 1, f"{gid}: {len(found)} artists"
    return found[0]


def ends2d(fig: Any, gid: str) -> tuple[np.ndarray, np.ndarray]:
    """(start, end) of a 2-D arrow drawn by plots.unit (an annotation)."""
    a = one(fig, gid)
    return np.asarray(a.xyann, dtype=float), np.asarray(a.xy, dtype=float)


def ends3d(fig: Any, gid: str) -> tuple[np.ndarray, np.ndarray]:
    a = one(fig, gid)
    return a.start, a.end


def unit_vector(v: Any) -> np.ndarray:
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


def text_of(fig: Any, gid: str) -> str:
    return str(one(fig, gid).get_text())


def rz(a: float) -> np.ndarray:
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def rx(a: float) -> np.ndarray:
    c, s = np.cos(a), np.sin(a)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def rodrigues(axis: Any, angle: float) -> np.ndarray:
    n = unit_vector(axis)
    k = np.array([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


# ---------------------------------------------------------------------------------------------
# The registry covers the unit
# ---------------------------------------------------------------------------------------------
_CAPTION = re.compile(r"^fig\s*[.:]*\s*[.:]?\s*(2(?:\.\d+)?)\s*$", re.IGNORECASE)
_REFERENCE = re.compile(r"\bfig(?:ure)?\s*[.:]*\s*\(?\s*(2\.\d+[a-d]?)\b", re.IGNORECASE)


def unit_figure_numbers(lines: list[str]) -> list[str]:
    """The figure numbers of the unit, in order, from its lines naming a figure: captions
    ("Fig: 2.1") and references in the text ("fig.2.3", "Fig.(2.12a)"). A caption that lost
    its number's decimals in the scan ("Fig: 2") is the one figure between its neighbours'
    captions; a number cited only in lettered parts (2.12a–d) is those parts."""
    found: list[str] = []
    for line in lines:
        cap = _CAPTION.match(line)
        if cap:
            found.append(cap.group(1))
        found += _REFERENCE.findall(line)
    ordered = list(dict.fromkeys(found))
    damaged = [n for n in ordered if "." not in n]
    for bad in damaged:  # "Fig: 2" between the captions 2.1 and 2.3 is 2.2
        i = ordered.index(bad)
        before, after = ordered[i - 1], ordered[i + 1]
        assert int(after.split(".")[1]) - int(before.split(".")[1]) == 2, (before, after)
        ordered[i] = f"2.{int(before.split('.')[1]) + 1}"
    parts = {re.sub("[a-d]$", "", n) for n in ordered if n[-1] in "abcd"}
    return [n for n in ordered if n not in parts]


def reference_lines() -> list[str]:
    return (REFERENCE / "unit_figures.txt").read_text(encoding="utf-8").splitlines()


def test_the_registry_holds_every_figure_of_the_unit_and_no_other() -> None:
    expected = unit_figure_numbers(reference_lines())
    # The parse itself: 15 figures, 2.12 in four parts, the scan-damaged "Fig: 2" read as 2.2.
    assert expected[:3] == ["2.1", "2.2", "2.3"]
    assert [n for n in expected if n.startswith("2.12")] == ["2.12a", "2.12b", "2.12c", "2.12d"]
    assert len(expected) == 18
    assert list(UNIT_FIGURES) == sorted(UNIT_FIGURES, key=expected.index)
    assert set(UNIT_FIGURES) == set(expected)


def test_a_figure_missing_from_the_registry_would_fail() -> None:
    """Negative control: the parse sees a figure the registry lacks."""
    lines = [*reference_lines(), "Fig.: 2.16"]
    assert set(unit_figure_numbers(lines)) - set(UNIT_FIGURES) == {"2.16"}


def test_the_reference_lines_are_the_units() -> None:
    assert figure_lines(unit_text()) == reference_lines()


# ---------------------------------------------------------------------------------------------
# Every figure draws cleanly, in both styles
# ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("style", ["paper", "slides"])
@pytest.mark.parametrize("number", list(UNIT_FIGURES))
def test_every_figure_fits_and_has_units(number: str, style: str) -> None:
    fig = unit_figure(number, style=style)
    assert layout_problems(fig) == []
    assert axes_without_units(fig) == []


def test_slides_are_larger_and_saved_at_200_dpi(tmp_path: Path) -> None:
    from PIL import Image

    sizes = {}
    for style in ("paper", "slides"):
        fig = unit_figure("2.5", style=style)
        sizes[style] = fig.get_size_inches()[0], one(fig, "coriolis-label").get_fontsize()
        fig.savefig(tmp_path / f"{style}.png")
    assert sizes["slides"][0] >= 1.5 * sizes["paper"][0]
    assert sizes["slides"][1] > sizes["paper"][1]
    dpi = Image.open(tmp_path / "slides.png").info["dpi"][0]
    assert round(dpi) >= 200


def test_the_checks_catch_a_broken_unit_figure() -> None:
    """Negative control: a title wider than the figure and an axis label without its unit
    on one of these figures are caught."""
    fig = unit_figure("2.4")
    fig.axes[0].set_title("x" * 400)
    fig.axes[0].set_xlabel("distance from the axis")
    assert any("leaves the figure" in p for p in layout_problems(fig))
    assert axes_without_units(fig) != []


def test_unknown_numbers_and_styles_are_refused_by_name() -> None:
    with pytest.raises(ps.PoinsotError, match=r"number: .*'2\.12a'.*got '2\.16'"):
        unit_figure("2.16")
    with pytest.raises(ps.PoinsotError, match="number: "):
        unit_figure(2.5)  # type: ignore[arg-type]
    with pytest.raises(ps.PoinsotError, match="style: "):
        unit_figure("2.5", style="poster")


def test_exported_from_poinsot_plots() -> None:
    names = {n for n in pu.__all__ if n.startswith("plot_")} | {"unit_figure"}
    assert names <= set(plots.__all__)  # __all__: the drawing functions
    for name in [*names, "UNIT_FIGURES"]:
        assert getattr(plots, name) is getattr(pu, name)


# ---------------------------------------------------------------------------------------------
# The numbers drawn are the model's
# ---------------------------------------------------------------------------------------------
def test_2_1_positions_and_accelerations_add_up() -> None:
    frame = ps.MovingFrame(origin=[3, 1, 0], velocity=[1, 0.5, 0], acceleration=[0.6, 0.3, 0])
    r, v, a = np.array([1.0, 1.5, 0.0]), np.array([0.0, 0.5, 0.0]), np.array([0.0, -0.4, 0.0])
    fig = pu.plot_translating_frame(frame, r, v, a)
    s, e = ends2d(fig, "r_fixed")
    np.testing.assert_allclose(s, [0.0, 0.0], atol=TIGHT)  # from O′
    np.testing.assert_allclose(e, (frame.origin + r)[:2], atol=TIGHT)  # r′ = R + r (2.1)
    _, e = ends2d(fig, "r_ddot_fixed")
    np.testing.assert_allclose(e, (frame.acceleration + a)[:2], atol=TIGHT)  # 2.3
    s2, e2 = ends2d(fig, "r_ddot")  # the relative part starts where R̈ ends
    np.testing.assert_allclose(s2, frame.acceleration[:2], atol=TIGHT)
    np.testing.assert_allclose(e2, e, atol=TIGHT)
    # Negative control: a rotating frame is not Fig. 2.1.
    with pytest.raises(ps.PoinsotError, match="frame: "):
        pu.plot_translating_frame(ps.MovingFrame(angular_velocity=[0, 0, 1.0]))


def test_2_2_rotating_axes_are_turned_by_omega_t() -> None:
    w, t, r = np.array([0.25, -0.2, 1.0]), 0.8, np.array([0.8, 0.5, 0.6])
    fig = pu.plot_rotating_frame(ps.MovingFrame(angular_velocity=w), r, t)
    R = rodrigues(w, np.linalg.norm(w) * t)  # Rodrigues' formula, independently
    for k in range(3):
        np.testing.assert_allclose(ends3d(fig, f"moving-{k + 1}")[1], R[:, k], atol=1e-12)
    np.testing.assert_allclose(ends3d(fig, "r")[1], R @ r, atol=1e-12)  # eq. 2.7
    start, end = ends3d(fig, "omega_cross_r")
    np.testing.assert_allclose(
        unit_vector(end - start), unit_vector(np.cross(w, R @ r)), atol=1e-12
    )
    # Negative control: the axes of the frame at t = 0 are not these.
    assert not np.allclose(ends3d(fig, "moving-1")[1], [1.0, 0.0, 0.0], atol=1e-3)


def test_2_3_centripetal_and_coriolis_arrows_are_the_frames_terms() -> None:
    w, r, v = np.array([0.0, 0.0, 2.0]), np.array([0.9, 0.0, 1.0]), np.array([0.0, 0.3, 0.2])
    fig = pu.plot_centripetal(ps.MovingFrame(angular_velocity=w), r, v)
    cp = np.cross(w, np.cross(w, r))  # the closed forms of 2.23
    co = 2 * np.cross(w, v)
    s, e = ends3d(fig, "centripetal")
    np.testing.assert_allclose(unit_vector(e - s), unit_vector(cp), atol=1e-12)
    # It reaches the axis: the foot is on ω's line.
    assert np.linalg.norm(np.cross(e, unit_vector(w))) < 1e-9
    s2, e2 = ends3d(fig, "coriolis")
    np.testing.assert_allclose(unit_vector(e2 - s2), unit_vector(co), atol=1e-12)
    # One scale for both: their lengths stand as their magnitudes.
    ratio = np.linalg.norm(e2 - s2) / np.linalg.norm(e - s)
    assert ratio == pytest.approx(np.linalg.norm(co) / np.linalg.norm(cp), rel=1e-9)
    # The values written: ω² r sin θ = 3.60 m/s² (2.24) and |2ω × ṙ|.
    assert shown(numbers(text_of(fig, "centripetal-label"))[0], 4.0 * 0.9)
    assert shown(numbers(text_of(fig, "coriolis-label"))[0], float(np.linalg.norm(co)))
    # Negative controls: no circle on the axis, no turning without ω; no Coriolis at rest.
    with pytest.raises(ps.PoinsotError, match="position: "):
        pu.plot_centripetal(position=[0.0, 0.0, 1.0])
    with pytest.raises(ps.PoinsotError, match="frame: "):
        pu.plot_centripetal(ps.MovingFrame())
    assert by_gid(pu.plot_centripetal(), "coriolis") == []


def test_2_4_centrifugal_is_omega_squared_r_cos_lambda_away_from_the_axis() -> None:
    earth = ps.Earth.solar_day(radius=6.4e6)  # the unit's numbers
    fig = pu.plot_earth_centrifugal(earth, latitude=45)
    w, R = earth.rotation_rate, earth.radius
    assert shown(numbers(text_of(fig, "centrifugal-label"))[0], w**2 * R * np.cos(np.pi / 4))
    s, e = ends2d(fig, "centrifugal")
    np.testing.assert_allclose(unit_vector(e - s), [1.0, 0.0], atol=1e-12)  # away from the axis
    info = text_of(fig, "info")
    assert "0.0338 m/s²" in info  # the unit's ω²R = 3.4×10⁻² m/s² (3.38×10⁻² with 2π/86400)
    deviation = earth.plumb_line_deviation(45, degrees=True)
    written = numbers(info.splitlines()[-1].split("m/s²")[1])[0]
    assert shown(written, deviation)  # the plumb line's angle, in degrees
    # Negative control: at the pole there is no centrifugal arrow to see.
    s, e = ends2d(pu.plot_earth_centrifugal(earth, latitude=90), "centrifugal")
    assert np.linalg.norm(e - s) < 1e-6 * np.linalg.norm(s)


@pytest.mark.parametrize(("latitude", "sense"), [(45.0, 1.0), (-45.0, -1.0), (90.0, 1.0)])
def test_2_5_2_6_coriolis_deflects_right_in_the_north(latitude: float, sense: float) -> None:
    earth, v = ps.Earth(), 10.0
    fig = pu.plot_earth_coriolis(earth, latitude=latitude, speed=v)
    lam = np.radians(latitude)
    expected = 2 * earth.rotation_rate * v * abs(np.sin(lam))  # 2ω v sin λ, closed form
    assert shown(numbers(text_of(fig, "coriolis-label"))[0], expected)
    # Another route through the core: the frames module's Coriolis force per unit mass.
    frame = ps.MovingFrame(angular_velocity=earth.omega_enu(lam))
    force = frame.fictitious_forces(1.0, [0.0, 0.0, 0.0], [0.0, v, 0.0])["coriolis"]
    np.testing.assert_allclose(force, earth.coriolis_acceleration(lam, [0.0, v, 0.0]), atol=1e-18)
    s, e = ends2d(fig, "coriolis-north")
    np.testing.assert_allclose(unit_vector(e - s), [sense, 0.0], atol=1e-12)  # to the right
    # Drawn so that 2ω v (the pole's) is as long as v: at λ it is |sin λ| as long.
    sv, ev = ends2d(fig, "v-north")
    assert np.linalg.norm(e - s) / np.linalg.norm(ev - sv) == pytest.approx(abs(np.sin(lam)))
    track = one(fig, "track-north").get_xydata()
    assert np.sign(track[-1, 0]) == sense  # the parcel launched north ends up to its right


def test_2_5_no_horizontal_coriolis_at_the_equator() -> None:
    """Negative control: at the equator the arrows of horizontal motion vanish."""
    fig = pu.plot_earth_coriolis(latitude=0.0)
    s, e = ends2d(fig, "coriolis-north")
    assert np.linalg.norm(e - s) < 1e-9 * np.linalg.norm(ends2d(fig, "v-north")[1])


def test_2_7_the_low_turns_counterclockwise_in_the_north() -> None:
    earth = ps.Earth()
    fig = pu.plot_flow_into_low(earth, latitudes=(45.0, -45.0))
    north, south = fig.axes
    assert north.get_title().endswith(": counterclockwise")
    assert south.get_title().endswith(": clockwise")
    flow = earth.flow_into_low(45.0, degrees=True)
    np.testing.assert_allclose(
        north.get_lines()[0].get_xydata(), flow.position[0] / 1e3, atol=TIGHT
    )
    # Independently of the core's sense: the parcels' mean angular momentum about L, r × v.
    xy, vel = flow.position, flow.velocity
    assert np.mean(xy[..., 0] * vel[..., 1] - xy[..., 1] * vel[..., 0]) > 0


def test_2_8_the_axis_lies_in_both_bisecting_planes() -> None:
    R = ps.euler_to_matrix([10.0, 50.0, 30.0], degrees=True)
    fig = pu.plot_euler_theorem(R)
    line = one(fig, "axis").get_data_3d()
    drawn = unit_vector([line[k][1] - line[k][0] for k in range(3)])
    values, vectors = np.linalg.eig(R)  # Euler's theorem: the eigenvector of eigenvalue 1
    n = np.real(vectors[:, np.argmin(abs(values - 1))])
    assert abs(abs(drawn @ n) - 1) < 1e-12
    for nm, p in (("A", [1.0, 0.0, 0.0]), ("B", [0.0, 0.0, 1.0])):
        marker = one(fig, f"{nm}'").get_data_3d()
        np.testing.assert_allclose(np.ravel(marker), R @ p, atol=1e-12)
        assert abs(one(fig, f"plane-{nm}").normal @ drawn) < 1e-12  # OC in the plane ⊥ AA′
        arc = one(fig, f"arc-{nm}").get_data_3d()
        np.testing.assert_allclose([c[-1] for c in arc], R @ p, atol=1e-12)  # A about OC → A′
    angle = numbers(text_of(fig, "info").splitlines()[1])[0]
    assert angle == pytest.approx(np.degrees(np.arccos((np.trace(R) - 1) / 2)), abs=1e-2)
    # Negative control: another rotation's axis is not in these planes.
    other, _ = ps.rotation_axis(ps.euler_to_matrix([60.0, 20.0, -40.0], degrees=True))
    assert abs(one(fig, "plane-A").normal @ other) > 0.1


def test_2_9_the_dumbbells_momentum_is_perpendicular_to_the_rod() -> None:
    m, w = np.array([1.0, 1.0]), np.array([0.0, 0.0, 2.0])
    pos = 0.5 * np.array([[np.sin(np.pi / 6), 0, np.cos(np.pi / 6)]]) * np.array([[1], [-1]])
    fig = pu.plot_dumbbell(m, pos, w)
    L = sum(mk * np.cross(rk, np.cross(w, rk)) for mk, rk in zip(m, pos))  # 2.58
    s, e = ends3d(fig, "L")
    np.testing.assert_allclose(unit_vector(e - s), unit_vector(L), atol=1e-12)
    assert abs(unit_vector(e - s) @ unit_vector(pos[0])) < 1e-12  # ⊥ rod
    s, e = ends3d(fig, "N")
    np.testing.assert_allclose(unit_vector(e - s), unit_vector(np.cross(w, L)), atol=1e-12)  # 2.59
    cone = np.array(one(fig, "L-cone").get_data_3d()).T  # L keeps its angle from ω as it turns
    cosines = cone @ unit_vector(w) / np.linalg.norm(cone, axis=1)
    np.testing.assert_allclose(cosines, cosines[0], atol=1e-12)
    assert numbers(text_of(fig, "info").splitlines()[2])[0] == pytest.approx(60.0)
    # Negative control: about a principal axis (here ⊥ rod) L ∥ ω and no torque is needed.
    fig = pu.plot_dumbbell(m, pos, [0.0, 2.0, 0.0])
    assert by_gid(fig, "N") == []
    s, e = ends3d(fig, "L")
    np.testing.assert_allclose(unit_vector(e - s), [0.0, 1.0, 0.0], atol=1e-12)


def test_2_10_the_body_cone_has_the_half_angle_of_2_90() -> None:
    top = ps.FreeSymmetricTop(1.0, 0.5, [0.8, 0.0, 2.0])
    fig = pu.plot_body_cone(top)
    trace = np.array(one(fig, "omega-trace").get_data_3d()).T
    angles = np.arccos(trace[:, 2] / np.linalg.norm(trace, axis=1))
    np.testing.assert_allclose(angles, np.arctan(0.8 / 2.0), atol=1e-12)  # tan α_b = A/ω₃
    assert numbers(text_of(fig, "info").splitlines()[-1])[-1] == pytest.approx(21.80, abs=0.01)
    # Negative control: an oblate top has another cone.
    other = pu.plot_body_cone(ps.FreeSymmetricTop(1.0, 1.5, [0.8, 0.0, 2.0]))
    trace2 = np.array(one(other, "omega-trace").get_data_3d()).T
    assert np.arccos(trace2[0, 2] / np.linalg.norm(trace2[0])) == pytest.approx(np.arctan(0.4))


def test_2_11_and_2_15_are_the_existing_pictures_of_the_classroom_tops() -> None:
    assert UNIT_FIGURES["2.11"].function is plots.plot_cones
    assert UNIT_FIGURES["2.15"].function is plots.plot_effective_potential
    top = UNIT_FIGURES["2.11"].arguments()["top"]
    assert top.body_cone_angle == pytest.approx(np.arctan(0.4))


def test_2_12_the_steps_compose_to_euler_to_matrix() -> None:
    phi, theta, psi = np.radians([40.0, 55.0, 30.0])
    expected = {"a": rz(phi), "b": rz(phi) @ rx(theta), "c": rz(phi) @ rx(theta) @ rz(psi)}
    expected["d"] = expected["c"]
    drawn = {}
    for step in "abcd":
        fig = unit_figure(f"2.12{step}")
        drawn[step] = np.column_stack([ends3d(fig, f"step-{k}")[1] for k in (1, 2, 3)])
        np.testing.assert_allclose(drawn[step], expected[step], atol=1e-12)
    np.testing.assert_allclose(drawn["d"], ps.euler_to_matrix([phi, theta, psi]), atol=1e-12)
    # Step by step: each is the one before turned about its own new axis (intrinsic).
    np.testing.assert_allclose(drawn["b"], drawn["a"] @ rx(theta), atol=1e-12)
    np.testing.assert_allclose(drawn["c"], drawn["b"] @ rz(psi), atol=1e-12)
    # Negative control: the extrinsic order is another attitude.
    assert not np.allclose(drawn["d"], rz(psi) @ rx(theta) @ rz(phi), atol=1e-3)
    with pytest.raises(ps.PoinsotError, match="step: "):
        pu.plot_euler_angle_steps(step="e")


def test_2_13_omega_resolved_along_xi_eta_zeta_is_2_98() -> None:
    phi, theta, psi = np.radians([40.0, 55.0, 30.0])
    pd, td, sd = np.radians([40.0, 30.0, 60.0])
    fig = pu.plot_omega_components([40, 55, 30], [40, 30, 60])
    lines = text_of(fig, "info").splitlines()
    # Eq. 2.98 in closed form: ω_ξ = θ̇, ω_η = φ̇ sin θ, ω_ζ = ψ̇ + φ̇ cos θ.
    for line, value in zip(lines[1:4], (td, pd * np.sin(theta), sd + pd * np.cos(theta))):
        assert shown(numbers(line.split("=")[-1])[0], value, 4)
    # The drawn ω is φ̇ Z + θ̇ ξ + ψ̇ ζ: the head-to-tail chain ends at its tip.
    xi = rz(phi) @ [1.0, 0.0, 0.0]
    zeta = rz(phi) @ rx(theta) @ [0.0, 0.0, 1.0]
    w = pd * np.array([0.0, 0.0, 1.0]) + td * xi + sd * zeta
    _, e = ends3d(fig, "omega")
    np.testing.assert_allclose(e, w / np.linalg.norm(w), atol=1e-12)
    np.testing.assert_allclose(ends3d(fig, "psi_dot")[1], e, atol=1e-12)
    body = (rz(phi) @ rx(theta) @ rz(psi)).T @ w  # 2.99
    assert all(shown(a, b, 4) for a, b in zip(numbers(lines[-1].split("=")[-1])[:3], body))


def test_2_14_the_top_leans_at_its_nutation_angle() -> None:
    top = ps.HeavyTop(1.0, 0.5, 1.0, 0.8, phi_dot=0.5, psi_dot=6.0)
    t = 1.2
    fig = pu.plot_heavy_top(top, t)
    phi, theta, _ = top.euler_angles(t)
    axis = np.array(one(fig, "axis-3").get_data_3d())[:, 1]
    expected = [np.sin(phi) * np.sin(theta), -np.cos(phi) * np.sin(theta), np.cos(theta)]
    np.testing.assert_allclose(axis / 1.25, expected, atol=1e-12)  # R_z(φ) R_x(θ) e_z
    path = np.array(one(fig, "tip-path").get_data_3d()).T
    t1, t2 = top.turning_points
    nut = np.arccos(np.clip(path[:, 2] / np.linalg.norm(path, axis=1), -1, 1))
    assert nut.min() >= t1 - 1e-9 and nut.max() <= t2 + 1e-9  # between the circles θ₁, θ₂
    assert nut.max() - nut.min() > 0.9 * (t2 - t1)  # and it nods over the whole band


def test_2_15_the_minimum_of_V_is_the_steady_precession_angle() -> None:
    top = UNIT_FIGURES["2.15"].arguments()["top"]
    fig = unit_figure("2.15")
    # The curve of V: the line whose values are the top's effective potential.
    curves = [
        ln
        for ln in fig.axes[0].get_lines()
        if len(ln.get_xdata()) > 50
        and np.allclose(ln.get_ydata(), top.effective_potential(ln.get_xdata()), rtol=1e-12)
    ]
    assert len(curves) == 1
    x, y = np.asarray(curves[0].get_xdata()), np.asarray(curves[0].get_ydata())
    drawn_min = x[np.argmin(y)]
    # 2.114 in closed form, (p_φ − p_ψ cos θ)(p_ψ − p_φ cos θ) = m g l I₁ sin⁴θ, by bisection
    # between the turning points, where the minimum lies.
    f = lambda th: (
        (top.p_phi - top.p_psi * np.cos(th)) * (top.p_psi - top.p_phi * np.cos(th))
        - top.mgl * top.I1 * np.sin(th) ** 4
    )
    lo, hi = top.turning_points
    assert f(lo) * f(hi) < 0
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(lo) * f(mid) > 0 else (lo, mid)
    theta0 = 0.5 * (lo + hi)
    assert abs(drawn_min - theta0) <= 1.01 * (x[1] - x[0])
    # At θ₀ one of the steady-precession rates (2.116) has this top's p_φ (2.104).
    slow, fast = ps.HeavyTop.steady_precession_rates(top.I1, top.I3, top.mgl, theta0, top.omega3)
    p_phi = [top.I1 * r * np.sin(theta0) ** 2 + top.p_psi * np.cos(theta0) for r in (slow, fast)]
    assert min(abs(p - top.p_phi) for p in p_phi) < 1e-9


# ---------------------------------------------------------------------------------------------
# The command line
# ---------------------------------------------------------------------------------------------
def run(*args: str) -> Any:
    return CliRunner().invoke(main, list(args))


def test_cli_writes_the_figure(tmp_path: Path) -> None:
    out = tmp_path / "coriolis.png"
    result = run("figure", "2.5", "--style", "slides", "--out", str(out))
    assert result.exit_code == 0, result.output
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    from PIL import Image

    image = Image.open(out)
    assert round(image.info["dpi"][0]) == 200 and image.size[0] > 2000
    assert str(out) in result.stdout


def test_cli_default_name(tmp_path: Path, monkeypatch: Any) -> None:
    monkeypatch.chdir(tmp_path)
    assert run("figure", "2.12a").exit_code == 0
    assert (tmp_path / "fig-2.12a.png").stat().st_size > 1000


def test_cli_lists_every_figure() -> None:
    result = run("figure", "--list")
    assert result.exit_code == 0
    listed = [line.split()[0] for line in result.stdout.splitlines()]
    assert listed == list(UNIT_FIGURES)
    assert "plot_earth_coriolis" in result.stdout


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        (["figure", "2.16"], "NUMBER: the unit has no figure '2.16'"),
        (["figure"], "NUMBER: missing"),
        (["figure", "--list", "2.5"], "--list"),
        (["figure", "2.5", "--out", "/no/such/folder/x.png"], "--out: no folder"),
        (["figure", "2.5", "--out", "x.nosuchkind"], "--out: matplotlib cannot write .nosuchkind"),
        (["figure", "2.5", "--style", "poster"], "--style"),
    ],
)
def test_cli_refuses_by_name(
    args: list[str], needle: str, tmp_path: Path, monkeypatch: Any
) -> None:
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(main, args, standalone_mode=True)
    assert result.exit_code == EXIT_USAGE
    assert needle in result.stderr
    assert result.stderr.count("\n") == 1 and result.stdout == ""
    assert list(tmp_path.iterdir()) == []


# ---------------------------------------------------------------------------------------------
# docs/figures.md
# ---------------------------------------------------------------------------------------------
_ROW = re.compile(r"^\| (2\.\d+[a-d]?) \| (.+?) \| `(\w+)` \| (—|`\?([^`]+)`) \| `(.+)` \|$")


def doc_rows() -> dict[str, tuple[str, str | None, str]]:
    text = (ROOT / "docs" / "figures.md").read_text(encoding="utf-8")
    rows = {}
    for line in text.splitlines():
        m = _ROW.match(line)
        if m:
            assert m.group(1) not in rows, f"{m.group(1)} twice in docs/figures.md"
            rows[m.group(1)] = (m.group(3), m.group(5), m.group(6))
    return rows


def test_the_docs_table_and_the_registry_agree() -> None:
    rows = doc_rows()
    assert list(rows) == list(UNIT_FIGURES)  # both ways, in the unit's order
    for number, (function, lab, call) in rows.items():
        entry = UNIT_FIGURES[number]
        assert function == entry.function.__name__, number
        assert lab == entry.lab, number
        assert call.startswith(function + "("), number


def test_the_docs_calls_draw() -> None:
    from matplotlib.figure import Figure

    namespace = {"ps": ps, **{n: getattr(plots, n) for n in plots.__all__}}
    for number, (_, _, call) in doc_rows().items():
        fig = eval(call, namespace)  # the documented one-liners, as a reader types them
        assert isinstance(fig, Figure), number


def test_readme_links_the_figures_page() -> None:
    assert "(docs/figures.md)" in (ROOT / "README.md").read_text(encoding="utf-8")
