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


POINSOT_SPIN_AXES = {"smallest": 0, "intermediate": 1, "largest": 2}


def poinsot_case(params: dict[str, Any], t: float) -> dict[str, Any]:
    """The Poinsot / tumbling-box scene: a uniform 1 kg box of sides a, b, c (m) along x, y, z,
    spun at ``spin`` rad/s about the axis of the smallest, intermediate or largest moment with
    ``eps``·spin on each of the other two axes (the page's set-up)."""
    rigid = poinsot.RigidBody.cuboid(1.0, [params["a"], params["b"], params["c"]])
    moments = np.diag(rigid.inertia).copy()
    axis = int(np.argsort(moments, kind="stable")[POINSOT_SPIN_AXES[params["axis"]]])
    spin, eps = float(params["spin"]), float(params["eps"])
    omega0 = np.full(3, eps * spin)
    omega0[axis] = spin
    body = poinsot.FreeRigidBody(moments, omega0)
    w, q = body.state(t)
    stab = poinsot.axis_stability(moments, spin)
    rho_body = body.contact_point(t, frame="body")
    rho = body.contact_point(t)
    normal = body.invariable_plane_normal
    d = body.invariable_plane_distance
    readouts = {
        "t": t,
        "moments": moments.tolist(),
        "spunAxis": axis,
        "stability": ", ".join(s.stability for s in stab),
        "stabilityRates": [s.rate for s in stab],
        "regime": body.regime,
        "period": body.period,
        "flipInterval": body.flip_interval,
        "omega": np.asarray(w).tolist(),
        "spinComponent": float(w[axis]),
        "attitude": np.asarray(q).tolist(),
        "planeDistance": d,
        "planeNormal": np.asarray(normal).tolist(),
        "contactPoint": np.asarray(rho).tolist(),
        "contactResidual": [2 * float(rigid.kinetic_energy(rho_body)) - 1, float(rho @ normal) / d - 1],
        "energy": body.energy,
        "energyNow": float(rigid.kinetic_energy(w)),
        "angularMomentum": float(np.linalg.norm(body.angular_momentum)),
        "angularMomentumNow": float(np.linalg.norm(rigid.angular_momentum(w))),
    }
    return {"scene": "poinsot", "params": params, "t": t, "readouts": readouts}


POINSOT = {"view": "Poinsot ellipsoid", "axis": "intermediate", "eps": 0.05, "spin": 4,
           "a": 0.24, "b": 0.16, "c": 0.04}


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
        poinsot_case(POINSOT, 3.3),  # near the separatrix, above it: flips about y
        poinsot_case({**POINSOT, "view": "tumbling box", "eps": 0.01, "spin": 6.5}, 11.75),
        poinsot_case({**POINSOT, "axis": "smallest", "eps": 0.3, "a": 0.1, "b": 0.3, "c": 0.18}, 40.0),
        poinsot_case({**POINSOT, "axis": "largest", "eps": 0.8, "spin": 2.5}, 0.0),
    ]


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "golden.json"
    with open(out, "w") as fh:
        json.dump({"tolerance": 1e-12, "cases": cases()}, fh, indent=1)
    print(f"wrote {out}")
