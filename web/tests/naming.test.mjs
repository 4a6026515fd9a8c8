// The naming contract (docs/naming.md), JavaScript half: each JavaScript name in its "Types" table
// is an export of the wasm module (a class, a function, or a member of a class), and each row of
// "Argument orders" has the same parameters in the same order as the Python binding's function
// (python/tests/test_naming.py checks those against the core's source).
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import { execFileSync } from "node:child_process";
import path from "node:path";
import { loadCore, repo, surface } from "./wasm_core.mjs";

const { raw } = await loadCore();
const api = surface();

/** The rows of the table under `## title` in docs/naming.md (backticks removed). */
function table(title) {
  const text = readFileSync(path.join(repo, "docs/naming.md"), "utf8");
  const section = text.split(`## ${title}\n`)[1].split("\n## ")[0];
  const rows = section.split("\n").filter((l) => l.startsWith("|"));
  return rows.slice(2).map((r) => r.trim().replace(/^\||\|$/g, "").split("|").map((c) => c.trim().replaceAll("`", "")));
}

/** Whether `name` ("HeavyTop", "HeavyTop.motionClass", "Earth.siderealRate", "errorClasses")
 * exists in the module. */
function exists(name) {
  const [head, member] = name.split(".");
  const value = raw[head];
  if (value === undefined) return false;
  if (member === undefined) return true;
  if (member === "constructor") return api.classes[head]?.ctor != null;
  return member in value || (value.prototype !== undefined && member in value.prototype);
}

test("every JavaScript name of the naming contract is an export of the wasm module", () => {
  const rows = table("Types");
  assert.ok(rows.length > 50, "the table was read");
  const missing = rows.filter(([, , js]) => js !== "—").filter(([, , js]) => !exists(js)).map(([core, , js]) => `${core} → ${js}`);
  assert.deepEqual(missing, []);
  for (const [core, , js, notes] of rows) if (js === "—") assert.ok(notes, `${core}: not in JavaScript, and no reason given`);
});

test("a misspelt name is not found (negative control)", () => {
  assert.equal(exists("HeavyTop.motion_class"), false);
  assert.equal(exists("HeavyTopCore"), false);
  assert.equal(exists("FreeRigidBody.constructor"), true);
});

test("the argument orders of JavaScript are those of the Python binding", () => {
  const rows = table("Argument orders");
  const python = process.env.PYTHON ?? path.join(repo, ".venv/bin/python");
  const script = `
import inspect, json, sys
sys.path.insert(0, sys.argv[1])
from poinsot import _core
from test_naming import _binding_groups
out = {}
for name in sys.argv[2:]:
    obj = _core
    for part in name.split("."):
        obj = getattr(obj, part)
    ps = [p for p in inspect.signature(obj).parameters.values() if p.name != "self"]  # a method, unbound
    # A tuple parameter (the heavy top's top = (I1, I3, mgl)) stands for the names its binding
    # unpacks it into (python/tests/test_naming.py reads them from the binding's source).
    groups = _binding_groups(name)
    names = [groups.get(p.name, [p.name]) for p in ps]
    out[name] = {"all": [n for group in names for n in group],
                 "required": sum(len(g) for p, g in zip(ps, names) if p.default is inspect.Parameter.empty)}
print(json.dumps(out))`;
  const py = JSON.parse(execFileSync(python, ["-c", script, path.join(repo, "python", "tests"), ...rows.map((r) => r[1])], { encoding: "utf8" }));
  const norm = (s) => s.replaceAll("_", "").toLowerCase();
  for (const [core, pyName, jsName] of rows) {
    const [cls, member] = jsName.split(".");
    const c = api.classes[cls];
    assert.ok(c, `${jsName}: no class ${cls}`);
    const params = member === "constructor" ? c.ctor : c.statics[member] ?? c.methods[member];
    assert.ok(params, `${jsName}: not found`);
    // JavaScript takes every parameter Python requires, in the same order, and may take the
    // optional ones that follow (as an empty array where Python's default is None).
    const { all, required } = py[pyName];
    assert.ok(params.length >= required && params.length <= all.length, `${core}: ${jsName} has ${params.length} parameters, _core.${pyName} ${required}..${all.length}`);
    assert.deepEqual(params.map((p) => norm(p.name)), all.slice(0, params.length).map(norm), `${core}: ${jsName} vs _core.${pyName}`);
  }
});
