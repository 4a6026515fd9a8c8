// The contract between the lab's shell (main.ts) and its scenes. A scene declares its
// parameters (which become sliders/selects and URL fields), builds its three.js objects once,
// rebuilds its physics objects (from the wasm core) when a parameter changes, and evaluates them
// at time t. Scenes hold no physics of their own: every number comes from the core.
//
// How numbers are shown (docs/lab.md, "Readouts"): one format for every number of the page
// (`fmt`), a value within a few ε of the scale of the quantities it was computed from shown as 0,
// and one angle unit for the whole lab, degrees (`angles`): sliders, readouts and share links;
// rates keep their scene's unit (`RateUnit`), the core stays in radians.
import type * as THREE from "three";
import type { Labels } from "./view";

/** A numeric parameter: a slider. `value` is the default. */
export interface NumberParam {
  kind: "number";
  key: string;
  label: string;
  unit: string;
  min: number;
  max: number;
  step: number;
  value: number;
  /** "log": the slider moves along a logarithmic scale (a range spanning decades; min > 0), its
   * values rounded to 3 significant digits. Without it, linear in steps of `step`. */
  scale?: "log";
  /** Whether the control applies to the current parameters (hidden where it does not; its value
   * is kept). Without it, always. */
  when?: (p: Params) => boolean;
}

/** A choice parameter: a select. */
export interface ChoiceParam {
  kind: "choice";
  key: string;
  label: string;
  options: string[];
  value: string;
  when?: (p: Params) => boolean;
}

export type Param = NumberParam | ChoiceParam;
export type Params = Record<string, number | string>;

/** One readout: a label, the exact value(s) (kept at full precision for tests and the share
 * link) and the text shown. */
export interface Readout {
  key: string;
  label: string;
  value: number | string | boolean | number[];
  text: string;
  warn?: boolean;
  /** Pinned on the canvas now (besides the scene's `pinned` keys): a warning that must be seen. */
  pin?: boolean;
  /** More detail (the core's own sentence, say), shown as the cell's tooltip. */
  detail?: string;
  /** The factor from `value` (SI: rad, rad/s) to the unit its label names (180/π for an angle
   * shown in degrees), by which the record's plot and CSV give it; 1 without it. */
  unitScale?: number;
  /** A check of the computation (a residual, a drift, a conserved quantity recomputed), not a
   * result: listed under "Checks" below the headline readouts. */
  check?: boolean;
}

/** A rectangle in CSS pixels (of the stage, or of a viewport in it). */
export interface Rect {
  x: number;
  y: number;
  w: number;
  h: number;
}

export interface SceneContext {
  scene: THREE.Scene;
  camera: THREE.PerspectiveCamera;
  /** The point the orbit controls turn about (the origin unless a scene moves it). */
  target: THREE.Vector3;
  /** An empty element under the parameter controls (cleared when the scene closes) for a
   * scene's own widgets: a file picker, a 2-D plot, a legend. */
  panel: HTMLElement;
  /** An empty element over the 3-D view (cleared when the scene closes, pointer events off) for
   * labels or an inset plot drawn on top of the canvas. An element with the class `hud` is a
   * title, an inset or a note: the camera keeps the scene's main object clear of it. */
  overlay: HTMLElement;
  /** Labels that follow points of the view (axis names, compass letters, scale bars), placed
   * by the shell after each frame (by the scene itself when it has `viewports`). */
  labels: Labels;
  /** The part of `viewport` (stage pixels) not covered by the page's HUD elements (titles,
   * insets, the pinned readouts, the view buttons), where the main object is drawn. */
  freeRect(viewport: Rect): Rect;
  /** Points the camera's projection centre at the middle of the free part of `viewport`
   * (stage pixels), for a scene that renders viewports of its own. */
  aim(camera: THREE.PerspectiveCamera, viewport: Rect): void;
}

/** The part of the scene that the camera frames: a sphere (scene units). */
export interface Frame {
  center: THREE.Vector3;
  radius: number;
}

export interface SceneInstance {
  /** Parameters changed: rebuild the physics objects. Throws the core's error on bad input. */
  configure(p: Params): void;
  /** Evaluate at time t (s) and move the three.js objects. */
  step(t: number): void;
  /** The current readouts. */
  readouts(): Readout[];
  /** Release the wasm objects and the three.js objects. */
  dispose(): void;
  /** The sphere the camera frames (it holds the main object at every time of the motion). */
  frame(): Frame;
  /** The main object(s): what no title, inset or readout may cover (their world bounding box). */
  main(): THREE.Object3D[];
  /** Draw the frame yourself (e.g. two viewports side by side); without it the shell renders
   * `scene` through `camera` on the whole canvas. */
  render?(renderer: THREE.WebGLRenderer, scene: THREE.Scene, camera: THREE.PerspectiveCamera): void;
  /** The viewports (stage pixels) the scene renders into, for a canvas of w × h; without it the
   * whole canvas. */
  viewports?(w: number, h: number): Rect[];
  /** The screen boxes (stage pixels) of the main object, one per viewport; without it the shell
   * projects `main()` through the camera. */
  mainBoxes?(): Rect[];
  /** Named points of the view that tests look at (stage pixels), e.g. a mark's centre. */
  probes?(camera: THREE.PerspectiveCamera, viewport: Rect): Record<string, { x: number; y: number }>;
}

/** The angle unit of a scene's rates: "°" (°/s, °/h: the slow turns of the Earth scenes, the
 * Euler-angle rates) or "rad" (rad/s: spins and angular velocities, the core's unit). Angles
 * themselves are in degrees in every scene (the lab's one angle unit). */
export type RateUnit = "°" | "rad";

export interface SceneDef {
  id: string;
  title: string;
  /** A short title for the tabs of a narrow screen. */
  short: string;
  blurb: string;
  params: Param[];
  /** The angle unit of the scene's rates (its angles are in degrees, as in every scene). */
  rateUnit: RateUnit;
  /** Share-link parameters of an earlier lab, read when the link lacks the current key: the old
   * name, the key it became and the factor from the old value to the new (`theta0` in rad →
   * `tilt` in degrees: 180/π). */
  legacyParams?: Record<string, { key: string; factor: number }>;
  /** The keys of the three or four readouts pinned on the canvas (for the current parameters). */
  pinned: string[] | ((p: Params) => string[]);
  /** What the 3-D view shows, for the canvas's aria-label. */
  describe: string;
  /** The parameter key of each core argument whose name differs from it (`omega3` → `w3`): the
   * shell reads the argument an error of the core names (its message's "argument: ...") to move
   * or stop the right slider. */
  argumentKeys?: Record<string, string>;
  create(ctx: SceneContext): SceneInstance;
}

/** Multiples of ε below which a value is shown as 0: a value whose magnitude is within
 * PRECISION_ULPS·ε of the scale of the quantities it was computed from is round-off (a handful
 * of roundings of numbers of that size), not a value (docs/lab.md, "Readouts"). */
export const PRECISION_ULPS = 8;
const SUPERSCRIPT: Record<string, string> = {
  "-": "⁻", "0": "⁰", "1": "¹", "2": "²", "3": "³", "4": "⁴", "5": "⁵", "6": "⁶", "7": "⁷", "8": "⁸", "9": "⁹",
};

/** Whether x is below the computation's precision at `scale` (0: only an exact 0 is). */
export function belowPrecision(x: number, scale = 0): boolean {
  return Math.abs(x) <= PRECISION_ULPS * Number.EPSILON * Math.abs(scale);
}

/** A number as every readout, slider and label of the page shows it: `digits` significant
 * digits, plain between 10⁻³ and 10⁶, else `m×10ⁿ`; the minus sign U+2212 everywhere; "0" for a
 * value below the precision of the computation at `scale` (see `belowPrecision`); ∞ for an
 * infinity. Full precision stays in the readout's `value`. */
export function fmt(x: number, digits = 6, scale = 0): string {
  if (!Number.isFinite(x)) return x > 0 ? "∞" : x < 0 ? "−∞" : "—";
  if (x === 0 || belowPrecision(x, scale)) return "0";
  const a = Math.abs(x);
  let s: string;
  if (a >= 1e-3 && a < 1e6) s = x.toPrecision(digits);
  else {
    const [m, e] = x.toExponential(digits - 1).split("e");
    s = `${m}×10${[...e.replace("+", "")].map((c) => SUPERSCRIPT[c]).join("")}`;
  }
  return s.replaceAll("-", "−");
}

/** A vector's components; a component below the precision at the vector's own scale (its
 * largest component, or `scale` when given) is 0. */
export function fmtVec(v: ArrayLike<number>, digits = 5, scale?: number): string {
  const xs = Array.from(v);
  const s = scale ?? Math.max(0, ...xs.map(Math.abs).filter(Number.isFinite));
  return "(" + xs.map((x) => fmt(x, digits, s)).join(", ") + ")";
}

/** A difference a − b (a drift, a residual) shown at the scale of what was subtracted. */
export function fmtDiff(a: number, b: number, digits = 3): string {
  return fmt(a - b, digits, Math.max(Math.abs(a), Math.abs(b)));
}

/** A slider's value with the decimals of its step. */
export function fmtStep(x: number, step: number): string {
  const decimals = (String(step).split(".")[1] ?? "").length;
  const s = x.toFixed(decimals);
  return Number(s) === 0 ? (0).toFixed(decimals) : s.replace("-", "−");
}

export const DEG = Math.PI / 180;

/** Angles and rates as a scene shows them: every angle in degrees (the lab's one angle unit),
 * rates in the scene's `rateUnit` per second or hour. Values stay in radians (the core's SI);
 * only the text is converted. */
export function angles(rateUnit: RateUnit) {
  const k = rateUnit === "°" ? 1 / DEG : 1;
  return {
    /** The angle unit: "°". */
    name: "°",
    /** The factors from the core's rad, rad/s and rad/s to what is shown (`Readout.unitScale`). */
    angleScale: 1 / DEG,
    rateScale: k,
    perHourScale: k * 3600,
    /** "°/s" or "rad/s". */
    perSecond: `${rateUnit}/s`,
    /** "°/h" or "rad/h". */
    perHour: `${rateUnit}/h`,
    /** An angle (rad) in degrees. */
    angle: (x: number, digits = 5, scale = 0) => fmt(x / DEG, digits, scale / DEG),
    /** Angles (rad) in degrees. */
    vec: (v: ArrayLike<number>, digits = 5, scale?: number) => fmtVec(Array.from(v, (x) => x / DEG), digits, scale === undefined ? undefined : scale / DEG),
    /** A rate (rad/s) in the scene's rate unit. */
    rate: (x: number, digits = 5, scale = 0) => fmt(x * k, digits, scale * k),
    /** Rates (rad/s) in the scene's rate unit. */
    rates: (v: ArrayLike<number>, digits = 5, scale?: number) => fmtVec(Array.from(v, (x) => x * k), digits, scale === undefined ? undefined : scale * k),
    perHourRate: (x: number, digits = 5) => fmt(x * k * 3600, digits),
  };
}
