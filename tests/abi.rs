//! ABI stability. `abi/asperity.abi` is the committed record of the C ABI of
//! the current major version: every function of `include/asperity.h`, every
//! `#define` constant with its value, and the size and alignment of every
//! `repr(C)` type (from `asperity_type_layout`, i.e. `size_of`/`align_of` of
//! the Rust types the header is generated from).
//!
//! Within one major version (the record's `major` equals Cargo's), the ABI
//! may only grow: a recorded function or constant that disappears, a
//! constant whose value changes, or a type whose size or alignment changes
//! fails this test ("bump the major version"). Additions fail too until they
//! are recorded with `ASPERITY_BLESS=1 cargo test --test abi`, so the record
//! always lists what a later change must keep. After a major version bump
//! (which also changes the soname, `libasperity.so.MAJOR`), the same command
//! rewrites the record from scratch.
//!
//! Before 1.0 (major version 0) an intended break can be acknowledged
//! instead: `ASPERITY_BLESS=1 ASPERITY_ABI_BREAK=1 cargo test --test abi`
//! prints what breaks and rewrites the record, so the removal shows in the
//! record's diff and its commit says why (issue 30 §1 replaced the three
//! friction step contracts by one `AsperityFriction` handle this way).

use asperity::ffi::abi::{asperity_type_count, asperity_type_layout, asperity_type_name};
use std::collections::BTreeMap;
use std::ffi::CString;
use std::path::PathBuf;

#[derive(Debug, Clone, PartialEq, Eq)]
struct Abi {
    major: u64,
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
        major: env!("CARGO_PKG_VERSION_MAJOR").parse().unwrap(),
        functions,
        constants,
        types,
    }
}

fn render(a: &Abi) -> String {
    let mut s = format!(
        "# The C ABI of asperity, major version {} (tests/abi.rs).\n\
         # Within a major version entries may be added, never removed or changed.\n\
         # Record additions: ASPERITY_BLESS=1 cargo test --test abi\n\
         major {}\n",
        a.major, a.major
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
        major: u64::MAX,
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
            ["major", m] => a.major = m.parse().map_err(|_| bad())?,
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
    if a.major == u64::MAX {
        return Err("abi/asperity.abi has no `major` line".into());
    }
    Ok(a)
}

/// What `now` breaks of `recorded` (same major version).
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
fn the_abi_only_grows_within_a_major_version() {
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
    // Before 1.0 an intended break may be acknowledged and recorded.
    let acknowledged =
        bless && now.major == 0 && std::env::var_os("ASPERITY_ABI_BREAK").is_some_and(|v| v == "1");
    if let Some(rec) = &recorded {
        if rec.major == now.major {
            let b = breaks(rec, &now);
            if acknowledged && !b.is_empty() {
                eprintln!(
                    "recording an acknowledged break of the pre-1.0 C ABI:\n  {}",
                    b.join("\n  ")
                );
            } else {
                assert!(
                    b.is_empty(),
                    "the C ABI of major version {} changed incompatibly; keep it, or bump the \
                     major version in Cargo.toml (soname libasperity.so.MAJOR) and re-record \
                     (before 1.0, an intended break: ASPERITY_BLESS=1 ASPERITY_ABI_BREAK=1 \
                     cargo test --test abi):\n  {}",
                    now.major,
                    b.join("\n  ")
                );
            }
        } else if !bless {
            panic!(
                "abi/asperity.abi records major version {}, Cargo.toml says {}: record the new \
                 ABI with ASPERITY_BLESS=1 cargo test --test abi",
                rec.major, now.major
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
