// The WebAssembly core in node, without a browser: loads the glue that `web/build.sh wasm` writes
// to web/src/wasm (wasm-bindgen --target web, instantiated with initSync), guarded by
// web/src/protect.js as the page does; reads the API surface (every export, its parameters and
// their types) from the generated TypeScript declarations; and injects real traps for the tests of
// the guard.
import { readFileSync } from "node:fs";
import path from "node:path";
import { fileURLToPath, pathToFileURL } from "node:url";

export const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), "../..");
/** The built glue: web/src/wasm, or $POINSOT_WASM_DIR (e.g. an older build, to show that a
 * regression test fails on it). */
export const WASM_DIR = process.env.POINSOT_WASM_DIR ?? path.join(repo, "web/src/wasm");

/** The raw export (e.g. "eulerToMatrix", "freerigidbody_contactPolhode") whose next call traps. */
let armed = null;

/** Makes the next call of the instance's raw export `name` trap inside the instance (see
 * `loadCore({ faults: true })`). */
export function armTrap(name) {
  armed = name;
}

/** Every instance made from now on (the first one and those of restarts) gets its exports wrapped:
 * a call of the export named by `armTrap` first asks the instance's own allocator for 4 GiB − 16
 * bytes, an impossible layout on wasm32, which aborts in Rust: a genuine `RuntimeError:
 * unreachable` raised inside the instance, as a panic or a failed allocation would. */
function injectFaults() {
  const Real = WebAssembly.Instance;
  if (Real.poinsotFaults) return;
  function Faulty(module, imports) {
    const instance = new Real(module, imports);
    const exports = {};
    for (const [name, value] of Object.entries(instance.exports)) {
      exports[name] = typeof value !== "function" ? value : function (...args) {
        if (armed === name) {
          armed = null;
          instance.exports.__wbindgen_malloc(0xfffffff0, 8);
        }
        return value.apply(this, args);
      };
    }
    return { exports };
  }
  Faulty.poinsotFaults = true;
  WebAssembly.Instance = Faulty;
}

/** The glue module (`raw`), instantiated, and its guarded exports (`core`, as the page has them;
 * null for a build without `__wbg_reset_state`). With `faults`, traps can be injected with
 * `armTrap`. */
export async function loadCore({ faults = false } = {}) {
  if (faults) injectFaults();
  const raw = await import(pathToFileURL(path.join(WASM_DIR, "poinsot_wasm.js")).href);
  raw.initSync({ module: readFileSync(path.join(WASM_DIR, "poinsot_wasm_bg.wasm")) });
  const { protect, errorNames } = await import(pathToFileURL(path.join(repo, "web/src/protect.js")).href);
  const core = typeof raw.__wbg_reset_state === "function" ? protect(raw) : null;
  return { raw, core, ERROR_NAMES: errorNames(raw) };
}

/** Whether `value` is one of the glue's classes. */
export const isClass = (value) => typeof value === "function" && /^class\b/.test(Function.prototype.toString.call(value));

/** Parameters `a: T, b: U` as `[{ name, type }]`. */
function params(list) {
  return list.split(",").map((p) => p.trim()).filter(Boolean).map((p) => {
    const i = p.indexOf(":");
    return { name: p.slice(0, i).trim().replace(/\?$/, ""), type: p.slice(i + 1).trim() };
  });
}

/** The API surface from the generated declarations: free functions and, per class, its
 * constructor (`null` when it has none), static methods, methods and getters, each with its
 * parameters `{ name, type }` (types: number, ArrayLike<number>, string, boolean, a class name). */
export function surface(dts = readFileSync(path.join(WASM_DIR, "poinsot_wasm.d.ts"), "utf8")) {
  const text = dts.replace(/\/\*[\s\S]*?\*\//g, "");
  const functions = {};
  const classes = {};
  let cls = null;
  for (const raw of text.split("\n")) {
    const line = raw.trim();
    let m;
    if ((m = line.match(/^export class (\w+) \{$/))) {
      cls = classes[m[1]] = { ctor: null, statics: {}, methods: {}, getters: [] };
    } else if (cls && line === "}") {
      cls = null;
    } else if (cls) {
      if ((m = line.match(/^constructor\((.*)\);$/))) cls.ctor = params(m[1]);
      else if ((m = line.match(/^static (\w+)\((.*)\): .*;$/))) cls.statics[m[1]] = params(m[2]);
      else if ((m = line.match(/^readonly (\w+): .*;$/))) cls.getters.push(m[1]);
      else if ((m = line.match(/^(\w+)\((.*)\): .*;$/)) && m[1] !== "free") cls.methods[m[1]] = params(m[2]);
    } else if ((m = line.match(/^export function (\w+)\((.*)\): .*;$/))) {
      functions[m[1]] = params(m[2]);
    }
  }
  return { functions, classes };
}
