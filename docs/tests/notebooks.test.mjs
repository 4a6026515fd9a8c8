// The teaching notebooks as the built site shows them (docs/_build/html/notebooks, executed by
// myst-nb when the site was built) in Debian's chromium: the notebooks page lists every
// notebook of the repository's notebooks/ folder, and each notebook's page has its equations
// typeset by the site's MathJax without a TeX error (a \tag inside the split environment Sphinx
// wraps round a multi-line equation is one) and within the text column, its figures drawn,
// its outputs there and no traceback among them, and no request leaving the site.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readdir } from "node:fs/promises";
import path from "node:path";
import { here, startSite } from "./serve.mjs";

const notebooks = (await readdir(path.join(here, "..", "..", "notebooks")))
  .filter((f) => f.endsWith(".ipynb"))
  .map((f) => f.slice(0, -".ipynb".length))
  .sort();
// A display equation may overhang the text column by this many pixels (sub-pixel rounding).
const OVERHANG_PX = 1;

const { base, browser } = await startSite();

/** Opens `rel` of the site; returns the page and the problems seen (console errors, failed or
 * off-site requests, 404s). */
async function open(rel) {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  const problems = [];
  page.on("console", (m) => { if (m.type() === "error") problems.push(`console: ${m.text()}`); });
  page.on("pageerror", (e) => problems.push(`page error: ${e.message}`));
  page.on("request", (r) => { if (!r.url().startsWith(base) && !r.url().startsWith("data:")) problems.push(`off-site request: ${r.url()}`); });
  page.on("response", (r) => { if (r.status() >= 400) problems.push(`${r.status()}: ${r.url()}`); });
  await page.goto(base + rel, { waitUntil: "networkidle" });
  return { page, problems };
}

/** What is wrong with the typeset math of the open page: TeX errors MathJax shows in place of a
 * formula, TeX left untypeset, display equations wider than the text column. */
async function mathProblems(page) {
  await page.waitForSelector("mjx-container", { timeout: 20000 });
  await page.evaluate(() => window.MathJax.startup.promise);
  return page.evaluate((overhang) => {
    const out = [];
    for (const e of document.querySelectorAll("mjx-merror")) {
      out.push(`TeX error: ${e.getAttribute("data-mjx-error") ?? e.textContent}`);
    }
    const text = document.querySelector("article").innerText;
    for (const raw of ["$$", "\\[", "\\(", "\\frac", "\\tag", "\\vec"]) {
      if (text.includes(raw)) out.push(`raw TeX left: ${raw}`);
    }
    const column = document.querySelector("article").getBoundingClientRect();
    for (const c of document.querySelectorAll('mjx-container[display="true"]')) {
      const math = c.querySelector("mjx-math").getBoundingClientRect();
      if (math.left < column.left - overhang || math.right > column.right + overhang) {
        out.push(`equation wider than the column (${Math.round(math.width)} px in ${Math.round(column.width)} px): ${c.textContent.slice(0, 40)}`);
      }
    }
    return out;
  }, OVERHANG_PX);
}

test("the notebooks page lists every notebook of notebooks/", async () => {
  assert.ok(notebooks.length >= 4, `only ${notebooks.length} notebooks`);
  const { page, problems } = await open("notebooks.html");
  const links = await page.$$eval("article a", (as) => as.map((a) => a.getAttribute("href")));
  for (const nb of notebooks) {
    assert.ok(links.some((h) => h && h.endsWith(`notebooks/${nb}.html`)), `no link to ${nb}`);
  }
  assert.deepEqual(problems, []);
  await page.close();
});

for (const nb of notebooks) {
  test(`notebook ${nb}: equations typeset and in the column, figures drawn, outputs shown`, async () => {
    const { page, problems } = await open(`notebooks/${nb}.html`);
    assert.deepEqual(await mathProblems(page), []);
    const images = await page.$$eval("article .cell_output img", (xs) =>
      xs.map((i) => ({ done: i.complete, w: i.naturalWidth, h: i.naturalHeight })));
    assert.ok(images.length >= 1, "no figure");
    for (const im of images) assert.ok(im.done && im.w > 100 && im.h > 100, JSON.stringify(im));
    const outputs = await page.$$eval("article .cell_output", (xs) => xs.map((x) => x.innerText));
    assert.ok(outputs.some((t) => /\d/.test(t)), "no printed number among the outputs");
    assert.ok(!outputs.some((t) => t.includes("Traceback")), "a traceback among the outputs");
    const title = await page.$eval("article h1", (h) => h.innerText);
    assert.ok(title.length > 5, "no title");
    assert.deepEqual(problems, []);
    await page.close();
  });
}

test("negative control: a TeX error and an equation wider than the column are reported", async () => {
  const { page } = await open(`notebooks/${notebooks[0]}.html`);
  assert.deepEqual(await mathProblems(page), []);
  await page.evaluate(async () => {
    const article = document.querySelector("article");
    for (const tex of ["\\[\\begin{split}a &= b\\\\ &= c \\tag{9.9}\\end{split}\\]",
      `\\[${Array.from({ length: 60 }, (_, k) => `x_{${k}}`).join(" + ")}\\]`]) {
      const div = document.createElement("div");
      div.className = "math";
      div.textContent = tex;
      article.append(div);
    }
    await window.MathJax.typesetPromise();
  });
  const found = await mathProblems(page);
  assert.ok(found.some((p) => p.startsWith("TeX error")), JSON.stringify(found));
  assert.ok(found.some((p) => p.startsWith("equation wider than the column")), JSON.stringify(found));
  await page.close();
});
