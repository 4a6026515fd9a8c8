//! JavaScript arguments in: the one place where a JavaScript value becomes a Rust number, whole
//! number (a count or an index), flag, string or array of numbers — or an error naming the
//! argument.
//!
//! wasm-bindgen's own conversions coerce silently: a number parameter takes `+x` (`"2"` becomes
//! 2, `null` 0), a `bool` takes `+x` (`"no"` is read as `false`, `"yes"` too), a `usize` wraps
//! modulo 2³² (`-1` asks for 4294967295 samples and the allocation traps), a fraction is truncated
//! (2.5 samples become 2), and a non-string where a `&str` is expected writes out of bounds.
//! Every export therefore takes its scalars and arrays as plain JavaScript values — the aliases
//! [`Number`], [`Count`], [`Flag`], [`Text`] and [`Numbers`] — and converts them here, **before**
//! any allocation or indexing:
//!
//! * a wrong JavaScript type is a `TypeError` naming the argument (`"seq: must be a string, got
//!   5"`); nothing is coerced;
//! * a count or an index must be a whole number ≥ 0 (`"samples: must be a whole number >= 0, got
//!   2.5"`), and a count, an array or an output sized by the user must fit the memory budget
//!   ([`check_budget`]: the error says how many bytes the request needs);
//! * NaN and ±Infinity are numbers: they reach the core, which refuses them where they are not
//!   meaningful and names the argument (`"t: must be finite, got NaN"`).
//!
//! Arrays are read by one small JavaScript function ([`numbers`]) that wasm-bindgen calls with
//! `catch`: an exception thrown while reading a hostile value (an accessor, a revoked proxy)
//! becomes a `TypeError` here instead of unwinding through the WebAssembly frames.
//!
//! In native builds (the crate's unit tests under `cargo test`) the aliases are the plain Rust
//! types (`f64`, `bool`, `String`, `Vec<f64>`); the JavaScript type checks are skipped there, and
//! the checks of whole numbers and of the memory budget run in both.

use crate::convert::{self, Failure, Out};
use poinsot::{Mat3, Vec3};

/// A number argument: any JavaScript value in WebAssembly (a `number` is required), `f64` natively.
#[cfg(target_arch = "wasm32")]
pub type Number = wasm_bindgen::JsValue;
/// A number argument: any JavaScript value in WebAssembly (a `number` is required), `f64` natively.
#[cfg(not(target_arch = "wasm32"))]
pub type Number = f64;

/// A count or an index: a [`Number`] that must be a whole number ≥ 0 (`f64` natively, so that the
/// unit tests exercise the checks of fractions, negatives and huge values).
pub type Count = Number;

/// A flag: any JavaScript value in WebAssembly (a `boolean` is required), `bool` natively.
#[cfg(target_arch = "wasm32")]
pub type Flag = wasm_bindgen::JsValue;
/// A flag: any JavaScript value in WebAssembly (a `boolean` is required), `bool` natively.
#[cfg(not(target_arch = "wasm32"))]
pub type Flag = bool;

/// A string argument: any JavaScript value in WebAssembly (a `string` is required), `&str` natively.
#[cfg(target_arch = "wasm32")]
pub type Text = wasm_bindgen::JsValue;
/// A string argument: any JavaScript value in WebAssembly (a `string` is required), `String`
/// natively.
#[cfg(not(target_arch = "wasm32"))]
pub type Text = String;

/// An array of numbers: any JavaScript value in WebAssembly (an `Array` of numbers or a typed
/// array of numbers is required), `Vec<f64>` natively.
#[cfg(target_arch = "wasm32")]
pub type Numbers = wasm_bindgen::JsValue;
/// An array of numbers: any JavaScript value in WebAssembly (an `Array` of numbers or a typed
/// array of numbers is required), `Vec<f64>` natively.
#[cfg(not(target_arch = "wasm32"))]
pub type Numbers = Vec<f64>;

/// Checks that `count` items of `bytes_each` bytes fit the core's memory budget
/// ([`poinsot::limits`]: 1 GiB in WebAssembly); the error names `argument` (the user's count or
/// array) and says how many bytes the request would need. `count` is a float so that it may be
/// astronomically large (a length, a product of counts).
pub fn check_budget(argument: &str, count: f64, bytes_each: usize) -> Out<()> {
    poinsot::limits::check_memory(argument, count, bytes_each).map_err(Failure::from)
}

/// Checks that a request of `needed` bytes fits the core's memory budget; the error names
/// `argument`, says `what` was asked for (`"1000000000"`, `"8 parcels × 10000000 samples"`) and
/// how many bytes it would need.
pub fn check_bytes(argument: &str, what: &str, needed: f64) -> Out<()> {
    poinsot::limits::check_bytes(argument, what, needed).map_err(Failure::from)
}

/// `value` as a whole number ≥ 0 (still a float: the caller checks the upper bound — the
/// memory budget or the valid range of an index — before converting it).
pub fn whole(argument: &str, value: f64) -> Out<f64> {
    if value.is_finite() && value >= 0.0 && value.fract() == 0.0 {
        Ok(value)
    } else {
        Err(Failure::invalid(
            argument,
            &format!("must be a whole number >= 0, got {value}"),
        ))
    }
}

/// A count of items of `bytes_each` bytes each (samples, parcels): a whole number ≥ 0 within the
/// memory budget. The minimum (2 samples, 1 parcel) is the caller's check, after this one.
pub fn count(argument: &str, value: &Count, bytes_each: usize) -> Out<usize> {
    let n = whole(argument, number(argument, value)?)?;
    check_budget(argument, n, bytes_each)?;
    // Exact: n is a whole number below the budget, far below 2³².
    Ok(n as usize)
}

/// An index into a collection of `len` items: a whole number `< len`, else an error naming
/// `argument` and `what` the collection is (`"index: must be < 8 parcels, got 9"`).
pub fn index_in(argument: &str, value: &Count, len: usize, what: &str) -> Out<usize> {
    let i = whole(argument, number(argument, value)?)?;
    if i < len as f64 {
        Ok(i as usize)
    } else {
        Err(Failure::invalid(
            argument,
            &format!("must be < {len} {what}, got {i}"),
        ))
    }
}

/// The numbers of an array argument with `bytes_each` bytes of memory per element (its copy, 8
/// bytes, plus what the call makes per element: 24 for three numbers out per time, ...), checked
/// against the memory budget before the copy is made.
pub fn numbers_each(argument: &str, value: &Numbers, bytes_each: usize) -> Out<Vec<f64>> {
    host::numbers(argument, value, bytes_each)
}

/// The numbers of an array argument (a vector, a matrix, a short list): [`numbers_each`] with the
/// 8 bytes of its own copy per element.
pub fn numbers(argument: &str, value: &Numbers) -> Out<Vec<f64>> {
    numbers_each(argument, value, 8)
}

/// A 3-vector argument (exactly 3 numbers).
pub fn vector(argument: &str, value: &Numbers) -> Out<Vec3> {
    convert::vec3(argument, &numbers(argument, value)?)
}

/// Three numbers as an array (angles, moments, sides, semi-axes).
pub fn triple(argument: &str, value: &Numbers) -> Out<[f64; 3]> {
    convert::array3(argument, &numbers(argument, value)?)
}

/// A row-major 3×3 matrix argument (exactly 9 numbers).
pub fn matrix(argument: &str, value: &Numbers) -> Out<Mat3> {
    convert::mat3(argument, &numbers(argument, value)?)
}

/// A number argument as `f64` (a `TypeError` naming `argument` if it is not a JavaScript number).
pub fn number(argument: &str, value: &Number) -> Out<f64> {
    host::number(argument, value)
}

/// `let_numbers!(i1, i3, mgl);` converts each [`Number`] argument to an `f64` of the same name
/// ([`number`]: a `TypeError` naming the argument for a value that is not a number), in order.
macro_rules! let_numbers {
    ($($x:ident),+ $(,)?) => {
        $(let $x = crate::args::number(stringify!($x), &$x)?;)+
    };
}
pub(crate) use let_numbers;

/// A flag argument as `bool` (a `TypeError` naming `argument` unless `true` or `false`).
pub fn flag(argument: &str, value: &Flag) -> Out<bool> {
    host::flag(argument, value)
}

/// A string argument (a `TypeError` naming `argument` if it is not a JavaScript string).
pub fn text(argument: &str, value: &Text) -> Out<String> {
    host::text(argument, value)
}

/// The conversions from JavaScript values (WebAssembly).
#[cfg(target_arch = "wasm32")]
mod host {
    use super::{check_budget, Flag, Number, Numbers, Text};
    use crate::convert::{Failure, Out};
    use wasm_bindgen::prelude::wasm_bindgen;
    use wasm_bindgen::{JsCast, JsValue};

    #[wasm_bindgen(inline_js = r#"
/** A short description of a JavaScript value for an error message; never throws. */
export function poinsot_describe(x) {
  try {
    if (x === null) return "null";
    switch (typeof x) {
      case "undefined": return "undefined";
      case "number": case "boolean": return String(x);
      case "string": return "a string " + JSON.stringify(x.length > 24 ? x.slice(0, 24) + "…" : x);
      case "bigint": return "a bigint";
      case "symbol": return "a symbol";
      case "function": return "a function";
    }
    if (Array.isArray(x)) return "an array of length " + x.length;
    if (ArrayBuffer.isView(x)) return "a " + Object.prototype.toString.call(x).slice(8, -1);
    return "an object";
  } catch (e) {
    return "an object";
  }
}

/** The numbers of `value` as a Float64Array if it is an Array of numbers or a typed array of
 * numbers, with at most `maxLength` elements; else its length (a number) if it is longer, or the
 * reason it is not (a string). Each element is read once. */
export function poinsot_numbers(value, maxLength) {
  if (ArrayBuffer.isView(value) && !(value instanceof DataView)) {
    if (value instanceof BigInt64Array || value instanceof BigUint64Array) {
      return "must hold numbers, got " + poinsot_describe(value);
    }
    if (value.length > maxLength) return value.length;
    return value instanceof Float64Array ? value : Float64Array.from(value);
  }
  if (!Array.isArray(value)) return "must be an array of numbers, got " + poinsot_describe(value);
  const n = value.length;
  if (n > maxLength) return n;
  const out = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    const x = value[i];
    if (typeof x !== "number") return "must hold numbers, got " + poinsot_describe(x) + " at index " + i;
    out[i] = x;
  }
  return out;
}
"#)]
    extern "C" {
        fn poinsot_describe(value: &JsValue) -> String;
        #[wasm_bindgen(catch)]
        fn poinsot_numbers(value: &JsValue, max_length: f64) -> Result<JsValue, JsValue>;
    }

    fn type_error(argument: &str, expected: &str, value: &JsValue) -> Failure {
        Failure::type_error(
            argument,
            &format!("must be {expected}, got {}", poinsot_describe(value)),
        )
    }

    pub fn number(argument: &str, value: &Number) -> Out<f64> {
        value
            .as_f64()
            .ok_or_else(|| type_error(argument, "a number", value))
    }

    pub fn flag(argument: &str, value: &Flag) -> Out<bool> {
        value
            .as_bool()
            .ok_or_else(|| type_error(argument, "true or false", value))
    }

    pub fn text(argument: &str, value: &Text) -> Out<String> {
        value
            .as_string()
            .ok_or_else(|| type_error(argument, "a string", value))
    }

    pub fn numbers(argument: &str, value: &Numbers, bytes_each: usize) -> Out<Vec<f64>> {
        // The longest array within the budget; a longer one is refused before it is copied.
        let max_length = (poinsot::limits::memory_budget() / bytes_each.max(1) as u64) as f64;
        let read = poinsot_numbers(value, max_length).map_err(|e| {
            Failure::type_error(
                argument,
                &format!(
                    "must be an array of numbers; reading it threw {}",
                    poinsot_describe(&e)
                ),
            )
        })?;
        if let Some(reason) = read.as_string() {
            return Err(Failure::type_error(argument, &reason));
        }
        if let Some(length) = read.as_f64() {
            check_budget(argument, length, bytes_each)?;
        }
        Ok(read.unchecked_into::<js_sys::Float64Array>().to_vec())
    }
}

/// The conversions in native builds (the unit tests): the values already have their Rust types.
#[cfg(not(target_arch = "wasm32"))]
mod host {
    use super::{check_budget, Flag, Number, Numbers, Text};
    use crate::convert::Out;

    pub fn number(_argument: &str, value: &Number) -> Out<f64> {
        Ok(*value)
    }

    pub fn flag(_argument: &str, value: &Flag) -> Out<bool> {
        Ok(*value)
    }

    pub fn text(_argument: &str, value: &Text) -> Out<String> {
        Ok(value.clone())
    }

    pub fn numbers(argument: &str, value: &Numbers, bytes_each: usize) -> Out<Vec<f64>> {
        check_budget(argument, value.len() as f64, bytes_each)?;
        Ok(value.clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convert::refused;

    #[test]
    fn counts_are_whole_non_negative_and_within_the_budget() {
        assert_eq!(count("samples", &601.0, 56).unwrap(), 601);
        assert_eq!(count("samples", &0.0, 56).unwrap(), 0);
        for bad in [2.5, -1.0, -2147483648.0, f64::NAN, f64::INFINITY, -0.5] {
            let e = refused(
                count("samples", &bad, 56),
                "samples: must be a whole number >= 0",
            );
            assert_eq!(e.name, "PoinsotError");
        }
        // 1e9 samples of 56 bytes: 56 GB, refused with the bytes it would need.
        let need = "samples: 1000000000 would need 56000000000 bytes (56.0 GB)";
        refused(count("samples", &1e9, 56), need);
        // The boundary: exactly the budget passes, one more item does not.
        let most = (poinsot::limits::memory_budget() / 8) as f64;
        assert!(count("samples", &most, 8).is_ok());
        assert!(count("samples", &(most + 1.0), 8).is_err());
    }

    #[test]
    fn indices_are_whole_and_in_range() {
        assert_eq!(index_in("index", &7.0, 8, "parcels").unwrap(), 7);
        let e = index_in("index", &8.0, 8, "parcels").unwrap_err();
        assert_eq!(e.message, "index: must be < 8 parcels, got 8");
        refused(
            index_in("index", &1e300, 8, "parcels"),
            "index: must be < 8 parcels",
        );
        let negative = index_in("index", &-1.0, 8, "parcels");
        refused(negative, "index: must be a whole number >= 0, got -1");
        assert!(index_in("index", &0.5, 8, "parcels").is_err());
    }

    #[test]
    fn arrays_longer_than_the_budget_are_refused_before_the_copy() {
        assert_eq!(numbers("t", &vec![1.0, 2.0]).unwrap(), vec![1.0, 2.0]);
        // 24 bytes per time: the budget allows poinsot::limits::memory_budget() / 24 of them.
        let half = poinsot::limits::memory_budget() as usize / 2;
        refused(numbers_each("t", &vec![0.0; 3], half), "t: 3 would need");
    }

    #[test]
    fn budget_errors_name_the_argument_and_the_bytes() {
        let need = "parcels: 1000000000000 would need 48000000000000 bytes";
        let e = refused(check_budget("parcels", 1e6 * 1e6, 48), need);
        assert_eq!(e.name, "PoinsotError");
        assert!(check_budget("parcels", f64::INFINITY, 1).is_err());
    }
}
