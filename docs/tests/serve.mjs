// The built site (docs/_build/html, or $SITE) served from loopback by a small static server, and
// Debian's chromium (playwright-core, headless), for the site's browser tests. Each test file
// calls `startSite()` once at its top level; both stop after the file's tests.
import { after } from "node:test";
import http from "node:http";
import { readFile, stat } from "node:fs/promises";
import path from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";

export const here = path.dirname(fileURLToPath(import.meta.url));
export const site = path.resolve(process.env.SITE ?? path.join(here, "..", "_build", "html"));

const TYPES = {
  ".html": "text/html; charset=utf-8", ".js": "text/javascript", ".mjs": "text/javascript",
  ".css": "text/css", ".json": "application/json", ".png": "image/png", ".gif": "image/gif",
  ".svg": "image/svg+xml", ".wasm": "application/wasm", ".woff": "font/woff",
  ".woff2": "font/woff2", ".ttf": "font/ttf", ".txt": "text/plain", ".inv": "application/octet-stream",
  ".ico": "image/x-icon", ".mp4": "video/mp4",
};

/** Serves the site on 127.0.0.1 and starts chromium; returns `{ base, browser }`. */
export async function startSite() {
  const server = http.createServer(async (req, res) => {
    const url = new URL(req.url, "http://127.0.0.1");
    let file = path.join(site, decodeURIComponent(url.pathname));
    if (!file.startsWith(site)) { res.writeHead(403).end(); return; }
    try {
      if ((await stat(file)).isDirectory()) file = path.join(file, "index.html");
      const body = await readFile(file);
      res.writeHead(200, { "content-type": TYPES[path.extname(file)] ?? "application/octet-stream" });
      res.end(body);
    } catch {
      res.writeHead(404).end("not found");
    }
  });
  await new Promise((r) => server.listen(0, "127.0.0.1", r));
  const base = `http://127.0.0.1:${server.address().port}/`;
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
    headless: true,
    args: ["--headless", "--no-sandbox", "--disable-gpu", "--enable-unsafe-swiftshader",
      "--disable-background-networking", "--disable-component-update", "--disable-sync", "--no-first-run"],
  });
  after(async () => {
    await browser.close();
    server.close();
  });
  return { base, browser };
}
