// Checks of what the lab shows, shared by the browser tests (issue 12): rectangles that overlap,
// numbers not in the page's one format, more than one angle unit in a scene, a number shown with
// the wrong sign. Each is a pure function, so that its negative control runs without a browser.

/** Whether two rectangles {x, y, w, h} overlap by more than `hair` pixels each way. */
export function overlaps(a, b, hair = 0.5) {
  return a.x + a.w - hair > b.x && b.x + b.w - hair > a.x && a.y + a.h - hair > b.y && b.y + b.h - hair > a.y;
}

/** The pairs of named rectangles ([{id, rect}]) that overlap. */
export function overlappingPairs(items) {
  const out = [];
  for (let i = 0; i < items.length; i++) {
    for (let j = i + 1; j < items.length; j++) {
      if (overlaps(items[i].rect, items[j].rect)) out.push(`${items[i].id} × ${items[j].id}`);
    }
  }
  return out;
}

/** Whether `inner` lies inside `outer` (to a pixel). */
export const inside = (inner, outer, tol = 1) =>
  inner.x >= outer.x - tol && inner.y >= outer.y - tol && inner.x + inner.w <= outer.x + outer.w + tol && inner.y + inner.h <= outer.y + outer.h + tol;

/** The numbers written in a text: a sign (U+2212 or a hyphen-minus), digits, a decimal part, and
 * an exponent (`×10ⁿ` in superscripts, or an e-notation the page must not use). */
const NUMBER = /(^|[^\p{L}\p{N}_.])([−-]?)(\d+(?:\.\d+)?)((?:×10[⁻]?[⁰¹²³⁴⁵⁶⁷⁸⁹]+)|(?:[eE][+\-−]?\d+))?/gu;
const SUPER = { "⁰": 0, "¹": 1, "²": 2, "³": 3, "⁴": 4, "⁵": 5, "⁶": 6, "⁷": 7, "⁸": 8, "⁹": 9 };

/** The numbers of `text` as [{text, value, index}] (the value as the page means it). */
export function numbersIn(text) {
  const out = [];
  for (const m of text.matchAll(NUMBER)) {
    const [, , sign, digits, exp] = m;
    let e = 0;
    if (exp?.startsWith("×10")) {
      const sup = exp.slice(3);
      e = (sup.startsWith("⁻") ? -1 : 1) * Number([...sup.replace("⁻", "")].map((c) => SUPER[c]).join(""));
    } else if (exp) e = Number(exp.slice(1).replace("−", "-"));
    const value = (sign ? -1 : 1) * Number(`${digits}e${e}`);
    out.push({ text: `${sign}${digits}${exp ?? ""}`, value, index: m.index + m[1].length, before: text.slice(0, m.index + m[1].length) });
  }
  return out;
}

/** What is wrong with the numbers of `text` against the page's one format (docs/lab.md,
 * "Readouts"): e-notation, a hyphen-minus for a minus sign, NaN/undefined/Infinity. */
export function numberFormatProblems(text) {
  const problems = [];
  if (/NaN|undefined|Infinity|null/.test(text)) problems.push(`not a number: ${text}`);
  for (const n of numbersIn(text)) {
    if (/[eE]/.test(n.text)) problems.push(`e-notation "${n.text}" in "${text}"`);
    if (n.text.startsWith("-")) problems.push(`hyphen-minus "${n.text}" in "${text}"`);
  }
  return problems;
}

/** The angle units a set of texts uses: "°" and/or "rad". */
export function angleUnits(texts) {
  const units = new Set();
  for (const t of texts) {
    if (/°/.test(t)) units.add("°");
    if (/\brad\b/.test(t)) units.add("rad");
  }
  return [...units].sort();
}

/** The texts that show an angle in radians: "rad" or "radian(s)" not followed by a "per" ("/s",
 * "/s²", " per second"): a rate in rad/s is not an angle. The lab's one angle unit is degrees. */
export function radianAngles(texts) {
  return texts.filter((t) => /\brad\b(?!\s*\/)|\bradians?\b(?!\s+per\b)/.test(t));
}

/** Whether a readout's numbers have the signs of its value: a number, or an array shown as as
 * many numbers in order. A number shown as 0 (below the precision) has no sign to check; numbers
 * after "drift" or "change" are differences shown beside the value, not the value. */
export function signProblems(key, value, text) {
  const shown = numbersIn(text).filter((n) => !/(drift|change)\s*$/.test(n.before));
  const values = typeof value === "number" ? [value] : Array.isArray(value) && value.every((x) => typeof x === "number") ? value : null;
  if (!values || values.length === 0) return [];
  const problems = [];
  const check = (want, got) => {
    if (got.value === 0 || !Number.isFinite(want)) return;
    if (Math.sign(want) !== Math.sign(got.value)) problems.push(`${key}: ${got.text} shown for ${want} in "${text}"`);
  };
  if (values.length === 1) shown.forEach((n) => check(values[0], n));
  else if (shown.length === values.length) values.forEach((v, i) => check(v, shown[i]));
  return problems;
}
