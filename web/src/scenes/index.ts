// The lab's scenes, in the order of the tabs (and of the number keys 1–9; the tenth and eleventh by their tabs): the unit's order.
import type { SceneDef } from "../scene";
import { framesScene } from "./frames";
import { dropScene } from "./drop";
import { foucaultScene } from "./foucault";
import { lowScene } from "./low";
import { inertiaScene } from "./inertia";
import { eulerScene } from "./euler";
import { freeTopScene } from "./freetop";
import { poinsotScene } from "./poinsot";
import { heavyTopScene } from "./heavytop";
import { earthTopScene } from "./earthtop";
import { gyrocompassScene } from "./gyrocompass";

export const SCENES: SceneDef[] = [
  framesScene, dropScene, foucaultScene, lowScene, inertiaScene, eulerScene, freeTopScene, poinsotScene, heavyTopScene, earthTopScene, gyrocompassScene,
];
