//! Type layout queries (`src/ffi/abi.rs`).

use super::common::*;
use super::Op;
use asperity::ffi::abi::*;
use std::ffi::{c_char, CStr};
use std::ptr::{null, null_mut};

/// Runs one operation of this domain; `super::call` routes each variant
/// to the module of its `src/ffi/` file.
pub(super) unsafe fn call(op: &Op) {
    match op {
        Op::TypeLayout { index, name, nulls } => {
            let mut name_buf: Vec<u8> = match name {
                Some(b) => b.iter().copied().filter(|&c| c != 0).take(64).collect(),
                None => {
                    let count = asperity_type_count();
                    let mut needed = 0usize;
                    let i = if count == 0 { 0 } else { index.0 % count };
                    let mut b = vec![0 as c_char; 128];
                    let _ = asperity_type_name(i, b.as_mut_ptr(), b.len(), &mut needed);
                    CStr::from_ptr(b.as_ptr()).to_bytes().to_vec()
                }
            };
            name_buf.push(0);
            let (mut size, mut align) = (0usize, 0usize);
            let np = if nulls.at(0) {
                null()
            } else {
                name_buf.as_ptr() as *const c_char
            };
            let s =
                asperity_type_layout(np, mp(&mut size, nulls.at(1)), mp(&mut align, nulls.at(2)));
            if ok(s, "type_layout") {
                assert!(
                    align.is_power_of_two() && size % align == 0,
                    "layout {size}/{align}"
                );
            }
        }
        Op::TypeName { index, len, nulls } => {
            let mut buf = vec![1 as c_char; len.0];
            let mut needed = 0usize;
            let p = if nulls.at(0) {
                null_mut()
            } else {
                buf.as_mut_ptr()
            };
            let s = asperity_type_name(index.0, p, len.0, mp(&mut needed, nulls.at(1)));
            if ok(s, "type_name") && !nulls.at(0) && len.0 > 0 {
                assert_eq!(buf[needed.min(len.0 - 1)], 0);
            }
        }
        _ => unreachable!("not a abi operation: {op:?}"),
    }
}
