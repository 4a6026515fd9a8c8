// Browser tests of the heavy-top scene (issue 6; the unit's 2.102–2.121): every preset loads and
// draws, the motion class shown is the preset's, θ(t) stays between the turning points over a
// seek sweep (and reaches both), the energy recomputed from the state at t is E to round-off
// (an independent evaluation of 2.105 agrees; a perturbed state does not), the V(θ) inset is drawn.
import { test } from "node:test";
import assert from "node:assert/strict";
import { open, pixels, readouts, startLab, state } from "./harness.mjs";

await startLab();

/** Relative round-off of the exact solution's constants recomputed from its state (the core's
 * tests hold them to 1e-12 of their scale). */
const ROUND_OFF = 1e-12;
/** θ may overshoot a turning point by the round-off of sn² times the band. */
const BAND_TOL = 1e-10;
/** The perturbation of the negative control (rad/s): ΔE ≈ I₁ θ̇ · 1e-6 ≫ round-off. */
const PERTURBATION = 1e-6;

const PRESETS = ["loops", "waves", "cusps", "steady precession", "sleeping", "custom"];
const BASE = "scene=heavytop&paused=1";
const q = (preset, extra = "") => `?${BASE}&preset=${encodeURIComponent(preset)}${extra}`;

/** The energy 2.105 written out here, independently of the core. */
function energyOf(p, theta, thetaDot, phiDot, psiDot) {
  const s = Math.sin(theta), c = Math.cos(theta);
  const w3 = psiDot + phiDot * c;
  return 0.5 * p.I1 * (thetaDot ** 2 + (phiDot * s) ** 2) + 0.5 * p.I3 * w3 ** 2 + p.mgl * c;
}

/** Pixels of the V(θ) inset: distinct colours, painted fraction, and whether the curve (blue) and
 * the energy line (orange) are there. */
const insetPixels = (page) =>
  page.evaluate(() => {
    const c = document.querySelector("canvas.heavytop-potential");
    if (!c) return null;
    const d = c.getContext("2d").getImageData(0, 0, c.width, c.height).data;
    const colours = new Set();
    let painted = 0, blue = 0, orange = 0, white = 0;
    for (let i = 0; i < d.length; i += 4) {
      if (d[i + 3] === 0) continue;
      painted++;
      colours.add((d[i] << 16) | (d[i + 1] << 8) | d[i + 2]);
      const [r, g, b] = [d[i], d[i + 1], d[i + 2]];
      if (Math.abs(r - 0x7c) < 20 && Math.abs(g - 0xc4) < 20 && Math.abs(b - 0xff) < 20) blue++;
      if (Math.abs(r - 0xf2) < 20 && Math.abs(g - 0xb8) < 20 && Math.abs(b - 0x4b) < 20) orange++;
      if (r > 240 && g > 240 && b > 240) white++;
    }
    return { colours: colours.size, painted: painted / (d.length / 4), blue, orange, white, hash: Array.from(d).reduce((h, x, i) => (h + x * (i % 997)) % 1e9, 0) };
  });

for (const preset of PRESETS) {
  test(`heavytop ${preset}: loads, draws, shows the preset's motion class`, async () => {
    const { page, errors } = await open(q(preset, "&t=2.5"));
    const s = await state(page);
    assert.equal(s.scene, "heavytop");
    assert.equal(s.error, null);
    const px = await pixels(page);
    assert.ok(px.colours > 20 && px.busy > 0.03, `blank canvas: ${JSON.stringify(px)}`);
    const text = await page.locator("#readouts").innerText();
    assert.ok(!/NaN|undefined/.test(text), text);
    const r = await readouts(page);
    if (preset !== "custom") assert.equal(r.motionClass, preset);
    const [th1, th2] = r.turningPoints;
    if (preset === "steady precession" || preset === "sleeping") assert.ok(th2 - th1 <= 1e-10, `${th1} ${th2}`);
    else assert.ok(th2 - th1 > 1e-3, `${th1} ${th2}`);
    if (preset === "cusps") {
      // Released at rest in θ and φ: φ̇₀ = θ̇₀ = 0, θ₀ the upper turning point.
      assert.deepEqual(r.initialRates.slice(0, 2), [0, 0]);
      assert.ok(Math.abs(th1 - s.params.tilt * (Math.PI / 180)) < 1e-15); // the tilt slider's degrees, in rad
    }
    if (preset === "sleeping") assert.equal(r.sleepsStably, true);
    assert.deepEqual(errors, []);
    await page.close();
  });
}

test("heavytop: θ(t) stays within the turning points over a seek sweep and reaches both", async () => {
  for (const preset of ["loops", "waves", "cusps"]) {
    const { page, errors } = await open(q(preset));
    const r0 = await readouts(page);
    const [th1, th2] = r0.turningPoints;
    const period = r0.nutationPeriod;
    // The sweep runs in the page (one round trip): θ shown at each seek.
    const times = Array.from({ length: 121 }, (_, k) => k * period * 0.0613);
    const thetas = await page.evaluate((ts) => ts.map((tt) => { window.__lab.seek(tt); return window.__lab.readouts().angles[1]; }), times);
    let lo = Infinity, hi = -Infinity;
    for (const [k, theta] of thetas.entries()) {
      const t = times[k];
      assert.ok(theta >= th1 - BAND_TOL && theta <= th2 + BAND_TOL, `${preset} t=${t}: θ=${theta} ∉ [${th1}, ${th2}]`);
      lo = Math.min(lo, theta);
      hi = Math.max(hi, theta);
    }
    // 7.4 periods sampled 16 times each: both turning circles are reached (to 2 % of the band).
    const band = th2 - th1;
    assert.ok(lo - th1 < 0.02 * band && th2 - hi < 0.02 * band, `${preset}: θ spans [${lo}, ${hi}] of [${th1}, ${th2}]`);
    assert.deepEqual(errors, []);
    await page.close();
  }
});

test("heavytop: the energy recomputed from the state is E to round-off; a perturbed state is not", async () => {
  for (const preset of ["loops", "cusps", "custom"]) {
    const { page, errors } = await open(q(preset, "&tilt=100&phiDot0=-1.2&thetaDot0=0.7"));
    const p = Object.fromEntries(Object.entries((await state(page)).params).map(([k, v]) => [k, Number(v)]));
    let checked = 0;
    for (const t of [0, 0.37, 1.9, 4.25, 11.5, 27.3]) {
      await page.evaluate((tt) => window.__lab.seek(tt), t);
      const r = await readouts(page);
      const scale = Math.abs(r.energy) + 0.5 * p.I3 * r.omega3 ** 2 + p.mgl;
      assert.ok(Math.abs(r.energyNow - r.energy) <= ROUND_OFF * scale, `${preset} t=${t}: E(t)=${r.energyNow} E=${r.energy}`);
      const pscale = Math.abs(r.pPhi) + Math.abs(r.pPsi);
      assert.ok(Math.abs(r.pPhiNow - r.pPhi) <= ROUND_OFF * pscale, `${preset} t=${t}: p_phi`);
      assert.ok(Math.abs(r.pPsiNow - r.pPsi) <= ROUND_OFF * pscale, `${preset} t=${t}: p_psi`);
      // Independent 2.105 from the state shown; the perturbed state misses E by far.
      const [, theta] = r.angles;
      const [phiDot, thetaDot, psiDot] = r.rates;
      const mine = energyOf(p, theta, thetaDot, phiDot, psiDot);
      assert.ok(Math.abs(mine - r.energyNow) <= 10 * ROUND_OFF * scale, `${preset} t=${t}: independent E ${mine}`);
      if (Math.abs(thetaDot) > 0.05) {
        const bad = energyOf(p, theta, thetaDot + PERTURBATION, phiDot, psiDot);
        assert.ok(Math.abs(bad - r.energy) > 100 * ROUND_OFF * scale, `${preset} t=${t}: the perturbation is not seen`);
        checked++;
      }
      // E' = ½ I₁ θ̇² + V(θ) (2.109), V from the core at θ(t).
      const ePrime = 0.5 * p.I1 * thetaDot ** 2 + r.potentialNow;
      assert.ok(Math.abs(ePrime - r.reducedEnergy) <= 10 * ROUND_OFF * scale, `${preset} t=${t}: E' ${ePrime} vs ${r.reducedEnergy}`);
    }
    assert.ok(checked >= 2, `${preset}: the negative control ran ${checked} times`);
    assert.deepEqual(errors, []);
    await page.close();
  }
});

test("heavytop: the V(θ) inset is drawn and its dot follows θ(t)", async () => {
  const { page, errors } = await open(q("loops"));
  const a = await insetPixels(page);
  assert.ok(a, "no V(θ) canvas");
  assert.ok(a.colours > 20 && a.painted > 0.02, JSON.stringify(a));
  assert.ok(a.blue > 100, `the V(θ) curve is missing: ${JSON.stringify(a)}`);
  assert.ok(a.orange > 50, `the energy line is missing: ${JSON.stringify(a)}`);
  assert.ok(a.white > 10, `the state dot is missing: ${JSON.stringify(a)}`);
  const r = await readouts(page);
  await page.evaluate((tt) => window.__lab.seek(tt), r.nutationPeriod / 2);
  await page.waitForTimeout(200); // the inset is drawn with the next frame
  const b = await insetPixels(page);
  assert.notEqual(a.hash, b.hash, "the inset does not change with t");
  // Chromium's note on the test's own repeated getImageData is the only message allowed.
  assert.deepEqual(errors.filter((e) => !/Multiple readback operations using getImageData/.test(e)), []);
  await page.close();
});

test("heavytop: a spin below the minimum for steady precession shows the core's error", async () => {
  const { page, errors } = await open(q("steady precession", "&w3=1"));
  const alert = page.locator("#alert");
  assert.equal(await alert.isVisible(), true);
  assert.match(await alert.innerText(), /^PoinsotError: omega3: .*minimum spin/);
  assert.ok(!/NaN|undefined/.test(await page.locator("#readouts").innerText()));
  // The readouts of a valid spin say there is no steady precession below the minimum.
  const ok = await open(q("cusps", "&w3=1"));
  const r = await readouts(ok.page);
  assert.deepEqual(r.steadyRates, []);
  assert.ok(r.minSpin > 1);
  assert.deepEqual([...errors, ...ok.errors], []);
  await ok.page.close();
  await page.close();
});

test("heavytop: the precession period is one turn of the axis at the mean rate, in words; none where the axis does not turn", async () => {
  // Steady precession: φ̇ = the core's slow rate, constant; one turn every 2π/|φ̇| s, and φ turns
  // a quarter turn in a quarter period (read from the state shown, independently of the period).
  const { page, errors } = await open(q("steady precession", "&t=0"));
  const r = await readouts(page);
  const rate = Math.abs(r.meanPrecessionRate);
  assert.ok(rate > 0);
  assert.ok(Math.abs(r.precessionPeriod - (2 * Math.PI) / rate) <= 1e-12 * r.precessionPeriod, `${r.precessionPeriod}`);
  await page.evaluate((tt) => window.__lab.seek(tt), r.precessionPeriod / 4);
  const phi = (await readouts(page)).angles[0];
  assert.ok(Math.abs(Math.abs(phi) - Math.PI / 2) < 1e-9, `φ after a quarter period: ${phi}`);
  const cell = page.locator("#readouts dd[data-key=precessionPeriod], #pinned dd[data-key=precessionPeriod]").first();
  const text = await cell.innerText();
  assert.match(text, /^one turn every [\d.]+ s$/, text);
  assert.equal(Number(text.match(/[\d.]+/)[0]), Number(r.precessionPeriod.toPrecision(3)));
  assert.equal(await page.locator("#pinned dd[data-key=precessionPeriod]").count(), 1, "the period is pinned on the view");
  // A sleeping top: the axis stays upright, no turn: "—" with the reason, never a number or ∞.
  const sleeping = await open(q("sleeping"));
  const s = await readouts(sleeping.page);
  assert.equal(s.precessionPeriod, "Infinity");
  const none = await sleeping.page.locator("#readouts dd[data-key=precessionPeriod], #pinned dd[data-key=precessionPeriod]").first().innerText();
  assert.match(none, /^— \(the axis does not turn on average/, none);
  assert.deepEqual([...errors, ...sleeping.errors], []);
  await sleeping.page.close();
  await page.close();
});

test("heavytop: the tilt is in degrees on its slider, readouts and link; a link of the earlier lab (theta0 in rad) still opens", async () => {
  const { page, errors } = await open(q("cusps", "&tilt=30"));
  const label = await page.locator("#controls label[data-key=tilt]").innerText();
  assert.match(label, /tilt θ₀ \(°\)\s*30\b/, label);
  assert.ok(!/rad\b(?!\/)/.test(label), label);
  const r = await readouts(page);
  assert.ok(Math.abs(r.turningPoints[0] - Math.PI / 6) < 1e-15, `θ₁ = ${r.turningPoints[0]} rad for a 30° tilt`);
  const tp = await page.locator("#readouts dd[data-key=turningPoints], #pinned dd[data-key=turningPoints]").first().innerText();
  assert.equal(Number(tp.split(",")[0]), 30, tp);
  assert.match(await page.evaluate(() => location.search), /[?&]tilt=30(&|$)/);
  // The earlier lab's link: theta0=0.52 rad is a 29.79° tilt (not 0.52°), and the link written
  // back says tilt in degrees; a link with both keys takes tilt.
  const old = await open(q("cusps", "&theta0=0.52"));
  const p = (await state(old.page)).params;
  assert.ok(Math.abs(p.tilt - (0.52 * 180) / Math.PI) < 1e-12, `tilt ${p.tilt}`);
  assert.ok(Math.abs((await readouts(old.page)).turningPoints[0] - 0.52) < 1e-15);
  assert.match(await old.page.evaluate(() => location.search), /[?&]tilt=29\.79/);
  const both = await open(q("cusps", "&theta0=0.52&tilt=40"));
  assert.equal((await state(both.page)).params.tilt, 40);
  assert.deepEqual([...errors, ...old.errors, ...both.errors], []);
  for (const x of [page, old.page, both.page]) await x.close();
});
