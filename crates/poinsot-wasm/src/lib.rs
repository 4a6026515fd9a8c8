//! # poinsot-wasm — the physics core for the browser lab
//!
//! WebAssembly bindings of the [`poinsot`] core, for the browser lab in `web/`. Like the Python
//! bindings this crate holds **no physics**: it converts JavaScript arrays (`Float64Array`,
//! row-major 3×3 matrices of nine numbers, scalar-first quaternions `[w, x, y, z]`) to the core's
//! types and back, and maps the core's errors to JavaScript exceptions.
//!
//! Error contract: every fallible export returns `Result<_, Failure>`. At the JavaScript boundary
//! a [`Failure`] becomes a thrown `Error` whose `name` is the Python exception class of the same
//! kind (`"InvalidInertiaError"`, `"GimbalLockError"`, ...) and whose `message` is the core's
//! `"argument: condition"` text, or a real `TypeError` for an argument of the wrong JavaScript
//! type. Arguments arrive as plain JavaScript values and are converted in [`args`] before any
//! allocation or indexing: nothing is coerced (a string is not a number, `"no"` is not a flag,
//! 2.5 is not a count), counts and arrays are checked against a memory budget. Every number
//! returned is finite (but the documented infinities: an infinite period on the separatrix, the
//! pitch of a pure translation, ...) because the core's functions promise it, naming the
//! argument otherwise; the binding keeps no output guard of its own.
//!
//! A Rust panic or a failed allocation must never happen; on `wasm32-unknown-unknown` it would
//! abort the instance (`RuntimeError: unreachable`), after [`console_error_panic_hook`] logged
//! it. The page's last line of defence, `web/src/protect.js`, turns such a trap into a
//! `PoinsotError` ("internal error: ... please report") and replaces the instance with a fresh
//! one (wasm-bindgen's `--experimental-reset-state-function`).
//!
//! Naming: functions and methods use JavaScript's camelCase (`eulerToMatrix`), classes keep the
//! Python API's names (`FreeSymmetricTop`, `RigidBody`, `Earth`, `MovingFrame`, `HeavyTop`).
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod args;
pub mod construction;
pub mod convert;
pub mod earth;
pub mod frames;
pub mod free;
pub mod heavy_top;
pub mod inertia;
pub mod rotation;

pub use convert::Failure;

use wasm_bindgen::prelude::wasm_bindgen;

/// Installs the panic hook once, when the module is instantiated: a panic is logged to the
/// console with its message (and the trap then throws in JavaScript) instead of failing silently.
#[wasm_bindgen(start)]
pub fn start() {
    console_error_panic_hook::set_once();
}

/// The version of the poinsot core compiled into this module (the workspace version).
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}
