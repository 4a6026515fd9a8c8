// Issue 21 ("never wrong, round two") in the browser's core: the WebAssembly binding calls the
// same core functions as Python, so each fix must hold here too. In node on the raw module.
import { test } from "node:test";
import assert from "node:assert/strict";
import { loadCore } from "./wasm_core.mjs";

const { raw } = await loadCore();

test("item 1: a heavy top a hair from the hanging pole is not read as steady precession", () => {
  for (const delta of [1e-7, 1e-8, 1e-12, 4e-16]) {
    const top = new raw.HeavyTop(1, 0.5, 1, 0, Math.PI - delta, 0, 0, 0, 1);
    assert.equal(top.motionClass, "cusps", `delta = ${delta}`);
    // It reproduces its own initial state (it gave (4, 0, 5) for delta = 1e-8).
    const rates = Array.from(top.eulerRates([0]));
    assert.deepEqual(rates.map((x) => Math.abs(x) < 1e-12 ? 0 : x), [0, 0, 1], `delta = ${delta}: ${rates}`);
  }
  // Negative control: the top hanging exactly still hangs (no nutation to speak of).
  const hanging = new raw.HeavyTop(1, 0.5, 1, 0, Math.PI, 0, 0, 0, 1);
  assert.notEqual(hanging.motionClass, "cusps");
});

test("item 2: effective gravity that overflows is refused naming rotation_rate, never [0, -inf, inf]", () => {
  const fast = new raw.Earth(1e151, raw.Earth.meanRadius(), raw.Earth.standardGravity());
  let thrown = null;
  try {
    fast.effectiveGravity(0.5);
  } catch (e) {
    thrown = e;
  }
  assert.ok(thrown && !(thrown instanceof WebAssembly.RuntimeError), `${thrown}`);
  assert.match(thrown.message, /^rotation_rate: .*overflows/);
  // Negative control: at 1e150 the answer exists and is finite.
  const g = new raw.Earth(1e150, raw.Earth.meanRadius(), raw.Earth.standardGravity()).effectiveGravity(0.5);
  assert.ok(Array.from(g).every(Number.isFinite), `${Array.from(g)}`);
});

test("item 3: small third Euler angles of a symmetric sequence to relative accuracy", () => {
  // R = Rz(0.7) Ry(0.4) Rz(psi) for a tiny psi, built in doubles; the extraction must return psi
  // to a few ulps relative (it was a difference of larger angles: 1.3e-13 relative at -0.0034).
  const rz = (a) => [[Math.cos(a), -Math.sin(a), 0], [Math.sin(a), Math.cos(a), 0], [0, 0, 1]];
  const ry = (a) => [[Math.cos(a), 0, Math.sin(a)], [0, 1, 0], [-Math.sin(a), 0, Math.cos(a)]];
  const mul = (a, b) => a.map((row) => [0, 1, 2].map((j) => row.reduce((s, x, k) => s + x * b[k][j], 0)));
  for (const psi of [-0.0034, 1e-6, 1e-9]) {
    const r = mul(mul(rz(0.7), ry(0.4)), rz(psi)).flat();
    const e = raw.matrixToEuler(r, "zyz", true);
    const got = e.angles[2];
    assert.ok(Math.abs(got / psi - 1) < 1e-11, `psi = ${psi}: got ${got}`);
  }
});

test("item 14: the free bodies' maxTime is a finite time past which t is refused", () => {
  const b = new raw.FreeRigidBody([1, 2, 3], [1, 0.1, 1], []);
  assert.ok(Number.isFinite(b.maxTime) && b.maxTime > 1e9, `${b.maxTime}`);
});

test("item 15: fromMesh merges CAD corners that differ in the last bits when asked (mergeVertices)", () => {
  // A unit cube as a triangle soup (each face with its own corners), the copies of each corner a
  // few ulps apart as SolidWorks writes them.
  const corner = (i) => [i & 1, (i >> 1) & 1, (i >> 2) & 1];
  const faces = [0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5];
  const jitter = [0, 1e-16, -2e-16, 3e-16];
  const soup = faces.flatMap((i) => corner(i)).map((x, k) => x + jitter[k % 4]);
  const index = soup.map((_, k) => k).slice(0, 36);
  // Negative control: as given (and with false, the default) the soup is open.
  for (const merge of [undefined, false]) {
    assert.throws(() => raw.RigidBody.fromMesh(soup, index, 2, merge), (e) => e.name === "InvalidMeshError" && /open/.test(e.message));
  }
  const b = raw.RigidBody.fromMesh(soup, index, 2, true);
  assert.ok(Math.abs(b.mass - 2) < 1e-15, `${b.mass}`);
  const I = Array.from(b.inertia);
  I.forEach((x, k) => assert.ok(Math.abs(x - (k % 4 === 0 ? 2 / 6 : 0)) < 1e-15, `inertia[${k}] = ${x}`));
});
