//! Python bindings of the poinsot core: conversion of arrays and mapping of errors, no physics.
//!
//! The files mirror the core's modules: `rotation.rs` binds `poinsot::rotation`,
//! `inertia.rs` binds `poinsot::inertia`. The compiled module is private (`poinsot._core`);
//! the typed public API lives in `python/poinsot`.
#![forbid(unsafe_code)]

/// Adds the `#[export]`ed functions to the module: `add_functions!(m; f, g)`.
macro_rules! add_functions {
    ($m:expr; $($f:ident),+ $(,)?) => {{
        $($m.add_function(::pyo3::wrap_pyfunction!($f, $m)?)?;)+
    }};
}

/// `#[export] impl Class { … }` for a class holding a core value in `inner`: the methods written
/// out after the lists, and one `#[getter]` per method of the core value, named after it and
/// returning what it returns: `getters { name -> Type; … }` for a plain value (`name.then() ->
/// Type` calls `then` on it: `.as_str()`, `.into()`), `fallible {
/// name -> Type; name.map(Wrapper) -> Wrapper; … }` for a core `Result` (its error mapped by
/// `IntoPy`, its value wrapped when `.map` says so), and `fields { name -> Type; name in
/// path -> Type; … }` for a field of the core value (`self.inner.name`, or
/// `self.inner.path.name`), copied. `new { (a: A, b: B) = make; }` is a value made from its
/// fields: the constructor `#[new] fn new(a, b)` (`make(a, b)`, its error mapped), the
/// pickling `__reduce__` (the class and `(inner.a, inner.b)`) and a getter per field. Each list
/// may be left out; those given come in this order. pyo3 takes one `#[pymethods]` block per
/// class, so the getters go into that block.
macro_rules! core_export {
    (impl $class:ident; $($rest:tt)*) => { core_export! { @getters $class $($rest)* } };
    // Each list, given or empty, gathered in brackets.
    (@getters $c:ident getters { $($l:tt)* } $($rest:tt)*) => { core_export! { @fallible $c [$($l)*] $($rest)* } };
    (@getters $c:ident $($rest:tt)*) => { core_export! { @fallible $c [] $($rest)* } };
    (@fallible $c:ident $g:tt fallible { $($l:tt)* } $($rest:tt)*) => { core_export! { @fields $c $g [$($l)*] $($rest)* } };
    (@fallible $c:ident $g:tt $($rest:tt)*) => { core_export! { @fields $c $g [] $($rest)* } };
    (@fields $c:ident $g:tt $f:tt fields { $($l:tt)* } $($rest:tt)*) => { core_export! { @new $c $g $f [$($l)*] $($rest)* } };
    (@fields $c:ident $g:tt $f:tt $($rest:tt)*) => { core_export! { @new $c $g $f [] $($rest)* } };
    (@new $c:ident $g:tt $f:tt $v:tt new { $($l:tt)* } $($rest:tt)*) => { core_export! { @all $c $g $f $v [$($l)*] $($rest)* } };
    (@new $c:ident $g:tt $f:tt $v:tt $($rest:tt)*) => { core_export! { @all $c $g $f $v [] $($rest)* } };
    (
        @all $class:ident
        [$($(#[$doc:meta])* $name:ident $(.$then:ident())* -> $out:ty;)*]
        [$($(#[$fdoc:meta])* $fname:ident $(.map($wrap:path))? -> $fout:ty;)*]
        [$($(#[$vdoc:meta])* $vname:ident $(in $($path:ident).+)? -> $vout:ty;)*]
        [$($(#[$ndoc:meta])* ($($arg:ident: $aty:ty),+ $(,)?) = $make:path;)?]
        $($methods:tt)*
    ) => {
        #[::poinsot_py_macros::export]
        impl $class {
            $($(#[$doc])*
            #[getter]
            fn $name(&self) -> $out {
                self.inner.$name()$(.$then())*
            })*
            $($(#[$fdoc])*
            #[getter]
            fn $fname(&self) -> ::pyo3::PyResult<$fout> {
                crate::errors::IntoPy::py(self.inner.$fname()$(.map($wrap))?)
            })*
            $($(#[$vdoc])*
            #[getter]
            fn $vname(&self) -> $vout {
                self.inner$($(.$path)+)?.$vname
            })*
            $($(#[$ndoc])*
            #[new]
            fn new($($arg: $aty),+) -> ::pyo3::PyResult<Self> {
                Ok(Self {
                    inner: crate::errors::IntoPy::py($make($($arg),+))?,
                })
            }
            /// The value made again from its fields (pickling).
            fn __reduce__<'py>(
                slf: &::pyo3::Bound<'py, Self>,
            ) -> (::pyo3::Bound<'py, ::pyo3::types::PyType>, ($($aty,)+)) {
                let inner = &slf.get().inner;
                (slf.get_type(), ($(inner.$arg,)+))
            }
            $(#[getter]
            fn $arg(&self) -> $aty {
                self.inner.$arg
            })+)?
            $($methods)*
        }
    };
}

mod control;
mod convert;
mod defaults;
mod errors;

/// The files that bind the core's modules, named once: `bindings!(rotation, inertia, …)` is
/// `mod rotation; mod inertia; …` and `register_bindings(m)`, which calls each file's
/// `register(m)` (its classes and functions), in that order.
macro_rules! bindings {
    ($($file:ident),+ $(,)?) => {
        $(mod $file;)+

        /// Registers every binding file's classes and functions on the module.
        fn register_bindings(m: &Bound<'_, PyModule>) -> PyResult<()> {
            $($file::register(m)?;)+
            Ok(())
        }
    };
}

bindings!(
    rotation,
    inertia,
    frames,
    earth,
    rigid_earth,
    special,
    analytic,
    dynamics,
    gyrocompass,
    heavy_top,
    sweep,
    wobble,
);

use poinsot_py_macros::export;
use pyo3::prelude::*;

/// The memory budget (bytes) of one call's outputs (see `poinsot.limits`).
#[export]
fn memory_budget() -> u64 {
    poinsot::limits::memory_budget()
}

/// Sets the memory budget (bytes); returns the previous one.
#[export]
fn set_memory_budget(bytes: u64) -> PyResult<u64> {
    use errors::IntoPy;
    poinsot::limits::set_memory_budget(bytes).py()
}

/// Panics on purpose, for the tests only (never called by the package): the panic guard every
/// export goes through (`errors::guard`, by `#[export]`) must turn it into
/// `poinsot.InternalError`. `place`: `"here"` (in the binding, the GIL held), `"detached"` (in
/// the core's monitored run with the GIL released, as a long run) or `"pool"` (on the core's
/// rayon threads, in parallel chunks).
#[export]
#[pyo3(signature = (message, place = "here"))]
fn _test_panic(py: Python<'_>, message: &str, place: &str) -> PyResult<()> {
    let message = message.to_owned();
    match place {
        "here" => panic!("{message}"),
        "detached" => control::run(py, None, || -> poinsot::Result<()> { panic!("{message}") }),
        "pool" => control::run(py, None, || {
            let mut out = vec![0.0_f64; 32];
            poinsot::control::fill_chunks(&mut out, 1, true, |_, _| panic!("{message}"))
        }),
        _ => Err(errors::invalid(
            "place",
            "must be 'here', 'detached' or 'pool'",
        )),
    }
}

/// Loads NumPy's C API now, at import. rust-numpy loads it at the first array it meets, by
/// running Python code (`numpy.lib.NumpyVersion`) during pyo3's extraction of the arguments,
/// outside any export's guard: a Ctrl-C that arrived just then was raised inside that code and
/// became a panic (`Failed to access NumPy array API capsule`), shown as pyo3's
/// `PanicException` instead of `KeyboardInterrupt` (`python/tests/test_limits.py`,
/// `test_numpy_api_is_loaded_at_import`). A Ctrl-C pending at import is raised as itself.
fn load_numpy_api(py: Python<'_>) -> PyResult<()> {
    py.check_signals()?;
    errors::guard("", "import", || {
        numpy::PyArray1::<f64>::zeros(py, 0, false);
        Ok(())
    })
}

/// The compiled core of poinsot (private: use the `poinsot` package).
#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("DEFAULT_MAX_STEPS", poinsot::limits::DEFAULT_MAX_STEPS)?;
    m.add(
        "DEFAULT_MEMORY_BUDGET",
        poinsot::limits::DEFAULT_MEMORY_BUDGET,
    )?;
    add_functions!(m; memory_budget, set_memory_budget, _test_panic);
    defaults::register(m)?;
    errors::register(m)?;
    load_numpy_api(m.py())?;
    register_bindings(m)
}
