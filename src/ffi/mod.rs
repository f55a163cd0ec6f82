//! The C ABI. Translation only: argument checks for pointers and selectors,
//! conversion between C values and the Rust API, status codes. No physics lives
//! here.
//!
//! Every exported function runs inside `guard`, which turns a Rust error into
//! a negative status with a thread-local message and a panic into
//! [`ASPERITY_ERR_INTERNAL`]: no panic crosses the C boundary.

#![allow(clippy::missing_safety_doc)]

pub mod abi;
pub mod afm;
pub mod contact;
pub mod dynamic;
pub mod fidelity;
pub mod friction;
pub mod friction_law;
pub mod hierarchical;
pub mod homogenised;
pub mod indentation;
pub mod lj_sphere;
pub mod material;
pub mod slider;
pub mod statistics;
mod status;
pub mod surface;
pub mod tabulated;

pub use status::*;

use crate::error::{Error, Result};
use std::cell::RefCell;
use std::ffi::c_char;

thread_local! {
    static LAST_ERROR: RefCell<String> = const { RefCell::new(String::new()) };
}

fn set_last_error(message: String) {
    LAST_ERROR.with(|m| *m.borrow_mut() = message);
}

/// A failed call: the error and, for batch calls, the element it happened at.
pub(crate) struct Failure {
    error: Error,
    index: Option<usize>,
}

impl Failure {
    /// The error `error` at element `index` of a batch.
    #[cold]
    pub(crate) fn at(index: usize, error: Error) -> Self {
        Self {
            error,
            index: Some(index),
        }
    }
}

impl From<Error> for Failure {
    #[inline]
    fn from(error: Error) -> Self {
        Self { error, index: None }
    }
}

/// Run `f`, map its outcome to a status, record the message of a failure.
#[inline]
pub(crate) fn guard<F: FnOnce() -> core::result::Result<(), Failure>>(f: F) -> i32 {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)) {
        Ok(Ok(())) => ASPERITY_OK,
        Ok(Err(e)) => fail(&e),
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".to_string());
            set_last_error(format!("internal error (please report): {what}"));
            ASPERITY_ERR_INTERNAL
        }
    }
}

#[cold]
fn fail(f: &Failure) -> i32 {
    set_last_error(match f.index {
        Some(i) => format!("element {i}: {}", f.error),
        None => f.error.to_string(),
    });
    status_of(&f.error)
}

/// Whether the arrays of `n` doubles at `a` and `b` overlap without being
/// the same array (callers accept in place or disjoint states, nothing in
/// between).
pub(crate) fn partial_overlap(a: *const f64, b: *const f64, n: usize) -> bool {
    let (a, b) = (a as usize, b as usize);
    let bytes = n * core::mem::size_of::<f64>();
    a != b && a < b.saturating_add(bytes) && b < a.saturating_add(bytes)
}

/// Borrow a required input pointer.
#[inline]
pub(crate) unsafe fn input<'a, T>(p: *const T, name: &'static str) -> Result<&'a T> {
    p.as_ref().ok_or(Error::NullPointer { name })
}

/// Borrow a required output pointer.
#[inline]
pub(crate) unsafe fn output<'a, T>(p: *mut T, name: &'static str) -> Result<&'a mut T> {
    p.as_mut().ok_or(Error::NullPointer { name })
}

/// Copy `text` into the caller's `buf` of `len` bytes (at most `len − 1`
/// bytes plus a terminating NUL; nothing when `buf` is NULL or `len` is 0)
/// and return its full length in bytes, so a caller can size a buffer with a
/// first call on `(NULL, 0)`.
///
/// # Safety
/// `buf` is NULL or points to `len` writable bytes.
pub(crate) unsafe fn copy_text(text: &str, buf: *mut c_char, len: usize) -> usize {
    let bytes = text.as_bytes();
    if !buf.is_null() && len > 0 {
        let n = bytes.len().min(len - 1);
        core::ptr::copy_nonoverlapping(bytes.as_ptr(), buf.cast::<u8>(), n);
        *buf.add(n) = 0;
    }
    bytes.len()
}

/// The `len` bytes at `text` (no NUL needed) as UTF-8; errors name `name`
/// (NULL pointer, or the offset of the first invalid byte).
///
/// # Safety
/// `text` is NULL or points to `len` readable bytes that outlive the result.
pub(crate) unsafe fn read_text<'a>(
    text: *const c_char,
    len: usize,
    name: &'static str,
) -> Result<&'a str> {
    let p = input(text, name)?;
    let bytes = core::slice::from_raw_parts((p as *const c_char).cast::<u8>(), len);
    core::str::from_utf8(bytes).map_err(|e| Error::InvalidArgument {
        name,
        value: e.valid_up_to() as f64,
        bound: "UTF-8 text (invalid byte at this offset)",
    })
}

/// The library version, "MAJOR.MINOR.PATCH", from `Cargo.toml`. Static storage;
/// do not free.
#[no_mangle]
pub extern "C" fn asperity_version() -> *const c_char {
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_ptr().cast()
}

/// Copy the message of the last failed call on this thread into `buf` (at most
/// `len − 1` bytes plus a terminating NUL) and return the message's full length
/// in bytes (without the NUL), so a caller can size a buffer with
/// `asperity_last_error_message(NULL, 0)`. Successful calls leave the message
/// unchanged; it is empty before the first failure.
#[no_mangle]
pub unsafe extern "C" fn asperity_last_error_message(buf: *mut c_char, len: usize) -> usize {
    let r = std::panic::catch_unwind(|| {
        LAST_ERROR.with(|m| {
            // SAFETY: the caller provides `len` writable bytes at `buf`.
            unsafe { copy_text(m.borrow().as_str(), buf, len) }
        })
    });
    r.unwrap_or(0)
}
