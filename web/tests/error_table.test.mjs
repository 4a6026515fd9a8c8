// One table of exception classes for both front ends (issue 11, item 2): the core maps each error
// kind to one class name (`ErrorKind::class_name`, crates/poinsot/src/error.rs); the WebAssembly
// binding throws an `Error` whose `name` it is, Python raises the class of that name
// (python/tests/test_error_table.py checks the same list). In node on the raw module.
import { test } from "node:test";
import assert from "node:assert/strict";
import { loadCore } from "./wasm_core.mjs";

const { raw, ERROR_NAMES } = await loadCore();

/** Every kind of core error and its class, in the core's order — the same list as in
 * python/tests/test_error_table.py. */
const EXPECTED = [
  ["InvalidArgument", "PoinsotError"],
  ["InvalidInertia", "InvalidInertiaError"],
  ["InvalidRotation", "InvalidRotationError"],
  ["InvalidMesh", "InvalidMeshError"],
  ["GimbalLock", "GimbalLockError"],
  ["Diverged", "IntegrationError"],
  ["Interrupted", "KeyboardInterrupt"],
];

test("the binding exposes the core's table, the same as Python's", () => {
  assert.deepEqual(raw.errorClasses(), EXPECTED);
  // The names the fuzz suite accepts are the core's classes, once each, and TypeError.
  assert.deepEqual(ERROR_NAMES, [...EXPECTED.map(([, name]) => name), "TypeError"]);
});

const earth = () => new raw.Earth(raw.Earth.siderealRate(), raw.Earth.meanRadius(), raw.Earth.standardGravity());

/** A real error of each kind the browser can throw (Interrupted needs a monitor: Python only). */
const TRIGGERS = {
  InvalidArgument: () => raw.RigidBody.solidSphere(-1, 1),
  InvalidInertia: () => raw.RigidBody.fromInertia(1, [1, 0, 0, 0, 1, 0, 0, 0, 3], [0, 0, 0]),
  InvalidRotation: () => raw.rotationAxis([1, 0, 0, 0, 1, 0, 0, 0, -1]),
  // A tetrahedron missing a face: open.
  InvalidMesh: () => raw.RigidBody.fromMesh([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1], [0, 2, 1, 0, 1, 3, 0, 3, 2], 1000),
  GimbalLock: () => raw.eulerRates([0.3, 0, 0.1], [0.5, 0.2, 3], "zxz", true),
  // A fall from 1e308 m: the step size of the integration underflows at once.
  Diverged: () => earth().drop(1e308, 0.5),
};

test("a real error of each kind throws its class", () => {
  for (const [kind, name] of EXPECTED) {
    if (!(kind in TRIGGERS)) continue;
    let thrown = null;
    try {
      TRIGGERS[kind]();
    } catch (e) {
      thrown = e;
    }
    assert.ok(thrown, `${kind}: no error`);
    assert.ok(!(thrown instanceof WebAssembly.RuntimeError), `${kind}: a trap: ${thrown}`);
    assert.equal(thrown.name, name, `${kind}: ${thrown.name}: ${thrown.message}`);
  }
});
