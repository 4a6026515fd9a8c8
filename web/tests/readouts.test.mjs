// Browser tests of what the lab's readouts and views say (issue 12, "The lab"): one number
// format, values below the computation's precision shown as 0, one angle unit per scene (that of
// its sliders), consistent signs; the warnings where an approximation stops holding (Foucault's
// −Ω sin λ; a drawing off its scale) appear exactly when their condition holds; the 2.42 mark is
// visible; the particle of the rotating frames stays on the table; the controls shown are those
// that apply; the Poinsot scene says how near the separatrix it is and its ω(t) plot has axes;
// the camera (reset button, keyboard orbit), the canvas's aria-label and prefers-reduced-motion.
import { test } from "node:test";
import assert from "node:assert/strict";
import { open, readouts, sceneIds, startLab, state } from "./harness.mjs";
import { angleUnits, numberFormatProblems, numbersIn, radianAngles, signProblems } from "./view_checks.mjs";

await startLab();
const SCENES = await sceneIds();

/** Every readout of the page as the user sees it: key, label, value and text, panel and pinned. */
const shown = (page) =>
  page.evaluate(() => {
    const values = window.__lab.readouts();
    const cells = [...document.querySelectorAll("#readouts dd, #pinned dd")];
    return cells.map((dd) => ({
      key: dd.dataset.key, label: dd.previousElementSibling?.textContent ?? "", text: dd.textContent, value: values[dd.dataset.key],
    }));
  });
/** The labels of the visible controls and their values. */
const controls = (page) =>
  page.evaluate(() => [...document.querySelectorAll("#controls label:not([hidden])")].map((l) => ({
    key: l.dataset.key, label: l.firstElementChild.textContent, out: l.querySelector("output")?.textContent ?? "",
    said: l.querySelector("input")?.getAttribute("aria-valuetext") ?? "",
  })));

/** Scene states whose readouts are checked besides the defaults: gimbal lock, an equator, a
 * lamina, a spring, the tumbling box, a warning, a southern latitude, the custom top. */
const STATES = [
  ...SCENES.map((s) => `scene=${s}`),
  "scene=euler&theta=0", "scene=euler&seq=zyx&theta=90", "scene=foucault&latitude=0", "scene=foucault&latitude=-60&length=80",
  "scene=low&latitude=-30", "scene=low&latitude=0", "scene=inertia&shape=disk&motion=Euler", "scene=inertia&motion=Chasles",
  "scene=frames&stiffness=2&omegaDot=0.3", "scene=poinsot&view=tumbling+box&axis=smallest", "scene=drop&latitude=-33",
  "scene=heavytop&preset=custom&tilt=100&phiDot0=-1.2&thetaDot0=0.7",
];

test("every readout uses the one number format, every angle is in degrees (no slider or readout in radians), and signs agree with the values", async () => {
  for (const q of STATES) {
    const { page, errors } = await open(`?${q}&paused=1&t=2.5`);
    const cells = await shown(page);
    const ctl = await controls(page);
    assert.ok(cells.length >= 8, `${q}: ${cells.length} readouts`);
    for (const c of cells) {
      assert.deepEqual(numberFormatProblems(c.text), [], `${q} ${c.key}`);
      assert.deepEqual(signProblems(c.key, c.value, c.text), [], `${q} ${c.key}`);
    }
    for (const c of ctl) assert.deepEqual(numberFormatProblems(c.out), [], `${q} slider ${c.key}`);
    // One angle unit for the lab, degrees: "rad" only in a rate (rad/s, rad/s²), never an angle.
    assert.deepEqual(radianAngles([...cells.flatMap((c) => [c.label, c.text]), ...ctl.flatMap((c) => [c.label, c.out, c.said])]), [], q);
    assert.deepEqual(errors, [], q);
    await page.close();
  }
});

test("negative controls: mixed formats, two angle units and a flipped sign are caught", () => {
  // The examples.
  assert.equal(numberFormatProblems("−1.554e-15").length, 1);
  assert.equal(numberFormatProblems("9.576e−16").length, 1);
  assert.equal(numberFormatProblems("-0.5").length, 1);
  assert.deepEqual(numberFormatProblems("−1.554×10⁻¹⁵, 9.576×10⁻¹⁶, (0.1, −2.5), 2.119"), []);
  assert.deepEqual(numbersIn("−1.554×10⁻¹⁵").map((n) => n.value), [-1.554e-15]);
  assert.deepEqual(angleUnits(["φ, θ, ψ (rad)", "θ₁, θ₂ (°)"]), ["rad", "°"]);
  assert.deepEqual(angleUnits(["radius (m)", "θ₁ (rad)"]), ["rad"]);
  // The earlier heavy top's tilt slider and readouts, and the rotating frames' launch direction.
  assert.deepEqual(radianAngles(["tilt θ₀ (rad)", "0.87 (49.8°)", "0.87 radians (49.8 degrees)", "θ₁, θ₂ (rad)", "launch direction (rad)"]),
    ["tilt θ₀ (rad)", "0.87 radians (49.8 degrees)", "θ₁, θ₂ (rad)", "launch direction (rad)"]);
  assert.deepEqual(radianAngles(["ω₃ (rad/s, 2.99)", "table ω̇ (rad/s²)", "157 radians per second (1499 rpm)", "θ₁, θ₂ (°)", "radius (m)"]), []);
  assert.equal(signProblems("foucaultRate", -5.1563e-5, "−5.15630×10⁻⁵ (10.64)").length, 1);
  assert.deepEqual(signProblems("energyNow", 0.66, "0.66 (rel. drift −2.1×10⁻¹⁶)"), []);
  assert.equal(signProblems("v", [1, -2], "(1, 2)").length, 1);
});

test("values below the computation's precision show as 0; real small values do not", async () => {
  // R = R_z(90°): cos(π/2) = 6.1e-17 in double precision, round-off of an entry of size 1.
  const { page, errors } = await open("?scene=euler&phi=90&theta=0&psi=0&phiDot=0&thetaDot=0&psiDot=0&paused=1");
  const r = await readouts(page);
  assert.ok(r.R[0] !== 0 && Math.abs(r.R[0]) < 1e-15, `R[0] = ${r.R[0]}`);
  const text = (await shown(page)).find((c) => c.key === "R").text;
  assert.equal(numbersIn(text)[0].text, "0", text);
  assert.deepEqual(numbersIn(text).map((n) => n.value), [0, -1, 0, 1, 0, 0, 0, 0, 1]);
  // Negative control: the drift north of a falling body, 4 µm of 100 m, is a value, not round-off.
  const drop = await open("?scene=drop&paused=1");
  const north = (await shown(drop.page)).find((c) => c.key === "north");
  assert.ok(north.value < 0 && Math.abs(north.value) < 1e-5);
  assert.equal(numbersIn(north.text)[0].value.toPrecision(4), north.value.toPrecision(4), north.text);
  assert.deepEqual([...errors, ...drop.errors], []);
  await drop.page.close();
  await page.close();
});

test("the falling body's Foucault rate has one unit and the sign of its value", async () => {
  for (const lat of [45, -33]) {
    const { page, errors } = await open(`?scene=drop&latitude=${lat}&paused=1`);
    const c = (await shown(page)).find((x) => x.key === "foucaultRate");
    assert.match(c.label, /°\/h/);
    const nums = numbersIn(c.text);
    assert.equal(nums.length, 1, c.text);
    // −Ω sin λ in °/h: Ω = 2π rad per sidereal day.
    const want = (-360 / 86164.0905) * 3600 * Math.sin((lat * Math.PI) / 180);
    assert.ok(Math.abs(nums[0].value - want) < 1e-3 * Math.abs(want), `${c.text} vs ${want}`);
    assert.equal(Math.sign(c.value), Math.sign(want));
    assert.deepEqual(errors, []);
    await page.close();
  }
});

// --- approximations ------------------------------------------------------------------------

/** The core's tolerance on −Ω sin λ (UNIT_RATE_TOLERANCE), read by the page's own module. */
const TOLERANCE = 0.01;

test("Foucault: the warning that −Ω sin λ does not apply appears exactly when Ω is not ≪ √(g/L) or the swing is wide", async () => {
  const cases = [
    // [query, spin not small, swing wide, steady turn]
    ["latitude=49&length=10&amplitude=1", false, false, true], // the default: it applies
    ["latitude=49&length=80&amplitude=1", true, false, true], // Ω/√(g/L) = 0.21
    ["latitude=49&length=10&amplitude=3", false, true, true], // A/L = 0.3
    ["latitude=20&length=100&amplitude=5", true, false, true],
    ["latitude=90&length=80&amplitude=1", false, false, true], // the pole: Δ = −Ω exactly
    ["latitude=0&length=10&amplitude=1", false, false, true], // the equator: no turn, as −Ω sin λ = 0 says
    ["latitude=2&length=80&amplitude=1", true, false, false], // the plane rocks: no rate to compare
  ];
  for (const [q, fastSpin, wide, steady] of cases) {
    const { page, errors } = await open(`?scene=foucault&spin=1000&${q}&paused=1`);
    const r = await readouts(page);
    const cells = await shown(page);
    const pinnedNote = await page.locator("#pinned .note dd[data-key=unitRate]").count();
    // The spin's departure from the page's own numbers: the exact small-swing rate Δ against −Ω sin λ.
    if (typeof r.theoryRate === "number") {
      const d = Math.abs(r.theoryRate - r.expectedRate) / Math.max(Math.abs(r.theoryRate), Math.abs(r.expectedRate));
      if (r.expectedRate !== 0) assert.equal(d > TOLERANCE, fastSpin, `${q}: Δ departs by ${d}`);
    }
    // The swing's: the small-amplitude estimate of its own precession, (3/8)(A/L)², against the
    // tolerance (the cases are far from it on either side).
    const [, L, A] = q.match(/length=(\d+)&amplitude=(\d+)/).map(Number);
    assert.equal(0.375 * (A / L) ** 2 > TOLERANCE, wide, `${q}: (3/8)(A/L)²`);
    const warn = fastSpin || wide || !steady;
    assert.equal(r.unitRate, !warn, `${q}: unitRate ${r.unitRate}`);
    assert.equal(pinnedNote, warn ? 1 : 0, `${q}: the warning is ${pinnedNote ? "" : "not "}pinned`);
    const text = cells.find((c) => c.key === "unitRate").text;
    if (fastSpin && steady) assert.match(text, /^no: Ω is not ≪ √\(g\/L\)/, q);
    if (wide) assert.match(text, /the swing is wide \(A\/L = /, q);
    if (!steady) assert.match(text, /^no: the plane does not turn steadily/, q);
    if (!warn) assert.match(text, /^yes: /, q);
    // The picture and the words agree: no sense is printed without a steady turn.
    if (!steady) assert.match(cells.find((c) => c.key === "sense").text, /^— /);
    assert.deepEqual(errors, [], q);
    await page.close();
  }
});

test("Foucault: moving the length across the threshold turns the warning on and off", async () => {
  const { page, errors } = await open("?scene=foucault&paused=1");
  const note = () => page.locator("#pinned dd[data-key=unitRate]").count();
  assert.equal(await note(), 0);
  await page.evaluate(() => { const i = document.querySelector('input[data-key="length"]'); i.value = "80"; i.dispatchEvent(new Event("input")); });
  assert.equal(await note(), 1);
  await page.evaluate(() => { const i = document.querySelector('input[data-key="length"]'); i.value = "10"; i.dispatchEvent(new Event("input")); });
  assert.equal(await note(), 0);
  assert.deepEqual(errors, []);
  await page.close();
});

test("off-scale drawings say so: the landing point beyond the ground, the inertial circle beyond the map", async () => {
  const cases = [
    ["scene=drop", "drawing", false],
    ["scene=drop&height=500&exaggeration=10000", "drawing", true],
    ["scene=drop&latitude=89&exaggeration=1", "drawing", true], // too small to see
    ["scene=low", "inertialOffMap", false],
    ["scene=low&latitude=0", "inertialOffMap", true],
    ["scene=low&latitude=3", "inertialOffMap", true], // 10 m/s / |f| is 2700 km
  ];
  for (const [q, key, warned] of cases) {
    const { page, errors } = await open(`?${q}&paused=1`);
    assert.equal(await page.locator(`#pinned dd[data-key=${key}]`).count(), warned ? 1 : 0, q);
    assert.deepEqual(errors, [], q);
    await page.close();
  }
});

// --- what the views show ------------------------------------------------------------------

test("falling body: the yellow 2.42 mark shows inside the white ring of the exact landing point", async () => {
  for (const viewport of [{ width: 1280, height: 800 }, { width: 390, height: 844 }]) {
    const { page, errors } = await open("?scene=drop&paused=1", viewport);
    await page.waitForTimeout(300);
    const { firstOrderMark: p } = await page.evaluate(() => window.__lab.probes());
    const png = await page.screenshot({ clip: { x: Math.round(p.x) - 1, y: Math.round(p.y) - 1, width: 3, height: 3 } });
    const rgb = await page.evaluate(async (b64) => {
      const img = new Image();
      img.src = `data:image/png;base64,${b64}`;
      await img.decode();
      const c = document.createElement("canvas");
      c.width = img.width; c.height = img.height;
      const g = c.getContext("2d");
      g.drawImage(img, 0, 0);
      return Array.from(g.getImageData(1, 1, 1, 1).data.slice(0, 3));
    }, png.toString("base64"));
    // #f2b84b, the mark's yellow (not the white ring, not the ground).
    assert.ok(rgb[0] > 200 && rgb[1] > 150 && rgb[1] < 210 && rgb[2] < 120, `${viewport.width}: the pixel at the 2.42 mark is ${rgb}`);
    assert.deepEqual(errors, []);
    await page.close();
  }
});

test("rotating frames: the particle never leaves the table, and the loop ends at the rim", async () => {
  const TABLE = 1;
  for (const q of ["", "&stiffness=0&speed=2&direction=0", "&stiffness=2&speed=1.5", "&launch=rotating+frame&omega=-2"]) {
    const { page, errors } = await open(`?scene=frames${q}&paused=1`);
    const loop = (await readouts(page)).loop;
    const radii = await page.evaluate((L) => Array.from({ length: 161 }, (_, k) => {
      window.__lab.seek((L * k) / 160 * (1 - 1e-9));
      const r = window.__lab.readouts();
      return [Math.hypot(...r.positionFixed), Math.hypot(...r.positionRotating)];
    }), loop);
    const worst = Math.max(...radii.flat());
    assert.ok(worst <= TABLE * (1 + 1e-3), `${q}: the particle reaches ${worst} m (loop ${loop} s)`);
    // |r| is the same seen from both frames (they share the axis).
    for (const [a, b] of radii) assert.ok(Math.abs(a - b) < 1e-12, `${a} vs ${b}`);
    if (q === "") assert.ok(radii.at(-1)[0] > 0.97 * TABLE, `the default loop ends at ${radii.at(-1)[0]} m, not at the rim`);
    assert.deepEqual(errors, [], q);
    await page.close();
  }
});

test("inertia: only the controls that apply are shown", async () => {
  const cases = [
    ["shape=cuboid", ["shape", "mass", "a", "b", "c", "motion"]],
    ["shape=sphere", ["shape", "mass", "a", "motion"]],
    ["shape=cylinder&motion=Euler", ["shape", "mass", "a", "b", "motion", "phi", "theta", "psi"]],
    ["shape=STL+file&motion=Chasles", ["shape", "density", "unit", "motion", "phi", "theta", "psi", "tx", "ty", "tz"]],
  ];
  for (const [q, want] of cases) {
    const { page } = await open(`?scene=inertia&${q}&paused=1`);
    assert.deepEqual((await controls(page)).map((c) => c.key), want, q);
    assert.equal(await page.locator("#scene-extra input[type=file]").isVisible(), q.includes("STL"), q);
    await page.close();
  }
});

test("poinsot: how near the separatrix the motion is, and why; the ω(t) plot has axes", async () => {
  const { page, errors } = await open("?scene=poinsot&paused=1&t=3");
  let r = await readouts(page);
  let cells = await shown(page);
  // Spun about the intermediate axis: just off the separatrix (the core's m near 1).
  assert.equal(r.regime, "about max axis");
  assert.ok(r.separatrix > 0.99 && r.separatrix < 1, `m = ${r.separatrix}`);
  const text = cells.find((c) => c.key === "separatrix").text;
  const gap = numbersIn(text)[1].value;
  assert.ok(Math.abs(gap - (1 - r.separatrix)) < 0.005 * (1 - r.separatrix), text); // 3 digits
  assert.match(text, /unstable.*flips/);
  assert.match(cells.find((c) => c.key === "regime").text, /largest-moment axis/);
  assert.equal(await page.locator("#pinned dd[data-key=separatrix]").count(), 1);
  const axes = await page.locator("figure.poinsot-plot canvas").getAttribute("data-axes");
  assert.match(axes, /^t \(s\): 0 to [\d.]+; ω \(rad\/s\): /);
  // Negative control: about the smallest axis it is far from the separatrix, stable, no flip.
  const far = await open("?scene=poinsot&axis=smallest&paused=1");
  r = await readouts(far.page);
  cells = await shown(far.page);
  assert.ok(r.separatrix < 0.9, `m = ${r.separatrix}`);
  assert.doesNotMatch(cells.find((c) => c.key === "separatrix").text, /flip/);
  assert.deepEqual([...errors, ...far.errors], []);
  await far.page.close();
  await page.close();
});

// --- camera and access -----------------------------------------------------------------------

const camera = (page) => page.evaluate(() => window.__lab.camera());
const close = (a, b, tol) => a.every((x, i) => Math.abs(x - b[i]) <= tol);

test("camera: the reset-view button and the keyboard orbit change and restore the view", async () => {
  for (const scene of ["drop", "frames"]) {
    const { page, errors } = await open(`?scene=${scene}&paused=1`);
    await page.waitForTimeout(200);
    const home = await camera(page);
    const canvas = page.locator("#view canvas");
    await canvas.focus();
    await canvas.press("ArrowLeft");
    await canvas.press("ArrowLeft");
    const turned = await camera(page);
    assert.ok(!close(turned.position, home.position, 1e-3), `${scene}: ArrowLeft did not turn the view`);
    // Two steps of 10° about the vertical through the target, at the same distance.
    const az = (c) => Math.atan2(c.position[1] - c.target[1], c.position[0] - c.target[0]);
    const dist = (c) => Math.hypot(...c.position.map((x, i) => x - c.target[i]));
    const dAz = Math.abs(((az(turned) - az(home) + 3 * Math.PI) % (2 * Math.PI)) - Math.PI);
    assert.ok(Math.abs(dAz - (20 * Math.PI) / 180) < 1e-9, `${scene}: turned by ${dAz} rad`);
    assert.ok(Math.abs(dist(turned) - dist(home)) < 1e-9 * dist(home));
    await canvas.press("ArrowUp");
    await canvas.press("+");
    const zoomed = await camera(page);
    assert.ok(dist(zoomed) < dist(home) / 1.1, `${scene}: + did not zoom in`);
    // The button brings the view back.
    await page.locator("#reset-view").click();
    assert.ok(close((await camera(page)).position, home.position, 1e-9), `${scene}: the reset button did not restore the view`);
    // And the key 0.
    await canvas.press("ArrowRight");
    await page.locator("body").press("0");
    assert.ok(close((await camera(page)).position, home.position, 1e-9), `${scene}: the key 0 did not restore the view`);
    assert.deepEqual(errors, []);
    await page.close();
  }
});

test("every scene's canvas has an aria-label naming the scene and the keys", async () => {
  const { page, errors } = await open("?paused=1");
  for (const [i, id] of SCENES.entries()) {
    // The number keys 1–9 open the first nine scenes; the later ones open by their tabs.
    if (i < 9) await page.locator("body").press(String(i + 1));
    else await page.locator(`#scenes button[data-scene="${id}"]`).click();
    const label = await page.locator("#view canvas").getAttribute("aria-label");
    const title = await page.locator("#scene-title").textContent();
    assert.ok(label.startsWith(`${title}: `) && /arrow keys/.test(label) && /0 resets the view/.test(label), `${id}: ${label}`);
    assert.equal(await page.locator("#view canvas").getAttribute("tabindex"), "0");
  }
  assert.deepEqual(errors, []);
  await page.close();
});

test("prefers-reduced-motion: nothing moves until Play is pressed; without it the lab plays", async () => {
  for (const scene of ["heavytop", "frames"]) {
    const { page, errors } = await open(`?scene=${scene}`, undefined, { reducedMotion: "reduce" });
    const s0 = await state(page);
    assert.equal(s0.playing, false);
    assert.equal(await page.evaluate(() => window.__lab.reducedMotion), true);
    const shot = () => page.locator("#view canvas").screenshot();
    const a = await shot();
    await page.waitForTimeout(500);
    const b = await shot();
    assert.equal((await state(page)).t, 0);
    assert.ok(a.equals(b), `${scene}: the view changed without Play`);
    // Another scene opens paused too.
    await page.locator("body").press("2");
    assert.equal((await state(page)).playing, false);
    // Asked: it plays.
    await page.locator("#play").click();
    await page.waitForTimeout(300);
    assert.ok((await state(page)).t > 0, `${scene}: Play did not start the motion`);
    assert.deepEqual(errors, []);
    await page.close();
  }
  // Negative control: no preference, the lab plays at once.
  const { page, errors } = await open("?scene=heavytop", undefined, { reducedMotion: "no-preference" });
  await page.waitForTimeout(300);
  assert.equal((await state(page)).playing, true);
  assert.ok((await state(page)).t > 0);
  assert.deepEqual(errors, []);
  await page.close();
});
