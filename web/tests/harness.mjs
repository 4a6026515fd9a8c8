// The browser-test harness of the lab: starts `poinsot lab` (or uses LAB_URL) and Debian chromium
// (playwright-core, headless, WebGL through SwiftShader), and gives the tests a page with its
// console errors collected. Each test file calls `startLab()` once at the top level.
//
// Environment: LAB_URL (a running `poinsot lab`; otherwise one is started with $PYTHON, default
// ../.venv/bin/python), CHROMIUM (default /usr/bin/chromium).
import { after } from "node:test";
import { spawn } from "node:child_process";
import { fileURLToPath } from "node:url";
import path from "node:path";
import { chromium } from "playwright-core";

export const here = path.dirname(fileURLToPath(import.meta.url));
export const repo = path.resolve(here, "../..");
/** The one console warning the tests cause themselves (reading the WebGL canvas back). */
const BENIGN_WARNING = /GL Driver Message \(OpenGL, Performance, [A-Z_]+, High\): GPU stall due to ReadPixels/;

let browser;
let server;
let base;

/** Start the server and the browser (once per test file); both stop after the file's tests. */
export async function startLab() {
  if (browser) return;
  if (process.env.LAB_URL) {
    base = process.env.LAB_URL;
  } else {
    const python = process.env.PYTHON ?? path.join(repo, ".venv/bin/python");
    server = spawn(python, ["-m", "poinsot", "lab", "--no-browser"], { stdio: ["ignore", "pipe", "inherit"] });
    base = await new Promise((resolve, reject) => {
      let text = "";
      server.stdout.on("data", (d) => {
        text += d;
        const m = text.match(/serving (http:\/\/127\.0\.0\.1:\d+\/)/);
        if (m) resolve(m[1]);
      });
      server.on("exit", (code) => reject(new Error(`poinsot lab exited (${code}): ${text}`)));
      setTimeout(() => reject(new Error(`poinsot lab did not start: ${text}`)), 20000);
    });
  }
  browser = await launchChromium();
  after(async () => {
    await browser?.close();
    server?.kill();
  });
}

/** Debian's chromium (or CHROMIUM), headless, WebGL through SwiftShader, no background traffic:
 * the browser of every browser test (the lab's, the exported file's, the widget's). */
export const launchChromium = () => chromium.launch({
  executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
  headless: true,
  args: ["--headless", "--no-sandbox", "--disable-gpu", "--enable-unsafe-swiftshader",
    "--disable-background-networking", "--disable-component-update", "--disable-sync", "--no-first-run"],
});

/** The console errors and warnings and the uncaught exceptions of `page` from now on, collected
 * into the array returned. */
export function collectErrors(page) {
  const errors = [];
  page.on("console", (msg) => {
    // The tests' own pixel read-back makes SwiftShader log a performance note; anything else counts.
    if (msg.type() === "warning" && BENIGN_WARNING.test(msg.text())) return;
    if (msg.type() === "error" || msg.type() === "warning") errors.push(`${msg.type()}: ${msg.text()}`);
  });
  page.on("pageerror", (e) => errors.push(`pageerror: ${e.message}`));
  return errors;
}

/** The page's URL for a query such as `?scene=top&paused=1`. */
export const urlFor = (query) => new URL(query, base).href;

/** Open the page at `query`, collecting console errors and uncaught exceptions; `beforeLoad`, a
 * function, runs in the page before its scripts (playwright's addInitScript); `reducedMotion`
 * ("reduce" or "no-preference") emulates the user's prefers-reduced-motion. */
export async function open(query, viewport = { width: 1200, height: 800 }, { beforeLoad, reducedMotion } = {}) {
  const page = await browser.newPage({ viewport, ...(reducedMotion ? { reducedMotion } : {}) });
  if (beforeLoad) await page.addInitScript(beforeLoad);
  const errors = collectErrors(page);
  await page.goto(urlFor(query));
  await page.waitForFunction(() => window.__lab?.ready && window.__lab.frames > 3, null, { timeout: 30000 });
  return { page, errors };
}

/** Distinct colours on a 32×32 grid of the WebGL canvas (the lab's, or the one `canvas` selects),
 * and the fraction of non-background cells (optionally of the region `x0..x1` of the canvas
 * width, as fractions). */
export async function pixels(page, x0 = 0, x1 = 1, canvas = "#view canvas") {
  return page.evaluate(([a, b, selector]) => {
    const src = document.querySelector(selector);
    const c = document.createElement("canvas");
    c.width = 32; c.height = 32;
    const g = c.getContext("2d");
    g.drawImage(src, a * src.width, 0, (b - a) * src.width, src.height, 0, 0, 32, 32);
    const d = g.getImageData(0, 0, 32, 32).data;
    const colours = new Set();
    let busy = 0;
    for (let i = 0; i < d.length; i += 4) {
      colours.add((d[i] << 16) | (d[i + 1] << 8) | d[i + 2]);
      if (Math.abs(d[i] - 0x10) + Math.abs(d[i + 1] - 0x14) + Math.abs(d[i + 2] - 0x18) > 24) busy++;
    }
    return { colours: colours.size, busy: busy / (d.length / 4) };
  }, [x0, x1, canvas]);
}

/** The scene's readouts at full precision, by key. */
export const readouts = (page) => page.evaluate(() => window.__lab.readouts());
/** The shell's state: scene, params, t, playing, error. */
export const state = (page) => page.evaluate(() => ({ scene: window.__lab.scene, params: window.__lab.params, t: window.__lab.t, playing: window.__lab.playing, error: window.__lab.error }));
/** The ids of every scene of the page, in tab order. */
export async function sceneIds() {
  const { page } = await open("?paused=1");
  const ids = await page.evaluate(() => window.__lab.scenes);
  await page.close();
  return ids;
}
