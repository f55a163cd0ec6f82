//! The C ABI's error message, read the way a host code reads it, and the
//! assertion the C tests make on a failing call (shared by the test crates
//! that call the C functions from Rust).

#![allow(dead_code)]

use asperity::ffi::asperity_last_error_message;
use std::ptr::null_mut;

/// The calling thread's last error message: sized by a first call with a
/// NULL buffer, then read whole; the length returned is the full length
/// whatever the buffer, and the message is NUL-terminated UTF-8.
pub fn last_message() -> String {
    // SAFETY: a NULL buffer of length 0 sizes the message; then a buffer of
    // that many bytes plus the NUL.
    unsafe {
        let n = asperity_last_error_message(null_mut(), 0);
        let mut buf = vec![0u8; n + 1];
        let m = asperity_last_error_message(buf.as_mut_ptr().cast(), buf.len());
        assert_eq!(m, n, "the full length is returned whatever the buffer");
        assert_eq!(buf[n], 0, "NUL-terminated");
        String::from_utf8(buf[..n].to_vec()).expect("UTF-8 message")
    }
}

/// Assert a status and that the message names `what` (e.g. "`radius`").
#[track_caller]
pub fn expect_error(status: i32, code: i32, what: &str) {
    let msg = last_message();
    assert_eq!(status, code, "status (message: {msg})");
    assert!(msg.contains(what), "message `{msg}` should name {what}");
}
