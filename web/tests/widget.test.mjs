// The notebook widget's front end (python/poinsot/widgets/static/widget.js, built from
// src/widget.ts) in chromium: a harness page served on loopback imports the module as anywidget
// does and calls its default export's render({ model, el }) with a fake model (get, set,
// save_changes, on, off); the slider ranges are checked against poinsot.widgets.SCENE_PARAMS.
import { test, after, before } from "node:test";
import assert from "node:assert/strict";
import http from "node:http";
import fs from "node:fs";
import path from "node:path";
import { execFileSync } from "node:child_process";
import { repo, launchChromium, collectErrors, pixels as canvasPixels } from "./harness.mjs";

const STATIC = path.join(repo, "python/poinsot/widgets/static");
const SHOTS = process.env.WIDGET_SHOTS; // a folder: screenshots of each scene for a person to look at

const PAGE = `<!doctype html><meta charset="utf-8"><link rel="stylesheet" href="/widget.css">
<body style="margin:0;background:#fff"><div id="cell" style="width:960px"></div>
<script type="module">
window.mount = async (scene, params) => {
  const { default: widget } = await import("/widget.js");
  const state = { scene, params };
  const listeners = {};
  const model = {
    sets: [], saves: 0,
    get: (k) => state[k],
    set: (k, v) => { state[k] = v; model.sets.push([k, v]); },
    save_changes: () => { model.saves++; },
    on: (ev, cb) => { (listeners[ev] ??= []).push(cb); },
    off: (ev, cb) => { listeners[ev] = (listeners[ev] ?? []).filter((f) => f !== cb); },
    // What anywidget does when Python assigns the trait: the new value, then change:params.
    fromPython: (k, v) => { state[k] = v; for (const cb of listeners["change:" + k] ?? []) cb(); },
    listeners,
  };
  window.model = model;
  const el = document.getElementById("cell");
  window.cleanup = await widget.render({ model, el });
  window.handle = el.__poinsot;
};
</script>`;

let server, base, browser;
before(async () => {
  if (!fs.existsSync(path.join(STATIC, "widget.js"))) throw new Error("build the widget first: cd web && npx vite build -c vite.widget.config.ts");
  const files = { "/": ["text/html", PAGE], "/widget.js": ["text/javascript"], "/widget.css": ["text/css"] };
  server = http.createServer((req, res) => {
    if (req.url === "/favicon.ico") { res.writeHead(204); res.end(); return; }
    const f = files[req.url];
    if (!f) { res.writeHead(404); res.end(); return; }
    res.writeHead(200, { "content-type": f[0] });
    res.end(f[1] ?? fs.readFileSync(path.join(STATIC, req.url.slice(1))));
  });
  await new Promise((r) => server.listen(0, "127.0.0.1", r));
  base = `http://127.0.0.1:${server.address().port}/`;
  browser = await launchChromium();
});
after(async () => {
  await browser?.close();
  server?.close();
});

async function mount(scene, params = {}) {
  const page = await browser.newPage({ viewport: { width: 1000, height: 600 } });
  const errors = collectErrors(page);
  await page.goto(base);
  await page.evaluate(([s, p]) => window.mount(s, p), [scene, params]);
  await page.waitForFunction(() => window.handle?.frames > 5, null, { timeout: 30000 });
  return { page, errors };
}

/** Distinct colours and the non-background fraction of the widget's WebGL canvas (32×32 grid). */
const pixels = (page) => canvasPixels(page, 0, 1, ".poinsot-widget .view canvas");

const pythonParams = JSON.parse(execFileSync(process.env.PYTHON ?? path.join(repo, ".venv/bin/python"), ["-c",
  "import json, dataclasses; from poinsot.widgets import SCENE_PARAMS as S; " +
  "print(json.dumps({k: {p: dataclasses.asdict(s) for p, s in v.items()} for k, v in S.items()}))"], { encoding: "utf8" }));

for (const scene of ["heavytop", "poinsot", "frames"]) {
  test(`${scene}: the scene draws, its sliders are Python's, no console errors`, async () => {
    const { page, errors } = await mount(scene);
    const px = await pixels(page);
    assert.ok(px.colours > 20 && px.busy > 0.05, `the canvas looks blank: ${JSON.stringify(px)}`);
    const pinned = await page.$$eval(".poinsot-widget .pinned dd", (dds) => dds.map((d) => d.textContent));
    assert.ok(pinned.length >= 3 && pinned.every((t) => t && t !== "—"), `pinned readouts: ${pinned}`);
    const sliders = await page.$$eval(".poinsot-widget input[type=range]", (xs) => xs.map((x) => [x.name, +x.min, +x.max, +x.step]));
    const want = Object.entries(pythonParams[scene]).filter(([, s]) => "min" in s).map(([k, s]) => [k, s.min, s.max, s.step]);
    assert.deepEqual(sliders, want);
    const choices = await page.$$eval(".poinsot-widget select", (xs) => xs.map((x) => [x.name, [...x.options].map((o) => o.value)]));
    assert.deepEqual(choices, Object.entries(pythonParams[scene]).filter(([, s]) => "options" in s).map(([k, s]) => [k, s.options]));
    if (SHOTS) await page.screenshot({ path: path.join(SHOTS, `${scene}.png`) });
    assert.deepEqual(errors, []);
    await page.close();
  });
}

test("moving a slider sets params on the model (and saves), the scene follows", async () => {
  const { page, errors } = await mount("heavytop", { preset: "custom" });
  const before = await page.evaluate(() => window.handle.readouts().pPsi);
  assert.ok(Math.abs(before - 0.5 * 9) < 1e-12, `p_psi = I3 w3 at the defaults: ${before}`);
  await page.$eval("input[name=w3]", (x) => { x.value = "20"; x.dispatchEvent(new Event("input")); });
  const { sets, saves } = await page.evaluate(() => ({ sets: window.model.sets, saves: window.model.saves }));
  assert.equal(sets.length, 1);
  assert.equal(sets[0][0], "params");
  assert.equal(sets[0][1].w3, 20);
  assert.equal(sets[0][1].preset, "custom");
  assert.equal(saves, 1);
  // p_psi = I3 w3 (2.103) from the core for the new spin.
  const after = await page.evaluate(() => window.handle.readouts().pPsi);
  assert.ok(Math.abs(after - 0.5 * 20) < 1e-12, `p_psi after the slider: ${after}`);
  assert.deepEqual(errors, []);
  await page.close();
});

test("a change of params from Python moves the sliders and reconfigures the scene", async () => {
  const { page, errors } = await mount("heavytop");
  const shown = () => page.evaluate(() => ({
    w3: document.querySelector("input[name=w3]").value,
    out: document.querySelector("label[data-key=w3] output").textContent,
    I3: document.querySelector("input[name=I3]").value,
    preset: document.querySelector("select[name=preset]").value,
    custom: !document.querySelector("label[data-key=phiDot0]").hidden,
    pinned: document.querySelector(".pinned dd[data-key=motionClass]").textContent,
    pPsi: window.handle.readouts().pPsi,
  }));
  const was = await shown();
  assert.equal(was.w3, "9");
  assert.equal(was.custom, false);
  await page.evaluate(() => window.model.fromPython("params", { ...window.model.get("params"), preset: "custom", w3: 30, I3: 0.8, phiDot0: 0, thetaDot0: 0 }));
  const now = await shown();
  assert.deepEqual([now.w3, now.out, now.I3, now.preset, now.custom], ["30", "30.0", "0.8", "custom", true]);
  assert.ok(Math.abs(now.pPsi - 0.8 * 30) < 1e-12, `p_psi from the core: ${now.pPsi}`);
  // A change from Python is not echoed back to Python.
  assert.deepEqual(await page.evaluate(() => window.model.sets), []);
  assert.deepEqual(errors, []);
  // Cleanup (the cell re-runs): the listener goes, the widget's element goes.
  await page.evaluate(() => window.cleanup());
  assert.deepEqual(await page.evaluate(() => [window.model.listeners["change:params"].length, document.querySelectorAll(".poinsot-widget").length]), [0, 0]);
  await page.close();
});

test("negative controls: an unknown scene is refused by name; a blank canvas reads as blank", async () => {
  const page = await browser.newPage();
  await page.goto(base);
  const message = await page.evaluate(() => window.mount("spinning-plate", {}).then(() => "rendered", (e) => e.message));
  assert.match(message, /no scene "spinning-plate" \(the scenes: frames, .*heavytop, earthtop, gyrocompass\)/);
  await page.evaluate(() => {
    const v = document.createElement("div");
    v.className = "poinsot-widget";
    v.innerHTML = '<div class="view"><canvas width="300" height="200"></canvas></div>';
    const g = v.querySelector("canvas").getContext("2d");
    g.fillStyle = "#101418";
    g.fillRect(0, 0, 300, 200);
    document.body.append(v);
  });
  const px = await pixels(page);
  assert.ok(!(px.colours > 20 && px.busy > 0.05), `a blank canvas passed the check: ${JSON.stringify(px)}`);
  await page.close();
});
