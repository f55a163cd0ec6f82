//! The committed C header must equal what the pinned cbindgen generates from
//! the current sources. `ASPERITY_BLESS=1 cargo test --test header` rewrites it.

use std::path::PathBuf;

fn generate() -> String {
    let crate_dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let config =
        cbindgen::Config::from_file(crate_dir.join("cbindgen.toml")).expect("cbindgen.toml parses");
    // The version macros come from Cargo.toml, never from a hand-kept copy.
    let version = format!(
        "\n#define ASPERITY_VERSION_MAJOR {}\n#define ASPERITY_VERSION_MINOR {}\n#define ASPERITY_VERSION_PATCH {}\n",
        env!("CARGO_PKG_VERSION_MAJOR"),
        env!("CARGO_PKG_VERSION_MINOR"),
        env!("CARGO_PKG_VERSION_PATCH"),
    );
    let mut out = Vec::new();
    cbindgen::Builder::new()
        .with_crate(&crate_dir)
        .with_config(config)
        .with_after_include(version)
        .generate()
        .expect("cbindgen generates the header")
        .write(&mut out);
    String::from_utf8(out).expect("header is UTF-8")
}

#[test]
fn header_is_up_to_date() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("include/asperity.h");
    let fresh = generate();
    if std::env::var_os("ASPERITY_BLESS").is_some_and(|v| v == "1") {
        std::fs::write(&path, &fresh).expect("write include/asperity.h");
        return;
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed == fresh,
        "include/asperity.h is stale: run `ASPERITY_BLESS=1 cargo test --test header` and commit it"
    );
}

#[test]
fn header_names_are_prefixed() {
    let h = generate();
    for line in h.lines() {
        let t = line.trim_start();
        if let Some(rest) = t.strip_prefix("#define ") {
            let name = rest.split_whitespace().next().unwrap();
            assert!(
                name.starts_with("ASPERITY_"),
                "macro `{name}` lacks the ASPERITY_ prefix"
            );
        }
        if t.starts_with("typedef struct") || t.starts_with("typedef union") {
            let name = t.split_whitespace().nth(2).unwrap();
            assert!(
                name.starts_with("Asperity"),
                "type `{name}` lacks the Asperity prefix"
            );
        }
        if let Some(i) = t.find("asperity_") {
            if t.starts_with("int32_t ")
                || t.starts_with("const char *")
                || t.starts_with("size_t ")
            {
                assert!(i > 0);
            }
        }
    }
}
