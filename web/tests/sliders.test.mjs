// A lab that no slider can break (issue 23, item 4): every slider of every scene dragged to
// both ends, alone and after each other slider at its ends (each alone again for each option of
// each choice), leaves a valid state on screen — no error, no refusal, readouts shown,
// every thumb where the parameters are. A move the core refuses is resolved by the sliders
// (another slider follows, or the moved one stops; src/sliders.ts), and the negative control
// shows that the sweep sees the failures those couplings prevent: with the coupling off
// (window.__lab.couple = false) the same sweep finds error states in the heavy top and the
// Foucault pendulum. Run with `npm test` in web/ (see harness.mjs).
import { test } from "node:test";
import assert from "node:assert/strict";
import { open, sceneIds, startLab } from "./harness.mjs";

await startLab();
const SCENES = await sceneIds();

/** Runs in the page: the sweep over the current scene; returns its failures (strings). */
function sweep({ couple, later }) {
  const lab = window.__lab;
  lab.couple = couple;
  const inputs = () => [...document.querySelectorAll("#controls label:not([hidden]) input[type=range]")];
  const selects = () => [...document.querySelectorAll("#controls select")];
  const drag = (input, end) => {
    input.value = end === "min" ? input.min : input.max;
    input.dispatchEvent(new Event("input", { bubbles: true }));
  };
  const choose = (key, value) => {
    const s = document.querySelector(`#controls select[name="${key}"]`);
    s.value = value;
    s.dispatchEvent(new Event("change", { bubbles: true }));
  };
  const reset = () => document.getElementById("reset").click();
  const failures = [];
  const check = (what) => {
    const bad = [];
    if (lab.error !== null) bad.push(`error ${lab.error}`);
    if (lab.refused !== null) bad.push(`refused ${lab.refused}`);
    if (!document.getElementById("alert").hidden) bad.push("alert shown");
    const text = document.getElementById("readouts").innerText;
    if (/NaN|undefined/.test(text)) bad.push("NaN in the readouts");
    if ([...document.querySelectorAll("#readouts dd")].some((dd) => dd.textContent === "—")) bad.push("readouts blanked");
    // Each thumb is where the state is (a slider that followed or stopped shows it).
    for (const input of inputs()) {
      const v = lab.params[input.name];
      const shown = input.dataset.scale === "log" ? null : Number(input.value);
      if (shown !== null && Math.abs(shown - v) > 1e-9 * Math.max(1, Math.abs(v)) && Number(input.value) !== Number(input.min) && Number(input.value) !== Number(input.max)) bad.push(`${input.name} thumb ${input.value} ≠ ${v}`);
    }
    if (!bad.length && later) {
      lab.seek(later);
      if (lab.error !== null) bad.push(`at t = ${later}: ${lab.error}`);
      lab.seek(0);
    }
    if (bad.length) failures.push(`${what}: ${bad.join("; ")}`);
  };
  // The choices: the defaults, then each option of each choice.
  const configs = [{}];
  for (const s of selects()) for (const o of s.options) if (o.value !== s.value) configs.push({ [s.name]: o.value });
  let states = 0;
  const skipped = [];
  for (const config of configs) {
    const setup = () => {
      reset();
      for (const [k, v] of Object.entries(config)) choose(k, v);
    };
    setup();
    // A choice that is itself a question to the student (the inertia's "STL file" before a file
    // is chosen) shows its own error: its sliders wait for the answer.
    if (lab.error !== null) {
      skipped.push(config);
      continue;
    }
    const names = inputs().map((i) => i.name);
    const desc = Object.entries(config).map(([k, v]) => `${k}=${v} `).join("");
    for (const a of names) {
      for (const ea of ["min", "max"]) {
        setup();
        drag(document.querySelector(`input[name="${a}"]`), ea);
        states++;
        check(`${desc}${a}→${ea}`);
        // Pairs under the default choices; each other option, slider by slider.
        for (const b of Object.keys(config).length ? [] : names) {
          if (b === a) continue;
          for (const eb of ["min", "max"]) {
            setup();
            const ib = document.querySelector(`input[name="${b}"]`);
            const ia = document.querySelector(`input[name="${a}"]`);
            if (!ib || !ia || ib.closest("label").hidden) continue;
            drag(ib, eb);
            if (ia.closest("label").hidden) continue;
            drag(ia, ea);
            states++;
            check(`${desc}${b}→${eb}, ${a}→${ea}`);
          }
        }
      }
    }
  }
  lab.couple = true;
  return { failures, states, skipped };
}

for (const scene of SCENES) {
  test(`${scene}: every slider to both ends, alone and after each other slider at its ends, leaves a valid state`, async () => {
    const { page, errors } = await open(`?scene=${scene}&paused=1`);
    const { failures, states, skipped } = await page.evaluate(sweep, { couple: true, later: 2.5 });
    assert.ok(states > 0, "no slider swept");
    // Only the STL choice without a file is an error of its own.
    assert.deepEqual(skipped, scene === "inertia" ? [{ shape: "STL file" }] : []);
    assert.deepEqual(failures.slice(0, 20), [], `${failures.length} of ${states} states fail`);
    assert.deepEqual(errors, []);
    await page.close();
  });
}

test("negative control: without the coupling the sweep finds the heavy top's and the pendulum's failures", async () => {
  for (const [scene, pair] of [["heavytop", /I1→min|I3→max/], ["foucault", /length→min|amplitude→max/]]) {
    const { page } = await open(`?scene=${scene}&paused=1`);
    const { failures } = await page.evaluate(sweep, { couple: false, later: 0 });
    assert.ok(failures.some((f) => pair.test(f)), `${scene}: the uncoupled sweep found no failure: ${failures.slice(0, 3)}`);
    await page.close();
  }
});

test("a refused move keeps the last valid state on screen and names the slider moved", async () => {
  let { page, errors } = await open("?scene=heavytop&paused=1");
  const before = await page.evaluate(() => window.__lab.readouts());
  // Without the coupling, I₃ beyond 2I₁ goes to the core, which refuses it.
  const r = await page.evaluate(() => {
    window.__lab.couple = false;
    const input = document.querySelector("input[name=I3]");
    input.value = input.max;
    input.dispatchEvent(new Event("input", { bubbles: true }));
    window.__lab.couple = true;
    return { refused: window.__lab.refused, error: window.__lab.error, params: window.__lab.params, alert: document.getElementById("alert").innerText };
  });
  assert.equal(r.error, null);
  assert.match(r.refused, /^I₃ cannot take that value: I3: must be <= 2\*I1/);
  assert.equal(r.alert, r.refused);
  assert.equal(r.params.I3, 0.5, "the last valid I₃ is kept");
  assert.deepEqual(await page.evaluate(() => window.__lab.readouts()), before, "the readouts are those of the last valid state");
  assert.ok(!(await page.locator("#readouts").innerText()).includes("—"));
  // With the coupling (the default), I₁ to its least value: the core's I₃ ≤ 2I₁ stops I₁ where the
  // loops' steady precession still exists (a smaller I₃ would need a faster spin) ...
  const stop = await page.evaluate(() => {
    const input = document.querySelector("input[name=I1]");
    input.value = input.min;
    input.dispatchEvent(new Event("input", { bubbles: true }));
    return { params: window.__lab.params, note: window.__lab.note, refused: window.__lab.refused };
  });
  assert.equal(stop.refused, null);
  assert.ok(stop.params.I3 === 0.5 && stop.params.I1 >= 0.25 && stop.params.I1 < 0.26, JSON.stringify(stop.params));
  assert.match(stop.note, /^I₁ \(pivot\) stops at 0\.25 kg·m²: I3 must be <= 2\*I1 = 0\.4\d/);
  assert.deepEqual(errors, []);
  await page.close();
  // ... and, released with the custom rates (no steady precession needed), I₃ follows I₁ down.
  ({ page, errors } = await open("?scene=heavytop&preset=custom&paused=1"));
  const c = await page.evaluate(() => {
    const input = document.querySelector("input[name=I1]");
    input.value = input.min;
    input.dispatchEvent(new Event("input", { bubbles: true }));
    return { params: window.__lab.params, note: window.__lab.note, refused: window.__lab.refused };
  });
  assert.equal(c.refused, null);
  assert.ok(c.params.I3 <= 2 * c.params.I1, JSON.stringify(c.params));
  assert.match(c.note, /^I₃ followed I₁ \(pivot\) to 0\.0002 kg·m²: I3 must be <= 2\*I1 = 0\.0002 \(the triangle inequality/);
  assert.deepEqual(errors, []);
  await page.close();
});

test("a choice the core refuses takes a slider along, or shows the core's error when nothing can follow", async () => {
  // Cusps at ω₃ = 1 rad/s are valid; steady precession needs the least spin 2.119: ω₃ follows up.
  let { page, errors } = await open("?scene=heavytop&preset=cusps&w3=1&paused=1");
  const r = await page.evaluate(() => {
    const s = document.querySelector("select[name=preset]");
    s.value = "steady precession";
    s.dispatchEvent(new Event("change", { bubbles: true }));
    return { params: window.__lab.params, note: window.__lab.note, error: window.__lab.error, minSpin: window.__lab.readouts().minSpin };
  });
  assert.equal(r.error, null);
  assert.equal(r.params.preset, "steady precession");
  assert.ok(r.params.w3 >= r.minSpin && r.params.w3 < 1.03 * r.minSpin, JSON.stringify(r));
  assert.match(r.note, /^spin ω₃ moved to \d\.\d+ rad\/s for Motion “steady precession”: omega3 /);
  assert.deepEqual(errors, []);
  await page.close();
  // An open STL file has nothing to follow: the choice stands with the core's error (inertia.test.mjs),
  // and a slider moved then starts from the parameters shown (the shape stays the file).
  ({ page, errors } = await open("?scene=inertia&shape=STL+file&paused=1"));
  const shape = await page.evaluate(() => {
    const i = document.querySelector("input[name=density]");
    i.value = i.max;
    i.dispatchEvent(new Event("input", { bubbles: true }));
    return window.__lab.params.shape;
  });
  assert.equal(shape, "STL file");
  assert.deepEqual(errors, []);
  await page.close();
});
