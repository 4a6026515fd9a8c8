// Tests of the scene "Gyrocompass" (issue 26): its period, steaming errors (exact and small-angle)
// and latitude error are the Python API's Gyrocompass's (relative 1e-12), the period said in
// words ("settles in one swing every 84.4 min"); the heading it shows is the core's simulation,
// equal to Python's, and settles toward north; Foucault's free gyroscope drifts against the
// ground at Ω sin λ; the binding refuses a pole latitude, naming it.
import { test } from "node:test";
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import path from "node:path";
import { open, readouts, repo, startLab } from "./harness.mjs";
import { loadCore } from "./wasm_core.mjs";

const DEG = Math.PI / 180;
const KNOT = 1852 / 3600;
const INERTIA = [5, 10, 10]; // the scene's LAB_INERTIA

// --- the binding (node, no browser) ------------------------------------------------------------

test("Gyrocompass in JavaScript: Schuler's 84.4 min, and refusals naming their argument", async () => {
  const { raw } = await loadCore();
  const c = raw.Gyrocompass.schulerTuned(50 * DEG, 1.2, 0.3, INERTIA);
  // Schuler's period from its closed form 2π √(R/g) (the core's default Earth).
  const schuler = 2 * Math.PI * Math.sqrt(6.371e6 / 9.80665);
  assert.ok(Math.abs(c.period / schuler - 1) < 1e-14, `${c.period}`);
  assert.ok(Math.abs(c.period / 60 - 84.4) < 0.05);
  // The steaming error's closed form, and the small-angle form beside it.
  const g = 7.292115e-5 * 6.371e6 * Math.cos(50 * DEG);
  const [v, course] = [20 * KNOT, 30 * DEG];
  assert.ok(Math.abs(c.speedError(v, course) - Math.atan(v * Math.cos(course) / (g + v * Math.sin(course)))) < 1e-15);
  assert.ok(Math.abs(c.speedErrorSmallAngle(v, course) - v * Math.cos(course) / g) < 1e-15);
  const refused = (fn, re) => assert.throws(fn, (x) => x.name === "PoinsotError" && re.test(x.message), String(re));
  refused(() => raw.Gyrocompass.schulerTuned(90 * DEG, 1.2, 0.3, INERTIA), /^latitude: .*pole/);
  refused(() => new raw.Gyrocompass(Math.PI / 2, 40, 1.2, 0.3, INERTIA), /^latitude: .*pole/);
  refused(() => new raw.Gyrocompass(0.8, 0, 1.2, 0.3, INERTIA), /^angular_momentum: /);
  refused(() => raw.Gyrocompass.schulerTuned(0.8, 1.2, 0.3, [1, 2]), /^inertia: must hold 3/);
  refused(() => c.speedError(500, -Math.PI / 2), /^speed: /);
  refused(() => c.simulate(NaN, 0.3, 0, 0, 0, 11), /^duration: /);
  refused(() => raw.freeGyroscope(2, 0, 0, 100, 3600, 3), /^latitude: /);
  refused(() => raw.freeGyroscope(0.8, 0, 0, NaN, 3600, 3), /^spin: /);
  assert.throws(() => c.speedError("10", 0), (x) => x instanceof TypeError && /^speed: /.test(x.message));
  c.free();
});

test("Foucault's free gyroscope: seen from the ground a horizontal axis drifts clockwise at Ω sin λ; a polar axis stays put", async () => {
  const { raw } = await loadCore();
  const lat = 49 * DEG, omega = 7.292115e-5, hour = 3600;
  const q = raw.freeGyroscope(lat, 0, 0, 100, hour, 2);
  // The spin axis (body x) in ENU from the attitude at the end: [w, x, y, z].
  const [w, x, y, z] = q.slice(4);
  const ax = [1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)];
  const heading = Math.atan2(ax[0], ax[1]);
  // An independent prediction: the inertial axis fixed, the ground turned by Ω t about the
  // Earth's axis k = (0, cos λ, sin λ): seen from it, north turned by −Ω t (Rodrigues).
  const k = [0, Math.cos(lat), Math.sin(lat)], a = -omega * hour, n0 = [0, 1, 0];
  const kxn = [k[1] * n0[2] - k[2] * n0[1], k[2] * n0[0] - k[0] * n0[2], k[0] * n0[1] - k[1] * n0[0]];
  const kdn = k[1];
  const want = n0.map((v, i) => v * Math.cos(a) + kxn[i] * Math.sin(a) + k[i] * kdn * (1 - Math.cos(a)));
  // (Started at rest on the ground, the rotor's ω has the Earth's Ω across its axis: it nods by
  // about Ω/spin = 7×10⁻⁷ rad about the fixed direction.)
  want.forEach((v, i) => assert.ok(Math.abs(ax[i] - v) < 2e-6, `axis ${ax} vs ${want}`));
  // Its first-order drift is the unit's Ω sin λ (the cone about the pole bends it by 0.5 % in an hour).
  assert.ok(Math.abs(heading / (omega * Math.sin(lat) * hour) - 1) < 1e-2, `${heading / DEG}°`);
  assert.ok(heading > 0, "clockwise (east) in the north");
  const polar = raw.freeGyroscope(lat, 0, lat, 100, 6 * hour, 2).slice(4);
  const [pw, px, py, pz] = polar;
  const pa = [1 - 2 * (py * py + pz * pz), 2 * (px * py + pw * pz), 2 * (px * pz - pw * py)];
  assert.ok(Math.abs(Math.atan2(pa[0], pa[1])) < 2e-6 && Math.abs(Math.asin(pa[2]) - lat) < 2e-6, `${pa}`);
});

test("fixedAxisHeadingRate: the core's rate of a fixed axis's heading seen from the ground, against the free gyroscope's run", async () => {
  const { raw } = await loadCore();
  const lat = 49 * DEG, omega = 7.292115e-5;
  // A horizontal axis drifts at Ω sin λ; an axis at the celestial pole stays put.
  assert.ok(Math.abs(raw.fixedAxisHeadingRate(lat, 1.0, 0) - omega * Math.sin(lat)) < 1e-19);
  assert.ok(Math.abs(raw.fixedAxisHeadingRate(lat, 0, lat)) < 1e-19);
  // A tilted axis: the heading's rate by a central difference of the core's free-gyroscope run
  // (samples 60 s apart, the axis at heading 40° and tilt 20° at the middle one).
  const q = raw.freeGyroscope(lat, 40 * DEG, 20 * DEG, 100, 120, 3);
  const axis = (i) => {
    const [w, x, y, z] = q.slice(4 * i, 4 * i + 4);
    return [1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)];
  };
  const head = (a) => Math.atan2(a[0], a[1]);
  const mid = axis(1);
  const fd = (head(axis(2)) - head(axis(0))) / 120;
  const rate = raw.fixedAxisHeadingRate(lat, head(mid), Math.asin(mid[2]));
  assert.ok(Math.abs(fd / rate - 1) < 1e-3, `${fd} vs ${rate}`);
  assert.ok(Math.abs(rate / (omega * Math.sin(lat)) - 1) > 0.2, "a tilted axis turns at another rate (0.76 Ω sin λ here)");
  assert.throws(() => raw.fixedAxisHeadingRate(lat, 0, Math.PI / 2), (x) => /^tilt: /.test(x.message));
  assert.throws(() => raw.fixedAxisHeadingRate(2, 0, 0), (x) => /^latitude: /.test(x.message));
});

// --- the scene ---------------------------------------------------------------------------------

await startLab();

function python(latDeg, headingDeg, speedKn, courseDeg, damping, times) {
  const script = `
import json, sys, math, numpy as np, poinsot
lat, h0, kn, course, zeta = map(float, sys.argv[1:6]); times = json.loads(sys.argv[6])
c = poinsot.Gyrocompass.schuler_tuned(math.radians(lat), damping=zeta, inertia=(5, 10, 10))
v, C = kn * 1852 / 3600, math.radians(course)
run = c.simulate(5 * c.period, math.radians(h0), speed=v, course=C, samples=1201)
print(json.dumps({"period": c.period, "speedError": c.speed_error(v, C), "speedErrorSmallAngle": c.speed_error_small_angle(v, C),
  "settleError": c.settle_error, "groundSpeed": c.ground_speed,
  "heading": [float(np.interp(t, run.t, run.heading)) for t in times], "settledHeading": float(run.heading[-1])}))`;
  const py = process.env.PYTHON ?? path.join(repo, ".venv/bin/python");
  return JSON.parse(execFileSync(py, ["-c", script, String(latDeg), String(headingDeg), String(speedKn), String(courseDeg), String(damping), JSON.stringify(times)], { encoding: "utf8" }));
}

const shown = (page, key) => page.locator(`#readouts dd[data-key="${key}"]`).innerText();

test("gyrocompass: the readouts are the Python API's Gyrocompass's; the heading is the core's run and settles toward north", async () => {
  // minutesPerSecond 20: t s of the clock are 1200 t s of the run.
  const cases = [[50, 30, 0, 0, 0.3], [60, -40, 30, 20, 0.3], [-35, 20, 12, 250, 0.5]];
  for (const [lat, h0, kn, course, zeta] of cases) {
    const q = `scene=gyrocompass&latitude=${lat}&heading0=${h0}&speed=${kn}&course=${course}&damping=${zeta}&minutesPerSecond=20&paused=1`;
    const early = await open(`?${q}&t=0`);
    const late = await open(`?${q}&t=30`);
    const [r1, r2] = [await readouts(early.page), await readouts(late.page)];
    const py = python(lat, h0, kn, course, zeta, [r1.hours, r2.hours]);
    for (const key of ["period", "speedError", "speedErrorSmallAngle", "settleError", "groundSpeed"]) {
      const err = Math.abs(r1[key] - py[key]) / Math.max(Math.abs(py[key]), 1e-300);
      assert.ok(err <= 1e-12 || Math.abs(r1[key] - py[key]) <= 1e-15, `${q} ${key}: page ${r1[key]}, python ${py[key]}`);
    }
    assert.equal(await shown(early.page, "period"), "settles in one swing every 84.4 min");
    // The heading is the core's simulation (the same in wasm and natively up to the round-off of
    // 10⁴ steps), and it settles: started |h0| off north, after 10 h it is within a degree of
    // where the core says a compass settles (the latitude and steaming errors).
    assert.ok(Math.abs(r1.heading - py.heading[0]) < 1e-7 && Math.abs(r2.heading - py.heading[1]) < 1e-7, `${r1.heading} ${py.heading}`);
    assert.ok(Math.abs(r1.heading - h0 * DEG) < 1e-12, "started off north by heading0");
    const settled = -py.settleError - py.speedError;
    assert.ok(Math.abs(r2.heading - settled) < 0.02 * Math.abs(h0 * DEG), `settled at ${r2.heading / DEG}°, core ${settled / DEG}°`);
    assert.deepEqual([...early.errors, ...late.errors], []);
    await early.page.close();
    await late.page.close();
  }
});

test("gyrocompass: Foucault's view shows the drift at Ω sin λ; a pole latitude is refused by name", async () => {
  const { page, errors } = await open("?scene=gyrocompass&view=Foucault%27s%20gyroscope&latitude=49&heading0=0&paused=1&t=0.5");
  const r = await readouts(page);
  assert.ok(Math.abs(r.driftRate / r.unitDriftRate - 1) < 1e-2, `${r.driftRate} vs ${r.unitDriftRate}`);
  assert.ok(Math.abs(r.unitDriftRate - 7.292115e-5 * Math.sin(49 * DEG)) < 1e-18);
  assert.ok(Math.abs(r.headingRate / r.unitDriftRate - 1) < 1e-2, "at the start the axis is horizontal");
  assert.deepEqual(errors, []);
  await page.close();
  // Half a sidereal day on, the axis (fixed among the stars) has risen off the horizontal and its
  // heading turns at another rate; the drift readout stays the horizontal axis's Ω sin λ.
  const later = await open("?scene=gyrocompass&view=Foucault%27s%20gyroscope&latitude=49&heading0=0&paused=1&minutesPerSecond=60&t=11.967");
  const q = await readouts(later.page);
  assert.ok(q.hours > 0.49 * 86164 && q.hours < 0.51 * 86164, `at ${q.hours} s`);
  assert.ok(Math.abs(q.driftRate / q.unitDriftRate - 1) < 1e-2, `${q.driftRate} vs ${q.unitDriftRate}`);
  assert.ok(Math.abs(q.headingRate / q.unitDriftRate - 1) > 0.05, `heading turns at ${q.headingRate} now`);
  assert.deepEqual(later.errors, []);
  await later.page.close();
  const { raw } = await loadCore();
  assert.throws(() => raw.Gyrocompass.schulerTuned(-Math.PI / 2, 1.2, 0.3, INERTIA), (x) => /^latitude: -90 degrees is a pole/.test(x.message));
});
