// The Poinsot / tumbling-box scene: both views draw; the contact point of the rolling ellipsoid
// lies on the ellipsoid and on the invariable plane to round-off; the box spun about its
// intermediate axis flips (ω's component on it reverses twice per period) and, the negative
// control, does not when spun about the axis of the smallest moment.
import { test } from "node:test";
import assert from "node:assert/strict";
import { open, pixels, readouts, startLab, state } from "./harness.mjs";

/** ρ·I·ρ − 1 and ρ·L̂/d − 1 (relative): ρ is ω/(2T)^½ from the exact solution, whose T and |L|
 * are conserved to ~1e-13 relative (the core's free-body tests). */
const CONTACT_TOL = 1e-12;
/** Samples per period when looking for sign changes of ω on the spun axis. */
const SAMPLES = 64;

await startLab();

const BOX = "?scene=poinsot&view=tumbling+box&paused=1";
const ELLIPSOID = "?scene=poinsot&view=Poinsot+ellipsoid&paused=1";

async function seek(page, t) {
  await page.evaluate((x) => window.__lab.seek(x), t);
  return readouts(page);
}

for (const [name, query] of [["Poinsot ellipsoid", ELLIPSOID], ["tumbling box", BOX]]) {
  test(`poinsot: the ${name} view loads, draws and shows no NaN`, async () => {
    const { page, errors } = await open(query.replace("&paused=1", "&t=2.5"));
    await page.waitForTimeout(400);
    const px = await pixels(page);
    assert.ok(px.colours > 20 && px.busy > 0.03, `blank canvas: ${JSON.stringify(px)}`);
    const s = await state(page);
    assert.equal(s.error, null);
    assert.equal(s.params.view, name);
    const text = await page.locator("#readouts").innerText();
    assert.ok(!/NaN|undefined/.test(text), text);
    assert.deepEqual(errors, []);
    await page.close();
  });
}

test("poinsot: the two views draw different pictures", async () => {
  const a = await open(`${ELLIPSOID}&t=1`);
  const b = await open(`${BOX}&t=1`);
  const shot = (p) => p.locator("#view canvas").screenshot();
  assert.notDeepEqual(await shot(a.page), await shot(b.page));
  await a.page.close();
  await b.page.close();
});

test("poinsot: the contact point lies on the ellipsoid and on the invariable plane", async () => {
  for (const q of [ELLIPSOID, `${ELLIPSOID}&axis=smallest&eps=0.4`, `${ELLIPSOID}&axis=largest&eps=1&spin=9.5&a=0.05&b=0.3&c=0.2`]) {
    const { page, errors } = await open(q);
    for (const t of [0, 0.7, 3.1, 17.25, 123.4]) {
      const r = await seek(page, t);
      const [onEllipsoid, onPlane] = r.contactResidual;
      assert.ok(Math.abs(onEllipsoid) < CONTACT_TOL && Math.abs(onPlane) < CONTACT_TOL, `${q} t=${t}: ${r.contactResidual}`);
      // Conservation shown live: T(t) and |L(t)| recomputed from ω(t) agree with the constants.
      assert.ok(Math.abs(r.energyNow / r.energy - 1) < CONTACT_TOL, `T drift at t=${t}`);
      assert.ok(Math.abs(r.angularMomentumNow / r.angularMomentum - 1) < CONTACT_TOL, `|L| drift at t=${t}`);
      assert.ok(r.planeDistance > 0);
    }
    assert.deepEqual(errors, []);
    await page.close();
  }
});

/** ω on the spun axis at SAMPLES + 1 times over one period of the exact solution. */
async function spinOverOnePeriod(query) {
  const { page, errors } = await open(query);
  const r0 = await readouts(page);
  assert.equal(typeof r0.period, "number", `finite period expected: ${r0.period}`);
  const values = [];
  for (let k = 0; k <= SAMPLES; k++) values.push((await seek(page, (r0.period * k) / SAMPLES)).spinComponent);
  assert.deepEqual(errors, []);
  await page.close();
  return { r0, values };
}

const signChanges = (v) => v.slice(1).filter((x, i) => Math.sign(x) !== Math.sign(v[i])).length;

test("poinsot: spun about the intermediate axis the box flips, twice per period", async () => {
  const { r0, values } = await spinOverOnePeriod(`${BOX}&axis=intermediate&eps=0.02`);
  assert.equal(r0.stability.split(", ")[r0.spunAxis], "unstable");
  assert.match(r0.regime, /^about (max|min) axis$/);
  assert.ok(Math.abs(2 * r0.flipInterval / r0.period - 1) < 1e-12);
  assert.ok(values[0] > 0);
  assert.equal(signChanges(values), 2, JSON.stringify(values));
  // Half a period later (the flip interval) the spin has reversed: the box turned over.
  const { page } = await open(`${BOX}&axis=intermediate&eps=0.02&t=${r0.flipInterval}`);
  const r = await readouts(page);
  assert.ok(r.spinComponent < -0.9 * r0.spinComponent, `${r.spinComponent} vs ${r0.spinComponent}`);
  await page.close();
});

test("poinsot: negative control, spun about the smallest-moment axis it never flips", async () => {
  // The same perturbation, a larger one too: the spin about the stable axis only wobbles.
  for (const eps of [0.02, 0.2]) {
    const { r0, values } = await spinOverOnePeriod(`${BOX}&axis=smallest&eps=${eps}`);
    assert.equal(r0.stability.split(", ")[r0.spunAxis], "stable");
    assert.equal(r0.regime, "about min axis");
    assert.equal(signChanges(values), 0, JSON.stringify(values));
    assert.ok(Math.min(...values) > 0.5 * values[0]);
  }
});

test("poinsot: no perturbation, a steady spin; the readouts say so without NaN", async () => {
  const { page, errors } = await open(`${BOX}&axis=intermediate&eps=0&t=50`);
  const r = await readouts(page);
  assert.equal(r.regime, "steady");
  assert.equal(r.period, "Infinity");
  assert.ok(r.spinComponent > 0);
  assert.ok(!/NaN|undefined/.test(await page.locator("#readouts").innerText()));
  assert.deepEqual(errors, []);
  await page.close();
});
