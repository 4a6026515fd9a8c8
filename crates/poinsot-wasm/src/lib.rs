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
//! `"argument: condition"` text. A result that is not finite where the contract promises a finite
//! number is turned into an error rather than shown. A Rust panic, which must never happen, is
//! logged by [`console_error_panic_hook`] and surfaces in JavaScript as a thrown `RuntimeError`.
//!
//! Naming: functions and methods use JavaScript's camelCase (`eulerToMatrix`), classes keep the
//! Python API's names (`FreeSymmetricTop`, `RigidBody`, `Earth`, `MovingFrame`, `HeavyTop`).
#![forbid(unsafe_code)]
#![warn(missing_docs)]

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
