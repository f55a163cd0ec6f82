//! Shared by the integration tests that run programs (`mod common;` in each):
//! where the crate is, the `asperity` binary the command-line tests run, and
//! (`native`) the helpers of the tests that compile C, C++ and Fortran
//! programs against the library.

pub mod c_errors;
pub mod counting;
pub mod native;

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

/// The crate's root directory.
#[allow(dead_code)]
pub fn manifest() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The binary: the one Cargo built for this test run when the `cli` feature
/// is on (`cargo test --features cli`); otherwise built once per run in its own
/// target directory, which keeps the library artifacts the C-example tests
/// link against untouched. (Only the command-line tests call it.)
#[allow(dead_code)]
pub fn binary() -> &'static Path {
    static BIN: OnceLock<PathBuf> = OnceLock::new();
    BIN.get_or_init(|| {
        // Cargo builds the binary for this run only with its required
        // feature `cli` on. Without it Cargo still names the binary, and a
        // file there is a stale build of some earlier run: build afresh.
        if cfg!(feature = "cli") {
            if let Some(bin) = option_env!("CARGO_BIN_EXE_asperity").map(PathBuf::from) {
                return bin;
            }
        }
        let target = manifest().join("target").join("cli-test");
        let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
        let out = Command::new(cargo)
            .current_dir(manifest())
            .args([
                "build",
                "--features",
                "cli",
                "--bin",
                "asperity",
                "--target-dir",
            ])
            .arg(&target)
            .output()
            .expect("run cargo build");
        assert!(
            out.status.success(),
            "cargo build --features cli failed:\n{}",
            String::from_utf8_lossy(&out.stderr)
        );
        target.join("debug").join("asperity")
    })
}
