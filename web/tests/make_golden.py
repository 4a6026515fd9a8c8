"""Write the parity golden file of the browser lab: for fixed scene parameters, the numbers the
page must display, computed here by the Python API (issue 6: "the numbers the page displays for
fixed parameters equal the Python API's to 1e-12").

Each case names the page's URL parameters and the readouts (by their `data-key`) expected for
them. The parameter → argument mapping is the page's (each scene's angle unit: degrees × π/180
where its sliders are in degrees, radians as they are where they are in radians; angle + rate ×
t), so a mismatch is a difference in the numbers, not in the set-up.

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


FOUCAULT_DURATION, FOUCAULT_SAMPLES = 120.0, 2401  # web/src/scenes/foucault.ts
LOW_RADIUS, LOW_PARCELS, LOW_DURATION, LOW_SAMPLES = 5e5, 8, 2 * 86400.0, 481  # web/src/scenes/low.ts
LOW_SECONDS_PER_PAGE_SECOND, INERTIAL_SPEED, INERTIAL_EQUATOR_RUN = 3600.0, 10.0, 86400.0


def foucault_case(params: dict[str, Any], i: int) -> dict[str, Any]:
    """The Foucault scene at its i-th sample time (the page continues the integration between
    samples; on a sample it shows the sample, which Python's run holds too)."""
    earth = poinsot.Earth(poinsot.earth.SIDEREAL_RATE * float(params["spin"]))
    lat = params["latitude"] * DEG
    run = earth.foucault(lat, length=params["length"], amplitude=params["amplitude"], azimuth=0.0,
                         duration=FOUCAULT_DURATION, samples=FOUCAULT_SAMPLES)
    t = float(run.t[i])
    tt = run.turn_times
    j = earth.jacobi_integral(lat, run.position, run.velocity)
    readouts = {
        "tau": t,
        "position": run.position[i].tolist(),
        "expectedRate": run.expected_rate,
        "precessionRate": run.precession_rate,
        "sense": run.sense,
        "period": 2 * (tt[-1] - tt[0]) / (len(tt) - 1),
        "jacobi": float(j[i]),
        "jacobiDrift": float(j[i] - j[0]),
    }
    return {"scene": "foucault", "params": params, "t": t, "readouts": readouts}


def low_case(params: dict[str, Any], i: int) -> dict[str, Any]:
    """The low at its i-th sample (one page second is an hour of the run)."""
    earth = poinsot.Earth()
    lat = params["latitude"] * DEG
    flow = earth.flow_into_low(lat, radius=LOW_RADIUS, parcels=LOW_PARCELS, pull=params["pull"] * 1e-3,
                               friction=params["friction"] * 1e-5, duration=LOW_DURATION, samples=LOW_SAMPLES)
    tau = float(flow.t[i])
    period = float(earth.inertial_period(lat))
    osc = earth.inertial_oscillation(lat, [INERTIAL_SPEED, 0.0], duration=2 * period if math.isfinite(period) else INERTIAL_EQUATOR_RUN,
                                     samples=401)
    readouts: dict[str, Any] = {
        "tau": tau,
        "parcel": np.concatenate([flow.position[0, i], flow.velocity[0, i]]).tolist(),
        "circulation": flow.circulation,
        "sense": flow.sense,
        "coriolis": float(earth.coriolis_parameter(lat)),
        "inertialTurning": osc.turning_rate,
        "energy": float(np.mean(flow.energy[:, i])),
        "dissipated": float(np.mean(flow.dissipated[:, i])),
    }
    if math.isfinite(period):
        readouts["inertialPeriod"] = period
    return {"scene": "low", "params": params, "t": tau / LOW_SECONDS_PER_PAGE_SECOND, "readouts": readouts}


FRAMES_MASS = 1.0  # the page's particle mass (kg)
FRAMES_SAMPLES = 600  # the page's path samples (TRAIL_SAMPLES)
FRAMES_LOOP_MAX = 8.0  # the page's loop (s) at most
FRAMES_TABLE = 1.0  # the table's radius (m): the loop ends where the path first leaves it


def frames_case(params: dict[str, Any], t: float) -> dict[str, Any]:
    """The rotating-frames scene: the particle integrated in the turntable's frame by
    ``simulate_particle`` (spring force −k r as a callable, none when k = 0), mapped back with
    ``MovingFrame.at(t).to_fixed``; energies by NumPy (independent of the core's formulas)."""
    w, wd, k = params["omega"], params["omegaDot"], params["stiffness"]
    frame0 = poinsot.MovingFrame(angular_velocity=[0.0, 0.0, w], angular_acceleration=[0.0, 0.0, wd])
    r0 = np.array([params["r0"], 0.0, 0.0])
    d = math.radians(params["launchAngle"])  # the slider's degrees (the lab's angle unit) in rad
    launch = np.array([params["speed"] * math.cos(d), params["speed"] * math.sin(d), 0.0])

    def accel(x: np.ndarray) -> np.ndarray:
        return -k * x / FRAMES_MASS

    if params["launch"] == "rotating frame":
        v0rel = launch
    else:
        v0rel = frame0.to_moving(r0, launch, accel(r0)).velocity
    # The page's scheme: the path over FRAMES_LOOP_MAX at FRAMES_SAMPLES times; the loop ends at the
    # last sample before the path first leaves the table (the first sample interval if it leaves at
    # once), the path is sampled again over the loop; then from the last sample before tau to tau.
    n = FRAMES_SAMPLES
    force = None if k == 0 else (lambda _t, x, _v: -k * x)

    def grid(length: float) -> list[float]:
        return [length if i == n - 1 else length * i / (n - 1) for i in range(n)]

    loop = FRAMES_LOOP_MAX
    times = grid(loop)
    path = poinsot.simulate_particle(frame0, r0, v0rel, loop, t_eval=times, mass=FRAMES_MASS, force=force)
    out = np.flatnonzero(np.linalg.norm(path.position[1:], axis=1) > FRAMES_TABLE)
    if out.size:
        loop = times[max(1, int(out[0]))]
        times = grid(loop)
        path = poinsot.simulate_particle(frame0, r0, v0rel, loop, t_eval=times, mass=FRAMES_MASS, force=force)
    tau = t % loop
    i = min(n - 1, math.floor(tau / loop * (n - 1)))
    while i > 0 and times[i] > tau:
        i -= 1
    dt = tau - times[i]
    if dt == 0:
        r, v = path.position[i], path.velocity[i]
    else:
        traj = poinsot.simulate_particle(frame0.at(times[i]), path.position[i], path.velocity[i], dt, t_eval=[dt],
                                         mass=FRAMES_MASS, force=force)
        r, v = traj.position[0], traj.velocity[0]
    f = frame0.at(tau)
    fixed = f.to_fixed(r, v)
    a_true = accel(fixed.position)
    rel = f.to_moving(fixed.position, fixed.velocity, a_true)
    fx = f.to_fixed(r, v, rel.acceleration)
    terms = fx.acceleration_terms
    w_moving = f.attitude.T @ f.angular_velocity
    energy = 0.5 * FRAMES_MASS * fixed.velocity @ fixed.velocity + 0.5 * k * fixed.position @ fixed.position
    wxr = np.cross(w_moving, r)
    jacobi = 0.5 * FRAMES_MASS * (v @ v - wxr @ wxr) + 0.5 * k * r @ r
    readouts = {
        "tau": tau,
        "omegaNow": float(f.angular_velocity[2]),
        "positionFixed": fixed.position.tolist(),
        "positionRotating": np.asarray(r).tolist(),
        "velocityFixed": fixed.velocity.tolist(),
        "velocityRotating": np.asarray(v).tolist(),
        "speedFixed": float(np.linalg.norm(fixed.velocity)),
        "speedRotating": float(np.linalg.norm(v)),
        "relative": terms["relative"].tolist(),
        "coriolis": terms["coriolis"].tolist(),
        "centripetal": terms["centripetal"].tolist(),
        "euler": terms["euler"].tolist(),
        "sum": fx.acceleration.tolist(),
        "accelerationFixed": a_true.tolist(),
        "residual": float(np.linalg.norm(fx.acceleration - a_true)),
        "energy": float(energy),
        "jacobi": float(jacobi),
    }
    return {"scene": "frames", "params": params, "t": t, "readouts": readouts}


FRAMES = {"omega": 1, "omegaDot": 0, "stiffness": 0, "r0": 0.8, "speed": 0.6, "launchAngle": 149,
          "launch": "fixed frame"}

INERTIA_MOTIONS = ("Chasles", "Euler")


def inertia_fraction(t: float) -> float:
    """The page's clock of the screw motion (presentation): rest 0.5 s, move 4 s, rest; period 6 s."""
    tau = max(0.0, t) % 6.0
    return min(1.0, max(0.0, (tau - 0.5) / 4.0))


def inertia_body(p: dict[str, Any]) -> poinsot.RigidBody:
    m, a, b, c = p["mass"], p["a"], p["b"], p["c"]
    rb = poinsot.RigidBody
    return {
        "cuboid": lambda: rb.cuboid(m, [a, b, c]),
        "sphere": lambda: rb.solid_sphere(m, a),
        "shell": lambda: rb.spherical_shell(m, a),
        "cylinder": lambda: rb.solid_cylinder(m, a, b),
        "cone": lambda: rb.solid_cone(m, a, b),
        "ellipsoid": lambda: rb.ellipsoid(m, [a, b, c]),
        "rod": lambda: rb.thin_rod(m, a),
        "disk": lambda: rb.thin_disk(m, a),
        "ring": lambda: rb.thin_ring(m, a),
    }[p["shape"]]()


def inertia_case(params: dict[str, Any], t: float) -> dict[str, Any]:
    body = inertia_body(params)
    moments = np.asarray(body.principal_moments)
    R = poinsot.euler_to_matrix([params["phi"] * DEG, params["theta"] * DEG, params["psi"] * DEG], "zxz")
    tr = [0.0, 0.0, 0.0] if params["motion"] == INERTIA_MOTIONS[1] else [params["tx"], params["ty"], params["tz"]]
    axis, angle = poinsot.rotation_axis(R)
    screw = poinsot.screw_axis(R, tr)
    s = inertia_fraction(t)
    Rs, ts = screw.displacement_at(s)
    com = np.asarray(body.center_of_mass)
    moved = body.translated(-com).rotated(Rs).translated(ts)
    readouts = {
        "s": s,
        "pose": np.concatenate([np.asarray(Rs).reshape(9), ts]).tolist(),
        "movedCom": np.asarray(moved.center_of_mass).tolist(),
        "movedInertia": np.asarray(moved.inertia).reshape(9).tolist(),
        "mass": body.mass,
        "com": com.tolist(),
        "inertia": np.asarray(body.inertia).reshape(9).tolist(),
        "principalMoments": moments.tolist(),
        "principalAxes": np.asarray(body.principal_axes).reshape(9).tolist(),
        "kind": body.kind,
        # 2 x the second moments along the principal axes (independent of the core's method).
        "triangleMargins": [moments[1] + moments[2] - moments[0], moments[2] + moments[0] - moments[1],
                            moments[0] + moments[1] - moments[2]],
        "R": np.asarray(R).reshape(9).tolist(),
        "translation": tr,
        "eulerAxis": np.asarray(axis).tolist(),
        "eulerAngle": float(angle),
        "screwAxis": np.asarray(screw.axis).tolist(),
        "screwPoint": np.asarray(screw.point).tolist(),
        "screwAngle": screw.angle,
        "screwSlide": screw.slide,
        "screwPitch": screw.pitch,
    }
    return {"scene": "inertia", "params": params, "t": t, "readouts": readouts}


INERTIA = {"mass": 2, "shape": "cuboid", "a": 1.2, "b": 0.8, "c": 0.4, "density": 1000, "unit": "m",
           "motion": INERTIA_MOTIONS[0], "phi": 60, "theta": 30, "psi": 30, "tx": 2, "ty": 0, "tz": 0.8}
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
def heavytop_case(params: dict[str, Any], t: float) -> dict[str, Any]:
    """The heavy top (2.102–2.121): the page's preset → initial state (θ̇₀ = 0 and φ̇₀ a fraction of
    the slow steady-precession rate; sleeping: θ₀ = 0; custom: the sliders), then the readouts."""
    i1, i3, mgl, w3 = params["I1"], params["I3"], params["mgl"], params["w3"]
    theta0 = math.radians(params["tilt"])  # the slider's degrees (the lab's angle unit) in rad
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
        # inf where the axis does not turn on average: the page's value is then the string.
        "precessionPeriod": top.precession_period if math.isfinite(top.precession_period) else "Infinity",
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


#: A Julian year (s), the clock of the Earth-as-a-top scene; the Moon's node regresses in
#: 6798.38 days (JPL Horizons, Moon 301; the core's MOON_ORBIT.node_period, which the scene reads).
YEAR = 365.25 * 86400.0
ARCSEC = math.pi / 648000


def earthtop_case(params: dict[str, Any], t: float) -> dict[str, Any]:
    """The rigid Earth's rates from the Python API, and the axis at the lab's time t (s, each
    second ``yearsPerSecond`` years): the API's averaged pole (``RigidEarth.averaged_pole``:
    longitude ψ = |ψ̇| t + Δψ₀ sin Ω, obliquity ε + Δε₀ cos Ω, Ω = −2π t / T_node, the node at 0
    at the start), the real (not exaggerated) nod."""
    e = poinsot.RigidEarth(dynamical_flattening=params["flattening"], obliquity=params["obliquity"], degrees=True)
    years = t * params["yearsPerSecond"]
    ts = years * YEAR
    dpsi, deps = e.nutation_amplitudes
    pole = e.averaged_pole(ts, moon_node=0.0)
    psi, eps, node = float(pole.psi), float(pole.obliquity), float(pole.moon_node)
    readouts = {
        "years": years,
        "precessionPeriod": e.precession_period,
        "precessionRate": e.precession_rate,
        "precessionParts": list(e.precession_parts),
        "iau2006": -poinsot.IAU2006_PRECESSION_RATE,
        "nutation": [dpsi, deps],
        "eulerPeriod": e.euler_period,
        "chandlerPeriod": e.chandler_period(0.3, 0.938),
        "poleLongitude": math.radians(math.degrees(psi) % 360),
        "obliquityNow": eps,
        "node": math.radians(math.degrees(node) % 360),
    }
    return {"scene": "earthtop", "params": params, "t": t, "readouts": readouts}


EARTHTOP = {"flattening": 0.003273795, "obliquity": 23.44, "yearsPerSecond": 1000, "nod": "1000"}


#: The gyrocompass scene's element (kg·m²): ten times the core's default moments (the scene's
#: LAB_INERTIA), and a knot (m/s).
GYRO_INERTIA = (5.0, 10.0, 10.0)
KNOT = 1852 / 3600


def gyrocompass_case(params: dict[str, Any]) -> dict[str, Any]:
    """The Schuler-tuned compass's closed forms from the Python API, at t = 0 (the heading the
    run starts from; the run itself is the core's integration, checked to 1e-7 rad in
    web/tests/gyrocompass.test.mjs since wasm's and the native libm's round-offs part over 10⁴
    steps)."""
    c = poinsot.Gyrocompass.schuler_tuned(params["latitude"] * DEG, damping=params["damping"], inertia=GYRO_INERTIA)
    v, course = params["speed"] * KNOT, params["course"] * DEG
    readouts = {
        "hours": 0.0,
        "heading": params["heading0"] * DEG,
        "period": c.period,
        "schulerPeriod": poinsot.Gyrocompass.schuler_period(),
        "speedError": c.speed_error(v, course),
        "speedErrorSmallAngle": c.speed_error_small_angle(v, course),
        "settleError": c.settle_error,
        "groundSpeed": c.ground_speed,
    }
    return {"scene": "gyrocompass", "params": params, "t": 0.0, "readouts": readouts}


GYROCOMPASS = {"view": "compass", "latitude": 50, "heading0": 30, "speed": 0, "course": 0, "damping": 0.3,
               "minutesPerSecond": 20}


HEAVYTOP = {"preset": "loops", "w3": 9, "tilt": 50, "phiDot0": 0.5, "thetaDot0": 0, "mgl": 1.5,
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
        foucault_case({"latitude": 45, "length": 10, "amplitude": 1, "spin": "1000"}, 0),
        foucault_case({"latitude": -60, "length": 25, "amplitude": 2.5, "spin": "100"}, 1234),  # south
        foucault_case({"latitude": 0, "length": 10, "amplitude": 1, "spin": "1000"}, 2000),  # equator: no turn
        low_case({"latitude": 45, "pull": 1, "friction": 1}, 0),
        low_case({"latitude": -30, "pull": 2.5, "friction": 4}, 135),  # south: clockwise
        low_case({"latitude": 0, "pull": 1, "friction": 1}, 240),  # equator: no circulation
        frames_case(FRAMES, 0.0),
        frames_case(FRAMES, 2.5),  # free particle: straight when fixed, curved when rotating
        # Spinning up (Euler term) with a spring, launched across the table in its own frame.
        frames_case({**FRAMES, "omega": -1.5, "omegaDot": 0.3, "stiffness": 2, "r0": 0.6, "speed": 0.4,
                     "launchAngle": 89, "launch": "rotating frame"}, 6.25),
        frames_case({**FRAMES, "omega": 0, "stiffness": 1}, 1.7),  # no rotation: no fictitious terms
        inertia_case(INERTIA, 1.7),  # asymmetric top, mid-screw
        inertia_case({**INERTIA, "shape": "cone", "a": 0.5, "b": 1.5, "mass": 3.3}, 3.25),  # CM off the origin
        # Euler: a rotation about the CM of a lamina (I1 + I2 = I3), screw through the CM, pitch 0.
        inertia_case({**INERTIA, "shape": "disk", "motion": INERTIA_MOTIONS[1], "phi": -120, "psi": 75}, 5.5),
        inertia_case({**INERTIA, "shape": "rod", "a": 1.7, "theta": 180, "phi": 0, "psi": 0}, 2.5),  # rotor, half turn
        poinsot_case(POINSOT, 3.3),  # near the separatrix, above it: flips about y
        poinsot_case({**POINSOT, "view": "tumbling box", "eps": 0.01, "spin": 6.5}, 11.75),
        poinsot_case({**POINSOT, "axis": "smallest", "eps": 0.3, "a": 0.1, "b": 0.3, "c": 0.18}, 40.0),
        poinsot_case({**POINSOT, "axis": "largest", "eps": 0.8, "spin": 2.5}, 0.0),
        heavytop_case(HEAVYTOP, 3.7),  # loops
        heavytop_case({**HEAVYTOP, "preset": "cusps", "w3": 12, "tilt": 30}, 5.25),
        heavytop_case({**HEAVYTOP, "preset": "waves", "mgl": 2, "I1": 1.2, "I3": 0.7}, 1.1),
        heavytop_case({**HEAVYTOP, "preset": "steady precession", "tilt": 120}, 2.0),
        heavytop_case({**HEAVYTOP, "preset": "sleeping", "w3": 7}, 1.0),
        heavytop_case({**HEAVYTOP, "preset": "custom", "tilt": 100, "phiDot0": -1.2, "thetaDot0": 0.7}, 4.0),
        earthtop_case(EARTHTOP, 0.0),
        earthtop_case(EARTHTOP, 7.25),  # 7250 years: a quarter turn of the axis and more
        earthtop_case({**EARTHTOP, "flattening": 0.0121, "obliquity": 60, "yearsPerSecond": 3.5, "nod": "1"}, 2.5),
        gyrocompass_case(GYROCOMPASS),
        gyrocompass_case({**GYROCOMPASS, "latitude": 81, "speed": 50, "course": 0, "heading0": -20}),
        gyrocompass_case({**GYROCOMPASS, "latitude": -35, "speed": 12, "course": 250, "damping": 0.5}),
    ]


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "golden.json"
    with open(out, "w") as fh:
        json.dump({"tolerance": 1e-12, "cases": cases()}, fh, indent=1)
    print(f"wrote {out}")
