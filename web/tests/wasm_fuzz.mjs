// Fuzzing the WebAssembly core (issue 10, item 18, the wasm half): every exported function, class
// constructor, static method, method and getter — discovered from the module's exports, typed
// from its generated declarations, so that a new export is fuzzed the day it is added — is called
// with adversarial values (NaN, ±Infinity, ±1e308, subnormals, 0, negatives, fractions, huge
// counts, wrong types: strings, objects, undefined, null, arrays of the wrong length, typed
// arrays, ragged and sparse arrays, throwing accessors, non-boolean flags, objects of the wrong
// class, freed objects) mixed with plausible ones, through the same guard as the page
// (web/src/protect.js). The contract, asserted on every call:
//
//  * it returns, and every number it returns is finite (±Infinity only where documented, in
//    INFINITE below; NaN never), or
//  * it throws an `Error` whose name is one of the core's error classes or `TypeError` (a real
//    one) and whose message starts with `argument: ` naming one of the call's arguments or one the
//    receiver was made from ("this" for a freed object);
//  * never a `WebAssembly.RuntimeError`, never a restart of the instance, never an internal error;
//  * never a hang: the calls run in a worker thread, and a call that takes longer than
//    `deadlineMs` is reported as a hang (the worker is stopped).
//
// Library: `runFuzz({ seed, calls, deadlineMs })` (tests/wasm_fuzz.test.mjs runs a bounded,
// fixed-seed run in `make test-web`). Command line (`make fuzz-web`, a long run):
//   node web/tests/wasm_fuzz.mjs [--calls N] [--seed S] [--deadline-ms D]
import { Worker, isMainThread, parentPort, workerData } from "node:worker_threads";
import { fileURLToPath } from "node:url";
import { isClass, loadCore, surface } from "./wasm_core.mjs";

/** The members documented to return ±Infinity (never NaN), with the reason. */
export const INFINITE = {
  "Earth.inertialPeriod": "no inertial oscillation at the equator",
  "FreeRigidBody.period": "on the separatrix the motion never repeats",
  "FreeRigidBody.flipInterval": "half the period, infinite on the separatrix",
  "Screw.pitch": "a pure translation (angle 0)",
  "HeavyTop.nutationPeriod": "θ never returns (an unstable sleeping top)",
  "HeavyTop.precessionPeriod": "the axis does not turn on average (a sleeping or hanging top)",
  "HeavyTop.cubicRoots": "the third root u₃ when m g l = 0",
  "HeavyTop.effectivePotential": "V(θ) at a pole where its numerator does not vanish",
  "HeavyTop.effectivePotentialDerivative": "dV/dθ at a pole where V is infinite",
  "SteadyPrecession.fast": "the fast rate at θ₀ = π/2",
};

/** A call that takes longer than this (ms) is listed as slow in the report; it is not a failure
 * (a hang is a call longer than `deadlineMs`). */
const SLOW_MS = 1000;

// ---------------------------------------------------------------------------------------------
// The worker: the fuzz loop.

function mulberry32(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

const ROTATION = [0.36, -0.48, 0.8, 0.8, 0.6, 0, -0.48, 0.64, 0.6];
const IDENTITY = [1, 0, 0, 0, 1, 0, 0, 0, 1];
const CUBE_VERTICES = [0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1];
const CUBE_FACES = [0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5];

const PLAUSIBLE_NUMBERS = [0, 0.1, 0.5, 0.7, 1, 1.5, 2, 3, 6, 8, 10, 21, 60, 101, 1e-3, 1e-5, 5e5, 9.80665, 7.292115e-5, 6.371e6, -0.8, -1.2, 0.3];
const ADVERSARIAL_NUMBERS = [
  NaN, Infinity, -Infinity, 1e308, -1e308, Number.MAX_VALUE, 5e-324, -5e-324, 2.2250738585072014e-308, 1e-310, 0, -0,
  -1, -(2 ** 31), 2 ** 31, 2 ** 32, 2 ** 53, 2 ** 64, 1e9, 1e15, 2.5, -2.5, 1e6, 1e300, -1e-300, 1e-12, 1e154, 1e-160,
];
const PLAUSIBLE_ARRAYS = [
  [1, 2, 3], [0.3, 1, 0.2], [0, 0, 1], [0, 0, 0], [1, 0, 0], [0.1, 0.2, 0.3], [0, 0, 2], IDENTITY, ROTATION, [1, 0, 0, 0], [0.5, 0.5, 0.5, 0.5],
  [10, 0], [0, 0, 0, 0, 0, 0], [1, 2, 3, 0.1, 0.2, 0.3], [0, 0.5, 1, 2], [0, 1], [], [0.7], CUBE_VERTICES, CUBE_FACES,
];

/** A hostile array: reading element 1 throws. */
function throwingArray() {
  const a = [1, 2, 3];
  Object.defineProperty(a, 1, { get() { throw new Error("boom"); } });
  return a;
}
function revokedProxy() {
  const { proxy, revoke } = Proxy.revocable([1, 2, 3], {});
  revoke();
  return proxy;
}
const WRONG_TYPES = [undefined, null, "1", "abc", "", true, false, {}, [], [1], 1n, Symbol("s"), () => 1, new Date(0), /x/];

function worker({ seed, calls, deadlineMs }) {
  return loadCore().then(({ raw, core, ERROR_NAMES }) => {
    const rng = mulberry32(seed);
    const pick = (xs) => xs[Math.floor(rng() * xs.length)];
    const chance = (p) => rng() < p;
    const api = surface();

    // --- discovery: every export of the module, typed from the declarations --------------------
    const targets = [];
    const problems = [];
    for (const [name, value] of Object.entries(raw)) {
      if (name === "default" || name === "initSync" || name.startsWith("__")) continue;
      if (isClass(value)) {
        const decl = api.classes[name];
        if (!decl) { problems.push(`class ${name}: not in the declarations`); continue; }
        targets.push({ kind: "new", cls: name, label: `new ${name}`, params: decl.ctor ?? [] , noCtor: decl.ctor === null });
        for (const key of Object.getOwnPropertyNames(value)) {
          if (["length", "name", "prototype"].includes(key) || key.startsWith("__")) continue;
          if (!(key in decl.statics)) { problems.push(`${name}.${key}: static method not in the declarations`); continue; }
          targets.push({ kind: "static", cls: name, name: key, label: `${name}.${key}`, params: decl.statics[key] });
        }
        for (const key of Object.getOwnPropertyNames(value.prototype)) {
          if (key === "constructor" || key.startsWith("__")) continue;
          const d = Object.getOwnPropertyDescriptor(value.prototype, key);
          if (d.get) {
            if (!decl.getters.includes(key)) problems.push(`${name}.${key}: getter not in the declarations`);
            targets.push({ kind: "get", cls: name, name: key, label: `${name}.${key}`, params: [] });
          } else if (key === "free") {
            targets.push({ kind: "free", cls: name, name: key, label: `${name}.free`, params: [] });
          } else if (key in decl.methods) {
            targets.push({ kind: "method", cls: name, name: key, label: `${name}.${key}`, params: decl.methods[key] });
          } else problems.push(`${name}.${key}: method not in the declarations`);
        }
      } else if (typeof value === "function") {
        if (!(name in api.functions)) { problems.push(`${name}: function not in the declarations`); continue; }
        targets.push({ kind: "function", name, label: name, params: api.functions[name] });
      }
    }
    const classNames = Object.keys(api.classes);

    // --- instances: seeds, then whatever the calls return -------------------------------------
    /** Per class: live instances `{ obj, names }` (`names`: the arguments they were made from). */
    const pool = Object.fromEntries(classNames.map((c) => [c, []]));
    const freed = [];
    const POOL_MAX = 6;
    function adopt(obj, names) {
      const cls = classNames.find((c) => obj instanceof raw[c]);
      if (!cls) return;
      const list = pool[cls];
      list.push({ obj, names });
      if (list.length > POOL_MAX) list.splice(1 + Math.floor(rng() * (list.length - 1)), 1)[0].obj.free();
    }
    const names = (...n) => new Set(n.map((x) => x.toLowerCase()));
    const EARTH = () => new core.Earth(300 * 7.292115e-5, 6.371e6, 9.80665);
    const FRAME = () => new core.MovingFrame([0, 0, 0], [0, 0, 0], [0, 0, 0], [0, 0, 1], [0, 0, 0.2]);
    /** Valid calls that make an instance of every class: `[make, the argument names behind it]`. */
    const SEEDS = [
      [EARTH, names()],
      [() => new core.FreeRigidBody([1, 2, 3], [0.3, 1, 0.2], []), names()],
      [() => new core.FreeSymmetricTop(1, 2, [0.1, 0, 3]), names()],
      [() => new core.HeavyTop(1, 0.5, 1, 0, 0.8, 0, 0, 0, 6), names()],
      [() => core.HeavyTop.steadyPrecession(1, 0.5, 1.5, 0.7, 8), names()],
      [FRAME, names()],
      [() => new core.SpringParticle(1, 2), names()],
      [() => new core.RigidEarth(3.273795e-3, 7.292115e-5, 0.409), names()],
      // The averaged pole at three times (s), the node at 0.3 rad, the nod drawn ×1000.
      [() => new core.RigidEarth(3.273795e-3, 7.292115e-5, 0.409).averagedPole([0, 3e7, 6e8], 0.3, 1000), names("t", "moon_node", "nutation_scale")],
      [() => core.Gyrocompass.schulerTuned(0.87, 1.2, 0.3, [5, 10, 10]), names()],
      // A short run (ten minutes, 11 samples) of the compass started 5° off north on a ship.
      [() => core.Gyrocompass.schulerTuned(0.87, 1.2, 0.3, [5, 10, 10]).simulate(600, 0.087, 0, 5, 0.3, 11), names("duration", "heading0", "tilt0", "speed", "course", "samples")],
      [() => {
        // Thirty years of a pole on a 433-day and an annual circle, every 30 days (the core needs
        // the beat of the band's shortest period, 380 d, with the annual one: 25.7 years).
        const t = Array.from({ length: 366 }, (_, i) => i * 30 * 86400);
        const w = (p) => (2 * Math.PI) / (p * 86400);
        return core.fitWobble(t, t.map((s) => 1e-6 * Math.cos(w(433) * s) + 4e-7 * Math.cos(w(365.24) * s)), t.map((s) => -1e-6 * Math.sin(w(433) * s)));
      }, names("t", "x", "y")],
      [() => core.RigidBody.cuboid(1, [1, 2, 3]), names()],
      [() => core.matrixToEuler(ROTATION, "zxz", true), names()],
      [() => core.screwAxis(ROTATION, [1, 2, 3]), names()],
      [() => core.axisStability([1, 2, 3], 1), names()],
      [() => EARTH().drop(100, 0.7), names("height", "latitude")],
      [() => EARTH().foucault(0.8, 10, 1, 0, 30, 301), names("latitude", "length", "amplitude", "azimuth", "duration", "samples")],
      [() => EARTH().flowIntoLow(0.8, 5e5, 4, 1e-3, 1e-5, 2e4, 21), names("latitude", "radius", "parcels", "pull", "friction", "duration", "samples")],
      [() => EARTH().inertialOscillation(0.7, [10, 0], 2e3, 21), names("latitude", "velocity", "duration", "samples")],
      [() => FRAME().toFixed([1, 0, 0], [0, 1, 0], [0, 0, 0]), names("position", "velocity", "acceleration")],
      [() => FRAME().toMoving([1, 0, 0], [0, 1, 0], [0, 0, 0]), names("position", "velocity", "acceleration")],
    ];
    for (const [make, n] of SEEDS) adopt(make(), n);
    /** Makes an instance of `cls` from the seeds again (when the fuzz has freed the last one). */
    function reseed(cls) {
      for (const [make, n] of SEEDS) {
        const o = make();
        if (o instanceof raw[cls]) adopt(o, n);
        else o.free();
      }
    }

    // --- values ------------------------------------------------------------------------------
    const number = () => (chance(0.5) ? pick(PLAUSIBLE_NUMBERS) : chance(0.75) ? pick(ADVERSARIAL_NUMBERS) : pick(WRONG_TYPES));
    function array() {
      const r = rng();
      if (r < 0.45) return pick(PLAUSIBLE_ARRAYS).slice();
      if (r < 0.6) return Array.from({ length: pick([0, 1, 2, 3, 3, 3, 4, 6, 9, 12]) }, () => (chance(0.7) ? pick(PLAUSIBLE_NUMBERS) : pick(ADVERSARIAL_NUMBERS)));
      if (r < 0.7) {
        const a = pick(PLAUSIBLE_ARRAYS).slice();
        if (a.length) a[Math.floor(rng() * a.length)] = pick(ADVERSARIAL_NUMBERS);
        return a;
      }
      if (r < 0.8) {
        const a = pick(PLAUSIBLE_ARRAYS);
        const T = pick([Float64Array, Float32Array, Int32Array, Uint8Array, Int8Array]);
        return chance(0.15) ? new BigInt64Array(a.length) : T.from(a);
      }
      if (r < 0.9) {
        return pick([
          () => [[1, 2], [3]], () => [[1, 2, 3], [4, 5, 6], [7, 8, 9]], () => [1, "2", 3], () => [1, null, 3], () => [, 1, 2],
          () => ({ length: 3, 0: 1, 1: 2, 2: 3 }), throwingArray, revokedProxy, () => new Float64Array(pick([1e5, 1e6])),
          () => [1, 2, 3, 4, 5, 6, 7, 8, 9, 10].map(() => pick(ADVERSARIAL_NUMBERS)), () => new Array(5), () => "abc",
        ])();
      }
      return pick(WRONG_TYPES);
    }
    const string = () => (chance(0.5) ? pick(["zxz", "xyz", "zyx", "zyz", "xzx"]) : chance(0.7) ? pick(["", "ZXZ", "zxzz", "abc", "zz", "z\u0000x", "xyx", "😀😀😀", "zx z"]) : pick([5, null, undefined, true, {}, ["zxz"], 1n]));
    const boolean = () => (chance(0.7) ? chance(0.5) : pick(["no", "yes", 0, 1, null, undefined, "true", {}, []]));
    function instanceOf(cls) {
      const r = rng();
      if (r < 0.75 && pool[cls]?.length) return pick(pool[cls]);
      if (r < 0.8 && freed.length) return { obj: pick(freed), names: new Set() };
      const other = pick(classNames.filter((c) => c !== cls && pool[c].length));
      if (r < 0.9 && other) return pick(pool[other]);
      return { obj: pick([{}, null, undefined, 5, "frame"]), names: new Set() };
    }
    function value(type, names) {
      // An optional parameter (`T | null` in the declarations, e.g. fromMesh's mergeVertices):
      // left out or null now and then, otherwise a value as for T.
      if (type.endsWith(" | null")) return chance(0.2) ? pick([null, undefined]) : value(type.slice(0, -" | null".length), names);
      if (type === "number") return number();
      if (type === "ArrayLike<number>") return array();
      if (type === "string") return string();
      if (type === "boolean") return boolean();
      if (type in pool) {
        const inst = instanceOf(type);
        for (const n of inst.names) names.add(n);
        return inst.obj;
      }
      throw new Error(`fuzz: no generator for the type ${type}`);
    }

    // --- the contract ------------------------------------------------------------------------
    const violations = [];
    const counts = {};
    const outcomes = { ok: 0 };
    const slow = [];
    /** One report per member and kind of failure (the first call that showed it), and a count. */
    const seen = new Map();
    const violate = (label, desc, what) => {
      const key = `${label}: ${what.replace(/-?\d[\d.e+-]*/g, "#")}`;
      if (seen.has(key)) { seen.get(key).n++; return; }
      const v = { text: `${label}: ${what}\n    call: ${desc}`, n: 1 };
      seen.set(key, v);
      violations.push(v);
    };
    function finiteOrDocumented(label, x, desc) {
      if (typeof x === "number") {
        if (Number.isNaN(x)) violate(label, desc, "returned NaN");
        else if (!Number.isFinite(x) && !(label in INFINITE)) violate(label, desc, `returned ${x}`);
      } else if (ArrayBuffer.isView(x) || Array.isArray(x)) {
        for (const v of x) finiteOrDocumented(label, v, desc);
      } else if (!["string", "boolean", "undefined"].includes(typeof x) && !classNames.some((c) => x instanceof raw[c])) {
        violate(label, desc, `returned an unexpected value ${String(x)}`);
      }
    }
    const show = (x) => {
      try {
        if (typeof x === "string") return JSON.stringify(x);
        if (typeof x === "bigint") return `${x}n`;
        if (typeof x === "symbol" || typeof x === "function") return String(x);
        if (ArrayBuffer.isView(x)) return `${x.constructor.name}(${x.length > 12 ? `${x.length} elements` : Array.from(x).join(", ")})`;
        if (Array.isArray(x)) return x.length > 12 ? `[${x.length} elements]` : `[${x.map(show).join(", ")}]`;
        if (x && typeof x === "object") return classNames.find((c) => x instanceof raw[c]) ?? "{…}";
        return String(x);
      } catch {
        return "<hostile>";
      }
    };

    for (let i = 0; i < calls; i++) {
      const t = pick(targets);
      const allowed = new Set(t.params.map((p) => p.name.toLowerCase()));
      allowed.add("this");
      let self;
      if (t.kind === "method" || t.kind === "get" || t.kind === "free") {
        const freedHere = freed.filter((f) => f instanceof raw[t.cls]);
        if (chance(0.03) && freedHere.length) self = pick(freedHere);
        else {
          if (!pool[t.cls].length) { counts[`${t.label} (no instance)`] = (counts[`${t.label} (no instance)`] ?? 0) + 1; continue; }
          const inst = pick(pool[t.cls]);
          self = inst.obj;
          for (const n of inst.names) allowed.add(n);
        }
      }
      let args = t.params.map((p) => value(p.type, allowed));
      if (chance(0.03) && args.length) args = args.slice(0, -1);
      else if (chance(0.02)) args.push(pick(ADVERSARIAL_NUMBERS));
      const desc = `${t.kind === "method" || t.kind === "get" || t.kind === "free" ? `(${show(self)}).` : ""}${t.label}${t.kind === "get" ? "" : `(${args.map(show).join(", ")})`}`;
      parentPort.postMessage({ type: "call", i, desc });
      counts[t.label] = (counts[t.label] ?? 0) + 1;
      const t0 = performance.now();
      let result;
      let thrown = null;
      try {
        const Cls = core[t.cls];
        if (t.kind === "new") result = new Cls(...args);
        else if (t.kind === "static") result = Cls[t.name](...args);
        else if (t.kind === "function") result = core[t.name](...args);
        else if (t.kind === "get") result = self[t.name];
        else result = self[t.name](...args);
      } catch (e) {
        thrown = { e };
      }
      const ms = performance.now() - t0;
      if (ms > SLOW_MS) slow.push(`${ms.toFixed(0)} ms: ${desc}`);
      if (core.coreStatus().restarts > 0) {
        violate(t.label, desc, `the instance trapped and was restarted: ${core.coreStatus().lastInternalError}`);
        break;
      }
      if (thrown) {
        const { e } = thrown;
        if (e instanceof WebAssembly.RuntimeError) { violate(t.label, desc, `WebAssembly.RuntimeError: ${e.message}`); continue; }
        if (!(e instanceof Error)) { violate(t.label, desc, `threw a non-Error ${show(e)}`); continue; }
        if (!ERROR_NAMES.includes(e.name)) { violate(t.label, desc, `threw ${e.name}: ${e.message}`); continue; }
        if (e.name === "TypeError" && !(e instanceof TypeError)) violate(t.label, desc, "a TypeError that is not a TypeError");
        if (/internal error/.test(e.message)) violate(t.label, desc, e.message);
        // "argument: ..." or "argument, argument: ...".
        const named = e.message.match(/^(\w+(?:, \w+)*): /);
        if (t.noCtor && e.name === "TypeError" && e.message.startsWith(`${t.cls}: has no constructor`)) {
          // `new` on a class that the core's functions make: no argument to name.
        } else if (!named || !named[1].split(", ").every((n) => allowed.has(n.toLowerCase()))) {
          violate(t.label, desc, `${e.name} names no argument of the call (${[...allowed].join(", ")}): ${e.message}`);
        }
        outcomes[e.name] = (outcomes[e.name] ?? 0) + 1;
        continue;
      }
      outcomes.ok++;
      if (t.kind === "free") {
        if (self && pool[t.cls].some((p) => p.obj === self)) {
          pool[t.cls] = pool[t.cls].filter((p) => p.obj !== self);
          freed.push(self);
          if (freed.length > 20) freed.shift();
          // Keep every class fuzzable: a freed last instance is made again.
          if (!pool[t.cls].length) reseed(t.cls);
        }
        continue;
      }
      finiteOrDocumented(t.label, result, desc);
      if (result && typeof result === "object" && !ArrayBuffer.isView(result) && !Array.isArray(result)) adopt(result, allowed);
    }
    const uncovered = targets.filter((t) => !counts[t.label]).map((t) => t.label);
    const noInstance = classNames.filter((c) => !pool[c].length && !freed.some((f) => f instanceof raw[c]));
    return { targets: targets.length, calls, outcomes, counts, violations: violations.map((v) => `${v.text}${v.n > 1 ? ` (and ${v.n - 1} more)` : ""}`), problems, uncovered, noInstance, slow };
  });
}

if (!isMainThread && workerData?.poinsotFuzz) {
  worker(workerData).then(
    (report) => parentPort.postMessage({ type: "done", report }),
    (e) => parentPort.postMessage({ type: "crash", error: String(e?.stack ?? e) }),
  );
}

// ---------------------------------------------------------------------------------------------
// The main thread: a worker per run, and a watchdog.

/** Runs `calls` fuzz calls with `seed` in a worker; a call that takes more than `deadlineMs` is a
 * hang (the worker is stopped). Resolves to the worker's report, with `hang` set on a hang. */
export function runFuzz({ seed = 1, calls = 2000, deadlineMs = 30000 } = {}) {
  return new Promise((resolve, reject) => {
    const w = new Worker(fileURLToPath(import.meta.url), { workerData: { poinsotFuzz: true, seed, calls, deadlineMs } });
    let current = null;
    let since = performance.now();
    const watchdog = setInterval(() => {
      if (current && performance.now() - since > deadlineMs) {
        clearInterval(watchdog);
        w.terminate();
        resolve({ hang: `call ${current.i} ran for more than ${deadlineMs} ms: ${current.desc}`, violations: [], calls: current.i });
      }
    }, 100);
    w.on("message", (m) => {
      if (m.type === "call") {
        current = m;
        since = performance.now();
      } else if (m.type === "done") {
        clearInterval(watchdog);
        resolve(m.report);
        w.terminate();
      } else if (m.type === "crash") {
        clearInterval(watchdog);
        reject(new Error(`the fuzz worker crashed: ${m.error}`));
      }
    });
    w.on("error", (e) => { clearInterval(watchdog); reject(e); });
  });
}

/** The report as text. */
export function describeReport(r, seed) {
  const lines = [`seed ${seed}: ${r.calls} calls over ${r.targets} exports; outcomes ${JSON.stringify(r.outcomes)}`];
  if (r.hang) lines.push(`HANG: ${r.hang}`);
  for (const p of r.problems ?? []) lines.push(`PROBLEM: ${p}`);
  if (r.uncovered?.length) lines.push(`never called: ${r.uncovered.join(", ")}`);
  if (r.noInstance?.length) lines.push(`no instance made of: ${r.noInstance.join(", ")} (add a seed)`);
  for (const s of r.slow ?? []) lines.push(`slow: ${s}`);
  for (const v of r.violations) lines.push(`VIOLATION ${v}`);
  return lines.join("\n");
}

if (isMainThread && process.argv[1] === fileURLToPath(import.meta.url)) {
  const arg = (name, dflt) => {
    const i = process.argv.indexOf(`--${name}`);
    return i > 0 ? Number(process.argv[i + 1]) : dflt;
  };
  const seed = arg("seed", Math.floor(Math.random() * 2 ** 31));
  const calls = arg("calls", 100000);
  const deadlineMs = arg("deadline-ms", 30000);
  const t0 = performance.now();
  const report = await runFuzz({ seed, calls, deadlineMs });
  console.log(describeReport(report, seed));
  console.log(`${((performance.now() - t0) / 1000).toFixed(1)} s`);
  const bad = report.hang || report.violations.length || report.problems?.length || report.noInstance?.length;
  process.exit(bad ? 1 : 0);
}
