// Browser tests of the rotating-frames scene (scenes/frames.ts): two views drawn side by side,
// the acceleration split of 2.21 / 2.26–2.27 at round-off, the fictitious terms vanishing with
// ω = 0 (negative control), the invariants of a free particle, and seek.
//   cd web && PYTHON=$PWD/../.venv/bin/python node --test --test-concurrency=1 tests/frames.test.mjs
import { test } from "node:test";
import assert from "node:assert/strict";
import { startLab, open, pixels, readouts, state } from "./harness.mjs";

await startLab();

/** The sum of four terms and F/m are computed by different paths of the core (to_moving then
 * to_fixed): they agree to a few ulps of the largest term (~1 m/s² here). */
const ROUND_OFF = 1e-14;
/** The core integrates at rtol 1e-10 (the Python default); over one loop the free particle's
 * fixed-frame path stays within this of the straight line (measured ~1e-11). */
const INTEGRATION = 1e-8;

const query = (p) => "?" + new URLSearchParams({ scene: "frames", paused: "1", ...p });
const norm = (v) => Math.hypot(...v);
const sub = (a, b) => a.map((x, i) => x - b[i]);

test("both halves of the canvas are drawn, each with its own content", async () => {
  const { page, errors } = await open(query({ t: "2" }));
  const left = await pixels(page, 0, 0.5);
  const right = await pixels(page, 0.5, 1);
  for (const [name, half] of [["left", left], ["right", right]]) {
    assert.ok(half.busy > 0.05, `${name} half blank: ${JSON.stringify(half)}`);
    assert.ok(half.colours > 20, `${name} half has too few colours: ${JSON.stringify(half)}`);
  }
  // Each half renders its own camera: the halves are not copies of each other.
  const diff = await page.evaluate(() => {
    const src = document.querySelector("#view canvas");
    const c = document.createElement("canvas");
    c.width = 64; c.height = 32;
    const g = c.getContext("2d", { willReadFrequently: true });
    g.drawImage(src, 0, 0, src.width, src.height, 0, 0, 64, 32);
    const px = g.getImageData(0, 0, 64, 32).data;
    let d = 0;
    for (let y = 0; y < 32; y++) {
      for (let x = 0; x < 32; x++) {
        for (let k = 0; k < 3; k++) d += Math.abs(px[4 * (64 * y + x) + k] - px[4 * (64 * y + x + 32) + k]);
      }
    }
    return d / (32 * 32 * 3);
  });
  assert.ok(diff > 1, `the two halves look the same (mean difference ${diff})`);
  const labels = await page.evaluate(() => document.getElementById("overlay").textContent);
  assert.match(labels, /Fixed \(inertial\) frame/);
  assert.match(labels, /Rotating frame/);
  assert.deepEqual(errors, []);
  await page.close();
});

test("the four terms sum to the fixed-frame acceleration F/m at round-off, and follow 2.21", async () => {
  const cases = [
    { t: "2.5" },
    { omega: "-1.5", omegaDot: "0.3", stiffness: "2", r0: "0.6", speed: "0.4", launchAngle: "89", launch: "rotating frame", t: "6.25" },
    { omega: "2", omegaDot: "-0.5", stiffness: "4", t: "7.9" },
  ];
  for (const c of cases) {
    const { page, errors } = await open(query(c));
    const r = await readouts(page);
    const where = JSON.stringify(c);
    assert.ok(r.residual < ROUND_OFF, `${where}: residual ${r.residual}`);
    const sum = [0, 1, 2].map((i) => r.relative[i] + r.coriolis[i] + r.centripetal[i] + r.euler[i]);
    assert.ok(norm(sub(sum, r.sum)) < ROUND_OFF, `${where}: the sum readout`);
    assert.ok(norm(sub(r.sum, r.accelerationFixed)) < ROUND_OFF, `${where}: sum vs F/m`);
    // F/m = −(k/m) r' with m = 1 kg (Hooke, independent of the core).
    const k = Number(c.stiffness ?? 0);
    assert.ok(norm(sub(r.accelerationFixed, r.positionFixed.map((x) => -k * x))) < 1e-15, where);
    // The terms' sizes (rotation-invariant, so fixed or moving components alike), all in the
    // table's plane: |2ω×v| = 2|ω||v|, |ω×(ω×r)| = ω²|r|, |ω̇×r| = |ω̇||r|.
    const w = r.omegaNow, wd = Number(c.omegaDot ?? 0);
    const close = (a, b, what) => assert.ok(Math.abs(a - b) < 1e-12 * Math.max(1, b), `${where} ${what}: ${a} vs ${b}`);
    close(norm(r.coriolis), 2 * Math.abs(w) * r.speedRotating, "Coriolis");
    close(norm(r.centripetal), w * w * norm(r.positionRotating), "centripetal");
    close(norm(r.euler), Math.abs(wd) * norm(r.positionRotating), "Euler");
    // The centripetal term points at the axis.
    close(r.centripetal[0] * r.positionFixed[1] - r.centripetal[1] * r.positionFixed[0], 0, "centripetal ∥ r");
    assert.ok(r.centripetal[0] * r.positionFixed[0] + r.centripetal[1] * r.positionFixed[1] <= 0, `${where}: centripetal points inwards`);
    assert.deepEqual(errors, []);
    await page.close();
  }
});

test("with ω = 0 the Coriolis, centripetal and Euler terms vanish (negative control: ω = 1 has them)", async () => {
  const { page } = await open(query({ omega: "0", omegaDot: "0", stiffness: "1", t: "1.7" }));
  const still = await readouts(page);
  assert.deepEqual(still.coriolis.map(Math.abs), [0, 0, 0]);
  assert.deepEqual(still.centripetal.map(Math.abs), [0, 0, 0]);
  assert.deepEqual(still.euler.map(Math.abs), [0, 0, 0]);
  assert.deepEqual(still.positionFixed, still.positionRotating);
  assert.equal(still.speedFixed, still.speedRotating);
  // The same motion on a turning table has every term.
  await page.evaluate(() => {
    const input = document.querySelector('input[data-key="omega"]');
    input.value = "1";
    input.dispatchEvent(new Event("input"));
  });
  const turning = await readouts(page);
  assert.ok(norm(turning.coriolis) > 0.01 && norm(turning.centripetal) > 0.01, JSON.stringify(turning));
  assert.notDeepEqual(turning.positionFixed, turning.positionRotating);
  await page.close();
});

test("free particle: straight at constant speed when seen fixed, Jacobi integral kept only while ω̇ = 0", async () => {
  // r0 = (0.8, 0, 0), v0' = 0.6 (cos 150°, sin 150°, 0) in the fixed frame (the launch direction
  // in degrees, the lab's angle unit): it reaches the table's rim, where the loop restarts, at 2.68 s.
  const v0 = [0.6 * Math.cos((150 * Math.PI) / 180), 0.6 * Math.sin((150 * Math.PI) / 180), 0];
  const { page } = await open(query({ launchAngle: "150", t: "0" }));
  const jacobi = [];
  for (const t of [0, 1.25, 2.0, 2.6]) {
    await page.evaluate((x) => window.__lab.seek(x), t);
    const r = await readouts(page);
    const line = [0.8 + v0[0] * t, v0[1] * t, 0];
    assert.ok(norm(sub(r.positionFixed, line)) < INTEGRATION, `t=${t}: ${r.positionFixed} vs ${line}`);
    assert.ok(Math.abs(r.speedFixed - 0.6) < INTEGRATION, `t=${t}: speed ${r.speedFixed}`);
    assert.ok(Math.abs(r.energy - 0.18) < INTEGRATION, `t=${t}: E ${r.energy}`);
    jacobi.push(r.jacobi);
    if (t > 1) assert.ok(norm(sub(r.positionRotating, line)) > 0.1, `t=${t}: the rotating view must curve`);
  }
  for (const j of jacobi) assert.ok(Math.abs(j - jacobi[0]) < INTEGRATION, `Jacobi ${jacobi}`);
  await page.close();
  // Negative control: a table spinning up changes the Jacobi integral (the Euler force works).
  const spun = await open(query({ omegaDot: "0.3", t: "0" }));
  const j0 = (await readouts(spun.page)).jacobi;
  await spun.page.evaluate(() => window.__lab.seek(3));
  const j3 = (await readouts(spun.page)).jacobi;
  assert.ok(Math.abs(j3 - j0) > 1e-2, `J(0) = ${j0}, J(3) = ${j3}`);
  const text = await spun.page.evaluate(() => document.querySelector('dd[data-key="jacobi"]').textContent);
  assert.match(text, /not conserved/);
  await spun.page.close();
});

test("seek shows the state at t, the same as opening the page at t", async () => {
  // A bound orbit that stays on the table: the loop is the whole 8 s.
  const p = { omega: "1.2", omegaDot: "0.2", stiffness: "1.5", r0: "0.5", speed: "0.3", launch: "rotating frame" };
  const fresh = await open(query({ ...p, t: "3.4" }));
  const want = await readouts(fresh.page);
  await fresh.page.close();
  const { page } = await open(query({ ...p, t: "0.5" }));
  const before = await readouts(page);
  assert.notDeepEqual(before.positionFixed, want.positionFixed);
  await page.evaluate(() => window.__lab.seek(3.4));
  const got = await readouts(page);
  assert.equal(got.tau, 3.4);
  assert.deepEqual(got, want);
  // Back again: deterministic, no history.
  await page.evaluate(() => window.__lab.seek(0.5));
  assert.deepEqual(await readouts(page), before);
  await page.close();
});

test("the launch direction is in degrees; a link of the earlier lab (direction in rad) still opens at the same launch", async () => {
  const { page, errors } = await open(query({ launchAngle: "90", t: "0" }));
  const r = await readouts(page);
  // Launched along +y in the fixed frame at 0.6 m/s (cos 90° = 6e-17 is round-off).
  assert.ok(Math.abs(r.velocityFixed[0]) < 1e-12 && Math.abs(r.velocityFixed[1] - 0.6) < 1e-12, JSON.stringify(r.velocityFixed));
  assert.match(await page.locator("#controls label[data-key=launchAngle]").innerText(), /launch direction \(°\)\s*90\b/);
  const old = await open(query({ direction: "2.6", t: "0" }));
  assert.ok(Math.abs((await state(old.page)).params.launchAngle - (2.6 * 180) / Math.PI) < 1e-12);
  const v = (await readouts(old.page)).velocityFixed;
  assert.ok(Math.abs(v[0] - 0.6 * Math.cos(2.6)) < 1e-12 && Math.abs(v[1] - 0.6 * Math.sin(2.6)) < 1e-12, JSON.stringify(v));
  assert.deepEqual([...errors, ...old.errors], []);
  await page.close();
  await old.page.close();
});
