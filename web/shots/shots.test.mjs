// One screenshot of each scene of the built lab, as Debian's chromium draws it at 1280×800, for
// the documentation's pages (docs/_ext/pictures.py shows them: the lab page, the topic pages).
// Each scene must load and run without a console error; the pictures go to LAB_SHOTS (default
// docs/_generated/lab, git-ignored) with scenes.json, the list of the scenes shot in tab order.
// `make lab-shots` (which `make docs` runs) runs it; it lives outside web/tests/ so that
// `make test-web` does not take the same pictures a second time.
import { test } from "node:test";
import assert from "node:assert/strict";
import { mkdirSync, writeFileSync, statSync } from "node:fs";
import path from "node:path";
import { startLab, open, repo } from "../tests/harness.mjs";

const OUT = process.env.LAB_SHOTS ?? path.join(repo, "docs/_generated/lab");
// The tabs' order (web/src/scenes/index.ts); a test below checks the page agrees.
const SCENES = ["frames", "drop", "foucault", "low", "inertia", "euler", "freetop", "poinsot", "heavytop", "earthtop", "gyrocompass"];

await startLab();
mkdirSync(OUT, { recursive: true });

test("the page's tabs are the scenes shot, in order", async () => {
  const { page, errors } = await open("?scene=frames");
  assert.deepEqual(await page.evaluate(() => window.__lab.scenes), SCENES);
  assert.deepEqual(errors, []);
  await page.close();
});

for (const scene of SCENES) {
  test(`screenshot of ${scene}`, async () => {
    const { page, errors } = await open(`?scene=${scene}`, { width: 1280, height: 800 });
    // Let the motion run a little (a trail, a rosette), then hold still for the picture.
    await page.waitForFunction(() => window.__lab.frames > 90, null, { timeout: 30000 });
    const file = path.join(OUT, `${scene}.png`);
    await page.screenshot({ path: file });
    assert.deepEqual(errors, [], `${scene}: console errors`);
    assert.ok(statSync(file).size > 20000, `${scene}: the picture is nearly empty`);
    await page.close();
  });
}

test("scenes.json lists the pictures", () => {
  writeFileSync(path.join(OUT, "scenes.json"), JSON.stringify(SCENES) + "\n");
});
