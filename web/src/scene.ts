// The contract between the lab's shell (main.ts) and its scenes. A scene declares its
// parameters (which become sliders/selects and URL fields), builds its three.js objects once,
// rebuilds its physics objects (from the wasm core) when a parameter changes, and evaluates them
// at time t. Scenes hold no physics of their own: every number comes from the core.
import type * as THREE from "three";

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
}

/** A choice parameter: a select. */
export interface ChoiceParam {
  kind: "choice";
  key: string;
  label: string;
  options: string[];
  value: string;
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
   * labels or an inset plot drawn on top of the canvas. */
  overlay: HTMLElement;
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
  /** Draw the frame yourself (e.g. two viewports side by side); without it the shell renders
   * `scene` through `camera` on the whole canvas. */
  render?(renderer: THREE.WebGLRenderer, scene: THREE.Scene, camera: THREE.PerspectiveCamera): void;
}

export interface SceneDef {
  id: string;
  title: string;
  blurb: string;
  params: Param[];
  create(ctx: SceneContext): SceneInstance;
}

/** Numbers as the readouts show them (full precision stays in `value`). */
export function fmt(x: number, digits = 6): string {
  if (!Number.isFinite(x)) return x > 0 ? "∞" : x < 0 ? "−∞" : "—";
  if (x === 0) return "0";
  const a = Math.abs(x);
  const s = a >= 1e-3 && a < 1e6 ? x.toPrecision(digits) : x.toExponential(digits - 1);
  return s.replace("-", "−");
}

export function fmtVec(v: ArrayLike<number>, digits = 5): string {
  return "(" + Array.from(v, (x) => fmt(x, digits)).join(", ") + ")";
}

export const DEG = Math.PI / 180;
