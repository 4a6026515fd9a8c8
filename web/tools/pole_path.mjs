// Writes web/src/generated/pole_path.json (git-ignored; run by web/build.sh before the page is
// built): the real path of the Earth's rotation pole for the lab's scene "The Earth as a top",
// a further-decimated copy of the package's attributed extract of the IERS EOP 20 C04 series
// (python/poinsot/data/eop_c04_polar_motion.csv: mjd, x_arcsec, y_arcsec, every 5th day), every
// STRIDE-th row with the last one kept, values unchanged, the extract's '#' header (its source and
// terms) carried along so that the scene shows the attribution. The page bundles the JSON (the
// one-file lab too), so the scene needs no network.
//   node web/tools/pole_path.mjs
import { mkdirSync, readFileSync, writeFileSync } from "node:fs";
import path from "node:path";
import { fileURLToPath } from "node:url";

const here = path.dirname(fileURLToPath(import.meta.url));
const repo = path.resolve(here, "../..");
const SOURCE = path.join(repo, "python/poinsot/data/eop_c04_polar_motion.csv");
const OUT = path.join(repo, "web/src/generated/pole_path.json");
/** Every 4th row of the 5-day extract: a point every 20 days, about 22 per Chandler cycle. */
export const STRIDE = 4;

/** The extract's header lines (without '#') and its rows, decimated by `stride`. */
export function polePath(text, stride = STRIDE) {
  const header = [];
  const rows = [];
  let columns = null;
  for (const line of text.split(/\r?\n/)) {
    if (line.startsWith("#")) header.push(line.replace(/^#\s?/, ""));
    else if (!line.trim()) continue;
    else if (columns === null) columns = line.split(",").map((s) => s.trim());
    else rows.push(line.split(",").map(Number));
  }
  const want = ["mjd", "x_arcsec", "y_arcsec"];
  if (JSON.stringify(columns) !== JSON.stringify(want)) throw new Error(`${SOURCE}: columns ${columns}, expected ${want}`);
  for (const [i, r] of rows.entries()) {
    if (r.length !== 3 || !r.every(Number.isFinite)) throw new Error(`${SOURCE}: data row ${i + 1} is not three numbers`);
    if (i > 0 && !(r[0] > rows[i - 1][0])) throw new Error(`${SOURCE}: data row ${i + 1}: dates not increasing`);
  }
  const kept = rows.filter((_, i) => i % stride === 0 || i === rows.length - 1);
  return {
    source: header,
    stride,
    rows: rows.length,
    mjd: kept.map((r) => r[0]),
    x: kept.map((r) => r[1]),
    y: kept.map((r) => r[2]),
  };
}

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const data = polePath(readFileSync(SOURCE, "utf8"));
  mkdirSync(path.dirname(OUT), { recursive: true });
  writeFileSync(OUT, JSON.stringify(data) + "\n");
  console.log(`${path.relative(repo, OUT)}: ${data.mjd.length} of ${data.rows} rows`);
}
