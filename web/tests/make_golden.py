"""Write the parity golden file of the browser lab: for fixed scene parameters, the numbers the
page must display, computed here by the Python API (issue 6: "the numbers the page displays for
fixed parameters equal the Python API's to 1e-12").

Each case names the page's URL parameters and the readouts (by their `data-key`) expected for
them. The parameter → argument mapping is the page's (degrees × π/180, angle + rate × t), so a
mismatch is a difference in the numbers, not in the set-up.

    python web/tests/make_golden.py web/tests/golden.json
"""

from __future__ import annotations

import json
import math
import sys
import warnings
from typing import Any

import numpy as np

import poinsot
from poinsot.errors import GimbalLockWarning, PoinsotError

DEG = math.pi / 180


def euler_case(params: dict[str, Any], t: float) -> dict[str, Any]:
    seq, intrinsic = params["seq"], params["convention"] == "intrinsic"
    deg = [params["phi"] + params["phiDot"] * t, params["theta"] + params["thetaDot"] * t,
           params["psi"] + params["psiDot"] * t]
    angles = [a * DEG for a in deg]
    rates = [params["phiDot"] * DEG, params["thetaDot"] * DEG, params["psiDot"] * DEG]
    R = poinsot.euler_to_matrix(angles, seq, intrinsic=intrinsic)
    axis, angle = poinsot.rotation_axis(R)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        recovered = poinsot.matrix_to_euler(R, seq, intrinsic=intrinsic)
    lock = any(issubclass(w.category, GimbalLockWarning) for w in caught)
    omega = poinsot.body_angular_velocity(angles, rates, seq, intrinsic=intrinsic)
    readouts: dict[str, Any] = {
        "angles": angles,
        "R": np.asarray(R).reshape(9).tolist(),
        "axis": np.asarray(axis).tolist(),
        "angle": float(angle),
        "recovered": np.asarray(recovered).tolist(),
        "gimbalLock": lock,
        "omegaBody": np.asarray(omega).tolist(),
    }
    try:
        readouts["ratesFromOmega"] = np.asarray(poinsot.euler_rates(angles, omega, seq, intrinsic=intrinsic)).tolist()
    except PoinsotError as exc:
        readouts["ratesFromOmega"] = {"error": type(exc).__name__}
    return {"scene": "euler", "params": params, "t": t, "readouts": readouts}


def free_top_case(params: dict[str, Any], t: float) -> dict[str, Any]:
    top = poinsot.FreeSymmetricTop(params["I1"], params["I3"], [params["w1"], 0.0, params["w3"]])
    readouts = {
        "t": t,
        "shape": top.shape,
        "omega": np.asarray(top.omega(t)).tolist(),
        "attitude": np.asarray(top.attitude(t)).tolist(),
        "precessionRate": top.precession_rate,
        "amplitude": top.amplitude,
        "bodyConeAngle": top.body_cone_angle,
        "spaceConeAngle": top.space_cone_angle,
        "energy": top.energy,
        "angularMomentum": top.angular_momentum_magnitude,
    }
    return {"scene": "freetop", "params": params, "t": t, "readouts": readouts}


def drop_case(params: dict[str, Any], t: float) -> dict[str, Any]:
    rate = poinsot.earth.SOLAR_DAY_RATE if params["rate"] == "solar day" else poinsot.earth.SIDEREAL_RATE
    earth = poinsot.Earth(rate)
    h, lat = params["height"], params["latitude"] * DEG
    fall = earth.drop(h, lat)
    first = float(earth.eastward_deflection(h, lat))
    readouts = {
        "time": fall.time,
        "east": fall.east,
        "north": fall.north,
        "eastFirstOrder": first,
        "ratio": fall.east / first,
        "foucaultRate": float(earth.foucault_rate(lat)),
    }
    return {"scene": "drop", "params": params, "t": t, "readouts": readouts}


def heavytop_case(params: dict[str, Any], t: float) -> dict[str, Any]:
    """The heavy top (2.102–2.121): the page's preset → initial state (θ̇₀ = 0 and φ̇₀ a fraction of
    the slow steady-precession rate; sleeping: θ₀ = 0; custom: the sliders), then the readouts."""
    i1, i3, mgl, w3 = params["I1"], params["I3"], params["mgl"], params["w3"]
    theta0 = params["theta0"] * DEG
    preset = params["preset"]
    theta_dot0, phi_dot0 = 0.0, 0.0
    if preset == "sleeping":
        theta0 = 0.0
    elif preset == "custom":
        theta_dot0, phi_dot0 = params["thetaDot0"], params["phiDot0"]
    elif preset != "cusps":
        slow = poinsot.HeavyTop.steady_precession(i1, i3, mgl, theta0, w3).slow
        phi_dot0 = {"loops": -0.5, "waves": 0.5, "steady precession": 1.0}[preset] * slow
    top = poinsot.HeavyTop.from_spin(i1, i3, mgl, theta0, w3, theta_dot=theta_dot0, phi_dot=phi_dot0)
    phi, theta, psi = top.euler_angles(t)
    phi_dot, theta_dot, psi_dot = top.euler_rates(t)
    now = poinsot.HeavyTop.constants_of_state(i1, i3, mgl, theta, theta_dot, phi_dot, psi_dot)
    init = top.initial_state
    min_spin = poinsot.HeavyTop.min_spin(i1, i3, mgl, theta0)
    steady: list[float] = []
    if abs(w3) >= min_spin:
        steady = list(poinsot.HeavyTop.steady_precession_rates(i1, i3, mgl, theta0, w3))
    readouts = {
        "t": t,
        "angles": [phi, theta, psi],
        "rates": [phi_dot, theta_dot, psi_dot],
        "motionClass": top.motion_class,
        "initialRates": [init["phi_dot"], init["theta_dot"], init["psi_dot"]],
        "omega3": top.omega3,
        "turningPoints": list(top.turning_points),
        "nutationPeriod": top.nutation_period,
        "meanPrecessionRate": top.mean_precession_rate,
        "steadyRates": steady,
        "minSpin": min_spin,
        "sleepingThreshold": poinsot.HeavyTop.sleeping_threshold(i1, i3, mgl),
        "sleepsStably": top.is_sleeping_stable,
        "energy": top.energy,
        "energyNow": now["energy"],
        "pPhi": top.p_phi,
        "pPhiNow": now["p_phi"],
        "pPsi": top.p_psi,
        "pPsiNow": now["p_psi"],
        "reducedEnergy": top.reduced_energy,
        "potentialNow": top.effective_potential(theta),
    }
    return {"scene": "heavytop", "params": params, "t": t, "readouts": readouts}


HEAVYTOP = {"preset": "loops", "w3": 9, "theta0": 50, "phiDot0": 0.5, "thetaDot0": 0, "mgl": 1.5,
            "I1": 1, "I3": 0.5}


EULER = {"seq": "zxz", "convention": "intrinsic", "phi": 30, "theta": 40, "psi": 20,
         "phiDot": 20, "thetaDot": 0, "psiDot": 45}


def cases() -> list[dict[str, Any]]:
    return [
        euler_case(EULER, 0.0),
        euler_case({**EULER, "seq": "xyz", "convention": "extrinsic", "thetaDot": -7}, 1.75),
        euler_case({**EULER, "seq": "zyz", "theta": 0, "thetaDot": 0}, 0.0),  # gimbal lock
        euler_case({**EULER, "seq": "zyx", "theta": 90, "thetaDot": 0}, 0.0),  # Tait–Bryan lock
        free_top_case({"I1": 1, "I3": 0.4, "w1": 0.6, "w3": 2}, 2.5),  # prolate
        free_top_case({"I1": 1, "I3": 1.7, "w1": 1.2, "w3": -0.8}, 7.125),  # oblate
        drop_case({"height": 100, "latitude": 45, "rate": "sidereal", "exaggeration": "1000"}, 0.0),
        drop_case({"height": 455, "latitude": -33, "rate": "solar day", "exaggeration": "10"}, 0.0),
        heavytop_case(HEAVYTOP, 3.7),  # loops
        heavytop_case({**HEAVYTOP, "preset": "cusps", "w3": 12, "theta0": 30}, 5.25),
        heavytop_case({**HEAVYTOP, "preset": "waves", "mgl": 2, "I1": 1.2, "I3": 0.7}, 1.1),
        heavytop_case({**HEAVYTOP, "preset": "steady precession", "theta0": 120}, 2.0),
        heavytop_case({**HEAVYTOP, "preset": "sleeping", "w3": 7}, 1.0),
        heavytop_case({**HEAVYTOP, "preset": "custom", "theta0": 100, "phiDot0": -1.2, "thetaDot0": 0.7}, 4.0),
    ]


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "golden.json"
    with open(out, "w") as fh:
        json.dump({"tolerance": 1e-12, "cases": cases()}, fh, indent=1)
    print(f"wrote {out}")
