// The lab's sliders: where a slider's thumb may stop (its grid of values, linear in steps or
// logarithmic over decades), how its value is said (with its unit, in words for a screen reader,
// rpm beside rad/s), and how a move the core refuses is resolved so that every state a slider can
// reach is valid (`resolve`).
//
// The rules of validity are the core's, never restated here: a move is tried on the scene (the
// core builds its objects or throws an error naming the argument at fault, "I3: must be <= 2*I1
// ..."); when the core names another slider than the one moved, that slider follows to the
// nearest value the core accepts (I₃ down with I₁, the amplitude down with the length); when it
// names the moved slider, the moved slider stops at the last value the core accepts. Both are
// searched by bisection on the sliders' grids (a handful of tries).
import { fmtStep, type NumberParam, type Param, type Params } from "./scene";

/** Revolutions per minute in 1 rad/s. */
export const RPM_PER_RAD_S = 60 / (2 * Math.PI);

/** The mantissas of a logarithmic slider's values in each decade: steps of 2 % or less (0.02
 * from 1 to 2, 0.05 from 2 to 5, 0.1 from 5 to 10), round numbers a student can read. */
const MANTISSAS: number[] = (() => {
  const out: number[] = [];
  for (let m = 100; m < 200; m += 2) out.push(m / 100);
  for (let m = 200; m < 500; m += 5) out.push(m / 100);
  for (let m = 500; m < 1000; m += 10) out.push(m / 100);
  return out;
})();

const grids = new WeakMap<NumberParam, number[]>();
/** The values a slider's thumb can take, ascending: `min + k·step` on a linear slider; on a
 * logarithmic one the round values (MANTISSAS × 10ⁿ) from `min` to `max`, both ends included. */
export function grid(spec: NumberParam): number[] {
  let out = grids.get(spec);
  if (out) return out;
  out = [];
  if (spec.scale === "log") {
    out.push(spec.min);
    for (let e = Math.floor(Math.log10(spec.min)); e <= Math.ceil(Math.log10(spec.max)); e++) {
      for (const m of MANTISSAS) {
        const x = Number((m * 10 ** e).toPrecision(3));
        if (x > out[out.length - 1] * (1 + 1e-9) && x < spec.max * (1 - 1e-9)) out.push(x);
      }
    }
    out.push(spec.max);
  } else {
    const n = Math.round((spec.max - spec.min) / spec.step);
    for (let k = 0; k <= n; k++) out.push(Number((spec.min + k * spec.step).toFixed(12)));
  }
  grids.set(spec, out);
  return out;
}

/** The input's range attributes (min, max, step) for a slider: a logarithmic slider's input
 * moves over the indices of its grid. */
export function inputRange(spec: NumberParam): { min: string; max: string; step: string } {
  return spec.scale === "log"
    ? { min: "0", max: String(grid(spec).length - 1), step: "1" }
    : { min: String(spec.min), max: String(spec.max), step: String(spec.step) };
}

/** The input's position for a value (on a log scale, the grid's value nearest in ratio). */
export function toInput(spec: NumberParam, value: number): string {
  if (spec.scale !== "log") return String(value);
  const g = grid(spec);
  let best = 0;
  for (let i = 1; i < g.length; i++) if (Math.abs(Math.log(g[i] / value)) < Math.abs(Math.log(g[best] / value))) best = i;
  return String(best);
}

/** The value at the input's position. */
export function fromInput(spec: NumberParam, position: string): number {
  if (spec.scale !== "log") return Number(position);
  const g = grid(spec);
  return g[Math.min(g.length - 1, Math.max(0, Math.round(Number(position))))];
}

/** A slider's value as its output shows it: the decimals of its step (3 significant digits on a
 * log scale), and the rpm beside a spin in rad/s. */
export function valueText(spec: NumberParam, x: number): string {
  const s = spec.scale === "log" ? plain(x) : fmtStep(x, spec.step);
  if (spec.unit === "rad/s" && Math.abs(x) >= 10) return `${s} (${rpm(x)} rpm)`;
  return s;
}

/** A spin (rad/s) in whole revolutions per minute. */
function rpm(x: number): string {
  return String(Math.round(x * RPM_PER_RAD_S)).replace("-", "−");
}

/** A value of a logarithmic slider's grid as it is (at most 3 significant digits, no trailing
 * zeros): 9, 0.5, 0.0021. */
function plain(x: number): string {
  return String(Number(x.toPrecision(3))).replace("-", "−");
}

/** Units in words, for a screen reader (aria-valuetext). */
const UNIT_WORDS: Record<string, [string, string]> = {
  "°": ["degree", "degrees"],
  "rad/s": ["radian per second", "radians per second"],
  "rad/s²": ["radian per second squared", "radians per second squared"],
  "°/s": ["degree per second", "degrees per second"],
  m: ["metre", "metres"],
  "m/s": ["metre per second", "metres per second"],
  "mm/s²": ["millimetre per second squared", "millimetres per second squared"],
  kg: ["kilogram", "kilograms"],
  "kg/m³": ["kilogram per cubic metre", "kilograms per cubic metre"],
  "kg·m²": ["kilogram square metre", "kilogram square metres"],
  "N·m": ["newton metre", "newton metres"],
  "N/m": ["newton per metre", "newtons per metre"],
  "10⁻⁵/s": ["times 10 to the minus 5 per second", "times 10 to the minus 5 per second"],
  "× spin": ["times the spin", "times the spin"],
};

/** What a screen reader says for a slider's value: "30 degrees", "157 radians per second (1500 rpm)". */
export function ariaValueText(spec: NumberParam, x: number): string {
  const n = (spec.scale === "log" ? plain(x) : fmtStep(x, spec.step)).replace("−", "minus ");
  const words = UNIT_WORDS[spec.unit];
  const unit = words ? words[Math.abs(x) === 1 ? 0 : 1] : spec.unit;
  const beside = spec.unit === "rad/s" && Math.abs(x) >= 10 ? ` (${rpm(x).replace("−", "minus ")} rpm)` : "";
  return `${n} ${unit}${beside}`.trim();
}

/** The argument an error of the core names ("I3: must be ..." → "I3"), and its condition. */
export function namedArgument(e: unknown): { argument: string; condition: string } | null {
  const m = /^([A-Za-z_][\w.]*): ([\s\S]*)$/.exec(String((e as { message?: string })?.message ?? ""));
  return m ? { argument: m[1], condition: m[2] } : null;
}

/** The condition of a core message without its ", got …" tail (the student sees the value). */
function condition(text: string): string {
  return text.replace(/,? got [\s\S]*$/, "").replace(/\s+/g, " ").trim();
}

/** How a move was resolved: the parameters now on screen, and a sentence (or null if the move
 * was taken as it was). `refused`: nothing the core accepts was found (the last valid state stays). */
export interface Resolution {
  params: Params;
  note: string | null;
  refused: boolean;
}

/**
 * Resolves the move of slider `key` to `value` from the valid parameters `last`: `trial(p)`
 * configures the scene with `p` and returns the core's error, or null when it accepts them
 * (the caller configures the scene with the returned parameters afterwards). `keyOf` maps a core
 * argument to a parameter key.
 */
export function resolve(params: Param[], last: Params, key: string, value: number | string, trial: (p: Params) => unknown, keyOf: (argument: string) => string): Resolution {
  const want = { ...last, [key]: value };
  const e = trial(want);
  if (e === null) return { params: want, note: null, refused: false };
  const moved = params.find((p) => p.key === key);
  const named = namedArgument(e);
  const other = named ? params.find((p): p is NumberParam => p.kind === "number" && p.key === keyOf(named.argument)) : undefined;
  const because = (err: unknown) => {
    const n = namedArgument(err);
    return n ? `${n.argument} ${condition(n.condition)}` : String((err as Error)?.message ?? err);
  };
  const why = because(e);
  const name = (p: Param) => p.label;
  const say = (p: NumberParam, x: number) => `${valueText(p, x)}${p.unit ? ` ${p.unit}` : ""}`;
  // Another slider is at fault: it follows to its nearest value the core accepts.
  if (other && other.key !== key) {
    const follow = nearestValid(other, Number(want[other.key]), (x) => trial({ ...want, [other.key]: x }) === null);
    if (follow !== null) {
      const p = { ...want, [other.key]: follow };
      const note = moved?.kind === "choice"
        ? `${name(other)} moved to ${say(other, follow)} for ${name(moved)} “${value}”: ${why}.`
        : `${name(other)} followed ${moved ? name(moved) : key} to ${say(other, follow)}: ${why}.`;
      return { params: p, note, refused: false };
    }
  }
  // The moved slider stops at the last value the core accepts on its way.
  if (moved?.kind === "number") {
    const stop = lastValid(moved, Number(last[key]), Number(value), (x) => trial({ ...last, [key]: x }) === null);
    if (stop !== null) {
      // The reason is the core's at the first value past the stop.
      const past = stop.next === null ? e : trial({ ...last, [key]: stop.next });
      return { params: { ...last, [key]: stop.value }, note: `${name(moved)} stops at ${say(moved, stop.value)}: ${past === null ? why : because(past)}.`, refused: false };
    }
    return { params: last, note: `${name(moved)} cannot go to ${say(moved, Number(value))}: ${why}.`, refused: true };
  }
  return { params: last, note: `${moved ? name(moved) : key} cannot be “${value}” with the other settings: ${why}.`, refused: true };
}

/** The index of the grid value nearest x. */
function indexOf(g: number[], x: number): number {
  let best = 0;
  for (let i = 1; i < g.length; i++) if (Math.abs(g[i] - x) < Math.abs(g[best] - x)) best = i;
  return best;
}

/** Between a valid index `ok` and an invalid index `bad` (validity one interval along the way),
 * the valid index nearest `bad`. */
function bisect(ok: number, bad: number, valid: (i: number) => boolean): number {
  while (Math.abs(bad - ok) > 1) {
    const mid = Math.trunc((ok + bad) / 2);
    if (valid(mid)) ok = mid;
    else bad = mid;
  }
  return ok;
}

/** The slider's valid value nearest x (x itself invalid), or null: a try at each end of the
 * grid, then bisection towards x from each valid end. */
function nearestValid(spec: NumberParam, x: number, valid: (x: number) => boolean): number | null {
  const g = grid(spec);
  const i0 = indexOf(g, x);
  const ok = (i: number) => valid(g[i]);
  let best: number | null = null;
  for (const end of [0, g.length - 1]) {
    if (end === i0 || !ok(end)) continue;
    const i = bisect(end, i0, ok);
    if (best === null || Math.abs(i - i0) < Math.abs(best - i0)) best = i;
  }
  return best === null ? null : g[best];
}

/** On the way from the valid value `from` to the refused `to`, the last value the core accepts
 * and the grid's next value towards `to` (null when there is none). */
function lastValid(spec: NumberParam, from: number, to: number, valid: (x: number) => boolean): { value: number; next: number | null } | null {
  const g = grid(spec);
  const a = indexOf(g, from), b = indexOf(g, to);
  if (!valid(g[a])) return null;
  if (a === b) return { value: g[a], next: null };
  const i = bisect(a, b, (k) => valid(g[k]));
  return { value: g[i], next: g[i + Math.sign(b - a)] };
}
