// The built documentation site (docs/_build/html, `make docs`) in Debian's chromium: the home
// page, a page with rendered math (MathJax served by the site, no raw TeX left), the gallery
// with its images, the API page of HeavyTop, the embedded lab drawing its canvas, and the
// search. The site is served from loopback by a small static server, as a user's browser would
// read it; any request that leaves 127.0.0.1 fails the test (the site must work offline).
import { test } from "node:test";
import assert from "node:assert/strict";
import path from "node:path";
import { execFileSync } from "node:child_process";
import { existsSync } from "node:fs";
import { here, site, startSite } from "./serve.mjs";

const { base, browser } = await startSite();

/** Opens `page` of the site; returns the page and the problems seen (console errors, failed
 * or off-site requests, 404s). */
async function open(rel, viewport = { width: 1280, height: 800 }) {
  const page = await browser.newPage({ viewport });
  const problems = [];
  page.on("console", (m) => { if (m.type() === "error") problems.push(`console: ${m.text()}`); });
  page.on("pageerror", (e) => problems.push(`page error: ${e.message}`));
  page.on("request", (r) => { if (!r.url().startsWith(base) && !r.url().startsWith("data:") && !r.url().startsWith("blob:")) problems.push(`off-site request: ${r.url()}`); });
  page.on("response", (r) => { if (r.status() >= 400) problems.push(`${r.status()}: ${r.url()}`); });
  await page.goto(base + rel, { waitUntil: "networkidle" });
  return { page, problems };
}

test("the home page links every part of the companion", async () => {
  const { page, problems } = await open("index.html");
  const links = await page.$$eval("a", (as) => as.map((a) => a.getAttribute("href")));
  for (const want of ["getting_started.html", "gallery/index.html", "api.html", "cli.html", "lab.html"]) {
    assert.ok(links.some((h) => h && h.endsWith(want)), `no link to ${want}`);
  }
  assert.deepEqual(problems, []);
  await page.close();
});

test("math is typeset by the site's own MathJax, no raw TeX is left", async () => {
  const { page, problems } = await open("getting_started.html");
  await page.waitForSelector("mjx-container", { timeout: 20000 });
  const n = await page.$$eval("mjx-container", (xs) => xs.length);
  assert.ok(n >= 3, `only ${n} formulas typeset`);
  const text = await page.$eval("article", (a) => a.innerText);
  assert.ok(!text.includes("$$") && !text.includes("\\(") && !/\\frac|\\mathbf|\\omega/.test(text), "raw TeX in the page");
  const scripts = await page.$$eval("script[src]", (s) => s.map((x) => x.src));
  assert.ok(scripts.some((s) => s.startsWith(base) && s.includes("mathjax")), "MathJax is not served by the site");
  assert.deepEqual(problems, []);
  await page.close();
});

test("a page that cites the unit's equations shows them: eq. 2.42 on the Earth page", async () => {
  const { page, problems } = await open("earth.html");
  await page.waitForSelector("#the-unit-s-equations-on-this-page mjx-container", { timeout: 20000 });
  const items = await page.$$eval("#the-unit-s-equations-on-this-page li", (xs) => xs.map((x) => x.innerText.split("\n")[0]));
  assert.ok(items.some((t) => t.startsWith("(2.42)")), `items: ${items.join(" / ")}`);
  // every item is typeset, none is raw TeX
  const raw = await page.$$eval("#the-unit-s-equations-on-this-page li", (xs) => xs.filter((x) => !x.querySelector("mjx-container")).length);
  assert.equal(raw, 0);
  assert.deepEqual(problems, []);
  await page.close();
});

test("the gallery shows every example with the figures drawn at build time", async () => {
  const { page, problems } = await open("gallery/index.html");
  const thumbs = await page.$$eval(".sphx-glr-thumbcontainer", (xs) => xs.length);
  assert.ok(thumbs >= 10, `${thumbs} examples in the gallery`);
  await page.goto(base + "gallery/heavy_top.html", { waitUntil: "networkidle" });
  const images = await page.$$eval("img.sphx-glr-single-img, img.sphx-glr-multi-img", (xs) => xs.map((i) => [i.naturalWidth, i.src]));
  assert.ok(images.length >= 2, `${images.length} figures on the heavy-top example`);
  for (const [w, src] of images) assert.ok(w > 100, `figure ${src} did not load`);
  assert.deepEqual(problems, []);
  await page.close();
});

test("the API page of HeavyTop documents its parameters with units", async () => {
  const { page, problems } = await open("generated/poinsot.HeavyTop.html");
  const text = await page.$eval("article", (a) => a.innerText);
  assert.match(text, /class poinsot\.HeavyTop/);
  assert.match(text, /kg m\^2|kg·m²/);
  for (const name of ["turning_points", "motion_class", "effective_potential"]) assert.ok(text.includes(name), `no ${name}`);
  assert.deepEqual(problems, []);
  await page.close();
});

test("every public name has its API page", () => {
  const python = process.env.PYTHON ?? path.join(here, "..", "..", ".venv", "bin", "python");
  const script = `
import importlib, json
out = []
for mod in ("poinsot", "poinsot.plots", "poinsot.special"):
    m = importlib.import_module(mod)
    out += [f"{mod}.{n}" for n in m.__all__ if n != "__version__"]
print(json.dumps(out))`;
  const names = JSON.parse(execFileSync(python, ["-c", script], { encoding: "utf8" }));
  assert.ok(names.length > 80, `${names.length} public names`);
  const missing = names.filter((n) => !existsSync(path.join(site, "generated", `${n}.html`)));
  assert.deepEqual(missing, []);
  // negative control: a name that is not public has no page
  assert.equal(existsSync(path.join(site, "generated", "poinsot._validate.html")), false);
});

test("the lab ships inside the site and draws its canvas", async () => {
  const doc = await open("lab.html");
  const hrefs = await doc.page.$$eval("article a", (as) => as.map((a) => a.getAttribute("href")));
  assert.ok(hrefs.includes("lab/index.html"), "the lab page does not link the embedded lab");
  await doc.page.close();
  const { page, problems } = await open("lab/index.html?scene=heavytop");
  const canvas = await page.waitForSelector("canvas", { timeout: 20000 });
  await page.waitForTimeout(1500);
  const box = await canvas.boundingBox();
  assert.ok(box && box.width > 200 && box.height > 200, "no canvas");
  const shot = await canvas.screenshot();
  // A drawn scene is not one flat colour: count distinct byte values of the PNG's pixels'
  // compressed stream as a cheap proxy (a blank canvas compresses to a few hundred bytes).
  assert.ok(shot.length > 5000, `the canvas looks blank (${shot.length} bytes)`);
  assert.deepEqual(problems.filter((p) => !/GPU stall due to ReadPixels/.test(p)), []);
  await page.close();
});

test("the search finds HeavyTop", async () => {
  const { page, problems } = await open("search.html?q=HeavyTop");
  await page.waitForFunction(() => document.querySelectorAll("#search-results li").length > 0, null, { timeout: 20000 });
  const hits = await page.$$eval("#search-results li a", (as) => as.map((a) => a.textContent));
  assert.ok(hits.some((h) => h.includes("HeavyTop")), `hits: ${hits.slice(0, 5)}`);
  assert.deepEqual(problems, []);
  await page.close();
});

test("negative control: a missing page is reported", async () => {
  const { page, problems } = await open("no-such-page.html");
  assert.ok(problems.some((p) => p.startsWith("404")));
  await page.close();
});
