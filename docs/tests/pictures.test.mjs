// Pictures on the site (issue 23, item 3): every topic page, the unit's figures page, the lab page
// and the home page show pictures made at build time (docs/_ext/pictures.py: the unit's figures
// drawn by the installed poinsot, the lab's scenes shot in chromium by web/shots/shots.test.mjs);
// the gallery has a real thumbnail for every example, in the unit's order; no page shows a path
// of the machine that built it, and no page loads a script or a style from another host.
import { test } from "node:test";
import assert from "node:assert/strict";
import path from "node:path";
import { readFileSync, readdirSync, statSync } from "node:fs";
import { createHash } from "node:crypto";
import { here, site, startSite } from "./serve.mjs";

const { base, browser } = await startSite();
const repo = path.resolve(here, "..", "..");

/** The pictures of `rel` that the browser loaded, inside the page's article: [naturalWidth, src]. */
async function pictures(rel) {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  const problems = [];
  page.on("response", (r) => { if (r.status() >= 400) problems.push(`${r.status()}: ${r.url()}`); });
  await page.goto(base + rel, { waitUntil: "networkidle" });
  // Lazy images load when scrolled to; ask each to load now.
  await page.$$eval("article img", (xs) => xs.forEach((i) => { i.loading = "eager"; i.scrollIntoView(); }));
  await page.waitForFunction(() => [...document.querySelectorAll("article img")].every((i) => i.complete), null, { timeout: 20000 });
  const imgs = await page.$$eval("article img", (xs) => xs.map((i) => [i.naturalWidth, i.getAttribute("src")]));
  await page.close();
  return { imgs, problems };
}

// Each page and the least number of pictures it must show (the unit's figures: all 18, 2.12 in four
// steps; the lab:
// its nine scenes).
const PAGES = {
  "index.html": 1, "frames.html": 2, "earth.html": 4, "inertia.html": 2, "dynamics.html": 2,
  "rotation.html": 6, "heavy_top.html": 3, "figures.html": 18, "lab.html": 9,
};

for (const [rel, least] of Object.entries(PAGES)) {
  test(`${rel} shows its pictures`, async () => {
    const { imgs, problems } = await pictures(rel);
    const loaded = imgs.filter(([w]) => w > 100);
    assert.ok(loaded.length >= least, `${rel}: ${loaded.length} pictures loaded, ${least} expected (${JSON.stringify(imgs)})`);
    assert.deepEqual(problems, []);
  });
}

test("negative control: a page without pictures is seen as one", async () => {
  const { imgs } = await pictures("conventions.html");
  assert.equal(imgs.filter(([w]) => w > 100).length, 0);
});

test("every example of the gallery has a figure and a thumbnail of its own, in the unit's order", async () => {
  const page = await browser.newPage();
  await page.goto(base + "gallery/index.html", { waitUntil: "networkidle" });
  const entries = await page.$$eval(".sphx-glr-thumbcontainer", (xs) => xs.map((x) => [x.querySelector("a")?.getAttribute("href") ?? x.querySelector("a.reference")?.getAttribute("href"), x.querySelector("img")?.getAttribute("src")]));
  // The order the site promises (docs/_ext/pictures.py's GALLERY_ORDER).
  const text = readFileSync(path.join(repo, "docs", "_ext", "pictures.py"), "utf8");
  const order = [...text.match(/GALLERY_ORDER = \[([^\]]*)\]/)[1].matchAll(/"([a-z_]+)\.py"/g)].map((m) => m[1]);
  const names = entries.map(([href]) => href.replace(/\.html.*$/, "").replace(/^.*\//, ""));
  assert.deepEqual(names, order);
  // A thumbnail is the example's own figure: sphinx-gallery's placeholder (the same picture for
  // every example without a figure) would repeat.
  const hashes = entries.map(([, src]) => createHash("sha256").update(readFileSync(path.join(site, "gallery", src))).digest("hex"));
  assert.equal(new Set(hashes).size, hashes.length, "two examples share a thumbnail (a placeholder)");
  for (const name of names) {
    await page.goto(base + `gallery/${name}.html`, { waitUntil: "networkidle" });
    const figs = await page.$$eval("img.sphx-glr-single-img, img.sphx-glr-multi-img", (xs) => xs.length);
    assert.ok(figs >= 1, `the example ${name} draws no figure (its thumbnail is a placeholder)`);
  }
  await page.close();
});

/** Every HTML file of the site. */
function htmlFiles(dir = site) {
  return readdirSync(dir).flatMap((n) => {
    const p = path.join(dir, n);
    if (statSync(p).isDirectory()) return n === "_static" || n === "lab" ? [] : htmlFiles(p);
    return n.endsWith(".html") ? [p] : [];
  });
}

test("no page shows a path of the machine that built it", () => {
  const bad = htmlFiles().filter((f) => {
    const s = readFileSync(f, "utf8");
    return s.includes(repo + "/") || s.includes("_build/gallery_out");
  });
  assert.deepEqual(bad.map((f) => path.relative(site, f)), []);
});

test("no page loads a script or a style from another host", () => {
  const remote = /<script\b[^>]*\bsrc="(?:https?:)?\/\/|<link\b(?=[^>]*\brel="(?:stylesheet|preload|modulepreload)")[^>]*\bhref="(?:https?:)?\/\//;
  const bad = htmlFiles().filter((f) => remote.test(readFileSync(f, "utf8")));
  assert.deepEqual(bad.map((f) => path.relative(site, f)), []);
  // negative control: the pattern sees one
  assert.ok(remote.test('<script src="https://code.jquery.com/jquery-3.7.0.js"></script>'));
  assert.ok(remote.test('<link href="https://cdn.datatables.net/x.css" rel="stylesheet" />'));
  assert.ok(!remote.test('<link rel="canonical" href="https://example.org/poinsot/" />'));
});
