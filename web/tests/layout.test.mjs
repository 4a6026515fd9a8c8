// Browser tests of the lab's layout (issue 12, "The lab"), for every scene at 1280×800 and on a
// phone (390×844): the pinned readouts lie inside the first viewport and are not cut; the HUD
// (titles, insets, pinned readouts, view buttons) does not overlap itself or the scene's main
// object (its projected screen box); the page does not scroll, and on a phone the view and the
// controls are on the screen together; slider values are not clipped; the tabs are compact;
// no console errors. Each case saves a screenshot into web/screenshots/ (git-ignored) for review.
//
// Environment: see harness.mjs; SCREENSHOTS (default web/screenshots).
import { test } from "node:test";
import assert from "node:assert/strict";
import { mkdirSync } from "node:fs";
import path from "node:path";
import { here, open, sceneIds, startLab } from "./harness.mjs";
import { inside, overlappingPairs, overlaps } from "./view_checks.mjs";

await startLab();
const SCENES = await sceneIds();
const SIZES = [[1280, 800], [390, 844]];
const SHOTS = process.env.SCREENSHOTS ?? path.join(here, "../screenshots");
mkdirSync(SHOTS, { recursive: true });
/** The main object must be drawn at least this large (a fraction of the stage's smaller side):
 * a framing that shrinks it to a speck to keep clear of the HUD fails. */
const MIN_MAIN = 0.25;

/** The states shown besides each scene's default: the heavy top's V(θ) inset unfolded on a phone,
 * a Foucault run where −Ω sin λ does not apply (the warning is pinned), the tumbling box, a
 * Chasles displacement, a landing point off the drawing, the equator of the low (no inertial
 * circle). */
const EXTRA = [
  { name: "heavytop-inset", query: "scene=heavytop", act: async (page) => { if (await page.locator(".heavytop-inset button[aria-expanded=false]").count()) await page.locator(".heavytop-inset button").click(); } },
  { name: "foucault-warning", query: "scene=foucault&length=80&amplitude=3" },
  { name: "poinsot-box", query: "scene=poinsot&view=tumbling+box" },
  { name: "inertia-chasles", query: "scene=inertia&motion=Chasles" },
  { name: "drop-offscale", query: "scene=drop&height=500&exaggeration=10000" },
  { name: "low-equator", query: "scene=low&latitude=0" },
];
const CASES = [...SCENES.map((s) => ({ name: s, query: `scene=${s}` })), ...EXTRA];

/** Everything the layout checks read, in page pixels. */
async function measure(page) {
  return page.evaluate(() => {
    const box = (el) => {
      const r = el.getBoundingClientRect();
      return { x: r.left, y: r.top, w: r.width, h: r.height };
    };
    const lay = window.__lab.layout();
    const shift = (r) => ({ x: r.x + lay.stage.x, y: r.y + lay.stage.y, w: r.w, h: r.h });
    const cut = (el) => el.scrollWidth > el.clientWidth + 1 || el.scrollHeight > el.clientHeight + 1;
    const visibleOutputs = [...document.querySelectorAll("#controls label:not([hidden]) output")];
    const panel = document.getElementById("panel");
    const firstControl = document.querySelector("#controls label:not([hidden])");
    return {
      viewport: { x: 0, y: 0, w: innerWidth, h: innerHeight },
      stage: lay.stage,
      huds: lay.huds.map((h) => ({ id: h.id, rect: shift(h.rect) })),
      main: lay.main.map(shift),
      free: lay.free.map(shift),
      pinned: [...document.querySelectorAll("#pinned dt, #pinned dd")].map((el) => ({ text: el.textContent, rect: box(el), cut: cut(el) })),
      canvas: box(document.querySelector("#view canvas")),
      ariaLabel: document.querySelector("#view canvas").getAttribute("aria-label") ?? "",
      scroll: { height: document.scrollingElement.scrollHeight, width: document.scrollingElement.scrollWidth },
      outputs: visibleOutputs.map((o) => ({ text: o.textContent, rect: box(o), cut: cut(o) })),
      panel: { rect: box(panel), inner: panel.getBoundingClientRect().left + panel.clientLeft + panel.clientWidth },
      firstControl: firstControl ? box(firstControl) : null,
      nav: box(document.getElementById("scenes")),
    };
  });
}

for (const c of CASES) {
  for (const [width, height] of SIZES) {
    test(`${c.name} at ${width}×${height}: pinned readouts on screen, HUD clear of itself and the main object, no scrolling page`, async () => {
      const { page, errors } = await open(`?${c.query}&paused=1&t=2`, { width, height });
      if (c.act) await c.act(page);
      // A few frames for the HUD to settle and the camera to frame the scene around it.
      await page.waitForTimeout(400);
      await page.screenshot({ path: path.join(SHOTS, `${c.name}-${width}x${height}.png`) });
      const m = await measure(page);
      const where = `${c.name} ${width}×${height}`;

      // The pinned readouts: 3 or more, every label and value inside the first viewport, none cut.
      assert.ok(m.pinned.length >= 6, `${where}: ${m.pinned.length / 2} pinned readouts`);
      for (const p of m.pinned) {
        assert.ok(inside(p.rect, m.viewport), `${where}: pinned "${p.text}" at ${JSON.stringify(p.rect)} is outside the viewport`);
        assert.ok(inside(p.rect, m.stage), `${where}: pinned "${p.text}" is not on the canvas`);
        assert.ok(!p.cut, `${where}: pinned "${p.text}" is cut`);
      }
      // The HUD: no two elements overlap; none overlaps the main object, which lies in its free
      // part of the stage and is drawn large enough to see.
      assert.ok(m.huds.some((h) => h.id === "pinned"), `${where}: the pinned readouts are not in the HUD`);
      assert.deepEqual(overlappingPairs(m.huds), [], `${where}: HUD elements overlap`);
      assert.ok(m.main.length >= 1, `${where}: no main object measured`);
      for (const box of m.main) {
        for (const h of m.huds) assert.ok(!overlaps(h.rect, box), `${where}: ${h.id} ${JSON.stringify(h.rect)} covers the main object ${JSON.stringify(box)}`);
        assert.ok(inside(box, m.stage, 2), `${where}: the main object ${JSON.stringify(box)} leaves the view ${JSON.stringify(m.stage)}`);
        assert.ok(Math.max(box.w, box.h) >= MIN_MAIN * Math.min(m.stage.w, m.stage.h) / m.main.length, `${where}: the main object is drawn too small: ${JSON.stringify(box)}`);
      }
      // The page itself never scrolls: the view and the controls are on the screen together.
      assert.ok(m.scroll.height <= height + 1 && m.scroll.width <= width + 1, `${where}: the page scrolls: ${JSON.stringify(m.scroll)}`);
      assert.ok(inside(m.canvas, m.viewport), `${where}: the canvas leaves the viewport`);
      assert.ok(m.firstControl && inside(m.firstControl, m.viewport), `${where}: the first control is not on the screen`);
      assert.ok(!overlaps(m.firstControl, m.canvas), `${where}: the first control covers the view`);
      // Slider values: inside the panel's content box, not cut.
      for (const o of m.outputs) {
        assert.ok(o.rect.x + o.rect.w <= m.panel.inner + 0.5 && !o.cut, `${where}: slider value "${o.text}" is clipped (${o.rect.x + o.rect.w} > ${m.panel.inner})`);
      }
      // Compact tabs on a phone: one row.
      if (width < 800) assert.ok(m.nav.h <= 40, `${where}: the scene tabs are ${m.nav.h} px tall`);
      assert.match(m.ariaLabel, /arrow keys/);
      assert.deepEqual(errors, [], where);
      await page.close();
    });
  }
}

test("negative control: a pinned box moved over the view's titles is caught", async () => {
  const { page, errors } = await open("?scene=frames&paused=1", { width: 390, height: 844 });
  await page.addStyleTag({ content: ".pinned { top: 0; bottom: auto !important; }" });
  await page.waitForTimeout(300);
  const m = await measure(page);
  const pairs = overlappingPairs(m.huds);
  assert.ok(pairs.some((p) => p.includes("pinned") && p.includes("frames-title")), `not caught: ${JSON.stringify(m.huds)}`);
  assert.deepEqual(errors, []);
  await page.close();
});

test("negative control: the overlap and containment checks", () => {
  const a = { x: 0, y: 0, w: 10, h: 10 };
  assert.equal(overlaps(a, { x: 9, y: 9, w: 5, h: 5 }), true);
  assert.equal(overlaps(a, { x: 10, y: 0, w: 5, h: 5 }), false); // touching is not overlapping
  assert.deepEqual(overlappingPairs([{ id: "a", rect: a }, { id: "b", rect: { x: 5, y: 5, w: 1, h: 1 } }]), ["a × b"]);
  assert.equal(inside({ x: 2, y: 2, w: 5, h: 5 }, a), true);
  assert.equal(inside({ x: 8, y: 2, w: 5, h: 5 }, a), false);
});
