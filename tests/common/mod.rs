//! Shared by the integration tests that run programs or need what the project
//! does not hold (`mod common;` in each): where the crate is, the `asperity`
//! binary the command-line tests run, how a check that cannot run here skips
//! (`skip`), the ABI version rule (`abi_version`: the soname's suffix), and
//! (`native`) the helpers of the tests that compile C, C++ and Fortran
//! programs against the library.

pub mod c_errors;
pub mod counting;
pub mod native;

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

/// A check that cannot run here (a tool, a host code or `../shared/data`
/// missing): prints `SKIPPED: {reason}`, so the skip is never a silent pass,
/// and under `ASPERITY_REQUIRE_ALL=1` (which `.ci/run` sets) fails instead.
/// The reason says what is missing and how to get it. The caller then returns
/// without running the check.
#[allow(dead_code)]
#[track_caller]
pub fn skip(reason: impl std::fmt::Display) {
    println!("SKIPPED: {reason}");
    if std::env::var_os("ASPERITY_REQUIRE_ALL").is_some_and(|v| v == "1") {
        panic!("this check could not run ({reason}), and ASPERITY_REQUIRE_ALL=1 forbids skipping");
    }
}

/// The ABI version of this crate's version (build.rs): `MAJOR` for
/// `MAJOR >= 1`, and `0.MINOR` for 0.x (semver: a 0.x minor release may
/// break). It names the soname, `libasperity.so.<ABI>`, and the ABI record
/// (`abi/asperity.abi`); the CMake package accepts a request of this ABI
/// version only.
#[allow(dead_code)]
pub fn abi_version() -> String {
    abi_version_of(
        env!("CARGO_PKG_VERSION_MAJOR").parse().unwrap(),
        env!("CARGO_PKG_VERSION_MINOR").parse().unwrap(),
    )
}

/// The ABI version of version `major.minor.*` (see [`abi_version`]).
#[allow(dead_code)]
pub fn abi_version_of(major: u64, minor: u64) -> String {
    if major == 0 {
        format!("0.{minor}")
    } else {
        major.to_string()
    }
}

/// The crate's root directory.
#[allow(dead_code)]
pub fn manifest() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The binary: the one Cargo built for this test run when the `cli` feature
/// is on (`cargo test --features cli`); otherwise built once per run, with
/// that feature, into this run's own target directory and profile, where
/// every dependency but the command line's own is already built. (A target
/// directory of its own rebuilt them all: 400–515 s of a CI run.) The
/// library is the same code with or without the feature (nothing outside
/// `src/bin` depends on it), and the tests that link the C libraries build
/// theirs first (`native::build_library`); Cargo runs test binaries one at
/// a time. (Only the command-line tests call it.)
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
        let l = native::layout().expect("the test's target layout");
        let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
        let mut cmd = Command::new(cargo);
        cmd.current_dir(manifest())
            .args(["build", "--features", "cli", "--bin", "asperity"])
            .args(["--profile", &l.profile, "--target-dir"])
            .arg(&l.target_dir);
        if let Some(t) = &l.cross_target {
            cmd.args(["--target", t]);
        }
        let out = cmd.output().expect("run cargo build");
        assert!(
            out.status.success(),
            "cargo build --features cli failed:\n{}",
            String::from_utf8_lossy(&out.stderr)
        );
        l.profile_dir
            .join(format!("asperity{}", std::env::consts::EXE_SUFFIX))
    })
}
