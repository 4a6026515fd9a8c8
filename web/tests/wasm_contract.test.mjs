// The WebAssembly binding's argument contract (issue 10, the wasm halves of items 8, 9 and 12), in
// node on the raw wasm-bindgen module — no guard, no browser: the binding itself must refuse bad
// input with an error naming the argument, before any allocation or indexing, and never trap.
// Every case here trapped (`RuntimeError: unreachable`, `memory access out of bounds`) or was
// accepted silently before the fix; run against an older build with POINSOT_WASM_DIR=<dir>.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync, readdirSync } from "node:fs";
import path from "node:path";
import { loadCore, repo } from "./wasm_core.mjs";

const { raw } = await loadCore();
const earth = () => new raw.Earth(raw.Earth.siderealRate(), raw.Earth.meanRadius(), raw.Earth.standardGravity());
const body = () => new raw.FreeRigidBody([1, 2, 3], [0.3, 1, 0.2], []);

/** `fn` throws an error of class name `name` whose message starts with `prefix` — not a trap. */
function refuses(fn, name, prefix) {
  let thrown = null;
  try {
    fn();
  } catch (e) {
    thrown = e;
  }
  assert.ok(thrown, `no error (expected ${name} "${prefix}…")`);
  assert.ok(!(thrown instanceof WebAssembly.RuntimeError), `a trap: ${thrown}`);
  assert.equal(thrown.name, name, `${thrown.name}: ${thrown.message}`);
  if (name === "TypeError") assert.ok(thrown instanceof TypeError, "a TypeError must be a real TypeError");
  assert.ok(thrown.message.startsWith(prefix), `"${thrown.message}" does not start with "${prefix}"`);
  return thrown;
}

test("item 9: samples and parcels of -1, -2^31 and 1e9 are refused by name, never a trap", () => {
  const runs = {
    "Earth.foucault samples": (n) => earth().foucault(0.8, 10, 1, 0, 60, n),
    "Earth.flowIntoLow samples": (n) => earth().flowIntoLow(0.8, 5e5, 8, 1e-3, 1e-5, 1e5, n),
    "Earth.flowIntoLow parcels": (n) => earth().flowIntoLow(0.8, 5e5, n, 1e-3, 1e-5, 1e5, 11),
    "Earth.inertialOscillation samples": (n) => earth().inertialOscillation(0.7, [10, 0], 1e4, n),
    "FreeRigidBody.contactPolhode samples": (n) => body().contactPolhode(n),
  };
  for (const [what, run] of Object.entries(runs)) {
    const arg = what.split(" ")[1];
    for (const n of [-1, -(2 ** 31)]) refuses(() => run(n), "PoinsotError", `${arg}: must be a whole number >= 0, got ${n}`);
    // 1e9 is a whole number: refused by the memory budget, with the bytes it would need.
    const e = refuses(() => run(1e9), "PoinsotError", `${arg}: 1000000000 would need `);
    assert.match(e.message, /would need \d+ bytes \(\d+\.\d GB\) of output, more than the memory budget of 1073741824 bytes/);
  }
  // The instance is intact: the same calls with valid counts work.
  assert.equal(body().contactPolhode(5).length, 15);
  assert.equal(earth().foucault(0.8, 10, 1, 0, 60, 7).times().length, 7);
});

test("item 9: a non-string seq is a TypeError naming seq, not a memory access out of bounds", () => {
  refuses(() => raw.eulerToMatrix([0.1, 0.2, 0.3], 5, true), "TypeError", "seq: must be a string, got 5");
  for (const seq of [null, undefined, {}, ["zxz"]]) refuses(() => raw.matrixToEuler([1, 0, 0, 0, 1, 0, 0, 0, 1], seq, true), "TypeError", "seq: must be a string");
  // Negative control: a string works, and gives R_z(.1) R_x(.2) R_z(.3)'s first entry.
  const r = raw.eulerToMatrix([0.1, 0.2, 0.3], "zxz", true);
  assert.ok(Math.abs(r[0] - (Math.cos(0.1) * Math.cos(0.3) - Math.sin(0.1) * Math.cos(0.2) * Math.sin(0.3))) < 1e-15);
});

test("item 12: flags must be booleans, not read by truthiness or coerced", () => {
  for (const flag of ["no", "yes", 0, 1, null, undefined, "true"]) {
    refuses(() => raw.eulerToMatrix([0.1, 0.2, 0.3], "zxz", flag), "TypeError", "intrinsic: must be true or false, got ");
  }
  // Negative control: true and false give the two conventions, which differ here.
  assert.notDeepEqual(raw.eulerToMatrix([0.1, 0.2, 0.3], "zxz", true), raw.eulerToMatrix([0.1, 0.2, 0.3], "zxz", false));
});

test("item 12: counts must be whole numbers (2.5 is not 2), indices too", () => {
  refuses(() => earth().foucault(0.8, 10, 1, 0, 60, 2.5), "PoinsotError", "samples: must be a whole number >= 0, got 2.5");
  refuses(() => earth().flowIntoLow(0.8, 5e5, 2.5, 1e-3, 1e-5, 1e5, 11), "PoinsotError", "parcels: must be a whole number >= 0, got 2.5");
  refuses(() => body().contactPolhode(NaN), "PoinsotError", "samples: must be a whole number >= 0, got NaN");
  refuses(() => body().contactPolhode(Infinity), "PoinsotError", "samples: must be a whole number >= 0, got inf");
  refuses(() => body().contactPolhode("10"), "TypeError", 'samples: must be a number, got a string "10"');
  const low = earth().flowIntoLow(0.8, 5e5, 4, 1e-3, 1e-5, 1e4, 11);
  refuses(() => low.track(-1), "PoinsotError", "index: must be a whole number >= 0, got -1");
  refuses(() => low.track(4), "PoinsotError", "index: must be < 4 parcels, got 4");
  refuses(() => low.track(1.5), "PoinsotError", "index: must be a whole number >= 0, got 1.5");
  assert.equal(low.track(3).length, 2 * 11);
  // The minimum stays the core's (2 samples), after the whole-number check.
  refuses(() => body().contactPolhode(1), "PoinsotError", "samples: must be >= 2, got 1");
});

test("item 12: numbers must be numbers — no string, null or object coerced to one", () => {
  refuses(() => raw.RigidBody.solidSphere("2", 1), "TypeError", 'mass: must be a number, got a string "2"');
  refuses(() => raw.RigidBody.solidSphere(null, 1), "TypeError", "mass: must be a number, got null");
  refuses(() => raw.RigidBody.solidSphere(1, undefined), "TypeError", "radius: must be a number, got undefined");
  refuses(() => raw.RigidBody.solidSphere(1, [2]), "TypeError", "radius: must be a number, got an array of length 1");
  refuses(() => raw.RigidBody.solidSphere(1, 2n), "TypeError", "radius: must be a number, got a bigint");
  // NaN and ±Infinity are numbers: the core refuses them where they are not meaningful.
  refuses(() => raw.RigidBody.solidSphere(NaN, 1), "PoinsotError", "mass: must be finite and > 0, got NaN");
  refuses(() => body().omega(Infinity), "PoinsotError", "t: must be finite, got inf");
  assert.equal(raw.RigidBody.solidSphere(2, 1).mass, 2);
});

test("item 12: arrays must hold numbers; typed arrays of numbers are arrays too", () => {
  refuses(() => raw.eulerToMatrix(undefined, "zxz", true), "TypeError", "angles: must be an array of numbers, got undefined");
  refuses(() => raw.eulerToMatrix("abc", "zxz", true), "TypeError", 'angles: must be an array of numbers, got a string "abc"');
  refuses(() => raw.eulerToMatrix({ length: 3, 0: 1, 1: 2, 2: 3 }, "zxz", true), "TypeError", "angles: must be an array of numbers, got an object");
  refuses(() => raw.eulerToMatrix([0.1, "0.2", 0.3], "zxz", true), "TypeError", 'angles: must hold numbers, got a string "0.2" at index 1');
  refuses(() => raw.eulerToMatrix([[0.1, 0.2], [0.3]], "zxz", true), "TypeError", "angles: must hold numbers, got an array of length 2 at index 0");
  refuses(() => raw.eulerToMatrix([, 0.2, 0.3], "zxz", true), "TypeError", "angles: must hold numbers, got undefined at index 0");
  refuses(() => raw.eulerToMatrix(new BigInt64Array(3), "zxz", true), "TypeError", "angles: must hold numbers, got a BigInt64Array");
  refuses(() => raw.eulerToMatrix([0.1, 0.2], "zxz", true), "PoinsotError", "angles: must hold 3 numbers, got 2");
  // An accessor that throws while the array is read, and a revoked proxy: a TypeError, no unwinding
  // through the WebAssembly frames (the instance keeps working).
  const hostile = [0.1, 0.2, 0.3];
  Object.defineProperty(hostile, 1, { get() { throw new Error("boom"); } });
  refuses(() => raw.eulerToMatrix(hostile, "zxz", true), "TypeError", "angles: must be an array of numbers; reading it threw ");
  const { proxy, revoke } = Proxy.revocable([0.1, 0.2, 0.3], {});
  revoke();
  refuses(() => raw.eulerToMatrix(proxy, "zxz", true), "TypeError", "angles: must be an array of numbers; reading it threw ");
  // Typed arrays of numbers give the same matrix as the plain array.
  const want = raw.eulerToMatrix([0.5, 0.25, -1], "zxz", true);
  for (const T of [Float64Array, Float32Array]) assert.deepEqual(raw.eulerToMatrix(T.of(0.5, 0.25, -1), "zxz", true), want);
  assert.deepEqual(raw.eulerToMatrix(Int32Array.of(1, 2, 3), "zxz", true), raw.eulerToMatrix([1, 2, 3], "zxz", true));
});

test("item 8: arrays and the outputs they ask for are checked against the memory budget first", () => {
  // attitude(t): 104 bytes per time (the copy, the angles, the matrix): 1.2e7 times need 1.25 GB.
  const top = new raw.HeavyTop(1, 0.5, 1, 0, 0.8, 0, 0, 0, 6);
  const t = new Float64Array(12_000_000);
  const t0 = performance.now();
  refuses(() => top.attitude(t), "PoinsotError", "t: 12000000 would need 1248000000 bytes (1.2 GB) of output");
  // Refused before the copy: far faster than evaluating 1.2e7 attitudes (~15 s).
  assert.ok(performance.now() - t0 < 2000, `took ${performance.now() - t0} ms`);
  // Within the budget it works; a product of counts is checked as a product.
  assert.equal(top.attitude(new Float64Array(10)).length, 90);
  refuses(() => earth().flowIntoLow(0.8, 5e5, 20000, 1e-3, 1e-5, 1e5, 20000), "PoinsotError", "samples: 20000 parcels × 20000 samples would need ");
});

test("errors name the JavaScript argument, not the core's internal one", () => {
  // The core says R, times, t_end, state0; the JavaScript call has r, t_eval, height, length.
  refuses(() => raw.rotationAxis([2, 0, 0, 0, 1, 0, 0, 0, 1]), "InvalidRotationError", "r: ");
  const frame = new raw.MovingFrame([0, 0, 0], [0, 0, 0], [0, 0, 0], [0, 0, 1], [0, 0, 0.2]);
  refuses(() => raw.simulateParticle(frame, [1, 0, 0], [0, 0, 0], 1, [2], 1, 0), "PoinsotError", "t_eval: ");
  refuses(() => earth().drop(1e308, 0.5), "IntegrationError", "height: ");
  refuses(() => earth().foucault(0.8, 1e300, 1, 0, 60, 11), "PoinsotError", "amplitude: ");
  // A run too short to measure the plane is no longer an error: its regime says so (item 3).
  assert.equal(earth().foucault(0.8, 10, 1, 0, 1.5, 2).regime, "too_short");
  // A result too large for double precision names the call's arguments.
  // (ω̇ t²/2 of a frame at t = 1e300 s overflows: its attitude cannot be represented.)
  refuses(() => frame.at(1e300), "PoinsotError", "t: the frame's attitude at t = 1e300 s is not representable as finite numbers");
  refuses(() => raw.RigidBody.solidSphere(1e308, 1e154), "PoinsotError", "mass: the largest moment of inertia (kg·m²) would be about");
  const spring = new raw.SpringParticle(1, 1e308);
  refuses(() => spring.acceleration([10, 0, 0]), "PoinsotError", "position: the result (acceleration) is not a finite number");
  refuses(() => spring.energy([Number.NaN, 0, 0], [0, 0, 0]), "PoinsotError", "position: must be finite, got NaN");
});

test("the page imports the core only through src/core.ts (the guard), never the raw module", () => {
  const src = path.join(repo, "web/src");
  const files = [];
  const walk = (dir) => {
    for (const e of readdirSync(dir, { withFileTypes: true })) {
      if (e.isDirectory() && e.name !== "wasm") walk(path.join(dir, e.name));
      else if (/\.(ts|js)$/.test(e.name)) files.push(path.join(dir, e.name));
    }
  };
  walk(src);
  assert.ok(files.length > 10);
  const offenders = files.filter((f) => {
    if (f.endsWith(path.join("src", "core.ts"))) return false;
    const text = readFileSync(f, "utf8");
    // Any import of the raw glue but a type-only one.
    return [...text.matchAll(/import\s+(type\s+)?[^;]*?from\s+["'][^"']*wasm\/poinsot_wasm(\.js)?["']/g)].some((m) => !m[1]);
  });
  assert.deepEqual(offenders, []);
});
