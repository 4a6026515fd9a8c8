// The last line of defence (web/src/protect.js, issue 10 item 9): a trap of the WebAssembly
// instance becomes a PoinsotError and the instance is replaced, so that later calls work; the
// glue's own errors name the argument. Real traps are injected (wasm_core.mjs: an impossible
// allocation inside the instance aborts it, as a panic would) — the shipped module has no trapping
// export. In node; tests/lab.test.mjs shows the same in the page.
import { test } from "node:test";
import assert from "node:assert/strict";
import { armTrap, loadCore } from "./wasm_core.mjs";

const { raw, core } = await loadCore({ faults: true });

/** `fn` throws `name` with a message starting with `prefix`; returns the error. */
function throws(fn, name, prefix) {
  let thrown = null;
  try {
    fn();
  } catch (e) {
    thrown = e;
  }
  assert.ok(thrown, "no error");
  assert.equal(thrown.name, name, `${thrown.name}: ${thrown.message}`);
  assert.ok(thrown.message.startsWith(prefix), `"${thrown.message}" does not start with "${prefix}"`);
  return thrown;
}

test("a trap becomes a PoinsotError, the instance restarts, later calls work", () => {
  const before = core.coreStatus().restarts;
  const b = new core.FreeRigidBody([1, 2, 3], [0.3, 1, 0.2], []);
  const w1 = b.omega(1.5);
  armTrap("freerigidbody_omega");
  const e = throws(() => b.omega(1.5), "PoinsotError", "internal error: the WebAssembly core failed in FreeRigidBody.omega (unreachable)");
  assert.match(e.message, /please report it/);
  assert.ok(e.cause instanceof WebAssembly.RuntimeError);
  assert.equal(core.coreStatus().restarts, before + 1);
  assert.equal(core.coreStatus().lastInternalError, e.message);
  // The object belongs to the old instance: using it says so, freeing it does nothing.
  throws(() => b.omega(1.5), "PoinsotError", "this: the object was made before the WebAssembly core was restarted");
  throws(() => b.energy, "PoinsotError", "this: the object was made before");
  b.free();
  b.free();
  // A new object on the new instance gives the same numbers as before the trap.
  const again = new core.FreeRigidBody([1, 2, 3], [0.3, 1, 0.2], []);
  assert.deepEqual(again.omega(1.5), w1);
  // A stale object passed as an argument is named.
  const frame = new core.MovingFrame([0, 0, 0], [0, 0, 0], [0, 0, 0], [0, 0, 1], [0, 0, 0]);
  armTrap("version");
  throws(() => core.version(), "PoinsotError", "internal error: the WebAssembly core failed in version");
  throws(() => core.simulateParticle(frame, [1, 0, 0], [0, 0, 0], 1, [0, 1], 1, 0), "PoinsotError", "frame: the object was made before");
  assert.equal(typeof core.version(), "string");
});

test("every kind of export is guarded: constructors, static methods, getters, methods, functions", () => {
  const cases = [
    ["new HeavyTop", "heavytop_new", () => new core.HeavyTop(1, 0.5, 1, 0, 0.8, 0, 0, 0, 6)],
    ["HeavyTop.minSpin", "heavytop_minSpin", () => core.HeavyTop.minSpin(1, 0.5, 1, 0.3)],
    ["Earth.foucault", "earth_foucault", () => new core.Earth(1e-3, 6.371e6, 9.8).foucault(0.8, 10, 1, 0, 30, 11)],
    ["eulerToMatrix", "eulerToMatrix", () => core.eulerToMatrix([0.1, 0.2, 0.3], "zxz", true)],
  ];
  for (const [label, wasmName, call] of cases) {
    call();
    armTrap(wasmName);
    throws(call, "PoinsotError", `internal error: the WebAssembly core failed in ${label} (unreachable)`);
    assert.ok(call() !== undefined);
  }
  const top = new core.HeavyTop(1, 0.5, 1, 0, 0.8, 0, 0, 0, 6);
  armTrap("heavytop_energy");
  throws(() => top.energy, "PoinsotError", "internal error: the WebAssembly core failed in HeavyTop.energy");
  assert.ok(Number.isFinite(new core.HeavyTop(1, 0.5, 1, 0, 0.8, 0, 0, 0, 6).energy));
});

test("the glue's own errors name the argument", () => {
  const p = new core.SpringParticle(1, 2);
  throws(() => p.jacobiIntegral({}, [1, 0, 0], [0, 1, 0]), "TypeError", "frame: must be a MovingFrame, got an object");
  throws(() => core.simulateParticle(null, [1, 0, 0], [0, 0, 0], 1, [0, 1], 1, 0), "TypeError", "frame: must be a MovingFrame, got null");
  throws(() => core.simulateParticle(p, [1, 0, 0], [0, 0, 0], 1, [0, 1], 1, 0), "TypeError", "frame: must be a MovingFrame, got a SpringParticle");
  const frame = new core.MovingFrame([0, 0, 0], [0, 0, 0], [0, 0, 0], [0, 0, 1], [0, 0, 0]);
  frame.free();
  throws(() => frame.at(1), "PoinsotError", "this: the object was freed");
  throws(() => p.jacobiIntegral(frame, [1, 0, 0], [0, 1, 0]), "PoinsotError", "frame: the object was freed");
  // Classes the core's functions make have no constructor.
  throws(() => new core.Fall(), "TypeError", "Fall: has no constructor");
  // instanceof still holds through the guarded constructor.
  assert.ok(new core.MovingFrame([0, 0, 0], [0, 0, 0], [0, 0, 0], [0, 0, 1], [0, 0, 0]) instanceof core.MovingFrame);
  assert.ok(new core.Earth(1e-4, 6e6, 9.8).drop(10, 0.5) instanceof core.Fall);
  assert.equal(core.coreStatus().broken, false);
});

// Last, as it leaves the instance trapped: without the guard (the raw module's free functions are
// not guarded; its classes are, in place), the same injection is a genuine RuntimeError.
test("negative control: unguarded, the injected fault is a genuine trap", () => {
  armTrap("eulerToMatrix");
  assert.throws(() => raw.eulerToMatrix([0.1, 0.2, 0.3], "zxz", true), (e) => e instanceof WebAssembly.RuntimeError && e.message === "unreachable");
});
