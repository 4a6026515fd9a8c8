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
pub mod gyrocompass;
pub mod heavy_top;
pub mod inertia;
pub mod rigid_earth;
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

/// Methods that read their arguments by name and call the core's method of the same name once:
/// `calls!(Type { " doc" jsName rust_name(arg: kind, ...) -> out; ... })` is, for each entry, a
/// `#[wasm_bindgen] impl Type` block of `pub fn rust_name(&self, arg, ...) -> Out<...>` that
/// converts each argument with `args::kind` (`number`: a JavaScript number, `vector`: 3 numbers,
/// passed to the core by reference) and returns `self.inner.rust_name(args...)?` as `out`
/// (`number`: the `f64` itself, `vector`: `convert::vec_out`, 3 numbers, or the name of a binding
/// type `Wrapper` of this crate: `Wrapper { inner }` around the core's value).
/// `calls!(fn Type { " doc" jsName rust_name(arg: kind, ...) -> out = core::function; ... })`
/// is the same for the static functions `Type.jsName(args...)`, returning
/// `core::function(args...)?` as `out`.
/// `calls!(Type::new { " doc" (arg: kind, ...) = core::Type::new; })` is the JavaScript
/// constructor `Type { inner: core::Type::new(args...)? }` in the same way, the arguments passed
/// by value. A core callee may be followed by fixed trailing arguments in brackets, passed after
/// the converted ones: `= core::Type::new[Earth::default()]`. Kinds: `number` (`f64`), `vector`
/// (a core vector, passed by reference), `triple` (`[f64; 3]`). Doc lines are string
/// literals, not `///` (wasm-bindgen writes a doc comment passed through `macro_rules!` into the
/// TypeScript declarations as `r" ..."`). The core validates the arguments, naming them, and
/// promises its numbers finite, so nothing else is checked here.
macro_rules! calls {
    ($ty:ident::new { $($doc:literal)* ($($arg:ident: $kind:ident),* $(,)?) = $core:path $([$($fixed:expr),*])?; }) => {
        crate::calls!(@params $ty [$($doc)*] [constructor $core [$($($fixed,)*)?]] [$($arg $kind)*] [$($arg $kind)*] []);
    };
    ($ty:ident { $($($doc:literal)* $js:ident $name:ident($($arg:ident: $kind:ident),* $(,)?) -> $out:ident;)* }) => {
        $(crate::calls!(@params $ty [$($doc)*] [call $js $name $out [&self,] [self.inner.$name] []] [$($arg $kind)*] [$($arg $kind)*] []);)*
    };
    (fn $ty:ident { $($($doc:literal)* $js:ident $name:ident($($arg:ident: $kind:ident),* $(,)?) -> $out:ident = $core:path $([$($fixed:expr),*])?;)* }) => {
        $(crate::calls!(@params $ty [$($doc)*] [call $js $name $out [] [$core] [$($($fixed,)*)?]] [$($arg $kind)*] [$($arg $kind)*] []);)*
    };
    // One parameter at a time, with the TypeScript type of its kind (an attribute takes only a
    // literal, so each kind is spelled out).
    (@params $ty:ident $docs:tt $mode:tt $args:tt [$arg:ident number $($rest:tt)*] [$($p:tt)*]) => {
        crate::calls!(@params $ty $docs $mode $args [$($rest)*] [$($p)*
            #[wasm_bindgen(unchecked_param_type = "number")] $arg: crate::args::Number,]);
    };
    (@params $ty:ident $docs:tt $mode:tt $args:tt [$arg:ident triple $($rest:tt)*] [$($p:tt)*]) => {
        crate::calls!(@params $ty $docs $mode $args [$($rest)*] [$($p)*
            #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] $arg: crate::args::Numbers,]);
    };
    (@params $ty:ident $docs:tt $mode:tt $args:tt [$arg:ident vector $($rest:tt)*] [$($p:tt)*]) => {
        crate::calls!(@params $ty $docs $mode $args [$($rest)*] [$($p)*
            #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>")] $arg: crate::args::Numbers,]);
    };
    // A method (`[&self,]`, calling `self.inner.name`) or a static function (`[]`, calling the
    // core's function).
    (@params $ty:ident [$($doc:literal)*] [call $js:ident $name:ident $out:ident [$($recv:tt)*] [$($callee:tt)+] [$($fixed:expr,)*]] [$($arg:ident $kind:ident)*] [] [$($p:tt)*]) => {
        #[wasm_bindgen::prelude::wasm_bindgen]
        impl $ty {
            $(#[doc = $doc])*
            #[wasm_bindgen(js_name = $js)]
            pub fn $name($($recv)* $($p)*) -> crate::convert::Out<crate::calls!(@type $out)> {
                $(let $arg = crate::args::$kind(stringify!($arg), &$arg)?;)*
                let value = $($callee)+($(crate::calls!(@pass $kind $arg),)* $($fixed),*)?;
                Ok(crate::calls!(@out $out value))
            }
        }
    };
    (@params $ty:ident [$($doc:literal)*] [constructor $core:path [$($fixed:expr,)*]] [$($arg:ident $kind:ident)*] [] [$($p:tt)*]) => {
        #[wasm_bindgen::prelude::wasm_bindgen]
        impl $ty {
            $(#[doc = $doc])*
            #[wasm_bindgen(constructor)]
            pub fn new($($p)*) -> crate::convert::Out<$ty> {
                $(let $arg = crate::args::$kind(stringify!($arg), &$arg)?;)*
                let inner = $core($($arg,)* $($fixed),*)?;
                Ok($ty { inner })
            }
        }
    };
    (@pass number $arg:ident) => { $arg };
    (@pass vector $arg:ident) => { &$arg };
    (@pass triple $arg:ident) => { $arg };
    (@type number) => { f64 };
    (@type vector) => { Vec<f64> };
    (@type $wrapper:ident) => { $wrapper };
    (@out number $value:ident) => { $value };
    (@out vector $value:ident) => { crate::convert::vec_out(&$value) };
    (@out $wrapper:ident $value:ident) => { $wrapper { inner: $value } };
}
pub(crate) use calls;

/// Getters of the core's fields: `fields!(Type { " doc" jsName rust_name -> out(field.path);
/// ... })` is one `#[wasm_bindgen] impl Type` block of `#[wasm_bindgen(getter, js_name =
/// jsName)] pub fn rust_name(&self)` returning `self.inner.field.path` as `out` (`number`,
/// `option`, `flag`: the `f64`, `Option<f64>` or `bool` itself, `text`, `numbers`: a copy of the
/// `String` or `Vec<f64>`, `vector`: 3 numbers, `matrix`: 9 numbers row-major);
/// `fields!(Type.member { ... })` reads `self.member.field.path` instead, and `fields!(fn Type {
/// ... })` makes methods `rust_name()` rather than getters.
/// Doc lines are string literals, as in `calls!`.
macro_rules! fields {
    (fn $ty:ident { $($entries:tt)* }) => {
        crate::fields!(@entries [] $ty.inner { $($entries)* });
    };
    ($ty:ident { $($entries:tt)* }) => {
        crate::fields!(@entries [getter,] $ty.inner { $($entries)* });
    };
    ($ty:ident . $root:ident { $($entries:tt)* }) => {
        crate::fields!(@entries [getter,] $ty.$root { $($entries)* });
    };
    (@entries $attr:tt $ty:ident . $root:ident { $($($doc:literal)* $js:ident $name:ident -> $out:ident($($field:ident).+);)* }) => {
        $(crate::fields!(@one $attr $ty [$($doc)*] $js $name $out [$root $(.$field)+]);)*
    };
    (@one [$($attr:tt)*] $ty:ident [$($doc:literal)*] $js:ident $name:ident $out:ident [$($path:tt)+]) => {
        #[wasm_bindgen::prelude::wasm_bindgen]
        impl $ty {
            $(#[doc = $doc])*
            #[wasm_bindgen($($attr)* js_name = $js)]
            pub fn $name(&self) -> crate::fields!(@type $out) {
                crate::fields!(@out $out self.$($path)+)
            }
        }
    };
    (@type number) => { f64 };
    (@type option) => { Option<f64> };
    (@type flag) => { bool };
    (@type text) => { String };
    (@type $out:ident) => { Vec<f64> };
    (@out vector $value:expr) => { crate::convert::vec_out(&$value) };
    (@out matrix $value:expr) => { crate::convert::mat_out(&$value) };
    (@out text $value:expr) => { $value.clone() };
    (@out numbers $value:expr) => { $value.clone() };
    (@out $copied:ident $value:expr) => { $value };
}
pub(crate) use fields;
