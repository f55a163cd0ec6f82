//! The README's quick starts are the example programs the tests compile and
//! run (`examples/c/quick_start.c` by tests/c_examples.rs,
//! `examples/cpp/quick_start.cpp` by tests/cpp_bindings.rs,
//! `examples/fortran/quick_start.f90` by tests/fortran_bindings.rs,
//! `examples/quick_start.rs` by Cargo): each fenced block that follows a
//! `<!-- quick-start: FILE -->` line must equal FILE, so the README cannot
//! drift from code that is known to work.

use std::path::PathBuf;

#[test]
fn quick_starts_are_the_tested_examples() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    let lines: Vec<&str> = readme.lines().collect();
    let mut seen = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let Some(file) = line
            .trim()
            .strip_prefix("<!-- quick-start:")
            .and_then(|r| r.strip_suffix("-->"))
            .map(str::trim)
        else {
            continue;
        };
        let fence = lines.get(i + 1).copied().unwrap_or_default();
        assert!(
            fence.starts_with("```"),
            "README line {}: a fenced block must follow the quick-start marker for {file}",
            i + 2
        );
        let end = lines[i + 2..]
            .iter()
            .position(|l| l.starts_with("```"))
            .unwrap_or_else(|| panic!("README: unterminated block for {file}"));
        let block: String = lines[i + 2..i + 2 + end]
            .iter()
            .map(|l| format!("{l}\n"))
            .collect();
        let text = std::fs::read_to_string(root.join(file))
            .unwrap_or_else(|e| panic!("README names {file}: {e}"));
        assert!(
            block == text,
            "the README block for {file} differs from the file: copy the file into the README"
        );
        seen.push(file.to_string());
    }
    for want in [
        "examples/c/quick_start.c",
        "examples/cpp/quick_start.cpp",
        "examples/fortran/quick_start.f90",
        "examples/quick_start.rs",
        "examples/python/quick_start.py",
    ] {
        assert!(
            seen.iter().any(|s| s == want),
            "the README has no quick start from {want}"
        );
    }
}
