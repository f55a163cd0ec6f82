//! Status codes of the C ABI and the one place that maps [`Error`] to them.

use crate::error::Error;
use std::ffi::c_char;

/// Success.
pub const ASPERITY_OK: i32 = 0;
/// A required pointer argument was NULL.
pub const ASPERITY_ERR_NULL_POINTER: i32 = -1;
/// An argument is outside its documented domain (NaN, ±∞ where not allowed,
/// negative radius, ν > 0.5, an unknown selector value, …).
pub const ASPERITY_ERR_INVALID_ARGUMENT: i32 = -2;
/// An iterative method did not reach its tolerance.
pub const ASPERITY_ERR_NOT_CONVERGED: i32 = -3;
/// Valid arguments, but no such state for this law (for example a load below
/// the pull-off force).
pub const ASPERITY_ERR_OUT_OF_DOMAIN: i32 = -4;
/// A bug in the library (a caught panic). The message says where.
pub const ASPERITY_ERR_INTERNAL: i32 = -5;
/// A file could not be read (not found, no permission, not text).
pub const ASPERITY_ERR_IO: i32 = -6;
/// A text file or buffer does not have the expected format; the message gives
/// the line.
pub const ASPERITY_ERR_PARSE: i32 = -7;

pub(crate) fn status_of(e: &Error) -> i32 {
    match e {
        Error::NullPointer { .. } => ASPERITY_ERR_NULL_POINTER,
        Error::InvalidArgument { .. } | Error::UnknownSelector { .. } => {
            ASPERITY_ERR_INVALID_ARGUMENT
        }
        Error::NotConverged { .. } => ASPERITY_ERR_NOT_CONVERGED,
        Error::OutOfDomain { .. } => ASPERITY_ERR_OUT_OF_DOMAIN,
        Error::Io { .. } => ASPERITY_ERR_IO,
        Error::Parse { .. } | Error::Binary { .. } => ASPERITY_ERR_PARSE,
    }
}

/// A static, NUL-terminated description of a status code; "unknown status"
/// for a value that is not one. Do not free.
#[no_mangle]
pub extern "C" fn asperity_status_string(status: i32) -> *const c_char {
    let s: &'static str = match status {
        ASPERITY_OK => "ok\0",
        ASPERITY_ERR_NULL_POINTER => "null pointer\0",
        ASPERITY_ERR_INVALID_ARGUMENT => "invalid argument\0",
        ASPERITY_ERR_NOT_CONVERGED => "not converged\0",
        ASPERITY_ERR_OUT_OF_DOMAIN => "out of domain\0",
        ASPERITY_ERR_INTERNAL => "internal error\0",
        ASPERITY_ERR_IO => "i/o error\0",
        ASPERITY_ERR_PARSE => "parse error\0",
        _ => "unknown status\0",
    };
    s.as_ptr().cast()
}
