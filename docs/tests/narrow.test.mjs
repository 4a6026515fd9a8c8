// The site on a phone and as a download (issue 23, items 2 and 7), in Debian's chromium:
// * at 390 px wide, the equation index and the pages with wide tables: no element wider than the
//   screen except inside a container that scrolls sideways, no table's text squeezed to a few letters a
//   line, and the equation index as long as a page can be read (it was 139,000 px, names one
//   letter per line); a negative control undoes the fix and must be caught;
// * each notebook's page links its .ipynb, which the site carries (a download);
// * the lab page offers the lab as one file, which the site carries too.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readdirSync } from "node:fs";
import path from "node:path";
import { here, startSite } from "./serve.mjs";

const { base, browser } = await startSite();
const PHONE = { width: 390, height: 844 };
/** The equation index on a phone must stay under this height (px): about 19,500 are measured;
 * squeezed to the screen's width it was 141,700. */
const MAX_INDEX_HEIGHT = 30000;
/** A table's text whose words are broken across lines with fewer characters a line than this,
 * on average, is broken letter by letter (a test name of 75 characters on 30 lines, as the
 * equation index had); a readable column holds 15 or more. */
const MIN_CHARS_PER_LINE = 8;
/** Pages with the widest tables, besides the equation index. */
const WIDE_TABLE_PAGES = ["equations.html", "lab.html", "inertia.html", "earth.html", "conventions.html", "naming.html"];

/** At the page's current size: elements that stick out of the screen outside any sideways
 * scrolling container, texts broken letter by letter, the page's height and width. */
function measure(page) {
  return page.evaluate((minChars) => {
    const vw = document.documentElement.clientWidth;
    const fits = (r) => r.right <= vw + 1 && r.left >= -1;
    const out = [];
    for (const el of document.querySelectorAll("body *")) {
      const r = el.getBoundingClientRect();
      if (r.width === 0 || r.height === 0 || fits(r)) continue;
      let a = el.parentElement;
      let scrolled = false;
      for (; a && a !== document.body; a = a.parentElement) {
        if (/(auto|scroll|hidden|clip)/.test(getComputedStyle(a).overflowX) && fits(a.getBoundingClientRect())) { scrolled = true; break; }
      }
      if (!scrolled) out.push(`${el.tagName.toLowerCase()}.${el.className} [${Math.round(r.left)}, ${Math.round(r.right)}]`);
    }
    // A text squeezed to a letter or two a line: words broken across lines (more lines, the
    // distinct tops of its line boxes, than words) with fewer than minChars characters a line.
    const narrow = [];
    const walker = document.createTreeWalker(document.querySelector("article") ?? document.body, NodeFilter.SHOW_TEXT);
    const range = document.createRange();
    for (let n = walker.nextNode(); n; n = walker.nextNode()) {
      const text = n.textContent.trim();
      if (text.length < 12 || !n.parentElement?.closest("td, th") || n.parentElement.closest("mjx-container")) continue;
      range.selectNodeContents(n);
      const lines = new Set([...range.getClientRects()].filter((r) => r.width > 0).map((r) => Math.round(r.top))).size;
      const words = text.split(/[\s/‐–—-]+/).length; // a hyphen or a slash may end a line
      if (lines > words && text.length / lines < minChars) narrow.push(`${lines} lines for ${text.length} characters: ${text.slice(0, 40)}`);
    }
    return { overflow: out, narrow, height: document.documentElement.scrollHeight, width: document.documentElement.scrollWidth, vw };
  }, MIN_CHARS_PER_LINE);
}

async function openPage(rel, viewport = PHONE) {
  const page = await browser.newPage({ viewport });
  const problems = [];
  page.on("pageerror", (e) => problems.push(`page error: ${e.message}`));
  page.on("request", (r) => { if (!r.url().startsWith(base) && !/^(data|blob):/.test(r.url())) problems.push(`off-site request: ${r.url()}`); });
  page.on("response", (r) => { if (r.status() >= 400) problems.push(`${r.status()}: ${r.url()}`); });
  await page.goto(base + rel, { waitUntil: "networkidle" });
  // MathJax typesets after the load: measure the page as it ends up
  await page.waitForFunction(() => !document.querySelector("script[src*=mathjax]") || (window.MathJax?.startup?.promise !== undefined), null, { timeout: 20000 });
  await page.evaluate(() => window.MathJax?.startup?.promise);
  return { page, problems };
}

for (const rel of WIDE_TABLE_PAGES) {
  test(`${rel} at 390 px: nothing wider than the screen outside a sideways scroll, no squeezed cell`, async () => {
    const { page, problems } = await openPage(rel);
    const m = await measure(page);
    assert.equal(m.width, m.vw, "the page itself scrolls sideways");
    assert.deepEqual(m.overflow, []);
    assert.deepEqual(m.narrow, []);
    if (rel === "equations.html") {
      assert.ok(m.height < MAX_INDEX_HEIGHT, `the equation index is ${m.height} px long at 390 px`);
      if (process.env.SHOTS) await page.screenshot({ path: path.join(process.env.SHOTS, "equations-390.png") });
    }
    assert.deepEqual(problems, []);
    await page.close();
  });
}

test("negative control: the equation index squeezed to the screen is caught", async () => {
  const { page } = await openPage("equations.html");
  await page.addStyleTag({ content: "#equation-index table { min-width: 0 !important; } .bd-article table td { min-width: 0 !important; }" });
  const m = await measure(page);
  assert.ok(m.height > MAX_INDEX_HEIGHT, `${m.height} px`);
  assert.ok(m.narrow.length > 0);
  await page.close();
});

const notebooks = readdirSync(path.join(here, "..", "..", "notebooks")).filter((f) => f.endsWith(".ipynb")).sort();

test("each notebook's page links its notebook, and the site carries it", async () => {
  assert.ok(notebooks.length >= 4, `notebooks: ${notebooks}`);
  for (const nb of notebooks) {
    const name = nb.replace(/\.ipynb$/, "");
    const { page, problems } = await openPage(`notebooks/${name}.html`, { width: 1280, height: 800 });
    const link = page.locator("article p.poinsot-download a");
    assert.equal(await link.count(), 1, `${name}: no download link`);
    assert.equal(await link.getAttribute("href"), nb);
    // right under the title
    const after = await page.evaluate(() => document.querySelector("article p.poinsot-download")?.previousElementSibling?.tagName);
    assert.equal(after, "H1");
    const res = await page.request.get(new URL(nb, page.url()).href);
    assert.equal(res.status(), 200);
    const json = JSON.parse(await res.text());
    assert.ok(Array.isArray(json.cells) && json.nbformat === 4, `${nb} is not a notebook`);
    assert.deepEqual(problems, []);
    await page.close();
  }
});

test("the lab page offers the lab as one file, and the site carries it", async () => {
  const { page, problems } = await openPage("lab.html", { width: 1280, height: 800 });
  const link = page.locator('article a[href="lab/poinsot-lab.html"]');
  assert.ok(await link.count() >= 1, "no link to lab/poinsot-lab.html");
  const res = await page.request.get(base + "lab/poinsot-lab.html");
  assert.equal(res.status(), 200);
  const body = await res.text();
  assert.ok(body.length > 1e6 && body.length < 4e6 && body.includes("Content-Security-Policy"), `${body.length} bytes`);
  assert.deepEqual(problems, []);
  await page.close();
});
