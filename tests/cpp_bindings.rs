//! The header-only C++ bindings (`bindings/cpp/asperity.hpp`).
//!
//! - Completeness: every `asperity_*` function of `include/asperity.h` is
//!   called by the C++ header and named in a doc comment there, so a new C
//!   entry point without a C++ counterpart fails here, naming it; likewise
//!   every opaque handle has an RAII class.
//! - Every program in `examples/cpp` is compiled with the `cc` crate's C++
//!   compiler (`-std=c++17 -Wall -Wextra -Werror -pedantic`), linked against
//!   the freshly built `libasperity.a` and, separately, the shared library,
//!   run, and its `CHECK <name> <value>` lines compared with closed forms
//!   (REFERENCE.md) or separate calls of the Rust API. A program is one
//!   `.cpp` file, or the files `<name>_a.cpp`, `<name>_b.cpp`, … compiled as
//!   separate translation units and linked together (`two_units`).
//! - The header alone, included twice, compiles under stricter warnings
//!   (`-Wshadow -Wconversion -Wsign-conversion -Wold-style-cast …`) in C++17
//!   and C++20.
//!
//! Without a C++ compiler the compiling tests print why and pass.

mod common;

use common::native::{self, Binaries, Linkage, Report, Run};
use std::collections::{BTreeMap, BTreeSet};
use std::f64::consts::PI;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

const CXX_FLAGS: &[&str] = &["-std=c++17", "-Wall", "-Wextra", "-Werror", "-pedantic"];

/// Warnings host codes often build with: the header must be clean under them.
const STRICT_FLAGS: &[&str] = &[
    "-Wshadow",
    "-Wconversion",
    "-Wsign-conversion",
    "-Wold-style-cast",
    "-Wnon-virtual-dtor",
    "-Wcast-qual",
    "-Wundef",
];

/// C functions with deliberately no C++ wrapper, with the reason. None
/// today: `asperity_last_error_message` is `asperity::last_error_message()`
/// (used by `check`), the static strings are returned as `const char*`.
const NO_WRAPPER: &[(&str, &str)] = &[];

const CPP: &str = "the C++ bindings (bindings/cpp/asperity.hpp)";
const FFI: &str = "the C ABI (src/ffi)";
const LAWS: &str = "the contact laws (src/contact)";
const TABLE: &str = "the tabulated law (src/contact/tabulated/)";
const HOMOGENISED: &str = "the homogenised friction law (src/friction/homogenised.rs)";
const SLIDER: &str = "the slider geometry (src/friction/geometry.rs)";
const INDENT: &str = "indentation and rescaling (src/indentation/, src/rescaling.rs)";
const MATERIAL: &str = "material (src/material.rs)";
const STATS: &str = "statistics (src/statistics)";
const SURFACE: &str = "surfaces (src/surface)";
const LJ: &str =
    "the Lennard-Jones sphere and the advisor (src/contact/lj_sphere, src/fidelity.rs)";

fn hpp_path() -> PathBuf {
    common::manifest().join("bindings/cpp/asperity.hpp")
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("reading {}: {e}", path.display()))
}

/// `text` without `//` and `/* */` comments, and the comments alone.
fn split_comments(text: &str) -> (String, String) {
    let (mut code, mut comments) = (String::new(), String::new());
    let mut rest = text;
    while !rest.is_empty() {
        let line = rest.find("//");
        let block = rest.find("/*");
        match (line, block) {
            (Some(l), b) if b.map_or(true, |b| l < b) => {
                code.push_str(&rest[..l]);
                let end = rest[l..].find('\n').map_or(rest.len(), |e| l + e);
                comments.push_str(&rest[l..end]);
                comments.push('\n');
                rest = &rest[end..];
            }
            (_, Some(b)) => {
                code.push_str(&rest[..b]);
                let end = rest[b..].find("*/").map_or(rest.len(), |e| b + e + 2);
                comments.push_str(&rest[b..end]);
                comments.push('\n');
                code.push(' ');
                rest = &rest[end..];
            }
            _ => {
                code.push_str(rest);
                rest = "";
            }
        }
    }
    (code, comments)
}

/// Identifiers starting with `prefix` and followed (after spaces) by `(`.
fn called_names(code: &str, prefix: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let bytes = code.as_bytes();
    let ident = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    let mut from = 0;
    while let Some(k) = code[from..].find(prefix) {
        let start = from + k;
        from = start + prefix.len();
        if start > 0 && ident(bytes[start - 1]) {
            continue;
        }
        let end = start + code[start..].bytes().take_while(|&c| ident(c)).count();
        if code[end..].trim_start().starts_with('(') {
            out.insert(code[start..end].to_string());
        }
    }
    out
}

/// The functions the C header declares.
fn header_functions() -> BTreeSet<String> {
    let (code, _) = split_comments(&read(&common::manifest().join("include/asperity.h")));
    called_names(&code, "asperity_")
}

#[test]
fn every_c_function_has_a_cpp_counterpart() {
    let functions = header_functions();
    assert!(
        functions.len() >= 100 && functions.contains("asperity_table_eval"),
        "parsing include/asperity.h found only {} functions",
        functions.len()
    );
    let (code, comments) = split_comments(&read(&hpp_path()));
    let called = called_names(&code, "asperity_");
    let allowed: BTreeSet<&str> = NO_WRAPPER.iter().map(|(f, _)| *f).collect();
    let missing: Vec<&String> = functions
        .iter()
        .filter(|f| !called.contains(*f) && !allowed.contains(f.as_str()))
        .collect();
    assert!(
        missing.is_empty(),
        "C functions without a C++ wrapper in bindings/cpp/asperity.hpp (add one, or list \
         the function in NO_WRAPPER with the reason): {missing:?}"
    );
    let undocumented: Vec<&String> = functions
        .iter()
        .filter(|f| !allowed.contains(f.as_str()) && !comments.contains(&format!("`{f}`")))
        .collect();
    assert!(
        undocumented.is_empty(),
        "C functions whose C++ wrapper has no doc comment naming them: {undocumented:?}"
    );
    let unknown: Vec<&String> = called.iter().filter(|f| !functions.contains(*f)).collect();
    assert!(
        unknown.is_empty(),
        "asperity.hpp calls functions the C header does not declare: {unknown:?}"
    );
    for (f, _) in NO_WRAPPER {
        assert!(
            functions.contains(*f),
            "NO_WRAPPER lists {f}, which the C header does not declare"
        );
    }
}

#[test]
fn every_opaque_handle_has_an_raii_class() {
    let header = read(&common::manifest().join("include/asperity.h"));
    let handles: Vec<&str> = header
        .lines()
        .filter_map(|l| l.strip_prefix("typedef struct "))
        .filter_map(|l| {
            let mut w = l.split_whitespace();
            let (a, b) = (w.next()?, w.next()?);
            (b == format!("{a};")).then_some(a)
        })
        .collect();
    assert!(handles.len() >= 4, "found handles {handles:?}");
    let (code, _) = split_comments(&read(&hpp_path()));
    for h in handles {
        assert!(
            code.contains(&format!("unique_handle<{h},")),
            "the opaque handle {h} has no RAII class (detail::unique_handle<{h}, …>)"
        );
    }
}

// ---------------------------------------------------------------------------
// Building the programs

enum Built {
    /// No C++ compiler: the reason.
    Skipped(String),
    /// The programs, built.
    Ready(Binaries),
}

/// Programs of `examples/cpp`: `<name>_<letter>.cpp` files form one program.
fn programs() -> BTreeMap<String, Vec<PathBuf>> {
    let mut out: BTreeMap<String, Vec<PathBuf>> = BTreeMap::new();
    for s in native::sources("examples/cpp", "cpp") {
        let stem = s.file_stem().unwrap().to_string_lossy().into_owned();
        let name = match stem.rsplit_once('_') {
            Some((base, unit))
                if unit.len() == 1 && unit.bytes().all(|c| c.is_ascii_lowercase()) =>
            {
                base.to_string()
            }
            _ => stem,
        };
        out.entry(name).or_default().push(s);
    }
    out
}

fn includes(cmd: &mut Command) {
    let root = common::manifest();
    cmd.arg("-I")
        .arg(root.join("include"))
        .arg("-I")
        .arg(root.join("bindings/cpp"));
}

/// Compile one translation unit to an object file.
fn compile_object(tool: &cc::Tool, source: &Path, object: &Path) -> Result<(), String> {
    let mut cmd = tool.to_command();
    cmd.args(CXX_FLAGS);
    includes(&mut cmd);
    cmd.arg("-c").arg(source).arg("-o").arg(object);
    native::run_ok(&mut cmd, &format!("compiling {}", source.display()))
}

fn link(
    tool: &cc::Tool,
    objects: &[PathBuf],
    out: &Path,
    linkage: Linkage,
    lib_dir: &Path,
) -> Result<PathBuf, String> {
    let mut cmd = tool.to_command();
    cmd.args(objects).arg("-o").arg(out);
    cmd.args(linkage.link_args(lib_dir));
    native::run_ok(
        &mut cmd,
        &format!("linking {} ({linkage:?})", out.display()),
    )?;
    Ok(out.to_path_buf())
}

/// The C++ compiler, or why there is none.
fn cxx(l: &native::Layout, scratch: &Path) -> Result<cc::Tool, String> {
    let tool = native::cpp_compiler(l, scratch)?;
    match tool.to_command().arg("--version").output() {
        Ok(o) if o.status.success() => Ok(tool),
        Ok(o) => Err(format!(
            "{} --version failed: {}",
            tool.path().display(),
            String::from_utf8_lossy(&o.stderr)
        )),
        Err(e) => Err(format!("{} cannot be run: {e}", tool.path().display())),
    }
}

fn build_all() -> Result<Built, String> {
    let l = native::layout()?;
    let out = native::out_dir(&l, "cpp_bindings");
    std::fs::create_dir_all(&out).map_err(|e| format!("creating {}: {e}", out.display()))?;
    let tool = match cxx(&l, &out) {
        Ok(t) => t,
        Err(reason) => return Ok(Built::Skipped(reason)),
    };
    native::build_library(&l)?;
    let programs = programs();
    // Each translation unit once, then each program linked both ways.
    let units: Vec<(PathBuf, PathBuf)> = programs
        .values()
        .flatten()
        .map(|s| {
            let stem = s.file_stem().unwrap().to_string_lossy();
            (s.clone(), out.join(format!("{stem}.o")))
        })
        .collect();
    let compiled: BTreeMap<PathBuf, Result<(), String>> = units
        .iter()
        .map(|(s, _)| s.clone())
        .zip(native::parallel(&units, |(s, o)| {
            compile_object(&tool, s, o)
        }))
        .collect();
    let jobs: Vec<(String, Linkage)> = programs
        .keys()
        .flat_map(|n| Linkage::BOTH.map(|k| (n.clone(), k)))
        .collect();
    let linked = native::parallel(&jobs, |(name, k)| {
        let sources = &programs[name];
        for s in sources {
            if let Err(e) = &compiled[s] {
                return Err(e.clone());
            }
        }
        let objects: Vec<PathBuf> = units
            .iter()
            .filter(|(s, _)| sources.contains(s))
            .map(|(_, o)| o.clone())
            .collect();
        let bin = out.join(format!("{name}-{}", k.suffix()));
        link(&tool, &objects, &bin, *k, &l.profile_dir)
    });
    let mut binaries = Binaries::new();
    for ((name, k), r) in jobs.into_iter().zip(linked) {
        binaries.entry(name).or_default().insert(k, r);
    }
    Ok(Built::Ready(binaries))
}

/// The built programs, or None (with the reason printed) without a C++
/// compiler.
fn built() -> Option<&'static Binaries> {
    static BUILT: OnceLock<Result<Built, String>> = OnceLock::new();
    match BUILT.get_or_init(build_all) {
        Ok(Built::Ready(b)) => Some(b),
        Ok(Built::Skipped(reason)) => {
            common::skip(format_args!(
                "no usable C++ compiler ({reason}); install one (e.g. `apt-get install g++`) \
                 or name it with CXX=..."
            ));
            None
        }
        Err(e) => panic!("building the library and the C++ examples failed: {e}"),
    }
}

fn run(name: &str, linkage: Linkage) -> Option<Run> {
    let bin = native::binary(built()?, name, linkage, &format!("examples/cpp/{name}"));
    Some(native::run(
        &bin,
        &[],
        &format!("{name} ({linkage:?} linkage)"),
    ))
}

#[test]
fn every_example_compiles_and_links_both_ways() {
    let Some(b) = built() else { return };
    let errors = native::build_errors(b);
    for expected in [
        "tour",
        "two_units",
        "fe_block",
        "every_function",
        "slider_patch",
    ] {
        assert!(b.contains_key(expected), "examples/cpp has no {expected}");
    }
    assert!(errors.is_empty(), "{errors}");
}

/// Examples without their own checks below must at least run cleanly.
#[test]
fn every_other_example_runs() {
    let Some(b) = built() else { return };
    let known = [
        "tour",
        "two_units",
        "fe_block",
        "every_function",
        "slider_patch",
    ];
    for name in b.keys().filter(|n| !known.contains(&n.as_str())) {
        for k in Linkage::BOTH {
            let r = run(name, k).unwrap();
            let mut c = Report::new(&r);
            c.exit_ok("(unknown: see stderr)");
            c.finish();
        }
    }
}

#[test]
fn header_alone_is_clean_under_strict_warnings() {
    let Some(_) = built() else { return };
    let l = native::layout().unwrap();
    let out = native::out_dir(&l, "cpp_bindings");
    let tool = cxx(&l, &out).unwrap();
    // Included twice; the templates instantiated.
    let source = out.join("strict.cpp");
    std::fs::write(
        &source,
        "#include <asperity.hpp>\n#include <asperity.hpp>\n#include <array>\n\
         int main()\n{\n    std::vector<double> v(4, 1.0);\n    std::array<double, 2> a{1.0, 2.0};\n\
         double c[3] = {1.0, 2.0, 3.0};\n    asperity::span<const double> s1(v);\n\
         asperity::span<const double> s2(a);\n    asperity::span<double> s3(c);\n\
         asperity::span<const double> s4(s3);\n    asperity::span<const double> s5{c, 2};\n\
         const AsperityZhuravlev z{0.0, 1e-6, 1e9, 100.0};\n    try {\n\
         (void)asperity::zhuravlev_eval(z, 1e-9, [](double x) { return x; }, \
         [](double x) { return 2.0 * x; }, 8);\n    } catch (const asperity::Error&) {\n    }\n\
         asperity::Table t;\n    asperity::Table u = std::move(t);\n\
         return static_cast<int>(s1.size() + s2.size() + s3.size() + s4.size() + s5.size()) - 15 + \
         (u ? 1 : 0);\n}\n",
    )
    .unwrap();
    for std in ["-std=c++17", "-std=c++20"] {
        let mut cmd = tool.to_command();
        cmd.args(&CXX_FLAGS[1..]).arg(std).args(STRICT_FLAGS);
        includes(&mut cmd);
        cmd.arg("-c")
            .arg(&source)
            .arg("-o")
            .arg(out.join(format!("strict{}.o", &std[5..])));
        native::run_ok(
            &mut cmd,
            &format!("compiling the header alone ({std}, strict warnings)"),
        )
        .unwrap_or_else(|e| panic!("{e}"));
    }
}

// ---------------------------------------------------------------------------
// Independent reference values

const R: f64 = 1e-6;
const W: f64 = 0.05;
const E_STAR: f64 = 1e9;
const SIGMA0: f64 = 3.27e7;

fn hertz(radius: f64, e_star: f64, delta: f64) -> f64 {
    4.0 / 3.0 * e_star * radius.sqrt() * delta.powf(1.5)
}

fn no_slip_factor(nu: f64) -> f64 {
    (1.0 - nu) * (3.0 - 4.0 * nu).ln() / (1.0 - 2.0 * nu)
}

/// The Maugis–Dugdale pull-off of the examples' sphere through the Rust API.
fn md_pull_off(control: asperity::Control) -> f64 {
    use asperity::contact::MaugisDugdale;
    use asperity::NormalContact;
    MaugisDugdale::new(R, E_STAR, W, SIGMA0)
        .unwrap()
        .pull_off_force(control)
        .unwrap()
}

/// The examples' Maugis–Dugdale table through the Rust API (built once).
fn md_table() -> &'static asperity::contact::TabulatedLaw {
    use asperity::contact::{MaugisDugdale, TabulatedLaw};
    static TABLE: OnceLock<TabulatedLaw> = OnceLock::new();
    TABLE.get_or_init(|| {
        let md = MaugisDugdale::new(R, E_STAR, W, SIGMA0).unwrap();
        TabulatedLaw::from_maugis_dugdale(&md, 1e-4).unwrap()
    })
}

/// Which linkages to test.
fn each_linkage(check: impl Fn(Linkage)) {
    for k in Linkage::BOTH {
        check(k);
    }
}

// ---------------------------------------------------------------------------

fn check_tour(linkage: Linkage) {
    let Some(r) = run("tour", linkage) else {
        return;
    };
    let mut c = Report::new(&r);
    c.exit_ok(CPP);
    let piwr = PI * W * R;
    c.rel(MATERIAL, "e_star", E_STAR, 1e-14);
    c.rel(MATERIAL, "work_of_adhesion", W, 1e-14);
    c.close(CPP, "version_matches_header", 1.0, 0.0);
    let delta = 10e-9;
    let a = (R * delta).sqrt();
    c.rel(LAWS, "hertz_force", hertz(R, E_STAR, delta), 1e-12);
    c.rel(LAWS, "hertz_contact_radius", a, 1e-12);
    c.rel(LAWS, "hertz_stiffness", 2.0 * E_STAR * a, 1e-12);
    c.rel(LAWS, "jkr_pull_off_load", -1.5 * piwr, 1e-9);
    c.rel(LAWS, "jkr_pull_off_displacement", -5.0 / 6.0 * piwr, 1e-9);
    c.rel(LAWS, "dmt_pull_off_load", -2.0 * piwr, 1e-12);
    // JKR at P = 1 µN: a³ = (3R/4E*)(P + 3πwR + √(6πwRP + (3πwR)²)),
    // REFERENCE.md section 8: 1.24133e-7 m.
    let p = 1e-6;
    let a_1un = (3.0 * R / (4.0 * E_STAR)
        * (p + 3.0 * piwr + (6.0 * piwr * p + (3.0 * piwr).powi(2)).sqrt()))
    .cbrt();
    assert!((a_1un - 1.24133e-7).abs() < 1e-12);
    c.rel(LAWS, "jkr_radius_at_1uN", a_1un, 1e-9);
    c.close(LAWS, "jkr_fresh_in_contact", 0.0, 0.0);
    c.close(LAWS, "jkr_retracted_in_contact", 1.0, 0.0);
    c.close(CPP, "jkr_state_radius_matches", 1.0, 0.0);
    // The retracted contact is on the JKR curve at δ = −1 nm.
    if let Some(a) = c.get(LAWS, "jkr_retracted_contact_radius") {
        let d = a * a / R - (2.0 * PI * W * a / E_STAR).sqrt();
        c.ok(LAWS, (d + 1e-9).abs() < 1e-9 * 1e-9, || {
            format!("retracted contact radius {a:e} gives δ = {d:e}, not −1 nm")
        });
        let force =
            4.0 * E_STAR * a.powi(3) / (3.0 * R) - (8.0 * PI * W * E_STAR * a.powi(3)).sqrt();
        c.rel(LAWS, "jkr_retracted_force", force, 1e-9);
    }
    c.rel(LAWS, "hertz_batch_force_3", hertz(R, E_STAR, delta), 1e-12);
    let k = 4.0 * E_STAR / 3.0;
    c.rel(
        MATERIAL,
        "maugis_lambda",
        2.0 * SIGMA0 * (R / (PI * W * k * k)).cbrt(),
        1e-12,
    );
    c.close(TABLE, "table_tolerance", 1e-4, 0.0);
    c.close(
        TABLE,
        "table_measured_error",
        md_table().measured_error(),
        0.0,
    );
    c.within(TABLE, "table_measured_error", 0.0, 1e-4);
    c.rel(
        TABLE,
        "table_pull_off_load",
        md_pull_off(asperity::Control::Load),
        1e-10,
    );
    c.rel(
        TABLE,
        "table_pull_off_displacement",
        md_pull_off(asperity::Control::Displacement),
        1e-10,
    );
    c.within(TABLE, "json_bytes", 100.0, f64::INFINITY);
    c.close(TABLE, "json_roundtrip_identical", 1.0, 0.0);
    c.close(CPP, "moved_from_is_empty", 1.0, 0.0);
    c.close(CPP, "moved_to_holds_table", 1.0, 0.0);
    if let Some(v) = c.get(CPP, "table_pull_off_load") {
        c.close(CPP, "raw_pull_off_load", v, 0.0);
    }
    c.close(CPP, "bad_radius_threw", 1.0, 0.0);
    c.close(CPP, "bad_radius_status", -2.0, 0.0);
    c.close(FFI, "bad_radius_names_radius", 1.0, 0.0);
    c.close(CPP, "bad_radius_message_is_last_error", 1.0, 0.0);
    c.close(CPP, "bad_radius_status_string_ok", 1.0, 0.0);
    c.close(CPP, "short_array_threw", 1.0, 0.0);
    c.close(CPP, "short_array_status", -2.0, 0.0);
    c.close(CPP, "short_array_names_force", 1.0, 0.0);
    let message_ok = r
        .stdout
        .lines()
        .find_map(|l| l.strip_prefix("message: "))
        .is_some_and(|m| m.contains("`radius`"));
    c.ok(CPP, message_ok, || {
        "no `message:` line naming `radius`".into()
    });
    c.finish();
}

#[test]
fn tour() {
    each_linkage(check_tour);
}

fn check_two_units(linkage: Linkage) {
    let Some(r) = run("two_units", linkage) else {
        return;
    };
    let mut c = Report::new(&r);
    c.exit_ok(CPP);
    let piwr = PI * W * R;
    c.rel(LAWS, "dmt_pull_off_from_b", -2.0 * piwr, 1e-12);
    c.rel(LAWS, "jkr_pull_off_from_a", -1.5 * piwr, 1e-9);
    c.rel(
        TABLE,
        "table_from_b_pull_off_load",
        md_pull_off(asperity::Control::Load),
        1e-10,
    );
    c.close(CPP, "error_from_b_caught", 1.0, 0.0);
    c.close(CPP, "error_from_b_status", -2.0, 0.0);
    c.close(FFI, "error_from_b_names_e_star", 1.0, 0.0);
    c.within(STATS, "zhuravlev_a_rel_diff_closed", 0.0, 1e-9);
    c.within(STATS, "zhuravlev_b_rel_diff_closed", 0.0, 1e-9);
    c.close(CPP, "hertz_batch_a_equals_b", 1.0, 0.0);
    c.rel(LAWS, "hertz_batch_force_2", hertz(R, E_STAR, 8e-9), 1e-12);
    c.finish();
}

#[test]
fn two_translation_units() {
    each_linkage(check_two_units);
}

fn check_fe_block(linkage: Linkage) {
    use asperity::friction::{CofForm, Dissipation, HomogenisedFriction, HomogenisedSample};
    let Some(r) = run("fe_block", linkage) else {
        return;
    };
    let mut c = Report::new(&r);
    c.exit_ok(HOMOGENISED);
    c.close(CPP, "state_size_matches", 1.0, 0.0);
    c.close(CPP, "points", 16.0, 0.0);
    // The program's law, rebuilt through the Rust API: a point slides at
    // its slip limit μ(p)(N + A), A = p_adh(p)·A_n.
    let law = HomogenisedFriction::from_samples(
        &[
            // (p MPa, μ, p_adh MPa, fraction, chemical, vdW, elastic)
            (20.0, 1.05, 2.0, 0.02, 0.93, 0.06, 0.005),
            (70.0, 0.98, 6.0, 0.07, 0.92, 0.065, 0.01),
            (120.0, 0.92, 10.0, 0.12, 0.90, 0.07, 0.02),
        ]
        .map(
            |(p, cof, adh, fraction, chemical, vdw, elastic)| HomogenisedSample {
                pressure: p * 1e6,
                cof,
                adhesion_pressure: adh * 1e6,
                contact_fraction: fraction,
                shares: Dissipation {
                    chemical,
                    van_der_waals: vdw,
                    elastic,
                    plastic: 1.0 - chemical - vdw - elastic,
                },
            },
        ),
        CofForm::Derjaguin,
    )
    .unwrap();
    let (area, k, ds, forward) = (1e-6, 1e7, 1e-7, 500.0);
    let limits: Vec<f64> = (0..16)
        .map(|i| {
            let p = 20e6 + 100e6 * i as f64 / 15.0;
            let s = law.sample_at(p).unwrap();
            s.cof * (p + s.adhesion_pressure) * area
        })
        .collect();
    let total: f64 = limits.iter().sum();
    // The force opposes the slip: −Σ limits forward, +Σ after the reversal.
    c.rel(HOMOGENISED, "force_along_end_forward", -total, 1e-9);
    c.rel(HOMOGENISED, "force_along_end_backward", total, 1e-9);
    c.close(
        HOMOGENISED,
        "first_slip_increment_point0",
        (limits[0] / (k * ds)).ceil(),
        0.0,
    );
    c.close(CPP, "scalar_equals_block", 1.0, 0.0);
    // Plastic slip path per point 2D − 3·limit/k, D = forward·ds.
    let dissipation: f64 = limits
        .iter()
        .map(|l| l * (2.0 * forward * ds - 3.0 * l / k))
        .sum();
    c.rel(HOMOGENISED, "total_dissipation", dissipation, 1e-9);
    c.rel(HOMOGENISED, "ledger_total", dissipation, 1e-9);
    c.close(HOMOGENISED, "min_increment_dissipation", 0.0, 0.0);
    // Every increment of every point is booked: Σ slip path = 16·2D.
    c.rel(
        HOMOGENISED,
        "slip_path_total",
        16.0 * 2.0 * forward * ds,
        1e-12,
    );
    c.close(HOMOGENISED, "slip_increment", ds, 0.0);
    c.close(HOMOGENISED, "stick_stiffness", k, 0.0);
    c.close(HOMOGENISED, "forward_increments", forward, 0.0);
    c.close(HOMOGENISED, "json_roundtrip_identical", 1.0, 0.0);
    c.close(CPP, "bad_area_threw", 1.0, 0.0);
    c.close(FFI, "bad_area_status", -2.0, 0.0);
    c.close(FFI, "bad_area_names_element", 1.0, 0.0);
    c.close(FFI, "bad_area_names_area", 1.0, 0.0);
    c.close(CPP, "short_areas_threw", 1.0, 0.0);
    c.close(CPP, "short_areas_status", -2.0, 0.0);
    c.close(CPP, "short_areas_names_areas", 1.0, 0.0);
    let history = r.rows(&["history"]).len();
    c.ok(HOMOGENISED, history == 10, || {
        format!("{history} history rows, expected 10")
    });
    c.finish();
}

#[test]
fn fe_block() {
    each_linkage(check_fe_block);
}

// ---------------------------------------------------------------------------
// slider_patch: self-checking; here its slider record against the Rust API

const SLIDER_STEP: &str = "the slider step (src/friction/slider/, src/ffi/slider.rs)";

/// `slider_patch` checks itself (exit status); its record of patch 0's
/// tangent step (`FrictionWork::slider_record`) is compared here with the
/// Rust step's `SliderWork::record()` from the same history, and the record
/// of the first two blocks (patch 3, from 0) with the track positions.
fn check_slider_patch(linkage: Linkage) {
    use asperity::friction::Slider;
    use asperity::scene::Scene;
    let Some(r) = run("slider_patch", linkage) else {
        return;
    };
    let mut c = Report::new(&r);
    c.exit_ok(SLIDER_STEP);
    let slider: Slider =
        Scene::from_file(common::manifest().join("examples/scenes/chapter6_copper.json"))
            .unwrap()
            .build()
            .unwrap();
    // The blocks' record (patch 3, from 0), and patch 0: 60 increments of
    // 1.5 um along +x at 5 % of the capacity, then one with both tangents
    // from that state.
    let step = 1.5e-6;
    let (_, position) = native::check_slider_record(
        &mut c,
        (SLIDER_STEP, FFI),
        ["block0", "block1"],
        &slider,
        0.05 * slider.capacity(),
        (60, step),
    );
    c.close(
        SLIDER_STEP,
        "tangent_record_position",
        position + step,
        1e-15,
    );
    c.close(CPP, "tangent_record_matches_state", 1.0, 0.0);
    c.close(CPP, "reevaluation_identical", 1.0, 0.0);
    c.close(FFI, "record_null_work_status", -1.0, 0.0);
    c.finish();
}

#[test]
fn slider_patch() {
    each_linkage(check_slider_patch);
}

// ---------------------------------------------------------------------------
// every_function: one check per wrapper

fn every_function_laws(c: &mut Report) {
    let piwr = PI * W * R;
    let delta = 10e-9;
    c.rel(
        LAWS,
        "sphere_in_crater_force",
        hertz(1.0 / (1.0 / R - 1.0 / 4e-6), E_STAR, delta),
        1e-12,
    );
    // Galin, d = 1.5: C(1.5) = 2.156652423, D(1.5) = 1.797210352.
    let (b, d) = (1e3, 1.5);
    let a = (2.1566524e-3 / (2.156652423 * b * E_STAR)).powf(1.0 / (d + 1.0));
    c.rel(LAWS, "power_punch_radius_at_load", a, 1e-8);
    c.rel(
        LAWS,
        "power_punch_delta_at_load",
        1.797210352 * b * a.powf(d),
        1e-8,
    );
    let tan = 1.2f64.tan();
    c.rel(
        LAWS,
        "cone_force",
        2.0 * E_STAR * delta * delta * tan / PI,
        1e-12,
    );
    c.rel(LAWS, "cone_contact_radius", 2.0 * delta * tan / PI, 1e-12);
    let b_imprint = 1.0 / 1.0f64.tan() - 1.0 / 1.3f64.tan();
    c.rel(
        LAWS,
        "cone_in_imprint_force",
        2.0 * E_STAR * delta * delta / (PI * b_imprint),
        1e-12,
    );
    c.rel(LAWS, "flat_punch_force", 2.0 * E_STAR * 2e-6 * 1e-9, 1e-12);
    c.rel(LAWS, "flat_punch_stiffness", 2.0 * E_STAR * 2e-6, 1e-12);
    c.rel(
        LAWS,
        "flat_punch_no_slip_force",
        2.0 * E_STAR * 2e-6 * 1e-9 * no_slip_factor(0.355),
        1e-12,
    );
    c.rel(
        LAWS,
        "dmt_force",
        hertz(R, E_STAR, delta) - 2.0 * piwr,
        1e-12,
    );
    c.rel(
        LAWS,
        "jkr_length_scale",
        0.75 * (PI * PI * W * W * R / (E_STAR * E_STAR)).cbrt(),
        1e-12,
    );
    c.close(LAWS, "hertz_length_scale", 3e-6, 0.0);
    c.close(CPP, "jkr_new_state_written", 1.0, 0.0);
    c.close(CPP, "jkr_old_state_untouched", 1.0, 0.0);
    c.close(CPP, "jkr_new_state_radius", 1.0, 0.0);
    c.rel(LAWS, "jkr_power_punch_pull_off", -1.5 * piwr, 1e-8);
    // Bonded punch, d = 2, ν = 0.355: A = C_NS C(2) B E*/k*(2),
    // b = √(8πwE*C_NS), P_c = −b (2d−1)/(2(d+1)) [3b/(2(d+1)A)]^{3/(2d−1)}
    // (REFERENCE.md section 7, k*(2) = 0.985405871).
    let cns = no_slip_factor(0.355);
    let big_a = cns * (8.0 / 3.0) * (1.0 / (2.0 * R)) * E_STAR / 0.985405871;
    let small_b = (8.0 * PI * W * E_STAR * cns).sqrt();
    let p_c = -small_b * 3.0 / 6.0 * (3.0 * small_b / (6.0 * big_a));
    c.rel(LAWS, "jkr_power_punch_no_slip_pull_off", p_c, 1e-7);
    let kendall = -(8.0 * PI * W * E_STAR * 1e-18f64).sqrt();
    assert!((kendall + 3.54491e-5).abs() < 1e-10);
    c.rel(LAWS, "kendall_pull_off", kendall, 1e-12);
    c.rel(
        LAWS,
        "kendall_no_slip_pull_off",
        kendall * cns.sqrt(),
        1e-12,
    );
    c.rel(
        LAWS,
        "from_params_kendall_no_slip_pull_off",
        kendall * cns.sqrt(),
        1e-12,
    );
    c.close(CPP, "from_params_inputs_read_back", 1.0, 0.0);
    c.close(CPP, "from_params_bad_no_slip_threw", 1.0, 0.0);
    c.close(FFI, "from_params_bad_no_slip_status", -2.0, 0.0);
    c.close(FFI, "from_params_bad_no_slip_names_argument", 1.0, 0.0);
    c.rel(
        LAWS,
        "md_pull_off_load",
        md_pull_off(asperity::Control::Load),
        1e-12,
    );
    let k = 4.0 * E_STAR / 3.0;
    c.rel(
        LAWS,
        "md_length_scale",
        (PI * PI * W * W * R / (k * k)).cbrt(),
        1e-12,
    );
    c.rel(LAWS, "derjaguin_pull_off", -2.0 * piwr, 1e-9);
    c.rel(LAWS, "derjaguin_length_scale", 0.3e-9, 1e-15);
    c.close(CPP, "hertz_batch_equals_scalar", 1.0, 0.0);
    c.rel(
        LAWS,
        "hertz_batch_stiffness_3",
        2.0 * E_STAR * (R * 20e-9).sqrt(),
        1e-12,
    );
}

fn every_function_lj_and_tables(c: &mut Report) {
    use asperity::contact::{LjSphere, TabulatedLaw};
    use asperity::{Control, NormalContact};
    let lj = LjSphere::new(110e-9, 4.075403e11, 7.40923e-3, 1.65e-10)
        .unwrap()
        .pull_off_force(64)
        .unwrap();
    c.rel(LJ, "lj_pull_off", lj, 1e-12);
    c.rel(LJ, "lj_pull_off", -5.121e-9, 0.02);
    c.rel(LJ, "fidelity_tabor", 0.1, 1e-12);
    // Richardson: 1.9689564 πRw at μ = 0.1 (tests/fidelity.rs).
    c.rel(
        LJ,
        "fidelity_reference_pull_off",
        -1.9689564 * PI * R * W,
        1e-3,
    );
    c.close(CPP, "fidelity_assessments_ordered", 1.0, 0.0);
    c.within(LJ, "fidelity_choice", 0.0, 5.0);
    let z0: f64 = 0.3e-9;
    let e05 = (R * W * W / z0.powi(3)).sqrt() / 0.5f64.powf(1.5);
    let table =
        TabulatedLaw::from_lj_sphere(&LjSphere::new(R, e05, W, z0).unwrap(), 48, 1e-3).unwrap();
    c.close(TABLE, "lj_table_tolerance", 1e-3, 0.0);
    c.close(
        TABLE,
        "lj_table_pull_off",
        table.pull_off_force(Control::Load).unwrap(),
        0.0,
    );
    c.close(
        TABLE,
        "md_table_at_zero_load_delta",
        md_table().eval_at_load(0.0).unwrap().delta,
        0.0,
    );
    c.close(CPP, "md_table_batch_equals_scalar", 1.0, 0.0);
}

fn every_function_slider(c: &mut Report) {
    use asperity::friction::SliderGeometry;
    c.close(CPP, "uniform_nano_round_trip", 1.0, 0.0);
    c.close(SLIDER, "uniform_levels", 1.0, 0.0);
    c.close(SLIDER, "uniform_rods", 3.0, 0.0);
    c.close(SLIDER, "uniform_rod_width", 13.5e-6, 0.0);
    c.close(SLIDER, "uniform_rod_heights_max_abs", 0.0, 0.0);
    let (nm, um) = (1e-9, 1e-6);
    let micro: Vec<f64> = [1.0, 3.0, -1.0, 5.0, 0.0, 2.0, 4.0, -2.0, 1.0, 3.0]
        .iter()
        .map(|h| h * nm)
        .collect();
    let period = [3.0, 3.0, 1.0, 1.0, -2.0, -2.0, -2.0, -2.0];
    let nano: Vec<f64> = (0..32).map(|j| period[j % 8] * nm).collect();
    let g =
        SliderGeometry::from_slices(&micro, um, &[5.0 * um, 2.5 * um], &nano, 10.0 * nm).unwrap();
    c.close(SLIDER, "profile_levels", g.levels().len() as f64, 0.0);
    for (l, level) in g.levels().iter().enumerate() {
        c.close(
            SLIDER,
            &format!("profile_rod_count_{l}"),
            level.len() as f64,
            0.0,
        );
        c.close(
            SLIDER,
            &format!("profile_rod_width_{l}"),
            level.width(),
            0.0,
        );
        c.close(
            SLIDER,
            &format!("profile_rod_origin_{l}"),
            level.origin(),
            0.0,
        );
        for (k, h) in level.heights().iter().enumerate() {
            c.close(SLIDER, &format!("profile_rod_height_{l}_{k}"), *h, 0.0);
        }
    }
    c.close(SLIDER, "profile_nano_h_vdw", g.nano().h_vdw, 0.0);
    c.close(SLIDER, "profile_nano_w_vdw", g.nano().w_vdw, 0.0);
    c.close(SLIDER, "profile_nano_spacing", g.nano().spacing, 0.0);
    c.close(SLIDER, "profile_nano_per_rod", g.nano_per_rod() as f64, 0.0);
    c.close(CPP, "rod_heights_short_threw", 1.0, 0.0);
    c.close(FFI, "rod_heights_short_status", -2.0, 0.0);
    c.close(FFI, "rod_heights_short_names_argument", 1.0, 0.0);

    // asperity_slider_new: the same slider through Slider::new.
    use asperity::friction::{
        FrictionIncrement, FrictionLaw, FrictionMaterial, Loading, NanoAsperities, Slider,
        SliderOptions, SliderWork,
    };
    let copper = FrictionMaterial::copper();
    c.close(FFI, "copper_yield_stress", copper.yield_stress, 0.0);
    c.close(FFI, "copper_work_of_adhesion", copper.work_of_adhesion, 0.0);
    c.close(CPP, "options_default", 1.0, 0.0);
    let nano = NanoAsperities {
        h_vdw: 20e-9,
        w_vdw: 430e-9,
        h_chem: 2e-9,
        w_chem: 161e-9,
        spacing: 1.3e-6,
    };
    let geometry = SliderGeometry::uniform(13.5e-6, 3, nano, 100).unwrap();
    let counter: Vec<f64> = (0..64).map(|i| 2e-7 * (0.7 * i as f64).sin()).collect();
    let slider = Slider::new(
        geometry,
        copper,
        counter,
        um,
        SliderOptions::new(Loading::FixedLoad { load: 0.01 }),
    )
    .unwrap();
    let mut state = vec![0.0; slider.state_len()];
    let increment = FrictionIncrement {
        normal_force: 0.01,
        slip: [um, 0.0],
        ..FrictionIncrement::default()
    };
    let mut work = slider.work();
    let r = slider
        .step_in_place(&mut state, &increment, &mut work)
        .unwrap();
    assert!(
        r.force_magnitude > 0.0,
        "the check must see a sliding contact"
    );
    c.close(SLIDER, "structs_friction_force", r.force_magnitude, 0.0);
    c.close(SLIDER, "structs_cof", r.cof, 0.0);
    // The program reads the step's full record (`FrictionWork::slider_record`).
    let sw = work.get::<SliderWork>().unwrap();
    let record = *sw.record();
    assert!(record.nano_contacts > 0, "the check must see nano contacts");
    for (name, n) in [
        ("nano_contacts", record.nano_contacts),
        ("adhesive_contacts", record.adhesive_contacts),
        ("rods_in_contact", record.rods_in_contact),
        ("yielded_rods", record.yielded_rods),
    ] {
        c.close(SLIDER, &format!("structs_{name}"), n as f64, 0.0);
    }
    c.close(
        SLIDER,
        "structs_adhesion_area_share",
        record.adhesion_area_share,
        0.0,
    );
    c.close(SLIDER, "structs_position", record.position, 0.0);
    c.close(SLIDER, "structs_position", um, 0.0);
    c.close(SLIDER, "structs_rod_position", record.rod_position, 0.0);
    c.close(SLIDER, "structs_seated", 1.0, 0.0);
    c.close(SLIDER, "structs_seated", sw.seated() as i32 as f64, 0.0);
    c.close(CPP, "structs_position_matches_state", 1.0, 0.0);
    c.within(SLIDER, "structs_true_contact_area_rel_diff", 0.0, 1e-12);
    slider
        .step_in_place(&mut state, &increment, &mut work)
        .unwrap();
    let sw = work.get::<SliderWork>().unwrap();
    c.close(SLIDER, "structs_second_seated", 0.0, 0.0);
    c.close(
        SLIDER,
        "structs_second_seated",
        sw.seated() as i32 as f64,
        0.0,
    );
    c.close(SLIDER, "structs_second_position", sw.record().position, 0.0);
    c.close(SLIDER, "structs_second_position", 2.0 * um, 0.0);
    c.close(CPP, "record_null_work_threw", 1.0, 0.0);
    c.close(FFI, "record_null_work_status", -1.0, 0.0);
    c.close(FFI, "record_null_work_names_argument", 1.0, 0.0);
    c.close(CPP, "record_lugre_work_threw", 1.0, 0.0);
    c.close(FFI, "record_lugre_work_status", -2.0, 0.0);
    c.close(FFI, "record_lugre_work_names_argument", 1.0, 0.0);
    c.close(CPP, "structs_bad_plastic_threw", 1.0, 0.0);
    c.close(FFI, "structs_bad_plastic_status", -2.0, 0.0);
    c.close(FFI, "structs_bad_plastic_names_argument", 1.0, 0.0);
}

fn every_function_dynamic(c: &mut Report) {
    use asperity::friction::dynamic::{FrictionIncrement, FrictionLaw, LuGre, MaxwellSlip};
    const DYN: &str = "the dynamic friction models (src/friction/dynamic)";
    let lugre = LuGre::new(0.3, 0.5, 1e-3, 2.0, 1e5, 1000.0, 1e-3, 0.4).unwrap();
    c.close(DYN, "lugre_state_size", 4.0, 0.0);
    // One second at 2 mm/s: e^{-a dt} underflows, the Stribeck curve.
    c.close(
        DYN,
        "lugre_steady_force",
        lugre.steady_force(3.0, 2e-3),
        1e-12,
    );
    let mut s = [0.0; 4];
    let inc = FrictionIncrement {
        normal_force: 3.0,
        slip: [2e-3, 0.0],
        dt: 1.0,
        ..Default::default()
    };
    let r = lugre
        .step_in_place(&mut s, &inc, &mut lugre.work())
        .unwrap();
    c.close(DYN, "lugre_dissipation", r.dissipated, 0.0);
    // Maxwell-slip, two elements of reach 2 and 15 µm: loaded 3 µm, back
    // 2 µm: Masing F = F_v(3) − 2 F_v(1) on the point (the force on the
    // point is minus that).
    let ms = MaxwellSlip::new(&[1e5, 2e4], &[0.2, 0.3], 0.0).unwrap();
    let masing = |n: f64| ms.virgin_force(n, 3e-6) - 2.0 * ms.virgin_force(n, 1e-6);
    c.close(DYN, "maxwell_force_0", -masing(1.0), 1e-12);
    c.close(DYN, "maxwell_force_1", -masing(2.0), 1e-12);
    // Point 1 (N = 2) slid 1 µm on the first element in the first
    // increment and nothing in the second (the reversal is elastic).
    c.close(DYN, "maxwell_dissipation_1", 0.0, 0.0);
    // Loaded 3 µm from rest with responses (N = 2): element 1 slid (at its
    // reach 2 µm, no radial stiffness left), element 2 sticks: partial
    // slip, F = −N (μ₁ + k₂·3 µm), dF/dΔs = −N k₂, dF/dN = −(μ₁ + k₂·3 µm),
    // E = ½N (k₁(2 µm)² + k₂(3 µm)²).
    c.close(
        DYN,
        "maxwell_responses_force_1",
        -2.0 * (0.2 + 2e4 * 3e-6),
        1e-15,
    );
    c.close(DYN, "maxwell_responses_regime_1", 1.0, 0.0);
    c.close(DYN, "maxwell_responses_dslip_1", -2.0 * 2e4, 1e-9);
    c.close(
        DYN,
        "maxwell_responses_dnormal_1",
        -(0.2 + 2e4 * 3e-6),
        1e-15,
    );
    c.rel(
        DYN,
        "maxwell_responses_stored_1",
        0.5 * 2.0 * (1e5 * 4e-12 + 2e4 * 9e-12),
        1e-12,
    );
    c.close(CPP, "maxwell_bad_threw", 1.0, 0.0);
    c.close(FFI, "maxwell_bad_status", -2.0, 0.0);
    c.close(FFI, "maxwell_bad_names_argument", 1.0, 0.0);
    // Two-spring Prandtl-Tomlinson: the same increment through Rust.
    let pt = asperity::friction::dynamic::PrandtlTomlinson::two_spring(
        3e-21, 3e-10, 2.0, 1e-12, 1e-6, 2.0, 1e-12, 1e-6, 1e-9,
    )
    .unwrap();
    c.close(DYN, "two_spring_state_size", 7.0, 0.0);
    let mut s = [0.0; 7];
    let inc = FrictionIncrement {
        normal_force: 1.0,
        slip: [1e-11, 0.0],
        dt: 1e-6,
        ..Default::default()
    };
    let f = pt
        .step_in_place(&mut s, &inc, &mut pt.work())
        .unwrap()
        .force[0];
    c.close(DYN, "two_spring_force", f, 1e-12 * f.abs());
    // Burridge-Knopoff: four stuck blocks, F = −4 k_p Δs.
    c.close(DYN, "burridge_knopoff_state_size", 11.0, 0.0);
    c.close(
        DYN,
        "burridge_knopoff_stuck_force",
        -4.0 * 1e3 * 1e-5,
        1e-15,
    );
    c.close(CPP, "burridge_knopoff_bad_threw", 1.0, 0.0);
    c.close(FFI, "burridge_knopoff_bad_status", -2.0, 0.0);
    c.close(FFI, "burridge_knopoff_bad_names_argument", 1.0, 0.0);
    // The homogenised law (μ 0.5, k = 1e6 N/m): a 1 mm slip at 1 N slides
    // at −μN after the elastic slip μN/k, dissipating μN (Δs − μN/k).
    c.close(HOMOGENISED, "homogenised_state_size", 9.0, 0.0);
    c.close(HOMOGENISED, "homogenised_force", -0.5, 1e-15);
    c.close(HOMOGENISED, "homogenised_regime", 2.0, 0.0);
    c.rel(
        HOMOGENISED,
        "homogenised_dissipated",
        0.5 * (1e-3 - 0.5 / 1e6),
        1e-12,
    );
    c.close(CPP, "homogenised_no_area_threw", 1.0, 0.0);
    c.close(FFI, "homogenised_no_area_status", -2.0, 0.0);
    c.close(FFI, "homogenised_no_area_names_argument", 1.0, 0.0);
}

fn every_function_indentation(c: &mut Report) {
    c.close(CPP, "default_options", 1.0, 0.0);
    // The synthetic curve: κ = 0.3, d = 2, E_r = 70 GPa, β = 1, rigid tip.
    c.close(INDENT, "fit_kappa", 0.3, 1e-5);
    c.rel(INDENT, "fit_d", 2.0, 1e-5);
    c.rel(INDENT, "fit_reduced_modulus", 70e9, 1e-5);
    c.rel(INDENT, "fit_sample_modulus", 70e9 * (1.0 - 0.09), 1e-5);
    if let Some(h_f) = c.get(INDENT, "fit_expected_final_depth") {
        c.rel(INDENT, "fit_final_depth", h_f, 1e-6);
    }
    c.close(INDENT, "fit_segments_from_labels", 1.0, 0.0);
    c.rel(INDENT, "fit_unlabelled_d", 2.0, 1e-3);
    c.close(INDENT, "fit_unlabelled_segments_from_labels", 0.0, 0.0);
    // Defaults: the same ideal area with β = 1.034 (King 1987).
    c.rel(INDENT, "fit_defaults_reduced_modulus", 70e9 / 1.034, 1e-5);
    c.close(INDENT, "fit_defaults_kappa", 0.3, 1e-5);
    c.close(CPP, "fit_load_length_threw", 1.0, 0.0);
    c.close(CPP, "fit_load_length_status", -2.0, 0.0);
    c.close(CPP, "fit_load_length_names_argument", 1.0, 0.0);

    // Rescaling, REFERENCE.md sections 2 and 8.
    let (kappa, d, p1, d1) = (0.112, 2.0, 2310.0, 0.224e-3);
    let s = 2.0 + kappa * (d - 1.0);
    let load =
        |lambda: f64, delta: f64| lambda.powf((kappa - 2.0) / d) * (delta / d1).powf(s / d) * p1;
    c.close(INDENT, "rescaling_load", 985.71, 0.01);
    c.rel(INDENT, "rescaling_load", load(1.0, 0.1e-3), 1e-12);
    c.rel(INDENT, "rescaling_load_lambda", load(1.3, 0.1e-3), 1e-12);
    c.rel(
        INDENT,
        "rescaling_depth",
        1.3f64.powf((2.0 - kappa) / s) * (985.71 / p1).powf(d / s) * d1,
        1e-12,
    );
    c.rel(
        INDENT,
        "rescaling_radius",
        1.3f64.powf(-kappa / s) * (985.71 / p1).powf(1.0 / s) * 0.3e-3,
        1e-12,
    );
    c.rel(INDENT, "lambda_spheres", 0.788 / 1.2, 1e-12);
    c.rel(INDENT, "lambda_cones", 1.2f64.tan() / 1.0f64.tan(), 1e-12);
    c.rel(
        INDENT,
        "kappa_from_slope",
        (4.17 * 1.43 - 2.0) / 3.17,
        1e-12,
    );
    c.rel(INDENT, "d_from_unloading_slope", 1.0 / 0.24, 1e-12);
    c.rel(INDENT, "d_from_loading_slope", 0.75 / 0.18, 1e-12);
    c.rel(
        INDENT,
        "galanov_unloading_radius",
        1e-3 * 0.25 * (2.0f64 / 1.5).powi(3),
        1e-12,
    );
    c.rel(
        INDENT,
        "galanov_medium_radius",
        0.788e-3 * 62.882e-3 / (62.882e-3 - 0.788e-3),
        1e-12,
    );
    c.close(INDENT, "galanov_medium_radius", 0.798e-3, 1e-6);
    let (p, dd, db) = (1000.0, 3e-3, 10e-3);
    c.rel(
        INDENT,
        "hardness_brinell",
        2.0 * p / (PI * db * (db - (db * db - dd * dd).sqrt())),
        1e-12,
    );
    c.rel(INDENT, "hardness_meyer", 4.0 * p / (PI * dd * dd), 1e-12);
    c.rel(
        INDENT,
        "hardness_ludwik",
        4.0 * p / (2f64.sqrt() * PI * dd * dd),
        1e-12,
    );
    c.rel(
        INDENT,
        "hardness_vickers",
        2.0 * p * 68f64.to_radians().sin() / (dd * dd),
        1e-12,
    );
    c.close(CPP, "cone_kappa_threw", 1.0, 0.0);
    c.close(FFI, "cone_kappa_status", -4.0, 0.0);
    c.close(FFI, "cone_kappa_names_argument", 1.0, 0.0);
}

fn every_function_material(c: &mut Report) {
    let compliance = |e: f64, nu: f64| (1.0 - nu * nu) / e;
    c.rel(
        MATERIAL,
        "effective_modulus",
        1.0 / (compliance(200e9, 0.3) + compliance(70e9, 0.22)),
        1e-12,
    );
    c.rel(
        MATERIAL,
        "rod_effective_modulus",
        1.0 / (1.0 / 200e9 + 1.0 / 70e9),
        1e-12,
    );
    c.rel(MATERIAL, "no_slip_factor", no_slip_factor(0.355), 1e-12);
    c.close(MATERIAL, "no_slip_factor", 1.017376, 1e-6);
    c.rel(
        MATERIAL,
        "tabor_parameter",
        (R * W * W / (E_STAR * E_STAR * 0.3e-9f64.powi(3))).cbrt(),
        1e-12,
    );
    c.close(MATERIAL, "tabor_parameter", 4.52403, 1e-5);
    let k = 4.0 * E_STAR / 3.0;
    c.rel(
        MATERIAL,
        "maugis_parameter",
        2.0 * 1.710667e8 * (R / (PI * W * k * k)).cbrt(),
        1e-12,
    );
    c.close(MATERIAL, "maugis_parameter", 5.23435, 1e-4);
    let weir = |m: f64, rho: f64, e: f64, nu: f64, prefactor: f64| {
        (m / rho).cbrt() * e / (3.0 * (1.0 - 2.0 * nu)) * prefactor
    };
    let diamond = weir(1.99e-26, 3500.0, 1164e9, 0.079, 1.0 / 40.0);
    let wc = weir(3.25e-25, 15250.0, 600e9, 0.2, 1.0 / 40.0);
    c.rel(MATERIAL, "weir_diamond", diamond, 1e-12);
    c.close(MATERIAL, "weir_diamond", 2.05615, 1e-5);
    c.rel(MATERIAL, "weir_wc", wc, 1e-12);
    c.rel(
        MATERIAL,
        "weir_diamond_three_over_mn",
        weir(1.99e-26, 3500.0, 1164e9, 0.079, 3.0 / 72.0),
        1e-12,
    );
    let pair = (diamond.sqrt() - wc.sqrt()).powi(2);
    c.rel(MATERIAL, "pair_seed001", pair, 1e-9);
    c.close(MATERIAL, "pair_seed001", 7.40923e-3, 1e-8);
    c.rel(
        MATERIAL,
        "hamaker_work_of_adhesion",
        2.7e-19 / (12.0 * PI * 2.56e-10f64.powi(2)),
        1e-12,
    );
    c.close(MATERIAL, "hamaker_work_of_adhesion", 0.10928, 1e-5);
    c.close(CPP, "bad_poisson_threw", 1.0, 0.0);
    c.close(FFI, "bad_poisson_status", -2.0, 0.0);
    c.close(FFI, "bad_poisson_names_argument", 1.0, 0.0);
}

fn every_function_statistics(c: &mut Report) {
    // Greenwood–Williamson, Gaussian, at d = σ: F_{3/2}(1), F₁(1), F₀(1) of
    // REFERENCE.md section 3.
    let (n, r, sigma, e): (f64, f64, f64, f64) = (1000.0, 50e-6, 1e-6, 1e11);
    c.rel(
        STATS,
        "gw_load",
        4.0 / 3.0 * n * e * r.sqrt() * sigma.powf(1.5) * 0.07566817739,
        1e-8,
    );
    c.rel(STATS, "gw_area", PI * n * r * sigma * 0.08331547059, 1e-8);
    c.rel(STATS, "gw_contacts", n * 0.1586552539, 1e-8);
    c.close(CPP, "gw_batch_equals_scalar", 1.0, 0.0);
    c.rel(STATS, "gw_separation", sigma, 1e-8);
    c.within(STATS, "gw_separation_residual", 0.0, 1e-9);
    let psi = (e / 2e9) * (sigma / r).sqrt();
    c.rel(STATS, "gw_plasticity_index", psi, 1e-12);
    c.rel(STATS, "plasticity_index", psi, 1e-12);
    c.close(STATS, "regime_0_5", 0.0, 0.0);
    c.close(STATS, "regime_0_8", 1.0, 0.0);
    c.close(STATS, "regime_1_5", 2.0, 0.0);

    // Listed summits: each stands for N/M of N = 500; at d = 0.2 µm the
    // summits at 0.3, 0.9 and 0.6 µm touch.
    let heights = [0.3e-6, -0.2e-6, 0.9e-6, 0.1e-6, -0.5e-6, 0.6e-6];
    let radii: [f64; 6] = [30e-6, 45e-6, 20e-6, 60e-6, 35e-6, 50e-6];
    let (per, r40, d): (f64, f64, f64) = (500.0 / 6.0, 40e-6, 0.2e-6);
    let touching = || heights.iter().zip(radii).filter(|(z, _)| **z > d);
    let load: f64 =
        touching().map(|(z, _)| (z - d).powf(1.5)).sum::<f64>() * per * 4.0 / 3.0 * e * r40.sqrt();
    c.rel(STATS, "gwe_load", load, 1e-12);
    c.rel(
        STATS,
        "gwe_area",
        per * PI * r40 * touching().map(|(z, _)| z - d).sum::<f64>(),
        1e-12,
    );
    c.rel(STATS, "gwe_contacts", per * 3.0, 1e-12);
    c.rel(STATS, "gwe_separation", d, 1e-8);
    let mean = heights.iter().sum::<f64>() / 6.0;
    let sd = (heights.iter().map(|z| (z - mean).powi(2)).sum::<f64>() / 6.0).sqrt();
    c.rel(
        STATS,
        "gwe_plasticity_index",
        e / 2e9 * (sd / r40).sqrt(),
        1e-12,
    );
    c.close(CPP, "gwe_batch_equals_scalar", 1.0, 0.0);
    c.rel(
        STATS,
        "gwe_radii_load",
        per * 4.0 / 3.0
            * e
            * touching()
                .map(|(z, r)| r.sqrt() * (z - d).powf(1.5))
                .sum::<f64>(),
        1e-12,
    );
    c.rel(
        STATS,
        "gwe_radii_area",
        per * PI * touching().map(|(z, r)| r * (z - d)).sum::<f64>(),
        1e-12,
    );
    c.close(CPP, "gwe_radii_length_threw", 1.0, 0.0);
    c.close(CPP, "gwe_radii_length_status", -2.0, 0.0);
    c.close(CPP, "gwe_radii_length_names_argument", 1.0, 0.0);

    // Zhuravlev, linear densities: P = (4/3)E*√R α₁α₂ Γ(5/2)/(N Γ(13/2)) x^{11/2},
    // S = π R α₁α₂ x⁵/(120 N), pairs α₁α₂ x⁴/(24 N).
    let (reff, ez, nz, a1, a2, x): (f64, f64, f64, f64, f64, f64) =
        (0.5e-6, 1e9, 1000.0, 1e14, 2e14, 50e-9);
    let zl = 4.0 / 3.0 * ez * reff.sqrt() * a1 * a2 * (16.0 / 3465.0) / nz * x.powf(5.5);
    let zs = PI * reff * a1 * a2 * x.powi(5) / (120.0 * nz);
    c.rel(STATS, "zh_load", zl, 1e-12);
    c.rel(STATS, "zh_area", zs, 1e-12);
    c.rel(
        STATS,
        "zh_contacts",
        a1 * a2 * x.powi(4) / (24.0 * nz),
        1e-12,
    );
    c.rel(STATS, "zh_approach", x, 1e-12);
    c.rel(STATS, "zh_friction_approach", x, 1e-12);
    c.rel(STATS, "zh_friction_force", 1e8 * zs, 1e-11);
    c.rel(STATS, "zh_friction_coefficient", 1e8 * zs / zl, 1e-11);
    c.within(STATS, "zh_callback_load_rel_diff", 0.0, 1e-9);
    // n(ξ) = βξ²: I_q(x) = 4β² x^{q+6} Γ(q+1)/Γ(q+7).
    let beta = 1e22;
    let i = |q: f64| {
        4.0 * beta * beta * x.powf(q + 6.0) / (1..=6).map(|k| q + k as f64).product::<f64>()
    };
    c.rel(
        STATS,
        "zh_quadratic_load",
        4.0 / 3.0 * ez * reff.sqrt() / nz * i(1.5),
        1e-9,
    );
    c.rel(STATS, "zh_quadratic_area", PI * reff / nz * i(1.0), 1e-12);
    c.close(CPP, "zh_exception_propagated", 1.0, 0.0);
}

fn every_function_surfaces(c: &mut Report) {
    use asperity::surface::{CantorBorodich, SelfAffine, WeierstrassMandelbrot};
    let (a, lambda, dx, n) = (1e-6, 64e-6, 1e-6, 4096.0);
    // ISO 4287 on a sine (REFERENCE.md section 4); Ra of the sampled sine is
    // 2A/π within 1e-3.
    c.rel(SURFACE, "sine_ra", 2.0 * a / PI, 2e-3);
    c.rel(SURFACE, "sine_rq", a / 2f64.sqrt(), 1e-12);
    c.close(SURFACE, "sine_rsk", 0.0, 1e-9);
    c.close(SURFACE, "sine_rku", 1.5, 1e-9);
    c.rel(SURFACE, "sine_rsm", lambda, 1e-3);
    c.rel(SURFACE, "sine_rdq", 2f64.sqrt() * PI * a / lambda, 1e-4);
    c.rel(SURFACE, "sine_m0", a * a / 2.0, 1e-9);
    c.close(SURFACE, "sine_n_evaluated", n, 0.0);
    c.close(SURFACE, "sine_sampling_lengths", 4.0, 0.0);
    c.close(SURFACE, "sine_has_rsm", 1.0, 0.0);
    c.close(SURFACE, "sine_filtered_first_index", 256.0, 0.0);
    c.rel(SURFACE, "sine_filtered_rq", a / 2f64.sqrt(), 5e-3);
    c.within(SURFACE, "line_linear_residual", 0.0, 1e-20);
    c.rel(SURFACE, "line_mean_removed_first", -99.0 * 2e-8 / 2.0, 1e-9);
    c.rel(SURFACE, "line_mean_removed_last", 99.0 * 2e-8 / 2.0, 1e-9);
    c.close(SURFACE, "filter_keep_n_out", n, 0.0);
    c.close(SURFACE, "filter_keep_first_index", 0.0, 0.0);
    c.close(SURFACE, "filter_discard_n_out", n - 512.0, 0.0);
    c.close(SURFACE, "filter_discard_first_index", 256.0, 0.0);
    c.within(SURFACE, "filter_parts_sum_max_err", 0.0, 1e-15 * a);
    c.rel(SURFACE, "filter_roughness_amplitude", a, 1e-3);
    c.close(SURFACE, "ratio_5", 0.5, 1e-15);
    c.rel(SURFACE, "level_first", a, 1e-12);
    c.rel(SURFACE, "level_last", -a, 1e-12);
    c.close(CPP, "level_span_equals_vector", 0.0, 0.0);
    c.close(SURFACE, "psd_len", n / 2.0 + 1.0, 0.0);
    c.rel(SURFACE, "psd_q1", 2.0 * PI / (n * dx), 1e-12);
    c.rel(SURFACE, "psd_peak_q", 2.0 * PI / lambda, 1e-12);
    c.rel(SURFACE, "psd_integral", a * a / 2.0, 1e-9);
    c.close(CPP, "psd_wrong_length_threw", 1.0, 0.0);
    c.close(FFI, "psd_wrong_length_status", -2.0, 0.0);
    c.close(FFI, "psd_wrong_length_names_argument", 1.0, 0.0);
    c.close(SURFACE, "peak_count", 64.0, 0.0);
    c.rel(SURFACE, "peak_density", 64.0 / (n * dx), 1e-12);
    c.rel(SURFACE, "peak_mean_height", a, 1e-12);
    c.rel(
        SURFACE,
        "peak_mean_curvature",
        a * (2.0 * PI / lambda).powi(2),
        2e-3,
    );
    // Generators: the same arguments through the Rust API, bit for bit.
    c.close(CPP, "sa_span_equals_vector", 0.0, 0.0);
    let sa = SelfAffine::new(0.7, 1e-6)
        .unwrap()
        .with_roll_off(1e-3)
        .unwrap()
        .with_cutoff(8e-6)
        .unwrap()
        .profile(4096, dx, 42)
        .unwrap();
    for i in [0, 1000, 4095] {
        c.close(SURFACE, &format!("sa_{i}"), sa.heights()[i], 0.0);
    }
    c.close(SURFACE, "hurst_fit", 0.7, 0.12);
    if let Some(slope) = c.get(SURFACE, "hurst_fit_slope") {
        c.rel(SURFACE, "hurst_fit", -(slope + 1.0) / 2.0, 1e-12);
    }
    let wm = WeierstrassMandelbrot::new(1.5, 1.5, 1e-7)
        .unwrap()
        .profile(1024, dx, 7)
        .unwrap();
    c.close(SURFACE, "wm_0", wm.heights()[0], 0.0);
    c.close(SURFACE, "wm_517", wm.heights()[517], 0.0);
    let cb = CantorBorodich::new(2, 0.25, 0.6, 1e-6, 5)
        .unwrap()
        .profile(1e-3, 512)
        .unwrap();
    c.close(SURFACE, "cb_100", cb.heights()[100], 0.0);
    c.close(SURFACE, "cb_300", cb.heights()[300], 0.0);
    c.close(
        SURFACE,
        "cb_max",
        cb.heights().iter().cloned().fold(f64::MIN, f64::max),
        0.0,
    );
}

fn check_every_function(linkage: Linkage) {
    let Some(r) = run("every_function", linkage) else {
        return;
    };
    let mut c = Report::new(&r);
    c.exit_ok(CPP);
    // The layout query (src/ffi/abi.rs) against the C++ compiler's sizeof.
    for name in [
        "layout_normal_response_size_matches",
        "layout_normal_response_align_matches",
        "layout_names_include_normal_law",
        "layout_unknown_name_throws",
    ] {
        c.close(CPP, name, 1.0, 0.0);
    }
    let line = |prefix: &str| {
        r.stdout
            .lines()
            .find_map(|l| l.strip_prefix(prefix))
            .map(str::to_string)
    };
    let version = line("version: ");
    c.ok(
        CPP,
        version.as_deref() == Some(env!("CARGO_PKG_VERSION")),
        || {
            format!(
                "version {version:?}, Cargo.toml says {}",
                env!("CARGO_PKG_VERSION")
            )
        },
    );
    let status = line("status_string -4: ");
    c.ok(CPP, status.as_deref() == Some("out of domain"), || {
        format!("status_string(-4) = {status:?}")
    });
    let flag = line("flag_name 1: ");
    c.ok(CPP, flag.as_deref() == Some("kappa_above_one"), || {
        format!("indentation_flag_name(1) = {flag:?}")
    });
    c.close(CPP, "flag_name_40_is_null", 1.0, 0.0);
    every_function_laws(&mut c);
    every_function_lj_and_tables(&mut c);
    every_function_slider(&mut c);
    every_function_dynamic(&mut c);
    every_function_indentation(&mut c);
    every_function_material(&mut c);
    every_function_statistics(&mut c);
    every_function_surfaces(&mut c);
    c.finish();
}

#[test]
fn every_function() {
    each_linkage(check_every_function);
}
