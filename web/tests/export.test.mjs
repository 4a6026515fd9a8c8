// The lab as one file (`poinsot lab --export`, issue 23 item 2), as a teacher hands it out and a
// student opens it: exported by the CLI into a folder whose name has a space and an accent, opened
// from file:// in Debian's chromium (no server at all). Every scene loads and draws with no console
// error; the page makes no request but file:, data: and blob: (it is offline); the share link is
// the file's own address with the state in its query, opens the same state again, and the page
// says it was copied — or, the clipboard refused, shows it to copy by hand — and where it works.
// The served lab's share link (`poinsot lab`) is the page's own host, and says it works on this
// computer while poinsot lab runs.
import { test, after } from "node:test";
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import { mkdtempSync, rmSync, statSync, mkdirSync } from "node:fs";
import { tmpdir } from "node:os";
import path from "node:path";
import { pathToFileURL } from "node:url";
import { repo, startLab, open as openServed, launchChromium, collectErrors, pixels } from "./harness.mjs";

const python = process.env.PYTHON ?? path.join(repo, ".venv/bin/python");
const dir = mkdtempSync(path.join(tmpdir(), "poinsot-export-"));
const folder = path.join(dir, "für die Klasse");
mkdirSync(folder);
const file = path.join(folder, "poinsot-lab.html");
execFileSync(python, ["-m", "poinsot", "lab", "--export", file], { stdio: "inherit" });
const fileUrl = pathToFileURL(file).href;
/** Where to keep the screenshots to look at (SHOTS=folder); none are kept otherwise. */
const shots = process.env.SHOTS;
const shoot = async (page, name) => { if (shots) await page.screenshot({ path: path.join(shots, `export-${name}.png`) }); };

const browser = await launchChromium();
await startLab();
after(async () => {
  await browser.close();
  rmSync(dir, { recursive: true, force: true });
});

/** Opens the exported file at `query`; returns the page, its console problems and every request
 * that is not file:, data: or blob:. `beforeLoad` runs in the page before its scripts. */
async function openFile(query = "", { viewport = { width: 1200, height: 800 }, beforeLoad } = {}) {
  const page = await browser.newPage({ viewport });
  if (beforeLoad) await page.addInitScript(beforeLoad);
  const problems = collectErrors(page);
  const requests = [];
  page.on("request", (r) => { if (!/^(file|data|blob):/.test(r.url())) requests.push(r.url()); });
  await page.goto(fileUrl + query);
  await page.waitForFunction(() => window.__lab?.ready && window.__lab.frames > 3, null, { timeout: 30000 });
  return { page, problems, requests };
}

test("the exported lab is one file small enough to e-mail", () => {
  const size = statSync(file).size;
  assert.ok(size > 1e6 && size < 4e6, `${size} bytes`);
});

test("every scene of the exported lab loads from file:// with no error and no request", async () => {
  const { page, problems, requests } = await openFile();
  const ids = await page.evaluate(() => window.__lab.scenes);
  assert.ok(ids.length >= 9, `scenes: ${ids}`);
  for (const [i, id] of ids.entries()) {
    await page.locator("#scenes button").nth(i).click();
    const f0 = await page.evaluate(() => window.__lab.frames);
    await page.waitForFunction((f) => window.__lab.frames > f + 5, f0, { timeout: 30000 });
    const s = await page.evaluate(() => ({ scene: window.__lab.scene, error: window.__lab.error, t: window.__lab.t }));
    assert.equal(s.scene, id);
    assert.equal(s.error, null, `${id}: ${s.error}`);
    // it draws: the canvas is not the bare background
    const { busy } = await pixels(page);
    assert.ok(busy > 0.01, `${id}: the view is empty (${busy})`);
    await shoot(page, `scene-${id}`);
  }
  assert.deepEqual(problems, []);
  assert.deepEqual(requests, []);
  await page.close();
});

test("share in the exported lab: the file's own link, copied or shown, says it works on this computer", async () => {
  // The clipboard answers: "Link copied".
  const ok = await openFile("?scene=heavytop", {
    beforeLoad: () => {
      Object.defineProperty(navigator, "clipboard", { value: { writeText: (t) => { window.__copied = t; return Promise.resolve(); } } });
    },
  });
  await ok.page.locator("#share").click();
  await ok.page.waitForFunction(() => /Link copied/.test(document.getElementById("share-note").textContent));
  const note = await ok.page.locator("#share-note").innerText();
  assert.match(note, /works on this computer/);
  const link = await ok.page.locator("#share-url").inputValue();
  assert.equal(await ok.page.evaluate(() => window.__copied), link);
  assert.ok(link.startsWith(fileUrl + "?"), link);
  assert.match(link, /[?&]scene=heavytop(&|$)/);
  assert.ok(!link.includes("127.0.0.1"));
  await shoot(ok.page, "share-copied");
  const params = await ok.page.evaluate(() => window.__lab.params);
  // the link opens the same scene and parameters
  const again = await openFile(link.slice(fileUrl.length));
  assert.equal(await again.page.evaluate(() => window.__lab.scene), "heavytop");
  assert.deepEqual(await again.page.evaluate(() => window.__lab.params), params);
  assert.deepEqual([...ok.problems, ...again.problems], []);
  assert.deepEqual([...ok.requests, ...again.requests], []);
  await ok.page.close();
  await again.page.close();

  // The clipboard refuses (as a browser may for a page opened from a file): the link is shown,
  // selected, with a sentence asking to copy it by hand.
  const no = await openFile("?scene=poinsot", {
    beforeLoad: () => {
      Object.defineProperty(navigator, "clipboard", { value: { writeText: () => Promise.reject(new DOMException("denied", "NotAllowedError")) } });
    },
  });
  await no.page.locator("#share").click();
  await no.page.waitForFunction(() => /by hand/.test(document.getElementById("share-note").textContent));
  assert.match(await no.page.locator("#share-note").innerText(), /Copy this link by hand.*works on this computer/);
  assert.equal(await no.page.evaluate(() => document.activeElement?.id), "share-url");
  const sel = await no.page.evaluate(() => { const e = document.getElementById("share-url"); return e.value.slice(e.selectionStart, e.selectionEnd); });
  assert.ok(sel.startsWith(fileUrl + "?scene=poinsot"), sel);
  await shoot(no.page, "share-by-hand");
  assert.deepEqual(no.problems, []);
  await no.page.close();

  // The browser's own clipboard, whatever it answers for a file: some sentence is shown.
  const real = await openFile("?scene=frames");
  await real.page.locator("#share").click();
  await real.page.waitForFunction(() => /Link copied|by hand/.test(document.getElementById("share-note").textContent), null, { timeout: 5000 });
  assert.deepEqual(real.problems, []);
  await real.page.close();
});

test("share in the served lab: the page's own host, working on this computer while poinsot lab runs", async () => {
  const { page, errors } = await openServed("?scene=euler", undefined, {
    beforeLoad: () => {
      Object.defineProperty(navigator, "clipboard", { value: { writeText: () => Promise.resolve() } });
    },
  });
  await page.locator("#share").click();
  await page.waitForFunction(() => /Link copied/.test(document.getElementById("share-note").textContent));
  const link = await page.locator("#share-url").inputValue();
  const origin = await page.evaluate(() => location.origin + location.pathname);
  assert.ok(link.startsWith(origin + "?scene=euler"), link);
  assert.match(await page.locator("#share-note").innerText(), /works on this computer while poinsot lab runs/);
  assert.deepEqual(errors, []);
  await page.close();
});
