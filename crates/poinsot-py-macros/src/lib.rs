//! `#[export]`: the one way a function or a class's methods are exported by the Python binding
//! (`crates/poinsot-py`), so that each goes through the binding's one panic guard,
//! `errors::guard` (`std::panic::catch_unwind`), and a panic anywhere below it — in the binding,
//! in the core, on a thread of the core's pool — reaches Python as `poinsot.InternalError`
//! rather than pyo3's `PanicException` (a `BaseException` that escapes `except Exception`).
//!
//! On a `fn` it is `#[pyo3::pyfunction]`, on an `impl` block `#[pyo3::pymethods]`, with each
//! function's body run inside the guard: `{ body }` becomes
//! `{ crate::errors::guard(class, name, move || body) }`, and a function that returns a plain
//! value (`-> f64`) returns `PyResult<f64>` instead (`Ok(body)` in the guard). The class and
//! function names go into the error message. Nothing else changes: pyo3 sees the same
//! arguments, attributes and doc comments.
//!
//! One consequence for Rust code: a plain-valued export (`fn gravity(&self) -> &'static str`)
//! now returns `PyResult`, so a method that needs the value calls the core (`self.inner.x()`),
//! not another export.
use proc_macro::TokenStream;
use proc_macro2::TokenStream as Tokens;
use quote::quote;
use syn::{parse_macro_input, parse_quote, Block, ImplItem, Item, ReturnType, Signature, Type};

/// Exports a function (`#[pyfunction]`) or the methods of a class (`#[pymethods]`) through the
/// binding's panic guard (see the crate's documentation).
#[proc_macro_attribute]
pub fn export(attr: TokenStream, item: TokenStream) -> TokenStream {
    if !attr.is_empty() {
        return syn::Error::new(
            Tokens::from(attr)
                .into_iter()
                .next()
                .map_or_else(proc_macro2::Span::call_site, |t| t.span()),
            "#[export] takes no arguments",
        )
        .to_compile_error()
        .into();
    }
    match parse_macro_input!(item as Item) {
        Item::Fn(mut f) => {
            let name = f.sig.ident.to_string();
            guard(&mut f.sig, &mut f.block, quote!(""), &name);
            quote!(#[::pyo3::pyfunction] #f).into()
        }
        Item::Impl(mut block) => {
            for item in &mut block.items {
                if let ImplItem::Fn(method) = item {
                    let name = method.sig.ident.to_string();
                    // The garbage collector's hooks have pyo3's fixed signatures and run no
                    // poinsot code.
                    if name == "__traverse__" || name == "__clear__" {
                        continue;
                    }
                    let shown = if is_constructor(&method.attrs) {
                        String::new()
                    } else {
                        name
                    };
                    guard(
                        &mut method.sig,
                        &mut method.block,
                        quote!(<Self as ::pyo3::PyClass>::NAME),
                        &shown,
                    );
                }
            }
            quote!(#[::pyo3::pymethods] #block).into()
        }
        other => syn::Error::new_spanned(other, "#[export] goes on a fn or an impl block")
            .to_compile_error()
            .into(),
    }
}

/// Whether a method is the class's `#[new]` (its errors are named by the class alone).
fn is_constructor(attrs: &[syn::Attribute]) -> bool {
    attrs.iter().any(|a| a.path().is_ident("new"))
}

/// Whether `ty` is spelled `PyResult<…>` (the binding's one fallible return type).
fn is_result(ty: &Type) -> bool {
    matches!(ty, Type::Path(p) if p.qself.is_none()
        && p.path.segments.last().is_some_and(|s| s.ident == "PyResult"))
}

/// Runs the body of `sig` inside `crate::errors::guard`, returning `PyResult`.
fn guard(sig: &mut Signature, block: &mut Block, class: Tokens, name: &str) {
    let body = &*block;
    let fallible = matches!(&sig.output, ReturnType::Type(_, ty) if is_result(ty));
    let new: Block = if fallible {
        parse_quote!({ crate::errors::guard(#class, #name, move || #body) })
    } else {
        parse_quote!({ crate::errors::guard(#class, #name, move || ::std::result::Result::Ok(#body)) })
    };
    *block = new;
    if !fallible {
        sig.output = match &sig.output {
            ReturnType::Default => parse_quote!(-> ::pyo3::PyResult<()>),
            ReturnType::Type(_, ty) => parse_quote!(-> ::pyo3::PyResult<#ty>),
        };
    }
}
