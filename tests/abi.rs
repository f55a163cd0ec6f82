//! ABI stability. `abi/asperity.abi` is the committed record of the C ABI of
//! the current ABI version: every function of `include/asperity.h`, every
//! `#define` constant with its value, and the size and alignment of every
//! `repr(C)` type (from `asperity_type_layout`, i.e. `size_of`/`align_of` of
//! the Rust types the header is generated from).
//!
//! The ABI version is `MAJOR` for `MAJOR >= 1`, and `0.MINOR` for 0.x (semver:
//! a 0.x minor release may break); it is the soname's suffix,
//! `libasperity.so.<ABI>` (build.rs, `common::abi_version`). Within one ABI
//! version (the record's `abi` equals the one of Cargo's version), the ABI
//! may only grow: a recorded function or constant that disappears, a
//! constant whose value changes, or a type whose size or alignment changes
//! fails this test, with no way to acknowledge it but a new ABI version.
//! Additions fail too until they are recorded with
//! `ASPERITY_BLESS=1 cargo test --test abi`, so the record always lists what
//! a later change must keep. An intended break bumps the ABI version in
//! `Cargo.toml` (the major version, or the minor one before 1.0), which also
//! changes the soname so that hosts built against the old ABI refuse the new
//! library; the same command then rewrites the record from scratch, and the
//! record's diff shows what broke.

mod common;

use asperity::ffi::abi::{asperity_type_count, asperity_type_layout, asperity_type_name};
use std::collections::BTreeMap;
use std::ffi::CString;
use std::path::PathBuf;

#[derive(Debug, Clone, PartialEq, Eq)]
struct Abi {
    /// The ABI version, `MAJOR` or `0.MINOR` (`common::abi_version`).
    abi: String,
    functions: BTreeMap<String, ()>,
    constants: BTreeMap<String, String>,
    types: BTreeMap<String, (usize, usize)>,
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The ABI of the library this test is linked with.
fn current() -> Abi {
    let header = std::fs::read_to_string(root().join("include/asperity.h")).expect("read header");
    let mut functions = BTreeMap::new();
    let mut constants = BTreeMap::new();
    for line in header.lines() {
        let t = line.trim();
        if let Some(rest) = t.strip_prefix("#define ") {
            let mut it = rest.split_whitespace();
            let (Some(name), Some(value)) = (it.next(), it.next()) else {
                continue;
            };
            // The version macros change with every release by design.
            if name.starts_with("ASPERITY_") && !name.starts_with("ASPERITY_VERSION_") {
                constants.insert(name.to_string(), value.to_string());
            }
            continue;
        }
        if t.starts_with("//") || t.starts_with('*') || t.starts_with("/*") {
            continue;
        }
        // Declarations: `<type> asperity_name(` (the name before the first
        // parenthesis of a prototype line).
        if let Some(p) = t.find("asperity_") {
            let tail = &t[p..];
            let end = tail
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .unwrap_or(tail.len());
            if tail[end..].starts_with('(') {
                functions.insert(tail[..end].to_string(), ());
            }
        }
    }
    let mut types = BTreeMap::new();
    for i in 0..asperity_type_count() {
        let mut needed = 0usize;
        let mut buf = vec![0u8; 128];
        // SAFETY: buf has buf.len() writable bytes; needed is valid.
        let s = unsafe { asperity_type_name(i, buf.as_mut_ptr().cast(), buf.len(), &mut needed) };
        assert_eq!(s, 0, "asperity_type_name({i})");
        assert!(needed < buf.len(), "type name {i} longer than the buffer");
        let name = String::from_utf8(buf[..needed].to_vec()).unwrap();
        let c = CString::new(name.clone()).unwrap();
        let (mut size, mut align) = (0usize, 0usize);
        // SAFETY: c is NUL-terminated; size and align are valid.
        let s = unsafe { asperity_type_layout(c.as_ptr(), &mut size, &mut align) };
        assert_eq!(s, 0, "asperity_type_layout({name})");
        types.insert(name, (size, align));
    }
    assert!(
        functions.len() > 50,
        "header parse found only {} functions",
        functions.len()
    );
    Abi {
        abi: common::abi_version(),
        functions,
        constants,
        types,
    }
}

fn render(a: &Abi) -> String {
    let mut s = format!(
        "# The C ABI of asperity, ABI version {} (soname libasperity.so.{}; tests/abi.rs).\n\
         # The ABI version is MAJOR, or 0.MINOR before 1.0. Within an ABI version\n\
         # entries may be added, never removed or changed.\n\
         # Record additions: ASPERITY_BLESS=1 cargo test --test abi\n\
         abi {}\n",
        a.abi, a.abi, a.abi
    );
    for f in a.functions.keys() {
        s += &format!("function {f}\n");
    }
    for (c, v) in &a.constants {
        s += &format!("constant {c} {v}\n");
    }
    for (t, (size, align)) in &a.types {
        s += &format!("type {t} size {size} align {align}\n");
    }
    s
}

fn parse(text: &str) -> Result<Abi, String> {
    let mut a = Abi {
        abi: String::new(),
        functions: BTreeMap::new(),
        constants: BTreeMap::new(),
        types: BTreeMap::new(),
    };
    for (k, line) in text.lines().enumerate() {
        let w: Vec<&str> = line.split_whitespace().collect();
        let bad = || format!("abi/asperity.abi line {}: cannot read `{line}`", k + 1);
        match w.as_slice() {
            [] => {}
            [c, ..] if c.starts_with('#') => {}
            ["abi", v] => a.abi = v.to_string(),
            ["function", f] => {
                a.functions.insert(f.to_string(), ());
            }
            ["constant", c, v] => {
                a.constants.insert(c.to_string(), v.to_string());
            }
            ["type", t, "size", s, "align", al] => {
                a.types.insert(
                    t.to_string(),
                    (
                        s.parse().map_err(|_| bad())?,
                        al.parse().map_err(|_| bad())?,
                    ),
                );
            }
            _ => return Err(bad()),
        }
    }
    if a.abi.is_empty() {
        return Err("abi/asperity.abi has no `abi` line (the ABI version it records)".into());
    }
    Ok(a)
}

/// What `now` breaks of `recorded` (same ABI version).
fn breaks(recorded: &Abi, now: &Abi) -> Vec<String> {
    let mut out = Vec::new();
    for f in recorded.functions.keys() {
        if !now.functions.contains_key(f) {
            out.push(format!("function {f} removed"));
        }
    }
    for (c, v) in &recorded.constants {
        match now.constants.get(c) {
            None => out.push(format!("constant {c} removed")),
            Some(w) if w != v => out.push(format!("constant {c} changed from {v} to {w}")),
            _ => {}
        }
    }
    for (t, l) in &recorded.types {
        match now.types.get(t) {
            None => out.push(format!("type {t} removed")),
            Some(m) if m != l => out.push(format!(
                "type {t} changed from size {} align {} to size {} align {}",
                l.0, l.1, m.0, m.1
            )),
            _ => {}
        }
    }
    out
}

/// What `now` adds to `recorded`.
fn additions(recorded: &Abi, now: &Abi) -> Vec<String> {
    let mut out = Vec::new();
    out.extend(
        now.functions
            .keys()
            .filter(|f| !recorded.functions.contains_key(*f))
            .map(|f| format!("function {f}")),
    );
    out.extend(
        now.constants
            .keys()
            .filter(|c| !recorded.constants.contains_key(*c))
            .map(|c| format!("constant {c}")),
    );
    out.extend(
        now.types
            .keys()
            .filter(|t| !recorded.types.contains_key(*t))
            .map(|t| format!("type {t}")),
    );
    out
}

#[test]
fn the_abi_only_grows_within_an_abi_version() {
    let path = root().join("abi/asperity.abi");
    let now = current();
    let bless = std::env::var_os("ASPERITY_BLESS").is_some_and(|v| v == "1");
    let recorded = match std::fs::read_to_string(&path) {
        Ok(text) => Some(parse(&text).unwrap()),
        Err(_) if bless => None,
        Err(e) => panic!(
            "{}: {e} (record it: ASPERITY_BLESS=1 cargo test --test abi)",
            path.display()
        ),
    };
    if let Some(rec) = &recorded {
        if rec.abi == now.abi {
            let b = breaks(rec, &now);
            assert!(
                b.is_empty(),
                "the C ABI of ABI version {} (soname libasperity.so.{}) changed incompatibly; \
                 keep it, or bump the ABI version in Cargo.toml (the major version, or the \
                 minor one before 1.0) and re-record with ASPERITY_BLESS=1 cargo test --test \
                 abi:\n  {}",
                now.abi,
                now.abi,
                b.join("\n  ")
            );
        } else if bless {
            let b = breaks(rec, &now);
            if !b.is_empty() {
                eprintln!(
                    "recording ABI version {} from scratch; it breaks ABI version {}:\n  {}",
                    now.abi,
                    rec.abi,
                    b.join("\n  ")
                );
            }
        } else {
            panic!(
                "abi/asperity.abi records ABI version {}, Cargo.toml's version has {}: record \
                 the new ABI with ASPERITY_BLESS=1 cargo test --test abi",
                rec.abi, now.abi
            );
        }
    }
    if bless {
        std::fs::write(&path, render(&now)).expect("write abi/asperity.abi");
        return;
    }
    let rec = recorded.unwrap();
    let add = additions(&rec, &now);
    assert!(
        add.is_empty(),
        "the C ABI grew; record the additions with ASPERITY_BLESS=1 cargo test --test abi:\n  {}",
        add.join("\n  ")
    );
}

/// The ABI version rule: `MAJOR` from 1.0 on, `0.MINOR` before, so that
/// 0.1 and 0.2 differ (semver lets a 0.x minor release break) while 1.3
/// and 1.4 agree.
#[test]
fn the_abi_version_is_major_or_zero_minor() {
    assert_eq!(common::abi_version_of(0, 1), "0.1");
    assert_eq!(common::abi_version_of(0, 2), "0.2");
    assert_eq!(common::abi_version_of(1, 3), "1");
    assert_eq!(common::abi_version_of(1, 4), "1");
    assert_eq!(common::abi_version_of(2, 0), "2");
}

/// The checker itself: a removal, a changed constant and a changed layout are
/// breaks; an addition is not.
#[test]
fn the_checker_sees_removals_and_changes() {
    let now = current();
    let mut old = now.clone();
    old.functions.insert("asperity_gone".into(), ());
    old.constants.insert("ASPERITY_GONE".into(), "1".into());
    let (t, l) = now
        .types
        .iter()
        .next()
        .map(|(t, l)| (t.clone(), *l))
        .unwrap();
    old.types.insert(t.clone(), (l.0 + 8, l.1));
    let c = now.constants.keys().next().unwrap().clone();
    old.constants.insert(c.clone(), "12345".into());
    let b = breaks(&old, &now);
    assert_eq!(b.len(), 4, "{b:?}");
    assert!(b.iter().any(|s| s.contains("asperity_gone")));
    assert!(b.iter().any(|s| s.contains(&t)));
    assert!(b.iter().any(|s| s.contains(&c)));
    let f = now.functions.keys().next().unwrap().clone();
    let mut smaller = now.clone();
    smaller.functions.remove(&f);
    assert!(
        breaks(&smaller, &now).is_empty(),
        "an addition is not a break"
    );
    assert_eq!(additions(&smaller, &now), vec![format!("function {f}")]);
    // The record round-trips.
    assert_eq!(parse(&render(&now)).unwrap(), now);
}
