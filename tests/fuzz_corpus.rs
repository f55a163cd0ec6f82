//! Replays the fuzzing corpora on stable, without cargo-fuzz: every file of
//! `fuzz/corpus/<target>/` (the minimised seed corpora of the libFuzzer runs)
//! and `fuzz/regressions/<target>/` (the inputs that found bugs, now fixed)
//! goes through the same harness function the fuzz target runs
//! (`fuzz/harness/<target>.rs`, included here). A harness panics on a
//! finding — a library panic, a panic the C guard caught
//! (`ASPERITY_ERR_INTERNAL`), an error status without a message — so a
//! regression fails the test named after its target, with the file named.
//! See RELIABILITY.md, "Fuzzing".

#[path = "../fuzz/harness/c_abi.rs"]
mod c_abi;
#[path = "../fuzz/harness/readers.rs"]
mod readers;
#[path = "../fuzz/harness/scene_json.rs"]
mod scene_json;
#[path = "../fuzz/harness/table_json.rs"]
mod table_json;

use std::path::{Path, PathBuf};

/// The files of `fuzz/<kind>/<target>/`, sorted (none when it is absent).
fn inputs(kind: &str, target: &str) -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("fuzz")
        .join(kind)
        .join(target);
    let mut files: Vec<PathBuf> = match std::fs::read_dir(&dir) {
        Ok(d) => d
            .filter_map(|e| e.ok())
            .map(|e| e.path())
            .filter(|p| p.is_file())
            .collect(),
        Err(_) => Vec::new(),
    };
    files.sort();
    files
}

/// Run `harness` on every corpus and regression file of `target`; fail with
/// the names of the files whose run panicked.
fn replay(target: &str, harness: fn(&[u8])) {
    let corpus = inputs("corpus", target);
    assert!(
        !corpus.is_empty(),
        "fuzz/corpus/{target}/ is empty or missing: the seed corpus is committed"
    );
    let files: Vec<PathBuf> = corpus
        .into_iter()
        .chain(inputs("regressions", target))
        .collect();
    let failed: Vec<String> = files
        .iter()
        .filter_map(|f| {
            let data = std::fs::read(f).expect("read corpus file");
            std::panic::catch_unwind(|| harness(&data)).err().map(|e| {
                let what = e
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| e.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_default();
                format!("{}: {what}", f.display())
            })
        })
        .collect();
    assert!(
        failed.is_empty(),
        "{} of {} {target} inputs failed:\n{}",
        failed.len(),
        files.len(),
        failed.join("\n")
    );
    println!("{target}: {} inputs replayed", files.len());
}

#[test]
fn c_abi_corpus() {
    replay("c_abi", c_abi::run);
}

#[test]
fn scene_json_corpus() {
    replay("scene_json", scene_json::run);
}

#[test]
fn readers_corpus() {
    replay("readers", readers::run);
}

#[test]
fn table_json_corpus() {
    replay("table_json", table_json::run);
}

/// The `c_abi` harness calls every function the C header declares: a new
/// entry point without a fuzz operation fails here, naming it.
#[test]
fn c_abi_harness_calls_every_c_function() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let header = std::fs::read_to_string(root.join("include/asperity.h")).expect("read header");
    // The harness: `fuzz/harness/c_abi.rs` and its per-domain modules in
    // `fuzz/harness/c_abi/`.
    let mut files = vec![root.join("fuzz/harness/c_abi.rs")];
    let mut modules: Vec<PathBuf> = std::fs::read_dir(root.join("fuzz/harness/c_abi"))
        .expect("read fuzz/harness/c_abi/")
        .map(|e| e.expect("read fuzz/harness/c_abi/").path())
        .filter(|p| p.extension().is_some_and(|x| x == "rs"))
        .collect();
    modules.sort();
    files.extend(modules);
    let harness: String = files
        .iter()
        .map(|f| std::fs::read_to_string(f).expect("read harness"))
        .collect();
    // Declarations: `<type> asperity_name(` at the start of a line.
    let declared: Vec<&str> = header
        .lines()
        .filter(|l| !l.starts_with("//") && !l.starts_with(' '))
        .filter_map(|l| {
            let start = l.find("asperity_")?;
            let end = start + l[start..].find('(')?;
            let name = &l[start..end];
            name.bytes()
                .all(|b| b.is_ascii_alphanumeric() || b == b'_')
                .then_some(name)
        })
        .collect();
    assert!(
        declared.len() > 100,
        "only {} functions found in include/asperity.h",
        declared.len()
    );
    let missing: Vec<&str> = declared
        .iter()
        .copied()
        .filter(|name| !harness.contains(&format!("{name}(")))
        .collect();
    assert!(
        missing.is_empty(),
        "fuzz/harness/c_abi{{.rs,/}} never calls {} of the {} C functions: {missing:?}",
        missing.len(),
        declared.len()
    );
}
