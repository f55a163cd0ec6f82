//! The Rust error type.
//!
//! Every fallible function of the library returns [`Result<T>`]. The variants
//! carry only `&'static str` and numbers, so building an error never allocates
//! (a host code can hit the error path inside a hot loop without touching the
//! heap); the message is formatted only when it is displayed. The C ABI maps each
//! variant to a status code in `ffi/status.rs` and nowhere else.

use core::fmt;

/// The library's error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Error {
    /// An argument is outside its documented domain (negative radius, ν > 0.5,
    /// NaN, …). `name` is the argument's name as it appears in the API and
    /// `bound` the condition it violates.
    InvalidArgument {
        /// Argument name, as in the API (e.g. `"radius"`).
        name: &'static str,
        /// The value received.
        value: f64,
        /// The violated condition, as text (e.g. `"finite and > 0"`).
        bound: &'static str,
    },
    /// A required pointer was NULL (C ABI only).
    NullPointer {
        /// Argument name.
        name: &'static str,
    },
    /// An integer selector (law kind, control mode, …) has no meaning.
    UnknownSelector {
        /// Argument name (e.g. `"kind"`).
        name: &'static str,
        /// The value received.
        value: i64,
    },
    /// The arguments are individually valid but the requested state does not
    /// exist for this law (for example a rigid-sphere law asked for a
    /// penetration, or a load below the pull-off force).
    OutOfDomain {
        /// Argument name.
        name: &'static str,
        /// The value received.
        value: f64,
        /// Why it is outside the law's domain.
        reason: &'static str,
    },
    /// An iterative method did not reach its tolerance.
    NotConverged {
        /// Which solver.
        what: &'static str,
        /// Iterations spent.
        iterations: u32,
        /// Residual reached (in the solver's own scaled units).
        residual: f64,
    },
    /// Reading a file failed (not found, permission denied, not UTF-8 text, …).
    Io {
        /// What was being read (e.g. `"profile file"`).
        what: &'static str,
        /// The operating system's error kind.
        kind: std::io::ErrorKind,
    },
    /// A text file or buffer does not have the expected format.
    Parse {
        /// What was expected (e.g. `"two numeric columns x, z"`).
        what: &'static str,
        /// 1-based line number of the offending line (0 when the problem is
        /// the text as a whole, e.g. too few lines).
        line: u64,
    },
    /// A binary file or buffer does not have the expected format.
    Binary {
        /// What was expected (e.g. `"a zip local file header"`).
        what: &'static str,
        /// Byte offset in the file (or in the named archive member) where
        /// the problem was found.
        offset: u64,
    },
}

/// `Result` with the library's [`Error`].
pub type Result<T> = core::result::Result<T, Error>;

impl Error {
    /// This error with the argument name `from` replaced by `to`, for a
    /// caller that derived the argument from one of its own (the message
    /// names what the caller's user passed). Other errors pass through
    /// unchanged.
    #[cold]
    pub(crate) fn renamed(mut self, from: &'static str, to: &'static str) -> Error {
        match &mut self {
            Error::InvalidArgument { name, .. }
            | Error::OutOfDomain { name, .. }
            | Error::NullPointer { name }
            | Error::UnknownSelector { name, .. }
                if *name == from =>
            {
                *name = to;
            }
            _ => {}
        }
        self
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Error::InvalidArgument { name, value, bound } => {
                write!(f, "invalid argument `{name}` = {value:e}: must be {bound}")
            }
            Error::NullPointer { name } => write!(f, "null pointer: `{name}` must not be NULL"),
            Error::UnknownSelector { name, value } => {
                write!(f, "unknown value {value} for `{name}`")
            }
            Error::OutOfDomain {
                name,
                value,
                reason,
            } => {
                write!(f, "out of domain: `{name}` = {value:e}: {reason}")
            }
            Error::NotConverged {
                what,
                iterations,
                residual,
            } => write!(
                f,
                "not converged: {what} after {iterations} iterations (residual {residual:e})"
            ),
            Error::Io { what, kind } => write!(f, "cannot read {what}: {kind}"),
            Error::Parse { what, line: 0 } => write!(f, "parse error: {what}"),
            Error::Parse { what, line } => write!(f, "parse error at line {line}: {what}"),
            Error::Binary { what, offset } => {
                write!(f, "malformed binary data at byte offset {offset}: {what}")
            }
        }
    }
}

impl std::error::Error for Error {}

/// Argument checks shared by every module. Each returns the value on success so
/// constructors read as `let r = check::positive("radius", radius)?;`.
pub mod check {
    use super::{Error, Result};

    /// Finite and strictly positive.
    #[inline]
    pub fn positive(name: &'static str, value: f64) -> Result<f64> {
        if value.is_finite() && value > 0.0 {
            Ok(value)
        } else {
            Err(Error::InvalidArgument {
                name,
                value,
                bound: "finite and > 0",
            })
        }
    }

    /// Finite and ≥ 0.
    #[inline]
    pub fn non_negative(name: &'static str, value: f64) -> Result<f64> {
        if value.is_finite() && value >= 0.0 {
            Ok(value)
        } else {
            Err(Error::InvalidArgument {
                name,
                value,
                bound: "finite and >= 0",
            })
        }
    }

    /// Finite (any sign).
    #[inline]
    pub fn finite(name: &'static str, value: f64) -> Result<f64> {
        if value.is_finite() {
            Ok(value)
        } else {
            Err(Error::InvalidArgument {
                name,
                value,
                bound: "finite",
            })
        }
    }

    /// Poisson's ratio of an isotropic solid used by the contact laws: 0 ≤ ν ≤ 0.5.
    #[inline]
    pub fn poisson(name: &'static str, value: f64) -> Result<f64> {
        if (0.0..=0.5).contains(&value) {
            Ok(value)
        } else {
            Err(Error::InvalidArgument {
                name,
                value,
                bound: "in [0, 0.5]",
            })
        }
    }

    /// A cone or pyramid half-angle (rad), strictly between 0 and π/2.
    #[inline]
    pub fn half_angle(name: &'static str, value: f64) -> Result<f64> {
        if value > 0.0 && value < core::f64::consts::FRAC_PI_2 {
            Ok(value)
        } else {
            Err(Error::InvalidArgument {
                name,
                value,
                bound: "in (0, pi/2) rad",
            })
        }
    }

    /// A computed result that must be finite: `Ok(result)` when it is,
    /// otherwise [`Error::OutOfDomain`] naming the argument `name` (with its
    /// value `arg`) that drove it out of `f64`, for `reason`.
    #[inline]
    pub fn finite_result(
        result: f64,
        name: &'static str,
        arg: f64,
        reason: &'static str,
    ) -> Result<f64> {
        if result.is_finite() {
            Ok(result)
        } else {
            Err(Error::OutOfDomain {
                name,
                value: arg,
                reason,
            })
        }
    }

    /// Of the arguments `(name, value)`, the one farthest from 1 in
    /// magnitude (|ln|x||): the one to name when a product or quotient of
    /// them leaves the range of `f64`.
    #[inline]
    pub fn extreme(args: &[(&'static str, f64)]) -> (&'static str, f64) {
        let mut best = args[0];
        for &a in &args[1..] {
            if a.1.abs().ln().abs() > best.1.abs().ln().abs() {
                best = a;
            }
        }
        best
    }

    /// [`finite_result`] naming the [`extreme`] of `args`.
    #[inline]
    pub fn finite_of(
        result: f64,
        args: &[(&'static str, f64)],
        reason: &'static str,
    ) -> Result<f64> {
        if result.is_finite() {
            Ok(result)
        } else {
            let (name, value) = extreme(args);
            Err(Error::OutOfDomain {
                name,
                value,
                reason,
            })
        }
    }

    /// A value in a closed range `[lo, hi]`; `bound` names it for the message.
    #[inline]
    pub fn in_range(
        name: &'static str,
        value: f64,
        lo: f64,
        hi: f64,
        bound: &'static str,
    ) -> Result<f64> {
        if value >= lo && value <= hi {
            Ok(value)
        } else {
            Err(Error::InvalidArgument { name, value, bound })
        }
    }
}
