// The WebAssembly core as the page uses it: every export of the wasm-bindgen module, each call
// guarded by protect.js (a trap restarts the instance and becomes a PoinsotError; the glue's own
// errors name the argument). The page imports the core from here, never from ./wasm directly
// (tests/wasm_fuzz.test.mjs checks it); a type-only import of ./wasm is fine.
import * as raw from "./wasm/poinsot_wasm.js";
import { protect } from "./protect.js";
export type { CoreStatus } from "./protect.js";

const core = protect(raw);

/** Loads and instantiates the WebAssembly module (once, before any other call). */
export default core.default;
/** The guard's record: restarts after a trap, the last internal error. */
export const coreStatus = core.coreStatus;

export const {
  version, start, errorClasses, eulerToMatrix, matrixToEuler, rotationAxis, screwAxis, bodyAngularVelocity,
  eulerRates, axisStability, simulateParticle, sampleTimes, fitWobble, freeGyroscope, fixedAxisHeadingRate,
  AveragedPole, AxisStability, CompassRun, Earth, EulerAngles, Fall, FixedMotion, FoucaultRun, FreeRigidBody, FreeSymmetricTop, Gyrocompass, HeavyTop,
  InertialOscillation, LowFlow, MovingFrame, RelativeMotion, RigidBody, RigidEarth, Screw, SpringParticle, SteadyPrecession, WobbleFit, WobbleTerm,
} = core;
export type AveragedPole = raw.AveragedPole;
export type AxisStability = raw.AxisStability;
export type CompassRun = raw.CompassRun;
export type Earth = raw.Earth;
export type EulerAngles = raw.EulerAngles;
export type Fall = raw.Fall;
export type FixedMotion = raw.FixedMotion;
export type FoucaultRun = raw.FoucaultRun;
export type FreeRigidBody = raw.FreeRigidBody;
export type FreeSymmetricTop = raw.FreeSymmetricTop;
export type Gyrocompass = raw.Gyrocompass;
export type HeavyTop = raw.HeavyTop;
export type InertialOscillation = raw.InertialOscillation;
export type LowFlow = raw.LowFlow;
export type MovingFrame = raw.MovingFrame;
export type RelativeMotion = raw.RelativeMotion;
export type RigidBody = raw.RigidBody;
export type RigidEarth = raw.RigidEarth;
export type Screw = raw.Screw;
export type SpringParticle = raw.SpringParticle;
export type SteadyPrecession = raw.SteadyPrecession;
export type WobbleFit = raw.WobbleFit;
export type WobbleTerm = raw.WobbleTerm;

// A new export of the binding must be listed above: tsc fails here until it is.
const exported = {
  version, start, errorClasses, eulerToMatrix, matrixToEuler, rotationAxis, screwAxis, bodyAngularVelocity,
  eulerRates, axisStability, simulateParticle, sampleTimes, fitWobble, freeGyroscope, fixedAxisHeadingRate,
  AveragedPole, AxisStability, CompassRun, Earth, EulerAngles, Fall, FixedMotion, FoucaultRun, FreeRigidBody, FreeSymmetricTop, Gyrocompass, HeavyTop,
  InertialOscillation, LowFlow, MovingFrame, RelativeMotion, RigidBody, RigidEarth, Screw, SpringParticle, SteadyPrecession, WobbleFit, WobbleTerm,
};
type Unlisted = Exclude<keyof typeof raw, keyof typeof exported | "default" | "initSync" | "__wbg_reset_state">;
export const everyExportListed: [Unlisted] extends [never] ? true : Unlisted = true;
