// The lab's scenes, in the order of the tabs (and of the number keys 1–9).
import type { SceneDef } from "../scene";
import { eulerScene } from "./euler";
import { freeTopScene } from "./freetop";
import { dropScene } from "./drop";
import { heavyTopScene } from "./heavytop";

export const SCENES: SceneDef[] = [eulerScene, freeTopScene, dropScene, heavyTopScene];
