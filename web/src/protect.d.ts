// Types of protect.js (plain JavaScript, shared with the node tests).

/** The `name`s of the errors the core and the binding throw (the core's table,
 * `raw.errorClasses()`), and `TypeError`. */
export function errorNames(raw: { errorClasses(): [string, string][] }): readonly string[];
/** Where an internal error should be reported. */
export const REPORT_URL: string;

/** The guard's record of the instance it protects. */
export interface CoreStatus {
  /** Restarts of the WebAssembly instance after a trap (each one a bug to report). */
  restarts: number;
  /** Whether a restart failed (every later call throws). */
  broken: boolean;
  /** The message of the last internal error, or null. */
  lastInternalError: string | null;
}

/** The exports of the wasm-bindgen module `raw`, every call guarded (see protect.js). */
export function protect<T extends object>(raw: T): T & { coreStatus(): CoreStatus };
