// The parameters (sliders and choices, with their ranges and defaults) of the scenes the notebook
// widgets also show, and their presets: one data file, python/poinsot/widgets/scenes.json, read
// here and by poinsot.widgets (its SCENE_PARAMS), so that the lab and the widgets cannot differ.
// The file lives in the Python package so that the widgets read it without a build.
import data from "../../../python/poinsot/widgets/scenes.json";
import { DEG, type ChoiceParam, type Param, type Params } from "../scene";

/** The scenes whose parameters live in scenes.json. */
export type SharedScene = "heavytop" | "poinsot" | "frames";

/** The scene's parameters from scenes.json, in order; `when` adds a visibility rule by key (the
 * one part of a parameter that is code, not data). */
export function sceneParams(scene: SharedScene, when: Record<string, (p: Params) => boolean> = {}): Param[] {
  const specs = data[scene].params as ReadonlyArray<{ key: string }>;
  return specs.map((spec) => {
    const param = { ...spec } as Param;
    const rule = when[spec.key];
    if (rule) param.when = rule;
    return param;
  });
}

/** The options of the choice `key` of the scene. */
export function choiceOptions(scene: SharedScene, key: string): string[] {
  const param = sceneParams(scene).find((p): p is ChoiceParam => p.kind === "choice" && p.key === key);
  if (!param) throw new Error(`scenes.json: ${scene} has no choice ${key}`);
  return param.options;
}

/** The share-link parameters of an earlier lab that the scene still reads (an angle in radians
 * whose slider is now in degrees: `theta0` → `tilt`), as `SceneDef.legacyParams`. */
export function legacyParams(scene: SharedScene): Record<string, { key: string; factor: number }> {
  const legacy = (data[scene] as { legacyParams?: Record<string, { key: string; unit: string }> }).legacyParams ?? {};
  const out: Record<string, { key: string; factor: number }> = {};
  for (const [old, { key, unit }] of Object.entries(legacy)) {
    if (unit !== "rad") throw new Error(`scenes.json: ${scene}.${old}: unknown legacy unit ${unit}`);
    out[old] = { key, factor: 1 / DEG };
  }
  return out;
}

/** The heavy top's presets released at a fraction of the core's slow steady precession at θ₀:
 * that fraction, by preset. */
export const PRECESSION_FACTORS: Record<string, number> = data.heavytop.precessionFactors;

/** The mass of the Poinsot scene's box (kg): it scales T and L only. */
export const BOX_MASS: number = data.poinsot.boxMass;
