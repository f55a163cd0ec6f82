//! The layout queries of the C ABI (`src/ffi/abi.rs`): `asperity_type_layout`
//! knows every struct and union of `include/asperity.h` that has a body (a
//! new struct without an entry fails here), `asperity_type_count` /
//! `asperity_type_name` list exactly those, and the sizes and alignments
//! agree with what a C compiler makes of the header.

use asperity::ffi::abi::{asperity_type_count, asperity_type_layout, asperity_type_name};
use asperity::ffi::{ASPERITY_ERR_INVALID_ARGUMENT, ASPERITY_ERR_NULL_POINTER, ASPERITY_OK};
use std::collections::{BTreeMap, BTreeSet};
use std::ffi::{c_char, CString};
use std::process::Command;

#[allow(dead_code)]
mod common;
use common::c_errors::last_message;

use common::native;

/// Structs and unions of the header with a body (`typedef struct X {`).
fn header_types() -> Vec<String> {
    let path = common::manifest().join("include/asperity.h");
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("reading {}: {e}", path.display()));
    text.lines()
        .filter_map(|l| {
            let rest = l
                .strip_prefix("typedef struct ")
                .or_else(|| l.strip_prefix("typedef union "))?;
            Some(rest.strip_suffix(" {")?.to_string())
        })
        .collect()
}

/// `asperity_type_layout(name)`: the status and (size, align).
fn layout(name: &[u8]) -> (i32, usize, usize) {
    let c = CString::new(name).unwrap();
    let (mut size, mut align) = (usize::MAX, usize::MAX);
    // SAFETY: a NUL-terminated name and two valid out-pointers.
    let st = unsafe { asperity_type_layout(c.as_ptr(), &mut size, &mut align) };
    (st, size, align)
}

/// Every name `asperity_type_name` lists, sized with a first call on (NULL, 0).
fn listed_names() -> Vec<String> {
    (0..asperity_type_count())
        .map(|i| {
            let mut needed = usize::MAX;
            // SAFETY: NULL buffer of length 0 and a valid `needed`.
            let st = unsafe { asperity_type_name(i, std::ptr::null_mut(), 0, &mut needed) };
            assert_eq!(
                st,
                ASPERITY_OK,
                "asperity_type_name({i}, NULL, 0): {}",
                last_message()
            );
            let mut buf = vec![b'#'; needed + 1];
            let mut again = 0usize;
            // SAFETY: `buf` holds `needed + 1` bytes.
            let st = unsafe {
                asperity_type_name(i, buf.as_mut_ptr().cast::<c_char>(), buf.len(), &mut again)
            };
            assert_eq!(st, ASPERITY_OK);
            assert_eq!(again, needed);
            assert_eq!(buf[needed], 0, "the name is NUL-terminated");
            String::from_utf8(buf[..needed].to_vec()).unwrap()
        })
        .collect()
}

#[test]
fn every_struct_of_the_header_is_known() {
    let types = header_types();
    assert!(
        types.len() >= 30,
        "only {} types parsed from the header",
        types.len()
    );
    let mut missing = Vec::new();
    for t in &types {
        let (st, size, align) = layout(t.as_bytes());
        if st != ASPERITY_OK {
            missing.push(format!("{t}: status {st}: {}", last_message()));
            continue;
        }
        assert!(
            size > 0 && align.is_power_of_two() && size % align == 0,
            "{t}: {size}, {align}"
        );
    }
    assert!(
        missing.is_empty(),
        "asperity_type_layout (src/ffi/abi.rs) does not know these structs of \
         include/asperity.h; add them to TYPES:\n{}",
        missing.join("\n")
    );
}

#[test]
fn the_list_is_exactly_the_header_structs() {
    let names = listed_names();
    let unique: BTreeSet<&String> = names.iter().collect();
    assert_eq!(
        unique.len(),
        names.len(),
        "a name is listed twice: {names:?}"
    );
    let header: BTreeSet<String> = header_types().into_iter().collect();
    let listed: BTreeSet<String> = names.into_iter().collect();
    let extra: Vec<_> = listed.difference(&header).collect();
    let missing: Vec<_> = header.difference(&listed).collect();
    assert!(
        extra.is_empty() && missing.is_empty(),
        "listed but not in the header: {extra:?}; in the header but not listed: {missing:?}"
    );
}

#[test]
fn names_are_copied_like_every_other_text() {
    // A buffer too small: truncated, NUL-terminated, the full length returned.
    let mut needed = 0usize;
    let mut small = [b'#'; 6];
    // SAFETY: `small` holds 6 bytes.
    let st = unsafe { asperity_type_name(0, small.as_mut_ptr().cast(), small.len(), &mut needed) };
    assert_eq!(st, ASPERITY_OK);
    let first = &listed_names()[0];
    assert_eq!(needed, first.len());
    assert_eq!(&small[..5], &first.as_bytes()[..5]);
    assert_eq!(small[5], 0);
}

#[test]
fn bad_arguments_are_named() {
    // An unknown name: invalid argument, the message names `name` and quotes it.
    let (st, _, _) = layout(b"AsperityNoSuchThing");
    assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT);
    let m = last_message();
    assert!(
        m.contains("`name`") && m.contains("\"AsperityNoSuchThing\""),
        "{m}"
    );
    // An opaque handle has no layout.
    let (st, _, _) = layout(b"AsperityTable");
    assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT);
    // Case matters, as in C.
    let (st, _, _) = layout(b"asperitynormallaw");
    assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT);
    // Not UTF-8: still a clear error, not a panic.
    let (st, _, _) = layout(b"Asperity\xff\xfe");
    assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT);
    assert!(last_message().contains("`name`"));
    // NULL pointers.
    let (mut size, mut align) = (0usize, 0usize);
    // SAFETY: NULL name is checked by the callee.
    let st = unsafe { asperity_type_layout(std::ptr::null(), &mut size, &mut align) };
    assert_eq!(st, ASPERITY_ERR_NULL_POINTER);
    assert!(last_message().contains("`name`"));
    let c = CString::new("AsperityNormalLaw").unwrap();
    // SAFETY: NULL `size` is checked by the callee.
    let st = unsafe { asperity_type_layout(c.as_ptr(), std::ptr::null_mut(), &mut align) };
    assert_eq!(st, ASPERITY_ERR_NULL_POINTER);
    assert!(last_message().contains("`size`"));
    // SAFETY: NULL `align` is checked by the callee.
    let st = unsafe { asperity_type_layout(c.as_ptr(), &mut size, std::ptr::null_mut()) };
    assert_eq!(st, ASPERITY_ERR_NULL_POINTER);
    assert!(last_message().contains("`align`"));
    // An index past the end.
    let mut needed = 0usize;
    let n = asperity_type_count();
    // SAFETY: NULL buffer of length 0.
    let st = unsafe { asperity_type_name(n, std::ptr::null_mut(), 0, &mut needed) };
    assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT);
    let m = last_message();
    assert!(
        m.contains("`index`") && m.contains("asperity_type_count"),
        "{m}"
    );
    // SAFETY: NULL `needed` is checked by the callee.
    let st = unsafe { asperity_type_name(0, std::ptr::null_mut(), 0, std::ptr::null_mut()) };
    assert_eq!(st, ASPERITY_ERR_NULL_POINTER);
    assert!(last_message().contains("`needed`"));
}

/// The sizes and alignments a C compiler gives the header's types (C11
/// `_Alignof`), against the library's answers.
#[test]
fn layouts_agree_with_the_c_compiler() {
    let l = native::layout().expect("target layout");
    let out = native::out_dir(&l, "abi_layout");
    std::fs::create_dir_all(&out).unwrap();
    let types = header_types();
    let mut src = String::from("#include \"asperity.h\"\n#include <stdio.h>\nint main(void)\n{\n");
    for t in &types {
        src.push_str(&format!(
            "    printf(\"%s %zu %zu\\n\", \"{t}\", sizeof({t}), (size_t)_Alignof({t}));\n"
        ));
    }
    src.push_str("    return 0;\n}\n");
    let c_file = out.join("layouts.c");
    std::fs::write(&c_file, src).unwrap();
    let bin = out.join("layouts");
    let tool = native::c_compiler(&l, &out).expect("a C compiler (the C examples need one too)");
    let mut cmd = tool.to_command();
    cmd.args(["-std=c11", "-Wall", "-Wextra", "-Werror", "-pedantic", "-I"])
        .arg(common::manifest().join("include"))
        .arg(&c_file)
        .arg("-o")
        .arg(&bin);
    native::run_ok(&mut cmd, "compiling the layout program").unwrap();
    let o = Command::new(&bin)
        .output()
        .expect("running the layout program");
    assert!(o.status.success());
    let c_layouts: BTreeMap<String, (usize, usize)> = String::from_utf8(o.stdout)
        .unwrap()
        .lines()
        .map(|l| {
            let w: Vec<&str> = l.split_whitespace().collect();
            (
                w[0].to_string(),
                (w[1].parse().unwrap(), w[2].parse().unwrap()),
            )
        })
        .collect();
    assert_eq!(c_layouts.len(), types.len());
    let mut errors = Vec::new();
    for (name, (size, align)) in &c_layouts {
        let (st, s, a) = layout(name.as_bytes());
        if st != ASPERITY_OK || (s, a) != (*size, *align) {
            errors.push(format!(
                "{name}: the C compiler says {size} bytes aligned to {align}, \
                 asperity_type_layout {s} and {a} (status {st})"
            ));
        }
    }
    assert!(errors.is_empty(), "{}", errors.join("\n"));
}
