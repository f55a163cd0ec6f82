//! Library-level queries (`src/ffi/mod.rs`, `src/ffi/status.rs`): the
//! version, the last error message, status strings.

use super::Op;
use asperity::ffi::{asperity_last_error_message, asperity_status_string, asperity_version};
use std::ffi::{c_char, CStr};
use std::ptr::null_mut;

/// Runs one operation of this domain; `super::call` routes each variant
/// to the module of its `src/ffi/` file.
pub(super) unsafe fn call(op: &Op) {
    match op {
        Op::Version => {
            let v = CStr::from_ptr(asperity_version());
            assert!(!v.to_bytes().is_empty());
        }
        Op::LastError { len, null } => {
            let mut buf = vec![1 as c_char; len.0];
            let p = if *null { null_mut() } else { buf.as_mut_ptr() };
            let n = asperity_last_error_message(p, if *null { 0 } else { len.0 });
            if !*null && len.0 > 0 {
                let k = n.min(len.0 - 1);
                assert_eq!(buf[k], 0, "last_error_message: no NUL at {k}");
            }
        }
        Op::StatusString(s) => {
            let p = asperity_status_string(*s);
            assert!(!p.is_null());
            let _ = CStr::from_ptr(p);
        }
        _ => unreachable!("not a status operation: {op:?}"),
    }
}
