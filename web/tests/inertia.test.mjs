// Browser tests of the inertia scene: every shape against its textbook moments; STL upload
// (binary and ASCII) of a closed box against the closed form and against the Python API's
// RigidBody.from_mesh(..., merge_vertices=True); an open STL refused with the core's
// InvalidMeshError (negative control); the screw motion recomposed to round-off (Chasles), the
// rotation about the CM (Euler) and the invariance of the principal moments along the motion.
import { test } from "node:test";
import assert from "node:assert/strict";
import { spawnSync } from "node:child_process";
import { mkdtempSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import path from "node:path";
import { open, readouts, repo, startLab, state } from "./harness.mjs";

await startLab();

/** Relative tolerance of closed forms evaluated in double precision (a few ulps of each term). */
const CLOSED_FORM_RTOL = 1e-13;
/** Round-off of Rodrigues' formula, the screw extraction and one composition (a few eps × O(1)). */
const ROUND_OFF = 1e-14;

const close = (a, b, rtol, what) => {
  const x = [a].flat(), y = [b].flat();
  assert.equal(x.length, y.length, what);
  x.forEach((v, i) => assert.ok(Math.abs(v - y[i]) <= rtol * Math.max(1, Math.abs(y[i])), `${what}[${i}]: ${v} vs ${y[i]}`));
};
const ascending = (v) => [...v].sort((p, q) => p - q);

// Textbook principal moments about the centre of mass (m mass; a, b, c the sliders' meaning).
const M = 2.5, A = 0.9, B = 1.4, C = 0.6;
const SHAPES = {
  cuboid: { kind: "asymmetric top", I: [(M / 12) * (B * B + C * C), (M / 12) * (A * A + C * C), (M / 12) * (A * A + B * B)] },
  sphere: { kind: "spherical top", I: [0.4 * M * A * A, 0.4 * M * A * A, 0.4 * M * A * A] },
  shell: { kind: "spherical top", I: [(2 / 3) * M * A * A, (2 / 3) * M * A * A, (2 / 3) * M * A * A] },
  cylinder: { kind: "symmetric top", I: [(M * (3 * A * A + B * B)) / 12, (M * (3 * A * A + B * B)) / 12, (M * A * A) / 2] },
  cone: { kind: "symmetric top", I: [(3 / 20) * M * A * A + (3 / 80) * M * B * B, (3 / 20) * M * A * A + (3 / 80) * M * B * B, 0.3 * M * A * A] },
  ellipsoid: { kind: "asymmetric top", I: [(M / 5) * (B * B + C * C), (M / 5) * (A * A + C * C), (M / 5) * (A * A + B * B)] },
  rod: { kind: "rotor", I: [(M * A * A) / 12, (M * A * A) / 12, 0] },
  disk: { kind: "symmetric top", I: [(M * A * A) / 4, (M * A * A) / 4, (M * A * A) / 2] },
  ring: { kind: "symmetric top", I: [(M * A * A) / 2, (M * A * A) / 2, M * A * A] },
};

test("inertia: every shape loads and shows its textbook moments and kind", async () => {
  for (const [shape, want] of Object.entries(SHAPES)) {
    const { page, errors } = await open(`?scene=inertia&shape=${shape}&mass=${M}&a=${A}&b=${B}&c=${C}&paused=1`);
    const s = await state(page);
    assert.equal(s.error, null, `${shape}: ${s.error}`);
    const r = await readouts(page);
    close(r.principalMoments, ascending(want.I), CLOSED_FORM_RTOL, `${shape} moments`);
    assert.equal(r.kind, want.kind, shape);
    assert.equal(r.mass, M);
    const text = await page.locator("#readouts").innerText();
    assert.ok(!/NaN|undefined|Infinity/.test(text), `${shape}: ${text}`);
    assert.match(await page.locator("#scene-extra").innerText(), new RegExp(`${shape}: `));
    assert.deepEqual(errors, [], shape);
    await page.close();
  }
});

// A closed box [x0, x0 + sides] as 12 outward triangles (counter-clockwise seen from outside).
const SIDES = [1, 2, 3], X0 = [0.5, -1, 2];
const CORNERS = Array.from({ length: 8 }, (_, i) => [0, 1, 2].map((k) => X0[k] + SIDES[k] * ((i >> k) & 1)));
const FACES = [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4], [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]];

function binaryStl(faces) {
  const buf = Buffer.alloc(84 + 50 * faces.length);
  buf.write("poinsot test box", 0);
  buf.writeUInt32LE(faces.length, 80);
  faces.forEach((f, k) => f.forEach((v, j) => CORNERS[v].forEach((x, i) => buf.writeFloatLE(x, 84 + 50 * k + 12 + 12 * j + 4 * i))));
  return buf;
}
function asciiStl(faces) {
  const lines = ["solid box"];
  for (const f of faces) {
    lines.push("  facet normal 0 0 0", "    outer loop");
    for (const v of f) lines.push(`      vertex ${CORNERS[v].join(" ")}`);
    lines.push("    endloop", "  endfacet");
  }
  lines.push("endsolid box");
  return lines.join("\n");
}

const dir = mkdtempSync(path.join(tmpdir(), "poinsot-stl-"));
const files = {
  binary: path.join(dir, "box.stl"),
  ascii: path.join(dir, "box-ascii.stl"),
  open: path.join(dir, "open.stl"),
};
writeFileSync(files.binary, binaryStl(FACES));
writeFileSync(files.ascii, asciiStl(FACES));
writeFileSync(files.open, binaryStl(FACES.slice(0, 11)));

/** The Python API's numbers for a binary STL: the triangle soup read with numpy, then
 * RigidBody.from_mesh(..., merge_vertices=True) (an independent parser and the Python path). */
function pythonMesh(file, density) {
  const python = process.env.PYTHON ?? path.join(repo, ".venv/bin/python");
  const code = `
import json, sys, numpy as np, poinsot
raw = open(sys.argv[1], "rb").read()
n = int(np.frombuffer(raw[80:84], "<u4")[0])
rec = np.frombuffer(raw[84:], dtype=np.dtype([("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")]), count=n)
soup = rec["v"].reshape(-1, 3).astype(np.float64)
b = poinsot.RigidBody.from_mesh(soup, np.arange(3 * n).reshape(-1, 3), float(sys.argv[2]), merge_vertices=True)
print(json.dumps({"mass": b.mass, "com": b.center_of_mass.tolist(), "inertia": b.inertia.reshape(9).tolist(),
                  "principalMoments": b.principal_moments.tolist(), "kind": b.kind}))`;
  const out = spawnSync(python, ["-c", code, file, String(density)], { encoding: "utf8" });
  assert.equal(out.status, 0, out.stderr);
  return JSON.parse(out.stdout);
}

/** Upload `file` (each with its own name) and wait until the scene has read it and reconfigured
 * (the status line names the file once the handler has run, just before the reconfiguration). */
async function upload(page, file) {
  await page.locator("#scene-extra input[type=file]").setInputFiles(file);
  const name = path.basename(file);
  await page.waitForFunction((n) => document.querySelector("[data-key=stlStatus]")?.textContent.startsWith(`${n}:`) && window.__lab.params.shape === "STL file", name);
}

test("inertia: an uploaded binary or ASCII STL box has the box's inertia (closed form and Python)", async () => {
  const rho = 250;
  const V = SIDES[0] * SIDES[1] * SIDES[2];
  const m = rho * V;
  const closed = [(m / 12) * (SIDES[1] ** 2 + SIDES[2] ** 2), 0, 0, 0, (m / 12) * (SIDES[0] ** 2 + SIDES[2] ** 2), 0, 0, 0, (m / 12) * (SIDES[0] ** 2 + SIDES[1] ** 2)];
  const py = pythonMesh(files.binary, rho);
  for (const kind of ["binary", "ascii"]) {
    const { page, errors } = await open(`?scene=inertia&density=${rho}&paused=1`);
    await upload(page, files[kind]);
    const s = await state(page);
    assert.equal(s.error, null, `${kind}: ${s.error}`);
    const r = await readouts(page);
    close(r.mass, m, CLOSED_FORM_RTOL, `${kind} mass`);
    close(r.com, X0.map((x, k) => x + SIDES[k] / 2), CLOSED_FORM_RTOL, `${kind} com`);
    r.inertia.forEach((x, i) => assert.ok(Math.abs(x - closed[i]) <= CLOSED_FORM_RTOL * m, `${kind} inertia[${i}]: ${x} vs ${closed[i]}`));
    assert.equal(r.kind, "asymmetric top");
    // Parity with the Python API (same core, independent parsing and merging): to 1e-12.
    for (const key of ["mass", "com", "inertia", "principalMoments"]) close(r[key], py[key], 1e-12, `${kind} ${key} vs python`);
    assert.equal(r.kind, py.kind);
    assert.match(await page.locator("#scene-extra").innerText(), /12 triangles, 8 distinct vertices/);
    // The file's unit scales lengths: in mm the box is 1000³ times lighter.
    await page.locator('#controls select[name="unit"]').selectOption("mm");
    close((await readouts(page)).mass, m * 1e-9, CLOSED_FORM_RTOL, `${kind} mass in mm`);
    assert.deepEqual(errors, []);
    await page.close();
  }
});

test("inertia: an open STL (one face removed) shows the core's InvalidMeshError", async () => {
  const { page, errors } = await open("?scene=inertia&paused=1");
  await upload(page, files.open);
  const alert = page.locator("#alert");
  assert.equal(await alert.isVisible(), true);
  const msg = await alert.innerText();
  assert.match(msg, /^InvalidMeshError: faces: the mesh is open: 3 boundary edge\(s\)/);
  assert.ok(!/NaN/.test(await page.locator("#readouts").innerText()));
  // Back to a closed file: the error clears.
  await upload(page, files.binary);
  assert.equal((await state(page)).error, null);
  assert.deepEqual(errors, []);
  await page.close();
});

test("inertia: STL chosen without a file says so (no numbers)", async () => {
  const { page, errors } = await open("?scene=inertia&shape=STL+file&paused=1");
  assert.match(String((await state(page)).error), /^PoinsotError: file: choose an STL file/);
  assert.deepEqual(errors, []);
  await page.close();
});

test("inertia: Chasles — the screw recomposes the displacement to round-off; the motion keeps the moments", async () => {
  const cases = ["phi=40&theta=65&psi=20&tx=1.5&ty=0.5&tz=1", "phi=-170&theta=120&psi=95&tx=-2.5&ty=3&tz=-0.4", "phi=3&theta=1&psi=-2&tx=0.1&ty=-2&tz=0.3"];
  for (const q of cases) {
    const { page, errors } = await open(`?scene=inertia&shape=cone&motion=Chasles&${q}&paused=1`);
    const r0 = await readouts(page);
    assert.ok(r0.residual <= ROUND_OFF, `${q}: residual ${r0.residual}`);
    // t = 0: the first pose; the middle of the motion; t = 4.5 s: the second pose (R, t).
    assert.equal(r0.s, 0);
    close(r0.pose, [1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0], 0, `${q} s=0`);
    for (const t of [1.3, 2.5, 4.5]) {
      await page.evaluate((x) => window.__lab.seek(x), t);
      const r = await readouts(page);
      assert.ok(r.momentDrift <= ROUND_OFF, `${q} t=${t}: drift ${r.momentDrift}`);
      // The CM starts at the origin, so it sits at t(s).
      close(r.movedCom, r.pose.slice(9), ROUND_OFF, `${q} CM at s`);
      if (t === 4.5) {
        assert.equal(r.s, 1);
        close(r.pose, [...r.R, ...r.translation], ROUND_OFF, `${q} s=1`);
      }
    }
    assert.deepEqual(errors, []);
    await page.close();
  }
});

test("inertia: Euler — a rotation about the CM has its screw axis through the CM and no slide", async () => {
  const { page, errors } = await open(`?scene=inertia&motion=${"Euler"}&phi=-120&theta=50&psi=75&paused=1&t=2.5`);
  const r = await readouts(page);
  assert.deepEqual(r.translation, [0, 0, 0]);
  close(r.screwPoint, [0, 0, 0], 0, "point");
  assert.ok(r.screwSlide === 0 && r.screwPitch === 0, `slide ${r.screwSlide}, pitch ${r.screwPitch}`); // ±0
  close(r.screwAxis, r.eulerAxis, 0, "screw axis = Euler axis");
  assert.equal(r.screwAngle, r.eulerAngle);
  // The CM stays put along the whole motion.
  close(r.movedCom, [0, 0, 0], ROUND_OFF, "CM fixed");
  assert.deepEqual(errors, []);
  await page.close();
});

test("inertia: playing animates the screw motion", async () => {
  const { page, errors } = await open("?scene=inertia&motion=Chasles");
  await page.evaluate(() => window.__lab.seek(0.6));
  const a = (await readouts(page)).pose;
  await page.waitForTimeout(400);
  const b = (await readouts(page)).pose;
  assert.notDeepEqual(a, b);
  assert.deepEqual(errors, []);
  await page.close();
});
