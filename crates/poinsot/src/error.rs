//! Errors of the physics core.
//!
//! Every fallible function of the core returns [`Result`]. An [`Error`] always names the
//! argument at fault and the condition it violates, so that the front ends (Python, the
//! browser) can show it as it is. Each [`ErrorKind`] has one exception class name
//! ([`ErrorKind::class_name`]), the one table both bindings use: Python raises the exception
//! class of that name (`crates/poinsot-py/src/errors.rs`), JavaScript throws an `Error` whose
//! `name` it is (`crates/poinsot-wasm/src/convert.rs`).

use std::fmt;

/// What went wrong, coarsely: the front ends map each kind to an exception type.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ErrorKind {
    /// An argument is out of its domain (non-finite, negative mass, `dt <= 0`, wrong shape, ...).
    InvalidArgument,
    /// An inertia tensor is not physical (asymmetric, negative moment, triangle inequality).
    InvalidInertia,
    /// A matrix is not a proper rotation (not orthonormal, or `det != +1`).
    InvalidRotation,
    /// A triangle mesh does not bound a solid (open, non-manifold, inside-out, degenerate).
    InvalidMesh,
    /// Euler-angle rates are undefined: the angles sit at the singularity of their sequence.
    GimbalLock,
    /// A numerical integration diverged or could not reach its tolerance.
    Diverged,
    /// The caller stopped the computation ([`crate::control`]: Ctrl-C, a progress callback
    /// that raised).
    Interrupted,
}

impl ErrorKind {
    /// Every kind, in declaration order (for the bindings' tables and their tests).
    pub const ALL: [ErrorKind; 7] = [
        ErrorKind::InvalidArgument,
        ErrorKind::InvalidInertia,
        ErrorKind::InvalidRotation,
        ErrorKind::InvalidMesh,
        ErrorKind::GimbalLock,
        ErrorKind::Diverged,
        ErrorKind::Interrupted,
    ];

    /// The kind's name, as spelled in Rust (`"InvalidArgument"`).
    pub fn name(self) -> &'static str {
        match self {
            ErrorKind::InvalidArgument => "InvalidArgument",
            ErrorKind::InvalidInertia => "InvalidInertia",
            ErrorKind::InvalidRotation => "InvalidRotation",
            ErrorKind::InvalidMesh => "InvalidMesh",
            ErrorKind::GimbalLock => "GimbalLock",
            ErrorKind::Diverged => "Diverged",
            ErrorKind::Interrupted => "Interrupted",
        }
    }

    /// The exception class of this kind, in Python and in JavaScript (the `name` of the thrown
    /// `Error`): the one table of the front ends. All but `KeyboardInterrupt` (a stopped run:
    /// Python's own class) are `poinsot.PoinsotError` or one of its subclasses.
    pub fn class_name(self) -> &'static str {
        match self {
            ErrorKind::InvalidArgument => "PoinsotError",
            ErrorKind::InvalidInertia => "InvalidInertiaError",
            ErrorKind::InvalidRotation => "InvalidRotationError",
            ErrorKind::InvalidMesh => "InvalidMeshError",
            ErrorKind::GimbalLock => "GimbalLockError",
            ErrorKind::Diverged => "IntegrationError",
            ErrorKind::Interrupted => "KeyboardInterrupt",
        }
    }
}

/// An error of the physics core: the argument at fault and the condition it violates.
#[derive(Debug, Clone, PartialEq)]
pub struct Error {
    /// The coarse kind, for mapping to exception types.
    pub kind: ErrorKind,
    /// The name of the argument at fault, as the public API spells it (e.g. `"mass"`).
    pub argument: String,
    /// The violated condition, in words, usually with the offending value.
    pub message: String,
}

/// The result type of the physics core.
pub type Result<T> = std::result::Result<T, Error>;

impl Error {
    /// A new error of `kind` about `argument`. Numbers that `message` spells out in full
    /// beyond [1e-4, 1e16) (`{}` of an f64) are put in exponent form ([`tidy_numbers`]).
    pub fn new(kind: ErrorKind, argument: impl Into<String>, message: impl Into<String>) -> Self {
        let message = message.into();
        Self {
            kind,
            argument: argument.into(),
            message: tidy_numbers(&message).unwrap_or(message),
        }
    }
    /// An argument out of its domain.
    pub fn invalid(argument: impl Into<String>, message: impl Into<String>) -> Self {
        Self::new(ErrorKind::InvalidArgument, argument, message)
    }
    /// A non-physical inertia tensor.
    pub fn inertia(argument: impl Into<String>, message: impl Into<String>) -> Self {
        Self::new(ErrorKind::InvalidInertia, argument, message)
    }
    /// A matrix that is not a proper rotation.
    pub fn rotation(argument: impl Into<String>, message: impl Into<String>) -> Self {
        Self::new(ErrorKind::InvalidRotation, argument, message)
    }
    /// A mesh that does not bound a solid.
    pub fn mesh(argument: impl Into<String>, message: impl Into<String>) -> Self {
        Self::new(ErrorKind::InvalidMesh, argument, message)
    }
    /// Euler-angle rates at a singular configuration.
    pub fn gimbal_lock(argument: impl Into<String>, message: impl Into<String>) -> Self {
        Self::new(ErrorKind::GimbalLock, argument, message)
    }
    /// A diverging or failing integration.
    pub fn diverged(argument: impl Into<String>, message: impl Into<String>) -> Self {
        Self::new(ErrorKind::Diverged, argument, message)
    }
    /// The same error naming `to` instead of `from` (an inner call's argument that the caller
    /// received under another name); other errors unchanged.
    pub fn renamed(mut self, from: &str, to: &str) -> Self {
        if self.argument == from {
            self.argument = to.to_string();
        }
        self
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // A message changed after construction (a prefix, an index) is tidied here too.
        match tidy_numbers(&self.message) {
            Some(tidy) => write!(f, "{}: {}", self.argument, tidy),
            None => write!(f, "{}: {}", self.argument, self.message),
        }
    }
}

impl std::error::Error for Error {}

/// A number for an error message: as Rust's `Display` for ordinary magnitudes, in exponent
/// form outside [1e-4, 1e16) — `1e308`, not 309 digits.
pub fn num(x: f64) -> String {
    let a = x.abs();
    if x == 0.0 || !x.is_finite() || (1e-4..1e16).contains(&a) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// The decimal number `digits` (integer part `int`, fraction `frac`, no sign) in the form of
/// [`num`] if it is spelled out in full beyond [1e-4, 1e16): `Some("1.25e-310")` for the
/// 312 characters of `0.000…125`; `None` when it is in range, zero, or has more than 17
/// significant digits (an exact whole number such as a `u64`, which is not an f64's `{}`).
fn exponent_form(int: &str, frac: &str) -> Option<String> {
    let large = int.len() > 16 && !int.starts_with('0');
    let small = int.bytes().all(|b| b == b'0') && frac.starts_with("0000");
    if !(large || small) {
        return None;
    }
    let all: Vec<u8> = int.bytes().chain(frac.bytes()).collect();
    let first = all.iter().position(|&b| b != b'0')?;
    let last = all.iter().rposition(|&b| b != b'0')?;
    let sig = &all[first..=last];
    if sig.len() > 17 {
        return None;
    }
    let exp = int.len() as i64 - 1 - first as i64;
    let mut out = String::with_capacity(sig.len() + 8);
    out.push(sig[0] as char);
    if sig.len() > 1 {
        out.push('.');
        out.extend(sig[1..].iter().map(|&b| b as char));
    }
    out.push('e');
    out.push_str(&exp.to_string());
    Some(out)
}

/// `message` with every number spelled out in full beyond [1e-4, 1e16) — what Rust's `{}`
/// prints for an f64 such as 1e-308 (310 characters) or 1e300 (301 digits) — rewritten in
/// the exponent form of [`num`] (the same digits, so the same value: `2e-308`, `1e300`);
/// `None` if there is none. Applied to every [`Error`]'s message, so that the documented
/// form (docs/limits.md: "exponent form beyond [1e-4, 1e16)") holds for every message of the
/// core, also where a message interpolates an f64 with `{}` instead of [`num`]. Digits that
/// are part of a word, an exponent or a longer exact whole number are left alone.
pub fn tidy_numbers(message: &str) -> Option<String> {
    let bytes = message.as_bytes();
    let word = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
    let mut out: Option<String> = None;
    let mut copied = 0;
    let mut i = 0;
    while i < bytes.len() {
        if !bytes[i].is_ascii_digit() || (i > 0 && (word(bytes[i - 1]) || bytes[i - 1] == b'.')) {
            i += 1;
            continue;
        }
        // An exponent's digits after `e-` / `e+` belong to a number already in exponent form.
        let after_exponent =
            i >= 2 && matches!(bytes[i - 1], b'-' | b'+') && matches!(bytes[i - 2], b'e' | b'E');
        let start = i;
        while i < bytes.len() && bytes[i].is_ascii_digit() {
            i += 1;
        }
        let int_end = i;
        let mut frac_end = i;
        if i + 1 < bytes.len() && bytes[i] == b'.' && bytes[i + 1].is_ascii_digit() {
            i += 1;
            while i < bytes.len() && bytes[i].is_ascii_digit() {
                i += 1;
            }
            frac_end = i;
        }
        if after_exponent || (i < bytes.len() && (word(bytes[i]) || bytes[i] == b'.')) {
            // Part of a longer token (1e308, x1, 1.2.3): skip it whole.
            while i < bytes.len() && (word(bytes[i]) || bytes[i] == b'.') {
                i += 1;
            }
            continue;
        }
        let frac = if frac_end > int_end {
            &message[int_end + 1..frac_end]
        } else {
            ""
        };
        if let Some(short) = exponent_form(&message[start..int_end], frac) {
            let buf = out.get_or_insert_with(|| String::with_capacity(message.len()));
            buf.push_str(&message[copied..start]);
            buf.push_str(&short);
            copied = frac_end;
        }
    }
    out.map(|mut buf| {
        buf.push_str(&message[copied..]);
        buf
    })
}

/// A computed `value` if it is finite; otherwise an error naming the user's `argument` that
/// says `what` cannot be represented (it overflows) — every returned number is finite.
pub fn finite_result(argument: &str, what: &str, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::invalid(
            argument,
            format!("{what} is not representable as a finite number for this value (it overflows)"),
        ))
    }
}

/// The error of a computed result that is not a finite number: `quantity` (`"force"`, `"energy"`)
/// overflows for the caller's `argument` (the input the overflowing term comes from), e.g.
/// `"position: the result (force) is not a finite number for these values (...)"`.
pub fn not_finite(argument: &str, quantity: &str) -> Error {
    Error::invalid(
        argument,
        format!(
            "the result ({quantity}) is not a finite number for these values (too large for \
             double precision, or outside the range where it can be computed); use smaller values"
        ),
    )
}

/// Checks that every computed value is finite; otherwise the error of [`not_finite`] naming
/// the caller's `argument` and the `quantity`. What makes "finite or refused" hold for every
/// number a public function of the core returns.
pub fn check_result(argument: &str, quantity: &str, values: &[f64]) -> Result<()> {
    if values.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(not_finite(argument, quantity))
    }
}

/// Checks that every value is finite; names `argument` otherwise.
pub fn check_finite(argument: &str, values: &[f64]) -> Result<()> {
    match values.iter().position(|v| !v.is_finite()) {
        None => Ok(()),
        Some(i) if values.len() == 1 => Err(Error::invalid(
            argument,
            format!("must be finite, got {}", num(values[i])),
        )),
        Some(i) => Err(Error::invalid(
            argument,
            format!("must be finite, got {} at index {}", num(values[i]), i),
        )),
    }
}

/// Checks that `value` is finite and strictly positive; names `argument` otherwise.
pub fn check_positive(argument: &str, value: f64) -> Result<()> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(Error::invalid(
            argument,
            format!("must be finite and > 0, got {}", num(value)),
        ))
    }
}

/// Checks that `value` is finite and not negative; names `argument` otherwise.
pub fn check_non_negative(argument: &str, value: f64) -> Result<()> {
    if value.is_finite() && value >= 0.0 {
        Ok(())
    } else {
        Err(Error::invalid(
            argument,
            format!("must be finite and >= 0, got {}", num(value)),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_kind_has_one_exception_class() {
        let names: Vec<&str> = ErrorKind::ALL.iter().map(|k| k.name()).collect();
        // The class names are pinned against Python's `poinsot.errors` by the Python test
        // `test_error_table.py`; here: one class a kind, the general kind's class the base, and
        // each other kind's class named for its condition (the interrupt is Python's own).
        let mut classes: Vec<&str> = ErrorKind::ALL.iter().map(|k| k.class_name()).collect();
        assert_eq!(ErrorKind::InvalidArgument.class_name(), "PoinsotError");
        assert_eq!(ErrorKind::Interrupted.class_name(), "KeyboardInterrupt");
        for kind in ErrorKind::ALL {
            let class = kind.class_name();
            assert!(
                class.ends_with("Error") || kind == ErrorKind::Interrupted,
                "{kind:?} -> {class}"
            );
        }
        classes.sort_unstable();
        classes.dedup();
        assert_eq!(
            classes.len(),
            ErrorKind::ALL.len(),
            "two kinds share a class"
        );
        for (kind, name) in ErrorKind::ALL.iter().zip(&names) {
            assert_eq!(format!("{kind:?}"), *name);
            assert!(!kind.class_name().is_empty());
        }
        // Every kind is listed once (a new kind must be added to ALL and to the table).
        let mut unique = names.clone();
        unique.sort_unstable();
        unique.dedup();
        assert_eq!(unique.len(), names.len());
        // Exhaustive: a kind missing from this match fails to compile.
        for kind in ErrorKind::ALL {
            match kind {
                ErrorKind::InvalidArgument
                | ErrorKind::InvalidInertia
                | ErrorKind::InvalidRotation
                | ErrorKind::InvalidMesh
                | ErrorKind::GimbalLock
                | ErrorKind::Diverged
                | ErrorKind::Interrupted => {}
            }
        }
    }

    #[test]
    fn messages_name_the_argument() {
        let e = check_positive("mass", -1.0).unwrap_err();
        assert_eq!(e.kind, ErrorKind::InvalidArgument);
        assert!(e.to_string().starts_with("mass:"), "{e}");
        assert!(check_finite("omega", &[1.0, f64::NAN, 2.0])
            .unwrap_err()
            .message
            .contains("index 1"));
        assert!(check_non_negative("height", 0.0).is_ok());
        assert!(check_non_negative("height", -0.0 - 1e-300).is_err());
        assert_eq!(num(1e308), "1e308");
        assert_eq!(num(-2.5), "-2.5");
        assert_eq!(num(5e-324), "5e-324");
        assert!(check_positive("dt", 1e-308).is_ok());
        // Numbers spelled out by `{}` become exponent form, same digits.
        assert_eq!(
            Error::invalid("I3", format!("must be <= 2*I1 = {}", 2e-308)).message,
            "must be <= 2*I1 = 2e-308"
        );
        assert_eq!(
            tidy_numbers(&format!("got {} and {} and {}", 1e300, -1.25e-310, 0.1)).unwrap(),
            "got 1e300 and -1.25e-310 and 0.1"
        );
        assert_eq!(
            tidy_numbers(&format!("{}", 1.2345678901234567e200)).unwrap(),
            "1.2345678901234567e200"
        );
        assert_eq!(tidy_numbers(&format!("{}", 1e16)).unwrap(), "1e16");
        assert_eq!(tidy_numbers(&format!("{}", 0.00001)).unwrap(), "1e-5");
        // In range, already in exponent form, words, exact whole numbers: unchanged.
        for kept in [
            "got 0.0001 and 9999999999999998 and 1e-308 and 5e-324 and 1.5e+308",
            "x100000000000000000000 at index 3, 0.00000 s",
            "18446744073709551615 bytes",
            "[1e-4, 1e16)",
        ] {
            assert_eq!(tidy_numbers(kept), None, "{kept}");
        }
        // Display applies it to a message changed after construction.
        let mut e = Error::invalid("t", "x");
        e.message = format!("got {}", 1e200);
        assert_eq!(e.to_string(), "t: got 1e200");
        assert!(check_positive("dt", -1e300)
            .unwrap_err()
            .message
            .ends_with("got -1e300"));
    }
}
