// Every scene records its readouts over time (issue 23, item 4): a plot of any numeric readout
// against time, picked from a list, and the record as a CSV download; sliders say their value
// with its unit (aria-valuetext), a spin in rpm beside rad/s; the checks of the computation
// (residuals, drifts) are listed apart from the results. Run with `npm test` in web/.
import { test } from "node:test";
import assert from "node:assert/strict";
import { open, readouts, sceneIds, startLab } from "./harness.mjs";

await startLab();
const SCENES = await sceneIds();

for (const scene of SCENES) {
  test(`${scene}: a readout plotted against time, and the record downloaded as CSV`, async () => {
    const { page, errors } = await open(`?scene=${scene}&paused=1`);
    await page.locator("#record summary").click();
    const options = await page.locator("#record-key option").evaluateAll((os) => os.map((o) => o.value));
    assert.ok(options.length >= 2, `${scene}: ${options.length} readouts to plot`);
    // The motion over 1 s, in 40 frames; the last readout of the list plotted.
    const key = options[options.length - 1];
    await page.selectOption("#record-key", key);
    await page.evaluate(() => { for (let k = 1; k <= 40; k++) window.__lab.seek(k / 40); });
    const series = await page.evaluate((k) => window.__lab.record().series(k), key);
    const now = (await readouts(page))[key.replace(/\[\d+\]$/, "")];
    const want = /\[(\d+)\]$/.test(key) ? now[Number(key.match(/\[(\d+)\]$/)[1])] : now;
    assert.equal(series.t.length, 41, `${scene}: ${series.t.length} times recorded`);
    assert.equal(series.t[40], 1);
    // In the unit the readout's label names (degrees for an angle, whose value is in rad).
    assert.equal(series.v[40], want * series.scale, `${scene}: the record's last value is the readout's`);
    await page.evaluate(() => document.getElementById("record-key").dispatchEvent(new Event("change")));
    assert.equal(await page.locator("#record-plot").getAttribute("data-points"), "41");
    assert.match(await page.locator("#record-plot").getAttribute("aria-label"), / against time t \(s\), 41 points$/);
    // The CSV: a header (t (s), then the readouts' labels), one row per recorded time.
    const download = page.waitForEvent("download");
    await page.locator("#record-csv").click();
    const file = await download;
    assert.equal(file.suggestedFilename(), `poinsot-${scene}.csv`);
    const chunks = [];
    for await (const c of await file.createReadStream()) chunks.push(c);
    const csv = Buffer.concat(chunks).toString("utf8");
    assert.equal(csv, (await page.evaluate(() => window.__lab.record())).csv);
    const lines = csv.trim().split("\n");
    assert.equal(lines.length, 42);
    assert.match(lines[0], /^"t \(s\)",/);
    assert.equal(lines[41].split(",")[0], "1");
    // A parameter change starts a new record.
    const slider = page.locator("#controls input[type=range]").first();
    await slider.focus();
    await slider.press("ArrowRight");
    assert.equal((await page.evaluate((k) => window.__lab.record().series(k), key)).t.length, 1);
    assert.deepEqual(errors, []);
    await page.close();
  });
}

test("sliders say their value with its unit; a spin in rpm beside rad/s", async () => {
  const { page, errors } = await open("?scene=heavytop&paused=1");
  const said = (name) => page.locator(`input[name=${name}]`).getAttribute("aria-valuetext");
  assert.equal(await said("w3"), "9 radians per second");
  assert.equal(await said("tilt"), "50 degrees");
  assert.equal(await said("I1"), "1 kilogram square metre");
  // A vector readout's components are plotted by their own names.
  // In the unit its label names, as the readout's text: θ in degrees (the lab's angle unit), not
  // the radians of the value the core gives.
  assert.equal(await page.locator('#record-key option[value="angles[1]"]').textContent(), "θ (°)");
  await page.evaluate(() => { for (let k = 1; k <= 4; k++) window.__lab.seek(k / 4); });
  const theta = await page.evaluate(() => window.__lab.record().series("angles[1]").v.at(-1));
  const rad = (await readouts(page)).angles[1];
  assert.ok(Math.abs(theta - (rad * 180) / Math.PI) < 1e-12 * theta, `θ recorded ${theta} for ${rad} rad`);
  const omega3 = await page.evaluate(() => window.__lab.record().series("omega3").v.at(-1));
  assert.equal(omega3, 9); // a rate stays in rad/s, as its label
  await page.evaluate(() => {
    const input = document.querySelector("input[name=w3]");
    input.value = input.max;
    input.dispatchEvent(new Event("input", { bubbles: true }));
  });
  assert.equal(await said("w3"), "200 radians per second (1910 rpm)");
  assert.equal(await page.locator("label[data-key=w3] output").innerText(), "200 (1910 rpm)");
  // A 1500 rpm tabletop top is on the spin slider's grid to 1 %.
  const grid = await page.evaluate(() => { const i = document.querySelector("input[name=w3]"); return [Number(i.min), Number(i.max)]; });
  assert.ok(grid[1] - grid[0] > 200, `the spin slider has ${grid[1] - grid[0] + 1} stops`);
  const foucault = await open("?scene=foucault&paused=1");
  assert.equal(await foucault.page.locator("input[name=latitude]").getAttribute("aria-valuetext"), "49 degrees");
  assert.equal(await foucault.page.locator("input[name=length]").getAttribute("aria-valuetext"), "10 metres");
  assert.deepEqual([...errors, ...foucault.errors], []);
  await foucault.page.close();
  await page.close();
});

test("residuals and drifts are checks, listed apart from the results and never pinned", async () => {
  for (const [scene, keys] of [["frames", ["residual"]], ["heavytop", ["energyNow", "pPhiNow", "pPsiNow"]], ["poinsot", ["contactResidual"]], ["foucault", ["jacobiDrift"]]]) {
    const { page, errors } = await open(`?scene=${scene}&paused=1`);
    for (const key of keys) {
      assert.equal(await page.locator(`#checks dd[data-key=${key}]`).count(), 1, `${scene}.${key} is not under the checks`);
      assert.equal(await page.locator(`#pinned dd[data-key=${key}]`).count(), 0, `${scene}.${key} is pinned`);
    }
    assert.equal(await page.locator("#readouts > dd").count() > 3, true);
    assert.deepEqual(errors, []);
    await page.close();
  }
});
